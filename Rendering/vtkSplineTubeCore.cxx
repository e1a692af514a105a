// SPDX-License-Identifier: BSD-3-Clause
#include "vtkSplineTubeCore.h"

#include "vtkSplineTubeMath.h"
#include "vtkSplineTubeVisibility.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPThreadLocalObject.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkTypeInt32Array.h"
#include "vtkTypeInt64Array.h"
#include "vtkTypeUInt32Array.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <initializer_list>
#include <vector>

vtkStandardNewMacro(vtkSplineTubeCore);

namespace
{
using vtkSplineTubeMath::vec3;
using vtkSplineTubeMath::vec4;

bool IsFinite(double v)
{
  return std::isfinite(v);
}

/// One double-reflection step of the rotation-minimizing frame (Wang, Jüttler,
/// Zheng and Liu 2008): carries the unit normal `r0` at (x0, t0) to the point
/// x1 with unit tangent t1.
vec3 DoubleReflection(
  const vec3& x0, const vec3& t0, const vec3& r0, const vec3& x1, const vec3& t1)
{
  const vec3 v1 = x1 - x0;
  const double c1 = glm::dot(v1, v1);
  vec3 rL = r0;
  vec3 tL = t0;
  if (c1 > 0.0)
  {
    rL = r0 - (2.0 / c1) * glm::dot(v1, r0) * v1;
    tL = t0 - (2.0 / c1) * glm::dot(v1, t0) * v1;
  }
  const vec3 v2 = t1 - tL;
  const double c2 = glm::dot(v2, v2);
  vec3 r1 = rL;
  if (c2 > 0.0)
  {
    r1 = rL - (2.0 / c2) * glm::dot(v2, rL) * v2;
  }
  // Remove the round-off drift: orthogonal to t1, unit length.
  r1 = r1 - glm::dot(r1, t1) * t1;
  const double len = glm::length(r1);
  if (len < 1e-12)
  {
    return vtkSplineTubeMath::svAnyOrthogonal(t1);
  }
  return r1 / len;
}

/// The box of segment k of a tube (nodes k, k + 1 of its positions and
/// radii p and their derivatives m, 4 each): its cubic Bezier control points
/// (the curve lies in their convex hull) padded by the largest of the radius
/// spline's (the radius lies below their maximum), that radius r, and the
/// control points.
void SegmentBox(
  const double* p, const double* m, vtkIdType k, double box[6], double control[4][3], double& r)
{
  const double* a = p + 4 * k;
  const double* b = p + 4 * (k + 1);
  const double* da = m + 4 * k;
  const double* db = m + 4 * (k + 1);
  r = std::max({ a[3], b[3], a[3] + da[3] / 3.0, b[3] - db[3] / 3.0 });
  for (int c = 0; c < 3; ++c)
  {
    control[0][c] = a[c];
    control[1][c] = a[c] + da[c] / 3.0;
    control[2][c] = b[c] - db[c] / 3.0;
    control[3][c] = b[c];
    box[2 * c] = std::min({ control[0][c], control[1][c], control[2][c], control[3][c] }) - r;
    box[2 * c + 1] = std::max({ control[0][c], control[1][c], control[2][c], control[3][c] }) + r;
  }
}

/// Grow `straightness` (4 values, see GetChunkStraightness()) by segment k's:
/// the shared math's svSegmentStraightness() and svSubSegmentStraightness()
/// of its two quadratic sub-segments, as the ray-cast tubes' vertex stage
/// computes them, and their ratios to the smallest radius they are compared
/// with there.
void GrowStraightness(const double* p, const double* m, vtkIdType k, double straightness[4])
{
  const double* a = p + 4 * k;
  const double* b = p + 4 * (k + 1);
  const double* da = m + 4 * k;
  const double* db = m + 4 * (k + 1);
  const vec4 p0(a[0], a[1], a[2], a[3]);
  const vec4 m0(da[0], da[1], da[2], da[3]);
  const vec4 p1(b[0], b[1], b[2], b[3]);
  const vec4 m1(db[0], db[1], db[2], db[3]);
  auto grow = [](double* pair, double error, double radius)
  {
    pair[0] = std::max(pair[0], error);
    pair[1] = std::max(pair[1], radius > 0.0 ? error / radius : double(VTK_FLOAT_MAX));
  };
  double reach = 0.0;
  grow(straightness, vtkSplineTubeMath::svSegmentStraightness(p0, m0, p1, m1, reach),
    std::min({ a[3], b[3], a[3] + da[3] / 3.0, b[3] - db[3] / 3.0 }));
  for (int sub = 0; sub < 2; ++sub)
  {
    vec4 q0, q1, q2;
    vtkSplineTubeMath::svSplitSegment(p0, m0, p1, m1, 2, sub, q0, q1, q2);
    grow(straightness + 2, vtkSplineTubeMath::svSubSegmentStraightness(q0, q1, q2),
      std::min({ q0.w, q1.w, q2.w }));
  }
}

/// Grow the box `bounds` (xmin, xmax, ymin, ...) to contain `box`.
void AddBox(double bounds[6], const double box[6])
{
  for (int q = 0; q < 6; q += 2)
  {
    bounds[q] = std::min(bounds[q], box[q]);
    bounds[q + 1] = std::max(bounds[q + 1], box[q + 1]);
  }
}

/// A box (xmin, xmax, ymin, ...), empty at first; grown by AddBox().
struct Box
{
  double B[6] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MIN, VTK_DOUBLE_MAX, VTK_DOUBLE_MIN, VTK_DOUBLE_MAX,
    VTK_DOUBLE_MIN };
};

/// A thread's scratch for the nodes of a tube (TubeNodes()) and the box it grows.
struct NodesAndBox : Box
{
  std::vector<double> P;
  std::vector<double> M;
};

/// The union of the threads' boxes (a Local is or derives from Box).
template <typename Local>
void MergeBounds(vtkSMPThreadLocal<Local>& locals, double bounds[6])
{
  const Box empty;
  std::copy(empty.B, empty.B + 6, bounds);
  for (auto& local : locals)
  {
    AddBox(bounds, local.B);
  }
}

/// Calls visit(local, t, n) for every tube t, in parallel, with the thread's
/// scratch `local` holding the tube's n nodes (in.TubeNodes()) and the box
/// the thread grows; the union of the threads' boxes into bounds.
template <typename Tubes, typename Visit>
void ForEachTubeNodes(const Tubes& in, vtkIdType numTubes, double bounds[6], const Visit& visit)
{
  vtkSMPThreadLocal<NodesAndBox> locals;
  vtkSMPTools::For(0, numTubes,
    [&](vtkIdType begin, vtkIdType end)
    {
      NodesAndBox& local = locals.Local();
      for (vtkIdType t = begin; t < end; ++t)
      {
        const vtkIdType n = in.TubeNodes(t, local.P, local.M);
        visit(local, t, n);
      }
    });
  MergeBounds(locals, bounds);
}
}

