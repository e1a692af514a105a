// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLRSplineVolumePreparer.h"

#include "vtkLRSplineGeometryMap.h"
#include "vtkLRSplineVolumeShaderBuilder.h"

#include "vtkDataObject.h"
#include "vtkObjectFactory.h"

#include <algorithm>
#include <cmath>
#include <sstream>

vtkStandardNewMacro(vtkLRSplineVolumePreparer);

namespace
{
// Element e of a patch (its Bezier volume at the common degree, the raised
// homogeneous geometry of a curved patch) into the arrays: its box (curved:
// the physical box and shortest side), coefficients and value ranges.
// `edge`: the patch's parameter-to-data scale per direction.
struct ElementAppender
{
  std::vector<float>& Boxes;
  std::vector<std::uint32_t>& Offsets;
  std::vector<float>& Coefficients;
  std::vector<float>& ComponentRanges;
  std::vector<float>& MagnitudeRanges;
  double& MinimumSide;

  void Append(const vtkLRSplineBezierVolume& volume, vtkIdType e,
    const vtkLRSplineGeometryMap* geometryMap, const vtkLRSplineBezierVolume& geometryRaised,
    const double edge[3], int per, int nc)
  {
    const double* b = volume.GetBox(e);
    if (geometryMap)
    {
      // The physical box; its fourth value the element's shortest side
      // (data units, > 0: marks a curved element).
      const double* pb = geometryMap->GetPhysicalBox(e);
      const double side = geometryMap->GetElementMinimumSide(e);
      this->Boxes.insert(this->Boxes.end(),
        { static_cast<float>(pb[0]), static_cast<float>(pb[1]), static_cast<float>(pb[2]), 0.0f,
          static_cast<float>(pb[3]), static_cast<float>(pb[4]), static_cast<float>(pb[5]),
          static_cast<float>(side) });
      this->MinimumSide = std::min(this->MinimumSide, side);
    }
    else
    {
      this->Boxes.insert(this->Boxes.end(),
        { static_cast<float>(b[0]), static_cast<float>(b[1]), static_cast<float>(b[2]), 0.0f,
          static_cast<float>(b[3]), static_cast<float>(b[4]), static_cast<float>(b[5]), 0.0f });
    }
    this->Offsets.push_back(static_cast<std::uint32_t>(this->Coefficients.size()));
    const double* c = volume.GetElementCoefficients(e);
    for (int i = 0; i < per; ++i)
    {
      this->Coefficients.push_back(static_cast<float>(c[i]));
    }
    if (geometryMap)
    {
      const double* gc = geometryRaised.GetElementCoefficients(e);
      const int gper = 4 * per / nc;
      for (int i = 0; i < gper; ++i)
      {
        this->Coefficients.push_back(static_cast<float>(gc[i]));
      }
    }
    // Coefficient ranges (the element's values lie within them). On a
    // rational map the coefficients are w f: the ranges are of f.
    const double* gw = geometryMap ? geometryRaised.GetElementCoefficients(e) + 3 : nullptr;
    auto coefficient = [&](int i) { return gw ? c[i] / gw[4 * (i / nc)] : c[i]; };
    double magnitudeLow = 0.0, magnitudeHigh = 0.0;
    for (int comp = 0; comp < nc; ++comp)
    {
      double lo = VTK_DOUBLE_MAX, hi = -VTK_DOUBLE_MAX;
      for (int i = comp; i < per; i += nc)
      {
        lo = std::min(lo, coefficient(i));
        hi = std::max(hi, coefficient(i));
      }
      this->ComponentRanges.push_back(static_cast<float>(lo));
      this->ComponentRanges.push_back(static_cast<float>(hi));
      magnitudeLow = std::max(magnitudeLow, lo > 0 ? lo : (hi < 0 ? -hi : 0.0));
    }
    for (int i = 0; i < per; i += nc)
    {
      double m2 = 0.0;
      for (int comp = 0; comp < nc; ++comp)
      {
        m2 += coefficient(i + comp) * coefficient(i + comp);
      }
      magnitudeHigh = std::max(magnitudeHigh, std::sqrt(m2));
    }
    this->MagnitudeRanges.push_back(static_cast<float>(magnitudeLow));
    this->MagnitudeRanges.push_back(static_cast<float>(magnitudeHigh));
    for (int k = 0; k < 3 && !geometryMap; ++k)
    {
      this->MinimumSide = std::min(this->MinimumSide, (b[k + 3] - b[k]) * edge[k]);
    }
  }
};
}

