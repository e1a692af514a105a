// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkLRSplineStreamTracer
 * @brief   Streamlines through LR-spline vector fields, integrated on the exact spline (Fuchs et
 * al. §5).
 *
 * Like vtkStreamTracer, but every evaluation is an exact evaluation of the
 * spline (k-d forest look-up and Bezier evaluation, vtkLRSplineField, Fuchs
 * et al. §3.2), not an interpolation of samples. Port 0: the vector field
 * (the point array selected with SetInputArrayToProcess(0, 0, 0,
 * vtkDataObject::FIELD_ASSOCIATION_POINTS, name), by default the active
 * vectors) of the output of vtkLRSplineReader or vtkIFEMReader (one patch or all; the
 * first patch containing a point wins): volumes, or surfaces in the plane or
 * curved in 3D, on which the field's tangential part is integrated (points
 * kept on the surface within SurfaceTolerance). Port 1 (Source): the seeds,
 * the points of any data set.
 *
 * Integrators (§5.4, IntegratorType): Euler, midpoint, Kutta's RK3, RK4, the
 * RK4 3/8 rule, RKF5, and the embedded pairs Heun-Euler, Bogacki-Shampine and
 * RKF45. StepMode: FIXED_TIME; FIXED_LENGTH (IntegrationStep in space, as
 * vtkStreamTracer's LENGTH_UNIT); LR_HEURISTIC (§5.2, Eq. 4: IntegrationStep
 * times the element's shortest side over 2^degree); ADAPTIVE (the embedded
 * pairs' error estimate below MaximumError, the step between
 * MinimumIntegrationStep and MaximumIntegrationStep). Precision (§5.6):
 * double, mixed (double state, single-precision evaluation, as the paper's
 * GPU solver) or single.
 *
 * Termination (vtkStreamTracer's codes): OUT_OF_DOMAIN (the last point on the
 * boundary), OUT_OF_STEPS, OUT_OF_LENGTH (MaximumPropagation), STAGNATION
 * (TerminalSpeed), UNEXPECTED_VALUE, OUT_OF_TIME = 7 (MaximumIntegrationTime).
 *
 * Output: one polyline per seed and direction (forward first); point arrays
 * the velocity, "Speed", "IntegrationTime", optionally "Vorticity"; cell
 * arrays "SeedIds", "ReasonForTermination"; field data
 * "SeedReasonForTermination". Parallel over the seeds (vtkSMPTools; the same
 * output for any number of threads), with progress, abort and a memory check.
 * Defaults that differ from vtkStreamTracer's: both directions, RK4,
 * FIXED_LENGTH steps of 0.01, no propagation limit, no vorticity; its ...To...
 * setters are here too. ComputeErrorMetric(): the paper's error metric (Eq. 7).
 */

#ifndef vtkLRSplineStreamTracer_h
#define vtkLRSplineStreamTracer_h

#include "SplineVizFiltersModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

#include <memory> // for std::unique_ptr
#include <string> // for std::string

class vtkLRSplineField;

