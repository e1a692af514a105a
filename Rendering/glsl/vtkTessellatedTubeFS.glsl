// SPDX-License-Identifier: BSD-3-Clause
// Tessellated spline tubes (Salm §3.1), fragment-stage declarations, inserted
// into VTK's polydata fragment shader (at //VTK::Normal::Dec); lighting,
// coloring, depth peeling and picking are VTK's. Per pixel: the interpolated
// normal, normalized, turned to the side seen (the start caps are wound the
// other way round), and the color spline's value interpolated from the
// evaluation stage's vertices.

in vec3 tubeNormalVCVSOutput;
in float tubeTVSOutput;
flat in ivec4 tubeInfoVSOutput; // first node, segment, tube, flags | kind << 2
in vec4 tubeColorVSOutput;

//SV::SplineTubeMath::Dec
