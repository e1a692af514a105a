// SPDX-License-Identifier: BSD-3-Clause
#include "vtkSuperquadricGlyphPreparer.h"

#include "vtkSplineVizTensorMath.h"

#include "vtkAbstractMapper.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataSet.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkSuperquadricGlyphPreparer);

namespace
{
namespace TM = vtkSplineVizTensorMath;

// Per-point classification of the data preparation.
enum PointClass : unsigned char
{
  KEEP = 0,
  INVALID = 1,
  ZERO = 2,
  MASKED = 3
};

constexpr vtkIdType BlockSize = 8192;

/// Bricks of the occlusion culling: glyphs per brick (more bricks: thinner
/// visibility layers, more CPU work per frame to order them).
constexpr double GlyphsPerBrick = 8.0;

/// The uniform grid of bricks over the glyphs and, per brick, the first
/// glyph (glyphs sorted by brick; Offsets has one more entry than bricks).
struct BrickGrid
{
  double Origin[3] = { 0, 0, 0 };
  double Spacing[3] = { 1, 1, 1 };
  int Dimensions[3] = { 1, 1, 1 };
  std::vector<vtkIdType> Offsets;
};

/// Reorders the per-glyph arrays by brick (a stable counting sort) and
/// returns the grid: GlyphsPerBrick glyphs per brick, at most 2^18 bricks, flat
/// extents get one brick across.
BrickGrid SortIntoBricks(vtkFloatArray* positions, vtkFloatArray* diag, vtkFloatArray* off,
  vtkIdTypeArray* ids, vtkDataArray* scalars)
{
  BrickGrid grid;
  const vtkIdType n = positions->GetNumberOfTuples();
  if (n == 0)
  {
    grid.Offsets = { 0, 0 };
    return grid;
  }
  const float* p = positions->GetPointer(0);
  double lo[3] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, VTK_DOUBLE_MAX };
  double hi[3] = { -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
  for (vtkIdType i = 0; i < n; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      lo[c] = std::min(lo[c], static_cast<double>(p[3 * i + c]));
      hi[c] = std::max(hi[c], static_cast<double>(p[3 * i + c]));
    }
  }
  double extent[3];
  double largest = 0.0;
  for (int c = 0; c < 3; ++c)
  {
    extent[c] = hi[c] - lo[c];
    largest = std::max(largest, extent[c]);
  }
  const double target =
    std::min(static_cast<double>(1 << 18), std::max(1.0, static_cast<double>(n) / GlyphsPerBrick));
  double volume = 1.0;
  int active = 0;
  for (int c = 0; c < 3; ++c)
  {
    if (extent[c] > 1e-9 * largest && extent[c] > 0.0)
    {
      volume *= extent[c];
      ++active;
    }
  }
  const double h = active > 0 ? std::pow(volume / target, 1.0 / active) : 1.0;
  for (int c = 0; c < 3; ++c)
  {
    const bool flat = !(extent[c] > 1e-9 * largest && extent[c] > 0.0);
    grid.Dimensions[c] =
      flat ? 1 : static_cast<int>(std::min(1024.0, std::max(1.0, std::ceil(extent[c] / h))));
    // a little margin so that the largest coordinate falls into the last brick
    grid.Spacing[c] = flat ? 1.0 : extent[c] * (1.0 + 1e-6) / grid.Dimensions[c];
    grid.Origin[c] = lo[c];
  }
  const vtkIdType bricks =
    static_cast<vtkIdType>(grid.Dimensions[0]) * grid.Dimensions[1] * grid.Dimensions[2];
  std::vector<unsigned int> brickOf(n);
  vtkSMPTools::For(0, n,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        vtkIdType b = 0;
        for (int c = 2; c >= 0; --c)
        {
          int k = static_cast<int>((p[3 * i + c] - grid.Origin[c]) / grid.Spacing[c]);
          k = std::min(grid.Dimensions[c] - 1, std::max(0, k));
          b = b * grid.Dimensions[c] + k;
        }
        brickOf[i] = static_cast<unsigned int>(b);
      }
    });
  grid.Offsets.assign(bricks + 1, 0);
  for (vtkIdType i = 0; i < n; ++i)
  {
    ++grid.Offsets[brickOf[i] + 1];
  }
  for (vtkIdType b = 0; b < bricks; ++b)
  {
    grid.Offsets[b + 1] += grid.Offsets[b];
  }
  // source of every destination slot (stable)
  std::vector<vtkIdType> source(n);
  {
    std::vector<vtkIdType> cursor(grid.Offsets.begin(), grid.Offsets.end() - 1);
    for (vtkIdType i = 0; i < n; ++i)
    {
      source[cursor[brickOf[i]]++] = i;
    }
  }
  auto gather = [&](vtkDataArray* a)
  {
    if (!a)
    {
      return;
    }
    vtkSmartPointer<vtkDataArray> copy;
    copy.TakeReference(a->NewInstance());
    copy->DeepCopy(a);
    if (a->HasStandardMemoryLayout())
    {
      const size_t tuple = static_cast<size_t>(a->GetNumberOfComponents()) * a->GetDataTypeSize();
      const char* from = static_cast<const char*>(copy->GetVoidPointer(0));
      char* to = static_cast<char*>(a->GetVoidPointer(0));
      vtkSMPTools::For(0, n,
        [&](vtkIdType begin, vtkIdType end)
        {
          for (vtkIdType k = begin; k < end; ++k)
          {
            std::memcpy(to + k * tuple, from + source[k] * tuple, tuple);
          }
        });
    }
    else
    {
      for (vtkIdType k = 0; k < n; ++k)
      {
        a->SetTuple(k, source[k], copy);
      }
    }
    a->Modified();
  };
  gather(positions);
  gather(diag);
  gather(off);
  gather(ids);
  gather(scalars);
  return grid;
}

