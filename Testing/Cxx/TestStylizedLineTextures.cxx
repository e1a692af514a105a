// SPDX-License-Identifier: BSD-3-Clause
// Image regression test of the textures of vtkStylizedLineMapper (Stoll
// §4.2, §6, Figs. 10-13), four views of wavy lines whose orientation array
// turns once every 30 radii:
//  top left:     stripes turned by the orientation (twisting along the lines);
//  top right:    arrows along the lines, turned by the orientation;
//  bottom left:  dashed lines with a halo;
//  bottom right: an actor texture (a checkerboard) as a normal map.
#include "vtkStylizedLineMapper.h"

#include "StylizedLineTestScenes.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkDoubleArray.h"
#include "vtkImageData.h"
#include "vtkProperty.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"
#include "vtkTexture.h"

#include <cmath>

namespace
{
/// A tangent-space normal map of bumps (a checkerboard of raised squares).
vtkSmartPointer<vtkTexture> Bumps()
{
  const int n = 64;
  vtkNew<vtkImageData> image;
  image->SetDimensions(n, n, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* p = static_cast<unsigned char*>(image->GetScalarPointer());
  for (int y = 0; y < n; ++y)
  {
    for (int x = 0; x < n; ++x)
    {
      // Height h = sin(2 pi x / 32) sin(2 pi y / 32); the normal (-dh/dx, -dh/dy, 1).
      const double k = 2.0 * 3.141592653589793 / 32.0;
      const double dx = 0.6 * std::cos(k * x) * std::sin(k * y);
      const double dy = 0.6 * std::sin(k * x) * std::cos(k * y);
      const double l = std::sqrt(dx * dx + dy * dy + 1.0);
      unsigned char* c = p + 3 * (y * n + x);
      c[0] = static_cast<unsigned char>(std::lround(127.5 * (1.0 - dx / l)));
      c[1] = static_cast<unsigned char>(std::lround(127.5 * (1.0 - dy / l)));
      c[2] = static_cast<unsigned char>(std::lround(127.5 * (1.0 + 1.0 / l)));
    }
  }
  auto texture = vtkSmartPointer<vtkTexture>::New();
  texture->SetInputData(image);
  texture->InterpolateOn();
  texture->RepeatOn();
  texture->MipmapOn();
  return texture;
}
}

int TestStylizedLineTextures(int argc, char* argv[])
{
  vtkNew<vtkRenderWindow> window;
  window->SetSize(800, 600);
  window->SetMultiSamples(0);

  std::vector<std::vector<SplineVizTest::Vec4>> curves;
  for (int k = 0; k < 4; ++k)
  {
    std::vector<SplineVizTest::Vec4> c;
    for (int i = 0; i <= 120; ++i)
    {
      const double x = -2.0 + 4.0 * i / 120.0;
      c.push_back({ x, -0.9 + 0.6 * k + 0.15 * std::sin(2.0 * x + k), 0.2 * std::cos(1.5 * x),
        0.11 + 0.03 * std::sin(1.3 * x + k) });
    }
    curves.push_back(c);
  }
  auto lines = SplineVizTest::MakePolylines(curves);
  vtkNew<vtkDoubleArray> angle;
  angle->SetName("Rotation");
  for (vtkIdType i = 0; i < lines->GetNumberOfPoints(); ++i)
  {
    double p[3];
    lines->GetPoint(i, p);
    angle->InsertNextValue(2.0 * 3.141592653589793 * p[0] / (30.0 * 0.11));
  }
  lines->GetPointData()->AddArray(angle);

  const double viewports[4][4] = { { 0.0, 0.5, 0.5, 1.0 }, { 0.5, 0.5, 1.0, 1.0 },
    { 0.0, 0.0, 0.5, 0.5 }, { 0.5, 0.0, 1.0, 0.5 } };
  for (int v = 0; v < 4; ++v)
  {
    vtkNew<vtkStylizedLineMapper> mapper;
    mapper->SetInputData(lines);
    mapper->SetRadiusArray("Radius");
    mapper->SetOrientationArray("Rotation");
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->GetProperty()->SetColor(0.95, 0.75, 0.3);
    actor->GetProperty()->SetSpecular(0.3);
    actor->GetProperty()->SetSpecularPower(20);
    switch (v)
    {
      case 0:
        mapper->SetTexturePatternToStripes();
        mapper->SetTextureCircumferentialRepeat(3);
        break;
      case 1:
        mapper->SetTexturePatternToArrows();
        mapper->SetTextureRepeat(6.0);
        break;
      case 2:
        mapper->SetTexturePatternToDashes();
        mapper->SetHaloWidth(0.4);
        actor->GetProperty()->SetColor(0.4, 0.7, 0.95);
        break;
      default:
        actor->SetTexture(Bumps());
        mapper->NormalMappingOn();
        mapper->SetTextureRepeat(8.0);
        mapper->SetTextureCircumferentialRepeat(1);
        actor->GetProperty()->SetColor(0.8, 0.8, 0.85);
        actor->GetProperty()->SetSpecular(0.6);
        break;
    }
    vtkNew<vtkRenderer> renderer;
    renderer->SetViewport(viewports[v][0], viewports[v][1], viewports[v][2], viewports[v][3]);
    renderer->SetBackground(0.12, 0.12, 0.15);
    renderer->AddActor(actor);
    window->AddRenderer(renderer);
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->SetFocalPoint(0.0, 0.0, 0.0);
    camera->SetPosition(0.8, 1.5, 6.0);
    camera->SetViewUp(0.0, 1.0, 0.0);
    renderer->ResetCamera();
    camera->Zoom(1.5);
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
