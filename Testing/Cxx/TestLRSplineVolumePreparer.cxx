// SPDX-License-Identifier: BSD-3-Clause
// Unit test of vtkLRSplineVolumePreparer, the CPU side of
// vtkLRSplineVolumeMapper (the flat arrays it uploads), without OpenGL, on the
// real three-patch file (k-d forest, 8^3 forest, octree) and on two small
// built patches of different degrees and two components (k-d forest and tree,
// octree, look-up texture: degree elevation to the common degrees), checked
// independently of the production flattening:
//  - sampled points (every element's centre, random points): the patch's
//    placement (PatchInfo) maps the physical point back to its parameters in
//    single precision, the element is found in the flattened search
//    structure by the shader's own code (vtkLRSplineVolumeMath.h) at the
//    patch's starts, the point lies in that element's box, and the element's
//    Bezier coefficients, summed with a separately written de Casteljau
//    tensor product, give the value of the brute-force LR B-spline reference
//    (Testing/Cxx/LRSplineTestUtilities.h: truncated powers, from the .lr
//    text) and of vtkLRSplineField within 1e-6 of the largest coefficient;
//    that value lies in the element's component range;
//  - the element boxes are the .lr file's elements, lie in the patch's
//    domain, do not overlap and fill it (their volumes sum to the domain's);
//  - the component ranges are the min / max of the element's coefficients,
//    the magnitude ranges bound the magnitude; skip flags: with a visible
//    value, exactly the elements whose range misses it are flagged (some
//    are, some are not), all or none for ranges outside / covering all;
//  - negative controls: one perturbed coefficient, two swapped offsets and a
//    duplicated box are caught by the same checks;
//  - bad input (polygonal data, degree 4, a missing array, no input) fails
//    with the field's own message; a rebuild only on a new input or settings
//    (the skip key then cleared); good input again works.
#include "LRSplineTestUtilities.h"
#include "LRSplineVolumeTestUtilities.h"
#include "SplineVizTestUtilities.h"

#include "vtkLRSplineVolumeMath.h"
#include "vtkLRSplineVolumePreparer.h"

