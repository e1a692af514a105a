// SPDX-License-Identifier: BSD-3-Clause
//VTK::System::Dec

// LR-spline volume ray casting (Fuchs et al. §4), fragment stage.
//
// Every fragment of the proxy box casts the ray of its pixel through the
// patches (data coordinates) from the entry to the exit of the union of the
// patch boxes, clipped by the clipping planes, ended by the opaque geometry
// already drawn (its depth) and, with a trimming surface, kept between the
// surface's nearest front and farthest back face (§4.1). Each sample finds
// the first patch containing it, the element (the previous sample's, else
// the k-d forest or octree of vtkLRSplineElementLocator) and evaluates the
// element's Bezier form exactly, with its gradient (vtkLRSplineVolumeShared.glsl).
//  - the step is adaptive (Eq. 4: the element's shortest side / 2^degree,
//    times lrStepScale) or fixed (lrSampleDistance);
//  - composite: front-to-back (Algorithm 2) with the opacity correction
//    1 - (1 - a)^(ds / unit distance); between two spline samples the
//    transfer function is supersampled at lrSupersampling points of the
//    linear interpolant of the two values (§4.1), against wood-grain;
//    early ray termination at 99 % opacity;
//  - maximum / minimum intensity: the extreme of the samples;
//  - isosurfaces: the crossings of the iso values between two samples,
//    refined by bisection on the exact spline, lit by the exact normal,
//    composited front to back (their depth written for the first one).
// Shading uses the exact gradient: VTK's ambient / diffuse / specular model
// (two-sided, as VTK's volume mappers) or Fuchs' diffuse max(0.4, |l . n|).
// Constants vtkLRSplineVolumeShaderBuilder defines: LR_DU, LR_DV, LR_DW
// (degrees, <= 3), LR_NC (components), LR_COMPONENT (-1: the vector's
// magnitude), LR_BLEND, LR_SHADE, LR_FUCHS, LR_TRIM, LR_SAMPLE_COUNT,
// LR_CURVED, LR_MULTIPASS; the array sizes LR_MAX_PATCHES, LR_ISO and
// LR_CLIP_PLANES; LR_PATCHES (the number of patches), LR_SUPERSAMPLING and
// LR_LIGHTS: loop bounds known at compile time, so that the compiler unrolls
// those loops (llvmpipe caps the loop iterations of a whole invocation at
// 65535, shared by all loops).

//VTK::Output::Dec

//SV::Prelude::Dec

// Patches (data coordinates x = A u + offset; lrPatchInverse is A^-1).
uniform vec3 lrPatchLo[LR_MAX_PATCHES];     // parameter domain
uniform vec3 lrPatchHi[LR_MAX_PATCHES];
uniform mat3 lrPatchInverse[LR_MAX_PATCHES];
uniform vec3 lrPatchOffset[LR_MAX_PATCHES];
uniform vec3 lrPatchEdge[LR_MAX_PATCHES]; // data length of a unit parameter step, per direction
uniform vec3 lrPatchBoxLo[LR_MAX_PATCHES];    // the patch's box, data coordinates
uniform vec3 lrPatchBoxHi[LR_MAX_PATCHES];
uniform int lrPatchBlocks[3 * LR_MAX_PATCHES]; // forest resolution (3 per patch)
uniform int lrPatchStarts[4 * LR_MAX_PATCHES]; // heads, nodes, octree, first element
uniform int lrPatchLocator[LR_MAX_PATCHES];  // 0: forest (k-d tree, texture), 1: octree
#if LR_CURVED
// 1: a curved geometry map (lrPatchLo/Hi: the physical domain of its forest;
// the element boxes are physical, their fourth hi value the shortest side;
// the geometry's coefficients follow the field's per element).
uniform int lrPatchCurved[LR_MAX_PATCHES];
uniform float lrMinimumSide; // the smallest element's shortest side (data units)
#endif

uniform usamplerBuffer lrHeads;
uniform usamplerBuffer lrNodeWords;
uniform samplerBuffer lrNodeSplits;
uniform usamplerBuffer lrOctree;
uniform samplerBuffer lrBoxes;        // per element: lo (xyz) + skip flag, hi (xyz), parameter space
uniform usamplerBuffer lrOffsets;     // per element: first coefficient
uniform samplerBuffer lrCoefficients; // Bernstein coefficients

