// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkSplineVizSharedGLSL.h
 * @brief  The C++ side of the GLSL sources shared by the shaders and the CPU code.
 *
 * The *Shared.glsl files (glsl/vtkSplineTubeMathShared.glsl,
 * glsl/vtkStylizedLineMathShared.glsl, glsl/vtkSuperquadricGlyphShared.glsl,
 * glsl/vtkLRSplineVolumeShared.glsl, Core/glsl/vtkTensorMathShared.glsl)
 * are written in the common subset of GLSL and C++ with GLM, so that the
 * shaders and the CPU code (references, preparers, unit tests) run one
 * algorithm from one text. Rules of the subset:
 *  - `real` for scalars, vec2/vec3/vec4 (and mat3) of real;
 *  - SV_OUT(T) / SV_INOUT(T) for output parameters;
 *  - real literals written with a decimal point;
 *  - no swizzles other than single components, no recursion, no
 *    constructors of structs;
 *  - every name starts with the file's prefix (sv: tubes, sl: stylized
 *    lines, svq: glyphs, svt: tensors, lr: LR volumes), so that files can be
 *    embedded next to each other.
 *
 * The substitution tags of SplineViz's own shader code are //SV::Name::Dec
 * and //SV::Name::Impl (VTK's tags stay //VTK::...).
 *
 * Helpers more than one file needs are in glsl/vtkSplineVizCommonShared.glsl.
 * The GLSL side is glsl/vtkSplineVizPrelude.glsl (real = float), put with the
 * common helpers before the shared code by vtkSplineVizShaderPrelude::Get().
 * The C++ side
 * is this header: include it, then, inside the namespace that is to hold the
 * functions,
 *
 * @code
 * SV_SHARED_GLSL_TYPES(double);
 * namespace // internal linkage: the GLSL text has no `inline`
 * {
 * #include "glsl/vtkSplineTubeMathShared.glsl"
 * }
 * @endcode
 *
 * Not wrapped; header-only.
 */
#ifndef vtkSplineVizSharedGLSL_h
#define vtkSplineVizSharedGLSL_h

#include <glm/glm.hpp>

/// Output parameters of the shared GLSL text, as C++ references.
#define SV_OUT(T) T&
#define SV_INOUT(T) T&

/// GLM in scope and GLSL's types with `real` of precision REAL (double for
/// the CPU references, float to reproduce what the GPU computes).
#define SV_SHARED_GLSL_TYPES(REAL)                                                                 \
  using namespace glm;                                                                             \
  using real = REAL;                                                                               \
  using vec2 = glm::vec<2, REAL>;                                                                  \
  using vec3 = glm::vec<3, REAL>;                                                                  \
  using vec4 = glm::vec<4, REAL>;                                                                  \
  using mat3 = glm::mat<3, 3, REAL>

#endif
