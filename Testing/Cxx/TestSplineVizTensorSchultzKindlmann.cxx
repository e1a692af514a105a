// SPDX-License-Identifier: BSD-3-Clause
// Tests of the Schultz-Kindlmann glyph shapes of the shared tensor math
// (vtkSplineVizTensorMath::SchultzKindlmannSquare / SchultzKindlmannShape,
// from glsl/vtkTensorMathShared.glsl):
//  - the paper's shape square (traceNormalized = false) at its known points
//    (isotropic corners, diag(1,0,0), diag(1,1,0), diag(1,1,-1), diag(1,0,-1));
//  - the glyph shapes against the independent reference of
//    SuperquadricGlyphTestUtilities.h (the whole square with Teem's ten
//    zones and shape table, not the folded five-zone code) on 200,000 random
//    eigenvalue triples of every sign pattern: the same (u, v), exponents
//    and symmetry axis;
//  - definite tensors: exactly Kindlmann's rule with the trace-normalized
//    Westin metrics (KindlmannShape), for any gamma;
//  - T and -T: the same exponents, the symmetry axis e1 <-> e3 (except at
//    Teem's ties); scale invariance;
//  - continuity: along random paths of eigenvalue triples with steps of
//    1e-4 the shape-square point moves by at most a few steps, and the
//    exponents change by O(step) except across a zero eigenvalue, where the
//    glyph is flat and the exponent of its cross-section in the plane of the
//    two non-zero eigenvalues is continuous instead.
#include "vtkSplineVizTensorMath.h"

#include "SplineVizTestUtilities.h"
#include "SuperquadricGlyphTestUtilities.h"
#include "TensorTestUtilities.h"

#include <algorithm>
#include <cmath>
#include <iostream>

namespace TM = vtkSplineVizTensorMath;

namespace
{
void Sort3(double l[3])
{
  std::sort(l, l + 3, [](double a, double b) { return a > b; });
}

/// The exponent of the glyph's cross-section in the plane of e1 and e2 (the
/// plane that remains when l3 = 0): about e1 the u (e3) direction is cut
/// away and the e1-e2 profile has exponent 2/beta; about e3 the cross-section
/// w = 0 has exponent 2/alpha.
double PlaneExponent12(const double abc[3], bool axisE1)
{
  return axisE1 ? abc[1] : abc[0];
}
}

