// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkSplineTubeRepresentation
 * @brief   ParaView geometry representation drawing polylines with a spline-tube mapper.
 *
 * Base of the SplineViz line representations ("Ray-Cast Tubes",
 * "Tessellated Tubes", "Stylized Lines"): a geometry representation (with
 * faces, so that it can stand in for ParaView's SurfaceRepresentation) whose
 * mappers (full and LOD) are replaced by a vtkSplineTubeMapper subclass, with
 * the settings every line mapper shares forwarded to both. Everything else
 * (coloring by arrays and lookup tables, opacity, lighting, block handling of
 * composite data, parallel rendering) is the geometry representation's.
 *
 * Level of detail: while the camera moves, ParaView draws the LOD mapper
 * (for data above the view's LOD threshold). Here the LOD mapper is a
 * stand-in (vtkSplineTubeMapper::SetLevelOfDetailOf) that has the full
 * mapper draw a subset of the lines sized to the interaction budget, from
 * the data and GPU buffers it already holds, instead of the decimated
 * geometry ParaView makes for surfaces (a quadric clustering that would
 * break the lines and cost seconds on large tractograms) or a second copy.
 *
 * The automatic radius (Tube Radius 0, the default) is taken from the bounds
 * of the whole data set, reduced over the ranks of a parallel server, so
 * that every piece is drawn with the same radius.
 */
#ifndef vtkSplineTubeRepresentation_h
#define vtkSplineTubeRepresentation_h

#include "SplineVizParaViewModule.h" // for export macro
#include "vtkGeometryRepresentationWithFaces.h"

class vtkSplineTubeMapper;

class SPLINEVIZPARAVIEW_EXPORT vtkSplineTubeRepresentation
  : public vtkGeometryRepresentationWithFaces
{
public:
  vtkTypeMacro(vtkSplineTubeRepresentation, vtkGeometryRepresentationWithFaces);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Forwarded to the tube mappers (see vtkSplineTubeMapper). A radius array
   * name that is empty or "None" selects the constant Radius; a visibility
   * array name that is empty or "None" draws all lines.
   */
  void SetRadius(double radius);
  void SetRadiusArray(const char* name);
  void SetVisibilityArray(const char* name);
  void SetDirectionColoring(bool direction);
  void SetEndpointMarkers(bool markers);
  void SetEndpointMarkerScale(double scale);
  void SetEndpointMarkerColor(double r, double g, double b);
  void SetSlabOrigin(double x, double y, double z);
  void SetSlabNormal(double x, double y, double z);
  void SetSlabThickness(double thickness);
  void SetRadiusScale(double scale);
  void SetOcclusionCulling(bool culling);
  void SetMinimumPixelWidth(double width);
  ///@}

  /// The LOD mapper draws the full data (see the class comment).
  int ProcessViewRequest(vtkInformationRequestKey* request_type, vtkInformation* inInfo,
    vtkInformation* outInfo) override;

  /**
   * Selection ids: the tube mappers report the picked polyline's original
   * cell id from `cellArray` (nullptr: "vtkOriginalCellIds"); tubes have no
   * points to pick. (The superclass' version expects a
   * vtkCompositePolyDataMapper2.)
   */
  void SetArrayIdNames(const char* pointArray, const char* cellArray) override;

protected:
  vtkSplineTubeRepresentation();
  ~vtkSplineTubeRepresentation() override;

  /// Replace the superclass' mappers by these (takes the references).
  void SetTubeMappers(vtkSplineTubeMapper* mapper, vtkSplineTubeMapper* lodMapper);

  vtkSplineTubeMapper* GetTubeMapper();
  vtkSplineTubeMapper* GetLODTubeMapper();

private:
  /// The mappers' automatic radius from the bounds of the data on all ranks.
  void UpdateAutomaticRadiusBounds();

  vtkSplineTubeRepresentation(const vtkSplineTubeRepresentation&) = delete;
  void operator=(const vtkSplineTubeRepresentation&) = delete;
};

#endif
