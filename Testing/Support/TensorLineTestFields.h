// SPDX-License-Identifier: BSD-3-Clause
// Tensor fields with known principal-direction curves for the tests and the
// benchmark of vtkTensorLineTracer (written here, independently of the
// filter), and helpers to read its output.
//
//  - HelixFieldTensor: T = a I + t t^T with t = (-y, x, c). Its principal
//    eigenvector is t / |t| (eigenvalue a + |t|^2, the others a), so the
//    traced lines are exact helices about the z axis (circles for c = 0):
//    x(s) = (r cos(phi0 + s / w), r sin(phi0 + s / w), z0 + c s / w),
//    w = sqrt(r^2 + c^2). Every component is a quadratic polynomial, so
//    tri-quadratic hexahedra represent it exactly (no interpolation error:
//    the traced lines then show the integrator's own error).
//  - TendHelixTensor: a twisting helical bundle like Teem's `tend helix`
//    (a tube of minor radius r about the helix (R cos th, R sin th, S th /
//    2 pi); inside it the principal direction is the helix tangent twisted
//    about the radial direction by an angle growing linearly with the
//    distance from the core, outside the tensors are isotropic, with a
//    smooth (erf) boundary). Written from the description of Teem's tool,
//    not from its code. On the core the principal direction is the core's
//    tangent, so a line seeded on the core follows the core helix.
#ifndef TensorLineTestFields_h
#define TensorLineTestFields_h

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkTriQuadraticHexahedron.h"
#include "vtkUnstructuredGrid.h"

#include <array>
#include <cmath>
#include <functional>
#include <vector>

