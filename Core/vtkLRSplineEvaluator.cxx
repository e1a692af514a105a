// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLRSplineEvaluator.h"

#include "vtkLRSplineGeometryMap.h"

#include "vtkSMPTools.h"
#include "vtkType.h"

#include <algorithm>
#include <cmath>
#include <limits>

//------------------------------------------------------------------------------
bool vtkLRSplineEvaluator::Initialize(
  vtkLRSplineBezierVolume&& volume, int locatorType, const int blocks[3], std::string* error)
{
  this->Volume = std::move(volume);
  if (this->Volume.GetNumberOfElements() < 1)
  {
    if (error)
    {
      *error = "the spline has no elements";
    }
    return false;
  }
  return this->Locator.Build(
    this->Volume.Boxes.data(), this->Volume.GetNumberOfElements(), locatorType, blocks, error);
}

//------------------------------------------------------------------------------
void vtkLRSplineEvaluator::SetPhysicalTransform(const double scale[3], const double offset[3])
{
  for (int i = 0; i < 9; ++i)
  {
    this->Matrix[i] = this->Inverse[i] = 0.0;
  }
  for (int d = 0; d < 3; ++d)
  {
    this->Matrix[4 * d] = scale[d];
    this->Inverse[4 * d] = 1.0 / scale[d];
    this->Offset[d] = offset[d];
  }
  this->AxisAligned = true;
}

//------------------------------------------------------------------------------
bool vtkLRSplineEvaluator::SetPhysicalAffine(const double A[9], const double offset[3])
{
  const double det = A[0] * (A[4] * A[8] - A[5] * A[7]) - A[1] * (A[3] * A[8] - A[5] * A[6]) +
    A[2] * (A[3] * A[7] - A[4] * A[6]);
  double norm = 0.0;
  for (int i = 0; i < 9; ++i)
  {
    norm = std::max(norm, std::abs(A[i]));
  }
  if (!std::isfinite(det) || !(std::abs(det) > 1e-12 * norm * norm * norm) ||
    !std::isfinite(offset[0] + offset[1] + offset[2]))
  {
    return false;
  }
  const double inv[9] = { (A[4] * A[8] - A[5] * A[7]) / det, (A[2] * A[7] - A[1] * A[8]) / det,
    (A[1] * A[5] - A[2] * A[4]) / det, (A[5] * A[6] - A[3] * A[8]) / det,
    (A[0] * A[8] - A[2] * A[6]) / det, (A[2] * A[3] - A[0] * A[5]) / det,
    (A[3] * A[7] - A[4] * A[6]) / det, (A[1] * A[6] - A[0] * A[7]) / det,
    (A[0] * A[4] - A[1] * A[3]) / det };
  std::copy(A, A + 9, this->Matrix);
  std::copy(inv, inv + 9, this->Inverse);
  std::copy(offset, offset + 3, this->Offset);
  this->AxisAligned = A[1] == 0 && A[2] == 0 && A[3] == 0 && A[5] == 0 && A[6] == 0 && A[7] == 0;
  return true;
}

//------------------------------------------------------------------------------
int vtkLRSplineEvaluator::GetMaximumDegree() const
{
  return std::max(this->Volume.Degree[0], std::max(this->Volume.Degree[1], this->Volume.Degree[2]));
}

//------------------------------------------------------------------------------
bool vtkLRSplineEvaluator::SetGeometry(std::shared_ptr<const vtkLRSplineGeometryMap> geometry)
{
  if (geometry && geometry->IsRational())
  {
    // A field on a rational basis is sum B w f / sum B w: keep w f.
    const vtkLRSplineBezierVolume& g = geometry->GetVolume();
    const int nc = this->Volume.NumberOfComponents;
    const std::size_t n = this->Volume.Coefficients.size() / nc;
    if (g.GetNumberOfElements() != this->Volume.GetNumberOfElements() ||
      g.Degree[0] != this->Volume.Degree[0] || g.Degree[1] != this->Volume.Degree[1] ||
      g.Degree[2] != this->Volume.Degree[2] || g.Coefficients.size() != 4 * n)
    {
      return false;
    }
    for (std::size_t k = 0; k < n; ++k)
    {
      for (int c = 0; c < nc; ++c)
      {
        this->Volume.Coefficients[k * nc + c] *= g.Coefficients[4 * k + 3];
      }
    }
    if (!this->Volume.CoefficientsFloat.empty())
    {
      this->Volume.MakeFloatCoefficients();
    }
  }
  else if (geometry && geometry->GetNumberOfElements() != this->Volume.GetNumberOfElements())
  {
    return false;
  }
  this->Geometry = std::move(geometry);
  return true;
}

