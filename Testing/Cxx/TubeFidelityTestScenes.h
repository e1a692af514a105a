// SPDX-License-Identifier: BSD-3-Clause
// Scenes, mappers and polygonal references shared by the line renderers'
// fidelity tests (TestTubeFidelity: opaque; TestTubeTranslucency:
// translucent): DIPY's real cb_2 bundle densely resampled, each renderer's
// mapper, each renderer's own surface model as a polygonal reference, and a
// camera at the whole data or zoomed toward a point on it.
#ifndef TubeFidelityTestScenes_h
#define TubeFidelityTestScenes_h

#include "vtkRayCastTubeMapper.h"
#include "vtkStylizedLineMapper.h"
#include "vtkTessellatedTubeMapper.h"

#include "SplineVizRenderingTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkMath.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkXMLPolyDataReader.h"

#include <cmath>
#include <string>
#include <vector>

namespace TubeFidelity
{
using SplineVizTest::Vec4;
using Curves = std::vector<std::vector<Vec4>>;

/// cb_2's streamlines resampled along their spline, with a radius varying
/// along each fibre; empty on a read error.
inline Curves LoadBundle()
{
  vtkNew<vtkXMLPolyDataReader> reader;
  reader->SetFileName((std::string(SPLINEVIZ_SOURCE_DATA_DIR) + "/DIPY/cb_2.vtp").c_str());
  reader->Update();
  vtkPolyData* pd = reader->GetOutput();
  Curves curves;
  if (!pd || pd->GetNumberOfLines() != 116)
  {
    return curves;
  }
  vtkCellArray* lines = pd->GetLines();
  vtkIdType n = 0;
  const vtkIdType* ids = nullptr;
  int fibre = 0;
  for (lines->InitTraversal(); lines->GetNextCell(n, ids); ++fibre)
  {
    std::vector<Vec4> nodes;
    for (vtkIdType i = 0; i < n; ++i)
    {
      double p[3];
      pd->GetPoint(ids[i], p);
      const double r = 0.3 + 0.08 * std::sin(0.45 * static_cast<double>(i) + fibre);
      nodes.push_back({ p[0], p[1], p[2], r });
    }
    curves.push_back(SplineVizTest::DenseSpline(nodes, 4));
  }
  return curves;
}

/// The lines' bounds widened by 0.4 on every side (room for the tubes),
/// which fix the camera's clipping range in every rendering of a scene.
inline void PaddedBounds(vtkPolyData* lines, double bounds[6])
{
  lines->GetBounds(bounds);
  for (int k = 0; k < 3; ++k)
  {
    bounds[2 * k] -= 0.4;
    bounds[2 * k + 1] += 0.4;
  }
}

/// An offscreen size x size window without multisampling (the fidelity
/// tests compare coverage pixel by pixel).
inline vtkSmartPointer<vtkRenderWindow> MakeWindow(int size)
{
  auto window = vtkSmartPointer<vtkRenderWindow>::New();
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(size, size);
  return window;
}

/// Render the actors with the camera `setup` in a renderer of their own on
/// black; `cameraOut` gets the camera (for depths and projections).
inline SplineVizTest::Frame RenderActors(vtkRenderWindow* window,
  const std::vector<vtkActor*>& actors, const SplineVizTest::CameraSetup& setup,
  const double bounds[6], vtkCamera* cameraOut)
{
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0.0, 0.0, 0.0);
  for (vtkActor* actor : actors)
  {
    renderer->AddActor(actor);
  }
  window->AddRenderer(renderer);
  setup(renderer->GetActiveCamera());
  renderer->ResetCameraClippingRange(const_cast<double*>(bounds));
  SplineVizTest::Frame frame = SplineVizTest::Grab(window);
  cameraOut->DeepCopy(renderer->GetActiveCamera());
  window->RemoveRenderer(renderer);
  return frame;
}

