// SPDX-License-Identifier: BSD-3-Clause
// What the benchmark programs share: command-line help (each program passes
// its usage text; `-h` or `--help` anywhere on the command line prints it and
// ends the program before any work starts), "--key value" checks and
// comma-separated lists, wall and process CPU clocks, and the bytes
// vtkOpenGLPolyDataMapper keeps on the GPU for a polygonal data set (the
// VTK paths the SplineViz renderers are compared with), and the polyline data
// sets more than one benchmark draws (LongCurves()).
#ifndef BenchmarkCommon_h
#define BenchmarkCommon_h

#include "vtkCellArray.h"
#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <sys/resource.h>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <sstream>
#include <string>
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
