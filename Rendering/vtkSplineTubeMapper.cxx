// SPDX-License-Identifier: BSD-3-Clause
#include "vtkSplineTubeMapper.h"

#include "vtkSplineTubeColor.h"
#include "vtkSplineTubeNodes.h"
#include "vtkSplineTubeCore.h"
#include "vtkSplineTubeVisibility.h"
#include "vtkSplineVizGPUBuffer.h"

#include "vtkActor.h"
#include "vtkBoundingBox.h"
#include "vtkCamera.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataPipeline.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkHardwareSelector.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkOpenGLCamera.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLSphereMapper.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexBufferObject.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkLookupTable.h"
#include "vtkSMPTools.h"
#include "vtkScalarsToColors.h"
#include "vtkShaderProgram.h"
#include "vtkSmartPointer.h"
#include "vtkTypeUInt32Array.h"
#include "vtkUnsignedCharArray.h"

#include <vtk_glew.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <functional>
#include <locale>
#include <sstream>
#include <vector>

struct vtkSplineTubeMapper::PyramidHolder
{
  vtkSplineTubeVisibility::DepthPyramid Pyramid;
};

//------------------------------------------------------------------------------
vtkSplineTubeMapper::vtkSplineTubeMapper()
  : NodesBuffer(new vtkSplineVizGPUBuffer)
  , NodeInfoBuffer(new vtkSplineVizGPUBuffer)
  , TubesBuffer(new vtkSplineVizGPUBuffer)
  , ColorsBuffer(new vtkSplineVizGPUBuffer)
  , Visibility(new vtkSplineTubeVisibility)
  , Pyramid(new PyramidHolder)
{
  // The tube data is built per data change; the VBO shift/scale machinery of
  // the superclass does not apply (we shift positions ourselves).
  this->SetVBOShiftScaleMethod(vtkOpenGLVertexBufferObject::DISABLE_SHIFT_SCALE);
  // Superclass code reads the points of CurrentInput (see RenderPiece).
  vtkNew<vtkPoints> noPoints;
  this->EmptyInput->SetPoints(noPoints);
}

//------------------------------------------------------------------------------
vtkSplineTubeMapper::~vtkSplineTubeMapper()
{
  this->SetRadiusArray(nullptr);
  this->SetVisibilityArray(nullptr);
  this->SetCellIdArray(nullptr);
}

//------------------------------------------------------------------------------
vtkSplineTubeCore* vtkSplineTubeMapper::GetTubeCore()
{
  return this->Core;
}

//------------------------------------------------------------------------------
int vtkSplineTubeMapper::FillInputPortInformation(int vtkNotUsed(port), vtkInformation* info)
{
  info->Remove(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE());
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkCompositeDataSet");
  return 1;
}

//------------------------------------------------------------------------------
vtkExecutive* vtkSplineTubeMapper::CreateDefaultExecutive()
{
  return vtkCompositeDataPipeline::New();
}

//------------------------------------------------------------------------------
std::string vtkSplineTubeMapper::BuildSignature()
{
  std::ostringstream s;
  s.precision(17);
  s << this->Radius << '|' << this->AutomaticRadiusBounds[0] << ','
    << this->AutomaticRadiusBounds[1] << ',' << this->AutomaticRadiusBounds[2] << ','
    << this->AutomaticRadiusBounds[3] << ',' << this->AutomaticRadiusBounds[4] << ','
    << this->AutomaticRadiusBounds[5] << '|' << (this->RadiusArray ? this->RadiusArray : "") << '|'
    << this->RadiusScale << '|' << (this->CellIdArray ? this->CellIdArray : "") << '|'
    << this->DirectionColoring << '|' << this->ScalarVisibility << '|' << this->ScalarMode << '|'
    << this->ArrayAccessMode << '|' << this->ArrayId << '|' << this->ArrayName << '|'
    << this->ArrayComponent << '|' << this->ColorMode << '|' << this->UseLookupTableScalarRange
    << '|' << this->ScalarRange[0] << '|' << this->ScalarRange[1] << '|' << this->FieldDataTupleId
    << '|' << this->LookupTable << '|' << (this->LookupTable ? this->LookupTable->GetMTime() : 0);
  this->AppendBuildSignature(s);
  return s.str();
}

//------------------------------------------------------------------------------
double vtkSplineTubeMapper::ComputeAutomaticRadius(const double bounds[6])
{
  double diagonal2 = 0.0;
  for (int i = 0; i < 3; ++i)
  {
    const double extent = bounds[2 * i + 1] - bounds[2 * i];
    diagonal2 += extent > 0.0 ? extent * extent : 0.0;
  }
  const double diagonal = std::sqrt(diagonal2);
  return diagonal > 0.0 && std::isfinite(diagonal) ? AutomaticRadiusFactor * diagonal : 0.01;
}

namespace
{
// Call `visit(polydata, block id)` for every polydata of `input`: the input
// itself (block 0) or the non-empty polydata leaves of a composite data set
// (their flat indices), the blocks the tubes are built from.
void ForEachPolyData(
  vtkDataObject* input, const std::function<void(vtkPolyData*, unsigned int)>& visit)
{
  if (auto* cd = vtkCompositeDataSet::SafeDownCast(input))
  {
    auto it = vtk::TakeSmartPointer(cd->NewIterator());
    it->SkipEmptyNodesOn();
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
    {
      if (auto* pd = vtkPolyData::SafeDownCast(it->GetCurrentDataObject()))
      {
        visit(pd, it->GetCurrentFlatIndex());
      }
    }
  }
  else if (auto* pd = vtkPolyData::SafeDownCast(input))
  {
    visit(pd, 0);
  }
}

// The bounds of the points of every polydata in `input` (invalid if none).
void ComputeInputBounds(vtkDataObject* input, double bounds[6])
{
  vtkBoundingBox box;
  ForEachPolyData(input,
    [&box](vtkPolyData* pd, unsigned int)
    {
      if (pd->GetNumberOfPoints() > 0)
      {
        double b[6];
        pd->GetBounds(b);
        box.AddBounds(b);
      }
    });
  if (box.IsValid())
  {
    box.GetBounds(bounds);
  }
  else
  {
    vtkMath::UninitializeBounds(bounds);
  }
}
}

