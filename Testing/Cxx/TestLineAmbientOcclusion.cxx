// SPDX-License-Identifier: BSD-3-Clause
// vtkLineAmbientOcclusionPass: ambient occlusion and depth-dependent halos
// from the depth buffer, for the three line mappers and plain polygons.
//  1. Against an independent expectation: a flat floor with a step (a plane
//     `gap` in front of it over x > 0), orthographic, unlit white. The
//     occlusion of a floor pixel at distance s from the step is the documented
//     estimator's mean over its sampling disk, integrated here by quadrature
//     over the part of the disk that lies on the step (the floor itself, at
//     right angles to its normal, does not occlude). The measured darkening
//     (mean over a column of pixels, Strength 3) must follow the integral
//     within 0.02 at every distance; as a control, the integral for a twice
//     deeper step must miss the measurement where it matters.
//  2. Lines, for each mapper (ray-cast, tessellated, stylized): a layer of
//     tubes along x with a crossing layer resting on it (default settings).
//     The lower tubes within 3 pixels of the upper ones (the crevice) darken
//     by more than 4 % on average and ten times more than a tube alone, which
//     keeps its own pixels within 3 % on average.
//  3. Controls: the pass with everything off, and on with Strength 0, gives
//     exactly the plain rendering; on, the picture differs.
//  4. Halos: a front tube crossing a back tube never changes its own pixels
//     (halos on against off); the back tube's pixels turned to the halo color
//     next to the front one are fewer for a small depth gap than for a large
//     one, and none below HaloDepthOffset.
// SPLINEVIZ_TEST_IMAGES=<dir> writes the renderings as PNG files.
#include "vtkLineAmbientOcclusionPass.h"
#include "vtkRayCastTubeMapper.h"
#include "vtkStylizedLineMapper.h"
#include "vtkTessellatedTubeMapper.h"

#include "SplineVizRenderingTestUtilities.h"
#include "SplineVizTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <cmath>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

