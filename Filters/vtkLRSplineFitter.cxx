// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLRSplineFitter.h"

#include "vtkLRSplineArrayNames.h"
#include "vtkLRSplineBezierVolume.h"
#include "vtkLRSplineElementLocator.h"
#include "vtkLRSplineField.h"
#include "vtkLRSplineFitCore.h"
#include "vtkLRSplinePatch.h"
#include "vtkSplineVizLocalOutliers.h"
#include "vtkSplineVizPieces.h"
#include "vtkSplineVizProgress.h"

#include "vtkAppendPolyData.h"
#include "vtkCellArray.h"
#include "vtkCellCenters.h"
#include "vtkCellData.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkDataSetSurfaceFilter.h"
#include "vtkDataSetTriangleFilter.h"
#include "vtkDoubleArray.h"
#include "vtkFeatureEdges.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPoints.h"
#include "vtkPolyDataNormals.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStringArray.h"
#include "vtkTriangleFilter.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkLRSplineFitter);

namespace
{
// Functions whose data weight (sum of their scaled B-spline over the points)
// is below this are pulled towards the previous fit.
constexpr double LittleData = 1.0;
// Conjugate gradients: the accuracy of the data values relative to the
// tolerance (1 %: the errors that decide the refinement move by at most that;
// scattered data leaves the normal equations worse conditioned than voxels,
// and 1e-4 as for images doubled the iterations on a CFD mesh, 2000 at most).
constexpr double SolverAccuracy = 1e-2;
// MBA sweeps per level (GoTools runs LR-MBA twice per level).
constexpr int MBASweeps = 2;
// RemoveOutliers: detection rounds at most (each with the tolerance of the
// values still in), and their share of the progress bar.
constexpr int OutlierRounds = 3;
constexpr double OutlierProgress = 0.1;
// A coefficient this many data ranges beyond the data's values makes the
// fitter warn that the spline may swing between the data points.
constexpr double OscillationFactor = 10.0;

// The data: parameters (3 per point) and values (Dim per point).
struct PointData
{
  std::vector<double> U;
  std::vector<double> F;
  int Dim = 1;
  vtkIdType Size() const { return static_cast<vtkIdType>(this->U.size() / 3); }
};

// The fit of a point cloud on the core's LR spline.
class PointFit
{
public:
  vtkLRSplineFitCore Core;
  const PointData* Data = nullptr;
  double Top[3] = { 1, 1, 1 }; // upper end of the parameter domain
  double Regularization = 0.1;
  double Smoothing = 0.0;
  double Tolerance = 0.0;
  bool RMSMode = false;

  // The patch being fitted (the builder's, compact).
  const vtkLRSplinePatch* Patch = nullptr;
  // Points per element (CSR, rebuilt after each refinement).
  std::vector<vtkIdType> PointOffsets, PointIds;
  // Per element: the largest (or RMS) error of its points; global statistics.
  std::vector<double> ElementError;
  double MaxError = 0.0, SumSquares = 0.0;
  int SolverIterations = 0;

