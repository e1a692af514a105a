//VTK::System::Dec

// Geometry shader of vtkSuperquadricGlyphMapper: the sprite of one glyph
// (Hlawitschka et al. §3.2-3.3). The worst case of any gamma is the glyph's
// box (gamma = infinity); instead of the screen rectangle around the box,
// the sprite is made of the box faces that face the eye (at most three
// parallelograms covering exactly the box's projection, fewer fragments),
// so each fragment lies where its ray enters the box. When the box crosses
// the near clipping plane the sprite is the whole viewport on that plane.
// The fragment shader casts the rays.

layout(points) in;
layout(triangle_strip, max_vertices = 12) out;

uniform mat4 VCDCMatrix;
uniform int cameraParallel;
uniform float nearPlaneVC; // z of the near clipping plane in view coordinates (< 0)

in int glyphValidVSOut[];
in vec3 glyphCenterVSOut[];
in mat3 glyphFrameVSOut[];
in vec3 glyphShapeVSOut[];
in vec3 glyphFormVSOut[];
in vec4 glyphColorVSOut[];

out vec4 vertexVCGSOutput;
flat out mat3 glyphInverseGSOutput;
flat out vec3 glyphCenterGSOutput;
flat out vec3 glyphShapeGSOutput;
flat out vec3 glyphFormGSOutput;
flat out vec4 glyphColorGSOutput;

//VTK::Picking::Dec

void emitCorner(vec3 p, mat3 inv)
{
  vertexVCGSOutput = vec4(p, 1.0);
  gl_Position = VCDCMatrix * vertexVCGSOutput;
  glyphInverseGSOutput = inv;
  glyphCenterGSOutput = glyphCenterVSOut[0];
  glyphShapeGSOutput = glyphShapeVSOut[0];
  glyphFormGSOutput = glyphFormVSOut[0];
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
  mat3 inv = inverse(G);
  if (zFront > nearPlaneVC)
  {
    // The box crosses the near plane: a rectangle on the near plane, the
    // box's extent in parallel projection, the whole viewport in perspective.
    float zp = nearPlaneVC;
    float xmin = c.x - h.x;
    float xmax = c.x + h.x;
    float ymin = c.y - h.y;
    float ymax = c.y + h.y;
    if (cameraParallel == 0)
    {
      float w = VCDCMatrix[2][3] * zp + VCDCMatrix[3][3];
      xmin = (-w - VCDCMatrix[2][0] * zp - VCDCMatrix[3][0]) / VCDCMatrix[0][0];
      xmax = (w - VCDCMatrix[2][0] * zp - VCDCMatrix[3][0]) / VCDCMatrix[0][0];
      ymin = (-w - VCDCMatrix[2][1] * zp - VCDCMatrix[3][1]) / VCDCMatrix[1][1];
      ymax = (w - VCDCMatrix[2][1] * zp - VCDCMatrix[3][1]) / VCDCMatrix[1][1];
    }
    emitCorner(vec3(xmin, ymin, zp), inv);
    emitCorner(vec3(xmax, ymin, zp), inv);
    emitCorner(vec3(xmin, ymax, zp), inv);
    emitCorner(vec3(xmax, ymax, zp), inv);
    EndPrimitive();
    return;
  }
  // The 8 corners, computed once so that shared edges are identical (no
  // cracks between the faces); corner k has the signs of bits 0, 1, 2 of k.
  vec3 corners[8];
  for (int k = 0; k < 8; ++k)
  {
    vec3 sgn = vec3((k & 1) != 0 ? 1.0 : -1.0, (k & 2) != 0 ? 1.0 : -1.0, (k & 4) != 0 ? 1.0 : -1.0);
    corners[k] = c + G * sgn;
  }
  for (int axis = 0; axis < 3; ++axis)
  {
    // outward normal of the face +axis: row `axis` of G^-1
    vec3 normal = vec3(inv[0][axis], inv[1][axis], inv[2][axis]);
    int a = (axis + 1) % 3;
    int b = (axis + 2) % 3;
    for (int side = 0; side < 2; ++side)
    {
      float sigma = side == 0 ? -1.0 : 1.0;
      vec3 faceCenter = c + sigma * G[axis];
      vec3 toEye = cameraParallel != 0 ? vec3(0.0, 0.0, 1.0) : -faceCenter;
      if (sigma * dot(normal, toEye) > 0.0)
      {
        int base = side << axis;
        emitCorner(corners[base], inv);
        emitCorner(corners[base | (1 << a)], inv);
        emitCorner(corners[base | (1 << b)], inv);
        emitCorner(corners[base | (1 << a) | (1 << b)], inv);
        EndPrimitive();
      }
    }
  }
}
