// SPDX-License-Identifier: BSD-3-Clause
#include "vtkTensorLineTracer.h"

#include "vtkSplineVizError.h"
#include "vtkSplineVizInputArrays.h"
#include "vtkSplineVizProgress.h"
#include "vtkSplineVizRungeKutta.h"
#include "vtkSplineVizSeeds.h"
#include "vtkSplineVizTensorMath.h"
#include "vtkSplineVizTermination.h"

#include "vtkAOSDataArrayTemplate.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkDataSetAttributes.h"
#include "vtkGenericCell.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkStaticCellLocator.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <initializer_list>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkTensorLineTracer);

// The public codes are the module's (vtkSplineVizTermination.h).
static_assert(
  static_cast<int>(vtkTensorLineTracer::OUT_OF_DOMAIN) == vtkSplineVizTermination::OUT_OF_DOMAIN &&
    static_cast<int>(vtkTensorLineTracer::NOT_INITIALIZED) ==
      vtkSplineVizTermination::NOT_INITIALIZED &&
    static_cast<int>(vtkTensorLineTracer::UNEXPECTED_VALUE) ==
      vtkSplineVizTermination::UNEXPECTED_VALUE &&
    static_cast<int>(vtkTensorLineTracer::OUT_OF_LENGTH) ==
      vtkSplineVizTermination::OUT_OF_LENGTH &&
    static_cast<int>(vtkTensorLineTracer::OUT_OF_STEPS) == vtkSplineVizTermination::OUT_OF_STEPS &&
    static_cast<int>(vtkTensorLineTracer::STAGNATION) == vtkSplineVizTermination::STAGNATION &&
    static_cast<int>(vtkTensorLineTracer::LOW_ANISOTROPY) ==
      vtkSplineVizTermination::LOW_ANISOTROPY &&
    static_cast<int>(vtkTensorLineTracer::HIGH_CURVATURE) ==
      vtkSplineVizTermination::HIGH_CURVATURE &&
    static_cast<int>(vtkTensorLineTracer::OUT_OF_MASK) == vtkSplineVizTermination::OUT_OF_MASK &&
    static_cast<int>(vtkTensorLineTracer::NEGATIVE_EIGENVALUE) ==
      vtkSplineVizTermination::NEGATIVE_EIGENVALUE,
  "vtkTensorLineTracer's termination codes must be vtkSplineVizTermination's");

namespace
{
namespace TM = vtkSplineVizTensorMath;
namespace RK = vtkSplineVizRungeKutta;

// Per-point flags of the precomputed tensors.
enum : unsigned char
{
  POINT_OK = 0,
  POINT_NONFINITE = 1,
  POINT_NEGATIVE = 2 // log-Euclidean with the STOP policy: indefinite point tensor
};

// Result of an interpolation.
enum FieldStatus
{
  FIELD_OK = 0,
  FIELD_OUTSIDE,
  FIELD_NONFINITE,
  FIELD_NEGATIVE
};

//------------------------------------------------------------------------------
// One data set of the input with its point tensors in the canonical order
// (or their logarithms for log-Euclidean interpolation).
struct Block
{
  vtkDataSet* Data = nullptr;
  bool IsImage = false;
  // image data: index = M (x, 1) (physical to index, rows of a 3x4 matrix)
  double M[12];
  int Extent[6];
  int Dims[3];
  // other data sets
  vtkSmartPointer<vtkStaticCellLocator> Locator;
  std::vector<double> Tensors; // 6 per point
  std::vector<unsigned char> Flags;
  std::vector<float> Mask; // empty: no mask
  bool AnyFlag = false;
};

// Per-thread interpolation state.
struct Probe
{
  int BlockIndex = -1;
  vtkIdType CellId = -1;
  vtkNew<vtkGenericCell> Cell;
  std::vector<double> Weights;
  vtkIdType Evaluations = 0;
};

class Field
{
public:
  std::vector<Block> Blocks;
  bool LogEuclidean = false;
  int SignPolicy = TM::SIGN_SKIP;
  bool HasMask = false;
  bool NeedLinearAnisotropy = false; // tensorlines with f = cl
  int MaxCellSize = 8;

  // Interpolates the (log) tensor and the mask at x.
  FieldStatus Interpolate(const double x[3], Probe& probe, double t[6], double& mask) const
  {
    ++probe.Evaluations;
    const int n = static_cast<int>(this->Blocks.size());
    if (probe.BlockIndex >= 0)
    {
      const FieldStatus s = this->InterpolateBlock(probe.BlockIndex, x, probe, t, mask);
      if (s != FIELD_OUTSIDE)
      {
        return s;
      }
    }
    for (int b = 0; b < n; ++b)
    {
      if (b == probe.BlockIndex)
      {
        continue;
      }
      const FieldStatus s = this->InterpolateBlock(b, x, probe, t, mask);
      if (s != FIELD_OUTSIDE)
      {
        probe.BlockIndex = b;
        return s;
      }
    }
    return FIELD_OUTSIDE;
  }

private:
  FieldStatus Accumulate(const Block& block, int count, const vtkIdType* ids, const double* w,
    double t[6], double& mask) const
  {
    for (int c = 0; c < 6; ++c)
    {
      t[c] = 0.0;
    }
    mask = 0.0;
    for (int k = 0; k < count; ++k)
    {
      if (w[k] == 0.0)
      {
        continue;
      }
      const vtkIdType id = ids[k];
      if (block.AnyFlag && block.Flags[id] != POINT_OK)
      {
        return block.Flags[id] == POINT_NONFINITE ? FIELD_NONFINITE : FIELD_NEGATIVE;
      }
      const double* p = block.Tensors.data() + 6 * id;
      for (int c = 0; c < 6; ++c)
      {
        t[c] += w[k] * p[c];
      }
      if (this->HasMask)
      {
        mask += w[k] * static_cast<double>(block.Mask[id]);
      }
    }
    if (!this->HasMask)
    {
      mask = 1.0;
    }
    return FIELD_OK;
  }

