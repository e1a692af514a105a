// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkStreamlineSelection
 * @brief   Virtual dissection of a tractogram: keeps the streamlines that pass
 * through, end in or avoid regions (spheres, boxes, implicit functions, label images).
 *
 * Input: polylines (a tractogram as vtkTractogramReader gives it), or a
 * composite data set whose polydata leaves are processed one by one. Each
 * line cell is a streamline. Every region has a role: INCLUDE (some segment
 * touches it), EXCLUDE (no segment may touch it) or ENDPOINT (EndpointMode:
 * either end point inside, or both). The INCLUDE and ENDPOINT regions combine
 * with AND or OR (IncludeCombination); a streamline is selected when that
 * holds (or there are none) and it touches no EXCLUDE region.
 *
 * Segment tests (regions are closed sets; a single-point streamline is a point):
 * - sphere: the closest point of each segment to the centre (exact);
 * - box, axis-aligned or oriented (any invertible affine map of a box): slab
 *   clipping of the segment in the box's frame (exact);
 * - vtkImplicitFunction (inside: value <= 0): a vtkSphere or vtkBox, with no
 *   or a linear Transform, is tested exactly as above; any other function is
 *   evaluated at both ends of each segment and at most ImplicitFunctionStep
 *   apart along it (a part of the region thinner than that can be missed);
 * - label image (vtkImageData with origin, spacing and direction matrix, as
 *   vtkNIfTIVolumeReader places NIfTI volumes; a one-component point or cell
 *   array; a set of label values): every voxel a segment passes through, by
 *   a 3D voxel walk (Amanatides and Woo) in index space (exact up to rounding
 *   on voxel faces; a point on a face belongs to the voxel of higher index).
 * A point with a NaN coordinate is inside no region.
 *
 * Output (OutputMode): SELECTED_STREAMLINES, the selected lines with their
 * point and cell data (other cell types not copied); or MARK_STREAMLINES, the
 * input with a cell array "Selected" (unsigned char 0/1). vtkSMPTools over
 * streamlines, progress and abort (an aborted run gives an empty output).
 * Bad input is an error (RequestData returns 0, empty output): a radius <= 0,
 * min > max, a singular box map, an empty label set, a label image without
 * the named one-component array, a null function or image. No regions at all
 * selects every streamline, with a warning.
 */
#ifndef vtkStreamlineSelection_h
#define vtkStreamlineSelection_h

#include "SplineVizFiltersModule.h" // for export macro
#include "vtkPassInputTypeAlgorithm.h"

#include <memory> // for std::unique_ptr

class vtkIdList;
class vtkImageData;
class vtkImplicitFunction;
class vtkMatrix4x4;
class vtkPolyData;

