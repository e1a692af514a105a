// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLRSplineGeometryMap.h"
#include "vtkSplineVizError.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkLRSplineArrayNames.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cmath>
#include <limits>

using vtkSplineVizError::Fail;

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

// The Newton step of a map with parametric dimension pd: J d = r for a
// volume; for a surface (J's third column zero) the least-squares step
// (J^T J) d = J^T r, d[2] = 0 (Gauss-Newton: the foot of the closest point).
bool SolveStep(const double J[9], const double r[3], double d[3], int pd)
{
  if (pd == 3)
  {
    return Solve3(J, r, d);
  }
  double G[3] = { 0, 0, 0 }, b[2] = { 0, 0 }; // G00, G01, G11
  for (int i = 0; i < 3; ++i)
  {
    G[0] += J[3 * i] * J[3 * i];
    G[1] += J[3 * i] * J[3 * i + 1];
    G[2] += J[3 * i + 1] * J[3 * i + 1];
    b[0] += J[3 * i] * r[i];
    b[1] += J[3 * i + 1] * r[i];
  }
  const double det = G[0] * G[2] - G[1] * G[1];
  if (!std::isfinite(det) || !(det > 1e-14 * G[0] * G[2]))
  {
    return false;
  }
  d[0] = (G[2] * b[0] - G[1] * b[1]) / det;
  d[1] = (G[0] * b[1] - G[1] * b[0]) / det;
  d[2] = 0.0;
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
  if (!grid || !grid->GetPoints() || grid->GetNumberOfCells() < 1)
  {
    return Fail(error, "the geometry grid has no cells");
  }
  // The control points (homogeneous where rational) as a point-data array,
  // so that the Bezier blocks come out in the field's element order.
  vtkDataArray* weights = grid->GetPointData()->GetRationalWeights();
  if (!weights)
  {
    weights = grid->GetPointData()->GetArray(vtkLRSplineArrayNames::RationalWeights);
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
      return Fail(error,
        "control point " + std::to_string(i) +
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
    return Fail(error, msg);
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
    return Fail(error, "the geometry is a single point");
  }
  this->Size.resize(ne);
  const bool surface = this->Volume.ParametricDimension == 2;
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
    if (surface)
    {
      // A surface's box holds the points within the distance tolerance of it.
      for (int d = 0; d < 3; ++d)
      {
        b[d] -= this->SurfaceTolerance * this->Size[e];
        b[d + 3] += this->SurfaceTolerance * this->Size[e];
      }
    }
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
    return Fail(error, "the physical element search: " + msg);
  }
  this->Affine = false;
  if (!surface)
  {
    this->DetectAffine();
  }
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
  vtkIdType e, const double x[3], double s[3], int* iterations, bool* far) const
{
  const double size = this->Size[e];
  const int pd = this->Volume.ParametricDimension;
  // A volume's residual must vanish; a surface's is the distance to it.
  const double accept = (pd == 2 ? std::max(1e-9, this->SurfaceTolerance) : 1e-9) * size;
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
    if (!SolveStep(J, r, d, pd))
    {
      return false;
    }
    const double dmax = std::max(std::abs(d[0]), std::max(std::abs(d[1]), std::abs(d[2])));
    // The decrease of |x(s) - x|^2 the step promises, |J d|^2: all of it for a
    // volume (J d = r), its tangential part for a surface, whose residual at
    // the foot is the distance (Armijo's rule on that, not on |r|^2).
    double promised = f;
    if (pd == 2)
    {
      double Jd[3];
      for (int i = 0; i < 3; ++i)
      {
        Jd[i] = J[3 * i] * d[0] + J[3 * i + 1] * d[1];
      }
      promised = Norm2(Jd);
    }
    // Backtracking line search on |x(s) - x|^2 (the full step when the
    // residual is already at rounding level or the step below the
    // convergence tolerance: a surface's residual at its foot is not zero).
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
      const bool armijo =
        pd == 3 ? fn <= f * (1.0 - 1e-4 * lambda) : fn <= f - 1e-4 * lambda * promised;
      // (A surface's small steps are taken whole: near the foot |r|^2 is the
      // squared distance, whose rounding hides the decrease of a tiny step.)
      if (armijo || f <= 1e-30 * size * size || lambda * dmax <= ConvergenceTolerance ||
        (pd == 2 && dmax <= 1e-4))
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
      if (far)
      {
        *far = !(f <= accept * accept);
      }
      return f <= accept * accept;
    }
  }
  return false;
}

