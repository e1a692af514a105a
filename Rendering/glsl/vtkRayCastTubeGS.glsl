// SPDX-License-Identifier: BSD-3-Clause
//VTK::System::Dec

// Ray-cast spline tubes (Salm §3.2 'Rendering'), geometry stage: the
// rectangle of one quadratic sub-segment (a point of the draw, set up by
// vtkRayCastTubeVS.glsl) as a 4-vertex triangle strip in the plane z of its
// nearest depth, corners lo and hi along the axes u and v = (-u.y, u.x).
// Nothing for sub-segments the vertex stage culled or left to another
// sub-segment's rectangle. (The outputs are named ...GSOutput: VTK's shader
// cache renames the fragment stage's ...VSOutput inputs so when a program has
// a geometry stage.)
//
// Why points and a geometry stage: the vertex stage's work (the segment into
// view coordinates, its split, the straightness tests, the bounds) is the
// same for the four corners; on a software rasterizer, where vertex shading
// runs on the application's thread, doing it once per sub-segment instead of
// once per corner shortened the frame (see vtkRayCastTubeMapper.h).

layout(points) in;
layout(triangle_strip, max_vertices = 4) out;

uniform mat4 VCDCMatrix;

in TubeRectangle
{
  flat vec4 q0;
  flat vec4 q1;
  flat vec4 q2;
  flat ivec4 info;
  flat vec4 frame;
  flat vec4 span;
  flat vec4 c0;
  flat vec4 d0;
  flat vec4 c1;
  flat vec4 d1;
  flat vec4 cut0;
  flat vec4 cut1;
} tubeRect[];

out vec4 vertexVCGSOutput;       // position on the rectangle, view coordinates
flat out vec4 tubeQ0GSOutput;    // quadratic sub-segment in view coordinates
flat out vec4 tubeQ1GSOutput;    // (xyz: control point, w: radius)
flat out vec4 tubeQ2GSOutput;
flat out ivec4 tubeInfoGSOutput; // first node, sub-segment, tube, flags | mode << 2
flat out vec4 tubeCut0GSOutput;  // translucent: the planes bounding the rectangle's part
flat out vec4 tubeCut1GSOutput;
//SV::TubeColor::GSDec

void main()
{
  vec4 frame = tubeRect[0].frame;
  if (frame.w <= 0.0)
  {
    return;
  }
  vec2 u = frame.xy;
  vec2 v = vec2(-u.y, u.x);
  vec4 span = tubeRect[0].span;
  for (int corner = 0; corner < 4; ++corner)
  {
    vec2 uv = vec2((corner & 1) != 0 ? span.z : span.x, (corner & 2) != 0 ? span.w : span.y);
    vec3 p = vec3(uv.x * u + uv.y * v, frame.z);
    vertexVCGSOutput = vec4(p, 1.0);
    tubeQ0GSOutput = tubeRect[0].q0;
    tubeQ1GSOutput = tubeRect[0].q1;
    tubeQ2GSOutput = tubeRect[0].q2;
    tubeInfoGSOutput = tubeRect[0].info;
    tubeCut0GSOutput = tubeRect[0].cut0;
    tubeCut1GSOutput = tubeRect[0].cut1;
    //SV::TubeColor::GSImpl
    gl_PrimitiveID = gl_PrimitiveIDIn;
    gl_Position = VCDCMatrix * vec4(p, 1.0);
    EmitVertex();
  }
  EndPrimitive();
}
