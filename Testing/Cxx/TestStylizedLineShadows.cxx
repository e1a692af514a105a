// SPDX-License-Identifier: BSD-3-Clause
// Shadows of vtkStylizedLineMapper (Stoll §4.2), both ways:
//  - its own shadow map (Shadows on): three lines along x, A above B, C
//    beside B, and a directional scene light from above; B is darkened (its
//    mean gray drops by at least 20 %), A and C keep their brightness (within
//    2 %); without a scene light the virtual light above the camera casts
//    shadows too (at least 2 % of the line pixels darker by 20 levels);
//  - inside VTK's vtkShadowMapPass (a spotlight above and in front): the
//    lines cast shadows on a plane below them: many plane pixels are darker
//    than with the lines hidden from the light's pass (at least 2 % of the
//    image by 30 gray levels).
// SPLINEVIZ_TEST_IMAGES=<dir> writes the renderings as PNG files.
#include "vtkStylizedLineMapper.h"

#include "SplineVizRenderingTestUtilities.h"
#include "SplineVizTestUtilities.h"
#include "StylizedLineTestScenes.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCameraPass.h"
#include "vtkLight.h"
#include "vtkPlaneSource.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderPassCollection.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSequencePass.h"
#include "vtkShadowMapBakerPass.h"
#include "vtkShadowMapPass.h"

#include <iostream>

namespace
{
const int Size = 300;

/// Lines along x: A at y = 1, B below it at y = 0, C beside B at z = 0.8.
vtkSmartPointer<vtkPolyData> Lines(int only)
{
  std::vector<std::vector<SplineVizTest::Vec4>> curves;
  for (int k = 0; k < 3; ++k)
  {
    if (only >= 0 && k != only)
    {
      continue;
    }
    std::vector<SplineVizTest::Vec4> line;
    for (int i = 0; i <= 20; ++i)
    {
      line.push_back({ -1.5 + 0.15 * i, k == 0 ? 1.0 : 0.0, k == 2 ? 0.8 : 0.0, 0.12 });
    }
    curves.push_back(line);
  }
  return SplineVizTest::MakePolylines(curves);
}

/// Mean gray of the pixels of `frame` set in `mask`.
double MeanGray(const SplineVizTest::Frame& frame, const std::vector<bool>& mask)
{
  double sum = 0.0;
  long n = 0;
  for (size_t i = 0; i < mask.size(); ++i)
  {
    if (mask[i])
    {
      sum += (frame.RGB[3 * i] + frame.RGB[3 * i + 1] + frame.RGB[3 * i + 2]) / 3.0;
      ++n;
    }
  }
  return n > 0 ? sum / n : 0.0;
}

SplineVizTest::Frame Render(vtkRenderWindow* window, vtkPolyData* lines, bool shadows,
  bool sceneLight, const std::string& name)
{
  vtkNew<vtkStylizedLineMapper> mapper;
  mapper->SetInputData(lines);
  mapper->SetRadiusArray("Radius");
  mapper->SetShadows(shadows);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.9, 0.9, 0.9);
  actor->GetProperty()->SetAmbient(0.1);
  actor->GetProperty()->SetDiffuse(0.9);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  if (sceneLight)
  {
    vtkNew<vtkLight> light;
    light->SetLightTypeToSceneLight();
    light->SetPositional(false);
    light->SetPosition(0.0, 10.0, 0.0);
    light->SetFocalPoint(0.0, 0.0, 0.0);
    renderer->AddLight(light);
  }
  window->AddRenderer(renderer);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetFocalPoint(0.0, 0.5, 0.3);
  camera->SetPosition(0.0, 3.0, 6.0);
  camera->SetViewUp(0.0, 1.0, 0.0);
  renderer->ResetCameraClippingRange(-3, 3, -3, 3, -3, 3);
  SplineVizTest::Frame frame = SplineVizTest::Grab(window);
  window->RemoveRenderer(renderer);
  StylizedLineTest::Save(frame, name);
  return frame;
}

std::vector<bool> Covered(const SplineVizTest::Frame& f)
{
  std::vector<bool> mask(static_cast<size_t>(f.Width * f.Height));
  for (size_t i = 0; i < mask.size(); ++i)
  {
    mask[i] = f.Depth[i] < 1.0f;
  }
  return mask;
}
}

