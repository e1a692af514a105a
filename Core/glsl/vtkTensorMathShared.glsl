// SPDX-License-Identifier: BSD-3-Clause
// Symmetric 3x3 tensor math shared, as one source, by the glyph shaders and
// the CPU code (vtkSplineVizTensorMath.cxx compiles this very text as C++ in
// double precision with GLM; the superquadric glyph shaders embed it in float).
//
// Written in the common subset of GLSL and C++ (the rules:
// Core/vtkSplineVizSharedGLSL.h). Every name starts with `svt` so that it
// can be embedded next to other SplineViz GLSL.
//
// A symmetric tensor is passed as diag = (xx, yy, zz) and off = (xy, yz, xz)
// (VTK's 6-component order split in two).
//
// Contents:
//  - svtSymmetricEigen: eigenvalues l1 >= l2 >= l3 and a right-handed
//    orthonormal eigenvector frame, robust for repeated eigenvalues (its
//    steps svtIsolatedEigenvector and svtPlaneRestriction are shared with
//    vtkSplineVizTensorMath's PrincipalEigen);
//  - svtFractionalAnisotropy, svtMeanDiffusivity, svtWestinMetrics
//    (trace-normalized, as in Teem: cl = (l1-l2)/S, cp = 2(l2-l3)/S, cs = 3 l3/S);
//  - svtApplySignPolicy: what to do with negative eigenvalues;
//  - svtKindlmannShape: Kindlmann's (2004) superquadric exponents and axis;
//  - svtSchultzKindlmannSquare, svtSchultzKindlmannShape: the glyph shape of
//    any symmetric tensor (Schultz and Kindlmann 2010), definite or not.

//------------------------------------------------------------------------------
// y = T x for the symmetric tensor (diag, off).
vec3 svtSymMul(vec3 diag, vec3 off, vec3 x)
{
  return vec3(diag.x * x.x + off.x * x.y + off.z * x.z, off.x * x.x + diag.y * x.y + off.y * x.z,
    off.z * x.x + off.y * x.y + diag.z * x.z);
}

// Swaps (la, va) and (lb, vb) when la < lb.
void svtOrderPair(SV_INOUT(real) la, SV_INOUT(vec3) va, SV_INOUT(real) lb, SV_INOUT(vec3) vb)
{
  if (la < lb)
  {
    real tl = la;
    la = lb;
    lb = tl;
    vec3 tv = va;
    va = vb;
    vb = tv;
  }
}

//------------------------------------------------------------------------------
// The first half of svtSymmetricEigen, which vtkSplineVizTensorMath's
// PrincipalEigen shares: the scale m, the shift q and the normalization p of
// C = (A/m - qI)/p = (cd, co) and the unit eigenvector u of C's isolated
// eigenvalue. Returns false for a multiple of the identity (the zero tensor
// included), whose eigenvalues are then all in lambda.
bool svtIsolatedEigenvector(vec3 diag, vec3 off, SV_OUT(vec3) lambda, SV_OUT(real) m,
  SV_OUT(real) q, SV_OUT(real) p, SV_OUT(vec3) cd, SV_OUT(vec3) co, SV_OUT(vec3) u)
{
  m = max(max(max(abs(diag.x), abs(diag.y)), abs(diag.z)),
    max(max(abs(off.x), abs(off.y)), abs(off.z)));
  if (!(m > 0.0))
  {
    lambda = vec3(0.0, 0.0, 0.0);
    return false;
  }
  vec3 d = diag / m;
  vec3 o = off / m;
  q = (d.x + d.y + d.z) / 3.0;
  vec3 b = d - vec3(q, q, q);
  real p2 = (dot(b, b) + 2.0 * dot(o, o)) / 6.0;
  if (p2 < 1e-30)
  {
    // A multiple of the identity: every vector is an eigenvector.
    lambda = vec3(m * q, m * q, m * q);
    return false;
  }
  p = sqrt(p2);
  cd = b / p;
  co = o / p;
  real detC = cd.x * (cd.y * cd.z - co.y * co.y) - co.x * (co.x * cd.z - co.y * co.z) +
    co.z * (co.x * co.y - cd.y * co.z);
  real r = clamp(0.5 * detC, -1.0, 1.0);
  real phi = acos(r) / 3.0;
  real betaIsolated = 2.0 * cos(phi);
  if (r < 0.0)
  {
    betaIsolated = 2.0 * cos(phi + 2.0943951023931957);
  }

  // Null vector of C - beta I: the largest cross product of two of its rows.
  vec3 r0 = vec3(cd.x - betaIsolated, co.x, co.z);
  vec3 r1 = vec3(co.x, cd.y - betaIsolated, co.y);
  vec3 r2 = vec3(co.z, co.y, cd.z - betaIsolated);
  vec3 x01 = cross(r0, r1);
  vec3 x02 = cross(r0, r2);
  vec3 x12 = cross(r1, r2);
  real n01 = dot(x01, x01);
  real n02 = dot(x02, x02);
  real n12 = dot(x12, x12);
  u = x01;
  real nu = n01;
  if (n02 > nu)
  {
    u = x02;
    nu = n02;
  }
  if (n12 > nu)
  {
    u = x12;
    nu = n12;
  }
  u = u / sqrt(nu);
  return true;
}

