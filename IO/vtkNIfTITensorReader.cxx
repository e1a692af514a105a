// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNIfTITensorReader.h"

#include "vtkSplineVizNameList.h"
#include "vtkSplineVizProgress.h"
#include "vtkSplineVizTensorMath.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMatrix4x4.h"
#include "vtkNIfTIFile.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <vector>

vtkStandardNewMacro(vtkNIfTITensorReader);

namespace TM = vtkSplineVizTensorMath;

namespace
{
// The volumes (indices over dimensions 4 to 7) holding the tensor
// components: the 5th dimension's 6 or 9 (NIfTI standard; the first of
// several 4th-dimension tensor volumes), else the 4th dimension's (FSL).
// Empty when the file does not hold 6 or 9 components in one of them.
std::vector<std::int64_t> TensorVolumes(const vtkNIfTIFile& file, bool& fourD)
{
  const auto& d = file.GetHeader().Dim;
  std::vector<std::int64_t> volumes;
  fourD = false;
  if (d[5] == 6 || d[5] == 9)
  {
    for (std::int64_t c = 0; c < d[5]; ++c)
    {
      volumes.push_back(c * d[4]);
    }
  }
  else if (d[5] == 1 && (d[4] == 6 || d[4] == 9))
  {
    fourD = true;
    for (std::int64_t c = 0; c < d[4]; ++c)
    {
      volumes.push_back(c);
    }
  }
  return volumes;
}

bool HoldsTensors(int dataType)
{
  return vtkNIfTIFile::GetElementsPerVoxel(dataType) == 1;
}

// A companion volume: its file, affine and the volumes that become its components.
struct Companion
{
  std::string Name; // as given
  vtkNIfTIFile File;
  double A[4][4];
  double InvA[4][4];
  std::vector<std::int64_t> Volumes;
};

// Opens a companion and checks everything that could stop it from being read
// onto `points` output points (its header, affine, the memory, its voxels):
// its first volume with all its vector components (the 5th dimension, else a
// 4th dimension of 2 to 9).
bool OpenCompanion(
  const std::string& name, int source, double points, Companion& c, std::string& error)
{
  c.Name = name;
  if (!c.File.Open(name, error))
  {
    return false;
  }
  if (!c.File.ComputeAffine(source, c.A, error))
  {
    error = "\"" + name + "\": " + error;
    return false;
  }
  vtkMatrix4x4::Invert(&c.A[0][0], &c.InvA[0][0]);
  const vtkNIfTIFile::Header& h = c.File.GetHeader();
  const auto& d = h.Dim;
  const int elements = vtkNIfTIFile::GetElementsPerVoxel(h.DataType);
  if (d[5] * elements > 65536)
  {
    error = "\"" + name + "\" has " + std::to_string(d[5] * elements) +
      " components per voxel (more than 65536)";
    return false;
  }
  c.Volumes.clear();
  if (d[5] > 1)
  {
    for (std::int64_t q = 0; q < d[5]; ++q)
    {
      c.Volumes.push_back(q * d[4]);
    }
  }
  else if (d[4] > 1 && d[4] <= 9)
  {
    for (std::int64_t q = 0; q < d[4]; ++q)
    {
      c.Volumes.push_back(q);
    }
  }
  else
  {
    c.Volumes.push_back(0);
  }
  const bool doubles =
    h.DataType == vtkNIfTIFile::FLOAT64 || h.DataType == vtkNIfTIFile::COMPLEX128;
  const double volumes = static_cast<double>(c.Volumes.size());
  const double bytes = static_cast<double>(c.File.GetNumberOfVoxels()) * volumes *
      vtkNIfTIFile::GetValueSize(h.DataType) +
    points * volumes * elements * (doubles ? 8.0 : 4.0);
  if (!vtkSplineVizProgress::CheckOutputSize(bytes, 1.0, "the companion volume", &error))
  {
    error = "\"" + name + "\": " + error;
    return false;
  }
  return c.File.VerifyData(error);
}
}

