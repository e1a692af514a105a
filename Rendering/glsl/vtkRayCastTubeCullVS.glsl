//VTK::System::Dec

// Ray-cast spline tubes: the occlusion-culling depth pre-pass, vertex stage.
//
// One quad per cubic segment (gl_VertexID = 4 * segment + corner, indexed
// triangles, no vertex attributes): a band around the segment's chord that
// lies inside the tube (svInnerBandHalfWidth), facing the eye and moved
// toward it by half its half-width (its points stay within the band's
// half-width of the chord). The pre-pass rasterizes these quads into a depth
// texture of its own with a fragment stage that writes nothing, so the
// rasterizer's early depth test applies; the ray-cast pass then discards,
// before any root finding, every fragment whose rectangle (which lies in
// front of its whole sub-segment) is behind that depth: something inside a
// tube, hence a tube's surface, is in front of it along the pixel's ray.
//
// Segments without a band (bent too much for their radius) and segments the
// ray origin may be inside of (the ray caster then draws nothing for them)
// produce a degenerate quad.

uniform samplerBuffer tubeNodes;     // per node: (x, y, z, r), (dx, dy, dz, dr)
uniform usamplerBuffer tubeSegments; // per segment: (first node | flags << 30, tube)
uniform int subSegments;             // quadratic sub-segments per cubic segment
uniform mat4 tubeMCVC;               // model (shifted) to view
uniform float tubeRadiusScale;       // model to view scale of radii
uniform mat4 VCDCMatrix;
uniform int cameraParallel;
uniform float tubeBandScale;         // 1; larger only in tests (negative control)

//VTK::SplineTubeMath::Dec

void main()
{
  int segment = gl_VertexID / 4;
  int corner = gl_VertexID - 4 * segment;
  int node = int(texelFetch(tubeSegments, segment).x & 0x3FFFFFFFu);
  vec4 p0 = texelFetch(tubeNodes, 2 * node);
  vec4 m0 = texelFetch(tubeNodes, 2 * node + 1);
  vec4 p1 = texelFetch(tubeNodes, 2 * node + 2);
  vec4 m1 = texelFetch(tubeNodes, 2 * node + 3);
  // View coordinates (the sub-segments' control points transform with them).
  p0 = vec4((tubeMCVC * vec4(p0.xyz, 1.0)).xyz, p0.w * tubeRadiusScale);
  p1 = vec4((tubeMCVC * vec4(p1.xyz, 1.0)).xyz, p1.w * tubeRadiusScale);
  m0 = vec4(mat3(tubeMCVC) * m0.xyz, m0.w * tubeRadiusScale);
  m1 = vec4(mat3(tubeMCVC) * m1.xyz, m1.w * tubeRadiusScale);
  // A margin of 1 % keeps the band strictly inside despite rounding.
  float reach;
  float h = tubeBandScale * 0.99 * svInnerBandHalfWidth(p0, m0, p1, m1, subSegments, reach);

  vec3 chord = p1.xyz - p0.xyz;
  vec3 mid = 0.5 * (p0.xyz + p1.xyz);
  vec3 toEye = cameraParallel != 0 ? vec3(0.0, 0.0, 1.0) : -mid;
  // Could the ray origin be inside the segment's tube (no point of which is
  // farther than `reach` from the chord)?
  bool eyeNear;
  if (cameraParallel != 0)
  {
    eyeNear = max(p0.z, p1.z) + reach >= 0.0;
  }
  else
  {
    float l = clamp(dot(-p0.xyz, chord) / max(dot(chord, chord), 1e-30), 0.0, 1.0);
    eyeNear = length(p0.xyz + l * chord) <= reach;
  }
  vec3 across = cross(chord, toEye);
  float acrossLength = length(across);
  if (h <= 0.0 || eyeNear || acrossLength <= 1e-12 * length(chord) * length(toEye))
  {
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0); // nothing drawn
    return;
  }
  across /= acrossLength;
  vec3 forward = normalize(cross(across, chord));
  if (dot(forward, toEye) < 0.0)
  {
    forward = -forward;
  }
  vec3 p = ((corner & 1) != 0 ? p1.xyz : p0.xyz) +
    ((corner & 2) != 0 ? 0.8660254 * h : -0.8660254 * h) * across + (0.5 * h) * forward;
  gl_Position = VCDCMatrix * vec4(p, 1.0);
}