// The restriction of C = (cd, co) to the plane orthogonal to the unit vector
// u: its basis (v, w = u x v) and the symmetric 2x2 matrix [[m00, m01], [m01,
// m11]] in it.
void svtPlaneRestriction(vec3 cd, vec3 co, vec3 u, SV_OUT(vec3) v, SV_OUT(vec3) w,
  SV_OUT(real) m00, SV_OUT(real) m11, SV_OUT(real) m01)
{
  v = svAnyOrthogonal(u);
  w = cross(u, v);
  vec3 cv = svtSymMul(cd, co, v);
  vec3 cw = svtSymMul(cd, co, w);
  m00 = dot(v, cv);
  m11 = dot(w, cw);
  m01 = 0.5 * (dot(v, cw) + dot(w, cv));
}

//------------------------------------------------------------------------------
// Eigen-decomposition of a symmetric tensor.
//
// lambda = (l1, l2, l3) with l1 >= l2 >= l3; e1, e2, e3 the unit eigenvectors,
// mutually orthogonal, with e3 = e1 x e2. For repeated eigenvalues any
// orthonormal basis of the eigenspace is returned (the identity frame for a
// multiple of the identity). The caller rejects non-finite input.
//
// Method: the tensor is scaled by its largest absolute entry and made
// traceless, B = A/m - qI, and normalized, C = B/p with p^2 = tr(B^2)/6. The
// eigenvalues of C are 2 cos(phi + 2k pi/3) with phi = acos(det(C)/2)/3. The
// eigenvalue farthest from the middle one (the largest when det(C) >= 0, the
// smallest otherwise) is separated from both others by at least sqrt(3): its
// eigenvector is the best-conditioned cross product of two rows of C - beta I.
// The two remaining eigenpairs are those of the 2x2 restriction of C to the
// plane orthogonal to it (a Jacobi rotation), which stays exact when they are
// equal. Eigenvalues are Rayleigh quotients of the final vectors.
void svtSymmetricEigen(
  vec3 diag, vec3 off, SV_OUT(vec3) lambda, SV_OUT(vec3) e1, SV_OUT(vec3) e2, SV_OUT(vec3) e3)
{
  e1 = vec3(1.0, 0.0, 0.0);
  e2 = vec3(0.0, 1.0, 0.0);
  e3 = vec3(0.0, 0.0, 1.0);
  real m;
  real q;
  real p;
  vec3 cd;
  vec3 co;
  vec3 u;
  if (!svtIsolatedEigenvector(diag, off, lambda, m, q, p, cd, co, u))
  {
    return;
  }

  // The 2x2 restriction to the plane orthogonal to u, diagonalized by a
  // rotation of angle theta = atan(2 m01, m00 - m11) / 2.
  vec3 v;
  vec3 w;
  real m00;
  real m11;
  real m01;
  svtPlaneRestriction(cd, co, u, v, w, m00, m11, m01);
  real c = 1.0;
  real s = 0.0;
  if (abs(m01) > 1e-30 || abs(m00 - m11) > 1e-30)
  {
    real theta = 0.5 * atan(2.0 * m01, m00 - m11);
    c = cos(theta);
    s = sin(theta);
  }
  vec3 va = normalize(c * v + s * w);
  vec3 vb = cross(u, va);

  real lu = dot(u, svtSymMul(cd, co, u));
  real la = dot(va, svtSymMul(cd, co, va));
  real lb = dot(vb, svtSymMul(cd, co, vb));
  // Sort the three pairs (a 3-element sorting network).
  svtOrderPair(lu, u, la, va);
  svtOrderPair(la, va, lb, vb);
  svtOrderPair(lu, u, la, va);

  lambda = vec3(m * (q + p * lu), m * (q + p * la), m * (q + p * lb));
  e1 = u;
  e2 = va;
  e3 = cross(u, va);
}

