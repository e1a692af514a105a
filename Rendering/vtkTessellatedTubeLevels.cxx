// SPDX-License-Identifier: BSD-3-Clause
#include "vtkTessellatedTubeLevels.h"

#include "vtkSplineTubeCore.h"
#include "vtkSplineTubeMath.h"

#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkMath.h"
#include "vtkSMPTools.h"
#include "vtkTypeUInt32Array.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace
{
/// What the thin-tube levels depend on in a view (see ThinChunkLevels).
struct ThinView
{
  const float* ModelView = nullptr; // column-major, shifted model to view
  double Proj[4][4];
  double HalfViewport[2];
  double PixelScale;  // pixels per view unit at clip w = 1
  double RadiusScale; // model to view
  double Shift[3];
  double SideLength;    // pixels per ring edge (2 MaxSilhouetteEdgeLength)
  double MaxEdgeLength; // longest edge along the tube, pixels
  double MaxLevel;      // MaxTessellationLevel
  bool Parallel;
};

/// A node in view coordinates: center, radius, derivatives, clip coordinates.
struct ViewNode
{
  double P[3];
  double R;
  double D[3];
  double DR;
  double Clip[4];
};

/// Node i of P (positions and radii, 4 per node, model coordinates) and M
/// (their derivatives) in view coordinates.
ViewNode ToView(const ThinView& v, const double* P, const double* M, vtkIdType i)
{
  ViewNode n;
  const double x[3] = { P[4 * i] - v.Shift[0], P[4 * i + 1] - v.Shift[1],
    P[4 * i + 2] - v.Shift[2] };
  const float* mv = v.ModelView;
  for (int r = 0; r < 3; ++r)
  {
    n.P[r] = mv[r] * x[0] + mv[4 + r] * x[1] + mv[8 + r] * x[2] + mv[12 + r];
    n.D[r] = mv[r] * M[4 * i] + mv[4 + r] * M[4 * i + 1] + mv[8 + r] * M[4 * i + 2];
  }
  n.R = P[4 * i + 3] * v.RadiusScale;
  n.DR = M[4 * i + 3] * v.RadiusScale;
  for (int r = 0; r < 4; ++r)
  {
    n.Clip[r] =
      v.Proj[r][0] * n.P[0] + v.Proj[r][1] * n.P[1] + v.Proj[r][2] * n.P[2] + v.Proj[r][3];
  }
  return n;
}

/// Intervals of the view-facing half ring at a node (the control stage's
/// tubeWallRingLevel, through the same shared functions).
double ThinRingLevel(const ThinView& v, const ViewNode& n)
{
  const vtkSplineTubeMath::vec3 d(n.D[0], n.D[1], n.D[2]);
  const vtkSplineTubeMath::vec3 toEye = v.Parallel
    ? vtkSplineTubeMath::vec3(0.0, 0.0, 1.0)
    : vtkSplineTubeMath::vec3(-n.P[0], -n.P[1], -n.P[2]);
  // (a degenerate direction counts as across the view: 3 intervals at least)
  const double least = glm::length(d) > 0.0 && glm::length(toEye) > 0.0
    ? vtkSplineTubeMath::svThinWallLeast(d, toEye)
    : 3.0;
  return vtkSplineTubeMath::svThinRingLevel(n.R, n.Clip[3], v.PixelScale, v.SideLength, 0.5, least);
}

/// Whether the cap of `kind` (1: start, 2: end) at a node is turned to the
/// eye, within a radius (the control stage's test for caps).
bool ThinCapVisible(const ThinView& v, const ViewNode& n, int kind)
{
  const double length = std::sqrt(n.D[0] * n.D[0] + n.D[1] * n.D[1] + n.D[2] * n.D[2]);
  if (length <= 0.0)
  {
    return true;
  }
  const double sign = kind == 1 ? -1.0 / length : 1.0 / length;
  const double facing =
    v.Parallel ? sign * n.D[2] : -sign * (n.D[0] * n.P[0] + n.D[1] * n.P[1] + n.D[2] * n.P[2]);
  return facing >= -n.R;
}

/// Pixel position of a node (false behind the eye).
bool ThinScreen(const ThinView& v, const ViewNode& n, double p[2])
{
  if (n.Clip[3] <= 0.0)
  {
    return false;
  }
  p[0] = n.Clip[0] / n.Clip[3] * v.HalfViewport[0];
  p[1] = n.Clip[1] / n.Clip[3] * v.HalfViewport[1];
  return true;
}

/// Rings along a thin run of `count` segments from node `first`: the level
/// the control stage's single-patch mode sets (tubeSinglePatch: edges at
/// most MaxEdgeLength pixels on screen, chords within a quarter pixel of the
/// curve on screen and within a tenth of the radius in space, 1.7 times that
/// inside runs, whose chords straddle the curve), and the intervals of its
/// first and last rings. The same bounds, through the same functions
/// (vtkSplineTubeMathShared.glsl's svThin...), computed once per view on the
/// CPU instead of per patch on the GPU.
void ThinChunkLevels(const ThinView& v, const double* P, const double* M, vtkIdType first,
  vtkIdType count, double& along, double& ring0, double& ring1)
{
  const ViewNode a = ToView(v, P, M, first);
  const ViewNode b = ToView(v, P, M, first + count);
  ring0 = ThinRingLevel(v, a);
  ring1 = ThinRingLevel(v, b);
  using vtkSplineTubeMath::vec3;
  if (count == 1)
  {
    // The cubic's deviation from its chord (svThinSegmentSagitta).
    double pa[2];
    double pb[2];
    double screen = 1e30;
    if (ThinScreen(v, a, pa) && ThinScreen(v, b, pb))
    {
      screen = std::hypot(pa[0] - pb[0], pa[1] - pb[1]);
    }
    // The segment's middle (svHermite at t = 1/2, position and radius).
    using vtkSplineTubeMath::vec4;
    const vec4 p0(a.P[0], a.P[1], a.P[2], a.R);
    const vec4 m0(a.D[0], a.D[1], a.D[2], a.DR);
    const vec4 p1(b.P[0], b.P[1], b.P[2], b.R);
    const vec4 m1(b.D[0], b.D[1], b.D[2], b.DR);
    const vec4 middle = vtkSplineTubeMath::svHermite(p0, m0, p1, m1, 0.5);
    const double sagitta = vtkSplineTubeMath::svThinSegmentSagitta(p0, m0, p1, m1, 1.0);
    const double w =
      v.Proj[3][0] * middle.x + v.Proj[3][1] * middle.y + v.Proj[3][2] * middle.z + v.Proj[3][3];
    const double radius = std::min({ a.R, b.R, middle.w });
    const double sagittaLevel =
      vtkSplineTubeMath::svThinSagittaLevel(sagitta, w, radius, v.PixelScale);
    along = std::min(
      std::max(std::max(std::min(screen / v.MaxEdgeLength, v.MaxLevel), sagittaLevel), 1.0), 64.0);
    return;
  }
  double total = 0.0;
  double total3 = 0.0;
  double shortest = 1e30;
  double shortest3 = 1e30;
  vec3 previous(0.0);
  vec3 direction(0.0);
  double previousLength = 0.0;
  vec3 previous3(0.0);
  vec3 direction3(0.0);
  double previousLength3 = 0.0;
  for (vtkIdType k = 0; k <= count; ++k)
  {
    const ViewNode n = k == 0 ? a : (k == count ? b : ToView(v, P, M, first + k));
    double p2[2];
    if (!ThinScreen(v, n, p2))
    {
      along = 64.0;
      return;
    }
    const vec3 p(p2[0], p2[1], 0.0);
    const vec3 p3(n.P[0], n.P[1], n.P[2]);
    if (k > 0)
    {
      const vec3 d = p - previous;
      const double len = glm::length(d);
      total += len;
      const double curvature =
        k > 1 ? vtkSplineTubeMath::svThinChainCurvature(d, len, direction, previousLength) : 0.0;
      if (curvature > 0.0)
      {
        shortest =
          std::min(shortest, std::sqrt(8.0 * vtkSplineTubeMath::svThinSagittaPixels / curvature));
      }
      direction = d;
      previousLength = len;
      const vec3 d3 = p3 - previous3;
      const double len3 = glm::length(d3);
      total3 += len3;
      const double curvature3 = k > 1
        ? vtkSplineTubeMath::svThinChainCurvature(d3, len3, direction3, previousLength3)
        : 0.0;
      if (curvature3 > 0.0)
      {
        shortest3 = std::min(shortest3,
          std::sqrt(8.0 * vtkSplineTubeMath::svThinRunStraddle *
            vtkSplineTubeMath::svThinDepthSagitta * n.R / curvature3));
      }
      direction3 = d3;
      previousLength3 = len3;
    }
    previous = p;
    previous3 = p3;
  }
  along = std::min(
    std::max(
      std::ceil(std::max({ total / v.MaxEdgeLength, total / shortest, total3 / shortest3 })), 1.0),
    64.0);
}

}

