// SPDX-License-Identifier: BSD-3-Clause
// Independent reference for fields on curved (isoparametric) LR-spline
// geometry, for the tests of physical-space evaluation and rendering. The
// geometry map x(u) and the field f(u) come from the LRSplines text alone
// (lrtest::ParseLR): on every element each is a polynomial, recovered by
// tensor-product Lagrange interpolation at Chebyshev points of the exact
// LR B-spline sum over the basis functions whose support covers the element,
// each univariate B by lrtest::TruncatedPowerBSpline (the Curry-Schoenberg
// divided difference of truncated powers on the function's local knot
// vector, in double-double: a different algorithm from the production
// code's Cox-de Boor recurrence, see LRSplineTestUtilities.h). Rational
// texts hold homogeneous coefficients (w x, w y, w z, w) and (w f, w):
// x = X / W and f = F / W, each with its own weight component. A physical
// point is found by Newton's method on the patch's global parameter (element
// by element, the boundary elements' polynomials extended outside the
// domain), started from the linear approximation at the centre of the
// previous sample's element or else of each element whose box (of the
// control points of its basis functions: the convex hull property) contains
// the point; it lies in the patch when Newton converges to a parameter
// inside the domain.
// Nothing here uses the SplineViz classes.
#ifndef LRSplinePhysicalReference_h
#define LRSplinePhysicalReference_h

