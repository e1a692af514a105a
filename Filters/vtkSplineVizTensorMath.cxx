#include "vtkSplineVizTensorMath.h"

#include "vtkDataArray.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>

namespace
{
// The shared GLSL text compiled as C++ in double precision.
namespace shared
{
using namespace glm;
using real = double;
using vec3 = glm::dvec3;
#define SV_OUT(T) T&
#define SV_INOUT(T) T&
#include "glsl/vtkTensorMathShared.glsl"
#undef SV_OUT
#undef SV_INOUT
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
      return "6 components XX XY YY XZ YZ ZZ (DIPY, FSL)";
    case SYMMETRIC_UPPER:
      return "6 components XX XY XZ YY YZ ZZ (MFEM)";
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
