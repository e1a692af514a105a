// SPDX-License-Identifier: BSD-3-Clause
// Benchmark of vtkLRSplineStreamTracer (Fuchs et al. §5; the paper's
// fluidized-bed setting: 250 seeds, up to 2,000 steps) against
// vtkStreamTracer on the same field resampled to a 128^3 vtkImageData, in the
// same run.
//
// The field: a generated quadratic LR volume of >= 30,000 elements (several
// refinement levels, golden-section knots) holding a swirling flow, written
// as .lr and read with vtkLRSplineReader. For each method: wall time on one
// core (vtkSMPTools Sequential) and on all cores (STDThread), points,
// evaluations per second, and the accuracy with the paper's error metric
// (Eq. 7) against a reference traced on the exact spline with RKF5 and a
// ten times smaller step.
//
//   BenchmarkLRSplineStreamTracer [numberOfSeeds]
#include "BenchmarkCommon.h"
#include "vtkLRSplineBuilder.h"
#include "vtkLRSplineReader.h"
#include "vtkLRSplineResampleToImage.h"
#include "vtkLRSplineStreamTracer.h"

#include "LRSplineBenchmarkVolumes.h"

#include "vtkImageData.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkStreamTracer.h"

#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <random>
#include <string>

namespace
{
using Clock = std::chrono::steady_clock;
double Seconds(Clock::time_point t0)
{
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

struct Result
{
  double Setup = 0.0; // building the evaluator (Bezier blocks, k-d forest), once per field
  double Wall[2] = { 0, 0 };
  vtkIdType Lines = 0, Points = 0, Evaluations = 0;
  double Error = 0.0;
};

void Print(const char* name, const Result& r)
{
  char evals[32] = "-", setup[32] = "-";
  if (r.Evaluations > 0)
  {
    std::snprintf(evals, sizeof(evals), "%.3e", r.Evaluations / r.Wall[1]);
  }
  if (r.Setup > 0)
  {
    std::snprintf(setup, sizeof(setup), "%.3f", r.Setup);
  }
  std::printf("  %-46s %8s %9.3f %9.3f %6lld %8lld %12s %11.3e\n", name, setup, r.Wall[0],
    r.Wall[1], static_cast<long long>(r.Lines), static_cast<long long>(r.Points), evals, r.Error);
}
}

const char* const Usage =
  "Usage: BenchmarkLRSplineStreamTracer [numberOfSeeds, default 250]\n"
  "vtkLRSplineStreamTracer's integrators against vtkStreamTracer on the field\n"
  "resampled to 128^3, with Fuchs et al.'s error metric.\n";

int main(int argc, char* argv[])
{
  if (splineviz_benchmark::HelpRequested(argc, argv, Usage))
  {
    return 0;
  }
  const int numSeeds = argc > 1 ? std::atoi(argv[1]) : 250;
  if (numSeeds <= 0)
  {
    std::fprintf(stderr, "the number of seeds must be a positive integer\n%s", Usage);
    return 2;
  }
  const double step = 0.002; // arc length per step
  const vtkIdType maxSteps = 2000;
  const double tolerance = 1e-6; // adaptive methods
  vtkSMPTools::SetBackend("STDThread");
  std::cout << "LR-spline stream tracer benchmark: " << numSeeds << " seeds, up to " << maxSteps
            << " steps; " << vtkSMPTools::GetEstimatedNumberOfThreads() << " threads\n";

  vtkLRSplineBuilder builder;
  if (!lrbench::MakeVolume(builder, 30000, false))
  {
    return 1;
  }
  const lrbench::TemporaryLRFile file(builder, "LRSplineBenchmark-tracer.lr");
  if (!file.IsOk())
  {
    std::cerr << "cannot write " << file.GetPath() << "\n";
    return 1;
  }
  const std::string& path = file.GetPath();
  vtkNew<vtkLRSplineReader> reader;
  reader->SetFileName(path.c_str());
  reader->SetOutputFieldName("velocity");
  auto t0 = Clock::now();
  reader->Update();
  std::cout << "read the field in " << Seconds(t0) << " s\n";
  vtkMultiBlockDataSet* field = reader->GetOutput();

  // Seeds: random, in the swirl's core region.
  vtkNew<vtkPolyData> seeds;
  {
    vtkNew<vtkPoints> pts;
    pts->SetDataTypeToDouble();
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> U(0.0, 1.0);
    for (int i = 0; i < numSeeds; ++i)
    {
      pts->InsertNextPoint(0.15 + 0.7 * U(rng), 0.15 + 0.7 * U(rng), 0.05 + 0.4 * U(rng));
    }
    seeds->SetPoints(pts);
  }

  auto runOurs = [&](
                   int integrator, int mode, double h, int precision, double tol, vtkPolyData* keep)
  {
    Result r;
    for (int b = 0; b < 2; ++b)
    {
      vtkSMPTools::SetBackend(b == 0 ? "Sequential" : "STDThread");
      vtkNew<vtkLRSplineStreamTracer> tracer;
      tracer->SetInputData(field);
      tracer->SetSourceData(seeds);
      tracer->SetIntegratorType(integrator);
      tracer->SetStepMode(mode);
      tracer->SetIntegrationStep(h);
      tracer->SetMaximumError(tol);
      tracer->SetMaximumIntegrationStep(0.1);
      tracer->SetMinimumIntegrationStep(1e-6);
      tracer->SetPrecision(precision);
      tracer->SetIntegrationDirection(vtkLRSplineStreamTracer::FORWARD);
      tracer->SetMaximumNumberOfSteps(maxSteps);
      // The first execution also builds the evaluator (cached afterwards).
      auto ts = Clock::now();
      tracer->Update();
      const double first = Seconds(ts);
      tracer->Modified();
      ts = Clock::now();
      tracer->Update();
      r.Wall[b] = Seconds(ts);
      r.Setup = std::max(r.Setup, first - r.Wall[b]);
      r.Lines = tracer->GetOutput()->GetNumberOfLines();
      r.Points = tracer->GetOutput()->GetNumberOfPoints();
      r.Evaluations = tracer->GetNumberOfEvaluations();
      if (keep && b == 1)
      {
        keep->DeepCopy(tracer->GetOutput());
      }
    }
    vtkSMPTools::SetBackend("STDThread");
    return r;
  };

  // Reference: RKF5 on the exact spline with a ten times smaller step.
  vtkNew<vtkPolyData> reference;
  {
    vtkNew<vtkLRSplineStreamTracer> tracer;
    tracer->SetInputData(field);
    tracer->SetSourceData(seeds);
    tracer->SetIntegratorType(vtkLRSplineStreamTracer::RKF5);
    tracer->SetStepMode(vtkLRSplineStreamTracer::FIXED_LENGTH);
    tracer->SetIntegrationStep(step / 10);
    tracer->SetIntegrationDirection(vtkLRSplineStreamTracer::FORWARD);
    tracer->SetMaximumNumberOfSteps(20 * maxSteps);
    tracer->SetMaximumPropagation(step * maxSteps);
    tracer->Update();
    reference->DeepCopy(tracer->GetOutput());
  }

  std::printf(
    "\n  method                                          setup[s] 1 core[s] %d cores[s]  lines"
    "   points evals/s(all)  Eq.7 error\n",
    vtkSMPTools::GetEstimatedNumberOfThreads());
  vtkNew<vtkPolyData> lines;
  const int D = vtkLRSplineStreamTracer::DOUBLE_PRECISION;
  Result r = runOurs(vtkLRSplineStreamTracer::RUNGE_KUTTA4, vtkLRSplineStreamTracer::FIXED_LENGTH,
    step, D, tolerance, lines);
  r.Error = vtkLRSplineStreamTracer::ComputeErrorMetric(lines, reference, "velocity");
  Print("SplineViz RK4, fixed length 0.002, double", r);
  const double oursRK4 = r.Wall[1];
  r = runOurs(vtkLRSplineStreamTracer::RUNGE_KUTTA4, vtkLRSplineStreamTracer::FIXED_LENGTH, step,
    vtkLRSplineStreamTracer::MIXED_PRECISION, tolerance, lines);
  r.Error = vtkLRSplineStreamTracer::ComputeErrorMetric(lines, reference, "velocity");
  Print("SplineViz RK4, fixed length 0.002, mixed", r);
  r = runOurs(vtkLRSplineStreamTracer::RUNGE_KUTTA4, vtkLRSplineStreamTracer::LR_HEURISTIC, 1.0, D,
    tolerance, lines);
  r.Error = vtkLRSplineStreamTracer::ComputeErrorMetric(lines, reference, "velocity");
  Print("SplineViz RK4, LR heuristic (base 1)", r);
  r = runOurs(
    vtkLRSplineStreamTracer::RKF45, vtkLRSplineStreamTracer::ADAPTIVE, 0.01, D, tolerance, lines);
  r.Error = vtkLRSplineStreamTracer::ComputeErrorMetric(lines, reference, "velocity");
  Print("SplineViz RKF45, adaptive, tolerance 1e-6", r);
  const double oursRKF45 = r.Wall[1];

  // The VTK way: resample to a 128^3 image, then vtkStreamTracer.
  vtkNew<vtkLRSplineResampleToImage> resample;
  resample->SetInputData(field);
  resample->SetSamplingDimensions(128, 128, 128);
  t0 = Clock::now();
  resample->Update();
  const double resampleSeconds = Seconds(t0);
  vtkImageData* image = resample->GetOutput();
  image->GetPointData()->SetActiveVectors("velocity");
  auto runVTK = [&](int integrator, vtkPolyData* keep)
  {
    Result r2{};
    for (int b = 0; b < 2; ++b)
    {
      vtkSMPTools::SetBackend(b == 0 ? "Sequential" : "STDThread");
      vtkNew<vtkStreamTracer> tracer;
      tracer->SetInputData(image);
      tracer->SetSourceData(seeds);
      tracer->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "velocity");
      tracer->SetIntegratorType(integrator);
      tracer->SetIntegrationStepUnit(vtkStreamTracer::LENGTH_UNIT);
      tracer->SetInitialIntegrationStep(integrator == vtkStreamTracer::RUNGE_KUTTA45 ? 0.01 : step);
      tracer->SetMinimumIntegrationStep(1e-6);
      tracer->SetMaximumIntegrationStep(0.1);
      tracer->SetMaximumError(tolerance);
      tracer->SetMaximumNumberOfSteps(maxSteps);
      tracer->SetMaximumPropagation(1e9);
      tracer->SetIntegrationDirection(vtkStreamTracer::FORWARD);
      tracer->SetComputeVorticity(false);
      const auto ts = Clock::now();
      tracer->Update();
      r2.Wall[b] = Seconds(ts);
      r2.Lines = tracer->GetOutput()->GetNumberOfLines();
      r2.Points = tracer->GetOutput()->GetNumberOfPoints();
      if (keep && b == 1)
      {
        keep->DeepCopy(tracer->GetOutput());
      }
    }
    vtkSMPTools::SetBackend("STDThread");
    return r2;
  };
  r = runVTK(vtkStreamTracer::RUNGE_KUTTA4, lines);
  r.Error = vtkLRSplineStreamTracer::ComputeErrorMetric(lines, reference, "velocity");
  Print("vtkStreamTracer RK4 on 128^3 image, length 0.002", r);
  const double vtkRK4 = r.Wall[1];
  r = runVTK(vtkStreamTracer::RUNGE_KUTTA45, lines);
  r.Error = vtkLRSplineStreamTracer::ComputeErrorMetric(lines, reference, "velocity");
  Print("vtkStreamTracer RK45 on 128^3 image, error 1e-6", r);
  const double vtkRK45 = r.Wall[1];
  std::printf("\n  (setup: Bezier blocks and k-d forest from the reader's grid, once per field "
              "and cached;\n   resampling the spline to the 128^3 image took %.3f s on %d threads, "
              "not included above)\n",
    resampleSeconds, vtkSMPTools::GetEstimatedNumberOfThreads());
  std::printf("  ratio vtkStreamTracer / SplineViz wall time (all cores): RK4 %.2f, RK45 %.2f\n",
    vtkRK4 / oursRK4, vtkRK45 / oursRKF45);
  return 0;
}
