// Helpers of the tensor-math tests: a seeded random sequence, random
// rotations and symmetric tensors composed from a known eigen-system,
// R diag(l) R^T, written out here independently of vtkSplineVizTensorMath.
#ifndef TensorTestUtilities_h
#define TensorTestUtilities_h

#include "vtkMath.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkNew.h"

#include <cmath>

namespace tensortest
{
/// Reproducible uniform numbers (VTK's minimal standard generator).
struct Random
{
  vtkNew<vtkMinimalStandardRandomSequence> Seq;
  explicit Random(int seed) { this->Seq->SetSeed(seed); }
  double Next(double lo, double hi)
  {
    this->Seq->Next();
    return this->Seq->GetRangeValue(lo, hi);
  }
};

/// A random rotation (columns of r) from a random unit quaternion (rejection
/// sampling in the unit ball, so the rotations are uniformly distributed).
inline void RandomRotation(Random& rnd, double r[3][3])
{
  double q[4];
  double n = 0.0;
  do
  {
    for (double& c : q)
    {
      c = rnd.Next(-1.0, 1.0);
    }
    n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  } while (n < 0.1 || n > 1.0);
  for (double& c : q)
  {
    c /= n;
  }
  vtkMath::QuaternionToMatrix3x3(q, r);
}

/// t = R diag(l) R^T (columns of R are the eigenvectors), as the six
/// symmetric components XX, YY, ZZ, XY, YZ, XZ.
inline void Compose(const double r[3][3], const double l[3], double t[6])
{
  double m[3][3] = {};
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      for (int k = 0; k < 3; ++k)
      {
        m[i][j] += r[i][k] * l[k] * r[j][k];
      }
    }
  }
  t[0] = m[0][0];
  t[1] = m[1][1];
  t[2] = m[2][2];
  t[3] = m[0][1];
  t[4] = m[1][2];
  t[5] = m[0][2];
}
}

#endif