//------------------------------------------------------------------------------
void vtkLRSplineEvaluator::GetBounds(double bounds[6]) const
{
  if (this->Geometry)
  {
    this->Geometry->GetBounds(bounds);
    return;
  }
  const double* dom = this->Locator.GetDomain();
  for (int d = 0; d < 3; ++d)
  {
    bounds[2 * d] = VTK_DOUBLE_MAX;
    bounds[2 * d + 1] = -VTK_DOUBLE_MAX;
  }
  for (int c = 0; c < 8; ++c)
  {
    const double u[3] = { dom[(c & 1) ? 3 : 0], dom[(c & 2) ? 4 : 1], dom[(c & 4) ? 5 : 2] };
    double x[3];
    this->ParameterToPhysical(u, x);
    for (int d = 0; d < 3; ++d)
    {
      bounds[2 * d] = std::min(bounds[2 * d], x[d]);
      bounds[2 * d + 1] = std::max(bounds[2 * d + 1], x[d]);
    }
  }
}

//------------------------------------------------------------------------------
double vtkLRSplineEvaluator::GetElementMinimumSide(vtkIdType e) const
{
  if (this->Geometry)
  {
    return this->Geometry->GetElementMinimumSide(e);
  }
  const double* b = this->Volume.GetBox(e);
  double m = VTK_DOUBLE_MAX;
  for (int d = 0; d < 3; ++d)
  {
    // The length of the element's edge along parameter direction d.
    const double* A = this->Matrix;
    const double column = std::sqrt(A[d] * A[d] + A[3 + d] * A[3 + d] + A[6 + d] * A[6 + d]);
    m = std::min(m, (b[d + 3] - b[d]) * column);
  }
  return m;
}

//------------------------------------------------------------------------------
void vtkLRSplineEvaluator::PhysicalToParameter(const double x[3], double u[3]) const
{
  if (this->Geometry)
  {
    double s[3];
    const vtkIdType e = this->Geometry->Invert(x, s);
    if (e < 0)
    {
      u[0] = u[1] = u[2] = std::numeric_limits<double>::quiet_NaN();
      return;
    }
    this->Geometry->LocalToParameter(e, s, u);
    return;
  }
  const double y[3] = { x[0] - this->Offset[0], x[1] - this->Offset[1], x[2] - this->Offset[2] };
  const double* M = this->Inverse;
  if (this->AxisAligned)
  {
    // (x - offset) / scale, as before the affine maps (bit for bit).
    for (int d = 0; d < 3; ++d)
    {
      u[d] = y[d] / this->Matrix[4 * d];
    }
    return;
  }
  for (int d = 0; d < 3; ++d)
  {
    u[d] = M[3 * d] * y[0] + M[3 * d + 1] * y[1] + M[3 * d + 2] * y[2];
  }
}

void vtkLRSplineEvaluator::ParameterToPhysical(const double u[3], double x[3]) const
{
  const double* A = this->Matrix;
  for (int d = 0; d < 3; ++d)
  {
    x[d] = this->Offset[d] + A[3 * d] * u[0] + A[3 * d + 1] * u[1] + A[3 * d + 2] * u[2];
  }
}

//------------------------------------------------------------------------------
template <typename Real>
void vtkLRSplineEvaluator::GradientToPhysical(Real* gradient, const double* b) const
{
  // d f / d x_j = sum_d (d f / d s_d) / w_d * Inverse[d][j].
  const int nc = this->Volume.NumberOfComponents;
  for (int c = 0; c < nc; ++c)
  {
    Real* g = gradient + 3 * c;
    Real gu[3];
    for (int d = 0; d < 3; ++d)
    {
      gu[d] = g[d] / static_cast<Real>(b[d + 3] - b[d]);
    }
    if (this->AxisAligned)
    {
      for (int d = 0; d < 3; ++d)
      {
        g[d] = gu[d] / static_cast<Real>(this->Matrix[4 * d]);
      }
      continue;
    }
    const double* M = this->Inverse;
    for (int j = 0; j < 3; ++j)
    {
      g[j] = static_cast<Real>(M[j]) * gu[0] + static_cast<Real>(M[3 + j]) * gu[1] +
        static_cast<Real>(M[6 + j]) * gu[2];
    }
  }
}

