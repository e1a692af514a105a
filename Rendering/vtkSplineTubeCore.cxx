#include "vtkSplineTubeCore.h"

#include "vtkSplineTubeMath.h"
#include "vtkSplineTubeVisibility.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
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
#include "vtkTypeUInt32Array.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
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

/// Central differences inside, second-order one-sided differences at the ends
/// (first-order for two values): the derivative of `n` values with `comps`
/// components each, in place into `out`.
void FiniteDifferences(const float* values, float* out, vtkIdType n, int comps)
{
  for (int c = 0; c < comps; ++c)
  {
    auto v = [&](vtkIdType i) { return static_cast<double>(values[i * comps + c]); };
    if (n == 1)
    {
      out[c] = 0.0f;
      continue;
    }
    if (n == 2)
    {
      const float d = static_cast<float>(v(1) - v(0));
      out[c] = d;
      out[comps + c] = d;
      continue;
    }
    out[c] = static_cast<float>(0.5 * (-3.0 * v(0) + 4.0 * v(1) - v(2)));
    for (vtkIdType i = 1; i + 1 < n; ++i)
    {
      out[i * comps + c] = static_cast<float>(0.5 * (v(i + 1) - v(i - 1)));
    }
    out[(n - 1) * comps + c] =
      static_cast<float>(0.5 * (3.0 * v(n - 1) - 4.0 * v(n - 2) + v(n - 3)));
  }
}

/// One double-reflection step of the rotation-minimizing frame (Wang et al.
/// 2008): carries the unit normal `r0` at (x0, t0) to the point x1 with unit
/// tangent t1.
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
}

//------------------------------------------------------------------------------
vtkSplineTubeCore::vtkSplineTubeCore()
{
  this->NodePositions->SetNumberOfComponents(3);
  this->NodePositions->SetName("Positions");
  this->NodeTangents->SetNumberOfComponents(3);
  this->NodeTangents->SetName("Tangents");
  this->NodeRadii->SetNumberOfComponents(2);
  this->NodeRadii->SetName("Radii");
  this->NodeColors->SetNumberOfComponents(4);
  this->NodeColors->SetName("Colors");
  this->NodeColorDerivatives->SetNumberOfComponents(4);
  this->NodeColorDerivatives->SetName("ColorDerivatives");
  this->NodeFrames->SetNumberOfComponents(3);
  this->NodeFrames->SetName("Frames");
  this->NodeScalars->SetNumberOfComponents(1);
  this->NodeScalars->SetName("Scalars");
  this->SegmentFirstNodes->SetName("SegmentFirstNodes");
  this->SegmentFlags->SetName("SegmentFlags");
  this->SegmentCellIds->SetName("SegmentCellIds");
  this->SegmentBlockIds->SetName("SegmentBlockIds");
  this->TubeFirstNodes->SetName("TubeFirstNodes");
  this->TubeNumberOfNodes->SetName("TubeNumberOfNodes");
  this->TubeFirstChunks->SetName("TubeFirstChunks");
  this->ChunkFirstSegments->SetName("ChunkFirstSegments");
  this->ChunkTubes->SetName("ChunkTubes");
  this->ChunkSpheres->SetNumberOfComponents(4);
  this->ChunkSpheres->SetName("ChunkSpheres");
  this->ChunkSizes->SetNumberOfComponents(3);
  this->ChunkSizes->SetName("ChunkSizes");
}

//------------------------------------------------------------------------------
vtkSplineTubeCore::~vtkSplineTubeCore()
{
  this->SetRadiusArrayName(nullptr);
  this->SetNodeScalarArrayName(nullptr);
  this->SetNodeScalarRole(nullptr);
  this->SetCellIdArrayName(nullptr);
}

