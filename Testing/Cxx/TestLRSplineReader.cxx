// SPDX-License-Identifier: BSD-3-Clause
// vtkLRSplineReader on the real files: counts of patches, basis functions and
// elements; the Bezier form (evaluated by the SplineViz evaluator AND by VTK's
// own Bezier hexahedron interpolation of the point data) equals the
// brute-force sum over all basis functions (Cox-de Boor, LRSplineTestUtilities.h)
// to 1e-12 relative at thousands of random points, element corners and the
// domain's upper boundary; the same for the g2 tensor-product volume, in
// field and geometry mode; physical bounds; pieces; a generated, locally
// refined, non-dyadic LR volume written to .lr and read back.
#include "vtkLRSplineArrayNames.h"
#include "vtkLRSplineBuilder.h"
#include "vtkLRSplineField.h"
#include "vtkLRSplineReader.h"

#include "LRSplineTestUtilities.h"
#include "SplineVizTestUtilities.h"

#include "vtkBezierHexahedron.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkGenericCell.h"
#include "vtkIdList.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStringArray.h"
#include "vtkUnstructuredGrid.h"

#include <cmath>
#include <fstream>
#include <random>
#include <set>

namespace
{
const std::string DataDir = SPLINEVIZ_EXTERNAL_DATA_DIR;

double Scale(const lrtest::BrutePatch& P)
{
  double m = 0.0;
  for (double c : P.Coef)
  {
    m = std::max(m, std::abs(c));
  }
  return std::max(m, 1e-300);
}

// Points where the evaluators must agree: random, element corners (lower
// and upper), face centres, and the upper boundary of the domain.
std::vector<std::array<double, 3>> TestPoints(
  const lrtest::BrutePatch& P, int numRandom, unsigned seed)
{
  std::vector<std::array<double, 3>> pts;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  for (int i = 0; i < numRandom; ++i)
  {
    std::array<double, 3> p;
    for (int d = 0; d < 3; ++d)
    {
      p[d] = P.Domain[d] + U(rng) * (P.Domain[d + 3] - P.Domain[d]);
    }
    pts.push_back(p);
  }
  for (std::size_t e = 0; e < P.Elements.size(); e += 3)
  {
    const auto& b = P.Elements[e];
    pts.push_back({ b[0], b[1], b[2] });
    pts.push_back({ b[3], b[4], b[5] });
    pts.push_back({ 0.5 * (b[0] + b[3]), 0.5 * (b[1] + b[4]), b[2] });
  }
  for (int i = 0; i < 50; ++i)
  {
    for (int d = 0; d < 3; ++d)
    {
      std::array<double, 3> p;
      for (int o = 0; o < 3; ++o)
      {
        p[o] = P.Domain[o] + U(rng) * (P.Domain[o + 3] - P.Domain[o]);
      }
      p[d] = P.Domain[d + 3];
      pts.push_back(p);
    }
  }
  pts.push_back({ P.Domain[3], P.Domain[4], P.Domain[5] });
  return pts;
}

// Compare one patch of a reader output with the brute-force sum.
void CheckPatch(SplineVizTestStatus& status, vtkUnstructuredGrid* grid, const lrtest::BrutePatch& P,
  const double scale[3], const double offset[3], int numRandom, const char* label)
{
  vtkLRSplineField field;
  std::string error;
  SV_CHECK_MSG(status,
    field.Build(grid, nullptr, vtkLRSplineElementLocator::KD_FOREST, nullptr, false, &error),
    error);
  if (field.GetNumberOfPatches() != 1)
  {
    return;
  }
  const double tol = 1e-12 * Scale(P);
  double worst = 0.0;
  int outside = 0;
  const auto pts = TestPoints(P, numRandom, 17);
  std::vector<double> ref(P.Dim), val(P.Dim);
  for (const auto& u : pts)
  {
    lrtest::BruteForce(P, u.data(), ref.data());
    double x[3];
    for (int d = 0; d < 3; ++d)
    {
      x[d] = offset[d] + scale[d] * u[d];
    }
    // Evaluate in parameter space through the evaluator (the physical map is
    // checked separately): x may round.
    const vtkIdType e = field.GetPatch(0).EvaluateParameter(u.data(), val.data());
    if (e < 0)
    {
      ++outside;
      continue;
    }
    for (int c = 0; c < P.Dim; ++c)
    {
      worst = std::max(worst, std::abs(val[c] - ref[c]));
    }
  }
  std::cout << label << ": " << pts.size() << " points, max |bezier - brute force| = " << worst
            << " (scale " << Scale(P) << ")" << std::endl;
  SV_CHECK_MSG(status, worst <= tol, label << ": worst " << worst);
  SV_CHECK_MSG(status, outside == 0, label << ": " << outside << " points not found");

  // VTK's own interpolation of the point data with the Bezier cell's basis.
  vtkDataArray* arr = grid->GetPointData()->GetArray(field.GetArrayName().c_str());
  vtkDataArray* boxes = grid->GetCellData()->GetArray(vtkLRSplineArrayNames::ParameterBox);
  SV_CHECK(status, arr && boxes);
  if (!arr || !boxes)
  {
    return;
  }
  vtkNew<vtkGenericCell> cell;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  double worstVTK = 0.0;
  const vtkIdType nc = grid->GetNumberOfCells();
  for (int i = 0; i < 600; ++i)
  {
    const vtkIdType c = static_cast<vtkIdType>(U(rng) * nc) % nc;
    grid->GetCell(c, cell);
    double box[6];
    boxes->GetTuple(c, box);
    double pc[3], u[3];
    for (int d = 0; d < 3; ++d)
    {
      pc[d] = U(rng);
      u[d] = box[d] + pc[d] * (box[d + 3] - box[d]);
    }
    std::vector<double> w(cell->GetNumberOfPoints());
    cell->InterpolateFunctions(pc, w.data());
    lrtest::BruteForce(P, u, ref.data());
    for (int comp = 0; comp < P.Dim; ++comp)
    {
      double v = 0.0;
      for (vtkIdType k = 0; k < cell->GetNumberOfPoints(); ++k)
      {
        v += w[k] * arr->GetComponent(cell->GetPointId(k), comp);
      }
      worstVTK = std::max(worstVTK, std::abs(v - ref[comp]));
    }
  }
  std::cout << label << ": VTK Bezier interpolation, max error " << worstVTK << std::endl;
  SV_CHECK_MSG(status, worstVTK <= 1e-11 * Scale(P), label << ": VTK interpolation " << worstVTK);
}

vtkIdType FieldId(vtkUnstructuredGrid* g, const char* name)
{
  vtkDataArray* a = g->GetFieldData()->GetArray(name);
  return a ? static_cast<vtkIdType>(a->GetComponent(0, 0)) : -1;
}
}

