// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkSuperquadricGlyphMath.h
 * @brief  The superquadric glyph math of glsl/vtkSuperquadricGlyphShared.glsl, compiled as C++.
 *
 * glsl/vtkSuperquadricGlyphShared.glsl is written in the common subset of GLSL
 * and C++ (the rules: vtkSplineVizSharedGLSL.h). The glyph shaders of
 * vtkSuperquadricGlyphMapper embed it; this header compiles the very same text
 * in double precision with GLM, in the namespace vtkSuperquadricGlyphMath, for
 * the unit tests (ray / superquadric intersection against brute force) and
 * the CPU side of the mapper (bounds): semi-axes from eigenvalues and scale
 * mode, the implicit function and its gradient, the unit-box clip and the
 * robust first-root search (Hlawitschka et al. §3.3-3.4; Teem's echo/sqd.c).
 *
 * Not wrapped; header-only.
 */
#ifndef vtkSuperquadricGlyphMath_h
#define vtkSuperquadricGlyphMath_h

#include "vtkSplineVizSharedGLSL.h"

namespace vtkSuperquadricGlyphMath
{
SV_SHARED_GLSL_TYPES(double);
namespace // internal linkage: the GLSL text has no `inline`
{
#include "glsl/vtkSuperquadricGlyphShared.glsl"
}
}

#endif
