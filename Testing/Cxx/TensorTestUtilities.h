// SPDX-License-Identifier: BSD-3-Clause
// Helpers of the tensor-math tests: a seeded random sequence, random
// rotations and symmetric tensors composed from a known eigen-system,
// R diag(l) R^T, written out here independently of vtkSplineVizTensorMath.
#ifndef TensorTestUtilities_h
#define TensorTestUtilities_h

#include "vtkMath.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkNew.h"
#include "vtkSplineVizTensorMath.h"

#include <cmath>
#include <vector>

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

/// The components of the symmetric tensor t (XX, YY, ZZ, XY, YZ, XZ) in a
/// vtkSplineVizTensorMath layout, written out here independently of the
/// library's readers; `confidence` is Teem's leading value.
inline std::vector<double> Encode(int layout, const double t[6], double confidence = 1.0)
{
  namespace TM = vtkSplineVizTensorMath;
  const double xx = t[0], yy = t[1], zz = t[2], xy = t[3], yz = t[4], xz = t[5];
  switch (layout)
  {
    case TM::FULL_9:
      return { xx, xy, xz, xy, yy, yz, xz, yz, zz };
    case TM::SYMMETRIC_LOWER:
      return { xx, xy, yy, xz, yz, zz };
    case TM::SYMMETRIC_UPPER:
      return { xx, xy, xz, yy, yz, zz };
    case TM::TEEM_7:
      return { confidence, xx, xy, xz, yy, yz, zz };
    default: // SYMMETRIC_VTK
      return { xx, yy, zz, xy, yz, xz };
  }
}
}

#endif
