// Helpers of the superquadric glyph tests: hand-made tensors with known
// eigen-systems, and an INDEPENDENT CPU reference of the glyphs: eigenvectors
// from vtkMath::Jacobi, Kindlmann's rule and the scale rule written out here
// from the paper and ../shared/docs/field-notes.md (not the SplineViz code),
// polygonal superquadrics from vtkSuperquadricSource, placed, rotated and
// scaled by the eigen-system and drawn by a standard vtkPolyDataMapper.
#ifndef SuperquadricGlyphTestUtilities_h
#define SuperquadricGlyphTestUtilities_h

#include "vtkAppendPolyData.h"
#include "vtkDoubleArray.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkSuperquadricSource.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace sqtest
{
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
