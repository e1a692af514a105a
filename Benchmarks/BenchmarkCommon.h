// SPDX-License-Identifier: BSD-3-Clause
// What the benchmark programs share: command-line help (each program passes
// its usage text; `-h` or `--help` anywhere on the command line prints it and
// ends the program before any work starts), "--key value" options (Options)
// and comma-separated lists, wall and process CPU clocks, and the bytes
// vtkOpenGLPolyDataMapper keeps on the GPU for a polygonal data set (the
// VTK paths the SplineViz renderers are compared with), and the polyline data
// sets more than one benchmark draws (LongCurves()), and the timing of
// rendered frames (AddWarmRenderer(), RenderFrame(), FrameTimes).
#ifndef BenchmarkCommon_h
#define BenchmarkCommon_h

#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"

#include <sys/resource.h>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include <algorithm>
#include <array>
#include <chrono>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace splineviz_benchmark
{
/// True (after printing `usage` to stdout) when -h or --help was given.
inline bool HelpRequested(int argc, char* argv[], const char* usage)
{
  for (int i = 1; i < argc; ++i)
  {
    if (!std::strcmp(argv[i], "-h") || !std::strcmp(argv[i], "--help"))
    {
      std::fputs(usage, stdout);
      return true;
    }
  }
  return false;
}

/// For "--key value" parsers: an option without its value is an error.
inline bool MissingOptionValue(int argc, char* argv[], const char* usage)
{
  if (argc % 2 == 0)
  {
    std::fprintf(stderr, "option %s needs a value\n%s", argv[argc - 1], usage);
    return true;
  }
  return false;
}

/// "a,b,c" -> {"a", "b", "c"} (empty items dropped).
inline std::vector<std::string> Split(const std::string& s)
{
  std::vector<std::string> out;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, ','))
  {
    if (!item.empty())
    {
      out.push_back(item);
    }
  }
  return out;
}

/// True when every item of `values` is one of `known`; otherwise says which
/// is not (`what` names the kind of item, e.g. "renderer"), lists the known
/// ones and returns false.
inline bool AllKnown(
  const std::vector<std::string>& values, const std::vector<std::string>& known, const char* what)
{
  for (const auto& value : values)
  {
    bool found = false;
    for (const auto& k : known)
    {
      found = found || k == value;
    }
    if (!found)
    {
      std::string list;
      for (const auto& k : known)
      {
        list += (list.empty() ? "" : ", ") + k;
      }
      std::fprintf(stderr, "unknown %s %s (known: %s)\n", what, value.c_str(), list.c_str());
      return false;
    }
  }
  return true;
}

/// "800x600" -> w = 800, h = 600; false for anything else.
inline bool ParseSize(const std::string& size, int& w, int& h)
{
  char rest = 0;
  return std::sscanf(size.c_str(), "%dx%d%c", &w, &h, &rest) == 2 && w > 0 && h > 0;
}

/// True when every "WxH" of `sizes` parses; otherwise says which does not
/// (with the usage) and returns false.
inline bool ValidSizes(const std::vector<std::string>& sizes, const char* usage)
{
  for (const auto& size : sizes)
  {
    int w = 0, h = 0;
    if (!ParseSize(size, w, h))
    {
      std::fprintf(stderr, "bad window size %s (WxH)\n%s", size.c_str(), usage);
      return false;
    }
  }
  return true;
}

/// The names (keys) of a map of renderer factories.
template <typename Map>
std::vector<std::string> Names(const Map& map)
{
  std::vector<std::string> names;
  for (const auto& item : map)
  {
    names.push_back(item.first);
  }
  return names;
}

/**
 * The "--key value" options of a program: each option names where its value
 * goes; Parse() prints the usage for -h / --help and refuses an option
 * without its value, an unknown option and a bad window size.
 */
class Options
{
public:
  explicit Options(const char* usage)
    : Usage(usage)
  {
  }

  /// Any option: `set` receives its value.
  Options& Add(const char* key, std::function<void(const std::string&)> set)
  {
    this->Keys.emplace_back(key, std::move(set));
    return *this;
  }
  /// A comma-separated list.
  Options& List(const char* key, std::vector<std::string>& values)
  {
    return this->Add(key, [&values](const std::string& v) { values = Split(v); });
  }
  /// A comma-separated list of "WxH" window sizes.
  Options& Sizes(const char* key, std::vector<std::string>& sizes)
  {
    this->SizeLists.push_back(&sizes);
    return this->List(key, sizes);
  }
  /// An integer, at least `minimum`.
  Options& Int(const char* key, int& value, int minimum = INT_MIN)
  {
    return this->Add(key,
      [&value, minimum](const std::string& v) { value = std::max(minimum, std::atoi(v.c_str())); });
  }
  Options& Double(const char* key, double& value)
  {
    return this->Add(key, [&value](const std::string& v) { value = std::atof(v.c_str()); });
  }
  Options& Text(const char* key, std::string& value)
  {
    return this->Add(key, [&value](const std::string& v) { value = v; });
  }

