// SPDX-License-Identifier: BSD-3-Clause
// Generated LR-spline volumes for the LR-spline benchmarks: locally refined
// quadratic volumes with several refinement levels around focus points on a
// helix, with non-dyadic knots (irrational breakpoints and golden-section
// splits) or dyadic ones (uniform breakpoints, halving), until at least a
// given number of elements. The field is a smooth swirling 3D vector field
// (quasi-interpolated at the Greville points).
#ifndef LRSplineBenchmarkVolumes_h
#define LRSplineBenchmarkVolumes_h

#include "vtkLRSplineBuilder.h"
#include "vtkLRSplineElementLocator.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
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

// The volumes of the volume-rendering benchmark, at Fuchs et al.'s sizes
// (§4.3: 5,311, 36,614 and 255,909 elements): a recipe refines a quadratic
// tensor-product start `Levels` times around each of `NumberOfFoci` focus
// points (a Halton sequence inside the domain), and the coefficients
// quasi-interpolate a field whose detail lives where the refinement is, as
// in LR-spline approximations of real data (Fuchs §4.2: "the smallest
// elements occur in areas with the largest local variation"): the swirl
// plus, at every focus, a radial core of radius CoreRadius() (two of the
// finest elements) whose magnitude peaks at the core radius and falls off
// like 1/r to a Gaussian window, i.e. varies at every scale the graded
// refinement resolves.
struct RefinedVolumeRecipe
{
  std::string Name;
  int BaseIntervals = 8; ///< knot intervals per direction of the start
  bool Dyadic = true;    ///< uniform breakpoints and halving; else irrational breakpoints
  int Levels = 8;        ///< refinement rounds around every focus point
  int NumberOfFoci = 16;
  double CoreAmplitude = 4.0;
  double WindowRadius = 0.1;
  double RefinementRadius = 1.5; ///< per level, in elements of the level above

  /// Side of the start's elements (the domain is [0, 1]^3).
  double BaseSide() const { return 1.0 / this->BaseIntervals; }
  /// Side of the elements at the foci after all levels (halving per level).
  double FinestSide() const { return this->BaseSide() / (1 << this->Levels); }
  double CoreRadius() const { return 2.0 * this->FinestSide(); }

  /// The focus points: a Halton sequence (bases 2, 3, 5) in [0.15, 0.85]^3.
  std::vector<std::array<double, 3>> Foci() const
  {
    std::vector<std::array<double, 3>> foci;
    const int bases[3] = { 2, 3, 5 };
    for (int f = 1; f <= this->NumberOfFoci; ++f)
    {
      std::array<double, 3> p;
      for (int d = 0; d < 3; ++d)
      {
        double h = 0.0, scale = 1.0 / bases[d];
        for (int i = f; i > 0; i /= bases[d], scale /= bases[d])
        {
          h += (i % bases[d]) * scale;
        }
        p[d] = 0.15 + 0.7 * h;
      }
      foci.push_back(p);
    }
    return foci;
  }

  /// The field the coefficients quasi-interpolate (3 components).
  void Field(const double x[3], double v[3]) const
  {
    Swirl(x, v);
    const double rc = this->CoreRadius();
    const double w2 = this->WindowRadius * this->WindowRadius;
    for (const auto& p : this->FociCache)
    {
      const double d[3] = { x[0] - p[0], x[1] - p[1], x[2] - p[2] };
      const double r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
      if (r2 > 16.0 * w2)
      {
        continue;
      }
      const double s = this->CoreAmplitude * rc / (r2 + rc * rc) * std::exp(-r2 / w2);
      for (int k = 0; k < 3; ++k)
      {
        v[k] += s * d[k];
      }
    }
  }

