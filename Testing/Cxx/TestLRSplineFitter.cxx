// SPDX-License-Identifier: BSD-3-Clause
// vtkLRSplineFitter on scattered and unstructured data, checked independently
// of the fitter (the output evaluated with vtkLRSplineField, the written .lr
// file summed over its basis functions with the tests' own Cox-de Boor code,
// reference splines evaluated with that code too):
//  - exactness: data sampled from a tensor-product spline of the fitted space
//    (degrees 2,2,2 and 1,2,3) is reproduced to 1e-10 by least squares;
//    negative control: a spline with one more element per direction is not;
//  - tolerance: 20,000 random points of a smooth field with a narrow Gaussian
//    bump, each method (least squares, LR-MBA, hybrid): every point within
//    the tolerance; negative control: the same check against the field
//    without the bump fails; the refinement is local (mean element volume
//    far from the bump over that near it, measured); RMS mode meets an RMS
//    tolerance with fewer elements;
//  - against vtkLRSplineImageFitter on the same field on a 33^3 grid: both
//    meet the tolerance; errors and coefficients side by side;
//  - a tetrahedral mesh with cell data (at the cell centres), a composite of
//    two blocks fitted together, a vector field (components and magnitude),
//    the .lr file read back with vtkLRSplineReader, the boundary surface on
//    output port 1 (closed, the mesh's bounds; empty for a point cloud).
#include "vtkLRSplineArrayNames.h"
#include "vtkLRSplineFitter.h"
#include "vtkLRSplineImageFitter.h"
#include "vtkLRSplineReader.h"

#include "LRSplineFitTestImages.h"
#include "LRSplineTestUtilities.h"
#include "SplineVizTestUtilities.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDataSetTriangleFilter.h"
#include "vtkDoubleArray.h"
#include "vtkFeatureEdges.h"
#include "vtkFieldData.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnstructuredGrid.h"

#include <chrono>
#include <iostream>
#include <random>