//------------------------------------------------------------------------------
struct vtkNIfTITensorReader::Internals
{
  explicit Internals(const vtkNIfTIImage& image)
    : Image(image)
  {
  }
  const vtkNIfTIImage& Image; // the tensor file and its placement (vtkNIfTIReaderBase)
  vtkSplineVizNameList Companions;
  std::vector<std::unique_ptr<Companion>> CompanionFiles; // opened by RequestInformation
  std::vector<std::int64_t> Volumes;                      // the volumes of the tensor components
  int Layout = -1;
  double R[3][3]; // tensor frame -> world

  void ComputeTensorRotation(int frame);
  vtkSmartPointer<vtkDataArray> ComputeTensors(
    const vtkNIfTIFile::Voxels& raw, const int ext[6], const char* name);
  vtkSmartPointer<vtkDataArray> ReadCompanion(
    Companion& cv, const int ext[6], vtkAlgorithm* algorithm, std::string& error);
};

//------------------------------------------------------------------------------
vtkNIfTITensorReader::vtkNIfTITensorReader()
  : Internal(new Internals(*this->Image))
{
  this->SetTensorArrayName("Tensors");
}

vtkNIfTITensorReader::~vtkNIfTITensorReader()
{
  this->SetTensorArrayName(nullptr);
}

void vtkNIfTITensorReader::AddCompanionFileName(const char* fileName)
{
  if (this->Internal->Companions.Add(fileName))
  {
    this->Modified();
  }
}

void vtkNIfTITensorReader::RemoveAllCompanionFileNames()
{
  if (this->Internal->Companions.Clear())
  {
    this->Modified();
  }
}

int vtkNIfTITensorReader::GetNumberOfCompanionFileNames() const
{
  return this->Internal->Companions.Size();
}

const char* vtkNIfTITensorReader::GetCompanionFileName(int i) const
{
  return this->Internal->Companions.Get(i);
}

std::string vtkNIfTITensorReader::CompanionArrayName(const std::string& fileName)
{
  const std::string name = vtkNIfTIFile::BaseName(fileName);
  return name.empty() ? std::string("Companion") : name;
}

int vtkNIfTITensorReader::CanReadFile(const char* fileName)
{
  if (!fileName)
  {
    return 0;
  }
  vtkNIfTIFile file;
  std::string error;
  bool fourD = false;
  return file.Open(fileName, error) && HoldsTensors(file.GetHeader().DataType) &&
      !TensorVolumes(file, fourD).empty()
    ? 1
    : 0;
}

