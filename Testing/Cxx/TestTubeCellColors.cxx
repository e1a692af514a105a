// SPDX-License-Identifier: BSD-3-Clause
// Coloring by a per-streamline value (a cell array) in every line renderer
// (vtkRayCastTubeMapper, vtkTessellatedTubeMapper, vtkStylizedLineMapper):
// the synthetic curls, each polyline with its own value of the cell array
// "Bundle", mapped through a lookup table of six distinct colors, lighting
// off (the color is the mapped color itself). Independent check: at points
// the test computes on each curve (10 per curve, projected with the
// camera's own matrices, kept where the curve's point is the nearest thing
// drawn at that pixel: its depth there agrees with the point's), the pixel
// has the lookup table's color of that curve's value within 3/255.
// Negative control, which must fail: the same pixels against the color of
// the next curve's value.
#include "TubeFidelityTestScenes.h"

#include "SplineVizRenderingTestUtilities.h"
#include "SplineVizTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkLookupTable.h"
#include "vtkMatrix4x4.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

namespace
{
using namespace TubeFidelity;

const int Size = 500;
const double Palette[6][3] = { { 0.9, 0.1, 0.1 }, { 0.1, 0.8, 0.2 }, { 0.2, 0.3, 0.95 },
  { 0.95, 0.8, 0.1 }, { 0.7, 0.2, 0.8 }, { 0.1, 0.8, 0.85 } };
}

int TestTubeCellColors(int, char*[])
{
  SplineVizTestStatus status;
  auto window = MakeWindow(Size);

  const Curves curves = SplineVizTest::Curls();
  auto lines = SplineVizTest::MakePolylines(curves);
  vtkNew<vtkDoubleArray> bundle;
  bundle->SetName("Bundle");
  for (size_t c = 0; c < curves.size(); ++c)
  {
    bundle->InsertNextValue(static_cast<double>(c % 6));
  }
  lines->GetCellData()->AddArray(bundle);
  vtkNew<vtkLookupTable> lut;
  lut->SetNumberOfTableValues(6);
  lut->SetTableRange(0.0, 5.0);
  for (int i = 0; i < 6; ++i)
  {
    lut->SetTableValue(i, Palette[i][0], Palette[i][1], Palette[i][2], 1.0);
  }
  lut->Build();
  double bounds[6];
  PaddedBounds(lines, bounds);
  const double direction[3] = { 4.0, 5.0, 9.0 };
  const double target[3] = { 0.0, 0.0, 0.0 };
  const auto setup = MakeCamera(bounds, direction, target, 1.0);

  for (Renderer which : { RayCast, Tessellated, Stylized })
  {
    const std::string name = std::string("cell-colors-") + RendererNames[which];
    auto mapper = MakeMapper(which, lines);
    mapper->ScalarVisibilityOn();
    mapper->SetScalarModeToUseCellFieldData();
    mapper->SelectColorArray("Bundle");
    mapper->SetLookupTable(lut);
    mapper->SetScalarRange(0.0, 5.0);
    mapper->SetColorModeToMapScalars();
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->GetProperty()->LightingOff();
    vtkNew<vtkCamera> camera;
    const SplineVizTest::Frame frame = RenderActors(window, { actor }, setup, bounds, camera);
    SplineVizTest::Save(frame, name);

    // The curves' own points, projected by the test (a square window).
    vtkMatrix4x4* worldToView = camera->GetCompositeProjectionTransformMatrix(1.0, -1.0, 1.0);
    int checked = 0, matched = 0, matchedOther = 0;
    for (size_t c = 0; c < curves.size(); ++c)
    {
      const double* own = Palette[c % 6];
      const double* other = Palette[(c + 1) % 6];
      for (int s = 1; s <= 10; ++s)
      {
        const Vec4& p = curves[c][s * (curves[c].size() - 1) / 11];
        const double in[4] = { p[0], p[1], p[2], 1.0 };
        double clip[4];
        worldToView->MultiplyPoint(in, clip);
        const double ndc[3] = { clip[0] / clip[3], clip[1] / clip[3], clip[2] / clip[3] };
        const int x = static_cast<int>(std::floor(0.5 * (ndc[0] + 1.0) * Size));
        const int y = static_cast<int>(std::floor(0.5 * (ndc[1] + 1.0) * Size));
        if (x < 0 || y < 0 || x >= Size || y >= Size)
        {
          continue;
        }
        const size_t i = static_cast<size_t>(y) * Size + x;
        // The tube's surface is at most a radius nearer than its axis point:
        // otherwise something else is in front of the curve there.
        const double axisDepth = SplineVizTest::ViewDepth(0.5 * (ndc[2] + 1.0), camera);
        const double drawnDepth = SplineVizTest::ViewDepth(frame.Depth[i], camera);
        if (frame.Depth[i] >= 1.0f || axisDepth - drawnDepth > 1.5 * p[3])
        {
          continue;
        }
        ++checked;
        auto close = [&](const double* rgb)
        {
          for (int k = 0; k < 3; ++k)
          {
            if (std::abs(frame.RGB[3 * i + k] - 255.0 * rgb[k]) > 3.0)
            {
              return false;
            }
          }
          return true;
        };
        matched += close(own) ? 1 : 0;
        matchedOther += close(other) ? 1 : 0;
      }
    }
    std::cout << name << ": " << matched << " of " << checked
              << " curve points show their curve's color (the next curve's color: " << matchedOther
              << ")" << std::endl;
    SV_CHECK_MSG(status, checked >= 30, name << ": only " << checked << " points checked");
    SV_CHECK_MSG(status, matched == checked,
      name << ": " << checked - matched << " points not in their curve's color");
    SV_CHECK_MSG(status, matchedOther < checked / 2,
      name << ": the negative control matched " << matchedOther);
  }
  return status.Result();
}