//------------------------------------------------------------------------------
bool vtkSplineTubeMapper::UpdateTubeCore()
{
  vtkDataObject* input = this->GetInputDataObject(0, 0);
  const std::string signature = this->BuildSignature();
  if (input && signature == this->LastSignature && this->CoreBuildTime.GetMTime() > 0)
  {
    if (input == this->LastInput && input->GetMTime() == this->LastInputMTime)
    {
      return false;
    }
    // A new or modified input whose tube data is the same (only other
    // arrays changed, e.g. a selection's): keep the tubes.
    std::string key = this->InputContentKey(input);
    if (key == this->LastContentKey)
    {
      this->LastInput = input;
      this->LastInputMTime = input->GetMTime();
      return false;
    }
  }

  this->Core->Initialize();
  this->EffectiveRadius = this->Radius;
  if (this->Radius <= 0.0)
  {
    double bounds[6];
    std::copy(this->AutomaticRadiusBounds, this->AutomaticRadiusBounds + 6, bounds);
    if (!(bounds[0] <= bounds[1]))
    {
      ComputeInputBounds(input, bounds);
    }
    this->EffectiveRadius = ComputeAutomaticRadius(bounds);
  }
  this->Core->SetRadius(this->EffectiveRadius);
  this->Core->SetRadiusArray(
    this->RadiusArray && this->RadiusArray[0] ? this->RadiusArray : nullptr);
  this->Core->SetRadiusScale(this->RadiusScale);
  this->Core->SetCellIdArray(this->CellIdArray);
  this->ConfigureTubeCore(this->Core);

  vtkIdType inputCells = 0;
  auto addLeaf = [this, &inputCells](vtkPolyData* pd, unsigned int blockId)
  {
    if (!pd)
    {
      return;
    }
    inputCells += pd->GetNumberOfCells();
    vtkSmartPointer<vtkUnsignedCharArray> colors;
    bool perCell = false;
    int cellFlag = 0;
    vtkAbstractArray* scalars = vtkAbstractMapper::GetAbstractScalars(
      pd, this->ScalarMode, this->ArrayAccessMode, this->ArrayId, this->ArrayName, cellFlag);
    if (this->ScalarVisibility && scalars && !this->DirectionColoring)
    {
      vtkDataArray* dataArray = vtkArrayDownCast<vtkDataArray>(scalars);
      if (dataArray && dataArray->GetLookupTable())
      {
        this->SetLookupTable(dataArray->GetLookupTable());
      }
      else
      {
        if (!this->LookupTable)
        {
          this->CreateDefaultLookupTable();
        }
        this->LookupTable->Build();
      }
      if (!this->UseLookupTableScalarRange)
      {
        this->LookupTable->SetRange(this->ScalarRange);
      }
      colors = vtk::TakeSmartPointer(
        this->LookupTable->MapScalars(scalars, this->ColorMode, this->ArrayComponent));
      if (cellFlag == 2 && colors && colors->GetNumberOfTuples() > 0)
      {
        // Field data: one color for the whole block.
        const vtkIdType tuple = std::min<vtkIdType>(
          std::max<vtkIdType>(this->FieldDataTupleId, 0), colors->GetNumberOfTuples() - 1);
        vtkNew<vtkUnsignedCharArray> uniform;
        uniform->SetNumberOfComponents(4);
        uniform->SetNumberOfTuples(pd->GetNumberOfPoints());
        const unsigned char* c = colors->GetPointer(4 * tuple);
        for (vtkIdType i = 0; i < pd->GetNumberOfPoints(); ++i)
        {
          uniform->SetTypedTuple(i, c);
        }
        colors = uniform;
      }
      perCell = (cellFlag == 1);
    }
    if (!this->Core->AddPolyData(pd, colors, blockId, perCell))
    {
      vtkErrorMacro(<< "Block " << blockId << " is not drawn (see the error above).");
    }
  };

  this->InputIsComposite = vtkCompositeDataSet::SafeDownCast(input) != nullptr;
  if (auto cd = vtkCompositeDataSet::SafeDownCast(input))
  {
    auto it = vtk::TakeSmartPointer(cd->NewIterator());
    it->SkipEmptyNodesOn();
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
    {
      vtkDataObject* leaf = it->GetCurrentDataObject();
      if (!vtkPolyData::SafeDownCast(leaf))
      {
        vtkWarningMacro(<< "Block " << it->GetCurrentFlatIndex() << " is a " << leaf->GetClassName()
                        << ", not a vtkPolyData: skipped (extract its lines or surface first).");
        continue;
      }
      addLeaf(vtkPolyData::SafeDownCast(leaf), it->GetCurrentFlatIndex());
    }
  }
  else
  {
    addLeaf(vtkPolyData::SafeDownCast(input), 0);
  }
  this->Core->Build();
  // The largest cell id the shaders write (picking needs it).
  this->MaximumCellId = this->Core->GetMaximumCellId();
  this->HaveColors = this->Core->HasColors();
  if (this->Core->GetNumberOfTubes() == 0 && inputCells > 0 &&
    this->Core->GetNumberOfSkippedLines() == 0)
  {
    vtkWarningMacro(<< "The input has " << inputCells
                    << " cells but no polylines (line or polyline cells): no tubes to draw.");
  }

  this->Core->GetCenter(this->Shift); // what the chunk spheres are relative to
  this->LastInput = input;
  this->LastInputMTime = input ? input->GetMTime() : 0;
  this->LastSignature = signature;
  this->LastContentKey = this->InputContentKey(input);
  this->CoreBuildTime.Modified();
  return true;
}

//------------------------------------------------------------------------------
std::string vtkSplineTubeMapper::InputContentKey(vtkDataObject* input)
{
  std::ostringstream key;
  auto identity = [&key](vtkObject* object)
  { key << object << ':' << (object ? object->GetMTime() : 0) << ','; };
  ForEachPolyData(input,
    [&](vtkPolyData* pd, unsigned int blockId)
    {
      key << '[' << blockId << ':' << pd->GetNumberOfVerts() << ':' << pd->GetNumberOfCells()
          << ',';
      identity(pd->GetPoints() ? pd->GetPoints()->GetData() : nullptr);
      vtkCellArray* lines = pd->GetLines();
      identity(lines);
      if (lines)
      {
        identity(lines->GetOffsetsArray());
        identity(lines->GetConnectivityArray());
      }
      int cellFlag = 0;
      identity(vtkAbstractMapper::GetAbstractScalars(
        pd, this->ScalarMode, this->ArrayAccessMode, this->ArrayId, this->ArrayName, cellFlag));
      identity(this->RadiusArray ? pd->GetPointData()->GetArray(this->RadiusArray) : nullptr);
      // Original cell ids are often made anew by each execution (ParaView's
      // geometry filter): compared by value.
      vtkDataArray* ids =
        this->CellIdArray ? pd->GetCellData()->GetArray(this->CellIdArray) : nullptr;
      if (ids)
      {
        const vtkIdType n = ids->GetNumberOfValues();
        std::uint64_t hash = 1469598103934665603ull;
        for (vtkIdType i = 0; i < n; ++i)
        {
          hash = (hash ^ static_cast<std::uint64_t>(ids->GetVariantValue(i).ToLongLong())) *
            1099511628211ull;
        }
        key << "ids:" << n << ':' << hash;
      }
      key << ']';
    });
  return key.str();
}

//------------------------------------------------------------------------------
void vtkSplineTubeMapper::UpdateSlabPlanes()
{
  const double length = vtkMath::Norm(this->SlabNormal);
  const bool wanted = this->SlabThickness > 0.0 && length > 0.0 && std::isfinite(length);
  if (this->SlabThickness > 0.0 && !wanted)
  {
    vtkErrorMacro(<< "The slab's normal is zero or not finite: no slab crop.");
  }
  if (!wanted)
  {
    if (this->SlabPlanesAdded)
    {
      this->RemoveClippingPlane(this->SlabPlanes[0]);
      this->RemoveClippingPlane(this->SlabPlanes[1]);
      this->SlabPlanesAdded = false;
    }
    return;
  }
  // Two planes facing into the slab (clipping keeps their positive side).
  for (int side = 0; side < 2; ++side)
  {
    const double sign = side == 0 ? 1.0 : -1.0;
    double normal[3];
    double origin[3];
    for (int c = 0; c < 3; ++c)
    {
      normal[c] = sign * this->SlabNormal[c] / length;
      origin[c] = this->SlabOrigin[c] - 0.5 * this->SlabThickness * normal[c];
    }
    vtkPlane* plane = this->SlabPlanes[side];
    const double* oldNormal = plane->GetNormal();
    const double* oldOrigin = plane->GetOrigin();
    if (oldNormal[0] != normal[0] || oldNormal[1] != normal[1] || oldNormal[2] != normal[2] ||
      oldOrigin[0] != origin[0] || oldOrigin[1] != origin[1] || oldOrigin[2] != origin[2])
    {
      plane->SetNormal(normal);
      plane->SetOrigin(origin);
    }
  }
  if (!this->SlabPlanesAdded)
  {
    this->AddClippingPlane(this->SlabPlanes[0]);
    this->AddClippingPlane(this->SlabPlanes[1]);
    this->SlabPlanesAdded = true;
  }
}