/// Pass 1: classify points, count the kept ones per block, track the largest
/// tensor norm (for the bounds).
struct ClassifyWorker
{
  vtkDataArray* Tensors;
  vtkDataArray* Mask;
  int Layout;
  vtkIdType NumberOfPoints;
  unsigned char* Classes;
  vtkIdType* BlockCounts;
  vtkSMPThreadLocal<double> MaxNorm;
  vtkSMPThreadLocal<vtkIdType> Invalid, Zero, Masked;

  void Initialize()
  {
    this->MaxNorm.Local() = 0.0;
    this->Invalid.Local() = 0;
    this->Zero.Local() = 0;
    this->Masked.Local() = 0;
  }

  void operator()(vtkIdType blockBegin, vtkIdType blockEnd)
  {
    double& maxNorm = this->MaxNorm.Local();
    for (vtkIdType b = blockBegin; b < blockEnd; ++b)
    {
      const vtkIdType begin = b * BlockSize;
      const vtkIdType end = std::min(this->NumberOfPoints, begin + BlockSize);
      vtkIdType kept = 0;
      for (vtkIdType i = begin; i < end; ++i)
      {
        double t[6];
        unsigned char c = KEEP;
        if (this->Mask && this->Mask->GetComponent(i, 0) == 0.0)
        {
          c = MASKED;
          ++this->Masked.Local();
        }
        else if (!TM::ReadSymmetric(this->Tensors, i, this->Layout, t))
        {
          c = INVALID;
          ++this->Invalid.Local();
        }
        else
        {
          const double n2 = t[0] * t[0] + t[1] * t[1] + t[2] * t[2] +
            2.0 * (t[3] * t[3] + t[4] * t[4] + t[5] * t[5]);
          if (!(n2 > 0.0))
          {
            c = ZERO;
            ++this->Zero.Local();
          }
          else
          {
            maxNorm = std::max(maxNorm, std::sqrt(n2));
            ++kept;
          }
        }
        this->Classes[i] = c;
      }
      this->BlockCounts[b] = kept;
    }
  }

  void Reduce() {}
};

/// Pass 2: write the kept points' positions and canonical float tensors.
struct FillWorker
{
  vtkDataSet* Input;
  vtkDataArray* Tensors;
  int Layout;
  vtkIdType NumberOfPoints;
  vtkIdType IdOffset; // added to the point ids (composite inputs)
  const unsigned char* Classes;
  const vtkIdType* BlockOffsets;
  float* Positions;
  float* Diag;
  float* Off;
  vtkIdType* Ids;