namespace
{
const int Size = 240;

using PassSetup = std::function<void(vtkLineAmbientOcclusionPass*)>;

/// Render `props` (unlit white on black unless `lit`) through the pass
/// configured by `setup` (none: plain rendering).
SplineVizTest::Frame RenderScene(vtkRenderWindow* window, const std::vector<vtkActor*>& actors,
  const std::function<void(vtkCamera*)>& camera, const PassSetup& setup, const std::string& name)
{
  vtkNew<vtkRenderer> renderer;
  for (vtkActor* a : actors)
  {
    renderer->AddActor(a);
  }
  renderer->SetBackground(0.0, 0.0, 0.0);
  vtkNew<vtkRenderStepsPass> steps;
  vtkNew<vtkLineAmbientOcclusionPass> pass;
  pass->SetDelegatePass(steps);
  if (setup)
  {
    setup(pass);
    renderer->SetPass(pass);
  }
  window->AddRenderer(renderer);
  camera(renderer->GetActiveCamera()); // (with a fixed clipping range)
  SplineVizTest::Frame frame = SplineVizTest::Grab(window);
  window->RemoveRenderer(renderer);
  SplineVizTest::Save(frame, name);
  return frame;
}

vtkSmartPointer<vtkActor> Flat(vtkMapper* mapper, double gray = 1.0)
{
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(gray, gray, gray);
  actor->GetProperty()->SetAmbient(1.0);
  actor->GetProperty()->SetDiffuse(0.0);
  actor->GetProperty()->SetSpecular(0.0);
  return actor;
}

vtkSmartPointer<vtkPolyData> Quad(double x0, double x1, double y0, double y1, double z)
{
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(x0, y0, z);
  points->InsertNextPoint(x1, y0, z);
  points->InsertNextPoint(x1, y1, z);
  points->InsertNextPoint(x0, y1, z);
  vtkNew<vtkCellArray> polys;
  const vtkIdType ids[4] = { 0, 1, 2, 3 };
  polys->InsertNextCell(4, ids);
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->SetPoints(points);
  out->SetPolys(polys);
  return out;
}

/// Expected occlusion of the floor at distance s (world) before a step of
/// height `gap` (world), hemisphere radius R (world) per level: the estimator
/// averaged over the sampling disk of each level (area-uniform), by midpoint
/// quadrature in polar coordinates.
double StepOcclusion(double s, double gap, double radius, int levels, double bias)
{
  double total = 0.0;
  for (int l = 0; l < levels; ++l)
  {
    const double r = radius * std::pow(2.0, l - levels + 1);
    const int nr = 200;
    const int na = 400;
    double sum = 0.0;
    for (int i = 0; i < nr; ++i)
    {
      const double rho = r * (i + 0.5) / nr;
      for (int j = 0; j < na; ++j)
      {
        const double phi = 2.0 * vtkMath::Pi() * (j + 0.5) / na;
        if (rho * std::cos(phi) <= s)
        {
          continue; // on the floor
        }
        const double vv = rho * rho + gap * gap;
        const double c = std::max(0.0, gap / std::sqrt(vv) - bias) / (1.0 - bias);
        sum += c * std::max(0.0, 1.0 - vv / (r * r)) * rho;
      }
    }
    // Area element rho drho dphi over the disk's area.
    total += sum * (r / nr) * (2.0 * vtkMath::Pi() / na) / (vtkMath::Pi() * r * r);
  }
  return total / levels;
}

double Gray(const SplineVizTest::Frame& f, int x, int y)
{
  return f.RGB[3 * (y * f.Width + x)] / 255.0;
}

/// 1. The step against the quadrature.
void TestStep(SplineVizTestStatus& status, vtkRenderWindow* window)
{
  const double pixel = 0.01; // world units per pixel: parallel scale Size / 2 pixels
  const double gap = 4.0 * pixel;
  const double radius = 16.0; // pixels
  const int levels = 2;
  const double bias = 0.1;
  const double strength = 3.0;
  vtkNew<vtkPolyDataMapper> floorMapper;
  floorMapper->SetInputData(Quad(-2, 2, -2, 2, 0.0));
  vtkNew<vtkPolyDataMapper> stepMapper;
  stepMapper->SetInputData(Quad(0.0, 2, -2, 2, gap));
  auto floor = Flat(floorMapper);
  auto step = Flat(stepMapper);
  auto camera = [&](vtkCamera* c)
  {
    c->ParallelProjectionOn();
    c->SetParallelScale(pixel * Size / 2.0);
    c->SetFocalPoint(0, 0, 0);
    c->SetPosition(0, 0, 5);
    c->SetViewUp(0, 1, 0);
    c->SetClippingRange(1.0, 10.0);
  };
  auto frame = RenderScene(
    window, { floor, step }, camera,
    [&](vtkLineAmbientOcclusionPass* p)
    {
      p->SetRadius(radius);
      p->SetLevels(levels);
      p->SetSamples(32);
      p->SetBias(bias);
      p->SetStrength(strength);
    },
    "ao-step");
  double worst = 0.0;
  double worstControl = 1.0;
  for (int d = 1; d <= static_cast<int>(radius) + 2; ++d)
  {
    // Floor pixel column d pixels left of the edge (x = 0 at the window's center line).
    const int x = Size / 2 - d;
    double mean = 0.0;
    const int y0 = 20;
    const int y1 = Size - 20;
    for (int y = y0; y < y1; ++y)
    {
      mean += 1.0 - Gray(frame, x, y);
    }
    mean /= (y1 - y0);
    const double s = (d - 0.5) * pixel;
    const double expected = strength * StepOcclusion(s, gap, radius * pixel, levels, bias);
    const double control = strength * StepOcclusion(s, 2.0 * gap, radius * pixel, levels, bias);
    std::cout << "step, " << d << " px from the edge: darkening " << mean << ", expected "
              << expected << " (a twice deeper step: " << control << ")" << std::endl;
    worst = std::max(worst, std::abs(mean - expected));
    if (expected > 0.15)
    {
      worstControl = std::min(worstControl, std::abs(mean - control));
    }
  }
  SV_CHECK_MSG(status, worst < 0.02, "occlusion off the expectation by " << worst);
  SV_CHECK_MSG(status, worstControl > 0.02 && worstControl < 1.0, "the control is not told apart");
  // The step's own top is not occluded (nothing nearer), the floor far away neither.
  double top = 0.0;
  double far = 0.0;
  for (int y = 20; y < Size - 20; ++y)
  {
    top += 1.0 - Gray(frame, Size / 2 + 30, y);
    far += 1.0 - Gray(frame, 20, y);
  }
  SV_CHECK_MSG(
    status, top == 0.0 && far == 0.0, "unoccluded pixels darkened: " << top << " " << far);
}

/// Straight polylines along x (dir 0) or y (dir 1) at height z, `count` of
/// them `spacing` apart, radius r.
vtkSmartPointer<vtkPolyData> Layer(int dir, int count, double spacing, double z, double r)
{
  std::vector<std::vector<SplineVizTest::Vec4>> curves;
  for (int k = 0; k < count; ++k)
  {
    const double c = (k - 0.5 * (count - 1)) * spacing;
    std::vector<SplineVizTest::Vec4> line;
    for (int i = 0; i <= 10; ++i)
    {
      const double s = -1.2 + 0.24 * i;
      line.push_back(
        dir == 0 ? SplineVizTest::Vec4{ s, c, z, r } : SplineVizTest::Vec4{ c, s, z, r });
    }
    curves.push_back(line);
  }
  return SplineVizTest::MakePolylines(curves);
}

vtkSmartPointer<vtkSplineTubeMapper> MakeMapper(int kind, vtkPolyData* lines)
{
  vtkSmartPointer<vtkSplineTubeMapper> m;
  if (kind == 0)
  {
    m = vtkSmartPointer<vtkRayCastTubeMapper>::New();
  }
  else if (kind == 1)
  {
    m = vtkSmartPointer<vtkTessellatedTubeMapper>::New();
  }
  else
  {
    m = vtkSmartPointer<vtkStylizedLineMapper>::New();
  }
  m->SetInputData(lines);
  m->SetRadiusArray("Radius");
  m->ScalarVisibilityOff();
  return m;
}

void TopView(vtkCamera* c)
{
  c->SetFocalPoint(0, 0, 0);
  c->SetPosition(0, 0, 10);
  c->SetViewUp(0, 1, 0);
  c->SetViewAngle(14.0);
  c->SetClippingRange(7.0, 13.0);
}

/// 2. and 3. for one mapper kind.
void TestLines(SplineVizTestStatus& status, vtkRenderWindow* window, int kind)
{
  const char* names[3] = { "raycast", "tessellated", "stylized" };
  const std::string name = names[kind];
  const double r = 0.06;
  auto lower = MakeMapper(kind, Layer(0, 5, 0.36, 0.0, r));
  auto upper = MakeMapper(kind, Layer(1, 5, 0.36, 2.0 * r, r));
  auto lowerActor = Flat(lower, 0.8);
  auto upperActor = Flat(upper, 0.8);
  auto ao = [](vtkLineAmbientOcclusionPass*) {}; // the defaults
  const auto plain =
    RenderScene(window, { lowerActor, upperActor }, TopView, nullptr, "ao-" + name + "-off");
  const auto shaded =
    RenderScene(window, { lowerActor, upperActor }, TopView, ao, "ao-" + name + "-on");
  // The crevice: visible lower-layer pixels (where the plain picture shows
  // the depth of the lower layer drawn alone) within 3 pixels of an upper
  // one (the upper tubes run along y: left or right).
  const auto lowerAlone =
    RenderScene(window, { lowerActor }, TopView, nullptr, "ao-" + name + "-lower");
  auto isLower = [&](int x, int y)
  {
    const size_t i = static_cast<size_t>(y) * Size + x;
    return plain.Covered(x, y) && std::abs(plain.Depth[i] - lowerAlone.Depth[i]) < 1e-6f;
  };
  double crevice = 0.0;
  long creviceCount = 0;
  for (int y = 0; y < Size; ++y)
  {
    for (int x = 3; x < Size - 3; ++x)
    {
      if (!isLower(x, y))
      {
        continue;
      }
      bool beside = false;
      for (int dx = -3; dx <= 3; ++dx)
      {
        beside = beside || (plain.Covered(x + dx, y) && !isLower(x + dx, y));
      }
      if (beside)
      {
        const size_t i = static_cast<size_t>(y) * Size + x;
        crevice += 1.0 - (shaded.RGB[3 * i] + 0.5) / (plain.RGB[3 * i] + 0.5);
        ++creviceCount;
      }
    }
  }
  crevice /= std::max<long>(1, creviceCount);

  const auto alonePlain =
    RenderScene(window, { upperActor }, TopView, nullptr, "ao-" + name + "-alone-off");
  const auto aloneShaded =
    RenderScene(window, { upperActor }, TopView, ao, "ao-" + name + "-alone-on");
  double own = 0.0;
  double ownMax = 0.0;
  long ownCount = 0;
  for (size_t i = 0; i < alonePlain.Depth.size(); ++i)
  {
    if (alonePlain.Depth[i] < 1.0f && alonePlain.RGB[3 * i] > 0)
    {
      const double d = 1.0 - (aloneShaded.RGB[3 * i] + 0.5) / (alonePlain.RGB[3 * i] + 0.5);
      own += d;
      ownMax = std::max(ownMax, d);
      ++ownCount;
    }
  }
  own /= std::max<long>(1, ownCount);
  std::cout << name << ": crevice darkening " << crevice << " over " << creviceCount
            << " pixels; lone tubes' own pixels " << own << " (max " << ownMax << ") over "
            << ownCount << std::endl;
  SV_CHECK_MSG(status, creviceCount > 100, name << ": no crevice found");
  SV_CHECK_MSG(status, crevice > 0.04 && crevice > 10.0 * own,
    name << ": the crevice is not darkened: " << crevice);
  SV_CHECK_MSG(status, own < 0.03, name << ": a lone tube darkens itself by " << own);

  // 3. Controls.
  const auto off = RenderScene(
    window, { lowerActor, upperActor }, TopView,
    [](vtkLineAmbientOcclusionPass* p)
    {
      p->AmbientOcclusionOff();
      p->DepthHalosOff();
    },
    "ao-" + name + "-disabled");
  const auto zero = RenderScene(
    window, { lowerActor, upperActor }, TopView,
    [](vtkLineAmbientOcclusionPass* p) { p->SetStrength(0.0); }, "ao-" + name + "-zero");
  long offDiff = 0;
  long zeroDiff = 0;
  long onDiff = 0;
  for (size_t i = 0; i < plain.RGB.size(); ++i)
  {
    offDiff += off.RGB[i] != plain.RGB[i] ? 1 : 0;
    zeroDiff += zero.RGB[i] != plain.RGB[i] ? 1 : 0;
    onDiff += shaded.RGB[i] != plain.RGB[i] ? 1 : 0;
  }
  std::cout << name << ": values differing from the plain rendering: pass off " << offDiff
            << ", strength 0 " << zeroDiff << ", on " << onDiff << std::endl;
  SV_CHECK_MSG(
    status, offDiff == 0 && zeroDiff == 0, name << ": a disabled pass changed the picture");
  SV_CHECK_MSG(status, onDiff > 500, name << ": the pass changed nothing");
}

/// 4. Halos of the pass around ray-cast tubes: a front tube along x at z = 0,
/// a back tube along y at z = -gap; halo color red.
long HaloPixels(SplineVizTestStatus& status, vtkRenderWindow* window, double gap, bool checkOwn)
{
  const double r = 0.06;
  std::vector<SplineVizTest::Vec4> front;
  std::vector<SplineVizTest::Vec4> back;
  for (int i = 0; i <= 10; ++i)
  {
    const double s = -1.2 + 0.24 * i;
    front.push_back({ s, 0.0, 0.0, r });
    back.push_back({ 0.0, s, -gap, r });
  }
  auto mapper = MakeMapper(0, SplineVizTest::MakePolylines({ front, back }));
  auto actor = Flat(mapper);
  auto halos = [](vtkLineAmbientOcclusionPass* p)
  {
    p->AmbientOcclusionOff();
    p->DepthHalosOn();
    p->SetHaloWidth(6.0);
    p->SetLengthUnitsToWorld();
    p->SetHaloDepthOffset(0.1);
    p->SetHaloDepthRange(0.6);
    p->HaloColorFromBackgroundOff();
    p->SetHaloColor(1.0, 0.0, 0.0);
  };
  const std::string tag = "ao-halo-gap" + std::to_string(static_cast<int>(100 * gap + 0.5));
  const auto plain = RenderScene(window, { actor }, TopView, nullptr, tag + "-off");
  const auto haloed = RenderScene(window, { actor }, TopView, halos, tag + "-on");
  long own = 0;
  long hidden = 0;
  long frontPixels = 0;
  for (int y = 0; y < Size; ++y)
  {
    for (int x = 0; x < Size; ++x)
    {
      const size_t i = static_cast<size_t>(y) * Size + x;
      if (!plain.Covered(x, y))
      {
        continue;
      }
      const unsigned char* a = &plain.RGB[3 * i];
      const unsigned char* b = &haloed.RGB[3 * i];
      const bool isFront = std::abs(y - Size / 2) <= 4; // the front tube's core rows
      const bool isRed = b[0] > 200 && b[1] < 60 && b[2] < 60;
      if (isFront)
      {
        ++frontPixels;
        own += (a[0] != b[0] || a[1] != b[1] || a[2] != b[2]) ? 1 : 0;
      }
      else
      {
        hidden += isRed ? 1 : 0;
      }
    }
  }
  std::cout << "halo, gap " << gap << ": " << hidden << " back-tube pixels in the halo; " << own
            << " of " << frontPixels << " front-tube pixels changed" << std::endl;
  if (checkOwn)
  {
    SV_CHECK_MSG(status, frontPixels > 500 && own == 0,
      "the halo changed " << own << " of the front tube's pixels");
  }
  return hidden;
}
}

int TestLineAmbientOcclusion(int, char*[])
{
  SplineVizTestStatus status;
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(Size, Size);

  TestStep(status, window);
  for (int kind = 0; kind < 3; ++kind)
  {
    TestLines(status, window, kind);
  }
  const long none = HaloPixels(status, window, 0.08, false);
  const long small = HaloPixels(status, window, 0.35, true);
  const long large = HaloPixels(status, window, 1.2, true);
  SV_CHECK_MSG(status, none == 0, "a halo below the depth offset: " << none);
  SV_CHECK_MSG(status, small > 10 && large > 1.5 * small,
    "the halo does not grow with the depth gap: " << small << " then " << large);
  return status.Result();
}