//------------------------------------------------------------------------------
void vtkSplineTubeMapper::UpdateLineMask()
{
  const bool wanted = this->VisibilityArray && this->VisibilityArray[0];
  vtkDataObject* input = this->GetInputDataObject(0, 0);
  std::ostringstream signature;
  signature << (wanted ? this->VisibilityArray : "") << '|' << input << '|'
            << (input ? input->GetMTime() : 0) << '|' << this->CoreBuildTime.GetMTime();
  if (signature.str() == this->LastMaskSignature)
  {
    return;
  }
  this->LastMaskSignature = signature.str();
  const vtkIdType numTubes = this->Core->GetNumberOfTubes();
  this->NumberOfVisibleLines = numTubes;
  this->LineMaskTime.Modified();
  if (!wanted)
  {
    this->LineMask.clear();
    this->Visibility->SetLineMask(nullptr);
    return;
  }
  // The array of each block (by flat index).
  std::vector<vtkDataArray*> arrays;
  ForEachPolyData(input,
    [&](vtkPolyData* pd, unsigned int blockId)
    {
      vtkDataArray* array = pd->GetCellData()->GetArray(this->VisibilityArray);
      if (!array || array->GetNumberOfComponents() != 1 ||
        array->GetNumberOfTuples() != pd->GetNumberOfCells())
      {
        vtkErrorMacro(<< "The visibility array \"" << this->VisibilityArray << "\" is "
                      << (array ? "not one value per cell" : "not a cell array") << " of block "
                      << blockId << ": all its lines are drawn.");
        return;
      }
      if (arrays.size() <= blockId)
      {
        arrays.resize(blockId + 1, nullptr);
      }
      arrays[blockId] = array;
    });
  this->LineMask.assign(static_cast<size_t>(numTubes), 1);
  vtkSplineTubeCore* core = this->Core;
  vtkSMPTools::For(0, numTubes,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType t = begin; t < end; ++t)
      {
        const unsigned int block = core->GetTubeBlockId(t);
        vtkDataArray* array = block < arrays.size() ? arrays[block] : nullptr;
        if (array)
        {
          const double value = array->GetComponent(core->GetTubeCellIndex(t), 0);
          this->LineMask[t] = (value != 0.0 && !std::isnan(value)) ? 1 : 0;
        }
      }
    });
  this->NumberOfVisibleLines =
    static_cast<vtkIdType>(std::count(this->LineMask.begin(), this->LineMask.end(), 1));
  this->Visibility->SetLineMask(this->LineMask.data());
}

//------------------------------------------------------------------------------
vtkIdType vtkSplineTubeMapper::UpdateTubes()
{
  if (this->GetInputAlgorithm())
  {
    this->GetInputAlgorithm()->Update();
  }
  this->UpdateTubeCore();
  return this->Core->GetNumberOfSegments();
}

//------------------------------------------------------------------------------
void vtkSplineTubeMapper::Render(vtkRenderer* ren, vtkActor* act)
{
  if (vtkSplineTubeMapper* full = this->LevelOfDetailOf)
  {
    // The full mapper draws its subset: no second core or upload. Its
    // settings are restored without Modified(), so that nothing is rebuilt.
    const bool force = full->ForceInteractive;
    const double frameTime = full->InteractiveFrameTime;
    full->ForceInteractive = true;
    full->InteractiveFrameTime = this->InteractiveFrameTime;
    full->Render(ren, act);
    full->ForceInteractive = force;
    full->InteractiveFrameTime = frameTime;
    return;
  }
  // One piece: the composite-aware RenderPiece() handles the whole input.
  this->RenderPiece(ren, act);
}