  void operator()(vtkIdType blockBegin, vtkIdType blockEnd)
  {
    for (vtkIdType b = blockBegin; b < blockEnd; ++b)
    {
      vtkIdType k = this->BlockOffsets[b];
      const vtkIdType begin = b * BlockSize;
      const vtkIdType end = std::min(this->NumberOfPoints, begin + BlockSize);
      for (vtkIdType i = begin; i < end; ++i)
      {
        if (this->Classes[i] != KEEP)
        {
          continue;
        }
        double t[6], p[3];
        TM::ReadSymmetric(this->Tensors, i, this->Layout, t);
        this->Input->GetPoint(i, p);
        for (int c = 0; c < 3; ++c)
        {
          this->Positions[3 * k + c] = static_cast<float>(p[c]);
          this->Diag[3 * k + c] = static_cast<float>(t[c]);
          this->Off[3 * k + c] = static_cast<float>(t[3 + c]);
        }
        this->Ids[k] = this->IdOffset + i;
        ++k;
      }
    }
  }
};

// What RequestData() keeps per leaf between classifying and filling.
struct LeafPlan
{
  vtkDataSet* Data;
  vtkDataArray* Tensors;
  vtkDataArray* Scalars;
  int Layout;
  vtkIdType IdOffset;
  std::vector<unsigned char> Classes;
  std::vector<vtkIdType> Offsets;
};

// The coloring scalars: the kept tuples of every leaf (in the first leaf's
// array type); nullptr unless all leaves provide them.
vtkSmartPointer<vtkDataArray> GatherColorScalars(
  const std::vector<LeafPlan>& plans, vtkIdType total)
{
  vtkSmartPointer<vtkDataArray> colorScalars;
  bool allScalars = !plans.empty();
  for (const LeafPlan& plan : plans)
  {
    allScalars = allScalars && plan.Scalars &&
      plan.Scalars->GetNumberOfComponents() == plans[0].Scalars->GetNumberOfComponents();
  }
  if (allScalars)
  {
    vtkDataArray* first = plans[0].Scalars;
    colorScalars.TakeReference(first->NewInstance());
    colorScalars->SetName(first->GetName() ? first->GetName() : "scalars");
    colorScalars->SetNumberOfComponents(first->GetNumberOfComponents());
    colorScalars->SetNumberOfTuples(total);
    if (first->GetLookupTable())
    {
      colorScalars->SetLookupTable(first->GetLookupTable());
    }
    vtkIdType k = 0;
    for (const LeafPlan& plan : plans)
    {
      const vtkIdType n = plan.Data->GetNumberOfPoints();
      for (vtkIdType i = 0; i < n; ++i)
      {
        if (plan.Classes[i] == KEEP)
        {
          colorScalars->SetTuple(k++, i, plan.Scalars);
        }
      }
    }
  }
  return colorScalars;
}

// The statistics (largest norm, invalid, zero and masked tensors) and the
// brick grid (origin, spacing, dimensions; first glyph of every brick) the
// mapper reads.
void AddFieldData(vtkPolyData* output, const BrickGrid& grid, double maxNorm, vtkIdType invalid,
  vtkIdType zero, vtkIdType masked)
{
  vtkNew<vtkDoubleArray> stats;
  stats->SetName("sqStatistics");
  stats->SetNumberOfTuples(4);
  stats->SetValue(0, maxNorm);
  stats->SetValue(1, static_cast<double>(invalid));
  stats->SetValue(2, static_cast<double>(zero));
  stats->SetValue(3, static_cast<double>(masked));
  output->GetFieldData()->AddArray(stats);
  vtkNew<vtkDoubleArray> gridArray;
  gridArray->SetName("sqBrickGrid");
  gridArray->SetNumberOfTuples(9);
  for (int c = 0; c < 3; ++c)
  {
    gridArray->SetValue(c, grid.Origin[c]);
    gridArray->SetValue(3 + c, grid.Spacing[c]);
    gridArray->SetValue(6 + c, grid.Dimensions[c]);
  }
  output->GetFieldData()->AddArray(gridArray);
  vtkNew<vtkIdTypeArray> offsets;
  offsets->SetName("sqBrickOffsets");
  offsets->SetNumberOfTuples(static_cast<vtkIdType>(grid.Offsets.size()));
  std::copy(grid.Offsets.begin(), grid.Offsets.end(), offsets->GetPointer(0));
  output->GetFieldData()->AddArray(offsets);
}
}

