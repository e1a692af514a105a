// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLRSplineFitCore.h"

#include "vtkLRSplineArrayNames.h"
#include "vtkLRSplineBezierGrid.h"
#include "vtkLRSplineBezierVolume.h"

#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <initializer_list>

namespace
{
// Always-on relative ridge (keeps the normal matrix definite).
constexpr double Ridge = 1e-12;
// Conjugate gradients: the delay of the error estimate, the iteration limit.
constexpr int SolverDelay = 10;
constexpr int SolverMaximumIterations = 2000;

double Dot(const std::vector<double>& a, const std::vector<double>& b)
{
  const vtkIdType n = static_cast<vtkIdType>(a.size());
  vtkSMPThreadLocal<double> partial(0.0);
  vtkSMPTools::For(0, n,
    [&](vtkIdType begin, vtkIdType end)
    {
      double s = 0.0;
      for (vtkIdType i = begin; i < end; ++i)
      {
        s += a[i] * b[i];
      }
      partial.Local() += s;
    });
  double s = 0.0;
  for (double v : partial)
  {
    s += v;
  }
  return s;
}
}

//------------------------------------------------------------------------------
// The functions on every element and the elements in every function's
// support (the builder's meshes are valid: every support is a union of
// elements). Each function is registered in the cells of a grid that its
// support overlaps; the functions containing an element are among those of
// the cell of its lower corner. The cells are as large as keeps the
// registrations to a few per function, and at least MinimumCell.
void vtkLRSplineFitCore::ComputeSupports()
{
  const vtkLRSplinePatch& patch = this->Builder.GetPatch();
  const vtkIdType ne = patch.GetNumberOfElements();
  const vtkIdType nf = patch.GetNumberOfBasisFunctions();
  double domain[6];
  patch.GetDomain(domain);
  const double minimumCell = this->MinimumCell;
  double volume = 0.0;
  for (vtkIdType f = 0; f < nf; ++f)
  {
    double v = 1.0;
    for (int d = 0; d < 3; ++d)
    {
      const double* t = patch.GetKnots(f, d);
      v *= t[patch.Order[d]] - t[0] + minimumCell;
    }
    volume += v;
  }
  const double cell = std::max(minimumCell, std::cbrt(volume / (8.0 * std::max<vtkIdType>(1, nf))));
  int G[3];
  for (int d = 0; d < 3; ++d)
  {
    G[d] = std::max(1, static_cast<int>(std::ceil((domain[d + 3] - domain[d]) / cell)));
  }
  auto cellOf = [&](double x, int d)
  { return std::min(G[d] - 1, std::max(0, static_cast<int>(std::floor((x - domain[d]) / cell)))); };
  auto cellRange = [&](const vtkIdType f, int c0[3], int c1[3])
  {
    for (int d = 0; d < 3; ++d)
    {
      const double* t = patch.GetKnots(f, d);
      c0[d] = cellOf(t[0], d);
      c1[d] = std::max(c0[d],
        std::min(
          G[d] - 1, static_cast<int>(std::ceil((t[patch.Order[d]] - domain[d]) / cell)) - 1));
    }
  };
  auto forCells = [&](vtkIdType f, const std::function<void(vtkIdType)>& visit)
  {
    int c0[3], c1[3];
    cellRange(f, c0, c1);
    for (int k = c0[2]; k <= c1[2]; ++k)
      for (int j = c0[1]; j <= c1[1]; ++j)
        for (int i = c0[0]; i <= c1[0]; ++i)
          visit((static_cast<vtkIdType>(k) * G[1] + j) * G[0] + i);
  };
  const vtkIdType cells = static_cast<vtkIdType>(G[0]) * G[1] * G[2];
  std::vector<vtkIdType> cellOffsets(cells + 1, 0);
  for (vtkIdType f = 0; f < nf; ++f)
  {
    forCells(f, [&](vtkIdType c) { ++cellOffsets[c + 1]; });
  }
  for (vtkIdType c = 0; c < cells; ++c)
  {
    cellOffsets[c + 1] += cellOffsets[c];
  }
  std::vector<int> cellFunctions(cellOffsets[cells]);
  {
    std::vector<vtkIdType> fill(cellOffsets.begin(), cellOffsets.end() - 1);
    for (vtkIdType f = 0; f < nf; ++f)
    {
      forCells(f, [&](vtkIdType c) { cellFunctions[fill[c]++] = static_cast<int>(f); });
    }
  }
  // Functions per element (in increasing order, as registered).
  std::vector<vtkIdType> counts(ne + 1, 0);
  std::vector<std::vector<int>>& perElement = this->ElementLists;
  perElement.resize(ne);
  vtkSMPTools::For(0, ne,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType e = begin; e < end; ++e)
      {
        const double* b = patch.ElementBoxes.data() + 6 * e;
        const vtkIdType c =
          (static_cast<vtkIdType>(cellOf(b[2], 2)) * G[1] + cellOf(b[1], 1)) * G[0] +
          cellOf(b[0], 0);
        std::vector<int>& list = perElement[e];
        list.clear();
        for (vtkIdType s = cellOffsets[c]; s < cellOffsets[c + 1]; ++s)
        {
          const int f = cellFunctions[s];
          bool inside = true;
          for (int d = 0; d < 3 && inside; ++d)
          {
            const double* t = patch.GetKnots(f, d);
            inside = t[0] <= b[d] && b[d + 3] <= t[patch.Order[d]];
          }
          if (inside)
          {
            list.push_back(f);
          }
        }
        counts[e + 1] = static_cast<vtkIdType>(list.size());
      }
    });
  this->SupportOffsets.assign(ne + 1, 0);
  for (vtkIdType e = 0; e < ne; ++e)
  {
    this->SupportOffsets[e + 1] = this->SupportOffsets[e] + counts[e + 1];
  }
  this->SupportIds.resize(this->SupportOffsets[ne]);
  this->FunctionElementOffsets.assign(nf + 1, 0);
  for (vtkIdType e = 0; e < ne; ++e)
  {
    std::copy(perElement[e].begin(), perElement[e].end(),
      this->SupportIds.begin() + this->SupportOffsets[e]);
    for (int f : perElement[e])
    {
      ++this->FunctionElementOffsets[f + 1];
    }
  }
  for (vtkIdType f = 0; f < nf; ++f)
  {
    this->FunctionElementOffsets[f + 1] += this->FunctionElementOffsets[f];
  }
  this->FunctionElements.resize(this->FunctionElementOffsets[nf]);
  std::vector<vtkIdType> fill(
    this->FunctionElementOffsets.begin(), this->FunctionElementOffsets.end() - 1);
  for (vtkIdType e = 0; e < ne; ++e)
  {
    for (int f : perElement[e])
    {
      this->FunctionElements[fill[f]++] = e;
    }
  }
}

