//VTK::System::Dec

// Geometry shader of vtkSuperquadricGlyphMapper: the sprite of one glyph
// (Hlawitschka et al. §3.2). The worst case of any gamma is the glyph's box
// (gamma = infinity); the sprite is the screen-space bounding rectangle of
// that box, placed on the plane through the box corner nearest to the eye
// (or on the near clipping plane when the box crosses it), so that every ray
// starts in front of the glyph. The fragment shader casts the rays.

layout(points) in;
layout(triangle_strip, max_vertices = 4) out;

uniform mat4 VCDCMatrix;
uniform int cameraParallel;
uniform float nearPlaneVC; // z of the near clipping plane in view coordinates (< 0)

in int glyphValidVSOut[];
in vec3 glyphCenterVSOut[];
in mat3 glyphFrameVSOut[];
in vec2 glyphShapeVSOut[];
in vec4 glyphColorVSOut[];

out vec4 vertexVCGSOutput;
flat out mat3 glyphInverseGSOutput;
flat out vec3 glyphCenterGSOutput;
flat out vec2 glyphShapeGSOutput;
flat out vec4 glyphColorGSOutput;

//VTK::Picking::Dec

void emitCorner(float x, float y, float z, mat3 inv)
{
  vertexVCGSOutput = vec4(x, y, z, 1.0);
  gl_Position = VCDCMatrix * vertexVCGSOutput;
  glyphInverseGSOutput = inv;
  glyphCenterGSOutput = glyphCenterVSOut[0];
  glyphShapeGSOutput = glyphShapeVSOut[0];
  glyphColorGSOutput = glyphColorVSOut[0];
  int i = 0;
  //VTK::Picking::Impl
  EmitVertex();
}

void main()
{
  if (glyphValidVSOut[0] == 0)
  {
    return;
  }
  vec3 c = glyphCenterVSOut[0];
  mat3 G = glyphFrameVSOut[0];
  // half extents of the glyph's box along the view axes
  vec3 h = abs(G[0]) + abs(G[1]) + abs(G[2]);
  float zFront = c.z + h.z;
  float zBack = c.z - h.z;
  if (zBack >= nearPlaneVC)
  {
    return; // entirely in front of the near plane (or behind the eye)
  }
  float zp = min(zFront, nearPlaneVC);
  mat3 inv = inverse(G);
  float xmin;
  float xmax;
  float ymin;
  float ymax;
  if (cameraParallel != 0)
  {
    xmin = c.x - h.x;
    xmax = c.x + h.x;
    ymin = c.y - h.y;
    ymax = c.y + h.y;
  }
  else if (zFront > nearPlaneVC)
  {
    // The box crosses the near plane: the whole viewport, on the near plane.
    float w = VCDCMatrix[2][3] * zp + VCDCMatrix[3][3];
    xmin = (-w - VCDCMatrix[2][0] * zp - VCDCMatrix[3][0]) / VCDCMatrix[0][0];
    xmax = (w - VCDCMatrix[2][0] * zp - VCDCMatrix[3][0]) / VCDCMatrix[0][0];
    ymin = (-w - VCDCMatrix[2][1] * zp - VCDCMatrix[3][1]) / VCDCMatrix[1][1];
    ymax = (w - VCDCMatrix[2][1] * zp - VCDCMatrix[3][1]) / VCDCMatrix[1][1];
  }
  else
  {
    // Central projection of the 8 corners onto the plane z = zp.
    xmin = 1e30;
    xmax = -1e30;
    ymin = 1e30;
    ymax = -1e30;
    for (int k = 0; k < 8; ++k)
    {
      vec3 sgn = vec3((k & 1) != 0 ? 1.0 : -1.0, (k & 2) != 0 ? 1.0 : -1.0, (k & 4) != 0 ? 1.0 : -1.0);
      vec3 p = c + G * sgn;
      float f = zp / p.z;
      xmin = min(xmin, p.x * f);
      xmax = max(xmax, p.x * f);
      ymin = min(ymin, p.y * f);
      ymax = max(ymax, p.y * f);
    }
  }
  emitCorner(xmin, ymin, zp, inv);
  emitCorner(xmax, ymin, zp, inv);
  emitCorner(xmin, ymax, zp, inv);
  emitCorner(xmax, ymax, zp, inv);
  EndPrimitive();
}
