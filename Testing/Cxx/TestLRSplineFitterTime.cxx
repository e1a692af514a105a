// SPDX-License-Identifier: BSD-3-Clause
// vtkLRSplineFitter on a transient field (its time series): a source with
// four time steps of scattered points whose field keeps a sharp bump and
// grows (f = (1 + t/4) exp(-|x - c|^2 / 0.03) + 0.2 t x):
//  - the input's time steps reach the output; each requested step is the
//    output's DATA_TIME_STEP;
//  - every step meets its tolerance at every data point, evaluated here
//    against the analytic field;
//  - ReusePreviousMesh: steps after the first start from the previous
//    step's mesh, need fewer fit-and-refine rounds than a fresh fit of the
//    same step (measured: total fit time printed), and their meshes only
//    gain elements;
//  - negative controls: with ReusePreviousMesh off, after a property
//    change, for the same time step again, and when the domain moves (the
//    points drift with time), nothing is reused.
#include "vtkLRSplineArrayNames.h"
#include "vtkLRSplineField.h"
#include "vtkLRSplineFitter.h"

#include "SplineVizTestUtilities.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataAlgorithm.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <cmath>
#include <iostream>
#include <vector>

namespace
{
const double Steps[4] = { 0.0, 0.5, 1.0, 1.5 };

double Field(const double x[3], double t)
{
  const double dx = x[0] - 0.6, dy = x[1] - 0.5, dz = x[2] - 0.5;
  return (1.0 + 0.25 * t) * std::exp(-(dx * dx + dy * dy + dz * dz) / 0.03) + 0.2 * t * x[0];
}

// Where point p (fixed random base position) is at time t: still, or (Moving)
// stretched along x by 1 + 0.1 t, which changes the domain.
void Position(const double base[3], double t, bool moving, double x[3])
{
  x[0] = base[0] * (moving ? 1.0 + 0.1 * t : 1.0);
  x[1] = base[1];
  x[2] = base[2];
}
}

// A time-dependent point cloud with point data "f" = Field(x, t).
class TransientPointSource : public vtkPolyDataAlgorithm
{
public:
  static TransientPointSource* New();
  vtkTypeMacro(TransientPointSource, vtkPolyDataAlgorithm);
  vtkSetMacro(Moving, bool);

protected:
  TransientPointSource()
  {
    this->SetNumberOfInputPorts(0);
    vtkNew<vtkMinimalStandardRandomSequence> random;
    random->SetSeed(30);
    for (int p = 0; p < 4000; ++p)
    {
      const double scale[3] = { 2.0, 1.0, 1.0 };
      for (int d = 0; d < 3; ++d)
      {
        this->Base.push_back(scale[d] * random->GetNextValue());
      }
    }
  }

  int RequestInformation(
    vtkInformation*, vtkInformationVector**, vtkInformationVector* out) override
  {
    vtkInformation* info = out->GetInformationObject(0);
    info->Set(vtkStreamingDemandDrivenPipeline::TIME_STEPS(), Steps, 4);
    const double range[2] = { Steps[0], Steps[3] };
    info->Set(vtkStreamingDemandDrivenPipeline::TIME_RANGE(), range, 2);
    return 1;
  }

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector* out) override
  {
    vtkInformation* info = out->GetInformationObject(0);
    vtkPolyData* output = vtkPolyData::GetData(out);
    double t = Steps[0];
    if (info->Has(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP()))
    {
      t = info->Get(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP());
    }
    const vtkIdType n = static_cast<vtkIdType>(this->Base.size() / 3);
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    points->SetNumberOfPoints(n);
    vtkNew<vtkDoubleArray> f;
    f->SetName("f");
    f->SetNumberOfTuples(n);
    for (vtkIdType p = 0; p < n; ++p)
    {
      double x[3];
      Position(&this->Base[3 * p], t, this->Moving, x);
      points->SetPoint(p, x);
      f->SetValue(p, Field(x, t));
    }
    output->SetPoints(points);
    output->GetPointData()->AddArray(f);
    output->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(), t);
    return 1;
  }

  std::vector<double> Base;
  bool Moving = false;

private:
  TransientPointSource(const TransientPointSource&) = delete;
  void operator=(const TransientPointSource&) = delete;
};
vtkStandardNewMacro(TransientPointSource);

namespace
{
// Largest |spline - Field(., t)| over the source's points at time t.
double FitError(vtkDataObject* spline, TransientPointSource* source, double t)
{
  vtkLRSplineField field;
  std::string error;
  if (!field.Build(spline, nullptr, 2, nullptr, false, &error))
  {
    std::cerr << "cannot build the field: " << error << std::endl;
    return 1e300;
  }
  source->UpdateTimeStep(t);
  vtkPolyData* points = source->GetOutput();
  double worst = 0.0;
  for (vtkIdType p = 0; p < points->GetNumberOfPoints(); ++p)
  {
    double x[3], s = 0.0;
    points->GetPoint(p, x);
    if (field.Evaluate(x, &s, nullptr) < 0)
    {
      return 1e300;
    }
    worst = std::max(worst, std::abs(s - Field(x, t)));
  }
  return worst;
}

void Configure(vtkLRSplineFitter* fitter, TransientPointSource* source)
{
  fitter->SetInputConnection(source->GetOutputPort());
  fitter->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "f");
  fitter->SetTolerance(0.01);
  fitter->ExtractBoundaryOff();
}
}

