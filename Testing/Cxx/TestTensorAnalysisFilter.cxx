// SPDX-License-Identifier: BSD-3-Clause
// Tests of vtkTensorAnalysisFilter:
//  - outputs on an image of tensors R diag(l) R^T with known eigen-systems
//    (eigenvalues, principal eigenvector up to sign, FA, MD, cl, cp, cs from
//    their textbook formulas written here), and against vtkMath::Jacobi;
//  - the same tensors in every component layout give the same outputs;
//    Teem's confidence is passed on;
//  - cell tensors selected by name, float and double precision, all
//    eigenvectors on request;
//  - bad input: NaN/inf tuples (NaN outputs and a warning), a missing array,
//    a wrong number of components, a layout that does not fit (errors);
//  - a multiblock input is processed block by block.
#include "vtkTensorAnalysisFilter.h"

#include "vtkSplineVizTensorMath.h"

#include "SplineVizTestUtilities.h"
#include "TensorTestUtilities.h"

#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkExecutive.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkTestErrorObserver.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace TM = vtkSplineVizTensorMath;

namespace
{
struct Sample
{
  double L[3];    // eigenvalues, any order
  double R[3][3]; // eigenvectors as columns
  double T[6];    // xx yy zz xy yz xz
};

std::vector<Sample> MakeSamples(int n)
{
  vtkNew<vtkMinimalStandardRandomSequence> rnd;
  rnd->SetSeed(42);
  auto next = [&](double lo, double hi)
  {
    rnd->Next();
    return rnd->GetRangeValue(lo, hi);
  };
  std::vector<Sample> out(n);
  for (int s = 0; s < n; ++s)
  {
    Sample& smp = out[s];
    double q[4];
    double norm;
    do
    {
      for (double& c : q)
      {
        c = next(-1, 1);
      }
      norm = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    } while (norm < 0.1 || norm > 1);
    for (double& c : q)
    {
      c /= norm;
    }
    vtkMath::QuaternionToMatrix3x3(q, smp.R);
    // distinct, well separated positive eigenvalues (DTI-like magnitudes)
    smp.L[0] = next(1.0, 2.0) * 1e-3;
    smp.L[1] = next(0.45, 0.55) * 1e-3;
    smp.L[2] = next(0.05, 0.3) * 1e-3;
    if (s % 3 == 1)
    {
      std::swap(smp.L[0], smp.L[2]);
    }
    double m[3][3] = {};
    for (int i = 0; i < 3; ++i)
    {
      for (int j = 0; j < 3; ++j)
      {
        for (int k = 0; k < 3; ++k)
        {
          m[i][j] += smp.R[i][k] * smp.L[k] * smp.R[j][k];
        }
      }
    }
    smp.T[0] = m[0][0];
    smp.T[1] = m[1][1];
    smp.T[2] = m[2][2];
    smp.T[3] = m[0][1];
    smp.T[4] = m[1][2];
    smp.T[5] = m[0][2];
  }
  return out;
}

/// Writes the samples' tensors in `layout` (double).
vtkSmartPointer<vtkDoubleArray> Encode(const std::vector<Sample>& samples, int layout)
{
  auto a = vtkSmartPointer<vtkDoubleArray>::New();
  a->SetName("DTI");
  a->SetNumberOfComponents(TM::GetNumberOfComponents(layout));
  for (const Sample& s : samples)
  {
    const std::vector<double> c = tensortest::Encode(layout, s.T, 0.5);
    a->InsertNextTuple(c.data());
  }
  return a;
}

vtkSmartPointer<vtkImageData> MakeImage(vtkDataArray* tensors, bool asCells)
{
  auto img = vtkSmartPointer<vtkImageData>::New();
  const int n = static_cast<int>(tensors->GetNumberOfTuples());
  if (asCells)
  {
    img->SetDimensions(n + 1, 2, 2);
    img->GetCellData()->AddArray(tensors);
  }
  else
  {
    img->SetDimensions(n, 1, 1);
    img->GetPointData()->AddArray(tensors);
  }
  return img;
}

/// Checks the filter's outputs in `attrs` against the samples.
void CheckOutputs(SplineVizTestStatus& status, const std::vector<Sample>& samples,
  vtkDataSetAttributes* attrs, double tol, const char* what)
{
  vtkDataArray* values = attrs->GetArray("Eigenvalues");
  vtkDataArray* e1 = attrs->GetArray("Eigenvector1");
  vtkDataArray* fa = attrs->GetArray("FractionalAnisotropy");
  vtkDataArray* md = attrs->GetArray("MeanDiffusivity");
  vtkDataArray* cl = attrs->GetArray("LinearAnisotropy");
  vtkDataArray* cp = attrs->GetArray("PlanarAnisotropy");
  vtkDataArray* cs = attrs->GetArray("SphericalAnisotropy");
  SV_CHECK_MSG(status, values && e1 && fa && md && cl && cp && cs, what << ": arrays missing");
  if (!(values && e1 && fa && md && cl && cp && cs))
  {
    return;
  }
  double worst = 0.0;
  for (size_t i = 0; i < samples.size(); ++i)
  {
    const Sample& s = samples[i];
    int order[3] = { 0, 1, 2 };
    std::sort(order, order + 3, [&](int a, int b) { return s.L[a] > s.L[b]; });
    const double l1 = s.L[order[0]], l2 = s.L[order[1]], l3 = s.L[order[2]];
    double w[3], v[3];
    values->GetTuple(static_cast<vtkIdType>(i), w);
    e1->GetTuple(static_cast<vtkIdType>(i), v);
    worst = std::max(
      { worst, std::abs(w[0] - l1) / l1, std::abs(w[1] - l2) / l1, std::abs(w[2] - l3) / l1 });
    const double col[3] = { s.R[0][order[0]], s.R[1][order[0]], s.R[2][order[0]] };
    worst = std::max(worst, 1.0 - std::abs(vtkMath::Dot(v, col)));
    const double mean = (l1 + l2 + l3) / 3.0;
    const double faRef = std::sqrt(1.5 *
      ((l1 - mean) * (l1 - mean) + (l2 - mean) * (l2 - mean) + (l3 - mean) * (l3 - mean)) /
      (l1 * l1 + l2 * l2 + l3 * l3));
    const double S = l1 + l2 + l3;
    const vtkIdType id = static_cast<vtkIdType>(i);
    worst = std::max({ worst, std::abs(fa->GetTuple1(id) - faRef),
      std::abs(md->GetTuple1(id) - mean) / l1, std::abs(cl->GetTuple1(id) - (l1 - l2) / S),
      std::abs(cp->GetTuple1(id) - 2.0 * (l2 - l3) / S),
      std::abs(cs->GetTuple1(id) - 3.0 * l3 / S) });
    // Schultz-Kindlmann's square, as Teem's tenGlyphBqdUvEval
    vtkDataArray* shape = attrs->GetArray("ShapeCoordinates");
    SV_CHECK_MSG(status, shape && shape->GetNumberOfComponents() == 2, what << ": no shape");
    if (shape)
    {
      const double m = std::max(std::abs(l1), std::abs(l3));
      const double x = l1 / m, y = l2 / m, z = l3 / m;
      const double u = (y + 1.0) / 2.0;
      const double v = x > -z ? (z + 1.0) / 2.0 - u + 1.0 : (x + 1.0) / 2.0 - u;
      worst = std::max({ worst, std::abs(shape->GetComponent(id, 0) - u),
        std::abs(shape->GetComponent(id, 1) - v) });
    }
  }
  SV_CHECK_MSG(status, worst < tol, what << ": worst relative error " << worst);
}
}

