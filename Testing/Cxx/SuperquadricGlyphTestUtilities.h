// SPDX-License-Identifier: BSD-3-Clause
// Helpers of the superquadric glyph tests: hand-made tensors with known
// eigen-systems, and an INDEPENDENT CPU reference of the glyphs: eigenvectors
// from vtkMath::Jacobi, Kindlmann's rule and the scale rule written out here
// from the papers and Teem's documented rule (not the SplineViz code),
// polygonal superquadrics from vtkSuperquadricSource, placed, rotated and
// scaled by the eigen-system and drawn by a standard vtkPolyDataMapper.
#ifndef SuperquadricGlyphTestUtilities_h
#define SuperquadricGlyphTestUtilities_h

#include "vtkActor.h"
#include "vtkAppendPolyData.h"
#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkSmartPointer.h"
#include "vtkSuperquadricSource.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace sqtest
{
/// An actor drawing `mapper` white and unlit (coverage comparisons).
inline vtkSmartPointer<vtkActor> UnlitWhiteActor(vtkMapper* mapper)
{
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(1, 1, 1);
  actor->GetProperty()->LightingOff();
  return actor;
}

struct HandTensor
{
  double L[3];     // eigenvalues (any order, any sign)
  double Euler[3]; // rotation of the eigenvectors, degrees (x, y, z)
  const char* What;
};

/// The hand-made tensors: linear, planar, spherical, cl == cp, nearly
/// repeated eigenvalues, mixed signs, an axis-aligned one, a thin plate.
inline std::vector<HandTensor> HandTensors()
{
  return {
    { { 1.0, 0.25, 0.2 }, { 10, 30, 50 }, "linear" },
    { { 1.0, 0.9, 0.15 }, { 60, -20, 10 }, "planar" },
    { { 1.0, 0.95, 0.9 }, { 15, 45, -30 }, "nearly spherical" },
    { { 1.0, 0.6, 0.4 }, { -35, 25, 70 }, "cl == cp" },
    { { 1.0, 1.0 - 1e-6, 0.3 }, { 40, 10, -60 }, "repeated largest" },
    { { 1.0, 0.3, 0.3 - 1e-7 }, { -20, 70, 15 }, "repeated smallest" },
    { { 1.0, -0.5, 0.3 }, { 25, -40, 35 }, "mixed signs" },
    { { 1.0, 0.5, 0.1 }, { 0, 0, 0 }, "axis aligned" },
    { { 0.8, 0.75, 0.02 }, { 70, 20, -10 }, "thin plate" },
    { { 1.0, 0.1, 0.05 }, { -60, -30, 20 }, "needle" },
    { { -1.0, -0.35, -0.2 }, { 30, 60, 90 }, "negative definite" },
    { { 1.0, 0.55, 0.3 }, { -75, 5, 40 }, "general" },
  };
}

/// Rotation matrix (columns = rotated axes) from Euler angles in degrees.
inline void Rotation(const double euler[3], double r[3][3])
{
  vtkNew<vtkTransform> t;
  t->RotateX(euler[0]);
  t->RotateY(euler[1]);
  t->RotateZ(euler[2]);
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      r[i][j] = t->GetMatrix()->GetElement(i, j);
    }
  }
}

/// VTK-order 6-component tensor R diag(L) R^T.
inline std::array<double, 6> Compose(const HandTensor& h)
{
  double r[3][3];
  Rotation(h.Euler, r);
  double m[3][3] = {};
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      for (int k = 0; k < 3; ++k)
      {
        m[i][j] += r[i][k] * h.L[k] * r[j][k];
      }
    }
  }
  return { m[0][0], m[1][1], m[2][2], m[0][1], m[1][2], m[0][2] };
}

