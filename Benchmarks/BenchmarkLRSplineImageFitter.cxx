// SPDX-License-Identifier: BSD-3-Clause
// Benchmark of vtkLRSplineImageFitter (a real data path) on the
// real MR scans Debian's python3-dipy ships, read by VTK's
// vtkNIFTIImageReader: aniso_vox.nii.gz (58 x 58 x 24) and S0_10slices.nii.gz
// (128 x 128 x 10).
//
// For each scan and tolerance (a fraction of the data range, at every voxel):
//  - the LR fit (local refinement): wall and CPU time, elements, basis
//    functions, refinement levels, fits, maximum and RMS error;
//  - the same tolerance with uniform refinement, side by side: the coarsest
//    tensor-product spline (elements of equal sides, m along the longest
//    direction, the same least squares) that meets it, found by bisection
//    over m, its elements and the time of that one fit;
//  - the sizes that matter to a renderer: the voxels (the image as floats,
//    what vtkSmartVolumeMapper uploads), the LR spline's Bezier form (27
//    floats and a box of 6 per element) and its LR form (one coefficient per
//    basis function).
// Ratios: uniform elements / LR elements.
//
//   BenchmarkLRSplineImageFitter [--tolerances 0.02,0.05,0.1] [--scans path,path]
//                                [--uniform 0|1]
#include "BenchmarkCommon.h"
#include "vtkLRSplineImageFitter.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkImageData.h"
#include "vtkNIFTIImageReader.h"
#include "vtkNew.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace
{
const char* Usage =
  "BenchmarkLRSplineImageFitter [--tolerances 0.02,0.05,0.1] [--scans a.nii.gz,b.nii.gz]\n"
  "                             [--uniform 1]\n"
  "  Fits LR splines to DIPY's real scans (default: aniso_vox.nii.gz and\n"
  "  S0_10slices.nii.gz from python3-dipy) at each tolerance (a fraction of the\n"
  "  data range, met at every voxel) and, with --uniform 1, finds the coarsest\n"
  "  uniform tensor-product spline meeting the same tolerance.\n";

struct Result
{
  bool Met = false;
  vtkIdType Elements = 0, Functions = 0;
  int Levels = 0, Fits = 0;
  double MaxError = 0, RMS = 0, Wall = 0, CPU = 0;
};

// uniform > 0: the tensor-product spline with elements of about equal sides,
// `uniform` along the image's longest direction.
Result Fit(vtkImageData* image, double tolerance, int uniform)
{
  vtkNew<vtkLRSplineImageFitter> fitter;
  fitter->SetInputData(image);
  fitter->SetTolerance(tolerance);
  vtkNew<vtkCallbackCommand> quiet; // "tolerance not met" is expected here
  if (uniform > 0)
  {
    int dims[3];
    image->GetDimensions(dims);
    const int longest = std::max(dims[0], std::max(dims[1], dims[2])) - 1;
    int m[3];
    for (int d = 0; d < 3; ++d)
    {
      m[d] = std::max(1, static_cast<int>(std::lround(uniform * (dims[d] - 1.0) / longest)));
      m[d] = uniform > longest ? dims[d] : m[d];
    }
    // knots on voxel faces like the LR fit (equal elements of whole voxels,
    // so that the finest can interpolate)
    fitter->SetInitialNumberOfElements(m);
    fitter->SetMaximumRefinementLevels(0);
    fitter->AddObserver(vtkCommand::WarningEvent, quiet);
  }
  const double w0 = splineviz_benchmark::Now(), c0 = splineviz_benchmark::CPUTime();
  fitter->Update();
  Result r;
  r.Wall = splineviz_benchmark::Now() - w0;
  r.CPU = splineviz_benchmark::CPUTime() - c0;
  r.Met = fitter->GetToleranceMet();
  r.Elements = fitter->GetNumberOfElements();
  r.Functions = fitter->GetNumberOfBasisFunctions();
  r.Levels = fitter->GetNumberOfRefinementLevels();
  r.Fits = fitter->GetNumberOfIterations();
  r.MaxError = fitter->GetMaximumError();
  r.RMS = fitter->GetRMSError();
  return r;
}
}

