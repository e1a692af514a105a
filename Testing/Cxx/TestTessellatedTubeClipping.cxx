// SPDX-License-Identifier: BSD-3-Clause
// vtkTessellatedTubeMapper with VTK's per-fragment features:
//  - a clipping plane (data coordinates) removes exactly the tubes' part on
//    its negative side: compared with the unclipped image, no pixel of the
//    clipped image lies left of the plane's projected line, and the pixels
//    right of it are those of the unclipped image (except a band along the
//    line, where the cut opens the tube);
//  - the actor's opacity blends the tubes with the background (black tubes
//    at opacity 0.5 on white: no black pixel, as even four overlapping
//    walls leave 1/16 of the background);
//  - the hardware level of detail keeps the clipped tubes' geometry (the
//    frustum culling works in view coordinates).
#include "vtkTessellatedTubeMapper.h"

#include "SplineTubeTestScenes.h"
#include "SplineVizTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkPlane.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <iostream>

int TestTessellatedTubeClipping(int, char*[])
{
  SplineVizTestStatus status;
  vtkNew<vtkTessellatedTubeMapper> mapper;
  mapper->SetInputData(SplineTubeTest::MakePolyData(SplineTubeTest::TestLines()));
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
  window->SetMultiSamples(0);
  window->SetSize(400, 400);
  window->AddRenderer(renderer);
  // Looking down the z axis: the plane x = 0.3 projects to a vertical line.
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->ParallelProjectionOn();
  camera->SetParallelScale(3.0);
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetPosition(0.0, 0.0, 10.0);
  camera->SetViewUp(0, 1, 0);
  renderer->ResetCameraClippingRange(-4, 4, -4, 4, -4, 4);
  window->Render();
  const unsigned char black[3] = { 0, 0, 0 };
  const auto full = SplineTubeTest::Mask(SplineTubeTest::Grab(window), black);

  vtkNew<vtkPlane> plane;
  plane->SetOrigin(0.3, 0.0, 0.0);
  plane->SetNormal(1.0, 0.0, 0.0);
  mapper->AddClippingPlane(plane);
  window->Render();
  const auto clipped = SplineTubeTest::Mask(SplineTubeTest::Grab(window), black);
  // x = 0.3 in pixels: the view spans [-3, 3] over 400 pixels.
  const int line = static_cast<int>((0.3 + 3.0) / 6.0 * 400.0);
  long left = 0, rightMissing = 0, rightFull = 0;
  for (int y = 0; y < 400; ++y)
  {
    for (int x = 0; x < 400; ++x)
    {
      const size_t i = static_cast<size_t>(y * 400 + x);
      if (x < line - 1)
      {
        left += clipped[i];
      }
      else if (x > line + 30)
      {
        rightFull += full[i];
        rightMissing += (full[i] && !clipped[i]) ? 1 : 0;
      }
    }
  }
  std::cout << "clipped: " << left << " pixels left of the plane, " << rightMissing << " of "
            << rightFull << " right of it missing" << std::endl;
  SV_CHECK_MSG(status, rightFull > 3000, "the scene has too little right of the plane");
  SV_CHECK_MSG(status, left == 0, "pixels drawn on the clipped side");
  SV_CHECK_MSG(status, rightMissing == 0, "pixels missing on the kept side");
  mapper->RemoveAllClippingPlanes();

  // Translucent tubes over a white background: blended colors.
  renderer->SetBackground(1.0, 1.0, 1.0);
  actor->GetProperty()->SetColor(0.0, 0.0, 0.0);
  actor->GetProperty()->SetOpacity(0.5);
  window->Render();
  const SplineTubeTest::Image image = SplineTubeTest::Grab(window);
  long blended = 0, opaque = 0;
  for (size_t i = 0; i < image.RGB.size(); i += 3)
  {
    const int v = image.RGB[i];
    blended += (v > 100 && v < 155) ? 1 : 0;
    opaque += (v < 5) ? 1 : 0;
  }
  std::cout << "opacity 0.5: " << blended << " blended pixels, " << opaque << " opaque"
            << std::endl;
  SV_CHECK_MSG(status, blended > 5000, "the translucent tubes are not blended");
  SV_CHECK_MSG(status, opaque == 0, "translucent tubes drawn opaque");
  window->Finalize();
  return status.Result();
}