//------------------------------------------------------------------------------
// The inputs and the tube table. Nodes are read from the inputs: tube t's
// node k is point Connectivity[ConnectivityOffset + k] of its source, or
// MergedPoints[Merged + k] for the (rare) tubes with merged repeated points.
struct vtkSplineTubeCore::Internals
{
  /// What scanning an input line found (Source::ScanLine()).
  enum LineStatus : unsigned char
  {
    LINE_OK,
    LINE_NONFINITE_POINT,
    LINE_BAD_RADIUS,
    LINE_BAD_SCALAR,
  };
  struct LineScan
  {
    vtkIdType Kept = 0;   ///< nodes kept
    vtkIdType Merged = 0; ///< repeated consecutive points merged
    vtkIdType BadPoint = -1;
    double BadRadius = 0.0;
    double MaxRadius = 0.0;
    unsigned char Status = LINE_OK;
  };

  struct Source
  {
    vtkSmartPointer<vtkPolyData> Data;
    vtkSmartPointer<vtkDataArray> Points;
    const float* PointsF = nullptr;
    const double* PointsD = nullptr;
    vtkSmartPointer<vtkDataArray> Radius;
    vtkSmartPointer<vtkDataArray> Scalar;
    vtkSmartPointer<vtkUnsignedCharArray> Colors;
    bool ColorsPerCell = false;
    vtkSmartPointer<vtkCellArray> Lines;
    const vtkTypeInt64* Connectivity64 = nullptr;
    const vtkTypeInt32* Connectivity32 = nullptr;
    vtkIdType FirstCellId = 0;
    unsigned int BlockId = 0;
    double ConstantRadius = 0.01;
    double RadiusScale = 1.0;

    vtkIdType Connectivity(vtkIdType i) const
    {
      return this->Connectivity64 ? static_cast<vtkIdType>(this->Connectivity64[i])
                                  : static_cast<vtkIdType>(this->Connectivity32[i]);
    }
    void Point(vtkIdType pid, double xyzr[4]) const
    {
      if (this->PointsF)
      {
        xyzr[0] = this->PointsF[3 * pid];
        xyzr[1] = this->PointsF[3 * pid + 1];
        xyzr[2] = this->PointsF[3 * pid + 2];
      }
      else if (this->PointsD)
      {
        xyzr[0] = this->PointsD[3 * pid];
        xyzr[1] = this->PointsD[3 * pid + 1];
        xyzr[2] = this->PointsD[3 * pid + 2];
      }
      else
      {
        this->Points->GetTuple(pid, xyzr);
      }
      xyzr[3] = this->Radius ? this->Radius->GetComponent(pid, 0) * this->RadiusScale
                             : this->ConstantRadius;
    }

    /// The input's points, lines and arrays (one-component radius and node
    /// scalar arrays, or nullptr; RGBA colors per point or per cell).
    void Init(vtkPolyData* input, vtkDataArray* radius, vtkDataArray* scalar,
      vtkUnsignedCharArray* colors, bool colorsPerCell, unsigned int blockId, double constantRadius,
      double radiusScale)
    {
      this->Data = input;
      this->Points = input->GetPoints()->GetData();
      if (auto* f = vtkFloatArray::SafeDownCast(this->Points))
      {
        this->PointsF = f->GetPointer(0);
      }
      else if (auto* d = vtkDoubleArray::SafeDownCast(this->Points))
      {
        this->PointsD = d->GetPointer(0);
      }
      this->Radius = radius;
      this->Scalar = scalar;
      this->Colors = colors;
      this->ColorsPerCell = colorsPerCell;
      this->Lines = input->GetLines();
      if (this->Lines->IsStorage64Bit())
      {
        this->Connectivity64 = this->Lines->GetConnectivityArray64()->GetPointer(0);
      }
      else
      {
        this->Connectivity32 = this->Lines->GetConnectivityArray32()->GetPointer(0);
      }
      this->FirstCellId = input->GetNumberOfVerts(); // line cell ids follow the verts
      this->BlockId = blockId;
      this->ConstantRadius = constantRadius;
      this->RadiusScale = radiusScale;
    }

    /**
     * Scan line `line` of the input: calls keep(pointId, xyzr) for every node kept
     * (repeated consecutive points merged); stops at the first point with a
     * non-finite coordinate, radius or scalar, or a radius <= 0.
     */
    template <typename Keep>
    void ScanLine(vtkIdType line, vtkIdList* scratch, LineScan& scan, Keep&& keep) const
    {
      vtkIdType npts;
      const vtkIdType* pts;
      this->Lines->GetCellAtId(line, npts, pts, scratch);
      double last[3] = { 0.0, 0.0, 0.0 };
      for (vtkIdType k = 0; k < npts; ++k)
      {
        double p[4];
        this->Point(pts[k], p);
        if (!IsFinite(p[0]) || !IsFinite(p[1]) || !IsFinite(p[2]))
        {
          scan.Status = LINE_NONFINITE_POINT;
          scan.BadPoint = pts[k];
          return;
        }
        if (this->Radius && (!IsFinite(p[3]) || p[3] <= 0.0))
        {
          scan.Status = LINE_BAD_RADIUS;
          scan.BadPoint = pts[k];
          scan.BadRadius = p[3];
          return;
        }
        if (this->Scalar && !IsFinite(this->Scalar->GetComponent(pts[k], 0)))
        {
          scan.Status = LINE_BAD_SCALAR;
          scan.BadPoint = pts[k];
          return;
        }
        if (scan.Kept > 0)
        {
          const double d2 = vtkMath::Distance2BetweenPoints(p, last);
          const double scale = std::max({ std::abs(p[0]), std::abs(p[1]), std::abs(p[2]), p[3] });
          if (d2 <= (1e-10 * scale) * (1e-10 * scale))
          {
            ++scan.Merged;
            continue;
          }
        }
        keep(pts[k], p);
        ++scan.Kept;
        scan.MaxRadius = std::max(scan.MaxRadius, p[3]);
        std::copy(p, p + 3, last);
      }
    }
  };
  struct Tube
  {
    vtkIdType ConnectivityOffset = 0;
    vtkIdType Line = 0; ///< index in the source's line array
    vtkIdType CellId = 0;
    vtkIdType Merged = -1;
    unsigned int Source = 0;
  };

  std::vector<Source> Sources;
  std::vector<Tube> Tubes;
  std::vector<vtkIdType> TubeFirst{ 0 }; ///< tubes + 1: first node of each tube
  std::vector<vtkIdType> MergedPoints;
  bool HaveScalars = false;

