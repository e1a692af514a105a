// SPDX-License-Identifier: BSD-3-Clause
// Stylized-line benchmark (Stoll et al. §5's measures, side by side in one
// process): for each data set and window size, each renderer draws the lines
// with the camera orbiting the data; reported are
//  - the time to the first frame (from the polylines in memory: tube
//    building, upload, shader compilation, drawing),
//  - the median frame time over the orbit (each frame finished),
//  - the bytes the renderer holds on the GPU per segment,
//  - the segment throughput on a 2x2 viewport (Stoll Table 1: vertex-bound
//    rather than fill-bound), segments per second,
// and, for time-dependent lines (the points move every frame), the time per
// frame of re-uploading the stylized lines against re-running vtkTubeFilter.
//
// Data sets: "torus" (Stoll's 65,536-segment toroid: 256 lines of 256
// segments wound around a torus), "stoll" (Stoll's 256 lines / 145,374
// segments: streamlines spiralling through a vortex), "fibers2" (Salm's
// Fibers2 size, vtkSyntheticFibersSource), "long" (Fibers2-sized set of long
// smooth curves, segments tens of radii long).
// Renderers: "stylized" (vtkStylizedLineMapper, defaults: fix-up and depth
// correction on, no halo), "stylized-halo" (a halo of 0.3 radii),
// "stylized-nofixup", "stylized-flat" (no depth correction: no gl_FragDepth),
// "tubefilter8" (vtkTubeFilter with 8 sides + vtkPolyDataMapper: Stoll's
// "geometry"), "tubefilter8-halo" (the geometry drawn a second time,
// widened, unlit, in the background color, behind: Stoll Table 2's geometry
// halo), "linesastubes" (vtkProperty::RenderLinesAsTubes), "raycast" and
// "tessellated" (SplineViz's spline tubes).
//
// Usage:
//   BenchmarkStylizedLines [--data torus,stoll,fibers2,long] [--size WxH,...]
//       [--renderers stylized,tubefilter8,...] [--frames N] [--seconds S]
//       [--dynamic-frames N]
#include "BenchmarkCommon.h"
#include "vtkRayCastTubeMapper.h"
#include "vtkStylizedLineMapper.h"
#include "vtkSyntheticFibersSource.h"
#include "vtkTessellatedTubeMapper.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkTubeFilter.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace
{
using splineviz_benchmark::Now;
using splineviz_benchmark::PolyDataGPUBytes;
using splineviz_benchmark::Split;
using Lines = splineviz_benchmark::Lines;

const double Pi = 3.141592653589793;

/// Stoll's toroid: 256 lines of 256 segments, each winding 3 times around
/// the tube of a torus (major radius 1, minor 0.35) while going once around.
vtkSmartPointer<vtkPolyData> Torus()
{
  Lines lines;
  for (int l = 0; l < 256; ++l)
  {
    std::vector<std::array<double, 3>> c;
    const double phase = 2.0 * Pi * l / 256.0;
    for (int i = 0; i <= 256; ++i)
    {
      const double u = 2.0 * Pi * i / 256.0 + phase / 16.0;
      const double v = 3.0 * 2.0 * Pi * i / 256.0 + phase;
      const double r = 1.0 + 0.35 * std::cos(v);
      c.push_back({ r * std::cos(u), r * std::sin(u), 0.35 * std::sin(v) });
    }
    lines.Add(c, 0.006);
  }
  return lines.Make();
}

/// Stoll's Fig. 1 sizes: 256 streamlines, 145,374 segments in all, spiralling
/// up through a vortex (angular speed falling off with the distance).
vtkSmartPointer<vtkPolyData> Stoll()
{
  Lines lines;
  const int total = 145374;
  for (int l = 0; l < 256; ++l)
  {
    const int segments = total / 256 + (l < total % 256 ? 1 : 0);
    std::vector<std::array<double, 3>> c;
    const double r0 = 0.1 + 0.9 * ((l * 37) % 256) / 256.0;
    const double a0 = 2.0 * Pi * l / 256.0;
    for (int i = 0; i <= segments; ++i)
    {
      const double s = static_cast<double>(i) / segments;
      const double r = r0 * (1.0 + 0.3 * std::sin(4.0 * Pi * s));
      const double a = a0 + 6.0 * Pi * s / (0.3 + r0);
      c.push_back({ r * std::cos(a), r * std::sin(a), -1.0 + 2.0 * s });
    }
    lines.Add(c, 0.006);
  }
  return lines.Make();
}

struct Built
{
  std::vector<vtkSmartPointer<vtkActor>> Actors;
  std::function<double()> GPUBytes;
  std::function<void()> Update; ///< per-frame work of time-dependent data (after the points moved)
};
using Factory = std::function<Built(vtkPolyData*, vtkRenderer*)>;

/// The spline tubes drawn by a tube mapper (vtkRayCastTubeMapper, vtkTessellatedTubeMapper).
template <typename Mapper>
Built Tubes(vtkPolyData* data)
{
  auto mapper = vtkSmartPointer<Mapper>::New();
  mapper->SetInputData(data);
  mapper->SetRadiusArray("Radius");
  mapper->SetScalarRange(0.0, 1.0);
  Built b;
  b.Actors.push_back(vtkSmartPointer<vtkActor>::New());
  b.Actors[0]->SetMapper(mapper);
  b.GPUBytes = [mapper]() { return static_cast<double>(mapper->GetGPUMemorySize()); };
  b.Update = [] {};
  return b;
}

std::map<std::string, Factory> Renderers()
{
  std::map<std::string, Factory> r;
  auto stylized = [](double halo, bool fixUp, bool depth)
  {
    return [=](vtkPolyData* data, vtkRenderer*)
    {
      auto mapper = vtkSmartPointer<vtkStylizedLineMapper>::New();
      mapper->SetInputData(data);
      mapper->SetRadiusArray("Radius");
      mapper->SetScalarRange(0.0, 1.0);
      mapper->SetHaloWidth(halo);
      mapper->SetFixUp(fixUp);
      mapper->SetDepthCorrection(depth);
      Built b;
      b.Actors.push_back(vtkSmartPointer<vtkActor>::New());
      b.Actors[0]->SetMapper(mapper);
      b.GPUBytes = [mapper]() { return static_cast<double>(mapper->GetGPUMemorySize()); };
      b.Update = [] {}; // the mapper sees the modified points and re-uploads
      return b;
    };
  };
  r["stylized"] = stylized(0.0, true, true);
  r["stylized-halo"] = stylized(0.3, true, true);
  r["stylized-nofixup"] = stylized(0.0, false, true);
  r["stylized-flat"] = stylized(0.0, true, false);
  auto tubes = [](bool halo)
  {
    return [halo](vtkPolyData* data, vtkRenderer* renderer)
    {
      auto filter = vtkSmartPointer<vtkTubeFilter>::New();
      auto input = vtkSmartPointer<vtkPolyData>::New();
      input->ShallowCopy(data);
      input->GetPointData()->SetActiveScalars("Radius");
      filter->SetInputData(input);
      filter->SetNumberOfSides(8);
      filter->SetVaryRadiusToVaryRadiusByAbsoluteScalar();
      filter->Update();
      auto tubeData = vtkSmartPointer<vtkPolyData>::New();
      tubeData->ShallowCopy(filter->GetOutput());
      tubeData->GetPointData()->SetActiveScalars("Scalar");
      auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
      mapper->SetInputData(tubeData);
      mapper->SetScalarRange(0.0, 1.0);
      Built b;
      b.Actors.push_back(vtkSmartPointer<vtkActor>::New());
      b.Actors[0]->SetMapper(mapper);
      if (halo)
      {
        // Stoll's geometry halo: the tubes again, 1.3 times as thick, in the
        // background color, unlit, pushed back by the coincident offset.
        auto wide = vtkSmartPointer<vtkTubeFilter>::New();
        wide->SetInputData(input);
        wide->SetNumberOfSides(8);
        wide->SetVaryRadiusToVaryRadiusByAbsoluteScalar();
        wide->SetRadiusFactor(1.3);
        wide->Update();
        auto wideMapper = vtkSmartPointer<vtkPolyDataMapper>::New();
        wideMapper->SetInputConnection(wide->GetOutputPort());
        wideMapper->ScalarVisibilityOff();
        wideMapper->SetRelativeCoincidentTopologyPolygonOffsetParameters(4.0, 4.0);
        auto haloActor = vtkSmartPointer<vtkActor>::New();
        haloActor->SetMapper(wideMapper);
        haloActor->GetProperty()->LightingOff();
        double* bg = renderer->GetBackground();
        haloActor->GetProperty()->SetColor(bg[0], bg[1], bg[2]);
        haloActor->GetProperty()->FrontfaceCullingOn();
        b.Actors.push_back(haloActor);
      }
      b.GPUBytes = [tubeData, halo]()
      { return (halo ? 2.0 : 1.0) * PolyDataGPUBytes(tubeData, true); };
      b.Update = [filter, input, data, tubeData]()
      {
        input->ShallowCopy(data);
        input->GetPointData()->SetActiveScalars("Radius");
        filter->Modified();
        filter->Update();
        tubeData->ShallowCopy(filter->GetOutput());
        tubeData->GetPointData()->SetActiveScalars("Scalar");
      };
      return b;
    };
  };
  r["tubefilter8"] = tubes(false);
  r["tubefilter8-halo"] = tubes(true);
  r["linesastubes"] = [](vtkPolyData* data, vtkRenderer*)
  {
    auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    mapper->SetInputData(data);
    mapper->SetScalarRange(0.0, 1.0);
    Built b;
    b.Actors.push_back(vtkSmartPointer<vtkActor>::New());
    b.Actors[0]->SetMapper(mapper);
    b.Actors[0]->GetProperty()->SetRenderLinesAsTubes(true);
    b.Actors[0]->GetProperty()->SetLineWidth(4);
    b.GPUBytes = [data]()
    {
      const vtkIdType segments = data->GetNumberOfPoints() - data->GetNumberOfLines();
      return static_cast<double>(data->GetNumberOfPoints()) * (12 + 4) +
        static_cast<double>(segments) * 2 * 4;
    };
    b.Update = [] {};
    return b;
  };
  r["raycast"] = [](vtkPolyData* data, vtkRenderer*) { return Tubes<vtkRayCastTubeMapper>(data); };
  r["tessellated"] = [](vtkPolyData* data, vtkRenderer*)
  { return Tubes<vtkTessellatedTubeMapper>(data); };
  return r;
}

struct Result
{
  double FirstFrame = 0.0;
  double MedianFrame = 0.0;
  double BytesPerSegment = 0.0;
  double Throughput = 0.0; ///< segments per second on a 2x2 viewport
  double Dynamic = 0.0;    ///< median seconds per frame when the points move every frame
  double Still = 0.0;      ///< median seconds per frame of the same view, points still
  int Frames = 0;
};

double Median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

Result Run(const Factory& factory, vtkPolyData* data, double extent, int width, int height,
  int frames, double maxSeconds, int dynamicFrames)
{
  const vtkIdType segments = data->GetNumberOfPoints() - data->GetNumberOfLines();
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(width, height);
  vtkSmartPointer<vtkRenderer> renderer = splineviz_benchmark::AddWarmRenderer(window);

  Result r;
  vtkCamera* camera = renderer->GetActiveCamera();
  auto placeCamera = [&]()
  {
    camera->SetFocalPoint(0.0, 0.0, 0.0);
    camera->SetPosition(0.0, -1.2 * extent, 2.2 * extent);
    camera->SetViewUp(0.0, 1.0, 0.0);
    camera->SetViewAngle(30.0);
    camera->SetClippingRange(0.1 * extent, 5.0 * extent);
  };
  const double start = Now();
  Built built = factory(data, renderer);
  for (auto& actor : built.Actors)
  {
    renderer->AddActor(actor);
  }
  placeCamera();
  splineviz_benchmark::RenderFrame(window);
  r.FirstFrame = Now() - start;
  r.BytesPerSegment = built.GPUBytes() / static_cast<double>(segments);

  splineviz_benchmark::FrameTimes times;
  times.Orbit(window, camera, frames, maxSeconds, 5,
    [&](int) { camera->SetClippingRange(0.1 * extent, 5.0 * extent); });
  r.Frames = times.Count();
  r.MedianFrame = Median(times.Wall);

  // Throughput: the same frames on a 2x2 viewport (vertex work only).
  window->SetSize(2, 2);
  placeCamera();
  window->Render();
  window->WaitForCompletion();
  std::vector<double> tiny;
  for (int i = 0; i < 9; ++i)
  {
    camera->Azimuth(40.0);
    const double t0 = Now();
    window->Render();
    window->WaitForCompletion();
    tiny.push_back(Now() - t0);
  }
  r.Throughput = segments / std::max(Median(tiny), 1e-9);
  window->SetSize(width, height);

  // Time-dependent lines: the points move every frame (a rotation about z
  // by a small angle), the renderer re-uploads or rebuilds.
  if (dynamicFrames > 0)
  {
    placeCamera();
    std::vector<double> still;
    for (int f = 0; f < dynamicFrames; ++f)
    {
      const double t0 = Now();
      window->Render();
      window->WaitForCompletion();
      still.push_back(Now() - t0);
    }
    r.Still = Median(still);
    vtkPoints* points = data->GetPoints();
    std::vector<double> dynamic;
    for (int f = 0; f < dynamicFrames; ++f)
    {
      const double t0 = Now();
      const double c = std::cos(0.01), s = std::sin(0.01);
      vtkSMPTools::For(0, points->GetNumberOfPoints(),
        [&](vtkIdType begin, vtkIdType end)
        {
          for (vtkIdType i = begin; i < end; ++i)
          {
            double p[3];
            points->GetPoint(i, p);
            points->SetPoint(i, c * p[0] - s * p[1], s * p[0] + c * p[1], p[2]);
          }
        });
      points->Modified();
      data->Modified();
      built.Update();
      window->Render();
      window->WaitForCompletion();
      dynamic.push_back(Now() - t0);
    }
    r.Dynamic = Median(dynamic);
  }
  renderer->RemoveAllViewProps();
  return r;
}
}

