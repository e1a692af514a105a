// SPDX-License-Identifier: BSD-3-Clause
#include "vtkStylizedLineFixUp.h"

#include "vtkSplineTubeMath.h"
#include "vtkStylizedLineMath.h"

#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkSplineTubeCore.h"
#include "vtkSplineTubeVisibility.h"
#include "vtkTypeUInt32Array.h"

#include <algorithm>
#include <cmath>

namespace
{
using vtkStylizedLineMath::vec3;
using vtkStylizedLineMath::vec4;

/// Column-major 4x4 times a point / a direction.
vec3 TransformPoint(const double* m, const vec3& p)
{
  return vec3(m[0] * p.x + m[4] * p.y + m[8] * p.z + m[12],
    m[1] * p.x + m[5] * p.y + m[9] * p.z + m[13], m[2] * p.x + m[6] * p.y + m[10] * p.z + m[14]);
}

vec3 TransformVector(const double* m, const vec3& v)
{
  return vec3(m[0] * v.x + m[4] * v.y + m[8] * v.z, m[1] * v.x + m[5] * v.y + m[9] * v.z,
    m[2] * v.x + m[6] * v.y + m[10] * v.z);
}
}

//------------------------------------------------------------------------------
void vtkStylizedLineFixUp::Nodes(
  vtkIdType tube, vtkIdType k0, vtkIdType k1, double* xyzr, vec3* tangents) const
{
  const vtkIdType n = this->Core->GetTubeNumberOfNodes(tube);
  const vtkIdType lo = std::max<vtkIdType>(0, k0 - 1);
  const vtkIdType hi = std::min(n - 1, k1 + 1);
  std::vector<double> around(static_cast<size_t>(4 * (hi - lo + 1)));
  this->Core->GetTubeNodes(tube, lo, hi - lo + 1, around.data(), nullptr);
  auto point = [&](vtkIdType k)
  { return vec3(around[4 * (k - lo)], around[4 * (k - lo) + 1], around[4 * (k - lo) + 2]); };
  for (vtkIdType k = k0; k <= k1; ++k)
  {
    if (xyzr)
    {
      std::copy(&around[4 * (k - lo)], &around[4 * (k - lo)] + 4, xyzr + 4 * (k - k0));
    }
    if (tangents)
    {
      const vec3 before = k > 0 ? point(k) - point(k - 1) : vec3(0.0);
      const vec3 after = k < n - 1 ? point(k + 1) - point(k) : vec3(0.0);
      tangents[k - k0] = vtkStylizedLineMath::slPolylineTangent(before, after);
    }
  }
}

//------------------------------------------------------------------------------
void vtkStylizedLineFixUp::GetTangent(vtkIdType node, double tangent[3]) const
{
  const vtkIdType t = this->Core->GetTubeOfNode(node);
  const vtkIdType k = node - this->Core->GetTubeFirstNode(t);
  vec3 m;
  this->Nodes(t, k, k, nullptr, &m);
  tangent[0] = m.x;
  tangent[1] = m.y;
  tangent[2] = m.z;
}

//------------------------------------------------------------------------------
void vtkStylizedLineFixUp::FillTangents(vtkIdType first, vtkIdType count, short* octahedral) const
{
  vtkSMPTools::For(first, first + count, 65536,
    [&](vtkIdType b, vtkIdType e)
    {
      std::vector<vec3> tangents;
      for (vtkIdType t = this->Core->GetTubeOfNode(b); b < e; ++t)
      {
        const vtkIdType tubeFirst = this->Core->GetTubeFirstNode(t);
        const vtkIdType stop = std::min(e, tubeFirst + this->Core->GetTubeNumberOfNodes(t));
        tangents.resize(static_cast<size_t>(stop - b));
        this->Nodes(t, b - tubeFirst, stop - 1 - tubeFirst, nullptr, tangents.data());
        for (vtkIdType i = b; i < stop; ++i)
        {
          vtkSplineTubeMath::svOctEncodeInt16(tangents[i - b], octahedral + 2 * (i - first));
        }
        b = stop;
      }
    });
}