  vtkIdType TubeOfNode(vtkIdType node) const
  {
    return static_cast<vtkIdType>(
      std::upper_bound(this->TubeFirst.begin(), this->TubeFirst.end(), node) -
      this->TubeFirst.begin() - 1);
  }
  vtkIdType TubeOfSegment(vtkIdType segment) const
  {
    // The first segment of tube t is TubeFirst[t] - t (increasing in t).
    vtkIdType lo = 0;
    vtkIdType hi = static_cast<vtkIdType>(this->Tubes.size());
    while (hi - lo > 1)
    {
      const vtkIdType mid = (lo + hi) / 2;
      if (this->TubeFirst[mid] - mid <= segment)
      {
        lo = mid;
      }
      else
      {
        hi = mid;
      }
    }
    return lo;
  }
  vtkIdType PointId(vtkIdType tube, vtkIdType k) const
  {
    const Tube& t = this->Tubes[tube];
    if (t.Merged >= 0)
    {
      return this->MergedPoints[t.Merged + k];
    }
    return this->Sources[t.Source].Connectivity(t.ConnectivityOffset + k);
  }
  void Node(vtkIdType tube, vtkIdType k, double xyzr[4]) const
  {
    this->Sources[this->Tubes[tube].Source].Point(this->PointId(tube, k), xyzr);
  }
  /// All nodes of a tube and their derivatives, into `xyzr` and `dxyzr`
  /// (resized; kept by the caller across tubes); returns their number.
  vtkIdType TubeNodes(vtkIdType tube, std::vector<double>& xyzr, std::vector<double>& dxyzr) const
  {
    const vtkIdType n = this->TubeFirst[tube + 1] - this->TubeFirst[tube];
    xyzr.resize(static_cast<size_t>(4 * n));
    dxyzr.resize(static_cast<size_t>(4 * n));
    this->Nodes(tube, 0, n, xyzr.data(), dxyzr.data());
    return n;
  }
  /// Nodes [first, first + count) of a tube (xyzr, 4 each) and, if asked, their derivatives.
  void Nodes(vtkIdType tube, vtkIdType first, vtkIdType count, double* xyzr, double* dxyzr) const
  {
    const vtkIdType n = this->TubeFirst[tube + 1] - this->TubeFirst[tube];
    // The nodes around too, for the derivatives.
    const vtkIdType lo = dxyzr ? std::max<vtkIdType>(0, first - 2) : first;
    const vtkIdType hi = dxyzr ? std::min(n, first + count + 2) : first + count;
    double local[4 * 64];
    std::vector<double> heap;
    double* around = local;
    if (hi - lo > 64)
    {
      heap.resize(static_cast<size_t>(4 * (hi - lo)));
      around = heap.data();
    }
    for (vtkIdType k = lo; k < hi; ++k)
    {
      this->Node(tube, k, around + 4 * (k - lo));
    }
    for (vtkIdType k = first; k < first + count; ++k)
    {
      const double* p = around + 4 * (k - lo);
      if (xyzr)
      {
        std::copy(p, p + 4, xyzr + 4 * (k - first));
      }
      if (dxyzr)
      {
        auto at = [&](vtkIdType j)
        {
          j = std::max(lo, std::min(hi - 1, j));
          const double* q = around + 4 * (j - lo);
          return vec4(q[0], q[1], q[2], q[3]);
        };
        const vec4 d = vtkSplineTubeMath::svNodeDerivative(at(k - 2), at(k - 1), at(k), at(k + 1),
          at(k + 2), k == 0, k == n - 1, k - 1 == 0, k + 1 == n - 1);
        double* out = dxyzr + 4 * (k - first);
        out[0] = d.x;
        out[1] = d.y;
        out[2] = d.z;
        out[3] = d.w;
      }
    }
  }
  /// Calls body(tube, firstNode, endNode) for the parts of the tubes in
  /// [first, first + count), in parallel blocks of nodes.
  template <typename Body>
  void ForNodes(vtkIdType first, vtkIdType count, Body&& body) const
  {
    if (count <= 0)
    {
      return;
    }
    const vtkIdType end = first + count;
    vtkSMPTools::For(first, end, 65536,
      [&](vtkIdType b, vtkIdType e)
      {
        for (vtkIdType t = this->TubeOfNode(b); b < e; ++t)
        {
          const vtkIdType stop = std::min(e, this->TubeFirst[t + 1]);
          body(t, b, stop);
          b = stop;
        }
      });
  }
};

//------------------------------------------------------------------------------
vtkSplineTubeCore::vtkSplineTubeCore()
  : Internal(new Internals)
{
  this->TubeFirstChunks->SetName("TubeFirstChunks");
  this->ChunkFirstSegments->SetName("ChunkFirstSegments");
  this->ChunkTubes->SetName("ChunkTubes");
  this->ChunkSpheres->SetNumberOfComponents(4);
  this->ChunkSpheres->SetName("ChunkSpheres");
  this->ChunkSizes->SetNumberOfComponents(3);
  this->ChunkSizes->SetName("ChunkSizes");
  this->SegmentSpheres->SetName("SegmentSpheres");
  this->ChunkStraightness->SetNumberOfComponents(4);
  this->ChunkStraightness->SetName("ChunkStraightness");
}

//------------------------------------------------------------------------------
vtkSplineTubeCore::~vtkSplineTubeCore()
{
  this->SetRadiusArray(nullptr);
  this->SetNodeScalarArray(nullptr);
  this->SetNodeScalarRole(nullptr);
  this->SetCellIdArray(nullptr);
}

//------------------------------------------------------------------------------
void vtkSplineTubeCore::Initialize()
{
  this->Internal.reset(new Internals);
  this->TubeFirstChunks->SetNumberOfTuples(0);
  this->ChunkFirstSegments->SetNumberOfTuples(0);
  this->ChunkTubes->SetNumberOfTuples(0);
  this->ChunkSpheres->SetNumberOfTuples(0);
  this->ChunkSizes->SetNumberOfTuples(0);
  this->SegmentSpheres->SetNumberOfTuples(0);
  this->ChunkStraightness->SetNumberOfTuples(0);
  vtkMath::UninitializeBounds(this->Bounds);
  vtkMath::UninitializeBounds(this->NodeBounds);
  this->ColorsGiven = false;
  this->ColorsMissing = false;
  this->MaximumRadius = 0.0;
  this->MaximumCellId = 0;
  this->NumberOfSkippedLines = 0;
  this->NumberOfMergedPoints = 0;
  this->Modified();
}

//------------------------------------------------------------------------------
vtkIdType vtkSplineTubeCore::GetNumberOfTubes() const
{
  return static_cast<vtkIdType>(this->Internal->Tubes.size());
}

vtkIdType vtkSplineTubeCore::GetNumberOfNodes() const
{
  return this->Internal->TubeFirst.back();
}

vtkIdType vtkSplineTubeCore::GetNumberOfSegments() const
{
  return this->GetNumberOfNodes() - this->GetNumberOfTubes();
}

vtkIdType vtkSplineTubeCore::GetNumberOfChunks() const
{
  return this->ChunkTubes->GetNumberOfTuples();
}

vtkIdType vtkSplineTubeCore::GetTubeFirstNode(vtkIdType tube) const
{
  return this->Internal->TubeFirst[tube];
}

vtkIdType vtkSplineTubeCore::GetTubeNumberOfNodes(vtkIdType tube) const
{
  return this->Internal->TubeFirst[tube + 1] - this->Internal->TubeFirst[tube];
}

