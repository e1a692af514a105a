// SPDX-License-Identifier: BSD-3-Clause
// Inputs of vtkTensorLineTracer:
//  - the same tensors in every component layout (9 components with a skew
//    part that the symmetrization removes, VTK's 6, DIPY's lower and MFEM's
//    upper triangle, Teem's 7) give the same lines;
//  - float tensors give float output (double on request) and the same lines
//    to float accuracy;
//  - the generic data-set path (the image as an unstructured grid of
//    hexahedra, and as a structured grid) gives the image path's lines;
//  - an image with a direction matrix (rotated lattice, rotated tensors)
//    gives the rotated lines;
//  - a multiblock of two images splitting the domain gives the lines of the
//    whole image; composite seed sources keep their order;
//  - voxel seeding: the seeds are exactly the voxels of the stride lattice
//    whose FA (computed here with vtkMath::Jacobi) reaches the threshold,
//    inside the mask; pieces split them and together give the whole output.
#include "vtkTensorLineTracer.h"

#include "vtkSplineVizTensorMath.h"

#include "SplineVizTestUtilities.h"
#include "TensorLineTestFields.h"

#include "vtkAppendFilter.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkImageDataToPointSet.h"
#include "vtkMath.h"
#include "vtkMatrix3x3.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkStructuredGrid.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <set>
#include <vector>

namespace TM = vtkSplineVizTensorMath;
using namespace TensorLineTest;

