// SPDX-License-Identifier: BSD-3-Clause
#include "vtkSplineTubeRepresentation.h"

#include "vtkCommunicator.h"
#include "vtkInformation.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"
#include "vtkPVRenderView.h"
#include "vtkSplineTubeMapper.h"

#include <algorithm>
#include <cfloat>
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
  // The LOD mapper draws the full mapper's data as a subset (no copy).
  lodMapper->SetLevelOfDetailOf(mapper);
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
namespace
{
// ParaView's array lists say "None" (or nothing) for no array.
const char* ArrayOrNull(const char* name)
{
  return (name && (name[0] == '\0' || std::strcmp(name, "None") == 0)) ? nullptr : name;
}
}

void vtkSplineTubeRepresentation::SetRadiusArray(const char* name)
{
  this->GetTubeMapper()->SetRadiusArray(ArrayOrNull(name));
  this->GetLODTubeMapper()->SetRadiusArray(ArrayOrNull(name));
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkSplineTubeRepresentation::SetDirectionColoring(bool direction)
{
  this->GetTubeMapper()->SetDirectionColoring(direction);
  this->GetLODTubeMapper()->SetDirectionColoring(direction);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkSplineTubeRepresentation::SetEndpointMarkers(bool markers)
{
  this->GetTubeMapper()->SetEndpointMarkers(markers);
  this->GetLODTubeMapper()->SetEndpointMarkers(markers);
  this->Modified();
}

void vtkSplineTubeRepresentation::SetEndpointMarkerScale(double scale)
{
  this->GetTubeMapper()->SetEndpointMarkerScale(scale);
  this->GetLODTubeMapper()->SetEndpointMarkerScale(scale);
  this->Modified();
}

void vtkSplineTubeRepresentation::SetEndpointMarkerColor(double r, double g, double b)
{
  this->GetTubeMapper()->SetEndpointMarkerColor(r, g, b);
  this->GetLODTubeMapper()->SetEndpointMarkerColor(r, g, b);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkSplineTubeRepresentation::SetSlabOrigin(double x, double y, double z)
{
  this->GetTubeMapper()->SetSlabOrigin(x, y, z);
  this->GetLODTubeMapper()->SetSlabOrigin(x, y, z);
  this->Modified();
}

void vtkSplineTubeRepresentation::SetSlabNormal(double x, double y, double z)
{
  this->GetTubeMapper()->SetSlabNormal(x, y, z);
  this->GetLODTubeMapper()->SetSlabNormal(x, y, z);
  this->Modified();
}

void vtkSplineTubeRepresentation::SetSlabThickness(double thickness)
{
  this->GetTubeMapper()->SetSlabThickness(thickness);
  this->GetLODTubeMapper()->SetSlabThickness(thickness);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkSplineTubeRepresentation::SetVisibilityArray(const char* name)
{
  this->GetTubeMapper()->SetVisibilityArray(ArrayOrNull(name));
  this->GetLODTubeMapper()->SetVisibilityArray(ArrayOrNull(name));
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
  if (request_type == vtkPVView::REQUEST_UPDATE())
  {
    this->UpdateAutomaticRadiusBounds();
  }
  if (request_type == vtkPVView::REQUEST_RENDER() && this->Mapper->GetNumberOfInputConnections(0))
  {
    this->LODMapper->SetInputConnection(0, this->Mapper->GetInputConnection(0, 0));
  }
  return result;
}

//------------------------------------------------------------------------------
void vtkSplineTubeRepresentation::UpdateAutomaticRadiusBounds()
{
  // The bounds of the data on every rank (REQUEST_UPDATE reaches the
  // representation on all of them): as minima of (min, -max).
  double local[6];
  double global[6];
  const double* b = this->VisibleDataBounds;
  const bool valid = b[0] <= b[1] && b[2] <= b[3] && b[4] <= b[5];
  for (int i = 0; i < 3; ++i)
  {
    local[i] = valid ? b[2 * i] : DBL_MAX;
    local[3 + i] = valid ? -b[2 * i + 1] : DBL_MAX;
  }
  std::copy(local, local + 6, global);
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  if (controller && controller->GetNumberOfProcesses() > 1)
  {
    controller->AllReduce(local, global, 6, vtkCommunicator::MIN_OP);
  }
  double bounds[6] = { 1.0, -1.0, 1.0, -1.0, 1.0, -1.0 };
  if (global[0] <= -global[3])
  {
    for (int i = 0; i < 3; ++i)
    {
      bounds[2 * i] = global[i];
      bounds[2 * i + 1] = -global[3 + i];
    }
  }
  this->GetTubeMapper()->SetAutomaticRadiusBounds(bounds);
  this->GetLODTubeMapper()->SetAutomaticRadiusBounds(bounds);
}

//------------------------------------------------------------------------------
void vtkSplineTubeRepresentation::SetMinimumPixelWidth(double width)
{
  this->GetTubeMapper()->SetMinimumPixelWidth(width);
  this->GetLODTubeMapper()->SetMinimumPixelWidth(width);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkSplineTubeRepresentation::SetArrayIdNames(const char*, const char* cellArray)
{
  const char* name = cellArray ? cellArray : "vtkOriginalCellIds";
  this->GetTubeMapper()->SetCellIdArray(name);
  this->GetLODTubeMapper()->SetCellIdArray(name);
}

//------------------------------------------------------------------------------
void vtkSplineTubeRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
