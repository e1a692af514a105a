// SPDX-License-Identifier: BSD-3-Clause
// Tube rendering benchmark (Salm §3.3's protocol): renders a synthetic fiber
// data set offscreen with the camera orbiting at a fixed distance, for each
// renderer side by side in one process, and reports
//  - time to first frame: from the polylines in memory to the first finished
//    frame (tube building, upload, shader compilation, drawing),
//  - median frame time over the orbit (each frame finished with glFinish),
//  - bytes the renderer holds on the GPU, per segment,
// Renderers: "raycast" (vtkRayCastTubeMapper, defaults but without occlusion
// culling), "raycast-culling" (with it), "raycast-roots" and
// "raycast-roots-culling" (root finding for every sub-segment: straight
// tolerance 0, as Salm), "raycast-straight5" and "raycast-straight5-culling"
// (straight tolerance 5 % of the radius), the tessellated tubes
// (vtkTessellatedTubeMapper, Salm §3.1) as "tessellated" (defaults: level
// of detail, adaptive refinement, occlusion culling), "tessellated-noculling"
// (the same without occlusion culling), "tessellated-exact" (the same with
// the exact radius at any zoom: MinimumPixelWidth 0), "tessellated-base"
// (level of detail, tessellation levels 1), "tessellated-paper" (the paper's
// fixed 16 x 8 base mesh for every segment, adaptive refinement: Salm Fig. 22
// "complete") and "tessellated-paper-base" (fixed base mesh, levels 1:
// Fig. 22 "unrefined"),
// and the ratios against VTK's own ways of drawing tubes:
//  - "tubefilter": vtkTubeFilter (12 sides, radius by the Radius array) +
//    vtkPolyDataMapper (the geometry VTK uploads: points, normals, colors,
//    triangle indices),
//  - "linesastubes": vtkProperty::RenderLinesAsTubes (screen-space width).
//
// Data sets: "fibers", "fibers2", "million" (vtkSyntheticFibersSource's
// presets: short segments, 2-5 radii long) and "long" (Fibers2-sized long
// smooth curves, segments about 25 radii long: LongCurves() of
// BenchmarkCommon.h, also drawn by BenchmarkStylizedLines).
//
// Usage:
//   SplineVizTubeBenchmark [--data fibers|fibers2|million|long] [--size WxH]
//       [--frames N] [--renderers raycast,tubefilter,linesastubes]
//       [--distance far|close] [--seconds S] [--samples N] [--snapshots DIR]
//       [--trace 1] [--allocator steady|default]
// Several --data/--size values may be given (comma separated). --snapshots
// writes each renderer's first frame to DIR/<data>-<size>-<renderer>.png;
// --trace 1 prints each frame's time, CPU time and minor page faults.
// By default freed heap memory stays in the process (SteadyAllocator() of
// BenchmarkCommon.h): otherwise whichever renderer runs first in a fresh
// process pays page faults for llvmpipe's bin memory every frame.
#include "BenchmarkCommon.h"
#include "vtkRayCastTubeMapper.h"
#include "vtkSplineTubeCore.h"
#include "vtkSyntheticFibersSource.h"
#include "vtkTessellatedTubeMapper.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkTimerLog.h"
#include "vtkSMPTools.h"
#include "vtkTubeFilter.h"
#include "vtkPNGWriter.h"
#include "vtkWindowToImageFilter.h"

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace
{
using splineviz_benchmark::CPUTime;
using splineviz_benchmark::Now;
using splineviz_benchmark::PolyDataGPUBytes;
using splineviz_benchmark::Split;

/// What a renderer builds for a data set: the actor, and after the first
/// frame, the bytes it holds on the GPU.
struct Built
{
  vtkSmartPointer<vtkActor> Actor;
  std::function<double()> GPUBytes;
  std::function<std::string()> Summary; // what the renderer drew, if it can say
};

using Factory = std::function<Built(vtkPolyData*)>;

std::map<std::string, Factory> Renderers()
{
  std::map<std::string, Factory> r;
  // Ray-cast tubes with and without occlusion culling and the closed-form
  // intersection of straight (sub-)segments.
  auto raycast = [](bool culling, double straight, int subSegments = 0)
  {
    return [culling, straight, subSegments](vtkPolyData* data)
    {
      auto mapper = vtkSmartPointer<vtkRayCastTubeMapper>::New();
      mapper->SetInputData(data);
      mapper->SetRadiusArray("Radius");
      mapper->SetScalarRange(0.0, 1.0);
      mapper->SetOcclusionCulling(culling);
      if (subSegments > 0)
      {
        mapper->SetSubSegments(subSegments);
      }
      if (straight >= 0.0)
      {
        mapper->SetStraightTolerance(straight);
      }
      Built b;
      b.Actor = vtkSmartPointer<vtkActor>::New();
      b.Actor->SetMapper(mapper);
      b.GPUBytes = [mapper]() { return static_cast<double>(mapper->GetGPUMemorySize()); };
      return b;
    };
  };
  r["raycast"] = raycast(false, -1.0); // the defaults, culling off
  r["raycast-culling"] = raycast(true, -1.0);
  r["raycast-roots"] = raycast(false, 0.0);
  r["raycast-roots-culling"] = raycast(true, 0.0);
  r["raycast-straight5"] = raycast(false, 0.05);
  r["raycast-straight5-culling"] = raycast(true, 0.05);
  r["raycast-sub1"] = raycast(false, -1.0, 1);
  r["raycast-sub3"] = raycast(false, -1.0, 3);
  r["raycast-sub4"] = raycast(false, -1.0, 4);
  // Tessellated tubes: level of detail on/off, adaptive or levels 1.
  auto tessellated = [](bool lod, bool refine, bool culling = true, double minimumPixels = 1.0)
  {
    return [lod, refine, culling, minimumPixels](vtkPolyData* data)
    {
      auto mapper = vtkSmartPointer<vtkTessellatedTubeMapper>::New();
      mapper->SetInputData(data);
      mapper->SetRadiusArray("Radius");
      mapper->SetScalarRange(0.0, 1.0);
      mapper->SetLevelOfDetail(lod);
      mapper->SetOcclusionCulling(culling);
      mapper->SetMinimumPixelWidth(minimumPixels);
      if (!refine)
      {
        mapper->SetMaxTessellationLevel(1);
        mapper->SetMaxSilhouetteTessellationLevel(1);
      }
      Built b;
      b.Actor = vtkSmartPointer<vtkActor>::New();
      b.Actor->SetMapper(mapper);
      b.GPUBytes = [mapper]() { return static_cast<double>(mapper->GetGPUMemorySize()); };
      b.Summary = [mapper]() { return mapper->GetLevelOfDetailSummary(); };
      return b;
    };
  };
  r["tessellated"] = tessellated(true, true);
  r["tessellated-noculling"] = tessellated(true, true, false);
  r["tessellated-exact"] = tessellated(true, true, true, 0.0);
  r["tessellated-base"] = tessellated(true, false);
  r["tessellated-paper"] = tessellated(false, true);
  r["tessellated-paper-base"] = tessellated(false, false);
  r["tubefilter"] = [](vtkPolyData* data)
  {
    auto tubes = vtkSmartPointer<vtkTubeFilter>::New();
    tubes->SetInputData(data);
    tubes->SetNumberOfSides(12);
    tubes->SetVaryRadiusToVaryRadiusByAbsoluteScalar();
    data->GetPointData()->SetActiveScalars("Radius");
    tubes->Update();
    auto tubeData = vtkSmartPointer<vtkPolyData>::New();
    tubeData->ShallowCopy(tubes->GetOutput());
    data->GetPointData()->SetActiveScalars("Scalar");
    tubeData->GetPointData()->SetActiveScalars("Scalar");
    auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    mapper->SetInputData(tubeData);
    mapper->SetScalarRange(0.0, 1.0);
    Built b;
    b.Actor = vtkSmartPointer<vtkActor>::New();
    b.Actor->SetMapper(mapper);
    // Float positions and normals, RGBA colors per point, triangle indices.
    b.GPUBytes = [tubeData]() { return PolyDataGPUBytes(tubeData, true); };
    return b;
  };
  r["linesastubes"] = [](vtkPolyData* data)
  {
    auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    mapper->SetInputData(data);
    mapper->SetScalarRange(0.0, 1.0);
    Built b;
    b.Actor = vtkSmartPointer<vtkActor>::New();
    b.Actor->SetMapper(mapper);
    b.Actor->GetProperty()->SetRenderLinesAsTubes(true);
    b.Actor->GetProperty()->SetLineWidth(4);
    // Positions and colors per point, 2 indices per line segment.
    b.GPUBytes = [data]()
    {
      const vtkIdType segments = data->GetNumberOfPoints() - data->GetNumberOfLines();
      return static_cast<double>(data->GetNumberOfPoints()) * (12 + 4) +
        static_cast<double>(segments) * 2 * 4;
    };
    return b;
  };
  return r;
}

struct Result
{
  double FirstFrame = 0.0;
  double MedianFrame = 0.0;
  double MedianFrameCPU = 0.0;
  double BestFrameCPU = 0.0;
  double BytesPerSegment = 0.0;
  int Frames = 0;
};

Result Run(const Factory& factory, vtkPolyData* data, double boxSize, vtkRenderWindow* window,
  int frames, double maxSeconds, bool close, const std::string& snapshot, bool trace)
{
  const vtkIdType segments = data->GetNumberOfPoints() - data->GetNumberOfLines();
  vtkSmartPointer<vtkRenderer> renderer = splineviz_benchmark::AddWarmRenderer(window);

  Result r;
  const double start = Now();
  Built built = factory(data);
  renderer->AddActor(built.Actor);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetFocalPoint(0, 0, 0);
  // Far: the whole box in view (medium coverage); close: inside the box's
  // front half (high coverage), as in Salm §3.3.
  const double distance = (close ? 0.9 : 2.4) * boxSize;
  const double nearPlane = 0.01 * boxSize, farPlane = distance + boxSize;
  camera->SetPosition(0, 0, distance);
  camera->SetViewUp(0, 1, 0);
  camera->SetViewAngle(30);
  camera->SetClippingRange(nearPlane, farPlane);
  splineviz_benchmark::RenderFrame(window);
  r.FirstFrame = Now() - start;
  r.BytesPerSegment = built.GPUBytes() / static_cast<double>(segments);
  if (trace && built.Summary)
  {
    std::printf("    first frame drew %s\n", built.Summary().c_str());
  }
  if (!snapshot.empty())
  {
    vtkNew<vtkWindowToImageFilter> grab;
    grab->SetInput(window);
    grab->ReadFrontBufferOff();
    vtkNew<vtkPNGWriter> writer;
    writer->SetInputConnection(grab->GetOutputPort());
    writer->SetFileName(snapshot.c_str());
    writer->Write();
  }

  splineviz_benchmark::FrameTimes times;
  long f0 = 0;
  times.Orbit(
    window, camera, frames, maxSeconds, 5,
    [&](int)
    {
      camera->SetClippingRange(nearPlane, farPlane);
      f0 = splineviz_benchmark::MinorFaults();
    },
    [&](int i)
    {
      if (trace)
      {
        std::printf("    frame %3d: %7.1f ms, CPU %7.1f ms, %6ld minor page faults\n", i,
          1000.0 * times.Wall.back(), 1000.0 * times.CPU.back(),
          splineviz_benchmark::MinorFaults() - f0);
      }
    });
  r.Frames = times.Count();
  r.MedianFrame = times.MedianWall();
  r.MedianFrameCPU = times.MedianCPU();
  r.BestFrameCPU = times.BestCPU();
  renderer->RemoveAllViewProps();
  window->RemoveRenderer(renderer);
  built.Actor->ReleaseGraphicsResources(window);
  return r;
}
}

