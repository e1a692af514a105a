// SPDX-License-Identifier: BSD-3-Clause
// The cost of vtkLineAmbientOcclusionPass: frames of a dense synthetic
// tractogram (vtkSyntheticTractogramSource) drawn by each line renderer
// without the pass, with ambient occlusion, and with ambient occlusion and
// depth-dependent halos, at the same camera positions of an orbit (the three
// variants alternate frame by frame, so that load from other processes hits
// them alike, after an untimed frame at each position that does the
// mappers' per-view work). Each frame is timed to its end (glFinish). Reports the median
// frame of each variant and the pass's added time as a share of the frame
// without it, in wall time and in the process's CPU time (all threads,
// llvmpipe's too: steadier than wall time on a machine shared with other
// processes). Since the pass works per pixel, its own cost is also measured
// where nothing else costs: a quad covering the whole window (every pixel
// shaded, many frames), which bounds its cost for any scene of that size.
//
// Usage:
//   BenchmarkLineAmbientOcclusion [--streamlines 20000] [--size 1200x768]
//       [--frames 7] [--radius 0.3] [--renderers raycast,tessellated,stylized]
#include "BenchmarkCommon.h"
#include "vtkLineAmbientOcclusionPass.h"
#include "vtkRayCastTubeMapper.h"
#include "vtkStylizedLineMapper.h"
#include "vtkSyntheticTractogramSource.h"
#include "vtkTessellatedTubeMapper.h"

#include "vtkActor.h"
#include "vtkPlaneSource.h"
#include "vtkPolyDataMapper.h"
#include "vtkCamera.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkProperty.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderer.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace
{
using splineviz_benchmark::CPUTime;
using splineviz_benchmark::Now;
using splineviz_benchmark::Split;

const char* Usage = "BenchmarkLineAmbientOcclusion [--streamlines 20000] [--size 1200x768]\n"
                    "    [--frames 7] [--radius 0.3] [--renderers raycast,tessellated,stylized]\n";

double Median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

vtkSmartPointer<vtkSplineTubeMapper> MakeMapper(const std::string& name)
{
  if (name == "raycast")
  {
    return vtkSmartPointer<vtkRayCastTubeMapper>::New();
  }
  if (name == "tessellated")
  {
    return vtkSmartPointer<vtkTessellatedTubeMapper>::New();
  }
  return vtkSmartPointer<vtkStylizedLineMapper>::New();
}

/// Median frames of the variants (none, AO, AO + halos) of `ren`, interleaved,
/// the camera turning by `turn` degrees per round: wall times, then CPU times.
std::vector<double> TimeVariants(vtkRenderWindow* window, vtkRenderer* ren, int frames, double turn)
{
  vtkNew<vtkRenderStepsPass> steps;
  vtkNew<vtkLineAmbientOcclusionPass> ao;
  ao->SetDelegatePass(steps);
  vtkNew<vtkLineAmbientOcclusionPass> aoHalo;
  aoHalo->SetDelegatePass(steps);
  aoHalo->DepthHalosOn();
  vtkRenderPass* variants[3] = { nullptr, ao, aoHalo };
  std::vector<double> times[3];
  std::vector<double> cpuTimes[3];
  auto* gl = vtkOpenGLRenderWindow::SafeDownCast(window);
  for (int v = 0; v < 3; ++v) // first frames: shaders, uploads
  {
    ren->SetPass(variants[v]);
    window->Render();
  }
  for (int f = 0; f < frames; ++f)
  {
    ren->GetActiveCamera()->Azimuth(turn);
    // The mappers' per-view work (culling, level of detail) runs once per
    // camera change: an untimed frame first, so that no variant pays it and
    // the pass's share is of a still frame.
    ren->SetPass(nullptr);
    window->Render();
    gl->WaitForCompletion();
    for (int v = 0; v < 3; ++v)
    {
      ren->SetPass(variants[v]);
      const double t0 = Now();
      const double c0 = CPUTime();
      window->Render();
      gl->WaitForCompletion();
      times[v].push_back(Now() - t0);
      cpuTimes[v].push_back(CPUTime() - c0);
    }
  }
  ren->SetPass(nullptr);
  return { Median(times[0]), Median(times[1]), Median(times[2]), Median(cpuTimes[0]),
    Median(cpuTimes[1]), Median(cpuTimes[2]) };
}
}

