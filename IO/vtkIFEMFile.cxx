// SPDX-License-Identifier: BSD-3-Clause
#include "vtkIFEMFile.h"
#include "vtkSplineVizError.h"

#include "vtkSplineVizProgress.h"

#include <hdf5.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <type_traits>

static_assert(std::is_same<hid_t, int64_t>::value, "HDF5 1.10 or later (64-bit hid_t) is needed");

namespace
{
// HDF5's automatic error printing off while an object lives.
class QuietErrors
{
public:
  QuietErrors()
  {
    H5Eget_auto2(H5E_DEFAULT, &this->Function, &this->Data);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  }
  ~QuietErrors() { H5Eset_auto2(H5E_DEFAULT, this->Function, this->Data); }
  QuietErrors(const QuietErrors&) = delete;
  QuietErrors& operator=(const QuietErrors&) = delete;

private:
  H5E_auto2_t Function = nullptr;
  void* Data = nullptr;
};

// An HDF5 identifier closed by its close function.
class Handle
{
public:
  Handle(hid_t id, herr_t (*close)(hid_t))
    : Id(id)
    , Close(close)
  {
  }
  ~Handle()
  {
    if (this->Id >= 0)
    {
      this->Close(this->Id);
    }
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  hid_t Get() const { return this->Id; }
  bool Valid() const { return this->Id >= 0; }

private:
  hid_t Id;
  herr_t (*Close)(hid_t);
};

bool IsNonNegativeInteger(const std::string& s, long long* value)
{
  if (s.empty() || s.size() > 9 || !std::all_of(s.begin(), s.end(), ::isdigit))
  {
    return false;
  }
  if (value)
  {
    *value = std::strtoll(s.c_str(), nullptr, 10);
  }
  return true;
}

using vtkSplineVizError::Fail;
}

//------------------------------------------------------------------------------
vtkIFEMFile::~vtkIFEMFile()
{
  this->Close();
}

void vtkIFEMFile::Close()
{
  if (this->File >= 0)
  {
    QuietErrors quiet;
    H5Fclose(this->File);
  }
  this->File = -1;
  this->FileBytes = 0;
}

//------------------------------------------------------------------------------
bool vtkIFEMFile::Open(const std::string& fileName, std::string* error)
{
  this->Close();
  QuietErrors quiet;
  {
    std::ifstream in(fileName, std::ios::binary | std::ios::ate);
    if (!in)
    {
      return Fail(error, "cannot open the file (it does not exist or is not readable)");
    }
    const std::streamoff size = in.tellg();
    if (size < 0)
    {
      return Fail(error, "cannot read the file (is it a directory?)");
    }
    this->FileBytes = static_cast<uint64_t>(size);
  }
  if (H5Fis_hdf5(fileName.c_str()) <= 0)
  {
    return Fail(error, "not an HDF5 file");
  }
  this->File = H5Fopen(fileName.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (this->File < 0)
  {
    return Fail(error, "HDF5 cannot open the file");
  }
  return true;
}

bool vtkIFEMFile::OpenImage(const std::string& bytes, std::string* error)
{
  this->Close();
  QuietErrors quiet;
  if (bytes.size() < 8 || bytes.compare(0, 8, "\x89HDF\r\n\x1a\n") != 0)
  {
    return Fail(error, "not an HDF5 file (no HDF5 signature at its start)");
  }
  Handle access(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
  if (!access.Valid() || H5Pset_fapl_core(access.Get(), 64 * 1024, 0) < 0 ||
    H5Pset_file_image(access.Get(), const_cast<char*>(bytes.data()), bytes.size()) < 0)
  {
    return Fail(error, "HDF5 cannot take the file image");
  }
  this->File = H5Fopen("in-memory IFEM file", H5F_ACC_RDONLY, access.Get());
  if (this->File < 0)
  {
    return Fail(error, "HDF5 cannot open the file image");
  }
  this->FileBytes = bytes.size();
  return true;
}

//------------------------------------------------------------------------------
bool vtkIFEMFile::Exists(const std::string& path)
{
  if (this->File < 0)
  {
    return false;
  }
  QuietErrors quiet;
  // Each part must be a hard link (H5Lexists needs its parents to exist).
  std::size_t pos = 0;
  while (pos < path.size())
  {
    std::size_t next = path.find('/', pos + 1);
    const std::string part = path.substr(0, next);
    if (part.size() > 1)
    {
      if (H5Lexists(this->File, part.c_str(), H5P_DEFAULT) <= 0)
      {
        return false;
      }
      H5L_info_t info;
      if (H5Lget_info(this->File, part.c_str(), &info, H5P_DEFAULT) < 0 ||
        info.type != H5L_TYPE_HARD)
      {
        return false;
      }
    }
    if (next == std::string::npos)
    {
      break;
    }
    pos = next;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkIFEMFile::ListChildren(const std::string& path, std::vector<std::string>& names,
  std::vector<bool>* isGroup, std::string* error)
{
  names.clear();
  if (isGroup)
  {
    isGroup->clear();
  }
  QuietErrors quiet;
  Handle group(H5Gopen2(this->File, path.c_str(), H5P_DEFAULT), H5Gclose);
  if (!group.Valid())
  {
    return Fail(error, "\"" + path + "\" is not a group");
  }
  H5G_info_t info;
  if (H5Gget_info(group.Get(), &info) < 0)
  {
    return Fail(error, "cannot list the group \"" + path + "\"");
  }
  if (info.nlinks > 10000000)
  {
    return Fail(error, "the group \"" + path + "\" claims too many members");
  }
  for (hsize_t i = 0; i < info.nlinks; ++i)
  {
    const ssize_t length =
      H5Lget_name_by_idx(group.Get(), ".", H5_INDEX_NAME, H5_ITER_INC, i, nullptr, 0, H5P_DEFAULT);
    if (length <= 0 || length > 4096)
    {
      return Fail(error, "a member of the group \"" + path + "\" has no usable name");
    }
    std::string name(static_cast<std::size_t>(length) + 1, '\0');
    H5Lget_name_by_idx(
      group.Get(), ".", H5_INDEX_NAME, H5_ITER_INC, i, &name[0], name.size(), H5P_DEFAULT);
    name.resize(static_cast<std::size_t>(length));
    H5L_info_t linkInfo;
    if (H5Lget_info(group.Get(), name.c_str(), &linkInfo, H5P_DEFAULT) < 0 ||
      linkInfo.type != H5L_TYPE_HARD)
    {
      continue; // soft and external links are not followed
    }
    // The basic information only (the type): the less of a damaged object
    // header HDF5 parses, the fewer of its error paths run.
    // (HDF5 1.12 replaced the 1.10 call and its struct by versions 3 and 2.)
#if H5_VERSION_GE(1, 12, 0)
    H5O_info2_t objectInfo;
    if (H5Oget_info_by_name3(group.Get(), name.c_str(), &objectInfo, H5O_INFO_BASIC, H5P_DEFAULT) <
      0)
#else
    H5O_info_t objectInfo;
    if (H5Oget_info_by_name2(group.Get(), name.c_str(), &objectInfo, H5O_INFO_BASIC, H5P_DEFAULT) <
      0)
#endif
    {
      return Fail(error, "cannot inspect \"" + (path == "/" ? "" : path) + "/" + name + "\"");
    }
    names.push_back(name);
    if (isGroup)
    {
      isGroup->push_back(objectInfo.type == H5O_TYPE_GROUP);
    }
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkIFEMFile::ScanGroup(const std::string& path, Group& group, std::string* error)
{
  std::vector<std::string> names;
  std::vector<bool> isGroup;
  if (!this->ListChildren(path, names, &isGroup, error))
  {
    return false;
  }
  for (std::size_t i = 0; i < names.size(); ++i)
  {
    const std::string& name = names[i];
    if (name == "basis" && isGroup[i])
    {
      std::vector<std::string> patches;
      if (!this->ListChildren(path + "/basis", patches, nullptr, error))
      {
        return false;
      }
      // Patches 1 .. n (other members, e.g. l2g-node, are not patches).
      long long count = 0;
      for (const std::string& p : patches)
      {
        long long v = 0;
        if (IsNonNegativeInteger(p, &v))
        {
          count = std::max(count, v);
        }
      }
      for (long long p = 1; p <= count; ++p)
      {
        if (std::find(patches.begin(), patches.end(), std::to_string(p)) == patches.end())
        {
          return Fail(error,
            "\"" + path + "/basis\" has patches up to " + std::to_string(count) + " but no patch " +
              std::to_string(p));
        }
      }
      if (count == 0)
      {
        return Fail(error, "\"" + path + "/basis\" holds no patch (datasets 1, 2, ...)");
      }
      group.NumberOfBasisPatches = static_cast<int>(count);
    }
    else if ((name == "fields" || name == "knotspan") && isGroup[i])
    {
      std::vector<std::string>& list = name == "fields" ? group.Fields : group.Knotspans;
      std::vector<bool> subGroup;
      if (!this->ListChildren(path + "/" + name, list, &subGroup, error))
      {
        return false;
      }
      for (std::size_t k = list.size(); k-- > 0;)
      {
        if (!subGroup[k])
        {
          list.erase(list.begin() + k); // a field is a group of per-patch datasets
        }
      }
    }
    else
    {
      group.Others.push_back(name);
    }
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkIFEMFile::Scan(std::vector<Level>& levels, std::string* error)
{
  levels.clear();
  if (this->File < 0)
  {
    return Fail(error, "no file is open");
  }
  std::vector<std::string> names;
  std::vector<bool> isGroup;
  if (!this->ListChildren("/", names, &isGroup, error))
  {
    return false;
  }
  long long count = 0;
  for (std::size_t i = 0; i < names.size(); ++i)
  {
    long long v = 0;
    if (IsNonNegativeInteger(names[i], &v) && isGroup[i])
    {
      count = std::max(count, v + 1);
    }
    else if (names[i] != "anasol" && names[i] != "log")
    {
      return Fail(error,
        "the top level holds \"" + names[i] +
          "\", which is not an output level (IFEM's levels are groups named 0, 1, 2, ...)");
    }
  }
  if (count == 0)
  {
    return Fail(error, "the file has no output level (no group named 0 at the top level)");
  }
  levels.resize(static_cast<std::size_t>(count));
  for (long long l = 0; l < count; ++l)
  {
    const std::string path = "/" + std::to_string(l);
    if (std::find(names.begin(), names.end(), std::to_string(l)) == names.end())
    {
      return Fail(error,
        "level " + std::to_string(l) + " is missing (levels go up to " + std::to_string(count - 1) +
          ")");
    }
    std::vector<std::string> groups;
    std::vector<bool> groupIsGroup;
    if (!this->ListChildren(path, groups, &groupIsGroup, error))
    {
      return false;
    }
    Level& level = levels[static_cast<std::size_t>(l)];
    for (std::size_t g = 0; g < groups.size(); ++g)
    {
      if (!groupIsGroup[g])
      {
        continue;
      }
      if (groups[g] == "timeinfo")
      {
        std::vector<double> time;
        if (this->Exists(path + "/timeinfo/level") &&
          this->ReadDoubles(path + "/timeinfo/level", time, error) && !time.empty() &&
          std::isfinite(time[0]))
        {
          level.HasTime = true;
          level.Time = time[0];
        }
        continue;
      }
      if (!this->ScanGroup(path + "/" + groups[g], level.Groups[groups[g]], error))
      {
        return false;
      }
    }
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkIFEMFile::OpenDataset(const std::string& path, Dataset& dataset, std::string* error)
{
  dataset = Dataset();
  if (!this->Exists(path))
  {
    return Fail(error, "\"" + path + "\" does not exist");
  }
  hid_t set = H5Dopen2(this->File, path.c_str(), H5P_DEFAULT);
  if (set < 0)
  {
    return Fail(error, "\"" + path + "\" is not a dataset");
  }
  Handle space(H5Dget_space(set), H5Sclose);
  Handle type(H5Dget_type(set), H5Tclose);
  const hssize_t points = space.Valid() ? H5Sget_simple_extent_npoints(space.Get()) : -1;
  if (!type.Valid() || points < 0)
  {
    H5Dclose(set);
    return Fail(error, "\"" + path + "\" has no usable shape or type");
  }
  const int typeClass = static_cast<int>(H5Tget_class(type.Get()));
  const std::size_t typeSize = H5Tget_size(type.Get());
  const bool isSigned = typeClass == H5T_INTEGER && H5Tget_sign(type.Get()) == H5T_SGN_2;
  const uint64_t count = static_cast<uint64_t>(points);
  // Refuse absurd sizes before allocating: no dataset of an IFEM file
  // (uncompressed doubles and chars) is larger than the file.
  const double bytes = static_cast<double>(count) * 8.0;
  std::string sizeError;
  if (bytes > 64.0 * static_cast<double>(this->FileBytes) + 1048576.0 ||
    !vtkSplineVizProgress::CheckOutputSize(
      static_cast<double>(count), 8.0, ("the dataset \"" + path + "\"").c_str(), &sizeError))
  {
    H5Dclose(set);
    return Fail(error,
      sizeError.empty() ? "the dataset \"" + path + "\" claims " + std::to_string(count) +
          " values, more than a file of " + std::to_string(this->FileBytes) +
          " bytes can hold: refused before allocating"
                        : sizeError);
  }
  dataset.Id = set;
  dataset.Count = count;
  dataset.TypeClass = typeClass;
  dataset.TypeSize = typeSize;
  dataset.IsSigned = isSigned;
  return true;
}

//------------------------------------------------------------------------------
bool vtkIFEMFile::GetNumberOfValues(const std::string& path, uint64_t& count, std::string* error)
{
  QuietErrors quiet;
  Dataset dataset;
  const bool ok = this->OpenDataset(path, dataset, error);
  count = dataset.Count;
  if (ok)
  {
    H5Dclose(dataset.Id);
  }
  return ok;
}

//------------------------------------------------------------------------------
bool vtkIFEMFile::ReadText(const std::string& path, std::string& text, std::string* error)
{
  text.clear();
  QuietErrors quiet;
  Dataset found;
  if (!this->OpenDataset(path, found, error))
  {
    return false;
  }
  Handle dataset(found.Id, H5Dclose);
  if (found.TypeClass != H5T_INTEGER || found.TypeSize != 1)
  {
    return Fail(error, "\"" + path + "\" is not text (IFEM writes patches as 1-byte characters)");
  }
  text.resize(static_cast<std::size_t>(found.Count));
  if (found.Count > 0 &&
    H5Dread(dataset.Get(), found.IsSigned ? H5T_NATIVE_SCHAR : H5T_NATIVE_UCHAR, H5S_ALL, H5S_ALL,
      H5P_DEFAULT, &text[0]) < 0)
  {
    text.clear();
    return Fail(error, "cannot read \"" + path + "\" (the file is damaged?)");
  }
  return true;
}

bool vtkIFEMFile::ReadDoubles(
  const std::string& path, std::vector<double>& values, std::string* error)
{
  values.clear();
  QuietErrors quiet;
  Dataset found;
  if (!this->OpenDataset(path, found, error))
  {
    return false;
  }
  Handle dataset(found.Id, H5Dclose);
  if (found.TypeClass != H5T_INTEGER && found.TypeClass != H5T_FLOAT)
  {
    return Fail(error, "\"" + path + "\" does not hold numbers");
  }
  values.resize(static_cast<std::size_t>(found.Count));
  if (found.Count > 0 &&
    H5Dread(dataset.Get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0)
  {
    values.clear();
    return Fail(error, "cannot read \"" + path + "\" (the file is damaged?)");
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkIFEMFile::LooksLikeIFEM(const char* fileName)
{
  if (!fileName)
  {
    return false;
  }
  vtkIFEMFile file;
  if (!file.Open(fileName, nullptr))
  {
    return false;
  }
  std::vector<std::string> names, groups;
  std::vector<bool> isGroup;
  if (!file.ListChildren("/", names, &isGroup, nullptr) || names.empty())
  {
    return false;
  }
  bool haveZero = false;
  for (std::size_t i = 0; i < names.size(); ++i)
  {
    if (!(IsNonNegativeInteger(names[i], nullptr) && isGroup[i]) && names[i] != "anasol" &&
      names[i] != "log")
    {
      return false;
    }
    haveZero = haveZero || (names[i] == "0" && isGroup[i]);
  }
  if (!haveZero || !file.ListChildren("/0", groups, nullptr, nullptr))
  {
    return false;
  }
  for (const std::string& g : groups)
  {
    if (g != "timeinfo" && file.Exists("/0/" + g + "/basis"))
    {
      return true;
    }
  }
  return false;
}

//------------------------------------------------------------------------------
long vtkIFEMFile::GetNumberOfOpenObjects()
{
  QuietErrors quiet;
  return static_cast<long>(H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL));
}
