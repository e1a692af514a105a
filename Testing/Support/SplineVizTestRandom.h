// SPDX-License-Identifier: BSD-3-Clause
// Random numbers for the tests: uniform values of a seeded
// vtkMinimalStandardRandomSequence and random unit vectors.
#ifndef SplineVizTestRandom_h
#define SplineVizTestRandom_h

#include "vtkMinimalStandardRandomSequence.h"
#include "vtkNew.h"

#include <glm/glm.hpp>

namespace SplineVizTest
{
/// A seeded sequence: the same values on every run (of one compiler: the
/// order in which a constructor's arguments, e.g. UnitVector()'s three draws,
/// are evaluated is unspecified).
class Random
{
public:
  explicit Random(int seed) { this->Sequence->SetSeed(seed); }

  /// The next value, uniform in [a, b).
  double Uniform(double a, double b)
  {
    this->Sequence->Next();
    return this->Sequence->GetRangeValue(a, b);
  }

  /// A unit vector of uniformly distributed direction: a point of the cube
  /// [-1, 1]^3 in the shell 0.1 <= |v| <= 1 (rejection), normalized.
  glm::dvec3 UnitVector()
  {
    glm::dvec3 v;
    do
    {
      v = glm::dvec3(this->Uniform(-1, 1), this->Uniform(-1, 1), this->Uniform(-1, 1));
    } while (glm::length(v) < 0.1 || glm::length(v) > 1.0);
    return glm::normalize(v);
  }

private:
  vtkNew<vtkMinimalStandardRandomSequence> Sequence;
};
}

#endif
