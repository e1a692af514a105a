// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLRSplinePatch.h"
#include "vtkSplineVizError.h"

#include "vtkLRSplineBezierVolume.h"
#include "vtkLRSplineElementLocator.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <iomanip>
#include <limits>
#include <mutex>
#include <ostream>
#include <sstream>

using vtkSplineVizError::Fail;

namespace
{
const char* DirName(int d)
{
  return d == 0 ? "u" : (d == 1 ? "v" : "w");
}

std::string Where(const std::vector<int>& lines, vtkIdType i)
{
  if (i >= 0 && static_cast<std::size_t>(i) < lines.size() && lines[i] > 0)
  {
    return "line " + std::to_string(lines[i]) + ": ";
  }
  return std::string();
}
}

//------------------------------------------------------------------------------
void vtkLRSplinePatch::GetDomain(double domain[6]) const
{
  for (int d = 0; d < 3; ++d)
  {
    domain[d] = std::numeric_limits<double>::infinity();
    domain[d + 3] = -std::numeric_limits<double>::infinity();
  }
  const vtkIdType n = this->GetNumberOfElements();
  for (vtkIdType e = 0; e < n; ++e)
  {
    const double* b = this->ElementBoxes.data() + 6 * e;
    for (int d = 0; d < 3; ++d)
    {
      domain[d] = std::min(domain[d], b[d]);
      domain[d + 3] = std::max(domain[d + 3], b[d + 3]);
    }
  }
}

//------------------------------------------------------------------------------
bool vtkLRSplinePatch::ApplyRationalMode(
  int mode, bool controlPoints, bool* inferred, std::string* error)
{
  if (inferred)
  {
    *inferred = false;
  }
  if (this->ExplicitRational)
  {
    return true;
  }
  bool rational = false;
  if (mode == RATIONAL_ALWAYS)
  {
    rational = true;
  }
  else if (mode == RATIONAL_AUTOMATIC && controlPoints)
  {
    rational = this->Rational == 1 || this->Dimension > this->ParametricDimension;
    if (inferred)
    {
      *inferred = this->Rational != 1 && rational;
    }
  }
  if (rational && this->Dimension < 2)
  {
    if (error)
    {
      *error = "a rational patch needs at least 2 coefficient components (the last is the weight), "
               "this one has " +
        std::to_string(this->Dimension);
    }
    return false;
  }
  this->RationalCoefficients = rational;
  return true;
}

