// SPDX-License-Identifier: BSD-3-Clause
// Superquadric tensor glyph benchmark (Hlawitschka et al. §5's questions on
// this machine): a synthetic DTI-like tensor volume (9-component tensors on
// a vtkImageData, every voxel drawn) rendered offscreen with the camera
// orbiting, for each renderer side by side in one process, reporting
//  - time to first frame: from the tensors in memory to the first finished
//    frame (all CPU work, upload, shader compilation, drawing);
//  - bytes held on the GPU per glyph;
//  - median frame time over the orbit (each frame finished with glFinish);
//  - time from a change of the glyph sharpness (gamma) to the next frame;
// for
//  - "superquadric": vtkSuperquadricGlyphMapper (per-tensor superquadrics,
//    gamma 3; a gamma change is a uniform: the mapper's upload count is
//    printed before and after the gamma changes);
//  - "superquadric-noculling": the same with occlusion culling off (one pass
//    over all glyphs, the design before culling); the ratio of the two
//    median frames is printed;
//  - "tensorglyph": vtkTensorGlyph with a vtkSuperquadricSource (16 x 16,
//    one fixed shape for all tensors) + vtkPolyDataMapper, the VTK/ParaView
//    "Tensor Glyph" way (a gamma change = a new source shape: the glyphs are
//    rebuilt and uploaded again);
//  - "glyph3dmapper": vtkGlyph3DMapper instancing the same source, oriented
//    and scaled per point by quaternions and eigenvalues computed on the CPU
//    (with SplineViz's multi-threaded eigen-decomposition; counted in the
//    first frame); a gamma change re-uploads only the source.
// The polygonal paths are skipped when their estimated memory exceeds the
// available memory (--memory GB, default 16).
//
// Usage:
//   SplineVizTensorGlyphBenchmark [--glyphs 100k,1m] [--size 800x600,1200x768]
//       [--renderers superquadric,superquadric-noculling,tensorglyph,glyph3dmapper]
//       [--frames N] [--seconds S] [--memory GB]
#include "BenchmarkCommon.h"
#include "vtkSplineVizTensorMath.h"
#include "vtkSuperquadricGlyphMapper.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkGlyph3DMapper.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkSuperquadricSource.h"
#include "vtkTensorGlyph.h"

#include <algorithm>
#include <chrono>
#include <cmath>
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
namespace TM = vtkSplineVizTensorMath;

constexpr double GlyphScale = 0.45; // semi-axis of the largest eigenvalue, voxel spacing 1

/// A DTI-like field on an n^3 grid: the principal direction turns along z
/// (a helix), the other eigenvalues vary smoothly so that linear, planar
/// and nearly spherical tensors all occur. 9 components, row-major.
vtkSmartPointer<vtkImageData> MakeTensorVolume(int n)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(n, n, n);
  vtkNew<vtkFloatArray> tensors;
  tensors->SetName("Tensors");
  tensors->SetNumberOfComponents(9);
  tensors->SetNumberOfTuples(static_cast<vtkIdType>(n) * n * n);
  float* t = tensors->GetPointer(0);
  vtkSMPTools::For(0, static_cast<vtkIdType>(n) * n * n,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType id = begin; id < end; ++id)
      {
        const int i = static_cast<int>(id % n), j = static_cast<int>((id / n) % n),
                  k = static_cast<int>(id / (static_cast<vtkIdType>(n) * n));
        const double x = static_cast<double>(i) / n, y = static_cast<double>(j) / n,
                     z = static_cast<double>(k) / n;
        const double angle = 3.0 * z + 2.0 * x;
        const double e1[3] = { std::cos(angle), std::sin(angle), 0.3 * std::sin(5.0 * y) };
        double u1[3] = { e1[0], e1[1], e1[2] };
        vtkMath::Normalize(u1);
        double u2[3];
        const double up[3] = { 0, 0, 1 };
        vtkMath::Cross(up, u1, u2);
        vtkMath::Normalize(u2);
        double u3[3];
        vtkMath::Cross(u1, u2, u3);
        const double l1 = 1.0;
        const double l2 = 0.15 + 0.8 * (0.5 + 0.5 * std::sin(6.0 * x + 4.0 * y));
        const double l3 = l2 * (0.2 + 0.75 * (0.5 + 0.5 * std::cos(5.0 * z + 3.0 * x)));
        float* out = t + 9 * id;
        for (int r = 0; r < 3; ++r)
        {
          for (int c = 0; c < 3; ++c)
          {
            out[3 * r + c] =
              static_cast<float>(l1 * u1[r] * u1[c] + l2 * u2[r] * u2[c] + l3 * u3[r] * u3[c]);
          }
        }
      }
    });
  image->GetPointData()->SetTensors(tensors);
  return image;
}