//------------------------------------------------------------------------------
bool vtkLRSplineVolumePreparer::Fail(const std::string& message)
{
  this->Valid = false;
  this->Error = message;
  return false;
}

//------------------------------------------------------------------------------
void vtkLRSplineVolumePreparer::Clear()
{
  this->Valid = false;
  this->Patches.clear();
  this->Heads.clear();
  this->NodeWords.clear();
  this->NodeSplits.clear();
  this->Octree.clear();
  this->Boxes.clear();
  this->Offsets.clear();
  this->Coefficients.clear();
  this->ComponentRanges.clear();
  this->MagnitudeRanges.clear();
  this->SkipKey.clear();
  this->SkippedElements = 0;
}

//------------------------------------------------------------------------------
void vtkLRSplineVolumePreparer::Reset()
{
  this->BuildKey.clear();
  this->Clear();
  this->Error.clear();
}

//------------------------------------------------------------------------------
bool vtkLRSplineVolumePreparer::Update(
  vtkDataObject* input, const char* arrayName, int locatorType, int forestResolution)
{
  if (!input)
  {
    this->Reset();
    return this->Fail("no input");
  }
  std::ostringstream key;
  key << input << ' ' << input->GetMTime() << ' ' << (arrayName ? arrayName : "") << ' '
      << locatorType << ' ' << forestResolution;
  if (key.str() == this->BuildKey)
  {
    return this->Valid;
  }
  this->BuildKey = key.str();
  this->Clear();
  this->BuildTime.Modified();

  // The spline's checks (vtkLRSplineField): what the shaders can render.
  vtkLRSplineField::Requirements needs;
  needs.Consumer = "the volume mapper";
  needs.Volume = true;
  needs.MaximumPatches = vtkLRSplineVolumeShaderBuilder::MaximumPatches;
  needs.PolynomialField = true;
  needs.MaximumComponents = 3;
  needs.MaximumDegree = 3;
  needs.FiniteCoefficients = true;
  std::string message;
  const int blocks[3] = { forestResolution, forestResolution, forestResolution };
  if (!this->Field.Build(
        input, arrayName, locatorType, forestResolution > 0 ? blocks : nullptr, needs, &message))
  {
    return this->Fail(message);
  }
  // Common degrees (raised exactly to the largest per direction).
  const int nc = this->Field.GetNumberOfComponents();
  this->Field.GetCommonDegrees(this->Degree);
  this->NumberOfComponents = nc;
  this->Field.GetBounds(this->Bounds);
  this->MinimumSide = VTK_DOUBLE_MAX;
  this->Curved = false;

  // Flatten every patch into the arrays.
  const int* degree = this->Degree;
  const int per = (degree[0] + 1) * (degree[1] + 1) * (degree[2] + 1) * nc;
  const vtkIdType totalElements = this->Field.GetNumberOfElements();
  const double coefficientCount = static_cast<double>(totalElements) * per;
  if (coefficientCount > 2.0e9)
  {
    return this->Fail("the spline has " + std::to_string(totalElements) +
      " elements: too many coefficients for the GPU buffers (limit 2^31)");
  }
  this->Coefficients.reserve(static_cast<std::size_t>(coefficientCount));
  this->Boxes.reserve(static_cast<std::size_t>(8 * totalElements));
  this->Offsets.reserve(static_cast<std::size_t>(totalElements));
  const bool kdLocator = locatorType != vtkLRSplineElementLocator::OCTREE &&
    locatorType != vtkLRSplineElementLocator::TEXTURE;
  vtkIdType firstElement = 0;
  for (int p = 0; p < this->Field.GetNumberOfPatches(); ++p)
  {
    if (!this->FlattenPatch(p, kdLocator, firstElement))
    {
      return false;
    }
  }
  this->Valid = true;
  this->Error.clear();
  return true;
}

