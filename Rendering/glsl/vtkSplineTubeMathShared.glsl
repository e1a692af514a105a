// SPDX-License-Identifier: BSD-3-Clause
// Spline-tube math shared, as one source, by the shaders and the CPU code.
//
// This file is written in the common subset of GLSL and C++ (with GLM):
// it is embedded into the tube shaders and also compiled as C++ through
// vtkSplineTubeMath.h, so the CPU reference, the unit tests and the GPU run
// the same algorithm (the rules of the subset: Core/vtkSplineVizSharedGLSL.h).
//
// Contents:
//  - cubic Hermite evaluation of (x, y, z, radius) splines (Salm §3);
//  - the split of a cubic segment into C1-continuous quadratic Bezier
//    sub-segments (Salm §3.2), and their oriented bounding boxes;
//  - the ray / quadratic sphere-swept sub-segment intersection of Salm §3.2
//    (roots of polyB by derivative bracketing and bisection, minima of the
//    entry distance f_t on each real interval).

//------------------------------------------------------------------------------
// Cubic Hermite spline through p0 (t = 0) and p1 (t = 1) with derivatives m0, m1.
vec4 svHermite(vec4 p0, vec4 m0, vec4 p1, vec4 m1, real t)
{
  real t2 = t * t;
  real t3 = t2 * t;
  real h00 = 2.0 * t3 - 3.0 * t2 + 1.0;
  real h10 = t3 - 2.0 * t2 + t;
  real h01 = -2.0 * t3 + 3.0 * t2;
  real h11 = t3 - t2;
  return h00 * p0 + h10 * m0 + h01 * p1 + h11 * m1;
}

// Derivative with respect to t of svHermite.
vec4 svHermiteDerivative(vec4 p0, vec4 m0, vec4 p1, vec4 m1, real t)
{
  real t2 = t * t;
  real d00 = 6.0 * t2 - 6.0 * t;
  real d10 = 3.0 * t2 - 4.0 * t + 1.0;
  real d01 = -6.0 * t2 + 6.0 * t;
  real d11 = 3.0 * t2 - 2.0 * t;
  return d00 * p0 + d10 * m0 + d01 * p1 + d11 * m1;
}

// Derivative (with respect to the node parameter) of the splines through a
// tube's nodes at node p, from its neighbours: central differences inside,
// second-order one-sided differences at the tube's first and last node
// (`first`, `last`; they reproduce straight lines and parabolas), the chord
// for a tube of two nodes. prev2, prev, next, next2 are the nodes around p
// (those beyond the tube's ends are not used: `prevIsFirst`, `nextIsLast`
// say where it ends); x, y, z and the radius alike.
vec4 svNodeDerivative(vec4 prev2, vec4 prev, vec4 p, vec4 next, vec4 next2, bool first, bool last,
  bool prevIsFirst, bool nextIsLast)
{
  if (first && last)
  {
    return vec4(0.0, 0.0, 0.0, 0.0);
  }
  if (first)
  {
    return nextIsLast ? next - p : 0.5 * (-3.0 * p + 4.0 * next - next2);
  }
  if (last)
  {
    return prevIsFirst ? p - prev : 0.5 * (3.0 * p - 4.0 * prev + prev2);
  }
  return 0.5 * (next - prev);
}

//------------------------------------------------------------------------------
// Quadratic sub-segments.
//
// A cubic segment c(t), t in [0, 1], is cut into `count` (even) pieces. Each
// pair of pieces covers [a, b] = [2j / count, (2j + 2) / count]; with the
// end values c(a), c(b) and end derivatives d_a = c'(a)(b - a), d_b = c'(b)(b - a)
// of that cubic piece, the two quadratic Bezier curves are
//   (c(a), A, M) and (M, B, c(b)),  A = c(a) + d_a / 4,  B = c(b) - d_b / 4,
//   M = (A + B) / 2.
// They interpolate c at a, b and at the middle (a + b) / 2 (M equals the
// cubic piece's midpoint), match its derivatives at a and b, and meet with a
// common tangent at M: the sub-segments form a C1 quadratic spline through
// the nodes. The radius (w component) is treated the same way; its control
// values are clamped to >= 0 so that the radius never becomes negative.
//
// Sub-segment k covers the cubic parameter range [k / count, (k + 1) / count].
void svSplitSegment(vec4 p0, vec4 m0, vec4 p1, vec4 m1, int count, int k, SV_OUT(vec4) q0,
  SV_OUT(vec4) q1, SV_OUT(vec4) q2)
{
  int pairIndex = k / 2;
  vec4 ca = p0;
  vec4 cb = p1;
  vec4 da = m0;
  vec4 db = m1;
  if (count > 2) // two sub-segments: the pair is the whole segment
  {
    real a = 2.0 * real(pairIndex) / real(count);
    real b = 2.0 * real(pairIndex + 1) / real(count);
    ca = svHermite(p0, m0, p1, m1, a);
    cb = svHermite(p0, m0, p1, m1, b);
    da = (b - a) * svHermiteDerivative(p0, m0, p1, m1, a);
    db = (b - a) * svHermiteDerivative(p0, m0, p1, m1, b);
  }
  vec4 A = ca + 0.25 * da;
  vec4 B = cb - 0.25 * db;
  vec4 M = 0.5 * (A + B);
  if (k - 2 * pairIndex == 0)
  {
    q0 = ca;
    q1 = A;
    q2 = M;
  }
  else
  {
    q0 = M;
    q1 = B;
    q2 = cb;
  }
  q0.w = max(q0.w, 0.0);
  q1.w = max(q1.w, 0.0);
  q2.w = max(q2.w, 0.0);
}

