// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkSplineVizTensorMath.h
 * @brief  Symmetric second-order tensor math of SplineViz (plain C++, double).
 *
 * The one place for the tensor math used by the tensor-analysis filter
 * (vtkTensorAnalysisFilter), the superquadric glyph mapper
 * (vtkSuperquadricGlyphMapper, whose shaders embed the same algorithms from
 * glsl/vtkTensorMathShared.glsl in float) and tensor fiber tracking.
 *
 * **Stable API** (other SplineViz code depends on it):
 *
 * - Component layouts of tensor arrays (TensorLayout) and their conversion to
 *   the canonical symmetric form `t[6] = {xx, yy, zz, xy, yz, xz}` (VTK's
 *   6-component order): ToSymmetric(), GetNumberOfComponents(), GuessLayout().
 * - EigenDecomposition(): l1 >= l2 >= l3, orthonormal right-handed
 *   eigenvectors, correct for repeated eigenvalues (see
 *   glsl/vtkTensorMathShared.glsl for the method).
 * - FractionalAnisotropy(), MeanDiffusivity(), WestinMetrics() (trace
 *   normalized as Teem: cl = (l1-l2)/S, cp = 2(l2-l3)/S, cs = 3 l3/S,
 *   S = l1+l2+l3, all 0 when S <= 0).
 * - ApplySignPolicy(): negative eigenvalues (skip, absolute values, or keep
 *   them for the Schultz-Kindlmann glyphs).
 * - SchultzKindlmannSquare(), SchultzKindlmannShape(): the superquadric glyph
 *   of any symmetric tensor, definite or not (Schultz and Kindlmann 2010;
 *   see glsl/vtkTensorMathShared.glsl for the definitions implemented).
 * - KindlmannShape(): superquadric exponents alpha, beta and symmetry axis
 *   from cl, cp and the sharpness gamma (Kindlmann 2004; Hlawitschka et al.
 *   §2; Teem's rule, as in Teem's tenGlyph).
 * - PrincipalEigen(): the eigenvalues and the principal eigenvector only
 *   (faster than EigenDecomposition(); for fiber tracking).
 * - FromEigenSystem(), Log(), Exp(): tensors from eigen-systems and the
 *   matrix logarithm and exponential through the eigen-decomposition, for
 *   log-Euclidean interpolation (Arsigny et al. 2006: interpolate log T
 *   linearly, map back with exp), used by the tensor line tracer.
 *
 * All functions are thread-safe (no state). Not wrapped (a namespace of
 * functions, exported for the tests and the other SplineViz classes).
 */
#ifndef vtkSplineVizTensorMath_h
#define vtkSplineVizTensorMath_h

#include "SplineVizCoreModule.h" // for export macro
#include "vtkType.h"             // for vtkIdType

class vtkDataArray;

