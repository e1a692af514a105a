// SPDX-License-Identifier: BSD-3-Clause
// Benchmark of vtkTensorLineTracer: whole-brain-style seeding on a 128^3
// synthetic tensor field, against VTK's vtkHyperStreamline on a subset of
// the seeds, in the same run.
//
// The field: a twisting helical bundle like Teem's `tend helix`
// (TensorLineTestFields.h) filling a 128^3 image of unit spacing (major
// radius 40, two turns, bundle radius 14, DTI-like eigenvalues, isotropic
// outside). Seeds: every voxel with FA >= 0.5 (SEEDS_FROM_VOXELS, a few
// hundred thousand). Tracking: step 0.5 voxel, FA stop 0.2, 45 degrees,
// at most 20 voxels per direction, float output. For each configuration: wall time on one
// core (vtkSMPTools Sequential) and on all cores (STDThread, selected here
// explicitly), lines per second, points, evaluations per second.
//
// vtkHyperStreamline traces one seed per execution (RK2, both directions,
// no FA stop): it runs on a subset of the seeds, and so does
// vtkTensorLineTracer with the same step, length and integrator (RK2, FA
// stop 0) for the comparison of lines per second; the largest distance
// between the two sets of lines is printed too.
//
//   BenchmarkTensorLineTracer [hyperstreamline subset size, default 2000] [profile]
//
// "profile": only the first configuration on one core (for perf). Environment:
// SPLINEVIZ_BENCHMARK_SUBSET_ONLY=1 skips the whole-volume table,
// SPLINEVIZ_BENCHMARK_DEBUG=1 prints where vtkHyperStreamline's lines and
// ours part by more than half a voxel.
#include "BenchmarkCommon.h"
#include "vtkTensorAnalysisFilter.h"
#include "vtkTensorLineTracer.h"

#include "TensorLineTestFields.h"
#include "vtkSplineVizTensorMath.h"

#include "vtkHyperStreamline.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <random>
#include <string>
#include <vector>

using namespace TensorLineTest;

