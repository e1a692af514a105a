// Generated LR-spline volumes for the LR-spline benchmarks: locally refined
// quadratic volumes with several refinement levels around focus points on a
// helix, with non-dyadic knots (irrational breakpoints and golden-section
// splits) or dyadic ones (uniform breakpoints, halving), until at least a
// given number of elements. The field is a smooth swirling 3D vector field
// (quasi-interpolated at the Greville points).
#ifndef LRSplineBenchmarkVolumes_h
#define LRSplineBenchmarkVolumes_h

#include "vtkLRSplineBuilder.h"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace lrbench
{
// A steady swirl in [0,1]^3: rotation about the z axis through (0.5, 0.5)
// plus a slow upward drift and a perturbation, |v| ~ 1.
inline void Swirl(const double p[3], double v[3])
{
  const double x = p[0] - 0.5, y = p[1] - 0.5, z = p[2];
  v[0] = -y + 0.15 * std::sin(6.0 * z);
  v[1] = x + 0.15 * std::cos(5.0 * z);
  v[2] = 0.12 + 0.08 * std::sin(4.0 * (x + y));
}

inline bool MakeVolume(
  vtkLRSplineBuilder& builder, vtkIdType minElements, bool dyadic, bool verbose = true)
{
  const auto t0 = std::chrono::steady_clock::now();
  const int degree[3] = { 2, 2, 2 };
  std::vector<double> breaks[3];
  const int n = 10;
  for (int d = 0; d < 3; ++d)
  {
    for (int i = 0; i <= n; ++i)
    {
      double t = static_cast<double>(i) / n;
      if (!dyadic && i > 0 && i < n)
      {
        t += 0.03 * std::sin(1.7 * i + d) / std::sqrt(2.0); // irrational breakpoints
      }
      if (dyadic)
      {
        t = static_cast<double>(i) / 8.0;
        if (i > 8)
        {
          break;
        }
      }
      breaks[d].push_back(t);
    }
  }
  std::string error;
  if (!builder.InitializeTensorProduct(degree, breaks, 3, &error))
  {
    std::cerr << "ERROR: " << error << std::endl;
    return false;
  }
  builder.SetCoefficientsFromGreville([](const double g[3], double* c) { Swirl(g, c); });
  const double golden = 0.5 * (std::sqrt(5.0) - 1.0);
  // Focus points on a helix; refine around them level by level.
  const int numFocus = 24;
  int level = 0;
  while (builder.GetNumberOfElements() < minElements && level < 40)
  {
    for (int f = 0; f < numFocus && builder.GetNumberOfElements() < minElements; ++f)
    {
      const double a = 2.0 * 3.14159265358979 * f / numFocus;
      const double p[3] = { 0.5 + 0.3 * std::cos(a), 0.5 + 0.3 * std::sin(a),
        0.1 + 0.8 * f / numFocus };
      const double ratio = dyadic ? 0.5 : (level % 2 ? golden : 0.5);
      if (!builder.RefineAt(p, ratio, &error))
      {
        std::cerr << "ERROR: " << error << std::endl;
        return false;
      }
    }
    ++level;
  }
  // Coefficients of the final basis (quasi-interpolation of the swirl).
  builder.SetCoefficientsFromGreville([](const double g[3], double* c) { Swirl(g, c); });
  if (verbose)
  {
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::cout << "generated " << (dyadic ? "dyadic" : "non-dyadic")
              << " LR volume: " << builder.GetNumberOfElements() << " elements, "
              << builder.GetNumberOfBasisFunctions() << " basis functions, " << level
              << " refinement rounds (" << s << " s)" << std::endl;
  }
  return true;
}

// A generated volume written as an .lr file in the system's temporary
// directory (so the benchmarks go through the reader like a user would) and
// removed again when the benchmark ends; nothing is left in the working
// directory.
class TemporaryLRFile
{
public:
  TemporaryLRFile(vtkLRSplineBuilder& builder, const std::string& name)
  {
    std::error_code ec;
    std::filesystem::path dir = std::filesystem::temp_directory_path(ec);
    if (ec)
    {
      dir = ".";
    }
    this->Path = (dir / name).string();
    std::ofstream out(this->Path);
    builder.GetPatch().Write(out);
    this->Ok = static_cast<bool>(out);
  }
  ~TemporaryLRFile()
  {
    std::error_code ec;
    std::filesystem::remove(this->Path, ec);
  }
  TemporaryLRFile(const TemporaryLRFile&) = delete;
  TemporaryLRFile& operator=(const TemporaryLRFile&) = delete;
  const std::string& GetPath() const { return this->Path; }
  bool IsOk() const { return this->Ok; }

private:
  std::string Path;
  bool Ok = false;
};
}

#endif
