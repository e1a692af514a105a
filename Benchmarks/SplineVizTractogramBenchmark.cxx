// SPDX-License-Identifier: BSD-3-Clause
// Whole-brain tractograms: the SplineViz line renderers against VTK's ways of
// drawing lines, at tractography's real sizes, side by side in one run.
//
// Data: synthetic whole-brain tractograms (vtkSyntheticTractogramSource:
// bundles of dense, overlapping streamlines of 50-200 points, 1 mm steps) at
// the given streamline counts, and DIPY's real cb_2 bundle; each written as
// an MRtrix .tck file once. Renderers: "raycast" (vtkRayCastTubeMapper),
// "tessellated" (vtkTessellatedTubeMapper), "stylized"
// (vtkStylizedLineMapper), and VTK's "lines" (vtkPolyDataMapper),
// "linesastubes" (vtkProperty::RenderLinesAsTubes, 3 pixels) and "tubefilter"
// (vtkTubeFilter, 8 sides; "tubefilter12": 12 sides; + vtkPolyDataMapper; only up to
// --tubefilter-max points: it needs about 400 bytes per point). Every (data, renderer) pair runs in
// a process of its own (this program, --child), so that its peak memory is its own and its window
// new (the first frame pays the shader compilation, as a user's does). Each child reads the .tck
// with vtkTractogramReader and reports:
//  - read: the reader's time and the peak RSS after reading,
//  - first: from the polylines in memory to the first finished frame,
//  - still: the median frame of an orbit (camera 10 degrees per frame), its
//    per-view CPU work (view s) and, for the stylized lines, the part of it
//    their fix-up takes (fixup s),
//  - interactive: the median frame while the render window asks for 15
//    frames per second (as VTK's interactors do while the camera moves), and
//    the fraction of the lines the SplineViz renderers drew,
//  - GPU bytes per segment, and the process' peak RSS.
// Ratios are to VTK's plain lines of the same data in the same run. With
// --png DIR, each child also writes its last still frame to
// DIR/<.tck name>-<renderer>.png, to look at what was measured.
//
// Usage:
//   SplineVizTractogramBenchmark [--streamlines 10000,100000,200000,1000000]
//       [--data synthetic,cb2] [--renderers
//       raycast,tessellated,stylized,lines,linesastubes,tubefilter]
//       [--size 1200x768] [--frames 8] [--interactive 8] [--radius 0.3]
//       [--dir /tmp] [--csv FILE] [--tubefilter-max 3000000] [--png DIR]
#include "BenchmarkCommon.h"
#include "vtkRayCastTubeMapper.h"
#include "vtkSplineTubeMapper.h"
#include "vtkStylizedLineMapper.h"
#include "vtkSyntheticTractogramSource.h"
#include "vtkTessellatedTubeMapper.h"
#include "vtkTractogramReader.h"
#include "vtkTractogramWriter.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkPNGWriter.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTubeFilter.h"
#include "vtkWindowToImageFilter.h"
#include "vtkXMLPolyDataReader.h"

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <string>
#include <vector>

