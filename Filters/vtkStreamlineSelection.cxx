// SPDX-License-Identifier: BSD-3-Clause
#include "vtkStreamlineSelection.h"
#include "vtkSplineVizProgress.h"

#include "vtkAbstractTransform.h"
#include "vtkBox.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkImageData.h"
#include "vtkImplicitFunction.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkLinearTransform.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkSphere.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

vtkStandardNewMacro(vtkStreamlineSelection);

namespace
{
const char* const RoleNames[] = { "INCLUDE", "EXCLUDE", "ENDPOINT" };

// A region as the user gave it.
struct Region
{
  enum Kinds
  {
    SPHERE,
    BOX,
    FUNCTION,
    LABELS
  };
  int Kind = SPHERE;
  int Role = vtkStreamlineSelection::INCLUDE;
  double Center[3] = { 0, 0, 0 };
  double Radius = 1;
  double Bounds[6] = { 0, 1, 0, 1, 0, 1 };
  vtkSmartPointer<vtkMatrix4x4> BoxToWorld; // null: axis-aligned
  vtkSmartPointer<vtkImplicitFunction> Function;
  vtkSmartPointer<vtkImageData> Image;
  std::string ArrayName;
  std::vector<double> Labels;
};

// An affine map y = A x + t (3x4, row-major).
struct Affine
{
  double M[12] = { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0 };
  void Apply(const double x[3], double y[3]) const
  {
    for (int i = 0; i < 3; ++i)
    {
      y[i] = this->M[4 * i] * x[0] + this->M[4 * i + 1] * x[1] + this->M[4 * i + 2] * x[2] +
        this->M[4 * i + 3];
    }
  }
  void Set(vtkMatrix4x4* m)
  {
    for (int i = 0; i < 3; ++i)
    {
      for (int j = 0; j < 4; ++j)
      {
        this->M[4 * i + j] = m->GetElement(i, j);
      }
    }
  }
};

// Segment a + t (b - a), t in [0, 1], clipped to the box [lo, hi] (closed):
// the parameter interval inside, or false.
// Cohen-Sutherland outcode: bit 2i below lo[i], bit 2i+1 above hi[i] (0: inside).
int OutCode(const double p[3], const double lo[3], const double hi[3])
{
  int code = 0;
  for (int i = 0; i < 3; ++i)
  {
    code |= (p[i] < lo[i] ? 1 : 0) << (2 * i);
    code |= (p[i] > hi[i] ? 1 : 0) << (2 * i + 1);
  }
  return code;
}

bool ClipToBox(const double a[3], const double b[3], const double lo[3], const double hi[3],
  double& t0, double& t1)
{
  t0 = 0.0;
  t1 = 1.0;
  if (OutCode(a, lo, hi) & OutCode(b, lo, hi))
  {
    return false; // both ends beyond the same face
  }
  for (int i = 0; i < 3; ++i)
  {
    const double d = b[i] - a[i];
    if (d == 0.0)
    {
      if (!(a[i] >= lo[i] && a[i] <= hi[i]))
      {
        return false;
      }
      continue;
    }
    double tl = (lo[i] - a[i]) / d;
    double th = (hi[i] - a[i]) / d;
    if (tl > th)
    {
      std::swap(tl, th);
    }
    t0 = std::max(t0, tl);
    t1 = std::min(t1, th);
    if (!(t0 <= t1)) // also false for NaN
    {
      return false;
    }
  }
  return true;
}

// A region prepared for one run: its shape in its local frame (world, the
// box's frame, the function's frame or the image's index space), the map to
// that frame and its world bounds.
struct Prepared
{
  enum Shapes
  {
    SPHERE,
    BOX,
    SAMPLED,
    VOXELS
  };
  int Shape = SPHERE;
  int Role = vtkStreamlineSelection::INCLUDE;
  bool Mapped = false; // world -> local through Map
  Affine Map;
  double Center[3] = { 0, 0, 0 }; // SPHERE
  double R2 = 0;
  double Lo[3] = { 0, 0, 0 }; // BOX; VOXELS: the index box of the labelled voxels +- 0.5
  double Hi[3] = { 0, 0, 0 };
  vtkImplicitFunction* Function = nullptr; // SAMPLED
  double Step = 0;
  std::vector<unsigned char> Mask; // VOXELS: one byte per voxel of the label extent
  int Min[3] = { 0, 0, 0 };        // VOXELS: index range of the mask
  int Max[3] = { -1, -1, -1 };
  bool Bounded = true;
  double WorldBounds[6] = { 0, 0, 0, 0, 0, 0 };

  void ToLocal(const double w[3], double l[3]) const
  {
    if (this->Mapped)
    {
      this->Map.Apply(w, l);
    }
    else
    {
      l[0] = w[0];
      l[1] = w[1];
      l[2] = w[2];
    }
  }

  bool Voxel(int i, int j, int k) const
  {
    const vtkIdType nx = this->Max[0] - this->Min[0] + 1;
    const vtkIdType ny = this->Max[1] - this->Min[1] + 1;
    return this->Mask[(i - this->Min[0]) + nx * ((j - this->Min[1]) + ny * (k - this->Min[2]))] !=
      0;
  }

