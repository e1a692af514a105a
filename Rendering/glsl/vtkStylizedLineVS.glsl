// SPDX-License-Identifier: BSD-3-Clause
//VTK::System::Dec

// Stylized lines (Stoll, Gumhold and Seidel 2005), vertex stage.
//
// No vertex attributes: every vertex reads its line vertex (position,
// radius, tangent, ...) from the buffers by index. Three kinds of draws share
// this stage (lineMode):
//  0  silhouette-quad splatting (§4.1): triangle strips of two vertices per
//     line vertex (gl_VertexID = 2 x vertex + side), one strip per polyline
//     piece; each vertex is moved to its silhouette point of Eq. 6 (or Eq. 8)
//     and carries the frame (x, y) of Eq. 4-5 and tex0 = +-f (tex1 = +-1)
//     for the normal of Eq. 10, widened by the halo (§4.2);
//  1  the fix-up (§4.4): for the segments the CPU found looking along the
//     view (instance = entry of lineSegments), a cylinder of lineSides sides
//     between the two profile circles, their phi = 0 directions synchronized
//     along t_i x t_i+1 (Stoll §3); the normal is the profile's radial
//     direction (Stoll: "the normal in the plane of the circle");
//  2  flat end caps (instance = 2 x polyline + end, or the entry of lineCaps
//     holding that with lineCapList), culled when turned away from the eye;
//  3  the fix-up's joints: a sphere of the line's radius at the inner
//     vertices of the fixed-up runs (instance = entry of lineJoints), ray cast in
//     the fragment stage on a view-facing square that bounds it. They fill
//     the wedges between the cylinders and close the cylinders' open ends
//     where the neighbouring quads cover only half of the profile disk; lit
//     with the normal of the vertex's cylinder (the sphere's normal made
//     orthogonal to the tangent), they continue the line's wall.
// Mode 2 draws its halo in a second draw (lineHaloPass) with the radius
// widened (modes 1 and 3 could, but the mapper does not draw them: see
// vtkStylizedLineMapper::RenderPieceDraw).

uniform samplerBuffer lineNodes;       // per vertex: (x, y, z, radius), shifted model coordinates
uniform float lineConstantRadius;      // not negative: every radius, and lineNodes holds (x, y, z)
uniform isamplerBuffer lineTangents;   // per vertex: unit tangent, octahedral, 2 x int16
uniform usamplerBuffer lineTubeStarts; // per polyline: its first vertex (one entry more: the end)
uniform usamplerBuffer lineSegments;   // fix-up: first vertex of each segment drawn as a cylinder
uniform usamplerBuffer lineJoints;     // fix-up: the vertices that get a joint sphere
uniform usamplerBuffer lineCaps;       // caps drawn (lineCapList): 2 x polyline + end
uniform int lineCapList;
uniform int lineNumberOfTubes;
uniform mat4 tubeMCVC;        // shifted model to view
uniform float tubeRadiusScale; // model to view scale of radii
uniform vec2 tubeMinimumRadius; // the narrowest drawn radius: x + y (view distance)
uniform mat4 VCDCMatrix;
uniform int cameraParallel;
uniform int lineMode;
uniform int lineHaloPass;
uniform float lineWiden;      // 1 + halo width
uniform int lineExact;        // Eq. 6 (1) or Eq. 8 (0)
uniform int lineSides;        // sides of the fix-up cylinders and the caps
uniform float lineDepthCap;   // largest depth-correction distance, in radii

#ifdef LINE_COLORS
uniform samplerBuffer lineColors; // per vertex: RGBA8
out vec4 lineColorVSOutput;
#elif defined(LINE_DIRECTION_COLORS)
out vec4 lineColorVSOutput; // the unit tangent (model coordinates), normalized per fragment
#endif
#ifdef LINE_TEXTURE
uniform samplerBuffer lineTexCoords; // per vertex: coordinate along the line, orientation
uniform isamplerBuffer lineFrames;   // per vertex: body-fixed frame vector, octahedral
out vec2 lineUVSOutput;
out vec3 lineFrameVSOutput;
#endif

out vec4 vertexVCVSOutput;       // position, view coordinates
out vec3 lineXVSOutput;          // frame x (toward the eye; modes 1, 2: the normal)
out vec3 lineYVSOutput;          // frame y (silhouette direction)
out vec2 lineTexVSOutput;        // tex0 = +-f (widened), tex1 = +-1 (widened)
out vec3 lineFrontVSOutput;      // depth correction: axis to front surface along the view ray
out float lineRadiusVSOutput;    // radius, view units
flat out ivec2 lineInfoVSOutput; // polyline (picking), kind | halo << 2
flat out vec4 lineSphereVSOutput; // mode 3: the sphere (center, view coordinates; radius)
uniform int lineSingleLayer;      // translucent: each line one layer (the cuts below)
flat out vec4 lineCut0VSOutput;   // mode 0, translucent: the planes of the polyline's ends,
flat out vec4 lineCut1VSOutput;   // dot(cut, (p, 1)) >= 0 inside
out vec2 lineEndSpanVSOutput;     // 0 at the polyline's first (x) or last (y) vertex, else 1

