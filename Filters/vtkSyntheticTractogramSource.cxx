// SPDX-License-Identifier: BSD-3-Clause
#include "vtkSyntheticTractogramSource.h"

#include "vtkSplineVizPolyLines.h"
#include "vtkSplineVizProgress.h"
#include "vtkSplineVizRandom.h"

#include "vtkCellData.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkSyntheticTractogramSource);

namespace
{
constexpr double TwoPi = 6.283185307179586;

struct Vec
{
  double x = 0.0, y = 0.0, z = 0.0;
};
Vec operator+(const Vec& a, const Vec& b)
{
  return { a.x + b.x, a.y + b.y, a.z + b.z };
}
Vec operator-(const Vec& a, const Vec& b)
{
  return { a.x - b.x, a.y - b.y, a.z - b.z };
}
Vec operator*(double s, const Vec& a)
{
  return { s * a.x, s * a.y, s * a.z };
}
double Dot(const Vec& a, const Vec& b)
{
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
Vec Cross(const Vec& a, const Vec& b)
{
  return { a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x };
}
Vec Normalized(const Vec& a)
{
  const double n = std::sqrt(Dot(a, a));
  return n > 0.0 ? (1.0 / n) * a : Vec{ 1.0, 0.0, 0.0 };
}

/// A bundle: its centre line sampled every step, with a rotation-minimizing
/// frame (N, B) of unit normals, and its radius.
struct Bundle
{
  std::vector<Vec> Center;
  std::vector<Vec> N;
  std::vector<Vec> B;
  double Radius = 1.0;
};

/// The centre line of bundle b: a walk of constant step whose direction
/// turns smoothly (a sum of slow sinusoids per component) and is steered
/// back into the ellipsoid.
Bundle MakeBundle(unsigned int seed, int b, int samples, double step, const double radii[3],
  const double radiusRange[2])
{
  vtkSplineVizRandom rng(seed ^ 0x5EEDB0u, b);
  Bundle bundle;
  bundle.Radius = rng.Uniform(radiusRange[0], radiusRange[1]);
  Vec p{ rng.Uniform(-0.6, 0.6) * radii[0], rng.Uniform(-0.6, 0.6) * radii[1],
    rng.Uniform(-0.6, 0.6) * radii[2] };
  double d0[3];
  rng.UnitVector(d0);
  Vec d{ d0[0], d0[1], d0[2] };
  double freq[3], phase[3], amp[3];
  for (int c = 0; c < 3; ++c)
  {
    freq[c] = rng.Uniform(0.005, 0.03) * step;
    phase[c] = rng.Uniform(0.0, TwoPi);
    amp[c] = rng.Uniform(0.01, 0.04) * step;
  }
  bundle.Center.resize(static_cast<size_t>(samples));
  std::vector<Vec> tangents(static_cast<size_t>(samples));
  for (int k = 0; k < samples; ++k)
  {
    bundle.Center[k] = p;
    tangents[k] = d;
    Vec turn{ amp[0] * std::sin(freq[0] * k + phase[0]), amp[1] * std::sin(freq[1] * k + phase[1]),
      amp[2] * std::sin(freq[2] * k + phase[2]) };
    // Steer back when the point ahead leaves 80 % of the ellipsoid.
    const Vec ahead = p + (10.0 * step) * d;
    const double e = ahead.x * ahead.x / (radii[0] * radii[0]) +
      ahead.y * ahead.y / (radii[1] * radii[1]) + ahead.z * ahead.z / (radii[2] * radii[2]);
    if (e > 0.64)
    {
      const Vec inward{ -ahead.x / (radii[0] * radii[0]), -ahead.y / (radii[1] * radii[1]),
        -ahead.z / (radii[2] * radii[2]) };
      turn = turn + (0.08 * std::min(e - 0.64, 1.0) / 0.36) * Normalized(inward);
    }
    d = Normalized(d + turn);
    p = p + step * d;
  }
  // A rotation-minimizing frame along the centre line (projection method).
  bundle.N.resize(tangents.size());
  bundle.B.resize(tangents.size());
  Vec n = Normalized(Cross(
    tangents[0], std::abs(tangents[0].x) < 0.9 ? Vec{ 1.0, 0.0, 0.0 } : Vec{ 0.0, 1.0, 0.0 }));
  for (size_t k = 0; k < tangents.size(); ++k)
  {
    n = Normalized(n - Dot(n, tangents[k]) * tangents[k]);
    bundle.N[k] = n;
    bundle.B[k] = Cross(tangents[k], n);
  }
  return bundle;
}

/// Points of streamline s (from its own random sequence).
int StreamlinePoints(unsigned int seed, vtkIdType s, int minimum, int maximum)
{
  vtkSplineVizRandom rng(seed ^ 0x57AEu, s);
  return minimum + static_cast<int>(rng.Uniform() * (maximum - minimum + 1));
}
}

//------------------------------------------------------------------------------
vtkSyntheticTractogramSource::vtkSyntheticTractogramSource()
{
  this->SetNumberOfInputPorts(0);
}

//------------------------------------------------------------------------------
int vtkSyntheticTractogramSource::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  outputVector->GetInformationObject(0)->Set(vtkAlgorithm::CAN_HANDLE_PIECE_REQUEST(), 1);
  return 1;
}

