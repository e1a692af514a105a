// SPDX-License-Identifier: BSD-3-Clause
// Translucent tubes of every line renderer (vtkRayCastTubeMapper,
// vtkTessellatedTubeMapper, vtkStylizedLineMapper) against their polygonal
// references, both drawn with the same opacity by the same order-independent
// method in the same window and camera, multisampling off:
// - VTK's dual depth peeling (the renderer's UseDepthPeeling, no limit on
//   the peels, occlusion ratio 0: exact);
// - VTK's weighted blended order-independent translucency
//   (vtkOrderIndependentTranslucentPass, what a vtkRenderer uses when depth
//   peeling is off).
// What a translucent tube shows (the renderers' documented model): its
// nearest wall, one layer per tube. The reference is each renderer's own
// surface model (TubeFidelityTestScenes.h: the spline's tube with rounded
// ends as hemispheres, the spline's tube with flat caps, the polylines' tube
// with flat caps) with backface culling, whose front faces are that one
// layer.
// Scenes: the synthetic curls (helices, a loop, a line; radii 0.04-0.11)
// and DIPY's real cb_2 bundle, resampled 4 points per segment (segments of
// about 0.25 mm against radii of 0.22-0.38 mm: every pixel of a tube lies
// near several joints, where the ray-cast tubes' neighbouring sub-segments
// overlap), at the whole view and zoomed 3x.
// Measure: the share of the pixels covered in either image whose color
// differs by more than 12/255 (largest channel) from every reference pixel
// within one pixel (silhouettes of the 24-sided reference move by a pixel).
// Targets: at most 1 % (curls), 1.5 % (cb_2 zoomed) and 2.5 % (cb_2 whole:
// tubes 2-3 pixels wide, mostly edge pixels). A second layer changes a
// pixel's color by 30-60/255. Polygons against polygons (the references at
// 24 and at 37 sides) differ on 0.1-1.1 %.
// Negative control, which must fail by 10 times its target: each renderer's
// tubes drawn again inside themselves (a second actor, radii 0.95 times),
// the error of a renderer that draws a tube's inside as well as its surface
// (as the ray-cast tubes did where neighbouring sub-segments overlap).
// (VTK 9.2's dual depth peeling stops after the first peel when the
// renderer's MaximumNumberOfPeels is 0, which its documentation calls no
// limit; the test asks for 200.)
// SPLINEVIZ_TEST_IMAGES=<dir> writes the renderings as PNG files.
#include "TubeFidelityTestScenes.h"

#include "SplineVizRenderingTestUtilities.h"
#include "SplineVizTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
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
const double Background[3] = { 0.3, 0.3, 0.3 };
const double Opacity = 0.4;

enum Method
{
  DepthPeeling,
  WeightedBlended
};
const char* const MethodNames[] = { "peeling", "blended" };

/// `mappers` drawn translucent (one actor each) by `method`; `culling`:
/// backface culling (the references).
SplineVizTest::Frame RenderTranslucent(vtkRenderWindow* window,
  const std::vector<vtkMapper*>& mappers, const SplineVizTest::CameraSetup& setup,
  const double bounds[6], Method method, bool culling, bool& peeled)
{
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(Background[0], Background[1], Background[2]);
  renderer->SetUseDepthPeeling(method == DepthPeeling);
  renderer->SetMaximumNumberOfPeels(200); // 0 is not unlimited (above)
  renderer->SetOcclusionRatio(0.0);
  for (vtkMapper* mapper : mappers)
  {
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->GetProperty()->SetColor(0.95, 0.55, 0.3);
    actor->GetProperty()->SetAmbient(0.1);
    actor->GetProperty()->SetDiffuse(0.9);
    actor->GetProperty()->SetOpacity(Opacity);
    actor->GetProperty()->SetBackfaceCulling(culling);
    renderer->AddActor(actor);
  }
  window->AddRenderer(renderer);
  setup(renderer->GetActiveCamera());
  renderer->ResetCameraClippingRange(const_cast<double*>(bounds));
  SplineVizTest::Frame frame = SplineVizTest::Grab(window);
  peeled = renderer->GetLastRenderingUsedDepthPeeling() != 0;
  window->RemoveRenderer(renderer);
  return frame;
}

struct Comparison
{
  long Covered = 0; ///< pixels not background in either frame
  long Off = 0;     ///< of those, farther than the tolerance from the reference
  double Share() const { return this->Covered > 0 ? double(this->Off) / this->Covered : 1.0; }
};

