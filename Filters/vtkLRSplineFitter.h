// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkLRSplineFitter
 * @brief   Fits an LR-spline volume to the point or cell data of any data set (scattered points,
 * unstructured meshes, images) by least squares and/or LR-MBA with local refinement until a
 * tolerance is met at every data point.
 *
 * Fuchs et al. render LR volumes that approximate simulation data on
 * unstructured meshes, trimmed by the mesh's boundary. Input: any vtkDataSet
 * or the leaves of a composite data set, fitted together; cell data at the
 * cell centres; vectors as magnitude or all components (VectorMode).
 *
 * From a tensor-product spline of degree Degree over the data's bounding box
 * (widened by Margin; InitialNumberOfElements) it repeats, as GoTools'
 * LRVolApprox: update the coefficients (Method: LEAST_SQUARES with
 * Regularization and Smoothing, shared with vtkLRSplineImageFitter; MBA, LR
 * multilevel B-spline approximation, Skytt, Barrowclough and Dokken 2015;
 * HYBRID, both); measure the error at every point; stop when the maximum or
 * RMS error (ToleranceType) is within Tolerance (ToleranceMode ABSOLUTE or
 * RELATIVE), else refine the elements above it that hold at least
 * MinimumPointsPerElement points, up to MaximumRefinementLevels and
 * MaximumNumberOfElements.
 *
 * Output port 0: one block in vtkLRSplineReader's format with the "LRFit..."
 * cell and field data (plus "LRFitDomain"). Port 1: the data's boundary
 * surface (empty for point clouds), also attached to the spline as
 * vtkLRSplineField::TRIMMING_SURFACE, so vtkLRSplineVolumeMapper trims by it.
 * Port 2: the outliers left out. FileName: also write a .lr file (read it back
 * with PhysicalBounds = LRFitDomain). Every piece fits all the data.
 *
 * Time steps pass through; ReusePreviousMesh (on) starts a step from the
 * previous step's spline when nothing else changed. RemoveOutliers: values that disagree with their
 * neighbours (vtkSplineVizLocalOutliers, OutlierThreshold) and non-finite
 * points are left out of the fit.
 *
 * The settings, checks and results it shares with vtkLRSplineImageFitter
 * (Degree, Tolerance, the limits, Regularization, OutputFieldName, FileName, the
 * errors) are vtkLRSplineFitterBase's. Also refused before allocating: no
 * points or array, non-finite values or coordinates (unless RemoveOutliers),
 * points without volume, limits whose spline would not fit in memory.
 * Details: docs/lr-fitting.md.
 */

#ifndef vtkLRSplineFitter_h
#define vtkLRSplineFitter_h

#include "SplineVizFiltersModule.h" // for export macro
#include "vtkLRSplineFitterBase.h"

#include <memory> // for std::unique_ptr
#include <string> // for std::string
#include <vector> // for std::vector

class vtkDataSet;
class vtkLRSplineBuilder;
class vtkLRSplineBezierVolume;
class vtkPolyData;

class SPLINEVIZFILTERS_EXPORT vtkLRSplineFitter : public vtkLRSplineFitterBase
{
public:
  static vtkLRSplineFitter* New();
  vtkTypeMacro(vtkLRSplineFitter, vtkLRSplineFitterBase);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Methods
  {
    MBA = 0,           ///< LR multilevel B-spline approximation, two sweeps per level
    LEAST_SQUARES = 1, ///< regularized least squares (conjugate gradients)
    HYBRID = 2         ///< least squares, then two MBA sweeps on its residual
  };
  enum ToleranceTypes
  {
    MAXIMUM_ERROR = 0, ///< every point within the tolerance
    RMS_ERROR = 1      ///< the root mean square error within the tolerance
  };
  enum VectorModes
  {
    MAGNITUDE = 0, ///< fit the length of a vector array
    COMPONENTS = 1 ///< fit every component (one spline with as many components)
  };

  ///@{
  /// How the coefficients are updated on every level. Default LEAST_SQUARES.
  vtkSetClampMacro(Method, int, MBA, HYBRID);
  vtkGetMacro(Method, int);
  void SetMethodToMBA() { this->SetMethod(MBA); }
  void SetMethodToLeastSquares() { this->SetMethod(LEAST_SQUARES); }
  void SetMethodToHybrid() { this->SetMethod(HYBRID); }
  ///@}

