#include "vtkNIfTITensorReader.h"

#include "vtkSplineVizNameList.h"
#include "vtkSplineVizTensorMath.h"

#include "vtkCallbackCommand.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMatrix4x4.h"
#include "vtkIntArray.h"
#include "vtkNIFTIImageHeader.h"
#include "vtkNIFTIImageReader.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>
#include <cmath>
#include <cctype>
#include <cstring>
#include <fstream>
#include <limits>
#include <vector>

vtkStandardNewMacro(vtkNIfTITensorReader);

namespace TM = vtkSplineVizTensorMath;

namespace
{
// NIfTI-1 data type codes that cannot hold tensor components.
constexpr int NIFTI_COMPLEX64 = 32;
constexpr int NIFTI_COMPLEX128 = 1792;
constexpr int NIFTI_COMPLEX256 = 2048;
constexpr int NIFTI_RGB24 = 128;
constexpr int NIFTI_RGBA32 = 2304;
constexpr int NIFTI_FLOAT64 = 64;

// Collects the messages of VTK's NIfTI reader (and its executive) so that
// they become this reader's error, instead of being printed on their own.
struct MessageCatcher
{
  std::string Text;
  vtkNew<vtkCallbackCommand> Command;
  MessageCatcher()
  {
    this->Command->SetClientData(this);
    this->Command->SetCallback(
      [](vtkObject*, unsigned long, void* clientData, void* callData)
      {
        auto* self = static_cast<MessageCatcher*>(clientData);
        if (callData && self->Text.empty())
        {
          std::string msg = static_cast<const char*>(callData);
          // VTK's messages start with the file and line; keep the last line.
          while (!msg.empty() && (msg.back() == '\n' || msg.back() == ' '))
          {
            msg.pop_back();
          }
          const auto nl = msg.find_last_of('\n');
          msg = nl == std::string::npos ? msg : msg.substr(nl + 1);
          // and drop the "vtkNIFTIImageReader (0x...): " prefix
          const auto tag = msg.find("): ");
          if (tag != std::string::npos && msg.find(" (0x") < tag)
          {
            msg = msg.substr(tag + 3);
          }
          self->Text = msg;
        }
      });
  }
  void Watch(vtkAlgorithm* a)
  {
    a->AddObserver(vtkCommand::ErrorEvent, this->Command);
    a->AddObserver(vtkCommand::WarningEvent, this->Command);
    a->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, this->Command);
  }
};

// What a NIfTI header says about one volume.
struct Volume
{
  std::string FileName;
  int Dims[3] = { 0, 0, 0 };
  vtkTypeInt64 Dim4 = 1, Dim5 = 1;
  int Components = 0;
  bool TimeAsVector = false;
  int DataType = 0;
  double Slope = 1.0, Intercept = 0.0;
  double A[4][4];            // voxel index -> world mm
  bool Flip = false;         // output slice k' = nz - 1 - k
  bool InternalFlip = false; // VTK's reader stores slice nz - 1 - k at k
  double InvA[4][4];
};

// Inverts an affine (4x4, row-major); false when it is singular.
bool Invert(const double m[4][4], double inv[4][4])
{
  if (!(std::abs(vtkMatrix4x4::Determinant(&m[0][0])) > 0.0))
  {
    return false;
  }
  vtkMatrix4x4::Invert(&m[0][0], &inv[0][0]);
  return true;
}

