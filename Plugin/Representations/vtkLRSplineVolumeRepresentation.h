// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkLRSplineVolumeRepresentation
 * @brief   ParaView representation "LR-Spline Volume": direct volume rendering of LR-spline
 * volumes with vtkLRSplineVolumeMapper, exact to the spline.
 *
 * ParaView's unstructured-grid volume representation tetrahedralizes its
 * input before any mapper sees it, which splits the Bezier cells of
 * vtkLRSplineReader through their control points. So this is a
 * vtkVolumeRepresentation of its own (the pattern of ParaView's
 * pvNVIDIAIndeX plugin): it hands the reader's vtkMultiBlockDataSet of
 * VTK_BEZIER_HEXAHEDRON patches, unchanged, to vtkLRSplineVolumeMapper
 * (Fuchs et al., "Direct interactive visualization of locally refined spline
 * volumes", §4).
 *
 * Forwarded as ParaView's volume representations do: the color map and
 * opacity editor (LookupTable, ScalarOpacityFunction,
 * ScalarOpacityUnitDistance); the color array with its vector mode and
 * component (Magnitude, X, Y, Z) as the mapper's FieldArray, VectorMode
 * and VectorComponent (without a color array: the spline's first field
 * through ParaView's default color map and opacity ramp); Shade with
 * Ambient, Diffuse, Specular, SpecularPower; BlendMode and IsosurfaceValues;
 * block visibility; the actor's position, orientation, scale and origin. Its
 * own settings are the mapper's, with the trimming surface on input port 1.
 *
 * Parallel: the whole data set is requested on every rank and only the first
 * rank renders it; the view composites the ranks' images in visibility
 * order, so the picture equals a single process's. The data is never sent to
 * the client. Interactive (LOD) renders draw the outline of the patches' box.
 *
 * Ignored: the mapper choice, the resampling dimensions, data partitions. Not
 * supported (a warning says so): a separate opacity array, multi-component
 * mapping. Details: docs/components.md, "LR-Spline Volume in ParaView".
 *
 * @sa vtkLRSplineVolumeMapper vtkLRSplineReader
 */
#ifndef vtkLRSplineVolumeRepresentation_h
#define vtkLRSplineVolumeRepresentation_h

#include "SplineVizParaViewModule.h" // for export macro
#include "vtkNew.h"                  // for vtkNew
#include "vtkSmartPointer.h"         // for vtkSmartPointer
#include "vtkVolumeRepresentation.h"

class vtkColorTransferFunction;
class vtkExtractBlockUsingDataAssembly;
class vtkLRSplineVolumeMapper;
class vtkPiecewiseFunction;
class vtkPolyData;
class vtkPolyDataMapper;

class SPLINEVIZPARAVIEW_EXPORT vtkLRSplineVolumeRepresentation : public vtkVolumeRepresentation
{
public:
  static vtkLRSplineVolumeRepresentation* New();
  vtkTypeMacro(vtkLRSplineVolumeRepresentation, vtkVolumeRepresentation);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  int ProcessViewRequest(vtkInformationRequestKey* request_type, vtkInformation* inInfo,
    vtkInformation* outInfo) override;

  ///@{
  /**
   * Forwarded to the vtkVolumeProperty (as vtkImageVolumeRepresentation does).
   * The iso values are the property's (SetIsosurfaceValue(i, value) after
   * SetNumberOfIsosurfaces(n), ParaView's IsosurfaceValues property).
   */
  void SetShade(bool shade);
  void SetAmbient(double value);
  void SetDiffuse(double value);
  void SetSpecular(double value);
  void SetSpecularPower(double value);
  void SetIsosurfaceValue(int i, double value);
  void SetNumberOfIsosurfaces(int number);
  ///@}

  ///@{
  /**
   * Forwarded to vtkLRSplineVolumeMapper (see there).
   */
  void SetBlendMode(int mode);
  void SetElementLocator(int locator);
  void SetForestResolution(int resolution);
  void SetAdaptiveSteps(bool adaptive);
  void SetStepScale(double scale);
  void SetSampleDistance(double distance);
  void SetSupersampling(int samples);
  void SetUseJittering(bool jitter);
  void SetShadingModel(int model);
  void SetIsosurfaceBisections(int steps);
  void SetMaximumNumberOfSteps(int steps);
  ///@}

  /**
   * Without a Trimming Surface, trim by the boundary of the data an LR-Spline
   * Fit fitted (vtkLRSplineField::TRIMMING_SURFACE on its spline). Default on.
   */
  void SetTrimByDataBoundary(bool trim);

  ///@{
  /**
   * Forwarded to a vtkExtractBlockUsingDataAssembly before the mapper: the
   * multiblock inspector's block selection (which patches are rendered).
   */
  void SetActiveAssembly(const char* name);
  void AddBlockSelector(const char* selector);
  void RemoveAllBlockSelectors();
  ///@}

  ///@{
  /**
   * Settings of ParaView's unstructured-grid volume representation, whose
   * properties this one's proxy inherits: they have no meaning for the LR-spline
   * mapper and are ignored.
   */
  void SetActiveVolumeMapper(const char*) {}
  void SetSamplingDimensions(int, int, int) {}
  void SetUseDataPartitions(bool) {}
  ///@}

  /// The mapper (for tests and scripting).
  vtkLRSplineVolumeMapper* GetVolumeMapper();

  /**
   * The rank that renders the spline in parallel (0; every other rank renders
   * nothing of it).
   */
  static int GetRenderingRank() { return 0; }

protected:
  vtkLRSplineVolumeRepresentation();
  ~vtkLRSplineVolumeRepresentation() override;

  /// Port 0: the spline (composite data or an unstructured grid); port 1: the trimming surface.
  int FillInputPortInformation(int port, vtkInformation* info) override;

  /// The whole data set on every port (no piece split).
  int RequestUpdateExtent(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  bool AddToView(vtkView* view) override;
  bool RemoveFromView(vtkView* view) override;

  /// Color array, vector mode, warnings: before each render (`data`: the delivered spline).
  void UpdateMapperParameters(vtkDataObject* data);

  /**
   * Without a color array: the spline's default field (the mapper's) through
   * ParaView's default color map ("Cool to Warm", diverging) and opacity ramp
   * (0 to 1) over the range of its coefficients (which bound its values), as
   * ParaView's "Volume" representation colors a new data set.
   */
  void UseDefaultTransferFunction(vtkDataObject* data);

  vtkNew<vtkLRSplineVolumeMapper> VolumeMapper;
  vtkNew<vtkPolyDataMapper> LODMapper;
  vtkNew<vtkExtractBlockUsingDataAssembly> BlockExtractor;
  vtkNew<vtkColorTransferFunction> DefaultColor;
  vtkNew<vtkPiecewiseFunction> DefaultOpacity;
  double DefaultRange[2] = { 0.0, 0.0 };
  vtkSmartPointer<vtkDataObject> Spline;        // what this rank delivers on port 0
  vtkSmartPointer<vtkPolyData> TrimmingSurface; // what this rank delivers on port 1
  vtkSmartPointer<vtkPolyData> Outline;         // the LOD picture
  bool HasTrimmingSurface = false;
  bool TrimByDataBoundary = true;
  std::string LastWarning;

private:
  vtkLRSplineVolumeRepresentation(const vtkLRSplineVolumeRepresentation&) = delete;
  void operator=(const vtkLRSplineVolumeRepresentation&) = delete;
};

#endif
