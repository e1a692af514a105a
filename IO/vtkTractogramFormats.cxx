// SPDX-License-Identifier: BSD-3-Clause
#include "vtkTractogramFormats.h"

#include "vtkMatrix4x4.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

namespace
{
std::string Lower(std::string s)
{
  std::transform(s.begin(), s.end(), s.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

std::string Trim(const std::string& s)
{
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos)
  {
    return std::string();
  }
  const auto e = s.find_last_not_of(" \t\r\n");
  return s.substr(b, e - b + 1);
}

// Typed access to the header bytes in the file's byte order.
template <typename T>
T Get(const unsigned char* bytes, std::size_t offset, bool swap)
{
  T v;
  std::memcpy(&v, bytes + offset, sizeof(T));
  if (swap)
  {
    vtkTractogramFormats::SwapBytes(&v, sizeof(T), 1);
  }
  return v;
}

template <typename T>
void Put(unsigned char* bytes, std::size_t offset, T v)
{
  if (!vtkTractogramFormats::HostIsLittleEndian())
  {
    vtkTractogramFormats::SwapBytes(&v, sizeof(T), 1);
  }
  std::memcpy(bytes + offset, &v, sizeof(T));
}

// Offsets of the TrackVis header fields.
enum TrkOffsets : std::size_t
{
  ID_STRING = 0,
  DIM = 6,
  VOXEL_SIZE = 12,
  ORIGIN = 24,
  N_SCALARS = 36,
  SCALAR_NAME = 38,
  N_PROPERTIES = 238,
  PROPERTY_NAME = 240,
  VOX_TO_RAS = 440,
  VOXEL_ORDER = 948,
  N_COUNT = 988,
  VERSION = 992,
  HDR_SIZE = 996
};

// Names of scalars or properties: "name", or "name\0N" for N values.
bool DecodeNames(const unsigned char* bytes, int total, const char* rest,
  std::vector<std::pair<std::string, int>>& names, std::string& error)
{
  names.clear();
  if (total <= 0)
  {
    return true;
  }
  int covered = 0;
  for (int i = 0; i < vtkTractogramFormats::TRK_MAX_NAMES; ++i)
  {
    const char* field =
      reinterpret_cast<const char*>(bytes) + i * vtkTractogramFormats::TRK_NAME_LENGTH;
    std::string raw(field, vtkTractogramFormats::TRK_NAME_LENGTH);
    raw.erase(raw.find_last_not_of('\0') + 1);
    if (raw.empty())
    {
      continue;
    }
    const auto nul = raw.find('\0');
    std::string name = raw.substr(0, nul);
    int count = 1;
    if (nul != std::string::npos)
    {
      const std::string digits = raw.substr(nul + 1);
      if (digits.find('\0') != std::string::npos || digits.empty() ||
        !std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; }))
      {
        error = "the name field \"" + name + "\" has unexpected bytes after its end";
        return false;
      }
      count = std::atoi(digits.c_str());
    }
    if (count <= 0)
    {
      continue;
    }
    if (covered + count > total)
    {
      error = "the " + std::string(rest) + " names cover more values than the header's count (" +
        std::to_string(total) + ")";
      return false;
    }
    names.emplace_back(name, count);
    covered += count;
  }
  if (covered < total)
  {
    names.emplace_back(rest, total - covered);
  }
  return true;
}

bool EncodeNames(
  const std::vector<std::pair<std::string, int>>& names, unsigned char* bytes, std::string& error)
{
  if (names.size() > static_cast<std::size_t>(vtkTractogramFormats::TRK_MAX_NAMES))
  {
    error = "TrackVis stores at most 10 named scalars and 10 named properties";
    return false;
  }
  for (std::size_t i = 0; i < names.size(); ++i)
  {
    std::string encoded = names[i].first;
    if (names[i].second > 1)
    {
      encoded += '\0';
      encoded += std::to_string(names[i].second);
    }
    if (encoded.size() > static_cast<std::size_t>(vtkTractogramFormats::TRK_NAME_LENGTH))
    {
      error = "the name \"" + names[i].first + "\" is too long for a TrackVis header";
      return false;
    }
    std::memcpy(bytes + i * vtkTractogramFormats::TRK_NAME_LENGTH, encoded.data(), encoded.size());
  }
  return true;
}

