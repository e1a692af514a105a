// SPDX-License-Identifier: BSD-3-Clause
// Superquadric glyph math shared, as one source, by the glyph shaders and the
// CPU code (vtkSuperquadricGlyphMath.h compiles this text as C++ in double
// precision for the unit tests). Same GLSL/C++ subset rules as
// Core/glsl/vtkTensorMathShared.glsl; names start with `svq`.
//
// Glyph space: the glyph of a tensor with semi-axes s (along its frame) is the
// image of the canonical superquadric
//   q(u, v, w) = (|u|^(2/alpha) + |v|^(2/alpha))^(alpha/beta) + |w|^(2/beta) - 1 = 0
// (symmetry axis w) under the glyph frame G = (s_u a_u, s_v a_v, s_w a_w).
// For alpha, beta in (0, 1] the solid q <= 0 is convex, contains the unit
// ball and lies in the unit box [-1, 1]^3 (Hlawitschka et al. §3.3), and in
// the ball of radius 2^(1 - (alpha + beta)/2): with rho the L_(2/alpha) norm
// of (u, v), the glyph is rho^(2/beta) + |w|^(2/beta) <= 1, and the power-mean
// inequality a^2 + b^2 <= 2^(1 - 2/p) (a^p + b^p)^(2/p) (p >= 2) bounds
// u^2 + v^2 + w^2 by 2^(1 - alpha) 2^(1 - beta). q itself is a convex
// function, so along a ray f(t) = q(o + t d) is convex.
//
// The Schultz-Kindlmann glyphs of indefinite tensors
// (Core/glsl/vtkTensorMathShared.glsl, svtSchultzKindlmannShape) add a
// third exponent c and exponents beta, c up to 1/minimumRoundness: the solid
//   |w| < 1 and g(u, v, w) = |u|^(2/alpha) / A(|w|) + |v|^(2/alpha) / B(|w|) < 1,
//   A(W) = (1 - W^(2/beta))^(beta/alpha), B(W) = (1 - W^(2/c))^(c/alpha),
// which is q <= 0 for c = beta. For beta > 1 or c != beta it is neither convex
// nor contains the unit ball, but it still lies in the unit box, is symmetric
// in every coordinate plane and, in every octant, monotone: g increases with
// each of |u|, |v|, |w|. So over any piece of a ray on which no coordinate
// changes sign, g is at least g at the componentwise smallest |coordinates|
// of the piece's end points (and at most g at the largest): an exact lower
// (upper) bound, which svqIntersectGeneral uses to find the first hit
// without missing thin parts (spikes, rims) of the concave shapes.
//
// Contents:
//  - svqSemiAxes: semi-axis lengths from eigenvalues and the scale mode;
//  - svqValueGradient: q and its gradient (the analytic normal);
//  - svqClipUnitBox: the ray's parameter interval inside the unit box;
//  - svqIntersect: the first root of f on that interval (Hlawitschka et al.
//    §3.4 Newton iteration, made robust as in Teem's echo/sqd.c: a bracket
//    from the inner unit sphere or from safe Newton steps on the convex f,
//    then Newton on log(1 + f) with a bisection fallback inside the bracket);
//  - svqGeneralAbs, svqGeneralValueGradient, svqBlendAbs,
//    svqIntersectGeneral: the same for the (alpha, beta, c) solids of any
//    Schultz-Kindlmann glyph and the blends of two of them;
//  - svqIsKindlmann, svqIntersectShape, svqShapeGradient, svqShapeInside:
//    the dispatch between the two (Kindlmann's convex glyphs keep the fast
//    path).

