// SPDX-License-Identifier: BSD-3-Clause
// Screen-space ambient occlusion and depth-dependent halos for lines
// (vtkLineAmbientOcclusionPass), one full-screen fragment stage.
//
// Inserted into VTK's full-screen-quad fragment template (the declarations
// part; its body calls lineAOMain()). Inputs: the color and the
// depth buffer the delegate passes drew. Nothing but the depth buffer is read
// for the geometry, so every opaque prop that writes its true depth takes part
// (the ray-cast tubes write their exact surface depth).
//
// Occlusion (after Eichelbaum et al. 2013, LineAO): for each pixel, the view
// point P and its normal n (from the depth buffer's neighbours), then for
// aoLevels radii (the largest aoRadius, each level half the next) aoSamples
// points of a disk around the pixel (area-uniform, turned per pixel); a sample
// Q occludes by max(0, n . (Q - P) / |Q - P| - bias) / (1 - bias), weighted
// by max(0, 1 - |Q - P|^2 / R^2) with R the level's radius in view units at
// P's distance (what is further away in depth than the hemisphere does not
// occlude). The levels are averaged; the color is scaled by
// clamp(1 - strength x occlusion, 0, 1). The background never occludes.
//
// Halos (after Everts et al. 2009): a pixel lies in the halo of a nearer
// pixel Q at screen distance s when s < haloWidth x clamp((gap - offset) /
// range, 0, 1), gap being how far P lies behind Q (the background: infinitely
// far). Lines close in depth (bundles) get no halo between them, lines far
// apart get the full width. The halo replaces the color (halo color).

uniform sampler2D aoColor;
uniform sampler2D aoDepth;
uniform mat4 aoInverseProjection; // normalized device to view coordinates
uniform vec2 aoClipW;             // clip w = aoClipW.x * z_view + aoClipW.y
uniform float aoPixelScale;       // one pixel in view units = aoPixelScale x clip w
uniform vec2 aoTexel;             // one pixel in texture coordinates
uniform ivec2 aoSize;             // the window's size in pixels
uniform int aoWorldUnits;         // radius and depth gaps: 1 view units, 0 pixels
uniform int aoEnabled;
uniform int aoLevels;
uniform int aoSamples;
uniform float aoRadius;
uniform float aoStrength;
uniform float aoBias;
uniform int aoHalo;
uniform float aoHaloWidth; // pixels
uniform float aoHaloOffset;
uniform float aoHaloRange;
uniform vec3 aoHaloColor;

// The view point at a pixel (outside the window: the nearest edge pixel);
// w = 0 marks the background. Integer fetches: no filtering to pay for.
vec4 aoViewPoint(ivec2 pixel)
{
  ivec2 q = clamp(pixel, ivec2(0), aoSize - 1);
  float d = texelFetch(aoDepth, q, 0).r;
  if (d >= 1.0)
  {
    return vec4(0.0);
  }
  vec2 ndc = (vec2(q) + 0.5) * (2.0 * aoTexel) - 1.0;
  vec4 p = aoInverseProjection * vec4(ndc, 2.0 * d - 1.0, 1.0);
  return vec4(p.xyz / p.w, 1.0);
}

// The size of one pixel in view units at view depth z.
float aoPixelSize(float z)
{
  return aoPixelScale * (aoClipW.x * z + aoClipW.y);
}

// The surface normal at P from the depth buffer: along each axis the
// neighbour nearer in depth (so that silhouettes do not bend it), facing the
// eye.
vec3 aoNormal(ivec2 uv, vec3 p)
{
  vec4 r = aoViewPoint(uv + ivec2(1, 0));
  vec4 l = aoViewPoint(uv - ivec2(1, 0));
  vec4 u = aoViewPoint(uv + ivec2(0, 1));
  vec4 d = aoViewPoint(uv - ivec2(0, 1));
  vec3 dx = vec3(1.0, 0.0, 0.0);
  vec3 dy = vec3(0.0, 1.0, 0.0);
  bool rl = r.w > 0.0 && (l.w == 0.0 || abs(r.z - p.z) <= abs(l.z - p.z));
  if (rl || l.w > 0.0)
  {
    dx = rl ? r.xyz - p : p - l.xyz;
  }
  bool ud = u.w > 0.0 && (d.w == 0.0 || abs(u.z - p.z) <= abs(d.z - p.z));
  if (ud || d.w > 0.0)
  {
    dy = ud ? u.xyz - p : p - d.xyz;
  }
  vec3 n = cross(dx, dy);
  float nl = length(n);
  vec3 toEye = aoClipW.x != 0.0 ? -p : vec3(0.0, 0.0, 1.0);
  n = nl > 0.0 ? n / nl : normalize(toEye);
  return dot(n, toEye) < 0.0 ? -n : n;
}

