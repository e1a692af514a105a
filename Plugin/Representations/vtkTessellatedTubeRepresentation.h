// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkTessellatedTubeRepresentation
 * @brief   ParaView representation "Tessellated Tubes": polylines as tessellated spline tubes.
 *
 * A vtkSplineTubeRepresentation backed by vtkTessellatedTubeMapper (Salm,
 * "Interactive Rendering of Spline Tubes", §3.1): a base mesh bent along the
 * splines and refined by the GPU's tessellation unit towards the
 * silhouettes, flat end caps. Adds the tessellation settings (refinement
 * criteria and their bounds, base mesh, level of detail, capping).
 */
#ifndef vtkTessellatedTubeRepresentation_h
#define vtkTessellatedTubeRepresentation_h

#include "SplineVizParaViewModule.h" // for export macro
#include "vtkSplineTubeRepresentation.h"

class SPLINEVIZPARAVIEW_EXPORT vtkTessellatedTubeRepresentation : public vtkSplineTubeRepresentation
{
public:
  static vtkTessellatedTubeRepresentation* New();
  vtkTypeMacro(vtkTessellatedTubeRepresentation, vtkSplineTubeRepresentation);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Forwarded to both vtkTessellatedTubeMapper instances.
   */
  void SetMaxEdgeLength(double pixels);
  void SetMaxSilhouetteEdgeLength(double pixels);
  void SetMaxTessellationLevel(int level);
  void SetMaxSilhouetteTessellationLevel(int level);
  void SetBaseRings(int rings);
  void SetBaseSides(int sides);
  void SetLevelOfDetail(bool on);
  void SetCapping(bool on);
  ///@}

protected:
  vtkTessellatedTubeRepresentation();
  ~vtkTessellatedTubeRepresentation() override;

private:
  vtkTessellatedTubeRepresentation(const vtkTessellatedTubeRepresentation&) = delete;
  void operator=(const vtkTessellatedTubeRepresentation&) = delete;
};

#endif