double Det3(const double m[4][4])
{
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
    m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
    m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

// Reads the header of `file` (through VTK's reader) and the affine chosen by `source`.
bool ReadVolume(const std::string& file, int source, bool tensors, Volume& v, std::string& error)
{
  v = Volume();
  v.FileName = file;
  {
    std::ifstream probe(file, std::ios::in | std::ios::binary);
    if (!probe)
    {
      error = "cannot open \"" + file + "\" (it does not exist or is not readable)";
      return false;
    }
  }
  vtkNew<vtkNIFTIImageReader> reader;
  MessageCatcher catcher;
  catcher.Watch(reader);
  if (!reader->CanReadFile(file.c_str()))
  {
    error = "\"" + file + "\" is not a NIfTI-1/2 file (no valid header)";
    return false;
  }
  reader->SetFileName(file.c_str());
  reader->UpdateInformation();
  vtkNIFTIImageHeader* h = reader->GetNIFTIHeader();
  if (!catcher.Text.empty() || !h)
  {
    error = "\"" + file + "\": " + (catcher.Text.empty() ? "unreadable header" : catcher.Text);
    return false;
  }
  const int ndim = static_cast<int>(h->GetDim(0));
  for (int i = 0; i < 3; ++i)
  {
    const vtkTypeInt64 d = i < ndim ? h->GetDim(i + 1) : 1;
    if (d < 1 || d > (1 << 30))
    {
      error = "\"" + file + "\": bad dimension " + std::to_string(d);
      return false;
    }
    v.Dims[i] = static_cast<int>(d);
  }
  v.Dim4 = ndim >= 4 ? std::max<vtkTypeInt64>(1, h->GetDim(4)) : 1;
  v.Dim5 = ndim >= 5 ? std::max<vtkTypeInt64>(1, h->GetDim(5)) : 1;
  v.DataType = h->GetDataType();
  const double voxels = double(v.Dims[0]) * v.Dims[1] * v.Dims[2];
  if (voxels > 2147483647.0)
  {
    error = "\"" + file + "\": more than 2^31 voxels";
    return false;
  }
  if (tensors)
  {
    if (v.DataType == NIFTI_COMPLEX64 || v.DataType == NIFTI_COMPLEX128 ||
      v.DataType == NIFTI_COMPLEX256 || v.DataType == NIFTI_RGB24 || v.DataType == NIFTI_RGBA32)
    {
      error = "\"" + file + "\": complex or RGB voxels (NIfTI datatype " +
        std::to_string(v.DataType) + ") cannot hold tensor components";
      return false;
    }
    if (v.Dim5 == 6 || v.Dim5 == 9)
    {
      v.Components = static_cast<int>(v.Dim5);
      v.TimeAsVector = false; // the first of Dim4 tensor volumes
    }
    else if (v.Dim5 == 1 && (v.Dim4 == 6 || v.Dim4 == 9))
    {
      v.Components = static_cast<int>(v.Dim4);
      v.TimeAsVector = true;
    }
    else
    {
      const vtkTypeInt64 comps = v.Dim5 > 1 ? v.Dim5 : v.Dim4;
      error = "\"" + file + "\" is " + std::to_string(v.Dims[0]) + " x " +
        std::to_string(v.Dims[1]) + " x " + std::to_string(v.Dims[2]) + " x " +
        std::to_string(v.Dim4) + " x " + std::to_string(v.Dim5) + ": " + std::to_string(comps) +
        " component(s), but a tensor volume needs 6 (symmetric) or 9 (full) components in its " +
        "4th (X x Y x Z x 6, FSL) or 5th dimension (X x Y x Z x 1 x 6, NIfTI standard)";
      return false;
    }
  }
  if (!tensors)
  {
    // a companion: its vector components (4th dimension up to 9, or 5th)
    v.TimeAsVector = v.Dim5 == 1 && v.Dim4 > 1 && v.Dim4 <= 9;
  }
  const double slope = h->GetSclSlope();
  if (std::isfinite(slope) && slope != 0.0)
  {
    v.Slope = slope;
    v.Intercept = std::isfinite(h->GetSclInter()) ? h->GetSclInter() : 0.0;
  }

  // The voxel -> world affine, in mm.
  const int units = h->GetXYZTUnits() & 0x07;
  const double toMM = units == 1 ? 1000.0 : (units == 3 ? 1e-3 : 1.0);
  const int qcode = h->GetQFormCode(), scode = h->GetSFormCode();
  int use = source;
  if (use == vtkNIfTITensorReader::AFFINE_AUTOMATIC)
  {
    use = scode > 0
      ? vtkNIfTITensorReader::AFFINE_SFORM
      : (qcode > 0 ? vtkNIfTITensorReader::AFFINE_QFORM : vtkNIfTITensorReader::AFFINE_PIXDIM);
  }
  double pix[4];
  for (int i = 0; i < 4; ++i)
  {
    pix[i] = h->GetPixDim(i);
  }
  double a[4][4] = {};
  a[3][3] = 1.0;
  if (use == vtkNIfTITensorReader::AFFINE_SFORM)
  {
    if (scode <= 0)
    {
      error = "\"" + file + "\" has no sform (sform_code 0)";
      return false;
    }
    double rows[3][4];
    h->GetSRowX(rows[0]);
    h->GetSRowY(rows[1]);
    h->GetSRowZ(rows[2]);
    for (int i = 0; i < 3; ++i)
    {
      for (int j = 0; j < 4; ++j)
      {
        a[i][j] = rows[i][j];
      }
    }
  }
  else if (use == vtkNIfTITensorReader::AFFINE_QFORM)
  {
    if (qcode <= 0)
    {
      error = "\"" + file + "\" has no qform (qform_code 0)";
      return false;
    }
    const double b = h->GetQuaternB(), c = h->GetQuaternC(), d = h->GetQuaternD();
    const double aa = std::sqrt(std::max(0.0, 1.0 - b * b - c * c - d * d));
    const double r[3][3] = { { aa * aa + b * b - c * c - d * d, 2 * (b * c - aa * d),
                               2 * (b * d + aa * c) },
      { 2 * (b * c + aa * d), aa * aa + c * c - b * b - d * d, 2 * (c * d - aa * b) },
      { 2 * (b * d - aa * c), 2 * (c * d + aa * b), aa * aa + d * d - c * c - b * b } };
    const double qfac = pix[0] < 0 ? -1.0 : 1.0;
    const double s[3] = { pix[1], pix[2], qfac * pix[3] };
    for (int i = 0; i < 3; ++i)
    {
      for (int j = 0; j < 3; ++j)
      {
        a[i][j] = r[i][j] * s[j];
      }
    }
    a[0][3] = h->GetQOffsetX();
    a[1][3] = h->GetQOffsetY();
    a[2][3] = h->GetQOffsetZ();
  }
  else
  {
    for (int i = 0; i < 3; ++i)
    {
      a[i][i] = std::abs(pix[i + 1]) > 0 ? std::abs(pix[i + 1]) : 1.0;
    }
  }
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 4; ++j)
    {
      a[i][j] *= toMM;
      if (!std::isfinite(a[i][j]))
      {
        error = "\"" + file + "\": the voxel to world transform has a non-finite value";
        return false;
      }
    }
  }
  std::memcpy(v.A, a, sizeof(a));
  if (!Invert(v.A, v.InvA))
  {
    error = "\"" + file + "\": the voxel to world transform is singular";
    return false;
  }
  v.Flip = Det3(v.A) < 0;
  v.InternalFlip = reader->GetQFac() < 0;
  return true;
}

