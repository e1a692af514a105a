// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkLRSplineEvaluator
 * @brief   Fast exact evaluation of one LR-spline patch: element look-up plus Bezier evaluation of
 * value and gradient.
 *
 * Plain C++ (not a vtkObject), shared by vtkLRSplineProbeFilter,
 * vtkLRSplineResampleToImage, vtkLRSplineStreamTracer and the volume renderer.
 * It combines the two parts of Fuchs et al. §3.2: the element search
 * (vtkLRSplineElementLocator, a k-d forest by default) and the Bezier blocks
 * (vtkLRSplineBezierVolume), so that the value and the exact gradient
 * (Jacobian for vector fields) at a point cost one look-up and one
 * tensor-product Bernstein evaluation.
 *
 * Points are physical: x = A u + b maps the parameter u to physical space
 * (identity by default): per axis, x = offset + scale * u (the reader's
 * field mode places the spline in a physical box this way), or any
 * invertible affine map (a patch whose geometry is an affine image of its
 * parameter domain, e.g. rotated, placed where its geometry says).
 * With a geometry map (SetGeometry: an isoparametric patch whose geometry is
 * curved), x is the geometry map of the parameter instead: points are found
 * and converted by vtkLRSplineGeometryMap's inversion, and gradients use the
 * map's Jacobian. Gradients are with respect to x (on a surface: the
 * tangential gradient; a surface is evaluated at the foot of x on it). The single-precision
 * overloads do the whole evaluation in float (the GPU arithmetic, used by the tracer's mixed and
 * single precision modes).
 *
 * All evaluation methods are const and thread-safe; EvaluateBatch() runs in
 * parallel with vtkSMPTools.
 */

#ifndef vtkLRSplineEvaluator_h
#define vtkLRSplineEvaluator_h

#include "SplineVizCoreModule.h" // for export macro
#include "vtkLRSplineBezierVolume.h"
#include "vtkLRSplineElementLocator.h"

#include <memory>
#include <string>

class vtkLRSplineGeometryMap;

class SPLINEVIZCORE_EXPORT vtkLRSplineEvaluator
{
public:
  /**
   * Take the Bezier blocks (moved in) and build the locator (see
   * vtkLRSplineElementLocator::Build). False with a message on failure.
   */
  bool Initialize(
    vtkLRSplineBezierVolume&& volume, int locatorType, const int blocks[3], std::string* error);

  /// x = offset + scale * u per axis (scale > 0). Default: identity.
  void SetPhysicalTransform(const double scale[3], const double offset[3]);
  /**
   * x = A u + offset, A row-major (x_i = sum_j A[3 i + j] u_j + offset_i).
   * False (nothing changed) when A is singular or not finite.
   */
  bool SetPhysicalAffine(const double A[9], const double offset[3]);
  /// The map's matrix A (row-major), its inverse, and the offset.
  const double* GetMatrix() const { return this->Matrix; }
  const double* GetInverseMatrix() const { return this->Inverse; }
  const double* GetOffset() const { return this->Offset; }
  /// True when A is diagonal (per-axis scale).
  bool IsAxisAligned() const { return this->AxisAligned; }

  /**
   * A curved geometry map (same elements, same order as the field): then
   * physical points are mapped by it and the affine map is not used. A
   * rational map makes the field's coefficients homogeneous (w f, the
   * rational basis of the field). Call once, after Initialize(); false when
   * the map does not match the field's elements.
   */
  bool SetGeometry(std::shared_ptr<const vtkLRSplineGeometryMap> geometry);
  const vtkLRSplineGeometryMap* GetGeometry() const { return this->Geometry.get(); }

  const vtkLRSplineBezierVolume& GetVolume() const { return this->Volume; }
  const vtkLRSplineElementLocator& GetLocator() const { return this->Locator; }
  int GetNumberOfComponents() const { return this->Volume.NumberOfComponents; }
  /// 3 (volume) or 2 (surface).
  int GetParametricDimension() const { return this->Volume.ParametricDimension; }
  vtkIdType GetNumberOfElements() const { return this->Volume.GetNumberOfElements(); }
  /// Largest of the three degrees.
  int GetMaximumDegree() const;
  /// Physical bounding box (xmin, xmax, ymin, ymax, zmin, zmax), VTK order.
  void GetBounds(double bounds[6]) const;
  /// Shortest side of element e in physical units.
  double GetElementMinimumSide(vtkIdType e) const;

  /// Physical to parameter point (with a geometry map: NaN outside the geometry).
  void PhysicalToParameter(const double x[3], double u[3]) const;
  void ParameterToPhysical(const double u[3], double x[3]) const;

  /// Element containing physical point x, or -1.
  vtkIdType FindElement(const double x[3]) const;
  /// True when element e contains physical point x.
  bool ElementContains(vtkIdType e, const double x[3]) const;

  /**
   * Value (NumberOfComponents entries) and, if `gradient` is not null, the
   * gradient d value_c / d x_j at gradient[3c + j], at physical point x.
   * Returns the element, or -1 (nothing written) outside the domain.
   */
  vtkIdType Evaluate(const double x[3], double* value, double* gradient = nullptr) const;
  /// The same in single precision (needs MakeFloat() first).
  vtkIdType Evaluate(const float x[3], float* value, float* gradient = nullptr) const;

  /// Evaluate in element e (known to contain x; not checked).
  void EvaluateInElement(vtkIdType e, const double x[3], double* value, double* gradient) const;
  void EvaluateInElement(vtkIdType e, const float x[3], float* value, float* gradient) const;

  /**
   * If element e contains physical point x, evaluate there and return true
   * (one conversion to parameter space; the fast path of coherent queries).
   */
  bool EvaluateIfInElement(vtkIdType e, const double x[3], double* value, double* gradient) const;

  /**
   * A surface patch with a geometry map: the closest point of element e to
   * physical x (its foot, see vtkLRSplineGeometryMap) and the unit normal
   * there. False (nothing written) for volumes or when x is not on e.
   */
  bool ProjectOntoSurface(vtkIdType e, const double x[3], double point[3], double normal[3]) const;

  /// Evaluate at parameter point u; gradient with respect to u.
  vtkIdType EvaluateParameter(const double u[3], double* value, double* gradient = nullptr) const;

  /// Prepare the single-precision coefficients.
  void MakeFloat() { this->Volume.MakeFloatCoefficients(); }

  /**
   * n points (3 doubles each) in parallel. values: n * NumberOfComponents;
   * gradients (may be null): n * 3 * NumberOfComponents; elements (may be
   * null): the element or -1. Points outside get zeros.
   */
  void EvaluateBatch(const double* points, vtkIdType n, double* values, double* gradients,
    vtkIdType* elements) const;

private:
  // Value and physical gradient at parameter point u inside element e.
  void AtParameter(vtkIdType e, const double u[3], double* value, double* gradient) const;

  // With the geometry map: value and physical gradient at local s of element e.
  template <typename Real>
  void AtLocal(vtkIdType e, const double s[3], Real* value, Real* gradient) const;

  // Local gradients of element `box` (3 per component, in place) to physical ones.
  template <typename Real>
  void GradientToPhysical(Real* gradient, const double* box) const;

  vtkLRSplineBezierVolume Volume;
  vtkLRSplineElementLocator Locator;
  double Matrix[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  double Inverse[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  double Offset[3] = { 0, 0, 0 };
  bool AxisAligned = true;
  std::shared_ptr<const vtkLRSplineGeometryMap> Geometry;
};

#endif
// VTK-HeaderTest-Exclude: vtkLRSplineEvaluator.h
