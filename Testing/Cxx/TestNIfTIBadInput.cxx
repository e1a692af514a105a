// SPDX-License-Identifier: BSD-3-Clause
// vtkNIfTIVolumeReader and vtkNIfTITensorReader (their shared NIfTI layer,
// vtkNIfTIFile) on bad input: every case must fail with a clear message
// (an error is reported, the update fails) and leave an empty output, in well
// under a second and without allocating what the header announces. The
// files are written byte by byte here (NeuroimagingTestFiles.h), each a
// valid file with one thing wrong: the crash class of VTK 9.2's own NIfTI
// reader (an unknown datatype code, a 0 dimension, dim[5] = 0), header
// fields out of range (sizeof_hdr, magic, dim[0], negative dimensions,
// float128, bitpix, vox_offset inside the header / fractional / past the end,
// a non-finite scl_inter, a quaternion longer than 1, a NaN sform, NIfTI-2's
// newline-damaged magic, 2^40 voxels along x, dimensions overflowing 2^62
// bytes), hostile sizes (32767^3 voxels in a small .nii and .nii.gz, a
// sparse file announcing four times this machine's memory), damaged gzip
// streams (cut short, a wrong checksum, damaged deflate data), pairs missing
// a part. Control: the same good file reads before and after every case,
// and read through gzip and as a pair it gives the same values. Then abort:
// an abort at the first progress event leaves an empty output without an
// error; the next update is complete.
#include "vtkNIfTITensorReader.h"
#include "vtkNIfTIVolumeReader.h"

#include "NeuroimagingTestFiles.h"
#include "SplineVizTestUtilities.h"

#include "vtkCallbackCommand.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkPointData.h"
#include "vtk_zlib.h"

#include <vtksys/SystemInformation.hxx>

#include <chrono>
#include <cstdio>

namespace
{
using namespace neurotest;

struct Case
{
  std::string Name;
  std::string Bytes;
  std::string Extension;
  std::string Expected; // part of the error message
  bool Gzip = false;    // write it gzip-compressed
};

void WriteGzip(const std::string& path, const std::string& bytes)
{
  gzFile f = gzopen(path.c_str(), "wb");
  gzwrite(f, bytes.data(), static_cast<unsigned>(bytes.size()));
  gzclose(f);
}

std::string Gzip(const std::string& bytes)
{
  const std::string path = OutDir + "/TestNIfTIBadInput-tmp.gz";
  WriteGzip(path, bytes);
  const std::string gz = ReadBytes(path);
  std::remove(path.c_str());
  return gz;
}

// A NIfTI-2 header (540 bytes + 4 extension bytes) of float32 voxels with the given dims.
std::string NIfTI2(const std::vector<std::int64_t>& dims, std::int16_t dataType = 16)
{
  std::string h(544, '\0');
  Put<std::int32_t>(h, 0, 540);
  h.replace(4, 8, std::string("n+2\0\r\n\032\n", 8));
  Put<std::int16_t>(h, 12, dataType);
  Put<std::int16_t>(h, 14, dataType == 16 ? 32 : 64);
  Put<std::int64_t>(h, 16, static_cast<std::int64_t>(dims.size()));
  for (std::size_t i = 0; i < 7; ++i)
  {
    Put<std::int64_t>(h, 24 + 8 * i, i < dims.size() ? dims[i] : 1);
    Put<double>(h, 104 + 8 * (i + 1), 1.0);
  }
  Put<std::int64_t>(h, 168, 544);
  return h;
}

// The voxels' value at point 0 (the output is not empty) or NaN.
double FirstValue(vtkImageData* image)
{
  vtkDataArray* a = image->GetPointData()->GetScalars();
  return a && a->GetNumberOfTuples() > 0 ? a->GetComponent(0, 0)
                                         : std::numeric_limits<double>::quiet_NaN();
}
}

