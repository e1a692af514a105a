// SPDX-License-Identifier: BSD-3-Clause
// Hardware picking of ray-cast tubes: a multiblock of two polydata blocks,
// each with polylines at known places. Selecting a rectangle around each
// tube must report that tube's polyline (cell id) and block (composite
// index), with the same conventions as VTK's own composite mapper drawing
// the same polylines as wide lines.
#include "vtkRayCastTubeMapper.h"

#include "SplineVizRenderingTestUtilities.h"
#include "SplineVizTestUtilities.h"

#include "vtkHardwareSelector.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkProperty.h"
#include "vtkSelection.h"
#include "vtkSelectionNode.h"
#include "vtkVersionMacros.h"

// VTK's OpenGL composite mapper: vtkCompositePolyDataMapper from VTK 9.3 on
// (vtkCompositePolyDataMapper2 is deprecated there).
#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 3, 0)
#include "vtkCompositePolyDataMapper.h"
using vtkOpenGLCompositeMapper = vtkCompositePolyDataMapper;
#else
#include "vtkCompositePolyDataMapper2.h"
using vtkOpenGLCompositeMapper = vtkCompositePolyDataMapper2;
#endif

#include <map>
#include <set>
#include <utility>

using namespace SplineVizTest;

namespace
{
/// (composite index, cell id) pairs selected in the rectangle.
std::set<std::pair<unsigned int, vtkIdType>> Select(
  vtkRenderer* renderer, unsigned int x0, unsigned int y0, unsigned int x1, unsigned int y1)
{
  std::set<std::pair<unsigned int, vtkIdType>> picked;
  vtkNew<vtkHardwareSelector> selector;
  selector->SetRenderer(renderer);
  selector->SetArea(x0, y0, x1, y1);
  selector->SetFieldAssociation(vtkDataObject::FIELD_ASSOCIATION_CELLS);
  vtkSmartPointer<vtkSelection> selection = vtk::TakeSmartPointer(selector->Select());
  for (unsigned int n = 0; selection && n < selection->GetNumberOfNodes(); ++n)
  {
    vtkSelectionNode* node = selection->GetNode(n);
    const unsigned int composite = node->GetProperties()->Has(vtkSelectionNode::COMPOSITE_INDEX())
      ? static_cast<unsigned int>(node->GetProperties()->Get(vtkSelectionNode::COMPOSITE_INDEX()))
      : 0u;
    vtkIdTypeArray* ids = vtkIdTypeArray::SafeDownCast(node->GetSelectionList());
    for (vtkIdType i = 0; ids && i < ids->GetNumberOfTuples(); ++i)
    {
      picked.insert({ composite, ids->GetValue(i) });
    }
  }
  return picked;
}
}

int TestRayCastTubePicking(int, char*[])
{
  SplineVizTestStatus status;
  // Block 0: two horizontal tubes (cells 0, 1); block 1: one vertex cell
  // (cell 0, not a tube) and two more tubes (cells 1, 2).
  auto line = [](double x0, double y0, double x1, double y1)
  {
    std::vector<Vec4> c;
    for (int i = 0; i <= 8; ++i)
    {
      const double t = i / 8.0;
      c.push_back({ x0 + t * (x1 - x0), y0 + t * (y1 - y0), 0.0, 0.06 });
    }
    return c;
  };
  auto block0 = MakePolylines({ line(-0.9, 0.6, -0.1, 0.6), line(-0.9, -0.6, -0.1, -0.6) });
  auto block1 = MakePolylines({ line(0.1, 0.6, 0.9, 0.6), line(0.1, -0.6, 0.9, -0.6) });
  {
    // prepend a vertex cell: the polylines become cells 1 and 2
    vtkNew<vtkCellArray> verts;
    verts->InsertNextCell(1);
    verts->InsertCellPoint(0);
    block1->SetVerts(verts);
  }
  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetNumberOfBlocks(2);
  blocks->SetBlock(0, block0);
  blocks->SetBlock(1, block1);

  vtkNew<vtkRenderWindow> window;
  window->SetSize(400, 400);
  window->SetMultiSamples(0);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  renderer->GetActiveCamera()->SetPosition(0, 0, 4);
  renderer->GetActiveCamera()->SetFocalPoint(0, 0, 0);
  renderer->GetActiveCamera()->SetParallelProjection(1);
  renderer->GetActiveCamera()->SetParallelScale(1.0);
  renderer->GetActiveCamera()->SetClippingRange(1, 10);

  // Quadrant rectangles (pixels) and what they should pick: (block, cell).
  // Block flat indices in a two-block multiblock are 1 and 2.
  const unsigned int q[4][4] = { { 40, 260, 180, 380 }, { 40, 20, 180, 140 },
    { 220, 260, 360, 380 }, { 220, 20, 360, 140 } };

  // VTK's own composite mapper, the tubes as wide lines: the conventions.
  vtkNew<vtkOpenGLCompositeMapper> vtkMapper;
  vtkMapper->SetInputDataObject(blocks);
  vtkNew<vtkActor> lines;
  lines->SetMapper(vtkMapper);
  lines->GetProperty()->SetLineWidth(8);
  renderer->AddActor(lines);
  window->Render();
  std::set<std::pair<unsigned int, vtkIdType>> expected[4];
  for (int i = 0; i < 4; ++i)
  {
    expected[i] = Select(renderer, q[i][0], q[i][1], q[i][2], q[i][3]);
    SV_CHECK_MSG(status, expected[i].size() == 1,
      "VTK mapper, quadrant " << i << ": " << expected[i].size() << " cells");
  }

  renderer->RemoveAllViewProps();
  vtkNew<vtkRayCastTubeMapper> mapper;
  mapper->SetInputDataObject(blocks);
  mapper->SetRadiusArray("Radius");
  vtkNew<vtkActor> tubes;
  tubes->SetMapper(mapper);
  renderer->AddActor(tubes);
  window->Render();
  for (int i = 0; i < 4; ++i)
  {
    const auto picked = Select(renderer, q[i][0], q[i][1], q[i][2], q[i][3]);
    for (const auto& p : picked)
    {
      std::cout << "quadrant " << i << ": block " << p.first << ", cell " << p.second << std::endl;
    }
    SV_CHECK_MSG(status, picked == expected[i],
      "quadrant " << i << ": the tubes pick differently from VTK's mapper");
  }
  // Sanity: the expected picks are the documented cells.
  SV_CHECK(status, expected[0].count({ 1u, 0 }) == 1 || expected[0].count({ 0u, 0 }) == 1);
  SV_CHECK(status, expected[3].size() == 1 && expected[3].begin()->second == 2);
  // A plain polydata input: the polyline's cell id.
  mapper->SetInputData(block1);
  window->Render();
  const auto plain = Select(renderer, q[3][0], q[3][1], q[3][2], q[3][3]);
  SV_CHECK_MSG(status, plain.size() == 1 && plain.begin()->second == 2,
    "plain polydata: " << plain.size() << " cells picked");
  mapper->SetInputDataObject(blocks);
  window->Render();
  // An empty area picks nothing.
  SV_CHECK(status, Select(renderer, 190, 190, 210, 210).empty());
  return status.Result();
}
