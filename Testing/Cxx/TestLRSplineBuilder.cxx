// SPDX-License-Identifier: BSD-3-Clause
// vtkLRSplineBuilder's refinement, against independent code (the brute-force
// Cox-de Boor sums of LRSplineTestUtilities.h on the written .lr files):
//  - RefineFunction gives exactly the patch that inserting its rectangles one
//    by one with InsertMeshRectangle gives (the order generated volumes have
//    always had);
//  - RefineFunctions (many functions at once, parents split first) gives the
//    same LR B-splines (knots and gammas) as inserting all those rectangles
//    one by one, and neither changes the spline (a quadratic and a cubic
//    volume with random coefficients, before and after, at random points)
//    nor the partition of unity;
//  - split values on a grid (voxel faces) and minimum parts are honoured;
//  - a large batch on a cubic volume is fast (inserting many rectangles at
//    once used to split a function again for every path it was reached on).
#include "vtkLRSplineBuilder.h"

#include "LRSplineTestUtilities.h"
#include "SplineVizTestUtilities.h"

#include <chrono>
#include <map>
#include <random>
#include <sstream>

namespace
{
lrtest::BrutePatch Brute(vtkLRSplineBuilder& builder)
{
  std::ostringstream os;
  builder.GetPatch().Write(os);
  return lrtest::ParseLR(os.str())[0];
}

std::map<std::vector<double>, double> Functions(vtkLRSplineBuilder& builder)
{
  const vtkLRSplinePatch& p = builder.GetPatch();
  std::map<std::vector<double>, double> m;
  const int kpf = p.GetKnotsPerFunction();
  for (vtkIdType f = 0; f < p.GetNumberOfBasisFunctions(); ++f)
  {
    m[std::vector<double>(p.Knots.begin() + f * kpf, p.Knots.begin() + (f + 1) * kpf)] +=
      p.Gamma[f];
  }
  return m;
}

void Initialize(vtkLRSplineBuilder& b, int degree, std::mt19937& rng)
{
  const int deg[3] = { degree, degree, degree };
  const std::vector<double> breaks[3] = { { 0, 4, 8, 12, 16 }, { 0, 5, 10, 15 },
    { 0, 3, 6, 9, 12 } };
  std::string error;
  b.InitializeTensorProduct(deg, breaks, 1, &error);
  std::uniform_real_distribution<double> uni(-1, 1);
  b.SetCoefficientsFromGreville([&](const double*, double* c) { c[0] = uni(rng); });
}

// The rectangles of the structured refinement of function f (midpoints).
void Rectangles(const vtkLRSplinePatch& p, vtkIdType f, std::vector<std::vector<double>>& out)
{
  double box[6];
  for (int d = 0; d < 3; ++d)
  {
    const double* t = p.GetKnots(f, d);
    box[d] = t[0];
    box[d + 3] = t[p.Order[d]];
  }
  for (int d = 0; d < 3; ++d)
  {
    const double* t = p.GetKnots(f, d);
    for (int k = 0; k < p.Order[d]; ++k)
    {
      if (t[k] < t[k + 1])
      {
        out.push_back({ static_cast<double>(d), 0.5 * (t[k] + t[k + 1]), box[0], box[1], box[2],
          box[3], box[4], box[5] });
      }
    }
  }
}

double MaxDifference(const lrtest::BrutePatch& a, const lrtest::BrutePatch& b, bool unity)
{
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(0, 1);
  double worst = 0.0;
  for (int s = 0; s < 200; ++s)
  {
    double u[3], va, vb;
    for (int d = 0; d < 3; ++d)
    {
      u[d] = a.Domain[d] + unit(rng) * (a.Domain[d + 3] - a.Domain[d]);
    }
    lrtest::BruteForce(a, u, &va);
    if (unity)
    {
      // sum of gamma_i B_i: a patch whose coefficients are all 1
      lrtest::BrutePatch ones = b;
      std::fill(ones.Coef.begin(), ones.Coef.end(), 1.0);
      lrtest::BruteForce(ones, u, &vb);
      worst = std::max(worst, std::abs(vb - 1.0));
      continue;
    }
    lrtest::BruteForce(b, u, &vb);
    worst = std::max(worst, std::abs(va - vb));
  }
  return worst;
}
}

