// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkLRSplineVolumeMath.h
 * @brief  The element search and Bezier evaluation of glsl/vtkLRSplineVolumeShared.glsl,
 * compiled as C++.
 *
 * vtkLRSplineVolumeMapper's fragment stage finds elements (Fuchs et al.
 * §3.2: the k-d forest of Algorithm 1, the octree of §3.2.2) and evaluates
 * their Bezier form (§3.2.3) with the code of
 * glsl/vtkLRSplineVolumeShared.glsl, written in the common subset of GLSL and
 * C++ (the rules: vtkSplineVizSharedGLSL.h). This header compiles the very
 * same text in single precision, as the GPU runs it, so that the unit test can
 * hold it against vtkLRSplineElementLocator and vtkLRSplineBezierVolume (the
 * double-precision CPU code) on every element.
 *
 * The data accessors of the shared code read the arrays the mapper uploads,
 * set per thread with vtkLRSplineVolumeMath::SetData().
 *
 * Not wrapped; header-only; for tests.
 */
#ifndef vtkLRSplineVolumeMath_h
#define vtkLRSplineVolumeMath_h

#include "vtkSplineVizSharedGLSL.h"

#include <cmath>
#include <cstdint>

namespace vtkLRSplineVolumeMath
{
/// The flat arrays the shader reads (vtkLRSplineElementLocator's layout).
struct Data
{
  const std::uint32_t* Heads = nullptr;
  const std::uint32_t* NodeWords = nullptr;
  const float* NodeSplits = nullptr;
  const std::uint32_t* Octree = nullptr;
  const float* Coefficients = nullptr;
};

namespace detail
{
inline const Data*& Current()
{
  static thread_local const Data* data = nullptr;
  return data;
}
}

/// The arrays the following calls read (this thread).
inline void SetData(const Data* data)
{
  detail::Current() = data;
}

namespace // internal linkage: the GLSL text has no `inline`
{
SV_SHARED_GLSL_TYPES(float); // as the GPU computes
using std::abs;
using std::max;
using ivec3 = glm::ivec3;
using uint = std::uint32_t;
using std::floor;

inline uint lrHead(int i)
{
  return detail::Current()->Heads[i];
}
inline uint lrNodeWord(int i)
{
  return detail::Current()->NodeWords[i];
}
inline real lrNodeSplit(int i)
{
  return detail::Current()->NodeSplits[i];
}
inline uint lrOctreeNode(int i)
{
  return detail::Current()->Octree[i];
}
inline real lrCoefficient(int i)
{
  return detail::Current()->Coefficients[i];
}

#include "glsl/vtkLRSplineVolumeShared.glsl"
}
}

#endif
// VTK-HeaderTest-Exclude: vtkLRSplineVolumeMath.h
