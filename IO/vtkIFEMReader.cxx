// SPDX-License-Identifier: BSD-3-Clause
#include "vtkIFEMReader.h"

#include "vtkIFEMBlockBuilder.h"
#include "vtkIFEMFile.h"
#include "vtkLRSplineArrayNames.h"
#include "vtkSplineVizPieces.h"

#include "vtkCompositeDataSet.h"
#include "vtkDataArraySelection.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStringArray.h"
#include "vtkUnstructuredGrid.h"
#include "vtksys/SystemTools.hxx"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <set>
#include <sstream>
#include <tuple>

vtkStandardNewMacro(vtkIFEMReader);

//------------------------------------------------------------------------------
namespace
{
// What RequestData needs for one basis at the level shown.
struct BasisPlan
{
  std::string Name;
  int BasisLevel = -1;
  int Patches = 0;
  // Fields and element fields: name -> (group, level) to read them from.
  std::map<std::string, std::pair<std::string, int>> Fields, Knotspans;
};

}

struct vtkIFEMReader::vtkInternals
{
  vtkIFEMFile File;
  std::string Key; // what the layout was read from
  std::vector<vtkIFEMFile::Level> Levels;
  std::vector<double> Times;
  std::vector<std::string> Bases;   // groups with a basis at some level
  std::vector<std::string> Orphans; // groups with fields but never a basis
  // Parsed patches by (basis, level of the basis, patch, rational mode).
  using PatchKey = std::tuple<std::string, int, int, int>;
  std::map<PatchKey, std::shared_ptr<vtkIFEMBlockBuilder::Patch>> Patches;
  std::set<PatchKey> Used;

  bool GetPatch(const std::string& basis, int basisLevel, int patch, int rationalMode,
    std::shared_ptr<vtkIFEMBlockBuilder::Patch>& out, std::string& error,
    std::vector<std::string>& warnings);
  std::vector<BasisPlan> PlanBases(int level) const;
  void AttachOrphans(
    int level, int rationalMode, std::vector<BasisPlan>& plans, std::vector<std::string>& warnings);
  bool ReadPatchValues(const BasisPlan& plan, int p, vtkDataArraySelection* pointSelection,
    vtkDataArraySelection* cellSelection, std::vector<vtkIFEMBlockBuilder::Values>& fields,
    std::vector<vtkIFEMBlockBuilder::Values>& knotspans, std::string& error);
  void AddGeometryDeviation(const std::string& reference, int referenceLevel, int p,
    int rationalMode, const vtkIFEMBlockBuilder::Patch& patch, const std::string& what,
    vtkUnstructuredGrid* grid, std::vector<std::string>& warnings);
  void WarnUnreadGroups(int level, std::vector<std::string>& warnings) const;

  // The last level <= `level` where `group` wrote its basis, -1 if none.
  int BasisLevel(const std::string& group, int level) const
  {
    for (int l = level; l >= 0; --l)
    {
      auto it = this->Levels[l].Groups.find(group);
      if (it != this->Levels[l].Groups.end() && it->second.NumberOfBasisPatches > 0)
      {
        return l;
      }
    }
    return -1;
  }

  // Per field name of `group`: the last level in [from, level] that wrote it.
  std::map<std::string, int> FieldLevels(
    const std::string& group, int from, int level, bool knotspan) const
  {
    std::map<std::string, int> found;
    for (int l = level; l >= std::max(from, 0); --l)
    {
      auto it = this->Levels[l].Groups.find(group);
      if (it == this->Levels[l].Groups.end())
      {
        continue;
      }
      for (const std::string& name : knotspan ? it->second.Knotspans : it->second.Fields)
      {
        found.emplace(name, l); // the latest level wins (visited first)
      }
    }
    return found;
  }
};

