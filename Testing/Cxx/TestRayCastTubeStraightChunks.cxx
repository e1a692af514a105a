// SPDX-License-Identifier: BSD-3-Clause
// The ray-cast tubes draw the chunks that are straight in the view with a
// second program without root finding (vtkRayCastTubeMapper::
// StraightChunkProgram). That must not change the picture: with it on and
// off the colors and depths are the same, pixel for pixel (up to rounding
// ties), on a synthetic tractogram with curled streamlines (segments that
// need the root finding) colored by a scalar, from afar in perspective, in
// parallel projection, close up, with the camera among the lines and
// translucent; and both programs must be used there (else the comparison
// would prove nothing).
//
// Negative control: a classification without its margin and ten times too
// lenient sends curved chunks to the straight program; the same comparison
// must see it.
#include "vtkRayCastTubeMapper.h"
#include "vtkSyntheticTractogramSource.h"

#include "SplineVizRenderingTestUtilities.h"
#include "SplineVizTestUtilities.h"

#include "vtkAppendPolyData.h"
#include "vtkDoubleArray.h"
#include "vtkLookupTable.h"
#include "vtkPointData.h"
#include "vtkProperty.h"

#include <algorithm>
#include <cmath>
#include <iostream>

using namespace SplineVizTest;

namespace
{
const double BackgroundColor[3] = { 0.1, 0.1, 0.12 };
const int Background[3] = { 26, 26, 31 }; // 255 * BackgroundColor, rounded

/// Coarse helices (12 points a turn) whose segments bend far more than
/// StraightTolerance allows, with a scalar (FA, as the tractogram's) along them.
vtkSmartPointer<vtkPolyData> CurledLines()
{
  std::vector<std::vector<Vec4>> curves;
  for (int curl = 0; curl < 6; ++curl)
  {
    std::vector<Vec4> curve;
    for (int i = 0; i < 40; ++i)
    {
      const double angle = 2.0 * M_PI * i / 12.0;
      curve.push_back({ -10.0 + 4.0 * curl + 1.5 * std::cos(angle), -8.0 + 0.45 * i,
        1.5 * std::sin(angle), 0.25 });
    }
    curves.push_back(curve);
  }
  vtkSmartPointer<vtkPolyData> curls = MakePolylines(curves);
  vtkNew<vtkDoubleArray> scalars;
  scalars->SetName("FA");
  for (const auto& curve : curves)
  {
    for (size_t i = 0; i < curve.size(); ++i)
    {
      scalars->InsertNextValue(0.2 + 0.7 * i / (curve.size() - 1.0));
    }
  }
  curls->GetPointData()->SetScalars(scalars);
  return curls;
}
}

int TestRayCastTubeStraightChunks(int, char*[])
{
  SplineVizTestStatus status;
  vtkNew<vtkSyntheticTractogramSource> source;
  source->SetNumberOfStreamlines(600);
  source->SetNumberOfBundles(10);
  source->SetMinimumPoints(30);
  source->SetMaximumPoints(60);
  source->SetBrainRadii(15.0, 18.0, 12.0);
  source->SetBundleRadiusRange(1.0, 2.5);
  source->Update();
  vtkNew<vtkAppendPolyData> append;
  append->AddInputConnection(source->GetOutputPort());
  append->AddInputData(CurledLines());
  append->Update();

  vtkNew<vtkLookupTable> lut;
  lut->SetHueRange(0.66, 0.0);
  lut->Build();
  vtkNew<vtkRayCastTubeMapper> mapper;
  mapper->SetInputConnection(append->GetOutputPort());
  mapper->SetRadius(0.25);
  mapper->SetLookupTable(lut);
  mapper->SetScalarRange(0.2, 0.9);
  mapper->InteractiveSubsetOff();
  vtkNew<vtkActor> tubes;
  tubes->SetMapper(mapper);
  tubes->GetProperty()->SetSpecular(0.3);
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(BackgroundColor);
  renderer->AddActor(tubes);
  vtkNew<vtkRenderWindow> window;
  window->SetSize(400, 320);
  window->SetMultiSamples(0);
  window->AddRenderer(renderer);
  auto view = [&](int parallel, double distance) { SetOrbitView(renderer, parallel, distance); };

  // One program, then two; the frame with two must be the one-program frame.
  auto compare = [&](const std::string& what, bool bothUsed)
  {
    mapper->StraightChunkProgramOff();
    const Frame one = Grab(window);
    SV_CHECK_MSG(status, mapper->GetLastNumberOfStraightChunks() == 0,
      what << ": the straight program is used while it is off");
    mapper->StraightChunkProgramOn();
    const Frame two = Grab(window);
    const vtkIdType straight = mapper->GetLastNumberOfStraightChunks();
    const vtkIdType full = mapper->GetLastNumberOfRootFindingChunks();
    const PixelDifference d = ComparePixels(one, two, Background);
    std::cout << what << ": " << straight << " chunks straight, " << full
              << " with root finding; covered " << d.Covered << " px, color differs on " << d.Color
              << ", depth on " << d.Depth << std::endl;
    SV_CHECK_MSG(status, !bothUsed || (straight > 0 && full > 0),
      what << ": " << straight << " straight and " << full << " root-finding chunks");
    SV_CHECK_MSG(status, d.Covered > 3000, what << ": too little covered: " << d.Covered);
    // Equal up to rounding ties (the two programs draw in another order).
    SV_CHECK_MSG(status, d.Color <= d.Covered / 5000,
      what << ": the straight program changes the color of " << d.Color << " pixels");
    SV_CHECK_MSG(status, d.Depth <= d.Covered / 5000,
      what << ": the straight program changes the depth of " << d.Depth << " pixels");
    return one;
  };

  view(0, 70.0);
  const Frame reference = compare("perspective", true);
  view(1, 70.0);
  compare("parallel", true);
  view(0, 30.0);
  compare("close up", true);
  view(0, 6.0);
  compare("camera among the lines", true);
  view(0, 30.0);
  tubes->GetProperty()->SetOpacity(0.6);
  compare("translucent", true);
  tubes->GetProperty()->SetOpacity(1.0);

  // Negative control: no margin, thresholds ten times too lenient.
  view(0, 70.0);
  mapper->SetStraightChunkMargin(10.0);
  const Frame wrong = Grab(window);
  mapper->SetStraightChunkMargin(0.9);
  const PixelDifference d = ComparePixels(reference, wrong, Background);
  std::cout << "negative control (margin 10): " << mapper->GetLastNumberOfRootFindingChunks()
            << " chunks with root finding; color differs on " << d.Color << " px, depth on "
            << d.Depth << std::endl;
  SV_CHECK_MSG(status, d.Color > d.Covered / 1000 || d.Depth > d.Covered / 1000,
    "the comparison cannot tell curved chunks drawn as straight: " << d.Color << " pixels");
  return status.Result();
}