  // Is the local point inside?
  bool Contains(const double p[3]) const
  {
    switch (this->Shape)
    {
      case SPHERE:
      {
        const double d[3] = { p[0] - this->Center[0], p[1] - this->Center[1],
          p[2] - this->Center[2] };
        return d[0] * d[0] + d[1] * d[1] + d[2] * d[2] <= this->R2;
      }
      case BOX:
        return p[0] >= this->Lo[0] && p[0] <= this->Hi[0] && p[1] >= this->Lo[1] &&
          p[1] <= this->Hi[1] && p[2] >= this->Lo[2] && p[2] <= this->Hi[2];
      case SAMPLED:
      {
        double x[3] = { p[0], p[1], p[2] };
        return this->Function->FunctionValue(x) <= 0.0;
      }
      default:
      {
        int v[3];
        for (int i = 0; i < 3; ++i)
        {
          const double f = std::floor(p[i] + 0.5);
          if (!(f >= this->Min[i] && f <= this->Max[i]))
          {
            return false;
          }
          v[i] = static_cast<int>(f);
        }
        return this->Voxel(v[0], v[1], v[2]);
      }
    }
  }

  // Does the local segment [a, b] touch the region?
  bool SegmentHits(const double a[3], const double b[3]) const
  {
    switch (this->Shape)
    {
      case SPHERE:
      {
        const double d[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
        const double c[3] = { this->Center[0] - a[0], this->Center[1] - a[1],
          this->Center[2] - a[2] };
        const double dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
        double t = dd > 0 ? (c[0] * d[0] + c[1] * d[1] + c[2] * d[2]) / dd : 0.0;
        t = std::min(1.0, std::max(0.0, t));
        const double e[3] = { c[0] - t * d[0], c[1] - t * d[1], c[2] - t * d[2] };
        return e[0] * e[0] + e[1] * e[1] + e[2] * e[2] <= this->R2;
      }
      case BOX:
      {
        const int ca = OutCode(a, this->Lo, this->Hi);
        const int cb = OutCode(b, this->Lo, this->Hi);
        if (ca & cb)
        {
          return false; // both ends beyond the same face
        }
        if ((ca == 0 && a[0] == a[0] && a[1] == a[1] && a[2] == a[2]) ||
          (cb == 0 && b[0] == b[0] && b[1] == b[1] && b[2] == b[2]))
        {
          return true; // an end inside (a NaN end has outcode 0 but is not inside)
        }
        double t0, t1;
        return ClipToBox(a, b, this->Lo, this->Hi, t0, t1);
      }
      case SAMPLED:
        return this->SampledHits(a, b);
      default:
        return this->WalkHits(a, b);
    }
  }

  bool SampledHits(const double a[3], const double b[3]) const
  {
    const double d[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
    const double length = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    double pieces = this->Step > 0 ? std::ceil(length / this->Step) : 1.0;
    pieces = std::max(1.0, std::min(pieces, 1e6)); // NaN length: 1
    const int n = static_cast<int>(pieces);
    for (int k = 0; k <= n; ++k)
    {
      const double t = static_cast<double>(k) / n;
      double x[3] = { a[0] + t * d[0], a[1] + t * d[1], a[2] + t * d[2] };
      if (this->Function->FunctionValue(x) <= 0.0)
      {
        return true;
      }
    }
    return false;
  }

  // Amanatides-Woo voxel walk in index space over the voxels of the mask box.
  bool WalkHits(const double a[3], const double b[3]) const
  {
    double t0, t1;
    if (!ClipToBox(a, b, this->Lo, this->Hi, t0, t1))
    {
      return false;
    }
    const double d[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
    int v[3], step[3];
    double tMax[3], tDelta[3];
    const double inf = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 3; ++i)
    {
      const double p = a[i] + t0 * d[i];
      v[i] = std::min(this->Max[i], std::max(this->Min[i], static_cast<int>(std::floor(p + 0.5))));
      if (d[i] > 0)
      {
        step[i] = 1;
        tMax[i] = (v[i] + 0.5 - a[i]) / d[i];
        tDelta[i] = 1.0 / d[i];
      }
      else if (d[i] < 0)
      {
        step[i] = -1;
        tMax[i] = (v[i] - 0.5 - a[i]) / d[i];
        tDelta[i] = -1.0 / d[i];
      }
      else
      {
        step[i] = 0;
        tMax[i] = inf;
        tDelta[i] = inf;
      }
    }
    for (;;)
    {
      if (this->Voxel(v[0], v[1], v[2]))
      {
        return true;
      }
      const int axis =
        tMax[0] <= tMax[1] ? (tMax[0] <= tMax[2] ? 0 : 2) : (tMax[1] <= tMax[2] ? 1 : 2);
      if (!(tMax[axis] <= t1))
      {
        return false;
      }
      v[axis] += step[axis];
      if (v[axis] < this->Min[axis] || v[axis] > this->Max[axis])
      {
        return false;
      }
      tMax[axis] += tDelta[axis];
    }
  }
};

// The world bounds of the local box [lo, hi] mapped by `localToWorld`.
void MappedBounds(const double lo[3], const double hi[3], vtkMatrix4x4* localToWorld, double out[6])
{
  for (int i = 0; i < 3; ++i)
  {
    out[2 * i] = VTK_DOUBLE_MAX;
    out[2 * i + 1] = -VTK_DOUBLE_MAX;
  }
  for (int c = 0; c < 8; ++c)
  {
    const double p[4] = { (c & 1) ? hi[0] : lo[0], (c & 2) ? hi[1] : lo[1], (c & 4) ? hi[2] : lo[2],
      1.0 };
    double w[4];
    localToWorld->MultiplyPoint(p, w);
    for (int i = 0; i < 3; ++i)
    {
      out[2 * i] = std::min(out[2 * i], w[i]);
      out[2 * i + 1] = std::max(out[2 * i + 1], w[i]);
    }
  }
}

bool IsAffineInvertible(vtkMatrix4x4* m)
{
  for (int i = 0; i < 16; ++i)
  {
    if (!std::isfinite(m->GetData()[i]))
    {
      return false;
    }
  }
  if (m->GetElement(3, 0) != 0 || m->GetElement(3, 1) != 0 || m->GetElement(3, 2) != 0 ||
    m->GetElement(3, 3) != 1)
  {
    return false;
  }
  const double det = m->Determinant();
  double norm = 0;
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      norm = std::max(norm, std::abs(m->GetElement(i, j)));
    }
  }
  return norm > 0 && std::abs(det) > 1e-12 * norm * norm * norm;
}

bool PrepareBox(const double bounds[6], vtkMatrix4x4* boxToWorld, Prepared& p, std::string& error)
{
  for (int i = 0; i < 3; ++i)
  {
    if (!(bounds[2 * i] <= bounds[2 * i + 1]) || !std::isfinite(bounds[2 * i]) ||
      !std::isfinite(bounds[2 * i + 1]))
    {
      error = "a box has min > max (or a bound that is not finite)";
      return false;
    }
    p.Lo[i] = bounds[2 * i];
    p.Hi[i] = bounds[2 * i + 1];
  }
  p.Shape = Prepared::BOX;
  if (!boxToWorld)
  {
    std::copy(bounds, bounds + 6, p.WorldBounds);
    return true;
  }
  if (!IsAffineInvertible(boxToWorld))
  {
    error = "an oriented box's map is not an invertible affine map";
    return false;
  }
  vtkNew<vtkMatrix4x4> inverse;
  vtkMatrix4x4::Invert(boxToWorld, inverse);
  p.Mapped = true;
  p.Map.Set(inverse);
  MappedBounds(p.Lo, p.Hi, boxToWorld, p.WorldBounds);
  return true;
}

// vtkSphere and vtkBox with no or a linear transform become exact regions.
bool PrepareFunction(vtkImplicitFunction* function, double step, Prepared& p, std::string& error)
{
  if (!function)
  {
    error = "an implicit-function region has no function";
    return false;
  }
  vtkAbstractTransform* transform = function->GetTransform();
  vtkLinearTransform* linear = vtkLinearTransform::SafeDownCast(transform);
  vtkSmartPointer<vtkMatrix4x4> worldToLocal;
  if (linear)
  {
    linear->Update();
    worldToLocal = vtkSmartPointer<vtkMatrix4x4>::New();
    worldToLocal->DeepCopy(linear->GetMatrix());
  }
  const bool exactFrame = !transform || (linear && IsAffineInvertible(worldToLocal));
  vtkSphere* sphere = vtkSphere::SafeDownCast(function);
  vtkBox* box = vtkBox::SafeDownCast(function);
  if (exactFrame && (sphere || box))
  {
    vtkSmartPointer<vtkMatrix4x4> localToWorld;
    if (worldToLocal)
    {
      p.Mapped = true;
      p.Map.Set(worldToLocal);
      localToWorld = vtkSmartPointer<vtkMatrix4x4>::New();
      vtkMatrix4x4::Invert(worldToLocal, localToWorld);
    }
    if (sphere)
    {
      const double r = sphere->GetRadius();
      if (!(r > 0) || !std::isfinite(r))
      {
        error = "a vtkSphere region has a radius <= 0 (or not finite)";
        return false;
      }
      p.Shape = Prepared::SPHERE;
      sphere->GetCenter(p.Center);
      p.R2 = r * r;
      for (int i = 0; i < 3; ++i)
      {
        p.Lo[i] = p.Center[i] - r;
        p.Hi[i] = p.Center[i] + r;
      }
    }
    else
    {
      double bounds[6];
      box->GetBounds(bounds);
      if (!PrepareBox(bounds, nullptr, p, error))
      {
        return false;
      }
    }
    if (localToWorld)
    {
      MappedBounds(p.Lo, p.Hi, localToWorld, p.WorldBounds);
    }
    else
    {
      for (int i = 0; i < 3; ++i)
      {
        p.WorldBounds[2 * i] = p.Lo[i];
        p.WorldBounds[2 * i + 1] = p.Hi[i];
      }
    }
    return true;
  }
  p.Shape = Prepared::SAMPLED;
  p.Function = function;
  p.Step = step;
  p.Bounded = false;
  return true;
}

bool PrepareLabels(const Region& r, Prepared& p, std::string& error)
{
  vtkImageData* image = r.Image;
  if (!image)
  {
    error = "a label-image region has no image";
    return false;
  }
  if (r.Labels.empty())
  {
    error = "the label set of a label-image region is empty";
    return false;
  }
  vtkDataArray* array = image->GetPointData()->GetArray(r.ArrayName.c_str());
  const bool cells = !array;
  if (cells)
  {
    array = image->GetCellData()->GetArray(r.ArrayName.c_str());
  }
  if (!array || array->GetNumberOfComponents() != 1)
  {
    error = "the label image has no one-component point or cell array named '" + r.ArrayName + "'";
    return false;
  }
  int ext[6];
  image->GetExtent(ext);
  double shift[3] = { 0, 0, 0 }; // index space -> voxel-centred space
  int n[3];
  for (int i = 0; i < 3; ++i)
  {
    n[i] = ext[2 * i + 1] - ext[2 * i] + 1;
    if (cells && n[i] > 1)
    {
      --n[i];
      shift[i] = -0.5;
    }
  }
  if (n[0] <= 0 || n[1] <= 0 || n[2] <= 0 ||
    array->GetNumberOfTuples() != static_cast<vtkIdType>(n[0]) * n[1] * n[2])
  {
    error = "the label image's array does not match its extent";
    return false;
  }
  vtkMatrix4x4* toPhysical = image->GetIndexToPhysicalMatrix();
  if (!IsAffineInvertible(toPhysical))
  {
    error = "the label image's placement (spacing, direction) is singular";
    return false;
  }
  vtkNew<vtkMatrix4x4> toIndex;
  vtkMatrix4x4::Invert(toPhysical, toIndex);
  for (int i = 0; i < 3; ++i)
  {
    toIndex->SetElement(i, 3, toIndex->GetElement(i, 3) + shift[i]);
  }
  std::vector<double> labels = r.Labels;
  std::sort(labels.begin(), labels.end());
  // The labelled voxels: which, and their index box.
  const vtkIdType count = array->GetNumberOfTuples();
  std::vector<unsigned char> all(count);
  vtkSMPTools::For(0, count,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType v = begin; v < end; ++v)
      {
        all[v] = std::binary_search(labels.begin(), labels.end(), array->GetComponent(v, 0));
      }
    });
  int lo[3] = { n[0], n[1], n[2] }, hi[3] = { -1, -1, -1 };
  for (vtkIdType v = 0; v < count; ++v)
  {
    if (all[v])
    {
      const int ijk[3] = { static_cast<int>(v % n[0]), static_cast<int>((v / n[0]) % n[1]),
        static_cast<int>(v / (static_cast<vtkIdType>(n[0]) * n[1])) };
      for (int i = 0; i < 3; ++i)
      {
        lo[i] = std::min(lo[i], ijk[i]);
        hi[i] = std::max(hi[i], ijk[i]);
      }
    }
  }
  p.Shape = Prepared::VOXELS;
  p.Mapped = true;
  p.Map.Set(toIndex);
  if (hi[0] < 0) // no voxel carries a label of the set: an empty region
  {
    p.Min[0] = p.Min[1] = p.Min[2] = 0;
    p.Max[0] = p.Max[1] = p.Max[2] = -1;
    p.Lo[0] = p.Lo[1] = p.Lo[2] = 1;
    p.Hi[0] = p.Hi[1] = p.Hi[2] = 0;
    p.Bounded = true;
    p.WorldBounds[0] = p.WorldBounds[2] = p.WorldBounds[4] = 1;
    p.WorldBounds[1] = p.WorldBounds[3] = p.WorldBounds[5] = 0;
    return true;
  }
  for (int i = 0; i < 3; ++i)
  {
    p.Min[i] = ext[2 * i] + lo[i];
    p.Max[i] = ext[2 * i] + hi[i];
    p.Lo[i] = p.Min[i] - 0.5;
    p.Hi[i] = p.Max[i] + 0.5;
  }
  p.Mask.resize(static_cast<size_t>(hi[0] - lo[0] + 1) * (hi[1] - lo[1] + 1) * (hi[2] - lo[2] + 1));
  size_t m = 0;
  for (int k = lo[2]; k <= hi[2]; ++k)
  {
    for (int j = lo[1]; j <= hi[1]; ++j)
    {
      for (int i = lo[0]; i <= hi[0]; ++i)
      {
        p.Mask[m++] =
          all[i + static_cast<vtkIdType>(n[0]) * (j + static_cast<vtkIdType>(n[1]) * k)];
      }
    }
  }
  vtkNew<vtkMatrix4x4> localToWorld;
  vtkMatrix4x4::Invert(toIndex, localToWorld);
  MappedBounds(p.Lo, p.Hi, localToWorld, p.WorldBounds);
  return true;
}

