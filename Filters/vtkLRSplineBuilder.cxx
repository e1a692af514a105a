// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLRSplineBuilder.h"
#include "vtkSplineVizError.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <queue>

using vtkSplineVizError::Fail;

namespace
{
void OtherDirections(int dir, int& e1, int& e2)
{
  e1 = dir == 0 ? 1 : 0;
  e2 = dir == 2 ? 1 : 2;
}
}

//------------------------------------------------------------------------------
std::string vtkLRSplineBuilder::Key(const double* knots) const
{
  return std::string(reinterpret_cast<const char*>(knots),
    sizeof(double) * static_cast<std::size_t>(this->Patch.GetKnotsPerFunction()));
}

//------------------------------------------------------------------------------
bool vtkLRSplineBuilder::InitializeTensorProduct(
  const int degree[3], const std::vector<double> breaks[3], int dimension, std::string* error)
{
  this->Patch = vtkLRSplinePatch();
  this->Alive.clear();
  this->Index.clear();
  this->NumberAlive = 0;
  for (auto& p : this->Planes)
  {
    p.clear();
  }
  if (dimension < 1 || dimension > 64)
  {
    return Fail(error, "dimension must be 1 to 64");
  }
  std::vector<double> knots[3];
  for (int d = 0; d < 3; ++d)
  {
    if (degree[d] < 0 || degree[d] > 15 || breaks[d].size() < 2)
    {
      return Fail(error, "invalid degree or breakpoints");
    }
    for (std::size_t k = 1; k < breaks[d].size(); ++k)
    {
      if (!(breaks[d][k] > breaks[d][k - 1]))
      {
        return Fail(error, "breakpoints must increase");
      }
    }
    this->Patch.Order[d] = degree[d] + 1;
    for (std::size_t k = 0; k < breaks[d].size(); ++k)
    {
      const int mult = (k == 0 || k + 1 == breaks[d].size()) ? degree[d] + 1 : 1;
      knots[d].insert(knots[d].end(), mult, breaks[d][k]);
    }
  }
  this->Patch.Dimension = dimension;
  const std::size_t n[3] = { knots[0].size() - degree[0] - 1, knots[1].size() - degree[1] - 1,
    knots[2].size() - degree[2] - 1 };
  std::vector<double> local;
  std::vector<double> zero(dimension, 0.0);
  for (std::size_t k = 0; k < n[2]; ++k)
  {
    for (std::size_t j = 0; j < n[1]; ++j)
    {
      for (std::size_t i = 0; i < n[0]; ++i)
      {
        const std::size_t idx[3] = { i, j, k };
        local.clear();
        for (int d = 0; d < 3; ++d)
        {
          local.insert(
            local.end(), knots[d].begin() + idx[d], knots[d].begin() + idx[d] + degree[d] + 2);
        }
        this->AddFunction(local.data(), zero.data(), 1.0);
      }
    }
  }
  for (std::size_t k = 0; k + 1 < breaks[2].size(); ++k)
  {
    for (std::size_t j = 0; j + 1 < breaks[1].size(); ++j)
    {
      for (std::size_t i = 0; i + 1 < breaks[0].size(); ++i)
      {
        this->Patch.ElementBoxes.insert(this->Patch.ElementBoxes.end(),
          { breaks[0][i], breaks[1][j], breaks[2][k], breaks[0][i + 1], breaks[1][j + 1],
            breaks[2][k + 1] });
      }
    }
  }
  for (int d = 0; d < 3; ++d)
  {
    int e1, e2;
    OtherDirections(d, e1, e2);
    for (double z : breaks[d])
    {
      this->Planes[d][z].push_back(
        Rect2{ breaks[e1].front(), breaks[e1].back(), breaks[e2].front(), breaks[e2].back() });
    }
  }
  return true;
}