/// An image (columns x rows, spacing 1) with the tensors as active point
/// tensors ("T", VTK order), in row-major order.
inline vtkSmartPointer<vtkImageData> TensorImage(
  const std::vector<std::array<double, 6>>& tensors, int columns)
{
  const int rows = static_cast<int>((tensors.size() + columns - 1) / columns);
  auto img = vtkSmartPointer<vtkImageData>::New();
  img->SetDimensions(columns, rows, 1);
  vtkNew<vtkDoubleArray> t;
  t->SetName("T");
  t->SetNumberOfComponents(6);
  t->SetNumberOfTuples(static_cast<vtkIdType>(columns) * rows);
  for (vtkIdType i = 0; i < t->GetNumberOfTuples(); ++i)
  {
    const std::array<double, 6> zero = { 0, 0, 0, 0, 0, 0 };
    t->SetTuple(i, i < static_cast<vtkIdType>(tensors.size()) ? tensors[i].data() : zero.data());
  }
  img->GetPointData()->SetTensors(t);
  return img;
}

/// Deliberate mistakes the reference comparison must detect.
enum Mutation
{
  NONE = 0,
  WRONG_AXIS_SWITCH = 1,      // symmetry axis rule inverted (z for linear, x for planar)
  SWAPPED_ALPHA_BETA = 2,     // alpha and beta exchanged
  WRONG_EIGENVECTOR_ORDER = 3 // the largest semi-axis along e3, the smallest along e1
};

struct ReferenceSettings
{
  double Gamma = 3.0;
  double ScaleFactor = 1.0;
  double MinimumRoundness = 0.2;
  double MinimumThickness = 0.05;
  bool AbsoluteValues = true; // else negative eigenvalues are skipped
  int Resolution = 256;
  Mutation Mutate = NONE;
};

/// The polygonal reference glyph of tensor t (VTK order) at center c, or
/// nullptr when the tensor is not drawn.
inline vtkSmartPointer<vtkPolyData> ReferenceGlyph(
  const double t[6], const double c[3], const ReferenceSettings& s)
{
  // Eigen-system by vtkMath::Jacobi (values descending, vectors in columns).
  double a0[3] = { t[0], t[3], t[5] }, a1[3] = { t[3], t[1], t[4] }, a2[3] = { t[5], t[4], t[2] };
  double v0[3], v1[3], v2[3], w[3];
  double* a[3] = { a0, a1, a2 };
  double* v[3] = { v0, v1, v2 };
  vtkMath::Jacobi(a, w, v);
  double l[3];
  double e[3][3];
  int order[3] = { 0, 1, 2 };
  if (s.AbsoluteValues)
  {
    std::sort(order, order + 3, [&](int i, int j) { return std::abs(w[i]) > std::abs(w[j]); });
  }
  for (int k = 0; k < 3; ++k)
  {
    l[k] = s.AbsoluteValues ? std::abs(w[order[k]]) : w[order[k]];
    for (int c2 = 0; c2 < 3; ++c2)
    {
      e[k][c2] = v[c2][order[k]];
    }
  }
  const double big = std::max(std::abs(l[0]), std::abs(l[2]));
  if (!(big > 0.0) || l[2] < -1e-5 * big)
  {
    return nullptr;
  }
  for (double& lk : l)
  {
    lk = std::max(lk, 0.0);
  }
  // Westin metrics normalized by the trace, Kindlmann's exponents.
  const double S = l[0] + l[1] + l[2];
  const double cl = (l[0] - l[1]) / S;
  const double cp = 2.0 * (l[1] - l[2]) / S;
  bool linear = cl > cp;
  double alpha = linear ? std::pow(1.0 - cp, s.Gamma) : std::pow(1.0 - cl, s.Gamma);
  double beta = linear ? std::pow(1.0 - cl, s.Gamma) : std::pow(1.0 - cp, s.Gamma);
  alpha = std::min(1.0, std::max(s.MinimumRoundness, alpha));
  beta = std::min(1.0, std::max(s.MinimumRoundness, beta));
  if (s.Mutate == WRONG_AXIS_SWITCH)
  {
    linear = !linear;
  }
  if (s.Mutate == SWAPPED_ALPHA_BETA)
  {
    std::swap(alpha, beta);
  }
  // Semi-axes: scale * eigenvalue, at least MinimumThickness of the largest.
  double semi[3];
  for (int k = 0; k < 3; ++k)
  {
    semi[k] = std::max(s.ScaleFactor * l[k], s.MinimumThickness * s.ScaleFactor * l[0]);
  }
  if (s.Mutate == WRONG_EIGENVECTOR_ORDER)
  {
    std::swap(semi[0], semi[2]);
  }
  // Canonical (u, v, w) with w the symmetry axis: x = e1 when linear, else z = e3.
  int axes[3] = { 0, 1, 2 };
  if (linear)
  {
    axes[0] = 1;
    axes[1] = 2;
    axes[2] = 0;
  }
  vtkNew<vtkSuperquadricSource> sq;
  sq->SetThetaRoundness(alpha);
  sq->SetPhiRoundness(beta);
  sq->SetSize(1.0);
  sq->SetZAxisOfSymmetry();
  sq->SetThetaResolution(s.Resolution);
  sq->SetPhiResolution(s.Resolution / 2);
  vtkNew<vtkMatrix4x4> m;
  for (int col = 0; col < 3; ++col)
  {
    for (int row = 0; row < 3; ++row)
    {
      m->SetElement(row, col, semi[axes[col]] * e[axes[col]][row]);
    }
    m->SetElement(col, 3, c[col]);
  }
  vtkNew<vtkTransform> xf;
  xf->SetMatrix(m);
  vtkNew<vtkTransformPolyDataFilter> tf;
  tf->SetInputConnection(sq->GetOutputPort());
  tf->SetTransform(xf);
  tf->Update();
  return tf->GetOutput();
}