//------------------------------------------------------------------------------
template <typename Real>
void vtkLRSplineEvaluator::AtLocal(
  vtkIdType e, const double s[3], Real* value, Real* gradient) const
{
  const Real sr[3] = { static_cast<Real>(s[0]), static_cast<Real>(s[1]), static_cast<Real>(s[2]) };
  this->Volume.EvaluateLocal(e, sr, value, gradient);
  double W = 1.0, dW[3] = { 0, 0, 0 };
  if (this->Geometry->IsRational())
  {
    // The field's coefficients are homogeneous (w f): f = F / W and
    // d f / d s = (d F / d s - f d W / d s) / W.
    this->Geometry->Weight(e, s, W, dW);
    const int nc = this->Volume.NumberOfComponents;
    for (int c = 0; c < nc; ++c)
    {
      value[c] = static_cast<Real>(value[c] / W);
      if (gradient)
      {
        for (int j = 0; j < 3; ++j)
        {
          gradient[3 * c + j] = static_cast<Real>((gradient[3 * c + j] - value[c] * dW[j]) / W);
        }
      }
    }
  }
  if (!gradient)
  {
    return;
  }
  // d f / d x = (d f / d s) (d s / d x): the inverse Jacobian (volume) or
  // its pseudo-inverse (surface: the tangential gradient).
  double inv[9];
  this->Geometry->InverseJacobian(e, s, inv);
  for (int c = 0; c < this->Volume.NumberOfComponents; ++c)
  {
    Real* g = gradient + 3 * c;
    const double gs[3] = { g[0], g[1], g[2] };
    for (int j = 0; j < 3; ++j)
    {
      g[j] = static_cast<Real>(gs[0] * inv[j] + gs[1] * inv[3 + j] + gs[2] * inv[6 + j]);
    }
  }
}

//------------------------------------------------------------------------------
vtkIdType vtkLRSplineEvaluator::FindElement(const double x[3]) const
{
  if (this->Geometry)
  {
    double s[3];
    return this->Geometry->Invert(x, s);
  }
  double u[3];
  this->PhysicalToParameter(x, u);
  return this->Locator.FindElement(u);
}

bool vtkLRSplineEvaluator::ElementContains(vtkIdType e, const double x[3]) const
{
  if (this->Geometry)
  {
    double s[3];
    return this->Geometry->GetLocator().Contains(e, x) && this->Geometry->InvertInElement(e, x, s);
  }
  double u[3];
  this->PhysicalToParameter(x, u);
  return this->Locator.Contains(e, u);
}

//------------------------------------------------------------------------------
void vtkLRSplineEvaluator::EvaluateInElement(
  vtkIdType e, const double x[3], double* value, double* gradient) const
{
  if (this->Geometry)
  {
    double s[3];
    this->Geometry->InvertInElement(e, x, s); // known inside: s is clamped
    this->AtLocal(e, s, value, gradient);
    return;
  }
  double u[3];
  this->PhysicalToParameter(x, u);
  this->AtParameter(e, u, value, gradient);
}

void vtkLRSplineEvaluator::EvaluateInElement(
  vtkIdType e, const float x[3], float* value, float* gradient) const
{
  if (this->Geometry)
  {
    const double xd[3] = { x[0], x[1], x[2] };
    double s[3];
    this->Geometry->InvertInElement(e, xd, s);
    this->AtLocal(e, s, value, gradient);
    return;
  }
  const double* b = this->Volume.GetBox(e);
  float u[3], s[3];
  const float y[3] = { x[0] - static_cast<float>(this->Offset[0]),
    x[1] - static_cast<float>(this->Offset[1]), x[2] - static_cast<float>(this->Offset[2]) };
  for (int d = 0; d < 3; ++d)
  {
    if (this->AxisAligned)
    {
      u[d] = y[d] / static_cast<float>(this->Matrix[4 * d]);
    }
    else
    {
      const double* M = this->Inverse + 3 * d;
      u[d] = static_cast<float>(M[0]) * y[0] + static_cast<float>(M[1]) * y[1] +
        static_cast<float>(M[2]) * y[2];
    }
  }
  for (int d = 0; d < 3; ++d)
  {
    const float lo = static_cast<float>(b[d]);
    const float w = static_cast<float>(b[d + 3] - b[d]);
    s[d] = std::min(1.0f, std::max(0.0f, (u[d] - lo) / w));
  }
  this->Volume.EvaluateLocal(e, s, value, gradient);
  if (gradient)
  {
    this->GradientToPhysical(gradient, b);
  }
}