namespace
{
void AddString(vtkFieldData* fd, const char* name, const std::string& value)
{
  vtkNew<vtkStringArray> a;
  a->SetName(name);
  a->InsertNextValue(value);
  fd->AddArray(a);
}

void AddNumber(vtkFieldData* fd, const char* name, double value, bool integer)
{
  if (integer)
  {
    vtkNew<vtkIntArray> a;
    a->SetName(name);
    a->InsertNextValue(static_cast<int>(value));
    fd->AddArray(a);
  }
  else
  {
    vtkNew<vtkDoubleArray> a;
    a->SetName(name);
    a->InsertNextValue(value);
    fd->AddArray(a);
  }
}

// "<Sim>-<b>" with b > 1 (or "proj") -> "<Sim>-1"; empty otherwise.
std::string ReferenceBasis(const std::string& name)
{
  const std::size_t dash = name.rfind('-');
  if (dash == std::string::npos || dash + 1 >= name.size())
  {
    return std::string();
  }
  const std::string tail = name.substr(dash + 1);
  if (tail == "1")
  {
    return std::string();
  }
  const bool number = std::all_of(tail.begin(), tail.end(), ::isdigit);
  return (number || tail == "proj") ? name.substr(0, dash) + "-1" : std::string();
}

std::string Quote(const std::string& path)
{
  return "\"" + path + "\"";
}
}

//------------------------------------------------------------------------------
vtkIFEMReader::vtkIFEMReader()
  : Internals(new vtkInternals)
{
  this->SetNumberOfInputPorts(0);
  this->PointSelection = vtkDataArraySelection::New();
  this->CellSelection = vtkDataArraySelection::New();
  this->BasisSelection = vtkDataArraySelection::New();
}

vtkIFEMReader::~vtkIFEMReader()
{
  this->SetFileName(nullptr);
  this->PointSelection->Delete();
  this->CellSelection->Delete();
  this->BasisSelection->Delete();
}

vtkMTimeType vtkIFEMReader::GetMTime()
{
  vtkMTimeType t = this->Superclass::GetMTime();
  t = std::max(t, this->PointSelection->GetMTime());
  t = std::max(t, this->CellSelection->GetMTime());
  return std::max(t, this->BasisSelection->GetMTime());
}

void vtkIFEMReader::SetInputString(const char* data, std::size_t length)
{
  std::string s = data ? std::string(data, length) : std::string();
  if (s != this->InputString)
  {
    this->InputString.swap(s);
    this->Modified();
  }
}

//------------------------------------------------------------------------------
// The array selections (ParaView's ArraySelectionInformationHelper API).
#define SV_SELECTION(Kind, member)                                                                 \
  int vtkIFEMReader::GetNumberOf##Kind##Arrays()                                                   \
  {                                                                                                \
    return this->member->GetNumberOfArrays();                                                      \
  }                                                                                                \
  const char* vtkIFEMReader::Get##Kind##ArrayName(int index)                                       \
  {                                                                                                \
    return this->member->GetArrayName(index);                                                      \
  }                                                                                                \
  int vtkIFEMReader::Get##Kind##ArrayStatus(const char* name)                                      \
  {                                                                                                \
    return this->member->ArrayIsEnabled(name);                                                     \
  }                                                                                                \
  void vtkIFEMReader::Set##Kind##ArrayStatus(const char* name, int status)                         \
  {                                                                                                \
    if (status)                                                                                    \
    {                                                                                              \
      this->member->EnableArray(name);                                                             \
    }                                                                                              \
    else                                                                                           \
    {                                                                                              \
      this->member->DisableArray(name);                                                            \
    }                                                                                              \
  }
SV_SELECTION(Point, PointSelection)
SV_SELECTION(Cell, CellSelection)
SV_SELECTION(Basis, BasisSelection)
#undef SV_SELECTION

int vtkIFEMReader::GetNumberOfTimeSteps()
{
  return static_cast<int>(this->Internals->Times.size());
}

double vtkIFEMReader::GetTimeStep(int index)
{
  return index >= 0 && index < this->GetNumberOfTimeSteps() ? this->Internals->Times[index] : 0.0;
}

int vtkIFEMReader::CanReadFile(const char* fileName)
{
  return vtkIFEMFile::LooksLikeIFEM(fileName) ? 1 : 0;
}

int vtkIFEMReader::Fail(const std::string& message)
{
  this->LastError = message;
  vtkErrorMacro(<< message);
  return 0;
}

