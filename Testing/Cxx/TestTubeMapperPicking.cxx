// SPDX-License-Identifier: BSD-3-Clause
// Hardware picking with the tube mappers (vtkTessellatedTubeMapper,
// vtkRayCastTubeMapper and vtkStylizedLineMapper share the picking code of
// vtkSplineTubeMapper; the stylized lines with their halo on, which is not
// part of the line and must not be picked): a
// multiblock of two polydata blocks (the first starts with a vertex cell, so
// that line cell ids do not start at 0) and a plain polydata. At the
// projected middle of every polyline, vtkHardwareSelector must report the
// actor, the polyline's cell id and the block's flat index (1 for the plain
// polydata, as for VTK's own polydata mapper); on the background nothing.
#include "vtkRayCastTubeMapper.h"
#include "vtkStylizedLineMapper.h"
#include "vtkTessellatedTubeMapper.h"

#include "SplineVizTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCoordinate.h"
#include "vtkDataObject.h"
#include "vtkHardwareSelector.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <cmath>
#include <iostream>
#include <string>
#include <vector>

namespace
{
struct Target
{
  double Point[3];
  unsigned int Composite;
  vtkIdType Cell;
};

/// A block of `lines` curved polylines at height z; with a leading vertex
/// cell when `withVertex`. Appends the pick targets.
vtkSmartPointer<vtkPolyData> MakeBlock(
  int lines, double z, bool withVertex, unsigned int composite, std::vector<Target>& targets)
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> verts;
  vtkNew<vtkCellArray> cells;
  if (withVertex)
  {
    const vtkIdType id = points->InsertNextPoint(0.0, 0.0, z);
    verts->InsertNextCell(1, &id);
  }
  for (int l = 0; l < lines; ++l)
  {
    cells->InsertNextCell(5);
    for (int i = 0; i < 5; ++i)
    {
      const double x = -1.0 + 0.5 * i;
      const double y = -1.5 + 1.2 * l + 0.15 * std::sin(2.0 * i);
      cells->InsertCellPoint(points->InsertNextPoint(x, y, z));
      if (i == 2)
      {
        targets.push_back({ { x, y, z }, composite, (withVertex ? 1 : 0) + l });
      }
    }
  }
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  pd->SetPoints(points);
  pd->SetVerts(verts);
  pd->SetLines(cells);
  return pd;
}

