// SPDX-License-Identifier: BSD-3-Clause
// vtkLRSplineGeometryMap: inversion of curved (non-affine), also rational,
// isoparametric geometry. The two patches of cube-2patch.lr (geometry mode)
// are bent by a smooth map of their control points; random points of random
// elements are mapped forward by VTK's own Bezier cell interpolation
// (vtkCell::EvaluateLocation, independent of the map's code) and must come
// back to their parameter within 1e-10; points pushed off the boundary along
// the outward normal are outside, pushed inward inside. Negative control: the
// unbent (affine) map puts a bent point elsewhere. Rational: random positive
// weights on the control points ("RationalWeights", VTK's rational Bezier).
#include "vtkLRSplineArrayNames.h"
#include "vtkLRSplineField.h"
#include "vtkLRSplineGeometryMap.h"
#include "vtkLRSplineReader.h"

#include "LRSplineVolumeTestUtilities.h"
#include "SplineVizTestUtilities.h"

#include "vtkCell.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkUnstructuredGrid.h"

#include <cmath>
#include <fstream>
#include <sstream>
#include <iostream>
#include <random>

namespace
{
// The LRSplines text with every coefficient c bent (lrvolume::Bend(c));
// rational: with homogeneous coefficients (w Bend(c), w), random positive
// weights w.
std::string BentText(const std::string& text, bool rational, unsigned seed)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> weight(0.6, 1.6);
  return lrvolume::RewriteCoefficients(text, 3, lrvolume::Bend,
    rational ? std::function<double()>([&]() { return weight(rng); }) : nullptr);
}

std::vector<vtkSmartPointer<vtkUnstructuredGrid>> ReadPatches(
  const std::string& text, bool rational = false)
{
  vtkNew<vtkLRSplineReader> reader;
  reader->SetRationalMode(rational ? 2 : 1);
  reader->ReadFromInputStringOn();
  reader->SetInputString(text);
  reader->GeometryModeOn();
  reader->Update();
  std::vector<vtkSmartPointer<vtkUnstructuredGrid>> grids;
  auto* mb = vtkMultiBlockDataSet::SafeDownCast(reader->GetOutputDataObject(0));
  for (unsigned b = 0; mb && b < mb->GetNumberOfBlocks(); ++b)
  {
    if (auto* g = vtkUnstructuredGrid::SafeDownCast(mb->GetBlock(b)))
    {
      grids.push_back(g);
    }
  }
  return grids;
}

// VTK's interpolation of cell `c` at local s (the independent forward map).
void Forward(vtkUnstructuredGrid* grid, vtkIdType c, const double s[3], double x[3])
{
  double pc[3] = { s[0], s[1], s[2] }, weights[64 * 64];
  int sub = 0;
  vtkCell* cell = grid->GetCell(c);
  cell->EvaluateLocation(sub, pc, x, weights);
}

// Outward unit normal of the face s[d] = side of cell c at s (finite differences).
void FaceNormal(
  vtkUnstructuredGrid* grid, vtkIdType c, const double s[3], int d, int side, double n[3])
{
  const int a = (d + 1) % 3, b = (d + 2) % 3;
  const double h = 1e-6;
  double sa[3] = { s[0], s[1], s[2] }, sb[3] = { s[0], s[1], s[2] }, sd[3] = { s[0], s[1], s[2] };
  sa[a] += h;
  sb[b] += h;
  sd[d] += side ? -h : h;
  double x0[3], xa[3], xb[3], xd[3];
  Forward(grid, c, s, x0);
  Forward(grid, c, sa, xa);
  Forward(grid, c, sb, xb);
  Forward(grid, c, sd, xd);
  double ta[3], tb[3], in[3];
  for (int i = 0; i < 3; ++i)
  {
    ta[i] = xa[i] - x0[i];
    tb[i] = xb[i] - x0[i];
    in[i] = xd[i] - x0[i];
  }
  n[0] = ta[1] * tb[2] - ta[2] * tb[1];
  n[1] = ta[2] * tb[0] - ta[0] * tb[2];
  n[2] = ta[0] * tb[1] - ta[1] * tb[0];
  const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  const double dot = n[0] * in[0] + n[1] * in[1] + n[2] * in[2];
  for (int i = 0; i < 3; ++i)
  {
    n[i] = (dot > 0 ? -1 : 1) * n[i] / len;
  }
}

