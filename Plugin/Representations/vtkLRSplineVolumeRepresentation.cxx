// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLRSplineVolumeRepresentation.h"

#include "vtkLRSplineField.h"

#include "vtkAlgorithmOutput.h"
#include "vtkColorTransferFunction.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkContourValues.h"
#include "vtkDataArray.h"
#include "vtkDataObject.h"
#include "vtkDataSet.h"
#include "vtkExtractBlockUsingDataAssembly.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkLRSplineVolumeMapper.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"
#include "vtkOutlineSource.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPVLODVolume.h"
#include "vtkPVRenderView.h"
#include "vtkPartitionedDataSetCollection.h"
#include "vtkPolyData.h"
#include "vtkPointData.h"
#include "vtkPolyDataMapper.h"
#include "vtkRenderer.h"
#include "vtkScalarsToColors.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnsignedCharArray.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <string>

namespace
{
//------------------------------------------------------------------------------
int LocalRank()
{
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  return controller ? controller->GetLocalProcessId() : 0;
}

//------------------------------------------------------------------------------
// True when `data` holds at least one data set with cells (a patch to render
// or a surface to trim with).
bool HasCells(vtkDataObject* data)
{
  if (auto* ds = vtkDataSet::SafeDownCast(data))
  {
    return ds->GetNumberOfCells() > 0;
  }
  if (auto* cd = vtkCompositeDataSet::SafeDownCast(data))
  {
    vtkSmartPointer<vtkCompositeDataIterator> it;
    it.TakeReference(cd->NewIterator());
    it->SkipEmptyNodesOn();
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
    {
      auto* leaf = vtkDataSet::SafeDownCast(it->GetCurrentDataObject());
      if (leaf && leaf->GetNumberOfCells() > 0)
      {
        return true;
      }
    }
  }
  return false;
}

//------------------------------------------------------------------------------
vtkDataObject* ProducedData(vtkAlgorithmOutput* port)
{
  return port && port->GetProducer() ? port->GetProducer()->GetOutputDataObject(port->GetIndex())
                                     : nullptr;
}
}

vtkStandardNewMacro(vtkLRSplineVolumeRepresentation);

//------------------------------------------------------------------------------
vtkLRSplineVolumeRepresentation::vtkLRSplineVolumeRepresentation()
{
  this->SetNumberOfInputPorts(2);
  this->BlockExtractor->SetAssemblyName("Hierarchy");
  this->BlockExtractor->AddSelector("/");
  // The volume mapper joins the actor in REQUEST_RENDER, once it has data
  // (the view asks the actor for bounds before that).
  this->Actor->SetLODMapper(this->LODMapper);
  this->LODMapper->SetScalarVisibility(1);
  this->LODMapper->SetColorModeToDirectScalars();
}

//------------------------------------------------------------------------------
vtkLRSplineVolumeRepresentation::~vtkLRSplineVolumeRepresentation() = default;

//------------------------------------------------------------------------------
vtkLRSplineVolumeMapper* vtkLRSplineVolumeRepresentation::GetVolumeMapper()
{
  return this->VolumeMapper;
}

//------------------------------------------------------------------------------
int vtkLRSplineVolumeRepresentation::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == 0)
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkUnstructuredGridBase");
    info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkCompositeDataSet");
  }
  else
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  }
  info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  return 1;
}