//------------------------------------------------------------------------------
// Schultz-Kindlmann glyphs, written out here independently of the shader code
// (vtkTensorMathShared.glsl folds the negative-dominant half of the shape
// square onto the positive one and blends five zones; this reference walks
// the whole square with the ten zones and shape table of Teem's
// tenGlyphBqdAbcUv and Deft's glyph palette), and a polygonal surface from
// an explicit parametrization (the shader ray casts an implicit function).

struct SKShape
{
  double ABC[3]; // alpha, beta, c
  bool AxisE1;   // symmetry axis along e1 (else e3)
  double UV[2];  // the point in the shape square
  int Zone;
};

/// Deliberate mistakes for the Schultz-Kindlmann reference.
enum SKMutation
{
  SK_NONE = 0,
  SK_SWAPPED_AXIS = 1,        // symmetry axis e3 where it is e1 and vice versa
  SK_ABSOLUTE_KINDLMANN = 2,  // Kindlmann's glyph of |l| (ABSOLUTE_VALUES)
  SK_PAPER_NORMALIZATION = 3, // the paper's max-normalized placement (no trace warp)
  SK_NO_THIRD_EXPONENT = 4,   // c = beta everywhere
  SK_UNSHARPENED = 5          // gamma ignored (the paper's shapes at gamma 1)
};

/// (u, v) of sorted eigenvalues l of a positive-dominant tensor (l0 = 1 after
/// normalization), with the documented trace re-parametrization.
inline void SKPositiveDominantUV(double x, double y, double z, bool trace, double uv[2])
{
  (void)x; // 1
  double yy = y, zz = z;
  if (trace && z >= 0.0)
  {
    const double S = 1.0 + y + z;
    yy = (2.0 * y + z) / S;
    zz = 3.0 * z / S;
  }
  else if (trace && y > 0.0)
  {
    yy = y * (2.0 + z) / (1.0 + y * (1.0 + z));
  }
  uv[0] = (yy + 1.0) / 2.0;
  uv[1] = (zz + 1.0) / 2.0 - uv[0] + 1.0;
}