//------------------------------------------------------------------------------
void vtkStylizedLineFixUp::Build(vtkSplineTubeCore* core, const double shift[3])
{
  this->Core = core;
  std::copy(shift, shift + 3, this->Shift);
  const vtkIdType numTubes = core->GetNumberOfTubes();
  // Per thread: a tube's nodes and vertex tangents (bisectors; segment
  // directions at the ends).
  struct Scratch
  {
    vtkIdType Tube = -1;
    std::vector<double> P;
    std::vector<vec3> M;
  };
  vtkSMPThreadLocal<Scratch> scratch;
  auto load = [&](vtkIdType t) -> Scratch&
  {
    Scratch& s = scratch.Local();
    if (s.Tube != t)
    {
      const vtkIdType n = core->GetTubeNumberOfNodes(t);
      s.P.resize(static_cast<size_t>(4 * n));
      s.M.resize(static_cast<size_t>(n));
      this->Nodes(t, 0, n - 1, s.P.data(), s.M.data());
      s.Tube = t;
    }
    return s;
  };

  // Pass 1 (parallel): batches per tube; pass 2: offsets; pass 3: fill.
  const double cosLimit = std::cos(MaximumBatchAngle);
  // (node numbers within the tube)
  auto cutTube = [&](vtkIdType t, auto&& emit)
  {
    const std::vector<vec3>& M = load(t).M;
    const vtkIdType last = core->GetTubeNumberOfNodes(t) - 1; // last node
    vtkIdType start = 0;
    while (start < last)
    {
      const vec3 axis = M[start];
      vtkIdType end = start + 1; // the batch's last node
      double minCos = 1.0;
      for (;;)
      {
        const double c = glm::dot(axis, M[end]);
        if (c < cosLimit)
        {
          if (end > start + 1)
          {
            --end; // the node that left the cone starts the next batch
          }
          else
          {
            minCos = c; // a sharp turn: a batch of one segment
          }
          break;
        }
        minCos = std::min(minCos, c);
        if (end == last || end - start == MaximumBatchSegments)
        {
          break;
        }
        ++end;
      }
      emit(start, end, axis, minCos);
      start = end;
    }
  };

  std::vector<vtkIdType> counts(static_cast<size_t>(numTubes) + 1, 0);
  vtkSMPTools::For(0, numTubes,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType t = begin; t < end; ++t)
      {
        vtkIdType n = 0;
        cutTube(t, [&n](vtkIdType, vtkIdType, const vec3&, double) { ++n; });
        counts[t + 1] = n;
      }
    });
  this->TubeFirstBatch.assign(static_cast<size_t>(numTubes) + 1, 0);
  for (vtkIdType t = 0; t < numTubes; ++t)
  {
    this->TubeFirstBatch[t + 1] = this->TubeFirstBatch[t] + counts[t + 1];
  }
  const size_t numBatches = static_cast<size_t>(this->TubeFirstBatch[numTubes]);
  this->Batches.resize(numBatches);
  this->Spheres.resize(4 * numBatches);
  this->Tubes.resize(numBatches);
  this->CullingWiden = -1.0; // radii and parts made by SetCullingChunks()
  vtkSMPTools::For(0, numTubes,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType t = begin; t < end; ++t)
      {
        vtkIdType b = this->TubeFirstBatch[t];
        cutTube(t,
          [&](vtkIdType start, vtkIdType stop, const vec3& axis, double minCos)
          {
            const std::vector<double>& P = load(t).P;
            Batch& batch = this->Batches[b];
            float* center = &this->Spheres[4 * b];
            this->Tubes[b++] = static_cast<std::uint32_t>(t);
            batch.FirstNode = static_cast<std::uint32_t>(core->GetTubeFirstNode(t) + start);
            batch.Segments = static_cast<int>(stop - start);
            for (int c = 0; c < 3; ++c)
            {
              batch.Axis[c] = static_cast<float>(axis[c]);
            }
            // Float round-off in the tangents: a little margin.
            batch.Cone =
              static_cast<float>(std::acos(std::max(-1.0, std::min(1.0, minCos))) + 1e-4);
            double lo[3] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, VTK_DOUBLE_MAX };
            double hi[3] = { VTK_DOUBLE_MIN, VTK_DOUBLE_MIN, VTK_DOUBLE_MIN };
            double maxRadius = 0.0;
            for (vtkIdType i = start; i <= stop; ++i)
            {
              for (int c = 0; c < 3; ++c)
              {
                const double x = P[4 * i + c] - this->Shift[c];
                lo[c] = std::min(lo[c], x);
                hi[c] = std::max(hi[c], x);
              }
              maxRadius = std::max(maxRadius, P[4 * i + 3]);
            }
            double r2 = 0.0;
            for (int c = 0; c < 3; ++c)
            {
              center[c] = static_cast<float>(0.5 * (lo[c] + hi[c]));
              r2 += 0.25 * (hi[c] - lo[c]) * (hi[c] - lo[c]);
            }
            batch.Radius = static_cast<float>(std::sqrt(r2) * (1.0 + 1e-6) + 1e-6 * maxRadius);
            batch.MaxRadius = static_cast<float>(maxRadius);
          });
      }
    });
  this->Flags.assign(this->Batches.size(), 0);
  this->Stamps.assign(this->Batches.size(), 0);
  this->ViewStamp = 0;
  this->Candidates = 0;
}