//------------------------------------------------------------------------------
bool vtkLRSplineVolumePreparer::FlattenPatch(int p, bool kdLocator, vtkIdType& firstElement)
{
  const int* degree = this->Degree;
  const int nc = this->NumberOfComponents;
  const int per = (degree[0] + 1) * (degree[1] + 1) * (degree[2] + 1) * nc;
  const vtkLRSplineEvaluator& patch = this->Field.GetPatch(p);
  const vtkLRSplineElementLocator& locator = patch.GetLocator();
  const vtkLRSplineBezierVolume* volume = &patch.GetVolume();
  vtkLRSplineBezierVolume raised;
  if (volume->Degree[0] != degree[0] || volume->Degree[1] != degree[1] ||
    volume->Degree[2] != degree[2])
  {
    raised = *volume;
    raised.CoefficientsFloat.clear();
    if (!raised.ElevateDegree(degree))
    {
      return this->Fail("patch " + std::to_string(p) + ": degree elevation failed");
    }
    volume = &raised;
  }
  // A curved patch: its geometry's Bezier coefficients follow the
  // field's per element, its search structure is the geometry map's.
  const vtkLRSplineGeometryMap* geometryMap = patch.GetGeometry();
  vtkLRSplineBezierVolume geometryRaised;
  if (geometryMap)
  {
    if (!kdLocator)
    {
      return this->Fail("patch " + std::to_string(p) +
        " has a curved geometry: its elements are found with a k-d forest or tree, not the " +
        "octree or the look-up texture");
    }
    geometryRaised = geometryMap->GetVolume();
    geometryRaised.CoefficientsFloat.clear();
    if (geometryRaised.NumberOfComponents == 3)
    {
      // The shader reads homogeneous coefficients (w x, w y, w z, w).
      std::vector<double> h(geometryRaised.Coefficients.size() / 3 * 4);
      for (std::size_t k = 0; k < h.size() / 4; ++k)
      {
        std::copy(
          &geometryRaised.Coefficients[3 * k], &geometryRaised.Coefficients[3 * k] + 3, &h[4 * k]);
        h[4 * k + 3] = 1.0;
      }
      geometryRaised.Coefficients.swap(h);
      geometryRaised.NumberOfComponents = 4;
    }
    if (!geometryRaised.ElevateDegree(degree))
    {
      return this->Fail("patch " + std::to_string(p) + ": the geometry's degree is too high");
    }
    this->Curved = true;
  }
  const vtkLRSplineElementLocator& search = geometryMap ? geometryMap->GetLocator() : locator;
  PatchInfo info;
  info.Curved = geometryMap ? 1 : 0;
  const double* domain = search.GetDomain();
  const double* A = patch.GetMatrix();
  const double* inverse = patch.GetInverseMatrix();
  const double* offset = patch.GetOffset();
  double patchBounds[6];
  patch.GetBounds(patchBounds);
  double edge[3];
  for (int k = 0; k < 3; ++k)
  {
    edge[k] = std::sqrt(A[k] * A[k] + A[3 + k] * A[3 + k] + A[6 + k] * A[6 + k]);
    info.Lo[k] = static_cast<float>(domain[k]);
    info.Hi[k] = static_cast<float>(domain[k + 3]);
    info.Offset[k] = static_cast<float>(offset[k]);
    info.Edge[k] = static_cast<float>(edge[k]);
    info.BoxLo[k] = static_cast<float>(patchBounds[2 * k]);
    info.BoxHi[k] = static_cast<float>(patchBounds[2 * k + 1]);
  }
  for (int k = 0; k < 9; ++k)
  {
    info.Inverse[k] = static_cast<float>(inverse[k]);
  }
  info.Starts[0] = static_cast<int>(this->Heads.size());
  info.Starts[1] = static_cast<int>(this->NodeWords.size());
  info.Starts[2] = static_cast<int>(this->Octree.size());
  info.Starts[3] = static_cast<int>(firstElement);
  if (search.GetType() == vtkLRSplineElementLocator::OCTREE)
  {
    info.Locator = 1;
    const auto& oct = search.GetOctreeNodes();
    this->Octree.insert(this->Octree.end(), oct.begin(), oct.end());
  }
  else
  {
    info.Locator = 0;
    const int* nb = search.GetNumberOfBlocks();
    std::copy(nb, nb + 3, info.Blocks);
    const auto& heads = search.GetHeads();
    const auto& words = search.GetNodeWords();
    const std::vector<float> splits = search.GetNodeSplitsFloat();
    this->Heads.insert(this->Heads.end(), heads.begin(), heads.end());
    this->NodeWords.insert(this->NodeWords.end(), words.begin(), words.end());
    this->NodeSplits.insert(this->NodeSplits.end(), splits.begin(), splits.end());
  }
  ElementAppender append{ this->Boxes, this->Offsets, this->Coefficients, this->ComponentRanges,
    this->MagnitudeRanges, this->MinimumSide };
  const vtkIdType ne = volume->GetNumberOfElements();
  for (vtkIdType e = 0; e < ne; ++e)
  {
    append.Append(*volume, e, geometryMap, geometryRaised, edge, per, nc);
  }
  firstElement += ne;
  this->Patches.push_back(info);
  return true;
}

