// SPDX-License-Identifier: BSD-3-Clause
//VTK::System::Dec

// Tessellated spline tubes (Salm §3.1), thin tubes without the tessellator.
//
// A tube a few pixels wide is drawn as the view-facing half of its wall
// with three vertices per ring: the exact silhouette points of the ring's
// circle seen from the eye and the point nearest the eye between them
// (tubeViewFacingFrame, as the evaluation stage's half rings). The
// fragment stage (vtkTessellatedTubeThinFS.glsl) finds the tube's front
// surface along each pixel's ray from there (the local cylinder of the
// interpolated ring center, radius and tangent: exact depth and normal). A
// half ring of 3-5 intervals whose polygon had to carry the depth (within
// 0.21 radii for 3) cost 2-3 times the triangles and vertices, and on a
// software rasterizer (Mesa llvmpipe) their shading, set-up and binning on
// the application's thread are the frame; two vertices per ring (the
// silhouettes only) lose the half ellipse a ring turned to the eye shows
// beyond them (TestTessellatedTubeReference's coverage). From a vertex stage
// alone: the control stage, the fixed-function tessellator and its
// per-patch bookkeeping run on the application's thread as well and cost
// more than the vertex shading itself (see vtkTessellatedTubeMapper.h). The
// rings along a run come from the mapper's per-view classification on the
// CPU (the level the control stage would compute, through the same
// functions: ThinChunkLevels in vtkTessellatedTubeMapper.cxx), which bins
// the runs by them: one instanced draw per ring count of an indexed
// triangle mesh, no vertex attributes.
//
// Instance gl_InstanceID is the run at entry 2 x (tubeListOffset +
// gl_InstanceID) of the instance list: (first segment, count | ends << 8),
// count segments of one tube, ends bit 0 (1) when the run starts its tube
// and bit 1 (2) when it ends it. Vertex gl_VertexID = tubeRibbonSides x ring
// + j: ring 0 .. n (n = tubeRings - 1 rings apart, evenly in the run's curve
// parameter t in [0, count]; from tubeMirrorRing on numbered from the end
// ring, for the mesh rows that mirror the start's: see
// vtkTessellatedTubeMapper's BuildBaseMeshes), j = 0 .. 2 from one
// silhouette point to the other. Neighbouring runs share their end rings and
// meet without cracks.
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
uniform mat4 VCDCMatrix;
uniform int cameraParallel;
uniform int tubeCapDraw;
const int tubeCapSides = 8; // vtkTessellatedTubeMapper's ThinCapSides
const int tubeMirrorRing = 65; // vtkTessellatedTubeMapper's ThinMirrorRing
const int tubeRibbonSides = 3; // vtkTessellatedTubeMapper's ThinRibbonSides

out vec4 vertexVCVSOutput; // position, view coordinates
// Walls: the ring's center and radius, and the curve's derivative by t
// (position and radius). Caps: radius 0, and the normal.
out vec4 tubeAxisVCVSOutput;
out vec4 tubeNormalVCVSOutput;
out float tubeTVSOutput;         // curve parameter in the run
flat out ivec4 tubeInfoVSOutput; // first node, first node, tube, count << 4 | ends (caps: kind << 2)
out vec4 tubeColorVSOutput;

//SV::SplineTubeMath::Dec

//SV::TessellatedTubeCommon::Dec

// Vertex gl_VertexID of a thin tube's cap (see above): on the circle of the
// cap's node, counter-clockwise around the curve's direction (the start caps
// are thus wound clockwise seen from outside, as the evaluation stage's),
// half of them on the arc between the silhouette points that faces the eye
// and half on the other.
void tubeThinCap()
{
  int entry = tubeListOffset + 2 * gl_InstanceID;
  int first = int(texelFetch(tubeInstances, entry).x);
  int kind = int(texelFetch(tubeInstances, entry + 1).x);
  float t = kind == 1 ? 0.0 : 1.0;
  int node = first + int(t);
  vec4 c = tubeNodePosition(node);
  vec3 d = tubeNodeDerivative(node).xyz;
  vec3 tangent = normalize(d);
  // The same frame as the wall's end ring (tubeViewFacingRing).
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
  tubeAxisVCVSOutput = vec4(0.0);
  tubeNormalVCVSOutput = vec4(dot(tangent, toEye) < 0.0 ? -tangent : tangent, 0.0);
  tubeTVSOutput = t;
  tubeInfoVSOutput = ivec4(first, first, tubeOfNode(first), (kind << 2) | (1 << 4));
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
  int first = int(texelFetch(tubeInstances, entry).x);
  uint run = texelFetch(tubeInstances, entry + 1).x;
  int count = int(run & 0xFFu);
  int intervals = tubeRings - 1;
  int ring = gl_VertexID / tubeRibbonSides;
  int j = gl_VertexID - tubeRibbonSides * ring;
  if (ring >= tubeMirrorRing)
  {
    ring = intervals - (ring - tubeMirrorRing); // numbered from the run's end
  }
  float tGlobal = float(count) * (float(ring) / float(intervals));
  int k = clamp(int(ceil(tGlobal)) - 1, 0, count - 1);
  float t = tGlobal - float(k);

  int node = first + k;
  vec4 p0 = tubeNodePosition(node);
  vec4 m0 = tubeNodeDerivative(node);
  vec4 p1 = tubeNodePosition(node + 1);
  vec4 m1 = tubeNodeDerivative(node + 1);
  float chord =
    count > 1 && ring > 0 && ring < intervals ? float(count) / float(intervals) : 0.0;
  vec4 d;
  vec4 dd;
  vec3 tangent;
  vec3 front;
  float halfSpan;
  vec4 c = tubeViewFacingRing(
    p0, m0, p1, m1, node, t, chord, cameraParallel != 0, d, dd, tangent, front, halfSpan);
  float phi = float(j - 1) * halfSpan;
  vec3 position = c.xyz + c.w * svTubeOffset(front, tangent, phi);

  vertexVCVSOutput = vec4(position, 1.0);
  tubeAxisVCVSOutput = c;
  tubeNormalVCVSOutput = d;
  tubeTVSOutput = tGlobal;
  tubeInfoVSOutput = ivec4(first, first, tubeOfNode(first), (count << 4) | int((run >> 8u) & 3u));
  tubeColorVSOutput = tubeColorAt(node, t);
  gl_Position = VCDCMatrix * vec4(position, 1.0);
}
