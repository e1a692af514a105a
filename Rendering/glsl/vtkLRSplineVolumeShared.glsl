// SPDX-License-Identifier: BSD-3-Clause
// LR-spline element look-up and Bezier evaluation, shared, as one source, by
// the fragment stage of vtkLRSplineVolumeMapper and its CPU check
// (vtkLRSplineVolumeMath.h compiles this text as C++).
//
// Fuchs et al., "Direct interactive visualization of locally refined spline
// volumes", §3.2: the element containing a parameter point is found in the
// flat arrays of vtkLRSplineElementLocator (the k-d forest of Algorithm 1 -
// also the single k-d tree and the look-up texture, which are forests - or
// the octree of §3.2.2), and the spline is evaluated in the element's Bezier
// form (§3.2.3) with the Bernstein recurrences of vtkLRSplineBezierVolume.
//
// Written in the common subset of GLSL and C++ described at the top of
// vtkSplineTubeMathShared.glsl, plus `uint`, ivec3 and the unsigned
// literals of the bit masks. The including code provides the data:
//   uint lrHead(int i), uint lrNodeWord(int i), real lrNodeSplit(int i),
//   uint lrOctreeNode(int i), real lrCoefficient(int i).
// Indices into the trees are relative to a patch's first entry (`nodes`,
// `octree`), as vtkLRSplineElementLocator stores them.

#define LR_LEAF 2147483648u
#define LR_ELEMENT_MASK 2147483647u
#define LR_CHILD_MASK 536870911u
#define LR_NO_ELEMENT 4294967295u

// The element of a k-d forest (Algorithm 1) containing parameter point u of
// the domain [lo, hi] with blocks x blocks... (i fastest) whose heads start
// at `heads` and whose nodes start at `nodes`; -1 for none. Points just
// outside the domain use its border blocks (the caller tests the domain).
int lrFindForest(vec3 u, vec3 lo, vec3 hi, ivec3 blocks, int heads, int nodes)
{
  int b[3];
  for (int d = 0; d < 3; ++d)
  {
    real t = (u[d] - lo[d]) / (hi[d] - lo[d]) * real(blocks[d]);
    int i = int(floor(t));
    b[d] = i < 0 ? 0 : (i > blocks[d] - 1 ? blocks[d] - 1 : i);
  }
  uint w = lrHead(heads + (b[2] * blocks[1] + b[1]) * blocks[0] + b[0]);
  if ((w & LR_LEAF) == 0u)
  {
    int index = int(w);
    for (int steps = 0; steps < 64; ++steps)
    {
      uint node = lrNodeWord(nodes + index);
      if ((node & LR_LEAF) != 0u)
      {
        w = node;
        break;
      }
      int dir = int((node >> 29u) & 3u);
      index = u[dir] < lrNodeSplit(nodes + index) ? int(node & LR_CHILD_MASK) : index + 1;
    }
  }
  return w == LR_NO_ELEMENT || (w & LR_LEAF) == 0u ? -1 : int(w & LR_ELEMENT_MASK);
}

// The element of an octree (§3.2.2) over [lo, hi] whose nodes start at
// `octree` containing u; -1 for none.
int lrFindOctree(vec3 u, vec3 lo, vec3 hi, int octree)
{
  vec3 a = lo;
  vec3 b = hi;
  uint w = lrOctreeNode(octree);
  for (int steps = 0; steps < 40 && (w & LR_LEAF) == 0u; ++steps)
  {
    int c = 0;
    for (int d = 0; d < 3; ++d)
    {
      real mid = 0.5 * (a[d] + b[d]);
      if (u[d] >= mid)
      {
        c = c + (d == 0 ? 1 : (d == 1 ? 2 : 4));
        a[d] = mid;
      }
      else
      {
        b[d] = mid;
      }
    }
    w = lrOctreeNode(octree + int(w) + c);
  }
  return w == LR_NO_ELEMENT || (w & LR_LEAF) == 0u ? -1 : int(w & LR_ELEMENT_MASK);
}