//------------------------------------------------------------------------------
// Semi-axis lengths (along e1, e2, e3) of the glyph of eigenvalues l >= 0
// (after the sign policy; absolute values for the Schultz-Kindlmann glyphs),
// with lmax the largest of them (l1 for sorted l):
//   scaleMode 0: s = scaleFactor * l
//   scaleMode 1: s = scaleFactor * l / lmax          (largest semi-axis = scaleFactor)
//   scaleMode 2: s = scaleFactor * l, uniformly shrunk so that max s <= maxScale
// then every semi-axis is at least minThickness * max s (so that planar and
// linear tensors keep a visible, ray-castable thickness).
vec3 svqSemiAxes(vec3 l, int scaleMode, real scaleFactor, real maxScale, real minThickness)
{
  real lmax = max(max(l.x, l.y), l.z);
  vec3 s = scaleFactor * l;
  if (scaleMode == 1)
  {
    s = vec3(0.0, 0.0, 0.0);
    if (lmax > 0.0)
    {
      s = (scaleFactor / lmax) * l;
    }
  }
  else if (scaleMode == 2)
  {
    real smax = scaleFactor * lmax;
    if (smax > maxScale && smax > 0.0)
    {
      s = (maxScale / smax) * s;
    }
  }
  real smallest = minThickness * max(max(s.x, s.y), s.z);
  return max(s, vec3(smallest, smallest, smallest));
}

//------------------------------------------------------------------------------
// q(x) and its gradient at x = (u, v, w).
real svqValueGradient(vec3 x, real alpha, real beta, SV_OUT(vec3) grad)
{
  real ea = 2.0 / alpha;
  real eb = 2.0 / beta;
  real r = alpha / beta;
  real au = abs(x.x);
  real av = abs(x.y);
  real aw = abs(x.z);
  real pu = pow(au, ea);
  real pv = pow(av, ea);
  real pw = pow(aw, eb);
  real P = pu + pv;
  real Pr = pow(P, r);
  grad = vec3(0.0, 0.0, 0.0);
  if (P > 1e-30)
  {
    // d/du P^r = r P^(r-1) ea |u|^(ea-1) sign(u), with |u|^(ea-1) = pu / |u|.
    real k = r * ea * Pr / P;
    if (au > 0.0)
    {
      grad.x = k * (pu / au) * sign(x.x);
    }
    if (av > 0.0)
    {
      grad.y = k * (pv / av) * sign(x.y);
    }
  }
  if (aw > 0.0)
  {
    grad.z = eb * (pw / aw) * sign(x.z);
  }
  return Pr + pw - 1.0;
}

//------------------------------------------------------------------------------
// Parameter interval [t0, t1] of the ray o + t d inside the unit box.
// Returns false when the ray misses the box.
bool svqClipUnitBox(vec3 o, vec3 d, SV_OUT(real) t0, SV_OUT(real) t1)
{
  t0 = -1e30;
  t1 = 1e30;
  for (int i = 0; i < 3; ++i)
  {
    real oi = o[i];
    real di = d[i];
    if (abs(di) < 1e-30)
    {
      if (abs(oi) > 1.0)
      {
        return false;
      }
    }
    else
    {
      real ta = (-1.0 - oi) / di;
      real tb = (1.0 - oi) / di;
      t0 = max(t0, min(ta, tb));
      t1 = min(t1, max(ta, tb));
    }
  }
  return t0 <= t1;
}