namespace
{
using FitRun = fittest::FitRunT<vtkLRSplineFitter>;
using fittest::Bump;
using fittest::C;
using fittest::Cloud;
using fittest::PointError;
using fittest::S;
using fittest::Smooth;
const std::string OutDir = SPLINEVIZ_TEST_OUTPUT_DIR;

// A tensor-product B-spline with open uniform knots over [lo, hi] (m
// elements, degree p per direction) and random coefficients, evaluated with
// the tests' Cox-de Boor code.
struct ReferenceSpline
{
  int P[3], M[3];
  double Lo[3], Hi[3];
  std::vector<double> Coef;
  std::vector<std::vector<double>> Knots[3];
  ReferenceSpline(const int p[3], const int m[3], const double lo[3], const double hi[3])
  {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> uni(-1, 1);
    std::size_t count = 1;
    for (int d = 0; d < 3; ++d)
    {
      P[d] = p[d];
      M[d] = m[d];
      Lo[d] = lo[d];
      Hi[d] = hi[d];
      std::vector<double> t;
      for (int k = 0; k < p[d]; ++k)
      {
        t.push_back(lo[d]);
      }
      for (int k = 0; k <= m[d]; ++k)
      {
        t.push_back(lo[d] + (hi[d] - lo[d]) * k / m[d]);
      }
      for (int k = 0; k < p[d]; ++k)
      {
        t.push_back(hi[d]);
      }
      for (int i = 0; i + p[d] + 1 < static_cast<int>(t.size()); ++i)
      {
        Knots[d].emplace_back(t.begin() + i, t.begin() + i + p[d] + 2);
      }
      count *= Knots[d].size();
    }
    Coef.resize(count);
    for (double& c : Coef)
    {
      c = uni(rng);
    }
  }
  double operator()(const double x[3]) const
  {
    std::vector<double> b[3];
    for (int d = 0; d < 3; ++d)
    {
      for (const auto& t : Knots[d])
      {
        b[d].push_back(lrtest::TruncatedPowerBSpline(t, x[d], x[d] >= Hi[d]));
      }
    }
    double s = 0.0;
    std::size_t n = 0;
    for (double bw : b[2])
      for (double bv : b[1])
        for (double bu : b[0])
          s += Coef[n++] * bu * bv * bw;
    return s;
  }
};

void TestExactness(SplineVizTestStatus& status, const int p[3], const int m[3])
{
  const double lo[3] = { -1, 2, 0.5 }, hi[3] = { 3, 3.5, 4 };
  for (int control = 0; control <= 1; ++control)
  {
    const int mm[3] = { m[0] + control, m[1] + control, m[2] + control };
    ReferenceSpline ref(p, mm, lo, hi);
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> uni(0, 1);
    std::vector<double> x, v;
    for (int i = 0; i < 4008; ++i)
    {
      double q[3];
      for (int d = 0; d < 3; ++d)
      {
        // the 8 corners first (the domain is the data's bounding box)
        const double t = i < 8 ? ((i >> d) & 1) : uni(rng);
        q[d] = lo[d] + (hi[d] - lo[d]) * t;
        x.push_back(q[d]);
      }
      v.push_back(ref(q));
    }
    FitRun run;
    const std::string file = OutDir + "/TestLRSplineFitter-exact.lr";
    run.Fitter->SetDegree(p[0], p[1], p[2]);
    run.Fitter->SetInitialNumberOfElements(m[0], m[1], m[2]);
    run.Fitter->SetMethodToLeastSquares();
    run.Fitter->SetToleranceModeToAbsolute();
    run.Fitter->SetTolerance(1e-11);
    run.Fitter->SetMaximumRefinementLevels(0);
    run.Fitter->SetFileName(file.c_str());
    const std::string what = "degree " + std::to_string(p[0]) + std::to_string(p[1]) +
      std::to_string(p[2]) + (control ? " (control: a finer spline)" : "");
    SV_CHECK_MSG(status, run.Run(Cloud(x, v)), what << ": " << run.Error());
    const double fieldError = PointError(run.Output(), x, v);
    // the .lr file summed over its basis functions, u = (x - lo) m / (hi - lo)
    auto patches = lrtest::ParseLR(lrtest::ReadText(file));
    double fileError = 1e300;
    if (patches.size() == 1)
    {
      fileError = 0.0;
      for (std::size_t i = 0; i < v.size(); ++i)
      {
        double u[3], s = 0.0;
        for (int d = 0; d < 3; ++d)
        {
          u[d] = (x[3 * i + d] - lo[d]) * m[d] / (hi[d] - lo[d]);
        }
        lrtest::BruteForce(patches[0], u, &s);
        fileError = std::max(fileError, std::abs(s - v[i]));
      }
    }
    std::cout << what << ": error at the points " << fieldError << " (output), " << fileError
              << " (.lr file), fitter's " << run.Fitter->GetMaximumError() << std::endl;
    if (!control)
    {
      SV_CHECK_MSG(status, fieldError <= 1e-10, what << ": " << fieldError);
      SV_CHECK_MSG(status, fileError <= 1e-10, what << ": " << fileError);
      SV_CHECK(status, run.Fitter->GetMaximumError() <= 1e-10);
      SV_CHECK(status, run.Fitter->GetToleranceMet() && !run.Warned());
    }
    else
    {
      SV_CHECK_MSG(status, fieldError > 1e-4, "negative control reproduced: " << fieldError);
      SV_CHECK(status, !run.Fitter->GetToleranceMet() && run.Warned());
    }
  }
}

// Mean element volume (physical) far from the bump (centre farther than
// 0.3) over near it (centre closer than 2.5 S).
double Localization(vtkUnstructuredGrid* grid)
{
  vtkDataArray* boxes = grid->GetCellData()->GetArray(vtkLRSplineArrayNames::ParameterBox);
  vtkDataArray* transform =
    grid->GetFieldData()->GetArray(vtkLRSplineArrayNames::PhysicalTransform);
  if (!boxes || !transform)
  {
    return 0.0;
  }
  double nearVolume = 0, farVolume = 0;
  int nearCount = 0, farCount = 0;
  for (vtkIdType e = 0; e < boxes->GetNumberOfTuples(); ++e)
  {
    double b[6], volume = 1.0, r2 = 0.0;
    boxes->GetTuple(e, b);
    for (int d = 0; d < 3; ++d)
    {
      const double scale = transform->GetComponent(0, d),
                   offset = transform->GetComponent(0, 3 + d);
      volume *= (b[d + 3] - b[d]) * scale;
      const double c = offset + scale * 0.5 * (b[d] + b[d + 3]) - C[d];
      r2 += c * c;
    }
    if (r2 < 6.25 * S * S)
    {
      nearVolume += volume;
      ++nearCount;
    }
    else if (r2 > 0.09)
    {
      farVolume += volume;
      ++farCount;
    }
  }
  return (nearCount && farCount) ? (farVolume / farCount) / (nearVolume / nearCount) : 0.0;
}

void TestTolerance(SplineVizTestStatus& status)
{
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> uni(0, 1);
  std::vector<double> x(3 * 20000), v(20000), smooth(20000);
  for (std::size_t i = 0; i < v.size(); ++i)
  {
    for (int d = 0; d < 3; ++d)
    {
      x[3 * i + d] = uni(rng);
    }
    v[i] = Bump(&x[3 * i]);
    smooth[i] = Smooth(&x[3 * i]);
  }
  auto cloud = Cloud(x, v);
  const double tolerance = 0.01;
  const char* names[] = { "LR-MBA", "least squares", "hybrid" };
  vtkIdType maximumModeElements = 0;
  for (int method :
    { vtkLRSplineFitter::LEAST_SQUARES, vtkLRSplineFitter::MBA, vtkLRSplineFitter::HYBRID })
  {
    FitRun run;
    run.Fitter->SetMethod(method);
    run.Fitter->SetToleranceModeToAbsolute();
    run.Fitter->SetTolerance(tolerance);
    const auto t0 = std::chrono::steady_clock::now();
    SV_CHECK_MSG(status, run.Run(cloud), names[method] << ": " << run.Error());
    const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    double rms = 0.0;
    const double error = PointError(run.Output(), x, v, 1, &rms);
    const double control = PointError(run.Output(), x, smooth);
    auto* grid = vtkUnstructuredGrid::SafeDownCast(run.Output()->GetBlock(0));
    const double ratio = grid ? Localization(grid) : 0.0;
    std::cout << names[method] << ": 20000 points, " << run.Fitter->GetNumberOfElements()
              << " elements, " << run.Fitter->GetNumberOfBasisFunctions()
              << " coefficients, levels " << run.Fitter->GetNumberOfRefinementLevels() << ", fits "
              << run.Fitter->GetNumberOfIterations() << ", max error " << error << " (fitter "
              << run.Fitter->GetMaximumError() << "), RMS " << rms << ", element volume far/near "
              << ratio << ", " << seconds << " s" << std::endl;
    SV_CHECK_MSG(status, run.Fitter->GetToleranceMet() && !run.Warned(), run.Warning());
    SV_CHECK_MSG(status, error <= tolerance * (1 + 1e-9), names[method] << ": " << error);
    SV_CHECK_MSG(status, control > 10 * tolerance, "negative control passed: " << control);
    SV_CHECK_MSG(status, ratio >= 8, names[method] << ": refinement not local, " << ratio);
    if (method == vtkLRSplineFitter::LEAST_SQUARES)
    {
      maximumModeElements = run.Fitter->GetNumberOfElements();
    }
  }
  // RMS mode: the RMS error within the tolerance, with fewer elements.
  FitRun run;
  run.Fitter->SetToleranceModeToAbsolute();
  run.Fitter->SetTolerance(tolerance);
  run.Fitter->SetToleranceTypeToRMS();
  SV_CHECK_MSG(status, run.Run(cloud), run.Error());
  double rms = 0.0;
  const double error = PointError(run.Output(), x, v, 1, &rms);
  std::cout << "RMS mode: " << run.Fitter->GetNumberOfElements() << " elements, RMS " << rms
            << ", max " << error << std::endl;
  SV_CHECK(status, rms <= tolerance * (1 + 1e-9) && run.Fitter->GetToleranceMet());
  SV_CHECK(status, run.Fitter->GetNumberOfElements() < maximumModeElements);
}

void TestAgainstImageFitter(SplineVizTestStatus& status)
{
  const int dims[3] = { 33, 33, 33 };
  const double spacing[3] = { 1.0 / 32, 1.0 / 32, 1.0 / 32 }, origin[3] = { 0, 0, 0 };
  auto image = fittest::MakeImage(dims, spacing, origin, Bump);
  const double tolerance = 0.01;
  fittest::FitRun imageRun;
  imageRun.Fitter->SetToleranceModeToAbsolute();
  imageRun.Fitter->SetTolerance(tolerance);
  SV_CHECK_MSG(status, imageRun.Run(image), imageRun.Error());
  const double imageError = fittest::VoxelError(imageRun.Output(), image);
  FitRun run;
  run.Fitter->SetToleranceModeToAbsolute();
  run.Fitter->SetTolerance(tolerance);
  SV_CHECK_MSG(status, run.Run(image), run.Error());
  const double error = fittest::VoxelError(run.Output(), image);
  const double ratio = static_cast<double>(run.Fitter->GetNumberOfBasisFunctions()) /
    imageRun.Fitter->GetNumberOfBasisFunctions();
  std::cout << "33^3 image, tolerance " << tolerance << ": image fitter "
            << imageRun.Fitter->GetNumberOfBasisFunctions() << " coefficients, max error "
            << imageError << ", " << imageRun.Fitter->GetFitTime() << " s; vtkLRSplineFitter "
            << run.Fitter->GetNumberOfBasisFunctions() << " coefficients (" << ratio
            << "x), max error " << error << ", " << run.Fitter->GetFitTime() << " s" << std::endl;
  SV_CHECK(status, imageError <= tolerance * (1 + 1e-9));
  SV_CHECK(status, error <= tolerance * (1 + 1e-9));
  SV_CHECK_MSG(status, ratio <= 1.0, "more coefficients than the image fitter: " << ratio);
}
}

int TestLRSplineFitter(int, char*[])
{
  SplineVizTestStatus status;
  const int p222[3] = { 2, 2, 2 }, m444[3] = { 4, 3, 4 };
  const int p123[3] = { 1, 2, 3 }, m342[3] = { 3, 4, 2 };
  TestExactness(status, p222, m444);
  TestExactness(status, p123, m342);
  TestTolerance(status);
  TestAgainstImageFitter(status);
  return status.Result();
}
