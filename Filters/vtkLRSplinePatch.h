/**
 * @class   vtkLRSplinePatch
 * @brief   One LR-spline volume patch in LR B-spline form, and its exact conversion to Bezier
 * blocks.
 *
 * Plain C++ (not a vtkObject). Holds what a `.lr` patch (LRSplines text format)
 * or a GoTools class 700 volume says (see docs/spline-formats.md and Fuchs et
 * al. §3.1, Eq. 2):
 *
 *   f(u, v, w) = sum_i gamma_i c_i B_i,u(u) B_i,v(v) B_i,w(w)
 *
 * with each B the Cox-de Boor B-spline of its own local knot vector (order + 1
 * knots per direction), and the box partition (elements) of the parameter
 * domain.
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

#include "SplineVizModule.h" // for export macro
#include "vtkType.h"

#include <iosfwd>
#include <string>
#include <vector>

class vtkLRSplineBezierVolume;

class SPLINEVIZ_EXPORT vtkLRSplinePatch
{
public:
  /// Orders (degree + 1) per direction.
  int Order[3] = { 0, 0, 0 };
  /// Number of coefficient components.
  int Dimension = 0;
  /// The file's "rational" flag (the LRSplines library ignores it; so do we).
  int Rational = 0;

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
   */
  bool ExtractBezier(vtkLRSplineBezierVolume& out, std::string* error,
    std::string* warning = nullptr, vtkIdType first = 0, vtkIdType last = -1) const;

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

  /// Write in the LRSplines text format ("# LRSPLINE VOLUME" ...).
  void Write(std::ostream& os) const;
};

#endif
// VTK-HeaderTest-Exclude: vtkLRSplinePatch.h