//------------------------------------------------------------------------------
bool vtkTessellatedTubeLevels::BuildMeshes(int baseRings, int baseSides)
{
  if (!this->MeshIndices.empty() && this->MeshBaseRings == baseRings &&
    this->MeshBaseSides == baseSides)
  {
    return false;
  }
  // The ladders: intervals along the segment halved down to 1; vertices per
  // ring halved down to 4, then one patch around.
  this->RingLadder.clear();
  for (int intervals = baseRings - 1;; intervals = (intervals + 1) / 2)
  {
    this->RingLadder.push_back(intervals + 1);
    if (intervals == 1)
    {
      break;
    }
  }
  this->SideLadder.clear();
  for (int sides = baseSides;; sides = (sides + 1) / 2)
  {
    this->SideLadder.push_back(sides);
    if ((sides + 1) / 2 < 4)
    {
      break;
    }
  }
  this->SideLadder.push_back(1); // one patch around the segment (thin tubes)

  // Quad patches (see vtkTessellatedTubeVS.glsl for the vertex numbering):
  // the walls of every (rings, sides), the caps of every sides (numbered as
  // a mesh of 2 rings: the first and the last ring of any segment).
  std::vector<unsigned int>& indices = this->MeshIndices;
  indices.clear();
  this->WallMeshes.clear();
  this->CapMeshes.clear();
  for (int sides : this->SideLadder)
  {
    const unsigned int perRing = static_cast<unsigned int>(sides + 1);
    for (int rings : this->RingLadder)
    {
      MeshRange range;
      range.Offset = indices.size();
      for (int i = 0; i + 1 < rings; ++i)
      {
        for (int j = 0; j < sides; ++j)
        {
          const unsigned int a =
            static_cast<unsigned int>(i) * perRing + static_cast<unsigned int>(j);
          indices.insert(indices.end(), { a, a + 1, a + 1 + perRing, a + perRing });
        }
      }
      range.Count = indices.size() - range.Offset;
      this->WallMeshes[std::make_pair(rings, sides)] = range;
    }
    MeshRange caps;
    caps.Offset = indices.size();
    const unsigned int startCenter = 2 * perRing;
    const unsigned int endCenter = startCenter + 1;
    for (int j = 0; j < sides; ++j)
    {
      const unsigned int a = static_cast<unsigned int>(j);
      indices.insert(indices.end(), { a, a + 1, startCenter, startCenter });
    }
    for (int j = 0; j < sides; ++j)
    {
      const unsigned int a = perRing + static_cast<unsigned int>(j);
      indices.insert(indices.end(), { a, a + 1, endCenter, endCenter });
    }
    caps.Count = indices.size() - caps.Offset;
    this->CapMeshes[sides] = caps;
  }
  // Thin-tube draws: triangles between consecutive rings of ThinRibbonSides
  // vertices (the silhouette points and the point nearest the eye, see
  // vtkTessellatedTubeThinVS.glsl), wound counter-clockwise seen from the
  // eye, the diagonals mirrored at the middle of the ring and of the run as
  // the tessellator's. One mesh serves every number n of rows: its rows
  // alternate between the run's start (row i: rings i, i + 1) and its end
  // (the mirror image, vertices numbered from the end ring: ThinMirrorRing +
  // rings before the end), so that the first n rows are the mesh of n rows.
  this->ThinLadder = { 1, 2, 3, 4, 5, 6, 7, 8, 10, 12, 14, 16, 20, 24, 28, 32, 40, 48, 56, 64 };
  this->ThinMesh.Offset = indices.size();
  {
    const int L = ThinRibbonSides - 1;
    const auto perRing = static_cast<unsigned int>(ThinRibbonSides);
    const unsigned int mirror = static_cast<unsigned int>(ThinMirrorRing) * perRing;
    for (int row = 0; row < this->ThinLadder.back(); ++row)
    {
      const unsigned int i = static_cast<unsigned int>(row / 2);
      const bool fromEnd = (row & 1) != 0;
      for (int j = 0; j < L; ++j)
      {
        const unsigned int a = (fromEnd ? mirror : 0) + i * perRing + static_cast<unsigned int>(j);
        // Rows at the start: the diagonal from (j + 1, i) to (j, i + 1) on
        // the ring's second half; mirrored rows (reversed winding) likewise
        // in their numbering, which is the other diagonal in the run's.
        const bool other = 2 * j >= L;
        if (!fromEnd)
        {
          if (other)
          {
            indices.insert(
              indices.end(), { a, a + 1, a + perRing, a + 1, a + 1 + perRing, a + perRing });
          }
          else
          {
            indices.insert(
              indices.end(), { a, a + 1, a + 1 + perRing, a, a + 1 + perRing, a + perRing });
          }
        }
        else if (other)
        {
          indices.insert(
            indices.end(), { a, a + perRing, a + 1, a + 1, a + perRing, a + 1 + perRing });
        }
        else
        {
          indices.insert(
            indices.end(), { a, a + 1 + perRing, a + 1, a, a + perRing, a + 1 + perRing });
        }
      }
    }
  }
  this->ThinMesh.Count = indices.size() - this->ThinMesh.Offset;
  // Thin caps: the polygon as a fan from its vertex 0.
  this->ThinCapMesh.Offset = indices.size();
  for (unsigned int j = 1; j + 1 < static_cast<unsigned int>(ThinCapSides); ++j)
  {
    indices.insert(indices.end(), { 0u, j, j + 1 });
  }
  this->ThinCapMesh.Count = indices.size() - this->ThinCapMesh.Offset;
  this->MeshBaseRings = baseRings;
  this->MeshBaseSides = baseSides;
  this->LastView.clear();
  return true;
}

