// SPDX-License-Identifier: BSD-3-Clause
// The halo of vtkStylizedLineMapper (Stoll §4.2) does what it is for: the
// lines are flat white, the halo red (HaloColorFromBackground off), the
// background black.
//  - it never covers its own line: a wavy line in the view plane rendered
//    with and without a halo shows exactly the same line pixels;
//  - it hides the parts of lines further behind than HaloDepthOffset radii:
//    where a line passes behind another one at 6 radii, the back line's
//    pixels next to the front line turn red (the halo band), about as many
//    as the band's width predicts;
//  - it does not hide lines nearer behind it than HaloDepthOffset: the same
//    crossing at 3 radii with an offset of 4 radii leaves the back line intact
//    except where the front line itself covers it;
//  - it follows the background by default, and the bounds grow by the halo;
//  - depth-dependent (Everts et al. 2009; offset 2 r, range 10 r): still never
//    over its own line; behind a crossing at a gap of g radii the hidden part
//    of the band, relative to a crossing far behind (full band), lies within
//    0.1 of clamp((g - 2 - b) / 10, 0, 1) for some b in [0, 1] (b: where on
//    the back line's profile, whose depth spans one radius); small gaps hide
//    less than large ones; a gap below the offset hides nothing.
// SPLINEVIZ_TEST_IMAGES=<dir> writes the renderings as PNG files.
#include "vtkStylizedLineMapper.h"

#include "SplineVizRenderingTestUtilities.h"
#include "SplineVizTestUtilities.h"
#include "StylizedLineTestScenes.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkMath.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <iostream>

namespace
{
const int Size = 300;
const double Radius = 0.1;

enum Kind
{
  BACKGROUND,
  LINE,
  HALO,
  OTHER
};

Kind Classify(const SplineVizTest::Frame& f, size_t pixel)
{
  const unsigned char* c = &f.RGB[3 * pixel];
  if (c[0] < 20 && c[1] < 20 && c[2] < 20)
  {
    return BACKGROUND;
  }
  if (c[0] > 235 && c[1] > 235 && c[2] > 235)
  {
    return LINE;
  }
  if (c[0] > 235 && c[1] < 20 && c[2] < 20)
  {
    return HALO;
  }
  return OTHER;
}

SplineVizTest::Frame Render(vtkRenderWindow* window, vtkPolyData* lines, double halo, double offset,
  const std::string& name, double background = 0.0, double depthRange = -1.0)
{
  vtkNew<vtkStylizedLineMapper> mapper;
  mapper->SetInputData(lines);
  mapper->SetRadiusArray("Radius");
  mapper->ScalarVisibilityOff();
  mapper->SetHaloWidth(halo);
  mapper->SetHaloDepthOffset(offset);
  mapper->HaloColorFromBackgroundOff();
  mapper->SetHaloColor(1.0, 0.0, 0.0);
  if (depthRange >= 0.0)
  {
    mapper->DepthDependentHaloOn();
    mapper->SetHaloDepthRange(depthRange);
  }
  if (background > 0.0)
  {
    mapper->HaloColorFromBackgroundOn();
  }
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(1.0, 1.0, 1.0);
  actor->GetProperty()->SetAmbient(1.0);
  actor->GetProperty()->SetDiffuse(0.0);
  actor->GetProperty()->SetSpecular(0.0);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->SetBackground(background, background, background);
  window->AddRenderer(renderer);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetPosition(0.0, 0.0, 10.0);
  camera->SetViewUp(0.0, 1.0, 0.0);
  camera->SetViewAngle(20.0);
  renderer->ResetCameraClippingRange(-3, 3, -3, 3, -3, 3);
  SplineVizTest::Frame frame = SplineVizTest::Grab(window);
  window->RemoveRenderer(renderer);
  StylizedLineTest::Save(frame, name);
  return frame;
}

/// Two straight lines crossing in the view: the front one along x at z = 0,
/// the back one along y at z = -depth.
vtkSmartPointer<vtkPolyData> Cross(double depth)
{
  std::vector<SplineVizTest::Vec4> front;
  std::vector<SplineVizTest::Vec4> back;
  for (int i = 0; i <= 20; ++i)
  {
    const double s = -1.4 + 0.14 * i;
    front.push_back({ s, 0.0, 0.0, Radius });
    back.push_back({ 0.0, s, -depth, Radius });
  }
  return SplineVizTest::MakePolylines({ front, back });
}
}