// The ray.
uniform mat4 lrDCMCMatrix;  // clip space to data coordinates
uniform mat4 lrMCDCMatrix;  // and back
uniform mat3 lrDataToWorld; // lengths in world units (the volume's matrix)
uniform mat3 lrNormalMatrix; // data gradients to world normals (inverse transpose)
uniform vec4 lrViewport;    // x, y, width, height (pixels)
uniform vec3 lrBoxLo;       // all patches (data coordinates)
uniform vec3 lrBoxHi;
uniform sampler2D lrDepth;  // the opaque geometry's depth
uniform int lrNumberOfClipPlanes;
uniform vec4 lrClipPlanes[LR_CLIP_PLANES]; // data coordinates: kept where dot(n, x) + w >= 0
#if LR_TRIM
uniform sampler2D lrTrimFront; // nearest front face of the trimming surface
uniform sampler2D lrTrimBack;  // farthest back face
#endif

// Sampling.
uniform int lrAdaptive;         // Eq. 4 (1) or a fixed step (0)
uniform float lrStepScale;      // times the element's shortest side / 2^degree
uniform float lrSampleDistance; // fixed step, world units
uniform int lrMaxSteps;
uniform float lrJitter;         // 0: none, 1: a random start within the first step

// Transfer functions and lighting.
uniform sampler2D lrTransfer; // RGBA over lrRange
uniform vec2 lrRange;
uniform float lrUnitDistance; // world units
uniform float lrAmbient;
uniform float lrDiffuse;
uniform float lrSpecular;
uniform float lrSpecularPower;
uniform vec3 lrLightDirections[LR_LIGHTS]; // world coordinates, toward each light
uniform vec3 lrLightColors[LR_LIGHTS];     // diffuse color times intensity
uniform float lrIsoValues[LR_ISO];
uniform int lrNumberOfIsoValues;
uniform int lrBisections;

#if LR_MULTIPASS
// Continuation (rays longer than one pass's loop budget, lrMaxSteps samples):
// each pass resumes every unfinished ray from the state the previous pass
// wrote (viewport-sized textures, ping-pong) and writes the new state; a ray
// that ends writes its final color (premultiplied) and depth once.
// Outputs: 0 final color, 1 final depth, 2 accumulated color, 3 ray state
// (t, previous t, previous value, flags: 1 active, 2 previous valid, 4
// found), 4 (previous gradient, extreme or first isosurface depth).
uniform int lrPass;
uniform int lrLastPass; // 1: the samples per ray are used up after this pass
uniform sampler2D lrStateColor;
uniform sampler2D lrStateRay;
uniform sampler2D lrStateExtra;
#endif

uint lrHead(int i)
{
  return texelFetch(lrHeads, i).x;
}
uint lrNodeWord(int i)
{
  return texelFetch(lrNodeWords, i).x;
}
float lrNodeSplit(int i)
{
  return texelFetch(lrNodeSplits, i).x;
}
uint lrOctreeNode(int i)
{
  return texelFetch(lrOctree, i).x;
}
float lrCoefficient(int i)
{
  return texelFetch(lrCoefficients, i).x;
}

//SV::LRSplineVolumeShared::Dec

// The element of the previous sample.
int lrCurrentPatch = -1;
vec3 lrCurrentLo = vec3(1.0);
vec3 lrCurrentHi = vec3(0.0);
int lrCurrentOffset = 0;
bool lrCurrentSkip = false; // the element adds nothing (empty-space skipping)
int lrSamples = 0;
float lrWorldPerData = 1.0; // world length of a data unit along the ray

#if LR_CURVED
int lrCurrentElement = -1;    // curved patches: the element (global index)
vec3 lrCurrentS = vec3(0.5);  // and the local coordinates of the previous sample
mat3 lrCurrentJinv = mat3(1.0);
float lrCurrentW = 1.0;        // the weight and its derivatives (rational maps)
vec3 lrCurrentDW = vec3(0.0);
float lrCurrentSide = 0.0;

