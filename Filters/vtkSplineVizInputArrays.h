// SPDX-License-Identifier: BSD-3-Clause
/**
 * An algorithm's input array `idx` selected by name, as
 * SetInputArrayToProcess(idx, port, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS,
 * name) sets it, with nullptr for no selection (vtkAlgorithm ignores a null
 * name): behind the filters' deprecated ArrayName / MaskArrayName setters
 * and getters (kept for one release) and their PrintSelf.
 *
 * Header-only, private to the module.
 */
#ifndef vtkSplineVizInputArrays_h
#define vtkSplineVizInputArrays_h

#include "vtkAlgorithm.h"
#include "vtkDataObject.h"
#include "vtkInformation.h"

namespace vtkSplineVizInputArrays
{
/// Select point array `name` as input array `idx` on `port`; nullptr clears the selection.
inline void SetName(vtkAlgorithm* algorithm, int idx, int port, const char* name)
{
  if (name)
  {
    algorithm->SetInputArrayToProcess(idx, port, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, name);
    return;
  }
  vtkInformation* info = algorithm->GetInputArrayInformation(idx);
  if (info->Has(vtkDataObject::FIELD_NAME()) || info->Has(vtkDataObject::FIELD_ATTRIBUTE_TYPE()))
  {
    info->Remove(vtkDataObject::FIELD_NAME());
    info->Remove(vtkDataObject::FIELD_ATTRIBUTE_TYPE());
    algorithm->Modified();
  }
}

/// The name selected as input array `idx`; nullptr when none is (or it is selected by attribute).
inline const char* GetName(vtkAlgorithm* algorithm, int idx)
{
  vtkInformation* info = algorithm->GetInputArrayInformation(idx);
  return info->Has(vtkDataObject::FIELD_NAME()) ? info->Get(vtkDataObject::FIELD_NAME()) : nullptr;
}
}

#endif
