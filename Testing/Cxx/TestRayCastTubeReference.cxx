// SPDX-License-Identifier: BSD-3-Clause
// Independent reference for vtkRayCastTubeMapper: the same tubes (the same
// spline, evaluated densely by independent code in the test, with the same
// radius function) built by vtkTubeFilter with 64 sides plus sphere caps and
// drawn by a standard vtkPolyDataMapper, at 800x600, perspective and parallel
// projection. Coverage must agree to within a pixel and depth to a small
// fraction of the radius. Negative controls prove the comparison can fail:
// tubes 10% too thick, and the far surface instead of the near one.
#include "vtkRayCastTubeMapper.h"

#include "SplineVizRenderingTestUtilities.h"
#include "SplineVizTestUtilities.h"

#include "vtkProperty.h"

#include <iostream>

using namespace SplineVizTest;

namespace
{
std::vector<std::vector<Vec4>> SceneCurves()
{
  std::vector<std::vector<Vec4>> curves;
  // A helix whose radius swells and shrinks.
  std::vector<Vec4> helix;
  for (int i = 0; i < 28; ++i)
  {
    const double a = 0.35 * i;
    helix.push_back({ 0.45 * std::cos(a) - 0.4, 0.45 * std::sin(a), -0.6 + 0.045 * i,
      0.045 + 0.02 * std::sin(0.5 * a) });
  }
  curves.push_back(helix);
  // An S-curve in a tilted plane.
  std::vector<Vec4> s;
  for (int i = 0; i < 16; ++i)
  {
    const double t = -1.0 + 2.0 * i / 15.0;
    s.push_back({ 0.6 + 0.35 * std::sin(3.0 * t), 0.9 * t, 0.3 * t, 0.05 });
  }
  curves.push_back(s);
  // A wavy line with a thin, tapering radius.
  std::vector<Vec4> wave;
  for (int i = 0; i < 20; ++i)
  {
    const double t = i / 19.0;
    wave.push_back({ -1.0 + 2.0 * t, -0.75 + 0.1 * std::sin(9.0 * t), 0.2 * std::cos(6.0 * t),
      0.035 - 0.02 * t });
  }
  curves.push_back(wave);
  return curves;
}

struct Comparison
{
  CoverageDifference Coverage;
  long DepthPixels = 0;
  double WorstDepth = 0.0; ///< world units
  double DepthOver = 0.0;  ///< fraction of compared pixels beyond tolerance
};

Comparison Compare(const Frame& a, const Frame& b, vtkCamera* camera, double depthTolerance)
{
  Comparison c;
  c.Coverage = CompareCoverage(a, b, 1);
  long over = 0;
  for (int y = 2; y < a.Height - 2; ++y)
  {
    for (int x = 2; x < a.Width - 2; ++x)
    {
      // interior pixels: covered in both frames in a 5x5 neighborhood
      bool interior = true;
      for (int dy = -2; dy <= 2 && interior; ++dy)
        for (int dx = -2; dx <= 2 && interior; ++dx)
          interior = a.Covered(x + dx, y + dy) && b.Covered(x + dx, y + dy);
      if (!interior)
        continue;
      const double da = ViewDepth(a.Depth[y * a.Width + x], camera);
      const double db = ViewDepth(b.Depth[y * b.Width + x], camera);
      const double e = std::abs(da - db);
      c.WorstDepth = std::max(c.WorstDepth, e);
      if (e > depthTolerance)
        ++over;
      ++c.DepthPixels;
    }
  }
  c.DepthOver = c.DepthPixels ? static_cast<double>(over) / c.DepthPixels : 1.0;
  return c;
}

void Report(const char* what, const Comparison& c)
{
  std::cout << what << ": covered " << c.Coverage.Covered[0] << " / " << c.Coverage.Covered[1]
            << " px, beyond 1 px: " << c.Coverage.Unexplained[0] << " / "
            << c.Coverage.Unexplained[1] << "; depth on " << c.DepthPixels << " interior px: worst "
            << c.WorstDepth << ", fraction over tolerance " << c.DepthOver << std::endl;
}
}

