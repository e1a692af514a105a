// SPDX-License-Identifier: BSD-3-Clause
// Tests of the tensor logarithm and exponential of the shared tensor math
// (vtkSplineVizTensorMath::FromEigenSystem, Log, Exp), the basis of the
// log-Euclidean interpolation of vtkTensorLineTracer:
//  - Exp against an independent matrix exponential (Taylor series with
//    scaling and squaring on full 3x3 matrices) for random symmetric tensors
//    with norms up to 4, and det(exp A) = exp(tr A);
//  - Log against R diag(log l) R^T built from known rotations and eigenvalues
//    over six orders of magnitude, and the independent exponential of Log(T)
//    gives T back;
//  - Log(Exp(A)) = A; clamping of small, zero and negative eigenvalues;
//  - the log-Euclidean mean of two tensors has the geometric mean of their
//    determinants (no swelling), unlike the linear mean;
//  - FromEigenSystem rebuilds a tensor from EigenDecomposition; bad input.
#include "vtkSplineVizTensorMath.h"

#include "SplineVizTestUtilities.h"
#include "TensorTestUtilities.h"

#include "vtkMath.h"
#include "vtkNew.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <limits>

namespace TM = vtkSplineVizTensorMath;

namespace
{
using tensortest::Compose;
using tensortest::Random;
using tensortest::RandomRotation;
using Mat = std::array<std::array<double, 3>, 3>;

Mat Full(const double t[6])
{
  Mat m;
  m[0] = { t[0], t[3], t[5] };
  m[1] = { t[3], t[1], t[4] };
  m[2] = { t[5], t[4], t[2] };
  return m;
}

Mat Mul(const Mat& a, const Mat& b)
{
  Mat c{};
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      for (int k = 0; k < 3; ++k)
      {
        c[i][j] += a[i][k] * b[k][j];
      }
    }
  }
  return c;
}

double MaxAbs(const Mat& m)
{
  double r = 0.0;
  for (const auto& row : m)
  {
    for (double v : row)
    {
      r = std::max(r, std::abs(v));
    }
  }
  return r;
}

double MaxDiff(const Mat& a, const Mat& b)
{
  double r = 0.0;
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      r = std::max(r, std::abs(a[i][j] - b[i][j]));
    }
  }
  return r;
}

// Independent matrix exponential: exp(A) = exp(A / 2^s)^(2^s), the inner one
// by its Taylor series to 30 terms.
Mat ExpTaylor(Mat a)
{
  int s = 0;
  while (MaxAbs(a) > 0.25)
  {
    for (auto& row : a)
    {
      for (double& v : row)
      {
        v *= 0.5;
      }
    }
    ++s;
  }
  Mat result{};
  Mat term{};
  for (int i = 0; i < 3; ++i)
  {
    result[i][i] = term[i][i] = 1.0;
  }
  for (int k = 1; k <= 30; ++k)
  {
    term = Mul(term, a);
    for (auto& row : term)
    {
      for (double& v : row)
      {
        v /= k;
      }
    }
    for (int i = 0; i < 3; ++i)
    {
      for (int j = 0; j < 3; ++j)
      {
        result[i][j] += term[i][j];
      }
    }
  }
  for (int i = 0; i < s; ++i)
  {
    result = Mul(result, result);
  }
  return result;
}

double Det(const Mat& m)
{
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
    m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
    m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

}

