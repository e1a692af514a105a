// SPDX-License-Identifier: BSD-3-Clause
//VTK::System::Dec

// LR-spline volume trimming (Fuchs et al. §4.1), depth pre-pass: the faces of
// the trimming surface are drawn into depth-only targets (the nearest front
// faces and the farthest back faces); nothing else is written.

//VTK::Output::Dec

void main()
{
  gl_FragData[0] = vec4(1.0);
}
