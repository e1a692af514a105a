// SPDX-License-Identifier: BSD-3-Clause
// Stopping criteria and bad input of vtkTensorLineTracer, each triggered by
// a constructed field whose stopping place is known:
//  - FA: l1 linear in x (trilinear interpolation exact), the line ends
//    where the next step would cross the FA threshold (computed here);
//  - turning angle: logarithmic spirals (curvature grows inwards), the line
//    stops where h * curvature reaches the maximum angle, and every turn
//    between consecutive steps respects it;
//  - domain, mask (0/1 mask: the boundary halfway between voxels), maximum
//    length (exact for a straight line), maximum number of steps, minimum
//    length filter;
//  - negative eigenvalues (stop, or absolute values), NaN tensors, zero
//    tensors (low FA, or no direction with a zero threshold);
//  - bad input: empty seeds, missing source, missing/cell/wrong-size tensor
//    arrays, layout mismatch, bad mask (missing, named "None" but missing,
//    cell data, 3 components), bad step, empty input: clear messages, no
//    crash; a point array named "None" is a mask like any other, an empty
//    name no mask.
#include "vtkTensorLineTracer.h"

#include "vtkSplineVizTensorMath.h"

#include "SplineVizTestUtilities.h"
#include "TensorLineTestFields.h"

#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDataSetAttributes.h"
#include "vtkDoubleArray.h"
#include "vtkExecutive.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkTestErrorObserver.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

namespace TM = vtkSplineVizTensorMath;
using namespace TensorLineTest;

namespace
{
// FA from eigenvalues, the textbook formula.
double FA(double l1, double l2, double l3)
{
  const double m = (l1 + l2 + l3) / 3.0;
  const double num = (l1 - m) * (l1 - m) + (l2 - m) * (l2 - m) + (l3 - m) * (l3 - m);
  const double den = l1 * l1 + l2 * l2 + l3 * l3;
  return den > 0 ? std::sqrt(1.5 * num / den) : 0.0;
}

struct Run
{
  vtkNew<vtkTensorLineTracer> Tracer;
  vtkNew<vtkTest::ErrorObserver> Observer;
  std::vector<TracedLine> Lines;
  int Result = 0;

  Run(vtkDataObject* field, const std::vector<Vec3>& seeds, double step,
    const std::function<void(vtkTensorLineTracer*)>& configure = nullptr)
  {
    this->Tracer->SetInputData(field);
    this->Tracer->SetSourceData(MakeSeeds(seeds));
    this->Tracer->SetIntegrationStepUnit(vtkTensorLineTracer::LENGTH_UNIT);
    this->Tracer->SetIntegrationStep(step);
    this->Tracer->SetStoppingFAThreshold(0.0);
    this->Tracer->SetMaximumAngle(90.0);
    if (configure)
    {
      configure(this->Tracer);
    }
    this->Tracer->AddObserver(vtkCommand::ErrorEvent, this->Observer);
    this->Tracer->AddObserver(vtkCommand::WarningEvent, this->Observer);
    this->Tracer->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, this->Observer);
    this->Result = this->Tracer->GetExecutive()->Update();
    this->Lines = GetLines(this->Tracer->GetOutput());
  }
};

// The end of a line with the larger (or smaller) coordinate `axis`: its
// point and its reason.
Vec3 End(const TracedLine& l, int axis, bool larger, int& reason)
{
  const bool lastIsLarger = l.Points.back()[axis] > l.Points.front()[axis];
  const bool last = lastIsLarger == larger;
  reason = l.Reasons[last ? 1 : 0];
  return last ? l.Points.back() : l.Points.front();
}

vtkSmartPointer<vtkImageData> Diagonal(const int dims[3], const double origin[3], double spacing,
  const std::function<void(const double x[3], double l[3])>& eigenvalues)
{
  const double sp[3] = { spacing, spacing, spacing };
  return MakeImage(dims, origin, sp,
    [&](const double x[3], double t[6])
    {
      double l[3];
      eigenvalues(x, l);
      t[0] = l[0];
      t[1] = l[1];
      t[2] = l[2];
      t[3] = t[4] = t[5] = 0.0;
    });
}

