// SPDX-License-Identifier: BSD-3-Clause
// Helpers of the shared GLSL/C++ subset used by more than one *Shared.glsl
// file (rules: Core/vtkSplineVizSharedGLSL.h): embedded after the prelude
// in the shaders, compiled as C++ next to the file that needs it.

// Any unit vector orthogonal to the unit vector n.
vec3 svAnyOrthogonal(vec3 n)
{
  vec3 o;
  if (abs(n.x) < abs(n.y) && abs(n.x) < abs(n.z))
  {
    o = vec3(0.0, -n.z, n.y);
  }
  else if (abs(n.y) < abs(n.z))
  {
    o = vec3(-n.z, 0.0, n.x);
  }
  else
  {
    o = vec3(-n.y, n.x, 0.0);
  }
  return normalize(o);
}
