// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkLRSplineProbeFilter
 * @brief   Evaluates an LR-spline field (vtkLRSplineReader output) exactly at the points of any
 * data set, like vtkProbeFilter.
 *
 * Port 0 (Input): any vtkDataSet (or a composite of them) whose points are
 * where to evaluate: points, a line, a slice, an image for resampling.
 * Port 1 (Source): the spline, i.e. the output of vtkLRSplineReader (one
 * patch's vtkUnstructuredGrid or the whole vtkMultiBlockDataSet), or the
 * output of vtkIFEMReader: volumes or surfaces (in the plane or curved in
 * 3D). With several patches the first patch (in block order) that contains a
 * point wins.
 *
 * The field: the source's point array selected with
 * SetInputArrayToProcess(0, 1, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS,
 * name) (port 1, the spline), by default its active vectors, else scalars.
 *
 * Output: a copy of the input with point arrays
 * - the field, under the source array's name (double, same components);
 * - optionally its exact gradient (ComputeGradient; GradientArrayName,
 *   3 x components: d f_c / d x_j at component 3c + j, the Jacobian for
 *   vector fields);
 * - "vtkValidPointMask" (char, 1 where the point is inside the spline).
 *
 * Evaluation uses vtkLRSplineField (a k-d forest per patch, Fuchs et al.
 * §3.2, and the Bezier blocks of §3.2.3), in parallel over the points with
 * vtkSMPTools; the search structure is built once per source and reused while
 * the source does not change. Geometry-mode splines and IFEM results are
 * evaluated at physical points by inverting their geometry map
 * (vtkLRSplineGeometryMap); a surface at the closest point of a point within
 * SurfaceTolerance of it. UseParameterCoordinates evaluates at parameter
 * coordinates instead. Progress is
 * reported and abort honoured between batches of points (an aborted run
 * gives an empty output); an input whose probed arrays could not fit in this
 * machine's memory is refused before anything is allocated.
 *
 * The whole source is requested (piece 0 of 1) so that every piece of the
 * input is evaluated everywhere.
 */

#ifndef vtkLRSplineProbeFilter_h
#define vtkLRSplineProbeFilter_h

#include "SplineVizFiltersModule.h" // for export macro
#include "vtkDataSetAlgorithm.h"

#include <memory> // for std::unique_ptr
#include <string> // for std::string

class vtkLRSplineField;

class SPLINEVIZFILTERS_EXPORT vtkLRSplineProbeFilter : public vtkDataSetAlgorithm
{
public:
  static vtkLRSplineProbeFilter* New();
  vtkTypeMacro(vtkLRSplineProbeFilter, vtkDataSetAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The spline (port 1).
  void SetSourceConnection(vtkAlgorithmOutput* algOutput);
  void SetSourceData(vtkDataObject* source);
  vtkDataObject* GetSource();
  ///@}

  // The field to evaluate is input array 0, a point array of the spline on
  // port 1: SetInputArrayToProcess(0, 1, 0,
  // vtkDataObject::FIELD_ASSOCIATION_POINTS, name). Nothing selected (the
  // default) or an empty name: the spline's active vectors, else scalars.

  ///@{
  /**
   * Deprecated: use SetInputArrayToProcess(0, 1, 0,
   * vtkDataObject::FIELD_ASSOCIATION_POINTS, name) and
   * GetInputArrayInformation(0); kept for one release. nullptr clears the
   * selection.
   */
  void SetArrayName(const char* name);
  const char* GetArrayName();
  ///@}

  ///@{
  /// Also output the exact gradient. Default off.
  vtkSetMacro(ComputeGradient, vtkTypeBool);
  vtkGetMacro(ComputeGradient, vtkTypeBool);
  vtkBooleanMacro(ComputeGradient, vtkTypeBool);
  ///@}

  ///@{
  /// Name of the gradient array. Default "Gradient".
  vtkSetStringMacro(GradientArrayName);
  vtkGetStringMacro(GradientArrayName);
  ///@}

  ///@{
  /// Name of the mask array. Default "vtkValidPointMask".
  vtkSetStringMacro(ValidPointMaskArrayName);
  vtkGetStringMacro(ValidPointMaskArrayName);
  ///@}

  ///@{
  /// Interpret the input points as parameter coordinates. Default off.
  vtkSetMacro(UseParameterCoordinates, vtkTypeBool);
  vtkGetMacro(UseParameterCoordinates, vtkTypeBool);
  vtkBooleanMacro(UseParameterCoordinates, vtkTypeBool);
  ///@}

  ///@{
  /**
   * Element search (vtkLRSplineElementLocator::LocatorType): 0 linear,
   * 1 k-d tree, 2 k-d forest (default), 3 octree, 4 lookup texture (the last
   * two only for dyadic knots).
   */
  vtkSetClampMacro(LocatorType, int, 0, 4);
  vtkGetMacro(LocatorType, int);
  ///@}

  ///@{
  /// Blocks per direction of the k-d forest; 0 (default): about 2 (elements)^(1/3), at most 64.
  vtkSetClampMacro(ForestResolution, int, 0, 1024);
  vtkGetMacro(ForestResolution, int);
  ///@}

  ///@{
  /**
   * Surface results: how far from the surface a point may lie and still be
   * evaluated (at its closest point on the surface), relative to the size of
   * the element there (the diagonal of its control points' box). Farther
   * points are outside (mask 0). Default 0.01; 0 keeps only points on the
   * surface up to rounding (1e-9). Volumes ignore it.
   */
  vtkSetClampMacro(SurfaceTolerance, double, 0.0, 1.0);
  vtkGetMacro(SurfaceTolerance, double);
  ///@}

protected:
  vtkLRSplineProbeFilter();
  ~vtkLRSplineProbeFilter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  vtkTypeBool ComputeGradient = 0;
  char* GradientArrayName = nullptr;
  char* ValidPointMaskArrayName = nullptr;
  vtkTypeBool UseParameterCoordinates = 0;
  int LocatorType = 2;
  int ForestResolution = 0;
  double SurfaceTolerance = 0.01;

private:
  vtkLRSplineProbeFilter(const vtkLRSplineProbeFilter&) = delete;
  void operator=(const vtkLRSplineProbeFilter&) = delete;

  std::unique_ptr<vtkLRSplineField> Field;
  std::string FieldKey;
};

#endif
