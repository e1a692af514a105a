// SPDX-License-Identifier: BSD-3-Clause
// Tests of the shared tensor math (vtkSplineVizTensorMath.h):
//  - every component layout converts a known tensor to the canonical order,
//    NaN/inf components and unknown layouts are rejected;
//  - the eigen-decomposition against vtkMath::Jacobi (independent code) on
//    random symmetric tensors over 12 orders of magnitude, and against exact
//    eigen-systems R diag(l) R^T with repeated, nearly repeated, zero and
//    negative eigenvalues: values, residuals |T e - l e|, orthonormality,
//    handedness, order, and the eigenspaces of repeated eigenvalues;
//  - FA, MD and the Westin metrics against their textbook formulas and
//    known tensors; the sign policies; Kindlmann's shape rule against
//    hand-computed values (both axis cases, continuity at cl == cp, clamping).
#include "vtkSplineVizTensorMath.h"

#include "SplineVizTestUtilities.h"
#include "TensorTestUtilities.h"

#include "vtkFloatArray.h"
#include "vtkMath.h"
#include "vtkNew.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace TM = vtkSplineVizTensorMath;

namespace
{
using tensortest::Compose;
using tensortest::Random;
using tensortest::RandomRotation;
using Vec = std::array<double, 3>;

double Dot(const double a[3], const double b[3])
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/// vtkMath::Jacobi on the full matrix: values descending, vectors as rows.
void Jacobi(const double t[6], double w[3], double v[3][3])
{
  double m[3][3];
  TM::ToMatrix(t, m);
  double a0[3], a1[3], a2[3], v0[3], v1[3], v2[3];
  for (int j = 0; j < 3; ++j)
  {
    a0[j] = m[0][j];
    a1[j] = m[1][j];
    a2[j] = m[2][j];
  }
  double* a[3] = { a0, a1, a2 };
  double* vv[3] = { v0, v1, v2 };
  vtkMath::Jacobi(a, w, vv);
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      v[i][j] = vv[j][i]; // Jacobi returns eigenvectors as columns
    }
  }
}

/// Structural checks of one decomposition: order, residual, orthonormality,
/// handedness. Returns the worst residual relative to `scale`.
void CheckDecomposition(SplineVizTestStatus& status, const double t[6], const double w[3],
  const double v[3][3], double scale, double tol, const char* what)
{
  SV_CHECK_MSG(
    status, w[0] >= w[1] && w[1] >= w[2], what << ": order " << w[0] << " " << w[1] << " " << w[2]);
  double worst = 0.0;
  for (int i = 0; i < 3; ++i)
  {
    double tv[3];
    TM::Multiply(t, v[i], tv);
    for (int c = 0; c < 3; ++c)
    {
      worst = std::max(worst, std::abs(tv[c] - w[i] * v[i][c]) / scale);
    }
    for (int j = 0; j < 3; ++j)
    {
      const double d = Dot(v[i], v[j]) - (i == j ? 1.0 : 0.0);
      SV_CHECK_MSG(status, std::abs(d) < 1e-12, what << ": orthonormality " << d);
    }
  }
  SV_CHECK_MSG(status, worst < tol, what << ": residual " << worst);
  double c[3];
  vtkMath::Cross(v[0], v[1], c);
  SV_CHECK_MSG(status, Dot(c, v[2]) > 1.0 - 1e-12, what << ": not right-handed");
}
}