void TestFA(SplineVizTestStatus& status)
{
  // l1 = 2 - x, l2 = l3 = 0.5 along x in [0, 2]: FA decreases with x.
  const int dims[3] = { 21, 3, 3 };
  const double origin[3] = { 0, -0.1, -0.1 };
  auto img = Diagonal(dims, origin, 0.1,
    [](const double x[3], double l[3])
    {
      l[0] = 2.0 - x[0];
      l[1] = l[2] = 0.5;
    });
  const double threshold = 0.4, h = 0.03;
  Run run(img, { { 0.2, 0.0, 0.0 } }, h,
    [&](vtkTensorLineTracer* t) { t->SetStoppingFAThreshold(threshold); });
  SV_CHECK(status, run.Lines.size() == 1);
  if (run.Lines.empty())
  {
    return;
  }
  const TracedLine& l = run.Lines[0];
  int reason;
  const Vec3 end = End(l, 0, true, reason);
  SV_CHECK(status, reason == vtkTensorLineTracer::LOW_ANISOTROPY);
  // the crossing x_c with FA(x_c) = threshold, by bisection of the formula
  double lo = 0.0, hi = 2.0;
  for (int i = 0; i < 100; ++i)
  {
    const double mid = 0.5 * (lo + hi);
    (FA(2.0 - mid, 0.5, 0.5) >= threshold ? lo : hi) = mid;
  }
  std::cout << "FA stop: last point x = " << end[0] << ", FA threshold crossed at " << lo
            << std::endl;
  SV_CHECK(status, end[0] <= lo && end[0] + h > lo);
  for (std::size_t i = 0; i < l.FA.size(); ++i)
  {
    SV_CHECK(status, l.FA[i] >= threshold);
    SV_CHECK_NEAR(status, l.FA[i], FA(2.0 - l.Points[i][0], 0.5, 0.5), 1e-12);
  }
  const Vec3 start = End(l, 0, false, reason);
  SV_CHECK(status, reason == vtkTensorLineTracer::OUT_OF_DOMAIN && start[0] < h);

  // a seed below the threshold gives no line
  Run low(img, { { 1.4, 0.0, 0.0 } }, h,
    [&](vtkTensorLineTracer* t) { t->SetStoppingFAThreshold(threshold); });
  SV_CHECK(status, low.Lines.empty());
  SV_CHECK(status, low.Tracer->GetNumberOfRejectedSeeds() == 1);
  SV_CHECK(status, low.Observer->CheckWarningMessage("FA below threshold") == 0);
}

