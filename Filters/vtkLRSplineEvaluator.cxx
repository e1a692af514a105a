#include "vtkLRSplineEvaluator.h"

#include "vtkSMPTools.h"

#include <algorithm>
#include <cmath>

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
  for (int d = 0; d < 3; ++d)
  {
    this->Scale[d] = scale[d];
    this->Offset[d] = offset[d];
  }
}

//------------------------------------------------------------------------------
int vtkLRSplineEvaluator::GetMaximumDegree() const
{
  return std::max(this->Volume.Degree[0], std::max(this->Volume.Degree[1], this->Volume.Degree[2]));
}

//------------------------------------------------------------------------------
void vtkLRSplineEvaluator::GetBounds(double bounds[6]) const
{
  const double* dom = this->Locator.GetDomain();
  for (int d = 0; d < 3; ++d)
  {
    bounds[2 * d] = this->Offset[d] + this->Scale[d] * dom[d];
    bounds[2 * d + 1] = this->Offset[d] + this->Scale[d] * dom[d + 3];
  }
}

//------------------------------------------------------------------------------
double vtkLRSplineEvaluator::GetElementMinimumSide(vtkIdType e) const
{
  const double* b = this->Volume.GetBox(e);
  double m = (b[3] - b[0]) * this->Scale[0];
  m = std::min(m, (b[4] - b[1]) * this->Scale[1]);
  m = std::min(m, (b[5] - b[2]) * this->Scale[2]);
  return m;
}

//------------------------------------------------------------------------------
void vtkLRSplineEvaluator::PhysicalToParameter(const double x[3], double u[3]) const
{
  for (int d = 0; d < 3; ++d)
  {
    u[d] = (x[d] - this->Offset[d]) / this->Scale[d];
  }
}

void vtkLRSplineEvaluator::ParameterToPhysical(const double u[3], double x[3]) const
{
  for (int d = 0; d < 3; ++d)
  {
    x[d] = this->Offset[d] + this->Scale[d] * u[d];
  }
}

//------------------------------------------------------------------------------
vtkIdType vtkLRSplineEvaluator::FindElement(const double x[3]) const
{
  double u[3];
  this->PhysicalToParameter(x, u);
  return this->Locator.FindElement(u);
}

bool vtkLRSplineEvaluator::ElementContains(vtkIdType e, const double x[3]) const
{
  double u[3];
  this->PhysicalToParameter(x, u);
  return this->Locator.Contains(e, u);
}

//------------------------------------------------------------------------------
void vtkLRSplineEvaluator::EvaluateInElement(
  vtkIdType e, const double x[3], double* value, double* gradient) const
{
  const double* b = this->Volume.GetBox(e);
  double s[3], inv[3];
  for (int d = 0; d < 3; ++d)
  {
    const double u = (x[d] - this->Offset[d]) / this->Scale[d];
    const double w = b[d + 3] - b[d];
    s[d] = std::min(1.0, std::max(0.0, (u - b[d]) / w));
    inv[d] = 1.0 / (w * this->Scale[d]);
  }
  this->Volume.EvaluateLocal(e, s, value, gradient);
  if (gradient)
  {
    const int nc = this->Volume.NumberOfComponents;
    for (int c = 0; c < nc; ++c)
    {
      for (int d = 0; d < 3; ++d)
      {
        gradient[3 * c + d] *= inv[d];
      }
    }
  }
}

void vtkLRSplineEvaluator::EvaluateInElement(
  vtkIdType e, const float x[3], float* value, float* gradient) const
{
  const double* b = this->Volume.GetBox(e);
  float s[3], inv[3];
  for (int d = 0; d < 3; ++d)
  {
    const float u =
      (x[d] - static_cast<float>(this->Offset[d])) / static_cast<float>(this->Scale[d]);
    const float lo = static_cast<float>(b[d]);
    const float w = static_cast<float>(b[d + 3] - b[d]);
    s[d] = std::min(1.0f, std::max(0.0f, (u - lo) / w));
    inv[d] = 1.0f / (w * static_cast<float>(this->Scale[d]));
  }
  this->Volume.EvaluateLocal(e, s, value, gradient);
  if (gradient)
  {
    const int nc = this->Volume.NumberOfComponents;
    for (int c = 0; c < nc; ++c)
    {
      for (int d = 0; d < 3; ++d)
      {
        gradient[3 * c + d] *= inv[d];
      }
    }
  }
}

//------------------------------------------------------------------------------
namespace
{
// Value and physical gradient at parameter u inside element e.
inline void AtParameter(const vtkLRSplineBezierVolume& volume, const double scale[3], vtkIdType e,
  const double u[3], double* value, double* gradient)
{
  const double* b = volume.GetBox(e);
  double s[3], w[3];
  for (int d = 0; d < 3; ++d)
  {
    w[d] = b[d + 3] - b[d];
    s[d] = std::min(1.0, std::max(0.0, (u[d] - b[d]) / w[d]));
  }
  volume.EvaluateLocal(e, s, value, gradient);
  if (gradient)
  {
    double inv[3];
    for (int d = 0; d < 3; ++d)
    {
      inv[d] = 1.0 / (w[d] * scale[d]);
    }
    const int nc = volume.NumberOfComponents;
    for (int c = 0; c < nc; ++c)
    {
      for (int d = 0; d < 3; ++d)
      {
        gradient[3 * c + d] *= inv[d];
      }
    }
  }
}
}

vtkIdType vtkLRSplineEvaluator::Evaluate(const double x[3], double* value, double* gradient) const
{
  double u[3];
  this->PhysicalToParameter(x, u);
  const vtkIdType e = this->Locator.FindElement(u);
  if (e >= 0)
  {
    AtParameter(this->Volume, this->Scale, e, u, value, gradient);
  }
  return e;
}

bool vtkLRSplineEvaluator::EvaluateIfInElement(
  vtkIdType e, const double x[3], double* value, double* gradient) const
{
  double u[3];
  this->PhysicalToParameter(x, u);
  if (!this->Locator.Contains(e, u))
  {
    return false;
  }
  AtParameter(this->Volume, this->Scale, e, u, value, gradient);
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
vtkIdType vtkLRSplineEvaluator::EvaluateParameter(
  const double u[3], double* value, double* gradient) const
{
  const vtkIdType e = this->Locator.FindElement(u);
  if (e < 0)
  {
    return e;
  }
  const double* b = this->Volume.GetBox(e);
  double s[3];
  for (int d = 0; d < 3; ++d)
  {
    s[d] = std::min(1.0, std::max(0.0, (u[d] - b[d]) / (b[d + 3] - b[d])));
  }
  this->Volume.EvaluateLocal(e, s, value, gradient);
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
