// SPDX-License-Identifier: BSD-3-Clause
// Benchmark of LR-spline element look-up and evaluation (Fuchs et al. §3.2;
// issue: "LR-spline volumes: reader, Bezier blocks, k-d forest").
//
// On the real file (cube-3patch-refined.lr, dyadic) and on generated
// quadratic LR volumes of >= 30,000 elements with several refinement levels
// (non-dyadic golden-section knots; and a dyadic one for the octree and the
// lookup texture):
//  - per search structure (linear search, one k-d tree, k-d forests of 8^3,
//    64^3, 256^3 blocks, octree, lookup texture): build time, memory, tree
//    depths (min / max / mean / variance over blocks, like the paper's
//    tables) and look-ups per second on one core and on all cores;
//  - field evaluations per second (quadratic, 3 components; value, and value
//    plus Jacobian; double and single precision) on one core and all cores;
//  - the VTK way side by side: vtkProbeFilter on the same Bezier-hexahedron
//    grid (vtkStaticCellLocator + VTK's Bezier cell inversion), with the
//    ratio and the largest difference of the values.
//
//   BenchmarkLRSplineEvaluation [path/to/cube-3patch-refined.lr]
#include "BenchmarkCommon.h"
#include "vtkLRSplineArrayNames.h"
#include "vtkLRSplineBuilder.h"
#include "vtkLRSplineEvaluator.h"
#include "vtkLRSplineField.h"
#include "vtkLRSplineReader.h"

#include "LRSplineBenchmarkVolumes.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProbeFilter.h"
#include "vtkSMPTools.h"
#include "vtkStaticCellLocator.h"
#include "vtkUnstructuredGrid.h"

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <random>
#include <sstream>