//------------------------------------------------------------------------------
std::size_t vtkLRSplineVolumePreparer::GetNumberOfBytes() const
{
  return 4 *
    (this->Heads.size() + this->NodeWords.size() + this->Octree.size() + this->Offsets.size() +
      this->NodeSplits.size() + this->Boxes.size() + this->Coefficients.size());
}

//------------------------------------------------------------------------------
void vtkLRSplineVolumePreparer::GetValueRange(vtkIdType e, int component, float range[2]) const
{
  const int nc = this->NumberOfComponents;
  const float* r = component < 0 && nc > 1
    ? &this->MagnitudeRanges[2 * e]
    : &this->ComponentRanges[2 * (nc * e + (nc == 1 ? 0 : component))];
  range[0] = r[0];
  range[1] = r[1];
}

//------------------------------------------------------------------------------
vtkIdType vtkLRSplineVolumePreparer::UpdateSkipFlags(
  int component, const std::function<bool(double, double)>& skip)
{
  const vtkIdType ne = static_cast<vtkIdType>(this->Offsets.size());
  vtkIdType skipped = 0;
  for (vtkIdType e = 0; e < ne; ++e)
  {
    float r[2];
    this->GetValueRange(e, component, r);
    // (Curved elements are never skipped: the jump to an element's exit is
    // computed for parameter boxes.)
    const bool flag = this->Boxes[8 * e + 7] == 0.0f && skip(r[0], r[1]);
    this->Boxes[8 * e + 3] = flag ? 1.0f : 0.0f;
    skipped += flag ? 1 : 0;
  }
  this->SkippedElements = skipped;
  return skipped;
}

vtkIdType vtkLRSplineVolumePreparer::UpdateSkipFlags(
  int component, const std::vector<std::array<double, 2>>& visibleRanges)
{
  return this->UpdateSkipFlags(component,
    [&visibleRanges](double lo, double hi)
    {
      for (const auto& v : visibleRanges)
      {
        if (v[0] <= hi && v[1] >= lo)
        {
          return false;
        }
      }
      return true;
    });
}

//------------------------------------------------------------------------------
void vtkLRSplineVolumePreparer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Valid: " << this->Valid << "\n";
  os << indent << "ErrorMessage: " << this->Error << "\n";
  os << indent << "Degree: " << this->Degree[0] << " " << this->Degree[1] << " " << this->Degree[2]
     << "\n";
  os << indent << "NumberOfComponents: " << this->NumberOfComponents << "\n";
  os << indent << "NumberOfPatches: " << this->Patches.size() << "\n";
  os << indent << "NumberOfElements: " << this->Offsets.size() << "\n";
  os << indent << "MinimumSide: " << this->MinimumSide << "\n";
  os << indent << "Curved: " << this->Curved << "\n";
  os << indent << "NumberOfBytes: " << this->GetNumberOfBytes() << "\n";
  os << indent << "NumberOfSkippedElements: " << this->SkippedElements << "\n";
}
