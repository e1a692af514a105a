// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLRSplineProbeFilter.h"

#include "vtkSplineVizPieces.h"
#include "vtkLRSplineField.h"
#include "vtkSplineVizInputArrays.h"
#include "vtkSplineVizProgress.h"

#include "vtkCellData.h"
#include "vtkDataSet.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

vtkStandardNewMacro(vtkLRSplineProbeFilter);

//------------------------------------------------------------------------------
vtkLRSplineProbeFilter::vtkLRSplineProbeFilter()
{
  this->SetNumberOfInputPorts(2);
  this->SetGradientArrayName("Gradient");
  this->SetValidPointMaskArrayName("vtkValidPointMask");
}

vtkLRSplineProbeFilter::~vtkLRSplineProbeFilter()
{
  this->SetGradientArrayName(nullptr);
  this->SetValidPointMaskArrayName(nullptr);
}

//------------------------------------------------------------------------------
void vtkLRSplineProbeFilter::SetSourceConnection(vtkAlgorithmOutput* algOutput)
{
  this->SetInputConnection(1, algOutput);
}

void vtkLRSplineProbeFilter::SetSourceData(vtkDataObject* input)
{
  this->SetInputData(1, input);
}

vtkDataObject* vtkLRSplineProbeFilter::GetSource()
{
  if (this->GetNumberOfInputConnections(1) < 1)
  {
    return nullptr;
  }
  return this->GetExecutive()->GetInputData(1, 0);
}

//------------------------------------------------------------------------------
void vtkLRSplineProbeFilter::SetArrayName(const char* name)
{
  vtkSplineVizInputArrays::SetName(this, 0, 1, name);
}

const char* vtkLRSplineProbeFilter::GetArrayName()
{
  return vtkSplineVizInputArrays::GetName(this, 0);
}

//------------------------------------------------------------------------------
int vtkLRSplineProbeFilter::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataObject");
    return 1;
  }
  return this->Superclass::FillInputPortInformation(port, info);
}

//------------------------------------------------------------------------------
int vtkLRSplineProbeFilter::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  if (inInfo)
  {
    inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(),
      outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER()));
    inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(),
      outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES()));
    inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(),
      outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS()));
  }
  // The whole spline everywhere.
  vtkSplineVizPieces::RequestWholeInput(inputVector[1]->GetInformationObject(0));
  return 1;
}

//------------------------------------------------------------------------------
int vtkLRSplineProbeFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkDataSet* input = vtkDataSet::GetData(inputVector[0], 0);
  vtkDataObject* source = vtkDataObject::GetData(inputVector[1], 0);
  vtkDataSet* output = vtkDataSet::GetData(outputVector, 0);
  if (!input || !output)
  {
    vtkErrorMacro(<< "no input data set");
    return 0;
  }
  if (!source)
  {
    vtkErrorMacro(<< "no spline source: connect the output of vtkLRSplineReader to port 1");
    return 0;
  }
  std::string error, fieldName;
  if (!vtkLRSplineField::SelectedFieldName(this, 0, 1, source, fieldName, &error))
  {
    vtkErrorMacro(<< error);
    return 0;
  }
  if (!vtkLRSplineField::BuildCached(this->Field, this->FieldKey, source, fieldName.c_str(),
        this->LocatorType, this->ForestResolution, this->UseParameterCoordinates != 0, &error,
        this->SurfaceTolerance))
  {
    vtkErrorMacro(<< "cannot evaluate the spline source: " << error);
    return 0;
  }
  // An absurd probe (e.g. an implicit image of 100000^3 points) is refused
  // before anything is allocated.
  const int nc = this->Field->GetNumberOfComponents();
  if (!vtkSplineVizProgress::CheckOutputSize(static_cast<double>(input->GetNumberOfPoints()),
        8.0 * nc * (this->ComputeGradient ? 4 : 1) + 1, "the probed values", &error))
  {
    vtkErrorMacro(<< error);
    return 0;
  }
  output->CopyStructure(input);
  output->GetPointData()->PassData(input->GetPointData());
  output->GetCellData()->PassData(input->GetCellData());
  output->GetFieldData()->PassData(input->GetFieldData());

  const vtkIdType n = input->GetNumberOfPoints();
  if (n > 0)
  {
    input->GetPoint(0); // build any internal point cache before the threads start
  }
  const vtkIdType inside = this->Field->EvaluateIntoPointData(
    output->GetPointData(), n, [input](vtkIdType i, double x[3]) { input->GetPoint(i, x); },
    this->ComputeGradient
      ? (this->GradientArrayName && *this->GradientArrayName ? this->GradientArrayName : "Gradient")
      : nullptr,
    this->ValidPointMaskArrayName && *this->ValidPointMaskArrayName ? this->ValidPointMaskArrayName
                                                                    : "vtkValidPointMask",
    this);
  if (inside < 0)
  {
    output->Initialize(); // aborted: a clean, empty output
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkLRSplineProbeFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  const char* field = vtkSplineVizInputArrays::GetName(this, 0);
  os << indent << "Field (input array 0, port 1): "
     << (field && *field ? field : "(active vectors, else scalars)") << "\n";
  os << indent << "ComputeGradient: " << this->ComputeGradient << "\n";
  os << indent
     << "GradientArrayName: " << (this->GradientArrayName ? this->GradientArrayName : "(none)")
     << "\n";
  os << indent << "ValidPointMaskArrayName: "
     << (this->ValidPointMaskArrayName ? this->ValidPointMaskArrayName : "(none)") << "\n";
  os << indent << "UseParameterCoordinates: " << this->UseParameterCoordinates << "\n";
  os << indent << "LocatorType: " << this->LocatorType << "\n";
  os << indent << "ForestResolution: " << this->ForestResolution << "\n";
  os << indent << "SurfaceTolerance: " << this->SurfaceTolerance << "\n";
}
