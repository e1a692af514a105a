// SPDX-License-Identifier: BSD-3-Clause
// Bad input for the tube mappers (vtkTessellatedTubeMapper,
// vtkRayCastTubeMapper and vtkStylizedLineMapper): clear errors or warnings,
// no crash, and the good tubes still drawn. The stylized lines also with a
// missing, three-component and NaN orientation array (with a texture).
//  - no input at all: nothing drawn (the renderer culls the actor, whose
//    bounds are uninitialized; a direct render reports "No input");
//  - an empty polydata, a polydata with vertices only: nothing drawn, quietly;
//  - a multiblock mixing a good block with blocks that have polylines with a
//    NaN coordinate, a negative, zero or infinite radius, repeated points, a
//    single point; a block without the radius array, with a two-component
//    one, with a string array of that name; an empty block and a null block:
//    one warning or error per problem, naming it, and exactly the good
//    polylines drawn (counted in the tube core and seen in the image).
#include "vtkRayCastTubeMapper.h"
#include "vtkSplineTubeCore.h"
#include "vtkStylizedLineMapper.h"
#include "vtkTessellatedTubeMapper.h"

#include "SplineTubeTestScenes.h"
#include "SplineVizTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkStringArray.h"
#include "vtkTestErrorObserver.h"

#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace
{
using Points = std::vector<std::array<double, 3>>;

/// A polydata with the given polylines and a "Radius" array (radii per point).
vtkSmartPointer<vtkPolyData> Lines(
  const std::vector<Points>& lines, const std::vector<std::vector<double>>& radii)
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkDoubleArray> radius;
  radius->SetName("Radius");
  vtkNew<vtkCellArray> cells;
  for (size_t l = 0; l < lines.size(); ++l)
  {
    cells->InsertNextCell(static_cast<int>(lines[l].size()));
    for (size_t i = 0; i < lines[l].size(); ++i)
    {
      cells->InsertCellPoint(points->InsertNextPoint(lines[l][i].data()));
      radius->InsertNextValue(radii[l][i]);
    }
  }
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  pd->SetPoints(points);
  pd->SetLines(cells);
  pd->GetPointData()->AddArray(radius);
  return pd;
}

Points Straight(double y, int n = 4)
{
  Points p;
  for (int i = 0; i < n; ++i)
  {
    p.push_back({ -1.0 + 0.6 * i, y, 0.0 });
  }
  return p;
}

struct Result
{
  std::string Errors;
  std::string Warnings;
  vtkIdType Segments = 0;
  long Covered = 0;
};

/// Render `input` with a fresh mapper made by `make`; collect its (and its
/// core's) errors and warnings.
Result Render(const std::function<vtkSmartPointer<vtkSplineTubeMapper>()>& make,
  vtkDataObject* input, vtkRenderWindow* window)
{
  vtkSmartPointer<vtkSplineTubeMapper> mapper = make();
  vtkNew<vtkTest::ErrorObserver> observer;
  mapper->AddObserver(vtkCommand::ErrorEvent, observer);
  mapper->AddObserver(vtkCommand::WarningEvent, observer);
  mapper->GetTubeCore()->AddObserver(vtkCommand::ErrorEvent, observer);
  mapper->GetTubeCore()->AddObserver(vtkCommand::WarningEvent, observer);
  if (input)
  {
    mapper->SetInputDataObject(input);
  }
  mapper->SetRadiusArray("Radius");
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->GetActiveCamera()->SetPosition(0.0, 0.0, 8.0);
  renderer->GetActiveCamera()->SetFocalPoint(0.0, 0.0, 0.0);
  window->AddRenderer(renderer);
  renderer->ResetCameraClippingRange(-3, 3, -3, 3, -3, 3);
  window->Render();
  const unsigned char black[3] = { 0, 0, 0 };
  const auto mask = SplineTubeTest::Mask(SplineTubeTest::Grab(window), black);
  window->RemoveRenderer(renderer);
  Result r;
  r.Errors = observer->GetErrorMessage();
  r.Warnings = observer->GetWarningMessage();
  r.Segments = mapper->GetTubeCore()->GetNumberOfSegments();
  for (unsigned char m : mask)
  {
    r.Covered += m;
  }
  return r;
}

