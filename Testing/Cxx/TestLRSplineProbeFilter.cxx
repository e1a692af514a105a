// SPDX-License-Identifier: BSD-3-Clause
// vtkLRSplineProbeFilter and vtkLRSplineResampleToImage: values at the probe
// points equal the brute-force sum over the basis functions (independent
// Cox-de Boor code) for points, a line and a multiblock input; gradients
// match the evaluator's; the valid-point mask is 0 outside the spline; the
// first of overlapping patches wins; a single patch block works as source;
// resampling covers the bounds exactly (last samples on the upper faces) and
// honours sub-extents; the field selected by attribute type gives the same
// values; bad setups (a missing field, a field selected on the wrong port or
// as cell data) give clear errors.
#include "vtkLRSplineProbeFilter.h"
#include "vtkLRSplineReader.h"
#include "vtkLRSplineResampleToImage.h"

#include "LRSplineTestUtilities.h"
#include "SplineVizTestUtilities.h"

#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkExecutive.h"
#include "vtkImageData.h"
#include "vtkLineSource.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkTestErrorObserver.h"
#include "vtkUnstructuredGrid.h"

#include <cmath>
#include <random>

namespace
{
// The reader maps the parameter box [0,1]^3 to [-1,3] x [0,2] x [1,1.5].
const double Bounds[6] = { -1, 3, 0, 2, 1, 1.5 };
void ToParameter(const double x[3], double u[3])
{
  for (int d = 0; d < 3; ++d)
  {
    u[d] = (x[d] - Bounds[2 * d]) / (Bounds[2 * d + 1] - Bounds[2 * d]);
  }
}

// Compare a probed data set with the brute-force value of `patch`.
double WorstError(vtkDataSet* ds, const lrtest::BrutePatch& patch, const char* name, int& invalid)
{
  vtkDataArray* v = ds->GetPointData()->GetArray(name);
  vtkDataArray* mask = ds->GetPointData()->GetArray("vtkValidPointMask");
  invalid = 0;
  if (!v || !mask)
  {
    return 1e300;
  }
  double worst = 0.0;
  for (vtkIdType i = 0; i < ds->GetNumberOfPoints(); ++i)
  {
    double x[3], u[3], ref[3];
    ds->GetPoint(i, x);
    ToParameter(x, u);
    if (mask->GetComponent(i, 0) == 0)
    {
      ++invalid;
      continue;
    }
    // points on the boundary may round outside [0,1]: clamp like the evaluator
    for (double& c : u)
    {
      c = std::min(1.0, std::max(0.0, c));
    }
    lrtest::BruteForce(patch, u, ref);
    for (int c = 0; c < 3; ++c)
    {
      worst = std::max(worst, std::abs(v->GetComponent(i, c) - ref[c]));
    }
  }
  return worst;
}
}