  FieldStatus InterpolateBlock(
    int b, const double x[3], Probe& probe, double t[6], double& mask) const
  {
    const Block& block = this->Blocks[b];
    if (block.IsImage)
    {
      const double tol = 1e-7;
      int i0[3];
      double f[3];
      for (int a = 0; a < 3; ++a)
      {
        const double* m = block.M + 4 * a;
        const double c = m[0] * x[0] + m[1] * x[1] + m[2] * x[2] + m[3] - block.Extent[2 * a];
        const int n = block.Dims[a];
        if (n == 1)
        {
          if (!(std::abs(c) <= tol))
          {
            return FIELD_OUTSIDE;
          }
          i0[a] = 0;
          f[a] = 0.0;
          continue;
        }
        if (!(c >= -tol && c <= (n - 1) + tol))
        {
          return FIELD_OUTSIDE;
        }
        int i = static_cast<int>(std::floor(c));
        i = std::min(std::max(i, 0), n - 2);
        i0[a] = i;
        f[a] = std::min(std::max(c - i, 0.0), 1.0);
      }
      const vtkIdType sx = 1, sy = block.Dims[0],
                      sz = static_cast<vtkIdType>(block.Dims[0]) * block.Dims[1];
      const vtkIdType base = i0[0] + sy * i0[1] + sz * i0[2];
      vtkIdType ids[8];
      double w[8];
      int count = 0;
      for (int dz = 0; dz < 2; ++dz)
      {
        const double wz = dz ? f[2] : 1.0 - f[2];
        for (int dy = 0; dy < 2; ++dy)
        {
          const double wy = dy ? f[1] : 1.0 - f[1];
          for (int dx = 0; dx < 2; ++dx)
          {
            const double wx = dx ? f[0] : 1.0 - f[0];
            const double ww = wx * wy * wz;
            if (ww == 0.0)
            {
              continue; // also keeps the index of flat axes in range
            }
            ids[count] = base + dx * sx + dy * sy + dz * sz;
            w[count] = ww;
            ++count;
          }
        }
      }
      return this->Accumulate(block, count, ids, w, t, mask);
    }

    // Any other data set: the cell containing x and its interpolation weights.
    double xx[3] = { x[0], x[1], x[2] };
    double pcoords[3], closest[3], dist2;
    int subId;
    bool found = false;
    if (probe.BlockIndex == b && probe.CellId >= 0)
    {
      found =
        probe.Cell->EvaluatePosition(xx, closest, subId, pcoords, dist2, probe.Weights.data()) == 1;
    }
    if (!found)
    {
      const vtkIdType cellId =
        block.Locator->FindCell(xx, 0.0, probe.Cell, subId, pcoords, probe.Weights.data());
      if (cellId < 0)
      {
        if (probe.BlockIndex == b)
        {
          probe.CellId = -1; // the generic cell no longer holds the hinted cell
        }
        return FIELD_OUTSIDE;
      }
      probe.CellId = cellId;
      if (probe.BlockIndex != b)
      {
        probe.BlockIndex = b;
      }
    }
    vtkIdList* ids = probe.Cell->GetPointIds();
    return this->Accumulate(block, static_cast<int>(ids->GetNumberOfIds()), ids->GetPointer(0),
      probe.Weights.data(), t, mask);
  }
};

//------------------------------------------------------------------------------
// A tensor at a point: eigen-system, FA, linear anisotropy, mask.
struct Sample
{
  double T[6];
  double L[3];
  double E[3][3];
  double FA = 0.0;
  double CL = 0.0;
  double Mask = 1.0;
};

// What every output point carries.
struct PointRecord
{
  double X[3];
  double T[6];
  double E[3];
  double FA;
  double Arc;
};

struct Line
{
  std::vector<PointRecord> Points;
  int Reasons[2] = { 0, 0 };
  int Rejected = 0; // reason code when the seed gave no line
  double Length = 0.0;
};

struct Params
{
  RK::Tableau Integrator; // midpoint (RUNGE_KUTTA2) or classic RK4
  double H = 0.1;
  double MaxLength = 0.0;
  vtkIdType MaxSteps = 10000;
  double StopFA = 0.1;
  double CosMaxAngle = 0.0;
  bool Tensorlines = false;
  bool UseCL = true;
  double F = 0.5, G = 0.5;
};

// The tracker's settings from the filter's (StepLength already computed).
Params MakeParams(vtkTensorLineTracer* self)
{
  Params p;
  // RK4's weights over their denominator, h / 6 (k1 + 2 k2 + 2 k3 + k4), as
  // this filter has always summed them.
  p.Integrator = self->GetIntegratorType() == vtkTensorLineTracer::RUNGE_KUTTA2
    ? RK::MakeTableau(RK::MIDPOINT)
    : RK::OverDenominator(RK::MakeTableau(RK::RUNGE_KUTTA4), 6.0);
  p.H = self->GetStepLength();
  p.MaxLength = self->GetMaximumPropagation();
  p.MaxSteps = self->GetMaximumNumberOfSteps();
  p.StopFA = self->GetStoppingFAThreshold();
  p.CosMaxAngle = std::cos(vtkMath::RadiansFromDegrees(self->GetMaximumAngle()));
  p.Tensorlines = self->GetUseTensorlines();
  p.UseCL = self->GetTensorlineWeightFromLinearAnisotropy();
  p.F = self->GetTensorlineEigenvectorWeight();
  p.G = self->GetTensorlineDeflectionWeight();
  return p;
}

//------------------------------------------------------------------------------
// Sylvester's criterion: true when the leading principal minors are positive
// (then every eigenvalue is positive). A quick test that spares the
// eigen-decomposition of most point tensors during the setup.
bool PositiveDefinite(const double t[6])
{
  // t = {xx, yy, zz, xy, yz, xz}
  const double m2 = t[0] * t[1] - t[3] * t[3];
  const double det = t[0] * (t[1] * t[2] - t[4] * t[4]) - t[3] * (t[3] * t[2] - t[4] * t[5]) +
    t[5] * (t[3] * t[4] - t[1] * t[5]);
  return t[0] > 0.0 && m2 > 0.0 && det > 0.0;
}

//------------------------------------------------------------------------------
// Converts a (log) tensor to a Sample; false for an indefinite tensor under
// the STOP policy.
bool Analyze(const Field& field, const double t[6], double mask, Sample& s)
{
  if (field.LogEuclidean)
  {
    TM::Exp(t, s.T, s.L, s.E);
  }
  else
  {
    for (int i = 0; i < 6; ++i)
    {
      s.T[i] = t[i];
    }
    // Only e1 is needed (E[1] and E[2] are not used): the faster solver,
    // unless the absolute values make another eigenvector the principal one.
    TM::PrincipalEigen(s.T, s.L, s.E[0]);
    if (field.SignPolicy == TM::SIGN_ABSOLUTE && std::abs(s.L[2]) > s.L[0])
    {
      TM::EigenDecomposition(s.T, s.L, s.E);
    }
    else
    {
      for (int k = 1; k < 3; ++k)
      {
        s.E[k][0] = s.E[k][1] = s.E[k][2] = 0.0;
      }
    }
    // (the policy keeps E[0] first here; it only changes the values)
    if (!TM::ApplySignPolicy(field.SignPolicy, s.L, s.E))
    {
      return false;
    }
  }
  s.FA = TM::FractionalAnisotropy(s.L);
  if (field.NeedLinearAnisotropy)
  {
    double cl, cp, cs;
    TM::WestinMetrics(s.L, cl, cp, cs);
    s.CL = std::min(std::max(cl, 0.0), 1.0);
  }
  s.Mask = mask;
  return true;
}

//------------------------------------------------------------------------------
class Tracker
{
public:
  Tracker(const Field& field, const Params& params)
    : F(field)
    , P(params)
  {
    this->Interp.Weights.resize(std::max(8, field.MaxCellSize));
  }

  vtkIdType GetEvaluations() const { return this->Interp.Evaluations; }

  // 0 or the reason why x has no usable tensor.
  int Evaluate(const double x[3], Sample& s)
  {
    double t[6], mask;
    switch (this->F.Interpolate(x, this->Interp, t, mask))
    {
      case FIELD_OUTSIDE:
        return vtkTensorLineTracer::OUT_OF_DOMAIN;
      case FIELD_NONFINITE:
        return vtkTensorLineTracer::UNEXPECTED_VALUE;
      case FIELD_NEGATIVE:
        return vtkTensorLineTracer::NEGATIVE_EIGENVALUE;
      default:
        break;
    }
    return Analyze(this->F, t, mask, s) ? 0 : vtkTensorLineTracer::NEGATIVE_EIGENVALUE;
  }