namespace
{
vtkSmartPointer<vtkPolyData> Trace(vtkDataObject* field, vtkDataObject* seeds,
  const std::function<void(vtkTensorLineTracer*)>& configure = nullptr)
{
  vtkNew<vtkTensorLineTracer> tracer;
  tracer->SetInputData(field);
  if (seeds)
  {
    tracer->SetSourceData(seeds);
  }
  tracer->SetIntegrationStep(0.25);
  tracer->SetStoppingFAThreshold(0.2);
  if (configure)
  {
    configure(tracer);
  }
  tracer->Update();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(tracer->GetOutput());
  return out;
}

// Largest distance between corresponding points (inf when the lines differ
// in number or size).
double Compare(vtkPolyData* a, vtkPolyData* b)
{
  const auto la = GetLines(a), lb = GetLines(b);
  if (la.size() != lb.size() || la.empty())
  {
    return VTK_DOUBLE_MAX;
  }
  double worst = 0.0;
  for (std::size_t k = 0; k < la.size(); ++k)
  {
    if (la[k].Points.size() != lb[k].Points.size() || la[k].SeedId != lb[k].SeedId ||
      la[k].Reasons[0] != lb[k].Reasons[0] || la[k].Reasons[1] != lb[k].Reasons[1])
    {
      return VTK_DOUBLE_MAX;
    }
    for (std::size_t i = 0; i < la[k].Points.size(); ++i)
    {
      const Vec3& p = la[k].Points[i];
      const Vec3& q = lb[k].Points[i];
      worst = std::max(worst, Norm({ p[0] - q[0], p[1] - q[1], p[2] - q[2] }));
    }
  }
  return worst;
}

vtkSmartPointer<vtkImageData> HelixImage(int n = 17)
{
  TendHelix helix;
  const int dims[3] = { n, n, n };
  const double h = 3.0 / (n - 1);
  const double origin[3] = { -1.5, -1.5, -1.5 }, spacing[3] = { h, h, h };
  return MakeImage(
    dims, origin, spacing, [&](const double x[3], double t[6]) { helix.Tensor(x, t); });
}

std::vector<Vec3> SomeSeeds()
{
  TendHelix helix;
  std::vector<Vec3> seeds;
  for (int k = 0; k < 8; ++k)
  {
    Vec3 c = helix.Core(-2.0 + 0.5 * k);
    c[0] += 0.05 * (k % 3);
    seeds.push_back(c);
  }
  return seeds;
}

void TestLayouts(SplineVizTestStatus& status)
{
  auto img = HelixImage();
  auto seeds = MakeSeeds(SomeSeeds());
  auto reference = Trace(img, seeds);
  std::cout << "layouts: reference " << reference->GetNumberOfLines() << " lines, "
            << reference->GetNumberOfPoints() << " points" << std::endl;
  SV_CHECK(status, reference->GetNumberOfLines() == 8);
  vtkDataArray* t6 = img->GetPointData()->GetTensors();
  const int layouts[] = { TM::FULL_9, TM::SYMMETRIC_LOWER, TM::SYMMETRIC_UPPER, TM::TEEM_7 };
  for (int layout : layouts)
  {
    vtkNew<vtkDoubleArray> a;
    a->SetName("Encoded");
    a->SetNumberOfComponents(TM::GetNumberOfComponents(layout));
    for (vtkIdType i = 0; i < t6->GetNumberOfTuples(); ++i)
    {
      double t[6];
      t6->GetTuple(i, t);
      const double xx = t[0], yy = t[1], zz = t[2], xy = t[3], yz = t[4], xz = t[5];
      const double k = 0.25e-3; // a skew part, removed by the symmetrization
      std::vector<double> c;
      switch (layout)
      {
        case TM::FULL_9:
          c = { xx, xy + k, xz - k, xy - k, yy, yz + k, xz + k, yz - k, zz };
          break;
        case TM::SYMMETRIC_LOWER:
          c = { xx, xy, yy, xz, yz, zz };
          break;
        case TM::SYMMETRIC_UPPER:
          c = { xx, xy, xz, yy, yz, zz };
          break;
        default:
          c = { 0.9, xx, xy, xz, yy, yz, zz };
          break;
      }
      a->InsertNextTuple(c.data());
    }
    auto copy = vtkSmartPointer<vtkImageData>::New();
    copy->ShallowCopy(img);
    copy->GetPointData()->AddArray(a);
    auto lines = Trace(copy, seeds,
      [&](vtkTensorLineTracer* t)
      {
        t->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Encoded");
        t->SetTensorLayout(layout == TM::FULL_9 || layout == TM::TEEM_7 ? 1 : layout);
      });
    const double d = Compare(reference, lines);
    std::cout << "  layout " << TM::GetLayoutName(layout) << ": largest difference " << d
              << std::endl;
    SV_CHECK(status, d < 1e-12);
  }
  // a wrong 6-component layout gives other lines (the option matters)
  auto wrong = Trace(img, seeds, [](vtkTensorLineTracer* t) { t->SetTensorLayout(2); });
  SV_CHECK(status, Compare(reference, wrong) > 1e-3);
}

void TestPrecision(SplineVizTestStatus& status)
{
  auto img = HelixImage();
  auto seeds = MakeSeeds(SomeSeeds());
  auto reference = Trace(img, seeds);
  vtkNew<vtkFloatArray> f;
  f->DeepCopy(img->GetPointData()->GetTensors());
  f->SetName("FloatTensors");
  auto copy = vtkSmartPointer<vtkImageData>::New();
  copy->ShallowCopy(img);
  copy->GetPointData()->SetTensors(f);
  auto single = Trace(copy, seeds);
  SV_CHECK(status, single->GetPoints()->GetDataType() == VTK_FLOAT);
  SV_CHECK(status, single->GetPointData()->GetArray("Tensors")->GetDataType() == VTK_FLOAT);
  SV_CHECK(status, reference->GetPoints()->GetDataType() == VTK_DOUBLE);
  auto dbl = Trace(copy, seeds,
    [](vtkTensorLineTracer* t) { t->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION); });
  SV_CHECK(status, dbl->GetPoints()->GetDataType() == VTK_DOUBLE);
  // float tensors: the same lines to float accuracy (rounding differences
  // grow along the lines; compare 40 steps on each side of the seeds)
  const auto a = GetLines(reference), b = GetLines(dbl);
  SV_CHECK(status, a.size() == b.size());
  double worst = 0.0;
  auto seedIndex = [](const TracedLine& l)
  {
    int s = 0;
    for (std::size_t i = 0; i < l.Arc.size(); ++i)
    {
      if (l.Arc[i] == 0.0)
      {
        s = static_cast<int>(i);
      }
    }
    return s;
  };
  for (std::size_t k = 0; k < std::min(a.size(), b.size()); ++k)
  {
    const int sa = seedIndex(a[k]), sb = seedIndex(b[k]);
    for (int j = -40; j <= 40; ++j)
    {
      const int ia = sa + j, ib = sb + j;
      if (ia < 0 || ib < 0 || ia >= static_cast<int>(a[k].Points.size()) ||
        ib >= static_cast<int>(b[k].Points.size()))
      {
        continue;
      }
      const Vec3& p = a[k].Points[ia];
      const Vec3& q = b[k].Points[ib];
      worst = std::max(worst, Norm({ p[0] - q[0], p[1] - q[1], p[2] - q[2] }));
    }
  }
  std::cout << "float vs double tensors: largest difference near the seeds " << worst << std::endl;
  SV_CHECK(status, worst < 1e-5);
}

