// SPDX-License-Identifier: BSD-3-Clause
#include "vtkTractogramReader.h"

#include "vtkSplineVizNameList.h"
#include "vtkSplineVizPieces.h"
#include "vtkSplineVizProgress.h"
#include "vtkTractogramFormats.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkSMPTools.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStringArray.h"
#include "vtkTypeInt32Array.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cctype>
#include <cstring>
#include <fstream>
#include <limits>
#include <memory>
#include <vector>

vtkStandardNewMacro(vtkTractogramReader);

using TF = vtkTractogramFormats;

namespace
{
constexpr unsigned long long ReadChunkBytes = 16ull << 20; // 16 MiB per read
constexpr vtkIdType BatchPoints = 1 << 21;                 // points per parallel batch

// A value of the data section in host order, as double.
inline double Value(const char* p, int size, bool swap)
{
  if (size == 4)
  {
    float f;
    std::memcpy(&f, p, 4);
    if (swap)
    {
      TF::SwapBytes(&f, 4, 1);
    }
    return f;
  }
  double d;
  std::memcpy(&d, p, 8);
  if (swap)
  {
    TF::SwapBytes(&d, 8, 1);
  }
  return d;
}

// The special tuples of a block of an MRtrix stream of k-tuples (3 for .tck,
// 1 for .tsf): all-NaN separators (ends of streamlines), the first
// all-infinite tuple (the end marker) and the first tuple mixing NaN or
// infinite values with numbers (damage). Indices are tuples of the block.
// Parallel over chunks of tuples.
struct MRtrixSpecials
{
  static constexpr std::uint64_t None = std::numeric_limits<std::uint64_t>::max();
  std::vector<std::uint64_t> Separators; // before Terminator and Invalid
  std::uint64_t Terminator = None;
  std::uint64_t Invalid = None;
};

void FindSpecials(const char* data, std::uint64_t tuples, int valueSize, bool swap, int tupleSize,
  MRtrixSpecials& out)
{
  const std::size_t tupleBytes = static_cast<std::size_t>(valueSize) * tupleSize;
  const std::uint64_t chunk = 1 << 20;
  const std::uint64_t chunks = (tuples + chunk - 1) / chunk;
  std::vector<MRtrixSpecials> results(static_cast<std::size_t>(chunks));
  vtkSMPTools::For(0, static_cast<vtkIdType>(chunks),
    [&](vtkIdType c0, vtkIdType c1)
    {
      for (vtkIdType c = c0; c < c1; ++c)
      {
        MRtrixSpecials& r = results[static_cast<std::size_t>(c)];
        const std::uint64_t t0 = static_cast<std::uint64_t>(c) * chunk;
        const std::uint64_t t1 = std::min(tuples, t0 + chunk);
        for (std::uint64_t t = t0; t < t1; ++t)
        {
          const char* p = data + t * tupleBytes;
          if (valueSize == 4)
          {
            // fast path: a float32 is NaN or infinite iff its exponent bits are all set
            const std::uint32_t mask = swap ? 0x0000807fu : 0x7f800000u; // byte-reversed
            bool special = false;
            for (int k = 0; k < tupleSize; ++k)
            {
              std::uint32_t w;
              std::memcpy(&w, p + 4 * k, 4);
              special = special || (w & mask) == mask;
            }
            if (!special)
            {
              continue;
            }
          }
          int nan = 0, inf = 0;
          for (int k = 0; k < tupleSize; ++k)
          {
            const double v = Value(p + k * valueSize, valueSize, swap);
            nan += std::isnan(v) ? 1 : 0;
            inf += std::isinf(v) ? 1 : 0;
          }
          if (nan == 0 && inf == 0)
          {
            continue;
          }
          if (nan == tupleSize)
          {
            r.Separators.push_back(t);
          }
          else if (inf == tupleSize)
          {
            r.Terminator = t;
            break; // nothing after the end marker matters
          }
          else
          {
            r.Invalid = t;
            break;
          }
        }
      }
    });
  out = MRtrixSpecials();
  for (MRtrixSpecials& r : results)
  {
    out.Separators.insert(out.Separators.end(), r.Separators.begin(), r.Separators.end());
    if (r.Terminator != MRtrixSpecials::None || r.Invalid != MRtrixSpecials::None)
    {
      out.Terminator = r.Terminator;
      out.Invalid = r.Invalid;
      break;
    }
  }
}

// The message for a damaged tuple.
std::string InvalidTupleError(std::uint64_t tuple)
{
  return "value tuple " + std::to_string(tuple) +
    " mixes NaN or infinite values with numbers (a damaged file)";
}

// The streamline structure of a whole MRtrix stream: the tuples before the
// first all-infinite one, split at the all-NaN ones.
struct MRtrixStructure
{
  std::vector<std::uint64_t> Start; // first tuple of each streamline
  std::vector<vtkIdType> Count;     // its number of tuples
  std::uint64_t Terminator = 0;     // the end marker's tuple
};

template <typename Buffer>
bool ScanMRtrix(const Buffer& data, int valueSize, bool swap, int tupleSize, MRtrixStructure& out,
  std::string& error, bool& trailing)
{
  const std::size_t tupleBytes = static_cast<std::size_t>(valueSize) * tupleSize;
  const bool partialTail = data.size() % tupleBytes != 0;
  MRtrixSpecials specials;
  FindSpecials(data.data(), data.size() / tupleBytes, valueSize, swap, tupleSize, specials);
  if (specials.Invalid != MRtrixSpecials::None)
  {
    error = InvalidTupleError(specials.Invalid);
    return false;
  }
  if (specials.Terminator == MRtrixSpecials::None)
  {
    error = partialTail
      ? "the file ends inside a value tuple and has no end marker (a truncated file)"
      : "the file has no end marker (inf inf inf): a truncated file";
    return false;
  }
  const std::uint64_t terminator = specials.Terminator;
  trailing = (terminator + 1) * tupleBytes < data.size();
  out.Start.clear();
  out.Count.clear();
  out.Terminator = terminator;
  std::uint64_t begin = 0;
  for (std::uint64_t s : specials.Separators)
  {
    out.Start.push_back(begin);
    out.Count.push_back(static_cast<vtkIdType>(s - begin));
    begin = s + 1;
  }
  if (begin != terminator)
  {
    error = "the last streamline is not ended by NaNs before the end marker (a damaged file)";
    return false;
  }
  return true;
}

// floor(total * p / n) without overflow.
std::uint64_t Share(std::uint64_t total, int p, int n)
{
  const std::uint64_t un = static_cast<std::uint64_t>(n), up = static_cast<std::uint64_t>(p);
  return (total / un) * up + (total % un) * up / un;
}

// Random reads of a file (the probes and record-header scans of piece
// reads), unbuffered: only the requested bytes are read; counted.
class FileCursor
{
public:
  explicit FileCursor(const std::string& name)
  {
    this->In.rdbuf()->pubsetbuf(nullptr, 0);
    this->In.open(name, std::ios::in | std::ios::binary);
  }
  bool Read(std::uint64_t offset, std::size_t n, void* dst)
  {
    this->In.clear();
    this->In.seekg(static_cast<std::streamoff>(offset), std::ios::beg);
    this->In.read(static_cast<char*>(dst), static_cast<std::streamsize>(n));
    this->BytesRead += static_cast<std::uint64_t>(this->In.gcount());
    return static_cast<bool>(this->In);
  }
  std::uint64_t BytesRead = 0;

private:
  std::ifstream In;
};

// The kind of an MRtrix k-tuple: 0 numbers, 1 all NaN, 2 all infinite, 3 mixed.
int TupleKind(const char* p, int valueSize, bool swap, int tupleSize)
{
  int nan = 0, inf = 0;
  for (int k = 0; k < tupleSize; ++k)
  {
    const double v = Value(p + k * valueSize, valueSize, swap);
    nan += std::isnan(v) ? 1 : 0;
    inf += std::isinf(v) ? 1 : 0;
  }
  return nan == tupleSize ? 1 : inf == tupleSize ? 2 : (nan + inf == 0 ? 0 : 3);
}

// The subset's random choice: a uniform number in [0, 1) from the seed and a key (splitmix64).
double SubsetHash(std::uint64_t key, int seed)
{
  std::uint64_t z = key + 0x9e3779b97f4a7c15ull * (static_cast<std::uint64_t>(seed) + 1);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  z ^= z >> 31;
  return static_cast<double>(z >> 11) * (1.0 / 9007199254740992.0);
}

std::string BaseName(const std::string& path)
{
  const auto slash = path.find_last_of("/\\");
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

std::string StripExtension(const std::string& name, const char* ext)
{
  const std::size_t n = std::strlen(ext);
  if (name.size() > n)
  {
    std::string tail = name.substr(name.size() - n);
    std::transform(tail.begin(), tail.end(), tail.begin(),
      [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (tail == ext)
    {
      return name.substr(0, name.size() - n);
    }
  }
  return name;
}
}

//------------------------------------------------------------------------------
// The bytes of a data section (not zero-initialized: they are read over).
struct vtkTractogramReader::DataBuffer
{
  std::unique_ptr<char[]> Bytes;
  std::size_t Size = 0;
  const char* data() const { return this->Bytes.get(); }
  char* data() { return this->Bytes.get(); }
  std::size_t size() const { return this->Size; }
  void clear()
  {
    this->Bytes.reset();
    this->Size = 0;
  }
};

struct vtkTractogramReader::Internals
{
  vtkSplineVizNameList ScalarFileNames;
};

// What a parser found: the raw data and where each streamline is in it.
// A piece's streamlines are those of its data buffer it owns (all of the
// file's for one piece), in file order.
struct vtkTractogramReader::Streamlines
{
  int Format = TF::UNKNOWN;
  DataBuffer Data;
  std::vector<std::uint64_t> Start; // .tck: first triplet; .trk: byte offset of the count
  std::vector<vtkIdType> Count;     // points
  long long FirstIndex = 0;         // index in the file of the first streamline; -1: unknown
  int ValueSize = 4;
  bool Swap = false;
  // .tck
  std::uint64_t FirstTuple = 0;          // the file's triplet at the start of Data
  std::uint64_t End = 0;                 // the triplets before the end marker
  std::vector<std::uint64_t> Separators; // of Data, for the .tsf check of a piece
  // .trk
  int ScalarsPerPoint = 0;
  int PropertiesPerLine = 0;
  double ToRAS[4][4];
  TF::TrkHeader Trk;
  // .tsf companions (.tck)
  struct Scalars
  {
    std::string Name;
    DataBuffer Data; // the values of the tractogram's triplets in Data
    int ValueSize = 4;
    bool Swap = false;
  };
  std::vector<Scalars> PointScalars;
  vtkNew<vtkFieldData> Field;
};

//------------------------------------------------------------------------------
vtkTractogramReader::vtkTractogramReader()
  : Internal(new Internals)
{
  this->SetNumberOfInputPorts(0);
}

vtkTractogramReader::~vtkTractogramReader()
{
  this->SetFileName(nullptr);
}

void vtkTractogramReader::AddScalarFileName(const char* fileName)
{
  if (this->Internal->ScalarFileNames.Add(fileName))
  {
    this->Modified();
  }
}

void vtkTractogramReader::RemoveAllScalarFileNames()
{
  if (this->Internal->ScalarFileNames.Clear())
  {
    this->Modified();
  }
}

int vtkTractogramReader::GetNumberOfScalarFileNames() const
{
  return this->Internal->ScalarFileNames.Size();
}

const char* vtkTractogramReader::GetScalarFileName(int i) const
{
  return this->Internal->ScalarFileNames.Get(i);
}

std::string vtkTractogramReader::ScalarArrayName(
  const std::string& tsfFileName, const std::string& tckFileName)
{
  std::string name = StripExtension(BaseName(tsfFileName), ".tsf");
  const std::string stem = StripExtension(BaseName(tckFileName), ".tck");
  if (!stem.empty() && name.size() > stem.size() + 1 && name.compare(0, stem.size(), stem) == 0 &&
    (name[stem.size()] == '.' || name[stem.size()] == '_'))
  {
    name = name.substr(stem.size() + 1);
  }
  return name.empty() ? std::string("Scalars") : name;
}

//------------------------------------------------------------------------------
int vtkTractogramReader::CanReadFile(const char* fileName)
{
  if (!fileName)
  {
    return 0;
  }
  std::ifstream in(fileName, std::ios::in | std::ios::binary);
  char head[16] = {};
  in.read(head, sizeof(head));
  const std::string s(head, static_cast<std::size_t>(in.gcount()));
  if (s.compare(0, 13, "mrtrix tracks") == 0)
  {
    return 1;
  }
  return (s.size() >= 6 && s.compare(0, 5, "TRACK") == 0 && s[5] == '\0') ? 1 : 0;
}

//------------------------------------------------------------------------------
int vtkTractogramReader::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  outputVector->GetInformationObject(0)->Set(CAN_HANDLE_PIECE_REQUEST(), 1);
  return 1;
}

//------------------------------------------------------------------------------
bool vtkTractogramReader::ReadChunked(const std::string& fileName, unsigned long long offset,
  unsigned long long size, DataBuffer& buffer, double progressBegin, double progressEnd,
  std::string& error)
{
  buffer.clear();
  // The data and the polylines made from them (about 1.4 times the data:
  // float32 points, 32-bit connectivity) must fit in this machine's memory.
  if (!vtkSplineVizProgress::CheckOutputSize(
        static_cast<double>(size), 2.4, "the data and the polylines made from them", &error))
  {
    return false;
  }
  try
  {
    buffer.Bytes.reset(new char[std::max<unsigned long long>(size, 1)]);
    buffer.Size = static_cast<std::size_t>(size);
  }
  catch (const std::bad_alloc&)
  {
    error = "not enough memory for " + std::to_string(size) + " bytes of data";
    return false;
  }
  // Chunks of 16 MiB, read by all threads in batches (each thread with its
  // own stream), with a progress report after each batch.
  const unsigned long long chunks = (size + ReadChunkBytes - 1) / ReadChunkBytes;
  const unsigned long long batch =
    2 * static_cast<unsigned long long>(std::max(1, vtkSMPTools::GetEstimatedNumberOfThreads()));
  std::atomic<bool> failed(false);
  for (unsigned long long b0 = 0; b0 < chunks; b0 += batch)
  {
    const unsigned long long b1 = std::min(chunks, b0 + batch);
    vtkSMPTools::For(static_cast<vtkIdType>(b0), static_cast<vtkIdType>(b1), 1,
      [&](vtkIdType c0, vtkIdType c1)
      {
        std::ifstream in(fileName, std::ios::in | std::ios::binary);
        for (vtkIdType c = c0; c < c1 && in; ++c)
        {
          const unsigned long long at = static_cast<unsigned long long>(c) * ReadChunkBytes;
          const unsigned long long n = std::min(ReadChunkBytes, size - at);
          in.seekg(static_cast<std::streamoff>(offset + at), std::ios::beg);
          in.read(buffer.data() + at, static_cast<std::streamsize>(n));
        }
        if (!in)
        {
          failed = true;
        }
      });
    if (failed)
    {
      error = "cannot read the data of \"" + fileName + "\"";
      return false;
    }
    this->LastBytesRead += static_cast<vtkTypeInt64>(
      std::min(size, b1 * ReadChunkBytes) - std::min(size, b0 * ReadChunkBytes));
    this->UpdateProgress(progressBegin + (progressEnd - progressBegin) * b1 / double(chunks));
    if (this->GetAbortExecute())
    {
      error = "aborted";
      return false;
    }
  }
  return true;
}

namespace
{
unsigned long long FileSize(const std::string& name)
{
  std::ifstream in(name, std::ios::in | std::ios::binary | std::ios::ate);
  const std::streamoff s = in ? static_cast<std::streamoff>(in.tellg()) : std::streamoff(-1);
  return s < 0 ? 0ull : static_cast<unsigned long long>(s);
}

// Polylines over consecutive points (offsets: nLines + 1 values); 32-bit
// storage when it fits (half the memory).
vtkSmartPointer<vtkCellArray> MakePolylines(vtkIdTypeArray* offsets, vtkIdType nPoints)
{
  const vtkIdType nLines = offsets->GetNumberOfValues() - 1;
  const vtkIdType* off = offsets->GetPointer(0);
  vtkNew<vtkCellArray> cells;
  if (nPoints < std::numeric_limits<std::int32_t>::max())
  {
    vtkNew<vtkTypeInt32Array> offsets32, connectivity;
    offsets32->SetNumberOfValues(nLines + 1);
    connectivity->SetNumberOfValues(nPoints);
    std::int32_t* o32 = offsets32->GetPointer(0);
    std::int32_t* conn = connectivity->GetPointer(0);
    vtkSMPTools::For(0, nLines + 1,
      [o32, off](vtkIdType b, vtkIdType e)
      {
        for (vtkIdType k = b; k < e; ++k)
        {
          o32[k] = static_cast<std::int32_t>(off[k]);
        }
      });
    vtkSMPTools::For(0, nPoints,
      [conn](vtkIdType b, vtkIdType e)
      {
        for (vtkIdType k = b; k < e; ++k)
        {
          conn[k] = static_cast<std::int32_t>(k);
        }
      });
    cells->SetData(offsets32, connectivity);
  }
  else
  {
    vtkNew<vtkIdTypeArray> connectivity;
    connectivity->SetNumberOfValues(nPoints);
    vtkIdType* conn = connectivity->GetPointer(0);
    vtkSMPTools::For(0, nPoints,
      [conn](vtkIdType b, vtkIdType e)
      {
        for (vtkIdType k = b; k < e; ++k)
        {
          conn[k] = k;
        }
      });
    cells->SetData(offsets, connectivity);
  }
  return cells;
}

// The sizes of a .trk record's parts.
struct TrkLayout
{
  bool Swap;
  std::uint64_t PointBytes;
  std::uint64_t PropertyBytes;
};

// The point count and size of the .trk record that starts with the (file-order) count `bytes`,
// checked against the `remaining` bytes of the data.
bool TrkRecord(const TrkLayout& layout, const char* bytes, std::uint64_t index,
  std::uint64_t remaining, vtkIdType& points, std::uint64_t& record, std::string& error)
{
  if (remaining < 4)
  {
    error = "the file ends inside the point count of streamline " + std::to_string(index) +
      " (a truncated file)";
    return false;
  }
  std::int32_t m;
  std::memcpy(&m, bytes, 4);
  if (layout.Swap)
  {
    TF::SwapBytes(&m, 4, 1);
  }
  if (m < 0)
  {
    error = "streamline " + std::to_string(index) + " has a negative point count (" +
      std::to_string(m) + ")";
    return false;
  }
  record = 4 + static_cast<std::uint64_t>(m) * layout.PointBytes + layout.PropertyBytes;
  if (record > remaining)
  {
    error = "streamline " + std::to_string(index) + " (" + std::to_string(m) +
      " points) runs past the end of the file (a truncated file, or wrong counts)";
    return false;
  }
  points = m;
  return true;
}
}

//------------------------------------------------------------------------------
// The number of tuples before the end marker when the file ends with its end
// marker right after a separator (or holds no streamline), as MRtrix writes
// it; such a file can be split into byte ranges. False (`end` unchanged)
// otherwise: the file is then read whole (to find its end marker or report
// its damage exactly as a whole read would).
bool vtkTractogramReader::ProbeMRtrixEnd(const std::string& fileName, std::uint64_t offset,
  std::uint64_t dataBytes, int valueSize, bool swap, int tupleSize, std::uint64_t& end)
{
  const std::uint64_t tupleBytes = static_cast<std::uint64_t>(valueSize) * tupleSize;
  const std::uint64_t tuples = dataBytes / tupleBytes;
  if (tuples == 0)
  {
    return false;
  }
  FileCursor cursor(fileName);
  char tail[2 * 3 * 8];
  const std::uint64_t probe = std::min<std::uint64_t>(2, tuples);
  const bool ok = cursor.Read(offset + (tuples - probe) * tupleBytes, probe * tupleBytes, tail);
  this->LastBytesRead += static_cast<vtkTypeInt64>(cursor.BytesRead);
  if (!ok || TupleKind(tail + (probe - 1) * tupleBytes, valueSize, swap, tupleSize) != 2 ||
    (probe == 2 && TupleKind(tail, valueSize, swap, tupleSize) != 1))
  {
    return false;
  }
  end = tuples - 1;
  return true;
}

//------------------------------------------------------------------------------
// Streams tuples [from, to) of an MRtrix file in blocks (nothing kept) and
// finds its special tuples: the number of separators, or (stopAtFirst) the
// first separator's index in `found`. An end marker or a damaged tuple in the
// range is an error.
bool vtkTractogramReader::ScanMRtrixRange(const std::string& fileName, std::uint64_t offset,
  int valueSize, bool swap, int tupleSize, std::uint64_t from, std::uint64_t to, bool stopAtFirst,
  std::uint64_t& found, double progressBegin, double progressEnd, std::string& error)
{
  const std::uint64_t tupleBytes = static_cast<std::uint64_t>(valueSize) * tupleSize;
  FileCursor cursor(fileName);
  std::vector<char> block;
  std::uint64_t blockTuples = stopAtFirst ? 64 : ReadChunkBytes / tupleBytes;
  found = stopAtFirst ? MRtrixSpecials::None : 0;
  bool ok = true;
  for (std::uint64_t t = from; t < to && ok;)
  {
    const std::uint64_t n = std::min(blockTuples, to - t);
    block.resize(static_cast<std::size_t>(n * tupleBytes));
    if (!cursor.Read(offset + t * tupleBytes, block.size(), block.data()))
    {
      error = "cannot read the data of \"" + fileName + "\"";
      ok = false;
      break;
    }
    MRtrixSpecials specials;
    FindSpecials(block.data(), n, valueSize, swap, tupleSize, specials);
    // (separators are found only before damage: what lies after the first belongs to others)
    if (stopAtFirst && !specials.Separators.empty())
    {
      found = t + specials.Separators.front();
      break;
    }
    else if (specials.Invalid != MRtrixSpecials::None)
    {
      error = InvalidTupleError(t + specials.Invalid);
      ok = false;
    }
    else if (specials.Terminator != MRtrixSpecials::None)
    {
      error = "an end marker (inf inf inf) at value tuple " +
        std::to_string(t + specials.Terminator) + ", before the end of the data (a damaged file)";
      ok = false;
    }
    found += stopAtFirst ? 0 : specials.Separators.size();
    t += n;
    blockTuples = std::min<std::uint64_t>(2 * blockTuples, ReadChunkBytes / tupleBytes);
    this->UpdateProgress(progressBegin + (progressEnd - progressBegin) * (t - from) / (to - from));
    if (ok && this->GetAbortExecute())
    {
      error = "aborted";
      ok = false;
    }
  }
  this->LastBytesRead += static_cast<vtkTypeInt64>(cursor.BytesRead);
  if (ok && stopAtFirst && found == MRtrixSpecials::None)
  {
    error = "no streamline end (NaN triplet) after value tuple " + std::to_string(from);
    ok = false;
  }
  return ok;
}

//------------------------------------------------------------------------------
// A piece of a .tck file that ends with its end marker after `end` tuples:
// the piece owns the streamlines whose first point lies in its share of the
// tuples, [end p / n, end (p + 1) / n); it reads from the tuple before its
// share (to know whether a streamline starts at its first tuple) to the end
// of its last streamline, which may run past its share.
bool vtkTractogramReader::ReadTCKPiece(const std::string& fileName, std::uint64_t offset,
  std::uint64_t end, Streamlines& lines, std::string& error)
{
  const int vs = lines.ValueSize;
  const std::uint64_t tupleBytes = 3ull * vs;
  const std::uint64_t a = Share(end, this->Piece, this->NumberOfPieces);
  const std::uint64_t b = Share(end, this->Piece + 1, this->NumberOfPieces);
  lines.FirstIndex = a == 0 ? 0 : -1;
  lines.FirstTuple = a;
  if (a == b)
  {
    return true;
  }
  std::uint64_t before = 0;
  if (a > 0 && this->SubsetMode == SUBSET_STRIDE)
  {
    // every k-th needs the streamline's index in the file: count the separators before the share
    if (!this->ScanMRtrixRange(
          fileName, offset, vs, lines.Swap, 3, 0, a - 1, false, before, 0.0, 0.1, error))
    {
      return false;
    }
    lines.FirstIndex = static_cast<long long>(before) + 1;
  }
  std::uint64_t last = 0; // the separator that ends the streamline holding tuple b - 1
  if (!this->ScanMRtrixRange(
        fileName, offset, vs, lines.Swap, 3, b - 1, end, true, last, 0.1, 0.1, error))
  {
    return false;
  }
  const std::uint64_t r0 = a > 0 ? a - 1 : 0;
  const std::uint64_t tuples = last - r0 + 1;
  if (!this->ReadChunked(
        fileName, offset + r0 * tupleBytes, tuples * tupleBytes, lines.Data, 0.1, 0.3, error))
  {
    return false;
  }
  MRtrixSpecials specials;
  FindSpecials(lines.Data.data(), tuples, vs, lines.Swap, 3, specials);
  if (specials.Invalid != MRtrixSpecials::None)
  {
    error = InvalidTupleError(r0 + specials.Invalid);
    return false;
  }
  if (specials.Terminator != MRtrixSpecials::None)
  {
    error = "an end marker (inf inf inf) at value tuple " +
      std::to_string(r0 + specials.Terminator) + ", before the end of the data (a damaged file)";
    return false;
  }
  lines.FirstTuple = r0;
  // Streamlines start at tuple 0 and after each separator; each ends at the next separator.
  std::vector<std::uint64_t>& separators = lines.Separators;
  separators.swap(specials.Separators);
  if (a == 0)
  {
    lines.Start.push_back(0);
    lines.Count.push_back(static_cast<vtkIdType>(separators.front()));
  }
  for (std::size_t k = 0; k + 1 < separators.size(); ++k)
  {
    const std::uint64_t start = separators[k] + 1;
    if (r0 + start >= a && r0 + start < b)
    {
      lines.Start.push_back(start);
      lines.Count.push_back(static_cast<vtkIdType>(separators[k + 1] - start));
    }
  }
  return true;
}

//------------------------------------------------------------------------------
// A .tck file read whole (its end marker not at its end: data after it, or no
// end marker, which is an error); the piece's streamlines are then chosen by
// the same rule as ReadTCKPiece's.
bool vtkTractogramReader::ReadTCKWhole(const std::string& fileName, std::uint64_t offset,
  std::uint64_t dataBytes, Streamlines& lines, std::string& error)
{
  if (!this->ReadChunked(fileName, offset, dataBytes, lines.Data, 0.0, 0.3, error))
  {
    return false;
  }
  MRtrixStructure structure;
  bool trailing = false;
  if (!ScanMRtrix(lines.Data, lines.ValueSize, lines.Swap, 3, structure, error, trailing))
  {
    return false;
  }
  if (trailing)
  {
    vtkWarningMacro(<< fileName << ": data after the end marker ignored");
  }
  lines.Start.swap(structure.Start);
  lines.Count.swap(structure.Count);
  lines.FirstTuple = 0;
  lines.FirstIndex = 0;
  lines.End = structure.Terminator;
  return true;
}

//------------------------------------------------------------------------------
// Keeps the streamlines of a whole read whose first tuple lies in the piece's share.
void vtkTractogramReader::KeepPieceOfWhole(Streamlines& lines)
{
  const std::uint64_t a = Share(lines.End, this->Piece, this->NumberOfPieces);
  const std::uint64_t b = Share(lines.End, this->Piece + 1, this->NumberOfPieces);
  const auto first = std::lower_bound(lines.Start.begin(), lines.Start.end(), a);
  const auto last = std::lower_bound(lines.Start.begin(), lines.Start.end(), b);
  const std::size_t i0 = static_cast<std::size_t>(first - lines.Start.begin());
  const std::size_t i1 = static_cast<std::size_t>(last - lines.Start.begin());
  lines.Start = std::vector<std::uint64_t>(lines.Start.begin() + i0, lines.Start.begin() + i1);
  lines.Count = std::vector<vtkIdType>(lines.Count.begin() + i0, lines.Count.begin() + i1);
  lines.FirstIndex = static_cast<long long>(i0);
}

//------------------------------------------------------------------------------
// A companion .tsf: value i belongs to the tractogram's tuple i (both have one
// entry per point and one separator per streamline). A piece reads the values
// of its tuples and checks that its separators are the tractogram's and that
// the end marker is where the tractogram's is; a whole read compares all.
bool vtkTractogramReader::ReadTSF(const std::string& name, const std::string& tckHeaderTimestamp,
  bool piece, Streamlines& lines, double progressBegin, double progressEnd, std::string& error)
{
  TF::MRtrixHeader th;
  if (!TF::ReadMRtrixHeader(name, "mrtrix track scalars", th, error))
  {
    return false;
  }
  Streamlines::Scalars s;
  s.Name = ScalarArrayName(name, this->FileName);
  s.ValueSize = th.ValueSize;
  s.Swap = th.BigEndian == TF::HostIsLittleEndian();
  const std::uint64_t dataBytes = FileSize(name) - th.DataOffset;
  const std::string mismatch = "it does not match the tractogram (other numbers of streamlines "
                               "or points)";
  if (piece)
  {
    char marker[8];
    FileCursor cursor(name);
    const std::uint64_t values = dataBytes / s.ValueSize;
    const bool ok = lines.End < values &&
      cursor.Read(th.DataOffset + lines.End * s.ValueSize, s.ValueSize, marker);
    this->LastBytesRead += static_cast<vtkTypeInt64>(cursor.BytesRead);
    if (!ok || TupleKind(marker, s.ValueSize, s.Swap, 1) != 2)
    {
      error = mismatch + ": its end marker is not at value " + std::to_string(lines.End);
      return false;
    }
    const std::uint64_t tuples = lines.Data.size() / (3ull * lines.ValueSize);
    if (tuples > 0)
    {
      if (!this->ReadChunked(name, th.DataOffset + lines.FirstTuple * s.ValueSize,
            tuples * s.ValueSize, s.Data, progressBegin, progressEnd, error))
      {
        return false;
      }
      MRtrixSpecials specials;
      FindSpecials(s.Data.data(), tuples, s.ValueSize, s.Swap, 1, specials);
      if (specials.Invalid != MRtrixSpecials::None || specials.Terminator != MRtrixSpecials::None ||
        specials.Separators != lines.Separators)
      {
        error = mismatch + " between values " + std::to_string(lines.FirstTuple) + " and " +
          std::to_string(lines.FirstTuple + tuples);
        return false;
      }
    }
  }
  else
  {
    if (!this->ReadChunked(
          name, th.DataOffset, dataBytes, s.Data, progressBegin, progressEnd, error))
    {
      return false;
    }
    MRtrixStructure ts;
    bool tsTrailing = false;
    if (!ScanMRtrix(s.Data, s.ValueSize, s.Swap, 1, ts, error, tsTrailing))
    {
      return false;
    }
    if (ts.Count != lines.Count)
    {
      error = mismatch + ": " + std::to_string(ts.Count.size()) + " streamlines instead of " +
        std::to_string(lines.Count.size()) + ", or other numbers of points";
      return false;
    }
  }
  if (!th.Timestamp.empty() && !tckHeaderTimestamp.empty() && th.Timestamp != tckHeaderTimestamp)
  {
    vtkWarningMacro(<< "track scalar file \"" << name
                    << "\" has another timestamp than the tractogram");
  }
  lines.PointScalars.push_back(std::move(s));
  return true;
}

//------------------------------------------------------------------------------
bool vtkTractogramReader::ReadTCK(Streamlines& lines, std::string& error)
{
  TF::MRtrixHeader header;
  if (!TF::ReadMRtrixHeader(this->FileName, "mrtrix tracks", header, error))
  {
    return false;
  }
  lines.Format = TF::TCK;
  lines.ValueSize = header.ValueSize;
  lines.Swap = header.BigEndian == TF::HostIsLittleEndian();
  const std::uint64_t dataBytes = FileSize(this->FileName) - header.DataOffset;
  const bool piece = this->ProbeMRtrixEnd(
    this->FileName, header.DataOffset, dataBytes, lines.ValueSize, lines.Swap, 3, lines.End);
  if (piece ? !this->ReadTCKPiece(this->FileName, header.DataOffset, lines.End, lines, error)
            : !this->ReadTCKWhole(this->FileName, header.DataOffset, dataBytes, lines, error))
  {
    return false;
  }
  // the number of streamlines in the file: known when everything was read
  const bool all = !piece || this->NumberOfPieces == 1;
  this->NumberOfStreamlinesInFile =
    all ? static_cast<vtkIdType>(lines.Count.size()) : static_cast<vtkIdType>(header.Count);
  if (all && header.Count >= 0 && header.Count != static_cast<long long>(lines.Count.size()))
  {
    vtkWarningMacro(<< this->FileName << ": the header's count says " << header.Count
                    << " streamlines, the file holds " << lines.Count.size());
  }
  vtkNew<vtkStringArray> fields;
  fields->SetName("MRtrixHeader");
  for (const auto& kv : header.Fields)
  {
    fields->InsertNextValue(kv.first + ": " + kv.second);
  }
  lines.Field->AddArray(fields);

  const std::size_t nScalarFiles = this->Internal->ScalarFileNames.Names.size();
  for (std::size_t f = 0; f < nScalarFiles; ++f)
  {
    const std::string& name = this->Internal->ScalarFileNames.Names[f];
    const double p0 = 0.3 + 0.1 * f / nScalarFiles;
    if (!this->ReadTSF(name, header.Timestamp, piece, lines, p0, p0 + 0.1 / nScalarFiles, error))
    {
      error = "track scalar file \"" + name + "\": " + error;
      return false;
    }
  }
  if (!piece)
  {
    this->KeepPieceOfWhole(lines);
  }
  return true;
}

//------------------------------------------------------------------------------
// A .trk piece: the streamlines [N p / n, (p + 1) N / n) of the N in the file
// (n_count; counted first when the header does not record it). The records
// before the piece are skipped by their counts (4 bytes read per record); the
// piece's records are read in one go (the last piece reads to the end of the
// data and parses the counts in memory, as a whole read does).
bool vtkTractogramReader::ReadTRK(Streamlines& lines, std::string& error)
{
  const unsigned long long size = FileSize(this->FileName);
  {
    std::ifstream in(this->FileName, std::ios::in | std::ios::binary);
    if (!in)
    {
      error = "cannot open the file (it does not exist or is not readable)";
      return false;
    }
    unsigned char bytes[TF::TRK_HEADER_SIZE];
    if (size < TF::TRK_HEADER_SIZE || !in.read(reinterpret_cast<char*>(bytes), sizeof(bytes)))
    {
      error = "the file is shorter than a TrackVis header (1000 bytes)";
      return false;
    }
    if (!TF::ParseTrkHeader(bytes, lines.Trk, error))
    {
      return false;
    }
  }
  const TF::TrkHeader& h = lines.Trk;
  if (h.Version == 3)
  {
    vtkWarningMacro(<< this->FileName << ": a TrackVis version 3 file, read as version 2");
  }
  if (!TF::TrkVoxmmToRAS(h, lines.ToRAS, error))
  {
    return false;
  }
  lines.Format = TF::TRK;
  lines.Swap = h.Swapped;
  lines.ScalarsPerPoint = h.NumberOfScalars;
  lines.PropertiesPerLine = h.NumberOfProperties;
  const TrkLayout layout{ lines.Swap, 4ull * (3 + lines.ScalarsPerPoint),
    4ull * lines.PropertiesPerLine };
  const std::uint64_t dataSize = size - TF::TRK_HEADER_SIZE;
  std::uint64_t total =
    h.NumberOfStreamlines > 0 ? static_cast<std::uint64_t>(h.NumberOfStreamlines) : 0;
  if (total > 0 && total * (4 + layout.PropertyBytes) > dataSize)
  {
    error = "the header's n_count (" + std::to_string(total) + " streamlines) exceeds what the " +
      std::to_string(dataSize) + " bytes of data can hold";
    return false;
  }
  const bool recorded = total > 0;

  // Skips records [from, to) (or up to the end of the data) from byte `pos` by their counts.
  FileCursor cursor(this->FileName);
  auto skip = [&](std::uint64_t from, std::uint64_t to, std::uint64_t& pos, std::uint64_t& index,
                bool keep, double p0, double p1)
  {
    for (index = from; index < to && pos < dataSize; ++index)
    {
      char count[4] = { 0, 0, 0, 0 };
      if (dataSize - pos >= 4 && !cursor.Read(TF::TRK_HEADER_SIZE + pos, 4, count))
      {
        error = "cannot read the data";
        return false;
      }
      vtkIdType m = 0;
      std::uint64_t record = 0;
      if (!TrkRecord(layout, count, index, dataSize - pos, m, record, error))
      {
        return false;
      }
      if (keep)
      {
        lines.Start.push_back(pos);
        lines.Count.push_back(m);
      }
      pos += record;
      if ((index & 0xffff) == 0xffff)
      {
        this->UpdateProgress(p0 + (p1 - p0) * (index - from) / double(to - from));
        if (this->GetAbortExecute())
        {
          error = "aborted";
          return false;
        }
      }
    }
    return true;
  };
  const std::uint64_t unlimited = std::numeric_limits<std::uint64_t>::max();
  std::uint64_t pos = 0, index = 0;
  if (!recorded && this->NumberOfPieces > 1)
  {
    // no n_count: count the records first (every piece must agree on the split)
    bool ok = skip(0, unlimited, pos, total, false, 0.0, 0.05);
    this->LastBytesRead += static_cast<vtkTypeInt64>(cursor.BytesRead);
    cursor.BytesRead = 0;
    if (!ok)
    {
      return false;
    }
    pos = 0;
  }
  const bool toEnd = !recorded && this->NumberOfPieces == 1;
  const std::uint64_t b = toEnd ? 0 : Share(total, this->Piece, this->NumberOfPieces);
  const std::uint64_t e = toEnd ? unlimited : Share(total, this->Piece + 1, this->NumberOfPieces);
  const bool last = toEnd || e == total;
  bool ok = skip(0, b, pos, index, false, 0.0, 0.1);
  if (ok && index < b)
  {
    error = "the header's n_count says " + std::to_string(total) + " streamlines, the file holds " +
      std::to_string(index) + " (a truncated file)";
    ok = false;
  }
  const std::uint64_t base = pos;
  lines.FirstIndex = static_cast<long long>(b);
  if (ok && !last)
  {
    ok = skip(b, e, pos, index, true, 0.1, 0.15);
    for (std::uint64_t& start : lines.Start)
    {
      start -= base;
    }
  }
  this->LastBytesRead += static_cast<vtkTypeInt64>(cursor.BytesRead);
  if (!ok)
  {
    return false;
  }
  if (!last && index < e)
  {
    error = "the header's n_count says " + std::to_string(total) + " streamlines, the file holds " +
      std::to_string(index) + " (a truncated file)";
    return false;
  }
  const std::uint64_t readEnd = last ? dataSize : pos;
  if (!this->ReadChunked(
        this->FileName, TF::TRK_HEADER_SIZE + base, readEnd - base, lines.Data, 0.15, 0.4, error))
  {
    return false;
  }
  if (last)
  {
    // the last piece: its records from the data in memory, up to the count or the end of the data
    const std::uint64_t n = readEnd - base;
    std::uint64_t at = 0;
    std::uint64_t i = b;
    for (; at < n && i < e; ++i)
    {
      vtkIdType m = 0;
      std::uint64_t record = 0;
      if (!TrkRecord(layout, lines.Data.data() + at, i, n - at, m, record, error))
      {
        return false;
      }
      lines.Start.push_back(at);
      lines.Count.push_back(m);
      at += record;
    }
    if (recorded && i < total)
    {
      error = "the header's n_count says " + std::to_string(total) +
        " streamlines, the file holds " + std::to_string(i) + " (a truncated file)";
      return false;
    }
    if (at < n)
    {
      vtkWarningMacro(<< this->FileName << ": " << (n - at)
                      << " bytes after the last of the header's " << total
                      << " streamlines ignored");
    }
    total = toEnd ? i : total;
  }
  this->NumberOfStreamlinesInFile = static_cast<vtkIdType>(total);
  this->AddTrkFieldData(lines);
  return true;
}

//------------------------------------------------------------------------------
// The TrackVis geometry as field data, for vtkTractogramWriter.
void vtkTractogramReader::AddTrkFieldData(Streamlines& lines)
{
  const TF::TrkHeader& h = lines.Trk;
  auto add = [&lines](const char* name, std::initializer_list<double> values)
  {
    vtkNew<vtkDoubleArray> a;
    a->SetName(name);
    a->SetNumberOfComponents(static_cast<int>(values.size()));
    a->SetNumberOfTuples(1);
    int c = 0;
    for (double v : values)
    {
      a->SetComponent(0, c++, v);
    }
    lines.Field->AddArray(a);
  };
  const auto& v = h.VoxelToRAS;
  add("TrackVisVoxelToRAS",
    { v[0][0], v[0][1], v[0][2], v[0][3], v[1][0], v[1][1], v[1][2], v[1][3], v[2][0], v[2][1],
      v[2][2], v[2][3], v[3][0], v[3][1], v[3][2], v[3][3] });
  add("TrackVisVoxelSize", { h.VoxelSize[0], h.VoxelSize[1], h.VoxelSize[2] });
  add("TrackVisDimensions",
    { double(h.Dimensions[0]), double(h.Dimensions[1]), double(h.Dimensions[2]) });
  vtkNew<vtkStringArray> order;
  order->SetName("TrackVisVoxelOrder");
  order->InsertNextValue(h.VoxelOrder);
  lines.Field->AddArray(order);
}

//------------------------------------------------------------------------------
// The streamlines of the piece to output: those of the subset, non-empty ones
// unless empty ones are kept.
std::vector<vtkIdType> vtkTractogramReader::SelectStreamlines(const Streamlines& lines) const
{
  std::vector<vtkIdType> selected;
  selected.reserve(lines.Count.size());
  for (std::size_t s = 0; s < lines.Count.size(); ++s)
  {
    if (lines.Count[s] == 0 && !this->KeepEmptyStreamlines)
    {
      continue;
    }
    const std::uint64_t index = static_cast<std::uint64_t>(lines.FirstIndex) + s;
    if (this->SubsetMode == SUBSET_STRIDE && index % std::max(1, this->SubsetStride) != 0)
    {
      continue;
    }
    if (this->SubsetMode == SUBSET_RANDOM_FRACTION)
    {
      // .tck pieces do not know the streamlines' indices in the file: their first triplet's
      const std::uint64_t key = lines.Format == TF::TCK ? lines.FirstTuple + lines.Start[s] : index;
      if (SubsetHash(key, this->SubsetSeed) >= this->SubsetFraction)
      {
        continue;
      }
    }
    selected.push_back(static_cast<vtkIdType>(s));
  }
  return selected;
}

//------------------------------------------------------------------------------
struct vtkTractogramReader::ValueArrays
{
  std::vector<vtkSmartPointer<vtkFloatArray>> Arrays;
  std::vector<float*> Targets;
  std::vector<int> Components;
  std::vector<int> Firsts; // the first value of each array in a .trk record

  // One array per (name, components), `tuples` tuples each.
  void Make(const std::vector<std::pair<std::string, int>>& names, vtkIdType tuples)
  {
    int first = 0;
    for (const auto& n : names)
    {
      auto a = vtkSmartPointer<vtkFloatArray>::New();
      a->SetName(n.first.c_str());
      a->SetNumberOfComponents(n.second);
      a->SetNumberOfTuples(tuples);
      this->Arrays.push_back(a);
      this->Targets.push_back(a->GetPointer(0));
      this->Components.push_back(n.second);
      this->Firsts.push_back(first);
      first += n.second;
    }
  }
};

//------------------------------------------------------------------------------
void vtkTractogramReader::ConvertTCK(const Streamlines& lines, std::size_t s, vtkIdType o,
  float* pf, double* pd, const ValueArrays& point)
{
  const vtkIdType m = lines.Count[s];
  const int vs = lines.ValueSize;
  const char* p = lines.Data.data() + lines.Start[s] * 3 * vs;
  if (!lines.Swap && !pd && vs == 4)
  {
    if (m > 0) // an empty streamline (kept) may leave the points array empty (null)
    {
      std::memcpy(pf + 3 * o, p, static_cast<std::size_t>(12 * m));
    }
  }
  else
  {
    for (vtkIdType j = 0; j < 3 * m; ++j)
    {
      const double v = Value(p + j * vs, vs, lines.Swap);
      if (pd)
      {
        pd[3 * o + j] = v;
      }
      else
      {
        pf[3 * o + j] = static_cast<float>(v);
      }
    }
  }
  for (std::size_t k = 0; k < lines.PointScalars.size(); ++k)
  {
    const auto& sc = lines.PointScalars[k];
    const char* q = sc.Data.data() + lines.Start[s] * sc.ValueSize;
    float* dst = point.Targets[k] + o;
    for (vtkIdType j = 0; j < m; ++j)
    {
      dst[j] = static_cast<float>(Value(q + j * sc.ValueSize, sc.ValueSize, sc.Swap));
    }
  }
}

//------------------------------------------------------------------------------
bool vtkTractogramReader::ConvertTRK(const Streamlines& lines, std::size_t s, vtkIdType o,
  vtkIdType i, float* pf, const ValueArrays& point, const ValueArrays& cell)
{
  const vtkIdType m = lines.Count[s];
  const int perPoint = 3 + lines.ScalarsPerPoint;
  const char* p = lines.Data.data() + lines.Start[s] + 4;
  const double(*a)[4] = lines.ToRAS;
  float record[3 + 32767 + 32767];
  for (vtkIdType j = 0; j < m; ++j, p += 4 * perPoint)
  {
    std::memcpy(record, p, 4 * static_cast<std::size_t>(perPoint));
    if (lines.Swap)
    {
      TF::SwapBytes(record, 4, static_cast<std::size_t>(perPoint));
    }
    const double x[3] = { record[0], record[1], record[2] };
    if (!std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2]))
    {
      return false;
    }
    float* dst = pf + 3 * (o + j);
    for (int r = 0; r < 3; ++r)
    {
      const double y = a[r][0] * x[0] + a[r][1] * x[1] + a[r][2] * x[2] + a[r][3];
      if (!(std::abs(y) <= std::numeric_limits<float>::max()))
      {
        // beyond float32 after the voxel-mm to RAS+ map (a voxel size near 0,
        // a huge vox_to_ras): as unusable as a NaN
        return false;
      }
      dst[r] = static_cast<float>(y);
    }
    for (std::size_t k = 0; k < point.Targets.size(); ++k)
    {
      const int nc = point.Components[k];
      std::memcpy(point.Targets[k] + nc * (o + j), record + 3 + point.Firsts[k],
        4 * static_cast<std::size_t>(nc));
    }
  }
  if (!cell.Targets.empty())
  {
    std::memcpy(record, p, 4 * static_cast<std::size_t>(lines.PropertiesPerLine));
    if (lines.Swap)
    {
      TF::SwapBytes(record, 4, static_cast<std::size_t>(lines.PropertiesPerLine));
    }
    for (std::size_t k = 0; k < cell.Targets.size(); ++k)
    {
      const int nc = cell.Components[k];
      std::memcpy(
        cell.Targets[k] + nc * i, record + cell.Firsts[k], 4 * static_cast<std::size_t>(nc));
    }
  }
  return true;
}