//------------------------------------------------------------------------------
int vtkLRSplineVolumeRepresentation::RequestUpdateExtent(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  this->Superclass::RequestUpdateExtent(request, inputVector, outputVector);
  // The whole data set, on every rank alike (a request that differs between
  // ranks could make only some of them re-execute a parallel filter upstream).
  for (int port = 0; port < this->GetNumberOfInputPorts(); ++port)
  {
    for (int i = 0; i < inputVector[port]->GetNumberOfInformationObjects(); ++i)
    {
      vtkInformation* info = inputVector[port]->GetInformationObject(i);
      info->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(), 0);
      info->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(), 1);
    }
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkLRSplineVolumeRepresentation::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkMath::UninitializeBounds(this->DataBounds);
  this->DataSize = 0;
  this->Spline = nullptr;
  this->TrimmingSurface = nullptr;
  this->HasTrimmingSurface = false;

  if (inputVector[0]->GetNumberOfInformationObjects() == 1)
  {
    vtkDataObject* input = vtkDataObject::GetData(inputVector[0], 0);
    vtkDataObject* selected = input;
    if (vtkMultiBlockDataSet::SafeDownCast(input) ||
      vtkPartitionedDataSetCollection::SafeDownCast(input))
    {
      // The blocks (patches) chosen in the multiblock inspector.
      this->BlockExtractor->SetInputConnection(this->GetInternalOutputPort(0));
      this->BlockExtractor->Update();
      selected = this->BlockExtractor->GetOutputDataObject(0);
    }
    if (selected)
    {
      this->Spline.TakeReference(selected->NewInstance());
      this->Spline->ShallowCopy(selected);
      this->DataSize = this->Spline->GetActualMemorySize();
      // The patches' box: in field mode the Bezier control points of every
      // element span exactly the element's box.
      if (auto* cd = vtkCompositeDataSet::SafeDownCast(this->Spline))
      {
        cd->GetBounds(this->DataBounds);
      }
      else if (auto* ds = vtkDataSet::SafeDownCast(this->Spline))
      {
        ds->GetBounds(this->DataBounds);
      }
    }
  }
  // The Trimming Surface chosen, else the boundary of the data an LR-Spline
  // Fit fitted (vtkLRSplineField::TRIMMING_SURFACE on its spline).
  vtkPolyData* surface = inputVector[1]->GetNumberOfInformationObjects() == 1
    ? vtkPolyData::GetData(inputVector[1], 0)
    : nullptr;
  if (!surface && this->TrimByDataBoundary && inputVector[0]->GetNumberOfInformationObjects() == 1)
  {
    surface = vtkLRSplineField::GetTrimmingSurface(vtkDataObject::GetData(inputVector[0], 0));
  }
  if (surface)
  {
    this->TrimmingSurface = vtkSmartPointer<vtkPolyData>::New();
    this->TrimmingSurface->ShallowCopy(surface);
    this->HasTrimmingSurface = this->TrimmingSurface->GetNumberOfPolys() > 0 ||
      this->TrimmingSurface->GetNumberOfStrips() > 0;
  }
  if (vtkMath::AreBoundsInitialized(this->DataBounds))
  {
    this->OutlineSource->SetBounds(this->DataBounds);
  }
  else
  {
    this->OutlineSource->SetBounds(0, 0, 0, 0, 0, 0);
  }
  this->OutlineSource->Update();
  // The interactive (LOD) picture: the box's edges in gray (vtkPVLODVolume
  // draws them at half opacity with a default, white, property).
  this->Outline = vtkSmartPointer<vtkPolyData>::New();
  this->Outline->ShallowCopy(this->OutlineSource->GetOutput());
  vtkNew<vtkUnsignedCharArray> gray;
  gray->SetName("OutlineColor");
  gray->SetNumberOfComponents(3);
  gray->SetNumberOfTuples(this->Outline->GetNumberOfPoints());
  gray->Fill(128);
  this->Outline->GetPointData()->SetScalars(gray);
  return this->Superclass::RequestData(request, inputVector, outputVector);
}

