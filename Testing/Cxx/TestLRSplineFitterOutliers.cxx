// SPDX-License-Identifier: BSD-3-Clause
// vtkLRSplineFitter's RemoveOutliers, checked against a corruption known to
// the test (the spline evaluated with vtkLRSplineField, against the analytic
// field, at the data points and at fresh points):
//  - 20,000 random points of a smooth field with a narrow Gaussian bump (a
//    real feature the detection must keep), 1 % of the values replaced by
//    spikes of 0.1-0.5 of the data range with random sign: every spike is
//    found, at most 0.05 % of the clean points are taken for spikes (the bump
//    is kept: the fit is as local as on clean data), the fit meets the
//    tolerance at the clean points against the clean values, and at 50,000
//    fresh points away from the spikes the spline stays near the field;
//    negative control: without RemoveOutliers the same data makes the spline
//    follow the spikes (error at fresh points near them, elements spent;
//    with Smoothing 0 the spline also swings between them, as
//    TestLRSplineFitterSmoothing shows on other data);
//  - clean data: nothing is left out and the fit is the one without
//    RemoveOutliers (same elements);
//  - NaN values and infinite coordinates are left out and counted (refused
//    without RemoveOutliers: TestLRSplineFitterBadInput);
//  - a vector field fitted by components, with spikes in one component;
//  - output port 2 holds the outliers with their values and deviations, the
//    field data "LRFitOutliers" their number.
#include "vtkLRSplineArrayNames.h"
#include "vtkLRSplineFitter.h"

#include "LRSplineFitTestImages.h"
#include "SplineVizTestUtilities.h"

#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkUnstructuredGrid.h"

#include <chrono>
#include <cmath>
#include <iostream>
#include <limits>
#include <random>
#include <set>

