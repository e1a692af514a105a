// SPDX-License-Identifier: BSD-3-Clause
#include "vtkTractogramWriter.h"

#include "vtkSplineVizNameList.h"
#include "vtkTractogramFormats.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkErrorCode.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkMatrix3x3.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkStringArray.h"

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cctype>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>
#include <vector>

vtkStandardNewMacro(vtkTractogramWriter);

using TF = vtkTractogramFormats;

struct vtkTractogramWriter::Internals
{
  vtkSplineVizNameList PointArrays;
  vtkSplineVizNameList CellArrays;
};

// The input's lines, flattened: line l has the points Ids[Offsets[l] ..
// Offsets[l + 1]) of block Block[l] (its cell Cell[l] in that block).
struct vtkTractogramWriter::Lines
{
  std::vector<vtkPolyData*> Blocks;
  std::vector<int> Block;
  std::vector<vtkIdType> Cell;
  std::vector<vtkIdType> Offsets{ 0 };
  std::vector<vtkIdType> Ids;
  // the named arrays, per block
  std::vector<std::vector<vtkDataArray*>> PointArrays, CellArrays;
  std::vector<int> PointComponents, CellComponents;
  vtkFieldData* Field = nullptr;

  vtkIdType NumberOfLines() const { return static_cast<vtkIdType>(this->Block.size()); }
  vtkIdType NumberOfPoints(vtkIdType l) const { return this->Offsets[l + 1] - this->Offsets[l]; }
  void Point(vtkIdType l, vtkIdType j, double x[3]) const
  {
    this->Blocks[this->Block[l]]->GetPoints()->GetPoint(this->Ids[this->Offsets[l] + j], x);
  }
};

namespace
{
void PutFloatLE(char* dst, double v)
{
  float f = static_cast<float>(v);
  if (!TF::HostIsLittleEndian())
  {
    TF::SwapBytes(&f, 4, 1);
  }
  std::memcpy(dst, &f, 4);
}

void PutInt32LE(char* dst, std::int32_t v)
{
  if (!TF::HostIsLittleEndian())
  {
    TF::SwapBytes(&v, 4, 1);
  }
  std::memcpy(dst, &v, 4);
}

bool WriteFile(const std::string& name, const std::string& head, const std::vector<char>& data,
  std::string& error)
{
  std::ofstream out(name, std::ios::out | std::ios::binary | std::ios::trunc);
  if (!out)
  {
    error = "cannot open \"" + name + "\" for writing";
    return false;
  }
  out.write(head.data(), static_cast<std::streamsize>(head.size()));
  const std::size_t chunk = 16u << 20;
  for (std::size_t done = 0; done < data.size() && out; done += chunk)
  {
    out.write(
      data.data() + done, static_cast<std::streamsize>(std::min(chunk, data.size() - done)));
  }
  out.close();
  if (!out)
  {
    error = "cannot write \"" + name + "\" (disk full?)";
    return false;
  }
  return true;
}

std::string StripTck(const std::string& name)
{
  if (name.size() > 4)
  {
    std::string tail = name.substr(name.size() - 4);
    for (char& c : tail)
    {
      c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
    if (tail == ".tck")
    {
      return name.substr(0, name.size() - 4);
    }
  }
  return name;
}
}

//------------------------------------------------------------------------------
vtkTractogramWriter::vtkTractogramWriter()
  : Internal(new Internals)
{
}

vtkTractogramWriter::~vtkTractogramWriter()
{
  this->SetFileName(nullptr);
}

int vtkTractogramWriter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Remove(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE());
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkCompositeDataSet");
  return 1;
}

