#include "vtkLRSplineGeometryMap.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace
{
// Solve J d = r (3x3, row-major) by Cramer's rule; false when J is singular
// relative to its size.
bool Solve3(const double J[9], const double r[3], double d[3])
{
  const double c0 = J[4] * J[8] - J[5] * J[7];
  const double c1 = J[5] * J[6] - J[3] * J[8];
  const double c2 = J[3] * J[7] - J[4] * J[6];
  const double det = J[0] * c0 + J[1] * c1 + J[2] * c2;
  double norm = 0.0;
  for (int i = 0; i < 9; ++i)
  {
    norm = std::max(norm, std::abs(J[i]));
  }
  if (!std::isfinite(det) || !(std::abs(det) > 1e-14 * norm * norm * norm))
  {
    return false;
  }
  const double inv[9] = { c0, J[2] * J[7] - J[1] * J[8], J[1] * J[5] - J[2] * J[4], c1,
    J[0] * J[8] - J[2] * J[6], J[2] * J[3] - J[0] * J[5], c2, J[1] * J[6] - J[0] * J[7],
    J[0] * J[4] - J[1] * J[3] };
  for (int i = 0; i < 3; ++i)
  {
    d[i] = (inv[3 * i] * r[0] + inv[3 * i + 1] * r[1] + inv[3 * i + 2] * r[2]) / det;
  }
  return true;
}

double Norm2(const double r[3])
{
  return r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
}

int AutomaticBlocks(vtkIdType n)
{
  const double b = 2.0 * std::cbrt(static_cast<double>(n));
  return std::max(1, std::min(64, static_cast<int>(std::ceil(b))));
}
}

//------------------------------------------------------------------------------
bool vtkLRSplineGeometryMap::Build(
  vtkUnstructuredGrid* grid, const int blocks[3], std::string* error)
{
  auto fail = [error](const std::string& msg)
  {
    if (error)
    {
      *error = msg;
    }
    return false;
  };
  if (!grid || !grid->GetPoints() || grid->GetNumberOfCells() < 1)
  {
    return fail("the geometry grid has no cells");
  }
  // The control points (homogeneous where rational) as a point-data array,
  // so that the Bezier blocks come out in the field's element order.
  vtkDataArray* weights = grid->GetPointData()->GetRationalWeights();
  if (!weights)
  {
    weights = grid->GetPointData()->GetArray("RationalWeights");
  }
  this->Rational = weights != nullptr;
  const int nc = this->Rational ? 4 : 3;
  const vtkIdType np = grid->GetNumberOfPoints();
  vtkNew<vtkDoubleArray> coords;
  coords->SetName("vtkLRSplineGeometryMap coordinates");
  coords->SetNumberOfComponents(nc);
  coords->SetNumberOfTuples(np);
  for (vtkIdType i = 0; i < np; ++i)
  {
    double x[3];
    grid->GetPoint(i, x);
    const double w = this->Rational ? weights->GetComponent(i, 0) : 1.0;
    if (!(w > 0) || !std::isfinite(w) || !std::isfinite(x[0] + x[1] + x[2]))
    {
      return fail("control point " + std::to_string(i) +
        " has a non-finite coordinate or a weight that is not positive");
    }
    for (int d = 0; d < 3; ++d)
    {
      coords->SetComponent(i, d, w * x[d]);
    }
    if (this->Rational)
    {
      coords->SetComponent(i, 3, w);
    }
  }
  vtkNew<vtkUnstructuredGrid> copy;
  copy->ShallowCopy(grid);
  vtkNew<vtkPointData> pd;
  pd->ShallowCopy(grid->GetPointData());
  pd->AddArray(coords);
  copy->GetPointData()->ShallowCopy(pd);
  std::string msg;
  if (!this->Volume.FromUnstructuredGrid(copy, coords->GetName(), &msg))
  {
    return fail(msg);
  }
  // Physical boxes of the control points, padded by a rounding tolerance.
  const vtkIdType ne = this->Volume.GetNumberOfElements();
  const int per = this->Volume.GetCoefficientsPerElement();
  std::vector<double> boxes(6 * static_cast<std::size_t>(ne));
  double all[6] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX,
    -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
  for (vtkIdType e = 0; e < ne; ++e)
  {
    double* b = boxes.data() + 6 * e;
    std::fill(b, b + 3, VTK_DOUBLE_MAX);
    std::fill(b + 3, b + 6, -VTK_DOUBLE_MAX);
    const double* c = this->Volume.GetElementCoefficients(e);
    for (int k = 0; k < per; ++k)
    {
      const double w = this->Rational ? c[nc * k + 3] : 1.0;
      for (int d = 0; d < 3; ++d)
      {
        const double x = c[nc * k + d] / w;
        b[d] = std::min(b[d], x);
        b[d + 3] = std::max(b[d + 3], x);
      }
    }
    for (int d = 0; d < 3; ++d)
    {
      all[d] = std::min(all[d], b[d]);
      all[d + 3] = std::max(all[d + 3], b[d + 3]);
    }
  }
  const double diagonal = std::sqrt((all[3] - all[0]) * (all[3] - all[0]) +
    (all[4] - all[1]) * (all[4] - all[1]) + (all[5] - all[2]) * (all[5] - all[2]));
  if (!(diagonal > 0))
  {
    return fail("the geometry is a single point");
  }
  this->Size.resize(ne);
  for (vtkIdType e = 0; e < ne; ++e)
  {
    double* b = boxes.data() + 6 * e;
    double s2 = 0.0;
    for (int d = 0; d < 3; ++d)
    {
      // Flat boxes (a planar face) get a thickness, all a rounding margin.
      const double pad = 1e-9 * diagonal;
      b[d] -= pad;
      b[d + 3] += pad;
      s2 += (b[d + 3] - b[d]) * (b[d + 3] - b[d]);
    }
    this->Size[e] = std::sqrt(s2);
  }
  int autoBlocks[3];
  if (!blocks || blocks[0] < 1)
  {
    autoBlocks[0] = autoBlocks[1] = autoBlocks[2] = AutomaticBlocks(ne);
    blocks = autoBlocks;
  }
  this->Locator.SetAllowOverlap(true);
  if (!this->Locator.Build(boxes.data(), ne, vtkLRSplineElementLocator::KD_FOREST, blocks, &msg))
  {
    return fail("the physical element search: " + msg);
  }
  this->DetectAffine();
  return true;
}