vtkSmartPointer<vtkSuperquadricSource> MakeSource(double roundness)
{
  auto source = vtkSmartPointer<vtkSuperquadricSource>::New();
  source->SetThetaResolution(16);
  source->SetPhiResolution(16);
  source->SetThetaRoundness(roundness);
  source->SetPhiRoundness(roundness);
  source->SetSize(1.0); // unit semi-axes: scaled by the eigenvalues
  source->SetZAxisOfSymmetry();
  return source;
}

/// A renderer under test: its actor, and how to change gamma.
struct Built
{
  vtkSmartPointer<vtkActor> Actor;
  std::function<double()> GPUBytes;
  std::function<void(double)> SetGamma;
  std::function<int()> Uploads; // GPU uploads of the per-glyph data, if known
  std::string Note;
};

using Factory = std::function<Built(vtkImageData*)>;

/// The superquadric glyphs, with or without occlusion culling (without: one
/// pass, as before culling existed).
Built Superquadrics(vtkImageData* data, bool culling)
{
  auto mapper = vtkSmartPointer<vtkSuperquadricGlyphMapper>::New();
  mapper->SetInputData(data);
  mapper->SetScaleFactor(GlyphScale);
  mapper->SetGamma(3.0);
  mapper->SetCulling(culling);
  Built b;
  b.Actor = vtkSmartPointer<vtkActor>::New();
  b.Actor->SetMapper(mapper);
  b.GPUBytes = [mapper]()
  { return static_cast<double>(mapper->GetGPUBytesPerGlyph()) * mapper->GetNumberOfGlyphs(); };
  b.SetGamma = [mapper](double g) { mapper->SetGamma(g); };
  b.Uploads = [mapper]() { return mapper->GetUploadCount(); };
  b.Note = culling ? "" : "culling off";
  return b;
}