namespace
{
using splineviz_benchmark::Now;
using splineviz_benchmark::Split;

const char* Usage =
  "SplineVizTractogramBenchmark [--streamlines 10000,100000,200000,1000000]\n"
  "    [--data synthetic,cb2] [--renderers "
  "raycast,tessellated,stylized,lines,linesastubes,tubefilter]\n"
  "    [--size 1200x768] [--frames 8] [--interactive 8] [--radius 0.3] [--dir /tmp]\n"
  "    [--csv FILE] [--tubefilter-max 3000000] [--png DIR]\n";

double PeakRSSGB()
{
  struct rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1e6; // kB -> GB
}

double Median(std::vector<double> v)
{
  if (v.empty())
  {
    return 0.0;
  }
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

/// "splineviz-benchmark-1000" of "/tmp/splineviz-benchmark-1000.tck".
std::string Stem(const std::string& path)
{
  const size_t slash = path.find_last_of('/');
  std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  return name.substr(0, name.find_last_of('.'));
}

/// One renderer on one file, in this (child) process; prints a RESULT line.
int Child(const std::string& file, const std::string& renderer, int width, int height, int frames,
  int interactiveFrames, double radius, const std::string& png)
{
  splineviz_benchmark::SteadyAllocator();
  double t0 = Now();
  vtkNew<vtkTractogramReader> reader;
  reader->SetFileName(file.c_str());
  reader->Update();
  const double readTime = Now() - t0;
  const double readRSS = PeakRSSGB();
  vtkPolyData* lines = reader->GetOutput();
  const vtkIdType segments = lines->GetNumberOfPoints() - lines->GetNumberOfLines();

  vtkNew<vtkRenderer> ren;
  ren->SetBackground(1.0, 1.0, 1.0);
  vtkNew<vtkRenderWindow> window;
  window->SetSize(width, height);
  window->SetMultiSamples(0);
  window->SetOffScreenRendering(1);
  window->AddRenderer(ren);
  vtkNew<vtkActor> actor;
  actor->GetProperty()->SetColor(0.8, 0.35, 0.2);
  ren->AddActor(actor);

  t0 = Now();
  vtkSmartPointer<vtkSplineTubeMapper> tubes;
  vtkSmartPointer<vtkPolyDataMapper> polys;
  vtkSmartPointer<vtkTubeFilter> filter;
  if (renderer == "raycast")
  {
    tubes = vtkSmartPointer<vtkRayCastTubeMapper>::New();
  }
  else if (renderer == "tessellated")
  {
    tubes = vtkSmartPointer<vtkTessellatedTubeMapper>::New();
  }
  else if (renderer == "stylized")
  {
    tubes = vtkSmartPointer<vtkStylizedLineMapper>::New();
  }
  else
  {
    polys = vtkSmartPointer<vtkPolyDataMapper>::New();
    if (renderer.compare(0, 10, "tubefilter") == 0)
    {
      // "tubefilter": 8 sides; "tubefilter12": 12.
      const int sides = renderer.size() > 10 ? std::atoi(renderer.c_str() + 10) : 8;
      filter = vtkSmartPointer<vtkTubeFilter>::New();
      filter->SetInputData(lines);
      filter->SetNumberOfSides(std::max(3, sides));
      filter->SetRadius(radius);
      polys->SetInputConnection(filter->GetOutputPort());
    }
    else
    {
      polys->SetInputData(lines);
      if (renderer == "linesastubes")
      {
        actor->GetProperty()->SetRenderLinesAsTubes(true);
        actor->GetProperty()->SetLineWidth(3.0);
      }
    }
    polys->ScalarVisibilityOff();
    actor->SetMapper(polys);
  }
  if (tubes)
  {
    tubes->SetInputData(lines);
    tubes->SetRadius(radius);
    tubes->ScalarVisibilityOff();
    actor->SetMapper(tubes);
  }
  ren->ResetCamera();
  window->Render();
  const double first = Now() - t0;

  std::vector<double> still;
  std::vector<double> perView;
  std::vector<double> fixUp;
  auto* stylized = vtkStylizedLineMapper::SafeDownCast(tubes);
  for (int f = 0; f < frames; ++f)
  {
    ren->GetActiveCamera()->Azimuth(10.0);
    const double s = Now();
    window->Render();
    still.push_back(Now() - s);
    perView.push_back(tubes ? tubes->GetLastPerViewTime() : 0.0);
    fixUp.push_back(stylized ? stylized->GetLastFixUpTime() : 0.0);
  }
  if (!png.empty())
  {
    vtkNew<vtkWindowToImageFilter> grab;
    grab->SetInput(window);
    grab->ReadFrontBufferOff();
    vtkNew<vtkPNGWriter> writer;
    writer->SetInputConnection(grab->GetOutputPort());
    writer->SetFileName(png.c_str());
    writer->Write();
  }
  std::vector<double> interactive;
  double fraction = 1.0;
  window->SetDesiredUpdateRate(15.0);
  for (int f = 0; f < interactiveFrames; ++f)
  {
    ren->GetActiveCamera()->Azimuth(5.0);
    const double s = Now();
    window->Render();
    if (f > 0)
    {
      interactive.push_back(Now() - s); // (the first adapts from the still frames)
    }
    if (tubes)
    {
      fraction = tubes->GetLastLineFraction();
    }
  }
  double gpu = 0.0;
  if (tubes)
  {
    gpu = static_cast<double>(tubes->GetGPUMemorySize());
  }
  else if (filter)
  {
    gpu = splineviz_benchmark::PolyDataGPUBytes(filter->GetOutput(), false);
  }
  else
  {
    gpu = 12.0 * lines->GetNumberOfPoints() + 8.0 * segments; // points, line indices
  }
  std::printf("RESULT %lld %.3f %.3f %.3f %.3f %.3f %.4f %.1f %.3f %.3f %.3f\n",
    static_cast<long long>(segments), readTime, readRSS, first, Median(still), Median(interactive),
    fraction, gpu / std::max<vtkIdType>(segments, 1), PeakRSSGB(), Median(perView), Median(fixUp));
  return 0;
}

struct Result
{
  bool Ok = false;
  long long Segments = 0;
  double Read = 0, ReadRSS = 0, First = 0, Still = 0, Interactive = 0, Fraction = 1, GPU = 0,
         RSS = 0;
  double PerView = 0; ///< of the still frames: per-view CPU work (our renderers)
  double FixUp = 0;   ///< of the still frames: the stylized lines' fix-up, part of PerView
};

/// Run this program as a child for one (file, renderer); parse its RESULT line.
Result RunChild(const char* self, const std::string& file, const std::string& renderer,
  const std::string& size, int frames, int interactive, double radius, const std::string& png)
{
  Result r;
  const std::string command = std::string("'") + self + "' --child '" + file + "' " + renderer +
    " " + size + " " + std::to_string(frames) + " " + std::to_string(interactive) + " " +
    std::to_string(radius) + (png.empty() ? std::string() : " '" + png + "'") + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe)
  {
    return r;
  }
  char line[1024];
  while (std::fgets(line, sizeof(line), pipe))
  {
    if (std::sscanf(line, "RESULT %lld %lf %lf %lf %lf %lf %lf %lf %lf %lf %lf", &r.Segments,
          &r.Read, &r.ReadRSS, &r.First, &r.Still, &r.Interactive, &r.Fraction, &r.GPU, &r.RSS,
          &r.PerView, &r.FixUp) == 11)
    {
      r.Ok = true;
    }
  }
  pclose(pipe);
  return r;
}

/// The data sets: (name, .tck file), written once.
std::vector<std::pair<std::string, std::string>> MakeData(const std::vector<std::string>& kinds,
  const std::vector<std::string>& counts, const std::string& dir)
{
  std::vector<std::pair<std::string, std::string>> data;
  for (const std::string& kind : kinds)
  {
    if (kind == "cb2")
    {
      const std::string vtp = SPLINEVIZ_DIPY_DATA_DIR "/cb_2.vtp";
      vtkNew<vtkXMLPolyDataReader> reader;
      reader->SetFileName(vtp.c_str());
      reader->Update();
      const std::string tck = dir + "/splineviz-benchmark-cb2.tck";
      vtkNew<vtkTractogramWriter> writer;
      writer->SetInputConnection(reader->GetOutputPort());
      writer->SetFileName(tck.c_str());
      if (writer->Write())
      {
        data.emplace_back("cb_2 (DIPY)", tck);
      }
      continue;
    }
    for (const std::string& count : counts)
    {
      const std::string tck = dir + "/splineviz-benchmark-" + count + ".tck";
      std::ifstream exists(tck);
      if (!exists)
      {
        vtkNew<vtkSyntheticTractogramSource> source;
        source->SetNumberOfStreamlines(std::stoll(count));
        vtkNew<vtkTractogramWriter> writer;
        writer->SetInputConnection(source->GetOutputPort());
        writer->SetFileName(tck.c_str());
        if (!writer->Write())
        {
          std::fprintf(stderr, "could not write %s\n", tck.c_str());
          continue;
        }
      }
      data.emplace_back(count + " streamlines", tck);
    }
  }
  return data;
}
}

