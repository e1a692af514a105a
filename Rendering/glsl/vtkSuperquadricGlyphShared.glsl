// Superquadric glyph math shared, as one source, by the glyph shaders and the
// CPU code (vtkSuperquadricGlyphMath.h compiles this text as C++ in double
// precision for the unit tests). Same GLSL/C++ subset rules as
// Filters/glsl/vtkTensorMathShared.glsl; names start with `svq`.
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
// Contents:
//  - svqSemiAxes: semi-axis lengths from eigenvalues and the scale mode;
//  - svqValueGradient: q and its gradient (the analytic normal);
//  - svqClipUnitBox: the ray's parameter interval inside the unit box;
//  - svqIntersect: the first root of f on that interval (Hlawitschka et al.
//    §3.4 Newton iteration, made robust as in Teem's echo/sqd.c: a bracket
//    from the inner unit sphere or from safe Newton steps on the convex f,
//    then Newton on log(1 + f) with a bisection fallback inside the bracket).

//------------------------------------------------------------------------------
// Semi-axis lengths (s1 >= s2 >= s3, along e1, e2, e3) of the glyph of
// eigenvalues l (l1 >= l2 >= l3 >= 0, after the sign policy):
//   scaleMode 0: s = scaleFactor * l
//   scaleMode 1: s = scaleFactor * l / l1           (largest semi-axis = scaleFactor)
//   scaleMode 2: s = scaleFactor * l, uniformly shrunk so that s1 <= maxScale
// then every semi-axis is at least minThickness * s1 (so that planar and
// linear tensors keep a visible, ray-castable thickness).
vec3 svqSemiAxes(vec3 l, int scaleMode, real scaleFactor, real maxScale, real minThickness)
{
  vec3 s = scaleFactor * l;
  if (scaleMode == 1)
  {
    s = vec3(0.0, 0.0, 0.0);
    if (l.x > 0.0)
    {
      s = (scaleFactor / l.x) * l;
    }
  }
  else if (scaleMode == 2)
  {
    if (s.x > maxScale && s.x > 0.0)
    {
      s = (maxScale / s.x) * s;
    }
  }
  real smallest = minThickness * s.x;
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
// in tHit; `evaluations` receives the number of evaluations used.
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
  // it need no evaluation, and it shortens [t0, t1] for the others.
  real outer2 = pow(2.0, 2.0 - alpha - beta);
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
  // Entry into the unit ball (inside the glyph).
  real c = oo - 1.0;
  real disc = b * b - dd * c;
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
