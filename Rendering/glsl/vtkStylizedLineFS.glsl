// SPDX-License-Identifier: BSD-3-Clause
// Stylized lines (Stoll, Gumhold and Seidel 2005), fragment-stage declarations.
//
// Inserted into VTK's polydata fragment shader (at //VTK::Normal::Dec); the
// rest of that shader (lighting, coloring, clipping, depth peeling, picking,
// shadow maps) is VTK's. lineFragment() runs first: the normal of Eq. 10
// (quads) or of the geometry (fix-up cylinders, caps), the halo test (§4.2),
// the depth-corrected surface point (§4.3, Eq. 11-12) and the texture
// coordinates; lineStyle() then modulates the colors (texture, halo) after
// VTK computed them.

in vec3 lineXVSOutput;
in vec3 lineYVSOutput;
in vec2 lineTexVSOutput;
in vec3 lineFrontVSOutput;
in float lineRadiusVSOutput;
flat in ivec2 lineInfoVSOutput;
flat in vec4 lineSphereVSOutput;
flat in vec4 lineCut0VSOutput; // translucent: the planes of the polyline's ends
flat in vec4 lineCut1VSOutput;
in vec2 lineEndSpanVSOutput; // below 1 on the polyline's first (x) or last (y) segment
#if defined(LINE_COLORS) || defined(LINE_DIRECTION_COLORS)
in vec4 lineColorVSOutput;
#endif
#ifdef LINE_TEXTURE
in vec2 lineUVSOutput;
in vec3 lineFrameVSOutput;
uniform float lineTextureRepeat; // coordinate units per repeat along the line
uniform float lineTextureAround; // repeats per turn around it
uniform int linePattern;         // 1 stripes, 2 arrows, 3 dashes (0 with an actor texture)
uniform int lineNormalMapping;
#endif

#ifdef LINE_SHADOWS
uniform sampler2DShadow lineShadowMap; // the lines' depth seen from the light
uniform mat4 lineShadowMatrix;         // view coordinates to shadow-map coordinates
uniform int lineShadowPass;            // 1 while the shadow map is drawn
uniform float lineShadowBias;          // in shadow-map depth units
uniform float lineShadowTexel;         // one texel in shadow-map coordinates
#endif

uniform mat4 VCDCMatrix;
uniform int lineDepthCorrection;
uniform vec3 lineHaloColor;
uniform float lineHaloDepth; // in radii
uniform float lineHaloDepthRange; // depth-dependent halos: the extra depth at the outer edge, in radii
uniform float lineWiden;          // 1 + halo width

//SV::SplineTubeMath::Dec

//SV::StylizedLineMath::Dec

// A box function of period 1, 1 on [0, duty), anti-aliased over the
// fragment's footprint w (in periods).
float lineBox(float x, float duty, float w)
{
  float s = fract(x);
  float inside = min(s, duty - s);        // > 0 inside: distance to an edge
  float outside = min(s - duty, 1.0 - s); // > 0 outside
  float d = s < duty ? inside : -outside;
  return clamp(0.5 + d / max(w, 1.0e-6), 0.0, 1.0);
}

// The built-in patterns: "ink" in [0, 1] at (u along, v around), both in
// repeats, with their footprints wu, wv.
float linePatternInk(int pattern, float u, float v, float wu, float wv)
{
  if (pattern == 1)
  {
    return lineBox(v, 0.5, wv); // stripes along the line
  }
  if (pattern == 2)
  {
    // An arrow per cell pointing along +u: a shaft, then a head.
    float a = fract(u);
    float b = fract(v) - 0.5;
    float head = min(0.8 * (1.0 - a) - abs(b), a - 0.5);
    float shaft = min(0.1 - abs(b), min(a - 0.1, 0.52 - a));
    float g = max(head, shaft);
    float w = max(0.5 * (wu + wv), 1.0e-6);
    return clamp(0.5 + g / w, 0.0, 1.0);
  }
  return 0.0;
}

// What lineFragment() found, for lineStyle().
bool lineHalo = false; // a halo fragment
float lineInk = 0.0;   // coverage of the built-in pattern
vec4 lineTexel = vec4(1.0); // the actor texture's sample
float lineLit = 1.0;        // the light's share that reaches the point (shadows)

