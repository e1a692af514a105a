// SPDX-License-Identifier: BSD-3-Clause
// One fidelity test for every tube renderer: vtkRayCastTubeMapper,
// vtkTessellatedTubeMapper and vtkStylizedLineMapper against vtkTubeFilter
// (64 sides), both sides rendered with multisampling off in the same window
// and camera, at the whole-data view and zoomed 2x and 5x (toward a point on
// the data, so that the zoomed views are full of tubes).
//
// Scenes (radius from the point array "Radius", or the mapper's constant
// Radius where the scene says so):
// - DIPY's real cb_2 bundle (Testing/Data/DIPY/cb_2.vtp: 116 streamlines,
//   2,088 points, mm), densely resampled: 4 points per segment along the
//   spline of its points (SplineVizTest::DenseSpline), radius 0.22-0.38 mm
//   varying along each fibre; tubes 2-3 pixels wide in the whole view;
// - the synthetic curls (SplineVizTest::Curls: helices, a loop and a line,
//   5 degrees of turn per segment, radii 0.04-0.11);
// - a dense bundle of 5,000 overlapping streamlines (DenseBundle(): 8
//   segments each along a bent bundle 12 mm across, the mapper's constant
//   radius 0.15 mm (the tubes buffer then holds positions only), tubes
//   1-2 pixels wide and tens of them behind each pixel of the bundle's core
//   in the whole view), whose references are coarser to stay small (8
//   samples per segment, 16 sides, caps of 8 x 8: silhouettes within 2 % of
//   the radius of a circle's).
// References, each renderer's own surface model:
// - ray-cast (sphere-swept tubes with rounded ends) and tessellated (disk
//   tubes with flat caps): the filter around the spline of the renderer's
//   input sampled 16 times per segment by the test's own Hermite code, with
//   spheres at the ends or flat caps;
// - stylized lines (circular profiles orthogonal to the vertex tangents,
//   straight segments): the filter around the polylines themselves, capped.
// Measures (SplineVizTest::Measure): coverage IoU and the share of the
// common pixels whose eye depth (linearized with the camera's clipping range)
// is within a quarter of the radius of the reference's (the radius seen at
// each pixel: SplineVizTest::RadiusFrame, the reference colored by its radius).
// Targets at every view, for every renderer: IoU >= 0.98 and depth on
// >= 98 % (the whole-brain target; measured 0.986-0.9997 and 98.4-99.99 %).
// The dense bundle holds the thin tubes' silhouettes to it: a tube in front
// that covers a pixel too few or too many shows the one behind it, a depth
// error of a radius or more.
// Negative controls, which must fail at the whole view: each renderer with
// radii 15 % too small (the IoU target; not for the dense bundle, whose
// coverage is saturated: thinner tubes cover the same pixels), and moved
// away from the eye by 0.3 times the largest radius (the depth target).
// GPU bytes: the constant radius leaves 4 bytes per node out of the tubes
// buffer (checked against the same bundle with its radius array).
// SPLINEVIZ_TEST_IMAGES=<dir> writes the renderings as PNG files.
#include "TubeFidelityTestScenes.h"

#include "SplineVizRenderingTestUtilities.h"
#include "SplineVizTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <cmath>
#include <iostream>
#include <string>
#include <vector>

