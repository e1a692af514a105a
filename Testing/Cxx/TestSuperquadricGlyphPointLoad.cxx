// Image regression test of vtkSuperquadricGlyphMapper on an indefinite
// tensor field: the Boussinesq stress tensors of vtkPointLoad (9 components,
// mixed-sign eigenvalues), left with the default policy (tensors with a
// negative eigenvalue are skipped: only the few positive semi-definite ones
// remain), right with absolute values; sizes normalized, colored by the
// effective stress through a lookup table.
#include "vtkSuperquadricGlyphMapper.h"
#include "PointLoadGlyphScene.h"

#include "vtkImageData.h"
#include "vtkLookupTable.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPointLoad.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"

#include <algorithm>
#include <iostream>
#include <vector>

int TestSuperquadricGlyphPointLoad(int argc, char* argv[])
{
  vtkNew<vtkPointLoad> load;
  load->SetLoadValue(100.0);
  load->SetSampleDimensions(7, 7, 7);
  load->ComputeEffectiveStressOn();
  load->SetModelBounds(-10, 10, -10, 10, -10, 10);
  load->Update();
  vtkImageData* stress = load->GetOutput();

  vtkNew<vtkRenderWindow> window;
  window->SetSize(640, 320);
  window->SetMultiSamples(0);
  vtkNew<vtkLookupTable> lut;
  lut->SetHueRange(0.66, 0.0);
  lut->Build();
  // color range: up to the 90th percentile (the load point is singular)
  std::vector<double> values;
  vtkDataArray* effective = stress->GetPointData()->GetScalars();
  for (vtkIdType i = 0; i < effective->GetNumberOfTuples(); ++i)
  {
    values.push_back(effective->GetTuple1(i));
  }
  std::sort(values.begin(), values.end());
  const double range[2] = { values.front(), values[values.size() * 9 / 10] };

  for (int v = 0; v < 2; ++v)
  {
    vtkNew<vtkSuperquadricGlyphMapper> mapper;
    mapper->SetInputConnection(load->GetOutputPort());
    mapper->SetNegativeEigenvaluePolicy(v == 0 ? vtkSuperquadricGlyphMapper::SKIP_NEGATIVE
                                               : vtkSuperquadricGlyphMapper::ABSOLUTE_VALUES);
    mapper->SetScaleMode(vtkSuperquadricGlyphMapper::SCALE_NORMALIZED);
    mapper->SetScaleFactor(1.4);
    mapper->SetGamma(3.0);
    mapper->SetGlyphColorMode(vtkSuperquadricGlyphMapper::COLOR_BY_SCALARS);
    mapper->SetScalarRange(range[0], range[1]);
    mapper->SetLookupTable(lut);
    sqtest::AddPointLoadView(window, load, mapper, v);
    window->Render();
    std::cout << (v == 0 ? "skip" : "absolute") << ": " << mapper->GetNumberOfGlyphs()
              << " glyphs uploaded" << std::endl;
  }

  vtkNew<vtkRenderWindowInteractor> interactor;
  interactor->SetRenderWindow(window);
  window->Render();
  const int result = vtkRegressionTestImageThreshold(window, 0.05);
  if (result == vtkRegressionTester::DO_INTERACTOR)
  {
    interactor->Start();
  }
  return result == vtkRegressionTester::FAILED ? 1 : 0;
}