vtkIdType vtkSplineTubeCore::GetTubeCellId(vtkIdType tube) const
{
  return this->Internal->Tubes[tube].CellId;
}

vtkIdType vtkSplineTubeCore::GetTubeCellIndex(vtkIdType tube) const
{
  const Internals& in = *this->Internal;
  return in.Sources[in.Tubes[tube].Source].FirstCellId + in.Tubes[tube].Line;
}

unsigned int vtkSplineTubeCore::GetTubeBlockId(vtkIdType tube) const
{
  const Internals& in = *this->Internal;
  return in.Sources[in.Tubes[tube].Source].BlockId;
}

vtkIdType vtkSplineTubeCore::GetTubeOfNode(vtkIdType node) const
{
  return this->Internal->TubeOfNode(node);
}

bool vtkSplineTubeCore::GetConstantRadius(double& radius) const
{
  const Internals& in = *this->Internal;
  if (in.Sources.empty())
  {
    return false;
  }
  for (const Internals::Source& source : in.Sources)
  {
    if (source.Radius || source.ConstantRadius != in.Sources[0].ConstantRadius)
    {
      return false;
    }
  }
  radius = in.Sources[0].ConstantRadius;
  return true;
}

//------------------------------------------------------------------------------
bool vtkSplineTubeCore::HasNodeScalars() const
{
  return this->Internal->HaveScalars;
}

