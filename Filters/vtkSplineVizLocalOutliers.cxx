// SPDX-License-Identifier: BSD-3-Clause
#include "vtkSplineVizLocalOutliers.h"

#include "vtkSplineVizProgress.h"

#include "vtkSMPThreadLocal.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace
{
// Normal-consistent scale of the median absolute deviation.
constexpr double MADScale = 1.4826;
// Ridge on the non-constant terms, relative to the number of neighbours
// (offsets are scaled to the unit ball, so coefficients are in value units).
constexpr double Ridge = 1e-6;

// The model's terms: 1 and the three offsets.
constexpr int Terms = 4;

// The model's terms at `x` about `centre`, offsets in units of `radius`.
void ModelTerms(const double* x, const double centre[3], double radius, double phi[Terms])
{
  phi[0] = 1.0;
  for (int d = 0; d < 3; ++d)
  {
    phi[d + 1] = (x[d] - centre[d]) / radius;
  }
}

// Solve the symmetric positive definite system M x = b (Cholesky on the lower
// triangle, in place) for `dim` right-hand sides stored Terms apart.
bool SolveSPD(double M[Terms][Terms], double* b, int dim)
{
  for (int j = 0; j < Terms; ++j)
  {
    double d = M[j][j];
    for (int k = 0; k < j; ++k)
    {
      d -= M[j][k] * M[j][k];
    }
    if (!(d > 0))
    {
      return false;
    }
    M[j][j] = std::sqrt(d);
    for (int i = j + 1; i < Terms; ++i)
    {
      double s = M[i][j];
      for (int k = 0; k < j; ++k)
      {
        s -= M[i][k] * M[j][k];
      }
      M[i][j] = s / M[j][j];
    }
  }
  for (int c = 0; c < dim; ++c)
  {
    double* x = b + Terms * c;
    for (int i = 0; i < Terms; ++i)
    {
      double s = x[i];
      for (int k = 0; k < i; ++k)
      {
        s -= M[i][k] * x[k];
      }
      x[i] = s / M[i][i];
    }
    for (int i = Terms - 1; i >= 0; --i)
    {
      double s = x[i];
      for (int k = i + 1; k < Terms; ++k)
      {
        s -= M[k][i] * x[k];
      }
      x[i] = s / M[i][i];
    }
  }
  return true;
}

// The linear model of `ids` about `centre` (Terms coefficients per
// component in `coef`); false when it cannot be fitted.
bool FitModel(const std::vector<double>& positions, const std::vector<double>& values, int dim,
  const double centre[3], double radius, const std::vector<vtkIdType>& ids,
  std::vector<double>& coef)
{
  double M[Terms][Terms] = {};
  coef.assign(Terms * dim, 0.0);
  double phi[Terms];
  for (vtkIdType id : ids)
  {
    ModelTerms(&positions[3 * id], centre, radius, phi);
    for (int i = 0; i < Terms; ++i)
    {
      for (int j = 0; j <= i; ++j)
      {
        M[i][j] += phi[i] * phi[j];
      }
      for (int c = 0; c < dim; ++c)
      {
        coef[Terms * c + i] += phi[i] * values[id * dim + c];
      }
    }
  }
  for (int i = 1; i < Terms; ++i)
  {
    M[i][i] += Ridge * static_cast<double>(ids.size());
  }
  return SolveSPD(M, coef.data(), dim);
}

// |f_id - model(x_id)| (the length of the residual vector).
double Residual(const std::vector<double>& positions, const std::vector<double>& values, int dim,
  const double centre[3], double radius, const std::vector<double>& coef, vtkIdType id)
{
  double phi[Terms];
  ModelTerms(&positions[3 * id], centre, radius, phi);
  double r2 = 0.0;
  for (int c = 0; c < dim; ++c)
  {
    double m = 0.0;
    for (int i = 0; i < Terms; ++i)
    {
      m += coef[Terms * c + i] * phi[i];
    }
    const double r = values[id * dim + c] - m;
    r2 += r * r;
  }
  return std::sqrt(r2);
}

// Step 2's robust refits: at most this many, each without the neighbours
// farther than DropFactor times max(spread, tolerance) from the last model
// (several, so that a cluster of two or three wrong values among the
// neighbours is peeled off one refit at a time). A tighter factor (3) drops
// clean neighbours where a linear model cannot follow the data, and at the
// one-sided neighbourhoods of a boundary the model of those left then
// misses clean points (it took 12 of ParaView's clipped Wavelet for spikes).
constexpr int Refits = 3;
constexpr double DropFactor = 5.0;

// The k nearest other points of any data point: points binned in a uniform
// grid of about two points per cell, cells searched ring by ring around the
// query's cell until no nearer point can remain. (vtkStaticPointLocator's
// FindClosestNPoints took 85 % of the detection, 19 s per million points.)
class GridNeighbours
{
public:
  explicit GridNeighbours(const std::vector<double>& positions)
    : Positions(positions)
  {
    const vtkIdType np = static_cast<vtkIdType>(positions.size() / 3);
    double lo[3] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, VTK_DOUBLE_MAX };
    double hi[3] = { -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
    for (vtkIdType p = 0; p < np; ++p)
    {
      for (int d = 0; d < 3; ++d)
      {
        lo[d] = std::min(lo[d], positions[3 * p + d]);
        hi[d] = std::max(hi[d], positions[3 * p + d]);
      }
    }
    const double largest = std::max({ hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2], 1e-300 });
    // Cubic cells of about two points each over the extents that are not flat.
    double volume = 1.0;
    int spread = 0;
    for (int d = 0; d < 3; ++d)
    {
      if (hi[d] - lo[d] > 1e-9 * largest)
      {
        volume *= hi[d] - lo[d];
        ++spread;
      }
    }
    // (At most 1024 cells per side: nearly flat data gets fewer, fuller cells.)
    this->Side =
      spread > 0 ? std::pow(volume * 2.0 / std::max<vtkIdType>(np, 1), 1.0 / spread) : largest;
    this->Side = std::max(this->Side, largest / 1024.0);
    vtkIdType cells = 1;
    for (int d = 0; d < 3; ++d)
    {
      this->Lo[d] = lo[d];
      this->Dims[d] = static_cast<int>(std::max(1.0, std::ceil((hi[d] - lo[d]) / this->Side)));
      cells *= this->Dims[d];
    }
    this->Start.assign(cells + 1, 0);
    std::vector<vtkIdType> cell(np);
    for (vtkIdType p = 0; p < np; ++p)
    {
      cell[p] = this->CellOf(&positions[3 * p]);
      ++this->Start[cell[p] + 1];
    }
    for (vtkIdType c = 0; c < cells; ++c)
    {
      this->Start[c + 1] += this->Start[c];
    }
    this->Points.resize(np);
    std::vector<vtkIdType> fill(this->Start.begin(), this->Start.end() - 1);
    for (vtkIdType p = 0; p < np; ++p)
    {
      this->Points[fill[cell[p]]++] = p;
    }
  }

  /// The points cell by cell (visiting them in this order keeps neighbours in cache).
  const std::vector<vtkIdType>& GetOrder() const { return this->Points; }

  // The k nearest points other than p, nearest first (fewer when there are not k others).
  void Find(vtkIdType p, int k, std::vector<std::pair<double, vtkIdType>>& heap,
    std::vector<vtkIdType>& ids) const
  {
    const double* x = &this->Positions[3 * p];
    int c[3];
    this->IndexOf(x, c);
    heap.clear();
    const int most = std::max({ this->Dims[0], this->Dims[1], this->Dims[2] });
    for (int r = 0; r <= most; ++r)
    {
      for (int di = -r; di <= r; ++di)
      {
        for (int dj = -r; dj <= r; ++dj)
        {
          const bool side = std::abs(di) == r || std::abs(dj) == r;
          for (int dk = -r; dk <= r; dk += (side ? 1 : std::max(1, 2 * r)))
          {
            this->Visit(c[0] + di, c[1] + dj, c[2] + dk, p, x, k, heap);
          }
        }
      }
      // Every point of ring r + 1 is at least r cells away.
      const double reach = r * this->Side;
      if (static_cast<int>(heap.size()) == k && heap.front().first <= reach * reach)
      {
        break;
      }
    }
    std::sort_heap(heap.begin(), heap.end());
    ids.clear();
    for (const auto& entry : heap)
    {
      ids.push_back(entry.second);
    }
  }

private:
  void IndexOf(const double* x, int c[3]) const
  {
    for (int d = 0; d < 3; ++d)
    {
      c[d] = std::min(this->Dims[d] - 1,
        std::max(0, static_cast<int>(std::floor((x[d] - this->Lo[d]) / this->Side))));
    }
  }
  vtkIdType CellOf(const double* x) const
  {
    int c[3];
    this->IndexOf(x, c);
    return c[0] + static_cast<vtkIdType>(this->Dims[0]) * (c[1] + this->Dims[1] * c[2]);
  }
  // Offer the points of cell (i, j, k) to the max-heap of the k nearest.
  void Visit(int i, int j, int l, vtkIdType self, const double* x, int k,
    std::vector<std::pair<double, vtkIdType>>& heap) const
  {
    if (i < 0 || j < 0 || l < 0 || i >= this->Dims[0] || j >= this->Dims[1] || l >= this->Dims[2])
    {
      return;
    }
    const vtkIdType cell = i + static_cast<vtkIdType>(this->Dims[0]) * (j + this->Dims[1] * l);
    for (vtkIdType at = this->Start[cell]; at < this->Start[cell + 1]; ++at)
    {
      const vtkIdType q = this->Points[at];
      if (q == self)
      {
        continue;
      }
      const double* y = &this->Positions[3 * q];
      const double d2 = (x[0] - y[0]) * (x[0] - y[0]) + (x[1] - y[1]) * (x[1] - y[1]) +
        (x[2] - y[2]) * (x[2] - y[2]);
      if (static_cast<int>(heap.size()) < k)
      {
        heap.emplace_back(d2, q);
        std::push_heap(heap.begin(), heap.end());
      }
      else if (d2 < heap.front().first)
      {
        std::pop_heap(heap.begin(), heap.end());
        heap.back() = { d2, q };
        std::push_heap(heap.begin(), heap.end());
      }
    }
  }

  const std::vector<double>& Positions;
  double Lo[3] = { 0, 0, 0 };
  double Side = 1.0;
  int Dims[3] = { 1, 1, 1 };
  std::vector<vtkIdType> Start, Points;
};