// Is x in curved element e (global index) of patch p? Newton from `seed`;
// on success the element becomes the current one.
bool lrTryCurved(int p, int e, vec3 x, vec3 seed)
{
  vec4 lo = texelFetch(lrBoxes, 2 * e);
  vec4 hi = texelFetch(lrBoxes, 2 * e + 1);
  vec3 tol = 1e-5 * (hi.xyz - lo.xyz);
  if (any(lessThan(x, lo.xyz - tol)) || any(greaterThan(x, hi.xyz + tol)))
  {
    return false;
  }
  int offset = int(texelFetch(lrOffsets, e).x);
  int geometry = offset + (LR_DU + 1) * (LR_DV + 1) * (LR_DW + 1) * LR_NC;
  vec3 s = seed;
  mat3 jinv;
  float w;
  vec3 dw;
  if (!lrInvert(geometry, LR_DU, LR_DV, LR_DW, x, 1e-4, s, jinv, w, dw))
  {
    return false;
  }
  lrCurrentW = w;
  lrCurrentDW = dw;
  lrCurrentPatch = p;
  lrCurrentElement = e;
  lrCurrentOffset = offset;
  lrCurrentS = s;
  lrCurrentJinv = jinv;
  lrCurrentSide = hi.w;
  lrCurrentSkip = false;
  return true;
}

// The element of curved patch p containing physical point x: the previous
// sample's, else the candidates of the k-d forest over the physical boxes
// (a leaf or a list leaf: word (3 << 29) | count, then the elements).
bool lrFindCurved(int p, vec3 x)
{
  if (lrCurrentPatch == p && lrCurrentElement >= 0 &&
    lrTryCurved(p, lrCurrentElement, x, lrCurrentS))
  {
    return true;
  }
  ivec4 starts = ivec4(lrPatchStarts[4 * p], lrPatchStarts[4 * p + 1], lrPatchStarts[4 * p + 2],
    lrPatchStarts[4 * p + 3]);
  ivec3 blocks = ivec3(lrPatchBlocks[3 * p], lrPatchBlocks[3 * p + 1], lrPatchBlocks[3 * p + 2]);
  vec3 lo = lrPatchLo[p];
  vec3 hi = lrPatchHi[p];
  ivec3 b;
  for (int d = 0; d < 3; ++d)
  {
    int i = int(floor((x[d] - lo[d]) / (hi[d] - lo[d]) * float(blocks[d])));
    b[d] = clamp(i, 0, blocks[d] - 1);
  }
  uint w = lrHead(starts.x + (b.z * blocks.y + b.y) * blocks.x + b.x);
  int index = -1;
  for (int steps = 0; steps < 64 && (w & LR_LEAF) == 0u; ++steps)
  {
    index = int(w);
    uint node = lrNodeWord(starts.y + index);
    if ((node & LR_LEAF) != 0u || ((node >> 29u) & 3u) == 3u)
    {
      w = node;
      break;
    }
    int dir = int((node >> 29u) & 3u);
    w = x[dir] < lrNodeSplit(starts.y + index) ? (node & LR_CHILD_MASK) : uint(index + 1);
  }
  if ((w & LR_LEAF) != 0u)
  {
    return w != LR_NO_ELEMENT && lrTryCurved(p, int(w & LR_ELEMENT_MASK) + starts.w, x, vec3(0.5));
  }
  if (((w >> 29u) & 3u) != 3u)
  {
    return false;
  }
  int count = int(w & LR_CHILD_MASK);
  for (int k = 1; k <= count; ++k)
  {
    int e = int(lrNodeWord(starts.y + index + k) & LR_ELEMENT_MASK);
    if (lrTryCurved(p, e + starts.w, x, vec3(0.5)))
    {
      return true;
    }
  }
  return false;
}
#endif

// The field's value (component LR_COMPONENT, or the magnitude) and its
// derivatives with respect to the local coordinates.
float lrValue(int offset, vec3 s, out vec3 grad)
{
#if LR_COMPONENT >= 0
  return lrEvaluate(offset, LR_DU, LR_DV, LR_DW, LR_NC, LR_COMPONENT, s, grad);
#else
  float m2 = 0.0;
  vec3 g = vec3(0.0);
  for (int c = 0; c < LR_NC; ++c)
  {
    vec3 gc;
    float v = lrEvaluate(offset, LR_DU, LR_DV, LR_DW, LR_NC, c, s, gc);
    m2 += v * v;
    g += v * gc;
  }
  float m = sqrt(m2);
  grad = m > 0.0 ? g / m : vec3(0.0);
  return m;
#endif
}

