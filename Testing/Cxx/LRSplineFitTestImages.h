// SPDX-License-Identifier: BSD-3-Clause
// Images and checks for the vtkLRSplineImageFitter and vtkLRSplineFitter tests: analytic scalar
// images, the fitter run with its errors and warnings observed, and the
// fitted spline evaluated independently of the fitter (vtkLRSplineField on
// its output grid, in physical coordinates).
#ifndef LRSplineFitTestImages_h
#define LRSplineFitTestImages_h

#include "vtkLRSplineField.h"
#include "vtkLRSplineFitter.h"
#include "vtkLRSplineImageFitter.h"

#include "vtkCommand.h"
#include "vtkDoubleArray.h"
#include "vtkExecutive.h"
#include "vtkImageData.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"
#include "vtkTestErrorObserver.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>

namespace fittest
{
/// An image of f(x) (physical coordinates) in a double point array `name`;
/// its extent starts at `start` (null: 0 0 0).
inline vtkSmartPointer<vtkImageData> MakeImage(const int dims[3], const double spacing[3],
  const double origin[3], const std::function<double(const double x[3])>& f,
  const char* name = "density", const int* start = nullptr)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  const int s[3] = { start ? start[0] : 0, start ? start[1] : 0, start ? start[2] : 0 };
  image->SetExtent(s[0], s[0] + dims[0] - 1, s[1], s[1] + dims[1] - 1, s[2], s[2] + dims[2] - 1);
  image->SetSpacing(spacing[0], spacing[1], spacing[2]);
  image->SetOrigin(origin[0], origin[1], origin[2]);
  vtkNew<vtkDoubleArray> values;
  values->SetName(name);
  values->SetNumberOfTuples(image->GetNumberOfPoints());
  for (vtkIdType i = 0; i < image->GetNumberOfPoints(); ++i)
  {
    double x[3];
    image->GetPoint(i, x);
    values->SetValue(i, f(x));
  }
  image->GetPointData()->SetScalars(values);
  return image;
}

/// Runs a fitter (vtkLRSplineImageFitter, vtkLRSplineFitter) with errors and
/// warnings observed (they are test expectations, not failures of the test run).
template <typename FitterT>
struct FitRunT
{
  vtkNew<FitterT> Fitter;
  vtkNew<vtkTest::ErrorObserver> Observer;
  FitRunT()
  {
    this->Fitter->AddObserver(vtkCommand::ErrorEvent, this->Observer);
    this->Fitter->AddObserver(vtkCommand::WarningEvent, this->Observer);
    this->Fitter->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, this->Observer);
  }
  /// True when the update succeeded without error.
  bool Run(vtkDataObject* input)
  {
    this->Observer->Clear();
    this->Fitter->SetInputData(input);
    this->Fitter->Modified();
    const int ok = this->Fitter->GetExecutive()->Update();
    return ok && !this->Observer->GetError();
  }
  vtkMultiBlockDataSet* Output() { return this->Fitter->GetOutput(); }
  std::string Error() { return this->Observer->GetErrorMessage(); }
  std::string Warning() { return this->Observer->GetWarningMessage(); }
  bool Warned() { return this->Observer->GetWarning() != 0; }
};
using FitRun = FitRunT<vtkLRSplineImageFitter>;

/// Largest |spline - voxel| over the voxels, the spline evaluated from the
/// fitter's output at the voxels' physical positions moved by `shift`
/// (voxels; 0 for the real check, non-zero for a negative control).
inline double VoxelError(
  vtkDataObject* spline, vtkImageData* image, double shift = 0.0, double* rms = nullptr)
{
  vtkLRSplineField field;
  std::string error;
  if (!field.Build(spline, nullptr, 2, nullptr, false, &error))
  {
    return 1e300;
  }
  vtkDataArray* values = image->GetPointData()->GetScalars();
  const double* spacing = image->GetSpacing();
  double worst = 0.0, sum = 0.0;
  for (vtkIdType i = 0; i < image->GetNumberOfPoints(); ++i)
  {
    double x[3], v = 0.0;
    image->GetPoint(i, x);
    for (int d = 0; d < 3; ++d)
    {
      x[d] += shift * spacing[d];
    }
    if (field.Evaluate(x, &v, nullptr) < 0)
    {
      // a shifted point outside the spline: compare with the nearest inside
      double bounds[6];
      field.GetBounds(bounds);
      for (int d = 0; d < 3; ++d)
      {
        x[d] = std::min(bounds[2 * d + 1], std::max(bounds[2 * d], x[d]));
      }
      if (field.Evaluate(x, &v, nullptr) < 0)
      {
        return 1e300;
      }
    }
    const double err = std::abs(v - values->GetComponent(i, 0));
    worst = std::max(worst, err);
    sum += err * err;
  }
  if (rms)
  {
    *rms = std::sqrt(sum / image->GetNumberOfPoints());
  }
  return worst;
}
}

#endif
