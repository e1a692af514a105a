// SPDX-License-Identifier: BSD-3-Clause
// Tessellated spline tubes (Salm §3.1 'Tessellation refinement and shading'),
// tessellation-control stage. One invocation per quad patch of the base mesh.
//
// Wall patches: corners (ring i, side j), (i, j + 1), (i + 1, j + 1), (i + 1, j)
// in that order; cap patches: two rim vertices of the first or last ring and
// the cap's center twice (a quad collapsed into a wedge of the disk).
//
// 1. Culling: caps where the tube goes on (no TUBE_START / TUBE_END flag) or
//    capping is off; patches whose four normals all face away from the eye
//    (back-patch culling; by more than tubeBackTolerance, as the normals of
//    the end rings leave out the small curvature term); patches outside the
//    view frustum.
// 2. Outer levels, per edge, from its two end vertices only and symmetrically
//    (so that the patches sharing the edge, also across segments, agree):
//    the maximum of
//    - the screen-space criterion: the edge's length in pixels divided by
//      tubeMaxEdgeLength, at most tubeMaxLevel;
//    - the silhouette criterion: the edge's length in view coordinates divided
//      by the clip w of its midpoint and scaled to pixels (Salm's isotropic
//      length, which keeps edges pointing at the eye refined and the
//      silhouettes free of notches), weighted by how close the edge is to
//      the silhouette: 1 when its end normals face opposite ways (it crosses
//      the silhouette), else the cube of the larger flatness of the angles
//      between the end normals and the rays to the eye (1 at the silhouette,
//      0 facing the eye; the cube keeps facing edges coarse), divided by
//      tubeSilhouetteEdgeLength, at most tubeMaxSilhouetteLevel;
//    and at least 1. Seam edges (the rim of a drawn cap) use the unweighted
//    isotropic length with tubeSilhouetteEdgeLength (Salm's finer seams).
// 3. Inner levels: the maximum of the two opposite outer levels.
// With tubeSides == 1 (the level of detail of thin tubes) the wall is one
// patch per segment whose rings the evaluation stage turns to the eye (the
// view-facing half of the cross-section, silhouette to silhouette): no
// back-patch culling (the rasterizer culls back faces), the ring levels are
// the half circumferences in pixels over tubeSideLength (at least 3
// intervals: the depth of the chords then stays within 0.21 radii of the
// circle's, more where the tube turns toward the eye: see
// tubeWallRingLevel), the caps' four times the circumferences (at least 8), and the level
// along makes the edges at most tubeMaxEdgeLength long on screen and keeps
// the chords within svThinSagittaPixels pixels of the curve on screen and within
// svThinDepthSagitta radii of it in space (so that the depth stays the tube's
// where the curve bends toward the eye); the ring levels depend on the nodes
// only, so neighbours agree. A patch may also span a run of `count` segments
// of one tube (count > 1, far away thin tubes): then its rings are the run's
// end nodes and the chords' bounds come from the curvature of the node chain
// (turning angle over chord length at each node, on screen and in space).
// The segment's nodes (view coordinates) and the patch's corner parameters go
// to the evaluation stage as per-patch outputs.

layout(vertices = 1) out;

in vec4 vertexVCVSOutput[];
in vec3 tubeNormalVCVSOutput[];
in float tubeTVSOutput[];
flat in ivec4 tubeInfoVSOutput[];
in vec4 tubeAxisVSOutput[];

patch out vec4 tubePatchP0;
patch out vec4 tubePatchM0;
patch out vec4 tubePatchP1;
patch out vec4 tubePatchM1;
patch out vec3 tubePatchF0;
patch out vec3 tubePatchF1;
patch out vec4 tubePatchParams; // s at u = 0 and u = 1, t at v = 0 and v = 1
patch out ivec4 tubePatchInfo;  // first node, segment, tube, flags | kind << 2 | count << 4

uniform mat4 VCDCMatrix;
uniform int cameraParallel;
uniform vec2 tubeViewport;             // pixels
uniform float tubeMaxEdgeLength;       // pixels
uniform float tubeSilhouetteEdgeLength; // pixels
uniform float tubeMaxLevel;
uniform float tubeMaxSilhouetteLevel;
uniform int tubeCaps;
uniform int tubeSides;        // 1: one patch around the segment
uniform float tubeSideLength; // pixels per ring edge in the single-patch mode

// The bounds of thin tubes: tubeMaxEdgeLength, svThinSagittaPixels,
// svThinDepthSagitta and svThinRunStraddle (vtkSplineTubeMathShared.glsl).
uniform vec4 tubeFrustum[6]; // view-coordinate planes, inside: dot >= 0

//SV::SplineTubeMath::Dec

//SV::TessellatedTubeCommon::Dec