//------------------------------------------------------------------------------
bool vtkStylizedLineFixUp::TestVertices(vtkIdType b, const View& view) const
{
  const Batch& batch = this->Batches[b];
  const std::uint32_t tube = this->Tubes[b];
  const vtkIdType k0 = batch.FirstNode - this->Core->GetTubeFirstNode(tube);
  double P[4 * (MaximumBatchSegments + 1)];
  vec3 M[MaximumBatchSegments + 1];
  this->Nodes(tube, k0, k0 + batch.Segments, P, M);
  for (int i = 0; i <= batch.Segments; ++i)
  {
    const vec3 p = TransformPoint(view.ModelView,
      vec3(
        P[4 * i] - this->Shift[0], P[4 * i + 1] - this->Shift[1], P[4 * i + 2] - this->Shift[2]));
    vec3 t = TransformVector(view.ModelView, M[i]);
    const double len = glm::length(t);
    t = len > 0.0 ? t / len : vec3(1.0, 0.0, 0.0);
    if (vtkStylizedLineMath::slNeedsFixUp(
          p, t, P[4 * i + 3] * view.RadiusScale, view.Parallel, view.Epsilon))
    {
      return true;
    }
  }
  return false;
}

//------------------------------------------------------------------------------
std::vector<unsigned char> vtkStylizedLineFixUp::ClassifyAllVertices(const View& view) const
{
  std::vector<unsigned char> flags(this->Batches.size(), 0);
  for (size_t b = 0; b < this->Batches.size(); ++b)
  {
    flags[b] = this->TestVertices(static_cast<vtkIdType>(b), view) ? 1 : 0;
  }
  return flags;
}

//------------------------------------------------------------------------------
bool vtkStylizedLineFixUp::NeedsFixUp(vtkIdType b, const View& view, double thetaEps) const
{
  const Batch& batch = this->Batches[b];
  const float* center = &this->Spheres[4 * b];
  const vec3 c = TransformPoint(view.ModelView, vec3(center[0], center[1], center[2]));
  vec3 a = TransformVector(view.ModelView, vec3(batch.Axis[0], batch.Axis[1], batch.Axis[2]));
  const double al = glm::length(a);
  a = al > 0.0 ? a / al : vec3(1.0, 0.0, 0.0);
  const double radius = batch.Radius * view.RadiusScale;
  const double lineRadius = batch.MaxRadius * view.RadiusScale;
  bool candidate = false;
  vec3 dir(0.0, 0.0, -1.0);
  double beta = 0.0;
  double dist = 0.0;
  if (!view.Parallel)
  {
    dist = glm::length(c);
    if (dist <= radius * 1.0001)
    {
      candidate = true; // the eye is inside the batch's sphere
    }
    else
    {
      dir = c / dist;
      beta = std::asin(std::min(1.0, radius / dist));
    }
  }
  if (!candidate)
  {
    const double theta = std::acos(std::min(1.0, std::abs(glm::dot(dir, a))));
    // The smallest angle any vertex tangent can make with its view ray.
    const double minAngle = theta - batch.Cone - beta;
    if (minAngle <= thetaEps + 1e-6)
    {
      candidate = true;
    }
    else if (!view.Parallel)
    {
      // |u_perp| = |u| sin(angle) < SL_NEAR_AXIS r needs a near eye.
      const double nearDistance = SL_NEAR_AXIS * lineRadius / std::sin(minAngle);
      candidate = dist - radius < nearDistance * 1.0001;
    }
  }
  if (!candidate)
  {
    return false;
  }
  ++this->Candidates; // (atomic)
  return this->TestVertices(b, view);
}

