// SPDX-License-Identifier: BSD-3-Clause
// Tests of vtkSplineVizTensorMath::PrincipalEigen (eigenvalues and principal
// eigenvector only, for fiber tracking):
//  - against vtkMath::Jacobi (independent code) on random symmetric tensors
//    over twelve orders of magnitude, prolate, oblate and indefinite: the
//    eigenvalues to 1e-13 of the largest |eigenvalue|, e1 parallel to
//    Jacobi's (within Jacobi's accuracy / gap^2), and an eigenvector to
//    rounding: |T e1 - l1 e1| < 1e-13 |l|max;
//  - against exact eigen-systems R diag(l) R^T with repeated and nearly
//    repeated eigenvalues (the values exact to rounding, e1 in the right
//    eigenspace), zero and isotropic tensors;
//  - the same values as EigenDecomposition.
#include "vtkSplineVizTensorMath.h"

#include "SplineVizTestUtilities.h"
#include "TensorTestUtilities.h"

#include "vtkMath.h"
#include "vtkNew.h"

#include <algorithm>
#include <cmath>
#include <iostream>

namespace TM = vtkSplineVizTensorMath;

namespace
{
using tensortest::Compose;
using tensortest::Random;
using tensortest::RandomRotation;

double Residual(const double t[6], double l, const double e[3])
{
  double te[3];
  TM::Multiply(t, e, te);
  double r = 0.0;
  for (int d = 0; d < 3; ++d)
  {
    r = std::max(r, std::abs(te[d] - l * e[d]));
  }
  return r;
}
}

int TestSplineVizTensorPrincipalEigen(int, char*[])
{
  SplineVizTestStatus status;
  Random rnd(11);

  // Random symmetric tensors against vtkMath::Jacobi.
  double worstValue = 0.0, worstVector = 0.0, worstResidual = 0.0, worstFull = 0.0;
  for (int n = 0; n < 20000; ++n)
  {
    const double scale = std::pow(10.0, rnd.Next(-6.0, 6.0));
    double t[6];
    for (double& c : t)
    {
      c = rnd.Next(-1.0, 1.0) * scale;
    }
    double l[3], e1[3];
    TM::PrincipalEigen(t, l, e1);
    double m[3][3];
    TM::ToMatrix(t, m);
    double w[3], v[3][3];
    double* mp[3] = { m[0], m[1], m[2] };
    double* vp[3] = { v[0], v[1], v[2] };
    vtkMath::Jacobi(mp, w, vp);
    const double big = std::max(std::abs(w[0]), std::abs(w[2]));
    for (int k = 0; k < 3; ++k)
    {
      worstValue = std::max(worstValue, std::abs(l[k] - w[k]) / big);
    }
    SV_CHECK(status, l[0] >= l[1] && l[1] >= l[2]);
    const double gap = (w[0] - w[1]) / big;
    const double je[3] = { v[0][0], v[1][0], v[2][0] };
    const double dot = std::abs(e1[0] * je[0] + e1[1] * je[1] + e1[2] * je[2]);
    // (vtkMath::Jacobi's vectors are accurate to ~1e-8 only: the residual
    // below is the sharp check of ours)
    worstVector = std::max(worstVector, (1.0 - dot) * gap * gap);
    worstResidual = std::max(worstResidual, Residual(t, l[0], e1) / big);
    SV_CHECK_NEAR(status, e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2], 1.0, 1e-14);
    double lf[3], ef[3][3];
    TM::EigenDecomposition(t, lf, ef);
    for (int k = 0; k < 3; ++k)
    {
      worstFull = std::max(worstFull, std::abs(l[k] - lf[k]) / big);
    }
  }
  std::cout << "random tensors vs Jacobi: values " << worstValue << ", (1 - |cos|) gap^2 "
            << worstVector << ", residual " << worstResidual << "; values vs EigenDecomposition "
            << worstFull << std::endl;
  SV_CHECK(status, worstValue < 1e-13);
  SV_CHECK(status, worstVector < 1e-13);
  SV_CHECK(status, worstResidual < 1e-13);
  SV_CHECK(status, worstFull < 1e-13);

  // Known eigen-systems: repeated and nearly repeated eigenvalues, prolate,
  // oblate, indefinite.
  const double cases[][3] = { { 3.0, 1.0, 1.0 }, { 3.0, 3.0, 1.0 }, { 2.0, 1.0, 0.5 },
    { 1.0, 1.0 - 1e-9, 0.2 }, { 1.0, 0.2 + 1e-12, 0.2 }, { 1.0, -0.5, -2.0 }, { -1.0, -2.0, -3.0 },
    { 1.7e-3, 0.3e-3, 0.3e-3 }, { 0.0, 0.0, -1.0 } };
  double worstKnown = 0.0, worstKnownFull = 0.0;
  for (const auto& c : cases)
  {
    for (int rep = 0; rep < 50; ++rep)
    {
      double r[3][3], t[6], l[3], e1[3];
      RandomRotation(rnd, r);
      Compose(r, c, t);
      TM::PrincipalEigen(t, l, e1);
      const double big = std::max(std::abs(c[0]), std::abs(c[2]));
      double lf[3], ef[3][3];
      TM::EigenDecomposition(t, lf, ef);
      for (int k = 0; k < 3; ++k)
      {
        worstKnown = std::max(worstKnown, std::abs(l[k] - c[k]) / big);
        worstKnownFull = std::max(worstKnownFull, std::abs(lf[k] - c[k]) / big);
      }
      if (c[0] - c[1] > 1e-6 * big)
      {
        // e1 is the first column of r (up to sign)
        const double dot = std::abs(e1[0] * r[0][0] + e1[1] * r[1][0] + e1[2] * r[2][0]);
        SV_CHECK_NEAR(status, dot, 1.0, 1e-12);
      }
      else
      {
        // repeated l1: e1 in the span of the first two columns
        const double d3 = e1[0] * r[0][2] + e1[1] * r[1][2] + e1[2] * r[2][2];
        SV_CHECK_NEAR(status, d3, 0.0, 1e-6);
      }
    }
  }
  std::cout << "known eigen-systems: largest value error " << worstKnown
            << " (EigenDecomposition: " << worstKnownFull << ")" << std::endl;
  SV_CHECK(status, worstKnown < 1e-13);

  // Zero and isotropic tensors.
  {
    const double zero[6] = { 0, 0, 0, 0, 0, 0 }, iso[6] = { 2, 2, 2, 0, 0, 0 };
    double l[3], e1[3];
    TM::PrincipalEigen(zero, l, e1);
    SV_CHECK(status, l[0] == 0.0 && l[1] == 0.0 && l[2] == 0.0);
    SV_CHECK(status, e1[0] == 1.0 && e1[1] == 0.0 && e1[2] == 0.0);
    TM::PrincipalEigen(iso, l, e1);
    SV_CHECK_NEAR(status, l[0], 2.0, 1e-15);
    SV_CHECK_NEAR(status, l[2], 2.0, 1e-15);
  }
  return status.Result();
}