int main(int argc, char* argv[])
{
  std::vector<std::string> tolerances = { "0.02", "0.05", "0.1" };
  std::vector<std::string> scans = {
    "/usr/lib/python3/dist-packages/dipy/data/files/aniso_vox.nii.gz",
    "/usr/lib/python3/dist-packages/dipy/data/files/S0_10slices.nii.gz"
  };
  bool uniform = true;
  splineviz_benchmark::Options options(Usage);
  options.List("--tolerances", tolerances)
    .List("--scans", scans)
    .Add("--uniform", [&](const std::string& v) { uniform = std::atoi(v.c_str()) != 0; });
  const int exitCode = options.Parse(argc, argv);
  if (exitCode >= 0)
  {
    return exitCode;
  }
  std::printf("vtkSMPTools backend %s, %d threads\n", vtkSMPTools::GetBackend(),
    vtkSMPTools::GetEstimatedNumberOfThreads());
  for (const std::string& path : scans)
  {
    vtkNew<vtkNIFTIImageReader> reader;
    reader->SetFileName(path.c_str());
    reader->Update();
    vtkImageData* image = reader->GetOutput();
    int dims[3];
    image->GetDimensions(dims);
    const vtkIdType voxels = image->GetNumberOfPoints();
    if (voxels < 8)
    {
      std::fprintf(stderr, "cannot read %s\n", path.c_str());
      return 1;
    }
    std::printf("\n%s: %d x %d x %d = %lld voxels (%.2f MB as floats)\n", path.c_str(), dims[0],
      dims[1], dims[2], static_cast<long long>(voxels), 4.0 * voxels / 1e6);
    std::printf("%9s | %8s %8s %6s %4s %9s %8s %8s %8s %9s %9s | %8s %9s %7s %7s\n", "tolerance",
      "elements", "function", "levels", "fits", "max err", "RMS", "wall s", "CPU s", "Bezier MB",
      "coef/vox", "uniform", "elements", "wall s", "ratio");
    for (const std::string& t : tolerances)
    {
      const double tolerance = std::atof(t.c_str());
      const Result lr = Fit(image, tolerance, 0);
      std::string m = "-", elements = "-", wall = "-", ratio = "-";
      if (uniform)
      {
        // Bisection for the coarsest m whose uniform spline meets the tolerance.
        // (one element per voxel at the most: knots on voxel faces)
        int lo = 1, hi = std::max(dims[0], std::max(dims[1], dims[2]));
        Result best = Fit(image, tolerance, hi);
        for (int step = 0; hi - lo > 1 && best.Met; ++step)
        {
          const int mid = (lo + hi) / 2;
          const Result r = Fit(image, tolerance, mid);
          if (r.Met)
          {
            hi = mid;
            best = r;
          }
          else
          {
            lo = mid;
          }
        }
        if (best.Met)
        {
          m = std::to_string(hi);
          elements = std::to_string(best.Elements);
          char buffer[64];
          std::snprintf(buffer, sizeof(buffer), "%.2f", best.Wall);
          wall = buffer;
          std::snprintf(buffer, sizeof(buffer), "%.2f", double(best.Elements) / lr.Elements);
          ratio = buffer;
        }
        else
        {
          m = "none";
        }
      }
      std::printf("%8.3g%% | %8lld %8lld %6d %4d %9.4g %8.4g %8.2f %8.2f %9.2f %9.3f | %8s %9s "
                  "%7s %7s%s\n",
        100 * tolerance, static_cast<long long>(lr.Elements), static_cast<long long>(lr.Functions),
        lr.Levels, lr.Fits, lr.MaxError, lr.RMS, lr.Wall, lr.CPU,
        (27 + 6) * 4.0 * lr.Elements / 1e6, double(lr.Functions) / voxels, m.c_str(),
        elements.c_str(), wall.c_str(), ratio.c_str(), lr.Met ? "" : "  (LR: tolerance not met)");
      std::fflush(stdout);
    }
  }
  std::printf("\nuniform: the coarsest tensor-product spline (equal elements, m along the longest\n"
              "direction; same fitter, no refinement) that\n"
              "meets the tolerance (none: not even one element per voxel interval does);\n"
              "ratio = its elements / the LR spline's.\n");
  return 0;
}