namespace TensorLineTest
{
using Vec3 = std::array<double, 3>;
/// A tensor at a point: t = {xx, yy, zz, xy, yz, xz}.
using TensorFunction = std::function<void(const double x[3], double t[6])>;

inline double Dot(const Vec3& a, const Vec3& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
inline Vec3 Cross(const Vec3& a, const Vec3& b)
{
  return { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
}
inline double Norm(const Vec3& a)
{
  return std::sqrt(Dot(a, a));
}
inline Vec3 Normalized(const Vec3& a)
{
  const double n = Norm(a);
  return { a[0] / n, a[1] / n, a[2] / n };
}

/// t = sum_k l[k] e[k] e[k]^T for orthonormal e[k].
inline void Compose(const double l[3], const Vec3 e[3], double t[6])
{
  for (int i = 0; i < 6; ++i)
  {
    t[i] = 0.0;
  }
  for (int k = 0; k < 3; ++k)
  {
    const Vec3& v = e[k];
    t[0] += l[k] * v[0] * v[0];
    t[1] += l[k] * v[1] * v[1];
    t[2] += l[k] * v[2] * v[2];
    t[3] += l[k] * v[0] * v[1];
    t[4] += l[k] * v[1] * v[2];
    t[5] += l[k] * v[0] * v[2];
  }
}

/// T = a I + t t^T, t = (-y, x, c).
inline void HelixFieldTensor(const double x[3], double c, double a, double t[6])
{
  const double v[3] = { -x[1], x[0], c };
  t[0] = a + v[0] * v[0];
  t[1] = a + v[1] * v[1];
  t[2] = a + v[2] * v[2];
  t[3] = v[0] * v[1];
  t[4] = v[1] * v[2];
  t[5] = v[0] * v[2];
}

/// The exact helix of HelixFieldTensor through p, at signed arc length s.
inline Vec3 HelixFieldCurve(const double p[3], double c, double s)
{
  const double r = std::hypot(p[0], p[1]);
  const double w = std::sqrt(r * r + c * c);
  const double phi = std::atan2(p[1], p[0]) + s / w;
  return { r * std::cos(phi), r * std::sin(phi), p[2] + c * s / w };
}

/// Parameters of TendHelixTensor.
struct TendHelix
{
  double R = 1.0;                                     // major radius of the helical core
  double S = 2.0;                                     // spacing between turns along z
  double r = 0.4;                                     // minor radius of the bundle
  double Fuzz = 0.05;                                 // width of the boundary (erf)
  double Twist = vtkMath::Pi() / 3.0;                 // twist at the bundle's surface (radians)
  double Eigenvalues[3] = { 1.5e-3, 0.4e-3, 0.3e-3 }; // along, around, radial
  double Isotropic = 0.7e-3;                          // outside the bundle

  Vec3 Core(double th) const
  {
    return { R * std::cos(th), R * std::sin(th), S * th / (2.0 * vtkMath::Pi()) };
  }
  Vec3 CoreTangent(double th) const
  {
    return Normalized({ -R * std::sin(th), R * std::cos(th), S / (2.0 * vtkMath::Pi()) });
  }

  /// The parameter of the point of the core closest to p.
  double Closest(const double p[3]) const
  {
    const double twoPi = 2.0 * vtkMath::Pi();
    const double phi = std::atan2(p[1], p[0]);
    const double th0 = phi + twoPi * std::round((twoPi * p[2] / S - phi) / twoPi);
    auto dist2 = [&](double th)
    {
      const Vec3 c = this->Core(th);
      return (c[0] - p[0]) * (c[0] - p[0]) + (c[1] - p[1]) * (c[1] - p[1]) +
        (c[2] - p[2]) * (c[2] - p[2]);
    };
    // coarse scan over a turn each side, then Newton on d/dth |H - p|^2
    double best = th0, bestD = dist2(th0);
    for (int k = -64; k <= 64; ++k)
    {
      const double th = th0 + k * vtkMath::Pi() / 32.0;
      const double d = dist2(th);
      if (d < bestD)
      {
        bestD = d;
        best = th;
      }
    }
    const double sz = S / twoPi;
    double th = best;
    for (int it = 0; it < 30; ++it)
    {
      const Vec3 c = this->Core(th);
      const Vec3 d1 = { -R * std::sin(th), R * std::cos(th), sz };
      const Vec3 d2 = { -R * std::cos(th), -R * std::sin(th), 0.0 };
      const Vec3 diff = { c[0] - p[0], c[1] - p[1], c[2] - p[2] };
      const double g = Dot(diff, d1);
      const double gp = Dot(d1, d1) + Dot(diff, d2);
      if (!(gp > 0))
      {
        break;
      }
      const double step = g / gp;
      th -= std::max(-0.1, std::min(0.1, step));
      if (std::abs(step) < 1e-15)
      {
        break;
      }
    }
    return th;
  }

  void Tensor(const double p[3], double t[6]) const
  {
    const double th = this->Closest(p);
    const Vec3 c = this->Core(th);
    const Vec3 f = this->CoreTangent(th);
    Vec3 d = { p[0] - c[0], p[1] - c[1], p[2] - c[2] };
    const double along = Dot(d, f);
    d = { d[0] - along * f[0], d[1] - along * f[1], d[2] - along * f[2] };
    const double rho = Norm(d);
    Vec3 rv;
    if (rho > 1e-12)
    {
      rv = { d[0] / rho, d[1] / rho, d[2] / rho };
    }
    else
    {
      // on the core: the helix normal (towards the axis), any choice works
      rv = { -std::cos(th), -std::sin(th), 0.0 };
    }
    const Vec3 uv = Cross(rv, f);
    const double angle = this->Twist * rho / this->r;
    const double ca = std::cos(angle), sa = std::sin(angle);
    // rotate (f, uv) about rv
    const Vec3 fr = { ca * f[0] + sa * uv[0], ca * f[1] + sa * uv[1], ca * f[2] + sa * uv[2] };
    const Vec3 ur = Cross(rv, fr);
    const double inside = 0.5 - 0.5 * std::erf((rho - this->r) / (this->Fuzz + 1e-4));
    double l[3];
    for (int k = 0; k < 3; ++k)
    {
      l[k] = this->Isotropic + inside * (this->Eigenvalues[k] - this->Isotropic);
    }
    const Vec3 e[3] = { fr, ur, rv };
    Compose(l, e, t);
  }
};

/// A vtkImageData with the point tensors of `fn` ("Tensors", 6 components,
/// XX YY ZZ XY YZ XZ, active tensors).
inline vtkSmartPointer<vtkImageData> MakeImage(
  const int dims[3], const double origin[3], const double spacing[3], const TensorFunction& fn)
{
  auto img = vtkSmartPointer<vtkImageData>::New();
  img->SetDimensions(dims[0], dims[1], dims[2]);
  img->SetOrigin(origin[0], origin[1], origin[2]);
  img->SetSpacing(spacing[0], spacing[1], spacing[2]);
  vtkNew<vtkDoubleArray> tensors;
  tensors->SetName("Tensors");
  tensors->SetNumberOfComponents(6);
  tensors->SetNumberOfTuples(img->GetNumberOfPoints());
  double* out = tensors->GetPointer(0);
  vtkImageData* raw = img;
  vtkSMPTools::For(0, img->GetNumberOfPoints(),
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        double x[3];
        raw->GetPoint(i, x);
        fn(x, out + 6 * i);
      }
    });
  img->GetPointData()->SetTensors(tensors);
  return img;
}

/// An unstructured grid of n[0] x n[1] x n[2] tri-quadratic hexahedra
/// (27 nodes) on the box `bounds`, with the point tensors of `fn`.
inline vtkSmartPointer<vtkUnstructuredGrid> MakeTriQuadraticGrid(
  const int n[3], const double bounds[6], const TensorFunction& fn)
{
  const int nn[3] = { 2 * n[0] + 1, 2 * n[1] + 1, 2 * n[2] + 1 };
  auto node = [&](int i, int j, int k) -> vtkIdType
  { return i + static_cast<vtkIdType>(nn[0]) * (j + static_cast<vtkIdType>(nn[1]) * k); };
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(nn[0]) * nn[1] * nn[2]);
  vtkNew<vtkDoubleArray> tensors;
  tensors->SetName("Tensors");
  tensors->SetNumberOfComponents(6);
  tensors->SetNumberOfTuples(points->GetNumberOfPoints());
  for (int k = 0; k < nn[2]; ++k)
  {
    for (int j = 0; j < nn[1]; ++j)
    {
      for (int i = 0; i < nn[0]; ++i)
      {
        const double x[3] = { bounds[0] + (bounds[1] - bounds[0]) * i / (nn[0] - 1),
          bounds[2] + (bounds[3] - bounds[2]) * j / (nn[1] - 1),
          bounds[4] + (bounds[5] - bounds[4]) * k / (nn[2] - 1) };
        points->SetPoint(node(i, j, k), x);
        double t[6];
        fn(x, t);
        tensors->SetTypedTuple(node(i, j, k), t);
      }
    }
  }
  vtkNew<vtkTriQuadraticHexahedron> reference;
  const double* pc = reference->GetParametricCoords();
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->SetPoints(points);
  grid->Allocate(n[0] * n[1] * n[2]);
  for (int k = 0; k < n[2]; ++k)
  {
    for (int j = 0; j < n[1]; ++j)
    {
      for (int i = 0; i < n[0]; ++i)
      {
        vtkIdType ids[27];
        for (int p = 0; p < 27; ++p)
        {
          ids[p] = node(2 * i + static_cast<int>(std::lround(2 * pc[3 * p])),
            2 * j + static_cast<int>(std::lround(2 * pc[3 * p + 1])),
            2 * k + static_cast<int>(std::lround(2 * pc[3 * p + 2])));
        }
        grid->InsertNextCell(VTK_TRIQUADRATIC_HEXAHEDRON, 27, ids);
      }
    }
  }
  grid->GetPointData()->SetTensors(tensors);
  return grid;
}