// Quadratic Bezier evaluation and derivative.
vec4 svQuadratic(vec4 q0, vec4 q1, vec4 q2, real l)
{
  real u = 1.0 - l;
  return (u * u) * q0 + (2.0 * u * l) * q1 + (l * l) * q2;
}

vec4 svQuadraticDerivative(vec4 q0, vec4 q1, vec4 q2, real l)
{
  return (2.0 * (1.0 - l)) * (q1 - q0) + (2.0 * l) * (q2 - q1);
}

//------------------------------------------------------------------------------
// Oriented bounding box of the spheres swept along a quadratic sub-segment
// (Salm §3.2 'Rendering'): x axis from start to end point, y axis the
// direction to the control point made orthogonal to x, z = x cross y; on each
// axis the extent is the exact range of (axis . center(l) -+ radius(l)),
// quadratics in l whose extrema are endpoints or the root of a linear equation.
// Collinear and coincident control points fall back to any orthonormal axes.

// Range over l in [0, 1] of the quadratic Bezier with control values c0, c1, c2.
vec2 svQuadraticRange(real c0, real c1, real c2)
{
  real lo = min(c0, c2);
  real hi = max(c0, c2);
  real den = c0 - 2.0 * c1 + c2;
  if (abs(den) > 1e-30)
  {
    real l = (c0 - c1) / den;
    if (l > 0.0 && l < 1.0)
    {
      real u = 1.0 - l;
      real v = u * u * c0 + 2.0 * u * l * c1 + l * l * c2;
      lo = min(lo, v);
      hi = max(hi, v);
    }
  }
  return vec2(lo, hi);
}

struct SvBox
{
  vec3 center; // world (or whatever frame the control points are in)
  vec3 axis0;  // unit axes
  vec3 axis1;
  vec3 axis2;
  vec3 halfSize; // half extents along the axes
};

void svSubSegmentBox(vec4 q0, vec4 q1, vec4 q2, SV_OUT(SvBox) box)
{
  vec3 p0 = vec3(q0);
  vec3 p1 = vec3(q1);
  vec3 p2 = vec3(q2);
  real scale = max(max(length(p1 - p0), length(p2 - p1)), max(max(q0.w, q1.w), q2.w));
  real tiny = 1e-6 * scale + 1e-30;
  vec3 x = p2 - p0;
  if (length(x) <= tiny)
  {
    x = p1 - p0;
  }
  if (length(x) <= tiny)
  {
    x = vec3(1.0, 0.0, 0.0);
  }
  x = normalize(x);
  vec3 y = (p1 - p0) - dot(p1 - p0, x) * x;
  if (length(y) <= tiny)
  {
    y = svAnyOrthogonal(x);
  }
  y = normalize(y);
  vec3 z = cross(x, y);
  box.axis0 = x;
  box.axis1 = y;
  box.axis2 = z;

  vec3 lo;
  vec3 hi;
  for (int i = 0; i < 3; ++i)
  {
    vec3 a = x;
    if (i == 1)
    {
      a = y;
    }
    if (i == 2)
    {
      a = z;
    }
    real c0 = dot(a, p0);
    real c1 = dot(a, p1);
    real c2 = dot(a, p2);
    vec2 upper = svQuadraticRange(c0 + q0.w, c1 + q1.w, c2 + q2.w);
    vec2 lower = svQuadraticRange(c0 - q0.w, c1 - q1.w, c2 - q2.w);
    lo[i] = lower.x;
    hi[i] = upper.y;
  }
  vec3 mid = 0.5 * (lo + hi);
  box.center = mid.x * x + mid.y * y + mid.z * z;
  box.halfSize = 0.5 * (hi - lo);
}

//------------------------------------------------------------------------------
// Inner band of a cubic segment, for occlusion culling (vtkRayCastTubeMapper):
// the largest h such that every point within distance h of the chord
// p0 -> p1 lies inside the union of the spheres swept along the segment's
// `count` quadratic sub-segments (svSplitSegment), the surface the ray caster
// draws. On sub-segment k, covering the chord parameters [a, b] =
// [k / count, (k + 1) / count], the chord is the quadratic Bezier curve
// (L(a), L((a + b) / 2), L(b)), so the distance between the sub-segment's
// centre and the chord at the same parameter is at most the largest distance
// between their control points (convex hull of the Bezier difference), and
// the radius at least the smallest control radius. A point within h of the
// chord point L(t) is then within d + h <= r_min <= r of the centre at t:
// h = r_min - d. Negative: the segment bends too much for a band. `reach`
// is r_max + d: no point of the segment's tube is farther from the chord.
real svInnerBandHalfWidth(vec4 p0, vec4 m0, vec4 p1, vec4 m1, int count, SV_OUT(real) reach)
{
  vec3 a0 = vec3(p0);
  vec3 chord = vec3(p1) - a0;
  real d = 0.0;
  real rMin = 1e30;
  real rMax = 0.0;
  for (int k = 0; k < count; ++k)
  {
    vec4 q0;
    vec4 q1;
    vec4 q2;
    svSplitSegment(p0, m0, p1, m1, count, k, q0, q1, q2);
    real a = real(k) / real(count);
    real b = real(k + 1) / real(count);
    d = max(d, length(vec3(q0) - (a0 + a * chord)));
    d = max(d, length(vec3(q1) - (a0 + (0.5 * (a + b)) * chord)));
    d = max(d, length(vec3(q2) - (a0 + b * chord)));
    rMin = min(rMin, min(q0.w, min(q1.w, q2.w)));
    rMax = max(rMax, max(q0.w, max(q1.w, q2.w)));
  }
  reach = rMax + d;
  return rMin - d;
}

