// SPDX-License-Identifier: BSD-3-Clause
// Data and checks for the vtkLRSplineImageFitter and vtkLRSplineFitter tests: analytic scalar
// images and point clouds, a smooth field with a narrow bump, the fitter run
// with its errors and warnings observed, and the fitted spline evaluated
// independently of the fitter (vtkLRSplineField on its output grid, in
// physical coordinates).
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
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkTestErrorObserver.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
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

// A point cloud (polydata without cells) with a `comps`-component array.
inline vtkSmartPointer<vtkPolyData> Cloud(
  const std::vector<double>& x, const std::vector<double>& v, int comps = 1)
{
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  const vtkIdType n = static_cast<vtkIdType>(x.size() / 3);
  points->SetNumberOfPoints(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    points->SetPoint(i, &x[3 * i]);
  }
  pd->SetPoints(points);
  vtkNew<vtkDoubleArray> a;
  a->SetName("f");
  a->SetNumberOfComponents(comps);
  a->SetNumberOfTuples(n);
  std::copy(v.begin(), v.end(), a->GetPointer(0));
  pd->GetPointData()->SetScalars(a);
  return pd;
}

// Largest |spline - v| (length of the difference for vectors) at the points,
// the spline evaluated from an output with vtkLRSplineField.
inline double PointError(vtkDataObject* spline, const std::vector<double>& x,
  const std::vector<double>& v, int comps = 1, double* rms = nullptr)
{
  vtkLRSplineField field;
  std::string error;
  if (!field.Build(spline, nullptr, 2, nullptr, false, &error))
  {
    std::cerr << "vtkLRSplineField: " << error << std::endl;
    return 1e300;
  }
  double worst = 0.0, sum = 0.0;
  const std::size_t n = x.size() / 3;
  std::vector<double> s(comps);
  for (std::size_t i = 0; i < n; ++i)
  {
    if (field.Evaluate(&x[3 * i], s.data(), nullptr) < 0)
    {
      return 1e300;
    }
    double e2 = 0.0;
    for (int c = 0; c < comps; ++c)
    {
      e2 += (s[c] - v[comps * i + c]) * (s[c] - v[comps * i + c]);
    }
    worst = std::max(worst, std::sqrt(e2));
    sum += e2;
  }
  if (rms)
  {
    *rms = std::sqrt(sum / n);
  }
  return worst;
}

// A smooth field with a narrow Gaussian bump at C (width S).
constexpr double C[3] = { 0.6, 0.4, 0.5 };
constexpr double S = 0.05;
inline double Smooth(const double x[3])
{
  return std::sin(2 * x[0]) + x[1] * x[2];
}
inline double Bump(const double x[3])
{
  const double r2 =
    (x[0] - C[0]) * (x[0] - C[0]) + (x[1] - C[1]) * (x[1] - C[1]) + (x[2] - C[2]) * (x[2] - C[2]);
  return Smooth(x) + std::exp(-r2 / (2 * S * S));
}
}

#endif
