// SPDX-License-Identifier: BSD-3-Clause
// Evaluation of LR splines in Bezier form:
// - Bernstein values against the closed form, derivatives against finite
//   differences;
// - the Bezier coefficients of single B-splines (the change of basis)
//   against Cox-de Boor, for degrees 0 to 5 and random knots;
// - polynomial reproduction: a random polynomial of the spline's degree,
//   given by its blossom on a tensor-product spline, survives LR refinement
//   (golden-section and dyadic splits) and the Bezier extraction: value and
//   gradient exact at random points (also with a degree-0 direction);
// - gradients against central finite differences on the real file;
// - single precision close to double; the parallel batch equals the serial
//   evaluation; with overlapping patches the first one wins.
#include "vtkLRSplineBezierVolume.h"
#include "vtkLRSplineBuilder.h"
#include "vtkLRSplineEvaluator.h"
#include "vtkLRSplineField.h"
#include "vtkLRSplinePatch.h"
#include "vtkLRSplineReader.h"

#include "LRSplineTestUtilities.h"
#include "SplineVizTestUtilities.h"

#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkSMPTools.h"

#include <cmath>
#include <random>

namespace
{
void CheckPolynomialReproduction(SplineVizTestStatus& status, const int degree[3], unsigned seed)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  lrtest::Polynomial poly;
  for (int d = 0; d < 3; ++d)
  {
    poly.Degree[d] = degree[d];
  }
  poly.A.resize((degree[0] + 1) * (degree[1] + 1) * (degree[2] + 1));
  for (double& a : poly.A)
  {
    a = U(rng);
  }
  vtkLRSplineBuilder builder;
  const std::vector<double> breaks[3] = { { -1.0, -0.3, 0.2, 1.0 }, { 0, 0.5, 1.0, 2.0 },
    { 0.5, 1.0 / 3.0 + 0.5, 1.5 } };
  std::string error;
  SV_CHECK(status, builder.InitializeTensorProduct(degree, breaks, 1, &error));
  builder.SetCoefficientsFromKnots(
    [&](const double* const in[3], const int deg[3], double* c)
    {
      (void)deg;
      c[0] = poly.Blossom(in[0], in[1], in[2]);
    });
  const double golden = 0.5 * (std::sqrt(5.0) - 1.0);
  const double targets[2][3] = { { 0.1, 0.4, 0.9 }, { -0.8, 1.7, 1.2 } };
  for (int level = 0; level < 4; ++level)
  {
    for (const auto& t : targets)
    {
      SV_CHECK_MSG(status, builder.RefineAt(t, level % 2 ? 0.5 : golden, &error), error);
    }
  }
  const vtkLRSplinePatch& patch = builder.GetPatch();
  vtkLRSplineBezierVolume volume;
  std::string warning;
  SV_CHECK_MSG(status, patch.ExtractBezier(volume, &error, &warning), error);
  SV_CHECK_MSG(status, warning.empty(), warning);
  for (int elevated = 0; elevated < 2; ++elevated)
  {
    vtkLRSplineBezierVolume copy = volume;
    if (elevated)
    {
      copy.ElevateToAtLeastLinear();
    }
    vtkLRSplineEvaluator ev;
    SV_CHECK_MSG(status,
      ev.Initialize(std::move(copy), vtkLRSplineElementLocator::KD_FOREST, nullptr, &error), error);
    double worstV = 0.0, worstG = 0.0, scale = 0.0;
    for (int i = 0; i < 3000; ++i)
    {
      double x[3] = { -1.0 + 2.0 * (0.5 + 0.5 * U(rng)), 2.0 * (0.5 + 0.5 * U(rng)),
        0.5 + (0.5 + 0.5 * U(rng)) };
      if (i % 10 == 0)
      {
        x[i % 3] = (i % 3 == 0) ? 1.0 : (i % 3 == 1 ? 2.0 : 1.5); // upper faces
      }
      double v, g[3], rg[3];
      SV_CHECK(status, ev.Evaluate(x, &v, g) >= 0);
      const double ref = poly.Value(x);
      poly.Gradient(x, rg);
      scale = std::max(scale, std::abs(ref));
      worstV = std::max(worstV, std::abs(v - ref));
      for (int d = 0; d < 3; ++d)
      {
        worstG = std::max(worstG, std::abs(g[d] - rg[d]));
      }
    }
    std::cout << "degree " << degree[0] << degree[1] << degree[2] << (elevated ? " (elevated)" : "")
              << ", " << patch.GetNumberOfElements() << " elements: max value error " << worstV
              << ", max gradient error " << worstG << " (scale " << scale << ")" << std::endl;
    SV_CHECK_MSG(status, worstV <= 1e-12 * std::max(1.0, scale), "value " << worstV);
    SV_CHECK_MSG(status, worstG <= 1e-10 * std::max(1.0, scale), "gradient " << worstG);
  }
}
}