//------------------------------------------------------------------------------
// First intersection (t >= 0) of the ray o + t d with q = 0, at most
// maxEvaluations evaluations of q. Returns true on a hit with its parameter
// in tHit; `evaluations` receives the number of evaluations used. For
// alpha <= 1 and beta <= 2 (q convex; the inner unit ball is used for
// beta <= 1 only).
//
// 1. Clip to the unit box and to the outer ball: [t0, t1] (f(t0) >= 0).
// 2. A bracket [lo, hi] with f(lo) >= 0 >= f(hi) and no root before lo:
//    - if the ray enters the unit ball (inside the glyph) in [t0, t1], hi is
//      that entry point: no evaluation needed;
//    - otherwise Newton steps on the convex f from t0. Each step
//      tn = t - f/f' stays before the first root (f lies above its
//      tangent), so lo = tn is safe; f' >= 0 or tn > t1 prove a miss (the
//      paper's "gradient flips" test, exact here by convexity). A bolder
//      step on log(1 + f) (Teem) is tried at each iteration: if it lands
//      inside (f <= 0) it closes the bracket; if it lands outside while f is
//      still decreasing it is also before the first root and is kept.
//    A Newton step shorter than the tolerance ends the search with a hit
//    (converged from outside). Running out of evaluations
//    without a bracket is reported as a miss
//    (rays grazing the silhouette within the root-finding tolerance).
// 3. Inside the bracket: Newton on log(1 + f) (plain Newton when |f| is
//    small), replaced by bisection whenever the step leaves the bracket;
//    stops when the Newton step or the bracket is shorter than 1e-4 glyph
//    units.
//    A bracket always yields a hit, so grazing rays do not speckle.
bool svqIntersect(vec3 o, vec3 d, real alpha, real beta, int maxEvaluations, SV_OUT(real) tHit,
  SV_OUT(int) evaluations)
{
  evaluations = 0;
  tHit = 0.0;
  real t0;
  real t1;
  if (!svqClipUnitBox(o, d, t0, t1))
  {
    return false;
  }
  real dd = dot(d, d);
  real b = dot(o, d);
  real oo = dot(o, o);
  // The glyph lies in the ball of radius 2^(1 - (alpha + beta)/2) (1 for
  // ellipsoids, the box's corners only for alpha = beta -> 0): rays that miss
  // it need no evaluation, and it shortens [t0, t1] for the others. (For
  // 1 < beta <= 2, still convex, rho^(2/beta) + |w|^(2/beta) <= 1 gives
  // rho^2 + w^2 <= 1 and the radius 2^((1 - alpha)/2).)
  real outer2 = pow(2.0, 1.0 - alpha + max(1.0 - beta, 0.0));
  real discOuter = b * b - dd * (oo - outer2);
  if (!(discOuter > 0.0))
  {
    return false;
  }
  real rootOuter = sqrt(discOuter);
  t0 = max(t0, (-b - rootOuter) / dd);
  t1 = min(t1, (-b + rootOuter) / dd);
  t0 = max(t0, 0.0);
  if (t1 <= t0)
  {
    return false;
  }
  real tTol = 1e-4 / sqrt(dd);

  real lo = t0;
  real hi = -1.0;
  // Entry into the unit ball (inside the glyph for beta <= 1).
  real c = oo - 1.0;
  real disc = beta <= 1.0 ? b * b - dd * c : -1.0;
  if (disc > 0.0)
  {
    real ts = (-b - sqrt(disc)) / dd;
    if (ts >= t0 && ts <= t1)
    {
      hi = ts;
    }
  }

  real t = t0;
  real f = 1.0;
  vec3 g = vec3(0.0, 0.0, 0.0);
  bool haveValue = false;
  if (hi < 0.0)
  {
    bool searching = true;
    while (searching && evaluations < maxEvaluations)
    {
      if (!haveValue)
      {
        f = svqValueGradient(o + t * d, alpha, beta, g);
        evaluations += 1;
      }
      haveValue = false;
      if (f <= 0.0)
      {
        hi = t;
        haveValue = true; // f and g are those at hi
        searching = false;
      }
      else
      {
        real fp = dot(g, d);
        if (fp >= 0.0)
        {
          return false;
        }
        real tn = t - f / fp;
        if (tn > t1)
        {
          return false;
        }
        if (tn - t < tTol)
        {
          // the step vanished: at the surface (Hlawitschka et al. §3.4)
          tHit = tn;
          return true;
        }
        lo = tn;
        real tl = t - (1.0 + f) * log(1.0 + f) / fp;
        t = tn;
        if (tl > tn && tl < t1 && evaluations < maxEvaluations)
        {
          vec3 gNew;
          real fNew = svqValueGradient(o + tl * d, alpha, beta, gNew);
          evaluations += 1;
          if (fNew <= 0.0)
          {
            hi = tl;
            t = tl;
            f = fNew;
            g = gNew;
            haveValue = true;
            searching = false;
          }
          else if (dot(gNew, d) < 0.0)
          {
            lo = tl;
            t = tl;
            f = fNew;
            g = gNew;
            haveValue = true;
          }
        }
      }
    }
    if (hi < 0.0)
    {
      return false;
    }
  }
  else
  {
    // start outside: the outer-ball entry is usually close to the surface
    t = lo;
  }

  // Refinement inside [lo, hi].
  while (hi - lo > tTol && (haveValue || evaluations < maxEvaluations))
  {
    if (!haveValue)
    {
      f = svqValueGradient(o + t * d, alpha, beta, g);
      evaluations += 1;
    }
    haveValue = false;
    real fp = dot(g, d);
    real tn = t - f / fp;
    if (abs(tn - t) < tTol)
    {
      // the Newton step vanished: at the surface
      tHit = t;
      return true;
    }
    if (f > 0.0)
    {
      lo = t;
    }
    else
    {
      hi = t;
    }
    if (f >= 1e-3)
    {
      // outside and far: Newton on log(1 + f) (Teem) when it stays in the
      // bracket, else plain Newton (safe from outside on the convex f)
      real tLog = t - (1.0 + f) * log(1.0 + f) / fp;
      if (tLog > lo && tLog < hi)
      {
        tn = tLog;
      }
    }
    if (!(tn > lo && tn < hi))
    {
      tn = 0.5 * (lo + hi);
    }
    t = tn;
  }
  tHit = clamp(t, lo, hi);
  return true;
}