  /// A file name that changes with every parameter (and the generator's
  /// version), for the cache.
  std::string FileName() const
  {
    std::ostringstream name;
    name << this->Name << "-v2-b" << this->BaseIntervals << (this->Dyadic ? "d" : "n") << "-l"
         << this->Levels << "-f" << this->NumberOfFoci << "-a" << this->CoreAmplitude << "-w"
         << this->WindowRadius << "-r" << this->RefinementRadius << ".lr";
    return name.str();
  }

  std::vector<std::array<double, 3>> FociCache; ///< filled by MakeRefinedVolume
};

/// Build the recipe's volume (see RefinedVolumeRecipe).
inline bool MakeRefinedVolume(
  vtkLRSplineBuilder& builder, RefinedVolumeRecipe& recipe, bool verbose = true)
{
  const auto t0 = std::chrono::steady_clock::now();
  const int degree[3] = { 2, 2, 2 };
  std::vector<double> breaks[3];
  const int n = recipe.BaseIntervals;
  for (int d = 0; d < 3; ++d)
  {
    for (int i = 0; i <= n; ++i)
    {
      double t = static_cast<double>(i) / n;
      if (!recipe.Dyadic && i > 0 && i < n)
      {
        t += 0.2 / n * std::sin(1.7 * i + d) / std::sqrt(2.0); // irrational breakpoints
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
  recipe.FociCache = recipe.Foci();
  // Level l halves (mid-planes in every direction, as mesh rectangles across
  // each element) every element of level l - 1 that meets the cube of half
  // width RefinementRadius x (the level l - 1 side) around a focus: a graded
  // refinement, so that the B-splines of the finest level are the ones that
  // live at the foci (refining only the smallest support at a point leaves
  // coarse B-splines dominating there, whose Greville points are far away,
  // and the quasi-interpolant would lose the detail).
  for (int level = 1; level <= recipe.Levels; ++level)
  {
    const double coarse = recipe.BaseSide() / (1 << (level - 1));
    const double radius = recipe.RefinementRadius * coarse;
    if (recipe.Dyadic)
    {
      // The same, faster: the elements of level l - 1 meeting the cube fill
      // a box on the level's grid; its mid-planes are inserted as one
      // rectangle each.
      for (const auto& p : recipe.FociCache)
      {
        double box[6];
        for (int d = 0; d < 3; ++d)
        {
          box[d] = std::max(0.0, std::floor((p[d] - radius) / coarse) * coarse);
          box[d + 3] = std::min(1.0, std::ceil((p[d] + radius) / coarse) * coarse);
        }
        for (int d = 0; d < 3; ++d)
        {
          for (double x = box[d] + 0.5 * coarse; x < box[d + 3]; x += coarse)
          {
            if (!builder.InsertMeshRectangle(d, x, box, &error))
            {
              std::cerr << "ERROR: " << error << std::endl;
              return false;
            }
          }
        }
      }
      continue;
    }
    const std::vector<double> boxes = builder.GetPatch().ElementBoxes;
    for (std::size_t e = 0; e + 5 < boxes.size(); e += 6)
    {
      const double* box = boxes.data() + e;
      bool meets = false;
      for (const auto& p : recipe.FociCache)
      {
        bool inside = true;
        for (int d = 0; d < 3; ++d)
        {
          inside = inside && box[d] < p[d] + radius && box[d + 3] > p[d] - radius;
        }
        meets = meets || inside;
      }
      if (!meets)
      {
        continue;
      }
      for (int d = 0; d < 3; ++d)
      {
        // Split the element where it is still of the coarser level (the
        // base of a non-dyadic start is irregular: more than 1.4 times the
        // level's nominal side).
        if (box[d + 3] - box[d] > 0.7 * coarse &&
          !builder.InsertMeshRectangle(d, 0.5 * (box[d] + box[d + 3]), box, &error))
        {
          std::cerr << "ERROR: " << error << std::endl;
          return false;
        }
      }
    }
  }
  builder.SetCoefficientsFromGreville(
    [&recipe](const double g[3], double* c) { recipe.Field(g, c); });
  if (verbose)
  {
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::cout << "generated " << recipe.Name << ": " << builder.GetNumberOfElements()
              << " elements, " << builder.GetNumberOfBasisFunctions() << " basis functions, "
              << recipe.Levels << " levels at " << recipe.NumberOfFoci << " foci (" << s << " s)"
              << std::endl;
  }
  return true;
}

/// The recipe's volume as an .lr file in `cacheDir` (created if needed),
/// generated only when the file is not there yet (written under a temporary
/// name and renamed, so an interrupted run leaves no half file). Returns the
/// path, or "" on failure. `generated` (may be null) tells whether it was
/// generated now.
inline std::string CachedRefinedVolume(
  RefinedVolumeRecipe& recipe, const std::string& cacheDir, bool* generated = nullptr)
{
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::create_directories(cacheDir, ec);
  const fs::path path = fs::path(cacheDir) / recipe.FileName();
  recipe.FociCache = recipe.Foci();
  if (generated)
  {
    *generated = false;
  }
  if (fs::exists(path, ec))
  {
    return path.string();
  }
  vtkLRSplineBuilder builder;
  if (!MakeRefinedVolume(builder, recipe))
  {
    return "";
  }
  const fs::path partial = path.string() + ".partial";
  {
    std::ofstream out(partial);
    builder.GetPatch().Write(out);
    if (!out)
    {
      std::cerr << "ERROR: cannot write " << partial << std::endl;
      return "";
    }
  }
  fs::rename(partial, path, ec);
  if (ec)
  {
    std::cerr << "ERROR: cannot rename " << partial << ": " << ec.message() << std::endl;
    return "";
  }
  if (generated)
  {
    *generated = true;
  }
  return path.string();
}

// Fuchs' table columns for an element search structure (Figs. 4-6): memory
// of the flat arrays, nodes, and the depth statistics over blocks
// (vtkLRSplineElementLocator::GetStatistics), as one header and one row.
inline std::string StatisticsHeader()
{
  return "memory [MB]     nodes  min  max  mean depth  var depth";
}

inline std::string StatisticsRow(const vtkLRSplineElementLocator::Statistics& s)
{
  char line[200];
  std::snprintf(line, sizeof(line), "%11.1f %9lld %4d %4d %11.4f %10.4f", s.MemoryBytes / 1048576.0,
    static_cast<long long>(s.NumberOfNodes), s.MinDepth, s.MaxDepth, s.MeanDepth, s.VarianceDepth);
  return line;
}

/// The statistics of several patches' structures as one: sums of nodes,
/// blocks and memory, the extreme depths, and the mean and variance over
/// all blocks together.
inline vtkLRSplineElementLocator::Statistics CombineStatistics(
  const std::vector<vtkLRSplineElementLocator::Statistics>& parts)
{
  vtkLRSplineElementLocator::Statistics all;
  if (parts.empty())
  {
    return all;
  }
  all.MinDepth = parts[0].MinDepth;
  double weight = 0.0, sum = 0.0, sum2 = 0.0;
  for (const auto& s : parts)
  {
    all.MinDepth = std::min(all.MinDepth, s.MinDepth);
    all.MaxDepth = std::max(all.MaxDepth, s.MaxDepth);
    all.NumberOfNodes += s.NumberOfNodes;
    all.NumberOfBlocks += s.NumberOfBlocks;
    all.NumberOfLeafBlocks += s.NumberOfLeafBlocks;
    all.MemoryBytes += s.MemoryBytes;
    const double w = s.NumberOfBlocks > 0 ? static_cast<double>(s.NumberOfBlocks) : 1.0;
    weight += w;
    sum += w * s.MeanDepth;
    sum2 += w * (s.VarianceDepth + s.MeanDepth * s.MeanDepth);
  }
  all.MeanDepth = sum / weight;
  all.VarianceDepth = std::max(0.0, sum2 / weight - all.MeanDepth * all.MeanDepth);
  return all;
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
