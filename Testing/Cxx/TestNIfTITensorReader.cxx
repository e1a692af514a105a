// SPDX-License-Identifier: BSD-3-Clause
// vtkNIfTITensorReader against an analytic tensor field: NIfTI files written
// byte by byte here (NeuroimagingTestFiles.h) hold T_file = Rf^T T(x) Rf at
// every voxel centre x = A (i, j, k), for affines with rotations and flips
// given as an sform, as a qform with qfac = -1, or without a flip; the reader
// must return T(p) at each of its points p (GetPoint, i.e. with the direction
// matrix), so geometry, slice order, layouts and the tensor rotation are all
// checked at once. Also: 5D (NIfTI lower triangle) and 4D (FSL upper
// triangle) files of the same field read identically, read in the wrong
// layout they do not; 9 components; the FSL and world tensor frames;
// companion volumes on the same grid (copied) and on another grid (a linear
// field resampled trilinearly is exact; an int16 mask by nearest voxel);
// sub-extents; bad input (5 components, truncated, not NIfTI, a missing
// qform, a layout that does not fit, a singular affine, a missing file).
// Independent checks against nibabel and DIPY: TestNeuroimagingNibabel.py.
#include "vtkNIfTITensorReader.h"

#include "NeuroimagingTestFiles.h"
#include "SplineVizTestUtilities.h"

#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkMatrix3x3.h"
#include "vtkPointData.h"
#include "vtkSplineVizTensorMath.h"

#include <array>
#include <cmath>
#include <vector>

namespace
{
using namespace neurotest;
namespace TM = vtkSplineVizTensorMath;
using Mat3 = std::array<std::array<double, 3>, 3>;

// The analytic field in world coordinates (positive definite, anisotropic,
// every component varying): T(x) = 0.2 I + t t^T, t = (1 + x/50, y/40 - 0.3, 0.5 + z/60).
Mat3 World(const double x[3])
{
  const double t[3] = { 1 + x[0] / 50, x[1] / 40 - 0.3, 0.5 + x[2] / 60 };
  Mat3 m;
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      m[i][j] = (i == j ? 0.2 : 0.0) + t[i] * t[j];
    }
  }
  return m;
}

double Linear(const double x[3])
{
  return 3.0 + 0.05 * x[0] - 0.02 * x[1] + 0.03 * x[2];
}

Mat3 Rotation(double angle, double ax, double ay, double az)
{
  const double n = std::sqrt(ax * ax + ay * ay + az * az);
  const double q[4] = { std::cos(angle / 2), std::sin(angle / 2) * ax / n,
    std::sin(angle / 2) * ay / n, std::sin(angle / 2) * az / n };
  double r[3][3];
  vtkMath::QuaternionToMatrix3x3(q, r);
  Mat3 m;
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      m[i][j] = r[i][j];
    }
  }
  return m;
}

Mat3 Mul(const Mat3& a, const Mat3& b)
{
  Mat3 c{};
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      for (int k = 0; k < 3; ++k)
      {
        c[i][j] += a[i][k] * b[k][j];
      }
    }
  }
  return c;
}

Mat3 Transpose(const Mat3& a)
{
  Mat3 t;
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      t[i][j] = a[j][i];
    }
  }
  return t;
}

enum Storage
{
  LOWER_5D,
  UPPER_4D,
  FULL_9_5D
};