void vtkTractogramWriter::AddPointArrayName(const char* name)
{
  if (this->Internal->PointArrays.Add(name))
  {
    this->Modified();
  }
}
void vtkTractogramWriter::RemoveAllPointArrayNames()
{
  if (this->Internal->PointArrays.Clear())
  {
    this->Modified();
  }
}
int vtkTractogramWriter::GetNumberOfPointArrayNames() const
{
  return this->Internal->PointArrays.Size();
}
const char* vtkTractogramWriter::GetPointArrayName(int i) const
{
  return this->Internal->PointArrays.Get(i);
}
void vtkTractogramWriter::AddCellArrayName(const char* name)
{
  if (this->Internal->CellArrays.Add(name))
  {
    this->Modified();
  }
}
void vtkTractogramWriter::RemoveAllCellArrayNames()
{
  if (this->Internal->CellArrays.Clear())
  {
    this->Modified();
  }
}
int vtkTractogramWriter::GetNumberOfCellArrayNames() const
{
  return this->Internal->CellArrays.Size();
}
const char* vtkTractogramWriter::GetCellArrayName(int i) const
{
  return this->Internal->CellArrays.Get(i);
}

std::string vtkTractogramWriter::ScalarFileName(
  const std::string& tckFileName, const std::string& arrayName)
{
  return StripTck(tckFileName) + "." + arrayName + ".tsf";
}

void vtkTractogramWriter::SetGeometryFromImage(vtkImageData* image)
{
  if (!image)
  {
    return;
  }
  const double* o = image->GetOrigin();
  const double* s = image->GetSpacing();
  const double* d = image->GetDirectionMatrix()->GetData();
  double m[16] = {};
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      m[4 * i + j] = d[3 * i + j] * s[j];
    }
    m[4 * i + 3] = o[i];
  }
  m[15] = 1.0;
  this->SetVoxelToRAS(m);
  this->SetVoxelSize(std::abs(s[0]), std::abs(s[1]), std::abs(s[2]));
  const int* dims = image->GetDimensions();
  this->SetDimensions(dims[0], dims[1], dims[2]);
  this->SetUseInputTrackVisGeometry(0);
}

