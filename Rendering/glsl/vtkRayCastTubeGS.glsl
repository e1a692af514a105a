//VTK::System::Dec

// Ray-cast spline tubes (Salm §3.2 'Rendering'), geometry stage.
//
// One invocation per quadratic sub-segment (the vertex stage only forwards
// gl_VertexID of a GL_POINTS draw). It reads the two nodes of its cubic
// segment from the tubes buffer, splits the segment into its quadratic
// sub-segments (svSplitSegment), transforms the one it owns to view
// coordinates and rasterizes its oriented bounding box (svSubSegmentBox):
// - only the faces turned to the eye (the box's silhouette, each pixel once),
// - all faces when the eye is inside the box or the box crosses the near
//   plane (then the far faces still cover the tube),
// - nothing when the box is outside the view frustum.
// The fragment stage intersects the view ray with the sub-segment. (VTK's
// shader cache renames the fragment stage's ...VSOutput inputs to
// ...GSOutput when a geometry stage is present.)

layout(points) in;
layout(triangle_strip, max_vertices = 24) out;

uniform samplerBuffer tubeNodes;     // per node: (x, y, z, r), (dx, dy, dz, dr)
uniform usamplerBuffer tubeSegments; // per segment: (first node | flags << 30, tube)
uniform int subSegments;             // quadratic sub-segments per cubic segment
uniform mat4 tubeMCVC;               // model (shifted) to view
uniform float tubeRadiusScale;       // model to view scale of radii
uniform mat4 VCDCMatrix;
uniform int cameraParallel;

flat in int subSegmentVSOutput[];

out vec4 vertexVCGSOutput;     // position on the box, view coordinates
flat out vec4 tubeQ0GSOutput;  // quadratic sub-segment in view coordinates
flat out vec4 tubeQ1GSOutput;  // (xyz: control point, w: radius)
flat out vec4 tubeQ2GSOutput;
flat out ivec4 tubeInfoGSOutput; // first node, sub-segment, tube, flags

//VTK::SplineTubeMath::Dec

// Outputs are undefined after EmitVertex(): every vertex sets them all.
vec4 subSegmentQ0;
vec4 subSegmentQ1;
vec4 subSegmentQ2;
ivec4 subSegmentInfo;

void emitCorner(vec3 p)
{
  tubeQ0GSOutput = subSegmentQ0;
  tubeQ1GSOutput = subSegmentQ1;
  tubeQ2GSOutput = subSegmentQ2;
  tubeInfoGSOutput = subSegmentInfo;
  vertexVCGSOutput = vec4(p, 1.0);
  gl_Position = VCDCMatrix * vec4(p, 1.0);
  EmitVertex();
}

void main()
{
  int id = subSegmentVSOutput[0];
  int segment = id / subSegments;
  int k = id - segment * subSegments;
  uvec2 s = texelFetch(tubeSegments, segment).xy;
  int node = int(s.x & 0x3FFFFFFFu);
  int flags = int(s.x >> 30u);

  vec4 p0 = texelFetch(tubeNodes, 2 * node);
  vec4 m0 = texelFetch(tubeNodes, 2 * node + 1);
  vec4 p1 = texelFetch(tubeNodes, 2 * node + 2);
  vec4 m1 = texelFetch(tubeNodes, 2 * node + 3);
  vec4 q0;
  vec4 q1;
  vec4 q2;
  svSplitSegment(p0, m0, p1, m1, subSegments, k, q0, q1, q2);
  q0 = vec4((tubeMCVC * vec4(q0.xyz, 1.0)).xyz, q0.w * tubeRadiusScale);
  q1 = vec4((tubeMCVC * vec4(q1.xyz, 1.0)).xyz, q1.w * tubeRadiusScale);
  q2 = vec4((tubeMCVC * vec4(q2.xyz, 1.0)).xyz, q2.w * tubeRadiusScale);

  SvBox box;
  svSubSegmentBox(q0, q1, q2, box);
  // Pad by a tiny fraction so that rounding never clips the surface.
  vec3 h = box.halfSize * 1.001 + vec3(1e-6 * length(box.halfSize));
  vec3 ax = box.axis0 * h.x;
  vec3 ay = box.axis1 * h.y;
  vec3 az = box.axis2 * h.z;
  vec3 c = box.center;

  // Corners: bit 0 -> +x, bit 1 -> +y, bit 2 -> +z.
  vec3 corner[8];
  bool allLeft = true;
  bool allRight = true;
  bool allBelow = true;
  bool allAbove = true;
  bool allFar = true;
  bool nearCrossing = false;
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
    nearCrossing = nearCrossing || clip.z < -clip.w || clip.w <= 0.0;
  }
  if (allLeft || allRight || allBelow || allAbove || allFar)
  {
    return; // outside the view frustum
  }

  subSegmentQ0 = q0;
  subSegmentQ1 = q1;
  subSegmentQ2 = q2;
  subSegmentInfo = ivec4(node, k, int(s.y), flags);

  // Is the eye inside the box? (perspective: the eye is the origin)
  vec3 e = -c;
  bool eyeInside = cameraParallel == 0 && abs(dot(e, box.axis0)) <= h.x &&
    abs(dot(e, box.axis1)) <= h.y && abs(dot(e, box.axis2)) <= h.z;
  bool allFaces = eyeInside || nearCrossing;

  // Faces as (axis, sign): corners of face +/-axis in strip order.
  for (int f = 0; f < 6; ++f)
  {
    int axis = f / 2;
    bool positive = (f & 1) != 0;
    vec3 n = axis == 0 ? box.axis0 : (axis == 1 ? box.axis1 : box.axis2);
    if (!positive)
    {
      n = -n;
    }
    vec3 faceCenter = c + (axis == 0 ? ax : (axis == 1 ? ay : az)) * (positive ? 1.0 : -1.0);
    bool facing = cameraParallel != 0 ? n.z > 0.0 : dot(n, -faceCenter) > 0.0;
    if (!allFaces && !facing)
    {
      continue;
    }
    // The two other axes' bits.
    int bitA = axis == 0 ? 2 : 1;
    int bitB = axis == 2 ? 2 : 4;
    int base = positive ? (1 << axis) : 0;
    emitCorner(corner[base]);
    emitCorner(corner[base + bitA]);
    emitCorner(corner[base + bitB]);
    emitCorner(corner[base + bitA + bitB]);
    EndPrimitive();
  }
}
