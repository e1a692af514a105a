// SPDX-License-Identifier: BSD-3-Clause
// Per-block display attributes of composite inputs
// (vtkSuperquadricGlyphMapper::SetCompositeDataDisplayAttributes, as
// vtkCompositePolyDataMapper2 takes them): a three-block vtkMultiBlockDataSet,
// unlit solid-colored glyphs on black, the color at each glyph's center:
//  - without attributes every glyph is the actor's white;
//  - block 0 colored red, block 1 hidden, block 2 at opacity 0.5 (drawn in
//    the translucent pass, blended with the background);
//  - changing a block color recolors without uploading the tensors again;
//  - Principal Direction coloring keeps its colors, visibility still applies.
#include "vtkSuperquadricGlyphMapper.h"

#include "SplineVizTestUtilities.h"
#include "SuperquadricGlyphTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCompositeDataDisplayAttributes.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <array>
#include <iostream>

int TestSuperquadricGlyphBlocks(int, char*[])
{
  SplineVizTestStatus status;
  constexpr int W = 300, H = 240;
  // three blocks of four glyphs, one row each
  vtkNew<vtkMultiBlockDataSet> blocks;
  for (int b = 0; b < 3; ++b)
  {
    std::vector<std::array<double, 6>> t;
    for (int i = 0; i < 4; ++i)
    {
      sqtest::HandTensor h = { { 1.0, 0.6, 0.5 }, { 10.0 * i, 20, 30 }, "" };
      t.push_back(sqtest::Compose(h));
    }
    auto image = sqtest::TensorImage(t, 4);
    image->SetOrigin(0, b, 0);
    blocks->SetBlock(b, image);
  }
  vtkNew<vtkSuperquadricGlyphMapper> mapper;
  mapper->SetInputData(blocks);
  mapper->SetScaleFactor(0.4);
  mapper->SetGlyphColorModeToSolid();
  auto actor = sqtest::UnlitWhiteActor(mapper);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->SetBackground(0, 0, 0);
  vtkNew<vtkRenderWindow> window;
  window->SetSize(W, H);
  window->SetMultiSamples(0);
  window->AddRenderer(renderer);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetFocalPoint(1.5, 1.0, 0.0);
  camera->SetPosition(1.5, 1.0, 6.0);
  camera->SetViewUp(0, 1, 0);
  camera->SetClippingRange(1.0, 12.0);

  // the color at the center of glyph i of block b
  auto colorAt = [&](int b, int i)
  {
    renderer->SetWorldPoint(i, b, 0.0, 1.0);
    renderer->WorldToDisplay();
    const double* d = renderer->GetDisplayPoint();
    const int x = static_cast<int>(d[0]), y = static_cast<int>(d[1]);
    unsigned char* p = window->GetPixelData(x, y, x, y, 0);
    std::array<int, 3> c = { p[0], p[1], p[2] };
    delete[] p;
    return c;
  };
  auto near = [](const std::array<int, 3>& c, int r, int g, int b)
  { return std::abs(c[0] - r) <= 3 && std::abs(c[1] - g) <= 3 && std::abs(c[2] - b) <= 3; };

  window->Render();
  int white = 0;
  for (int b = 0; b < 3; ++b)
    for (int i = 0; i < 4; ++i)
      white += near(colorAt(b, i), 255, 255, 255);
  std::cout << white << " of 12 glyphs white without attributes" << std::endl;
  SV_CHECK(status, white == 12);
  const int uploads = mapper->GetUploadCount();

  vtkNew<vtkCompositeDataDisplayAttributes> attributes;
  const double redColor[3] = { 1.0, 0.0, 0.0 };
  attributes->SetBlockColor(blocks->GetBlock(0), redColor);
  attributes->SetBlockVisibility(blocks->GetBlock(1), false);
  attributes->SetBlockOpacity(blocks->GetBlock(2), 0.5);
  mapper->SetCompositeDataDisplayAttributes(attributes);
  SV_CHECK(status, mapper->HasTranslucentPolygonalGeometry());
  window->Render();
  int red = 0, hidden = 0, half = 0;
  for (int i = 0; i < 4; ++i)
  {
    red += near(colorAt(0, i), 255, 0, 0);
    hidden += near(colorAt(1, i), 0, 0, 0);
    half += near(colorAt(2, i), 128, 128, 128);
  }
  std::cout << "attributes: " << red << " red, " << hidden << " hidden, " << half
            << " half transparent (of 4 each)" << std::endl;
  SV_CHECK(status, red == 4 && hidden == 4 && half == 4);

  const double greenColor[3] = { 0.0, 1.0, 0.0 };
  attributes->SetBlockColor(blocks->GetBlock(0), greenColor);
  attributes->RemoveBlockOpacities();
  SV_CHECK(status, !mapper->HasTranslucentPolygonalGeometry());
  window->Render();
  int green = 0, opaque = 0;
  for (int i = 0; i < 4; ++i)
  {
    green += near(colorAt(0, i), 0, 255, 0);
    opaque += near(colorAt(2, i), 255, 255, 255);
  }
  SV_CHECK(status, green == 4 && opaque == 4);
  SV_CHECK_MSG(status, mapper->GetUploadCount() == uploads, "a block color re-uploaded tensors");

  // Principal direction colors stay; hidden blocks stay hidden.
  mapper->SetGlyphColorModeToEigenvector();
  window->Render();
  int kept = 0;
  for (int i = 0; i < 4; ++i)
  {
    const auto c = colorAt(0, i);
    kept += !near(c, 0, 255, 0) && (c[0] + c[1] + c[2]) > 0;
    hidden += near(colorAt(1, i), 0, 0, 0);
  }
  SV_CHECK(status, kept == 4 && hidden == 8);
  return status.Result();
}