// World axis (0 x, 1 y, 2 z) and sign of an orientation letter; -1 if unknown.
int AxisOfCode(char c, int& sign)
{
  switch (std::toupper(static_cast<unsigned char>(c)))
  {
    case 'R':
      sign = 1;
      return 0;
    case 'L':
      sign = -1;
      return 0;
    case 'A':
      sign = 1;
      return 1;
    case 'P':
      sign = -1;
      return 1;
    case 'S':
      sign = 1;
      return 2;
    case 'I':
      sign = -1;
      return 2;
    default:
      sign = 0;
      return -1;
  }
}
}

//------------------------------------------------------------------------------
bool vtkTractogramFormats::HostIsLittleEndian()
{
  const std::uint16_t one = 1;
  unsigned char first;
  std::memcpy(&first, &one, 1);
  return first == 1;
}

void vtkTractogramFormats::SwapBytes(void* data, std::size_t size, std::size_t count)
{
  unsigned char* p = static_cast<unsigned char*>(data);
  for (std::size_t i = 0; i < count; ++i, p += size)
  {
    std::reverse(p, p + size);
  }
}

//------------------------------------------------------------------------------
int vtkTractogramFormats::FormatFromExtension(const std::string& fileName)
{
  const std::string name = Lower(fileName);
  auto ends = [&name](const char* ext)
  {
    const std::size_t n = std::strlen(ext);
    return name.size() >= n && name.compare(name.size() - n, n, ext) == 0;
  };
  if (ends(".tck"))
  {
    return TCK;
  }
  if (ends(".trk"))
  {
    return TRK;
  }
  return UNKNOWN;
}

int vtkTractogramFormats::DetectFormat(const std::string& fileName)
{
  std::ifstream in(fileName, std::ios::in | std::ios::binary);
  if (in)
  {
    char head[16] = {};
    in.read(head, sizeof(head));
    const std::string s(head, static_cast<std::size_t>(in.gcount()));
    if (s.compare(0, 13, "mrtrix tracks") == 0)
    {
      return TCK;
    }
    if (s.size() >= 6 && s.compare(0, 5, "TRACK") == 0 && s[5] == '\0')
    {
      return TRK;
    }
  }
  return FormatFromExtension(fileName);
}

//------------------------------------------------------------------------------
bool vtkTractogramFormats::ReadMRtrixHeader(
  const std::string& fileName, const char* magic, MRtrixHeader& header, std::string& error)
{
  header = MRtrixHeader();
  std::ifstream in(fileName, std::ios::in | std::ios::binary);
  if (!in)
  {
    error = "cannot open the file (it does not exist or is not readable)";
    return false;
  }
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  in.seekg(0, std::ios::beg);
  if (size <= 0)
  {
    error = "the file is empty";
    return false;
  }
  std::string line;
  if (!std::getline(in, line) || Trim(line) != magic)
  {
    error = std::string("not an MRtrix file: the first line is not \"") + magic + "\"";
    return false;
  }
  header.Magic = magic;
  bool end = false, haveFile = false;
  const std::streamoff maxHeader = std::streamoff(64) << 20;
  std::string fileValue;
  while (std::getline(in, line))
  {
    if (in.tellg() > maxHeader)
    {
      break;
    }
    line = Trim(line);
    if (line == "END")
    {
      end = true;
      break;
    }
    if (line.empty())
    {
      continue;
    }
    const auto colon = line.find(':');
    if (colon == std::string::npos)
    {
      if (header.Fields.empty())
      {
        error = "header line \"" + line + "\" is neither \"key: value\" nor END";
        return false;
      }
      header.Fields.back().second += "\n" + line; // continuation of the last key
      continue;
    }
    const std::string key = Trim(line.substr(0, colon));
    const std::string value = Trim(line.substr(colon + 1));
    if (key == "datatype")
    {
      header.DataType = value;
    }
    else if (key == "file")
    {
      fileValue = value;
      haveFile = true;
    }
    else if (key == "count")
    {
      char* stop = nullptr;
      const long long c = std::strtoll(value.c_str(), &stop, 10);
      header.Count = (stop && *stop == '\0' && c >= 0) ? c : -1;
    }
    else
    {
      if (key == "timestamp")
      {
        header.Timestamp = value;
      }
      header.Fields.emplace_back(key, value);
    }
  }
  if (!end)
  {
    error = "the header has no END line (truncated file?)";
    return false;
  }
  const std::streamoff headerEnd = in.tellg();
  if (header.DataType == "Float32LE" || header.DataType == "Float32BE")
  {
    header.ValueSize = 4;
  }
  else if (header.DataType == "Float64LE" || header.DataType == "Float64BE")
  {
    header.ValueSize = 8;
  }
  else
  {
    error = "unsupported datatype \"" + header.DataType +
      "\" (MRtrix tracks are Float32LE or Float32BE; Float64 is accepted too)";
    return false;
  }
  header.BigEndian = header.DataType.compare(header.DataType.size() - 2, 2, "BE") == 0;
  if (!haveFile)
  {
    header.DataOffset = static_cast<std::uint64_t>(headerEnd); // as nibabel guesses
  }
  else
  {
    std::istringstream f(fileValue);
    std::string dot;
    long long offset = -1;
    f >> dot >> offset;
    if (dot != "." || f.fail() || offset < 0)
    {
      error = "\"file: " + fileValue +
        "\" is not supported (only single-file data, \"file: . OFFSET\", is)";
      return false;
    }
    if (offset < headerEnd || offset > size)
    {
      error = "the data offset " + std::to_string(offset) +
        " lies outside the file (header ends at " + std::to_string(headerEnd) + ", file size " +
        std::to_string(size) + ")";
      return false;
    }
    header.DataOffset = static_cast<std::uint64_t>(offset);
  }
  return true;
}