int TestLRSplineFitterTime(int, char*[])
{
  SplineVizTestStatus status;
  vtkNew<TransientPointSource> source;
  vtkNew<TransientPointSource> probe; // the reference field's points, separately
  vtkNew<vtkLRSplineFitter> reuse;
  vtkNew<vtkLRSplineFitter> fresh;
  Configure(reuse, source);
  Configure(fresh, source);
  fresh->ReusePreviousMeshOff();

  // The time steps pass through.
  reuse->UpdateInformation();
  vtkInformation* outInfo = reuse->GetOutputInformation(0);
  SV_CHECK(status, outInfo->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS()) == 4);

  double reuseSeconds = 0.0, freshSeconds = 0.0;
  int reuseRounds = 0, freshRounds = 0;
  vtkIdType previousElements = 0;
  for (int k = 0; k < 4; ++k)
  {
    const double t = Steps[k];
    SV_CHECK(status, reuse->UpdateTimeStep(t));
    SV_CHECK(status, fresh->UpdateTimeStep(t));
    vtkDataObject* out = reuse->GetOutputDataObject(0);
    SV_CHECK(status,
      out->GetInformation()->Has(vtkDataObject::DATA_TIME_STEP()) &&
        out->GetInformation()->Get(vtkDataObject::DATA_TIME_STEP()) == t);
    const double error = FitError(out, probe, t);
    const double freshError = FitError(fresh->GetOutputDataObject(0), probe, t);
    std::cout << "t = " << t << ": reused " << reuse->GetReusedPreviousMesh() << ", "
              << reuse->GetNumberOfIterations() << " rounds, " << reuse->GetNumberOfElements()
              << " elements, " << reuse->GetFitTime() << " s, error " << error << " (tolerance "
              << reuse->GetAbsoluteTolerance() << "); fresh: " << fresh->GetNumberOfIterations()
              << " rounds, " << fresh->GetNumberOfElements() << " elements, " << fresh->GetFitTime()
              << " s, error " << freshError << std::endl;
    SV_CHECK(status, reuse->GetToleranceMet() && fresh->GetToleranceMet());
    SV_CHECK_MSG(status, error <= reuse->GetAbsoluteTolerance() * (1 + 1e-9), error);
    SV_CHECK_MSG(status, freshError <= fresh->GetAbsoluteTolerance() * (1 + 1e-9), freshError);
    SV_CHECK(status, reuse->GetReusedPreviousMesh() == (k > 0));
    SV_CHECK(status, !fresh->GetReusedPreviousMesh());
    SV_CHECK(status, reuse->GetNumberOfElements() >= previousElements);
    previousElements = reuse->GetNumberOfElements();
    if (k > 0)
    {
      reuseSeconds += reuse->GetFitTime();
      freshSeconds += fresh->GetFitTime();
      reuseRounds += reuse->GetNumberOfIterations();
      freshRounds += fresh->GetNumberOfIterations();
    }
  }
  std::cout << "steps 2-4: " << reuseRounds << " rounds, " << reuseSeconds
            << " s with the previous mesh; " << freshRounds << " rounds, " << freshSeconds
            << " s fresh" << std::endl;
  SV_CHECK_MSG(status, reuseRounds < freshRounds, reuseRounds << " vs " << freshRounds);

  // The field data says so.
  {
    reuse->UpdateTimeStep(Steps[0]);
    auto* block = vtkMultiBlockDataSet::SafeDownCast(reuse->GetOutputDataObject(0))->GetBlock(0);
    vtkDataArray* flag =
      block->GetFieldData()->GetArray(vtkLRSplineArrayNames::FitReusedPreviousMesh);
    SV_CHECK(status, flag && flag->GetTuple1(0) == 1);
  }
  // Negative controls: the same step again (a re-execution forced by the
  // source), a property change, a moving domain.
  source->Modified();
  reuse->UpdateTimeStep(Steps[0]);
  SV_CHECK(status, !reuse->GetReusedPreviousMesh());
  reuse->SetTolerance(0.02);
  reuse->UpdateTimeStep(Steps[1]);
  SV_CHECK(status, !reuse->GetReusedPreviousMesh());
  reuse->UpdateTimeStep(Steps[2]);
  SV_CHECK(status, reuse->GetReusedPreviousMesh());
  source->SetMoving(true);
  reuse->UpdateTimeStep(Steps[3]);
  SV_CHECK(status, !reuse->GetReusedPreviousMesh());
  probe->SetMoving(true);
  const double movingError = FitError(reuse->GetOutputDataObject(0), probe, Steps[3]);
  SV_CHECK_MSG(status, movingError <= reuse->GetAbsoluteTolerance() * (1 + 1e-9), movingError);
  return status.Result();
}