//------------------------------------------------------------------------------
int vtkLRSplineVolumeRepresentation::ProcessViewRequest(
  vtkInformationRequestKey* request_type, vtkInformation* inInfo, vtkInformation* outInfo)
{
  if (!this->Superclass::ProcessViewRequest(request_type, inInfo, outInfo))
  {
    return 0;
  }
  // Only one rank renders the spline: the mapper cannot composite pieces of
  // it in visibility order, and the same translucent picture drawn by every
  // rank would be blended N times.
  const bool renders = LocalRank() == GetRenderingRank();
  if (request_type == vtkPVView::REQUEST_UPDATE())
  {
    vtkSmartPointer<vtkDataObject> spline = this->Spline;
    if (!renders || !spline)
    {
      spline = vtkSmartPointer<vtkMultiBlockDataSet>::New();
    }
    vtkSmartPointer<vtkPolyData> surface = this->TrimmingSurface;
    if (!renders || !surface || !this->HasTrimmingSurface)
    {
      surface = vtkSmartPointer<vtkPolyData>::New();
    }
    vtkPVRenderView::SetPiece(inInfo, this, spline, renders ? this->DataSize : 0, 0);
    vtkPVRenderView::SetPiece(inInfo, this, surface, 0, 1);
    // Translucent pictures of several ranks are blended in visibility order;
    // the spline's control points take part in building that order.
    outInfo->Set(vtkPVRenderView::NEED_ORDERED_COMPOSITING(), 1);
    vtkPVRenderView::SetOrderedCompositingConfiguration(
      inInfo, this, vtkPVRenderView::USE_DATA_FOR_LOAD_BALANCING);
    // The ranks render (the client never receives the spline).
    vtkPVRenderView::SetRequiresDistributedRendering(inInfo, this, true);
    double bounds[6];
    vtkMath::UninitializeBounds(bounds);
    if (renders)
    {
      std::copy(this->DataBounds, this->DataBounds + 6, bounds);
    }
    vtkNew<vtkMatrix4x4> matrix;
    this->Actor->GetMatrix(matrix);
    vtkPVRenderView::SetGeometryBounds(inInfo, this, bounds, matrix);
    // Until REQUEST_RENDER connects the delivered data, the mapper's input is
    // stale or a placeholder: keep it out of the view's bounds and renders.
    this->Actor->SetMapper(nullptr);
  }
  else if (request_type == vtkPVView::REQUEST_UPDATE_LOD())
  {
    // Interactive renders: the outline of the patches' box.
    vtkSmartPointer<vtkDataObject> outline = this->Outline;
    if (!renders || !outline || !vtkMath::AreBoundsInitialized(this->DataBounds))
    {
      outline = vtkSmartPointer<vtkPolyData>::New();
    }
    vtkPVRenderView::SetPieceLOD(inInfo, this, outline);
  }
  else if (request_type == vtkPVView::REQUEST_RENDER())
  {
    vtkAlgorithmOutput* producer = vtkPVRenderView::GetPieceProducer(inInfo, this, 0);
    vtkAlgorithmOutput* trimProducer = vtkPVRenderView::GetPieceProducer(inInfo, this, 1);
    this->UpdateMapperParameters(ProducedData(producer));
    if (producer && HasCells(ProducedData(producer)))
    {
      this->VolumeMapper->SetInputConnection(producer);
      this->VolumeMapper->SetTrimmingSurfaceConnection(
        trimProducer && HasCells(ProducedData(trimProducer)) ? trimProducer : nullptr);
      this->Actor->SetMapper(this->VolumeMapper);
    }
    else
    {
      // Nothing of the spline on this process (another rank renders it).
      this->Actor->SetMapper(nullptr);
    }
    this->LODMapper->SetInputConnection(vtkPVRenderView::GetPieceProducerLOD(inInfo, this));
    this->Actor->SetEnableLOD(inInfo->Has(vtkPVRenderView::USE_LOD()) ? 1 : 0);
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkLRSplineVolumeRepresentation::UpdateMapperParameters(vtkDataObject* data)
{
  // The color array selects the field (a point array of Bezier coefficients).
  const char* name = nullptr;
  int association = vtkDataObject::FIELD_ASSOCIATION_POINTS;
  vtkInformation* info = this->GetInputArrayInformation(0);
  if (info && info->Has(vtkDataObject::FIELD_ASSOCIATION()) &&
    info->Has(vtkDataObject::FIELD_NAME()))
  {
    name = info->Get(vtkDataObject::FIELD_NAME());
    association = info->Get(vtkDataObject::FIELD_ASSOCIATION());
  }
  std::string warning;
  if (name && name[0] && association != vtkDataObject::FIELD_ASSOCIATION_POINTS)
  {
    warning = std::string("LR-Spline Volume renders point arrays (the Bezier coefficients of the "
                          "spline); \"") +
      name + "\" is not one: the spline's default field is rendered instead.";
    name = nullptr;
  }
  this->VolumeMapper->SetFieldArray(name && name[0] ? name : nullptr);
  if (!name || !name[0])
  {
    // No color array (ParaView picks one for its own "Volume" only): the
    // spline's first field with ParaView's default color map and opacity
    // ramp over its range, as ParaView's "Volume" shows a new data set.
    this->UseDefaultTransferFunction(data);
  }

  // Magnitude or one component, from the lookup table (as ParaView's volume
  // representations do).
  this->Property->SetIndependentComponents(true);
  vtkColorTransferFunction* ctf = this->Property->GetRGBTransferFunction(0);
  if (ctf && ctf->GetVectorMode() == vtkScalarsToColors::COMPONENT)
  {
    this->VolumeMapper->SetVectorMode(vtkLRSplineVolumeMapper::COMPONENT);
    this->VolumeMapper->SetVectorComponent(ctf->GetVectorComponent());
  }
  else
  {
    this->VolumeMapper->SetVectorMode(vtkLRSplineVolumeMapper::MAGNITUDE);
  }

  if (this->UseSeparateOpacityArray)
  {
    warning = "LR-Spline Volume does not support a separate opacity array: the opacity follows "
              "the colored field.";
  }
  else if (this->MultiComponentsMapping || !this->MapScalars)
  {
    warning = "LR-Spline Volume maps its field through the color map only (Map Scalars on, "
              "Multi Components Mapping off).";
  }
  if (!warning.empty() && warning != this->LastWarning)
  {
    vtkWarningMacro(<< warning);
  }
  this->LastWarning = warning;
}

//------------------------------------------------------------------------------
void vtkLRSplineVolumeRepresentation::UseDefaultTransferFunction(vtkDataObject* data)
{
  // The mapper's default field: the active vectors, else the active scalars,
  // else the first point array; the range of its magnitude over all patches
  // (Bezier coefficients bound the spline's values).
  double range[2] = { VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
  auto add = [&range](vtkDataSet* ds)
  {
    vtkPointData* pd = ds ? ds->GetPointData() : nullptr;
    vtkDataArray* field = nullptr;
    if (pd)
    {
      field = pd->GetVectors() ? pd->GetVectors()
                               : (pd->GetScalars() ? pd->GetScalars() : pd->GetArray(0));
    }
    if (field && field->GetNumberOfTuples() > 0)
    {
      double r[2];
      field->GetRange(r, field->GetNumberOfComponents() > 1 ? -1 : 0);
      range[0] = std::min(range[0], r[0]);
      range[1] = std::max(range[1], r[1]);
    }
  };
  if (auto* cd = vtkCompositeDataSet::SafeDownCast(data))
  {
    vtkSmartPointer<vtkCompositeDataIterator> it;
    it.TakeReference(cd->NewIterator());
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
    {
      add(vtkDataSet::SafeDownCast(it->GetCurrentDataObject()));
    }
  }
  else
  {
    add(vtkDataSet::SafeDownCast(data));
  }
  if (!(range[1] >= range[0]))
  {
    range[0] = 0.0;
    range[1] = 1.0;
  }
  if (range[1] == range[0])
  {
    range[1] = range[0] + 1.0;
  }
  if (this->DefaultColor->GetSize() != 3 || this->DefaultRange[0] != range[0] ||
    this->DefaultRange[1] != range[1])
  {
    // ParaView's defaults for a new color array: the "Cool to Warm" map
    // (diverging) and a linear opacity ramp from 0 to 1, over the data range.
    this->DefaultColor->RemoveAllPoints();
    this->DefaultColor->SetColorSpaceToDiverging();
    this->DefaultColor->SetVectorModeToMagnitude(); // vtkScalarsToColors' default is a component
    this->DefaultColor->AddRGBPoint(range[0], 0.231373, 0.298039, 0.752941);
    this->DefaultColor->AddRGBPoint(0.5 * (range[0] + range[1]), 0.865003, 0.865003, 0.865003);
    this->DefaultColor->AddRGBPoint(range[1], 0.705882, 0.0156863, 0.14902);
    this->DefaultOpacity->RemoveAllPoints();
    this->DefaultOpacity->AddPoint(range[0], 0.0);
    this->DefaultOpacity->AddPoint(range[1], 1.0);
    this->DefaultRange[0] = range[0];
    this->DefaultRange[1] = range[1];
  }
  if (this->Property->GetRGBTransferFunction(0) != this->DefaultColor.GetPointer())
  {
    this->Property->SetColor(this->DefaultColor);
  }
  if (this->Property->GetScalarOpacity(0) != this->DefaultOpacity.GetPointer())
  {
    this->Property->SetScalarOpacity(this->DefaultOpacity);
  }
}

//------------------------------------------------------------------------------
bool vtkLRSplineVolumeRepresentation::AddToView(vtkView* view)
{
  vtkPVRenderView* rview = vtkPVRenderView::SafeDownCast(view);
  if (rview)
  {
    // Not registered for hardware selection: the ray caster draws colors, not ids.
    rview->GetRenderer()->AddActor(this->Actor);
    return this->Superclass::AddToView(view);
  }
  return false;
}

//------------------------------------------------------------------------------
bool vtkLRSplineVolumeRepresentation::RemoveFromView(vtkView* view)
{
  vtkPVRenderView* rview = vtkPVRenderView::SafeDownCast(view);
  if (rview)
  {
    rview->GetRenderer()->RemoveActor(this->Actor);
    return this->Superclass::RemoveFromView(view);
  }
  return false;
}

//------------------------------------------------------------------------------
// The volume property.
void vtkLRSplineVolumeRepresentation::SetShade(bool shade)
{
  this->Property->SetShade(shade ? 1 : 0);
}

void vtkLRSplineVolumeRepresentation::SetAmbient(double value)
{
  this->Property->SetAmbient(value);
}

void vtkLRSplineVolumeRepresentation::SetDiffuse(double value)
{
  this->Property->SetDiffuse(value);
}

void vtkLRSplineVolumeRepresentation::SetSpecular(double value)
{
  this->Property->SetSpecular(value);
}

void vtkLRSplineVolumeRepresentation::SetSpecularPower(double value)
{
  this->Property->SetSpecularPower(value);
}

void vtkLRSplineVolumeRepresentation::SetIsosurfaceValue(int i, double value)
{
  this->Property->GetIsoSurfaceValues()->SetValue(i, value);
}

void vtkLRSplineVolumeRepresentation::SetNumberOfIsosurfaces(int number)
{
  this->Property->GetIsoSurfaceValues()->SetNumberOfContours(number);
}

//------------------------------------------------------------------------------
// The mapper.
#define SV_FORWARD(method, type)                                                                   \
  void vtkLRSplineVolumeRepresentation::method(type value)                                         \
  {                                                                                                \
    this->VolumeMapper->method(value);                                                             \
  }

SV_FORWARD(SetBlendMode, int)
SV_FORWARD(SetElementLocator, int)
SV_FORWARD(SetForestResolution, int)
SV_FORWARD(SetAdaptiveSteps, bool)
SV_FORWARD(SetStepScale, double)
SV_FORWARD(SetSampleDistance, double)
SV_FORWARD(SetSupersampling, int)
SV_FORWARD(SetUseJittering, bool)
SV_FORWARD(SetShadingModel, int)
SV_FORWARD(SetIsosurfaceBisections, int)
SV_FORWARD(SetMaximumNumberOfSteps, int)
#undef SV_FORWARD

//------------------------------------------------------------------------------
void vtkLRSplineVolumeRepresentation::SetTrimByDataBoundary(bool trim)
{
  if (this->TrimByDataBoundary != trim)
  {
    this->TrimByDataBoundary = trim;
    this->MarkModified(); // RequestData chooses the surface it delivers
  }
}

//------------------------------------------------------------------------------
// The block selection.
void vtkLRSplineVolumeRepresentation::SetActiveAssembly(const char* name)
{
  this->BlockExtractor->SetAssemblyName(name);
  this->MarkModified();
}

void vtkLRSplineVolumeRepresentation::AddBlockSelector(const char* selector)
{
  this->BlockExtractor->AddSelector(selector);
  this->MarkModified();
}

void vtkLRSplineVolumeRepresentation::RemoveAllBlockSelectors()
{
  this->BlockExtractor->ClearSelectors();
  this->MarkModified();
}

//------------------------------------------------------------------------------
void vtkLRSplineVolumeRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "RenderingRank: " << GetRenderingRank() << "\n";
  os << indent << "HasTrimmingSurface: " << this->HasTrimmingSurface << "\n";
  os << indent << "TrimByDataBoundary: " << this->TrimByDataBoundary << "\n";
  os << indent << "VolumeMapper:\n";
  this->VolumeMapper->PrintSelf(os, indent.GetNextIndent());
}
