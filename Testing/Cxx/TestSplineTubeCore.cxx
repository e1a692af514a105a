// SPDX-License-Identifier: BSD-3-Clause
// Unit tests of the shared tube core (vtkSplineTubeCore) and of the spline
// math shared with the shaders (vtkSplineTubeMath.h):
//  - the Hermite splines reproduce the nodes and the documented tangents;
//  - frames are orthonormal to the tangents and rotation-minimizing: they match
//    an independent reference (the projection method with tiny steps along the
//    same spline, evaluated here with its own code), also around sharp bends;
//  - the quadratic split interpolates the segment ends, is C1 at the joints,
//    deviates little from the cubic and converges when refined;
//  - every sub-segment box contains the spheres swept along it (dense
//    sampling) and is tight;
//  - the segment table and the handling of degenerate input.
#include "vtkSplineTubeCore.h"
#include "vtkSplineTubeMath.h"

#include "SplineVizTestUtilities.h"

#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkMath.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSyntheticFibersSource.h"
#include "vtkTestErrorObserver.h"
#include "vtkTypeUInt32Array.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace
{
using Vec = std::array<double, 3>;

Vec Sub(const Vec& a, const Vec& b)
{
  return { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
}
double Dot(const Vec& a, const Vec& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
double Norm(const Vec& a)
{
  return std::sqrt(Dot(a, a));
}
Vec Scale(const Vec& a, double s)
{
  return { a[0] * s, a[1] * s, a[2] * s };
}
Vec Unit(const Vec& a)
{
  return Scale(a, 1.0 / Norm(a));
}

/// One polyline through `pts`; optional per-point radii as array "R".
vtkSmartPointer<vtkPolyData> MakeLine(
  const std::vector<Vec>& pts, const std::vector<double>* radii = nullptr)
{
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> lines;
  lines->InsertNextCell(static_cast<int>(pts.size()));
  for (const auto& p : pts)
  {
    lines->InsertCellPoint(points->InsertNextPoint(p.data()));
  }
  pd->SetPoints(points);
  pd->SetLines(lines);
  if (radii)
  {
    vtkNew<vtkDoubleArray> r;
    r->SetName("R");
    for (double v : *radii)
    {
      r->InsertNextValue(v);
    }
    pd->GetPointData()->AddArray(r);
  }
  return pd;
}

std::vector<Vec> Helix(int n, double radius, double pitch, double dtheta)
{
  std::vector<Vec> pts;
  for (int i = 0; i < n; ++i)
  {
    const double a = i * dtheta;
    pts.push_back({ radius * std::cos(a), radius * std::sin(a), pitch * a });
  }
  return pts;
}

/// Independent cubic Hermite evaluation (not the shared math).
Vec HermiteRef(const Vec& p0, const Vec& m0, const Vec& p1, const Vec& m1, double t)
{
  const double h00 = (1 + 2 * t) * (1 - t) * (1 - t);
  const double h10 = t * (1 - t) * (1 - t);
  const double h01 = t * t * (3 - 2 * t);
  const double h11 = t * t * (t - 1);
  Vec r;
  for (int c = 0; c < 3; ++c)
  {
    r[c] = h00 * p0[c] + h10 * m0[c] + h01 * p1[c] + h11 * m1[c];
  }
  return r;
}

/// The core's node data as arrays (read through its accessors): positions
/// (3), derivatives of the position spline (3), radii and their derivatives
/// (2), rotation-minimizing frames (3), node scalars (1).
vtkSmartPointer<vtkFloatArray> NodeArray(vtkSplineTubeCore* core, int which)
{
  auto a = vtkSmartPointer<vtkFloatArray>::New();
  const int comps = which == 2 ? 2 : (which == 4 ? 1 : 3);
  a->SetNumberOfComponents(comps);
  a->SetNumberOfTuples(core->GetNumberOfNodes());
  for (vtkIdType t = 0; t < core->GetNumberOfTubes(); ++t)
  {
    const vtkIdType first = core->GetTubeFirstNode(t);
    const vtkIdType n = core->GetTubeNumberOfNodes(t);
    std::vector<double> p(4 * n), m(4 * n), f(3 * n);
    core->GetTubeNodes(t, 0, n, p.data(), m.data());
    if (which == 3)
    {
      core->GetTubeFrames(t, f.data());
    }
    for (vtkIdType k = 0; k < n; ++k)
    {
      for (int c = 0; c < comps; ++c)
      {
        double v = 0.0;
        switch (which)
        {
          case 0:
            v = p[4 * k + c];
            break;
          case 1:
            v = m[4 * k + c];
            break;
          case 2:
            v = c == 0 ? p[4 * k + 3] : m[4 * k + 3];
            break;
          case 3:
            v = f[3 * k + c];
            break;
          default:
            v = core->GetNodeScalar(first + k);
        }
        a->SetComponent(first + k, c, v);
      }
    }
  }
  return a;
}
vtkSmartPointer<vtkFloatArray> Positions(vtkSplineTubeCore* core)
{
  return NodeArray(core, 0);
}
vtkSmartPointer<vtkFloatArray> Tangents(vtkSplineTubeCore* core)
{
  return NodeArray(core, 1);
}
vtkSmartPointer<vtkFloatArray> Radii(vtkSplineTubeCore* core)
{
  return NodeArray(core, 2);
}
vtkSmartPointer<vtkFloatArray> Frames(vtkSplineTubeCore* core)
{
  return NodeArray(core, 3);
}
vtkSmartPointer<vtkFloatArray> Scalars(vtkSplineTubeCore* core)
{
  return NodeArray(core, 4);
}

Vec NodeVec(vtkFloatArray* a, vtkIdType i)
{
  return { a->GetComponent(i, 0), a->GetComponent(i, 1), a->GetComponent(i, 2) };
}

//------------------------------------------------------------------------------
void TestHermite(SplineVizTestStatus& status)
{
  const auto pts = Helix(20, 1.0, 0.2, 0.4);
  vtkNew<vtkSplineTubeCore> core;
  core->AddPolyData(MakeLine(pts), nullptr);
  core->Build();
  SV_CHECK(status, core->GetNumberOfTubes() == 1);
  SV_CHECK(status, core->GetNumberOfNodes() == 20);
  SV_CHECK(status, core->GetNumberOfSegments() == 19);

  // Documented tangents: central differences inside, second-order one-sided at the ends.
  const int n = static_cast<int>(pts.size());
  for (int i = 0; i < n; ++i)
  {
    Vec expected;
    if (i == 0)
    {
      for (int c = 0; c < 3; ++c)
        expected[c] = 0.5 * (-3 * pts[0][c] + 4 * pts[1][c] - pts[2][c]);
    }
    else if (i == n - 1)
    {
      for (int c = 0; c < 3; ++c)
        expected[c] = 0.5 * (3 * pts[n - 1][c] - 4 * pts[n - 2][c] + pts[n - 3][c]);
    }
    else
    {
      expected = Scale(Sub(pts[i + 1], pts[i - 1]), 0.5);
    }
    const Vec got = NodeVec(Tangents(core), i);
    SV_CHECK_NEAR(status, Norm(Sub(got, expected)), 0.0, 1e-5);
  }

  // Segments reproduce their end nodes and end tangents, and agree with an
  // independent Hermite evaluation inside.
  for (vtkIdType s = 0; s < core->GetNumberOfSegments(); ++s)
  {
    double p[3], d[3], r, dr;
    core->EvaluateSegment(s, 0.0, p, d, &r, &dr);
    SV_CHECK_NEAR(status, Norm(Sub({ p[0], p[1], p[2] }, pts[s])), 0.0, 1e-6);
    SV_CHECK_NEAR(status, Norm(Sub({ d[0], d[1], d[2] }, NodeVec(Tangents(core), s))), 0.0, 1e-6);
    core->EvaluateSegment(s, 1.0, p, d, &r, &dr);
    SV_CHECK_NEAR(status, Norm(Sub({ p[0], p[1], p[2] }, pts[s + 1])), 0.0, 1e-6);
    SV_CHECK_NEAR(
      status, Norm(Sub({ d[0], d[1], d[2] }, NodeVec(Tangents(core), s + 1))), 0.0, 1e-6);
    core->EvaluateSegment(s, 0.3, p, nullptr, nullptr, nullptr);
    const Vec ref = HermiteRef(
      pts[s], NodeVec(Tangents(core), s), pts[s + 1], NodeVec(Tangents(core), s + 1), 0.3);
    SV_CHECK_NEAR(status, Norm(Sub({ p[0], p[1], p[2] }, ref)), 0.0, 1e-6);
  }

  // A straight, evenly spaced line is reproduced exactly (tangent = spacing).
  std::vector<Vec> straight;
  for (int i = 0; i < 6; ++i)
  {
    straight.push_back({ 1.0 + 0.5 * i, -2.0 + 0.25 * i, 0.1 * i });
  }
  vtkNew<vtkSplineTubeCore> line;
  line->AddPolyData(MakeLine(straight), nullptr);
  line->Build();
  for (int i = 0; i < 6; ++i)
  {
    SV_CHECK_NEAR(
      status, Norm(Sub(NodeVec(Tangents(line), i), Sub(straight[1], straight[0]))), 0.0, 1e-6);
  }
}

//------------------------------------------------------------------------------
/// Reference rotation-minimizing vectors at the nodes of tube `tube` of
/// `core`: projection method with `steps` tiny steps per segment along the
/// spline (independent Hermite evaluation), started from the core's first
/// vector. Returns the largest angle (radians) between reference and core.
double CompareWithReferenceFrames(vtkSplineTubeCore* core, vtkIdType tube, int steps)
{
  const vtkIdType first = core->GetTubeFirstNode(tube);
  const vtkIdType n = core->GetTubeNumberOfNodes(tube);
  vtkSmartPointer<vtkFloatArray> P = Positions(core);
  vtkSmartPointer<vtkFloatArray> M = Tangents(core);
  Vec r = NodeVec(Frames(core), first);
  double worst = 0.0;
  for (vtkIdType i = first; i + 1 < first + n; ++i)
  {
    const Vec p0 = NodeVec(P, i), m0 = NodeVec(M, i), p1 = NodeVec(P, i + 1),
              m1 = NodeVec(M, i + 1);
    Vec prev = HermiteRef(p0, m0, p1, m1, 0.0);
    for (int k = 1; k <= steps; ++k)
    {
      const double t = static_cast<double>(k) / steps;
      const Vec cur = HermiteRef(p0, m0, p1, m1, t);
      // tangent by a symmetric difference of the reference curve
      const double h = 1e-5;
      Vec tangent =
        Sub(HermiteRef(p0, m0, p1, m1, std::min(1.0, t + h)), HermiteRef(p0, m0, p1, m1, t - h));
      if (Norm(tangent) < 1e-14)
      {
        tangent = Sub(cur, prev);
      }
      tangent = Unit(tangent);
      r = Unit(Sub(r, Scale(tangent, Dot(r, tangent))));
      prev = cur;
    }
    const Vec got = NodeVec(Frames(core), i + 1);
    const double c = std::max(-1.0, std::min(1.0, Dot(Unit(got), r)));
    worst = std::max(worst, std::acos(c));
  }
  return worst;
}

void CheckOrthonormalFrames(SplineVizTestStatus& status, vtkSplineTubeCore* core)
{
  double worstLength = 0.0;
  double worstDot = 0.0;
  for (vtkIdType i = 0; i < core->GetNumberOfNodes(); ++i)
  {
    const Vec f = NodeVec(Frames(core), i);
    const Vec t = Unit(NodeVec(Tangents(core), i));
    worstLength = std::max(worstLength, std::abs(Norm(f) - 1.0));
    worstDot = std::max(worstDot, std::abs(Dot(f, t)));
  }
  SV_CHECK_MSG(status, worstLength < 1e-5, "frame length error " << worstLength);
  SV_CHECK_MSG(status, worstDot < 1e-4, "frame/tangent dot " << worstDot);
}

void TestFrames(SplineVizTestStatus& status)
{
  // A helix: nonzero torsion, so frames that are not rotation-minimizing
  // (e.g. Frenet frames, or an independent orthogonal vector per node) differ.
  {
    vtkNew<vtkSplineTubeCore> core;
    core->AddPolyData(MakeLine(Helix(40, 1.0, 0.3, 0.35)), nullptr);
    core->Build();
    CheckOrthonormalFrames(status, core);
    const double angle = CompareWithReferenceFrames(core, 0, 4000);
    std::cout << "helix: largest angle to the reference RMF " << angle << " rad" << std::endl;
    SV_CHECK_MSG(status, angle < 2e-3, "helix frame deviates by " << angle);
  }
  // A planar zigzag with sharp (up to 150 degree) turns: the frame of a planar
  // curve keeps a constant angle to the plane's normal, and matches the reference.
  {
    std::vector<Vec> zig = { { 0, 0, 0 }, { 1, 0, 0 }, { 1.2, 1, 0 }, { 0.3, 0.6, 0 },
      { 0.5, 1.8, 0 }, { 2, 2, 0 }, { 2.1, 0.2, 0 } };
    vtkNew<vtkSplineTubeCore> core;
    core->AddPolyData(MakeLine(zig), nullptr);
    core->Build();
    CheckOrthonormalFrames(status, core);
    const Vec normal = { 0, 0, 1 };
    const double a0 = Dot(NodeVec(Frames(core), 0), normal);
    double worst = 0.0;
    for (vtkIdType i = 0; i < core->GetNumberOfNodes(); ++i)
    {
      worst = std::max(worst, std::abs(Dot(NodeVec(Frames(core), i), normal) - a0));
    }
    SV_CHECK_MSG(status, worst < 1e-4, "planar frame drifts from the normal by " << worst);
    const double angle = CompareWithReferenceFrames(core, 0, 20000);
    std::cout << "zigzag: largest angle to the reference RMF " << angle << " rad" << std::endl;
    SV_CHECK_MSG(status, angle < 5e-3, "zigzag frame deviates by " << angle);
  }
  // A 3D curve with a near-reversal (tangents turning by ~170 degrees between nodes).
  {
    std::vector<Vec> sharp = { { 0, 0, 0 }, { 1, 0, 0 }, { 1.1, 0.3, 0.2 }, { 0.1, 0.35, 0.3 },
      { 0.2, 0.5, 1.0 }, { 1.0, 0.2, 1.4 } };
    vtkNew<vtkSplineTubeCore> core;
    core->AddPolyData(MakeLine(sharp), nullptr);
    core->Build();
    CheckOrthonormalFrames(status, core);
    const double angle = CompareWithReferenceFrames(core, 0, 20000);
    std::cout << "sharp: largest angle to the reference RMF " << angle << " rad" << std::endl;
    SV_CHECK_MSG(status, angle < 5e-3, "sharp-turn frame deviates by " << angle);
  }
  // Many random smooth tubes.
  {
    vtkNew<vtkSyntheticFibersSource> source;
    source->SetNumberOfTubes(20);
    source->SetNumberOfSegments(600);
    source->SetMaximumTurn(0.8);
    source->Update();
    vtkNew<vtkSplineTubeCore> core;
    core->AddPolyData(source->GetOutput(), nullptr);
    core->Build();
    SV_CHECK(status, core->GetNumberOfTubes() == 20);
    SV_CHECK(status, core->GetNumberOfSegments() == 600);
    CheckOrthonormalFrames(status, core);
    double worst = 0.0;
    for (vtkIdType t = 0; t < core->GetNumberOfTubes(); ++t)
    {
      worst = std::max(worst, CompareWithReferenceFrames(core, t, 2000));
    }
    std::cout << "fibers: largest angle to the reference RMF " << worst << " rad" << std::endl;
    SV_CHECK_MSG(status, worst < 2e-3, "fiber frames deviate by " << worst);
  }
}

//------------------------------------------------------------------------------
using vtkSplineTubeMath::vec4;

/// Largest distance (in xyzr space) from the quadratic sub-segments of a cubic
/// segment to the cubic itself: for samples of the quadratics, the distance to
/// the nearest point of the cubic (dense sampling, then golden-section search).
double SplitDeviation(const vec4& p0, const vec4& m0, const vec4& p1, const vec4& m1, int count)
{
  auto cubic = [&](double t) { return vtkSplineTubeMath::svHermite(p0, m0, p1, m1, t); };
  const int dense = 2000;
  std::vector<vec4> samples;
  for (int i = 0; i <= dense; ++i)
  {
    samples.push_back(cubic(static_cast<double>(i) / dense));
  }
  double worst = 0.0;
  for (int k = 0; k < count; ++k)
  {
    vec4 q0, q1, q2;
    vtkSplineTubeMath::svSplitSegment(p0, m0, p1, m1, count, k, q0, q1, q2);
    for (int i = 0; i <= 200; ++i)
    {
      const vec4 q = vtkSplineTubeMath::svQuadratic(q0, q1, q2, i / 200.0);
      int bestIndex = 0;
      double best = 1e300;
      for (int j = 0; j <= dense; ++j)
      {
        const double d = glm::length(q - samples[j]);
        if (d < best)
        {
          best = d;
          bestIndex = j;
        }
      }
      double a = std::max(0, bestIndex - 1) / static_cast<double>(dense);
      double b = std::min(dense, bestIndex + 1) / static_cast<double>(dense);
      const double g = 0.5 * (std::sqrt(5.0) - 1.0);
      for (int it = 0; it < 80; ++it)
      {
        const double c = b - g * (b - a);
        const double d = a + g * (b - a);
        if (glm::length(q - cubic(c)) < glm::length(q - cubic(d)))
        {
          b = d;
        }
        else
        {
          a = c;
        }
      }
      best = std::min(best, glm::length(q - cubic(0.5 * (a + b))));
      worst = std::max(worst, best);
    }
  }
  return worst;
}

void TestSplit(SplineVizTestStatus& status)
{
  // Bound (relative to the chord) on the deviation of two sub-segments; the
  // extreme cases (tangents 3x the chord, an S with an inflection, a U-turn)
  // are only checked for convergence.
  struct Case
  {
    const char* Name;
    vec4 P0, M0, P1, M1;
    double Bound2;
  };
  const Case cases[] = {
    { "helix-like", vec4(1, 0, 0, 0.1), vec4(0, 1, 0.2, 0.05), vec4(0.6, 0.8, 0.2, 0.15),
      vec4(-0.8, 0.6, 0.2, 0.0), 2e-3 },
    { "s-curve", vec4(0, 0, 0, 0.2), vec4(2, 2, 0, 0.0), vec4(1, 0, 0, 0.2), vec4(2, 2, 0.5, 0.1),
      1.0 },
    { "tight bend", vec4(0, 0, 0, 0.05), vec4(1, 0, 0, 0.0), vec4(0, 0.3, 0, 0.05),
      vec4(-1, 0, 0, 0.0), 1.0 },
  };
  for (const auto& c : cases)
  {
    double previous = 0.0;
    for (int count : { 2, 4, 8, 16 })
    {
      // Ends, joints and C1 continuity.
      vec4 q0, q1, q2, n0, n1, n2;
      vtkSplineTubeMath::svSplitSegment(c.P0, c.M0, c.P1, c.M1, count, 0, q0, q1, q2);
      SV_CHECK_NEAR(status, glm::length(q0 - c.P0), 0.0, 1e-12);
      vtkSplineTubeMath::svSplitSegment(c.P0, c.M0, c.P1, c.M1, count, count - 1, q0, q1, q2);
      SV_CHECK_NEAR(status, glm::length(q2 - c.P1), 0.0, 1e-12);
      for (int k = 0; k + 1 < count; ++k)
      {
        vtkSplineTubeMath::svSplitSegment(c.P0, c.M0, c.P1, c.M1, count, k, q0, q1, q2);
        vtkSplineTubeMath::svSplitSegment(c.P0, c.M0, c.P1, c.M1, count, k + 1, n0, n1, n2);
        SV_CHECK_NEAR(status, glm::length(q2 - n0), 0.0, 1e-12);
        // Equal parameter lengths: C1 means q2 - q1 == n1 - n0.
        SV_CHECK_NEAR(status, glm::length((q2 - q1) - (n1 - n0)), 0.0, 1e-12);
      }
      // End derivatives of the cubic are matched: d/dt at t = 0 is count * 2 (q1 - q0).
      vtkSplineTubeMath::svSplitSegment(c.P0, c.M0, c.P1, c.M1, count, 0, q0, q1, q2);
      SV_CHECK_NEAR(status, glm::length(2.0 * count * (q1 - q0) - c.M0), 0.0, 1e-12);

      const double deviation = SplitDeviation(c.P0, c.M0, c.P1, c.M1, count);
      const double chord = glm::length(vtkSplineTubeMath::vec3(c.P1 - c.P0));
      std::cout << c.Name << ": " << count << " sub-segments, deviation " << deviation << " (chord "
                << chord << ")" << std::endl;
      if (count == 2)
      {
        SV_CHECK_MSG(status, deviation < c.Bound2 * chord,
          c.Name << ": two sub-segments deviate by " << deviation);
      }
      else
      {
        // Third order: halving the sub-segments divides the deviation by ~8.
        SV_CHECK_MSG(status, deviation < previous / 6.0,
          c.Name << ": deviation " << deviation << " after " << previous);
      }
      previous = deviation;
    }
  }

  // Real tubes with sharp turns (up to 0.8 rad, 46 degrees, between
  // segments): two sub-segments stay within 1% of the segment length of the
  // cubic, i.e. sub-pixel for segments up to 100 pixels long on screen.
  vtkNew<vtkSyntheticFibersSource> source;
  source->SetNumberOfTubes(10);
  source->SetNumberOfSegments(300);
  source->SetMaximumTurn(0.8);
  source->Update();
  vtkNew<vtkSplineTubeCore> core;
  core->SetRadiusArray("Radius");
  core->AddPolyData(source->GetOutput(), nullptr);
  core->Build();
  double worst = 0.0;
  for (vtkIdType s = 0; s < core->GetNumberOfSegments(); ++s)
  {
    const vtkIdType i = core->GetSegmentFirstNode(s);
    auto node = [&](vtkIdType j)
    {
      return vec4(Positions(core)->GetComponent(j, 0), Positions(core)->GetComponent(j, 1),
        Positions(core)->GetComponent(j, 2), Radii(core)->GetComponent(j, 0));
    };
    auto deriv = [&](vtkIdType j)
    {
      return vec4(Tangents(core)->GetComponent(j, 0), Tangents(core)->GetComponent(j, 1),
        Tangents(core)->GetComponent(j, 2), Radii(core)->GetComponent(j, 1));
    };
    worst = std::max(worst, SplitDeviation(node(i), deriv(i), node(i + 1), deriv(i + 1), 2) / 0.02);
  }
  std::cout << "fibers: worst deviation of 2 sub-segments " << worst << " of the segment length"
            << std::endl;
  SV_CHECK_MSG(status, worst < 1e-2, "fiber split deviates by " << worst);
}

//------------------------------------------------------------------------------
/// Checks that the box contains every sampled sphere and is tight.
void CheckBox(SplineVizTestStatus& status, const vec4& q0, const vec4& q1, const vec4& q2,
  double& worstOutside, double& worstSlack)
{
  vtkSplineTubeMath::SvBox box;
  vtkSplineTubeMath::svSubSegmentBox(q0, q1, q2, box);
  const vtkSplineTubeMath::vec3 axes[3] = { box.axis0, box.axis1, box.axis2 };
  SV_CHECK_NEAR(status, glm::dot(box.axis0, box.axis1), 0.0, 1e-9);
  SV_CHECK_NEAR(status, glm::dot(box.axis0, box.axis2), 0.0, 1e-9);
  SV_CHECK_NEAR(status, glm::dot(box.axis1, box.axis2), 0.0, 1e-9);
  double reachHi[3] = { -1e300, -1e300, -1e300 };
  double reachLo[3] = { 1e300, 1e300, 1e300 };
  const int samples = 2000;
  for (int i = 0; i <= samples; ++i)
  {
    const vec4 s = vtkSplineTubeMath::svQuadratic(q0, q1, q2, static_cast<double>(i) / samples);
    const vtkSplineTubeMath::vec3 d = vtkSplineTubeMath::vec3(s) - box.center;
    for (int a = 0; a < 3; ++a)
    {
      const double x = glm::dot(d, axes[a]);
      reachHi[a] = std::max(reachHi[a], x + s.w);
      reachLo[a] = std::min(reachLo[a], x - s.w);
    }
  }
  const double size = std::max({ box.halfSize.x, box.halfSize.y, box.halfSize.z });
  for (int a = 0; a < 3; ++a)
  {
    worstOutside = std::max(worstOutside, (reachHi[a] - box.halfSize[a]) / size);
    worstOutside = std::max(worstOutside, (-box.halfSize[a] - reachLo[a]) / size);
    worstSlack = std::max(worstSlack, (box.halfSize[a] - reachHi[a]) / size);
    worstSlack = std::max(worstSlack, (reachLo[a] + box.halfSize[a]) / size);
  }
}

void TestBoxes(SplineVizTestStatus& status)
{
  double worstOutside = 0.0;
  double worstSlack = 0.0;
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(7);
  auto uniform = [&](double a, double b)
  {
    random->Next();
    return random->GetRangeValue(a, b);
  };
  for (int trial = 0; trial < 500; ++trial)
  {
    vec4 q[3];
    for (auto& v : q)
    {
      v = vec4(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1), uniform(0.0, 0.3));
    }
    if (trial % 50 == 0)
    {
      q[1] = 0.5 * (q[0] + q[2]); // collinear
    }
    if (trial % 77 == 0)
    {
      q[2] = q[0]; // closed
    }
    CheckBox(status, q[0], q[1], q[2], worstOutside, worstSlack);
  }
  // Sub-segments of real tubes.
  vtkNew<vtkSyntheticFibersSource> source;
  source->SetNumberOfTubes(10);
  source->SetNumberOfSegments(300);
  source->Update();
  vtkNew<vtkSplineTubeCore> core;
  core->SetRadiusArray("Radius");
  core->AddPolyData(source->GetOutput(), nullptr);
  core->Build();
  for (vtkIdType s = 0; s < core->GetNumberOfSegments(); ++s)
  {
    const vtkIdType i = core->GetSegmentFirstNode(s);
    auto node = [&](vtkIdType j)
    {
      return vec4(Positions(core)->GetComponent(j, 0), Positions(core)->GetComponent(j, 1),
        Positions(core)->GetComponent(j, 2), Radii(core)->GetComponent(j, 0));
    };
    auto deriv = [&](vtkIdType j)
    {
      return vec4(Tangents(core)->GetComponent(j, 0), Tangents(core)->GetComponent(j, 1),
        Tangents(core)->GetComponent(j, 2), Radii(core)->GetComponent(j, 1));
    };
    for (int k = 0; k < 2; ++k)
    {
      vec4 q0, q1, q2;
      vtkSplineTubeMath::svSplitSegment(
        node(i), deriv(i), node(i + 1), deriv(i + 1), 2, k, q0, q1, q2);
      CheckBox(status, q0, q1, q2, worstOutside, worstSlack);
    }
  }
  std::cout << "boxes: worst relative protrusion " << worstOutside << ", worst slack " << worstSlack
            << std::endl;
  SV_CHECK_MSG(status, worstOutside < 1e-9, "a swept sphere leaves its box by " << worstOutside);
  SV_CHECK_MSG(status, worstSlack < 2e-3, "a box is loose by " << worstSlack);
}

//------------------------------------------------------------------------------
void TestSegmentTable(SplineVizTestStatus& status)
{
  vtkNew<vtkSyntheticFibersSource> source;
  source->SetNumberOfTubes(30);
  source->SetNumberOfSegments(500);
  source->Update();
  vtkNew<vtkSplineTubeCore> core;
  core->AddPolyData(source->GetOutput(), nullptr, 3);
  core->AddPolyData(source->GetOutput(), nullptr, 4);
  core->Build();
  SV_CHECK(status, core->GetNumberOfTubes() == 60);
  SV_CHECK(status, core->GetNumberOfSegments() == 1000);
  SV_CHECK(status, core->GetNumberOfNodes() == 1060);
  vtkIdType s = 0;
  for (vtkIdType t = 0; t < core->GetNumberOfTubes(); ++t)
  {
    const vtkIdType first = core->GetTubeFirstNode(t);
    const vtkIdType n = core->GetTubeNumberOfNodes(t);
    for (vtkIdType k = 0; k + 1 < n; ++k, ++s)
    {
      SV_CHECK(status, core->GetSegmentFirstNode(s) == first + k);
      const int flags = core->GetSegmentFlags(s);
      SV_CHECK(status, ((flags & vtkSplineTubeCore::TUBE_START) != 0) == (k == 0));
      SV_CHECK(status, ((flags & vtkSplineTubeCore::TUBE_END) != 0) == (k + 2 == n));
      SV_CHECK(
        status, core->GetTubeCellId(core->GetTubeOfNode(core->GetSegmentFirstNode(s))) == t % 30);
      SV_CHECK(status,
        core->GetTubeBlockId(core->GetTubeOfNode(core->GetSegmentFirstNode(s))) ==
          (t < 30 ? 3u : 4u));
    }
  }
  SV_CHECK(status, s == core->GetNumberOfSegments());
  double b[6];
  core->GetBounds(b);
  double pb[6];
  source->GetOutput()->GetBounds(pb);
  SV_CHECK(status, b[0] < pb[0] && b[1] > pb[1] && b[2] < pb[2] && b[3] > pb[3]);
}

//------------------------------------------------------------------------------
// ChunkTables off (the stylized lines): no chunk table, the same bounds.
void TestBoundsOnly(SplineVizTestStatus& status)
{
  vtkNew<vtkSyntheticFibersSource> source;
  source->SetNumberOfTubes(40);
  source->SetNumberOfSegments(300);
  source->Update();
  vtkNew<vtkSplineTubeCore> full;
  vtkNew<vtkSplineTubeCore> bounds;
  bounds->ChunkTablesOff();
  for (vtkSplineTubeCore* core : { full.GetPointer(), bounds.GetPointer() })
  {
    core->SetRadius(0.05);
    core->AddPolyData(source->GetOutput(), nullptr);
    core->Build();
  }
  SV_CHECK(status, full->GetNumberOfChunks() > 0);
  SV_CHECK(status, bounds->GetNumberOfChunks() == 0);
  SV_CHECK(status, bounds->GetChunkSpheres()->GetNumberOfTuples() == 0);
  SV_CHECK(status, bounds->GetSegmentSpheres()->GetNumberOfTuples() == 0);
  SV_CHECK(status, bounds->GetNumberOfSegments() == full->GetNumberOfSegments());
  double a[6];
  double b[6];
  full->GetBounds(a);
  bounds->GetBounds(b);
  double pb[6];
  source->GetOutput()->GetBounds(pb);
  for (int k = 0; k < 6; ++k)
  {
    SV_CHECK_MSG(status, a[k] == b[k],
      "bound " << k << ": " << a[k] << " with the chunk table, " << b[k] << " without");
    // Every point's sphere of radius 0.05 lies inside (independently of the core).
    const double point = k % 2 == 0 ? pb[k] - 0.05 : pb[k] + 0.05;
    SV_CHECK(status, k % 2 == 0 ? b[k] <= point + 1e-12 : b[k] >= point - 1e-12);
  }
  // Back on: the table again.
  bounds->ChunkTablesOn();
  bounds->Initialize();
  bounds->AddPolyData(source->GetOutput(), nullptr);
  bounds->Build();
  SV_CHECK(status, bounds->GetNumberOfChunks() == full->GetNumberOfChunks());
}

//------------------------------------------------------------------------------
void TestDegenerateInput(SplineVizTestStatus& status)
{
  vtkNew<vtkTest::ErrorObserver> observer;
  vtkNew<vtkSplineTubeCore> core;
  core->AddObserver(vtkCommand::ErrorEvent, observer);
  core->AddObserver(vtkCommand::WarningEvent, observer);

  // Repeated points are merged.
  core->AddPolyData(
    MakeLine({ { 0, 0, 0 }, { 0, 0, 0 }, { 1, 0, 0 }, { 1, 0, 0 }, { 2, 1, 0 } }), nullptr);
  core->Build();
  SV_CHECK(status, core->GetNumberOfNodes() == 3);
  SV_CHECK(status, core->GetNumberOfMergedPoints() == 2);
  SV_CHECK(status, observer->CheckWarningMessage("repeated") == 0);

  // One-point lines and lines of one repeated point are skipped.
  core->Initialize();
  core->AddPolyData(MakeLine({ { 0, 0, 0 } }), nullptr);
  core->AddPolyData(MakeLine({ { 1, 1, 1 }, { 1, 1, 1 }, { 1, 1, 1 } }), nullptr);
  core->Build();
  SV_CHECK(status, core->GetNumberOfTubes() == 0);
  SV_CHECK(status, core->GetNumberOfSkippedLines() == 2);
  SV_CHECK(status, observer->CheckWarningMessage("fewer than two distinct points") == 0);

  // NaN positions.
  core->Initialize();
  const double nan = std::nan("");
  core->AddPolyData(MakeLine({ { 0, 0, 0 }, { nan, 0, 0 }, { 1, 0, 0 } }), nullptr);
  core->AddPolyData(MakeLine({ { 0, 0, 0 }, { 1, 0, 0 } }), nullptr);
  core->Build();
  SV_CHECK(status, core->GetNumberOfTubes() == 1);
  SV_CHECK(status, observer->CheckWarningMessage("NaN or infinite coordinate") == 0);

  // Zero, negative, NaN radii.
  core->SetRadiusArray("R");
  for (double bad : { 0.0, -1.0, nan })
  {
    core->Initialize();
    const std::vector<double> radii = { 0.1, bad, 0.1 };
    core->AddPolyData(MakeLine({ { 0, 0, 0 }, { 1, 0, 0 }, { 2, 0, 0 } }, &radii), nullptr);
    core->Build();
    SV_CHECK(status, core->GetNumberOfTubes() == 0);
    SV_CHECK(status, observer->CheckWarningMessage("has the radius") == 0);
  }
  // Radius scale applies.
  core->Initialize();
  core->SetRadiusScale(2.0);
  const std::vector<double> radii = { 0.1, 0.2, 0.3 };
  core->AddPolyData(MakeLine({ { 0, 0, 0 }, { 1, 0, 0 }, { 2, 0, 0 } }, &radii), nullptr);
  core->Build();
  SV_CHECK_NEAR(status, Radii(core)->GetComponent(2, 0), 0.6, 1e-6);
  SV_CHECK_NEAR(status, Radii(core)->GetComponent(1, 1), 0.2, 1e-6);
  SV_CHECK_NEAR(status, core->GetMaximumRadius(), 0.6, 1e-6);

  // Missing radius array: an error, nothing added.
  core->Initialize();
  core->SetRadiusArray("NoSuchArray");
  SV_CHECK(status, !core->AddPolyData(MakeLine({ { 0, 0, 0 }, { 1, 0, 0 } }), nullptr));
  SV_CHECK(status, observer->CheckErrorMessage("is not a point array") == 0);
  SV_CHECK(status, core->GetNumberOfTubes() == 0);

  // A 3-component radius array: an error.
  auto line = MakeLine({ { 0, 0, 0 }, { 1, 0, 0 } });
  vtkNew<vtkFloatArray> vectors;
  vectors->SetName("V");
  vectors->SetNumberOfComponents(3);
  vectors->InsertNextTuple3(1, 1, 1);
  vectors->InsertNextTuple3(1, 1, 1);
  line->GetPointData()->AddArray(vectors);
  core->SetRadiusArray("V");
  SV_CHECK(status, !core->AddPolyData(line, nullptr));
  SV_CHECK(status, observer->CheckErrorMessage("components") == 0);

  // Bad colors: an error.
  core->SetRadiusArray(nullptr);
  vtkNew<vtkUnsignedCharArray> rgb;
  rgb->SetNumberOfComponents(3);
  rgb->SetNumberOfTuples(2);
  SV_CHECK(status, !core->AddPolyData(line, rgb));
  SV_CHECK(status, observer->CheckErrorMessage("RGBA") == 0);

  // Empty input and input without lines: nothing, no message.
  core->Initialize();
  vtkNew<vtkPolyData> empty;
  SV_CHECK(status, core->AddPolyData(empty, nullptr));
  SV_CHECK(status, core->AddPolyData(nullptr, nullptr));
  core->Build();
  SV_CHECK(status, core->GetNumberOfTubes() == 0);
  double b[6];
  core->GetBounds(b);
  SV_CHECK(status, !vtkMath::AreBoundsInitialized(b));
  SV_CHECK(status, !observer->GetError());
}

//------------------------------------------------------------------------------
// The optional per-node values (NodeScalarArray): carried through the
// merge of repeated points, NaN skips the line, a missing or 3-component
// array is an error naming the role.
void TestNodeScalars(SplineVizTestStatus& status)
{
  vtkNew<vtkTest::ErrorObserver> observer;
  vtkNew<vtkSplineTubeCore> core;
  core->AddObserver(vtkCommand::ErrorEvent, observer);
  core->AddObserver(vtkCommand::WarningEvent, observer);
  core->SetNodeScalarArray("Angle");
  core->SetNodeScalarRole("orientation");
  auto withAngles = [](vtkPolyData* line, const std::vector<double>& angles)
  {
    vtkNew<vtkDoubleArray> a;
    a->SetName("Angle");
    for (double v : angles)
    {
      a->InsertNextValue(v);
    }
    line->GetPointData()->AddArray(a);
  };
  auto line = MakeLine({ { 0, 0, 0 }, { 1, 0, 0 }, { 1, 0, 0 }, { 2, 1, 0 } });
  withAngles(line, { 0.5, 1.5, 2.5, 3.5 });
  auto second = MakeLine({ { 5, 0, 0 }, { 6, 0, 0 } });
  withAngles(second, { -1.0, -2.0 });
  core->AddPolyData(line, nullptr);
  core->AddPolyData(second, nullptr);
  core->Build();
  vtkSmartPointer<vtkFloatArray> values = Scalars(core);
  SV_CHECK(status, core->GetNumberOfNodes() == 5);
  SV_CHECK(status, values->GetNumberOfTuples() == 5);
  // The merged point keeps the first of the repeated values.
  const double expected[5] = { 0.5, 1.5, 3.5, -1.0, -2.0 };
  for (int i = 0; i < 5 && values->GetNumberOfTuples() == 5; ++i)
  {
    SV_CHECK_NEAR(status, values->GetValue(i), expected[i], 1e-6);
  }

  // A NaN angle skips its line with a warning that names the role.
  core->Initialize();
  auto bad = MakeLine({ { 0, 0, 0 }, { 1, 0, 0 }, { 2, 0, 0 } });
  withAngles(bad, { 0.0, std::nan(""), 0.0 });
  core->AddPolyData(bad, nullptr);
  core->Build();
  SV_CHECK(status, core->GetNumberOfTubes() == 0);
  SV_CHECK(status, observer->CheckWarningMessage("orientation array \"Angle\"") == 0);

  // Missing: an error naming the role, nothing added.
  core->Initialize();
  SV_CHECK(status, !core->AddPolyData(MakeLine({ { 0, 0, 0 }, { 1, 0, 0 } }), nullptr));
  SV_CHECK(status, observer->CheckErrorMessage("The orientation array \"Angle\" is not") == 0);
  // Three components: an error.
  auto vectorLine = MakeLine({ { 0, 0, 0 }, { 1, 0, 0 } });
  vtkNew<vtkFloatArray> vectors;
  vectors->SetName("Angle");
  vectors->SetNumberOfComponents(3);
  vectors->InsertNextTuple3(1, 1, 1);
  vectors->InsertNextTuple3(1, 1, 1);
  vectorLine->GetPointData()->AddArray(vectors);
  SV_CHECK(status, !core->AddPolyData(vectorLine, nullptr));
  SV_CHECK(status, observer->CheckErrorMessage("components") == 0);
  SV_CHECK(status, core->GetNumberOfTubes() == 0);
}
}

int TestSplineTubeCore(int, char*[])
{
  SplineVizTestStatus status;
  TestHermite(status);
  TestFrames(status);
  TestSplit(status);
  TestBoxes(status);
  TestSegmentTable(status);
  TestBoundsOnly(status);
  TestDegenerateInput(status);
  TestNodeScalars(status);
  return status.Result();
}
