// SPDX-License-Identifier: BSD-3-Clause
// Progress, abort, hostile sizes and vtkStreamTracer API parity of the
// SplineViz filters and readers:
//  - progress: every long-running filter and reader (LR-spline resample and
//    probe, both tracers, the tensor analysis, the synthetic fibers, the
//    LR-spline reader) sends vtkCommand::ProgressEvent several times (>= 5
//    for the batched loops), with values that never decrease, ending at 1;
//  - abort: an observer that sets AbortExecute at the first progress event
//    past 20 % stops the run: the output is empty (no points, no arrays),
//    no error is reported, and the next run without abort gives the full
//    output again (the same number of points as a run never aborted). The
//    negative control: an observer that never aborts leaves the output full;
//  - hostile sizes: Resample To Image at 100000^3, a probe of an implicit
//    100000^3 image, 10^9 seeds (an implicit 1000^3 image as the seed source)
//    for both tracers, 10^12 synthetic fiber segments: each fails with an
//    error that says the request is larger than this machine's memory
//    (RequestData returns 0, output empty), and the process goes on; a
//    sensible size right after works;
//  - API parity: vtkLRSplineStreamTracer's SetIntegrationDirectionTo...,
//    SetIntegratorTypeTo..., SetIntegrationStepUnit..., SetStepModeTo...,
//    SetPrecisionTo...; vtkTensorLineTracer's ...To... setters; the
//    documented defaults (BOTH for the LR tracer).
#include "vtkLRSplineProbeFilter.h"
#include "vtkLRSplineReader.h"
#include "vtkLRSplineResampleToImage.h"
#include "vtkLRSplineStreamTracer.h"
#include "vtkSyntheticFibersSource.h"
#include "vtkTensorAnalysisFilter.h"
#include "vtkTensorLineTracer.h"

#include "LRSplineTestFields.h"
#include "SplineVizTestUtilities.h"
#include "TensorLineTestFields.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkDataSet.h"
#include "vtkExecutive.h"
#include "vtkImageData.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPointSource.h"
#include "vtkPolyData.h"
#include "vtkTestErrorObserver.h"

#include <functional>
#include <string>
#include <vector>

namespace
{
const std::string DataDir = SPLINEVIZ_EXTERNAL_DATA_DIR;

/// Records the progress values of an algorithm; optionally aborts it at the
/// first value past AbortAt.
struct ProgressRecorder
{
  std::vector<double> Values;
  double AbortAt = 2.0; // never
  static void Callback(vtkObject* caller, unsigned long, void* clientData, void* callData)
  {
    auto* self = static_cast<ProgressRecorder*>(clientData);
    const double p = *static_cast<double*>(callData);
    self->Values.push_back(p);
    if (p > self->AbortAt)
    {
      static_cast<vtkAlgorithm*>(caller)->AbortExecuteOn();
    }
  }
};

/// Number of points of any output (data set or composite).
vtkIdType CountPoints(vtkDataObject* obj)
{
  if (!obj)
  {
    return -1;
  }
  return obj->GetNumberOfElements(vtkDataObject::POINT);
}

int CountArrays(vtkDataObject* obj)
{
  auto* ds = vtkDataSet::SafeDownCast(obj);
  return ds ? ds->GetPointData()->GetNumberOfArrays() : 0;
}

/// Progress and abort of one algorithm (already set up; Update() runs it).
void CheckProgressAndAbort(
  SplineVizTestStatus& status, const std::string& what, vtkAlgorithm* algorithm, int minEvents)
{
  vtkNew<vtkTest::ErrorObserver> errors;
  algorithm->AddObserver(vtkCommand::ErrorEvent, errors);
  algorithm->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, errors);
  ProgressRecorder recorder;
  vtkNew<vtkCallbackCommand> cb;
  cb->SetCallback(ProgressRecorder::Callback);
  cb->SetClientData(&recorder);
  const unsigned long tag = algorithm->AddObserver(vtkCommand::ProgressEvent, cb);

