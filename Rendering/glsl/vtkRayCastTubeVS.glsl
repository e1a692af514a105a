// SPDX-License-Identifier: BSD-3-Clause
//VTK::System::Dec

// Ray-cast spline tubes (Salm §3.2 'Rendering'), vertex stage.
//
// One point per quadratic sub-segment of the chunks drawn (gl_VertexID =
// (entry of tubeChunkList) x tubeChunkSegments x subSegments + sub-segment
// in the chunk), no vertex attributes. The vertex reads its sub-segment's two nodes from the tubes
// buffer, splits the cubic segment into its quadratic sub-segments
// (svSplitSegment), takes the one it owns into view coordinates, bounds it
// with its oriented box (svSubSegmentBox) and covers the box's projection
// with a rectangle in the image plane, oriented along the sub-segment's
// projected chord (a tight fit for the long, thin boxes of tubes), which the
// geometry stage (vtkRayCastTubeGS.glsl) emits. Boxes crossing the near
// plane are clipped to it first; boxes outside the view frustum get no
// rectangle. The fragment stage intersects the view ray with the
// sub-segment.
//
// Why a rectangle and not the box itself: on Mesa llvmpipe, rasterizing the
// box faces (from a geometry shader or an instanced box mesh) costs about
// 3 times more triangles per sub-segment and the triangle setup dominates the
// frame time (see vtkRayCastTubeMapper.h for the measurements).

uniform int subSegments;             // quadratic sub-segments per cubic segment
uniform usamplerBuffer tubeChunkList; // per chunk drawn: its first node, its segment count
uniform int tubeHaveColors;          // the color spline's ends for the fragment stage
uniform int tubeChunkSegments;       // the longest chunk, in segments
uniform mat4 tubeMCVC;               // model (shifted) to view
uniform float tubeRadiusScale;       // model to view scale of radii
uniform float tubeNearPlane;         // distance of the near plane (view units)
uniform mat4 VCDCMatrix;
uniform int cameraParallel;
uniform float tubeStraightTolerance; // fraction of the radius; 0: always root finding
uniform float tubePixelScale;        // pixels per view unit (at unit distance if perspective)
uniform vec2 tubeMinimumRadius;      // the narrowest drawn radius: x + y (view distance)
uniform int tubeSingleLayer;         // 1: translucent, each tube one layer (cut0, cut1)

// The sub-segment and its rectangle, for the geometry stage.
out TubeRectangle
{
  flat vec4 q0;    // quadratic sub-segment in view coordinates
  flat vec4 q1;    // (xyz: control point, w: radius)
  flat vec4 q2;
  flat ivec4 info; // first node, sub-segment, tube, flags | mode << 2
  flat vec4 frame; // u (xy: the rectangle's first axis; v = (-u.y, u.x)), z of its plane, w > 0: drawn
  flat vec4 span;  // lo (xy), hi (zw): extents along u and v
  flat vec4 c0;    // the color spline: colors and derivatives at the segment's ends
  flat vec4 d0;
  flat vec4 c1;
  flat vec4 d1;
  flat vec4 cut0;  // with tubeSingleLayer: the planes between which the rectangle's
  flat vec4 cut1;  // part of the tube lies (dot(cut, (p, 1)) >= 0 and > 0)
} tubeRect;

//SV::SplineTubeMath::Dec

// The plane through the segment's point at parameter `t` (k / subSegments)
// normal to its tangent there, (normal, offset), the normal facing forward.
// Both rectangles on either side of a joint compute it from the same inputs
// by the same operations, so they cut the tube along the same plane.
vec4 tubeCutPlane(vec4 a, vec4 da, vec4 b, vec4 db, int k)
{
  vec3 c = k == 0 ? a.xyz : (k == subSegments ? b.xyz : svHermite(a, da, b, db,
    float(k) / float(subSegments)).xyz);
  vec3 n = k == 0 ? da.xyz : (k == subSegments ? db.xyz : svHermiteDerivative(a, da, b, db,
    float(k) / float(subSegments)).xyz);
  return vec4(n, -dot(n, c));
}

// Projection of view-space point p onto the plane z = zp along the view ray.
vec2 projectToPlane(vec3 p, float zp)
{
  if (cameraParallel != 0)
  {
    return p.xy;
  }
  return p.xy * (zp / p.z);
}