// Bernstein basis values b[i] = B_i^n(s) and derivatives d[i], i = 0..n,
// n <= 3, in closed form (no loops: shader loops are costly, and llvmpipe
// caps the loop iterations of a whole shader invocation).
void lrBernstein(int n, real s, SV_OUT(vec4) b, SV_OUT(vec4) d)
{
  real t = 1.0 - s;
  if (n == 0)
  {
    b = vec4(1.0, 0.0, 0.0, 0.0);
    d = vec4(0.0, 0.0, 0.0, 0.0);
  }
  else if (n == 1)
  {
    b = vec4(t, s, 0.0, 0.0);
    d = vec4(-1.0, 1.0, 0.0, 0.0);
  }
  else if (n == 2)
  {
    b = vec4(t * t, 2.0 * t * s, s * s, 0.0);
    d = vec4(-2.0 * t, 2.0 * (t - s), 2.0 * s, 0.0);
  }
  else
  {
    b = vec4(t * t * t, 3.0 * t * t * s, 3.0 * t * s * s, s * s * s);
    d = vec4(-3.0 * t * t, 3.0 * t * (t - 2.0 * s), 3.0 * s * (2.0 * t - s), 3.0 * s * s);
  }
}

// One row (fixed j, k) of lrEvaluate: sum_i c_ijk B_i(s) and its derivative,
// unrolled (du <= 3); `base` indexes coefficient (0, j, k) of the component.
void lrRow(int base, int nc, int du, vec4 bu, vec4 gu, SV_OUT(real) row, SV_OUT(real) rowDu)
{
  real c = lrCoefficient(base);
  row = c * bu[0];
  rowDu = c * gu[0];
  if (du >= 1)
  {
    c = lrCoefficient(base + nc);
    row = row + c * bu[1];
    rowDu = rowDu + c * gu[1];
  }
  if (du >= 2)
  {
    c = lrCoefficient(base + 2 * nc);
    row = row + c * bu[2];
    rowDu = rowDu + c * gu[2];
  }
  if (du >= 3)
  {
    c = lrCoefficient(base + 3 * nc);
    row = row + c * bu[3];
    rowDu = rowDu + c * gu[3];
  }
}

// Add row (j, k) to the value and the three derivatives (sum in `acc`: value,
// d/ds0, d/ds1, d/ds2).
void lrAddRow(int offset, int du, int dv, int nc, int comp, int j, int k, vec4 bu, vec4 gu,
  real bvj, real gvj, real bwk, real gwk, SV_INOUT(vec4) acc)
{
  real row;
  real rowDu;
  lrRow(offset + ((k * (dv + 1) + j) * (du + 1)) * nc + comp, nc, du, bu, gu, row, rowDu);
  acc = acc + vec4(row * bvj * bwk, rowDu * bvj * bwk, row * gvj * bwk, row * bvj * gwk);
}

// The rows of one k (all j <= dv).
void lrAddLayer(int offset, int du, int dv, int nc, int comp, int k, vec4 bu, vec4 gu, vec4 bv,
  vec4 gv, real bwk, real gwk, SV_INOUT(vec4) acc)
{
  lrAddRow(offset, du, dv, nc, comp, 0, k, bu, gu, bv[0], gv[0], bwk, gwk, acc);
  if (dv >= 1)
  {
    lrAddRow(offset, du, dv, nc, comp, 1, k, bu, gu, bv[1], gv[1], bwk, gwk, acc);
  }
  if (dv >= 2)
  {
    lrAddRow(offset, du, dv, nc, comp, 2, k, bu, gu, bv[2], gv[2], bwk, gwk, acc);
  }
  if (dv >= 3)
  {
    lrAddRow(offset, du, dv, nc, comp, 3, k, bu, gu, bv[3], gv[3], bwk, gwk, acc);
  }
}

