// SPDX-License-Identifier: BSD-3-Clause
// vtkSplineTubeVisibility (the line renderers' culling, on the CPU) against
// brute force:
// - the encoded part spheres contain the parts;
// - the depth pyramid's maximum over a rectangle is at least the brute-force
//   maximum of its pixels (and equal for single pixels);
// - frustum culling and grouping: every chunk whose sphere is seen by some
//   pixel's ray is in exactly one group, and no chunk appears twice;
// - occlusion culling is conservative: for random spheres in front of and
//   behind a random depth image, every chunk dropped as hidden is hidden at
//   every pixel whose ray meets its sphere (ray-traced, in perspective and
//   parallel projection); and most chunks behind a near wall are dropped;
// - negative control: with a depth bias, the brute force finds visible
//   chunks dropped;
// - the interaction subsets are nested and hold about the asked fraction.
#include "vtkSplineTubeVisibility.h"

#include "SplineVizTestUtilities.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <random>
#include <set>
#include <vector>

namespace
{
using View = vtkSplineTubeVisibility::View;

/// A camera at the origin looking down -z (view = chunk coordinates scaled
/// by `scale` and moved by -distance along z), perspective or parallel.
View MakeView(bool parallel, double scale, int width, int height)
{
  View v;
  std::fill(v.ModelView, v.ModelView + 16, 0.0);
  v.ModelView[0] = v.ModelView[5] = v.ModelView[10] = scale;
  v.ModelView[14] = -10.0;
  v.ModelView[15] = 1.0;
  std::fill(v.Projection, v.Projection + 16, 0.0);
  const double n = 2.0;
  const double f = 30.0;
  const double aspect = static_cast<double>(width) / height;
  if (parallel)
  {
    const double h = 4.0;
    v.Projection[0] = 1.0 / (h * aspect);
    v.Projection[5] = 1.0 / h;
    v.Projection[10] = -2.0 / (f - n);
    v.Projection[14] = -(f + n) / (f - n);
    v.Projection[15] = 1.0;
  }
  else
  {
    const double t = 1.0 / std::tan(0.5 * 0.7);
    v.Projection[0] = t / aspect;
    v.Projection[5] = t;
    v.Projection[10] = -(f + n) / (f - n);
    v.Projection[11] = -1.0;
    v.Projection[14] = -2.0 * f * n / (f - n);
  }
  v.Width = width;
  v.Height = height;
  return v;
}

double At(const double* m, int r, int c)
{
  return m[4 * c + r];
}

/// The nearest window depth where the ray of pixel (x, y) meets the sphere
/// (chunk coordinates), or -1.
double RayDepth(const View& v, const float* sphere, int x, int y)
{
  const double* p = v.Projection;
  const double ndc[2] = { 2.0 * (x + 0.5) / v.Width - 1.0, 2.0 * (y + 0.5) / v.Height - 1.0 };
  // View-space ray.
  double origin[3];
  double dir[3];
  const bool parallel = At(p, 3, 2) == 0.0;
  if (parallel)
  {
    origin[0] = (ndc[0] - At(p, 0, 3)) / At(p, 0, 0);
    origin[1] = (ndc[1] - At(p, 1, 3)) / At(p, 1, 1);
    origin[2] = 0.0;
    dir[0] = dir[1] = 0.0;
    dir[2] = -1.0;
  }
  else
  {
    origin[0] = origin[1] = origin[2] = 0.0;
    dir[0] = ndc[0] / At(p, 0, 0);
    dir[1] = ndc[1] / At(p, 1, 1);
    dir[2] = -1.0;
  }
  const double s = v.ModelView[0];
  const double c[3] = { s * sphere[0], s * sphere[1], s * sphere[2] + v.ModelView[14] };
  const double r = s * sphere[3];
  double oc[3];
  for (int k = 0; k < 3; ++k)
  {
    oc[k] = origin[k] - c[k];
  }
  const double a = dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2];
  const double b = oc[0] * dir[0] + oc[1] * dir[1] + oc[2] * dir[2];
  const double cc = oc[0] * oc[0] + oc[1] * oc[1] + oc[2] * oc[2] - r * r;
  const double disc = b * b - a * cc;
  if (disc < 0.0)
  {
    return -1.0;
  }
  const double t = (-b - std::sqrt(disc)) / a;
  if (t < 0.0)
  {
    return 0.0; // inside: touches the eye
  }
  const double z = origin[2] + t * dir[2];
  const double clipZ = At(p, 2, 2) * z + At(p, 2, 3);
  const double w = At(p, 3, 2) * z + At(p, 3, 3);
  return 0.5 * clipZ / w + 0.5;
}

