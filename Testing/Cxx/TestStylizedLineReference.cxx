// SPDX-License-Identifier: BSD-3-Clause
// vtkStylizedLineMapper against an independent polygonal reference: the same
// polylines through vtkTubeFilter (64 sides, flat caps), both rendered with
// multisampling off in the same window and camera (StylizedLineTestScenes.h).
//
// - coverage IoU >= 0.95 at a far view (lines 4-6 pixels wide), a whole-scene
//   view and a close-up of the curls, and at a view looking down a bundle of
//   lines (most tangents toward the eye) with the fix-up on;
// - the same end-on view with the fix-up off must lose coverage (miss at
//   least 3 times as many of the reference's pixels, and at least 1 % of
//   them): the fix-up is what closes the holes; there the eye depth agrees
//   within a quarter radius on >= 80 % of the common pixels (without the
//   fix-up's cylinders, or with their front faces culled instead of their
//   back faces, 59 %; without the fix-up 30 %);
// - depth: on the common pixels of the close-up the eye depth agrees with
//   the reference within a quarter of the smallest radius on >= 90 % of them;
//   without the depth correction the share must be lower;
// - lines through an opaque sphere: of the pixels where the sphere is and a
//   line is seen in either image, at most 2 % show the other object than the
//   reference; without the depth correction at least twice as many;
// - stability: turning the camera by 0.1 degree around a view along a
//   ring's tangent changes the color (by more than 32 levels) of hardly more
//   pixels with the fix-up on than in the reference (at most twice as many,
//   plus 0.1 % of the covered pixels); without the fix-up (negative control)
//   Stoll's flipping artifact (Fig. 6) must break that bound.
// SPLINEVIZ_TEST_IMAGES=<dir> writes the renderings as PNG files.
#include "vtkStylizedLineMapper.h"

#include "SplineVizTestUtilities.h"
#include "StylizedLineTestScenes.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkSplineTubeCore.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"

#include <functional>
#include <iostream>

namespace
{
const int Size = 400;

struct Scene
{
  vtkSmartPointer<vtkPolyData> Lines;
  vtkSmartPointer<vtkPolyData> Reference;
  double MinRadius;
};

Scene MakeScene(const std::vector<std::vector<SplineVizTest::Vec4>>& curves)
{
  Scene scene;
  scene.Lines = SplineVizTest::MakePolylines(curves);
  scene.Reference = StylizedLineTest::PolylineReferenceTubes(scene.Lines);
  scene.MinRadius = 1e30;
  for (const auto& curve : curves)
  {
    for (const auto& p : curve)
    {
      scene.MinRadius = std::min(scene.MinRadius, p[3]);
    }
  }
  return scene;
}

using SplineVizTest::CameraSetup;
using SplineVizTest::Render;

vtkSmartPointer<vtkStylizedLineMapper> MakeMapper(vtkPolyData* lines)
{
  auto mapper = vtkSmartPointer<vtkStylizedLineMapper>::New();
  mapper->SetInputData(lines);
  mapper->SetRadiusArray("Radius");
  mapper->ScalarVisibilityOff();
  return mapper;
}
}

