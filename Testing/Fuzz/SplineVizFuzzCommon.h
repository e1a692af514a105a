// SPDX-License-Identifier: BSD-3-Clause
// Shared by the SplineViz libFuzzer targets (Testing/Fuzz): failure reports,
// the checks every reader target makes, input files written for readers that
// read from files, and a structure-aware mutator of typed binary header fields.
#ifndef SplineVizFuzzCommon_h
#define SplineVizFuzzCommon_h

#include "vtkLRSplineBezierVolume.h"
#include "vtkLRSplinePatch.h"

#include "vtkAlgorithm.h"
#include "vtkDataSet.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkPointData.h"
#include "vtkPoints.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <unistd.h> // getpid

#ifdef SPLINEVIZ_LIBFUZZER
extern "C" size_t LLVMFuzzerMutate(uint8_t* data, size_t size, size_t maxSize);
#endif

namespace SplineVizFuzz
{
/// A broken promise of the code under test: report and abort (libFuzzer
/// keeps the input as a crash).
[[noreturn]] inline void Fail(const std::string& what)
{
  std::fprintf(stderr, "SplineViz fuzz target: %s\n", what.c_str());
  std::abort();
}

/// A failed parse or read must say why.
inline void CheckMessage(const std::string& error)
{
  if (error.empty())
  {
    Fail("an input was rejected without a message");
  }
}

/// Every accepted patch must be valid and its Bezier form extractable (or
/// refused with a message).
inline void ExtractAll(const std::vector<vtkLRSplinePatch>& patches)
{
  for (const vtkLRSplinePatch& patch : patches)
  {
    std::string error, warning;
    if (!patch.Validate(&error))
    {
      Fail("the parser accepted a patch that does not validate: " + error);
    }
    vtkLRSplineBezierVolume volume;
    if (!patch.ExtractBezier(volume, &error, &warning, 0, patch.GetNumberOfElements()))
    {
      CheckMessage(error);
    }
  }
}

/// Every point of `pts` (none when null) must be finite.
inline void CheckPointsFinite(vtkPoints* pts)
{
  for (vtkIdType i = 0; pts && i < pts->GetNumberOfPoints(); ++i)
  {
    double x[3];
    pts->GetPoint(i, x);
    if (!std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2]))
    {
      Fail("a point is not finite");
    }
  }
}

/// The result of a reader's update: when it failed (`ok` 0) it must say
/// why and leave an empty output; when it succeeded, every point array must
/// cover every point and the points must be finite. SPLINEVIZ_FUZZ_VERBOSE
/// set: prints what happened (replaying the seeds: are they read?).
inline void CheckReaderResult(vtkAlgorithm* reader, int ok, const std::string& lastError)
{
  auto* out = vtkDataSet::SafeDownCast(reader->GetOutputDataObject(0));
  if (!out)
  {
    Fail("the reader has no data set output");
  }
  if (std::getenv("SPLINEVIZ_FUZZ_VERBOSE"))
  {
    std::printf("  %s\n",
      ok ? ("read: " + std::to_string(out->GetNumberOfPoints()) + " points, " +
             std::to_string(out->GetPointData()->GetNumberOfArrays()) + " arrays")
             .c_str()
         : ("refused: " + lastError).c_str());
  }
  if (!ok)
  {
    CheckMessage(lastError);
    if (out->GetNumberOfPoints() != 0 || out->GetPointData()->GetNumberOfArrays() != 0)
    {
      Fail("the read failed but the output is not empty");
    }
    return;
  }
  const vtkIdType n = out->GetNumberOfPoints();
  for (int a = 0; a < out->GetPointData()->GetNumberOfArrays(); ++a)
  {
    vtkAbstractArray* array = out->GetPointData()->GetAbstractArray(a);
    if (array->GetNumberOfTuples() != n)
    {
      Fail(std::string("point array ") + (array->GetName() ? array->GetName() : "?") + " has " +
        std::to_string(array->GetNumberOfTuples()) + " tuples for " + std::to_string(n) +
        " points");
    }
  }
  for (vtkIdType i = 0; i < n; i += std::max<vtkIdType>(1, n / 64))
  {
    double x[3];
    out->GetPoint(i, x);
    if (!std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2]))
    {
      Fail("point " + std::to_string(i) + " is not finite");
    }
  }
}

/// A file of this process for a reader that reads files (in /dev/shm when
/// there is one: no disk traffic); removed when the object goes.
struct TemporaryFile
{
  std::string Path;
  explicit TemporaryFile(const std::string& suffix)
  {
    const char* dir = access("/dev/shm", W_OK) == 0 ? "/dev/shm" : "/tmp";
    this->Path = std::string(dir) + "/splineviz-fuzz-" + std::to_string(getpid()) + suffix;
  }
  ~TemporaryFile() { std::remove(this->Path.c_str()); }
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;
  void Write(const uint8_t* data, size_t size) const
  {
    FILE* f = std::fopen(this->Path.c_str(), "wb");
    if (!f)
    {
      Fail("cannot write " + this->Path);
    }
    if (size > 0 && std::fwrite(data, 1, size, f) != size)
    {
      Fail("cannot write " + this->Path);
    }
    std::fclose(f);
  }
  void Write(const std::vector<uint8_t>& bytes) const { this->Write(bytes.data(), bytes.size()); }
};