#include "vtkLRSplineBuilder.h"
#include "vtkLRSplineElementLocator.h"
#include "vtkLRSplineField.h"
#include "vtkLRSplineReader.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <iostream>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace
{
using PatchInfo = vtkLRSplineVolumePreparer::PatchInfo;

// Copies of the preparer's arrays (the negative controls perturb them).
struct Arrays
{
  std::vector<PatchInfo> Patches;
  std::vector<std::uint32_t> Heads, NodeWords, Octree, Offsets;
  std::vector<float> NodeSplits, Boxes, Coefficients;
  int Degree[3] = { 0, 0, 0 };
  int NumberOfComponents = 0;
};

Arrays CopyArrays(const vtkLRSplineVolumePreparer* p)
{
  Arrays a;
  a.Patches = p->GetPatches();
  a.Heads = p->GetHeads();
  a.NodeWords = p->GetNodeWords();
  a.Octree = p->GetOctree();
  a.Offsets = p->GetOffsets();
  a.NodeSplits = p->GetNodeSplits();
  a.Boxes = p->GetBoxes();
  a.Coefficients = p->GetCoefficients();
  std::copy(p->GetDegree(), p->GetDegree() + 3, a.Degree);
  a.NumberOfComponents = p->GetNumberOfComponents();
  return a;
}

// The elements of patch q: [first, end).
void ElementRange(const Arrays& a, int q, vtkIdType& first, vtkIdType& end)
{
  first = a.Patches[q].Starts[3];
  end = q + 1 < static_cast<int>(a.Patches.size()) ? a.Patches[q + 1].Starts[3]
                                                   : static_cast<vtkIdType>(a.Offsets.size());
}

// de Casteljau on n + 1 values (modified in place).
double DeCasteljau(std::vector<double> c, double s)
{
  for (std::size_t r = 1; r < c.size(); ++r)
  {
    for (std::size_t i = 0; i + r < c.size(); ++i)
    {
      c[i] = (1.0 - s) * c[i] + s * c[i + 1];
    }
  }
  return c[0];
}

// Component `comp` of the Bezier volume with coefficients `c` (coefficient
// (i, j, k) of component comp at ((k (d1 + 1) + j) (d0 + 1) + i) nc + comp)
// at local s: de Casteljau along u for every (j, k), then v, then w.
double Bezier(const float* c, const int d[3], int nc, int comp, const double s[3])
{
  std::vector<double> layer(d[2] + 1);
  for (int k = 0; k <= d[2]; ++k)
  {
    std::vector<double> column(d[1] + 1);
    for (int j = 0; j <= d[1]; ++j)
    {
      std::vector<double> row(d[0] + 1);
      for (int i = 0; i <= d[0]; ++i)
      {
        row[i] = c[((k * (d[1] + 1) + j) * (d[0] + 1) + i) * nc + comp];
      }
      column[j] = DeCasteljau(row, s[0]);
    }
    layer[k] = DeCasteljau(column, s[1]);
  }
  return DeCasteljau(layer, s[2]);
}

// The brute-force reference at parameter u: sum of gamma c B over the basis
// functions whose support holds u (lrtest::BruteForce with a support test
// first, for speed).
void Reference(const lrtest::BrutePatch& P, const double u[3], double* out)
{
  std::fill(out, out + P.Dim, 0.0);
  bool fromLeft[3];
  for (int d = 0; d < 3; ++d)
  {
    fromLeft[d] = u[d] == P.Domain[d + 3];
  }
  for (std::size_t i = 0; i < P.Gamma.size(); ++i)
  {
    bool inside = true;
    for (int d = 0; d < 3 && inside; ++d)
    {
      const std::vector<double>& t = P.Knots[i][d];
      inside = u[d] >= t.front() && u[d] <= t.back();
    }
    if (!inside)
    {
      continue;
    }
    double b = P.Gamma[i];
    for (int d = 0; d < 3 && b != 0.0; ++d)
    {
      b *= lrtest::TruncatedPowerBSpline(P.Knots[i][d], u[d], fromLeft[d]);
    }
    for (int c = 0; c < P.Dim; ++c)
    {
      out[c] += b * P.Coef[i * P.Dim + c];
    }
  }
}

double LargestCoefficient(const lrtest::BrutePatch& P)
{
  double m = 0.0;
  for (double c : P.Coef)
  {
    m = std::max(m, std::abs(c));
  }
  return std::max(m, 1e-30);
}

struct SampleReport
{
  long long Points = 0, NotFound = 0, OutsideBox = 0, Wrong = 0, OutsideRange = 0;
  double MaxReferenceError = 0.0, MaxFieldError = 0.0;
  bool Good() const { return NotFound + OutsideBox + Wrong + OutsideRange == 0 && Points > 0; }
};

// The sampled-point check of the arrays `a` (see the file comment); `ranges`
// the preparer's component ranges; `quiet`: no messages (negative controls).
SampleReport CheckSamples(const Arrays& a, const std::vector<float>& ranges,
  const vtkLRSplineField& field, const std::vector<lrtest::BrutePatch>& brute, int randomPoints,
  bool quiet = false)
{
  SampleReport report;
  vtkLRSplineVolumeMath::Data data;
  data.Heads = a.Heads.data();
  data.NodeWords = a.NodeWords.data();
  data.NodeSplits = a.NodeSplits.data();
  data.Octree = a.Octree.data();
  data.Coefficients = a.Coefficients.data();
  vtkLRSplineVolumeMath::SetData(&data);
  const int nc = a.NumberOfComponents;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  for (int q = 0; q < static_cast<int>(a.Patches.size()); ++q)
  {
    const PatchInfo& info = a.Patches[q];
    const lrtest::BrutePatch& P = brute[q];
    const vtkLRSplineEvaluator& patch = field.GetPatch(q);
    const double scale = LargestCoefficient(P);
    std::vector<std::array<double, 3>> points;
    for (const auto& b : P.Elements)
    {
      points.push_back({ 0.5 * (b[0] + b[3]), 0.5 * (b[1] + b[4]), 0.5 * (b[2] + b[5]) });
    }
    for (int i = 0; i < randomPoints; ++i)
    {
      std::array<double, 3> u;
      for (int d = 0; d < 3; ++d)
      {
        u[d] = P.Domain[d] + U(rng) * (P.Domain[d + 3] - P.Domain[d]);
      }
      points.push_back(u);
    }
    const glm::vec3 lo(info.Lo[0], info.Lo[1], info.Lo[2]);
    const glm::vec3 hi(info.Hi[0], info.Hi[1], info.Hi[2]);
    const glm::ivec3 blocks(info.Blocks[0], info.Blocks[1], info.Blocks[2]);
    for (const auto& up : points)
    {
      ++report.Points;
      double x[3];
      patch.ParameterToPhysical(up.data(), x);
      // The shader's map back to parameters (single precision), clamped to
      // the patch's domain.
      glm::vec3 u;
      for (int r = 0; r < 3; ++r)
      {
        float v = 0.0f;
        for (int c = 0; c < 3; ++c)
        {
          v += info.Inverse[3 * r + c] * (static_cast<float>(x[c]) - info.Offset[c]);
        }
        u[r] = std::min(hi[r], std::max(lo[r], v));
      }
      const int local = info.Locator == 0
        ? vtkLRSplineVolumeMath::lrFindForest(u, lo, hi, blocks, info.Starts[0], info.Starts[1])
        : vtkLRSplineVolumeMath::lrFindOctree(u, lo, hi, info.Starts[2]);
      if (local < 0)
      {
        ++report.NotFound;
        continue;
      }
      const vtkIdType e = local + info.Starts[3];
      const float* box = &a.Boxes[8 * e];
      double s[3], ud[3];
      bool inBox = true;
      for (int d = 0; d < 3; ++d)
      {
        ud[d] = u[d];
        const double size = box[d + 4] - box[d];
        const double tol = 1e-5 * (P.Domain[d + 3] - P.Domain[d]);
        inBox = inBox && ud[d] >= box[d] - tol && ud[d] <= box[d + 4] + tol;
        s[d] = std::min(1.0, std::max(0.0, (ud[d] - box[d]) / size));
      }
      if (!inBox)
      {
        if (report.OutsideBox++ < 3 && !quiet)
        {
          std::cerr << "  patch " << q << ": (" << ud[0] << ", " << ud[1] << ", " << ud[2]
                    << ") is not in element " << e << "'s box" << std::endl;
        }
        continue;
      }
      std::vector<double> reference(nc), production(nc);
      Reference(P, ud, reference.data());
      double xd[3];
      patch.ParameterToPhysical(ud, xd);
      patch.Evaluate(xd, production.data());
      bool wrong = false;
      for (int c = 0; c < nc; ++c)
      {
        const double v = Bezier(&a.Coefficients[a.Offsets[e]], a.Degree, nc, c, s);
        const double toReference = std::abs(v - reference[c]) / scale;
        const double toField = std::abs(v - production[c]) / scale;
        report.MaxReferenceError = std::max(report.MaxReferenceError, toReference);
        report.MaxFieldError = std::max(report.MaxFieldError, toField);
        wrong = wrong || !(toReference <= 1e-6 && toField <= 1e-6);
        const float* r = &ranges[2 * (nc * e + c)];
        const double tol = 1e-6 * scale;
        if (!(reference[c] >= r[0] - tol && reference[c] <= r[1] + tol))
        {
          ++report.OutsideRange;
        }
      }
      if (wrong && report.Wrong++ < 3 && !quiet)
      {
        std::cerr << "  patch " << q << ", element " << e << ": the Bezier value differs from the "
                  << "reference at (" << ud[0] << ", " << ud[1] << ", " << ud[2] << ")"
                  << std::endl;
      }
    }
  }
  vtkLRSplineVolumeMath::SetData(nullptr);
  return report;
}

// Boxes of the elements of every patch against the .lr elements; overlaps
// and the covered volume. Returns the number of problems.
long long CheckBoxes(const Arrays& a, const std::vector<lrtest::BrutePatch>& brute,
  const std::string& what, bool quiet = false)
{
  long long problems = 0;
  auto problem = [&](const std::string& message)
  {
    if (!quiet && problems < 5)
    {
      std::cerr << "  " << what << ": " << message << std::endl;
    }
    ++problems;
  };
  for (int q = 0; q < static_cast<int>(a.Patches.size()); ++q)
  {
    const lrtest::BrutePatch& P = brute[q];
    vtkIdType first, end;
    ElementRange(a, q, first, end);
    std::vector<std::array<double, 6>> boxes, expected;
    for (vtkIdType e = first; e < end; ++e)
    {
      const float* b = &a.Boxes[8 * e];
      boxes.push_back({ b[0], b[1], b[2], b[4], b[5], b[6] });
    }
    for (const auto& b : P.Elements)
    {
      expected.push_back(
        { static_cast<float>(b[0]), static_cast<float>(b[1]), static_cast<float>(b[2]),
          static_cast<float>(b[3]), static_cast<float>(b[4]), static_cast<float>(b[5]) });
    }
    double domainVolume = 1.0, extent = 0.0;
    for (int d = 0; d < 3; ++d)
    {
      domainVolume *= P.Domain[d + 3] - P.Domain[d];
      extent = std::max(extent, P.Domain[d + 3] - P.Domain[d]);
      if (std::abs(a.Patches[q].Lo[d] - P.Domain[d]) > 1e-6 * extent ||
        std::abs(a.Patches[q].Hi[d] - P.Domain[d + 3]) > 1e-6 * extent)
      {
        problem("patch " + std::to_string(q) + ": domain is not the file's");
      }
    }
    std::sort(boxes.begin(), boxes.end());
    std::sort(expected.begin(), expected.end());
    if (boxes != expected)
    {
      problem("patch " + std::to_string(q) + ": the element boxes are not the file's elements");
    }
    const double tol = 1e-6 * extent;
    double volume = 0.0;
    for (std::size_t i = 0; i < boxes.size(); ++i)
    {
      const auto& b = boxes[i];
      double v = 1.0;
      for (int d = 0; d < 3; ++d)
      {
        v *= b[d + 3] - b[d];
        if (!(b[d] >= P.Domain[d] - tol && b[d + 3] <= P.Domain[d + 3] + tol && b[d + 3] > b[d]))
        {
          problem("patch " + std::to_string(q) + ": a box outside the domain or empty");
        }
      }
      volume += v;
      // Sorted by the lower x: only the following boxes that start before
      // this one ends can overlap it.
      for (std::size_t j = i + 1; j < boxes.size() && boxes[j][0] < b[3] - tol; ++j)
      {
        const auto& c = boxes[j];
        bool overlap = true;
        for (int d = 0; d < 3; ++d)
        {
          overlap = overlap && std::min(b[d + 3], c[d + 3]) - std::max(b[d], c[d]) > tol;
        }
        if (overlap)
        {
          problem("patch " + std::to_string(q) + ": two element boxes overlap");
        }
      }
    }
    if (!(std::abs(volume - domainVolume) <= 1e-5 * domainVolume))
    {
      problem("patch " + std::to_string(q) + ": the boxes' volume " + std::to_string(volume) +
        " is not the domain's " + std::to_string(domainVolume));
    }
  }
  return problems;
}

// Ranges and skip flags (see the file comment).
void CheckRangesAndSkipping(
  SplineVizTestStatus& status, vtkLRSplineVolumePreparer* prep, const std::string& what)
{
  const Arrays a = CopyArrays(prep);
  const int nc = a.NumberOfComponents;
  const int per = (a.Degree[0] + 1) * (a.Degree[1] + 1) * (a.Degree[2] + 1) * nc;
  const vtkIdType ne = static_cast<vtkIdType>(a.Offsets.size());
  const std::vector<float>& ranges = prep->GetComponentRanges();
  const std::vector<float>& magnitudes = prep->GetMagnitudeRanges();
  SV_CHECK(status, ranges.size() == static_cast<std::size_t>(2 * nc * ne));
  SV_CHECK(status, magnitudes.size() == static_cast<std::size_t>(2 * ne));
  // Independent ranges: min / max of the element's coefficients.
  std::vector<std::array<double, 2>> independent(nc * ne);
  long long rangeErrors = 0, magnitudeErrors = 0;
  for (vtkIdType e = 0; e < ne; ++e)
  {
    const float* c = &a.Coefficients[a.Offsets[e]];
    double magnitudeHigh = 0.0, magnitudeLow = 0.0;
    for (int comp = 0; comp < nc; ++comp)
    {
      double lo = std::numeric_limits<double>::infinity(), hi = -lo;
      for (int i = comp; i < per; i += nc)
      {
        lo = std::min(lo, static_cast<double>(c[i]));
        hi = std::max(hi, static_cast<double>(c[i]));
      }
      independent[nc * e + comp] = { lo, hi };
      rangeErrors += ranges[2 * (nc * e + comp)] != lo || ranges[2 * (nc * e + comp) + 1] != hi;
      magnitudeLow = std::max(magnitudeLow, lo > 0 ? lo : (hi < 0 ? -hi : 0.0));
    }
    for (int i = 0; i < per; i += nc)
    {
      double m2 = 0.0;
      for (int comp = 0; comp < nc; ++comp)
      {
        m2 += static_cast<double>(c[i + comp]) * c[i + comp];
      }
      magnitudeHigh = std::max(magnitudeHigh, std::sqrt(m2));
    }
    const double tol = 1e-6 * std::max(1.0, magnitudeHigh);
    magnitudeErrors += std::abs(magnitudes[2 * e] - magnitudeLow) > tol ||
      std::abs(magnitudes[2 * e + 1] - magnitudeHigh) > tol;
    float r[2];
    prep->GetValueRange(e, -1, r);
    magnitudeErrors += nc > 1 && (r[0] != magnitudes[2 * e] || r[1] != magnitudes[2 * e + 1]);
  }
  SV_CHECK_MSG(status, rangeErrors == 0, what + ": component ranges are not the coefficients'");
  SV_CHECK_MSG(status, magnitudeErrors == 0, what + ": magnitude ranges");

  // Skip flags for one visible value of the last component: the median of
  // the elements' midpoints (some elements hold it, some do not).
  const int comp = nc - 1;
  std::vector<double> mids;
  double lowest = std::numeric_limits<double>::infinity(), highest = -lowest;
  for (vtkIdType e = 0; e < ne; ++e)
  {
    mids.push_back(0.5 * (independent[nc * e + comp][0] + independent[nc * e + comp][1]));
    lowest = std::min(lowest, independent[nc * e + comp][0]);
    highest = std::max(highest, independent[nc * e + comp][1]);
  }
  std::nth_element(mids.begin(), mids.begin() + mids.size() / 2, mids.end());
  const double t = mids[mids.size() / 2];
  const vtkIdType skipped = prep->UpdateSkipFlags(comp, { { t, t } });
  long long expectedSkipped = 0, flagErrors = 0;
  vtkIdType flaggedExample = -1, keptExample = -1;
  for (vtkIdType e = 0; e < ne; ++e)
  {
    const bool outside =
      !(independent[nc * e + comp][0] <= t && t <= independent[nc * e + comp][1]);
    const float flag = prep->GetBoxes()[8 * e + 3];
    expectedSkipped += outside;
    flagErrors += flag != (outside ? 1.0f : 0.0f);
    (outside ? flaggedExample : keptExample) = e;
  }
  std::cout << what << ": visible value " << t << " of component " << comp << ": " << skipped
            << " of " << ne << " elements skipped" << std::endl;
  SV_CHECK_MSG(status, flagErrors == 0, what + ": skip flags differ from the ranges");
  SV_CHECK(status, skipped == expectedSkipped && skipped == prep->GetNumberOfSkippedElements());
  SV_CHECK_MSG(status, flaggedExample >= 0 && keptExample >= 0,
    what + ": the visible value should split the elements");
  // Every other array is untouched by the flags.
  const Arrays b = CopyArrays(prep);
  SV_CHECK(status, b.Coefficients == a.Coefficients && b.Offsets == a.Offsets);
  // A range below all values: everything skipped; one covering all: nothing.
  SV_CHECK(status, prep->UpdateSkipFlags(comp, { { lowest - 2.0, lowest - 1.0 } }) == ne);
  SV_CHECK(status,
    prep->UpdateSkipFlags(comp, { { lowest - 2.0, lowest - 1.0 }, { lowest, highest } }) == 0);
  SV_CHECK(status, prep->UpdateSkipFlags(-1, [](double, double) { return true; }) == ne);
  SV_CHECK(status, prep->UpdateSkipFlags(-1, [](double, double) { return false; }) == 0);
}

// Build `input` with the preparer and check everything.
void CheckInput(SplineVizTestStatus& status, vtkDataObject* input,
  const std::vector<lrtest::BrutePatch>& brute, int locator, int resolution,
  const std::string& what)
{
  vtkNew<vtkLRSplineVolumePreparer> prep;
  if (!prep->Update(input, nullptr, locator, resolution))
  {
    status.Fail(what + ": " + prep->GetErrorMessage(), __FILE__, __LINE__);
    return;
  }
  SV_CHECK(status, prep->IsValid() && prep->GetErrorMessage().empty());
  SV_CHECK(status, prep->GetNumberOfPatches() == static_cast<int>(brute.size()));
  if (prep->GetNumberOfPatches() != static_cast<int>(brute.size()))
  {
    return;
  }
  std::size_t elements = 0;
  int degree[3] = { 0, 0, 0 };
  for (const auto& P : brute)
  {
    elements += P.Elements.size();
    for (int d = 0; d < 3; ++d)
    {
      degree[d] = std::max(degree[d], P.Order[d] - 1);
    }
  }
  const Arrays a = CopyArrays(prep);
  SV_CHECK(status, a.Offsets.size() == elements && a.Boxes.size() == 8 * elements);
  SV_CHECK(
    status, a.Degree[0] == degree[0] && a.Degree[1] == degree[1] && a.Degree[2] == degree[2]);
  SV_CHECK(status, a.NumberOfComponents == brute[0].Dim);
  const int per = (degree[0] + 1) * (degree[1] + 1) * (degree[2] + 1) * a.NumberOfComponents;
  SV_CHECK(status, a.Coefficients.size() == elements * per);
  SV_CHECK(status,
    prep->GetNumberOfBytes() ==
      4 *
        (a.Heads.size() + a.NodeWords.size() + a.NodeSplits.size() + a.Octree.size() +
          a.Offsets.size() + a.Boxes.size() + a.Coefficients.size()));

  const SampleReport r = CheckSamples(a, prep->GetComponentRanges(), prep->GetField(), brute, 300);
  std::cout << what << ": " << r.Points << " points: " << r.NotFound << " not found, "
            << r.OutsideBox << " outside their element's box, " << r.Wrong << " wrong values, "
            << r.OutsideRange
            << " outside the element's range; largest error (relative to the largest "
               "coefficient) "
            << r.MaxReferenceError << " to the brute-force reference, " << r.MaxFieldError
            << " to vtkLRSplineField" << std::endl;
  SV_CHECK_MSG(status, r.Good(), what + ": sampled points");
  SV_CHECK_MSG(status, CheckBoxes(a, brute, what) == 0, what + ": element boxes");
  CheckRangesAndSkipping(status, prep, what);

  // Negative controls.
  {
    // One coefficient of the middle element of the first patch.
    Arrays bad = a;
    const vtkIdType e = static_cast<vtkIdType>(brute[0].Elements.size() / 2);
    bad.Coefficients[bad.Offsets[e] + per / 2] += 1e-2 * LargestCoefficient(brute[0]);
    const SampleReport n =
      CheckSamples(bad, prep->GetComponentRanges(), prep->GetField(), brute, 0, true);
    std::cout << what << ": perturbed coefficient: " << n.Wrong << " wrong values" << std::endl;
    SV_CHECK_MSG(status, n.Wrong > 0, what + ": a perturbed coefficient is not caught");
  }
  {
    Arrays bad = a;
    std::swap(bad.Offsets[1], bad.Offsets[2]);
    const SampleReport n =
      CheckSamples(bad, prep->GetComponentRanges(), prep->GetField(), brute, 0, true);
    SV_CHECK_MSG(status, n.Wrong > 0, what + ": swapped coefficient offsets are not caught");
  }
  {
    Arrays bad = a;
    std::copy(&bad.Boxes[8], &bad.Boxes[16], &bad.Boxes[0]);
    SV_CHECK_MSG(
      status, CheckBoxes(bad, brute, what, true) > 0, what + ": a duplicated box is not caught");
  }
}

// A dyadic locally refined patch (uniform breaks, halving refinements), two
// components, written as .lr (and parsed for the reference) and read back.
vtkSmartPointer<vtkDataObject> BuiltPatch(const int degree[3], const double focus[3],
  const std::string& path, std::vector<lrtest::BrutePatch>& brute)
{
  if (!lrvolume::WriteDyadicVolume(degree, focus, 3, path))
  {
    return nullptr;
  }
  for (const auto& P : lrtest::ParseLR(lrtest::ReadText(path)))
  {
    brute.push_back(P);
  }
  vtkNew<vtkLRSplineReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  return reader->GetOutputDataObject(0);
}

// The requirements the preparer must check (written out here: its messages
// must be the field's for these).
vtkLRSplineField::Requirements VolumeMapperRequirements()
{
  vtkLRSplineField::Requirements needs;
  needs.Consumer = "the volume mapper";
  needs.Volume = true;
  needs.MaximumPatches = 16;
  needs.PolynomialField = true;
  needs.MaximumComponents = 3;
  needs.MaximumDegree = 3;
  needs.FiniteCoefficients = true;
  return needs;
}

void CheckBadInput(SplineVizTestStatus& status, vtkLRSplineVolumePreparer* prep,
  vtkDataObject* input, const char* arrayName, const std::string& what)
{
  vtkLRSplineField field;
  std::string expected;
  const bool built = field.Build(input, arrayName, vtkLRSplineElementLocator::KD_FOREST, nullptr,
    VolumeMapperRequirements(), &expected);
  SV_CHECK_MSG(status, !built, what + ": the field accepts it");
  const bool ok = prep->Update(input, arrayName, vtkLRSplineElementLocator::KD_FOREST, 0);
  std::cout << what << ": \"" << prep->GetErrorMessage() << "\"" << std::endl;
  SV_CHECK_MSG(status, !ok && !prep->IsValid(), what + ": accepted");
  SV_CHECK_MSG(status, !expected.empty() && prep->GetErrorMessage() == expected,
    what + ": the message is not the field's (\"" + expected + "\")");
}
}

