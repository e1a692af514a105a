// SPDX-License-Identifier: BSD-3-Clause
// Independent reference code for the LR-spline tests: a minimal parser of the
// .lr and .g2 formats and the brute-force evaluation of an LR spline as the
// sum over ALL its basis functions of gamma * c * B_u * B_v * B_w.
//
// Each univariate B, on the function's local knot vector t_0 <= ... <= t_p+1,
// is TruncatedPowerBSpline: the Curry-Schoenberg definition
//   B(x) = (t_p+1 - t_0) [t_0, ..., t_p+1] (. - x)_+^p,
// the divided difference of the truncated power in its first argument (a
// knot of multiplicity m contributes the Taylor coefficients of orders up to
// m - 1: the confluent divided difference). It is a different algorithm from
// the production code's (vtkLRSplinePatch::BSplineValue, the Cox-de Boor
// recurrence on half-open knot intervals): no shared formula, no shared
// intermediate values, and the conventions at the knots (half-open
// [t_j, t_j+1); fromLeft at the upper end of a domain) come from one-sided
// limits of the truncated power, not from indicators of intervals, so a
// mistake in the recurrence or in its conventions cannot repeat itself here.
// Divided differences cancel (the condition grows like (support / smallest
// knot gap)^degree: in plain double, 1e-10 at degree 5 for gaps of 1/10 of
// the support), so the table is carried in double-double arithmetic (about
// 106 bits) with a running error bound. On random knot vectors of degrees 0
// to 7 with gaps down to 1e-4 the value is within 5.6e-17 (half an ulp of 1)
// of the exact one (measured offline with exact rational arithmetic);
// Cox-de Boor's rounding is up to 1.5e-15 there. Where the bound exceeds
// 1e-15 (gaps down to 1e-3: 0.1 % of the values, all of degree 5 to 7) the
// function throws rather than return an inaccurate reference.
//
// CoxDeBoor, the recurrence, stays only as the second of two independent
// algorithms that TestLRSplineTruncatedPowerBSpline checks against each other.
// Nothing here uses the SplineViz classes (it checks them).
#ifndef LRSplineTestUtilities_h
#define LRSplineTestUtilities_h

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace lrtest
{
struct BrutePatch
{
  int Order[3] = { 0, 0, 0 };
  int Dim = 0;
  std::vector<std::array<std::vector<double>, 3>> Knots;
  std::vector<double> Coef; // Dim per function
  std::vector<double> Gamma;
  std::vector<std::array<double, 6>> Elements;
  int NumberOfMeshRectangles = 0;
  double Domain[6] = { 1e300, 1e300, 1e300, -1e300, -1e300, -1e300 };
};

inline std::string ReadText(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Cox-de Boor: the B-spline of degree p = t.size() - 2 with knots t at x.
// Half-open intervals [t_j, t_j+1); with fromLeft, (t_j, t_j+1] (the upper
// end of the domain is evaluated from the left). The same recurrence as the
// production code: only a cross-check of TruncatedPowerBSpline (below), which
// is the reference.
inline double CoxDeBoor(const std::vector<double>& t, double x, bool fromLeft)
{
  const int p = static_cast<int>(t.size()) - 2;
  std::vector<double> N(p + 1);
  for (int j = 0; j <= p; ++j)
  {
    const bool in = fromLeft ? (t[j] < x && x <= t[j + 1]) : (t[j] <= x && x < t[j + 1]);
    N[j] = in ? 1.0 : 0.0;
  }
  for (int k = 1; k <= p; ++k)
  {
    for (int j = 0; j + k <= p; ++j)
    {
      const double d1 = t[j + k] - t[j];
      const double d2 = t[j + k + 1] - t[j + 1];
      const double a = d1 > 0 ? (x - t[j]) / d1 * N[j] : 0.0;
      const double b = d2 > 0 ? (t[j + k + 1] - x) / d2 * N[j + 1] : 0.0;
      N[j] = a + b;
    }
  }
  return N[0];
}

namespace detail
{
// Double-double numbers Hi + Lo (|Lo| <= ulp(Hi) / 2, about 106 bits) with the
// error-free transformations of Dekker (1971) and Knuth (TAOCP 4.2.2) and the
// operations of Hida, Li and Bailey's QD library (2001).
struct DoubleDouble
{
  double Hi;
  double Lo;
};

// a + b exactly.
inline DoubleDouble TwoSum(double a, double b)
{
  const double s = a + b;
  const double bb = s - a;
  return { s, (a - (s - bb)) + (b - bb) };
}

// a + b exactly, for |a| >= |b|.
inline DoubleDouble FastTwoSum(double a, double b)
{
  const double s = a + b;
  return { s, b - (s - a) };
}

// a * b exactly (fma is correctly rounded).
inline DoubleDouble TwoProduct(double a, double b)
{
  const double p = a * b;
  return { p, std::fma(a, b, -p) };
}

inline DoubleDouble operator+(DoubleDouble a, DoubleDouble b)
{
  DoubleDouble s = TwoSum(a.Hi, b.Hi);
  const DoubleDouble t = TwoSum(a.Lo, b.Lo);
  s.Lo += t.Hi;
  s = FastTwoSum(s.Hi, s.Lo);
  s.Lo += t.Lo;
  return FastTwoSum(s.Hi, s.Lo);
}

inline DoubleDouble operator-(DoubleDouble a, DoubleDouble b)
{
  return a + DoubleDouble{ -b.Hi, -b.Lo };
}

inline DoubleDouble operator*(DoubleDouble a, DoubleDouble b)
{
  DoubleDouble p = TwoProduct(a.Hi, b.Hi);
  p.Lo += a.Hi * b.Lo + a.Lo * b.Hi;
  return FastTwoSum(p.Hi, p.Lo);
}

inline DoubleDouble operator/(DoubleDouble a, DoubleDouble b)
{
  const double q1 = a.Hi / b.Hi;
  DoubleDouble r = a - b * DoubleDouble{ q1, 0.0 };
  const double q2 = r.Hi / b.Hi;
  r = r - b * DoubleDouble{ q2, 0.0 };
  const double q3 = r.Hi / b.Hi;
  return FastTwoSum(q1, q2) + DoubleDouble{ q3, 0.0 };
}

// a / b for a double b (cheaper than the division by a double-double).
inline DoubleDouble operator/(DoubleDouble a, double b)
{
  const double q1 = a.Hi / b;
  const DoubleDouble p = TwoProduct(q1, b);
  const DoubleDouble s = TwoSum(a.Hi, -p.Hi);
  const double q2 = (s.Hi + (s.Lo - p.Lo + a.Lo)) / b;
  return FastTwoSum(q1, q2);
}

// The k-th Taylor coefficient in y of the truncated power (y - x)_+^p,
// (1/k!) d^k/dy^k (y - x)_+^p = C(p, k) (y - x)_+^(p - k) for 0 <= k <= p.
// At y == x it is the one-sided limit in x: from the right (x -> y+, where
// y - x < 0) every coefficient is 0, which makes B right-continuous in x (the
// half-open intervals [t_j, t_j+1)); from the left (x -> y-, where y - x > 0)
// the coefficients tend to C(p, k) 0^(p - k): 1 for k == p, else 0.
inline DoubleDouble TruncatedPowerTaylor(double y, double x, int p, int k, bool fromLeft)
{
  if (y < x)
  {
    return { 0.0, 0.0 };
  }
  if (y == x)
  {
    return { fromLeft && k == p ? 1.0 : 0.0, 0.0 };
  }
  double binomial = 1.0; // C(p, k): an integer at every step, exact
  for (int i = 1; i <= k; ++i)
  {
    binomial = binomial * (p - k + i) / i;
  }
  const DoubleDouble d = TwoSum(y, -x); // y - x exactly
  DoubleDouble r{ binomial, 0.0 };
  for (int i = 0; i < p - k; ++i)
  {
    r = r * d;
  }
  return r;
}
}

// The B-spline of degree p = t.size() - 2 with the nondecreasing knots t at x,
// by the Curry-Schoenberg definition (see the top of the file):
//   B(x) = (t_p+1 - t_0) [t_0, ..., t_p+1] (. - x)_+^p,
// the divided-difference table built by
//   [t_i..t_i+k] = ([t_i+1..t_i+k] - [t_i..t_i+k-1]) / (t_i+k - t_i),
// or, where t_i == t_i+k (a knot of multiplicity > k), the k-th Taylor
// coefficient (1/k!) g^(k)(t_i) of g = (. - x)_+^p. Right-continuous in x
// (the intervals [t_j, t_j+1)); with fromLeft, the limit from the left (the
// intervals (t_j, t_j+1], for the upper end of a domain), from the one-sided
// Taylor coefficients at y == x, not by moving x.
// Left of t_0 (and at t_0 from the left) g is the polynomial (. - x)^p on all
// the knots, whose divided difference of order p + 1 vanishes: 0 is returned
// exactly rather than its rounding; right of t_p+1 (and at t_p+1 from the
// right) every Taylor coefficient is 0, and so is the table (not built).
// The table is in double-double arithmetic, with a first-order running error
// bound (Higham, Accuracy and Stability of Numerical Algorithms, 3.3) of a
// generous unit 1e-29 (the double-double unit is 2^-106, about 1.2e-32);
// `errorBound`, when given, receives it plus the final rounding to double.
// Throws std::runtime_error when that exceeds 1e-15 (clustered knots of a
// high degree), std::invalid_argument for decreasing or non-finite knots.
inline double TruncatedPowerBSpline(
  const std::vector<double>& t, double x, bool fromLeft, double* errorBound = nullptr)
{
  using detail::DoubleDouble;
  constexpr int MaxKnots = 32;
  constexpr double Unit = 1e-29;
  const int n = static_cast<int>(t.size()) - 1; // p + 1
  if (n < 1 || n >= MaxKnots)
  {
    throw std::invalid_argument("TruncatedPowerBSpline: 2 to 32 knots");
  }
  for (int i = 0; i < n; ++i)
  {
    if (!(std::isfinite(t[i]) && t[i] <= t[i + 1] && std::isfinite(t[i + 1])))
    {
      throw std::invalid_argument("TruncatedPowerBSpline: knots not finite and nondecreasing");
    }
  }
  if (!std::isfinite(x))
  {
    throw std::invalid_argument("TruncatedPowerBSpline: x not finite");
  }
  if (errorBound)
  {
    *errorBound = 0.0;
  }
  const int p = n - 1;
  if (!(t[0] < t[n]) || x < t[0] || (fromLeft && x == t[0]))
  {
    return 0.0; // empty support (multiplicity p + 2), or left of the support
  }
  if (x > t[n] || (!fromLeft && x == t[n]))
  {
    return 0.0; // right of the support: every Taylor coefficient is 0
  }
  DoubleDouble D[MaxKnots];
  double E[MaxKnots]; // error bounds of D
  for (int i = 0; i <= n; ++i)
  {
    D[i] = detail::TruncatedPowerTaylor(t[i], x, p, 0, fromLeft);
    E[i] = Unit * std::abs(D[i].Hi);
  }
  for (int k = 1; k <= n; ++k)
  {
    for (int i = 0; i + k <= n; ++i) // D[i + 1] is still of order k - 1
    {
      if (t[i + k] == t[i])
      {
        D[i] = detail::TruncatedPowerTaylor(t[i], x, p, k, fromLeft);
        E[i] = Unit * std::abs(D[i].Hi);
      }
      else
      {
        const DoubleDouble gap = detail::TwoSum(t[i + k], -t[i]); // exact
        D[i] = gap.Lo == 0.0 ? (D[i + 1] - D[i]) / gap.Hi : (D[i + 1] - D[i]) / gap;
        E[i] = (E[i + 1] + E[i]) / gap.Hi + Unit * std::abs(D[i].Hi);
      }
    }
  }
  const DoubleDouble length = detail::TwoSum(t[n], -t[0]);
  const DoubleDouble b = length * D[0];
  const double value = b.Hi + b.Lo;
  const double bound =
    length.Hi * E[0] + Unit * std::abs(b.Hi) + 1.1102230246251565e-16 * std::abs(value);
  if (errorBound)
  {
    *errorBound = bound;
  }
  if (!(bound <= 1e-15))
  {
    std::ostringstream message;
    message << "TruncatedPowerBSpline: knots too clustered for an accurate value (error bound "
            << bound << ")";
    throw std::runtime_error(message.str());
  }
  return value;
}

// f(u, v, w) = sum_i gamma_i c_i B_i,u B_i,v B_i,w over all basis functions.
inline void BruteForce(const BrutePatch& P, const double u[3], double* out)
{
  for (int c = 0; c < P.Dim; ++c)
  {
    out[c] = 0.0;
  }
  bool fromLeft[3];
  for (int d = 0; d < 3; ++d)
  {
    fromLeft[d] = (u[d] == P.Domain[d + 3]);
  }
  for (std::size_t i = 0; i < P.Gamma.size(); ++i)
  {
    double b = P.Gamma[i];
    for (int d = 0; d < 3 && b != 0.0; ++d)
    {
      b *= TruncatedPowerBSpline(P.Knots[i][d], u[d], fromLeft[d]);
    }
    if (b == 0.0)
    {
      continue;
    }
    for (int c = 0; c < P.Dim; ++c)
    {
      out[c] += b * P.Coef[i * P.Dim + c];
    }
  }
}

// Minimal .lr parser: punctuation becomes blanks, then tokens are read in the
// documented order. Only for well-formed files.
inline std::vector<BrutePatch> ParseLR(const std::string& text)
{
  std::vector<BrutePatch> patches;
  std::istringstream lines(text);
  std::string line;
  enum
  {
    None,
    Header,
    Basis,
    Rects,
    Elems
  } state = None;
  std::size_t nb = 0, nl = 0, ne = 0;
  while (std::getline(lines, line))
  {
    if (line.find("# LRSPLINE VOLUME") != std::string::npos)
    {
      patches.emplace_back();
      state = Header;
      continue;
    }
    if (line.empty() || line[0] == '#' || line.find_first_not_of(" \t\r") == std::string::npos)
    {
      continue;
    }
    BrutePatch& P = patches.back();
    std::string clean = line;
    for (char& ch : clean)
    {
      if (ch == ':' || ch == '[' || ch == ']' || ch == '(' || ch == ')' || ch == ',' || ch == '{' ||
        ch == '}')
      {
        ch = ' ';
      }
    }
    std::istringstream s(clean);
    std::vector<std::string> tok;
    std::string t;
    while (s >> t)
    {
      if (t != "x")
      {
        tok.push_back(t);
      }
    }
    if (state == Header)
    {
      for (int d = 0; d < 3; ++d)
      {
        P.Order[d] = std::stoi(tok[d]);
      }
      nb = std::stoul(tok[3]);
      nl = std::stoul(tok[4]);
      ne = std::stoul(tok[5]);
      P.Dim = std::stoi(tok[6]);
      P.NumberOfMeshRectangles = static_cast<int>(nl);
      state = Basis;
      continue;
    }
    if (state == Basis)
    {
      std::size_t k = 1;
      std::array<std::vector<double>, 3> kn;
      for (int d = 0; d < 3; ++d)
      {
        for (int j = 0; j <= P.Order[d]; ++j)
        {
          kn[d].push_back(std::stod(tok[k++]));
        }
      }
      P.Knots.push_back(kn);
      for (int c = 0; c < P.Dim; ++c)
      {
        P.Coef.push_back(std::stod(tok[k++]));
      }
      P.Gamma.push_back(std::stod(tok[k++]));
      if (P.Gamma.size() == nb)
      {
        state = nl > 0 ? Rects : Elems;
      }
      continue;
    }
    if (state == Rects)
    {
      if (--nl == 0)
      {
        state = Elems;
      }
      continue;
    }
    if (state == Elems)
    {
      std::array<double, 6> b;
      for (int c = 0; c < 6; ++c)
      {
        b[c] = std::stod(tok[2 + c]);
      }
      P.Elements.push_back(b);
      for (int d = 0; d < 3; ++d)
      {
        P.Domain[d] = std::min(P.Domain[d], b[d]);
        P.Domain[d + 3] = std::max(P.Domain[d + 3], b[d + 3]);
      }
      if (P.Elements.size() == ne)
      {
        state = None;
      }
    }
  }
  return patches;
}

// Minimal g2 class 700 parser (one volume, non-rational).
inline BrutePatch ParseG2(const std::string& text)
{
  std::istringstream s(text);
  BrutePatch P;
  int cls, major, minor, ncol;
  s >> cls >> major >> minor >> ncol;
  for (int i = 0; i < ncol; ++i)
  {
    int c;
    s >> c;
  }
  int rational;
  s >> P.Dim >> rational;
  int n[3];
  std::vector<double> knots[3];
  for (int d = 0; d < 3; ++d)
  {
    s >> n[d] >> P.Order[d];
    knots[d].resize(n[d] + P.Order[d]);
    for (double& v : knots[d])
    {
      s >> v;
    }
    P.Domain[d] = knots[d].front();
    P.Domain[d + 3] = knots[d].back();
  }
  for (int k = 0; k < n[2]; ++k)
  {
    for (int j = 0; j < n[1]; ++j)
    {
      for (int i = 0; i < n[0]; ++i)
      {
        std::array<std::vector<double>, 3> kn;
        const int idx[3] = { i, j, k };
        for (int d = 0; d < 3; ++d)
        {
          kn[d].assign(knots[d].begin() + idx[d], knots[d].begin() + idx[d] + P.Order[d] + 1);
        }
        P.Knots.push_back(kn);
        for (int c = 0; c < P.Dim; ++c)
        {
          double v;
          s >> v;
          P.Coef.push_back(v);
        }
        P.Gamma.push_back(1.0);
      }
    }
  }
  return P;
}

// Elementary symmetric polynomial e_k of x[0..n-1].
inline double ElementarySymmetric(const double* x, int n, int k)
{
  std::vector<double> e(k + 1, 0.0);
  e[0] = 1.0;
  for (int i = 0; i < n; ++i)
  {
    for (int j = std::min(k, i + 1); j >= 1; --j)
    {
      e[j] += x[i] * e[j - 1];
    }
  }
  return e[k];
}

inline double Binomial(int n, int k)
{
  double r = 1.0;
  for (int i = 1; i <= k; ++i)
  {
    r = r * (n - k + i) / i;
  }
  return r;
}

// A polynomial sum_{a,b,c} A[a][b][c] u^a v^b w^c with a <= p, b <= q, c <= r.
struct Polynomial
{
  int Degree[3];
  std::vector<double> A; // ((c * (q+1) + b) * (p+1) + a)
  double Coefficient(int a, int b, int c) const
  {
    return A[(c * (Degree[1] + 1) + b) * (Degree[0] + 1) + a];
  }
  double Value(const double x[3]) const
  {
    double s = 0.0;
    for (int c = 0; c <= Degree[2]; ++c)
      for (int b = 0; b <= Degree[1]; ++b)
        for (int a = 0; a <= Degree[0]; ++a)
          s += Coefficient(a, b, c) * std::pow(x[0], a) * std::pow(x[1], b) * std::pow(x[2], c);
    return s;
  }
  void Gradient(const double x[3], double g[3]) const
  {
    g[0] = g[1] = g[2] = 0.0;
    for (int c = 0; c <= Degree[2]; ++c)
      for (int b = 0; b <= Degree[1]; ++b)
        for (int a = 0; a <= Degree[0]; ++a)
        {
          const double k = Coefficient(a, b, c);
          if (a > 0)
            g[0] += k * a * std::pow(x[0], a - 1) * std::pow(x[1], b) * std::pow(x[2], c);
          if (b > 0)
            g[1] += k * b * std::pow(x[0], a) * std::pow(x[1], b - 1) * std::pow(x[2], c);
          if (c > 0)
            g[2] += k * c * std::pow(x[0], a) * std::pow(x[1], b) * std::pow(x[2], c - 1);
        }
  }
  // Blossom (polar form) at u[0..p-1], v[0..q-1], w[0..r-1].
  double Blossom(const double* u, const double* v, const double* w) const
  {
    double s = 0.0;
    for (int c = 0; c <= Degree[2]; ++c)
      for (int b = 0; b <= Degree[1]; ++b)
        for (int a = 0; a <= Degree[0]; ++a)
          s += Coefficient(a, b, c) * ElementarySymmetric(u, Degree[0], a) /
            Binomial(Degree[0], a) * ElementarySymmetric(v, Degree[1], b) / Binomial(Degree[1], b) *
            ElementarySymmetric(w, Degree[2], c) / Binomial(Degree[2], c);
    return s;
  }
};
}

#endif