//------------------------------------------------------------------------------
// The (alpha, beta, c) solids of the Schultz-Kindlmann glyphs.

// g at absolute coordinates (U, V, W) >= 0 (inside: g < 1); 1e30 for W >= 1.
real svqGeneralAbs(real U, real V, real W, vec3 abc)
{
  if (W >= 1.0)
  {
    return 1e30;
  }
  real ea = 2.0 / abc.x;
  real a = pow(1.0 - pow(W, 2.0 / abc.y), abc.y / abc.x);
  real b = pow(1.0 - pow(W, 2.0 / abc.z), abc.z / abc.x);
  return pow(U, ea) / max(a, 1e-30) + pow(V, ea) / max(b, 1e-30);
}

// The blend of the Schultz-Kindlmann band (svtSchultzKindlmannBlend): the
// glyph abc weighted by w and a second glyph blend.xyz weighted by 1 - w,
// with blend.w = w, or w + 2 when the second glyph's symmetry axis is the
// other one of e1, e3 (its u and w swapped). blend.w = 1: abc alone.
// Blended are the radius-like n_i = g_i^(alpha_i / 2) (a norm of (u, v) at
// w = 0) as the harmonic mean: the blend is inside where
//   G = 1 / (w / n_1 + (1 - w) / n_2) < 1,
// so along a ray from the center where n_i grows like s / r_i the blended
// surface is at r = w r_1 + (1 - w) r_2, a continuous motion from one
// surface to the other as w goes from 0 to 1, at the pace of w. (An
// arithmetic blend of g, or of a bounded g / (1 + g), is not continuous: the
// steep g of sharp glyphs saturates, and the points deep inside one glyph and
// far outside the other would all switch at the same w. A geometric one moves
// most of the way at small w.) G increases with |u|, |v|, |w| as the n_i do:
// the bounds of svqIntersectGeneral hold.
real svqBlendAbs(real U, real V, real W, vec3 abc, vec4 blend)
{
  real g = svqGeneralAbs(U, V, W, abc);
  bool swapped = blend.w >= 2.0;
  real w = swapped ? blend.w - 2.0 : blend.w;
  if (w >= 1.0)
  {
    return g;
  }
  vec3 other = vec3(blend.x, blend.y, blend.z);
  real second = swapped ? svqGeneralAbs(W, V, U, other) : svqGeneralAbs(U, V, W, other);
  real n1 = max(pow(g, 0.5 * abc.x), 1e-30);
  real n2 = max(pow(second, 0.5 * other.x), 1e-30);
  return 1.0 / (w / n1 + (1.0 - w) / n2);
}

// g(x) - 1 and the gradient of g at x = (u, v, w) (|w| < 1; the normal).
real svqGeneralValueGradient(vec3 x, vec3 abc, SV_OUT(vec3) grad)
{
  grad = vec3(0.0, 0.0, 0.0);
  real U = abs(x.x);
  real V = abs(x.y);
  real W = min(abs(x.z), 1.0 - 1e-7);
  real ea = 2.0 / abc.x;
  real wb = pow(W, 2.0 / abc.y);
  real wc = pow(W, 2.0 / abc.z);
  real a = max(pow(1.0 - wb, abc.y / abc.x), 1e-30);
  real b = max(pow(1.0 - wc, abc.z / abc.x), 1e-30);
  real pu = pow(U, ea);
  real pv = pow(V, ea);
  if (U > 0.0)
  {
    grad.x = ea * pu / (U * a) * sign(x.x);
  }
  if (V > 0.0)
  {
    grad.y = ea * pv / (V * b) * sign(x.y);
  }
  if (W > 0.0)
  {
    // d(1/A)/dW = (2/alpha) W^(2/beta - 1) (1 - W^(2/beta))^(-beta/alpha - 1)
    grad.z = ea / W * (pu / a * wb / max(1.0 - wb, 1e-30) + pv / b * wc / max(1.0 - wc, 1e-30)) *
      sign(x.z);
  }
  return pu / a + pv / b - 1.0;
}