//------------------------------------------------------------------------------
void vtkLRSplineFitCore::BuildPattern(bool sorted)
{
  const vtkIdType nf = this->Builder.GetNumberOfBasisFunctions();
  // Functions overlap when they share an element (the lists are kept between
  // fits: their memory is reused).
  std::vector<std::vector<int>>& rows = this->Rows;
  rows.resize(nf);
  vtkSMPThreadLocal<std::vector<vtkIdType>> tlMark;
  vtkSMPTools::For(0, nf,
    [&](vtkIdType begin, vtkIdType end)
    {
      std::vector<vtkIdType>& mark = tlMark.Local();
      if (mark.size() != static_cast<std::size_t>(nf))
      {
        mark.assign(nf, -1);
      }
      for (vtkIdType f = begin; f < end; ++f)
      {
        std::vector<int>& row = rows[f];
        row.clear();
        for (vtkIdType k = this->FunctionElementOffsets[f]; k < this->FunctionElementOffsets[f + 1];
             ++k)
        {
          const vtkIdType e = this->FunctionElements[k];
          for (vtkIdType s = this->SupportOffsets[e]; s < this->SupportOffsets[e + 1]; ++s)
          {
            const vtkIdType g = this->SupportIds[s];
            if (mark[g] != f)
            {
              mark[g] = f;
              row.push_back(static_cast<int>(g));
            }
          }
        }
        if (sorted)
        {
          std::sort(row.begin(), row.end());
        }
      }
    });
  this->RowOffsets.assign(nf + 1, 0);
  for (vtkIdType f = 0; f < nf; ++f)
  {
    this->RowOffsets[f + 1] = this->RowOffsets[f] + static_cast<vtkIdType>(rows[f].size());
  }
  this->Columns.resize(this->RowOffsets[nf]);
  this->Entries.assign(this->RowOffsets[nf], 0.0);
  vtkSMPTools::For(0, nf,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType f = begin; f < end; ++f)
      {
        std::copy(rows[f].begin(), rows[f].end(), this->Columns.begin() + this->RowOffsets[f]);
      }
    });
}

