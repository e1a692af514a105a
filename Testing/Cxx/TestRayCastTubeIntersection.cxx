// The ray / quadratic sub-segment intersection of the ray-cast tubes (Salm
// §3.2), run on the CPU from the very source the fragment shader uses
// (vtkSplineTubeMath.h), checked against brute force: the first entry into
// the union of densely sampled spheres along the sub-segment. Random
// sub-segments and rays, rays grazing the surface, rays along the axis, rays
// through the caps, misses, and rays starting inside.
#include "vtkSplineTubeMath.h"

#include "SplineVizTestUtilities.h"

#include "vtkMinimalStandardRandomSequence.h"
#include "vtkNew.h"

#include <algorithm>
#include <cmath>
#include <iostream>

namespace
{
using vec3 = vtkSplineTubeMath::vec3;
using vec4 = vtkSplineTubeMath::vec4;
using vtkSplineTubeMath::svAnyOrthogonal;
using vtkSplineTubeMath::SvHit;
using vtkSplineTubeMath::svIntersectSubSegment;
using vtkSplineTubeMath::svQuadratic;

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
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(12345);
  auto uniform = [&](double a, double b)
  {
    random->Next();
    return random->GetRangeValue(a, b);
  };
  auto randomUnit = [&]()
  {
    vec3 v;
    do
    {
      v = vec3(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
    } while (glm::length(v) < 0.1 || glm::length(v) > 1.0);
    return glm::normalize(v);
  };

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
    vec3 target = vec3(c) + randomUnit() * uniform(0.0, 1.5 * rmax);
    vec3 dir = randomUnit();
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
    const vec3 dir = randomUnit();
    const vec3 target = vec3(svQuadratic(q0, q1, q2, uniform(0, 1))) + randomUnit() * 0.05;
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
  return status.Result();
}
