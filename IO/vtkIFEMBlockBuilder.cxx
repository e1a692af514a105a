// SPDX-License-Identifier: BSD-3-Clause
#include "vtkIFEMBlockBuilder.h"
#include "vtkSplineVizError.h"

#include "vtkLRSplineArrayNames.h"
#include "vtkLRSplineBezierVolume.h"
#include "vtkLRSplineElementLocator.h"
#include "vtkLRSplineParser.h"
#include "vtkSplineVizProgress.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <sstream>

namespace
{
using PointArray = vtkLRSplineBezierGrid::Options::PointArray;

using vtkSplineVizError::Fail;

std::string Trim(const std::string& s)
{
  const std::size_t b = s.find_first_not_of(" \t");
  const std::size_t e = s.find_last_not_of(" \t");
  return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}

// The fields side by side: rows x width values, and their arrays (components
// counted from `offset`). Checks each field's size against `rows` and its values.
bool CombineFields(const std::vector<vtkIFEMBlockBuilder::Values>& fields, vtkIdType rows,
  const char* what, int offset, std::vector<double>& table, int& width,
  std::vector<PointArray>& arrays, std::string* error, std::string* warning)
{
  std::vector<int> components;
  width = 0;
  for (const auto& f : fields)
  {
    const std::size_t n = f.Data.size();
    if (rows < 1 || n == 0 || n % static_cast<std::size_t>(rows) != 0)
    {
      return Fail(error,
        std::string(what) + " \"" + f.Name + "\" has " + std::to_string(n) +
          " values, which is not a positive multiple of the " + std::to_string(rows) +
          (std::string(what) == "field" ? " basis functions or nodes" : " elements") +
          " of its patch");
    }
    components.push_back(static_cast<int>(n / static_cast<std::size_t>(rows)));
    if (components.back() > 64)
    {
      return Fail(error, std::string(what) + " \"" + f.Name + "\" has more than 64 components");
    }
    const std::size_t bad = static_cast<std::size_t>(
      std::count_if(f.Data.begin(), f.Data.end(), [](double v) { return !std::isfinite(v); }));
    if (bad > 0 && warning)
    {
      // Simulations write NaN for undefined values (e.g. error estimates):
      // kept, they spoil only the elements where their basis functions live.
      *warning += (warning->empty() ? "" : "; ") + std::string(what) + " \"" + f.Name + "\" has " +
        std::to_string(bad) + " values that are not finite numbers (kept as they are)";
    }
    width += components.back();
  }
  std::string sizeError;
  if (!vtkSplineVizProgress::CheckOutputSize(
        static_cast<double>(rows) * width, 8.0, "the fields of a patch", &sizeError))
  {
    return Fail(error, sizeError);
  }
  table.assign(static_cast<std::size_t>(rows) * width, 0.0);
  int first = 0;
  for (std::size_t k = 0; k < fields.size(); ++k)
  {
    const int nc = components[k];
    for (vtkIdType r = 0; r < rows; ++r)
    {
      std::copy(fields[k].Data.begin() + r * nc, fields[k].Data.begin() + (r + 1) * nc,
        table.begin() + r * width + first);
    }
    for (PointArray a : vtkIFEMBlockBuilder::ArraysFor(fields[k].Name, nc))
    {
      for (int& c : a.Components)
      {
        c += offset + first;
      }
      arrays.push_back(a);
    }
    first += nc;
  }
  return true;
}

// Arrays of `specs` (components of `table`, `width` per row) for the given rows.
void AddArraysFromTable(vtkDataSetAttributes* attributes, const std::vector<PointArray>& specs,
  const std::vector<double>& table, int width, const std::vector<vtkIdType>& rows)
{
  for (const PointArray& spec : specs)
  {
    const int n = std::max(static_cast<int>(spec.Components.size()), spec.NumberOfComponents);
    vtkNew<vtkDoubleArray> array;
    array->SetName(spec.Name.c_str());
    array->SetNumberOfComponents(n);
    array->SetNumberOfTuples(static_cast<vtkIdType>(rows.size()));
    for (std::size_t i = 0; i < rows.size(); ++i)
    {
      for (int c = 0; c < n; ++c)
      {
        array->SetTypedComponent(static_cast<vtkIdType>(i), c,
          c < static_cast<int>(spec.Components.size())
            ? table[static_cast<std::size_t>(rows[i]) * width + spec.Components[c]]
            : 0.0);
      }
    }
    attributes->AddArray(array);
    if (spec.Active == 3)
    {
      attributes->SetActiveVectors(spec.Name.c_str());
    }
    else if (spec.Active == 1)
    {
      attributes->SetActiveScalars(spec.Name.c_str());
    }
  }
}

// The first array becomes the active scalars or vectors (the default field).
void MarkFirstActive(std::vector<PointArray>& arrays)
{
  for (PointArray& a : arrays)
  {
    const int n = std::max(static_cast<int>(a.Components.size()), a.NumberOfComponents);
    if (n == 1 || n == 3)
    {
      a.Active = n;
      return;
    }
  }
}
}