// NIfTI slice k of a volume -> the slice VTK's reader stored it at.
inline int InternalSlice(const Volume& v, int k)
{
  return v.InternalFlip ? v.Dims[2] - 1 - k : k;
}

// Reads all voxels of a volume. (Not a sub-extent: VTK 9.2's NIfTI reader
// returns the mirrored slab for sub-extents of files it stores in reverse
// slice order, qfac = -1; the whole file is decompressed anyway.)
vtkSmartPointer<vtkImageData> ReadVoxels(const Volume& v, std::string& error)
{
  vtkNew<vtkNIFTIImageReader> reader;
  MessageCatcher catcher;
  catcher.Watch(reader);
  reader->SetFileName(v.FileName.c_str());
  reader->SetTimeAsVector(v.TimeAsVector);
  reader->Update();
  vtkImageData* image = reader->GetOutput();
  vtkDataArray* scalars = image ? image->GetPointData()->GetScalars() : nullptr;
  const vtkIdType expected = vtkIdType(v.Dims[0]) * v.Dims[1] * v.Dims[2];
  const int* e = image ? image->GetExtent() : nullptr;
  if (!catcher.Text.empty() || !scalars || scalars->GetNumberOfTuples() != expected || e[0] != 0 ||
    e[2] != 0 || e[4] != 0)
  {
    error = "cannot read the voxels of \"" + v.FileName + "\": " +
      (catcher.Text.empty() ? std::string("the file is truncated or damaged") : catcher.Text);
    return nullptr;
  }
  vtkSmartPointer<vtkImageData> result = image;
  return result;
}
}

//------------------------------------------------------------------------------
struct vtkNIfTITensorReader::Internals
{
  vtkSplineVizNameList Companions;
  Volume Tensors;
  int Layout = -1;
  double R[3][3]; // tensor frame -> world
  double Origin[3], Spacing[3], Direction[9];
};

//------------------------------------------------------------------------------
vtkNIfTITensorReader::vtkNIfTITensorReader()
  : Internal(new Internals)
{
  this->SetNumberOfInputPorts(0);
  this->SetTensorArrayName("Tensors");
}