void TestParts(SplineVizTestStatus& status, std::mt19937& rng)
{
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  long bad = 0;
  for (int trial = 0; trial < 20000; ++trial)
  {
    const float chunk[4] = { static_cast<float>(5 * u(rng)), static_cast<float>(5 * u(rng)),
      static_cast<float>(5 * u(rng)), static_cast<float>(0.1 + std::abs(u(rng))) };
    double part[4];
    const double rp = chunk[3] * std::abs(u(rng));
    for (int k = 0; k < 3; ++k)
    {
      part[k] = chunk[k] + (chunk[3] - rp) * u(rng) / std::sqrt(3.0);
    }
    part[3] = rp;
    float decoded[4];
    vtkSplineTubeVisibility::DecodePart(
      chunk, vtkSplineTubeVisibility::EncodePart(chunk, part), decoded);
    double d2 = 0.0;
    for (int k = 0; k < 3; ++k)
    {
      d2 += (decoded[k] - part[k]) * (decoded[k] - part[k]);
    }
    bad += std::sqrt(d2) + part[3] > decoded[3] ? 1 : 0;
  }
  SV_CHECK_MSG(status, bad == 0, bad << " decoded part spheres do not contain their parts");
}

void TestEnclosingSphere(SplineVizTestStatus& status, std::mt19937& rng)
{
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  long bad = 0;
  long loose = 0;
  for (int trial = 0; trial < 20000; ++trial)
  {
    // Far from the origin (float rounding of the centre matters) and small.
    const double offset = 1000.0 * u(rng);
    const std::uint32_t count = 1 + trial % 4;
    float spheres[4][4];
    for (std::uint32_t k = 0; k < count; ++k)
    {
      for (int i = 0; i < 3; ++i)
      {
        spheres[k][i] = static_cast<float>(offset + 0.01 * u(rng));
      }
      spheres[k][3] = static_cast<float>(0.001 * std::abs(u(rng)));
    }
    float around[4];
    vtkSplineTubeVisibility::EnclosingSphere(spheres, count, around);
    for (std::uint32_t k = 0; k < count; ++k)
    {
      double d2 = 0.0;
      for (int i = 0; i < 3; ++i)
      {
        const double d = static_cast<double>(spheres[k][i]) - around[i];
        d2 += d * d;
      }
      bad += std::sqrt(d2) + spheres[k][3] > around[3] ? 1 : 0;
    }
    // Not a useless bound either: within 2x of the spheres' own extent (plus
    // the padding for float rounding at this distance from the origin).
    double extent = 0.0;
    for (std::uint32_t k = 0; k < count; ++k)
    {
      extent = std::max(extent, static_cast<double>(spheres[k][3]));
      for (std::uint32_t j = 0; j < count; ++j)
      {
        double d2 = 0.0;
        for (int i = 0; i < 3; ++i)
        {
          const double d = static_cast<double>(spheres[k][i]) - spheres[j][i];
          d2 += d * d;
        }
        extent = std::max(extent, std::sqrt(d2) + spheres[k][3] + spheres[j][3]);
      }
    }
    loose += around[3] > 2.0 * extent + 1e-6 * (std::abs(offset) + 1.0) ? 1 : 0;
  }
  SV_CHECK_MSG(status, bad == 0, bad << " enclosing spheres do not contain their spheres");
  SV_CHECK_MSG(status, loose == 0, loose << " enclosing spheres more than twice too large");
}

