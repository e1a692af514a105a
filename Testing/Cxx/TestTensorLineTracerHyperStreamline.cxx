// SPDX-License-Identifier: BSD-3-Clause
// vtkTensorLineTracer against VTK's own vtkHyperStreamline (FiltersGeneral)
// on the same field and seeds: a twisting helical bundle like Teem's
// `tend helix` sampled on an image, seeds on and around the bundle's core,
// both directions, the same step in world units and the same length, RK2
// in both (VTK integrates with Heun's method, we with the midpoint rule: both
// second order). vtkHyperStreamline outputs tubes (rings of NumberOfSides
// points around each centre, resampled along the line); the centre line is
// the mean of each ring. The largest distance between the two sets of lines
// (each centre of VTK's to our line and each of our points to VTK's line,
// away from the length limit) must shrink at second order as the step is
// halved (both converge to the same curves) and be below a fiftieth of the
// voxel size at the smallest step; for the seed on the core both stay on the
// exact core helix. The run times are printed (the benchmark measures them).
#include "vtkTensorLineTracer.h"

#include "SplineVizTestUtilities.h"
#include "TensorLineTestFields.h"

#include "vtkHyperStreamline.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPolyData.h"

#include <chrono>
#include <cstdlib>
#include <cmath>
#include <iostream>
#include <vector>

using namespace TensorLineTest;

namespace
{
double Compare(SplineVizTestStatus& status, vtkImageData* img, const TendHelix& helix,
  const std::vector<Vec3>& seeds, double fraction)
{
  // vtkHyperStreamline: of the cell diagonal
  const double h = img->GetSpacing()[0];
  const double step = fraction * h * std::sqrt(3.0); // the same step in world units
  const double length = 1.5;                         // per direction
  const int sides = 4;

  using Clock = std::chrono::steady_clock;
  auto t0 = Clock::now();
  std::vector<std::vector<std::vector<Vec3>>> vtkLines;
  for (const Vec3& s : seeds)
  {
    vtkNew<vtkHyperStreamline> hs;
    hs->SetInputData(img);
    hs->SetStartPosition(s[0], s[1], s[2]);
    hs->SetIntegrationEigenvectorToMajor();
    hs->SetIntegrationDirectionToIntegrateBothDirections();
    hs->SetIntegrationStepLength(fraction);
    hs->SetMaximumPropagationDistance(length);
    hs->SetTerminalEigenvalue(0.0);
    hs->SetStepLength(0.002);
    hs->SetNumberOfSides(sides);
    hs->SetRadius(0.001);
    hs->Update();
    vtkLines.push_back(CentreLines(hs->GetOutput(), sides));
  }
  const double vtkTime = std::chrono::duration<double>(Clock::now() - t0).count();

  t0 = Clock::now();
  vtkNew<vtkTensorLineTracer> tracer;
  tracer->SetInputData(img);
  tracer->SetSourceData(MakeSeeds(seeds));
  tracer->SetIntegratorType(vtkTensorLineTracer::RUNGE_KUTTA2);
  tracer->SetIntegrationStepUnit(vtkTensorLineTracer::LENGTH_UNIT);
  tracer->SetIntegrationStep(step);
  tracer->SetMaximumPropagation(length);
  tracer->SetStoppingFAThreshold(0.0);
  tracer->SetMaximumAngle(90.0);
  tracer->Update();
  const double ourTime = std::chrono::duration<double>(Clock::now() - t0).count();
  const auto ours = GetLines(tracer->GetOutput());
  std::cout << "vtkHyperStreamline: " << vtkTime << " s, vtkTensorLineTracer: " << ourTime
            << " s for " << seeds.size() << " seeds (both directions)" << std::endl;
  SV_CHECK(status, ours.size() == seeds.size());
  if (ours.size() != seeds.size())
  {
    return VTK_DOUBLE_MAX;
  }

  double worstTheirs = 0.0, worstOurs = 0.0, coreOurs = 0.0, coreTheirs = 0.0;
  for (std::size_t s = 0; s < seeds.size(); ++s)
  {
    const TracedLine& l = ours[s];
    SV_CHECK(status, l.SeedId == static_cast<int>(s));
    SV_CHECK(status, vtkLines[s].size() == 2);
    if (vtkLines[s].size() != 2)
    {
      continue;
    }
    // VTK's two streamers joined: the backward one reversed, then the forward one
    std::vector<Vec3> theirs(vtkLines[s][1].rbegin(), vtkLines[s][1].rend());
    theirs.insert(theirs.end(), vtkLines[s][0].begin(), vtkLines[s][0].end());
    for (const auto& streamer : vtkLines[s])
    {
      // every VTK centre (away from the length limit) is close to our line
      double arc = 0.0;
      for (std::size_t i = 0; i < streamer.size(); ++i)
      {
        if (i > 0)
        {
          arc += Norm({ streamer[i][0] - streamer[i - 1][0], streamer[i][1] - streamer[i - 1][1],
            streamer[i][2] - streamer[i - 1][2] });
        }
        if (arc < length - 2 * step)
        {
          worstTheirs = std::max(worstTheirs, DistanceToPolyline(streamer[i], l.Points));
        }
      }
    }
    for (std::size_t i = 0; i < l.Points.size(); ++i)
    {
      if (std::abs(l.Arc[i]) < length - 2 * step)
      {
        worstOurs = std::max(worstOurs, DistanceToPolyline(l.Points[i], theirs));
      }
    }
    if (s == 0)
    {
      // the seed on the core: both follow the core helix
      for (const Vec3& p : l.Points)
      {
        const Vec3 q = helix.Core(helix.Closest(p.data()));
        coreOurs = std::max(coreOurs, Norm({ p[0] - q[0], p[1] - q[1], p[2] - q[2] }));
      }
      for (const Vec3& p : theirs)
      {
        const Vec3 q = helix.Core(helix.Closest(p.data()));
        coreTheirs = std::max(coreTheirs, Norm({ p[0] - q[0], p[1] - q[1], p[2] - q[2] }));
      }
    }
    // both lines have about the same extent
    double vtkLength = 0.0;
    for (std::size_t i = 1; i < theirs.size(); ++i)
    {
      vtkLength += Norm({ theirs[i][0] - theirs[i - 1][0], theirs[i][1] - theirs[i - 1][1],
        theirs[i][2] - theirs[i - 1][2] });
    }
    SV_CHECK_NEAR(status, vtkLength, l.Length, 2 * step + 0.01);
  }
  std::cout << "step " << step << ": largest distance of VTK's centre lines from ours "
            << worstTheirs << ", of ours from VTK's " << worstOurs
            << "; from the exact core helix: ours " << coreOurs << ", VTK's " << coreTheirs
            << std::endl;
  SV_CHECK(status, coreOurs < 0.005 && coreTheirs < 0.01);
  return std::max(worstTheirs, worstOurs);
}
}

