// SPDX-License-Identifier: BSD-3-Clause
// lrtest::TruncatedPowerBSpline, the univariate B-spline of the tests'
// brute-force LR-spline references (BruteForce, PhysicalField): the
// Curry-Schoenberg divided difference of truncated powers, in double-double,
// a different algorithm from the production Cox-de Boor recurrence
// (vtkLRSplinePatch::BSplineValue).
// (a) closed forms: the degree-0 indicator of [a, b) (of (a, b] from the
//     left), hat functions (also with a double knot), the uniform cubic
//     B-spline (1/6, 2/3, 1/6 at its inner knots, its four cubic pieces
//     between), and the Bernstein polynomials C(p, i) s^i (1 - s)^(p - i) of
//     the knots a^(p+1-i) b^(i+1), degrees 0 to 8, at the ends from both sides;
// (b) partition of unity of all B-splines of clamped knot vectors (interior
//     multiplicities up to p + 1), at random points, every knot and the upper
//     end from the left; the values are >= 0 (within their error bounds: an
//     exact 0 inside the support may come out as -1e-27) and exactly 0
//     outside their supports;
// (c) agreement with lrtest::CoxDeBoor and with the production BSplineValue
//     (two independent algorithms) on random knot vectors of degrees 0 to 7
//     with multiplicities up to p + 1, at every knot from both sides and at
//     random points inside and outside the support: well separated knots and
//     graded ones (gaps down to 1e-3 of the unit, the few values the guard
//     refuses skipped); the difference is Cox-de Boor's own rounding, which
//     grows with the degree (the double-double value is within half an ulp
//     of 1 of the exact one: checked offline against exact rational
//     arithmetic), largest 1.0e-15 here and 1.9e-15 (degree 7; 1.0e-15 up to
//     degree 5) in 46 million values of the same generator offline: held to
//     4e-15, twice that;
// (d) negative controls against the production evaluation, which the same
//     tolerance must reject: the degree one lower, the knots shifted by one
//     (the neighbouring B-spline), the other one-sided limit at the knots, and
//     one knot moved by 1e-12 of the support;
// (e) the guard: clustered knots of a high degree (the divided differences
//     cancel beyond the double-double precision) throw std::runtime_error,
//     decreasing or non-finite knots std::invalid_argument; the error bound
//     is printed for (b) and (c).
#include "vtkLRSplinePatch.h"

#include "LRSplineTestUtilities.h"
#include "SplineVizTestUtilities.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <stdexcept>
#include <utility>
#include <vector>

