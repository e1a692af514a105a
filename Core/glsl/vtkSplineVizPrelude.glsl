// SPDX-License-Identifier: BSD-3-Clause
// The GLSL side of the shared GLSL/C++ subset (the rules and the C++ side:
// Core/vtkSplineVizSharedGLSL.h). vtkSplineVizShaderPrelude::Get() puts it,
// with the common helpers, before the shared code of every shader that embeds
// a *Shared.glsl file.
#define real float
#define SV_OUT(T) out T
#define SV_INOUT(T) inout T
