// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLRSplineFitterBase.h"

#include "vtkLRSplineArrayNames.h"
#include "vtkSplineVizPieces.h"

#include "vtkDataSetAttributes.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace
{
// Safety bound on fit-and-refine rounds.
constexpr int MaximumRounds = 64;

// Seconds on the steady clock.
double Now()
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
}

//------------------------------------------------------------------------------
vtkLRSplineFitterBase::vtkLRSplineFitterBase()
{
  this->SetInputArrayToProcess(
    0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::SCALARS);
}

vtkLRSplineFitterBase::~vtkLRSplineFitterBase()
{
  this->SetOutputFieldName(nullptr);
  this->SetFileName(nullptr);
}

//------------------------------------------------------------------------------
int vtkLRSplineFitterBase::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  for (int port = 0; port < outputVector->GetNumberOfInformationObjects(); ++port)
  {
    outputVector->GetInformationObject(port)->Set(CAN_HANDLE_PIECE_REQUEST(), 1);
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkLRSplineFitterBase::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  // Every piece fits all the data.
  vtkSplineVizPieces::RequestWholeInput(inputVector[0]->GetInformationObject(0));
  return 1;
}

//------------------------------------------------------------------------------
bool vtkLRSplineFitterBase::CheckSettings()
{
  if (!(this->Tolerance > 0) || !std::isfinite(this->Tolerance))
  {
    vtkErrorMacro(<< "Tolerance must be positive and finite (it is " << this->Tolerance << ")");
    return false;
  }
  for (int d = 0; d < 3; ++d)
  {
    if (this->Degree[d] < 1 || this->Degree[d] > 5)
    {
      vtkErrorMacro(<< "Degree must be 1 to 5 in every direction (it is " << this->Degree[0] << " "
                    << this->Degree[1] << " " << this->Degree[2] << ")");
      return false;
    }
    if (this->InitialNumberOfElements[d] < 1)
    {
      vtkErrorMacro(<< "InitialNumberOfElements must be at least 1 in every direction (it is "
                    << this->InitialNumberOfElements[0] << " " << this->InitialNumberOfElements[1]
                    << " " << this->InitialNumberOfElements[2] << ")");
      return false;
    }
  }
  if (this->MaximumRefinementLevels < 0 || this->MaximumRefinementLevels > 30)
  {
    vtkErrorMacro(<< "MaximumRefinementLevels must be 0 to 30 (it is "
                  << this->MaximumRefinementLevels
                  << "): 30 halvings already make elements a billionth of the initial ones");
    return false;
  }
  if (this->MaximumNumberOfElements < 1)
  {
    vtkErrorMacro(<< "MaximumNumberOfElements must be at least 1");
    return false;
  }
  if (!std::isfinite(this->Regularization))
  {
    vtkErrorMacro(<< "Regularization must be finite");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkLRSplineFitterBase::ResetResults()
{
  this->FitStart = Now();
  this->MaximumError = this->RMSError = this->AbsoluteTolerance = this->FitTime = 0.0;
  this->ToleranceMet = false;
  this->NumberOfElements = this->NumberOfBasisFunctions = 0;
  this->NumberOfRefinementLevels = this->NumberOfIterations = 0;
}

//------------------------------------------------------------------------------
void vtkLRSplineFitterBase::RecordFitTime(vtkMultiBlockDataSet* output)
{
  this->FitTime = Now() - this->FitStart;
  vtkDataObject* first = output && output->GetNumberOfBlocks() > 0 ? output->GetBlock(0) : nullptr;
  if (first)
  {
    vtkNew<vtkDoubleArray> seconds;
    seconds->SetName(vtkLRSplineArrayNames::FitSeconds);
    seconds->InsertNextValue(this->FitTime);
    first->GetFieldData()->AddArray(seconds);
  }
}

//------------------------------------------------------------------------------
double vtkLRSplineFitterBase::ComputeAbsoluteTolerance(const double range[2]) const
{
  const double tolerance = this->ToleranceMode == RELATIVE_TOLERANCE
    ? this->Tolerance * (range[1] - range[0])
    : this->Tolerance;
  // Constant data: its constant, up to rounding.
  return std::max(tolerance, 1e-10 * std::max(std::abs(range[0]), std::abs(range[1])));
}

//------------------------------------------------------------------------------
std::string vtkLRSplineFitterBase::ResolveOutputFieldName(const char* arrayName) const
{
  if (this->OutputFieldName && *this->OutputFieldName)
  {
    return this->OutputFieldName;
  }
  return (arrayName && *arrayName) ? arrayName : "Field";
}

//------------------------------------------------------------------------------
int vtkLRSplineFitterBase::GetMaximumRounds() const
{
  return std::min(MaximumRounds, 3 * (this->MaximumRefinementLevels + 1));
}

//------------------------------------------------------------------------------
void vtkLRSplineFitterBase::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Degree: " << this->Degree[0] << " " << this->Degree[1] << " " << this->Degree[2]
     << "\n";
  os << indent << "InitialNumberOfElements: " << this->InitialNumberOfElements[0] << " "
     << this->InitialNumberOfElements[1] << " " << this->InitialNumberOfElements[2] << "\n";
  os << indent << "Tolerance: " << this->Tolerance << "\n";
  os << indent
     << "ToleranceMode: " << (this->ToleranceMode == RELATIVE_TOLERANCE ? "Relative" : "Absolute")
     << "\n";
  os << indent << "MaximumNumberOfElements: " << this->MaximumNumberOfElements << "\n";
  os << indent << "MaximumRefinementLevels: " << this->MaximumRefinementLevels << "\n";
  os << indent << "Regularization: " << this->Regularization << "\n";
  os << indent
     << "OutputFieldName: " << (this->OutputFieldName ? this->OutputFieldName : "(input array's)")
     << "\n";
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "MaximumError: " << this->MaximumError << "\n";
  os << indent << "RMSError: " << this->RMSError << "\n";
  os << indent << "AbsoluteTolerance: " << this->AbsoluteTolerance << "\n";
  os << indent << "ToleranceMet: " << this->ToleranceMet << "\n";
  os << indent << "NumberOfElements: " << this->NumberOfElements << "\n";
  os << indent << "NumberOfBasisFunctions: " << this->NumberOfBasisFunctions << "\n";
  os << indent << "NumberOfRefinementLevels: " << this->NumberOfRefinementLevels << "\n";
  os << indent << "NumberOfIterations: " << this->NumberOfIterations << "\n";
  os << indent << "FitTime: " << this->FitTime << "\n";
}