int TestStylizedLineHalo(int, char*[])
{
  SplineVizTestStatus status;
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(Size, Size);
  const size_t pixels = static_cast<size_t>(Size * Size);

  // 1. Never over its own line.
  std::vector<SplineVizTest::Vec4> wave;
  for (int i = 0; i <= 60; ++i)
  {
    const double x = -1.4 + 2.8 * i / 60.0;
    wave.push_back({ x, 0.6 * std::sin(3.0 * x), 0.2 * std::cos(2.0 * x), Radius });
  }
  auto waveLines = SplineVizTest::MakePolylines({ wave });
  const SplineVizTest::Frame plain = Render(window, waveLines, 0.0, 2.0, "halo-wave-off");
  const SplineVizTest::Frame haloed = Render(window, waveLines, 0.6, 2.0, "halo-wave-on");
  long linePixels = 0;
  long changed = 0;
  long haloPixels = 0;
  for (size_t i = 0; i < pixels; ++i)
  {
    const Kind before = Classify(plain, i);
    const Kind after = Classify(haloed, i);
    linePixels += before == LINE ? 1 : 0;
    changed += (before == LINE && after != LINE) ? 1 : 0;
    haloPixels += after == HALO ? 1 : 0;
  }
  std::cout << "own line: " << linePixels << " line pixels, " << changed << " changed by the halo; "
            << haloPixels << " halo pixels" << std::endl;
  SV_CHECK_MSG(status, changed == 0, changed << " pixels of the line are covered by its own halo");
  SV_CHECK_MSG(status, haloPixels > 0.3 * linePixels, "the halo is missing");

  // 2. Hides lines further behind than the offset.
  auto crossing = [&](double depth, double offset, const std::string& name)
  {
    auto lines = Cross(depth);
    const SplineVizTest::Frame off = Render(window, lines, 0.0, offset, name + "-off");
    const SplineVizTest::Frame on = Render(window, lines, 0.6, offset, name + "-on");
    long hidden = 0;
    for (size_t i = 0; i < pixels; ++i)
    {
      hidden += (Classify(off, i) == LINE && Classify(on, i) == HALO) ? 1 : 0;
    }
    return hidden;
  };
  // The band: 2 x 0.6 r wide, 2 r long (the back line's width), in pixels.
  const double pixelsPerUnit = Size / (2.0 * 10.0 * std::tan(vtkMath::RadiansFromDegrees(10.0)));
  const double band = 2.0 * 0.6 * Radius * 2.0 * Radius * pixelsPerUnit * pixelsPerUnit;
  const long farHidden = crossing(6.0 * Radius, 2.0, "halo-cross-far");
  std::cout << "crossing 6 r behind: " << farHidden << " back-line pixels hidden by the halo (band "
            << band << ")" << std::endl;
  SV_CHECK_MSG(status, farHidden > 0.6 * band && farHidden < 1.6 * band,
    "the halo must hide the line 6 r behind: " << farHidden << " pixels, band " << band);
  const long nearHidden = crossing(3.0 * Radius, 4.0, "halo-cross-near");
  std::cout << "crossing 3 r behind, offset 4 r: " << nearHidden << " pixels hidden" << std::endl;
  SV_CHECK_MSG(status, nearHidden == 0, "the halo hid a line nearer than its offset");

  // 4. Depth-dependent halos.
  const SplineVizTest::Frame dependent =
    Render(window, waveLines, 0.6, 2.0, "halo-wave-dependent", 0.0, 10.0);
  long dependentChanged = 0;
  for (size_t i = 0; i < pixels; ++i)
  {
    dependentChanged += (Classify(plain, i) == LINE && Classify(dependent, i) != LINE) ? 1 : 0;
  }
  SV_CHECK_MSG(status, dependentChanged == 0,
    dependentChanged << " pixels of the line are covered by its own depth-dependent halo");
  auto dependentHidden = [&](double gap)
  {
    auto lines = Cross(gap * Radius);
    const std::string name = "halo-dependent-" + std::to_string(static_cast<int>(gap));
    const SplineVizTest::Frame off = Render(window, lines, 0.0, 2.0, name + "-off");
    const SplineVizTest::Frame on = Render(window, lines, 0.6, 2.0, name + "-on", 0.0, 10.0);
    long hidden = 0;
    for (size_t i = 0; i < pixels; ++i)
    {
      hidden += (Classify(off, i) == LINE && Classify(on, i) == HALO) ? 1 : 0;
    }
    return hidden;
  };
  const long full = dependentHidden(30.0);
  SV_CHECK_MSG(status, full > 0.6 * band && full < 1.6 * band,
    "a depth-dependent halo 30 r in front: " << full << " pixels, band " << band);
  long previous = -1;
  for (double gap : { 1.5, 4.0, 7.0, 10.0 })
  {
    const long hidden = dependentHidden(gap);
    const double fraction = static_cast<double>(hidden) / std::max<long>(1, full);
    const double lo = std::min(1.0, std::max(0.0, (gap - 3.0) / 10.0)) - 0.1;
    const double hi = std::min(1.0, std::max(0.0, (gap - 2.0) / 10.0)) + 0.1;
    std::cout << "depth-dependent halo, gap " << gap << " r: " << hidden << " pixels hidden, "
              << fraction << " of the full band (expected " << lo + 0.1 << " to " << hi - 0.1 << ")"
              << std::endl;
    SV_CHECK_MSG(status, fraction >= lo && fraction <= hi,
      "gap " << gap << ": hidden fraction " << fraction << " outside [" << lo << ", " << hi << "]");
    SV_CHECK_MSG(status, hidden > previous || hidden == 0, "the halo does not grow with the gap");
    previous = hidden;
  }

  // 3. The background color by default; bounds with the halo.
  const SplineVizTest::Frame grayOff =
    Render(window, Cross(6.0 * Radius), 0.0, 2.0, "halo-gray-off", 0.5);
  const SplineVizTest::Frame grayOn =
    Render(window, Cross(6.0 * Radius), 0.6, 2.0, "halo-gray-on", 0.5);
  long grayHidden = 0;
  long red = 0;
  for (size_t i = 0; i < pixels; ++i)
  {
    const unsigned char* c = &grayOn.RGB[3 * i];
    const bool background =
      std::abs(c[0] - 128) < 4 && std::abs(c[1] - 128) < 4 && std::abs(c[2] - 128) < 4;
    grayHidden += (Classify(grayOff, i) == LINE && background) ? 1 : 0;
    red += Classify(grayOn, i) == HALO ? 1 : 0;
  }
  SV_CHECK_MSG(status, red == 0 && grayHidden > 0.6 * band,
    "the halo does not take the background color: " << grayHidden << " pixels hidden, " << red
                                                    << " red");
  vtkNew<vtkStylizedLineMapper> bounded;
  bounded->SetInputData(Cross(0.0));
  bounded->SetRadiusArray("Radius");
  double b0[6];
  bounded->GetBounds(b0);
  bounded->SetHaloWidth(1.0);
  double b1[6];
  bounded->GetBounds(b1);
  SV_CHECK_NEAR(status, b0[0] - b1[0], Radius, 1e-6);
  SV_CHECK_NEAR(status, b1[5] - b0[5], Radius, 1e-6);
  return status.Result();
}