//------------------------------------------------------------------------------
// Scalar invariants from the eigenvalues l = (l1, l2, l3).

// Fractional anisotropy sqrt(1/2) |l - mean| ... in [0, 1]; 0 for the zero tensor.
real svtFractionalAnisotropy(vec3 l)
{
  real den = dot(l, l);
  if (!(den > 0.0))
  {
    return 0.0;
  }
  real a = l.x - l.y;
  real b = l.y - l.z;
  real c = l.z - l.x;
  return sqrt(0.5 * (a * a + b * b + c * c) / den);
}

// Mean diffusivity (l1 + l2 + l3) / 3.
real svtMeanDiffusivity(vec3 l)
{
  return (l.x + l.y + l.z) / 3.0;
}

// Westin's linear, planar and spherical anisotropy, normalized by the trace
// S = l1 + l2 + l3 as in Teem (cl + cp + cs = 1 for positive semi-definite
// tensors): cl = (l1 - l2)/S, cp = 2 (l2 - l3)/S, cs = 3 l3/S. All three are
// 0 when S <= 0.
vec3 svtWestinMetrics(vec3 l)
{
  real S = l.x + l.y + l.z;
  if (!(S > 0.0))
  {
    return vec3(0.0, 0.0, 0.0);
  }
  return vec3((l.x - l.y) / S, 2.0 * (l.y - l.z) / S, 3.0 * l.z / S);
}

//------------------------------------------------------------------------------
// Negative eigenvalues. policy 0 (skip): returns false when an eigenvalue is
// negative beyond rounding (l3 < -1e-5 max|l|); slightly negative values are
// set to 0. policy 1 (absolute): the absolute values, re-sorted with their
// eigenvectors (the frame stays right-handed). policy 2 (Schultz-Kindlmann):
// the signed eigenvalues are kept (svtSchultzKindlmannShape draws any sign
// pattern). Returns true when the tensor is to be shown.
bool svtApplySignPolicy(
  int policy, SV_INOUT(vec3) lambda, SV_INOUT(vec3) e1, SV_INOUT(vec3) e2, SV_INOUT(vec3) e3)
{
  real big = max(abs(lambda.x), abs(lambda.z));
  if (policy == 2)
  {
    return true;
  }
  if (policy == 1)
  {
    real l1 = abs(lambda.x);
    real l2 = abs(lambda.y);
    real l3 = abs(lambda.z);
    svtOrderPair(l1, e1, l2, e2);
    svtOrderPair(l2, e2, l3, e3);
    svtOrderPair(l1, e1, l2, e2);
    lambda = vec3(l1, l2, l3);
    e3 = cross(e1, e2);
    return true;
  }
  if (lambda.z < -1e-5 * big)
  {
    return false;
  }
  lambda = max(lambda, vec3(0.0, 0.0, 0.0));
  return true;
}

//------------------------------------------------------------------------------
// Kindlmann's superquadric tensor glyph shape (Kindlmann 2004; Hlawitschka et
// al. §2). From the Westin metrics cl, cp (clamped to [0, 1]) and the
// sharpness gamma:
//   cl > cp (linear):  symmetry axis x (along e1), alpha = (1-cp)^gamma, beta = (1-cl)^gamma
//   otherwise (planar): symmetry axis z (along e3), alpha = (1-cl)^gamma, beta = (1-cp)^gamma
// and the surface about the symmetry axis w, with u, v the two other axes,
//   (|u|^(2/alpha) + |v|^(2/alpha))^(alpha/beta) + |w|^(2/beta) = 1.
// Both cases give the same shape at cl == cp (alpha == beta). alpha and beta
// are clamped to [minimumRoundness, 1] to bound the exponents (and so the
// root-finding work); gamma = 0 gives ellipsoids, large gamma boxes.
// Returns true for the linear case (symmetry axis x).
bool svtKindlmannShape(
  real cl, real cp, real gamma, real minimumRoundness, SV_OUT(real) alpha, SV_OUT(real) beta)
{
  real l = clamp(cl, 0.0, 1.0);
  real p = clamp(cp, 0.0, 1.0);
  bool isLinear = l > p;
  real a = 1.0 - p;
  real b = 1.0 - l;
  if (!isLinear)
  {
    a = 1.0 - l;
    b = 1.0 - p;
  }
  alpha = clamp(pow(max(a, 1e-6), gamma), minimumRoundness, 1.0);
  beta = clamp(pow(max(b, 1e-6), gamma), minimumRoundness, 1.0);
  return isLinear;
}