// The interval after interval (level, index) of the binary subdivision
// svqIntersectGeneral walks (length len), climbing while it would be a left
// child; false when the walk is back at level 0 (no interval is left).
bool svqNextInterval(SV_INOUT(int) index, SV_INOUT(int) level, SV_INOUT(real) len)
{
  index += 1;
  while (level > 0 && (index - 2 * (index / 2)) == 0)
  {
    index = index / 2;
    level -= 1;
    len = 2.0 * len;
  }
  return level != 0;
}

// First point (t >= 0) of the ray o + t d inside the (alpha, beta, c) solid,
// within 3e-4 glyph units, with at most maxEvaluations evaluations of g (on
// random rays: median 30 for hits, 3 for misses; 99.9 % of the rays within
// 150, but rays that run close to a thin rim need hundreds).
// On each piece of [t0, t1] (unit box) between the ray's crossings of the
// coordinate planes, an implicit binary subdivision is walked front to back:
// a sub-interval whose lower bound (g at the smallest |coordinates|) is >= 1
// holds no inside point and is skipped; one whose upper bound is < 1 is
// entirely inside, so the solid starts at its beginning (all before it was
// skipped); the others are split until shorter than the tolerance. No part of
// the solid thicker than the tolerance is missed. Rays that would need more
// evaluations are reported as misses (they graze the surface).
bool svqIntersectGeneral(vec3 o, vec3 d, vec3 abc, vec4 blend, int maxEvaluations,
  SV_OUT(real) tHit, SV_OUT(int) evaluations)
{
  evaluations = 0;
  tHit = 0.0;
  real t0;
  real t1;
  if (!svqClipUnitBox(o, d, t0, t1))
  {
    return false;
  }
  t0 = max(t0, 0.0);
  if (!(t1 > t0))
  {
    return false;
  }
  real tTol = 3e-4 / sqrt(dot(d, d));
  // where the coordinates change sign
  real bx = abs(d.x) > 1e-30 ? -o.x / d.x : -1.0;
  real by = abs(d.y) > 1e-30 ? -o.y / d.y : -1.0;
  real bz = abs(d.z) > 1e-30 ? -o.z / d.z : -1.0;
  real s = t0;
  // the start point itself (a ray starting inside, e.g. at a clipping plane)
  vec3 p0 = abs(o + s * d);
  evaluations += 1;
  if (svqBlendAbs(p0.x, p0.y, p0.z, abc, blend) < 1.0)
  {
    tHit = s;
    return true;
  }
  for (int piece = 0; piece < 4; ++piece)
  {
    real e = t1;
    if (bx > s && bx < e)
    {
      e = bx;
    }
    if (by > s && by < e)
    {
      e = by;
    }
    if (bz > s && bz < e)
    {
      e = bz;
    }
    // walk the subdivision of [s, e]: interval (level, index) is
    // [s + index * len, s + (index + 1) * len], len = (e - s) / 2^level
    real len = e - s;
    int level = 0;
    int index = 0;
    bool walking = true;
    while (walking)
    {
      if (evaluations + 2 > maxEvaluations)
      {
        return false;
      }
      real a = s + real(index) * len;
      real b = a + len;
      vec3 pa = abs(o + a * d);
      vec3 pb = abs(o + b * d);
      vec3 lo = min(pa, pb);
      evaluations += 1;
      if (svqBlendAbs(lo.x, lo.y, lo.z, abc, blend) >= 1.0)
      {
        // nothing inside [a, b]: the next interval (the piece is done when
        // there is none)
        walking = svqNextInterval(index, level, len);
      }
      else
      {
        if (level < 7)
        {
          // (deeper, whole intervals inside are rare: not worth an evaluation)
          vec3 hi = max(pa, pb);
          evaluations += 1;
          if (svqBlendAbs(hi.x, hi.y, hi.z, abc, blend) < 1.0)
          {
            tHit = a; // all of [a, b] is inside, all before it outside
            return true;
          }
        }
        bool descend = len > tTol;
        if (!descend)
        {
          // a leaf: a hit only at an actual inside point (the bound may be
          // loose where g is steep, near spike tips)
          evaluations += 1;
          vec3 pm = abs(o + (a + 0.5 * len) * d);
          if (svqBlendAbs(pm.x, pm.y, pm.z, abc, blend) < 1.0)
          {
            tHit = a + 0.5 * len;
            return true;
          }
          evaluations += 1;
          if (svqBlendAbs(pb.x, pb.y, pb.z, abc, blend) < 1.0)
          {
            tHit = b;
            return true;
          }
          // nothing found: treat as empty (a sliver thinner than the tolerance)
          walking = svqNextInterval(index, level, len);
        }
        else
        {
          level += 1;
          index = 2 * index;
          len = 0.5 * len;
        }
      }
    }
    if (e >= t1)
    {
      return false;
    }
    s = e;
  }
  return false;
}