//------------------------------------------------------------------------------
int vtkNIfTITensorReader::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  auto fail = [this, outInfo](const std::string& msg) { return this->Fail(outInfo, msg); };
  if (!this->OpenFile(outInfo))
  {
    return 0;
  }
  Internals& in = *this->Internal;
  vtkNIfTIFile& nifti = this->Image->File;
  const std::string file = this->FileName;
  std::string error;
  const vtkNIfTIFile::Header& h = nifti.GetHeader();
  if (!HoldsTensors(h.DataType))
  {
    return fail("\"" + file + "\": complex or RGB voxels (NIfTI datatype " +
      std::to_string(h.DataType) + ") cannot hold tensor components");
  }
  bool fourD = false;
  in.Volumes = TensorVolumes(nifti, fourD);
  if (in.Volumes.empty())
  {
    const std::int64_t comps = h.Dim[5] > 1 ? h.Dim[5] : h.Dim[4];
    return fail("\"" + file + "\" is " + std::to_string(h.Dim[1]) + " x " +
      std::to_string(h.Dim[2]) + " x " + std::to_string(h.Dim[3]) + " x " +
      std::to_string(h.Dim[4]) + " x " + std::to_string(h.Dim[5]) + ": " + std::to_string(comps) +
      " component(s), but a tensor volume needs 6 (symmetric) or 9 (full) components in its " +
      "4th (X x Y x Z x 6, FSL) or 5th dimension (X x Y x Z x 1 x 6, NIfTI standard)");
  }
  const int nc = static_cast<int>(in.Volumes.size());
  int layout = this->TensorLayout;
  if (layout == LAYOUT_AUTOMATIC)
  {
    layout = fourD ? TM::SYMMETRIC_FSL : TM::SYMMETRIC_NIFTI;
  }
  in.Layout = TM::ResolveLayout(layout, nc); // 9 components: always FULL_9
  if (in.Layout < 0)
  {
    return fail("\"" + file + "\" has " + std::to_string(nc) +
      " tensor components, which cannot be read in the layout " + TM::GetLayoutName(layout));
  }
  if (h.Dim[5] > 1 && h.Dim[4] > 1)
  {
    vtkWarningMacro(<< file << " holds " << h.Dim[4] << " tensor volumes; the first is read");
  }
  if (!this->ComputeAffine(outInfo))
  {
    return 0;
  }
  // Everything that can go wrong is found here, not in RequestData (see
  // vtkNIfTIFile::VerifyData): the memory of the whole image (the voxels
  // read and the tensors), the voxels being there, the companions.
  const bool doubles = h.DataType == vtkNIfTIFile::FLOAT64;
  const double points = static_cast<double>(nifti.GetNumberOfVoxels());
  if (!vtkSplineVizProgress::CheckOutputSize(points,
        nc * vtkNIfTIFile::GetValueSize(h.DataType) + (doubles ? 48.0 : 24.0), "the tensors",
        &error))
  {
    return fail("\"" + file + "\": " + error);
  }
  if (!nifti.VerifyData(error))
  {
    return fail(error);
  }
  const std::size_t nCompanions = in.Companions.Names.size();
  in.CompanionFiles.resize(nCompanions);
  for (std::size_t f = 0; f < nCompanions; ++f)
  {
    if (!in.CompanionFiles[f])
    {
      in.CompanionFiles[f].reset(new Companion);
    }
    if (!OpenCompanion(
          in.Companions.Names[f], this->AffineSource, points, *in.CompanionFiles[f], error))
    {
      return fail("companion volume: " + error);
    }
  }
  this->PlaceImage(outInfo);
  in.ComputeTensorRotation(this->TensorFrame);
  return 1;
}

//------------------------------------------------------------------------------
void vtkNIfTITensorReader::Internals::ComputeTensorRotation(int frame)
{
  // The orthogonal polar factor of A's 3x3 part, M (M^T M)^(-1/2), through
  // the eigen-decomposition of M^T M.
  Internals& in = *this;
  const double(*a)[4] = in.Image.A;
  double full[3][3];
  for (int p = 0; p < 3; ++p)
  {
    for (int q = 0; q < 3; ++q)
    {
      full[p][q] = a[0][p] * a[0][q] + a[1][p] * a[1][q] + a[2][p] * a[2][q];
    }
  }
  const double mtm[6] = { full[0][0], full[1][1], full[2][2], full[0][1], full[1][2], full[0][2] };
  double values[3], vectors[3][3];
  TM::EigenDecomposition(mtm, values, vectors);
  double inverseRoot[3][3] = {};
  for (int k = 0; k < 3; ++k)
  {
    const double w = 1.0 / std::sqrt(values[k]);
    for (int p = 0; p < 3; ++p)
    {
      for (int q = 0; q < 3; ++q)
      {
        inverseRoot[p][q] += w * vectors[k][p] * vectors[k][q];
      }
    }
  }
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      in.R[i][j] =
        a[i][0] * inverseRoot[0][j] + a[i][1] * inverseRoot[1][j] + a[i][2] * inverseRoot[2][j];
    }
  }
  const double det = a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
    a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
    a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
  if (frame == FRAME_FSL && det > 0)
  {
    for (int i = 0; i < 3; ++i)
    {
      in.R[i][0] = -in.R[i][0]; // R diag(-1, 1, 1)
    }
  }
  else if (frame == FRAME_WORLD)
  {
    for (int i = 0; i < 3; ++i)
    {
      for (int j = 0; j < 3; ++j)
      {
        in.R[i][j] = i == j ? 1.0 : 0.0;
      }
    }
  }
}

