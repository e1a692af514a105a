//VTK::System::Dec

// Tessellated spline tubes (Salm §3.1), thin tubes without the tessellator.
//
// A tube a few pixels wide is drawn as the view-facing half of its wall
// (tubeHalfRingVertex, the surface the evaluation stage's single-patch mode
// makes), but from a vertex stage alone: on a software rasterizer (Mesa
// llvmpipe) the control stage, the fixed-function tessellator and its
// per-patch bookkeeping run on the application's thread and cost more than
// the vertex shading itself (see vtkTessellatedTubeMapper.h). The levels the
// control stage would compute per view (rings along the run, intervals per
// ring) come from the mapper's per-view classification on the CPU (the same
// bounds through the same functions: ThinChunkLevels in
// vtkTessellatedTubeMapper.cxx), which bins the runs by
// them: one instanced draw per (rings, intervals) of an indexed triangle
// mesh, no vertex attributes.
//
// Instance gl_InstanceID is the run at entry 2 x (tubeListOffset +
// gl_InstanceID) of the instance list: (first segment, count | L0 << 8 |
// L1 << 16), count segments of one tube, L0 and L1 the intervals of its first
// and last ring. Vertex gl_VertexID = ring x tubeSides + j: ring 0 .. n
// (n = tubeRings - 1 rings apart, evenly in the run's curve parameter
// t in [0, count]; from tubeMirrorRing on numbered from the end ring, for the
// mesh rows that mirror the start's: see vtkTessellatedTubeMapper's
// BuildBaseMeshes), j = 0 .. L (L = tubeSides - 1 intervals, at least L0 and
// L1). The end rings take their own intervals (vertex j moves to the
// nearest vertex of the L0 or L1 sampling, some triangles degenerate) so that
// neighbouring runs, which share them, meet without cracks.
//
// tubeCapDraw != 0: the caps of thin runs instead (without the tessellator as
// well: llvmpipe's evaluation stage grows its output buffer patch by patch,
// and the heap it grows is trimmed and mapped in again frame after frame).
// Instance gl_InstanceID is the cap at entry 2 x (tubeListOffset +
// gl_InstanceID): (segment, kind), kind 1 the start and 2 the end cap, listed
// only when turned to the eye (as the control stage culls them). The cap is
// the disk's inscribed polygon of tubeCapSides vertices (a fan from vertex
// 0), the control stage's level for caps of thin tubes, two of them the
// silhouette points where the wall's half rings end.

uniform usamplerBuffer tubeInstances;
uniform int tubeListOffset;
uniform int tubeRings; // n + 1
uniform int tubeSides; // L + 1
uniform mat4 VCDCMatrix;
uniform int cameraParallel;
uniform int tubeCapDraw;
const int tubeCapSides = 8; // vtkTessellatedTubeMapper's ThinCapSides
const int tubeMirrorRing = 65; // vtkTessellatedTubeMapper's ThinMirrorRing

out vec4 vertexVCVSOutput;       // position, view coordinates
out vec3 tubeNormalVCVSOutput;   // normal, view coordinates
out float tubeTVSOutput;         // curve parameter in the run
flat out ivec4 tubeInfoVSOutput; // first node, segment, tube, count << 4
out vec4 tubeColorVSOutput;

//VTK::SplineTubeMath::Dec

//VTK::TessellatedTubeCommon::Dec

