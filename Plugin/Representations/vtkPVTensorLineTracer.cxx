// SPDX-License-Identifier: BSD-3-Clause
#include "vtkPVTensorLineTracer.h"

#include "vtkCompositeDataSet.h"
#include "vtkDataObject.h"
#include "vtkDataSet.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"

#include <cstring>

vtkStandardNewMacro(vtkPVTensorLineTracer);

vtkPVTensorLineTracer::vtkPVTensorLineTracer() = default;

vtkPVTensorLineTracer::~vtkPVTensorLineTracer() = default;

void vtkPVTensorLineTracer::SetInputArrayToProcess(
  int idx, int port, int connection, int fieldAssociation, const char* name)
{
  if (idx != 1)
  {
    this->Superclass::SetInputArrayToProcess(idx, port, connection, fieldAssociation, name);
    return;
  }
  this->MaskIsNone = name && std::strcmp(name, vtkPVTensorLineTracer::GetNoneString()) == 0;
  if (!this->MaskIsNone)
  {
    this->Superclass::SetInputArrayToProcess(idx, port, connection, fieldAssociation, name);
    return;
  }
  // No selection: neither a name nor an attribute type.
  vtkInformation* info = this->GetInputArrayInformation(idx);
  if (info->Has(vtkDataObject::FIELD_NAME()) || info->Has(vtkDataObject::FIELD_ATTRIBUTE_TYPE()))
  {
    info->Remove(vtkDataObject::FIELD_NAME());
    info->Remove(vtkDataObject::FIELD_ATTRIBUTE_TYPE());
    this->Modified();
  }
}

int vtkPVTensorLineTracer::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkInformation* mask = this->GetInputArrayInformation(1);
  if (this->MaskIsNone && !mask->Has(vtkDataObject::FIELD_NAME()) &&
    !mask->Has(vtkDataObject::FIELD_ATTRIBUTE_TYPE()))
  {
    vtkDataObject* input = vtkDataObject::GetData(inputVector[0], 0);
    for (vtkDataSet* ds : vtkCompositeDataSet::GetDataSets(input))
    {
      if (ds->GetPointData()->GetAbstractArray(vtkPVTensorLineTracer::GetNoneString()))
      {
        vtkWarningMacro(<< "the input has a point array named '"
                        << vtkPVTensorLineTracer::GetNoneString()
                        << "', which the Mask Array list cannot tell from its entry for no mask: "
                           "traced without a mask; rename the array to use it as the mask");
        break;
      }
    }
  }
  return this->Superclass::RequestData(request, inputVector, outputVector);
}

void vtkPVTensorLineTracer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "MaskIsNone: " << this->MaskIsNone << "\n";
}