// 1.4826 times the median of `r` (reordered).
double Spread(std::vector<double>& r)
{
  if (r.empty())
  {
    return 0.0;
  }
  const std::size_t half = r.size() / 2;
  std::nth_element(r.begin(), r.begin() + half, r.end());
  double median = r[half];
  if (r.size() % 2 == 0)
  {
    median = 0.5 * (median + *std::max_element(r.begin(), r.begin() + half));
  }
  return MADScale * median;
}
}

//------------------------------------------------------------------------------
double vtkSplineVizLocalOutliers::FitNeighbourhood(const std::vector<double>& positions,
  const std::vector<double>& values, int dim, const double centre[3], std::vector<vtkIdType>& ids,
  double* a) const
{
  double radius = 0.0;
  for (vtkIdType id : ids)
  {
    double d2 = 0.0;
    for (int k = 0; k < 3; ++k)
    {
      const double d = positions[3 * id + k] - centre[k];
      d2 += d * d;
    }
    radius = std::max(radius, std::sqrt(d2));
  }
  radius = radius > 0 ? radius : 1.0;
  std::vector<double> coef, residuals;
  const std::vector<vtkIdType> all = ids;
  double spread = 0.0;
  for (int pass = 0; pass <= Refits; ++pass)
  {
    if (!FitModel(positions, values, dim, centre, radius, ids, coef))
    {
      // (cannot happen with the ridge and at least one neighbour; be safe)
      coef.assign(Terms * dim, 0.0);
      for (int c = 0; c < dim; ++c)
      {
        for (vtkIdType id : ids)
        {
          coef[Terms * c] += values[id * dim + c] / static_cast<double>(ids.size());
        }
      }
    }
    residuals.clear();
    for (vtkIdType id : ids)
    {
      residuals.push_back(Residual(positions, values, dim, centre, radius, coef, id));
    }
    std::vector<double> sorted = residuals;
    spread = Spread(sorted);
    if (pass == Refits)
    {
      break;
    }
    // Neighbours far off this model are left out of the next fit.
    const double limit = DropFactor * std::max(spread, this->Tolerance);
    std::vector<vtkIdType> kept;
    for (std::size_t i = 0; i < ids.size(); ++i)
    {
      if (residuals[i] <= limit)
      {
        kept.push_back(ids[i]);
      }
    }
    if (kept.size() == ids.size() || kept.size() < static_cast<std::size_t>(Terms + 4))
    {
      break;
    }
    ids.swap(kept);
  }
  for (int c = 0; c < dim; ++c)
  {
    a[c] = coef[Terms * c];
  }
  if (ids.size() == all.size())
  {
    return spread;
  }
  // The spread of all the neighbours about the final model: the median
  // ignores the few wrong ones, and clean neighbours dropped because a linear
  // model cannot follow them here still say so.
  residuals.clear();
  for (vtkIdType id : all)
  {
    residuals.push_back(Residual(positions, values, dim, centre, radius, coef, id));
  }
  return Spread(residuals);
}