// The per-fragment part of Stoll §4.2-4.3. vertexVC (in: the point of the
// quad or geometry) becomes the surface point (the depth-corrected one for
// quads, pushed back for halos); `normal` receives the surface normal.
void lineFragment(inout vec4 vertexVC, out vec3 normal)
{
  int kind = lineInfoVSOutput.y & 3;
  lineHalo = (lineInfoVSOutput.y & 4) != 0 || (kind == 0 && abs(lineTexVSOutput.y) > 1.0);
  // The interpolated frame vectors are nearly unit (neighbouring vertices'
  // frames are close): Eq. 10 normalizes the sum only (the hot path of
  // every fragment; normalized x, y are made where textures need them).
  vec3 x = lineXVSOutput;
  vec3 y = lineYVSOutput;
  normal = kind == 0 ? slNormal(x, y, lineTexVSOutput.x) : normalize(x);
  if (kind == 3)
  {
    vec3 dir = cameraParallel != 0 ? vec3(0.0, 0.0, -1.0) : normalize(vertexVC.xyz);
    // The joint sphere: the view ray's entry point.
    vec3 origin = cameraParallel != 0 ? vec3(vertexVC.xy, 0.0) : vec3(0.0);
    vec3 oc = origin - lineSphereVSOutput.xyz;
    float b = dot(oc, dir);
    float c = dot(oc, oc) - lineSphereVSOutput.w * lineSphereVSOutput.w;
    float disc = b * b - c;
    if (disc < 0.0)
    {
      discard;
    }
    vec3 hit = origin + (-b - sqrt(disc)) * dir;
    vec3 ns = (hit - lineSphereVSOutput.xyz) / lineSphereVSOutput.w;
    // The wall's normal: the sphere's, mostly orthogonal to the tangent (in
    // y); a tenth of its tangential part keeps it defined (and the sphere's
    // own) where the view looks straight along the line.
    normal = normalize(ns - 0.9 * dot(ns, lineYVSOutput) * lineYVSOutput);
    x = normal;
    y = lineYVSOutput;
    vertexVC.xyz = hit;
  }
  if (lineHalo)
  {
    vec3 dir = cameraParallel != 0 ? vec3(0.0, 0.0, -1.0) : normalize(vertexVC.xyz);
    // Depth-dependent halos (Everts et al. 2009): deeper toward the outer
    // edge (h from 0 at the line's edge to 1), so that a line behind is
    // hidden only over the part of the halo nearer than it.
    float h = clamp((abs(lineTexVSOutput.y) - 1.0) / max(lineWiden - 1.0, 1.0e-6), 0.0, 1.0);
    vertexVC.xyz += ((lineHaloDepth + lineHaloDepthRange * h) * lineRadiusVSOutput) * dir;
  }
  else if (kind == 0 && lineDepthCorrection != 0)
  {
    float s = clamp(lineTexVSOutput.x, -1.0, 1.0);
    vertexVC.xyz += sqrt(max(0.0, 1.0 - s * s)) * lineFrontVSOutput;
  }
  // Translucent: where an end turned to the eye overlaps the quads of its
  // segment, their surface point lies beyond the end's plane and the cap is
  // the line's surface there; drawn, the quad would be a second layer.
  if (kind == 0 && !lineHalo)
  {
    float tolerance = -1.0e-3 * lineRadiusVSOutput;
    if ((lineEndSpanVSOutput.x < 0.999 && dot(lineCut0VSOutput, vertexVC) < tolerance) ||
      (lineEndSpanVSOutput.y < 0.999 && dot(lineCut1VSOutput, vertexVC) < tolerance))
    {
      discard;
    }
  }
#ifdef LINE_TEXTURE
  // u along the line, v around it (a rotation-minimizing frame vector of the
  // line, turned by the orientation angle, is v = 0), both in repeats.
  x = normalize(x);
  float yl = length(y);
  y = yl > 0.0 ? y / yl : svAnyOrthogonal(x);
  float u = lineUVSOutput.x / lineTextureRepeat;
  vec3 t = normalize(cross(y, x));
  vec3 f = lineFrameVSOutput - dot(lineFrameVSOutput, t) * t;
  float fl = length(f);
  f = fl > 0.0 ? f / fl : svAnyOrthogonal(t);
  vec3 g = cross(t, f);
  float cn = dot(normal, f);
  float sn = dot(normal, g);
  float turn = lineTextureAround / 6.283185307179586;
  float v = kind == 2 ? 0.0 : (atan(sn, cn) + lineUVSOutput.y) * turn;
  // The same angle with its seam on the other side, for seam-free footprints.
  float v2 = kind == 2 ? 0.0 : (atan(-sn, -cn) + lineUVSOutput.y) * turn;
  float wu = fwidth(u);
  float wv = min(fwidth(v), fwidth(v2));
  lineInk = linePatternInk(linePattern, u, v, wu, wv);
#ifdef LINE_ACTOR_TEXTURE
  vec2 dx = vec2(dFdx(u), abs(dFdx(v)) < abs(dFdx(v2)) ? dFdx(v) : dFdx(v2));
  vec2 dy = vec2(dFdy(u), abs(dFdy(v)) < abs(dFdy(v2)) ? dFdy(v) : dFdy(v2));
  lineTexel = textureGrad(actortexture, vec2(u, fract(v)), dx, dy);
#endif
  // Bumps: the ink as a height field (a tenth of the radius deep), by the
  // surface gradient of its screen-space derivatives (Mikkelsen 2010).
  float height = 0.1 * lineRadiusVSOutput * lineInk;
  vec3 dpdx = dFdx(vertexVC.xyz);
  vec3 dpdy = dFdy(vertexVC.xyz);
  float dhdx = dFdx(height);
  float dhdy = dFdy(height);
  if (linePattern == 3 && fract(u) >= 0.5)
  {
    discard; // the gaps of dashed lines
  }
  if (lineNormalMapping != 0 && !lineHalo)
  {
#ifdef LINE_ACTOR_TEXTURE
    vec3 m = 2.0 * lineTexel.rgb - vec3(1.0);
    vec3 around = cross(t, normal);
    normal = normalize(m.x * around + m.y * t + m.z * normal);
#else
    vec3 r1 = cross(dpdy, normal);
    vec3 r2 = cross(normal, dpdx);
    float det = dot(dpdx, r1);
    vec3 grad = sign(det) * (dhdx * r1 + dhdy * r2);
    vec3 bumped = abs(det) * normal - grad;
    float bl = length(bumped);
    normal = bl > 0.0 ? bumped / bl : normal;
#endif
  }
#endif
#ifdef LINE_SHADOWS
  // 3x3 percentage-closer filtering of the shadow map; points outside it are lit.
  if (lineShadowPass == 0 && !lineHalo)
  {
    vec4 sc = lineShadowMatrix * vertexVC;
    vec3 s = sc.xyz / sc.w;
    if (s.x >= 0.0 && s.x <= 1.0 && s.y >= 0.0 && s.y <= 1.0 && s.z <= 1.0)
    {
      float lit = 0.0;
      for (int i = -1; i <= 1; ++i)
      {
        for (int j = -1; j <= 1; ++j)
        {
          lit += texture(lineShadowMap,
            vec3(s.xy + lineShadowTexel * vec2(float(i), float(j)), s.z - lineShadowBias));
        }
      }
      lineLit = mix(0.4, 1.0, lit / 9.0);
    }
  }
#endif
#ifdef LINE_PICKING
  if (lineHalo)
  {
    discard; // halos are not part of the line
  }
#endif
}

// Colors after VTK computed them: the halo's own color (unlit), or the
// texture's modulation.
void lineStyle(inout vec3 ambient, inout vec3 diffuse, inout float opacity)
{
  if (lineHalo)
  {
    ambient = lineHaloColor;
    diffuse = vec3(0.0);
    opacity = 1.0;
    return;
  }
#ifdef LINE_TEXTURE
  if (lineNormalMapping == 0)
  {
    vec3 k = (1.0 - 0.7 * lineInk) * lineTexel.rgb;
    ambient *= k;
    diffuse *= k;
    opacity *= lineTexel.a;
  }
#endif
  diffuse *= lineLit;
}
