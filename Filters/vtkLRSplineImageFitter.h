// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkLRSplineImageFitter
 * @brief   Fits an LR-spline volume to a scalar image by least squares and local refinement
 * until a tolerance is met at every voxel.
 *
 * The real data path of Fuchs et al., "Direct interactive visualization of
 * locally refined spline volumes": the LR splines they render (an MR brain,
 * simulation fields) are approximations of sampled data, refined locally where
 * the data varies. This filter makes such an approximation from a 3D
 * vtkImageData (a CT/MR scan, a simulation sampled on a grid), so that it can
 * be volume rendered, probed and traced as an exact spline.
 *
 * Input: a vtkImageData (or a composite data set of them; each image becomes
 * its own patch) with a one-component point-data array chosen with
 * SetInputArrayToProcess (default: the active scalars), at least 2 voxels in
 * every direction, an identity direction matrix (rotated images are refused:
 * the output's parameter-to-physical map is a per-axis scale and offset) and
 * no NaN or infinite values.
 *
 * Method. The spline's parameter domain is the image's structured (voxel
 * index) coordinates, [0, nx-1] x [0, ny-1] x [0, nz-1], so that voxels sit
 * at integer parameters and element sides are measured in voxels; the
 * physical map is x = origin + spacing * u ("LRPhysicalTransform"). It starts
 * from a tensor-product spline of tri-degree Degree (default 2, 2, 2) with
 * InitialNumberOfElements elements per direction and repeats:
 *
 * 1. Least squares on the voxel values: minimize
 *      sum_v (s(x_v) - f_v)^2 + sum_i delta_i (c_i - c_i^prev)^2
 *    over the coefficients c_i. The normal equations are assembled sparse
 *    (one row per basis function, an entry per pair sharing an element; the
 *    voxels form a tensor grid, so every entry is a product of three 1D
 *    sums) and solved by conjugate gradients with a Jacobi preconditioner,
 *    starting from c^prev, until the error the solve leaves in the voxel
 *    values (its energy norm, estimated from the last 10 steps after
 *    Hestenes and Stiefel / Strakos and Tichy) is below 1e-4 times the
 *    tolerance. c^prev is the previous fit carried exactly through the
 *    refinement (refinement does not change the spline) and, on the initial
 *    mesh, the image sampled trilinearly at the Greville points. The
 *    regularization acts on basis functions with little data only: with
 *    w_i the smallest over the three directions of the sum of the function's
 *    1D B-spline over the voxel coordinates (how many voxels it sees along
 *    its worst direction; 1 for a one-voxel element, less only at the image's
 *    faces and below voxel size), delta_i = A_ii (1e-12 + Regularization *
 *    max(0, 1 - w_i)). This pins the null space that appears when there are
 *    more functions than voxels (at the faces of fully refined regions)
 *    to the coarser fit; functions that see a voxel or more are fitted by
 *    plain least squares, so a polynomial of the spline's degree is
 *    reproduced exactly.
 * 2. The error |s(x_v) - f_v| at every voxel, element by element in parallel
 *    (vtkSMPTools); maximum and RMS over all voxels. The final errors are
 *    those of the output's Bezier form (vtkLRSplinePatch::ExtractBezier).
 * 3. Stop when the maximum error is at most the tolerance (Tolerance, in data
 *    units (ABSOLUTE) or as a fraction of the data range (RELATIVE, default,
 *    2 %)). Otherwise every element whose largest voxel error exceeds it is
 *    marked, and on each the basis function of smallest support that can
 *    still be refined (the best centred on the element among equal ones) is
 *    refined by structured mesh refinement (every knot interval of its
 *    support halved, vtkLRSplineBuilder::RefineFunctions; Johannessen,
 *    Kvamsdal and Dokken 2014), which splits the element and its neighbours
 *    only: the refinement is local. A marked element that is already as
 *    small as allowed gets all the functions on it refined that can be. With
 *    AlignKnotsToVoxels (default) the splits are rounded to voxel faces (even
 *    degrees) or centres (odd degrees), so that the finest elements are one
 *    voxel, which the spline can interpolate. No split leaves a side shorter
 *    than MinimumElementSize voxels or finer than MaximumRefinementLevels
 *    halvings of the initial elements.
 *
 * The loop also ends (with a warning saying which limit and the error
 * reached) when MaximumNumberOfElements or MaximumRefinementLevels is
 * reached, or when no marked element can be refined further.
 *
 * Output: a vtkMultiBlockDataSet in the format of vtkLRSplineReader (one
 * block per patch, field mode; see vtkLRSplineBezierGrid), the point array
 * named FieldName (default: the input array's name), plus
 * - cell data "LRFitElementMaxError" (largest voxel error in each element);
 * - field data "LRFitMaximumError", "LRFitRMSError", "LRFitTolerance"
 *   (absolute), "LRFitToleranceMet", "LRFitIterations",
 *   "LRFitRefinementLevels" (halvings of the initial elements),
 *   "LRFitDataRange", "LRFitSeconds" and "LRFitHistory" (per iteration:
 *   elements, basis functions, maximum error, RMS error, solver iterations).
 * The same numbers are available from the getters after an update (for
 * composite input: errors over all voxels, counts summed).
 *
 * With FileName set, the fitted spline is also written as an LRSplines text
 * file (.lr; several patches for composite input). Its parameters are the
 * voxel index coordinates: read it with vtkLRSplineReader and PhysicalBounds
 * set to the image's bounds to get the same output.
 *
 * Piece requests are honoured like the reader does: every piece fits the
 * whole image (it needs all of it) and outputs its share of the elements.
 * Progress is reported per iteration; an abort stops after the current one.
 *
 * Refused with an error before anything large is allocated: no or a
 * multi-component array, cell data, fewer than 2 voxels in a direction, more
 * than 2^27 voxels, a non-identity direction matrix, non-positive spacing,
 * Tolerance <= 0 or not finite, degrees outside 1..5, NaN or infinite voxels.
 */

#ifndef vtkLRSplineImageFitter_h
#define vtkLRSplineImageFitter_h

#include "SplineVizModule.h" // for export macro
#include "vtkMultiBlockDataSetAlgorithm.h"
#include "vtkSmartPointer.h" // for BuildOutputBlock

#include <cstddef> // for std::size_t
#include <string>  // for GetStopReason
#include <vector>  // for CollectImages

class vtkDataArray;
class vtkImageData;
class vtkMultiBlockDataSet;
class vtkUnstructuredGrid;

class SPLINEVIZ_EXPORT vtkLRSplineImageFitter : public vtkMultiBlockDataSetAlgorithm
{
public:
  static vtkLRSplineImageFitter* New();
  vtkTypeMacro(vtkLRSplineImageFitter, vtkMultiBlockDataSetAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Polynomial degree per direction, 1 to 5. Default 2 2 2 (Fuchs' splines are quadratic).
  vtkSetVector3Macro(Degree, int);
  vtkGetVector3Macro(Degree, int);
  ///@}

  ///@{
  /**
   * Elements per direction of the initial tensor-product spline: at most one
   * per voxel interval, or one per voxel when the knots are on voxel faces
   * (AlignKnotsToVoxels with an even degree). Default 4 4 4.
   */
  vtkSetVector3Macro(InitialNumberOfElements, int);
  vtkGetVector3Macro(InitialNumberOfElements, int);
  ///@}

  enum ToleranceModes
  {
    ABSOLUTE_TOLERANCE = 0, ///< Tolerance in the data's units
    RELATIVE_TOLERANCE = 1  ///< Tolerance as a fraction of the data range (max - min)
  };

  ///@{
  /// Largest allowed |spline - voxel| at any voxel. Default 0.02 (relative: 2 % of the range).
  vtkSetMacro(Tolerance, double);
  vtkGetMacro(Tolerance, double);
  ///@}

  ///@{
  /// How Tolerance is meant. Default RELATIVE_TOLERANCE.
  vtkSetClampMacro(ToleranceMode, int, ABSOLUTE_TOLERANCE, RELATIVE_TOLERANCE);
  vtkGetMacro(ToleranceMode, int);
  void SetToleranceModeToAbsolute() { this->SetToleranceMode(ABSOLUTE_TOLERANCE); }
  void SetToleranceModeToRelative() { this->SetToleranceMode(RELATIVE_TOLERANCE); }
  ///@}

  ///@{
  /// Refinement stops when a patch has this many elements. Default 500000.
  vtkSetClampMacro(MaximumNumberOfElements, vtkIdType, 1, VTK_ID_MAX);
  vtkGetMacro(MaximumNumberOfElements, vtkIdType);
  ///@}

  ///@{
  /// Most halvings of an initial element side. Default 10.
  vtkSetClampMacro(MaximumRefinementLevels, int, 0, 30);
  vtkGetMacro(MaximumRefinementLevels, int);
  ///@}

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

  ///@{
  /**
   * Weight of the pull towards the previous fit for basis functions that see
   * less than one voxel along some direction (see the class documentation).
   * Default 0.1 (stronger pulls converge a little faster and bias the fit at
   * the image's faces more).
   */
  vtkSetClampMacro(Regularization, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(Regularization, double);
  ///@}

  ///@{
  /// Name of the output's point array; empty (default): the input array's name.
  vtkSetStringMacro(FieldName);
  vtkGetStringMacro(FieldName);
  ///@}

  ///@{
  /// If set, the fitted spline is also written to this .lr file.
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  ///@{
  /// Results of the last update (errors over all voxels, counts over all patches).
  double GetMaximumError() const { return this->MaximumError; }
  double GetRMSError() const { return this->RMSError; }
  /// The tolerance in data units that was applied.
  double GetAbsoluteTolerance() const { return this->AbsoluteTolerance; }
  bool GetToleranceMet() const { return this->ToleranceMet; }
  vtkIdType GetNumberOfElements() const { return this->NumberOfElements; }
  vtkIdType GetNumberOfBasisFunctions() const { return this->NumberOfBasisFunctions; }
  /// Halvings of the initial element sides reached (largest over directions).
  int GetNumberOfRefinementLevels() const { return this->NumberOfRefinementLevels; }
  /// Fit-and-refine rounds (1: the initial spline was good enough).
  int GetNumberOfIterations() const { return this->NumberOfIterations; }
  /// Wall time of the fit in seconds.
  double GetFitTime() const { return this->FitTime; }
  ///@}

protected:
  vtkLRSplineImageFitter();
  ~vtkLRSplineImageFitter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Degree[3] = { 2, 2, 2 };
  int InitialNumberOfElements[3] = { 4, 4, 4 };
  double Tolerance = 0.02;
  int ToleranceMode = RELATIVE_TOLERANCE;
  vtkIdType MaximumNumberOfElements = 500000;
  int MaximumRefinementLevels = 10;
  double MinimumElementSize = 0.5;
  vtkTypeBool AlignKnotsToVoxels = 1;
  double Regularization = 0.1;
  char* FieldName = nullptr;
  char* FileName = nullptr;

  double MaximumError = 0.0;
  double RMSError = 0.0;
  double AbsoluteTolerance = 0.0;
  bool ToleranceMet = false;
  vtkIdType NumberOfElements = 0;
  vtkIdType NumberOfBasisFunctions = 0;
  int NumberOfRefinementLevels = 0;
  int NumberOfIterations = 0;
  double FitTime = 0.0;

private:
  vtkLRSplineImageFitter(const vtkLRSplineImageFitter&) = delete;
  void operator=(const vtkLRSplineImageFitter&) = delete;

  /// The fit settings are usable (else an error, false).
  bool CheckSettings();
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
  /// Zero results before an update.
  void ResetResults();
  /// Every image checked (CheckImage), one job each; false after an error.
  bool PrepareJobs(const std::vector<vtkImageData*>& images, std::vector<Job>& jobs);
  /// The tolerance in data units for the data range `range`.
  double ComputeAbsoluteTolerance(const double range[2]) const;
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