int TestRayCastTubeReference(int, char*[])
{
  SplineVizTestStatus status;
  const auto curves = SceneCurves();
  const double minRadius = 0.015;

  vtkNew<vtkRayCastTubeMapper> mapper;
  mapper->SetInputData(MakePolylines(curves));
  mapper->SetRadiusArray("Radius");
  mapper->ScalarVisibilityOff();
  vtkNew<vtkActor> tubes;
  tubes->SetMapper(mapper);

  vtkNew<vtkPolyDataMapper> referenceMapper;
  referenceMapper->SetInputData(ReferenceTubes(curves, 24, 64));
  referenceMapper->ScalarVisibilityOff();
  vtkNew<vtkActor> reference;
  reference->SetMapper(referenceMapper);

  // Negative controls.
  auto thick = curves;
  for (auto& curve : thick)
    for (auto& p : curve)
      p[3] *= 1.1;
  vtkNew<vtkPolyDataMapper> thickMapper;
  thickMapper->SetInputData(ReferenceTubes(thick, 24, 64));
  vtkNew<vtkActor> thickReference;
  thickReference->SetMapper(thickMapper);
  vtkNew<vtkActor> farReference; // the far surface of the reference tubes
  farReference->SetMapper(referenceMapper);
  farReference->GetProperty()->FrontfaceCullingOn();

  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0, 0, 0);
  vtkNew<vtkRenderWindow> window;
  window->SetSize(800, 600);
  window->SetMultiSamples(0);
  window->AddRenderer(renderer);
  vtkCamera* camera = renderer->GetActiveCamera();

  for (int parallel = 0; parallel <= 1; ++parallel)
  {
    camera->SetPosition(0.8, -1.5, 3.2);
    camera->SetFocalPoint(0.0, 0.0, 0.0);
    camera->SetViewUp(0, 1, 0);
    camera->SetViewAngle(40);
    camera->SetParallelProjection(parallel);
    camera->SetParallelScale(1.25);
    camera->SetClippingRange(1.5, 6.0); // fixed: the same depth mapping for all
    renderer->SetAutomaticLightCreation(true);

    auto show = [&](vtkActor* actor)
    {
      renderer->RemoveAllViewProps();
      renderer->AddActor(actor);
      camera->SetClippingRange(1.5, 6.0);
      return Grab(window);
    };
    const Frame rayCast = show(tubes);
    const Frame ref = show(reference);
    const Frame refThick = show(thickReference);
    const Frame refFar = show(farReference);

    const char* projection = parallel ? "parallel" : "perspective";
    std::cout << "--- " << projection << std::endl;
    const double depthTolerance = 0.1 * minRadius;
    const Comparison c = Compare(rayCast, ref, camera, depthTolerance);
    Report("ray cast vs reference", c);
    const long covered = std::max(c.Coverage.Covered[0], c.Coverage.Covered[1]);
    SV_CHECK_MSG(status, covered > 20000, projection << ": too little covered: " << covered);
    // Silhouettes within a pixel: at most 0.1% of the covered pixels further.
    SV_CHECK_MSG(status, c.Coverage.Unexplained[0] <= covered / 1000,
      projection << ": ray-cast pixels farther than 1 px from the reference: "
                 << c.Coverage.Unexplained[0]);
    SV_CHECK_MSG(status, c.Coverage.Unexplained[1] <= covered / 1000,
      projection << ": reference pixels farther than 1 px from the ray cast: "
                 << c.Coverage.Unexplained[1]);
    // Depth: within a tenth of the smallest radius almost everywhere.
    SV_CHECK_MSG(status, c.DepthPixels > 10000, projection << ": too few depth samples");
    SV_CHECK_MSG(status, c.DepthOver < 0.002,
      projection << ": depth differs by more than " << depthTolerance << " on "
                 << 100.0 * c.DepthOver << "% of the pixels");
    SV_CHECK_MSG(status, c.WorstDepth < 0.5 * minRadius,
      projection << ": worst depth difference " << c.WorstDepth);

    // The negative controls must fail the same criteria.
    const Comparison thickC = Compare(rayCast, refThick, camera, depthTolerance);
    Report("negative control: 10% thicker reference", thickC);
    SV_CHECK_MSG(status, thickC.Coverage.Unexplained[1] > covered / 1000,
      projection << ": coverage comparison cannot tell 10% thicker tubes");
    const Comparison farC = Compare(rayCast, refFar, camera, depthTolerance);
    Report("negative control: far surface", farC);
    SV_CHECK_MSG(
      status, farC.DepthOver > 0.5, projection << ": depth comparison cannot tell the far surface");
  }
  return status.Result();
}
