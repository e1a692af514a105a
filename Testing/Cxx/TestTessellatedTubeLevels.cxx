// SPDX-License-Identifier: BSD-3-Clause
// The tessellation levels of vtkTessellatedTubeMapper respond to the view:
// the triangles the GPU generates (a GL_PRIMITIVES_GENERATED query,
// CountPrimitives) are counted for the same tubes seen from a sequence of
// distances.
//  - With the paper's fixed base mesh (LevelOfDetail off) the count grows as
//    the camera approaches (never falls by more than back-patch culling
//    noise), is several times the base mesh's close up, and is the base
//    mesh's (levels 1) far away.
//  - Each criterion contributes: close up, bounding the silhouette
//    criterion's level to 1 or the screen-space criterion's level to 1 lowers
//    the count.
//  - With LevelOfDetail on the count also grows as the camera approaches and
//    far away it is a fraction of the fixed base mesh's.
#include "vtkTessellatedTubeMapper.h"

#include "SplineTubeTestScenes.h"
#include "SplineVizTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <cmath>
#include <iostream>
#include <vector>

namespace
{
std::vector<double> Distances()
{
  return { 2.0, 3.0, 4.5, 7.0, 11.0, 17.0, 26.0, 40.0, 64.0 };
}

/// Triangles generated at each distance (camera on a fixed ray).
std::vector<double> Count(vtkRenderWindow* window, vtkTessellatedTubeMapper* mapper)
{
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  window->AddRenderer(renderer);
  std::vector<double> counts;
  for (double d : Distances())
  {
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->SetFocalPoint(0.0, 0.0, 0.0);
    camera->SetPosition(0.3 * d, -0.8 * d, 0.52 * d);
    camera->SetViewUp(0, 0, 1);
    camera->SetViewAngle(30.0);
    renderer->ResetCameraClippingRange();
    window->Render();
    counts.push_back(static_cast<double>(mapper->GetNumberOfPrimitivesGenerated()));
  }
  window->RemoveRenderer(renderer);
  return counts;
}

void Print(const char* what, const std::vector<double>& counts)
{
  std::cout << what << ":";
  for (double c : counts)
  {
    std::cout << " " << c;
  }
  std::cout << std::endl;
}
}

int TestTessellatedTubeLevels(int, char*[])
{
  SplineVizTestStatus status;
  // A short curved tube with a varying radius that stays in view.
  SplineTubeTest::Line line;
  for (int i = 0; i <= 4; ++i)
  {
    const double a = -0.8 + 0.4 * i;
    line.Points.push_back({ 0.9 * std::sin(a), 0.9 * std::cos(a) - 0.75, 0.1 * i - 0.2 });
    line.Radii.push_back(0.12 + 0.03 * i);
  }
  vtkSmartPointer<vtkPolyData> input = SplineTubeTest::MakePolyData({ line });
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(400, 400);

  auto makeMapper = [&](bool lod, int maxLevel, int maxSilhouetteLevel)
  {
    auto mapper = vtkSmartPointer<vtkTessellatedTubeMapper>::New();
    mapper->SetInputData(input);
    mapper->SetRadiusArray("Radius");
    mapper->SetLevelOfDetail(lod);
    mapper->SetMaxTessellationLevel(maxLevel);
    mapper->SetMaxSilhouetteTessellationLevel(maxSilhouetteLevel);
    mapper->CountPrimitivesOn();
    return mapper;
  };

  const std::vector<double> adaptive = Count(window, makeMapper(false, 5, 7));
  const std::vector<double> baseOnly = Count(window, makeMapper(false, 1, 1));
  const std::vector<double> noSilhouette = Count(window, makeMapper(false, 5, 1));
  const std::vector<double> noScreen = Count(window, makeMapper(false, 1, 7));
  const std::vector<double> lod = Count(window, makeMapper(true, 5, 7));
  Print("distances", Distances());
  Print("adaptive, fixed base mesh", adaptive);
  Print("base mesh only (levels 1)", baseOnly);
  Print("silhouette criterion bounded to 1", noSilhouette);
  Print("screen-space criterion bounded to 1", noScreen);
  Print("adaptive, level of detail", lod);

  const size_t n = adaptive.size();
  for (size_t i = 0; i < n; ++i)
  {
    SV_CHECK_MSG(status, adaptive[i] > 0 && lod[i] > 0, "nothing drawn at distance " << i);
    SV_CHECK(status, adaptive[i] >= baseOnly[i]);
  }
  for (size_t i = 0; i + 1 < n; ++i)
  {
    // Nearer: at least as many triangles (back-patch culling changes the
    // base count by a few percent between views).
    SV_CHECK_MSG(status, adaptive[i] >= 0.95 * adaptive[i + 1],
      "fixed base mesh: fewer triangles nearer, at distance " << i);
    SV_CHECK_MSG(
      status, lod[i] >= 0.95 * lod[i + 1], "level of detail: fewer triangles nearer, at " << i);
  }
  SV_CHECK_MSG(status, adaptive[0] > 4.0 * baseOnly[0], "little refinement close up");
  SV_CHECK_MSG(status, adaptive[0] > 4.0 * adaptive[n - 1], "the levels do not follow the view");
  SV_CHECK_MSG(status, adaptive[n - 1] <= 1.05 * baseOnly[n - 1], "refined far away");
  SV_CHECK_MSG(status, noSilhouette[0] < 0.6 * adaptive[0], "silhouette criterion inactive");
  SV_CHECK_MSG(status, noScreen[0] < 0.97 * adaptive[0], "screen-space criterion inactive");
  SV_CHECK_MSG(status, lod[0] > 4.0 * lod[n - 1], "level of detail does not follow the view");
  SV_CHECK_MSG(status, lod[n - 1] < 0.5 * adaptive[n - 1], "no level of detail far away");
  return status.Result();
}