// Value, gradient (data coordinates) and the element's shortest side (data
// units) at data point x; false outside every patch.
bool lrSample(vec3 x, out float value, out vec3 gradient, out float minSide)
{
  ++lrSamples;
  int p = -1;
  vec3 u = vec3(0.0);
  for (int q = 0; q < LR_PATCHES; ++q)
  {
#if LR_CURVED
    if (lrPatchCurved[q] != 0)
    {
      if (lrFindCurved(q, x))
      {
        // The field at the inverted point (its coefficients are w f: f =
        // F / W, as the weights are positive also for the magnitude);
        // d/dx = (d/ds) (dx/ds)^-1.
        vec3 gs;
        value = lrValue(lrCurrentOffset, lrCurrentS, gs) / lrCurrentW;
        gs = (gs - value * lrCurrentDW) / lrCurrentW;
        gradient = gs * lrCurrentJinv;
        minSide = lrCurrentSide;
        return true;
      }
      continue;
    }
#endif
    // Points within a rounding tolerance of the domain count as inside and
    // are moved onto it (ray ends computed on the box faces).
    vec3 uq = lrPatchInverse[q] * (x - lrPatchOffset[q]);
    vec3 tol = 1e-5 * (lrPatchHi[q] - lrPatchLo[q]);
    if (all(greaterThanEqual(uq, lrPatchLo[q] - tol)) && all(lessThanEqual(uq, lrPatchHi[q] + tol)))
    {
      p = q;
      u = clamp(uq, lrPatchLo[q], lrPatchHi[q]);
      break;
    }
  }
  if (p < 0)
  {
    return false;
  }
  if (p != lrCurrentPatch || any(lessThan(u, lrCurrentLo)) || any(greaterThan(u, lrCurrentHi)))
  {
    ivec4 starts = ivec4(lrPatchStarts[4 * p], lrPatchStarts[4 * p + 1],
      lrPatchStarts[4 * p + 2], lrPatchStarts[4 * p + 3]);
    ivec3 blocks = ivec3(lrPatchBlocks[3 * p], lrPatchBlocks[3 * p + 1], lrPatchBlocks[3 * p + 2]);
    int e = lrPatchLocator[p] == 0
      ? lrFindForest(u, lrPatchLo[p], lrPatchHi[p], blocks, starts.x, starts.y)
      : lrFindOctree(u, lrPatchLo[p], lrPatchHi[p], starts.z);
    if (e < 0)
    {
      return false;
    }
    e += starts.w;
    lrCurrentPatch = p;
#if LR_CURVED
    lrCurrentElement = -1;
#endif
    vec4 lo = texelFetch(lrBoxes, 2 * e);
    lrCurrentLo = lo.xyz;
    lrCurrentSkip = lo.w > 0.5;
    lrCurrentHi = texelFetch(lrBoxes, 2 * e + 1).xyz;
    lrCurrentOffset = int(texelFetch(lrOffsets, e).x);
  }
  vec3 size = lrCurrentHi - lrCurrentLo;
  vec3 s = clamp((u - lrCurrentLo) / size, 0.0, 1.0);
  vec3 g;
  value = lrValue(lrCurrentOffset, s, g);
  // d/dx = (d/du) A^-1 (a row vector times the inverse).
  gradient = (g / size) * lrPatchInverse[p];
  vec3 side = size * lrPatchEdge[p];
  minSide = min(side.x, min(side.y, side.z));
  return true;
}

vec4 lrTransferFunction(float v)
{
  float t = clamp((v - lrRange.x) / (lrRange.y - lrRange.x), 0.0, 1.0);
  float n = float(textureSize(lrTransfer, 0).x);
  return texture(lrTransfer, vec2((t * (n - 1.0) + 0.5) / n, 0.5));
}