int TestLRSplineReader(int, char*[])
{
  SplineVizTestStatus status;
  const double one[3] = { 1, 1, 1 }, zero[3] = { 0, 0, 0 };

  //--- The real locally refined file: three patches.
  const std::string cube = DataDir + "/cube-3patch-refined.lr";
  const auto brute = lrtest::ParseLR(lrtest::ReadText(cube));
  SV_CHECK(status, brute.size() == 3);
  {
    bool nonTrivialGamma = false;
    for (const auto& P : brute)
    {
      for (double g : P.Gamma)
      {
        nonTrivialGamma = nonTrivialGamma || std::abs(g - 1.0) > 1e-3;
      }
    }
    SV_CHECK(status, nonTrivialGamma);
  }
  vtkNew<vtkLRSplineReader> reader;
  reader->SetFileName(cube.c_str());
  reader->Update();
  vtkMultiBlockDataSet* mb = reader->GetOutput();
  SV_CHECK(status, mb->GetNumberOfBlocks() == 3);
  for (unsigned int p = 0; p < mb->GetNumberOfBlocks() && p < brute.size(); ++p)
  {
    auto* grid = vtkUnstructuredGrid::SafeDownCast(mb->GetBlock(p));
    SV_CHECK(status, grid != nullptr);
    if (!grid)
    {
      continue;
    }
    SV_CHECK(status, grid->GetNumberOfCells() == 1240);
    SV_CHECK(status, FieldId(grid, vtkLRSplineArrayNames::NumberOfBasisFunctions) == 1176);
    SV_CHECK(status, FieldId(grid, vtkLRSplineArrayNames::NumberOfElements) == 1240);
    SV_CHECK(status, FieldId(grid, vtkLRSplineArrayNames::NumberOfMeshRectangles) == 189);
    SV_CHECK(status, FieldId(grid, vtkLRSplineArrayNames::PatchIndex) == static_cast<vtkIdType>(p));
    SV_CHECK(status, grid->GetCellType(0) == VTK_BEZIER_HEXAHEDRON);
    vtkDataArray* deg = grid->GetCellData()->GetHigherOrderDegrees();
    SV_CHECK(status, deg && deg->GetComponent(0, 0) == 2 && deg->GetComponent(0, 2) == 2);
    SV_CHECK(status, grid->GetPointData()->GetVectors() != nullptr);
    SV_CHECK(status, grid->GetNumberOfPoints() < 1240 * 27); // merged
    vtkDataArray* levels = grid->GetFieldData()->GetArray(vtkLRSplineArrayNames::RefinementLevels);
    SV_CHECK(status, levels && levels->GetComponent(0, 0) >= 1);
    CheckPatch(
      status, grid, brute[p], one, zero, 3000, ("cube patch " + std::to_string(p)).c_str());
  }
  // The first patch is the identity map (its coefficients are the geometry of
  // the unit cube): evaluating it reproduces the point.
  {
    vtkLRSplineField field;
    std::string error;
    SV_CHECK(status,
      field.Build(mb, nullptr, vtkLRSplineElementLocator::KD_FOREST, nullptr, false, &error));
    SV_CHECK(status, field.GetNumberOfPatches() == 3 && field.GetArrayName() == "Field");
    const double x[3] = { 0.3, 0.71, 0.55 };
    double v[3];
    SV_CHECK(status, field.Evaluate(x, v, nullptr) == 0);
  }

  //--- Physical bounds: the field is placed in a box; values unchanged,
  // gradients scaled.
  {
    vtkNew<vtkLRSplineReader> placed;
    placed->SetFileName(cube.c_str());
    placed->SetPhysicalBounds(-2, 2, 10, 11, 0, 0.5);
    placed->Update();
    auto* grid = vtkUnstructuredGrid::SafeDownCast(placed->GetOutput()->GetBlock(1));
    SV_CHECK(status, grid != nullptr);
    if (grid)
    {
      double b[6];
      grid->GetBounds(b);
      SV_CHECK_NEAR(status, b[0], -2.0, 1e-14);
      SV_CHECK_NEAR(status, b[3], 11.0, 1e-14);
      SV_CHECK_NEAR(status, b[5], 0.5, 1e-14);
      vtkLRSplineField field;
      std::string error;
      SV_CHECK(status,
        field.Build(grid, nullptr, vtkLRSplineElementLocator::KD_FOREST, nullptr, false, &error));
      std::mt19937 rng(3);
      std::uniform_real_distribution<double> U(0.0, 1.0);
      double worst = 0.0;
      for (int i = 0; i < 500; ++i)
      {
        const double u[3] = { U(rng), U(rng), U(rng) };
        const double x[3] = { -2 + 4 * u[0], 10 + u[1], 0.5 * u[2] };
        double v[3], ref[3];
        SV_CHECK(status, field.Evaluate(x, v, nullptr) == 0);
        double up[3];
        field.GetPatch(0).PhysicalToParameter(x, up);
        lrtest::BruteForce(brute[1], up, ref);
        for (int c = 0; c < 3; ++c)
        {
          worst = std::max(worst, std::abs(v[c] - ref[c]));
        }
      }
      SV_CHECK_MSG(status, worst < 1e-12, "physical bounds: " << worst);
      // Geometry mode would not be probe-able in physical space.
    }
  }

  //--- Pieces: the elements of every patch are split without overlap.
  {
    std::set<vtkIdType> seen[3];
    vtkIdType total = 0;
    for (int piece = 0; piece < 3; ++piece)
    {
      vtkNew<vtkLRSplineReader> pr;
      pr->SetFileName(cube.c_str());
      pr->UpdatePiece(piece, 3, 0);
      vtkMultiBlockDataSet* out = pr->GetOutput();
      for (unsigned int p = 0; p < out->GetNumberOfBlocks(); ++p)
      {
        auto* grid = vtkUnstructuredGrid::SafeDownCast(out->GetBlock(p));
        if (!grid)
        {
          continue;
        }
        vtkDataArray* ids = grid->GetCellData()->GetArray(vtkLRSplineArrayNames::ElementId);
        for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
        {
          seen[p].insert(static_cast<vtkIdType>(ids->GetComponent(c, 0)));
        }
        total += grid->GetNumberOfCells();
        if (p == 2 && piece == 1)
        {
          // the piece is exact too
          vtkLRSplineField field;
          std::string error;
          SV_CHECK(status,
            field.Build(
              grid, nullptr, vtkLRSplineElementLocator::KD_FOREST, nullptr, false, &error));
          vtkDataArray* boxes = grid->GetCellData()->GetArray(vtkLRSplineArrayNames::ParameterBox);
          double box[6];
          boxes->GetTuple(7, box);
          const double u[3] = { 0.3 * box[0] + 0.7 * box[3], 0.5 * (box[1] + box[4]), box[2] };
          double v[3], ref[3];
          SV_CHECK(status, field.GetPatch(0).EvaluateParameter(u, v) >= 0);
          lrtest::BruteForce(brute[2], u, ref);
          SV_CHECK_NEAR(status, v[0], ref[0], 1e-12);
          SV_CHECK_NEAR(status, v[2], ref[2], 1e-12);
        }
      }
    }
    SV_CHECK(status, total == 3 * 1240);
    for (auto& s : seen)
    {
      SV_CHECK(status, s.size() == 1240);
    }
  }

  //--- The g2 tensor-product volume, field mode and geometry mode.
  const std::string g2 = DataDir + "/tensor-product-volume.g2";
  const auto bruteG2 = lrtest::ParseG2(lrtest::ReadText(g2));
  {
    vtkNew<vtkLRSplineReader> r;
    r->SetFileName(g2.c_str());
    r->Update();
    auto* grid = vtkUnstructuredGrid::SafeDownCast(r->GetOutput()->GetBlock(0));
    SV_CHECK(status, grid != nullptr && r->GetOutput()->GetNumberOfBlocks() == 1);
    if (grid)
    {
      SV_CHECK(status, grid->GetNumberOfCells() == 6);
      SV_CHECK(status, FieldId(grid, vtkLRSplineArrayNames::NumberOfBasisFunctions) == 72);
      vtkDataArray* deg = grid->GetCellData()->GetHigherOrderDegrees();
      SV_CHECK(status,
        deg->GetComponent(0, 0) == 3 && deg->GetComponent(0, 1) == 3 &&
          deg->GetComponent(0, 2) == 1);
      auto* fmt = vtkStringArray::SafeDownCast(
        grid->GetFieldData()->GetAbstractArray(vtkLRSplineArrayNames::SourceFormat));
      SV_CHECK(status, fmt && fmt->GetValue(0).find("g2") != std::string::npos);
      CheckPatch(status, grid, bruteG2, one, zero, 3000, "g2 field mode");
    }
    r->GeometryModeOn();
    r->Update();
    grid = vtkUnstructuredGrid::SafeDownCast(r->GetOutput()->GetBlock(0));
    SV_CHECK(status, grid != nullptr);
    if (grid)
    {
      // The points are the geometry: VTK's Bezier map of parametric
      // coordinates gives the brute-force geometry.
      vtkDataArray* boxes = grid->GetCellData()->GetArray(vtkLRSplineArrayNames::ParameterBox);
      vtkNew<vtkGenericCell> cell;
      std::mt19937 rng(11);
      std::uniform_real_distribution<double> U(0.0, 1.0);
      double worst = 0.0;
      for (int i = 0; i < 300; ++i)
      {
        const vtkIdType c = i % grid->GetNumberOfCells();
        grid->GetCell(c, cell);
        double box[6], pc[3], u[3], x[3], ref[3], w[64];
        boxes->GetTuple(c, box);
        for (int d = 0; d < 3; ++d)
        {
          pc[d] = U(rng);
          u[d] = box[d] + pc[d] * (box[d + 3] - box[d]);
        }
        int sub = 0;
        cell->EvaluateLocation(sub, pc, x, w);
        lrtest::BruteForce(bruteG2, u, ref);
        for (int d = 0; d < 3; ++d)
        {
          worst = std::max(worst, std::abs(x[d] - ref[d]));
        }
      }
      std::cout << "g2 geometry mode: max |VTK location - brute force| = " << worst << std::endl;
      SV_CHECK_MSG(status, worst < 1e-12, "g2 geometry " << worst);
      SV_CHECK(status,
        grid->GetPointData()->GetArray(vtkLRSplineArrayNames::ParameterCoordinates) != nullptr);
      vtkLRSplineField field;
      std::string error;
      // Physical space: the geometry map is inverted; its own coefficients
      // as the field give back the point.
      SV_CHECK(status,
        field.Build(grid, nullptr, vtkLRSplineElementLocator::KD_FOREST, nullptr, false, &error));
      if (field.GetNumberOfComponents() == 3)
      {
        double back = 0.0;
        for (vtkIdType c = 0; c < grid->GetNumberOfCells(); c += 7)
        {
          double pc[3] = { 0.31, 0.62, 0.47 }, x[3], w[1024], v[3];
          int sub = 0;
          grid->GetCell(c)->EvaluateLocation(sub, pc, x, w);
          SV_CHECK(status, field.Evaluate(x, v, nullptr) >= 0);
          for (int d = 0; d < 3; ++d)
          {
            back = std::max(back, std::abs(v[d] - x[d]));
          }
        }
        std::cout << "g2 geometry mode in physical space: max |f(x) - x| = " << back << std::endl;
        SV_CHECK(status, back < 1e-10);
      }
      SV_CHECK(status,
        field.Build(grid, nullptr, vtkLRSplineElementLocator::KD_FOREST, nullptr, true, &error));
    }
  }

  //--- A generated LR volume: several levels of local refinement, non-dyadic
  // (golden-section) knots, written to .lr and read back.
  {
    vtkLRSplineBuilder builder;
    const int degree[3] = { 2, 2, 2 };
    const std::vector<double> breaks[3] = { { 0, 0.3, 0.7, 1.0 }, { 0, 0.5, 1.0 },
      { -1.0, -0.2, 0.6, 1.0 } };
    std::string error;
    SV_CHECK(status, builder.InitializeTensorProduct(degree, breaks, 2, &error));
    builder.SetCoefficientsFromGreville(
      [](const double g[3], double* c)
      {
        c[0] = std::sin(3 * g[0]) + g[1] * g[2];
        c[1] = g[0] - 2 * g[2];
      });
    const double golden = 0.5 * (std::sqrt(5.0) - 1.0);
    const double targets[3][3] = { { 0.31, 0.62, 0.1 }, { 0.8, 0.2, -0.7 }, { 0.05, 0.95, 0.9 } };
    for (int level = 0; level < 4; ++level)
    {
      for (const auto& t : targets)
      {
        SV_CHECK_MSG(status, builder.RefineAt(t, level % 2 ? 0.5 : golden, &error), error);
      }
    }
    const vtkLRSplinePatch& patch = builder.GetPatch();
    std::cout << "generated: " << patch.GetNumberOfElements() << " elements, "
              << patch.GetNumberOfBasisFunctions() << " basis functions" << std::endl;
    SV_CHECK(status, patch.GetNumberOfElements() > 200);
    const std::string path =
      std::string(SPLINEVIZ_TEST_OUTPUT_DIR) + "/TestLRSplineReader-generated.lr";
    {
      std::ofstream out(path);
      patch.Write(out);
    }
    const auto bruteGen = lrtest::ParseLR(lrtest::ReadText(path));
    SV_CHECK(status, bruteGen.size() == 1);
    vtkNew<vtkLRSplineReader> r;
    r->SetFileName(path.c_str());
    r->Update();
    auto* grid = vtkUnstructuredGrid::SafeDownCast(r->GetOutput()->GetBlock(0));
    SV_CHECK_MSG(status, grid != nullptr, r->GetLastErrorMessage());
    if (grid && bruteGen.size() == 1)
    {
      SV_CHECK(status, grid->GetNumberOfCells() == patch.GetNumberOfElements());
      CheckPatch(status, grid, bruteGen[0], one, zero, 2000, "generated LR volume");
      vtkDataArray* levels =
        grid->GetFieldData()->GetArray(vtkLRSplineArrayNames::RefinementLevels);
      SV_CHECK(status, levels->GetComponent(0, 0) >= 3);
    }
  }
  return status.Result();
}