  // The direction at a sample: the principal eigenvector turned to agree
  // with `ref`, or the tensorline blend with the incoming direction `in`.
  // The first stage of a step uses ref = in (the previous step); the others
  // use ref = the first stage's direction, so that the stages of one step
  // never cancel each other (which they could when the field has turned
  // away from the previous step).
  bool Direction(const Sample& s, const double in[3], const double ref[3], double out[3]) const
  {
    if (!(s.L[0] > 0.0))
    {
      return false;
    }
    const double* e = s.E[0];
    const double sign = (e[0] * ref[0] + e[1] * ref[1] + e[2] * ref[2]) < 0.0 ? -1.0 : 1.0;
    if (!this->P.Tensorlines)
    {
      for (int d = 0; d < 3; ++d)
      {
        out[d] = sign * e[d];
      }
      return true;
    }
    const double f = this->P.UseCL ? s.CL : this->P.F;
    const double g = this->P.G;
    double u[3];
    TM::Multiply(s.T, in, u);
    double v[3];
    for (int d = 0; d < 3; ++d)
    {
      v[d] = f * sign * e[d] + (1.0 - f) * ((1.0 - g) * in[d] + g * u[d] / s.L[0]);
    }
    const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (!(n > 1e-12))
    {
      return false;
    }
    for (int d = 0; d < 3; ++d)
    {
      out[d] = v[d] / n;
    }
    return true;
  }

  void Trace(const double seed[3], Line& line)
  {
    line.Points.clear();
    line.Rejected = 0;
    line.Length = 0.0;
    if (!(std::isfinite(seed[0]) && std::isfinite(seed[1]) && std::isfinite(seed[2])))
    {
      line.Rejected = vtkTensorLineTracer::UNEXPECTED_VALUE;
      return;
    }
    Sample s0;
    const int r = this->Evaluate(seed, s0);
    if (r != 0)
    {
      line.Rejected = r;
      return;
    }
    if (s0.Mask < 0.5)
    {
      line.Rejected = vtkTensorLineTracer::OUT_OF_MASK;
      return;
    }
    if (s0.FA < this->P.StopFA)
    {
      line.Rejected = vtkTensorLineTracer::LOW_ANISOTROPY;
      return;
    }
    if (!(s0.L[0] > 0.0))
    {
      line.Rejected = vtkTensorLineTracer::STAGNATION;
      return;
    }
    double lengthF = 0.0, lengthB = 0.0;
    line.Reasons[1] = this->Half(seed, s0, 1.0, this->Forward, lengthF);
    line.Reasons[0] = this->Half(seed, s0, -1.0, this->Backward, lengthB);
    line.Length = lengthF + lengthB;
    line.Points.reserve(this->Forward.size() + this->Backward.size() + 1);
    for (auto it = this->Backward.rbegin(); it != this->Backward.rend(); ++it)
    {
      PointRecord p = *it;
      for (int d = 0; d < 3; ++d)
      {
        p.E[d] = -p.E[d];
      }
      p.Arc = -p.Arc;
      line.Points.push_back(p);
    }
    PointRecord p0;
    std::copy(seed, seed + 3, p0.X);
    std::copy(s0.T, s0.T + 6, p0.T);
    std::copy(s0.E[0], s0.E[0] + 3, p0.E);
    p0.FA = s0.FA;
    p0.Arc = 0.0;
    line.Points.push_back(p0);
    line.Points.insert(line.Points.end(), this->Forward.begin(), this->Forward.end());
  }

private:
  // A stage without a direction (zero tensor): its FA is 0, so it is below
  // a positive threshold.
  int NoDirection(const Sample& s) const
  {
    return s.FA < this->P.StopFA ? vtkTensorLineTracer::LOW_ANISOTROPY
                                 : vtkTensorLineTracer::STAGNATION;
  }

  // One direction from the seed; returns the reason for termination.
  int Half(const double seed[3], const Sample& s0, double sign, std::vector<PointRecord>& out,
    double& length)
  {
    out.clear();
    length = 0.0;
    const Params& P = this->P;
    Sample s = s0, stage, next;
    double x[3] = { seed[0], seed[1], seed[2] };
    double in[3] = { sign * s0.E[0][0], sign * s0.E[0][1], sign * s0.E[0][2] };
    // Stage i of a step: the direction at its sample (stage 0: at x),
    // turned like `ref` (see Direction()); 0 or why the line ends there.
    auto direction = [&](int i, const double xs[3], const double ref[3], double k[3]) -> int
    {
      if (i == 0)
      {
        return this->Direction(s, in, ref, k) ? 0 : vtkTensorLineTracer::STAGNATION;
      }
      const int reason = this->Evaluate(xs, stage);
      if (reason != 0)
      {
        return reason;
      }
      return this->Direction(stage, in, ref, k) ? 0 : NoDirection(stage);
    };
    for (vtkIdType step = 0;; ++step)
    {
      if (step >= P.MaxSteps)
      {
        return vtkTensorLineTracer::OUT_OF_STEPS;
      }
      double h = P.H;
      bool last = false;
      if (P.MaxLength > 0.0)
      {
        const double remaining = P.MaxLength - length;
        if (remaining <= 1e-12 * P.MaxLength)
        {
          return vtkTensorLineTracer::OUT_OF_LENGTH;
        }
        if (h >= remaining)
        {
          h = remaining;
          last = true;
        }
      }
      double xn[3];
      int r = RK::Step(P.Integrator, x, in, h, direction, xn);
      if (r != 0)
      {
        return r;
      }
      if ((r = this->Evaluate(xn, next)) != 0)
      {
        return r;
      }
      if (next.Mask < 0.5)
      {
        return vtkTensorLineTracer::OUT_OF_MASK;
      }
      if (next.FA < P.StopFA)
      {
        return vtkTensorLineTracer::LOW_ANISOTROPY;
      }
      if (!(next.L[0] > 0.0))
      {
        return vtkTensorLineTracer::STAGNATION;
      }
      double chord[3] = { xn[0] - x[0], xn[1] - x[1], xn[2] - x[2] };
      const double len = std::sqrt(chord[0] * chord[0] + chord[1] * chord[1] + chord[2] * chord[2]);
      if (!(len > 0.0))
      {
        return vtkTensorLineTracer::STAGNATION;
      }
      for (double& c : chord)
      {
        c /= len;
      }
      if (chord[0] * in[0] + chord[1] * in[1] + chord[2] * in[2] < P.CosMaxAngle || len < 0.5 * h)
      {
        // (a chord shorter than half the step: the direction turns by more
        // than about 120 degrees within the step)
        return vtkTensorLineTracer::HIGH_CURVATURE;
      }
      // accept
      s = next;
      std::copy(xn, xn + 3, x);
      length += len;
      std::copy(chord, chord + 3, in);
      PointRecord p;
      std::copy(xn, xn + 3, p.X);
      std::copy(next.T, next.T + 6, p.T);
      const double* e = next.E[0];
      // along the direction of travel (the backward half is turned at the join)
      const double o = (e[0] * chord[0] + e[1] * chord[1] + e[2] * chord[2]) < 0.0 ? -1.0 : 1.0;
      for (int d = 0; d < 3; ++d)
      {
        p.E[d] = o * e[d];
      }
      p.FA = next.FA;
      p.Arc = length;
      out.push_back(p);
      if (last)
      {
        return vtkTensorLineTracer::OUT_OF_LENGTH;
      }
    }
  }

