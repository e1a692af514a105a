// SPDX-License-Identifier: BSD-3-Clause
#include "vtkSplineTubeVisibility.h"

#include "vtkMath.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <cmath>

namespace
{
/// Window depths closer than this are equal for the occlusion test (24-bit
/// depth buffers store steps of 6e-8; shaders compute depths in float).
constexpr double DepthTolerance = 1e-6;

/// Element (row, column) of a column-major 4x4 matrix.
inline double At(const double* m, int row, int column)
{
  return m[4 * column + row];
}

/// The largest singular value of the upper 3x3 block of a column-major 4x4
/// matrix (how much it can stretch a sphere's radius).
double SpectralNorm3(const double* m)
{
  double a[3][3];
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      a[r][c] = 0.0;
      for (int k = 0; k < 3; ++k)
      {
        a[r][c] += At(m, k, r) * At(m, k, c); // (M^T M)[r][c]
      }
    }
  }
  double* rows[3] = { a[0], a[1], a[2] };
  double values[3];
  double vecStorage[3][3];
  double* vectors[3] = { vecStorage[0], vecStorage[1], vecStorage[2] };
  vtkMath::Jacobi(rows, values, vectors);
  return std::sqrt(std::max({ values[0], values[1], values[2], 0.0 }));
}
}

//------------------------------------------------------------------------------
void vtkSplineTubeVisibility::DepthPyramid::Build(const float* depth, int width, int height)
{
  this->Width = std::max(width, 1);
  this->Height = std::max(height, 1);
  this->Levels.resize(1);
  this->LevelWidths.assign(1, this->Width);
  this->LevelHeights.assign(1, this->Height);
  this->Levels[0].assign(depth, depth + static_cast<size_t>(this->Width) * this->Height);
  int w = this->Width;
  int h = this->Height;
  while (w > 1 || h > 1)
  {
    const int nw = (w + 1) / 2;
    const int nh = (h + 1) / 2;
    const std::vector<float>& src = this->Levels.back();
    std::vector<float> dst(static_cast<size_t>(nw) * nh);
    vtkSMPTools::For(0, nh,
      [&](vtkIdType y0, vtkIdType y1)
      {
        for (vtkIdType y = y0; y < y1; ++y)
        {
          const size_t ra = static_cast<size_t>(2 * y) * w;
          const size_t rb = static_cast<size_t>(std::min<vtkIdType>(2 * y + 1, h - 1)) * w;
          for (int x = 0; x < nw; ++x)
          {
            const int xa = 2 * x;
            const int xb = std::min(2 * x + 1, w - 1);
            dst[static_cast<size_t>(y) * nw + x] =
              std::max(std::max(src[ra + xa], src[ra + xb]), std::max(src[rb + xa], src[rb + xb]));
          }
        }
      });
    this->Levels.push_back(std::move(dst));
    this->LevelWidths.push_back(nw);
    this->LevelHeights.push_back(nh);
    w = nw;
    h = nh;
  }
}

//------------------------------------------------------------------------------
float vtkSplineTubeVisibility::DepthPyramid::MaximumOver(int x0, int y0, int x1, int y1) const
{
  if (this->Levels.empty())
  {
    return 1.0f;
  }
  x0 = std::max(0, std::min(x0, this->Width - 1));
  x1 = std::max(0, std::min(x1, this->Width - 1));
  y0 = std::max(0, std::min(y0, this->Height - 1));
  y1 = std::max(0, std::min(y1, this->Height - 1));
  // The finest level where the rectangle spans at most 4 x 4 tiles.
  size_t level = 0;
  while (level + 1 < this->Levels.size() &&
    ((x1 >> level) - (x0 >> level) > 3 || (y1 >> level) - (y0 >> level) > 3))
  {
    ++level;
  }
  const std::vector<float>& tiles = this->Levels[level];
  const int w = this->LevelWidths[level];
  const int tx0 = x0 >> level;
  const int tx1 = std::min(x1 >> level, w - 1);
  const int ty0 = y0 >> level;
  const int ty1 = std::min(y1 >> level, this->LevelHeights[level] - 1);
  float result = 0.0f;
  for (int y = ty0; y <= ty1; ++y)
  {
    for (int x = tx0; x <= tx1; ++x)
    {
      result = std::max(result, tiles[static_cast<size_t>(y) * w + x]);
    }
  }
  return result;
}

