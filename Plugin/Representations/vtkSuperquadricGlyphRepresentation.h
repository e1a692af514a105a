// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkSuperquadricGlyphRepresentation
 * @brief   ParaView representation "Superquadric Glyphs": a tensor glyph at every point.
 *
 * Draws vtkSuperquadricGlyphMapper's ray-cast superquadric tensor glyphs
 * (Kindlmann 2004; Hlawitschka et al.) at every point of any data set with a
 * point tensor array, including image data (DTI volumes), unstructured
 * grids and composite data.
 *
 * vtkGeometryRepresentation, which this class extends for its coloring,
 * lookup tables, opacity, lighting and selection machinery, extracts the
 * *surface* of its input with vtkPVGeometryFilter: for glyphs at every point
 * of a volume that would keep only the boundary points. This representation
 * replaces that geometry filter by one that keeps every point of the input
 * with its point data (shallow copies; points of image and rectilinear data
 * are generated), so the delivered data are the glyph centres. The mappers
 * are swapped for vtkSuperquadricGlyphMapper; level-of-detail rendering is
 * off (the glyphs are already cheap). The bounds reported to the view
 * include the glyphs' extent.
 *
 * Composite inputs keep their structure, and the display's block colors,
 * opacities and visibilities (Block Colors, Block Opacities, Hide Block)
 * reach the mapper as vtkCompositeDataDisplayAttributes.
 *
 * The glyph properties (Set...) only change the mappers' uniforms: the view
 * re-renders without re-executing the pipeline or uploading the tensors.
 */
#ifndef vtkSuperquadricGlyphRepresentation_h
#define vtkSuperquadricGlyphRepresentation_h

#include "SplineVizParaViewModule.h" // for export macro
#include "vtkGeometryRepresentationWithFaces.h"

class vtkSuperquadricGlyphMapper;

class SPLINEVIZPARAVIEW_EXPORT vtkSuperquadricGlyphRepresentation
  : public vtkGeometryRepresentationWithFaces
{
public:
  static vtkSuperquadricGlyphRepresentation* New();
  vtkTypeMacro(vtkSuperquadricGlyphRepresentation, vtkGeometryRepresentationWithFaces);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Forwarded to both vtkSuperquadricGlyphMapper instances (see there). Array
   * names that are empty or "None" mean: the active point tensors, no mask.
   */
  void SetTensorArray(const char* name);
  void SetTensorLayout(int layout);
  void SetMaskArray(const char* name);
  void SetGamma(double gamma);
  void SetMinimumRoundness(double value);
  void SetGlyphScaleFactor(double value);
  void SetGlyphScaleMode(int mode);
  void SetMaximumScale(double value);
  void SetMinimumThickness(double value);
  void SetAnisotropyThreshold(double value);
  void SetMinimumEigenvalue(double value);
  void SetNegativeEigenvaluePolicy(int policy);
  void SetGlyphColorMode(int mode);
  void SetMaximumIterations(int n);
  void SetCulling(int culling);
  ///@}

  /**
   * Selection ids: nothing to set (the glyph mapper is not the
   * vtkCompositePolyDataMapper2 the superclass' version expects, which made
   * every selection in a view with this representation crash).
   */
  void SetArrayIdNames(const char*, const char*) override {}

  /// The mapper (for tests and scripting).
  vtkSuperquadricGlyphMapper* GetGlyphMapper();

  int ProcessViewRequest(vtkInformationRequestKey* request_type, vtkInformation* inInfo,
    vtkInformation* outInfo) override;

protected:
  vtkSuperquadricGlyphRepresentation();
  ~vtkSuperquadricGlyphRepresentation() override;

private:
  vtkSuperquadricGlyphRepresentation(const vtkSuperquadricGlyphRepresentation&) = delete;
  void operator=(const vtkSuperquadricGlyphRepresentation&) = delete;
};

#endif
