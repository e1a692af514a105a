// SPDX-License-Identifier: BSD-3-Clause
#include "vtkPVStreamlineSelection.h"

#include "vtkObjectFactory.h"
#include "vtkPVBox.h"

#include <algorithm>

vtkStandardNewMacro(vtkPVStreamlineSelection);

namespace
{
int ClampRole(int role)
{
  return std::min(static_cast<int>(vtkPVStreamlineSelection::WIDGET_ENDPOINT),
    std::max(static_cast<int>(vtkPVStreamlineSelection::OFF), role));
}
}

vtkPVStreamlineSelection::vtkPVStreamlineSelection()
{
  this->UpdateRegions();
}

vtkPVStreamlineSelection::~vtkPVStreamlineSelection() = default;

void vtkPVStreamlineSelection::UpdateRegions()
{
  this->RemoveAllRegions();
  if (this->SphereRole != OFF)
  {
    this->AddSphere(this->SphereCenter, this->SphereRadius, this->SphereRole - 1);
  }
  if (this->BoxRole != OFF)
  {
    this->Box->SetUseReferenceBounds(false);
    this->Box->SetPosition(this->BoxPosition);
    this->Box->SetRotation(this->BoxRotation);
    this->Box->SetScale(this->BoxScale);
    this->AddImplicitFunction(this->Box, this->BoxRole - 1);
  }
  this->Modified();
}

void vtkPVStreamlineSelection::SetSphereRole(int role)
{
  this->SphereRole = ClampRole(role);
  this->UpdateRegions();
}

void vtkPVStreamlineSelection::SetSphereCenter(double x, double y, double z)
{
  this->SphereCenter[0] = x;
  this->SphereCenter[1] = y;
  this->SphereCenter[2] = z;
  this->UpdateRegions();
}

void vtkPVStreamlineSelection::SetSphereRadius(double radius)
{
  this->SphereRadius = radius;
  this->UpdateRegions();
}

void vtkPVStreamlineSelection::SetBoxRole(int role)
{
  this->BoxRole = ClampRole(role);
  this->UpdateRegions();
}

void vtkPVStreamlineSelection::SetBoxPosition(double x, double y, double z)
{
  this->BoxPosition[0] = x;
  this->BoxPosition[1] = y;
  this->BoxPosition[2] = z;
  this->UpdateRegions();
}

void vtkPVStreamlineSelection::SetBoxRotation(double x, double y, double z)
{
  this->BoxRotation[0] = x;
  this->BoxRotation[1] = y;
  this->BoxRotation[2] = z;
  this->UpdateRegions();
}

void vtkPVStreamlineSelection::SetBoxScale(double x, double y, double z)
{
  this->BoxScale[0] = x;
  this->BoxScale[1] = y;
  this->BoxScale[2] = z;
  this->UpdateRegions();
}

void vtkPVStreamlineSelection::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SphereRole: " << this->SphereRole << "\n";
  os << indent << "SphereCenter: " << this->SphereCenter[0] << " " << this->SphereCenter[1] << " "
     << this->SphereCenter[2] << "\n";
  os << indent << "SphereRadius: " << this->SphereRadius << "\n";
  os << indent << "BoxRole: " << this->BoxRole << "\n";
  os << indent << "BoxPosition: " << this->BoxPosition[0] << " " << this->BoxPosition[1] << " "
     << this->BoxPosition[2] << "\n";
  os << indent << "BoxRotation: " << this->BoxRotation[0] << " " << this->BoxRotation[1] << " "
     << this->BoxRotation[2] << "\n";
  os << indent << "BoxScale: " << this->BoxScale[0] << " " << this->BoxScale[1] << " "
     << this->BoxScale[2] << "\n";
}
