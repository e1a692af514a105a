// SPDX-License-Identifier: BSD-3-Clause
// vtkLRSplineImageFitter on analytic images, checked independently of the
// fitter:
//  - exactness: a polynomial of the spline's tri-degree (2,2,2, and mixed
//    1,2,3) is reproduced on the initial mesh to 1e-9 of its range, at the
//    voxels and between them, by the brute-force sum over the basis
//    functions of the written .lr file (independent Cox-de Boor code) and by
//    the output grid; negative control: a cubic in one direction is not;
//  - a smooth field with a sharp, localized bump: the tolerance is met at
//    every voxel (the output evaluated with vtkLRSplineField); negative
//    controls: the same check half a voxel off fails, and the initial spline
//    does not meet it (with a warning); the refinement is local (the small
//    elements are all near the bump) and needs fewer elements than the
//    coarsest uniform tensor-product fit that meets the same tolerance
//    (searched);
//  - convergence: uniform refinement of a smooth field converges with order
//    close to 3 (quadratic), and the RMS error never grows during the
//    adaptive loop (nested spaces, least squares);
//  - the .lr file read back by vtkLRSplineReader (PhysicalBounds = the
//    image's bounds) is the same spline; pieces split the elements; knots
//    lie on voxel faces (even degree) or centres (odd), or are dyadic when
//    alignment is off (then the octree look-up applies); composite input
//    gives one patch per image.
#include "vtkLRSplineArrayNames.h"
#include "vtkLRSplineElementLocator.h"
#include "vtkLRSplineImageFitter.h"
#include "vtkLRSplineReader.h"

#include "LRSplineFitTestImages.h"
#include "LRSplineTestUtilities.h"
#include "SplineVizTestUtilities.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnstructuredGrid.h"

#include <chrono>
#include <iostream>
#include <random>