//------------------------------------------------------------------------------
void vtkSplineTubeCore::Initialize()
{
  this->NodePositions->SetNumberOfTuples(0);
  this->NodeTangents->SetNumberOfTuples(0);
  this->NodeRadii->SetNumberOfTuples(0);
  this->NodeColors->SetNumberOfTuples(0);
  this->NodeColorDerivatives->SetNumberOfTuples(0);
  this->NodeFrames->SetNumberOfTuples(0);
  this->NodeScalars->SetNumberOfTuples(0);
  this->SegmentFirstNodes->SetNumberOfTuples(0);
  this->SegmentFlags->SetNumberOfTuples(0);
  this->SegmentCellIds->SetNumberOfTuples(0);
  this->SegmentBlockIds->SetNumberOfTuples(0);
  this->TubeFirstNodes->SetNumberOfTuples(0);
  this->TubeNumberOfNodes->SetNumberOfTuples(0);
  this->TubeFirstChunks->SetNumberOfTuples(0);
  this->ChunkFirstSegments->SetNumberOfTuples(0);
  this->ChunkTubes->SetNumberOfTuples(0);
  this->ChunkSpheres->SetNumberOfTuples(0);
  this->ChunkSizes->SetNumberOfTuples(0);
  this->SegmentSpheres->SetNumberOfTuples(0);
  vtkMath::UninitializeBounds(this->Bounds);
  this->ColorsGiven = false;
  this->ColorsMissing = false;
  this->MaximumRadius = 0.0;
  this->NumberOfSkippedLines = 0;
  this->NumberOfMergedPoints = 0;
  this->Modified();
}

//------------------------------------------------------------------------------
vtkIdType vtkSplineTubeCore::GetNumberOfTubes() const
{
  return this->TubeFirstNodes->GetNumberOfTuples();
}

vtkIdType vtkSplineTubeCore::GetNumberOfNodes() const
{
  return this->NodePositions->GetNumberOfTuples();
}

vtkIdType vtkSplineTubeCore::GetNumberOfSegments() const
{
  return this->SegmentFirstNodes->GetNumberOfTuples();
}