//------------------------------------------------------------------------------
void vtkLRSplineGeometryMap::GetBounds(double bounds[6]) const
{
  const double* dom = this->Locator.GetDomain();
  for (int d = 0; d < 3; ++d)
  {
    bounds[2 * d] = dom[d];
    bounds[2 * d + 1] = dom[d + 3];
  }
}

void vtkLRSplineGeometryMap::GetAffineMap(double A[9], double b[3]) const
{
  std::copy(this->AffineA, this->AffineA + 9, A);
  std::copy(this->AffineB, this->AffineB + 3, b);
}

//------------------------------------------------------------------------------
void vtkLRSplineGeometryMap::DetectAffine()
{
  this->Affine = false;
  const int nc = this->Volume.NumberOfComponents;
  const int* deg = this->Volume.Degree;
  // The candidate from element 0's corners.
  const double* box = this->Volume.GetBox(0);
  double x0[3], A[9], b[3];
  const double s0[3] = { 0, 0, 0 };
  this->Map(0, s0, x0, nullptr);
  for (int j = 0; j < 3; ++j)
  {
    double s[3] = { 0, 0, 0 }, x[3];
    s[j] = 1.0;
    this->Map(0, s, x, nullptr);
    for (int i = 0; i < 3; ++i)
    {
      A[3 * i + j] = (x[i] - x0[i]) / (box[j + 3] - box[j]);
    }
  }
  for (int i = 0; i < 3; ++i)
  {
    b[i] = x0[i] - A[3 * i] * box[0] - A[3 * i + 1] * box[1] - A[3 * i + 2] * box[2];
  }
  double bounds[6];
  this->GetBounds(bounds);
  const double tol =
    1e-12 * std::max(bounds[1] - bounds[0], std::max(bounds[3] - bounds[2], bounds[5] - bounds[4]));
  const double w0 = this->Rational ? this->Volume.GetElementCoefficients(0)[3] : 1.0;
  const vtkIdType ne = this->Volume.GetNumberOfElements();
  for (vtkIdType e = 0; e < ne; ++e)
  {
    const double* bx = this->Volume.GetBox(e);
    const double* c = this->Volume.GetElementCoefficients(e);
    for (int k = 0; k <= deg[2]; ++k)
    {
      for (int j = 0; j <= deg[1]; ++j)
      {
        for (int i = 0; i <= deg[0]; ++i)
        {
          const double* cf = c + ((k * (deg[1] + 1) + j) * (deg[0] + 1) + i) * nc;
          const double w = this->Rational ? cf[3] : 1.0;
          if (std::abs(w - w0) > 1e-12 * w0)
          {
            return;
          }
          // The Bezier points of the identity map are equally spaced.
          const double u[3] = { bx[0] + (bx[3] - bx[0]) * i / deg[0],
            bx[1] + (bx[4] - bx[1]) * j / deg[1], bx[2] + (bx[5] - bx[2]) * k / deg[2] };
          for (int d = 0; d < 3; ++d)
          {
            const double x = b[d] + A[3 * d] * u[0] + A[3 * d + 1] * u[1] + A[3 * d + 2] * u[2];
            if (!(std::abs(cf[d] / w - x) <= tol))
            {
              return;
            }
          }
        }
      }
    }
  }
  std::copy(A, A + 9, this->AffineA);
  std::copy(b, b + 3, this->AffineB);
  this->Affine = true;
}