// The line cells of a polydata as vtkIdType offsets and connectivity.
struct LineView
{
  const vtkIdType* Offsets = nullptr;
  const vtkIdType* Connectivity = nullptr;
  vtkIdType Count = 0;
  std::vector<vtkIdType> OffsetsCopy, ConnectivityCopy;

  explicit LineView(vtkCellArray* lines)
  {
    this->Count = lines ? lines->GetNumberOfCells() : 0;
    if (this->Count == 0)
    {
      return;
    }
    if (lines->IsStorage64Bit() && sizeof(vtkIdType) == 8)
    {
      this->Offsets = reinterpret_cast<const vtkIdType*>(lines->GetOffsetsArray64()->GetPointer(0));
      this->Connectivity =
        reinterpret_cast<const vtkIdType*>(lines->GetConnectivityArray64()->GetPointer(0));
      return;
    }
    vtkDataArray* offsets = lines->GetOffsetsArray();
    vtkDataArray* connectivity = lines->GetConnectivityArray();
    this->OffsetsCopy.resize(offsets->GetNumberOfTuples());
    for (vtkIdType i = 0; i < offsets->GetNumberOfTuples(); ++i)
    {
      this->OffsetsCopy[i] = static_cast<vtkIdType>(offsets->GetComponent(i, 0));
    }
    this->ConnectivityCopy.resize(connectivity->GetNumberOfTuples());
    for (vtkIdType i = 0; i < connectivity->GetNumberOfTuples(); ++i)
    {
      this->ConnectivityCopy[i] = static_cast<vtkIdType>(connectivity->GetComponent(i, 0));
    }
    this->Offsets = this->OffsetsCopy.data();
    this->Connectivity = this->ConnectivityCopy.data();
  }
};

