// SPDX-License-Identifier: BSD-3-Clause
// Endpoint markers of the line renderers (vtkSplineTubeMapper's
// EndpointMarkers, shared by vtkRayCastTubeMapper, vtkTessellatedTubeMapper
// and vtkStylizedLineMapper) against an independent reference: the same
// lines without markers plus polygonal spheres (vtkSphereSource, 48 x 48)
// placed by the test at the ends of the curves, of 1.5 times the radius the
// test gives those points, in the markers' color. Scene: the synthetic curls
// (six lines with a radius array, one of them hidden by a visibility array)
// in a 500 x 500 window, multisampling off.
// Measures: the pixels of the markers' color (yellow: red and green well
// above blue; the lines are blue) in both images, compared with a one-pixel
// tolerance (SplineVizTest::CompareCoverage on the marker pixels); and the
// eye depth of the common marker pixels, within a quarter of the marker
// radius of the reference's.
// Targets: at most 3 % of either image's marker pixels farther than a pixel
// from the other's; depth within tolerance on 95 % of the common ones.
// The hidden line's markers are absent: 2 markers per shown line
// (GetNumberOfEndpointMarkers), no marker pixels near its ends.
// Negative controls, which must fail: markers of scale 1.2 against the
// reference's 1.5, and markers off (no marker pixels at all).
// SPLINEVIZ_TEST_IMAGES=<dir> writes the renderings as PNG files.
#include "TubeFidelityTestScenes.h"

#include "SplineVizRenderingTestUtilities.h"
#include "SplineVizTestUtilities.h"

#include "vtkActor.h"
#include "vtkAppendPolyData.h"
#include "vtkCamera.h"
#include "vtkCellData.h"
#include "vtkIntArray.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"

#include <cmath>
#include <iostream>
#include <string>
#include <vector>

namespace
{
using namespace TubeFidelity;

const int Size = 500;
const double MarkerColor[3] = { 1.0, 0.85, 0.0 };
const int Hidden = 1; // the curve hidden by the visibility array

/// The frame's marker pixels (yellow), as a frame whose depth is 1 elsewhere.
SplineVizTest::Frame MarkerPixels(const SplineVizTest::Frame& frame, long& count)
{
  SplineVizTest::Frame markers = frame;
  count = 0;
  for (size_t i = 0; i < frame.Depth.size(); ++i)
  {
    const int r = frame.RGB[3 * i];
    const int g = frame.RGB[3 * i + 1];
    const int b = frame.RGB[3 * i + 2];
    const bool yellow = r > 40 && g > 30 && b < r / 2 && b < g / 2;
    if (!yellow)
    {
      markers.Depth[i] = 1.0f;
    }
    count += yellow ? 1 : 0;
  }
  return markers;
}

vtkSmartPointer<vtkActor> LineActor(vtkMapper* mapper)
{
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.15, 0.3, 0.9);
  return actor;
}
}

