// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkLRSplineGeometryMap
 * @brief   The geometry map x(u) of an isoparametric LR-spline patch (volume or surface) and its
 * inverse: the element and the parameter of a physical point.
 *
 * Plain C++ (not a vtkObject), the one inversion used by vtkLRSplineEvaluator
 * (probing, resampling and tracing on curved geometry) and by the volume
 * mapper's CPU side. Built from a geometry-mode grid of vtkLRSplineReader or
 * vtkIFEMReader, it keeps per element the Bezier coefficients of x
 * (homogeneous when rational) and the box of its control points, which
 * contains the element (convex hull property; positive weights).
 *
 * Invert(): candidate elements from the k-d forest of
 * vtkLRSplineElementLocator over the physical boxes (they overlap: list
 * leaves); in each, Newton's method on s -> x(s) in local coordinates,
 * started from the element's linear approximation, then from its centre and
 * corners, with a backtracking line search; converged when the step is below
 * ConvergenceTolerance and the residual below 1e-9 of the element's size;
 * inside when s lies in [0, 1]^3 up to InsideTolerance.
 *
 * Surfaces (in the plane or curved in 3D): the closest-point projection
 * (Gauss-Newton); a point is on the surface when its foot lies in the
 * element and its distance is at most SurfaceTolerance times the element's
 * size. Gradients of surface fields are tangential.
 *
 * IsAffine(): every element's map is one affine map x = A u + b (within 1e-12
 * of the patch size); callers then keep their fast affine paths (volumes).
 *
 * Limits: degrees up to vtkLRSplineBezierVolume's; on a surface in 3D,
 * points off a convex crease whose foot is the crease belong to neither
 * side. Thread-safe (const) after Build(). See docs/ifem.md, "Physical space".
 */

#ifndef vtkLRSplineGeometryMap_h
#define vtkLRSplineGeometryMap_h

#include "SplineVizCoreModule.h" // for export macro
#include "vtkLRSplineBezierVolume.h"
#include "vtkLRSplineElementLocator.h"

#include <string>
#include <vector>

class vtkUnstructuredGrid;

class SPLINEVIZCORE_EXPORT vtkLRSplineGeometryMap
{
public:
  /// Newton's convergence in local coordinates.
  static constexpr double ConvergenceTolerance = 1e-13;
  /// How far outside [0, 1]^3 (local) a solution still counts as inside.
  static constexpr double InsideTolerance = 1e-9;
  /// The default SurfaceTolerance (relative to the element's size).
  static constexpr double DefaultSurfaceTolerance = 1e-2;

  /**
   * Surfaces: how far from the surface a point may lie and still be on it,
   * relative to the size of the element (the diagonal of its control
   * points' box). Values below 1e-9 mean 1e-9 (rounding). Set before Build().
   */
  void SetSurfaceTolerance(double relative)
  {
    this->SurfaceTolerance = relative >= 0 ? relative : DefaultSurfaceTolerance;
  }
  double GetSurfaceTolerance() const { return this->SurfaceTolerance; }

  /**
   * Build from a geometry-mode grid (see the class comment); `blocks` the k-d
   * forest resolution (null: automatic). False with a message otherwise.
   */
  bool Build(vtkUnstructuredGrid* grid, const int blocks[3], std::string* error);

  vtkIdType GetNumberOfElements() const { return this->Volume.GetNumberOfElements(); }
  /// 3 (volume) or 2 (surface).
  int GetParametricDimension() const { return this->Volume.ParametricDimension; }
  bool IsRational() const { return this->Rational; }
  /// Bezier coefficients: (x, y, z), or (w x, w y, w z, w) when rational.
  const vtkLRSplineBezierVolume& GetVolume() const { return this->Volume; }
  /// The locator over the physical boxes.
  const vtkLRSplineElementLocator& GetLocator() const { return this->Locator; }
  /// Physical box of element e (lo xyz, hi xyz).
  const double* GetPhysicalBox(vtkIdType e) const { return this->Locator.GetBox(e); }
  /// Parameter box of element e (lo uvw, hi uvw).
  const double* GetParameterBox(vtkIdType e) const { return this->Volume.GetBox(e); }
  /// Bounds of all control points (VTK order).
  void GetBounds(double bounds[6]) const;

  /// True when the map is one affine map x = A u + b (A row-major).
  bool IsAffine() const { return this->Affine; }
  void GetAffineMap(double A[9], double b[3]) const;

  /**
   * x(s) at local coordinates s of element e and (J may be null) the
   * Jacobian J[3 i + j] = d x_i / d s_j.
   */
  void Map(vtkIdType e, const double s[3], double x[3], double J[9]) const;

  /**
   * d s / d x at local coordinates s of element e, row-major (inv[3 d + j] =
   * d s_d / d x_j): the inverse Jacobian of a volume, the pseudo-inverse
   * (J^T J)^-1 J^T of a surface (third row zero). False when singular.
   */
  bool InverseJacobian(vtkIdType e, const double s[3], double inv[9]) const;

  /// A surface's point x(s) and unit normal (d x / d s_0 x d x / d s_1) at s of element e.
  void SurfaceFrame(vtkIdType e, const double s[3], double x[3], double normal[3]) const;

  /// The rational weight W(s) and d W / d s (1 and 0 when polynomial).
  void Weight(vtkIdType e, const double s[3], double& W, double dW[3]) const;

  /**
   * The local coordinates s of x in element e (Newton, see the class
   * comment; `seed` may be null). True when x lies in the element (s is then
   * clamped to [0, 1]^3); false when it does not or Newton did not converge
   * (s is then the last iterate).
   */
  bool InvertInElement(vtkIdType e, const double x[3], double s[3], const double* seed = nullptr,
    int* iterations = nullptr) const;

  /**
   * The element containing x and its local coordinates s, or -1 when x is
   * outside the geometry. `hint` (may be -1) is tried first.
   */
  vtkIdType Invert(const double x[3], double s[3], vtkIdType hint = -1) const;

  /// The parameter point of local coordinates s in element e.
  void LocalToParameter(vtkIdType e, const double s[3], double u[3]) const;

  /// Shortest edge of element e in physical units (the chords of its edges).
  double GetElementMinimumSide(vtkIdType e) const;

private:
  // `far` (may be null): converged, but the residual is above the acceptance.
  bool Newton(
    vtkIdType e, const double x[3], double s[3], int* iterations, bool* far = nullptr) const;
  void DetectAffine();

  vtkLRSplineBezierVolume Volume;
  vtkLRSplineElementLocator Locator;
  std::vector<double> Size; // per element: diagonal of its physical box
  double SurfaceTolerance = DefaultSurfaceTolerance;
  bool Rational = false;
  bool Affine = false;
  double AffineA[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  double AffineB[3] = { 0, 0, 0 };
};

#endif
// VTK-HeaderTest-Exclude: vtkLRSplineGeometryMap.h
