// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLRSplineImageFitter.h"

#include "vtkLRSplineBezierGrid.h"
#include "vtkLRSplineBezierVolume.h"
#include "vtkLRSplineBuilder.h"
#include "vtkLRSplinePatch.h"

#include "vtkArrayDispatch.h"
#include "vtkCellData.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkDataArrayRange.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkMatrix3x3.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <fstream>
#include <functional>
#include <initializer_list>
#include <string>
#include <unordered_map>
#include <vector>

vtkStandardNewMacro(vtkLRSplineImageFitter);

namespace
{
// Largest image the fitter accepts (voxels): 512^3.
constexpr vtkIdType MaximumVoxels = vtkIdType(1) << 27;
// Basis functions that see fewer voxels than this are regularized.
constexpr double LittleData = 1.0;
// Always-on relative ridge (keeps the normal matrix definite).
constexpr double Ridge = 1e-12;
// Conjugate gradients: the accuracy of the voxel values relative to the
// tolerance, the delay of the error estimate, the iteration limit.
constexpr double SolverAccuracy = 1e-4;
constexpr int SolverDelay = 10;
constexpr int SolverMaximumIterations = 2000;
// Safety bound on fit-and-refine rounds (each halves the marked intervals).
constexpr int MaximumRounds = 64;

// Copy a one-component array to doubles; false at the first NaN/infinity.
struct CopyWorker
{
  template <typename ArrayT>
  void operator()(ArrayT* array, std::vector<double>& out, std::atomic<bool>& finite)
  {
    const auto values = vtk::DataArrayValueRange<1>(array);
    const vtkIdType n = static_cast<vtkIdType>(values.size());
    vtkSMPTools::For(0, n,
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType i = begin; i < end; ++i)
        {
          const double v = static_cast<double>(values[i]);
          out[i] = v;
          if (!std::isfinite(v))
          {
            finite = false;
          }
        }
      });
  }
};

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

struct Statistics
{
  double MaxError = 0.0;
  double SumSquares = 0.0;
};

// The fit of one image.
class ImageFit
{
public:
  // Image: values (x fastest), sizes.
  const std::vector<double>* Values = nullptr;
  int N[3] = { 0, 0, 0 };
  int Degree[3] = { 2, 2, 2 };
  double Regularization = 0.1;
  double Tolerance = 0.0; // absolute

  vtkLRSplineBuilder Builder;
  // Per element of the current patch.
  std::vector<double> ElementError;
  Statistics Stats;
  int SolverIterations = 0;

  // The initial tensor-product mesh; Options says where later splits go.
  bool Initialize(
    const int elements[3], bool align, double minimumSize, int maximumLevels, std::string* error)
  {
    std::vector<double> breaks[3];
    for (int d = 0; d < 3; ++d)
    {
      // at most one element per voxel interval, or per voxel with knots on
      // voxel faces
      const bool faces = align && this->Degree[d] % 2 == 0;
      const int m = std::max(1, std::min(elements[d], this->N[d] - (faces ? 0 : 1)));
      const double length = this->N[d] - 1;
      this->InitialSide[d] = length / m;
      // Voxel-aligned knots: at voxel faces (half-integers) for even degrees,
      // at voxel centres (integers) for odd ones, where the sampling of the
      // B-splines at the voxels is best conditioned (at the finest level one
      // element per voxel, which can interpolate).
      this->Options.GridStep[d] = align ? 1.0 : 0.0;
      this->Options.GridOffset[d] = (this->Degree[d] % 2 == 0) ? 0.5 : 0.0;
      breaks[d].push_back(0.0);
      for (int k = 1; k < m; ++k)
      {
        double z = length * k / m;
        if (align)
        {
          const double o = this->Options.GridOffset[d];
          z = std::min(length - o, std::max(o, o + std::round(z - o)));
        }
        if (z > breaks[d].back() && z < length)
        {
          breaks[d].push_back(z);
        }
      }
      breaks[d].push_back(length);
      // No part shorter than MinimumElementSize voxels, or finer than
      // MaximumRefinementLevels halvings of the initial elements.
      // (a side s is at level round(log2(InitialSide / s))).
      this->Options.MinimumPart[d] = std::max(minimumSize * (1.0 - 1e-9),
        this->InitialSide[d] * std::pow(2.0, -(maximumLevels + 0.5)) * (1.0 + 1e-9));
    }
    this->Options.Ratio = 0.5;
    if (!this->Builder.InitializeTensorProduct(this->Degree, breaks, 1, error))
    {
      return false;
    }
    // The starting guess: the image sampled at the Greville points.
    this->Builder.SetCoefficientsFromGreville(
      [this](const double g[3], double* c) { c[0] = this->Trilinear(g); });
    return true;
  }

  vtkLRSplineBuilder::RefineOptions Options;
  double InitialSide[3] = { 1, 1, 1 };