//------------------------------------------------------------------------------
void vtkSplineTubeMapper::SetLevelOfDetailOf(vtkSplineTubeMapper* full)
{
  if (full == this)
  {
    vtkErrorMacro(<< "A mapper cannot be its own level of detail.");
    return;
  }
  if (this->LevelOfDetailOf != full)
  {
    this->LevelOfDetailOf = full;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkSplineTubeMapper* vtkSplineTubeMapper::GetLevelOfDetailOf()
{
  return this->LevelOfDetailOf;
}

//------------------------------------------------------------------------------
void vtkSplineTubeMapper::RenderPiece(vtkRenderer* ren, vtkActor* actor)
{
  if (ren->GetRenderWindow()->CheckAbortStatus())
  {
    return;
  }
  vtkOpenGLRenderWindow* window = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());

  if (!this->GetInputDataObject(0, 0))
  {
    vtkErrorMacro(<< "No input.");
    return;
  }
  this->InvokeEvent(vtkCommand::StartEvent, nullptr);
  if (!this->Static && this->GetInputAlgorithm())
  {
    this->GetInputAlgorithm()->Update();
  }
  this->InvokeEvent(vtkCommand::EndEvent, nullptr);

  this->UpdateTubeCore();
  if (this->NeedToUploadTubes())
  {
    this->UploadFailed = false;
    std::vector<PagedBuffer> paged;
    this->GetPagedBuffers(paged);
    for (const PagedBuffer& buffer : paged)
    {
      buffer.second->SetPageable(true);
    }
    this->UploadTubes(window);
    this->SetVisibilityChunks();
    this->UploadTime.Modified();
  }
  this->UpdateLineMask();
  this->UpdateSlabPlanes();
  // Interaction: the render window's desired rate (VTK's interactors raise
  // it while the camera moves), or the representation's LOD mapper.
  this->InteractiveRender = this->InteractiveSubset &&
    (this->ForceInteractive ||
      window->GetDesiredUpdateRate() >= std::max(this->InteractiveUpdateRate, 1e-300));
  if (this->Core->GetNumberOfSegments() == 0 || this->UploadFailed)
  {
    return;
  }

  // The superclass reads CurrentInput in places (timers, shader decisions);
  // an empty polydata keeps those paths neutral.
  this->CurrentInput = this->EmptyInput;
  this->RenderStart = std::chrono::steady_clock::now();
  this->RenderPieceStart(ren, actor);
  if (vtkHardwareSelector* selector = ren->GetSelector())
  {
    selector->UpdateMaximumCellId(this->MaximumCellId);
  }
  this->RenderPieceDraw(ren, actor);
  this->RenderPieceFinish(ren, actor);
  this->RenderEndpointMarkers(ren, actor);
}

//------------------------------------------------------------------------------
void vtkSplineTubeMapper::UpdateEndpointMarkers()
{
  vtkDataObject* input = this->GetInputDataObject(0, 0);
  std::ostringstream signature;
  signature << input << '|' << (input ? input->GetMTime() : 0) << '|'
            << this->CoreBuildTime.GetMTime() << '|' << this->LineMaskTime.GetMTime() << '|'
            << this->EndpointMarkerScale << '|' << this->EndpointMarkerColor[0] << ','
            << this->EndpointMarkerColor[1] << ',' << this->EndpointMarkerColor[2];
  if (signature.str() == this->LastMarkerSignature && this->Markers)
  {
    return;
  }
  this->LastMarkerSignature = signature.str();
  // The polydata of each block (by flat index), for the tubes' end points.
  std::vector<vtkPolyData*> blocks;
  ForEachPolyData(input,
    [&](vtkPolyData* pd, unsigned int blockId)
    {
      if (blocks.size() <= blockId)
      {
        blocks.resize(blockId + 1, nullptr);
      }
      blocks[blockId] = pd;
    });
  const bool useArray = this->RadiusArray && this->RadiusArray[0];
  const vtkIdType numTubes = this->Core->GetNumberOfTubes();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkFloatArray> radii;
  radii->SetName("EndpointMarkerRadius");
  vtkNew<vtkUnsignedCharArray> colors;
  colors->SetName("EndpointMarkerColor");
  colors->SetNumberOfComponents(3);
  unsigned char rgb[3];
  for (int k = 0; k < 3; ++k)
  {
    rgb[k] = static_cast<unsigned char>(
      std::lround(255.0 * std::max(0.0, std::min(1.0, this->EndpointMarkerColor[k]))));
  }
  for (vtkIdType t = 0; t < numTubes; ++t)
  {
    if (!this->LineMask.empty() && !this->LineMask[t])
    {
      continue;
    }
    const unsigned int block = this->Core->GetTubeBlockId(t);
    vtkPolyData* pd = block < blocks.size() ? blocks[block] : nullptr;
    const vtkIdType cell = this->Core->GetTubeCellIndex(t);
    if (!pd || cell < 0 || cell >= pd->GetNumberOfCells())
    {
      continue;
    }
    vtkDataArray* radiusArray =
      useArray ? pd->GetPointData()->GetArray(this->RadiusArray) : nullptr;
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    pd->GetCellPoints(cell, n, ids);
    if (n < 1)
    {
      continue;
    }
    for (vtkIdType id : { ids[0], ids[n - 1] })
    {
      const double r =
        radiusArray ? this->RadiusScale * radiusArray->GetComponent(id, 0) : this->EffectiveRadius;
      if (!(r > 0.0) || !std::isfinite(r))
      {
        continue;
      }
      points->InsertNextPoint(pd->GetPoint(id));
      radii->InsertNextValue(static_cast<float>(this->EndpointMarkerScale * r));
      colors->InsertNextTypedTuple(rgb);
    }
  }
  this->Markers = vtkSmartPointer<vtkPolyData>::New();
  this->Markers->SetPoints(points);
  this->Markers->GetPointData()->AddArray(radii);
  this->Markers->GetPointData()->SetScalars(colors);
}

//------------------------------------------------------------------------------
void vtkSplineTubeMapper::RenderEndpointMarkers(vtkRenderer* ren, vtkActor* act)
{
  this->NumberOfEndpointMarkers = 0;
  if (!this->EndpointMarkers || ren->GetSelector())
  {
    return;
  }
  this->UpdateEndpointMarkers();
  if (this->Markers->GetNumberOfPoints() == 0)
  {
    return;
  }
  if (!this->MarkerMapper)
  {
    this->MarkerMapper = vtkSmartPointer<vtkOpenGLSphereMapper>::New();
    this->MarkerMapper->SetScaleArray("EndpointMarkerRadius");
    this->MarkerMapper->SetColorModeToDirectScalars();
    this->MarkerMapper->ScalarVisibilityOn();
  }
  this->MarkerMapper->SetInputData(this->Markers);
  this->MarkerMapper->SetClippingPlanes(this->ClippingPlanes); // the slab's too
  this->MarkerMapper->Render(ren, act);
  this->NumberOfEndpointMarkers = this->Markers->GetNumberOfPoints();
}

//------------------------------------------------------------------------------
void vtkSplineTubeMapper::SetVisibilityChunks()
{
  this->Visibility->SetChunks(this->Core->GetChunkSpheres()->GetPointer(0),
    this->Core->GetChunkTubes()->GetPointer(0), this->Core->GetNumberOfChunks(),
    this->Core->GetSegmentSpheres()->GetPointer(0),
    this->Core->GetChunkFirstSegments()->GetPointer(0));
}

//------------------------------------------------------------------------------
vtkIdType vtkSplineTubeMapper::GetLastNumberOfChunksInFrustum() const
{
  return this->Visibility->GetNumberOfChunksInFrustum();
}

vtkIdType vtkSplineTubeMapper::GetLastNumberOfChunksDrawn() const
{
  return this->Visibility->GetNumberOfChunksDrawn();
}

vtkIdType vtkSplineTubeMapper::GetLastNumberOfChunksHidden() const
{
  return this->Visibility->GetNumberOfChunksHidden();
}

void vtkSplineTubeMapper::SetOcclusionCullingDepthBias(double bias)
{
  this->Visibility->SetDepthBias(bias);
  this->Modified();
}

//------------------------------------------------------------------------------
bool vtkSplineTubeMapper::ReadDepthPyramid(vtkRenderer* ren)
{
  auto* window = static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow());
  vtkOpenGLState* state = window->GetState();
  int width = 0;
  int height = 0;
  int x0 = 0;
  int y0 = 0;
  ren->GetTiledSizeAndOrigin(&width, &height, &x0, &y0);
  if (width <= 0 || height <= 0)
  {
    return false;
  }
  this->DepthImage.resize(static_cast<size_t>(width) * height);
  unsigned int drawBinding = 0;
  unsigned int drawBuffer = 0;
  state->GetCurrentDrawFramebufferState(drawBinding, drawBuffer);
  state->PushReadFramebufferBinding();
  state->vtkglBindFramebuffer(GL_READ_FRAMEBUFFER, drawBinding);
  GLint packBuffer = 0;
  glGetIntegerv(GL_PIXEL_PACK_BUFFER_BINDING, &packBuffer);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  state->vtkglPixelStorei(GL_PACK_ALIGNMENT, 4);
  glReadPixels(x0, y0, width, height, GL_DEPTH_COMPONENT, GL_FLOAT, this->DepthImage.data());
  glBindBuffer(GL_PIXEL_PACK_BUFFER, static_cast<GLuint>(packBuffer));
  state->PopReadFramebufferBinding();
  if (glGetError() != GL_NO_ERROR)
  {
    return false;
  }
  this->Pyramid->Pyramid.Build(this->DepthImage.data(), width, height);
  ++this->LastNumberOfDepthPyramids;
  return true;
}

