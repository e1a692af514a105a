// Tessellated spline tubes (Salm §3.1): what the vertex, tessellation-control
// and tessellation-evaluation stages share. Needs the spline-tube math
// (vtkSplineTubeMathShared.glsl) before it.
//
// The tubes buffer (see vtkSplineTubeMapper and vtkTessellatedTubeMapper):
uniform samplerBuffer tubeNodes;     // per node: (x, y, z, r), (dx, dy, dz, dr)
uniform isamplerBuffer tubeFrames;   // per node: orthogonal vector, octahedral, int16
uniform usamplerBuffer tubeSegments; // per segment: (first node | flags << 30, tube)
uniform mat4 tubeMCVC;               // model (shifted) to view
uniform float tubeRadiusScale;       // model to view scale of radii

// A cubic segment in view coordinates: nodes (xyz, radius), derivatives
// (xyz, radius derivative) and orthogonal vectors.
struct TubeSegment
{
  vec4 p0;
  vec4 m0;
  vec4 p1;
  vec4 m1;
  vec3 f0;
  vec3 f1;
};

vec4 tubeNodePosition(int node)
{
  vec4 p = texelFetch(tubeNodes, 2 * node);
  return vec4((tubeMCVC * vec4(p.xyz, 1.0)).xyz, p.w * tubeRadiusScale);
}

vec4 tubeNodeDerivative(int node)
{
  vec4 m = texelFetch(tubeNodes, 2 * node + 1);
  return vec4(mat3(tubeMCVC) * m.xyz, m.w * tubeRadiusScale);
}

vec3 tubeNodeFrame(int node)
{
  vec3 f = svOctDecode(vec2(texelFetch(tubeFrames, node).xy) / 32767.0);
  return normalize(mat3(tubeMCVC) * f);
}

TubeSegment tubeLoadSegment(int node)
{
  TubeSegment s;
  s.p0 = tubeNodePosition(node);
  s.m0 = tubeNodeDerivative(node);
  s.p1 = tubeNodePosition(node + 1);
  s.m1 = tubeNodeDerivative(node + 1);
  s.f0 = tubeNodeFrame(node);
  s.f1 = tubeNodeFrame(node + 1);
  return s;
}