void TestAngle(SplineVizTestStatus& status)
{
  // v = (-y - b x, x - b y, 0): logarithmic spirals r = r0 exp(-b theta),
  // curvature 1 / (r sqrt(1 + b^2)) growing inwards.
  const double b = 0.1, a = 0.05, h = 0.02;
  const int dims[3] = { 97, 97, 1 };
  const double origin[3] = { -1.2, -1.2, 0 }, spacing[3] = { 0.025, 0.025, 1 };
  auto img = MakeImage(dims, origin, spacing,
    [&](const double x[3], double t[6])
    {
      const double v[3] = { -x[1] - b * x[0], x[0] - b * x[1], 0.0 };
      t[0] = a + v[0] * v[0];
      t[1] = a + v[1] * v[1];
      t[2] = a;
      t[3] = v[0] * v[1];
      t[4] = t[5] = 0.0;
    });
  double previousEnd = VTK_DOUBLE_MAX;
  for (double maxAngle : { 10.0, 20.0 })
  {
    Run run(
      img, { { 1.0, 0.0, 0.0 } }, h, [&](vtkTensorLineTracer* t) { t->SetMaximumAngle(maxAngle); });
    SV_CHECK(status, run.Lines.size() == 1);
    if (run.Lines.empty())
    {
      continue;
    }
    const TracedLine& l = run.Lines[0];
    // the inner end (smaller radius) stopped by the angle, the outer one by the domain
    const double r0 = std::hypot(l.Points.front()[0], l.Points.front()[1]);
    const double r1 = std::hypot(l.Points.back()[0], l.Points.back()[1]);
    const int inner = r0 < r1 ? 0 : 1;
    const double rEnd = std::min(r0, r1);
    SV_CHECK(status, l.Reasons[inner] == vtkTensorLineTracer::HIGH_CURVATURE);
    SV_CHECK(status, l.Reasons[1 - inner] == vtkTensorLineTracer::OUT_OF_DOMAIN);
    // h / (r sqrt(1 + b^2)) = angle at the stop
    const double rExpected = h / (vtkMath::RadiansFromDegrees(maxAngle) * std::sqrt(1 + b * b));
    std::cout << "angle stop at " << maxAngle << " degrees: inner end at r = " << rEnd
              << " (h kappa = angle at r = " << rExpected << ")" << std::endl;
    SV_CHECK(status, rEnd > 0.6 * rExpected && rEnd < 1.6 * rExpected);
    SV_CHECK(status, rEnd < previousEnd);
    previousEnd = rEnd;
    // every turn between consecutive steps (except at the seed joint) is allowed
    std::size_t seedIndex = 0;
    for (std::size_t i = 0; i < l.Arc.size(); ++i)
    {
      if (l.Arc[i] == 0.0)
      {
        seedIndex = i;
      }
    }
    double largest = 0.0;
    for (std::size_t i = 1; i + 1 < l.Points.size(); ++i)
    {
      if (i == seedIndex)
      {
        continue;
      }
      const Vec3 d0 = Normalized({ l.Points[i][0] - l.Points[i - 1][0],
        l.Points[i][1] - l.Points[i - 1][1], l.Points[i][2] - l.Points[i - 1][2] });
      const Vec3 d1 = Normalized({ l.Points[i + 1][0] - l.Points[i][0],
        l.Points[i + 1][1] - l.Points[i][1], l.Points[i + 1][2] - l.Points[i][2] });
      largest =
        std::max(largest, vtkMath::DegreesFromRadians(std::acos(std::min(1.0, Dot(d0, d1)))));
    }
    SV_CHECK(status, largest <= maxAngle + 1e-9);
    SV_CHECK(status, largest > 0.8 * maxAngle); // the line did come close to the limit
  }
}