int TestLRSplineProbeFilter(int, char*[])
{
  SplineVizTestStatus status;
  const std::string file = std::string(SPLINEVIZ_EXTERNAL_DATA_DIR) + "/cube-3patch-refined.lr";
  const auto brute = lrtest::ParseLR(lrtest::ReadText(file));
  vtkNew<vtkLRSplineReader> reader;
  reader->SetFileName(file.c_str());
  reader->SetPhysicalBounds(const_cast<double*>(Bounds));
  reader->SetOutputFieldName("velocity");

  //--- Random points (some outside), the whole multiblock as source: patch 0 wins.
  vtkNew<vtkPolyData> cloud;
  {
    vtkNew<vtkPoints> pts;
    std::mt19937 rng(4);
    std::uniform_real_distribution<double> U(-0.1, 1.1);
    for (int i = 0; i < 5000; ++i)
    {
      pts->InsertNextPoint(
        Bounds[0] + U(rng) * 4, Bounds[2] + U(rng) * 2, Bounds[4] + U(rng) * 0.5);
    }
    pts->InsertNextPoint(Bounds[1], Bounds[3], Bounds[5]); // upper corner
    cloud->SetPoints(pts);
  }
  vtkNew<vtkLRSplineProbeFilter> probe;
  probe->SetInputData(cloud);
  probe->SetSourceConnection(reader->GetOutputPort());
  probe->ComputeGradientOn();
  probe->Update();
  auto* out = vtkPolyData::SafeDownCast(probe->GetOutput());
  SV_CHECK(status, out && out->GetNumberOfPoints() == cloud->GetNumberOfPoints());
  int invalid = 0;
  double worst = WorstError(out, brute[0], "velocity", invalid);
  std::cout << "probe: max error " << worst << ", " << invalid << " points outside" << std::endl;
  SV_CHECK_MSG(status, worst < 1e-12, "probe worst " << worst);
  // Exactly the points outside the box are invalid.
  int expectInvalid = 0;
  for (vtkIdType i = 0; i < cloud->GetNumberOfPoints(); ++i)
  {
    double x[3];
    cloud->GetPoint(i, x);
    bool in = true;
    for (int d = 0; d < 3; ++d)
    {
      in = in && x[d] >= Bounds[2 * d] && x[d] <= Bounds[2 * d + 1];
    }
    expectInvalid += in ? 0 : 1;
  }
  SV_CHECK_MSG(status, invalid == expectInvalid, invalid << " vs " << expectInvalid);
  SV_CHECK(status, out->GetPointData()->GetVectors() != nullptr);
  vtkDataArray* grad = out->GetPointData()->GetArray("Gradient");
  SV_CHECK(status, grad && grad->GetNumberOfComponents() == 9);
  // Patch 0 is the identity of the unit cube; in the placed box its Jacobian
  // is diag(1/4, 1/2, 2) (d u / d x).
  if (grad)
  {
    double g[9];
    grad->GetTuple(10, g);
    SV_CHECK_NEAR(status, g[0], 0.25, 1e-12);
    SV_CHECK_NEAR(status, g[4], 0.5, 1e-12);
    SV_CHECK_NEAR(status, g[8], 2.0, 1e-12);
    SV_CHECK_NEAR(status, g[1], 0.0, 1e-12);
  }

  //--- A single patch block as source; a line as input; a multiblock input.
  reader->Update();
  vtkNew<vtkLineSource> line;
  line->SetPoint1(-1, 0, 1);
  line->SetPoint2(3, 2, 1.5);
  line->SetResolution(333);
  vtkNew<vtkLRSplineProbeFilter> probe2;
  probe2->SetInputConnection(line->GetOutputPort());
  probe2->SetSourceData(reader->GetOutput()->GetBlock(2));
  probe2->Update();
  worst = WorstError(vtkDataSet::SafeDownCast(probe2->GetOutput()), brute[2], "velocity", invalid);
  std::cout << "line through patch 2: max error " << worst << ", invalid " << invalid << std::endl;
  SV_CHECK(status, worst < 1e-12 && invalid == 0);

  vtkNew<vtkMultiBlockDataSet> inputs;
  inputs->SetNumberOfBlocks(2);
  inputs->SetBlock(0, cloud);
  line->Update();
  inputs->SetBlock(1, line->GetOutput());
  vtkNew<vtkLRSplineProbeFilter> probe3;
  probe3->SetInputData(inputs);
  probe3->SetSourceConnection(reader->GetOutputPort());
  probe3->Update();
  auto* mbOut = vtkMultiBlockDataSet::SafeDownCast(probe3->GetOutputDataObject(0));
  SV_CHECK(status, mbOut && mbOut->GetNumberOfBlocks() == 2);
  if (mbOut)
  {
    worst = WorstError(vtkDataSet::SafeDownCast(mbOut->GetBlock(1)), brute[0], "velocity", invalid);
    SV_CHECK(status, worst < 1e-12 && invalid == 0);
  }

  //--- Resample to image.
  vtkNew<vtkLRSplineResampleToImage> resample;
  resample->SetInputConnection(reader->GetOutputPort());
  resample->SetSamplingDimensions(9, 7, 5);
  resample->Update();
  vtkImageData* image = resample->GetOutput();
  SV_CHECK(status, image->GetNumberOfPoints() == 9 * 7 * 5);
  worst = WorstError(image, brute[0], "velocity", invalid);
  std::cout << "resample: max error " << worst << ", invalid " << invalid << std::endl;
  SV_CHECK(status, worst < 1e-12);
  SV_CHECK(status, invalid == 0); // the last samples lie on the upper faces, inside
  double ib[6];
  image->GetBounds(ib);
  SV_CHECK_NEAR(status, ib[1], 3.0, 1e-12);
  SV_CHECK_NEAR(status, ib[5], 1.5, 1e-12);
  // explicit, larger bounds: samples outside are masked
  resample->UseInputBoundsOff();
  resample->SetSamplingBounds(-2, 4, 0, 2, 1, 1.5);
  resample->SetSamplingDimensions(13, 3, 3);
  resample->Update();
  worst = WorstError(resample->GetOutput(), brute[0], "velocity", invalid);
  SV_CHECK(status, worst < 1e-12);
  SV_CHECK_MSG(status, invalid == 2 * 2 * 3 * 3, "invalid " << invalid); // x = -2, -1.5, 3.5, 4
  // a sub-extent
  resample->UseInputBoundsOn();
  resample->SetSamplingDimensions(10, 10, 10);
  resample->UpdateExtent(std::array<int, 6>{ 2, 5, 0, 9, 7, 9 }.data());
  SV_CHECK(status, resample->GetOutput()->GetNumberOfPoints() == 4 * 10 * 3);
  worst = WorstError(resample->GetOutput(), brute[0], "velocity", invalid);
  SV_CHECK(status, worst < 1e-12 && invalid == 0);

  //--- The field selected by attribute type (the reader's 3-component field
  // is the active vectors): the same values.
  {
    vtkNew<vtkLRSplineProbeFilter> byType;
    byType->SetInputData(cloud);
    byType->SetSourceConnection(reader->GetOutputPort());
    byType->SetInputArrayToProcess(
      0, 1, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::VECTORS);
    byType->Update();
    worst = WorstError(byType->GetOutput(), brute[0], "velocity", invalid);
    SV_CHECK_MSG(status, worst < 1e-12, "field selected by attribute type: worst " << worst);
  }

  //--- Errors.
  {
    vtkNew<vtkTest::ErrorObserver> obs;
    vtkNew<vtkLRSplineProbeFilter> bad;
    bad->AddObserver(vtkCommand::ErrorEvent, obs);
    bad->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, obs);
    bad->SetInputData(cloud);
    bad->SetSourceConnection(reader->GetOutputPort());
    bad->SetInputArrayToProcess(0, 1, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "nope");
    bad->Update();
    SV_CHECK(
      status, obs->GetError() && obs->GetErrorMessage().find("\"nope\"") != std::string::npos);
    obs->Clear();
    // The field is point data of port 1 (the spline), not of the probed points.
    bad->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "velocity");
    bad->Update();
    SV_CHECK(status, obs->GetError() && obs->GetErrorMessage().find("port 1") != std::string::npos);
    obs->Clear();
    bad->SetInputArrayToProcess(0, 1, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, "velocity");
    bad->Update();
    SV_CHECK(
      status, obs->GetError() && obs->GetErrorMessage().find("point data") != std::string::npos);
    obs->Clear();
    vtkNew<vtkLRSplineReader> geometry;
    geometry->SetFileName(file.c_str());
    geometry->GeometryModeOn();
    bad->SetInputArrayToProcess(
      0, 1, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, ""); // the default field
    bad->SetSourceConnection(geometry->GetOutputPort());
    bad->Update();
    // Geometry mode is evaluated in physical space (by inversion) now.
    SV_CHECK(status, !obs->GetError());
    obs->Clear();
    bad->UseParameterCoordinatesOn();
    bad->Update();
    SV_CHECK(status, !obs->GetError());
    vtkNew<vtkPolyData> notSpline;
    bad->SetSourceData(notSpline);
    bad->Update();
    SV_CHECK(status,
      obs->GetError() && obs->GetErrorMessage().find("vtkLRSplineReader") != std::string::npos);
  }
  return status.Result();
}
