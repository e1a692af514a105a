// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLRSplineImageFitter.h"

#include "vtkLRSplineBezierVolume.h"
#include "vtkLRSplineFitCore.h"
#include "vtkLRSplinePatch.h"
#include "vtkSplineVizPieces.h"

#include "vtkArrayDispatch.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkDataArrayRange.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMatrix3x3.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkObjectFactory.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <atomic>
#include <cmath>
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
constexpr double SolverAccuracy = 1e-4;
constexpr int SolverDelay = 10;
constexpr int SolverMaximumIterations = 2000;

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

  vtkLRSplineFitCore Core;
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
      this->Core.InitialSide[d] = length / m;
      // Voxel-aligned knots: at voxel faces (half-integers) for even degrees,
      // at voxel centres (integers) for odd ones, where the sampling of the
      // B-splines at the voxels is best conditioned (at the finest level one
      // element per voxel, which can interpolate).
      this->Core.Options.GridStep[d] = align ? 1.0 : 0.0;
      this->Core.Options.GridOffset[d] = (this->Degree[d] % 2 == 0) ? 0.5 : 0.0;
      breaks[d].push_back(0.0);
      for (int k = 1; k < m; ++k)
      {
        double z = length * k / m;
        if (align)
        {
          const double o = this->Core.Options.GridOffset[d];
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
      this->Core.Options.MinimumPart[d] = std::max(minimumSize * (1.0 - 1e-9),
        this->Core.InitialSide[d] * std::pow(2.0, -(maximumLevels + 0.5)) * (1.0 + 1e-9));
    }
    this->Core.Options.Ratio = 0.5;
    if (!this->Core.Builder.InitializeTensorProduct(this->Degree, breaks, 1, error))
    {
      return false;
    }
    // The starting guess: the image sampled at the Greville points.
    this->Core.Builder.SetCoefficientsFromGreville(
      [this](const double g[3], double* c) { c[0] = this->Trilinear(g); });
    return true;
  }

  // Least squares on the current mesh (coefficients in the builder).
  bool Solve()
  {
    const vtkLRSplinePatch& patch = this->Core.Builder.GetPatch();
    const vtkIdType nf = patch.GetNumberOfBasisFunctions();
    this->Core.ComputeSupports();
    this->BuildTables(patch);
    this->Core.BuildPattern(false);
    std::vector<double> rhs(nf), diagonal(nf), weight(nf);
    const std::vector<double>& gamma = patch.Gamma;
    const std::vector<double>& values = *this->Values;
    const int nx = this->N[0], ny = this->N[1];
    const std::vector<vtkIdType>& rowOffsets = this->Core.RowOffsets;
    const std::vector<int>& columns = this->Core.Columns;
    std::vector<double>& entries = this->Core.Entries;
    vtkSMPTools::For(0, nf,
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType f = begin; f < end; ++f)
        {
          const int* tf = &this->FunctionTable[3 * f];
          for (vtkIdType k = rowOffsets[f]; k < rowOffsets[f + 1]; ++k)
          {
            const int g = columns[k];
            const int* tg = &this->FunctionTable[3 * g];
            double v = gamma[f] * gamma[g];
            for (int d = 0; d < 3 && v != 0.0; ++d)
            {
              v *= this->Gram(d, tf[d], tg[d]);
            }
            entries[k] = v;
            if (g == f)
            {
              diagonal[f] = v;
            }
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
    std::vector<double> delta, x;
    vtkLRSplineFitCore::Regularize(weight, this->Regularization, LittleData, diagonal, delta);
    this->SolverIterations =
      this->Core.Solve(rhs, prior, delta, diagonal, SolverAccuracy * this->Tolerance, x);
    this->Core.Builder.SetCoefficients(x);
    this->Core.Columns.clear();
    this->Core.Entries.clear();
    return true;
  }

  // The error at every voxel, per element, from the basis functions (the
  // tables of the last Solve()): every round.
  void EvaluateFromBasis()
  {
    const vtkLRSplinePatch& patch = this->Core.Builder.GetPatch();
    const std::vector<double>& gamma = patch.Gamma;
    const std::vector<double>& coefficients = patch.Coefficients;
    this->ErrorPass(patch.ElementBoxes.data(), patch.GetNumberOfElements(),
      [&](vtkIdType e, const int lo[3], const int hi[3], double* v)
      {
        const int nu = hi[0] - lo[0] + 1, nv = hi[1] - lo[1] + 1, nw = hi[2] - lo[2] + 1;
        std::fill(v, v + static_cast<std::size_t>(nu) * nv * nw, 0.0);
        for (vtkIdType s = this->Core.SupportOffsets[e]; s < this->Core.SupportOffsets[e + 1]; ++s)
        {
          const vtkIdType f = this->Core.SupportIds[s];
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
};
}

//------------------------------------------------------------------------------
// An image to fit: checked before anything is fitted.
struct vtkLRSplineImageFitter::Job
{
  vtkImageData* Image = nullptr;
  vtkDataArray* Array = nullptr;
  const std::vector<double>* Values = nullptr; ///< the voxel values, read after every check
  std::string Which;                           ///< "block b: " for composite input
  int N[3] = { 0, 0, 0 };
  double Offset[3] = { 0.0, 0.0, 0.0 };
  double Scale[3] = { 1.0, 1.0, 1.0 };
};

// One image's fit: the refined spline, its Bezier form and how it ended.
struct vtkLRSplineImageFitter::BlockFit
{
  ImageFit Fit;
  vtkLRSplineBezierVolume Volume;
  std::vector<double> History; ///< per fit: elements, functions, maximum, RMS, solver iterations
  std::string StopReason;
  double RMS = 0.0;
  int Iterations = 0;
  bool Met = false;
};

//------------------------------------------------------------------------------
vtkLRSplineImageFitter::vtkLRSplineImageFitter() = default;

vtkLRSplineImageFitter::~vtkLRSplineImageFitter() = default;

//------------------------------------------------------------------------------
int vtkLRSplineImageFitter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkCompositeDataSet");
  return 1;
}

//------------------------------------------------------------------------------
bool vtkLRSplineImageFitter::CheckSettings()
{
  if (!this->Superclass::CheckSettings())
  {
    return false;
  }
  if (!std::isfinite(this->MinimumElementSize))
  {
    vtkErrorMacro(<< "MinimumElementSize must be finite");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkLRSplineImageFitter::CollectImages(vtkDataObject* input, std::vector<vtkImageData*>& images)
{
  images.clear();
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
        return false;
      }
      images.push_back(leaf);
    }
  }
  if (images.empty())
  {
    vtkErrorMacro(<< "no input image: connect a vtkImageData (e.g. vtkNIFTIImageReader)");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkLRSplineImageFitter::CheckImage(vtkImageData* image, const std::string& which, int n[3],
  double offset[3], double scale[3], vtkDataArray*& array)
{
  int extent[6];
  image->GetExtent(extent);
  vtkIdType voxels = 1;
  for (int d = 0; d < 3; ++d)
  {
    n[d] = extent[2 * d + 1] - extent[2 * d] + 1;
    if (n[d] < 2)
    {
      vtkErrorMacro(<< which << "the image must have at least 2 voxels in every direction (it has "
                    << std::max(0, extent[1] - extent[0] + 1) << " x "
                    << std::max(0, extent[3] - extent[2] + 1) << " x "
                    << std::max(0, extent[5] - extent[4] + 1)
                    << "): an LR-spline volume needs a 3D image");
      return false;
    }
    voxels *= n[d];
    if (voxels > MaximumVoxels)
    {
      vtkErrorMacro(<< which << "the image is too large to fit (" << n[0] << " x "
                    << extent[3] - extent[2] + 1 << " x " << extent[5] - extent[4] + 1
                    << " voxels; at most " << MaximumVoxels
                    << "): crop or shrink it first (vtkExtractVOI, vtkImageShrink3D)");
      return false;
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
      return false;
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
      return false;
    }
    scale[d] = spacing[d];
    offset[d] = origin[d] + spacing[d] * extent[2 * d];
  }
  int association = -1;
  array = this->GetInputArrayToProcess(0, image, association);
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
    return false;
  }
  if (association != vtkDataObject::FIELD_ASSOCIATION_POINTS)
  {
    vtkErrorMacro(<< which << "the array \"" << (array->GetName() ? array->GetName() : "")
                  << "\" is not point data; the fitter fits voxel (point) values");
    return false;
  }
  if (array->GetNumberOfComponents() != 1)
  {
    vtkErrorMacro(<< which << "the array \"" << (array->GetName() ? array->GetName() : "")
                  << "\" has " << array->GetNumberOfComponents()
                  << " components; the fitter needs a scalar (extract a component or the "
                     "magnitude first)");
    return false;
  }
  if (array->GetNumberOfTuples() != voxels)
  {
    vtkErrorMacro(<< which << "the array has " << array->GetNumberOfTuples() << " values for "
                  << voxels << " voxels");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
std::string vtkLRSplineImageFitter::GetStopReason(int outcome) const
{
  return vtkLRSplineFitCore::StopReason(static_cast<vtkLRSplineFitCore::Outcome>(outcome),
    this->MaximumNumberOfElements,
    "MinimumElementSize (" + std::to_string(this->MinimumElementSize) +
      " voxels) or MaximumRefinementLevels (" + std::to_string(this->MaximumRefinementLevels) +
      ")");
}

//------------------------------------------------------------------------------
bool vtkLRSplineImageFitter::ReadValues(const std::vector<vtkDataArray*>& arrays,
  std::vector<std::vector<double>>& values, double range[2])
{
  values.assign(arrays.size(), std::vector<double>());
  range[0] = VTK_DOUBLE_MAX;
  range[1] = -VTK_DOUBLE_MAX;
  for (std::size_t b = 0; b < arrays.size(); ++b)
  {
    values[b].resize(static_cast<std::size_t>(arrays[b]->GetNumberOfTuples()));
    std::atomic<bool> finite(true);
    CopyWorker worker;
    if (!vtkArrayDispatch::Dispatch::Execute(arrays[b], worker, values[b], finite))
    {
      worker(arrays[b], values[b], finite);
    }
    if (!finite)
    {
      vtkErrorMacro(<< (arrays.size() > 1 ? "block " + std::to_string(b) + ": " : std::string())
                    << "the array \"" << (arrays[b]->GetName() ? arrays[b]->GetName() : "")
                    << "\" has NaN or infinite values; mask or replace them first");
      return false;
    }
    for (double v : values[b])
    {
      range[0] = std::min(range[0], v);
      range[1] = std::max(range[1], v);
    }
  }
  return true;
}

//------------------------------------------------------------------------------
int vtkLRSplineImageFitter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  this->ResetResults();
  vtkDataObject* input = vtkDataObject::GetData(inputVector[0], 0);
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkMultiBlockDataSet* output = vtkMultiBlockDataSet::GetData(outInfo);

  // Everything is checked before anything large is allocated.
  std::vector<vtkImageData*> images;
  std::vector<Job> jobs;
  if (!this->CheckSettings() || !this->CollectImages(input, images) ||
    !this->PrepareJobs(images, jobs))
  {
    return 0;
  }
  std::vector<vtkDataArray*> arrays;
  for (const Job& job : jobs)
  {
    arrays.push_back(job.Array);
  }
  std::vector<std::vector<double>> values;
  double range[2];
  if (!this->ReadValues(arrays, values, range))
  {
    return 0;
  }
  const double tolerance = this->ComputeAbsoluteTolerance(range);
  this->AbsoluteTolerance = tolerance;

  int piece = 0, numPieces = 1;
  vtkSplineVizPieces::GetRequested(outInfo, piece, numPieces);
  double sumSquares = 0.0, voxelCount = 0.0;
  std::vector<vtkLRSplinePatch> written;
  bool allMet = true;
  output->SetNumberOfBlocks(static_cast<unsigned int>(jobs.size()));
  for (std::size_t b = 0; b < jobs.size(); ++b)
  {
    jobs[b].Values = &values[b];
    BlockFit fit;
    if (!this->FitBlock(jobs, b, tolerance, fit))
    {
      output->Initialize();
      return 0;
    }
    this->ReportBlock(jobs, b, tolerance, fit);
    allMet = allMet && fit.Met;
    sumSquares += fit.Fit.Stats.SumSquares;
    voxelCount += static_cast<double>(values[b].size());
    vtkSmartPointer<vtkUnstructuredGrid> grid =
      this->BuildOutputBlock(jobs, b, tolerance, range, piece, numPieces, fit);
    if (!grid)
    {
      output->Initialize();
      return 0;
    }
    output->SetBlock(static_cast<unsigned int>(b), grid);
    output->GetMetaData(static_cast<unsigned int>(b))
      ->Set(vtkCompositeDataSet::NAME(), ("Patch " + std::to_string(b)).c_str());
    if (this->FileName && *this->FileName && piece == 0)
    {
      written.push_back(fit.Fit.Core.Builder.GetPatch());
    }
  }
  this->RMSError = voxelCount > 0 ? std::sqrt(sumSquares / voxelCount) : 0.0;
  this->ToleranceMet = allMet;

  std::string error;
  if (!written.empty() && !vtkLRSplineFitCore::WritePatches(this->FileName, written, &error))
  {
    vtkErrorMacro(<< error);
    output->Initialize();
    return 0;
  }
  this->RecordFitTime(output);
  return 1;
}

//------------------------------------------------------------------------------
bool vtkLRSplineImageFitter::PrepareJobs(
  const std::vector<vtkImageData*>& images, std::vector<Job>& jobs)
{
  for (std::size_t b = 0; b < images.size(); ++b)
  {
    Job job;
    job.Image = images[b];
    job.Which = images.size() > 1 ? "block " + std::to_string(b) + ": " : std::string();
    if (!this->CheckImage(job.Image, job.Which, job.N, job.Offset, job.Scale, job.Array))
    {
      return false;
    }
    jobs.push_back(job);
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkLRSplineImageFitter::FitBlock(
  const std::vector<Job>& jobs, std::size_t b, double tolerance, BlockFit& result)
{
  const Job& job = jobs[b];
  ImageFit& fit = result.Fit;
  fit.Values = job.Values;
  std::copy(job.N, job.N + 3, fit.N);
  std::copy(this->Degree, this->Degree + 3, fit.Degree);
  fit.Regularization = this->Regularization;
  fit.Tolerance = tolerance;
  std::string error;
  if (!fit.Initialize(this->InitialNumberOfElements, this->AlignKnotsToVoxels != 0,
        this->MinimumElementSize, this->MaximumRefinementLevels, &error))
  {
    vtkErrorMacro(<< job.Which << "cannot make the initial spline: " << error);
    return false;
  }
  // Least squares, then refinement of the elements out of tolerance, until
  // the tolerance is met or the refinement stops.
  const int rounds = this->GetMaximumRounds();
  const double voxels = static_cast<double>(job.Values->size());
  for (result.Iterations = 1;; ++result.Iterations)
  {
    fit.Solve();
    fit.EvaluateFromBasis();
    const vtkLRSplinePatch& patch = fit.Core.Builder.GetPatch();
    result.History.insert(result.History.end(),
      { static_cast<double>(patch.GetNumberOfElements()),
        static_cast<double>(patch.GetNumberOfBasisFunctions()), fit.Stats.MaxError,
        std::sqrt(fit.Stats.SumSquares / voxels), static_cast<double>(fit.SolverIterations) });
    this->UpdateProgress((b + std::min(1.0, result.Iterations / (rounds + 1.0))) / jobs.size());
    if (fit.Stats.MaxError <= tolerance)
    {
      result.Met = true;
      break;
    }
    if (this->CheckAbort())
    {
      result.StopReason = "the update was aborted";
      break;
    }
    if (result.Iterations >= rounds)
    {
      result.StopReason =
        "the limit of " + std::to_string(rounds) + " refinement rounds was reached";
      break;
    }
    const vtkLRSplineFitCore::Outcome outcome =
      fit.Core.Refine(fit.ElementError, tolerance, this->MaximumNumberOfElements, &error);
    if (outcome == vtkLRSplineFitCore::FAILED)
    {
      vtkErrorMacro(<< job.Which << "the refinement failed: " << error);
      return false;
    }
    if (outcome != vtkLRSplineFitCore::REFINED)
    {
      result.StopReason = this->GetStopReason(outcome);
      break;
    }
  }
  // The output's Bezier form, and the errors it has at the voxels.
  if (!fit.Core.Builder.GetPatch().ExtractBezier(result.Volume, &error))
  {
    vtkErrorMacro(<< job.Which << "the fitted spline is invalid: " << error);
    return false;
  }
  fit.EvaluateFromBezier(result.Volume);
  if (result.Met && !(fit.Stats.MaxError <= tolerance))
  {
    result.Met = false;
    result.StopReason = "the Bezier form differs from the basis form by rounding";
  }
  result.RMS = std::sqrt(fit.Stats.SumSquares / voxels);
  return true;
}

//------------------------------------------------------------------------------
void vtkLRSplineImageFitter::ReportBlock(
  const std::vector<Job>& jobs, std::size_t b, double tolerance, BlockFit& result)
{
  const vtkLRSplinePatch& patch = result.Fit.Core.Builder.GetPatch();
  if (!result.Met)
  {
    vtkWarningMacro(<< jobs[b].Which << "the tolerance " << tolerance
                    << " is not met everywhere: maximum error " << result.Fit.Stats.MaxError
                    << " (RMS " << result.RMS << ") with " << patch.GetNumberOfElements()
                    << " elements after " << result.Iterations
                    << (result.Iterations == 1 ? " fit" : " fits") << ", because "
                    << result.StopReason);
  }
  this->MaximumError = std::max(this->MaximumError, result.Fit.Stats.MaxError);
  this->NumberOfElements += patch.GetNumberOfElements();
  this->NumberOfBasisFunctions += patch.GetNumberOfBasisFunctions();
  this->NumberOfRefinementLevels =
    std::max(this->NumberOfRefinementLevels, result.Fit.Core.Levels());
  this->NumberOfIterations = std::max(this->NumberOfIterations, result.Iterations);
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkUnstructuredGrid> vtkLRSplineImageFitter::BuildOutputBlock(
  const std::vector<Job>& jobs, std::size_t b, double tolerance, const double range[2], int piece,
  int numPieces, BlockFit& result)
{
  const Job& job = jobs[b];
  vtkLRSplineFitCore::Report report;
  report.MaximumError = result.Fit.Stats.MaxError;
  report.RMSError = result.RMS;
  report.Tolerance = tolerance;
  report.ToleranceMet = result.Met;
  report.Iterations = result.Iterations;
  report.Levels = result.Fit.Core.Levels();
  report.DataRange[0] = range[0];
  report.DataRange[1] = range[1];
  report.History = std::move(result.History);
  const std::string fieldName = this->ResolveOutputFieldName(job.Array->GetName());
  std::string error;
  // This piece's elements, in the reader's format.
  vtkSmartPointer<vtkUnstructuredGrid> grid = vtkLRSplineFitCore::BuildBlock(
    result.Fit.Core.Builder.GetPatch(), result.Volume, static_cast<int>(b), piece, numPieces,
    job.Scale, job.Offset, fieldName, "vtkLRSplineImageFitter (least squares, local refinement)",
    result.Fit.ElementError, report, &error);
  if (!grid)
  {
    vtkErrorMacro(<< job.Which << "cannot build the output: " << error);
  }
  return grid;
}

//------------------------------------------------------------------------------
void vtkLRSplineImageFitter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "MinimumElementSize: " << this->MinimumElementSize << "\n";
  os << indent << "AlignKnotsToVoxels: " << this->AlignKnotsToVoxels << "\n";
}