void TestDomainMaskLengthSteps(SplineVizTestStatus& status)
{
  // e1 = x everywhere on [-3, 3] x [-1, 1]^2; mask 1 for |x| <= 1.
  const int dims[3] = { 7, 3, 3 };
  const double origin[3] = { -3, -1, -1 };
  auto img = Diagonal(dims, origin, 1.0,
    [](const double*, double l[3])
    {
      l[0] = 1.0;
      l[1] = l[2] = 0.2;
    });
  vtkNew<vtkDoubleArray> mask;
  mask->SetName("Mask");
  for (vtkIdType i = 0; i < img->GetNumberOfPoints(); ++i)
  {
    double x[3];
    img->GetPoint(i, x);
    mask->InsertNextValue(std::abs(x[0]) <= 1.0 ? 1.0 : 0.0);
  }
  img->GetPointData()->AddArray(mask);
  const double h = 0.07;

  Run domain(img, { { 0.1, 0.2, 0.3 } }, h);
  SV_CHECK(status, domain.Lines.size() == 1);
  for (const TracedLine& l : domain.Lines)
  {
    SV_CHECK(status, l.Reasons[0] == vtkTensorLineTracer::OUT_OF_DOMAIN);
    SV_CHECK(status, l.Reasons[1] == vtkTensorLineTracer::OUT_OF_DOMAIN);
    SV_CHECK(status, std::abs(l.Points.front()[0]) > 3.0 - h);
    SV_CHECK(status, std::abs(l.Points.back()[0]) > 3.0 - h);
  }

  Run masked(img, { { 0.1, 0.2, 0.3 }, { 2.0, 0.0, 0.0 } }, h,
    [](vtkTensorLineTracer* t)
    { t->SetInputArrayToProcess(1, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Mask"); });
  SV_CHECK(status, masked.Lines.size() == 1);
  SV_CHECK(status, masked.Tracer->GetNumberOfRejectedSeeds() == 1);
  SV_CHECK(status, masked.Observer->CheckWarningMessage("1 out of mask") == 0);
  for (const TracedLine& l : masked.Lines)
  {
    SV_CHECK(status, l.SeedId == 0);
    SV_CHECK(status, l.Reasons[0] == vtkTensorLineTracer::OUT_OF_MASK);
    SV_CHECK(status, l.Reasons[1] == vtkTensorLineTracer::OUT_OF_MASK);
    for (const Vec3* p : { &l.Points.front(), &l.Points.back() })
    {
      // the interpolated 0/1 mask is 0.5 at |x| = 1.5
      SV_CHECK(status, std::abs((*p)[0]) <= 1.5 && std::abs((*p)[0]) > 1.5 - h);
    }
  }
  // The mask selected by attribute type (the active point scalars): the same line.
  img->GetPointData()->SetActiveScalars("Mask");
  Run maskedByType(img, { { 0.1, 0.2, 0.3 }, { 2.0, 0.0, 0.0 } }, h,
    [](vtkTensorLineTracer* t)
    {
      t->SetInputArrayToProcess(
        1, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::SCALARS);
    });
  SV_CHECK(status,
    maskedByType.Lines.size() == 1 && masked.Lines.size() == 1 &&
      maskedByType.Lines[0].Points == masked.Lines[0].Points);
  SV_CHECK(status, maskedByType.Tracer->GetNumberOfRejectedSeeds() == 1);
  img->GetPointData()->SetActiveAttribute(-1, vtkDataSetAttributes::SCALARS);
  // The filter knows no GUI's word for "no array": a point array named
  // "None" is a mask like any other, and an empty name (or no selection) is
  // no mask, without a message.
  {
    auto named = vtkSmartPointer<vtkImageData>::New();
    named->DeepCopy(img);
    vtkDataArray* copy = named->GetPointData()->GetArray("Mask");
    copy->SetName("None");
    Run maskedNone(named, { { 0.1, 0.2, 0.3 }, { 2.0, 0.0, 0.0 } }, h,
      [](vtkTensorLineTracer* t)
      { t->SetInputArrayToProcess(1, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "None"); });
    SV_CHECK(status,
      maskedNone.Lines.size() == 1 && masked.Lines.size() == 1 &&
        maskedNone.Lines[0].Points == masked.Lines[0].Points);
    SV_CHECK(status, maskedNone.Tracer->GetNumberOfRejectedSeeds() == 1);
    SV_CHECK(status, !maskedNone.Observer->GetError());
  }
  Run emptyName(img, { { 0.1, 0.2, 0.3 } }, h,
    [](vtkTensorLineTracer* t)
    { t->SetInputArrayToProcess(1, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, ""); });
  SV_CHECK(status, !emptyName.Observer->GetError() && !emptyName.Observer->GetWarning());
  SV_CHECK(status,
    emptyName.Lines.size() == 1 && domain.Lines.size() == 1 &&
      emptyName.Lines[0].Points == domain.Lines[0].Points);

  Run length(
    img, { { 0.1, 0.2, 0.3 } }, h, [](vtkTensorLineTracer* t) { t->SetMaximumPropagation(1.0); });
  SV_CHECK(status, length.Lines.size() == 1);
  for (const TracedLine& l : length.Lines)
  {
    SV_CHECK(status, l.Reasons[0] == vtkTensorLineTracer::OUT_OF_LENGTH);
    SV_CHECK(status, l.Reasons[1] == vtkTensorLineTracer::OUT_OF_LENGTH);
    SV_CHECK_NEAR(status, l.Length, 2.0, 1e-12); // straight: chords = steps
    SV_CHECK_NEAR(status, l.Arc.front(), -1.0, 1e-12);
    SV_CHECK_NEAR(status, l.Arc.back(), 1.0, 1e-12);
  }

  Run steps(
    img, { { 0.1, 0.2, 0.3 } }, h, [](vtkTensorLineTracer* t) { t->SetMaximumNumberOfSteps(7); });
  SV_CHECK(status, steps.Lines.size() == 1);
  for (const TracedLine& l : steps.Lines)
  {
    SV_CHECK(status, l.Reasons[0] == vtkTensorLineTracer::OUT_OF_STEPS);
    SV_CHECK(status, l.Reasons[1] == vtkTensorLineTracer::OUT_OF_STEPS);
    SV_CHECK(status, l.Points.size() == 15);
  }

  // Minimum length: a mask with a long region [-2.5, 0.5] and a short one
  // [1.5, 2.5]; the two lines seeded in the short one are left out.
  vtkNew<vtkDoubleArray> islands;
  islands->SetName("Islands");
  for (vtkIdType i = 0; i < img->GetNumberOfPoints(); ++i)
  {
    double x[3];
    img->GetPoint(i, x);
    islands->InsertNextValue((x[0] >= -2.0 && x[0] <= 0.0) || x[0] == 2.0 ? 1.0 : 0.0);
  }
  img->GetPointData()->AddArray(islands);
  Run shortLines(img, { { 2.0, 0.0, 0.0 }, { -1.0, 0.0, 0.0 }, { 2.2, 0.0, 0.0 } }, 0.2,
    [](vtkTensorLineTracer* t)
    {
      t->SetInputArrayToProcess(1, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Islands");
      t->SetMinimumLength(1.5);
    });
  SV_CHECK(status, shortLines.Lines.size() == 1);
  SV_CHECK(status, shortLines.Tracer->GetNumberOfShortLines() == 2);
  SV_CHECK(status, !shortLines.Lines.empty() && shortLines.Lines[0].SeedId == 1);
}

void TestNegativeNaNZero(SplineVizTestStatus& status)
{
  // l3 = 0.2 - 0.2 x turns negative beyond x = 1; l1 = 1 stays the largest |l|.
  const int dims[3] = { 9, 3, 3 };
  const double origin[3] = { -1, -1, -1 };
  auto img = Diagonal(dims, origin, 0.5,
    [](const double x[3], double l[3])
    {
      l[0] = 1.0;
      l[1] = 0.3;
      l[2] = 0.2 - 0.2 * x[0];
    });
  const double h = 0.05;
  for (int interpolation :
    { vtkTensorLineTracer::LINEAR_INTERPOLATION, vtkTensorLineTracer::LOG_EUCLIDEAN_INTERPOLATION })
  {
    Run stop(img, { { 0.0, 0.0, 0.0 } }, h,
      [&](vtkTensorLineTracer* t) { t->SetInterpolation(interpolation); });
    SV_CHECK(status, stop.Lines.size() == 1);
    SV_CHECK(status, stop.Tracer->GetNumberOfIndefiniteTensors() == 4 * 9); // x >= 1.5
    SV_CHECK(status, stop.Observer->CheckWarningMessage("have negative eigenvalues") == 0);
    for (const TracedLine& l : stop.Lines)
    {
      int reason;
      const Vec3 end = End(l, 0, true, reason);
      SV_CHECK(status, reason == vtkTensorLineTracer::NEGATIVE_EIGENVALUE);
      // linear: where the interpolated l3 < 0 (x > 1, within one RK4 step);
      // log-Euclidean: before interpolating with the first indefinite voxel
      // (x = 1.5), i.e. also at x <= 1
      SV_CHECK(status, end[0] <= 1.0 + 1e-4 && end[0] > 1.0 - h - 1e-9);
      const Vec3 start = End(l, 0, false, reason);
      SV_CHECK(status, reason == vtkTensorLineTracer::OUT_OF_DOMAIN && start[0] < -1.0 + h);
    }
    Run absolute(img, { { 0.0, 0.0, 0.0 } }, h,
      [&](vtkTensorLineTracer* t)
      {
        t->SetInterpolation(interpolation);
        t->SetNegativeEigenvalues(vtkTensorLineTracer::NEGATIVE_EIGENVALUES_ABSOLUTE);
      });
    SV_CHECK(status, absolute.Lines.size() == 1);
    for (const TracedLine& l : absolute.Lines)
    {
      SV_CHECK(status, l.Reasons[0] == vtkTensorLineTracer::OUT_OF_DOMAIN);
      SV_CHECK(status, l.Reasons[1] == vtkTensorLineTracer::OUT_OF_DOMAIN);
    }
  }

  // A NaN voxel at x = 2 and zero tensors for x <= -2 on a line along x.
  const int dims2[3] = { 9, 1, 1 };
  const double origin2[3] = { -4, 0, 0 };
  auto line = Diagonal(dims2, origin2, 1.0,
    [](const double x[3], double l[3])
    {
      const double v = x[0] <= -2.0 ? 0.0 : 1.0;
      l[0] = v;
      l[1] = l[2] = 0.2 * v;
    });
  line->GetPointData()->GetTensors()->SetComponent(6, 4, std::numeric_limits<double>::quiet_NaN());
  for (double threshold : { 0.1, 0.0 })
  {
    Run run(line, { { 0.5, 0, 0 }, { -3.0, 0, 0 } }, 0.1,
      [&](vtkTensorLineTracer* t) { t->SetStoppingFAThreshold(threshold); });
    SV_CHECK(status, run.Result == 1);
    SV_CHECK(status, run.Lines.size() == 1);
    SV_CHECK(status, run.Tracer->GetNumberOfInvalidTensors() == 1);
    SV_CHECK(status, run.Observer->CheckWarningMessage("1 point tensors have NaN") == 0);
    for (const TracedLine& l : run.Lines)
    {
      int reason;
      const Vec3 hi = End(l, 0, true, reason);
      SV_CHECK(status, reason == vtkTensorLineTracer::UNEXPECTED_VALUE);
      SV_CHECK(status, hi[0] <= 1.0 + 1e-12 && hi[0] > 0.8);
      const Vec3 lo = End(l, 0, false, reason);
      SV_CHECK(status,
        reason ==
          (threshold > 0 ? vtkTensorLineTracer::LOW_ANISOTROPY : vtkTensorLineTracer::STAGNATION));
      SV_CHECK(status, lo[0] > -2.0 && lo[0] < -1.0);
    }
  }
}

void TestBadInput(SplineVizTestStatus& status)
{
  const int dims[3] = { 4, 4, 4 };
  const double origin[3] = { 0, 0, 0 };
  auto img = Diagonal(dims, origin, 1.0,
    [](const double*, double l[3])
    {
      l[0] = 1.0;
      l[1] = l[2] = 0.2;
    });

  // empty seeds: a warning, an empty output, no error
  {
    vtkNew<vtkPolyData> none;
    vtkNew<vtkPoints> pts;
    none->SetPoints(pts);
    vtkNew<vtkTensorLineTracer> t;
    t->SetInputData(img);
    t->SetSourceData(none);
    vtkNew<vtkTest::ErrorObserver> obs;
    t->AddObserver(vtkCommand::WarningEvent, obs);
    t->AddObserver(vtkCommand::ErrorEvent, obs);
    t->Update();
    SV_CHECK(status, obs->CheckWarningMessage("the seed source has no points") == 0);
    SV_CHECK(status, !obs->GetError());
    SV_CHECK(status, t->GetOutput()->GetNumberOfLines() == 0);
  }
  // no voxel above the seed threshold
  {
    vtkNew<vtkTensorLineTracer> t;
    t->SetInputData(img);
    t->SetSeedMode(vtkTensorLineTracer::SEEDS_FROM_VOXELS);
    t->SetSeedFAThreshold(0.99);
    vtkNew<vtkTest::ErrorObserver> obs;
    t->AddObserver(vtkCommand::WarningEvent, obs);
    t->Update();
    SV_CHECK(status, obs->CheckWarningMessage("no seeds, no lines") == 0);
  }

  struct Case
  {
    const char* Message;
    std::function<void(vtkImageData*, vtkTensorLineTracer*)> Setup;
  };
  const Case cases[] = {
    { "no seeds: connect",
      [](vtkImageData*, vtkTensorLineTracer* t) { t->SetSourceData(nullptr); } },
    { "no tensor array",
      [](vtkImageData*, vtkTensorLineTracer* t)
      { t->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Nope"); } },
    { "must be point data",
      [](vtkImageData* im, vtkTensorLineTracer* t)
      {
        vtkNew<vtkDoubleArray> cellTensors;
        cellTensors->SetName("CellT");
        cellTensors->SetNumberOfComponents(6);
        cellTensors->SetNumberOfTuples(im->GetNumberOfCells());
        cellTensors->Fill(1.0);
        im->GetCellData()->AddArray(cellTensors);
        t->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, "CellT");
      } },
    { "has 3 components",
      [](vtkImageData* im, vtkTensorLineTracer* t)
      {
        vtkNew<vtkDoubleArray> v;
        v->SetName("V");
        v->SetNumberOfComponents(3);
        v->SetNumberOfTuples(im->GetNumberOfPoints());
        v->Fill(1.0);
        im->GetPointData()->AddArray(v);
        t->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "V");
      } },
    { "has 6 components, which does not fit",
      [](vtkImageData*, vtkTensorLineTracer* t) { t->SetTensorLayout(TM::FULL_9); } },
    { "the mask array 'Missing' is not a point array",
      [](vtkImageData*, vtkTensorLineTracer* t)
      { t->SetInputArrayToProcess(1, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Missing"); } },
    // "None" is ParaView's label for no array (its plugin clears the
    // selection); to the filter it is a name like any other.
    { "the mask array 'None' is not a point array of vtkImageData: select a 1-component point "
      "array",
      [](vtkImageData*, vtkTensorLineTracer* t)
      { t->SetInputArrayToProcess(1, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "None"); } },
    { "must have one component",
      [](vtkImageData* im, vtkTensorLineTracer* t)
      {
        vtkNew<vtkDoubleArray> v;
        v->SetName("M3");
        v->SetNumberOfComponents(3);
        v->SetNumberOfTuples(im->GetNumberOfPoints());
        v->Fill(1.0);
        im->GetPointData()->AddArray(v);
        t->SetInputArrayToProcess(1, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "M3");
      } },
    { "the mask array 'CellMask' is not a point array",
      [](vtkImageData* im, vtkTensorLineTracer* t)
      {
        vtkNew<vtkDoubleArray> m;
        m->SetName("CellMask");
        m->SetNumberOfTuples(im->GetNumberOfCells());
        m->Fill(1.0);
        im->GetCellData()->AddArray(m);
        t->SetInputArrayToProcess(1, 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, "CellMask");
      } },
    { "IntegrationStep must be a positive number",
      [](vtkImageData*, vtkTensorLineTracer* t) { t->SetIntegrationStep(0.0); } },
    { "IntegrationStep must be a positive number",
      [](vtkImageData*, vtkTensorLineTracer* t)
      { t->SetIntegrationStep(std::numeric_limits<double>::quiet_NaN()); } },
    { "the input has no points",
      [](vtkImageData*, vtkTensorLineTracer* t) { t->SetInputData(vtkNew<vtkImageData>()); } },
  };
  for (const Case& c : cases)
  {
    auto copy = vtkSmartPointer<vtkImageData>::New();
    copy->DeepCopy(img);
    vtkNew<vtkTensorLineTracer> t;
    t->SetInputData(copy);
    t->SetSourceData(MakeSeeds({ { 1.5, 1.5, 1.5 } }));
    c.Setup(copy, t);
    vtkNew<vtkTest::ErrorObserver> obs;
    t->AddObserver(vtkCommand::ErrorEvent, obs);
    t->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, obs);
    t->Update();
    SV_CHECK_MSG(status, obs->CheckErrorMessage(c.Message) == 0, c.Message);
    SV_CHECK(status, t->GetOutput()->GetNumberOfPoints() == 0);
  }
}
}

int TestTensorLineTracerStopping(int, char*[])
{
  SplineVizTestStatus status;
  TestFA(status);
  TestAngle(status);
  TestDomainMaskLengthSteps(status);
  TestNegativeNaNZero(status);
  TestBadInput(status);
  return status.Result();
}
