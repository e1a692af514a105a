// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkLRSplineField
 * @brief   The LR-spline field of a reader output (one or several patches) ready for evaluation.
 *
 * Plain C++ (not a vtkObject). Collects the Bezier grids (volumes or surfaces) of a
 * vtkLRSplineReader output (a vtkUnstructuredGrid patch, or a
 * vtkMultiBlockDataSet / any composite of them), builds one
 * vtkLRSplineEvaluator per patch that has the field's array (the blocks of
 * other bases of a mixed IFEM result are left out), and evaluates at
 * physical points with the rule of vtkLRSplineProbeFilter: the first patch
 * (in block order) that contains the point wins.
 *
 * The physical placement comes from the field data the reader writes
 * ("LRPhysicalTransform": scale xyz then offset xyz, or a row-major 3x3
 * matrix A then offset xyz for x = A u + offset; identity if absent).
 * Patches read in geometry mode ("LRMode" = 1: the points are the control
 * points of the geometry map, isoparametric fields) are evaluated in
 * physical space by inverting that map (vtkLRSplineGeometryMap); when the
 * map is affine it is used as an affine placement (the fast path). Surface
 * patches (VTK_BEZIER_QUADRILATERAL grids, in either mode) are always
 * evaluated through their geometry map, at the closest point of the surface
 * within surfaceTolerance (relative to the element's size; see
 * vtkLRSplineGeometryMap). With parameterSpace every patch is evaluated at
 * parameter points instead.
 */

#ifndef vtkLRSplineField_h
#define vtkLRSplineField_h

#include "SplineVizCoreModule.h" // for export macro
#include "vtkLRSplineEvaluator.h"
#include "vtkLRSplineGeometryMap.h" // for DefaultSurfaceTolerance

#include <functional>
#include <memory>
#include <string>
#include <vector>

class vtkAlgorithm;
class vtkDataObject;
class vtkInformationDataObjectKey;
class vtkPointData;
class vtkPolyData;

class SPLINEVIZCORE_EXPORT vtkLRSplineField
{
public:
  /**
   * Key of a spline block's meta-data: the closed surface of the data the
   * spline was fitted to (vtkPolyData). vtkLRSplineFitter sets it on its
   * spline output's block when it extracts the data's boundary
   * (ExtractBoundary), so that vtkLRSplineVolumeMapper and ParaView's
   * LR-Spline Volume representation trim by it (Fuchs et al. §4.1) when no
   * trimming surface is connected. Shallow copies keep it; filters that make
   * new blocks drop it.
   */
  static vtkInformationDataObjectKey* TRIMMING_SURFACE();
  /// The TRIMMING_SURFACE of a top-level block of `spline`; null if none has one.
  static vtkPolyData* GetTrimmingSurface(vtkDataObject* spline);

  /**
   * Build from a data object. `arrayName` null or empty: the active vectors
   * (else scalars) of the first patch; `blocks` the k-d forest resolution
   * (null: 64^3 capped to the element count). False with a message when there
   * is no usable patch.
   */
  bool Build(vtkDataObject* source, const char* arrayName, int locatorType, const int blocks[3],
    bool parameterSpace, std::string* error,
    double surfaceTolerance = vtkLRSplineGeometryMap::DefaultSurfaceTolerance);

  /**
   * What a consumer of the field renders or evaluates, checked by the Build()
   * that takes it (0 or false: no limit). Before building, on the source: a
   * volume consumer refuses surface splines and polygonal data, and a source
   * without patches, with its own message; at most MaximumPatches patches; no
   * rational field (rational weights outside geometry mode; rational geometry
   * maps are fine). After building: at most MaximumComponents components,
   * degrees up to MaximumDegree per direction, finite coefficients. The
   * messages name the Consumer ("the volume mapper renders degrees up to 3").
   */
  struct Requirements
  {
    std::string Consumer = "the consumer";
    bool Volume = false;
    int MaximumPatches = 0;
    bool PolynomialField = false;
    int MaximumComponents = 0;
    int MaximumDegree = 0;
    bool FiniteCoefficients = false;
  };

  /**
   * Build() in data space with the default surface tolerance, checking
   * `requirements` (false with the message of the first one not met).
   */
  bool Build(vtkDataObject* source, const char* arrayName, int locatorType, const int blocks[3],
    const Requirements& requirements, std::string* error);

  /// The patches' common degrees: the largest per direction (1 at least).
  void GetCommonDegrees(int degree[3]) const;

  /**
   * Build `field` from `source` unless `key` shows it was built from the same
   * source (pointer and modification time) with the same settings; the
   * cache the filters keep between executions. `resolution` 0: automatic.
   */
  static bool BuildCached(std::unique_ptr<vtkLRSplineField>& field, std::string& key,
    vtkDataObject* source, const char* arrayName, int locatorType, int resolution,
    bool parameterSpace, std::string* error,
    double surfaceTolerance = vtkLRSplineGeometryMap::DefaultSurfaceTolerance);

