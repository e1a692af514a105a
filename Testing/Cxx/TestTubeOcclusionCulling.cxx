// SPDX-License-Identifier: BSD-3-Clause
// Occlusion culling of the line renderers (vtkSplineTubeMapper: chunks drawn
// front to back in groups, hidden ones never drawn, vtkSplineTubeVisibility)
// must not change the picture: the ray-cast tubes, the tessellated tubes and
// the stylized lines drawn with culling on and off give the same colors and
// depths, pixel for pixel (up to rounding ties), on a dense synthetic
// tractogram (bundles of overlapping streamlines, colored by a scalar) around
// an opaque sphere, in perspective, in parallel projection and with the
// camera among the lines, with depth peeling of a translucent sphere, with a
// clipping plane, and for hardware picking; the first frame with culling
// (no frame before it to start from) and the next one (which starts from the
// chunks visible in the first) both. Culling must also drop most of the
// chunks here (else the comparison would prove nothing).
//
// Negative control: a depth bias that hides visible chunks must be seen by
// the same comparison.
#include "vtkRayCastTubeMapper.h"
#include "vtkStylizedLineMapper.h"
#include "vtkSyntheticTractogramSource.h"
#include "vtkTessellatedTubeMapper.h"

#include "SplineVizRenderingTestUtilities.h"
#include "SplineVizTestUtilities.h"

#include "vtkHardwareSelector.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkLookupTable.h"
#include "vtkPlane.h"
#include "vtkProperty.h"
#include "vtkSelection.h"
#include "vtkSelectionNode.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <set>
#include <utility>

using namespace SplineVizTest;