//------------------------------------------------------------------------------
// Superquadric glyphs for symmetric tensors of any signature: Schultz and
// Kindlmann, "Superquadric Glyphs for Symmetric Second-Order Tensors", IEEE
// TVCG 16(6), 2010, as its authors implement it in Teem (ten/glyph.c:
// tenGlyphBqdUvEval for the shape square of §4.2, tenGlyphBqdAbcUv for the
// superquadric parameters of §4.3) and in Kindlmann's Deft viewer (the
// sharpness). The glyph is the superquadric with exponents (alpha, beta, c)
// about a symmetry axis w, with u, v the two other axes (v along the middle
// eigenvector e2):
//   |w| <= 1 and (|u| / R_beta(w))^(2/alpha) + (|v| / R_c(w))^(2/alpha) <= 1,
//   R_e(w) = (1 - |w|^(2/e))^(e/2),
// which for c = beta is the signed superquadric
//   (|u|^(2/alpha) + |v|^(2/alpha))^(alpha/beta) + |w|^(2/beta) <= 1
// of Barr's parametrization x = (cos^alpha(theta) sin^beta(phi),
// sin^alpha(theta) sin^beta(phi), cos^beta(phi)) with sgn-powers, scaled by
// |l_i| along the eigenvectors. beta <= 1: convex (Kindlmann's glyphs);
// beta = 2: a linear profile (cones, octahedra); beta > 2: concave profiles
// (the pinched "thorn" glyphs of indefinite tensors). T and -T have the same
// glyph (the paper distinguishes them by color).

// The point of the sorted eigenvalues l (l1 >= l2 >= l3) in the shape square
// (u, v) in [0, 1]^2 of Schultz and Kindlmann §4.2: with m = max |l_i| and
// (x, y, z) = l / m, u = (y + 1)/2 and v = (z + 1)/2 - u + 1 when x >= -z
// (positive-dominant: x = 1, the half u + v >= 1 of the square), otherwise the
// point of -T mirrored, (1 - u(-T), 1 - v(-T)). u + v >= 1.5 exactly for
// positive semi-definite tensors, (1, 1) and (0, 0) are the isotropic ones,
// (1/2, 1/2) is diag(1, 0, -1). Returned folded, as (u, v, mirrored): the
// point of the positive-dominant one of T and -T, and mirrored = 1 when that
// is -T (a negative-dominant T: its glyph is that of -T, whose e1 is e3 of T;
// its point in the square is (1 - u, 1 - v)).
//
// traceNormalized = false gives the paper's point. traceNormalized = true
// gives the point that the glyphs use: the definite triangle is
// re-parametrized so that its linear and planar measures are Westin's
// trace-normalized cl = (l1 - l2)/S, cp = 2 (l2 - l3)/S (S = trace) of
// svtKindlmannShape (the paper's, max-normalized, are (l1 - l2)/l1 and
// (l2 - l3)/l1): definite glyphs are then exactly Kindlmann's as drawn by the
// other sign policies; for indefinite positive-dominant tensors with y > 0,
// y is replaced by y (2 + z) / (1 + y (1 + z)), which equals the definite
// side's value 2y/(1+y) at z = 0 and y at the anti-diagonal z = -1 (so the
// placement stays continuous and the negation symmetry is kept).
vec3 svtSchultzKindlmannSquare(vec3 l, bool traceNormalized)
{
  real m = max(abs(l.x), abs(l.z));
  if (!(m > 0.0))
  {
    return vec3(1.0, 1.0, 0.0); // the zero tensor: a sphere
  }
  real x = l.x / m;
  real y = l.y / m;
  real z = l.z / m;
  real mirrored = 0.0;
  if (x + z < 0.0)
  {
    real t = x;
    x = -z;
    y = -y;
    z = -t;
    mirrored = 1.0;
  }
  y = clamp(y, -1.0, 1.0);
  z = clamp(z, -1.0, y);
  if (traceNormalized)
  {
    if (z >= 0.0)
    {
      real S = 1.0 + y + z;
      real yn = (2.0 * y + z) / S;
      z = 3.0 * z / S;
      y = yn;
    }
    else if (y > 0.0)
    {
      y = y * (2.0 + z) / (1.0 + y * (1.0 + z));
    }
  }
  real u = 0.5 * (y + 1.0);
  return vec3(u, 0.5 * (z + 1.0) - u + 1.0, mirrored);
}