int TestStylizedLineShadows(int, char*[])
{
  SplineVizTestStatus status;
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(Size, Size);

  // The pixels of each line that no other line covers.
  std::vector<bool> masks[3];
  for (int k = 0; k < 3; ++k)
  {
    masks[k] = Covered(Render(window, Lines(k), false, true, "shadow-line-" + std::to_string(k)));
  }
  for (int k = 0; k < 3; ++k)
  {
    for (size_t i = 0; i < masks[k].size(); ++i)
    {
      masks[k][i] = masks[k][i] && !masks[(k + 1) % 3][i] && !masks[(k + 2) % 3][i];
    }
  }
  auto all = Lines(-1);
  const SplineVizTest::Frame plain = Render(window, all, false, true, "shadow-off");
  const SplineVizTest::Frame shaded = Render(window, all, true, true, "shadow-on");
  double before[3];
  double after[3];
  for (int k = 0; k < 3; ++k)
  {
    before[k] = MeanGray(plain, masks[k]);
    after[k] = MeanGray(shaded, masks[k]);
    std::cout << "line "
              << "ABC"[k] << ": mean gray " << before[k] << " without shadows, " << after[k]
              << " with" << std::endl;
  }
  SV_CHECK_MSG(status, after[1] < 0.8 * before[1], "the line below is not in the shadow");
  SV_CHECK_MSG(status, std::abs(after[0] - before[0]) < 0.02 * before[0],
    "the upper line changed with shadows");
  SV_CHECK_MSG(status, std::abs(after[2] - before[2]) < 0.02 * before[2],
    "the line beside changed with shadows");

  // No scene light: the virtual light above the camera casts shadows too
  // (somewhere on the lines, by at least 20 gray levels).
  const SplineVizTest::Frame virtualOff = Render(window, all, false, false, "shadow-virtual-off");
  const SplineVizTest::Frame virtualOn = Render(window, all, true, false, "shadow-virtual-on");
  long linePixels = 0;
  long darkened = 0;
  for (size_t i = 0; i < masks[0].size(); ++i)
  {
    if (virtualOff.Depth[i] < 1.0f)
    {
      ++linePixels;
      const int a = virtualOff.RGB[3 * i] + virtualOff.RGB[3 * i + 1] + virtualOff.RGB[3 * i + 2];
      const int b = virtualOn.RGB[3 * i] + virtualOn.RGB[3 * i + 1] + virtualOn.RGB[3 * i + 2];
      darkened += (a - b) > 60 ? 1 : 0;
    }
  }
  std::cout << "virtual light: " << darkened << " of " << linePixels << " line pixels in a shadow"
            << std::endl;
  SV_CHECK_MSG(status, darkened > 0.02 * linePixels, "no shadow from the virtual light");

  // Inside vtkShadowMapPass: the lines' shadows on a plane below.
  auto passRender = [&](bool linesCastShadows, const std::string& name)
  {
    vtkNew<vtkStylizedLineMapper> mapper;
    mapper->SetInputData(all);
    mapper->SetRadiusArray("Radius");
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->SetVisibility(true);
    vtkNew<vtkPlaneSource> plane;
    plane->SetOrigin(-2.5, -0.6, -2.5);
    plane->SetPoint1(2.5, -0.6, -2.5);
    plane->SetPoint2(-2.5, -0.6, 2.5);
    plane->SetResolution(40, 40);
    vtkNew<vtkPolyDataMapper> planeMapper;
    planeMapper->SetInputConnection(plane->GetOutputPort());
    vtkNew<vtkActor> planeActor;
    planeActor->SetMapper(planeMapper);
    vtkNew<vtkRenderer> renderer;
    renderer->AddActor(planeActor);
    if (linesCastShadows)
    {
      renderer->AddActor(actor);
    }
    renderer->AutomaticLightCreationOff();
    vtkNew<vtkLight> light;
    light->SetPositional(true);
    light->SetPosition(0.0, 6.0, 3.0);
    light->SetFocalPoint(0.0, 0.0, 0.0);
    light->SetConeAngle(40.0);
    renderer->AddLight(light);
    vtkNew<vtkShadowMapPass> shadows;
    vtkNew<vtkSequencePass> sequence;
    vtkNew<vtkRenderPassCollection> passes;
    passes->AddItem(shadows->GetShadowMapBakerPass());
    passes->AddItem(shadows);
    sequence->SetPasses(passes);
    vtkNew<vtkCameraPass> cameraPass;
    cameraPass->SetDelegatePass(sequence);
    renderer->SetPass(cameraPass);
    window->AddRenderer(renderer);
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->SetFocalPoint(0.0, -0.6, 0.0);
    camera->SetPosition(0.0, 5.0, 0.01);
    camera->SetViewUp(0.0, 0.0, -1.0);
    renderer->ResetCameraClippingRange(-3, 3, -3, 3, -3, 3);
    SplineVizTest::Frame frame = SplineVizTest::Grab(window);
    window->RemoveRenderer(renderer);
    StylizedLineTest::Save(frame, name);
    return frame;
  };
  const SplineVizTest::Frame withLines = passRender(true, "shadow-pass");
  const SplineVizTest::Frame planeOnly = passRender(false, "shadow-pass-plane");
  // Plane pixels (not covered by a line: the line renders cover them only
  // where the depth differs from the plane-only render's) that got darker.
  long darker = 0;
  const size_t pixels = static_cast<size_t>(Size * Size);
  for (size_t i = 0; i < pixels; ++i)
  {
    const bool line = std::abs(withLines.Depth[i] - planeOnly.Depth[i]) > 1e-6f;
    if (line)
    {
      continue;
    }
    const double a = (withLines.RGB[3 * i] + withLines.RGB[3 * i + 1] + withLines.RGB[3 * i + 2]);
    const double b = (planeOnly.RGB[3 * i] + planeOnly.RGB[3 * i + 1] + planeOnly.RGB[3 * i + 2]);
    darker += (b - a) / 3.0 > 30.0 ? 1 : 0;
  }
  std::cout << "vtkShadowMapPass: " << darker << " plane pixels in the lines' shadows" << std::endl;
  SV_CHECK_MSG(status, darker > 0.02 * pixels, "no shadows of the lines in vtkShadowMapPass");
  return status.Result();
}