// Selects streamlines [begin, end): the regions in order EXCLUDE first, then
// INCLUDE and ENDPOINT.
template <typename T>
struct SelectWorker
{
  const T* Points;
  const LineView& Lines;
  const std::vector<Prepared>& Regions;
  size_t NumberOfExcludes;
  bool And;
  bool BothEnds;
  unsigned char* Selected;

  void Load(vtkIdType id, double x[3]) const
  {
    const T* p = this->Points + 3 * id;
    x[0] = static_cast<double>(p[0]);
    x[1] = static_cast<double>(p[1]);
    x[2] = static_cast<double>(p[2]);
  }

  bool EndHits(const Prepared& r, const vtkIdType* ids, vtkIdType n) const
  {
    double w[3], l[3];
    this->Load(ids[0], w);
    r.ToLocal(w, l);
    const bool first = r.Contains(l);
    if (first != this->BothEnds)
    {
      return first; // EITHER: first inside; BOTH: first outside
    }
    this->Load(ids[n - 1], w);
    r.ToLocal(w, l);
    return r.Contains(l);
  }

  bool Touches(const Prepared& r, const vtkIdType* ids, vtkIdType n, const double box[6]) const
  {
    if (r.Bounded)
    {
      for (int i = 0; i < 3; ++i)
      {
        if (box[2 * i] > r.WorldBounds[2 * i + 1] || box[2 * i + 1] < r.WorldBounds[2 * i])
        {
          return false;
        }
      }
    }
    double w[3], a[3], b[3];
    this->Load(ids[0], w);
    r.ToLocal(w, a);
    if (n == 1)
    {
      return r.Contains(a);
    }
    for (vtkIdType k = 1; k < n; ++k)
    {
      this->Load(ids[k], w);
      r.ToLocal(w, b);
      if (r.SegmentHits(a, b))
      {
        return true;
      }
      a[0] = b[0];
      a[1] = b[1];
      a[2] = b[2];
    }
    return false;
  }

