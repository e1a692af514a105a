// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkStylizedLineMath.h
 * @brief  The stylized-line math of glsl/vtkStylizedLineMathShared.glsl, compiled as C++.
 *
 * The same text the shaders of vtkStylizedLineMapper embed (Stoll et al.
 * §4.1-4.4: the silhouette frame and extrusion, the per-fragment normal, the
 * depth-correction distance and the fix-up criterion), compiled in double
 * precision with GLM in the namespace vtkStylizedLineMath, for the mapper's
 * CPU fix-up classification (vtkStylizedLineFixUp) and the tests.
 *
 * Not wrapped; header-only.
 */
#ifndef vtkStylizedLineMath_h
#define vtkStylizedLineMath_h

#include "vtkSplineTubeMath.h"

namespace vtkStylizedLineMath
{
using namespace glm;
using real = double;
using vec2 = glm::dvec2;
using vec3 = glm::dvec3;
using vec4 = glm::dvec4;
using vtkSplineTubeMath::svAnyOrthogonal;

#define SV_OUT(T) T&
#define SV_INOUT(T) T&
// Internal linkage: the GLSL source has no `inline`.
namespace
{
#include "glsl/vtkStylizedLineMathShared.glsl"
}
#undef SV_OUT
#undef SV_INOUT
}

#endif