// The color of a sample lit with the gradient (data coordinates), seen
// along `dir` (data coordinates); two-sided: the normal faces the viewer.
vec3 lrShade(vec3 color, vec3 gradient, vec3 dir)
{
#if LR_SHADE
  vec3 nw = lrNormalMatrix * gradient;
  float gl = length(nw);
  if (gl <= 0.0)
  {
    return color;
  }
  vec3 n = nw / gl;
  vec3 toEye = -normalize(lrDataToWorld * dir);
  if (dot(n, toEye) < 0.0)
  {
    n = -n;
  }
#if LR_FUCHS
  // Fuchs' model has one light: the first.
  return color * max(0.4, abs(dot(lrLightDirections[0], n)));
#else
  // VTK's model, summed over the lights (as VTK's volume mappers do).
  vec3 diffuse = vec3(0.0);
  vec3 specular = vec3(0.0);
  for (int i = 0; i < LR_LIGHTS; ++i)
  {
    float d = max(dot(lrLightDirections[i], n), 0.0);
    vec3 h = normalize(lrLightDirections[i] + toEye);
    float sp = d > 0.0 ? pow(max(dot(h, n), 0.0), lrSpecularPower) : 0.0;
    diffuse += d * lrLightColors[i];
    specular += sp * lrLightColors[i];
  }
  return color * (lrAmbient + lrDiffuse * diffuse) + lrSpecular * specular;
#endif
#else
  return color;
#endif
}

// The opacity of a step of `x` unit distances for opacity `a` per unit
// distance, 1 - (1 - a)^x, accurate also for the tiny values of fine steps
// (1 - pow() in single precision loses them: series for small terms).
float lrCorrectedOpacity(float a, float x)
{
  if (a >= 1.0)
  {
    return 1.0;
  }
  float l = a < 0.05 ? -a * (1.0 + a * (0.5 + a * (1.0 / 3.0 + a * 0.25))) : log(1.0 - a);
  float y = x * l; // log(1 - alpha) <= 0
  return y > -0.05 ? -y * (1.0 + y * (0.5 + y * (1.0 / 6.0 + y / 24.0))) : 1.0 - exp(y);
}

// Step length (data units) after a sample in an element of shortest side
// minSide.
float lrStep(float minSide)
{
  if (lrAdaptive != 0)
  {
    return lrStepScale * minSide / float(1 << max(LR_DU, max(LR_DV, LR_DW)));
  }
  return lrSampleDistance / lrWorldPerData;
}

// The ray parameter where the ray leaves the current element.
float lrElementExit(vec3 origin, vec3 dir)
{
  mat3 m = lrPatchInverse[lrCurrentPatch];
  vec3 u0 = m * (origin - lrPatchOffset[lrCurrentPatch]);
  vec3 ud = m * dir;
  vec3 ta = (lrCurrentLo - u0) / ud;
  vec3 tb = (lrCurrentHi - u0) / ud;
  vec3 tf = max(ta, tb);
  return min(min(tf.x, tf.y), tf.z);
}

// The next ray parameter after t inside some patch box (the ray crosses a gap
// between patches), or 1e30 for none.
float lrNextEntry(vec3 origin, vec3 dir, float t, float eps)
{
  float next = 1e30;
  for (int q = 0; q < LR_PATCHES; ++q)
  {
    vec3 ta = (lrPatchBoxLo[q] - origin) / dir;
    vec3 tb = (lrPatchBoxHi[q] - origin) / dir;
    vec3 tn = min(ta, tb);
    vec3 tf = max(ta, tb);
    float a = max(max(tn.x, tn.y), tn.z);
    float b = min(min(tf.x, tf.y), tf.z);
    if (b > t + eps && b > a)
    {
      next = min(next, max(a, t + eps));
    }
  }
  return next;
}

// The ray parameter where the ray meets window depth `depth` (clip space z).
float lrRayDepth(vec2 ndc, float depth, vec3 origin, vec3 dir)
{
  vec4 p = lrDCMCMatrix * vec4(ndc, 2.0 * depth - 1.0, 1.0);
  return dot(p.xyz / p.w - origin, dir);
}

// The ray's march: what the samples so far left (carried from pass to pass
// by the multi-pass continuation).
struct LrMarch
{
  vec4 result;     // composited color (premultiplied)
  float extreme;   // maximum / minimum intensity
  bool found;      // an extreme or an isosurface was met
  float t;         // the next sample's ray parameter
  float prevT;     // the previous sample's
  float prevValue; // and its value and gradient
  vec3 prevGradient;
  bool prevValid; // the previous sample was inside a patch
  float hitDepth; // window depth of the first isosurface
};