  bool Hits(const Prepared& r, const vtkIdType* ids, vtkIdType n, const double box[6]) const
  {
    return r.Role == vtkStreamlineSelection::ENDPOINT ? this->EndHits(r, ids, n)
                                                      : this->Touches(r, ids, n, box);
  }

  bool SelectOne(vtkIdType line) const
  {
    const vtkIdType* ids = this->Lines.Connectivity + this->Lines.Offsets[line];
    const vtkIdType n = this->Lines.Offsets[line + 1] - this->Lines.Offsets[line];
    if (n <= 0)
    {
      return false;
    }
    double box[6] = { VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX,
      VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
    for (vtkIdType k = 0; k < n; ++k)
    {
      double x[3];
      this->Load(ids[k], x);
      for (int i = 0; i < 3; ++i)
      {
        if (x[i] < box[2 * i])
        {
          box[2 * i] = x[i];
        }
        if (x[i] > box[2 * i + 1])
        {
          box[2 * i + 1] = x[i];
        }
      }
    }
    for (size_t r = 0; r < this->NumberOfExcludes; ++r)
    {
      if (this->Hits(this->Regions[r], ids, n, box))
      {
        return false;
      }
    }
    if (this->NumberOfExcludes == this->Regions.size())
    {
      return true;
    }
    for (size_t r = this->NumberOfExcludes; r < this->Regions.size(); ++r)
    {
      if (this->Hits(this->Regions[r], ids, n, box) != this->And)
      {
        return !this->And; // AND: one fails; OR: one holds
      }
    }
    return this->And;
  }

  void operator()(vtkIdType begin, vtkIdType end) const
  {
    for (vtkIdType line = begin; line < end; ++line)
    {
      this->Selected[line] = this->SelectOne(line) ? 1 : 0;
    }
  }
};
}

struct vtkStreamlineSelection::Internals
{
  std::vector<Region> Regions;

  // The prepared regions (EXCLUDE first) for an input of the given bounds.
  bool Prepare(double step, std::vector<Prepared>& out, size_t& excludes, std::string& error) const
  {
    std::vector<Prepared> include;
    std::vector<Prepared> exclude;
    for (size_t i = 0; i < this->Regions.size(); ++i)
    {
      const Region& r = this->Regions[i];
      Prepared p;
      p.Role = r.Role;
      bool ok = true;
      switch (r.Kind)
      {
        case Region::SPHERE:
          if (!(r.Radius > 0) || !std::isfinite(r.Radius) || !std::isfinite(r.Center[0]) ||
            !std::isfinite(r.Center[1]) || !std::isfinite(r.Center[2]))
          {
            error = "a sphere has a radius <= 0 (or a value that is not finite)";
            ok = false;
            break;
          }
          p.Shape = Prepared::SPHERE;
          std::copy(r.Center, r.Center + 3, p.Center);
          p.R2 = r.Radius * r.Radius;
          for (int k = 0; k < 3; ++k)
          {
            p.WorldBounds[2 * k] = r.Center[k] - r.Radius;
            p.WorldBounds[2 * k + 1] = r.Center[k] + r.Radius;
          }
          break;
        case Region::BOX:
          ok = PrepareBox(r.Bounds, r.BoxToWorld, p, error);
          break;
        case Region::FUNCTION:
          ok = PrepareFunction(r.Function, step, p, error);
          break;
        default:
          ok = PrepareLabels(r, p, error);
          break;
      }
      if (!ok)
      {
        std::ostringstream msg;
        msg << "Region " << i << " (" << RoleNames[r.Role] << "): " << error;
        error = msg.str();
        return false;
      }
      (r.Role == EXCLUDE ? exclude : include).push_back(std::move(p));
    }
    excludes = exclude.size();
    out = std::move(exclude);
    for (Prepared& p : include)
    {
      out.push_back(std::move(p));
    }
    return true;
  }
};

