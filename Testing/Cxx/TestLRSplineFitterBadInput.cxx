// SPDX-License-Identifier: BSD-3-Clause
// vtkLRSplineFitter refuses bad input and settings with an error that names
// the problem, a failed update and an empty output, without crashing,
// hanging or allocating: empty data, a missing array, NaN values and
// coordinates, coplanar, collinear and coincident points, Tolerance <= 0 or
// NaN, degrees outside 1..5, refinement levels outside 0..30, and limits
// whose spline would not fit in memory (refused at once). Control: the same
// data and settings, corrected, fit.
#include "vtkLRSplineFitter.h"

#include "LRSplineFitTestImages.h"
#include "SplineVizTestUtilities.h"

#include "vtkCallbackCommand.h"
#include "vtkDoubleArray.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <chrono>
#include <cmath>
#include <functional>
#include <iostream>
#include <limits>
#include <random>

namespace
{
using FitRun = fittest::FitRunT<vtkLRSplineFitter>;

// n random points in the unit cube (or squashed: z = 0, or y = z = 0), f = x + y.
vtkSmartPointer<vtkPolyData> Cloud(int n, int flat = 0)
{
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> uni(0, 1);
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  vtkNew<vtkDoubleArray> f;
  f->SetName("f");
  for (int i = 0; i < n; ++i)
  {
    double x[3] = { uni(rng), uni(rng), uni(rng) };
    if (flat >= 1)
    {
      x[2] = 0.25;
    }
    if (flat >= 2)
    {
      x[1] = 0.5;
    }
    if (flat >= 3)
    {
      x[0] = 0.5;
    }
    points->InsertNextPoint(x);
    f->InsertNextValue(x[0] + x[1]);
  }
  pd->SetPoints(points);
  pd->GetPointData()->SetScalars(f);
  return pd;
}

void Expect(SplineVizTestStatus& status, const std::string& what, vtkDataObject* input,
  const std::string& message, const std::function<void(vtkLRSplineFitter*)>& set = nullptr)
{
  FitRun run;
  run.Fitter->SetTolerance(0.01);
  if (set)
  {
    set(run.Fitter);
  }
  const auto t0 = std::chrono::steady_clock::now();
  const bool ok = run.Run(input);
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const std::string error = run.Error();
  // the fitter's message (the observer also holds the executive's)
  const std::size_t at = error.find("vtkLRSplineFitter (");
  const std::size_t from = at == std::string::npos ? 0 : error.find("): ", at) + 3;
  std::cout << what << ": " << (ok ? "accepted" : error.substr(from, error.find('\n', from) - from))
            << " (" << seconds << " s)" << std::endl;
  SV_CHECK_MSG(status, !ok, what << ": accepted");
  SV_CHECK_MSG(status, error.find(message) != std::string::npos,
    what << ": the error does not say \"" << message << "\": " << error);
  SV_CHECK_MSG(status, run.Output()->GetNumberOfBlocks() == 0, what << ": output not empty");
  SV_CHECK_MSG(status, seconds < 2.0, what << ": took " << seconds << " s");
}
}

