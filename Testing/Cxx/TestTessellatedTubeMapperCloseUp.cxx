// SPDX-License-Identifier: BSD-3-Clause
// Image regression test of vtkTessellatedTubeMapper close up: left the
// shaded tube (smooth silhouettes from the silhouette criterion), right the
// same view in wireframe, which shows the tessellation: the base mesh
// refined most along the silhouettes and on the rim of the end cap (finer
// seams), back patches culled.
#include "vtkTessellatedTubeMapper.h"

#include "SplineTubeTestScenes.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkProperty.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"

int TestTessellatedTubeMapperCloseUp(int argc, char* argv[])
{
  vtkNew<vtkTessellatedTubeMapper> mapper;
  mapper->SetInputData(SplineTubeTest::MakePolyData(SplineTubeTest::TestLines()));
  mapper->SetRadiusArray("Radius");
  mapper->ScalarVisibilityOff();

  vtkNew<vtkRenderWindow> window;
  window->SetMultiSamples(0);
  window->SetSize(600, 300);
  for (int side = 0; side < 2; ++side)
  {
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->GetProperty()->SetColor(0.9, 0.75, 0.3);
    if (side == 1)
    {
      actor->GetProperty()->SetRepresentationToWireframe();
      actor->GetProperty()->SetColor(0.1, 0.2, 0.5);
      actor->GetProperty()->LightingOff();
    }
    vtkNew<vtkRenderer> renderer;
    renderer->AddActor(actor);
    renderer->SetBackground(1.0, 1.0, 1.0);
    renderer->SetViewport(0.5 * side, 0.0, 0.5 * side + 0.5, 1.0);
    window->AddRenderer(renderer);
    // The start of the helix: its end cap and a bend.
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->SetFocalPoint(0.85, 0.1, -1.3);
    camera->SetPosition(2.4, -1.2, -0.9);
    camera->SetViewUp(0, 0, 1);
    camera->SetViewAngle(30);
    renderer->ResetCameraClippingRange(-4, 4, -4, 4, -4, 4);
  }
  window->Render();

  int result = vtkRegressionTestImage(window);
  if (result == vtkRegressionTester::DO_INTERACTOR)
  {
    vtkNew<vtkRenderWindowInteractor> interactor;
    interactor->SetRenderWindow(window);
    interactor->Start();
  }
  return !result;
}