//------------------------------------------------------------------------------
void vtkStylizedLineFixUp::BeginView(const View& view, bool enabled)
{
  this->CurrentView = view;
  this->Enabled = enabled && this->Core;
  this->Candidates = 0;
  ++this->ViewStamp;
  if (this->ViewStamp == 0)
  {
    std::fill(this->Stamps.begin(), this->Stamps.end(), 0);
    this->ViewStamp = 1;
  }
  // The largest radius on screen of the polylines' ends (their caps), and of
  // the fixed-up points of the last view.
  this->MaximumScreenRadius = this->FixedScreenRadius;
  this->FixedScreenRadius = 0.0;
  if (!this->Core)
  {
    return;
  }
  const vtkIdType numTubes = this->Core->GetNumberOfTubes();
  vtkSplineTubeCore* core = this->Core;
  vtkSMPThreadLocal<double> largest(0.0);
  vtkSMPTools::For(0, numTubes,
    [&](vtkIdType begin, vtkIdType end)
    {
      double& local = largest.Local();
      for (vtkIdType t = begin; t < end; ++t)
      {
        local = std::max({ local, this->ScreenRadius(t, 0),
          this->ScreenRadius(t, core->GetTubeNumberOfNodes(t) - 1) });
      }
    });
  for (double r : largest)
  {
    this->MaximumScreenRadius = std::max(this->MaximumScreenRadius, r);
  }
}

//------------------------------------------------------------------------------
double vtkStylizedLineFixUp::ScreenRadius(vtkIdType t, vtkIdType k) const
{
  const View& view = this->CurrentView;
  double P[4];
  this->Core->GetTubeNode(t, k, P);
  const vec3 p = TransformPoint(
    view.ModelView, vec3(P[0] - this->Shift[0], P[1] - this->Shift[1], P[2] - this->Shift[2]));
  const double r = P[3] * view.RadiusScale * view.PixelsPerUnit;
  if (view.Parallel)
  {
    return r;
  }
  return p.z < 0.0 ? r / std::max(-p.z, 1e-30) : 0.0;
}

//------------------------------------------------------------------------------
void vtkStylizedLineFixUp::BuildDraws(const std::vector<std::uint32_t>& batches,
  std::vector<int>& stripFirsts, std::vector<int>& stripCounts, std::vector<std::uint32_t>& caps,
  std::vector<std::uint32_t>& segments, std::vector<std::uint32_t>& joints)
{
  stripFirsts.clear();
  stripCounts.clear();
  caps.clear();
  segments.clear();
  joints.clear();
  if (!this->Core)
  {
    return;
  }
  const View& view = this->CurrentView;
  // Classify the batches not yet classified in this view (in parallel).
  if (this->Enabled)
  {
    const double epsilon = std::max(0.0, std::min(1.0, view.Epsilon));
    const double thetaEps = std::acos(1.0 - epsilon);
    const vtkIdType n = static_cast<vtkIdType>(batches.size());
    vtkSMPTools::For(0, n,
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType i = begin; i < end; ++i)
        {
          const std::uint32_t b = batches[i];
          if (this->Stamps[b] != this->ViewStamp)
          {
            this->Stamps[b] = this->ViewStamp;
            this->Flags[b] = this->NeedsFixUp(b, view, thetaEps) ? 1 : 0;
          }
        }
      });
  }
  vtkSplineTubeCore* core = this->Core;
  auto point = [core](vtkIdType t, vtkIdType k)
  {
    double p[4];
    core->GetTubeNode(t, k, p);
    return vec4(p[0], p[1], p[2], p[3]);
  };
  for (std::uint32_t b : batches)
  {
    const Batch& batch = this->Batches[b];
    const std::uint32_t tube = this->Tubes[b];
    if (b == this->TubeFirstBatch[tube])
    {
      caps.push_back(2 * tube);
    }
    if (b + 1 == this->TubeFirstBatch[tube + 1])
    {
      caps.push_back(2 * tube + 1);
    }
    if (!this->Enabled || this->Stamps[b] != this->ViewStamp || !this->Flags[b])
    {
      // Two strip vertices per point; a batch continuing the last strip
      // (its first point the strip's last) extends it.
      const int first = static_cast<int>(2 * batch.FirstNode);
      const int count = 2 * (batch.Segments + 1);
      if (!stripFirsts.empty() && stripFirsts.back() + stripCounts.back() - 2 == first)
      {
        stripCounts.back() += count - 2;
      }
      else
      {
        stripFirsts.push_back(first);
        stripCounts.push_back(count);
      }
      continue;
    }
    // Fixed up: its segments as cylinders; joints at its points but those
    // whose sphere would stick out of an end cap.
    const vtkIdType tubeStart = core->GetTubeFirstNode(tube);
    const vtkIdType last = core->GetTubeNumberOfNodes(tube) - 1;
    const vec3 start = vec3(point(tube, 0));
    const vec3 end = vec3(point(tube, last));
    const vtkIdType local = batch.FirstNode - tubeStart; // the batch's first node in its tube
    for (int s = 0; s < batch.Segments; ++s)
    {
      segments.push_back(batch.FirstNode + static_cast<std::uint32_t>(s));
      this->FixedScreenRadius =
        std::max(this->FixedScreenRadius, this->ScreenRadius(tube, local + s));
    }
    for (vtkIdType i = batch.FirstNode; i <= batch.FirstNode + batch.Segments; ++i)
    {
      const vec4 p = point(tube, i - tubeStart);
      const double clearance = view.JointRadius * p.w;
      if (glm::distance(vec3(p), start) > clearance && glm::distance(vec3(p), end) > clearance)
      {
        joints.push_back(static_cast<std::uint32_t>(i));
      }
    }
  }
  // Consecutive fixed-up batches share a point: one joint.
  std::sort(joints.begin(), joints.end());
  joints.erase(std::unique(joints.begin(), joints.end()), joints.end());
  this->MaximumScreenRadius = std::max(this->MaximumScreenRadius, this->FixedScreenRadius);
}

