// Image regression test of the Schultz-Kindlmann glyphs
// (NegativeEigenvaluePolicy SCHULTZ_KINDLMANN) on the indefinite stress field
// of vtkPointLoad (the Boussinesq solution, 9 components, mixed-sign
// eigenvalues), the field TestSuperquadricGlyphPointLoad draws with the
// skip and absolute-value policies: left colored by the sign of the
// quadratic form x^T T x (orange tension, blue compression), right by the
// effective stress through a lookup table; sizes normalized. Also checks
// that every finite non-zero tensor gets a glyph (the skip policy keeps only
// the few definite ones). The shapes themselves are checked against an
// independent reference in TestSuperquadricGlyphSchultzKindlmann.
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

int TestSuperquadricGlyphPointLoadSchultzKindlmann(int argc, char* argv[])
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

  int failures = 0;
  for (int v = 0; v < 2; ++v)
  {
    vtkNew<vtkSuperquadricGlyphMapper> mapper;
    mapper->SetInputConnection(load->GetOutputPort());
    mapper->SetNegativeEigenvaluePolicyToSchultzKindlmann();
    mapper->SetScaleMode(vtkSuperquadricGlyphMapper::SCALE_NORMALIZED);
    mapper->SetScaleFactor(1.4);
    mapper->SetGamma(3.0);
    if (v == 0)
    {
      mapper->SetGlyphColorModeToQuadraticForm();
    }
    else
    {
      mapper->SetGlyphColorModeToScalars();
      mapper->SetScalarRange(range[0], range[1]);
      mapper->SetLookupTable(lut);
    }
    sqtest::AddPointLoadView(window, load, mapper, v);
    window->Render();
    const vtkIdType drawn = mapper->GetNumberOfGlyphs();
    const vtkIdType left = mapper->GetNumberOfInvalidTensors() + mapper->GetNumberOfZeroTensors();
    std::cout << (v == 0 ? "quadratic form" : "effective stress") << ": " << drawn << " glyphs, "
              << left << " invalid or zero tensors of " << stress->GetNumberOfPoints() << " points"
              << std::endl;
    if (drawn + left != stress->GetNumberOfPoints() || drawn < stress->GetNumberOfPoints() - 7)
    {
      std::cerr << "Schultz-Kindlmann: not every finite non-zero tensor got a glyph" << std::endl;
      ++failures;
    }
  }

  vtkNew<vtkRenderWindowInteractor> interactor;
  interactor->SetRenderWindow(window);
  window->Render();
  const int result = vtkRegressionTestImageThreshold(window, 0.05);
  if (result == vtkRegressionTester::DO_INTERACTOR)
  {
    interactor->Start();
  }
  return (result == vtkRegressionTester::FAILED || failures) ? 1 : 0;
}