class SPLINEVIZFILTERS_EXPORT vtkStreamlineSelection : public vtkPassInputTypeAlgorithm
{
public:
  static vtkStreamlineSelection* New();
  vtkTypeMacro(vtkStreamlineSelection, vtkPassInputTypeAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Roles
  {
    INCLUDE = 0,  ///< the streamline must touch the region
    EXCLUDE = 1,  ///< the streamline must not touch the region
    ENDPOINT = 2, ///< an end point (or both, EndpointMode) must be inside
  };

  ///@{
  /**
   * Add a region with a role (INCLUDE, EXCLUDE, ENDPOINT); each returns the
   * region's index. Regions are checked when the filter runs (bad ones make
   * it fail). The objects passed are referenced, not copied: changing them
   * re-runs the filter.
   * AddOrientedBox: the box `bounds` (xmin, xmax, ymin, ymax, zmin, zmax) in
   * its own frame, placed in the world by the affine `boxToWorld`.
   * AddLabelImage: the voxels of `image` whose `arrayName` value is one of
   * `labels` (more with AddRegionLabel).
   */
  int AddSphere(double cx, double cy, double cz, double radius, int role);
  int AddSphere(const double center[3], double radius, int role);
  int AddBox(const double bounds[6], int role);
  int AddOrientedBox(const double bounds[6], vtkMatrix4x4* boxToWorld, int role);
  int AddImplicitFunction(vtkImplicitFunction* function, int role);
  int AddLabelImage(vtkImageData* image, const char* arrayName, vtkIdList* labels, int role);
  void AddRegionLabel(int region, vtkIdType label);
  ///@}

  /// Remove every region.
  void RemoveAllRegions();
  int GetNumberOfRegions();

  enum IncludeCombinations
  {
    COMBINE_AND = 0, ///< every INCLUDE and ENDPOINT region must hold
    COMBINE_OR = 1   ///< one of them suffices
  };
  ///@{
  /// How INCLUDE and ENDPOINT regions combine. Default COMBINE_AND.
  vtkSetClampMacro(IncludeCombination, int, COMBINE_AND, COMBINE_OR);
  vtkGetMacro(IncludeCombination, int);
  void SetIncludeCombinationToAnd() { this->SetIncludeCombination(COMBINE_AND); }
  void SetIncludeCombinationToOr() { this->SetIncludeCombination(COMBINE_OR); }
  ///@}

  enum EndpointModes
  {
    EITHER_END = 0, ///< the first or the last point inside
    BOTH_ENDS = 1   ///< the first and the last point inside
  };
  ///@{
  /// Which end points an ENDPOINT region needs. Default EITHER_END.
  vtkSetClampMacro(EndpointMode, int, EITHER_END, BOTH_ENDS);
  vtkGetMacro(EndpointMode, int);
  void SetEndpointModeToEitherEnd() { this->SetEndpointMode(EITHER_END); }
  void SetEndpointModeToBothEnds() { this->SetEndpointMode(BOTH_ENDS); }
  ///@}

  enum OutputModes
  {
    SELECTED_STREAMLINES = 0, ///< only the selected streamlines
    MARK_STREAMLINES = 1      ///< all, with the cell array "Selected" (0/1)
  };
  ///@{
  /// What the output holds. Default SELECTED_STREAMLINES.
  vtkSetClampMacro(OutputMode, int, SELECTED_STREAMLINES, MARK_STREAMLINES);
  vtkGetMacro(OutputMode, int);
  void SetOutputModeToSelectedStreamlines() { this->SetOutputMode(SELECTED_STREAMLINES); }
  void SetOutputModeToMarkStreamlines() { this->SetOutputMode(MARK_STREAMLINES); }
  ///@}

  ///@{
  /**
   * Largest distance between the evaluations of a general implicit function
   * along a segment, in world units; 0 (the default): a thousandth of the
   * diagonal of the input's bounds.
   */
  vtkSetClampMacro(ImplicitFunctionStep, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(ImplicitFunctionStep, double);
  ///@}

  /// Number of streamlines selected by the last run (all blocks).
  vtkGetMacro(NumberOfSelectedStreamlines, vtkIdType);

  /// Includes the regions' objects (functions, images, matrices).
  vtkMTimeType GetMTime() override;

protected:
  vtkStreamlineSelection();
  ~vtkStreamlineSelection() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int IncludeCombination = COMBINE_AND;
  int EndpointMode = EITHER_END;
  int OutputMode = SELECTED_STREAMLINES;
  double ImplicitFunctionStep = 0.0;
  vtkIdType NumberOfSelectedStreamlines = 0;

private:
  vtkStreamlineSelection(const vtkStreamlineSelection&) = delete;
  void operator=(const vtkStreamlineSelection&) = delete;

  int AddRegion(int role);
  int SelectBlock(vtkPolyData* input, vtkPolyData* output, double from, double to);
  void MarkSelected(vtkPolyData* input, const unsigned char* selected, vtkPolyData* output);
  void CopySelected(vtkPolyData* input, const unsigned char* selected, vtkPolyData* output);

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
