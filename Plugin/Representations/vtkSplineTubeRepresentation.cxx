#include "vtkSplineTubeRepresentation.h"

#include "vtkInformation.h"
#include "vtkObjectFactory.h"
#include "vtkPVRenderView.h"
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
  lodMapper->ForceInteractiveOn();
  lodMapper->SetInteractiveFrameTime(0.15);
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
void vtkSplineTubeRepresentation::SetOcclusionCulling(bool culling)
{
  this->GetTubeMapper()->SetOcclusionCulling(culling);
  this->GetLODTubeMapper()->SetOcclusionCulling(culling);
  this->Modified();
}

//------------------------------------------------------------------------------
int vtkSplineTubeRepresentation::ProcessViewRequest(
  vtkInformationRequestKey* request_type, vtkInformation* inInfo, vtkInformation* outInfo)
{
  if (request_type == vtkPVView::REQUEST_UPDATE_LOD())
  {
    // No decimated geometry: the LOD mapper draws a subset of the full data.
    return 1;
  }
  const int result = this->Superclass::ProcessViewRequest(request_type, inInfo, outInfo);
  if (request_type == vtkPVView::REQUEST_RENDER() && this->Mapper->GetNumberOfInputConnections(0))
  {
    this->LODMapper->SetInputConnection(0, this->Mapper->GetInputConnection(0, 0));
  }
  return result;
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
