// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkSplineTubeMath.h
 * @brief  The spline-tube math of glsl/vtkSplineTubeMathShared.glsl, compiled as C++.
 *
 * glsl/vtkSplineTubeMathShared.glsl is written in the common subset of GLSL and C++
 * (the rules: vtkSplineVizSharedGLSL.h). The shaders embed it; this header compiles the
 * very same text in double precision with GLM, in the namespace
 * vtkSplineTubeMath, for the tube core, the CPU reference intersection and the
 * unit tests: Hermite evaluation, the split of a cubic segment into quadratic
 * sub-segments and their oriented boxes (Salm §3.2 'Rendering'), and the
 * ray / sub-segment intersection (Salm §3.2 'Intersection calculation').
 *
 * Not wrapped; header-only.
 */
#ifndef vtkSplineTubeMath_h
#define vtkSplineTubeMath_h

#include "vtkSplineVizSharedGLSL.h"

namespace vtkSplineTubeMath
{
SV_SHARED_GLSL_TYPES(double);
namespace // internal linkage: the GLSL text has no `inline`
{
#include "glsl/vtkSplineVizCommonShared.glsl"
#include "glsl/vtkSplineTubeMathShared.glsl"
}

/// A unit vector in the GPU buffers' octahedral format (RG16I, decoded by
/// svOctDecode from the components / 32767): svOctEncode rounded half away
/// from zero, without a library call (frames of every node per upload).
inline void svOctEncodeInt16(const vec3& v, short out[2])
{
  const vec2 o = 32767.0 * svOctEncode(v);
  out[0] = static_cast<short>(o.x + (o.x >= 0.0 ? 0.5 : -0.5));
  out[1] = static_cast<short>(o.y + (o.y >= 0.0 ? 0.5 : -0.5));
}
}

#endif
