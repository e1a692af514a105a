// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkPVStreamlineSelection
 * @brief   vtkStreamlineSelection with one sphere and one box region given as
 * ParaView's 3D widgets set them (the "Select Streamlines" filter).
 *
 * The sphere (SphereCenter, SphereRadius) and the box (BoxPosition,
 * BoxRotation, BoxScale: the unit box [0, 1]^3 scaled, rotated by the angles
 * in degrees about z, x, y, and moved, as ParaView's box widget and vtkPVBox
 * define it) each have a role: SphereRole / BoxRole 0 = off, 1 = include,
 * 2 = exclude, 3 = endpoint. They replace the regions of the superclass each
 * time one of them changes; the box is a vtkPVBox, tested exactly by the
 * superclass (a vtkBox under a linear transform). Combination, endpoint and
 * output modes are the superclass's.
 */
#ifndef vtkPVStreamlineSelection_h
#define vtkPVStreamlineSelection_h

#include "SplineVizParaViewModule.h" // for export macro
#include "vtkNew.h"                  // for vtkNew
#include "vtkStreamlineSelection.h"

class vtkPVBox;

class SPLINEVIZPARAVIEW_EXPORT vtkPVStreamlineSelection : public vtkStreamlineSelection
{
public:
  static vtkPVStreamlineSelection* New();
  vtkTypeMacro(vtkPVStreamlineSelection, vtkStreamlineSelection);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum WidgetRoles
  {
    OFF = 0,
    WIDGET_INCLUDE = 1,
    WIDGET_EXCLUDE = 2,
    WIDGET_ENDPOINT = 3
  };

  ///@{
  /// The sphere region: role (default WIDGET_INCLUDE), centre, radius (default 1).
  void SetSphereRole(int role);
  vtkGetMacro(SphereRole, int);
  void SetSphereCenter(double x, double y, double z);
  vtkGetVector3Macro(SphereCenter, double);
  void SetSphereRadius(double radius);
  vtkGetMacro(SphereRadius, double);
  ///@}

  ///@{
  /// The box region: role (default OFF), position, rotation (degrees), scale.
  void SetBoxRole(int role);
  vtkGetMacro(BoxRole, int);
  void SetBoxPosition(double x, double y, double z);
  vtkGetVector3Macro(BoxPosition, double);
  void SetBoxRotation(double x, double y, double z);
  vtkGetVector3Macro(BoxRotation, double);
  void SetBoxScale(double x, double y, double z);
  vtkGetVector3Macro(BoxScale, double);
  ///@}

protected:
  vtkPVStreamlineSelection();
  ~vtkPVStreamlineSelection() override;

  int SphereRole = WIDGET_INCLUDE;
  double SphereCenter[3] = { 0, 0, 0 };
  double SphereRadius = 1;
  int BoxRole = OFF;
  double BoxPosition[3] = { 0, 0, 0 };
  double BoxRotation[3] = { 0, 0, 0 };
  double BoxScale[3] = { 1, 1, 1 };

private:
  vtkPVStreamlineSelection(const vtkPVStreamlineSelection&) = delete;
  void operator=(const vtkPVStreamlineSelection&) = delete;

  void UpdateRegions();
  vtkNew<vtkPVBox> Box;
};

#endif
