// SPDX-License-Identifier: BSD-3-Clause
// Image regression test of vtkTessellatedTubeMapper: tubes with strongly
// varying radii (per-point "Radius" array), colored by a point scalar
// through the mapper's lookup table (the color spline), flat end caps, a
// one-segment tube with both caps, lit with VTK's default light. The
// baseline was checked against the vtkTubeFilter reference (see
// TestTessellatedTubeReference).
#include "vtkTessellatedTubeMapper.h"

#include "SplineTubeTestScenes.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkProperty.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"

int TestTessellatedTubeMapper(int argc, char* argv[])
{
  vtkNew<vtkTessellatedTubeMapper> mapper;
  mapper->SetInputData(SplineTubeTest::MakePolyData(SplineTubeTest::TestLines()));
  mapper->SetRadiusArray("Radius");
  mapper->SetScalarModeToUsePointFieldData();
  mapper->SelectColorArray("Scalar");
  mapper->SetScalarRange(0.0, 1.0);
  mapper->ScalarVisibilityOn();
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetSpecular(0.4);
  actor->GetProperty()->SetSpecularPower(30.0);

  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->SetBackground(1.0, 1.0, 1.0);
  vtkNew<vtkRenderWindow> window;
  window->SetMultiSamples(0);
  window->SetSize(400, 300);
  window->AddRenderer(renderer);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetFocalPoint(0.0, 0.0, 0.4);
  camera->SetPosition(2.0, -7.5, 4.4);
  camera->SetViewUp(0, 0, 1);
  camera->SetViewAngle(30);
  renderer->ResetCameraClippingRange();
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