int main(int argc, char* argv[])
{
  long streamlines = 20000;
  int width = 1200;
  int height = 768;
  int frames = 7;
  double radius = 0.3;
  std::vector<std::string> renderers = { "raycast", "tessellated", "stylized" };
  splineviz_benchmark::Options options(Usage);
  options.Add("--streamlines", [&](const std::string& v) { streamlines = std::atol(v.c_str()); })
    .Add("--size", [&](const std::string& v) { std::sscanf(v.c_str(), "%dx%d", &width, &height); })
    .Int("--frames", frames, 1)
    .Double("--radius", radius)
    .List("--renderers", renderers);
  const int exitCode = options.Parse(argc, argv);
  if (exitCode >= 0)
  {
    return exitCode;
  }
  if (!splineviz_benchmark::AllKnown(
        renderers, { "raycast", "tessellated", "stylized" }, "renderer"))
  {
    return 1;
  }

  vtkNew<vtkSyntheticTractogramSource> source;
  source->SetNumberOfStreamlines(streamlines);
  source->Update();
  vtkPolyData* lines = source->GetOutput();
  std::printf("%ld streamlines, %lld points, %dx%d, radius %g, %d frames per variant\n",
    streamlines, static_cast<long long>(lines->GetNumberOfPoints()), width, height, radius, frames);
  std::printf("%-12s %10s %10s %10s %8s %8s\n", "renderer", "plain ms", "AO ms", "AO+halo ms",
    "AO %", "AO+h %");

  for (const std::string& name : renderers)
  {
    vtkNew<vtkRenderer> ren;
    ren->SetBackground(1.0, 1.0, 1.0);
    vtkNew<vtkRenderWindow> window;
    window->SetSize(width, height);
    window->SetMultiSamples(0);
    window->SetOffScreenRendering(1);
    window->AddRenderer(ren);
    auto mapper = MakeMapper(name);
    mapper->SetInputData(lines);
    mapper->SetRadius(radius);
    mapper->ScalarVisibilityOff();
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->GetProperty()->SetColor(0.8, 0.35, 0.2);
    ren->AddActor(actor);
    ren->ResetCamera();
    ren->GetActiveCamera()->Zoom(1.3);

    const std::vector<double> t = TimeVariants(window, ren, frames, 10.0);
    const double plain = t[0];
    const double withAO = t[1];
    const double withHalo = t[2];
    std::printf("%-12s %10.1f %10.1f %10.1f %7.1f%% %7.1f%%\n", name.c_str(), 1e3 * plain,
      1e3 * withAO, 1e3 * withHalo, 100.0 * (withAO - plain) / plain,
      100.0 * (withHalo - plain) / plain);
    std::printf("%-12s %10.1f %10.1f %10.1f %7.1f%% %7.1f%%\n", "  (CPU)", 1e3 * t[3], 1e3 * t[4],
      1e3 * t[5], 100.0 * (t[4] - t[3]) / t[3], 100.0 * (t[5] - t[3]) / t[3]);
  }

  // The pass alone: a window-filling quad.
  vtkNew<vtkRenderer> ren;
  vtkNew<vtkRenderWindow> window;
  window->SetSize(width, height);
  window->SetMultiSamples(0);
  window->SetOffScreenRendering(1);
  window->AddRenderer(ren);
  vtkNew<vtkPlaneSource> plane;
  plane->SetResolution(64, 64);
  vtkNew<vtkPolyDataMapper> quadMapper;
  quadMapper->SetInputConnection(plane->GetOutputPort());
  vtkNew<vtkActor> quad;
  quad->SetMapper(quadMapper);
  ren->AddActor(quad);
  ren->ResetCamera();
  ren->GetActiveCamera()->Zoom(3.0);
  ren->GetActiveCamera()->Elevation(30.0);
  const std::vector<double> q = TimeVariants(window, ren, 4 * frames, 0.5);
  std::printf("the pass on a window-filling quad: %.1f ms (AO), %.1f ms (AO + halos); the quad "
              "alone %.1f ms\n",
    1e3 * (q[1] - q[0]), 1e3 * (q[2] - q[0]), 1e3 * q[0]);
  std::printf("  (CPU) %.1f ms (AO), %.1f ms (AO + halos); the quad alone %.1f ms\n",
    1e3 * (q[4] - q[3]), 1e3 * (q[5] - q[3]), 1e3 * q[3]);
  return 0;
}