vtkNIfTITensorReader::~vtkNIfTITensorReader()
{
  this->SetFileName(nullptr);
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
  const auto slash = fileName.find_last_of("/\\");
  std::string name = slash == std::string::npos ? fileName : fileName.substr(slash + 1);
  std::string lower = name;
  std::transform(lower.begin(), lower.end(), lower.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  for (const char* ext : { ".nii.gz", ".nii", ".img.gz", ".img", ".hdr.gz", ".hdr" })
  {
    const std::size_t n = std::strlen(ext);
    if (lower.size() > n && lower.compare(lower.size() - n, n, ext) == 0)
    {
      return name.substr(0, name.size() - n);
    }
  }
  return name.empty() ? std::string("Companion") : name;
}

int vtkNIfTITensorReader::CanReadFile(const char* fileName)
{
  if (!fileName)
  {
    return 0;
  }
  vtkNew<vtkNIFTIImageReader> reader;
  return reader->CanReadFile(fileName) > 0 ? 1 : 0;
}

//------------------------------------------------------------------------------
int vtkNIfTITensorReader::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  this->LastError.clear();
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  auto fail = [this, outInfo](const std::string& msg)
  {
    if (vtkDataObject* output = outInfo->Get(vtkDataObject::DATA_OBJECT()))
    {
      output->Initialize(); // no stale data from an earlier read
    }
    this->LastError = msg;
    vtkErrorMacro(<< msg);
    return 0;
  };
  if (!this->FileName || !*this->FileName)
  {
    return fail("no file name was given");
  }
  Internals& in = *this->Internal;
  std::string error;
  if (!ReadVolume(this->FileName, this->AffineSource, true, in.Tensors, error))
  {
    return fail(error);
  }
  const Volume& v = in.Tensors;
  int layout = this->TensorLayout;
  if (layout == LAYOUT_AUTOMATIC)
  {
    layout = v.TimeAsVector ? TM::SYMMETRIC_FSL : TM::SYMMETRIC_NIFTI;
  }
  in.Layout = TM::ResolveLayout(layout, v.Components); // 9 components: always FULL_9
  if (in.Layout < 0)
  {
    return fail(std::string("\"") + this->FileName + "\" has " + std::to_string(v.Components) +
      " tensor components, which cannot be read in the layout " + TM::GetLayoutName(layout));
  }
  if (v.Dim5 > 1 && v.Dim4 > 1)
  {
    vtkWarningMacro(<< this->FileName << " holds " << v.Dim4
                    << " tensor volumes; the first is read");
  }

  // Output geometry: A, with the slices reversed when det A < 0.
  double a[4][4];
  std::memcpy(a, v.A, sizeof(a));
  if (v.Flip)
  {
    for (int i = 0; i < 3; ++i)
    {
      a[i][3] += a[i][2] * (v.Dims[2] - 1);
      a[i][2] = -a[i][2];
    }
  }
  for (int j = 0; j < 3; ++j)
  {
    const double s = std::sqrt(a[0][j] * a[0][j] + a[1][j] * a[1][j] + a[2][j] * a[2][j]);
    in.Spacing[j] = s;
    for (int i = 0; i < 3; ++i)
    {
      in.Direction[3 * i + j] = a[i][j] / s;
    }
  }
  for (int i = 0; i < 3; ++i)
  {
    in.Origin[i] = a[i][3];
  }
  double shear = 0.0;
  for (int p = 0; p < 3; ++p)
  {
    for (int q = p + 1; q < 3; ++q)
    {
      double dot = 0.0;
      for (int i = 0; i < 3; ++i)
      {
        dot += in.Direction[3 * i + p] * in.Direction[3 * i + q];
      }
      shear = std::max(shear, std::abs(dot));
    }
  }
  if (shear > 1e-4)
  {
    vtkWarningMacro(<< this->FileName
                    << ": the voxel to world transform has shear; the image's direction "
                       "matrix is not orthonormal");
  }
  for (int i = 0; i < 4; ++i)
  {
    for (int j = 0; j < 4; ++j)
    {
      this->Affine[4 * i + j] = v.A[i][j];
    }
  }

  // The rotation of the tensors: the orthogonal polar factor of A's 3x3 part,
  // M (M^T M)^(-1/2), through the eigen-decomposition of M^T M.
  double mtm[6];
  {
    double full[3][3];
    for (int p = 0; p < 3; ++p)
    {
      for (int q = 0; q < 3; ++q)
      {
        full[p][q] = v.A[0][p] * v.A[0][q] + v.A[1][p] * v.A[1][q] + v.A[2][p] * v.A[2][q];
      }
    }
    mtm[0] = full[0][0];
    mtm[1] = full[1][1];
    mtm[2] = full[2][2];
    mtm[3] = full[0][1];
    mtm[4] = full[1][2];
    mtm[5] = full[0][2];
  }
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
      in.R[i][j] = v.A[i][0] * inverseRoot[0][j] + v.A[i][1] * inverseRoot[1][j] +
        v.A[i][2] * inverseRoot[2][j];
    }
  }
  if (this->TensorFrame == FRAME_FSL && Det3(v.A) > 0)
  {
    for (int i = 0; i < 3; ++i)
    {
      in.R[i][0] = -in.R[i][0]; // R diag(-1, 1, 1)
    }
  }
  else if (this->TensorFrame == FRAME_WORLD)
  {
    for (int i = 0; i < 3; ++i)
    {
      for (int j = 0; j < 3; ++j)
      {
        in.R[i][j] = i == j ? 1.0 : 0.0;
      }
    }
  }

  const int whole[6] = { 0, v.Dims[0] - 1, 0, v.Dims[1] - 1, 0, v.Dims[2] - 1 };
  outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), whole, 6);
  outInfo->Set(vtkDataObject::ORIGIN(), in.Origin, 3);
  outInfo->Set(vtkDataObject::SPACING(), in.Spacing, 3);
  outInfo->Set(vtkDataObject::DIRECTION(), in.Direction, 9);
  outInfo->Set(CAN_PRODUCE_SUB_EXTENT(), 1);
  return 1;
}

