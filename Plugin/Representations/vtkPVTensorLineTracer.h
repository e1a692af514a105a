// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkPVTensorLineTracer
 * @brief   vtkTensorLineTracer as ParaView's "Tensor Line Tracer" filter sets
 * it: the Mask Array's "None" entry is no mask.
 *
 * ParaView's array lists offer their none_string ("None") as the first entry
 * and pass it as the array name. This subclass turns that name, as input
 * array 1 (the mask), into no selection, so that vtkTensorLineTracer, which
 * reports a mask array the input does not have, never sees ParaView's label.
 * The deprecated 1-element MaskArray of older states reaches
 * SetInputArrayToProcess too (through SetMaskArrayName), so their "None" is no
 * mask as well. A point array that is really named "None" cannot be told from
 * the entry: the filter then runs without a mask and warns that the array
 * must be renamed to be used as the mask.
 */
#ifndef vtkPVTensorLineTracer_h
#define vtkPVTensorLineTracer_h

#include "SplineVizParaViewModule.h" // for export macro
#include "vtkTensorLineTracer.h"

class SPLINEVIZPARAVIEW_EXPORT vtkPVTensorLineTracer : public vtkTensorLineTracer
{
public:
  static vtkPVTensorLineTracer* New();
  vtkTypeMacro(vtkPVTensorLineTracer, vtkTensorLineTracer);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The entry of the Mask Array list that stands for no array ("None").
  static const char* GetNoneString() { return "None"; }

  using Superclass::SetInputArrayToProcess;
  /**
   * As the superclass, except that GetNoneString() as input array 1 (the
   * mask) clears its selection: no mask.
   */
  void SetInputArrayToProcess(
    int idx, int port, int connection, int fieldAssociation, const char* name) override;

protected:
  vtkPVTensorLineTracer();
  ~vtkPVTensorLineTracer() override;

  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  // Whether the mask was last set to GetNoneString() (and therefore cleared).
  bool MaskIsNone = false;

private:
  vtkPVTensorLineTracer(const vtkPVTensorLineTracer&) = delete;
  void operator=(const vtkPVTensorLineTracer&) = delete;
};

#endif
