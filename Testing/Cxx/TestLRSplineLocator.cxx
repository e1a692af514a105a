// SPDX-License-Identifier: BSD-3-Clause
// vtkLRSplineElementLocator: the k-d forest (several resolutions, also not
// dividing the element grid), the single k-d tree, the octree and the lookup
// texture (dyadic knots only) and the linear search all return the element
// that an independent scan of the element boxes says contains the point, for
// random points, every element corner, face centres, edge midpoints and the
// domain's upper faces; on the real file and on generated LR volumes with
// several refinement levels, dyadic and non-dyadic (golden-section) knots.
// Octree and texture must refuse non-dyadic knots. Range queries agree with a
// scan. Depth statistics are printed like the paper's tables.
#include "vtkLRSplineBuilder.h"
#include "vtkLRSplineElementLocator.h"
#include "vtkLRSplineParser.h"

#include "LRSplineTestUtilities.h"
#include "SplineVizTestUtilities.h"

#include <cmath>
#include <iomanip>
#include <limits>
#include <random>

namespace
{
// Independent containment: half-open boxes, closed at the domain's upper faces.
vtkIdType ScanContaining(
  const std::vector<double>& boxes, const double dom[6], const double p[3], int& count)
{
  count = 0;
  vtkIdType found = -1;
  const vtkIdType n = static_cast<vtkIdType>(boxes.size() / 6);
  for (vtkIdType e = 0; e < n; ++e)
  {
    const double* b = boxes.data() + 6 * e;
    bool in = true;
    for (int d = 0; d < 3 && in; ++d)
    {
      in = b[d] <= p[d] && (p[d] < b[d + 3] || (p[d] == dom[d + 3] && b[d + 3] == dom[d + 3]));
    }
    if (in)
    {
      ++count;
      found = e;
    }
  }
  return found;
}

std::vector<std::array<double, 3>> Points(
  const std::vector<double>& boxes, const double dom[6], unsigned seed, int numRandom)
{
  std::vector<std::array<double, 3>> pts;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  for (int i = 0; i < numRandom; ++i)
  {
    pts.push_back({ dom[0] + U(rng) * (dom[3] - dom[0]), dom[1] + U(rng) * (dom[4] - dom[1]),
      dom[2] + U(rng) * (dom[5] - dom[2]) });
  }
  const std::size_t n = boxes.size() / 6;
  for (std::size_t e = 0; e < n; ++e)
  {
    const double* b = boxes.data() + 6 * e;
    for (int c = 0; c < 8; ++c) // corners
    {
      pts.push_back({ b[(c & 1) ? 3 : 0], b[(c & 2) ? 4 : 1], b[(c & 4) ? 5 : 2] });
    }
    const double m[3] = { 0.5 * (b[0] + b[3]), 0.5 * (b[1] + b[4]), 0.5 * (b[2] + b[5]) };
    for (int d = 0; d < 3; ++d) // face centres
    {
      std::array<double, 3> lo = { m[0], m[1], m[2] }, hi = lo;
      lo[d] = b[d];
      hi[d] = b[d + 3];
      pts.push_back(lo);
      pts.push_back(hi);
      // edge midpoints along d
      std::array<double, 3> edge = { b[0], b[1], b[2] };
      edge[d] = m[d];
      pts.push_back(edge);
      const int o = (d + 1) % 3;
      edge[o] = b[o + 3];
      pts.push_back(edge);
    }
  }
  for (int i = 0; i < 300; ++i) // upper faces, edges and corner of the domain
  {
    std::array<double, 3> p = { dom[0] + U(rng) * (dom[3] - dom[0]),
      dom[1] + U(rng) * (dom[4] - dom[1]), dom[2] + U(rng) * (dom[5] - dom[2]) };
    p[i % 3] = dom[i % 3 + 3];
    if (i % 7 == 0)
    {
      p[(i + 1) % 3] = dom[(i + 1) % 3 + 3];
    }
    pts.push_back(p);
  }
  pts.push_back({ dom[3], dom[4], dom[5] });
  pts.push_back({ dom[0], dom[1], dom[2] });
  return pts;
}

void CheckAgreement(
  SplineVizTestStatus& status, const std::vector<double>& boxes, bool dyadic, const char* label)
{
  const vtkIdType n = static_cast<vtkIdType>(boxes.size() / 6);
  double dom[6] = { 1e300, 1e300, 1e300, -1e300, -1e300, -1e300 };
  for (vtkIdType e = 0; e < n; ++e)
  {
    for (int d = 0; d < 3; ++d)
    {
      dom[d] = std::min(dom[d], boxes[6 * e + d]);
      dom[d + 3] = std::max(dom[d + 3], boxes[6 * e + d + 3]);
    }
  }
  struct Config
  {
    int Type;
    int Blocks[3];
  };
  std::vector<Config> configs = { { vtkLRSplineElementLocator::LINEAR, { 0, 0, 0 } },
    { vtkLRSplineElementLocator::KD_TREE, { 0, 0, 0 } },
    { vtkLRSplineElementLocator::KD_FOREST, { 8, 8, 8 } },
    { vtkLRSplineElementLocator::KD_FOREST, { 7, 5, 3 } },
    { vtkLRSplineElementLocator::KD_FOREST, { 64, 64, 64 } },
    { vtkLRSplineElementLocator::OCTREE, { 0, 0, 0 } },
    { vtkLRSplineElementLocator::TEXTURE, { 0, 0, 0 } } };
  std::vector<vtkLRSplineElementLocator> locators(configs.size());
  std::vector<bool> built(configs.size(), false);
  std::cout << label << ": " << n << " elements\n"
            << "  structure            blocks     nodes   min  max   mean depth  var depth\n";
  for (std::size_t c = 0; c < configs.size(); ++c)
  {
    std::string error;
    built[c] = locators[c].Build(boxes.data(), n, configs[c].Type, configs[c].Blocks, &error);
    const bool needsDyadic = configs[c].Type == vtkLRSplineElementLocator::OCTREE ||
      configs[c].Type == vtkLRSplineElementLocator::TEXTURE;
    if (needsDyadic && !dyadic)
    {
      SV_CHECK_MSG(status, !built[c],
        label << ": " << vtkLRSplineElementLocator::GetTypeName(configs[c].Type)
              << " accepted non-dyadic knots");
      SV_CHECK(status, error.find("dyadic") != std::string::npos);
      continue;
    }
    SV_CHECK_MSG(status, built[c], label << ": " << error);
    const auto& st = locators[c].GetStatistics();
    std::cout << "  " << std::setw(18) << vtkLRSplineElementLocator::GetTypeName(configs[c].Type)
              << std::setw(9) << st.NumberOfBlocks << std::setw(10) << st.NumberOfNodes
              << std::setw(6) << st.MinDepth << std::setw(5) << st.MaxDepth << std::setw(12)
              << st.MeanDepth << std::setw(11) << st.VarianceDepth << "\n";
  }
  // Finer forests are shallower (the paper's observation).
  SV_CHECK(status, locators[4].GetStatistics().MeanDepth <= locators[2].GetStatistics().MeanDepth);
  SV_CHECK(status, locators[2].GetStatistics().MaxDepth <= locators[1].GetStatistics().MaxDepth);

  const auto pts = Points(boxes, dom, 42, 20000);
  int mismatches = 0, notUnique = 0;
  for (const auto& p : pts)
  {
    int count = 0;
    const vtkIdType ref = ScanContaining(boxes, dom, p.data(), count);
    if (count != 1)
    {
      ++notUnique;
    }
    for (std::size_t c = 0; c < configs.size(); ++c)
    {
      if (!built[c])
      {
        continue;
      }
      const vtkIdType e = locators[c].FindElement(p.data());
      if (e != ref)
      {
        if (++mismatches < 10)
        {
          std::cerr << label << ": " << vtkLRSplineElementLocator::GetTypeName(configs[c].Type)
                    << " found " << e << ", expected " << ref << " at " << std::setprecision(17)
                    << p[0] << " " << p[1] << " " << p[2] << std::endl;
        }
      }
    }
  }
  std::cout << "  " << pts.size() << " points compared" << std::endl;
  SV_CHECK_MSG(status, notUnique == 0,
    label << ": " << notUnique << " points not in exactly one element (the mesh does not tile)");
  SV_CHECK_MSG(status, mismatches == 0, label << ": " << mismatches << " mismatches");

  // Outside points and NaN.
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double outside[4][3] = { { dom[3] + 1e-12 * (dom[3] - dom[0]) + 1e-300, dom[1], dom[2] },
    { dom[0], std::nextafter(dom[1], -1e300), dom[2] }, { nan, dom[1], dom[2] },
    { dom[0], dom[1], std::nextafter(dom[5], 1e300) } };
  for (std::size_t c = 0; c < configs.size(); ++c)
  {
    if (!built[c])
    {
      continue;
    }
    for (const auto& p : outside)
    {
      SV_CHECK(status, locators[c].FindElement(p) == -1);
    }
  }

  // Range queries (open boxes) against a scan.
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  int rangeMismatch = 0;
  for (int i = 0; i < 200; ++i)
  {
    double q[6];
    for (int d = 0; d < 3; ++d)
    {
      double a = dom[d] + U(rng) * (dom[d + 3] - dom[d]);
      double b = a + 0.2 * U(rng) * (dom[d + 3] - dom[d]);
      if (i % 5 == 0) // exactly an element's box
      {
        const vtkIdType e = i % n;
        a = boxes[6 * e + d];
        b = boxes[6 * e + d + 3];
      }
      q[d] = a;
      q[d + 3] = b;
    }
    std::vector<vtkIdType> ref;
    for (vtkIdType e = 0; e < n; ++e)
    {
      bool meets = true;
      for (int d = 0; d < 3; ++d)
      {
        meets = meets && boxes[6 * e + d] < q[d + 3] && boxes[6 * e + d + 3] > q[d];
      }
      if (meets)
      {
        ref.push_back(e);
      }
    }
    for (std::size_t c : { 1, 2, 3 })
    {
      std::vector<vtkIdType> got;
      locators[c].FindElementsIntersecting(q, got);
      rangeMismatch += got != ref ? 1 : 0;
    }
  }
  SV_CHECK_MSG(status, rangeMismatch == 0, label << ": range query mismatches " << rangeMismatch);
}
}