void CheckPicks(SplineVizTestStatus& status, vtkRenderWindow* window, vtkSplineTubeMapper* mapper,
  vtkDataObject* input, const std::vector<Target>& targets, const char* what)
{
  mapper->SetInputDataObject(input);
  mapper->SetRadius(0.12);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  window->AddRenderer(renderer);
  renderer->GetActiveCamera()->SetPosition(0.2, 0.3, 8.0);
  renderer->GetActiveCamera()->SetFocalPoint(0.0, 0.3, 0.0);
  renderer->ResetCameraClippingRange();
  window->Render();
  // The tubes are about 17 pixels wide: tessellated tubes are drawn without
  // the tessellator (thin draws, their own program), which picking must
  // reach as well.
  if (auto* tessellated = vtkTessellatedTubeMapper::SafeDownCast(mapper))
  {
    const std::string summary = tessellated->GetLevelOfDetailSummary();
    std::cout << what << ": " << summary << std::endl;
    SV_CHECK_MSG(status, summary.find("thin ") != std::string::npos, what << ": no thin draws");
  }

  vtkNew<vtkHardwareSelector> selector;
  selector->SetRenderer(renderer);
  selector->SetFieldAssociation(vtkDataObject::FIELD_ASSOCIATION_CELLS);
  selector->SetArea(0, 0, 299, 299);
  SV_CHECK_MSG(status, selector->CaptureBuffers(), what << ": capturing the selection failed");
  vtkNew<vtkCoordinate> coordinate;
  coordinate->SetCoordinateSystemToWorld();
  for (const Target& target : targets)
  {
    coordinate->SetValue(target.Point[0], target.Point[1], target.Point[2]);
    const int* display = coordinate->GetComputedDisplayValue(renderer);
    unsigned int position[2] = { static_cast<unsigned int>(display[0]),
      static_cast<unsigned int>(display[1]) };
    unsigned int out[2];
    const vtkHardwareSelector::PixelInformation info =
      selector->GetPixelInformation(position, 0, out);
    std::cout << what << ": pixel (" << position[0] << ", " << position[1] << "): valid "
              << info.Valid << ", composite " << info.CompositeID << ", cell " << info.AttributeID
              << " (expected " << target.Composite << ", " << target.Cell << ")" << std::endl;
    SV_CHECK_MSG(status, info.Valid && info.Prop == actor.GetPointer(), what << ": missed a tube");
    SV_CHECK_MSG(status, info.CompositeID == target.Composite, what << ": wrong composite index");
    SV_CHECK_MSG(status, info.AttributeID == target.Cell, what << ": wrong cell id");
  }
  // The halo band (a quarter radius outside the line, above the first
  // target) is not part of the line.
  if (auto* lines = vtkStylizedLineMapper::SafeDownCast(mapper))
  {
    if (lines->GetHaloWidth() > 0.0)
    {
      const Target& target = targets.front();
      coordinate->SetValue(target.Point[0], target.Point[1] + 1.25 * 0.12, target.Point[2]);
      const int* display = coordinate->GetComputedDisplayValue(renderer);
      unsigned int position[2] = { static_cast<unsigned int>(display[0]),
        static_cast<unsigned int>(display[1]) };
      unsigned int out[2];
      SV_CHECK_MSG(status, !selector->GetPixelInformation(position, 0, out).Valid,
        what << ": the halo was picked");
      // (It is drawn there: the depth buffer of a normal render is covered.)
      window->Render();
      SV_CHECK_MSG(status,
        window->GetZbufferDataAtPoint(
          static_cast<int>(position[0]), static_cast<int>(position[1])) < 1.0f,
        what << ": no halo where the pick was tested");
    }
  }
  unsigned int corner[2] = { 2, 2 };
  unsigned int out[2];
  SV_CHECK_MSG(status, !selector->GetPixelInformation(corner, 0, out).Valid,
    what << ": the background was picked");
  window->RemoveRenderer(renderer);
}
}

int TestTubeMapperPicking(int, char*[])
{
  SplineVizTestStatus status;
  std::vector<Target> compositeTargets;
  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetNumberOfBlocks(2);
  blocks->SetBlock(0, MakeBlock(2, 0.0, true, 1, compositeTargets));
  blocks->SetBlock(1, MakeBlock(2, 0.5, false, 2, compositeTargets));
  // Blocks 1 and 2 hold polylines at y = -1.5, -0.3 (block 1) and the same
  // at z = 0.5: move block 2's up in y so that they do not hide block 1's.
  vtkPolyData* second = vtkPolyData::SafeDownCast(blocks->GetBlock(1));
  for (vtkIdType i = 0; i < second->GetNumberOfPoints(); ++i)
  {
    double p[3];
    second->GetPoint(i, p);
    second->GetPoints()->SetPoint(i, p[0], p[1] + 2.4, p[2]);
  }
  compositeTargets[2].Point[1] += 2.4;
  compositeTargets[3].Point[1] += 2.4;

  std::vector<Target> plainTargets;
  vtkSmartPointer<vtkPolyData> plain = MakeBlock(3, 0.0, true, 1, plainTargets);

  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(300, 300);
  vtkNew<vtkTessellatedTubeMapper> tessellated;
  CheckPicks(status, window, tessellated, blocks, compositeTargets, "tessellated, multiblock");
  vtkNew<vtkTessellatedTubeMapper> tessellatedPlain;
  CheckPicks(status, window, tessellatedPlain, plain, plainTargets, "tessellated, polydata");
  vtkNew<vtkRayCastTubeMapper> rayCast;
  CheckPicks(status, window, rayCast, blocks, compositeTargets, "ray cast, multiblock");
  vtkNew<vtkRayCastTubeMapper> rayCastPlain;
  CheckPicks(status, window, rayCastPlain, plain, plainTargets, "ray cast, polydata");
  vtkNew<vtkStylizedLineMapper> stylized;
  stylized->SetHaloWidth(0.5);
  CheckPicks(status, window, stylized, blocks, compositeTargets, "stylized, multiblock");
  vtkNew<vtkStylizedLineMapper> stylizedPlain;
  CheckPicks(status, window, stylizedPlain, plain, plainTargets, "stylized, polydata");
  window->Finalize();
  return status.Result();
}
