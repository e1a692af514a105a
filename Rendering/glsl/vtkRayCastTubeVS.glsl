//VTK::System::Dec

// Ray-cast spline tubes (Salm §3.2), vertex stage: a GL_POINTS draw with one
// point per quadratic sub-segment and no vertex attributes; the geometry
// stage reads the tubes buffer and builds the sub-segment's bounding box.
flat out int subSegmentVSOutput;

void main()
{
  subSegmentVSOutput = gl_VertexID;
  gl_Position = vec4(0.0, 0.0, 0.0, 1.0);
}