int TestLRSplineBuilder(int, char*[])
{
  SplineVizTestStatus status;
  std::string error;
  for (int degree : { 2, 3 })
  {
    std::mt19937 rng(degree);
    // RefineFunction == its rectangles one by one.
    {
      vtkLRSplineBuilder a, b;
      Initialize(a, degree, rng);
      std::mt19937 rng2(degree);
      Initialize(b, degree, rng2);
      for (int round = 0; round < 6; ++round)
      {
        const vtkLRSplinePatch& p = a.GetPatch();
        const vtkIdType f = (round * 37) % p.GetNumberOfBasisFunctions();
        std::vector<std::vector<double>> rects;
        Rectangles(p, f, rects);
        SV_CHECK(status, a.RefineFunction(f, 0.5, &error));
        for (const auto& r : rects)
        {
          SV_CHECK_MSG(status,
            b.InsertMeshRectangle(static_cast<int>(r[0]), r[1], r.data() + 2, &error), error);
        }
      }
      const vtkLRSplinePatch& pa = a.GetPatch();
      const vtkLRSplinePatch& pb = b.GetPatch();
      SV_CHECK(status,
        pa.Knots == pb.Knots && pa.Gamma == pb.Gamma && pa.ElementBoxes == pb.ElementBoxes &&
          pa.Coefficients == pb.Coefficients);
    }
    // A batch == all its rectangles one by one; the spline is unchanged.
    {
      vtkLRSplineBuilder a, b;
      Initialize(a, degree, rng);
      std::mt19937 rng2(degree + 100);
      Initialize(b, degree, rng2);
      b.SetCoefficients(a.GetPatch().Coefficients);
      const lrtest::BrutePatch before = Brute(a);
      for (int round = 0; round < 2; ++round)
      {
        const vtkLRSplinePatch& p = a.GetPatch();
        std::vector<vtkIdType> ids;
        std::vector<std::vector<double>> rects;
        for (vtkIdType f = round; f < p.GetNumberOfBasisFunctions(); f += 7 + 4 * round)
        {
          ids.push_back(f);
          Rectangles(p, f, rects);
        }
        vtkLRSplineBuilder::RefineOptions options;
        vtkIdType inserted = 0;
        SV_CHECK_MSG(status, a.RefineFunctions(ids, options, &error, &inserted), error);
        SV_CHECK(status, inserted == static_cast<vtkIdType>(rects.size()));
        for (const auto& r : rects)
        {
          SV_CHECK_MSG(status,
            b.InsertMeshRectangle(static_cast<int>(r[0]), r[1], r.data() + 2, &error), error);
        }
        const auto fa = Functions(a), fb = Functions(b);
        bool same = fa.size() == fb.size();
        for (auto it = fa.begin(), jt = fb.begin(); same && it != fa.end(); ++it, ++jt)
        {
          same = it->first == jt->first && std::abs(it->second - jt->second) <= 1e-12;
        }
        SV_CHECK_MSG(status, same,
          "degree " << degree << " round " << round << ": " << fa.size() << " vs " << fb.size()
                    << " functions, or different gammas");
        SV_CHECK(status, a.GetNumberOfElements() == b.GetNumberOfElements());
      }
      const lrtest::BrutePatch after = Brute(a), sequential = Brute(b);
      const double changed = MaxDifference(before, after, false);
      const double versus = MaxDifference(after, sequential, false);
      const double unity = MaxDifference(after, after, true);
      std::cout << "degree " << degree << ": " << after.Gamma.size() << " functions, "
                << after.Elements.size() << " elements after 2 batches; the spline changed by "
                << changed << ", batch vs one by one " << versus << ", partition of unity " << unity
                << std::endl;
      SV_CHECK(status, changed <= 1e-12 && versus <= 1e-12 && unity <= 1e-12);
    }
  }

  // Splits on the voxel-face grid (k + 1/2), no part shorter than 1.
  {
    vtkLRSplineBuilder::RefineOptions options;
    for (int d = 0; d < 3; ++d)
    {
      options.GridStep[d] = 1.0;
      options.GridOffset[d] = 0.5;
      options.MinimumPart[d] = 1.0;
    }
    double z = 0.0;
    SV_CHECK(status, vtkLRSplineBuilder::SplitValue(0, 4, 0, options, &z) && z == 2.5);
    SV_CHECK(status, vtkLRSplineBuilder::SplitValue(2.5, 4.5, 0, options, &z) && z == 3.5);
    SV_CHECK(status, !vtkLRSplineBuilder::SplitValue(2.5, 3.5, 0, options, &z));
    SV_CHECK(status, !vtkLRSplineBuilder::SplitValue(0, 1.5, 0, options, &z)); // part 0.5 < 1
    options.MinimumPart[0] = 0.5;
    SV_CHECK(status, vtkLRSplineBuilder::SplitValue(0, 1.5, 0, options, &z) && z == 0.5);
    vtkLRSplineBuilder b;
    std::mt19937 rng(5);
    Initialize(b, 2, rng);
    for (int round = 0; round < 3; ++round)
    {
      std::vector<vtkIdType> all(b.GetPatch().GetNumberOfBasisFunctions());
      for (std::size_t i = 0; i < all.size(); ++i)
      {
        all[i] = static_cast<vtkIdType>(i);
      }
      SV_CHECK(status, b.RefineFunctions(all, options, &error));
    }
    const vtkLRSplinePatch& p = b.GetPatch();
    bool onGrid = true, longEnough = true;
    for (vtkIdType e = 0; e < p.GetNumberOfElements(); ++e)
    {
      const double* box = p.ElementBoxes.data() + 6 * e;
      for (int c = 0; c < 6; ++c)
      {
        const double v = box[c];
        const double step = c % 3 == 0 ? 4 : (c % 3 == 1 ? 5 : 3); // the initial breaks
        onGrid = onGrid && (std::fmod(v, step) == 0 || v - 0.5 == std::floor(v - 0.5));
      }
      for (int d = 0; d < 3; ++d)
      {
        longEnough = longEnough && box[d + 3] - box[d] >= 0.5;
      }
    }
    std::cout << "grid splits: " << p.GetNumberOfElements() << " elements, on the grid " << onGrid
              << ", parts >= 0.5 " << longEnough << std::endl;
    SV_CHECK(status, onGrid && longEnough && p.GetNumberOfElements() > 1000);
  }

  // A large batch on a cubic volume stays fast.
  {
    vtkLRSplineBuilder b;
    std::mt19937 rng(9);
    Initialize(b, 3, rng);
    const auto t0 = std::chrono::steady_clock::now();
    for (int round = 0; round < 3; ++round)
    {
      std::vector<vtkIdType> all(b.GetPatch().GetNumberOfBasisFunctions());
      for (std::size_t i = 0; i < all.size(); ++i)
      {
        all[i] = static_cast<vtkIdType>(i);
      }
      SV_CHECK(status, b.RefineFunctions(all, vtkLRSplineBuilder::RefineOptions(), &error));
    }
    const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::cout << "cubic, three batches of all functions: " << b.GetNumberOfElements()
              << " elements, " << b.GetNumberOfBasisFunctions() << " functions in " << seconds
              << " s" << std::endl;
    SV_CHECK(status, seconds < 20.0);
  }
  return status.Result();
}
