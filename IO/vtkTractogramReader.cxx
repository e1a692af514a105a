#include "vtkTractogramReader.h"

#include "vtkSplineVizNameList.h"
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

// The streamline structure of an MRtrix stream of k-tuples (3 for .tck,
// 1 for .tsf): the tuples before the first all-infinite one, split at the
// all-NaN ones. Parallel over chunks of tuples.
struct MRtrixStructure
{
  std::vector<std::uint64_t> Start; // first tuple of each streamline
  std::vector<vtkIdType> Count;     // its number of tuples
};

template <typename Buffer>
bool ScanMRtrix(const Buffer& data, int valueSize, bool swap, int tupleSize, MRtrixStructure& out,
  std::string& error, bool& trailing)
{
  const std::size_t tupleBytes = static_cast<std::size_t>(valueSize) * tupleSize;
  const std::uint64_t tuples = data.size() / tupleBytes;
  const bool partialTail = data.size() % tupleBytes != 0;
  const std::uint64_t chunk = 1 << 20;
  const std::uint64_t chunks = (tuples + chunk - 1) / chunk;
  struct ChunkResult
  {
    std::vector<std::uint64_t> Separators;
    std::uint64_t Terminator = std::numeric_limits<std::uint64_t>::max();
    std::uint64_t Invalid = std::numeric_limits<std::uint64_t>::max();
  };
  std::vector<ChunkResult> results(static_cast<std::size_t>(chunks));
  vtkSMPTools::For(0, static_cast<vtkIdType>(chunks),
    [&](vtkIdType c0, vtkIdType c1)
    {
      for (vtkIdType c = c0; c < c1; ++c)
      {
        ChunkResult& r = results[static_cast<std::size_t>(c)];
        const std::uint64_t t0 = static_cast<std::uint64_t>(c) * chunk;
        const std::uint64_t t1 = std::min(tuples, t0 + chunk);
        for (std::uint64_t t = t0; t < t1; ++t)
        {
          const char* p = data.data() + t * tupleBytes;
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
  // The first end marker ends the data; an invalid tuple before it is an error.
  std::uint64_t terminator = std::numeric_limits<std::uint64_t>::max();
  std::uint64_t invalid = std::numeric_limits<std::uint64_t>::max();
  for (const ChunkResult& r : results)
  {
    invalid = std::min(invalid, r.Invalid);
    if (r.Terminator != std::numeric_limits<std::uint64_t>::max())
    {
      terminator = r.Terminator;
      break;
    }
  }
  if (invalid < terminator)
  {
    error = "value tuple " + std::to_string(invalid) +
      " mixes NaN or infinite values with numbers (a damaged file)";
    return false;
  }
  if (terminator == std::numeric_limits<std::uint64_t>::max())
  {
    error = partialTail
      ? "the file ends inside a value tuple and has no end marker (a truncated file)"
      : "the file has no end marker (inf inf inf): a truncated file";
    return false;
  }
  trailing = (terminator + 1) * tupleBytes < data.size();
  out.Start.clear();
  out.Count.clear();
  std::uint64_t begin = 0;
  for (const ChunkResult& r : results)
  {
    for (std::uint64_t s : r.Separators)
    {
      if (s > terminator)
      {
        break;
      }
      out.Start.push_back(begin);
      out.Count.push_back(static_cast<vtkIdType>(s - begin));
      begin = s + 1;
    }
    if (r.Terminator == terminator)
    {
      break;
    }
  }
  if (begin != terminator)
  {
    error = "the last streamline is not ended by NaNs before the end marker (a damaged file)";
    return false;
  }
  return true;
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
struct vtkTractogramReader::Streamlines
{
  int Format = TF::UNKNOWN;
  DataBuffer Data;
  std::vector<std::uint64_t> Start; // .tck: first triplet; .trk: byte offset of the count
  std::vector<vtkIdType> Count;     // points
  int ValueSize = 4;
  bool Swap = false;
  // .trk
  int ScalarsPerPoint = 0;
  int PropertiesPerLine = 0;
  double ToRAS[4][4];
  TF::TrkHeader Trk;
  // .tsf companions (.tck)
  struct Scalars
  {
    std::string Name;
    DataBuffer Data;
    std::vector<std::uint64_t> Start;
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
}

//------------------------------------------------------------------------------
bool vtkTractogramReader::ReadTCK(Streamlines& lines, std::string& error)
{
  TF::MRtrixHeader header;
  if (!TF::ReadMRtrixHeader(this->FileName, "mrtrix tracks", header, error))
  {
    return false;
  }
  const unsigned long long size = FileSize(this->FileName);
  const double readShare = this->Internal->ScalarFileNames.Size() == 0 ? 0.4 : 0.25;
  if (!this->ReadChunked(this->FileName, header.DataOffset, size - header.DataOffset, lines.Data,
        0.0, readShare, error))
  {
    return false;
  }
  lines.Format = TF::TCK;
  lines.ValueSize = header.ValueSize;
  lines.Swap = header.BigEndian == TF::HostIsLittleEndian();
  MRtrixStructure structure;
  bool trailing = false;
  if (!ScanMRtrix(lines.Data, lines.ValueSize, lines.Swap, 3, structure, error, trailing))
  {
    return false;
  }
  if (trailing)
  {
    vtkWarningMacro(<< this->FileName << ": data after the end marker ignored");
  }
  lines.Start.swap(structure.Start);
  lines.Count.swap(structure.Count);
  if (header.Count >= 0 && header.Count != static_cast<long long>(lines.Count.size()))
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

  // Companion .tsf files: the same streamline structure, one value per point.
  const std::size_t nScalarFiles = this->Internal->ScalarFileNames.Names.size();
  for (std::size_t f = 0; f < nScalarFiles; ++f)
  {
    const std::string& name = this->Internal->ScalarFileNames.Names[f];
    TF::MRtrixHeader th;
    std::string e;
    if (!TF::ReadMRtrixHeader(name, "mrtrix track scalars", th, e))
    {
      error = "track scalar file \"" + name + "\": " + e;
      return false;
    }
    Streamlines::Scalars s;
    s.Name = ScalarArrayName(name, this->FileName);
    s.ValueSize = th.ValueSize;
    s.Swap = th.BigEndian == TF::HostIsLittleEndian();
    const double p0 = readShare + 0.15 * f / nScalarFiles;
    if (!this->ReadChunked(name, th.DataOffset, FileSize(name) - th.DataOffset, s.Data, p0,
          p0 + 0.15 / nScalarFiles, e))
    {
      error = "track scalar file \"" + name + "\": " + e;
      return false;
    }
    MRtrixStructure ts;
    bool tsTrailing = false;
    if (!ScanMRtrix(s.Data, s.ValueSize, s.Swap, 1, ts, e, tsTrailing))
    {
      error = "track scalar file \"" + name + "\": " + e;
      return false;
    }
    if (ts.Count != lines.Count)
    {
      error = "track scalar file \"" + name +
        "\" does not match the tractogram: " + std::to_string(ts.Count.size()) +
        " streamlines instead of " + std::to_string(lines.Count.size()) +
        ", or other numbers of points";
      return false;
    }
    if (!th.Timestamp.empty() && !header.Timestamp.empty() && th.Timestamp != header.Timestamp)
    {
      vtkWarningMacro(<< "track scalar file \"" << name
                      << "\" has another timestamp than the tractogram");
    }
    s.Start.swap(ts.Start);
    lines.PointScalars.push_back(std::move(s));
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkTractogramReader::ReadTRK(Streamlines& lines, std::string& error)
{
  const unsigned long long size = FileSize(this->FileName);
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
  in.close();
  TF::TrkHeader& h = lines.Trk;
  if (!TF::ParseTrkHeader(bytes, h, error))
  {
    return false;
  }
  if (h.Version == 3)
  {
    vtkWarningMacro(<< this->FileName << ": a TrackVis version 3 file, read as version 2");
  }
  if (!TF::TrkVoxmmToRAS(h, lines.ToRAS, error))
  {
    return false;
  }
  if (!this->ReadChunked(this->FileName, TF::TRK_HEADER_SIZE, size - TF::TRK_HEADER_SIZE,
        lines.Data, 0.0, 0.4, error))
  {
    return false;
  }
  lines.Format = TF::TRK;
  lines.Swap = h.Swapped;
  lines.ScalarsPerPoint = h.NumberOfScalars;
  lines.PropertiesPerLine = h.NumberOfProperties;
  // The records are found one after the other (each starts with its count);
  // a record must fit in the file before it is accepted.
  const std::uint64_t pointBytes = 4ull * (3 + lines.ScalarsPerPoint);
  const std::uint64_t propertyBytes = 4ull * lines.PropertiesPerLine;
  const std::uint64_t dataSize = lines.Data.size();
  const std::uint64_t expected =
    h.NumberOfStreamlines > 0 ? static_cast<std::uint64_t>(h.NumberOfStreamlines) : 0;
  if (expected > 0 && expected * (4 + propertyBytes) > dataSize)
  {
    error = "the header's n_count (" + std::to_string(expected) +
      " streamlines) exceeds what the " + std::to_string(dataSize) + " bytes of data can hold";
    return false;
  }
  std::uint64_t pos = 0;
  while (pos < dataSize && (expected == 0 || lines.Start.size() < expected))
  {
    if (dataSize - pos < 4)
    {
      error = "the file ends inside the point count of streamline " +
        std::to_string(lines.Start.size()) + " (a truncated file)";
      return false;
    }
    std::int32_t m;
    std::memcpy(&m, lines.Data.data() + pos, 4);
    if (lines.Swap)
    {
      TF::SwapBytes(&m, 4, 1);
    }
    if (m < 0)
    {
      error = "streamline " + std::to_string(lines.Start.size()) + " has a negative point count (" +
        std::to_string(m) + ")";
      return false;
    }
    const std::uint64_t record = 4 + static_cast<std::uint64_t>(m) * pointBytes + propertyBytes;
    if (record > dataSize - pos)
    {
      error = "streamline " + std::to_string(lines.Start.size()) + " (" + std::to_string(m) +
        " points) runs past the end of the file (a truncated file, or wrong counts)";
      return false;
    }
    lines.Start.push_back(pos);
    lines.Count.push_back(m);
    pos += record;
  }
  if (expected > 0 && lines.Start.size() < expected)
  {
    error = "the header's n_count says " + std::to_string(expected) +
      " streamlines, the file holds " + std::to_string(lines.Start.size()) + " (a truncated file)";
    return false;
  }
  if (pos < dataSize)
  {
    vtkWarningMacro(<< this->FileName << ": " << (dataSize - pos)
                    << " bytes after the last of the header's " << expected
                    << " streamlines ignored");
  }
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
  const std::string where = std::string("cannot read \"") + this->FileName + "\": ";
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
  if (outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER()))
  {
    this->NumberOfPieces =
      std::max(1, outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES()));
    this->Piece = std::max(0,
      std::min(outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER()),
        this->NumberOfPieces - 1));
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
  this->NumberOfStreamlinesInFile = static_cast<vtkIdType>(lines.Count.size());

  // The streamlines to output: non-empty ones (unless kept), then this piece's share.
  std::vector<vtkIdType> selected;
  selected.reserve(lines.Count.size());
  for (std::size_t s = 0; s < lines.Count.size(); ++s)
  {
    if (lines.Count[s] > 0 || this->KeepEmptyStreamlines)
    {
      selected.push_back(static_cast<vtkIdType>(s));
    }
  }
  {
    const vtkIdType n = static_cast<vtkIdType>(selected.size());
    const vtkIdType b = n * this->Piece / this->NumberOfPieces;
    const vtkIdType e = n * (this->Piece + 1) / this->NumberOfPieces;
    selected = std::vector<vtkIdType>(selected.begin() + b, selected.begin() + e);
  }
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
  std::vector<vtkSmartPointer<vtkFloatArray>> pointArrays, cellArrays;
  std::vector<int> pointArrayFirst, cellArrayFirst; // first value of each array in a record
  // one float array per named .trk scalar / property, with its first value in a record
  auto makeArrays = [](const std::vector<std::pair<std::string, int>>& names, vtkIdType tuples,
                      std::vector<vtkSmartPointer<vtkFloatArray>>& arrays, std::vector<int>& firsts)
  {
    int first = 0;
    for (const auto& n : names)
    {
      auto a = vtkSmartPointer<vtkFloatArray>::New();
      a->SetName(n.first.c_str());
      a->SetNumberOfComponents(n.second);
      a->SetNumberOfTuples(tuples);
      arrays.push_back(a);
      firsts.push_back(first);
      first += n.second;
    }
  };
  if (lines.Format == TF::TRK)
  {
    makeArrays(lines.Trk.Scalars, nPoints, pointArrays, pointArrayFirst);
    makeArrays(lines.Trk.Properties, nLines, cellArrays, cellArrayFirst);
  }
  else
  {
    for (std::size_t k = 0; k < lines.PointScalars.size(); ++k)
    {
      auto a = vtkSmartPointer<vtkFloatArray>::New();
      a->SetName(lines.PointScalars[k].Name.c_str());
      a->SetNumberOfTuples(nPoints);
      pointArrays.push_back(a);
    }
  }

  // Raw pointers of the arrays (no virtual calls in the loops below).
  std::vector<float*> pointTargets, cellTargets;
  std::vector<int> pointComponents, cellComponents;
  for (auto& a : pointArrays)
  {
    pointTargets.push_back(a->GetPointer(0));
    pointComponents.push_back(a->GetNumberOfComponents());
  }
  for (auto& a : cellArrays)
  {
    cellTargets.push_back(a->GetPointer(0));
    cellComponents.push_back(a->GetNumberOfComponents());
  }

  // Convert and copy, in parallel batches of about BatchPoints points.
  std::atomic<vtkIdType> badLine(-1);
  float* pf =
    doublePoints ? nullptr : static_cast<vtkFloatArray*>(points->GetData())->GetPointer(0);
  double* pd =
    doublePoints ? static_cast<vtkDoubleArray*>(points->GetData())->GetPointer(0) : nullptr;
  const char* data = lines.Data.data();
  auto convert = [&](vtkIdType i0, vtkIdType i1)
  {
    for (vtkIdType i = i0; i < i1; ++i)
    {
      const std::size_t s = static_cast<std::size_t>(selected[static_cast<std::size_t>(i)]);
      const vtkIdType m = lines.Count[s];
      const vtkIdType o = off[i];
      if (lines.Format == TF::TCK)
      {
        const int vs = lines.ValueSize;
        const char* p = data + lines.Start[s] * 3 * vs;
        if (!lines.Swap && !doublePoints && vs == 4)
        {
          std::memcpy(pf + 3 * o, p, static_cast<std::size_t>(12 * m));
        }
        else
        {
          for (vtkIdType j = 0; j < 3 * m; ++j)
          {
            const double v = Value(p + j * vs, vs, lines.Swap);
            if (doublePoints)
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
          const char* q = sc.Data.data() + sc.Start[s] * sc.ValueSize;
          float* dst = pointTargets[k] + o;
          for (vtkIdType j = 0; j < m; ++j)
          {
            dst[j] = static_cast<float>(Value(q + j * sc.ValueSize, sc.ValueSize, sc.Swap));
          }
        }
      }
      else
      {
        const int perPoint = 3 + lines.ScalarsPerPoint;
        const char* p = data + lines.Start[s] + 4;
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
            vtkIdType expected = -1;
            badLine.compare_exchange_strong(expected, static_cast<vtkIdType>(s));
            return;
          }
          float* dst = pf + 3 * (o + j);
          for (int r = 0; r < 3; ++r)
          {
            const double y = a[r][0] * x[0] + a[r][1] * x[1] + a[r][2] * x[2] + a[r][3];
            if (!(std::abs(y) <= std::numeric_limits<float>::max()))
            {
              // beyond float32 after the voxel-mm to RAS+ map (a voxel size
              // near 0, a huge vox_to_ras): as unusable as a NaN
              vtkIdType expected = -1;
              badLine.compare_exchange_strong(expected, static_cast<vtkIdType>(s));
              return;
            }
            dst[r] = static_cast<float>(y);
          }
          for (std::size_t k = 0; k < pointTargets.size(); ++k)
          {
            const int nc = pointComponents[k];
            std::memcpy(pointTargets[k] + nc * (o + j), record + 3 + pointArrayFirst[k],
              4 * static_cast<std::size_t>(nc));
          }
        }
        if (!cellTargets.empty())
        {
          std::memcpy(record, p, 4 * static_cast<std::size_t>(lines.PropertiesPerLine));
          if (lines.Swap)
          {
            TF::SwapBytes(record, 4, static_cast<std::size_t>(lines.PropertiesPerLine));
          }
          for (std::size_t k = 0; k < cellTargets.size(); ++k)
          {
            const int nc = cellComponents[k];
            std::memcpy(cellTargets[k] + nc * i, record + cellArrayFirst[k],
              4 * static_cast<std::size_t>(nc));
          }
        }
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
    return fail(where + "streamline " + std::to_string(badLine.load()) +
      " has NaN or infinite coordinates, in the file or after the voxel-mm to RAS+ map (a damaged "
      "file or header)");
  }
  lines.Data.clear();

  // Polylines over consecutive points; 32-bit storage when it fits (half the memory).
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
  output->SetPoints(points);
  output->SetLines(cells);
  for (auto& a : pointArrays)
  {
    output->GetPointData()->AddArray(a);
  }
  if (pointArrays.size() == 1 && pointArrays[0]->GetNumberOfComponents() == 1)
  {
    output->GetPointData()->SetActiveScalars(pointArrays[0]->GetName());
  }
  for (auto& a : cellArrays)
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
  os << indent << "NumberOfStreamlinesInFile: " << this->NumberOfStreamlinesInFile << "\n";
}
