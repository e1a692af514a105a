#include "vtkSplineTubeRepresentation.h"

#include "vtkObjectFactory.h"
#include "vtkSplineTubeMapper.h"

#include <cstring>

//------------------------------------------------------------------------------
vtkSplineTubeRepresentation::vtkSplineTubeRepresentation() = default;

//------------------------------------------------------------------------------
vtkSplineTubeRepresentation::~vtkSplineTubeRepresentation() = default;

//------------------------------------------------------------------------------
void vtkSplineTubeRepresentation::SetTubeMappers(
  vtkSplineTubeMapper* mapper, vtkSplineTubeMapper* lodMapper)
{
  this->Mapper->Delete();
  this->LODMapper->Delete();
  this->Mapper = mapper;
  this->LODMapper = lodMapper;
  // The superclass wires its pipeline and actor to the mappers here.
  this->SetupDefaults();
}

//------------------------------------------------------------------------------
vtkSplineTubeMapper* vtkSplineTubeRepresentation::GetTubeMapper()
{
  return vtkSplineTubeMapper::SafeDownCast(this->Mapper);
}

//------------------------------------------------------------------------------
vtkSplineTubeMapper* vtkSplineTubeRepresentation::GetLODTubeMapper()
{
  return vtkSplineTubeMapper::SafeDownCast(this->LODMapper);
}

//------------------------------------------------------------------------------
void vtkSplineTubeRepresentation::SetRadius(double radius)
{
  this->GetTubeMapper()->SetRadius(radius);
  this->GetLODTubeMapper()->SetRadius(radius);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkSplineTubeRepresentation::SetRadiusArray(const char* name)
{
  if (name && (name[0] == '\0' || std::strcmp(name, "None") == 0))
  {
    name = nullptr;
  }
  this->GetTubeMapper()->SetRadiusArray(name);
  this->GetLODTubeMapper()->SetRadiusArray(name);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkSplineTubeRepresentation::SetRadiusScale(double scale)
{
  this->GetTubeMapper()->SetRadiusScale(scale);
  this->GetLODTubeMapper()->SetRadiusScale(scale);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkSplineTubeRepresentation::SetArrayIdNames(const char*, const char* cellArray)
{
  const char* name = cellArray ? cellArray : "vtkOriginalCellIds";
  this->GetTubeMapper()->SetCellIdArrayName(name);
  this->GetLODTubeMapper()->SetCellIdArrayName(name);
}

//------------------------------------------------------------------------------
void vtkSplineTubeRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