int TestTensorAnalysisFilter(int, char*[])
{
  SplineVizTestStatus status;
  const std::vector<Sample> samples = MakeSamples(500);

  // Every layout, point data, selected by name; default layout for 6
  // components is VTK's.
  for (int layout :
    { TM::SYMMETRIC_VTK, TM::SYMMETRIC_LOWER, TM::SYMMETRIC_UPPER, TM::FULL_9, TM::TEEM_7 })
  {
    auto img = MakeImage(Encode(samples, layout), false);
    vtkNew<vtkTensorAnalysisFilter> filter;
    filter->SetInputData(img);
    filter->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "DTI");
    if (layout != TM::SYMMETRIC_VTK)
    {
      filter->SetTensorLayout(layout);
    }
    filter->Update();
    auto* out = vtkImageData::SafeDownCast(filter->GetOutput());
    SV_CHECK(status, out && out->GetPointData()->GetArray("DTI"));
    CheckOutputs(status, samples, out->GetPointData(), 1e-12, TM::GetLayoutName(layout));
    SV_CHECK(status, out->GetPointData()->GetArray("Eigenvector2") == nullptr);
    vtkDataArray* conf = out->GetPointData()->GetArray("Confidence");
    SV_CHECK(status, (conf != nullptr) == (layout == TM::TEEM_7));
    if (conf)
    {
      SV_CHECK(status, conf->GetTuple1(7) == 0.5);
    }
    SV_CHECK(status, filter->GetNumberOfInvalidTensors() == 0);
  }

  // A wrong 6-component order gives different results (the layout matters):
  // the DIPY-ordered array read as VTK order.
  {
    auto img = MakeImage(Encode(samples, TM::SYMMETRIC_LOWER), false);
    img->GetPointData()->SetTensors(img->GetPointData()->GetArray("DTI"));
    vtkNew<vtkTensorAnalysisFilter> filter;
    filter->SetInputData(img); // default: active tensors, VTK order
    filter->Update();
    vtkDataArray* fa = filter->GetOutput()->GetPointData()->GetArray("FractionalAnisotropy");
    int differ = 0;
    for (vtkIdType i = 0; i < fa->GetNumberOfTuples(); ++i)
    {
      double w[3];
      double l[3] = { samples[i].L[0], samples[i].L[1], samples[i].L[2] };
      std::sort(l, l + 3);
      filter->GetOutput()->GetPointData()->GetArray("Eigenvalues")->GetTuple(i, w);
      differ += std::abs(w[0] - l[2]) > 1e-6 * l[2];
    }
    SV_CHECK_MSG(status, differ > 450, "wrong layout not detected by the outputs: " << differ);
  }

  // Cell tensors, float precision, all eigenvectors; against Jacobi.
  {
    vtkNew<vtkFloatArray> f;
    f->DeepCopy(Encode(samples, TM::SYMMETRIC_VTK));
    f->SetName("DTI");
    auto img = MakeImage(f, true);
    vtkNew<vtkTensorAnalysisFilter> filter;
    filter->SetInputData(img);
    filter->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, "DTI");
    filter->ComputeAllEigenvectorsOn();
    filter->Update();
    vtkCellData* cd = filter->GetOutput()->GetCellData();
    SV_CHECK(status, vtkFloatArray::SafeDownCast(cd->GetArray("Eigenvalues")) != nullptr);
    CheckOutputs(status, samples, cd, 2e-5, "cell data, float");
    vtkDataArray* e2 = cd->GetArray("Eigenvector2");
    vtkDataArray* e3 = cd->GetArray("Eigenvector3");
    SV_CHECK(status, e2 && e3);
    if (e2 && e3)
    {
      double worst = 0.0;
      for (vtkIdType i = 0; i < f->GetNumberOfTuples(); ++i)
      {
        double t[6], m[3][3], a0[3], a1[3], a2[3], v0[3], v1[3], v2[3], w[3];
        f->GetTuple(i, t);
        TM::ToMatrix(t, m);
        std::copy(m[0], m[0] + 3, a0);
        std::copy(m[1], m[1] + 3, a1);
        std::copy(m[2], m[2] + 3, a2);
        double* a[3] = { a0, a1, a2 };
        double* v[3] = { v0, v1, v2 };
        vtkMath::Jacobi(a, w, v);
        double ev[3];
        for (int k = 0; k < 3; ++k)
        {
          cd->GetArray(k == 0 ? "Eigenvector1" : (k == 1 ? "Eigenvector2" : "Eigenvector3"))
            ->GetTuple(i, ev);
          const double col[3] = { v[0][k], v[1][k], v[2][k] };
          worst = std::max(worst, 1.0 - std::abs(vtkMath::Dot(ev, col)));
        }
      }
      SV_CHECK_MSG(status, worst < 1e-6, "eigenvectors vs Jacobi " << worst);
    }
  }

  // Bad tuples: NaN and infinity give NaN outputs and one warning.
  {
    auto tensors = Encode(samples, TM::SYMMETRIC_VTK);
    tensors->SetComponent(3, 2, std::numeric_limits<double>::quiet_NaN());
    tensors->SetComponent(9, 5, std::numeric_limits<double>::infinity());
    auto img = MakeImage(tensors, false);
    vtkNew<vtkTensorAnalysisFilter> filter;
    filter->SetInputData(img);
    filter->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "DTI");
    vtkNew<vtkTest::ErrorObserver> observer;
    filter->AddObserver(vtkCommand::WarningEvent, observer);
    filter->Update();
    SV_CHECK(status, observer->CheckWarningMessage("2 of 500 tensors") == 0);
    SV_CHECK(status, filter->GetNumberOfInvalidTensors() == 2);
    vtkDataArray* fa = filter->GetOutput()->GetPointData()->GetArray("FractionalAnisotropy");
    SV_CHECK(status, std::isnan(fa->GetTuple1(3)) && std::isnan(fa->GetTuple1(9)));
    SV_CHECK(status, !std::isnan(fa->GetTuple1(4)));
  }

  // Errors: missing array, wrong component count, layout mismatch.
  {
    struct Case
    {
      const char* Array;
      int Comps;
      int Layout;
      const char* Message;
    };
    const Case cases[] = { { "Nope", 6, TM::SYMMETRIC_VTK, "No tensor array" },
      { "DTI", 3, TM::SYMMETRIC_VTK, "has 3 components" },
      { "DTI", 6, TM::FULL_9, "has 6 components" } };
    for (const Case& c : cases)
    {
      vtkNew<vtkDoubleArray> a;
      a->SetName("DTI");
      a->SetNumberOfComponents(c.Comps);
      a->SetNumberOfTuples(4);
      a->Fill(1.0);
      auto img = MakeImage(a, false);
      vtkNew<vtkTensorAnalysisFilter> filter;
      filter->SetInputData(img);
      filter->SetTensorLayout(c.Layout);
      filter->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, c.Array);
      vtkNew<vtkTest::ErrorObserver> observer;
      filter->AddObserver(vtkCommand::ErrorEvent, observer);
      filter->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, observer);
      filter->Update();
      SV_CHECK_MSG(status, observer->CheckErrorMessage(c.Message) == 0, c.Message);
    }
  }

  // Multiblock: each block gets its arrays.
  {
    vtkNew<vtkMultiBlockDataSet> mb;
    mb->SetBlock(0, MakeImage(Encode(samples, TM::SYMMETRIC_VTK), false));
    mb->SetBlock(1, MakeImage(Encode(samples, TM::SYMMETRIC_VTK), false));
    vtkNew<vtkTensorAnalysisFilter> filter;
    filter->SetInputData(mb);
    filter->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "DTI");
    filter->Update();
    auto* out = vtkMultiBlockDataSet::SafeDownCast(filter->GetOutputDataObject(0));
    SV_CHECK(status, out && out->GetNumberOfBlocks() == 2);
    if (out)
    {
      for (unsigned int b = 0; b < 2; ++b)
      {
        auto* blk = vtkImageData::SafeDownCast(out->GetBlock(b));
        SV_CHECK(status, blk != nullptr);
        if (blk)
        {
          CheckOutputs(status, samples, blk->GetPointData(), 1e-12, "multiblock");
        }
      }
    }
  }

  // ShapeCoordinates of indefinite and negative tensors (the Westin metrics
  // are meaningless there): Schultz and Kindlmann's square at known points.
  {
    const double diag[][5] = { { 1, 0, -1, 0.5, 0.5 }, { -1, -1, -1, 0.0, 0.0 },
      { 2, 2, -2, 1.0, 0.0 }, { 1, -1, -1, 0.0, 1.0 }, { 0, 0, -3, 0.5, 0.0 },
      { 1, 0.5, -0.25, 0.75, 0.625 } };
    vtkNew<vtkImageData> img;
    img->SetDimensions(6, 1, 1);
    vtkNew<vtkDoubleArray> t;
    t->SetNumberOfComponents(6);
    t->SetNumberOfTuples(6);
    for (int i = 0; i < 6; ++i)
    {
      const double tuple[6] = { diag[i][0], diag[i][1], diag[i][2], 0, 0, 0 };
      t->SetTuple(i, tuple);
    }
    img->GetPointData()->SetTensors(t);
    vtkNew<vtkTensorAnalysisFilter> filter;
    filter->SetInputData(img);
    filter->Update();
    vtkDataArray* shape =
      vtkDataSet::SafeDownCast(filter->GetOutput())->GetPointData()->GetArray("ShapeCoordinates");
    SV_CHECK(status, shape != nullptr);
    for (int i = 0; shape && i < 6; ++i)
    {
      SV_CHECK_NEAR(status, shape->GetComponent(i, 0), diag[i][3], 1e-12);
      SV_CHECK_NEAR(status, shape->GetComponent(i, 1), diag[i][4], 1e-12);
    }
  }

  return status.Result();
}