vec3 tubeToEye(vec3 p)
{
  return cameraParallel != 0 ? vec3(0.0, 0.0, 1.0) : -p;
}

const float tubeBackTolerance = 0.2;

bool tubeFacesAway(vec3 n, vec3 p)
{
  return dot(n, normalize(tubeToEye(p))) < -tubeBackTolerance;
}

float tubePixelScale()
{
  return 0.5 * max(VCDCMatrix[0][0] * tubeViewport.x, VCDCMatrix[1][1] * tubeViewport.y);
}

// Length of edge (a, b) in pixels as if it faced the eye (Salm's silhouette
// measure); -1 when the edge reaches behind the eye.
float tubeIsotropicLength(vec3 a, vec3 b)
{
  float w = (VCDCMatrix * vec4(0.5 * (a + b), 1.0)).w;
  if (w <= 0.0)
  {
    return -1.0;
  }
  return length(a - b) / w * tubePixelScale();
}

float tubeEdgeLevel(vec3 a, vec3 b, vec3 na, vec3 nb)
{
  vec4 ca = VCDCMatrix * vec4(a, 1.0);
  vec4 cb = VCDCMatrix * vec4(b, 1.0);
  float iso = tubeIsotropicLength(a, b);
  if (ca.w <= 0.0 || cb.w <= 0.0 || iso < 0.0)
  {
    return max(tubeMaxLevel, tubeMaxSilhouetteLevel);
  }
  vec2 halfViewport = 0.5 * tubeViewport;
  float screen = length(ca.xy / ca.w * halfViewport - cb.xy / cb.w * halfViewport);
  float level = min(screen / tubeMaxEdgeLength, tubeMaxLevel);
  float facingA = dot(na, normalize(tubeToEye(a)));
  float facingB = dot(nb, normalize(tubeToEye(b)));
  float flatness = max(1.0 - abs(facingA), 1.0 - abs(facingB));
  float weight = facingA * facingB <= 0.0 ? 1.0 : flatness * flatness * flatness;
  float silhouette = min(weight * iso / tubeSilhouetteEdgeLength, tubeMaxSilhouetteLevel);
  return max(1.0, max(level, silhouette));
}

float tubeSeamLevel(vec3 a, vec3 b)
{
  float iso = tubeIsotropicLength(a, b);
  if (iso < 0.0)
  {
    return tubeMaxSilhouetteLevel;
  }
  return max(1.0, min(iso / tubeSilhouetteEdgeLength, tubeMaxSilhouetteLevel));
}

void tubeCull()
{
  gl_TessLevelOuter[0] = 0.0;
  gl_TessLevelOuter[1] = 0.0;
  gl_TessLevelOuter[2] = 0.0;
  gl_TessLevelOuter[3] = 0.0;
  gl_TessLevelInner[0] = 0.0;
  gl_TessLevelInner[1] = 0.0;
}

// The levels of a patch drawn as one ring of `level` edges (a cap or a
// seam): `level` along the first outer edge and the first inner direction,
// 1 elsewhere.
void tubeSetRingLevels(float level)
{
  gl_TessLevelOuter[0] = 1.0;
  gl_TessLevelOuter[1] = level;
  gl_TessLevelOuter[2] = 1.0;
  gl_TessLevelOuter[3] = 1.0;
  gl_TessLevelInner[0] = level;
  gl_TessLevelInner[1] = 1.0;
}

// The patch's segment (Hermite form and frames) for the evaluation stage.
void tubeSetPatchSegment(TubeSegment seg)
{
  tubePatchP0 = seg.p0;
  tubePatchM0 = seg.m0;
  tubePatchP1 = seg.p1;
  tubePatchM1 = seg.m1;
  tubePatchF0 = seg.f0;
  tubePatchF1 = seg.f1;
}

bool tubeOutsideFrustum(vec3 a, vec3 b, vec3 c, vec3 d)
{
  float margin = 0.5 * max(length(a - c), length(b - d));
  for (int i = 0; i < 6; ++i)
  {
    vec4 p = tubeFrustum[i];
    if (dot(p.xyz, a) + p.w < -margin && dot(p.xyz, b) + p.w < -margin &&
      dot(p.xyz, c) + p.w < -margin && dot(p.xyz, d) + p.w < -margin)
    {
      return true;
    }
  }
  return false;
}

// Intervals of the ring around node center p (xyz, radius w) in the
// single-patch mode: `turn` of the circumference (0.5: the view-facing half
// ring of a wall; 1: a cap), at least `least` (svThinRingLevel).
float tubeRingLevel(vec4 p, float turn, float least)
{
  float w = (VCDCMatrix * vec4(p.xyz, 1.0)).w;
  return svThinRingLevel(p.w, w, tubePixelScale(), tubeSideLength, turn, least);
}