//------------------------------------------------------------------------------
void vtkLRSplineFitCore::Regularize(const std::vector<double>& weight, double regularization,
  double littleData, std::vector<double>& diagonal, std::vector<double>& delta)
{
  const std::size_t nf = diagonal.size();
  delta.resize(nf);
  for (std::size_t f = 0; f < nf; ++f)
  {
    const double little = std::max(0.0, 1.0 - weight[f] / littleData);
    delta[f] = diagonal[f] > 0 ? diagonal[f] * (Ridge + regularization * little) : 1.0;
    diagonal[f] += delta[f];
  }
}

//------------------------------------------------------------------------------
namespace
{
constexpr int MaxOrder = vtkLRSplineBezierVolume::MaximumDegree + 1;

// Gauss-Legendre nodes and weights of n points on [0, 1] (exact for
// polynomials of degree 2n - 1): Newton's method on the Legendre polynomial.
void GaussLegendre(int n, double* x, double* w)
{
  const double pi = 3.14159265358979323846;
  for (int i = 0; i < n; ++i)
  {
    double z = std::cos(pi * (i + 0.75) / (n + 0.5));
    double slope = 1.0;
    for (int iteration = 0; iteration < 100; ++iteration)
    {
      double p1 = 1.0, p0 = 0.0;
      for (int j = 1; j <= n; ++j)
      {
        const double pm = p0;
        p0 = p1;
        p1 = ((2.0 * j - 1.0) * z * p0 - (j - 1.0) * pm) / j;
      }
      slope = n * (z * p1 - p0) / (z * z - 1.0);
      const double step = p1 / slope;
      z -= step;
      if (std::abs(step) < 1e-16)
      {
        break;
      }
    }
    x[i] = 0.5 * (1.0 - z);
    w[i] = 1.0 / ((1.0 - z * z) * slope * slope);
  }
}

// The k-th derivative at s in [0, 1] of the polynomial with Bernstein
// coefficients c[0..p]: p!/(p-k)! times the Bernstein polynomial of degree
// p - k of the k-th forward differences (de Casteljau).
double BernsteinDerivative(const double* c, int p, int k, double s)
{
  if (k > p)
  {
    return 0.0;
  }
  double d[MaxOrder];
  std::copy(c, c + p + 1, d);
  double factor = 1.0;
  for (int j = 0; j < k; ++j)
  {
    factor *= p - j;
    for (int i = 0; i < p - j; ++i)
    {
      d[i] = d[i + 1] - d[i];
    }
  }
  const int n = p - k;
  for (int r = 1; r <= n; ++r)
  {
    for (int i = 0; i <= n - r; ++i)
    {
      d[i] = (1.0 - s) * d[i] + s * d[i + 1];
    }
  }
  return factor * d[0];
}
}