int TestSplineVizTensorSchultzKindlmann(int, char*[])
{
  SplineVizTestStatus status;
  tensortest::Random rnd(23);

  //----------------------------------------------------------------------------
  // The paper's square.
  {
    const double points[][5] = { { 1, 1, 1, 1, 1 }, { -1, -1, -1, 0, 0 }, { 1, 0, 0, 0.5, 1 },
      { 1, 1, 0, 1, 0.5 }, { 1, 1, -1, 1, 0 }, { 1, -1, -1, 0, 1 }, { 1, 0, -1, 0.5, 0.5 },
      { 0, 0, -1, 0.5, 0 }, { 2, 1, 0, 0.75, 0.75 } };
    for (const auto& p : points)
    {
      double uv[2];
      TM::SchultzKindlmannSquare(p, false, uv);
      SV_CHECK_NEAR(status, uv[0], p[3], 1e-15);
      SV_CHECK_NEAR(status, uv[1], p[4], 1e-15);
    }
    double uv[2];
    SV_CHECK(status, TM::SchultzKindlmannSquare(points[1], false, uv));
    SV_CHECK(status, !TM::SchultzKindlmannSquare(points[0], false, uv));
  }

  //----------------------------------------------------------------------------
  // Against the independent reference; Kindlmann's rule for definite
  // tensors; T and -T; scale invariance.
  {
    int mismatches = 0, axisMismatches = 0, kindlmannMismatches = 0, negationMismatches = 0;
    double worst = 0.0, worstKindlmann = 0.0;
    int definite = 0;
    for (int n = 0; n < 200000; ++n)
    {
      double l[3] = { rnd.Next(-1, 1), rnd.Next(-1, 1), rnd.Next(-1, 1) };
      if (n % 5 == 0)
      {
        l[n % 3] = 0.0; // zero eigenvalues
      }
      if (n % 7 == 0)
      {
        l[1] = l[0]; // repeated
      }
      Sort3(l);
      const double gamma = n % 3 == 0 ? 0.0 : (n % 3 == 1 ? 3.0 : rnd.Next(0.5, 10.0));
      const double minRound = 0.2;
      double abc[3], uv[2];
      const bool axisE1 = TM::SchultzKindlmannShape(l, gamma, minRound, abc);
      TM::SchultzKindlmannSquare(l, true, uv);
      const sqtest::SKShape ref = sqtest::SchultzKindlmann(l, gamma, minRound);
      double diff = std::max(std::abs(uv[0] - ref.UV[0]), std::abs(uv[1] - ref.UV[1]));
      for (int k = 0; k < 3; ++k)
      {
        diff = std::max(diff, std::abs(abc[k] - ref.ABC[k]));
      }
      worst = std::max(worst, diff);
      mismatches += diff > 1e-12;
      axisMismatches += axisE1 != ref.AxisE1;

      // definite: Kindlmann's rule
      if (l[2] >= 0.0 && l[0] > 0.0)
      {
        ++definite;
        double cl, cp, cs, a, b;
        TM::WestinMetrics(l, cl, cp, cs);
        const bool linear = TM::KindlmannShape(cl, cp, gamma, minRound, a, b);
        const double d =
          std::max({ std::abs(abc[0] - a), std::abs(abc[1] - b), std::abs(abc[2] - b) });
        worstKindlmann = std::max(worstKindlmann, d);
        kindlmannMismatches += d > 1e-12 || linear != axisE1;
      }

      // -T: reversed and negated eigenvalues, the same glyph about the same
      // eigenvector (e1 of -T is e3 of T); and 7.5 T
      double neg[3] = { -l[2], -l[1], -l[0] };
      double abcNeg[3];
      const bool axisNeg = TM::SchultzKindlmannShape(neg, gamma, minRound, abcNeg);
      double scaled[3] = { 7.5 * l[0], 7.5 * l[1], 7.5 * l[2] };
      double abcScaled[3];
      const bool axisScaled = TM::SchultzKindlmannShape(scaled, gamma, minRound, abcScaled);
      // Teem breaks ties (l2 = 0, the anti-diagonal l1 = -l3, cl = cp) on
      // the two halves of the square differently: there the glyphs of T and
      // -T agree only up to the thickness of a flat glyph or about which of
      // two equal exponents' axes is called the symmetry axis
      const bool tie =
        std::abs(l[1]) < 1e-12 || std::abs(l[0] + l[2]) < 1e-12 || std::abs(uv[0] - uv[1]) < 1e-12;
      double dn = 0.0;
      for (int k = 0; k < 3; ++k)
      {
        dn = std::max(dn, std::abs(abcNeg[k] - abc[k]));
        dn = std::max(dn, std::abs(abcScaled[k] - abc[k]));
      }
      negationMismatches += (!tie && (dn > 1e-12 || axisNeg == axisE1)) || axisScaled != axisE1;
    }
    std::cout << "against the ten-zone reference: worst difference " << worst << ", " << mismatches
              << " value and " << axisMismatches << " axis mismatches; " << definite
              << " definite tensors, worst difference from Kindlmann's rule " << worstKindlmann
              << ", " << kindlmannMismatches << " mismatches; " << negationMismatches
              << " T/-T or scale mismatches" << std::endl;
    SV_CHECK(status, mismatches == 0);
    SV_CHECK(status, axisMismatches == 0);
    SV_CHECK(status, definite > 20000);
    SV_CHECK(status, kindlmannMismatches == 0);
    SV_CHECK(status, negationMismatches == 0);
  }

  //----------------------------------------------------------------------------
  // Continuity along random paths.
  {
    const double step = 1e-4;
    double worstUV = 0.0, worstABC = 0.0, worstFlat = 0.0;
    int flatCrossings = 0, steps = 0;
    for (int path = 0; path < 300; ++path)
    {
      // a random straight path through the unit cube of eigenvalues,
      // normalized so that max |l| = 1 at every point
      double a[3] = { rnd.Next(-1, 1), rnd.Next(-1, 1), rnd.Next(-1, 1) };
      double b[3] = { rnd.Next(-1, 1), rnd.Next(-1, 1), rnd.Next(-1, 1) };
      double prevL[3], prevUV[2], prevABC[3];
      bool prevAxis = false;
      for (int k = 0; k <= 2000; ++k)
      {
        const double s = static_cast<double>(k) / 2000;
        double l[3];
        for (int c = 0; c < 3; ++c)
        {
          l[c] = (1 - s) * a[c] + s * b[c];
        }
        Sort3(l);
        const double m = std::max(std::abs(l[0]), std::abs(l[2]));
        for (double& c : l)
        {
          c /= m;
        }
        double uv[2], abc[3];
        TM::SchultzKindlmannSquare(l, true, uv);
        const bool axis = TM::SchultzKindlmannShape(l, 3.0, 0.05, abc);
        if (k > 0)
        {
          const double dl = std::max(
            { std::abs(l[0] - prevL[0]), std::abs(l[1] - prevL[1]), std::abs(l[2] - prevL[2]) });
          if (dl < step * 10 && dl > 0.0)
          {
            ++steps;
            worstUV = std::max(
              worstUV, std::max(std::abs(uv[0] - prevUV[0]), std::abs(uv[1] - prevUV[1])) / dl);
            const bool crossesZero = (l[2] > 0) != (prevL[2] > 0) || (l[0] > 0) != (prevL[0] > 0);
            if (crossesZero)
            {
              ++flatCrossings;
              // the flat glyph's cross-section in the plane of the non-zero
              // eigenvalues (e1, e2 at l3 = 0; e2, e3 at l1 = 0, the mirror)
              const bool atL3 = (l[2] > 0) != (prevL[2] > 0);
              const double e = atL3 ? PlaneExponent12(abc, axis) : PlaneExponent12(abc, !axis);
              const double ePrev =
                atL3 ? PlaneExponent12(prevABC, prevAxis) : PlaneExponent12(prevABC, !prevAxis);
              worstFlat = std::max(worstFlat, std::abs(e - ePrev) / dl);
            }
            else if (axis == prevAxis)
            {
              for (int c = 0; c < 3; ++c)
              {
                worstABC = std::max(worstABC, std::abs(abc[c] - prevABC[c]) / dl);
              }
            }
          }
        }
        std::copy(l, l + 3, prevL);
        std::copy(uv, uv + 2, prevUV);
        std::copy(abc, abc + 3, prevABC);
        prevAxis = axis;
      }
    }
    std::cout << "continuity over " << steps << " steps: |d(u,v)| / |dl| <= " << worstUV
              << ", |d(abc)| / |dl| <= " << worstABC << " (same axis); " << flatCrossings
              << " crossings of a zero eigenvalue, |d exponent| / |dl| <= " << worstFlat
              << std::endl;
    SV_CHECK(status, steps > 100000);
    SV_CHECK_MSG(status, worstUV < 5.0, "the shape-square point jumps");
    SV_CHECK_MSG(status, worstABC < 200.0, "the exponents jump");
    SV_CHECK(status, flatCrossings > 50);
    SV_CHECK_MSG(status, worstFlat < 200.0, "the flat glyphs' cross-sections jump");
  }
  return status.Result();
}