  /// -1 when the program goes on; else its exit code (0 after the help, 2 after an error).
  int Parse(int argc, char* argv[]) const
  {
    if (HelpRequested(argc, argv, this->Usage))
    {
      return 0;
    }
    if (MissingOptionValue(argc, argv, this->Usage))
    {
      return 2;
    }
    for (int i = 1; i + 1 < argc; i += 2)
    {
      const std::string key = argv[i];
      auto option = std::find_if(this->Keys.begin(), this->Keys.end(),
        [&key](const std::pair<std::string, std::function<void(const std::string&)>>& k)
        { return k.first == key; });
      if (option == this->Keys.end())
      {
        std::fprintf(stderr, "unknown option %s\n%s", key.c_str(), this->Usage);
        return 2;
      }
      option->second(argv[i + 1]);
    }
    for (const auto* sizes : this->SizeLists)
    {
      if (!ValidSizes(*sizes, this->Usage))
      {
        return 2;
      }
    }
    return -1;
  }

private:
  const char* Usage;
  std::vector<std::pair<std::string, std::function<void(const std::string&)>>> Keys;
  std::vector<const std::vector<std::string>*> SizeLists;
};

/// Wall-clock seconds (monotonic).
inline double Now()
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

/// CPU time of the whole process (all threads, including llvmpipe's): less
/// sensitive than wall time to other processes sharing the machine.
inline double CPUTime()
{
  struct rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_utime.tv_sec + usage.ru_stime.tv_sec +
    1e-6 * (usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

/// Keep freed heap memory in the process (glibc: trim threshold 256 MB,
/// blocks up to 32 MB from the heap)
/// instead of glibc's default, which returns the top of the heap to the
/// system when more than 128 kB is free there, until the process frees its
/// first large mapped block (the threshold then grows with it). llvmpipe
/// allocates its bins (the triangles of a scene, tens of megabytes per frame)
/// in 64 kB blocks and frees them after each scene: with the default, every
/// frame of whichever renderer runs first in a fresh process maps those
/// pages in again (thousands of page faults, up to twice the frame time),
/// and a renderer that runs after a large free does not. Applied before any
/// renderer runs, so that all run with the same allocator. Returns false
/// where it is not available.
inline bool SteadyAllocator()
{
#if defined(__GLIBC__)
  // Setting the trim threshold also ends glibc's growing of the mapping
  // threshold: set that to its largest value as well, or every block over
  // 128 kB (llvmpipe's per-draw vertex buffers) is mapped in anew.
  return mallopt(M_TRIM_THRESHOLD, 256 * 1024 * 1024) == 1 &&
    mallopt(M_MMAP_THRESHOLD, 32 * 1024 * 1024) == 1;
#else
  return false;
#endif
}

/// Minor page faults of the process so far (memory the kernel had to map in).
inline long MinorFaults()
{
  struct rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_minflt;
}

/// Renders one frame of `window` and waits until the GPU has finished it.
inline void RenderFrame(vtkRenderWindow* window)
{
  window->Render();
  window->WaitForCompletion();
}

/// A renderer with the benchmarks' background added to `window`, whose
/// context is warmed up by one frame (not part of any measured frame).
inline vtkSmartPointer<vtkRenderer> AddWarmRenderer(vtkRenderWindow* window)
{
  auto renderer = vtkSmartPointer<vtkRenderer>::New();
  renderer->SetBackground(0.1, 0.1, 0.12);
  window->AddRenderer(renderer);
  RenderFrame(window);
  return renderer;
}

/// The wall and process CPU seconds of rendered frames.
struct FrameTimes
{
  std::vector<double> Wall, CPU;

  /// Renders one frame (RenderFrame()) and records its times.
  void Render(vtkRenderWindow* window)
  {
    const double t0 = Now();
    const double c0 = CPUTime();
    RenderFrame(window);
    this->Wall.push_back(Now() - t0);
    this->CPU.push_back(CPUTime() - c0);
  }
  /**
   * An orbit: up to `frames` frames, the camera turned by 360 / frames
   * degrees (Azimuth) before each, ended after `maxSeconds` once
   * `minimumFrames` are done; `before(i)` and `after(i)` (if given) run
   * around frame i. The times are sorted afterwards.
   */
  void Orbit(vtkRenderWindow* window, vtkCamera* camera, int frames, double maxSeconds,
    int minimumFrames, const std::function<void(int)>& before = nullptr,
    const std::function<void(int)>& after = nullptr)
  {
    const double start = Now();
    for (int i = 0; i < frames; ++i)
    {
      camera->Azimuth(360.0 / frames);
      if (before)
      {
        before(i);
      }
      this->Render(window);
      if (after)
      {
        after(i);
      }
      if (Now() - start > maxSeconds && this->Count() >= minimumFrames)
      {
        break;
      }
    }
    this->Sort();
  }
  int Count() const { return static_cast<int>(this->Wall.size()); }
  /// Sorts the times, for the medians and the best.
  void Sort()
  {
    std::sort(this->Wall.begin(), this->Wall.end());
    std::sort(this->CPU.begin(), this->CPU.end());
  }
  ///@{
  /// After Sort() (at least one frame).
  double MedianWall() const { return this->Wall[this->Wall.size() / 2]; }
  double MedianCPU() const { return this->CPU[this->CPU.size() / 2]; }
  double BestCPU() const { return this->CPU.front(); }
  ///@}
};

/// What vtkOpenGLPolyDataMapper uploads for a polygonal data set: float
/// positions and normals, RGBA colors when scalars are colored, 3 indices
/// per triangle of the strips and polygons.
inline double PolyDataGPUBytes(vtkPolyData* pd, bool colors)
{
  vtkIdType triangles = 0;
  vtkCellArray* strips = pd->GetStrips();
  triangles += strips->GetNumberOfConnectivityIds() - 2 * strips->GetNumberOfCells();
  vtkCellArray* polys = pd->GetPolys();
  triangles += polys->GetNumberOfConnectivityIds() - 2 * polys->GetNumberOfCells();
  return static_cast<double>(pd->GetNumberOfPoints()) * (12 + 12 + (colors ? 4 : 0)) +
    static_cast<double>(triangles) * 3 * 4;
}

/// Polylines with "Radius" and "Scalar" point arrays.
struct Lines
{
  vtkNew<vtkPoints> Points;
  vtkNew<vtkCellArray> Cells;
  vtkNew<vtkFloatArray> Radius;
  vtkNew<vtkFloatArray> Scalar;
  Lines()
  {
    this->Radius->SetName("Radius");
    this->Scalar->SetName("Scalar");
  }
  void Add(const std::vector<std::array<double, 3>>& curve, double radius)
  {
    this->Cells->InsertNextCell(static_cast<int>(curve.size()));
    for (size_t i = 0; i < curve.size(); ++i)
    {
      this->Cells->InsertCellPoint(this->Points->InsertNextPoint(curve[i].data()));
      this->Radius->InsertNextValue(static_cast<float>(radius));
      this->Scalar->InsertNextValue(static_cast<float>(i) / (curve.size() - 1));
    }
  }
  vtkSmartPointer<vtkPolyData> Make()
  {
    auto pd = vtkSmartPointer<vtkPolyData>::New();
    pd->SetPoints(this->Points);
    pd->SetLines(this->Cells);
    pd->GetPointData()->AddArray(this->Radius);
    pd->GetPointData()->AddArray(this->Scalar);
    pd->GetPointData()->SetActiveScalars("Scalar");
    return pd;
  }
};

/// Long smooth curves, Fibers2-sized (1,701 curves x 68 points, 113,967
/// segments, radius 0.0012, about 2 x 2.3 x 2.3 units, running along z):
/// segments about 25 radii long, the second shape of streamlines and
/// tractograms besides the short segments of vtkSyntheticFibersSource.
inline vtkSmartPointer<vtkPolyData> LongCurves()
{
  Lines lines;
  for (int l = 0; l < 1701; ++l)
  {
    std::vector<std::array<double, 3>> c;
    const double x0 = -1.0 + 2.0 * ((l * 53) % 1701) / 1701.0;
    const double y0 = -1.0 + 2.0 * ((l * 97) % 1701) / 1701.0;
    for (int i = 0; i < 68; ++i)
    {
      const double s = -1.0 + 2.0 * i / 67.0;
      c.push_back(
        { x0 + 0.15 * std::sin(3.0 * s + l), y0 + 0.15 * std::cos(2.0 * s + 0.5 * l), s });
    }
    lines.Add(c, 0.0012);
  }
  return lines.Make();
}
}

#endif