inline SKShape SchultzKindlmann(
  const double lsorted[3], double gamma, double minRoundness, SKMutation mutate = SK_NONE)
{
  SKShape r;
  const bool trace = mutate != SK_PAPER_NORMALIZATION;
  const double m = std::max(std::abs(lsorted[0]), std::abs(lsorted[2]));
  double x = lsorted[0] / m, y = lsorted[1] / m, z = lsorted[2] / m;
  if (x >= -z)
  {
    SKPositiveDominantUV(x, y, z, trace, r.UV);
  }
  else
  {
    double uvNeg[2];
    SKPositiveDominantUV(-z, -y, -x, trace, uvNeg);
    r.UV[0] = 1.0 - uvNeg[0];
    r.UV[1] = 1.0 - uvNeg[1];
  }
  const double u = r.UV[0], v = r.UV[1];
  // Teem's zones of the unit square (the definite zones with their edge
  // u + v = 3/2, a zero smallest eigenvalue, as documented)
  int zone;
  if (u > 0.5 || u + v >= 1.5)
  {
    if (u + v >= 1.5)
      zone = u < v ? 0 : 1;
    else if (2 * u + v > 2)
      zone = 2;
    else if (u + v > 1)
      zone = 3;
    else
      zone = 4;
  }
  else
  {
    if (u + v > 0.5)
    {
      if (u + v > 1)
        zone = 5;
      else if (2 * u + v > 1)
        zone = 6;
      else
        zone = 7;
    }
    else
      zone = u < v ? 8 : 9;
  }
  r.Zone = zone;
  static const double corner[11][2] = { { 1.00, 1.00 }, { 0.50, 1.00 }, { 0.75, 0.75 },
    { 1.00, 0.50 }, { 1.00, 0.00 }, { 0.50, 0.50 }, { 0.00, 1.00 }, { 0.00, 0.50 }, { 0.25, 0.25 },
    { 0.50, 0.00 }, { 0.00, 0.00 } };
  static const int zoneCorners[10][3] = { { 0, 1, 2 }, { 0, 2, 3 }, { 1, 3, 4 }, { 1, 4, 5 },
    { 4, 5, 9 }, { 1, 5, 6 }, { 5, 6, 9 }, { 6, 7, 9 }, { 7, 8, 10 }, { 8, 9, 10 } };
  enum Base
  {
    BALL,
    CYLINDER,
    HALF,
    OCTAHEDRON,
    CONE,
    THORN,
    CENTER
  };
  static const double base[7][3] = { { 1, 1, 1 }, { 1, 0, 0 }, { 0.5, 0.5, 0.5 }, { 0, 2, 2 },
    { 1, 2, 2 }, { 1, 3, 3 }, { 0, 3, 2 } };
  static const int zoneShapes[10][3] = { { BALL, CYLINDER, HALF }, { BALL, HALF, CYLINDER },
    { OCTAHEDRON, CONE, THORN }, { OCTAHEDRON, THORN, CENTER }, { THORN, CENTER, CONE },
    { CONE, CENTER, THORN }, { CENTER, THORN, OCTAHEDRON }, { THORN, CONE, OCTAHEDRON },
    { CYLINDER, HALF, BALL }, { HALF, CYLINDER, BALL } };
  // barycentric coordinates from sub-triangle areas
  auto area = [](const double* a, const double* b, double pu, double pv)
  { return std::abs((a[0] - pu) * (b[1] - pv) - (b[0] - pu) * (a[1] - pv)); };
  const double* c0 = corner[zoneCorners[zone][0]];
  const double* c1 = corner[zoneCorners[zone][1]];
  const double* c2 = corner[zoneCorners[zone][2]];
  const double a0 = area(c1, c2, u, v), a1 = area(c0, c2, u, v), a2 = area(c0, c1, u, v);
  const double sum = a0 + a1 + a2;
  for (int k = 0; k < 3; ++k)
  {
    r.ABC[k] = (a0 * base[zoneShapes[zone][0]][k] + a1 * base[zoneShapes[zone][1]][k] +
                 a2 * base[zoneShapes[zone][2]][k]) /
      sum;
  }
  // Deft: the symmetry axis is x (e1) in zones 0, 5, 6, 7, 8, else z (e3)
  r.AxisE1 = zone == 0 || zone == 5 || zone == 6 || zone == 7 || zone == 8;
  if (mutate == SK_SWAPPED_AXIS)
  {
    r.AxisE1 = !r.AxisE1;
  }
  if (mutate == SK_NO_THIRD_EXPONENT)
  {
    r.ABC[2] = r.ABC[1];
  }
  const double g = mutate == SK_UNSHARPENED ? 1.0 : gamma;
  const double lo = std::max(minRoundness, 1e-3);
  for (int k = 0; k < 3; ++k)
  {
    double e = r.ABC[k];
    if (e < 1.0)
      e = std::pow(std::max(e, 1e-6), g);
    else if (e > 2.0)
      e = 2.0 + (e - 2.0) * g;
    r.ABC[k] = std::min(k == 0 ? 1.0 : 1.0 / lo, std::max(lo, e));
  }
  return r;
}