//------------------------------------------------------------------------------
void vtkSplineTubeMapper::DrawVisibleChunks(vtkRenderer* ren, vtkActor* act,
  const std::function<void(const std::vector<std::uint32_t>& chunks)>& draw)
{
  const auto start = std::chrono::steady_clock::now();
  this->LastNumberOfDepthPyramids = 0;

  // The view, as the shaders see it: uploaded (shifted) positions to view
  // coordinates, and the projection.
  vtkSplineTubeVisibility::View view;
  float modelView[16];
  float radiusScale = 1.0f;
  this->ComputeTubeMatrices(ren, act, modelView, nullptr, radiusScale);
  vtkMatrix4x4* vcdc = GetViewToDisplayMatrix(ren); // the projection, transposed
  for (int i = 0; i < 16; ++i)
  {
    view.ModelView[i] = modelView[i];
    view.Projection[i] = vcdc->GetElement(i / 4, i % 4);
  }
  int x0 = 0;
  int y0 = 0;
  ren->GetTiledSizeAndOrigin(&view.Width, &view.Height, &x0, &y0);

  // Occlusion culling needs an opaque draw and a depth buffer that can be
  // read back (not multisampled).
  GLint sampleBuffers = 0;
  glGetIntegerv(GL_SAMPLE_BUFFERS, &sampleBuffers);
  const bool occlusionPossible = this->OcclusionCulling && sampleBuffers == 0 &&
    !act->IsRenderingTranslucentPolygonalGeometry() && view.Width > 0 && view.Height > 0;

  // The interaction subset: the fraction that met the budget last time; the
  // first interactive frame after a still one scales the still frame's cost.
  const double budget = this->InteractiveFrameTime > 0.0
    ? this->InteractiveFrameTime
    : std::max(act->GetAllocatedRenderTime(), 1e-3);
  double fraction = 1.0;
  if (this->InteractiveRender)
  {
    fraction = this->InteractiveFraction;
    if (!this->LastRenderInteractive && this->LastProportionalTime > 0.0)
    {
      // From the still frame's cost, undamped.
      const double available = std::max(budget - this->LastFixedTime, budget / 3.0);
      fraction = std::max(
        MinimumLineFraction, std::min(1.0, available / std::max(this->LastProportionalTime, 1e-9)));
    }
  }
  // Small subsets hide little: no occlusion culling (its read-backs would
  // cost more than they save).
  const bool occlusion = occlusionPossible && fraction >= 0.1;
  double fixed = std::chrono::duration<double>(start - this->RenderStart).count();
  auto timed = [&fixed](const std::function<void()>& work)
  {
    const auto t = std::chrono::steady_clock::now();
    work();
    fixed += std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
  };
  timed([&]() { this->Visibility->BeginFrame(view, fraction, occlusion, true); });
  std::vector<std::uint32_t> chunks;
  const int groups = this->Visibility->GetNumberOfGroups();
  bool pyramid = false;
  for (int g = 0; g < groups; ++g)
  {
    if (g > 0 && occlusion)
    {
      pyramid = this->ReadDepthPyramid(ren);
    }
    timed([&]()
      { this->Visibility->CullGroup(g, pyramid ? &this->Pyramid->Pyramid : nullptr, chunks); });
    if (!chunks.empty())
    {
      draw(chunks);
    }
  }
  // Remember what is visible in the finished picture for the next frame
  // (still frames only: a subset's visible chunks hide less).
  if (!this->InteractiveRender)
  {
    const bool finalPyramid = occlusion && groups > 0 && this->ReadDepthPyramid(ren);
    timed([&]() { this->Visibility->EndFrame(finalPyramid ? &this->Pyramid->Pyramid : nullptr); });
  }

  // The time to the end of the GPU's work adapts the interaction subset.
  if (this->InteractiveSubset)
  {
    glFinish();
  }
  // Cost model: the per-view work (classification, projection, culling
  // tests) is fixed, the rest (drawing, waiting for the rasterizer) grows
  // with the lines drawn.
  this->LastDrawTime =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - this->RenderStart).count();
  this->LastFixedTime = fixed;
  this->LastProportionalTime = std::max(this->LastDrawTime - fixed, 1e-6) / fraction;
  this->LastLineFraction = fraction;
  this->LastRenderInteractive = this->InteractiveRender;
  if (this->InteractiveRender)
  {
    this->InteractiveFraction = this->NextFraction(fraction, budget);
  }
}

//------------------------------------------------------------------------------
double vtkSplineTubeMapper::NextFraction(double fraction, double budget) const
{
  // The fraction whose drawing fits what the fixed work leaves of the
  // budget (at least a third of it), damped.
  const double available = std::max(budget - this->LastFixedTime, budget / 3.0);
  const double wanted = available / std::max(this->LastProportionalTime, 1e-9);
  const double ratio = std::max(0.2, std::min(5.0, wanted / fraction));
  return std::max(MinimumLineFraction, std::min(1.0, fraction * std::pow(ratio, 0.8)));
}

//------------------------------------------------------------------------------
void vtkSplineTubeMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  // The superclass releases its resources only through the resource
  // callback of the render window, whose class VTK 9.2 does not install;
  // the renderer calls this method when the window is finalized or the
  // actor removed, so release what the tube mappers use here.
  for (int i = PrimitiveStart; i < PrimitiveEnd; ++i)
  {
    this->Primitives[i].ReleaseGraphicsResources(window);
    this->SelectionPrimitives[i].ReleaseGraphicsResources(window);
  }
  this->NodesBuffer->ReleaseGraphicsResources(window);
  this->NodeInfoBuffer->ReleaseGraphicsResources(window);
  this->TubesBuffer->ReleaseGraphicsResources(window);
  this->ColorsBuffer->ReleaseGraphicsResources(window);
  if (this->MarkerMapper)
  {
    this->MarkerMapper->ReleaseGraphicsResources(window);
  }
  this->UploadTime = vtkTimeStamp();
  this->Modified();
}

//------------------------------------------------------------------------------
bool vtkSplineTubeMapper::UploadTubeBuffers(vtkOpenGLRenderWindow* window)
{
  vtkSplineTubeCore* core = this->Core;
  const vtkIdType numNodes = core->GetNumberOfNodes();
  const vtkIdType numTubes = core->GetNumberOfTubes();
  if (numTubes > static_cast<vtkIdType>(vtkSplineTubeCore::NODE_TUBE_MASK))
  {
    vtkErrorMacro(<< "Too many tubes (" << numTubes << "); at most 2^30 are supported.");
    return false;
  }
  // Filled piece by piece from the input: no copy of the whole data on the
  // CPU side (vtkSplineTubeCore::Fill...).
  bool ok = this->UploadNodes(window, *this->NodesBuffer);
  ok = ok &&
    this->NodeInfoBuffer->UploadInPieces(window, static_cast<size_t>(numNodes), 1, VTK_TYPE_UINT32,
      GL_R32UI,
      [&](size_t first, size_t count, void* destination)
      {
        core->FillNodeInfo(static_cast<vtkIdType>(first), static_cast<vtkIdType>(count),
          static_cast<unsigned int*>(destination));
      });
  // Per tube: (cell id, block id), for picking.
  ok = ok &&
    this->TubesBuffer->UploadInPieces(window, static_cast<size_t>(numTubes), 2, VTK_TYPE_INT32,
      GL_RG32I,
      [&](size_t first, size_t count, void* destination)
      {
        auto* ids = static_cast<vtkTypeInt32*>(destination);
        for (size_t t = 0; t < count; ++t)
        {
          ids[2 * t] = static_cast<vtkTypeInt32>(core->GetTubeCellId(first + t));
          ids[2 * t + 1] = static_cast<vtkTypeInt32>(core->GetTubeBlockId(first + t));
        }
      });
  // Colors (RGBA8, one word per node), only with scalar coloring; the
  // derivatives come from the neighbours in the shaders.
  if (this->HaveColors)
  {
    ok = ok &&
      this->ColorsBuffer->UploadInPieces(window, static_cast<size_t>(numNodes), 1, VTK_TYPE_UINT32,
        GL_R32UI,
        [&](size_t first, size_t count, void* destination)
        {
          core->FillColors(static_cast<vtkIdType>(first), static_cast<vtkIdType>(count),
            static_cast<unsigned int*>(destination));
        });
  }
  else
  {
    this->ColorsBuffer->ReleaseGraphicsResources(window);
  }
  if (!ok)
  {
    vtkErrorMacro(<< "Could not upload the tubes buffer to the GPU: "
                  << vtkSplineVizGPUBuffer::FirstUploadError(
                       { this->NodesBuffer.get(), this->NodeInfoBuffer.get(),
                         this->TubesBuffer.get(), this->ColorsBuffer.get() }));
    this->UploadFailed = true;
  }
  return ok;
}

