// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLRSplineStreamTracer.h"

#include "vtkLRSplineField.h"
#include "vtkSplineVizInputArrays.h"
#include "vtkSplineVizProgress.h"
#include "vtkSplineVizRungeKutta.h"
#include "vtkSplineVizSeeds.h"
#include "vtkSplineVizTermination.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <map>
#include <type_traits>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkLRSplineStreamTracer);

// The public codes are the module's (vtkSplineVizTermination.h).
static_assert(static_cast<int>(vtkLRSplineStreamTracer::OUT_OF_DOMAIN) ==
      vtkSplineVizTermination::OUT_OF_DOMAIN &&
    static_cast<int>(vtkLRSplineStreamTracer::NOT_INITIALIZED) ==
      vtkSplineVizTermination::NOT_INITIALIZED &&
    static_cast<int>(vtkLRSplineStreamTracer::UNEXPECTED_VALUE) ==
      vtkSplineVizTermination::UNEXPECTED_VALUE &&
    static_cast<int>(vtkLRSplineStreamTracer::OUT_OF_LENGTH) ==
      vtkSplineVizTermination::OUT_OF_LENGTH &&
    static_cast<int>(vtkLRSplineStreamTracer::OUT_OF_STEPS) ==
      vtkSplineVizTermination::OUT_OF_STEPS &&
    static_cast<int>(vtkLRSplineStreamTracer::STAGNATION) == vtkSplineVizTermination::STAGNATION &&
    static_cast<int>(vtkLRSplineStreamTracer::OUT_OF_TIME) == vtkSplineVizTermination::OUT_OF_TIME,
  "vtkLRSplineStreamTracer's termination codes must be vtkSplineVizTermination's");
// The integrators are the shared Runge-Kutta methods (vtkSplineVizRungeKutta.h).
static_assert(static_cast<int>(vtkLRSplineStreamTracer::EULER) == vtkSplineVizRungeKutta::EULER &&
    static_cast<int>(vtkLRSplineStreamTracer::MIDPOINT) == vtkSplineVizRungeKutta::MIDPOINT &&
    static_cast<int>(vtkLRSplineStreamTracer::KUTTA3) == vtkSplineVizRungeKutta::KUTTA3 &&
    static_cast<int>(vtkLRSplineStreamTracer::RUNGE_KUTTA4) ==
      vtkSplineVizRungeKutta::RUNGE_KUTTA4 &&
    static_cast<int>(vtkLRSplineStreamTracer::RUNGE_KUTTA4_38) ==
      vtkSplineVizRungeKutta::RUNGE_KUTTA4_38 &&
    static_cast<int>(vtkLRSplineStreamTracer::RKF5) == vtkSplineVizRungeKutta::RKF5 &&
    static_cast<int>(vtkLRSplineStreamTracer::HEUN_EULER) == vtkSplineVizRungeKutta::HEUN_EULER &&
    static_cast<int>(vtkLRSplineStreamTracer::BOGACKI_SHAMPINE) ==
      vtkSplineVizRungeKutta::BOGACKI_SHAMPINE &&
    static_cast<int>(vtkLRSplineStreamTracer::RKF45) == vtkSplineVizRungeKutta::RKF45,
  "vtkLRSplineStreamTracer's integrators must be vtkSplineVizRungeKutta's methods");

//------------------------------------------------------------------------------
const char* vtkLRSplineStreamTracer::GetReasonName(int reason)
{
  return vtkSplineVizTermination::Name(reason);
}

namespace
{
namespace RK = vtkSplineVizRungeKutta;

struct Params
{
  RK::Tableau T;
  int StepMode;
  double Step, MinStep, MaxStep, Tolerance;
  vtkIdType MaxSteps;
  double MaxLength, MaxTime, TerminalSpeed;
  bool Vorticity;
  // Points all lines may hold together (this machine's memory): counted per
  // 1024 steps of a line; past it every line stops and the filter fails.
  std::atomic<vtkIdType>* PointsTraced = nullptr;
  vtkIdType PointBudget = VTK_ID_MAX;
  std::atomic<bool>* OverBudget = nullptr;
};

// One traced line.
struct Line
{
  std::vector<double> Points, Velocity, Vorticity, Speed, Time;
  int Reason = -1;
};

enum StepStatus
{
  STEP_OK,
  STEP_OUTSIDE,
  STEP_NAN
};

//------------------------------------------------------------------------------
// The integrator for a state precision S and an evaluation precision E.
template <typename S, typename E>
class Integrator
{
public:
  Integrator(const vtkLRSplineField& field, const Params& params)
    : Field(field)
    , P(params)
  {
  }

  vtkIdType Evaluations = 0;

