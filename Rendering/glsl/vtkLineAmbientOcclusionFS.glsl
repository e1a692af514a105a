// SPDX-License-Identifier: BSD-3-Clause
// Screen-space ambient occlusion and depth-dependent halos for lines
// (vtkLineAmbientOcclusionPass), in stages, each its own program.
//
// Inserted after vtkLineAmbientOcclusionCommon.glsl into VTK's
// full-screen-quad fragment template (the declarations part; its body calls
// one of the entry points below). Inputs: the color and the depth buffer the
// delegate passes drew. Nothing but the depth buffer is read for the
// geometry, so every opaque prop that writes its true depth takes part (the
// ray-cast tubes write their exact surface depth).
//
// The stages, in the order the pass draws them:
//  1. lineAOPositionsMain (offscreen): the view point of every pixel, from
//     the depth buffer, into a floating-point texture (aoPositions) that the
//     other stages read: each pixel's point is computed once, not once per
//     sample that reads it, and a float color texture reads several times
//     faster than a depth texture on Mesa's llvmpipe.
//  2. lineAOBlocksMain (offscreen, halos only): per block of aoBlockSize
//     pixels (at least the halo's reach), the view z of its nearest and
//     farthest pixel.
//  3. lineAOBlockReachMain (offscreen, halos only): per block, the nearest
//     view z of the 3 x 3 blocks around it (every pixel a sample of the
//     block's pixels can read) and the block's farthest. Stage 6 reads it
//     per tile of 2 x 2 blocks and per pixel.
//  4. lineAOCopyMain: the delegate's color and depth, unchanged.
//  5. lineAOOcclusionMain: the factor the color is multiplied by (the pass
//     blends dst x src) where there is geometry: the pass draws it behind
//     everything with a GL_GREATER depth test, so the background is never
//     shaded (the early depth test skips it; on llvmpipe a stage in a branch
//     or behind a uniform switch costs as if it ran, hence one program per
//     stage).
//  6. lineAOHaloMain: the halo color with its coverage as alpha, blended
//     over, drawn by vtkLineAmbientOcclusionTilesVS.glsl on the tiles that
//     can hold a halo (compiled with LINE_AO_TILES defined).
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
uniform sampler2D aoPositions;    // view points (stage 0's output), w = 0: background
uniform mat4 aoInverseProjection; // normalized device to view coordinates
uniform vec2 aoTexel;             // one pixel in texture coordinates
uniform ivec2 aoSize;             // the window's size in pixels
uniform int aoLevels;
uniform int aoSamples;
uniform float aoRadius;
uniform float aoStrength;
uniform float aoBias;
uniform vec3 aoHaloColor;
uniform sampler2D aoBlocks;     // stage 2's output: per block, nearest and farthest view z
uniform sampler2D aoBlockReach; // stage 3's output: nearest view z within reach, farthest
uniform ivec2 aoBlockCount;     // blocks along x and y
uniform int aoBlockSize;        // pixels per block side

// The view point at a pixel (outside the window: the nearest edge pixel);
// w = 0 marks the background. Integer fetches: no filtering to pay for.
vec4 aoViewPoint(ivec2 pixel)
{
  return texelFetch(aoPositions, clamp(pixel, ivec2(0), aoSize - 1), 0);
}