// Barycentric coordinates of (u, v) in the triangle (a, b, c) (points given
// as vec3(u, v, 0)).
vec3 svtBarycentric(real u, real v, vec3 a, vec3 b, vec3 c)
{
  real det = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
  real wb = ((u - a.x) * (c.y - a.y) - (c.x - a.x) * (v - a.y)) / det;
  real wc = ((b.x - a.x) * (v - a.y) - (u - a.x) * (b.y - a.y)) / det;
  return vec3(1.0 - wb - wc, wb, wc);
}

// Kindlmann's sharpness applied to one exponent as in Deft's glyph palette:
// e < 1 (convex): e^gamma; e > 2 (concave): 2 + (e - 2) gamma; linear in
// between (so gamma = 1 leaves the paper's shapes, gamma = 0 gives spheres for
// definite and cones for indefinite tensors).
real svtSharpenExponent(real e, real gamma)
{
  if (e < 1.0)
  {
    return pow(max(e, 1e-6), gamma);
  }
  if (e > 2.0)
  {
    return 2.0 + (e - 2.0) * gamma;
  }
  return e;
}

// The Schultz-Kindlmann glyph of the sorted eigenvalues l: exponents
// abc = (alpha, beta, c) and the symmetry axis (returns true for e1, false
// for e3; u is then the other of e1, e3 and v is e2). In the square (placed
// with traceNormalized = true) the positive-dominant half is cut into the
// zones of tenGlyphBqdAbcUv, and (alpha, beta, c) is the barycentric blend of
// the base shapes at the zone's corners (the negative-dominant half is the
// mirror image through -T):
//   ball (1, 1, 1) at (1, 1); cylinder (1, 0, 0) at (1/2, 1) [diag(1,0,0)]
//   and (1, 1/2) [diag(1,1,0)]; (1/2, 1/2, 1/2) at (3/4, 3/4); octahedron
//   (0, 2, 2) and cone (1, 2, 2) at (1/2, 1) and (1, 1/2) seen from the
//   indefinite side; thorn (1, 3, 3) at (1, 0) and (0, 1); and (0, 3, 2) at
//   (1/2, 1/2) [diag(1, 0, -1)];
//   zone 0 (u + v >= 3/2, u < v; axis e1): ball, cylinder, half;
//   zone 1 (u + v >= 3/2, u >= v; axis e3): ball, half, cylinder;
//   zone 2 (2u + v >= 2; axis e3): octahedron, cone, thorn;
//   zone 3 (u > 1/2; axis e3): octahedron, thorn, (0, 3, 2);
//   zone 5 (u <= 1/2; axis e1): cone, (0, 3, 2), thorn.
// Ties are broken as in Teem (where a zero eigenvalue makes the glyph flat,
// the zones on both sides agree up to its thickness), except that the
// definite zones include their edge u + v = 3/2 (a zero smallest
// eigenvalue): positive semi-definite tensors get Kindlmann's glyph, as the
// negative semi-definite ones do in Teem's table.
// Zones 0 and 1 are Kindlmann's rule (alpha = 1 - cp, beta = 1 - cl about e1
// when cl > cp, alpha = 1 - cl, beta = 1 - cp about e3 otherwise) before the
// sharpness. Then every exponent is sharpened by gamma
// (svtSharpenExponent), and alpha is clamped to [minimumRoundness, 1], beta
// and c to [minimumRoundness, 1 / minimumRoundness] (which bounds the
// exponents 2/alpha, 2/beta, 2/c to [2 m, 2 / m]).
bool svtSchultzKindlmannShape(
  vec3 l, real gamma, real minimumRoundness, SV_OUT(vec3) abc)
{
  vec3 s = svtSchultzKindlmannSquare(l, true);
  real u = s.x;
  real v = s.y;
  // Teem's ties on the negative-dominant side, seen in the folded square
  bool mirrored = s.z > 0.5;
  vec3 ball = vec3(1.0, 1.0, 1.0);
  vec3 cylinder = vec3(1.0, 0.0, 0.0);
  vec3 midway = vec3(0.5, 0.5, 0.5);
  vec3 octahedron = vec3(0.0, 2.0, 2.0);
  vec3 cone = vec3(1.0, 2.0, 2.0);
  vec3 thorn = vec3(1.0, 3.0, 3.0);
  vec3 center = vec3(0.0, 3.0, 2.0);
  vec3 p0 = vec3(1.0, 1.0, 0.0);
  vec3 p1 = vec3(0.5, 1.0, 0.0);
  vec3 p2 = vec3(0.75, 0.75, 0.0);
  vec3 p3 = vec3(1.0, 0.5, 0.0);
  vec3 p4 = vec3(1.0, 0.0, 0.0);
  vec3 p5 = vec3(0.5, 0.5, 0.0);
  vec3 p6 = vec3(0.0, 1.0, 0.0);
  bool axisE1 = false;
  vec3 w;
  if (u + v >= 1.5)
  {
    if (u < v || (mirrored && u == v))
    {
      w = svtBarycentric(u, v, p0, p1, p2);
      abc = w.x * ball + w.y * cylinder + w.z * midway;
      axisE1 = true;
    }
    else
    {
      w = svtBarycentric(u, v, p0, p2, p3);
      abc = w.x * ball + w.y * midway + w.z * cylinder;
    }
  }
  else if (u > 0.5 || (mirrored && u == 0.5))
  {
    if (2.0 * u + v >= 2.0)
    {
      w = svtBarycentric(u, v, p1, p3, p4);
      abc = w.x * octahedron + w.y * cone + w.z * thorn;
    }
    else
    {
      w = svtBarycentric(u, v, p1, p4, p5);
      abc = w.x * octahedron + w.y * thorn + w.z * center;
    }
  }
  else
  {
    w = svtBarycentric(u, v, p1, p5, p6);
    abc = w.x * cone + w.y * center + w.z * thorn;
    axisE1 = true;
  }
  real r = max(minimumRoundness, 1e-3);
  abc = vec3(clamp(svtSharpenExponent(abc.x, gamma), r, 1.0),
    clamp(svtSharpenExponent(abc.y, gamma), r, 1.0 / r),
    clamp(svtSharpenExponent(abc.z, gamma), r, 1.0 / r));
  if (mirrored)
  {
    axisE1 = !axisE1; // the glyph of -T: its e1 is e3 of T
  }
  return axisE1;
}

