#include "vtkStylizedLineFixUp.h"

#include "vtkStylizedLineMath.h"

#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkSplineTubeCore.h"
#include "vtkTypeUInt32Array.h"

#include <algorithm>
#include <cmath>

namespace
{
using vtkStylizedLineMath::vec3;

/// Unit tangent of node i.
vec3 UnitTangent(const float* T, vtkIdType i)
{
  return vec3(T[3 * i], T[3 * i + 1], T[3 * i + 2]);
}

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
void vtkStylizedLineFixUp::Build(vtkSplineTubeCore* core, const double shift[3])
{
  this->Core = core;
  std::copy(shift, shift + 3, this->Shift);
  const vtkIdType numTubes = core->GetNumberOfTubes();
  const float* P = core->GetNodePositions()->GetPointer(0);
  const float* R = core->GetNodeRadii()->GetPointer(0);
  const vtkIdType* tubeFirst = core->GetTubeFirstNodes()->GetPointer(0);
  const vtkIdType* tubeNodes = core->GetTubeNumberOfNodes()->GetPointer(0);

  // The vertex tangents (bisectors; segment directions at the ends).
  this->Tangents.resize(static_cast<size_t>(3 * core->GetNumberOfNodes()));
  float* M = this->Tangents.data();
  vtkSMPTools::For(0, numTubes,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType t = begin; t < end; ++t)
      {
        const vtkIdType first = tubeFirst[t];
        const vtkIdType last = first + tubeNodes[t] - 1;
        auto point = [P](vtkIdType i) { return vec3(P[3 * i], P[3 * i + 1], P[3 * i + 2]); };
        for (vtkIdType i = first; i <= last; ++i)
        {
          const vec3 before = i > first ? point(i) - point(i - 1) : vec3(0.0);
          const vec3 after = i < last ? point(i + 1) - point(i) : vec3(0.0);
          const vec3 tangent = vtkStylizedLineMath::slPolylineTangent(before, after);
          for (int c = 0; c < 3; ++c)
          {
            M[3 * i + c] = static_cast<float>(tangent[c]);
          }
        }
      }
    });

  // Pass 1 (parallel): batches per tube; pass 2: offsets; pass 3: fill.
  const double cosLimit = std::cos(MaximumBatchAngle);
  auto cutTube = [&](vtkIdType t, auto&& emit)
  {
    const vtkIdType first = tubeFirst[t];
    const vtkIdType last = first + tubeNodes[t] - 1; // last node
    vtkIdType start = first;
    while (start < last)
    {
      const vec3 axis = UnitTangent(M, start);
      vtkIdType end = start + 1; // the batch's last node
      double minCos = 1.0;
      for (;;)
      {
        const double c = glm::dot(axis, UnitTangent(M, end));
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
  this->Batches.resize(static_cast<size_t>(this->TubeFirstBatch[numTubes]));
  vtkSMPTools::For(0, numTubes,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType t = begin; t < end; ++t)
      {
        vtkIdType b = this->TubeFirstBatch[t];
        cutTube(t,
          [&](vtkIdType start, vtkIdType stop, const vec3& axis, double minCos)
          {
            Batch& batch = this->Batches[b++];
            batch.FirstNode = static_cast<std::uint32_t>(start);
            batch.Tube = static_cast<std::uint32_t>(t);
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
                const double x = P[3 * i + c] - this->Shift[c];
                lo[c] = std::min(lo[c], x);
                hi[c] = std::max(hi[c], x);
              }
              maxRadius = std::max(maxRadius, static_cast<double>(R[2 * i]));
            }
            double r2 = 0.0;
            for (int c = 0; c < 3; ++c)
            {
              batch.Center[c] = static_cast<float>(0.5 * (lo[c] + hi[c]));
              r2 += 0.25 * (hi[c] - lo[c]) * (hi[c] - lo[c]);
            }
            batch.Radius = static_cast<float>(std::sqrt(r2) * (1.0 + 1e-6) + 1e-6 * maxRadius);
            batch.MaxRadius = static_cast<float>(maxRadius);
          });
      }
    });
  this->Flags.assign(this->Batches.size(), 0);
  this->Candidates = 0;
}

//------------------------------------------------------------------------------
bool vtkStylizedLineFixUp::TestVertices(const Batch& batch, const View& view) const
{
  const float* P = this->Core->GetNodePositions()->GetPointer(0);
  const float* M = this->Tangents.data();
  const float* R = this->Core->GetNodeRadii()->GetPointer(0);
  for (vtkIdType i = batch.FirstNode; i <= batch.FirstNode + batch.Segments; ++i)
  {
    const vec3 p = TransformPoint(view.ModelView,
      vec3(
        P[3 * i] - this->Shift[0], P[3 * i + 1] - this->Shift[1], P[3 * i + 2] - this->Shift[2]));
    vec3 t = TransformVector(view.ModelView, UnitTangent(M, i));
    const double len = glm::length(t);
    t = len > 0.0 ? t / len : vec3(1.0, 0.0, 0.0);
    if (vtkStylizedLineMath::slNeedsFixUp(
          p, t, R[2 * i] * view.RadiusScale, view.Parallel, view.Epsilon))
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
    flags[b] = this->TestVertices(this->Batches[b], view) ? 1 : 0;
  }
  return flags;
}

