#include "vtkLRSplineBezierGrid.h"

#include "vtkLRSplineBezierVolume.h"
#include "vtkLRSplinePatch.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkHigherOrderHexahedron.h"
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
  return Build(patch, volume, options, error);
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkUnstructuredGrid> vtkLRSplineBezierGrid::Build(const vtkLRSplinePatch& patch,
  vtkLRSplineBezierVolume& volume, const Options& options, std::string* error)
{
  const bool geometryMode = options.GeometryMode;
  if (geometryMode && patch.Dimension != 2 && patch.Dimension != 3)
  {
    if (error)
    {
      *error = "geometry mode needs coefficients with 2 or 3 components, this patch has " +
        std::to_string(patch.Dimension);
    }
    return nullptr;
  }
  const vtkIdType ne = patch.GetNumberOfElements();
  const vtkIdType first = std::max<vtkIdType>(0, std::min(options.FirstElement, ne));
  const double* scale = options.Scale;
  const double* offset = options.Offset;
  const bool merge = options.MergePoints;

  volume.ElevateToAtLeastLinear();
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

  vtkNew<vtkUnstructuredGrid> grid;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->Allocate(count * per);
  const char* fieldName = options.FieldName.empty() ? "Field" : options.FieldName.c_str();
  vtkNew<vtkDoubleArray> field;
  field->SetName(fieldName);
  field->SetNumberOfComponents(nc);
  field->Allocate(count * per * nc);
  vtkNew<vtkDoubleArray> paramCoords;
  paramCoords->SetName("LRParameterCoordinates");
  paramCoords->SetNumberOfComponents(3);

  vtkNew<vtkIdTypeArray> offsets, connectivity;
  offsets->SetNumberOfTuples(count + 1);
  connectivity->SetNumberOfTuples(count * per);
  std::unordered_map<std::array<double, 3>, std::vector<vtkIdType>, KeyHash> mergeMap;
  if (merge)
  {
    mergeMap.reserve(static_cast<std::size_t>(count * per));
  }
  for (vtkIdType e = 0; e < count; ++e)
  {
    const double* box = volume.GetBox(e);
    const double* coeffs = volume.GetElementCoefficients(e);
    offsets->SetValue(e, e * per);
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
                  same = std::abs(field->GetValue(candidate * nc + comp) - c[comp]) <= tol;
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
            double x[3];
            if (geometryMode)
            {
              x[0] = c[0];
              x[1] = c[1];
              x[2] = nc >= 3 ? c[2] : 0.0;
              paramCoords->InsertNextTuple(u.data());
            }
            else
            {
              for (int d = 0; d < 3; ++d)
              {
                x[d] = offset[d] + scale[d] * u[d];
              }
            }
            id = points->InsertNextPoint(x);
            for (int comp = 0; comp < nc; ++comp)
            {
              field->InsertNextValue(c[comp]);
            }
            if (merge)
            {
              mergeMap[u].push_back(id);
            }
          }
          connectivity->SetValue(
            e * per + vtkHigherOrderHexahedron::PointIndexFromIJK(i, j, k, deg), id);
        }
      }
    }
  }
  offsets->SetValue(count, count * per);
  std::unordered_map<std::array<double, 3>, std::vector<vtkIdType>, KeyHash>().swap(mergeMap);
  points->Squeeze();
  field->Squeeze();
  grid->SetPoints(points);
  vtkNew<vtkCellArray> cells;
  cells->SetData(offsets, connectivity);
  grid->SetCells(VTK_BEZIER_HEXAHEDRON, cells);

  vtkPointData* pd = grid->GetPointData();
  pd->AddArray(field);
  if (nc == 3)
  {
    pd->SetActiveVectors(fieldName);
  }
  else if (nc == 1)
  {
    pd->SetActiveScalars(fieldName);
  }
  if (geometryMode)
  {
    pd->AddArray(paramCoords);
  }

  vtkCellData* cd = grid->GetCellData();
  vtkNew<vtkIntArray> degrees;
  degrees->SetName("HigherOrderDegrees");
  degrees->SetNumberOfComponents(3);
  degrees->SetNumberOfTuples(count);
  vtkNew<vtkDoubleArray> boxes;
  boxes->SetName("LRParameterBox");
  boxes->SetNumberOfComponents(6);
  boxes->SetNumberOfTuples(count);
  vtkNew<vtkIdTypeArray> elementIds;
  elementIds->SetName("LRElementId");
  elementIds->SetNumberOfTuples(count);
  vtkNew<vtkDoubleArray> minSide;
  minSide->SetName("LRElementMinSide");
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
    for (int d = 0; d < 3; ++d)
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

  // Metadata of the whole patch.
  double dom[6];
  patch.GetDomain(dom);
  int levels[3];
  for (int d = 0; d < 3; ++d)
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
  vtkFieldData* fd = grid->GetFieldData();
  AddFieldArray<vtkIntArray, int>(fd, "LRPatchIndex", { options.PatchIndex });
  AddFieldArray<vtkIntArray, int>(
    fd, "LRDegrees", { patch.Order[0] - 1, patch.Order[1] - 1, patch.Order[2] - 1 });
  AddFieldArray<vtkIdTypeArray, vtkIdType>(
    fd, "LRNumberOfBasisFunctions", { patch.GetNumberOfBasisFunctions() });
  AddFieldArray<vtkIdTypeArray, vtkIdType>(fd, "LRNumberOfElements", { ne });
  AddFieldArray<vtkIdTypeArray, vtkIdType>(
    fd, "LRNumberOfMeshRectangles", { static_cast<vtkIdType>(patch.MeshMultiplicities.size()) });
  AddFieldArray<vtkIntArray, int>(fd, "LRRefinementLevels", { levels[0], levels[1], levels[2] });
  AddFieldArray<vtkDoubleArray, double>(
    fd, "LRParameterDomain", { dom[0], dom[1], dom[2], dom[3], dom[4], dom[5] });
  AddFieldArray<vtkIntArray, int>(fd, "LRMode", { geometryMode ? 1 : 0 });
  if (!geometryMode)
  {
    AddFieldArray<vtkDoubleArray, double>(
      fd, "LRPhysicalTransform", { scale[0], scale[1], scale[2], offset[0], offset[1], offset[2] });
  }
  vtkNew<vtkStringArray> source;
  source->SetName("LRSourceFormat");
  source->InsertNextValue(options.SourceFormat);
  fd->AddArray(source);
  return vtkSmartPointer<vtkUnstructuredGrid>(grid.GetPointer());
}