const char* const Usage =
  "Usage: SplineVizTubeBenchmark [--data fibers|fibers2|million|long] [--size WxH]\n"
  "    [--frames N] [--renderers raycast,tubefilter,linesastubes,tessellated,...]\n"
  "    [--distance far|close] [--seconds S] [--samples N] [--snapshots DIR]\n"
  "    [--trace 1] (each frame's time, CPU time and minor page faults)\n"
  "    [--allocator steady|default] (steady: freed heap memory stays in the process)\n"
  "Several --data/--size/--renderers values may be given, comma separated.\n"
  "Defaults: --data fibers2 --size 800x600,1200x768 --frames 60 --seconds 30.\n";

int main(int argc, char* argv[])
{
  // Both cores for the CPU work (VTK's default SMP backend is sequential).
  vtkSMPTools::SetBackend("STDThread");
  std::vector<std::string> datasets = { "fibers2" };
  std::vector<std::string> sizes = { "800x600", "1200x768" };
  std::vector<std::string> renderers = { "raycast", "tubefilter", "linesastubes" };
  int frames = 60;
  double seconds = 30.0;
  bool close = false;
  int samples = 0;
  std::string snapshots;
  bool trace = false;
  bool steadyAllocator = true;
  splineviz_benchmark::Options options(Usage);
  options.List("--data", datasets)
    .Sizes("--size", sizes)
    .List("--renderers", renderers)
    .Int("--frames", frames, 5)
    .Double("--seconds", seconds)
    .Add("--distance", [&](const std::string& v) { close = v == "close"; })
    .Add("--trace", [&](const std::string& v) { trace = v != "0"; })
    .Add("--allocator", [&](const std::string& v) { steadyAllocator = v != "default"; })
    .Int("--samples", samples, 0)
    .Text("--snapshots", snapshots);
  const int exitCode = options.Parse(argc, argv);
  if (exitCode >= 0)
  {
    return exitCode;
  }
  // The same allocator for every renderer (see SteadyAllocator()).
  const bool steady = steadyAllocator && splineviz_benchmark::SteadyAllocator();
  std::printf("allocator: %s\n",
    steady ? "steady (freed heap memory stays in the process; --allocator default: glibc's)"
           : "the C library's default");
  const auto factories = Renderers();
  if (!splineviz_benchmark::AllKnown(
        renderers, splineviz_benchmark::Names(factories), "renderer") ||
    !splineviz_benchmark::AllKnown(
      datasets, { "fibers", "fibers2", "million", "long" }, "data set"))
  {
    return 2;
  }

  for (const auto& dataset : datasets)
  {
    vtkSmartPointer<vtkPolyData> data;
    double boxSize = 1.0;
    if (dataset == "long")
    {
      // About 2.3 units across; framed as BenchmarkStylizedLines frames it
      // (tubes about 1 pixel wide at 1200x768, up to 3 near the camera).
      data = splineviz_benchmark::LongCurves();
      boxSize = 1.5;
    }
    else
    {
      vtkNew<vtkSyntheticFibersSource> source;
      if (dataset == "fibers")
        source->SetPresetToFibers();
      else if (dataset == "fibers2")
        source->SetPresetToFibers2();
      else
        source->SetPresetToOneMillion();
      source->Update();
      data = source->GetOutput();
      boxSize = source->GetBoxSize();
    }
    data->GetPointData()->SetActiveScalars("Scalar");
    const vtkIdType segments = data->GetNumberOfPoints() - data->GetNumberOfLines();
    std::printf("\n== %s: %lld tubes, %lld segments, camera %s\n", dataset.c_str(),
      static_cast<long long>(data->GetNumberOfLines()), static_cast<long long>(segments),
      close ? "close" : "far");
    for (const auto& size : sizes)
    {
      int w = 800, h = 600;
      splineviz_benchmark::ParseSize(size, w, h);
      vtkNew<vtkRenderWindow> window;
      window->SetOffScreenRendering(1);
      window->SetSize(w, h);
      window->SetMultiSamples(samples);
      std::printf("-- %dx%d%s\n", w, h,
        samples ? (", " + std::to_string(samples) + "x multisampling").c_str() : "");
      std::printf("  %-28s %14s %16s %10s %10s %14s %8s\n", "renderer", "first frame s",
        "median frame ms", "(CPU ms)", "(best CPU)", "GPU B/segment", "frames");
      std::map<std::string, Result> results;
      for (const auto& name : renderers)
      {
        const std::string snapshot =
          snapshots.empty() ? "" : snapshots + "/" + dataset + "-" + size + "-" + name + ".png";
        const Result r =
          Run(factories.at(name), data, boxSize, window, frames, seconds, close, snapshot, trace);
        results[name] = r;
        std::printf("  %-28s %14.3f %16.1f %10.1f %10.1f %14.1f %8d\n", name.c_str(), r.FirstFrame,
          1000.0 * r.MedianFrame, 1000.0 * r.MedianFrameCPU, 1000.0 * r.BestFrameCPU,
          r.BytesPerSegment, r.Frames);
        std::fflush(stdout);
      }
      for (const auto& name : renderers)
      {
        if (name == "tubefilter" || name == "linesastubes" || !results.count("tubefilter"))
          continue;
        const Result& a = results[name];
        const Result& t = results["tubefilter"];
        std::printf("  %s vs tubefilter: first frame %.1fx shorter, GPU memory %.1fx smaller, "
                    "frame time ratio %.2f (<1: faster)\n",
          name.c_str(), t.FirstFrame / a.FirstFrame, t.BytesPerSegment / a.BytesPerSegment,
          a.MedianFrame / t.MedianFrame);
        if (results.count("linesastubes"))
        {
          const Result& l = results["linesastubes"];
          std::printf("  %s vs linesastubes: frame time ratio %.2f, first frame ratio %.2f\n",
            name.c_str(), a.MedianFrame / l.MedianFrame, a.FirstFrame / l.FirstFrame);
        }
      }
    }
  }
  return 0;
}