std::map<std::string, Factory> Renderers()
{
  std::map<std::string, Factory> r;
  r["superquadric"] = [](vtkImageData* data) { return Superquadrics(data, true); };
  r["superquadric-noculling"] = [](vtkImageData* data) { return Superquadrics(data, false); };
  r["tensorglyph"] = [](vtkImageData* data)
  {
    auto source = MakeSource(0.3);
    auto glyphs = vtkSmartPointer<vtkTensorGlyph>::New();
    glyphs->SetInputData(data);
    glyphs->SetSourceConnection(source->GetOutputPort());
    glyphs->SetScaleFactor(GlyphScale);
    glyphs->ExtractEigenvaluesOn();
    glyphs->SetColorModeToEigenvalues();
    glyphs->ClampScalingOff();
    auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    mapper->SetInputConnection(glyphs->GetOutputPort());
    mapper->SetScalarRange(0.0, 1.0);
    Built b;
    b.Actor = vtkSmartPointer<vtkActor>::New();
    b.Actor->SetMapper(mapper);
    b.GPUBytes = [glyphs, data]() { return PolyDataGPUBytes(glyphs->GetOutput(), true); };
    b.SetGamma = [source](double g) { source->SetThetaRoundness(std::pow(0.8, g)); };
    return b;
  };
  r["glyph3dmapper"] = [](vtkImageData* data)
  {
    // Per point: orientation (quaternion of the eigenvector frame) and
    // scale (eigenvalues), from SplineViz's eigen-decomposition.
    const vtkIdType n = data->GetNumberOfPoints();
    vtkDataArray* tensors = data->GetPointData()->GetTensors();
    auto orientation = vtkSmartPointer<vtkFloatArray>::New();
    orientation->SetName("Orientation");
    orientation->SetNumberOfComponents(4);
    orientation->SetNumberOfTuples(n);
    auto scale = vtkSmartPointer<vtkFloatArray>::New();
    scale->SetName("Scale");
    scale->SetNumberOfComponents(3);
    scale->SetNumberOfTuples(n);
    vtkSMPTools::For(0, n,
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType i = begin; i < end; ++i)
        {
          double t[6], w[3], v[3][3], m[3][3], q[4];
          TM::ReadSymmetric(tensors, i, TM::FULL_9, t);
          TM::EigenDecomposition(t, w, v);
          for (int r = 0; r < 3; ++r)
          {
            for (int c = 0; c < 3; ++c)
            {
              m[r][c] = v[c][r]; // columns: e1, e2, e3
            }
          }
          vtkMath::Matrix3x3ToQuaternion(m, q);
          for (int c = 0; c < 4; ++c)
          {
            orientation->SetTypedComponent(i, c, static_cast<float>(q[c]));
          }
          for (int c = 0; c < 3; ++c)
          {
            scale->SetTypedComponent(i, c, static_cast<float>(std::max(w[c], 0.05 * w[0])));
          }
        }
      });
    auto points = vtkSmartPointer<vtkImageData>::New();
    points->ShallowCopy(data);
    points->GetPointData()->AddArray(orientation);
    points->GetPointData()->AddArray(scale);
    auto source = MakeSource(0.3);
    // symmetry axis along e1 (x) as for linear tensors
    source->SetXAxisOfSymmetry();
    auto mapper = vtkSmartPointer<vtkGlyph3DMapper>::New();
    mapper->SetInputData(points);
    mapper->SetSourceConnection(source->GetOutputPort());
    mapper->SetOrientationModeToQuaternion();
    mapper->SetOrientationArray("Orientation");
    mapper->SetScaleModeToScaleByVectorComponents();
    mapper->SetScaleArray("Scale");
    mapper->SetScaleFactor(GlyphScale);
    mapper->ScalarVisibilityOff();
    Built b;
    b.Actor = vtkSmartPointer<vtkActor>::New();
    b.Actor->SetMapper(mapper);
    // Instanced: the source once, and per instance a 4x4 transform, a 3x3
    // normal matrix (floats) and an RGBA color (vtkOpenGLGlyph3DHelper).
    b.GPUBytes = [source, n]() {
      return PolyDataGPUBytes(source->GetOutput(), false) + static_cast<double>(n) * (64 + 36 + 4);
    };
    b.SetGamma = [source](double g) { source->SetThetaRoundness(std::pow(0.8, g)); };
    b.Note = "one shape for all glyphs";
    return b;
  };
  return r;
}

struct Result
{
  double FirstFrame = 0.0;
  double MedianFrame = 0.0;
  double MedianFrameCPU = 0.0; // process CPU time (both cores), less disturbed by other jobs
  double GammaChange = 0.0;
  int UploadsBeforeGamma = -1; // upload counts around the gamma changes (-1: unknown)
  int UploadsAfterGamma = -1;
  double BytesPerGlyph = 0.0;
  int Frames = 0;
  bool Skipped = false;
  std::string Note;
};