  // A full run (the negative control of the abort: nothing aborts it).
  algorithm->Modified();
  algorithm->Update();
  const vtkIdType full = CountPoints(algorithm->GetOutputDataObject(0));
  SV_CHECK_MSG(status, full > 0, what << ": the full run gave no points");
  SV_CHECK_MSG(status, static_cast<int>(recorder.Values.size()) >= minEvents,
    what << ": " << recorder.Values.size() << " progress events, expected at least " << minEvents);
  bool monotone = true;
  for (std::size_t i = 1; i < recorder.Values.size(); ++i)
  {
    monotone = monotone && recorder.Values[i] >= recorder.Values[i - 1];
  }
  SV_CHECK_MSG(status, monotone, what << ": the progress decreased");
  SV_CHECK_MSG(status, !recorder.Values.empty() && recorder.Values.back() == 1.0,
    what << ": the last progress is not 1");
  std::cout << what << ": " << recorder.Values.size() << " progress events, " << full << " points"
            << std::endl;

  // Aborted at the first event past 20 %.
  recorder.Values.clear();
  recorder.AbortAt = 0.2;
  algorithm->Modified();
  algorithm->Update();
  const vtkIdType aborted = CountPoints(algorithm->GetOutputDataObject(0));
  SV_CHECK_MSG(status, aborted == 0, what << ": the aborted run gave " << aborted << " points");
  SV_CHECK_MSG(status, CountArrays(algorithm->GetOutputDataObject(0)) == 0,
    what << ": the aborted run left point arrays");
  SV_CHECK_MSG(status, errors->GetErrorMessage().empty(),
    what << ": abort reported an error: " << errors->GetErrorMessage());
  double last = 0.0;
  for (double v : recorder.Values)
  {
    last = v < 1.0 ? std::max(last, v) : last;
  }
  SV_CHECK_MSG(
    status, last < 0.9, what << ": the aborted run went on to progress " << last << " before 1");

  // Recovery: the next run without abort is full again.
  recorder.AbortAt = 2.0;
  algorithm->AbortExecuteOff();
  algorithm->Modified();
  algorithm->Update();
  const vtkIdType again = CountPoints(algorithm->GetOutputDataObject(0));
  SV_CHECK_MSG(
    status, again == full, what << ": after the abort " << again << " points instead of " << full);
  algorithm->RemoveObserver(tag);
}

/// A hostile request: Update fails with an error containing `phrase`, the
/// output is empty.
void CheckRefused(SplineVizTestStatus& status, const std::string& what, vtkAlgorithm* algorithm,
  const std::string& phrase)
{
  vtkNew<vtkTest::ErrorObserver> errors;
  const unsigned long t1 = algorithm->AddObserver(vtkCommand::ErrorEvent, errors);
  const unsigned long t2 = algorithm->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, errors);
  algorithm->Modified();
  const int ok = algorithm->GetExecutive()->Update();
  const std::string message = errors->GetErrorMessage();
  SV_CHECK_MSG(status, ok == 0, what << ": the hostile request did not fail");
  SV_CHECK_MSG(status, message.find(phrase) != std::string::npos,
    what << ": message \"" << message << "\" lacks \"" << phrase << "\"");
  SV_CHECK_MSG(status, CountPoints(algorithm->GetOutputDataObject(0)) <= 0,
    what << ": the refused request left an output");
  const std::size_t at = message.rfind('\n', message.find(phrase));
  std::cout << what << ": "
            << message.substr(at == std::string::npos ? 0 : at + 1,
                 message.find('\n', message.find(phrase)) - (at == std::string::npos ? 0 : at + 1))
            << std::endl;
  algorithm->RemoveObserver(t1);
  algorithm->GetExecutive()->RemoveObserver(t2);
}

vtkSmartPointer<vtkImageData> ImplicitImage(int nx, int ny, int nz)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(nx, ny, nz);
  image->SetOrigin(0.1, 0.1, 0.1);
  image->SetSpacing(0.8 / nx, 0.8 / ny, 0.8 / nz);
  return image;
}
}

