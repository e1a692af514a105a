// SPDX-License-Identifier: BSD-3-Clause
// Unit tests of the stylized-line math shared with the shaders
// (vtkStylizedLineMath.h, Stoll et al. §4.1-4.4) and of the fix-up's CPU
// classification (vtkStylizedLineFixUp):
//  - Eq. 4-5: y is orthogonal to t and to u_perp, x = t x y points from the
//    axis toward the eye;
//  - Eq. 6-7: the exact silhouette points lie on the vertex's circle and the
//    cylinder's normal there is orthogonal to the ray from the eye (Eq. 3),
//    checked against the definition, not the formula; Eq. 8 only
//    approximately (a negative control that the check can fail);
//  - Eq. 9-10: the interpolated normal is a unit vector that reaches the
//    silhouette normals at tex0 = +-f;
//  - Eq. 11: the front distance equals the distance to the infinite
//    cylinder found by bisection along the ray;
//  - the vertex tangents are the bisectors (segment directions at the ends);
//  - the fix-up: batches tile every polyline within the documented limits;
//    for random views (perspective and parallel, near, far and inside the
//    lines) the classification with the cone test flags exactly the batches
//    that the vertex-by-vertex reference flags, every vertex that needs the
//    fix-up lies in a flagged batch, and the draw lists cover every segment
//    exactly once (as a quad or as a cylinder).
#include "vtkStylizedLineFixUp.h"
#include "vtkStylizedLineMath.h"

#include "SplineVizTestUtilities.h"

#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSplineTubeCore.h"

#include <cmath>
#include <vector>