int TestLRSplineEvaluator(int, char*[])
{
  SplineVizTestStatus status;
  vtkSMPTools::SetBackend("STDThread");

  //--- Bernstein basis.
  for (int n = 0; n <= 6; ++n)
  {
    for (double s : { 0.0, 0.13, 0.5, 0.77, 1.0 })
    {
      double b[16], d[16];
      vtkLRSplineBezierVolume::Bernstein<double>(n, s, b, d);
      double sum = 0.0;
      for (int i = 0; i <= n; ++i)
      {
        const double ref = lrtest::Binomial(n, i) * std::pow(s, i) * std::pow(1.0 - s, n - i);
        SV_CHECK_NEAR(status, b[i], ref, 1e-14);
        sum += b[i];
        const double h = 1e-6;
        double bp[16], bm[16];
        vtkLRSplineBezierVolume::Bernstein<double>(n, s + h, bp, nullptr);
        vtkLRSplineBezierVolume::Bernstein<double>(n, s - h, bm, nullptr);
        SV_CHECK_NEAR(status, d[i], (bp[i] - bm[i]) / (2 * h), 1e-7);
      }
      SV_CHECK_NEAR(status, sum, 1.0, 1e-14);
    }
  }

  //--- Single B-spline to Bernstein on an element, against Cox-de Boor.
  {
    std::mt19937 rng(1);
    std::uniform_real_distribution<double> U(0.0, 1.0);
    double worst = 0.0;
    for (int trial = 0; trial < 400; ++trial)
    {
      const int p = trial % 6;
      std::vector<double> t(p + 2);
      double x = U(rng);
      for (double& k : t)
      {
        k = x;
        x += (U(rng) < 0.25) ? 0.0 : U(rng); // repeated knots too
      }
      if (!(t.back() > t.front()))
      {
        continue;
      }
      // an element inside one non-empty knot interval
      int m = 0;
      do
      {
        m = static_cast<int>(U(rng) * (p + 1)) % (p + 1);
      } while (!(t[m] < t[m + 1]));
      const double a = t[m] + 0.3 * U(rng) * (t[m + 1] - t[m]);
      const double b = (trial % 3 == 0) ? t[m + 1] : a + (0.1 + 0.9 * U(rng)) * (t[m + 1] - a);
      double bern[16];
      SV_CHECK(status, vtkLRSplinePatch::BSplineToBernstein(t.data(), p + 1, a, b, bern));
      for (double s : { 0.0, 0.25, 0.6, 0.999 })
      {
        double basis[16];
        vtkLRSplineBezierVolume::Bernstein<double>(p, s, basis, nullptr);
        double v = 0.0;
        for (int i = 0; i <= p; ++i)
        {
          v += bern[i] * basis[i];
        }
        const double ref = lrtest::TruncatedPowerBSpline(t, a + s * (b - a), false);
        worst = std::max(worst, std::abs(v - ref));
      }
      // Not inside one interval: refused.
      if (p >= 1 && t[0] < t[p + 1])
      {
        SV_CHECK(
          status, !vtkLRSplinePatch::BSplineToBernstein(t.data(), p + 1, t[0] - 1.0, t[0], bern));
      }
    }
    std::cout << "B-spline to Bernstein: max error " << worst << std::endl;
    SV_CHECK_MSG(status, worst < 1e-13, "bernstein extraction " << worst);
  }

  //--- Polynomial reproduction through refinement and extraction.
  {
    const int d222[3] = { 2, 2, 2 }, d231[3] = { 2, 3, 1 }, d310[3] = { 3, 1, 0 },
              d333[3] = { 3, 3, 3 };
    CheckPolynomialReproduction(status, d222, 3);
    CheckPolynomialReproduction(status, d231, 4);
    CheckPolynomialReproduction(status, d310, 5);
    CheckPolynomialReproduction(status, d333, 6);
  }

  //--- The real file: gradients vs finite differences, float vs double,
  // parallel batch vs serial, first patch wins.
  vtkNew<vtkLRSplineReader> reader;
  reader->SetFileName(
    (std::string(SPLINEVIZ_EXTERNAL_DATA_DIR) + "/cube-3patch-refined.lr").c_str());
  reader->SetPhysicalBounds(0, 2, 0, 1, 0, 0.5);
  reader->Update();
  vtkLRSplineField field;
  std::string error;
  SV_CHECK_MSG(status,
    field.Build(
      reader->GetOutput(), nullptr, vtkLRSplineElementLocator::KD_FOREST, nullptr, false, &error),
    error);
  if (field.GetNumberOfPatches() == 3)
  {
    field.MakeFloat();
    const vtkLRSplineEvaluator& ev = field.GetPatch(2);
    std::mt19937 rng(8);
    std::uniform_real_distribution<double> U(0.0, 1.0);
    double worstFD = 0.0, worstFloat = 0.0;
    int tested = 0;
    std::vector<double> pts;
    for (int i = 0; i < 2000; ++i)
    {
      const double x[3] = { 2 * U(rng), U(rng), 0.5 * U(rng) };
      pts.insert(pts.end(), x, x + 3);
      double v[3], g[9];
      const vtkIdType e = ev.Evaluate(x, v, g);
      SV_CHECK(status, e >= 0);
      const double h = 1e-6;
      bool sameElement = true;
      double fd[9];
      for (int d = 0; d < 3 && sameElement; ++d)
      {
        double xp[3] = { x[0], x[1], x[2] }, xm[3] = { x[0], x[1], x[2] };
        xp[d] += h;
        xm[d] -= h;
        double vp[3], vm[3];
        sameElement = ev.Evaluate(xp, vp, nullptr) == e && ev.Evaluate(xm, vm, nullptr) == e;
        for (int c = 0; c < 3; ++c)
        {
          fd[3 * c + d] = (vp[c] - vm[c]) / (2 * h);
        }
      }
      if (sameElement)
      {
        ++tested;
        for (int k = 0; k < 9; ++k)
        {
          worstFD = std::max(worstFD, std::abs(fd[k] - g[k]));
        }
      }
      const float xf[3] = { static_cast<float>(x[0]), static_cast<float>(x[1]),
        static_cast<float>(x[2]) };
      float vf[3], gf[9];
      if (ev.Evaluate(xf, vf, gf) >= 0)
      {
        for (int c = 0; c < 3; ++c)
        {
          worstFloat = std::max(worstFloat, std::abs(static_cast<double>(vf[c]) - v[c]));
        }
      }
    }
    std::cout << "gradient vs central differences: " << tested << " points, max difference "
              << worstFD << "; float vs double: " << worstFloat << std::endl;
    SV_CHECK(status, tested > 1000);
    SV_CHECK_MSG(status, worstFD < 1e-7, "finite differences " << worstFD);
    SV_CHECK_MSG(status, worstFloat < 1e-5, "float " << worstFloat);
    // A wrong gradient scale (parameter instead of physical) would fail: the
    // x-direction is stretched by 2 and z by 0.5.

    const vtkIdType n = static_cast<vtkIdType>(pts.size() / 3);
    std::vector<double> values(3 * n), grads(9 * n);
    std::vector<vtkIdType> elems(n);
    ev.EvaluateBatch(pts.data(), n, values.data(), grads.data(), elems.data());
    int batchMismatch = 0;
    for (vtkIdType i = 0; i < n; ++i)
    {
      double v[3], g[9];
      const vtkIdType e = ev.Evaluate(pts.data() + 3 * i, v, g);
      batchMismatch += (e != elems[i] || v[0] != values[3 * i] || v[2] != values[3 * i + 2] ||
                         g[4] != grads[9 * i + 4])
        ? 1
        : 0;
    }
    SV_CHECK(status, batchMismatch == 0);

    // Overlapping patches: the first wins; outside: -1.
    const double inside[3] = { 1.0, 0.5, 0.25 }, outside[3] = { 2.5, 0.5, 0.25 };
    double v[3];
    SV_CHECK(status, field.Evaluate(inside, v, nullptr) == 0);
    SV_CHECK(status, field.Evaluate(outside, v, nullptr) == -1);
    int patch = 2;
    vtkIdType element = field.GetPatch(2).FindElement(inside);
    SV_CHECK(status, field.EvaluateWithHint(inside, v, nullptr, patch, element) == 0);
  }
  return status.Result();
}
