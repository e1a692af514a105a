// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLRSplineBezierGrid.h"

#include "vtkLRSplineArrayNames.h"
#include "vtkLRSplineBezierVolume.h"
#include "vtkLRSplinePatch.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkHigherOrderHexahedron.h"
#include "vtkHigherOrderQuadrilateral.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkStringArray.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <unordered_map>
#include <vector>

namespace
{
struct KeyHash
{
  std::size_t operator()(const std::array<double, 3>& k) const
  {
    std::size_t h = 0;
    for (double v : k)
    {
      std::uint64_t bits;
      const double z = v == 0.0 ? 0.0 : v; // -0 == 0
      std::memcpy(&bits, &z, sizeof(bits));
      h ^= std::hash<std::uint64_t>()(bits) + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
    }
    return h;
  }
};

template <typename ArrayT, typename T>
void AddFieldArray(vtkFieldData* fd, const char* name, std::initializer_list<T> values)
{
  vtkNew<ArrayT> a;
  a->SetName(name);
  a->SetNumberOfComponents(static_cast<int>(values.size()));
  a->SetNumberOfTuples(1);
  int c = 0;
  for (T v : values)
  {
    a->SetTypedComponent(0, c++, v);
  }
  fd->AddArray(a);
}
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkUnstructuredGrid> vtkLRSplineBezierGrid::Build(
  const vtkLRSplinePatch& patch, const Options& options, std::string* error, std::string* warning)
{
  vtkLRSplineBezierVolume volume;
  std::string message;
  if (!patch.ExtractBezier(volume, &message, warning, options.FirstElement, options.LastElement))
  {
    if (error)
    {
      *error = message;
    }
    return nullptr;
  }
  if (!patch.RationalCoefficients)
  {
    return Build(patch, volume, options, error);
  }
  // Rational: the weight (the last component) becomes VTK's rational weights.
  const int nc = volume.NumberOfComponents;
  if (!options.GeometryMode || nc < 3)
  {
    if (error)
    {
      *error = options.GeometryMode
        ? "geometry mode needs 2 or 3 Cartesian components, this rational patch has " +
          std::to_string(nc - 1)
        : "the patch is rational: it can be read in geometry mode only (its weights make the "
          "field mode's placement of the parameter domain non-polynomial): read it with "
          "GeometryMode on";
    }
    return nullptr;
  }
  if (!volume.Dehomogenize(nc - 1, &message))
  {
    if (error)
    {
      *error = message;
    }
    return nullptr;
  }
  Options rational = options;
  if (rational.PointComponents[0] < 0 && rational.PointComponents[1] < 0 &&
    rational.PointComponents[2] < 0)
  {
    rational.PointComponents[0] = 0;
    rational.PointComponents[1] = 1;
    rational.PointComponents[2] = nc - 1 >= 3 ? 2 : -1;
  }
  rational.WeightComponent = nc - 1;
  return Build(patch, volume, rational, error);
}

//------------------------------------------------------------------------------
namespace
{
// The control points of the Bezier cells, merged where neighbours share them:
// the parameter point and all coefficient components of every point.
struct ControlPoints
{
  std::vector<double> Parameters; // 3 per point
  std::vector<double> Values;     // nc per point
  vtkNew<vtkIdTypeArray> Offsets;
  vtkNew<vtkIdTypeArray> Connectivity;
};

void CollectControlPoints(
  const vtkLRSplineBezierVolume& volume, int pd, bool merge, ControlPoints& out)
{
  const int* deg = volume.Degree;
  const int nc = volume.NumberOfComponents;
  const int per = volume.GetCoefficientsPerElement();
  const vtkIdType count = volume.GetNumberOfElements();
  double maxAbs = 0.0;
  for (double c : volume.Coefficients)
  {
    maxAbs = std::max(maxAbs, std::abs(c));
  }
  const double tol = 1e-10 * std::max(maxAbs, 1e-300);
  out.Parameters.reserve(static_cast<std::size_t>(count) * per * 3);
  out.Values.reserve(static_cast<std::size_t>(count) * per * nc);
  out.Offsets->SetNumberOfTuples(count + 1);
  out.Connectivity->SetNumberOfTuples(count * per);
  std::unordered_map<std::array<double, 3>, std::vector<vtkIdType>, KeyHash> mergeMap;
  if (merge)
  {
    mergeMap.reserve(static_cast<std::size_t>(count * per));
  }
  for (vtkIdType e = 0; e < count; ++e)
  {
    const double* box = volume.GetBox(e);
    const double* coeffs = volume.GetElementCoefficients(e);
    out.Offsets->SetValue(e, e * per);
    for (int k = 0; k <= deg[2]; ++k)
    {
      for (int j = 0; j <= deg[1]; ++j)
      {
        for (int i = 0; i <= deg[0]; ++i)
        {
          const int ijk[3] = { i, j, k };
          std::array<double, 3> u;
          for (int d = 0; d < 3; ++d)
          {
            u[d] = ijk[d] == 0
              ? box[d]
              : (ijk[d] == deg[d]
                    ? box[d + 3]
                    : box[d] + (box[d + 3] - box[d]) * (static_cast<double>(ijk[d]) / deg[d]));
          }
          const double* c = coeffs + ((k * (deg[1] + 1) + j) * (deg[0] + 1) + i) * nc;
          vtkIdType id = -1;
          if (merge)
          {
            auto it = mergeMap.find(u);
            if (it != mergeMap.end())
            {
              for (vtkIdType candidate : it->second)
              {
                bool same = true;
                for (int comp = 0; comp < nc && same; ++comp)
                {
                  same = std::abs(out.Values[candidate * nc + comp] - c[comp]) <= tol;
                }
                if (same)
                {
                  id = candidate;
                  break;
                }
              }
            }
          }
          if (id < 0)
          {
            id = static_cast<vtkIdType>(out.Parameters.size() / 3);
            out.Parameters.insert(out.Parameters.end(), u.begin(), u.end());
            out.Values.insert(out.Values.end(), c, c + nc);
            if (merge)
            {
              mergeMap[u].push_back(id);
            }
          }
          const int local = pd == 2 ? vtkHigherOrderQuadrilateral::PointIndexFromIJK(i, j, deg)
                                    : vtkHigherOrderHexahedron::PointIndexFromIJK(i, j, k, deg);
          out.Connectivity->SetValue(e * per + local, id);
        }
      }
    }
  }
  out.Offsets->SetValue(count, count * per);
}

// The point arrays of the options (or the default one) from the control points' values.
void AddPointArrays(vtkPointData* pd, const ControlPoints& points, int nc,
  const vtkLRSplineBezierGrid::Options& options)
{
  std::vector<vtkLRSplineBezierGrid::Options::PointArray> arrays = options.PointArrays;
  if (arrays.empty())
  {
    vtkLRSplineBezierGrid::Options::PointArray all;
    all.Name = options.FieldName.empty() ? "Field" : options.FieldName;
    for (int c = 0; c < nc; ++c)
    {
      all.Components.push_back(c);
    }
    all.Active = nc == 3 ? 3 : (nc == 1 ? 1 : 0);
    arrays.push_back(all);
  }
  const vtkIdType n = static_cast<vtkIdType>(points.Parameters.size() / 3);
  for (const auto& spec : arrays)
  {
    const int width = std::max(static_cast<int>(spec.Components.size()), spec.NumberOfComponents);
    vtkNew<vtkDoubleArray> array;
    array->SetName(spec.Name.c_str());
    array->SetNumberOfComponents(width);
    array->SetNumberOfTuples(n);
    for (vtkIdType i = 0; i < n; ++i)
    {
      for (int c = 0; c < width; ++c)
      {
        array->SetTypedComponent(i, c,
          c < static_cast<int>(spec.Components.size())
            ? points.Values[static_cast<std::size_t>(i) * nc + spec.Components[c]]
            : 0.0);
      }
    }
    pd->AddArray(array);
    if (spec.Active == 3)
    {
      pd->SetActiveVectors(spec.Name.c_str());
    }
    else if (spec.Active == 1)
    {
      pd->SetActiveScalars(spec.Name.c_str());
    }
  }
}

void AddCellData(vtkCellData* cd, const vtkLRSplineBezierVolume& volume, int pd, vtkIdType first,
  bool geometryMode, const double* scale)
{
  const int* deg = volume.Degree;
  const vtkIdType count = volume.GetNumberOfElements();
  vtkNew<vtkIntArray> degrees;
  degrees->SetName("HigherOrderDegrees");
  degrees->SetNumberOfComponents(3);
  degrees->SetNumberOfTuples(count);
  vtkNew<vtkDoubleArray> boxes;
  boxes->SetName(vtkLRSplineArrayNames::ParameterBox);
  boxes->SetNumberOfComponents(6);
  boxes->SetNumberOfTuples(count);
  vtkNew<vtkIdTypeArray> elementIds;
  elementIds->SetName(vtkLRSplineArrayNames::ElementId);
  elementIds->SetNumberOfTuples(count);
  vtkNew<vtkDoubleArray> minSide;
  minSide->SetName(vtkLRSplineArrayNames::ElementMinSide);
  minSide->SetNumberOfTuples(count);
  for (vtkIdType e = 0; e < count; ++e)
  {
    const double* box = volume.GetBox(e);
    for (int d = 0; d < 3; ++d)
    {
      degrees->SetTypedComponent(e, d, deg[d]);
    }
    boxes->SetTypedTuple(e, box);
    elementIds->SetValue(e, first + e);
    double m = VTK_DOUBLE_MAX;
    for (int d = 0; d < pd; ++d)
    {
      m = std::min(m, (box[d + 3] - box[d]) * (geometryMode ? 1.0 : scale[d]));
    }
    minSide->SetValue(e, m);
  }
  cd->AddArray(degrees);
  cd->SetHigherOrderDegrees(degrees);
  cd->AddArray(boxes);
  cd->AddArray(elementIds);
  cd->AddArray(minSide);
}

void AddFieldData(vtkFieldData* fd, const vtkLRSplinePatch& patch,
  const vtkLRSplineBezierGrid::Options& options, bool geometryMode)
{
  const vtkIdType ne = patch.GetNumberOfElements();
  const int pd = patch.ParametricDimension;
  double dom[6];
  patch.GetDomain(dom);
  int levels[3] = { 0, 0, 0 };
  for (int d = 0; d < pd; ++d)
  {
    double smallest = VTK_DOUBLE_MAX, largest = 0.0;
    for (vtkIdType e = 0; e < ne; ++e)
    {
      const double side = patch.ElementBoxes[6 * e + d + 3] - patch.ElementBoxes[6 * e + d];
      smallest = std::min(smallest, side);
      largest = std::max(largest, side);
    }
    levels[d] = static_cast<int>(std::lround(std::log2(largest / smallest)));
  }
  AddFieldArray<vtkIntArray, int>(fd, vtkLRSplineArrayNames::PatchIndex, { options.PatchIndex });
  AddFieldArray<vtkIntArray, int>(fd, vtkLRSplineArrayNames::ParametricDimension, { pd });
  AddFieldArray<vtkIntArray, int>(fd, vtkLRSplineArrayNames::Degrees,
    { patch.Order[0] - 1, patch.Order[1] - 1, patch.Order[2] - 1 });
  AddFieldArray<vtkIdTypeArray, vtkIdType>(
    fd, vtkLRSplineArrayNames::NumberOfBasisFunctions, { patch.GetNumberOfBasisFunctions() });
  AddFieldArray<vtkIdTypeArray, vtkIdType>(fd, vtkLRSplineArrayNames::NumberOfElements, { ne });
  AddFieldArray<vtkIdTypeArray, vtkIdType>(fd, vtkLRSplineArrayNames::NumberOfMeshRectangles,
    { static_cast<vtkIdType>(patch.MeshMultiplicities.size()) });
  AddFieldArray<vtkIntArray, int>(
    fd, vtkLRSplineArrayNames::RefinementLevels, { levels[0], levels[1], levels[2] });
  AddFieldArray<vtkDoubleArray, double>(
    fd, vtkLRSplineArrayNames::ParameterDomain, { dom[0], dom[1], dom[2], dom[3], dom[4], dom[5] });
  AddFieldArray<vtkIntArray, int>(fd, vtkLRSplineArrayNames::Mode, { geometryMode ? 1 : 0 });
  AddFieldArray<vtkIntArray, int>(
    fd, vtkLRSplineArrayNames::Rational, { options.WeightComponent >= 0 ? 1 : 0 });
  if (!geometryMode)
  {
    const double* scale = options.Scale;
    const double* offset = options.Offset;
    AddFieldArray<vtkDoubleArray, double>(fd, vtkLRSplineArrayNames::PhysicalTransform,
      { scale[0], scale[1], scale[2], offset[0], offset[1], offset[2] });
  }
  vtkNew<vtkStringArray> source;
  source->SetName(vtkLRSplineArrayNames::SourceFormat);
  source->InsertNextValue(options.SourceFormat);
  fd->AddArray(source);
}
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkUnstructuredGrid> vtkLRSplineBezierGrid::Build(const vtkLRSplinePatch& patch,
  vtkLRSplineBezierVolume& volume, const Options& options, std::string* error)
{
  auto fail = [error](const std::string& msg) -> vtkSmartPointer<vtkUnstructuredGrid>
  {
    if (error)
    {
      *error = msg;
    }
    return nullptr;
  };
  const bool geometryMode = options.GeometryMode;
  const int nc = volume.NumberOfComponents;
  const int pd = patch.ParametricDimension == 2 ? 2 : 3;
  int xyz[3] = { options.PointComponents[0], options.PointComponents[1],
    options.PointComponents[2] };
  if (geometryMode && xyz[0] < 0 && xyz[1] < 0 && xyz[2] < 0)
  {
    if (nc != 2 && nc != 3)
    {
      return fail("geometry mode needs coefficients with 2 or 3 components, this patch has " +
        std::to_string(nc));
    }
    xyz[0] = 0;
    xyz[1] = 1;
    xyz[2] = nc == 3 ? 2 : -1;
  }
  for (int d = 0; d < 3; ++d)
  {
    if (xyz[d] >= nc)
    {
      return fail("a point component does not exist in the coefficients");
    }
  }
  if (options.WeightComponent >= nc || (options.WeightComponent >= 0 && !geometryMode))
  {
    return fail("rational weights need geometry mode and an existing weight component");
  }
  for (const auto& spec : options.PointArrays)
  {
    for (int c : spec.Components)
    {
      if (c < 0 || c >= nc)
      {
        return fail("the point array \"" + spec.Name + "\" names a component that does not exist");
      }
    }
  }
  const vtkIdType ne = patch.GetNumberOfElements();
  const vtkIdType first = std::max<vtkIdType>(0, std::min(options.FirstElement, ne));
  volume.ElevateToAtLeastLinear(pd);

  ControlPoints cp;
  CollectControlPoints(volume, pd, options.MergePoints, cp);
  const vtkIdType np = static_cast<vtkIdType>(cp.Parameters.size() / 3);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(np);
  vtkNew<vtkDoubleArray> paramCoords;
  paramCoords->SetName(vtkLRSplineArrayNames::ParameterCoordinates);
  paramCoords->SetNumberOfComponents(3);
  vtkNew<vtkDoubleArray> weights;
  weights->SetName(vtkLRSplineArrayNames::RationalWeights);
  if (geometryMode)
  {
    paramCoords->SetNumberOfTuples(np);
  }
  if (options.WeightComponent >= 0)
  {
    weights->SetNumberOfTuples(np);
  }
  for (vtkIdType i = 0; i < np; ++i)
  {
    const double* u = cp.Parameters.data() + 3 * i;
    const double* c = cp.Values.data() + static_cast<std::size_t>(i) * nc;
    double x[3];
    for (int d = 0; d < 3; ++d)
    {
      x[d] = geometryMode ? (xyz[d] >= 0 ? c[xyz[d]] : 0.0)
                          : options.Offset[d] + options.Scale[d] * u[d];
    }
    points->SetPoint(i, x);
    if (geometryMode)
    {
      paramCoords->SetTypedTuple(i, u);
    }
    if (options.WeightComponent >= 0)
    {
      weights->SetValue(i, c[options.WeightComponent]);
    }
  }

  vtkNew<vtkUnstructuredGrid> grid;
  grid->SetPoints(points);
  vtkNew<vtkCellArray> cells;
  cells->SetData(cp.Offsets, cp.Connectivity);
  grid->SetCells(pd == 2 ? VTK_BEZIER_QUADRILATERAL : VTK_BEZIER_HEXAHEDRON, cells);
  vtkPointData* pointData = grid->GetPointData();
  AddPointArrays(pointData, cp, nc, options);
  if (geometryMode)
  {
    pointData->AddArray(paramCoords);
  }
  if (options.WeightComponent >= 0)
  {
    pointData->SetRationalWeights(weights);
  }
  AddCellData(grid->GetCellData(), volume, pd, first, geometryMode, options.Scale);
  AddFieldData(grid->GetFieldData(), patch, options, geometryMode);
  return vtkSmartPointer<vtkUnstructuredGrid>(grid.GetPointer());
}
