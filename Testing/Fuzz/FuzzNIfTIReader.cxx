// SPDX-License-Identifier: BSD-3-Clause
// libFuzzer target: vtkNIfTIVolumeReader and vtkNIfTITensorReader (and the
// NIfTI file layer under them, vtkNIfTIFile) on files made from the input.
// The first byte chooses how, the rest is the file:
//   bits 0-1  0: a .nii; 1: a .nii.gz (the rest compressed here, so that the
//             header mutations below reach compressed files too); 2: a
//             .nii.gz as given (damaged gzip streams); 3: a .hdr/.img pair
//             (the first 348 or 540 bytes the .hdr, the rest the .img)
//   bit 2     the tensor reader (else the volume reader)
//   bits 3-4  AffineSource (automatic, sform, qform, pixdim)
//   bit 5     read a sub-extent (half the slices) instead of the whole image
//   bit 6     volume reader: every 4th-dimension volume a component;
//             tensor reader: the FSL layout
//   bit 7     volume reader: volume 1 of the 4th dimension; tensor reader:
//             companions (the file itself, and a volume on another grid);
//             a pair: opened through its .img
// Either reader must succeed with a complete, finite output or fail with a
// message and an empty output (SplineVizFuzz::CheckReaderResult).
//
// LLVMFuzzerCustomMutator mutates the header's fields as typed values
// (NIfTI-1 and NIfTI-2 layouts, in the header's byte order) most of the time,
// libFuzzer's byte-level mutations otherwise.
#include "SplineVizFuzzCommon.h"

#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkNIfTITensorReader.h"
#include "vtkNIfTIVolumeReader.h"
#include "vtkNew.h"
#include "vtkObject.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtk_zlib.h"

#include <random>

namespace
{
enum Containers
{
  NII = 0,
  NII_GZ = 1,
  RAW_GZ = 2,
  PAIR = 3
};

std::vector<uint8_t> Gzip(const uint8_t* data, size_t size)
{
  z_stream zs;
  std::memset(&zs, 0, sizeof(zs));
  if (deflateInit2(&zs, 1, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY) != Z_OK)
  {
    SplineVizFuzz::Fail("deflateInit2 failed");
  }
  std::vector<uint8_t> out(deflateBound(&zs, static_cast<uLong>(size)) + 64);
  zs.next_in = const_cast<Bytef*>(data);
  zs.avail_in = static_cast<uInt>(size);
  zs.next_out = out.data();
  zs.avail_out = static_cast<uInt>(out.size());
  deflate(&zs, Z_FINISH);
  out.resize(zs.total_out);
  deflateEnd(&zs);
  return out;
}

// Where sizeof_hdr says the header ends (540 for NIfTI-2, else 348), and its byte order.
size_t HeaderSize(const uint8_t* p, size_t n, bool& bigEndian)
{
  bigEndian = false;
  if (n < 4)
  {
    return 348;
  }
  const std::uint32_t le = p[0] | p[1] << 8 | p[2] << 16 | static_cast<std::uint32_t>(p[3]) << 24;
  const std::uint32_t be = p[3] | p[2] << 8 | p[1] << 16 | static_cast<std::uint32_t>(p[0]) << 24;
  if (le != 348 && le != 540 && (be == 348 || be == 540))
  {
    bigEndian = true;
    return be;
  }
  return le == 540 ? 540 : 348;
}

template <typename T>
void Put(std::vector<uint8_t>& b, size_t at, T v)
{
  std::memcpy(b.data() + at, &v, sizeof(T));
}

// A valid float32 volume, 4 x 3 x 3, on a rotated 1.5 mm grid: a companion on
// another grid than the input's (the tensor reader's resampling path).
const std::string& OtherGridCompanion()
{
  static SplineVizFuzz::TemporaryFile file(".companion.nii");
  static const bool written = []()
  {
    std::vector<uint8_t> b(352 + 36 * 4, 0);
    Put<std::int32_t>(b, 0, 348);
    const std::int16_t dims[8] = { 3, 4, 3, 3, 1, 1, 1, 1 };
    for (int i = 0; i < 8; ++i)
    {
      Put<std::int16_t>(b, 40 + 2 * i, dims[i]);
      Put<float>(b, 76 + 4 * i, 1.5f);
    }
    Put<std::int16_t>(b, 70, 16);
    Put<std::int16_t>(b, 72, 32);
    Put<float>(b, 108, 352.0f);
    Put<std::int16_t>(b, 254, 1);
    const float rows[12] = { 1.3f, -0.75f, 0, -2, 0.75f, 1.3f, 0, 1, 0, 0, 1.5f, -1 };
    for (int i = 0; i < 12; ++i)
    {
      Put<float>(b, 280 + 4 * i, rows[i]);
    }
    std::memcpy(b.data() + 344, "n+1\0", 4);
    for (int v = 0; v < 36; ++v)
    {
      Put<float>(b, 352 + 4 * v, 0.25f * v);
    }
    SplineVizFuzz::TemporaryFile* f = &file;
    f->Write(b);
    return true;
  }();
  (void)written;
  return file.Path;
}

// Half the slices of the reader's whole extent.
void HalfExtent(vtkAlgorithm* reader, int ext[6])
{
  vtkInformation* info = reader->GetOutputInformation(0);
  info->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), ext);
  ext[4] = (ext[4] + ext[5] + 1) / 2;
}

