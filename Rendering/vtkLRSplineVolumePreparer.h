// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkLRSplineVolumePreparer
 * @brief   The CPU side of vtkLRSplineVolumeMapper: the spline as flat arrays (internal).
 *
 * The data half of the LR-spline volume mapper, as vtkLRSplineVolumeShaderBuilder
 * is its shader-text half: no OpenGL. Update() builds the vtkLRSplineField of
 * the mapper's input (field array, element locator, forest resolution), checked
 * by the field's Requirements for what the shaders render (a volume, at most
 * MaximumPatches patches, a polynomial field of at most 3 components, degrees
 * up to 3, finite coefficients), and flattens it into the arrays the mapper
 * uploads (Fuchs et al. §3.2, §4): per patch its search structure (k-d forest
 * heads, node words and splits, or octree nodes) and PatchInfo (parameter
 * domain, placement, box, where its structure and elements start); per
 * element, at the common degrees (raised exactly), its box (two texels:
 * lo + skip flag, hi + shortest side of a curved element), the offset of its
 * Bernstein coefficients and the coefficients (followed, for a curved patch,
 * by the homogeneous coefficients of its geometry map); the range of its
 * coefficients per component and of the magnitude (the convex hull property
 * bounds its values by them), from which UpdateSkipFlags() sets the skip flags
 * of empty-space skipping (§4.1).
 *
 * Internal to vtkLRSplineVolumeMapper (not wrapped); unit-tested by
 * TestLRSplineVolumePreparer.
 *
 * @sa vtkLRSplineVolumeMapper vtkLRSplineVolumeShaderBuilder vtkLRSplineField
 */
#ifndef vtkLRSplineVolumePreparer_h
#define vtkLRSplineVolumePreparer_h

#include "SplineVizRenderingModule.h" // for export macro
#include "vtkLRSplineField.h" // for vtkLRSplineField
#include "vtkObject.h"
#include "vtkTimeStamp.h" // for vtkTimeStamp

#include <array>      // for std::array
#include <cstdint>    // for std::uint32_t
#include <functional> // for std::function
#include <string>     // for std::string
#include <vector>     // for std::vector

class vtkDataObject;