  // Sort the points into the elements of the current patch.
  bool Bin(std::string* error)
  {
    const vtkLRSplinePatch& patch = this->Core.Builder.GetPatch();
    this->Patch = &patch;
    const vtkIdType ne = patch.GetNumberOfElements();
    const vtkIdType np = this->Data->Size();
    vtkLRSplineElementLocator locator;
    if (!locator.Build(
          patch.ElementBoxes.data(), ne, vtkLRSplineElementLocator::KD_FOREST, nullptr, error))
    {
      return false;
    }
    std::vector<vtkIdType> owner(np);
    std::atomic<bool> lost(false);
    vtkSMPTools::For(0, np,
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType p = begin; p < end; ++p)
        {
          owner[p] = locator.FindElement(&this->Data->U[3 * p]);
          if (owner[p] < 0)
          {
            lost = true;
          }
        }
      });
    if (lost)
    {
      *error = "a data point lies outside the spline's elements";
      return false;
    }
    this->PointOffsets.assign(ne + 1, 0);
    for (vtkIdType p = 0; p < np; ++p)
    {
      ++this->PointOffsets[owner[p] + 1];
    }
    for (vtkIdType e = 0; e < ne; ++e)
    {
      this->PointOffsets[e + 1] += this->PointOffsets[e];
    }
    this->PointIds.resize(np);
    std::vector<vtkIdType> fill(this->PointOffsets.begin(), this->PointOffsets.end() - 1);
    for (vtkIdType p = 0; p < np; ++p)
    {
      this->PointIds[fill[owner[p]]++] = p;
    }
    return true;
  }

  // w_i = gamma_i B_i(u) of the functions on element e at point p.
  void Basis(vtkIdType e, vtkIdType p, double* w) const
  {
    const vtkLRSplinePatch& patch = *this->Patch;
    const double* u = &this->Data->U[3 * p];
    const vtkIdType first = this->Core.SupportOffsets[e];
    const vtkIdType count = this->Core.SupportOffsets[e + 1] - first;
    for (vtkIdType k = 0; k < count; ++k)
    {
      const vtkIdType f = this->Core.SupportIds[first + k];
      double v = patch.Gamma[f];
      for (int d = 0; d < 3 && v != 0.0; ++d)
      {
        v *= vtkLRSplinePatch::BSplineValue(
          patch.GetKnots(f, d), patch.Order[d], u[d], u[d] >= this->Top[d]);
      }
      w[k] = v;
    }
  }

  // For every element (in parallel) and its points: body(e, p, w, count).
  template <typename BodyT>
  void ForPoints(BodyT&& body) const
  {
    const vtkIdType ne = static_cast<vtkIdType>(this->PointOffsets.size()) - 1;
    vtkSMPThreadLocal<std::vector<double>> tlW;
    vtkSMPTools::For(0, ne,
      [&](vtkIdType begin, vtkIdType end)
      {
        std::vector<double>& w = tlW.Local();
        for (vtkIdType e = begin; e < end; ++e)
        {
          const vtkIdType count = this->Core.SupportOffsets[e + 1] - this->Core.SupportOffsets[e];
          if (w.size() < static_cast<std::size_t>(count))
          {
            w.resize(count);
          }
          for (vtkIdType k = this->PointOffsets[e]; k < this->PointOffsets[e + 1]; ++k)
          {
            const vtkIdType p = this->PointIds[k];
            this->Basis(e, p, w.data());
            body(e, p, w.data(), count);
          }
        }
      });
  }

  // The residual r = f - s at every point (Dim per point), and the errors.
  void Residuals(std::vector<double>& residual)
  {
    const vtkLRSplinePatch& patch = this->Core.Builder.GetPatch();
    const int dim = this->Data->Dim;
    residual.resize(this->Data->F.size());
    this->ForPoints(
      [&](vtkIdType e, vtkIdType p, const double* w, vtkIdType count)
      {
        const vtkIdType first = this->Core.SupportOffsets[e];
        for (int c = 0; c < dim; ++c)
        {
          double s = 0.0;
          for (vtkIdType k = 0; k < count; ++k)
          {
            s += w[k] * patch.Coefficients[this->Core.SupportIds[first + k] * dim + c];
          }
          residual[p * dim + c] = this->Data->F[p * dim + c] - s;
        }
      });
    this->Errors(residual);
  }

  // Per-element and global errors from the residuals.
  void Errors(const std::vector<double>& residual)
  {
    const vtkIdType ne = static_cast<vtkIdType>(this->PointOffsets.size()) - 1;
    const int dim = this->Data->Dim;
    this->ElementError.assign(ne, 0.0);
    vtkSMPThreadLocal<double> tlMax(0.0), tlSum(0.0);
    vtkSMPTools::For(0, ne,
      [&](vtkIdType begin, vtkIdType end)
      {
        double& worst = tlMax.Local();
        double& sum = tlSum.Local();
        for (vtkIdType e = begin; e < end; ++e)
        {
          double elementMax = 0.0, elementSum = 0.0;
          for (vtkIdType k = this->PointOffsets[e]; k < this->PointOffsets[e + 1]; ++k)
          {
            const double* r = &residual[this->PointIds[k] * dim];
            double s2 = 0.0;
            for (int c = 0; c < dim; ++c)
            {
              s2 += r[c] * r[c];
            }
            elementMax = std::max(elementMax, std::sqrt(s2));
            elementSum += s2;
          }
          const vtkIdType n = this->PointOffsets[e + 1] - this->PointOffsets[e];
          this->ElementError[e] =
            this->RMSMode ? (n > 0 ? std::sqrt(elementSum / n) : 0.0) : elementMax;
          worst = std::max(worst, elementMax);
          sum += elementSum;
        }
      });
    this->MaxError = 0.0;
    this->SumSquares = 0.0;
    for (double v : tlMax)
    {
      this->MaxError = std::max(this->MaxError, v);
    }
    for (double v : tlSum)
    {
      this->SumSquares += v;
    }
  }

  // One LR-MBA sweep on the residual: every point proposes a correction of
  // the coefficients of the functions on its element, each coefficient moves
  // by the weighted mean of its proposals.
  void MBASweep(const std::vector<double>& residual)
  {
    const vtkLRSplinePatch& patch = this->Core.Builder.GetPatch();
    const vtkIdType nf = patch.GetNumberOfBasisFunctions();
    const int dim = this->Data->Dim;
    vtkSMPThreadLocal<std::vector<double>> tlNum, tlDen;
    this->ForPoints(
      [&](vtkIdType e, vtkIdType p, const double* w, vtkIdType count)
      {
        std::vector<double>& num = tlNum.Local();
        std::vector<double>& den = tlDen.Local();
        if (den.empty())
        {
          num.assign(static_cast<std::size_t>(nf) * dim, 0.0);
          den.assign(nf, 0.0);
        }
        double sum2 = 0.0;
        for (vtkIdType k = 0; k < count; ++k)
        {
          sum2 += w[k] * w[k];
        }
        if (!(sum2 > 0))
        {
          return;
        }
        const vtkIdType first = this->Core.SupportOffsets[e];
        for (vtkIdType k = 0; k < count; ++k)
        {
          const vtkIdType f = this->Core.SupportIds[first + k];
          const double w2 = w[k] * w[k];
          // w^2 phi = w^3 r / sum2
          for (int c = 0; c < dim; ++c)
          {
            num[f * dim + c] += w2 * w[k] * residual[p * dim + c] / sum2;
          }
          den[f] += w2;
        }
      });
    std::vector<double> coefficients(patch.Coefficients.begin(), patch.Coefficients.end());
    std::vector<double> num(static_cast<std::size_t>(nf) * dim, 0.0), den(nf, 0.0);
    for (const std::vector<double>& v : tlNum)
    {
      for (std::size_t i = 0; i < v.size(); ++i)
      {
        num[i] += v[i];
      }
    }
    for (const std::vector<double>& v : tlDen)
    {
      for (std::size_t i = 0; i < v.size(); ++i)
      {
        den[i] += v[i];
      }
    }
    for (vtkIdType f = 0; f < nf; ++f)
    {
      if (den[f] > 0)
      {
        for (int c = 0; c < dim; ++c)
        {
          coefficients[f * dim + c] += num[f * dim + c] / den[f];
        }
      }
    }
    this->Core.Builder.SetCoefficients(coefficients);
  }

  // Regularized least squares with smoothing on the current mesh, each
  // component. False with a message when the smoothing cannot be assembled.
  bool LeastSquares(std::string* error)
  {
    const vtkLRSplinePatch& patch = this->Core.Builder.GetPatch();
    const vtkIdType nf = patch.GetNumberOfBasisFunctions();
    const int dim = this->Data->Dim;
    this->Core.BuildPattern(true);
    const std::vector<vtkIdType>& rowOffsets = this->Core.RowOffsets;
    const std::vector<int>& columns = this->Core.Columns;
    const std::size_t nnz = this->Core.Entries.size();
    struct Sums
    {
      std::vector<double> Entries, Rhs, Weight, DataDiagonal;
    };
    std::atomic<bool> failed(false);
    std::string failure;
    vtkSMPThreadLocal<Sums> tlSums;
    const vtkIdType ne = patch.GetNumberOfElements();
    vtkSMPThreadLocal<std::vector<double>> tlW, tlLocal;
    vtkSMPTools::For(0, ne,
      [&](vtkIdType begin, vtkIdType end)
      {
        Sums& sums = tlSums.Local();
        if (sums.Weight.empty())
        {
          sums.Entries.assign(nnz, 0.0);
          sums.Rhs.assign(static_cast<std::size_t>(nf) * dim, 0.0);
          sums.Weight.assign(nf, 0.0);
          sums.DataDiagonal.assign(nf, 0.0);
        }
        std::vector<double>& w = tlW.Local();
        std::vector<double>& local = tlLocal.Local();
        for (vtkIdType e = begin; e < end; ++e)
        {
          const vtkIdType first = this->Core.SupportOffsets[e];
          const vtkIdType count = this->Core.SupportOffsets[e + 1] - first;
          const vtkIdType points = this->PointOffsets[e + 1] - this->PointOffsets[e];
          // Smoothing on elements with fewer points than functions, fading
          // to none where the data alone can determine them.
          const double fade =
            std::max(0.0, 1.0 - static_cast<double>(points) / static_cast<double>(count));
          const double smoothing = this->Smoothing * fade;
          if (points == 0 && !(smoothing > 0))
          {
            continue;
          }
          w.resize(count);
          local.assign(static_cast<std::size_t>(count * count), 0.0);
          if (smoothing > 0)
          {
            std::string why;
            if (!this->Core.AddElementSmoothing(patch, e, smoothing, local.data(), &why))
            {
              bool expected = false;
              if (failed.compare_exchange_strong(expected, true))
              {
                failure = why;
              }
              continue;
            }
          }
          for (vtkIdType k = this->PointOffsets[e]; k < this->PointOffsets[e + 1]; ++k)
          {
            const vtkIdType p = this->PointIds[k];
            this->Basis(e, p, w.data());
            for (vtkIdType a = 0; a < count; ++a)
            {
              const vtkIdType f = this->Core.SupportIds[first + a];
              sums.Weight[f] += w[a];
              sums.DataDiagonal[f] += w[a] * w[a];
              for (int c = 0; c < dim; ++c)
              {
                sums.Rhs[f * dim + c] += w[a] * this->Data->F[p * dim + c];
              }
              for (vtkIdType b = 0; b < count; ++b)
              {
                local[a * count + b] += w[a] * w[b];
              }
            }
          }
          for (vtkIdType a = 0; a < count; ++a)
          {
            const vtkIdType f = this->Core.SupportIds[first + a];
            const int* row = columns.data() + rowOffsets[f];
            const int* rowEnd = columns.data() + rowOffsets[f + 1];
            for (vtkIdType b = 0; b < count; ++b)
            {
              const int g = static_cast<int>(this->Core.SupportIds[first + b]);
              const int* at = std::lower_bound(row, rowEnd, g);
              sums.Entries[at - columns.data()] += local[a * count + b];
            }
          }
        }
      });
    if (failed)
    {
      *error = "cannot assemble the smoothing term: " + failure;
      return false;
    }
    std::vector<double>& entries = this->Core.Entries;
    std::vector<double> rhs(static_cast<std::size_t>(nf) * dim, 0.0), weight(nf, 0.0);
    std::vector<double> dataDiagonal(nf, 0.0);
    for (const Sums& sums : tlSums)
    {
      if (sums.Weight.empty())
      {
        continue;
      }
      vtkSMPTools::For(0, static_cast<vtkIdType>(nnz),
        [&](vtkIdType begin, vtkIdType end)
        {
          for (vtkIdType i = begin; i < end; ++i)
          {
            entries[i] += sums.Entries[i];
          }
        });
      for (std::size_t i = 0; i < rhs.size(); ++i)
      {
        rhs[i] += sums.Rhs[i];
      }
      for (vtkIdType f = 0; f < nf; ++f)
      {
        weight[f] += sums.Weight[f];
        dataDiagonal[f] += sums.DataDiagonal[f];
      }
    }
    std::vector<double> diagonal(nf, 0.0);
    for (vtkIdType f = 0; f < nf; ++f)
    {
      const int* row = columns.data() + rowOffsets[f];
      diagonal[f] =
        entries[std::lower_bound(row, columns.data() + rowOffsets[f + 1], static_cast<int>(f)) -
          columns.data()];
    }
    // The pull towards the previous fit is scaled by the data's part of the
    // diagonal (A_ii); the preconditioner takes the whole (with the smoothing).
    std::vector<double> delta;
    vtkLRSplineFitCore::Regularize(weight, this->Regularization, LittleData, dataDiagonal, delta);
    for (vtkIdType f = 0; f < nf; ++f)
    {
      diagonal[f] += delta[f];
    }
    std::vector<double> coefficients(patch.Coefficients.begin(), patch.Coefficients.end());
    std::vector<double> b(nf), prior(nf), x;
    this->SolverIterations = 0;
    for (int c = 0; c < dim; ++c)
    {
      for (vtkIdType f = 0; f < nf; ++f)
      {
        b[f] = rhs[f * dim + c];
        prior[f] = coefficients[f * dim + c];
      }
      this->SolverIterations +=
        this->Core.Solve(b, prior, delta, diagonal, SolverAccuracy * this->Tolerance, x);
      for (vtkIdType f = 0; f < nf; ++f)
      {
        coefficients[f * dim + c] = x[f];
      }
    }
    this->Core.Builder.SetCoefficients(coefficients);
    this->Core.Columns.clear();
    this->Core.Entries.clear();
    return true;
  }

  // The errors of the output's Bezier form at the points.
  void ErrorsFromBezier(const vtkLRSplineBezierVolume& volume, std::vector<double>& residual)
  {
    const int dim = this->Data->Dim;
    const vtkIdType ne = volume.GetNumberOfElements();
    residual.resize(this->Data->F.size());
    vtkSMPTools::For(0, ne,
      [&](vtkIdType begin, vtkIdType end)
      {
        std::vector<double> v(dim);
        for (vtkIdType e = begin; e < end; ++e)
        {
          const double* box = volume.GetBox(e);
          for (vtkIdType k = this->PointOffsets[e]; k < this->PointOffsets[e + 1]; ++k)
          {
            const vtkIdType p = this->PointIds[k];
            double s[3];
            for (int d = 0; d < 3; ++d)
            {
              s[d] = std::min(
                1.0, std::max(0.0, (this->Data->U[3 * p + d] - box[d]) / (box[d + 3] - box[d])));
            }
            volume.EvaluateLocal(e, s, v.data(), nullptr);
            for (int c = 0; c < dim; ++c)
            {
              residual[p * dim + c] = this->Data->F[p * dim + c] - v[c];
            }
          }
        }
      });
    this->Errors(residual);
  }
};