void TestGenericPaths(SplineVizTestStatus& status)
{
  auto img = HelixImage();
  auto seeds = MakeSeeds(SomeSeeds());
  auto reference = Trace(img, seeds);
  vtkNew<vtkAppendFilter> toGrid; // image -> unstructured grid of hexahedra (voxels)
  toGrid->AddInputData(img);
  toGrid->Update();
  auto ugLines = Trace(toGrid->GetOutput(), seeds);
  vtkNew<vtkImageDataToPointSet> toStructured;
  toStructured->SetInputData(img);
  toStructured->Update();
  auto sgLines = Trace(toStructured->GetOutput(), seeds);
  const double du = Compare(reference, ugLines), ds = Compare(reference, sgLines);
  std::cout << "generic path: unstructured grid " << du << ", structured grid " << ds << std::endl;
  SV_CHECK(status, du < 1e-9);
  SV_CHECK(status, ds < 1e-9);

  // a direction matrix: the lattice and the tensors turned by R
  double q[4] = { std::cos(0.4), 0.3 * std::sin(0.4), -0.5 * std::sin(0.4), 0.0 };
  const double qn = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
  for (double& c : q)
  {
    c /= qn;
  }
  double r[3][3];
  vtkMath::QuaternionToMatrix3x3(q, r);
  auto rotated = vtkSmartPointer<vtkImageData>::New();
  rotated->DeepCopy(img);
  double origin[3];
  img->GetOrigin(origin);
  double rorigin[3];
  vtkMath::Multiply3x3(r, origin, rorigin);
  rotated->SetOrigin(rorigin);
  rotated->SetDirectionMatrix(
    r[0][0], r[0][1], r[0][2], r[1][0], r[1][1], r[1][2], r[2][0], r[2][1], r[2][2]);
  vtkDataArray* t = rotated->GetPointData()->GetTensors();
  for (vtkIdType i = 0; i < t->GetNumberOfTuples(); ++i)
  {
    double v[6], m[3][3], rm[3][3], rmrt[3][3];
    t->GetTuple(i, v);
    TM::ToMatrix(v, m);
    vtkMath::Multiply3x3(r, m, rm);
    double rt[3][3];
    vtkMath::Transpose3x3(r, rt);
    vtkMath::Multiply3x3(rm, rt, rmrt);
    const double w[6] = { rmrt[0][0], rmrt[1][1], rmrt[2][2], rmrt[0][1], rmrt[1][2], rmrt[0][2] };
    t->SetTuple(i, w);
  }
  std::vector<Vec3> rseeds;
  for (Vec3 s : SomeSeeds())
  {
    Vec3 o;
    vtkMath::Multiply3x3(r, s.data(), o.data());
    rseeds.push_back(o);
  }
  auto rlines = Trace(rotated, MakeSeeds(rseeds));
  // turn the reference lines and compare
  auto turned = vtkSmartPointer<vtkPolyData>::New();
  turned->DeepCopy(reference);
  for (vtkIdType i = 0; i < turned->GetNumberOfPoints(); ++i)
  {
    double p[3], o[3];
    turned->GetPoint(i, p);
    vtkMath::Multiply3x3(r, p, o);
    turned->GetPoints()->SetPoint(i, o);
  }
  const double dr = Compare(turned, rlines);
  std::cout << "direction matrix: largest difference " << dr << std::endl;
  SV_CHECK(status, dr < 1e-9);
}

