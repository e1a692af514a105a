// SPDX-License-Identifier: BSD-3-Clause
// vtkLineAmbientOcclusionPass: the halos it draws (tiles that can hold one,
// per-pixel bounds on what each ring of samples can give, searches that stop
// once a bound is reached) against the search without bounds (every tile,
// every pixel sampling until full coverage; the pass's HaloFullSearch, for
// tests only), on synthetic tractograms at 600 x 384:
//  - sparse (2,000 streamlines, tessellated tubes), the defaults with
//    ambient occlusion;
//  - dense (20,000 streamlines, stylized lines), halos alone;
//  - sparse (ray-cast tubes), halo color blue (so that the halos on the
//    background show), width 12 pixels (larger blocks), depth range 0 (full
//    halos at once), parallel projection;
//  - sparse (tessellated tubes), offset and range in world units.
// The two pictures must agree within 1/255 in every value; as a control, the
// halos must change at least 1 % of the values of the picture without them.
// SPLINEVIZ_TEST_IMAGES=<dir> writes the renderings as PNG files.
#include "vtkLineAmbientOcclusionPass.h"
#include "vtkRayCastTubeMapper.h"
#include "vtkStylizedLineMapper.h"
#include "vtkSyntheticTractogramSource.h"
#include "vtkTessellatedTubeMapper.h"

#include "SplineVizRenderingTestUtilities.h"
#include "SplineVizTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <algorithm>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <string>

namespace
{
/// The pass with the search without bounds.
class FullSearchPass : public vtkLineAmbientOcclusionPass
{
public:
  static FullSearchPass* New();
  vtkTypeMacro(FullSearchPass, vtkLineAmbientOcclusionPass);

protected:
  FullSearchPass() { this->HaloFullSearch = true; }
  ~FullSearchPass() override = default;

private:
  FullSearchPass(const FullSearchPass&) = delete;
  void operator=(const FullSearchPass&) = delete;
};
vtkStandardNewMacro(FullSearchPass);

using PassSetup = std::function<void(vtkLineAmbientOcclusionPass*)>;

/// `lines` drawn by `mapper` through `pass` configured by `setup`.
SplineVizTest::Frame Render(vtkRenderWindow* window, vtkSplineTubeMapper* mapper, bool parallel,
  vtkLineAmbientOcclusionPass* pass, const PassSetup& setup, const std::string& name)
{
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.8, 0.35, 0.2);
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(1.0, 1.0, 1.0);
  renderer->AddActor(actor);
  vtkNew<vtkRenderStepsPass> steps;
  pass->SetDelegatePass(steps);
  setup(pass);
  renderer->SetPass(pass);
  window->AddRenderer(renderer);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetParallelProjection(parallel);
  renderer->ResetCamera();
  camera->Zoom(1.3);
  camera->Azimuth(20.0);
  camera->Elevation(10.0);
  renderer->ResetCameraClippingRange();
  SplineVizTest::Frame frame = SplineVizTest::Grab(window);
  window->RemoveRenderer(renderer);
  SplineVizTest::Save(frame, name);
  return frame;
}

void Compare(SplineVizTestStatus& status, vtkRenderWindow* window, vtkSplineTubeMapper* mapper,
  bool parallel, const PassSetup& setup, const std::string& name)
{
  auto withoutHalos = [&](vtkLineAmbientOcclusionPass* p)
  {
    setup(p);
    p->DepthHalosOff();
  };
  vtkNew<vtkLineAmbientOcclusionPass> plainPass;
  const auto plain = Render(window, mapper, parallel, plainPass, withoutHalos, name + "-plain");
  vtkNew<vtkLineAmbientOcclusionPass> bounded;
  const auto halos = Render(window, mapper, parallel, bounded, setup, name);
  vtkNew<FullSearchPass> full;
  const auto reference = Render(window, mapper, parallel, full, setup, name + "-full");
  int largest = 0;
  long differing = 0;
  long haloed = 0;
  for (size_t i = 0; i < halos.RGB.size(); ++i)
  {
    const int d = std::abs(static_cast<int>(halos.RGB[i]) - static_cast<int>(reference.RGB[i]));
    largest = std::max(largest, d);
    differing += d > 0 ? 1 : 0;
    haloed += halos.RGB[i] != plain.RGB[i] ? 1 : 0;
  }
  std::cout << name << ": " << haloed << " of " << halos.RGB.size()
            << " values changed by the halos; against the full search " << differing
            << " differ, by at most " << largest << "/255" << std::endl;
  SV_CHECK_MSG(status, haloed > static_cast<long>(halos.RGB.size() / 100),
    name << ": the halos changed only " << haloed << " values");
  SV_CHECK_MSG(status, largest <= 1,
    name << ": " << differing << " values differ from the full search, by up to " << largest);
}

vtkSmartPointer<vtkPolyData> Tractogram(vtkIdType streamlines)
{
  vtkNew<vtkSyntheticTractogramSource> source;
  source->SetNumberOfStreamlines(streamlines);
  source->Update();
  return source->GetOutput();
}
}

int TestLineAmbientOcclusionHalos(int, char*[])
{
  SplineVizTestStatus status;
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(600, 384);

  auto sparse = Tractogram(2000);
  auto dense = Tractogram(20000);
  auto setupMapper = [](vtkSplineTubeMapper* m, vtkPolyData* lines)
  {
    m->SetInputData(lines);
    m->SetRadius(0.3);
    m->ScalarVisibilityOff();
  };

  vtkNew<vtkTessellatedTubeMapper> tessellated;
  setupMapper(tessellated, sparse);
  Compare(
    status, window, tessellated, false, [](vtkLineAmbientOcclusionPass* p) { p->DepthHalosOn(); },
    "halos-sparse");

  vtkNew<vtkStylizedLineMapper> stylized;
  setupMapper(stylized, dense);
  Compare(
    status, window, stylized, false,
    [](vtkLineAmbientOcclusionPass* p)
    {
      p->AmbientOcclusionOff();
      p->DepthHalosOn();
    },
    "halos-dense");

  vtkNew<vtkRayCastTubeMapper> raycast;
  setupMapper(raycast, sparse);
  Compare(
    status, window, raycast, true,
    [](vtkLineAmbientOcclusionPass* p)
    {
      p->AmbientOcclusionOff();
      p->DepthHalosOn();
      p->SetHaloWidth(12.0);
      p->SetHaloDepthRange(0.0);
      p->HaloColorFromBackgroundOff();
      p->SetHaloColor(0.1, 0.3, 1.0);
    },
    "halos-wide-parallel");

  Compare(
    status, window, tessellated, false,
    [](vtkLineAmbientOcclusionPass* p)
    {
      p->AmbientOcclusionOff();
      p->DepthHalosOn();
      p->SetLengthUnitsToWorld();
      p->SetHaloDepthOffset(2.0);
      p->SetHaloDepthRange(10.0);
    },
    "halos-world");
  return status.Result();
}
