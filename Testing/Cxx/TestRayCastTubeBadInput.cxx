// SPDX-License-Identifier: BSD-3-Clause
// Bad input for the ray-cast tube mapper: every case renders without a
// crash, gives a clear message, and still draws whatever is valid.
//  - no polylines (only triangles), an empty polydata, a non-polydata block
//  - one-point lines, repeated points, zero / negative / NaN radii, NaN points
//  - a missing radius array (error; the other, valid block is still drawn)
#include "vtkRayCastTubeMapper.h"
#include "vtkSplineTubeCore.h"

#include "SplineVizRenderingTestUtilities.h"
#include "SplineVizTestUtilities.h"

#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkTestErrorObserver.h"

#include <limits>

using namespace SplineVizTest;

namespace
{
long CoveredPixels(vtkRenderWindow* window)
{
  const Frame f = Grab(window);
  long n = 0;
  for (int y = 0; y < f.Height; ++y)
    for (int x = 0; x < f.Width; ++x)
      n += f.Covered(x, y) ? 1 : 0;
  return n;
}

std::vector<Vec4> Line(double y, double r)
{
  std::vector<Vec4> c;
  for (int i = 0; i <= 6; ++i)
    c.push_back({ -0.8 + 0.25 * i, y, 0.0, r });
  return c;
}
}

int TestRayCastTubeBadInput(int, char*[])
{
  SplineVizTestStatus status;
  vtkNew<vtkTest::ErrorObserver> mapperMessages;
  vtkNew<vtkTest::ErrorObserver> coreMessages;

  vtkNew<vtkRayCastTubeMapper> mapper;
  mapper->AddObserver(vtkCommand::ErrorEvent, mapperMessages);
  mapper->AddObserver(vtkCommand::WarningEvent, mapperMessages);
  mapper->GetTubeCore()->AddObserver(vtkCommand::ErrorEvent, coreMessages);
  mapper->GetTubeCore()->AddObserver(vtkCommand::WarningEvent, coreMessages);
  mapper->SetRadiusArray("Radius");
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  vtkNew<vtkRenderWindow> window;
  window->SetSize(300, 300);
  window->AddRenderer(renderer);
  renderer->GetActiveCamera()->SetPosition(0, 0, 3);
  renderer->GetActiveCamera()->SetClippingRange(0.5, 10);

  // 1. Only triangles: a warning, nothing drawn.
  {
    auto tri = vtkSmartPointer<vtkPolyData>::New();
    vtkNew<vtkPoints> pts;
    pts->InsertNextPoint(0, 0, 0);
    pts->InsertNextPoint(1, 0, 0);
    pts->InsertNextPoint(0, 1, 0);
    vtkNew<vtkCellArray> polys;
    polys->InsertNextCell({ 0, 1, 2 });
    tri->SetPoints(pts);
    tri->SetPolys(polys);
    mapper->SetInputData(tri);
    SV_CHECK(status, CoveredPixels(window) == 0);
    SV_CHECK(status, mapperMessages->CheckWarningMessage("no polylines") == 0);
  }
  // 2. Empty polydata: nothing, silently.
  {
    vtkNew<vtkPolyData> empty;
    mapper->SetInputData(empty);
    SV_CHECK(status, CoveredPixels(window) == 0);
    SV_CHECK(status, !mapperMessages->GetError() && !mapperMessages->GetWarning());
  }
  // 3. Degenerate polylines next to a good one: warnings; the good one is drawn.
  {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    auto pd = MakePolylines({ Line(0.0, 0.05), { { 0.2, 0.5, 0.0, 0.05 } },
      { { 0, 0.3, 0, 0.05 }, { 0, 0.3, 0, 0.05 }, { 0.3, 0.3, 0, 0.05 } }, Line(-0.4, 0.0),
      Line(-0.5, -0.1), Line(-0.6, nan), { { nan, 0, 0, 0.05 }, { 1, 0, 0, 0.05 } } });
    mapper->SetInputData(pd);
    SV_CHECK(status, CoveredPixels(window) > 300);
    const std::string warnings = coreMessages->GetWarningMessage();
    SV_CHECK_MSG(
      status, warnings.find("fewer than two distinct points") != std::string::npos, warnings);
    SV_CHECK_MSG(status, warnings.find("repeated") != std::string::npos, warnings);
    SV_CHECK_MSG(status, warnings.find("has the radius 0") != std::string::npos, warnings);
    SV_CHECK_MSG(status, warnings.find("has the radius -0.1") != std::string::npos, warnings);
    SV_CHECK_MSG(status, warnings.find("has the radius nan") != std::string::npos, warnings);
    SV_CHECK_MSG(
      status, warnings.find("NaN or infinite coordinate") != std::string::npos, warnings);
    SV_CHECK(status, mapper->GetTubeCore()->GetNumberOfTubes() == 2);
    coreMessages->Clear();
  }
  // 4. A missing radius array in one block: an error; the other block is drawn.
  //    A non-polydata block: a warning.
  {
    auto good = MakePolylines({ Line(0.0, 0.05) });
    auto bad = MakePolylines({ Line(0.4, 0.05) });
    bad->GetPointData()->RemoveArray("Radius");
    vtkNew<vtkImageData> image;
    image->SetDimensions(2, 2, 2);
    vtkNew<vtkMultiBlockDataSet> blocks;
    blocks->SetNumberOfBlocks(3);
    blocks->SetBlock(0, good);
    blocks->SetBlock(1, bad);
    blocks->SetBlock(2, image);
    mapper->SetInputDataObject(blocks);
    SV_CHECK(status, CoveredPixels(window) > 300);
    const std::string errors = mapperMessages->GetErrorMessage();
    const std::string warnings = mapperMessages->GetWarningMessage();
    SV_CHECK(status, coreMessages->CheckErrorMessage("\"Radius\" is not a point array") == 0);
    SV_CHECK_MSG(status, errors.find("Block 2 is not drawn") != std::string::npos, errors);
    SV_CHECK_MSG(
      status, warnings.find("vtkImageData, not a vtkPolyData") != std::string::npos, warnings);
    mapperMessages->Clear();
    SV_CHECK(status, mapper->GetTubeCore()->GetNumberOfTubes() == 1);
  }
  // 5. No input at all: nothing drawn, no crash.
  {
    vtkNew<vtkRayCastTubeMapper> orphan;
    actor->SetMapper(orphan);
    SV_CHECK(status, CoveredPixels(window) == 0);
    double bounds[6];
    orphan->GetBounds(bounds);
    SV_CHECK(status, !vtkMath::AreBoundsInitialized(bounds));
  }
  return status.Result();
}