// The convex glyphs (alpha <= 1, beta <= 2, c = beta: Kindlmann's and the
// Schultz-Kindlmann cones and octahedra) take the fast path.
bool svqIsKindlmann(vec3 abc)
{
  return abc.x <= 1.0 && abc.y <= 2.0 && abc.z == abc.y;
}

// Dispatch: the first hit of the ray with the glyph of exponents abc. Convex
// glyphs with 1 < beta <= 2 get 4 maxEvaluations, the general solids
// 48 maxEvaluations + 32 evaluations (512 for the default
// 10; rays that graze a concave rim over a long stretch need many).
bool svqIntersectShape(vec3 o, vec3 d, vec3 abc, vec4 blend, int maxEvaluations,
  SV_OUT(real) tHit, SV_OUT(int) evaluations)
{
  if (blend.w == 1.0 && svqIsKindlmann(abc))
  {
    // flatter faces (1 < beta <= 2) converge more slowly
    return svqIntersect(
      o, d, abc.x, abc.y, abc.y <= 1.0 ? maxEvaluations : 4 * maxEvaluations, tHit, evaluations);
  }
  return svqIntersectGeneral(o, d, abc, blend, 48 * maxEvaluations + 32, tHit, evaluations);
}

// The (unnormalized) outward normal of the glyph abc (blended with blend) at x.
vec3 svqShapeGradient(vec3 x, vec3 abc, vec4 blend)
{
  vec3 g;
  if (blend.w == 1.0 && svqIsKindlmann(abc))
  {
    svqValueGradient(x, abc.x, abc.y, g);
    return g;
  }
  real f = svqGeneralValueGradient(x, abc, g) + 1.0;
  bool swapped = blend.w >= 2.0;
  real w = swapped ? blend.w - 2.0 : blend.w;
  if (w < 1.0)
  {
    // the gradient of G: with n_i = g_i^(alpha_i / 2), along
    // sum_i w_i grad n_i / n_i^2 = sum_i w_i alpha_i grad g_i / (2 n_i g_i)
    vec3 g2;
    vec3 other = vec3(blend.x, blend.y, blend.z);
    real f2;
    if (swapped)
    {
      f2 = svqGeneralValueGradient(vec3(x.z, x.y, x.x), other, g2) + 1.0;
      g2 = vec3(g2.z, g2.y, g2.x);
    }
    else
    {
      f2 = svqGeneralValueGradient(x, other, g2) + 1.0;
    }
    real n1 = max(pow(max(f, 0.0), 0.5 * abc.x), 1e-30);
    real n2 = max(pow(max(f2, 0.0), 0.5 * other.x), 1e-30);
    g = (w * abc.x / max(n1 * f, 1e-30)) * g + ((1.0 - w) * other.x / max(n2 * f2, 1e-30)) * g2;
  }
  return g;
}

// True when x is inside the glyph abc (blended with blend).
bool svqShapeInside(vec3 x, vec3 abc, vec4 blend)
{
  if (blend.w == 1.0 && svqIsKindlmann(abc))
  {
    vec3 g;
    return svqValueGradient(x, abc.x, abc.y, g) < 0.0;
  }
  vec3 p = abs(x);
  return svqBlendAbs(p.x, p.y, p.z, abc, blend) < 1.0;
}