  const Field& F;
  const Params& P;
  Probe Interp;
  std::vector<PointRecord> Forward, Backward;
};

//------------------------------------------------------------------------------
// Output arrays grown batch by batch (amortized: vtkDataArray::Resize at
// least doubles the capacity).
template <typename T>
struct Output
{
  using Array = vtkAOSDataArrayTemplate<T>;
  vtkNew<Array> Points, FA, Tensors, Direction, Arc, Length;
  vtkNew<vtkUnsignedCharArray> Colors;
  vtkNew<vtkIdTypeArray> Offsets, Connectivity;
  vtkNew<vtkIntArray> SeedIds, Reasons;
  vtkIdType NumberOfPoints = 0, NumberOfLines = 0;

  Output()
  {
    this->Points->SetNumberOfComponents(3);
    this->FA->SetName("FractionalAnisotropy");
    this->Tensors->SetName("Tensors");
    this->Tensors->SetNumberOfComponents(6);
    this->Direction->SetName("PrincipalDirection");
    this->Direction->SetNumberOfComponents(3);
    this->Colors->SetName("DirectionColors");
    this->Colors->SetNumberOfComponents(3);
    this->Arc->SetName("ArcLength");
    this->Length->SetName("Length");
    this->SeedIds->SetName("SeedIds");
    this->Reasons->SetName("ReasonForTermination");
    this->Reasons->SetNumberOfComponents(2);
    this->Offsets->InsertNextValue(0);
  }

  template <class A>
  static void Grow(A* a, vtkIdType tuples)
  {
    if (tuples * a->GetNumberOfComponents() > a->GetSize())
    {
      a->Resize(tuples);
    }
    a->SetNumberOfTuples(tuples);
  }

  // Appends the kept lines of a batch (seed ids firstSeed + i).
  void Append(const std::vector<Line>& lines, const std::vector<char>& keep, vtkIdType firstSeed)
  {
    const vtkIdType n = static_cast<vtkIdType>(lines.size());
    std::vector<vtkIdType> pointOffset(n + 1, 0), lineIndex(n, -1);
    vtkIdType lineCount = 0;
    for (vtkIdType i = 0; i < n; ++i)
    {
      pointOffset[i + 1] = pointOffset[i];
      if (keep[i])
      {
        pointOffset[i + 1] += static_cast<vtkIdType>(lines[i].Points.size());
        lineIndex[i] = lineCount++;
      }
    }
    const vtkIdType p0 = this->NumberOfPoints, c0 = this->NumberOfLines;
    const vtkIdType np = p0 + pointOffset[n], nc = c0 + lineCount;
    Grow(this->Points.GetPointer(), np);
    Grow(this->FA.GetPointer(), np);
    Grow(this->Tensors.GetPointer(), np);
    Grow(this->Direction.GetPointer(), np);
    Grow(this->Colors.GetPointer(), np);
    Grow(this->Arc.GetPointer(), np);
    Grow(this->Connectivity.GetPointer(), np);
    Grow(this->Length.GetPointer(), nc);
    Grow(this->SeedIds.GetPointer(), nc);
    Grow(this->Reasons.GetPointer(), nc);
    Grow(this->Offsets.GetPointer(), nc + 1);
    T* pts = this->Points->GetPointer(0);
    T* fa = this->FA->GetPointer(0);
    T* ten = this->Tensors->GetPointer(0);
    T* dir = this->Direction->GetPointer(0);
    T* arc = this->Arc->GetPointer(0);
    unsigned char* col = this->Colors->GetPointer(0);
    vtkIdType* conn = this->Connectivity->GetPointer(0);
    vtkIdType* offs = this->Offsets->GetPointer(0);
    T* len = this->Length->GetPointer(0);
    int* seeds = this->SeedIds->GetPointer(0);
    int* reasons = this->Reasons->GetPointer(0);
    vtkSMPTools::For(0, n, 16,
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType i = begin; i < end; ++i)
        {
          if (!keep[i])
          {
            continue;
          }
          const Line& l = lines[i];
          const vtkIdType c = c0 + lineIndex[i];
          vtkIdType p = p0 + pointOffset[i];
          offs[c + 1] = p0 + pointOffset[i + 1];
          len[c] = static_cast<T>(l.Length);
          seeds[c] = static_cast<int>(firstSeed + i);
          reasons[2 * c] = l.Reasons[0];
          reasons[2 * c + 1] = l.Reasons[1];
          for (const PointRecord& r : l.Points)
          {
            for (int d = 0; d < 3; ++d)
            {
              pts[3 * p + d] = static_cast<T>(r.X[d]);
              dir[3 * p + d] = static_cast<T>(r.E[d]);
              col[3 * p + d] =
                static_cast<unsigned char>(std::lround(std::min(1.0, std::abs(r.E[d])) * 255.0));
            }
            for (int d = 0; d < 6; ++d)
            {
              ten[6 * p + d] = static_cast<T>(r.T[d]);
            }
            fa[p] = static_cast<T>(r.FA);
            arc[p] = static_cast<T>(r.Arc);
            conn[p] = p;
            ++p;
          }
        }
      });
    this->NumberOfPoints = np;
    this->NumberOfLines = nc;
  }

  void Finish(vtkPolyData* output)
  {
    for (vtkDataArray* a : std::initializer_list<vtkDataArray*>{ this->Points, this->FA,
           this->Tensors, this->Direction, this->Colors, this->Arc, this->Connectivity,
           this->Length, this->SeedIds, this->Reasons, this->Offsets })
    {
      a->Squeeze();
    }
    vtkNew<vtkPoints> points;
    points->SetData(this->Points);
    vtkNew<vtkCellArray> cells;
    cells->SetData(this->Offsets, this->Connectivity);
    output->SetPoints(points);
    output->SetLines(cells);
    vtkPointData* pd = output->GetPointData();
    pd->AddArray(this->FA);
    pd->SetActiveScalars(this->FA->GetName());
    pd->AddArray(this->Tensors);
    pd->SetActiveTensors(this->Tensors->GetName());
    pd->AddArray(this->Direction);
    pd->SetActiveVectors(this->Direction->GetName());
    pd->AddArray(this->Colors);
    pd->AddArray(this->Arc);
    vtkCellData* cd = output->GetCellData();
    cd->AddArray(this->SeedIds);
    cd->AddArray(this->Reasons);
    cd->AddArray(this->Length);
  }
};

