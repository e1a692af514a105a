// SPDX-License-Identifier: BSD-3-Clause
// Image regression test of the hybrid fix-up of vtkStylizedLineMapper (Stoll
// §4.3-4.4): the bundle of StylizedLineTestScenes.h seen down its lines,
// left with the fix-up (the lines' ends and the turns toward the eye closed
// by real geometry), right without it (holes and half-covered caps where the
// silhouette quads degenerate, Stoll Figs. 6 and 8 left).
#include "vtkStylizedLineMapper.h"

#include "StylizedLineTestScenes.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkProperty.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"

int TestStylizedLineEndOn(int argc, char* argv[])
{
  vtkNew<vtkRenderWindow> window;
  window->SetSize(800, 400);
  window->SetMultiSamples(0);
  auto lines = SplineVizTest::MakePolylines(StylizedLineTest::Bundle());
  for (int v = 0; v < 2; ++v)
  {
    vtkNew<vtkStylizedLineMapper> mapper;
    mapper->SetInputData(lines);
    mapper->SetRadiusArray("Radius");
    mapper->SetFixUp(v == 0);
    mapper->SetHaloWidth(0.25);
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->GetProperty()->SetColor(0.3, 0.75, 0.55);
    actor->GetProperty()->SetSpecular(0.4);
    actor->GetProperty()->SetSpecularPower(30);
    vtkNew<vtkRenderer> renderer;
    renderer->SetViewport(0.5 * v, 0.0, 0.5 * v + 0.5, 1.0);
    renderer->SetBackground(0.12, 0.12, 0.15);
    renderer->AddActor(actor);
    window->AddRenderer(renderer);
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->SetFocalPoint(0.0, 0.0, 0.0);
    camera->SetPosition(7.0, 0.15, 0.1);
    camera->SetViewUp(0.0, 1.0, 0.0);
    camera->SetViewAngle(30.0);
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
