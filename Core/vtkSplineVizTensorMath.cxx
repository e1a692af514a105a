// SPDX-License-Identifier: BSD-3-Clause
#include "vtkSplineVizTensorMath.h"

#include "vtkDataArray.h"

#include "vtkSplineVizSharedGLSL.h"

#include <algorithm>
#include <cmath>

namespace
{
// The shared GLSL text compiled as C++ in double precision.
namespace shared
{
SV_SHARED_GLSL_TYPES(double);
#include "glsl/vtkSplineVizCommonShared.glsl"
#include "glsl/vtkTensorMathShared.glsl"
}

bool AllFinite(const double* c, int n)
{
  for (int i = 0; i < n; ++i)
  {
    if (!std::isfinite(c[i]))
    {
      return false;
    }
  }
  return true;
}
}

namespace vtkSplineVizTensorMath
{
//------------------------------------------------------------------------------
int GetNumberOfComponents(int layout)
{
  switch (layout)
  {
    case FULL_9:
      return 9;
    case SYMMETRIC_VTK:
    case SYMMETRIC_LOWER:
    case SYMMETRIC_UPPER:
      return 6;
    case TEEM_7:
      return 7;
    default:
      return 0;
  }
}

//------------------------------------------------------------------------------
const char* GetLayoutName(int layout)
{
  switch (layout)
  {
    case FULL_9:
      return "9 components (row-major 3x3, symmetrized)";
    case SYMMETRIC_VTK:
      return "6 components XX YY ZZ XY YZ XZ (VTK, ParaView)";
    case SYMMETRIC_LOWER:
      return "6 components XX XY YY XZ YZ ZZ (NIfTI, DIPY)";
    case SYMMETRIC_UPPER:
      return "6 components XX XY XZ YY YZ ZZ (FSL, MFEM)";
    case TEEM_7:
      return "7 components CONF XX XY XZ YY YZ ZZ (Teem, NRRD)";
    default:
      return "unknown";
  }
}

//------------------------------------------------------------------------------
int GuessLayout(int numberOfComponents)
{
  switch (numberOfComponents)
  {
    case 9:
      return FULL_9;
    case 6:
      return SYMMETRIC_VTK;
    case 7:
      return TEEM_7;
    default:
      return -1;
  }
}

//------------------------------------------------------------------------------
int ResolveLayout(int requestedLayout, int numberOfComponents)
{
  switch (numberOfComponents)
  {
    case 9:
      return FULL_9;
    case 7:
      return TEEM_7;
    case 6:
      if (requestedLayout == -1)
      {
        return SYMMETRIC_VTK;
      }
      if (requestedLayout == SYMMETRIC_VTK || requestedLayout == SYMMETRIC_LOWER ||
        requestedLayout == SYMMETRIC_UPPER)
      {
        return requestedLayout;
      }
      return -1;
    default:
      return -1;
  }
}

//------------------------------------------------------------------------------
bool ToSymmetric(int layout, const double* c, double t[6], double* confidence)
{
  const int n = GetNumberOfComponents(layout);
  if (n == 0 || !AllFinite(c, n))
  {
    return false;
  }
  if (confidence)
  {
    *confidence = 1.0;
  }
  // t = {xx, yy, zz, xy, yz, xz}
  switch (layout)
  {
    case FULL_9:
      t[0] = c[0];
      t[1] = c[4];
      t[2] = c[8];
      t[3] = 0.5 * (c[1] + c[3]);
      t[4] = 0.5 * (c[5] + c[7]);
      t[5] = 0.5 * (c[2] + c[6]);
      break;
    case SYMMETRIC_VTK:
      for (int i = 0; i < 6; ++i)
      {
        t[i] = c[i];
      }
      break;
    case SYMMETRIC_LOWER: // xx xy yy xz yz zz
      t[0] = c[0];
      t[1] = c[2];
      t[2] = c[5];
      t[3] = c[1];
      t[4] = c[4];
      t[5] = c[3];
      break;
    case SYMMETRIC_UPPER: // xx xy xz yy yz zz
      t[0] = c[0];
      t[1] = c[3];
      t[2] = c[5];
      t[3] = c[1];
      t[4] = c[4];
      t[5] = c[2];
      break;
    case TEEM_7: // conf xx xy xz yy yz zz
      if (confidence)
      {
        *confidence = c[0];
      }
      t[0] = c[1];
      t[1] = c[4];
      t[2] = c[6];
      t[3] = c[2];
      t[4] = c[5];
      t[5] = c[3];
      break;
    default:
      return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool ReadSymmetric(vtkDataArray* array, vtkIdType id, int layout, double t[6], double* confidence)
{
  double c[9];
  const int n = GetNumberOfComponents(layout);
  if (!array || n == 0 || array->GetNumberOfComponents() != n)
  {
    return false;
  }
  array->GetTuple(id, c);
  return ToSymmetric(layout, c, t, confidence);
}

//------------------------------------------------------------------------------
void ToMatrix(const double t[6], double m[3][3])
{
  m[0][0] = t[0];
  m[1][1] = t[1];
  m[2][2] = t[2];
  m[0][1] = m[1][0] = t[3];
  m[1][2] = m[2][1] = t[4];
  m[0][2] = m[2][0] = t[5];
}

//------------------------------------------------------------------------------
void Multiply(const double t[6], const double x[3], double y[3])
{
  const double y0 = t[0] * x[0] + t[3] * x[1] + t[5] * x[2];
  const double y1 = t[3] * x[0] + t[1] * x[1] + t[4] * x[2];
  const double y2 = t[5] * x[0] + t[4] * x[1] + t[2] * x[2];
  y[0] = y0;
  y[1] = y1;
  y[2] = y2;
}

//------------------------------------------------------------------------------
void EigenDecomposition(const double t[6], double values[3], double vectors[3][3])
{
  glm::dvec3 lambda, e1, e2, e3;
  shared::svtSymmetricEigen(
    glm::dvec3(t[0], t[1], t[2]), glm::dvec3(t[3], t[4], t[5]), lambda, e1, e2, e3);
  for (int i = 0; i < 3; ++i)
  {
    values[i] = lambda[i];
    vectors[0][i] = e1[i];
    vectors[1][i] = e2[i];
    vectors[2][i] = e3[i];
  }
}

//------------------------------------------------------------------------------
void PrincipalEigen(const double t[6], double values[3], double e1[3])
{
  // The first steps are those of svtSymmetricEigen (glsl/vtkTensorMathShared.glsl):
  // scaling, the traceless normalized C, the isolated eigenvalue's vector u.
  using glm::dvec3;
  e1[0] = 1.0;
  e1[1] = e1[2] = 0.0;
  dvec3 lambda, cd, co, u;
  double m, q, p;
  if (!shared::svtIsolatedEigenvector(
        dvec3(t[0], t[1], t[2]), dvec3(t[3], t[4], t[5]), lambda, m, q, p, cd, co, u))
  {
    values[0] = lambda[0];
    values[1] = lambda[1];
    values[2] = lambda[2];
    return;
  }
  // The 2x2 restriction to the plane orthogonal to u, in closed form.
  dvec3 v, w;
  double m00, m11, m01;
  shared::svtPlaneRestriction(cd, co, u, v, w, m00, m11, m01);
  const double mean = 0.5 * (m00 + m11), half = 0.5 * (m00 - m11);
  const double radius = std::sqrt(half * half + m01 * m01);
  const double la = mean + radius, lb = mean - radius;
  const double lu = glm::dot(u, shared::svtSymMul(cd, co, u));
  double l[3];
  dvec3 e;
  if (lu >= la)
  {
    l[0] = lu;
    l[1] = la;
    l[2] = lb;
    e = u;
  }
  else
  {
    // the larger eigenvector of [[m00, m01], [m01, m11]]: the better of
    // (m01, la - m00) and (la - m11, m01)
    const double a0 = m01, a1 = la - m00, c0 = la - m11, c1 = m01;
    double s0 = a0, s1 = a1;
    if (c0 * c0 + c1 * c1 > a0 * a0 + a1 * a1)
    {
      s0 = c0;
      s1 = c1;
    }
    const double ns = std::sqrt(s0 * s0 + s1 * s1);
    e = ns > 0.0 ? (s0 * v + s1 * w) / ns : v;
    l[0] = la;
    l[1] = std::max(lu, lb);
    l[2] = std::min(lu, lb);
  }
  for (int i = 0; i < 3; ++i)
  {
    values[i] = m * (q + p * l[i]);
    e1[i] = e[i];
  }
}

//------------------------------------------------------------------------------
double FractionalAnisotropy(const double values[3])
{
  return shared::svtFractionalAnisotropy(glm::dvec3(values[0], values[1], values[2]));
}

//------------------------------------------------------------------------------
double MeanDiffusivity(const double values[3])
{
  return shared::svtMeanDiffusivity(glm::dvec3(values[0], values[1], values[2]));
}

//------------------------------------------------------------------------------
void WestinMetrics(const double values[3], double& cl, double& cp, double& cs)
{
  const glm::dvec3 w = shared::svtWestinMetrics(glm::dvec3(values[0], values[1], values[2]));
  cl = w.x;
  cp = w.y;
  cs = w.z;
}

//------------------------------------------------------------------------------
bool ApplySignPolicy(int policy, double values[3], double vectors[3][3])
{
  glm::dvec3 l(values[0], values[1], values[2]);
  glm::dvec3 e1(vectors[0][0], vectors[0][1], vectors[0][2]);
  glm::dvec3 e2(vectors[1][0], vectors[1][1], vectors[1][2]);
  glm::dvec3 e3(vectors[2][0], vectors[2][1], vectors[2][2]);
  const bool show = shared::svtApplySignPolicy(policy, l, e1, e2, e3);
  for (int i = 0; i < 3; ++i)
  {
    values[i] = l[i];
    vectors[0][i] = e1[i];
    vectors[1][i] = e2[i];
    vectors[2][i] = e3[i];
  }
  return show;
}

//------------------------------------------------------------------------------
bool KindlmannShape(
  double cl, double cp, double gamma, double minimumRoundness, double& alpha, double& beta)
{
  return shared::svtKindlmannShape(cl, cp, gamma, minimumRoundness, alpha, beta);
}

//------------------------------------------------------------------------------
bool SchultzKindlmannSquare(const double values[3], bool traceNormalized, double uv[2])
{
  const glm::dvec3 s =
    shared::svtSchultzKindlmannSquare(glm::dvec3(values[0], values[1], values[2]), traceNormalized);
  const bool mirrored = s.z > 0.5; // folded: the point of -T
  uv[0] = mirrored ? 1.0 - s.x : s.x;
  uv[1] = mirrored ? 1.0 - s.y : s.y;
  return mirrored;
}

//------------------------------------------------------------------------------
bool SchultzKindlmannShape(
  const double values[3], double gamma, double minimumRoundness, double abc[3])
{
  glm::dvec3 r;
  const bool axisE1 = shared::svtSchultzKindlmannShape(
    glm::dvec3(values[0], values[1], values[2]), gamma, minimumRoundness, r);
  abc[0] = r.x;
  abc[1] = r.y;
  abc[2] = r.z;
  return axisE1;
}

//------------------------------------------------------------------------------
void FromEigenSystem(const double values[3], const double vectors[3][3], double t[6])
{
  for (int i = 0; i < 6; ++i)
  {
    t[i] = 0.0;
  }
  for (int k = 0; k < 3; ++k)
  {
    const double l = values[k];
    const double* e = vectors[k];
    t[0] += l * e[0] * e[0];
    t[1] += l * e[1] * e[1];
    t[2] += l * e[2] * e[2];
    t[3] += l * e[0] * e[1];
    t[4] += l * e[1] * e[2];
    t[5] += l * e[0] * e[2];
  }
}

//------------------------------------------------------------------------------
bool Log(const double t[6], double minimumEigenvalue, double logT[6])
{
  if (!AllFinite(t, 6) || !(minimumEigenvalue > 0.0) || !std::isfinite(minimumEigenvalue))
  {
    return false;
  }
  double values[3], vectors[3][3];
  EigenDecomposition(t, values, vectors);
  for (double& l : values)
  {
    l = std::log(std::max(l, minimumEigenvalue));
  }
  FromEigenSystem(values, vectors, logT);
  return true;
}

//------------------------------------------------------------------------------
void Exp(const double t[6], double expT[6], double values[3], double vectors[3][3])
{
  double l[3], e[3][3];
  EigenDecomposition(t, l, e);
  for (double& v : l)
  {
    v = std::exp(v);
  }
  FromEigenSystem(l, e, expT);
  if (values)
  {
    for (int i = 0; i < 3; ++i)
    {
      values[i] = l[i];
    }
  }
  if (vectors)
  {
    for (int i = 0; i < 3; ++i)
    {
      for (int j = 0; j < 3; ++j)
      {
        vectors[i][j] = e[i][j];
      }
    }
  }
}
}