// The boundary surface of a data set as triangles without data arrays.
vtkSmartPointer<vtkPolyData> BoundaryTriangles(vtkDataSet* data)
{
  vtkNew<vtkDataSetSurfaceFilter> surface;
  surface->SetInputData(data);
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(surface->GetOutputPort());
  triangles->PassVertsOff();
  triangles->PassLinesOff();
  triangles->Update();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(triangles->GetOutput());
  out->GetPointData()->Initialize();
  out->GetCellData()->Initialize();
  return out;
}

// Edges of a surface used by one triangle or by more than two.
vtkIdType OpenEdges(vtkPolyData* surface)
{
  if (surface->GetNumberOfPolys() == 0)
  {
    return 0;
  }
  vtkNew<vtkFeatureEdges> edges;
  edges->SetInputData(surface);
  edges->BoundaryEdgesOn();
  edges->NonManifoldEdgesOn();
  edges->FeatureEdgesOff();
  edges->ManifoldEdgesOff();
  edges->ColoringOff();
  edges->Update();
  return edges->GetOutput()->GetNumberOfLines();
}

// The range of the values (`dim` per point; of the vectors' lengths).
void DataRange(const std::vector<double>& values, int dim, double range[2])
{
  range[0] = VTK_DOUBLE_MAX;
  range[1] = -VTK_DOUBLE_MAX;
  const std::size_t np = values.size() / dim;
  for (std::size_t p = 0; p < np; ++p)
  {
    double v2 = 0.0;
    for (int c = 0; c < dim; ++c)
    {
      v2 += values[p * dim + c] * values[p * dim + c];
    }
    const double v = dim > 1 ? std::sqrt(v2) : values[p];
    range[0] = std::min(range[0], v);
    range[1] = std::max(range[1], v);
  }
}

// The parameter domain [0, m] per direction and the refinement limits
// (halvings of the initial elements down to `levels`).
void ConfigureFit(PointFit& fit, const int elements[3], int levels)
{
  for (int d = 0; d < 3; ++d)
  {
    fit.Top[d] = elements[d];
    fit.Core.InitialSide[d] = 1.0;
    fit.Core.Options.MinimumPart[d] = std::pow(2.0, -(levels + 0.5)) * (1.0 + 1e-9);
  }
  fit.Core.Options.Ratio = 0.5;
  fit.Core.MinimumCell = 1e-9;
}