int TestSplineVizTensorLogExp(int, char*[])
{
  SplineVizTestStatus status;
  Random rnd(7);

  // Exp against the independent series, and det(exp A) = exp(tr A).
  double worstExp = 0.0, worstDet = 0.0;
  for (int n = 0; n < 500; ++n)
  {
    double a[6];
    const double scale = rnd.Next(0.01, 4.0);
    for (double& c : a)
    {
      c = rnd.Next(-1.0, 1.0) * scale / 1.5;
    }
    double e[6], values[3], vectors[3][3];
    TM::Exp(a, e, values, vectors);
    const Mat reference = ExpTaylor(Full(a));
    worstExp = std::max(worstExp, MaxDiff(Full(e), reference) / MaxAbs(reference));
    // (the determinant's rounding error scales with the cube of the entries)
    const double m = MaxAbs(Full(e));
    worstDet =
      std::max(worstDet, std::abs(Det(Full(e)) - std::exp(a[0] + a[1] + a[2])) / (m * m * m));
    // the returned eigen-system is that of exp(A): sorted, and E v = l v
    SV_CHECK(status, values[0] >= values[1] && values[1] >= values[2] && values[2] > 0);
    for (int k = 0; k < 3; ++k)
    {
      double ev[3];
      TM::Multiply(e, vectors[k], ev);
      for (int d = 0; d < 3; ++d)
      {
        SV_CHECK_NEAR(status, ev[d], values[k] * vectors[k][d], 1e-12 * values[0]);
      }
    }
  }
  std::cout << "Exp vs Taylor series: relative " << worstExp << ", det vs exp(trace): " << worstDet
            << std::endl;
  SV_CHECK(status, worstExp < 1e-12);
  SV_CHECK(status, worstDet < 1e-12);

  // Log of known eigen-systems over six orders of magnitude, exp(log T) = T,
  // log(exp A) = A.
  double worstLog = 0.0, worstRoundTrip = 0.0, worstLogExp = 0.0;
  for (int n = 0; n < 500; ++n)
  {
    double r[3][3];
    RandomRotation(rnd, r);
    double l[3], logl[3];
    for (int k = 0; k < 3; ++k)
    {
      l[k] = std::pow(10.0, rnd.Next(-6.0, 0.0)) * 1e-3;
      logl[k] = std::log(l[k]);
    }
    if (n % 5 == 0)
    {
      l[1] = l[0]; // repeated eigenvalues
      logl[1] = logl[0];
    }
    double t[6], expected[6], logT[6];
    Compose(r, l, t);
    Compose(r, logl, expected);
    SV_CHECK(status, TM::Log(t, 1e-30, logT));
    worstLog = std::max(worstLog, MaxDiff(Full(logT), Full(expected)) / MaxAbs(Full(expected)));
    const Mat back = ExpTaylor(Full(logT));
    // relative to the smallest eigenvalue's scale: exp of log reproduces
    // the tensor in every direction
    worstRoundTrip = std::max(worstRoundTrip, MaxDiff(back, Full(t)) / MaxAbs(Full(t)));
    double a[6], expA[6], logExpA[6];
    for (double& c : a)
    {
      c = rnd.Next(-2.0, 2.0);
    }
    TM::Exp(a, expA);
    SV_CHECK(status, TM::Log(expA, 1e-300, logExpA));
    worstLogExp = std::max(worstLogExp, MaxDiff(Full(logExpA), Full(a)));
  }
  std::cout << "Log vs R diag(log l) R^T: relative " << worstLog
            << ", exp(log T) vs T: " << worstRoundTrip << ", log(exp A) vs A: " << worstLogExp
            << std::endl;
  SV_CHECK(status, worstLog < 1e-10);
  SV_CHECK(status, worstRoundTrip < 1e-9);
  SV_CHECK(status, worstLogExp < 1e-10);

  // Clamping: zero and negative eigenvalues are raised to the minimum.
  {
    const double t[6] = { 2.0, 0.0, -1.0, 0.0, 0.0, 0.0 };
    double logT[6];
    SV_CHECK(status, TM::Log(t, 1e-3, logT));
    SV_CHECK_NEAR(status, logT[0], std::log(2.0), 1e-14);
    SV_CHECK_NEAR(status, logT[1], std::log(1e-3), 1e-12);
    SV_CHECK_NEAR(status, logT[2], std::log(1e-3), 1e-12);
    SV_CHECK_NEAR(status, std::abs(logT[3]) + std::abs(logT[4]) + std::abs(logT[5]), 0.0, 1e-14);
  }

  // Log-Euclidean mean: det = geometric mean of the determinants; the
  // linear mean of two differently oriented tensors swells.
  {
    double r0[3][3], r1[3][3];
    RandomRotation(rnd, r0);
    RandomRotation(rnd, r1);
    const double l0[3] = { 1.7e-3, 0.3e-3, 0.2e-3 }, l1[3] = { 1.2e-3, 0.5e-3, 0.1e-3 };
    double t0[6], t1[6], g0[6], g1[6], mean[6], linear[6], logMean[6];
    Compose(r0, l0, t0);
    Compose(r1, l1, t1);
    SV_CHECK(status, TM::Log(t0, 1e-30, g0));
    SV_CHECK(status, TM::Log(t1, 1e-30, g1));
    for (int i = 0; i < 6; ++i)
    {
      logMean[i] = 0.5 * (g0[i] + g1[i]);
      linear[i] = 0.5 * (t0[i] + t1[i]);
    }
    TM::Exp(logMean, mean);
    const double geometric = std::sqrt(Det(Full(t0)) * Det(Full(t1)));
    SV_CHECK_NEAR(status, Det(Full(mean)) / geometric, 1.0, 1e-12);
    SV_CHECK(status, Det(Full(linear)) > 1.05 * geometric);
  }

  // FromEigenSystem rebuilds the tensor from its eigen-decomposition.
  {
    double worst = 0.0;
    for (int n = 0; n < 200; ++n)
    {
      double t[6], values[3], vectors[3][3], back[6];
      for (double& c : t)
      {
        c = rnd.Next(-1.0, 1.0);
      }
      TM::EigenDecomposition(t, values, vectors);
      TM::FromEigenSystem(values, vectors, back);
      for (int i = 0; i < 6; ++i)
      {
        worst = std::max(worst, std::abs(back[i] - t[i]));
      }
    }
    SV_CHECK(status, worst < 1e-14);
  }

  // Bad input.
  {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double bad[6] = { 1.0, nan, 1.0, 0.0, 0.0, 0.0 };
    const double good[6] = { 1.0, 1.0, 1.0, 0.0, 0.0, 0.0 };
    double out[6];
    SV_CHECK(status, !TM::Log(bad, 1e-6, out));
    SV_CHECK(status, !TM::Log(good, 0.0, out));
    SV_CHECK(status, !TM::Log(good, -1.0, out));
    SV_CHECK(status, !TM::Log(good, nan, out));
  }
  return status.Result();
}