//------------------------------------------------------------------------------
void vtkTractogramWriter::WriteData()
{
  this->LastError.clear();
  auto fail = [this](const std::string& msg, unsigned long code = vtkErrorCode::UserError)
  {
    this->LastError = msg;
    this->SetErrorCode(code);
    vtkErrorMacro(<< msg);
  };
  if (!this->FileName || !*this->FileName)
  {
    fail("no file name was given", vtkErrorCode::NoFileNameError);
    return;
  }
  int format = this->FileFormat;
  if (format == AUTOMATIC)
  {
    format = TF::FormatFromExtension(this->FileName);
    if (format == TF::UNKNOWN)
    {
      fail(std::string("\"") + this->FileName +
        "\": the extension is neither .tck nor .trk (set FileFormat)");
      return;
    }
  }

  // Gather the lines of every polydata block.
  Lines lines;
  vtkDataObject* input = this->GetInputDataObject(0, 0);
  if (auto* pd = vtkPolyData::SafeDownCast(input))
  {
    lines.Blocks.push_back(pd);
  }
  else if (auto* cd = vtkCompositeDataSet::SafeDownCast(input))
  {
    vtkSmartPointer<vtkCompositeDataIterator> it;
    it.TakeReference(cd->NewIterator());
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
    {
      if (auto* leaf = vtkPolyData::SafeDownCast(it->GetCurrentDataObject()))
      {
        lines.Blocks.push_back(leaf);
      }
    }
  }
  else
  {
    fail("the input is not polydata");
    return;
  }
  bool otherCells = false;
  for (std::size_t b = 0; b < lines.Blocks.size(); ++b)
  {
    vtkPolyData* pd = lines.Blocks[b];
    otherCells =
      otherCells || pd->GetNumberOfVerts() + pd->GetNumberOfPolys() + pd->GetNumberOfStrips() > 0;
    if (pd->GetNumberOfLines() == 0)
    {
      continue;
    }
    const vtkIdType firstLine = pd->GetNumberOfVerts();
    auto it = vtk::TakeSmartPointer(pd->GetLines()->NewIterator());
    vtkIdType k = 0;
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell(), ++k)
    {
      vtkIdType n;
      const vtkIdType* ids;
      it->GetCurrentCell(n, ids);
      lines.Block.push_back(static_cast<int>(b));
      lines.Cell.push_back(firstLine + k);
      lines.Ids.insert(lines.Ids.end(), ids, ids + n);
      lines.Offsets.push_back(static_cast<vtkIdType>(lines.Ids.size()));
    }
  }
  if (otherCells)
  {
    vtkWarningMacro(<< "only the lines of the input are written (vertices and polygons ignored)");
  }
  lines.Field = lines.Blocks.empty() ? nullptr : lines.Blocks[0]->GetFieldData();
  const vtkIdType nLines = lines.NumberOfLines();

  // Named arrays: present in every block that has lines, same component count.
  auto gather = [&](const std::vector<std::string>& names, bool point,
                  std::vector<std::vector<vtkDataArray*>>& arrays, std::vector<int>& comps) -> bool
  {
    arrays.assign(names.size(), std::vector<vtkDataArray*>(lines.Blocks.size(), nullptr));
    comps.assign(names.size(), -1);
    for (std::size_t k = 0; k < names.size(); ++k)
    {
      for (std::size_t b = 0; b < lines.Blocks.size(); ++b)
      {
        vtkPolyData* pd = lines.Blocks[b];
        if (pd->GetNumberOfLines() == 0)
        {
          continue;
        }
        vtkDataArray* a = point ? pd->GetPointData()->GetArray(names[k].c_str())
                                : pd->GetCellData()->GetArray(names[k].c_str());
        if (!a)
        {
          fail(std::string("the input has no ") + (point ? "point" : "cell") + " array \"" +
            names[k] + "\"");
          return false;
        }
        if (comps[k] >= 0 && comps[k] != a->GetNumberOfComponents())
        {
          fail("the array \"" + names[k] + "\" has different numbers of components in the blocks");
          return false;
        }
        comps[k] = a->GetNumberOfComponents();
        arrays[k][b] = a;
      }
      comps[k] = std::max(comps[k], 1);
    }
    return true;
  };
  if (!gather(this->Internal->PointArrays.Names, true, lines.PointArrays, lines.PointComponents) ||
    (format == TF::TRK &&
      !gather(this->Internal->CellArrays.Names, false, lines.CellArrays, lines.CellComponents)))
  {
    return;
  }
  if (format == TF::TCK && this->Internal->CellArrays.Size() > 0)
  {
    vtkWarningMacro(<< "a .tck file has no per-streamline properties: cell arrays not written");
  }

  // Coordinates must be finite (a .tck would read NaNs as separators).
  std::atomic<vtkIdType> bad(-1);
  vtkSMPTools::For(0, nLines,
    [&](vtkIdType l0, vtkIdType l1)
    {
      double x[3];
      for (vtkIdType l = l0; l < l1 && bad.load() < 0; ++l)
      {
        for (vtkIdType j = 0; j < lines.NumberOfPoints(l); ++j)
        {
          lines.Point(l, j, x);
          if (!std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2]))
          {
            vtkIdType e = -1;
            bad.compare_exchange_strong(e, l);
            break;
          }
        }
      }
    });
  if (bad.load() >= 0)
  {
    fail("line " + std::to_string(bad.load()) + " has NaN or infinite coordinates");
    return;
  }
  this->UpdateProgress(0.1);

  std::string error;
  const bool ok = format == TF::TCK ? this->WriteTCK(lines, error) : this->WriteTRK(lines, error);
  if (!ok)
  {
    std::remove(this->FileName);
    fail(std::string("cannot write \"") + this->FileName + "\": " + error,
      error.find("disk") != std::string::npos ? vtkErrorCode::OutOfDiskSpaceError
                                              : vtkErrorCode::UserError);
    return;
  }
  this->UpdateProgress(1.0);
}