/// Polydata with the given points (seeds).
inline vtkSmartPointer<vtkPolyData> MakeSeeds(const std::vector<Vec3>& seeds)
{
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (const Vec3& s : seeds)
  {
    points->InsertNextPoint(s.data());
  }
  pd->SetPoints(points);
  return pd;
}

/// One output line: its points and point/cell values.
struct TracedLine
{
  std::vector<Vec3> Points;
  std::vector<Vec3> Directions;
  std::vector<double> FA, Arc;
  int SeedId = -1;
  int Reasons[2] = { 0, 0 };
  double Length = 0.0;
};

inline std::vector<TracedLine> GetLines(vtkPolyData* pd)
{
  std::vector<TracedLine> out;
  vtkDataArray* dir = pd->GetPointData()->GetArray("PrincipalDirection");
  vtkDataArray* fa = pd->GetPointData()->GetArray("FractionalAnisotropy");
  vtkDataArray* arc = pd->GetPointData()->GetArray("ArcLength");
  vtkDataArray* seeds = pd->GetCellData()->GetArray("SeedIds");
  vtkDataArray* reasons = pd->GetCellData()->GetArray("ReasonForTermination");
  vtkDataArray* length = pd->GetCellData()->GetArray("Length");
  vtkCellArray* lines = pd->GetLines();
  if (!lines || !dir || !fa || !arc || !seeds || !reasons || !length)
  {
    return out;
  }
  vtkIdType n;
  const vtkIdType* ids;
  vtkIdType c = 0;
  for (lines->InitTraversal(); lines->GetNextCell(n, ids); ++c)
  {
    TracedLine l;
    for (vtkIdType i = 0; i < n; ++i)
    {
      Vec3 p, d;
      pd->GetPoint(ids[i], p.data());
      dir->GetTuple(ids[i], d.data());
      l.Points.push_back(p);
      l.Directions.push_back(d);
      l.FA.push_back(fa->GetComponent(ids[i], 0));
      l.Arc.push_back(arc->GetComponent(ids[i], 0));
    }
    l.SeedId = static_cast<int>(seeds->GetComponent(c, 0));
    l.Reasons[0] = static_cast<int>(reasons->GetComponent(c, 0));
    l.Reasons[1] = static_cast<int>(reasons->GetComponent(c, 1));
    l.Length = length->GetComponent(c, 0);
    out.push_back(l);
  }
  return out;
}