//------------------------------------------------------------------------------
bool vtkIFEMReader::UpdateLayout(std::string* error)
{
  vtkInternals& in = *this->Internals;
  std::ostringstream key;
  if (this->ReadFromInputString)
  {
    key << "memory:" << this->InputString.size() << ":"
        << std::hash<std::string>()(this->InputString);
  }
  else
  {
    if (!this->FileName || !*this->FileName)
    {
      *error = "no file name was given";
      return false;
    }
    key << "file:" << this->FileName << ":" << vtksys::SystemTools::ModifiedTime(this->FileName)
        << ":" << vtksys::SystemTools::FileLength(this->FileName);
  }
  if (key.str() == in.Key && in.File.IsOpen())
  {
    return true;
  }
  in.Key.clear();
  in.Levels.clear();
  in.Times.clear();
  in.Bases.clear();
  in.Orphans.clear();
  in.Patches.clear();
  const bool opened = this->ReadFromInputString ? in.File.OpenImage(this->InputString, error)
                                                : in.File.Open(this->FileName, error);
  if (!opened || !in.File.Scan(in.Levels, error))
  {
    in.File.Close();
    in.Levels.clear();
    return false;
  }
  // Times: timeinfo when every level has an increasing one, else the level numbers.
  bool useTimes = true;
  for (std::size_t l = 0; l < in.Levels.size(); ++l)
  {
    useTimes =
      useTimes && in.Levels[l].HasTime && (l == 0 || in.Levels[l].Time > in.Levels[l - 1].Time);
  }
  std::set<std::string> bases, groups, fields, knotspans;
  for (std::size_t l = 0; l < in.Levels.size(); ++l)
  {
    in.Times.push_back(useTimes ? in.Levels[l].Time : static_cast<double>(l));
    for (const auto& g : in.Levels[l].Groups)
    {
      groups.insert(g.first);
      if (g.second.NumberOfBasisPatches > 0)
      {
        bases.insert(g.first);
      }
      fields.insert(g.second.Fields.begin(), g.second.Fields.end());
      knotspans.insert(g.second.Knotspans.begin(), g.second.Knotspans.end());
    }
  }
  if (bases.empty())
  {
    *error = "no basis group holds patches (no <level>/<name>/basis/1)";
    in.File.Close();
    return false;
  }
  in.Bases.assign(bases.begin(), bases.end());
  std::set_difference(
    groups.begin(), groups.end(), bases.begin(), bases.end(), std::back_inserter(in.Orphans));
  for (const std::string& b : in.Bases)
  {
    this->BasisSelection->AddArray(b.c_str());
  }
  for (const std::string& f : fields)
  {
    this->PointSelection->AddArray(f.c_str());
  }
  for (const std::string& f : knotspans)
  {
    this->CellSelection->AddArray(f.c_str());
  }
  in.Key = key.str();
  return true;
}

//------------------------------------------------------------------------------
int vtkIFEMReader::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  this->LastError.clear();
  std::string error;
  const std::string name = this->ReadFromInputString
    ? std::string("the input string")
    : std::string(this->FileName ? this->FileName : "(none)");
  if (!this->UpdateLayout(&error))
  {
    return this->Fail("cannot read \"" + name + "\": " + error);
  }
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  const std::vector<double>& times = this->Internals->Times;
  outInfo->Set(
    vtkStreamingDemandDrivenPipeline::TIME_STEPS(), times.data(), static_cast<int>(times.size()));
  const double range[2] = { times.front(), times.back() };
  outInfo->Set(vtkStreamingDemandDrivenPipeline::TIME_RANGE(), range, 2);
  outInfo->Set(CAN_HANDLE_PIECE_REQUEST(), 1);
  return 1;
}

//------------------------------------------------------------------------------
namespace
{
// The level shown: the last one whose time is not after the requested time.
int RequestedLevel(vtkInformation* outInfo, const std::vector<double>& times)
{
  int level = 0;
  if (outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP()))
  {
    const double t = outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP());
    for (std::size_t l = 0; l < times.size(); ++l)
    {
      const double tol = 1e-12 * std::max(1.0, std::abs(times[l]));
      if (times[l] <= t + tol)
      {
        level = static_cast<int>(l);
      }
    }
  }
  return level;
}
}

//------------------------------------------------------------------------------
// The parsed basis patch (cached per basis, level of the basis, patch and
// rational mode; marked used for this request). On failure `error` says why.
bool vtkIFEMReader::vtkInternals::GetPatch(const std::string& basis, int basisLevel, int patch,
  int rationalMode, std::shared_ptr<vtkIFEMBlockBuilder::Patch>& out, std::string& error,
  std::vector<std::string>& warnings)
{
  const PatchKey key(basis, basisLevel, patch, rationalMode);
  this->Used.insert(key);
  auto it = this->Patches.find(key);
  if (it != this->Patches.end())
  {
    out = it->second;
    return true;
  }
  const std::string path =
    "/" + std::to_string(basisLevel) + "/" + basis + "/basis/" + std::to_string(patch);
  std::string text, warning;
  auto parsed = std::make_shared<vtkIFEMBlockBuilder::Patch>();
  if (!this->File.ReadText(path, text, &error) ||
    !vtkIFEMBlockBuilder::ParsePatch(text, rationalMode, *parsed, &error, &warning))
  {
    error = Quote(path) + ": " + error;
    return false;
  }
  if (!warning.empty())
  {
    warnings.push_back(Quote(path) + ": " + warning);
  }
  this->Patches[key] = parsed;
  out = parsed;
  return true;
}

