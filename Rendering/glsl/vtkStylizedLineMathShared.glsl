// SPDX-License-Identifier: BSD-3-Clause
// Stylized-line math shared, as one source, by the shaders and the CPU code.
//
// Stoll, Gumhold and Seidel, "Visualization with stylized line primitives"
// (IEEE Visualization 2005), §4.1-4.4. Written in the common subset of GLSL
// and C++ described at the top of vtkSplineTubeMathShared.glsl (`real`,
// vec3 of real, SV_OUT(T) outputs, literals with a decimal point, no
// swizzles): the vertex and fragment stages of vtkStylizedLineMapper embed
// it, and vtkStylizedLineMath.h compiles it as C++ for the mapper's CPU
// fix-up classification and the tests.
//
// All vectors are in view coordinates, the eye at the origin looking along
// -z. A line vertex is the point p on the line's axis, its unit tangent t and
// its radius r. The view vector is u = p - eye = p for a perspective camera
// and the view direction (0, 0, -1) for a parallel one.

// Distance, in units of the radius, below which the eye counts as "at the
// line" (inside or grazing the infinite cylinder of a vertex): Eq. 6 has no
// silhouette there (r / |u_perp| >= 1 gives f = 0), so the vertex is fixed up.
#define SL_NEAR_AXIS 2.0

// The unit tangent of a polyline vertex from the segments before and after
// it (either may be zero at the polyline's ends): the bisector of their
// directions, so that the profile circle at a joint is the one the two
// straight segments share symmetrically (as vtkTubeFilter builds its rings),
// and the segment's own direction at the ends (caps orthogonal to it).
vec3 slPolylineTangent(vec3 before, vec3 after)
{
  real lb = length(before);
  real la = length(after);
  vec3 t = vec3(0.0, 0.0, 0.0);
  if (lb > 0.0)
  {
    t = t + before / lb;
  }
  if (la > 0.0)
  {
    t = t + after / la;
  }
  real lt = length(t);
  if (lt <= 1.0e-6)
  {
    // No segment, or a full turn back: the direction of either segment.
    return la > 0.0 ? after / la : (lb > 0.0 ? before / lb : vec3(1.0, 0.0, 0.0));
  }
  return t / lt;
}

// The local frame of Eq. 4-5 at a vertex: u_perp, the part of the view vector
// orthogonal to the tangent (the view vector to p_perp, the point of the
// axis nearest to the eye); y = t x u_perp / |t x u_perp| (Eq. 4, the
// silhouette direction in the image) and x = t x y (Eq. 5, pointing from the
// axis toward the eye). `uPerpLength` receives |u_perp| (for a parallel
// camera the sine of the angle between the view direction and the tangent).
// Returns false (and some orthonormal x, y) when t is parallel to u: the
// singular view of §4.3, where the quad of the vertex degenerates.
bool slFrame(vec3 u, vec3 t, SV_OUT(vec3) x, SV_OUT(vec3) y, SV_OUT(real) uPerpLength)
{
  vec3 uPerp = u - dot(u, t) * t;
  uPerpLength = length(uPerp);
  vec3 c = cross(t, uPerp);
  real cl = length(c);
  if (cl <= 1.0e-20 || uPerpLength <= 1.0e-12 * length(u))
  {
    y = svAnyOrthogonal(t);
    x = cross(t, y);
    return false;
  }
  y = c / cl;
  x = cross(t, y);
  return true;
}

// Extrusion vector of a silhouette point (Eq. 6 when `exact`, else Eq. 8),
// side = -1 or +1, with the halo: the component along y is widened by
// `widen` = 1 + halo width (Stoll §4.2). `f` receives the silhouette factor
// f_i = sqrt(1 - (r / |u_perp|)^2) of Eq. 6 (1 for Eq. 8, 0 when the eye is
// inside the cylinder). For a parallel camera (parallel = true) r / |u_perp|
// is 0: the silhouette lies in the plane of the axis.
vec3 slExtrusion(vec3 x, vec3 y, real r, real uPerpLength, bool parallel, bool exact, real side,
  real widen, SV_OUT(real) f)
{
  real q = 0.0;
  if (exact && !parallel)
  {
    q = uPerpLength > r ? r / uPerpLength : 1.0;
  }
  f = sqrt(max(0.0, 1.0 - q * q));
  return r * (q * x + (side * f * widen) * y);
}

// Per-fragment normal of Eq. 10 from the interpolated frame vectors x, y and
// the interpolated silhouette parameter tex0 (-f .. f across the line; the
// normal of Eq. 9 at the silhouette points).
vec3 slNormal(vec3 x, vec3 y, real tex0)
{
  real s = clamp(tex0, -1.0, 1.0);
  return normalize(sqrt(max(0.0, 1.0 - s * s)) * x + s * y);
}

// Depth correction (§4.3, Eq. 11-12): the distance d = r / sin(alpha) along
// the unit view ray `dir` from a point of the axis to the front surface of
// the vertex's infinite cylinder (alpha the angle between the ray and the
// tangent), at most `cap` (the cylinder's depth grows without bound as the
// ray turns along the axis; there the fix-up draws real geometry).
real slFrontDistance(vec3 dir, vec3 t, real r, real cap)
{
  real c = dot(dir, t);
  real s = sqrt(max(0.0, 1.0 - c * c));
  return s * cap > r ? r / s : cap;
}

// The fix-up criterion of §4.4 at a vertex at view position p: the tangent
// nearly along the view vector, |f_i| = |u_hat . t| > 1 - epsilon, or (a
// perspective camera) the eye within SL_NEAR_AXIS radii of the vertex's axis.
bool slNeedsFixUp(vec3 p, vec3 t, real r, bool parallel, real epsilon)
{
  vec3 u = parallel ? vec3(0.0, 0.0, -1.0) : p;
  real ul = length(u);
  if (ul <= 0.0)
  {
    return true;
  }
  real c = dot(u, t) / ul;
  if (abs(c) > 1.0 - epsilon)
  {
    return true;
  }
  if (!parallel)
  {
    vec3 uPerp = u - dot(u, t) * t;
    if (length(uPerp) < SL_NEAR_AXIS * r)
    {
      return true;
    }
  }
  return false;
}