// The initial tensor-product spline (unit knot intervals on the domain of
// ConfigureFit()), all coefficients the data mean.
bool InitializeFit(PointFit& fit, const int degree[3], const int elements[3], std::string* error)
{
  const PointData& data = *fit.Data;
  std::vector<double> breaks[3];
  for (int d = 0; d < 3; ++d)
  {
    for (int k = 0; k <= elements[d]; ++k)
    {
      breaks[d].push_back(k);
    }
  }
  if (!fit.Core.Builder.InitializeTensorProduct(degree, breaks, data.Dim, error))
  {
    return false;
  }
  const vtkIdType np = data.Size();
  std::vector<double> mean(data.Dim, 0.0);
  for (vtkIdType p = 0; p < np; ++p)
  {
    for (int c = 0; c < data.Dim; ++c)
    {
      mean[c] += data.F[p * data.Dim + c] / np;
    }
  }
  fit.Core.Builder.SetCoefficientsFromGreville(
    [&mean](const double*, double* c) { std::copy(mean.begin(), mean.end(), c); });
  return true;
}

// What the fit-and-refine loop needs of the filter's settings.
struct LoopSettings
{
  int Method = vtkLRSplineFitter::LEAST_SQUARES;
  int MaximumRefinementLevels = 10;
  vtkIdType MaximumNumberOfElements = 500000;
  vtkIdType MinimumPointsPerElement = 2;
  // The most fit-and-refine rounds (vtkLRSplineFitterBase::GetMaximumRounds()).
  int MaximumRounds = 33;
  // Progress already reported before the loop (outlier detection).
  double ProgressStart = 0.0;
};

// Fit, evaluate, refine until the tolerance is met or a limit is reached
// (met false, stopReason says which); progress and abort via `algorithm`.
// False with a message on failure.
bool FitLoop(PointFit& fit, const LoopSettings& settings, double tolerance, vtkAlgorithm* algorithm,
  std::vector<double>& residual, std::vector<double>& history, bool& met, int& iteration,
  std::string& stopReason, std::string* error)
{
  const int rounds = settings.MaximumRounds;
  const vtkIdType np = fit.Data->Size();
  met = false;
  iteration = 0;
  for (;; ++iteration)
  {
    fit.Core.ComputeSupports();
    if (!fit.Bin(error))
    {
      *error = "cannot sort the points into the elements: " + *error;
      return false;
    }
    if (settings.Method != vtkLRSplineFitter::MBA)
    {
      if (!fit.LeastSquares(error))
      {
        return false;
      }
    }
    else
    {
      fit.SolverIterations = 0;
    }
    if (settings.Method != vtkLRSplineFitter::LEAST_SQUARES)
    {
      for (int sweep = 0; sweep < MBASweeps; ++sweep)
      {
        fit.Residuals(residual);
        fit.MBASweep(residual);
      }
    }
    fit.Residuals(residual);
    const vtkLRSplinePatch& patch = fit.Core.Builder.GetPatch();
    const double rms = std::sqrt(fit.SumSquares / np);
    history.insert(history.end(),
      { static_cast<double>(patch.GetNumberOfElements()),
        static_cast<double>(patch.GetNumberOfBasisFunctions()), fit.MaxError, rms,
        static_cast<double>(fit.SolverIterations) });
    algorithm->UpdateProgress(settings.ProgressStart +
      (1.0 - settings.ProgressStart) * std::min(1.0, (iteration + 1.0) / (rounds + 1.0)));
    if ((fit.RMSMode ? rms : fit.MaxError) <= tolerance)
    {
      met = true;
      break;
    }
    if (algorithm->CheckAbort())
    {
      stopReason = "the update was aborted";
      break;
    }
    if (iteration + 1 >= rounds)
    {
      stopReason = "the limit of " + std::to_string(rounds) + " refinement rounds was reached";
      break;
    }
    // Elements with too few points to determine finer functions are not split.
    std::vector<double> marked = fit.ElementError;
    bool sparse = false;
    for (std::size_t e = 0; e < marked.size(); ++e)
    {
      if (fit.PointOffsets[e + 1] - fit.PointOffsets[e] < settings.MinimumPointsPerElement &&
        marked[e] > tolerance)
      {
        marked[e] = 0.0;
        sparse = true;
      }
    }
    const vtkLRSplineFitCore::Outcome outcome =
      fit.Core.Refine(marked, tolerance, settings.MaximumNumberOfElements, error);
    if (outcome == vtkLRSplineFitCore::FAILED)
    {
      *error = "the refinement failed: " + *error;
      return false;
    }
    if (outcome == vtkLRSplineFitCore::REFINED)
    {
      continue;
    }
    stopReason = vtkLRSplineFitCore::StopReason(outcome, settings.MaximumNumberOfElements,
      "MaximumRefinementLevels (" + std::to_string(settings.MaximumRefinementLevels) + ")" +
        (sparse ? " or hold fewer than MinimumPointsPerElement (" +
              std::to_string(settings.MinimumPointsPerElement) + ") data points"
                : std::string()));
    if (sparse && fit.Smoothing > 0)
    {
      std::ostringstream hint;
      hint << "; where elements hold few points, Smoothing (" << fit.Smoothing
           << ") also holds the spline back from them: a lower Smoothing follows them more "
              "closely, at the risk of swings between the points";
      stopReason += hint.str();
    }
    break;
  }
  return true;
}

// The fitted spline's Bezier form (the output), its errors at the points and
// the .lr file.
struct FitResult
{
  vtkLRSplineBezierVolume Volume;
};

bool FinishFit(PointFit& fit, std::vector<double>& residual, const char* fileName,
  FitResult& result, std::string* error)
{
  const vtkLRSplinePatch& patch = fit.Core.Builder.GetPatch();
  if (!patch.ExtractBezier(result.Volume, error))
  {
    *error = "the fitted spline is invalid: " + *error;
    return false;
  }
  fit.ErrorsFromBezier(result.Volume, residual);
  if (fileName && *fileName)
  {
    return vtkLRSplineFitCore::WritePatches(fileName, { patch }, error);
  }
  return true;
}

// The time of a data object's time step (false: it has none).
bool DataTime(vtkDataObject* object, double* time)
{
  vtkInformation* info = object ? object->GetInformation() : nullptr;
  if (!info || !info->Has(vtkDataObject::DATA_TIME_STEP()))
  {
    return false;
  }
  *time = info->Get(vtkDataObject::DATA_TIME_STEP());
  return true;
}

// The data sets to fit: the input, or the non-empty leaves of a composite input.
std::vector<vtkDataSet*> Leaves(vtkDataObject* input)
{
  std::vector<vtkDataSet*> leaves = vtkCompositeDataSet::GetDataSets(input);
  if (vtkCompositeDataSet::SafeDownCast(input))
  {
    leaves.erase(std::remove_if(leaves.begin(), leaves.end(),
                   [](vtkDataSet* leaf) { return leaf->GetNumberOfPoints() == 0; }),
      leaves.end());
  }
  return leaves;
}