// Intervals of the view-facing half ring of a wall at node center p with
// the curve's derivative d there (more where the tube turns toward the eye:
// svThinWallLeast).
float tubeWallRingLevel(vec4 p, vec3 d)
{
  return tubeRingLevel(p, 0.5, svThinWallLeast(d, tubeToEye(p.xyz)));
}

float tubeScreenLength(vec3 a, vec3 b)
{
  vec4 ca = VCDCMatrix * vec4(a, 1.0);
  vec4 cb = VCDCMatrix * vec4(b, 1.0);
  if (ca.w <= 0.0 || cb.w <= 0.0)
  {
    return 1e30;
  }
  vec2 halfViewport = 0.5 * tubeViewport;
  return length(ca.xy / ca.w * halfViewport - cb.xy / cb.w * halfViewport);
}

// Level along a run of `count` segments from node `first` (see above).
float tubeRunLevel(int first, int count)
{
  vec2 halfViewport = 0.5 * tubeViewport;
  float total = 0.0;     // pixels
  float total3 = 0.0;    // view units
  float shortest = 1e30; // longest admissible edge, pixels
  float shortest3 = 1e30; // likewise in view units, for the depth
  vec2 previous = vec2(0.0);
  vec2 direction = vec2(0.0);
  float previousLength = 0.0;
  vec3 previous3 = vec3(0.0);
  vec3 direction3 = vec3(0.0);
  float previousLength3 = 0.0;
  for (int k = 0; k <= count; ++k)
  {
    vec4 node = tubeNodePosition(first + k);
    vec4 c = VCDCMatrix * vec4(node.xyz, 1.0);
    if (c.w <= 0.0)
    {
      return 64.0;
    }
    vec2 p = c.xy / c.w * halfViewport;
    if (k > 0)
    {
      vec2 d = p - previous;
      float len = length(d);
      total += len;
      float curvature = k > 1 ? svThinChainCurvature(vec3(d, 0.0), len, vec3(direction, 0.0),
                                  previousLength) : 0.0;
      if (curvature > 0.0)
      {
        shortest = min(shortest, sqrt(8.0 * svThinSagittaPixels / curvature));
      }
      direction = d;
      previousLength = len;
      vec3 d3 = node.xyz - previous3;
      float len3 = length(d3);
      total3 += len3;
      float curvature3 = k > 1 ? svThinChainCurvature(d3, len3, direction3, previousLength3) : 0.0;
      if (curvature3 > 0.0)
      {
        shortest3 =
          min(shortest3, sqrt(8.0 * svThinRunStraddle * svThinDepthSagitta * node.w / curvature3));
      }
      direction3 = d3;
      previousLength3 = len3;
    }
    previous = p;
    previous3 = node.xyz;
  }
  return clamp(
    ceil(max(max(total / tubeMaxEdgeLength, total / shortest), total3 / shortest3)), 1.0, 64.0);
}

void tubeSinglePatch(ivec4 info, int flags, int kind)
{
  TubeSegment seg = tubeLoadSegment(info.x);
  int count = info.w >> 4;
  float tA = tubeTVSOutput[0];
  float tD = tubeTVSOutput[3];
  vec4 pA;
  vec4 pD;
  float screen = 0.0;
  if (count > 1)
  {
    // A run of segments: its end nodes, and its chords on screen.
    pA = tubeNodePosition(info.x);
    pD = tubeNodePosition(info.x + count);
    tA = 0.0;
    tD = float(count);
  }
  else
  {
    pA = svHermite(seg.p0, seg.m0, seg.p1, seg.m1, tA);
    pD = svHermite(seg.p0, seg.m0, seg.p1, seg.m1, tD);
    screen = tubeScreenLength(pA.xyz, pD.xyz);
  }
  if (kind != 0)
  {
    bool wanted = tubeCaps != 0 && (flags & kind) != 0;
    vec4 p = pA;
    vec3 n = normalize(kind == 1 ? -seg.m0.xyz : seg.m1.xyz);
    if (!wanted || dot(n, tubeToEye(p.xyz)) < -p.w)
    {
      tubeCull();
      return;
    }
    // Caps are seen face-on, where a coarse polygon shows: edges of a
    // quarter of tubeSideLength, at least 8.
    float ring = tubeRingLevel(p, 4.0, 8.0);
    tubeSetRingLevels(ring);
  }
  else
  {
    vec3 dA = count > 1 ? tubeNodeDerivative(info.x).xyz
                        : svHermiteDerivative(seg.p0, seg.m0, seg.p1, seg.m1, tA).xyz;
    vec3 dD = count > 1 ? tubeNodeDerivative(info.x + count).xyz
                        : svHermiteDerivative(seg.p0, seg.m0, seg.p1, seg.m1, tD).xyz;
    float ring0 = tubeWallRingLevel(pA, dA);
    float ring1 = tubeWallRingLevel(pD, dD);
    float along = 1.0;
    if (count > 1)
    {
      along = tubeRunLevel(info.x, count);
    }
    else
    {
      // The cubic's deviation from its chord between tA and tD.
      float sagitta = svThinSegmentSagitta(seg.p0, seg.m0, seg.p1, seg.m1, tD - tA);
      vec4 middle = svHermite(seg.p0, seg.m0, seg.p1, seg.m1, 0.5 * (tA + tD));
      float w = (VCDCMatrix * vec4(middle.xyz, 1.0)).w;
      along = clamp(max(min(screen / tubeMaxEdgeLength, tubeMaxLevel),
                      svThinSagittaLevel(sagitta, w, min(min(pA.w, pD.w), middle.w), tubePixelScale())),
        1.0, 64.0);
    }
    gl_TessLevelOuter[0] = along;
    gl_TessLevelOuter[1] = ring0;
    gl_TessLevelOuter[2] = along;
    gl_TessLevelOuter[3] = ring1;
    gl_TessLevelInner[0] = max(ring0, ring1);
    gl_TessLevelInner[1] = along;
  }
  tubeSetPatchSegment(seg);
  tubePatchParams = vec4(0.0, 1.0, tA, tD);
  tubePatchInfo = ivec4(info.x, info.y, info.z, flags | (kind << 2) | (count << 4));
}

