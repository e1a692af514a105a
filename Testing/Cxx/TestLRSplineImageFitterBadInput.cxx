// SPDX-License-Identifier: BSD-3-Clause
// vtkLRSplineImageFitter on bad input and at its limits. Every bad case must
// fail with a clear message (RequestData returns 0, an error names the
// problem) and an empty output, never crash or hang: Tolerance <= 0 or NaN,
// degrees outside 1..5, no initial elements, MaximumRefinementLevels outside
// 0..30, MaximumNumberOfElements below 1, a NaN or an infinite voxel, a
// 1-voxel-thick image, no scalars, an unknown array name, a 3-component
// array, a cell-data array, a huge image (refused before anything is
// allocated: the image has no array at all), a rotated image (direction
// matrix), zero spacing, a composite input with a polydata block, an empty
// composite, an unwritable FileName. Limits: MaximumNumberOfElements and
// MaximumRefinementLevels stop the refinement with a warning naming the
// limit and the error reached (the output is still the best spline), and an
// abort requested from a progress observer stops after the first fit.
#include "vtkLRSplineImageFitter.h"

#include "LRSplineFitTestImages.h"
#include "SplineVizTestUtilities.h"

#include "vtkCallbackCommand.h"
#include "vtkCellData.h"
#include "vtkMatrix3x3.h"
#include "vtkPolyData.h"

#include <chrono>
#include <iostream>
#include <limits>

namespace
{
using fittest::FitRun;
using fittest::MakeImage;

double Smooth(const double x[3])
{
  return std::sin(0.3 * x[0]) + std::cos(0.2 * x[1]) * x[2] + std::exp(-0.5 * x[0] * x[0]);
}

vtkSmartPointer<vtkImageData> Good()
{
  const int dims[3] = { 12, 11, 10 };
  const double spacing[3] = { 1, 1, 1 }, origin[3] = { -4, -4, 0 };
  return MakeImage(dims, spacing, origin, Smooth);
}

void Expect(SplineVizTestStatus& status, const std::string& what, FitRun& run, vtkDataObject* input,
  const std::string& text)
{
  const auto t0 = std::chrono::steady_clock::now();
  const bool ok = run.Run(input);
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const std::string message = run.Error();
  SV_CHECK_MSG(status, !ok, what << ": the update did not fail");
  SV_CHECK_MSG(status, message.find(text) != std::string::npos,
    what << ": message \"" << message << "\" lacks \"" << text << "\"");
  SV_CHECK_MSG(status, run.Output()->GetNumberOfBlocks() == 0, what << ": output not empty");
  SV_CHECK_MSG(status, seconds < 5.0, what << ": took " << seconds << " s");
  // the fitter's own line (the observer also collects the executive's report)
  const std::size_t at = message.find("vtkLRSplineImageFitter (");
  const std::size_t from = at == std::string::npos ? 0 : message.find("): ", at) + 3;
  std::cout << what << ": " << message.substr(from, message.find('\n', from) - from) << std::endl;
}

std::string FirstLine(const std::string& message)
{
  const std::size_t at = message.find("): ");
  const std::size_t from = at == std::string::npos ? 0 : at + 3;
  return message.substr(from, message.find('\n', from) - from);
}
}