void TestComposite(SplineVizTestStatus& status)
{
  auto img = HelixImage();
  auto seeds = MakeSeeds(SomeSeeds());
  auto reference = Trace(img, seeds);
  // two halves sharing the plane i = 8
  vtkNew<vtkMultiBlockDataSet> mb;
  for (int b = 0; b < 2; ++b)
  {
    vtkNew<vtkImageData> part;
    part->SetOrigin(img->GetOrigin());
    part->SetSpacing(img->GetSpacing());
    part->SetExtent(b == 0 ? 0 : 8, b == 0 ? 8 : 16, 0, 16, 0, 16);
    vtkNew<vtkDoubleArray> t;
    t->SetName("Tensors");
    t->SetNumberOfComponents(6);
    for (int k = 0; k <= 16; ++k)
    {
      for (int j = 0; j <= 16; ++j)
      {
        for (int i = b == 0 ? 0 : 8; i <= (b == 0 ? 8 : 16); ++i)
        {
          t->InsertNextTuple(img->GetPointData()->GetTensors()->GetTuple(i + 17 * (j + 17 * k)));
        }
      }
    }
    part->GetPointData()->SetTensors(t);
    mb->SetBlock(b, part);
  }
  auto lines = Trace(mb, seeds);
  const double d = Compare(reference, lines);
  std::cout << "multiblock field: largest difference " << d << std::endl;
  SV_CHECK(status, d < 1e-10);

  // composite seeds: two point sets, in order
  const auto all = SomeSeeds();
  vtkNew<vtkMultiBlockDataSet> seedBlocks;
  seedBlocks->SetBlock(0, MakeSeeds(std::vector<Vec3>(all.begin(), all.begin() + 3)));
  seedBlocks->SetBlock(1, MakeSeeds(std::vector<Vec3>(all.begin() + 3, all.end())));
  auto split = Trace(img, seedBlocks);
  SV_CHECK(status, Compare(reference, split) == 0.0);
}