void main()
{
  if (tubeSides == 1)
  {
    ivec4 info1 = tubeInfoVSOutput[0];
    tubeSinglePatch(info1, info1.w & 3, (tubeInfoVSOutput[2].w >> 2) & 3);
    return;
  }
  vec3 a = vertexVCVSOutput[0].xyz;
  vec3 b = vertexVCVSOutput[1].xyz;
  vec3 c = vertexVCVSOutput[2].xyz;
  vec3 d = vertexVCVSOutput[3].xyz;
  ivec4 info = tubeInfoVSOutput[0];
  int flags = info.w & 3;
  int kind = (tubeInfoVSOutput[2].w >> 2) & 3; // the cap's center, or 0

  if (kind != 0)
  {
    // Caps: only at the tube's ends, and only when turned to the eye.
    bool wanted = tubeCaps != 0 && (flags & kind) != 0;
    vec3 n = tubeNormalVCVSOutput[2];
    if (!wanted ||
      (dot(n, tubeToEye(a)) < 0.0 && dot(n, tubeToEye(b)) < 0.0 && dot(n, tubeToEye(c)) < 0.0))
    {
      tubeCull();
      return;
    }
  }
  else if (tubeFacesAway(tubeNormalVCVSOutput[0], a) && tubeFacesAway(tubeNormalVCVSOutput[1], b) &&
    tubeFacesAway(tubeNormalVCVSOutput[2], c) && tubeFacesAway(tubeNormalVCVSOutput[3], d))
  {
    tubeCull(); // back-patch culling
    return;
  }
  if (tubeOutsideFrustum(a, b, c, d))
  {
    tubeCull();
    return;
  }

  if (kind != 0)
  {
    float seam = tubeSeamLevel(a, b);
    tubeSetRingLevels(seam);
  }
  else
  {
    float tA = tubeTVSOutput[0];
    float tD = tubeTVSOutput[3];
    bool startSeam = tubeCaps != 0 && tA == 0.0 && (flags & 1) != 0;
    bool endSeam = tubeCaps != 0 && tD == 1.0 && (flags & 2) != 0;
    vec3 na = tubeNormalVCVSOutput[0];
    vec3 nb = tubeNormalVCVSOutput[1];
    vec3 nc = tubeNormalVCVSOutput[2];
    vec3 nd = tubeNormalVCVSOutput[3];
    float o0 = tubeEdgeLevel(a, d, na, nd);
    float o1 = startSeam ? tubeSeamLevel(a, b) : tubeEdgeLevel(a, b, na, nb);
    float o2 = tubeEdgeLevel(b, c, nb, nc);
    float o3 = endSeam ? tubeSeamLevel(d, c) : tubeEdgeLevel(d, c, nd, nc);
    gl_TessLevelOuter[0] = o0;
    gl_TessLevelOuter[1] = o1;
    gl_TessLevelOuter[2] = o2;
    gl_TessLevelOuter[3] = o3;
    gl_TessLevelInner[0] = max(o1, o3);
    gl_TessLevelInner[1] = max(o0, o2);
  }

  TubeSegment seg = tubeLoadSegment(info.x);
  tubeSetPatchSegment(seg);
  tubePatchParams =
    vec4(tubeAxisVSOutput[0].w, tubeAxisVSOutput[1].w, tubeTVSOutput[0], tubeTVSOutput[3]);
  tubePatchInfo = ivec4(info.x, info.y, info.z, flags | (kind << 2) | (1 << 4));
}