int TestSplineVizProgressAbort(int, char*[])
{
  SplineVizTestStatus status;
  const std::string cube = DataDir + "/cube-3patch-refined.lr";

  // The LR-spline reader: progress per patch (3 patches).
  vtkNew<vtkLRSplineReader> reader;
  reader->SetFileName(cube.c_str());
  CheckProgressAndAbort(status, "vtkLRSplineReader", reader, 3);
  reader->Update();

  // Resample To Image, 48^3.
  vtkNew<vtkLRSplineResampleToImage> resample;
  resample->SetInputConnection(reader->GetOutputPort());
  resample->SetSamplingDimensions(48, 48, 48);
  CheckProgressAndAbort(status, "vtkLRSplineResampleToImage", resample, 5);

  // Probe of a 48^3 image.
  vtkNew<vtkLRSplineProbeFilter> probe;
  probe->SetInputData(ImplicitImage(48, 48, 48));
  probe->SetSourceConnection(reader->GetOutputPort());
  CheckProgressAndAbort(status, "vtkLRSplineProbeFilter", probe, 5);

  // The LR-spline stream tracer on a linear field, 200 seeds.
  const double A[9] = { 0, -1, 0, 1, 0, 0, 0, 0, 0.1 };
  const double b[3] = { 0, 0, 0.2 };
  const double focus[3] = { 0.4, 0.4, 0.4 };
  vtkSmartPointer<vtkMultiBlockDataSet> linear =
    lrtest::LinearField(A, b, 2, 3, focus, "TestSplineVizProgressAbort");
  vtkNew<vtkPointSource> seeds;
  seeds->SetCenter(0.5, 0.5, 0.5);
  seeds->SetRadius(0.3);
  seeds->SetNumberOfPoints(200);
  vtkNew<vtkLRSplineStreamTracer> tracer;
  tracer->SetInputData(linear);
  tracer->SetSourceConnection(seeds->GetOutputPort());
  tracer->SetIntegrationStep(0.01);
  CheckProgressAndAbort(status, "vtkLRSplineStreamTracer", tracer, 5);

  // The tensor line tracer on a helix field, seeds at every voxel.
  const int dims[3] = { 24, 24, 24 };
  const double origin[3] = { -1, -1, -1 };
  const double spacing[3] = { 2.0 / 23, 2.0 / 23, 2.0 / 23 };
  vtkSmartPointer<vtkImageData> helix = TensorLineTest::MakeImage(dims, origin, spacing,
    [](const double x[3], double t[6]) { TensorLineTest::HelixFieldTensor(x, 0.5, 0.8, t); });
  vtkNew<vtkTensorLineTracer> tensorLines;
  tensorLines->SetInputData(helix);
  tensorLines->SetSeedModeToVoxels();
  tensorLines->SetSeedStride(4);
  tensorLines->SetSeedFAThreshold(0.0);
  tensorLines->SetStoppingFAThreshold(0.0);
  CheckProgressAndAbort(status, "vtkTensorLineTracer", tensorLines, 5);

  // The tensor analysis of a 48^3 tensor image.
  const int dims64[3] = { 48, 48, 48 };
  const double spacing64[3] = { 2.0 / 47, 2.0 / 47, 2.0 / 47 };
  vtkNew<vtkTensorAnalysisFilter> analysis;
  analysis->SetInputData(TensorLineTest::MakeImage(dims64, origin, spacing64,
    [](const double x[3], double t[6]) { TensorLineTest::HelixFieldTensor(x, 0.5, 0.8, t); }));
  CheckProgressAndAbort(status, "vtkTensorAnalysisFilter", analysis, 5);

  // The synthetic fibers.
  vtkNew<vtkSyntheticFibersSource> fibers;
  fibers->SetNumberOfTubes(2000);
  fibers->SetNumberOfSegments(200000);
  CheckProgressAndAbort(status, "vtkSyntheticFibersSource", fibers, 5);

  // Hostile sizes: refused with a clear message, nothing allocated, the
  // process goes on; a sensible size right after works.
  const std::string memory = "more than this machine's";
  resample->SetSamplingDimensions(100000, 100000, 100000);
  CheckRefused(status, "Resample To Image at 100000^3", resample, memory);
  resample->SetSamplingDimensions(8, 8, 8);
  resample->Update();
  SV_CHECK(status, resample->GetOutput()->GetNumberOfPoints() == 512);

  probe->SetInputData(ImplicitImage(100000, 100000, 100000));
  CheckRefused(status, "probe of a 100000^3 image", probe, memory);

  tracer->SetSourceData(ImplicitImage(1000, 1000, 1000));
  CheckRefused(status, "LR-spline streamlines from 10^9 seeds", tracer, memory);
  tracer->SetSourceConnection(seeds->GetOutputPort());
  tracer->Update();
  SV_CHECK(status, tracer->GetOutput()->GetNumberOfPoints() > 0);

  tensorLines->SetSeedModeToSource();
  tensorLines->SetSourceData(ImplicitImage(1000, 1000, 1000));
  CheckRefused(status, "tensor lines from 10^9 seeds", tensorLines, memory);

  fibers->SetNumberOfSegments(1000000000000LL);
  CheckRefused(status, "10^12 synthetic fiber segments", fibers, memory);

  // vtkStreamTracer's setters and the documented defaults.
  vtkNew<vtkLRSplineStreamTracer> t;
  SV_CHECK(status, t->GetIntegrationDirection() == vtkLRSplineStreamTracer::BOTH);
  t->SetIntegrationDirectionToForward();
  SV_CHECK(status, t->GetIntegrationDirection() == vtkLRSplineStreamTracer::FORWARD);
  t->SetIntegrationDirectionToBackward();
  SV_CHECK(status, t->GetIntegrationDirection() == vtkLRSplineStreamTracer::BACKWARD);
  t->SetIntegrationDirectionToBoth();
  SV_CHECK(status, t->GetIntegrationDirection() == vtkLRSplineStreamTracer::BOTH);
  SV_CHECK(status, t->GetIntegratorType() == vtkLRSplineStreamTracer::RUNGE_KUTTA4);
  t->SetIntegratorTypeToRungeKutta2();
  SV_CHECK(status, t->GetIntegratorType() == vtkLRSplineStreamTracer::MIDPOINT);
  t->SetIntegratorTypeToRungeKutta45();
  SV_CHECK(status, t->GetIntegratorType() == vtkLRSplineStreamTracer::RKF45);
  t->SetIntegratorTypeToEuler();
  SV_CHECK(status, t->GetIntegratorType() == vtkLRSplineStreamTracer::EULER);
  t->SetIntegratorTypeToBogackiShampine();
  SV_CHECK(status, t->GetIntegratorType() == vtkLRSplineStreamTracer::BOGACKI_SHAMPINE);
  t->SetIntegratorTypeToRungeKutta4();
  SV_CHECK(status, t->GetIntegratorType() == vtkLRSplineStreamTracer::RUNGE_KUTTA4);
  SV_CHECK(status, t->GetIntegrationStepUnit() == vtkLRSplineStreamTracer::LENGTH_UNIT);
  t->SetIntegrationStepUnit(vtkLRSplineStreamTracer::CELL_LENGTH_UNIT);
  SV_CHECK(status, t->GetStepMode() == vtkLRSplineStreamTracer::LR_HEURISTIC);
  SV_CHECK(status, t->GetIntegrationStepUnit() == vtkLRSplineStreamTracer::CELL_LENGTH_UNIT);
  t->SetIntegrationStepUnitToLengthUnit();
  SV_CHECK(status, t->GetStepMode() == vtkLRSplineStreamTracer::FIXED_LENGTH);
  t->SetStepModeToAdaptive();
  SV_CHECK(status, t->GetStepMode() == vtkLRSplineStreamTracer::ADAPTIVE);
  SV_CHECK(status, t->GetIntegrationStepUnit() == 0);
  t->SetPrecisionToMixed();
  SV_CHECK(status, t->GetPrecision() == vtkLRSplineStreamTracer::MIXED_PRECISION);

  vtkNew<vtkTensorLineTracer> tt;
  tt->SetIntegratorTypeToRungeKutta2();
  SV_CHECK(status, tt->GetIntegratorType() == vtkTensorLineTracer::RUNGE_KUTTA2);
  tt->SetIntegratorTypeToRungeKutta4();
  SV_CHECK(status, tt->GetIntegratorType() == vtkTensorLineTracer::RUNGE_KUTTA4);
  tt->SetIntegrationStepUnitToLengthUnit();
  SV_CHECK(status, tt->GetIntegrationStepUnit() == vtkTensorLineTracer::LENGTH_UNIT);
  tt->SetIntegrationStepUnitToCellLengthUnit();
  SV_CHECK(status, tt->GetIntegrationStepUnit() == vtkTensorLineTracer::CELL_LENGTH_UNIT);
  tt->SetInterpolationToLogEuclidean();
  SV_CHECK(status, tt->GetInterpolation() == vtkTensorLineTracer::LOG_EUCLIDEAN_INTERPOLATION);
  tt->SetNegativeEigenvaluesToAbsolute();
  SV_CHECK(
    status, tt->GetNegativeEigenvalues() == vtkTensorLineTracer::NEGATIVE_EIGENVALUES_ABSOLUTE);
  tt->SetSeedModeToVoxels();
  SV_CHECK(status, tt->GetSeedMode() == vtkTensorLineTracer::SEEDS_FROM_VOXELS);
  tt->SetOutputPointsPrecisionToDouble();
  SV_CHECK(status, tt->GetOutputPointsPrecision() == vtkAlgorithm::DOUBLE_PRECISION);
  return status.Result();
}