void TestVoxelSeeding(SplineVizTestStatus& status)
{
  auto img = HelixImage(21);
  // a mask: the voxels with x > 0 (x = 0.15 and beyond; the interpolated
  // mask reaches 0.5 at x = 0.075)
  vtkNew<vtkDoubleArray> mask;
  mask->SetName("Mask");
  for (vtkIdType i = 0; i < img->GetNumberOfPoints(); ++i)
  {
    double x[3];
    img->GetPoint(i, x);
    mask->InsertNextValue(x[0] > 1e-9 ? 1.0 : 0.0);
  }
  img->GetPointData()->AddArray(mask);
  const double threshold = 0.5;
  for (int stride : { 1, 2, 3 })
  {
    for (bool useMask : { false, true })
    {
      // the expected seeds: FA from vtkMath::Jacobi's eigenvalues
      std::set<std::array<long, 3>> expected;
      int dims[3];
      img->GetDimensions(dims);
      for (int k = 0; k < dims[2]; k += stride)
      {
        for (int j = 0; j < dims[1]; j += stride)
        {
          for (int i = 0; i < dims[0]; i += stride)
          {
            const vtkIdType id = i + dims[0] * (j + dims[1] * k);
            double t[6], m[3][3], w[3], v[3][3];
            img->GetPointData()->GetTensors()->GetTuple(id, t);
            TM::ToMatrix(t, m);
            double* mp[3] = { m[0], m[1], m[2] };
            double* vp[3] = { v[0], v[1], v[2] };
            vtkMath::Jacobi(mp, w, vp);
            const double mean = (w[0] + w[1] + w[2]) / 3;
            const double fa = std::sqrt(1.5 *
              ((w[0] - mean) * (w[0] - mean) + (w[1] - mean) * (w[1] - mean) +
                (w[2] - mean) * (w[2] - mean)) /
              (w[0] * w[0] + w[1] * w[1] + w[2] * w[2]));
            if (fa >= threshold && (!useMask || mask->GetValue(id) >= 0.5))
            {
              expected.insert({ i, j, k });
            }
          }
        }
      }
      vtkNew<vtkTensorLineTracer> tracer;
      tracer->SetInputData(img);
      tracer->SetSeedMode(vtkTensorLineTracer::SEEDS_FROM_VOXELS);
      tracer->SetSeedStride(stride);
      tracer->SetSeedFAThreshold(threshold);
      tracer->SetStoppingFAThreshold(0.2);
      if (useMask)
      {
        tracer->SetInputArrayToProcess(1, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Mask");
      }
      tracer->Update();
      vtkPolyData* out = tracer->GetOutput();
      std::set<std::array<long, 3>> found;
      std::set<int> seedIds;
      bool inMask = true;
      for (const TracedLine& l : GetLines(out))
      {
        seedIds.insert(l.SeedId);
        for (std::size_t i = 0; i < l.Points.size(); ++i)
        {
          if (useMask && l.Points[i][0] < 0.075 - 1e-9)
          {
            inMask = false;
          }
          if (l.Arc[i] == 0.0)
          {
            const double* o = img->GetOrigin();
            const double* s = img->GetSpacing();
            found.insert({ std::lround((l.Points[i][0] - o[0]) / s[0]),
              std::lround((l.Points[i][1] - o[1]) / s[1]),
              std::lround((l.Points[i][2] - o[2]) / s[2]) });
          }
        }
      }
      std::cout << "voxel seeding, stride " << stride << (useMask ? ", mask" : "") << ": "
                << expected.size() << " voxels expected, " << tracer->GetNumberOfSeeds()
                << " seeds, " << out->GetNumberOfLines() << " lines, "
                << tracer->GetNumberOfShortLines() << " single points" << std::endl;
      SV_CHECK(status, tracer->GetNumberOfSeeds() == static_cast<vtkIdType>(expected.size()));
      SV_CHECK(status, tracer->GetNumberOfRejectedSeeds() == 0);
      SV_CHECK(status,
        out->GetNumberOfLines() + tracer->GetNumberOfShortLines() == tracer->GetNumberOfSeeds());
      SV_CHECK(status, std::includes(expected.begin(), expected.end(), found.begin(), found.end()));
      SV_CHECK(status, found.size() == static_cast<std::size_t>(out->GetNumberOfLines()));
      SV_CHECK(status, inMask);
      SV_CHECK(status, expected.size() > 20);

      // pieces: three pieces together give the whole output
      if (stride == 1 && !useMask)
      {
        std::map<int, std::size_t> whole;
        for (const TracedLine& l : GetLines(out))
        {
          whole[l.SeedId] = l.Points.size();
        }
        std::map<int, std::size_t> pieces;
        for (int p = 0; p < 3; ++p)
        {
          tracer->UpdatePiece(p, 3, 0);
          for (const TracedLine& l : GetLines(tracer->GetOutput()))
          {
            SV_CHECK(status, pieces.count(l.SeedId) == 0);
            pieces[l.SeedId] = l.Points.size();
          }
        }
        SV_CHECK(status, pieces == whole);
      }
    }
  }
}
}

int TestTensorLineTracerInputs(int, char*[])
{
  SplineVizTestStatus status;
  TestLayouts(status);
  TestPrecision(status);
  TestGenericPaths(status);
  TestComposite(status);
  TestVoxelSeeding(status);
  return status.Result();
}