//------------------------------------------------------------------------------
bool vtkSplineTubeMapper::UploadNodes(vtkOpenGLRenderWindow* window, vtkSplineVizGPUBuffer& buffer)
{
  vtkSplineTubeCore* core = this->Core;
  double radius = 0.0;
  const bool positionsOnly =
    core->GetConstantRadius(radius) && vtkSplineVizGPUBuffer::SupportsRGB32F();
  const int components = positionsOnly ? 3 : 4;
  this->NodesConstantRadius = positionsOnly ? static_cast<float>(radius) : -1.0f;
  const double shift[3] = { this->Shift[0], this->Shift[1], this->Shift[2] };
  return buffer.UploadInPieces(window, static_cast<size_t>(core->GetNumberOfNodes()), components,
    VTK_FLOAT, positionsOnly ? GL_RGB32F : GL_RGBA32F,
    [&](size_t first, size_t count, void* destination)
    {
      core->FillNodes(static_cast<vtkIdType>(first), static_cast<vtkIdType>(count), shift,
        static_cast<float*>(destination), components);
    });
}

//------------------------------------------------------------------------------
void vtkSplineTubeMapper::SetNodesUniforms(vtkShaderProgram* program, const char* prefix)
{
  const std::string name = std::string(prefix) + "ConstantRadius";
  if (program->IsUniformUsed(name.c_str()))
  {
    program->SetUniformf(name.c_str(), this->NodesConstantRadius);
  }
}

//------------------------------------------------------------------------------
void vtkSplineTubeMapper::ActivateTubeBuffers(vtkShaderProgram* program)
{
  this->NodesBuffer->Activate(program, "tubeNodes");
  this->SetNodesUniforms(program, "tube");
  this->NodeInfoBuffer->Activate(program, "tubeNodeInfo");
  if (program->IsUniformUsed("tubeTubes"))
  {
    this->TubesBuffer->Activate(program, "tubeTubes");
  }
  if (this->HaveColors)
  {
    this->ColorsBuffer->Activate(program, "tubeColors");
  }
}

//------------------------------------------------------------------------------
void vtkSplineTubeMapper::DeactivateTubeBuffers()
{
  this->NodesBuffer->Deactivate();
  this->NodeInfoBuffer->Deactivate();
  this->TubesBuffer->Deactivate();
  this->ColorsBuffer->Deactivate();
}

//------------------------------------------------------------------------------
size_t vtkSplineTubeMapper::GetTubeBuffersSize()
{
  return this->NodesBuffer->GetNumberOfBytes() + this->NodeInfoBuffer->GetNumberOfBytes() +
    this->TubesBuffer->GetNumberOfBytes() + this->ColorsBuffer->GetNumberOfBytes();
}

//------------------------------------------------------------------------------
std::string vtkSplineTubeMapper::GetTubeNodesDeclarations()
{
  return vtkSplineTubeNodes;
}

//------------------------------------------------------------------------------
std::string vtkSplineTubeMapper::GetTubeColorDeclarations()
{
  return vtkSplineTubeColor;
}

//------------------------------------------------------------------------------
std::string vtkSplineTubeMapper::GetTubeDirectionColorDeclarations()
{
  return "vec4 tubeDirectionColor(vec3 derivative)\n"
         "{\n"
         "  return vec4(abs(derivative) / max(length(derivative), 1e-30), 1.0);\n"
         "}\n";
}

//------------------------------------------------------------------------------
std::string vtkSplineTubeMapper::GetTubeColorImplementation(
  const char* nodeExpression, const char* tExpression)
{
  std::ostringstream s;
  s << "  vec4 tubeColor = tubeColorSpline(" << nodeExpression << ", " << tExpression << ");\n";
  return s.str();
}

//------------------------------------------------------------------------------
void vtkSplineTubeMapper::ReplaceShaderTubePicking(
  std::string& FSSource, const char* tubeExpression)
{
  if (this->LastSelectionState < vtkHardwareSelector::MIN_KNOWN_PASS)
  {
    return;
  }
  const std::string encode =
    "  gl_FragData[0] = vec4(float(idx % 256) / 255.0, float((idx / 256) % 256) / 255.0,\n"
    "    float((idx / 65536) % 256) / 255.0, 1.0);\n";
  const std::string tubes = std::string("texelFetch(tubeTubes, ") + tubeExpression + ")";
  switch (this->LastSelectionState)
  {
    case vtkHardwareSelector::CELL_ID_LOW24:
      vtkShaderProgram::Substitute(
        FSSource, "//VTK::Picking::Dec", "uniform isamplerBuffer tubeTubes;\n");
      vtkShaderProgram::Substitute(
        FSSource, "//VTK::Picking::Impl", "  int idx = " + tubes + ".x;\n" + encode);
      break;
    case vtkHardwareSelector::CELL_ID_HIGH24:
      vtkShaderProgram::Substitute(
        FSSource, "//VTK::Picking::Dec", "uniform isamplerBuffer tubeTubes;\n");
      vtkShaderProgram::Substitute(
        FSSource, "//VTK::Picking::Impl", "  int idx = (" + tubes + ".x >> 24) & 0xff;\n" + encode);
      break;
    case vtkHardwareSelector::COMPOSITE_INDEX_PASS:
      // The block's flat index (as vtkCompositePolyDataMapper2 reports it);
      // a non-composite input keeps VTK's per-mapper index.
      if (this->InputIsComposite)
      {
        vtkShaderProgram::Substitute(
          FSSource, "//VTK::Picking::Dec", "uniform isamplerBuffer tubeTubes;\n");
        vtkShaderProgram::Substitute(
          FSSource, "//VTK::Picking::Impl", "  int idx = " + tubes + ".y;\n" + encode);
      }
      break;
    case vtkHardwareSelector::POINT_ID_LOW24:
    case vtkHardwareSelector::POINT_ID_HIGH24:
      // Tubes have no points to pick.
      vtkShaderProgram::Substitute(FSSource, "//VTK::Picking::Impl", "  discard;\n");
      break;
    default:
      break; // actor and process passes: VTK's mapperIndex
  }
}

//------------------------------------------------------------------------------
void vtkSplineTubeMapper::ReplaceShaderColor(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act)
{
  if (this->GetTubeColorMode() == 0)
  {
    this->Superclass::ReplaceShaderColor(shaders, ren, act);
    return;
  }
  // As VTK does for interpolated point colors, with the color spline's value.
  std::string FSSource = shaders[vtkShader::Fragment]->GetSource();
  std::string colorDec = "uniform float ambientIntensity;\n"
                         "uniform float diffuseIntensity;\n"
                         "uniform float opacityUniform;\n"
                         "uniform vec3 ambientColorUniform;\n"
                         "uniform vec3 diffuseColorUniform;\n";
  std::string colorImpl;
  if (this->PrimitiveInfo[this->LastBoundBO].LastLightComplexity)
  {
    colorDec += "uniform float specularIntensity;\n"
                "uniform vec3 specularColorUniform;\n"
                "uniform float specularPowerUniform;\n";
    colorImpl += "  vec3 specularColor = specularIntensity * specularColorUniform;\n"
                 "  float specularPower = specularPowerUniform;\n";
  }
  colorImpl += "  vec3 ambientColor = ambientIntensity * tubeColor.rgb;\n"
               "  vec3 diffuseColor = diffuseIntensity * tubeColor.rgb;\n"
               "  float opacity = opacityUniform * tubeColor.a;\n";
  vtkShaderProgram::Substitute(FSSource, "//VTK::Color::Dec", colorDec);
  vtkShaderProgram::Substitute(FSSource, "//VTK::Color::Impl", colorImpl);
  shaders[vtkShader::Fragment]->SetSource(FSSource);
}