namespace
{
using namespace TubeFidelity;

const int Size = 600;

/// 5,000 streamlines in a bundle along a quarter circle of radius 40 mm:
/// each at its own offset (in a disk of radius 6 mm) that drifts along it, 9
/// nodes, radius 0.15 mm (a fixed pseudo-random sequence).
Curves DenseBundle()
{
  Curves curves;
  unsigned int state = 12345u;
  auto uniform = [&state]()
  {
    state = state * 1664525u + 1013904223u;
    return static_cast<double>(state >> 8) / 16777216.0;
  };
  for (int s = 0; s < 5000; ++s)
  {
    const double a = 2.0 * vtkMath::Pi() * uniform();
    const double rho = 6.0 * std::sqrt(uniform());
    const double drift[2] = { 1.5 * (uniform() - 0.5), 1.5 * (uniform() - 0.5) };
    const double start = 0.25 * uniform();
    std::vector<Vec4> nodes;
    for (int i = 0; i < 9; ++i)
    {
      const double u = start + 0.08 * i; // fraction of the quarter circle
      const double phi = 0.5 * vtkMath::Pi() * u;
      const double ox = rho * std::cos(a) + drift[0] * i;
      const double oz = rho * std::sin(a) + drift[1] * i;
      const double r = 40.0 + ox; // offset across the bundle, in its plane
      nodes.push_back({ r * std::cos(phi), r * std::sin(phi), oz, 0.15 });
    }
    curves.push_back(nodes);
  }
  return curves;
}

/// The test frame's colors with the common pixels whose depth is off (more
/// than `tolerance`) in red, nearer than the reference, or blue, farther
/// (for SPLINEVIZ_TEST_IMAGES).
SplineVizTest::Frame DepthErrors(const SplineVizTest::Frame& test,
  const SplineVizTest::Frame& reference, vtkCamera* camera, const std::vector<double>& tolerance)
{
  SplineVizTest::Frame out = test;
  for (size_t i = 0; i < test.Depth.size(); ++i)
  {
    if (test.Depth[i] < 1.0f && reference.Depth[i] < 1.0f)
    {
      const double d = SplineVizTest::ViewDepth(test.Depth[i], camera) -
        SplineVizTest::ViewDepth(reference.Depth[i], camera);
      if (std::abs(d) > tolerance[i])
      {
        out.RGB[3 * i] = d < 0.0 ? 255 : 0;
        out.RGB[3 * i + 1] = 0;
        out.RGB[3 * i + 2] = d < 0.0 ? 0 : 255;
      }
    }
  }
  return out;
}

/// The GPU bytes of `mapper` after a frame with the camera `setup` (its
/// resources are released when its renderer leaves the window).
long long GPUBytes(vtkRenderWindow* window, vtkSplineTubeMapper* mapper,
  const SplineVizTest::CameraSetup& setup, const double bounds[6])
{
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  window->AddRenderer(renderer);
  setup(renderer->GetActiveCamera());
  renderer->ResetCameraClippingRange(const_cast<double*>(bounds));
  window->Render();
  const auto bytes = static_cast<long long>(mapper->GetGPUMemorySize());
  window->RemoveRenderer(renderer);
  return bytes;
}

struct View
{
  std::string Name;
  double Zoom;
};
const View Views[] = { { "whole", 1.0 }, { "zoom2", 2.0 }, { "zoom5", 5.0 } };

struct Scene
{
  std::string Name;
  Curves Lines;
  double Direction[3];
  double Target[3]; // a point on the data
  ReferenceResolution Resolution;
  bool SaturatedCoverage = false; // tubes behind every pixel: IoU cannot see the radius
  double ConstantRadius = 0.0;    // > 0: the mapper's Radius instead of the array
};
}