//------------------------------------------------------------------------------
// Each basis written at or before `level`, with its fields (own, not yet
// the orphans').
std::vector<BasisPlan> vtkIFEMReader::vtkInternals::PlanBases(int level) const
{
  std::vector<BasisPlan> plans;
  for (const std::string& b : this->Bases)
  {
    BasisPlan plan;
    plan.Name = b;
    plan.BasisLevel = this->BasisLevel(b, level);
    if (plan.BasisLevel < 0)
    {
      continue; // written first at a later level
    }
    plan.Patches = this->Levels[plan.BasisLevel].Groups.at(b).NumberOfBasisPatches;
    for (const auto& f : this->FieldLevels(b, plan.BasisLevel, level, false))
    {
      plan.Fields[f.first] = { b, f.second };
    }
    for (const auto& f : this->FieldLevels(b, plan.BasisLevel, level, true))
    {
      plan.Knotspans[f.first] = { b, f.second };
    }
    plans.push_back(plan);
  }
  return plans;
}

// Groups without a basis of their own: their fields go to the one basis
// their sizes fit (one dataset per patch, sizes multiples of the patch's
// nodes or elements); none or several: a warning, not read.
void vtkIFEMReader::vtkInternals::AttachOrphans(
  int level, int rationalMode, std::vector<BasisPlan>& plans, std::vector<std::string>& warnings)
{
  for (const std::string& orphan : this->Orphans)
  {
    const auto fields = this->FieldLevels(orphan, 0, level, false);
    const auto knotspans = this->FieldLevels(orphan, 0, level, true);
    if (fields.empty() && knotspans.empty())
    {
      continue;
    }
    auto fits = [&](const BasisPlan& plan)
    {
      std::string ignored;
      for (int k = 0; k < 2; ++k)
      {
        for (const auto& f : k == 0 ? fields : knotspans)
        {
          const std::string base = "/" + std::to_string(f.second) + "/" + orphan +
            (k == 0 ? "/fields/" : "/knotspan/") + f.first + "/";
          if (this->File.Exists(base + std::to_string(plan.Patches + 1)))
          {
            return false;
          }
          for (int p = 1; p <= plan.Patches; ++p)
          {
            std::shared_ptr<vtkIFEMBlockBuilder::Patch> patch;
            uint64_t count = 0;
            if (!this->GetPatch(
                  plan.Name, plan.BasisLevel, p, rationalMode, patch, ignored, warnings) ||
              !this->File.GetNumberOfValues(base + std::to_string(p), count, nullptr))
            {
              return false;
            }
            const vtkIdType n = k == 0 ? patch->GetNumberOfNodes() : patch->GetNumberOfElements();
            if (count % static_cast<uint64_t>(n) != 0)
            {
              return false;
            }
          }
        }
      }
      return true;
    };
    std::vector<BasisPlan*> matches;
    for (BasisPlan& plan : plans)
    {
      if (fits(plan))
      {
        matches.push_back(&plan);
      }
    }
    if (matches.size() != 1)
    {
      warnings.push_back("the fields of \"" + orphan +
        "\" (a group without a basis of its own) fit " + std::to_string(matches.size()) +
        " bases instead of one: they are not read");
      continue;
    }
    for (const auto& f : fields)
    {
      matches[0]->Fields.emplace(f.first, std::make_pair(orphan, f.second));
    }
    for (const auto& f : knotspans)
    {
      matches[0]->Knotspans.emplace(f.first, std::make_pair(orphan, f.second));
    }
  }
}