// Per-pixel rotation of the sample pattern (interleaved gradient noise).
float aoNoise()
{
  return fract(52.9829189 * fract(dot(gl_FragCoord.xy, vec2(0.06711056, 0.00583715))));
}

// Occlusion in [0, 1] at P (normal n), the mean over the levels.
float aoOcclusion(ivec2 uv, vec3 p, vec3 n)
{
  float pixel = aoPixelSize(p.z);
  float radius = aoWorldUnits != 0 ? aoRadius / pixel : aoRadius; // pixels
  float turn = 6.283185307179586 * aoNoise();
  float total = 0.0;
  for (int level = 0; level < aoLevels; ++level)
  {
    float rl = radius * exp2(float(level - aoLevels + 1));
    float rv = rl * pixel; // the hemisphere's radius in view units
    float sum = 0.0;
    for (int k = 0; k < aoSamples; ++k)
    {
      float a = turn + 2.399963229728653 * float(k + 7 * level); // golden angle
      float t = rl * sqrt((float(k) + 0.5) / float(aoSamples));
      vec4 q = aoViewPoint(uv + ivec2(floor(t * vec2(cos(a), sin(a)) + 0.5)));
      if (q.w == 0.0)
      {
        continue;
      }
      vec3 v = q.xyz - p;
      float vv = dot(v, v);
      if (vv <= 0.0)
      {
        continue;
      }
      float c = max(0.0, dot(n, v) * inversesqrt(vv) - aoBias) / (1.0 - aoBias);
      sum += c * max(0.0, 1.0 - vv / (rv * rv));
    }
    total += sum / float(aoSamples);
  }
  return total / float(aoLevels);
}

// Halo coverage in [0, 1] of the pixel (P, or the background when p.w = 0).
float aoHaloCoverage(ivec2 uv, vec4 p)
{
  const int directions = 8;
  const int rings = 3;
  float turn = 0.785398163 * aoNoise();
  float halo = 0.0;
  for (int j = 0; j < rings; ++j)
  {
    float s = aoHaloWidth * float(j + 1) / float(rings);
    for (int i = 0; i < directions; ++i)
    {
      float a = turn + 0.785398163 * (float(i) + 0.5 * float(j));
      vec4 q = aoViewPoint(uv + ivec2(floor(s * vec2(cos(a), sin(a)) + 0.5)));
      if (q.w == 0.0)
      {
        continue;
      }
      float gap = p.w == 0.0 ? 1.0e30 : q.z - p.z; // > 0: P lies behind Q
      gap = aoWorldUnits != 0 ? gap : gap / aoPixelSize(q.z);
      float w = aoHaloRange > 0.0 ? clamp((gap - aoHaloOffset) / aoHaloRange, 0.0, 1.0)
                                  : (gap > aoHaloOffset ? 1.0 : 0.0);
      halo = max(halo, clamp(aoHaloWidth * w - s + 0.5, 0.0, 1.0));
    }
  }
  return halo;
}

void lineAOMain()
{
  ivec2 pixel = ivec2(texCoord * vec2(aoSize));
  vec4 color = texelFetch(aoColor, pixel, 0);
  float depth = texelFetch(aoDepth, pixel, 0).r;
  vec4 p = aoViewPoint(pixel);
  if (p.w > 0.0 && aoEnabled != 0 && aoStrength > 0.0)
  {
    float occlusion = aoOcclusion(pixel, p.xyz, aoNormal(pixel, p.xyz));
    color.rgb *= clamp(1.0 - aoStrength * occlusion, 0.0, 1.0);
  }
  if (aoHalo != 0 && aoHaloWidth > 0.0)
  {
    color.rgb = mix(color.rgb, aoHaloColor, aoHaloCoverage(pixel, p));
  }
  gl_FragData[0] = color;
  gl_FragDepth = depth;
}