std::string vtkTractogramFormats::MakeMRtrixHeader(const char* magic,
  const std::vector<std::pair<std::string, std::string>>& fields, long long count)
{
  std::ostringstream s;
  s << magic << "\n";
  for (const auto& kv : fields)
  {
    if (kv.first == "count" || kv.first == "datatype" || kv.first == "file" || kv.first == "END")
    {
      continue;
    }
    // a value spanning lines is written as repeated keys (MRtrix's convention)
    std::istringstream lines(kv.second);
    std::string l;
    bool any = false;
    while (std::getline(lines, l))
    {
      s << kv.first << ": " << l << "\n";
      any = true;
    }
    if (!any)
    {
      s << kv.first << ": \n";
    }
  }
  char countText[32];
  std::snprintf(countText, sizeof(countText), "%010lld", count);
  s << "count: " << countText << "\n";
  s << "datatype: Float32LE\n";
  const std::string head = s.str();
  const std::string tail = "\nEND\n";
  std::size_t digits = 1;
  std::size_t offset = 0;
  for (int iter = 0; iter < 4; ++iter)
  {
    offset = head.size() + std::strlen("file: . ") + digits + tail.size();
    digits = std::to_string(offset).size();
  }
  offset = head.size() + std::strlen("file: . ") + digits + tail.size();
  return head + "file: . " + std::to_string(offset) + tail;
}

