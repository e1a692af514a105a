// Occlusion culling of vtkRayCastTubeMapper (its depth pre-pass of bands
// inside the tubes) must not change the picture: the same tubes drawn with
// culling on and off give the same colors and depths, pixel for pixel (up to
// rounding ties), on a dense bundle (vtkSyntheticFibersSource's "Fibers",
// 3,530 segments, colored by a scalar) crossing an opaque sphere, in
// perspective, in parallel projection and with the camera among the tubes,
// with depth peeling of a translucent sphere, and for hardware picking.
// Translucent tubes and clipping planes must draw without the pre-pass.
//
// Negative control: bands 1.5 times wider than the proved bound stick out
// of the tubes and cull visible fragments; the same comparison must see it
// (which also shows the pre-pass really culls: if it culled nothing, the
// wider bands could not change the picture either).
#include "vtkRayCastTubeMapper.h"
#include "vtkSyntheticFibersSource.h"

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

struct Difference
{
  long Covered = 0;
  long Color = 0; ///< pixels with a channel differing by more than 2
  long Depth = 0; ///< pixels whose window depth differs by more than 1e-5
};

Difference Compare(const Frame& a, const Frame& b)
{
  Difference d;
  for (int i = 0; i < a.Width * a.Height; ++i)
  {
    // Covered: something in front of the background (translucent tubes
    // write no depth, so their color counts too).
    bool covered = a.Depth[i] < 1.0f || b.Depth[i] < 1.0f;
    for (int c = 0; c < 3; ++c)
    {
      covered = covered || std::abs(int(a.RGB[3 * i + c]) - Background[c]) > 3 ||
        std::abs(int(b.RGB[3 * i + c]) - Background[c]) > 3;
    }
    if (covered)
    {
      ++d.Covered;
    }
    int worst = 0;
    for (int c = 0; c < 3; ++c)
    {
      worst = std::max(worst, std::abs(int(a.RGB[3 * i + c]) - int(b.RGB[3 * i + c])));
    }
    if (worst > 2)
    {
      ++d.Color;
    }
    if (std::abs(a.Depth[i] - b.Depth[i]) > 1e-5f)
    {
      ++d.Depth;
    }
  }
  return d;
}

void Report(const std::string& what, const Difference& d)
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
}