const char* const Usage =
  "Usage: BenchmarkStylizedLines [--data torus,stoll,fibers2,long] [--size WxH,...]\n"
  "    [--renderers stylized,stylized-halo,stylized-nofixup,stylized-flat,tubefilter8,\n"
  "     tubefilter8-halo,linesastubes,raycast,tessellated] [--frames N] [--seconds S]\n"
  "    [--dynamic-frames N]\n"
  "Defaults: --data torus,stoll,fibers2 --size 800x600,1200x768 --frames 36 --seconds 20\n"
  "    --dynamic-frames 10 --renderers stylized,stylized-halo,stylized-nofixup,tubefilter8,\n"
  "    tubefilter8-halo,linesastubes\n";

int main(int argc, char* argv[])
{
  vtkSMPTools::SetBackend("STDThread");
  std::vector<std::string> datasets = { "torus", "stoll", "fibers2" };
  std::vector<std::string> sizes = { "800x600", "1200x768" };
  std::vector<std::string> renderers = { "stylized", "stylized-halo", "stylized-nofixup",
    "tubefilter8", "tubefilter8-halo", "linesastubes" };
  int frames = 36;
  double seconds = 20.0;
  int dynamicFrames = 10;
  splineviz_benchmark::Options options(Usage);
  options.List("--data", datasets)
    .Sizes("--size", sizes)
    .List("--renderers", renderers)
    .Int("--frames", frames)
    .Double("--seconds", seconds)
    .Int("--dynamic-frames", dynamicFrames);
  const int exitCode = options.Parse(argc, argv);
  if (exitCode >= 0)
  {
    return exitCode;
  }
  const auto factories = Renderers();
  if (frames < 5 || seconds <= 0.0 || dynamicFrames < 0)
  {
    std::fprintf(stderr, "--frames must be at least 5, --seconds positive\n%s", Usage);
    return 2;
  }
  if (!splineviz_benchmark::AllKnown(
        renderers, splineviz_benchmark::Names(factories), "renderer") ||
    !splineviz_benchmark::AllKnown(datasets, { "torus", "stoll", "fibers2", "long" }, "data set"))
  {
    return 2;
  }
  for (const auto& dataset : datasets)
  {
    vtkSmartPointer<vtkPolyData> data;
    double extent = 1.5;
    if (dataset == "torus")
    {
      data = Torus();
    }
    else if (dataset == "stoll")
    {
      data = Stoll();
    }
    else if (dataset == "long")
    {
      data = splineviz_benchmark::LongCurves();
    }
    else
    {
      vtkNew<vtkSyntheticFibersSource> source;
      source->SetPresetToFibers2();
      source->Update();
      data = source->GetOutput();
      data->GetPointData()->SetActiveScalars("Scalar");
      extent = source->GetBoxSize() * 0.7;
    }
    const vtkIdType segments = data->GetNumberOfPoints() - data->GetNumberOfLines();
    std::printf("\n== %s: %lld lines, %lld segments\n", dataset.c_str(),
      static_cast<long long>(data->GetNumberOfLines()), static_cast<long long>(segments));
    for (const auto& size : sizes)
    {
      int w = 800, h = 600;
      splineviz_benchmark::ParseSize(size, w, h);
      std::printf("-- %dx%d\n", w, h);
      std::printf("  %-18s %12s %14s %12s %16s %16s %7s\n", "renderer", "first frame s",
        "median frame ms", "GPU B/seg", "2x2 Mseg/s", "moving ms/frame", "frames");
      std::map<std::string, Result> results;
      for (const auto& name : renderers)
      {
        // A fresh copy of the data: the dynamic test moves the points.
        auto copy = vtkSmartPointer<vtkPolyData>::New();
        copy->DeepCopy(data);
        copy->GetPointData()->SetActiveScalars("Scalar");
        const bool dynamic = name == "stylized" || name == "tubefilter8";
        const Result r =
          Run(factories.at(name), copy, extent, w, h, frames, seconds, dynamic ? dynamicFrames : 0);
        results[name] = r;
        std::printf("  %-18s %12.3f %14.1f %12.1f %16.2f %16s %7d\n", name.c_str(), r.FirstFrame,
          1000.0 * r.MedianFrame, r.BytesPerSegment, 1e-6 * r.Throughput,
          dynamic && dynamicFrames > 0 ? std::to_string(1000.0 * r.Dynamic).substr(0, 7).c_str()
                                       : "-",
          r.Frames);
        std::fflush(stdout);
      }
      auto ratio = [&](const char* a, const char* b, const char* what, double (*get)(const Result&))
      {
        if (results.count(a) && results.count(b) && get(results[a]) > 0.0)
        {
          std::printf("  %s: %s / %s = %.2f\n", what, b, a, get(results[b]) / get(results[a]));
        }
      };
      auto frame = [](const Result& r) { return r.MedianFrame; };
      auto first = [](const Result& r) { return r.FirstFrame; };
      auto bytes = [](const Result& r) { return r.BytesPerSegment; };
      auto throughput = [](const Result& r) { return 1.0 / r.Throughput; };
      auto moving = [](const Result& r) { return r.Dynamic; };
      auto update = [](const Result& r) { return std::max(r.Dynamic - r.Still, 1e-6); };
      ratio("stylized", "tubefilter8", "frame time (x shorter)", frame);
      ratio("stylized", "tubefilter8", "first frame (x shorter)", first);
      ratio("stylized", "tubefilter8", "GPU memory (x smaller)", bytes);
      ratio("stylized", "tubefilter8", "2x2 throughput (x higher)", throughput);
      ratio("stylized", "tubefilter8", "moving lines, time per frame (x shorter)", moving);
      ratio("stylized", "tubefilter8",
        "moving lines, update per frame: re-upload vs re-running the tube filter (x shorter)",
        update);
      if (results.count("stylized") && results["stylized"].Dynamic > 0.0)
      {
        std::printf("  moving lines, update per frame: stylized %.1f ms, tubefilter8 %.1f ms\n",
          1000.0 * update(results["stylized"]),
          results.count("tubefilter8") ? 1000.0 * update(results["tubefilter8"]) : 0.0);
      }
      ratio("linesastubes", "stylized", "frame time vs RenderLinesAsTubes (x slower)", frame);
      ratio("stylized-nofixup", "stylized", "fix-up cost (frame, with / without)", frame);
      ratio("stylized", "stylized-halo", "halo cost (frame, with / without)", frame);
      ratio("tubefilter8", "tubefilter8-halo", "geometry halo cost (with / without)", frame);
      ratio("stylized-halo", "tubefilter8-halo", "with halos (x shorter)", frame);
      ratio("stylized", "stylized-flat", "depth correction (frame, flat / corrected)", frame);
    }
  }
  return 0;
}
