// SPDX-License-Identifier: BSD-3-Clause
// Image regression test of vtkStylizedLineMapper (VTK regression-image
// framework), four views of the curls of StylizedLineTestScenes.h colored by
// a scalar through a lookup table:
//  top left:     the whole scene, no halo;
//  top right:    the same with a halo (a third of the radius, the
//                background's color): lines behind others are cut;
//  bottom left:  a close-up with the halo, among the lines;
//  bottom right: the lines through an opaque sphere (depth correction), in a
//                parallel projection.
#include "vtkStylizedLineMapper.h"

#include "StylizedLineTestScenes.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkDoubleArray.h"
#include "vtkLookupTable.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"

#include <cmath>

int TestStylizedLineMapper(int argc, char* argv[])
{
  vtkNew<vtkRenderWindow> window;
  window->SetSize(800, 600);
  window->SetMultiSamples(0);

  auto lines = SplineVizTest::MakePolylines(StylizedLineTest::Curls());
  vtkNew<vtkDoubleArray> scalar;
  scalar->SetName("Scalar");
  for (vtkIdType i = 0; i < lines->GetNumberOfPoints(); ++i)
  {
    double p[3];
    lines->GetPoint(i, p);
    scalar->InsertNextValue(std::sin(2.0 * p[0]) * std::cos(1.5 * p[1] + p[2]));
  }
  lines->GetPointData()->SetScalars(scalar);
  vtkNew<vtkLookupTable> lut;
  lut->SetHueRange(0.66, 0.0);
  lut->Build();

  const double viewports[4][4] = { { 0.0, 0.5, 0.5, 1.0 }, { 0.5, 0.5, 1.0, 1.0 },
    { 0.0, 0.0, 0.5, 0.5 }, { 0.5, 0.0, 1.0, 0.5 } };
  for (int v = 0; v < 4; ++v)
  {
    vtkNew<vtkStylizedLineMapper> mapper;
    mapper->SetInputData(lines);
    mapper->SetRadiusArray("Radius");
    mapper->SetLookupTable(lut);
    mapper->SetScalarRange(-1.0, 1.0);
    mapper->SetHaloWidth(v == 0 ? 0.0 : 0.35);
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->GetProperty()->SetSpecular(0.4);
    actor->GetProperty()->SetSpecularPower(30);
    vtkNew<vtkRenderer> renderer;
    renderer->SetViewport(viewports[v][0], viewports[v][1], viewports[v][2], viewports[v][3]);
    renderer->SetBackground(0.12, 0.12, 0.15);
    renderer->AddActor(actor);
    if (v == 3)
    {
      vtkNew<vtkSphereSource> sphere;
      sphere->SetCenter(-0.2, 0.3, 0.0);
      sphere->SetRadius(0.8);
      sphere->SetThetaResolution(64);
      sphere->SetPhiResolution(64);
      vtkNew<vtkPolyDataMapper> sphereMapper;
      sphereMapper->SetInputConnection(sphere->GetOutputPort());
      vtkNew<vtkActor> sphereActor;
      sphereActor->SetMapper(sphereMapper);
      sphereActor->GetProperty()->SetColor(0.85, 0.85, 0.8);
      renderer->AddActor(sphereActor);
    }
    window->AddRenderer(renderer);
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->SetFocalPoint(0.0, 0.0, 0.0);
    camera->SetPosition(4.0, 5.0, 9.0);
    camera->SetViewUp(0.0, 1.0, 0.0);
    if (v == 2)
    {
      camera->SetFocalPoint(-1.2, 0.6, 0.0);
      camera->SetPosition(-0.6, 1.2, 1.6);
      camera->SetViewAngle(50.0);
    }
    else
    {
      camera->SetParallelProjection(v == 3);
      renderer->ResetCamera();
      camera->Zoom(1.4);
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