/// The curves with their radii scaled (a negative control).
inline Curves ScaleRadii(Curves curves, double factor)
{
  for (auto& curve : curves)
  {
    for (auto& p : curve)
    {
      p[3] *= factor;
    }
  }
  return curves;
}

enum Renderer
{
  RayCast,
  Tessellated,
  Stylized
};
inline const char* const RendererNames[] = { "raycast", "tessellated", "stylized" };

/// The renderer's mapper for `lines`: radii from their "Radius" array, or
/// the constant `constantRadius` when it is positive.
inline vtkSmartPointer<vtkSplineTubeMapper> MakeMapper(
  Renderer which, vtkPolyData* lines, double constantRadius = 0.0)
{
  vtkSmartPointer<vtkSplineTubeMapper> mapper;
  switch (which)
  {
    case RayCast:
      mapper = vtkSmartPointer<vtkRayCastTubeMapper>::New();
      break;
    case Tessellated:
      mapper = vtkSmartPointer<vtkTessellatedTubeMapper>::New();
      break;
    case Stylized:
      mapper = vtkSmartPointer<vtkStylizedLineMapper>::New();
      break;
  }
  mapper->SetInputData(lines);
  if (constantRadius > 0.0)
  {
    mapper->SetRadius(constantRadius);
  }
  else
  {
    mapper->SetRadiusArray("Radius");
  }
  mapper->ScalarVisibilityOff();
  return mapper;
}

/// How finely the reference tubes are made.
struct ReferenceResolution
{
  int PerSegment = 16;
  int Sides = 64;
  int Caps = 64;
};

/// The renderer's surface model as polygons. `singleLayer`: each point of
/// the image covered by one front-facing polygon of each tube (for
/// translucent rendering with backface culling: the rounded ends as the
/// hemispheres outside the tube, not whole spheres).
inline vtkSmartPointer<vtkPolyData> MakeReference(Renderer which, const Curves& curves,
  const ReferenceResolution& resolution, bool singleLayer = false)
{
  switch (which)
  {
    case RayCast:
      return SplineVizTest::ReferenceTubes(
        curves, resolution.PerSegment, resolution.Sides, false, resolution.Caps, singleLayer);
    case Tessellated:
      return SplineVizTest::ReferenceTubes(
        curves, resolution.PerSegment, resolution.Sides, true, resolution.Caps);
    default:
      return SplineVizTest::PolylineReferenceTubes(
        SplineVizTest::MakePolylines(curves), resolution.Sides);
  }
}

/// Camera looking along `direction` at the whole data (bounds), then zoomed
/// by `zoom` toward `target` (the view direction kept).
inline SplineVizTest::CameraSetup MakeCamera(
  const double bounds[6], const double direction[3], const double target[3], double zoom)
{
  std::vector<double> b(bounds, bounds + 6);
  std::vector<double> d(direction, direction + 3);
  std::vector<double> t(target, target + 3);
  return [b, d, t, zoom](vtkCamera* camera)
  {
    double center[3] = { 0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5]) };
    double radius = 0.0;
    for (int k = 0; k < 3; ++k)
    {
      radius += 0.25 * (b[2 * k + 1] - b[2 * k]) * (b[2 * k + 1] - b[2 * k]);
    }
    radius = std::sqrt(radius);
    const double viewAngle = 30.0;
    const double distance = radius / std::sin(vtkMath::RadiansFromDegrees(0.5 * viewAngle));
    const double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    double focal[3];
    for (int k = 0; k < 3; ++k)
    {
      // Whole view: at the center; zoomed: at the target.
      focal[k] = zoom > 1.0 ? t[k] : center[k];
    }
    camera->SetFocalPoint(focal);
    camera->SetPosition(focal[0] + distance * d[0] / len, focal[1] + distance * d[1] / len,
      focal[2] + distance * d[2] / len);
    camera->SetViewUp(0.0, 0.0, 1.0);
    camera->OrthogonalizeViewUp();
    camera->SetViewAngle(viewAngle);
    camera->Zoom(zoom);
  };
}
}

#endif