//------------------------------------------------------------------------------
int vtkSyntheticTractogramSource::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkPolyData* output = vtkPolyData::GetData(outInfo);
  if (this->MinimumPoints > this->MaximumPoints)
  {
    vtkErrorMacro(<< "MinimumPoints (" << this->MinimumPoints << ") exceeds MaximumPoints ("
                  << this->MaximumPoints << ").");
    return 0;
  }
  if (!(this->BundleRadiusRange[0] >= 0.0 &&
        this->BundleRadiusRange[1] >= this->BundleRadiusRange[0]) ||
    !(this->BrainRadii[0] > 0.0 && this->BrainRadii[1] > 0.0 && this->BrainRadii[2] > 0.0))
  {
    vtkErrorMacro(<< "BrainRadii must be positive and BundleRadiusRange must satisfy 0 <= min "
                     "<= max.");
    return 0;
  }
  const vtkIdType total = this->NumberOfStreamlines;
  // Per point: position, FA, connectivity (24 bytes); refuse before allocating.
  std::string sizeError;
  if (!vtkSplineVizProgress::CheckOutputSize(static_cast<double>(total) * this->MaximumPoints, 24.0,
        "the synthetic tractogram (NumberOfStreamlines x MaximumPoints points)", &sizeError))
  {
    vtkErrorMacro(<< sizeError);
    return 0;
  }
  vtkIdType first, end;
  vtkSplineVizPolyLines::PieceRange(outInfo, total, first, end);
  const vtkIdType local = end - first;

  // The bundles' centre lines (long enough for the longest streamline).
  const int samples = 2 * this->MaximumPoints + 1;
  std::vector<Bundle> bundles(static_cast<size_t>(this->NumberOfBundles));
  vtkSMPTools::For(0, this->NumberOfBundles,
    [&](vtkIdType b0, vtkIdType b1)
    {
      for (vtkIdType b = b0; b < b1; ++b)
      {
        bundles[b] = MakeBundle(this->Seed, static_cast<int>(b), samples, this->StepLength,
          this->BrainRadii, this->BundleRadiusRange);
      }
    });

  vtkSplineVizPolyLines lines;
  lines.Allocate(local,
    [&](vtkIdType i)
    { return StreamlinePoints(this->Seed, first + i, this->MinimumPoints, this->MaximumPoints); });
  vtkNew<vtkFloatArray> fa;
  fa->SetName("FA");
  fa->SetNumberOfTuples(lines.GetNumberOfPoints());
  vtkNew<vtkIdTypeArray> streamlineIds;
  streamlineIds->SetName("StreamlineId");
  streamlineIds->SetNumberOfTuples(local);
  vtkNew<vtkIdTypeArray> bundleIds;
  bundleIds->SetName("BundleId");
  bundleIds->SetNumberOfTuples(local);
  float* faValues = fa->GetPointer(0);

  const bool done = vtkSplineVizProgress::For(
    this, 0, local, 0, 1024,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        const vtkIdType s = first + i;
        const int b = static_cast<int>(s % this->NumberOfBundles);
        const Bundle& bundle = bundles[b];
        vtkSplineVizRandom rng(this->Seed, s);
        const vtkIdType offset = lines.GetOffset(i);
        const vtkIdType n = lines.GetOffset(i + 1) - offset;
        const int start = static_cast<int>(rng.Uniform() * (samples - n));
        // The offset in the bundle's cross-section: a point of the disk that
        // wanders slowly (amplitude a quarter of the radius).
        const double rho = bundle.Radius * std::sqrt(rng.Uniform());
        const double theta = rng.Uniform(0.0, TwoPi);
        const double wobble = 0.25 * bundle.Radius;
        const double w1 = rng.Uniform(0.02, 0.08);
        const double w2 = rng.Uniform(0.02, 0.08);
        const double p1 = rng.Uniform(0.0, TwoPi);
        const double p2 = rng.Uniform(0.0, TwoPi);
        const double faPhase = rng.Uniform(0.0, TwoPi);
        for (vtkIdType k = 0; k < n; ++k)
        {
          const size_t c = static_cast<size_t>(start + k);
          const double u = rho * std::cos(theta) + wobble * std::sin(w1 * k + p1);
          const double v = rho * std::sin(theta) + wobble * std::sin(w2 * k + p2);
          const Vec p = bundle.Center[c] + u * bundle.N[c] + v * bundle.B[c];
          const vtkIdType id = offset + k;
          lines.SetPoint(id, p.x, p.y, p.z);
          faValues[id] = static_cast<float>(0.55 + 0.35 * std::sin(0.05 * k + faPhase));
        }
        streamlineIds->SetValue(i, s);
        bundleIds->SetValue(i, b);
      }
    },
    0.05, 1.0);
  if (!done)
  {
    output->Initialize(); // aborted: a clean, empty output
    return 1;
  }
  lines.SetOutput(output);
  output->GetPointData()->SetScalars(fa);
  output->GetCellData()->AddArray(streamlineIds);
  output->GetCellData()->AddArray(bundleIds);
  return 1;
}

//------------------------------------------------------------------------------
void vtkSyntheticTractogramSource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfStreamlines: " << this->NumberOfStreamlines << "\n";
  os << indent << "NumberOfBundles: " << this->NumberOfBundles << "\n";
  os << indent << "MinimumPoints: " << this->MinimumPoints << "\n";
  os << indent << "MaximumPoints: " << this->MaximumPoints << "\n";
  os << indent << "StepLength: " << this->StepLength << "\n";
  os << indent << "BrainRadii: " << this->BrainRadii[0] << " " << this->BrainRadii[1] << " "
     << this->BrainRadii[2] << "\n";
  os << indent << "BundleRadiusRange: " << this->BundleRadiusRange[0] << " "
     << this->BundleRadiusRange[1] << "\n";
  os << indent << "Seed: " << this->Seed << "\n";
}