namespace
{
const double BackgroundColor[3] = { 0.1, 0.1, 0.12 };
const int Background[3] = { 26, 26, 31 }; // 255 * BackgroundColor, rounded

void Report(const std::string& what, const PixelDifference& d)
{
  std::cout << what << ": covered " << d.Covered << " px, color differs on " << d.Color
            << ", depth on " << d.Depth << std::endl;
}

/// (prop, cell id) pairs selected over the whole window.
std::set<std::pair<vtkProp*, vtkIdType>> SelectAll(vtkRenderer* renderer, int width, int height)
{
  std::set<std::pair<vtkProp*, vtkIdType>> picked;
  vtkNew<vtkHardwareSelector> selector;
  selector->SetRenderer(renderer);
  selector->SetArea(0, 0, width - 1, height - 1);
  selector->SetFieldAssociation(vtkDataObject::FIELD_ASSOCIATION_CELLS);
  vtkSmartPointer<vtkSelection> selection = vtk::TakeSmartPointer(selector->Select());
  for (unsigned int n = 0; selection && n < selection->GetNumberOfNodes(); ++n)
  {
    vtkSelectionNode* node = selection->GetNode(n);
    vtkProp* prop = vtkProp::SafeDownCast(node->GetProperties()->Get(vtkSelectionNode::PROP()));
    vtkIdTypeArray* ids = vtkIdTypeArray::SafeDownCast(node->GetSelectionList());
    for (vtkIdType i = 0; ids && i < ids->GetNumberOfTuples(); ++i)
    {
      picked.insert({ prop, ids->GetValue(i) });
    }
  }
  return picked;
}

void TestMapper(SplineVizTestStatus& status, const std::string& name, vtkSplineTubeMapper* mapper,
  vtkPolyData* lines)
{
  std::cout << "== " << name << std::endl;
  vtkNew<vtkLookupTable> lut;
  lut->SetHueRange(0.66, 0.0);
  lut->Build();
  mapper->SetInputData(lines);
  mapper->SetRadius(0.25);
  mapper->SetLookupTable(lut);
  mapper->SetScalarRange(0.2, 0.9);
  mapper->InteractiveSubsetOff();
  vtkNew<vtkActor> tubes;
  tubes->SetMapper(mapper);
  tubes->GetProperty()->SetSpecular(0.3);

  vtkNew<vtkSphereSource> sphereSource;
  sphereSource->SetRadius(8.0);
  sphereSource->SetCenter(3.0, -2.0, 4.0);
  sphereSource->SetThetaResolution(48);
  sphereSource->SetPhiResolution(48);
  vtkNew<vtkPolyDataMapper> sphereMapper;
  sphereMapper->SetInputConnection(sphereSource->GetOutputPort());
  vtkNew<vtkActor> sphere;
  sphere->SetMapper(sphereMapper);
  sphere->GetProperty()->SetColor(0.85, 0.85, 0.8);

  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(BackgroundColor);
  renderer->AddActor(tubes);
  renderer->AddActor(sphere);
  vtkNew<vtkRenderWindow> window;
  const int width = 360, height = 300;
  window->SetSize(width, height);
  window->SetMultiSamples(0);
  window->AddRenderer(renderer);

  // Culling off, then on twice (the first frame after the off one has no
  // visible chunks to start from; the second has).
  auto onOff = [&](const std::string& what, bool culled)
  {
    mapper->OcclusionCullingOff();
    const Frame off = Grab(window);
    SV_CHECK_MSG(status, mapper->GetLastNumberOfChunksHidden() == 0,
      what << ": chunks hidden while culling is off");
    mapper->OcclusionCullingOn();
    for (int pass = 0; pass < 2; ++pass)
    {
      const Frame on = Grab(window);
      const vtkIdType inside = mapper->GetLastNumberOfChunksInFrustum();
      const vtkIdType hidden = mapper->GetLastNumberOfChunksHidden();
      std::cout << what << ", pass " << pass << ": " << hidden << " of " << inside
                << " chunks hidden, " << mapper->GetLastNumberOfDepthPyramids() << " pyramids"
                << std::endl;
      // (the first frame may draw all: small views hold a single group)
      SV_CHECK_MSG(status, culled ? (hidden > 0 || pass == 0) : hidden == 0,
        what << ": " << hidden << " chunks hidden (expected " << (culled ? "some" : "none") << ")");
      const PixelDifference d = ComparePixels(on, off, Background);
      Report(what + ", culling on vs off", d);
      SV_CHECK_MSG(status, d.Covered > 5000, what << ": too little covered: " << d.Covered);
      // Equal up to rounding ties: at most 0.02 % of the covered pixels.
      SV_CHECK_MSG(status, d.Color <= d.Covered / 5000,
        what << ": culling changes the color of " << d.Color << " pixels");
      SV_CHECK_MSG(status, d.Depth <= d.Covered / 5000,
        what << ": culling changes the depth of " << d.Depth << " pixels");
    }
    return off;
  };
  auto view = [&](int parallel, double distance) { SetOrbitView(renderer, parallel, distance); };

  // The whole tractogram in perspective: culling must drop a good share of
  // the chunks there (a fifth of them at this small size: lines a pixel or
  // two wide).
  view(0, 70.0);
  const Frame reference = onOff("perspective", true);
  Grab(window);
  const double share = static_cast<double>(mapper->GetLastNumberOfChunksHidden()) /
    std::max<vtkIdType>(mapper->GetLastNumberOfChunksInFrustum(), 1);
  SV_CHECK_MSG(status, share > 0.2, "only " << share << " of the chunks hidden");
  // Negative control: a bias hides visible chunks; the comparison must see it.
  mapper->SetOcclusionCullingDepthBias(0.05);
  Grab(window);
  const Frame biased = Grab(window);
  mapper->SetOcclusionCullingDepthBias(0.0);
  const PixelDifference wrong = ComparePixels(biased, reference, Background);
  Report("negative control: depth bias 0.05", wrong);
  SV_CHECK_MSG(status, wrong.Color > wrong.Covered / 1000,
    "the comparison cannot tell visible chunks culled: " << wrong.Color << " pixels differ");

  view(1, 70.0);
  onOff("parallel", true);
  // Among the lines: chunks around the eye are never hidden.
  view(0, 6.0);
  onOff("camera among the lines", true);

  // Depth peeling with a translucent sphere: the opaque lines are culled.
  view(0, 70.0);
  renderer->SetUseDepthPeeling(1);
  renderer->SetMaximumNumberOfPeels(8);
  renderer->SetOcclusionRatio(0.0);
  sphere->GetProperty()->SetOpacity(0.4);
  onOff("depth peeling, translucent sphere", true);
  // Translucent lines do not hide each other: no culling.
  tubes->GetProperty()->SetOpacity(0.6);
  onOff("translucent lines", false);
  tubes->GetProperty()->SetOpacity(1.0);
  sphere->GetProperty()->SetOpacity(1.0);
  renderer->SetUseDepthPeeling(0);

  // A clipping plane: what is drawn is in the depth buffer, culling stays exact.
  vtkNew<vtkPlane> plane;
  plane->SetOrigin(0.0, 0.0, 0.0);
  plane->SetNormal(0.3, 0.2, 1.0);
  mapper->AddClippingPlane(plane);
  onOff("clipping plane", true);
  mapper->RemoveAllClippingPlanes();

  // Hardware picking sees the same lines with and without culling.
  mapper->OcclusionCullingOff();
  const auto pickedOff = SelectAll(renderer, width, height);
  mapper->OcclusionCullingOn();
  const auto pickedOn = SelectAll(renderer, width, height);
  const auto tubesPicked = std::count_if(pickedOff.begin(), pickedOff.end(),
    [&](const std::pair<vtkProp*, vtkIdType>& p) { return p.first == tubes.GetPointer(); });
  std::cout << "picking: " << pickedOff.size() << " cells (" << tubesPicked
            << " lines) without culling, " << pickedOn.size() << " with" << std::endl;
  SV_CHECK_MSG(status, tubesPicked > 50, "too few lines picked: " << tubesPicked);
  SV_CHECK_MSG(status, pickedOn == pickedOff, "culling changes the picked cells");
}
}

int TestTubeOcclusionCulling(int, char*[])
{
  SplineVizTestStatus status;
  vtkNew<vtkSyntheticTractogramSource> source;
  source->SetNumberOfStreamlines(900);
  source->SetNumberOfBundles(12);
  source->SetMinimumPoints(30);
  source->SetMaximumPoints(60);
  source->SetBrainRadii(15.0, 18.0, 12.0);
  source->SetBundleRadiusRange(1.0, 2.5);
  source->Update();
  vtkPolyData* lines = source->GetOutput();

  vtkNew<vtkRayCastTubeMapper> raycast;
  TestMapper(status, "ray-cast tubes", raycast, lines);
  vtkNew<vtkTessellatedTubeMapper> tessellated;
  TestMapper(status, "tessellated tubes", tessellated, lines);
  vtkNew<vtkStylizedLineMapper> stylized;
  stylized->SetHaloWidth(0.4);
  TestMapper(status, "stylized lines", stylized, lines);
  return status.Result();
}
