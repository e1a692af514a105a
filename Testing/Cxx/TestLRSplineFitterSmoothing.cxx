// SPDX-License-Identifier: BSD-3-Clause
// The smoothing term of the LR-spline least squares (vtkLRSplineFitter's
// Smoothing, vtkLRSplineFitCore::AddElementSmoothing):
//  - the element energy c^T S_e c against references computed without the
//    production code: exact energies of the polynomials u^2 and u v (built
//    from their blossoms), zero for an affine function, and, for random
//    coefficients on a tensor-product and a locally refined patch of degrees
//    (2,2,2) and (1,2,3), the thin-plate integrand by central differences of
//    the spline summed with the tests' own Cox-de Boor (exact for these
//    degrees up to rounding) and a 4-point Gauss rule per direction, to 1e-6
//    relative; negative control: the same reference with the mixed
//    derivatives counted once differs by more than 1 %;
//  - the swing it exists for: ParaView's Wavelet clipped by a sphere of
//    radius 9 (an unstructured grid whose boundary elements hold data in one
//    corner), fitted to 2 % of its range. At random points inside the sphere,
//    the spline's distance from the trilinear interpolation of the unclipped
//    image (an independent estimate of the field) near the boundary
//    (8 <= r < 8.99) stays within twice that of the interior (r < 8), the
//    spline within the data's range widened by a quarter of it, and the
//    tolerance is met without the swing warning; negative control: with
//    Smoothing 0 the spline leaves the range by more than 10 ranges there and
//    the fitter warns that it may swing between the data points.
// Exactness with the default Smoothing (dense data is fitted without it):
// TestLRSplineFitter.
#include "vtkLRSplineField.h"
#include "vtkLRSplineFitCore.h"
#include "vtkLRSplineFitter.h"

#include "LRSplineFitTestImages.h"
#include "LRSplineTestUtilities.h"
#include "SplineVizTestUtilities.h"

#include "vtkClipDataSet.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProbeFilter.h"
#include "vtkRTAnalyticSource.h"
#include "vtkSphere.h"
#include "vtkUnstructuredGrid.h"

#include <array>
#include <cmath>
#include <iostream>
#include <random>