// The direction d turned by the angle whose cosine and sine are cs.
vec2 aoTurn(vec2 d, vec2 cs)
{
  return vec2(cs.x * d.x - cs.y * d.y, cs.y * d.x + cs.x * d.y);
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
    // Sample k lies at the angle turn + golden angle x (k + 7 level), each
    // direction the previous one turned (no sine or cosine per sample).
    float a = turn + 2.399963229728653 * float(7 * level);
    vec2 direction = vec2(cos(a), sin(a));
    const vec2 golden = vec2(-0.7373688780783197, 0.6754902942615238);
    for (int k = 0; k < aoSamples; ++k, direction = aoTurn(direction, golden))
    {
      float t = rl * sqrt((float(k) + 0.5) / float(aoSamples));
      vec4 q = aoViewPoint(uv + ivec2(floor(t * direction + 0.5)));
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

// Halo coverage in [0, 1] of the pixel (P, or the background when p.w = 0):
// 3 rings of 8 samples, inner ring first. `nearest`: the view z of the
// nearest pixel within reach (-1e30: none). A sample Q gives
// clamp(aoHaloWidth x w - s + 0.5, 0, 1), which grows with Q's z (w grows
// with the gap, and the gap with the front point's z), so the same with
// `nearest` for Q bounds what ring s can still give: the search stops once
// the coverage found reaches the bound of the ring it is at (the bounds fall
// from ring to ring; a pixel with nothing far enough in front takes no
// sample, one with full coverage stops too). The samples taken and their
// order are those of the full search, so the coverage is the same.
// One loop whose length is not a constant: the compiler keeps it a loop,
// and a loop ends once all the pixels shaded together are done (an unrolled
// or branched-over block costs its full price on llvmpipe).
float aoHaloCoverage(ivec2 uv, vec4 p, float nearest)
{
  const int directions = 8;
  const int rings = 3;
  const vec2 eighth = vec2(0.7071067811865476, 0.7071067811865476);
  const vec2 sixteenth = vec2(0.9238795325112867, 0.3826834323650898);
  float turn = 0.785398163 * aoNoise();
  // Sample i of ring j lies at turn + (i + j / 2) eighths of a turn.
  vec2 direction = vec2(cos(turn), sin(turn));
  // No sample can give a halo unless the nearest point around lies more than
  // the offset in front.
  bool possible = p.w == 0.0 ? nearest > -1.0e29 : aoHaloGap(nearest, p.z) > aoHaloOffset;
  int count = possible ? directions * rings : 0;
  // The most each ring can give: a sample at `nearest`.
  float nearestW = aoHaloWeight(p.w == 0.0 ? 1.0e30 : aoHaloGap(nearest, p.z));
  vec3 bound;
  for (int j = 0; j < rings; ++j)
  {
    bound[j] = aoHaloRingCoverage(nearestW, aoHaloWidth * float(j + 1) / float(rings));
  }
#ifdef LINE_AO_FULL_SEARCH
  count = directions * rings; // (for tests) every sample until full coverage
  bound = vec3(1.0);
#endif
  float halo = 0.0;
  for (int k = 0; k < count && halo < bound[min(k / directions, rings - 1)]; ++k)
  {
    int j = k / directions;
    if (k > 0)
    {
      direction = aoTurn(direction, k == j * directions ? sixteenth : eighth);
    }
    float s = aoHaloWidth * float(j + 1) / float(rings);
    vec2 q = aoViewPoint(uv + ivec2(floor(s * direction + 0.5))).zw;
    if (q.y == 0.0)
    {
      continue;
    }
    float gap = p.w == 0.0 ? 1.0e30 : aoHaloGap(q.x, p.z); // > 0: P lies behind Q
    halo = max(halo, aoHaloRingCoverage(aoHaloWeight(gap), s));
  }
  return halo;
}

// The pixel this fragment shades.
ivec2 aoPixel()
{
  return ivec2(texCoord * vec2(aoSize));
}

void lineAOPositionsMain()
{
  ivec2 pixel = aoPixel();
  float d = texelFetch(aoDepth, pixel, 0).r;
  vec4 p = vec4(0.0);
  if (d < 1.0)
  {
    vec2 ndc = (vec2(pixel) + 0.5) * (2.0 * aoTexel) - 1.0;
    p = aoInverseProjection * vec4(ndc, 2.0 * d - 1.0, 1.0);
    p = vec4(p.xyz / p.w, 1.0);
  }
  gl_FragData[0] = p;
}

void lineAOBlocksMain()
{
  ivec2 block = ivec2(texCoord * vec2(aoBlockCount));
  ivec2 first = block * aoBlockSize;
  ivec2 last = min(first + aoBlockSize, aoSize) - 1;
  float nearest = -1.0e30; // no geometry
  float farthest = 1.0e30;
  for (int y = first.y; y <= last.y; ++y)
  {
    for (int x = first.x; x <= last.x; ++x)
    {
      vec4 p = texelFetch(aoPositions, ivec2(x, y), 0);
      float z = p.w > 0.0 ? p.z : -1.0e30; // the background: infinitely far
      nearest = p.w > 0.0 ? max(nearest, z) : nearest;
      farthest = min(farthest, z);
    }
  }
  gl_FragData[0] = vec4(nearest, farthest, 0.0, 1.0);
}

void lineAOBlockReachMain()
{
  ivec2 block = ivec2(texCoord * vec2(aoBlockCount));
  float nearest = -1.0e30;
  for (int dy = -1; dy <= 1; ++dy)
  {
    for (int dx = -1; dx <= 1; ++dx)
    {
      ivec2 b = clamp(block + ivec2(dx, dy), ivec2(0), aoBlockCount - 1);
      nearest = max(nearest, texelFetch(aoBlocks, b, 0).x);
    }
  }
  gl_FragData[0] = vec4(nearest, texelFetch(aoBlocks, block, 0).y, 0.0, 1.0);
}

void lineAOCopyMain()
{
  ivec2 pixel = aoPixel();
  gl_FragData[0] = texelFetch(aoColor, pixel, 0);
  gl_FragDepth = texelFetch(aoDepth, pixel, 0).r;
}

void lineAOOcclusionMain()
{
  ivec2 pixel = aoPixel();
  vec4 p = aoViewPoint(pixel);
  float factor = 1.0;
  if (p.w > 0.0) // (the depth test keeps the background out when there is a depth buffer)
  {
    float occlusion = aoOcclusion(pixel, p.xyz, aoNormal(pixel, p.xyz));
    factor = clamp(1.0 - aoStrength * occlusion, 0.0, 1.0);
  }
  gl_FragData[0] = vec4(factor, factor, factor, 1.0);
}

#ifdef LINE_AO_TILES
void lineAOHaloMain()
{
  ivec2 pixel = aoPixel();
  float nearest = texelFetch(aoBlockReach, pixel / aoBlockSize, 0).x;
  gl_FragData[0] = vec4(aoHaloColor, aoHaloCoverage(pixel, aoViewPoint(pixel), nearest));
}
#endif