/// sgn(x) |x|^p
inline double SignedPower(double x, double p)
{
  return x < 0 ? -std::pow(-x, p) : std::pow(x, p);
}

/// A glyph as a solid, for CPU ray casting in tests: center, the scaled
/// glyph axes u, v, w (w the symmetry axis) and the exponents; optionally
/// blended (Weight < 1) with a second shape ABC2 in the same axes (Swapped2:
/// its symmetry axis is u), as in the zero-eigenvalue band of the
/// Schultz-Kindlmann glyphs.
struct GlyphSolid
{
  double Center[3];
  double Axes[3][3]; // Axes[k] = semi-axis k times its unit vector
  double ABC[3];
  double ABC2[3] = { 1.0, 1.0, 1.0 };
  bool Swapped2 = false;
  double Weight = 1.0;

  /// The glyph coordinates of world point p (Axes are orthogonal).
  void ToGlyph(const double p[3], double x[3]) const
  {
    for (int k = 0; k < 3; ++k)
    {
      double dot = 0.0, len2 = 0.0;
      for (int r = 0; r < 3; ++r)
      {
        dot += (p[r] - this->Center[r]) * this->Axes[k][r];
        len2 += this->Axes[k][r] * this->Axes[k][r];
      }
      x[k] = dot / len2;
    }
  }

  /// (|u|/R_beta(w))^(2/alpha) + (|v|/R_c(w))^(2/alpha) for |w| < 1, else
  /// infinity: the solid is where it is below 1.
  static double Implicit(const double x[3], const double abc[3])
  {
    if (std::abs(x[2]) >= 1.0)
    {
      return std::numeric_limits<double>::infinity();
    }
    auto radius = [&](double e)
    { return std::pow(1.0 - std::pow(std::abs(x[2]), 2.0 / e), e / 2.0); };
    return std::pow(std::abs(x[0]) / radius(abc[1]), 2.0 / abc[0]) +
      std::pow(std::abs(x[1]) / radius(abc[2]), 2.0 / abc[0]);
  }

  /// Inside, in glyph coordinates. Blended: the radius-like n_i =
  /// g_i^(alpha_i / 2) of the two shapes by their weighted harmonic mean,
  /// inside where w / n_1 + (1 - w) / n_2 > 1.
  bool InsideGlyph(const double x[3]) const
  {
    const double g = Implicit(x, this->ABC);
    if (this->Weight >= 1.0)
    {
      return g < 1.0;
    }
    const double x2[3] = { this->Swapped2 ? x[2] : x[0], x[1], this->Swapped2 ? x[0] : x[2] };
    const double g2 = Implicit(x2, this->ABC2);
    const double n1 = std::pow(g, this->ABC[0] / 2.0), n2 = std::pow(g2, this->ABC2[0] / 2.0);
    return this->Weight / n1 + (1.0 - this->Weight) / n2 > 1.0;
  }

  bool Inside(const double p[3]) const
  {
    double x[3];
    this->ToGlyph(p, x);
    return this->InsideGlyph(x);
  }
};

/// The Schultz-Kindlmann glyph of tensor t (VTK order) at c as a solid
/// (eigen-system from vtkMath::Jacobi; semi-axes scale |l_i|, at least
/// minThickness of the largest). Mutations as for ReferenceSKGlyph(). In
/// the band |l_edge| < band max|l| on the indefinite side of a zero
/// eigenvalue (l_edge = l3 of positive-dominant tensors, l1 of
/// negative-dominant ones) the solid is blended, with the weight
/// smoothstep(|l_edge| / (band max|l|)), with the shape of the tensor whose
/// l_edge is 0 (the class documentation of vtkSuperquadricGlyphMapper).
inline GlyphSolid SKGlyphSolid(const double t[6], const double c[3], double gamma, double scale,
  double minRoundness, double minThickness, SKMutation mutate = SK_NONE, double band = 0.15);

