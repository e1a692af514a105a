// SPDX-License-Identifier: BSD-3-Clause
// Tessellated spline tubes (Salm §3.1), thin tubes drawn without the
// tessellator (vtkTessellatedTubeThinVS.glsl): fragment-stage declarations,
// inserted into VTK's polydata fragment shader (at //VTK::Normal::Dec);
// lighting, coloring, depth peeling and picking are VTK's.
//
// A wall fragment lies on the view-facing half of the tube's wall, drawn
// with three vertices per ring (inside the tube). Along its ray the tube's
// front surface is, locally, that of the cylinder of the interpolated ring
// center, radius and axis tangent (svCylinderFrontDistance): the fragment
// takes that point's depth (gl_FragDepth) and normal (tilted by the radius'
// slope, as on a cone). Exact for straight tubes of constant radius;
// elsewhere within the chords' deviation from the curve, which the rings
// along keep within a tenth of the radius (TestTubeFidelity measures the
// depth). Where that point lies beyond the tube's end (seen obliquely, the
// cylinder's surface along the ray can lie past the end ring) the ray meets
// the cap first: the fragment is dropped for the cap's. Cap fragments
// (radius 0) keep their polygon's depth and normal.

in vec4 tubeAxisVCVSOutput;   // walls: ring center (xyz), radius (w); caps: 0
in vec4 tubeNormalVCVSOutput; // walls: derivative by t (position, radius); caps: normal
in float tubeTVSOutput;
flat in ivec4 tubeInfoVSOutput; // first node, segment, tube, count << 4 | ends (caps: kind << 2)
in vec4 tubeColorVSOutput;
uniform mat4 VCDCMatrix;

//SV::SplineTubeMath::Dec

// The front surface of the tube along the ray through the wall fragment at
// p (view coordinates): the point and its unit normal; false when the point
// lies beyond the end of the tube (tubeInfoVSOutput.w: the run's segment
// count << 4, bit 0 when it starts its tube, bit 1 when it ends it).
bool tubeThinSurface(vec3 p, out vec3 hit, out vec3 normal)
{
  float speed = max(length(tubeNormalVCVSOutput.xyz), 1e-30);
  vec3 a = tubeNormalVCVSOutput.xyz / speed;
  vec3 c = tubeAxisVCVSOutput.xyz;
  float r = tubeAxisVCVSOutput.w;
  vec3 dir = cameraParallel != 0 ? vec3(0.0, 0.0, -1.0) : normalize(p);
  float s = svCylinderFrontDistance(p, dir, c, a, r, 8.0 * r);
  hit = p + s * dir;
  vec3 w = hit - c;
  vec3 radial = w - dot(w, a) * a;
  float len = length(radial);
  radial = len > 0.0 ? radial / len : -dir;
  normal = normalize(radial - (tubeNormalVCVSOutput.w / speed) * a);
  // the hit's curve parameter in the run (t moves by the axial displacement
  // over the speed)
  float t = tubeTVSOutput + s * dot(dir, a) / speed;
  int ends = tubeInfoVSOutput.w;
  return !(((ends & 1) != 0 && t < 0.0) || ((ends & 2) != 0 && t > float(ends >> 4)));
}