//------------------------------------------------------------------------------
vtkIdType vtkLRSplineBuilder::AddFunction(const double* knots, const double* coeff, double gamma)
{
  const std::string key = this->Key(knots);
  auto it = this->Index.find(key);
  const int dim = this->Patch.Dimension;
  if (it != this->Index.end())
  {
    const vtkIdType g = it->second;
    const double old = this->Patch.Gamma[g];
    const double neu = old + gamma;
    for (int c = 0; c < dim; ++c)
    {
      double& cg = this->Patch.Coefficients[g * dim + c];
      cg = (old * cg + gamma * coeff[c]) / neu;
    }
    this->Patch.Gamma[g] = neu;
    return g;
  }
  const vtkIdType id = static_cast<vtkIdType>(this->Patch.Gamma.size());
  this->Patch.Knots.insert(
    this->Patch.Knots.end(), knots, knots + this->Patch.GetKnotsPerFunction());
  this->Patch.Coefficients.insert(this->Patch.Coefficients.end(), coeff, coeff + dim);
  this->Patch.Gamma.push_back(gamma);
  this->Alive.push_back(1);
  ++this->NumberAlive;
  this->Index.emplace(key, id);
  return id;
}

//------------------------------------------------------------------------------
void vtkLRSplineBuilder::SetCoefficientsFromGreville(
  const std::function<void(const double g[3], double* c)>& f)
{
  const vtkIdType n = static_cast<vtkIdType>(this->Patch.Gamma.size());
  for (vtkIdType i = 0; i < n; ++i)
  {
    if (!this->Alive[i])
    {
      continue;
    }
    double g[3];
    for (int d = 0; d < 3; ++d)
    {
      const double* t = this->Patch.GetKnots(i, d);
      const int p = this->Patch.Order[d] - 1;
      if (p == 0)
      {
        g[d] = 0.5 * (t[0] + t[1]);
        continue;
      }
      double s = 0.0;
      for (int k = 1; k <= p; ++k)
      {
        s += t[k];
      }
      g[d] = s / p;
    }
    f(g, this->Patch.Coefficients.data() + i * this->Patch.Dimension);
  }
}

void vtkLRSplineBuilder::SetCoefficientsFromKnots(
  const std::function<void(const double* const interior[3], const int degree[3], double* c)>& f)
{
  const vtkIdType n = static_cast<vtkIdType>(this->Patch.Gamma.size());
  const int degree[3] = { this->Patch.Order[0] - 1, this->Patch.Order[1] - 1,
    this->Patch.Order[2] - 1 };
  for (vtkIdType i = 0; i < n; ++i)
  {
    if (!this->Alive[i])
    {
      continue;
    }
    const double* interior[3] = { this->Patch.GetKnots(i, 0) + 1, this->Patch.GetKnots(i, 1) + 1,
      this->Patch.GetKnots(i, 2) + 1 };
    f(interior, degree, this->Patch.Coefficients.data() + i * this->Patch.Dimension);
  }
}