// The enabled fields (k = 0, nodal) and element fields (k = 1) of `plan` on
// patch p; records not written for the patch, or empty (IFEM's inactive
// patches), are left out. On failure `error` names the dataset.
bool vtkIFEMReader::vtkInternals::ReadPatchValues(const BasisPlan& plan, int p,
  vtkDataArraySelection* pointSelection, vtkDataArraySelection* cellSelection,
  std::vector<vtkIFEMBlockBuilder::Values>& fields,
  std::vector<vtkIFEMBlockBuilder::Values>& knotspans, std::string& error)
{
  for (int k = 0; k < 2; ++k)
  {
    const auto& list = k == 0 ? plan.Fields : plan.Knotspans;
    vtkDataArraySelection* selection = k == 0 ? pointSelection : cellSelection;
    for (const auto& f : list)
    {
      if (!selection->ArrayIsEnabled(f.first.c_str()))
      {
        continue;
      }
      const std::string path = "/" + std::to_string(f.second.second) + "/" + f.second.first +
        (k == 0 ? "/fields/" : "/knotspan/") + f.first + "/" + std::to_string(p);
      if (!this->File.Exists(path))
      {
        continue; // not written for this patch
      }
      vtkIFEMBlockBuilder::Values values;
      values.Name = f.first;
      if (!this->File.ReadDoubles(path, values.Data, &error))
      {
        error = Quote(path) + ": " + error;
        return false;
      }
      if (!values.Data.empty())
      {
        (k == 0 ? fields : knotspans).push_back(std::move(values));
      }
    }
  }
  return true;
}

// Mixed methods: how far the geometry of `patch` (basis `what`) is from the
// reference basis' patch, as field data; a warning when it is not the same.
void vtkIFEMReader::vtkInternals::AddGeometryDeviation(const std::string& reference,
  int referenceLevel, int p, int rationalMode, const vtkIFEMBlockBuilder::Patch& patch,
  const std::string& what, vtkUnstructuredGrid* grid, std::vector<std::string>& warnings)
{
  std::shared_ptr<vtkIFEMBlockBuilder::Patch> ref;
  std::string error;
  if (referenceLevel < 0 || patch.IsLagrange ||
    p > this->Levels[referenceLevel].Groups.at(reference).NumberOfBasisPatches ||
    !this->GetPatch(reference, referenceLevel, p, rationalMode, ref, error, warnings) ||
    ref->IsLagrange)
  {
    return;
  }
  double deviation = 0.0;
  if (!vtkIFEMBlockBuilder::GeometryDeviation(*ref, patch, deviation, &error))
  {
    return;
  }
  vtkFieldData* fd = grid->GetFieldData();
  AddString(fd, vtkLRSplineArrayNames::GeometryReferenceBasis, reference);
  AddNumber(fd, vtkLRSplineArrayNames::GeometryDeviation, deviation, false);
  const double size = std::sqrt(grid->GetLength2());
  if (!(deviation <= 1e-9 * std::max(size, 1e-300)))
  {
    std::ostringstream msg;
    msg << what << ": its geometry differs from that of \"" << reference << "\" by " << deviation
        << " (the basis does not contain the geometry map); its fields "
        << "are drawn on its own geometry";
    warnings.push_back(msg.str());
  }
}

// Groups of `level` the reader leaves out, as warnings.
void vtkIFEMReader::vtkInternals::WarnUnreadGroups(
  int level, std::vector<std::string>& warnings) const
{
  for (const auto& groupLevel : this->Levels[level].Groups)
  {
    for (const std::string& other : groupLevel.second.Others)
    {
      if (other != "l2g-node")
      {
        warnings.push_back("\"" + groupLevel.first + "/" + other + "\" is not read (" +
          (other == "Eigenmode" ? "eigenmode files are not supported" : "unknown group") + ")");
      }
    }
  }
}

