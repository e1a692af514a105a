// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkLRSplineStreamTracer
 * @brief   Streamlines through LR-spline vector fields, integrated on the exact spline (Fuchs et
 * al. §5).
 *
 * Port 0: the vector field, the output of vtkLRSplineReader or vtkIFEMReader
 * (one patch or the whole vtkMultiBlockDataSet; with several patches the
 * first patch containing a point wins). Volumes, or surfaces (in the plane or
 * curved in 3D): there the field (2 or 3 components) is integrated on the
 * surface in physical space: every evaluation is at the foot of the point on
 * the surface (within SurfaceTolerance) and takes the field's tangential
 * part, and every accepted point is moved onto its foot. Port 1 (Source): the seeds, the points of
 * any data set (or composite of them). Like vtkStreamTracer, but every evaluation is an exact
 * evaluation of the spline (k-d forest look-up and Bezier evaluation,
 * vtkLRSplineField, Fuchs et al. §3.2), not an interpolation of samples.
 *
 * Integrators (§5.4): explicit Euler (RK1), midpoint (RK2), Kutta's third
 * order (RK3), classic RK4, the 3/8 rule (RK4 3/8), Runge-Kutta-Fehlberg's
 * fifth-order solution (RKF5), and the embedded pairs Heun-Euler (2(1)),
 * Bogacki-Shampine (3(2)) and Runge-Kutta-Fehlberg (4(5), the fifth-order
 * solution is propagated).
 *
 * Step modes:
 * - FIXED_TIME: the time step is IntegrationStep;
 * - FIXED_LENGTH: each step advances about IntegrationStep in space
 *   (time step IntegrationStep / |v|, like vtkStreamTracer's LENGTH_UNIT);
 * - LR_HEURISTIC (§4.2, §5.2, Eq. 4): the spatial step is IntegrationStep
 *   times (shortest side of the current element) / 2^degree, so the steps
 *   follow the local refinement of the LR mesh;
 * - ADAPTIVE: the embedded integrators' local error estimate keeps the
 *   error per step below MaximumError (step between MinimumIntegrationStep
 *   and MaximumIntegrationStep, in time units).
 *
 * Precision (§5.6): DOUBLE_PRECISION (state and evaluation in double),
 * MIXED_PRECISION (the integration state in double, the spline evaluated in
 * single precision, as the paper's GPU solver), SINGLE_PRECISION (both in
 * single precision; for comparison, it stagnates in very small elements).
 *
 * Termination (vtkStreamTracer's ReasonForTermination codes): leaving the
 * domain (OUT_OF_DOMAIN; the last point is placed on the boundary of the
 * spline's box), MaximumNumberOfSteps (OUT_OF_STEPS), MaximumPropagation in
 * arc length (OUT_OF_LENGTH), speed at or below TerminalSpeed (STAGNATION),
 * a non-finite value (UNEXPECTED_VALUE), and MaximumIntegrationTime
 * (OUT_OF_TIME = 7, vtkStreamTracer::FIXED_REASONS_FOR_TERMINATION_COUNT, the
 * first code vtkStreamTracer leaves to custom reasons).
 *
 * Output: one polyline per seed and direction (forward first, in seed order;
 * lines of a single point are left out), point arrays: the velocity (named
 * like the input array), "Speed", "IntegrationTime" (negative backward),
 * optionally "Vorticity" (from the exact Jacobian); cell arrays "SeedIds" and
 * "ReasonForTermination"; field data "SeedReasonForTermination" (per seed:
 * forward and backward reason, -1 when not traced, also for seeds that gave
 * no line). Ready for the tube mappers (radius or colour from "Speed").
 *
 * Parallel over the seeds with vtkSMPTools; the output does not depend on the
 * number of threads. Progress is reported per batch of seeds and abort
 * (AbortExecute, or an abort upstream) is honoured between batches: an
 * aborted run gives an empty output. Seeds whose lines could not fit in
 * this machine's memory are refused before anything is allocated, and the
 * tracing stops with an error when the lines outgrow it.
 *
 * Defaults that differ from vtkStreamTracer's: IntegrationDirection BOTH
 * (vtkStreamTracer: FORWARD), IntegratorType RUNGE_KUTTA4 (RUNGE_KUTTA2),
 * step mode FIXED_LENGTH, i.e. LENGTH_UNIT (CELL_LENGTH_UNIT),
 * IntegrationStep 0.01 (0.5 cell lengths), MaximumPropagation 0 = no limit
 * (1), ComputeVorticity off (on). The ...To... setters vtkStreamTracer users
 * type (SetIntegrationDirectionToForward, SetIntegratorTypeToRungeKutta4,
 * SetIntegrationStepUnit, ...) are here too.
 *
 * ComputeErrorMetric() is the paper's error metric (Eq. 7) of a set of lines
 * against a reference set (e.g. RKF5 with a very small step).
 */

#ifndef vtkLRSplineStreamTracer_h
#define vtkLRSplineStreamTracer_h

#include "SplineVizModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

#include <memory> // for std::unique_ptr
#include <string> // for std::string

class vtkLRSplineField;

class SPLINEVIZ_EXPORT vtkLRSplineStreamTracer : public vtkPolyDataAlgorithm
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

  ///@{
  /// The point-data vector array of the spline; empty: its active vectors.
  vtkSetStringMacro(ArrayName);
  vtkGetStringMacro(ArrayName);
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

  char* ArrayName = nullptr;
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