//------------------------------------------------------------------------------
void vtkTessellatedTubeLevels::SetCore(vtkSplineTubeCore* core)
{
  this->Core = core;
  const vtkIdType numChunks = core->GetNumberOfChunks();
  this->ChunkRingBin.assign(static_cast<size_t>(numChunks), Culled);
  this->ChunkPixels.assign(static_cast<size_t>(numChunks), -1.0f);
  this->ChunkThinLevels.assign(static_cast<size_t>(numChunks), 0);
  this->TubeSideBin.assign(static_cast<size_t>(core->GetNumberOfTubes()), Culled);
  this->TubeStamp.assign(static_cast<size_t>(core->GetNumberOfTubes()), 0);
  this->ThinStartCaps.assign(static_cast<size_t>(core->GetNumberOfTubes()), 0);
  this->ThinEndCaps.assign(static_cast<size_t>(core->GetNumberOfTubes()), 0);
  this->LastView.clear();
}

//------------------------------------------------------------------------------
bool vtkTessellatedTubeLevels::ClassifyView(const View& view, const Settings& settings)
{
  vtkSplineTubeCore* core = this->Core;
  if (!core)
  {
    return false;
  }
  const vtkIdType numChunks = core->GetNumberOfChunks();

  // Skip the classification when nothing it depends on changed.
  std::vector<double> key(view.ModelView, view.ModelView + 16);
  key.insert(key.end(), &view.Proj[0][0], &view.Proj[0][0] + 16);
  key.insert(key.end(),
    { static_cast<double>(view.Width), static_cast<double>(view.Height), view.RadiusScale,
      view.Parallel ? 1.0 : 0.0, settings.LevelOfDetail ? 1.0 : 0.0, settings.Capping ? 1.0 : 0.0,
      settings.MaxEdgeLength, settings.MaxSilhouetteEdgeLength,
      static_cast<double>(settings.BaseRings), static_cast<double>(settings.BaseSides),
      static_cast<double>(numChunks), static_cast<double>(settings.MaxTessellationLevel) });
  if (key == this->LastView)
  {
    return false;
  }
  this->LastView = key;
  this->CurrentView = view;
  this->CurrentSettings = settings;

  // The tubes are classified when first drawn in this view (ClassifyTube()).
  ++this->ViewStamp;
  if (this->ViewStamp == 0)
  {
    std::fill(this->TubeStamp.begin(), this->TubeStamp.end(), 0);
    this->ViewStamp = 1;
  }
  // Frustum planes (view coordinates, normalized): row3 +- row0, +- row1, +- row2.
  const double(*proj)[4] = view.Proj;
  for (int k = 0; k < 3; ++k)
  {
    for (int side = 0; side < 2; ++side)
    {
      double* p = this->Planes[2 * k + side];
      for (int c = 0; c < 4; ++c)
      {
        p[c] = proj[3][c] + (side == 0 ? 1.0 : -1.0) * proj[k][c];
      }
      const double len = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
      for (int c = 0; c < 4 && len > 0.0; ++c)
      {
        p[c] /= len;
      }
    }
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkTessellatedTubeLevels::ClassifyTube(vtkIdType t)
{
  vtkSplineTubeCore* core = this->Core;
  const View& view = this->CurrentView;
  const Settings& settings = this->CurrentSettings;
  const int ringBins = static_cast<int>(this->RingLadder.size());
  const int sideBins = static_cast<int>(this->SideLadder.size());
  const vtkIdType* tubeFirstChunk = core->GetTubeFirstChunks()->GetPointer(0);
  if (!settings.LevelOfDetail)
  {
    for (vtkIdType c = tubeFirstChunk[t]; c < tubeFirstChunk[t + 1]; ++c)
    {
      this->ChunkRingBin[c] = 0;
      this->ChunkPixels[c] = 0.0f;
    }
    this->TubeSideBin[t] = 0;
    return;
  }
  const double(*proj)[4] = view.Proj;
  const float* modelView = view.ModelView;
  const double(*planes)[4] = this->Planes;
  const double pixelScale =
    0.5 * std::max(proj[0][0] * view.Width, proj[1][1] * view.Height); // pixels per unit at w = 1
  const double wSlope =
    std::sqrt(proj[3][0] * proj[3][0] + proj[3][1] * proj[3][1] + proj[3][2] * proj[3][2]);
  const double ringTarget = 0.5 * settings.MaxEdgeLength;
  const double sideTarget = 2.0 * settings.MaxSilhouetteEdgeLength;
  const double twoPi = 2.0 * vtkMath::Pi();
  const float* spheres = core->GetChunkSpheres()->GetPointer(0);
  const float* sizes = core->GetChunkSizes()->GetPointer(0);
  const double radiusScale = view.RadiusScale;
  double widest = -1.0; // pixels; < 0: the tube is culled
  for (vtkIdType c = tubeFirstChunk[t]; c < tubeFirstChunk[t + 1]; ++c)
  {
    const float* sphere = spheres + 4 * c;
    double center[3];
    for (int r = 0; r < 3; ++r)
    {
      center[r] = modelView[r] * sphere[0] + modelView[4 + r] * sphere[1] +
        modelView[8 + r] * sphere[2] + modelView[12 + r];
    }
    const double radius = sphere[3] * radiusScale;
    bool outside = false;
    for (int k = 0; k < 6 && !outside; ++k)
    {
      outside = planes[k][0] * center[0] + planes[k][1] * center[1] + planes[k][2] * center[2] +
          planes[k][3] <
        -radius;
    }
    if (outside)
    {
      this->ChunkRingBin[c] = Culled;
      this->ChunkPixels[c] = -1.0f;
      continue;
    }
    const double w = proj[3][0] * center[0] + proj[3][1] * center[1] + proj[3][2] * center[2] +
      proj[3][3] - wSlope * radius;
    int ringBin = 0;
    double radiusPixels = VTK_DOUBLE_MAX;
    double lengthPixels = VTK_DOUBLE_MAX;
    if (w > 1e-6 * (std::abs(proj[3][3]) + std::abs(center[2]) + radius))
    {
      const double scale = pixelScale * radiusScale / w;
      lengthPixels = sizes[3 * c] * scale;
      const double intervals = sizes[3 * c + 1] * scale / ringTarget;
      radiusPixels = sizes[3 * c + 2] * scale;
      ringBin = ringBins - 1;
      while (ringBin > 0 && this->RingLadder[ringBin] - 1 < intervals)
      {
        --ringBin;
      }
    }
    this->ChunkRingBin[c] = static_cast<unsigned char>(ringBin);
    this->ChunkPixels[c] = static_cast<float>(std::min(lengthPixels, 1e30));
    widest = std::max(widest, radiusPixels);
  }
  // Sides: one patch around when at most SinglePatchSides ring edges are
  // needed (the tessellator makes them), else the fewest base vertices that
  // the silhouette refinement can at least double to the need. From the
  // widest chunk of the tube in view, so that the rings of its chunks match.
  int sideBin = Culled;
  if (widest >= 0.0)
  {
    const double sidesNeeded = twoPi * widest / sideTarget;
    sideBin = sideBins - 1;
    if (sidesNeeded > SinglePatchSides)
    {
      sideBin = sideBins - 2;
      while (sideBin > 0 && this->SideLadder[sideBin] < 0.5 * sidesNeeded)
      {
        --sideBin;
      }
    }
  }
  this->TubeSideBin[t] = static_cast<unsigned char>(sideBin);
}

//------------------------------------------------------------------------------
void vtkTessellatedTubeLevels::ClassifyThin(std::uint32_t c)
{
  // Thin tubes (one patch around): a chunk whose length on screen fits the
  // largest tessellation level with 16-pixel edges is drawn without the
  // tessellator (a thin draw, its levels computed here) unless its rings need
  // more than ThinMaxSides intervals; then it becomes one patch. Longer
  // chunks: each segment is one patch (2 rings) whose level along the
  // control stage sets from the segment's length and bending.
  vtkSplineTubeCore* core = this->Core;
  const View& view = this->CurrentView;
  const Settings& settings = this->CurrentSettings;
  const int ringBins = static_cast<int>(this->RingLadder.size());
  const double pixels = this->ChunkPixels[c];
  const vtkTypeUInt32* chunkFirst = core->GetChunkFirstSegments()->GetPointer(0);
  const vtkIdType count = chunkFirst[c + 1] - chunkFirst[c];
  if (pixels <= WholeChunkPixels)
  {
    ThinView thin;
    thin.ModelView = view.ModelView;
    std::copy(&view.Proj[0][0], &view.Proj[0][0] + 16, &thin.Proj[0][0]);
    thin.HalfViewport[0] = 0.5 * view.Width;
    thin.HalfViewport[1] = 0.5 * view.Height;
    thin.PixelScale = 0.5 * std::max(view.Proj[0][0] * view.Width, view.Proj[1][1] * view.Height);
    thin.RadiusScale = view.RadiusScale;
    core->GetCenter(thin.Shift);
    thin.SideLength = 2.0 * settings.MaxSilhouetteEdgeLength;
    thin.MaxEdgeLength = settings.MaxEdgeLength;
    thin.MaxLevel = settings.MaxTessellationLevel;
    thin.Parallel = view.Parallel;
    // The chunk's nodes, read from the core.
    const vtkIdType tube = core->GetChunkTubes()->GetValue(c);
    const vtkIdType firstSegment = core->GetTubeFirstSegment(tube);
    const vtkIdType k0 = chunkFirst[c] - firstSegment;
    double P[4 * (vtkSplineTubeCore::ChunkSegments + 1)];
    double M[4 * (vtkSplineTubeCore::ChunkSegments + 1)];
    core->GetTubeNodes(tube, k0, count + 1, P, M);
    double along = 1.0;
    double ring0 = 3.0;
    double ring1 = 3.0;
    ThinChunkLevels(thin, P, M, 0, count, along, ring0, ring1);
    if (std::max(ring0, ring1) <= ThinMaxSides)
    {
      size_t rung = 0;
      while (rung + 1 < this->ThinLadder.size() && this->ThinLadder[rung] < along)
      {
        ++rung;
      }
      this->ChunkRingBin[c] = ThinChunk;
      this->ChunkThinLevels[c] = static_cast<std::uint32_t>(rung);
      // Caps of the tube's ends turned to the eye (the control stage's test),
      // written by the chunk that holds the end (one writer per byte).
      const vtkIdType lastSegment = firstSegment + core->GetTubeNumberOfNodes(tube) - 2;
      if (settings.Capping && chunkFirst[c] == firstSegment)
      {
        this->ThinStartCaps[tube] = ThinCapVisible(thin, ToView(thin, P, M, 0), 1) ? 1 : 0;
      }
      if (settings.Capping && chunkFirst[c + 1] == lastSegment + 1)
      {
        this->ThinEndCaps[tube] =
          ThinCapVisible(thin, ToView(thin, P, M, lastSegment - chunkFirst[c] + 1), 2) ? 1 : 0;
      }
      return;
    }
  }
  this->ChunkRingBin[c] =
    pixels <= WholeChunkPixels && count > 1 ? WholeChunk : static_cast<unsigned char>(ringBins - 1);
}

//------------------------------------------------------------------------------
int vtkTessellatedTubeLevels::SegmentEnds(vtkIdType segment, std::uint32_t tube) const
{
  const vtkIdType firstSegment = this->Core->GetTubeFirstSegment(tube);
  return (segment == firstSegment ? 1 : 0) |
    (segment == firstSegment + this->Core->GetTubeNumberOfNodes(tube) - 2 ? 2 : 0);
}

//------------------------------------------------------------------------------
int vtkTessellatedTubeLevels::ThinCapsToDraw(std::uint32_t tube, int ends) const
{
  return ((ends & 1) && this->ThinStartCaps[tube] ? 1 : 0) |
    ((ends & 2) && this->ThinEndCaps[tube] ? 2 : 0);
}

//------------------------------------------------------------------------------
vtkTessellatedTubeLevels::BinLayout vtkTessellatedTubeLevels::GetBinLayout() const
{
  // Walls per (rings, sides), caps per sides, whole chunks (2 list entries
  // each), thin runs per rung (2 entries), thin caps ((segment, kind) pairs).
  BinLayout layout;
  layout.SideBins = static_cast<int>(this->SideLadder.size());
  layout.Walls = static_cast<int>(this->RingLadder.size()) * layout.SideBins;
  layout.Chunks = layout.Walls + layout.SideBins;
  layout.ThinBase = layout.Chunks + 1;
  layout.ThinBins = static_cast<int>(this->ThinLadder.size());
  layout.ThinCaps = layout.ThinBase + layout.ThinBins;
  return layout;
}

//------------------------------------------------------------------------------
bool vtkTessellatedTubeLevels::IsDrawn(std::uint32_t chunk) const
{
  const vtkTypeUInt32* chunkTube = this->Core->GetChunkTubes()->GetPointer(0);
  return this->TubeSideBin[chunkTube[chunk]] != Culled && this->ChunkRingBin[chunk] != Culled;
}

//------------------------------------------------------------------------------
void vtkTessellatedTubeLevels::BuildDraws(const std::vector<std::uint32_t>& chunks)
{
  this->Draws.clear();
  this->Instances.clear();
  if (!this->Core)
  {
    return;
  }
  this->ClassifyChunks(chunks);
  const BinLayout layout = this->GetBinLayout();
  const std::vector<vtkIdType> counts = this->CountInstances(chunks, layout);
  std::vector<vtkIdType> offsets(counts.size() + 1, 0);
  for (size_t b = 0; b < counts.size(); ++b)
  {
    offsets[b + 1] = offsets[b] + counts[b];
  }
  this->FillInstances(chunks, layout, offsets);
  this->AddDraws(layout, counts, offsets);
}

//------------------------------------------------------------------------------
void vtkTessellatedTubeLevels::ClassifyChunks(const std::vector<std::uint32_t>& chunks)
{
  // The tubes of these chunks not yet classified in this view (in parallel),
  // then the thin tubes' chunks: their levels, in parallel.
  const vtkTypeUInt32* chunkTube = this->Core->GetChunkTubes()->GetPointer(0);
  const int sideBins = static_cast<int>(this->SideLadder.size());
  std::vector<std::uint32_t> tubes;
  for (std::uint32_t c : chunks)
  {
    const std::uint32_t t = chunkTube[c];
    if (this->TubeStamp[t] != this->ViewStamp)
    {
      this->TubeStamp[t] = this->ViewStamp;
      tubes.push_back(t);
    }
  }
  vtkSMPTools::For(0, static_cast<vtkIdType>(tubes.size()),
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        this->ClassifyTube(tubes[i]);
      }
    });
  if (this->CurrentSettings.LevelOfDetail)
  {
    vtkSMPTools::For(0, static_cast<vtkIdType>(chunks.size()),
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType i = begin; i < end; ++i)
        {
          const std::uint32_t c = chunks[i];
          if (this->TubeSideBin[chunkTube[c]] == sideBins - 1 && this->ChunkPixels[c] >= 0.0f)
          {
            this->ClassifyThin(c);
          }
        }
      });
  }
}