//------------------------------------------------------------------------------
vtkIdType vtkIFEMBlockBuilder::Patch::GetNumberOfNodes() const
{
  return this->IsLagrange ? this->Lagrange.GetNumberOfNodes()
                          : this->Spline.GetNumberOfBasisFunctions();
}

vtkIdType vtkIFEMBlockBuilder::Patch::GetNumberOfElements() const
{
  return this->IsLagrange ? this->Lagrange.GetNumberOfElements()
                          : this->Spline.GetNumberOfElements();
}

//------------------------------------------------------------------------------
std::vector<PointArray> vtkIFEMBlockBuilder::ArraysFor(const std::string& name, int components)
{
  std::vector<PointArray> arrays;
  auto scalar = [&arrays](const std::string& n, int c)
  {
    PointArray a;
    a.Name = n;
    a.Components = { c };
    arrays.push_back(a);
  };
  if (name.find("&&") != std::string::npos)
  {
    std::vector<std::string> parts;
    std::size_t start = 0;
    for (;;)
    {
      const std::size_t at = name.find("&&", start);
      parts.push_back(Trim(name.substr(start, at == std::string::npos ? at : at - start)));
      if (at == std::string::npos)
      {
        break;
      }
      start = at + 2;
    }
    const std::size_t space = parts[0].find(' ');
    if (space != std::string::npos)
    {
      const std::string prefix = parts[0].substr(0, space);
      parts[0] = parts[0].substr(space + 1);
      for (std::string& p : parts)
      {
        p = prefix + " " + p;
      }
    }
    if (static_cast<int>(parts.size()) == components)
    {
      for (int c = 0; c < components; ++c)
      {
        scalar(parts[c], c);
      }
      return arrays;
    }
  }
  if (components == 1)
  {
    scalar(name, 0);
  }
  else if (components <= 3)
  {
    PointArray v;
    v.Name = name;
    for (int c = 0; c < components; ++c)
    {
      v.Components.push_back(c);
      scalar(name + "_" + "xyz"[c], c);
    }
    v.NumberOfComponents = 3;
    arrays.insert(arrays.begin(), v);
  }
  else
  {
    for (int c = 0; c < components; ++c)
    {
      scalar(name + "_" + std::to_string(c), c);
    }
  }
  return arrays;
}

//------------------------------------------------------------------------------
void vtkIFEMBlockBuilder::AddRecombinedVectors(std::vector<PointArray>& arrays)
{
  std::set<std::string> names;
  for (const PointArray& a : arrays)
  {
    names.insert(a.Name);
  }
  std::vector<PointArray> added;
  for (const PointArray& a : arrays)
  {
    const std::string& n = a.Name;
    if (n.size() < 3 || n.compare(n.size() - 2, 2, "_x") != 0 || a.Components.size() != 1)
    {
      continue;
    }
    const std::string base = n.substr(0, n.size() - 2);
    if (names.count(base))
    {
      continue;
    }
    PointArray v;
    v.Name = base;
    v.NumberOfComponents = 3;
    for (int d = 0; d < 3; ++d)
    {
      const std::string want = base + "_" + "xyz"[d];
      auto it = std::find_if(arrays.begin(), arrays.end(),
        [&want](const PointArray& b) { return b.Name == want && b.Components.size() == 1; });
      if (it == arrays.end())
      {
        break; // x and y at least; z when present
      }
      v.Components.push_back(it->Components[0]);
    }
    if (v.Components.size() >= 2)
    {
      names.insert(base);
      added.push_back(v);
    }
  }
  arrays.insert(arrays.end(), added.begin(), added.end());
}

