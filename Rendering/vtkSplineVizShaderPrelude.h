// SPDX-License-Identifier: BSD-3-Clause
/**
 * The GLSL text every SplineViz shader that embeds shared GLSL starts with:
 * the prelude of the shared subset (glsl/vtkSplineVizPrelude.glsl: real =
 * float, SV_OUT, SV_INOUT) and the helpers of
 * glsl/vtkSplineVizCommonShared.glsl (rules: vtkSplineVizSharedGLSL.h). The
 * tube mappers put it before the tube math; the glyph and volume shaders have
 * it substituted for //SV::Prelude::Dec.
 *
 * Header-only, private to the module (it includes generated shader headers).
 */
#ifndef vtkSplineVizShaderPrelude_h
#define vtkSplineVizShaderPrelude_h

#include "vtkSplineVizCommonShared.h"
#include "vtkSplineVizPrelude.h"

#include <string>

namespace vtkSplineVizShaderPrelude
{
/// The prelude and the common helpers, in that order.
inline std::string Get()
{
  return std::string(vtkSplineVizPrelude) + vtkSplineVizCommonShared;
}
}

#endif
