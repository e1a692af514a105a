// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkLRSplinePatch
 * @brief   One LR-spline patch (volume or surface, polynomial or rational) in LR B-spline form,
 * and its exact conversion to Bezier blocks.
 *
 * Plain C++ (not a vtkObject). Holds what a `.lr` patch (LRSplines text format),
 * a GoTools g2 tensor-product (classes 200, 700) or LR (classes 293, 793)
 * patch says (see docs/spline-formats.md and Fuchs et al. §3.1, Eq. 2):
 *
 *   f(u, v, w) = sum_i gamma_i c_i B_i,u(u) B_i,v(v) B_i,w(w)
 *
 * with each B the Cox-de Boor B-spline of its own local knot vector (order + 1
 * knots per direction), and the box partition (elements) of the parameter
 * domain.
 *
 * A surface (ParametricDimension 2) is stored as a volume of order 1 (degree
 * 0) in w over [0, 1]: every basis function has the w knots (0, 1), every
 * element and mesh rectangle spans w in [0, 1], so the same code serves both.
 * Rational patches (RationalCoefficients) keep homogeneous coefficients, the
 * last component being the weight w_i and the others w_i times the Cartesian
 * coefficient (GoTools' and IFEM's convention): the map is the quotient of the
 * first components of f by its last, and Bezier extraction, being linear,
 * stays exact on the homogeneous form.
 *
 * ExtractBezier() performs the change of basis of §3.2.3: on each element box
 * [a, b] every supported basis function is a polynomial whose Bernstein
 * coefficients are its blossom at (a,...,a, b,...,b), evaluated with de Boor's
 * recurrence on the function's local knots: this is knot insertion of the
 * element bounds into the local knot vector, done once and exactly, in
 * parallel over elements (vtkSMPTools). The supports are computed from the
 * knots (not trusted from the file) and the file's lists are checked against
 * them.
 *
 * Write() writes the LRSplines text format (17 significant digits, so that
 * writing and reading back is exact).
 */

#ifndef vtkLRSplinePatch_h
#define vtkLRSplinePatch_h

#include "SplineVizCoreModule.h" // for export macro
#include "vtkType.h"

#include <iosfwd>
#include <string>
#include <vector>

class vtkLRSplineBezierVolume;
class vtkLRSplineElementLocator;

class SPLINEVIZCORE_EXPORT vtkLRSplinePatch
{
public:
  /// 3 for a volume, 2 for a surface (then Order[2] is 1 and w spans [0, 1]).
  int ParametricDimension = 3;
  /// Orders (degree + 1) per direction.
  int Order[3] = { 0, 0, 0 };
  /// Number of coefficient components (with the weight when rational).
  int Dimension = 0;
  /// The file's "rational" flag, as written (the LRSplines library ignores it).
  int Rational = 0;
  /**
   * The coefficients are homogeneous: the last component is the weight (which
   * must be positive), the others are the weight times the Cartesian value.
   * Set by the parser for g2 patches flagged rational and by the readers'
   * rational rule for LRSplines text (whose own flag IFEM leaves at 0).
   */
  bool RationalCoefficients = false;
  /// The file states the rationality itself (GoTools g2); ApplyRationalMode keeps it.
  bool ExplicitRational = false;

  /// How readers decide whether LRSplines text patches are rational.
  enum RationalModes
  {
    /**
     * g2 patches as flagged; LRSplines text patches whose coefficients are
     * control points are rational when their header says rat = 1 or when they
     * have more components than parametric directions (dim > pardim, SISO's
     * rule: IFEM writes NURBS patches with rat = 0 and dim = nsd + 1). Field
     * coefficients (no geometry) are never taken as rational.
     */
    RATIONAL_AUTOMATIC = 0,
    /// LRSplines text patches are polynomial (g2 patches as flagged).
    RATIONAL_POLYNOMIAL = 1,
    /// LRSplines text patches are rational, the last component the weight.
    RATIONAL_ALWAYS = 2
  };

  /**
   * Set RationalCoefficients by `mode` (see RationalModes); `controlPoints`
   * says whether the coefficients are the geometry. Returns false with a
   * message when the result is impossible (rational with one component);
   * `inferred` (may be null) is set when AUTOMATIC made a patch rational from
   * its number of components alone (worth a warning, as SISO gives).
   */
  bool ApplyRationalMode(int mode, bool controlPoints, bool* inferred, std::string* error);

  /// Per basis function: Order[0]+1 knots (u), then Order[1]+1 (v), then Order[2]+1 (w).
  std::vector<double> Knots;
  /// Dimension values per basis function.
  std::vector<double> Coefficients;
  /// Scaling weight per basis function.
  std::vector<double> Gamma;

  /// 6 values per element: (umin, vmin, wmin, umax, vmax, wmax).
  std::vector<double> ElementBoxes;
  /// Optional: the support lists as the file gave them (CSR); empty if none.
  std::vector<vtkIdType> FileSupportOffsets;
  std::vector<vtkIdType> FileSupport;

