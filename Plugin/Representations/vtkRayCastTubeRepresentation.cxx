// SPDX-License-Identifier: BSD-3-Clause
#include "vtkRayCastTubeRepresentation.h"

#include "vtkObjectFactory.h"
#include "vtkRayCastTubeMapper.h"

vtkStandardNewMacro(vtkRayCastTubeRepresentation);

//------------------------------------------------------------------------------
vtkRayCastTubeRepresentation::vtkRayCastTubeRepresentation()
{
  this->SetTubeMappers(vtkRayCastTubeMapper::New(), vtkRayCastTubeMapper::New());
}

//------------------------------------------------------------------------------
vtkRayCastTubeRepresentation::~vtkRayCastTubeRepresentation() = default;

//------------------------------------------------------------------------------
void vtkRayCastTubeRepresentation::SetSubSegments(int n)
{
  static_cast<vtkRayCastTubeMapper*>(this->Mapper)->SetSubSegments(n);
  static_cast<vtkRayCastTubeMapper*>(this->LODMapper)->SetSubSegments(n);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkRayCastTubeRepresentation::SetRootIterations(int n)
{
  static_cast<vtkRayCastTubeMapper*>(this->Mapper)->SetRootIterations(n);
  static_cast<vtkRayCastTubeMapper*>(this->LODMapper)->SetRootIterations(n);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkRayCastTubeRepresentation::SetStraightTolerance(double tolerance)
{
  static_cast<vtkRayCastTubeMapper*>(this->Mapper)->SetStraightTolerance(tolerance);
  static_cast<vtkRayCastTubeMapper*>(this->LODMapper)->SetStraightTolerance(tolerance);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkRayCastTubeRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