//------------------------------------------------------------------------------
void vtkStylizedLineFixUp::SetCullingChunks(double widen, vtkSplineTubeVisibility& visibility)
{
  const size_t n = this->Batches.size();
  if (widen != this->CullingWiden)
  {
    this->CullingWiden = widen;
    this->PartFirsts.resize(n + 1);
    this->PartFirsts[0] = 0;
    for (size_t b = 0; b < n; ++b)
    {
      this->PartFirsts[b + 1] =
        this->PartFirsts[b] + static_cast<std::uint32_t>(this->Batches[b].Segments);
    }
    this->Parts.resize(this->PartFirsts[n]);
    vtkSMPTools::For(0, static_cast<vtkIdType>(n),
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType b = begin; b < end; ++b)
        {
          const Batch& batch = this->Batches[b];
          float* sphere = &this->Spheres[4 * b];
          const double extent = std::abs(sphere[0]) + std::abs(sphere[1]) + std::abs(sphere[2]);
          sphere[3] = static_cast<float>(
            (batch.Radius + widen * batch.MaxRadius) * (1.0 + 1e-6) + 1e-6 * extent);
          // The segments: straight, within `widen` radii of their points.
          const std::uint32_t tube = this->Tubes[b];
          const vtkIdType k0 = batch.FirstNode - this->Core->GetTubeFirstNode(tube);
          double P[4 * (MaximumBatchSegments + 1)];
          this->Core->GetTubeNodes(tube, k0, batch.Segments + 1, P, nullptr);
          for (int s = 0; s < batch.Segments; ++s)
          {
            double part[4];
            double half2 = 0.0;
            for (int k = 0; k < 3; ++k)
            {
              const double a = P[4 * s + k] - this->Shift[k];
              const double c = P[4 * s + 4 + k] - this->Shift[k];
              part[k] = 0.5 * (a + c);
              half2 += 0.25 * (c - a) * (c - a);
            }
            part[3] =
              (std::sqrt(half2) + widen * std::max(P[4 * s + 3], P[4 * s + 7])) * (1.0 + 1e-6) +
              1e-6 * extent;
            this->Parts[this->PartFirsts[b] + s] =
              vtkSplineTubeVisibility::EncodePart(sphere, part);
          }
        }
      });
  }
  visibility.SetChunks(this->Spheres.data(), this->Tubes.data(), static_cast<vtkIdType>(n),
    this->Parts.data(), this->PartFirsts.data());
}
