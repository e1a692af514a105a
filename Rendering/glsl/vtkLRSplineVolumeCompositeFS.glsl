// SPDX-License-Identifier: BSD-3-Clause
//VTK::System::Dec

// LR-spline volume ray casting, the last step of the multi-pass
// continuation: the final colors (premultiplied) and, for isosurfaces, the
// depths that the passes wrote into viewport-sized textures are drawn over
// the proxy box into the render target.

//VTK::Output::Dec

uniform sampler2D lrFinalColor;
uniform sampler2D lrFinalDepth;
uniform vec4 lrViewport; // x, y, width, height (pixels)
uniform int lrWriteDepth;

void main()
{
  ivec2 pixel = ivec2(gl_FragCoord.xy - lrViewport.xy);
  vec4 color = texelFetch(lrFinalColor, pixel, 0);
  if (color.a <= 0.0)
  {
    discard;
  }
  gl_FragDepth = lrWriteDepth != 0 ? texelFetch(lrFinalDepth, pixel, 0).r : gl_FragCoord.z;
  gl_FragData[0] = color; // premultiplied: blended as src + (1 - src.a) dst
}