//SV::SplineTubeMath::Dec

// Position and radius of a vertex (shifted model coordinates).
vec4 lineNode(int node)
{
  vec4 n = texelFetch(lineNodes, node);
  return lineConstantRadius < 0.0 ? n : vec4(n.xyz, lineConstantRadius);
}

//SV::StylizedLineMath::Dec

vec3 lineViewTangent(int node)
{
  vec2 e = vec2(texelFetch(lineTangents, node).xy) / 32767.0;
  return normalize(mat3(tubeMCVC) * svOctDecode(e));
}

// The polyline of a vertex: binary search in lineTubeStarts (picking, translucency).
int lineTubeOf(int node)
{
  int lo = 0;
  int hi = lineNumberOfTubes;
  while (hi - lo > 1)
  {
    int mid = (lo + hi) / 2;
    if (int(texelFetch(lineTubeStarts, mid).x) <= node)
    {
      lo = mid;
    }
    else
    {
      hi = mid;
    }
  }
  return lo;
}

void lineAttributes(int node)
{
#ifdef LINE_COLORS
  lineColorVSOutput = texelFetch(lineColors, node);
#elif defined(LINE_DIRECTION_COLORS)
  lineColorVSOutput = vec4(svOctDecode(vec2(texelFetch(lineTangents, node).xy) / 32767.0), 1.0);
#endif
#ifdef LINE_TEXTURE
  lineUVSOutput = texelFetch(lineTexCoords, node).xy;
  vec2 f = vec2(texelFetch(lineFrames, node).xy) / 32767.0;
  lineFrameVSOutput = mat3(tubeMCVC) * svOctDecode(f);
#endif
}

void lineCulled()
{
  gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
  vertexVCVSOutput = vec4(0.0, 0.0, -1.0, 1.0);
  lineXVSOutput = vec3(0.0, 0.0, 1.0);
  lineYVSOutput = vec3(1.0, 0.0, 0.0);
  lineTexVSOutput = vec2(0.0);
  lineFrontVSOutput = vec3(0.0);
  lineRadiusVSOutput = 0.0;
  lineInfoVSOutput = ivec2(0);
  lineSphereVSOutput = vec4(0.0);
  lineCut0VSOutput = vec4(0.0, 0.0, 0.0, 1.0);
  lineCut1VSOutput = vec4(0.0, 0.0, 0.0, 1.0);
  lineEndSpanVSOutput = vec2(1.0);
}

// The planes normal to the line at the ends of the polyline of `node`,
// facing inward (every vertex of the polyline makes the same two).
void lineEndCuts(int node)
{
  int polyline = lineTubeOf(node);
  int first = int(texelFetch(lineTubeStarts, polyline).x);
  int last = int(texelFetch(lineTubeStarts, polyline + 1).x) - 1;
  vec3 c0 = (tubeMCVC * vec4(lineNode(first).xyz, 1.0)).xyz;
  vec3 c1 = (tubeMCVC * vec4(lineNode(last).xyz, 1.0)).xyz;
  vec3 t0 = lineViewTangent(first);
  vec3 t1 = lineViewTangent(last);
  lineCut0VSOutput = vec4(t0, -dot(t0, c0));
  lineCut1VSOutput = vec4(-t1, dot(t1, c1));
  lineEndSpanVSOutput = vec2(node == first ? 0.0 : 1.0, node == last ? 0.0 : 1.0);
}