namespace vtkSplineVizTensorMath
{
/**
 * Component layouts of tensor arrays.
 *
 * | layout            | comps | order                                   | used by              |
 * |-------------------|-------|-----------------------------------------|----------------------|
 * | FULL_9            | 9     | xx xy xz yx yy yz zx zy zz (row-major)  | VTK 9-comp tensors   |
 * | SYMMETRIC_VTK     | 6     | xx yy zz xy yz xz                       | VTK, ParaView        |
 * | SYMMETRIC_LOWER   | 6     | xx xy yy xz yz zz (lower triangle)      | NIfTI standard, DIPY |
 * | SYMMETRIC_UPPER   | 6     | xx xy xz yy yz zz (upper triangle)      | FSL dtifit, MFEM     |
 * | TEEM_7            | 7     | conf xx xy xz yy yz zz                  | Teem / NRRD          |
 *
 * The lower triangle row by row is the NIfTI standard's order for symmetric
 * matrices (NIFTI_INTENT_SYMMATRIX, in the 5th dimension) and DIPY's default;
 * FSL's `dtifit --save_tensor` writes a 4D volume in the upper-triangular
 * order Dxx Dxy Dxz Dyy Dyz Dzz (FSL's fslpy, fsl/data/dtifit.py, and DIPY's
 * `nifti_tensor=False` output "used by other software (e.g., FSL)"), so
 * SYMMETRIC_NIFTI and SYMMETRIC_FSL name the same two layouts.
 *
 * A 9-component tensor is symmetrized, (A + A^T)/2.
 */
enum TensorLayout
{
  FULL_9 = 0,
  SYMMETRIC_VTK = 1,
  SYMMETRIC_LOWER = 2,
  SYMMETRIC_UPPER = 3,
  TEEM_7 = 4,
  /// Aliases: the NIfTI standard's (and DIPY's) order, FSL dtifit's order.
  SYMMETRIC_NIFTI = SYMMETRIC_LOWER,
  SYMMETRIC_FSL = SYMMETRIC_UPPER
};

/// Number of components of a layout (0 for an unknown layout).
SPLINEVIZCORE_EXPORT int GetNumberOfComponents(int layout);

/// Human-readable name of a layout ("unknown" for an unknown layout).
SPLINEVIZCORE_EXPORT const char* GetLayoutName(int layout);

/**
 * The default layout for a number of components: 9 -> FULL_9,
 * 6 -> SYMMETRIC_VTK, 7 -> TEEM_7, anything else -> -1.
 */
SPLINEVIZCORE_EXPORT int GuessLayout(int numberOfComponents);

/**
 * The layout to read an array of `numberOfComponents` components with, when
 * the user asked for `requestedLayout`: 9 components are always FULL_9 and 7
 * components always TEEM_7 (unambiguous); 6 components use requestedLayout
 * when it is one of the 6-component layouts (SYMMETRIC_VTK, SYMMETRIC_LOWER,
 * SYMMETRIC_UPPER) and SYMMETRIC_VTK when requestedLayout is -1 (automatic).
 * Returns -1 when the array cannot be read that way (another component count,
 * or a 6-component array with FULL_9 or TEEM_7 requested).
 */
SPLINEVIZCORE_EXPORT int ResolveLayout(int requestedLayout, int numberOfComponents);

/**
 * Converts one tuple in the given layout to `t = {xx, yy, zz, xy, yz, xz}`.
 * Returns false (and leaves t unspecified) when the layout is unknown or a
 * component is NaN or infinite. For TEEM_7, `confidence` (if given) receives
 * the leading confidence value; for the other layouts it is set to 1.
 */
SPLINEVIZCORE_EXPORT bool ToSymmetric(
  int layout, const double* components, double t[6], double* confidence = nullptr);

/**
 * Reads tuple `id` of `array` in the given layout (the array must have
 * GetNumberOfComponents(layout) components; not checked here). Same return
 * value as ToSymmetric(). Thread-safe for concurrent reads.
 */
SPLINEVIZCORE_EXPORT bool ReadSymmetric(
  vtkDataArray* array, vtkIdType id, int layout, double t[6], double* confidence = nullptr);

/// The full matrix of t.
SPLINEVIZCORE_EXPORT void ToMatrix(const double t[6], double m[3][3]);

/// y = T x.
SPLINEVIZCORE_EXPORT void Multiply(const double t[6], const double x[3], double y[3]);

/**
 * Eigen-decomposition of the symmetric tensor t: values[0] >= values[1] >=
 * values[2]; vectors[i] is the unit eigenvector of values[i]; the vectors are
 * orthonormal and right-handed (vectors[2] = vectors[0] x vectors[1]). For
 * repeated eigenvalues any orthonormal basis of the eigenspace is returned.
 * Relative accuracy ~1e-14 of the largest |eigenvalue|. t must be finite.
 */
SPLINEVIZCORE_EXPORT void EigenDecomposition(const double t[6], double values[3], double vectors[3][3]);

/**
 * The eigenvalues (values[0] >= values[1] >= values[2]) and the unit
 * principal eigenvector e1 (of values[0]) of the symmetric tensor t, about
 * 1.5 times faster than EigenDecomposition() (175 vs 265 ns here) because
 * the other two eigenvectors are not built. The same method (the isolated eigenvalue's
 * vector as a cross product of two rows, then the 2x2 restriction to the
 * plane orthogonal to it), with the 2x2 problem solved in closed form
 * without trigonometric functions; the same accuracy for the values, e1 up
 * to its sign and to rounding divided by the gap l1 - l2 (any unit vector of
 * the eigenspace when l1 is repeated; (1, 0, 0) for multiples of the
 * identity). For tracking along e1 (vtkTensorLineTracer). t must be finite.
 */
SPLINEVIZCORE_EXPORT void PrincipalEigen(const double t[6], double values[3], double e1[3]);

/// Fractional anisotropy from eigenvalues, in [0, 1]; 0 for the zero tensor.
SPLINEVIZCORE_EXPORT double FractionalAnisotropy(const double values[3]);

/// Mean diffusivity (l1 + l2 + l3) / 3.
SPLINEVIZCORE_EXPORT double MeanDiffusivity(const double values[3]);

/**
 * Westin metrics from sorted eigenvalues (l1 >= l2 >= l3), trace-normalized
 * as in Teem: cl = (l1-l2)/S, cp = 2 (l2-l3)/S, cs = 3 l3/S with
 * S = l1 + l2 + l3; all three 0 when S <= 0. cl + cp + cs = 1 when S > 0;
 * each is in [0, 1] for positive semi-definite tensors.
 */
SPLINEVIZCORE_EXPORT void WestinMetrics(const double values[3], double& cl, double& cp, double& cs);

/// Policies for negative eigenvalues.
enum SignPolicy
{
  /// Do not show tensors with a negative eigenvalue (l3 < -1e-5 max|l|;
  /// slightly negative values from rounding are set to 0).
  SIGN_SKIP = 0,
  /// Use the absolute values of the eigenvalues, re-sorted with their vectors.
  SIGN_ABSOLUTE = 1,
  /// Keep the signed eigenvalues: the Schultz-Kindlmann glyphs
  /// (SchultzKindlmannShape()) draw every sign pattern.
  SIGN_SCHULTZ_KINDLMANN = 2
};

/**
 * Applies a SignPolicy to sorted eigenvalues and their vectors (as returned
 * by EigenDecomposition()). Returns false when the tensor is not to be shown.
 * The frame stays right-handed.
 */
SPLINEVIZCORE_EXPORT bool ApplySignPolicy(int policy, double values[3], double vectors[3][3]);

/**
 * Kindlmann's superquadric exponents. With cl, cp clamped to [0, 1]:
 * cl > cp: returns true (symmetry axis x, along e1), alpha = (1-cp)^gamma,
 * beta = (1-cl)^gamma; otherwise returns false (symmetry axis z, along e3),
 * alpha = (1-cl)^gamma, beta = (1-cp)^gamma. alpha and beta are clamped to
 * [minimumRoundness, 1]. The surface about the symmetry axis w (u, v the two
 * other glyph axes, in their cyclic order) is
 * (|u|^(2/alpha) + |v|^(2/alpha))^(alpha/beta) + |w|^(2/beta) = 1.
 */
SPLINEVIZCORE_EXPORT bool KindlmannShape(
  double cl, double cp, double gamma, double minimumRoundness, double& alpha, double& beta);

/**
 * The point (uv[0], uv[1]) in [0, 1]^2 of sorted eigenvalues (values[0] >=
 * values[1] >= values[2], any signs) in the shape square of Schultz and
 * Kindlmann (2010, §4.2; Teem's tenGlyphBqdUvEval): (1, 1) and (0, 0) are the
 * positive and negative isotropic tensors, u + v >= 1.5 the positive
 * semi-definite ones, (1/2, 1/2) diag(1, 0, -1). Returns true when the tensor
 * is negative-dominant (values[0] + values[2] < 0: its glyph is that of -T).
 * traceNormalized = true gives the placement the glyphs use, in which the
 * definite triangle follows Westin's trace-normalized cl, cp (so that
 * definite glyphs equal KindlmannShape()'s); false gives the paper's.
 */
SPLINEVIZCORE_EXPORT bool SchultzKindlmannSquare(
  const double values[3], bool traceNormalized, double uv[2]);

/**
 * The Schultz-Kindlmann superquadric glyph (Schultz and Kindlmann 2010,
 * §4.3, as Teem's tenGlyphBqdAbcUv and Deft's palette) of sorted eigenvalues
 * of any signs: abc = (alpha, beta, c), the glyph about its symmetry axis w
 * (u, v the two other axes, v along e2) being
 * (|u| / R_beta(w))^(2/alpha) + (|v| / R_c(w))^(2/alpha) <= 1 with
 * R_e(w) = (1 - |w|^(2/e))^(e/2) (for c = beta: the superquadric
 * (|u|^(2/alpha) + |v|^(2/alpha))^(alpha/beta) + |w|^(2/beta) <= 1), scaled
 * by |values[i]| along vectors[i]. Sharpened by gamma, alpha clamped to
 * [minimumRoundness, 1], beta and c to [minimumRoundness, 1/minimumRoundness].
 * Returns true when the symmetry axis is e1, false for e3. For positive
 * definite tensors the result is KindlmannShape()'s (alpha, beta, beta) and
 * axis. T and -T give the same glyph.
 */
SPLINEVIZCORE_EXPORT bool SchultzKindlmannShape(
  const double values[3], double gamma, double minimumRoundness, double abc[3]);

/**
 * t = sum_i values[i] vectors[i] vectors[i]^T (vectors[i] the unit
 * eigenvector of values[i], as returned by EigenDecomposition()).
 */
SPLINEVIZCORE_EXPORT void FromEigenSystem(
  const double values[3], const double vectors[3][3], double t[6]);

/**
 * Matrix logarithm of the symmetric tensor t through its eigen-decomposition:
 * logT = R diag(log max(l_i, minimumEigenvalue)) R^T. Eigenvalues below
 * minimumEigenvalue (zero or negative ones included) are raised to it, so the
 * result is the logarithm of the nearest tensor whose eigenvalues are at
 * least minimumEigenvalue. Returns false (logT unspecified) when t has a
 * non-finite component or minimumEigenvalue is not a positive number.
 */
SPLINEVIZCORE_EXPORT bool Log(const double t[6], double minimumEigenvalue, double logT[6]);

/**
 * Matrix exponential of the symmetric tensor t (finite components):
 * expT = R diag(exp l_i) R^T. If given, `values` and `vectors` receive its
 * eigen-decomposition (exp l1 >= exp l2 >= exp l3 and the eigenvectors of t,
 * the same order and handedness as EigenDecomposition()).
 */
SPLINEVIZCORE_EXPORT void Exp(
  const double t[6], double expT[6], double values[3] = nullptr, double vectors[3][3] = nullptr);
}

#endif