namespace
{
using FitRun = fittest::FitRunT<vtkLRSplineFitter>;

// The patch's basis in the tests' own evaluator (all functions summed).
lrtest::BrutePatch Brute(const vtkLRSplinePatch& patch, const std::vector<double>& coefficients)
{
  lrtest::BrutePatch brute;
  brute.Dim = 1;
  const vtkIdType nf = patch.GetNumberOfBasisFunctions();
  for (vtkIdType f = 0; f < nf; ++f)
  {
    std::array<std::vector<double>, 3> knots;
    for (int d = 0; d < 3; ++d)
    {
      const double* t = patch.GetKnots(f, d);
      knots[d].assign(t, t + patch.Order[d] + 1);
    }
    brute.Knots.push_back(knots);
  }
  brute.Gamma = patch.Gamma;
  brute.Coef = coefficients;
  for (int d = 0; d < 3; ++d)
  {
    brute.Order[d] = patch.Order[d];
    brute.Domain[d] = 1e300;
    brute.Domain[d + 3] = -1e300;
  }
  for (vtkIdType e = 0; e < patch.GetNumberOfElements(); ++e)
  {
    for (int d = 0; d < 3; ++d)
    {
      brute.Domain[d] = std::min(brute.Domain[d], patch.ElementBoxes[6 * e + d]);
      brute.Domain[d + 3] = std::max(brute.Domain[d + 3], patch.ElementBoxes[6 * e + d + 3]);
    }
  }
  return brute;
}

// Integral over element e of u_ss^2 + v_ss^2 + w_ss^2 + mixed (u_s v_s ...)^2
// times `mixedWeight` (2 for the thin-plate energy), s the element's own
// coordinates: central differences with step h in s, 4-point Gauss-Legendre.
double ReferenceEnergy(const lrtest::BrutePatch& brute, const double* box, double mixedWeight)
{
  const double node[4] = { -0.8611363115940526, -0.3399810435848563, 0.3399810435848563,
    0.8611363115940526 };
  const double weight[4] = { 0.3478548451374538, 0.6521451548625461, 0.6521451548625461,
    0.3478548451374538 };
  const double h = 3e-4;
  auto value = [&](const double s[3])
  {
    double u[3], out = 0.0;
    for (int d = 0; d < 3; ++d)
    {
      u[d] = box[d] + s[d] * (box[d + 3] - box[d]);
    }
    lrtest::BruteForce(brute, u, &out);
    return out;
  };
  double energy = 0.0;
  for (int i = 0; i < 4; ++i)
  {
    for (int j = 0; j < 4; ++j)
    {
      for (int k = 0; k < 4; ++k)
      {
        const double s[3] = { 0.5 + 0.5 * node[i], 0.5 + 0.5 * node[j], 0.5 + 0.5 * node[k] };
        const double w = 0.125 * weight[i] * weight[j] * weight[k];
        const double f0 = value(s);
        double integrand = 0.0;
        for (int a = 0; a < 3; ++a)
        {
          double sp[3] = { s[0], s[1], s[2] }, sm[3] = { s[0], s[1], s[2] };
          sp[a] += h;
          sm[a] -= h;
          const double faa = (value(sp) - 2 * f0 + value(sm)) / (h * h);
          integrand += faa * faa;
          for (int b = a + 1; b < 3; ++b)
          {
            double q[4][3];
            for (int c = 0; c < 4; ++c)
            {
              std::copy(s, s + 3, q[c]);
              q[c][a] += (c & 1) ? -h : h;
              q[c][b] += (c & 2) ? -h : h;
            }
            const double fab =
              (value(q[0]) - value(q[1]) - value(q[2]) + value(q[3])) / (4 * h * h);
            integrand += mixedWeight * fab * fab;
          }
        }
        energy += w * integrand;
      }
    }
  }
  return energy;
}

// sum_e c^T S_e c by the production code (per element in `perElement`).
double CoreEnergy(
  vtkLRSplineFitCore& core, const std::vector<double>& c, std::vector<double>& perElement, bool& ok)
{
  const vtkLRSplinePatch& patch = core.Builder.GetPatch();
  core.ComputeSupports();
  const vtkIdType ne = patch.GetNumberOfElements();
  perElement.assign(ne, 0.0);
  double total = 0.0;
  ok = true;
  for (vtkIdType e = 0; e < ne; ++e)
  {
    const vtkIdType first = core.SupportOffsets[e];
    const vtkIdType count = core.SupportOffsets[e + 1] - first;
    std::vector<double> local(count * count, 0.0);
    std::string error;
    if (!core.AddElementSmoothing(patch, e, 1.0, local.data(), &error))
    {
      std::cerr << error << std::endl;
      ok = false;
      return 0.0;
    }
    double s = 0.0;
    for (vtkIdType a = 0; a < count; ++a)
    {
      for (vtkIdType b = 0; b < count; ++b)
      {
        s += c[core.SupportIds[first + a]] * local[a * count + b] * c[core.SupportIds[first + b]];
      }
    }
    perElement[e] = s;
    total += s;
  }
  return total;
}

using Blossom = std::function<void(const double* const t[3], const int p[3], double* c)>;

// A patch of the given degrees on breaks 0..3 per direction with the
// coefficients `blossom` gives (when set), optionally refined once at element
// 0 (then an LR spline, not a tensor product; refining keeps the function).
bool MakePatch(
  vtkLRSplineFitCore& core, const int degree[3], bool refine, const Blossom& blossom = nullptr)
{
  std::vector<double> breaks[3];
  for (int d = 0; d < 3; ++d)
  {
    breaks[d] = { 0.0, 1.0, 2.0, 3.0 };
  }
  std::string error;
  core.Options.Ratio = 0.5;
  core.MinimumCell = 1e-9;
  if (!core.Builder.InitializeTensorProduct(degree, breaks, 1, &error))
  {
    std::cerr << error << std::endl;
    return false;
  }
  if (blossom)
  {
    core.Builder.SetCoefficientsFromKnots(blossom);
  }
  if (refine)
  {
    core.ComputeSupports();
    std::vector<double> marks(core.Builder.GetPatch().GetNumberOfElements(), 0.0);
    marks[0] = 1.0;
    if (core.Refine(marks, 0.5, 100000, &error) != vtkLRSplineFitCore::REFINED)
    {
      std::cerr << "refinement: " << error << std::endl;
      return false;
    }
  }
  return true;
}

void TestElementEnergy(SplineVizTestStatus& status)
{
  const int degrees[2][3] = { { 2, 2, 2 }, { 1, 2, 3 } };
  for (const auto& degree : degrees)
  {
    for (int refine = 0; refine <= 1; ++refine)
    {
      vtkLRSplineFitCore core;
      const std::string what = "degree " + std::to_string(degree[0]) + std::to_string(degree[1]) +
        std::to_string(degree[2]) + (refine ? ", refined" : ", tensor product");
      if (!MakePatch(core, degree, refine != 0))
      {
        status.Fail(what + ": patch", __FILE__, __LINE__);
        continue;
      }
      const vtkLRSplinePatch& patch = core.Builder.GetPatch();
      const vtkIdType nf = patch.GetNumberOfBasisFunctions();
      const vtkIdType ne = patch.GetNumberOfElements();
      std::mt19937 rng(11 + refine);
      std::uniform_real_distribution<double> uni(-1, 1);
      std::vector<double> c(nf);
      for (double& v : c)
      {
        v = uni(rng);
      }
      std::vector<double> perElement;
      bool ok = false;
      const double total = CoreEnergy(core, c, perElement, ok);
      SV_CHECK_MSG(status, ok, what);
      const lrtest::BrutePatch brute = Brute(patch, c);
      double reference = 0.0, once = 0.0, worst = 0.0;
      for (vtkIdType e = 0; e < ne; ++e)
      {
        const double r = ReferenceEnergy(brute, &patch.ElementBoxes[6 * e], 2.0);
        reference += r;
        once += ReferenceEnergy(brute, &patch.ElementBoxes[6 * e], 1.0);
        worst = std::max(worst, std::abs(perElement[e] - r) / std::max(r, 1e-12));
      }
      std::cout << what << ": " << ne << " elements, " << nf << " functions; energy " << total
                << ", reference " << reference << " (largest relative difference per element "
                << worst << "); mixed terms once: " << once << std::endl;
      SV_CHECK_MSG(status, worst <= 1e-6, what << ": " << worst);
      SV_CHECK_MSG(status, std::abs(once - total) > 0.01 * total,
        what << ": negative control passed: " << once << " against " << total);

      // Polynomials of the space by their blossoms: u^2 (degree >= 2 in u),
      // u v, and an affine function; element sides hu, hv in parameters.
      struct Case
      {
        const char* Name;
        int Needs[3];
        std::function<double(const double* const t[3], const int p[3])> Blossom;
        std::function<double(double hu, double hv)> Energy;
      };
      auto mean = [](const double* t, int p)
      {
        double s = 0.0;
        for (int i = 0; i < p; ++i)
        {
          s += t[i] / p;
        }
        return s;
      };
      const Case cases[] = {
        { "u^2", { 2, 0, 0 },
          [&](const double* const t[3], const int p[3])
          {
            // the blossom of u^2 of degree p: sum_{i<j} t_i t_j / C(p, 2)
            double s = 0.0;
            for (int i = 0; i < p[0]; ++i)
            {
              for (int j = i + 1; j < p[0]; ++j)
              {
                s += t[0][i] * t[0][j];
              }
            }
            return s / (p[0] * (p[0] - 1) / 2.0);
          },
          [](double hu, double) { return 4 * hu * hu * hu * hu; } },
        { "u v", { 1, 1, 0 },
          [&](const double* const t[3], const int p[3])
          { return mean(t[0], p[0]) * mean(t[1], p[1]); },
          [](double hu, double hv) { return 2 * hu * hu * hv * hv; } },
        { "1 + 2u - v + w/2", { 1, 1, 1 },
          [&](const double* const t[3], const int p[3])
          { return 1 + 2 * mean(t[0], p[0]) - mean(t[1], p[1]) + 0.5 * mean(t[2], p[2]); },
          [](double, double) { return 0.0; } },
      };
      for (const Case& test : cases)
      {
        if (degree[0] < test.Needs[0] || degree[1] < test.Needs[1] || degree[2] < test.Needs[2])
        {
          continue;
        }
        vtkLRSplineFitCore exactCore;
        MakePatch(exactCore, degree, refine != 0,
          [&](const double* const t[3], const int p[3], double* out)
          { out[0] = test.Blossom(t, p); });
        const std::vector<double> coefficients = exactCore.Builder.GetPatch().Coefficients;
        const double energy = CoreEnergy(exactCore, coefficients, perElement, ok);
        double exact = 0.0;
        for (vtkIdType e = 0; e < ne; ++e)
        {
          const double* box = &patch.ElementBoxes[6 * e];
          exact += test.Energy(box[3] - box[0], box[4] - box[1]);
        }
        std::cout << what << ", " << test.Name << ": energy " << energy << ", exact " << exact
                  << std::endl;
        SV_CHECK_MSG(status, std::abs(energy - exact) <= 1e-10 * (1 + exact),
          what << ", " << test.Name << ": " << energy << " against " << exact);
      }
    }
  }
}

// Random points, `n` inside the sphere of radius `inner` and `n` in the
// shell between it and `outer` (their radii in `r`).
vtkSmartPointer<vtkPolyData> PointsInSphere(
  double inner, double outer, int n, std::vector<double>& r)
{
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> uni(-outer, outer);
  vtkNew<vtkPoints> points;
  r.clear();
  int counts[2] = { 0, 0 };
  while (counts[0] < n || counts[1] < n)
  {
    const double x[3] = { uni(rng), uni(rng), uni(rng) };
    const double d = std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
    const int shell = d < inner ? 0 : 1;
    if (d < outer && counts[shell] < n)
    {
      ++counts[shell];
      points->InsertNextPoint(x);
      r.push_back(d);
    }
  }
  auto cloud = vtkSmartPointer<vtkPolyData>::New();
  cloud->SetPoints(points);
  return cloud;
}

// The fitted spline at the points (vtkLRSplineField); empty on failure.
std::vector<double> Evaluate(vtkDataObject* spline, vtkPolyData* points)
{
  vtkLRSplineField field;
  std::string error;
  std::vector<double> values;
  if (!field.Build(spline, nullptr, 2, nullptr, false, &error))
  {
    std::cerr << "vtkLRSplineField: " << error << std::endl;
    return values;
  }
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    double x[3], s = 0.0;
    points->GetPoint(i, x);
    if (field.Evaluate(x, &s, nullptr) < 0)
    {
      std::cerr << "point " << i << " outside the spline" << std::endl;
      return std::vector<double>();
    }
    values.push_back(s);
  }
  return values;
}