// The glyph of a zero eigenvalue is flat in the paper, so its two sides may
// differ in the flat direction: Kindlmann's glyph on the definite side, the
// cones and octahedra of zone 2 on the indefinite side. With a minimum
// thickness that difference is visible (a jump when a tensor path crosses
// from definite to indefinite). So on the indefinite side, within a band
// |l_near| < bandWidth max |l_i| of the definite edge (l_near = l3 for
// positive-dominant tensors, l1 for negative-dominant ones), the glyph is the
// blend of the two implicit functions,
//   g = w g_SK + (1 - w) g_definite,  w = smoothstep(0, bandWidth, |l_near| / max |l_i|),
// where g_definite is the glyph of the tensor with l_near set to 0 (Kindlmann's
// glyph there, the limit of the definite side). Returns w (1 outside the band:
// the Schultz-Kindlmann glyph alone) and, for w < 1, the definite shape in
// abcDefinite and its axis (true: e1) in axisDefiniteE1.
real svtSchultzKindlmannBlend(vec3 l, real gamma, real minimumRoundness, real bandWidth,
  SV_OUT(vec3) abcDefinite, SV_OUT(bool) axisDefiniteE1)
{
  abcDefinite = vec3(1.0, 1.0, 1.0);
  axisDefiniteE1 = false;
  real m = max(abs(l.x), abs(l.z));
  if (!(m > 0.0) || !(bandWidth > 0.0))
  {
    return 1.0;
  }
  bool negativeDominant = l.x + l.z < 0.0;
  real edge = negativeDominant ? l.x : l.z; // the eigenvalue at the definite edge
  real edgeSign = negativeDominant ? 1.0 : -1.0;
  // only on the indefinite side of the edge
  if (!(edge * edgeSign > 0.0))
  {
    return 1.0;
  }
  real x = abs(edge) / (bandWidth * m);
  if (x >= 1.0)
  {
    return 1.0;
  }
  vec3 flattened = l;
  if (negativeDominant)
  {
    flattened = vec3(0.0, l.y, l.z);
  }
  else
  {
    flattened = vec3(l.x, l.y, 0.0);
  }
  axisDefiniteE1 = svtSchultzKindlmannShape(flattened, gamma, minimumRoundness, abcDefinite);
  return x * x * (3.0 - 2.0 * x);
}
