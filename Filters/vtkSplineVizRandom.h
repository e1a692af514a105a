// SPDX-License-Identifier: BSD-3-Clause
/**
 * vtkSplineVizRandom: a small counter-based random generator (splitmix64) for
 * the synthetic sources. Every item (tube, streamline, bundle) gets its own
 * stream from (seed, item id), so the sources' output does not depend on
 * threading or on how the items are split into pieces.
 *
 * Header-only, private to the module.
 */
#ifndef vtkSplineVizRandom_h
#define vtkSplineVizRandom_h

#include "vtkType.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

struct vtkSplineVizRandom
{
  std::uint64_t State;
  vtkSplineVizRandom(unsigned int seed, vtkIdType item)
    : State(0x9E3779B97F4A7C15ull * (static_cast<std::uint64_t>(seed) + 1) ^
        (static_cast<std::uint64_t>(item) * 0xD1B54A32D192ED03ull))
  {
  }
  std::uint64_t Next()
  {
    std::uint64_t z = (this->State += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  /// Uniform in [0, 1).
  double Uniform() { return static_cast<double>(this->Next() >> 11) * (1.0 / 9007199254740992.0); }
  double Uniform(double a, double b) { return a + (b - a) * this->Uniform(); }
  /// Uniform on the unit sphere.
  void UnitVector(double v[3])
  {
    const double z = this->Uniform(-1.0, 1.0);
    const double phi = this->Uniform(0.0, 2.0 * 3.14159265358979323846);
    const double s = std::sqrt(std::max(0.0, 1.0 - z * z));
    v[0] = s * std::cos(phi);
    v[1] = s * std::sin(phi);
    v[2] = z;
  }
};

#endif