// Is x inside any patch?
bool InsideAny(const std::vector<vtkLRSplineGeometryMap>& maps, const double x[3])
{
  for (const auto& m : maps)
  {
    double s[3];
    if (m.Invert(x, s) >= 0)
    {
      return true;
    }
  }
  return false;
}

// Random points of random elements of every patch; returns the failures.
int CheckInversion(
  const std::string& text, bool rational, double& worst, double& worstResidual, int& outsideWrong)
{
  int failures = 0;
  std::vector<vtkSmartPointer<vtkUnstructuredGrid>> curved =
    ReadPatches(BentText(text, rational, 7), rational);
  if (curved.size() != 2 || (rational && !curved[0]->GetPointData()->GetRationalWeights()))
  {
    std::cerr << "the bent patches were not read as expected\n";
    return 1;
  }
  std::vector<vtkLRSplineGeometryMap> maps(curved.size());
  for (std::size_t p = 0; p < curved.size(); ++p)
  {
    std::string error;
    if (!maps[p].Build(curved[p], nullptr, &error))
    {
      std::cerr << "Build failed: " << error << "\n";
      return 1;
    }
    if (maps[p].IsAffine())
    {
      std::cerr << "the bent geometry was taken as affine\n";
      ++failures;
    }
  }
  std::mt19937 rng(rational ? 11 : 5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  vtkDataArray* boxes = nullptr;
  for (std::size_t p = 0; p < curved.size(); ++p)
  {
    vtkUnstructuredGrid* g = curved[p];
    boxes = g->GetCellData()->GetArray(vtkLRSplineArrayNames::ParameterBox);
    const vtkIdType nc = g->GetNumberOfCells();
    for (int k = 0; k < 400; ++k)
    {
      const vtkIdType c = std::min<vtkIdType>(nc - 1, static_cast<vtkIdType>(unit(rng) * nc));
      double s[3] = { unit(rng), unit(rng), unit(rng) }, x[3];
      if (k % 10 == 0)
      {
        s[k % 3] = (k / 10) % 2 ? 1.0 : 0.0; // on a face
      }
      Forward(g, c, s, x);
      double box[6];
      boxes->GetTuple(c, box);
      double sr[3];
      const vtkIdType e = maps[p].Invert(x, sr);
      if (e < 0)
      {
        std::cerr << "patch " << p << " cell " << c << ": an inside point was reported outside\n";
        ++failures;
        continue;
      }
      // Compare in parameter space (on a face, the neighbour's parameter is
      // the same point).
      double u[3], ur[3];
      for (int d = 0; d < 3; ++d)
      {
        u[d] = box[d] + s[d] * (box[d + 3] - box[d]);
      }
      maps[p].LocalToParameter(e, sr, ur);
      double xr[3];
      maps[p].Map(e, sr, xr, nullptr);
      for (int d = 0; d < 3; ++d)
      {
        worst = std::max(worst, std::abs(u[d] - ur[d]));
        worstResidual = std::max(worstResidual, std::abs(x[d] - xr[d]));
      }
      // Boundary faces of the patch: outside along the outward normal.
      if (k % 10 == 0)
      {
        const int d = k % 3, side = (k / 10) % 2;
        const double* dom = maps[p].GetVolume().GetBox(0);
        (void)dom;
        double n[3];
        FaceNormal(g, c, s, d, side, n);
        const double eps = 1e-4;
        const double xo[3] = { x[0] + eps * n[0], x[1] + eps * n[1], x[2] + eps * n[2] };
        const double xi[3] = { x[0] - eps * n[0], x[1] - eps * n[1], x[2] - eps * n[2] };
        double so[3];
        // Inward: inside this patch. Outward: outside this element; outside the
        // patch when the face is on the patch boundary.
        if (maps[p].Invert(xi, so) < 0)
        {
          std::cerr << "patch " << p << ": a point just inside was reported outside\n";
          ++outsideWrong;
        }
        double u0[3];
        for (int i = 0; i < 3; ++i)
        {
          u0[i] = box[i] + s[i] * (box[i + 3] - box[i]);
        }
        const bool patchBoundary = (side ? u0[d] >= 1.0 - 1e-12 : u0[d] <= 1e-12);
        const vtkIdType eo = maps[p].Invert(xo, so);
        if (patchBoundary && eo >= 0)
        {
          std::cerr << "patch " << p << ": a point outside the patch was reported inside\n";
          ++outsideWrong;
        }
        if (!patchBoundary && eo == c)
        {
          std::cerr << "patch " << p << ": a point outside the element was reported in it\n";
          ++outsideWrong;
        }
      }
    }
  }
  // The field evaluation on the same geometry: the geometry-mode array
  // "Field" holds the coefficients themselves (x, y, z, and the weight when
  // rational: a field on the rational basis), so f(x) = x.
  {
    vtkNew<vtkMultiBlockDataSet> mb;
    for (std::size_t p = 0; p < curved.size(); ++p)
    {
      mb->SetBlock(static_cast<unsigned>(p), curved[p]);
    }
    vtkLRSplineField field;
    std::string error;
    if (!field.Build(mb, "Field", vtkLRSplineElementLocator::KD_FOREST, nullptr, false, &error))
    {
      std::cerr << "field: " << error << "\n";
      return failures + 1;
    }
    double worstField = 0.0;
    for (int k = 0; k < 200; ++k)
    {
      const std::size_t p = k % 2;
      const vtkIdType c = static_cast<vtkIdType>(unit(rng) * (curved[p]->GetNumberOfCells() - 1));
      const double s[3] = { unit(rng), unit(rng), unit(rng) };
      double x[3], v[8];
      Forward(curved[p], c, s, x);
      if (field.Evaluate(x, v, nullptr) < 0)
      {
        ++failures;
        continue;
      }
      for (int d = 0; d < 3; ++d)
      {
        worstField = std::max(worstField, std::abs(v[d] - x[d]));
      }
    }
    std::cout << (rational ? "rational" : "polynomial") << " field f(x) = x: largest error "
              << worstField << "\n";
    if (!(worstField <= 1e-10))
    {
      ++failures;
    }
  }
  // Points far away and outside both patches' boxes.
  const double far[3][3] = { { 5, 5, 5 }, { -1, 0.5, 0.5 }, { 0.5, 0.5, 3 } };
  for (const auto& x : far)
  {
    if (InsideAny(maps, x))
    {
      ++outsideWrong;
    }
  }
  return failures;
}
}

