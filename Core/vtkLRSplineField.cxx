// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLRSplineField.h"
#include "vtkSplineVizError.h"

#include "vtkAlgorithm.h"
#include "vtkCharArray.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkDataObjectTree.h"
#include "vtkDataObjectTreeIterator.h"
#include "vtkDataSetAttributes.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationDataObjectKey.h"
#include "vtkLRSplineArrayNames.h"
#include "vtkLRSplineGeometryMap.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkSplineVizProgress.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cmath>
#include <sstream>

using vtkSplineVizError::Fail;

namespace
{
// The non-empty grids of `obj`; `surface` (may be null) set when a grid of
// surface cells or a polygonal data set is found.
void CollectGrids(
  vtkDataObject* obj, std::vector<vtkUnstructuredGrid*>& grids, bool* surface = nullptr)
{
  if (auto* ug = vtkUnstructuredGrid::SafeDownCast(obj))
  {
    if (ug->GetNumberOfCells() > 0)
    {
      const int type = ug->GetCellType(0);
      if (surface &&
        (type == VTK_BEZIER_QUADRILATERAL || type == VTK_BEZIER_TRIANGLE ||
          type == VTK_LAGRANGE_QUADRILATERAL || type == VTK_QUAD || type == VTK_TRIANGLE))
      {
        *surface = true;
      }
      grids.push_back(ug);
    }
    return;
  }
  if (auto* cds = vtkCompositeDataSet::SafeDownCast(obj))
  {
    vtkSmartPointer<vtkCompositeDataIterator> it;
    it.TakeReference(cds->NewIterator());
    it->SkipEmptyNodesOn();
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
    {
      CollectGrids(it->GetCurrentDataObject(), grids, surface);
    }
    return;
  }
  if (surface && obj && obj->IsA("vtkPolyData"))
  {
    *surface = true;
  }
}

// The requirements that are checked on the source, before building.
bool CheckSource(
  vtkDataObject* source, const vtkLRSplineField::Requirements& needs, std::string* error)
{
  std::vector<vtkUnstructuredGrid*> grids;
  bool surface = false;
  CollectGrids(source, grids, &surface);
  if (needs.Volume && surface)
  {
    return Fail(error,
      "the input is a surface (2D) spline or a polygonal data set: " + needs.Consumer +
        " renders trivariate LR-spline volumes only");
  }
  if (needs.Volume && grids.empty())
  {
    return Fail(error,
      std::string("the input (") + (source ? source->GetClassName() : "null") +
        ") holds no LR-spline patch: expected the output of vtkLRSplineReader, a "
        "vtkMultiBlockDataSet of VTK_BEZIER_HEXAHEDRON grids");
  }
  if (needs.MaximumPatches > 0 && static_cast<int>(grids.size()) > needs.MaximumPatches)
  {
    return Fail(error,
      "the input has " + std::to_string(grids.size()) + " patches; " + needs.Consumer +
        " renders at most " + std::to_string(needs.MaximumPatches));
  }
  for (std::size_t g = 0; g < grids.size() && needs.PolynomialField; ++g)
  {
    vtkPointData* pd = grids[g]->GetPointData();
    vtkFieldData* fd = grids[g]->GetFieldData();
    vtkDataArray* rational = fd ? fd->GetArray(vtkLRSplineArrayNames::Rational) : nullptr;
    vtkDataArray* mode = fd ? fd->GetArray(vtkLRSplineArrayNames::Mode) : nullptr;
    const bool geometryMode =
      mode && mode->GetNumberOfTuples() > 0 && mode->GetComponent(0, 0) == 1;
    // (Rational geometry maps are inverted, their fields rational splines;
    // a rational field over a parameter box is not supported.)
    if (!geometryMode &&
      (pd->GetRationalWeights() || pd->GetArray(vtkLRSplineArrayNames::RationalWeights) ||
        (rational && rational->GetNumberOfTuples() > 0 && rational->GetComponent(0, 0) != 0)))
    {
      return Fail(error,
        "patch " + std::to_string(g) + " is rational (it has rational weights): " + needs.Consumer +
          " renders polynomial LR splines only");
    }
  }
  return true;
}

int AutomaticBlocks(vtkIdType numElements)
{
  const double b = 2.0 * std::cbrt(static_cast<double>(numElements));
  return std::max(1, std::min(64, static_cast<int>(std::ceil(b))));
}

// The index of the first patch in which `find` (patch -> element or -1)
// finds an element, and that element in *element (if given); -1 and -1 when
// none does.
template <typename Patches, typename Find>
int FirstPatch(const Patches& patches, const Find& find, vtkIdType* element)
{
  for (std::size_t p = 0; p < patches.size(); ++p)
  {
    const vtkIdType e = find(*patches[p]);
    if (e >= 0)
    {
      if (element)
      {
        *element = e;
      }
      return static_cast<int>(p);
    }
  }
  if (element)
  {
    *element = -1;
  }
  return -1;
}
}