// Vertex gl_VertexID of a thin tube's cap (see above): on the circle of the
// cap's node, counter-clockwise around the curve's direction (the start caps
// are thus wound clockwise seen from outside, as the evaluation stage's),
// half of them on the arc between the silhouette points that faces the eye
// and half on the other.
void tubeThinCap()
{
  int entry = tubeListOffset + 2 * gl_InstanceID;
  int segment = int(texelFetch(tubeInstances, entry).x);
  int kind = int(texelFetch(tubeInstances, entry + 1).x);
  uvec2 sd = texelFetch(tubeSegments, segment).xy;
  int first = int(sd.x & 0x3FFFFFFFu);
  float t = kind == 1 ? 0.0 : 1.0;
  int node = first + int(t);
  vec4 c = tubeNodePosition(node);
  vec3 d = tubeNodeDerivative(node).xyz;
  vec3 tangent = normalize(d);
  // The same frame as the wall's end ring (tubeHalfRingVertex).
  vec3 front;
  float halfSpan;
  tubeViewFacingFrame(c, tangent, d, first, t, cameraParallel != 0, front, halfSpan);
  int halfSides = tubeCapSides / 2;
  int j = gl_VertexID;
  float phi = j <= halfSides
    ? -halfSpan + 2.0 * halfSpan * float(j) / float(halfSides)
    : halfSpan + (6.283185307179586 - 2.0 * halfSpan) * float(j - halfSides) / float(halfSides);
  vec3 position = c.xyz + c.w * svTubeOffset(front, tangent, phi);

  vertexVCVSOutput = vec4(position, 1.0);
  // (turned to the eye: the thin program's fragment stage does not flip
  // normals of back faces)
  vec3 toEye = cameraParallel != 0 ? vec3(0.0, 0.0, 1.0) : -c.xyz;
  tubeNormalVCVSOutput = dot(tangent, toEye) < 0.0 ? -tangent : tangent;
  tubeTVSOutput = t;
  tubeInfoVSOutput = ivec4(first, segment, int(sd.y), (kind << 2) | (1 << 4));
  tubeColorVSOutput = tubeColorAt(first, t);
  gl_Position = VCDCMatrix * vec4(position, 1.0);
}

void main()
{
  if (tubeCapDraw != 0)
  {
    tubeThinCap();
    return;
  }
  int entry = tubeListOffset + 2 * gl_InstanceID;
  int segment = int(texelFetch(tubeInstances, entry).x);
  uint levels = texelFetch(tubeInstances, entry + 1).x;
  int count = int(levels & 0xFFu);
  int intervals = tubeRings - 1;
  int L = tubeSides - 1;
  int ring = gl_VertexID / tubeSides;
  int j = gl_VertexID - ring * tubeSides;
  if (ring >= tubeMirrorRing)
  {
    ring = intervals - (ring - tubeMirrorRing); // numbered from the run's end
  }
  int level = L;
  if (ring == 0 || ring == intervals)
  {
    level = int(ring == 0 ? (levels >> 8u) & 0xFFu : (levels >> 16u) & 0xFFu);
    j = (2 * j * level + L) / (2 * L); // the nearest vertex of the end ring's sampling
  }
  float s = float(j) / float(level);
  float tGlobal = float(count) * (float(ring) / float(intervals));
  int k = clamp(int(ceil(tGlobal)) - 1, 0, count - 1);
  float t = tGlobal - float(k);

  uvec2 sd = texelFetch(tubeSegments, segment).xy;
  int first = int(sd.x & 0x3FFFFFFFu);
  int node = first + k;
  vec4 p0 = tubeNodePosition(node);
  vec4 m0 = tubeNodeDerivative(node);
  vec4 p1 = tubeNodePosition(node + 1);
  vec4 m1 = tubeNodeDerivative(node + 1);
  float chord =
    count > 1 && ring > 0 && ring < intervals ? float(count) / float(intervals) : 0.0;
  vec3 position;
  vec3 normal;
  tubeHalfRingVertex(
    p0, m0, p1, m1, node, t, s, float(level), chord, cameraParallel != 0, position, normal);

  vertexVCVSOutput = vec4(position, 1.0);
  tubeNormalVCVSOutput = normal;
  tubeTVSOutput = tGlobal;
  tubeInfoVSOutput = ivec4(first, segment, int(sd.y), count << 4);
  tubeColorVSOutput = tubeColorAt(node, t);
  gl_Position = VCDCMatrix * vec4(position, 1.0);
}