//------------------------------------------------------------------------------
bool vtkTractogramFormats::ParseTrkHeader(
  const unsigned char* bytes, TrkHeader& header, std::string& error)
{
  header = TrkHeader();
  if (std::memcmp(bytes + ID_STRING, "TRACK", 5) != 0)
  {
    error = "not a TrackVis file: it does not start with \"TRACK\"";
    return false;
  }
  bool swap = false;
  int hdrSize = Get<std::int32_t>(bytes, HDR_SIZE, false);
  if (hdrSize != TRK_HEADER_SIZE)
  {
    swap = true;
    hdrSize = Get<std::int32_t>(bytes, HDR_SIZE, true);
    if (hdrSize != TRK_HEADER_SIZE)
    {
      error = "the header's hdr_size is " +
        std::to_string(Get<std::int32_t>(bytes, HDR_SIZE, false)) +
        ", not 1000 (in either byte order): not a TrackVis file, or a damaged header";
      return false;
    }
  }
  header.Swapped = swap;
  for (int i = 0; i < 3; ++i)
  {
    header.Dimensions[i] = Get<std::int16_t>(bytes, DIM + 2 * i, swap);
    header.VoxelSize[i] = Get<float>(bytes, VOXEL_SIZE + 4 * i, swap);
    header.Origin[i] = Get<float>(bytes, ORIGIN + 4 * i, swap);
  }
  header.NumberOfScalars = Get<std::int16_t>(bytes, N_SCALARS, swap);
  header.NumberOfProperties = Get<std::int16_t>(bytes, N_PROPERTIES, swap);
  header.NumberOfStreamlines = Get<std::int32_t>(bytes, N_COUNT, swap);
  header.Version = Get<std::int32_t>(bytes, VERSION, swap);
  if (header.Version != 1 && header.Version != 2 && header.Version != 3)
  {
    error = "unsupported TrackVis version " + std::to_string(header.Version) + " (1 and 2 are)";
    return false;
  }
  if (header.NumberOfScalars < 0 || header.NumberOfProperties < 0)
  {
    error = "negative n_scalars or n_properties in the header";
    return false;
  }
  if (header.NumberOfStreamlines < 0)
  {
    error = "negative n_count (" + std::to_string(header.NumberOfStreamlines) + ") in the header";
    return false;
  }
  for (int i = 0; i < 3; ++i)
  {
    const float v = header.VoxelSize[i];
    if (!std::isfinite(v) || v <= 0.0f)
    {
      error = "the voxel size must be positive and finite";
      return false;
    }
  }
  header.VoxelToRASRecorded = false;
  if (header.Version >= 2)
  {
    double m[4][4];
    for (int i = 0; i < 4; ++i)
    {
      for (int j = 0; j < 4; ++j)
      {
        m[i][j] = Get<float>(bytes, VOX_TO_RAS + 4 * (4 * i + j), swap);
        if (!std::isfinite(m[i][j]))
        {
          error = "vox_to_ras has a non-finite value";
          return false;
        }
      }
    }
    if (m[3][3] != 0.0)
    {
      header.VoxelToRASRecorded = true;
      std::memcpy(header.VoxelToRAS, m, sizeof(m));
    }
  }
  std::string order(reinterpret_cast<const char*>(bytes) + VOXEL_ORDER, 4);
  order.erase(std::find(order.begin(), order.end(), '\0'), order.end());
  order = Trim(order);
  header.VoxelOrder = order.empty() ? std::string("LPS") : order;
  if (!DecodeNames(bytes + SCALAR_NAME, header.NumberOfScalars, "scalars", header.Scalars, error) ||
    !DecodeNames(
      bytes + PROPERTY_NAME, header.NumberOfProperties, "properties", header.Properties, error))
  {
    return false;
  }
  return true;
}

bool vtkTractogramFormats::EncodeTrkHeader(
  const TrkHeader& header, unsigned char* bytes, std::string& error)
{
  std::memset(bytes, 0, TRK_HEADER_SIZE);
  std::memcpy(bytes + ID_STRING, "TRACK", 5);
  for (int i = 0; i < 3; ++i)
  {
    Put<std::int16_t>(bytes, DIM + 2 * i, header.Dimensions[i]);
    Put<float>(bytes, VOXEL_SIZE + 4 * i, header.VoxelSize[i]);
    Put<float>(bytes, ORIGIN + 4 * i, header.Origin[i]);
  }
  int ns = 0, np = 0;
  for (const auto& s : header.Scalars)
  {
    ns += s.second;
  }
  for (const auto& p : header.Properties)
  {
    np += p.second;
  }
  if (ns > 32767 || np > 32767)
  {
    error = "too many scalar or property values per point or streamline";
    return false;
  }
  Put<std::int16_t>(bytes, N_SCALARS, static_cast<std::int16_t>(ns));
  Put<std::int16_t>(bytes, N_PROPERTIES, static_cast<std::int16_t>(np));
  if (!EncodeNames(header.Scalars, bytes + SCALAR_NAME, error) ||
    !EncodeNames(header.Properties, bytes + PROPERTY_NAME, error))
  {
    return false;
  }
  for (int i = 0; i < 4; ++i)
  {
    for (int j = 0; j < 4; ++j)
    {
      Put<float>(bytes, VOX_TO_RAS + 4 * (4 * i + j), static_cast<float>(header.VoxelToRAS[i][j]));
    }
  }
  const std::string order = header.VoxelOrder.substr(0, 3);
  std::memcpy(bytes + VOXEL_ORDER, order.data(), order.size());
  Put<std::int32_t>(bytes, N_COUNT, header.NumberOfStreamlines);
  Put<std::int32_t>(bytes, VERSION, 2);
  Put<std::int32_t>(bytes, HDR_SIZE, TRK_HEADER_SIZE);
  return true;
}