//------------------------------------------------------------------------------
vtkStreamlineSelection::vtkStreamlineSelection()
  : Internal(new Internals)
{
}

vtkStreamlineSelection::~vtkStreamlineSelection() = default;

//------------------------------------------------------------------------------
int vtkStreamlineSelection::AddRegion(int role)
{
  Region r;
  r.Role = std::min(static_cast<int>(ENDPOINT), std::max(static_cast<int>(INCLUDE), role));
  if (r.Role != role)
  {
    vtkWarningMacro(<< "Unknown region role " << role << ", using " << RoleNames[r.Role]);
  }
  this->Internal->Regions.push_back(r);
  this->Modified();
  return static_cast<int>(this->Internal->Regions.size()) - 1;
}

int vtkStreamlineSelection::AddSphere(double cx, double cy, double cz, double radius, int role)
{
  const int index = this->AddRegion(role);
  Region& r = this->Internal->Regions[index];
  r.Kind = Region::SPHERE;
  r.Center[0] = cx;
  r.Center[1] = cy;
  r.Center[2] = cz;
  r.Radius = radius;
  return index;
}

int vtkStreamlineSelection::AddSphere(const double center[3], double radius, int role)
{
  return this->AddSphere(center[0], center[1], center[2], radius, role);
}

int vtkStreamlineSelection::AddBox(const double bounds[6], int role)
{
  return this->AddOrientedBox(bounds, nullptr, role);
}

int vtkStreamlineSelection::AddOrientedBox(
  const double bounds[6], vtkMatrix4x4* boxToWorld, int role)
{
  const int index = this->AddRegion(role);
  Region& r = this->Internal->Regions[index];
  r.Kind = Region::BOX;
  std::copy(bounds, bounds + 6, r.Bounds);
  r.BoxToWorld = boxToWorld;
  return index;
}

int vtkStreamlineSelection::AddImplicitFunction(vtkImplicitFunction* function, int role)
{
  const int index = this->AddRegion(role);
  Region& r = this->Internal->Regions[index];
  r.Kind = Region::FUNCTION;
  r.Function = function;
  return index;
}

int vtkStreamlineSelection::AddLabelImage(
  vtkImageData* image, const char* arrayName, vtkIdList* labels, int role)
{
  const int index = this->AddRegion(role);
  Region& r = this->Internal->Regions[index];
  r.Kind = Region::LABELS;
  r.Image = image;
  r.ArrayName = arrayName ? arrayName : "";
  for (vtkIdType i = 0; labels && i < labels->GetNumberOfIds(); ++i)
  {
    r.Labels.push_back(static_cast<double>(labels->GetId(i)));
  }
  return index;
}

void vtkStreamlineSelection::AddRegionLabel(int region, vtkIdType label)
{
  if (region < 0 || region >= this->GetNumberOfRegions() ||
    this->Internal->Regions[region].Kind != Region::LABELS)
  {
    vtkErrorMacro(<< "AddRegionLabel: region " << region << " is not a label-image region");
    return;
  }
  this->Internal->Regions[region].Labels.push_back(static_cast<double>(label));
  this->Modified();
}

void vtkStreamlineSelection::RemoveAllRegions()
{
  if (!this->Internal->Regions.empty())
  {
    this->Internal->Regions.clear();
    this->Modified();
  }
}

int vtkStreamlineSelection::GetNumberOfRegions()
{
  return static_cast<int>(this->Internal->Regions.size());
}

vtkMTimeType vtkStreamlineSelection::GetMTime()
{
  vtkMTimeType mtime = this->Superclass::GetMTime();
  for (const Region& r : this->Internal->Regions)
  {
    if (r.BoxToWorld)
    {
      mtime = std::max(mtime, r.BoxToWorld->GetMTime());
    }
    if (r.Function)
    {
      mtime = std::max(mtime, r.Function->GetMTime());
    }
    if (r.Image)
    {
      mtime = std::max(mtime, r.Image->GetMTime());
    }
  }
  return mtime;
}

//------------------------------------------------------------------------------
int vtkStreamlineSelection::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port != 0)
  {
    return 0;
  }
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkCompositeDataSet");
  return 1;
}