int TestLRSplineFitterBadInput(int, char*[])
{
  SplineVizTestStatus status;
  // Control: good data fits.
  {
    FitRun run;
    SV_CHECK_MSG(status, run.Run(Cloud(500)), run.Error());
    SV_CHECK(status, run.Output()->GetNumberOfBlocks() == 1 && run.Fitter->GetToleranceMet());
  }
  vtkNew<vtkPolyData> empty;
  Expect(status, "empty data", empty, "no data to fit");
  vtkNew<vtkMultiBlockDataSet> noLeaves;
  Expect(status, "composite without leaves", noLeaves, "no data to fit");
  Expect(status, "missing array", Cloud(100), "no array to fit",
    [](vtkLRSplineFitter* f)
    { f->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "nothing"); });
  {
    auto nan = Cloud(100);
    nan->GetPointData()->GetScalars()->SetTuple1(17, std::numeric_limits<double>::quiet_NaN());
    Expect(status, "a NaN value", nan, "NaN");
    auto inf = Cloud(100);
    inf->GetPoints()->SetPoint(3, 0.5, std::numeric_limits<double>::infinity(), 0.5);
    Expect(status, "an infinite coordinate", inf, "NaN or infinite");
  }
  Expect(status, "coplanar points", Cloud(200, 1), "plane or line");
  Expect(status, "collinear points", Cloud(200, 2), "plane or line");
  Expect(status, "coincident points", Cloud(200, 3), "lie on a point");
  auto good = Cloud(200);
  Expect(status, "tolerance 0", good, "Tolerance must be positive",
    [](vtkLRSplineFitter* f) { f->SetTolerance(0.0); });
  Expect(status, "tolerance -1", good, "Tolerance must be positive",
    [](vtkLRSplineFitter* f) { f->SetTolerance(-1.0); });
  Expect(status, "tolerance NaN", good, "Tolerance must be positive",
    [](vtkLRSplineFitter* f) { f->SetTolerance(std::numeric_limits<double>::quiet_NaN()); });
  Expect(status, "smoothing NaN", good, "Smoothing must be finite",
    [](vtkLRSplineFitter* f) { f->SetSmoothing(std::numeric_limits<double>::quiet_NaN()); });
  Expect(status, "degree 0", good, "Degree must be 1 to 5",
    [](vtkLRSplineFitter* f) { f->SetDegree(2, 0, 2); });
  Expect(status, "degree 6", good, "Degree must be 1 to 5",
    [](vtkLRSplineFitter* f) { f->SetDegree(6, 2, 2); });
  Expect(status, "31 levels", good, "MaximumRefinementLevels must be 0 to 30",
    [](vtkLRSplineFitter* f) { f->SetMaximumRefinementLevels(31); });
  Expect(status, "-1 levels", good, "MaximumRefinementLevels must be 0 to 30",
    [](vtkLRSplineFitter* f) { f->SetMaximumRefinementLevels(-1); });
  Expect(status, "10^15 elements of 30 levels", good, "refused before allocating",
    [](vtkLRSplineFitter* f)
    {
      f->SetMaximumRefinementLevels(30);
      f->SetMaximumNumberOfElements(1000000000000000LL);
    });
  // The level count alone bounds the elements: 30 levels with the default
  // element limit is allowed (and fits this easy field at once).
  {
    FitRun run;
    run.Fitter->SetMaximumRefinementLevels(30);
    SV_CHECK_MSG(status, run.Run(good), run.Error());
  }
  {
    // Progress, and an abort from a progress observer: the loop stops after
    // the first fit (negative control: without the abort it refines on).
    for (int aborting = 1; aborting >= 0; --aborting)
    {
      FitRun run;
      run.Fitter->SetTolerance(1e-6);
      run.Fitter->SetMaximumRefinementLevels(2);
      vtkNew<vtkCallbackCommand> progress;
      int events = 0;
      progress->SetClientData(&events);
      progress->SetCallback(
        [](vtkObject* caller, unsigned long, void* clientData, void*)
        {
          ++*static_cast<int*>(clientData);
          vtkAlgorithm::SafeDownCast(caller)->SetAbortExecute(1);
        });
      vtkNew<vtkCallbackCommand> count;
      count->SetClientData(&events);
      count->SetCallback([](vtkObject*, unsigned long, void* clientData, void*)
        { ++*static_cast<int*>(clientData); });
      run.Fitter->AddObserver(vtkCommand::ProgressEvent, aborting ? progress : count);
      auto data = Cloud(3000);
      // a field the initial spline cannot meet
      for (vtkIdType i = 0; i < 3000; ++i)
      {
        double x[3];
        data->GetPoint(i, x);
        data->GetPointData()->GetScalars()->SetTuple1(i, std::sin(9 * x[0]) * std::cos(7 * x[1]));
      }
      run.Run(data);
      std::cout << (aborting ? "abort" : "no abort") << ": " << events << " progress events, "
                << run.Fitter->GetNumberOfIterations() << " fits" << std::endl;
      SV_CHECK(status, events >= 1);
      SV_CHECK_MSG(status, (run.Fitter->GetNumberOfIterations() == 1) == (aborting == 1),
        run.Fitter->GetNumberOfIterations() << " fits");
    }
  }
  return status.Result();
}
