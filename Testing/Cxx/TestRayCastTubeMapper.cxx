// SPDX-License-Identifier: BSD-3-Clause
// Image regression test of vtkRayCastTubeMapper (VTK regression-image
// framework), four views of one scene:
//  top left:     tubes with varying radius, colored by a scalar through a
//                lookup table, crossing an opaque sphere (exact depth against
//                other geometry) and each other;
//  top right:    close-up camera among the tubes;
//  bottom left:  parallel projection;
//  bottom right: tight curls (tangents turning fast) and two tubes
//                intersecting, with actor color and specular highlights.
#include "vtkRayCastTubeMapper.h"

#include "SplineVizRenderingTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkLookupTable.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"

#include <cmath>

using namespace SplineVizTest;

namespace
{
vtkSmartPointer<vtkPolyData> ColoredScene()
{
  std::vector<std::vector<Vec4>> curves;
  for (int tube = 0; tube < 7; ++tube)
  {
    std::vector<Vec4> c;
    const double phase = 0.9 * tube;
    for (int i = 0; i < 24; ++i)
    {
      const double t = -1.0 + 2.0 * i / 23.0;
      c.push_back({ 1.2 * t, 0.6 * std::sin(2.0 * t + phase) - 0.5 + 0.17 * tube,
        0.5 * std::cos(1.5 * t + 2 * phase), 0.035 + 0.025 * std::sin(3.0 * t + phase) });
    }
    curves.push_back(c);
  }
  auto pd = MakePolylines(curves);
  vtkNew<vtkDoubleArray> scalar;
  scalar->SetName("Scalar");
  for (vtkIdType i = 0; i < pd->GetNumberOfPoints(); ++i)
  {
    double p[3];
    pd->GetPoint(i, p);
    scalar->InsertNextValue(std::sin(3.0 * p[0]) * std::cos(2.0 * p[2]));
  }
  pd->GetPointData()->SetScalars(scalar);
  return pd;
}

vtkSmartPointer<vtkPolyData> CurlScene()
{
  std::vector<Vec4> curl, cross;
  for (int i = 0; i < 60; ++i)
  {
    const double a = 0.5 * i; // fast turning: 0.5 rad between nodes
    const double r = 0.25 + 0.004 * i;
    curl.push_back({ r * std::cos(a), r * std::sin(a), -0.6 + 0.02 * i, 0.05 });
  }
  for (int i = 0; i < 12; ++i)
  {
    const double t = -1.0 + 2.0 * i / 11.0;
    cross.push_back({ 0.9 * t, 0.1 * t, 0.2 * std::sin(2.0 * t), 0.08 });
  }
  return MakePolylines({ curl, cross });
}
}

int TestRayCastTubeMapper(int argc, char* argv[])
{
  vtkNew<vtkRenderWindow> window;
  window->SetSize(800, 600);
  window->SetMultiSamples(0);

  vtkNew<vtkLookupTable> lut;
  lut->SetHueRange(0.66, 0.0);
  lut->Build();

  auto colored = ColoredScene();
  vtkNew<vtkSphereSource> sphereSource;
  sphereSource->SetRadius(0.45);
  sphereSource->SetThetaResolution(64);
  sphereSource->SetPhiResolution(64);

  const double viewports[3][4] = { { 0.0, 0.5, 0.5, 1.0 }, { 0.5, 0.5, 1.0, 1.0 },
    { 0.0, 0.0, 0.5, 0.5 } };
  for (int v = 0; v < 3; ++v)
  {
    vtkNew<vtkRayCastTubeMapper> mapper;
    mapper->SetInputData(colored);
    mapper->SetRadiusArray("Radius");
    mapper->SetLookupTable(lut);
    mapper->SetScalarRange(-1.0, 1.0);
    vtkNew<vtkActor> tubes;
    tubes->SetMapper(mapper);
    tubes->GetProperty()->SetSpecular(0.3);
    tubes->GetProperty()->SetSpecularPower(20);

    vtkNew<vtkPolyDataMapper> sphereMapper;
    sphereMapper->SetInputConnection(sphereSource->GetOutputPort());
    vtkNew<vtkActor> sphere;
    sphere->SetMapper(sphereMapper);
    sphere->GetProperty()->SetColor(0.85, 0.85, 0.8);

    vtkNew<vtkRenderer> renderer;
    renderer->SetViewport(viewports[v][0], viewports[v][1], viewports[v][2], viewports[v][3]);
    renderer->SetBackground(0.12, 0.12, 0.15);
    renderer->AddActor(tubes);
    renderer->AddActor(sphere);
    window->AddRenderer(renderer);
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->SetFocalPoint(0, 0, 0);
    camera->SetPosition(0.5, 0.8, 3.5);
    camera->SetViewUp(0, 1, 0);
    if (v == 1)
    {
      camera->SetPosition(-0.35, -0.1, 0.75); // close up, among the tubes
      camera->SetFocalPoint(-0.6, -0.2, -0.2);
      camera->SetViewAngle(60);
    }
    if (v == 2)
    {
      camera->SetParallelProjection(1);
    }
    if (v != 1)
    {
      renderer->ResetCamera();
      camera->Zoom(1.7);
    }
    renderer->ResetCameraClippingRange();
  }

  // Tight curls and intersecting tubes, solid color.
  vtkNew<vtkRayCastTubeMapper> curlMapper;
  curlMapper->SetInputData(CurlScene());
  curlMapper->SetRadiusArray("Radius");
  vtkNew<vtkActor> curl;
  curl->SetMapper(curlMapper);
  curl->GetProperty()->SetColor(0.95, 0.6, 0.2);
  curl->GetProperty()->SetSpecular(0.6);
  curl->GetProperty()->SetSpecularPower(40);
  vtkNew<vtkRenderer> curlRenderer;
  curlRenderer->SetViewport(0.5, 0.0, 1.0, 0.5);
  curlRenderer->SetBackground(0.12, 0.12, 0.15);
  curlRenderer->AddActor(curl);
  window->AddRenderer(curlRenderer);
  curlRenderer->GetActiveCamera()->SetPosition(0.4, -2.2, 1.6);
  curlRenderer->GetActiveCamera()->SetViewUp(0, 0, 1);
  curlRenderer->ResetCamera();
  curlRenderer->GetActiveCamera()->Zoom(1.3);

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
