// SPDX-License-Identifier: BSD-3-Clause
// The tube-surface math of the tessellated tubes (Salm §3.1), run on the CPU
// from the very source the shaders use (vtkSplineTubeMath.h), checked against
// independent computations:
//  - svHermite and svHermiteSecondDerivative reproduce a cubic given in the
//    power basis (analytic derivatives);
//  - the octahedral encoding of the orthogonal vectors round-trips through
//    the 16-bit quantization of the tubes buffer within 1e-4 rad;
//  - svInterpolateFrame returns unit vectors orthogonal to the tangent that
//    reproduce the node vectors at the nodes;
//  - surface points lie at the radius from the axis in the cross-section plane;
//  - the wall normal (Salm Fig. 7: offset projected onto the plane of the
//    central-difference surface tangent) matches the normal from the cross
//    product of finely differenced partial derivatives, on real tubes with
//    strongly varying radius (where the offset vector itself is not the
//    normal: the test checks that it would fail);
//  - the analytic surface tangent used for the tessellation levels gives the
//    exact normal (o' has no component along T other than -(o . T') T for any
//    frame, and the twist part is orthogonal to the projected offset);
//  - svCylinderFrontDistance, the thin walls' depth per fragment, against
//    ray marching;
//  - the levels of thin tubes: the chord count of svThinSagittaLevel is the
//    fewest that keeps the bound, svThinChainCurvature reproduces a circle's,
//    svThinWallLeast grows from 3 to 5 as the tube turns toward the eye, and
//    svThinRingLevel rounds the arc up within its limits.
#include "vtkSplineTubeCore.h"
#include "vtkSplineTubeMath.h"

#include "SplineVizTestRandom.h"
#include "SplineVizTestUtilities.h"

#include "vtkCellArray.h"
#include "vtkFloatArray.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkTypeUInt32Array.h"

#include <algorithm>
#include <cmath>
#include <vector>
#include <cstdint>
#include <iostream>

namespace
{
using vec2 = vtkSplineTubeMath::vec2;
using vec3 = vtkSplineTubeMath::vec3;
using vec4 = vtkSplineTubeMath::vec4;
namespace sm = vtkSplineTubeMath;

double AngleBetween(const vec3& a, const vec3& b)
{
  const double c = glm::dot(a, b) / (glm::length(a) * glm::length(b));
  return std::acos(std::max(-1.0, std::min(1.0, c)));
}

/// A segment of the core as the shaders see it.
struct Segment
{
  vec4 p0, m0, p1, m1;
  vec3 f0, f1;
};

Segment GetSegment(vtkSplineTubeCore* core, vtkIdType s)
{
  const vtkIdType i = core->GetSegmentFirstNode(s);
  const vtkIdType tube = core->GetTubeOfNode(i);
  const vtkIdType k = i - core->GetTubeFirstNode(tube);
  double P[8];
  double M[8];
  core->GetTubeNodes(tube, k, 2, P, M);
  std::vector<double> F(3 * core->GetTubeNumberOfNodes(tube));
  core->GetTubeFrames(tube, F.data());
  Segment g;
  g.p0 = vec4(P[0], P[1], P[2], P[3]);
  g.m0 = vec4(M[0], M[1], M[2], M[3]);
  g.p1 = vec4(P[4], P[5], P[6], P[7]);
  g.m1 = vec4(M[4], M[5], M[6], M[7]);
  g.f0 = vec3(F[3 * k], F[3 * k + 1], F[3 * k + 2]);
  g.f1 = vec3(F[3 * k + 3], F[3 * k + 4], F[3 * k + 5]);
  return g;
}

vec3 Surface(const Segment& g, double t, double a)
{
  vec3 o;
  return sm::svTubeSurfacePoint(g.p0, g.m0, g.p1, g.m1, g.f0, g.f1, t, a, 1.0, o);
}

/// The exact wall normal by an independent route: the cross product of the
/// partial derivatives along the angle and along the curve, each by a fine
/// central difference, oriented outwards.
vec3 ReferenceNormal(const Segment& g, double t, double a)
{
  const double e = 1e-5;
  const vec3 dt = (Surface(g, t + e, a) - Surface(g, t - e, a)) / (2.0 * e);
  const vec3 da = (Surface(g, t, a + e) - Surface(g, t, a - e)) / (2.0 * e);
  vec3 n = glm::normalize(glm::cross(da, dt));
  vec3 o;
  sm::svTubeSurfacePoint(g.p0, g.m0, g.p1, g.m1, g.f0, g.f1, t, a, 1.0, o);
  return glm::dot(n, o) < 0.0 ? -n : n;
}

/// A core with one tube through `points` and radii `radii`.
vtkSmartPointer<vtkSplineTubeCore> MakeCore(
  const std::vector<vec3>& points, const std::vector<double>& radii)
{
  vtkNew<vtkPoints> pts;
  vtkNew<vtkFloatArray> r;
  r->SetName("R");
  vtkNew<vtkCellArray> lines;
  lines->InsertNextCell(static_cast<int>(points.size()));
  for (size_t i = 0; i < points.size(); ++i)
  {
    pts->InsertNextPoint(points[i].x, points[i].y, points[i].z);
    r->InsertNextValue(static_cast<float>(radii[i]));
    lines->InsertCellPoint(static_cast<vtkIdType>(i));
  }
  vtkNew<vtkPolyData> pd;
  pd->SetPoints(pts);
  pd->SetLines(lines);
  pd->GetPointData()->AddArray(r);
  auto core = vtkSmartPointer<vtkSplineTubeCore>::New();
  core->SetRadiusArray("R");
  core->AddPolyData(pd, nullptr);
  core->Build();
  return core;
}
}

