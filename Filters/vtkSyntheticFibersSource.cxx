// SPDX-License-Identifier: BSD-3-Clause
#include "vtkSyntheticFibersSource.h"

#include "vtkSplineVizPolyLines.h"
#include "vtkSplineVizProgress.h"
#include "vtkSplineVizRandom.h"

#include "vtkCellData.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

vtkStandardNewMacro(vtkSyntheticFibersSource);

namespace
{
using TubeRandom = vtkSplineVizRandom;

double Dot(const double a[3], const double b[3])
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

void Normalize(double v[3])
{
  const double n = std::sqrt(Dot(v, v));
  if (n > 0.0)
  {
    v[0] /= n;
    v[1] /= n;
    v[2] /= n;
  }
}

/// Weight of a tube's share of the segments (in [0.5, 1.5)), from its id only.
double TubeWeight(unsigned int seed, vtkIdType tube)
{
  TubeRandom r(seed ^ 0xA5A5A5A5u, tube);
  return 0.5 + r.Uniform();
}
}

//------------------------------------------------------------------------------
vtkSyntheticFibersSource::vtkSyntheticFibersSource()
{
  this->SetNumberOfInputPorts(0);
}

//------------------------------------------------------------------------------
void vtkSyntheticFibersSource::SetPreset(int preset)
{
  vtkIdType tubes = this->NumberOfTubes;
  vtkIdType segments = this->NumberOfSegments;
  double box = this->BoxSize;
  // The box grows with the data so that the tubes fill about 1.5% of its
  // volume (with the default step and radii), like white-matter tracts in a
  // brain: the papers' data sets are of that kind, not solid bundles.
  switch (preset)
  {
    case FIBERS:
      tubes = 241;
      segments = 3530;
      box = 1.0;
      break;
    case FIBERS2:
      tubes = 1701;
      segments = 114489;
      box = 3.1;
      break;
    case ONE_MILLION:
      tubes = 8000;
      segments = 1000000;
      box = 6.4;
      break;
    case CUSTOM:
      break;
    default:
      vtkErrorMacro(<< "Unknown preset " << preset
                    << " (expected 0 = custom, 1 = Fibers, 2 = Fibers2, 3 = one million)");
      return;
  }
  if (this->Preset != preset || tubes != this->NumberOfTubes ||
    segments != this->NumberOfSegments || box != this->BoxSize)
  {
    this->Preset = preset;
    this->NumberOfTubes = tubes;
    this->NumberOfSegments = segments;
    this->BoxSize = box;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkSyntheticFibersSource::SetNumberOfTubes(vtkIdType n)
{
  n = std::max<vtkIdType>(n, 0);
  if (n != this->NumberOfTubes)
  {
    this->NumberOfTubes = n;
    this->Preset = CUSTOM;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkSyntheticFibersSource::SetNumberOfSegments(vtkIdType n)
{
  n = std::max<vtkIdType>(n, 0);
  if (n != this->NumberOfSegments)
  {
    this->NumberOfSegments = n;
    this->Preset = CUSTOM;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
int vtkSyntheticFibersSource::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  outInfo->Set(vtkAlgorithm::CAN_HANDLE_PIECE_REQUEST(), 1);
  return 1;
}

//------------------------------------------------------------------------------
int vtkSyntheticFibersSource::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkPolyData* output = vtkPolyData::GetData(outInfo);

  const vtkIdType nTubes = this->NumberOfTubes;
  if (nTubes > 0 && this->NumberOfSegments < nTubes)
  {
    vtkErrorMacro(<< "NumberOfSegments (" << this->NumberOfSegments
                  << ") must be at least NumberOfTubes (" << nTubes
                  << "): every tube has at least one segment.");
    return 0;
  }
  if (this->RadiusRange[0] <= 0.0 || this->RadiusRange[1] < this->RadiusRange[0])
  {
    vtkErrorMacro(<< "RadiusRange must satisfy 0 < min <= max, got [" << this->RadiusRange[0]
                  << ", " << this->RadiusRange[1] << "]");
    return 0;
  }
  // Absurd sizes are refused before anything is allocated: per point its
  // position, radius, scalar and connectivity (about 28 bytes), per tube an
  // offset, an id and a weight.
  std::string sizeError;
  if (!vtkSplineVizProgress::CheckOutputSize(
        static_cast<double>(this->NumberOfSegments) + static_cast<double>(nTubes), 40.0,
        "the synthetic fibers (NumberOfTubes + NumberOfSegments points)", &sizeError))
  {
    vtkErrorMacro(<< sizeError);
    return 0;
  }

  vtkIdType firstTube, endTube;
  vtkSplineVizPolyLines::PieceRange(outInfo, nTubes, firstTube, endTube);

  // Segments per tube: one each, plus a share of the rest proportional to a
  // per-tube weight; the cumulative rounding makes the total exact.
  std::vector<double> cumulative(static_cast<size_t>(nTubes) + 1, 0.0);
  for (vtkIdType t = 0; t < nTubes; ++t)
  {
    cumulative[t + 1] = cumulative[t] + TubeWeight(this->Seed, t);
  }
  const vtkIdType extra = this->NumberOfSegments - nTubes;
  auto extraBefore = [&](vtkIdType t) -> vtkIdType
  {
    if (nTubes == 0 || cumulative[nTubes] <= 0.0)
    {
      return 0;
    }
    return static_cast<vtkIdType>(
      std::floor(static_cast<double>(extra) * cumulative[t] / cumulative[nTubes] + 0.5));
  };

  const vtkIdType localTubes = endTube - firstTube;
  vtkSplineVizPolyLines lines; // a tube's points: 1 + its segments
  lines.Allocate(localTubes,
    [&](vtkIdType i)
    {
      const vtkIdType t = firstTube + i;
      return 2 + extraBefore(t + 1) - extraBefore(t);
    });
  const vtkIdType nPoints = lines.GetNumberOfPoints();

  vtkNew<vtkFloatArray> radius;
  radius->SetName("Radius");
  radius->SetNumberOfTuples(nPoints);
  vtkNew<vtkFloatArray> scalar;
  scalar->SetName("Scalar");
  scalar->SetNumberOfTuples(nPoints);
  vtkNew<vtkIdTypeArray> tubeIds;
  tubeIds->SetName("TubeId");
  tubeIds->SetNumberOfTuples(localTubes);

  float* rad = radius->GetPointer(0);
  float* sca = scalar->GetPointer(0);
  const double half = 0.5 * this->BoxSize;
  const double step = this->StepLength;
  const double maxTurn = this->MaximumTurn;
  const double rmin = this->RadiusRange[0];
  const double rmax = this->RadiusRange[1];
  const unsigned int seed = this->Seed;
  const double twoPi = 2.0 * 3.14159265358979323846;

  // Progress and abort between batches of tubes (the ONE_MILLION preset
  // takes seconds).
  const bool done = vtkSplineVizProgress::For(
    this, 0, localTubes, 0, 256,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        const vtkIdType t = firstTube + i;
        TubeRandom rng(seed, t);
        double p[3] = { rng.Uniform(-0.8, 0.8) * half, rng.Uniform(-0.8, 0.8) * half,
          rng.Uniform(-0.8, 0.8) * half };
        double d[3];
        rng.UnitVector(d);
        double omega[3] = { 0.0, 0.0, 0.0 }; // slowly varying turn vector
        const double radiusWave = rng.Uniform(0.15, 0.5) * this->BoxSize;
        const double radiusPhase = rng.Uniform(0.0, twoPi);
        const double scalarWave = rng.Uniform(0.3, 1.0) * this->BoxSize;
        const double scalarPhase = rng.Uniform(0.0, twoPi);
        double arc = 0.0;

        for (vtkIdType k = lines.GetOffset(i); k < lines.GetOffset(i + 1); ++k)
        {
          lines.SetPoint(k, p[0], p[1], p[2]);
          rad[k] = static_cast<float>(
            rmin + (rmax - rmin) * (0.5 + 0.5 * std::sin(twoPi * arc / radiusWave + radiusPhase)));
          sca[k] = static_cast<float>(0.5 + 0.5 * std::sin(twoPi * arc / scalarWave + scalarPhase));

          // Evolve the turn vector: a damped random walk, plus a pull towards
          // the centre near the walls of the box.
          double kick[3];
          rng.UnitVector(kick);
          for (int c = 0; c < 3; ++c)
          {
            omega[c] = 0.85 * omega[c] + 0.25 * maxTurn * kick[c];
            const double ahead = p[c] + 4.0 * step * d[c];
            if (std::abs(ahead) > 0.85 * half)
            {
              omega[c] -= (ahead > 0 ? 1.0 : -1.0) * maxTurn;
            }
          }
          // Only the part of omega normal to d turns the direction.
          const double along = Dot(omega, d);
          double turn[3] = { omega[0] - along * d[0], omega[1] - along * d[1],
            omega[2] - along * d[2] };
          const double turnLength = std::sqrt(Dot(turn, turn));
          if (turnLength > maxTurn)
          {
            for (double& c : turn)
            {
              c *= maxTurn / turnLength;
            }
          }
          // Rotate d by the angle |turn| towards turn (exact rotation, so the
          // turning angle between segments never exceeds MaximumTurn).
          const double angle = std::min(std::sqrt(Dot(turn, turn)), maxTurn);
          if (angle > 0.0)
          {
            Normalize(turn);
            for (int c = 0; c < 3; ++c)
            {
              d[c] = std::cos(angle) * d[c] + std::sin(angle) * turn[c];
            }
            Normalize(d);
          }
          for (int c = 0; c < 3; ++c)
          {
            p[c] += step * d[c];
          }
          arc += step;
        }
        tubeIds->SetValue(i, t);
      }
    },
    0.0, 0.95);
  if (!done)
  {
    output->Initialize(); // aborted: a clean, empty output
    return 1;
  }

  lines.SetOutput(output);
  output->GetPointData()->AddArray(radius);
  output->GetPointData()->SetScalars(scalar);
  output->GetCellData()->AddArray(tubeIds);
  return 1;
}

//------------------------------------------------------------------------------
void vtkSyntheticFibersSource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Preset: " << this->Preset << "\n";
  os << indent << "NumberOfTubes: " << this->NumberOfTubes << "\n";
  os << indent << "NumberOfSegments: " << this->NumberOfSegments << "\n";
  os << indent << "BoxSize: " << this->BoxSize << "\n";
  os << indent << "StepLength: " << this->StepLength << "\n";
  os << indent << "MaximumTurn: " << this->MaximumTurn << "\n";
  os << indent << "RadiusRange: " << this->RadiusRange[0] << " " << this->RadiusRange[1] << "\n";
  os << indent << "Seed: " << this->Seed << "\n";
}
