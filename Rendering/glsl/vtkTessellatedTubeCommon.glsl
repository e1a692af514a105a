// SPDX-License-Identifier: BSD-3-Clause
// Tessellated spline tubes (Salm §3.1): what the vertex, tessellation-control
// and tessellation-evaluation stages share. Needs the spline-tube math
// (vtkSplineTubeMathShared.glsl) and the tubes buffer
// (vtkSplineTubeNodes.glsl) before it.
uniform isamplerBuffer tubeFrames;   // per node: orthogonal vector, octahedral, int16
uniform mat4 tubeMCVC;               // model (shifted) to view
uniform float tubeRadiusScale;       // model to view scale of radii
uniform vec2 tubeMinimumRadius;      // the narrowest drawn radius: x + y (view distance)

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
  vec4 p = tubeNodeModel(node);
  vec3 x = (tubeMCVC * vec4(p.xyz, 1.0)).xyz;
  return vec4(x, svDrawnRadius(p.w * tubeRadiusScale, x.z, tubeMinimumRadius));
}

vec4 tubeNodeDerivative(int node)
{
  vec4 m = tubeNodeDerivativeModel(node);
  return vec4(mat3(tubeMCVC) * m.xyz, m.w * tubeRadiusScale);
}

// The flags of the run of `count` segments from `node`: 1 when it starts its
// tube, 2 when it ends it.
int tubeRunFlags(int node, int count)
{
  uint a = texelFetch(tubeNodeInfo, node).x;
  uint b = texelFetch(tubeNodeInfo, node + count).x;
  return ((a & tubeFirstNodeBit) != 0u ? 1 : 0) | ((b & tubeLastNodeBit) != 0u ? 2 : 0);
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

// The scalar-color spline (vtkSplineTubeColor.glsl, inserted here), evaluated
// at curve parameter t of the segment from `node`; white without scalar
// coloring (1: scalar coloring; 2: direction coloring, made per fragment).
uniform int tubeHaveColors;
//SV::SplineTubeColor::Dec

vec4 tubeColorAt(int node, float t)
{
  if (tubeHaveColors != 1)
  {
    return vec4(1.0);
  }
  return tubeColorSpline(node, t);
}

// The circle of center c.xyz and radius c.w across the unit tangent `tangent`
// as seen from the eye: `front`, the unit direction to the eye orthogonal to
// the tangent (where the tube points at the eye, the orthogonal vector of
// the segment from `node` at curve parameter t, d the curve's derivative
// there), and `halfSpan`, the angle from `front` to either silhouette point
// (acos(r / |eye - c| across the tangent); pi / 2 in parallel projection).
// The offsets cos(phi) front + sin(phi) (tangent x front), phi in
// [-halfSpan, halfSpan], are the circle's half that faces the eye.
void tubeViewFacingFrame(vec4 c, vec3 tangent, vec3 d, int node, float t, bool parallel,
  out vec3 front, out float halfSpan)
{
  vec3 toEye = parallel ? vec3(0.0, 0.0, 1.0) : -c.xyz;
  vec3 across = toEye - dot(toEye, tangent) * tangent;
  float distance = length(across);
  if (distance > 1e-6 * length(toEye))
  {
    front = across / distance;
  }
  else
  {
    front = svInterpolateFrame(tubeNodeFrame(node), tubeNodeFrame(node + 1), t, d);
  }
  halfSpan =
    parallel || distance <= 0.0 ? 1.5707963267948966 : acos(clamp(c.w / distance, 0.0, 1.0));
}

// A thin tube's ring at curve parameter t of the segment (p0, m0, p1, m1)
// (its first node `node`): the center and radius (returned), the curve's
// derivatives and unit tangent there, and its view-facing frame
// (tubeViewFacingFrame). chord > 0: the ring lies inside a run whose rings
// are `chord` apart in t; it then moves away from the center of curvature
// by half the sagitta of such a chord (the chord's middle lies
// |c''_perp| h^2 / 8 inside the curve), so that the chords deviate by at
// most half their sagitta (3/4 next to the run's ends, whose rings stay on
// the curve for the neighbours).
vec4 tubeViewFacingRing(vec4 p0, vec4 m0, vec4 p1, vec4 m1, int node, float t, float chord,
  bool parallel, out vec4 d, out vec4 dd, out vec3 tangent, out vec3 front, out float halfSpan)
{
  vec4 c = svHermite(p0, m0, p1, m1, t);
  d = svHermiteDerivative(p0, m0, p1, m1, t);
  dd = svHermiteSecondDerivative(p0, m0, p1, m1, t);
  tangent = normalize(d.xyz);
  if (chord > 0.0)
  {
    vec3 inward = dd.xyz - dot(dd.xyz, tangent) * tangent;
    c.xyz -= inward * (0.0625 * chord * chord);
  }
  tubeViewFacingFrame(c, tangent, d.xyz, node, t, parallel, front, halfSpan);
  return c;
}

// A vertex of the view-facing half ring of thin tubes (the single-patch mode
// of the evaluation stage and the thin-tube draws of vtkTessellatedTubeThinVS,
// which share it so that both draw the same surface): the wall point of the
// segment (p0, m0, p1, m1) (view coordinates; its first node `node`, whose
// orthogonal vectors serve where the tube points at the eye) at curve
// parameter t and ring parameter s in [0, 1] (from one silhouette point to
// the other through the point nearest the eye: the offsets
// cos(phi) F + sin(phi) (T x F), F the direction to the eye orthogonal to
// the tangent T, phi in [-A, A] with A = acos(r / |eye - c| across T), pi / 2
// in parallel projection: the exact silhouette of the circle seen from the
// eye), on a ring of L intervals. The vertices between the silhouettes lie
// nearer the silhouettes (phi = A sin(pi/2 sigma), sigma = 2s - 1, where the
// circle's depth changes fastest) and 1 + 3.3 / L^3 radii out, so that the
// chords straddle the circle: the depth error stays below 0.21 r for L = 3,
// 0.13 r for L = 4, 0.07 r for L = 6 (up to 97 % of the half width).
// chord > 0: inside a run, see tubeViewFacingRing.
void tubeHalfRingVertex(vec4 p0, vec4 m0, vec4 p1, vec4 m1, int node, float t, float s,
  float L, float chord, bool parallel, out vec3 position, out vec3 normal)
{
  vec4 d;
  vec4 dd;
  vec3 tangent;
  vec3 front;
  float halfSpan;
  vec4 c =
    tubeViewFacingRing(p0, m0, p1, m1, node, t, chord, parallel, d, dd, tangent, front, halfSpan);
  L = max(ceil(L), 3.0);
  float sigma = 2.0 * s - 1.0;
  vec3 offset = svTubeOffset(front, tangent, halfSpan * sin(1.5707963267948966 * sigma));
  float outward = abs(sigma) < 1.0 ? 1.0 + 3.3 / (L * L * L) : 1.0;
  position = c.xyz + (outward * c.w) * offset;
  // The normal is exact for any frame (svTubeSurfaceTangent), also for this
  // one that turns with the view.
  normal = svTubeNormal(offset, svTubeSurfaceTangent(d.xyz, dd.xyz, c.w, d.w, offset));
}
