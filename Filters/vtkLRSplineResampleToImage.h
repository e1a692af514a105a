// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkLRSplineResampleToImage
 * @brief   Samples an LR-spline field (vtkLRSplineReader output) exactly on a regular grid
 * (vtkImageData).
 *
 * The convenience counterpart of vtkResampleToImage for LR splines: the
 * output is a vtkImageData with SamplingDimensions points spanning the
 * spline's bounds (UseInputBounds, default) or SamplingBounds, whose point
 * data holds the field (the spline's point array selected with
 * SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS,
 * name), by default its active vectors, else scalars) evaluated exactly
 * (vtkLRSplineField: k-d forest
 * look-up and Bezier evaluation, Fuchs et al. §3.2), optionally its gradient,
 * and "vtkValidPointMask". Parallel over the samples (vtkSMPTools); honours
 * update extents (each piece samples only its extent). Reports progress and
 * honours abort between batches of samples (an aborted run gives an empty
 * image); sampling dimensions whose image could not fit in this machine's
 * memory (e.g. 100000^3) are refused with an error before anything is
 * allocated.
 *
 * With several patches the first patch containing a sample wins (see
 * vtkLRSplineProbeFilter).
 */

#ifndef vtkLRSplineResampleToImage_h
#define vtkLRSplineResampleToImage_h

#include "SplineVizFiltersModule.h" // for export macro
#include "vtkImageAlgorithm.h"

#include <memory> // for std::unique_ptr
#include <string> // for std::string

class vtkLRSplineField;

class SPLINEVIZFILTERS_EXPORT vtkLRSplineResampleToImage : public vtkImageAlgorithm
{
public:
  static vtkLRSplineResampleToImage* New();
  vtkTypeMacro(vtkLRSplineResampleToImage, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Number of samples per direction. Default 64 64 64.
  vtkSetVector3Macro(SamplingDimensions, int);
  vtkGetVector3Macro(SamplingDimensions, int);
  ///@}

  ///@{
  /// Sample the spline's bounds (default on) or SamplingBounds.
  vtkSetMacro(UseInputBounds, vtkTypeBool);
  vtkGetMacro(UseInputBounds, vtkTypeBool);
  vtkBooleanMacro(UseInputBounds, vtkTypeBool);
  ///@}

  ///@{
  /// Box sampled when UseInputBounds is off (xmin, xmax, ymin, ymax, zmin, zmax).
  vtkSetVector6Macro(SamplingBounds, double);
  vtkGetVector6Macro(SamplingBounds, double);
  ///@}

  // The field to sample is input array 0, a point array of the spline:
  // SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS,
  // name). Nothing selected (the default) or an empty name: the spline's
  // active vectors, else scalars.

  ///@{
  /**
   * Deprecated: use SetInputArrayToProcess(0, 0, 0,
   * vtkDataObject::FIELD_ASSOCIATION_POINTS, name) and
   * GetInputArrayInformation(0); kept for one release. nullptr clears the
   * selection.
   */
  void SetArrayName(const char* name);
  const char* GetArrayName();
  ///@}

  ///@{
  /// Also sample the exact gradient (array "Gradient"). Default off.
  vtkSetMacro(ComputeGradient, vtkTypeBool);
  vtkGetMacro(ComputeGradient, vtkTypeBool);
  vtkBooleanMacro(ComputeGradient, vtkTypeBool);
  ///@}

  ///@{
  /// Element search, see vtkLRSplineProbeFilter. Default 2 (k-d forest).
  vtkSetClampMacro(LocatorType, int, 0, 4);
  vtkGetMacro(LocatorType, int);
  vtkSetClampMacro(ForestResolution, int, 0, 1024);
  vtkGetMacro(ForestResolution, int);
  ///@}

protected:
  vtkLRSplineResampleToImage();
  ~vtkLRSplineResampleToImage() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int SamplingDimensions[3] = { 64, 64, 64 };
  vtkTypeBool UseInputBounds = 1;
  double SamplingBounds[6] = { 0, 1, 0, 1, 0, 1 };
  vtkTypeBool ComputeGradient = 0;
  int LocatorType = 2;
  int ForestResolution = 0;

private:
  vtkLRSplineResampleToImage(const vtkLRSplineResampleToImage&) = delete;
  void operator=(const vtkLRSplineResampleToImage&) = delete;

  std::unique_ptr<vtkLRSplineField> Field;
  std::string FieldKey;
};

#endif
