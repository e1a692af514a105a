// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkStylizedLineRepresentation
 * @brief   ParaView representation "Stylized Lines": polylines as stylized line primitives.
 *
 * A vtkSplineTubeRepresentation backed by vtkStylizedLineMapper (Stoll,
 * Gumhold and Seidel, "Visualization with stylized line primitives"): lit
 * generalized cylinders splatted as silhouette quads, with a halo, textures
 * along the lines turned by an orientation array, depth correction and the
 * hybrid fix-up where the lines point at the viewer. The radius settings are
 * the tube representations'; everything else of the mapper is forwarded.
 */
#ifndef vtkStylizedLineRepresentation_h
#define vtkStylizedLineRepresentation_h

#include "SplineVizParaViewModule.h" // for export macro
#include "vtkSplineTubeRepresentation.h"

class SPLINEVIZPARAVIEW_EXPORT vtkStylizedLineRepresentation : public vtkSplineTubeRepresentation
{
public:
  static vtkStylizedLineRepresentation* New();
  vtkTypeMacro(vtkStylizedLineRepresentation, vtkSplineTubeRepresentation);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Forwarded to both vtkStylizedLineMapper instances (see there). An
   * orientation array name that is empty or "None" selects none.
   */
  void SetHaloWidth(double width);
  void SetHaloColor(double r, double g, double b);
  void SetHaloColorFromBackground(bool on);
  void SetHaloDepthOffset(double radii);
  void SetDepthDependentHalo(bool on);
  void SetHaloDepthRange(double radii);
  void SetExactSilhouette(bool on);
  void SetDepthCorrection(bool on);
  void SetFixUp(bool on);
  void SetFixUpEpsilon(double epsilon);
  void SetFixUpSides(int sides);
  void SetCapping(bool on);
  void SetTexturePattern(int pattern);
  void SetTextureRepeat(double length);
  void SetTextureRepeatUnits(int units);
  void SetTextureCircumferentialRepeat(int copies);
  void SetOrientationArray(const char* name);
  void SetNormalMapping(bool on);
  void SetShadows(bool on);
  ///@}

protected:
  vtkStylizedLineRepresentation();
  ~vtkStylizedLineRepresentation() override;

private:
  vtkStylizedLineRepresentation(const vtkStylizedLineRepresentation&) = delete;
  void operator=(const vtkStylizedLineRepresentation&) = delete;
};

#endif