vtkIdType vtkSplineTubeCore::GetNumberOfChunks() const
{
  return this->ChunkTubes->GetNumberOfTuples();
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

  // A named one-component numeric point array, or an error.
  auto findArray = [&](const char* name, const char* what, vtkDataArray*& array)
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
  };
  vtkDataArray* radiusArray = nullptr;
  vtkDataArray* scalarArray = nullptr;
  if (!findArray(this->RadiusArrayName, "radius", radiusArray) ||
    !findArray(this->NodeScalarArrayName,
      this->NodeScalarRole ? this->NodeScalarRole : "node scalar", scalarArray))
  {
    return false;
  }
  if (colors && (colors->GetNumberOfComponents() != 4 || colors->GetNumberOfTuples() < numPoints))
  {
    vtkErrorMacro(<< "Colors must be RGBA (4 components) with one tuple per point; got "
                  << colors->GetNumberOfComponents() << " components and "
                  << colors->GetNumberOfTuples() << " tuples for " << numPoints << " points.");
    return false;
  }
  if (colors)
  {
    this->ColorsGiven = true;
  }
  else
  {
    this->ColorsMissing = true;
  }

  // Two passes over the polylines, both parallel (vtkSMPTools): the first
  // validates every line and counts the nodes it keeps; the offsets then
  // place each line's nodes and segments, and the second pass writes them.
  // Output order and messages are those of a sequential scan.
  vtkPoints* points = input->GetPoints();
  vtkCellArray* lines = input->GetLines();
  const vtkIdType numLines = lines->GetNumberOfCells();
  const vtkIdType firstCellId = input->GetNumberOfVerts(); // line cell ids follow the verts
  // Original cell ids, when the input carries them (one component, integer).
  vtkDataArray* originalIds = nullptr;
  if (this->CellIdArrayName && this->CellIdArrayName[0])
  {
    originalIds = input->GetCellData()->GetArray(this->CellIdArrayName);
    if (originalIds &&
      (originalIds->GetNumberOfComponents() != 1 ||
        vtkDataArray::GetDataTypeMin(originalIds->GetDataType()) == VTK_DOUBLE_MIN ||
        vtkDataArray::GetDataTypeMin(originalIds->GetDataType()) == VTK_FLOAT_MIN ||
        originalIds->GetNumberOfTuples() != input->GetNumberOfCells()))
    {
      originalIds = nullptr;
    }
  }
  const double constantRadius = this->Radius;
  const double radiusScale = this->RadiusScale;

  enum LineStatus : unsigned char
  {
    LINE_OK,
    LINE_NONFINITE_POINT,
    LINE_BAD_RADIUS,
    LINE_BAD_SCALAR,
  };
  struct LineScan
  {
    vtkIdType Kept = 0;
    vtkIdType Merged = 0;
    vtkIdType BadPoint = -1;
    double BadRadius = 0.0;
    unsigned char Status = LINE_OK;
  };
  // Scans line `line`: calls keep(pointId, position, radius) for every node
  // kept (repeated consecutive points merged); stops at the first point with
  // a non-finite coordinate or radius.
  auto scanLine = [&](vtkIdType line, vtkIdList* scratch, LineScan& scan, auto&& keep)
  {
    vtkIdType npts;
    const vtkIdType* pts;
    lines->GetCellAtId(line, npts, pts, scratch);
    double last[3] = { 0.0, 0.0, 0.0 };
    for (vtkIdType k = 0; k < npts; ++k)
    {
      double p[3];
      points->GetPoint(pts[k], p);
      if (!IsFinite(p[0]) || !IsFinite(p[1]) || !IsFinite(p[2]))
      {
        scan.Status = LINE_NONFINITE_POINT;
        scan.BadPoint = pts[k];
        return;
      }
      double r = constantRadius;
      if (radiusArray)
      {
        r = radiusArray->GetComponent(pts[k], 0) * radiusScale;
        if (!IsFinite(r) || r <= 0.0)
        {
          scan.Status = LINE_BAD_RADIUS;
          scan.BadPoint = pts[k];
          scan.BadRadius = r;
          return;
        }
      }
      if (scalarArray && !IsFinite(scalarArray->GetComponent(pts[k], 0)))
      {
        scan.Status = LINE_BAD_SCALAR;
        scan.BadPoint = pts[k];
        return;
      }
      // Merge repeated consecutive points (the spline needs distinct nodes).
      if (scan.Kept > 0)
      {
        const double d2 = vtkMath::Distance2BetweenPoints(p, last);
        const double scale = std::max({ std::abs(p[0]), std::abs(p[1]), std::abs(p[2]), r });
        if (d2 <= (1e-10 * scale) * (1e-10 * scale))
        {
          ++scan.Merged;
          continue;
        }
      }
      keep(pts[k], p, r, scan.Kept);
      ++scan.Kept;
      std::copy(p, p + 3, last);
    }
  };

  std::vector<LineScan> scans(static_cast<size_t>(numLines));
  vtkSMPThreadLocalObject<vtkIdList> scratch1;
  vtkSMPTools::For(0, numLines,
    [&](vtkIdType begin, vtkIdType end)
    {
      vtkIdList* scratch = scratch1.Local();
      for (vtkIdType line = begin; line < end; ++line)
      {
        scanLine(line, scratch, scans[line], [](vtkIdType, const double*, double, vtkIdType) {});
      }
    });

  // Offsets of the lines that become tubes; messages in line order.
  const vtkIdType nodesBefore = this->NodePositions->GetNumberOfTuples();
  const vtkIdType segmentsBefore = this->SegmentFirstNodes->GetNumberOfTuples();
  const vtkIdType tubesBefore = this->TubeFirstNodes->GetNumberOfTuples();
  std::vector<vtkIdType> tubeOf(static_cast<size_t>(numLines), -1);
  std::vector<vtkIdType> nodeOffset(static_cast<size_t>(numLines), 0);
  vtkIdType mergedHere = 0;
  vtkIdType shortLines = 0;
  vtkIdType numNodes = nodesBefore;
  vtkIdType numTubes = tubesBefore;
  for (vtkIdType line = 0; line < numLines; ++line)
  {
    const LineScan& scan = scans[line];
    const vtkIdType cellId = firstCellId + line;
    mergedHere += scan.Merged;
    if (scan.Status == LINE_NONFINITE_POINT)
    {
      vtkWarningMacro(<< "Polyline " << cellId << " skipped: point " << scan.BadPoint
                      << " has a NaN or infinite coordinate.");
      ++this->NumberOfSkippedLines;
      continue;
    }
    if (scan.Status == LINE_BAD_RADIUS)
    {
      vtkWarningMacro(<< "Polyline " << cellId << " skipped: point " << scan.BadPoint
                      << " has the radius " << scan.BadRadius
                      << " (radii must be finite and > 0).");
      ++this->NumberOfSkippedLines;
      continue;
    }
    if (scan.Status == LINE_BAD_SCALAR)
    {
      vtkWarningMacro(<< "Polyline " << cellId << " skipped: point " << scan.BadPoint
                      << " has a NaN or infinite value in the "
                      << (this->NodeScalarRole ? this->NodeScalarRole : "node scalar")
                      << " array \"" << this->NodeScalarArrayName << "\".");
      ++this->NumberOfSkippedLines;
      continue;
    }
    if (scan.Kept < 2)
    {
      ++shortLines;
      ++this->NumberOfSkippedLines;
      continue;
    }
    tubeOf[line] = numTubes++;
    nodeOffset[line] = numNodes;
    numNodes += scan.Kept;
  }
  const vtkIdType numSegments =
    segmentsBefore + (numNodes - nodesBefore) - (numTubes - tubesBefore);

  // Grow keeping what earlier calls added: Resize() keeps the values,
  // SetNumberOfTuples() alone may reallocate without them (VTK 9.2).
  this->NodePositions->Resize(numNodes);
  this->NodePositions->SetNumberOfTuples(numNodes);
  this->NodeRadii->Resize(numNodes);
  this->NodeRadii->SetNumberOfTuples(numNodes);
  this->NodeColors->Resize(numNodes);
  this->NodeColors->SetNumberOfTuples(numNodes);
  if (scalarArray)
  {
    this->NodeScalars->Resize(numNodes);
    this->NodeScalars->SetNumberOfTuples(numNodes);
  }
  this->SegmentFirstNodes->Resize(numSegments);
  this->SegmentFirstNodes->SetNumberOfTuples(numSegments);
  this->SegmentFlags->Resize(numSegments);
  this->SegmentFlags->SetNumberOfTuples(numSegments);
  this->SegmentCellIds->Resize(numSegments);
  this->SegmentCellIds->SetNumberOfTuples(numSegments);
  this->SegmentBlockIds->Resize(numSegments);
  this->SegmentBlockIds->SetNumberOfTuples(numSegments);
  this->TubeFirstNodes->Resize(numTubes);
  this->TubeFirstNodes->SetNumberOfTuples(numTubes);
  this->TubeNumberOfNodes->Resize(numTubes);
  this->TubeNumberOfNodes->SetNumberOfTuples(numTubes);

  float* positions = this->NodePositions->GetPointer(0);
  float* radii = this->NodeRadii->GetPointer(0);
  float* nodeColors = this->NodeColors->GetPointer(0);
  float* nodeScalars = scalarArray ? this->NodeScalars->GetPointer(0) : nullptr;
  vtkTypeUInt32* segmentFirst = this->SegmentFirstNodes->GetPointer(0);
  unsigned char* segmentFlags = this->SegmentFlags->GetPointer(0);
  vtkIdType* segmentCells = this->SegmentCellIds->GetPointer(0);
  vtkTypeUInt32* segmentBlocks = this->SegmentBlockIds->GetPointer(0);
  vtkIdType* tubeFirst = this->TubeFirstNodes->GetPointer(0);
  vtkIdType* tubeNodes = this->TubeNumberOfNodes->GetPointer(0);
  const unsigned char* colorBytes = colors ? colors->GetPointer(0) : nullptr;

  vtkSMPThreadLocalObject<vtkIdList> scratch2;
  vtkSMPThreadLocal<double> maxRadius(0.0);
  vtkSMPTools::For(0, numLines,
    [&](vtkIdType begin, vtkIdType end)
    {
      vtkIdList* scratch = scratch2.Local();
      double& rMax = maxRadius.Local();
      for (vtkIdType line = begin; line < end; ++line)
      {
        const vtkIdType tube = tubeOf[line];
        if (tube < 0)
        {
          continue;
        }
        const vtkIdType cellId = firstCellId + line;
        const vtkIdType first = nodeOffset[line];
        // Segments of the tubes before this one: one fewer than their nodes.
        const vtkIdType firstSegment =
          segmentsBefore + (first - nodesBefore) - (tube - tubesBefore);
        LineScan scan;
        scanLine(line, scratch, scan,
          [&](vtkIdType pointId, const double* p, double r, vtkIdType k)
          {
            const vtkIdType i = first + k;
            positions[3 * i] = static_cast<float>(p[0]);
            positions[3 * i + 1] = static_cast<float>(p[1]);
            positions[3 * i + 2] = static_cast<float>(p[2]);
            radii[2 * i] = static_cast<float>(r);
            radii[2 * i + 1] = 0.0f;
            rMax = std::max(rMax, r);
            if (nodeScalars)
            {
              nodeScalars[i] = static_cast<float>(scalarArray->GetComponent(pointId, 0));
            }
            float* c = nodeColors + 4 * i;
            if (colorBytes)
            {
              const unsigned char* rgba = colorBytes + 4 * (colorsPerCell ? cellId : pointId);
              for (int j = 0; j < 4; ++j)
              {
                c[j] = static_cast<float>(rgba[j] / 255.0);
              }
            }
            else
            {
              std::fill(c, c + 4, 1.0f);
            }
          });
        const vtkIdType n = scan.Kept;
        tubeFirst[tube] = first;
        tubeNodes[tube] = n;
        for (vtkIdType k = 0; k + 1 < n; ++k)
        {
          unsigned char flags = 0;
          if (k == 0)
          {
            flags |= TUBE_START;
          }
          if (k + 2 == n)
          {
            flags |= TUBE_END;
          }
          const vtkIdType s = firstSegment + k;
          segmentFirst[s] = static_cast<vtkTypeUInt32>(first + k);
          segmentFlags[s] = flags;
          segmentCells[s] =
            originalIds ? static_cast<vtkIdType>(originalIds->GetComponent(cellId, 0)) : cellId;
          segmentBlocks[s] = blockId;
        }
      }
    });
  for (double r : maxRadius)
  {
    this->MaximumRadius = std::max(this->MaximumRadius, r);
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
  const vtkIdType numNodes = this->NodePositions->GetNumberOfTuples();
  const vtkIdType numTubes = this->TubeFirstNodes->GetNumberOfTuples();
  this->NodeTangents->SetNumberOfTuples(numNodes);
  this->NodeColorDerivatives->SetNumberOfTuples(numNodes);
  this->NodeFrames->SetNumberOfTuples(this->ComputeFrames ? numNodes : 0);

  float* positions = this->NodePositions->GetPointer(0);
  float* tangents = this->NodeTangents->GetPointer(0);
  float* radii = this->NodeRadii->GetPointer(0);
  float* colors = this->NodeColors->GetPointer(0);
  float* colorDerivatives = this->NodeColorDerivatives->GetPointer(0);

  vtkSMPTools::For(0, numTubes,
    [&](vtkIdType begin, vtkIdType end)
    {
      std::vector<float> r;
      std::vector<float> dr;
      for (vtkIdType t = begin; t < end; ++t)
      {
        const vtkIdType first = this->TubeFirstNodes->GetValue(t);
        const vtkIdType n = this->TubeNumberOfNodes->GetValue(t);
        FiniteDifferences(positions + 3 * first, tangents + 3 * first, n, 3);
        FiniteDifferences(colors + 4 * first, colorDerivatives + 4 * first, n, 4);
        r.resize(n);
        dr.resize(n);
        for (vtkIdType k = 0; k < n; ++k)
        {
          r[k] = radii[2 * (first + k)];
        }
        FiniteDifferences(r.data(), dr.data(), n, 1);
        for (vtkIdType k = 0; k < n; ++k)
        {
          radii[2 * (first + k) + 1] = dr[k];
        }
        if (this->ComputeFrames)
        {
          this->PropagateFrames(t);
        }
      }
    });
  this->BuildChunks();
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkSplineTubeCore::BuildChunks()
{
  const vtkIdType numTubes = this->TubeFirstNodes->GetNumberOfTuples();
  const vtkIdType numSegments = this->SegmentFirstNodes->GetNumberOfTuples();
  const vtkIdType* tubeNodes = this->TubeNumberOfNodes->GetPointer(0);
  this->TubeFirstChunks->SetNumberOfTuples(numTubes + 1);
  vtkIdType* tubeFirstChunk = this->TubeFirstChunks->GetPointer(0);
  tubeFirstChunk[0] = 0;
  for (vtkIdType t = 0; t < numTubes; ++t)
  {
    tubeFirstChunk[t + 1] =
      tubeFirstChunk[t] + (tubeNodes[t] - 1 + ChunkSegments - 1) / ChunkSegments;
  }
  const vtkIdType numChunks = tubeFirstChunk[numTubes];
  this->ChunkFirstSegments->SetNumberOfTuples(numChunks + 1);
  this->ChunkTubes->SetNumberOfTuples(numChunks);
  this->ChunkSpheres->SetNumberOfTuples(numChunks);
  this->ChunkSizes->SetNumberOfTuples(numChunks);
  this->SegmentSpheres->SetNumberOfTuples(numSegments);
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
  const float* P = this->NodePositions->GetPointer(0);
  const float* M = this->NodeTangents->GetPointer(0);
  const float* R = this->NodeRadii->GetPointer(0);
  const vtkTypeUInt32* first = this->SegmentFirstNodes->GetPointer(0);
  const vtkIdType* tubeFirstNode = this->TubeFirstNodes->GetPointer(0);

  // The box of a segment: its cubic Bezier control points (the curve lies in
  // their convex hull) padded by the largest of the radius spline's (the
  // radius lies below their maximum).
  auto segmentBox = [&](vtkIdType segment, double box[6], double control[4][3], double& r)
  {
    const vtkIdType i = first[segment];
    const vtkIdType j = i + 1;
    r = std::max({ static_cast<double>(R[2 * i]), static_cast<double>(R[2 * j]),
      R[2 * i] + R[2 * i + 1] / 3.0, R[2 * j] - R[2 * j + 1] / 3.0 });
    for (int k = 0; k < 3; ++k)
    {
      control[0][k] = P[3 * i + k];
      control[1][k] = P[3 * i + k] + M[3 * i + k] / 3.0;
      control[2][k] = P[3 * j + k] - M[3 * j + k] / 3.0;
      control[3][k] = P[3 * j + k];
      box[2 * k] = std::min({ control[0][k], control[1][k], control[2][k], control[3][k] }) - r;
      box[2 * k + 1] = std::max({ control[0][k], control[1][k], control[2][k], control[3][k] }) + r;
    }
  };

  // Pass 1: per chunk its box (kept in `boxes` until the centre is known),
  // sizes, first segment and tube; the bounds by thread.
  std::vector<double> boxes(static_cast<size_t>(6 * numChunks));
  struct Local
  {
    double B[6] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MIN, VTK_DOUBLE_MAX, VTK_DOUBLE_MIN, VTK_DOUBLE_MAX,
      VTK_DOUBLE_MIN };
  };
  vtkSMPThreadLocal<Local> locals;
  vtkSMPTools::For(0, numTubes,
    [&](vtkIdType begin, vtkIdType end)
    {
      double* B = locals.Local().B;
      for (vtkIdType t = begin; t < end; ++t)
      {
        // Segments of the tubes before this one: one fewer than their nodes.
        vtkIdType segment = tubeFirstNode[t] - t;
        const vtkIdType last = segment + tubeNodes[t] - 1;
        for (vtkIdType c = tubeFirstChunk[t]; c < tubeFirstChunk[t + 1]; ++c)
        {
          chunkFirst[c] = static_cast<vtkTypeUInt32>(segment);
          chunkTube[c] = static_cast<vtkTypeUInt32>(t);
          double* box = &boxes[6 * c];
          for (int k = 0; k < 3; ++k)
          {
            box[2 * k] = VTK_DOUBLE_MAX;
            box[2 * k + 1] = VTK_DOUBLE_MIN;
          }
          double length = 0.0;
          double maxLength = 0.0;
          double maxRadius = 0.0;
          const vtkIdType stop = std::min<vtkIdType>(last, segment + ChunkSegments);
          for (; segment < stop; ++segment)
          {
            double segmentBounds[6];
            double control[4][3];
            double r = 0.0;
            segmentBox(segment, segmentBounds, control, r);
            for (int k = 0; k < 6; k += 2)
            {
              box[k] = std::min(box[k], segmentBounds[k]);
              box[k + 1] = std::max(box[k + 1], segmentBounds[k + 1]);
            }
            double polygon = 0.0;
            for (int q = 0; q < 3; ++q)
            {
              polygon += std::sqrt(vtkMath::Distance2BetweenPoints(control[q], control[q + 1]));
            }
            length += polygon;
            maxLength = std::max(maxLength, polygon);
            maxRadius = std::max(maxRadius, r);
          }
          for (int k = 0; k < 6; k += 2)
          {
            B[k] = std::min(B[k], box[k]);
            B[k + 1] = std::max(B[k + 1], box[k + 1]);
          }
          sizes[3 * c] = static_cast<float>(length);
          sizes[3 * c + 1] = static_cast<float>(maxLength);
          sizes[3 * c + 2] = static_cast<float>(maxRadius);
        }
      }
    });
  chunkFirst[numChunks] = static_cast<vtkTypeUInt32>(numSegments);
  for (int k = 0; k < 6; k += 2)
  {
    this->Bounds[k] = VTK_DOUBLE_MAX;
    this->Bounds[k + 1] = VTK_DOUBLE_MIN;
  }
  for (auto& local : locals)
  {
    for (int k = 0; k < 6; k += 2)
    {
      this->Bounds[k] = std::min(this->Bounds[k], local.B[k]);
      this->Bounds[k + 1] = std::max(this->Bounds[k + 1], local.B[k + 1]);
    }
  }

  // Pass 2: the spheres around the boxes, relative to the centre. Rounding
  // to float is covered by a relative margin.
  double center[3];
  this->GetCenter(center);
  vtkSMPTools::For(0, numChunks,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType c = begin; c < end; ++c)
      {
        const double* box = &boxes[6 * c];
        double radius2 = 0.0;
        double extent = 0.0;
        for (int k = 0; k < 3; ++k)
        {
          const double mid = 0.5 * (box[2 * k] + box[2 * k + 1]);
          spheres[4 * c + k] = static_cast<float>(mid - center[k]);
          radius2 += 0.25 * (box[2 * k + 1] - box[2 * k]) * (box[2 * k + 1] - box[2 * k]);
          extent = std::max(extent, std::abs(mid - center[k]));
        }
        const double radius = std::sqrt(radius2);
        spheres[4 * c + 3] = static_cast<float>(radius + 1e-6 * (radius + extent));
        // The segments' spheres, relative to the chunk's.
        for (vtkIdType segment = chunkFirst[c]; segment < chunkFirst[c + 1]; ++segment)
        {
          double segmentBounds[6];
          double control[4][3];
          double r = 0.0;
          segmentBox(segment, segmentBounds, control, r);
          double part[4];
          double partRadius2 = 0.0;
          for (int k = 0; k < 3; ++k)
          {
            part[k] = 0.5 * (segmentBounds[2 * k] + segmentBounds[2 * k + 1]) - center[k];
            partRadius2 += 0.25 * (segmentBounds[2 * k + 1] - segmentBounds[2 * k]) *
              (segmentBounds[2 * k + 1] - segmentBounds[2 * k]);
          }
          part[3] = std::sqrt(partRadius2) * (1.0 + 1e-6) + 1e-6 * extent;
          segmentSpheres[segment] = vtkSplineTubeVisibility::EncodePart(spheres + 4 * c, part);
        }
      }
    });
}