  // v = f(x); false outside (or non-finite: NaN set). On a surface patch v
  // is the tangential part of the field at the foot of x (kept for Snap).
  bool Eval(const S x[3], S v[3], bool& nan)
  {
    ++this->Evaluations;
    nan = false;
    this->HasFoot = false;
    E xe[3] = { static_cast<E>(x[0]), static_cast<E>(x[1]), static_cast<E>(x[2]) };
    E ve[3] = { E(0), E(0), E(0) }; // a 2-component field leaves z at 0
    if (this->Field.EvaluateWithHint(xe, ve, nullptr, this->Patch, this->Element) < 0)
    {
      if (!(std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2])))
      {
        nan = true;
      }
      return false;
    }
    for (int d = 0; d < 3; ++d)
    {
      v[d] = static_cast<S>(ve[d]);
      if (!std::isfinite(v[d]))
      {
        nan = true;
        return false;
      }
    }
    double normal[3];
    const double xd[3] = { static_cast<double>(xe[0]), static_cast<double>(xe[1]),
      static_cast<double>(xe[2]) };
    if (this->Field.GetPatch(this->Patch).GetParametricDimension() == 2 &&
      this->Field.ProjectOntoSurface(this->Patch, this->Element, xd, this->Foot, normal))
    {
      this->HasFoot = true;
      const double vn = static_cast<double>(v[0]) * normal[0] +
        static_cast<double>(v[1]) * normal[1] + static_cast<double>(v[2]) * normal[2];
      for (int d = 0; d < 3; ++d)
      {
        v[d] = static_cast<S>(static_cast<double>(v[d]) - vn * normal[d]);
      }
    }
    return true;
  }

  // Move x, the point of the last successful Eval, onto its foot on the
  // surface (nothing for volumes): the line stays on the surface.
  void Snap(S x[3]) const
  {
    if (this->HasFoot)
    {
      for (int d = 0; d < 3; ++d)
      {
        x[d] = static_cast<S>(this->Foot[d]);
      }
    }
  }

  // One step of size h (signed) from x with k1 = f(x).
  StepStatus Step(const S x[3], const S k1[3], S h, S out[3], S& error)
  {
    auto f = [this, k1](int stage, const S xs[3], const S*, S k[3]) -> int
    {
      if (stage == 0)
      {
        std::copy(k1, k1 + 3, k);
        return STEP_OK;
      }
      bool nan;
      return this->Eval(xs, k, nan) ? STEP_OK : (nan ? STEP_NAN : STEP_OUTSIDE);
    };
    return static_cast<StepStatus>(RK::Step(this->P.T, x, k1, h, f, out, &error));
  }

  void Append(Line& line, const S x[3], const S v[3], double t)
  {
    double speed = 0.0;
    for (int d = 0; d < 3; ++d)
    {
      line.Points.push_back(static_cast<double>(x[d]));
      line.Velocity.push_back(static_cast<double>(v[d]));
      speed += static_cast<double>(v[d]) * static_cast<double>(v[d]);
    }
    line.Speed.push_back(std::sqrt(speed));
    line.Time.push_back(t);
    if (this->P.Vorticity)
    {
      const double xd[3] = { static_cast<double>(x[0]), static_cast<double>(x[1]),
        static_cast<double>(x[2]) };
      double vd[3] = { 0, 0, 0 }, J[9] = { 0, 0, 0, 0, 0, 0, 0, 0, 0 };
      ++this->Evaluations;
      if (this->Field.Evaluate(xd, vd, J) >= 0)
      {
        line.Vorticity.insert(line.Vorticity.end(), { J[7] - J[5], J[2] - J[6], J[3] - J[1] });
      }
      else
      {
        line.Vorticity.insert(line.Vorticity.end(), { 0.0, 0.0, 0.0 });
      }
    }
  }

  // The line leaves the domain during the step of size h from (x, v): find
  // by bisection the largest step that stays inside, then go on along the
  // velocity to the boundary of the current patch's box and end there.
  void Exit(Line& line, const S x[3], const S v[3], S h, double t, S sign)
  {
    S lo = S(0), hi = h;
    S xlo[3] = { x[0], x[1], x[2] }, vlo[3] = { v[0], v[1], v[2] };
    for (int it = 0; it < 48 && hi - lo > std::abs(h) * S(1e-12); ++it)
    {
      const S mid = S(0.5) * (lo + hi);
      if (!(mid > lo && mid < hi))
      {
        break;
      }
      S xm[3], vm[3], err;
      bool nan = false;
      if (this->Step(x, v, sign * mid, xm, err) == STEP_OK && this->Eval(xm, vm, nan))
      {
        this->Snap(xm);
        lo = mid;
        std::copy(xm, xm + 3, xlo);
        std::copy(vm, vm + 3, vlo);
      }
      else
      {
        hi = mid;
      }
    }
    // The box of the patch containing xlo.
    const double xd[3] = { static_cast<double>(xlo[0]), static_cast<double>(xlo[1]),
      static_cast<double>(xlo[2]) };
    const int patch = this->Field.FindPatch(xd);
    line.Reason = vtkLRSplineStreamTracer::OUT_OF_DOMAIN;
    const bool surface = patch >= 0 && this->Field.GetPatch(patch).GetParametricDimension() == 2;
    if (patch >= 0 && this->Field.GetPatch(patch).GetGeometry() && (lo > S(0) || surface))
    {
      // A curved patch: its box is not its boundary; the bisection's last
      // inside point is the boundary point (to 1e-12 of the step).
      if (lo > S(0))
      {
        this->Append(line, xlo, vlo, t + static_cast<double>(sign) * static_cast<double>(lo));
      }
      return;
    }
    double bounds[6];
    if (patch >= 0)
    {
      this->Field.GetPatch(patch).GetBounds(bounds);
    }
    else
    {
      this->Field.GetBounds(bounds);
    }
    double tExit = VTK_DOUBLE_MAX;
    int exitAxis = -1;
    double exitValue = 0.0;
    for (int d = 0; d < 3; ++d)
    {
      const double w = static_cast<double>(sign) * static_cast<double>(vlo[d]);
      if (w > 0)
      {
        const double te = (bounds[2 * d + 1] - xd[d]) / w;
        if (te < tExit)
        {
          tExit = te;
          exitAxis = d;
          exitValue = bounds[2 * d + 1];
        }
      }
      else if (w < 0)
      {
        const double te = (bounds[2 * d] - xd[d]) / w;
        if (te < tExit)
        {
          tExit = te;
          exitAxis = d;
          exitValue = bounds[2 * d];
        }
      }
    }
    line.Reason = vtkLRSplineStreamTracer::OUT_OF_DOMAIN;
    if (exitAxis < 0)
    {
      return;
    }
    tExit = std::max(0.0, tExit);
    S xe[3];
    for (int d = 0; d < 3; ++d)
    {
      double c = xd[d] + static_cast<double>(sign) * static_cast<double>(vlo[d]) * tExit;
      c = std::min(bounds[2 * d + 1], std::max(bounds[2 * d], c));
      xe[d] = static_cast<S>(c);
    }
    xe[exitAxis] = static_cast<S>(exitValue);
    S ve[3];
    bool nan;
    if (!this->Eval(xe, ve, nan))
    {
      std::copy(vlo, vlo + 3, ve);
    }
    const double te = t + static_cast<double>(sign) * (static_cast<double>(lo) + tExit);
    // Skip a boundary point that coincides with the last point.
    const double* last = line.Points.data() + line.Points.size() - 3;
    if (last[0] == static_cast<double>(xe[0]) && last[1] == static_cast<double>(xe[1]) &&
      last[2] == static_cast<double>(xe[2]))
    {
      return;
    }
    this->Append(line, xe, ve, te);
  }

  void Trace(const double seed[3], S sign, Line& line)
  {
    this->Patch = -1;
    this->Element = -1;
    S x[3] = { static_cast<S>(seed[0]), static_cast<S>(seed[1]), static_cast<S>(seed[2]) };
    S v[3];
    bool nan = false;
    if (!(std::isfinite(seed[0]) && std::isfinite(seed[1]) && std::isfinite(seed[2])))
    {
      line.Reason = vtkLRSplineStreamTracer::UNEXPECTED_VALUE;
      return;
    }
    if (!this->Eval(x, v, nan))
    {
      line.Reason =
        nan ? vtkLRSplineStreamTracer::UNEXPECTED_VALUE : vtkLRSplineStreamTracer::OUT_OF_DOMAIN;
      return;
    }
    this->Snap(x);
    this->PatchOfX = this->Patch;
    this->ElementOfX = this->Element;
    double t = 0.0;
    double length = 0.0;
    this->Append(line, x, v, t);
    const Params& P = this->P;
    const int q = P.T.ErrorOrder;
    S hAdaptive = static_cast<S>(std::min(P.MaxStep, std::max(P.MinStep, P.Step)));
    for (vtkIdType step = 0;; ++step)
    {
      const double speed = std::sqrt(static_cast<double>(v[0]) * v[0] +
        static_cast<double>(v[1]) * v[1] + static_cast<double>(v[2]) * v[2]);
      if (!(speed > P.TerminalSpeed))
      {
        line.Reason = vtkLRSplineStreamTracer::STAGNATION;
        return;
      }
      if (step >= P.MaxSteps)
      {
        line.Reason = vtkLRSplineStreamTracer::OUT_OF_STEPS;
        return;
      }
      if ((step & 1023) == 1023 && P.PointsTraced &&
        (P.PointsTraced->fetch_add(1024, std::memory_order_relaxed) > P.PointBudget ||
          P.OverBudget->load(std::memory_order_relaxed)))
      {
        P.OverBudget->store(true, std::memory_order_relaxed);
        line.Reason = vtkLRSplineStreamTracer::OUT_OF_STEPS;
        return;
      }
      double remaining = VTK_DOUBLE_MAX;
      if (P.MaxTime > 0)
      {
        remaining = P.MaxTime - std::abs(t);
        if (remaining <= 1e-12 * P.MaxTime)
        {
          line.Reason = vtkLRSplineStreamTracer::OUT_OF_TIME;
          return;
        }
      }
      // Step size (positive, time units).
      double h = P.Step;
      switch (P.StepMode)
      {
        case vtkLRSplineStreamTracer::FIXED_LENGTH:
          h = P.Step / speed;
          break;
        case vtkLRSplineStreamTracer::LR_HEURISTIC:
        {
          const vtkLRSplineEvaluator& patch = this->Field.GetPatch(this->PatchOfX);
          h = P.Step * patch.GetElementMinimumSide(this->ElementOfX) /
            std::ldexp(1.0, patch.GetMaximumDegree()) / speed;
          break;
        }
        case vtkLRSplineStreamTracer::ADAPTIVE:
          h = static_cast<double>(hAdaptive);
          break;
        default:
          break;
      }
      bool lastByTime = false;
      if (h >= remaining)
      {
        h = remaining;
        lastByTime = true;
      }
      S xn[3], err = S(0);
      S hs = static_cast<S>(h);
      StepStatus status = STEP_OK;
      for (int attempt = 0;; ++attempt)
      {
        status = this->Step(x, v, sign * hs, xn, err);
        if (status != STEP_OK || P.StepMode != vtkLRSplineStreamTracer::ADAPTIVE)
        {
          break;
        }
        const double e = static_cast<double>(err);
        const double factor = e > 0 ? 0.9 * std::pow(P.Tolerance / e, 1.0 / (q + 1)) : 5.0;
        if (e <= P.Tolerance || static_cast<double>(hs) <= P.MinStep || attempt >= 60)
        {
          double next = static_cast<double>(hs) * std::min(5.0, std::max(0.2, factor));
          hAdaptive = static_cast<S>(std::min(P.MaxStep, std::max(P.MinStep, next)));
          break;
        }
        hs = static_cast<S>(std::max(P.MinStep, static_cast<double>(hs) * std::max(0.2, factor)));
        lastByTime = false;
      }
      if (status == STEP_NAN)
      {
        line.Reason = vtkLRSplineStreamTracer::UNEXPECTED_VALUE;
        return;
      }
      S vn[3];
      bool nanEnd = false;
      if (status == STEP_OUTSIDE || !this->Eval(xn, vn, nanEnd))
      {
        if (nanEnd)
        {
          line.Reason = vtkLRSplineStreamTracer::UNEXPECTED_VALUE;
          return;
        }
        this->Exit(line, x, v, hs, t, sign);
        return;
      }
      this->Snap(xn);
      double dl = 0.0;
      for (int d = 0; d < 3; ++d)
      {
        const double dd = static_cast<double>(xn[d]) - static_cast<double>(x[d]);
        dl += dd * dd;
      }
      dl = std::sqrt(dl);
      bool lastByLength = false;
      if (P.MaxLength > 0 && length + dl > P.MaxLength)
      {
        // shorten the step to end at the maximal length
        hs = static_cast<S>(static_cast<double>(hs) * (P.MaxLength - length) / dl);
        if (this->Step(x, v, sign * hs, xn, err) != STEP_OK || !this->Eval(xn, vn, nanEnd))
        {
          this->Exit(line, x, v, hs, t, sign);
          return;
        }
        this->Snap(xn);
        dl = P.MaxLength - length;
        lastByLength = true;
        lastByTime = false;
      }
      this->PatchOfX = this->Patch;
      this->ElementOfX = this->Element;
      std::copy(xn, xn + 3, x);
      std::copy(vn, vn + 3, v);
      t += static_cast<double>(sign) * static_cast<double>(hs);
      length += dl;
      this->Append(line, x, v, t);
      if (lastByLength)
      {
        line.Reason = vtkLRSplineStreamTracer::OUT_OF_LENGTH;
        return;
      }
      if (lastByTime)
      {
        line.Reason = vtkLRSplineStreamTracer::OUT_OF_TIME;
        return;
      }
    }
  }