// The segment of node `node` in view coordinates (Hermite and Bezier forms
// transform with their control points), its radii the drawn ones.
void tubeViewSegment(int node, out vec4 a, out vec4 da, out vec4 b, out vec4 db, out int flags,
  out int tube)
{
  vec4 p0;
  vec4 m0;
  vec4 p1;
  vec4 m1;
  tubeSegmentModel(node, p0, m0, p1, m1, flags, tube);
  a = vec4((tubeMCVC * vec4(p0.xyz, 1.0)).xyz, p0.w * tubeRadiusScale);
  b = vec4((tubeMCVC * vec4(p1.xyz, 1.0)).xyz, p1.w * tubeRadiusScale);
  da = vec4(mat3(tubeMCVC) * m0.xyz, m0.w * tubeRadiusScale);
  db = vec4(mat3(tubeMCVC) * m1.xyz, m1.w * tubeRadiusScale);
  a.w = svDrawnRadius(a.w, a.z, tubeMinimumRadius);
  b.w = svDrawnRadius(b.w, b.z, tubeMinimumRadius);
}

// How sub-segment k (q0, q1, q2) of the segment is intersected. Straight
// segments and sub-segments (to within tubeStraightTolerance of their
// smallest radius and a quarter pixel) are intersected as round cones in
// closed form instead of by root finding: a straight segment is one
// rectangle (drawn by its first sub-segment), a pair of straight
// sub-segments (k, k + 1 for even k) one rectangle with two cones (drawn by
// the first), and a straight sub-segment alone one cone. Returns the mode (0:
// root finding, 1: straight sub-segment, 2: straight segment, 3: straight
// pair) and sets q0, q1, q2 to the control points to bound; -1 when another
// sub-segment's rectangle draws this one.
int tubeStraightMode(vec4 a, vec4 da, vec4 b, vec4 db, int k, inout vec4 q0, inout vec4 q1,
  inout vec4 q2)
{
  int mode = 0;
  if (tubeStraightTolerance > 0.0)
  {
    float reach;
    float segmentError = svSegmentStraightness(a, da, b, db, reach);
    // The tolerance in view units where the segment is nearest to the eye.
    float zNearest = max(a.z, b.z) + reach;
    float pixel = cameraParallel != 0 ? 1.0 / tubePixelScale : -zNearest / tubePixelScale;
    float rMinSegment = min(min(a.w, b.w), min(a.w + da.w / 3.0, b.w - db.w / 3.0));
    int partner = k + 1 - 2 * (k & 1);
    vec4 r0;
    vec4 r1;
    vec4 r2;
    svSplitSegment(a, da, b, db, subSegments, partner, r0, r1, r2);
    float rMin = min(min(q0.w, q1.w), q2.w);
    float rMinPair = min(rMin, min(min(r0.w, r1.w), r2.w));
    float error = svSubSegmentStraightness(q0, q1, q2);
    float partnerError = svSubSegmentStraightness(r0, r1, r2);
    bool straight = error <= min(tubeStraightTolerance * rMin, 0.25 * pixel);
    // (the same decision for both sub-segments of the pair)
    bool pairStraight =
      max(error, partnerError) <= min(tubeStraightTolerance * rMinPair, 0.25 * pixel);
    if (cameraParallel == 0 && zNearest >= -tubeNearPlane)
    {
      mode = 0; // near the eye: always the root finding
    }
    else if (segmentError <= min(tubeStraightTolerance * max(rMinSegment, 0.0), 0.25 * pixel))
    {
      mode = 2;
    }
    else if (pairStraight)
    {
      mode = 3;
    }
    else if (straight)
    {
      mode = 1;
    }
    if ((mode == 2 && k != 0) || (mode == 3 && (k & 1) != 0))
    {
      return -1; // drawn by another sub-segment's rectangle
    }
    if (mode == 2)
    {
      q0 = a;
      q1 = 0.5 * (a + b); // the cone's convex hull for the bounds
      q2 = b;
    }
    else if (mode == 3)
    {
      q1 = q2; // the two cones (q0, q1) and (q1, q2)
      q2 = r2;
    }
    else if (mode == 1)
    {
      q1 = 0.5 * (q0 + q2);
    }
  }
  return mode;
}

// Translucent: the part of the tube this rectangle draws, between the
// planes at its first and last sub-segment's ends (none at the tube's
// ends), so that neighbours never both draw a pixel (vtkRayCastTubeFS).
void tubeSetCutPlanes(vec4 a, vec4 da, vec4 b, vec4 db, int k, int mode, int flags)
{
  tubeRect.cut0 = vec4(0.0, 0.0, 0.0, 1.0);
  tubeRect.cut1 = vec4(0.0, 0.0, 0.0, 1.0);
  if (tubeSingleLayer != 0)
  {
    int first = mode == 2 ? 0 : k;
    int last = mode == 2 ? subSegments - 1 : (mode == 3 ? k + 1 : k);
    if ((flags & 1) == 0 || first != 0)
    {
      tubeRect.cut0 = tubeCutPlane(a, da, b, db, first);
    }
    if ((flags & 2) == 0 || last != subSegments - 1)
    {
      tubeRect.cut1 = -tubeCutPlane(a, da, b, db, last + 1);
    }
  }
}