//------------------------------------------------------------------------------
bool vtkLRSplineGeometryMap::InvertInElement(
  vtkIdType e, const double x[3], double s[3], const double* seed, int* iterations) const
{
  const int pd = this->Volume.ParametricDimension;
  auto inside = [&]()
  {
    for (int d = 0; d < pd; ++d)
    {
      if (!(s[d] >= -InsideTolerance && s[d] <= 1.0 + InsideTolerance))
      {
        return false;
      }
    }
    for (int d = 0; d < 3; ++d)
    {
      s[d] = d < pd ? std::min(1.0, std::max(0.0, s[d])) : 0.0;
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
  // (A surface's w is 0: its map does not depend on it.)
  const double w0 = pd == 2 ? 0.0 : 0.5;
  const double centre[3] = { 0.5, 0.5, w0 };
  double xc[3], J[9], r[3], d[3];
  this->Map(e, centre, xc, J);
  for (int i = 0; i < 3; ++i)
  {
    r[i] = x[i] - xc[i];
  }
  // A surface's foot is unique near the element: a converged solution
  // farther than the tolerance is final (no restarts).
  bool far = false;
  bool* farFlag = pd == 2 ? &far : nullptr;
  if (SolveStep(J, r, d, pd))
  {
    for (int i = 0; i < 3; ++i)
    {
      s[i] = std::min(1.25, std::max(-0.25, centre[i] + d[i]));
    }
    if (this->Newton(e, x, s, iterations, farFlag))
    {
      return inside();
    }
    if (far)
    {
      return false;
    }
  }
  // Fallbacks: the centre and the corners (8 of a volume, 4 of a surface).
  const int corners = pd == 2 ? 4 : 8;
  for (int c = 0; c <= corners; ++c)
  {
    for (int i = 0; i < 3; ++i)
    {
      s[i] = i >= pd ? 0.0 : (c == corners ? 0.5 : ((c >> i) & 1 ? 0.9 : 0.1));
    }
    if (this->Newton(e, x, s, iterations, farFlag))
    {
      return inside();
    }
    if (far)
    {
      return false;
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
  const int pd = this->Volume.ParametricDimension;
  for (int d = 0; d < pd; ++d)
  {
    const double w0 = pd == 2 ? 0.0 : 0.5;
    double a[3] = { 0.5, 0.5, w0 }, b[3] = { 0.5, 0.5, w0 }, xa[3], xb[3];
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

//------------------------------------------------------------------------------
bool vtkLRSplineGeometryMap::InverseJacobian(vtkIdType e, const double s[3], double inv[9]) const
{
  double x[3], J[9];
  this->Map(e, s, x, J);
  if (this->Volume.ParametricDimension == 3)
  {
    const double c0 = J[4] * J[8] - J[5] * J[7], c1 = J[5] * J[6] - J[3] * J[8],
                 c2 = J[3] * J[7] - J[4] * J[6];
    const double det = J[0] * c0 + J[1] * c1 + J[2] * c2;
    const double m[9] = { c0 / det, (J[2] * J[7] - J[1] * J[8]) / det,
      (J[1] * J[5] - J[2] * J[4]) / det, c1 / det, (J[0] * J[8] - J[2] * J[6]) / det,
      (J[2] * J[3] - J[0] * J[5]) / det, c2 / det, (J[1] * J[6] - J[0] * J[7]) / det,
      (J[0] * J[4] - J[1] * J[3]) / det };
    std::copy(m, m + 9, inv);
    return std::isfinite(det) && det != 0.0;
  }
  // A surface: the pseudo-inverse (J^T J)^-1 J^T of the 3x2 Jacobian, so
  // that gradients are the surface (tangential) gradients.
  double G00 = 0, G01 = 0, G11 = 0;
  for (int i = 0; i < 3; ++i)
  {
    G00 += J[3 * i] * J[3 * i];
    G01 += J[3 * i] * J[3 * i + 1];
    G11 += J[3 * i + 1] * J[3 * i + 1];
  }
  const double det = G00 * G11 - G01 * G01;
  for (int i = 0; i < 3; ++i)
  {
    inv[i] = (G11 * J[3 * i] - G01 * J[3 * i + 1]) / det;
    inv[3 + i] = (G00 * J[3 * i + 1] - G01 * J[3 * i]) / det;
    inv[6 + i] = 0.0;
  }
  return std::isfinite(det) && det > 0.0;
}

//------------------------------------------------------------------------------
void vtkLRSplineGeometryMap::SurfaceFrame(
  vtkIdType e, const double s[3], double x[3], double normal[3]) const
{
  double J[9];
  this->Map(e, s, x, J);
  const double n[3] = { J[3] * J[7] - J[6] * J[4], J[6] * J[1] - J[0] * J[7],
    J[0] * J[4] - J[3] * J[1] };
  const double len = std::sqrt(Norm2(n));
  for (int i = 0; i < 3; ++i)
  {
    normal[i] = len > 0 ? n[i] / len : 0.0;
  }
}
