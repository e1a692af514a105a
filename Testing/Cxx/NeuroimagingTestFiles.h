// SPDX-License-Identifier: BSD-3-Clause
// Helpers of the neuroimaging IO tests: files written byte by byte here,
// independently of the readers and writers under test (a minimal NIfTI-1
// writer, raw MRtrix .tck/.tsf and TrackVis .trk builders), and a harness
// that runs a reader with its errors observed.
#ifndef NeuroimagingTestFiles_h
#define NeuroimagingTestFiles_h

#include "vtkAlgorithm.h"
#include "vtkCommand.h"
#include "vtkExecutive.h"
#include "vtkNew.h"
#include "vtkTestErrorObserver.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

namespace neurotest
{
const std::string OutDir = SPLINEVIZ_TEST_OUTPUT_DIR;

inline void WriteBytes(const std::string& path, const std::string& bytes)
{
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

inline std::string ReadBytes(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

inline bool HostLittleEndian()
{
  const std::uint16_t one = 1;
  unsigned char b;
  std::memcpy(&b, &one, 1);
  return b == 1;
}

/// Appends v in little- (or big-) endian byte order.
template <typename T>
void Append(std::string& s, T v, bool bigEndian = false)
{
  unsigned char b[sizeof(T)];
  std::memcpy(b, &v, sizeof(T));
  if (bigEndian == HostLittleEndian())
  {
    for (std::size_t i = 0; i < sizeof(T) / 2; ++i)
    {
      std::swap(b[i], b[sizeof(T) - 1 - i]);
    }
  }
  s.append(reinterpret_cast<const char*>(b), sizeof(T));
}

template <typename T>
void Put(std::string& s, std::size_t offset, T v)
{
  std::string tmp;
  Append(tmp, v);
  s.replace(offset, sizeof(T), tmp);
}

/// A NIfTI-1 single file (.nii), float32 little-endian voxels in NIfTI order
/// (x fastest, then y, z, dim 4, dim 5). `sform` (3 rows of 4) is used when
/// sformCode > 0; the quaternion (b, c, d), qfac and offsets when qformCode > 0.
struct NIfTIFile
{
  int Dim[5] = { 1, 1, 1, 1, 1 };
  int NumberOfDimensions = 3;
  float PixDim[3] = { 1, 1, 1 };
  float QFac = 1;
  int SFormCode = 0, QFormCode = 0;
  double SForm[3][4] = { { 1, 0, 0, 0 }, { 0, 1, 0, 0 }, { 0, 0, 1, 0 } };
  double Quatern[3] = { 0, 0, 0 };
  double QOffset[3] = { 0, 0, 0 };
  int IntentCode = 0;
  int Units = 2;      // mm
  bool Int16 = false; // int16 voxels instead of float32
  std::vector<float> Data;

  std::string Bytes() const
  {
    std::string h(352, '\0');
    Put<std::int32_t>(h, 0, 348);
    h[39] = 0;
    Put<std::int16_t>(h, 40, static_cast<std::int16_t>(this->NumberOfDimensions));
    for (int i = 0; i < 5; ++i)
    {
      Put<std::int16_t>(h, 42 + 2 * i, static_cast<std::int16_t>(this->Dim[i]));
    }
    for (int i = 5; i < 7; ++i)
    {
      Put<std::int16_t>(h, 42 + 2 * i, 1);
    }
    Put<std::int16_t>(h, 68, static_cast<std::int16_t>(this->IntentCode));
    Put<std::int16_t>(h, 70, static_cast<std::int16_t>(this->Int16 ? 4 : 16)); // int16, float32
    Put<std::int16_t>(h, 72, static_cast<std::int16_t>(this->Int16 ? 16 : 32));
    Put<float>(h, 76, this->QFac);
    for (int i = 0; i < 3; ++i)
    {
      Put<float>(h, 80 + 4 * i, this->PixDim[i]);
    }
    Put<float>(h, 92, 1.0f);
    Put<float>(h, 96, 1.0f);
    Put<float>(h, 108, 352.0f); // vox_offset
    Put<float>(h, 112, 0.0f);   // scl_slope: no scaling
    h[123] = static_cast<char>(this->Units);
    Put<std::int16_t>(h, 252, static_cast<std::int16_t>(this->QFormCode));
    Put<std::int16_t>(h, 254, static_cast<std::int16_t>(this->SFormCode));
    for (int i = 0; i < 3; ++i)
    {
      Put<float>(h, 256 + 4 * i, static_cast<float>(this->Quatern[i]));
      Put<float>(h, 268 + 4 * i, static_cast<float>(this->QOffset[i]));
    }
    for (int r = 0; r < 3; ++r)
    {
      for (int c = 0; c < 4; ++c)
      {
        Put<float>(h, 280 + 16 * r + 4 * c, static_cast<float>(this->SForm[r][c]));
      }
    }
    h.replace(344, 4, std::string("n+1\0", 4));
    for (float v : this->Data)
    {
      if (this->Int16)
      {
        Append(h, static_cast<std::int16_t>(std::lround(v)));
      }
      else
      {
        Append(h, v);
      }
    }
    return h;
  }
  void Write(const std::string& path) const { WriteBytes(path, this->Bytes()); }
};

/// An MRtrix file: `magic`, the given header lines, `file: . OFFSET`, END, then `values`.
inline std::string MRtrixBytes(const std::string& magic, const std::string& lines,
  const std::vector<float>& values, bool bigEndian = false, const char* datatype = nullptr)
{
  std::string head = magic + "\n" + lines +
    "datatype: " + (datatype ? datatype : (bigEndian ? "Float32BE" : "Float32LE")) + "\n";
  // a fixed-width offset field keeps the arithmetic simple
  const std::size_t offset = head.size() + std::strlen("file: . 00000000\nEND\n");
  char field[32];
  std::snprintf(field, sizeof(field), "file: . %08zu\nEND\n", offset);
  std::string s = head + field;
  for (float v : values)
  {
    Append(s, v, bigEndian);
  }
  return s;
}

/// Streamlines as .tck values: the points, a NaN triplet after each, inf at the end.
inline std::vector<float> TckValues(const std::vector<std::vector<float>>& lines)
{
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  std::vector<float> v;
  for (const auto& l : lines)
  {
    v.insert(v.end(), l.begin(), l.end());
    v.insert(v.end(), { nan, nan, nan });
  }
  v.insert(v.end(), { inf, inf, inf });
  return v;
}

/// A TrackVis header (little-endian unless bigEndian) with the given fields.
struct TrkFile
{
  short Dim[3] = { 10, 10, 10 };
  float VoxelSize[3] = { 1, 1, 1 };
  short NumberOfScalars = 0, NumberOfProperties = 0;
  std::vector<std::string> ScalarNames, PropertyNames;
  float VoxelToRAS[16] = { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 };
  std::string VoxelOrder = "RAS";
  int Count = 0;
  int Version = 2;
  int HeaderSize = 1000;
  bool BigEndian = false;
  std::string Magic = std::string("TRACK\0", 6);
  std::string Records;

  std::string Header() const
  {
    std::string h;
    h += this->Magic;
    for (short d : this->Dim)
    {
      Append(h, d, this->BigEndian);
    }
    for (float v : this->VoxelSize)
    {
      Append(h, v, this->BigEndian);
    }
    for (int i = 0; i < 3; ++i)
    {
      Append(h, 0.0f, this->BigEndian);
    }
    Append(h, this->NumberOfScalars, this->BigEndian);
    std::string names(200, '\0');
    for (std::size_t i = 0; i < this->ScalarNames.size(); ++i)
    {
      names.replace(20 * i, this->ScalarNames[i].size(), this->ScalarNames[i]);
    }
    h += names;
    Append(h, this->NumberOfProperties, this->BigEndian);
    names.assign(200, '\0');
    for (std::size_t i = 0; i < this->PropertyNames.size(); ++i)
    {
      names.replace(20 * i, this->PropertyNames[i].size(), this->PropertyNames[i]);
    }
    h += names;
    for (float v : this->VoxelToRAS)
    {
      Append(h, this->Version >= 2 ? v : 0.0f, this->BigEndian);
    }
    h += std::string(444, '\0');
    std::string order = this->VoxelOrder;
    order.resize(4, '\0');
    h += order;
    h += std::string(4 + 24 + 2 + 6, '\0');
    Append(h, this->Count, this->BigEndian);
    Append(h, this->Version, this->BigEndian);
    Append(h, this->HeaderSize, this->BigEndian);
    return h;
  }
  /// Appends a streamline: its points (x y z scalars...) then its properties.
  void AddStreamline(int points, const std::vector<float>& values, const std::vector<float>& props)
  {
    Append(this->Records, static_cast<std::int32_t>(points), this->BigEndian);
    for (float v : values)
    {
      Append(this->Records, v, this->BigEndian);
    }
    for (float v : props)
    {
      Append(this->Records, v, this->BigEndian);
    }
  }
  std::string Bytes() const { return this->Header() + this->Records; }
};

/// Runs `algorithm` with errors and warnings observed; true when it succeeded.
struct Harness
{
  vtkNew<vtkTest::ErrorObserver> Observer;
  void Watch(vtkAlgorithm* a)
  {
    a->AddObserver(vtkCommand::ErrorEvent, this->Observer);
    a->AddObserver(vtkCommand::WarningEvent, this->Observer);
    a->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, this->Observer);
  }
  bool Run(vtkAlgorithm* a)
  {
    this->Observer->Clear();
    a->Modified();
    const int ok = a->GetExecutive()->Update();
    return ok && !this->Observer->GetError();
  }
  std::string Error() { return this->Observer->GetErrorMessage(); }
  bool Warned() { return this->Observer->GetWarning(); }
};
}

#endif
