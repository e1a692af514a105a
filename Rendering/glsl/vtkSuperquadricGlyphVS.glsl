// SPDX-License-Identifier: BSD-3-Clause
//VTK::System::Dec

// Vertex shader of vtkSuperquadricGlyphMapper: one vertex per glyph, carrying
// the glyph's centre and its raw symmetric tensor. Per glyph, on the GPU
// (Hlawitschka et al. §3.1, §3.6): eigen-decomposition, sign policy,
// thresholds, Westin metrics, Kindlmann's shape (alpha, beta, symmetry axis),
// the glyph frame in view coordinates and the glyph's color.

in vec4 vertexMC;
in vec3 tensorDiagMC; // xx, yy, zz
in vec3 tensorOffMC;  // xy, yz, xz
//SV::ScalarColor::Dec
//SV::BlockColor::Dec

uniform mat4 MCVCMatrix;
uniform mat3 glyphMCVC; // linear part of model -> view

uniform float sqGamma;
uniform float sqScaleFactor;
uniform float sqMaximumScale;
uniform float sqMinimumThickness;
uniform float sqMinimumRoundness;
//SV::GeneralShapes::Dec
#ifdef SQ_GENERAL_SHAPES
uniform float sqZeroEigenvalueBand;
#endif
uniform float sqAnisotropyThreshold;
uniform float sqMinimumEigenvalue;
uniform int sqScaleMode;
uniform int sqSignPolicy;
uniform int sqColorMode;

out int glyphValidVSOut;
out vec3 glyphCenterVSOut;
out mat3 glyphFrameVSOut; // columns: the glyph's u, v, w axes (scaled), view coordinates
out vec3 glyphShapeVSOut; // alpha, beta, c (c = beta for Kindlmann's glyphs)
out vec3 glyphFormVSOut;  // the quadratic form in glyph coordinates: l_i s_i^2, normalized
#ifdef SQ_GENERAL_SHAPES
out vec4 glyphBlendVSOut; // the band of a zero eigenvalue (svqBlendAbs); w = 1: none
#endif
out vec4 glyphColorVSOut; // rgba, a < 0: use the actor's colors

//VTK::Picking::Dec

//SV::Prelude::Dec
//SV::TensorMath::Dec
//SV::GlyphMath::Dec

// The glyph's frame (columns: its u, v, w axes, the eigenvectors eu, ev, ew
// scaled by s) and its quadratic form in glyph coordinates (l_i s_i^2), from
// the eigenvalues l and semi-axes s in the order of the axes.
void glyphAxes(vec3 l, vec3 s, vec3 eu, vec3 ev, vec3 ew, out mat3 frame, out vec3 form)
{
  frame = mat3(s.x * eu, s.y * ev, s.z * ew);
  form = vec3(l.x * s.x * s.x, l.y * s.y * s.y, l.z * s.z * s.z);
}

void main()
{
  glyphValidVSOut = 0;
  glyphCenterVSOut = (MCVCMatrix * vertexMC).xyz;
  glyphFrameVSOut = mat3(1.0);
  glyphShapeVSOut = vec3(1.0);
  glyphFormVSOut = vec3(1.0);
#ifdef SQ_GENERAL_SHAPES
  glyphBlendVSOut = vec4(1.0);
#endif
  glyphColorVSOut = vec4(1.0, 1.0, 1.0, -1.0);
  gl_Position = vec4(glyphCenterVSOut, 1.0);

  //VTK::Picking::Impl

  if (any(isnan(tensorDiagMC)) || any(isnan(tensorOffMC)) || any(isinf(tensorDiagMC)) ||
    any(isinf(tensorOffMC)))
  {
    return;
  }
  vec3 lambda;
  vec3 e1;
  vec3 e2;
  vec3 e3;
  svtSymmetricEigen(tensorDiagMC, tensorOffMC, lambda, e1, e2, e3);
  if (!(max(abs(lambda.x), abs(lambda.z)) > 0.0))
  {
    return; // the zero tensor
  }
  if (!svtApplySignPolicy(sqSignPolicy, lambda, e1, e2, e3))
  {
    return;
  }
  // FA of the eigenvalues drawn (after the sign policy, so in [0, 1])
  float fa = svtFractionalAnisotropy(lambda);
  if (fa < sqAnisotropyThreshold)
  {
    return;
  }
  if (lambda.z < sqMinimumEigenvalue)
  {
    return;
  }
  mat3 frameMC;
  vec3 form;
  if (sqSignPolicy == 2)
  {
    // Schultz and Kindlmann: any sign pattern; semi-axes |l_i| along e_i,
    // symmetry axis e1 or e3, v along e2.
    vec3 abc;
    bool axisE1 = svtSchultzKindlmannShape(lambda, sqGamma, sqMinimumRoundness, abc);
    vec3 s =
      svqSemiAxes(abs(lambda), sqScaleMode, sqScaleFactor, sqMaximumScale, sqMinimumThickness);
    if (!(max(s.x, s.z) > 0.0))
    {
      return;
    }
    if (axisE1)
    {
      glyphAxes(lambda.zyx, s.zyx, e3, e2, e1, frameMC, form);
    }
    else
    {
      glyphAxes(lambda, s, e1, e2, e3, frameMC, form);
    }
    glyphShapeVSOut = abc;
#ifdef SQ_GENERAL_SHAPES
    // near a zero eigenvalue, on the indefinite side: the blend with the
    // definite side's glyph (continuity with a minimum thickness)
    vec3 abcDefinite;
    bool axisDefiniteE1;
    float w = svtSchultzKindlmannBlend(
      lambda, sqGamma, sqMinimumRoundness, sqZeroEigenvalueBand, abcDefinite, axisDefiniteE1);
    if (w < 1.0)
    {
      glyphBlendVSOut = vec4(abcDefinite, axisDefiniteE1 != axisE1 ? w + 2.0 : w);
    }
#endif
  }
  else
  {
    vec3 westin = svtWestinMetrics(lambda);
    float alpha;
    float beta;
    bool isLinear =
      svtKindlmannShape(westin.x, westin.y, sqGamma, sqMinimumRoundness, alpha, beta);
    vec3 s = svqSemiAxes(lambda, sqScaleMode, sqScaleFactor, sqMaximumScale, sqMinimumThickness);
    if (!(s.x > 0.0))
    {
      return;
    }
    // Canonical axes (u, v, w), w the symmetry axis: e1 for linear glyphs
    // (Kindlmann's x axis), e3 otherwise (z axis).
    if (isLinear)
    {
      glyphAxes(lambda.yzx, s.yzx, e2, e3, e1, frameMC, form);
    }
    else
    {
      glyphAxes(lambda, s, e1, e2, e3, frameMC, form);
    }
    glyphShapeVSOut = vec3(alpha, beta, beta);
  }
  glyphFrameVSOut = glyphMCVC * frameMC;
  float formScale = max(max(abs(form.x), abs(form.y)), abs(form.z));
  glyphFormVSOut = formScale > 0.0 ? form / formScale : vec3(1.0);
  if (sqColorMode == 0)
  {
    // principal direction RGB, modulated by FA (at most 1: the FA of
    // indefinite eigenvalues reaches sqrt(3/2))
    glyphColorVSOut = vec4(abs(e1) * min(fa, 1.0), 1.0);
  }
  //SV::ScalarColor::Impl
  //SV::BlockColor::Impl
  glyphValidVSOut = 1;
}
