// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkTensorLineTracer
 * @brief   Deterministic fiber tracking (hyperstreamlines, tensorlines) along the principal
 * eigenvector of a symmetric tensor field.
 *
 * Traces lines x(s) with dx/ds = e1(T(x)), the unit principal eigenvector
 * of the interpolated tensor, in arc length s: what diffusion-MRI users call
 * deterministic tractography and engineers call hyperstreamlines (Delmarcelle
 * and Hesselink 1993). The output polylines are the input of the SplineViz
 * tube mappers (Salm's spline tubes, e.g. with the radius from the
 * fractional anisotropy), and the interpolated tensor along the lines the
 * input of the superquadric glyphs (Hlawitschka et al.).
 *
 * **Input (port 0)**: the tensor field, point data of a vtkImageData (fast
 * path: trilinear interpolation, the image's direction matrix honoured) or
 * of any other vtkDataSet VTK can interpolate (cells located with a
 * vtkStaticCellLocator, interpolated with the cells' own weights, so that
 * e.g. tri-quadratic hexahedra interpolate quadratically), or a composite
 * data set of them (the first block containing a point wins). The tensor
 * array is selected with SetInputArrayToProcess(0, ...) (default: the active
 * point tensors); its components are read by vtkSplineVizTensorMath: 9
 * components as a 3x3 matrix (symmetrized), 7 as Teem/NRRD (the confidence
 * is ignored), 6 in the TensorLayout order (VTK's XX YY ZZ XY YZ XZ, the
 * lower triangle of NIfTI and DIPY, the upper triangle of FSL and MFEM). An optional point array
 * MaskArrayName restricts the tracking to where its interpolated value is at
 * least 0.5 (a 0/1 mask ends halfway between voxels).
 *
 * **Seeds**: SEEDS_FROM_SOURCE: the points of the data set on port 1 (any
 * data set or composite of them); SEEDS_FROM_VOXELS: every SeedStride-th
 * point of the input in each index direction (every SeedStride-th point id
 * for non-image data) whose tensor has a fractional anisotropy of at least
 * SeedFAThreshold, inside the mask. A seed that is outside the domain or the
 * mask, whose tensor is invalid or whose FA is below StoppingFAThreshold
 * gives no line (counted by GetNumberOfRejectedSeeds()).
 *
 * **Tracking**: tensors are interpolated, not eigenvectors: linearly
 * (trilinear on images) or log-Euclidean (Arsigny et al. 2006: the matrix
 * logarithms of the point tensors are interpolated and mapped back with the
 * matrix exponential; eigenvalues below 1e-6 of the largest eigenvalue in
 * the data set, zero tensors included, are raised to that floor first).
 * Eigenvectors have no sign: the principal eigenvector is flipped to agree
 * with the incoming direction (the previous step) at the first Runge-Kutta
 * stage and with the first stage's direction at the others, so lines never
 * U-turn where the eigen-solver's sign changes. RK2
 * (midpoint) or RK4 in arc length with a fixed step IntegrationStep, in world
 * units (LENGTH_UNIT) or in multiples of the cell size (CELL_LENGTH_UNIT: the
 * smallest voxel spacing of an image; for other data sets the cube root of
 * the mean cell volume, from the bounds). Each seed is traced in both
 * directions and the two halves are joined into one polyline (the backward
 * half reversed, then the forward half; the seed is one point of it).
 * Optionally the direction is Weinstein et al.'s tensorline (1999):
 * v_out = f e1 + (1 - f) ((1 - g) v_in + g T v_in / l1) with v_in the
 * incoming direction, f = TensorlineEigenvectorWeight or the linear
 * anisotropy cl (TensorlineWeightFromLinearAnisotropy, the default), and the
 * deflection (puncture) weight g = TensorlineDeflectionWeight; it passes
 * straight through isotropic regions instead of following noise.
 *
 * **Stopping** (per half, vtkStreamTracer's ReasonForTermination codes; 7 is
 * vtkLRSplineStreamTracer's OUT_OF_TIME and not used here): leaving the
 * domain (OUT_OF_DOMAIN, also when a Runge-Kutta stage leaves it), a tensor
 * with a non-finite component among the interpolated ones (UNEXPECTED_VALUE),
 * MaximumPropagation arc length per half (OUT_OF_LENGTH; the last step is
 * shortened to the remaining length, its chord is shorter by O(h^3)),
 * MaximumNumberOfSteps (OUT_OF_STEPS), no direction (STAGNATION: a zero
 * tensor with a zero FA threshold; with a positive threshold a zero tensor
 * stops the line as LOW_ANISOTROPY), FA below StoppingFAThreshold
 * (LOW_ANISOTROPY = 8), a turning angle between two consecutive steps above
 * MaximumAngle degrees or a step whose chord is shorter than half the step
 * (the direction turns by more than about 120 degrees within it)
 * (HIGH_CURVATURE = 9), leaving the mask (OUT_OF_MASK = 10), a tensor with a
 * negative eigenvalue under the NEGATIVE_EIGENVALUES_STOP policy
 * (NEGATIVE_EIGENVALUE = 11; with NEGATIVE_EIGENVALUES_ABSOLUTE the absolute
 * eigenvalues are used). The point that fails a criterion is not added:
 * every output point has FA >= StoppingFAThreshold and lies inside the mask
 * and the domain, and every turn between consecutive steps of a half is at
 * most MaximumAngle. Lines shorter than MinimumLength (total arc length), or
 * of a single point, are left out (GetNumberOfShortLines()).
 *
 * **Output**: one polyline per seed, in seed order. Point data:
 * `FractionalAnisotropy` (active scalars), `Tensors` (the interpolated
 * tensor, 6 components XX YY ZZ XY YZ XZ, active tensors, for glyphs along
 * the lines), `PrincipalDirection` (unit e1, oriented along the line from its
 * first to its last point; active vectors), `DirectionColors` (unsigned char
 * RGB = 255 |e1|, the usual DTI direction colors, for direct color mapping),
 * `ArcLength` (signed arc length from the seed, negative on the backward
 * half). Cell data: `SeedIds` (index of the seed in the seed list),
 * `ReasonForTermination` (2 components: the reason at the first point, i.e.
 * the end of the backward half, and at the last point, the end of the
 * forward half), `Length` (total arc length). Points and arrays are float or
 * double following OutputPointsPrecision (default: the tensor array's).
 *
 * Parallel over seeds (vtkSMPTools); the output is the same for any number
 * of threads and any SMP backend. Seeds are processed in batches, so the
 * temporary memory does not grow with the number of seeds. Piece requests
 * split the seed list (the field is needed whole). Progress is reported and
 * abort honoured after every batch (an aborted run gives an empty output);
 * more seeds than this machine's memory could hold lines for are refused
 * before anything is allocated, and the tracing stops with an error when
 * the output outgrows the memory.
 *
 * Unlike vtkStreamTracer (IntegrationDirection, default FORWARD), every seed
 * is traced in both directions. vtkStreamTracer's setters are here too
 * (SetIntegratorTypeToRungeKutta2/4, SetIntegrationStepUnitToLengthUnit /
 * ToCellLengthUnit), and ...To... setters for the other choices.
 *
 * The tensor math (layouts, eigen-decomposition, FA, Westin metrics, sign
 * policies, matrix log/exp) is vtkSplineVizTensorMath, shared with
 * vtkTensorAnalysisFilter and the superquadric glyph mapper.
 */

#ifndef vtkTensorLineTracer_h
#define vtkTensorLineTracer_h

#include "SplineVizModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

#include <map>    // for ReportRejectedSeeds
#include <vector> // for CollectTensorArrays

class vtkDataArray;
class vtkDataSet;

class SPLINEVIZ_EXPORT vtkTensorLineTracer : public vtkPolyDataAlgorithm
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

  ///@{
  /**
   * Name of a 1-component point array restricting the tracking to where its
   * interpolated value is >= 0.5. Empty, nullptr (default) or "None"
   * (ParaView's choice of no array, unless a point array has that name): no
   * mask.
   */
  vtkSetStringMacro(MaskArrayName);
  vtkGetStringMacro(MaskArrayName);
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
  char* MaskArrayName = nullptr;
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