namespace
{
// A random knot vector of degree p (p + 2 knots) from `first`: distinct
// breakpoints with gaps in [minGap, 1] (log-uniform when graded), each
// repeated 1 to p + 1 times.
std::vector<double> RandomKnots(std::mt19937& rng, int p, double first, double minGap, bool graded)
{
  std::uniform_real_distribution<double> U(0.0, 1.0);
  std::vector<double> t;
  double x = first;
  while (static_cast<int>(t.size()) < p + 2)
  {
    const bool repeated = U(rng) < 0.5;
    const int m = std::min(
      p + 2 - static_cast<int>(t.size()), repeated ? 1 + static_cast<int>(U(rng) * (p + 1)) : 1);
    t.insert(t.end(), m, x);
    x += graded ? std::pow(minGap, U(rng)) : minGap + (1.0 - minGap) * U(rng);
  }
  return t; // multiplicities are at most p + 1: t_0 < t_p+1
}

// Evaluation points of a knot vector: every knot (from both sides) and random
// points in and around [t_0, t_p+1] (from the right).
std::vector<std::pair<double, bool>> Points(std::mt19937& rng, const std::vector<double>& t)
{
  std::uniform_real_distribution<double> U(0.0, 1.0);
  std::vector<std::pair<double, bool>> points;
  for (double k : t)
  {
    points.emplace_back(k, false);
    points.emplace_back(k, true);
  }
  const double a = t.front(), L = t.back() - t.front();
  for (int i = 0; i < 12; ++i)
  {
    points.emplace_back(a + L * (1.4 * U(rng) - 0.2), false);
  }
  return points;
}

double Production(const std::vector<double>& t, double x, bool fromLeft)
{
  return vtkLRSplinePatch::BSplineValue(t.data(), static_cast<int>(t.size()) - 1, x, fromLeft);
}

double Reference(const std::vector<double>& t, double x, bool fromLeft)
{
  return lrtest::TruncatedPowerBSpline(t, x, fromLeft);
}

// The largest |variant - production| over random knot vectors (degrees
// `minDegree` to 7), well separated knots, at every knot from both sides and
// random points. `variant` gets the knot vector of the production function,
// its neighbours in one longer knot vector (shifted by one) and the point.
double MaxDifferenceToProduction(unsigned seed, int minDegree,
  const std::function<double(const std::vector<double>&, const std::vector<double>&, double, bool)>&
    variant)
{
  std::mt19937 rng(seed);
  double worst = 0.0;
  for (int trial = 0; trial < 800; ++trial)
  {
    const int p = minDegree + trial % (8 - minDegree);
    // p + 3 knots: the function's p + 2 and the next one (for the shift).
    std::vector<double> all = RandomKnots(rng, p + 1, -0.5, 0.05, false);
    const std::vector<double> t(all.begin(), all.end() - 1), next(all.begin() + 1, all.end());
    if (!(t.back() > t.front()))
    {
      continue;
    }
    for (const auto& xp : Points(rng, t))
    {
      worst = std::max(worst,
        std::abs(variant(t, next, xp.first, xp.second) - Production(t, xp.first, xp.second)));
    }
  }
  return worst;
}
}