// What the output says of the fit beyond vtkLRSplineFitCore's report: the
// domain, whether the previous mesh was reused, the number of data points
// fitted and of those left out (RemoveOutliers).
void AddFitFieldData(
  vtkFieldData* fd, const double domain[6], bool reused, vtkIdType points, vtkIdType outliers)
{
  vtkNew<vtkDoubleArray> box;
  box->SetName(vtkLRSplineArrayNames::FitDomain);
  box->SetNumberOfComponents(6);
  box->InsertNextTuple(domain);
  fd->AddArray(box);
  vtkNew<vtkIdTypeArray> reuse;
  reuse->SetName(vtkLRSplineArrayNames::FitReusedPreviousMesh);
  reuse->InsertNextValue(reused ? 1 : 0);
  fd->AddArray(reuse);
  vtkNew<vtkIdTypeArray> count;
  count->SetName(vtkLRSplineArrayNames::FitDataPoints);
  count->InsertNextValue(points);
  fd->AddArray(count);
  vtkNew<vtkIdTypeArray> left;
  left->SetName(vtkLRSplineArrayNames::FitOutliers);
  left->InsertNextValue(outliers);
  fd->AddArray(left);
}
}

// What ReusePreviousMesh keeps of an update: the fitted spline and what it
// was fitted under.
struct vtkLRSplineFitter::PreviousFit
{
  vtkLRSplineBuilder Builder;
  vtkMTimeType Settings = 0; // the filter's MTime
  double Time = 0.0;
  double Lo[3] = { 0, 0, 0 }, Hi[3] = { 0, 0, 0 };
  int Dim = 0;
};

//------------------------------------------------------------------------------
bool vtkLRSplineFitter::CanReusePreviousFit(
  bool hasTime, double time, const double lo[3], const double hi[3], int dim)
{
  const PreviousFit* previous = this->Previous.get();
  if (!this->ReusePreviousMesh || !previous || !hasTime || previous->Settings != this->GetMTime() ||
    previous->Dim != dim || previous->Time == time)
  {
    return false;
  }
  for (int d = 0; d < 3; ++d)
  {
    const double tolerance = 1e-9 * (hi[d] - lo[d]);
    if (std::abs(previous->Lo[d] - lo[d]) > tolerance ||
      std::abs(previous->Hi[d] - hi[d]) > tolerance)
    {
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkLRSplineFitter::RememberFit(
  const vtkLRSplineBuilder& builder, double time, const double lo[3], const double hi[3], int dim)
{
  this->Previous.reset(new PreviousFit);
  this->Previous->Builder = builder;
  this->Previous->Settings = this->GetMTime();
  this->Previous->Time = time;
  this->Previous->Dim = dim;
  std::copy(lo, lo + 3, this->Previous->Lo);
  std::copy(hi, hi + 3, this->Previous->Hi);
}

//------------------------------------------------------------------------------
vtkLRSplineFitter::vtkLRSplineFitter()
{
  this->SetNumberOfOutputPorts(3);
}

vtkLRSplineFitter::~vtkLRSplineFitter() = default;

//------------------------------------------------------------------------------
int vtkLRSplineFitter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataSet");
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkCompositeDataSet");
  return 1;
}

//------------------------------------------------------------------------------
int vtkLRSplineFitter::FillOutputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), port == 0 ? "vtkMultiBlockDataSet" : "vtkPolyData");
  return 1;
}

