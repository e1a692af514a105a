// SPDX-License-Identifier: BSD-3-Clause
// vtkTessellatedTubeMapper in an OpenGL context without tessellation shaders
// (ctest runs this with Mesa's MESA_GL_VERSION_OVERRIDE=3.3 and
// MESA_EXTENSION_OVERRIDE=-GL_ARB_tessellation_shader): the mapper warns
// once, draws with vtkRayCastTubeMapper instead, and the image is exactly
// what vtkRayCastTubeMapper with the same settings draws.
#include "vtkRayCastTubeMapper.h"
#include "vtkTessellatedTubeMapper.h"

#include "SplineTubeTestScenes.h"
#include "SplineVizTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTestErrorObserver.h"

#include <iostream>

namespace
{
SplineTubeTest::Image Render(vtkRenderWindow* window, vtkSplineTubeMapper* mapper)
{
  mapper->SetInputData(SplineTubeTest::MakePolyData(SplineTubeTest::TestLines()));
  mapper->SetRadiusArray("Radius");
  mapper->SetScalarModeToUsePointFieldData();
  mapper->SelectColorArray("Scalar");
  mapper->SetScalarRange(0.0, 1.0);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  window->AddRenderer(renderer);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetFocalPoint(0.0, 0.0, 0.4);
  camera->SetPosition(2.0, -7.5, 4.4);
  camera->SetViewUp(0, 0, 1);
  renderer->ResetCameraClippingRange(-4, 4, -4, 4, -4, 4);
  window->Render();
  window->Render(); // a second frame: no second warning
  SplineTubeTest::Image image = SplineTubeTest::Grab(window);
  window->RemoveRenderer(renderer);
  return image;
}
}

int TestTessellatedTubeFallback(int, char*[])
{
  SplineVizTestStatus status;
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(300, 300);
  window->Render();
  if (vtkTessellatedTubeMapper::IsTessellationSupported(window))
  {
    std::cout << "ERROR: this test needs an OpenGL context without tessellation shaders "
                 "(run it through ctest, which sets Mesa overrides)"
              << std::endl;
    return EXIT_FAILURE;
  }

  vtkNew<vtkTessellatedTubeMapper> tessellated;
  vtkNew<vtkTest::ErrorObserver> observer;
  tessellated->AddObserver(vtkCommand::WarningEvent, observer);
  tessellated->AddObserver(vtkCommand::ErrorEvent, observer);
  const SplineTubeTest::Image fallback = Render(window, tessellated);
  std::cout << "warnings: " << observer->GetWarningMessage() << std::endl;
  SV_CHECK_MSG(status, !observer->GetError(), "errors: " << observer->GetErrorMessage());
  const std::string warnings = observer->GetWarningMessage();
  const size_t first = warnings.find("no tessellation shaders");
  SV_CHECK_MSG(status, first != std::string::npos, "no warning about the missing tessellation");
  SV_CHECK_MSG(status,
    first == std::string::npos ||
      warnings.find("no tessellation shaders", first + 1) == std::string::npos,
    "warned more than once");
  SV_CHECK(status, tessellated->GetUsingFallback());

  vtkNew<vtkRayCastTubeMapper> rayCast;
  const SplineTubeTest::Image reference = Render(window, rayCast);
  const unsigned char black[3] = { 0, 0, 0 };
  long covered = 0;
  for (unsigned char m : SplineTubeTest::Mask(reference, black))
  {
    covered += m;
  }
  SV_CHECK_MSG(status, covered > 5000, "the ray-cast tubes were not drawn");
  SV_CHECK_MSG(status, fallback.RGB == reference.RGB, "the fallback differs from the ray caster");
  window->Finalize();
  return status.Result();
}