//------------------------------------------------------------------------------
void vtkSuperquadricGlyphPreparer::SetTensorArray(const char* name)
{
  const std::string value = name ? name : "";
  if (value != this->TensorArray)
  {
    this->TensorArray = value;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkSuperquadricGlyphPreparer::SetMaskArray(const char* name)
{
  const std::string value = name ? name : "";
  if (value != this->MaskArray)
  {
    this->MaskArray = value;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkSuperquadricGlyphPreparer::SetColorArraySelection(
  bool visible, int scalarMode, int accessMode, int arrayId, const char* arrayName)
{
  const std::string name = arrayName ? arrayName : "";
  if (visible != this->ColorVisible || scalarMode != this->ColorScalarMode ||
    accessMode != this->ColorAccessMode || arrayId != this->ColorArrayId ||
    name != this->ColorArrayName)
  {
    this->ColorVisible = visible;
    this->ColorScalarMode = scalarMode;
    this->ColorAccessMode = accessMode;
    this->ColorArrayId = arrayId;
    this->ColorArrayName = name;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
int vtkSuperquadricGlyphPreparer::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataSet");
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkCompositeDataSet");
  return 1;
}

//------------------------------------------------------------------------------
bool vtkSuperquadricGlyphPreparer::FindLeafArrays(vtkDataSet* leaf, const std::string& where,
  vtkDataArray*& tensors, int& layout, vtkDataArray*& mask, vtkDataArray*& scalars)
{
  vtkPointData* pd = leaf->GetPointData();
  const bool named = !this->TensorArray.empty();
  tensors = named ? pd->GetArray(this->TensorArray.c_str()) : pd->GetTensors();
  if (!tensors)
  {
    if (named)
    {
      vtkErrorMacro("No point tensor array named '" << this->TensorArray << "'" << where
                                                    << ": no glyphs drawn for it.");
    }
    else
    {
      vtkErrorMacro(
        "No active point tensors" << where << " (set the tensor array name): no glyphs drawn.");
    }
    return false;
  }
  layout = TM::ResolveLayout(this->TensorLayout, tensors->GetNumberOfComponents());
  if (layout < 0)
  {
    vtkErrorMacro("Tensor array '"
      << (tensors->GetName() ? tensors->GetName() : "(unnamed)") << "'" << where << " has "
      << tensors->GetNumberOfComponents() << " components, which does not fit the layout '"
      << TM::GetLayoutName(this->TensorLayout)
      << "' (6, 7 or 9 components are needed): no glyphs drawn for it.");
    return false;
  }
  mask = nullptr;
  if (!this->MaskArray.empty())
  {
    mask = pd->GetArray(this->MaskArray.c_str());
    if (!mask)
    {
      vtkErrorMacro("No point mask array named '" << this->MaskArray << "'" << where
                                                  << ": no glyphs drawn for it.");
      return false;
    }
  }
  scalars = nullptr;
  if (this->ColorVisible)
  {
    int cellFlag = 0;
    scalars = vtkArrayDownCast<vtkDataArray>(
      vtkAbstractMapper::GetAbstractScalars(leaf, this->ColorScalarMode, this->ColorAccessMode,
        this->ColorArrayId, this->ColorArrayName.c_str(), cellFlag));
    if (cellFlag != 0)
    {
      scalars = nullptr; // glyphs sit at points: cell scalars cannot color them
    }
  }
  return true;
}

//------------------------------------------------------------------------------
int vtkSuperquadricGlyphPreparer::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkDataObject* input = vtkDataObject::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  if (!output)
  {
    vtkErrorMacro("No output polydata.");
    return 0;
  }

  // The leaves to draw.
  const std::vector<vtkDataSet*> leaves = vtkCompositeDataSet::GetDataSets(input);
  if (!vtkDataSet::SafeDownCast(input) && !vtkCompositeDataSet::SafeDownCast(input))
  {
    vtkErrorMacro("Input of type " << (input ? input->GetClassName() : "(none)")
                                   << " is not supported: a vtkDataSet or composite data set "
                                      "with a point tensor array is needed.");
    return 0;
  }

  // Per leaf: classify, then fill.
  std::vector<LeafPlan> plans;
  vtkIdType total = 0;
  vtkIdType idOffset = 0;
  vtkIdType invalid = 0, zero = 0, masked = 0;
  double maxNorm = 0.0;
  bool ok = true;
  for (size_t b = 0; b < leaves.size(); ++b)
  {
    vtkDataSet* leaf = leaves[b];
    const vtkIdType n = leaf->GetNumberOfPoints();
    const vtkIdType offset = idOffset;
    idOffset += n;
    if (n == 0)
    {
      continue;
    }
    vtkDataArray* tensors = nullptr;
    vtkDataArray* mask = nullptr;
    vtkDataArray* scalars = nullptr;
    int layout = -1;
    if (!this->FindLeafArrays(leaf, leaves.size() > 1 ? " in block " + std::to_string(b) : "",
          tensors, layout, mask, scalars))
    {
      ok = false;
      continue;
    }

    LeafPlan plan;
    plan.Data = leaf;
    plan.Tensors = tensors;
    plan.Scalars = scalars;
    plan.Layout = layout;
    plan.IdOffset = offset;
    plan.Classes.resize(n);
    const vtkIdType nBlocks = (n + BlockSize - 1) / BlockSize;
    std::vector<vtkIdType> counts(nBlocks, 0);
    ClassifyWorker classify;
    classify.Tensors = tensors;
    classify.Mask = mask;
    classify.Layout = layout;
    classify.NumberOfPoints = n;
    classify.Classes = plan.Classes.data();
    classify.BlockCounts = counts.data();
    vtkSMPTools::For(0, nBlocks, classify);
    for (double m : classify.MaxNorm)
    {
      maxNorm = std::max(maxNorm, m);
    }
    for (vtkIdType c : classify.Invalid)
    {
      invalid += c;
    }
    for (vtkIdType c : classify.Zero)
    {
      zero += c;
    }
    for (vtkIdType c : classify.Masked)
    {
      masked += c;
    }
    plan.Offsets.resize(nBlocks);
    for (vtkIdType k = 0; k < nBlocks; ++k)
    {
      plan.Offsets[k] = total;
      total += counts[k];
    }
    plans.push_back(std::move(plan));
  }

  if (invalid > 0 || zero > 0)
  {
    vtkWarningMacro(<< invalid << " tensors with NaN or infinite components and " << zero
                    << " zero tensors are not drawn.");
  }

  // Fill the compacted arrays.
  vtkNew<vtkFloatArray> positions;
  positions->SetNumberOfComponents(3);
  positions->SetNumberOfTuples(total);
  vtkNew<vtkFloatArray> diag;
  diag->SetName("sqTensorDiag");
  diag->SetNumberOfComponents(3);
  diag->SetNumberOfTuples(total);
  vtkNew<vtkFloatArray> off;
  off->SetName("sqTensorOff");
  off->SetNumberOfComponents(3);
  off->SetNumberOfTuples(total);
  vtkNew<vtkIdTypeArray> ids;
  ids->SetName("sqPointIds");
  ids->SetNumberOfTuples(total);
  for (LeafPlan& plan : plans)
  {
    FillWorker fill;
    fill.Input = plan.Data;
    fill.Tensors = plan.Tensors;
    fill.Layout = plan.Layout;
    fill.NumberOfPoints = plan.Data->GetNumberOfPoints();
    fill.IdOffset = plan.IdOffset;
    fill.Classes = plan.Classes.data();
    fill.BlockOffsets = plan.Offsets.data();
    fill.Positions = positions->GetPointer(0);
    fill.Diag = diag->GetPointer(0);
    fill.Off = off->GetPointer(0);
    fill.Ids = ids->GetPointer(0);
    vtkSMPTools::For(0, static_cast<vtkIdType>(plan.Offsets.size()), fill);
  }

  vtkSmartPointer<vtkDataArray> colorScalars = GatherColorScalars(plans, total);

  // Bricks: the glyphs sorted by the cells of a uniform grid over their
  // bounds (about 8 glyphs per cell), so that the mapper can draw them brick
  // by brick in visibility order (occlusion culling).
  const BrickGrid grid = SortIntoBricks(positions, diag, off, ids, colorScalars);

  vtkNew<vtkPoints> points;
  points->SetData(positions);
  output->Initialize();
  output->SetPoints(points);
  output->GetPointData()->AddArray(diag);
  output->GetPointData()->AddArray(off);
  output->GetPointData()->AddArray(ids);
  if (colorScalars)
  {
    output->GetPointData()->SetScalars(colorScalars);
  }
  AddFieldData(output, grid, maxNorm, invalid, zero, masked);
  return ok ? 1 : 0;
}

//------------------------------------------------------------------------------
void vtkSuperquadricGlyphPreparer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "TensorArray: " << this->TensorArray << "\n";
  os << indent << "TensorLayout: " << this->TensorLayout << "\n";
  os << indent << "MaskArray: " << this->MaskArray << "\n";
}