class SPLINEVIZRENDERING_EXPORT vtkLRSplineVolumePreparer : public vtkObject
{
public:
  static vtkLRSplineVolumePreparer* New();
  vtkTypeMacro(vtkLRSplineVolumePreparer, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Per patch: what the shader needs to map data points to parameters and to find elements.
  struct PatchInfo
  {
    float Lo[3], Hi[3];             ///< parameter domain (curved: the physical one)
    float Inverse[9];               ///< u = Inverse (x - offset), row-major
    float Offset[3];                ///< x = A u + offset
    float Edge[3];                  ///< |A e_d|: data length of a unit parameter step
    float BoxLo[3], BoxHi[3];       ///< data box
    int Blocks[3] = { 1, 1, 1 };    ///< forest resolution
    int Starts[4] = { 0, 0, 0, 0 }; ///< heads, nodes, octree, first element
    int Locator = 0;                ///< 0: forest-like, 1: octree
    int Curved = 0;                 ///< 1: a curved geometry map
  };

  /**
   * Build the field of `input` (`arrayName` null or empty: the active vectors,
   * else scalars; `locatorType` a vtkLRSplineElementLocator::LocatorType;
   * `forestResolution` > 0 the k-d forest's trees per direction, 0 automatic)
   * and its arrays, unless they were built from the same input (pointer and
   * modification time) and settings: then the previous outcome. False with
   * GetErrorMessage() when the input cannot be rendered (the field's message).
   */
  bool Update(vtkDataObject* input, const char* arrayName, int locatorType, int forestResolution);

  /// Forget the build: invalid, and the next Update() builds again.
  void Reset();

  /// The last Update() succeeded.
  bool IsValid() const { return this->Valid; }
  /// Why the last Update() failed (empty after a success).
  const std::string& GetErrorMessage() const { return this->Error; }
  /// Changes with every build (also a failed one).
  vtkMTimeType GetBuildTime() const { return this->BuildTime.GetMTime(); }

  ///@{
  /// The built field and what the shaders are compiled for (after a successful Update()).
  const vtkLRSplineField& GetField() const { return this->Field; }
  const int* GetDegree() const { return this->Degree; }
  int GetNumberOfComponents() const { return this->NumberOfComponents; }
  int GetNumberOfPatches() const { return static_cast<int>(this->Patches.size()); }
  vtkIdType GetNumberOfElements() const { return static_cast<vtkIdType>(this->Offsets.size()); }
  /// Union of the patches' bounds (VTK order).
  const double* GetBounds() const { return this->Bounds; }
  /// The shortest element side, data units (the finest adaptive step's scale).
  double GetMinimumSide() const { return this->MinimumSide; }
  /// Some patch has a curved geometry map.
  bool GetCurved() const { return this->Curved; }
  ///@}

  ///@{
  /// The arrays to upload (layouts: the class comment and glsl/vtkLRSplineVolumeFS.glsl).
  const std::vector<PatchInfo>& GetPatches() const { return this->Patches; }
  const std::vector<std::uint32_t>& GetHeads() const { return this->Heads; }
  const std::vector<std::uint32_t>& GetNodeWords() const { return this->NodeWords; }
  const std::vector<float>& GetNodeSplits() const { return this->NodeSplits; }
  const std::vector<std::uint32_t>& GetOctree() const { return this->Octree; }
  const std::vector<float>& GetBoxes() const { return this->Boxes; }
  const std::vector<std::uint32_t>& GetOffsets() const { return this->Offsets; }
  const std::vector<float>& GetCoefficients() const { return this->Coefficients; }
  /// Bytes of all the arrays to upload.
  std::size_t GetNumberOfBytes() const;
  ///@}

  ///@{
  /**
   * Per element, the range (low, high) of its Bezier coefficients, which
   * bounds its values: per component (2 * components values per element) and
   * bounds of the magnitude (2 per element). On a rational map, of f (not w f).
   */
  const std::vector<float>& GetComponentRanges() const { return this->ComponentRanges; }
  const std::vector<float>& GetMagnitudeRanges() const { return this->MagnitudeRanges; }
  /// Element e's range for `component` (-1: the magnitude; a scalar field: its value).
  void GetValueRange(vtkIdType e, int component, float range[2]) const;
  ///@}

  ///@{
  /**
   * Set the skip flags (fourth value of an element's first box texel: 1
   * skip, 0 not) of all elements: an element is skipped when `skip` says so
   * for its value range (GetValueRange for `component`); curved elements
   * never are (the jump to an element's exit is computed for parameter
   * boxes). Returns the number of skipped elements.
   */
  vtkIdType UpdateSkipFlags(int component, const std::function<bool(double, double)>& skip);
  /// The same, skipping the elements whose range meets none of the closed `visibleRanges`.
  vtkIdType UpdateSkipFlags(int component, const std::vector<std::array<double, 2>>& visibleRanges);
  vtkIdType GetNumberOfSkippedElements() const { return this->SkippedElements; }
  ///@}

  ///@{
  /**
   * What the caller computed the skip flags for (its settings as text);
   * cleared by every build: compare to know whether to compute them again.
   */
  void SetSkipKey(const std::string& key) { this->SkipKey = key; }
  const std::string& GetSkipKey() const { return this->SkipKey; }
  ///@}

protected:
  vtkLRSplineVolumePreparer() = default;
  ~vtkLRSplineVolumePreparer() override = default;

private:
  vtkLRSplineVolumePreparer(const vtkLRSplineVolumePreparer&) = delete;
  void operator=(const vtkLRSplineVolumePreparer&) = delete;

  bool Fail(const std::string& message);
  void Clear();
  // Patch p into the arrays; `kdLocator`: a k-d forest or tree (curved
  // patches need one); firstElement advances past its elements.
  bool FlattenPatch(int p, bool kdLocator, vtkIdType& firstElement);

  vtkLRSplineField Field;
  std::string BuildKey;
  bool Valid = false;
  std::string Error;
  vtkTimeStamp BuildTime;
  int Degree[3] = { 1, 1, 1 };
  int NumberOfComponents = 1;
  double Bounds[6] = { 0, -1, 0, -1, 0, -1 };
  double MinimumSide = 0.0;
  bool Curved = false;
  std::vector<PatchInfo> Patches;
  std::vector<std::uint32_t> Heads, NodeWords, Octree, Offsets;
  std::vector<float> NodeSplits, Boxes, Coefficients;
  std::vector<float> ComponentRanges, MagnitudeRanges;
  std::string SkipKey;
  vtkIdType SkippedElements = 0;
};

#endif