//------------------------------------------------------------------------------
int vtkLRSplineFitter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  this->ResetResults();
  vtkDataObject* input = vtkDataObject::GetData(inputVector[0], 0);
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkMultiBlockDataSet* output = vtkMultiBlockDataSet::GetData(outInfo);
  vtkPolyData* boundary = vtkPolyData::GetData(outputVector, 1);
  vtkPolyData* outliers = vtkPolyData::GetData(outputVector, 2);
  if (outliers)
  {
    outliers->Initialize();
  }

  if (!this->CheckSettings())
  {
    return 0;
  }
  const std::vector<vtkDataSet*> leaves = Leaves(input);

  // The data: positions, values, checked.
  PointData data;
  std::vector<double> positions;
  std::string fieldName;
  vtkIdType invalid = 0;
  if (!this->GatherData(leaves, positions, data.F, data.Dim, fieldName, invalid))
  {
    return 0;
  }
  this->NumberOfOutliers = invalid;
  int piece = 0, numPieces = 1;
  vtkSplineVizPieces::GetRequested(outInfo, piece, numPieces);
  if (this->RemoveOutliers &&
    !this->SeparateOutliers(
      positions, data.F, data.Dim, fieldName, piece == 0 ? outliers : nullptr))
  {
    return 0;
  }
  const vtkIdType np = static_cast<vtkIdType>(positions.size() / 3);
  this->NumberOfDataPoints = np;

  // The domain: the bounding box (with the margin); a volume is needed.
  double lo[3], hi[3], scale[3];
  if (!this->ComputeDomain(positions, lo, hi, scale))
  {
    return 0;
  }
  data.U.resize(3 * np);
  vtkSMPTools::For(0, np,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType p = begin; p < end; ++p)
      {
        for (int d = 0; d < 3; ++d)
        {
          const double top = this->InitialNumberOfElements[d];
          data.U[3 * p + d] =
            std::min(top, std::max(0.0, (positions[3 * p + d] - lo[d]) / scale[d]));
        }
      }
    });
  positions = std::vector<double>();

  // The tolerance (relative: of the range of the fitted values or lengths).
  double range[2];
  const double tolerance = this->ComputeAbsoluteTolerance(data.F, data.Dim, range);
  this->AbsoluteTolerance = tolerance;

  // The initial spline: the data mean everywhere.
  PointFit fit;
  fit.Data = &data;
  fit.Regularization = this->Regularization;
  fit.Smoothing = this->Smoothing;
  fit.Tolerance = tolerance;
  fit.RMSMode = this->ToleranceType == RMS_ERROR;
  std::string error;
  ConfigureFit(fit, this->InitialNumberOfElements, this->MaximumRefinementLevels);
  double time = 0.0;
  const bool hasTime = DataTime(input, &time);
  this->ReusedPreviousMesh = this->CanReusePreviousFit(hasTime, time, lo, hi, data.Dim);
  if (this->ReusedPreviousMesh)
  {
    fit.Core.Builder = this->Previous->Builder;
  }
  else if (!InitializeFit(fit, this->Degree, this->InitialNumberOfElements, &error))
  {
    vtkErrorMacro(<< "cannot make the initial spline: " << error);
    return 0;
  }
  this->Previous.reset();

  // Fit, evaluate, refine.
  LoopSettings settings;
  settings.Method = this->Method;
  settings.MaximumRefinementLevels = this->MaximumRefinementLevels;
  settings.MaximumNumberOfElements = this->MaximumNumberOfElements;
  settings.MinimumPointsPerElement = this->MinimumPointsPerElement;
  settings.MaximumRounds = this->GetMaximumRounds();
  settings.ProgressStart = this->RemoveOutliers ? OutlierProgress : 0.0;
  std::vector<double> residual;
  vtkLRSplineFitCore::Report report;
  std::string stopReason;
  bool met = false;
  int iteration = 0;
  if (!FitLoop(fit, settings, tolerance, this, residual, report.History, met, iteration, stopReason,
        &error))
  {
    vtkErrorMacro(<< error);
    return 0;
  }
  // The output's Bezier form, its errors at the points, the output.
  FitResult result;
  if (!FinishFit(fit, residual, this->FileName, result, &error))
  {
    vtkErrorMacro(<< error);
    output->Initialize();
    return 0;
  }
  report.Tolerance = tolerance;
  report.DataRange[0] = range[0];
  report.DataRange[1] = range[1];
  report.Iterations = iteration + 1;
  report.MaximumError = fit.MaxError;
  report.RMSError = std::sqrt(fit.SumSquares / np);
  report.ToleranceMet = met && (fit.RMSMode ? report.RMSError : fit.MaxError) <= tolerance;
  report.Levels = fit.Core.Levels();
  if (met && !report.ToleranceMet)
  {
    stopReason = "the Bezier form differs from the basis form by rounding";
  }
  const char* methods[] = { "LR-MBA", "least squares", "least squares + LR-MBA" };
  vtkSmartPointer<vtkUnstructuredGrid> grid =
    vtkLRSplineFitCore::BuildBlock(fit.Core.Builder.GetPatch(), result.Volume, 0, piece, numPieces,
      scale, lo, this->ResolveOutputFieldName(fieldName.c_str()),
      std::string("vtkLRSplineFitter (") + methods[this->Method] + ", local refinement)",
      fit.ElementError, report, &error);
  if (!grid)
  {
    vtkErrorMacro(<< "cannot build the output: " << error);
    output->Initialize();
    return 0;
  }
  if (this->ReusePreviousMesh && hasTime)
  {
    this->RememberFit(fit.Core.Builder, time, lo, hi, data.Dim);
  }
  this->MaximumError = report.MaximumError;
  this->RMSError = report.RMSError;
  this->ToleranceMet = report.ToleranceMet;
  this->NumberOfElements = fit.Core.Builder.GetPatch().GetNumberOfElements();
  this->NumberOfBasisFunctions = fit.Core.Builder.GetPatch().GetNumberOfBasisFunctions();
  this->NumberOfRefinementLevels = report.Levels;
  this->NumberOfIterations = report.Iterations;
  if (!report.ToleranceMet)
  {
    vtkWarningMacro(<< "the tolerance " << tolerance << " (" << (fit.RMSMode ? "RMS" : "maximum")
                    << ") is not met: maximum error " << report.MaximumError << ", RMS "
                    << report.RMSError << " with " << this->NumberOfElements << " elements after "
                    << report.Iterations << (report.Iterations == 1 ? " fit" : " fits")
                    << ", because " << stopReason);
  }
  this->WarnIfOscillating(result.Volume, fit.PointOffsets, range);
  AddFitFieldData(
    grid->GetFieldData(), this->Domain, this->ReusedPreviousMesh, np, this->NumberOfOutliers);
  output->SetNumberOfBlocks(1);
  output->SetBlock(0, grid);
  output->GetMetaData(0u)->Set(vtkCompositeDataSet::NAME(), "Patch 0");
  output->GetMetaData(0u)->Remove(vtkLRSplineField::TRIMMING_SURFACE());
  if (!this->BuildBoundary(leaves, boundary))
  {
    output->Initialize();
    return 0;
  }
  if (boundary && boundary->GetNumberOfPolys() > 0)
  {
    // The boundary travels with the spline too, so that a volume mapper or
    // the LR-Spline Volume representation trims by it without being told.
    vtkNew<vtkPolyData> trimming;
    trimming->ShallowCopy(boundary);
    output->GetMetaData(0u)->Set(vtkLRSplineField::TRIMMING_SURFACE(), trimming);
  }
  this->RecordFitTime(output);
  return 1;
}

//------------------------------------------------------------------------------
void vtkLRSplineFitter::ResetResults()
{
  this->Superclass::ResetResults();
  this->ReusedPreviousMesh = false;
  this->NumberOfDataPoints = this->NumberOfOutliers = 0;
  std::fill(this->Domain, this->Domain + 6, 0.0);
}