// The point tensors of every block in canonical order, flags for the
// non-finite (and, for the log-Euclidean interpolation, indefinite) ones, the
// mask values; counts the invalid and indefinite tensors and returns the
// largest eigenvalue over the definite ones.
double ReadPointTensors(Field& field, const std::vector<vtkDataSet*>& dataSets,
  const std::vector<vtkDataArray*>& tensorArrays, const std::vector<vtkDataArray*>& maskArrays,
  const std::vector<int>& layouts, vtkIdType& numInvalid, vtkIdType& numIndefinite)
{
  const bool useMask = field.HasMask;
  std::atomic<vtkIdType> invalid(0), indefinite(0);
  double globalMax = 0.0;
  vtkSMPThreadLocal<double> localMax(0.0);
  for (std::size_t b = 0; b < dataSets.size(); ++b)
  {
    Block& block = field.Blocks[b];
    vtkDataSet* ds = dataSets[b];
    const vtkIdType n = ds->GetNumberOfPoints();
    block.Data = ds;
    block.Tensors.resize(6 * n);
    block.Flags.assign(n, POINT_OK);
    if (useMask)
    {
      block.Mask.resize(n);
    }
    vtkDataArray* tensors = tensorArrays[b];
    vtkDataArray* mask = maskArrays[b];
    const int layout = layouts[b];
    const int policy = field.SignPolicy;
    const bool logEuclidean = field.LogEuclidean;
    vtkSMPTools::For(0, n,
      [&](vtkIdType begin, vtkIdType end)
      {
        double& lmax = localMax.Local();
        vtkIdType nInvalid = 0, nIndefinite = 0;
        for (vtkIdType i = begin; i < end; ++i)
        {
          double* t = block.Tensors.data() + 6 * i;
          if (mask)
          {
            block.Mask[i] = static_cast<float>(mask->GetComponent(i, 0));
          }
          if (!TM::ReadSymmetric(tensors, i, layout, t))
          {
            block.Flags[i] = POINT_NONFINITE;
            std::fill(t, t + 6, 0.0);
            ++nInvalid;
            continue;
          }
          if (!logEuclidean && PositiveDefinite(t))
          {
            continue; // nothing to count or flag (the common case: no eigen-decomposition)
          }
          double l[3], e[3][3], ls[3], es[3][3];
          TM::EigenDecomposition(t, l, e);
          std::copy(l, l + 3, ls);
          std::copy(&e[0][0], &e[0][0] + 9, &es[0][0]);
          const bool definite = TM::ApplySignPolicy(TM::SIGN_SKIP, ls, es);
          if (!definite)
          {
            ++nIndefinite;
          }
          if (policy == TM::SIGN_SKIP)
          {
            if (!definite)
            {
              block.Flags[i] = POINT_NEGATIVE; // only used by the log-Euclidean interpolation
              continue;
            }
            lmax = std::max(lmax, ls[0]);
          }
          else
          {
            TM::ApplySignPolicy(policy, l, e);
            lmax = std::max(lmax, l[0]);
          }
        }
        invalid += nInvalid;
        indefinite += nIndefinite;
      });
  }
  for (double m : localMax)
  {
    globalMax = std::max(globalMax, m);
  }
  numInvalid = invalid;
  numIndefinite = indefinite;
  return globalMax;
}

// The blocks' interpolation data: the tensors' logarithms (log-Euclidean;
// eigenvalues floored at 1e-6 of `globalMax`), image geometry or a cell
// locator.
bool PrepareBlocks(
  Field& field, const std::vector<vtkDataSet*>& dataSets, double globalMax, std::string* error)
{
  for (std::size_t b = 0; b < dataSets.size(); ++b)
  {
    Block& block = field.Blocks[b];
    vtkDataSet* ds = dataSets[b];
    if (!field.LogEuclidean)
    {
      // Linear interpolation: indefinite point tensors are fine, the
      // interpolated tensor decides.
      for (unsigned char& f : block.Flags)
      {
        if (f == POINT_NEGATIVE)
        {
          f = POINT_OK;
        }
      }
    }
    else
    {
      const double floor = globalMax > 0.0 ? 1e-6 * globalMax : 1e-300;
      const int policy = field.SignPolicy;
      vtkSMPTools::For(0, ds->GetNumberOfPoints(),
        [&](vtkIdType begin, vtkIdType end)
        {
          for (vtkIdType i = begin; i < end; ++i)
          {
            if (block.Flags[i] != POINT_OK)
            {
              continue;
            }
            double* t = block.Tensors.data() + 6 * i;
            double l[3], e[3][3];
            TM::EigenDecomposition(t, l, e);
            TM::ApplySignPolicy(policy, l, e);
            for (double& v : l)
            {
              v = std::log(std::max(v, floor));
            }
            TM::FromEigenSystem(l, e, t);
          }
        });
    }
    block.AnyFlag = std::any_of(
      block.Flags.begin(), block.Flags.end(), [](unsigned char f) { return f != POINT_OK; });
    if (auto* image = vtkImageData::SafeDownCast(ds))
    {
      block.IsImage = true;
      image->GetExtent(block.Extent);
      image->GetDimensions(block.Dims);
      vtkMatrix4x4* m = image->GetPhysicalToIndexMatrix();
      for (int r = 0; r < 3; ++r)
      {
        for (int c = 0; c < 4; ++c)
        {
          block.M[4 * r + c] = m->GetElement(r, c);
        }
      }
    }
    else
    {
      if (ds->GetNumberOfCells() == 0)
      {
        return vtkSplineVizError::Fail(error,
          std::string("the ") + ds->GetClassName() +
            " of the tensor field has points but no cells to interpolate in");
      }
      block.Locator = vtkSmartPointer<vtkStaticCellLocator>::New();
      block.Locator->SetDataSet(ds);
      block.Locator->BuildLocator();
      field.MaxCellSize = std::max(field.MaxCellSize, ds->GetMaxCellSize());
    }
  }
  return true;
}

// The smallest cell size of the blocks (images: the smallest spacing;
// other data sets: the edge of a cube of their mean cell volume), 1 if none.
double SmallestCellLength(const std::vector<vtkDataSet*>& dataSets)
{
  double cellLength = VTK_DOUBLE_MAX;
  for (vtkDataSet* ds : dataSets)
  {
    if (auto* image = vtkImageData::SafeDownCast(ds))
    {
      const double* spacing = image->GetSpacing();
      const int* dims = image->GetDimensions();
      for (int a = 0; a < 3; ++a)
      {
        if (dims[a] > 1 && std::abs(spacing[a]) > 0)
        {
          cellLength = std::min(cellLength, std::abs(spacing[a]));
        }
      }
    }
    else
    {
      double bounds[6];
      ds->GetBounds(bounds);
      double volume = 1.0;
      int dim = 0;
      for (int a = 0; a < 3; ++a)
      {
        const double e = bounds[2 * a + 1] - bounds[2 * a];
        if (e > 0)
        {
          volume *= e;
          ++dim;
        }
      }
      if (dim > 0)
      {
        cellLength = std::min(
          cellLength, std::pow(volume / std::max<vtkIdType>(1, ds->GetNumberOfCells()), 1.0 / dim));
      }
    }
  }
  return cellLength == VTK_DOUBLE_MAX ? 1.0 : cellLength;
}