int TestTubeFidelity(int, char*[])
{
  SplineVizTestStatus status;
  auto window = MakeWindow(Size);

  std::vector<Scene> scenes;
  {
    Scene bundle;
    bundle.Name = "cb_2";
    bundle.Lines = LoadBundle();
    if (bundle.Lines.empty())
    {
      std::cerr << "ERROR: could not read Testing/Data/DIPY/cb_2.vtp (116 streamlines)"
                << std::endl;
      return EXIT_FAILURE;
    }
    const auto& fibre = bundle.Lines[58];
    const auto& middle = fibre[fibre.size() / 2];
    bundle.Direction[0] = 1.0;
    bundle.Direction[1] = -0.35;
    bundle.Direction[2] = 0.3;
    std::copy(middle.begin(), middle.begin() + 3, bundle.Target);
    scenes.push_back(bundle);
    Scene curls;
    curls.Name = "curls";
    curls.Lines = SplineVizTest::Curls();
    curls.Direction[0] = 4.0;
    curls.Direction[1] = 5.0;
    curls.Direction[2] = 9.0;
    const auto& helix = curls.Lines[0][40];
    std::copy(helix.begin(), helix.begin() + 3, curls.Target);
    scenes.push_back(curls);
    Scene dense;
    dense.Name = "dense";
    dense.Lines = DenseBundle();
    dense.Direction[0] = 0.6;
    dense.Direction[1] = 0.5;
    dense.Direction[2] = 1.0;
    const auto& node = dense.Lines[17][4];
    std::copy(node.begin(), node.begin() + 3, dense.Target);
    dense.Resolution = { 8, 16, 8 };
    dense.SaturatedCoverage = true;
    dense.ConstantRadius = 0.15;
    scenes.push_back(dense);
  }

  for (const Scene& scene : scenes)
  {
    double rMin = 1e30;
    double rMax = 0.0;
    for (const auto& curve : scene.Lines)
    {
      for (const auto& p : curve)
      {
        rMin = std::min(rMin, p[3]);
        rMax = std::max(rMax, p[3]);
      }
    }
    auto lines = SplineVizTest::MakePolylines(scene.Lines);
    auto thinLines = SplineVizTest::MakePolylines(ScaleRadii(scene.Lines, 0.85));
    double bounds[6];
    PaddedBounds(lines, bounds);
    for (Renderer which : { RayCast, Tessellated, Stylized })
    {
      const std::string renderer = RendererNames[which];
      const auto referenceTubes = MakeReference(which, scene.Lines, scene.Resolution);
      vtkNew<vtkPolyDataMapper> reference;
      reference->SetInputData(referenceTubes);
      reference->ScalarVisibilityOff();
      auto mapper = MakeMapper(which, lines, scene.ConstantRadius);
      const double iouTarget = 0.98;
      const double depthTarget = 0.98;
      for (const View& view : Views)
      {
        const auto setup = MakeCamera(bounds, scene.Direction, scene.Target, view.Zoom);
        vtkNew<vtkCamera> camera;
        const auto ref = SplineVizTest::Render(window, reference, setup, bounds, camera);
        const auto test = SplineVizTest::Render(window, mapper, setup, bounds, camera);
        const std::string name = scene.Name + "-" + view.Name + "-" + renderer;
        SplineVizTest::Save(ref, scene.Name + "-" + view.Name + "-" + renderer + "-reference");
        SplineVizTest::Save(test, name);
        std::vector<double> tolerance =
          SplineVizTest::RadiusFrame(window, referenceTubes, setup, bounds, rMin, rMax);
        for (double& r : tolerance)
        {
          r *= 0.25;
        }
        const auto m = SplineVizTest::Measure(test, ref, camera, 0.0, &tolerance);
        SplineVizTest::Save(DepthErrors(test, ref, camera, tolerance), name + "-depth-errors");
        std::cout << name << ": covered " << m.Covered[0] << " (reference " << m.Covered[1]
                  << "), IoU " << m.IoU << ", eye depth within r/4 on " << 100.0 * m.DepthShare
                  << " % of " << m.Common << " common pixels (mean difference "
                  << m.MeanDepthDifference / rMin << " rMin)" << std::endl;
        SV_CHECK_MSG(status, m.Covered[1] > Size * Size / 200,
          name << ": the reference covers only " << m.Covered[1] << " pixels");
        SV_CHECK_MSG(status, m.IoU >= iouTarget, name << ": IoU " << m.IoU << " < " << iouTarget);
        SV_CHECK_MSG(status, m.DepthShare >= depthTarget,
          name << ": eye depth within r/4 on " << 100.0 * m.DepthShare << " % < "
               << 100.0 * depthTarget << " %");

        if (view.Zoom != 1.0)
        {
          continue;
        }
        if (scene.ConstantRadius > 0.0)
        {
          // The same tubes with the radius array: 4 more bytes per node.
          auto withArray = MakeMapper(which, lines);
          const auto nodes = static_cast<long long>(lines->GetNumberOfPoints());
          const long long bytes = GPUBytes(window, mapper, setup, bounds);
          const long long arrayBytes = GPUBytes(window, withArray, setup, bounds);
          std::cout << "  GPU bytes per node: " << static_cast<double>(bytes) / nodes
                    << " with the constant radius, " << static_cast<double>(arrayBytes) / nodes
                    << " with the radius array" << std::endl;
          SV_CHECK_MSG(status, arrayBytes - bytes == 4 * nodes,
            name << ": the constant radius saves " << arrayBytes - bytes
                 << " bytes, not 4 per node (" << 4 * nodes << ")");
        }
        // Negative controls at the whole view (moved by 0.3 rMax: at least
        // 0.3 local radii everywhere).
        if (!scene.SaturatedCoverage)
        {
          auto thin = MakeMapper(which, thinLines, 0.85 * scene.ConstantRadius);
          const auto thinFrame = SplineVizTest::Render(window, thin, setup, bounds, camera);
          const auto thinMeasure = SplineVizTest::Measure(thinFrame, ref, camera, 0.0, &tolerance);
          std::cout << "  negative control, radii 15 % too small: IoU " << thinMeasure.IoU
                    << std::endl;
          SV_CHECK_MSG(status, thinMeasure.IoU < iouTarget,
            name << ": radii 15 % too small must fail the IoU target, IoU " << thinMeasure.IoU);
        }
        {
          double shift[3];
          camera->GetDirectionOfProjection(shift);
          for (double& c : shift)
          {
            c *= 0.3 * rMax;
          }
          const auto farFrame = SplineVizTest::Render(window, mapper, setup, bounds, camera, shift);
          const auto farMeasure = SplineVizTest::Measure(farFrame, ref, camera, 0.0, &tolerance);
          std::cout << "  negative control, 0.3 rMax farther: depth within r/4 on "
                    << 100.0 * farMeasure.DepthShare << " %" << std::endl;
          SV_CHECK_MSG(status, farMeasure.DepthShare < depthTarget,
            name << ": moved 0.3 r away the depth must fail, " << 100.0 * farMeasure.DepthShare
                 << " %");
        }
      }
    }
  }
  return status.Result();
}
