// SPDX-License-Identifier: BSD-3-Clause
// Tests of vtkSyntheticFibersSource: exact counts of the presets, arrays and
// their ranges, smoothness (turn angle bound), box containment, determinism,
// pieces that partition the whole, and bad settings.
#include "vtkSyntheticFibersSource.h"

#include "SplineVizTestUtilities.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkTestErrorObserver.h"

#include <algorithm>
#include <cmath>

namespace
{
vtkIdType CountSegments(vtkPolyData* pd)
{
  return pd->GetNumberOfPoints() - pd->GetNumberOfLines();
}
}

int TestSyntheticFibersSource(int, char*[])
{
  SplineVizTestStatus status;

  // Presets: exact tube and segment counts.
  struct Preset
  {
    int Id;
    vtkIdType Tubes, Segments;
  };
  for (const Preset& p : { Preset{ vtkSyntheticFibersSource::FIBERS, 241, 3530 },
         Preset{ vtkSyntheticFibersSource::FIBERS2, 1701, 114489 } })
  {
    vtkNew<vtkSyntheticFibersSource> source;
    source->SetPreset(p.Id);
    source->Update();
    vtkPolyData* out = source->GetOutput();
    SV_CHECK(status, out->GetNumberOfLines() == p.Tubes);
    SV_CHECK(status, CountSegments(out) == p.Segments);
  }

  vtkNew<vtkSyntheticFibersSource> source;
  source->SetNumberOfTubes(50);
  source->SetNumberOfSegments(2000);
  source->SetRadiusRange(0.01, 0.02);
  source->SetMaximumTurn(0.3);
  source->SetBoxSize(2.0);
  source->Update();
  vtkPolyData* out = source->GetOutput();
  SV_CHECK(status, source->GetPreset() == vtkSyntheticFibersSource::CUSTOM);
  SV_CHECK(status, out->GetNumberOfLines() == 50);
  SV_CHECK(status, CountSegments(out) == 2000);

  // Arrays and ranges.
  vtkDataArray* radius = out->GetPointData()->GetArray("Radius");
  vtkDataArray* scalar = out->GetPointData()->GetArray("Scalar");
  SV_CHECK(status, radius && scalar && out->GetCellData()->GetArray("TubeId"));
  if (radius && scalar)
  {
    double r[2], s[2];
    radius->GetRange(r);
    scalar->GetRange(s);
    SV_CHECK(status, r[0] >= 0.01 - 1e-7 && r[1] <= 0.02 + 1e-7 && r[1] - r[0] > 0.005);
    SV_CHECK(status, s[0] >= 0.0 && s[1] <= 1.0 && s[1] - s[0] > 0.5);
  }
  double b[6];
  out->GetBounds(b);
  for (int c = 0; c < 3; ++c)
  {
    SV_CHECK(status, b[2 * c] >= -1.0 && b[2 * c + 1] <= 1.0);
  }
  // Turning angle between successive segments bounded by MaximumTurn, and
  // every step of length StepLength.
  double worstTurn = 0.0;
  double worstStep = 0.0;
  auto it = vtk::TakeSmartPointer(out->GetLines()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType n;
    const vtkIdType* ids;
    it->GetCurrentCell(n, ids);
    for (vtkIdType k = 0; k + 1 < n; ++k)
    {
      double p0[3], p1[3];
      out->GetPoint(ids[k], p0);
      out->GetPoint(ids[k + 1], p1);
      const double d[3] = { p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2] };
      worstStep =
        std::max(worstStep, std::abs(std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) - 0.02));
      if (k + 2 < n)
      {
        double p2[3];
        out->GetPoint(ids[k + 2], p2);
        const double e[3] = { p2[0] - p1[0], p2[1] - p1[1], p2[2] - p1[2] };
        const double c = (d[0] * e[0] + d[1] * e[1] + d[2] * e[2]) /
          std::sqrt(
            (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) * (e[0] * e[0] + e[1] * e[1] + e[2] * e[2]));
        worstTurn = std::max(worstTurn, std::acos(std::min(1.0, std::max(-1.0, c))));
      }
    }
  }
  SV_CHECK_MSG(status, worstTurn <= 0.3 + 1e-4, "turn " << worstTurn);
  SV_CHECK_MSG(status, worstStep < 1e-6, "step error " << worstStep);

  // Determinism: same seed, same points; another seed, other points.
  vtkNew<vtkSyntheticFibersSource> again;
  again->SetNumberOfTubes(50);
  again->SetNumberOfSegments(2000);
  again->SetRadiusRange(0.01, 0.02);
  again->SetMaximumTurn(0.3);
  again->SetBoxSize(2.0);
  again->Update();
  double maxDiff = 0.0;
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    double p[3], q[3];
    out->GetPoint(i, p);
    again->GetOutput()->GetPoint(i, q);
    maxDiff =
      std::max({ maxDiff, std::abs(p[0] - q[0]), std::abs(p[1] - q[1]), std::abs(p[2] - q[2]) });
  }
  SV_CHECK(status, maxDiff == 0.0);
  again->SetSeed(2);
  again->Update();
  double p[3], q[3];
  out->GetPoint(0, p);
  again->GetOutput()->GetPoint(0, q);
  SV_CHECK(status, p[0] != q[0] || p[1] != q[1] || p[2] != q[2]);

  // Pieces: 3 pieces partition the tubes and reproduce the whole.
  vtkIdType tubes = 0;
  vtkIdType points = 0;
  for (int piece = 0; piece < 3; ++piece)
  {
    source->UpdatePiece(piece, 3, 0);
    vtkPolyData* part = source->GetOutput();
    tubes += part->GetNumberOfLines();
    points += part->GetNumberOfPoints();
    vtkIdTypeArray* ids = vtkIdTypeArray::SafeDownCast(part->GetCellData()->GetArray("TubeId"));
    SV_CHECK(status, ids && ids->GetValue(0) == 50 * piece / 3);
  }
  SV_CHECK(status, tubes == 50);
  SV_CHECK(status, points == 2050);

  // Bad settings: a clear error, no output.
  vtkNew<vtkTest::ErrorObserver> observer;
  vtkNew<vtkSyntheticFibersSource> bad;
  bad->AddObserver(vtkCommand::ErrorEvent, observer);
  bad->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, observer);
  bad->SetNumberOfTubes(10);
  bad->SetNumberOfSegments(5);
  bad->Update();
  SV_CHECK(status, observer->CheckErrorMessage("at least NumberOfTubes") == 0);
  bad->SetNumberOfSegments(50);
  bad->SetRadiusRange(0.0, 1.0);
  bad->Update();
  SV_CHECK(status, observer->CheckErrorMessage("RadiusRange") == 0);
  bad->SetPreset(42);
  SV_CHECK(status, observer->CheckErrorMessage("Unknown preset") == 0);

  return status.Result();
}