// The color spline's ends for the fragment stage.
void tubeSetColors(int node)
{
  if (tubeHaveColors == 1)
  {
    tubeRect.c0 = tubeNodeColor(node);
    tubeRect.d0 = tubeNodeColorDerivative(node);
    tubeRect.c1 = tubeNodeColor(node + 1);
    tubeRect.d1 = tubeNodeColorDerivative(node + 1);
  }
  else if (tubeHaveColors == 2)
  {
    // Direction coloring: the position spline (model coordinates).
    tubeRect.c0 = tubeNodeModel(node);
    tubeRect.d0 = tubeNodeDerivativeModel(node);
    tubeRect.c1 = tubeNodeModel(node + 1);
    tubeRect.d1 = tubeNodeDerivativeModel(node + 1);
  }
}

// Fast path, for a sub-segment whose nearest depth reached, zNear, is in
// front of the near plane: the sub-segment lies in the convex hull of its
// control points with the largest radius rMax (Bernstein property, radii
// >= 0); bound the projections of those three spheres. A sphere (center p,
// radius r, in front of the eye) projects onto the plane z = zp inside the
// segment of its center's projections scaled by s in [s_min, s_max],
// thickened by r * s_max, with s = zp / z for z in [p.z - r, p.z + r].
void tubeHullRectangle(vec4 q0, vec4 q1, vec4 q2, float rMax, float zNear)
{
  float zp = zNear;
  vec2 u = vec2(1.0, 0.0);
  vec2 chord = cameraParallel != 0 ? q2.xy - q0.xy : q2.xy / q2.z - q0.xy / q0.z;
  if (length(chord) > 1e-20)
  {
    u = normalize(chord);
  }
  vec2 v = vec2(-u.y, u.x);
  vec2 lo = vec2(1e30);
  vec2 hi = vec2(-1e30);
  vec4 qs[3];
  qs[0] = q0;
  qs[1] = q1;
  qs[2] = q2;
  for (int i = 0; i < 3; ++i)
  {
    vec3 p = qs[i].xyz;
    float sMin = 1.0;
    float sMax = 1.0;
    if (cameraParallel == 0)
    {
      sMin = zp / (p.z - rMax);
      sMax = zp / (p.z + rMax);
    }
    vec2 uv = vec2(dot(p.xy, u), dot(p.xy, v));
    float pad = rMax * sMax;
    lo = min(lo, min(uv * sMin, uv * sMax) - vec2(pad));
    hi = max(hi, max(uv * sMin, uv * sMax) + vec2(pad));
  }
  // Beyond the far plane: nothing (rectangles beside the viewport are
  // clipped by the rasterizer at no fragment cost).
  vec4 farClip = VCDCMatrix * vec4(0.0, 0.0, zNear, 1.0);
  if (farClip.z <= farClip.w)
  {
    tubeRect.frame = vec4(u, zp, 1.0);
    tubeRect.span = vec4(lo, hi);
  }
}

// The corners of the sub-segment's oriented box (bit 0: +x, bit 1: +y, bit
// 2: +z), padded by a tiny fraction so that rounding never clips the
// surface, and their nearest depth zMax (view z is negative in front); false
// when the box is outside the view frustum (culled in clip space).
bool tubeBoxCorners(vec4 q0, vec4 q1, vec4 q2, out vec3 corner[8], out float zMax)
{
  SvBox box;
  svSubSegmentBox(q0, q1, q2, box);
  vec3 h = box.halfSize * 1.001 + vec3(1e-6 * length(box.halfSize));
  vec3 ax = box.axis0 * h.x;
  vec3 ay = box.axis1 * h.y;
  vec3 az = box.axis2 * h.z;
  vec3 c = box.center;
  bool allLeft = true;
  bool allRight = true;
  bool allBelow = true;
  bool allAbove = true;
  bool allFar = true;
  bool allNear = true;
  zMax = -1e30;
  for (int i = 0; i < 8; ++i)
  {
    vec3 p = c + ((i & 1) != 0 ? ax : -ax) + ((i & 2) != 0 ? ay : -ay) + ((i & 4) != 0 ? az : -az);
    corner[i] = p;
    vec4 clip = VCDCMatrix * vec4(p, 1.0);
    allLeft = allLeft && clip.x < -clip.w;
    allRight = allRight && clip.x > clip.w;
    allBelow = allBelow && clip.y < -clip.w;
    allAbove = allAbove && clip.y > clip.w;
    allFar = allFar && clip.z > clip.w;
    allNear = allNear && p.z > -tubeNearPlane;
    zMax = max(zMax, p.z);
  }
  return !(allLeft || allRight || allBelow || allAbove || allFar || allNear);
}