  // Least squares on the current mesh (coefficients in the builder).
  bool Solve(std::string* error)
  {
    const vtkLRSplinePatch& patch = this->Builder.GetPatch();
    const vtkIdType nf = patch.GetNumberOfBasisFunctions();
    this->ComputeSupports(patch);
    this->BuildTables(patch);

    // Sparsity: functions overlap when they share an element.
    // (the lists are kept between fits: their memory is reused)
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
          for (vtkIdType k = this->FunctionElementOffsets[f];
               k < this->FunctionElementOffsets[f + 1]; ++k)
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
        }
      });
    this->RowOffsets.assign(nf + 1, 0);
    for (vtkIdType f = 0; f < nf; ++f)
    {
      this->RowOffsets[f + 1] = this->RowOffsets[f] + static_cast<vtkIdType>(rows[f].size());
    }
    this->Columns.resize(this->RowOffsets[nf]);
    this->Entries.resize(this->RowOffsets[nf]);
    std::vector<double> rhs(nf), diagonal(nf), weight(nf);
    const std::vector<double>& gamma = patch.Gamma;
    const std::vector<double>& values = *this->Values;
    const int nx = this->N[0], ny = this->N[1];
    vtkSMPTools::For(0, nf,
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType f = begin; f < end; ++f)
        {
          std::vector<int>& row = rows[f];
          vtkIdType out = this->RowOffsets[f];
          const int* tf = &this->FunctionTable[3 * f];
          for (int g : row)
          {
            const int* tg = &this->FunctionTable[3 * g];
            double v = gamma[f] * gamma[g];
            for (int d = 0; d < 3 && v != 0.0; ++d)
            {
              v *= this->Gram(d, tf[d], tg[d]);
            }
            this->Columns[out] = g;
            this->Entries[out] = v;
            if (g == f)
            {
              diagonal[f] = v;
            }
            ++out;
          }
          // Right-hand side and data weight: sums over the support's voxels.
          const Table& tu = this->Tables[0][tf[0]];
          const Table& tv = this->Tables[1][tf[1]];
          const Table& tw = this->Tables[2][tf[2]];
          double b = 0.0;
          for (int k = 0; k < tw.Count; ++k)
          {
            const double bw = tw.Values[k];
            for (int j = 0; j < tv.Count; ++j)
            {
              const double bvw = bw * tv.Values[j];
              const double* fv = values.data() +
                ((static_cast<std::size_t>(tw.Start + k) * ny + tv.Start + j) * nx + tu.Start);
              double s = 0.0;
              for (int i = 0; i < tu.Count; ++i)
              {
                s += tu.Values[i] * fv[i];
              }
              b += bvw * s;
            }
          }
          rhs[f] = gamma[f] * b;
          // how many voxels the function sees along its worst direction
          weight[f] = std::min(tu.Sum, std::min(tv.Sum, tw.Sum));
        }
      });

    // Regularization towards the previous fit (c^prev) for functions with
    // little data; A_ii = 0 (no voxel at all) keeps c^prev.
    std::vector<double> prior(patch.Coefficients.begin(), patch.Coefficients.end());
    std::vector<double> delta(nf);
    for (vtkIdType f = 0; f < nf; ++f)
    {
      const double little = std::max(0.0, 1.0 - weight[f] / LittleData);
      delta[f] = diagonal[f] > 0 ? diagonal[f] * (Ridge + this->Regularization * little) : 1.0;
      rhs[f] += delta[f] * prior[f];
      diagonal[f] += delta[f];
    }

    // Preconditioned conjugate gradients from c^prev.
    std::vector<double> x = prior, r(nf), z(nf), p(nf), q(nf);
    this->Multiply(x, delta, q);
    for (vtkIdType f = 0; f < nf; ++f)
    {
      r[f] = rhs[f] - q[f];
      z[f] = r[f] / diagonal[f];
    }
    p = z;
    double rz = Dot(r, z);
    // Stop when the error of the voxel values the solve leaves,
    // ||Phi (c_k - c*)||_2 <= ||c_k - c*||_(A+D), is below SolverAccuracy *
    // tolerance: the error in that norm is estimated from the last
    // SolverDelay steps (Hestenes-Stiefel; Strakos and Tichy 2002:
    // ||e_k||^2 = sum_{j>=k} alpha_j r_j.z_j). Or at the rounding level.
    const double target = SolverAccuracy * this->Tolerance;
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
      this->Multiply(p, delta, q);
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
    this->SolverIterations = it;
    this->Builder.SetCoefficients(x);
    this->Columns.clear();
    this->Entries.clear();
    return true;
  }

  // The error at every voxel, per element, from the basis functions (the
  // tables of the last Solve()): every round.
  void EvaluateFromBasis()
  {
    const vtkLRSplinePatch& patch = this->Builder.GetPatch();
    const std::vector<double>& gamma = patch.Gamma;
    const std::vector<double>& coefficients = patch.Coefficients;
    this->ErrorPass(patch.ElementBoxes.data(), patch.GetNumberOfElements(),
      [&](vtkIdType e, const int lo[3], const int hi[3], double* v)
      {
        const int nu = hi[0] - lo[0] + 1, nv = hi[1] - lo[1] + 1, nw = hi[2] - lo[2] + 1;
        std::fill(v, v + static_cast<std::size_t>(nu) * nv * nw, 0.0);
        for (vtkIdType s = this->SupportOffsets[e]; s < this->SupportOffsets[e + 1]; ++s)
        {
          const vtkIdType f = this->SupportIds[s];
          const double gc = gamma[f] * coefficients[f];
          const Table* t[3] = { &this->Tables[0][this->FunctionTable[3 * f]],
            &this->Tables[1][this->FunctionTable[3 * f + 1]],
            &this->Tables[2][this->FunctionTable[3 * f + 2]] };
          int a[3], z[3];
          for (int d = 0; d < 3; ++d)
          {
            a[d] = std::max(lo[d], t[d]->Start);
            z[d] = std::min(hi[d], t[d]->Start + t[d]->Count - 1);
          }
          for (int k = a[2]; k <= z[2]; ++k)
          {
            const double wk = gc * t[2]->Values[k - t[2]->Start];
            for (int j = a[1]; j <= z[1]; ++j)
            {
              const double wjk = wk * t[1]->Values[j - t[1]->Start];
              double* row = v + (static_cast<std::size_t>(k - lo[2]) * nv + (j - lo[1])) * nu;
              for (int i = a[0]; i <= z[0]; ++i)
              {
                row[i - lo[0]] += wjk * t[0]->Values[i - t[0]->Start];
              }
            }
          }
        }
      });
  }

  // The same from the Bezier form (the output): once, at the end.
  void EvaluateFromBezier(const vtkLRSplineBezierVolume& volume)
  {
    this->ErrorPass(volume.Boxes.data(), volume.GetNumberOfElements(),
      [&](vtkIdType e, const int lo[3], const int hi[3], double* v)
      {
        const double* box = volume.GetBox(e);
        for (int k = lo[2]; k <= hi[2]; ++k)
        {
          for (int j = lo[1]; j <= hi[1]; ++j)
          {
            for (int i = lo[0]; i <= hi[0]; ++i)
            {
              const double c[3] = { static_cast<double>(i), static_cast<double>(j),
                static_cast<double>(k) };
              double s[3];
              for (int d = 0; d < 3; ++d)
              {
                s[d] = std::min(1.0, std::max(0.0, (c[d] - box[d]) / (box[d + 3] - box[d])));
              }
              volume.EvaluateLocal(e, s, v++, nullptr);
            }
          }
        }
      });
  }

  // Halvings of the initial element sides reached (largest over directions).
  int Levels()
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

  enum Outcome
  {
    REFINED,
    ELEMENT_LIMIT,
    NOTHING_REFINABLE,
    NO_PROGRESS,
    FAILED
  };

  // Mark the elements above the tolerance and refine on each the basis
  // function of smallest support that can still be refined (the element
  // itself may be as small as allowed while larger functions on it are not).
  Outcome Refine(double tolerance, vtkIdType maximumElements, std::string* error)
  {
    const vtkLRSplinePatch& patch = this->Builder.GetPatch();
    const vtkIdType ne = patch.GetNumberOfElements();
    const vtkIdType nf = patch.GetNumberOfBasisFunctions();
    std::vector<vtkIdType> marked;
    for (vtkIdType e = 0; e < ne; ++e)
    {
      if (this->ElementError[e] > tolerance)
      {
        marked.push_back(e);
      }
    }
    std::stable_sort(marked.begin(), marked.end(),
      [this](vtkIdType a, vtkIdType b) { return this->ElementError[a] > this->ElementError[b]; });
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

private:
  struct Table
  {
    int Start = 0;
    int Count = 0;
    double Sum = 0.0;
    std::vector<double> Values;
  };
  std::vector<Table> Tables[3];
  std::vector<int> FunctionTable; // 3 per function
  std::vector<vtkIdType> SupportOffsets, SupportIds;
  std::vector<vtkIdType> FunctionElementOffsets, FunctionElements;
  std::vector<vtkIdType> RowOffsets;
  std::vector<std::vector<int>> Rows, ElementLists;
  std::vector<int> Columns;
  std::vector<double> Entries;

  // Per element (in parallel): the spline at its voxels from `values`,
  // then the largest error, and the sum of squares over all voxels.
  template <typename ValuesT>
  void ErrorPass(const double* boxes, vtkIdType ne, ValuesT&& values)
  {
    this->ElementError.assign(ne, 0.0);
    vtkSMPThreadLocal<Statistics> tlStats;
    vtkSMPThreadLocal<std::vector<double>> tlBuffer;
    const std::vector<double>& data = *this->Values;
    const int nx = this->N[0], ny = this->N[1];
    vtkSMPTools::For(0, ne,
      [&](vtkIdType begin, vtkIdType end)
      {
        Statistics& stats = tlStats.Local();
        std::vector<double>& buffer = tlBuffer.Local();
        for (vtkIdType e = begin; e < end; ++e)
        {
          int lo[3], hi[3];
          this->VoxelRange(boxes + 6 * e, lo, hi);
          if (lo[0] > hi[0] || lo[1] > hi[1] || lo[2] > hi[2])
          {
            continue; // an element between voxels
          }
          const std::size_t count =
            static_cast<std::size_t>(hi[0] - lo[0] + 1) * (hi[1] - lo[1] + 1) * (hi[2] - lo[2] + 1);
          if (buffer.size() < count)
          {
            buffer.resize(count);
          }
          values(e, lo, hi, buffer.data());
          const double* v = buffer.data();
          double worst = 0.0;
          for (int k = lo[2]; k <= hi[2]; ++k)
          {
            for (int j = lo[1]; j <= hi[1]; ++j)
            {
              const double* f = data.data() + (static_cast<std::size_t>(k) * ny + j) * nx;
              for (int i = lo[0]; i <= hi[0]; ++i)
              {
                const double err = std::abs(*v++ - f[i]);
                worst = std::max(worst, err);
                stats.SumSquares += err * err;
              }
            }
          }
          this->ElementError[e] = worst;
          stats.MaxError = std::max(stats.MaxError, worst);
        }
      });
    this->Stats = Statistics();
    for (const Statistics& st : tlStats)
    {
      this->Stats.MaxError = std::max(this->Stats.MaxError, st.MaxError);
      this->Stats.SumSquares += st.SumSquares;
    }
  }

  double Trilinear(const double g[3]) const
  {
    int i0[3];
    double t[3];
    for (int d = 0; d < 3; ++d)
    {
      const double x = std::min(static_cast<double>(this->N[d] - 1), std::max(0.0, g[d]));
      i0[d] = std::min(this->N[d] - 2, static_cast<int>(std::floor(x)));
      t[d] = x - i0[d];
    }
    const std::vector<double>& f = *this->Values;
    double v = 0.0;
    for (int c = 0; c < 8; ++c)
    {
      const int di = c & 1, dj = (c >> 1) & 1, dk = (c >> 2) & 1;
      const double w = (di ? t[0] : 1 - t[0]) * (dj ? t[1] : 1 - t[1]) * (dk ? t[2] : 1 - t[2]);
      if (w != 0.0)
      {
        v += w *
          f[(static_cast<std::size_t>(i0[2] + dk) * this->N[1] + i0[1] + dj) * this->N[0] + i0[0] +
            di];
      }
    }
    return v;
  }

  // Voxels of an element: integer coordinates in [lo, hi) per direction, and
  // the upper end of the domain with the elements touching it.
  void VoxelRange(const double* box, int lo[3], int hi[3]) const
  {
    for (int d = 0; d < 3; ++d)
    {
      const double top = this->N[d] - 1;
      lo[d] = static_cast<int>(std::ceil(box[d]));
      hi[d] = box[d + 3] >= top ? this->N[d] - 1 : static_cast<int>(std::ceil(box[d + 3])) - 1;
    }
  }

  // The functions on every element and the elements in every function's
  // support (the builder's meshes are valid: every support is a union of
  // elements). Each function is registered in the cells of a grid that its
  // support overlaps; the functions containing an element are among those of
  // the cell of its lower corner. The cells are as large as keeps the
  // registrations to a few per function.
  void ComputeSupports(const vtkLRSplinePatch& patch)
  {
    const vtkIdType ne = patch.GetNumberOfElements();
    const vtkIdType nf = patch.GetNumberOfBasisFunctions();
    double volume = 0.0;
    for (vtkIdType f = 0; f < nf; ++f)
    {
      double v = 1.0;
      for (int d = 0; d < 3; ++d)
      {
        const double* t = patch.GetKnots(f, d);
        v *= t[patch.Order[d]] - t[0] + 1.0;
      }
      volume += v;
    }
    const double cell = std::max(1.0, std::cbrt(volume / (8.0 * std::max<vtkIdType>(1, nf))));
    int G[3];
    for (int d = 0; d < 3; ++d)
    {
      G[d] = std::max(1, static_cast<int>(std::ceil((this->N[d] - 1) / cell)));
    }
    auto cellOf = [&](double x, int d)
    { return std::min(G[d] - 1, std::max(0, static_cast<int>(std::floor(x / cell)))); };
    auto cellRange = [&](const vtkIdType f, int c0[3], int c1[3])
    {
      for (int d = 0; d < 3; ++d)
      {
        const double* t = patch.GetKnots(f, d);
        c0[d] = cellOf(t[0], d);
        c1[d] = std::max(
          c0[d], std::min(G[d] - 1, static_cast<int>(std::ceil(t[patch.Order[d]] / cell)) - 1));
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

  // Values of every distinct local knot vector at the voxel coordinates.
  void BuildTables(const vtkLRSplinePatch& patch)
  {
    const vtkIdType nf = patch.GetNumberOfBasisFunctions();
    this->FunctionTable.resize(3 * nf);
    for (int d = 0; d < 3; ++d)
    {
      this->Tables[d].clear();
      const int order = patch.Order[d];
      const int nk = order + 1;
      const double top = this->N[d] - 1;
      std::unordered_map<std::string, int> ids;
      for (vtkIdType f = 0; f < nf; ++f)
      {
        const double* t = patch.GetKnots(f, d);
        std::string key(reinterpret_cast<const char*>(t), sizeof(double) * nk);
        auto it = ids.find(key);
        if (it != ids.end())
        {
          this->FunctionTable[3 * f + d] = it->second;
          continue;
        }
        Table table;
        const int c0 = std::max(0, static_cast<int>(std::ceil(t[0])));
        const int c1 = std::min(this->N[d] - 1, static_cast<int>(std::floor(t[order])));
        std::vector<double> v;
        for (int c = c0; c <= c1; ++c)
        {
          v.push_back(vtkLRSplinePatch::BSplineValue(t, order, c, c == top && t[order] == top));
        }
        // Trim the zeros at both ends.
        std::size_t first = 0, last = v.size();
        while (first < last && v[first] == 0.0)
        {
          ++first;
        }
        while (last > first && v[last - 1] == 0.0)
        {
          --last;
        }
        table.Start = c0 + static_cast<int>(first);
        table.Count = static_cast<int>(last - first);
        table.Values.assign(v.begin() + first, v.begin() + last);
        for (double x : table.Values)
        {
          table.Sum += x;
        }
        const int id = static_cast<int>(this->Tables[d].size());
        this->Tables[d].push_back(std::move(table));
        ids.emplace(std::move(key), id);
        this->FunctionTable[3 * f + d] = id;
      }
    }
  }

  double Gram(int d, int a, int b) const
  {
    const Table& ta = this->Tables[d][a];
    const Table& tb = this->Tables[d][b];
    const int lo = std::max(ta.Start, tb.Start);
    const int hi = std::min(ta.Start + ta.Count, tb.Start + tb.Count);
    double s = 0.0;
    for (int c = lo; c < hi; ++c)
    {
      s += ta.Values[c - ta.Start] * tb.Values[c - tb.Start];
    }
    return s;
  }

  // q = (A + D) x
  void Multiply(
    const std::vector<double>& x, const std::vector<double>& delta, std::vector<double>& q) const
  {
    const vtkIdType nf = static_cast<vtkIdType>(x.size());
    vtkSMPTools::For(0, nf,
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType f = begin; f < end; ++f)
        {
          double s = delta[f] * x[f];
          for (vtkIdType k = this->RowOffsets[f]; k < this->RowOffsets[f + 1]; ++k)
          {
            s += this->Entries[k] * x[this->Columns[k]];
          }
          q[f] = s;
        }
      });
  }
};
}

