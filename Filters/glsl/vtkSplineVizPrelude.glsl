// SPDX-License-Identifier: BSD-3-Clause
// The GLSL side of the shared GLSL/C++ subset (the rules are in
// Filters/vtkSplineVizSharedGLSL.h, the C++ side): every shader that embeds a
// *Shared.glsl file has this first (the tube mappers prepend it, the glyph and
// volume shaders substitute it for //SV::Prelude::Dec).
#define real float
#define SV_OUT(T) out T
#define SV_INOUT(T) inout T