//------------------------------------------------------------------------------
bool vtkIFEMBlockBuilder::ParsePatch(
  const std::string& text, int rationalMode, Patch& patch, std::string* error, std::string* warning)
{
  if (warning)
  {
    warning->clear();
  }
  const std::size_t start = text.find_first_not_of(" \t\r\n");
  if (start != std::string::npos && text.compare(start, 12, "# LAGRANGIAN") == 0)
  {
    patch.IsLagrange = true;
    patch.SpatialDimension = 3;
    patch.Format = "IFEM Lagrange";
    return patch.Lagrange.Parse(text.substr(start), error);
  }
  patch.IsLagrange = false;
  std::vector<vtkLRSplinePatch> patches;
  const int format = vtkLRSplineParser::DetectFormat(text);
  if (format == vtkLRSplineParser::AUTOMATIC)
  {
    return Fail(error,
      "unknown patch text: neither LRSplines (\"# LRSPLINE\"), GoTools g2 (a class number) nor "
      "Lagrange (\"# LAGRANGIAN\")");
  }
  if (!vtkLRSplineParser::Parse(text, format, patches, error))
  {
    return false;
  }
  if (patches.size() != 1)
  {
    return Fail(
      error, "the patch text holds " + std::to_string(patches.size()) + " patches instead of one");
  }
  patch.Spline = std::move(patches[0]);
  patch.Format = format == vtkLRSplineParser::G2 ? "GoTools g2" : "LRSplines text";
  bool inferred = false;
  if (!patch.Spline.ApplyRationalMode(rationalMode, true, &inferred, error) ||
    !patch.Spline.Validate(error))
  {
    return false;
  }
  const int nsd = patch.Spline.GetNumberOfCartesianComponents();
  const int pd = patch.Spline.ParametricDimension;
  if (nsd < pd || nsd > 3)
  {
    return Fail(error,
      "the geometry has " + std::to_string(nsd) + " coordinates" +
        (patch.Spline.RationalCoefficients ? " (and a weight)" : "") + "; a patch of " +
        std::to_string(pd) + " parametric directions needs " + std::to_string(pd) +
        " to 3 (see RationalMode)");
  }
  patch.SpatialDimension = nsd;
  if (inferred && warning)
  {
    std::ostringstream msg;
    msg << "an LR patch with " << patch.Spline.Dimension << " components and " << pd
        << " parametric directions is read as rational (the last component is the weight, "
        << "SISO's rule); set RationalMode to Polynomial if it is not";
    *warning = msg.str();
  }
  return true;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkUnstructuredGrid> vtkIFEMBlockBuilder::Build(const Patch& patch,
  const std::vector<Values>& fields, const std::vector<Values>& knotspans, const Options& options,
  std::string* error, std::string* warning)
{
  if (warning)
  {
    warning->clear();
  }
  const vtkIdType ne = patch.GetNumberOfElements();
  vtkIdType first = std::max<vtkIdType>(0, std::min(options.FirstElement, ne));
  vtkIdType last = options.LastElement < 0 ? ne : std::min(options.LastElement, ne);
  last = std::max(first, last);
  Options range = options;
  range.FirstElement = first;
  range.LastElement = last;
  vtkSmartPointer<vtkUnstructuredGrid> grid = patch.IsLagrange
    ? BuildLagrange(patch, fields, range, error, warning)
    : BuildSpline(patch, fields, range, error, warning);
  if (!grid)
  {
    return nullptr;
  }
  std::vector<vtkIdType> elementIds;
  vtkDataArray* ids = grid->GetCellData()->GetArray(vtkLRSplineArrayNames::ElementId);
  for (vtkIdType c = 0; ids && c < ids->GetNumberOfTuples(); ++c)
  {
    elementIds.push_back(static_cast<vtkIdType>(ids->GetComponent(c, 0)));
  }
  if (!AddCellValues(grid, knotspans, ne, elementIds, error, warning))
  {
    return nullptr;
  }
  return grid;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkUnstructuredGrid> vtkIFEMBlockBuilder::BuildSpline(const Patch& patch,
  const std::vector<Values>& fields, const Options& options, std::string* error,
  std::string* warning)
{
  const vtkLRSplinePatch& spline = patch.Spline;
  const vtkIdType nb = spline.GetNumberOfBasisFunctions();
  const int dim = spline.Dimension;
  const bool rational = spline.RationalCoefficients;
  const int nsd = patch.SpatialDimension;
  const int geometryWidth = nsd + (rational ? 1 : 0);
  std::vector<double> table;
  int fieldWidth = 0;
  std::vector<PointArray> arrays;
  if (!CombineFields(fields, nb, "field", geometryWidth, table, fieldWidth, arrays, error, warning))
  {
    return nullptr;
  }
  // The combined coefficients: geometry (homogeneous when rational), weight, fields (times
  // the weight when rational).
  const int width = geometryWidth + fieldWidth;
  std::vector<double> coefficients(static_cast<std::size_t>(nb) * width);
  for (vtkIdType i = 0; i < nb; ++i)
  {
    const double* c = spline.Coefficients.data() + static_cast<std::size_t>(i) * dim;
    double* out = coefficients.data() + static_cast<std::size_t>(i) * width;
    const double w = rational ? c[dim - 1] : 1.0;
    std::copy(c, c + nsd, out);
    if (rational)
    {
      out[nsd] = w;
    }
    for (int k = 0; k < fieldWidth; ++k)
    {
      out[geometryWidth + k] = w * table[static_cast<std::size_t>(i) * fieldWidth + k];
    }
  }
  std::vector<double>().swap(table);
  vtkLRSplineBezierVolume volume;
  std::string extractWarning;
  if (!spline.ExtractBezier(volume, error, &extractWarning, options.FirstElement,
        options.LastElement, coefficients.data(), width))
  {
    return nullptr;
  }
  if (warning && !extractWarning.empty())
  {
    *warning += (warning->empty() ? "" : "; ") + extractWarning;
  }
  std::vector<double>().swap(coefficients);
  if (rational && !volume.Dehomogenize(nsd, error))
  {
    return nullptr;
  }
  AddRecombinedVectors(arrays);
  MarkFirstActive(arrays);
  vtkLRSplineBezierGrid::Options gridOptions;
  gridOptions.GeometryMode = true;
  gridOptions.PointComponents[0] = 0;
  gridOptions.PointComponents[1] = nsd >= 2 ? 1 : -1;
  gridOptions.PointComponents[2] = nsd >= 3 ? 2 : -1;
  gridOptions.WeightComponent = rational ? nsd : -1;
  gridOptions.PointArrays = arrays;
  gridOptions.MergePoints = options.MergePoints;
  gridOptions.PatchIndex = options.PatchIndex;
  gridOptions.FirstElement = options.FirstElement;
  gridOptions.LastElement = options.LastElement;
  gridOptions.SourceFormat = patch.Format;
  vtkSmartPointer<vtkUnstructuredGrid> grid =
    vtkLRSplineBezierGrid::Build(spline, volume, gridOptions, error);
  if (grid && arrays.empty())
  {
    // Without fields the grid's default array would repeat the geometry.
    grid->GetPointData()->RemoveArray("Field");
  }
  return grid;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkUnstructuredGrid> vtkIFEMBlockBuilder::BuildLagrange(const Patch& patch,
  const std::vector<Values>& fields, const Options& options, std::string* error,
  std::string* warning)
{
  std::vector<double> table;
  int width = 0;
  std::vector<PointArray> arrays;
  if (!CombineFields(
        fields, patch.GetNumberOfNodes(), "field", 0, table, width, arrays, error, warning))
  {
    return nullptr;
  }
  AddRecombinedVectors(arrays);
  MarkFirstActive(arrays);
  std::vector<vtkIdType> nodeIds, elementIds;
  vtkSmartPointer<vtkUnstructuredGrid> grid =
    patch.Lagrange.BuildGrid(options.FirstElement, options.LastElement, nodeIds, elementIds);
  AddArraysFromTable(grid->GetPointData(), arrays, table, width, nodeIds);
  vtkNew<vtkIdTypeArray> ids;
  ids->SetName(vtkLRSplineArrayNames::ElementId);
  ids->SetNumberOfTuples(static_cast<vtkIdType>(elementIds.size()));
  for (std::size_t c = 0; c < elementIds.size(); ++c)
  {
    ids->SetValue(static_cast<vtkIdType>(c), elementIds[c]);
  }
  grid->GetCellData()->AddArray(ids);
  return grid;
}

//------------------------------------------------------------------------------
bool vtkIFEMBlockBuilder::AddCellValues(vtkUnstructuredGrid* grid,
  const std::vector<Values>& knotspans, vtkIdType numberOfElements,
  const std::vector<vtkIdType>& elementIds, std::string* error, std::string* warning)
{
  if (knotspans.empty())
  {
    return true;
  }
  std::vector<double> table;
  int width = 0;
  std::vector<PointArray> arrays;
  if (!CombineFields(
        knotspans, numberOfElements, "element field", 0, table, width, arrays, error, warning))
  {
    return false;
  }
  // Names taken by point arrays stay theirs: an element field of the same name is suffixed.
  for (PointArray& a : arrays)
  {
    if (grid->GetPointData()->GetAbstractArray(a.Name.c_str()))
    {
      a.Name += " (element)";
    }
  }
  AddArraysFromTable(grid->GetCellData(), arrays, table, width, elementIds);
  return true;
}

//------------------------------------------------------------------------------
bool vtkIFEMBlockBuilder::GeometryDeviation(
  const Patch& a, const Patch& b, double& deviation, std::string* error)
{
  deviation = std::numeric_limits<double>::infinity();
  if (a.IsLagrange || b.IsLagrange)
  {
    return Fail(error, "only spline patches can be compared");
  }
  if (a.SpatialDimension != b.SpatialDimension ||
    a.Spline.ParametricDimension != b.Spline.ParametricDimension)
  {
    return true;
  }
  const int nsd = a.SpatialDimension;
  const int pd = a.Spline.ParametricDimension;
  double da[6], db[6];
  a.Spline.GetDomain(da);
  b.Spline.GetDomain(db);
  for (int d = 0; d < 6; ++d)
  {
    if (std::abs(da[d] - db[d]) > 1e-12 * (1.0 + std::abs(da[d])))
    {
      return true; // different parameter domains
    }
  }
  // Homogeneous geometry (w x, w) of each patch, extracted whole.
  vtkLRSplineBezierVolume volumes[2];
  const Patch* patches[2] = { &a, &b };
  for (int k = 0; k < 2; ++k)
  {
    const vtkLRSplinePatch& s = patches[k]->Spline;
    const vtkIdType nb = s.GetNumberOfBasisFunctions();
    std::vector<double> h(static_cast<std::size_t>(nb) * (nsd + 1));
    for (vtkIdType i = 0; i < nb; ++i)
    {
      const double* c = s.Coefficients.data() + static_cast<std::size_t>(i) * s.Dimension;
      std::copy(c, c + nsd, h.begin() + i * (nsd + 1));
      h[i * (nsd + 1) + nsd] = s.RationalCoefficients ? c[s.Dimension - 1] : 1.0;
    }
    std::string warning;
    if (!s.ExtractBezier(volumes[k], error, &warning, 0, -1, h.data(), nsd + 1))
    {
      return false;
    }
  }
  vtkLRSplineElementLocator locator;
  const vtkIdType na = volumes[0].GetNumberOfElements();
  if (!locator.Build(
        volumes[0].Boxes.data(), na, vtkLRSplineElementLocator::KD_TREE, nullptr, error))
  {
    return false;
  }
  int samples[3] = { 1, 1, 1 };
  for (int d = 0; d < pd; ++d)
  {
    samples[d] = volumes[0].Degree[d] + volumes[1].Degree[d] + 1;
  }
  double worst = 0.0;
  std::vector<vtkIdType> hits;
  for (vtkIdType e = 0; e < volumes[1].GetNumberOfElements(); ++e)
  {
    const double* eb = volumes[1].GetBox(e);
    locator.FindElementsIntersecting(eb, hits);
    if (hits.empty())
    {
      deviation = std::numeric_limits<double>::infinity();
      return true;
    }
    for (vtkIdType h : hits)
    {
      const double* ha = volumes[0].GetBox(h);
      double box[6];
      bool overlap = true;
      for (int d = 0; d < 3; ++d)
      {
        box[d] = std::max(ha[d], eb[d]);
        box[d + 3] = std::min(ha[d + 3], eb[d + 3]);
        overlap = overlap && (d >= pd || box[d + 3] > box[d]);
      }
      if (!overlap)
      {
        continue;
      }
      for (int k = 0; k < samples[2]; ++k)
      {
        for (int j = 0; j < samples[1]; ++j)
        {
          for (int i = 0; i < samples[0]; ++i)
          {
            const int ijk[3] = { i, j, k };
            double sa[3], sb[3];
            for (int d = 0; d < 3; ++d)
            {
              const double t = (ijk[d] + 0.5) / samples[d];
              const double u = box[d] + t * (box[d + 3] - box[d]);
              sa[d] = (u - ha[d]) / (ha[d + 3] - ha[d]);
              sb[d] = (u - eb[d]) / (eb[d + 3] - eb[d]);
            }
            double va[4], vb[4];
            volumes[0].EvaluateLocal(h, sa, va, nullptr);
            volumes[1].EvaluateLocal(e, sb, vb, nullptr);
            for (int c = 0; c < nsd; ++c)
            {
              worst = std::max(worst, std::abs(va[c] / va[nsd] - vb[c] / vb[nsd]));
            }
          }
        }
      }
    }
  }
  deviation = worst;
  return true;
}