namespace
{
using fittest::FitRun;
using fittest::MakeImage;
using fittest::VoxelError;

const std::string OutDir = SPLINEVIZ_TEST_OUTPUT_DIR;

vtkUnstructuredGrid* Block(vtkMultiBlockDataSet* mb, unsigned int b = 0)
{
  return vtkUnstructuredGrid::SafeDownCast(mb->GetBlock(b));
}

double FieldValue(vtkUnstructuredGrid* grid, const char* name, int c = 0)
{
  vtkDataArray* a = grid ? grid->GetFieldData()->GetArray(name) : nullptr;
  return a ? a->GetComponent(0, c) : -1e300;
}

// A polynomial sum a_ijk xi^i eta^j zeta^k of tri-degree `deg` in coordinates
// normalized to [-1, 1] over the image.
struct Poly
{
  int Deg[3];
  std::vector<double> A;
  double Center[3], Half[3];
  double operator()(const double x[3]) const
  {
    double s = 0.0;
    std::size_t n = 0;
    for (int k = 0; k <= Deg[2]; ++k)
      for (int j = 0; j <= Deg[1]; ++j)
        for (int i = 0; i <= Deg[0]; ++i)
          s += A[n++] * std::pow((x[0] - Center[0]) / Half[0], i) *
            std::pow((x[1] - Center[1]) / Half[1], j) * std::pow((x[2] - Center[2]) / Half[2], k);
    return s;
  }
};

void TestPolynomial(
  SplineVizTestStatus& status, const int splineDeg[3], const int polyDeg[3], bool expectExact)
{
  const int dims[3] = { 33, 29, 21 };
  const double spacing[3] = { 0.5, 0.7, 1.1 }, origin[3] = { -3, 2, 1 };
  Poly p;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> uni(-1, 1);
  for (int d = 0; d < 3; ++d)
  {
    p.Deg[d] = polyDeg[d];
    p.Half[d] = 0.5 * spacing[d] * (dims[d] - 1);
    p.Center[d] = origin[d] + p.Half[d];
  }
  p.A.resize((polyDeg[0] + 1) * (polyDeg[1] + 1) * (polyDeg[2] + 1));
  for (double& a : p.A)
  {
    a = uni(rng);
  }
  auto image = MakeImage(dims, spacing, origin, p);
  double range[2];
  image->GetPointData()->GetScalars()->GetRange(range);
  const double scale = range[1] - range[0];

  FitRun run;
  const std::string file = OutDir + "/TestLRSplineImageFitter-poly.lr";
  run.Fitter->SetDegree(splineDeg[0], splineDeg[1], splineDeg[2]);
  run.Fitter->SetInitialNumberOfElements(4, 3, 3);
  run.Fitter->SetToleranceModeToAbsolute();
  run.Fitter->SetTolerance(1e-6 * scale);
  run.Fitter->SetMaximumRefinementLevels(expectExact ? 10 : 0);
  run.Fitter->SetFileName(file.c_str());
  const std::string what = "degree " + std::to_string(splineDeg[0]) + std::to_string(splineDeg[1]) +
    std::to_string(splineDeg[2]) + ", polynomial " + std::to_string(polyDeg[0]) +
    std::to_string(polyDeg[1]) + std::to_string(polyDeg[2]);
  SV_CHECK_MSG(status, run.Run(image), what << ": " << run.Error());
  const double voxelError = VoxelError(run.Output(), image);
  // Between the voxels: the .lr file summed over its basis functions.
  auto patches = lrtest::ParseLR(lrtest::ReadText(file));
  double between = 1e300;
  if (patches.size() == 1)
  {
    between = 0.0;
    std::uniform_real_distribution<double> unit(0, 1);
    for (int s = 0; s < 400; ++s)
    {
      double u[3], x[3], v;
      for (int d = 0; d < 3; ++d)
      {
        u[d] = unit(rng) * (dims[d] - 1);
        x[d] = origin[d] + spacing[d] * u[d];
      }
      lrtest::BruteForce(patches[0], u, &v);
      between = std::max(between, std::abs(v - p(x)));
    }
  }
  std::cout << what << ": " << run.Fitter->GetNumberOfElements() << " elements, "
            << run.Fitter->GetNumberOfBasisFunctions() << " functions, fitter's maximum error "
            << run.Fitter->GetMaximumError() / scale << ", at the voxels " << voxelError / scale
            << ", between them (brute force) " << between / scale << " (relative to the range)"
            << std::endl;
  if (expectExact)
  {
    SV_CHECK_MSG(status, run.Fitter->GetNumberOfIterations() == 1 && run.Fitter->GetToleranceMet(),
      what << ": not reproduced by the initial spline");
    SV_CHECK(status, run.Fitter->GetMaximumError() <= 1e-9 * scale);
    SV_CHECK(status, voxelError <= 1e-9 * scale);
    SV_CHECK(status, between <= 1e-9 * scale);
  }
  else
  {
    // negative control: the same checks must fail
    SV_CHECK_MSG(status, !run.Fitter->GetToleranceMet() && run.Warned(),
      what << ": a polynomial of higher degree must not be reproduced");
    SV_CHECK(status, voxelError > 1e-6 * scale && between > 1e-6 * scale);
  }
}

// The smooth field with a sharp bump (width 1.5 voxels) off the grid points.
const double Bump[3] = { 20.3, 11.6, 17.2 };
double BumpField(const double x[3])
{
  const double r2 = (x[0] - Bump[0]) * (x[0] - Bump[0]) + (x[1] - Bump[1]) * (x[1] - Bump[1]) +
    (x[2] - Bump[2]) * (x[2] - Bump[2]);
  return 0.25 * std::sin(2 * M_PI * x[0] / 40.0) * std::cos(2 * M_PI * x[1] / 50.0) +
    0.1 * x[2] / 32.0 + std::exp(-r2 / (2 * 1.5 * 1.5));
}

vtkIdType UniformFit(vtkImageData* image, double tolerance, int m, bool& met)
{
  FitRun run;
  run.Fitter->SetAlignKnotsToVoxels(false); // m equal elements per direction
  run.Fitter->SetInitialNumberOfElements(m, m, m);
  run.Fitter->SetMaximumRefinementLevels(0);
  run.Fitter->SetTolerance(tolerance);
  run.Run(image);
  met = run.Fitter->GetToleranceMet();
  return run.Fitter->GetNumberOfElements();
}

void TestLocalRefinement(SplineVizTestStatus& status)
{
  const int dims[3] = { 32, 32, 32 };
  const double spacing[3] = { 1, 1, 1 }, origin[3] = { 0, 0, 0 };
  auto image = MakeImage(dims, spacing, origin, BumpField);
  const double tolerance = 0.01; // relative: 1 % of the range

  FitRun run;
  run.Fitter->SetTolerance(tolerance);
  const std::string file = OutDir + "/TestLRSplineImageFitter-bump.lr";
  run.Fitter->SetFileName(file.c_str());
  const auto t0 = std::chrono::steady_clock::now();
  SV_CHECK_MSG(status, run.Run(image), run.Error());
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const double tol = run.Fitter->GetAbsoluteTolerance();
  double rms = 0.0;
  const double voxelError = VoxelError(run.Output(), image, 0.0, &rms);
  const double shifted = VoxelError(run.Output(), image, 0.5);
  std::cout << "bump: tolerance " << tol << ", " << run.Fitter->GetNumberOfElements()
            << " elements, " << run.Fitter->GetNumberOfBasisFunctions() << " functions, "
            << run.Fitter->GetNumberOfRefinementLevels() << " levels, "
            << run.Fitter->GetNumberOfIterations() << " fits, maximum error "
            << run.Fitter->GetMaximumError() << " (at the voxels, independently: " << voxelError
            << ", RMS " << rms << "; half a voxel off: " << shifted << "), " << seconds << " s"
            << std::endl;
  SV_CHECK(status, run.Fitter->GetToleranceMet() && !run.Warned());
  SV_CHECK(status, voxelError <= tol * (1 + 1e-9));
  SV_CHECK_NEAR(status, voxelError, run.Fitter->GetMaximumError(), 1e-9 * tol);
  SV_CHECK_NEAR(status, rms, run.Fitter->GetRMSError(), 1e-9 * tol);
  SV_CHECK_MSG(status, shifted > 2 * tol, "negative control: the check must see a misplacement");

  vtkUnstructuredGrid* grid = Block(run.Output());
  SV_CHECK(status, grid && grid->GetNumberOfCells() == run.Fitter->GetNumberOfElements());
  SV_CHECK(status, FieldValue(grid, vtkLRSplineArrayNames::FitToleranceMet) == 1);
  SV_CHECK_NEAR(status, FieldValue(grid, vtkLRSplineArrayNames::FitMaximumError),
    run.Fitter->GetMaximumError(), 0);
  vtkDataArray* history =
    grid ? grid->GetFieldData()->GetArray(vtkLRSplineArrayNames::FitHistory) : nullptr;
  SV_CHECK(status, history && history->GetNumberOfTuples() == run.Fitter->GetNumberOfIterations());

  // Negative control: the initial spline alone does not meet the tolerance.
  {
    FitRun coarse;
    coarse.Fitter->SetTolerance(tolerance);
    coarse.Fitter->SetMaximumRefinementLevels(0);
    SV_CHECK(status, coarse.Run(image));
    SV_CHECK(status, !coarse.Fitter->GetToleranceMet() && coarse.Warned());
    SV_CHECK(status, VoxelError(coarse.Output(), image) > 5 * tol);
    SV_CHECK(status, coarse.Warning().find("MaximumRefinementLevels") != std::string::npos);
  }

  // Locality: the smallest elements (the finest level reached) lie at the
  // bump; the smooth part needs coarser ones only.
  vtkDataArray* boxes =
    grid ? grid->GetCellData()->GetArray(vtkLRSplineArrayNames::ParameterBox) : nullptr;
  std::vector<double> side, dist;
  for (vtkIdType e = 0; boxes && e < boxes->GetNumberOfTuples(); ++e)
  {
    double b[6], s = 1e300, d2 = 0.0;
    boxes->GetTuple(e, b);
    for (int d = 0; d < 3; ++d)
    {
      s = std::min(s, b[d + 3] - b[d]);
      const double c = 0.5 * (b[d] + b[d + 3]);
      d2 += (c - Bump[d]) * (c - Bump[d]);
    }
    side.push_back(s);
    dist.push_back(std::sqrt(d2));
  }
  const double finest = side.empty() ? 0 : *std::min_element(side.begin(), side.end());
  double farthest = 0.0, farthestCoarse = 0.0;
  vtkIdType fine = 0;
  for (std::size_t e = 0; e < side.size(); ++e)
  {
    // the elements at the faces of the image are half a voxel: count the
    // finest interior ones (1 voxel)
    if (side[e] <= 1.0 + 1e-9)
    {
      ++fine;
      farthest = std::max(farthest, dist[e]);
    }
    else
    {
      farthestCoarse = std::max(farthestCoarse, dist[e]);
    }
  }
  std::cout << "bump: finest side " << finest << "; " << fine
            << " elements of one voxel or less, all within " << farthest
            << " voxels of the bump (coarser ones reach " << farthestCoarse << ")" << std::endl;
  SV_CHECK(status, fine > 0 && farthest < 12.0 && farthestCoarse > 20.0);

  // The coarsest uniform tensor-product spline that meets the tolerance.
  int lo = 4, hi = 4;
  bool met = false;
  vtkIdType uniform = UniformFit(image, tolerance, hi, met);
  while (!met && hi < dims[0] - 1)
  {
    lo = hi;
    hi = std::min(dims[0] - 1, 2 * hi);
    uniform = UniformFit(image, tolerance, hi, met);
  }
  SV_CHECK_MSG(status, met, "no uniform spline meets the tolerance");
  while (hi - lo > 1)
  {
    const int mid = (lo + hi) / 2;
    bool m = false;
    const vtkIdType n = UniformFit(image, tolerance, mid, m);
    if (m)
    {
      hi = mid;
      uniform = n;
    }
    else
    {
      lo = mid;
    }
  }
  std::cout << "bump: uniform refinement needs " << hi << "^3 = " << uniform
            << " elements for the same tolerance, the LR spline "
            << run.Fitter->GetNumberOfElements() << " ("
            << static_cast<double>(uniform) / run.Fitter->GetNumberOfElements() << " x fewer)"
            << std::endl;
  SV_CHECK(status, 2 * run.Fitter->GetNumberOfElements() < uniform);

  // The .lr file read back is the same spline.
  vtkNew<vtkLRSplineReader> reader;
  reader->SetFileName(file.c_str());
  double bounds[6];
  image->GetBounds(bounds);
  reader->SetPhysicalBounds(bounds);
  reader->Update();
  vtkUnstructuredGrid* back = Block(reader->GetOutput());
  SV_CHECK(status, back && back->GetNumberOfCells() == grid->GetNumberOfCells());
  vtkLRSplineField a, b;
  std::string error;
  SV_CHECK(status, a.Build(run.Output(), nullptr, 2, nullptr, false, &error));
  SV_CHECK(status, b.Build(reader->GetOutput(), nullptr, 2, nullptr, false, &error));
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(0, 1);
  double worst = 0.0;
  for (int s = 0; s < 3000; ++s)
  {
    double x[3], va = 0, vb = 1e300;
    for (int d = 0; d < 3; ++d)
    {
      x[d] = bounds[2 * d] + unit(rng) * (bounds[2 * d + 1] - bounds[2 * d]);
    }
    a.Evaluate(x, &va, nullptr);
    b.Evaluate(x, &vb, nullptr);
    worst = std::max(worst, std::abs(va - vb));
  }
  std::cout << "bump: the .lr read back differs by " << worst << std::endl;
  SV_CHECK(status, worst <= 1e-12);

  // Pieces: every piece fits the whole image and keeps its share.
  vtkIdType total = 0;
  for (int piece = 0; piece < 2; ++piece)
  {
    FitRun part;
    part.Fitter->SetTolerance(tolerance);
    part.Fitter->SetInputData(image);
    part.Fitter->UpdatePiece(piece, 2, 0);
    vtkUnstructuredGrid* g = Block(part.Output());
    vtkDataArray* ids = g ? g->GetCellData()->GetArray(vtkLRSplineArrayNames::ElementId) : nullptr;
    const vtkIdType n = run.Fitter->GetNumberOfElements();
    SV_CHECK(status,
      ids && ids->GetNumberOfTuples() > 0 &&
        static_cast<vtkIdType>(ids->GetComponent(0, 0)) == n * piece / 2);
    total += g ? g->GetNumberOfCells() : 0;
  }
  SV_CHECK(status, total == run.Fitter->GetNumberOfElements());
}

void TestConvergence(SplineVizTestStatus& status)
{
  const int dims[3] = { 37, 37, 37 };
  const double spacing[3] = { 1, 1, 1 }, origin[3] = { 0, 0, 0 };
  auto smooth = [](const double x[3])
  {
    return std::sin(2 * M_PI * x[0] / 36.0 + 0.3) * std::sin(2 * M_PI * 0.8 * x[1] / 36.0) *
      std::cos(2 * M_PI * 0.7 * x[2] / 36.0);
  };
  auto image = MakeImage(dims, spacing, origin, smooth);
  double errors[3];
  const int m[3] = { 3, 6, 12 };
  for (int i = 0; i < 3; ++i)
  {
    FitRun run;
    run.Fitter->SetInitialNumberOfElements(m[i], m[i], m[i]);
    run.Fitter->SetMaximumRefinementLevels(0);
    run.Fitter->SetTolerance(1e-12);
    run.Fitter->SetAlignKnotsToVoxels(false); // exact halvings
    SV_CHECK(status, run.Run(image));
    errors[i] = VoxelError(run.Output(), image);
  }
  const double order1 = std::log2(errors[0] / errors[1]), order2 = std::log2(errors[1] / errors[2]);
  std::cout << "convergence: maximum errors " << errors[0] << ", " << errors[1] << ", " << errors[2]
            << " for h = 12, 6, 3 voxels; observed orders " << order1 << ", " << order2
            << " (quadratic: 3)" << std::endl;
  SV_CHECK(status, order1 > 2.5 && order2 > 2.5);

  // The adaptive loop: the RMS error never grows.
  FitRun run;
  run.Fitter->SetTolerance(1e-3);
  SV_CHECK(status, run.Run(image));
  vtkDataArray* history =
    Block(run.Output())->GetFieldData()->GetArray(vtkLRSplineArrayNames::FitHistory);
  bool monotone = history && history->GetNumberOfTuples() >= 3;
  for (vtkIdType i = 1; history && i < history->GetNumberOfTuples(); ++i)
  {
    std::cout << "  fit " << i << ": " << history->GetComponent(i, 0) << " elements, maximum "
              << history->GetComponent(i, 2) << ", RMS " << history->GetComponent(i, 3)
              << std::endl;
    monotone =
      monotone && history->GetComponent(i, 3) <= history->GetComponent(i - 1, 3) * (1 + 1e-6);
  }
  SV_CHECK_MSG(status, monotone, "the RMS error grew during the refinement");
  SV_CHECK(status, run.Fitter->GetToleranceMet());
}

void TestKnotsAndComposite(SplineVizTestStatus& status)
{
  const int dims[3] = { 24, 22, 20 };
  const double spacing[3] = { 1, 1, 1 }, origin[3] = { 0, 0, 0 };
  auto image = MakeImage(dims, spacing, origin, BumpField);
  for (int degree : { 2, 3 })
  {
    for (bool align : { true, false })
    {
      FitRun run;
      run.Fitter->SetDegree(degree, degree, degree);
      run.Fitter->SetTolerance(0.02);
      run.Fitter->SetAlignKnotsToVoxels(align);
      SV_CHECK(status, run.Run(image));
      vtkUnstructuredGrid* grid = Block(run.Output());
      vtkDataArray* boxes = grid->GetCellData()->GetArray(vtkLRSplineArrayNames::ParameterBox);
      bool onGrid = true, dyadic = true;
      for (vtkIdType e = 0; e < boxes->GetNumberOfTuples(); ++e)
      {
        for (int c = 0; c < 6; ++c)
        {
          const double v = boxes->GetComponent(e, c);
          const double offset = degree % 2 == 0 ? 0.5 : 0.0;
          const int d = c % 3;
          const double top = dims[d] - 1;
          onGrid = onGrid && (v == 0 || v == top || v - offset == std::floor(v - offset));
          const double t = v / top * 4.0;
          dyadic = dyadic && std::ldexp(t, 12) == std::floor(std::ldexp(t, 12));
        }
      }
      std::vector<double> all(boxes->GetNumberOfTuples() * 6);
      for (vtkIdType e = 0; e < boxes->GetNumberOfTuples(); ++e)
      {
        boxes->GetTuple(e, all.data() + 6 * e);
      }
      vtkLRSplineElementLocator octree;
      std::string error;
      const bool octreeOk = octree.Build(
        all.data(), boxes->GetNumberOfTuples(), vtkLRSplineElementLocator::OCTREE, nullptr, &error);
      std::cout << "degree " << degree << (align ? ", aligned" : ", dyadic") << ": "
                << run.Fitter->GetNumberOfElements() << " elements, maximum error "
                << run.Fitter->GetMaximumError() << ", octree " << (octreeOk ? "yes" : "no")
                << std::endl;
      SV_CHECK(status, run.Fitter->GetToleranceMet());
      if (align)
      {
        SV_CHECK_MSG(status, onGrid, "knots off the voxel grid");
      }
      else
      {
        SV_CHECK_MSG(status, dyadic && octreeOk, "dyadic knots expected: " << error);
      }
    }
  }

  // Composite input: one patch per image, each placed where its image is
  // (the second's extent does not start at 0, as after vtkExtractVOI).
  const double origin2[3] = { 100, -50, 7 }, spacing2[3] = { 2, 3, 0.5 };
  const int dims2[3] = { 12, 10, 9 }, start2[3] = { 5, -3, 2 };
  auto second = MakeImage(
    dims2, spacing2, origin2, [](const double x[3]) { return 0.01 * x[0] * x[1] + x[2]; },
    "density", start2);
  vtkNew<vtkMultiBlockDataSet> both;
  both->SetBlock(0, image);
  both->SetBlock(1, second);
  FitRun run;
  run.Fitter->SetTolerance(0.02);
  SV_CHECK(status, run.Run(both));
  SV_CHECK(status, run.Output()->GetNumberOfBlocks() == 2);
  if (run.Output()->GetNumberOfBlocks() == 2)
  {
    vtkNew<vtkMultiBlockDataSet> one, two;
    one->SetBlock(0, run.Output()->GetBlock(0));
    two->SetBlock(0, run.Output()->GetBlock(1));
    const double tol = run.Fitter->GetAbsoluteTolerance();
    SV_CHECK(status, VoxelError(one, image) <= tol * (1 + 1e-9));
    SV_CHECK(status, VoxelError(two, second) <= tol * (1 + 1e-9));
    SV_CHECK(status, FieldValue(Block(run.Output(), 1), vtkLRSplineArrayNames::PatchIndex) == 1);
  }
}
}

int TestLRSplineImageFitter(int, char*[])
{
  SplineVizTestStatus status;
  const auto start = std::chrono::steady_clock::now();
  auto lap = [&start](const char* what)
  {
    std::cout << "(" << what << " done after "
              << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()
              << " s)" << std::endl;
  };
  const int d222[3] = { 2, 2, 2 }, d123[3] = { 1, 2, 3 }, d322[3] = { 3, 2, 2 };
  TestPolynomial(status, d222, d222, true);
  TestPolynomial(status, d123, d123, true);
  TestPolynomial(status, d222, d322, false);
  lap("polynomials");
  TestLocalRefinement(status);
  lap("bump");
  TestConvergence(status);
  lap("convergence");
  TestKnotsAndComposite(status);
  lap("knots");
  return status.Result();
}