class SPLINEVIZFILTERS_EXPORT vtkLRSplineStreamTracer : public vtkPolyDataAlgorithm
{
public:
  static vtkLRSplineStreamTracer* New();
  vtkTypeMacro(vtkLRSplineStreamTracer, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Integrators
  {
    EULER = 0,            ///< RK1, order 1
    MIDPOINT = 1,         ///< RK2, order 2
    KUTTA3 = 2,           ///< RK3, order 3
    RUNGE_KUTTA4 = 3,     ///< classic RK4, order 4
    RUNGE_KUTTA4_38 = 4,  ///< 3/8 rule, order 4
    RKF5 = 5,             ///< Fehlberg's fifth-order solution, fixed steps
    HEUN_EULER = 6,       ///< embedded 2(1)
    BOGACKI_SHAMPINE = 7, ///< embedded 3(2)
    RKF45 = 8             ///< embedded 4(5), fifth order propagated
  };
  enum StepModes
  {
    FIXED_TIME = 0,
    FIXED_LENGTH = 1,
    LR_HEURISTIC = 2,
    ADAPTIVE = 3
  };
  enum Precisions
  {
    DOUBLE_PRECISION = 0,
    MIXED_PRECISION = 1,
    SINGLE_PRECISION = 2
  };
  /// vtkStreamTracer's values.
  enum Directions
  {
    FORWARD = 0,
    BACKWARD = 1,
    BOTH = 2
  };
  /// vtkStreamTracer's codes (OUT_OF_TIME is the first custom one).
  enum ReasonForTermination
  {
    OUT_OF_DOMAIN = 1,
    NOT_INITIALIZED = 2,
    UNEXPECTED_VALUE = 3,
    OUT_OF_LENGTH = 4,
    OUT_OF_STEPS = 5,
    STAGNATION = 6,
    OUT_OF_TIME = 7
  };
  /// A short name of a ReasonForTermination code (the same names as vtkTensorLineTracer's).
  static const char* GetReasonName(int reason);

  /// Order of the propagated solution of an integrator.
  static int GetIntegratorOrder(int integrator);
  /// True for the embedded (error-estimating) integrators.
  static bool IsEmbedded(int integrator);
  static const char* GetIntegratorName(int integrator);

  ///@{
  /// The seeds (port 1): the points of any data set.
  void SetSourceConnection(vtkAlgorithmOutput* algOutput);
  void SetSourceData(vtkDataObject* source);
  ///@}

  // The vector field is input array 0, a point array of the spline:
  // SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS,
  // name). Nothing selected (the default) or an empty name: the spline's
  // active vectors.

  ///@{
  /**
   * Deprecated: use SetInputArrayToProcess(0, 0, 0,
   * vtkDataObject::FIELD_ASSOCIATION_POINTS, name) and
   * GetInputArrayInformation(0); kept for one release. nullptr clears the
   * selection.
   */
  void SetArrayName(const char* name);
  const char* GetArrayName();
  ///@}

  ///@{
  /**
   * Integrator (Integrators). Default RUNGE_KUTTA4 (vtkStreamTracer's default
   * is RUNGE_KUTTA2). vtkStreamTracer's setters are here too:
   * SetIntegratorTypeToRungeKutta2 (MIDPOINT), ...ToRungeKutta4 and
   * ...ToRungeKutta45 (RKF45; vtkStreamTracer's RK45 adapts its step, here
   * that is StepMode ADAPTIVE, set separately).
   */
  vtkSetClampMacro(IntegratorType, int, EULER, RKF45);
  vtkGetMacro(IntegratorType, int);
  void SetIntegratorTypeToEuler() { this->SetIntegratorType(EULER); }
  void SetIntegratorTypeToMidpoint() { this->SetIntegratorType(MIDPOINT); }
  void SetIntegratorTypeToRungeKutta2() { this->SetIntegratorType(MIDPOINT); }
  void SetIntegratorTypeToKutta3() { this->SetIntegratorType(KUTTA3); }
  void SetIntegratorTypeToRungeKutta4() { this->SetIntegratorType(RUNGE_KUTTA4); }
  void SetIntegratorTypeToRungeKutta438() { this->SetIntegratorType(RUNGE_KUTTA4_38); }
  void SetIntegratorTypeToRKF5() { this->SetIntegratorType(RKF5); }
  void SetIntegratorTypeToHeunEuler() { this->SetIntegratorType(HEUN_EULER); }
  void SetIntegratorTypeToBogackiShampine() { this->SetIntegratorType(BOGACKI_SHAMPINE); }
  void SetIntegratorTypeToRungeKutta45() { this->SetIntegratorType(RKF45); }
  ///@}

  ///@{
  /// Step mode (StepModes). Default FIXED_LENGTH.
  vtkSetClampMacro(StepMode, int, FIXED_TIME, ADAPTIVE);
  vtkGetMacro(StepMode, int);
  void SetStepModeToFixedTime() { this->SetStepMode(FIXED_TIME); }
  void SetStepModeToFixedLength() { this->SetStepMode(FIXED_LENGTH); }
  void SetStepModeToLRHeuristic() { this->SetStepMode(LR_HEURISTIC); }
  void SetStepModeToAdaptive() { this->SetStepMode(ADAPTIVE); }
  ///@}

  /// vtkStreamTracer's step units.
  enum StepUnits
  {
    LENGTH_UNIT = 1,
    CELL_LENGTH_UNIT = 2
  };
  ///@{
  /**
   * vtkStreamTracer's IntegrationStepUnit, as a step mode: LENGTH_UNIT is
   * FIXED_LENGTH (IntegrationStep in world units), CELL_LENGTH_UNIT is
   * LR_HEURISTIC (IntegrationStep in units of the current element's size,
   * Eq. 4). GetIntegrationStepUnit() is 0 in the other step modes.
   * vtkStreamTracer's default is CELL_LENGTH_UNIT; this filter's default step
   * mode is FIXED_LENGTH (LENGTH_UNIT).
   */
  void SetIntegrationStepUnit(int unit)
  {
    this->SetStepMode(unit == CELL_LENGTH_UNIT ? LR_HEURISTIC : FIXED_LENGTH);
  }
  int GetIntegrationStepUnit()
  {
    return this->StepMode == FIXED_LENGTH ? LENGTH_UNIT
                                          : (this->StepMode == LR_HEURISTIC ? CELL_LENGTH_UNIT : 0);
  }
  void SetIntegrationStepUnitToLengthUnit() { this->SetIntegrationStepUnit(LENGTH_UNIT); }
  void SetIntegrationStepUnitToCellLengthUnit() { this->SetIntegrationStepUnit(CELL_LENGTH_UNIT); }
  ///@}

  ///@{
  /**
   * The base step: a time step (FIXED_TIME), a length (FIXED_LENGTH), a
   * factor of the element size heuristic (LR_HEURISTIC), or the first time
   * step (ADAPTIVE). Default 0.01.
   */
  vtkSetMacro(IntegrationStep, double);
  vtkGetMacro(IntegrationStep, double);
  ///@}

  ///@{
  /// ADAPTIVE: bounds of the time step. Defaults 1e-8 and 1.
  vtkSetMacro(MinimumIntegrationStep, double);
  vtkGetMacro(MinimumIntegrationStep, double);
  vtkSetMacro(MaximumIntegrationStep, double);
  vtkGetMacro(MaximumIntegrationStep, double);
  ///@}

  ///@{
  /// ADAPTIVE: the tolerance on the local error per step (position units). Default 1e-6.
  vtkSetMacro(MaximumError, double);
  vtkGetMacro(MaximumError, double);
  ///@}

  ///@{
  /**
   * FORWARD, BACKWARD or BOTH. Default BOTH: unlike vtkStreamTracer, whose
   * default is FORWARD, this filter traces both halves of every streamline.
   */
  vtkSetClampMacro(IntegrationDirection, int, FORWARD, BOTH);
  vtkGetMacro(IntegrationDirection, int);
  void SetIntegrationDirectionToForward() { this->SetIntegrationDirection(FORWARD); }
  void SetIntegrationDirectionToBackward() { this->SetIntegrationDirection(BACKWARD); }
  void SetIntegrationDirectionToBoth() { this->SetIntegrationDirection(BOTH); }
  ///@}

  ///@{
  /**
   * Limits: steps (default 2000, as vtkStreamTracer), arc length and
   * integration time (0, the defaults: none; vtkStreamTracer's
   * MaximumPropagation defaults to 1).
   */
  vtkSetMacro(MaximumNumberOfSteps, vtkIdType);
  vtkGetMacro(MaximumNumberOfSteps, vtkIdType);
  vtkSetMacro(MaximumPropagation, double);
  vtkGetMacro(MaximumPropagation, double);
  vtkSetMacro(MaximumIntegrationTime, double);
  vtkGetMacro(MaximumIntegrationTime, double);
  ///@}

  ///@{
  /// Lines stop where the speed is at or below this. Default 1e-12.
  vtkSetMacro(TerminalSpeed, double);
  vtkGetMacro(TerminalSpeed, double);
  ///@}

  ///@{
  /// Precision (Precisions). Default DOUBLE_PRECISION.
  vtkSetClampMacro(Precision, int, DOUBLE_PRECISION, SINGLE_PRECISION);
  vtkGetMacro(Precision, int);
  void SetPrecisionToDouble() { this->SetPrecision(DOUBLE_PRECISION); }
  void SetPrecisionToMixed() { this->SetPrecision(MIXED_PRECISION); }
  void SetPrecisionToSingle() { this->SetPrecision(SINGLE_PRECISION); }
  ///@}

  ///@{
  /// Also output "Vorticity" (curl, from the exact Jacobian). Default off (vtkStreamTracer: on).
  vtkSetMacro(ComputeVorticity, vtkTypeBool);
  vtkGetMacro(ComputeVorticity, vtkTypeBool);
  vtkBooleanMacro(ComputeVorticity, vtkTypeBool);
  ///@}

  ///@{
  /// Element search and forest resolution, see vtkLRSplineProbeFilter.
  vtkSetClampMacro(LocatorType, int, 0, 4);
  vtkGetMacro(LocatorType, int);
  vtkSetClampMacro(ForestResolution, int, 0, 1024);
  vtkGetMacro(ForestResolution, int);
  ///@}

  ///@{
  /**
   * Surface fields: how far from the surface a point (a seed, an
   * integrator's stage) may lie and still be on it, relative to the size of
   * the element there, see vtkLRSplineProbeFilter. Default 0.01.
   */
  vtkSetClampMacro(SurfaceTolerance, double, 0.0, 1.0);
  vtkGetMacro(SurfaceTolerance, double);
  ///@}

  /// Number of field evaluations of the last execution.
  vtkIdType GetNumberOfEvaluations() const { return this->NumberOfEvaluations; }

  /**
   * The error metric of Fuchs et al., Eq. 7: the largest, over the lines of
   * `approximation`, of sum_i dt_i |x(t_i) - y(t_i)|, where y(t_i) are the
   * line's points, dt_i its time steps, and x the matching line of
   * `reference` (same seed and direction; "SeedIds" and the sign of
   * "IntegrationTime") evaluated at t_i by cubic Hermite interpolation of its
   * points and velocities (array `velocityName`, default the active vectors).
   * Beyond the end of the reference line its last point is used. Returns -1
   * when the inputs lack the arrays.
   */
  static double ComputeErrorMetric(
    vtkPolyData* approximation, vtkPolyData* reference, const char* velocityName = nullptr);

protected:
  vtkLRSplineStreamTracer();
  ~vtkLRSplineStreamTracer() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int IntegratorType = RUNGE_KUTTA4;
  int StepMode = FIXED_LENGTH;
  double IntegrationStep = 0.01;
  double MinimumIntegrationStep = 1e-8;
  double MaximumIntegrationStep = 1.0;
  double MaximumError = 1e-6;
  int IntegrationDirection = BOTH;
  vtkIdType MaximumNumberOfSteps = 2000;
  double MaximumPropagation = 0.0;
  double MaximumIntegrationTime = 0.0;
  double TerminalSpeed = 1e-12;
  int Precision = DOUBLE_PRECISION;
  vtkTypeBool ComputeVorticity = 0;
  int LocatorType = 2;
  int ForestResolution = 0;
  double SurfaceTolerance = 0.01;
  vtkIdType NumberOfEvaluations = 0;

private:
  vtkLRSplineStreamTracer(const vtkLRSplineStreamTracer&) = delete;
  void operator=(const vtkLRSplineStreamTracer&) = delete;

  /// The integration settings are usable (else an error, false).
  bool CheckSettings();

  std::unique_ptr<vtkLRSplineField> Field;
  std::string FieldKey;
};

#endif