// A NIfTI file of the field: voxel (i, j, k) at A (i, j, k); components
// T_file = Rf^T T(x) Rf in the given storage.
NIfTIFile FieldFile(const int dims[3], const double a[3][4], const Mat3& rf, Storage storage,
  bool useQForm, double qfac = 1.0, const Mat3* qRotation = nullptr, const double* pix = nullptr)
{
  NIfTIFile f;
  f.Dim[0] = dims[0];
  f.Dim[1] = dims[1];
  f.Dim[2] = dims[2];
  const int nc = storage == FULL_9_5D ? 9 : 6;
  if (storage == UPPER_4D)
  {
    f.NumberOfDimensions = 4;
    f.Dim[3] = nc;
  }
  else
  {
    f.NumberOfDimensions = 5;
    f.Dim[3] = 1;
    f.Dim[4] = nc;
    f.IntentCode = storage == LOWER_5D ? 1005 : 0;
  }
  if (useQForm)
  {
    double r[3][3], q[4];
    for (int i = 0; i < 3; ++i)
    {
      for (int j = 0; j < 3; ++j)
      {
        r[i][j] = (*qRotation)[i][j];
      }
    }
    vtkMath::Matrix3x3ToQuaternion(r, q);
    if (q[0] < 0)
    {
      for (double& c : q)
      {
        c = -c;
      }
    }
    f.QFormCode = 1;
    f.QFac = static_cast<float>(qfac);
    f.Quatern[0] = q[1];
    f.Quatern[1] = q[2];
    f.Quatern[2] = q[3];
    for (int i = 0; i < 3; ++i)
    {
      f.QOffset[i] = a[i][3];
      f.PixDim[i] = static_cast<float>(pix[i]);
    }
  }
  else
  {
    f.SFormCode = 1;
    for (int i = 0; i < 3; ++i)
    {
      for (int j = 0; j < 4; ++j)
      {
        f.SForm[i][j] = a[i][j];
      }
      f.PixDim[i] =
        static_cast<float>(std::sqrt(a[0][i] * a[0][i] + a[1][i] * a[1][i] + a[2][i] * a[2][i]));
    }
  }
  const std::size_t nv = std::size_t(dims[0]) * dims[1] * dims[2];
  f.Data.assign(nv * nc, 0.0f);
  for (int k = 0; k < dims[2]; ++k)
  {
    for (int j = 0; j < dims[1]; ++j)
    {
      for (int i = 0; i < dims[0]; ++i)
      {
        double x[3];
        for (int r = 0; r < 3; ++r)
        {
          x[r] = a[r][0] * i + a[r][1] * j + a[r][2] * k + a[r][3];
        }
        const Mat3 t = Mul(Transpose(rf), Mul(World(x), rf));
        double c[9];
        if (storage == LOWER_5D)
        {
          const double v[6] = { t[0][0], t[1][0], t[1][1], t[2][0], t[2][1], t[2][2] };
          std::copy(v, v + 6, c);
        }
        else if (storage == UPPER_4D)
        {
          const double v[6] = { t[0][0], t[0][1], t[0][2], t[1][1], t[1][2], t[2][2] };
          std::copy(v, v + 6, c);
        }
        else
        {
          for (int p = 0; p < 9; ++p)
          {
            c[p] = t[p / 3][p % 3];
          }
        }
        const std::size_t voxel = i + std::size_t(dims[0]) * (j + std::size_t(dims[1]) * k);
        for (int q = 0; q < nc; ++q)
        {
          f.Data[voxel + nv * q] = static_cast<float>(c[q]);
        }
      }
    }
  }
  return f;
}

// Largest relative difference between the reader's tensors and T at its points.
double FieldError(vtkImageData* img, const char* name = "Tensors")
{
  vtkDataArray* t = img->GetPointData()->GetArray(name);
  if (!t || t->GetNumberOfComponents() != 6 || img->GetNumberOfPoints() == 0)
  {
    return 1e30;
  }
  double worst = 0;
  for (vtkIdType id = 0; id < img->GetNumberOfPoints(); ++id)
  {
    double p[3], v[6];
    img->GetPoint(id, p);
    t->GetTuple(id, v);
    const Mat3 w = World(p);
    const double ref[6] = { w[0][0], w[1][1], w[2][2], w[0][1], w[1][2], w[0][2] };
    double scale = 0;
    for (double r : ref)
    {
      scale = std::max(scale, std::abs(r));
    }
    for (int c = 0; c < 6; ++c)
    {
      worst = std::max(worst, std::abs(v[c] - ref[c]) / scale);
    }
  }
  return worst;
}