//------------------------------------------------------------------------------
int vtkNIfTITensorReader::RequestPiece(
  vtkInformation* outInfo, vtkImageData* output, const int ext[6])
{
  Internals& in = *this->Internal;
  vtkNIfTIFile::Voxels raw;
  std::string error;
  if (!this->Image->ReadPiece(in.Volumes, ext, this->ReadProgress(0.4), raw, error))
  {
    return this->FailRead(outInfo, error);
  }
  this->UpdateProgress(0.4);
  vtkSmartPointer<vtkDataArray> tensors = in.ComputeTensors(raw, ext, this->TensorArrayName);
  if (!tensors)
  {
    return this->Fail(outInfo,
      "\"" + std::string(this->FileName) +
        "\": the tensors would not fit in this "
        "machine's memory");
  }
  raw = vtkNIfTIFile::Voxels();
  output->GetPointData()->SetTensors(tensors);
  this->UpdateProgress(0.7);
  if (this->CheckAbort())
  {
    output->Initialize();
    return 1;
  }

  // Companion volumes, on this grid or resampled onto it.
  const std::size_t nCompanions = in.CompanionFiles.size();
  for (std::size_t f = 0; f < nCompanions; ++f)
  {
    vtkSmartPointer<vtkDataArray> array = in.ReadCompanion(*in.CompanionFiles[f], ext, this, error);
    if (!array)
    {
      return error == "aborted" ? this->FailRead(outInfo, error)
                                : this->Fail(outInfo, "companion volume: " + error);
    }
    output->GetPointData()->AddArray(array);
    this->UpdateProgress(0.7 + 0.3 * (f + 1) / nCompanions);
    if (this->CheckAbort())
    {
      output->Initialize();
      return 1;
    }
  }
  this->FinishPiece(output, ext);
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkDataArray> vtkNIfTITensorReader::Internals::ComputeTensors(
  const vtkNIfTIFile::Voxels& raw, const int ext[6], const char* name)
{
  Internals& in = *this;
  const int nx = ext[1] - ext[0] + 1, ny = ext[3] - ext[2] + 1, nz = ext[5] - ext[4] + 1;
  const vtkIdType n = vtkIdType(nx) * ny * nz;
  const bool doubles = in.Image.File.GetHeader().DataType == vtkNIfTIFile::FLOAT64;
  std::string error;
  if (!vtkSplineVizProgress::CheckOutputSize(
        static_cast<double>(n), doubles ? 48.0 : 24.0, "the tensors", &error))
  {
    return nullptr;
  }
  vtkSmartPointer<vtkDataArray> tensors;
  if (doubles)
  {
    tensors = vtkSmartPointer<vtkDoubleArray>::New();
  }
  else
  {
    tensors = vtkSmartPointer<vtkFloatArray>::New();
  }
  tensors->SetName(name ? name : "Tensors");
  tensors->SetNumberOfComponents(6);
  tensors->SetNumberOfTuples(n);
  const int layout = in.Layout;
  const double(*R)[3] = in.R;
  const double slope = in.Image.File.GetSlope(), intercept = in.Image.File.GetIntercept();
  const int nc = static_cast<int>(in.Volumes.size());
  const int fileNX = in.Image.Size[0];
  vtkSMPTools::For(0, n,
    [&](vtkIdType b, vtkIdType e)
    {
      double c[9], t[6], m[3][3], rt[3][3], w[3][3];
      const double nan = std::numeric_limits<double>::quiet_NaN();
      for (vtkIdType id = b; id < e; ++id)
      {
        const int i = ext[0] + static_cast<int>(id % nx);
        const int j = ext[2] + static_cast<int>((id / nx) % ny);
        const int k = in.Image.FileSlice(ext[4] + static_cast<int>(id / (vtkIdType(nx) * ny)));
        for (int q = 0; q < nc; ++q)
        {
          c[q] = slope * raw.Get(q, i, j, k, 0, fileNX) + intercept;
        }
        double out[6] = { nan, nan, nan, nan, nan, nan };
        if (TM::ToSymmetric(layout, c, t))
        {
          TM::ToMatrix(t, m);
          for (int p = 0; p < 3; ++p) // rt = R m
          {
            for (int q = 0; q < 3; ++q)
            {
              rt[p][q] = R[p][0] * m[0][q] + R[p][1] * m[1][q] + R[p][2] * m[2][q];
            }
          }
          for (int p = 0; p < 3; ++p) // w = R m R^T
          {
            for (int q = 0; q < 3; ++q)
            {
              w[p][q] = rt[p][0] * R[q][0] + rt[p][1] * R[q][1] + rt[p][2] * R[q][2];
            }
          }
          out[0] = w[0][0];
          out[1] = w[1][1];
          out[2] = w[2][2];
          out[3] = 0.5 * (w[0][1] + w[1][0]);
          out[4] = 0.5 * (w[1][2] + w[2][1]);
          out[5] = 0.5 * (w[0][2] + w[2][0]);
        }
        tensors->SetTuple(id, out);
      }
    });
  return tensors;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkDataArray> vtkNIfTITensorReader::Internals::ReadCompanion(
  Companion& cv, const int ext[6], vtkAlgorithm* algorithm, std::string& error)
{
  const vtkNIfTIImage& in = this->Image;
  const std::string& name = cv.Name;
  const vtkNIfTIFile::Header& ch = cv.File.GetHeader();
  int size[3];
  for (int p = 0; p < 3; ++p)
  {
    size[p] = cv.File.GetSize(p);
  }
  bool sameGrid = size[0] == in.Size[0] && size[1] == in.Size[1] && size[2] == in.Size[2];
  const double tolerance =
    1e-3 * std::min({ in.Place.Spacing[0], in.Place.Spacing[1], in.Place.Spacing[2] });
  for (int p = 0; p < 3 && sameGrid; ++p)
  {
    for (int q = 0; q < 4 && sameGrid; ++q)
    {
      sameGrid = std::abs(cv.A[p][q] - in.A[p][q]) <= tolerance;
    }
  }
  // The same grid: this piece's slices; another grid: all of them (resampled).
  int k0 = 0, k1 = size[2] - 1;
  if (sameGrid)
  {
    in.FileSlices(ext, k0, k1);
  }
  vtkNIfTIFile::Voxels values;
  cv.File.Progress = [algorithm](double) { return !algorithm->CheckAbort(); };
  if (!cv.File.ReadSlices(cv.Volumes, k0, k1, values, error))
  {
    return nullptr;
  }
  const int elements = values.Elements;
  const int ncc = static_cast<int>(cv.Volumes.size()) * elements;
  const int nx = ext[1] - ext[0] + 1, ny = ext[3] - ext[2] + 1, nz = ext[5] - ext[4] + 1;
  const vtkIdType n = vtkIdType(nx) * ny * nz;
  const bool doubles =
    ch.DataType == vtkNIfTIFile::FLOAT64 || ch.DataType == vtkNIfTIFile::COMPLEX128;
  if (!vtkSplineVizProgress::CheckOutputSize(
        static_cast<double>(n) * ncc, doubles ? 8.0 : 4.0, "the companion volume", &error))
  {
    return nullptr;
  }
  vtkSmartPointer<vtkDataArray> array;
  if (doubles)
  {
    array = vtkSmartPointer<vtkDoubleArray>::New();
  }
  else
  {
    array = vtkSmartPointer<vtkFloatArray>::New();
  }
  array->SetName(CompanionArrayName(name).c_str());
  array->SetNumberOfComponents(ncc);
  array->SetNumberOfTuples(n);
  const double cs = cv.File.GetSlope(), ci = cv.File.GetIntercept();
  const bool nearest = !vtkNIfTIFile::IsFloatingPoint(ch.DataType);
  double toIndex[4][4]; // output index -> companion NIfTI index
  {
    // output index (i, j, k') -> world: origin + D diag(spacing) (i, j, k')
    double o2w[4][4] = {};
    for (int p = 0; p < 3; ++p)
    {
      for (int q = 0; q < 3; ++q)
      {
        o2w[p][q] = in.Place.Direction[3 * p + q] * in.Place.Spacing[q];
      }
      o2w[p][3] = in.Place.Origin[p];
    }
    o2w[3][3] = 1.0;
    vtkMatrix4x4::Multiply4x4(&cv.InvA[0][0], &o2w[0][0], &toIndex[0][0]);
  }
  // value of component q (volume q / elements, element q % elements) at a file index
  auto value = [&](int i, int j, int k, int q)
  { return cs * values.Get(q / elements, i, j, k, q % elements, size[0]) + ci; };
  vtkSMPTools::For(0, n,
    [&](vtkIdType b, vtkIdType e)
    {
      std::vector<double> out(static_cast<std::size_t>(ncc));
      for (vtkIdType id = b; id < e; ++id)
      {
        const int i = ext[0] + static_cast<int>(id % nx);
        const int j = ext[2] + static_cast<int>((id / nx) % ny);
        const int k = ext[4] + static_cast<int>(id / (vtkIdType(nx) * ny));
        std::fill(out.begin(), out.end(), 0.0);
        if (sameGrid)
        {
          for (int q = 0; q < ncc; ++q)
          {
            out[q] = value(i, j, in.FileSlice(k), q);
          }
          array->SetTuple(id, out.data());
          continue;
        }
        const double x[3] = { double(i), double(j), double(k) };
        double u[3];
        bool inside = true;
        for (int p = 0; p < 3; ++p)
        {
          u[p] = toIndex[p][0] * x[0] + toIndex[p][1] * x[1] + toIndex[p][2] * x[2] + toIndex[p][3];
          inside = inside && u[p] >= -1e-6 && u[p] <= size[p] - 1 + 1e-6;
          u[p] = std::min(std::max(u[p], 0.0), double(size[p] - 1));
        }
        if (inside && nearest)
        {
          const int ii = static_cast<int>(std::lround(u[0]));
          const int jj = static_cast<int>(std::lround(u[1]));
          const int kk = static_cast<int>(std::lround(u[2]));
          for (int q = 0; q < ncc; ++q)
          {
            out[q] = value(ii, jj, kk, q);
          }
        }
        else if (inside)
        {
          int i0[3];
          double fr[3];
          for (int p = 0; p < 3; ++p)
          {
            i0[p] = std::min(static_cast<int>(std::floor(u[p])), std::max(size[p] - 2, 0));
            fr[p] = u[p] - i0[p];
          }
          for (int corner = 0; corner < 8; ++corner)
          {
            int idx[3];
            double weight = 1.0;
            for (int p = 0; p < 3; ++p)
            {
              const int bit = (corner >> p) & 1;
              idx[p] = std::min(i0[p] + bit, size[p] - 1);
              weight *= bit ? fr[p] : 1.0 - fr[p];
            }
            for (int q = 0; weight != 0.0 && q < ncc; ++q)
            {
              out[q] += weight * value(idx[0], idx[1], idx[2], q);
            }
          }
        }
        array->SetTuple(id, out.data());
      }
    });
  return array;
}

//------------------------------------------------------------------------------
void vtkNIfTITensorReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "TensorLayout: " << this->TensorLayout << " ("
     << (this->TensorLayout == LAYOUT_AUTOMATIC ? "automatic"
                                                : TM::GetLayoutName(this->TensorLayout))
     << ")\n";
  os << indent << "TensorFrame: " << this->TensorFrame << "\n";
  os << indent << "TensorArrayName: " << (this->TensorArrayName ? this->TensorArrayName : "(none)")
     << "\n";
  os << indent << "CompanionFileNames:";
  this->Internal->Companions.Print(os);
}