//------------------------------------------------------------------------------
std::vector<vtkIdType> vtkTessellatedTubeLevels::CountInstances(
  const std::vector<std::uint32_t>& chunks, const BinLayout& layout)
{
  const vtkTypeUInt32* chunkFirst = this->Core->GetChunkFirstSegments()->GetPointer(0);
  const vtkTypeUInt32* chunkTube = this->Core->GetChunkTubes()->GetPointer(0);
  const bool capping = this->CurrentSettings.Capping;
  std::vector<vtkIdType> counts(static_cast<size_t>(layout.ThinCaps + 1), 0);
  for (std::uint32_t c : chunks)
  {
    if (!this->IsDrawn(c))
    {
      continue;
    }
    const std::uint32_t tube = chunkTube[c];
    const int sideBin = this->TubeSideBin[tube];
    const vtkIdType segments = chunkFirst[c + 1] - chunkFirst[c];
    const unsigned char ringBin = this->ChunkRingBin[c];
    this->DrawnSegments += segments;
    if (ringBin == WholeChunk)
    {
      counts[layout.Chunks] += 2;
    }
    else if (ringBin == ThinChunk)
    {
      counts[layout.ThinBase + this->ChunkThinLevels[c]] += 2;
    }
    else
    {
      counts[ringBin * layout.SideBins + sideBin] += segments;
    }
    for (vtkIdType s = chunkFirst[c]; capping && s < chunkFirst[c + 1]; ++s)
    {
      const int ends = this->SegmentEnds(s, tube);
      if (ends == 0)
      {
        continue;
      }
      if (ringBin == ThinChunk)
      {
        const int kinds = this->ThinCapsToDraw(tube, ends);
        counts[layout.ThinCaps] += 2 * ((kinds & 1) + (kinds >> 1));
      }
      else
      {
        counts[layout.Walls + sideBin] += 1;
      }
    }
  }
  return counts;
}