int TestLRSplineImageFitterBadInput(int, char*[])
{
  SplineVizTestStatus status;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();

  // The settings.
  {
    FitRun run;
    run.Fitter->SetTolerance(0.0);
    Expect(status, "tolerance 0", run, Good(), "Tolerance must be positive");
    run.Fitter->SetTolerance(-1.0);
    Expect(status, "negative tolerance", run, Good(), "Tolerance must be positive");
    run.Fitter->SetTolerance(nan);
    Expect(status, "NaN tolerance", run, Good(), "Tolerance must be positive");
  }
  {
    FitRun run;
    run.Fitter->SetDegree(2, 0, 2);
    Expect(status, "degree 0", run, Good(), "Degree must be 1 to 5");
    run.Fitter->SetDegree(2, 2, 6);
    Expect(status, "degree 6", run, Good(), "Degree must be 1 to 5");
  }
  {
    FitRun run;
    run.Fitter->SetInitialNumberOfElements(4, 0, 4);
    Expect(status, "no initial elements", run, Good(), "InitialNumberOfElements");
  }
  {
    FitRun run;
    run.Fitter->SetMaximumRefinementLevels(31);
    Expect(status, "31 levels", run, Good(), "MaximumRefinementLevels must be 0 to 30");
    run.Fitter->SetMaximumRefinementLevels(-1);
    Expect(status, "-1 levels", run, Good(), "MaximumRefinementLevels must be 0 to 30");
    run.Fitter->SetMaximumRefinementLevels(10);
    run.Fitter->SetMaximumNumberOfElements(0);
    Expect(
      status, "no elements allowed", run, Good(), "MaximumNumberOfElements must be at least 1");
  }

  // The voxels.
  for (double bad : { nan, inf, -inf })
  {
    auto image = Good();
    vtkDataArray* scalars = image->GetPointData()->GetScalars();
    scalars->SetComponent(scalars->GetNumberOfTuples() / 2, 0, bad);
    FitRun run;
    Expect(status, "a voxel " + std::to_string(bad), run, image, "NaN or infinite");
  }
  {
    const int dims[3] = { 20, 20, 1 };
    const double spacing[3] = { 1, 1, 1 }, origin[3] = { 0, 0, 0 };
    FitRun run;
    Expect(status, "one voxel thick", run, MakeImage(dims, spacing, origin, Smooth),
      "at least 2 voxels in every direction");
  }
  {
    auto image = Good();
    image->GetPointData()->Initialize();
    FitRun run;
    Expect(status, "no scalars", run, image, "no point-data array");
  }
  {
    FitRun run;
    run.Fitter->SetInputArrayToProcess(
      0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "no such array");
    Expect(status, "unknown array", run, Good(), "no array \"no such array\"");
  }
  {
    auto image = Good();
    vtkNew<vtkDoubleArray> vectors;
    vectors->SetName("velocity");
    vectors->SetNumberOfComponents(3);
    vectors->SetNumberOfTuples(image->GetNumberOfPoints());
    vectors->Fill(1.0);
    image->GetPointData()->SetScalars(vectors);
    FitRun run;
    Expect(status, "3 components", run, image, "has 3 components");
  }
  {
    auto image = Good();
    vtkNew<vtkDoubleArray> cells;
    cells->SetName("cellvalues");
    cells->SetNumberOfTuples(image->GetNumberOfCells());
    cells->Fill(2.0);
    image->GetCellData()->AddArray(cells);
    FitRun run;
    run.Fitter->SetInputArrayToProcess(
      0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, "cellvalues");
    Expect(status, "cell data", run, image, "not point data");
  }
  {
    // 2^30 voxels, declared only: refused before any allocation.
    vtkNew<vtkImageData> huge;
    huge->SetExtent(0, 1023, 0, 1023, 0, 1023);
    FitRun run;
    Expect(status, "huge image", run, huge, "too large");
  }
  {
    auto image = Good();
    const double rotation[9] = { 0, -1, 0, 1, 0, 0, 0, 0, 1 };
    image->SetDirectionMatrix(rotation);
    FitRun run;
    Expect(status, "rotated image", run, image, "non-identity direction matrix");
  }
  {
    auto image = Good();
    image->SetSpacing(1, 0, 1);
    FitRun run;
    Expect(status, "zero spacing", run, image, "spacing must be positive");
  }
  {
    vtkNew<vtkMultiBlockDataSet> mixed;
    mixed->SetBlock(0, Good());
    vtkNew<vtkPolyData> poly;
    mixed->SetBlock(1, poly);
    FitRun run;
    Expect(status, "composite with polydata", run, mixed, "must be a vtkImageData");
    vtkNew<vtkMultiBlockDataSet> empty;
    Expect(status, "empty composite", run, empty, "no input image");
  }
  {
    FitRun run;
    run.Fitter->SetFileName("/nonexistent-folder/fit.lr");
    Expect(status, "unwritable file", run, Good(), "cannot write");
  }

  // Limits: a warning naming the limit, and the best spline so far.
  {
    FitRun run;
    run.Fitter->SetTolerance(1e-6);
    run.Fitter->SetMaximumNumberOfElements(200);
    const bool ok = run.Run(Good());
    SV_CHECK(status, ok && run.Output()->GetNumberOfBlocks() == 1);
    SV_CHECK_MSG(status,
      run.Warning().find("MaximumNumberOfElements (200) was reached") != std::string::npos,
      run.Warning());
    SV_CHECK(status, !run.Fitter->GetToleranceMet() && run.Fitter->GetNumberOfElements() <= 200);
    std::cout << "element limit: " << FirstLine(run.Warning()) << std::endl;
    run.Fitter->SetMaximumNumberOfElements(1000000);
    run.Fitter->SetMaximumRefinementLevels(1);
    SV_CHECK(status, run.Run(Good()) && run.Fitter->GetNumberOfRefinementLevels() <= 1);
    SV_CHECK_MSG(status, run.Warning().find("MaximumRefinementLevels (1)") != std::string::npos,
      run.Warning());
    std::cout << "level limit: " << FirstLine(run.Warning()) << std::endl;
  }
  {
    // An abort from a progress observer: the loop stops after the first fit.
    FitRun run;
    run.Fitter->SetTolerance(1e-9);
    vtkNew<vtkCallbackCommand> abort;
    abort->SetCallback([](vtkObject* caller, unsigned long, void*, void*)
      { vtkAlgorithm::SafeDownCast(caller)->SetAbortExecute(1); });
    run.Fitter->AddObserver(vtkCommand::ProgressEvent, abort);
    const auto t0 = std::chrono::steady_clock::now();
    run.Run(Good());
    const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    SV_CHECK_MSG(status, run.Fitter->GetNumberOfIterations() == 1,
      "aborted after " << run.Fitter->GetNumberOfIterations() << " fits");
    SV_CHECK(status, seconds < 5.0);
    std::cout << "abort: stopped after " << run.Fitter->GetNumberOfIterations() << " fit"
              << std::endl;
  }
  return status.Result();
}