int TestTensorLineTracerHyperStreamline(int, char*[])
{
  SplineVizTestStatus status;
  TendHelix helix;
  const double h = 0.1; // voxel size
  const int dims[3] = { 31, 31, 21 };
  const double origin[3] = { -1.5, -1.5, -1.0 }, spacing[3] = { h, h, h };
  auto img =
    MakeImage(dims, origin, spacing, [&](const double x[3], double t[6]) { helix.Tensor(x, t); });

  std::vector<Vec3> seeds;
  for (int k = 0; k < 6; ++k)
  {
    Vec3 c = helix.Core(-1.5 + 0.6 * k);
    if (k > 0)
    {
      // off the core, still inside the bundle
      c[0] += 0.12 * std::cos(1.3 * k);
      c[1] += 0.12 * std::sin(1.3 * k);
      c[2] += 0.05 * (k % 2);
    }
    seeds.push_back(c);
  }
  // vtkHyperStreamline's step: a fraction of the cell diagonal; both lines
  // converge at order 2 to the same curve, so their distance shrinks
  // fourfold with each halving of the step.
  double previous = 0.0;
  for (double fraction : { 0.2, 0.1, 0.05 })
  {
    const double d = Compare(status, img, helix, seeds, fraction);
    if (fraction < 0.2)
    {
      std::cout << "  ratio to the previous step: " << previous / d << std::endl;
      SV_CHECK(status, previous / d > 3.0);
    }
    previous = d;
  }
  SV_CHECK(status, previous < 0.002); // a fiftieth of the voxel size
  return status.Result();
}
