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

#include "vtkSplineVizSharedGLSL.h"

namespace vtkStylizedLineMath
{
SV_SHARED_GLSL_TYPES(double);
namespace // internal linkage: the GLSL text has no `inline`
{
#include "glsl/vtkSplineVizCommonShared.glsl"
#include "glsl/vtkStylizedLineMathShared.glsl"
}
}

#endif