//------------------------------------------------------------------------------
void vtkSplineTubeVisibility::SetChunks(const float* spheres, const std::uint32_t* lines,
  vtkIdType count, const std::uint32_t* parts, const std::uint32_t* partFirsts)
{
  this->Spheres = spheres;
  this->Lines = lines;
  this->Parts = partFirsts ? parts : nullptr;
  this->PartFirsts = parts ? partFirsts : nullptr;
  this->NumberOfChunks = count;
  this->Visible.assign(static_cast<size_t>(count), 0);
  // The chunks by their line's rank (a counting sort in RankBuckets buckets),
  // so that a subset's chunks are a prefix.
  this->RankBucketStart.assign(RankBuckets + 1, 0);
  std::vector<int> bucketOf(static_cast<size_t>(count));
  for (vtkIdType c = 0; c < count; ++c)
  {
    bucketOf[c] = std::min(RankBuckets - 1, static_cast<int>(Rank(lines[c]) * RankBuckets));
    ++this->RankBucketStart[bucketOf[c] + 1];
  }
  for (int b = 0; b < RankBuckets; ++b)
  {
    this->RankBucketStart[b + 1] += this->RankBucketStart[b];
  }
  this->RankOrder.resize(static_cast<size_t>(count));
  std::vector<vtkIdType> cursor(this->RankBucketStart.begin(), this->RankBucketStart.end() - 1);
  for (vtkIdType c = 0; c < count; ++c)
  {
    this->RankOrder[cursor[bucketOf[c]]++] = static_cast<std::uint32_t>(c);
  }
  this->Order.clear();
  this->GroupStarts.assign(1, 0);
  this->OrderedProjection.clear();
  this->DrawnPositions.clear();
  this->Drawn = 0;
  this->Hidden = 0;
}

//------------------------------------------------------------------------------
std::uint32_t vtkSplineTubeVisibility::EncodePart(const float chunk[4], const double part[4])
{
  const double inverse = 1.0 / std::max(static_cast<double>(chunk[3]), 1e-30);
  std::uint32_t code = 0;
  for (int k = 0; k < 3; ++k)
  {
    const double o = std::max(-1.0, std::min(1.0, (part[k] - chunk[k]) * inverse));
    // Rounded to nearest (o + 1 >= 0: adding a half and truncating is lround, without its call).
    code |= static_cast<std::uint32_t>((o + 1.0) * 127.5 + 0.5) << (8 * k);
  }
  const double q = std::ceil(std::max(0.0, part[3]) * inverse * 255.0);
  code |= static_cast<std::uint32_t>(std::min(255.0, q)) << 24;
  return code;
}

//------------------------------------------------------------------------------
void vtkSplineTubeVisibility::DecodePart(const float chunk[4], std::uint32_t code, float part[4])
{
  const double r = chunk[3];
  for (int k = 0; k < 3; ++k)
  {
    part[k] = static_cast<float>(chunk[k] + r * (((code >> (8 * k)) & 255u) / 127.5 - 1.0));
  }
  // Widened by the centre's rounding (half a step per coordinate) and float round-off.
  part[3] = static_cast<float>(r * ((code >> 24) / 255.0 + 0.5 * std::sqrt(3.0) / 127.5) * 1.0001);
}

//------------------------------------------------------------------------------
double vtkSplineTubeVisibility::Rank(std::uint32_t line)
{
  // A 32-bit integer hash (lowbias32, C. Wellons): good avalanche, cheap.
  std::uint32_t x = line;
  x ^= x >> 16;
  x *= 0x7feb352dU;
  x ^= x >> 15;
  x *= 0x846ca68bU;
  x ^= x >> 16;
  return x / 4294967296.0;
}