void Expect(SplineVizTestStatus& status, const std::string& what, const std::string& messages,
  const std::vector<std::string>& phrases)
{
  for (const std::string& phrase : phrases)
  {
    SV_CHECK_MSG(status, messages.find(phrase) != std::string::npos,
      what << ": no message containing \"" << phrase << "\" in:\n"
           << messages);
  }
}
}

int TestTubeMapperBadInput(int, char*[])
{
  SplineVizTestStatus status;
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(200, 200);

  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetNumberOfBlocks(8);
  // 1: good, 3 segments.
  blocks->SetBlock(0, Lines({ Straight(-1.5) }, { { 0.1, 0.1, 0.1, 0.1 } }));
  // 2: NaN point, negative / zero / infinite radius, repeated points (4 nodes
  //    left: 3 segments), one point, all points equal; and a good line (3).
  {
    Points withNaN = Straight(-1.0);
    withNaN[2][1] = nan;
    Points repeated = Straight(1.0);
    repeated.insert(repeated.begin() + 2, repeated[1]);
    repeated.insert(repeated.begin() + 2, repeated[1]);
    blocks->SetBlock(1,
      Lines({ withNaN, Straight(-0.6), Straight(-0.3), Straight(0.0), Straight(0.4), repeated,
              Straight(1.3, 1), { { 0.0, 1.6, 0.0 }, { 0.0, 1.6, 0.0 }, { 0.0, 1.6, 0.0 } } },
        { { 0.1, 0.1, 0.1, 0.1 }, { 0.1, -0.1, 0.1, 0.1 }, { 0.1, 0.1, 0.0, 0.1 },
          { 0.1, inf, 0.1, 0.1 }, { 0.1, 0.1, 0.1, 0.1 }, { 0.1, 0.1, 0.1, 0.1, 0.1, 0.1 }, { 0.1 },
          { 0.1, 0.1, 0.1 } }));
  }
  // 3: no radius array; 4: two components; 5: a string array.
  {
    vtkSmartPointer<vtkPolyData> none = Lines({ Straight(2.0) }, { { 0.1, 0.1, 0.1, 0.1 } });
    none->GetPointData()->RemoveArray("Radius");
    blocks->SetBlock(2, none);
    vtkSmartPointer<vtkPolyData> two = Lines({ Straight(2.0) }, { { 0.1, 0.1, 0.1, 0.1 } });
    vtkNew<vtkDoubleArray> radius2;
    radius2->SetName("Radius");
    radius2->SetNumberOfComponents(2);
    radius2->SetNumberOfTuples(4);
    radius2->Fill(0.1);
    two->GetPointData()->AddArray(radius2);
    blocks->SetBlock(3, two);
    vtkSmartPointer<vtkPolyData> text = Lines({ Straight(2.0) }, { { 0.1, 0.1, 0.1, 0.1 } });
    text->GetPointData()->RemoveArray("Radius");
    vtkNew<vtkStringArray> strings;
    strings->SetName("Radius");
    strings->SetNumberOfTuples(4);
    text->GetPointData()->AddArray(strings);
    blocks->SetBlock(4, text);
  }
  // 6: empty; 7: vertices only; 8: null.
  blocks->SetBlock(5, vtkNew<vtkPolyData>());
  {
    vtkSmartPointer<vtkPolyData> verts = Lines({}, {});
    vtkNew<vtkCellArray> cells;
    const vtkIdType id = verts->GetPoints()->InsertNextPoint(0, 0, 0);
    verts->GetPointData()->GetArray("Radius")->InsertNextTuple1(0.1);
    cells->InsertNextCell(1, &id);
    verts->SetVerts(cells);
    blocks->SetBlock(6, verts);
  }
  blocks->SetBlock(7, nullptr);

  const std::vector<std::pair<std::string, std::function<vtkSmartPointer<vtkSplineTubeMapper>()>>>
    mappers = {
      { "tessellated", [] { return vtkSmartPointer<vtkTessellatedTubeMapper>::New(); } },
      { "ray cast", [] { return vtkSmartPointer<vtkRayCastTubeMapper>::New(); } },
      { "stylized", [] { return vtkSmartPointer<vtkStylizedLineMapper>::New(); } },
    };
  for (const auto& m : mappers)
  {
    const std::string& name = m.first;
    // No input.
    Result r = Render(m.second, nullptr, window);
    SV_CHECK_MSG(status, r.Covered == 0, name << ": drew without input");
    {
      vtkSmartPointer<vtkSplineTubeMapper> mapper = m.second();
      vtkNew<vtkTest::ErrorObserver> observer;
      mapper->AddObserver(vtkCommand::ErrorEvent, observer);
      vtkNew<vtkActor> actor;
      vtkNew<vtkRenderer> renderer;
      window->AddRenderer(renderer);
      window->Render();
      mapper->Render(renderer, actor);
      window->RemoveRenderer(renderer);
      Expect(status, name + ", no input", observer->GetErrorMessage(), { "No input" });
    }

    // Empty and vertex-only polydata.
    r = Render(m.second, blocks->GetBlock(5), window);
    SV_CHECK_MSG(status, r.Errors.empty() && r.Covered == 0, name << ", empty: " << r.Errors);
    r = Render(m.second, blocks->GetBlock(6), window);
    SV_CHECK_MSG(status, r.Errors.empty() && r.Covered == 0, name << ", vertices: " << r.Errors);

    // The mixed multiblock.
    r = Render(m.second, blocks, window);
    // (The messages are printed without their "ERROR:" prefix, which ctest
    // takes for a failure.)
    std::string errors = r.Errors;
    vtkShaderProgram::Substitute(errors, "ERROR: In", "error in", true);
    std::cout << name << ", multiblock: " << r.Segments << " segments, " << r.Covered
              << " pixels\n  errors: " << errors << "\n  warnings: " << r.Warnings << std::endl;
    Expect(status, name + ", multiblock", r.Warnings,
      { "NaN or infinite coordinate", "has the radius -0.1", "has the radius 0",
        "has the radius inf", "4 repeated consecutive point(s) merged",
        "2 polyline(s) with fewer than two distinct points skipped" });
    Expect(status, name + ", multiblock", r.Errors,
      { "\"Radius\" is not a point array", "has 2 components", "is not numeric",
        "Block 3 is not drawn", "Block 4 is not drawn", "Block 5 is not drawn" });
    SV_CHECK_MSG(status, r.Segments == 3 + 3 + 3, name << ": " << r.Segments << " segments");
    SV_CHECK_MSG(status, r.Covered > 1000, name << ": the good tubes are not drawn");
  }

  // The stylized lines' orientation array (used with a texture): missing or
  // three components is an error for the block; NaN angles skip the line.
  {
    auto stylized = [](const char* orientation)
    {
      return [orientation]
      {
        auto mapper = vtkSmartPointer<vtkStylizedLineMapper>::New();
        mapper->SetTexturePatternToStripes();
        mapper->SetOrientationArray(orientation);
        return vtkSmartPointer<vtkSplineTubeMapper>(mapper);
      };
    };
    vtkSmartPointer<vtkPolyData> lines =
      Lines({ Straight(-1.0), Straight(1.0) }, { { 0.1, 0.1, 0.1, 0.1 }, { 0.1, 0.1, 0.1, 0.1 } });
    vtkNew<vtkDoubleArray> angles;
    angles->SetName("Angle");
    for (double v : { 0.0, 1.0, 2.0, 3.0, 0.0, nan, 2.0, 3.0 })
    {
      angles->InsertNextValue(v);
    }
    lines->GetPointData()->AddArray(angles);
    vtkNew<vtkDoubleArray> vectors;
    vectors->SetName("Vectors");
    vectors->SetNumberOfComponents(3);
    vectors->SetNumberOfTuples(8);
    vectors->Fill(1.0);
    lines->GetPointData()->AddArray(vectors);
    Result r = Render(stylized("Angle"), lines, window);
    Expect(status, "stylized, NaN orientation", r.Warnings,
      { "has a NaN or infinite value in the orientation array \"Angle\"" });
    SV_CHECK_MSG(status, r.Segments == 3, "stylized, NaN orientation: " << r.Segments);
    r = Render(stylized("NoSuchAngle"), lines, window);
    Expect(status, "stylized, missing orientation", r.Errors,
      { "The orientation array \"NoSuchAngle\" is not a point array" });
    SV_CHECK_MSG(status, r.Segments == 0 && r.Covered == 0, "stylized, missing orientation drew");
    r = Render(stylized("Vectors"), lines, window);
    Expect(status, "stylized, 3-component orientation", r.Errors, { "has 3 components" });
    SV_CHECK_MSG(status, r.Segments == 0, "stylized, 3-component orientation drew");
  }
  window->Finalize();
  return status.Result();
}