/// Pixels of `test` whose color differs by more than `tolerance` (largest
/// channel, 0-255) from every pixel of `reference` within one pixel.
Comparison Compare(const SplineVizTest::Frame& test, const SplineVizTest::Frame& reference,
  int tolerance, SplineVizTest::Frame* errors)
{
  const int w = test.Width;
  const int h = test.Height;
  int background[3];
  for (int c = 0; c < 3; ++c)
  {
    background[c] = static_cast<int>(std::lround(255.0 * Background[c]));
  }
  auto differs = [](const unsigned char* a, const int* b, int tol)
  {
    for (int c = 0; c < 3; ++c)
    {
      if (std::abs(static_cast<int>(a[c]) - b[c]) > tol)
      {
        return true;
      }
    }
    return false;
  };
  if (errors)
  {
    *errors = test;
  }
  Comparison result;
  for (int y = 0; y < h; ++y)
  {
    for (int x = 0; x < w; ++x)
    {
      const unsigned char* t = &test.RGB[3 * (y * w + x)];
      const unsigned char* r = &reference.RGB[3 * (y * w + x)];
      if (!differs(t, background, 2) && !differs(r, background, 2))
      {
        continue;
      }
      ++result.Covered;
      const int tv[3] = { t[0], t[1], t[2] };
      bool matched = false;
      for (int dy = -1; dy <= 1 && !matched; ++dy)
      {
        for (int dx = -1; dx <= 1 && !matched; ++dx)
        {
          const int xx = x + dx;
          const int yy = y + dy;
          if (xx >= 0 && yy >= 0 && xx < w && yy < h)
          {
            matched = !differs(&reference.RGB[3 * (yy * w + xx)], tv, tolerance);
          }
        }
      }
      if (!matched)
      {
        ++result.Off;
        if (errors)
        {
          unsigned char* e = &errors->RGB[3 * (y * w + x)];
          e[0] = 255;
          e[1] = 0;
          e[2] = 255;
        }
      }
    }
  }
  return result;
}

struct Scene
{
  std::string Name;
  Curves Lines;
  double Direction[3];
  double Target[3];
  double Zoom;
  double Tolerated; ///< share of the pixels that may be off
};
}

int TestTubeTranslucency(int, char*[])
{
  SplineVizTestStatus status;
  auto window = MakeWindow(Size);
  window->SetAlphaBitPlanes(1);

  std::vector<Scene> scenes;
  {
    Scene curls{ "curls", SplineVizTest::Curls(), { 4.0, 5.0, 9.0 }, { 0, 0, 0 }, 1.0, 0.01 };
    scenes.push_back(curls);
    const Curves bundle = LoadBundle();
    if (bundle.empty())
    {
      std::cerr << "ERROR: could not read Testing/Data/DIPY/cb_2.vtp (116 streamlines)"
                << std::endl;
      return EXIT_FAILURE;
    }
    Scene whole{ "cb_2", bundle, { 1.0, -0.35, 0.3 }, { 0, 0, 0 }, 1.0, 0.025 };
    scenes.push_back(whole);
    Scene zoom = whole;
    zoom.Name = "cb_2-zoom3";
    zoom.Zoom = 3.0;
    zoom.Tolerated = 0.015;
    const auto& fibre = bundle[58];
    std::copy(fibre[fibre.size() / 2].begin(), fibre[fibre.size() / 2].begin() + 3, zoom.Target);
    scenes.push_back(zoom);
  }

  const int tolerance = 12;
  for (const Scene& scene : scenes)
  {
    auto lines = SplineVizTest::MakePolylines(scene.Lines);
    auto inner = SplineVizTest::MakePolylines(ScaleRadii(scene.Lines, 0.95));
    const double target = scene.Tolerated;
    double bounds[6];
    PaddedBounds(lines, bounds);
    const auto setup = MakeCamera(bounds, scene.Direction, scene.Target, scene.Zoom);
    for (Renderer which : { RayCast, Tessellated, Stylized })
    {
      ReferenceResolution resolution;
      resolution.PerSegment = 8;
      resolution.Sides = 24;
      resolution.Caps = 24;
      vtkNew<vtkPolyDataMapper> reference;
      reference->SetInputData(MakeReference(which, scene.Lines, resolution, true));
      reference->ScalarVisibilityOff();
      auto mapper = MakeMapper(which, lines);
      for (Method method : { DepthPeeling, WeightedBlended })
      {
        const std::string name =
          scene.Name + "-" + RendererNames[which] + "-" + MethodNames[method];
        bool peeledReference = false;
        bool peeled = false;
        const auto ref =
          RenderTranslucent(window, { reference }, setup, bounds, method, true, peeledReference);
        const auto test =
          RenderTranslucent(window, { mapper }, setup, bounds, method, false, peeled);
        SplineVizTest::Frame errors;
        const Comparison c = Compare(test, ref, tolerance, &errors);
        SplineVizTest::Save(ref, name + "-reference");
        SplineVizTest::Save(test, name);
        SplineVizTest::Save(errors, name + "-errors");
        std::cout << name << ": " << c.Off << " of " << c.Covered << " covered pixels ("
                  << 100.0 * c.Share() << " %) off by more than " << tolerance << "/255"
                  << std::endl;
        SV_CHECK_MSG(status, c.Covered > Size * Size / 100, name << ": nothing drawn");
        SV_CHECK_MSG(status, c.Share() <= target,
          name << ": " << 100.0 * c.Share() << " % of the pixels off, more than " << 100.0 * target
               << " %");
        SV_CHECK_MSG(status, method != DepthPeeling || (peeled && peeledReference),
          name << ": depth peeling was not used");
        if (scene.Zoom != 1.0)
        {
          continue;
        }
        // Negative control: every tube drawn again inside itself.
        auto insides = MakeMapper(which, inner);
        const auto doubled =
          RenderTranslucent(window, { mapper, insides }, setup, bounds, method, false, peeled);
        const Comparison d = Compare(doubled, ref, tolerance, nullptr);
        std::cout << "  negative control, the insides drawn too: " << 100.0 * d.Share() << " % off"
                  << std::endl;
        SV_CHECK_MSG(status, d.Share() > 10 * target,
          name << ": a second layer inside must fail, " << 100.0 * d.Share() << " % off");
      }
    }
  }
  return status.Result();
}
