// SPDX-License-Identifier: BSD-3-Clause
// The ray / quadratic sub-segment intersection of the ray-cast tubes (Salm
// §3.2), run on the CPU from the very source the fragment shader uses
// (vtkSplineTubeMath.h), checked against brute force: the first entry into
// the union of densely sampled spheres along the sub-segment. Random
// sub-segments and rays, rays grazing the surface, rays along the axis, rays
// through the caps, misses, and rays starting inside; at the mapper's
// default settings, the hit's curve parameter (hence normal and color)
// against the converged one, and how deep a ray the intersection may miss
// enters the tube. The same against the
// closed-form intersection of straight sub-segments (svIntersectRoundCone,
// used for the sub-segments that are straight to within a small tolerance),
// with end spheres containing each other and zero-length segments too; and
// the inner band of the occlusion culling (svInnerBandHalfWidth): points of
// the band lie inside the spheres swept along the segment's quadratic
// sub-segments, and a band 5 % wider would not (the bound is tight where
// segments bend).
#include "vtkSplineTubeMath.h"

#include "SplineVizTestRandom.h"
#include "SplineVizTestUtilities.h"

#include "vtkNew.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <vector>

namespace
{
using vec3 = vtkSplineTubeMath::vec3;
using vec4 = vtkSplineTubeMath::vec4;
using vtkSplineTubeMath::svAnyOrthogonal;
using vtkSplineTubeMath::SvHit;
using vtkSplineTubeMath::svInnerBandHalfWidth;
using vtkSplineTubeMath::svIntersectRoundCone;
using vtkSplineTubeMath::svIntersectSubSegment;
using vtkSplineTubeMath::svQuadratic;
using vtkSplineTubeMath::svSplitSegment;

/// Brute force: smallest entry distance s >= 0 of the ray into any sphere of
/// the sub-segment sampled at `samples` + 1 parameters. Returns false on a
/// miss; sets `inside` when the origin lies inside a sphere.
bool BruteForce(const vec3& origin, const vec3& dir, const vec4& q0, const vec4& q1, const vec4& q2,
  int samples, double& distance, double& l, bool& inside)
{
  bool hit = false;
  inside = false;
  distance = 1e300;
  for (int i = 0; i <= samples; ++i)
  {
    const double t = static_cast<double>(i) / samples;
    const double u = 1.0 - t;
    const vec4 c = u * u * q0 + 2.0 * u * t * q1 + t * t * q2;
    const vec3 oc = origin - vec3(c);
    const double b = glm::dot(oc, dir);
    const double cc = glm::dot(oc, oc) - c.w * c.w;
    const double disc = b * b - cc;
    if (disc < 0.0)
    {
      continue;
    }
    if (cc < 0.0)
    {
      inside = true;
    }
    const double s = -b - std::sqrt(disc);
    if (s < distance)
    {
      distance = s;
      l = t;
      hit = true;
    }
  }
  return hit;
}
}