inline GlyphSolid SKGlyphSolid(const double t[6], const double c[3], double gamma, double scale,
  double minRoundness, double minThickness, SKMutation mutate, double band)
{
  double a0[3] = { t[0], t[3], t[5] }, a1[3] = { t[3], t[1], t[4] }, a2[3] = { t[5], t[4], t[2] };
  double v0[3], v1[3], v2[3], w[3];
  double* a[3] = { a0, a1, a2 };
  double* v[3] = { v0, v1, v2 };
  vtkMath::Jacobi(a, w, v); // descending values, vectors in columns
  double e[3][3];
  for (int k = 0; k < 3; ++k)
  {
    for (int r = 0; r < 3; ++r)
    {
      e[k][r] = v[r][k];
    }
  }
  double abc[3];
  bool axisE1;
  double semi[3];
  const double big = std::max({ std::abs(w[0]), std::abs(w[1]), std::abs(w[2]) });
  if (mutate == SK_ABSOLUTE_KINDLMANN)
  {
    // Kindlmann's glyph of the absolute eigenvalues (trace-normalized Westin)
    int order[3] = { 0, 1, 2 };
    std::sort(order, order + 3, [&](int i, int j) { return std::abs(w[i]) > std::abs(w[j]); });
    double l[3], ee[3][3];
    for (int k = 0; k < 3; ++k)
    {
      l[k] = std::abs(w[order[k]]);
      for (int r = 0; r < 3; ++r)
        ee[k][r] = e[order[k]][r];
    }
    for (int k = 0; k < 3; ++k)
      for (int r = 0; r < 3; ++r)
        e[k][r] = ee[k][r];
    for (int k = 0; k < 3; ++k)
      w[k] = l[k];
    const double S = l[0] + l[1] + l[2];
    const double cl = (l[0] - l[1]) / S, cp = 2.0 * (l[1] - l[2]) / S;
    axisE1 = cl > cp;
    const double al = std::pow(std::max(axisE1 ? 1 - cp : 1 - cl, 1e-6), gamma);
    const double be = std::pow(std::max(axisE1 ? 1 - cl : 1 - cp, 1e-6), gamma);
    abc[0] = std::min(1.0, std::max(minRoundness, al));
    abc[1] = abc[2] = std::min(1.0, std::max(minRoundness, be));
  }
  else
  {
    const SKShape sh = SchultzKindlmann(w, gamma, minRoundness, mutate);
    for (int k = 0; k < 3; ++k)
      abc[k] = sh.ABC[k];
    axisE1 = sh.AxisE1;
  }
  double weight = 1.0, abc2[3] = { 1.0, 1.0, 1.0 };
  bool axis2E1 = axisE1;
  if (mutate != SK_ABSOLUTE_KINDLMANN && band > 0.0)
  {
    const double m = std::max(std::abs(w[0]), std::abs(w[2]));
    const int edge = w[0] + w[2] < 0.0 ? 0 : 2;
    const double x = std::abs(w[edge]) / (band * m);
    if ((edge == 0 ? w[0] > 0.0 : w[2] < 0.0) && x < 1.0)
    {
      weight = x * x * (3.0 - 2.0 * x);
      double flat[3] = { w[0], w[1], w[2] };
      flat[edge] = 0.0;
      const SKShape sh2 = SchultzKindlmann(flat, gamma, minRoundness, mutate);
      std::copy(sh2.ABC, sh2.ABC + 3, abc2);
      axis2E1 = sh2.AxisE1;
    }
  }
  for (int k = 0; k < 3; ++k)
  {
    semi[k] = std::max(scale * std::abs(w[k]), minThickness * scale * big);
  }
  // glyph axes (u, v, w): u = the other of e1/e3, v = e2, w = the symmetry axis
  const int axes[3] = { axisE1 ? 2 : 0, 1, axisE1 ? 0 : 2 };
  GlyphSolid solid;
  for (int k = 0; k < 3; ++k)
  {
    solid.Center[k] = c[k];
    solid.ABC[k] = abc[k];
    solid.ABC2[k] = abc2[k];
    for (int r = 0; r < 3; ++r)
    {
      solid.Axes[k][r] = semi[axes[k]] * e[axes[k]][r];
    }
  }
  solid.Weight = weight;
  solid.Swapped2 = axis2E1 != axisE1;
  return solid;
}