//------------------------------------------------------------------------------
bool vtkLRSplineFitCore::AddElementSmoothing(const vtkLRSplinePatch& patch, vtkIdType e,
  double smoothing, double* local, std::string* error) const
{
  const double* box = &patch.ElementBoxes[6 * e];
  const vtkIdType first = this->SupportOffsets[e];
  const int count = static_cast<int>(this->SupportOffsets[e + 1] - first);
  // Per direction: the Gauss points, and for every function the value, first
  // and second derivative (in s) of its univariate factor at each of them.
  // Gauss-Legendre rules of 1..MaxOrder points, computed once.
  struct Rules
  {
    double X[MaxOrder + 1][MaxOrder], W[MaxOrder + 1][MaxOrder];
    Rules()
    {
      for (int n = 1; n <= MaxOrder; ++n)
      {
        GaussLegendre(n, this->X[n], this->W[n]);
      }
    }
  };
  static const Rules rules;
  const double* x[3];
  const double* w[3];
  int points[3];
  std::vector<double> table[3];
  for (int d = 0; d < 3; ++d)
  {
    const int order = patch.Order[d];
    points[d] = order;
    x[d] = rules.X[order];
    w[d] = rules.W[order];
    table[d].resize(static_cast<std::size_t>(count) * 3 * order);
    double bernstein[MaxOrder];
    for (int a = 0; a < count; ++a)
    {
      const vtkIdType f = this->SupportIds[first + a];
      if (!vtkLRSplinePatch::BSplineToBernstein(
            patch.GetKnots(f, d), order, box[d], box[d + 3], bernstein))
      {
        if (error)
        {
          *error = "basis function " + std::to_string(f) + " does not cover element " +
            std::to_string(e) + " in direction " + std::to_string(d);
        }
        return false;
      }
      for (int k = 0; k < 3; ++k)
      {
        for (int q = 0; q < order; ++q)
        {
          table[d][(a * 3 + k) * order + q] = BernsteinDerivative(bernstein, order - 1, k, x[d][q]);
        }
      }
    }
  }
  // M[d][k](a, b) = integral over [0, 1] of the k-th derivatives of the
  // factors of a and b in direction d.
  std::vector<double> m[3][3];
  for (int d = 0; d < 3; ++d)
  {
    const int n = points[d];
    for (int k = 0; k < 3; ++k)
    {
      std::vector<double>& mk = m[d][k];
      mk.assign(static_cast<std::size_t>(count) * count, 0.0);
      for (int a = 0; a < count; ++a)
      {
        const double* ta = &table[d][(a * 3 + k) * n];
        for (int b = a; b < count; ++b)
        {
          const double* tb = &table[d][(b * 3 + k) * n];
          double sum = 0.0;
          for (int q = 0; q < n; ++q)
          {
            sum += w[d][q] * ta[q] * tb[q];
          }
          mk[a * count + b] = mk[b * count + a] = sum;
        }
      }
    }
  }
  // The thin-plate energy is separable: u_ss^2 + v_ss^2 + w_ss^2 +
  // 2 (u_s v_s)^2 + 2 (u_s w_s)^2 + 2 (v_s w_s)^2 in terms of the factors.
  for (int a = 0; a < count; ++a)
  {
    const double ga = patch.Gamma[this->SupportIds[first + a]];
    for (int b = 0; b < count; ++b)
    {
      const std::size_t ab = static_cast<std::size_t>(a) * count + b;
      const double energy = m[0][2][ab] * m[1][0][ab] * m[2][0][ab] +
        m[0][0][ab] * m[1][2][ab] * m[2][0][ab] + m[0][0][ab] * m[1][0][ab] * m[2][2][ab] +
        2.0 *
          (m[0][1][ab] * m[1][1][ab] * m[2][0][ab] + m[0][1][ab] * m[1][0][ab] * m[2][1][ab] +
            m[0][0][ab] * m[1][1][ab] * m[2][1][ab]);
      local[ab] += smoothing * ga * patch.Gamma[this->SupportIds[first + b]] * energy;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
int vtkLRSplineFitCore::Solve(const std::vector<double>& rhsData, const std::vector<double>& prior,
  const std::vector<double>& delta, const std::vector<double>& diagonal, double target,
  std::vector<double>& x) const
{
  const vtkIdType nf = static_cast<vtkIdType>(prior.size());
  // q = (A + D) v
  auto multiply = [&](const std::vector<double>& v, std::vector<double>& q)
  {
    vtkSMPTools::For(0, nf,
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType f = begin; f < end; ++f)
        {
          double s = delta[f] * v[f];
          for (vtkIdType k = this->RowOffsets[f]; k < this->RowOffsets[f + 1]; ++k)
          {
            s += this->Entries[k] * v[this->Columns[k]];
          }
          q[f] = s;
        }
      });
  };
  std::vector<double> rhs(nf);
  for (vtkIdType f = 0; f < nf; ++f)
  {
    rhs[f] = rhsData[f] + delta[f] * prior[f];
  }
  x = prior;
  std::vector<double> r(nf), z(nf), p(nf), q(nf);
  multiply(x, q);
  for (vtkIdType f = 0; f < nf; ++f)
  {
    r[f] = rhs[f] - q[f];
    z[f] = r[f] / diagonal[f];
  }
  p = z;
  double rz = Dot(r, z);
  // Stop when the error of the data values the solve leaves,
  // ||Phi (c_k - c*)||_2 <= ||c_k - c*||_(A+D), is below target: the error in
  // that norm is estimated from the last SolverDelay steps (Hestenes-Stiefel;
  // Strakos and Tichy 2002: ||e_k||^2 = sum_{j>=k} alpha_j r_j.z_j). Or at
  // the rounding level.
  const double floor = 1e-14 * std::sqrt(Dot(rhs, rhs));
  std::vector<double> terms;
  int it = 0;
  for (; it < SolverMaximumIterations; ++it)
  {
    if (terms.size() >= static_cast<std::size_t>(SolverDelay))
    {
      double estimate = 0.0;
      for (std::size_t j = terms.size() - SolverDelay; j < terms.size(); ++j)
      {
        estimate += terms[j];
      }
      if (std::sqrt(estimate) <= target)
      {
        break;
      }
    }
    if (std::sqrt(Dot(r, r)) <= floor)
    {
      break;
    }
    multiply(p, q);
    const double pq = Dot(p, q);
    if (!(pq > 0))
    {
      break;
    }
    const double alpha = rz / pq;
    terms.push_back(alpha * rz);
    vtkSMPTools::For(0, nf,
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType f = begin; f < end; ++f)
        {
          x[f] += alpha * p[f];
          r[f] -= alpha * q[f];
          z[f] = r[f] / diagonal[f];
        }
      });
    const double rzNew = Dot(r, z);
    const double beta = rzNew / rz;
    rz = rzNew;
    vtkSMPTools::For(0, nf,
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType f = begin; f < end; ++f)
        {
          p[f] = z[f] + beta * p[f];
        }
      });
  }
  return it;
}

