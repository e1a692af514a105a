// SPDX-License-Identifier: BSD-3-Clause
// Tessellated spline tubes (Salm §3.1), tessellation-evaluation stage: every
// vertex of the refined patch is bent onto the tube again, from its patch
// coordinates: angle parameter s along u, curve parameter t along v (wall) or
// relative radius 1 - v (caps). The orthogonal vector is interpolated between
// the segment's pre-computed ones, re-projected onto the cross-section plane
// and normalized (svInterpolateFrame); the wall normal is the offset vector
// projected onto the plane of the numerically determined surface tangent
// (Salm Fig. 7, svTubeWallNormal); the caps' normal is the axis direction.
// The color spline (scalar coloring) is evaluated per vertex here and
// interpolated per pixel (the refined edges are at most tubeMaxEdgeLength
// pixels long, much shorter near the silhouettes; per pixel it cost a
// quarter of the frame time on llvmpipe).
// Shared edges get bit-identical vertices: every position is computed by the
// same code from parameters that are exact at the patch borders.
// A patch spanning a run of segments (count > 1) finds the segment of each
// vertex from its curve parameter t in [0, count] and reads its nodes. In the
// single-patch mode (tubeSides == 1, thin tubes drawn with few vertices per
// ring) a wall ring is the view-facing half of the cross-section, from one
// silhouette point to the other (tubeHalfRingVertex, shared with the
// thin-tube draws of vtkTessellatedTubeThinVS.glsl); caps are the disk's
// inscribed polygon.

layout(quads, equal_spacing, ccw) in;

patch in vec4 tubePatchP0;
patch in vec4 tubePatchM0;
patch in vec4 tubePatchP1;
patch in vec4 tubePatchM1;
patch in vec3 tubePatchF0;
patch in vec3 tubePatchF1;
patch in vec4 tubePatchParams;
patch in ivec4 tubePatchInfo;

uniform mat4 VCDCMatrix;
uniform int cameraParallel;
uniform int tubeSides;

out vec4 vertexVCVSOutput;
out vec3 tubeNormalVCVSOutput;
out float tubeTVSOutput;
flat out ivec4 tubeInfoVSOutput;
out vec4 tubeColorVSOutput;

//SV::SplineTubeMath::Dec

//SV::TessellatedTubeCommon::Dec

// Segment of curve parameter t in [0, count] of a run (a vertex at a node
// belongs to the segment before it, t = 0 to the first).
int tubeSegmentOf(float t, int count)
{
  return clamp(int(ceil(t)) - 1, 0, count - 1);
}

void main()
{
  float u = gl_TessCoord.x;
  float v = gl_TessCoord.y;
  int kind = (tubePatchInfo.w >> 2) & 3;
  int count = tubePatchInfo.w >> 4;
  float s = mix(tubePatchParams.x, tubePatchParams.y, u);
  float angle = svTubeAngle(s);
  float tGlobal = kind == 0 ? mix(tubePatchParams.z, tubePatchParams.w, v) : tubePatchParams.z;
  float rho = kind == 0 ? 1.0 : 1.0 - v;

  TubeSegment seg;
  float t = tGlobal;
  int k = 0;
  bool halfRing = tubeSides == 1 && kind == 0;
  if (count > 1 && kind == 0)
  {
    k = tubeSegmentOf(tGlobal, count);
    t = tGlobal - float(k);
    int node = tubePatchInfo.x + k;
    if (halfRing)
    {
      // The orthogonal vectors only where the tube points at the eye (below).
      seg.p0 = tubeNodePosition(node);
      seg.m0 = tubeNodeDerivative(node);
      seg.p1 = tubeNodePosition(node + 1);
      seg.m1 = tubeNodeDerivative(node + 1);
    }
    else
    {
      seg = tubeLoadSegment(node);
    }
  }
  else
  {
    seg.p0 = tubePatchP0;
    seg.m0 = tubePatchM0;
    seg.p1 = tubePatchP1;
    seg.m1 = tubePatchM1;
    seg.f0 = tubePatchF0;
    seg.f1 = tubePatchF1;
  }

  vec3 offset;
  vec3 position;
  vec3 normal;
  if (halfRing)
  {
    // The view-facing half ring (see above and tubeHalfRingVertex): the ring
    // levels are the edges' (v = 0: outer 1, v = 1: outer 3) or the inner one.
    float L = v == 0.0 ? gl_TessLevelOuter[1]
                       : (v == 1.0 ? gl_TessLevelOuter[3] : gl_TessLevelInner[0]);
    float chord =
      count > 1 && v > 0.0 && v < 1.0 ? float(count) / max(gl_TessLevelOuter[0], 1.0) : 0.0;
    tubeHalfRingVertex(seg.p0, seg.m0, seg.p1, seg.m1, tubePatchInfo.x + k, t, s, L, chord,
      cameraParallel != 0, position, normal);
  }
  else if (kind == 0)
  {
    position =
      svTubeSurfacePoint(seg.p0, seg.m0, seg.p1, seg.m1, seg.f0, seg.f1, t, angle, rho, offset);
    // Relative to the first node for the difference's precision.
    vec4 p1 = vec4(seg.p1.xyz - seg.p0.xyz, seg.p1.w);
    normal = svTubeWallNormal(
      vec4(0.0, 0.0, 0.0, seg.p0.w), seg.m0, p1, seg.m1, seg.f0, seg.f1, t, angle, offset);
  }
  else
  {
    position =
      svTubeSurfacePoint(seg.p0, seg.m0, seg.p1, seg.m1, seg.f0, seg.f1, t, angle, rho, offset);
    vec3 axis = normalize(svHermiteDerivative(seg.p0, seg.m0, seg.p1, seg.m1, t).xyz);
    normal = kind == 1 ? -axis : axis;
  }

  vec4 color = tubeColorAt(tubePatchInfo.x + k, t);

  vertexVCVSOutput = vec4(position, 1.0);
  tubeNormalVCVSOutput = normal;
  tubeColorVSOutput = color;
  tubeTVSOutput = tGlobal;
  tubeInfoVSOutput = tubePatchInfo;
  gl_Position = VCDCMatrix * vec4(position, 1.0);
}