  /// Mesh rectangles: 6 values each (like element boxes, one direction flat)
  /// and their multiplicity. Kept as metadata.
  std::vector<double> MeshRectangles;
  std::vector<int> MeshMultiplicities;

  /// Line numbers in the source file (for messages); may be empty.
  std::vector<int> BasisLines;
  std::vector<int> ElementLines;
  int HeaderLine = 0;

  vtkIdType GetNumberOfBasisFunctions() const { return static_cast<vtkIdType>(this->Gamma.size()); }
  vtkIdType GetNumberOfElements() const
  {
    return static_cast<vtkIdType>(this->ElementBoxes.size() / 6);
  }
  int GetKnotsPerFunction() const { return this->Order[0] + this->Order[1] + this->Order[2] + 3; }
  /// Local knot vector (Order[dir] + 1 values) of basis function i.
  const double* GetKnots(vtkIdType i, int dir) const
  {
    const int offset =
      dir == 0 ? 0 : (dir == 1 ? this->Order[0] + 1 : this->Order[0] + this->Order[1] + 2);
    return this->Knots.data() + i * this->GetKnotsPerFunction() + offset;
  }
  /// Bounding box of all elements.
  void GetDomain(double domain[6]) const;

  /**
   * Check orders, counts, finiteness, sorted non-degenerate knot vectors,
   * positive gammas and non-empty element boxes. Messages name the line when
   * BasisLines/ElementLines are set.
   */
  bool Validate(std::string* error) const;

  /**
   * Compute, from the knots, the basis functions supported on each element
   * (CSR arrays), and check that the elements tile the domain without
   * overlaps, that every support is a union of elements, and (when the file
   * gave support lists) that they agree.
   */
  bool ComputeSupports(
    std::vector<vtkIdType>& offsets, std::vector<vtkIdType>& ids, std::string* error) const;

  /**
   * Exact Bezier form of elements [first, last) (all when last < 0), in
   * parallel. Degrees are Order-1. Checks the partition of unity of the scaled
   * basis; a violation larger than 1e-8 is reported in `warning`.
   *
   * `coefficients` (optional): other coefficients on the same basis,
   * `numberOfComponents` values per basis function in the order of the basis
   * functions (e.g. the nodal values of simulation fields, several fields side
   * by side), extracted instead of the patch's own. They are used as given:
   * for a rational patch pass homogeneous values (see RationalCoefficients).
   */
  bool ExtractBezier(vtkLRSplineBezierVolume& out, std::string* error,
    std::string* warning = nullptr, vtkIdType first = 0, vtkIdType last = -1,
    const double* coefficients = nullptr, int numberOfComponents = 0) const;

  /**
   * Bernstein coefficients (degree = size(knots) - 2) on [a, b] of the single
   * B-spline with local knot vector `knots`, where [a, b] lies in one knot
   * interval of it. Returns false when it does not. Exposed for tests.
   */
  static bool BSplineToBernstein(const double* knots, int order, double a, double b, double* out);

  /**
   * Value at x of the single B-spline with local knot vector `knots` (order + 1
   * values), by the Cox-de Boor recurrence on half-open intervals [t_j, t_j+1);
   * with fromLeft, (t_j, t_j+1] (the upper end of a domain).
   */
  static double BSplineValue(const double* knots, int order, double x, bool fromLeft);

  /// Number of Cartesian components (Dimension without the weight when rational).
  int GetNumberOfCartesianComponents() const
  {
    return this->Dimension - (this->RationalCoefficients ? 1 : 0);
  }

  /// The w interval of a surface's elements, knots and mesh rectangles.
  static constexpr double SurfaceW0 = 0.0;
  static constexpr double SurfaceW1 = 1.0;

  /// Write in the LRSplines text format ("# LRSPLINE VOLUME" or "SURFACE" ...).
  void Write(std::ostream& os) const;

private:
  ///@{
  /// ComputeSupports(), step by step: the elements tile the domain (no
  /// overlap, no hole); the elements in each basis function's support (each
  /// support a union of elements); those lists per element (every element
  /// in some support); the file's lists, when given, say the same.
  bool CheckElementsTile(const vtkLRSplineElementLocator& tree, std::string* error) const;
  bool FindSupportElements(const vtkLRSplineElementLocator& tree,
    std::vector<std::vector<vtkIdType>>& perFunction, std::string* error) const;
  bool InvertSupports(const std::vector<std::vector<vtkIdType>>& perFunction,
    std::vector<vtkIdType>& offsets, std::vector<vtkIdType>& ids, std::string* error) const;
  bool CheckFileSupports(const std::vector<vtkIdType>& offsets, const std::vector<vtkIdType>& ids,
    std::string* error) const;
  ///@}
};

#endif
// VTK-HeaderTest-Exclude: vtkLRSplinePatch.h