namespace
{
using vtkStylizedLineMath::slExtrusion;
using vtkStylizedLineMath::slFrame;
using vtkStylizedLineMath::slFrontDistance;
using vtkStylizedLineMath::slNeedsFixUp;
using vtkStylizedLineMath::slNormal;
using vtkStylizedLineMath::slPolylineTangent;
using vec3 = glm::dvec3;

struct Random
{
  vtkNew<vtkMinimalStandardRandomSequence> Sequence;
  explicit Random(int seed) { this->Sequence->SetSeed(seed); }
  double Next(double lo, double hi)
  {
    this->Sequence->Next();
    return this->Sequence->GetRangeValue(lo, hi);
  }
  vec3 Unit()
  {
    for (;;)
    {
      vec3 v(this->Next(-1, 1), this->Next(-1, 1), this->Next(-1, 1));
      const double l = glm::length(v);
      if (l > 0.1 && l <= 1.0)
      {
        return v / l;
      }
    }
  }
};

void TestSilhouette(SplineVizTestStatus& status)
{
  Random random(7);
  double worstOnCircle = 0.0;
  double worstTangency = 0.0;
  double worstFrame = 0.0;
  double worstNormal = 0.0;
  double approxTangency = 0.0;
  for (int trial = 0; trial < 2000; ++trial)
  {
    const vec3 t = random.Unit();
    const double r = random.Next(0.01, 1.0);
    // The vertex p (view coordinates, eye at 0) at a distance of 2r .. 100r
    // from the axis line and anywhere along it.
    const vec3 side = glm::normalize(glm::cross(t, random.Unit()));
    const vec3 p = random.Next(2.0, 100.0) * r * side + random.Next(-50.0, 50.0) * r * t;
    vec3 x;
    vec3 y;
    double uPerp = 0.0;
    SV_CHECK(status, slFrame(p, t, x, y, uPerp));
    const vec3 u = p - glm::dot(p, t) * t;
    worstFrame = std::max({ worstFrame, std::abs(glm::dot(y, t)), std::abs(glm::dot(y, u)),
      std::abs(glm::length(y) - 1.0), glm::length(x + u / glm::length(u)),
      std::abs(uPerp - glm::length(u)) / glm::length(u) });
    for (double s : { -1.0, 1.0 })
    {
      double f = 0.0;
      const vec3 e = slExtrusion(x, y, r, uPerp, false, true, s, 1.0, f);
      // On the vertex's circle: in its plane, at distance r from p.
      worstOnCircle =
        std::max({ worstOnCircle, std::abs(glm::dot(e, t)) / r, std::abs(glm::length(e) - r) / r });
      // A silhouette point: the cylinder's normal e / r is orthogonal to the
      // ray from the eye to the point (Eq. 3).
      const vec3 q = p + e;
      worstTangency = std::max(worstTangency, std::abs(glm::dot(e / r, q / glm::length(q))));
      // Eq. 9 = Eq. 10 at tex0 = s f.
      const vec3 n = slNormal(x, y, s * f);
      worstNormal = std::max(worstNormal, glm::length(n - e / r));
      // Eq. 8 for comparison.
      double f8 = 0.0;
      const vec3 e8 = slExtrusion(x, y, r, uPerp, false, false, s, 1.0, f8);
      const vec3 q8 = p + e8;
      approxTangency = std::max(approxTangency, std::abs(glm::dot(e8 / r, q8 / glm::length(q8))));
    }
  }
  SV_CHECK_MSG(status, worstFrame < 1e-9, "Eq. 4-5 frame error " << worstFrame);
  SV_CHECK_MSG(
    status, worstOnCircle < 1e-9, "silhouette points off the circle by " << worstOnCircle);
  SV_CHECK_MSG(
    status, worstTangency < 1e-9, "Eq. 6 points are not silhouette points: " << worstTangency);
  SV_CHECK_MSG(
    status, worstNormal < 1e-9, "Eq. 10 misses Eq. 9 at the silhouette: " << worstNormal);
  // Negative control: Eq. 8 is measurably not tangent close to the line.
  SV_CHECK_MSG(status, approxTangency > 0.1, "Eq. 8 tangency error only " << approxTangency);

  // A parallel camera: the silhouette lies in the plane of the axis, +-r y.
  const vec3 t(0.0, 0.6, 0.8);
  vec3 x;
  vec3 y;
  double uPerp;
  slFrame(vec3(0.0, 0.0, -1.0), t, x, y, uPerp);
  double f = 0.0;
  const vec3 e = slExtrusion(x, y, 0.5, uPerp, true, true, 1.0, 2.0, f);
  SV_CHECK_NEAR(status, f, 1.0, 1e-12);
  SV_CHECK_NEAR(status, glm::length(e - 1.0 * y), 0.0, 1e-12); // widened by the halo factor 2
  SV_CHECK_NEAR(status, x.z, 0.6, 1e-12); // toward the eye: x = -u_perp / |u_perp|

  // The singular view: no frame, but orthonormal vectors.
  SV_CHECK(status, !slFrame(vec3(0.0, 0.0, -5.0), vec3(0.0, 0.0, 1.0), x, y, uPerp));
  SV_CHECK_NEAR(status, glm::length(x), 1.0, 1e-12);
  SV_CHECK_NEAR(status, glm::dot(x, y), 0.0, 1e-12);
}

void TestFrontDistance(SplineVizTestStatus& status)
{
  Random random(11);
  double worst = 0.0;
  for (int trial = 0; trial < 1000; ++trial)
  {
    const vec3 t = random.Unit();
    vec3 dir = random.Unit();
    if (std::abs(glm::dot(dir, t)) > 0.97)
    {
      continue;
    }
    const double r = random.Next(0.1, 2.0);
    // From a point of the axis back along the ray to the cylinder's surface:
    // the distance from the axis of p - lambda dir grows monotonically.
    auto axisDistance = [&](double lambda)
    {
      const vec3 q = -lambda * dir;
      return glm::length(q - glm::dot(q, t) * t);
    };
    double lo = 0.0;
    double hi = 1.0;
    while (axisDistance(hi) < r)
    {
      hi *= 2.0;
    }
    for (int it = 0; it < 100; ++it)
    {
      const double mid = 0.5 * (lo + hi);
      (axisDistance(mid) < r ? lo : hi) = mid;
    }
    worst = std::max(worst, std::abs(slFrontDistance(dir, t, r, 1e9) - lo) / r);
  }
  SV_CHECK_MSG(status, worst < 1e-9, "Eq. 11 distance error " << worst);
  // The cap applies along the axis.
  SV_CHECK_NEAR(status, slFrontDistance(vec3(0, 0, 1), vec3(0, 0, 1), 1.0, 8.0), 8.0, 1e-12);
}

void TestTangents(SplineVizTestStatus& status)
{
  const vec3 a(2.0, 0.0, 0.0);
  const vec3 b(0.0, 3.0, 0.0);
  const vec3 t = slPolylineTangent(a, b);
  SV_CHECK_NEAR(status, glm::length(t - glm::normalize(vec3(1.0, 1.0, 0.0))), 0.0, 1e-12);
  SV_CHECK_NEAR(status, glm::length(slPolylineTangent(vec3(0.0), b) - vec3(0, 1, 0)), 0.0, 1e-12);
  SV_CHECK_NEAR(status, glm::length(slPolylineTangent(a, vec3(0.0)) - vec3(1, 0, 0)), 0.0, 1e-12);
  // A full turn back: the following segment's direction.
  SV_CHECK_NEAR(status, glm::length(slPolylineTangent(a, -a) + vec3(1, 0, 0)), 0.0, 1e-12);
}

/// Random polylines: smooth wanderers, straight lines, and short ones.
vtkSmartPointer<vtkPolyData> RandomLines(Random& random)
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> lines;
  vtkNew<vtkDoubleArray> radius;
  radius->SetName("Radius");
  for (int l = 0; l < 60; ++l)
  {
    const int n = l % 10 == 0 ? 2 : 5 + static_cast<int>(random.Next(0, 120));
    vec3 p(random.Next(-3, 3), random.Next(-3, 3), random.Next(-3, 3));
    vec3 d = random.Unit();
    const double turn = l % 7 == 0 ? 0.0 : random.Next(0.0, 0.5);
    lines->InsertNextCell(n);
    for (int i = 0; i < n; ++i)
    {
      lines->InsertCellPoint(points->InsertNextPoint(p.x, p.y, p.z));
      radius->InsertNextValue(random.Next(0.01, 0.08));
      d = glm::normalize(d + turn * random.Unit());
      p += random.Next(0.02, 0.2) * d;
    }
  }
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  pd->SetPoints(points);
  pd->SetLines(lines);
  pd->GetPointData()->AddArray(radius);
  return pd;
}