//------------------------------------------------------------------------------
bool vtkLRSplinePatch::Validate(std::string* error) const
{
  for (int d = 0; d < 3; ++d)
  {
    if (this->Order[d] < 1 || this->Order[d] > vtkLRSplineBezierVolume::MaximumDegree + 1)
    {
      return Fail(error,
        "order " + std::to_string(this->Order[d]) + " in direction " + DirName(d) +
          " is not supported (1 to " + std::to_string(vtkLRSplineBezierVolume::MaximumDegree + 1) +
          ")");
    }
  }
  if (this->ParametricDimension != 2 && this->ParametricDimension != 3)
  {
    return Fail(error,
      "the parametric dimension must be 2 (surface) or 3 (volume), not " +
        std::to_string(this->ParametricDimension));
  }
  if (this->ParametricDimension == 2 && this->Order[2] != 1)
  {
    return Fail(error, "a surface patch must have order 1 in its third (w) direction");
  }
  if (this->Dimension < 1 || this->Dimension > 64)
  {
    return Fail(error,
      "the number of coefficient components must be 1 to 64, not " +
        std::to_string(this->Dimension));
  }
  if (this->RationalCoefficients && this->Dimension < 2)
  {
    return Fail(error,
      "a rational patch needs at least 2 coefficient components (the last is the "
      "weight)");
  }
  const vtkIdType nb = this->GetNumberOfBasisFunctions();
  const vtkIdType ne = this->GetNumberOfElements();
  if (nb < 1 || ne < 1)
  {
    return Fail(error, "a patch needs at least one basis function and one element");
  }
  if (static_cast<vtkIdType>(this->Knots.size()) != nb * this->GetKnotsPerFunction() ||
    static_cast<vtkIdType>(this->Coefficients.size()) != nb * this->Dimension)
  {
    return Fail(error, "inconsistent basis function arrays");
  }
  for (vtkIdType i = 0; i < nb; ++i)
  {
    for (int d = 0; d < 3; ++d)
    {
      const double* t = this->GetKnots(i, d);
      const int n = this->Order[d] + 1;
      for (int k = 0; k < n; ++k)
      {
        if (!std::isfinite(t[k]))
        {
          return Fail(error,
            Where(this->BasisLines, i) + "basis function " + std::to_string(i) + ": knot vector " +
              DirName(d) + " has a value that is not a finite number");
        }
        if (k > 0 && t[k] < t[k - 1])
        {
          return Fail(error,
            Where(this->BasisLines, i) + "basis function " + std::to_string(i) + ": knot vector " +
              DirName(d) + " is not non-decreasing");
        }
      }
      if (!(t[0] < t[n - 1]))
      {
        return Fail(error,
          Where(this->BasisLines, i) + "basis function " + std::to_string(i) + ": knot vector " +
            DirName(d) + " has an empty support");
      }
    }
    for (int c = 0; c < this->Dimension; ++c)
    {
      if (!std::isfinite(this->Coefficients[i * this->Dimension + c]))
      {
        return Fail(error,
          Where(this->BasisLines, i) + "basis function " + std::to_string(i) + ": coefficient " +
            std::to_string(c) + " is not a finite number");
      }
    }
    if (this->RationalCoefficients)
    {
      const double w = this->Coefficients[(i + 1) * this->Dimension - 1];
      if (!(w > 0))
      {
        return Fail(error,
          Where(this->BasisLines, i) + "basis function " + std::to_string(i) +
            ": the rational weight (the last coefficient component) must be positive, it is " +
            std::to_string(w));
      }
    }
    const double g = this->Gamma[i];
    if (!std::isfinite(g) || !(g > 0))
    {
      return Fail(error,
        Where(this->BasisLines, i) + "basis function " + std::to_string(i) +
          ": the scaling weight gamma must be a positive finite number");
    }
  }
  for (vtkIdType e = 0; e < ne; ++e)
  {
    const double* b = this->ElementBoxes.data() + 6 * e;
    for (int d = 0; d < 3; ++d)
    {
      if (!std::isfinite(b[d]) || !std::isfinite(b[d + 3]))
      {
        return Fail(error,
          Where(this->ElementLines, e) + "element " + std::to_string(e) +
            ": a corner is not a finite number");
      }
      if (!(b[d] < b[d + 3]))
      {
        return Fail(error,
          Where(this->ElementLines, e) + "element " + std::to_string(e) +
            ": the box is empty in direction " + DirName(d));
      }
    }
  }
  if (!this->FileSupportOffsets.empty())
  {
    if (static_cast<vtkIdType>(this->FileSupportOffsets.size()) != ne + 1)
    {
      return Fail(error, "inconsistent element support arrays");
    }
    for (vtkIdType e = 0; e < ne; ++e)
    {
      for (vtkIdType k = this->FileSupportOffsets[e]; k < this->FileSupportOffsets[e + 1]; ++k)
      {
        if (this->FileSupport[k] < 0 || this->FileSupport[k] >= nb)
        {
          return Fail(error,
            Where(this->ElementLines, e) + "element " + std::to_string(e) +
              ": basis function index " + std::to_string(this->FileSupport[k]) +
              " is out of range (there are " + std::to_string(nb) + ")");
        }
      }
    }
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkLRSplinePatch::ComputeSupports(
  std::vector<vtkIdType>& offsets, std::vector<vtkIdType>& ids, std::string* error) const
{
  const vtkIdType ne = this->GetNumberOfElements();
  vtkLRSplineElementLocator tree;
  std::string locError;
  if (!tree.Build(
        this->ElementBoxes.data(), ne, vtkLRSplineElementLocator::KD_TREE, nullptr, &locError))
  {
    if (error)
    {
      *error = locError;
    }
    return false;
  }
  std::vector<std::vector<vtkIdType>> perFunction;
  return this->CheckElementsTile(tree, error) &&
    this->FindSupportElements(tree, perFunction, error) &&
    this->InvertSupports(perFunction, offsets, ids, error) &&
    this->CheckFileSupports(offsets, ids, error);
}

//------------------------------------------------------------------------------
bool vtkLRSplinePatch::CheckElementsTile(
  const vtkLRSplineElementLocator& tree, std::string* error) const
{
  const vtkIdType ne = this->GetNumberOfElements();
  double domain[6];
  this->GetDomain(domain);

  // The elements must tile the domain: no two overlap, and the volumes add up.
  // (the smallest overlapping element is reported, with the one it overlaps)
  std::atomic<vtkIdType> overlapping(ne);
  vtkSMPThreadLocal<std::vector<vtkIdType>> tlHits;
  vtkSMPTools::For(0, ne,
    [&](vtkIdType begin, vtkIdType end)
    {
      std::vector<vtkIdType>& hits = tlHits.Local();
      for (vtkIdType e = begin; e < end && e < overlapping.load(); ++e)
      {
        tree.FindElementsIntersecting(this->ElementBoxes.data() + 6 * e, hits);
        if (hits.size() != 1)
        {
          vtkIdType current = overlapping.load();
          while (e < current && !overlapping.compare_exchange_weak(current, e))
          {
          }
        }
      }
    });
  if (overlapping.load() < ne)
  {
    const vtkIdType e = overlapping.load();
    std::vector<vtkIdType> hits;
    tree.FindElementsIntersecting(this->ElementBoxes.data() + 6 * e, hits);
    vtkIdType other = -1;
    for (vtkIdType h : hits)
    {
      if (h != e)
      {
        other = h;
        break;
      }
    }
    std::string msg = Where(this->ElementLines, e) + "element " + std::to_string(e) + " overlaps";
    if (other >= 0)
    {
      msg += " element " + std::to_string(other);
      if (static_cast<std::size_t>(other) < this->ElementLines.size())
      {
        msg += " (line " + std::to_string(this->ElementLines[other]) + ")";
      }
    }
    else
    {
      msg += " another element";
    }
    return Fail(error, msg);
  }
  double volume = 0.0;
  for (vtkIdType e = 0; e < ne; ++e)
  {
    const double* b = this->ElementBoxes.data() + 6 * e;
    volume += (b[3] - b[0]) * (b[4] - b[1]) * (b[5] - b[2]);
  }
  const double domainVolume =
    (domain[3] - domain[0]) * (domain[4] - domain[1]) * (domain[5] - domain[2]);
  if (!(std::abs(volume - domainVolume) <= 1e-9 * domainVolume))
  {
    return Fail(error, "the elements do not fill their bounding box (there are holes in the mesh)");
  }

  return true;
}

//------------------------------------------------------------------------------
bool vtkLRSplinePatch::FindSupportElements(const vtkLRSplineElementLocator& tree,
  std::vector<std::vector<vtkIdType>>& perFunction, std::string* error) const
{
  const vtkIdType nb = this->GetNumberOfBasisFunctions();
  vtkSMPThreadLocal<std::vector<vtkIdType>> tlHits;
  // Elements in each basis function's support.
  perFunction.assign(nb, std::vector<vtkIdType>());
  std::atomic<vtkIdType> badFunction(-1);
  std::atomic<vtkIdType> badElement(-1);
  vtkSMPTools::For(0, nb,
    [&](vtkIdType begin, vtkIdType end)
    {
      std::vector<vtkIdType>& hits = tlHits.Local();
      for (vtkIdType i = begin; i < end && badFunction.load() < 0; ++i)
      {
        double box[6];
        for (int d = 0; d < 3; ++d)
        {
          const double* t = this->GetKnots(i, d);
          box[d] = t[0];
          box[d + 3] = t[this->Order[d]];
        }
        tree.FindElementsIntersecting(box, hits);
        double covered = 0.0;
        for (vtkIdType e : hits)
        {
          const double* b = this->ElementBoxes.data() + 6 * e;
          bool inside = true;
          for (int d = 0; d < 3; ++d)
          {
            inside = inside && b[d] >= box[d] && b[d + 3] <= box[d + 3];
          }
          if (!inside)
          {
            vtkIdType expected = -1;
            if (badFunction.compare_exchange_strong(expected, i))
            {
              badElement = e;
            }
            break;
          }
          covered += (b[3] - b[0]) * (b[4] - b[1]) * (b[5] - b[2]);
        }
        const double supportVolume = (box[3] - box[0]) * (box[4] - box[1]) * (box[5] - box[2]);
        if (badFunction.load() < 0 && !(std::abs(covered - supportVolume) <= 1e-9 * supportVolume))
        {
          vtkIdType expected = -1;
          badFunction.compare_exchange_strong(expected, i);
        }
        perFunction[i] = hits;
      }
    });
  if (badFunction.load() >= 0)
  {
    const vtkIdType i = badFunction.load();
    std::string msg = Where(this->BasisLines, i) + "basis function " + std::to_string(i) +
      ": its support (the box of its knot vectors) ";
    if (badElement.load() >= 0)
    {
      msg += "cuts through element " + std::to_string(badElement.load()) +
        " (the knots do not match the mesh)";
    }
    else
    {
      msg += "is not covered by elements (it reaches outside the mesh)";
    }
    return Fail(error, msg);
  }

  return true;
}

//------------------------------------------------------------------------------
bool vtkLRSplinePatch::InvertSupports(const std::vector<std::vector<vtkIdType>>& perFunction,
  std::vector<vtkIdType>& offsets, std::vector<vtkIdType>& ids, std::string* error) const
{
  const vtkIdType nb = this->GetNumberOfBasisFunctions();
  const vtkIdType ne = this->GetNumberOfElements();
  // Invert to per-element lists (ascending function index).
  offsets.assign(ne + 1, 0);
  for (vtkIdType i = 0; i < nb; ++i)
  {
    for (vtkIdType e : perFunction[i])
    {
      ++offsets[e + 1];
    }
  }
  for (vtkIdType e = 0; e < ne; ++e)
  {
    offsets[e + 1] += offsets[e];
  }
  ids.assign(offsets[ne], 0);
  std::vector<vtkIdType> fill(offsets.begin(), offsets.end() - 1);
  for (vtkIdType i = 0; i < nb; ++i)
  {
    for (vtkIdType e : perFunction[i])
    {
      ids[fill[e]++] = i;
    }
  }
  for (vtkIdType e = 0; e < ne; ++e)
  {
    if (offsets[e + 1] == offsets[e])
    {
      return Fail(error,
        Where(this->ElementLines, e) + "element " + std::to_string(e) +
          " is not in the support of any basis function");
    }
  }

  return true;
}

//------------------------------------------------------------------------------
bool vtkLRSplinePatch::CheckFileSupports(const std::vector<vtkIdType>& offsets,
  const std::vector<vtkIdType>& ids, std::string* error) const
{
  const vtkIdType ne = this->GetNumberOfElements();
  // The file's lists, when given, must say the same.
  if (!this->FileSupportOffsets.empty())
  {
    std::vector<vtkIdType> mine, theirs;
    for (vtkIdType e = 0; e < ne; ++e)
    {
      mine.assign(ids.begin() + offsets[e], ids.begin() + offsets[e + 1]);
      theirs.assign(this->FileSupport.begin() + this->FileSupportOffsets[e],
        this->FileSupport.begin() + this->FileSupportOffsets[e + 1]);
      std::sort(theirs.begin(), theirs.end());
      if (mine != theirs)
      {
        std::ostringstream msg;
        msg << Where(this->ElementLines, e) << "element " << e << " lists " << theirs.size()
            << " basis functions in its support, but the knot vectors give " << mine.size();
        std::vector<vtkIdType> diff;
        std::set_symmetric_difference(
          mine.begin(), mine.end(), theirs.begin(), theirs.end(), std::back_inserter(diff));
        if (!diff.empty())
        {
          msg << " (basis function " << diff[0];
          if (static_cast<std::size_t>(diff[0]) < this->BasisLines.size())
          {
            msg << " on line " << this->BasisLines[diff[0]];
          }
          msg << " differs)";
        }
        return Fail(error, msg.str());
      }
    }
  }
  return true;
}

//------------------------------------------------------------------------------
double vtkLRSplinePatch::BSplineValue(const double* t, int order, double x, bool fromLeft)
{
  constexpr int M = vtkLRSplineBezierVolume::MaximumDegree + 1;
  double N[M];
  const int p = order - 1;
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

//------------------------------------------------------------------------------
bool vtkLRSplinePatch::BSplineToBernstein(
  const double* t, int order, double a, double b, double* out)
{
  const int p = order - 1;
  if (p == 0)
  {
    if (a >= t[0] && b <= t[1] && t[0] < t[1])
    {
      out[0] = 1.0;
      return true;
    }
    return false;
  }
  int m = -1;
  for (int j = 0; j <= p; ++j)
  {
    if (t[j] < t[j + 1] && t[j] <= a && b <= t[j + 1])
    {
      m = j;
      break;
    }
  }
  const double L = t[p + 1] - t[0];
  if (m < 0 || !(L > 0) || !(a < b))
  {
    return false;
  }
  // Extended knot sequence: p pads on either side (their values do not change
  // the result, they only keep the denominators positive).
  constexpr int MaxP = vtkLRSplineBezierVolume::MaximumDegree;
  double E[3 * MaxP + 2];
  for (int i = 0; i < p; ++i)
  {
    E[i] = t[0] - (p - i) * L;
    E[2 * p + 2 + i] = t[p + 1] + (i + 1) * L;
  }
  for (int i = 0; i <= p + 1; ++i)
  {
    E[p + i] = t[i];
  }
  const int mu = m + p; // E[mu] <= a < b <= E[mu + 1]
  double dd[MaxP + 1];
  for (int k = 0; k <= p; ++k)
  {
    // Blossom at (a^(p-k), b^k) by de Boor's recurrence with one argument per level.
    for (int i = 0; i <= p; ++i)
    {
      dd[i] = (mu - p + i == p) ? 1.0 : 0.0; // dd[i] holds d_{mu-p+i}
    }
    for (int r = 1; r <= p; ++r)
    {
      const double u = (r <= p - k) ? a : b;
      for (int i = mu; i >= mu - p + r; --i)
      {
        const double alpha = (u - E[i]) / (E[i + p + 1 - r] - E[i]);
        const int li = i - (mu - p);
        dd[li] = (1.0 - alpha) * dd[li - 1] + alpha * dd[li];
      }
    }
    out[k] = dd[p];
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkLRSplinePatch::ExtractBezier(vtkLRSplineBezierVolume& out, std::string* error,
  std::string* warning, vtkIdType first, vtkIdType last, const double* coefficients,
  int numberOfComponents) const
{
  if (!this->Validate(error))
  {
    return false;
  }
  std::vector<vtkIdType> offsets, ids;
  if (!this->ComputeSupports(offsets, ids, error))
  {
    return false;
  }
  const vtkIdType ne = this->GetNumberOfElements();
  if (last < 0 || last > ne)
  {
    last = ne;
  }
  first = std::max<vtkIdType>(0, std::min(first, last));
  const vtkIdType count = last - first;

  if (coefficients && numberOfComponents < 1)
  {
    return Fail(error, "the coefficients to extract have no components");
  }
  const int nc = coefficients ? numberOfComponents : this->Dimension;
  const double* source = coefficients ? coefficients : this->Coefficients.data();
  for (int d = 0; d < 3; ++d)
  {
    out.Degree[d] = this->Order[d] - 1;
  }
  out.NumberOfComponents = nc;
  const int nu = this->Order[0], nv = this->Order[1], nw = this->Order[2];
  const int per = nu * nv * nw;
  out.Boxes.assign(this->ElementBoxes.begin() + 6 * first, this->ElementBoxes.begin() + 6 * last);
  out.Coefficients.assign(static_cast<std::size_t>(count) * per * nc, 0.0);
  out.CoefficientsFloat.clear();

  std::atomic<vtkIdType> badElement(-1), badFunction(-1);
  std::mutex unityMutex;
  double worstUnity = 0.0;
  vtkIdType worstElement = -1;
  vtkSMPTools::For(0, count,
    [&](vtkIdType begin, vtkIdType end)
    {
      constexpr int M = vtkLRSplineBezierVolume::MaximumDegree + 1;
      double bu[M], bv[M], bw[M];
      std::vector<double> unity(per);
      double localWorst = 0.0;
      vtkIdType localWorstElement = -1;
      for (vtkIdType le = begin; le < end; ++le)
      {
        const vtkIdType e = first + le;
        const double* box = this->ElementBoxes.data() + 6 * e;
        double* dst = out.Coefficients.data() + static_cast<std::size_t>(le) * per * nc;
        std::fill(unity.begin(), unity.end(), 0.0);
        for (vtkIdType s = offsets[e]; s < offsets[e + 1]; ++s)
        {
          const vtkIdType f = ids[s];
          if (!BSplineToBernstein(this->GetKnots(f, 0), nu, box[0], box[3], bu) ||
            !BSplineToBernstein(this->GetKnots(f, 1), nv, box[1], box[4], bv) ||
            !BSplineToBernstein(this->GetKnots(f, 2), nw, box[2], box[5], bw))
          {
            vtkIdType expected = -1;
            if (badElement.compare_exchange_strong(expected, e))
            {
              badFunction = f;
            }
            return;
          }
          const double g = this->Gamma[f];
          const double* c = source + static_cast<std::size_t>(f) * nc;
          for (int k = 0; k < nw; ++k)
          {
            for (int j = 0; j < nv; ++j)
            {
              const double gjk = g * bv[j] * bw[k];
              for (int i = 0; i < nu; ++i)
              {
                const double w = gjk * bu[i];
                const int idx = (k * nv + j) * nu + i;
                unity[idx] += w;
                double* o = dst + static_cast<std::size_t>(idx) * nc;
                for (int comp = 0; comp < nc; ++comp)
                {
                  o[comp] += w * c[comp];
                }
              }
            }
          }
        }
        for (int idx = 0; idx < per; ++idx)
        {
          const double dev = std::abs(unity[idx] - 1.0);
          if (dev > localWorst)
          {
            localWorst = dev;
            localWorstElement = e;
          }
        }
      }
      std::lock_guard<std::mutex> lock(unityMutex);
      if (localWorst > worstUnity)
      {
        worstUnity = localWorst;
        worstElement = localWorstElement;
      }
    });
  if (badElement.load() >= 0)
  {
    const vtkIdType e = badElement.load();
    return Fail(error,
      Where(this->ElementLines, e) + "element " + std::to_string(e) +
        " is not inside one knot interval of basis function " + std::to_string(badFunction.load()) +
        (static_cast<std::size_t>(badFunction.load()) < this->BasisLines.size()
            ? " on line " + std::to_string(this->BasisLines[badFunction.load()])
            : std::string()) +
        " (the knot vectors do not match the mesh)");
  }
  if (warning)
  {
    warning->clear();
    if (worstUnity > 1e-8)
    {
      std::ostringstream msg;
      msg << Where(this->ElementLines, worstElement) << "the scaled basis (gamma_i B_i) is not a "
          << "partition of unity on element " << worstElement << " (off by " << worstUnity
          << "): the gamma values may be wrong";
      *warning = msg.str();
    }
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkLRSplinePatch::Write(std::ostream& os) const
{
  const std::streamsize oldPrecision = os.precision();
  os << std::setprecision(17);
  std::vector<vtkIdType> offsets, ids;
  std::string error;
  const bool haveSupports = this->ComputeSupports(offsets, ids, &error);
  const vtkIdType nb = this->GetNumberOfBasisFunctions();
  const vtkIdType ne = this->GetNumberOfElements();
  const vtkIdType nr = static_cast<vtkIdType>(this->MeshMultiplicities.size());
  const int pd = this->ParametricDimension == 2 ? 2 : 3;
  if (pd == 3)
  {
    os << "# LRSPLINE VOLUME\n";
    os << "#\tp1\tp2\tp3\tNbasis\tNline\tNel\tdim\trat\n";
  }
  else
  {
    os << "# LRSPLINE SURFACE\n";
    os << "#\tp1\tp2\tNbasis\tNline\tNel\tdim\trat\n";
  }
  os << "\t";
  for (int d = 0; d < pd; ++d)
  {
    os << this->Order[d] << "\t";
  }
  os << nb << "\t" << nr << "\t" << ne << "\t" << this->Dimension << "\t" << this->Rational << "\n";
  os << "# Basis functions:\n";
  for (vtkIdType i = 0; i < nb; ++i)
  {
    os << i << ":";
    for (int d = 0; d < pd; ++d)
    {
      os << (d ? " x [" : " [");
      const double* t = this->GetKnots(i, d);
      for (int k = 0; k <= this->Order[d]; ++k)
      {
        os << t[k] << " ";
      }
      os << "]";
    }
    for (int c = 0; c < this->Dimension; ++c)
    {
      os << " " << this->Coefficients[i * this->Dimension + c];
    }
    os << " (" << this->Gamma[i] << ")\n";
  }
  os << (pd == 3 ? "# Mesh rectangles:\n" : "# Mesh lines:\n");
  for (vtkIdType r = 0; r < nr; ++r)
  {
    const double* m = this->MeshRectangles.data() + 6 * r;
    if (pd == 3)
    {
      os << "[" << m[0] << ", " << m[3] << "] x [" << m[1] << ", " << m[4] << "] x [" << m[2]
         << ", " << m[5] << "]";
    }
    else if (m[0] == m[3]) // u constant
    {
      os << m[0] << " x [" << m[1] << ", " << m[4] << "]";
    }
    else
    {
      os << "[" << m[0] << ", " << m[3] << "] x " << m[1];
    }
    os << " (" << this->MeshMultiplicities[r] << ")\n";
  }
  os << "# Elements:\n";
  for (vtkIdType e = 0; e < ne; ++e)
  {
    const double* b = this->ElementBoxes.data() + 6 * e;
    os << e << " [" << pd << "] : (";
    for (int d = 0; d < pd; ++d)
    {
      os << (d ? ", " : "") << b[d];
    }
    os << ") x (";
    for (int d = 0; d < pd; ++d)
    {
      os << (d ? ", " : "") << b[d + 3];
    }
    os << ")    {";
    if (haveSupports)
    {
      for (vtkIdType k = offsets[e]; k < offsets[e + 1]; ++k)
      {
        os << (k > offsets[e] ? ", " : "") << ids[k];
      }
    }
    os << "}\n";
  }
  os << std::setprecision(static_cast<int>(oldPrecision));
}