int TestLRSplineTruncatedPowerBSpline(int, char*[])
{
  SplineVizTestStatus status;
  // The closed forms are rounded too: 4 ulp of 1 (measured 1.1e-16).
  const double closedTol = 4.0 * std::numeric_limits<double>::epsilon();
  // Two algorithms (see the top): measured up to 1.9e-15.
  const double agreeTol = 4e-15;

  //--- (a) Closed forms.
  {
    // Degree 0: the indicator of [a, b), from the left of (a, b].
    const std::vector<double> t0 = { 0.25, 1.5 };
    SV_CHECK(status, Reference(t0, 0.25, false) == 1.0);
    SV_CHECK(status, Reference(t0, 0.25, true) == 0.0);
    SV_CHECK(status, Reference(t0, 1.0, false) == 1.0 && Reference(t0, 1.0, true) == 1.0);
    SV_CHECK(status, Reference(t0, 1.5, false) == 0.0);
    SV_CHECK(status, Reference(t0, 1.5, true) == 1.0);
    SV_CHECK(status, Reference(t0, 0.0, false) == 0.0 && Reference(t0, 2.0, true) == 0.0);

    // Degree 1: hat functions, with simple and double knots.
    const double a = 0.5, b = 1.25, c = 3.0;
    double worst = 0.0;
    for (int i = -10; i <= 110; ++i)
    {
      const double x = a + (c - a) * i / 100.0;
      const double hat = (x >= a && x < b) ? (x - a) / (b - a)
        : (x >= b && x < c)                ? (c - x) / (c - b)
                                           : 0.0;
      const double down = (x >= a && x < c) ? (c - x) / (c - a) : 0.0; // knots a a c
      const double up = (x >= a && x < c) ? (x - a) / (c - a) : 0.0;   // knots a c c
      worst = std::max(worst, std::abs(Reference({ a, b, c }, x, false) - hat));
      worst = std::max(worst, std::abs(Reference({ a, a, c }, x, false) - down));
      worst = std::max(worst, std::abs(Reference({ a, c, c }, x, false) - up));
    }
    SV_CHECK_NEAR(status, Reference({ a, b, c }, b, false), 1.0, closedTol);
    SV_CHECK_NEAR(status, Reference({ a, b, c }, b, true), 1.0, closedTol);
    SV_CHECK(
      status, Reference({ a, a, c }, a, false) == 1.0 && Reference({ a, a, c }, a, true) == 0.0);
    SV_CHECK(status, Reference({ a, c, c }, c, false) == 0.0);
    SV_CHECK_NEAR(status, Reference({ a, c, c }, c, true), 1.0, closedTol);

    // The uniform cubic B-spline on 0, 1, 2, 3, 4 (times 0.75, plus 2: exact
    // in binary) and its pieces.
    const std::vector<double> t3 = { 2.0, 2.75, 3.5, 4.25, 5.0 };
    SV_CHECK_NEAR(status, Reference(t3, 2.75, false), 1.0 / 6.0, closedTol);
    SV_CHECK_NEAR(status, Reference(t3, 3.5, false), 2.0 / 3.0, closedTol);
    SV_CHECK_NEAR(status, Reference(t3, 4.25, false), 1.0 / 6.0, closedTol);
    SV_CHECK_NEAR(status, Reference(t3, 4.25, true), 1.0 / 6.0, closedTol);
    SV_CHECK(status, Reference(t3, 2.0, false) == 0.0 && Reference(t3, 5.0, false) == 0.0);
    SV_CHECK(status, Reference(t3, 5.0, true) == 0.0);
    for (int i = -8; i <= 264; ++i)
    {
      const double s = i / 64.0; // in units of the knot spacing; x exact in binary
      // The pieces in the well-conditioned form (1 + 3r + 3r^2 - 3r^3) / 6 in
      // the middle (r from the outer knots), r^3 / 6 at the ends.
      auto middle = [](double r) { return (1.0 + 3.0 * r + 3.0 * r * r - 3.0 * r * r * r) / 6.0; };
      double cubic = 0.0;
      if (s >= 0 && s < 1)
        cubic = s * s * s / 6.0;
      else if (s >= 1 && s < 2)
        cubic = middle(s - 1.0);
      else if (s >= 2 && s < 3)
        cubic = middle(3.0 - s);
      else if (s >= 3 && s < 4)
        cubic = (4.0 - s) * (4.0 - s) * (4.0 - s) / 6.0;
      worst = std::max(worst, std::abs(Reference(t3, 2.0 + 0.75 * s, false) - cubic));
    }

    // Bernstein polynomials: knots a^(p+1-i) b^(i+1).
    const double lo = -1.0, hi = 1.5;
    for (int p = 0; p <= 8; ++p)
    {
      for (int i = 0; i <= p; ++i)
      {
        std::vector<double> t(p + 1 - i, lo);
        t.insert(t.end(), i + 1, hi);
        for (int j = 0; j <= 64; ++j)
        {
          const double s = j / 64.0, x = lo + s * (hi - lo); // exact in binary
          const double bern = lrtest::Binomial(p, i) * std::pow(s, i) * std::pow(1.0 - s, p - i);
          if (j < 64)
          {
            worst = std::max(worst, std::abs(Reference(t, x, false) - bern));
          }
          if (j > 0)
          {
            worst = std::max(worst, std::abs(Reference(t, x, true) - bern));
          }
        }
        SV_CHECK(status, Reference(t, lo, false) == (i == 0 ? 1.0 : 0.0));
        SV_CHECK(status, Reference(t, lo, true) == 0.0);
        SV_CHECK(status, Reference(t, hi, false) == 0.0);
        SV_CHECK_NEAR(status, Reference(t, hi, true), i == p ? 1.0 : 0.0, closedTol);
      }
    }
    std::cout << "closed forms (hats, uniform cubic, Bernstein up to degree 8): max difference "
              << worst << std::endl;
    SV_CHECK_MSG(status, worst <= closedTol, "closed forms " << worst);
  }

  //--- (b) Partition of unity of clamped knot vectors.
  {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> U(0.0, 1.0);
    double worstSum = 0.0, mostNegative = 0.0, outside = 0.0, worstBound = 0.0;
    bool nonnegative = true;
    for (int trial = 0; trial < 240; ++trial)
    {
      const int p = trial % 8;
      const double a = -2.0 + U(rng), b = a + 0.5 + 3.0 * U(rng);
      std::vector<double> knots(p + 1, a);
      const int interior = 1 + static_cast<int>(U(rng) * 8);
      std::vector<double> breaks; // a jittered grid: gaps >= 0.2 / 9 of [a, b]
      for (int k = 1; k <= interior; ++k)
      {
        breaks.push_back(a + (b - a) * (k + 0.8 * (U(rng) - 0.5)) / (interior + 1));
      }
      for (double k : breaks)
      {
        const int m = (trial % 5 == 0) ? p + 1 : 1 + static_cast<int>(U(rng) * p); // up to p + 1
        knots.insert(knots.end(), std::max(m, 1), k);
      }
      knots.insert(knots.end(), p + 1, b);
      std::vector<std::pair<double, bool>> points;
      for (double k : knots)
      {
        points.emplace_back(k, k == b); // every knot; the upper end from the left
      }
      for (int i = 0; i < 40; ++i)
      {
        points.emplace_back(a + (b - a) * U(rng), false);
      }
      for (const auto& xp : points)
      {
        double sum = 0.0;
        for (std::size_t f = 0; f + p + 1 < knots.size(); ++f)
        {
          const std::vector<double> t(knots.begin() + f, knots.begin() + f + p + 2);
          double bound = 0.0;
          const double v = lrtest::TruncatedPowerBSpline(t, xp.first, xp.second, &bound);
          sum += v;
          mostNegative = std::min(mostNegative, v);
          worstBound = std::max(worstBound, bound);
          nonnegative = nonnegative && v >= -bound; // >= 0 within its error bound
          if (xp.first < t.front() || xp.first > t.back())
          {
            outside = std::max(outside, std::abs(v));
          }
        }
        worstSum = std::max(worstSum, std::abs(sum - 1.0));
      }
    }
    std::cout << "partition of unity (degrees 0-7): max |sum - 1| " << worstSum
              << ", most negative value " << mostNegative
              << " (within its error bound: " << nonnegative << "), max outside the support "
              << outside << ", largest error bound " << worstBound << std::endl;
    SV_CHECK_MSG(status, worstSum <= agreeTol, "partition of unity " << worstSum);
    SV_CHECK(status, nonnegative && outside == 0.0);
  }

  //--- (c) Agreement with Cox-de Boor (test copy and production).
  {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> U(0.0, 1.0);
    const char* names[2] = { "well separated knots (gaps 0.05 to 1)",
      "graded knots (gaps 1e-3 to 1, log-uniform)" };
    for (int graded = 0; graded < 2; ++graded)
    {
      double worstCopy = 0.0, worstProduction = 0.0, worstBound = 0.0;
      int evaluations = 0, refused = 0, onKnots = 0;
      for (int trial = 0; trial < 4000; ++trial)
      {
        const int p = trial % 8;
        const double first = (trial % 3 == 0) ? 1000.0 * U(rng) : 2.0 * U(rng) - 1.0;
        const std::vector<double> t = RandomKnots(rng, p, first, graded ? 1e-3 : 0.05, graded);
        for (const auto& xp : Points(rng, t))
        {
          double bound = 0.0, v = 0.0;
          try
          {
            v = lrtest::TruncatedPowerBSpline(t, xp.first, xp.second, &bound);
          }
          catch (const std::runtime_error&)
          {
            ++refused;
            continue;
          }
          ++evaluations;
          onKnots += std::count(t.begin(), t.end(), xp.first) > 0 ? 1 : 0;
          worstBound = std::max(worstBound, bound);
          worstCopy = std::max(worstCopy, std::abs(v - lrtest::CoxDeBoor(t, xp.first, xp.second)));
          worstProduction =
            std::max(worstProduction, std::abs(v - Production(t, xp.first, xp.second)));
        }
      }
      std::cout << names[graded] << ", degrees 0-7: " << evaluations << " values (" << onKnots
                << " on knots), " << refused
                << " refused by the guard; max |truncated power - CoxDeBoor| " << worstCopy
                << ", max |truncated power - vtkLRSplinePatch::BSplineValue| " << worstProduction
                << ", largest error bound " << worstBound << std::endl;
      SV_CHECK_MSG(status, worstCopy <= agreeTol, names[graded] << ": " << worstCopy);
      SV_CHECK_MSG(status, worstProduction <= agreeTol, names[graded] << ": " << worstProduction);
      SV_CHECK(status, refused <= evaluations / 100);
      if (!graded)
      {
        SV_CHECK(status, refused == 0);
      }
    }
  }

  //--- (d) Negative controls: deliberate mistakes must exceed the tolerance.
  {
    const double correct = MaxDifferenceToProduction(3, 0,
      [](const std::vector<double>& t, const std::vector<double>&, double x, bool fromLeft)
      { return Reference(t, x, fromLeft); });
    const double degreeOff = MaxDifferenceToProduction(3, 1,
      [](const std::vector<double>& t, const std::vector<double>&, double x, bool fromLeft)
      { return Reference(std::vector<double>(t.begin(), t.end() - 1), x, fromLeft); });
    const double shifted = MaxDifferenceToProduction(3, 0,
      [](const std::vector<double>&, const std::vector<double>& next, double x, bool fromLeft)
      { return Reference(next, x, fromLeft); });
    const double otherSide = MaxDifferenceToProduction(3, 0,
      [](const std::vector<double>& t, const std::vector<double>&, double x, bool fromLeft)
      { return Reference(t, x, !fromLeft); });
    const double moved = MaxDifferenceToProduction(3, 1,
      [](const std::vector<double>& t, const std::vector<double>&, double x, bool fromLeft)
      {
        std::vector<double> m = t;
        const int i = static_cast<int>(m.size()) / 2;
        const double shift = 1e-12 * (m.back() - m.front());
        if (m[i - 1] < m[i] && m[i] + shift < m[i + 1])
        {
          m[i] += shift;
        }
        return Reference(m, x, fromLeft);
      });
    std::cout << "against vtkLRSplinePatch::BSplineValue (tolerance " << agreeTol << "): correct "
              << correct << "; negative controls: degree one lower " << degreeOff
              << ", knots shifted by one " << shifted << ", the other one-sided limit " << otherSide
              << ", one knot moved by 1e-12 " << moved << std::endl;
    SV_CHECK_MSG(status, correct <= agreeTol, "correct variant " << correct);
    SV_CHECK_MSG(status, degreeOff > 0.1, "degree control " << degreeOff);
    SV_CHECK_MSG(status, shifted > 0.1, "shift control " << shifted);
    SV_CHECK_MSG(status, otherSide > 0.1, "one-sided control " << otherSide);
    SV_CHECK_MSG(status, moved > 10 * agreeTol, "moved-knot control " << moved);
  }

  //--- (e) The guard.
  {
    std::vector<double> clustered = { 0.0 };
    for (int i = 1; i <= 8; ++i)
    {
      clustered.push_back(1.0 + 1e-6 * i); // degree 7, gaps 1e-6 of the support
    }
    bool threw = false;
    try
    {
      lrtest::TruncatedPowerBSpline(clustered, 0.5, false);
    }
    catch (const std::runtime_error& e)
    {
      threw = true;
      std::cout << "clustered knots: " << e.what() << std::endl;
    }
    SV_CHECK_MSG(status, threw, "clustered knots accepted");
    const std::vector<std::vector<double>> invalid = { { 1.0 }, { 0.0, 2.0, 1.0 },
      { 0.0, std::numeric_limits<double>::quiet_NaN(), 1.0 },
      { 0.0, std::numeric_limits<double>::infinity() } };
    for (const auto& t : invalid)
    {
      bool rejected = false;
      try
      {
        lrtest::TruncatedPowerBSpline(t, 0.5, false);
      }
      catch (const std::invalid_argument&)
      {
        rejected = true;
      }
      SV_CHECK(status, rejected);
    }
  }
  return status.Result();
}