// The interval [t0, t1] of the ray (origin, dir) through pixel `pixel` (ndc:
// its normalized device coordinates) that is sampled: the union box, the
// opaque geometry, the clipping planes and the trimming surface. Discards the
// fragment when the interval is empty.
void lrRayInterval(vec2 ndc, ivec2 pixel, vec3 origin, vec3 dir, out float t0, out float t1)
{
  vec3 inv = 1.0 / dir;
  vec3 ta = (lrBoxLo - origin) * inv;
  vec3 tb = (lrBoxHi - origin) * inv;
  vec3 tmin = min(ta, tb);
  vec3 tmax = max(ta, tb);
  t0 = max(max(tmin.x, tmin.y), max(tmin.z, 0.0));
  t1 = min(min(tmax.x, tmax.y), tmax.z);
  t1 = min(t1, lrRayDepth(ndc, texelFetch(lrDepth, pixel, 0).r, origin, dir));
  for (int i = 0; i < lrNumberOfClipPlanes; ++i)
  {
    float denom = dot(lrClipPlanes[i].xyz, dir);
    float dist = dot(lrClipPlanes[i].xyz, origin) + lrClipPlanes[i].w;
    if (abs(denom) < 1e-20)
    {
      if (dist < 0.0)
      {
        discard;
      }
      continue;
    }
    float t = -dist / denom;
    if (denom > 0.0)
    {
      t0 = max(t0, t);
    }
    else
    {
      t1 = min(t1, t);
    }
  }
#if LR_TRIM
  float front = texelFetch(lrTrimFront, pixel, 0).r;
  float back = texelFetch(lrTrimBack, pixel, 0).r;
  if (front >= 1.0 || back <= 0.0)
  {
    discard; // the trimming surface does not cover this pixel
  }
  t0 = max(t0, lrRayDepth(ndc, front, origin, dir));
  t1 = min(t1, lrRayDepth(ndc, back, origin, dir));
#endif
  if (!(t1 > t0))
  {
    discard;
  }
}

#if LR_MULTIPASS
// The state the previous pass left for this pixel's ray; discards the
// fragment of a ray that has ended.
void lrResume(ivec2 pixel, inout LrMarch m)
{
  vec4 ray = texelFetch(lrStateRay, pixel, 0);
  int flags = int(ray.w + 0.5);
  if ((flags & 1) == 0)
  {
    discard; // ended in an earlier pass (or never started)
  }
  vec4 extra = texelFetch(lrStateExtra, pixel, 0);
  m.result = texelFetch(lrStateColor, pixel, 0);
  m.t = ray.x;
  m.prevT = ray.y;
  m.prevValue = ray.z;
  m.prevValid = (flags & 2) != 0;
  m.found = (flags & 4) != 0;
  m.prevGradient = extra.xyz;
  m.extreme = extra.w;
  m.hitDepth = extra.w;
}
#endif

#if LR_BLEND == 0
// Front-to-back compositing of [m.prevT, m.t] (the sample there: value,
// gradient), the transfer function supersampled along the linear
// interpolant of the two values.
void lrCompositeInterval(inout LrMarch m, float value, vec3 gradient, vec3 dir)
{
  float ds = (m.t - m.prevT) * lrWorldPerData / float(LR_SUPERSAMPLING);
  for (int k = 0; k < LR_SUPERSAMPLING; ++k)
  {
    float f = (float(k) + 0.5) / float(LR_SUPERSAMPLING);
    vec4 c = lrTransferFunction(mix(m.prevValue, value, f));
    float alpha = lrCorrectedOpacity(c.a, ds / lrUnitDistance);
    vec3 shaded = lrShade(c.rgb, mix(m.prevGradient, gradient, f), dir);
    m.result.rgb += (1.0 - m.result.a) * alpha * shaded;
    m.result.a += (1.0 - m.result.a) * alpha;
  }
}
#endif

#if LR_BLEND == 5
// The ray parameter where the spline crosses iso value c in [lo, hi] (flo:
// the value minus c at lo), by bisection on the exact spline.
float lrIsoRoot(vec3 origin, vec3 dir, float c, float lo, float hi, float flo)
{
  for (int it = 0; it < lrBisections; ++it)
  {
    float mid = 0.5 * (lo + hi);
    float v;
    vec3 g;
    float side;
    float fm = lrSample(origin + mid * dir, v, g, side) ? v - c : flo;
    if ((fm < 0.0) == (flo < 0.0))
    {
      lo = mid;
      flo = fm;
    }
    else
    {
      hi = mid;
    }
  }
  return 0.5 * (lo + hi);
}