namespace
{
using Clock = std::chrono::steady_clock;
double Seconds(Clock::time_point t0)
{
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

std::vector<double> RandomPoints(const double dom[6], vtkIdType n, unsigned seed)
{
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  std::vector<double> p(3 * n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    for (int d = 0; d < 3; ++d)
    {
      p[3 * i + d] = dom[d] + U(rng) * (dom[d + 3] - dom[d]);
    }
  }
  return p;
}

// Look-ups per second over `pts` (all threads of the current backend).
double LookupsPerSecond(const vtkLRSplineElementLocator& loc, const std::vector<double>& pts,
  std::vector<vtkIdType>* found = nullptr)
{
  const vtkIdType n = static_cast<vtkIdType>(pts.size() / 3);
  std::vector<vtkIdType> local;
  std::vector<vtkIdType>& out = found ? *found : local;
  out.resize(n);
  const auto t0 = Clock::now();
  vtkSMPTools::For(0, n,
    [&](vtkIdType b, vtkIdType e)
    {
      for (vtkIdType i = b; i < e; ++i)
      {
        out[i] = loc.FindElement(pts.data() + 3 * i);
      }
    });
  return n / Seconds(t0);
}

struct Row
{
  std::string Name;
  bool Built;
  std::string Why;
  double BuildSeconds;
  vtkLRSplineElementLocator::Statistics Stats;
  double Single, Multi;
};

void BenchmarkLocators(const std::string& label, const std::vector<double>& boxes, bool dyadic)
{
  const vtkIdType ne = static_cast<vtkIdType>(boxes.size() / 6);
  double dom[6] = { 1e300, 1e300, 1e300, -1e300, -1e300, -1e300 };
  for (vtkIdType e = 0; e < ne; ++e)
  {
    for (int d = 0; d < 3; ++d)
    {
      dom[d] = std::min(dom[d], boxes[6 * e + d]);
      dom[d + 3] = std::max(dom[d + 3], boxes[6 * e + d + 3]);
    }
  }
  std::cout << "\n== Element look-up: " << label << " (" << ne << " elements, "
            << (dyadic ? "dyadic" : "non-dyadic") << " knots)\n";
  struct Config
  {
    const char* Name;
    int Type;
    int Blocks;
  };
  const Config configs[] = { { "linear search", vtkLRSplineElementLocator::LINEAR, 0 },
    { "k-d tree", vtkLRSplineElementLocator::KD_TREE, 0 },
    { "k-d forest 8^3", vtkLRSplineElementLocator::KD_FOREST, 8 },
    { "k-d forest 64^3", vtkLRSplineElementLocator::KD_FOREST, 64 },
    { "k-d forest 256^3", vtkLRSplineElementLocator::KD_FOREST, 256 },
    { "octree", vtkLRSplineElementLocator::OCTREE, 0 },
    { "lookup texture", vtkLRSplineElementLocator::TEXTURE, 0 } };
  const std::vector<double> pts = RandomPoints(dom, 2000000, 7);
  const std::vector<double> fewPts(pts.begin(), pts.begin() + 3 * 20000);
  std::vector<vtkIdType> reference;
  std::vector<Row> rows;
  double linearRate = 0.0, forestRate = 0.0;
  for (const Config& c : configs)
  {
    Row row{ c.Name, false, "", 0.0, {}, 0.0, 0.0 };
    vtkLRSplineElementLocator loc;
    const int blocks[3] = { c.Blocks, c.Blocks, c.Blocks };
    std::string error;
    const auto t0 = Clock::now();
    row.Built = loc.Build(boxes.data(), ne, c.Type, c.Blocks ? blocks : nullptr, &error);
    row.BuildSeconds = Seconds(t0);
    if (!row.Built)
    {
      row.Why = error.substr(0, 60);
      rows.push_back(row);
      continue;
    }
    row.Stats = loc.GetStatistics();
    const std::vector<double>& P = (c.Type == vtkLRSplineElementLocator::LINEAR) ? fewPts : pts;
    std::vector<vtkIdType> found;
    vtkSMPTools::SetBackend("Sequential");
    row.Single = LookupsPerSecond(loc, P, &found);
    vtkSMPTools::SetBackend("STDThread");
    row.Multi = LookupsPerSecond(loc, P);
    // All structures must agree with the linear search.
    if (reference.empty())
    {
      reference = found;
    }
    for (std::size_t i = 0; i < reference.size() && i < found.size(); ++i)
    {
      if (found[i] != reference[i])
      {
        std::cout << "ERROR: " << c.Name << " disagrees with the linear search at point " << i
                  << std::endl;
        break;
      }
    }
    if (c.Type == vtkLRSplineElementLocator::LINEAR)
    {
      linearRate = row.Multi;
    }
    if (c.Blocks == 64)
    {
      forestRate = row.Multi;
    }
    rows.push_back(row);
  }
  std::cout << "  structure            build [s] " << lrbench::StatisticsHeader()
            << "   look-ups/s 1 core   look-ups/s " << vtkSMPTools::GetEstimatedNumberOfThreads()
            << " cores\n";
  for (const Row& r : rows)
  {
    if (!r.Built)
    {
      std::cout << "  " << std::left << std::setw(20) << r.Name << std::right
                << " not applicable: " << r.Why << "\n";
      continue;
    }
    char line[300];
    std::snprintf(line, sizeof(line), "  %-20s %9.3f %s %17.3e %17.3e\n", r.Name.c_str(),
      r.BuildSeconds, lrbench::StatisticsRow(r.Stats).c_str(), r.Single, r.Multi);
    std::cout << line;
  }
  if (linearRate > 0)
  {
    std::cout << "  k-d forest 64^3 / linear search: " << forestRate / linearRate << " x\n";
  }
}

void BenchmarkEvaluation(const std::string& label, vtkMultiBlockDataSet* spline, unsigned int block)
{
  auto* grid = vtkUnstructuredGrid::SafeDownCast(spline->GetBlock(block));
  vtkLRSplineField field;
  std::string error;
  const auto tb = Clock::now();
  if (!field.Build(grid, nullptr, vtkLRSplineElementLocator::KD_FOREST, nullptr, false, &error))
  {
    std::cout << "ERROR: " << error << std::endl;
    return;
  }
  const double buildSeconds = Seconds(tb);
  field.MakeFloat();
  const vtkLRSplineEvaluator& ev = field.GetPatch(0);
  const vtkIdType n = 4000000;
  double bounds[6];
  ev.GetBounds(bounds);
  const double dom[6] = { bounds[0], bounds[2], bounds[4], bounds[1], bounds[3], bounds[5] };
  const std::vector<double> pts = RandomPoints(dom, n, 3);
  std::vector<float> ptsf(pts.begin(), pts.end());
  std::vector<double> values(3 * n), grads(9 * n);
  std::vector<float> valuesf(3 * n), gradsf(9 * n);
  const auto& st = ev.GetLocator().GetStatistics();
  std::cout << "\n== Evaluation: " << label << " (" << ev.GetNumberOfElements()
            << " elements, degree " << ev.GetVolume().Degree[0] << ev.GetVolume().Degree[1]
            << ev.GetVolume().Degree[2] << ", " << ev.GetNumberOfComponents()
            << " components; k-d forest " << ev.GetLocator().GetNumberOfBlocks()[0]
            << "^3 built in " << buildSeconds << " s, mean depth " << st.MeanDepth << ")\n";
  std::cout << "  random points; evaluations per second (look-up + Bezier evaluation)\n"
            << "  kind                          1 core        "
            << vtkSMPTools::GetEstimatedNumberOfThreads() << " cores\n";
  struct Kind
  {
    const char* Name;
    int Mode;
  };
  const Kind kinds[] = { { "value, double", 0 }, { "value + Jacobian, double", 1 },
    { "value, float", 2 }, { "value + Jacobian, float", 3 } };
  for (const Kind& k : kinds)
  {
    double rate[2];
    for (int b = 0; b < 2; ++b)
    {
      vtkSMPTools::SetBackend(b == 0 ? "Sequential" : "STDThread");
      const auto t0 = Clock::now();
      vtkSMPTools::For(0, n,
        [&](vtkIdType begin, vtkIdType end)
        {
          for (vtkIdType i = begin; i < end; ++i)
          {
            switch (k.Mode)
            {
              case 0:
                ev.Evaluate(pts.data() + 3 * i, values.data() + 3 * i, nullptr);
                break;
              case 1:
                ev.Evaluate(pts.data() + 3 * i, values.data() + 3 * i, grads.data() + 9 * i);
                break;
              case 2:
                ev.Evaluate(ptsf.data() + 3 * i, valuesf.data() + 3 * i, nullptr);
                break;
              default:
                ev.Evaluate(ptsf.data() + 3 * i, valuesf.data() + 3 * i, gradsf.data() + 9 * i);
                break;
            }
          }
        });
      rate[b] = n / Seconds(t0);
    }
    std::printf("  %-26s %12.3e %12.3e\n", k.Name, rate[0], rate[1]);
  }
  // Coherent points: a 160^3 image in scanline order (what resampling, probing
  // lines and tracing do), through vtkLRSplineField::EvaluatePoints, which
  // first tries the previous point's element.
  {
    const int m = 160;
    const vtkIdType nm = static_cast<vtkIdType>(m) * m * m;
    std::vector<double> out(3 * nm), outGrad(9 * nm);
    for (int withGrad = 0; withGrad < 2; ++withGrad)
    {
      double rate[2];
      for (int b = 0; b < 2; ++b)
      {
        vtkSMPTools::SetBackend(b == 0 ? "Sequential" : "STDThread");
        const auto t0 = Clock::now();
        field.EvaluatePoints(
          nm,
          [&](vtkIdType id, double x[3])
          {
            const vtkIdType ijk[3] = { id % m, (id / m) % m, id / (static_cast<vtkIdType>(m) * m) };
            for (int d = 0; d < 3; ++d)
            {
              x[d] = dom[d] + (dom[d + 3] - dom[d]) * (ijk[d] + 0.5) / m;
            }
          },
          out.data(), withGrad ? outGrad.data() : nullptr, nullptr);
        rate[b] = nm / Seconds(t0);
      }
      std::printf("  %-26s %12.3e %12.3e\n",
        withGrad ? "image order, value + Jac." : "image order, value", rate[0], rate[1]);
    }
  }
  vtkSMPTools::SetBackend("STDThread");

  // The VTK way: vtkProbeFilter on the same Bezier grid.
  const vtkIdType nv = 20000;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(nv);
  for (vtkIdType i = 0; i < nv; ++i)
  {
    points->SetPoint(i, pts.data() + 3 * i);
  }
  vtkNew<vtkPolyData> cloud;
  cloud->SetPoints(points);
  vtkNew<vtkProbeFilter> probe;
  probe->SetInputData(cloud);
  probe->SetSourceData(grid);
  vtkNew<vtkStaticCellLocator> locator;
  probe->SetCellLocatorPrototype(locator);
  const auto t0 = Clock::now();
  probe->Update();
  const double vtkSeconds = Seconds(t0);
  vtkDataArray* vtkValues =
    probe->GetOutput()->GetPointData()->GetArray(field.GetArrayName().c_str());
  vtkDataArray* mask = probe->GetOutput()->GetPointData()->GetArray("vtkValidPointMask");
  double worst = 0.0;
  vtkIdType missed = 0;
  for (vtkIdType i = 0; i < nv; ++i)
  {
    if (!mask || mask->GetComponent(i, 0) == 0)
    {
      ++missed;
      continue;
    }
    double v[3];
    ev.Evaluate(pts.data() + 3 * i, v, nullptr);
    for (int c = 0; c < 3; ++c)
    {
      worst = std::max(worst, std::abs(v[c] - vtkValues->GetComponent(i, c)));
    }
  }
  // ours on the same points, all cores
  const auto t1 = Clock::now();
  field.EvaluatePoints(
    nv, [&](vtkIdType i, double x[3]) { std::copy(pts.data() + 3 * i, pts.data() + 3 * i + 3, x); },
    values.data(), nullptr, nullptr);
  const double ourSeconds = Seconds(t1);
  std::printf("  VTK vtkProbeFilter on the Bezier grid: %.3e evaluations/s (%lld of %lld points "
              "not found); SplineViz: %.3e/s, %.0f x faster; max |difference| %.2e\n",
    nv / vtkSeconds, static_cast<long long>(missed), static_cast<long long>(nv), nv / ourSeconds,
    vtkSeconds / ourSeconds, worst);
}
}

const char* const Usage =
  "Usage: BenchmarkLRSplineEvaluation [path/to/file.lr]\n"
  "Element look-up and evaluation rates of the LR-spline search structures on\n"
  "the given file (default: the external cube-3patch-refined.lr) and on\n"
  "generated volumes of >= 30,000 elements, against vtkProbeFilter.\n";

int main(int argc, char* argv[])
{
  if (splineviz_benchmark::HelpRequested(argc, argv, Usage))
  {
    return 0;
  }
  vtkSMPTools::SetBackend("STDThread");
  std::cout << "LR-spline look-up and evaluation benchmark; vtkSMPTools backend "
            << vtkSMPTools::GetBackend() << ", " << vtkSMPTools::GetEstimatedNumberOfThreads()
            << " threads\n";
  const std::string file =
    argc > 1 ? argv[1] : SPLINEVIZ_EXTERNAL_DATA_DIR "/cube-3patch-refined.lr";

  vtkNew<vtkLRSplineReader> reader;
  reader->SetFileName(file.c_str());
  const auto t0 = Clock::now();
  reader->Update();
  std::cout << "read " << file << " in " << Seconds(t0) << " s (parse, supports, Bezier "
            << "extraction, VTK grid of 3 patches)" << std::endl;
  auto* real = vtkUnstructuredGrid::SafeDownCast(reader->GetOutput()->GetBlock(0));
  if (!real)
  {
    std::cerr << "ERROR: cannot read " << file << std::endl;
    return 1;
  }
  std::vector<double> realBoxes;
  {
    vtkDataArray* b = real->GetCellData()->GetArray(vtkLRSplineArrayNames::ParameterBox);
    for (vtkIdType c = 0; c < b->GetNumberOfTuples(); ++c)
    {
      for (int k = 0; k < 6; ++k)
      {
        realBoxes.push_back(b->GetComponent(c, k));
      }
    }
  }
  BenchmarkLocators("cube-3patch-refined.lr, patch 0", realBoxes, true);

  // Generated volumes.
  vtkLRSplineBuilder nonDyadic, dyadic;
  if (!lrbench::MakeVolume(nonDyadic, 30000, false) || !lrbench::MakeVolume(dyadic, 30000, true))
  {
    return 1;
  }
  BenchmarkLocators("generated LR volume", nonDyadic.GetPatch().ElementBoxes, false);
  BenchmarkLocators("generated dyadic LR volume", dyadic.GetPatch().ElementBoxes, true);

  // Evaluation through the reader's output (the path every filter takes).
  BenchmarkEvaluation("cube-3patch-refined.lr, patch 0", reader->GetOutput(), 0);
  const lrbench::TemporaryLRFile generatedFile(nonDyadic, "LRSplineBenchmark-generated.lr");
  if (!generatedFile.IsOk())
  {
    std::cerr << "cannot write " << generatedFile.GetPath() << "\n";
    return 1;
  }
  const std::string& path = generatedFile.GetPath();
  vtkNew<vtkLRSplineReader> generated;
  generated->SetFileName(path.c_str());
  const auto t1 = Clock::now();
  generated->Update();
  std::cout << "\nread the generated volume (" << nonDyadic.GetNumberOfElements()
            << " elements) in " << Seconds(t1) << " s" << std::endl;
  BenchmarkEvaluation("generated LR volume", generated->GetOutput(), 0);
  return 0;
}