#include "LRSplineTestUtilities.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace lrtest
{
class PhysicalField
{
public:
  /// The geometry (3 components, or 4 homogeneous when `rational`) and the
  /// field (n components, n + 1 homogeneous when `rational`) as LRSplines
  /// texts with the same patches and elements.
  bool Build(const std::string& geometryText, const std::string& fieldText, bool rational,
    std::string* error)
  {
    const std::vector<BrutePatch> geometry = ParseLR(geometryText);
    const std::vector<BrutePatch> field = ParseLR(fieldText);
    this->Rational = rational;
    if (geometry.empty() || geometry.size() != field.size())
    {
      *error = "the geometry and the field have different patches";
      return false;
    }
    this->Patches.clear();
    for (std::size_t p = 0; p < geometry.size(); ++p)
    {
      const BrutePatch& G = geometry[p];
      const BrutePatch& F = field[p];
      if (G.Dim != (rational ? 4 : 3) || F.Dim < (rational ? 2 : 1) ||
        G.Elements.size() != F.Elements.size() || G.Elements.empty())
      {
        *error = "patch " + std::to_string(p) + ": unexpected dimensions or elements";
        return false;
      }
      Patch P;
      P.FieldDim = F.Dim;
      std::copy(G.Domain, G.Domain + 6, P.Domain);
      for (int d = 0; d < 3; ++d)
      {
        P.Order[d] = std::max(G.Order[d], F.Order[d]);
        if (P.Order[d] > 8)
        {
          *error = "degree too high";
          return false;
        }
        for (int i = 0; i < P.Order[d]; ++i)
        {
          P.T[d][i] = Node(P.Order[d], i);
        }
      }
      for (const auto& box : G.Elements)
      {
        P.Elements.push_back(this->Interpolate(G, F, P, box));
      }
      this->Patches.push_back(std::move(P));
    }
    // Bounds from the control points (inside their convex hull).
    for (int k = 0; k < 3; ++k)
    {
      this->Bounds[2 * k] = 1e300;
      this->Bounds[2 * k + 1] = -1e300;
    }
    for (const BrutePatch& G : geometry)
    {
      for (std::size_t i = 0; i < G.Gamma.size(); ++i)
      {
        const double w = rational ? G.Coef[4 * i + 3] : 1.0;
        for (int k = 0; k < 3; ++k)
        {
          const double x = G.Coef[G.Dim * i + k] / w;
          this->Bounds[2 * k] = std::min(this->Bounds[2 * k], x);
          this->Bounds[2 * k + 1] = std::max(this->Bounds[2 * k + 1], x);
        }
      }
    }
    return true;
  }

  int GetNumberOfComponents() const
  {
    return this->Patches.front().FieldDim - (this->Rational ? 1 : 0);
  }
  void GetBounds(double bounds[6]) const { std::copy(this->Bounds, this->Bounds + 6, bounds); }

  /// The shortest physical edge chord of any element.
  double MinimumSide() const
  {
    double m = 1e300;
    for (const Patch& P : this->Patches)
    {
      for (std::size_t e = 0; e < P.Elements.size(); ++e)
      {
        const double* b = P.Elements[e].Box;
        for (int d = 0; d < 3; ++d)
        {
          double u0[3] = { b[0], b[1], b[2] };
          double u1[3] = { b[0], b[1], b[2] };
          u1[d] = b[d + 3];
          double x0[3], x1[3], J[9];
          this->Map(P, P.Elements[e], u0, x0, J);
          this->Map(P, P.Elements[e], u1, x1, J);
          m = std::min(m,
            std::sqrt((x1[0] - x0[0]) * (x1[0] - x0[0]) + (x1[1] - x0[1]) * (x1[1] - x0[1]) +
              (x1[2] - x0[2]) * (x1[2] - x0[2])));
        }
      }
    }
    return m;
  }

  /// The field (and d f / d x, 3 per component) at physical x: the patch
  /// index, or -1 outside. `patch` and `element` (-1: none) are the hint,
  /// updated to the point's.
  template <class Index>
  int EvaluateWithHint(
    const double x[3], double* value, double* gradient, int& patch, Index& element) const
  {
    double u[3];
    if (patch >= 0 && patch < static_cast<int>(this->Patches.size()) && element >= 0)
    {
      int e = static_cast<int>(element);
      if (this->Invert(this->Patches[patch], x, e, u))
      {
        element = e;
        this->Field(this->Patches[patch], e, u, value, gradient);
        return patch;
      }
    }
    for (int p = 0; p < static_cast<int>(this->Patches.size()); ++p)
    {
      const Patch& P = this->Patches[p];
      for (int k = 0; k < static_cast<int>(P.Elements.size()); ++k)
      {
        const double* box = P.Elements[k].PhysicalBox;
        int e = k;
        if (box[0] <= x[0] && x[0] <= box[3] && box[1] <= x[1] && x[1] <= box[4] &&
          box[2] <= x[2] && x[2] <= box[5] && this->Invert(P, x, e, u))
        {
          patch = p;
          element = e;
          this->Field(P, e, u, value, gradient);
          return p;
        }
      }
    }
    patch = -1;
    element = -1;
    return -1;
  }

  int Evaluate(const double x[3], double* value, double* gradient) const
  {
    int patch = -1;
    long long element = -1;
    return this->EvaluateWithHint(x, value, gradient, patch, element);
  }

private:
  struct Element
  {
    double Box[6];
    std::vector<double> Nodes; // per node (i fastest): 3 or 4 geometry, then field components
    double PhysicalBox[6];     // of the control points of its basis functions (lo, hi)
    double Centre[3];          // x at the parameter centre
    double CentreJinv[9];      // d u / d x there
  };
  struct Patch
  {
    int Order[3];
    double T[3][8]; // the interpolation nodes on [0, 1]
    int FieldDim = 0;
    double Domain[6];
    std::vector<Element> Elements;
  };

  static double Node(int n, int i)
  {
    return 0.5 - 0.5 * std::cos((2.0 * i + 1.0) * Pi() / (2.0 * n));
  }
  static double Pi() { return 3.14159265358979323846; }

  int GeometryDim() const { return this->Rational ? 4 : 3; }

  // The spline sum at u over the basis functions in `active`.
  static void Sum(
    const BrutePatch& B, const std::vector<std::size_t>& active, const double u[3], double* out)
  {
    for (int c = 0; c < B.Dim; ++c)
    {
      out[c] = 0.0;
    }
    for (std::size_t i : active)
    {
      double b = B.Gamma[i];
      for (int d = 0; d < 3; ++d)
      {
        b *= TruncatedPowerBSpline(B.Knots[i][d], u[d], false);
      }
      for (int c = 0; c < B.Dim; ++c)
      {
        out[c] += b * B.Coef[i * B.Dim + c];
      }
    }
  }

  static std::vector<std::size_t> Active(const BrutePatch& B, const std::array<double, 6>& box)
  {
    std::vector<std::size_t> active;
    for (std::size_t i = 0; i < B.Gamma.size(); ++i)
    {
      bool covers = true;
      for (int d = 0; d < 3; ++d)
      {
        covers = covers && B.Knots[i][d].front() <= box[d] && box[d + 3] <= B.Knots[i][d].back();
      }
      if (covers)
      {
        active.push_back(i);
      }
    }
    return active;
  }

  Element Interpolate(const BrutePatch& G, const BrutePatch& F, const Patch& P,
    const std::array<double, 6>& box) const
  {
    Element E;
    std::copy(box.begin(), box.end(), E.Box);
    const std::vector<std::size_t> ga = Active(G, box), fa = Active(F, box);
    std::vector<double> g(G.Dim), f(F.Dim);
    for (int k = 0; k < P.Order[2]; ++k)
    {
      for (int j = 0; j < P.Order[1]; ++j)
      {
        for (int i = 0; i < P.Order[0]; ++i)
        {
          const int idx[3] = { i, j, k };
          double u[3];
          for (int d = 0; d < 3; ++d)
          {
            u[d] = box[d] + Node(P.Order[d], idx[d]) * (box[d + 3] - box[d]);
          }
          Sum(G, ga, u, g.data());
          Sum(F, fa, u, f.data());
          E.Nodes.insert(E.Nodes.end(), g.begin(), g.end());
          E.Nodes.insert(E.Nodes.end(), f.begin(), f.end());
        }
      }
    }
    const double mid[3] = { 0.5 * (box[0] + box[3]), 0.5 * (box[1] + box[4]),
      0.5 * (box[2] + box[5]) };
    double J[9];
    this->Map(P, E, mid, E.Centre, J);
    Inverse(J, E.CentreJinv);
    for (int k = 0; k < 3; ++k)
    {
      E.PhysicalBox[k] = 1e300;
      E.PhysicalBox[k + 3] = -1e300;
    }
    for (std::size_t i : ga)
    {
      const double w = this->Rational ? G.Coef[4 * i + 3] : 1.0;
      for (int k = 0; k < 3; ++k)
      {
        const double x = G.Coef[G.Dim * i + k] / w;
        E.PhysicalBox[k] = std::min(E.PhysicalBox[k], x);
        E.PhysicalBox[k + 3] = std::max(E.PhysicalBox[k + 3], x);
      }
    }
    for (int k = 0; k < 3; ++k)
    {
      const double pad = 1e-9 * (1.0 + std::abs(E.PhysicalBox[k]) + std::abs(E.PhysicalBox[k + 3]));
      E.PhysicalBox[k] -= pad;
      E.PhysicalBox[k + 3] += pad;
    }
    return E;
  }

  // Lagrange basis (n Chebyshev points on [0, 1]) and its derivative at t.
  static void Lagrange(int n, const double* T, double t, double* L, double* dL)
  {
    for (int i = 0; i < n; ++i)
    {
      double l = 1.0, dl = 0.0;
      for (int j = 0; j < n; ++j)
      {
        if (j == i)
        {
          continue;
        }
        const double den = T[i] - T[j];
        dl = (dl * (t - T[j]) + l) / den;
        l *= (t - T[j]) / den;
      }
      L[i] = l;
      dL[i] = dl;
    }
  }

  // All components at parameter u of element e (extended outside it) and
  // their derivatives with respect to u (3 per component).
  void Interpolant(const Patch& P, const Element& E, const double u[3], double* v, double* dv) const
  {
    const int nc = this->GeometryDim() + P.FieldDim;
    double L[3][8], dL[3][8], h[3];
    for (int d = 0; d < 3; ++d)
    {
      h[d] = E.Box[d + 3] - E.Box[d];
      Lagrange(P.Order[d], P.T[d], (u[d] - E.Box[d]) / h[d], L[d], dL[d]);
    }
    std::fill(v, v + nc, 0.0);
    std::fill(dv, dv + 3 * nc, 0.0);
    int node = 0;
    for (int k = 0; k < P.Order[2]; ++k)
    {
      for (int j = 0; j < P.Order[1]; ++j)
      {
        for (int i = 0; i < P.Order[0]; ++i, ++node)
        {
          const double b = L[0][i] * L[1][j] * L[2][k];
          const double db[3] = { dL[0][i] * L[1][j] * L[2][k] / h[0],
            L[0][i] * dL[1][j] * L[2][k] / h[1], L[0][i] * L[1][j] * dL[2][k] / h[2] };
          const double* c = &E.Nodes[static_cast<std::size_t>(node) * nc];
          for (int q = 0; q < nc; ++q)
          {
            v[q] += b * c[q];
            for (int d = 0; d < 3; ++d)
            {
              dv[3 * q + d] += db[d] * c[q];
            }
          }
        }
      }
    }
  }

  // x(u) and J[3 i + j] = d x_i / d u_j on element e.
  void Map(const Patch& P, const Element& E, const double u[3], double x[3], double J[9]) const
  {
    double v[16], dv[48];
    this->Interpolant(P, E, u, v, dv);
    const double W = this->Rational ? v[3] : 1.0;
    const double dW[3] = { this->Rational ? dv[9] : 0.0, this->Rational ? dv[10] : 0.0,
      this->Rational ? dv[11] : 0.0 };
    for (int i = 0; i < 3; ++i)
    {
      x[i] = v[i] / W;
      for (int j = 0; j < 3; ++j)
      {
        J[3 * i + j] = (dv[3 * i + j] - x[i] * dW[j]) / W;
      }
    }
  }

  // The element containing u (clamped to the domain); `hint` tried first.
  static int Find(const Patch& P, const double u[3], int hint)
  {
    double c[3];
    for (int d = 0; d < 3; ++d)
    {
      c[d] = std::min(std::max(u[d], P.Domain[d]), P.Domain[d + 3]);
    }
    auto in = [&](int e)
    {
      const double* b = P.Elements[e].Box;
      return b[0] <= c[0] && c[0] <= b[3] && b[1] <= c[1] && c[1] <= b[4] && b[2] <= c[2] &&
        c[2] <= b[5];
    };
    if (hint >= 0 && hint < static_cast<int>(P.Elements.size()) && in(hint))
    {
      return hint;
    }
    for (int e = 0; e < static_cast<int>(P.Elements.size()); ++e)
    {
      if (in(e))
      {
        return e;
      }
    }
    return -1;
  }

  static bool Solve(const double J[9], const double r[3], double d[3])
  {
    const double det = J[0] * (J[4] * J[8] - J[5] * J[7]) - J[1] * (J[3] * J[8] - J[5] * J[6]) +
      J[2] * (J[3] * J[7] - J[4] * J[6]);
    if (!(std::abs(det) > 0) || !std::isfinite(det))
    {
      return false;
    }
    for (int c = 0; c < 3; ++c)
    {
      double M[9];
      std::copy(J, J + 9, M);
      for (int i = 0; i < 3; ++i)
      {
        M[3 * i + c] = r[i];
      }
      d[c] = (M[0] * (M[4] * M[8] - M[5] * M[7]) - M[1] * (M[3] * M[8] - M[5] * M[6]) +
               M[2] * (M[3] * M[7] - M[4] * M[6])) /
        det;
    }
    return true;
  }

  static void Inverse(const double J[9], double Jinv[9])
  {
    for (int c = 0; c < 3; ++c)
    {
      const double unit[3] = { c == 0 ? 1.0 : 0.0, c == 1 ? 1.0 : 0.0, c == 2 ? 1.0 : 0.0 };
      double col[3] = { 0, 0, 0 };
      Solve(J, unit, col);
      for (int r = 0; r < 3; ++r)
      {
        Jinv[3 * r + c] = col[r];
      }
    }
  }

  // Newton on the patch parameter from the linear approximation at the
  // centre of element e: true when
  // x = x(u) with u inside the domain (e is then u's element).
  bool Invert(const Patch& P, const double x[3], int& e, double u[3]) const
  {
    double size = 0.0;
    for (int d = 0; d < 3; ++d)
    {
      size = std::max(size, P.Domain[d + 3] - P.Domain[d]);
    }
    const Element& E = P.Elements[e];
    for (int d = 0; d < 3; ++d)
    {
      u[d] = 0.5 * (E.Box[d] + E.Box[d + 3]);
      for (int k = 0; k < 3; ++k)
      {
        u[d] += E.CentreJinv[3 * d + k] * (x[k] - E.Centre[k]);
      }
      u[d] = std::min(std::max(u[d], P.Domain[d] - 0.5 * size), P.Domain[d + 3] + 0.5 * size);
    }
    bool converged = false;
    for (int it = 0; it < 50 && !converged; ++it)
    {
      e = Find(P, u, e);
      double xm[3], J[9], d[3];
      this->Map(P, P.Elements[e], u, xm, J);
      const double r[3] = { xm[0] - x[0], xm[1] - x[1], xm[2] - x[2] };
      if (!Solve(J, r, d))
      {
        return false;
      }
      const double step = std::max(std::abs(d[0]), std::max(std::abs(d[1]), std::abs(d[2])));
      const double scale = step > 0.25 * size ? 0.25 * size / step : 1.0;
      for (int k = 0; k < 3; ++k)
      {
        u[k] = std::min(
          std::max(u[k] - scale * d[k], P.Domain[k] - 0.5 * size), P.Domain[k + 3] + 0.5 * size);
      }
      converged = step < 1e-13 * size;
    }
    const double tol = 1e-9 * size;
    if (!converged)
    {
      return false;
    }
    for (int d = 0; d < 3; ++d)
    {
      if (u[d] < P.Domain[d] - tol || u[d] > P.Domain[d + 3] + tol)
      {
        return false;
      }
      u[d] = std::min(std::max(u[d], P.Domain[d]), P.Domain[d + 3]);
    }
    e = Find(P, u, e);
    return true;
  }

  // The field and d f / d x at parameter u of element e.
  void Field(const Patch& P, int e, const double u[3], double* value, double* gradient) const
  {
    double v[16], dv[48], x[3], J[9], Jinv[9];
    this->Interpolant(P, P.Elements[e], u, v, dv);
    this->Map(P, P.Elements[e], u, x, J);
    Inverse(J, Jinv);
    const int g = this->GeometryDim();
    const int n = this->GetNumberOfComponents();
    const double W = this->Rational ? v[g + n] : 1.0;
    for (int c = 0; c < n; ++c)
    {
      value[c] = v[g + c] / W;
      double du[3];
      for (int j = 0; j < 3; ++j)
      {
        const double dW = this->Rational ? dv[3 * (g + n) + j] : 0.0;
        du[j] = (dv[3 * (g + c) + j] - value[c] * dW) / W;
      }
      if (gradient)
      {
        for (int k = 0; k < 3; ++k)
        {
          gradient[3 * c + k] = du[0] * Jinv[k] + du[1] * Jinv[3 + k] + du[2] * Jinv[6 + k];
        }
      }
    }
  }

  bool Rational = false;
  std::vector<Patch> Patches;
  double Bounds[6] = { 0, 0, 0, 0, 0, 0 };
};
}

#endif