/// Distance from p to the polyline `line`.
inline double DistanceToPolyline(const Vec3& p, const std::vector<Vec3>& line)
{
  double best = VTK_DOUBLE_MAX;
  for (std::size_t i = 0; i + 1 < line.size(); ++i)
  {
    const Vec3& a = line[i];
    const Vec3& b = line[i + 1];
    const Vec3 ab = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
    const Vec3 ap = { p[0] - a[0], p[1] - a[1], p[2] - a[2] };
    const double l2 = Dot(ab, ab);
    double t = l2 > 0 ? Dot(ap, ab) / l2 : 0.0;
    t = std::min(1.0, std::max(0.0, t));
    const Vec3 q = { a[0] + t * ab[0] - p[0], a[1] + t * ab[1] - p[1], a[2] + t * ab[2] - p[2] };
    best = std::min(best, Norm(q));
  }
  if (line.size() == 1)
  {
    const Vec3 q = { line[0][0] - p[0], line[0][1] - p[1], line[0][2] - p[2] };
    best = Norm(q);
  }
  return best;
}

// The centre lines of vtkHyperStreamline's tubes (one per streamer): the
// mean of each ring of `sides` points of its triangle strips.
inline std::vector<std::vector<Vec3>> CentreLines(vtkPolyData* tubes, int sides)
{
  std::vector<std::vector<Vec3>> out;
  vtkCellArray* strips = tubes->GetStrips();
  vtkIdType n;
  const vtkIdType* ids;
  vtkIdType offset = 0;
  int strip = 0;
  for (strips->InitTraversal(); strips->GetNextCell(n, ids); ++strip)
  {
    if (strip % sides != 0)
    {
      continue; // the other strips of the same streamer
    }
    const vtkIdType rings = n / 2;
    std::vector<Vec3> line;
    for (vtkIdType r = 0; r < rings; ++r)
    {
      Vec3 c = { 0, 0, 0 };
      for (int k = 0; k < sides; ++k)
      {
        double p[3];
        tubes->GetPoint(offset + r * sides + k, p);
        for (int d = 0; d < 3; ++d)
        {
          c[d] += p[d] / sides;
        }
      }
      line.push_back(c);
    }
    offset += rings * sides;
    out.push_back(line);
  }
  return out;
}
}

#endif