int TestStylizedLineReference(int, char*[])
{
  SplineVizTestStatus status;
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(Size, Size);

  Scene curls = MakeScene(StylizedLineTest::Curls());
  Scene bundle = MakeScene(StylizedLineTest::Bundle());

  auto compare = [&](const std::string& name, const Scene& scene, const CameraSetup& setup,
                   const std::function<void(vtkStylizedLineMapper*)>& configure,
                   StylizedLineTest::Measures* out)
  {
    double bounds[6];
    scene.Reference->GetBounds(bounds);
    vtkNew<vtkPolyDataMapper> reference;
    reference->SetInputData(scene.Reference);
    reference->ScalarVisibilityOff();
    auto mapper = MakeMapper(scene.Lines);
    if (configure)
    {
      configure(mapper);
    }
    vtkNew<vtkCamera> camera;
    const SplineVizTest::Frame ref = Render(window, reference, setup, bounds, camera);
    const SplineVizTest::Frame test = Render(window, mapper, setup, bounds, camera);
    StylizedLineTest::Save(ref, name + "-reference");
    StylizedLineTest::Save(test, name);
    const StylizedLineTest::Measures m =
      StylizedLineTest::Measure(test, ref, camera, 0.25 * scene.MinRadius);
    std::cout << name << ": covered " << m.Covered[0] << " (reference " << m.Covered[1] << "), IoU "
              << m.IoU << ", eye depth within r/4 on " << 100.0 * m.DepthShare << " % of "
              << m.Common << " common pixels; fixed-up segments "
              << mapper->GetNumberOfFixedUpSegments() << " of "
              << mapper->GetTubeCore()->GetNumberOfSegments() << std::endl;
    if (out)
    {
      *out = m;
    }
    return m;
  };

  // The curls from a general direction: far (lines 4-6 pixels wide), the
  // whole scene, and a close-up.
  auto general = [](double zoom)
  {
    return [zoom](vtkCamera* c)
    {
      c->SetFocalPoint(0.0, 0.0, 0.0);
      c->SetPosition(4.0, 5.0, 9.0);
      c->SetViewUp(0.0, 1.0, 0.0);
      c->SetViewAngle(30.0);
      c->Zoom(zoom);
    };
  };
  const auto far = compare("curls-far", curls, general(0.6), nullptr, nullptr);
  SV_CHECK_MSG(status, far.IoU >= 0.95, "far view IoU " << far.IoU);
  const auto whole = compare("curls-whole", curls, general(1.1), nullptr, nullptr);
  SV_CHECK_MSG(status, whole.IoU >= 0.95, "whole-scene IoU " << whole.IoU);
  const auto close = compare("curls-close", curls, general(4.0), nullptr, nullptr);
  SV_CHECK_MSG(status, close.IoU >= 0.95, "close-up IoU " << close.IoU);
  SV_CHECK_MSG(status, close.DepthShare >= 0.90,
    "close-up: eye depth within r/4 on " << 100.0 * close.DepthShare << " % (at least 90 %)");
  const auto flat = compare(
    "curls-close-nodepth", curls, general(4.0),
    [](vtkStylizedLineMapper* m) { m->DepthCorrectionOff(); }, nullptr);
  SV_CHECK_MSG(status, flat.DepthShare < close.DepthShare - 0.05,
    "without depth correction the depth must agree less: " << 100.0 * flat.DepthShare << " % vs "
                                                           << 100.0 * close.DepthShare << " %");

  // Lines through an opaque sphere (red; the lines white, unlit): which of
  // the two is seen at each pixel must agree with the reference where the
  // lines enter the sphere, and agree less without the depth correction.
  auto sphereScene = [&](const std::string& name, vtkMapper* lines)
  {
    vtkNew<vtkSphereSource> sphere;
    sphere->SetCenter(-0.2, 0.3, 0.0);
    sphere->SetRadius(0.8);
    sphere->SetThetaResolution(128);
    sphere->SetPhiResolution(128);
    vtkNew<vtkPolyDataMapper> sphereMapper;
    sphereMapper->SetInputConnection(sphere->GetOutputPort());
    vtkNew<vtkActor> sphereActor;
    sphereActor->SetMapper(sphereMapper);
    sphereActor->GetProperty()->SetColor(1.0, 0.0, 0.0);
    sphereActor->GetProperty()->SetAmbient(1.0);
    sphereActor->GetProperty()->SetDiffuse(0.0);
    vtkNew<vtkRenderer> renderer;
    renderer->AddActor(sphereActor);
    vtkNew<vtkActor> lineActor;
    if (lines)
    {
      lineActor->SetMapper(lines);
      lineActor->GetProperty()->SetColor(1.0, 1.0, 1.0);
      lineActor->GetProperty()->SetAmbient(1.0);
      lineActor->GetProperty()->SetDiffuse(0.0);
      renderer->AddActor(lineActor);
    }
    window->AddRenderer(renderer);
    general(2.0)(renderer->GetActiveCamera());
    double bounds[6];
    curls.Reference->GetBounds(bounds);
    renderer->ResetCameraClippingRange(bounds);
    SplineVizTest::Frame frame = SplineVizTest::Grab(window);
    window->RemoveRenderer(renderer);
    StylizedLineTest::Save(frame, name);
    return frame;
  };
  vtkNew<vtkPolyDataMapper> referenceLines;
  referenceLines->SetInputData(curls.Reference);
  referenceLines->ScalarVisibilityOff();
  const SplineVizTest::Frame sphereAlone = sphereScene("sphere-alone", nullptr);
  const SplineVizTest::Frame sphereRef = sphereScene("sphere-reference", referenceLines);
  auto sphereMismatch = [&](bool correction)
  {
    auto mapper = MakeMapper(curls.Lines);
    mapper->SetDepthCorrection(correction);
    const SplineVizTest::Frame frame =
      sphereScene(correction ? "sphere" : "sphere-nodepth", mapper);
    // Where the sphere is and a line is seen in either image, whether the
    // sphere or the line is in front.
    long contested = 0;
    long differ = 0;
    for (size_t i = 0; i + 2 < frame.RGB.size(); i += 3)
    {
      const bool sphereThere = sphereAlone.RGB[i] > 128;
      const bool refLine = sphereRef.RGB[i + 1] > 128;
      const bool testLine = frame.RGB[i + 1] > 128;
      if (sphereThere && (refLine || testLine))
      {
        ++contested;
        differ += refLine != testLine ? 1 : 0;
      }
    }
    std::cout << "lines through a sphere" << (correction ? "" : " without depth correction") << ": "
              << differ << " of " << contested
              << " pixels where lines and sphere compete show the other object than the reference"
              << std::endl;
    return static_cast<double>(differ) / std::max<long>(contested, 1);
  };
  const double withCorrection = sphereMismatch(true);
  const double withoutCorrection = sphereMismatch(false);
  SV_CHECK_MSG(status, withCorrection <= 0.02,
    "lines through a sphere: " << 100.0 * withCorrection << " % of the pixels differ");
  SV_CHECK_MSG(status, withoutCorrection >= 2.0 * withCorrection + 0.01,
    "the depth correction must matter at the sphere: " << 100.0 * withoutCorrection << " % vs "
                                                       << 100.0 * withCorrection << " %");

  // Looking down the bundle (along -x, slightly off the axis).
  auto endOn = [](double turn)
  {
    return [turn](vtkCamera* c)
    {
      c->SetFocalPoint(0.0, 0.0, 0.0);
      c->SetPosition(7.0, 0.15, 0.1);
      c->SetViewUp(0.0, 1.0, 0.0);
      c->SetViewAngle(30.0);
      c->Azimuth(turn);
    };
  };
  const auto on = compare("bundle-end-on", bundle, endOn(0.0), nullptr, nullptr);
  SV_CHECK_MSG(status, on.IoU >= 0.95, "end-on view with the fix-up: IoU " << on.IoU);
  const auto off = compare(
    "bundle-end-on-nofixup", bundle, endOn(0.0), [](vtkStylizedLineMapper* m) { m->FixUpOff(); },
    nullptr);
  const long missingOn = on.Covered[1] - on.Common;
  const long missingOff = off.Covered[1] - off.Common;
  std::cout << "end-on: reference pixels missed " << missingOn << " with the fix-up, " << missingOff
            << " without" << std::endl;
  SV_CHECK_MSG(status, missingOff >= 3 * missingOn && missingOff >= 0.01 * on.Covered[1],
    "without the fix-up the end-on view must lose coverage: " << missingOff << " pixels missed vs "
                                                              << missingOn);
  SV_CHECK_MSG(status, on.DepthShare >= 0.80,
    "end-on view with the fix-up: eye depth within r/4 on " << 100.0 * on.DepthShare
                                                            << " % (at least 80 %)");
  SV_CHECK_MSG(status, off.DepthShare < on.DepthShare - 0.2,
    "without the fix-up the end-on depth must agree less: " << 100.0 * off.DepthShare << " % vs "
                                                            << 100.0 * on.DepthShare << " %");

  // Stability near the singular view: the ring seen along its tangent at
  // (1, 0, 0), the camera turned by 0.1 degree.
  Scene ring = MakeScene(StylizedLineTest::Ring());
  auto alongRing = [](double turn)
  {
    return [turn](vtkCamera* c)
    {
      c->SetFocalPoint(1.0, 0.0, 0.0);
      c->SetPosition(1.0, 0.01, 4.0);
      c->SetViewUp(0.0, 1.0, 0.0);
      c->SetViewAngle(20.0);
      c->Azimuth(turn);
    };
  };
  auto turned = [&](int which, double turn)
  {
    double bounds[6];
    ring.Reference->GetBounds(bounds);
    vtkNew<vtkPolyDataMapper> reference;
    reference->SetInputData(ring.Reference);
    reference->ScalarVisibilityOff();
    auto mapper = MakeMapper(ring.Lines);
    mapper->SetFixUp(which == 1);
    vtkNew<vtkCamera> camera;
    SplineVizTest::Frame frame =
      Render(window, which == 0 ? static_cast<vtkMapper*>(reference) : mapper.Get(),
        alongRing(turn), bounds, camera);
    StylizedLineTest::Save(frame, "ring-" + std::to_string(which) + "-" + std::to_string(turn));
    return frame;
  };
  long changed[3];
  long covered = 0;
  for (int which = 0; which < 3; ++which)
  {
    const SplineVizTest::Frame before = turned(which, 0.0);
    changed[which] = StylizedLineTest::ColorChanges(before, turned(which, 0.1), 32);
    if (which == 0)
    {
      covered = StylizedLineTest::CoverageChanges(before,
        SplineVizTest::Frame{
          before.Width, before.Height, {}, std::vector<float>(before.Depth.size(), 1.0f) });
    }
  }
  std::cout << "0.1 degree turn of the view along the ring: " << changed[1]
            << " pixels change color with the fix-up, " << changed[2] << " without, " << changed[0]
            << " in the reference (of " << covered << " covered)" << std::endl;
  auto stable = [&](long n) { return n <= 2 * changed[0] + 0.001 * covered; };
  SV_CHECK_MSG(status, stable(changed[1]),
    "0.1 degree changes " << changed[1] << " pixels with the fix-up, " << changed[0]
                          << " in the reference");
  SV_CHECK_MSG(status, !stable(changed[2]),
    "negative control: without the fix-up the same turn must change many pixels (" << changed[2]
                                                                                   << ")");
  return status.Result();
}
