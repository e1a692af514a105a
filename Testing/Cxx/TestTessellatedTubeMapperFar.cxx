// SPDX-License-Identifier: BSD-3-Clause
// Image regression test of vtkTessellatedTubeMapper far away: the synthetic
// "Fibers" data set (241 tubes, 3,530 segments) in a small window, where the
// level of detail draws thin tubes without the tessellator: the view-facing
// half of the wall per run of segments, the caps as polygons. Also checks
// that those draws are used.
#include "vtkTessellatedTubeMapper.h"

#include "SplineVizTestUtilities.h"
#include "vtkSyntheticFibersSource.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"

#include <string>

int TestTessellatedTubeMapperFar(int argc, char* argv[])
{
  vtkNew<vtkSyntheticFibersSource> fibers;
  fibers->SetPresetToFibers();
  vtkNew<vtkTessellatedTubeMapper> mapper;
  mapper->SetInputConnection(fibers->GetOutputPort());
  mapper->SetRadiusArray("Radius");
  mapper->SetScalarModeToUsePointFieldData();
  mapper->SelectColorArray("Scalar");
  mapper->SetScalarRange(0.0, 1.0);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);

  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->SetBackground(0.1, 0.1, 0.12);
  vtkNew<vtkRenderWindow> window;
  window->SetMultiSamples(0);
  window->SetSize(300, 300);
  window->AddRenderer(renderer);
  renderer->ResetCamera();
  renderer->GetActiveCamera()->Azimuth(30);
  renderer->GetActiveCamera()->Elevation(20);
  renderer->ResetCameraClippingRange();
  window->Render();

  SplineVizTestStatus status;
  const std::string summary = mapper->GetLevelOfDetailSummary();
  std::cout << "levels of detail: " << summary << std::endl;
  SV_CHECK_MSG(status, summary.find("thin ") != std::string::npos, "no thin-tube draws far away");
  // The caps of thin tubes: polygons of the vertex stage, as the walls.
  SV_CHECK_MSG(status, summary.find("caps thin ") != std::string::npos, "no thin-tube caps far away");

  int result = vtkRegressionTestImage(window);
  if (result == vtkRegressionTester::DO_INTERACTOR)
  {
    vtkNew<vtkRenderWindowInteractor> interactor;
    interactor->SetRenderWindow(window);
    interactor->Start();
  }
  return (!result || status.Result()) ? EXIT_FAILURE : EXIT_SUCCESS;
}
