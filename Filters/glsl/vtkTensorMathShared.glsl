// Symmetric 3x3 tensor math shared, as one source, by the glyph shaders and
// the CPU code (vtkSplineVizTensorMath.cxx compiles this very text as C++ in
// double precision with GLM; the superquadric glyph shaders embed it in float).
//
// Written in the common subset of GLSL and C++ (same rules as
// Rendering/glsl/vtkSplineTubeMath.glsl): `real` for scalars, vec3 of real,
// SV_OUT(T)/SV_INOUT(T) for output parameters, real literals with a decimal
// point, single-component swizzles only, no recursion. Every name starts with
// `svt` so that it can be embedded next to other SplineViz GLSL.
//
// A symmetric tensor is passed as diag = (xx, yy, zz) and off = (xy, yz, xz)
// (VTK's 6-component order split in two).
//
// Contents:
//  - svtSymmetricEigen: eigenvalues l1 >= l2 >= l3 and a right-handed
//    orthonormal eigenvector frame, robust for repeated eigenvalues;
//  - svtFractionalAnisotropy, svtMeanDiffusivity, svtWestinMetrics
//    (trace-normalized, as in Teem: cl = (l1-l2)/S, cp = 2(l2-l3)/S, cs = 3 l3/S);
//  - svtApplySignPolicy: what to do with negative eigenvalues;
//  - svtKindlmannShape: Kindlmann's (2004) superquadric exponents and axis.

//------------------------------------------------------------------------------
// y = T x for the symmetric tensor (diag, off).
vec3 svtSymMul(vec3 diag, vec3 off, vec3 x)
{
  return vec3(diag.x * x.x + off.x * x.y + off.z * x.z, off.x * x.x + diag.y * x.y + off.y * x.z,
    off.z * x.x + off.y * x.y + diag.z * x.z);
}

// Any unit vector orthogonal to the unit vector n.
vec3 svtAnyOrthogonal(vec3 n)
{
  vec3 o;
  if (abs(n.x) < abs(n.y) && abs(n.x) < abs(n.z))
  {
    o = vec3(0.0, -n.z, n.y);
  }
  else if (abs(n.y) < abs(n.z))
  {
    o = vec3(-n.z, 0.0, n.x);
  }
  else
  {
    o = vec3(-n.y, n.x, 0.0);
  }
  return normalize(o);
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
  real m = max(max(max(abs(diag.x), abs(diag.y)), abs(diag.z)),
    max(max(abs(off.x), abs(off.y)), abs(off.z)));
  if (!(m > 0.0))
  {
    lambda = vec3(0.0, 0.0, 0.0);
    return;
  }
  vec3 d = diag / m;
  vec3 o = off / m;
  real q = (d.x + d.y + d.z) / 3.0;
  vec3 b = d - vec3(q, q, q);
  real p2 = (dot(b, b) + 2.0 * dot(o, o)) / 6.0;
  if (p2 < 1e-30)
  {
    // A multiple of the identity: every vector is an eigenvector.
    lambda = vec3(m * q, m * q, m * q);
    return;
  }
  real p = sqrt(p2);
  vec3 cd = b / p;
  vec3 co = o / p;
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
  vec3 u = x01;
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

  // The 2x2 restriction to the plane orthogonal to u, diagonalized by a
  // rotation of angle theta = atan(2 m01, m00 - m11) / 2.
  vec3 v = svtAnyOrthogonal(u);
  vec3 w = cross(u, v);
  vec3 cv = svtSymMul(cd, co, v);
  vec3 cw = svtSymMul(cd, co, w);
  real m00 = dot(v, cv);
  real m11 = dot(w, cw);
  real m01 = 0.5 * (dot(v, cw) + dot(w, cv));
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
// eigenvectors (the frame stays right-handed). Returns true when the tensor is
// to be shown.
bool svtApplySignPolicy(
  int policy, SV_INOUT(vec3) lambda, SV_INOUT(vec3) e1, SV_INOUT(vec3) e2, SV_INOUT(vec3) e3)
{
  real big = max(abs(lambda.x), abs(lambda.z));
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