//------------------------------------------------------------------------------
bool vtkLRSplineFitter::ComputeDomain(
  const std::vector<double>& positions, double lo[3], double hi[3], double scale[3])
{
  const vtkIdType np = static_cast<vtkIdType>(positions.size() / 3);
  for (int d = 0; d < 3; ++d)
  {
    lo[d] = VTK_DOUBLE_MAX;
    hi[d] = -VTK_DOUBLE_MAX;
  }
  for (vtkIdType p = 0; p < np; ++p)
  {
    for (int d = 0; d < 3; ++d)
    {
      lo[d] = std::min(lo[d], positions[3 * p + d]);
      hi[d] = std::max(hi[d], positions[3 * p + d]);
    }
  }
  const double largest = std::max(hi[0] - lo[0], std::max(hi[1] - lo[1], hi[2] - lo[2]));
  for (int d = 0; d < 3; ++d)
  {
    if (!(hi[d] - lo[d] > 1e-9 * largest))
    {
      vtkErrorMacro(<< "the " << np << " data points have no volume: they all lie on a "
                    << (largest > 0 ? "plane or line" : "point") << " (extent " << hi[0] - lo[0]
                    << " x " << hi[1] - lo[1] << " x " << hi[2] - lo[2]
                    << "); an LR-spline volume needs 3D data");
      return false;
    }
    const double m = (hi[d] - lo[d]) * this->Margin;
    lo[d] -= m;
    hi[d] += m;
    scale[d] = (hi[d] - lo[d]) / this->InitialNumberOfElements[d];
    this->Domain[2 * d] = lo[d];
    this->Domain[2 * d + 1] = hi[d];
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkLRSplineFitter::CheckSettings()
{
  if (!this->Superclass::CheckSettings())
  {
    return false;
  }
  for (int d = 0; d < 3; ++d)
  {
    if (this->InitialNumberOfElements[d] > 1024)
    {
      vtkErrorMacro(<< "InitialNumberOfElements must be 1 to 1024 in every direction");
      return false;
    }
  }
  if (!std::isfinite(this->Smoothing))
  {
    vtkErrorMacro(<< "Smoothing must be finite");
    return false;
  }
  // The most elements the limits allow, and the memory they would take: the
  // Bezier coefficients and points of the output, the supports, the normal
  // matrix rows (about as many functions as elements).
  double elements = static_cast<double>(this->MaximumNumberOfElements);
  double finest = 1.0;
  for (int d = 0; d < 3; ++d)
  {
    finest *= this->InitialNumberOfElements[d] * std::ldexp(1.0, this->MaximumRefinementLevels);
  }
  elements = std::min(elements, finest);
  const double per = (this->Degree[0] + 1.0) * (this->Degree[1] + 1) * (this->Degree[2] + 1);
  const double overlap =
    (2 * this->Degree[0] + 1.0) * (2 * this->Degree[1] + 1) * (2 * this->Degree[2] + 1);
  const double bytes = per * (8.0 * 3 + 8.0 * 3 + 16.0) + overlap * 12.0 + 200.0;
  std::string error;
  if (!vtkSplineVizProgress::CheckOutputSize(elements, bytes,
        "the LR spline allowed by MaximumNumberOfElements and MaximumRefinementLevels", &error))
  {
    vtkErrorMacro(<< error << "; lower MaximumNumberOfElements");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkLRSplineFitter::GatherData(const std::vector<vtkDataSet*>& leaves,
  std::vector<double>& positions, std::vector<double>& values, int& dim, std::string& fieldName,
  vtkIdType& invalid)
{
  invalid = 0;
  vtkIdType total = 0;
  for (vtkDataSet* leaf : leaves)
  {
    total += leaf->GetNumberOfPoints();
  }
  if (total == 0)
  {
    vtkErrorMacro(<< "no data to fit: the input has no points");
    return false;
  }
  total = 0;
  int components = 0;
  struct Leaf
  {
    vtkSmartPointer<vtkDataSet> Points; // the leaf, or its cell centres
    vtkDataArray* Array;
  };
  std::vector<Leaf> sources;
  for (std::size_t b = 0; b < leaves.size(); ++b)
  {
    vtkDataSet* leaf = leaves[b];
    const std::string which =
      leaves.size() > 1 ? "block " + std::to_string(b) + ": " : std::string();
    int association = -1;
    vtkDataArray* array = this->GetInputArrayToProcess(0, leaf, association);
    if (!array)
    {
      vtkErrorMacro(<< which
                    << "no array to fit: choose a point or cell array with "
                       "SetInputArrayToProcess (the data set has none of that name, or no "
                       "active scalars)");
      return false;
    }
    if (components == 0)
    {
      components = array->GetNumberOfComponents();
      fieldName = array->GetName() ? array->GetName() : "";
    }
    else if (array->GetNumberOfComponents() != components)
    {
      vtkErrorMacro(<< which << "the array has " << array->GetNumberOfComponents()
                    << " components, another block's " << components);
      return false;
    }
    Leaf source{ leaf, array };
    if (association == vtkDataObject::FIELD_ASSOCIATION_CELLS)
    {
      // cell data at the cells' centres
      vtkNew<vtkCellCenters> centres;
      centres->SetInputData(leaf);
      centres->SetVertexCells(false);
      centres->SetCopyArrays(true);
      centres->Update();
      vtkPolyData* points = centres->GetOutput();
      source.Points = points;
      source.Array =
        array->GetName() ? points->GetPointData()->GetArray(array->GetName()) : nullptr;
      if (!source.Array || source.Array->GetNumberOfTuples() != points->GetNumberOfPoints())
      {
        vtkErrorMacro(<< which
                      << "cannot take the cell array at the cell centres (give it a name)");
        return false;
      }
    }
    else if (association != vtkDataObject::FIELD_ASSOCIATION_POINTS)
    {
      vtkErrorMacro(<< which << "the array to fit must be point or cell data");
      return false;
    }
    total += source.Points->GetNumberOfPoints();
    sources.push_back(source);
  }
  if (total == 0)
  {
    vtkErrorMacro(<< "no data to fit: the input has no points");
    return false;
  }
  dim = (components == 1 || this->VectorMode == MAGNITUDE) ? 1 : components;
  positions.resize(3 * total);
  values.resize(static_cast<std::size_t>(total) * dim);
  vtkIdType at = 0, bad = 0;
  std::vector<double> tuple(components);
  for (const Leaf& source : sources)
  {
    const vtkIdType n = source.Points->GetNumberOfPoints();
    for (vtkIdType i = 0; i < n; ++i)
    {
      source.Points->GetPoint(i, &positions[3 * at]);
      source.Array->GetTuple(i, tuple.data());
      bool finite = std::isfinite(positions[3 * at]) && std::isfinite(positions[3 * at + 1]) &&
        std::isfinite(positions[3 * at + 2]);
      double length = 0.0;
      for (int c = 0; c < components; ++c)
      {
        finite = finite && std::isfinite(tuple[c]);
        length += tuple[c] * tuple[c];
      }
      if (!finite)
      {
        ++bad;
        continue;
      }
      if (dim == 1 && components > 1)
      {
        values[at] = std::sqrt(length);
      }
      else
      {
        std::copy(tuple.begin(), tuple.end(), values.begin() + at * dim);
      }
      ++at;
    }
  }
  invalid = bad;
  if (bad > 0 && !this->RemoveOutliers)
  {
    vtkErrorMacro(<< bad << " of " << total << " data points have NaN or infinite "
                  << "values or coordinates; mask or replace them first (e.g. Threshold), "
                  << "or turn RemoveOutliers on to leave them out");
    return false;
  }
  if (at == 0)
  {
    vtkErrorMacro(<< "no data to fit: all " << total
                  << " data points have NaN or infinite values or coordinates");
    return false;
  }
  positions.resize(3 * at);
  values.resize(static_cast<std::size_t>(at) * dim);
  return true;
}

//------------------------------------------------------------------------------
void vtkLRSplineFitter::WarnIfOscillating(const vtkLRSplineBezierVolume& volume,
  const std::vector<vtkIdType>& pointOffsets, const double range[2])
{
  // On each element the spline lies in the hull of its Bezier coefficients;
  // coefficients far outside the data's range, on an element that holds
  // data, mean that the spline can swing that far between the data points.
  // (Elements without data are an extrapolation, hidden by trimming.)
  const double width = range[1] - range[0];
  const double bound = std::max(std::abs(range[0]), std::abs(range[1])) +
    OscillationFactor * (width > 0 ? width : std::max(std::abs(range[1]), 1e-300));
  const vtkIdType per =
    static_cast<vtkIdType>(volume.GetCoefficientsPerElement()) * volume.NumberOfComponents;
  double largest = 0.0;
  vtkIdType elements = 0;
  for (vtkIdType e = 0; e < volume.GetNumberOfElements(); ++e)
  {
    if (pointOffsets[e + 1] == pointOffsets[e])
    {
      continue;
    }
    const double* c = volume.GetElementCoefficients(e);
    double worst = 0.0;
    for (vtkIdType i = 0; i < per; ++i)
    {
      worst = std::max(worst, std::abs(c[i]));
    }
    largest = std::max(largest, worst);
    elements += worst > bound ? 1 : 0;
  }
  if (elements > 0)
  {
    vtkWarningMacro(<< "the fitted spline may swing far from the data between the data points: "
                    << "on " << elements << " elements that hold data its Bezier coefficients "
                    << "reach " << largest << " for data in [" << range[0] << ", " << range[1]
                    << "]; single wrong values (turn RemoveOutliers on), too little Smoothing ("
                    << this->Smoothing << ") or too few points per element (raise "
                    << "MinimumPointsPerElement) cause this");
  }
}

//------------------------------------------------------------------------------
double vtkLRSplineFitter::ComputeAbsoluteTolerance(
  const std::vector<double>& values, int dim, double range[2])
{
  DataRange(values, dim, range);
  return this->Superclass::ComputeAbsoluteTolerance(range);
}

//------------------------------------------------------------------------------
bool vtkLRSplineFitter::SeparateOutliers(std::vector<double>& positions,
  std::vector<double>& values, int dim, const std::string& fieldName, vtkPolyData* outliers)
{
  vtkSplineVizLocalOutliers finder;
  finder.Threshold = this->OutlierThreshold;
  std::vector<double> outPositions, outValues, outDeviations;
  for (int round = 0; round < OutlierRounds; ++round)
  {
    double range[2];
    finder.Tolerance = this->ComputeAbsoluteTolerance(values, dim, range);
    std::vector<double> deviation;
    std::vector<unsigned char> flag;
    const double from = OutlierProgress * round / OutlierRounds;
    if (!finder.Find(positions, values, dim, deviation, flag, this, from,
          from + OutlierProgress / OutlierRounds))
    {
      if (this->CheckAbort())
      {
        return false;
      }
      vtkWarningMacro(<< "RemoveOutliers: only " << positions.size() / 3
                      << " data points, too few to compare each with " << finder.NumberOfNeighbors
                      << " neighbours; none is left out");
      break;
    }
    // Move the flagged points out, keep the others in order.
    std::size_t kept = 0;
    const std::size_t np = flag.size();
    for (std::size_t p = 0; p < np; ++p)
    {
      if (flag[p])
      {
        outPositions.insert(outPositions.end(), &positions[3 * p], &positions[3 * p] + 3);
        outValues.insert(outValues.end(), &values[p * dim], &values[p * dim] + dim);
        outDeviations.push_back(deviation[p]);
        continue;
      }
      std::copy(&positions[3 * p], &positions[3 * p] + 3, &positions[3 * kept]);
      std::copy(&values[p * dim], &values[p * dim] + dim, &values[kept * dim]);
      ++kept;
    }
    if (kept == np)
    {
      break;
    }
    positions.resize(3 * kept);
    values.resize(kept * dim);
    this->NumberOfOutliers += static_cast<vtkIdType>(np - kept);
  }
  if (!outliers)
  {
    return true;
  }
  const vtkIdType n = static_cast<vtkIdType>(outDeviations.size());
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(n);
  std::copy(
    outPositions.begin(), outPositions.end(), static_cast<double*>(points->GetVoidPointer(0)));
  vtkNew<vtkCellArray> vertices;
  for (vtkIdType i = 0; i < n; ++i)
  {
    vertices->InsertNextCell(1, &i);
  }
  vtkNew<vtkDoubleArray> value;
  value->SetName(fieldName.c_str());
  value->SetNumberOfComponents(dim);
  value->SetNumberOfTuples(n);
  std::copy(outValues.begin(), outValues.end(), value->GetPointer(0));
  vtkNew<vtkDoubleArray> deviation;
  deviation->SetName(vtkLRSplineArrayNames::FitOutlierDeviation);
  deviation->SetNumberOfTuples(n);
  std::copy(outDeviations.begin(), outDeviations.end(), deviation->GetPointer(0));
  outliers->SetPoints(points);
  outliers->SetVerts(vertices);
  outliers->GetPointData()->SetScalars(value);
  outliers->GetPointData()->AddArray(deviation);
  return true;
}

//------------------------------------------------------------------------------
bool vtkLRSplineFitter::BuildBoundary(const std::vector<vtkDataSet*>& leaves, vtkPolyData* boundary)
{
  if (!boundary)
  {
    return true;
  }
  boundary->Initialize();
  if (!this->ExtractBoundary)
  {
    return true;
  }
  vtkNew<vtkAppendPolyData> append;
  int inputs = 0;
  vtkIdType open = 0;
  for (vtkDataSet* leaf : leaves)
  {
    if (leaf->GetNumberOfCells() == 0)
    {
      continue;
    }
    vtkSmartPointer<vtkPolyData> surface = BoundaryTriangles(leaf);
    vtkIdType edges = OpenEdges(surface);
    if (edges > 0 && leaf->GetMaxCellSize() > 4 && !vtkPolyData::SafeDownCast(leaf))
    {
      // Non-conforming faces (a quad against two triangles, as a clip leaves
      // them) show up as surface: cut the cells into tetrahedra first, whose
      // ordered triangulation makes shared faces match.
      vtkNew<vtkDataSetTriangleFilter> tetrahedra;
      tetrahedra->SetInputData(leaf);
      tetrahedra->Update();
      surface = BoundaryTriangles(tetrahedra->GetOutput());
      edges = OpenEdges(surface);
    }
    if (!vtkPolyData::SafeDownCast(leaf))
    {
      open += edges; // (a surface data set is open by nature)
    }
    append->AddInputData(surface);
    ++inputs;
  }
  if (open > 0)
  {
    vtkWarningMacro(<< "the data's boundary surface is not closed (" << open
                    << " open or non-manifold edges): trimming by it may let parts of the "
                       "volume outside the data show");
  }
  if (inputs > 0)
  {
    // Consistent, outward winding: the volume mapper's trimming tells the
    // surface's front faces from its back faces by it.
    vtkNew<vtkPolyDataNormals> oriented;
    oriented->SetInputConnection(append->GetOutputPort());
    oriented->SplittingOff();
    oriented->ConsistencyOn();
    oriented->AutoOrientNormalsOn();
    oriented->ComputeCellNormalsOff();
    oriented->ComputePointNormalsOn();
    oriented->Update();
    boundary->ShallowCopy(oriented->GetOutput());
    boundary->GetPointData()->Initialize();
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkLRSplineFitter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Method: "
     << (this->Method == MBA ? "MBA" : (this->Method == LEAST_SQUARES ? "LeastSquares" : "Hybrid"))
     << "\n";
  os << indent << "ToleranceType: " << (this->ToleranceType == RMS_ERROR ? "RMS" : "Maximum")
     << "\n";
  os << indent << "VectorMode: " << (this->VectorMode == COMPONENTS ? "Components" : "Magnitude")
     << "\n";
  os << indent << "Margin: " << this->Margin << "\n";
  os << indent << "MinimumPointsPerElement: " << this->MinimumPointsPerElement << "\n";
  os << indent << "Smoothing: " << this->Smoothing << "\n";
  os << indent << "ExtractBoundary: " << this->ExtractBoundary << "\n";
  os << indent << "ReusePreviousMesh: " << this->ReusePreviousMesh << "\n";
  os << indent << "ReusedPreviousMesh: " << this->ReusedPreviousMesh << "\n";
  os << indent << "RemoveOutliers: " << this->RemoveOutliers << "\n";
  os << indent << "OutlierThreshold: " << this->OutlierThreshold << "\n";
  os << indent << "NumberOfDataPoints: " << this->NumberOfDataPoints << "\n";
  os << indent << "NumberOfOutliers: " << this->NumberOfOutliers << "\n";
}