//------------------------------------------------------------------------------
std::string vtkLRSplineFitCore::StopReason(
  Outcome outcome, vtkIdType maximumElements, const std::string& limits)
{
  switch (outcome)
  {
    case ELEMENT_LIMIT:
      return "MaximumNumberOfElements (" + std::to_string(maximumElements) + ") was reached";
    case NOTHING_REFINABLE:
      return "the elements above the tolerance are at " + limits;
    case NO_PROGRESS:
      return "the refinement did not split any element";
    default:
      return std::string();
  }
}

//------------------------------------------------------------------------------
int vtkLRSplineFitCore::Levels()
{
  const vtkLRSplinePatch& patch = this->Builder.GetPatch();
  int levels = 0;
  const vtkIdType ne = patch.GetNumberOfElements();
  for (vtkIdType e = 0; e < ne; ++e)
  {
    const double* b = patch.ElementBoxes.data() + 6 * e;
    for (int d = 0; d < 3; ++d)
    {
      const double ratio = this->InitialSide[d] / (b[d + 3] - b[d]);
      levels = std::max(levels, static_cast<int>(std::lround(std::log2(ratio))));
    }
  }
  return levels;
}

//------------------------------------------------------------------------------
// Mark the elements above the tolerance and refine on each the basis function
// of smallest support that can still be refined (the element itself may be as
// small as allowed while larger functions on it are not).
vtkLRSplineFitCore::Outcome vtkLRSplineFitCore::Refine(const std::vector<double>& elementError,
  double tolerance, vtkIdType maximumElements, std::string* error)
{
  const vtkLRSplinePatch& patch = this->Builder.GetPatch();
  const vtkIdType ne = patch.GetNumberOfElements();
  const vtkIdType nf = patch.GetNumberOfBasisFunctions();
  std::vector<vtkIdType> marked;
  for (vtkIdType e = 0; e < ne; ++e)
  {
    if (elementError[e] > tolerance)
    {
      marked.push_back(e);
    }
  }
  std::stable_sort(marked.begin(), marked.end(),
    [&elementError](vtkIdType a, vtkIdType b) { return elementError[a] > elementError[b]; });
  std::vector<signed char> splittable(nf, -1);
  auto canSplit = [&](vtkIdType f)
  {
    if (splittable[f] < 0)
    {
      splittable[f] = 0;
      for (int d = 0; d < 3 && !splittable[f]; ++d)
      {
        const double* t = patch.GetKnots(f, d);
        for (int k = 0; k < patch.Order[d] && !splittable[f]; ++k)
        {
          double z;
          splittable[f] = vtkLRSplineBuilder::SplitValue(t[k], t[k + 1], d, this->Options, &z);
        }
      }
    }
    return splittable[f] != 0;
  };
  std::vector<char> chosen(nf, 0);
  std::vector<vtkIdType> functions;
  vtkIdType estimate = ne;
  bool limited = false;
  std::vector<vtkIdType> picks;
  for (vtkIdType e : marked)
  {
    // An element that can still be split: the smallest function on it that
    // can be refined (local). One that cannot: every function on it that
    // can (more freedom where the smallest elements are not enough).
    const double* b = patch.ElementBoxes.data() + 6 * e;
    bool small = true;
    for (int d = 0; d < 3 && small; ++d)
    {
      double z;
      small = !vtkLRSplineBuilder::SplitValue(b[d], b[d + 3], d, this->Options, &z);
    }
    picks.clear();
    vtkIdType best = -1;
    double bestVolume = 0.0, bestOffCentre = 0.0;
    for (vtkIdType s = this->SupportOffsets[e]; s < this->SupportOffsets[e + 1]; ++s)
    {
      const vtkIdType f = this->SupportIds[s];
      if (small)
      {
        if (canSplit(f))
        {
          picks.push_back(f);
        }
        continue;
      }
      // the smallest support; among equal ones the best centred on the
      // element (a choice that does not depend on the functions' order)
      double volume = 1.0, offCentre = 0.0;
      for (int d = 0; d < 3; ++d)
      {
        const double* t = patch.GetKnots(f, d);
        const double length = t[patch.Order[d]] - t[0];
        volume *= length;
        const double c = (0.5 * (t[0] + t[patch.Order[d]]) - 0.5 * (b[d] + b[d + 3])) / length;
        offCentre += c * c;
      }
      const bool smaller = best < 0 || volume < bestVolume * (1 - 1e-12) ||
        (volume <= bestVolume * (1 + 1e-12) && offCentre < bestOffCentre);
      if (smaller && canSplit(f))
      {
        best = f;
        bestVolume = volume;
        bestOffCentre = offCentre;
      }
    }
    if (best >= 0)
    {
      picks.push_back(best);
    }
    for (vtkIdType f : picks)
    {
      if (chosen[f])
      {
        continue;
      }
      // Each element of the support splits into at most 8.
      const vtkIdType added =
        7 * (this->FunctionElementOffsets[f + 1] - this->FunctionElementOffsets[f]);
      if (estimate + added > maximumElements)
      {
        limited = true;
        break;
      }
      estimate += added;
      chosen[f] = 1;
      functions.push_back(f);
    }
    if (limited)
    {
      break;
    }
  }
  if (functions.empty())
  {
    return limited ? ELEMENT_LIMIT : NOTHING_REFINABLE;
  }
  if (!this->Builder.RefineFunctions(functions, this->Options, error))
  {
    return FAILED;
  }
  if (this->Builder.GetNumberOfElements() == ne)
  {
    return NO_PROGRESS;
  }
  return REFINED;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkUnstructuredGrid> vtkLRSplineFitCore::BuildBlock(const vtkLRSplinePatch& patch,
  const vtkLRSplineBezierVolume& volume, int patchIndex, int piece, int numPieces,
  const double scale[3], const double offset[3], const std::string& fieldName,
  const std::string& sourceFormat, const std::vector<double>& elementError, const Report& report,
  std::string* error)
{
  vtkLRSplineBezierGrid::Options options;
  options.PatchIndex = patchIndex;
  const vtkIdType ne = patch.GetNumberOfElements();
  options.FirstElement = ne * piece / numPieces;
  options.LastElement = ne * (piece + 1) / numPieces;
  std::copy(scale, scale + 3, options.Scale);
  std::copy(offset, offset + 3, options.Offset);
  options.FieldName = fieldName;
  options.SourceFormat = sourceFormat;
  vtkLRSplineBezierVolume pieceVolume;
  std::copy(volume.Degree, volume.Degree + 3, pieceVolume.Degree);
  pieceVolume.NumberOfComponents = volume.NumberOfComponents;
  const std::size_t per =
    static_cast<std::size_t>(volume.GetCoefficientsPerElement()) * volume.NumberOfComponents;
  pieceVolume.Boxes.assign(volume.Boxes.begin() + 6 * options.FirstElement,
    volume.Boxes.begin() + 6 * options.LastElement);
  pieceVolume.Coefficients.assign(volume.Coefficients.begin() + per * options.FirstElement,
    volume.Coefficients.begin() + per * options.LastElement);
  vtkSmartPointer<vtkUnstructuredGrid> grid =
    vtkLRSplineBezierGrid::Build(patch, pieceVolume, options, error);
  if (!grid)
  {
    return nullptr;
  }
  vtkNew<vtkDoubleArray> errors;
  errors->SetName(vtkLRSplineArrayNames::FitElementMaxError);
  errors->SetNumberOfTuples(options.LastElement - options.FirstElement);
  for (vtkIdType e = options.FirstElement; e < options.LastElement; ++e)
  {
    errors->SetValue(e - options.FirstElement, elementError[e]);
  }
  grid->GetCellData()->AddArray(errors);
  vtkFieldData* fd = grid->GetFieldData();
  auto addDouble = [fd](const char* name, std::initializer_list<double> v)
  {
    vtkNew<vtkDoubleArray> a;
    a->SetName(name);
    a->SetNumberOfComponents(static_cast<int>(v.size()));
    a->InsertNextTuple(std::vector<double>(v).data());
    fd->AddArray(a);
  };
  auto addInt = [fd](const char* name, int v)
  {
    vtkNew<vtkIntArray> a;
    a->SetName(name);
    a->InsertNextValue(v);
    fd->AddArray(a);
  };
  addDouble(vtkLRSplineArrayNames::FitMaximumError, { report.MaximumError });
  addDouble(vtkLRSplineArrayNames::FitRMSError, { report.RMSError });
  addDouble(vtkLRSplineArrayNames::FitTolerance, { report.Tolerance });
  addInt(vtkLRSplineArrayNames::FitToleranceMet, report.ToleranceMet ? 1 : 0);
  addInt(vtkLRSplineArrayNames::FitIterations, report.Iterations);
  addInt(vtkLRSplineArrayNames::FitRefinementLevels, report.Levels);
  addDouble(vtkLRSplineArrayNames::FitDataRange, { report.DataRange[0], report.DataRange[1] });
  vtkNew<vtkDoubleArray> hist;
  hist->SetName(vtkLRSplineArrayNames::FitHistory);
  hist->SetNumberOfComponents(5);
  hist->SetComponentName(0, "Elements");
  hist->SetComponentName(1, "BasisFunctions");
  hist->SetComponentName(2, "MaximumError");
  hist->SetComponentName(3, "RMSError");
  hist->SetComponentName(4, "SolverIterations");
  hist->SetNumberOfTuples(static_cast<vtkIdType>(report.History.size() / 5));
  std::copy(report.History.begin(), report.History.end(), hist->GetPointer(0));
  fd->AddArray(hist);
  return grid;
}

//------------------------------------------------------------------------------
bool vtkLRSplineFitCore::WritePatches(
  const char* fileName, const std::vector<vtkLRSplinePatch>& patches, std::string* error)
{
  std::ofstream out(fileName, std::ios::out | std::ios::binary);
  for (const vtkLRSplinePatch& patch : patches)
  {
    patch.Write(out);
  }
  out.close();
  if (!out)
  {
    if (error)
    {
      *error = std::string("cannot write \"") + fileName + "\"";
    }
    return false;
  }
  return true;
}
