// SPDX-License-Identifier: BSD-3-Clause
//VTK::System::Dec

// LR-spline volume ray casting (Fuchs et al. §4), vertex stage: the faces of
// the box around all patches (data coordinates) as the proxy of the rays;
// the fragment stage builds its ray from gl_FragCoord.

in vec3 vertexMC;
uniform mat4 lrMCDCMatrix; // data coordinates to clip space

void main()
{
  gl_Position = lrMCDCMatrix * vec4(vertexMC, 1.0);
}
