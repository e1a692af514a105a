// SPDX-License-Identifier: BSD-3-Clause
// LR-spline vector fields with known streamlines for the tracer tests: a
// linear field v(p) = A p + b is represented exactly by any spline of degree
// >= 1 (Greville coefficients on the tensor-product start, kept exact by LR
// refinement). The volume is refined locally (golden-section and dyadic
// splits) around a focus point, written as .lr and read back with
// vtkLRSplineReader, so the tracer runs on the same path as for real files.
#ifndef LRSplineTestFields_h
#define LRSplineTestFields_h

#include "vtkLRSplineBuilder.h"
#include "vtkLRSplineReader.h"

#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkSmartPointer.h"

#include <cmath>
#include <fstream>
#include <string>

namespace lrtest
{
inline vtkSmartPointer<vtkMultiBlockDataSet> LinearField(const double A[9], const double b[3],
  int degree, int levels, const double focus[3], const std::string& name,
  const char* fieldName = "velocity", std::vector<double> breaks = { 0, 0.3, 0.55, 0.8, 1.0 })
{
  vtkLRSplineBuilder builder;
  const int deg[3] = { degree, degree, degree };
  const std::vector<double> br[3] = { breaks, breaks, breaks };
  std::string error;
  if (!builder.InitializeTensorProduct(deg, br, 3, &error))
  {
    return nullptr;
  }
  builder.SetCoefficientsFromGreville(
    [&](const double g[3], double* c)
    {
      for (int i = 0; i < 3; ++i)
      {
        c[i] = A[3 * i] * g[0] + A[3 * i + 1] * g[1] + A[3 * i + 2] * g[2] + b[i];
      }
    });
  const double golden = 0.5 * (std::sqrt(5.0) - 1.0);
  for (int l = 0; l < levels; ++l)
  {
    if (!builder.RefineAt(focus, l % 3 == 0 ? golden : 0.5, &error))
    {
      return nullptr;
    }
  }
  const std::string path = std::string(SPLINEVIZ_TEST_OUTPUT_DIR) + "/" + name + ".lr";
  {
    std::ofstream out(path);
    builder.GetPatch().Write(out);
  }
  vtkNew<vtkLRSplineReader> reader;
  reader->SetFileName(path.c_str());
  reader->SetOutputFieldName(fieldName);
  reader->Update();
  vtkSmartPointer<vtkMultiBlockDataSet> out = reader->GetOutput();
  return out;
}
}

#endif