private:
  const vtkLRSplineField& Field;
  const Params& P;
  int Patch = -1;
  vtkIdType Element = -1;
  // The foot on a surface of the last evaluated point.
  double Foot[3] = { 0, 0, 0 };
  bool HasFoot = false;

  // patch and element of the current point (for the LR heuristic)
  int PatchOfX = 0;
  vtkIdType ElementOfX = 0;
};

// Trace all seeds with one precision combination.
// With `progress`: progress reported and abort honoured between batches of
// seeds (returns -1 when aborted).
template <typename S, typename E>
vtkIdType TraceAll(const vtkLRSplineField& field, const Params& P, const std::vector<double>& seeds,
  int direction, std::vector<Line>& lines, vtkAlgorithm* progress)
{
  const vtkIdType n = static_cast<vtkIdType>(seeds.size() / 3);
  vtkSMPThreadLocal<vtkIdType> evaluations(0);
  const bool done = vtkSplineVizProgress::For(
    progress, 0, n, 1, 16,
    [&](vtkIdType begin, vtkIdType end)
    {
      Integrator<S, E> integrator(field, P);
      for (vtkIdType s = begin; s < end; ++s)
      {
        for (int dir = 0; dir < 2; ++dir)
        {
          if ((dir == 0 && direction == vtkLRSplineStreamTracer::BACKWARD) ||
            (dir == 1 && direction == vtkLRSplineStreamTracer::FORWARD))
          {
            continue;
          }
          Line& line = lines[2 * s + dir];
          integrator.Trace(seeds.data() + 3 * s, dir == 0 ? S(1) : S(-1), line);
        }
      }
      evaluations.Local() += integrator.Evaluations;
    },
    0.0, 0.9);
  if (!done)
  {
    return -1;
  }
  vtkIdType total = 0;
  for (vtkIdType e : evaluations)
  {
    total += e;
  }
  return total;
}