//------------------------------------------------------------------------------
bool vtkLRSplineField::Build(vtkDataObject* source, const char* arrayName, int locatorType,
  const int blocks[3], bool parameterSpace, std::string* error, double surfaceTolerance)
{
  this->Patches.clear();
  this->NumberOfComponents = 0;
  this->ArrayName.clear();
  this->PatchesOverlap = false;
  std::vector<vtkUnstructuredGrid*> grids;
  CollectGrids(source, grids);
  if (grids.empty())
  {
    return Fail(error,
      "the spline input has no non-empty vtkUnstructuredGrid (expected the output of "
      "vtkLRSplineReader)");
  }
  std::string name = arrayName ? arrayName : "";
  for (std::size_t g = 0; g < grids.size(); ++g)
  {
    vtkUnstructuredGrid* grid = grids[g];
    if (!name.empty() && !grid->GetPointData()->GetArray(name.c_str()))
    {
      // Another basis of a mixed method (its own fields): not this field's.
      continue;
    }
    vtkLRSplineBezierVolume volume;
    std::string msg, used;
    if (!volume.FromUnstructuredGrid(grid, name.c_str(), &msg, nullptr, &used))
    {
      return Fail(error, "patch " + std::to_string(g) + ": " + msg);
    }
    if (name.empty())
    {
      name = used; // the following patches must provide the same array
    }
    if (this->NumberOfComponents == 0)
    {
      this->NumberOfComponents = volume.NumberOfComponents;
    }
    else if (this->NumberOfComponents != volume.NumberOfComponents)
    {
      return Fail(error, "the patches' field arrays have different numbers of components");
    }
    // The physical placement: 6 values (scale xyz, offset xyz: per axis) or
    // 12 (a row-major 3x3 matrix A, offset xyz: x = A u + offset).
    double matrix[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 }, offset[3] = { 0, 0, 0 };
    bool axisAligned = true;
    vtkFieldData* fd = grid->GetFieldData();
    vtkDataArray* mode = fd ? fd->GetArray(vtkLRSplineArrayNames::Mode) : nullptr;
    std::shared_ptr<vtkLRSplineGeometryMap> geometry;
    const bool geometryMode =
      mode && mode->GetNumberOfTuples() > 0 && mode->GetComponent(0, 0) == 1;
    if ((geometryMode || volume.ParametricDimension == 2) && !parameterSpace)
    {
      // Isoparametric: the points are the geometry's control points (a
      // surface's in field mode too: its placement is their Bezier form).
      geometry = std::make_shared<vtkLRSplineGeometryMap>();
      geometry->SetSurfaceTolerance(surfaceTolerance);
      if (!geometry->Build(grid, blocks, &msg))
      {
        return Fail(error, "patch " + std::to_string(g) + " (geometry): " + msg);
      }
      if (geometry->IsAffine())
      {
        // The fast path: an affine image of the parameter domain.
        geometry->GetAffineMap(matrix, offset);
        axisAligned = matrix[1] == 0 && matrix[2] == 0 && matrix[3] == 0 && matrix[5] == 0 &&
          matrix[6] == 0 && matrix[7] == 0 && matrix[0] > 0 && matrix[4] > 0 && matrix[8] > 0;
        geometry.reset();
      }
    }
    vtkDataArray* transform = fd ? fd->GetArray(vtkLRSplineArrayNames::PhysicalTransform) : nullptr;
    if (transform && !parameterSpace && !geometry && transform->GetNumberOfTuples() > 0)
    {
      const vtkIdType count = transform->GetNumberOfComponents() * transform->GetNumberOfTuples();
      const int nc = transform->GetNumberOfComponents();
      auto value = [&](vtkIdType i)
      { return transform->GetComponent(i / nc, static_cast<int>(i % nc)); };
      if (count == 6)
      {
        for (int d = 0; d < 3; ++d)
        {
          matrix[4 * d] = value(d);
          offset[d] = value(d + 3);
          if (!(matrix[4 * d] > 0) || !std::isfinite(matrix[4 * d]) || !std::isfinite(offset[d]))
          {
            return Fail(
              error, "patch " + std::to_string(g) + " has an invalid LRPhysicalTransform");
          }
        }
      }
      else if (count == 12)
      {
        for (int i = 0; i < 9; ++i)
        {
          matrix[i] = value(i);
        }
        for (int d = 0; d < 3; ++d)
        {
          offset[d] = value(9 + d);
        }
        axisAligned = false;
      }
      else
      {
        return Fail(error,
          "patch " + std::to_string(g) + " has an LRPhysicalTransform of " + std::to_string(count) +
            " values (6: scale and offset, or 12: a 3x3 matrix and offset)");
      }
    }
    int autoBlocks[3];
    if (!blocks || blocks[0] < 1)
    {
      autoBlocks[0] = autoBlocks[1] = autoBlocks[2] = AutomaticBlocks(volume.GetNumberOfElements());
      blocks = nullptr;
    }
    auto evaluator = std::make_unique<vtkLRSplineEvaluator>();
    if (!evaluator->Initialize(std::move(volume), locatorType, blocks ? blocks : autoBlocks, &msg))
    {
      return Fail(error, "patch " + std::to_string(g) + ": " + msg);
    }
    if (geometry)
    {
      if (!evaluator->SetGeometry(std::move(geometry)))
      {
        return Fail(error,
          "patch " + std::to_string(g) + ": the geometry and the field \"" + name +
            "\" have different elements");
      }
    }
    else if (axisAligned)
    {
      const double scale[3] = { matrix[0], matrix[4], matrix[8] };
      evaluator->SetPhysicalTransform(scale, offset);
    }
    else if (!evaluator->SetPhysicalAffine(matrix, offset))
    {
      return Fail(error,
        "patch " + std::to_string(g) + " has a singular or non-finite LRPhysicalTransform matrix");
    }
    this->Patches.push_back(std::move(evaluator));
  }
  if (this->Patches.empty())
  {
    return Fail(
      error, "no patch of the spline input has a point-data array named \"" + name + "\"");
  }
  this->ArrayName = name;
  // Do the patches' boxes overlap (then the hint must not skip the order rule)?
  for (std::size_t a = 0; a < this->Patches.size(); ++a)
  {
    double ba[6];
    this->Patches[a]->GetBounds(ba);
    for (std::size_t b = a + 1; b < this->Patches.size(); ++b)
    {
      double bb[6];
      this->Patches[b]->GetBounds(bb);
      bool overlap = true;
      for (int d = 0; d < 3; ++d)
      {
        overlap = overlap && ba[2 * d] < bb[2 * d + 1] && bb[2 * d] < ba[2 * d + 1];
      }
      this->PatchesOverlap = this->PatchesOverlap || overlap;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkLRSplineField::Build(vtkDataObject* source, const char* arrayName, int locatorType,
  const int blocks[3], const Requirements& requirements, std::string* error)
{
  if (!CheckSource(source, requirements, error) ||
    !this->Build(source, arrayName, locatorType, blocks, false, error))
  {
    this->Patches.clear();
    return false;
  }
  const int nc = this->NumberOfComponents;
  if (requirements.MaximumComponents > 0 && nc > requirements.MaximumComponents)
  {
    return Fail(error,
      "the field \"" + this->ArrayName + "\" has " + std::to_string(nc) + " components; " +
        requirements.Consumer + " renders fields of at most " +
        std::to_string(requirements.MaximumComponents) + " components");
  }
  int degree[3];
  this->GetCommonDegrees(degree);
  for (int k = 0; k < 3 && requirements.MaximumDegree > 0; ++k)
  {
    if (degree[k] > requirements.MaximumDegree)
    {
      return Fail(error,
        "the spline has degree " + std::to_string(degree[k]) + " in direction " +
          std::to_string(k) + "; " + requirements.Consumer + " renders degrees up to " +
          std::to_string(requirements.MaximumDegree));
    }
  }
  for (int p = 0; p < this->GetNumberOfPatches() && requirements.FiniteCoefficients; ++p)
  {
    for (double c : this->Patches[p]->GetVolume().Coefficients)
    {
      if (!std::isfinite(c))
      {
        return Fail(error,
          "patch " + std::to_string(p) + " has NaN or infinite coefficients in \"" +
            this->ArrayName + "\"");
      }
    }
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkLRSplineField::GetCommonDegrees(int degree[3]) const
{
  degree[0] = degree[1] = degree[2] = 1;
  for (const auto& p : this->Patches)
  {
    const int* d = p->GetVolume().Degree;
    for (int k = 0; k < 3; ++k)
    {
      degree[k] = std::max(degree[k], d[k]);
    }
  }
}

//------------------------------------------------------------------------------
vtkIdType vtkLRSplineField::GetNumberOfElements() const
{
  vtkIdType n = 0;
  for (const auto& p : this->Patches)
  {
    n += p->GetNumberOfElements();
  }
  return n;
}

void vtkLRSplineField::GetBounds(double bounds[6]) const
{
  for (int d = 0; d < 3; ++d)
  {
    bounds[2 * d] = VTK_DOUBLE_MAX;
    bounds[2 * d + 1] = -VTK_DOUBLE_MAX;
  }
  for (const auto& p : this->Patches)
  {
    double b[6];
    p->GetBounds(b);
    for (int d = 0; d < 3; ++d)
    {
      bounds[2 * d] = std::min(bounds[2 * d], b[2 * d]);
      bounds[2 * d + 1] = std::max(bounds[2 * d + 1], b[2 * d + 1]);
    }
  }
}

int vtkLRSplineField::GetParametricDimension() const
{
  int pd = 0;
  for (const auto& p : this->Patches)
  {
    pd = std::max(pd, p->GetParametricDimension());
  }
  return pd;
}

bool vtkLRSplineField::ProjectOntoSurface(
  int patch, vtkIdType element, const double x[3], double point[3], double normal[3]) const
{
  return patch >= 0 && patch < this->GetNumberOfPatches() && element >= 0 &&
    this->Patches[patch]->ProjectOntoSurface(element, x, point, normal);
}

int vtkLRSplineField::GetMaximumDegree() const
{
  int m = 0;
  for (const auto& p : this->Patches)
  {
    m = std::max(m, p->GetMaximumDegree());
  }
  return m;
}

void vtkLRSplineField::MakeFloat()
{
  for (auto& p : this->Patches)
  {
    p->MakeFloat();
  }
}

//------------------------------------------------------------------------------
int vtkLRSplineField::FindPatch(const double x[3], vtkIdType* element) const
{
  return FirstPatch(
    this->Patches, [x](const vtkLRSplineEvaluator& patch) { return patch.FindElement(x); },
    element);
}

int vtkLRSplineField::Evaluate(
  const double x[3], double* value, double* gradient, vtkIdType* element) const
{
  return FirstPatch(
    this->Patches,
    [x, value, gradient](const vtkLRSplineEvaluator& patch)
    { return patch.Evaluate(x, value, gradient); },
    element);
}

int vtkLRSplineField::Evaluate(
  const float x[3], float* value, float* gradient, vtkIdType* element) const
{
  const double xd[3] = { x[0], x[1], x[2] };
  vtkIdType e;
  const int p = this->FindPatch(xd, &e);
  if (p >= 0)
  {
    this->Patches[p]->EvaluateInElement(e, x, value, gradient);
  }
  if (element)
  {
    *element = e;
  }
  return p;
}

//------------------------------------------------------------------------------
int vtkLRSplineField::EvaluateWithHint(
  const double x[3], double* value, double* gradient, int& patch, vtkIdType& element) const
{
  if (patch >= 0 && element >= 0 && (!this->PatchesOverlap || patch == 0) &&
    patch < this->GetNumberOfPatches() &&
    this->Patches[patch]->EvaluateIfInElement(element, x, value, gradient))
  {
    return patch;
  }
  patch = this->Evaluate(x, value, gradient, &element);
  return patch;
}

int vtkLRSplineField::EvaluateWithHint(
  const float x[3], float* value, float* gradient, int& patch, vtkIdType& element) const
{
  const double xd[3] = { x[0], x[1], x[2] };
  if (patch >= 0 && element >= 0 && (!this->PatchesOverlap || patch == 0) &&
    patch < this->GetNumberOfPatches() && this->Patches[patch]->ElementContains(element, xd))
  {
    this->Patches[patch]->EvaluateInElement(element, x, value, gradient);
    return patch;
  }
  patch = this->Evaluate(x, value, gradient, &element);
  return patch;
}

//------------------------------------------------------------------------------
vtkIdType vtkLRSplineField::EvaluatePoints(vtkIdType n,
  const std::function<void(vtkIdType, double[3])>& point, double* values, double* gradients,
  char* mask, vtkAlgorithm* progress) const
{
  const int nc = this->NumberOfComponents;
  vtkSMPThreadLocal<vtkIdType> inside(0);
  const bool done = vtkSplineVizProgress::For(progress, 0, n, 0, 4096,
    [&](vtkIdType begin, vtkIdType end)
    {
      vtkIdType& count = inside.Local();
      int patch = -1;
      vtkIdType element = -1;
      for (vtkIdType i = begin; i < end; ++i)
      {
        double x[3];
        point(i, x);
        double* v = values + i * nc;
        double* g = gradients ? gradients + 3 * i * nc : nullptr;
        const int p = this->EvaluateWithHint(x, v, g, patch, element);
        if (p < 0)
        {
          std::fill(v, v + nc, 0.0);
          if (g)
          {
            std::fill(g, g + 3 * nc, 0.0);
          }
        }
        else
        {
          ++count;
        }
        if (mask)
        {
          mask[i] = p >= 0 ? 1 : 0;
        }
      }
    });
  if (!done)
  {
    return -1;
  }
  vtkIdType total = 0;
  for (vtkIdType c : inside)
  {
    total += c;
  }
  return total;
}

//------------------------------------------------------------------------------
vtkIdType vtkLRSplineField::EvaluateIntoPointData(vtkPointData* pd, vtkIdType n,
  const std::function<void(vtkIdType, double[3])>& point, const char* gradientName,
  const char* maskName, vtkAlgorithm* progress) const
{
  const int nc = this->NumberOfComponents;
  vtkNew<vtkDoubleArray> values;
  values->SetName(this->ArrayName.c_str());
  values->SetNumberOfComponents(nc);
  values->SetNumberOfTuples(n);
  vtkNew<vtkDoubleArray> gradients;
  if (gradientName)
  {
    gradients->SetName(gradientName);
    gradients->SetNumberOfComponents(3 * nc);
    gradients->SetNumberOfTuples(n);
  }
  vtkNew<vtkCharArray> mask;
  mask->SetName(maskName);
  mask->SetNumberOfTuples(n);
  vtkIdType inside = 0;
  if (n > 0)
  {
    inside = this->EvaluatePoints(n, point, values->GetPointer(0),
      gradientName ? gradients->GetPointer(0) : nullptr, mask->GetPointer(0), progress);
    if (inside < 0)
    {
      return -1; // aborted
    }
  }
  pd->AddArray(values);
  if (nc == 3)
  {
    pd->SetActiveVectors(values->GetName());
  }
  else if (nc == 1)
  {
    pd->SetActiveScalars(values->GetName());
  }
  if (gradientName)
  {
    pd->AddArray(gradients);
  }
  pd->AddArray(mask);
  return inside;
}

//------------------------------------------------------------------------------
bool vtkLRSplineField::BuildCached(std::unique_ptr<vtkLRSplineField>& field, std::string& key,
  vtkDataObject* source, const char* arrayName, int locatorType, int resolution,
  bool parameterSpace, std::string* error, double surfaceTolerance)
{
  std::ostringstream k;
  k.precision(17);
  k << static_cast<const void*>(source) << "/" << (source ? source->GetMTime() : 0) << "/"
    << (arrayName ? arrayName : "") << "/" << locatorType << "/" << resolution << "/"
    << parameterSpace << "/" << surfaceTolerance;
  if (field && key == k.str())
  {
    return true;
  }
  key.clear();
  auto fresh = std::make_unique<vtkLRSplineField>();
  const int blocks[3] = { resolution, resolution, resolution };
  if (!fresh->Build(source, arrayName, locatorType, resolution > 0 ? blocks : nullptr,
        parameterSpace, error, surfaceTolerance))
  {
    field.reset();
    return false;
  }
  field = std::move(fresh);
  key = k.str();
  return true;
}

//------------------------------------------------------------------------------
bool vtkLRSplineField::SelectedFieldName(vtkAlgorithm* algorithm, int idx, int port,
  vtkDataObject* source, std::string& name, std::string* error)
{
  name.clear();
  vtkInformation* info = algorithm->GetInputArrayInformation(idx);
  const bool named = info->Has(vtkDataObject::FIELD_NAME());
  const bool byAttribute = !named && info->Has(vtkDataObject::FIELD_ATTRIBUTE_TYPE());
  if (!named && !byAttribute)
  {
    return true; // nothing selected: the active vectors, else scalars
  }
  if (info->Has(vtkAlgorithm::INPUT_PORT()) && info->Get(vtkAlgorithm::INPUT_PORT()) != port)
  {
    return Fail(error,
      "the field is selected on input port " +
        std::to_string(info->Get(vtkAlgorithm::INPUT_PORT())) + ", but the spline is on port " +
        std::to_string(port) + ": use SetInputArrayToProcess(" + std::to_string(idx) + ", " +
        std::to_string(port) + ", 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, name)");
  }
  const int association = info->Has(vtkDataObject::FIELD_ASSOCIATION())
    ? info->Get(vtkDataObject::FIELD_ASSOCIATION())
    : vtkDataObject::FIELD_ASSOCIATION_POINTS;
  if (association != vtkDataObject::FIELD_ASSOCIATION_POINTS &&
    association != vtkDataObject::FIELD_ASSOCIATION_POINTS_THEN_CELLS)
  {
    return Fail(error,
      std::string("the field must be selected as point data (the spline's coefficients are point "
                  "data), not ") +
        vtkDataObject::GetAssociationTypeAsString(association));
  }
  if (named)
  {
    const char* selected = info->Get(vtkDataObject::FIELD_NAME());
    name = selected ? selected : "";
    return true;
  }
  const int attribute = info->Get(vtkDataObject::FIELD_ATTRIBUTE_TYPE());
  std::vector<vtkUnstructuredGrid*> grids;
  CollectGrids(source, grids);
  for (vtkUnstructuredGrid* grid : grids)
  {
    vtkDataArray* array = grid->GetPointData()->GetAttribute(attribute);
    if (array && array->GetName() && array->GetName()[0])
    {
      name = array->GetName();
      return true;
    }
  }
  return Fail(error,
    std::string("no patch of the spline has active ") +
      vtkDataSetAttributes::GetAttributeTypeAsString(attribute) + " point data to evaluate");
}

//------------------------------------------------------------------------------
vtkInformationKeyMacro(vtkLRSplineField, TRIMMING_SURFACE, DataObject);

vtkPolyData* vtkLRSplineField::GetTrimmingSurface(vtkDataObject* spline)
{
  // In the meta-data of a top-level block: it survives the shallow copies a
  // pipeline makes (ParaView's post filters), which the data object's own
  // information does not.
  auto* tree = vtkDataObjectTree::SafeDownCast(spline);
  if (!tree)
  {
    return nullptr;
  }
  vtkSmartPointer<vtkDataObjectTreeIterator> it;
  it.TakeReference(tree->NewTreeIterator());
  it->TraverseSubTreeOff();
  it->VisitOnlyLeavesOff();
  it->SkipEmptyNodesOff();
  for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
  {
    if (it->HasCurrentMetaData())
    {
      if (auto* surface =
            vtkPolyData::SafeDownCast(it->GetCurrentMetaData()->Get(TRIMMING_SURFACE())))
      {
        return surface;
      }
    }
  }
  return nullptr;
}
