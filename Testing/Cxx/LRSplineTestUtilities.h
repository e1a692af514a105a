// SPDX-License-Identifier: BSD-3-Clause
// Independent reference code for the LR-spline tests: a minimal parser of the
// .lr and .g2 formats and the brute-force evaluation of an LR spline as the
// sum over ALL its basis functions of gamma * c * B_u * B_v * B_w, each B the
// classical Cox-de Boor recursion on the function's local knot vector.
// Nothing here uses the SplineViz classes (it checks them).
#ifndef LRSplineTestUtilities_h
#define LRSplineTestUtilities_h

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <sstream>
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
// end of the domain is evaluated from the left).
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
      b *= CoxDeBoor(P.Knots[i][d], u[d], fromLeft[d]);
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