int TestSplineVizTensorMath(int, char*[])
{
  SplineVizTestStatus status;

  //----------------------------------------------------------------------------
  // Layouts: one tensor written in every layout.
  {
    const double xx = 1.5, yy = -2.25, zz = 3.125, xy = 0.5, yz = -0.75, xz = 0.875;
    const double full[9] = { xx, xy, xz, xy, yy, yz, xz, yz, zz };
    const double vtk[6] = { xx, yy, zz, xy, yz, xz };
    const double lower[6] = { xx, xy, yy, xz, yz, zz };
    const double upper[6] = { xx, xy, xz, yy, yz, zz };
    const double teem[7] = { 0.75, xx, xy, xz, yy, yz, zz };
    const double* inputs[5] = { full, vtk, lower, upper, teem };
    const int layouts[5] = { TM::FULL_9, TM::SYMMETRIC_VTK, TM::SYMMETRIC_LOWER,
      TM::SYMMETRIC_UPPER, TM::TEEM_7 };
    const int comps[5] = { 9, 6, 6, 6, 7 };
    for (int k = 0; k < 5; ++k)
    {
      double t[6];
      double conf = -1.0;
      SV_CHECK(status, TM::GetNumberOfComponents(layouts[k]) == comps[k]);
      SV_CHECK(status, TM::ToSymmetric(layouts[k], inputs[k], t, &conf));
      for (int i = 0; i < 6; ++i)
      {
        SV_CHECK_MSG(status, t[i] == vtk[i], "layout " << k << " component " << i);
      }
      SV_CHECK(status, conf == (layouts[k] == TM::TEEM_7 ? 0.75 : 1.0));
      SV_CHECK(status, std::string(TM::GetLayoutName(layouts[k])) != "unknown");
    }
    // The tools' names: NIfTI's SYMMATRIX and DIPY's order is the lower
    // triangle, FSL dtifit's (Dxx Dxy Dxz Dyy Dyz Dzz) the upper one; the
    // names shown in menus and messages say so (an earlier version called
    // FSL's order lower-triangular).
    SV_CHECK(status, TM::SYMMETRIC_NIFTI == TM::SYMMETRIC_LOWER);
    SV_CHECK(status, TM::SYMMETRIC_FSL == TM::SYMMETRIC_UPPER);
    const std::string lowerName = TM::GetLayoutName(TM::SYMMETRIC_LOWER);
    const std::string upperName = TM::GetLayoutName(TM::SYMMETRIC_UPPER);
    SV_CHECK(status, lowerName.find("NIfTI") != std::string::npos);
    SV_CHECK(status, lowerName.find("DIPY") != std::string::npos);
    SV_CHECK(status, lowerName.find("FSL") == std::string::npos);
    SV_CHECK(status, upperName.find("FSL") != std::string::npos);
    {
      const double dtifit[6] = { xx, xy, xz, yy, yz, zz }; // FSL's documented order
      double t[6];
      SV_CHECK(status, TM::ToSymmetric(TM::SYMMETRIC_FSL, dtifit, t));
      for (int i = 0; i < 6; ++i)
      {
        SV_CHECK_MSG(status, t[i] == vtk[i], "FSL order, component " << i);
      }
    }
    // A non-symmetric 9-component tensor is symmetrized.
    const double ns[9] = { 1, 2, 3, 4, 5, 6, 7, 8, 9 };
    double t[6];
    SV_CHECK(status, TM::ToSymmetric(TM::FULL_9, ns, t));
    SV_CHECK(status, t[0] == 1 && t[1] == 5 && t[2] == 9 && t[3] == 3 && t[4] == 7 && t[5] == 5);
    // Bad components and layouts.
    double bad[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
    bad[4] = std::numeric_limits<double>::quiet_NaN();
    SV_CHECK(status, !TM::ToSymmetric(TM::FULL_9, bad, t));
    bad[4] = std::numeric_limits<double>::infinity();
    SV_CHECK(status, !TM::ToSymmetric(TM::FULL_9, bad, t));
    SV_CHECK(status, !TM::ToSymmetric(17, vtk, t));
    SV_CHECK(status, TM::GetNumberOfComponents(17) == 0);
    SV_CHECK(status,
      TM::GuessLayout(9) == TM::FULL_9 && TM::GuessLayout(6) == TM::SYMMETRIC_VTK &&
        TM::GuessLayout(7) == TM::TEEM_7 && TM::GuessLayout(3) == -1);
    SV_CHECK(status, TM::ResolveLayout(TM::SYMMETRIC_LOWER, 9) == TM::FULL_9);
    SV_CHECK(status, TM::ResolveLayout(TM::SYMMETRIC_LOWER, 7) == TM::TEEM_7);
    SV_CHECK(status, TM::ResolveLayout(TM::SYMMETRIC_LOWER, 6) == TM::SYMMETRIC_LOWER);
    SV_CHECK(status, TM::ResolveLayout(TM::SYMMETRIC_UPPER, 6) == TM::SYMMETRIC_UPPER);
    SV_CHECK(status, TM::ResolveLayout(-1, 6) == TM::SYMMETRIC_VTK);
    SV_CHECK(status, TM::ResolveLayout(TM::FULL_9, 6) == -1);
    SV_CHECK(status, TM::ResolveLayout(TM::TEEM_7, 6) == -1);
    SV_CHECK(status, TM::ResolveLayout(TM::SYMMETRIC_VTK, 3) == -1);
    // Reading from a float array, DIPY order.
    vtkNew<vtkFloatArray> arr;
    arr->SetNumberOfComponents(6);
    arr->InsertNextTuple(lower);
    SV_CHECK(status, TM::ReadSymmetric(arr, 0, TM::SYMMETRIC_LOWER, t));
    SV_CHECK_NEAR(status, t[5], xz, 1e-7);
    SV_CHECK_NEAR(status, t[1], yy, 1e-7);
    SV_CHECK(status, !TM::ReadSymmetric(arr, 0, TM::FULL_9, t)); // wrong component count
    // Multiply and ToMatrix agree.
    double m[3][3];
    TM::ToMatrix(vtk, m);
    const double x[3] = { 0.3, -1.1, 2.0 };
    double y[3];
    TM::Multiply(vtk, x, y);
    for (int i = 0; i < 3; ++i)
    {
      SV_CHECK_NEAR(status, y[i], m[i][0] * x[0] + m[i][1] * x[1] + m[i][2] * x[2], 1e-14);
      SV_CHECK(status, m[i][(i + 1) % 3] == m[(i + 1) % 3][i]);
    }
  }

  //----------------------------------------------------------------------------
  // Random symmetric tensors against vtkMath::Jacobi.
  {
    Random rnd(7);
    int compared = 0;
    double worstValue = 0.0;
    for (int n = 0; n < 20000; ++n)
    {
      const double scale = std::pow(10.0, rnd.Next(-6.0, 6.0));
      double t[6];
      for (double& c : t)
      {
        c = scale * rnd.Next(-1.0, 1.0);
      }
      double w[3], v[3][3], wj[3], vj[3][3];
      TM::EigenDecomposition(t, w, v);
      Jacobi(t, wj, vj);
      const double big = std::max(std::abs(wj[0]), std::abs(wj[2]));
      CheckDecomposition(status, t, w, v, big, 1e-13, "random");
      for (int i = 0; i < 3; ++i)
      {
        worstValue = std::max(worstValue, std::abs(w[i] - wj[i]) / big);
      }
      // Eigenvectors of well-separated eigenvalues agree with Jacobi's up to
      // sign, within ~eps / relative gap.
      for (int i = 0; i < 3; ++i)
      {
        double gap = std::numeric_limits<double>::max();
        for (int j = 0; j < 3; ++j)
        {
          if (j != i)
          {
            gap = std::min(gap, std::abs(wj[i] - wj[j]) / big);
          }
        }
        if (gap > 1e-6)
        {
          double c[3];
          vtkMath::Cross(v[i], vj[i], c);
          const double sinAngle = vtkMath::Norm(c);
          SV_CHECK_MSG(status, sinAngle < 1e-14 / gap + 1e-13,
            "eigenvector " << i << " differs from Jacobi's: sin " << sinAngle << ", gap " << gap);
          ++compared;
        }
      }
    }
    std::cout << "random: worst relative eigenvalue difference to Jacobi " << worstValue << ", "
              << compared << " eigenvectors compared" << std::endl;
    SV_CHECK_MSG(status, worstValue < 1e-13, "eigenvalues vs Jacobi " << worstValue);
    SV_CHECK(status, compared > 50000);
  }

  //----------------------------------------------------------------------------
  // Exact eigen-systems with repeated, nearly repeated, zero and negative
  // eigenvalues (including axis-aligned and permuted diagonal tensors).
  {
    const double spectra[][3] = { { 2, 1, 1 }, { 1, 1, -3 }, { 5, 5, 5 }, { 0, 0, 1 },
      { 0, 0, 0.5 }, { 1, 0, 0 }, { -1, -1, 2 }, { 1, 1 + 1e-9, 3 }, { 1, 1 + 1e-12, 1 - 1e-12 },
      { 1e-3, 2e-4, 2e-4 }, { 1.7e-3, 3e-4, 2.9e-4 }, { -2, 0, 2 }, { 3, 3, 3 + 1e-7 },
      { 1, 2, 3 } };
    Random rnd(11);
    for (const auto& spectrum : spectra)
    {
      for (int rot = 0; rot < 200; ++rot)
      {
        double r[3][3];
        if (rot == 0)
        {
          vtkMath::Identity3x3(r);
        }
        else if (rot == 1)
        {
          // a permutation: diagonal tensor in another order
          const double p[3][3] = { { 0, 1, 0 }, { 0, 0, 1 }, { 1, 0, 0 } };
          std::copy(&p[0][0], &p[0][0] + 9, &r[0][0]);
        }
        else
        {
          RandomRotation(rnd, r);
        }
        double t[6];
        Compose(r, spectrum, t);
        double exact[3] = { spectrum[0], spectrum[1], spectrum[2] };
        std::sort(exact, exact + 3, [](double a, double b) { return a > b; });
        const double big = std::max({ std::abs(exact[0]), std::abs(exact[2]), 1e-300 });
        double w[3], v[3][3];
        TM::EigenDecomposition(t, w, v);
        CheckDecomposition(status, t, w, v, big, 1e-13, "exact spectrum");
        for (int i = 0; i < 3; ++i)
        {
          SV_CHECK_MSG(status, std::abs(w[i] - exact[i]) < 1e-13 * big,
            "eigenvalue " << i << ": " << w[i] << " vs " << exact[i]);
        }
        // Eigenspaces: each returned vector lies in the eigenspace of its
        // value, i.e. is orthogonal to the exact eigenvectors of clearly
        // different eigenvalues.
        for (int i = 0; i < 3; ++i)
        {
          for (int k = 0; k < 3; ++k)
          {
            const double lk = spectrum[k];
            const double gap = std::abs(lk - w[i]) / big;
            if (gap > 1e-4)
            {
              const double col[3] = { r[0][k], r[1][k], r[2][k] };
              SV_CHECK_MSG(status, std::abs(Dot(v[i], col)) < 1e-13 / gap + 1e-13,
                "vector " << i << " leaks into the eigenspace of " << lk);
            }
          }
        }
        // Jacobi agrees on the values.
        double wj[3], vj[3][3];
        Jacobi(t, wj, vj);
        for (int i = 0; i < 3; ++i)
        {
          SV_CHECK_MSG(status, std::abs(w[i] - wj[i]) < 1e-13 * big, "vs Jacobi");
        }
      }
    }
    // The zero tensor.
    const double zero[6] = { 0, 0, 0, 0, 0, 0 };
    double w[3], v[3][3];
    TM::EigenDecomposition(zero, w, v);
    SV_CHECK(status, w[0] == 0 && w[1] == 0 && w[2] == 0);
    CheckDecomposition(status, zero, w, v, 1.0, 1e-15, "zero");
  }

  //----------------------------------------------------------------------------
  // FA, MD, Westin metrics.
  {
    const double lin[3] = { 1, 0, 0 }, pla[3] = { 1, 1, 0 }, sph[3] = { 2, 2, 2 };
    double cl, cp, cs;
    SV_CHECK_NEAR(status, TM::FractionalAnisotropy(lin), 1.0, 1e-15);
    SV_CHECK_NEAR(status, TM::FractionalAnisotropy(pla), std::sqrt(0.5), 1e-15);
    SV_CHECK_NEAR(status, TM::FractionalAnisotropy(sph), 0.0, 1e-15);
    SV_CHECK_NEAR(status, TM::MeanDiffusivity(sph), 2.0, 1e-15);
    TM::WestinMetrics(lin, cl, cp, cs);
    SV_CHECK(status, cl == 1.0 && cp == 0.0 && cs == 0.0);
    TM::WestinMetrics(pla, cl, cp, cs);
    SV_CHECK(status, cl == 0.0 && cp == 1.0 && cs == 0.0);
    TM::WestinMetrics(sph, cl, cp, cs);
    SV_CHECK(status, cl == 0.0 && cp == 0.0 && cs == 1.0);
    const double zero[3] = { 0, 0, 0 }, negTrace[3] = { 1, -1, -2 };
    TM::WestinMetrics(zero, cl, cp, cs);
    SV_CHECK(status, cl == 0.0 && cp == 0.0 && cs == 0.0);
    TM::WestinMetrics(negTrace, cl, cp, cs);
    SV_CHECK(status, cl == 0.0 && cp == 0.0 && cs == 0.0);
    SV_CHECK(status, TM::FractionalAnisotropy(zero) == 0.0);
    // Random positive tensors: textbook formulas written out here.
    Random rnd(3);
    for (int n = 0; n < 1000; ++n)
    {
      double l[3] = { rnd.Next(0, 2), rnd.Next(0, 2), rnd.Next(0, 2) };
      std::sort(l, l + 3, [](double a, double b) { return a > b; });
      const double md = (l[0] + l[1] + l[2]) / 3.0;
      const double fa = std::sqrt(1.5) *
        std::sqrt(
          (l[0] - md) * (l[0] - md) + (l[1] - md) * (l[1] - md) + (l[2] - md) * (l[2] - md)) /
        std::sqrt(l[0] * l[0] + l[1] * l[1] + l[2] * l[2]);
      SV_CHECK_NEAR(status, TM::FractionalAnisotropy(l), fa, 1e-14);
      SV_CHECK_NEAR(status, TM::MeanDiffusivity(l), md, 1e-15);
      TM::WestinMetrics(l, cl, cp, cs);
      const double s = l[0] + l[1] + l[2];
      SV_CHECK_NEAR(status, cl, (l[0] - l[1]) / s, 1e-15);
      SV_CHECK_NEAR(status, cp, 2.0 * (l[1] - l[2]) / s, 1e-15);
      SV_CHECK_NEAR(status, cs, 3.0 * l[2] / s, 1e-15);
      SV_CHECK_NEAR(status, cl + cp + cs, 1.0, 1e-14);
      SV_CHECK(status, cl >= 0 && cp >= 0 && cs >= 0);
    }
  }

  //----------------------------------------------------------------------------
  // Sign policies.
  {
    Random rnd(5);
    double r[3][3];
    RandomRotation(rnd, r);
    const double spectrum[3] = { 1.0, -3.0, 0.5 };
    double t[6];
    Compose(r, spectrum, t);
    double w[3], v[3][3];
    TM::EigenDecomposition(t, w, v);
    double ws[3] = { w[0], w[1], w[2] };
    double vs[3][3];
    std::copy(&v[0][0], &v[0][0] + 9, &vs[0][0]);
    SV_CHECK(status, !TM::ApplySignPolicy(TM::SIGN_SKIP, ws, vs));
    SV_CHECK(status, TM::ApplySignPolicy(TM::SIGN_ABSOLUTE, w, v));
    SV_CHECK_NEAR(status, w[0], 3.0, 1e-13);
    SV_CHECK_NEAR(status, w[1], 1.0, 1e-13);
    SV_CHECK_NEAR(status, w[2], 0.5, 1e-13);
    // The vectors moved with their values: T e = +-|l| e.
    const double sign[3] = { -1.0, 1.0, 1.0 };
    double worst = 0.0;
    for (int i = 0; i < 3; ++i)
    {
      double tv[3];
      TM::Multiply(t, v[i], tv);
      for (int c = 0; c < 3; ++c)
      {
        worst = std::max(worst, std::abs(tv[c] - sign[i] * w[i] * v[i][c]));
      }
    }
    SV_CHECK_MSG(status, worst < 1e-13, "absolute policy residual " << worst);
    double c[3];
    vtkMath::Cross(v[0], v[1], c);
    SV_CHECK(status, Dot(c, v[2]) > 1.0 - 1e-12);
    // Rounding-level negative values are accepted and set to zero.
    double wz[3] = { 1.0, 0.5, -1e-9 };
    double vz[3][3] = { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
    SV_CHECK(status, TM::ApplySignPolicy(TM::SIGN_SKIP, wz, vz) && wz[2] == 0.0);
    double wn[3] = { 1.0, 0.5, -1e-3 };
    SV_CHECK(status, !TM::ApplySignPolicy(TM::SIGN_SKIP, wn, vz));
  }

  //----------------------------------------------------------------------------
  // Kindlmann's rule, hand-computed.
  {
    double a, b;
    // linear: cl = 0.6 > cp = 0.2, gamma 3: alpha = 0.8^3, beta = 0.4^3
    SV_CHECK(status, TM::KindlmannShape(0.6, 0.2, 3.0, 0.01, a, b));
    SV_CHECK_NEAR(status, a, 0.512, 1e-14);
    SV_CHECK_NEAR(status, b, 0.064, 1e-14);
    // planar: cl = 0.2 < cp = 0.6: alpha = (1 - cl)^3, beta = (1 - cp)^3
    SV_CHECK(status, !TM::KindlmannShape(0.2, 0.6, 3.0, 0.01, a, b));
    SV_CHECK_NEAR(status, a, 0.512, 1e-14);
    SV_CHECK_NEAR(status, b, 0.064, 1e-14);
    // a different pair, so that swapping cl/cp inside a case would show
    SV_CHECK(status, TM::KindlmannShape(0.5, 0.3, 2.0, 0.01, a, b));
    SV_CHECK_NEAR(status, a, 0.49, 1e-14);
    SV_CHECK_NEAR(status, b, 0.25, 1e-14);
    SV_CHECK(status, !TM::KindlmannShape(0.1, 0.7, 1.0, 0.01, a, b));
    SV_CHECK_NEAR(status, a, 0.9, 1e-14);
    SV_CHECK_NEAR(status, b, 0.3, 1e-14);
    // clamping to the minimum roundness
    SV_CHECK(status, TM::KindlmannShape(0.6, 0.2, 3.0, 0.2, a, b));
    SV_CHECK_NEAR(status, a, 0.512, 1e-14);
    SV_CHECK_NEAR(status, b, 0.2, 1e-14);
    // gamma 0: ellipsoid; cl == cp: alpha == beta (continuity of the switch)
    TM::KindlmannShape(0.9, 0.05, 0.0, 0.2, a, b);
    SV_CHECK(status, a == 1.0 && b == 1.0);
    double a1, b1, a2, b2;
    const bool l1 = TM::KindlmannShape(0.3 + 1e-9, 0.3, 3.0, 0.01, a1, b1);
    const bool l2 = TM::KindlmannShape(0.3 - 1e-9, 0.3, 3.0, 0.01, a2, b2);
    SV_CHECK(status, l1 && !l2);
    SV_CHECK_NEAR(status, a1, b1, 1e-8);
    SV_CHECK_NEAR(status, a2, b2, 1e-8);
    SV_CHECK_NEAR(status, a1, a2, 1e-8);
    // out-of-range metrics are clamped to [0, 1]
    TM::KindlmannShape(1.5, -0.5, 3.0, 0.01, a, b);
    SV_CHECK_NEAR(status, a, 1.0, 1e-14);
    SV_CHECK_NEAR(status, b, 0.01, 1e-14);
  }

  return status.Result();
}
