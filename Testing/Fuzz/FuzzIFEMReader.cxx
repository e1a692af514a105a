// SPDX-License-Identifier: BSD-3-Clause
// libFuzzer target: vtkIFEMReader on an in-memory HDF5 file (ReadFromInputString:
// HDF5's core driver with a file image), every time step of it (at most 4).
// The reader must either succeed with finite points or fail (RequestData
// returns 0) with a message and an empty output, and leave no HDF5 object
// open once it is deleted (HDF5's own losses on damaged files are suppressed
// in Testing/Sanitizers/lsan.supp; this checks SplineViz's handles).
#include "SplineVizFuzzCommon.h"

#include "vtkExecutive.h"
#include "vtkIFEMFile.h"
#include "vtkIFEMReader.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkObject.h"
#include "vtkPoints.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>

namespace
{
void CheckBlocks(vtkMultiBlockDataSet* out)
{
  for (unsigned int b = 0; b < out->GetNumberOfBlocks(); ++b)
  {
    auto* basis = vtkMultiBlockDataSet::SafeDownCast(out->GetBlock(b));
    if (!basis)
    {
      SplineVizFuzz::Fail("a basis block is not a multiblock");
    }
    for (unsigned int p = 0; p < basis->GetNumberOfBlocks(); ++p)
    {
      auto* grid = vtkUnstructuredGrid::SafeDownCast(basis->GetBlock(p));
      if (!grid)
      {
        SplineVizFuzz::Fail("a patch block is not an unstructured grid");
      }
      SplineVizFuzz::CheckPointsFinite(grid->GetPoints());
    }
  }
}
}

namespace
{
void ReadAll(const uint8_t* data, size_t size)
{
  vtkNew<vtkIFEMReader> reader;
  reader->ReadFromInputStringOn();
  reader->SetInputString(reinterpret_cast<const char*>(data), size);
  if (!reader->GetExecutive()->UpdateInformation())
  {
    SplineVizFuzz::CheckMessage(reader->GetLastErrorMessage());
    return;
  }
  const int steps = std::min(4, std::max(1, reader->GetNumberOfTimeSteps()));
  for (int s = 0; s < steps; ++s)
  {
    reader->UpdateTimeStep(reader->GetTimeStep(s));
    vtkMultiBlockDataSet* out = reader->GetOutput();
    if (!reader->GetLastErrorMessage()[0])
    {
      CheckBlocks(out);
    }
    else if (out->GetNumberOfBlocks() != 0)
    {
      SplineVizFuzz::Fail("the read failed but the output is not empty");
    }
  }
}
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  vtkObject::GlobalWarningDisplayOff(); // errors are expected; keep the run quiet
  ReadAll(data, size);
  if (vtkIFEMFile::GetNumberOfOpenObjects() != 0)
  {
    SplineVizFuzz::Fail("HDF5 objects are left open after the reader is deleted");
  }
  return 0;
}