namespace
{
using Clock = std::chrono::steady_clock;
double Seconds(Clock::time_point t0)
{
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

void UseCores(int cores)
{
  if (cores == 1)
  {
    vtkSMPTools::SetBackend("Sequential");
  }
  else
  {
    vtkSMPTools::SetBackend("STDThread");
    vtkSMPTools::Initialize(cores);
  }
}

struct Run
{
  double Wall = 0.0, CPU = 0.0;
  vtkIdType Seeds = 0, Lines = 0, Points = 0, Evaluations = 0;
};

Run TraceOnce(vtkImageData* field, vtkPolyData* seeds, int cores,
  const std::function<void(vtkTensorLineTracer*)>& configure,
  vtkSmartPointer<vtkPolyData>* keep = nullptr)
{
  UseCores(cores);
  vtkNew<vtkTensorLineTracer> tracer;
  tracer->SetInputData(field);
  if (seeds)
  {
    tracer->SetSourceData(seeds);
  }
  tracer->SetIntegrationStepUnit(vtkTensorLineTracer::LENGTH_UNIT);
  tracer->SetIntegrationStep(0.5);
  tracer->SetStoppingFAThreshold(0.2);
  tracer->SetMaximumAngle(45.0);
  tracer->SetMaximumPropagation(20.0);
  tracer->SetOutputPointsPrecision(
    vtkAlgorithm::SINGLE_PRECISION); // float output, as usual for fibers
  configure(tracer);
  const auto t0 = Clock::now();
  const double c0 = splineviz_benchmark::CPUTime();
  tracer->Update();
  Run r;
  r.Wall = Seconds(t0);
  r.CPU = splineviz_benchmark::CPUTime() - c0;
  r.Seeds = tracer->GetNumberOfSeeds();
  r.Lines = tracer->GetOutput()->GetNumberOfLines();
  r.Points = tracer->GetOutput()->GetNumberOfPoints();
  r.Evaluations = tracer->GetNumberOfEvaluations();
  if (keep)
  {
    *keep = vtkSmartPointer<vtkPolyData>::New();
    (*keep)->ShallowCopy(tracer->GetOutput());
  }
  return r;
}

void PrintRow(const char* name, const Run& one, const Run& two)
{
  std::printf(
    "| %-36s | %7lld | %9lld | %6.1f s (%6.1f) | %6.1f s (%6.1f) | %6.0f | %6.0f | %7.2e |\n", name,
    static_cast<long long>(two.Lines), static_cast<long long>(two.Points), one.Wall, one.CPU,
    two.Wall, two.CPU, one.Lines / one.Wall, two.Lines / two.Wall, two.Evaluations / two.Wall);
}
}

const char* const Usage =
  "Usage: BenchmarkTensorLineTracer [hyperstreamline subset size, default 2000] [profile]\n"
  "Whole-volume seeding on a 128^3 helix tensor field (1 and 2 cores) and\n"
  "vtkHyperStreamline on a subset of the seeds. Environment:\n"
  "SPLINEVIZ_BENCHMARK_SUBSET_ONLY=1, SPLINEVIZ_BENCHMARK_DEBUG=1.\n";

int main(int argc, char* argv[])
{
  if (splineviz_benchmark::HelpRequested(argc, argv, Usage))
  {
    return 0;
  }
  const int subset = argc > 1 ? std::atoi(argv[1]) : 2000;
  if (subset <= 0)
  {
    std::fprintf(stderr, "the subset size must be a positive integer\n%s", Usage);
    return 2;
  }
  const int cores = std::max(2, vtkSMPTools::GetEstimatedNumberOfThreads());

  // The field.
  UseCores(cores);
  TendHelix helix;
  helix.R = 40.0;
  helix.S = 64.0;
  helix.r = 14.0;
  helix.Fuzz = 2.0;
  const int dims[3] = { 128, 128, 128 };
  const double origin[3] = { -63.5, -63.5, -63.5 }, spacing[3] = { 1, 1, 1 };
  auto t0 = Clock::now();
  auto field =
    MakeImage(dims, origin, spacing, [&](const double x[3], double t[6]) { helix.Tensor(x, t); });
  std::printf("field: 128^3 tend-helix image made in %.1f s (%d cores)\n", Seconds(t0), cores);

  // One seed: the per-execution setup (point tensors, eigen-decompositions).
  vtkNew<vtkPolyData> one;
  {
    vtkNew<vtkPoints> p;
    const Vec3 c = helix.Core(0.0);
    p->InsertNextPoint(c.data());
    one->SetPoints(p);
  }
  const auto noop = [](vtkTensorLineTracer*) {};
  const Run setup1 = TraceOnce(field, one, 1, noop);
  const Run setup2 = TraceOnce(field, one, cores, noop);
  std::printf("setup (a run with one seed: the point tensors read and checked): %.2f s on 1 "
              "core, %.2f s on %d cores\n\n",
    setup1.Wall, setup2.Wall, cores);

  std::printf("Whole-volume seeding (every voxel with FA >= 0.5), step 0.5, FA stop 0.2, 45 deg, "
              "<= 20 per direction:\n\n");
  std::printf("| %-36s | %7s | %9s | %17s | %17s | %6s | %6s | %7s |\n", "configuration", "lines",
    "points", "1 core: wall (CPU)", "2 cores: wall (CPU)", "lines/s 1", "lines/s 2", "evals/s 2");
  std::printf("|---|---|---|---|---|---|---|---|\n");
  struct Config
  {
    const char* Name;
    std::function<void(vtkTensorLineTracer*)> Setup;
  };
  const Config configs[] = {
    { "RK4, linear interpolation",
      [](vtkTensorLineTracer* t)
      {
        t->SetSeedMode(vtkTensorLineTracer::SEEDS_FROM_VOXELS);
        t->SetSeedFAThreshold(0.5);
      } },
    { "RK2, linear interpolation",
      [](vtkTensorLineTracer* t)
      {
        t->SetSeedMode(vtkTensorLineTracer::SEEDS_FROM_VOXELS);
        t->SetSeedFAThreshold(0.5);
        t->SetIntegratorType(vtkTensorLineTracer::RUNGE_KUTTA2);
      } },
    { "RK4, log-Euclidean interpolation",
      [](vtkTensorLineTracer* t)
      {
        t->SetSeedMode(vtkTensorLineTracer::SEEDS_FROM_VOXELS);
        t->SetSeedFAThreshold(0.5);
        t->SetInterpolation(vtkTensorLineTracer::LOG_EUCLIDEAN_INTERPOLATION);
      } },
    { "RK4, tensorlines (f = cl, g = 0.5)",
      [](vtkTensorLineTracer* t)
      {
        t->SetSeedMode(vtkTensorLineTracer::SEEDS_FROM_VOXELS);
        t->SetSeedFAThreshold(0.5);
        t->UseTensorlinesOn();
      } },
  };
  vtkIdType seedCount = 0;
  if (argc > 2 && std::string(argv[2]) == "profile")
  {
    // one configuration on one core, for a profiler
    const Run r = TraceOnce(field, nullptr, 1, configs[0].Setup);
    std::printf("profile run: %lld lines, %.2f s\n", static_cast<long long>(r.Lines), r.Wall);
    return EXIT_SUCCESS;
  }
  for (const Config& c : configs)
  {
    if (std::getenv("SPLINEVIZ_BENCHMARK_SUBSET_ONLY"))
    {
      break;
    }
    const Run r1 = TraceOnce(field, nullptr, 1, c.Setup);
    const Run r2 = TraceOnce(field, nullptr, cores, c.Setup);
    seedCount = r2.Seeds;
    PrintRow(c.Name, r1, r2);
    std::fflush(stdout);
  }
  std::printf("\n%lld seeds\n\n", static_cast<long long>(seedCount));

  // vtkHyperStreamline on a subset of the seeds (random, reproducible).
  std::vector<Vec3> all;
  {
    UseCores(cores);
    vtkNew<vtkTensorAnalysisFilter> analysis;
    analysis->SetInputData(field);
    analysis->Update();
    vtkDataArray* fa = vtkDataSet::SafeDownCast(analysis->GetOutput())
                         ->GetPointData()
                         ->GetArray("FractionalAnisotropy");
    for (vtkIdType i = 0; i < field->GetNumberOfPoints(); ++i)
    {
      if (fa->GetComponent(i, 0) >= 0.5)
      {
        Vec3 p;
        field->GetPoint(i, p.data());
        all.push_back(p);
      }
    }
  }
  std::mt19937 rng(12345);
  std::shuffle(all.begin(), all.end(), rng);
  all.resize(std::min<std::size_t>(all.size(), subset));
  auto subsetSeeds = MakeSeeds(all);

  const double step = 0.5, length = 20.0;
  const int sides = 3;
  UseCores(1);
  t0 = Clock::now();
  double c0 = splineviz_benchmark::CPUTime();
  std::vector<std::vector<std::vector<Vec3>>> vtkLines;
  vtkIdType vtkCentres = 0;
  for (const Vec3& s : all)
  {
    vtkNew<vtkHyperStreamline> hs;
    hs->SetInputData(field);
    hs->SetStartPosition(s[0], s[1], s[2]);
    hs->SetIntegrationEigenvectorToMajor();
    hs->SetIntegrationDirectionToIntegrateBothDirections();
    hs->SetIntegrationStepLength(step / std::sqrt(3.0)); // of the cell diagonal
    hs->SetMaximumPropagationDistance(length);
    hs->SetTerminalEigenvalue(0.0);
    hs->SetStepLength(step / field->GetLength()); // tube rings every step
    hs->SetNumberOfSides(sides);
    hs->Update();
    vtkLines.push_back(CentreLines(hs->GetOutput(), sides));
    vtkCentres += hs->GetOutput()->GetNumberOfPoints() / sides;
  }
  const double vtkWall = Seconds(t0), vtkCPU = splineviz_benchmark::CPUTime() - c0;

  // The same work: RK2, step and length as above, no FA or angle stop.
  const auto same = [](vtkTensorLineTracer* t)
  {
    t->SetIntegratorType(vtkTensorLineTracer::RUNGE_KUTTA2);
    t->SetStoppingFAThreshold(0.0);
    t->SetMaximumAngle(90.0);
  };
  const auto sameWhole = [&](vtkTensorLineTracer* t)
  {
    same(t);
    t->SetSeedMode(vtkTensorLineTracer::SEEDS_FROM_VOXELS);
    t->SetSeedFAThreshold(0.5);
  };
  vtkSmartPointer<vtkPolyData> ours;
  const Run s1 = TraceOnce(field, subsetSeeds, 1, same, &ours);
  const Run s2 = TraceOnce(field, subsetSeeds, cores, same);
  const Run w1 = TraceOnce(field, nullptr, 1, sameWhole);
  const Run w2 = TraceOnce(field, nullptr, cores, sameWhole);

  // Agreement inside the bundle (outside it the tensors are isotropic and
  // the principal direction is arbitrary: there the lines of any two
  // implementations part) and a voxel away from the image's faces.
  const auto lines = GetLines(ours);
  double worst = 0.0;
  vtkIdType compared = 0;
  for (std::size_t k = 0; k < lines.size() && k < vtkLines.size(); ++k)
  {
    for (const auto& streamer : vtkLines[k])
    {
      double arc = 0.0;
      for (std::size_t i = 0; i < streamer.size(); ++i)
      {
        if (i > 0)
        {
          arc += Norm({ streamer[i][0] - streamer[i - 1][0], streamer[i][1] - streamer[i - 1][1],
            streamer[i][2] - streamer[i - 1][2] });
        }
        double t[6], l[3], e[3][3];
        helix.Tensor(streamer[i].data(), t);
        vtkSplineVizTensorMath::EigenDecomposition(t, l, e);
        bool interior = true; // vtkHyperStreamline goes on a little outside the image
        for (int a = 0; a < 3; ++a)
        {
          interior = interior && std::abs(streamer[i][a]) < 63.5 - 1.0;
        }
        if (vtkSplineVizTensorMath::FractionalAnisotropy(l) < 0.4 || arc >= length - 2 * step ||
          !interior)
        {
          break;
        }
        const double dist = DistanceToPolyline(streamer[i], lines[k].Points);
        if (std::getenv("SPLINEVIZ_BENCHMARK_DEBUG") && dist > 0.5)
        {
          std::printf("line %zu (seed id %d): VTK centre %zu at arc %.2f (%.2f %.2f %.2f) is "
                      "%.2f from ours (%zu points)\n",
            k, lines[k].SeedId, i, arc, streamer[i][0], streamer[i][1], streamer[i][2], dist,
            lines[k].Points.size());
          break;
        }
        worst = std::max(worst, dist);
        ++compared;
      }
    }
  }
  std::printf("vtkHyperStreamline on a random subset of %zu of the seeds; the same work for both "
              "(RK2, step 0.5, <= 20 per direction, no FA or angle stop):\n\n",
    all.size());
  // Ratios of lines per CPU second: the machine is shared, so wall times
  // include waiting for a core; CPU times do not.
  std::printf("| method | seeds | wall (CPU) | lines/s (wall) | lines per CPU s | vs "
              "vtkHyperStreamline (CPU) |\n|---|---|---|---|---|---|\n");
  const double vtkRate = all.size() / vtkCPU;
  const auto row = [&](const char* name, double seedsTraced, double wall, double cpu)
  {
    std::printf("| %s | %.0f | %.2f s (%.2f) | %.0f | %.0f | %.1f x |\n", name, seedsTraced, wall,
      cpu, seedsTraced / wall, seedsTraced / cpu, (seedsTraced / cpu) / vtkRate);
  };
  row("vtkHyperStreamline, 1 core (one execution per seed)", static_cast<double>(all.size()),
    vtkWall, vtkCPU);
  row(
    "vtkTensorLineTracer, 1 core, setup included", static_cast<double>(s1.Seeds), s1.Wall, s1.CPU);
  row(
    "vtkTensorLineTracer, 2 cores, setup included", static_cast<double>(s2.Seeds), s2.Wall, s2.CPU);
  row("vtkTensorLineTracer, 1 core, all seeds", static_cast<double>(w1.Seeds), w1.Wall, w1.CPU);
  row("vtkTensorLineTracer, 2 cores, all seeds", static_cast<double>(w2.Seeds), w2.Wall, w2.CPU);
  std::printf("\nvtkHyperStreamline: %lld centre points; ours on the subset: %lld points. Largest "
              "distance of VTK's centre lines from ours inside the bundle (FA >= 0.4): %.2e voxels "
              "over %lld centres.\n",
    static_cast<long long>(vtkCentres), static_cast<long long>(s1.Points), worst,
    static_cast<long long>(compared));
  std::printf("At vtkHyperStreamline's rate the %lld seeds would take %.0f CPU s (ours: %.1f).\n",
    static_cast<long long>(w1.Seeds), w1.Seeds / vtkRate, w1.CPU);
  return EXIT_SUCCESS;
}