int main(int argc, char* argv[])
{
  if (argc >= 8 && std::string(argv[1]) == "--child")
  {
    int w = 0, h = 0;
    splineviz_benchmark::ParseSize(argv[4], w, h);
    return Child(argv[2], argv[3], w, h, std::atoi(argv[5]), std::atoi(argv[6]), std::atof(argv[7]),
      argc >= 9 ? argv[8] : "");
  }
  if (splineviz_benchmark::HelpRequested(argc, argv, Usage) ||
    splineviz_benchmark::MissingOptionValue(argc, argv, Usage))
  {
    return argc > 1 && argc % 2 == 0 ? EXIT_FAILURE : EXIT_SUCCESS;
  }
  std::map<std::string, std::string> options = { { "--streamlines", "10000,100000,200000,1000000" },
    { "--data", "synthetic,cb2" },
    { "--renderers", "raycast,tessellated,stylized,lines,linesastubes,tubefilter" },
    { "--size", "1200x768" }, { "--frames", "8" }, { "--interactive", "8" }, { "--radius", "0.3" },
    { "--dir", "/tmp" }, { "--csv", "" }, { "--tubefilter-max", "3000000" }, { "--png", "" } };
  for (int i = 1; i + 1 < argc; i += 2)
  {
    if (!options.count(argv[i]))
    {
      std::fprintf(stderr, "unknown option %s\n%s", argv[i], Usage);
      return EXIT_FAILURE;
    }
    options[argv[i]] = argv[i + 1];
  }
  const std::vector<std::string> renderers = Split(options["--renderers"]);
  if (!splineviz_benchmark::AllKnown(renderers,
        { "raycast", "tessellated", "stylized", "lines", "linesastubes", "tubefilter",
          "tubefilter12" },
        "renderer") ||
    !splineviz_benchmark::ValidSizes({ options["--size"] }, Usage))
  {
    return EXIT_FAILURE;
  }
  const int frames = std::max(1, std::atoi(options["--frames"].c_str()));
  const int interactive = std::max(2, std::atoi(options["--interactive"].c_str()));
  const double radius = std::atof(options["--radius"].c_str());
  const double tubeFilterMax = std::atof(options["--tubefilter-max"].c_str());
  std::FILE* csv = options["--csv"].empty() ? nullptr : std::fopen(options["--csv"].c_str(), "w");
  if (csv)
  {
    std::fprintf(csv,
      "data,renderer,segments,read_s,read_rss_gb,first_s,still_s,interactive_s,"
      "fraction,gpu_bytes_per_segment,peak_rss_gb,per_view_s,fixup_s\n");
  }
  std::printf("Tractograms at %s, radius %g mm, %d still and %d interactive frames; each "
              "renderer in a process of its own. Ratios to VTK's plain lines.\n",
    options["--size"].c_str(), radius, frames, interactive);
  const double start = Now();
  for (const auto& data :
    MakeData(Split(options["--data"]), Split(options["--streamlines"]), options["--dir"]))
  {
    std::printf("\n== %s\n", data.first.c_str());
    std::printf("%-13s %10s %7s %7s %8s %7s %7s %8s %9s %8s %7s %7s %7s\n", "renderer", "segments",
      "read s", "first s", "still s", "view s", "fixup s", "inter s", "fraction", "GPU B/s",
      "RSS GB", "first x", "still x");
    std::map<std::string, Result> results;
    // VTK's lines first: the reference of the ratios.
    std::vector<std::string> order = renderers;
    std::stable_partition(
      order.begin(), order.end(), [](const std::string& r) { return r == "lines"; });
    for (const std::string& renderer : order)
    {
      Result r;
      if (renderer.compare(0, 10, "tubefilter") == 0 && !results.empty() &&
        static_cast<double>(results.begin()->second.Segments) > tubeFilterMax)
      {
        std::printf("%-13s (skipped: more than %g segments)\n", renderer.c_str(), tubeFilterMax);
        continue;
      }
      const std::string png = options["--png"].empty()
        ? std::string()
        : options["--png"] + "/" + Stem(data.second) + "-" + renderer + ".png";
      r = RunChild(
        argv[0], data.second, renderer, options["--size"], frames, interactive, radius, png);
      results[renderer] = r;
      if (!r.Ok)
      {
        std::printf("%-13s failed\n", renderer.c_str());
        continue;
      }
      const Result* lines =
        results.count("lines") && results["lines"].Ok ? &results["lines"] : nullptr;
      std::printf("%-13s %10lld %7.2f %7.2f %8.3f %7.3f %7.3f %8.3f %9.4f %8.1f %7.2f %7s %7s\n",
        renderer.c_str(), r.Segments, r.Read, r.First, r.Still, r.PerView, r.FixUp, r.Interactive,
        r.Fraction, r.GPU, r.RSS,
        lines ? std::to_string(r.First / lines->First).substr(0, 5).c_str() : "-",
        lines ? std::to_string(r.Still / lines->Still).substr(0, 5).c_str() : "-");
      std::fflush(stdout);
      if (csv)
      {
        std::fprintf(csv, "%s,%s,%lld,%.3f,%.3f,%.3f,%.3f,%.3f,%.4f,%.1f,%.3f,%.3f,%.3f\n",
          data.first.c_str(), renderer.c_str(), r.Segments, r.Read, r.ReadRSS, r.First, r.Still,
          r.Interactive, r.Fraction, r.GPU, r.RSS, r.PerView, r.FixUp);
        std::fflush(csv);
      }
    }
  }
  if (csv)
  {
    std::fclose(csv);
  }
  std::printf("\nwhole run: %.1f min\n", (Now() - start) / 60.0);
  return EXIT_SUCCESS;
}