//------------------------------------------------------------------------------
int vtkTractogramReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkPolyData* output = vtkPolyData::GetData(outInfo);
  output->Initialize();
  this->LastError.clear();
  this->NumberOfStreamlinesInFile = 0;
  auto fail = [this, output](const std::string& msg)
  {
    output->Initialize();
    this->LastError = msg;
    vtkErrorMacro(<< msg);
    return 0;
  };
  if (!this->FileName || !*this->FileName)
  {
    return fail("no file name was given");
  }
  std::string where = std::string("cannot read \"") + this->FileName + "\": ";
  int format = this->FileFormat;
  if (format == AUTOMATIC)
  {
    format = TF::DetectFormat(this->FileName);
    if (format == TF::UNKNOWN)
    {
      std::ifstream probe(this->FileName);
      return fail(where +
        (probe ? "neither an MRtrix .tck (\"mrtrix tracks\") nor a TrackVis .trk (\"TRACK\") file"
               : "the file does not exist or is not readable"));
    }
  }
  this->Piece = 0;
  this->NumberOfPieces = 1;
  this->LastBytesRead = 0;
  vtkSplineVizPieces::GetRequested(outInfo, this->Piece, this->NumberOfPieces);
  if (this->NumberOfPieces > 1)
  {
    where +=
      "piece " + std::to_string(this->Piece) + " of " + std::to_string(this->NumberOfPieces) + ": ";
  }

  Streamlines lines;
  std::string error;
  const bool ok = format == TF::TCK ? this->ReadTCK(lines, error) : this->ReadTRK(lines, error);
  if (!ok)
  {
    if (error == "aborted")
    {
      output->Initialize();
      return 1;
    }
    return fail(where + error);
  }
  const std::vector<vtkIdType> selected = this->SelectStreamlines(lines);
  const vtkIdType nLines = static_cast<vtkIdType>(selected.size());
  vtkNew<vtkIdTypeArray> offsets;
  offsets->SetNumberOfValues(nLines + 1);
  vtkIdType* off = offsets->GetPointer(0);
  off[0] = 0;
  for (vtkIdType i = 0; i < nLines; ++i)
  {
    off[i + 1] =
      off[i] + lines.Count[static_cast<std::size_t>(selected[static_cast<std::size_t>(i)])];
  }
  const vtkIdType nPoints = off[nLines];

  // Output arrays (filled below, attached only when everything succeeded).
  const bool doublePoints = lines.Format == TF::TCK && lines.ValueSize == 8;
  vtkNew<vtkPoints> points;
  points->SetDataType(doublePoints ? VTK_DOUBLE : VTK_FLOAT);
  points->SetNumberOfPoints(nPoints);
  ValueArrays pointValues, cellValues;
  if (lines.Format == TF::TRK)
  {
    pointValues.Make(lines.Trk.Scalars, nPoints);
    cellValues.Make(lines.Trk.Properties, nLines);
  }
  else
  {
    std::vector<std::pair<std::string, int>> names;
    for (const auto& scalars : lines.PointScalars)
    {
      names.emplace_back(scalars.Name, 1);
    }
    pointValues.Make(names, nPoints);
  }

  // Convert and copy, in parallel batches of about BatchPoints points.
  std::atomic<vtkIdType> badLine(-1);
  float* pf =
    doublePoints ? nullptr : static_cast<vtkFloatArray*>(points->GetData())->GetPointer(0);
  double* pd =
    doublePoints ? static_cast<vtkDoubleArray*>(points->GetData())->GetPointer(0) : nullptr;
  auto convert = [&](vtkIdType i0, vtkIdType i1)
  {
    for (vtkIdType i = i0; i < i1; ++i)
    {
      const std::size_t s = static_cast<std::size_t>(selected[static_cast<std::size_t>(i)]);
      if (lines.Format == TF::TCK)
      {
        ConvertTCK(lines, s, off[i], pf, pd, pointValues);
      }
      else if (!ConvertTRK(lines, s, off[i], i, pf, pointValues, cellValues))
      {
        vtkIdType expected = -1;
        badLine.compare_exchange_strong(expected, static_cast<vtkIdType>(s));
        return;
      }
    }
  };
  vtkIdType done = 0;
  while (done < nLines)
  {
    vtkIdType end = done + 1;
    while (end < nLines && off[end] - off[done] < BatchPoints)
    {
      ++end;
    }
    vtkSMPTools::For(done, end, 256, convert);
    done = end;
    this->UpdateProgress(0.4 + 0.6 * (nPoints > 0 ? double(off[done]) / nPoints : 1.0));
    if (badLine.load() >= 0)
    {
      break;
    }
    if (this->GetAbortExecute())
    {
      output->Initialize();
      return 1;
    }
  }
  if (badLine.load() >= 0)
  {
    // the streamline's index in the file, when the piece knows it; else in the piece
    badLine = badLine.load() + std::max(0LL, lines.FirstIndex);
    where += lines.FirstIndex < 0 ? "counting from the piece's first streamline, " : "";
    return fail(where + "streamline " + std::to_string(badLine.load()) +
      " has NaN or infinite coordinates, in the file or after the voxel-mm to RAS+ map (a damaged "
      "file or header)");
  }
  lines.Data.clear();

  vtkSmartPointer<vtkCellArray> cells = MakePolylines(offsets, nPoints);
  output->SetPoints(points);
  output->SetLines(cells);
  for (auto& a : pointValues.Arrays)
  {
    output->GetPointData()->AddArray(a);
  }
  if (pointValues.Arrays.size() == 1 && pointValues.Arrays[0]->GetNumberOfComponents() == 1)
  {
    output->GetPointData()->SetActiveScalars(pointValues.Arrays[0]->GetName());
  }
  for (auto& a : cellValues.Arrays)
  {
    output->GetCellData()->AddArray(a);
  }
  output->SetFieldData(lines.Field);
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkTractogramReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "FileFormat: " << this->FileFormat << "\n";
  os << indent << "KeepEmptyStreamlines: " << this->KeepEmptyStreamlines << "\n";
  os << indent << "ScalarFileNames:";
  this->Internal->ScalarFileNames.Print(os);
  os << indent << "SubsetMode: " << this->SubsetMode << "\n";
  os << indent << "SubsetStride: " << this->SubsetStride << "\n";
  os << indent << "SubsetFraction: " << this->SubsetFraction << "\n";
  os << indent << "SubsetSeed: " << this->SubsetSeed << "\n";
  os << indent << "NumberOfStreamlinesInFile: " << this->NumberOfStreamlinesInFile << "\n";
  os << indent << "LastBytesRead: " << this->LastBytesRead << "\n";
}