//------------------------------------------------------------------------------
// Ray / sub-segment intersection (Salm §3.2, eqs. 1-8).
//
// In ray space the ray is the x axis. A sphere of center (x, y, z) and
// radius r is entered at s = x - sqrt(r^2 - y^2 - z^2). Along the sub-segment
// the entry distance is f(l) = polyA(l) - sqrt(polyB(l)) with
// polyA = t_x(l) (degree 2) and polyB = t_r^2 - t_y^2 - t_z^2 (degree 4).
// The ray enters the union of the spheres at the smallest f over the set where
// polyB >= 0: at l = 0 or l = 1 (the rounded caps) or at a minimum of f inside
// a real interval, where f'(l) = polyA' - polyB' / (2 sqrt(polyB)) = 0.
//
// 1. The real intervals: the roots of polyB in [0, 1] by Salm's bracketing,
//    polyB''' (linear) and polyB'' (quadratic) analytically, then polyB' and
//    polyB by bisection between consecutive roots of their derivative.
// 2. On each interval, g(l) = 2 polyA' sqrt(polyB) - polyB' has the sign of f'
//    and the same roots but stays finite at the interval ends (where f' is
//    -infinite at a left end and +infinite at a right end, so an interval holds
//    1 or 3 roots, Salm Figs. 15-16). g is sampled at a few points; every
//    - to + change of sign brackets a minimum of f, refined by bisection.

// Polynomial of degree <= 4 in power form: c0 + c1 l + ... + c4 l^4.
struct SvPoly
{
  real c0;
  real c1;
  real c2;
  real c3;
  real c4;
};

real svPolyEval(SvPoly p, real l)
{
  return (((p.c4 * l + p.c3) * l + p.c2) * l + p.c1) * l + p.c0;
}

SvPoly svPolyDerivative(SvPoly p)
{
  SvPoly d;
  d.c0 = p.c1;
  d.c1 = 2.0 * p.c2;
  d.c2 = 3.0 * p.c3;
  d.c3 = 4.0 * p.c4;
  d.c4 = 0.0;
  return d;
}