namespace
{
using FitRun = fittest::FitRunT<vtkLRSplineFitter>;
constexpr int NumberOfPoints = 20000;
constexpr double Tolerance = 0.01;

// Random points of the bump field; `spikes` of them (their indices in
// `spiked`) get a spike of 0.1-0.5 of the data range (about 1.9) added.
struct Data
{
  std::vector<double> X, Clean, Values;
  std::set<vtkIdType> Spiked;
};

Data MakeData(int spikes, unsigned seed)
{
  Data data;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uni(0, 1);
  data.X.resize(3 * NumberOfPoints);
  data.Clean.resize(NumberOfPoints);
  for (int i = 0; i < NumberOfPoints; ++i)
  {
    for (int d = 0; d < 3; ++d)
    {
      data.X[3 * i + d] = uni(rng);
    }
    data.Clean[i] = fittest::Bump(&data.X[3 * i]);
  }
  data.Values = data.Clean;
  std::uniform_int_distribution<vtkIdType> pick(0, NumberOfPoints - 1);
  while (static_cast<int>(data.Spiked.size()) < spikes)
  {
    const vtkIdType i = pick(rng);
    if (data.Spiked.insert(i).second)
    {
      const double size = (0.1 + 0.4 * uni(rng)) * 1.9;
      data.Values[i] += uni(rng) < 0.5 ? -size : size;
    }
  }
  return data;
}

// Largest |spline - field| at `n` fresh random points farther than `away`
// from every spiked point (all points when `away` is 0), and the largest
// within `away` of one (`near`, when given).
double FreshError(vtkDataObject* spline, const Data& data, double away, double* near = nullptr)
{
  std::mt19937 rng(99);
  std::uniform_real_distribution<double> uni(0.02, 0.98);
  std::vector<double> x, v, xNear, vNear;
  for (int i = 0; i < 50000; ++i)
  {
    double p[3] = { uni(rng), uni(rng), uni(rng) };
    bool isNear = false;
    for (vtkIdType s : data.Spiked)
    {
      double d2 = 0.0;
      for (int d = 0; d < 3; ++d)
      {
        d2 += (p[d] - data.X[3 * s + d]) * (p[d] - data.X[3 * s + d]);
      }
      if (d2 < away * away)
      {
        isNear = true;
        break;
      }
    }
    std::vector<double>& xs = isNear ? xNear : x;
    std::vector<double>& vs = isNear ? vNear : v;
    xs.insert(xs.end(), p, p + 3);
    vs.push_back(fittest::Bump(p));
  }
  if (near)
  {
    *near = xNear.empty() ? 0.0 : fittest::PointError(spline, xNear, vNear);
  }
  return fittest::PointError(spline, x, v);
}

// The clean points' values and positions (spiked ones left out).
void CleanPoints(const Data& data, std::vector<double>& x, std::vector<double>& v)
{
  for (vtkIdType i = 0; i < NumberOfPoints; ++i)
  {
    if (!data.Spiked.count(i))
    {
      x.insert(x.end(), &data.X[3 * i], &data.X[3 * i] + 3);
      v.push_back(data.Clean[i]);
    }
  }
}

void Configure(vtkLRSplineFitter* fitter, bool remove)
{
  fitter->SetToleranceModeToAbsolute();
  fitter->SetTolerance(Tolerance);
  fitter->SetRemoveOutliers(remove);
}

void TestSpikes(SplineVizTestStatus& status)
{
  const Data data = MakeData(NumberOfPoints / 100, 5);
  auto cloud = fittest::Cloud(data.X, data.Values);
  std::vector<double> cleanX, cleanV;
  CleanPoints(data, cleanX, cleanV);

  // The fit of the clean data, for comparison.
  FitRun reference;
  Configure(reference.Fitter, false);
  SV_CHECK_MSG(status, reference.Run(fittest::Cloud(data.X, data.Clean)), reference.Error());
  const vtkIdType cleanElements = reference.Fitter->GetNumberOfElements();

  FitRun run;
  Configure(run.Fitter, true);
  const auto t0 = std::chrono::steady_clock::now();
  SV_CHECK_MSG(status, run.Run(cloud), run.Error());
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  vtkPolyData* outliers = vtkPolyData::SafeDownCast(run.Fitter->GetOutputDataObject(2));
  SV_CHECK(status, outliers != nullptr);
  if (!outliers)
  {
    return;
  }
  // Which points were found: by position (the output keeps them exactly).
  std::set<vtkIdType> found;
  vtkIdType falsePositives = 0;
  for (vtkIdType o = 0; o < outliers->GetNumberOfPoints(); ++o)
  {
    double p[3];
    outliers->GetPoint(o, p);
    for (vtkIdType i = 0; i < NumberOfPoints; ++i)
    {
      if (p[0] == data.X[3 * i] && p[1] == data.X[3 * i + 1] && p[2] == data.X[3 * i + 2])
      {
        found.insert(i);
        falsePositives += data.Spiked.count(i) ? 0 : 1;
        break;
      }
    }
  }
  vtkIdType missed = 0;
  for (vtkIdType s : data.Spiked)
  {
    missed += found.count(s) ? 0 : 1;
  }
  const double error = fittest::PointError(run.Output(), cleanX, cleanV);
  double near = 0.0;
  const double fresh = FreshError(run.Output(), data, 0.03, &near);
  const double referenceFresh = FreshError(reference.Output(), data, 0.03);
  std::cout << "1 % spikes, RemoveOutliers: " << run.Fitter->GetNumberOfOutliers()
            << " left out of " << NumberOfPoints << " (" << data.Spiked.size() << " spikes, "
            << missed << " missed, " << falsePositives << " clean points taken) in " << seconds
            << " s; " << run.Fitter->GetNumberOfElements() << " elements (clean data "
            << cleanElements << "); max error at the clean points " << error << "; at fresh points "
            << fresh << " away from the spikes (clean fit " << referenceFresh << "), " << near
            << " near them" << std::endl;
  SV_CHECK_MSG(status, missed == 0, missed << " spikes missed");
  SV_CHECK_MSG(status, falsePositives <= NumberOfPoints / 2000,
    falsePositives << " clean points taken for outliers");
  SV_CHECK(status, run.Fitter->GetNumberOfOutliers() == outliers->GetNumberOfPoints());
  SV_CHECK(status, outliers->GetNumberOfVerts() == outliers->GetNumberOfPoints());
  SV_CHECK(status, run.Fitter->GetNumberOfDataPoints() == NumberOfPoints - (vtkIdType)found.size());
  SV_CHECK_MSG(status, run.Fitter->GetToleranceMet() && !run.Warned(), run.Warning());
  SV_CHECK_MSG(status, error <= Tolerance * (1 + 1e-9), "clean points: " << error);
  SV_CHECK_MSG(status, fresh <= 1.5 * referenceFresh + Tolerance,
    "fresh points " << fresh << " against the clean fit's " << referenceFresh);
  SV_CHECK_MSG(status, near <= 1.5 * referenceFresh + Tolerance, "near the spikes: " << near);
  SV_CHECK_MSG(status, run.Fitter->GetNumberOfElements() <= 1.25 * cleanElements + 64,
    "elements " << run.Fitter->GetNumberOfElements() << " against " << cleanElements);
  vtkDataArray* deviation =
    outliers->GetPointData()->GetArray(vtkLRSplineArrayNames::FitOutlierDeviation);
  vtkDataArray* value = outliers->GetPointData()->GetScalars();
  SV_CHECK(status, deviation && value && value->GetName() && std::string(value->GetName()) == "f");
  if (deviation)
  {
    double range[2];
    deviation->GetRange(range);
    SV_CHECK_MSG(status, range[0] > run.Fitter->GetOutlierThreshold(), range[0]);
  }
  auto* grid = vtkUnstructuredGrid::SafeDownCast(run.Output()->GetBlock(0));
  vtkDataArray* count =
    grid ? grid->GetFieldData()->GetArray(vtkLRSplineArrayNames::FitOutliers) : nullptr;
  SV_CHECK(status, count && count->GetTuple1(0) == run.Fitter->GetNumberOfOutliers());

  // Negative control: the same data without RemoveOutliers. Chasing the
  // spikes would refine to about 22x the clean fit's elements; capped at 4x
  // it shows the same failure, and the test takes a third of the time (it
  // runs under the sanitizers in CI).
  FitRun control;
  Configure(control.Fitter, false);
  control.Fitter->SetMaximumNumberOfElements(4 * cleanElements);
  control.Run(cloud);
  double controlNear = 0.0;
  const double controlFresh = FreshError(control.Output(), data, 0.03, &controlNear);
  std::cout << "without RemoveOutliers: " << control.Fitter->GetNumberOfElements()
            << " elements, max error at fresh points away from the spikes " << controlFresh
            << ", near them " << controlNear << std::endl;
  SV_CHECK_MSG(status, controlNear > 10 * Tolerance, "negative control passed: " << controlNear);
  SV_CHECK_MSG(status, control.Fitter->GetNumberOfElements() > 2 * cleanElements,
    "negative control: " << control.Fitter->GetNumberOfElements() << " elements");
}

void TestCleanAndInvalid(SplineVizTestStatus& status)
{
  Data data = MakeData(0, 7);
  FitRun plain, removing;
  Configure(plain.Fitter, false);
  Configure(removing.Fitter, true);
  SV_CHECK_MSG(status, plain.Run(fittest::Cloud(data.X, data.Values)), plain.Error());
  SV_CHECK_MSG(status, removing.Run(fittest::Cloud(data.X, data.Values)), removing.Error());
  std::cout << "clean data: " << removing.Fitter->GetNumberOfOutliers() << " left out, "
            << removing.Fitter->GetNumberOfElements() << " elements (without RemoveOutliers "
            << plain.Fitter->GetNumberOfElements() << ")" << std::endl;
  SV_CHECK(status, removing.Fitter->GetNumberOfOutliers() == 0);
  SV_CHECK(status, removing.Fitter->GetNumberOfElements() == plain.Fitter->GetNumberOfElements());
  SV_CHECK(status, plain.Fitter->GetNumberOfOutliers() == 0);

  // Three NaN values and two infinite coordinates.
  auto cloud = fittest::Cloud(data.X, data.Values);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (vtkIdType i : { 10, 500, 7000 })
  {
    cloud->GetPointData()->GetScalars()->SetTuple1(i, nan);
  }
  cloud->GetPoints()->SetPoint(20, 0.5, std::numeric_limits<double>::infinity(), 0.5);
  cloud->GetPoints()->SetPoint(30, nan, 0.5, 0.5);
  FitRun run;
  Configure(run.Fitter, true);
  SV_CHECK_MSG(status, run.Run(cloud), run.Error());
  std::cout << "5 non-finite points: " << run.Fitter->GetNumberOfOutliers() << " left out, "
            << run.Fitter->GetNumberOfDataPoints() << " fitted" << std::endl;
  SV_CHECK(status, run.Fitter->GetNumberOfOutliers() == 5);
  SV_CHECK(status, run.Fitter->GetNumberOfDataPoints() == NumberOfPoints - 5);
  SV_CHECK(status, run.Fitter->GetToleranceMet());
  FitRun refused;
  Configure(refused.Fitter, false);
  SV_CHECK(
    status, !refused.Run(cloud) && refused.Error().find("RemoveOutliers") != std::string::npos);
}

void TestVector(SplineVizTestStatus& status)
{
  // v = (bump, x - y, 2 z), spikes in the second component only.
  const Data data = MakeData(0, 11);
  std::vector<double> v(3 * NumberOfPoints);
  std::set<vtkIdType> spiked;
  std::mt19937 rng(13);
  std::uniform_int_distribution<vtkIdType> pick(0, NumberOfPoints - 1);
  while (spiked.size() < 100)
  {
    spiked.insert(pick(rng));
  }
  for (vtkIdType i = 0; i < NumberOfPoints; ++i)
  {
    const double* x = &data.X[3 * i];
    v[3 * i] = data.Clean[i];
    v[3 * i + 1] = x[0] - x[1] + (spiked.count(i) ? 0.6 : 0.0);
    v[3 * i + 2] = 2 * x[2];
  }
  FitRun run;
  Configure(run.Fitter, true);
  run.Fitter->SetVectorModeToComponents();
  SV_CHECK_MSG(status, run.Run(fittest::Cloud(data.X, v, 3)), run.Error());
  vtkPolyData* outliers = vtkPolyData::SafeDownCast(run.Fitter->GetOutputDataObject(2));
  vtkIdType hits = 0;
  for (vtkIdType o = 0; outliers && o < outliers->GetNumberOfPoints(); ++o)
  {
    double p[3];
    outliers->GetPoint(o, p);
    for (vtkIdType s : spiked)
    {
      hits += (p[0] == data.X[3 * s] && p[1] == data.X[3 * s + 1] && p[2] == data.X[3 * s + 2]);
    }
  }
  std::cout << "vector field, 100 spikes in one component: " << run.Fitter->GetNumberOfOutliers()
            << " left out, " << hits << " of them spikes" << std::endl;
  SV_CHECK(status, hits == 100);
  SV_CHECK(status, run.Fitter->GetNumberOfOutliers() <= 100 + NumberOfPoints / 2000);
  SV_CHECK(status,
    outliers && outliers->GetPointData()->GetScalars() &&
      outliers->GetPointData()->GetScalars()->GetNumberOfComponents() == 3);
}
}

int TestLRSplineFitterOutliers(int, char*[])
{
  SplineVizTestStatus status;
  TestSpikes(status);
  TestCleanAndInvalid(status);
  TestVector(status);
  return status.Result();
}