//------------------------------------------------------------------------------
int vtkNIfTITensorReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkImageData* output = vtkImageData::GetData(outInfo);
  output->Initialize();
  auto fail = [this, output](const std::string& msg)
  {
    output->Initialize();
    this->LastError = msg;
    vtkErrorMacro(<< msg);
    return 0;
  };
  if (!this->LastError.empty())
  {
    return fail(this->LastError); // RequestInformation failed
  }
  Internals& in = *this->Internal;
  const Volume& v = in.Tensors;
  int ext[6];
  outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(), ext);
  for (int i = 0; i < 3; ++i)
  {
    ext[2 * i] = std::max(ext[2 * i], 0);
    ext[2 * i + 1] = std::min(ext[2 * i + 1], v.Dims[i] - 1);
    if (ext[2 * i] > ext[2 * i + 1])
    {
      return 1; // an empty piece
    }
  }
  // Output slice k' is NIfTI slice k = nz - 1 - k' when flipped.
  auto niftiSlice = [&v](int kOut) { return v.Flip ? v.Dims[2] - 1 - kOut : kOut; };
  std::string error;
  vtkSmartPointer<vtkImageData> raw = ReadVoxels(v, error);
  if (!raw)
  {
    return fail(error);
  }
  vtkDataArray* comps = raw->GetPointData()->GetScalars();
  if (comps->GetNumberOfComponents() != v.Components)
  {
    return fail("VTK's NIfTI reader gave " + std::to_string(comps->GetNumberOfComponents()) +
      " components instead of " + std::to_string(v.Components));
  }
  this->UpdateProgress(0.4);
  if (this->GetAbortExecute())
  {
    output->Initialize();
    return 1;
  }

  output->SetExtent(ext);
  output->SetOrigin(in.Origin);
  output->SetSpacing(in.Spacing);
  output->SetDirectionMatrix(in.Direction);
  const int nx = ext[1] - ext[0] + 1, ny = ext[3] - ext[2] + 1, nz = ext[5] - ext[4] + 1;
  const vtkIdType n = vtkIdType(nx) * ny * nz;
  const int* rawExt = raw->GetExtent();
  const vtkIdType rnx = rawExt[1] - rawExt[0] + 1, rny = rawExt[3] - rawExt[2] + 1;
  // raw index of output point (i, j, k) (relative to ext)
  auto rawIndex = [&](int i, int j, int k) -> vtkIdType
  {
    const int kInternal = InternalSlice(v, niftiSlice(ext[4] + k));
    return (vtkIdType(kInternal - rawExt[4]) * rny + (ext[2] + j - rawExt[2])) * rnx +
      (ext[0] + i - rawExt[0]);
  };

  vtkSmartPointer<vtkDataArray> tensors;
  if (v.DataType == NIFTI_FLOAT64)
  {
    tensors = vtkSmartPointer<vtkDoubleArray>::New();
  }
  else
  {
    tensors = vtkSmartPointer<vtkFloatArray>::New();
  }
  tensors->SetName(this->TensorArrayName ? this->TensorArrayName : "Tensors");
  tensors->SetNumberOfComponents(6);
  tensors->SetNumberOfTuples(n);
  const int layout = in.Layout;
  const double(*R)[3] = in.R;
  const double slope = v.Slope, intercept = v.Intercept;
  const int nc = v.Components;
  vtkSMPTools::For(0, n,
    [&](vtkIdType b, vtkIdType e)
    {
      double c[9], t[6], m[3][3], rt[3][3], w[3][3];
      const double nan = std::numeric_limits<double>::quiet_NaN();
      for (vtkIdType id = b; id < e; ++id)
      {
        const int i = static_cast<int>(id % nx);
        const int j = static_cast<int>((id / nx) % ny);
        const int k = static_cast<int>(id / (vtkIdType(nx) * ny));
        const vtkIdType r = rawIndex(i, j, k);
        for (int q = 0; q < nc; ++q)
        {
          c[q] = slope * comps->GetComponent(r, q) + intercept;
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
  raw = nullptr;
  output->GetPointData()->SetTensors(tensors);
  this->UpdateProgress(0.7);

  // Companion volumes, on this grid or resampled onto it.
  const std::size_t nCompanions = in.Companions.Names.size();
  for (std::size_t f = 0; f < nCompanions; ++f)
  {
    Volume cv;
    if (!ReadVolume(in.Companions.Names[f], this->AffineSource, false, cv, error))
    {
      return fail("companion volume: " + error);
    }
    bool sameGrid = cv.Dims[0] == v.Dims[0] && cv.Dims[1] == v.Dims[1] && cv.Dims[2] == v.Dims[2];
    const double tolerance = 1e-3 * std::min({ in.Spacing[0], in.Spacing[1], in.Spacing[2] });
    for (int p = 0; p < 3 && sameGrid; ++p)
    {
      for (int q = 0; q < 4 && sameGrid; ++q)
      {
        sameGrid = std::abs(cv.A[p][q] - v.A[p][q]) <= tolerance;
      }
    }
    vtkSmartPointer<vtkImageData> image = ReadVoxels(cv, error);
    if (!image)
    {
      return fail("companion volume: " + error);
    }
    vtkDataArray* values = image->GetPointData()->GetScalars();
    const int ncc = values->GetNumberOfComponents();
    vtkSmartPointer<vtkDataArray> array;
    if (values->GetDataType() == VTK_DOUBLE)
    {
      array = vtkSmartPointer<vtkDoubleArray>::New();
    }
    else
    {
      array = vtkSmartPointer<vtkFloatArray>::New();
    }
    array->SetName(CompanionArrayName(in.Companions.Names[f]).c_str());
    array->SetNumberOfComponents(ncc);
    array->SetNumberOfTuples(n);
    const int* iext = image->GetExtent();
    const vtkIdType inx = iext[1] - iext[0] + 1, iny = iext[3] - iext[2] + 1;
    const double cs = cv.Slope, ci = cv.Intercept;
    const bool nearest =
      !(values->GetDataType() == VTK_FLOAT || values->GetDataType() == VTK_DOUBLE);
    double toIndex[4][4]; // output index -> companion NIfTI index
    {
      // output index (i, j, k') -> world: origin + D diag(spacing) (i, j, k')
      double o2w[4][4] = {};
      for (int p = 0; p < 3; ++p)
      {
        for (int q = 0; q < 3; ++q)
        {
          o2w[p][q] = in.Direction[3 * p + q] * in.Spacing[q];
        }
        o2w[p][3] = in.Origin[p];
      }
      o2w[3][3] = 1.0;
      for (int p = 0; p < 4; ++p)
      {
        for (int q = 0; q < 4; ++q)
        {
          toIndex[p][q] = cv.InvA[p][0] * o2w[0][q] + cv.InvA[p][1] * o2w[1][q] +
            cv.InvA[p][2] * o2w[2][q] + cv.InvA[p][3] * o2w[3][q];
        }
      }
    }
    vtkSMPTools::For(0, n,
      [&](vtkIdType b, vtkIdType e)
      {
        std::vector<double> out(static_cast<std::size_t>(ncc));
        for (vtkIdType id = b; id < e; ++id)
        {
          const int i = static_cast<int>(id % nx);
          const int j = static_cast<int>((id / nx) % ny);
          const int k = static_cast<int>(id / (vtkIdType(nx) * ny));
          std::fill(out.begin(), out.end(), 0.0);
          if (sameGrid)
          {
            const int kInternal = InternalSlice(cv, niftiSlice(ext[4] + k));
            const vtkIdType r =
              (vtkIdType(kInternal - iext[4]) * iny + (ext[2] + j - iext[2])) * inx +
              (ext[0] + i - iext[0]);
            for (int q = 0; q < ncc; ++q)
            {
              out[q] = cs * values->GetComponent(r, q) + ci;
            }
          }
          else
          {
            const double x[3] = { double(ext[0] + i), double(ext[2] + j), double(ext[4] + k) };
            double u[3];
            for (int p = 0; p < 3; ++p)
            {
              u[p] =
                toIndex[p][0] * x[0] + toIndex[p][1] * x[1] + toIndex[p][2] * x[2] + toIndex[p][3];
            }
            const double eps = 1e-6;
            bool inside = true;
            for (int p = 0; p < 3; ++p)
            {
              inside = inside && u[p] >= -eps && u[p] <= cv.Dims[p] - 1 + eps;
              u[p] = std::min(std::max(u[p], 0.0), double(cv.Dims[p] - 1));
            }
            if (inside && nearest)
            {
              const int ii = static_cast<int>(std::lround(u[0]));
              const int jj = static_cast<int>(std::lround(u[1]));
              const int kk = InternalSlice(cv, static_cast<int>(std::lround(u[2])));
              const vtkIdType r = (vtkIdType(kk) * iny + jj) * inx + ii;
              for (int q = 0; q < ncc; ++q)
              {
                out[q] = cs * values->GetComponent(r, q) + ci;
              }
            }
            else if (inside)
            {
              int i0[3];
              double fr[3];
              for (int p = 0; p < 3; ++p)
              {
                i0[p] = std::min(static_cast<int>(std::floor(u[p])), std::max(cv.Dims[p] - 2, 0));
                fr[p] = u[p] - i0[p];
              }
              for (int corner = 0; corner < 8; ++corner)
              {
                int idx[3];
                double weight = 1.0;
                for (int p = 0; p < 3; ++p)
                {
                  const int bit = (corner >> p) & 1;
                  idx[p] = std::min(i0[p] + bit, cv.Dims[p] - 1);
                  weight *= bit ? fr[p] : 1.0 - fr[p];
                }
                if (weight == 0.0)
                {
                  continue;
                }
                const vtkIdType r =
                  (vtkIdType(InternalSlice(cv, idx[2])) * iny + idx[1]) * inx + idx[0];
                for (int q = 0; q < ncc; ++q)
                {
                  out[q] += weight * (cs * values->GetComponent(r, q) + ci);
                }
              }
            }
          }
          array->SetTuple(id, out.data());
        }
      });
    output->GetPointData()->AddArray(array);
    this->UpdateProgress(0.7 + 0.3 * (f + 1) / nCompanions);
    if (this->GetAbortExecute())
    {
      output->Initialize();
      return 1;
    }
  }

  vtkNew<vtkDoubleArray> affine;
  affine->SetName("NIfTIAffine");
  affine->SetNumberOfComponents(16);
  affine->SetNumberOfTuples(1);
  affine->SetTuple(0, this->Affine);
  output->GetFieldData()->AddArray(affine);
  vtkNew<vtkIntArray> reversed;
  reversed->SetName("NIfTISlicesReversed");
  reversed->InsertNextValue(v.Flip ? 1 : 0);
  output->GetFieldData()->AddArray(reversed);
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkNIfTITensorReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "TensorLayout: " << this->TensorLayout << " ("
     << (this->TensorLayout == LAYOUT_AUTOMATIC ? "automatic"
                                                : TM::GetLayoutName(this->TensorLayout))
     << ")\n";
  os << indent << "TensorFrame: " << this->TensorFrame << "\n";
  os << indent << "AffineSource: " << this->AffineSource << "\n";
  os << indent << "TensorArrayName: " << (this->TensorArrayName ? this->TensorArrayName : "(none)")
     << "\n";
  os << indent << "CompanionFileNames:";
  this->Internal->Companions.Print(os);
}