// Component `comp` of an element in Bezier form at local coordinates s in
// [0, 1]^3: the value, and (grad) its derivatives with respect to s.
// Degrees du, dv, dw <= 3; `offset` is the element's first coefficient,
// `nc` the number of components (coefficient (i, j, k), component c, at
// offset + ((k (dv + 1) + j) (du + 1) + i) nc + c, as in
// vtkLRSplineBezierVolume). Written without loops (see lrBernstein).
real lrEvaluate(int offset, int du, int dv, int dw, int nc, int comp, vec3 s, SV_OUT(vec3) grad)
{
  vec4 bu;
  vec4 bv;
  vec4 bw;
  vec4 gu;
  vec4 gv;
  vec4 gw;
  lrBernstein(du, s[0], bu, gu);
  lrBernstein(dv, s[1], bv, gv);
  lrBernstein(dw, s[2], bw, gw);
  vec4 acc = vec4(0.0, 0.0, 0.0, 0.0);
  lrAddLayer(offset, du, dv, nc, comp, 0, bu, gu, bv, gv, bw[0], gw[0], acc);
  if (dw >= 1)
  {
    lrAddLayer(offset, du, dv, nc, comp, 1, bu, gu, bv, gv, bw[1], gw[1], acc);
  }
  if (dw >= 2)
  {
    lrAddLayer(offset, du, dv, nc, comp, 2, bu, gu, bv, gv, bw[2], gw[2], acc);
  }
  if (dw >= 3)
  {
    lrAddLayer(offset, du, dv, nc, comp, 3, bu, gu, bv, gv, bw[3], gw[3], acc);
  }
  grad = vec3(acc[1], acc[2], acc[3]);
  return acc[0];
}

// The geometry map of a curved element (homogeneous coefficients, 4
// components (w x, w y, w z, w) at `offset`, degrees du, dv, dw): x(s) =
// X(s) / W(s) and its Jacobian J (column j: d x / d s_j); W and dW the
// weight and its derivatives (1 and 0 for a polynomial map).
vec3 lrMap(int offset, int du, int dv, int dw, vec3 s, SV_OUT(mat3) J, SV_OUT(real) W,
  SV_OUT(vec3) dW)
{
  vec3 g0;
  vec3 g1;
  vec3 g2;
  real x0 = lrEvaluate(offset, du, dv, dw, 4, 0, s, g0);
  real x1 = lrEvaluate(offset, du, dv, dw, 4, 1, s, g1);
  real x2 = lrEvaluate(offset, du, dv, dw, 4, 2, s, g2);
  W = lrEvaluate(offset, du, dv, dw, 4, 3, s, dW);
  vec3 x = vec3(x0, x1, x2) / W;
  g0 = (g0 - x[0] * dW) / W;
  g1 = (g1 - x[1] * dW) / W;
  g2 = (g2 - x[2] * dW) / W;
  J = mat3(vec3(g0[0], g1[0], g2[0]), vec3(g0[1], g1[1], g2[1]), vec3(g0[2], g1[2], g2[2]));
  return x;
}

// The local coordinates s of physical point x in a curved element (the
// inversion of vtkLRSplineGeometryMap in single precision): Newton from s
// (the previous sample's, or the centre, whose first step is the element's
// linear approximation), steps kept within [-0.5, 1.5]^3. True when it
// converged inside [0, 1]^3 (up to `tol`); s is then clamped, and Jinv,
// W and dW are the inverse Jacobian and the weight at the last iterate.
bool lrInvert(int offset, int du, int dv, int dw, vec3 x, real tol, SV_INOUT(vec3) s,
  SV_OUT(mat3) Jinv, SV_OUT(real) W, SV_OUT(vec3) dW)
{
  mat3 J;
  bool converged = false;
  for (int it = 0; it < 10; ++it)
  {
    vec3 r = lrMap(offset, du, dv, dw, s, J, W, dW) - x;
    Jinv = inverse(J);
    vec3 d = Jinv * r;
    s = clamp(s - d, vec3(-0.5, -0.5, -0.5), vec3(1.5, 1.5, 1.5));
    if (max(abs(d[0]), max(abs(d[1]), abs(d[2]))) < 1e-5)
    {
      converged = true;
      break;
    }
  }
  if (!converged || s[0] < -tol || s[1] < -tol || s[2] < -tol || s[0] > 1.0 + tol ||
    s[1] > 1.0 + tol || s[2] > 1.0 + tol)
  {
    return false;
  }
  s = clamp(s, vec3(0.0, 0.0, 0.0), vec3(1.0, 1.0, 1.0));
  return true;
}