//------------------------------------------------------------------------------
bool vtkSplineTubeVisibility::Project(
  const float* sphere, const View& view, double pixelSlope[2], Projected& out) const
{
  const double* mv = view.ModelView;
  const double* p = view.Projection;
  double c[3];
  for (int r = 0; r < 3; ++r)
  {
    c[r] =
      At(mv, r, 0) * sphere[0] + At(mv, r, 1) * sphere[1] + At(mv, r, 2) * sphere[2] + At(mv, r, 3);
  }
  const bool perspective = At(p, 3, 2) != 0.0;
  double radius = sphere[3] * this->Scale;
  // Widen by a pixel at the sphere's far side (sub-pixel lines drawn a pixel wide).
  const double slope = std::max(pixelSlope[0], pixelSlope[1]);
  radius += perspective ? slope * std::abs(-c[2] + radius) : slope;

  // Frustum planes (view coordinates).
  for (const auto& plane : this->Planes)
  {
    if (plane[0] * c[0] + plane[1] * c[1] + plane[2] * c[2] + plane[3] < -radius)
    {
      return false;
    }
  }
  const int width = view.Width;
  const int height = view.Height;
  // w over the sphere's box; near the eye plane the rectangle is the viewport.
  auto clipW = [&](double x, double y, double z)
  { return At(p, 3, 0) * x + At(p, 3, 1) * y + At(p, 3, 2) * z + At(p, 3, 3); };
  const double wScale = std::abs(At(p, 3, 0)) + std::abs(At(p, 3, 1)) + std::abs(At(p, 3, 2));
  const double wMin = clipW(c[0], c[1], c[2]) - wScale * radius;
  if (wMin <= 1e-9 * (std::abs(At(p, 3, 3)) + std::abs(c[2]) + radius))
  {
    out = { 0, 0, static_cast<std::uint16_t>(std::max(0, std::min(width - 1, 65535))),
      static_cast<std::uint16_t>(std::max(0, std::min(height - 1, 65535))), 0.0f };
    return true;
  }
  double lo[2] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MAX };
  double hi[2] = { VTK_DOUBLE_MIN, VTK_DOUBLE_MIN };
  if (At(p, 3, 0) == 0.0 && At(p, 3, 1) == 0.0 && At(p, 0, 1) == 0.0 && At(p, 1, 0) == 0.0)
  {
    // The cameras' projections: w depends on z only, the x (y) row on x (y)
    // and z. Over the box, each NDC coordinate is linear in x (y) and, w
    // being positive, monotone in z: its extremes are at the four corners of
    // (x or y) and z, with two divisions instead of the eight corners' eight.
    // Widened by a relative 1e-12 for the rounding of the reciprocal.
    const double z[2] = { c[2] - radius, c[2] + radius };
    const double invW[2] = { 1.0 / clipW(0.0, 0.0, z[0]), 1.0 / clipW(0.0, 0.0, z[1]) };
    for (int a = 0; a < 2; ++a)
    {
      for (int k = 0; k < 4; ++k)
      {
        const double u = c[a] + ((k & 1) ? radius : -radius);
        const double ndc = (At(p, a, a) * u + At(p, a, 2) * z[k >> 1] + At(p, a, 3)) * invW[k >> 1];
        lo[a] = std::min(lo[a], ndc);
        hi[a] = std::max(hi[a], ndc);
      }
      const double pad = 1e-12 * (std::abs(lo[a]) + std::abs(hi[a]) + 1.0);
      lo[a] -= pad;
      hi[a] += pad;
    }
  }
  else
  {
    for (int k = 0; k < 8; ++k)
    {
      const double x = c[0] + ((k & 1) ? radius : -radius);
      const double y = c[1] + ((k & 2) ? radius : -radius);
      const double z = c[2] + ((k & 4) ? radius : -radius);
      const double w = clipW(x, y, z);
      for (int a = 0; a < 2; ++a)
      {
        const double ndc = (At(p, a, 0) * x + At(p, a, 1) * y + At(p, a, 2) * z + At(p, a, 3)) / w;
        lo[a] = std::min(lo[a], ndc);
        hi[a] = std::max(hi[a], ndc);
      }
    }
  }
  const double x0 = std::floor((0.5 * lo[0] + 0.5) * width) - 1.0;
  const double x1 = std::floor((0.5 * hi[0] + 0.5) * width) + 1.0;
  const double y0 = std::floor((0.5 * lo[1] + 0.5) * height) - 1.0;
  const double y1 = std::floor((0.5 * hi[1] + 0.5) * height) + 1.0;
  if (x1 < 0.0 || y1 < 0.0 || x0 > width - 1 || y0 > height - 1)
  {
    return false;
  }
  // (OpenGL viewports are far below 65535 pixels: GL_MAX_VIEWPORT_DIMS.)
  out.X0 = static_cast<std::uint16_t>(std::min(std::max(x0, 0.0), 65535.0));
  out.Y0 = static_cast<std::uint16_t>(std::min(std::max(y0, 0.0), 65535.0));
  out.X1 = static_cast<std::uint16_t>(std::max(std::min({ x1, width - 1.0, 65535.0 }), 0.0));
  out.Y1 = static_cast<std::uint16_t>(std::max(std::min({ y1, height - 1.0, 65535.0 }), 0.0));
  // Nearest window depth: window depth grows with the distance -z for the
  // projections of cameras (no x, y terms in the depth and w rows).
  const double z = c[2] + radius;
  const double clipZ = At(p, 2, 2) * z + At(p, 2, 3);
  const double w = At(p, 3, 2) * z + At(p, 3, 3);
  const double ndc = w > 0.0 ? clipZ / w : -1.0;
  out.Depth = static_cast<float>(std::max(0.0, std::min(1.0, 0.5 * ndc + 0.5)));
  return true;
}