// The isosurfaces crossed in (m.prevT, m.t] (a value met exactly at a sample
// counts once, arriving; value: the sample at m.t), composited nearest
// first; the depth of the first one.
void lrCompositeIsosurfaces(inout LrMarch m, float value, vec3 origin, vec3 dir)
{
  float roots[LR_ISO];
  int which[LR_ISO];
  int count = 0;
  for (int i = 0; i < lrNumberOfIsoValues; ++i)
  {
    float c = lrIsoValues[i];
    if ((m.prevValue - c) * (value - c) < 0.0 || (value == c && m.prevValue != c))
    {
      // Insertion into the sorted list.
      float root = lrIsoRoot(origin, dir, c, m.prevT, m.t, m.prevValue - c);
      int k = count;
      while (k > 0 && roots[k - 1] > root)
      {
        roots[k] = roots[k - 1];
        which[k] = which[k - 1];
        --k;
      }
      roots[k] = root;
      which[k] = i;
      ++count;
    }
  }
  for (int k = 0; k < count; ++k)
  {
    float v;
    vec3 g;
    float side;
    lrSample(origin + roots[k] * dir, v, g, side);
    vec4 c = lrTransferFunction(lrIsoValues[which[k]]);
    vec3 shaded = lrShade(c.rgb, g, dir);
    m.result.rgb += (1.0 - m.result.a) * c.a * shaded;
    m.result.a += (1.0 - m.result.a) * c.a;
    if (!m.found)
    {
      m.found = true;
      vec4 clip = lrMCDCMatrix * vec4(origin + roots[k] * dir, 1.0);
      m.hitDepth = 0.5 * (gl_DepthRange.diff * (clip.z / clip.w) + gl_DepthRange.near +
        gl_DepthRange.far);
#if !LR_MULTIPASS
      gl_FragDepth = m.hitDepth;
#endif
    }
  }
}
#endif

// Takes a sample (valid: inside a patch) as the previous one; maximum and
// minimum intensity keep their extreme.
void lrKeepSample(inout LrMarch m, bool valid, float value, vec3 gradient)
{
  if (valid)
  {
#if LR_BLEND == 1
    m.extreme = max(m.extreme, value);
    m.found = true;
#elif LR_BLEND == 2
    m.extreme = min(m.extreme, value);
    m.found = true;
#endif
    m.prevValue = value;
    m.prevGradient = gradient;
  }
  m.prevValid = valid;
  m.prevT = m.t;
}

// The next sample's ray parameter after the sample at m.t (valid: inside a
// patch, in an element of shortest side minSide); eps: the interval's
// rounding tolerance.
void lrAdvance(inout LrMarch m, bool valid, float minSide, float eps, vec3 origin, vec3 dir)
{
  if (valid && lrCurrentSkip)
  {
    // Empty-space skipping: by the convex hull property of the Bezier
    // form the element's values lie in its coefficients' range, over which
    // the transfer function is transparent (or which holds no iso value):
    // jump to its exit; nothing is composited across it.
    m.t = max(lrElementExit(origin, dir), m.t) + 10.0 * eps;
    m.prevValid = false;
  }
  else
  {
    m.t = valid ? m.t + max(lrStep(minSide), eps) : lrNextEntry(origin, dir, m.t, 10.0 * eps);
#if LR_CURVED
    // A curved patch does not fill its box: outside points inside the
    // boxes advance by the finest step.
    if (!valid)
    {
      m.t = max(m.t, m.prevT + max(lrStep(lrMinimumSide), eps));
    }
#endif
  }
}

