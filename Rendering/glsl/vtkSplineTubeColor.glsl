// Scalar coloring of spline tubes (vtkSplineTubeMapper), shared by every
// stage that evaluates the color spline. Needs the spline-tube math
// (vtkSplineTubeMathShared.glsl) before it.
//
// Per node one RG32UI texel of `tubeColors`: the color (RGBA8, x) and its
// derivative along the segment (signed bytes, y; scaled by 127: at most a
// full color change per segment). One fetch per node instead of two: on
// llvmpipe every texelFetch is a gather per SIMD lane, and the color spline
// is evaluated per vertex (tessellated tubes) or per fragment (ray-cast
// tubes).
uniform usamplerBuffer tubeColors;

// The four bytes of v, lowest first, as values 0 .. 255.
vec4 tubeColorBytes(uint v)
{
  return vec4(uvec4(v, v >> 8u, v >> 16u, v >> 24u) & uvec4(0xFFu));
}

// The color derivative's bytes as values in [-1, 1].
vec4 tubeColorDerivative(uint v)
{
  vec4 b = tubeColorBytes(v);
  return (b - 256.0 * step(vec4(128.0), b)) / 127.0;
}

// The color spline of the segment from `node` at curve parameter t.
vec4 tubeColorSpline(int node, float t)
{
  uvec2 a = texelFetch(tubeColors, node).xy;
  uvec2 b = texelFetch(tubeColors, node + 1).xy;
  return clamp(svHermite(tubeColorBytes(a.x) / 255.0, tubeColorDerivative(a.y),
                 tubeColorBytes(b.x) / 255.0, tubeColorDerivative(b.y), t),
    0.0, 1.0);
}
