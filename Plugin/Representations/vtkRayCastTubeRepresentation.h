// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkRayCastTubeRepresentation
 * @brief   ParaView representation "Ray-Cast Tubes": polylines as ray-cast spline tubes.
 *
 * A vtkSplineTubeRepresentation backed by vtkRayCastTubeMapper (Salm,
 * "Interactive Rendering of Spline Tubes", §3.2). Adds the ray-casting
 * settings SubSegments, RootIterations and StraightTolerance (closed-form
 * intersection of straight segments).
 */
#ifndef vtkRayCastTubeRepresentation_h
#define vtkRayCastTubeRepresentation_h

#include "SplineVizParaViewModule.h" // for export macro
#include "vtkSplineTubeRepresentation.h"

class SPLINEVIZPARAVIEW_EXPORT vtkRayCastTubeRepresentation : public vtkSplineTubeRepresentation
{
public:
  static vtkRayCastTubeRepresentation* New();
  vtkTypeMacro(vtkRayCastTubeRepresentation, vtkSplineTubeRepresentation);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Forwarded to both vtkRayCastTubeMapper instances.
   */
  void SetSubSegments(int n);
  void SetRootIterations(int n);
  void SetStraightTolerance(double tolerance);
  ///@}

protected:
  vtkRayCastTubeRepresentation();
  ~vtkRayCastTubeRepresentation() override;

private:
  vtkRayCastTubeRepresentation(const vtkRayCastTubeRepresentation&) = delete;
  void operator=(const vtkRayCastTubeRepresentation&) = delete;
};

#endif