void main()
{
  int node;
  int kind = lineMode;
  int tube = 0;
  vec3 position;
  lineSphereVSOutput = vec4(0.0);
  lineCut0VSOutput = vec4(0.0, 0.0, 0.0, 1.0);
  lineCut1VSOutput = vec4(0.0, 0.0, 0.0, 1.0);
  lineEndSpanVSOutput = vec2(1.0);
  if (lineMode == 0)
  {
    node = gl_VertexID >> 1;
    float side = (gl_VertexID & 1) != 0 ? 1.0 : -1.0;
    vec4 pr = lineNode(node);
    vec3 p = (tubeMCVC * vec4(pr.xyz, 1.0)).xyz;
    float r = svDrawnRadius(pr.w * tubeRadiusScale, p.z, tubeMinimumRadius);
    vec3 t = lineViewTangent(node);
    vec3 u = cameraParallel != 0 ? vec3(0.0, 0.0, -1.0) : p;
    vec3 x;
    vec3 y;
    float uPerp;
    slFrame(u, t, x, y, uPerp);
    float f;
    vec3 e = slExtrusion(x, y, r, uPerp, cameraParallel != 0, lineExact != 0, side, lineWiden, f);
    position = p + e;
    lineXVSOutput = x;
    lineYVSOutput = y;
    lineTexVSOutput = vec2(side * f * lineWiden, side * lineWiden);
    vec3 dir = cameraParallel != 0 ? vec3(0.0, 0.0, -1.0) : normalize(p);
    lineFrontVSOutput = -dir * slFrontDistance(dir, t, r, lineDepthCap * r);
    lineRadiusVSOutput = r;
    if (lineSingleLayer != 0)
    {
      lineEndCuts(node);
    }
#ifdef LINE_PICKING
    tube = lineTubeOf(node);
#endif
  }
  else if (lineMode == 1)
  {
    int first = int(texelFetch(lineSegments, gl_InstanceID).x);
    int ring = gl_VertexID / lineSides;
    int j = gl_VertexID - ring * lineSides;
    node = first + ring;
    vec3 t0 = lineViewTangent(first);
    vec3 t1 = lineViewTangent(first + 1);
    vec3 a = cross(t0, t1);
    float al = length(a);
    a = al > 1.0e-6 ? a / al : svAnyOrthogonal(t0);
    vec3 t = ring == 0 ? t0 : t1;
    vec3 b = cross(t, a);
    float phi = 6.283185307179586 * float(j) / float(lineSides);
    vec3 n = cos(phi) * a + sin(phi) * b;
    vec4 pr = lineNode(node);
    vec3 p = (tubeMCVC * vec4(pr.xyz, 1.0)).xyz;
    float r = svDrawnRadius(pr.w * tubeRadiusScale, p.z, tubeMinimumRadius);
    position = p + (r * (lineHaloPass != 0 ? lineWiden : 1.0)) * n;
    lineXVSOutput = n;
    lineYVSOutput = cross(n, t);
    lineTexVSOutput = vec2(0.0);
    lineFrontVSOutput = vec3(0.0);
    lineRadiusVSOutput = r;
#ifdef LINE_PICKING
    tube = lineTubeOf(node);
#endif
  }
  else if (lineMode == 3)
  {
    node = int(texelFetch(lineJoints, gl_InstanceID).x);
    vec4 pr = lineNode(node);
    vec3 p = (tubeMCVC * vec4(pr.xyz, 1.0)).xyz;
    float r = svDrawnRadius(pr.w * tubeRadiusScale, p.z, tubeMinimumRadius);
    float rr = r * (lineHaloPass != 0 ? lineWiden : 1.0);
    // A square in the plane through the center, orthogonal to the view ray
    // to it, that bounds the sphere's projection (the cone tangent to it).
    vec3 dir = cameraParallel != 0 ? vec3(0.0, 0.0, -1.0) : normalize(p);
    float dist = length(p);
    if (cameraParallel == 0 && dist <= rr * 1.001)
    {
      lineCulled(); // the eye is inside the sphere
      return;
    }
    float extent = cameraParallel != 0 ? rr : rr * dist / sqrt(dist * dist - rr * rr);
    vec3 a = svAnyOrthogonal(dir);
    vec3 b = cross(dir, a);
    position = p + (extent * 1.01) * (((gl_VertexID & 1) != 0 ? 1.0 : -1.0) * a +
                                      ((gl_VertexID & 2) != 0 ? 1.0 : -1.0) * b);
    lineSphereVSOutput = vec4(p, rr);
    lineXVSOutput = -dir;
    lineYVSOutput = lineViewTangent(node); // for the fragment stage's normal
    lineTexVSOutput = vec2(0.0);
    lineFrontVSOutput = vec3(0.0);
    lineRadiusVSOutput = r;
#ifdef LINE_PICKING
    tube = lineTubeOf(node);
#endif
  }
  else
  {
    int cap = lineCapList != 0 ? int(texelFetch(lineCaps, gl_InstanceID).x) : gl_InstanceID;
    tube = cap >> 1;
    int end = cap & 1;
    node = end != 0 ? int(texelFetch(lineTubeStarts, tube + 1).x) - 1
                    : int(texelFetch(lineTubeStarts, tube).x);
    vec4 pr = lineNode(node);
    vec3 p = (tubeMCVC * vec4(pr.xyz, 1.0)).xyz;
    float r = svDrawnRadius(pr.w * tubeRadiusScale, p.z, tubeMinimumRadius);
    vec3 t = lineViewTangent(node);
    vec3 outward = end != 0 ? t : -t;
    vec3 toEye = cameraParallel != 0 ? vec3(0.0, 0.0, 1.0) : -p;
    if (dot(outward, toEye) <= 0.0)
    {
      lineCulled(); // the cap is turned away: hidden by its line
      return;
    }
    vec3 a = svAnyOrthogonal(t);
    vec3 b = cross(t, a);
    position = p;
    if (gl_VertexID > 0)
    {
      float phi = 6.283185307179586 * float(gl_VertexID - 1) / float(lineSides);
      position += (r * (lineHaloPass != 0 ? lineWiden : 1.0)) * (cos(phi) * a + sin(phi) * b);
    }
    lineXVSOutput = outward;
    lineYVSOutput = a;
    // The rim at the halo's outer edge (for depth-dependent halos).
    lineTexVSOutput = vec2(0.0, gl_VertexID > 0 && lineHaloPass != 0 ? lineWiden : 0.0);
    lineFrontVSOutput = vec3(0.0);
    lineRadiusVSOutput = r;
  }
  lineAttributes(node);
  lineInfoVSOutput = ivec2(tube, kind | (lineMode != 0 && lineHaloPass != 0 ? 4 : 0));
  vertexVCVSOutput = vec4(position, 1.0);
  gl_Position = VCDCMatrix * vec4(position, 1.0);
}
