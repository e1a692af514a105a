// SPDX-License-Identifier: BSD-3-Clause
//VTK::System::Dec

// The ray-cast surface is never in front of the rasterized sprite, so the
// depth test can run before the shader (early z) where supported.
#ifdef GL_ARB_conservative_depth
#extension GL_ARB_conservative_depth : enable
layout(depth_greater) out float gl_FragDepth;
#endif

// Fragment shader of vtkSuperquadricGlyphMapper: casts the pixel's ray in
// glyph space (Hlawitschka et al. §3.3-3.4): clip to the unit box, find the
// first root of the superquadric function robustly (svqIntersect), write the
// exact depth, shade with VTK's lights using the analytic normal.

uniform int PrimitiveIDOffset;

//VTK::CustomUniforms::Dec

in vec4 vertexVCGSOutput;
flat in mat3 glyphInverseGSOutput;
flat in vec3 glyphCenterGSOutput;
flat in vec3 glyphShapeGSOutput;
flat in vec3 glyphFormGSOutput;
flat in vec4 glyphColorGSOutput;

uniform mat4 VCDCMatrix;
uniform int cameraParallel;
uniform int sqMaximumIterations;
uniform int sqCulling;
uniform sampler2D sqPyramid0; // the depth of what is drawn (occlusion culling)
uniform ivec2 sqViewportOrigin;
uniform int sqColorMode;
uniform vec3 sqPositiveFormColor;
uniform vec3 sqNegativeFormColor;

//VTK::Color::Dec

//VTK::Light::Dec

//VTK::Picking::Dec

//VTK::DepthPeeling::Dec

//VTK::Output::Dec

//SV::Prelude::Dec
//SV::GeneralShapes::Dec
//SV::Clip::Dec
//SV::GlyphMath::Dec

#ifdef SQ_GENERAL_SHAPES
flat in vec4 glyphBlendGSOutput;
#endif

#ifdef SQ_CLIP
// VTK's clipping planes (data coordinates; the kept side has
// dot(plane, (x, 1)) >= 0) and the view-to-data transformation.
uniform int numClipPlanes;
uniform vec4 clipPlanes[6];
uniform mat4 glyphVCMC;
#endif

void main()
{
  // The sprite lies on the glyph's box, in front of the glyph: if it is
  // already behind what is drawn, so is the glyph (before the ray cast). The
  // margin of two 24-bit depth steps keeps ties to the depth test.
  if (sqCulling != 0 &&
    gl_FragCoord.z >
      texelFetch(sqPyramid0, ivec2(gl_FragCoord.xy) - sqViewportOrigin, 0).r + 1.2e-7)
  {
    discard;
  }
  vec4 vertexVC = vertexVCGSOutput;
  vec3 dirVC = vec3(0.0, 0.0, -1.0);
  if (cameraParallel == 0)
  {
    dirVC = normalize(vertexVC.xyz);
  }
  mat3 inv = glyphInverseGSOutput;
  vec3 o = inv * (vertexVC.xyz - glyphCenterGSOutput);
  vec3 d = inv * dirVC;
  float t;
  int evaluations;
  // Clipping planes clip the solid glyph: the ray's part in the kept
  // half-spaces is [tStart, tEnd]; where the ray enters it inside the glyph,
  // the cut itself is seen (depth and normal of the plane).
  float tStart = 0.0;
  float tEnd = 1e30;
  vec3 capNormalVC = vec3(0.0);
#ifdef SQ_CLIP
  vec4 originMC = glyphVCMC * vec4(vertexVC.xyz, 1.0);
  vec3 dirMC = mat3(glyphVCMC) * dirVC;
  for (int i = 0; i < numClipPlanes; ++i)
  {
    float value = dot(clipPlanes[i], originMC);
    float slope = dot(clipPlanes[i].xyz, dirMC);
    if (slope > 0.0)
    {
      float tc = -value / slope;
      if (tc > tStart)
      {
        tStart = tc;
        capNormalVC = transpose(mat3(glyphVCMC)) * clipPlanes[i].xyz;
      }
    }
    else if (slope < 0.0)
    {
      tEnd = min(tEnd, -value / slope);
    }
    else if (value < 0.0)
    {
      discard;
    }
  }
  if (!(tStart < tEnd))
  {
    discard;
  }
#endif
  vec3 start = o + tStart * d;
  bool cap = false;
  if (tStart > 0.0)
  {
#ifdef SQ_GENERAL_SHAPES
    cap = svqShapeInside(start, glyphShapeGSOutput, glyphBlendGSOutput);
#else
    vec3 unused;
    cap = svqValueGradient(start, glyphShapeGSOutput.x, glyphShapeGSOutput.y, unused) < 0.0;
#endif
  }
  vec3 hitGlyph = start;
  vec3 gradient = vec3(0.0);
  if (cap)
  {
    t = tStart;
  }
  else
  {
    // (the general ray caster of the Schultz-Kindlmann shapes is compiled
    // in only for that policy: its mere presence slows llvmpipe down by 40 %)
#ifdef SQ_GENERAL_SHAPES
    if (!svqIntersectShape(
          start, d, glyphShapeGSOutput, glyphBlendGSOutput, sqMaximumIterations, t, evaluations))
    {
      discard;
    }
    hitGlyph = start + t * d;
    gradient = svqShapeGradient(hitGlyph, glyphShapeGSOutput, glyphBlendGSOutput);
#else
    if (!svqIntersect(start, d, glyphShapeGSOutput.x, glyphShapeGSOutput.y, sqMaximumIterations,
          t, evaluations))
    {
      discard;
    }
    hitGlyph = start + t * d;
    svqValueGradient(hitGlyph, glyphShapeGSOutput.x, glyphShapeGSOutput.y, gradient);
#endif
    t += tStart;
    if (t > tEnd)
    {
      discard;
    }
  }
  vertexVC.xyz = vertexVC.xyz + t * dirVC;
  // normal = G^-T grad q (or the cut's plane); the first hit faces the viewer
  vec3 normalVCVSOutput = normalize(cap ? capNormalVC : transpose(inv) * gradient);
  if (dot(normalVCVSOutput, dirVC) > 0.0)
  {
    normalVCVSOutput = -normalVCVSOutput;
  }
  vec4 posDC = VCDCMatrix * vertexVC;
  float depth = 0.5 * (posDC.z / posDC.w) + 0.5;
  if (depth > 1.0)
  {
    discard;
  }
  gl_FragDepth = depth;

  // the glyph's color; a < 0: the actor's colors with opacity -a
  vec4 glyphColorFS = glyphColorGSOutput;
  if (sqColorMode == 3)
  {
    // the sign of the quadratic form x^T T x at the surface point
    float form = dot(glyphFormGSOutput, hitGlyph * hitGlyph);
    glyphColorFS = vec4(form >= 0.0 ? sqPositiveFormColor : sqNegativeFormColor,
      abs(glyphColorGSOutput.a));
  }

  //VTK::DepthPeeling::PreColor

  //VTK::Color::Impl

  //VTK::Light::Impl

  if (gl_FragData[0].a <= 0.0)
  {
    discard;
  }

  //VTK::DepthPeeling::Impl

  //VTK::Picking::Impl
}