void TestPyramid(SplineVizTestStatus& status, std::mt19937& rng)
{
  const int w = 97;
  const int h = 61;
  std::vector<float> depth(w * h);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (float& d : depth)
  {
    d = u(rng);
  }
  vtkSplineTubeVisibility::DepthPyramid pyramid;
  pyramid.Build(depth.data(), w, h);
  std::uniform_int_distribution<int> ux(0, w - 1);
  std::uniform_int_distribution<int> uy(0, h - 1);
  long below = 0;
  long single = 0;
  for (int trial = 0; trial < 5000; ++trial)
  {
    int x0 = ux(rng), x1 = ux(rng), y0 = uy(rng), y1 = uy(rng);
    if (trial % 5 == 0)
    {
      x1 = x0;
      y1 = y0;
    }
    if (x0 > x1)
    {
      std::swap(x0, x1);
    }
    if (y0 > y1)
    {
      std::swap(y0, y1);
    }
    float brute = 0.0f;
    for (int y = y0; y <= y1; ++y)
    {
      for (int x = x0; x <= x1; ++x)
      {
        brute = std::max(brute, depth[y * w + x]);
      }
    }
    const float m = pyramid.MaximumOver(x0, y0, x1, y1);
    below += m < brute ? 1 : 0;
    single += (x0 == x1 && y0 == y1 && m != brute) ? 1 : 0;
  }
  SV_CHECK_MSG(status, below == 0, below << " pyramid maxima below the brute-force maxima");
  SV_CHECK_MSG(status, single == 0, single << " single-pixel maxima not exact");
}

/// Random chunks; a depth image with a wall at depth `wall` over the left
/// part of the image and random depths elsewhere; culling checked by rays.
void TestCulling(SplineVizTestStatus& status, std::mt19937& rng, bool parallel, double bias,
  long& wronglyHidden, long& hiddenBehindWall, long& behindWall)
{
  const int w = 128;
  const int h = 96;
  const View view = MakeView(parallel, 1.0, w, h);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const int n = 1200;
  std::vector<float> spheres(4 * n);
  std::vector<std::uint32_t> lines(n);
  for (int c = 0; c < n; ++c)
  {
    spheres[4 * c] = static_cast<float>(5.0 * u(rng));
    spheres[4 * c + 1] = static_cast<float>(4.0 * u(rng));
    spheres[4 * c + 2] = static_cast<float>(6.0 * u(rng));
    spheres[4 * c + 3] = static_cast<float>(0.05 + 0.3 * std::abs(u(rng)));
    lines[c] = static_cast<std::uint32_t>(c / 3);
  }
  // Occluders: a wall at z = 3 (depth of the chunk plane z = 3) on the left
  // half, random depths on the right.
  std::vector<float> depth(w * h);
  double wallDepth = 0.0;
  {
    // The window depth of view z = 3 - 10.
    const double z = 3.0 - 10.0;
    const double* p = view.Projection;
    wallDepth = 0.5 * (At(p, 2, 2) * z + At(p, 2, 3)) / (At(p, 3, 2) * z + At(p, 3, 3)) + 0.5;
  }
  std::uniform_real_distribution<float> ud(0.3f, 1.0f);
  for (int y = 0; y < h; ++y)
  {
    for (int x = 0; x < w; ++x)
    {
      depth[y * w + x] = x < w / 2 ? static_cast<float>(wallDepth) : ud(rng);
    }
  }
  vtkSplineTubeVisibility::DepthPyramid pyramid;
  pyramid.Build(depth.data(), w, h);

  vtkSplineTubeVisibility visibility;
  visibility.SetChunks(spheres.data(), lines.data(), n);
  visibility.SetDepthBias(bias);
  visibility.BeginFrame(view, 1.0, true, false);
  std::set<std::uint32_t> listed;
  std::set<std::uint32_t> drawn;
  std::vector<std::uint32_t> chunks;
  long duplicates = 0;
  for (int g = 0; g < visibility.GetNumberOfGroups(); ++g)
  {
    visibility.CullGroup(g, nullptr, chunks);
    for (std::uint32_t c : chunks)
    {
      duplicates += listed.insert(c).second ? 0 : 1;
    }
  }
  SV_CHECK_MSG(status, duplicates == 0, duplicates << " chunks in two groups");
  // Every chunk some pixel's ray meets is listed; culling against the image.
  visibility.BeginFrame(view, 1.0, true, false);
  for (int g = 0; g < visibility.GetNumberOfGroups(); ++g)
  {
    visibility.CullGroup(g, &pyramid, chunks);
    drawn.insert(chunks.begin(), chunks.end());
  }
  long missing = 0;
  for (int c = 0; c < n; ++c)
  {
    bool seen = false;
    bool visible = false;
    bool fullyBehindWall = true;
    for (int y = 0; y < h; ++y)
    {
      for (int x = 0; x < w; ++x)
      {
        const double d = RayDepth(view, &spheres[4 * c], x, y);
        if (d < 0.0 || d > 1.0)
        {
          continue;
        }
        seen = true;
        visible = visible || d <= depth[y * w + x];
        fullyBehindWall = fullyBehindWall && x < w / 2 - 2 && d > wallDepth + 1e-3;
      }
    }
    if (seen && !listed.count(c))
    {
      ++missing;
    }
    if (visible && !drawn.count(c))
    {
      ++wronglyHidden;
    }
    if (seen && fullyBehindWall)
    {
      ++behindWall;
      hiddenBehindWall += drawn.count(c) ? 0 : 1;
    }
  }
  SV_CHECK_MSG(status, missing == 0,
    (parallel ? "parallel" : "perspective") << ": " << missing << " chunks in view not listed");
}