Result Run(const Factory& factory, vtkImageData* data, vtkRenderWindow* window, int frames,
  double maxSeconds)
{
  const int n = data->GetDimensions()[0];
  vtkSmartPointer<vtkRenderer> renderer = splineviz_benchmark::AddWarmRenderer(window);

  Result r;
  const double start = Now();
  Built built = factory(data);
  renderer->AddActor(built.Actor);
  vtkCamera* camera = renderer->GetActiveCamera();
  const double c = 0.5 * (n - 1);
  camera->SetFocalPoint(c, c, c);
  const double distance = 2.2 * n;
  camera->SetPosition(c + 0.35 * distance, c - 0.8 * distance, c + 0.5 * distance);
  camera->SetViewUp(0, 0, 1);
  camera->SetViewAngle(30);
  camera->SetClippingRange(0.2 * n, 4.0 * n);
  splineviz_benchmark::RenderFrame(window);
  r.FirstFrame = Now() - start;
  r.BytesPerGlyph = built.GPUBytes() / static_cast<double>(data->GetNumberOfPoints());
  r.Note = built.Note;

  splineviz_benchmark::FrameTimes times;
  times.Orbit(window, camera, frames, maxSeconds, 3);
  r.Frames = times.Count();
  r.MedianFrame = times.MedianWall();
  r.MedianFrameCPU = times.MedianCPU();

  // Gamma change to the next finished frame (median of 3 changes).
  std::vector<double> changes;
  r.UploadsBeforeGamma = built.Uploads ? built.Uploads() : -1;
  const double gammas[3] = { 6.0, 1.5, 3.0 };
  for (double g : gammas)
  {
    const double t0 = Now();
    built.SetGamma(g);
    window->Render();
    window->WaitForCompletion();
    changes.push_back(Now() - t0);
  }
  std::sort(changes.begin(), changes.end());
  r.GammaChange = changes[1];
  r.UploadsAfterGamma = built.Uploads ? built.Uploads() : -1;
  renderer->RemoveAllViewProps();
  window->RemoveRenderer(renderer);
  built.Actor->ReleaseGraphicsResources(window);
  return r;
}

std::string LoadAverage()
{
  char buffer[128] = { 0 };
  if (FILE* f = std::fopen("/proc/loadavg", "r"))
  {
    if (!std::fgets(buffer, sizeof(buffer), f))
    {
      buffer[0] = 0;
    }
    std::fclose(f);
  }
  std::string s(buffer);
  if (!s.empty() && s.back() == '\n')
  {
    s.pop_back();
  }
  return s;
}

double AvailableGB()
{
  double gb = 0.0;
  if (FILE* f = std::fopen("/proc/meminfo", "r"))
  {
    char key[64];
    double kb;
    char unit[16];
    while (std::fscanf(f, "%63s %lf %15s", key, &kb, unit) == 3)
    {
      if (std::string(key) == "MemAvailable:")
      {
        gb = kb / 1024.0 / 1024.0;
        break;
      }
    }
    std::fclose(f);
  }
  return gb;
}
}

const char* const Usage =
  "Usage: SplineVizTensorGlyphBenchmark [--glyphs 10k,100k,1m] [--size 800x600,1200x768]\n"
  "    [--renderers superquadric,superquadric-noculling,tensorglyph,glyph3dmapper]\n"
  "    [--frames N] [--seconds S] [--memory GB]\n"
  "superquadric-noculling: the superquadric glyphs with occlusion culling off.\n"
  "Polygonal renderers are skipped when their estimated memory exceeds --memory\n"
  "(default 16 GB).\n";