//------------------------------------------------------------------------------
std::string vtkTractogramFormats::AxisCodes(const double m[4][4])
{
  // Greedy assignment of the largest normalized entries (unique rows).
  double norm[3];
  for (int j = 0; j < 3; ++j)
  {
    norm[j] = std::sqrt(m[0][j] * m[0][j] + m[1][j] * m[1][j] + m[2][j] * m[2][j]);
    if (!(norm[j] > 0.0))
    {
      return std::string();
    }
  }
  bool rowUsed[3] = { false, false, false };
  int rowOf[3] = { -1, -1, -1 };
  for (int round = 0; round < 3; ++round)
  {
    double best = -1.0;
    int bi = -1, bj = -1;
    for (int j = 0; j < 3; ++j)
    {
      if (rowOf[j] >= 0)
      {
        continue;
      }
      for (int i = 0; i < 3; ++i)
      {
        const double v = std::abs(m[i][j]) / norm[j];
        if (!rowUsed[i] && v > best)
        {
          best = v;
          bi = i;
          bj = j;
        }
      }
    }
    if (bi < 0 || best <= 0.0)
    {
      return std::string();
    }
    rowUsed[bi] = true;
    rowOf[bj] = bi;
  }
  static const char pos[3] = { 'R', 'A', 'S' };
  static const char neg[3] = { 'L', 'P', 'I' };
  std::string codes;
  for (int j = 0; j < 3; ++j)
  {
    codes += m[rowOf[j]][j] > 0 ? pos[rowOf[j]] : neg[rowOf[j]];
  }
  return codes;
}

bool vtkTractogramFormats::InvertAffine(const double m[4][4], double inverse[4][4])
{
  const double det = vtkMatrix4x4::Determinant(&m[0][0]);
  if (!(std::abs(det) > 0.0) || !std::isfinite(det))
  {
    return false;
  }
  vtkMatrix4x4::Invert(&m[0][0], &inverse[0][0]);
  return true;
}

bool vtkTractogramFormats::TrkVoxmmToRAS(
  const TrkHeader& header, double out[4][4], std::string& error)
{
  const std::string affineCodes = AxisCodes(header.VoxelToRAS);
  if (affineCodes.empty())
  {
    error = "vox_to_ras does not name three axis directions";
    return false;
  }
  const std::string order = header.VoxelOrder;
  int headerAxis[3], headerSign[3];
  bool seen[3] = { false, false, false };
  if (order.size() < 3)
  {
    error = "the voxel order \"" + order + "\" does not name three axes";
    return false;
  }
  for (int j = 0; j < 3; ++j)
  {
    headerAxis[j] = AxisOfCode(order[j], headerSign[j]);
    if (headerAxis[j] < 0 || seen[headerAxis[j]])
    {
      error = "the voxel order \"" + order + "\" does not name three distinct axes";
      return false;
    }
    seen[headerAxis[j]] = true;
  }
  // voxmm -> voxel centres in the header's voxel order: v = x / size - 0.5
  double a[4][4] = {};
  for (int j = 0; j < 3; ++j)
  {
    a[j][j] = 1.0 / header.VoxelSize[j];
    a[j][3] = -0.5;
  }
  a[3][3] = 1.0;
  // header voxel order -> the voxel order of vox_to_ras (flips, swaps)
  double o[4][4] = {};
  o[3][3] = 1.0;
  for (int k = 0; k < 3; ++k)
  {
    int sign;
    const int axis = AxisOfCode(affineCodes[k], sign);
    for (int j = 0; j < 3; ++j)
    {
      if (headerAxis[j] == axis)
      {
        if (headerSign[j] == sign)
        {
          o[k][j] = 1.0;
        }
        else
        {
          o[k][j] = -1.0;
          o[k][3] = header.Dimensions[j] - 1.0;
        }
      }
    }
  }
  auto mul = [](const double x[4][4], const double y[4][4], double z[4][4])
  {
    double t[4][4];
    for (int i = 0; i < 4; ++i)
    {
      for (int j = 0; j < 4; ++j)
      {
        t[i][j] = x[i][0] * y[0][j] + x[i][1] * y[1][j] + x[i][2] * y[2][j] + x[i][3] * y[3][j];
      }
    }
    std::memcpy(z, t, sizeof(t));
  };
  double oa[4][4];
  mul(o, a, oa);
  mul(header.VoxelToRAS, oa, out);
  return true;
}