//------------------------------------------------------------------------------
void vtkSplineTubeVisibility::BeginFrame(
  const View& view, double fraction, bool occlusion, bool useLastFrame)
{
  const double* p = view.Projection;
  this->Scale = SpectralNorm3(view.ModelView);
  // Frustum planes in view coordinates: row 3 +- rows 0, 1, 2, normalized.
  for (int k = 0; k < 3; ++k)
  {
    for (int side = 0; side < 2; ++side)
    {
      double* plane = this->Planes[2 * k + side];
      for (int c = 0; c < 4; ++c)
      {
        plane[c] = At(p, 3, c) + (side == 0 ? 1.0 : -1.0) * At(p, k, c);
      }
      const double len = std::sqrt(plane[0] * plane[0] + plane[1] * plane[1] + plane[2] * plane[2]);
      for (int c = 0; c < 4 && len > 0.0; ++c)
      {
        plane[c] /= len;
      }
    }
  }
  // The occlusion test needs depths that depend on z only.
  this->Occlusion = occlusion && At(p, 2, 0) == 0.0 && At(p, 2, 1) == 0.0 && At(p, 3, 0) == 0.0 &&
    At(p, 3, 1) == 0.0;
  double pixelSlope[2] = { 2.0 / (std::abs(At(p, 0, 0)) * std::max(view.Width, 1)),
    2.0 / (std::abs(At(p, 1, 1)) * std::max(view.Height, 1)) };
  for (double& s : pixelSlope)
  {
    if (!std::isfinite(s))
    {
      s = 0.0;
    }
  }

  this->CurrentView = view;
  this->PixelSlope[0] = pixelSlope[0];
  this->PixelSlope[1] = pixelSlope[1];
  // The candidates: all chunks, or those of the lines in the subset (a
  // prefix of the chunks ordered by their line's rank).
  const vtkIdType n = this->NumberOfChunks;
  const bool all = fraction >= 1.0;
  vtkIdType numCandidates = n;
  if (!all)
  {
    const int b = std::max(0, std::min(RankBuckets, static_cast<int>(fraction * RankBuckets) + 1));
    numCandidates = this->RankBucketStart[b];
  }
  auto candidate = [&](vtkIdType i) -> vtkIdType { return all ? i : this->RankOrder[i]; };
  // Project the candidates (in parallel), with a sort key per candidate: 0
  // outside the frustum, else 1 + its depth bucket (4096 buckets of nearest
  // depth), the chunks visible in the last frame first. The projections live
  // while the frame starts only: the culling keeps them in draw order
  // (OrderedProjection), nothing per chunk is kept between frames.
  constexpr int Buckets = 4096;
  constexpr int TileShift = 6; // tiles of 64 pixels square
  const bool temporal = this->Occlusion && useLastFrame;
  const int tilesX = (view.Width >> TileShift) + 1;
  const int tilesY = (view.Height >> TileShift) + 1;
  std::vector<Projected> projected(static_cast<size_t>(numCandidates));
  std::vector<std::uint16_t> key(static_cast<size_t>(numCandidates), 0);
  vtkSMPTools::For(0, numCandidates,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        const vtkIdType c = candidate(i);
        Projected& pr = projected[i];
        if ((!all && Rank(this->Lines[c]) >= fraction) ||
          (this->LineMask && !this->LineMask[this->Lines[c]]) ||
          !this->Project(this->Spheres + 4 * c, view, pixelSlope, pr))
        {
          continue;
        }
        const int b = std::min(Buckets - 1, static_cast<int>(pr.Depth * Buckets));
        key[i] = static_cast<std::uint16_t>(1 + ((temporal && this->Visible[c]) ? b : Buckets + b));
      }
    });

  // Order front to back: a counting sort by the key. Order holds candidate
  // indices (their projections are read below) until the groups are made.
  this->Order.clear();
  this->DrawnPositions.clear();
  this->Drawn = 0;
  this->Hidden = 0;
  std::vector<vtkIdType> counts(2 * Buckets + 2, 0);
  for (vtkIdType i = 0; i < numCandidates; ++i)
  {
    ++counts[key[i]];
  }
  // counts[k] becomes the start of key k (key 0, outside, is not ordered).
  vtkIdType total = 0;
  for (int k = 1; k <= 2 * Buckets; ++k)
  {
    const vtkIdType n = counts[k];
    counts[k] = total;
    total += n;
  }
  const vtkIdType numInside = total;
  const vtkIdType numTemporal = counts[Buckets + 1];
  this->Order.resize(static_cast<size_t>(numInside));
  // With occlusion, the screen tile of each chunk's rectangle centre in
  // depth order too (read in order below, not gathered from the projections).
  const size_t numTiles = std::min<size_t>(static_cast<size_t>(tilesX) * tilesY, 65536);
  std::vector<std::uint16_t> tileOf(this->Occlusion ? static_cast<size_t>(numInside) : 0);
  for (vtkIdType i = 0; i < numCandidates; ++i)
  {
    if (key[i])
    {
      const vtkIdType position = counts[key[i]]++;
      this->Order[position] = static_cast<std::uint32_t>(i);
      if (this->Occlusion)
      {
        const Projected& pr = projected[i];
        const size_t tile = static_cast<size_t>(((pr.Y0 + pr.Y1) / 2) >> TileShift) * tilesX +
          (((pr.X0 + pr.X1) / 2) >> TileShift);
        tileOf[position] = static_cast<std::uint16_t>(std::min(tile, numTiles - 1));
      }
    }
  }

  // Groups: the last frame's visible chunks, then the rest by layers of
  // screen tiles: per tile its nearest 64 chunks, then the next 64, 128,
  // 256, ... (doubling), so that each group covers the whole picture with
  // the layer in front of what the earlier groups drew. Small steps: a
  // pyramid costs a few milliseconds, drawing what it would have hidden far
  // more (most of all in a frame without a last frame).
  this->GroupStarts.assign(1, 0);
  if (this->Occlusion && numTemporal > 0)
  {
    this->GroupStarts.push_back(numTemporal);
  }
  if (this->Occlusion)
  {
    constexpr int Layers = 17; // ranks [0, 64), [64, 128), ..., [2^21, inf)
    std::vector<std::uint32_t> rank(numTiles, 0);
    std::vector<unsigned char> layer(static_cast<size_t>(numInside - numTemporal), 0);
    std::vector<vtkIdType> layerCounts(Layers + 1, 0);
    for (vtkIdType i = numTemporal; i < numInside; ++i)
    {
      const std::uint32_t r = rank[tileOf[i]]++;
      int l = 0;
      for (std::uint32_t limit = 64; l + 1 < Layers && r >= limit; limit *= 2)
      {
        ++l;
      }
      layer[i - numTemporal] = static_cast<unsigned char>(l);
      ++layerCounts[l + 1];
    }
    for (int l = 0; l < Layers; ++l)
    {
      layerCounts[l + 1] += layerCounts[l];
    }
    // A stable counting sort by layer (depth order within each).
    std::vector<std::uint32_t> rest(this->Order.begin() + numTemporal, this->Order.end());
    std::vector<vtkIdType> cursor(layerCounts.begin(), layerCounts.end() - 1);
    for (size_t i = 0; i < rest.size(); ++i)
    {
      this->Order[numTemporal + cursor[layer[i]]++] = rest[i];
    }
    for (int l = 0; l < Layers; ++l)
    {
      if (layerCounts[l + 1] > layerCounts[l])
      {
        this->GroupStarts.push_back(numTemporal + layerCounts[l + 1]);
      }
    }
  }
  else
  {
    this->GroupStarts.push_back(numInside);
  }
  // The projections in draw order (with occlusion only: the culling reads
  // them in order, not scattered over the chunks), candidate indices to chunks.
  this->OrderedProjection.resize(this->Occlusion ? static_cast<size_t>(numInside) : 0);
  vtkSMPTools::For(0, numInside,
    [&](vtkIdType b, vtkIdType e)
    {
      for (vtkIdType i = b; i < e; ++i)
      {
        if (this->Occlusion)
        {
          this->OrderedProjection[i] = projected[this->Order[i]];
        }
        this->Order[i] = static_cast<std::uint32_t>(candidate(this->Order[i]));
      }
    });
}