template <typename Reader>
void Run(Reader* reader, bool subExtent)
{
  int ok;
  if (subExtent)
  {
    ok =
      vtkStreamingDemandDrivenPipeline::SafeDownCast(reader->GetExecutive())->UpdateInformation();
    if (ok)
    {
      int ext[6] = { 0, -1, 0, -1, 0, -1 };
      HalfExtent(reader, ext);
      ok = reader->UpdateExtent(ext);
    }
  }
  else
  {
    ok = reader->GetExecutive()->Update();
  }
  SplineVizFuzz::CheckReaderResult(reader, ok, reader->GetLastErrorMessage());
}
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  if (size < 1)
  {
    return 0;
  }
  vtkObject::GlobalWarningDisplayOff(); // errors are expected; keep the run quiet
  const uint8_t mode = data[0];
  const uint8_t* payload = data + 1;
  const size_t n = size - 1;
  const int container = mode & 3;
  SplineVizFuzz::TemporaryFile nii(".nii"), gz(".nii.gz"), hdr(".hdr"), img(".img");
  std::string path;
  switch (container)
  {
    case NII:
      nii.Write(payload, n);
      path = nii.Path;
      break;
    case NII_GZ:
      gz.Write(Gzip(payload, n));
      path = gz.Path;
      break;
    case RAW_GZ:
      gz.Write(payload, n);
      path = gz.Path;
      break;
    default:
    {
      bool big;
      const size_t h = std::min(n, HeaderSize(payload, n, big));
      hdr.Write(payload, h);
      img.Write(payload + h, n - h);
      path = (mode & 0x80) ? img.Path : hdr.Path;
      break;
    }
  }
  const int affineSource = (mode >> 3) & 3;
  const bool subExtent = (mode & 0x20) != 0;
  if (mode & 4)
  {
    vtkNew<vtkNIfTITensorReader> reader;
    reader->SetFileName(path.c_str());
    reader->SetAffineSource(affineSource);
    if (mode & 0x40)
    {
      reader->SetTensorLayoutToFSL();
    }
    if ((mode & 0x80) && container != PAIR)
    {
      reader->AddCompanionFileName(path.c_str());
      reader->AddCompanionFileName(OtherGridCompanion().c_str());
    }
    Run(reader.Get(), subExtent);
  }
  else
  {
    vtkNew<vtkNIfTIVolumeReader> reader;
    reader->SetFileName(path.c_str());
    reader->SetAffineSource(affineSource);
    if (mode & 0x40)
    {
      reader->SetFourthDimensionToComponents();
    }
    else if ((mode & 0x80) && container != PAIR)
    {
      reader->SetFourthDimensionToVolumes();
      reader->SetVolumeIndex(1);
    }
    Run(reader.Get(), subExtent);
  }
  return 0;
}

#ifdef SPLINEVIZ_LIBFUZZER
namespace
{
using SplineVizFuzz::Field;
// The NIfTI-1 header's numeric fields (offset, type, count).
const std::vector<Field> NIfTI1Fields = { { 0, 'i', 1 }, { 40, 'h', 8 }, { 56, 'f', 3 },
  { 68, 'h', 1 }, { 70, 'h', 1 }, { 72, 'h', 1 }, { 74, 'h', 1 }, { 76, 'f', 8 }, { 108, 'f', 1 },
  { 112, 'f', 1 }, { 116, 'f', 1 }, { 120, 'h', 1 }, { 122, 'b', 2 }, { 124, 'f', 4 },
  { 252, 'h', 1 }, { 254, 'h', 1 }, { 256, 'f', 3 }, { 268, 'f', 3 }, { 280, 'f', 12 } };
// The NIfTI-2 header's.
const std::vector<Field> NIfTI2Fields = { { 0, 'i', 1 }, { 12, 'h', 1 }, { 14, 'h', 1 },
  { 16, 'q', 8 }, { 80, 'd', 3 }, { 104, 'd', 8 }, { 168, 'q', 1 }, { 176, 'd', 1 },
  { 184, 'd', 1 }, { 192, 'd', 4 }, { 224, 'q', 2 }, { 344, 'i', 1 }, { 348, 'i', 1 },
  { 352, 'd', 3 }, { 376, 'd', 3 }, { 400, 'd', 12 }, { 496, 'i', 3 } };
}

extern "C" size_t LLVMFuzzerCustomMutator(
  uint8_t* data, size_t size, size_t maxSize, unsigned int seed)
{
  std::minstd_rand rng(seed);
  if (size < 2 || (data[0] & 3) == RAW_GZ || rng() % 4 == 0)
  {
    return LLVMFuzzerMutate(data, size, maxSize);
  }
  if (rng() % 16 == 0)
  {
    data[0] = static_cast<uint8_t>(rng());
    return size;
  }
  uint8_t* header = data + 1;
  const size_t n = size - 1;
  bool big = false;
  const size_t h = HeaderSize(header, n, big);
  if (rng() % 10 == 0)
  {
    // the magic: the other version's, the pair's, or none
    static const char* magics[] = { "n+1", "ni1", "n+2", "ni2", "\0\0\0" };
    const char* m = magics[rng() % 5];
    const size_t at = h == 540 ? 4 : 344;
    if (at + 4 <= n)
    {
      std::memcpy(header + at, m, 3);
      header[at + 3] = 0;
    }
    return size;
  }
  SplineVizFuzz::MutateFields(
    header, n, h == 540 ? NIfTI2Fields : NIfTI1Fields, big, static_cast<unsigned int>(rng()));
  return size;
}
#endif