double ArrayDifference(vtkImageData* a, vtkImageData* b)
{
  vtkDataArray* x = a->GetPointData()->GetArray("Tensors");
  vtkDataArray* y = b->GetPointData()->GetArray("Tensors");
  if (!x || !y || x->GetNumberOfTuples() != y->GetNumberOfTuples())
  {
    return 1e30;
  }
  double worst = 0;
  for (vtkIdType i = 0; i < x->GetNumberOfTuples(); ++i)
  {
    for (int c = 0; c < 6; ++c)
    {
      worst = std::max(worst, std::abs(x->GetComponent(i, c) - y->GetComponent(i, c)));
    }
  }
  return worst;
}

vtkSmartPointer<vtkImageData> ReadFile(
  Harness& h, vtkNIfTITensorReader* r, const std::string& path, bool& ok)
{
  r->SetFileName(path.c_str());
  ok = h.Run(r);
  auto copy = vtkSmartPointer<vtkImageData>::New();
  copy->DeepCopy(r->GetOutput());
  return copy;
}
}

int TestNIfTITensorReader(int, char*[])
{
  SplineVizTestStatus status;
  Harness h;
  vtkNew<vtkNIfTITensorReader> reader;
  h.Watch(reader);
  const int dims[3] = { 7, 6, 5 };
  const Mat3 rot = Rotation(0.6, 1, -2, 0.5);
  const Mat3 flipX = { { { -1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } } };
  const double spacing[3] = { 2.0, 2.5, 3.0 };
  bool ok;

  // sform with a rotation and a flip (det < 0), 5D lower triangle: the frame
  // of the tensors is the voxel axes, Rf = Rot F (the polar factor of A).
  double aFlip[3][4];
  {
    const Mat3 m = Mul(rot, flipX);
    const double offset[3] = { 40, -60, 25 };
    for (int i = 0; i < 3; ++i)
    {
      for (int j = 0; j < 3; ++j)
      {
        aFlip[i][j] = m[i][j] * spacing[j];
      }
      aFlip[i][3] = offset[i];
    }
  }
  const Mat3 rfFlip = Mul(rot, flipX);
  const std::string lower = OutDir + "/TestNIfTITensorReader-lower5d.nii";
  FieldFile(dims, aFlip, rfFlip, LOWER_5D, false).Write(lower);
  auto img5 = ReadFile(h, reader, lower, ok);
  SV_CHECK_MSG(status, ok, h.Error());
  const double e5 = FieldError(img5);
  std::cout << "sform, flip, 5D lower: largest relative tensor error " << e5 << std::endl;
  SV_CHECK(status, e5 < 2e-6);
  SV_CHECK(status, img5->GetDirectionMatrix()->Determinant() > 0.999999);
  SV_CHECK(status, img5->GetFieldData()->GetArray("NIfTISlicesReversed")->GetComponent(0, 0) == 1);
  {
    // output point 0 is NIfTI voxel (0, 0, nz - 1): the slices are reversed
    double p[3];
    img5->GetPoint(0, p);
    double x[3];
    for (int r = 0; r < 3; ++r)
    {
      x[r] = aFlip[r][2] * (dims[2] - 1) + aFlip[r][3];
    }
    SV_CHECK_NEAR(
      status, std::abs(p[0] - x[0]) + std::abs(p[1] - x[1]) + std::abs(p[2] - x[2]), 0.0, 1e-5);
    const double* affine = reader->GetAffine();
    SV_CHECK_NEAR(status, affine[0], aFlip[0][0], 1e-6);
    SV_CHECK_NEAR(status, affine[11], aFlip[2][3], 1e-6);
  }

  // the same field as a 4D FSL file: identical tensors; in the wrong layout not
  const std::string upper = OutDir + "/TestNIfTITensorReader-upper4d.nii";
  FieldFile(dims, aFlip, rfFlip, UPPER_4D, false).Write(upper);
  auto img4 = ReadFile(h, reader, upper, ok);
  SV_CHECK_MSG(status, ok, h.Error());
  SV_CHECK_NEAR(status, ArrayDifference(img4, img5), 0.0, 0.0);
  reader->SetTensorLayoutToNIfTI();
  auto wrong = ReadFile(h, reader, upper, ok);
  SV_CHECK(status, ok && FieldError(wrong) > 1e-2);
  reader->SetTensorLayoutToFSL();
  auto right = ReadFile(h, reader, upper, ok);
  SV_CHECK(status, ok && ArrayDifference(right, img5) == 0.0);
  reader->SetTensorLayoutToFSL();
  wrong = ReadFile(h, reader, lower, ok);
  SV_CHECK(status, ok && FieldError(wrong) > 1e-2);
  reader->SetTensorLayoutToAutomatic();
  // negative control: the tensors not rotated (world frame assumed) are wrong
  reader->SetTensorFrameToWorld();
  wrong = ReadFile(h, reader, lower, ok);
  SV_CHECK(status, ok && FieldError(wrong) > 1e-2);
  reader->SetTensorFrameToVoxel();

  // qform with qfac = -1 (VTK's reader reverses its slices), 9 components
  {
    double a[3][4];
    const double qfacSpacing[3] = { spacing[0], spacing[1], -spacing[2] };
    const double offset[3] = { -30, 12, 70 };
    for (int i = 0; i < 3; ++i)
    {
      for (int j = 0; j < 3; ++j)
      {
        a[i][j] = rot[i][j] * qfacSpacing[j];
      }
      a[i][3] = offset[i];
    }
    const Mat3 flipZ = { { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, -1 } } };
    const std::string path = OutDir + "/TestNIfTITensorReader-qform9.nii";
    FieldFile(dims, a, Mul(rot, flipZ), FULL_9_5D, true, -1.0, &rot, spacing).Write(path);
    auto img = ReadFile(h, reader, path, ok);
    SV_CHECK_MSG(status, ok, h.Error());
    const double e = FieldError(img);
    std::cout << "qform, qfac -1, 9 components: largest relative tensor error " << e << std::endl;
    SV_CHECK(status, e < 2e-6);
    // asked for an sform it does not have
    reader->SetAffineSourceToSForm();
    ReadFile(h, reader, path, ok);
    SV_CHECK(status, !ok && h.Error().find("no sform") != std::string::npos);
    reader->SetAffineSourceToAutomatic();
  }

  // no flip (det > 0): the FSL frame flips x, the world frame is unrotated
  double aPlain[3][4];
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      aPlain[i][j] = rot[i][j] * spacing[j];
    }
    aPlain[i][3] = 10.0 * i - 20;
  }
  {
    const std::string path = OutDir + "/TestNIfTITensorReader-fslframe.nii";
    FieldFile(dims, aPlain, Mul(rot, flipX), UPPER_4D, false).Write(path);
    reader->SetTensorFrameToFSL();
    auto img = ReadFile(h, reader, path, ok);
    SV_CHECK(status, ok && FieldError(img) < 2e-6);
    SV_CHECK(status, img->GetFieldData()->GetArray("NIfTISlicesReversed")->GetComponent(0, 0) == 0);
    reader->SetTensorFrameToVoxel(); // the x flip missing: wrong
    img = ReadFile(h, reader, path, ok);
    SV_CHECK(status, ok && FieldError(img) > 1e-2);
    const Mat3 identity = { { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } } };
    const std::string world = OutDir + "/TestNIfTITensorReader-worldframe.nii";
    FieldFile(dims, aPlain, identity, LOWER_5D, false).Write(world);
    reader->SetTensorFrameToWorld();
    img = ReadFile(h, reader, world, ok);
    SV_CHECK(status, ok && FieldError(img) < 2e-6);
    reader->SetTensorFrameToVoxel();
  }

  // Companions: the same grid (copied), another grid (resampled), an int16 mask.
  {
    NIfTIFile same;
    same.Dim[0] = dims[0];
    same.Dim[1] = dims[1];
    same.Dim[2] = dims[2];
    same.SFormCode = 1;
    std::memcpy(same.SForm, aFlip, sizeof(aFlip));
    for (int k = 0; k < dims[2]; ++k)
      for (int j = 0; j < dims[1]; ++j)
        for (int i = 0; i < dims[0]; ++i)
        {
          double x[3];
          for (int r = 0; r < 3; ++r)
          {
            x[r] = aFlip[r][0] * i + aFlip[r][1] * j + aFlip[r][2] * k + aFlip[r][3];
          }
          same.Data.push_back(static_cast<float>(Linear(x)));
        }
    const std::string fa = OutDir + "/TestNIfTITensorReader_FA.nii";
    same.Write(fa);
    // another grid: axis-aligned, 1.5 mm, covering the tensor volume's bounds
    double lo[3], hi[3];
    const double* b = img5->GetBounds(); // of the points, direction matrix included
    NIfTIFile other;
    for (int r = 0; r < 3; ++r)
    {
      lo[r] = b[2 * r] - 2.0;
      hi[r] = b[2 * r + 1] + 2.0;
      other.Dim[r] = static_cast<int>(std::ceil((hi[r] - lo[r]) / 1.5)) + 1;
      other.SForm[r][r] = 1.5;
      other.SForm[r][3] = lo[r];
    }
    other.SFormCode = 1;
    NIfTIFile mask = other;
    mask.Int16 = true;
    for (int k = 0; k < other.Dim[2]; ++k)
      for (int j = 0; j < other.Dim[1]; ++j)
        for (int i = 0; i < other.Dim[0]; ++i)
        {
          const double x[3] = { lo[0] + 1.5 * i, lo[1] + 1.5 * j, lo[2] + 1.5 * k };
          other.Data.push_back(static_cast<float>(Linear(x)));
          mask.Data.push_back(x[2] > 0.5 * (b[4] + b[5]) ? 1.0f : 0.0f);
        }
    const std::string t1 = OutDir + "/TestNIfTITensorReader-T1.nii";
    other.Write(t1);
    const std::string maskFile = OutDir + "/TestNIfTITensorReader-mask.nii";
    mask.Write(maskFile);
    reader->AddCompanionFileName(fa.c_str());
    reader->AddCompanionFileName(t1.c_str());
    reader->AddCompanionFileName(maskFile.c_str());
    auto img = ReadFile(h, reader, lower, ok);
    SV_CHECK_MSG(status, ok, h.Error());
    vtkDataArray* cfa = img->GetPointData()->GetArray("TestNIfTITensorReader_FA");
    vtkDataArray* ct1 = img->GetPointData()->GetArray("TestNIfTITensorReader-T1");
    vtkDataArray* cmask = img->GetPointData()->GetArray("TestNIfTITensorReader-mask");
    SV_CHECK(status, cfa && ct1 && cmask);
    double worstSame = 0, worstOther = 0;
    int maskValues[2] = { 0, 0 };
    bool maskBinary = true;
    for (vtkIdType id = 0; cfa && ct1 && cmask && id < img->GetNumberOfPoints(); ++id)
    {
      double p[3];
      img->GetPoint(id, p);
      const double f = Linear(p);
      worstSame = std::max(worstSame, std::abs(cfa->GetComponent(id, 0) - f) / std::abs(f));
      worstOther = std::max(worstOther, std::abs(ct1->GetComponent(id, 0) - f) / std::abs(f));
      const double m = cmask->GetComponent(id, 0);
      maskBinary = maskBinary && (m == 0.0 || m == 1.0);
      if (m == 0.0 || m == 1.0)
      {
        ++maskValues[static_cast<int>(m)];
      }
    }
    std::cout << "companions: same grid " << worstSame << ", resampled " << worstOther
              << " (relative), mask " << maskValues[0] << " / " << maskValues[1] << std::endl;
    SV_CHECK(status, worstSame < 1e-6);
    SV_CHECK(status, worstOther < 1e-5);
    SV_CHECK(status, maskBinary && maskValues[0] > 0 && maskValues[1] > 0);
    reader->RemoveAllCompanionFileNames();
  }

  // Sub-extents (ParaView's pieces): the same values at the same points, for
  // slices stored reversed (sform with a flip) and for a qform with qfac = -1.
  {
    const std::string qfac = OutDir + "/TestNIfTITensorReader-qform9.nii";
    reader->SetFileName(qfac.c_str());
    const int sub[6] = { 0, 4, 1, 5, 1, 3 };
    reader->UpdateExtent(sub);
    vtkImageData* part = reader->GetOutput();
    SV_CHECK(status, part->GetNumberOfPoints() == 5 * 5 * 3);
    SV_CHECK(status, FieldError(part) < 2e-6);
  }
  {
    reader->SetFileName(lower.c_str());
    const int sub[6] = { 1, 5, 0, 3, 2, 4 };
    reader->UpdateExtent(sub);
    vtkImageData* part = reader->GetOutput();
    SV_CHECK(status, part->GetNumberOfPoints() == 5 * 4 * 3);
    SV_CHECK(status, FieldError(part) < 2e-6);
    const int* e = part->GetExtent();
    SV_CHECK(status, e[0] == 1 && e[1] == 5 && e[4] == 2 && e[5] == 4);
  }

  // Bad input: an error, an empty output.
  {
    NIfTIFile five = FieldFile(dims, aFlip, rfFlip, UPPER_4D, false);
    five.Dim[3] = 5;
    five.Data.resize(std::size_t(dims[0]) * dims[1] * dims[2] * 5);
    const std::string fivePath = OutDir + "/TestNIfTITensorReader-five.nii";
    five.Write(fivePath);
    const std::string bytes = ReadBytes(lower);
    const std::string truncated = OutDir + "/TestNIfTITensorReader-truncated.nii";
    WriteBytes(truncated, bytes.substr(0, bytes.size() / 2));
    const std::string notNifti = OutDir + "/TestNIfTITensorReader-not.nii";
    WriteBytes(notNifti, std::string(600, 'x'));
    NIfTIFile singular = FieldFile(dims, aFlip, rfFlip, LOWER_5D, false);
    for (auto& row : singular.SForm)
    {
      row[0] = row[1] = 0.0;
    }
    const std::string singularPath = OutDir + "/TestNIfTITensorReader-singular.nii";
    singular.Write(singularPath);
    struct Bad
    {
      std::string Path, Expected;
      int Layout;
    };
    const std::vector<Bad> cases = { { fivePath, "6 (symmetric) or 9", -1 },
      { truncated, "truncated", -1 }, { notNifti, "not a NIfTI", -1 },
      { singularPath, "singular", -1 }, { lower, "cannot be read in the layout", 0 },
      { OutDir + "/no-such-file.nii.gz", "does not exist", -1 } };
    for (const Bad& c : cases)
    {
      reader->SetTensorLayout(c.Layout);
      auto img = ReadFile(h, reader, c.Path, ok);
      const std::string msg = reader->GetLastErrorMessage();
      std::cout << c.Path << ": " << msg << std::endl;
      SV_CHECK_MSG(status, !ok, c.Path << " was accepted");
      SV_CHECK_MSG(status,
        img->GetNumberOfPoints() == 0 && !img->GetPointData()->GetArray("Tensors"),
        c.Path << " gave a partial output");
      SV_CHECK_MSG(status, msg.find(c.Expected) != std::string::npos,
        c.Path << ": the message does not say \"" << c.Expected << "\"");
    }
    reader->SetTensorLayoutToAutomatic();
    // and after the errors a good file reads again
    auto img = ReadFile(h, reader, lower, ok);
    SV_CHECK(status, ok && FieldError(img) < 2e-6);
  }
  return status.Result();
}