//------------------------------------------------------------------------------
void vtkSplineTubeCore::GetCenter(double center[3]) const
{
  for (int k = 0; k < 3; ++k)
  {
    center[k] = vtkMath::AreBoundsInitialized(this->Bounds)
      ? 0.5 * (this->Bounds[2 * k] + this->Bounds[2 * k + 1])
      : 0.0;
  }
}

//------------------------------------------------------------------------------
void vtkSplineTubeCore::PropagateFrames(vtkIdType tube)
{
  const vtkIdType first = this->TubeFirstNodes->GetValue(tube);
  const vtkIdType n = this->TubeNumberOfNodes->GetValue(tube);
  const float* P = this->NodePositions->GetPointer(0);
  const float* M = this->NodeTangents->GetPointer(0);
  float* F = this->NodeFrames->GetPointer(0);

  auto node = [&](vtkIdType i) { return vec4(P[3 * i], P[3 * i + 1], P[3 * i + 2], 0.0); };
  auto deriv = [&](vtkIdType i) { return vec4(M[3 * i], M[3 * i + 1], M[3 * i + 2], 0.0); };
  // Unit tangent of the cubic of segment s at parameter u; falls back to the
  // chord when the derivative vanishes (a cusp of the spline).
  auto unitTangent = [&](vtkIdType s, double u)
  {
    vec3 d =
      vec3(vtkSplineTubeMath::svHermiteDerivative(node(s), deriv(s), node(s + 1), deriv(s + 1), u));
    double len = glm::length(d);
    if (len < 1e-12)
    {
      d = vec3(node(s + 1) - node(s));
      len = glm::length(d);
    }
    return len > 0.0 ? d / len : vec3(1.0, 0.0, 0.0);
  };

  vec3 t = unitTangent(first, 0.0);
  vec3 r = vtkSplineTubeMath::svAnyOrthogonal(t);
  F[3 * first + 0] = static_cast<float>(r.x);
  F[3 * first + 1] = static_cast<float>(r.y);
  F[3 * first + 2] = static_cast<float>(r.z);

  const double maxAngle = this->MaximumFrameStepAngle;
  for (vtkIdType s = first; s + 1 < first + n; ++s)
  {
    // Sub-steps: sample the tangent densely enough that no step turns it by
    // more than maxAngle (the total turning is estimated on 8 samples).
    double turning = 0.0;
    vec3 prev = t;
    for (int k = 1; k <= 8; ++k)
    {
      const vec3 cur = unitTangent(s, k / 8.0);
      turning += std::acos(std::max(-1.0, std::min(1.0, glm::dot(prev, cur))));
      prev = cur;
    }
    const int steps = std::max(1, std::min(256, static_cast<int>(std::ceil(turning / maxAngle))));
    vec3 x = vec3(node(s));
    for (int k = 1; k <= steps; ++k)
    {
      const double u = static_cast<double>(k) / steps;
      const vec3 x1 =
        vec3(vtkSplineTubeMath::svHermite(node(s), deriv(s), node(s + 1), deriv(s + 1), u));
      const vec3 t1 = unitTangent(s, u);
      r = DoubleReflection(x, t, r, x1, t1);
      x = x1;
      t = t1;
    }
    F[3 * (s + 1) + 0] = static_cast<float>(r.x);
    F[3 * (s + 1) + 1] = static_cast<float>(r.y);
    F[3 * (s + 1) + 2] = static_cast<float>(r.z);
  }
}