int TestTubeEndpointMarkers(int, char*[])
{
  SplineVizTestStatus status;
  auto window = MakeWindow(Size);

  const Curves curves = SplineVizTest::Curls();
  auto lines = SplineVizTest::MakePolylines(curves);
  vtkNew<vtkIntArray> shown;
  shown->SetName("Shown");
  for (size_t c = 0; c < curves.size(); ++c)
  {
    shown->InsertNextValue(static_cast<int>(c) == Hidden ? 0 : 1);
  }
  lines->GetCellData()->AddArray(shown);
  double bounds[6];
  PaddedBounds(lines, bounds);
  const double direction[3] = { 4.0, 5.0, 9.0 };
  const double target[3] = { 0.0, 0.0, 0.0 };
  const auto setup = MakeCamera(bounds, direction, target, 1.0);

  // The reference spheres: at the ends of the shown curves, 1.5 radii.
  vtkNew<vtkAppendPolyData> spheres;
  double rMin = 1e30;
  for (size_t c = 0; c < curves.size(); ++c)
  {
    if (static_cast<int>(c) == Hidden)
    {
      continue;
    }
    for (const Vec4* end : { &curves[c].front(), &curves[c].back() })
    {
      vtkNew<vtkSphereSource> sphere;
      sphere->SetCenter((*end)[0], (*end)[1], (*end)[2]);
      sphere->SetRadius(1.5 * (*end)[3]);
      sphere->SetThetaResolution(48);
      sphere->SetPhiResolution(48);
      sphere->Update();
      spheres->AddInputData(sphere->GetOutput());
      rMin = std::min(rMin, 1.5 * (*end)[3]);
    }
  }
  spheres->Update();
  vtkNew<vtkPolyDataMapper> sphereMapper;
  sphereMapper->SetInputConnection(spheres->GetOutputPort());
  sphereMapper->ScalarVisibilityOff();
  vtkNew<vtkActor> sphereActor;
  sphereActor->SetMapper(sphereMapper);
  sphereActor->GetProperty()->SetColor(MarkerColor[0], MarkerColor[1], MarkerColor[2]);

  for (Renderer which : { RayCast, Tessellated, Stylized })
  {
    const std::string name = std::string("markers-") + RendererNames[which];
    auto plain = MakeMapper(which, lines);
    plain->SetVisibilityArray("Shown");
    auto withMarkers = MakeMapper(which, lines);
    withMarkers->SetVisibilityArray("Shown");
    withMarkers->EndpointMarkersOn();
    withMarkers->SetEndpointMarkerColor(MarkerColor[0], MarkerColor[1], MarkerColor[2]);

    vtkNew<vtkCamera> camera;
    const auto reference =
      RenderActors(window, { LineActor(plain), sphereActor }, setup, bounds, camera);
    const auto test = RenderActors(window, { LineActor(withMarkers) }, setup, bounds, camera);
    SplineVizTest::Save(reference, name + "-reference");
    SplineVizTest::Save(test, name);
    long refCount = 0;
    long testCount = 0;
    const auto refMarkers = MarkerPixels(reference, refCount);
    const auto testMarkers = MarkerPixels(test, testCount);
    const auto d = SplineVizTest::CompareCoverage(testMarkers, refMarkers, 1);
    std::vector<double> tolerance(test.Depth.size(), 0.25 * rMin);
    const auto m = SplineVizTest::Measure(testMarkers, refMarkers, camera, 0.0, &tolerance);
    std::cout << name << ": " << withMarkers->GetNumberOfEndpointMarkers() << " markers, "
              << testCount << " marker pixels (reference " << refCount << "), unexplained "
              << d.Unexplained[0] << " / " << d.Unexplained[1] << ", eye depth within "
              << 0.25 * rMin << " on " << 100.0 * m.DepthShare << " % of " << m.Common
              << " common pixels" << std::endl;
    const long shownLines = static_cast<long>(curves.size()) - 1;
    SV_CHECK_MSG(status, withMarkers->GetNumberOfEndpointMarkers() == 2 * shownLines,
      name << ": " << withMarkers->GetNumberOfEndpointMarkers() << " markers, not "
           << 2 * shownLines);
    SV_CHECK_MSG(status, refCount > 200, name << ": the reference shows " << refCount);
    SV_CHECK_MSG(status,
      d.Unexplained[0] <= 0.03 * testCount && d.Unexplained[1] <= 0.03 * refCount,
      name << ": marker pixels unexplained " << d.Unexplained[0] << " / " << d.Unexplained[1]);
    SV_CHECK_MSG(status, m.DepthShare >= 0.95,
      name << ": marker depth within tolerance on " << 100.0 * m.DepthShare << " %");

    // Negative controls: smaller markers, and none.
    withMarkers->SetEndpointMarkerScale(1.2);
    const auto smaller = RenderActors(window, { LineActor(withMarkers) }, setup, bounds, camera);
    long smallCount = 0;
    const auto ds =
      SplineVizTest::CompareCoverage(MarkerPixels(smaller, smallCount), refMarkers, 1);
    std::cout << "  negative control, scale 1.2: unexplained reference pixels " << ds.Unexplained[1]
              << " of " << refCount << std::endl;
    SV_CHECK_MSG(status, ds.Unexplained[1] > 0.03 * refCount,
      name << ": markers of scale 1.2 must fail, " << ds.Unexplained[1] << " unexplained");
    withMarkers->EndpointMarkersOff();
    const auto none = RenderActors(window, { LineActor(withMarkers) }, setup, bounds, camera);
    long noneCount = 0;
    MarkerPixels(none, noneCount);
    SV_CHECK_MSG(status, noneCount == 0 && withMarkers->GetNumberOfEndpointMarkers() == 0,
      name << ": markers off, " << noneCount << " marker pixels");
  }
  return status.Result();
}
