// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkLRSplineImageFitter
 * @brief   Fits an LR-spline volume to a scalar image by least squares and local refinement
 * until a tolerance is met at every voxel.
 *
 * The data path of Fuchs et al., "Direct interactive visualization of locally
 * refined spline volumes": the LR splines they render approximate sampled
 * data, refined where it varies. This filter makes one from a 3D
 * vtkImageData (a scan, a simulation on a grid), to be volume rendered,
 * probed and traced as an exact spline. Input: an image (or a composite of
 * them, one patch each) with a one-component point array
 * (SetInputArrayToProcess; default: the active scalars), at least 2 voxels
 * per direction, an identity direction matrix and finite values.
 *
 * Method: parameters are the voxel index coordinates (x = origin + spacing *
 * u). From a tensor-product spline of degree Degree (default 2, 2, 2) with
 * InitialNumberOfElements (at most one per voxel interval, or one per voxel
 * with knots on voxel faces) it repeats: regularized least squares on the voxel
 * values (conjugate gradients; Regularization pulls basis functions that see
 * less than one voxel towards the previous fit); the error at every voxel;
 * on every element above Tolerance (ABSOLUTE, or RELATIVE to the data range:
 * the default, 2 %), structured mesh refinement of its basis function of
 * smallest support (Johannessen, Kvamsdal and Dokken 2014), with knots on
 * voxel faces or centres (AlignKnotsToVoxels). It stops when the tolerance
 * holds at every voxel, or with a warning at MaximumNumberOfElements,
 * MaximumRefinementLevels or MinimumElementSize.
 *
 * Output: a vtkMultiBlockDataSet in vtkLRSplineReader's format (field mode),
 * the point array OutputFieldName, cell data "LRFitElementMaxError" and field data
 * "LRFit..." (errors, tolerance, iterations, history), also from the getters.
 * FileName: also write a .lr file (read it back with PhysicalBounds = the
 * image's bounds). Every piece fits the whole image and keeps its share of
 * the elements; progress per iteration, abort after the current one.
 *
 * The settings, checks and results it shares with vtkLRSplineFitter are
 * vtkLRSplineFitterBase's. Also refused before allocating: a missing,
 * multi-component or cell array, more than 2^27 voxels, a rotated image,
 * non-positive spacing, NaN or infinite voxels. Details: docs/components.md,
 * "Fitting an LR spline to an image".
 */

#ifndef vtkLRSplineImageFitter_h
#define vtkLRSplineImageFitter_h

#include "SplineVizFiltersModule.h" // for export macro
#include "vtkLRSplineFitterBase.h"
#include "vtkSmartPointer.h" // for BuildOutputBlock

#include <cstddef> // for std::size_t
#include <string>  // for GetStopReason
#include <vector>  // for CollectImages

class vtkDataArray;
class vtkImageData;
class vtkMultiBlockDataSet;
class vtkUnstructuredGrid;

class SPLINEVIZFILTERS_EXPORT vtkLRSplineImageFitter : public vtkLRSplineFitterBase
{
public:
  static vtkLRSplineImageFitter* New();
  vtkTypeMacro(vtkLRSplineImageFitter, vtkLRSplineFitterBase);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * No split leaves an element side shorter than this many voxels. Default
   * 0.5 (with aligned knots: one element per voxel at the finest, half a
   * voxel at the image's faces).
   */
  vtkSetClampMacro(MinimumElementSize, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(MinimumElementSize, double);
  ///@}

  ///@{
  /**
   * Knots on voxel faces (even degrees) or voxel centres (odd degrees): the
   * initial breaks and every split are rounded to them (default on). Off:
   * exact halvings of the initial elements, dyadic knots as the octree and
   * lookup-texture element searches need (vtkLRSplineElementLocator), but
   * elements at the finest level are then not aligned with the voxels.
   */
  vtkSetMacro(AlignKnotsToVoxels, vtkTypeBool);
  vtkGetMacro(AlignKnotsToVoxels, vtkTypeBool);
  vtkBooleanMacro(AlignKnotsToVoxels, vtkTypeBool);
  ///@}

protected:
  vtkLRSplineImageFitter();
  ~vtkLRSplineImageFitter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  /// The shared settings and a finite MinimumElementSize (else an error, false).
  bool CheckSettings() override;

  double MinimumElementSize = 0.5;
  vtkTypeBool AlignKnotsToVoxels = 1;

private:
  vtkLRSplineImageFitter(const vtkLRSplineImageFitter&) = delete;
  void operator=(const vtkLRSplineImageFitter&) = delete;

  /// The input image, or the leaves of a composite input (all images); false after an error.
  bool CollectImages(vtkDataObject* input, std::vector<vtkImageData*>& images);
  /**
   * An image that can be fitted (3D, not too large, axis-aligned, a scalar
   * point array to fit): its voxel counts `n`, the placement of its first
   * voxel (`offset`) and spacing (`scale`) and the array; false after an
   * error (`which` names the block).
   */
  bool CheckImage(vtkImageData* image, const std::string& which, int n[3], double offset[3],
    double scale[3], vtkDataArray*& array);
  /// The arrays' values as doubles and their range over all; false (an error) at NaN or infinity.
  bool ReadValues(const std::vector<vtkDataArray*>& arrays,
    std::vector<std::vector<double>>& values, double range[2]);
  /// Why the refinement stopped (a vtkLRSplineFitCore::Outcome other than FAILED or REFINED).
  std::string GetStopReason(int outcome) const;

  struct Job;
  struct BlockFit;
  /// Every image checked (CheckImage), one job each; false after an error.
  bool PrepareJobs(const std::vector<vtkImageData*>& images, std::vector<Job>& jobs);
  /**
   * Fit job `b`: least squares on the initial spline, then refinement of
   * the elements out of tolerance until it is met or the refinement stops;
   * the Bezier form and its errors at the voxels. False after an error.
   */
  bool FitBlock(const std::vector<Job>& jobs, std::size_t b, double tolerance, BlockFit& result);
  /// The block's warning when it missed the tolerance, and the totals it adds to.
  void ReportBlock(const std::vector<Job>& jobs, std::size_t b, double tolerance, BlockFit& result);
  /// The output block of this piece's elements; nullptr after an error.
  vtkSmartPointer<vtkUnstructuredGrid> BuildOutputBlock(const std::vector<Job>& jobs, std::size_t b,
    double tolerance, const double range[2], int piece, int numPieces, BlockFit& result);
};

#endif