//------------------------------------------------------------------------------
// 0: failed (error reported), -1: aborted, 1: done.
int vtkStreamlineSelection::SelectBlock(
  vtkPolyData* input, vtkPolyData* output, double from, double to)
{
  std::vector<Prepared> regions;
  size_t excludes = 0;
  std::string error;
  double step = this->ImplicitFunctionStep;
  if (step <= 0)
  {
    step = 1e-3 * input->GetLength();
  }
  if (!this->Internal->Prepare(step, regions, excludes, error))
  {
    vtkErrorMacro(<< error);
    return 0;
  }
  for (const Prepared& p : regions)
  {
    if (p.Function && p.Function->GetTransform())
    {
      p.Function->GetTransform()->Update(); // not from the worker threads
    }
  }
  LineView lines(input->GetLines());
  std::vector<unsigned char> selected(lines.Count, 0);
  vtkPoints* points = input->GetPoints();
  if (lines.Count > 0 && points)
  {
    vtkSmartPointer<vtkDataArray> data = points->GetData();
    if (!vtkFloatArray::SafeDownCast(data) && !vtkDoubleArray::SafeDownCast(data))
    {
      vtkNew<vtkDoubleArray> copy;
      copy->DeepCopy(data);
      data = copy;
    }
    bool done = true;
    auto run = [&](auto* typed)
    {
      using T = std::remove_const_t<std::remove_pointer_t<decltype(typed)>>;
      SelectWorker<T> worker{ typed, lines, regions, excludes,
        this->IncludeCombination == COMBINE_AND, this->EndpointMode == BOTH_ENDS, selected.data() };
      done = vtkSplineVizProgress::For(
        this, 0, lines.Count, 0, 1024,
        [&worker](vtkIdType begin, vtkIdType end) { worker(begin, end); }, from,
        from + 0.9 * (to - from));
    };
    if (auto* f = vtkFloatArray::SafeDownCast(data))
    {
      run(f->GetPointer(0));
    }
    else
    {
      run(vtkDoubleArray::SafeDownCast(data)->GetPointer(0));
    }
    if (!done)
    {
      return -1;
    }
  }
  vtkIdType count = 0;
  for (unsigned char s : selected)
  {
    count += s;
  }
  this->NumberOfSelectedStreamlines += count;
  if (this->OutputMode == MARK_STREAMLINES)
  {
    this->MarkSelected(input, selected.data(), output);
  }
  else
  {
    this->CopySelected(input, selected.data(), output);
  }
  this->UpdateProgress(to);
  return 1;
}

void vtkStreamlineSelection::MarkSelected(
  vtkPolyData* input, const unsigned char* selected, vtkPolyData* output)
{
  output->ShallowCopy(input);
  vtkNew<vtkUnsignedCharArray> marks;
  marks->SetName("Selected");
  marks->SetNumberOfTuples(input->GetNumberOfCells());
  marks->FillValue(0);
  const vtkIdType first = input->GetNumberOfVerts();
  std::copy(selected, selected + input->GetNumberOfLines(), marks->GetPointer(first));
  output->GetCellData()->RemoveArray("Selected");
  output->GetCellData()->AddArray(marks);
}

void vtkStreamlineSelection::CopySelected(
  vtkPolyData* input, const unsigned char* selected, vtkPolyData* output)
{
  output->Initialize();
  output->GetFieldData()->PassData(input->GetFieldData());
  LineView lines(input->GetLines());
  // The selected lines' cells and point ids (input numbering).
  vtkIdType cells = 0, size = 0;
  for (vtkIdType line = 0; line < lines.Count; ++line)
  {
    if (selected[line])
    {
      ++cells;
      size += lines.Offsets[line + 1] - lines.Offsets[line];
    }
  }
  vtkNew<vtkIdList> sourceCells;
  sourceCells->SetNumberOfIds(cells);
  vtkNew<vtkIdTypeArray> offsets;
  offsets->SetNumberOfValues(cells + 1);
  vtkNew<vtkIdTypeArray> connectivity;
  connectivity->SetNumberOfValues(size);
  vtkIdType* ids = connectivity->GetPointer(0);
  offsets->SetValue(0, 0);
  for (vtkIdType line = 0, cell = 0, at = 0; line < lines.Count; ++line)
  {
    if (selected[line])
    {
      sourceCells->SetId(cell, input->GetNumberOfVerts() + line);
      const vtkIdType begin = lines.Offsets[line], end = lines.Offsets[line + 1];
      std::copy(lines.Connectivity + begin, lines.Connectivity + end, ids + at);
      at += end - begin;
      offsets->SetValue(++cell, at);
    }
  }
  // The points used, in input order, and the connectivity renumbered: a
  // lookup table over all points when many are used, else sorted ids.
  const vtkIdType numberOfPoints = input->GetNumberOfPoints();
  vtkNew<vtkIdList> sourcePoints;
  if (size * 8 >= numberOfPoints)
  {
    std::vector<vtkIdType> map(numberOfPoints, -1);
    for (vtkIdType k = 0; k < size; ++k)
    {
      map[ids[k]] = 0;
    }
    vtkIdType used = 0;
    for (vtkIdType p = 0; p < numberOfPoints; ++p)
    {
      if (map[p] == 0)
      {
        map[p] = used++;
      }
    }
    sourcePoints->SetNumberOfIds(used);
    for (vtkIdType p = 0; p < numberOfPoints; ++p)
    {
      if (map[p] >= 0)
      {
        sourcePoints->SetId(map[p], p);
      }
    }
    vtkSMPTools::For(0, size,
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType k = begin; k < end; ++k)
        {
          ids[k] = map[ids[k]];
        }
      });
  }
  else
  {
    std::vector<vtkIdType> used(ids, ids + size);
    vtkSMPTools::Sort(used.begin(), used.end());
    used.erase(std::unique(used.begin(), used.end()), used.end());
    sourcePoints->SetNumberOfIds(static_cast<vtkIdType>(used.size()));
    std::copy(used.begin(), used.end(), sourcePoints->GetPointer(0));
    vtkSMPTools::For(0, size,
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType k = begin; k < end; ++k)
        {
          ids[k] = std::lower_bound(used.begin(), used.end(), ids[k]) - used.begin();
        }
      });
  }
  const vtkIdType used = sourcePoints->GetNumberOfIds();
  if (used > 0)
  {
    vtkNew<vtkPoints> points;
    points->SetDataType(input->GetPoints()->GetDataType());
    points->SetNumberOfPoints(used);
    points->GetData()->InsertTuplesStartingAt(0, sourcePoints, input->GetPoints()->GetData());
    output->SetPoints(points);
    output->GetPointData()->CopyAllocate(input->GetPointData(), used);
    output->GetPointData()->CopyData(
      input->GetPointData(), sourcePoints.GetPointer(), vtkIdType(0));
  }
  vtkNew<vtkCellArray> out;
  out->SetData(offsets, connectivity);
  output->SetLines(out);
  output->GetCellData()->CopyAllocate(input->GetCellData(), cells);
  output->GetCellData()->CopyData(input->GetCellData(), sourceCells.GetPointer(), vtkIdType(0));
}