//------------------------------------------------------------------------------
bool vtkLRSplineBuilder::Covered(int dir, double value, const double support[6]) const
{
  auto it = this->Planes[dir].find(value);
  if (it == this->Planes[dir].end())
  {
    return false;
  }
  int e1, e2;
  OtherDirections(dir, e1, e2);
  const double a0 = support[e1], a1 = support[e1 + 3], b0 = support[e2], b1 = support[e2 + 3];
  // One rectangle covering the support, or else the union of those that
  // overlap it (a plane holds many rectangles, most of them far away).
  std::vector<const Rect2*> near;
  for (const Rect2& r : it->second)
  {
    if (r.A0 <= a0 && a1 <= r.A1 && r.B0 <= b0 && b1 <= r.B1)
    {
      return true;
    }
    if (r.A0 < a1 && r.A1 > a0 && r.B0 < b1 && r.B1 > b0)
    {
      near.push_back(&r);
    }
  }
  if (near.size() < 2)
  {
    return false;
  }
  // Union coverage: every cell of the grid of rectangle edges must be covered.
  std::vector<double> xs{ a0, a1 }, ys{ b0, b1 };
  for (const Rect2* r : near)
  {
    if (r->A0 > a0 && r->A0 < a1)
      xs.push_back(r->A0);
    if (r->A1 > a0 && r->A1 < a1)
      xs.push_back(r->A1);
    if (r->B0 > b0 && r->B0 < b1)
      ys.push_back(r->B0);
    if (r->B1 > b0 && r->B1 < b1)
      ys.push_back(r->B1);
  }
  std::sort(xs.begin(), xs.end());
  xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
  std::sort(ys.begin(), ys.end());
  ys.erase(std::unique(ys.begin(), ys.end()), ys.end());
  for (std::size_t i = 0; i + 1 < xs.size(); ++i)
  {
    const double cx = 0.5 * (xs[i] + xs[i + 1]);
    for (std::size_t j = 0; j + 1 < ys.size(); ++j)
    {
      const double cy = 0.5 * (ys[j] + ys[j + 1]);
      bool in = false;
      for (const Rect2* r : near)
      {
        if (r->A0 <= cx && cx <= r->A1 && r->B0 <= cy && cy <= r->B1)
        {
          in = true;
          break;
        }
      }
      if (!in)
      {
        return false;
      }
    }
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkLRSplineBuilder::Split(std::vector<vtkIdType>& work, bool parentsFirst)
{
  const int kpf = this->Patch.GetKnotsPerFunction();
  const int dim = this->Patch.Dimension;
  std::vector<double> knots(kpf), k1(kpf), k2(kpf), coeff(dim);
  // Parents first: a split child has a smaller support, or the same support
  // with one more knot inside it, so taking the largest support (fewest
  // inner knots) first splits every function once, with all its
  // contributions gathered. (In any other order a function reached along
  // many split paths, as after inserting many rectangles at once, is split
  // again for every path.)
  struct Entry
  {
    double Volume;
    int Inner;
    vtkIdType Id;
  };
  auto later = [](const Entry& a, const Entry& b)
  {
    return a.Volume < b.Volume ||
      (a.Volume == b.Volume && (a.Inner > b.Inner || (a.Inner == b.Inner && a.Id > b.Id)));
  };
  std::priority_queue<Entry, std::vector<Entry>, decltype(later)> heap(later);
  std::vector<char> queued;
  auto push = [&](vtkIdType f)
  {
    if (!parentsFirst)
    {
      work.push_back(f);
      return;
    }
    if (static_cast<vtkIdType>(queued.size()) <= f)
    {
      queued.resize(f + 1, 0);
    }
    if (queued[f])
    {
      return;
    }
    queued[f] = 1;
    Entry entry{ 1.0, 0, f };
    for (int d = 0; d < 3; ++d)
    {
      const double* t = this->Patch.GetKnots(f, d);
      const int o = this->Patch.Order[d];
      entry.Volume *= t[o] - t[0];
      for (int j = 1; j < o; ++j)
      {
        entry.Inner += (t[j] > t[0] && t[j] < t[o]) ? 1 : 0;
      }
    }
    heap.push(entry);
  };
  auto pop = [&](vtkIdType& f)
  {
    if (!parentsFirst)
    {
      if (work.empty())
      {
        return false;
      }
      f = work.back();
      work.pop_back();
      return true;
    }
    if (heap.empty())
    {
      return false;
    }
    f = heap.top().Id;
    heap.pop();
    queued[f] = 0;
    return true;
  };
  if (parentsFirst)
  {
    std::vector<vtkIdType> initial;
    initial.swap(work);
    for (vtkIdType f : initial)
    {
      push(f);
    }
  }
  vtkIdType f;
  while (pop(f))
  {
    if (!this->Alive[f])
    {
      continue;
    }
    std::copy(this->Patch.Knots.begin() + f * kpf, this->Patch.Knots.begin() + (f + 1) * kpf,
      knots.begin());
    double support[6];
    int offset[3];
    offset[0] = 0;
    offset[1] = this->Patch.Order[0] + 1;
    offset[2] = offset[1] + this->Patch.Order[1] + 1;
    for (int d = 0; d < 3; ++d)
    {
      support[d] = knots[offset[d]];
      support[d + 3] = knots[offset[d] + this->Patch.Order[d]];
    }
    int splitDir = -1;
    double z = 0.0;
    for (int d = 0; d < 3 && splitDir < 0; ++d)
    {
      const double* t = knots.data() + offset[d];
      const int np = this->Patch.Order[d] + 1;
      auto it = this->Planes[d].upper_bound(support[d]);
      auto end = this->Planes[d].lower_bound(support[d + 3]);
      for (; it != end; ++it)
      {
        const double v = it->first;
        if (std::find(t, t + np, v) != t + np)
        {
          continue;
        }
        if (this->Covered(d, v, support))
        {
          splitDir = d;
          z = v;
          break;
        }
      }
    }
    if (splitDir < 0)
    {
      continue;
    }
    // B = a1 B1 + a2 B2 (knot insertion of z into the local knot vector).
    const int d = splitDir;
    const int p = this->Patch.Order[d] - 1;
    const double* t = knots.data() + offset[d];
    std::vector<double> tt(t, t + p + 2);
    tt.insert(std::upper_bound(tt.begin(), tt.end(), z), z);
    const double a1 = (t[p] > t[0]) ? std::min(1.0, (z - t[0]) / (t[p] - t[0])) : 1.0;
    const double a2 = (t[p + 1] > t[1]) ? std::min(1.0, (t[p + 1] - z) / (t[p + 1] - t[1])) : 1.0;
    k1 = knots;
    k2 = knots;
    std::copy(tt.begin(), tt.begin() + p + 2, k1.begin() + offset[d]);
    std::copy(tt.begin() + 1, tt.begin() + p + 3, k2.begin() + offset[d]);
    std::copy(this->Patch.Coefficients.begin() + f * dim,
      this->Patch.Coefficients.begin() + (f + 1) * dim, coeff.begin());
    const double gamma = this->Patch.Gamma[f];
    this->Alive[f] = 0;
    --this->NumberAlive;
    this->Index.erase(this->Key(knots.data()));
    if (a1 > 0)
    {
      push(this->AddFunction(k1.data(), coeff.data(), a1 * gamma));
    }
    if (a2 > 0)
    {
      push(this->AddFunction(k2.data(), coeff.data(), a2 * gamma));
    }
  }
}

//------------------------------------------------------------------------------
void vtkLRSplineBuilder::AddToPlane(std::vector<Rect2>& plane, Rect2 r)
{
  for (const Rect2& q : plane)
  {
    if (q.A0 <= r.A0 && r.A1 <= q.A1 && q.B0 <= r.B0 && r.B1 <= q.B1)
    {
      return; // already covered
    }
  }
  // Drop the rectangles r contains and merge r with those it extends to a
  // rectangle, until nothing changes (the union, which is all that counts,
  // stays the same; the lists stay short).
  bool changed = true;
  while (changed)
  {
    changed = false;
    plane.erase(std::remove_if(plane.begin(), plane.end(),
                  [&r](const Rect2& q)
                  { return r.A0 <= q.A0 && q.A1 <= r.A1 && r.B0 <= q.B0 && q.B1 <= r.B1; }),
      plane.end());
    for (std::size_t i = 0; i < plane.size(); ++i)
    {
      const Rect2& q = plane[i];
      if (q.A0 == r.A0 && q.A1 == r.A1 && q.B0 <= r.B1 && r.B0 <= q.B1)
      {
        r.B0 = std::min(r.B0, q.B0);
        r.B1 = std::max(r.B1, q.B1);
      }
      else if (q.B0 == r.B0 && q.B1 == r.B1 && q.A0 <= r.A1 && r.A0 <= q.A1)
      {
        r.A0 = std::min(r.A0, q.A0);
        r.A1 = std::max(r.A1, q.A1);
      }
      else
      {
        continue;
      }
      plane.erase(plane.begin() + i);
      changed = true;
      break;
    }
  }
  plane.push_back(r);
}

//------------------------------------------------------------------------------
bool vtkLRSplineBuilder::InsertRectangles(
  std::vector<Rectangle>& rects, bool parentsFirst, std::string* error)
{
  if (rects.empty())
  {
    return true;
  }
  // The new rectangles by direction and value.
  std::map<double, std::vector<Rect2>> fresh[3];
  for (const Rectangle& r : rects)
  {
    int e1, e2;
    OtherDirections(r.Dir, e1, e2);
    AddToPlane(fresh[r.Dir][r.Value], Rect2{ r.Box[e1], r.Box[e1 + 3], r.Box[e2], r.Box[e2 + 3] });
  }
  for (int d = 0; d < 3; ++d)
  {
    for (const auto& plane : fresh[d])
    {
      for (const Rect2& q : plane.second)
      {
        AddToPlane(this->Planes[d][plane.first], q);
      }
    }
  }

  // Split the elements they cross: an element is split by a rectangle that
  // spans it; one crossed only partly must be split first by another one
  // (or the rectangle ends inside an element, which is an error).
  const vtkIdType ne = this->GetNumberOfElements();
  std::vector<vtkIdType> stack;
  for (vtkIdType e = 0; e < ne; ++e)
  {
    stack.push_back(e);
    while (!stack.empty())
    {
      const vtkIdType x = stack.back();
      stack.pop_back();
      const double* b = this->Patch.ElementBoxes.data() + 6 * x;
      int splitDir = -1;
      double splitValue = 0.0;
      bool partial = false;
      for (int d = 0; d < 3 && splitDir < 0; ++d)
      {
        int e1, e2;
        OtherDirections(d, e1, e2);
        auto it = fresh[d].upper_bound(b[d]);
        auto end = fresh[d].lower_bound(b[d + 3]);
        for (; it != end && splitDir < 0; ++it)
        {
          for (const Rect2& q : it->second)
          {
            if (!(b[e1] < q.A1 && b[e1 + 3] > q.A0 && b[e2] < q.B1 && b[e2 + 3] > q.B0))
            {
              continue;
            }
            if (q.A0 <= b[e1] && b[e1 + 3] <= q.A1 && q.B0 <= b[e2] && b[e2 + 3] <= q.B1)
            {
              splitDir = d;
              splitValue = it->first;
              break;
            }
            partial = true;
          }
        }
      }
      if (splitDir < 0)
      {
        if (partial)
        {
          if (error)
          {
            *error =
              "the mesh rectangle ends inside an element (its edges must lie on mesh planes)";
          }
          return false;
        }
        continue;
      }
      double upper[6];
      std::copy(b, b + 6, upper);
      upper[splitDir] = splitValue;
      this->Patch.ElementBoxes[6 * x + splitDir + 3] = splitValue;
      this->Patch.ElementBoxes.insert(this->Patch.ElementBoxes.end(), upper, upper + 6);
      stack.push_back(x);
      stack.push_back(this->GetNumberOfElements() - 1);
    }
  }

  // Split the basis functions they (with the rest of their planes) traverse.
  std::vector<vtkIdType> work;
  const vtkIdType nf = static_cast<vtkIdType>(this->Patch.Gamma.size());
  for (vtkIdType f = 0; f < nf; ++f)
  {
    if (!this->Alive[f])
    {
      continue;
    }
    bool crossed = false;
    for (int d = 0; d < 3 && !crossed; ++d)
    {
      int e1, e2;
      OtherDirections(d, e1, e2);
      const double* t = this->Patch.GetKnots(f, d);
      const double* te1 = this->Patch.GetKnots(f, e1);
      const double* te2 = this->Patch.GetKnots(f, e2);
      const double s1 = te1[0], t1 = te1[this->Patch.Order[e1]];
      const double s2 = te2[0], t2 = te2[this->Patch.Order[e2]];
      auto it = fresh[d].upper_bound(t[0]);
      auto end = fresh[d].lower_bound(t[this->Patch.Order[d]]);
      for (; it != end && !crossed; ++it)
      {
        for (const Rect2& q : it->second)
        {
          if (s1 < q.A1 && t1 > q.A0 && s2 < q.B1 && t2 > q.B0)
          {
            crossed = true;
            break;
          }
        }
      }
    }
    if (crossed)
    {
      work.push_back(f);
    }
  }
  this->Split(work, parentsFirst);
  return true;
}

//------------------------------------------------------------------------------
bool vtkLRSplineBuilder::InsertMeshRectangle(
  int dir, double value, const double box[6], std::string* error)
{
  std::vector<Rectangle> rects(1);
  rects[0].Dir = dir;
  rects[0].Value = value;
  std::copy(box, box + 6, rects[0].Box);
  return this->InsertRectangles(rects, false, error);
}

//------------------------------------------------------------------------------
void vtkLRSplineBuilder::FunctionRectangles(
  vtkIdType i, const RefineOptions& options, std::vector<Rectangle>& out) const
{
  Rectangle r;
  for (int d = 0; d < 3; ++d)
  {
    const double* t = this->Patch.GetKnots(i, d);
    r.Box[d] = t[0];
    r.Box[d + 3] = t[this->Patch.Order[d]];
  }
  for (int d = 0; d < 3; ++d)
  {
    const double* t = this->Patch.GetKnots(i, d);
    for (int k = 0; k < this->Patch.Order[d]; ++k)
    {
      if (SplitValue(t[k], t[k + 1], d, options, &r.Value))
      {
        r.Dir = d;
        out.push_back(r);
      }
    }
  }
}

bool vtkLRSplineBuilder::SplitValue(
  double a, double b, int d, const RefineOptions& options, double* value)
{
  if (!(a < b))
  {
    return false;
  }
  const double step = options.GridStep[d], origin = options.GridOffset[d];
  double z = a + options.Ratio * (b - a);
  if (step > 0)
  {
    // the nearest grid point strictly inside (a, b), if any
    const double lo = std::floor((a - origin) / step) + 1.0;
    const double hi = std::ceil((b - origin) / step) - 1.0;
    if (lo > hi)
    {
      return false;
    }
    z = origin + std::min(hi, std::max(lo, std::round((z - origin) / step))) * step;
  }
  if (z > a && z < b && z - a >= options.MinimumPart[d] && b - z >= options.MinimumPart[d])
  {
    *value = z;
    return true;
  }
  return false;
}

//------------------------------------------------------------------------------
bool vtkLRSplineBuilder::RefineFunction(vtkIdType i, double ratio, std::string* error)
{
  if (i < 0 || i >= static_cast<vtkIdType>(this->Patch.Gamma.size()) || !this->Alive[i] ||
    !(ratio > 0 && ratio < 1))
  {
    if (error)
    {
      *error = "invalid basis function or ratio";
    }
    return false;
  }
  // One rectangle after the other (the same LR spline as all at once, and
  // the order of the functions that generated volumes have always had).
  std::vector<Rectangle> rects;
  RefineOptions options;
  options.Ratio = ratio;
  this->FunctionRectangles(i, options, rects);
  for (const Rectangle& r : rects)
  {
    std::vector<Rectangle> one{ r };
    if (!this->InsertRectangles(one, false, error))
    {
      return false;
    }
  }
  return true;
}

bool vtkLRSplineBuilder::RefineFunctions(const std::vector<vtkIdType>& ids,
  const RefineOptions& options, std::string* error, vtkIdType* inserted)
{
  if (inserted)
  {
    *inserted = 0;
  }
  if (!(options.Ratio > 0 && options.Ratio < 1))
  {
    if (error)
    {
      *error = "invalid basis function or ratio";
    }
    return false;
  }
  std::vector<Rectangle> rects;
  std::vector<char> seen(this->Alive.size(), 0);
  for (vtkIdType i : ids)
  {
    if (i < 0 || i >= static_cast<vtkIdType>(this->Alive.size()) || !this->Alive[i] || seen[i])
    {
      continue;
    }
    seen[i] = 1;
    this->FunctionRectangles(i, options, rects);
  }
  if (inserted)
  {
    *inserted = static_cast<vtkIdType>(rects.size());
  }
  return this->InsertRectangles(rects, true, error);
}

bool vtkLRSplineBuilder::RefineAt(const double p[3], double ratio, std::string* error)
{
  vtkIdType best = -1;
  double bestVolume = 0.0;
  const vtkIdType nf = static_cast<vtkIdType>(this->Patch.Gamma.size());
  for (vtkIdType f = 0; f < nf; ++f)
  {
    if (!this->Alive[f])
    {
      continue;
    }
    double volume = 1.0;
    bool inside = true;
    for (int d = 0; d < 3 && inside; ++d)
    {
      const double* t = this->Patch.GetKnots(f, d);
      const double lo = t[0], hi = t[this->Patch.Order[d]];
      inside = lo <= p[d] && p[d] <= hi;
      volume *= hi - lo;
    }
    if (inside && (best < 0 || volume < bestVolume))
    {
      best = f;
      bestVolume = volume;
    }
  }
  if (best < 0)
  {
    if (error)
    {
      *error = "the point is outside the domain";
    }
    return false;
  }
  return this->RefineFunction(best, ratio, error);
}

//------------------------------------------------------------------------------
void vtkLRSplineBuilder::Compact()
{
  const vtkIdType n = static_cast<vtkIdType>(this->Patch.Gamma.size());
  if (n == this->NumberAlive)
  {
    return;
  }
  const int kpf = this->Patch.GetKnotsPerFunction();
  const int dim = this->Patch.Dimension;
  vtkIdType out = 0;
  for (vtkIdType f = 0; f < n; ++f)
  {
    if (!this->Alive[f])
    {
      continue;
    }
    if (out != f)
    {
      std::copy(this->Patch.Knots.begin() + f * kpf, this->Patch.Knots.begin() + (f + 1) * kpf,
        this->Patch.Knots.begin() + out * kpf);
      std::copy(this->Patch.Coefficients.begin() + f * dim,
        this->Patch.Coefficients.begin() + (f + 1) * dim,
        this->Patch.Coefficients.begin() + out * dim);
      this->Patch.Gamma[out] = this->Patch.Gamma[f];
    }
    ++out;
  }
  this->Patch.Knots.resize(out * kpf);
  this->Patch.Coefficients.resize(out * dim);
  this->Patch.Gamma.resize(out);
  this->Alive.assign(out, 1);
  this->Index.clear();
  for (vtkIdType f = 0; f < out; ++f)
  {
    this->Index.emplace(this->Key(this->Patch.Knots.data() + f * kpf), f);
  }
}

//------------------------------------------------------------------------------
void vtkLRSplineBuilder::SetCoefficients(const std::vector<double>& coefficients)
{
  this->Compact();
  const std::size_t n = static_cast<std::size_t>(this->NumberAlive) * this->Patch.Dimension;
  std::copy(coefficients.begin(), coefficients.begin() + std::min(n, coefficients.size()),
    this->Patch.Coefficients.begin());
}

//------------------------------------------------------------------------------
const vtkLRSplinePatch& vtkLRSplineBuilder::GetPatch()
{
  this->Compact();
  this->Patch.MeshRectangles.clear();
  this->Patch.MeshMultiplicities.clear();
  double domain[6];
  this->Patch.GetDomain(domain);
  for (int d = 0; d < 3; ++d)
  {
    int e1, e2;
    OtherDirections(d, e1, e2);
    for (const auto& plane : this->Planes[d])
    {
      const bool boundary = plane.first == domain[d] || plane.first == domain[d + 3];
      for (const Rect2& r : plane.second)
      {
        double m[6];
        m[d] = m[d + 3] = plane.first;
        m[e1] = r.A0;
        m[e1 + 3] = r.A1;
        m[e2] = r.B0;
        m[e2 + 3] = r.B1;
        this->Patch.MeshRectangles.insert(this->Patch.MeshRectangles.end(), m, m + 6);
        this->Patch.MeshMultiplicities.push_back(boundary ? this->Patch.Order[d] : 1);
      }
    }
  }
  return this->Patch;
}