//------------------------------------------------------------------------------
bool vtkSplineTubeMapper::GetNeedToRebuildShaders(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  // Shader variants depend on scalar coloring and composite input too;
  // always let the superclass update its bookkeeping.
  const int variant = this->GetTubeColorMode() | (this->InputIsComposite ? 4 : 0);
  const bool superclass = this->Superclass::GetNeedToRebuildShaders(cellBO, ren, act);
  // Shaders read the arrays from as many pages as the data needs.
  const std::string paging = this->GetPagingKey();
  std::string& programPaging = this->ProgramPaging[&cellBO];
  const bool pagingChanged = programPaging != paging;
  programPaging = paging;
  if (variant != this->ShaderVariant)
  {
    this->ShaderVariant = variant;
    return true;
  }
  return superclass || pagingChanged;
}

//------------------------------------------------------------------------------
void vtkSplineTubeMapper::BuildShaders(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act)
{
  this->Superclass::BuildShaders(shaders, ren, act);
  for (auto& stage : shaders)
  {
    if (stage.second)
    {
      std::string source = stage.second->GetSource();
      this->ApplyPaging(source);
      stage.second->SetSource(source);
    }
  }
}

//------------------------------------------------------------------------------
std::string vtkSplineTubeMapper::GetPagingKey()
{
  std::vector<PagedBuffer> buffers;
  this->GetPagedBuffers(buffers);
  std::string key;
  for (const PagedBuffer& buffer : buffers)
  {
    key += buffer.second->GetPagingKey() + ";";
  }
  return key;
}

//------------------------------------------------------------------------------
void vtkSplineTubeMapper::ApplyPaging(std::string& source)
{
  std::vector<PagedBuffer> buffers;
  this->GetPagedBuffers(buffers);
  for (const PagedBuffer& buffer : buffers)
  {
    buffer.second->ApplyPaging(source, buffer.first);
  }
}

//------------------------------------------------------------------------------
void vtkSplineTubeMapper::GetPagedBuffers(std::vector<PagedBuffer>& buffers)
{
  buffers.emplace_back("tubeNodes", this->NodesBuffer.get());
  buffers.emplace_back("tubeNodeInfo", this->NodeInfoBuffer.get());
  buffers.emplace_back("tubeColors", this->ColorsBuffer.get());
}

//------------------------------------------------------------------------------
void vtkSplineTubeMapper::SetMapperShaderParameters(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  this->Superclass::SetMapperShaderParameters(cellBO, ren, act);
  this->ActivateTubeBuffers(cellBO.Program);
}

//------------------------------------------------------------------------------
void vtkSplineTubeMapper::SetCameraShaderParameters(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  this->Superclass::SetCameraShaderParameters(cellBO, ren, act);
  vtkShaderProgram* program = cellBO.Program;
  float modelView[16];
  float viewModel[16];
  float radiusScale = 1.0f;
  this->ComputeTubeMatrices(ren, act, modelView, viewModel, radiusScale);
  program->SetUniformMatrix4x4("tubeMCVC", modelView);
  program->SetUniformf("tubeRadiusScale", radiusScale);
  if (program->IsUniformUsed("tubeMinimumRadius"))
  {
    // The narrowest drawn radius at view distance d: a + b d (view units).
    const double halfWidth = 0.5 * this->MinimumPixelWidth / std::max(GetPixelScale(ren), 1e-30);
    const bool parallel = ren->GetActiveCamera()->GetParallelProjection() != 0;
    const float minimum[2] = { static_cast<float>(parallel ? halfWidth : 0.0),
      static_cast<float>(parallel ? 0.0 : halfWidth) };
    program->SetUniform2f("tubeMinimumRadius", minimum);
  }
  if (program->IsUniformUsed("tubeVCMC"))
  {
    program->SetUniformMatrix4x4("tubeVCMC", viewModel);
  }
  program->SetUniformMatrix("VCDCMatrix", GetViewToDisplayMatrix(ren));
}

//------------------------------------------------------------------------------
double vtkSplineTubeMapper::GetPixelScale(vtkRenderer* ren)
{
  vtkMatrix4x4* vcdc = GetViewToDisplayMatrix(ren);
  int width = 1;
  int height = 1;
  ren->GetTiledSize(&width, &height);
  return 0.5 *
    std::max(std::abs(vcdc->GetElement(0, 0)) * width, std::abs(vcdc->GetElement(1, 1)) * height);
}

//------------------------------------------------------------------------------
vtkMatrix4x4* vtkSplineTubeMapper::GetViewToDisplayMatrix(vtkRenderer* ren)
{
  vtkMatrix4x4* wcdc;
  vtkMatrix4x4* wcvc;
  vtkMatrix3x3* normals;
  vtkMatrix4x4* vcdc;
  static_cast<vtkOpenGLCamera*>(ren->GetActiveCamera())
    ->GetKeyMatrices(ren, wcvc, normals, vcdc, wcdc);
  return vcdc;
}

//------------------------------------------------------------------------------
void vtkSplineTubeMapper::ReplaceShaderTubeClip(
  std::string& FSSource, const char* implementationTag)
{
  if (!this->GetNumberOfClippingPlanes())
  {
    return;
  }
  vtkShaderProgram::Substitute(FSSource, "//VTK::Clip::Dec",
    "uniform int numClipPlanes;\n"
    "uniform vec4 clipPlanes[6];\n"
    "uniform mat4 tubeVCMC;\n");
  vtkShaderProgram::Substitute(FSSource, implementationTag,
    "  vec4 tubeClipMC = tubeVCMC * vertexVC;\n"
    "  for (int planeNum = 0; planeNum < numClipPlanes; planeNum++)\n"
    "  {\n"
    "    if (dot(clipPlanes[planeNum], tubeClipMC) < 0.0) discard;\n"
    "  }\n");
}

//------------------------------------------------------------------------------
const char* vtkSplineTubeMapper::GetFragDepthWrittenMarker()
{
  return "// SplineViz: gl_FragDepth is the primitive's depth from here on\n";
}

//------------------------------------------------------------------------------
void vtkSplineTubeMapper::UseWrittenFragDepth(std::string& FSSource)
{
  const size_t marker = FSSource.find(GetFragDepthWrittenMarker());
  if (marker == std::string::npos)
  {
    return;
  }
  std::string tail = FSSource.substr(marker);
  vtkShaderProgram::Substitute(tail, "gl_FragCoord.z", "gl_FragDepth", true);
  vtkShaderProgram::Substitute(tail, "1.0/gl_FragCoord.w", "(-vertexVC.z)", true);
  // The dual depth peeling's tolerance (its declaration "float epsilon = ...;"),
  // widened where it is smaller.
  const std::string declaration = "float epsilon = ";
  const size_t at = tail.find(declaration);
  const size_t end = at == std::string::npos ? at : tail.find(';', at);
  if (end != std::string::npos)
  {
    const size_t value = at + declaration.size();
    std::istringstream parsed(tail.substr(value, end - value));
    parsed.imbue(std::locale::classic());
    double epsilon = 0.0;
    // (only a plain number: anything else is left as VTK wrote it)
    if ((parsed >> epsilon) && (parsed >> std::ws).eof() && epsilon < WrittenFragDepthTolerance)
    {
      std::ostringstream widened;
      widened.imbue(std::locale::classic());
      widened << std::scientific << WrittenFragDepthTolerance;
      tail.replace(value, end - value, widened.str());
    }
  }
  FSSource = FSSource.substr(0, marker) + tail;
}