//------------------------------------------------------------------------------
bool vtkSplineTubeVisibility::IsHidden(const Projected& pr, const DepthPyramid& pyramid) const
{
  if (pr.Depth <= 0.0f)
  {
    return false;
  }
  const double occluder = pyramid.MaximumOver(pr.X0, pr.Y0, pr.X1, pr.Y1);
  return pr.Depth + this->DepthBias > occluder + DepthTolerance;
}

//------------------------------------------------------------------------------
bool vtkSplineTubeVisibility::IsHidden(
  std::uint32_t chunk, const Projected& projected, const DepthPyramid& pyramid) const
{
  if (this->IsHidden(projected, pyramid))
  {
    return true;
  }
  if (!this->Parts)
  {
    return false;
  }
  // The parts: hidden when each is (outside the frustum counts as hidden),
  // tested in groups of PartGroup: first a sphere around the group's parts
  // (it hides them all when it is hidden: their rectangles lie in its
  // rectangle, their depths behind its depth), then each part.
  const float* sphere = this->Spheres + 4 * chunk;
  double slope[2] = { this->PixelSlope[0], this->PixelSlope[1] };
  const std::uint32_t first = this->PartFirsts[chunk];
  const std::uint32_t last = this->PartFirsts[chunk + 1];
  for (std::uint32_t g = first; g < last; g += PartGroup)
  {
    const std::uint32_t count = std::min<std::uint32_t>(PartGroup, last - g);
    float parts[PartGroup][4];
    for (std::uint32_t k = 0; k < count; ++k)
    {
      DecodePart(sphere, this->Parts[g + k], parts[k]);
    }
    Projected pr;
    if (count > 1)
    {
      float around[4];
      EnclosingSphere(parts, count, around);
      if (!this->Project(around, this->CurrentView, slope, pr) || this->IsHidden(pr, pyramid))
      {
        continue;
      }
    }
    for (std::uint32_t k = 0; k < count; ++k)
    {
      if (this->Project(parts[k], this->CurrentView, slope, pr) && !this->IsHidden(pr, pyramid))
      {
        return false;
      }
    }
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkSplineTubeVisibility::EnclosingSphere(
  const float (*spheres)[4], std::uint32_t count, float out[4])
{
  double center[3] = { 0.0, 0.0, 0.0 };
  for (std::uint32_t k = 0; k < count; ++k)
  {
    for (int i = 0; i < 3; ++i)
    {
      center[i] += spheres[k][i] / count;
    }
  }
  double radius = 0.0;
  for (std::uint32_t k = 0; k < count; ++k)
  {
    const double dx = spheres[k][0] - center[0];
    const double dy = spheres[k][1] - center[1];
    const double dz = spheres[k][2] - center[2];
    radius = std::max(radius, std::sqrt(dx * dx + dy * dy + dz * dz) + spheres[k][3]);
  }
  for (int i = 0; i < 3; ++i)
  {
    out[i] = static_cast<float>(center[i]);
  }
  // Widened for the rounding of the centre to float (half an ulp per
  // coordinate) and of the radius.
  const double ulp = 6e-8 * (std::abs(center[0]) + std::abs(center[1]) + std::abs(center[2]));
  out[3] = static_cast<float>((radius + ulp) * (1.0 + 1e-6));
}

//------------------------------------------------------------------------------
void vtkSplineTubeVisibility::CullGroup(
  int g, const DepthPyramid* pyramid, std::vector<std::uint32_t>& chunks)
{
  chunks.clear();
  if (g < 0 || g >= this->GetNumberOfGroups())
  {
    return;
  }
  const vtkIdType begin = this->GroupStarts[g];
  const vtkIdType end = this->GroupStarts[g + 1];
  if (!pyramid || !this->Occlusion)
  {
    chunks.assign(this->Order.begin() + begin, this->Order.begin() + end);
    for (vtkIdType i = begin; i < end && this->Occlusion; ++i)
    {
      this->DrawnPositions.push_back(static_cast<std::uint32_t>(i));
    }
  }
  else
  {
    std::vector<unsigned char> hidden(static_cast<size_t>(end - begin), 0);
    vtkSMPTools::For(begin, end,
      [&](vtkIdType b, vtkIdType e)
      {
        for (vtkIdType i = b; i < e; ++i)
        {
          hidden[i - begin] =
            this->IsHidden(this->Order[i], this->OrderedProjection[i], *pyramid) ? 1 : 0;
        }
      });
    for (vtkIdType i = begin; i < end; ++i)
    {
      if (!hidden[i - begin])
      {
        chunks.push_back(this->Order[i]);
        this->DrawnPositions.push_back(static_cast<std::uint32_t>(i));
      }
    }
    this->Hidden += (end - begin) - static_cast<vtkIdType>(chunks.size());
  }
  this->Drawn += static_cast<vtkIdType>(chunks.size());
}

//------------------------------------------------------------------------------
void vtkSplineTubeVisibility::EndFrame(const DepthPyramid* pyramid)
{
  std::fill(this->Visible.begin(), this->Visible.end(), 0);
  if (pyramid && this->Occlusion)
  {
    const vtkIdType n = static_cast<vtkIdType>(this->DrawnPositions.size());
    vtkSMPTools::For(0, n,
      [&](vtkIdType b, vtkIdType e)
      {
        for (vtkIdType i = b; i < e; ++i)
        {
          const std::uint32_t position = this->DrawnPositions[i];
          const std::uint32_t c = this->Order[position];
          this->Visible[c] =
            this->IsHidden(c, this->OrderedProjection[position], *pyramid) ? 0 : 1;
        }
      });
  }
  // (Without a pyramid nothing is known of what is visible.)
  this->DrawnPositions.clear();
}