int main(int argc, char* argv[])
{
  std::vector<std::string> counts = { "100k", "1m" };
  std::vector<std::string> sizes = { "800x600", "1200x768" };
  std::vector<std::string> renderers = { "superquadric", "superquadric-noculling", "tensorglyph",
    "glyph3dmapper" };
  int frames = 24;
  double seconds = 20.0;
  double memoryGB = 16.0;
  splineviz_benchmark::Options options(Usage);
  options.List("--glyphs", counts)
    .Sizes("--size", sizes)
    .List("--renderers", renderers)
    .Int("--frames", frames, 3)
    .Double("--seconds", seconds)
    .Double("--memory", memoryGB);
  const int exitCode = options.Parse(argc, argv);
  if (exitCode >= 0)
  {
    return exitCode;
  }
  const auto factories = Renderers();
  if (!splineviz_benchmark::AllKnown(
        renderers, splineviz_benchmark::Names(factories), "renderer") ||
    !splineviz_benchmark::AllKnown(counts, { "10k", "100k", "1m" }, "glyph count"))
  {
    return 2;
  }
  memoryGB = std::min(memoryGB, AvailableGB() > 0 ? 0.8 * AvailableGB() : memoryGB);

  for (const auto& count : counts)
  {
    const int n = count == "1m" ? 100 : (count == "10k" ? 22 : 47);
    auto data = MakeTensorVolume(n);
    const double glyphs = static_cast<double>(data->GetNumberOfPoints());
    std::printf("\n== %s glyphs (%d^3 tensor volume, 9 components, float)\n", count.c_str(), n);
    for (const auto& size : sizes)
    {
      int w = 800, h = 600;
      splineviz_benchmark::ParseSize(size, w, h);
      // one window (and GL context) per size, shared by the renderers in turn
      vtkNew<vtkRenderWindow> window;
      window->SetOffScreenRendering(1);
      window->SetSize(w, h);
      window->SetMultiSamples(0);
      std::printf("-- %dx%d (load average before: %s)\n", w, h, LoadAverage().c_str());
      std::printf("  %-22s %14s %12s %16s %10s %16s %7s\n", "renderer", "first frame s",
        "GPU B/glyph", "median frame ms", "(CPU ms)", "gamma change ms", "frames");
      std::map<std::string, Result> results;
      for (const auto& name : renderers)
      {
        // vtkTensorGlyph output (points, normals, colors, strips; CPU copy
        // plus GPU copy on llvmpipe) ~ 45 KB per glyph.
        if (name == "tensorglyph" && glyphs * 45e3 / 1e9 > memoryGB)
        {
          std::printf("  %-14s skipped: needs ~%.0f GB of memory (limit %.0f GB)\n", name.c_str(),
            glyphs * 45e3 / 1e9, memoryGB);
          Result skipped;
          skipped.Skipped = true;
          results[name] = skipped;
          continue;
        }
        const Result r = Run(factories.at(name), data, window, frames, seconds);
        results[name] = r;
        std::printf("  %-22s %14.3f %12.1f %16.1f %10.1f %16.1f %7d %s\n", name.c_str(),
          r.FirstFrame, r.BytesPerGlyph, 1000.0 * r.MedianFrame, 1000.0 * r.MedianFrameCPU,
          1000.0 * r.GammaChange, r.Frames, r.Note.c_str());
        if (r.UploadsBeforeGamma >= 0)
        {
          std::printf("  %-22s uploads before the 3 gamma changes %d, after %d (%s)\n", "",
            r.UploadsBeforeGamma, r.UploadsAfterGamma,
            r.UploadsAfterGamma == r.UploadsBeforeGamma ? "uniforms only" : "RE-UPLOADED");
        }
        std::fflush(stdout);
      }
      std::printf("  (load average after: %s)\n", LoadAverage().c_str());
      if (results.count("superquadric"))
      {
        const Result& s = results["superquadric"];
        if (results.count("superquadric-noculling"))
        {
          const Result& o = results["superquadric-noculling"];
          std::printf("  culling on vs off: median frame %.2fx shorter (CPU time %.2fx less), "
                      "first frame ratio %.2f\n",
            o.MedianFrame / s.MedianFrame, o.MedianFrameCPU / s.MedianFrameCPU,
            s.FirstFrame / o.FirstFrame);
        }
        for (const char* other : { "tensorglyph", "glyph3dmapper" })
        {
          if (!results.count(other) || results[other].Skipped)
            continue;
          const Result& o = results[other];
          std::printf("  superquadric vs %s: first frame %.1fx shorter, GPU memory %.1fx "
                      "smaller, frame time ratio %.2f (<1: faster), gamma change %.1fx faster\n",
            other, o.FirstFrame / s.FirstFrame, o.BytesPerGlyph / s.BytesPerGlyph,
            s.MedianFrame / o.MedianFrame, o.GammaChange / s.GammaChange);
        }
      }
    }
  }
  return 0;
}
