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
// n <= 3 (the recurrence of vtkLRSplineBezierVolume::Bernstein).
void lrBernstein(int n, real s, SV_OUT(vec4) b, SV_OUT(vec4) d)
{
  real t = 1.0 - s;
  b = vec4(1.0, 0.0, 0.0, 0.0);
  d = vec4(0.0, 0.0, 0.0, 0.0);
  // Degree n - 1 first (for the derivative).
  for (int k = 1; k < n; ++k)
  {
    real saved = 0.0;
    for (int i = 0; i < k; ++i)
    {
      real tmp = b[i];
      b[i] = saved + t * tmp;
      saved = s * tmp;
    }
    b[k] = saved;
  }
  if (n == 0)
  {
    return;
  }
  real rn = real(n);
  d[0] = -rn * b[0];
  for (int i = 1; i < n; ++i)
  {
    d[i] = rn * (b[i - 1] - b[i]);
  }
  d[n] = rn * b[n - 1];
  real saved = 0.0;
  for (int i = 0; i < n; ++i)
  {
    real tmp = b[i];
    b[i] = saved + t * tmp;
    saved = s * tmp;
  }
  b[n] = saved;
}

// Component `comp` of an element in Bezier form at local coordinates s in
// [0, 1]^3: the value, and (grad) its derivatives with respect to s.
// Degrees du, dv, dw <= 3; `offset` is the element's first coefficient,
// `nc` the number of components (coefficient (i, j, k), component c, at
// offset + ((k (dv + 1) + j) (du + 1) + i) nc + c, as in
// vtkLRSplineBezierVolume).
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
  real value = 0.0;
  real sx = 0.0;
  real sy = 0.0;
  real sz = 0.0;
  for (int k = 0; k <= dw; ++k)
  {
    for (int j = 0; j <= dv; ++j)
    {
      real row = 0.0;
      real rowDu = 0.0;
      for (int i = 0; i <= du; ++i)
      {
        real c = lrCoefficient(offset + ((k * (dv + 1) + j) * (du + 1) + i) * nc + comp);
        row = row + c * bu[i];
        rowDu = rowDu + c * gu[i];
      }
      value = value + row * bv[j] * bw[k];
      sx = sx + rowDu * bv[j] * bw[k];
      sy = sy + row * gv[j] * bw[k];
      sz = sz + row * bv[j] * gw[k];
    }
  }
  grad = vec3(sx, sy, sz);
  return value;
}