//------------------------------------------------------------------------------
void vtkTessellatedTubeLevels::FillInstances(const std::vector<std::uint32_t>& chunks,
  const BinLayout& layout, const std::vector<vtkIdType>& offsets)
{
  // Instance entries name segments by their first node (segment + tube).
  const vtkTypeUInt32* chunkFirst = this->Core->GetChunkFirstSegments()->GetPointer(0);
  const vtkTypeUInt32* chunkTube = this->Core->GetChunkTubes()->GetPointer(0);
  const bool capping = this->CurrentSettings.Capping;
  this->Instances.resize(static_cast<size_t>(offsets.back()));
  std::vector<vtkIdType> cursor(offsets.begin(), offsets.end() - 1);
  for (std::uint32_t c : chunks)
  {
    if (!this->IsDrawn(c))
    {
      continue;
    }
    const std::uint32_t tube = chunkTube[c];
    const int sideBin = this->TubeSideBin[tube];
    const unsigned char ringBin = this->ChunkRingBin[c];
    const vtkIdType first = chunkFirst[c];
    const vtkIdType stop = chunkFirst[c + 1];
    const std::uint32_t toNode = tube;
    const bool thinChunk = ringBin == ThinChunk;
    if (thinChunk)
    {
      vtkIdType& entry = cursor[layout.ThinBase + this->ChunkThinLevels[c]];
      this->Instances[entry++] = static_cast<std::uint32_t>(first) + toNode;
      // (count | whether the run starts and ends its tube << 8)
      this->Instances[entry++] = static_cast<std::uint32_t>(stop - first) |
        (static_cast<std::uint32_t>(
           (this->SegmentEnds(first, tube) & 1) | (this->SegmentEnds(stop - 1, tube) & 2))
          << 8);
    }
    const bool whole = thinChunk || ringBin == WholeChunk;
    if (whole && !thinChunk)
    {
      vtkIdType& entry = cursor[layout.Chunks];
      this->Instances[entry++] = static_cast<std::uint32_t>(first) + toNode;
      this->Instances[entry++] = static_cast<std::uint32_t>(stop - first);
    }
    vtkIdType& wall = cursor[whole ? 0 : ringBin * layout.SideBins + sideBin];
    for (vtkIdType s = first; s < stop; ++s)
    {
      if (!whole)
      {
        this->Instances[wall++] = static_cast<std::uint32_t>(s) + toNode;
      }
      const int ends = this->SegmentEnds(s, tube);
      if (capping && ends != 0 && thinChunk)
      {
        const int kinds = this->ThinCapsToDraw(tube, ends);
        for (std::uint32_t kind = 1; kind <= 2; ++kind)
        {
          if ((kinds & kind) != 0)
          {
            this->Instances[cursor[layout.ThinCaps]++] = static_cast<std::uint32_t>(s) + toNode;
            this->Instances[cursor[layout.ThinCaps]++] = kind;
          }
        }
      }
      else if (capping && ends != 0)
      {
        this->Instances[cursor[layout.Walls + sideBin]++] = static_cast<std::uint32_t>(s) + toNode;
      }
    }
  }
}

