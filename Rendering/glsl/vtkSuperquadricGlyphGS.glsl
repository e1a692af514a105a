// SPDX-License-Identifier: BSD-3-Clause
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

// Occlusion culling (vtkSuperquadricGlyphMapper draws the glyphs in groups;
// from the second group on, sqCulling = 1): the maxima of the depth buffer
// over 2 x 2, 4 x 4, 16 x 16 and 64 x 64 pixel tiles of what is already drawn.
uniform int sqCulling;
uniform sampler2D sqPyramid1;
uniform sampler2D sqPyramid2;
uniform sampler2D sqPyramid4;
uniform sampler2D sqPyramid6;
uniform ivec2 sqViewportSize;

in int glyphValidVSOut[];
in vec3 glyphCenterVSOut[];
in mat3 glyphFrameVSOut[];
in vec3 glyphShapeVSOut[];
in vec3 glyphFormVSOut[];
in vec4 glyphColorVSOut[];
//SV::GeneralShapes::Dec
#ifdef SQ_GENERAL_SHAPES
in vec4 glyphBlendVSOut[];
flat out vec4 glyphBlendGSOutput;
#endif

out vec4 vertexVCGSOutput;
flat out mat3 glyphInverseGSOutput;
flat out vec3 glyphCenterGSOutput;
flat out vec3 glyphShapeGSOutput;
flat out vec3 glyphFormGSOutput;
flat out vec4 glyphColorGSOutput;

//SV::Clip::Dec
#ifdef SQ_CLIP
// VTK's clipping planes (data coordinates) and the view-to-data
// transformation: glyphs whose box is beyond a plane are not drawn.
uniform int numClipPlanes;
uniform vec4 clipPlanes[6];
uniform mat4 glyphVCMC;
#endif

//VTK::Picking::Dec

void emitCorner(vec3 p, mat3 inv)
{
  vertexVCGSOutput = vec4(p, 1.0);
  gl_Position = VCDCMatrix * vertexVCGSOutput;
  glyphInverseGSOutput = inv;
  glyphCenterGSOutput = glyphCenterVSOut[0];
  glyphShapeGSOutput = glyphShapeVSOut[0];
  glyphFormGSOutput = glyphFormVSOut[0];
#ifdef SQ_GENERAL_SHAPES
  glyphBlendGSOutput = glyphBlendVSOut[0];
#endif
  glyphColorGSOutput = glyphColorVSOut[0];
  int i = 0;
  //VTK::Picking::Impl
  EmitVertex();
}

// Occlusion tests: the window-space rectangle and nearest depth of a set of
// points (view coordinates, all in front of the near plane) ...
void extendBounds(vec3 p, inout vec2 lo, inout vec2 hi, inout float zNear)
{
  vec4 clip = VCDCMatrix * vec4(p, 1.0);
  vec3 ndc = clip.xyz / clip.w;
  vec2 pixel = (0.5 * ndc.xy + 0.5) * vec2(sqViewportSize);
  lo = min(lo, pixel);
  hi = max(hi, pixel);
  zNear = min(zNear, 0.5 * ndc.z + 0.5);
}