// The root of p in [lo, hi] by `iterations` bisection steps when p changes
// sign there; otherwise hi. Applied to consecutive brackets this yields a
// sorted list of roots in which a missing root collapses onto its bracket's
// end (an empty interval), so that every loop below has a fixed structure
// and no array is indexed dynamically (which is slow in software renderers).
real svBisectPoly(SvPoly p, real lo, real hi, int iterations)
{
  real flo = svPolyEval(p, lo);
  real fhi = svPolyEval(p, hi);
  if (!((flo < 0.0 && fhi > 0.0) || (flo > 0.0 && fhi < 0.0)))
  {
    return hi;
  }
  for (int it = 0; it < iterations; ++it)
  {
    real mid = 0.5 * (lo + hi);
    real fm = svPolyEval(p, mid);
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

// The real roots of a l^2 + b l + c clamped to [0, 1], sorted (x, y); a
// missing root is 1.
vec2 svQuadraticRoots01(real a, real b, real c)
{
  vec2 r = vec2(1.0, 1.0);
  real scale = max(max(abs(a), abs(b)), abs(c));
  if (abs(a) > 1e-12 * scale)
  {
    real disc = b * b - 4.0 * a * c;
    if (disc > 0.0)
    {
      real sq = sqrt(disc);
      // Numerically stable pair of roots.
      real q = -0.5 * (b + (b >= 0.0 ? sq : -sq));
      real x0 = q / a;
      real x1 = abs(q) > 0.0 ? c / q : x0;
      r = vec2(clamp(min(x0, x1), 0.0, 1.0), clamp(max(x0, x1), 0.0, 1.0));
    }
  }
  else if (abs(b) > 1e-12 * scale)
  {
    r.x = clamp(-c / b, 0.0, 1.0);
  }
  return r;
}

// g(l) = 2 polyA'(l) sqrt(polyB(l)) - polyB'(l), sign of f'(l) where polyB > 0.
real svEntrySlope(SvPoly dA, SvPoly B, SvPoly dB, real l)
{
  return 2.0 * svPolyEval(dA, l) * sqrt(max(svPolyEval(B, l), 0.0)) - svPolyEval(dB, l);
}

// Result of a ray / sub-segment intersection.
struct SvHit
{
  bool hit;      // the ray enters the swept volume at distance `distance` >= 0
  bool inside;   // the ray starts inside the swept volume
  real distance; // along the (unit) ray direction, from the ray origin
  real l;        // curve parameter of the sphere hit, in [0, 1]
};

// Running minimum of the entry distance f over candidates.
struct SvBest
{
  real f;
  real l;
  bool found;
};

SvHit svNoHit()
{
  SvHit result;
  result.hit = false;
  result.inside = false;
  result.distance = 0.0;
  result.l = 0.0;
  return result;
}

// The hit of the smallest entry distance `best` (relative to the ray-space
// origin, `shift` along the ray from the ray origin): inside when negative.
SvHit svHitFromBest(SvBest best, real shift)
{
  SvHit result = svNoHit();
  if (best.found)
  {
    real dist = best.f + shift;
    if (dist < 0.0)
    {
      result.inside = true;
    }
    else
    {
      result.hit = true;
      result.distance = dist;
      result.l = best.l;
    }
  }
  return result;
}

void svConsider(SV_INOUT(SvBest) best, real f, real l)
{
  if (f < best.f)
  {
    best.f = f;
    best.l = l;
    best.found = true;
  }
}

// The minima of f = polyA - sqrt(polyB) on a piece [lo, hi] between two
// consecutive roots of polyB where polyB > 0: the sub-segment ends (caps)
// when the piece touches them, and the - to + changes of sign of g among
// `samples` samples, refined by bisection.
void svPieceMinima(SvPoly A, SvPoly dA, SvPoly B, SvPoly dB, real lo, real hi, int samples,
  int iterations, SV_INOUT(SvBest) best)
{
  if (lo == 0.0)
  {
    svConsider(best, svPolyEval(A, 0.0) - sqrt(max(svPolyEval(B, 0.0), 0.0)), 0.0);
  }
  if (hi == 1.0)
  {
    svConsider(best, svPolyEval(A, 1.0) - sqrt(max(svPolyEval(B, 1.0), 0.0)), 1.0);
  }
  real dl = (hi - lo) / real(samples);
  real prevL = lo;
  real prevG = svEntrySlope(dA, B, dB, lo);
  for (int s = 1; s <= samples; ++s)
  {
    real curL = (s == samples) ? hi : lo + real(s) * dl;
    real curG = svEntrySlope(dA, B, dB, curL);
    if (prevG < 0.0 && curG >= 0.0)
    {
      real a = prevL;
      real b = curL;
      for (int it = 0; it < iterations; ++it)
      {
        real m = 0.5 * (a + b);
        if (svEntrySlope(dA, B, dB, m) < 0.0)
        {
          a = m;
        }
        else
        {
          b = m;
        }
      }
      real lm = 0.5 * (a + b);
      svConsider(best, svPolyEval(A, lm) - sqrt(max(svPolyEval(B, lm), 0.0)), lm);
    }
    prevL = curL;
    prevG = curG;
  }
}

// One step of the scan for the k-th run of positive pieces: piece [a, b]
// with sign `on`; `previous` is the sign of the piece before.
void svRunStep(bool on, SV_INOUT(bool) previous, real a, real b, int k, SV_INOUT(int) seen,
  SV_INOUT(real) lo, SV_INOUT(real) hi, SV_INOUT(bool) picked)
{
  if (on && !previous)
  {
    if (seen == k)
    {
      lo = a;
      picked = true;
    }
    seen = seen + 1;
  }
  if (on && seen - 1 == k)
  {
    hi = b;
  }
  previous = on;
}

// Intersect the ray origin + s * dir (dir of unit length, s >= 0) with the
// spheres swept along the quadratic sub-segment (q0, q1, q2) (xyz center,
// w radius). `rootIterations` bisection steps per root; `samples` (>= 2)
// evaluations of g per real interval to bracket the minima of f.
SvHit svIntersectSubSegment(
  vec3 origin, vec3 dir, vec4 q0, vec4 q1, vec4 q2, int rootIterations, int samples)
{

  // Ray space: x along the ray, y and z across; the origin is moved along the
  // ray next to the sub-segment so that the coordinates stay small.
  vec3 ex = dir;
  vec3 ey = svAnyOrthogonal(ex);
  vec3 ez = cross(ex, ey);
  real shift = dot(vec3(q0) - origin, ex);
  vec3 o = origin + shift * ex;
  vec3 a0 = vec3(q0) - o;
  vec3 a1 = vec3(q1) - o;
  vec3 a2 = vec3(q2) - o;

  // Power-basis coefficients of a quadratic Bezier: c + b l + a l^2.
  vec3 X = vec3(dot(a0, ex), dot(a1, ex), dot(a2, ex));
  vec3 Y = vec3(dot(a0, ey), dot(a1, ey), dot(a2, ey));
  vec3 Z = vec3(dot(a0, ez), dot(a1, ez), dot(a2, ez));
  vec3 R = vec3(q0.w, q1.w, q2.w);
  // (c, b, a) of each component
  vec3 px = vec3(X.x, 2.0 * (X.y - X.x), X.x - 2.0 * X.y + X.z);
  vec3 py = vec3(Y.x, 2.0 * (Y.y - Y.x), Y.x - 2.0 * Y.y + Y.z);
  vec3 pz = vec3(Z.x, 2.0 * (Z.y - Z.x), Z.x - 2.0 * Z.y + Z.z);
  vec3 pr = vec3(R.x, 2.0 * (R.y - R.x), R.x - 2.0 * R.y + R.z);

  SvPoly A;
  A.c0 = px.x;
  A.c1 = px.y;
  A.c2 = px.z;
  A.c3 = 0.0;
  A.c4 = 0.0;
  // polyB = r^2 - y^2 - z^2; the square of (c + b l + a l^2) is
  // c^2 + 2bc l + (b^2 + 2ac) l^2 + 2ab l^3 + a^2 l^4.
  SvPoly B;
  B.c0 = pr.x * pr.x - py.x * py.x - pz.x * pz.x;
  B.c1 = 2.0 * (pr.y * pr.x - py.y * py.x - pz.y * pz.x);
  B.c2 = (pr.y * pr.y + 2.0 * pr.z * pr.x) - (py.y * py.y + 2.0 * py.z * py.x) -
    (pz.y * pz.y + 2.0 * pz.z * pz.x);
  B.c3 = 2.0 * (pr.z * pr.y - py.z * py.y - pz.z * pz.y);
  B.c4 = pr.z * pr.z - py.z * py.z - pz.z * pz.z;

  // Early miss: polyB < 0 on [0, 1] when all its Bernstein coefficients are.
  real b1 = B.c0 + 0.25 * B.c1;
  real b2 = B.c0 + 0.5 * B.c1 + B.c2 / 6.0;
  real b3 = B.c0 + 0.75 * B.c1 + 0.5 * B.c2 + 0.25 * B.c3;
  real b4 = B.c0 + B.c1 + B.c2 + B.c3 + B.c4;
  if (max(max(max(B.c0, b1), max(b2, b3)), b4) < 0.0)
  {
    return svNoHit();
  }

  // 1. Roots of polyB in [0, 1] (Salm's bracketing): the third derivative is
  //    linear and the second quadratic (roots analytic), then the first
  //    derivative and polyB by bisection between the roots of their
  //    derivatives.
  SvPoly dB = svPolyDerivative(B);
  SvPoly ddB = svPolyDerivative(dB);
  vec2 e = svQuadraticRoots01(ddB.c2, ddB.c1, ddB.c0);
  int coarse = max(4, rootIterations / 2);
  real s1 = svBisectPoly(dB, 0.0, e.x, coarse);
  real s2 = svBisectPoly(dB, e.x, e.y, coarse);
  real s3 = svBisectPoly(dB, e.y, 1.0, coarse);
  real t1 = svBisectPoly(B, 0.0, s1, rootIterations);
  real t2 = svBisectPoly(B, s1, s2, rootIterations);
  real t3 = svBisectPoly(B, s2, s3, rootIterations);
  real t4 = svBisectPoly(B, s3, 1.0, rootIterations);

  // 2. The minima of f on the pieces between consecutive roots of polyB
  //    where polyB > 0, joined into the real intervals of polyB (at most 3,
  //    usually 1; a missing root only split an interval at a root of polyB').
  //    The k-th interval is picked by selects, so that the loop runs once per
  //    real interval rather than once per piece (shaders run rays in lock step).
  SvPoly dA = svPolyDerivative(A);
  SvBest best;
  best.f = 1e30;
  best.l = 0.0;
  best.found = false;
  bool on0 = t1 > 0.0 && svPolyEval(B, 0.5 * t1) >= 0.0;
  bool on1 = t2 > t1 && svPolyEval(B, 0.5 * (t1 + t2)) >= 0.0;
  bool on2 = t3 > t2 && svPolyEval(B, 0.5 * (t2 + t3)) >= 0.0;
  bool on3 = t4 > t3 && svPolyEval(B, 0.5 * (t3 + t4)) >= 0.0;
  bool on4 = 1.0 > t4 && svPolyEval(B, 0.5 * (t4 + 1.0)) >= 0.0;
  for (int k = 0; k < 3; ++k)
  {
    // Runs of consecutive positive pieces form the real intervals of polyB.
    int seen = 0;
    real lo = 0.0;
    real hi = 0.0;
    bool picked = false;
    bool previous = false;
    svRunStep(on0, previous, 0.0, t1, k, seen, lo, hi, picked);
    svRunStep(on1, previous, t1, t2, k, seen, lo, hi, picked);
    svRunStep(on2, previous, t2, t3, k, seen, lo, hi, picked);
    svRunStep(on3, previous, t3, t4, k, seen, lo, hi, picked);
    svRunStep(on4, previous, t4, 1.0, k, seen, lo, hi, picked);
    if (!picked)
    {
      break;
    }
    svPieceMinima(A, dA, B, dB, lo, hi, samples, rootIterations, best);
  }

  return svHitFromBest(best, shift);
}

//------------------------------------------------------------------------------
// Straightness: how far the spheres swept along a segment or sub-segment can
// be from those of the round cone on its chord (the straight line between
// its end centres, the radius interpolated linearly between its end radii).
// The difference of two curves at the same parameter bounds the distance
// between the two unions of spheres (each sphere of one lies within that
// distance of a sphere of the other), and the difference of two Bezier
// curves of the same degree is bounded by the largest difference of their
// control points (the chord as a Bezier curve of the same degree).

// A quadratic sub-segment (q0, q1, q2): its difference from the chord is
// 2 l (1 - l) (q1 - (q0 + q2) / 2), at most half of that at l = 1/2.
real svSubSegmentStraightness(vec4 q0, vec4 q1, vec4 q2)
{
  vec4 e = q1 - 0.5 * (q0 + q2);
  return 0.5 * (length(vec3(e)) + abs(e.w));
}

// A cubic Hermite segment (p0, m0, p1, m1): the Bezier control points
// p0 + m0 / 3 and p1 - m1 / 3 against the chord's at 1/3 and 2/3. `reach`:
// no point of the segment's tube is farther from the chord than that.
real svSegmentStraightness(vec4 p0, vec4 m0, vec4 p1, vec4 m1, SV_OUT(real) reach)
{
  vec4 e1 = (p0 + m0 / 3.0) - (p0 + (p1 - p0) / 3.0);
  vec4 e2 = (p1 - m1 / 3.0) - (p0 + 2.0 * (p1 - p0) / 3.0);
  real e = max(length(vec3(e1)), length(vec3(e2))) + max(abs(e1.w), abs(e2.w));
  real rMax = max(max(p0.w, p1.w), max(p0.w + m0.w / 3.0, p1.w - m1.w / 3.0));
  reach = rMax + max(length(vec3(e1)), length(vec3(e2)));
  return e;
}

//------------------------------------------------------------------------------
// Ray / linear sub-segment intersection, in closed form.
//
// The spheres swept along a straight line a -> b with a linearly varying
// radius ra -> rb (a "round cone"): with the ray origin + t dir (dir of unit
// length) and, for the sphere at s in [0, 1], f(s) = A0 + alpha s - sqrt(B(s))
// the entry distance as in svIntersectSubSegment, but now A is linear
// (alpha = (b - a) . dir) and B(s) = beta0 + beta1 s + beta2 s^2 quadratic.
// Where B > 0, f'' = disc / (4 B^(3/2)) with disc = beta1^2 - 4 beta0 beta2,
// so f is convex there when disc > 0, and its only stationary point solves
// B'(s) = 2 alpha sqrt(B(s)); squaring gives B(s*) = disc / (4 kappa) with
// kappa = |b - a|^2 - (rb - ra)^2 (> 0 unless one end sphere contains the
// other, when the union is the larger end sphere), and
// s* = (2 alpha sqrt(B*) - beta1) / (2 beta2)
//    = (beta1^2 - 4 alpha^2 beta0) / (2 kappa (2 alpha sqrt(B*) + beta1))
// (the same number; the form without cancellation is used). The ray
// enters the union at the smallest f among s = 0 and s = 1 (the end spheres,
// where B >= 0) and s* (when in [0, 1]); at the other ends of the intervals
// where B >= 0, f' is infinite and f not minimal.
SvHit svIntersectRoundCone(vec3 origin, vec3 dir, vec4 a, vec4 b)
{
  // Relative to the point of the ray nearest to a (small numbers).
  real shift = dot(vec3(a) - origin, dir);
  vec3 w = vec3(a) - (origin + shift * dir); // a, across the ray
  vec3 u = vec3(b) - vec3(a);
  real alpha = dot(u, dir);
  vec3 uPerp = u - alpha * dir;
  real ra = a.w;
  real delta = b.w - a.w;
  real beta0 = ra * ra - dot(w, w);
  real beta1 = 2.0 * (ra * delta - dot(w, uPerp));
  real beta2 = delta * delta - dot(uPerp, uPerp);
  real B1 = beta0 + beta1 + beta2;

  SvBest best;
  best.f = 1e30;
  best.l = 0.0;
  best.found = false;
  if (beta0 >= 0.0)
  {
    svConsider(best, -sqrt(beta0), 0.0);
  }
  if (B1 >= 0.0)
  {
    svConsider(best, alpha - sqrt(B1), 1.0);
  }
  real kappa = dot(u, u) - delta * delta;
  real disc = beta1 * beta1 - 4.0 * beta0 * beta2;
  if (kappa > 1e-12 * dot(u, u) && disc > 0.0)
  {
    real rootB = sqrt(disc / (4.0 * kappa));
    real q = 2.0 * alpha * rootB;
    real s = 2.0; // none
    if (q * beta1 <= 0.0)
    {
      if (beta2 != 0.0)
      {
        s = (q - beta1) / (2.0 * beta2);
      }
    }
    else
    {
      s = (beta1 * beta1 - 4.0 * alpha * alpha * beta0) / (2.0 * kappa * (q + beta1));
    }
    if (s > 0.0 && s < 1.0)
    {
      svConsider(best, alpha * s - rootB, s);
    }
  }
  return svHitFromBest(best, shift);
}

//------------------------------------------------------------------------------
// Frames for the tessellated tubes (Salm §3.1): the orthogonal vector at
// parameter t is the linear interpolation of the two node vectors, projected
// onto the cross-section plane of tangent `tangent` and normalized.
vec3 svInterpolateFrame(vec3 n0, vec3 n1, real t, vec3 tangent)
{
  vec3 n = (1.0 - t) * n0 + t * n1;
  vec3 tu = normalize(tangent);
  n = n - dot(n, tu) * tu;
  if (length(n) < 1e-12)
  {
    return svAnyOrthogonal(tu);
  }
  return normalize(n);
}

//------------------------------------------------------------------------------
// Tessellated tubes (Salm §3.1): the disk-swept tube surface.
//
// A point of the surface is S(t, a) = c(t) + rho r(t) o(t, a), with c and r the
// position and radius splines, o the unit offset vector at angle a (radians)
// around the axis in the cross-section plane spanned by the orthogonal vector
// n(t) and b = T x n (T the unit tangent), rho = 1 on the wall and in [0, 1]
// on the flat end caps.

// Second derivative with respect to t of svHermite.
vec4 svHermiteSecondDerivative(vec4 p0, vec4 m0, vec4 p1, vec4 m1, real t)
{
  real e00 = 12.0 * t - 6.0;
  real e10 = 6.0 * t - 4.0;
  real e01 = 6.0 - 12.0 * t;
  real e11 = 6.0 * t - 2.0;
  return e00 * p0 + e10 * m0 + e01 * p1 + e11 * m1;
}

// Octahedral encoding of a unit vector into [-1, 1]^2 (the compact format of
// the orthogonal vectors in the tubes buffer, as Salm §5 suggests) and back.
vec2 svOctEncode(vec3 n)
{
  real s = abs(n.x) + abs(n.y) + abs(n.z);
  real x = n.x / s;
  real y = n.y / s;
  if (n.z < 0.0)
  {
    real ox = (1.0 - abs(y)) * (x >= 0.0 ? 1.0 : -1.0);
    real oy = (1.0 - abs(x)) * (y >= 0.0 ? 1.0 : -1.0);
    x = ox;
    y = oy;
  }
  return vec2(x, y);
}

vec3 svOctDecode(vec2 e)
{
  real x = e.x;
  real y = e.y;
  real z = 1.0 - abs(x) - abs(y);
  if (z < 0.0)
  {
    real ox = (1.0 - abs(y)) * (x >= 0.0 ? 1.0 : -1.0);
    real oy = (1.0 - abs(x)) * (y >= 0.0 ? 1.0 : -1.0);
    x = ox;
    y = oy;
  }
  return normalize(vec3(x, y, z));
}

// Unit offset vector at angle `angle` around the unit tangent `unitTangent`,
// from the unit orthogonal vector `n` (angle 0).
vec3 svTubeOffset(vec3 n, vec3 unitTangent, real angle)
{
  vec3 b = cross(unitTangent, n);
  return cos(angle) * n + sin(angle) * b;
}

// Angle of the base-mesh coordinate s in [0, 1] (one turn); s = 1 gives
// exactly the angle of s = 0, so that the mesh closes without a seam.
real svTubeAngle(real s)
{
  return 6.283185307179586 * fract(s);
}

// Point of the tube surface of the segment (p0, m0) -> (p1, m1) (xyz: position
// and its derivative, w: radius and its derivative) with the orthogonal
// vectors f0, f1 at its nodes: curve parameter t, angle `angle`, relative
// radius rho. Also returns the unit offset vector.
vec3 svTubeSurfacePoint(vec4 p0, vec4 m0, vec4 p1, vec4 m1, vec3 f0, vec3 f1, real t, real angle,
  real rho, SV_OUT(vec3) offset)
{
  vec4 c = svHermite(p0, m0, p1, m1, t);
  vec3 d = vec3(svHermiteDerivative(p0, m0, p1, m1, t));
  vec3 tangent = normalize(d);
  vec3 n = svInterpolateFrame(f0, f1, t, d);
  offset = svTubeOffset(n, tangent, angle);
  return vec3(c) + (rho * c.w) * offset;
}

// Normal of the tube wall (Salm Fig. 7): the offset vector projected onto the
// plane of the surface tangent `surfaceTangent` (the derivative of the
// surface point along the curve), normalized.
vec3 svTubeNormal(vec3 offset, vec3 surfaceTangent)
{
  real len = length(surfaceTangent);
  if (len <= 0.0)
  {
    return offset;
  }
  vec3 s = surfaceTangent / len;
  return normalize(offset - dot(offset, s) * s);
}

// Surface tangent of the wall along the curve, analytically, up to a
// component along the angular direction: o stays orthogonal to T, so the part
// of o' along T is -(o . T') T and dS/dt = c' + r' o - r (o . T') T + (twist),
// T' = (c'' - (c'' . T) T) / |c'|. The twist part is orthogonal to the offset
// and to this vector, so svTubeNormal(o, svTubeSurfaceTangent(...)) is the
// exact normal for any frame.
// d, dd: first and second derivative of the position spline; r, dr: radius
// and its derivative; o: unit offset vector.
vec3 svTubeSurfaceTangent(vec3 d, vec3 dd, real r, real dr, vec3 o)
{
  real speed = length(d);
  vec3 tangent = d / speed;
  vec3 dT = (dd - dot(dd, tangent) * tangent) / speed;
  return d + dr * o - (r * dot(o, dT)) * tangent;
}

// Normal of the tube wall at (t, angle) as Salm computes it (Fig. 7): the
// surface tangent along the curve by a central difference of
// svTubeSurfacePoint (step 1/64 of the segment; the cubic is extended beyond
// [0, 1] at the ends), then svTubeNormal. `offset` is the unit offset vector
// at (t, angle). Pass positions relative to a point near the segment (e.g.
// p1 - p0 and a zero p0) so that the difference keeps its precision.
vec3 svTubeWallNormal(
  vec4 p0, vec4 m0, vec4 p1, vec4 m1, vec3 f0, vec3 f1, real t, real angle, vec3 offset)
{
  real h = 0.015625;
  vec3 oa;
  vec3 ob;
  vec3 a = svTubeSurfacePoint(p0, m0, p1, m1, f0, f1, t + h, angle, 1.0, oa);
  vec3 b = svTubeSurfacePoint(p0, m0, p1, m1, f0, f1, t - h, angle, 1.0, ob);
  return svTubeNormal(offset, a - b);
}

//------------------------------------------------------------------------------
// Levels of thin tubes (vtkTessellatedTubeMapper: the control stage's
// single-patch mode on the GPU and the thin-tube draws' classification on the
// CPU, which must agree). A thin tube's wall is the view-facing half of its
// cross-section; along the curve its chords stay within svThinSagittaPixels
// pixels of it on screen and within svThinDepthSagitta radii in space, edges
// at most MaxEdgeLength on screen. A quarter pixel and edges of
// MaxEdgeLength keep the silhouettes of tubes a few pixels wide
// where TestTubeFidelity wants them (IoU >= 0.98 on curved tubes; in a dense
// bundle a silhouette a pixel off shows the tube behind it): half a pixel
// and edges of 4 MaxEdgeLength gave IoU 0.979 on the curls and the depth on
// 95.9 % of a dense bundle, for 3-4 % shorter whole-brain frames.
const real svThinSagittaPixels = 0.25;
const real svThinDepthSagitta = 0.1;
// Inside a run of segments the chords straddle the curve (deviation at most
// half the sagitta, 3/4 next to the run's ends): in space sagittas 1.7 times
// svThinDepthSagitta are admitted (the chords then stay within 0.85 of it,
// 1.3 next to the run's ends); on screen the bound stays (coverage within a
// pixel, TestTessellatedTubeReference). Measured with TestTubeFidelity (depth
// share on cb_2 and the curls) and the triangles of a Fibers2 frame
// (800x600): without straddling 96.9-97.1 %, 934k triangles with the same
// levels; straddling with factor 1 98.1-98.4 %, 934k; 1.7 96.8-97.9 %, 766k.
const real svThinRunStraddle = 1.7;

// The front surface of a thin tube along a fragment's ray, locally the
// infinite cylinder of axis through c along the unit vector a and radius r:
// the smaller s at which the line p + s dir (dir the unit view ray, away from
// the eye) meets it. p lies on the tube's view-facing ribbon (between its
// silhouette lines, so inside or on the cylinder: s <= 0); where the line
// misses the cylinder (p just outside, where the ribbon's chords leave a
// bending tube) the nearest approach; where the line runs along the axis 0,
// and |s| at most `cap` (the surface seen ever more obliquely moves away
// without bound as the ray turns along the axis).
real svCylinderFrontDistance(vec3 p, vec3 dir, vec3 c, vec3 a, real r, real cap)
{
  vec3 w = p - c;
  vec3 wp = w - dot(w, a) * a;
  vec3 dp = dir - dot(dir, a) * a;
  real qa = dot(dp, dp);
  if (qa <= 1e-12)
  {
    return 0.0;
  }
  real qb = dot(wp, dp);
  real qc = dot(wp, wp) - r * r;
  real s = (-qb - sqrt(max(qb * qb - qa * qc, 0.0))) / qa;
  return clamp(s, -cap, cap);
}

// Intervals of `turn` of the circumference of a ring of radius `radius`
// (view units) whose center is at clip w `w`, in steps of `sideLength`
// pixels (pixelScale: pixels per view unit at w = 1), at least `least`, at
// most 64.
real svThinRingLevel(real radius, real w, real pixelScale, real sideLength, real turn, real least)
{
  if (w <= 0.0)
  {
    return 64.0;
  }
  real arc = turn * 6.283185307179586 * radius / w * pixelScale;
  return clamp(ceil(arc / sideLength), least, 64.0);
}

// The fewest intervals of a wall's half ring where the curve's derivative is
// d and the direction to the eye toEye (both nonzero). A ray meets the wall
// of a tube that turns toward the eye obliquely: the depth error of the
// chords (about 1.9 / L^2 radii across the tube) grows by 1 / sin(theta),
// theta the angle between the tangent and the ray, so L grows as
// 1 / sqrt(sin(theta)) from 3 (at most 5, for tubes seen nearly end-on).
real svThinWallLeast(vec3 d, vec3 toEye)
{
  real sine = length(cross(normalize(d), normalize(toEye)));
  return ceil(2.9 / sqrt(max(sine, 0.34)));
}

// Chords of a curve piece with sagitta `sagitta` (view units) needed to keep
// each within svThinSagittaPixels on screen (at clip w `w`) and within
// svThinDepthSagitta of the radius `radius` in space (the sagitta shrinks
// with the square of the number of chords).
real svThinSagittaLevel(real sagitta, real w, real radius, real pixelScale)
{
  real bound =
    min(svThinSagittaPixels * max(w, 0.0) / pixelScale, svThinDepthSagitta * radius);
  return bound > 0.0 ? ceil(sqrt(sagitta / bound)) : 64.0;
}

// How far the cubic Hermite segment (p0, m0, p1, m1) (xyz) deviates from its
// chords over pieces of `interval` of its parameter range: at most 1/8 of
// the largest second derivative times the square of the interval. The
// second derivative is linear in t, so its largest length is at an end:
// 6 (p1 - p0) - 4 m0 - 2 m1 at t = 0, -6 (p1 - p0) + 2 m0 + 4 m1 at t = 1.
// A bound for S-shaped segments too (m0 and m1 parallel and off the chord),
// whose middle lies on the chord; exact for a quadratic.
real svThinSegmentSagitta(vec4 p0, vec4 m0, vec4 p1, vec4 m1, real interval)
{
  vec3 delta = vec3(p1) - vec3(p0);
  real start = length(6.0 * delta - 4.0 * vec3(m0) - 2.0 * vec3(m1));
  real end = length(-6.0 * delta + 2.0 * vec3(m0) + 4.0 * vec3(m1));
  return 0.125 * max(start, end) * interval * interval;
}

// Curvature of a node chain at a node: the turning angle between the chord
// `previous` (length previousLength) and the next chord d (length len) over
// their mean length; 0 where a chord is degenerate.
real svThinChainCurvature(vec3 d, real len, vec3 previous, real previousLength)
{
  if (len <= 0.0 || previousLength <= 0.0)
  {
    return 0.0;
  }
  real turn = acos(clamp(dot(d, previous) / (len * previousLength), -1.0, 1.0));
  return turn / (0.5 * (len + previousLength));
}

//------------------------------------------------------------------------------
// The radius a tube is drawn with at view depth z (z < 0 in front of the eye
// in perspective): its radius r, but at least minimum[0] + minimum[1] (-z),
// the mapper's MinimumPixelWidth as a view-space radius at that distance.
real svDrawnRadius(real r, real z, vec2 minimum)
{
  return max(r, minimum[0] + minimum[1] * max(-z, 0.0));
}
