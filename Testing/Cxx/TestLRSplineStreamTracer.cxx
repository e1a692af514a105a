// SPDX-License-Identifier: BSD-3-Clause
// vtkLRSplineStreamTracer on fields with known streamlines, represented
// exactly by locally refined LR splines with non-dyadic knots (linear fields
// v = A p + b): rotations (circles) and diagonal A (exponentials).
// - Every fixed-step integrator converges at its theoretical order (1, 2, 3,
//   4, 4, 5; the embedded ones at 2, 3, 5 with fixed steps), measured with the
//   paper's error metric (Eq. 7) against the analytic solution; also with the
//   LR-structure step heuristic.
// - The adaptive integrators keep every step's local error (against the
//   exact flow) below the tolerance, and the global error falls with it.
// - Termination: a seed outside gives no line and a reason; a line leaving
//   the domain ends exactly on the boundary; both directions start at the
//   seed; steps, length, time and speed limits; vorticity.
// - Mixed precision beats single precision on a field with 20 refinement
//   levels (Fuchs et al. Fig. 9).
// - ComputeErrorMetric (Eq. 7 against a reference solution) agrees with the
//   analytic metric; output independent of the number of threads.
// - Bad input: NaN seeds, a zero field, no seeds, no field, a scalar field,
//   adaptive steps with a non-embedded integrator.
#include "vtkLRSplineBuilder.h"
#include "vtkLRSplineReader.h"
#include "vtkLRSplineStreamTracer.h"
#include "vtkTensorLineTracer.h"

#include "LRSplineTestFields.h"
#include "SplineVizTestUtilities.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkStreamTracer.h"
#include "vtkTestErrorObserver.h"

#include <cmath>
#include <functional>
#include <iomanip>
#include <limits>

// The termination codes and directions are vtkStreamTracer's.
constexpr int Code(int c)
{
  return c;
}
static_assert(
  Code(vtkLRSplineStreamTracer::OUT_OF_DOMAIN) == Code(vtkStreamTracer::OUT_OF_DOMAIN), "codes");
static_assert(
  Code(vtkLRSplineStreamTracer::NOT_INITIALIZED) == Code(vtkStreamTracer::NOT_INITIALIZED),
  "codes");
static_assert(
  Code(vtkLRSplineStreamTracer::UNEXPECTED_VALUE) == Code(vtkStreamTracer::UNEXPECTED_VALUE),
  "codes");
static_assert(
  Code(vtkLRSplineStreamTracer::OUT_OF_LENGTH) == Code(vtkStreamTracer::OUT_OF_LENGTH), "codes");
static_assert(
  Code(vtkLRSplineStreamTracer::OUT_OF_STEPS) == Code(vtkStreamTracer::OUT_OF_STEPS), "codes");
static_assert(
  Code(vtkLRSplineStreamTracer::STAGNATION) == Code(vtkStreamTracer::STAGNATION), "codes");
static_assert(Code(vtkLRSplineStreamTracer::OUT_OF_TIME) ==
    Code(vtkStreamTracer::FIXED_REASONS_FOR_TERMINATION_COUNT),
  "the first custom code");
static_assert(Code(vtkLRSplineStreamTracer::BOTH) == Code(vtkStreamTracer::BOTH) &&
    Code(vtkLRSplineStreamTracer::BACKWARD) == Code(vtkStreamTracer::BACKWARD),
  "directions");

namespace
{
using Exact = std::function<void(const double x0[3], double t, double x[3])>;

vtkSmartPointer<vtkPolyData> Seeds(std::initializer_list<std::array<double, 3>> pts)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (const auto& p : pts)
  {
    points->InsertNextPoint(p.data());
  }
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  pd->SetPoints(points);
  return pd;
}