int TestLRSplineGeometryMap(int, char*[])
{
  std::ifstream file(std::string(SPLINEVIZ_EXTERNAL_DATA_DIR) + "/cube-2patch.lr");
  std::stringstream buffer;
  buffer << file.rdbuf();
  const std::string text = buffer.str();
  std::vector<vtkSmartPointer<vtkUnstructuredGrid>> grids = ReadPatches(text);
  if (grids.size() != 2)
  {
    std::cerr << "expected the two patches of cube-2patch.lr\n";
    return EXIT_FAILURE;
  }
  int failures = 0;
  // The unbent cube is affine (the fast path).
  for (auto& g : grids)
  {
    vtkLRSplineGeometryMap m;
    std::string error;
    if (!m.Build(g, nullptr, &error) || !m.IsAffine())
    {
      std::cerr << "the cube's patches should be affine: " << error << "\n";
      ++failures;
    }
  }
  for (bool rational : { false, true })
  {
    double worst = 0.0, residual = 0.0;
    int outsideWrong = 0;
    failures += CheckInversion(text, rational, worst, residual, outsideWrong);
    std::cout << (rational ? "rational" : "polynomial") << " bent cube: largest parameter error "
              << worst << ", residual " << residual << ", wrong inside/outside " << outsideWrong
              << "\n";
    if (!(worst <= 1e-10) || !(residual <= 1e-12) || outsideWrong > 0)
    {
      ++failures;
    }
  }
  // Negative control: the unbent map does not invert a bent point.
  {
    vtkLRSplineGeometryMap flat;
    flat.Build(grids[0], nullptr, nullptr);
    auto bent = ReadPatches(BentText(text, false, 1))[0];
    const double s[3] = { 0.3, 0.6, 0.4 };
    double x[3], sr[3], box[6], ur[3];
    Forward(bent, 5, s, x);
    bent->GetCellData()->GetArray(vtkLRSplineArrayNames::ParameterBox)->GetTuple(5, box);
    const vtkIdType e = flat.Invert(x, sr);
    double err = 1.0;
    if (e >= 0)
    {
      flat.LocalToParameter(e, sr, ur);
      err = 0.0;
      for (int d = 0; d < 3; ++d)
      {
        err = std::max(err, std::abs(ur[d] - (box[d] + s[d] * (box[d + 3] - box[d]))));
      }
    }
    std::cout << "negative control (unbent map): parameter error " << err << "\n";
    if (!(err > 1e-4))
    {
      std::cerr << "the negative control did not fail\n";
      ++failures;
    }
  }
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