int TestLRSplineVolumePreparer(int, char*[])
{
  SplineVizTestStatus status;
  const std::string dir = SPLINEVIZ_TEST_OUTPUT_DIR;

  // The real three-patch file.
  const std::string file = SPLINEVIZ_EXTERNAL_DATA_DIR "/cube-3patch-refined.lr";
  const std::vector<lrtest::BrutePatch> cube = lrtest::ParseLR(lrtest::ReadText(file));
  vtkNew<vtkLRSplineReader> reader;
  reader->SetFileName(file.c_str());
  reader->Update();
  vtkDataObject* real = reader->GetOutputDataObject(0);
  SV_CHECK(status, cube.size() == 3);
  CheckInput(status, real, cube, vtkLRSplineElementLocator::KD_FOREST, 0, "cube-3patch k-d forest");
  CheckInput(status, real, cube, vtkLRSplineElementLocator::KD_FOREST, 8, "cube-3patch 8^3 forest");
  CheckInput(status, real, cube, vtkLRSplineElementLocator::OCTREE, 0, "cube-3patch octree");

  // Two small built patches of different degrees: elevated to (3, 2, 2).
  std::vector<lrtest::BrutePatch> built;
  const int degreeA[3] = { 3, 2, 1 }, degreeB[3] = { 1, 1, 2 };
  const double focusA[3] = { 0.3, 0.6, 0.45 }, focusB[3] = { 0.7, 0.2, 0.8 };
  vtkSmartPointer<vtkDataObject> a =
    BuiltPatch(degreeA, focusA, dir + "/TestLRSplineVolumePreparer-a.lr", built);
  vtkSmartPointer<vtkDataObject> b =
    BuiltPatch(degreeB, focusB, dir + "/TestLRSplineVolumePreparer-b.lr", built);
  SV_CHECK(status, a && b && built.size() == 2);
  if (!a || !b || built.size() != 2)
  {
    return status.Result();
  }
  vtkNew<vtkMultiBlockDataSet> two;
  two->SetBlock(0, vtkMultiBlockDataSet::SafeDownCast(a)->GetBlock(0));
  two->SetBlock(1, vtkMultiBlockDataSet::SafeDownCast(b)->GetBlock(0));
  CheckInput(status, two, built, vtkLRSplineElementLocator::KD_FOREST, 0, "built k-d forest");
  CheckInput(status, two, built, vtkLRSplineElementLocator::KD_TREE, 0, "built k-d tree");
  CheckInput(status, two, built, vtkLRSplineElementLocator::OCTREE, 0, "built octree");
  CheckInput(status, two, built, vtkLRSplineElementLocator::TEXTURE, 0, "built texture");

  // Rebuilds: only for a new input or settings; a build clears the skip key.
  {
    vtkNew<vtkLRSplineVolumePreparer> prep;
    SV_CHECK(status, prep->Update(two, nullptr, vtkLRSplineElementLocator::KD_FOREST, 0));
    const vtkMTimeType first = prep->GetBuildTime();
    prep->SetSkipKey("some settings");
    SV_CHECK(status, prep->Update(two, nullptr, vtkLRSplineElementLocator::KD_FOREST, 0));
    SV_CHECK(status, prep->GetBuildTime() == first && prep->GetSkipKey() == "some settings");
    two->Modified();
    SV_CHECK(status, prep->Update(two, nullptr, vtkLRSplineElementLocator::KD_FOREST, 0));
    SV_CHECK(status, prep->GetBuildTime() > first && prep->GetSkipKey().empty());
    const vtkMTimeType second = prep->GetBuildTime();
    SV_CHECK(status, prep->Update(two, nullptr, vtkLRSplineElementLocator::KD_TREE, 0));
    SV_CHECK(status, prep->GetBuildTime() > second);

    // Bad input: the field's message; then good input again.
    vtkNew<vtkSphereSource> sphere;
    sphere->Update();
    CheckBadInput(status, prep, sphere->GetOutput(), nullptr, "polygonal data");
    CheckBadInput(status, prep, two, "NoSuchArray", "a missing array");
    {
      vtkLRSplineBuilder builder;
      const int degree[3] = { 4, 2, 2 };
      const std::vector<double> breaks[3] = { { 0, 0.5, 1 }, { 0, 1 }, { 0, 1 } };
      std::string error;
      SV_CHECK(status, builder.InitializeTensorProduct(degree, breaks, 1, &error));
      builder.SetCoefficientsFromGreville([](const double g[3], double* c) { c[0] = g[0]; });
      const std::string path = dir + "/TestLRSplineVolumePreparer-degree4.lr";
      {
        std::ofstream out(path);
        builder.GetPatch().Write(out);
      }
      vtkNew<vtkLRSplineReader> quartic;
      quartic->SetFileName(path.c_str());
      quartic->Update();
      CheckBadInput(status, prep, quartic->GetOutputDataObject(0), nullptr, "degree 4");
    }
    SV_CHECK(status, !prep->Update(nullptr, nullptr, vtkLRSplineElementLocator::KD_FOREST, 0));
    SV_CHECK(status, !prep->GetErrorMessage().empty());
    SV_CHECK(status, prep->Update(two, nullptr, vtkLRSplineElementLocator::KD_FOREST, 0));
    SV_CHECK(status, prep->IsValid() && prep->GetErrorMessage().empty());
    SV_CHECK(status,
      prep->GetNumberOfElements() ==
        static_cast<vtkIdType>(built[0].Elements.size() + built[1].Elements.size()));
    prep->Print(std::cout);
  }
  return status.Result();
}