//------------------------------------------------------------------------------
void vtkSplineTubeMapper::DumpShaderSources(
  const std::vector<std::pair<std::string, std::string>>& stages)
{
  if (!getenv("SPLINEVIZ_DUMP_SHADERS"))
  {
    return;
  }
  for (const auto& stage : stages)
  {
    cout << "=== " << stage.first << "\n" << stage.second << "\n";
  }
  cout.flush();
}

//------------------------------------------------------------------------------
void vtkSplineTubeMapper::ProcessSelectorPixelBuffers(
  vtkHardwareSelector*, std::vector<unsigned int>&, vtkProp*)
{
  // The shader wrote the final cell and block ids; nothing to convert.
}

//------------------------------------------------------------------------------
void vtkSplineTubeMapper::ComputeBounds()
{
  // The renderer asks every frame; the bounds (a pass over all segments)
  // change only when the core is rebuilt.
  this->UpdateTubeCore();
  if (this->BoundsTime.GetMTime() < this->CoreBuildTime.GetMTime())
  {
    this->Core->GetBounds(this->CoreBounds);
    this->BoundsTime.Modified();
  }
  std::copy(this->CoreBounds, this->CoreBounds + 6, this->Bounds);
  // Endpoint markers wider than the lines reach beyond them.
  const double pad = this->EndpointMarkers
    ? std::max(0.0, this->EndpointMarkerScale - 1.0) * this->Core->GetMaximumRadius()
    : 0.0;
  if (pad > 0.0 && this->Bounds[0] <= this->Bounds[1])
  {
    for (int k = 0; k < 3; ++k)
    {
      this->Bounds[2 * k] -= pad;
      this->Bounds[2 * k + 1] += pad;
    }
  }
}

//------------------------------------------------------------------------------
double* vtkSplineTubeMapper::GetBounds()
{
  if (vtkSplineTubeMapper* full = this->LevelOfDetailOf)
  {
    full->GetBounds(this->Bounds);
    return this->Bounds;
  }
  if (!this->GetInputDataObject(0, 0))
  {
    vtkMath::UninitializeBounds(this->Bounds);
    return this->Bounds;
  }
  if (!this->Static && this->GetInputAlgorithm())
  {
    this->GetInputAlgorithm()->Update();
  }
  this->ComputeBounds();
  return this->Bounds;
}

//------------------------------------------------------------------------------
void vtkSplineTubeMapper::ComputeTubeMatrices(
  vtkRenderer* ren, vtkActor* act, float modelView[16], float viewModel[16], float& radiusScale)
{
  this->ComputeTubeMatrices(
    ren->GetActiveCamera()->GetModelViewTransformMatrix(), act, modelView, viewModel, radiusScale);
}

//------------------------------------------------------------------------------
void vtkSplineTubeMapper::ComputeTubeMatrices(vtkMatrix4x4* worldToView, vtkActor* act,
  float modelView[16], float viewModel[16], float& radiusScale)
{
  vtkNew<vtkMatrix4x4> m;
  m->DeepCopy(worldToView);
  if (!act->GetIsIdentity())
  {
    vtkMatrix4x4::Multiply4x4(m, act->GetMatrix(), m);
  }
  // View to data coordinates (for clipping planes, given in data coordinates).
  vtkNew<vtkMatrix4x4> inverse;
  vtkMatrix4x4::Invert(m, inverse);
  // Shifted model (uploaded positions are relative to Shift) to view.
  vtkNew<vtkMatrix4x4> shift;
  for (int c = 0; c < 3; ++c)
  {
    shift->SetElement(c, 3, this->Shift[c]);
  }
  vtkMatrix4x4::Multiply4x4(m, shift, m);
  // Radii scale with the cube root of the volume change (the exact factor
  // for a rigid transform with uniform scaling).
  double a[3][3];
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      a[r][c] = m->GetElement(r, c);
    }
  }
  radiusScale = static_cast<float>(std::cbrt(std::abs(vtkMath::Determinant3x3(a))));
  // Column-major for glUniformMatrix4fv(..., GL_FALSE, ...).
  for (int r = 0; r < 4; ++r)
  {
    for (int c = 0; c < 4; ++c)
    {
      modelView[c * 4 + r] = static_cast<float>(m->GetElement(r, c));
      if (viewModel)
      {
        viewModel[c * 4 + r] = static_cast<float>(inverse->GetElement(r, c));
      }
    }
  }
}

//------------------------------------------------------------------------------
void vtkSplineTubeMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Radius: " << this->Radius << " (in use: " << this->EffectiveRadius << ")\n";
  os << indent << "EndpointMarkers: " << this->EndpointMarkers << " (scale "
     << this->EndpointMarkerScale << ", color " << this->EndpointMarkerColor[0] << ' '
     << this->EndpointMarkerColor[1] << ' ' << this->EndpointMarkerColor[2] << ")\n";
  os << indent << "AutomaticRadiusBounds: " << this->AutomaticRadiusBounds[0] << ' '
     << this->AutomaticRadiusBounds[1] << ' ' << this->AutomaticRadiusBounds[2] << ' '
     << this->AutomaticRadiusBounds[3] << ' ' << this->AutomaticRadiusBounds[4] << ' '
     << this->AutomaticRadiusBounds[5] << "\n";
  os << indent << "MinimumPixelWidth: " << this->MinimumPixelWidth << "\n";
  os << indent << "RadiusArray: " << (this->RadiusArray ? this->RadiusArray : "(none)") << "\n";
  os << indent << "DirectionColoring: " << this->DirectionColoring << "\n";
  os << indent << "Slab: origin (" << this->SlabOrigin[0] << ", " << this->SlabOrigin[1] << ", "
     << this->SlabOrigin[2] << "), normal (" << this->SlabNormal[0] << ", " << this->SlabNormal[1]
     << ", " << this->SlabNormal[2] << "), thickness " << this->SlabThickness << "\n";
  os << indent << "VisibilityArray: " << (this->VisibilityArray ? this->VisibilityArray : "(none)")
     << "\n";
  os << indent << "RadiusScale: " << this->RadiusScale << "\n";
  os << indent << "CellIdArray: " << (this->CellIdArray ? this->CellIdArray : "(none)") << "\n";
  os << indent << "Segments: " << this->Core->GetNumberOfSegments() << "\n";
  os << indent << "OcclusionCulling: " << this->OcclusionCulling << "\n";
  os << indent << "InteractiveSubset: " << this->InteractiveSubset << "\n";
  os << indent << "InteractiveUpdateRate: " << this->InteractiveUpdateRate << "\n";
  os << indent << "ForceInteractive: " << this->ForceInteractive << "\n";
  os << indent << "LevelOfDetailOf: " << this->LevelOfDetailOf.GetPointer() << "\n";
  os << indent << "InteractiveFrameTime: " << this->InteractiveFrameTime << "\n";
}