//------------------------------------------------------------------------------
void vtkLRSplineGeometryMap::Map(vtkIdType e, const double s[3], double x[3], double J[9]) const
{
  double value[4], dlocal[12];
  this->Volume.EvaluateLocal(e, s, value, J ? dlocal : nullptr);
  if (!this->Rational)
  {
    std::copy(value, value + 3, x);
    if (J)
    {
      std::copy(dlocal, dlocal + 9, J);
    }
    return;
  }
  const double w = value[3];
  for (int i = 0; i < 3; ++i)
  {
    x[i] = value[i] / w;
  }
  if (J)
  {
    // x = X / W: dx/ds = (dX/ds - x dW/ds) / W.
    for (int i = 0; i < 3; ++i)
    {
      for (int j = 0; j < 3; ++j)
      {
        J[3 * i + j] = (dlocal[3 * i + j] - x[i] * dlocal[9 + j]) / w;
      }
    }
  }
}

//------------------------------------------------------------------------------
bool vtkLRSplineGeometryMap::Newton(
  vtkIdType e, const double x[3], double s[3], int* iterations) const
{
  const double size = this->Size[e];
  const double accept = 1e-9 * size;
  double xs[3], J[9], r[3];
  this->Map(e, s, xs, J);
  for (int i = 0; i < 3; ++i)
  {
    r[i] = xs[i] - x[i];
  }
  double f = Norm2(r);
  for (int it = 0; it < 60; ++it)
  {
    if (iterations)
    {
      ++*iterations;
    }
    double d[3];
    if (!Solve3(J, r, d))
    {
      return false;
    }
    // Backtracking line search on |x(s) - x|^2 (the full step when the
    // residual is already at rounding level).
    double lambda = 1.0, sn[3], xn[3], Jn[9], rn[3], fn = 0.0;
    for (int ls = 0; ls < 40; ++ls)
    {
      for (int i = 0; i < 3; ++i)
      {
        sn[i] = std::min(3.0, std::max(-2.0, s[i] - lambda * d[i]));
      }
      this->Map(e, sn, xn, Jn);
      for (int i = 0; i < 3; ++i)
      {
        rn[i] = xn[i] - x[i];
      }
      fn = Norm2(rn);
      if (fn <= f * (1.0 - 1e-4 * lambda) || f <= 1e-30 * size * size)
      {
        break;
      }
      lambda *= 0.5;
    }
    const double step =
      std::max(std::abs(sn[0] - s[0]), std::max(std::abs(sn[1] - s[1]), std::abs(sn[2] - s[2])));
    std::copy(sn, sn + 3, s);
    std::copy(Jn, Jn + 9, J);
    std::copy(rn, rn + 3, r);
    f = fn;
    if (!std::isfinite(f))
    {
      return false;
    }
    if (step <= ConvergenceTolerance)
    {
      return f <= accept * accept;
    }
  }
  return false;
}

