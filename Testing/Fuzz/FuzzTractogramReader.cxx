// SPDX-License-Identifier: BSD-3-Clause
// libFuzzer target: vtkTractogramReader on .tck, .trk and .tck + .tsf files
// made from the input. The first byte chooses how, the rest is the file:
//   bits 0-1  0: a .tck; 1: a .trk; 2: a .tck and a .tsf (the .tsf starts at
//             the first "mrtrix track scalars" of the rest); 3: a file of
//             unknown extension (the format recognised by its first bytes)
//   bit 2     FileFormat set (TCK, or TRK for 1) instead of automatic
//   bit 3     KeepEmptyStreamlines
//   bit 4     a piece request: the number of pieces (1-8) and the piece from the last byte
//   bits 5-6  SubsetMode (0 all, 1 every 3rd, 2 a random half, 3 all)
// The reader must succeed with complete, finite polylines whose point ids
// are points of the output, or fail with a message and an empty output.
//
// LLVMFuzzerCustomMutator mutates the TrackVis header's fields (and the first
// streamline's point count) as typed values for .trk inputs, in the header's
// byte order; byte-level mutations otherwise.
#include "SplineVizFuzzCommon.h"

#include "vtkCellArray.h"
#include "vtkNew.h"
#include "vtkObject.h"
#include "vtkPolyData.h"
#include "vtkTractogramReader.h"

#include <random>

namespace
{
enum Kinds
{
  TCK = 0,
  TRK = 1,
  TCK_TSF = 2,
  DETECT = 3
};

// Every point id of every polyline is a point of the output.
void CheckLines(vtkPolyData* lines)
{
  const vtkIdType n = lines->GetNumberOfPoints();
  vtkCellArray* cells = lines->GetLines();
  vtkIdType count;
  const vtkIdType* ids;
  for (cells->InitTraversal(); cells->GetNextCell(count, ids);)
  {
    for (vtkIdType i = 0; i < count; ++i)
    {
      if (ids[i] < 0 || ids[i] >= n)
      {
        SplineVizFuzz::Fail(
          "a polyline refers to point " + std::to_string(ids[i]) + " of " + std::to_string(n));
      }
    }
  }
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
  const int kind = mode & 3;
  const uint8_t* payload = data + 1;
  const size_t n = size - 1;
  SplineVizFuzz::TemporaryFile tck(".tck"), trk(".trk"), tsf(".tsf"), other(".fib");
  vtkNew<vtkTractogramReader> reader;
  switch (kind)
  {
    case TCK:
      tck.Write(payload, n);
      reader->SetFileName(tck.Path.c_str());
      break;
    case TRK:
      trk.Write(payload, n);
      reader->SetFileName(trk.Path.c_str());
      break;
    case TCK_TSF:
    {
      static const std::string marker = "mrtrix track scalars";
      const std::string text(reinterpret_cast<const char*>(payload), n);
      const size_t split = std::min(text.find(marker, 1), n);
      tck.Write(payload, split);
      tsf.Write(payload + split, n - split);
      reader->SetFileName(tck.Path.c_str());
      reader->AddScalarFileName(tsf.Path.c_str());
      break;
    }
    default:
      other.Write(payload, n);
      reader->SetFileName(other.Path.c_str());
      break;
  }
  if (mode & 4)
  {
    reader->SetFileFormat(kind == TRK ? vtkTractogramReader::TRK : vtkTractogramReader::TCK);
  }
  reader->SetKeepEmptyStreamlines((mode & 8) != 0);
  reader->SetSubsetMode(((mode >> 5) & 3) % 3);
  reader->SetSubsetStride(3);
  reader->SetSubsetFraction(0.5);
  const int last = n > 0 ? payload[n - 1] : 0;
  const int pieces = 1 + last % 8;
  const int ok = (mode & 16) ? reader->UpdatePiece((last / 8) % pieces, pieces, 0)
                             : reader->GetExecutive()->Update();
  SplineVizFuzz::CheckReaderResult(reader, ok, reader->GetLastErrorMessage());
  if (ok)
  {
    CheckLines(reader->GetOutput());
  }
  return 0;
}

#ifdef SPLINEVIZ_LIBFUZZER
namespace
{
using SplineVizFuzz::Field;
// The TrackVis header's numeric fields, and the first streamline's point count.
const std::vector<Field> TrkFields = { { 6, 'h', 3 }, { 12, 'f', 3 }, { 24, 'f', 3 },
  { 36, 'h', 1 }, { 238, 'h', 1 }, { 440, 'f', 16 }, { 956, 'f', 6 }, { 988, 'i', 1 },
  { 992, 'i', 1 }, { 996, 'i', 1 }, { 1000, 'i', 1 } };
}

extern "C" size_t LLVMFuzzerCustomMutator(
  uint8_t* data, size_t size, size_t maxSize, unsigned int seed)
{
  std::minstd_rand rng(seed);
  if (size < 1001 || (data[0] & 3) != TRK || rng() % 3 == 0)
  {
    return LLVMFuzzerMutate(data, size, maxSize);
  }
  // hdr_size (the last header int) is 1000 in the file's byte order
  const uint8_t* hs = data + 1 + 996;
  const bool big = hs[0] == 0 && hs[1] == 0 && hs[2] == 0x03 && hs[3] == 0xe8;
  SplineVizFuzz::MutateFields(data + 1, size - 1, TrkFields, big, static_cast<unsigned int>(rng()));
  return size;
}
#endif