// The fragment's outputs once the march stops (done: the ray has ended,
// not cut by the step budget).
void lrWriteOutputs(LrMarch m, bool done)
{
  vec4 result = m.result;
#if LR_MULTIPASS
  if (!done && lrLastPass == 0)
  {
    // Cut by this pass's budget: the state for the next pass.
    gl_FragData[0] = vec4(0.0);
    gl_FragData[1] = vec4(1.0);
    gl_FragData[2] = result;
    gl_FragData[3] = vec4(m.t, m.prevT, m.prevValue,
      float(1 + (m.prevValid ? 2 : 0) + (m.found ? 4 : 0)));
    gl_FragData[4] = vec4(m.prevGradient, LR_BLEND == 5 ? m.hitDepth : m.extreme);
    return;
  }
#endif
#if LR_SAMPLE_COUNT
  // The number of spline evaluations, as a 24-bit integer in RGB.
  gl_FragData[0] = vec4(float(lrSamples % 256) / 255.0, float((lrSamples / 256) % 256) / 255.0,
    float((lrSamples / 65536) % 256) / 255.0, 1.0);
  return;
#endif
#if LR_BLEND == 1 || LR_BLEND == 2
  if (!m.found)
  {
    discard;
  }
  vec4 c = lrTransferFunction(m.extreme);
  result = vec4(c.rgb * c.a, c.a);
#endif
#if LR_BLEND == 5
  if (!m.found)
  {
    discard;
  }
#endif
  if (result.a <= 0.0)
  {
    discard;
  }
#if LR_MULTIPASS
  // Ended in this pass: its final color and depth; the state says inactive.
  gl_FragData[0] = result;
  gl_FragData[1] = vec4(m.hitDepth);
  gl_FragData[2] = vec4(0.0);
  gl_FragData[3] = vec4(0.0);
  gl_FragData[4] = vec4(0.0);
#else
  gl_FragData[0] = result; // premultiplied: blended as src + (1 - src.a) dst
#endif
}

void main()
{
  vec2 ndc = 2.0 * (gl_FragCoord.xy - lrViewport.xy) / lrViewport.zw - 1.0;
  ivec2 pixel = ivec2(gl_FragCoord.xy - lrViewport.xy);
#if LR_BLEND == 5
  gl_FragDepth = gl_FragCoord.z;
#endif
  vec4 a = lrDCMCMatrix * vec4(ndc, -1.0, 1.0);
  vec4 b = lrDCMCMatrix * vec4(ndc, 1.0, 1.0);
  vec3 origin = a.xyz / a.w;
  vec3 dir = normalize(b.xyz / b.w - origin);
  // World length of a data unit along the ray (opacity correction).
  lrWorldPerData = length(lrDataToWorld * dir);
  float t0;
  float t1;
  lrRayInterval(ndc, pixel, origin, dir, t0, t1);

  LrMarch m;
  m.result = vec4(0.0);
  m.extreme = LR_BLEND == 2 ? 1e30 : -1e30;
  m.found = false;
  m.t = t0;
  m.prevT = t0;
  m.prevValue = 0.0;
  m.prevGradient = vec3(0.0);
  m.prevValid = false;
  m.hitDepth = 1.0;
  float value;
  vec3 gradient;
  float minSide;
  bool done = false; // the ray has ended (not cut by the step budget)
  bool resume = false;
#if LR_MULTIPASS
  if (lrPass > 0)
  {
    lrResume(pixel, m);
    resume = true;
  }
#endif
  // A random start within the first step (VTK's jittering).
  if (lrJitter > 0.0 && !resume)
  {
    float r = fract(sin(dot(gl_FragCoord.xy, vec2(12.9898, 78.233))) * 43758.5453);
    if (lrSample(origin + m.t * dir, value, gradient, minSide))
    {
      m.t = min(t1, m.t + r * lrStep(minSide));
    }
  }
  for (int step = 0; step < lrMaxSteps; ++step)
  {
    bool last = m.t >= t1;
    m.t = min(m.t, t1);
    bool valid = lrSample(origin + m.t * dir, value, gradient, minSide);
    if (valid && m.prevValid && m.t > m.prevT)
    {
#if LR_BLEND == 0
      lrCompositeInterval(m, value, gradient, dir);
#elif LR_BLEND == 5
      lrCompositeIsosurfaces(m, value, origin, dir);
#endif
#if LR_BLEND == 0 || LR_BLEND == 5
      if (m.result.a > 0.99)
      {
        done = true; // early ray termination
        break;
      }
#endif
    }
    lrKeepSample(m, valid, value, gradient);
    if (last)
    {
      done = true;
      break;
    }
    lrAdvance(m, valid, minSide, 1e-6 * (t1 - t0), origin, dir);
    if (m.t > 1e29)
    {
      done = true;
      break;
    }
  }
  lrWriteOutputs(m, done);
}