//------------------------------------------------------------------------------
void vtkTessellatedTubeLevels::AddDraws(const BinLayout& layout,
  const std::vector<vtkIdType>& counts, const std::vector<vtkIdType>& offsets)
{
  auto add = [&](int b, bool thin, bool caps, bool whole, int rings, int sides, vtkIdType count)
  {
    if (counts[b] == 0)
    {
      return;
    }
    Draw draw;
    draw.Thin = thin;
    draw.Caps = caps;
    draw.Chunks = whole;
    draw.Rings = rings;
    draw.Sides = sides;
    draw.Offset = offsets[b];
    draw.Count = count;
    this->Draws.push_back(draw);
    std::ostringstream name;
    name << (caps ? "caps " : "") << (whole ? "chunks " : "") << (thin ? "thin " : "") << rings
         << " x " << sides;
    this->Summary[name.str()] += count;
  };
  const int sideBins = layout.SideBins;
  for (int b = 0; b <= layout.Chunks; ++b)
  {
    const bool caps = b >= layout.Walls && b < layout.Chunks;
    const bool whole = b == layout.Chunks;
    add(b, false, caps, whole, (caps || whole) ? 2 : this->RingLadder[b / sideBins],
      whole ? 1 : this->SideLadder[caps ? b - layout.Walls : b % sideBins],
      whole ? counts[b] / 2 : counts[b]);
  }
  for (int b = layout.ThinBase; b < layout.ThinBase + layout.ThinBins; ++b)
  {
    add(b, true, false, false, this->ThinLadder[static_cast<size_t>(b - layout.ThinBase)] + 1,
      ThinRibbonSides, counts[b] / 2);
  }
  add(layout.ThinCaps, true, true, false, 1, ThinCapSides, counts[layout.ThinCaps] / 2);
}

//------------------------------------------------------------------------------
void vtkTessellatedTubeLevels::ResetSummary()
{
  this->Summary.clear();
  this->DrawnSegments = 0;
}

//------------------------------------------------------------------------------
std::string vtkTessellatedTubeLevels::GetSummary() const
{
  std::ostringstream s;
  for (const auto& entry : this->Summary)
  {
    s << entry.first << ": " << entry.second << "; ";
  }
  const vtkIdType total = this->Core ? this->Core->GetNumberOfSegments() : 0;
  s << "culled: " << std::max<vtkIdType>(0, total - this->DrawnSegments);
  return s.str();
}