// The output: the lines of 2 or more points in seed order, forward before
// backward, with their point arrays (the field's vectors, speed, time,
// vorticity), seed ids and termination reasons per line and per seed.
void AssembleOutput(const std::vector<Line>& lines, vtkIdType numSeeds,
  const std::string& arrayName, bool vorticityOn, vtkPolyData* output)
{
  vtkIdType numPoints = 0, numLines = 0;
  for (const Line& l : lines)
  {
    if (l.Time.size() >= 2)
    {
      numPoints += static_cast<vtkIdType>(l.Time.size());
      ++numLines;
    }
  }
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(numPoints);
  vtkNew<vtkDoubleArray> velocity, speed, time, vorticity;
  velocity->SetName(arrayName.c_str());
  velocity->SetNumberOfComponents(3);
  velocity->SetNumberOfTuples(numPoints);
  speed->SetName("Speed");
  speed->SetNumberOfTuples(numPoints);
  time->SetName("IntegrationTime");
  time->SetNumberOfTuples(numPoints);
  vorticity->SetName("Vorticity");
  vorticity->SetNumberOfComponents(3);
  if (vorticityOn)
  {
    vorticity->SetNumberOfTuples(numPoints);
  }
  vtkNew<vtkIntArray> seedIds, reasons;
  seedIds->SetName("SeedIds");
  seedIds->SetNumberOfTuples(numLines);
  reasons->SetName("ReasonForTermination");
  reasons->SetNumberOfTuples(numLines);
  vtkNew<vtkIdTypeArray> offsets, connectivity;
  offsets->SetNumberOfTuples(numLines + 1);
  connectivity->SetNumberOfTuples(numPoints);
  vtkNew<vtkIntArray> seedReasons;
  seedReasons->SetName("SeedReasonForTermination");
  seedReasons->SetNumberOfComponents(2);
  seedReasons->SetNumberOfTuples(numSeeds);
  vtkIdType p = 0, c = 0;
  for (vtkIdType s = 0; s < numSeeds; ++s)
  {
    for (int dir = 0; dir < 2; ++dir)
    {
      const Line& l = lines[2 * s + dir];
      seedReasons->SetTypedComponent(s, dir, l.Reason);
      if (l.Time.size() < 2)
      {
        continue;
      }
      offsets->SetValue(c, p);
      seedIds->SetValue(c, static_cast<int>(s));
      reasons->SetValue(c, l.Reason);
      for (std::size_t i = 0; i < l.Time.size(); ++i, ++p)
      {
        points->SetPoint(p, l.Points.data() + 3 * i);
        velocity->SetTypedTuple(p, l.Velocity.data() + 3 * i);
        speed->SetValue(p, l.Speed[i]);
        time->SetValue(p, l.Time[i]);
        if (vorticityOn)
        {
          vorticity->SetTypedTuple(p, l.Vorticity.data() + 3 * i);
        }
        connectivity->SetValue(p, p);
      }
      ++c;
    }
  }
  offsets->SetValue(numLines, numPoints);
  vtkNew<vtkCellArray> cells;
  cells->SetData(offsets, connectivity);
  output->SetPoints(points);
  output->SetLines(cells);
  vtkPointData* pd = output->GetPointData();
  pd->AddArray(velocity);
  pd->SetActiveVectors(velocity->GetName());
  pd->AddArray(speed);
  pd->SetActiveScalars("Speed");
  pd->AddArray(time);
  if (vorticityOn)
  {
    pd->AddArray(vorticity);
  }
  output->GetCellData()->AddArray(seedIds);
  output->GetCellData()->AddArray(reasons);
  output->GetFieldData()->AddArray(seedReasons);
}