void TestFixUp(SplineVizTestStatus& status)
{
  Random random(3);
  vtkNew<vtkSplineTubeCore> core;
  core->SetRadiusArray("Radius");
  core->AddPolyData(RandomLines(random), nullptr);
  core->Build();
  const double shift[3] = { 0.3, -0.2, 0.1 };
  vtkStylizedLineFixUp fixUp;
  fixUp.Build(core, shift);
  const vtkIdType numTubes = core->GetNumberOfTubes();
  const vtkIdType numNodes = core->GetNumberOfNodes();
  // The nodes (positions, radii) and the fix-up's vertex tangents, read
  // through the accessors, laid out 3, 2 and 3 per node.
  std::vector<double> P(static_cast<size_t>(3 * numNodes));
  std::vector<double> R(static_cast<size_t>(2 * numNodes));
  std::vector<double> T(static_cast<size_t>(3 * numNodes));
  for (vtkIdType i = 0; i < numNodes; ++i)
  {
    double p[4];
    core->GetNode(i, p);
    std::copy(p, p + 3, &P[3 * i]);
    R[2 * i] = p[3];
    fixUp.GetTangent(i, &T[3 * i]);
    SV_CHECK(
      status, std::abs(glm::length(vec3(T[3 * i], T[3 * i + 1], T[3 * i + 2])) - 1.0) < 1e-9);
  }

  // Batches tile the polylines: consecutive, sharing their end points, at
  // most 16 segments, tangents within 12 degrees of the first.
  std::vector<int> segmentBatches(static_cast<size_t>(numNodes), 0);
  for (vtkIdType b = 0; b < fixUp.GetNumberOfBatches(); ++b)
  {
    const vtkIdType first = fixUp.GetBatchFirstNode(b);
    const int segments = fixUp.GetBatchNumberOfSegments(b);
    SV_CHECK(status, segments >= 1 && segments <= vtkStylizedLineFixUp::MaximumBatchSegments);
    const vec3 axis(T[3 * first], T[3 * first + 1], T[3 * first + 2]);
    for (vtkIdType i = first; i <= first + segments; ++i)
    {
      const vec3 ti(T[3 * i], T[3 * i + 1], T[3 * i + 2]);
      if (segments > 1 || i == first)
      {
        SV_CHECK(
          status, glm::dot(axis, ti) >= std::cos(vtkStylizedLineFixUp::MaximumBatchAngle) - 1e-6);
      }
    }
    for (vtkIdType s = first; s < first + segments; ++s)
    {
      ++segmentBatches[s];
    }
  }
  for (vtkIdType t = 0; t < numTubes; ++t)
  {
    const vtkIdType first = core->GetTubeFirstNode(t);
    const vtkIdType n = core->GetTubeNumberOfNodes(t);
    for (vtkIdType s = first; s + 1 < first + n; ++s)
    {
      SV_CHECK(status, segmentBatches[s] == 1);
    }
  }

  // Random views.
  long flaggedTotal = 0;
  long candidates = 0;
  long batches = 0;
  for (int trial = 0; trial < 300; ++trial)
  {
    vtkStylizedLineFixUp::View view;
    // A rigid motion with a uniform scale: eye anywhere (also among and
    // inside the lines), looking anywhere.
    vec3 eye(random.Next(-5, 5), random.Next(-5, 5), random.Next(-5, 5));
    vec3 forward = random.Unit();
    if (trial % 6 == 1)
    {
      // Exactly along a vertex tangent, from before the vertex.
      const vtkIdType i = static_cast<vtkIdType>(random.Next(0, numNodes - 1));
      forward = vec3(T[3 * i], T[3 * i + 1], T[3 * i + 2]);
      eye = vec3(P[3 * i], P[3 * i + 1], P[3 * i + 2]) - random.Next(0.5, 5.0) * forward;
    }
    const vec3 right = glm::normalize(glm::cross(forward, random.Unit()));
    const vec3 up = glm::cross(right, forward);
    const double scale = random.Next(0.5, 2.0);
    // Rows of the rotation: right, up, -forward; translation -R (eye - shift).
    const vec3 rows[3] = { right, up, -forward };
    const vec3 eyeShifted = eye - vec3(shift[0], shift[1], shift[2]);
    for (int r = 0; r < 3; ++r)
    {
      for (int c = 0; c < 3; ++c)
      {
        view.ModelView[4 * c + r] = scale * rows[r][c];
      }
      view.ModelView[12 + r] = -scale * glm::dot(rows[r], eyeShifted);
      view.ModelView[4 * r + 3] = 0.0;
    }
    view.ModelView[15] = 1.0;
    view.RadiusScale = scale;
    view.Parallel = trial % 4 == 3;
    view.Epsilon = trial % 5 == 0 ? 0.2 : 0.025;
    view.JointRadius = 1.0;
    view.PixelsPerUnit = 500.0;
    view.PixelsPerUnit = 500.0;
    std::vector<int> firsts;
    std::vector<int> counts;
    std::vector<std::uint32_t> segments;
    std::vector<std::uint32_t> joints;
    std::vector<std::uint32_t> all(static_cast<size_t>(fixUp.GetNumberOfBatches()));
    for (size_t b = 0; b < all.size(); ++b)
    {
      all[b] = static_cast<std::uint32_t>(b);
    }
    std::vector<std::uint32_t> caps;
    fixUp.BeginView(view, true);
    fixUp.BuildDraws(all, firsts, counts, caps, segments, joints);
    SV_CHECK_MSG(status, static_cast<vtkIdType>(caps.size()) == 2 * numTubes,
      "view " << trial << ": " << caps.size() << " caps for " << numTubes << " polylines");
    const std::vector<unsigned char>& flags = fixUp.GetBatchFlags();
    const std::vector<unsigned char> reference = fixUp.ClassifyAllVertices(view);
    long mismatches = 0;
    for (size_t b = 0; b < flags.size(); ++b)
    {
      mismatches += flags[b] != reference[b] ? 1 : 0;
      flaggedTotal += flags[b];
    }
    SV_CHECK_MSG(status, mismatches == 0,
      "view " << trial << ": " << mismatches << " batches classified unlike the reference");
    candidates += fixUp.GetNumberOfCandidateBatches();
    batches += fixUp.GetNumberOfBatches();

    // Every vertex that needs the fix-up lies in a flagged batch.
    std::vector<char> fixedNode(static_cast<size_t>(numNodes), 0);
    for (vtkIdType b = 0; b < fixUp.GetNumberOfBatches(); ++b)
    {
      if (flags[b])
      {
        for (vtkIdType i = fixUp.GetBatchFirstNode(b);
             i <= fixUp.GetBatchFirstNode(b) + fixUp.GetBatchNumberOfSegments(b); ++i)
        {
          fixedNode[i] = 1;
        }
      }
    }
    long missed = 0;
    for (vtkIdType i = 0; i < numNodes; ++i)
    {
      const vec3 pm(P[3 * i] - shift[0], P[3 * i + 1] - shift[1], P[3 * i + 2] - shift[2]);
      vec3 p(0.0);
      vec3 t(0.0);
      for (int r = 0; r < 3; ++r)
      {
        p[r] = view.ModelView[12 + r];
        for (int c = 0; c < 3; ++c)
        {
          p[r] += view.ModelView[4 * c + r] * pm[c];
          t[r] += view.ModelView[4 * c + r] * T[3 * i + c];
        }
      }
      t = glm::normalize(t);
      if (slNeedsFixUp(p, t, R[2 * i] * scale, view.Parallel, view.Epsilon) && !fixedNode[i])
      {
        ++missed;
      }
    }
    SV_CHECK_MSG(status, missed == 0, "view " << trial << ": " << missed << " vertices missed");

    // The draw lists: every segment once, as part of a strip or fixed up.
    std::vector<int> drawn(static_cast<size_t>(numNodes), 0);
    for (size_t k = 0; k < firsts.size(); ++k)
    {
      SV_CHECK(status, firsts[k] % 2 == 0 && counts[k] % 2 == 0 && counts[k] >= 4);
      for (int i = firsts[k] / 2; i < firsts[k] / 2 + counts[k] / 2 - 1; ++i)
      {
        ++drawn[i];
      }
    }
    for (std::uint32_t s : segments)
    {
      ++drawn[s];
    }
    long wrong = 0;
    for (vtkIdType t = 0; t < numTubes; ++t)
    {
      const vtkIdType first = core->GetTubeFirstNode(t);
      const vtkIdType n = core->GetTubeNumberOfNodes(t);
      for (vtkIdType i = first; i < first + n; ++i)
      {
        wrong += drawn[i] != (i + 1 < first + n ? 1 : 0) ? 1 : 0;
      }
    }
    SV_CHECK_MSG(
      status, wrong == 0, "view " << trial << ": " << wrong << " segments drawn wrongly");
    // Joints: once each, inside fixed batches, clear of the polylines' ends.
    for (size_t k = 1; k < joints.size(); ++k)
    {
      SV_CHECK(status, joints[k - 1] < joints[k]);
    }
    for (std::uint32_t j : joints)
    {
      SV_CHECK(status, fixedNode[j] == 1);
    }
  }
  std::cout << "fix-up: " << fixUp.GetNumberOfBatches() << " batches for "
            << core->GetNumberOfSegments() << " segments; over 300 views "
            << 100.0 * flaggedTotal / batches << " % flagged, the cone test kept "
            << 100.0 * candidates / batches << " % for the vertex test" << std::endl;
  SV_CHECK_MSG(status, candidates < batches / 2, "the cone test prunes too little");

  // Disabled: no batch, whole polylines as strips.
  vtkStylizedLineFixUp::View view{};
  view.ModelView[0] = view.ModelView[5] = view.ModelView[10] = view.ModelView[15] = 1.0;
  view.ModelView[14] = -20.0;
  view.RadiusScale = 1.0;
  view.Epsilon = 0.5;
  view.JointRadius = 1.0;
  view.PixelsPerUnit = 500.0;
  std::vector<int> firsts;
  std::vector<int> counts;
  std::vector<std::uint32_t> segments;
  std::vector<std::uint32_t> joints;
  std::vector<std::uint32_t> all(static_cast<size_t>(fixUp.GetNumberOfBatches()));
  for (size_t b = 0; b < all.size(); ++b)
  {
    all[b] = static_cast<std::uint32_t>(b);
  }
  std::vector<std::uint32_t> caps;
  fixUp.BeginView(view, false);
  fixUp.BuildDraws(all, firsts, counts, caps, segments, joints);
  SV_CHECK(status, static_cast<vtkIdType>(firsts.size()) == numTubes);
  SV_CHECK(status, segments.empty() && joints.empty());
}
}

int TestStylizedLineMath(int, char*[])
{
  SplineVizTestStatus status;
  TestSilhouette(status);
  TestFrontDistance(status);
  TestTangents(status);
  TestFixUp(status);
  return status.Result();
}
