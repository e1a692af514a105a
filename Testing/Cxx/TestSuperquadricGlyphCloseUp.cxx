// SPDX-License-Identifier: BSD-3-Clause
// Image regression test: a close-up of one superquadric glyph (gamma 3,
// between linear and planar) filling the view, cut by a polygonal plane and
// pierced by a second glyph: the ray-cast surfaces write their exact depth,
// so the intersection curves with the plane and with each other are sharp
// and in the right place (a sprite-depth impostor would show straight
// cuts). Right: the same scene in parallel projection from the side.
#include "vtkSuperquadricGlyphMapper.h"

#include "SuperquadricGlyphTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"

int TestSuperquadricGlyphCloseUp(int argc, char* argv[])
{
  const sqtest::HandTensor big = { { 1.0, 0.62, 0.22 }, { 20, -35, 25 }, "big" };
  const sqtest::HandTensor small = { { 0.5, 0.12, 0.1 }, { 70, 40, -20 }, "small" };
  std::vector<std::array<double, 6>> tensors = { sqtest::Compose(big), sqtest::Compose(small) };
  auto image = sqtest::TensorImage(tensors, 2);
  image->SetSpacing(1.1, 1, 1);

  vtkNew<vtkSuperquadricGlyphMapper> mapper;
  mapper->SetInputData(image);
  mapper->SetGamma(3.0);
  mapper->SetMinimumRoundness(0.1);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetSpecular(0.5);
  actor->GetProperty()->SetSpecularPower(40);

  vtkNew<vtkPlaneSource> plane;
  // z = 0.3 x + 0.1 y - 0.25: tilted, through both glyphs
  plane->SetOrigin(-1.6, -1.6, -0.89);
  plane->SetPoint1(1.8, -1.6, 0.13);
  plane->SetPoint2(-1.6, 1.6, -0.57);
  vtkNew<vtkPolyDataMapper> planeMapper;
  planeMapper->SetInputConnection(plane->GetOutputPort());
  vtkNew<vtkActor> planeActor;
  planeActor->SetMapper(planeMapper);
  planeActor->GetProperty()->SetColor(0.85, 0.85, 0.8);

  vtkNew<vtkRenderWindow> window;
  window->SetSize(640, 360);
  window->SetMultiSamples(0);
  for (int v = 0; v < 2; ++v)
  {
    vtkNew<vtkRenderer> renderer;
    renderer->SetViewport(v == 0 ? 0.0 : 0.6, 0.0, v == 0 ? 0.6 : 1.0, 1.0);
    renderer->SetBackground(0.25, 0.27, 0.33);
    renderer->AddActor(actor);
    renderer->AddActor(planeActor);
    window->AddRenderer(renderer);
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->SetFocalPoint(0.5, 0, 0);
    if (v == 0)
    {
      camera->SetPosition(1.9, -2.3, 2.4);
      camera->SetViewUp(0, 0, 1);
      camera->SetViewAngle(40);
    }
    else
    {
      camera->SetPosition(0.5, -6, 1.6);
      camera->SetViewUp(0, 0, 1);
      camera->SetParallelProjection(1);
      camera->SetParallelScale(1.4);
    }
    renderer->ResetCameraClippingRange();
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
