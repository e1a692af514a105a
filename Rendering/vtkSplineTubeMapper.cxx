#include "vtkSplineTubeMapper.h"

#include "vtkSplineTubeCore.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataPipeline.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkHardwareSelector.h"
#include "vtkIdTypeArray.h"
#include "vtkPoints.h"
#include "vtkInformation.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLVertexBufferObject.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkLookupTable.h"
#include "vtkScalarsToColors.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <sstream>

//------------------------------------------------------------------------------
vtkSplineTubeMapper::vtkSplineTubeMapper()
{
  // The tube data is built per data change; the VBO shift/scale machinery of
  // the superclass does not apply (we shift positions ourselves).
  this->SetVBOShiftScaleMethod(vtkOpenGLVertexBufferObject::DISABLE_SHIFT_SCALE);
  vtkNew<vtkPoints> noPoints;
  this->EmptyInput->SetPoints(noPoints);
}

//------------------------------------------------------------------------------
vtkSplineTubeMapper::~vtkSplineTubeMapper()
{
  this->SetRadiusArray(nullptr);
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
  s << this->Radius << '|' << (this->RadiusArray ? this->RadiusArray : "") << '|'
    << this->RadiusScale << '|' << this->ScalarVisibility << '|' << this->ScalarMode << '|'
    << this->ArrayAccessMode << '|' << this->ArrayId << '|' << this->ArrayName << '|'
    << this->ArrayComponent << '|' << this->ColorMode << '|' << this->UseLookupTableScalarRange
    << '|' << this->ScalarRange[0] << '|' << this->ScalarRange[1] << '|' << this->FieldDataTupleId
    << '|' << this->LookupTable << '|' << (this->LookupTable ? this->LookupTable->GetMTime() : 0);
  return s.str();
}

//------------------------------------------------------------------------------
bool vtkSplineTubeMapper::UpdateTubeCore()
{
  vtkDataObject* input = this->GetInputDataObject(0, 0);
  const std::string signature = this->BuildSignature();
  if (input == this->LastInput && input && input->GetMTime() == this->LastInputMTime &&
    signature == this->LastSignature && this->CoreBuildTime.GetMTime() > 0)
  {
    return false;
  }

  this->Core->Initialize();
  this->Core->SetRadius(this->Radius);
  this->Core->SetRadiusArrayName(
    this->RadiusArray && this->RadiusArray[0] ? this->RadiusArray : nullptr);
  this->Core->SetRadiusScale(this->RadiusScale);

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
    if (this->ScalarVisibility && scalars)
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
  this->HaveColors = this->Core->HasColors();
  if (this->Core->GetNumberOfTubes() == 0 && inputCells > 0 &&
    this->Core->GetNumberOfSkippedLines() == 0)
  {
    vtkWarningMacro(<< "The input has " << inputCells
                    << " cells but no polylines (line or polyline cells): no tubes to draw.");
  }

  double bounds[6];
  this->Core->GetBounds(bounds);
  if (vtkMath::AreBoundsInitialized(bounds))
  {
    for (int c = 0; c < 3; ++c)
    {
      this->Shift[c] = 0.5 * (bounds[2 * c] + bounds[2 * c + 1]);
    }
  }
  this->LastInput = input;
  this->LastInputMTime = input ? input->GetMTime() : 0;
  this->LastSignature = signature;
  this->CoreBuildTime.Modified();
  return true;
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
  // One piece: the composite-aware RenderPiece() handles the whole input.
  this->RenderPiece(ren, act);
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
    this->UploadTubes(window);
    this->UploadTime.Modified();
  }
  if (this->Core->GetNumberOfSegments() == 0)
  {
    return;
  }

  // The superclass reads CurrentInput in places (timers, shader decisions);
  // an empty polydata keeps those paths neutral.
  this->CurrentInput = this->EmptyInput;
  this->RenderPieceStart(ren, actor);
  if (vtkHardwareSelector* selector = ren->GetSelector())
  {
    // The largest cell id the shaders write (the polylines' cell ids).
    vtkIdType maxCellId = 0;
    vtkIdTypeArray* cellIds = this->Core->GetSegmentCellIds();
    for (vtkIdType s = 0; s < cellIds->GetNumberOfTuples(); ++s)
    {
      maxCellId = std::max(maxCellId, cellIds->GetValue(s));
    }
    selector->UpdateMaximumCellId(maxCellId);
  }
  this->RenderPieceDraw(ren, actor);
  this->RenderPieceFinish(ren, actor);
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
  this->UploadTime = vtkTimeStamp();
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkSplineTubeMapper::ComputeBounds()
{
  this->UpdateTubeCore();
  this->Core->GetBounds(this->Bounds);
}

//------------------------------------------------------------------------------
double* vtkSplineTubeMapper::GetBounds()
{
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
  vtkNew<vtkMatrix4x4> m;
  m->DeepCopy(ren->GetActiveCamera()->GetModelViewTransformMatrix());
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
      viewModel[c * 4 + r] = static_cast<float>(inverse->GetElement(r, c));
    }
  }
}

//------------------------------------------------------------------------------
void vtkSplineTubeMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Radius: " << this->Radius << "\n";
  os << indent << "RadiusArray: " << (this->RadiusArray ? this->RadiusArray : "(none)") << "\n";
  os << indent << "RadiusScale: " << this->RadiusScale << "\n";
  os << indent << "Segments: " << this->Core->GetNumberOfSegments() << "\n";
}
