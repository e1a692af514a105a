// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkTensorLineTracer
 * @brief   Deterministic fiber tracking (hyperstreamlines, tensorlines) along the principal
 * eigenvector of a symmetric tensor field.
 *
 * Traces lines x(s) with dx/ds = e1(T(x)), the unit principal eigenvector of
 * the interpolated tensor, in arc length s: deterministic tractography, or
 * hyperstreamlines (Delmarcelle and Hesselink 1993). The lines feed the tube
 * mappers (Salm's spline tubes) and, through the tensor interpolated along
 * them, the superquadric glyphs (Hlawitschka et al.).
 *
 * Input (port 0): point tensors of a vtkImageData (trilinear, direction matrix
 * honoured), of any vtkDataSet VTK can interpolate, or of a composite of them;
 * the array of SetInputArrayToProcess(0, ...) (default: active point tensors)
 * with 9, 7 (Teem) or 6 components in TensorLayout order. Optional mask,
 * the point array of SetInputArrayToProcess(1, ...): tracked where its value
 * is >= 0.5. Seeds: SEEDS_FROM_SOURCE
 * (the points on port 1) or SEEDS_FROM_VOXELS (every SeedStride-th point with
 * FA >= SeedFAThreshold, inside the mask).
 *
 * Tracking: tensors, not eigenvectors, are interpolated (Interpolation:
 * linear or log-Euclidean, Arsigny et al. 2006); e1 is turned to agree with
 * the incoming direction; RK2 or RK4 with a fixed IntegrationStep in world
 * units or cell lengths; both directions from each seed, joined into one
 * polyline. UseTensorlines: Weinstein et al.'s tensorlines (1999).
 *
 * Stopping, per half (vtkStreamTracer's ReasonForTermination codes, then
 * LOW_ANISOTROPY = 8, HIGH_CURVATURE = 9, OUT_OF_MASK = 10,
 * NEGATIVE_EIGENVALUE = 11): the domain, the mask, StoppingFAThreshold,
 * MaximumAngle, MaximumPropagation, MaximumNumberOfSteps, invalid tensors,
 * NegativeEigenvalues. The failing point is not added; lines shorter than
 * MinimumLength are left out.
 *
 * Output: one polyline per seed; point data FractionalAnisotropy, Tensors
 * (XX YY ZZ XY YZ XZ), PrincipalDirection, DirectionColors, ArcLength; cell
 * data SeedIds, ReasonForTermination (both ends), Length. Parallel over the
 * seeds (vtkSMPTools; the same output for any number of threads), with
 * progress, abort and a memory check; pieces split the seeds. Unlike
 * vtkStreamTracer every seed is traced both ways. Details:
 * docs/components.md, "Fiber tracking".
 */

#ifndef vtkTensorLineTracer_h
#define vtkTensorLineTracer_h

#include "SplineVizFiltersModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

#include <map>    // for ReportRejectedSeeds
#include <vector> // for CollectTensorArrays

class vtkDataArray;
class vtkDataSet;

class SPLINEVIZFILTERS_EXPORT vtkTensorLineTracer : public vtkPolyDataAlgorithm
{
public:
  static vtkTensorLineTracer* New();
  vtkTypeMacro(vtkTensorLineTracer, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum SeedModes
  {
    SEEDS_FROM_SOURCE = 0,
    SEEDS_FROM_VOXELS = 1
  };
  /// vtkStreamTracer's values.
  enum Integrators
  {
    RUNGE_KUTTA2 = 0, ///< midpoint rule, order 2
    RUNGE_KUTTA4 = 1  ///< classic RK4, order 4
  };
  /// vtkStreamTracer's values.
  enum StepUnits
  {
    LENGTH_UNIT = 1,
    CELL_LENGTH_UNIT = 2
  };
  enum Interpolations
  {
    LINEAR_INTERPOLATION = 0,
    LOG_EUCLIDEAN_INTERPOLATION = 1
  };
  enum NegativeEigenvaluePolicies
  {
    NEGATIVE_EIGENVALUES_STOP = 0,    ///< stop (reason NEGATIVE_EIGENVALUE)
    NEGATIVE_EIGENVALUES_ABSOLUTE = 1 ///< use |l| (re-sorted)
  };
  /// vtkStreamTracer's codes 1-6, then the tensor-specific ones.
  enum ReasonForTermination
  {
    OUT_OF_DOMAIN = 1,
    NOT_INITIALIZED = 2,
    UNEXPECTED_VALUE = 3,
    OUT_OF_LENGTH = 4,
    OUT_OF_STEPS = 5,
    STAGNATION = 6,
    LOW_ANISOTROPY = 8,
    HIGH_CURVATURE = 9,
    OUT_OF_MASK = 10,
    NEGATIVE_EIGENVALUE = 11
  };
  /// A short name of a ReasonForTermination code.
  static const char* GetReasonName(int reason);

  ///@{
  /// The seeds for SEEDS_FROM_SOURCE (port 1): the points of any data set.
  void SetSourceConnection(vtkAlgorithmOutput* algOutput);
  void SetSourceData(vtkDataObject* source);
  ///@}

  ///@{
  /**
   * Order of the components of 6-component tensor arrays
   * (vtkSplineVizTensorMath::TensorLayout: SYMMETRIC_VTK = 1, the default,
   * SYMMETRIC_LOWER = 2 for NIfTI and DIPY, SYMMETRIC_UPPER = 3 for FSL). 9- and
   * 7-component arrays are always read as FULL_9 and TEEM_7.
   */
  vtkSetClampMacro(TensorLayout, int, 0, 4);
  vtkGetMacro(TensorLayout, int);
  ///@}

  // The mask is input array 1: SetInputArrayToProcess(1, 0, 0,
  // vtkDataObject::FIELD_ASSOCIATION_POINTS, name), a 1-component point
  // array restricting the tracking to where its interpolated value is >= 0.5.
  // Nothing selected (the default) or an empty name: no mask. Any other name
  // must be a point array of the input, else the update fails with an error.

  ///@{
  /**
   * Deprecated: use SetInputArrayToProcess(1, 0, 0,
   * vtkDataObject::FIELD_ASSOCIATION_POINTS, name) and
   * GetInputArrayInformation(1); kept for one release. nullptr clears the
   * selection.
   */
  void SetMaskArrayName(const char* name);
  const char* GetMaskArrayName();
  ///@}

  ///@{
  /// SEEDS_FROM_SOURCE (default) or SEEDS_FROM_VOXELS.
  vtkSetClampMacro(SeedMode, int, SEEDS_FROM_SOURCE, SEEDS_FROM_VOXELS);
  vtkGetMacro(SeedMode, int);
  void SetSeedModeToSource() { this->SetSeedMode(SEEDS_FROM_SOURCE); }
  void SetSeedModeToVoxels() { this->SetSeedMode(SEEDS_FROM_VOXELS); }
  ///@}

  ///@{
  /// SEEDS_FROM_VOXELS: seed at every n-th voxel in each direction. Default 1.
  vtkSetClampMacro(SeedStride, int, 1, VTK_INT_MAX);
  vtkGetMacro(SeedStride, int);
  ///@}

  ///@{
  /// SEEDS_FROM_VOXELS: seed where the voxel's FA is at least this. Default 0.3.
  vtkSetClampMacro(SeedFAThreshold, double, 0.0, 1.0);
  vtkGetMacro(SeedFAThreshold, double);
  ///@}

  ///@{
  /// RUNGE_KUTTA2 or RUNGE_KUTTA4 (default).
  vtkSetClampMacro(IntegratorType, int, RUNGE_KUTTA2, RUNGE_KUTTA4);
  vtkGetMacro(IntegratorType, int);
  void SetIntegratorTypeToRungeKutta2() { this->SetIntegratorType(RUNGE_KUTTA2); }
  void SetIntegratorTypeToRungeKutta4() { this->SetIntegratorType(RUNGE_KUTTA4); }
  ///@}

  ///@{
  /// The step, in IntegrationStepUnit. Default 0.2 (cell lengths).
  vtkSetMacro(IntegrationStep, double);
  vtkGetMacro(IntegrationStep, double);
  ///@}

  ///@{
  /// LENGTH_UNIT (world units) or CELL_LENGTH_UNIT (default).
  vtkSetClampMacro(IntegrationStepUnit, int, LENGTH_UNIT, CELL_LENGTH_UNIT);
  vtkGetMacro(IntegrationStepUnit, int);
  void SetIntegrationStepUnitToLengthUnit() { this->SetIntegrationStepUnit(LENGTH_UNIT); }
  void SetIntegrationStepUnitToCellLengthUnit() { this->SetIntegrationStepUnit(CELL_LENGTH_UNIT); }
  ///@}

  ///@{
  /// LINEAR_INTERPOLATION (default) or LOG_EUCLIDEAN_INTERPOLATION.
  vtkSetClampMacro(Interpolation, int, LINEAR_INTERPOLATION, LOG_EUCLIDEAN_INTERPOLATION);
  vtkGetMacro(Interpolation, int);
  void SetInterpolationToLinear() { this->SetInterpolation(LINEAR_INTERPOLATION); }
  void SetInterpolationToLogEuclidean() { this->SetInterpolation(LOG_EUCLIDEAN_INTERPOLATION); }
  ///@}

  ///@{
  /// NEGATIVE_EIGENVALUES_STOP (default) or NEGATIVE_EIGENVALUES_ABSOLUTE.
  vtkSetClampMacro(
    NegativeEigenvalues, int, NEGATIVE_EIGENVALUES_STOP, NEGATIVE_EIGENVALUES_ABSOLUTE);
  vtkGetMacro(NegativeEigenvalues, int);
  void SetNegativeEigenvaluesToStop() { this->SetNegativeEigenvalues(NEGATIVE_EIGENVALUES_STOP); }
  void SetNegativeEigenvaluesToAbsolute()
  {
    this->SetNegativeEigenvalues(NEGATIVE_EIGENVALUES_ABSOLUTE);
  }
  ///@}

  ///@{
  /// Weinstein's tensorlines instead of pure principal-eigenvector tracking. Default off.
  vtkSetMacro(UseTensorlines, bool);
  vtkGetMacro(UseTensorlines, bool);
  vtkBooleanMacro(UseTensorlines, bool);
  ///@}

  ///@{
  /// Tensorlines: f = the linear anisotropy cl (default on) or TensorlineEigenvectorWeight.
  vtkSetMacro(TensorlineWeightFromLinearAnisotropy, bool);
  vtkGetMacro(TensorlineWeightFromLinearAnisotropy, bool);
  vtkBooleanMacro(TensorlineWeightFromLinearAnisotropy, bool);
  ///@}

  ///@{
  /// Tensorlines: the weight f of the principal eigenvector. Default 0.5.
  vtkSetClampMacro(TensorlineEigenvectorWeight, double, 0.0, 1.0);
  vtkGetMacro(TensorlineEigenvectorWeight, double);
  ///@}

  ///@{
  /// Tensorlines: the deflection (puncture) weight g of T v_in. Default 0.5.
  vtkSetClampMacro(TensorlineDeflectionWeight, double, 0.0, 1.0);
  vtkGetMacro(TensorlineDeflectionWeight, double);
  ///@}

  ///@{
  /// Lines stop where the FA is below this. Default 0.1.
  vtkSetClampMacro(StoppingFAThreshold, double, 0.0, 1.0);
  vtkGetMacro(StoppingFAThreshold, double);
  ///@}

  ///@{
  /// Lines stop where two consecutive steps turn by more than this (degrees). Default 45.
  vtkSetClampMacro(MaximumAngle, double, 0.0, 180.0);
  vtkGetMacro(MaximumAngle, double);
  ///@}

  ///@{
  /// Largest arc length of each half (world units); 0 (default): no limit.
  vtkSetClampMacro(MaximumPropagation, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(MaximumPropagation, double);
  ///@}

  ///@{
  /// Largest number of steps of each half. Default 10000.
  vtkSetClampMacro(MaximumNumberOfSteps, vtkIdType, 0, VTK_ID_MAX);
  vtkGetMacro(MaximumNumberOfSteps, vtkIdType);
  ///@}

  ///@{
  /// Lines whose total arc length is below this are left out. Default 0.
  vtkSetClampMacro(MinimumLength, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(MinimumLength, double);
  ///@}

  ///@{
  /**
   * vtkAlgorithm::DEFAULT_PRECISION (default: float output for float
   * tensors, double otherwise), SINGLE_PRECISION or DOUBLE_PRECISION, for the
   * points and the floating-point arrays.
   */
  vtkSetClampMacro(OutputPointsPrecision, int, SINGLE_PRECISION, DEFAULT_PRECISION);
  vtkGetMacro(OutputPointsPrecision, int);
  void SetOutputPointsPrecisionToSingle() { this->SetOutputPointsPrecision(SINGLE_PRECISION); }
  void SetOutputPointsPrecisionToDouble() { this->SetOutputPointsPrecision(DOUBLE_PRECISION); }
  void SetOutputPointsPrecisionToDefault() { this->SetOutputPointsPrecision(DEFAULT_PRECISION); }
  ///@}

  ///@{
  /// Statistics of the last execution.
  vtkGetMacro(NumberOfSeeds, vtkIdType);
  vtkGetMacro(NumberOfRejectedSeeds, vtkIdType);
  vtkGetMacro(NumberOfShortLines, vtkIdType);
  vtkGetMacro(NumberOfEvaluations, vtkIdType);
  vtkGetMacro(NumberOfInvalidTensors, vtkIdType);
  vtkGetMacro(NumberOfIndefiniteTensors, vtkIdType);
  /// The step length used, in world units.
  vtkGetMacro(StepLength, double);
  ///@}

protected:
  vtkTensorLineTracer();
  ~vtkTensorLineTracer() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int TensorLayout = 1;
  int SeedMode = SEEDS_FROM_SOURCE;
  int SeedStride = 1;
  double SeedFAThreshold = 0.3;
  int IntegratorType = RUNGE_KUTTA4;
  double IntegrationStep = 0.2;
  int IntegrationStepUnit = CELL_LENGTH_UNIT;
  int Interpolation = LINEAR_INTERPOLATION;
  int NegativeEigenvalues = NEGATIVE_EIGENVALUES_STOP;
  bool UseTensorlines = false;
  bool TensorlineWeightFromLinearAnisotropy = true;
  double TensorlineEigenvectorWeight = 0.5;
  double TensorlineDeflectionWeight = 0.5;
  double StoppingFAThreshold = 0.1;
  double MaximumAngle = 45.0;
  double MaximumPropagation = 0.0;
  vtkIdType MaximumNumberOfSteps = 10000;
  double MinimumLength = 0.0;
  int OutputPointsPrecision = DEFAULT_PRECISION;

  vtkIdType NumberOfSeeds = 0;
  vtkIdType NumberOfRejectedSeeds = 0;
  vtkIdType NumberOfShortLines = 0;
  vtkIdType NumberOfEvaluations = 0;
  vtkIdType NumberOfInvalidTensors = 0;
  vtkIdType NumberOfIndefiniteTensors = 0;
  double StepLength = 0.0;

private:
  vtkTensorLineTracer(const vtkTensorLineTracer&) = delete;
  void operator=(const vtkTensorLineTracer&) = delete;

  /**
   * The input's data sets with points, their tensor arrays (checked: point
   * data, a layout that fits), layouts and masks (useMask: a mask array is
   * set); false after an error.
   */
  bool CollectTensorArrays(vtkDataObject* input, std::vector<vtkDataSet*>& dataSets,
    std::vector<vtkDataArray*>& tensorArrays, std::vector<vtkDataArray*>& maskArrays,
    std::vector<int>& layouts, bool& useMask);
  /// Warnings for the point tensors that are not finite or not positive definite.
  void ReportTensorProblems();
  /// The seeds of the source port (SEEDS_FROM_SOURCE); false after an error.
  bool CollectSourceSeeds(vtkInformationVector* sourceVector, std::vector<double>& seeds);
  /// This piece's share [first, last) of `total` voxel seeds (all of the source's).
  void GetSeedRange(
    vtkInformation* outInfo, vtkIdType total, vtkIdType& first, vtkIdType& last) const;
  /// Double output points (OutputPointsPrecision; DEFAULT: as the input tensors).
  bool UseDoubleOutput(bool inputDouble) const;
  /// The warning for a piece without seeds (useMask: a mask array is set).
  void WarnNoSeeds(bool useMask);
  /// Adds the seeds that gave no line to NumberOfRejectedSeeds (`rejected`:
  /// how many per termination reason) and, for a seed source, warns.
  void ReportRejectedSeeds(const std::map<int, vtkIdType>& rejected);
};

#endif