int TestRayCastTubeCulling(int, char*[])
{
  SplineVizTestStatus status;
  vtkNew<vtkSyntheticFibersSource> source;
  source->SetPresetToFibers();
  source->Update();
  vtkPolyData* fibers = source->GetOutput();
  fibers->GetPointData()->SetActiveScalars("Scalar");
  const double box = source->GetBoxSize();

  vtkNew<vtkLookupTable> lut;
  lut->SetHueRange(0.66, 0.0);
  lut->Build();
  vtkNew<vtkRayCastTubeMapper> mapper;
  mapper->SetInputData(fibers);
  mapper->SetRadiusArray("Radius");
  mapper->SetLookupTable(lut);
  mapper->SetScalarRange(0.0, 1.0);
  vtkNew<vtkActor> tubes;
  tubes->SetMapper(mapper);
  tubes->GetProperty()->SetSpecular(0.3);

  vtkNew<vtkSphereSource> sphereSource;
  sphereSource->SetRadius(0.2 * box);
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
  const int width = 600, height = 450;
  window->SetSize(width, height);
  window->SetMultiSamples(0);
  window->AddRenderer(renderer);
  vtkCamera* camera = renderer->GetActiveCamera();

  // Culling on and off; `culled` says whether the pre-pass must have run.
  auto onOff = [&](const std::string& what, bool culled)
  {
    mapper->OcclusionCullingOff();
    const Frame off = Grab(window);
    SV_CHECK_MSG(status, !mapper->GetLastRenderCulled(), what << ": culled while off");
    mapper->OcclusionCullingOn();
    const Frame on = Grab(window);
    SV_CHECK_MSG(status, mapper->GetLastRenderCulled() == culled,
      what << ": the pre-pass " << (culled ? "did not run" : "ran"));
    const Difference d = Compare(on, off);
    Report(what + ", culling on vs off", d);
    SV_CHECK_MSG(status, d.Covered > 10000, what << ": too little covered: " << d.Covered);
    // Equal up to rounding ties: at most 0.02 % of the covered pixels.
    SV_CHECK_MSG(status, d.Color <= d.Covered / 5000,
      what << ": culling changes the color of " << d.Color << " pixels");
    SV_CHECK_MSG(status, d.Depth <= d.Covered / 5000,
      what << ": culling changes the depth of " << d.Depth << " pixels");
    return std::make_pair(off, d.Covered);
  };

  auto view = [&](int parallel, double distance)
  {
    camera->SetFocalPoint(0.0, 0.0, 0.0);
    camera->SetPosition(0.35 * distance * box, 0.25 * distance * box, distance * box);
    camera->SetViewUp(0, 1, 0);
    camera->SetViewAngle(30);
    camera->SetParallelProjection(parallel);
    camera->SetParallelScale(0.6 * box);
    renderer->ResetCameraClippingRange();
  };

  // The whole bundle in perspective: the negative control too.
  view(0, 2.2);
  const auto reference = onOff("perspective", true);
  mapper->SetCullingBandScale(1.5);
  const Frame wide = Grab(window);
  mapper->SetCullingBandScale(1.0);
  const Difference wrong = Compare(wide, reference.first);
  Report("negative control: bands 1.5x wider", wrong);
  SV_CHECK_MSG(status, wrong.Color > reference.second / 200,
    "the comparison cannot tell bands that stick out of the tubes: " << wrong.Color
                                                                     << " pixels differ");

  view(1, 2.2);
  onOff("parallel", true);
  // Among the tubes: segments the eye may be inside of get no band.
  view(0, 0.3);
  onOff("camera among the tubes", true);

  // Depth peeling with a translucent sphere: the opaque tubes are culled.
  view(0, 2.2);
  renderer->SetUseDepthPeeling(1);
  renderer->SetMaximumNumberOfPeels(8);
  renderer->SetOcclusionRatio(0.0);
  sphere->GetProperty()->SetOpacity(0.4);
  onOff("depth peeling, translucent sphere", true);
  // Translucent tubes: no pre-pass (they do not hide each other).
  tubes->GetProperty()->SetOpacity(0.6);
  onOff("translucent tubes", false);
  tubes->GetProperty()->SetOpacity(1.0);
  sphere->GetProperty()->SetOpacity(1.0);
  renderer->SetUseDepthPeeling(0);

  // Clipping planes: no pre-pass (a clipped tube hides nothing).
  vtkNew<vtkPlane> plane;
  plane->SetOrigin(0.0, 0.0, 0.0);
  plane->SetNormal(0.3, 0.2, 1.0);
  mapper->AddClippingPlane(plane);
  onOff("clipping plane", false);
  mapper->RemoveAllClippingPlanes();

  // Hardware picking sees the same tubes with and without culling.
  mapper->OcclusionCullingOff();
  const auto pickedOff = SelectAll(renderer, width, height);
  mapper->OcclusionCullingOn();
  const auto pickedOn = SelectAll(renderer, width, height);
  const auto tubesPicked = std::count_if(pickedOff.begin(), pickedOff.end(),
    [&](const std::pair<vtkProp*, vtkIdType>& p) { return p.first == tubes.GetPointer(); });
  std::cout << "picking: " << pickedOff.size() << " cells (" << tubesPicked
            << " tubes) without culling, " << pickedOn.size() << " with" << std::endl;
  SV_CHECK_MSG(status, tubesPicked > 50, "too few tubes picked: " << tubesPicked);
  SV_CHECK_MSG(status, pickedOn == pickedOff, "culling changes the picked cells");
  return status.Result();
}