// The sub-segment may reach the near plane: bound its oriented box clipped
// to the near plane (rare: the camera is among the tubes).
void tubeClippedBoxRectangle(vec4 q0, vec4 q1, vec4 q2)
{
  vec3 corner[8];
  float zMax;
  if (!tubeBoxCorners(q0, q1, q2, corner, zMax))
  {
    return; // outside the frustum: nothing drawn
  }

  // The image plane the rectangle lies in: through the nearest corner, or
  // the near plane when the box crosses it.
  bool crossing = zMax > -tubeNearPlane;
  float zp = crossing ? -tubeNearPlane : zMax;

  // Orientation: the projected chord of the sub-segment (axis-aligned when
  // the box crosses the near plane, where the chord may be behind the eye).
  vec2 u = vec2(1.0, 0.0);
  if (!crossing)
  {
    vec2 chord = projectToPlane(q2.xyz, zp) - projectToPlane(q0.xyz, zp);
    if (length(chord) > 1e-20)
    {
      u = normalize(chord);
    }
  }
  vec2 v = vec2(-u.y, u.x);

  // Extents of the (near-clipped) box's projection along u and v.
  vec2 lo = vec2(1e30);
  vec2 hi = vec2(-1e30);
  for (int i = 0; i < 8; ++i)
  {
    if (corner[i].z <= -tubeNearPlane)
    {
      vec2 q = projectToPlane(corner[i], zp);
      vec2 uv = vec2(dot(q, u), dot(q, v));
      lo = min(lo, uv);
      hi = max(hi, uv);
    }
  }
  if (crossing)
  {
    // where the box's edges cross the near plane
    for (int i = 0; i < 8; ++i)
    {
      for (int bit = 1; bit <= 4; bit *= 2)
      {
        if ((i & bit) != 0)
        {
          continue;
        }
        vec3 e0 = corner[i];
        vec3 e1 = corner[i | bit];
        float d0 = e0.z + tubeNearPlane;
        float d1 = e1.z + tubeNearPlane;
        if ((d0 > 0.0) != (d1 > 0.0))
        {
          vec3 x = mix(e0, e1, d0 / (d0 - d1));
          vec2 q = projectToPlane(vec3(x.xy, -tubeNearPlane), zp);
          vec2 uv = vec2(dot(q, u), dot(q, v));
          lo = min(lo, uv);
          hi = max(hi, uv);
        }
      }
    }
  }

  tubeRect.frame = vec4(u, zp, 1.0);
  tubeRect.span = vec4(lo, hi);
}

void main()
{
  tubeRect.frame = vec4(0.0); // not drawn (unless set below)
  tubeRect.span = vec4(0.0);
  int perChunk = tubeChunkSegments * subSegments;
  int entry = gl_VertexID / perChunk;
  int local = gl_VertexID - entry * perChunk;
  uvec2 chunk = texelFetch(tubeChunkList, entry).xy;
  if (local >= int(chunk.y) * subSegments)
  {
    tubeRect.info = ivec4(0);
    tubeRect.q0 = tubeRect.q1 = tubeRect.q2 = vec4(0.0);
    tubeRect.c0 = tubeRect.d0 = tubeRect.c1 = tubeRect.d1 = vec4(0.0);
    return; // past the chunk's end: no rectangle
  }
  int node = int(chunk.x) + local / subSegments;
  int k = local - (local / subSegments) * subSegments;
  vec4 a;
  vec4 da;
  vec4 b;
  vec4 db;
  int flags;
  int tube;
  tubeViewSegment(node, a, da, b, db, flags, tube);
  vec4 q0;
  vec4 q1;
  vec4 q2;
  svSplitSegment(a, da, b, db, subSegments, k, q0, q1, q2);
  int mode = tubeStraightMode(a, da, b, db, k, q0, q1, q2);
  if (mode < 0)
  {
    return; // drawn by another sub-segment's rectangle
  }
  tubeSetCutPlanes(a, da, b, db, k, mode, flags);
  tubeRect.q0 = q0;
  tubeRect.q1 = q1;
  tubeRect.q2 = q2;
  tubeRect.info = ivec4(node, k, tube, flags | (mode << 2));
  tubeSetColors(node);

  float rMax = max(max(q0.w, q1.w), q2.w);
  float zNear = max(max(q0.z, q1.z), q2.z) + rMax; // nearest depth reached
  if (zNear < -tubeNearPlane)
  {
    tubeHullRectangle(q0, q1, q2, rMax, zNear);
    return;
  }
  tubeClippedBoxRectangle(q0, q1, q2);
}