//------------------------------------------------------------------------------
bool vtkSplineVizLocalOutliers::Find(const std::vector<double>& positions,
  const std::vector<double>& values, int dim, std::vector<double>& deviation,
  std::vector<unsigned char>& outlier, vtkAlgorithm* algorithm, double from, double to) const
{
  const vtkIdType np = static_cast<vtkIdType>(positions.size() / 3);
  deviation.assign(np, 0.0);
  outlier.assign(np, 0);
  const int k = std::max(Terms + 4, this->NumberOfNeighbors);
  if (np < k + 1)
  {
    return false;
  }
  const GridNeighbours grid(positions);
  const std::vector<vtkIdType>& order = grid.GetOrder();

  // Every point's neighbours and its distance from their model (step 1-3).
  std::vector<vtkIdType> neighbours(static_cast<std::size_t>(np) * k, -1);
  std::vector<double> distance(np, 0.0), spread(np, 0.0);
  vtkSMPThreadLocal<std::vector<std::pair<double, vtkIdType>>> tlHeap;
  vtkSMPThreadLocal<std::vector<vtkIdType>> tlIds;
  vtkSMPThreadLocal<std::vector<double>> tlA;
  const double middle = from + 0.8 * (to - from);
  if (!vtkSplineVizProgress::For(
        algorithm, 0, np, 256, 4096,
        [&](vtkIdType begin, vtkIdType end)
        {
          std::vector<std::pair<double, vtkIdType>>& heap = tlHeap.Local();
          std::vector<vtkIdType>& ids = tlIds.Local();
          std::vector<double>& a = tlA.Local();
          a.resize(dim);
          for (vtkIdType at = begin; at < end; ++at)
          {
            const vtkIdType p = order[at];
            const double* x = &positions[3 * p];
            grid.Find(p, k, heap, ids);
            std::copy(ids.begin(), ids.end(), &neighbours[static_cast<std::size_t>(p) * k]);
            spread[p] = this->FitNeighbourhood(positions, values, dim, x, ids, a.data());
            double d2 = 0.0;
            for (int c = 0; c < dim; ++c)
            {
              const double d = values[p * dim + c] - a[c];
              d2 += d * d;
            }
            distance[p] = std::sqrt(d2);
          }
        },
        from, middle))
  {
    return false;
  }

  // Step 4, against what the model misses at the neighbours themselves.
  const double tolerance = this->Tolerance > 0 ? this->Tolerance : 1e-300;
  vtkSMPThreadLocal<std::vector<double>> tlNear;
  return vtkSplineVizProgress::For(
    algorithm, 0, np, 1024, 16384,
    [&](vtkIdType begin, vtkIdType end)
    {
      std::vector<double>& near = tlNear.Local();
      std::vector<vtkIdType>& ids = tlIds.Local();
      std::vector<double>& a = tlA.Local();
      a.resize(dim);
      for (vtkIdType at = begin; at < end; ++at)
      {
        const vtkIdType p = order[at];
        const vtkIdType* mine = &neighbours[static_cast<std::size_t>(p) * k];
        const double base = std::max(spread[p], tolerance);
        near.clear();
        if (distance[p] <= this->Threshold * base)
        {
          // Not an outlier whatever the neighbours say.
          for (int i = 0; i < k && mine[i] >= 0; ++i)
          {
            near.push_back(distance[mine[i]]);
          }
        }
        else
        {
          // The verdict rests on the neighbours: how well are they predicted
          // without p? (A wrong p bends its neighbours' models, and would
          // otherwise raise its own scale: 0.4 % of the spikes of a 1 %
          // corruption of a million points were missed that way.)
          for (int i = 0; i < k && mine[i] >= 0; ++i)
          {
            const vtkIdType q = mine[i];
            ids.clear();
            const vtkIdType* theirs = &neighbours[static_cast<std::size_t>(q) * k];
            for (int j = 0; j < k && theirs[j] >= 0; ++j)
            {
              if (theirs[j] != p)
              {
                ids.push_back(theirs[j]);
              }
            }
            this->FitNeighbourhood(positions, values, dim, &positions[3 * q], ids, a.data());
            double d2 = 0.0;
            for (int c = 0; c < dim; ++c)
            {
              const double d = values[q * dim + c] - a[c];
              d2 += d * d;
            }
            near.push_back(std::sqrt(d2));
          }
        }
        deviation[p] = distance[p] / std::max(Spread(near), base);
        outlier[p] = deviation[p] > this->Threshold ? 1 : 0;
      }
    },
    middle, to);
}
