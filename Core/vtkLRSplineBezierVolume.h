// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkLRSplineBezierVolume
 * @brief   One LR-spline patch as Bezier blocks: a box and (p+1)(q+1)(r+1) Bernstein coefficients
 * per element.
 *
 * Plain C++ (not a vtkObject). The representation of Fuchs et al., "Direct
 * interactive visualization of locally refined spline volumes" §3.2.3: on each
 * element (an axis-aligned box of the LR mesh) the spline is one polynomial of
 * tri-degree (p, q, r); written in the tensor-product Bernstein basis of the
 * element box it needs a fixed number of coefficients, evaluated with the
 * Bernstein/de Casteljau recurrences. The change of basis from LR B-splines is
 * exact (vtkLRSplinePatch::ExtractBezier), so evaluating these blocks IS
 * evaluating the LR spline.
 *
 * Layout (flat arrays, ready for upload to a GPU buffer):
 * - Boxes: 6 doubles per element, (umin, vmin, wmin, umax, vmax, wmax) in
 *   parameter space;
 * - Coefficients: per element (p+1)(q+1)(r+1) * NumberOfComponents doubles,
 *   coefficient (i, j, k) component c at
 *   ((k * (q+1) + j) * (p+1) + i) * NumberOfComponents + c, i along u.
 *
 * Evaluation is thread-safe (const). The templated kernels serve double and
 * single precision (the float copy is made by MakeFloatCoefficients()).
 */

#ifndef vtkLRSplineBezierVolume_h
#define vtkLRSplineBezierVolume_h

#include "SplineVizCoreModule.h" // for export macro
#include "vtkType.h"

#include <string>
#include <vector>

class vtkUnstructuredGrid;

class SPLINEVIZCORE_EXPORT vtkLRSplineBezierVolume
{
public:
  /// Largest supported degree per direction.
  static constexpr int MaximumDegree = 15;

  int Degree[3] = { 0, 0, 0 };
  int NumberOfComponents = 0;
  /// 3: a volume; 2: a surface (degree 0 in w, boxes with w in [0, 1]).
  int ParametricDimension = 3;
  std::vector<double> Boxes;
  std::vector<double> Coefficients;
  /// Single-precision copy of Coefficients (empty until MakeFloatCoefficients()).
  std::vector<float> CoefficientsFloat;

  vtkIdType GetNumberOfElements() const { return static_cast<vtkIdType>(this->Boxes.size() / 6); }
  int GetCoefficientsPerElement() const
  {
    return (this->Degree[0] + 1) * (this->Degree[1] + 1) * (this->Degree[2] + 1);
  }
  const double* GetBox(vtkIdType e) const { return this->Boxes.data() + 6 * e; }
  const double* GetElementCoefficients(vtkIdType e) const
  {
    return this->Coefficients.data() +
      e * this->GetCoefficientsPerElement() * this->NumberOfComponents;
  }
  /// Bounding box of all element boxes (umin, vmin, wmin, umax, vmax, wmax).
  void GetDomain(double domain[6]) const;
  /// Fill CoefficientsFloat from Coefficients.
  void MakeFloatCoefficients();

  /**
   * Raise the degree to at least 1 in the first `parametricDimension`
   * directions (exact: a constant is a linear polynomial with equal
   * coefficients). VTK's Bezier cells need it. A surface (2) keeps degree 0 in
   * w, so that each element's coefficients are those of a Bezier quadrilateral.
   */
  void ElevateToAtLeastLinear(int parametricDimension = 3);

  /**
   * Turn homogeneous coefficients into VTK's rational Bezier form: every
   * component except `weightComponent` is divided by that component's value
   * (the Bezier weight), which is kept. Then sum_k B_k w_k P_k / sum_k B_k w_k
   * is the rational spline again (VTK's "RationalWeights" interpolation).
   * False (nothing changed) when a weight is not positive and finite.
   */
  bool Dehomogenize(int weightComponent, std::string* error);

  /**
   * Raise the degrees to `degree` (each at least the current one) by exact
   * Bernstein degree elevation, one degree at a time per direction:
   * c'_i = i / (n + 1) c_{i-1} + (1 - i / (n + 1)) c_i. The polynomial of
   * every element does not change. False (nothing changed) when a target is
   * below the current degree or above MaximumDegree.
   */
  bool ElevateDegree(const int degree[3]);

  /**
   * Value and derivatives with respect to the element-local coordinates
   * s in [0,1]^3 of element e. `value` has NumberOfComponents entries;
   * `dlocal` (may be null) 3*NumberOfComponents entries, d value_c / d s_j at
   * [c*3 + j].
   */
  void EvaluateLocal(vtkIdType e, const double s[3], double* value, double* dlocal) const;
  void EvaluateLocal(vtkIdType e, const float s[3], float* value, float* dlocal) const;

  /**
   * Bernstein basis values B_i^n(s), i = 0..n, and (if d is non-null) their
   * derivatives, by the de Casteljau-type recurrence. Exposed for tests.
   */
  template <typename Real>
  static void Bernstein(int n, Real s, Real* b, Real* d);

  /**
   * Build from a vtkUnstructuredGrid of VTK_BEZIER_HEXAHEDRON cells (a volume)
   * or VTK_BEZIER_QUADRILATERAL cells (a surface: ParametricDimension 2,
   * degree 0 in w) as written by vtkLRSplineBezierGrid: cell data
   * "LRParameterBox" (6 components) when present, otherwise the axis-aligned
   * bounds of each cell's corner points (w in [0, 1] for a surface); degrees
   * from the cell data's HigherOrderDegrees array (all cells must share them
   * and their type); the coefficients from the point-data array `arrayName`
   * (active vectors, else active scalars, else the first array other than
   * the geometry's "LRParameterCoordinates" and "RationalWeights", when null
   * or empty). `cellIds` (may be null) receives the grid's cell id of every
   * element. Returns false with a message when the grid is not such a grid.
   */
  bool FromUnstructuredGrid(vtkUnstructuredGrid* grid, const char* arrayName, std::string* error,
    std::vector<vtkIdType>* cellIds = nullptr, std::string* usedArrayName = nullptr);
};

#endif
// VTK-HeaderTest-Exclude: vtkLRSplineBezierVolume.h