inline bool HostLittleEndian()
{
  const std::uint16_t one = 1;
  unsigned char first;
  std::memcpy(&first, &one, 1);
  return first == 1;
}

/// A typed field of a binary header: where, which type ('b' int8, 'h'
/// int16, 'i' int32, 'q' int64, 'f' float32, 'd' float64) and how many.
struct Field
{
  size_t Offset;
  char Type;
  int Count;
};

/**
 * Structure-aware mutation of a binary header at `data` (`size` bytes
 * available): 1 to 3 fields of `fields` set to values a reader must survive
 * (0, +-1, small counts, type limits, NaN, infinities, huge and tiny values,
 * values near the input's size, neighbours of the old value, random bits),
 * written in the header's byte order (`bigEndian`).
 */
inline void MutateFields(
  uint8_t* data, size_t size, const std::vector<Field>& fields, bool bigEndian, unsigned int seed)
{
  std::minstd_rand rng(seed);
  auto pick = [&rng](size_t n) { return static_cast<size_t>(rng() % n); };
  const bool swap = bigEndian == HostLittleEndian();
  const int changes = 1 + static_cast<int>(pick(3));
  for (int c = 0; c < changes; ++c)
  {
    const Field& f = fields[pick(fields.size())];
    const size_t width = f.Type == 'b'   ? 1
      : f.Type == 'h'                    ? 2
      : (f.Type == 'i' || f.Type == 'f') ? 4
                                         : 8;
    const size_t at = f.Offset + width * pick(static_cast<size_t>(f.Count));
    if (at + width > size)
    {
      continue;
    }
    unsigned char bytes[8];
    std::memcpy(bytes, data + at, width);
    auto flip = [&]()
    {
      for (size_t i = 0; swap && i < width / 2; ++i)
      {
        std::swap(bytes[i], bytes[width - 1 - i]);
      }
    };
    flip(); // to host order
    if (f.Type == 'f' || f.Type == 'd')
    {
      double old;
      if (f.Type == 'f')
      {
        float v;
        std::memcpy(&v, bytes, 4);
        old = v;
      }
      else
      {
        std::memcpy(&old, bytes, 8);
      }
      const double special[] = { 0.0, -0.0, 1.0, -1.0, 0.5, 2.0, 348.0, 352.0, 540.0, 544.0,
        static_cast<double>(size), std::numeric_limits<double>::quiet_NaN(),
        std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(), 1e-38,
        1e38, 3.4e38, -3.4e38, 1e-300, 1e300, 1.4e-45, 0.999999, 1.000001, 16.5, 1e9 };
      double v;
      switch (pick(4))
      {
        case 0:
        case 1:
          v = special[pick(sizeof(special) / sizeof(special[0]))];
          break;
        case 2:
          v = old * (pick(2) ? -1.0 : 2.0) + static_cast<double>(pick(5)) - 2.0;
          break;
        default:
          v = std::ldexp(
            static_cast<double>(rng()) / 2147483647.0 - 0.5, static_cast<int>(pick(80)) - 20);
          break;
      }
      if (f.Type == 'f')
      {
        const float fv = static_cast<float>(v);
        std::memcpy(bytes, &fv, 4);
      }
      else
      {
        std::memcpy(bytes, &v, 8);
      }
    }
    else
    {
      std::int64_t old = 0;
      if (width == 1)
      {
        old = static_cast<std::int8_t>(bytes[0]);
      }
      else if (width == 2)
      {
        std::int16_t v;
        std::memcpy(&v, bytes, 2);
        old = v;
      }
      else if (width == 4)
      {
        std::int32_t v;
        std::memcpy(&v, bytes, 4);
        old = v;
      }
      else
      {
        std::memcpy(&old, bytes, 8);
      }
      const std::int64_t special[] = { 0, 1, -1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 16, 32, 64, 100, 127,
        -128, 255, 256, 348, 352, 540, 1000, 32767, -32768, 65535, 2147483647LL, -2147483647LL - 1,
        4294967295LL, (std::int64_t(1) << 40), (std::int64_t(1) << 62),
        std::numeric_limits<std::int64_t>::max(), std::numeric_limits<std::int64_t>::min(),
        static_cast<std::int64_t>(size), static_cast<std::int64_t>(size) / 4,
        static_cast<std::int64_t>(size) - 352 };
      std::int64_t v;
      switch (pick(4))
      {
        case 0:
        case 1:
          v = special[pick(sizeof(special) / sizeof(special[0]))];
          break;
        case 2:
          // (unsigned: wraps around instead of overflowing)
          v = static_cast<std::int64_t>(
            static_cast<std::uint64_t>(old) + static_cast<std::uint64_t>(pick(33)) - 16u);
          break;
        default:
          v = static_cast<std::int64_t>(rng()) ^ (static_cast<std::int64_t>(rng()) << 31);
          break;
      }
      // the low bytes of v, in host order
      std::memcpy(
        bytes, reinterpret_cast<unsigned char*>(&v) + (HostLittleEndian() ? 0 : 8 - width), width);
    }
    flip(); // back to the file's order
    std::memcpy(data + at, bytes, width);
  }
}
}

#endif