  ///@{
  /// Which error the tolerance bounds. Default MAXIMUM_ERROR.
  vtkSetClampMacro(ToleranceType, int, MAXIMUM_ERROR, RMS_ERROR);
  vtkGetMacro(ToleranceType, int);
  void SetToleranceTypeToMaximum() { this->SetToleranceType(MAXIMUM_ERROR); }
  void SetToleranceTypeToRMS() { this->SetToleranceType(RMS_ERROR); }
  ///@}

  ///@{
  /// Vector arrays: the magnitude or every component. Default MAGNITUDE.
  vtkSetClampMacro(VectorMode, int, MAGNITUDE, COMPONENTS);
  vtkGetMacro(VectorMode, int);
  void SetVectorModeToMagnitude() { this->SetVectorMode(MAGNITUDE); }
  void SetVectorModeToComponents() { this->SetVectorMode(COMPONENTS); }
  ///@}

  ///@{
  /**
   * An element is split only when it holds at least this many data points
   * (finer functions would have no data to determine them). Default 2.
   */
  vtkSetClampMacro(MinimumPointsPerElement, vtkIdType, 1, VTK_ID_MAX);
  vtkGetMacro(MinimumPointsPerElement, vtkIdType);
  ///@}

  ///@{
  /// Each side of the data's bounding box is widened by Margin times its length. Default 0.
  vtkSetClampMacro(Margin, double, 0.0, 10.0);
  vtkGetMacro(Margin, double);
  ///@}