// Eq. 7 against the analytic solution: max over lines of sum dt_i |x(t_i) - y_i|.
double Eq7(vtkPolyData* lines, const Exact& exact)
{
  vtkDataArray* time = lines->GetPointData()->GetArray("IntegrationTime");
  double worst = 0.0;
  vtkCellArray* ca = lines->GetLines();
  vtkIdType n;
  const vtkIdType* ids;
  for (ca->InitTraversal(); ca->GetNextCell(n, ids);)
  {
    double x0[3];
    lines->GetPoint(ids[0], x0);
    double sum = 0.0;
    for (vtkIdType i = 1; i < n; ++i)
    {
      const double t = time->GetComponent(ids[i], 0);
      const double dt = std::abs(t - time->GetComponent(ids[i - 1], 0));
      double y[3], x[3];
      lines->GetPoint(ids[i], y);
      exact(x0, t, x);
      sum += dt *
        std::sqrt((x[0] - y[0]) * (x[0] - y[0]) + (x[1] - y[1]) * (x[1] - y[1]) +
          (x[2] - y[2]) * (x[2] - y[2]));
    }
    worst = std::max(worst, sum);
  }
  return worst;
}

vtkSmartPointer<vtkPolyData> Trace(vtkDataObject* field, vtkPolyData* seeds, int integrator,
  int mode, double step, double maxTime, int direction = vtkLRSplineStreamTracer::FORWARD,
  int precision = vtkLRSplineStreamTracer::DOUBLE_PRECISION, double tol = 1e-6,
  vtkIdType maxSteps = 1000000)
{
  vtkNew<vtkLRSplineStreamTracer> tracer;
  tracer->SetInputData(field);
  tracer->SetSourceData(seeds);
  tracer->SetIntegratorType(integrator);
  tracer->SetStepMode(mode);
  tracer->SetIntegrationStep(step);
  tracer->SetMaximumIntegrationTime(maxTime);
  tracer->SetMaximumNumberOfSteps(maxSteps);
  tracer->SetIntegrationDirection(direction);
  tracer->SetPrecision(precision);
  tracer->SetMaximumError(tol);
  tracer->SetMaximumIntegrationStep(0.5);
  tracer->Update();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(tracer->GetOutput());
  return out;
}

const double Center[3] = { 0.5, 0.5, 0.0 };
// v = A (p - c), A the rotation generator about z: circles about (0.5, 0.5).
void Rotation(const double x0[3], double t, double x[3])
{
  const double c = std::cos(t), s = std::sin(t);
  const double dx = x0[0] - Center[0], dy = x0[1] - Center[1];
  x[0] = Center[0] + c * dx - s * dy;
  x[1] = Center[1] + s * dx + c * dy;
  x[2] = x0[2];
}
// v = a (p - p*), diagonal: exponentials.
const double Rate[3] = { 0.5, -0.8, 0.3 };
void Exponential(const double x0[3], double t, double x[3])
{
  for (int d = 0; d < 3; ++d)
  {
    x[d] = 0.5 + (x0[d] - 0.5) * std::exp(Rate[d] * t);
  }
}

int LastPoint(vtkPolyData* pd, int line, double x[3])
{
  vtkCellArray* ca = pd->GetLines();
  vtkIdType n;
  const vtkIdType* ids;
  int c = 0;
  for (ca->InitTraversal(); ca->GetNextCell(n, ids); ++c)
  {
    if (c == line)
    {
      pd->GetPoint(ids[n - 1], x);
      return static_cast<int>(n);
    }
  }
  return 0;
}
}