int TestNIfTIBadInput(int, char*[])
{
  SplineVizTestStatus status;
  Harness h;

  // A good volume (float32, 4 x 3 x 2, rotated sform) and a good tensor file.
  NIfTIFile goodVolume;
  goodVolume.Dim[0] = 4;
  goodVolume.Dim[1] = 3;
  goodVolume.Dim[2] = 2;
  goodVolume.SFormCode = 1;
  goodVolume.SForm[0][1] = 0.5;
  for (int v = 0; v < 24; ++v)
  {
    goodVolume.Data.push_back(0.5f * v + 1);
  }
  const std::string good = goodVolume.Bytes();
  NIfTIFile goodTensor = goodVolume;
  goodTensor.NumberOfDimensions = 5;
  goodTensor.Dim[3] = 1;
  goodTensor.Dim[4] = 6;
  goodTensor.Data.assign(24 * 6, 1.0f);
  const std::string tensor = goodTensor.Bytes();

  // Control: the good files read (also through gzip and as a .hdr/.img pair).
  const std::string goodPath = OutDir + "/TestNIfTIBadInput-good.nii";
  WriteBytes(goodPath, good);
  const std::string goodTensorPath = OutDir + "/TestNIfTIBadInput-good-tensor.nii";
  WriteBytes(goodTensorPath, tensor);
  vtkNew<vtkNIfTIVolumeReader> volume;
  vtkNew<vtkNIfTITensorReader> tensors;
  h.Watch(volume);
  h.Watch(tensors);
  auto readsGood = [&]()
  {
    volume->SetFileName(goodPath.c_str());
    tensors->SetFileName(goodTensorPath.c_str());
    return h.Run(volume) && volume->GetOutput()->GetNumberOfPoints() == 24 &&
      FirstValue(volume->GetOutput()) == 1.0 && h.Run(tensors) &&
      tensors->GetOutput()->GetNumberOfPoints() == 24;
  };
  SV_CHECK_MSG(status, readsGood(), h.Error());
  {
    const std::string gzPath = OutDir + "/TestNIfTIBadInput-good.nii.gz";
    WriteGzip(gzPath, good);
    std::string header = good.substr(0, 348);
    header.replace(344, 4, std::string("ni1\0", 4));
    Put<float>(header, 108, 0.0f);
    WriteBytes(OutDir + "/TestNIfTIBadInput-pair.hdr", header);
    WriteBytes(OutDir + "/TestNIfTIBadInput-pair.img", good.substr(352));
    for (const std::string& path :
      { gzPath, OutDir + "/TestNIfTIBadInput-pair.hdr", OutDir + "/TestNIfTIBadInput-pair.img" })
    {
      volume->SetFileName(path.c_str());
      SV_CHECK_MSG(status,
        h.Run(volume) && volume->GetOutput()->GetNumberOfPoints() == 24 &&
          volume->GetOutput()->GetPointData()->GetScalars()->GetComponent(23, 0) == 12.5,
        path << ": " << h.Error());
    }
  }

  std::vector<Case> cases;
  auto with = [](std::string bytes, std::size_t offset, auto value)
  {
    Put(bytes, offset, value);
    return bytes;
  };
  // VTK 9.2's vtkNIFTIImageReader crashes on these (SIGSEGV, SIGFPE).
  cases.push_back({ "unknown datatype code (VTK 9.2: SIGSEGV)", with(tensor, 70, std::int16_t(-1)),
    ".nii", "unknown datatype code -1" });
  cases.push_back({ "unknown datatype code, gzip", with(tensor, 70, std::int16_t(99)), ".nii.gz",
    "unknown datatype code 99", true });
  cases.push_back(
    { "dim[3] = 0 (VTK 9.2: SIGSEGV)", with(tensor, 46, std::int16_t(0)), ".nii", "dim[3] is 0" });
  cases.push_back(
    { "dim[5] = 0 (VTK 9.2: SIGFPE)", with(tensor, 50, std::int16_t(0)), ".nii", "dim[5] is 0" });
  // Header fields out of range.
  cases.push_back({ "sizeof_hdr 349", with(good, 0, std::int32_t(349)), ".nii", "sizeof_hdr" });
  cases.push_back(
    { "no magic (Analyze 7.5)", with(good, 344, std::int32_t(0)), ".nii", "Analyze" });
  cases.push_back({ "dim[0] = 8", with(good, 40, std::int16_t(8)), ".nii", "dim[0]" });
  cases.push_back({ "dim[2] = -3", with(good, 44, std::int16_t(-3)), ".nii", "dim[2] is -3" });
  cases.push_back({ "float128", with(with(good, 70, std::int16_t(1536)), 72, std::int16_t(128)),
    ".nii", "float128" });
  cases.push_back({ "bitpix 16 for float32", with(good, 72, std::int16_t(16)), ".nii", "bitpix" });
  cases.push_back(
    { "vox_offset inside the header", with(good, 108, 100.0f), ".nii", "inside the" });
  cases.push_back({ "vox_offset 352.5", with(good, 108, 352.5f), ".nii", "whole number of bytes" });
  cases.push_back({ "vox_offset 1e9", with(good, 108, 1e9f), ".nii", "truncated" });
  cases.push_back(
    { "scl_inter inf", with(with(good, 112, 2.0f), 116, std::numeric_limits<float>::infinity()),
      ".nii", "scl_inter" });
  {
    NIfTIFile q = goodTensor;
    q.SFormCode = 0;
    q.QFormCode = 1;
    q.Quatern[0] = 1.5; // |(b, c, d)| > 1
    cases.push_back({ "qform quaternion longer than 1", q.Bytes(), ".nii", "quaternion" });
  }
  cases.push_back({ "sform NaN", with(tensor, 284, std::numeric_limits<float>::quiet_NaN()), ".nii",
    "non-finite" });
  {
    std::string damaged = NIfTI2({ 4, 3, 2 }) + good.substr(352);
    damaged[8] = '\n'; // "\r\n" -> "\n\n": a text-mode newline conversion
    cases.push_back({ "NIfTI-2 magic newline-damaged", damaged, ".nii", "newline" });
    cases.push_back({ "NIfTI-2, 2^40 voxels along x",
      NIfTI2({ std::int64_t(1) << 40, 3, 2 }) + good.substr(352), ".nii", "extents" });
    cases.push_back({ "NIfTI-2, dimensions overflowing 2^62 bytes",
      NIfTI2({ 4, 3, 2, std::int64_t(1) << 40, std::int64_t(1) << 40 }) + good.substr(352), ".nii",
      "2^62" });
  }
  // Hostile sizes: refused from the file size, before allocating.
  const std::string cubed = with(
    with(with(tensor, 42, std::int16_t(32767)), 44, std::int16_t(32767)), 46, std::int16_t(32767));
  cases.push_back({ "32767^3 voxels in a small file", cubed, ".nii", "truncated" });
  cases.push_back({ "32767^3 voxels in a small gzip file", cubed, ".nii.gz", "cannot hold", true });
  // Damaged gzip streams.
  const std::string gz = Gzip(tensor);
  cases.push_back({ "gzip cut short", gz.substr(0, gz.size() - 50), ".nii.gz", "cut short" });
  {
    std::string crc = gz;
    crc[crc.size() - 8] = static_cast<char>(crc[crc.size() - 8] ^ 0xff);
    cases.push_back({ "gzip with a wrong checksum", crc, ".nii.gz", "incorrect data check" });
    std::string data = gz;
    for (std::size_t i = 40; i < 70; ++i)
    {
      data[i] = static_cast<char>(data[i] ^ 0x55);
    }
    cases.push_back({ "gzip with damaged deflate data", data, ".nii.gz", "damaged" });
  }
  {
    std::string header = good.substr(0, 348);
    header.replace(344, 4, std::string("ni1\0", 4));
    Put<float>(header, 108, 0.0f);
    cases.push_back({ "a .hdr without its .img", header, ".hdr", ".img file is missing" });
    cases.push_back({ "an .img without its .hdr", good.substr(352), ".img", ".hdr) is missing" });
  }

  for (const Case& c : cases)
  {
    const std::string path = OutDir + "/TestNIfTIBadInput-case" + c.Extension;
    if (c.Gzip)
    {
      WriteGzip(path, c.Bytes);
    }
    else
    {
      WriteBytes(path, c.Bytes);
    }
    for (int which = 0; which < 2; ++which)
    {
      vtkImageAlgorithm* reader = which == 0 ? static_cast<vtkImageAlgorithm*>(volume.Get())
                                             : static_cast<vtkImageAlgorithm*>(tensors.Get());
      if (which == 0)
      {
        volume->SetFileName(path.c_str());
      }
      else
      {
        tensors->SetFileName(path.c_str());
      }
      const auto start = std::chrono::steady_clock::now();
      const bool ok = h.Run(reader);
      const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      const std::string msg =
        which == 0 ? volume->GetLastErrorMessage() : tensors->GetLastErrorMessage();
      vtkImageData* out = vtkImageData::SafeDownCast(reader->GetOutputDataObject(0));
      std::cout << c.Name << (which == 0 ? " (volume): " : " (tensor): ") << msg << std::endl;
      SV_CHECK_MSG(status, !ok, c.Name << " was accepted");
      SV_CHECK_MSG(status, out->GetNumberOfPoints() == 0 && !out->GetPointData()->GetScalars(),
        c.Name << " gave a partial output");
      SV_CHECK_MSG(status, msg.find(c.Expected) != std::string::npos,
        c.Name << ": the message does not say \"" << c.Expected << "\"");
      SV_CHECK_MSG(status, seconds < 0.5, c.Name << " took " << seconds << " s");
    }
    SV_CHECK_MSG(status, readsGood(), "after " << c.Name << ": " << h.Error());
    std::remove(path.c_str());
  }

  // A sparse file announcing four times this machine's memory: it passes the
  // file-size checks and is refused before anything is allocated.
  {
    vtksys::SystemInformation info;
    const double memory = static_cast<double>(info.GetHostMemoryTotal()) * 1024.0;
    const std::int64_t nx = 1 << 16, ny = 1 << 14;
    const std::int64_t nz = static_cast<std::int64_t>(4.0 * memory / (4.0 * nx * ny)) + 1;
    const std::string path = OutDir + "/TestNIfTIBadInput-sparse.nii";
    {
      std::ofstream f(path, std::ios::binary | std::ios::trunc);
      const std::string header = NIfTI2({ nx, ny, nz });
      f.write(header.data(), static_cast<std::streamsize>(header.size()));
      f.seekp(static_cast<std::streamoff>(544 + 4 * nx * ny * nz - 1));
      f.put('\0');
    }
    volume->SetFileName(path.c_str());
    const auto start = std::chrono::steady_clock::now();
    const bool ok = h.Run(volume);
    const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::cout << "sparse file of " << (4.0 * nx * ny * nz) / (1 << 30)
              << " GiB of voxels: " << volume->GetLastErrorMessage() << std::endl;
    SV_CHECK(status, !ok && volume->GetOutput()->GetNumberOfPoints() == 0);
    SV_CHECK(
      status, std::string(volume->GetLastErrorMessage()).find("memory") != std::string::npos);
    SV_CHECK_MSG(status, seconds < 0.5, "the sparse file took " << seconds << " s");
    std::remove(path.c_str());
  }

  // Abort at the first progress event: an empty output, no error; then complete.
  {
    NIfTIFile big;
    big.Dim[0] = big.Dim[1] = big.Dim[2] = 48;
    big.Data.assign(48 * 48 * 48, 3.0f);
    const std::string path = OutDir + "/TestNIfTIBadInput-abort.nii.gz";
    WriteGzip(path, big.Bytes());
    vtkNew<vtkCallbackCommand> abort;
    abort->SetCallback([](vtkObject* caller, unsigned long, void*, void*)
      { static_cast<vtkAlgorithm*>(caller)->SetAbortExecute(1); });
    const unsigned long tag = volume->AddObserver(vtkCommand::ProgressEvent, abort);
    volume->SetFileName(path.c_str());
    h.Run(volume);
    SV_CHECK_MSG(status, !h.Observer->GetError() && volume->GetOutput()->GetNumberOfPoints() == 0,
      "aborted: " << h.Error());
    volume->RemoveObserver(tag);
    volume->SetAbortExecute(0);
    SV_CHECK_MSG(status,
      h.Run(volume) && volume->GetOutput()->GetNumberOfPoints() == 48 * 48 * 48 &&
        FirstValue(volume->GetOutput()) == 3.0,
      "after the abort: " << h.Error());
  }
  return status.Result();
}