  ///@{
  /**
   * Least squares: weight of the smoothing term, the thin-plate energy of
   * the spline on an element measured in the element's own coordinates
   * (vtkLRSplineFitCore::AddElementSmoothing), against the sum of squared
   * errors at the data points: an element with n data points and k basis
   * functions on it counts as Smoothing * max(0, 1 - n / k) data points that
   * ask for no curvature across it. It keeps the spline close to the data
   * between the points where elements hold data in one corner only (at a
   * mesh's boundary); elements with at least as many points as functions
   * are fitted without it (dense data from a spline of the space is
   * reproduced exactly), and its pull fades as elements are refined.
   * 0: plain least squares. Default 1e-4 (measured: docs/lr-fitting.md,
   * "Smoothing").
   */
  vtkSetClampMacro(Smoothing, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(Smoothing, double);
  ///@}

  ///@{
  /// Output port 1 gets the data's boundary surface, and the spline carries it
  /// for trimming (default on).
  vtkSetMacro(ExtractBoundary, vtkTypeBool);
  vtkGetMacro(ExtractBoundary, vtkTypeBool);
  vtkBooleanMacro(ExtractBoundary, vtkTypeBool);
  ///@}

  ///@{
  /**
   * Start each update whose input is a different time step of data on the
   * same domain, with no setting changed since the previous update, from
   * the previous update's refined mesh and coefficients (see the class
   * documentation). Default on. Off: every update starts from the coarse
   * tensor-product spline.
   */
  vtkSetMacro(ReusePreviousMesh, vtkTypeBool);
  vtkGetMacro(ReusePreviousMesh, vtkTypeBool);
  vtkBooleanMacro(ReusePreviousMesh, vtkTypeBool);
  ///@}

  ///@{
  /**
   * Leave out of the fit the data values that disagree with their
   * neighbours, and points with NaN or infinite values or coordinates (see
   * the class documentation). Default off: every point is fitted, and
   * non-finite data is refused.
   */
  vtkSetMacro(RemoveOutliers, vtkTypeBool);
  vtkGetMacro(RemoveOutliers, vtkTypeBool);
  vtkBooleanMacro(RemoveOutliers, vtkTypeBool);
  ///@}

  ///@{
  /**
   * RemoveOutliers: a value is an outlier when the linear model of its
   * neighbours misses it by more than this many times max(what such models
   * miss at those neighbours, the tolerance). Default 5; lower finds smaller spikes and risks
   * taking narrow real features for them.
   */
  vtkSetClampMacro(OutlierThreshold, double, 1.0, 1e6);
  vtkGetMacro(OutlierThreshold, double);
  ///@}

  ///@{
  /// Results of the last update beyond those of vtkLRSplineFitterBase.
  vtkIdType GetNumberOfDataPoints() const { return this->NumberOfDataPoints; }
  /// Data points left out of the last fit (RemoveOutliers): detected and non-finite.
  vtkIdType GetNumberOfOutliers() const { return this->NumberOfOutliers; }
  /// Whether the last update started from the previous update's mesh (ReusePreviousMesh).
  bool GetReusedPreviousMesh() const { return this->ReusedPreviousMesh; }
  /// The fitted domain (xmin, xmax, ymin, ymax, zmin, zmax).
  const double* GetDomain() const { return this->Domain; }
  ///@}

protected:
  vtkLRSplineFitter();
  ~vtkLRSplineFitter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  // Refuse bad settings (false with an error): the shared ones, then
  // InitialNumberOfElements above 1024, a non-finite Smoothing and limits
  // whose spline would not fit in memory.
  bool CheckSettings() override;
  // The shared results and those of this class.
  void ResetResults() override;
  // The positions (3 per point) and values (dim per point) of every leaf.
  // With RemoveOutliers, points with non-finite values or coordinates are
  // left out and counted in `invalid`; without, they are refused.
  bool GatherData(const std::vector<vtkDataSet*>& leaves, std::vector<double>& positions,
    std::vector<double>& values, int& dim, std::string& fieldName, vtkIdType& invalid);
  // The absolute tolerance for `values` (dim per point) and their range (of
  // the lengths, for vectors): Superclass::ComputeAbsoluteTolerance of the range.
  double ComputeAbsoluteTolerance(const std::vector<double>& values, int dim, double range[2]);
  // RemoveOutliers: take the outliers out of `positions` and `values`, into
  // `outliers` (may be null) with their deviations; false when aborted.
  bool SeparateOutliers(std::vector<double>& positions, std::vector<double>& values, int dim,
    const std::string& fieldName, vtkPolyData* outliers);
  // The data's bounding box with the margin (lo, hi), scale = side / elements;
  // false with an error when the points have no volume.
  bool ComputeDomain(
    const std::vector<double>& positions, double lo[3], double hi[3], double scale[3]);
  // Whether a fit of data on [lo, hi] (dim components, at `time`) may start
  // from the previous update's spline: ReusePreviousMesh, another time step,
  // the same domain (to rounding), no setting changed, the same components.
  bool CanReusePreviousFit(
    bool hasTime, double time, const double lo[3], const double hi[3], int dim);
  // Keep the fitted spline for the next update (ReusePreviousMesh, data with a time).
  void RememberFit(const vtkLRSplineBuilder& builder, double time, const double lo[3],
    const double hi[3], int dim);
  // Warn when, on elements that hold data (pointOffsets: CSR of the points
  // per element), Bezier coefficients lie far outside the data's range (the
  // spline can then swing that far between the data points).
  void WarnIfOscillating(const vtkLRSplineBezierVolume& volume,
    const std::vector<vtkIdType>& pointOffsets, const double range[2]);
  // The boundary surface of the leaves (output port 1).
  bool BuildBoundary(const std::vector<vtkDataSet*>& leaves, vtkPolyData* boundary);

  int Method = LEAST_SQUARES;
  int ToleranceType = MAXIMUM_ERROR;
  int VectorMode = MAGNITUDE;
  vtkIdType MinimumPointsPerElement = 2;
  double Margin = 0.0;
  double Smoothing = 1e-4;
  vtkTypeBool ExtractBoundary = 1;
  vtkTypeBool ReusePreviousMesh = 1;
  vtkTypeBool RemoveOutliers = 0;
  double OutlierThreshold = 5.0;

  vtkIdType NumberOfDataPoints = 0;
  vtkIdType NumberOfOutliers = 0;
  double Domain[6] = { 0, 0, 0, 0, 0, 0 };
  bool ReusedPreviousMesh = false;

private:
  // The previous update's spline and what it was fitted under (ReusePreviousMesh).
  struct PreviousFit;
  std::unique_ptr<PreviousFit> Previous;

  vtkLRSplineFitter(const vtkLRSplineFitter&) = delete;
  void operator=(const vtkLRSplineFitter&) = delete;
};

#endif