//------------------------------------------------------------------------------
bool vtkTractogramWriter::WriteTCK(const Lines& lines, std::string& error)
{
  const vtkIdType nLines = lines.NumberOfLines();
  const vtkIdType nPoints = lines.Offsets.back();
  // Header fields: the input's (as the reader keeps them) and a timestamp.
  std::vector<std::pair<std::string, std::string>> fields;
  std::string timestamp;
  if (auto* kept = lines.Field
      ? vtkStringArray::SafeDownCast(lines.Field->GetAbstractArray("MRtrixHeader"))
      : nullptr)
  {
    for (vtkIdType i = 0; i < kept->GetNumberOfValues(); ++i)
    {
      const std::string kv = kept->GetValue(i);
      const auto colon = kv.find(':');
      if (colon == std::string::npos)
      {
        continue;
      }
      std::string key = kv.substr(0, colon), value = kv.substr(colon + 1);
      if (!value.empty() && value[0] == ' ')
      {
        value.erase(0, 1);
      }
      if (key == "timestamp")
      {
        timestamp = value;
      }
      else
      {
        fields.emplace_back(key, value);
      }
    }
  }
  if (timestamp.empty())
  {
    const double now =
      std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
    char text[64];
    std::snprintf(text, sizeof(text), "%.10g", now);
    timestamp = text;
  }
  fields.emplace_back("timestamp", timestamp);
  const std::string head = TF::MakeMRtrixHeader("mrtrix tracks", fields, nLines);

  // Data: the points of line l start at triplet Offsets[l] + l.
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  std::vector<char> data;
  try
  {
    data.resize(static_cast<std::size_t>(12 * (nPoints + nLines + 1)));
  }
  catch (const std::bad_alloc&)
  {
    error = "not enough memory";
    return false;
  }
  vtkSMPTools::For(0, nLines,
    [&](vtkIdType l0, vtkIdType l1)
    {
      double x[3];
      for (vtkIdType l = l0; l < l1; ++l)
      {
        char* p = data.data() + 12 * (lines.Offsets[l] + l);
        for (vtkIdType j = 0; j < lines.NumberOfPoints(l); ++j, p += 12)
        {
          lines.Point(l, j, x);
          PutFloatLE(p, x[0]);
          PutFloatLE(p + 4, x[1]);
          PutFloatLE(p + 8, x[2]);
        }
        PutFloatLE(p, nan);
        PutFloatLE(p + 4, nan);
        PutFloatLE(p + 8, nan);
      }
    });
  char* end = data.data() + 12 * (nPoints + nLines);
  PutFloatLE(end, inf);
  PutFloatLE(end + 4, inf);
  PutFloatLE(end + 8, inf);
  this->UpdateProgress(0.4);
  if (!WriteFile(this->FileName, head, data, error))
  {
    return false;
  }

  // One .tsf per named point array, with the tractogram's timestamp.
  for (std::size_t k = 0; k < lines.PointArrays.size(); ++k)
  {
    const std::string name = this->Internal->PointArrays.Names[k];
    if (lines.PointComponents[k] != 1)
    {
      error = "the point array \"" + name + "\" has " + std::to_string(lines.PointComponents[k]) +
        " components; a .tsf holds one value per point";
      return false;
    }
    std::vector<char> values(static_cast<std::size_t>(4 * (nPoints + nLines + 1)));
    std::atomic<bool> finite(true);
    vtkSMPTools::For(0, nLines,
      [&](vtkIdType l0, vtkIdType l1)
      {
        for (vtkIdType l = l0; l < l1; ++l)
        {
          vtkDataArray* a = lines.PointArrays[k][lines.Block[l]];
          char* p = values.data() + 4 * (lines.Offsets[l] + l);
          for (vtkIdType j = 0; j < lines.NumberOfPoints(l); ++j, p += 4)
          {
            const double v = a->GetComponent(lines.Ids[lines.Offsets[l] + j], 0);
            if (!std::isfinite(v))
            {
              finite = false;
            }
            PutFloatLE(p, v);
          }
          PutFloatLE(p, nan);
        }
      });
    if (!finite)
    {
      error = "the point array \"" + name +
        "\" has NaN or infinite values, which a .tsf cannot store (they mark its streamline ends)";
      return false;
    }
    PutFloatLE(values.data() + 4 * (nPoints + nLines), inf);
    const std::string tsf = ScalarFileName(this->FileName, name);
    const std::string tsfHead =
      TF::MakeMRtrixHeader("mrtrix track scalars", { { "timestamp", timestamp } }, nLines);
    if (!WriteFile(tsf, tsfHead, values, error))
    {
      return false;
    }
    this->UpdateProgress(0.4 + 0.6 * (k + 1) / lines.PointArrays.size());
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkTractogramWriter::WriteTRK(const Lines& lines, std::string& error)
{
  const vtkIdType nLines = lines.NumberOfLines();
  if (nLines > std::numeric_limits<std::int32_t>::max())
  {
    error = "more streamlines than a .trk can count";
    return false;
  }
  TF::TrkHeader h;
  const double* m = this->VoxelToRAS;
  double voxelSize[3] = { this->VoxelSize[0], this->VoxelSize[1], this->VoxelSize[2] };
  int dims[3] = { this->Dimensions[0], this->Dimensions[1], this->Dimensions[2] };
  double fromInput[16];
  if (this->UseInputTrackVisGeometry && lines.Field)
  {
    vtkDataArray* v2r = lines.Field->GetArray("TrackVisVoxelToRAS");
    vtkDataArray* vs = lines.Field->GetArray("TrackVisVoxelSize");
    vtkDataArray* dm = lines.Field->GetArray("TrackVisDimensions");
    if (v2r && v2r->GetNumberOfComponents() == 16 && v2r->GetNumberOfTuples() == 1 && vs &&
      vs->GetNumberOfComponents() == 3 && dm && dm->GetNumberOfComponents() == 3)
    {
      v2r->GetTuple(0, fromInput);
      m = fromInput;
      vs->GetTuple(0, voxelSize);
      for (int i = 0; i < 3; ++i)
      {
        dims[i] = static_cast<int>(dm->GetComponent(0, i));
      }
    }
  }
  for (int i = 0; i < 3; ++i)
  {
    if (!(voxelSize[i] > 0.0) || !std::isfinite(voxelSize[i]))
    {
      error = "the voxel size must be positive";
      return false;
    }
    if (dims[i] < 1 || dims[i] > 32767)
    {
      error = "the dimensions must be in [1, 32767]";
      return false;
    }
    h.VoxelSize[i] = static_cast<float>(voxelSize[i]);
    h.Dimensions[i] = static_cast<short>(dims[i]);
  }
  for (int i = 0; i < 4; ++i)
  {
    for (int j = 0; j < 4; ++j)
    {
      h.VoxelToRAS[i][j] = static_cast<float>(m[4 * i + j]); // as stored
    }
  }
  h.VoxelOrder = TF::AxisCodes(h.VoxelToRAS);
  if (h.VoxelOrder.empty())
  {
    error = "the voxel to RAS matrix is singular";
    return false;
  }
  h.NumberOfStreamlines = static_cast<int>(nLines);
  int ns = 0, np = 0;
  for (std::size_t k = 0; k < lines.PointArrays.size(); ++k)
  {
    h.Scalars.emplace_back(this->Internal->PointArrays.Names[k], lines.PointComponents[k]);
    ns += lines.PointComponents[k];
  }
  for (std::size_t k = 0; k < lines.CellArrays.size(); ++k)
  {
    h.Properties.emplace_back(this->Internal->CellArrays.Names[k], lines.CellComponents[k]);
    np += lines.CellComponents[k];
  }
  unsigned char bytes[TF::TRK_HEADER_SIZE];
  if (!TF::EncodeTrkHeader(h, bytes, error))
  {
    return false;
  }
  double toRAS[4][4], toVoxmm[4][4];
  if (!TF::TrkVoxmmToRAS(h, toRAS, error) || !TF::InvertAffine(toRAS, toVoxmm))
  {
    error = error.empty() ? std::string("the voxel to RAS matrix is singular") : error;
    return false;
  }

  // Records: int32 count, (x y z scalars) per point, properties.
  std::vector<vtkIdType> start(static_cast<std::size_t>(nLines) + 1, 0);
  for (vtkIdType l = 0; l < nLines; ++l)
  {
    const vtkIdType n = lines.NumberOfPoints(l);
    if (n > std::numeric_limits<std::int32_t>::max())
    {
      error = "a streamline has more points than a .trk can count";
      return false;
    }
    start[l + 1] = start[l] + 4 + 4 * n * (3 + ns) + 4 * np;
  }
  std::vector<char> data;
  try
  {
    data.resize(static_cast<std::size_t>(start[nLines]));
  }
  catch (const std::bad_alloc&)
  {
    error = "not enough memory";
    return false;
  }
  vtkSMPTools::For(0, nLines,
    [&](vtkIdType l0, vtkIdType l1)
    {
      double x[3];
      std::vector<double> tuple;
      for (vtkIdType l = l0; l < l1; ++l)
      {
        const vtkIdType n = lines.NumberOfPoints(l);
        char* p = data.data() + start[l];
        PutInt32LE(p, static_cast<std::int32_t>(n));
        p += 4;
        for (vtkIdType j = 0; j < n; ++j)
        {
          lines.Point(l, j, x);
          for (int r = 0; r < 3; ++r, p += 4)
          {
            PutFloatLE(p,
              toVoxmm[r][0] * x[0] + toVoxmm[r][1] * x[1] + toVoxmm[r][2] * x[2] + toVoxmm[r][3]);
          }
          const vtkIdType id = lines.Ids[lines.Offsets[l] + j];
          for (std::size_t k = 0; k < lines.PointArrays.size(); ++k)
          {
            vtkDataArray* a = lines.PointArrays[k][lines.Block[l]];
            for (int c = 0; c < lines.PointComponents[k]; ++c, p += 4)
            {
              PutFloatLE(p, a->GetComponent(id, c));
            }
          }
        }
        for (std::size_t k = 0; k < lines.CellArrays.size(); ++k)
        {
          vtkDataArray* a = lines.CellArrays[k][lines.Block[l]];
          for (int c = 0; c < lines.CellComponents[k]; ++c, p += 4)
          {
            PutFloatLE(p, a->GetComponent(lines.Cell[l], c));
          }
        }
      }
    });
  this->UpdateProgress(0.5);
  return WriteFile(
    this->FileName, std::string(reinterpret_cast<char*>(bytes), sizeof(bytes)), data, error);
}

//------------------------------------------------------------------------------
void vtkTractogramWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "FileFormat: " << this->FileFormat << "\n";
  os << indent << "PointArrayNames:";
  this->Internal->PointArrays.Print(os);
  os << indent << "CellArrayNames:";
  this->Internal->CellArrays.Print(os);
  os << indent << "VoxelToRAS:";
  for (double v : this->VoxelToRAS)
  {
    os << " " << v;
  }
  os << "\n"
     << indent << "VoxelSize: " << this->VoxelSize[0] << " " << this->VoxelSize[1] << " "
     << this->VoxelSize[2] << "\n";
  os << indent << "Dimensions: " << this->Dimensions[0] << " " << this->Dimensions[1] << " "
     << this->Dimensions[2] << "\n";
  os << indent << "UseInputTrackVisGeometry: " << this->UseInputTrackVisGeometry << "\n";
}