void TestClippedWavelet(SplineVizTestStatus& status)
{
  vtkNew<vtkRTAnalyticSource> wavelet;
  wavelet->SetWholeExtent(-10, 10, -10, 10, -10, 10);
  vtkNew<vtkSphere> sphere;
  sphere->SetRadius(9.0);
  vtkNew<vtkClipDataSet> clip;
  clip->SetInputConnection(wavelet->GetOutputPort());
  clip->SetClipFunction(sphere);
  clip->InsideOutOn();
  clip->Update();
  double range[2];
  clip->GetOutput()->GetPointData()->GetScalars()->GetRange(range);
  const double width = range[1] - range[0];

  std::vector<double> r;
  vtkSmartPointer<vtkPolyData> fresh = PointsInSphere(8.0, 8.99, 20000, r);
  vtkNew<vtkProbeFilter> trilinear;
  trilinear->SetInputData(fresh);
  trilinear->SetSourceConnection(wavelet->GetOutputPort());
  trilinear->Update();
  vtkDataArray* reference = trilinear->GetOutput()->GetPointData()->GetArray("RTData");

  double interior[2] = { 0, 0 }, boundary[2] = { 0, 0 }, excursion[2] = { 0, 0 };
  bool swingWarning[2] = { false, false }, met[2] = { false, false };
  vtkIdType elements[2] = { 0, 0 };
  for (int control = 0; control <= 1; ++control)
  {
    FitRun run;
    run.Fitter->SetTolerance(0.02);
    if (control)
    {
      run.Fitter->SetSmoothing(0.0);
    }
    const bool ran = run.Run(clip->GetOutput());
    SV_CHECK_MSG(status, ran, run.Error());
    if (!ran)
    {
      return;
    }
    const std::vector<double> spline = Evaluate(run.Output(), fresh);
    SV_CHECK(status, spline.size() == r.size());
    if (spline.size() != r.size())
    {
      return;
    }
    for (std::size_t i = 0; i < r.size(); ++i)
    {
      const double e = std::abs(spline[i] - reference->GetTuple1(static_cast<vtkIdType>(i)));
      double& band = r[i] < 8.0 ? interior[control] : boundary[control];
      band = std::max(band, e);
      const double out = std::max(range[0] - spline[i], spline[i] - range[1]) / width;
      excursion[control] = std::max(excursion[control], out);
    }
    swingWarning[control] = run.Warning().find("swing far from the data") != std::string::npos;
    met[control] = run.Fitter->GetToleranceMet() != 0;
    elements[control] = run.Fitter->GetNumberOfElements();
    std::cout << "clipped Wavelet, Smoothing " << run.Fitter->GetSmoothing() << ": "
              << elements[control] << " elements, tolerance met " << met[control]
              << "; |spline - trilinear| up to " << interior[control] << " for r < 8, "
              << boundary[control] << " for 8 <= r < 8.99; outside the data's range by up to "
              << excursion[control] << " ranges; swing warning " << swingWarning[control]
              << std::endl;
  }
  SV_CHECK_MSG(status, boundary[0] <= 2 * interior[0], boundary[0] << " against " << interior[0]);
  SV_CHECK_MSG(status, excursion[0] <= 0.25, excursion[0]);
  SV_CHECK(status, met[0] && !swingWarning[0]);
  SV_CHECK_MSG(status, excursion[1] > 10, "negative control passed: " << excursion[1]);
  SV_CHECK_MSG(status, boundary[1] > 100 * interior[1], "negative control passed");
  SV_CHECK(status, swingWarning[1]);
}
}

int TestLRSplineFitterSmoothing(int, char*[])
{
  SplineVizTestStatus status;
  TestElementEnergy(status);
  TestClippedWavelet(status);
  return status.Result();
}