vtkIdType vtkLRSplineEvaluator::Evaluate(const double x[3], double* value, double* gradient) const
{
  if (this->Geometry)
  {
    double s[3];
    const vtkIdType e = this->Geometry->Invert(x, s);
    if (e >= 0)
    {
      this->AtLocal(e, s, value, gradient);
    }
    return e;
  }
  double u[3];
  this->PhysicalToParameter(x, u);
  const vtkIdType e = this->Locator.FindElement(u);
  if (e >= 0)
  {
    this->AtParameter(e, u, value, gradient);
  }
  return e;
}

bool vtkLRSplineEvaluator::EvaluateIfInElement(
  vtkIdType e, const double x[3], double* value, double* gradient) const
{
  if (this->Geometry)
  {
    double s[3];
    if (!this->Geometry->GetLocator().Contains(e, x) || !this->Geometry->InvertInElement(e, x, s))
    {
      return false;
    }
    this->AtLocal(e, s, value, gradient);
    return true;
  }
  double u[3];
  this->PhysicalToParameter(x, u);
  if (!this->Locator.Contains(e, u))
  {
    return false;
  }
  this->AtParameter(e, u, value, gradient);
  return true;
}

vtkIdType vtkLRSplineEvaluator::Evaluate(const float x[3], float* value, float* gradient) const
{
  const double xd[3] = { x[0], x[1], x[2] };
  const vtkIdType e = this->FindElement(xd);
  if (e >= 0)
  {
    this->EvaluateInElement(e, x, value, gradient);
  }
  return e;
}

//------------------------------------------------------------------------------
namespace
{
// Value and local derivatives of element e of `volume` at parameter point u
// (clamped to the element's box); returns the box.
const double* EvaluateInBox(const vtkLRSplineBezierVolume& volume, vtkIdType e, const double u[3],
  double* value, double* dlocal)
{
  const double* b = volume.GetBox(e);
  double s[3];
  for (int d = 0; d < 3; ++d)
  {
    s[d] = std::min(1.0, std::max(0.0, (u[d] - b[d]) / (b[d + 3] - b[d])));
  }
  volume.EvaluateLocal(e, s, value, dlocal);
  return b;
}
}

void vtkLRSplineEvaluator::AtParameter(
  vtkIdType e, const double u[3], double* value, double* gradient) const
{
  const double* b = EvaluateInBox(this->Volume, e, u, value, gradient);
  if (gradient)
  {
    this->GradientToPhysical(gradient, b);
  }
}

//------------------------------------------------------------------------------
vtkIdType vtkLRSplineEvaluator::EvaluateParameter(
  const double u[3], double* value, double* gradient) const
{
  const vtkIdType e = this->Locator.FindElement(u);
  if (e < 0)
  {
    return e;
  }
  const double* b = EvaluateInBox(this->Volume, e, u, value, gradient);
  if (gradient)
  {
    for (int c = 0; c < this->Volume.NumberOfComponents; ++c)
    {
      for (int d = 0; d < 3; ++d)
      {
        gradient[3 * c + d] /= (b[d + 3] - b[d]);
      }
    }
  }
  return e;
}

//------------------------------------------------------------------------------
void vtkLRSplineEvaluator::EvaluateBatch(
  const double* points, vtkIdType n, double* values, double* gradients, vtkIdType* elements) const
{
  const int nc = this->Volume.NumberOfComponents;
  vtkSMPTools::For(0, n,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        double* v = values + i * nc;
        double* g = gradients ? gradients + 3 * i * nc : nullptr;
        const vtkIdType e = this->Evaluate(points + 3 * i, v, g);
        if (e < 0)
        {
          std::fill(v, v + nc, 0.0);
          if (g)
          {
            std::fill(g, g + 3 * nc, 0.0);
          }
        }
        if (elements)
        {
          elements[i] = e;
        }
      }
    });
}

//------------------------------------------------------------------------------
bool vtkLRSplineEvaluator::ProjectOntoSurface(
  vtkIdType e, const double x[3], double point[3], double normal[3]) const
{
  double s[3];
  if (!this->Geometry || this->Geometry->GetParametricDimension() != 2 ||
    !this->Geometry->InvertInElement(e, x, s))
  {
    return false;
  }
  this->Geometry->SurfaceFrame(e, s, point, normal);
  return true;
}
