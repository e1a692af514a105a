// SPDX-License-Identifier: BSD-3-Clause
//VTK::System::Dec

// Tessellated spline tubes (Salm §3.1 'Base tessellation'), vertex stage.
//
// An instanced draw of a base mesh, one instance per segment: the segment is
// entry tubeListOffset + gl_InstanceID of the instance list (the mapper's
// level-of-detail bins); the base-mesh vertex is gl_VertexID (the mesh has no
// attributes): vertex rings r = 0 .. tubeRings - 1 of tubeSides + 1 vertices
// (the last repeats the first at s = 1), then the centers of the start and
// end caps. The vertex is bent along the segment's position spline: curve
// parameter t = r / (tubeRings - 1), offset along the interpolated orthogonal
// vector rotated by the angle of s, radius spline. Its normal (from the
// analytic surface tangent) serves the control stage's back-patch culling
// and silhouette criterion. On the end rings it leaves out the curvature
// term (the position spline is only C1 at the nodes): it then depends on the
// node's data only, so the two segments meeting at a node compute the same
// normals and hence the same tessellation levels for their shared edges
// (watertight junctions).
//
// The outputs named like the fragment stage's inputs let VTK link this stage
// with the fragment stage before the mapper links in the tessellation stages.

uniform int tubeRings;
uniform int tubeSides;
uniform usamplerBuffer tubeInstances; // the segments (first nodes) of the level-of-detail bins
uniform int tubeListOffset;
uniform int tubeChunks; // instances are (first node, count) runs of one tube

out vec4 vertexVCVSOutput;       // position, view coordinates
out vec3 tubeNormalVCVSOutput;   // normal, view coordinates
out float tubeTVSOutput;         // curve parameter
flat out ivec4 tubeInfoVSOutput; // first node, first node, tube, flags | kind << 2 | count << 4
out vec4 tubeColorVSOutput;      // (made by the evaluation stage)
out vec4 tubeAxisVSOutput;       // unit tangent (view coordinates), s

//SV::SplineTubeMath::Dec

//SV::TessellatedTubeCommon::Dec

void main()
{
  int node;
  int count = 1;
  if (tubeChunks != 0)
  {
    node = int(texelFetch(tubeInstances, tubeListOffset + 2 * gl_InstanceID).x);
    count = int(texelFetch(tubeInstances, tubeListOffset + 2 * gl_InstanceID + 1).x);
  }
  else
  {
    node = int(texelFetch(tubeInstances, tubeListOffset + gl_InstanceID).x);
  }
  int flags = tubeRunFlags(node, count);
  int tube = tubeOfNode(node);

  int perRing = tubeSides + 1;
  if (tubeSides == 1)
  {
    // Single-patch mode: the control stage works from the nodes.
    int wall = tubeRings * perRing;
    int capKind = gl_VertexID < wall ? 0 : gl_VertexID - wall + 1;
    int ring = gl_VertexID / perRing;
    vertexVCVSOutput = vec4(0.0, 0.0, 0.0, 1.0);
    tubeNormalVCVSOutput = vec3(0.0, 0.0, 1.0);
    tubeTVSOutput = capKind == 0 ? float(ring) / float(tubeRings - 1) : float(capKind - 1);
    tubeInfoVSOutput = ivec4(node, node, tube, flags | (capKind << 2) | (count << 4));
    tubeAxisVSOutput = vec4(0.0);
    tubeColorVSOutput = vec4(1.0);
    gl_Position = vec4(0.0, 0.0, 0.0, 1.0);
    return;
  }
  TubeSegment seg = tubeLoadSegment(node);
  int wallVertices = tubeRings * perRing;
  int id = gl_VertexID;
  int kind = 0; // 0: wall, 1: start-cap center, 2: end-cap center
  float t;
  float s;
  if (id < wallVertices)
  {
    int ring = id / perRing;
    t = float(ring) / float(tubeRings - 1);
    s = float(id - ring * perRing) / float(tubeSides);
  }
  else
  {
    kind = id - wallVertices + 1;
    t = kind == 1 ? 0.0 : 1.0;
    s = 0.0;
  }

  vec4 c = svHermite(seg.p0, seg.m0, seg.p1, seg.m1, t);
  vec4 d = svHermiteDerivative(seg.p0, seg.m0, seg.p1, seg.m1, t);
  vec3 unitTangent = normalize(d.xyz);
  vec3 position;
  vec3 normal;
  if (kind == 0)
  {
    vec3 n = svInterpolateFrame(seg.f0, seg.f1, t, d.xyz);
    vec3 o = svTubeOffset(n, unitTangent, svTubeAngle(s));
    position = c.xyz + c.w * o;
    vec3 dd = vec3(0.0);
    if (t != 0.0 && t != 1.0)
    {
      dd = svHermiteSecondDerivative(seg.p0, seg.m0, seg.p1, seg.m1, t).xyz;
    }
    normal = svTubeNormal(o, svTubeSurfaceTangent(d.xyz, dd, c.w, d.w, o));
  }
  else
  {
    position = c.xyz;
    normal = kind == 1 ? -unitTangent : unitTangent;
  }

  vertexVCVSOutput = vec4(position, 1.0);
  tubeNormalVCVSOutput = normal;
  tubeTVSOutput = t;
  tubeInfoVSOutput = ivec4(node, node, tube, flags | (kind << 2) | (1 << 4));
  tubeAxisVSOutput = vec4(unitTangent, s);
  tubeColorVSOutput = vec4(1.0);
  gl_Position = vec4(position, 1.0);
}
