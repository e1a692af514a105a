//VTK::System::Dec
//VTK::Output::Dec

// Ray-cast spline tubes: the occlusion-culling depth pre-pass, fragment
// stage. It writes nothing (the pass has only a depth attachment) and never
// discards, so the rasterizer keeps its early depth test; see
// vtkRayCastTubeCullVS.glsl.

void main()
{
}