/// Polygonal Schultz-Kindlmann glyph of tensor t (VTK order) at center c:
/// the (alpha, beta, c) surface z = cos^beta(phi), x = cos^alpha(theta)
/// R_beta(z), y = sin^alpha(theta) R_c(z), R_e(z) = (1 - |z|^(2/e))^(e/2)
/// (Barr's superquadric for c = beta), res x res/2 quads, placed by the
/// eigen-system from vtkMath::Jacobi with semi-axes scale |l_i| (at least
/// minThickness of the largest). Blended glyphs (see SKGlyphSolid()): the
/// points of that parametrization of the unblended shape moved along their
/// rays from the center onto the blended surface (by bisection).
inline vtkSmartPointer<vtkPolyData> ReferenceSKGlyph(const double t[6], const double c[3],
  double gamma, double scale, double minRoundness, double minThickness, int res,
  SKMutation mutate = SK_NONE, double band = 0.15)
{
  const GlyphSolid solid =
    SKGlyphSolid(t, c, gamma, scale, minRoundness, minThickness, mutate, band);
  const double* abc = solid.ABC;
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> pts;
  vtkNew<vtkCellArray> quads;
  const int nt = res, np = res / 2;
  auto radius = [](double z, double ex)
  { return std::pow(std::max(0.0, 1.0 - std::pow(std::abs(z), 2.0 / ex)), ex / 2.0); };
  for (int j = 0; j <= np; ++j)
  {
    const double phi = vtkMath::Pi() * j / np;
    for (int i = 0; i < nt; ++i)
    {
      const double theta = 2.0 * vtkMath::Pi() * i / nt;
      const double zz = SignedPower(std::cos(phi), abc[1]);
      const double xx = SignedPower(std::cos(theta), abc[0]) * radius(zz, abc[1]);
      const double yy = SignedPower(std::sin(theta), abc[0]) * radius(zz, abc[2]);
      double g[3] = { xx, yy, zz };
      if (solid.Weight < 1.0)
      {
        // blended (star-shaped about the center: the solid's function grows
        // along every ray from it): the surface point on the ray through
        // the unblended surface point, by bisection
        double lo = 0.0, hi = 1.0 / std::max({ std::abs(xx), std::abs(yy), std::abs(zz) });
        for (int it = 0; it < 40; ++it)
        {
          const double mid = 0.5 * (lo + hi);
          const double x[3] = { mid * xx, mid * yy, mid * zz };
          (solid.InsideGlyph(x) ? lo : hi) = mid;
        }
        for (double& gk : g)
        {
          gk *= 0.5 * (lo + hi);
        }
      }
      double p[3] = { c[0], c[1], c[2] };
      for (int k = 0; k < 3; ++k)
      {
        for (int r = 0; r < 3; ++r)
        {
          p[r] += g[k] * solid.Axes[k][r];
        }
      }
      pts->InsertNextPoint(p);
    }
  }
  for (int j = 0; j < np; ++j)
  {
    for (int i = 0; i < nt; ++i)
    {
      const vtkIdType q[4] = { j * nt + i, j * nt + (i + 1) % nt, (j + 1) * nt + (i + 1) % nt,
        (j + 1) * nt + i };
      quads->InsertNextCell(4, q);
    }
  }
  pd->SetPoints(pts);
  pd->SetPolys(quads);
  return pd;
}

/// The reference glyphs of all tensors of an image (or any data set).
inline vtkSmartPointer<vtkPolyData> ReferenceGlyphs(vtkDataSet* data, const ReferenceSettings& s)
{
  vtkNew<vtkAppendPolyData> append;
  vtkDataArray* tensors = data->GetPointData()->GetTensors();
  int count = 0;
  for (vtkIdType i = 0; i < data->GetNumberOfPoints(); ++i)
  {
    double t[6], c[3];
    tensors->GetTuple(i, t);
    data->GetPoint(i, c);
    auto g = ReferenceGlyph(t, c, s);
    if (g)
    {
      append->AddInputData(g);
      ++count;
    }
  }
  if (count == 0)
  {
    return vtkSmartPointer<vtkPolyData>::New();
  }
  append->Update();
  return append->GetOutput();
}
}

#endif