//------------------------------------------------------------------------------
void vtkSplineTubeCore::EvaluateSegment(vtkIdType segment, double t, double position[3],
  double derivative[3], double* radius, double* radiusDerivative)
{
  const vtkIdType i = this->SegmentFirstNodes->GetValue(segment);
  const float* P = this->NodePositions->GetPointer(0);
  const float* M = this->NodeTangents->GetPointer(0);
  const float* R = this->NodeRadii->GetPointer(0);
  const vec4 p0(P[3 * i], P[3 * i + 1], P[3 * i + 2], R[2 * i]);
  const vec4 m0(M[3 * i], M[3 * i + 1], M[3 * i + 2], R[2 * i + 1]);
  const vtkIdType j = i + 1;
  const vec4 p1(P[3 * j], P[3 * j + 1], P[3 * j + 2], R[2 * j]);
  const vec4 m1(M[3 * j], M[3 * j + 1], M[3 * j + 2], R[2 * j + 1]);
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
void vtkSplineTubeCore::GetBounds(double bounds[6]) const
{
  std::copy(this->Bounds, this->Bounds + 6, bounds);
}

//------------------------------------------------------------------------------
void vtkSplineTubeCore::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Radius: " << this->Radius << "\n";
  os << indent << "RadiusArrayName: " << (this->RadiusArrayName ? this->RadiusArrayName : "(none)")
     << "\n";
  os << indent << "RadiusScale: " << this->RadiusScale << "\n";
  os << indent << "MaximumFrameStepAngle: " << this->MaximumFrameStepAngle << "\n";
  os << indent << "NumberOfTubes: " << this->GetNumberOfTubes() << "\n";
  os << indent << "NumberOfNodes: " << this->GetNumberOfNodes() << "\n";
  os << indent << "NumberOfSegments: " << this->GetNumberOfSegments() << "\n";
  os << indent << "NumberOfChunks: " << this->GetNumberOfChunks() << "\n";
  os << indent << "NumberOfSkippedLines: " << this->NumberOfSkippedLines << "\n";
  os << indent << "NumberOfMergedPoints: " << this->NumberOfMergedPoints << "\n";
}