// Every `stride`-th voxel (point) whose own tensor has FA >= `seedFA` and a
// positive major eigenvalue (and is inside the mask), in point order.
void CollectVoxelSeeds(Field& field, const std::vector<vtkDataSet*>& dataSets, int stride,
  double seedFA, std::vector<double>& seeds)
{
  const bool useMask = field.HasMask;
  for (std::size_t b = 0; b < dataSets.size(); ++b)
  {
    Block& block = field.Blocks[b];
    vtkDataSet* ds = dataSets[b];
    std::vector<vtkIdType> candidates;
    if (block.IsImage)
    {
      for (int k = 0; k < block.Dims[2]; k += stride)
      {
        for (int j = 0; j < block.Dims[1]; j += stride)
        {
          for (int i = 0; i < block.Dims[0]; i += stride)
          {
            candidates.push_back(i +
              static_cast<vtkIdType>(block.Dims[0]) *
                (j + static_cast<vtkIdType>(block.Dims[1]) * k));
          }
        }
      }
    }
    else
    {
      for (vtkIdType i = 0; i < ds->GetNumberOfPoints(); i += stride)
      {
        candidates.push_back(i);
      }
    }
    std::vector<char> ok(candidates.size(), 0);
    vtkSMPTools::For(0, static_cast<vtkIdType>(candidates.size()),
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType c = begin; c < end; ++c)
        {
          const vtkIdType id = candidates[c];
          if (block.Flags[id] != POINT_OK || (useMask && block.Mask[id] < 0.5f))
          {
            continue;
          }
          Sample s;
          if (Analyze(field, block.Tensors.data() + 6 * id, 1.0, s) && s.FA >= seedFA &&
            s.L[0] > 0.0)
          {
            ok[c] = 1;
          }
        }
      });
    for (std::size_t c = 0; c < candidates.size(); ++c)
    {
      if (ok[c])
      {
        double x[3];
        ds->GetPoint(candidates[c], x);
        seeds.insert(seeds.end(), x, x + 3);
      }
    }
  }
}

}

//------------------------------------------------------------------------------
vtkTensorLineTracer::vtkTensorLineTracer()
{
  this->SetNumberOfInputPorts(2);
  this->SetInputArrayToProcess(
    0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::TENSORS);
}

vtkTensorLineTracer::~vtkTensorLineTracer() = default;

//------------------------------------------------------------------------------
void vtkTensorLineTracer::SetMaskArrayName(const char* name)
{
  vtkSplineVizInputArrays::SetName(this, 1, 0, name);
}

const char* vtkTensorLineTracer::GetMaskArrayName()
{
  return vtkSplineVizInputArrays::GetName(this, 1);
}

//------------------------------------------------------------------------------
const char* vtkTensorLineTracer::GetReasonName(int reason)
{
  return vtkSplineVizTermination::Name(reason);
}

//------------------------------------------------------------------------------
void vtkTensorLineTracer::SetSourceConnection(vtkAlgorithmOutput* algOutput)
{
  this->SetInputConnection(1, algOutput);
}

void vtkTensorLineTracer::SetSourceData(vtkDataObject* source)
{
  this->SetInputData(1, source);
}

//------------------------------------------------------------------------------
int vtkTensorLineTracer::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == 0)
  {
    info->Remove(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE());
    info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataSet");
    info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkCompositeDataSet");
  }
  else
  {
    vtkSplineVizSeeds::FillPortInformation(info);
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkTensorLineTracer::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  outputVector->GetInformationObject(0)->Set(CAN_HANDLE_PIECE_REQUEST(), 1);
  return 1;
}

//------------------------------------------------------------------------------
int vtkTensorLineTracer::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  // The whole field in every piece; the pieces split the seeds.
  vtkSplineVizSeeds::RequestUpdateExtent(inputVector, outputVector);
  return 1;
}