//------------------------------------------------------------------------------
vtkLRSplineImageFitter::vtkLRSplineImageFitter()
{
  this->SetInputArrayToProcess(
    0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::SCALARS);
}

vtkLRSplineImageFitter::~vtkLRSplineImageFitter()
{
  this->SetFieldName(nullptr);
  this->SetFileName(nullptr);
}

//------------------------------------------------------------------------------
int vtkLRSplineImageFitter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkCompositeDataSet");
  return 1;
}

//------------------------------------------------------------------------------
int vtkLRSplineImageFitter::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  outputVector->GetInformationObject(0)->Set(CAN_HANDLE_PIECE_REQUEST(), 1);
  return 1;
}

//------------------------------------------------------------------------------
int vtkLRSplineImageFitter::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  // Every piece fits the whole image.
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  if (inInfo)
  {
    inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(), 0);
    inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(), 1);
    inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(), 0);
    if (inInfo->Has(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()))
    {
      inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(),
        inInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()), 6);
    }
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkLRSplineImageFitter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  const auto start = std::chrono::steady_clock::now();
  vtkDataObject* input = vtkDataObject::GetData(inputVector[0], 0);
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkMultiBlockDataSet* output = vtkMultiBlockDataSet::GetData(outInfo);
  this->MaximumError = this->RMSError = this->AbsoluteTolerance = this->FitTime = 0.0;
  this->ToleranceMet = false;
  this->NumberOfElements = this->NumberOfBasisFunctions = 0;
  this->NumberOfRefinementLevels = this->NumberOfIterations = 0;

  // The settings.
  if (!(this->Tolerance > 0) || !std::isfinite(this->Tolerance))
  {
    vtkErrorMacro(<< "Tolerance must be positive and finite (it is " << this->Tolerance << ")");
    return 0;
  }
  for (int d = 0; d < 3; ++d)
  {
    if (this->Degree[d] < 1 || this->Degree[d] > 5)
    {
      vtkErrorMacro(<< "Degree must be 1 to 5 in every direction (it is " << this->Degree[0] << " "
                    << this->Degree[1] << " " << this->Degree[2] << ")");
      return 0;
    }
    if (this->InitialNumberOfElements[d] < 1)
    {
      vtkErrorMacro(<< "InitialNumberOfElements must be at least 1 in every direction");
      return 0;
    }
  }
  if (!std::isfinite(this->MinimumElementSize) || !std::isfinite(this->Regularization))
  {
    vtkErrorMacro(<< "MinimumElementSize and Regularization must be finite");
    return 0;
  }

  // The images: the input, or the leaves of a composite input.
  std::vector<vtkImageData*> images;
  if (vtkImageData* image = vtkImageData::SafeDownCast(input))
  {
    images.push_back(image);
  }
  else if (vtkCompositeDataSet* composite = vtkCompositeDataSet::SafeDownCast(input))
  {
    vtkSmartPointer<vtkCompositeDataIterator> it;
    it.TakeReference(composite->NewIterator());
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
    {
      vtkImageData* leaf = vtkImageData::SafeDownCast(it->GetCurrentDataObject());
      if (!leaf)
      {
        vtkErrorMacro(<< "every block of a composite input must be a vtkImageData (one is a "
                      << it->GetCurrentDataObject()->GetClassName() << ")");
        return 0;
      }
      images.push_back(leaf);
    }
  }
  if (images.empty())
  {
    vtkErrorMacro(<< "no input image: connect a vtkImageData (e.g. vtkNIFTIImageReader)");
    return 0;
  }

  // Check every image before allocating anything.
  struct Job
  {
    vtkImageData* Image;
    vtkDataArray* Array;
    int N[3];
    double Offset[3];
    double Scale[3];
  };
  std::vector<Job> jobs;
  for (std::size_t b = 0; b < images.size(); ++b)
  {
    vtkImageData* image = images[b];
    const std::string which =
      images.size() > 1 ? "block " + std::to_string(b) + ": " : std::string();
    Job job;
    job.Image = image;
    int extent[6];
    image->GetExtent(extent);
    vtkIdType voxels = 1;
    for (int d = 0; d < 3; ++d)
    {
      job.N[d] = extent[2 * d + 1] - extent[2 * d] + 1;
      if (job.N[d] < 2)
      {
        vtkErrorMacro(<< which
                      << "the image must have at least 2 voxels in every direction (it has "
                      << std::max(0, extent[1] - extent[0] + 1) << " x "
                      << std::max(0, extent[3] - extent[2] + 1) << " x "
                      << std::max(0, extent[5] - extent[4] + 1)
                      << "): an LR-spline volume needs a 3D image");
        return 0;
      }
      voxels *= job.N[d];
      if (voxels > MaximumVoxels)
      {
        vtkErrorMacro(<< which << "the image is too large to fit (" << job.N[0] << " x "
                      << extent[3] - extent[2] + 1 << " x " << extent[5] - extent[4] + 1
                      << " voxels; at most " << MaximumVoxels
                      << "): crop or shrink it first (vtkExtractVOI, vtkImageShrink3D)");
        return 0;
      }
    }
    if (vtkMatrix3x3* direction = image->GetDirectionMatrix())
    {
      if (!direction->IsIdentity())
      {
        vtkErrorMacro(<< which
                      << "the image has a non-identity direction matrix; the fitted spline is "
                         "placed by a scale and offset per axis only: resample the image to an "
                         "axis-aligned grid first (vtkImageReslice) or set its direction to the "
                         "identity and transform the result");
        return 0;
      }
    }
    const double* spacing = image->GetSpacing();
    const double* origin = image->GetOrigin();
    for (int d = 0; d < 3; ++d)
    {
      if (!(spacing[d] > 0) || !std::isfinite(spacing[d]) || !std::isfinite(origin[d]))
      {
        vtkErrorMacro(<< which << "the image spacing must be positive and finite (it is "
                      << spacing[0] << " " << spacing[1] << " " << spacing[2] << ")");
        return 0;
      }
      job.Scale[d] = spacing[d];
      job.Offset[d] = origin[d] + spacing[d] * extent[2 * d];
    }
    int association = -1;
    vtkDataArray* array = this->GetInputArrayToProcess(0, image, association);
    if (!array)
    {
      vtkInformation* arrayInfo = this->GetInputArrayInformation(0);
      const char* name = arrayInfo && arrayInfo->Has(vtkDataObject::FIELD_NAME())
        ? arrayInfo->Get(vtkDataObject::FIELD_NAME())
        : nullptr;
      if (name)
      {
        vtkErrorMacro(<< which << "no point-data array to fit: the image has no array \"" << name
                      << "\" (SetInputArrayToProcess)");
      }
      else
      {
        vtkErrorMacro(<< which
                      << "no point-data array to fit: the image has no active scalars; choose "
                         "an array with SetInputArrayToProcess");
      }
      return 0;
    }
    if (association != vtkDataObject::FIELD_ASSOCIATION_POINTS)
    {
      vtkErrorMacro(<< which << "the array \"" << (array->GetName() ? array->GetName() : "")
                    << "\" is not point data; the fitter fits voxel (point) values");
      return 0;
    }
    if (array->GetNumberOfComponents() != 1)
    {
      vtkErrorMacro(<< which << "the array \"" << (array->GetName() ? array->GetName() : "")
                    << "\" has " << array->GetNumberOfComponents()
                    << " components; the fitter needs a scalar (extract a component or the "
                       "magnitude first)");
      return 0;
    }
    if (array->GetNumberOfTuples() != voxels)
    {
      vtkErrorMacro(<< which << "the array has " << array->GetNumberOfTuples() << " values for "
                    << voxels << " voxels");
      return 0;
    }
    job.Array = array;
    jobs.push_back(job);
  }

  // The voxel values, checked, and the data range (over all images).
  std::vector<std::vector<double>> values(jobs.size());
  double range[2] = { VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
  for (std::size_t b = 0; b < jobs.size(); ++b)
  {
    values[b].resize(static_cast<std::size_t>(jobs[b].Array->GetNumberOfTuples()));
    std::atomic<bool> finite(true);
    CopyWorker worker;
    if (!vtkArrayDispatch::Dispatch::Execute(jobs[b].Array, worker, values[b], finite))
    {
      worker(jobs[b].Array, values[b], finite);
    }
    if (!finite)
    {
      vtkErrorMacro(<< (jobs.size() > 1 ? "block " + std::to_string(b) + ": " : std::string())
                    << "the array \"" << (jobs[b].Array->GetName() ? jobs[b].Array->GetName() : "")
                    << "\" has NaN or infinite values; mask or replace them first");
      return 0;
    }
    for (double v : values[b])
    {
      range[0] = std::min(range[0], v);
      range[1] = std::max(range[1], v);
    }
  }
  double tolerance = this->ToleranceMode == RELATIVE_TOLERANCE
    ? this->Tolerance * (range[1] - range[0])
    : this->Tolerance;
  // A constant image: its constant, up to rounding.
  tolerance = std::max(tolerance, 1e-10 * std::max(std::abs(range[0]), std::abs(range[1])));
  this->AbsoluteTolerance = tolerance;

  int piece = 0, numPieces = 1;
  if (outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER()))
  {
    piece = outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER());
    numPieces =
      std::max(1, outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES()));
    piece = std::max(0, std::min(piece, numPieces - 1));
  }

  const int rounds = std::min(MaximumRounds, 3 * (this->MaximumRefinementLevels + 1));
  double sumSquares = 0.0, voxelCount = 0.0;
  bool allMet = true;
  std::vector<vtkLRSplinePatch> written;
  output->SetNumberOfBlocks(static_cast<unsigned int>(jobs.size()));
  for (std::size_t b = 0; b < jobs.size(); ++b)
  {
    const Job& job = jobs[b];
    const std::string which = jobs.size() > 1 ? "block " + std::to_string(b) + ": " : std::string();
    ImageFit fit;
    fit.Values = &values[b];
    std::copy(job.N, job.N + 3, fit.N);
    std::copy(this->Degree, this->Degree + 3, fit.Degree);
    fit.Regularization = this->Regularization;
    fit.Tolerance = tolerance;
    std::string error;
    if (!fit.Initialize(this->InitialNumberOfElements, this->AlignKnotsToVoxels != 0,
          this->MinimumElementSize, this->MaximumRefinementLevels, &error))
    {
      vtkErrorMacro(<< which << "cannot make the initial spline: " << error);
      output->Initialize();
      return 0;
    }
    std::vector<double> history;
    vtkLRSplineBezierVolume volume;
    std::string stopReason;
    bool met = false;
    int iteration = 0;
    for (;; ++iteration)
    {
      if (!fit.Solve(&error))
      {
        vtkErrorMacro(<< which << "the fit failed: " << error);
        output->Initialize();
        return 0;
      }
      fit.EvaluateFromBasis();
      const vtkLRSplinePatch& patch = fit.Builder.GetPatch();
      const vtkIdType voxels = static_cast<vtkIdType>(values[b].size());
      history.insert(history.end(),
        { static_cast<double>(patch.GetNumberOfElements()),
          static_cast<double>(patch.GetNumberOfBasisFunctions()), fit.Stats.MaxError,
          std::sqrt(fit.Stats.SumSquares / voxels), static_cast<double>(fit.SolverIterations) });
      this->UpdateProgress((b + std::min(1.0, (iteration + 1.0) / (rounds + 1.0))) / jobs.size());
      if (fit.Stats.MaxError <= tolerance)
      {
        met = true;
        break;
      }
      if (this->CheckAbort())
      {
        stopReason = "the update was aborted";
        break;
      }
      if (iteration + 1 >= rounds)
      {
        stopReason = "the limit of " + std::to_string(rounds) + " refinement rounds was reached";
        break;
      }
      const ImageFit::Outcome outcome =
        fit.Refine(tolerance, this->MaximumNumberOfElements, &error);
      if (outcome == ImageFit::FAILED)
      {
        vtkErrorMacro(<< which << "the refinement failed: " << error);
        output->Initialize();
        return 0;
      }
      if (outcome == ImageFit::ELEMENT_LIMIT)
      {
        stopReason = "MaximumNumberOfElements (" + std::to_string(this->MaximumNumberOfElements) +
          ") was reached";
        break;
      }
      if (outcome == ImageFit::NOTHING_REFINABLE)
      {
        stopReason = "the elements above the tolerance are at MinimumElementSize (" +
          std::to_string(this->MinimumElementSize) + " voxels) or MaximumRefinementLevels (" +
          std::to_string(this->MaximumRefinementLevels) + ")";
        break;
      }
      if (outcome == ImageFit::NO_PROGRESS)
      {
        stopReason = "the refinement did not split any element";
        break;
      }
    }
    // The output's Bezier form, and the errors it has at the voxels.
    const vtkLRSplinePatch& patch = fit.Builder.GetPatch();
    if (!patch.ExtractBezier(volume, &error))
    {
      vtkErrorMacro(<< which << "the fitted spline is invalid: " << error);
      output->Initialize();
      return 0;
    }
    fit.EvaluateFromBezier(volume);
    if (met && !(fit.Stats.MaxError <= tolerance))
    {
      met = false;
      stopReason = "the Bezier form differs from the basis form by rounding";
    }
    const int levels = fit.Levels();
    const double rms = std::sqrt(fit.Stats.SumSquares / static_cast<double>(values[b].size()));
    if (!met)
    {
      allMet = false;
      vtkWarningMacro(<< which << "the tolerance " << tolerance
                      << " is not met everywhere: maximum error " << fit.Stats.MaxError << " (RMS "
                      << rms << ") with " << patch.GetNumberOfElements() << " elements after "
                      << iteration + 1 << (iteration == 0 ? " fit" : " fits") << ", because "
                      << stopReason);
    }
    this->MaximumError = std::max(this->MaximumError, fit.Stats.MaxError);
    sumSquares += fit.Stats.SumSquares;
    voxelCount += static_cast<double>(values[b].size());
    this->NumberOfElements += patch.GetNumberOfElements();
    this->NumberOfBasisFunctions += patch.GetNumberOfBasisFunctions();
    this->NumberOfRefinementLevels = std::max(this->NumberOfRefinementLevels, levels);
    this->NumberOfIterations = std::max(this->NumberOfIterations, iteration + 1);

    // The output block: this piece's elements, in the reader's format.
    vtkLRSplineBezierGrid::Options options;
    options.PatchIndex = static_cast<int>(b);
    const vtkIdType ne = patch.GetNumberOfElements();
    options.FirstElement = ne * piece / numPieces;
    options.LastElement = ne * (piece + 1) / numPieces;
    std::copy(job.Scale, job.Scale + 3, options.Scale);
    std::copy(job.Offset, job.Offset + 3, options.Offset);
    const char* arrayName = job.Array->GetName();
    options.FieldName = (this->FieldName && *this->FieldName)
      ? this->FieldName
      : ((arrayName && *arrayName) ? arrayName : "Field");
    options.SourceFormat = "vtkLRSplineImageFitter (least squares, local refinement)";
    vtkLRSplineBezierVolume pieceVolume;
    pieceVolume.Degree[0] = volume.Degree[0];
    pieceVolume.Degree[1] = volume.Degree[1];
    pieceVolume.Degree[2] = volume.Degree[2];
    pieceVolume.NumberOfComponents = volume.NumberOfComponents;
    const std::size_t per =
      static_cast<std::size_t>(volume.GetCoefficientsPerElement()) * volume.NumberOfComponents;
    pieceVolume.Boxes.assign(volume.Boxes.begin() + 6 * options.FirstElement,
      volume.Boxes.begin() + 6 * options.LastElement);
    pieceVolume.Coefficients.assign(volume.Coefficients.begin() + per * options.FirstElement,
      volume.Coefficients.begin() + per * options.LastElement);
    vtkSmartPointer<vtkUnstructuredGrid> grid =
      vtkLRSplineBezierGrid::Build(patch, pieceVolume, options, &error);
    if (!grid)
    {
      vtkErrorMacro(<< which << "cannot build the output: " << error);
      output->Initialize();
      return 0;
    }
    vtkNew<vtkDoubleArray> elementError;
    elementError->SetName("LRFitElementMaxError");
    elementError->SetNumberOfTuples(options.LastElement - options.FirstElement);
    for (vtkIdType e = options.FirstElement; e < options.LastElement; ++e)
    {
      elementError->SetValue(e - options.FirstElement, fit.ElementError[e]);
    }
    grid->GetCellData()->AddArray(elementError);
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
    addDouble("LRFitMaximumError", { fit.Stats.MaxError });
    addDouble("LRFitRMSError", { rms });
    addDouble("LRFitTolerance", { tolerance });
    addInt("LRFitToleranceMet", met ? 1 : 0);
    addInt("LRFitIterations", iteration + 1);
    addInt("LRFitRefinementLevels", levels);
    addDouble("LRFitDataRange", { range[0], range[1] });
    vtkNew<vtkDoubleArray> hist;
    hist->SetName("LRFitHistory");
    hist->SetNumberOfComponents(5);
    hist->SetComponentName(0, "Elements");
    hist->SetComponentName(1, "BasisFunctions");
    hist->SetComponentName(2, "MaximumError");
    hist->SetComponentName(3, "RMSError");
    hist->SetComponentName(4, "SolverIterations");
    hist->SetNumberOfTuples(static_cast<vtkIdType>(history.size() / 5));
    std::copy(history.begin(), history.end(), hist->GetPointer(0));
    fd->AddArray(hist);
    output->SetBlock(static_cast<unsigned int>(b), grid);
    output->GetMetaData(static_cast<unsigned int>(b))
      ->Set(vtkCompositeDataSet::NAME(), ("Patch " + std::to_string(b)).c_str());
    if (this->FileName && *this->FileName && piece == 0)
    {
      written.push_back(patch);
    }
  }
  this->RMSError = voxelCount > 0 ? std::sqrt(sumSquares / voxelCount) : 0.0;
  this->ToleranceMet = allMet;

  if (!written.empty())
  {
    std::ofstream out(this->FileName, std::ios::out | std::ios::binary);
    for (const vtkLRSplinePatch& patch : written)
    {
      patch.Write(out);
    }
    out.close();
    if (!out)
    {
      vtkErrorMacro(<< "cannot write \"" << this->FileName << "\"");
      output->Initialize();
      return 0;
    }
  }
  this->FitTime = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  vtkFieldData* fd = output->GetNumberOfBlocks() > 0
    ? vtkDataObject::SafeDownCast(output->GetBlock(0))->GetFieldData()
    : nullptr;
  if (fd)
  {
    vtkNew<vtkDoubleArray> seconds;
    seconds->SetName("LRFitSeconds");
    seconds->InsertNextValue(this->FitTime);
    fd->AddArray(seconds);
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkLRSplineImageFitter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Degree: " << this->Degree[0] << " " << this->Degree[1] << " " << this->Degree[2]
     << "\n";
  os << indent << "InitialNumberOfElements: " << this->InitialNumberOfElements[0] << " "
     << this->InitialNumberOfElements[1] << " " << this->InitialNumberOfElements[2] << "\n";
  os << indent << "Tolerance: " << this->Tolerance << "\n";
  os << indent
     << "ToleranceMode: " << (this->ToleranceMode == RELATIVE_TOLERANCE ? "Relative" : "Absolute")
     << "\n";
  os << indent << "MaximumNumberOfElements: " << this->MaximumNumberOfElements << "\n";
  os << indent << "MaximumRefinementLevels: " << this->MaximumRefinementLevels << "\n";
  os << indent << "MinimumElementSize: " << this->MinimumElementSize << "\n";
  os << indent << "AlignKnotsToVoxels: " << this->AlignKnotsToVoxels << "\n";
  os << indent << "Regularization: " << this->Regularization << "\n";
  os << indent << "FieldName: " << (this->FieldName ? this->FieldName : "(input array's)") << "\n";
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "MaximumError: " << this->MaximumError << "\n";
  os << indent << "RMSError: " << this->RMSError << "\n";
  os << indent << "AbsoluteTolerance: " << this->AbsoluteTolerance << "\n";
  os << indent << "ToleranceMet: " << this->ToleranceMet << "\n";
  os << indent << "NumberOfElements: " << this->NumberOfElements << "\n";
  os << indent << "NumberOfBasisFunctions: " << this->NumberOfBasisFunctions << "\n";
  os << indent << "NumberOfRefinementLevels: " << this->NumberOfRefinementLevels << "\n";
  os << indent << "NumberOfIterations: " << this->NumberOfIterations << "\n";
  os << indent << "FitTime: " << this->FitTime << "\n";
}
