// SPDX-License-Identifier: BSD-3-Clause
// libFuzzer target: vtkLRSplineReader's whole RequestData (format detection,
// parsing, Bezier extraction, point merging, the output grids) on in-memory
// input (ReadFromInputString). The reader must either succeed with finite
// points or fail (RequestData returns 0) with a message and an empty output.
#include "SplineVizFuzzCommon.h"

#include "vtkExecutive.h"
#include "vtkLRSplineReader.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkObject.h"
#include "vtkPoints.h"
#include "vtkUnstructuredGrid.h"

#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  vtkObject::GlobalWarningDisplayOff(); // errors are expected; keep the run quiet
  vtkNew<vtkLRSplineReader> reader;
  reader->ReadFromInputStringOn();
  reader->SetInputString(reinterpret_cast<const char*>(data), size);
  reader->SetPhysicalBounds(-1, 1, -2, 2, 0, 10);
  const int ok = reader->GetExecutive()->Update();
  vtkMultiBlockDataSet* out = reader->GetOutput();
  if (!ok)
  {
    SplineVizFuzz::CheckMessage(reader->GetLastErrorMessage());
    if (out->GetNumberOfBlocks() != 0)
    {
      SplineVizFuzz::Fail("the read failed but the output is not empty");
    }
    return 0;
  }
  for (unsigned int b = 0; b < out->GetNumberOfBlocks(); ++b)
  {
    auto* grid = vtkUnstructuredGrid::SafeDownCast(out->GetBlock(b));
    if (!grid)
    {
      SplineVizFuzz::Fail("a block is not an unstructured grid");
    }
    SplineVizFuzz::CheckPointsFinite(grid->GetPoints());
  }
  return 0;
}