//------------------------------------------------------------------------------
bool vtkTensorLineTracer::CollectTensorArrays(vtkDataObject* input,
  std::vector<vtkDataSet*>& dataSets, std::vector<vtkDataArray*>& tensorArrays,
  std::vector<vtkDataArray*>& maskArrays, std::vector<int>& layouts, bool& useMask)
{
  dataSets.clear();
  for (vtkDataSet* ds : vtkCompositeDataSet::GetDataSets(input))
  {
    if (ds->GetNumberOfPoints() > 0)
    {
      dataSets.push_back(ds);
    }
  }
  if (dataSets.empty())
  {
    vtkErrorMacro(<< "the input has no points: connect a vtkImageData (or any data set) with a "
                     "point tensor array to port 0");
    return false;
  }
  // The mask: input array 1, by name or attribute type. No selection or an
  // empty name: none. Any other name must be a point array of the input.
  vtkInformation* maskInfo = this->GetInputArrayInformation(1);
  std::string maskLabel; // for messages
  if (maskInfo->Has(vtkDataObject::FIELD_NAME()))
  {
    const char* maskName = maskInfo->Get(vtkDataObject::FIELD_NAME());
    maskLabel = maskName ? maskName : "";
    useMask = !maskLabel.empty();
  }
  else if (maskInfo->Has(vtkDataObject::FIELD_ATTRIBUTE_TYPE()))
  {
    maskLabel = std::string("active ") +
      vtkDataSetAttributes::GetAttributeTypeAsString(
        maskInfo->Get(vtkDataObject::FIELD_ATTRIBUTE_TYPE()));
    useMask = true;
  }
  else
  {
    useMask = false;
  }
  tensorArrays.assign(dataSets.size(), nullptr);
  maskArrays.assign(dataSets.size(), nullptr);
  layouts.assign(dataSets.size(), 0);
  for (std::size_t b = 0; b < dataSets.size(); ++b)
  {
    vtkDataSet* ds = dataSets[b];
    int association = vtkDataObject::FIELD_ASSOCIATION_POINTS;
    vtkDataArray* tensors = this->GetInputArrayToProcess(0, ds, association);
    if (!tensors)
    {
      vtkErrorMacro(<< "no tensor array in " << ds->GetClassName()
                    << ": select a point array with 6, 7 or 9 components "
                       "(SetInputArrayToProcess) or set active point tensors");
      return false;
    }
    if (association != vtkDataObject::FIELD_ASSOCIATION_POINTS ||
      tensors->GetNumberOfTuples() != ds->GetNumberOfPoints())
    {
      vtkErrorMacro(<< "the tensor array '" << (tensors->GetName() ? tensors->GetName() : "")
                    << "' must be point data (one tensor per point), for interpolation; "
                       "convert cell data with vtkCellDataToPointData");
      return false;
    }
    const int comps = tensors->GetNumberOfComponents();
    layouts[b] = TM::ResolveLayout(this->TensorLayout, comps);
    if (layouts[b] < 0)
    {
      vtkErrorMacro(<< "tensor array '" << (tensors->GetName() ? tensors->GetName() : "(unnamed)")
                    << "' has " << comps << " components, which does not fit the tensor layout '"
                    << TM::GetLayoutName(this->TensorLayout)
                    << "' (6-component layouts need 6, FULL_9 needs 9, TEEM_7 7)");
      return false;
    }
    tensorArrays[b] = tensors;
    if (useMask)
    {
      int maskAssociation = vtkDataObject::FIELD_ASSOCIATION_POINTS;
      vtkDataArray* mask = this->GetInputArrayToProcess(1, ds, maskAssociation);
      if (mask &&
        (maskAssociation != vtkDataObject::FIELD_ASSOCIATION_POINTS ||
          mask->GetNumberOfTuples() != ds->GetNumberOfPoints()))
      {
        mask = nullptr; // cell data: not a point array
      }
      if (!mask || mask->GetNumberOfComponents() != 1)
      {
        if (mask)
        {
          vtkErrorMacro(<< "the mask array '" << maskLabel << "' must have one component");
        }
        else
        {
          vtkErrorMacro(<< "the mask array '" << maskLabel << "' is not a point array of "
                        << ds->GetClassName()
                        << ": select a 1-component point array of the input as input array 1 "
                           "(SetInputArrayToProcess), or nothing for no mask");
        }
        return false;
      }
      maskArrays[b] = mask;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkTensorLineTracer::ReportTensorProblems()
{
  if (this->NumberOfInvalidTensors > 0)
  {
    vtkWarningMacro(<< this->NumberOfInvalidTensors
                    << " point tensors have NaN or infinite components; lines stop before "
                       "interpolating them (reason "
                    << UNEXPECTED_VALUE << ")");
  }
  if (this->NumberOfIndefiniteTensors > 0)
  {
    vtkWarningMacro(<< this->NumberOfIndefiniteTensors
                    << " point tensors have negative eigenvalues; "
                    << (this->NegativeEigenvalues == NEGATIVE_EIGENVALUES_STOP
                           ? "lines stop where the tensor is indefinite (reason 11)"
                           : "their absolute values are used"));
  }
}

//------------------------------------------------------------------------------
bool vtkTensorLineTracer::CollectSourceSeeds(
  vtkInformationVector* sourceVector, std::vector<double>& seeds)
{
  vtkDataObject* source = sourceVector->GetNumberOfInformationObjects() > 0
    ? vtkDataObject::GetData(sourceVector, 0)
    : nullptr;
  if (!source)
  {
    vtkErrorMacro(<< "no seeds: connect a data set whose points are the seeds to the source "
                     "port (port 1), or use SeedMode SEEDS_FROM_VOXELS");
    return false;
  }
  // Absurd seed counts (e.g. an implicit image of 10^9 points) are refused
  // before anything is allocated: per seed its coordinates, a line and at
  // least two points of output.
  const double seedCount = vtkSplineVizSeeds::Count(source);
  std::string sizeError;
  if (!vtkSplineVizProgress::CheckOutputSize(
        seedCount, 3 * 8.0 + sizeof(Line) + 2 * 100.0, "the tensor lines of all seeds", &sizeError))
  {
    vtkErrorMacro(<< sizeError);
    return false;
  }
  vtkSplineVizSeeds::Collect(source, seeds);
  return true;
}

//------------------------------------------------------------------------------
void vtkTensorLineTracer::GetSeedRange(
  vtkInformation* outInfo, vtkIdType total, vtkIdType& first, vtkIdType& last) const
{
  // Pieces split the voxel seeds (source seeds are split by the source's pieces).
  first = 0;
  last = total;
  if (this->SeedMode == SEEDS_FROM_VOXELS)
  {
    const int piece = outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER());
    const int pieces = outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES());
    if (pieces > 1 && piece >= 0 && piece < pieces)
    {
      first = total * piece / pieces;
      last = total * (piece + 1) / pieces;
    }
  }
}

//------------------------------------------------------------------------------
bool vtkTensorLineTracer::UseDoubleOutput(bool inputDouble) const
{
  bool outDouble = inputDouble;
  if (this->OutputPointsPrecision == SINGLE_PRECISION)
  {
    outDouble = false;
  }
  else if (this->OutputPointsPrecision == DOUBLE_PRECISION)
  {
    outDouble = true;
  }
  return outDouble;
}

//------------------------------------------------------------------------------
int vtkTensorLineTracer::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  vtkDataObject* input = vtkDataObject::GetData(inputVector[0], 0);
  this->NumberOfSeeds = this->NumberOfRejectedSeeds = this->NumberOfShortLines = 0;
  this->NumberOfEvaluations = this->NumberOfInvalidTensors = this->NumberOfIndefiniteTensors = 0;
  this->StepLength = 0.0;

  // Settings.
  if (!(this->IntegrationStep > 0.0) || !std::isfinite(this->IntegrationStep))
  {
    vtkErrorMacro(<< "IntegrationStep must be a positive number, not " << this->IntegrationStep);
    return 0;
  }

  // The field's data sets and their arrays.
  std::vector<vtkDataSet*> dataSets;
  std::vector<vtkDataArray*> tensorArrays;
  std::vector<vtkDataArray*> maskArrays;
  std::vector<int> layouts;
  bool useMask = false;
  if (!this->CollectTensorArrays(input, dataSets, tensorArrays, maskArrays, layouts, useMask))
  {
    return 0;
  }
  const bool dbl = std::any_of(tensorArrays.begin(), tensorArrays.end(),
    [](vtkDataArray* a) { return a->GetDataType() == VTK_DOUBLE; });
  Field field;
  field.LogEuclidean = this->Interpolation == LOG_EUCLIDEAN_INTERPOLATION;
  field.SignPolicy =
    this->NegativeEigenvalues == NEGATIVE_EIGENVALUES_ABSOLUTE ? TM::SIGN_ABSOLUTE : TM::SIGN_SKIP;
  field.HasMask = useMask;
  field.NeedLinearAnisotropy = this->UseTensorlines && this->TensorlineWeightFromLinearAnisotropy;
  field.Blocks.resize(dataSets.size());

  // Precompute the point tensors (canonical order; logarithms for the
  // log-Euclidean interpolation) and the locators.
  const double globalMax = ReadPointTensors(field, dataSets, tensorArrays, maskArrays, layouts,
    this->NumberOfInvalidTensors, this->NumberOfIndefiniteTensors);
  std::string error;
  if (!PrepareBlocks(field, dataSets, globalMax, &error))
  {
    vtkErrorMacro(<< error);
    return 0;
  }
  this->ReportTensorProblems();

  // The step in world units.
  const double cellLength = SmallestCellLength(dataSets);
  this->StepLength = this->IntegrationStepUnit == CELL_LENGTH_UNIT
    ? this->IntegrationStep * cellLength
    : this->IntegrationStep;

  // Seeds.
  std::vector<double> seeds;
  if (this->SeedMode == SEEDS_FROM_SOURCE)
  {
    if (!this->CollectSourceSeeds(inputVector[1], seeds))
    {
      return 0;
    }
  }
  else
  {
    // Every SeedStride-th voxel whose own tensor has FA >= SeedFAThreshold
    // (and is inside the mask), in point order.
    CollectVoxelSeeds(field, dataSets, this->SeedStride,
      std::max(this->SeedFAThreshold, this->StoppingFAThreshold), seeds);
  }
  const vtkIdType totalSeeds = static_cast<vtkIdType>(seeds.size() / 3);
  vtkIdType firstSeed = 0, lastSeed = totalSeeds;
  this->GetSeedRange(outInfo, totalSeeds, firstSeed, lastSeed);
  this->NumberOfSeeds = lastSeed - firstSeed;
  if (this->NumberOfSeeds == 0)
  {
    this->WarnNoSeeds(useMask);
  }
  const Params P = MakeParams(this);

  const bool outDouble = this->UseDoubleOutput(dbl);
  std::unique_ptr<Output<float>> outF;
  std::unique_ptr<Output<double>> outD;
  if (outDouble)
  {
    outD.reset(new Output<double>);
  }
  else
  {
    outF.reset(new Output<float>);
  }

  // Trace in batches: parallel over the seeds of a batch, appended in order;
  // between batches progress (the last 90 %) and abort, and a check that the
  // output still fits in this machine's memory.
  const vtkIdType batchSize =
    std::max<vtkIdType>(64, std::min<vtkIdType>(4096, (lastSeed - firstSeed + 49) / 50));
  const double memoryLimit = vtkSplineVizProgress::GetMemoryLimit();
  std::vector<Line> lines;
  std::vector<char> keep;
  vtkSMPThreadLocal<vtkIdType> evaluations(0);
  std::map<int, vtkIdType> rejected;
  for (vtkIdType b0 = firstSeed; b0 < lastSeed; b0 += batchSize)
  {
    const vtkIdType n = std::min(batchSize, lastSeed - b0);
    lines.resize(n);
    keep.assign(n, 0);
    vtkSMPTools::For(0, n, 8,
      [&](vtkIdType begin, vtkIdType end)
      {
        Tracker tracker(field, P);
        for (vtkIdType i = begin; i < end; ++i)
        {
          Line& line = lines[i];
          tracker.Trace(seeds.data() + 3 * (b0 + i), line);
          keep[i] =
            line.Rejected == 0 && line.Points.size() >= 2 && line.Length >= this->MinimumLength;
        }
        evaluations.Local() += tracker.GetEvaluations();
      });
    for (vtkIdType i = 0; i < n; ++i)
    {
      if (lines[i].Rejected != 0)
      {
        ++rejected[lines[i].Rejected];
      }
      else if (!keep[i])
      {
        ++this->NumberOfShortLines;
      }
    }
    if (outD)
    {
      outD->Append(lines, keep, b0);
    }
    else
    {
      outF->Append(lines, keep, b0);
    }
    this->UpdateProgress(0.1 +
      0.9 * static_cast<double>(b0 + n - firstSeed) / static_cast<double>(lastSeed - firstSeed));
    if (this->CheckAbort())
    {
      output->Initialize(); // aborted: a clean, empty output
      return 1;
    }
    const double outputBytes =
      static_cast<double>(outD ? outD->NumberOfPoints : outF->NumberOfPoints) * 100.0;
    if (outputBytes > 0.75 * memoryLimit)
    {
      vtkErrorMacro(<< "the tensor lines would need more than this machine's memory ("
                    << outputBytes << " bytes after " << (b0 + n - firstSeed) << " of "
                    << (lastSeed - firstSeed)
                    << " seeds): lower MaximumNumberOfSteps or the number of seeds");
      output->Initialize();
      return 0;
    }
  }
  for (vtkIdType e : evaluations)
  {
    this->NumberOfEvaluations += e;
  }
  this->ReportRejectedSeeds(rejected);
  if (outD)
  {
    outD->Finish(output);
  }
  else
  {
    outF->Finish(output);
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkTensorLineTracer::WarnNoSeeds(bool useMask)
{
  if (this->SeedMode == SEEDS_FROM_SOURCE)
  {
    vtkWarningMacro(<< "the seed source has no points: no lines");
  }
  else
  {
    vtkWarningMacro(<< "no voxel has FA >= "
                    << std::max(this->SeedFAThreshold, this->StoppingFAThreshold)
                    << (useMask ? " inside the mask" : "") << ": no seeds, no lines");
  }
}

//------------------------------------------------------------------------------
void vtkTensorLineTracer::ReportRejectedSeeds(const std::map<int, vtkIdType>& rejected)
{
  for (const auto& r : rejected)
  {
    this->NumberOfRejectedSeeds += r.second;
  }
  if (this->SeedMode == SEEDS_FROM_SOURCE && this->NumberOfRejectedSeeds > 0)
  {
    std::ostringstream why;
    for (const auto& r : rejected)
    {
      why << " " << r.second << " " << GetReasonName(r.first) << ";";
    }
    vtkWarningMacro(<< this->NumberOfRejectedSeeds << " of " << this->NumberOfSeeds
                    << " seeds gave no line:" << why.str());
  }
}

//------------------------------------------------------------------------------
void vtkTensorLineTracer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "TensorLayout: " << this->TensorLayout << " ("
     << TM::GetLayoutName(this->TensorLayout) << ")\n";
  const char* mask = vtkSplineVizInputArrays::GetName(this, 1);
  os << indent << "Mask (input array 1): " << (mask && *mask ? mask : "(none)") << "\n";
  os << indent << "SeedMode: " << this->SeedMode << "\n";
  os << indent << "SeedStride: " << this->SeedStride << "\n";
  os << indent << "SeedFAThreshold: " << this->SeedFAThreshold << "\n";
  os << indent << "IntegratorType: " << (this->IntegratorType == RUNGE_KUTTA2 ? "RK2" : "RK4")
     << "\n";
  os << indent << "IntegrationStep: " << this->IntegrationStep << "\n";
  os << indent << "IntegrationStepUnit: " << this->IntegrationStepUnit << "\n";
  os << indent << "Interpolation: " << this->Interpolation << "\n";
  os << indent << "NegativeEigenvalues: " << this->NegativeEigenvalues << "\n";
  os << indent << "UseTensorlines: " << this->UseTensorlines << "\n";
  os << indent
     << "TensorlineWeightFromLinearAnisotropy: " << this->TensorlineWeightFromLinearAnisotropy
     << "\n";
  os << indent << "TensorlineEigenvectorWeight: " << this->TensorlineEigenvectorWeight << "\n";
  os << indent << "TensorlineDeflectionWeight: " << this->TensorlineDeflectionWeight << "\n";
  os << indent << "StoppingFAThreshold: " << this->StoppingFAThreshold << "\n";
  os << indent << "MaximumAngle: " << this->MaximumAngle << "\n";
  os << indent << "MaximumPropagation: " << this->MaximumPropagation << "\n";
  os << indent << "MaximumNumberOfSteps: " << this->MaximumNumberOfSteps << "\n";
  os << indent << "MinimumLength: " << this->MinimumLength << "\n";
  os << indent << "OutputPointsPrecision: " << this->OutputPointsPrecision << "\n";
  os << indent << "NumberOfSeeds: " << this->NumberOfSeeds << "\n";
  os << indent << "NumberOfRejectedSeeds: " << this->NumberOfRejectedSeeds << "\n";
  os << indent << "NumberOfShortLines: " << this->NumberOfShortLines << "\n";
  os << indent << "NumberOfEvaluations: " << this->NumberOfEvaluations << "\n";
  os << indent << "StepLength: " << this->StepLength << "\n";
}