//------------------------------------------------------------------------------
bool vtkLRSplineGeometryMap::InvertInElement(
  vtkIdType e, const double x[3], double s[3], const double* seed, int* iterations) const
{
  auto inside = [&]()
  {
    for (int d = 0; d < 3; ++d)
    {
      if (!(s[d] >= -InsideTolerance && s[d] <= 1.0 + InsideTolerance))
      {
        return false;
      }
    }
    for (int d = 0; d < 3; ++d)
    {
      s[d] = std::min(1.0, std::max(0.0, s[d]));
    }
    return true;
  };
  if (iterations)
  {
    *iterations = 0;
  }
  if (seed)
  {
    std::copy(seed, seed + 3, s);
    if (this->Newton(e, x, s, iterations))
    {
      return inside();
    }
  }
  // The element's linear approximation: its tangent map at the centre.
  const double centre[3] = { 0.5, 0.5, 0.5 };
  double xc[3], J[9], r[3], d[3];
  this->Map(e, centre, xc, J);
  for (int i = 0; i < 3; ++i)
  {
    r[i] = x[i] - xc[i];
  }
  if (Solve3(J, r, d))
  {
    for (int i = 0; i < 3; ++i)
    {
      s[i] = std::min(1.25, std::max(-0.25, 0.5 + d[i]));
    }
    if (this->Newton(e, x, s, iterations))
    {
      return inside();
    }
  }
  // Fallbacks: the centre and the corners.
  for (int c = 0; c < 9; ++c)
  {
    for (int i = 0; i < 3; ++i)
    {
      s[i] = c == 8 ? 0.5 : ((c >> i) & 1 ? 0.9 : 0.1);
    }
    if (this->Newton(e, x, s, iterations))
    {
      return inside();
    }
  }
  return false;
}

//------------------------------------------------------------------------------
vtkIdType vtkLRSplineGeometryMap::Invert(const double x[3], double s[3], vtkIdType hint) const
{
  if (hint >= 0 && hint < this->GetNumberOfElements() && this->Locator.Contains(hint, x) &&
    this->InvertInElement(hint, x, s))
  {
    return hint;
  }
  thread_local std::vector<vtkIdType> candidates;
  this->Locator.FindCandidates(x, candidates);
  for (vtkIdType e : candidates)
  {
    if (e != hint && this->InvertInElement(e, x, s))
    {
      return e;
    }
  }
  return -1;
}

//------------------------------------------------------------------------------
void vtkLRSplineGeometryMap::LocalToParameter(vtkIdType e, const double s[3], double u[3]) const
{
  const double* b = this->Volume.GetBox(e);
  for (int d = 0; d < 3; ++d)
  {
    u[d] = b[d] + s[d] * (b[d + 3] - b[d]);
  }
}

//------------------------------------------------------------------------------
double vtkLRSplineGeometryMap::GetElementMinimumSide(vtkIdType e) const
{
  double m = VTK_DOUBLE_MAX;
  for (int d = 0; d < 3; ++d)
  {
    double a[3] = { 0.5, 0.5, 0.5 }, b[3] = { 0.5, 0.5, 0.5 }, xa[3], xb[3];
    a[d] = 0.0;
    b[d] = 1.0;
    this->Map(e, a, xa, nullptr);
    this->Map(e, b, xb, nullptr);
    m = std::min(m,
      std::sqrt((xb[0] - xa[0]) * (xb[0] - xa[0]) + (xb[1] - xa[1]) * (xb[1] - xa[1]) +
        (xb[2] - xa[2]) * (xb[2] - xa[2])));
  }
  return m;
}

//------------------------------------------------------------------------------
void vtkLRSplineGeometryMap::Weight(vtkIdType e, const double s[3], double& W, double dW[3]) const
{
  if (!this->Rational)
  {
    W = 1.0;
    dW[0] = dW[1] = dW[2] = 0.0;
    return;
  }
  double value[4], dlocal[12];
  this->Volume.EvaluateLocal(e, s, value, dlocal);
  W = value[3];
  for (int j = 0; j < 3; ++j)
  {
    dW[j] = dlocal[9 + j];
  }
}