// Calls visit(seed and direction, npts, ids) for each line of `pd` with two
// or more points, in order; the direction is 1 for a backward line (negative
// time at its end), 0 for a forward one. Stops, returning false, when visit
// returns false.
template <typename Visit>
bool ForEachSeedLine(vtkPolyData* pd, vtkDataArray* time, vtkDataArray* seedIds, const Visit& visit)
{
  vtkCellArray* ls = pd->GetLines();
  vtkIdType npts;
  const vtkIdType* ids;
  vtkIdType cell = 0;
  for (ls->InitTraversal(); ls->GetNextCell(npts, ids); ++cell)
  {
    if (npts < 2)
    {
      continue;
    }
    const int dir = time->GetComponent(ids[npts - 1], 0) < 0 ? 1 : 0;
    if (!visit(std::make_pair(static_cast<int>(seedIds->GetComponent(cell, 0)), dir), npts, ids))
    {
      return false;
    }
  }
  return true;
}

}

//------------------------------------------------------------------------------
vtkLRSplineStreamTracer::vtkLRSplineStreamTracer()
{
  this->SetNumberOfInputPorts(2);
}

vtkLRSplineStreamTracer::~vtkLRSplineStreamTracer() = default;

//------------------------------------------------------------------------------
void vtkLRSplineStreamTracer::SetArrayName(const char* name)
{
  vtkSplineVizInputArrays::SetName(this, 0, 0, name);
}