//------------------------------------------------------------------------------
int vtkIFEMReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkMultiBlockDataSet* output = vtkMultiBlockDataSet::GetData(outInfo);
  this->LastError.clear();
  vtkInternals& in = *this->Internals;
  const std::string name = this->ReadFromInputString
    ? std::string("the input string")
    : std::string(this->FileName ? this->FileName : "(none)");
  const std::string where = "cannot read \"" + name + "\": ";
  std::string error;
  if (!this->UpdateLayout(&error))
  {
    return this->Fail(where + error);
  }
  const int level = RequestedLevel(outInfo, in.Times);
  int piece = 0, numPieces = 1;
  vtkSplineVizPieces::GetRequested(outInfo, piece, numPieces);

  // Plans: each basis with its fields (own and attached).
  std::vector<std::string> warnings;
  in.Used.clear();
  std::vector<BasisPlan> plans = in.PlanBases(level);
  in.AttachOrphans(level, this->RationalMode, plans, warnings);

  // The blocks: per enabled basis, one grid per patch (this piece's elements).
  unsigned int block = 0;
  int done = 0, total = 0;
  for (const BasisPlan& plan : plans)
  {
    total += this->BasisSelection->ArrayIsEnabled(plan.Name.c_str()) ? plan.Patches : 0;
  }
  for (const BasisPlan& plan : plans)
  {
    if (!this->BasisSelection->ArrayIsEnabled(plan.Name.c_str()))
    {
      continue;
    }
    vtkNew<vtkMultiBlockDataSet> patches;
    patches->SetNumberOfBlocks(static_cast<unsigned int>(plan.Patches));
    const std::string reference = ReferenceBasis(plan.Name);
    const int referenceLevel = reference.empty() ? -1 : in.BasisLevel(reference, level);
    for (int p = 1; p <= plan.Patches; ++p)
    {
      if (this->CheckAbort())
      {
        output->Initialize();
        return 1;
      }
      this->UpdateProgress(static_cast<double>(done++) / std::max(1, total));
      std::shared_ptr<vtkIFEMBlockBuilder::Patch> patch;
      std::vector<vtkIFEMBlockBuilder::Values> fields, knotspans;
      if (!in.GetPatch(plan.Name, plan.BasisLevel, p, this->RationalMode, patch, error, warnings) ||
        !in.ReadPatchValues(
          plan, p, this->PointSelection, this->CellSelection, fields, knotspans, error))
      {
        output->Initialize();
        return this->Fail(where + error);
      }
      vtkIFEMBlockBuilder::Options options;
      options.MergePoints = this->MergePoints != 0;
      options.PatchIndex = p - 1;
      const vtkIdType ne = patch->GetNumberOfElements();
      options.FirstElement = ne * piece / numPieces;
      options.LastElement = ne * (piece + 1) / numPieces;
      std::string warning;
      vtkSmartPointer<vtkUnstructuredGrid> grid =
        vtkIFEMBlockBuilder::Build(*patch, fields, knotspans, options, &error, &warning);
      const std::string what = "basis \"" + plan.Name + "\" (level " +
        std::to_string(plan.BasisLevel) + "), patch " + std::to_string(p);
      if (!grid)
      {
        output->Initialize();
        return this->Fail(where + what + ": " + error);
      }
      if (!warning.empty())
      {
        warnings.push_back(what + ": " + warning);
      }
      vtkFieldData* fd = grid->GetFieldData();
      AddString(fd, "IFEMBasis", plan.Name);
      AddNumber(fd, "IFEMPatch", p, true);
      AddNumber(fd, "IFEMLevel", level, true);
      AddNumber(fd, "IFEMBasisLevel", plan.BasisLevel, true);
      AddNumber(fd, "IFEMTime", in.Times[level], false);
      AddNumber(fd, "IFEMSpatialDimension", patch->SpatialDimension, true);
      in.AddGeometryDeviation(
        reference, referenceLevel, p, this->RationalMode, *patch, what, grid, warnings);
      patches->SetBlock(static_cast<unsigned int>(p - 1), grid);
      patches->GetMetaData(static_cast<unsigned int>(p - 1))
        ->Set(vtkCompositeDataSet::NAME(), ("Patch " + std::to_string(p)).c_str());
    }
    output->SetBlock(block, patches);
    output->GetMetaData(block)->Set(vtkCompositeDataSet::NAME(), plan.Name.c_str());
    ++block;
  }
  in.WarnUnreadGroups(level, warnings);
  for (const std::string& w : warnings)
  {
    vtkWarningMacro(<< "\"" << name << "\": " << w);
  }
  // Keep the parsed patches of this level only.
  for (auto it = in.Patches.begin(); it != in.Patches.end();)
  {
    it = in.Used.count(it->first) ? std::next(it) : in.Patches.erase(it);
  }
  output->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(), in.Times[level]);
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkIFEMReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "ReadFromInputString: " << this->ReadFromInputString << " ("
     << this->InputString.size() << " bytes)\n";
  os << indent << "RationalMode: " << this->RationalMode << "\n";
  os << indent << "MergePoints: " << this->MergePoints << "\n";
  os << indent << "Bases: " << this->BasisSelection->GetNumberOfArrays()
     << ", nodal fields: " << this->PointSelection->GetNumberOfArrays()
     << ", element fields: " << this->CellSelection->GetNumberOfArrays() << "\n";
}
