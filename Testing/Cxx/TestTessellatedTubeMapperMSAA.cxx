// SPDX-License-Identifier: BSD-3-Clause
// vtkTessellatedTubeMapper with multisampling: the colored test scene in a
// window with 8 samples (image regression), and a check that the samples
// are used: flat white tubes on black have only pure pixels without
// multisampling but many intermediate gray levels along their silhouettes
// with it.
#include "vtkTessellatedTubeMapper.h"

#include "SplineTubeTestScenes.h"
#include "SplineVizTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkProperty.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"

namespace
{
void SetupCamera(vtkRenderer* renderer)
{
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetFocalPoint(0.0, 0.0, 0.4);
  camera->SetPosition(2.0, -7.5, 4.4);
  camera->SetViewUp(0, 0, 1);
  camera->SetViewAngle(30);
  renderer->ResetCameraClippingRange(-4, 4, -4, 4, -4, 4);
}

/// Pixels of a flat white-on-black rendering that are neither.
long MixedPixels(vtkPolyData* input, int samples)
{
  vtkNew<vtkTessellatedTubeMapper> mapper;
  mapper->SetInputData(input);
  mapper->SetRadiusArray("Radius");
  mapper->ScalarVisibilityOff();
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetAmbient(1.0);
  actor->GetProperty()->SetDiffuse(0.0);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(samples);
  window->SetSize(400, 300);
  window->AddRenderer(renderer);
  SetupCamera(renderer);
  window->Render();
  const SplineTubeTest::Image image = SplineTubeTest::Grab(window);
  long mixed = 0;
  for (size_t i = 0; i < image.RGB.size(); i += 3)
  {
    mixed += (image.RGB[i] != 0 && image.RGB[i] != 255) ? 1 : 0;
  }
  return mixed;
}
}

int TestTessellatedTubeMapperMSAA(int argc, char* argv[])
{
  SplineVizTestStatus status;
  vtkSmartPointer<vtkPolyData> input = SplineTubeTest::MakePolyData(SplineTubeTest::TestLines());
  const long plain = MixedPixels(input, 0);
  const long antialiased = MixedPixels(input, 8);
  std::cout << "intermediate pixels: " << plain << " without, " << antialiased << " with 8 samples"
            << std::endl;
  SV_CHECK_MSG(status, plain == 0, "intermediate pixels without multisampling");
  SV_CHECK_MSG(status, antialiased > 500, "multisampling had no effect");

  vtkNew<vtkTessellatedTubeMapper> mapper;
  mapper->SetInputData(input);
  mapper->SetRadiusArray("Radius");
  mapper->SetScalarModeToUsePointFieldData();
  mapper->SelectColorArray("Scalar");
  mapper->SetScalarRange(0.0, 1.0);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->SetBackground(1.0, 1.0, 1.0);
  vtkNew<vtkRenderWindow> window;
  window->SetMultiSamples(8);
  window->SetSize(400, 300);
  window->AddRenderer(renderer);
  SetupCamera(renderer);
  window->Render();

  int result = vtkRegressionTestImage(window);
  if (result == vtkRegressionTester::DO_INTERACTOR)
  {
    vtkNew<vtkRenderWindowInteractor> interactor;
    interactor->SetRenderWindow(window);
    interactor->Start();
  }
  return (!result || status.Result()) ? EXIT_FAILURE : EXIT_SUCCESS;
}