const char* vtkLRSplineStreamTracer::GetArrayName()
{
  return vtkSplineVizInputArrays::GetName(this, 0);
}

//------------------------------------------------------------------------------
int vtkLRSplineStreamTracer::GetIntegratorOrder(int integrator)
{
  return vtkSplineVizRungeKutta::MakeTableau(integrator).Order;
}

bool vtkLRSplineStreamTracer::IsEmbedded(int integrator)
{
  return vtkSplineVizRungeKutta::MakeTableau(integrator).Embedded;
}

const char* vtkLRSplineStreamTracer::GetIntegratorName(int integrator)
{
  return vtkSplineVizRungeKutta::Name(integrator);
}

//------------------------------------------------------------------------------
void vtkLRSplineStreamTracer::SetSourceConnection(vtkAlgorithmOutput* algOutput)
{
  this->SetInputConnection(1, algOutput);
}

void vtkLRSplineStreamTracer::SetSourceData(vtkDataObject* source)
{
  this->SetInputData(1, source);
}

//------------------------------------------------------------------------------
int vtkLRSplineStreamTracer::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == 1)
  {
    vtkSplineVizSeeds::FillPortInformation(info);
    return 1;
  }
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataObject");
  return 1;
}

//------------------------------------------------------------------------------
int vtkLRSplineStreamTracer::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkSplineVizSeeds::RequestUpdateExtent(inputVector, outputVector); // the whole spline everywhere
  return 1;
}