int TestLRSplineLocator(int, char*[])
{
  SplineVizTestStatus status;

  // The real file (dyadic knots).
  {
    std::vector<vtkLRSplinePatch> patches;
    std::string error;
    SV_CHECK(status,
      vtkLRSplineParser::Parse(
        lrtest::ReadText(std::string(SPLINEVIZ_EXTERNAL_DATA_DIR) + "/cube-3patch-refined.lr"),
        vtkLRSplineParser::AUTOMATIC, patches, &error));
    if (!patches.empty())
    {
      CheckAgreement(status, patches[0].ElementBoxes, true, "cube-3patch-refined.lr patch 0");
    }
  }

  const int degree[3] = { 2, 2, 2 };
  // Generated, non-dyadic: irrational breakpoints and golden-section splits,
  // several refinement levels around three points.
  {
    vtkLRSplineBuilder builder;
    const std::vector<double> breaks[3] = { { 0, 1.0 / 3.0, std::sqrt(0.5), 1.0 }, { 0, 0.5, 1.0 },
      { 0, 0.25, 1.0 / std::sqrt(3.0), 1.0 } };
    std::string error;
    SV_CHECK(status, builder.InitializeTensorProduct(degree, breaks, 1, &error));
    const double golden = 0.5 * (std::sqrt(5.0) - 1.0);
    const double targets[3][3] = { { 0.2, 0.7, 0.3 }, { 0.9, 0.1, 0.8 }, { 0.5, 0.5, 0.5 } };
    for (int level = 0; level < 5; ++level)
    {
      for (const auto& t : targets)
      {
        SV_CHECK_MSG(status, builder.RefineAt(t, level % 2 ? golden : 1.0 - golden, &error), error);
      }
    }
    CheckAgreement(status, builder.GetPatch().ElementBoxes, false, "generated non-dyadic");
  }
  // Generated, dyadic, deep refinement at one point (octree and texture apply).
  {
    vtkLRSplineBuilder builder;
    const std::vector<double> breaks[3] = { { 0, 0.25, 0.5, 0.75, 1.0 }, { 0, 0.5, 1.0 },
      { 0, 0.5, 1.0 } };
    std::string error;
    SV_CHECK(status, builder.InitializeTensorProduct(degree, breaks, 1, &error));
    const double t[3] = { 0.3, 0.6, 0.45 };
    for (int level = 0; level < 6; ++level)
    {
      SV_CHECK_MSG(status, builder.RefineAt(t, 0.5, &error), error);
    }
    CheckAgreement(status, builder.GetPatch().ElementBoxes, true, "generated dyadic");
  }
  return status.Result();
}