int TestLRSplineStreamTracer(int, char*[])
{
  SplineVizTestStatus status;
  vtkSMPTools::SetBackend("STDThread");
  const double focus[3] = { 0.8, 0.5, 0.5 };

  // Fields: rotation (degree 1 and 2) and exponential (degree 2), locally refined.
  const double Arot[9] = { 0, -1, 0, 1, 0, 0, 0, 0, 0 };
  const double brot[3] = { 0.5, -0.5, 0 }; // -A c
  auto rotation = lrtest::LinearField(Arot, brot, 2, 6, focus, "TestLRSplineStreamTracer-rotation");
  auto rotation1 =
    lrtest::LinearField(Arot, brot, 1, 6, focus, "TestLRSplineStreamTracer-rotation1");
  const double Aexp[9] = { Rate[0], 0, 0, 0, Rate[1], 0, 0, 0, Rate[2] };
  const double bexp[3] = { -0.5 * Rate[0], -0.5 * Rate[1], -0.5 * Rate[2] };
  auto exponential = lrtest::LinearField(Aexp, bexp, 2, 6, focus, "TestLRSplineStreamTracer-exp");
  SV_CHECK(status, rotation && rotation1 && exponential);
  if (!rotation || !rotation1 || !exponential)
  {
    return status.Result();
  }
  auto seeds = Seeds({ { 0.8, 0.5, 0.5 }, { 0.5, 0.25, 0.3 }, { 0.35, 0.6, 0.9 } });
  auto expSeeds = Seeds({ { 0.6, 0.8, 0.45 }, { 0.45, 0.2, 0.7 } });

  //--- Convergence orders with fixed time steps (Eq. 7 vs the analytic solution).
  struct Method
  {
    int Type;
    int N0;
  };
  const Method methods[] = { { vtkLRSplineStreamTracer::EULER, 200 },
    { vtkLRSplineStreamTracer::MIDPOINT, 40 }, { vtkLRSplineStreamTracer::KUTTA3, 20 },
    { vtkLRSplineStreamTracer::RUNGE_KUTTA4, 12 }, { vtkLRSplineStreamTracer::RUNGE_KUTTA4_38, 12 },
    { vtkLRSplineStreamTracer::RKF5, 8 }, { vtkLRSplineStreamTracer::HEUN_EULER, 40 },
    { vtkLRSplineStreamTracer::BOGACKI_SHAMPINE, 20 }, { vtkLRSplineStreamTracer::RKF45, 8 } };
  const double T = 2.0;
  for (const Method& m : methods)
  {
    const int order = vtkLRSplineStreamTracer::GetIntegratorOrder(m.Type);
    for (int field = 0; field < 3; ++field)
    {
      vtkDataObject* f =
        field == 0 ? rotation.Get() : (field == 1 ? rotation1.Get() : exponential.Get());
      vtkPolyData* s = field == 2 ? expSeeds.Get() : seeds.Get();
      const Exact exact = field == 2 ? Exact(Exponential) : Exact(Rotation);
      double E[3];
      for (int k = 0; k < 3; ++k)
      {
        const int N = m.N0 << k;
        auto lines = Trace(f, s, m.Type, vtkLRSplineStreamTracer::FIXED_TIME, T / N, T);
        E[k] = Eq7(lines, exact);
        SV_CHECK(status, lines->GetNumberOfLines() == s->GetNumberOfPoints());
      }
      const double r1 = std::log2(E[0] / E[1]), r2 = std::log2(E[1] / E[2]);
      std::cout << std::left << std::setw(28) << vtkLRSplineStreamTracer::GetIntegratorName(m.Type)
                << std::right
                << (field == 0 ? " rotation q2" : (field == 1 ? " rotation q1" : " exponential"))
                << ": E = " << std::setprecision(3) << E[0] << ", " << E[1] << ", " << E[2]
                << "; observed orders " << r1 << ", " << r2 << " (theory " << order << ")"
                << std::endl;
      SV_CHECK_MSG(status, std::abs(r2 - order) < 0.3 && std::abs(r1 - order) < 0.5,
        vtkLRSplineStreamTracer::GetIntegratorName(m.Type) << " order " << r1 << ", " << r2);
    }
  }

  //--- The LR heuristic (element size / 2^degree) converges at the order too.
  {
    double E[3];
    for (int k = 0; k < 3; ++k)
    {
      auto lines = Trace(rotation, seeds, vtkLRSplineStreamTracer::RUNGE_KUTTA4,
        vtkLRSplineStreamTracer::LR_HEURISTIC, 4.0 / (1 << k), T);
      E[k] = Eq7(lines, Rotation);
    }
    const double r = std::log2(E[1] / E[2]);
    std::cout << "RK4, LR heuristic: E = " << E[0] << ", " << E[1] << ", " << E[2] << ", order "
              << r << std::endl;
    SV_CHECK_MSG(status, std::abs(r - 4.0) < 0.5, "heuristic order " << r);
  }

  //--- Adaptive: every step's local error below the tolerance; global error
  // falls with the tolerance.
  for (int type : { vtkLRSplineStreamTracer::HEUN_EULER, vtkLRSplineStreamTracer::BOGACKI_SHAMPINE,
         vtkLRSplineStreamTracer::RKF45 })
  {
    double previous = 1e300;
    for (double tol : { 1e-5, 1e-7, 1e-9 })
    {
      auto lines = Trace(rotation, seeds, type, vtkLRSplineStreamTracer::ADAPTIVE, 0.1, T,
        vtkLRSplineStreamTracer::FORWARD, vtkLRSplineStreamTracer::DOUBLE_PRECISION, tol);
      vtkDataArray* time = lines->GetPointData()->GetArray("IntegrationTime");
      double worstLocal = 0.0;
      vtkIdType steps = 0;
      for (vtkIdType i = 1; i < lines->GetNumberOfPoints(); ++i)
      {
        const double t0 = time->GetComponent(i - 1, 0), t1 = time->GetComponent(i, 0);
        if (t1 <= t0)
        {
          continue; // the next line
        }
        double y0[3], y1[3], x[3];
        lines->GetPoint(i - 1, y0);
        lines->GetPoint(i, y1);
        Rotation(y0, t1 - t0, x);
        worstLocal = std::max(
          worstLocal, std::sqrt((x[0] - y1[0]) * (x[0] - y1[0]) + (x[1] - y1[1]) * (x[1] - y1[1])));
        ++steps;
      }
      const double global = Eq7(lines, Rotation);
      std::cout << vtkLRSplineStreamTracer::GetIntegratorName(type) << " tol " << tol << ": "
                << steps << " steps, max local error " << worstLocal << ", Eq. 7 " << global
                << std::endl;
      SV_CHECK_MSG(status, worstLocal <= tol, "local error " << worstLocal << " > tol " << tol);
      SV_CHECK(status, global < previous);
      previous = global;
    }
  }

  //--- Termination, directions and limits, on a constant field v = (1, 0.3, 0).
  {
    const double A0[9] = { 0, 0, 0, 0, 0, 0, 0, 0, 0 }, b0[3] = { 1.0, 0.3, 0.0 };
    auto constant = lrtest::LinearField(A0, b0, 2, 4, focus, "TestLRSplineStreamTracer-constant");
    auto s = Seeds({ { 0.2, 0.5, 0.5 }, { 2.0, 2.0, 2.0 } });
    auto lines = Trace(constant, s, vtkLRSplineStreamTracer::RUNGE_KUTTA4,
      vtkLRSplineStreamTracer::FIXED_LENGTH, 0.07, 0.0, vtkLRSplineStreamTracer::BOTH);
    SV_CHECK(status, lines->GetNumberOfLines() == 2); // the outside seed gives none
    vtkDataArray* reasons = lines->GetCellData()->GetArray("ReasonForTermination");
    vtkDataArray* seedIds = lines->GetCellData()->GetArray("SeedIds");
    vtkDataArray* time = lines->GetPointData()->GetArray("IntegrationTime");
    vtkDataArray* seedReasons = lines->GetFieldData()->GetArray("SeedReasonForTermination");
    SV_CHECK(status, reasons && seedIds && time && seedReasons);
    if (reasons && seedIds && time && seedReasons && lines->GetNumberOfLines() == 2)
    {
      SV_CHECK(status, reasons->GetComponent(0, 0) == vtkLRSplineStreamTracer::OUT_OF_DOMAIN);
      SV_CHECK(status, reasons->GetComponent(1, 0) == vtkLRSplineStreamTracer::OUT_OF_DOMAIN);
      SV_CHECK(status, seedIds->GetComponent(0, 0) == 0 && seedIds->GetComponent(1, 0) == 0);
      SV_CHECK(status, seedReasons->GetComponent(1, 0) == vtkLRSplineStreamTracer::OUT_OF_DOMAIN);
      SV_CHECK(status, seedReasons->GetComponent(1, 1) == vtkLRSplineStreamTracer::OUT_OF_DOMAIN);
      double end[3];
      const int n0 = LastPoint(lines, 0, end);
      std::cout << "forward line: " << n0 << " points, ends at " << std::setprecision(17) << end[0]
                << " " << end[1] << " " << end[2] << ", t = " << time->GetComponent(n0 - 1, 0)
                << std::endl;
      SV_CHECK(status, end[0] == 1.0);
      SV_CHECK_NEAR(status, end[1], 0.74, 1e-12);
      SV_CHECK_NEAR(status, time->GetComponent(n0 - 1, 0), 0.8, 1e-12);
      const int n1 = LastPoint(lines, 1, end);
      SV_CHECK(status, end[0] == 0.0);
      SV_CHECK_NEAR(status, end[1], 0.44, 1e-12);
      SV_CHECK_NEAR(status, time->GetComponent(n0 + n1 - 1, 0), -0.2, 1e-12);
      // both directions start at the seed at time 0
      double p0[3], p1[3];
      lines->GetPoint(0, p0);
      lines->GetPoint(n0, p1);
      SV_CHECK(status, p0[0] == 0.2 && p1[0] == 0.2 && p0[1] == 0.5 && p1[1] == 0.5);
      SV_CHECK(status, time->GetComponent(0, 0) == 0.0 && time->GetComponent(n0, 0) == 0.0);
      SV_CHECK(status, time->GetComponent(n0 + 1, 0) < 0.0);
      // equal steps in length
      double q[3];
      lines->GetPoint(1, q);
      SV_CHECK_NEAR(status,
        std::sqrt((q[0] - p0[0]) * (q[0] - p0[0]) + (q[1] - p0[1]) * (q[1] - p0[1])), 0.07, 1e-12);
    }
    // Limits.
    vtkNew<vtkLRSplineStreamTracer> tracer;
    tracer->SetInputData(constant);
    tracer->SetSourceData(s);
    tracer->SetIntegrationDirection(vtkLRSplineStreamTracer::FORWARD);
    tracer->SetIntegrationStep(0.01);
    tracer->SetMaximumNumberOfSteps(5);
    tracer->Update();
    vtkPolyData* out = tracer->GetOutput();
    SV_CHECK(status, out->GetNumberOfPoints() == 6);
    SV_CHECK(status,
      out->GetCellData()->GetArray("ReasonForTermination")->GetComponent(0, 0) ==
        vtkLRSplineStreamTracer::OUT_OF_STEPS);
    tracer->SetMaximumNumberOfSteps(1000);
    tracer->SetMaximumPropagation(0.123);
    tracer->Update();
    double end[3];
    const int n = LastPoint(out, 0, end);
    SV_CHECK(status,
      out->GetCellData()->GetArray("ReasonForTermination")->GetComponent(0, 0) ==
        vtkLRSplineStreamTracer::OUT_OF_LENGTH);
    SV_CHECK_NEAR(status,
      std::sqrt((end[0] - 0.2) * (end[0] - 0.2) + (end[1] - 0.5) * (end[1] - 0.5)), 0.123, 1e-12);
    SV_CHECK(status, n == 14);
    tracer->SetMaximumPropagation(0.0);
    tracer->SetStepMode(vtkLRSplineStreamTracer::FIXED_TIME);
    tracer->SetMaximumIntegrationTime(0.0555);
    tracer->Update();
    SV_CHECK(status, out->GetCellData()->GetArray("ReasonForTermination")->GetComponent(0, 0) == 7);
    vtkDataArray* t = out->GetPointData()->GetArray("IntegrationTime");
    SV_CHECK_NEAR(status, t->GetComponent(out->GetNumberOfPoints() - 1, 0), 0.0555, 1e-14);
  }

  //--- Stagnation near the rotation centre; vorticity of the rotation is (0, 0, 2).
  {
    vtkNew<vtkLRSplineStreamTracer> tracer;
    tracer->SetInputData(rotation);
    tracer->SetSourceData(Seeds({ { 0.5 + 1e-9, 0.5, 0.4 }, { 0.7, 0.5, 0.4 } }));
    tracer->SetTerminalSpeed(1e-6);
    tracer->SetIntegrationDirection(vtkLRSplineStreamTracer::FORWARD);
    tracer->SetMaximumNumberOfSteps(20);
    tracer->ComputeVorticityOn();
    tracer->Update();
    vtkPolyData* out = tracer->GetOutput();
    SV_CHECK(status, out->GetNumberOfLines() == 1);
    vtkDataArray* sr = out->GetFieldData()->GetArray("SeedReasonForTermination");
    SV_CHECK(status, sr->GetComponent(0, 0) == vtkLRSplineStreamTracer::STAGNATION);
    SV_CHECK(status, sr->GetComponent(0, 1) == -1);
    vtkDataArray* vort = out->GetPointData()->GetArray("Vorticity");
    SV_CHECK(status, vort != nullptr);
    if (vort)
    {
      SV_CHECK_NEAR(status, vort->GetComponent(3, 2), 2.0, 1e-10);
      SV_CHECK_NEAR(status, vort->GetComponent(3, 0), 0.0, 1e-10);
    }
    vtkDataArray* speed = out->GetPointData()->GetArray("Speed");
    SV_CHECK_NEAR(status, speed->GetComponent(0, 0), 0.2, 1e-12);
    SV_CHECK(status, out->GetPointData()->GetArray("velocity") != nullptr);
  }

  //--- Mixed precision beats single precision in very small elements (28
  // refinement levels at a point of the circle: the smallest elements are far
  // below the float resolution there; LR heuristic steps).
  {
    // a point of the circle of radius 0.3 through the seed, off all knot planes
    const double onCircle[3] = { 0.5 + 0.3 * std::cos(0.3), 0.5 + 0.3 * std::sin(0.3), 0.47 };
    auto fine = lrtest::LinearField(Arot, brot, 2, 28, onCircle, "TestLRSplineStreamTracer-fine");
    auto s = Seeds({ { 0.5, 0.2, 0.47 } }); // reaches the refined point at t = pi/2 + 0.3
    double E[3][2];
    vtkIdType points[3][2];
    for (int p = 0; p < 3; ++p)
    {
      for (int k = 0; k < 2; ++k)
      {
        auto lines = Trace(fine, s, vtkLRSplineStreamTracer::RUNGE_KUTTA4,
          vtkLRSplineStreamTracer::LR_HEURISTIC, 0.25 / (1 << k), 3.0,
          vtkLRSplineStreamTracer::FORWARD, p, 1e-6, 400000);
        E[p][k] = Eq7(lines, Rotation);
        points[p][k] = lines->GetNumberOfPoints();
      }
    }
    std::cout << "28 refinement levels, RK4 + LR heuristic, Eq. 7 for base steps 1/4 and 1/8: "
              << "double " << E[0][0] << ", " << E[0][1] << " (" << points[0][1]
              << " points); mixed " << E[1][0] << ", " << E[1][1] << " (" << points[1][1]
              << "); single " << E[2][0] << ", " << E[2][1] << " (" << points[2][1] << ")"
              << std::endl;
    SV_CHECK(status, E[1][1] < 1e-6);             // mixed converges to single precision
    SV_CHECK(status, E[1][1] * 10 < E[2][1]);     // and beats single precision
    SV_CHECK(status, E[2][1] > 0.5 * E[2][0]);    // single does not converge
    SV_CHECK(status, E[0][1] <= E[1][1] + 1e-12); // double is at least as good
  }

  //--- Eq. 7 against a reference solution (RKF5, small fixed step).
  {
    auto approx = Trace(rotation, seeds, vtkLRSplineStreamTracer::RUNGE_KUTTA4,
      vtkLRSplineStreamTracer::FIXED_TIME, T / 12, T);
    auto reference = Trace(rotation, seeds, vtkLRSplineStreamTracer::RKF5,
      vtkLRSplineStreamTracer::FIXED_TIME, T / 2000, T);
    const double metric = vtkLRSplineStreamTracer::ComputeErrorMetric(approx, reference);
    const double analytic = Eq7(approx, Rotation);
    std::cout << "Eq. 7 vs RKF5 reference " << metric << ", vs analytic " << analytic << std::endl;
    SV_CHECK_NEAR(status, metric, analytic, 1e-3 * analytic);
    SV_CHECK(status, vtkLRSplineStreamTracer::ComputeErrorMetric(reference, reference) == 0.0);
  }

  //--- The output does not depend on the number of threads.
  {
    auto many = Seeds({ { 0.8, 0.5, 0.5 }, { 0.5, 0.25, 0.3 }, { 0.35, 0.6, 0.9 },
      { 0.6, 0.6, 0.1 }, { 0.55, 0.45, 0.2 }, { 0.9, 0.9, 0.9 } });
    vtkSMPTools::SetBackend("Sequential");
    auto a = Trace(rotation, many, vtkLRSplineStreamTracer::RKF45,
      vtkLRSplineStreamTracer::ADAPTIVE, 0.1, 5.0, vtkLRSplineStreamTracer::BOTH);
    vtkSMPTools::SetBackend("STDThread");
    auto b = Trace(rotation, many, vtkLRSplineStreamTracer::RKF45,
      vtkLRSplineStreamTracer::ADAPTIVE, 0.1, 5.0, vtkLRSplineStreamTracer::BOTH);
    bool same = a->GetNumberOfPoints() == b->GetNumberOfPoints() &&
      a->GetNumberOfLines() == b->GetNumberOfLines();
    for (vtkIdType i = 0; same && i < a->GetNumberOfPoints(); ++i)
    {
      same = a->GetPoint(i)[0] == b->GetPoint(i)[0] && a->GetPoint(i)[2] == b->GetPoint(i)[2];
    }
    SV_CHECK(status, same);
  }

  //--- Bad input.
  {
    vtkNew<vtkTest::ErrorObserver> obs;
    vtkNew<vtkLRSplineStreamTracer> tracer;
    tracer->AddObserver(vtkCommand::ErrorEvent, obs);
    tracer->AddObserver(vtkCommand::WarningEvent, obs);
    tracer->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, obs);
    tracer->SetInputData(rotation);
    tracer->Update(); // no seeds
    SV_CHECK(
      status, obs->GetError() && obs->GetErrorMessage().find("no seeds") != std::string::npos);
    obs->Clear();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    auto nanSeeds = Seeds({ { nan, 0.5, 0.5 }, { 0.7, 0.5, 0.5 } });
    tracer->SetSourceData(nanSeeds);
    tracer->SetMaximumNumberOfSteps(50);
    tracer->Update();
    SV_CHECK(
      status, obs->GetWarning() && obs->GetWarningMessage().find("seed 0") != std::string::npos);
    vtkPolyData* out = tracer->GetOutput();
    SV_CHECK(status, out->GetNumberOfLines() == 2); // the good seed, both directions
    SV_CHECK(status,
      out->GetFieldData()->GetArray("SeedReasonForTermination")->GetComponent(0, 0) ==
        vtkLRSplineStreamTracer::UNEXPECTED_VALUE);
    obs->Clear();
    // a zero field: every line stagnates at once; no line, no endless loop
    const double Z[9] = { 0 }, z[3] = { 0, 0, 0 };
    auto zero = lrtest::LinearField(Z, z, 2, 2, focus, "TestLRSplineStreamTracer-zero");
    tracer->SetInputData(zero);
    tracer->SetSourceData(seeds);
    tracer->SetMaximumNumberOfSteps(1000000);
    tracer->Update();
    SV_CHECK(status, tracer->GetOutput()->GetNumberOfLines() == 0);
    SV_CHECK(status,
      tracer->GetOutput()
          ->GetFieldData()
          ->GetArray("SeedReasonForTermination")
          ->GetComponent(1, 0) == vtkLRSplineStreamTracer::STAGNATION);
    // adaptive with a fixed-step integrator
    tracer->SetInputData(rotation);
    tracer->SetStepMode(vtkLRSplineStreamTracer::ADAPTIVE);
    tracer->SetIntegratorType(vtkLRSplineStreamTracer::RUNGE_KUTTA4);
    tracer->Update();
    SV_CHECK(
      status, obs->GetError() && obs->GetErrorMessage().find("embedded") != std::string::npos);
    obs->Clear();
    tracer->SetStepMode(vtkLRSplineStreamTracer::FIXED_TIME);
    tracer->SetIntegrationStep(-1.0);
    tracer->Update();
    SV_CHECK(status,
      obs->GetError() && obs->GetErrorMessage().find("IntegrationStep") != std::string::npos);
    obs->Clear();
    tracer->SetIntegrationStep(0.01);
    // a scalar field
    vtkLRSplineBuilder builder;
    const int deg[3] = { 1, 1, 1 };
    const std::vector<double> br[3] = { { 0, 1 }, { 0, 1 }, { 0, 1 } };
    builder.InitializeTensorProduct(deg, br, 1, nullptr);
    const std::string path =
      std::string(SPLINEVIZ_TEST_OUTPUT_DIR) + "/TestLRSplineStreamTracer-scalar.lr";
    {
      std::ofstream o(path);
      builder.GetPatch().Write(o);
    }
    vtkNew<vtkLRSplineReader> scalar;
    scalar->SetFileName(path.c_str());
    tracer->SetInputConnection(scalar->GetOutputPort());
    tracer->Update();
    SV_CHECK(
      status, obs->GetError() && obs->GetErrorMessage().find("3-component") != std::string::npos);
    obs->Clear();
    // no field at all
    vtkNew<vtkLRSplineStreamTracer> empty;
    empty->AddObserver(vtkCommand::ErrorEvent, obs);
    empty->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, obs);
    vtkNew<vtkPolyData> nothing;
    empty->SetInputData(nothing);
    empty->SetSourceData(seeds);
    empty->Update();
    SV_CHECK(status,
      obs->GetError() && obs->GetErrorMessage().find("vtkLRSplineReader") != std::string::npos);
  }
  // One set of termination codes and names for both tracers.
  for (int reason = vtkLRSplineStreamTracer::OUT_OF_DOMAIN;
       reason <= vtkTensorLineTracer::NEGATIVE_EIGENVALUE; ++reason)
  {
    SV_CHECK_MSG(status,
      std::string(vtkLRSplineStreamTracer::GetReasonName(reason)) ==
          vtkTensorLineTracer::GetReasonName(reason) &&
        std::string(vtkLRSplineStreamTracer::GetReasonName(reason)) != "unknown",
      "termination code " << reason << ": " << vtkLRSplineStreamTracer::GetReasonName(reason)
                          << " / " << vtkTensorLineTracer::GetReasonName(reason));
  }
  SV_CHECK(status,
    std::string(vtkLRSplineStreamTracer::GetReasonName(vtkLRSplineStreamTracer::OUT_OF_TIME)) ==
      "maximum integration time");
  SV_CHECK(status, std::string(vtkLRSplineStreamTracer::GetReasonName(12)) == "unknown");
  return status.Result();
}