//------------------------------------------------------------------------------
bool vtkLRSplineStreamTracer::CheckSettings()
{
  if (!(this->IntegrationStep > 0) || !std::isfinite(this->IntegrationStep))
  {
    vtkErrorMacro(<< "IntegrationStep must be a positive number");
    return false;
  }
  if (this->StepMode == ADAPTIVE && !IsEmbedded(this->IntegratorType))
  {
    vtkErrorMacro(<< "the ADAPTIVE step mode needs an embedded integrator (Heun-Euler, "
                     "Bogacki-Shampine or RKF45), not "
                  << GetIntegratorName(this->IntegratorType));
    return false;
  }
  if (this->StepMode == ADAPTIVE &&
    (!(this->MaximumError > 0) || !(this->MinimumIntegrationStep > 0) ||
      !(this->MaximumIntegrationStep >= this->MinimumIntegrationStep)))
  {
    vtkErrorMacro(<< "the ADAPTIVE step mode needs MaximumError > 0 and 0 < "
                     "MinimumIntegrationStep <= MaximumIntegrationStep");
    return false;
  }
  if (this->MaximumNumberOfSteps < 0)
  {
    vtkErrorMacro(<< "MaximumNumberOfSteps must not be negative");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
int vtkLRSplineStreamTracer::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkDataObject* spline = vtkDataObject::GetData(inputVector[0], 0);
  vtkDataObject* source = inputVector[1]->GetNumberOfInformationObjects() > 0
    ? vtkDataObject::GetData(inputVector[1], 0)
    : nullptr;
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  this->NumberOfEvaluations = 0;
  if (!spline)
  {
    vtkErrorMacro(<< "no vector field: connect the output of vtkLRSplineReader to port 0");
    return 0;
  }
  if (!source)
  {
    vtkErrorMacro(<< "no seeds: connect a data set whose points are the seeds to the source "
                     "port (port 1)");
    return 0;
  }
  if (!this->CheckSettings())
  {
    return 0;
  }
  std::string error, fieldName;
  if (!vtkLRSplineField::SelectedFieldName(this, 0, 0, spline, fieldName, &error))
  {
    vtkErrorMacro(<< error);
    return 0;
  }
  if (!vtkLRSplineField::BuildCached(this->Field, this->FieldKey, spline, fieldName.c_str(),
        this->LocatorType, this->ForestResolution, false, &error, this->SurfaceTolerance))
  {
    vtkErrorMacro(<< "cannot evaluate the vector field: " << error);
    return 0;
  }
  const int nc = this->Field->GetNumberOfComponents();
  const bool surfaces = this->Field->GetParametricDimension() == 2;
  if (nc != 3 && !(nc == 2 && surfaces))
  {
    vtkErrorMacro(<< "the field \"" << this->Field->GetArrayName() << "\" has " << nc
                  << " components; streamlines need a 3-component vector field"
                  << (surfaces ? " or, on surfaces, a 2-component one" : ""));
    return 0;
  }
  if (this->Precision != DOUBLE_PRECISION)
  {
    this->Field->MakeFloat();
  }

  // Absurd seed counts (e.g. an implicit image of 10^9 points) are refused
  // before anything is allocated: per seed its coordinates, two lines and at
  // least two points in each.
  const double seedCount = vtkSplineVizSeeds::Count(source);
  if (!vtkSplineVizProgress::CheckOutputSize(seedCount, 3 * 8.0 + 2 * (sizeof(Line) + 2 * 80.0),
        "the streamlines of all seeds (source port)", &error))
  {
    vtkErrorMacro(<< error);
    return 0;
  }
  std::vector<double> seeds;
  vtkSplineVizSeeds::Collect(source, seeds);
  const vtkIdType numSeeds = static_cast<vtkIdType>(seeds.size() / 3);
  for (vtkIdType s = 0; s < numSeeds; ++s)
  {
    if (!std::isfinite(seeds[3 * s]) || !std::isfinite(seeds[3 * s + 1]) ||
      !std::isfinite(seeds[3 * s + 2]))
    {
      vtkWarningMacro(<< "seed " << s << " has a coordinate that is not a finite number; it "
                      << "gives no line (reason UNEXPECTED_VALUE)");
    }
  }

  Params P;
  P.T = RK::MakeTableau(this->IntegratorType);
  P.StepMode = this->StepMode;
  P.Step = this->IntegrationStep;
  P.MinStep = this->MinimumIntegrationStep;
  P.MaxStep = this->MaximumIntegrationStep;
  P.Tolerance = this->MaximumError;
  P.MaxSteps = this->MaximumNumberOfSteps;
  P.MaxLength = this->MaximumPropagation;
  P.MaxTime = this->MaximumIntegrationTime;
  P.TerminalSpeed = this->TerminalSpeed;
  P.Vorticity = this->ComputeVorticity != 0;
  // Each stored point: position, velocity, (vorticity,) speed, time, and
  // the output's copy of all that.
  std::atomic<vtkIdType> pointsTraced(0);
  std::atomic<bool> overBudget(false);
  P.PointsTraced = &pointsTraced;
  P.OverBudget = &overBudget;
  P.PointBudget =
    static_cast<vtkIdType>(vtkSplineVizProgress::GetMemoryLimit() / (2 * (P.Vorticity ? 88 : 64)));

  std::vector<Line> lines(2 * numSeeds);
  switch (this->Precision)
  {
    case MIXED_PRECISION:
      this->NumberOfEvaluations =
        TraceAll<double, float>(*this->Field, P, seeds, this->IntegrationDirection, lines, this);
      break;
    case SINGLE_PRECISION:
      this->NumberOfEvaluations =
        TraceAll<float, float>(*this->Field, P, seeds, this->IntegrationDirection, lines, this);
      break;
    default:
      this->NumberOfEvaluations =
        TraceAll<double, double>(*this->Field, P, seeds, this->IntegrationDirection, lines, this);
      break;
  }

  if (this->NumberOfEvaluations < 0)
  {
    this->NumberOfEvaluations = 0;
    output->Initialize(); // aborted: a clean, empty output
    return 1;
  }
  if (overBudget.load())
  {
    vtkErrorMacro(<< "the streamlines would need more than this machine's memory ("
                  << pointsTraced.load() << " points and counting): lower MaximumNumberOfSteps "
                  << "or the number of seeds");
    return 0;
  }

  AssembleOutput(lines, numSeeds, this->Field->GetArrayName(), this->ComputeVorticity != 0, output);
  return 1;
}

//------------------------------------------------------------------------------
double vtkLRSplineStreamTracer::ComputeErrorMetric(
  vtkPolyData* approximation, vtkPolyData* reference, const char* velocityName)
{
  if (!approximation || !reference)
  {
    return -1.0;
  }
  auto arrays = [velocityName](
                  vtkPolyData* pd, vtkDataArray*& vel, vtkDataArray*& t, vtkDataArray*& ids)
  {
    vel =
      velocityName ? pd->GetPointData()->GetArray(velocityName) : pd->GetPointData()->GetVectors();
    t = pd->GetPointData()->GetArray("IntegrationTime");
    ids = pd->GetCellData()->GetArray("SeedIds");
    return vel && t && ids && vel->GetNumberOfComponents() == 3;
  };
  vtkDataArray *av, *at, *aid, *rv, *rt, *rid;
  if (!arrays(approximation, av, at, aid) || !arrays(reference, rv, rt, rid))
  {
    return -1.0;
  }
  // Reference lines by (seed, direction).
  std::map<std::pair<int, int>, std::vector<vtkIdType>> refLines;
  ForEachSeedLine(reference, rt, rid,
    [&refLines](const std::pair<int, int>& key, vtkIdType npts, const vtkIdType* ids)
    {
      refLines[key].assign(ids, ids + npts);
      return true;
    });
  double worst = 0.0;
  const bool matched = ForEachSeedLine(approximation, at, aid,
    [&](const std::pair<int, int>& key, vtkIdType npts, const vtkIdType* ids)
    {
      const int dir = key.second;
      auto it = refLines.find(key);
      if (it == refLines.end())
      {
        return false;
      }
      const std::vector<vtkIdType>& ref = it->second;
      // reference times as |t| (monotonically increasing)
      std::vector<double> rtime(ref.size());
      for (std::size_t k = 0; k < ref.size(); ++k)
      {
        rtime[k] = std::abs(rt->GetComponent(ref[k], 0));
      }
      double sum = 0.0;
      for (vtkIdType i = 1; i < npts; ++i)
      {
        const double ti = std::abs(at->GetComponent(ids[i], 0));
        const double dt = ti - std::abs(at->GetComponent(ids[i - 1], 0));
        double y[3], x[3];
        approximation->GetPoint(ids[i], y);
        if (ti >= rtime.back())
        {
          reference->GetPoint(ref.back(), x);
        }
        else
        {
          const std::size_t k1 = static_cast<std::size_t>(
            std::upper_bound(rtime.begin(), rtime.end(), ti) - rtime.begin());
          const std::size_t k0 = k1 - 1;
          const double h = rtime[k1] - rtime[k0];
          const double s = h > 0 ? (ti - rtime[k0]) / h : 0.0;
          // cubic Hermite with the velocities (d x / d|t| = +-v)
          const double sgn = dir == 1 ? -1.0 : 1.0;
          const double h00 = 2 * s * s * s - 3 * s * s + 1, h10 = s * s * s - 2 * s * s + s;
          const double h01 = -2 * s * s * s + 3 * s * s, h11 = s * s * s - s * s;
          double p0[3], p1[3], v0[3], v1[3];
          reference->GetPoint(ref[k0], p0);
          reference->GetPoint(ref[k1], p1);
          rv->GetTuple(ref[k0], v0);
          rv->GetTuple(ref[k1], v1);
          for (int d = 0; d < 3; ++d)
          {
            x[d] = h00 * p0[d] + h10 * h * sgn * v0[d] + h01 * p1[d] + h11 * h * sgn * v1[d];
          }
        }
        double e = 0.0;
        for (int d = 0; d < 3; ++d)
        {
          e += (x[d] - y[d]) * (x[d] - y[d]);
        }
        sum += std::abs(dt) * std::sqrt(e);
      }
      worst = std::max(worst, sum);
      return true;
    });
  return matched ? worst : -1.0;
}

//------------------------------------------------------------------------------
void vtkLRSplineStreamTracer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  const char* field = vtkSplineVizInputArrays::GetName(this, 0);
  os << indent << "Field (input array 0): " << (field && *field ? field : "(active vectors)")
     << "\n";
  os << indent << "IntegratorType: " << GetIntegratorName(this->IntegratorType) << "\n";
  os << indent << "StepMode: " << this->StepMode << "\n";
  os << indent << "IntegrationStep: " << this->IntegrationStep << "\n";
  os << indent << "MinimumIntegrationStep: " << this->MinimumIntegrationStep << "\n";
  os << indent << "MaximumIntegrationStep: " << this->MaximumIntegrationStep << "\n";
  os << indent << "MaximumError: " << this->MaximumError << "\n";
  os << indent << "IntegrationDirection: " << this->IntegrationDirection << "\n";
  os << indent << "MaximumNumberOfSteps: " << this->MaximumNumberOfSteps << "\n";
  os << indent << "MaximumPropagation: " << this->MaximumPropagation << "\n";
  os << indent << "MaximumIntegrationTime: " << this->MaximumIntegrationTime << "\n";
  os << indent << "TerminalSpeed: " << this->TerminalSpeed << "\n";
  os << indent << "Precision: " << this->Precision << "\n";
  os << indent << "ComputeVorticity: " << this->ComputeVorticity << "\n";
  os << indent << "LocatorType: " << this->LocatorType << "\n";
  os << indent << "ForestResolution: " << this->ForestResolution << "\n";
  os << indent << "SurfaceTolerance: " << this->SurfaceTolerance << "\n";
}