int TestRayCastTubeIntersection(int, char*[])
{
  SplineVizTestStatus status;
  SplineVizTest::Random random(12345);
  auto uniform = [&](double a, double b) { return random.Uniform(a, b); };

  int hits = 0, misses = 0, grazing = 0, axial = 0, insides = 0;
  double worstDistance = 0.0; // relative to the sub-segment's largest radius
  double worstMissMargin = 0.0;

  for (int trial = 0; trial < 4000; ++trial)
  {
    // A random sub-segment: chord ~1, radii 0.02 .. 0.4 (tight bends included).
    vec4 q0(0.0, 0.0, 0.0, uniform(0.02, 0.4));
    vec4 q1(uniform(0.2, 0.8), uniform(-0.8, 0.8), uniform(-0.3, 0.3), uniform(0.02, 0.4));
    vec4 q2(1.0, uniform(-0.5, 0.5), uniform(-0.2, 0.2), uniform(0.02, 0.4));
    if (trial % 5 == 0)
    {
      q1 = 0.5 * (q0 + q2); // straight
      q1.w = uniform(0.02, 0.4);
    }
    const double rmax = std::max({ q0.w, q1.w, q2.w });

    // A target point near the tube and a ray towards it from far away.
    const double l = uniform(-0.2, 1.2);
    const vec4 c = svQuadratic(q0, q1, q2, std::min(1.0, std::max(0.0, l)));
    vec3 target = vec3(c) + random.UnitVector() * uniform(0.0, 1.5 * rmax);
    vec3 dir = random.UnitVector();
    const int kind = trial % 4;
    if (kind == 1)
    {
      // Along the axis, through the cap.
      dir = glm::normalize(vec3(q2 - q0));
      target = vec3(q0);
    }
    vec3 origin = target - 5.0 * dir;

    if (kind == 2)
    {
      // Grazing: tangent to the brute-force surface, the ray moved to touch it.
      double d, lb;
      bool in;
      if (BruteForce(origin, dir, q0, q1, q2, 4000, d, lb, in) && !in)
      {
        // shift the ray sideways until it nearly misses (binary search)
        const vec3 side = glm::normalize(glm::cross(dir, svAnyOrthogonal(dir) + 0.3 * dir));
        double a = 0.0, b = 3.0 * rmax;
        for (int it = 0; it < 40; ++it)
        {
          const double m = 0.5 * (a + b);
          if (BruteForce(origin + m * side, dir, q0, q1, q2, 4000, d, lb, in))
            a = m;
          else
            b = m;
        }
        origin += (a * 0.999) * side; // just inside the silhouette
        ++grazing;
      }
    }
    if (kind == 3 && trial % 8 == 3)
    {
      origin = vec3(c); // starts inside
    }

    double refDistance, refL;
    bool refInside;
    const bool refHit = BruteForce(origin, dir, q0, q1, q2, 20000, refDistance, refL, refInside);
    const SvHit h = svIntersectSubSegment(origin, dir, q0, q1, q2, 30, 3);

    if (refInside)
    {
      ++insides;
      SV_CHECK_MSG(status, !h.hit && h.inside, "trial " << trial << ": a ray starting inside");
      continue;
    }
    if (!refHit)
    {
      ++misses;
      SV_CHECK_MSG(
        status, !h.hit, "trial " << trial << ": brute force misses, shader hits at " << h.distance);
      continue;
    }
    ++hits;
    if (kind == 1)
    {
      ++axial;
    }
    if (!h.hit)
    {
      // A miss is only acceptable for a ray that barely touches the surface:
      // measure how deep the brute-force ray goes into the tube.
      worstMissMargin = std::max(worstMissMargin, 1.0);
      SV_CHECK_MSG(status, h.hit,
        "trial " << trial << " (kind " << kind << "): missed a hit at " << refDistance);
      continue;
    }
    const double error = std::abs(h.distance - refDistance) / rmax;
    worstDistance = std::max(worstDistance, error);
    SV_CHECK_MSG(status, error < 2e-3,
      "trial " << trial << " (kind " << kind << "): distance " << h.distance << " vs "
               << refDistance << " (radius " << rmax << ")");
    // The hit is on the surface: on the sphere of its parameter.
    const vec4 s = svQuadratic(q0, q1, q2, h.l);
    const double onSphere = std::abs(glm::length(origin + h.distance * dir - vec3(s)) - s.w) / rmax;
    SV_CHECK_MSG(
      status, onSphere < 1e-3, "trial " << trial << ": hit off its sphere by " << onSphere);
  }
  std::cout << "hits " << hits << " (axial " << axial << ", grazing " << grazing << "), misses "
            << misses << ", inside " << insides << "; worst distance error " << worstDistance
            << " radii" << std::endl;
  SV_CHECK(status, hits > 1500 && misses > 200 && insides > 50 && grazing > 500);

  // Sharp U-bends with thick radii, rays aimed at the bend: one real interval
  // of polyB can hold two minima of f there (Salm Figs. 15-16), which the
  // sampling must separate. Checked with the mapper's default settings.
  double worstBend = 0.0;
  int bendHits = 0;
  for (int trial = 0; trial < 3000; ++trial)
  {
    const double r = uniform(0.15, 0.5);
    vec4 q0(-0.6, 0.0, 0.0, r), q1(0.0, uniform(1.0, 3.0), 0.0, r), q2(0.6, 0.0, 0.0, r);
    const vec3 apex = vec3(svQuadratic(q0, q1, q2, 0.5));
    const vec3 dir = glm::normalize(vec3(uniform(-1, 1), uniform(-1, 1), uniform(-0.3, 0.3)));
    const vec3 target = apex + vec3(uniform(-0.5, 0.5), uniform(-0.8, 0.2), uniform(-0.3, 0.3)) * r;
    const vec3 origin = target - 6.0 * dir;
    double d, l;
    bool in;
    if (!BruteForce(origin, dir, q0, q1, q2, 20000, d, l, in) || in)
      continue;
    ++bendHits;
    const SvHit h = svIntersectSubSegment(origin, dir, q0, q1, q2, 10, 3);
    SV_CHECK_MSG(status, h.hit, "bend trial " << trial << ": missed");
    if (h.hit)
      worstBend = std::max(worstBend, std::abs(h.distance - d) / r);
  }
  std::cout << "sharp bends: " << bendHits << " hits, worst distance error " << worstBend
            << " radii" << std::endl;
  SV_CHECK_MSG(status, worstBend < 1e-2, "sharp bends: error " << worstBend);

  // The default shader setting (10 iterations) stays within a pixel-scale
  // tolerance on the same kind of rays.
  double worst10 = 0.0;
  for (int trial = 0; trial < 1000; ++trial)
  {
    vec4 q0(0.0, 0.0, 0.0, 0.1), q1(0.5, uniform(-0.5, 0.5), 0.0, 0.12), q2(1.0, 0.0, 0.1, 0.08);
    const vec3 dir = random.UnitVector();
    const vec3 target = vec3(svQuadratic(q0, q1, q2, uniform(0, 1))) + random.UnitVector() * 0.05;
    const vec3 origin = target - 5.0 * dir;
    double d, l;
    bool in;
    if (!BruteForce(origin, dir, q0, q1, q2, 20000, d, l, in) || in)
      continue;
    const SvHit h = svIntersectSubSegment(origin, dir, q0, q1, q2, 10, 3);
    SV_CHECK(status, h.hit);
    if (h.hit)
      worst10 = std::max(worst10, std::abs(h.distance - d) / 0.12);
  }
  std::cout << "10 iterations: worst distance error " << worst10 << " radii" << std::endl;
  SV_CHECK_MSG(status, worst10 < 1e-2, "10 iterations: error " << worst10);

  // The curve parameter of the hit gives the normal (from the sphere centre
  // to the hit point) and the color: at the mapper's default settings it must
  // match the converged one (40 refinement steps, checked against brute force
  // above) on random sub-segments, sharp bends included, to well below what
  // shading shows. The distance error is second order in the parameter's (f
  // is stationary there), the normal's first order, so this is the stricter
  // check of the refinement.
  double worstNormal = 0.0, worstGrazingMiss = 0.0;
  int normalHits = 0;
  for (int trial = 0; trial < 4000; ++trial)
  {
    const double r = uniform(0.02, 0.4);
    vec4 q0(0.0, 0.0, 0.0, r);
    vec4 q1(uniform(0.0, 1.0), uniform(-1.5, 1.5), uniform(-0.3, 0.3), uniform(0.02, 0.4));
    vec4 q2(1.0, uniform(-0.5, 0.5), uniform(-0.2, 0.2), uniform(0.02, 0.4));
    const double rmax = std::max({ q0.w, q1.w, q2.w });
    const vec3 target =
      vec3(svQuadratic(q0, q1, q2, uniform(0, 1))) + random.UnitVector() * uniform(0.0, 1.2 * rmax);
    const vec3 dir = random.UnitVector();
    const vec3 origin = target - 5.0 * dir;
    const SvHit ref = svIntersectSubSegment(origin, dir, q0, q1, q2, 40, 3);
    if (!ref.hit)
      continue;
    const SvHit h = svIntersectSubSegment(origin, dir, q0, q1, q2, 10, 3);
    if (!h.hit)
    {
      // Only a ray that barely touches the surface may be missed: how deep
      // does it enter the spheres, relative to the radius?
      double depth = -1e300;
      for (int i = 0; i <= 20000; ++i)
      {
        const vec4 c = svQuadratic(q0, q1, q2, i / 20000.0);
        const vec3 oc = vec3(c) - origin;
        const double across = glm::length(oc - glm::dot(oc, dir) * dir);
        depth = std::max(depth, (c.w - across) / rmax);
      }
      worstGrazingMiss = std::max(worstGrazingMiss, depth);
      continue;
    }
    ++normalHits;
    const vec4 cr = svQuadratic(q0, q1, q2, ref.l);
    const vec4 ch = svQuadratic(q0, q1, q2, h.l);
    const vec3 nr = glm::normalize(origin + ref.distance * dir - vec3(cr));
    const vec3 nh = glm::normalize(origin + h.distance * dir - vec3(ch));
    worstNormal = std::max(worstNormal, glm::length(nh - nr));
  }
  std::cout << "normals at default settings: " << normalHits << " hits, worst error " << worstNormal
            << "; deepest ray missed " << worstGrazingMiss << " radii" << std::endl;
  SV_CHECK_MSG(status, worstGrazingMiss < 5e-3, "missed a ray entering " << worstGrazingMiss);
  SV_CHECK_MSG(status, worstNormal < 1e-2, "default settings: normal error " << worstNormal);

  // The closed form for straight sub-segments (round cones).
  int coneHits = 0, coneMisses = 0, coneInside = 0, coneGrazing = 0, coneNested = 0;
  double worstCone = 0.0;
  for (int trial = 0; trial < 6000; ++trial)
  {
    vec4 a(uniform(-0.2, 0.2), uniform(-0.2, 0.2), uniform(-0.2, 0.2), uniform(0.02, 0.4));
    vec4 b(uniform(0.5, 1.2), uniform(-0.5, 0.5), uniform(-0.5, 0.5), uniform(0.02, 0.4));
    const int kind = trial % 6;
    if (kind == 4)
    {
      // One end sphere containing the other (a degenerate cone).
      b = vec4(vec3(a) + 0.5 * (a.w + 0.3) * random.UnitVector(), 0.0);
      b.w = uniform(0.0, 0.3);
      a.w = glm::length(vec3(b) - vec3(a)) + b.w + uniform(0.0, 0.1);
      if (trial % 12 == 4)
      {
        std::swap(a, b);
      }
      ++coneNested;
    }
    if (kind == 5 && trial % 12 == 5)
    {
      b = vec4(vec3(a), uniform(0.02, 0.4)); // zero length
    }
    const vec4 m = 0.5 * (a + b);
    const double rmax = std::max(a.w, b.w);
    const vec3 c = vec3(a) + uniform(-0.2, 1.2) * (vec3(b) - vec3(a));
    vec3 target = c + random.UnitVector() * uniform(0.0, 1.5 * rmax);
    vec3 dir = random.UnitVector();
    if (kind == 1 && glm::length(vec3(b) - vec3(a)) > 0.0)
    {
      dir = glm::normalize(vec3(b) - vec3(a)); // along the axis
      target = vec3(a);
    }
    vec3 origin = target - 5.0 * dir;
    double d, l;
    bool in;
    if (kind == 2 && BruteForce(origin, dir, a, m, b, 4000, d, l, in) && !in)
    {
      const vec3 side = glm::normalize(glm::cross(dir, svAnyOrthogonal(dir) + 0.3 * dir));
      double lo = 0.0, hi = 3.0 * rmax;
      for (int it = 0; it < 40; ++it)
      {
        const double mid = 0.5 * (lo + hi);
        if (BruteForce(origin + mid * side, dir, a, m, b, 4000, d, l, in))
          lo = mid;
        else
          hi = mid;
      }
      origin += (lo * 0.999) * side;
      ++coneGrazing;
    }
    if (kind == 3 && trial % 12 == 3)
    {
      origin = vec3(a) + uniform(0.0, 1.0) * (vec3(b) - vec3(a)); // starts inside
    }
    const bool refHit = BruteForce(origin, dir, a, m, b, 20000, d, l, in);
    const SvHit h = svIntersectRoundCone(origin, dir, a, b);
    if (in)
    {
      ++coneInside;
      SV_CHECK_MSG(status, !h.hit && h.inside, "cone trial " << trial << ": a ray starting inside");
      continue;
    }
    if (!refHit)
    {
      ++coneMisses;
      SV_CHECK_MSG(status, !h.hit, "cone trial " << trial << ": a miss hit at " << h.distance);
      continue;
    }
    ++coneHits;
    SV_CHECK_MSG(status, h.hit, "cone trial " << trial << " (kind " << kind << "): missed");
    if (!h.hit)
    {
      continue;
    }
    // The closed form is exact; brute force samples the spheres.
    const double error = std::abs(h.distance - d) / rmax;
    worstCone = std::max(worstCone, error);
    SV_CHECK_MSG(status, error < 1e-3,
      "cone trial " << trial << " (kind " << kind << "): distance " << h.distance << " vs " << d);
    const vec4 sphere = a + h.l * (b - a);
    const double onSphere =
      std::abs(glm::length(origin + h.distance * dir - vec3(sphere)) - sphere.w) / rmax;
    SV_CHECK_MSG(status, onSphere < 1e-6, "cone trial " << trial << ": hit off its sphere");
  }
  std::cout << "round cones: hits " << coneHits << " (grazing " << coneGrazing << ", nested "
            << coneNested << "), misses " << coneMisses << ", inside " << coneInside
            << "; worst distance error " << worstCone << " radii" << std::endl;
  SV_CHECK(status, coneHits > 2000 && coneMisses > 300 && coneInside > 100 && coneGrazing > 500);

  // The inner band: points within h of the chord lie inside the swept
  // spheres of the segment's quadratic sub-segments.
  // Its own random sequence, drawn one value per statement: the order in
  // which a constructor's arguments are evaluated is unspecified (GCC: right
  // to left, clang: left to right), so the data set of the sections above
  // depends on the compiler; this one's must not (its tightness check is a
  // property of the data set).
  SplineVizTest::Random bandRandom(20261202);
  auto bandUniform = [&](double a, double b) { return bandRandom.Uniform(a, b); };
  int bands = 0;
  double tightest = 1e30; // smallest (distance to the surface) / h at 1.05 h
  for (int trial = 0; trial < 600; ++trial)
  {
    const int count = 2 * (1 + trial % 3);
    const vec4 p0(0.0, 0.0, 0.0, bandUniform(0.05, 0.3));
    auto draw4 = [&](double lo0, double hi0, double lo1, double hi1, double lo2, double hi2,
                   double lo3, double hi3)
    {
      const double x = bandUniform(lo0, hi0);
      const double y = bandUniform(lo1, hi1);
      const double z = bandUniform(lo2, hi2);
      const double w = bandUniform(lo3, hi3);
      return vec4(x, y, z, w);
    };
    const double p1y = bandUniform(-0.2, 0.2);
    const double p1z = bandUniform(-0.2, 0.2);
    const double p1w = bandUniform(0.05, 0.3);
    const vec4 p1(1.0, p1y, p1z, p1w);
    const vec4 m0 = draw4(0.5, 1.5, -0.6, 0.6, -0.6, 0.6, -0.2, 0.2);
    const vec4 m1 = draw4(0.5, 1.5, -0.6, 0.6, -0.6, 0.6, -0.2, 0.2);
    double reach = 0.0;
    const double h = svInnerBandHalfWidth(p0, m0, p1, m1, count, reach);
    // Depth of point x inside the union of the spheres (> 0 inside), and its
    // largest distance from the chord over the sampled spheres' points.
    std::vector<vec4> spheres;
    for (int k = 0; k < count; ++k)
    {
      vec4 q0, q1, q2;
      svSplitSegment(p0, m0, p1, m1, count, k, q0, q1, q2);
      for (int i = 0; i <= 400; ++i)
      {
        spheres.push_back(svQuadratic(q0, q1, q2, i / 400.0));
      }
    }
    auto depthInside = [&](const vec3& x)
    {
      double best = -1e30;
      for (const vec4& sphere : spheres)
      {
        best = std::max(best, sphere.w - glm::length(x - vec3(sphere)));
      }
      return best;
    };
    const vec3 chord = vec3(p1) - vec3(p0);
    double farthest = 0.0; // of the spheres' surfaces from the chord
    for (const vec4& sphere : spheres)
    {
      const double t =
        std::min(1.0, std::max(0.0, glm::dot(vec3(sphere), chord) / glm::dot(chord, chord)));
      farthest = std::max(farthest, glm::length(vec3(sphere) - t * chord) + sphere.w);
    }
    SV_CHECK_MSG(status, farthest <= reach * (1.0 + 1e-9),
      "band trial " << trial << ": the tube reaches " << farthest << " from the chord, bound "
                    << reach);
    if (h <= 0.0)
    {
      continue;
    }
    ++bands;
    double worstAtH = 1e30;
    double worstWider = 1e30;
    for (int i = 0; i < 300; ++i)
    {
      const double t = bandUniform(0.0, 1.0);
      const vec3 offset = svAnyOrthogonal(glm::normalize(chord));
      const vec3 other = glm::cross(glm::normalize(chord), offset);
      const double angle = bandUniform(0.0, 6.283185307179586);
      const vec3 direction = std::cos(angle) * offset + std::sin(angle) * other;
      const vec3 x = t * chord + h * direction;
      worstAtH = std::min(worstAtH, depthInside(x));
      worstWider = std::min(worstWider, depthInside(t * chord + 1.05 * h * direction));
    }
    SV_CHECK_MSG(status, worstAtH >= -1e-4 * h,
      "band trial " << trial << ": a band point is outside the tube by " << -worstAtH);
    tightest = std::min(tightest, worstWider / h);
  }
  std::cout << "inner bands: " << bands << " segments with a band; 5 % wider, the worst point is "
            << -tightest << " band widths outside" << std::endl;
  SV_CHECK_MSG(status, bands > 200, "too few segments with a band: " << bands);
  SV_CHECK_MSG(status, tightest < 0.0, "the band bound is not tight anywhere");
  return status.Result();
}
