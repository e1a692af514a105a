// SPDX-License-Identifier: BSD-3-Clause
// Prelude that lets glsl/vtkSplineTubeMathShared.glsl (written in the common subset
// of GLSL and C++) compile as GLSL.
#define real float
#define SV_OUT(T) out T
#define SV_INOUT(T) inout T