// ... is occluded when the nearest depth is beyond the largest depth of every
// pyramid tile the rectangle touches (the tiles of the level at which it spans
// at most 4 x 4 of them; larger than 192 pixels: left to the fragment test).
bool occludedRect(vec2 lo, vec2 hi, float zNear)
{
  // (window coordinates: pixel i covers [i, i + 1))
  if (hi.x < 0.0 || hi.y < 0.0 || lo.x >= float(sqViewportSize.x) ||
    lo.y >= float(sqViewportSize.y))
  {
    return true; // outside the viewport
  }
  lo = max(lo, vec2(0.0));
  hi = min(hi, vec2(sqViewportSize) - 1.0);
  float extent = max(hi.x - lo.x, hi.y - lo.y);
  int tile;
  if (extent <= 6.0)
  {
    tile = 2;
  }
  else if (extent <= 12.0)
  {
    tile = 4;
  }
  else if (extent <= 48.0)
  {
    tile = 16;
  }
  else if (extent <= 192.0)
  {
    tile = 64;
  }
  else
  {
    return false;
  }
  ivec2 t0 = ivec2(lo) / tile;
  ivec2 t1 = ivec2(hi) / tile;
  float farthest = 0.0;
  for (int y = t0.y; y <= t1.y; ++y)
  {
    for (int x = t0.x; x <= t1.x; ++x)
    {
      float z;
      if (tile == 2)
      {
        z = texelFetch(sqPyramid1, ivec2(x, y), 0).r;
      }
      else if (tile == 4)
      {
        z = texelFetch(sqPyramid2, ivec2(x, y), 0).r;
      }
      else if (tile == 16)
      {
        z = texelFetch(sqPyramid4, ivec2(x, y), 0).r;
      }
      else
      {
        z = texelFetch(sqPyramid6, ivec2(x, y), 0).r;
      }
      farthest = max(farthest, z);
    }
  }
  return zNear > farthest + 1.2e-7; // (two 24-bit depth steps: ties to the depth test)
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
#ifdef SQ_CLIP
  // the largest value of a plane's function over the box: its value at the
  // center plus |plane . (semi-axis k)| for the three axes
  vec3 cMC = (glyphVCMC * vec4(c, 1.0)).xyz;
  mat3 axesMC = mat3(glyphVCMC) * G;
  for (int i = 0; i < numClipPlanes; ++i)
  {
    vec3 n = clipPlanes[i].xyz;
    float reach = abs(dot(n, axesMC[0])) + abs(dot(n, axesMC[1])) + abs(dot(n, axesMC[2]));
    if (dot(n, cMC) + clipPlanes[i].w + reach < 0.0)
    {
      return; // all beyond the plane
    }
  }
#endif
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
  if (sqCulling != 0)
  {
    // A tighter box for the test: Kindlmann's glyphs (alpha, beta <= 1) also
    // lie in the ellipsoid G (ball of radius 2^(1 - (alpha + beta)/2)), whose
    // half extent along view axis i is that radius times |row i of G|.
    vec3 shape = glyphShapeVSOut[0];
    vec3 hb = h;
    bool kindlmann = shape.x <= 1.0 && shape.y <= 1.0 && shape.z == shape.y;
#ifdef SQ_GENERAL_SHAPES
    kindlmann = kindlmann && glyphBlendVSOut[0].w == 1.0;
#endif
    if (kindlmann)
    {
      float radius = pow(2.0, 1.0 - 0.5 * (shape.x + shape.y));
      vec3 row0 = vec3(G[0][0], G[1][0], G[2][0]);
      vec3 row1 = vec3(G[0][1], G[1][1], G[2][1]);
      vec3 row2 = vec3(G[0][2], G[1][2], G[2][2]);
      vec3 he = radius * sqrt(vec3(dot(row0, row0), dot(row1, row1), dot(row2, row2)));
      hb = min(h, he);
    }
    vec2 lo = vec2(1e30);
    vec2 hi = vec2(-1e30);
    float zNear = 1.0;
    for (int k = 0; k < 8; ++k)
    {
      extendBounds(c + hb * vec3((k & 1) != 0 ? 1.0 : -1.0, (k & 2) != 0 ? 1.0 : -1.0,
                         (k & 4) != 0 ? 1.0 : -1.0),
        lo, hi, zNear);
    }
    if (occludedRect(lo, hi, zNear))
    {
      return;
    }
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
      int base = side << axis;
      bool visible = sigma * dot(normal, toEye) > 0.0;
      if (visible && sqCulling != 0)
      {
        // each face on its own: behind what is drawn, so is the glyph there
        vec2 lo = vec2(1e30);
        vec2 hi = vec2(-1e30);
        float zNear = 1.0;
        extendBounds(corners[base], lo, hi, zNear);
        extendBounds(corners[base | (1 << a)], lo, hi, zNear);
        extendBounds(corners[base | (1 << b)], lo, hi, zNear);
        extendBounds(corners[base | (1 << a) | (1 << b)], lo, hi, zNear);
        visible = !occludedRect(lo, hi, zNear);
      }
      if (visible)
      {
        emitCorner(corners[base], inv);
        emitCorner(corners[base | (1 << a)], inv);
        emitCorner(corners[base | (1 << b)], inv);
        emitCorner(corners[base | (1 << a) | (1 << b)], inv);
        EndPrimitive();
      }
    }
  }
}