//------------------------------------------------------------------------------
bool vtkSplineTubeCore::FindPointArray(
  vtkPolyData* input, const char* name, const char* what, vtkDataArray*& array)
{
  array = nullptr;
  if (!name || !name[0])
  {
    return true;
  }
  vtkAbstractArray* abstractArray = input->GetPointData()->GetAbstractArray(name);
  if (!abstractArray)
  {
    vtkErrorMacro(<< "The " << what << " array \"" << name
                  << "\" is not a point array of the input.");
    return false;
  }
  array = vtkDataArray::SafeDownCast(abstractArray);
  if (!array)
  {
    vtkErrorMacro(<< "The " << what << " array \"" << name << "\" is not numeric.");
    return false;
  }
  if (array->GetNumberOfComponents() != 1)
  {
    vtkErrorMacro(<< "The " << what << " array \"" << name << "\" has "
                  << array->GetNumberOfComponents() << " components; a " << what
                  << " array needs exactly one.");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
vtkDataArray* vtkSplineTubeCore::FindOriginalIds(vtkPolyData* input) const
{
  vtkDataArray* originalIds = nullptr;
  if (this->CellIdArray && this->CellIdArray[0])
  {
    originalIds = input->GetCellData()->GetArray(this->CellIdArray);
    if (originalIds &&
      (originalIds->GetNumberOfComponents() != 1 ||
        vtkDataArray::GetDataTypeMin(originalIds->GetDataType()) == VTK_DOUBLE_MIN ||
        vtkDataArray::GetDataTypeMin(originalIds->GetDataType()) == VTK_FLOAT_MIN ||
        originalIds->GetNumberOfTuples() != input->GetNumberOfCells()))
    {
      originalIds = nullptr;
    }
  }
  return originalIds;
}

//------------------------------------------------------------------------------
bool vtkSplineTubeCore::AddPolyData(
  vtkPolyData* input, vtkUnsignedCharArray* colors, unsigned int blockId, bool colorsPerCell)
{
  if (!input || !input->GetPoints() || input->GetNumberOfPoints() == 0 ||
    input->GetNumberOfLines() == 0)
  {
    return true; // nothing to add; the caller reports an empty scene
  }
  const vtkIdType numPoints = input->GetNumberOfPoints();

  const char* role = this->NodeScalarRole ? this->NodeScalarRole : "node scalar";
  vtkDataArray* radiusArray = nullptr;
  vtkDataArray* scalarArray = nullptr;
  if (!this->FindPointArray(input, this->RadiusArray, "radius", radiusArray) ||
    !this->FindPointArray(input, this->NodeScalarArray, role, scalarArray))
  {
    return false;
  }
  const vtkIdType colorTuples =
    colorsPerCell ? input->GetNumberOfCells() : numPoints; // per cell: all cells
  if (colors && (colors->GetNumberOfComponents() != 4 || colors->GetNumberOfTuples() < colorTuples))
  {
    vtkErrorMacro(<< "Colors must be RGBA (4 components) with one tuple per "
                  << (colorsPerCell ? "cell" : "point") << "; got "
                  << colors->GetNumberOfComponents() << " components and "
                  << colors->GetNumberOfTuples() << " tuples for " << colorTuples << ".");
    return false;
  }
  Internals& in = *this->Internal;
  if (colors)
  {
    this->ColorsGiven = true;
  }
  else
  {
    this->ColorsMissing = true;
  }

  Internals::Source source;
  source.Init(input, radiusArray, scalarArray, colors, colorsPerCell, blockId, this->Radius,
    this->RadiusScale);
  in.HaveScalars = in.HaveScalars || scalarArray;

  vtkDataArray* originalIds = this->FindOriginalIds(input);

  // One pass over the polylines in parallel (vtkSMPTools): validate every
  // line and count the nodes it keeps (repeated consecutive points merged);
  // messages in line order.
  vtkCellArray* lines = source.Lines;
  const vtkIdType numLines = lines->GetNumberOfCells();
  using LineScan = Internals::LineScan;
  std::vector<LineScan> scans(static_cast<size_t>(numLines));
  vtkSMPThreadLocalObject<vtkIdList> scratch;
  vtkSMPThreadLocal<Box> nodeBoxes; // of the lines that become tubes
  vtkSMPTools::For(0, numLines,
    [&](vtkIdType begin, vtkIdType end)
    {
      vtkIdList* s = scratch.Local();
      double* nodeBox = nodeBoxes.Local().B;
      for (vtkIdType line = begin; line < end; ++line)
      {
        Box lineBox;
        source.ScanLine(line, s, scans[line],
          [&](vtkIdType, const double xyzr[4])
          {
            const double point[6] = { xyzr[0], xyzr[0], xyzr[1], xyzr[1], xyzr[2], xyzr[2] };
            AddBox(lineBox.B, point);
          });
        if (scans[line].Status == Internals::LINE_OK && scans[line].Kept >= 2)
        {
          AddBox(nodeBox, lineBox.B);
        }
      }
    });
  double nodeBounds[6];
  MergeBounds(nodeBoxes, nodeBounds);
  if (vtkMath::AreBoundsInitialized(nodeBounds))
  {
    if (!vtkMath::AreBoundsInitialized(this->NodeBounds))
    {
      std::copy(nodeBounds, nodeBounds + 6, this->NodeBounds);
    }
    AddBox(this->NodeBounds, nodeBounds);
  }

  const vtkIdType firstCellId = source.FirstCellId;
  const unsigned int sourceIndex = static_cast<unsigned int>(in.Sources.size());
  vtkIdType mergedHere = 0;
  vtkIdType shortLines = 0;
  std::vector<vtkIdType> mergedLines; // lines whose kept points are listed
  const vtkTypeInt64* offsets64 =
    lines->IsStorage64Bit() ? lines->GetOffsetsArray64()->GetPointer(0) : nullptr;
  const vtkTypeInt32* offsets32 =
    lines->IsStorage64Bit() ? nullptr : lines->GetOffsetsArray32()->GetPointer(0);
  for (vtkIdType line = 0; line < numLines; ++line)
  {
    const LineScan& scan = scans[line];
    const vtkIdType cellId = firstCellId + line;
    mergedHere += scan.Merged;
    if (scan.Status == Internals::LINE_NONFINITE_POINT)
    {
      vtkWarningMacro(<< "Polyline " << cellId << " skipped: point " << scan.BadPoint
                      << " has a NaN or infinite coordinate.");
      ++this->NumberOfSkippedLines;
      continue;
    }
    if (scan.Status == Internals::LINE_BAD_RADIUS)
    {
      vtkWarningMacro(<< "Polyline " << cellId << " skipped: point " << scan.BadPoint
                      << " has the radius " << scan.BadRadius
                      << " (radii must be finite and > 0).");
      ++this->NumberOfSkippedLines;
      continue;
    }
    if (scan.Status == Internals::LINE_BAD_SCALAR)
    {
      vtkWarningMacro(<< "Polyline " << cellId << " skipped: point " << scan.BadPoint
                      << " has a NaN or infinite value in the " << role << " array \""
                      << this->NodeScalarArray << "\".");
      ++this->NumberOfSkippedLines;
      continue;
    }
    if (scan.Kept < 2)
    {
      ++shortLines;
      ++this->NumberOfSkippedLines;
      continue;
    }
    Internals::Tube tube;
    tube.Source = sourceIndex;
    tube.Line = line;
    tube.ConnectivityOffset =
      offsets64 ? static_cast<vtkIdType>(offsets64[line]) : static_cast<vtkIdType>(offsets32[line]);
    tube.CellId =
      originalIds ? static_cast<vtkIdType>(originalIds->GetComponent(cellId, 0)) : cellId;
    if (scan.Merged > 0)
    {
      tube.Merged = static_cast<vtkIdType>(in.MergedPoints.size());
      in.MergedPoints.resize(in.MergedPoints.size() + static_cast<size_t>(scan.Kept));
      mergedLines.push_back(static_cast<vtkIdType>(in.Tubes.size()));
    }
    this->MaximumRadius = std::max(this->MaximumRadius, scan.MaxRadius);
    this->MaximumCellId = std::max(this->MaximumCellId, tube.CellId);
    in.Tubes.push_back(tube);
    in.TubeFirst.push_back(in.TubeFirst.back() + scan.Kept);
  }
  in.Sources.push_back(source);
  // The kept points of the tubes with merged points (few).
  vtkNew<vtkIdList> list;
  for (vtkIdType t : mergedLines)
  {
    vtkIdType k = in.Tubes[t].Merged;
    LineScan scan;
    source.ScanLine(in.Tubes[t].Line, list, scan,
      [&](vtkIdType pid, const double*) { in.MergedPoints[k++] = pid; });
  }

  if (mergedHere > 0)
  {
    vtkWarningMacro(<< mergedHere << " repeated consecutive point(s) merged.");
    this->NumberOfMergedPoints += mergedHere;
  }
  if (shortLines > 0)
  {
    vtkWarningMacro(<< shortLines
                    << " polyline(s) with fewer than two distinct points skipped (a tube "
                       "needs at least one segment).");
  }
  this->Modified();
  return true;
}

//------------------------------------------------------------------------------
void vtkSplineTubeCore::Build()
{
  if (this->ChunkTables)
  {
    this->BuildChunks();
  }
  else
  {
    this->BuildBounds();
  }
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkSplineTubeCore::GetNode(vtkIdType node, double xyzr[4]) const
{
  const Internals& in = *this->Internal;
  const vtkIdType t = in.TubeOfNode(node);
  in.Node(t, node - in.TubeFirst[t], xyzr);
}

//------------------------------------------------------------------------------
void vtkSplineTubeCore::GetTubeNode(vtkIdType tube, vtkIdType k, double xyzr[4]) const
{
  this->Internal->Node(tube, k, xyzr);
}

//------------------------------------------------------------------------------
void vtkSplineTubeCore::GetNodeDerivative(vtkIdType node, double dxyzr[4]) const
{
  const Internals& in = *this->Internal;
  const vtkIdType t = in.TubeOfNode(node);
  in.Nodes(t, node - in.TubeFirst[t], 1, nullptr, dxyzr);
}

//------------------------------------------------------------------------------
void vtkSplineTubeCore::GetTubeNodes(
  vtkIdType tube, vtkIdType first, vtkIdType count, double* xyzr, double* dxyzr) const
{
  this->Internal->Nodes(tube, first, count, xyzr, dxyzr);
}

//------------------------------------------------------------------------------
void vtkSplineTubeCore::GetNodeColor(vtkIdType node, double rgba[4]) const
{
  const Internals& in = *this->Internal;
  const vtkIdType t = in.TubeOfNode(node);
  const Internals::Source& s = in.Sources[in.Tubes[t].Source];
  if (!s.Colors)
  {
    std::fill(rgba, rgba + 4, 1.0);
    return;
  }
  const vtkIdType tuple =
    s.ColorsPerCell ? s.FirstCellId + in.Tubes[t].Line : in.PointId(t, node - in.TubeFirst[t]);
  const unsigned char* c = s.Colors->GetPointer(4 * tuple);
  for (int k = 0; k < 4; ++k)
  {
    rgba[k] = c[k] / 255.0;
  }
}

//------------------------------------------------------------------------------
double vtkSplineTubeCore::GetNodeScalar(vtkIdType node) const
{
  const Internals& in = *this->Internal;
  const vtkIdType t = in.TubeOfNode(node);
  const Internals::Source& s = in.Sources[in.Tubes[t].Source];
  return s.Scalar ? s.Scalar->GetComponent(in.PointId(t, node - in.TubeFirst[t]), 0) : 0.0;
}

//------------------------------------------------------------------------------
vtkIdType vtkSplineTubeCore::GetSegmentFirstNode(vtkIdType segment) const
{
  return segment + this->Internal->TubeOfSegment(segment);
}

//------------------------------------------------------------------------------
int vtkSplineTubeCore::GetSegmentFlags(vtkIdType segment) const
{
  const Internals& in = *this->Internal;
  const vtkIdType t = in.TubeOfSegment(segment);
  const vtkIdType k = segment - (in.TubeFirst[t] - t);
  const vtkIdType n = in.TubeFirst[t + 1] - in.TubeFirst[t];
  return (k == 0 ? TUBE_START : 0) | (k == n - 2 ? TUBE_END : 0);
}

//------------------------------------------------------------------------------
void vtkSplineTubeCore::EvaluateSegment(vtkIdType segment, double t, double position[3],
  double derivative[3], double* radius, double* radiusDerivative) const
{
  const Internals& in = *this->Internal;
  const vtkIdType tube = in.TubeOfSegment(segment);
  double p[8];
  double m[8];
  in.Nodes(tube, segment - (in.TubeFirst[tube] - tube), 2, p, m);
  const vec4 p0(p[0], p[1], p[2], p[3]);
  const vec4 m0(m[0], m[1], m[2], m[3]);
  const vec4 p1(p[4], p[5], p[6], p[7]);
  const vec4 m1(m[4], m[5], m[6], m[7]);
  const vec4 c = vtkSplineTubeMath::svHermite(p0, m0, p1, m1, t);
  const vec4 d = vtkSplineTubeMath::svHermiteDerivative(p0, m0, p1, m1, t);
  if (position)
  {
    position[0] = c.x;
    position[1] = c.y;
    position[2] = c.z;
  }
  if (derivative)
  {
    derivative[0] = d.x;
    derivative[1] = d.y;
    derivative[2] = d.z;
  }
  if (radius)
  {
    *radius = c.w;
  }
  if (radiusDerivative)
  {
    *radiusDerivative = d.w;
  }
}

//------------------------------------------------------------------------------
void vtkSplineTubeCore::FillNodes(
  vtkIdType first, vtkIdType count, const double shift[3], float* out, int components) const
{
  const Internals& in = *this->Internal;
  const bool withRadius = components >= 4;
  const vtkIdType stride = withRadius ? 4 : 3;
  in.ForNodes(first, count,
    [&](vtkIdType t, vtkIdType b, vtkIdType e)
    {
      for (vtkIdType node = b; node < e; ++node)
      {
        double p[4];
        in.Node(t, node - in.TubeFirst[t], p);
        float* o = out + stride * (node - first);
        for (int c = 0; c < 3; ++c)
        {
          o[c] = static_cast<float>(p[c] - shift[c]);
        }
        if (withRadius)
        {
          o[3] = static_cast<float>(p[3]);
        }
      }
    });
}

//------------------------------------------------------------------------------
void vtkSplineTubeCore::FillNodeInfo(vtkIdType first, vtkIdType count, unsigned int* info) const
{
  const Internals& in = *this->Internal;
  in.ForNodes(first, count,
    [&](vtkIdType t, vtkIdType b, vtkIdType e)
    {
      const vtkIdType firstNode = in.TubeFirst[t];
      const vtkIdType lastNode = in.TubeFirst[t + 1] - 1;
      for (vtkIdType node = b; node < e; ++node)
      {
        info[node - first] = (static_cast<unsigned int>(t) & NODE_TUBE_MASK) |
          (node == firstNode ? NODE_FIRST : 0u) | (node == lastNode ? NODE_LAST : 0u);
      }
    });
}

//------------------------------------------------------------------------------
void vtkSplineTubeCore::FillColors(vtkIdType first, vtkIdType count, unsigned int* rgba) const
{
  const Internals& in = *this->Internal;
  in.ForNodes(first, count,
    [&](vtkIdType t, vtkIdType b, vtkIdType e)
    {
      const Internals::Source& s = in.Sources[in.Tubes[t].Source];
      for (vtkIdType node = b; node < e; ++node)
      {
        unsigned int word = 0xFFFFFFFFu;
        if (s.Colors)
        {
          const vtkIdType tuple = s.ColorsPerCell ? s.FirstCellId + in.Tubes[t].Line
                                                  : in.PointId(t, node - in.TubeFirst[t]);
          const unsigned char* c = s.Colors->GetPointer(4 * tuple);
          word = static_cast<unsigned int>(c[0]) | (static_cast<unsigned int>(c[1]) << 8) |
            (static_cast<unsigned int>(c[2]) << 16) | (static_cast<unsigned int>(c[3]) << 24);
        }
        rgba[node - first] = word;
      }
    });
}

//------------------------------------------------------------------------------
void vtkSplineTubeCore::FillScalars(vtkIdType first, vtkIdType count, float* scalars) const
{
  const Internals& in = *this->Internal;
  in.ForNodes(first, count,
    [&](vtkIdType t, vtkIdType b, vtkIdType e)
    {
      const Internals::Source& s = in.Sources[in.Tubes[t].Source];
      for (vtkIdType node = b; node < e; ++node)
      {
        scalars[node - first] = s.Scalar
          ? static_cast<float>(s.Scalar->GetComponent(in.PointId(t, node - in.TubeFirst[t]), 0))
          : 0.0f;
      }
    });
}

//------------------------------------------------------------------------------
void vtkSplineTubeCore::PropagateFrames(vtkIdType t, vtkIdType n,
  const std::function<void(vtkIdType k, const double frame[3])>& write) const
{
  // The tube's first n nodes (at least two) and their derivatives.
  const Internals& in = *this->Internal;
  const vtkIdType total = in.TubeFirst[t + 1] - in.TubeFirst[t];
  n = std::min(total, std::max<vtkIdType>(n, 2));
  std::vector<double> p(static_cast<size_t>(4 * n));
  std::vector<double> m(static_cast<size_t>(4 * n));
  in.Nodes(t, 0, n, p.data(), m.data());
  auto node = [&](vtkIdType i) { return vec3(p[4 * i], p[4 * i + 1], p[4 * i + 2]); };
  auto deriv = [&](vtkIdType i) { return vec3(m[4 * i], m[4 * i + 1], m[4 * i + 2]); };
  auto emit = [&](vtkIdType k, const vec3& r)
  {
    const double frame[3] = { r.x, r.y, r.z };
    write(k, frame);
  };
  const double maxAngle = this->MaximumFrameStepAngle;
  // The cubic Hermite segment s in power form, set once per segment:
  // position c0 + u c1 + u^2 c2 + u^3 c3, derivative c1 + 2u c2 + 3u^2 c3
  // (the same curve as vtkSplineTubeMath::svHermite; evaluating the basis
  // functions per sample was most of the first frame's frame propagation).
  vec3 c0, c1, c2, c3, chord;
  auto setSegment = [&](vtkIdType s)
  {
    const vec3 p0 = node(s), p1 = node(s + 1), m0 = deriv(s), m1 = deriv(s + 1);
    chord = p1 - p0;
    c0 = p0;
    c1 = m0;
    c2 = 3.0 * chord - 2.0 * m0 - m1;
    c3 = -2.0 * chord + m0 + m1;
  };
  auto position = [&](double u) { return c0 + u * (c1 + u * (c2 + u * c3)); };
  // Unit tangent at parameter u; the chord where the derivative vanishes (a
  // cusp of the spline).
  auto unitTangent = [&](double u)
  {
    vec3 d = c1 + u * (2.0 * c2 + u * (3.0 * c3));
    double len = glm::length(d);
    if (len < 1e-12)
    {
      d = chord;
      len = glm::length(d);
    }
    return len > 0.0 ? d / len : vec3(1.0, 0.0, 0.0);
  };
  setSegment(0);
  vec3 tangent = unitTangent(0.0);
  vec3 r = vtkSplineTubeMath::svAnyOrthogonal(tangent);
  emit(0, r);
  // A segment turns by less than maxAngle when the two angles of its
  // hodograph's control polygon (m0, 3 chord - m0 - m1, m1: the derivative
  // is the quadratic Bezier curve of these) are each below maxAngle / 2: the
  // tangents' directions then lie on a convex spherical arc inside that
  // polygon's, which is no longer. Tested with dot products only (cos^2 of
  // the angles), no square root: most segments of smooth lines pass and take
  // one step without sampling their tangent.
  const double cosHalf = std::cos(0.5 * std::min(maxAngle, 1.0));
  const double cosHalf2 = cosHalf * cosHalf;
  auto within = [&](const vec3& a, const vec3& b)
  {
    const double ab = glm::dot(a, b);
    return ab > 0.0 && ab * ab > cosHalf2 * glm::dot(a, a) * glm::dot(b, b);
  };
  for (vtkIdType s = 0; s + 1 < n; ++s)
  {
    setSegment(s);
    const vec3 h1 = c2 + c1; // 3 chord - m0 - m1
    int steps = 1;
    vec3 prev;
    if (within(c1, h1) && within(h1, deriv(s + 1)))
    {
      prev = glm::normalize(deriv(s + 1));
    }
    else
    {
      // Sub-steps: sample the tangent densely enough that no step turns it
      // by more than maxAngle (the total turning is estimated on 4 samples;
      // it only sets the step count: TestSplineTubeCore's frames agree with
      // the reference as closely as with 8 samples).
      double turning = 0.0;
      prev = tangent;
      for (int k = 1; k <= 4; ++k)
      {
        const vec3 cur = unitTangent(k / 4.0);
        // The angle between unit vectors from their distance c: 2 asin(c / 2),
        // by its series below c = 1 (relative error under 1e-3; acos was a
        // fifth of the first frame's CPU time on whole-brain tractograms).
        const double c = glm::length(cur - prev);
        const double cc = c * c;
        turning += c < 1.0 ? c * (1.0 + cc * (1.0 / 24.0 + cc * (3.0 / 640.0)))
                           : 2.0 * std::asin(std::min(1.0, 0.5 * c));
        prev = cur;
      }
      steps = std::max(1, std::min(256, static_cast<int>(std::ceil(turning / maxAngle))));
    }
    vec3 x = c0;
    for (int k = 1; k <= steps; ++k)
    {
      // The segment's end exactly at its node; its tangent there is the
      // last turning sample.
      const double u = static_cast<double>(k) / steps;
      const vec3 x1 = k == steps ? node(s + 1) : position(u);
      const vec3 t1 = k == steps ? prev : unitTangent(u);
      r = DoubleReflection(x, tangent, r, x1, t1);
      x = x1;
      tangent = t1;
    }
    emit(s + 1, r);
  }
}

//------------------------------------------------------------------------------
void vtkSplineTubeCore::GetTubeFrames(vtkIdType tube, double* frames) const
{
  this->PropagateFrames(tube, this->GetTubeNumberOfNodes(tube),
    [&](vtkIdType k, const double frame[3]) { std::copy(frame, frame + 3, frames + 3 * k); });
}

//------------------------------------------------------------------------------
void vtkSplineTubeCore::FillFrames(vtkIdType first, vtkIdType count, short* octahedral) const
{
  const Internals& in = *this->Internal;
  in.ForNodes(first, count,
    [&](vtkIdType t, vtkIdType b, vtkIdType e)
    {
      // Propagated from the tube's first node; written for [b, e).
      const vtkIdType firstNode = in.TubeFirst[t];
      this->PropagateFrames(t, e - firstNode,
        [&](vtkIdType k, const double frame[3])
        {
          const vtkIdType node = firstNode + k;
          if (node >= b && node < e)
          {
            vtkSplineTubeMath::svOctEncodeInt16(
              vec3(frame[0], frame[1], frame[2]), octahedral + 2 * (node - first));
          }
        });
    });
}

//------------------------------------------------------------------------------
void vtkSplineTubeCore::BuildChunks()
{
  const Internals& in = *this->Internal;
  const vtkIdType numTubes = this->GetNumberOfTubes();
  const vtkIdType numSegments = this->GetNumberOfSegments();
  this->TubeFirstChunks->SetNumberOfTuples(numTubes + 1);
  vtkIdType* tubeFirstChunk = this->TubeFirstChunks->GetPointer(0);
  tubeFirstChunk[0] = 0;
  for (vtkIdType t = 0; t < numTubes; ++t)
  {
    const vtkIdType segments = in.TubeFirst[t + 1] - in.TubeFirst[t] - 1;
    tubeFirstChunk[t + 1] = tubeFirstChunk[t] + (segments + ChunkSegments - 1) / ChunkSegments;
  }
  const vtkIdType numChunks = tubeFirstChunk[numTubes];
  this->ChunkFirstSegments->SetNumberOfTuples(numChunks + 1);
  this->ChunkTubes->SetNumberOfTuples(numChunks);
  this->ChunkSpheres->SetNumberOfTuples(numChunks);
  this->ChunkSizes->SetNumberOfTuples(numChunks);
  this->SegmentSpheres->SetNumberOfTuples(numSegments);
  this->ChunkStraightness->SetNumberOfTuples(numChunks);
  vtkMath::UninitializeBounds(this->Bounds);
  if (numChunks == 0)
  {
    this->ChunkFirstSegments->SetValue(0, 0);
    return;
  }
  vtkTypeUInt32* chunkFirst = this->ChunkFirstSegments->GetPointer(0);
  vtkTypeUInt32* chunkTube = this->ChunkTubes->GetPointer(0);
  float* spheres = this->ChunkSpheres->GetPointer(0);
  float* sizes = this->ChunkSizes->GetPointer(0);
  vtkTypeUInt32* segmentSpheres = this->SegmentSpheres->GetPointer(0);
  float* straightness = this->ChunkStraightness->GetPointer(0);

  // One pass over the tubes (the centre, the spheres' origin, is known from
  // AddPolyData()): per chunk its segments' boxes, from them its box, sizes
  // and sphere, then its segments' spheres relative to the chunk's; the
  // bounds by thread.
  double center[3];
  this->GetCenter(center);
  ForEachTubeNodes(in, numTubes, this->Bounds,
    [&](NodesAndBox& local, vtkIdType t, vtkIdType n)
    {
      vtkIdType k = 0; // segment of the tube
      for (vtkIdType c = tubeFirstChunk[t]; c < tubeFirstChunk[t + 1]; ++c)
      {
        const vtkIdType firstSegment = in.TubeFirst[t] - t + k;
        chunkFirst[c] = static_cast<vtkTypeUInt32>(firstSegment);
        chunkTube[c] = static_cast<vtkTypeUInt32>(t);
        double segmentBounds[ChunkSegments][6];
        Box box;
        double length = 0.0;
        double maxLength = 0.0;
        double maxRadius = 0.0;
        double chunkStraightness[4] = { 0.0, 0.0, 0.0, 0.0 };
        const vtkIdType stop = std::min<vtkIdType>(n - 1, k + ChunkSegments);
        const vtkIdType chunkSegments = stop - k;
        for (vtkIdType j = 0; j < chunkSegments; ++j, ++k)
        {
          double control[4][3];
          double r = 0.0;
          SegmentBox(local.P.data(), local.M.data(), k, segmentBounds[j], control, r);
          AddBox(box.B, segmentBounds[j]);
          double polygon = 0.0;
          for (int q = 0; q < 3; ++q)
          {
            polygon += std::sqrt(vtkMath::Distance2BetweenPoints(control[q], control[q + 1]));
          }
          length += polygon;
          maxLength = std::max(maxLength, polygon);
          maxRadius = std::max(maxRadius, r);
          GrowStraightness(local.P.data(), local.M.data(), k, chunkStraightness);
        }
        for (int q = 0; q < 4; ++q)
        {
          straightness[4 * c + q] =
            static_cast<float>(std::min(chunkStraightness[q], double(VTK_FLOAT_MAX)));
        }
        AddBox(local.B, box.B);
        sizes[3 * c] = static_cast<float>(length);
        sizes[3 * c + 1] = static_cast<float>(maxLength);
        sizes[3 * c + 2] = static_cast<float>(maxRadius);

        // The sphere around the box, relative to the centre (rounding to
        // float covered by a relative margin), and the segments' spheres.
        double radius2 = 0.0;
        double extent = 0.0;
        for (int q = 0; q < 3; ++q)
        {
          const double mid = 0.5 * (box.B[2 * q] + box.B[2 * q + 1]);
          spheres[4 * c + q] = static_cast<float>(mid - center[q]);
          radius2 += 0.25 * (box.B[2 * q + 1] - box.B[2 * q]) * (box.B[2 * q + 1] - box.B[2 * q]);
          extent = std::max(extent, std::abs(mid - center[q]));
        }
        const double radius = std::sqrt(radius2);
        spheres[4 * c + 3] = static_cast<float>(radius + 1e-6 * (radius + extent));
        for (vtkIdType j = 0; j < chunkSegments; ++j)
        {
          const double* b = segmentBounds[j];
          double part[4];
          double partRadius2 = 0.0;
          for (int q = 0; q < 3; ++q)
          {
            part[q] = 0.5 * (b[2 * q] + b[2 * q + 1]) - center[q];
            partRadius2 += 0.25 * (b[2 * q + 1] - b[2 * q]) * (b[2 * q + 1] - b[2 * q]);
          }
          part[3] = std::sqrt(partRadius2) * (1.0 + 1e-6) + 1e-6 * extent;
          segmentSpheres[firstSegment + j] =
            vtkSplineTubeVisibility::EncodePart(spheres + 4 * c, part);
        }
      }
    });
  chunkFirst[numChunks] = static_cast<vtkTypeUInt32>(numSegments);
}

//------------------------------------------------------------------------------
void vtkSplineTubeCore::BuildBounds()
{
  const Internals& in = *this->Internal;
  for (vtkDataArray* table :
    std::initializer_list<vtkDataArray*>{ this->TubeFirstChunks, this->ChunkTubes,
      this->ChunkSpheres, this->ChunkSizes, this->SegmentSpheres, this->ChunkStraightness })
  {
    table->Initialize();
  }
  this->ChunkFirstSegments->SetNumberOfTuples(1);
  this->ChunkFirstSegments->SetValue(0, 0);
  vtkMath::UninitializeBounds(this->Bounds);
  const vtkIdType numTubes = this->GetNumberOfTubes();
  if (numTubes == 0)
  {
    return;
  }
  // The same boxes as the chunk table's spheres contain, by thread.
  ForEachTubeNodes(in, numTubes, this->Bounds,
    [](NodesAndBox& local, vtkIdType, vtkIdType n)
    {
      for (vtkIdType k = 0; k + 1 < n; ++k)
      {
        double box[6];
        double control[4][3];
        double r = 0.0;
        SegmentBox(local.P.data(), local.M.data(), k, box, control, r);
        AddBox(local.B, box);
      }
    });
}

//------------------------------------------------------------------------------
void vtkSplineTubeCore::GetCenter(double center[3]) const
{
  for (int k = 0; k < 3; ++k)
  {
    center[k] = vtkMath::AreBoundsInitialized(this->NodeBounds)
      ? 0.5 * (this->NodeBounds[2 * k] + this->NodeBounds[2 * k + 1])
      : 0.0;
  }
}

//------------------------------------------------------------------------------
void vtkSplineTubeCore::GetBounds(double bounds[6]) const
{
  std::copy(this->Bounds, this->Bounds + 6, bounds);
}

//------------------------------------------------------------------------------
size_t vtkSplineTubeCore::GetMemorySize() const
{
  const Internals& in = *this->Internal;
  return in.Tubes.size() * sizeof(Internals::Tube) + in.TubeFirst.size() * sizeof(vtkIdType) +
    in.MergedPoints.size() * sizeof(vtkIdType) +
    static_cast<size_t>(this->TubeFirstChunks->GetActualMemorySize() +
      this->ChunkFirstSegments->GetActualMemorySize() + this->ChunkTubes->GetActualMemorySize() +
      this->ChunkSpheres->GetActualMemorySize() + this->ChunkSizes->GetActualMemorySize() +
      this->SegmentSpheres->GetActualMemorySize() +
      this->ChunkStraightness->GetActualMemorySize()) *
    1024;
}

//------------------------------------------------------------------------------
void vtkSplineTubeCore::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Radius: " << this->Radius << "\n";
  os << indent << "RadiusArray: " << (this->RadiusArray ? this->RadiusArray : "(none)") << "\n";
  os << indent << "NodeScalarArray: " << (this->NodeScalarArray ? this->NodeScalarArray : "(none)")
     << "\n";
  os << indent << "CellIdArray: " << (this->CellIdArray ? this->CellIdArray : "(none)") << "\n";
  os << indent << "RadiusScale: " << this->RadiusScale << "\n";
  os << indent << "MaximumFrameStepAngle: " << this->MaximumFrameStepAngle << "\n";
  os << indent << "ChunkTables: " << (this->ChunkTables ? "On" : "Off") << "\n";
  os << indent << "NumberOfTubes: " << this->GetNumberOfTubes() << "\n";
  os << indent << "NumberOfNodes: " << this->GetNumberOfNodes() << "\n";
  os << indent << "NumberOfSegments: " << this->GetNumberOfSegments() << "\n";
  os << indent << "NumberOfChunks: " << this->GetNumberOfChunks() << "\n";
  os << indent << "NumberOfSkippedLines: " << this->NumberOfSkippedLines << "\n";
  os << indent << "NumberOfMergedPoints: " << this->NumberOfMergedPoints << "\n";
}