//------------------------------------------------------------------------------
int vtkStreamlineSelection::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkDataObject* input = vtkDataObject::GetData(inputVector[0], 0);
  vtkDataObject* output = vtkDataObject::GetData(outputVector, 0);
  this->NumberOfSelectedStreamlines = 0;
  if (this->Internal->Regions.empty())
  {
    vtkWarningMacro(<< "No regions: every streamline is selected");
  }
  vtkCompositeDataSet* compositeIn = vtkCompositeDataSet::SafeDownCast(input);
  vtkCompositeDataSet* compositeOut = vtkCompositeDataSet::SafeDownCast(output);
  if (!compositeIn)
  {
    vtkPolyData* in = vtkPolyData::SafeDownCast(input);
    vtkPolyData* out = vtkPolyData::SafeDownCast(output);
    if (!in || !out)
    {
      vtkErrorMacro(<< "The input is not polydata or a composite of polydata");
      return 0;
    }
    const int status = this->SelectBlock(in, out, 0.0, 1.0);
    if (status <= 0)
    {
      out->Initialize();
      this->NumberOfSelectedStreamlines = 0;
    }
    return status == 0 ? 0 : 1;
  }
  if (!compositeOut)
  {
    vtkErrorMacro(<< "The output is not a composite data set");
    return 0;
  }
  compositeOut->CopyStructure(compositeIn);
  vtkSmartPointer<vtkCompositeDataIterator> it =
    vtkSmartPointer<vtkCompositeDataIterator>::Take(compositeIn->NewIterator());
  vtkIdType total = 0;
  for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
  {
    if (vtkPolyData* block = vtkPolyData::SafeDownCast(it->GetCurrentDataObject()))
    {
      total += block->GetNumberOfLines();
    }
  }
  vtkIdType done = 0;
  bool skipped = false;
  for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
  {
    vtkPolyData* block = vtkPolyData::SafeDownCast(it->GetCurrentDataObject());
    if (!block)
    {
      skipped = true;
      continue;
    }
    const double from = total > 0 ? static_cast<double>(done) / total : 0.0;
    done += block->GetNumberOfLines();
    const double to = total > 0 ? static_cast<double>(done) / total : 1.0;
    vtkNew<vtkPolyData> result;
    const int status = this->SelectBlock(block, result, from, to);
    if (status <= 0)
    {
      compositeOut->Initialize();
      this->NumberOfSelectedStreamlines = 0;
      return status == 0 ? 0 : 1;
    }
    compositeOut->SetDataSet(it, result);
  }
  if (skipped)
  {
    vtkWarningMacro(<< "Blocks that are not polydata are left empty");
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkStreamlineSelection::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  static const char* const kinds[] = { "sphere", "box", "implicit function", "label image" };
  os << indent << "Regions: " << this->Internal->Regions.size() << "\n";
  for (const Region& r : this->Internal->Regions)
  {
    os << indent.GetNextIndent() << RoleNames[r.Role] << " " << kinds[r.Kind];
    if (r.Kind == Region::SPHERE)
    {
      os << " centre (" << r.Center[0] << ", " << r.Center[1] << ", " << r.Center[2] << ") radius "
         << r.Radius;
    }
    else if (r.Kind == Region::BOX)
    {
      os << " bounds (" << r.Bounds[0] << ", " << r.Bounds[1] << ", " << r.Bounds[2] << ", "
         << r.Bounds[3] << ", " << r.Bounds[4] << ", " << r.Bounds[5] << ")"
         << (r.BoxToWorld ? " oriented" : "");
    }
    else if (r.Kind == Region::LABELS)
    {
      os << " array '" << r.ArrayName << "', " << r.Labels.size() << " labels";
    }
    os << "\n";
  }
  os << indent << "IncludeCombination: " << (this->IncludeCombination == COMBINE_AND ? "AND" : "OR")
     << "\n";
  os << indent
     << "EndpointMode: " << (this->EndpointMode == EITHER_END ? "EITHER_END" : "BOTH_ENDS") << "\n";
  os << indent << "OutputMode: "
     << (this->OutputMode == SELECTED_STREAMLINES ? "SELECTED_STREAMLINES" : "MARK_STREAMLINES")
     << "\n";
  os << indent << "ImplicitFunctionStep: " << this->ImplicitFunctionStep << "\n";
  os << indent << "NumberOfSelectedStreamlines: " << this->NumberOfSelectedStreamlines << "\n";
}