int TestTessellatedTubeMath(int, char*[])
{
  SplineVizTestStatus status;
  SplineVizTest::Random random(4242);
  auto uniform = [&](double a, double b) { return random.Uniform(a, b); };

  // 1. Hermite value and second derivative against a power-basis cubic.
  for (int trial = 0; trial < 100; ++trial)
  {
    vec4 a(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
    vec4 b(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
    vec4 c(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
    vec4 d(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
    auto value = [&](double t) { return a + t * b + (t * t) * c + (t * t * t) * d; };
    auto first = [&](double t) { return b + (2.0 * t) * c + (3.0 * t * t) * d; };
    auto second = [&](double t) { return 2.0 * c + (6.0 * t) * d; };
    const vec4 p0 = value(0.0), m0 = first(0.0), p1 = value(1.0), m1 = first(1.0);
    for (double t : { -0.1, 0.0, 0.3, 0.77, 1.0, 1.05 })
    {
      SV_CHECK_NEAR(status, glm::length(sm::svHermite(p0, m0, p1, m1, t) - value(t)), 0.0, 1e-12);
      SV_CHECK_NEAR(status,
        glm::length(sm::svHermiteSecondDerivative(p0, m0, p1, m1, t) - second(t)), 0.0, 1e-12);
    }
  }

  // 2. Octahedral encoding with the 16-bit quantization of the tubes buffer.
  double worstOct = 0.0;
  for (int trial = 0; trial < 20000; ++trial)
  {
    vec3 n = random.UnitVector();
    if (trial < 6)
    {
      n = vec3(0.0);
      n[trial / 2] = (trial % 2) ? -1.0 : 1.0; // the axes
    }
    const vec2 e = sm::svOctEncode(n);
    SV_CHECK(status, std::abs(e.x) <= 1.0 && std::abs(e.y) <= 1.0);
    const vec2 q(std::lround(e.x * 32767.0) / 32767.0, std::lround(e.y * 32767.0) / 32767.0);
    const vec3 back = sm::svOctDecode(q);
    SV_CHECK_NEAR(status, glm::length(back), 1.0, 1e-12);
    worstOct = std::max(worstOct, AngleBetween(n, back));
  }
  std::cout << "octahedral 16-bit round trip: worst " << worstOct << " rad" << std::endl;
  SV_CHECK_MSG(status, worstOct < 1e-4, "octahedral round trip error " << worstOct);

  // Real tubes: a planar arc with a strongly varying radius, and random space
  // curves with varying radii.
  std::vector<vtkSmartPointer<vtkSplineTubeCore>> cores;
  std::vector<bool> planar;
  {
    std::vector<vec3> pts;
    std::vector<double> radii;
    for (int i = 0; i <= 12; ++i)
    {
      const double phi = 0.25 * i;
      pts.emplace_back(std::cos(phi), std::sin(phi), 0.0);
      radii.push_back(0.05 + 0.04 * std::sin(1.3 * i));
    }
    cores.push_back(MakeCore(pts, radii));
    planar.push_back(true);
  }
  for (int k = 0; k < 6; ++k)
  {
    std::vector<vec3> pts;
    std::vector<double> radii;
    vec3 p(0.0);
    vec3 dir = random.UnitVector();
    for (int i = 0; i < 15; ++i)
    {
      pts.push_back(p);
      radii.push_back(uniform(0.01, 0.06));
      dir = glm::normalize(dir + 0.5 * random.UnitVector());
      p += 0.2 * dir;
    }
    cores.push_back(MakeCore(pts, radii));
    planar.push_back(false);
  }

  double worstNormal = 0.0;
  double worstOffsetAsNormal = 0.0;
  double worstPlanarTangent = 0.0;
  double worstSpaceTangent = 0.0;
  int samples = 0;
  for (size_t c = 0; c < cores.size(); ++c)
  {
    vtkSplineTubeCore* core = cores[c];
    for (vtkIdType s = 0; s < core->GetNumberOfSegments(); ++s)
    {
      const Segment g = GetSegment(core, s);
      for (int i = 0; i <= 8; ++i)
      {
        const double t = i / 8.0;
        const vec3 d = vec3(sm::svHermiteDerivative(g.p0, g.m0, g.p1, g.m1, t));
        const vec3 unitT = glm::normalize(d);

        // 3. Frames: unit, orthogonal to the tangent, the node vectors at the nodes.
        const vec3 n = sm::svInterpolateFrame(g.f0, g.f1, t, d);
        SV_CHECK_NEAR(status, glm::length(n), 1.0, 1e-9);
        SV_CHECK_NEAR(status, glm::dot(n, unitT), 0.0, 1e-9);
        if (i == 0)
        {
          SV_CHECK_NEAR(status, glm::length(n - g.f0), 0.0, 1e-5);
        }
        if (i == 8)
        {
          SV_CHECK_NEAR(status, glm::length(n - g.f1), 0.0, 1e-5);
        }

        for (int j = 0; j < 8; ++j)
        {
          const double sParam = (j + 0.37) / 8.0;
          const double angle = sm::svTubeAngle(sParam);
          vec3 o;
          const vec3 x =
            sm::svTubeSurfacePoint(g.p0, g.m0, g.p1, g.m1, g.f0, g.f1, t, angle, 1.0, o);
          // 4. On the circle of the cross-section.
          const vec4 center = sm::svHermite(g.p0, g.m0, g.p1, g.m1, t);
          SV_CHECK_NEAR(status, glm::length(x - vec3(center)), center.w, 1e-9);
          SV_CHECK_NEAR(status, glm::dot(x - vec3(center), unitT), 0.0, 1e-9);

          // 5. The wall normal against the independent normal; relative
          //    positions as the evaluation stage passes them.
          Segment local = g;
          local.p1 = vec4(vec3(g.p1) - vec3(g.p0), g.p1.w);
          local.p0 = vec4(0.0, 0.0, 0.0, g.p0.w);
          const vec3 normal = sm::svTubeWallNormal(
            local.p0, local.m0, local.p1, local.m1, local.f0, local.f1, t, angle, o);
          const vec3 reference = ReferenceNormal(g, t, angle);
          worstNormal = std::max(worstNormal, AngleBetween(normal, reference));
          worstOffsetAsNormal = std::max(worstOffsetAsNormal, AngleBetween(o, reference));

          // 6. The analytic surface tangent of the level normals.
          const vec4 dd = sm::svHermiteSecondDerivative(g.p0, g.m0, g.p1, g.m1, t);
          const vec4 d4 = sm::svHermiteDerivative(g.p0, g.m0, g.p1, g.m1, t);
          const vec3 st = sm::svTubeSurfaceTangent(d, vec3(dd), center.w, d4.w, o);
          const vec3 levelNormal = sm::svTubeNormal(o, st);
          const double e = AngleBetween(levelNormal, reference);
          if (planar[c])
          {
            worstPlanarTangent = std::max(worstPlanarTangent, e);
          }
          else
          {
            worstSpaceTangent = std::max(worstSpaceTangent, e);
          }
          ++samples;
        }
      }
    }
  }
  std::cout << samples << " surface samples: wall normal worst " << worstNormal
            << " rad (offset as normal: " << worstOffsetAsNormal << " rad); level normal worst "
            << worstPlanarTangent << " rad (planar), " << worstSpaceTangent << " rad (space curves)"
            << std::endl;
  SV_CHECK_MSG(status, worstNormal < 0.01, "wall normal error " << worstNormal << " rad");
  // The test has teeth: ignoring the radius change would fail it by far.
  SV_CHECK_MSG(status, worstOffsetAsNormal > 0.1, "offset vs normal " << worstOffsetAsNormal);
  SV_CHECK_MSG(status, worstPlanarTangent < 1e-4, "planar level normal " << worstPlanarTangent);
  SV_CHECK_MSG(status, worstSpaceTangent < 1e-4, "space-curve level normal " << worstSpaceTangent);

  // The levels of thin tubes (shared by the control stage and the CPU
  // classification of the thin-tube draws).
  // - svThinSagittaLevel: the fewest chords n whose sagitta s / n^2 is within
  //   the bound (svThinSagittaPixels on screen, svThinDepthSagitta radii in
  //   space).
  for (int i = 0; i < 200; ++i)
  {
    const double sagitta = uniform(1e-4, 10.0);
    const double w = uniform(0.5, 50.0);
    const double radius = uniform(1e-3, 1.0);
    const double pixelScale = uniform(100.0, 2000.0);
    const double bound =
      std::min(sm::svThinSagittaPixels * w / pixelScale, sm::svThinDepthSagitta * radius);
    const double n = sm::svThinSagittaLevel(sagitta, w, radius, pixelScale);
    SV_CHECK(status, n >= 1.0 && n == std::floor(n));
    SV_CHECK(status, sagitta / (n * n) <= bound * (1.0 + 1e-12));
    SV_CHECK(status, n == 1.0 || sagitta / ((n - 1.0) * (n - 1.0)) > bound);
  }
  // - svThinSegmentSagitta: a bound on how far the segment strays from the
  //   linear interpolation between its points at the ends of a piece (what
  //   the thin walls' rings interpolate), measured by sampling each of n
  //   pieces 64 times: never above the bound, and within 8 times of it at
  //   the worst piece (quadratic segments: equal to it). Random segments,
  //   and S-shaped ones (m0 = m1 off the chord), whose middle lies on the
  //   chord: the deviation of the middle alone (|m0 - m1| / 8, the negative
  //   control) says 0 there and must fail the measured deviation.
  {
    using vec4 = vtkSplineTubeMath::vec4;
    auto measured = [](const vec4& p0, const vec4& m0, const vec4& p1, const vec4& m1, int n)
    {
      double worst = 0.0;
      for (int k = 0; k < n; ++k)
      {
        const double t0 = static_cast<double>(k) / n;
        const double t1 = static_cast<double>(k + 1) / n;
        const vec3 a(sm::svHermite(p0, m0, p1, m1, t0));
        const vec3 b(sm::svHermite(p0, m0, p1, m1, t1));
        for (int j = 1; j < 64; ++j)
        {
          const double f = j / 64.0;
          const vec3 c(sm::svHermite(p0, m0, p1, m1, t0 + f * (t1 - t0)));
          worst = std::max(worst, glm::length(c - ((1.0 - f) * a + f * b)));
        }
      }
      return worst;
    };
    double loosest = 0.0;
    int controlFailures = 0;
    for (int i = 0; i < 200; ++i)
    {
      const vec4 p0(uniform(-1.0, 1.0), uniform(-1.0, 1.0), uniform(-1.0, 1.0), 0.1);
      const vec4 p1(uniform(-1.0, 1.0), uniform(-1.0, 1.0), uniform(-1.0, 1.0), 0.1);
      const vec4 m0(uniform(-3.0, 3.0), uniform(-3.0, 3.0), uniform(-3.0, 3.0), 0.0);
      const bool sShaped = i % 2 == 1;
      const vec4 m1 =
        sShaped ? m0 : vec4(uniform(-3.0, 3.0), uniform(-3.0, 3.0), uniform(-3.0, 3.0), 0.0);
      for (int n : { 1, 2, 5 })
      {
        const double bound = sm::svThinSegmentSagitta(p0, m0, p1, m1, 1.0 / n);
        const double deviation = measured(p0, m0, p1, m1, n);
        SV_CHECK_MSG(status, deviation <= bound * (1.0 + 1e-9),
          "svThinSegmentSagitta " << bound << " below the measured deviation " << deviation << " ("
                                  << n << " pieces)");
        if (deviation > 1e-9)
        {
          loosest = std::max(loosest, bound / deviation);
        }
        const double middleOnly = 0.125 * glm::length(vec3(m0) - vec3(m1)) / (n * n);
        if (sShaped && n == 1 && deviation > middleOnly * (1.0 + 1e-9))
        {
          ++controlFailures;
        }
      }
    }
    std::cout << "svThinSegmentSagitta: at most " << loosest
              << " times the measured deviation; the middle-only control fails on "
              << controlFailures << " of 100 S-shaped segments" << std::endl;
    SV_CHECK_MSG(status, loosest <= 8.0, "svThinSegmentSagitta too loose: " << loosest << "x");
    SV_CHECK_MSG(status, controlFailures == 100,
      "the middle-only control passed on " << 100 - controlFailures << " S-shaped segments");
  }
  // - svCylinderFrontDistance (the thin walls' depth per fragment): from
  //   random points inside random cylinders along random rays (from
  //   across the axis to 5 degrees off it), the first entry found by
  //   marching the ray from 8 radii in front and bisecting the crossing;
  //   clamped to 8 radii; a ray along the axis gives 0; from a point just
  //   outside, the nearest approach to the axis.
  double worstFront = 0.0;
  int clamped = 0;
  for (int i = 0; i < 2000; ++i)
  {
    const vec3 a = glm::normalize(vec3(uniform(-1.0, 1.0), uniform(-1.0, 1.0), uniform(-1.0, 1.0)));
    const vec3 helper = std::abs(a.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0);
    const vec3 e1 = glm::normalize(glm::cross(a, helper));
    const vec3 e2 = glm::cross(a, e1);
    const double r = uniform(0.01, 2.0);
    const vec3 c(uniform(-5.0, 5.0), uniform(-5.0, 5.0), uniform(-5.0, 5.0));
    const double off = vtkMath::RadiansFromDegrees(uniform(5.0, 90.0)); // ray to axis
    const double spin = uniform(0.0, 2.0 * vtkMath::Pi());
    const vec3 across = std::cos(spin) * e1 + std::sin(spin) * e2;
    const vec3 dir = std::cos(off) * a + std::sin(off) * across;
    const double rho = r * std::sqrt(uniform(0.0, 1.0));
    const double phi = uniform(0.0, 2.0 * vtkMath::Pi());
    const vec3 p = c + uniform(-3.0, 3.0) * a + rho * (std::cos(phi) * e1 + std::sin(phi) * e2);
    auto inside = [&](double t)
    {
      const vec3 w = p + t * dir - c;
      return glm::length(w - glm::dot(w, a) * a) <= r;
    };
    const double cap = 8.0 * r;
    double ref = -cap;
    if (!inside(-cap))
    {
      double lo = -cap;
      for (int k = 1; k <= 4000; ++k)
      {
        const double t = -cap + cap * k / 4000.0;
        if (inside(t))
        {
          double hi = t;
          for (int it = 0; it < 60; ++it)
          {
            const double m = 0.5 * (lo + hi);
            (inside(m) ? hi : lo) = m;
          }
          ref = hi;
          break;
        }
        lo = t;
      }
    }
    else
    {
      ++clamped;
    }
    const double got = sm::svCylinderFrontDistance(p, dir, c, a, r, cap);
    worstFront = std::max(worstFront, std::abs(got - ref) / r);
  }
  std::cout << "cylinder front: worst error " << worstFront << " radii (" << clamped << " clamped)"
            << std::endl;
  SV_CHECK_MSG(status, worstFront < 1e-6, "cylinder front distance error " << worstFront);
  SV_CHECK(status, clamped > 0);
  SV_CHECK(status,
    sm::svCylinderFrontDistance(
      vec3(0.1, 0.0, 0.0), vec3(0.0, 0.0, -1.0), vec3(0.0), vec3(0.0, 0.0, 1.0), 0.5, 4.0) == 0.0);
  {
    // 0.2 outside a unit cylinder along z, the ray along x at y = 1.2: the
    // nearest approach is at x = 0.
    const double s = sm::svCylinderFrontDistance(
      vec3(0.7, 1.2, 0.0), vec3(-1.0, 0.0, 0.0), vec3(0.0), vec3(0.0, 0.0, 1.0), 1.0, 8.0);
    SV_CHECK_NEAR(status, s, 0.7, 1e-12);
  }
  // - svThinChainCurvature: nodes on a circle of radius rho, equal angular
  //   steps theta: theta over the chord 2 rho sin(theta / 2).
  for (double theta : { 0.01, 0.1, 0.5 })
  {
    const double rho = 3.0;
    const vec3 a(rho, 0.0, 0.0);
    const vec3 b(rho * std::cos(theta), rho * std::sin(theta), 0.0);
    const vec3 c(rho * std::cos(2.0 * theta), rho * std::sin(2.0 * theta), 0.0);
    const double k = sm::svThinChainCurvature(c - b, glm::length(c - b), b - a, glm::length(b - a));
    SV_CHECK_NEAR(status, k, theta / (2.0 * rho * std::sin(0.5 * theta)), 1e-9);
  }
  SV_CHECK(status, sm::svThinChainCurvature(vec3(1.0, 0.0, 0.0), 1.0, vec3(0.0), 0.0) == 0.0);
  // - svThinWallLeast: 3 intervals across the view, 5 seen end-on, never
  //   fewer as the tube turns toward the eye.
  SV_CHECK(status, sm::svThinWallLeast(vec3(1.0, 0.0, 0.0), vec3(0.0, 0.0, 1.0)) == 3.0);
  SV_CHECK(status, sm::svThinWallLeast(vec3(0.0, 0.0, 2.0), vec3(0.0, 0.0, 1.0)) == 5.0);
  double previousLeast = 0.0;
  for (int i = 0; i <= 90; ++i)
  {
    const double angle = vtkMath::RadiansFromDegrees(90.0 - i); // tangent to ray: 90 .. 0 degrees
    const double least =
      sm::svThinWallLeast(vec3(std::sin(angle), 0.0, std::cos(angle)), vec3(0.0, 0.0, 1.0));
    SV_CHECK(status, least >= previousLeast && least >= 3.0 && least <= 5.0);
    previousLeast = least;
  }
  // - svThinRingLevel: the arc (turn of the circumference, in pixels) over
  //   the side length, rounded up, within [least, 64]; 64 behind the eye.
  SV_CHECK(status, sm::svThinRingLevel(0.01, 2.0, 1000.0, 2.0, 0.5, 3.0) == 8.0); // 15.7 px
  SV_CHECK(status, sm::svThinRingLevel(0.001, 2.0, 1000.0, 2.0, 0.5, 3.0) == 3.0);
  SV_CHECK(status, sm::svThinRingLevel(1.0, 2.0, 1000.0, 2.0, 0.5, 3.0) == 64.0);
  SV_CHECK(status, sm::svThinRingLevel(0.01, -1.0, 1000.0, 2.0, 0.5, 3.0) == 64.0);
  return status.Result();
}