void TestSubsets(SplineVizTestStatus& status)
{
  const int n = 100000;
  long inHalf = 0;
  long inTenth = 0;
  long notNested = 0;
  for (int l = 0; l < n; ++l)
  {
    const double r = vtkSplineTubeVisibility::Rank(static_cast<std::uint32_t>(l));
    SV_CHECK(status, r >= 0.0 && r < 1.0);
    inHalf += r < 0.5 ? 1 : 0;
    inTenth += r < 0.1 ? 1 : 0;
    notNested += (r < 0.1 && !(r < 0.5)) ? 1 : 0;
  }
  std::cout << "subsets: " << inHalf << " of " << n << " below 0.5, " << inTenth << " below 0.1"
            << std::endl;
  SV_CHECK(status, std::abs(inHalf - n / 2) < 1500 && std::abs(inTenth - n / 10) < 900);
  SV_CHECK(status, notNested == 0);
}
}

int TestSplineTubeVisibility(int, char*[])
{
  SplineVizTestStatus status;
  std::mt19937 rng(7);
  TestParts(status, rng);
  TestEnclosingSphere(status, rng);
  TestPyramid(status, rng);
  for (bool parallel : { false, true })
  {
    long wrong = 0;
    long hidden = 0;
    long behind = 0;
    TestCulling(status, rng, parallel, 0.0, wrong, hidden, behind);
    std::cout << (parallel ? "parallel" : "perspective") << ": " << hidden << " of " << behind
              << " chunks behind the wall dropped, " << wrong << " visible ones dropped"
              << std::endl;
    SV_CHECK_MSG(status, wrong == 0, wrong << " visible chunks dropped");
    SV_CHECK_MSG(status, behind > 50 && hidden > 0.8 * behind,
      "only " << hidden << " of " << behind << " chunks behind the wall dropped");
    // Negative control: a bias drops visible chunks, and the rays see it.
    long biasedWrong = 0;
    TestCulling(status, rng, parallel, 0.2, biasedWrong, hidden, behind);
    std::cout << "  with a depth bias of 0.2: " << biasedWrong << " visible chunks dropped"
              << std::endl;
    SV_CHECK_MSG(status, biasedWrong > 10, "the brute force does not see a biased culling");
  }
  TestSubsets(status);
  return status.Result();
}