//------------------------------------------------------------------------------
void vtkStylizedLineFixUp::Classify(const View& view, bool enabled,
  std::vector<std::uint32_t>& segments, std::vector<std::uint32_t>& joints)
{
  const vtkIdType numBatches = static_cast<vtkIdType>(this->Batches.size());
  this->Flags.assign(this->Batches.size(), 0);
  this->Candidates = 0;
  if (enabled && this->Core)
  {
    const double epsilon = std::max(0.0, std::min(1.0, view.Epsilon));
    const double thetaEps = std::acos(1.0 - epsilon);
    vtkSMPThreadLocal<vtkIdType> candidates(0);
    vtkSMPTools::For(0, numBatches,
      [&](vtkIdType begin, vtkIdType end)
      {
        vtkIdType& local = candidates.Local();
        for (vtkIdType b = begin; b < end; ++b)
        {
          const Batch& batch = this->Batches[b];
          const vec3 c =
            TransformPoint(view.ModelView, vec3(batch.Center[0], batch.Center[1], batch.Center[2]));
          vec3 a =
            TransformVector(view.ModelView, vec3(batch.Axis[0], batch.Axis[1], batch.Axis[2]));
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
          if (candidate)
          {
            ++local;
            this->Flags[b] = this->TestVertices(batch, view) ? 1 : 0;
          }
        }
      });
    for (vtkIdType n : candidates)
    {
      this->Candidates += n;
    }
  }

  // The fix-up's lists, tube by tube.
  segments.clear();
  joints.clear();
  if (!this->Core)
  {
    return;
  }
  const vtkIdType numTubes = this->Core->GetNumberOfTubes();
  const vtkIdType* tubeFirst = this->Core->GetTubeFirstNodes()->GetPointer(0);
  const vtkIdType* tubeNodes = this->Core->GetTubeNumberOfNodes()->GetPointer(0);
  const float* P = this->Core->GetNodePositions()->GetPointer(0);
  const float* R = this->Core->GetNodeRadii()->GetPointer(0);
  auto point = [P](vtkIdType i) { return vec3(P[3 * i], P[3 * i + 1], P[3 * i + 2]); };
  // The radius on screen of point i, in pixels (0 behind the eye).
  auto screenRadius = [&](vtkIdType i)
  {
    const vec3 p = TransformPoint(view.ModelView,
      vec3(
        P[3 * i] - this->Shift[0], P[3 * i + 1] - this->Shift[1], P[3 * i + 2] - this->Shift[2]));
    const double r = R[2 * i] * view.RadiusScale * view.PixelsPerUnit;
    if (view.Parallel)
    {
      return r;
    }
    return p.z < 0.0 ? r / std::max(-p.z, 1e-30) : 0.0;
  };
  this->MaximumScreenRadius = 0.0;
  for (vtkIdType t = 0; t < numTubes; ++t)
  {
    const vtkIdType last = tubeFirst[t] + tubeNodes[t] - 1;
    this->MaximumScreenRadius =
      std::max({ this->MaximumScreenRadius, screenRadius(tubeFirst[t]), screenRadius(last) });
    for (vtkIdType b = this->TubeFirstBatch[t]; b < this->TubeFirstBatch[t + 1]; ++b)
    {
      if (!this->Flags[b])
      {
        continue;
      }
      const Batch& batch = this->Batches[b];
      for (int s = 0; s < batch.Segments; ++s)
      {
        segments.push_back(batch.FirstNode + static_cast<std::uint32_t>(s));
        this->MaximumScreenRadius =
          std::max(this->MaximumScreenRadius, screenRadius(batch.FirstNode + s));
      }
      // Joints: the batch's points, each once (consecutive fixed batches
      // share one), but those whose sphere would stick out of an end cap.
      for (vtkIdType i = batch.FirstNode; i <= batch.FirstNode + batch.Segments; ++i)
      {
        if (!joints.empty() && joints.back() >= i)
        {
          continue;
        }
        const double clearance = view.JointRadius * R[2 * i];
        if (glm::distance(point(i), point(tubeFirst[t])) > clearance &&
          glm::distance(point(i), point(last)) > clearance)
        {
          joints.push_back(static_cast<std::uint32_t>(i));
        }
      }
    }
  }
}

//------------------------------------------------------------------------------
void vtkStylizedLineFixUp::BuildStrips(const std::vector<std::uint32_t>& batches,
  std::vector<int>& stripFirsts, std::vector<int>& stripCounts, std::vector<std::uint32_t>& caps)
{
  stripFirsts.clear();
  stripCounts.clear();
  caps.clear();
  for (std::uint32_t b : batches)
  {
    const Batch& batch = this->Batches[b];
    if (b == this->TubeFirstBatch[batch.Tube])
    {
      caps.push_back(2 * batch.Tube);
    }
    if (b + 1 == this->TubeFirstBatch[batch.Tube + 1])
    {
      caps.push_back(2 * batch.Tube + 1);
    }
    if (b < this->Flags.size() && this->Flags[b])
    {
      continue; // drawn by the fix-up
    }
    // Two strip vertices per point; a batch continuing the last strip (its
    // first point the strip's last) extends it.
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
  }
}

//------------------------------------------------------------------------------
void vtkStylizedLineFixUp::GetCullingChunks(
  double widen, std::vector<float>& spheres, std::vector<std::uint32_t>& tubes) const
{
  const size_t n = this->Batches.size();
  spheres.resize(4 * n);
  tubes.resize(n);
  for (size_t b = 0; b < n; ++b)
  {
    const Batch& batch = this->Batches[b];
    std::copy(batch.Center, batch.Center + 3, &spheres[4 * b]);
    spheres[4 * b + 3] = static_cast<float>(
      (batch.Radius + widen * batch.MaxRadius) * (1.0 + 1e-6) + 1e-6 * std::abs(batch.Center[0]) +
      1e-6 * std::abs(batch.Center[1]) + 1e-6 * std::abs(batch.Center[2]));
    tubes[b] = batch.Tube;
  }
}