  /**
   * The field a filter evaluates is its input array `idx`, selected the VTK
   * way: SetInputArrayToProcess(idx, port, 0,
   * vtkDataObject::FIELD_ASSOCIATION_POINTS, name), `port` the input port
   * of the spline. SelectedFieldName() gives the name to pass to Build():
   * "" when nothing is selected or the name is empty (the active vectors,
   * else scalars); with a selection by attribute type (e.g.
   * vtkDataSetAttributes::SCALARS) the name of that point attribute in the
   * first patch of `source` that has one. False with a message when the
   * selection is on another input port or not point data (the coefficients
   * are point data), or names an attribute no patch has.
   */
  static bool SelectedFieldName(vtkAlgorithm* algorithm, int idx, int port, vtkDataObject* source,
    std::string& name, std::string* error);

  int GetNumberOfPatches() const { return static_cast<int>(this->Patches.size()); }
  const vtkLRSplineEvaluator& GetPatch(int i) const { return *this->Patches[i]; }
  int GetNumberOfComponents() const { return this->NumberOfComponents; }
  const std::string& GetArrayName() const { return this->ArrayName; }
  vtkIdType GetNumberOfElements() const;
  /// Union of the patches' physical bounds (VTK order).
  void GetBounds(double bounds[6]) const;
  /// Largest degree over all patches.
  int GetMaximumDegree() const;
  /// Largest parametric dimension over the patches: 2 when all are surfaces.
  int GetParametricDimension() const;

  /**
   * On a surface patch: the closest point of `element` of `patch` to x and
   * the unit normal there (vtkLRSplineEvaluator::ProjectOntoSurface); false
   * for volume patches.
   */
  bool ProjectOntoSurface(
    int patch, vtkIdType element, const double x[3], double point[3], double normal[3]) const;

  /// Prepare single-precision evaluation.
  void MakeFloat();

  /**
   * Evaluate at physical x: returns the patch index or -1. `element`
   * (may be null) receives the element within that patch.
   */
  int Evaluate(
    const double x[3], double* value, double* gradient, vtkIdType* element = nullptr) const;
  int Evaluate(const float x[3], float* value, float* gradient, vtkIdType* element = nullptr) const;

  /**
   * Like Evaluate, but tries the element of the previous call first (patch
   * and element are in/out; -1 for none). Equivalent to Evaluate when the
   * patches do not overlap; with overlapping patches it falls back to the
   * full search.
   */
  int EvaluateWithHint(
    const double x[3], double* value, double* gradient, int& patch, vtkIdType& element) const;
  int EvaluateWithHint(
    const float x[3], float* value, float* gradient, int& patch, vtkIdType& element) const;

  /**
   * Evaluate at n points in parallel (vtkSMPTools); point(i, x) writes the
   * i-th point. values: n * NumberOfComponents; gradients (may be null):
   * n * 3 * NumberOfComponents; mask (may be null): 1 inside, 0 outside
   * (outside points get zeros). Returns the number of points inside.
   */
  vtkIdType EvaluatePoints(vtkIdType n, const std::function<void(vtkIdType, double[3])>& point,
    double* values, double* gradients, char* mask, vtkAlgorithm* progress = nullptr) const;

  /**
   * EvaluatePoints into new arrays added to `pd`, the output convention of
   * the probe and resampling filters: the values as doubles named like the
   * field (the active vectors with 3 components, the active scalars with
   * 1), with `gradientName` (null: no gradient) the gradient with 3 *
   * components (d/dx, d/dy, d/dz per component), and the char array
   * `maskName` (1 where a patch contains the point). Returns the number of
   * points inside.
   *
   * With `progress` (both methods), the points are evaluated in batches
   * that report progress (0 to 1) to that algorithm and honour its abort
   * (vtkSplineVizProgress::For): an aborted evaluation returns -1 and adds
   * no arrays.
   */
  vtkIdType EvaluateIntoPointData(vtkPointData* pd, vtkIdType n,
    const std::function<void(vtkIdType, double[3])>& point, const char* gradientName,
    const char* maskName, vtkAlgorithm* progress = nullptr) const;

  /// Patch and element containing x (-1 when none).
  int FindPatch(const double x[3], vtkIdType* element = nullptr) const;

private:
  std::vector<std::unique_ptr<vtkLRSplineEvaluator>> Patches;
  int NumberOfComponents = 0;
  std::string ArrayName;
  bool PatchesOverlap = false;
};

#endif
// VTK-HeaderTest-Exclude: vtkLRSplineField.h
