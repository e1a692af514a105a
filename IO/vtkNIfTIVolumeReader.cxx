// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNIfTIVolumeReader.h"

#include "vtkNIfTIFile.h"
#include "vtkSplineVizProgress.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkTypeTraits.h"

#include <algorithm>
#include <cstring>
#include <type_traits>
#include <vector>

vtkStandardNewMacro(vtkNIfTIVolumeReader);

namespace
{
constexpr int MaximumComponents = 65536;

// Calls f(T()) with T the C type of one value (element) of a NIfTI datatype.
template <typename F>
void WithElementType(int dataType, F&& f)
{
  switch (dataType)
  {
    case vtkNIfTIFile::UINT8:
    case vtkNIfTIFile::RGB24:
    case vtkNIfTIFile::RGBA32:
      f(vtkTypeUInt8());
      break;
    case vtkNIfTIFile::INT8:
      f(vtkTypeInt8());
      break;
    case vtkNIfTIFile::INT16:
      f(vtkTypeInt16());
      break;
    case vtkNIfTIFile::UINT16:
      f(vtkTypeUInt16());
      break;
    case vtkNIfTIFile::INT32:
      f(vtkTypeInt32());
      break;
    case vtkNIfTIFile::UINT32:
      f(vtkTypeUInt32());
      break;
    case vtkNIfTIFile::INT64:
      f(vtkTypeInt64());
      break;
    case vtkNIfTIFile::UINT64:
      f(vtkTypeUInt64());
      break;
    case vtkNIfTIFile::FLOAT32:
    case vtkNIfTIFile::COMPLEX64:
      f(vtkTypeFloat32());
      break;
    case vtkNIfTIFile::FLOAT64:
    case vtkNIfTIFile::COMPLEX128:
      f(vtkTypeFloat64());
      break;
    default:
      break;
  }
}

// The VTK type of the output: the voxels' own, or float / double when scaled
// (double for float64 and 32/64-bit integers, which float would round).
int OutputType(int dataType, bool scaled)
{
  int type = VTK_VOID;
  WithElementType(dataType,
    [&](auto v)
    {
      using T = decltype(v);
      type = vtkTypeTraits<T>::VTK_TYPE_ID;
      if (scaled)
      {
        type = sizeof(T) >= 4 && !std::is_same<T, vtkTypeFloat32>::value ? VTK_DOUBLE : VTK_FLOAT;
      }
    });
  return type;
}

// Copies (and scales) the voxels of the output extent `ext` into `out`:
// point id, then for each volume read its `elements` values.
template <typename S, typename D>
void Fill(const vtkNIfTIFile::Voxels& raw, D* out, const int ext[6], int fileNX,
  const vtkNIfTIFile::Placement& place, int nz, bool scaled, double slope, double intercept)
{
  const int nx = ext[1] - ext[0] + 1, ny = ext[3] - ext[2] + 1;
  const vtkIdType n = vtkIdType(nx) * ny * (ext[5] - ext[4] + 1);
  const int elements = raw.Elements;
  const std::size_t volumes = raw.Volumes;
  const std::size_t nc = volumes * static_cast<std::size_t>(elements);
  const unsigned char* bytes = raw.Bytes.data();
  vtkSMPTools::For(0, n,
    [&](vtkIdType b, vtkIdType e)
    {
      for (vtkIdType id = b; id < e; ++id)
      {
        const int i = ext[0] + static_cast<int>(id % nx);
        const int j = ext[2] + static_cast<int>((id / nx) % ny);
        const int k =
          vtkNIfTIFile::FileSlice(place, nz, ext[4] + static_cast<int>(id / (vtkIdType(nx) * ny)));
        for (std::size_t m = 0; m < volumes; ++m)
        {
          const std::int64_t voxel =
            (static_cast<std::int64_t>(m) * raw.Slices + (k - raw.FirstSlice)) * raw.SliceVoxels +
            static_cast<std::int64_t>(j) * fileNX + i;
          for (int c = 0; c < elements; ++c)
          {
            S s;
            std::memcpy(
              &s, bytes + static_cast<std::size_t>(voxel * elements + c) * sizeof(S), sizeof(S));
            out[static_cast<std::size_t>(id) * nc + m * elements + c] = scaled
              ? static_cast<D>(slope * static_cast<double>(s) + intercept)
              : static_cast<D>(s);
          }
        }
      }
    });
}
}

//------------------------------------------------------------------------------
struct vtkNIfTIVolumeReader::Internals
{
  std::vector<std::int64_t> Volumes; // the file volumes read, in component order
  int OutputType = VTK_VOID;
  int Components = 1;
  bool Scaled = false;
  std::string Name;
};

//------------------------------------------------------------------------------
vtkNIfTIVolumeReader::vtkNIfTIVolumeReader()
  : Internal(new Internals)
{
}

vtkNIfTIVolumeReader::~vtkNIfTIVolumeReader()
{
  this->SetArrayName(nullptr);
}

int vtkNIfTIVolumeReader::CanReadFile(const char* fileName)
{
  return fileName && vtkNIfTIFile::LooksLikeNIfTI(fileName) ? 1 : 0;
}

//------------------------------------------------------------------------------
int vtkNIfTIVolumeReader::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  this->VolumeRange[0] = this->VolumeRange[1] = 0;
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  auto fail = [this, outInfo](const std::string& msg) { return this->Fail(outInfo, msg); };
  if (!this->OpenFile(outInfo) || !this->ComputeAffine(outInfo))
  {
    return 0;
  }
  Internals& in = *this->Internal;
  vtkNIfTIFile& nifti = this->Image->File;
  const std::string file = this->FileName;
  std::string error;
  const vtkNIfTIFile::Header& h = nifti.GetHeader();

  // The volumes: the 5th dimension's as components; the 4th (6th, 7th) as
  // components or one of them chosen.
  const std::int64_t n4 = h.Dim[4], n5 = h.Dim[5];
  const std::int64_t steps = h.Dim[4] * h.Dim[6] * h.Dim[7];
  const bool stepsAsComponents = this->FourthDimension == FOURTH_DIMENSION_COMPONENTS ||
    (this->FourthDimension == FOURTH_DIMENSION_AUTOMATIC && n5 == 1 && steps <= 4);
  const int elements = vtkNIfTIFile::GetElementsPerVoxel(h.DataType);
  const std::int64_t components = (stepsAsComponents ? steps : 1) * n5 * elements;
  if (components > MaximumComponents)
  {
    return fail("\"" + file + "\" would give " + std::to_string(components) +
      " components per voxel (more than " + std::to_string(MaximumComponents) +
      "); read one volume of the 4th dimension at a time (FourthDimension VOLUMES)");
  }
  // file volume of step t (flattened 4th, 6th, 7th) and component c5 of the 5th
  auto volume = [&](std::int64_t t, std::int64_t c5) { return t % n4 + n4 * (c5 + n5 * (t / n4)); };
  in.Volumes.clear();
  if (stepsAsComponents)
  {
    for (std::int64_t c5 = 0; c5 < n5; ++c5)
    {
      for (std::int64_t t = 0; t < steps; ++t)
      {
        in.Volumes.push_back(volume(t, c5));
      }
    }
  }
  else
  {
    this->VolumeRange[1] = static_cast<int>(std::min<std::int64_t>(steps - 1, VTK_INT_MAX));
    if (this->VolumeIndex >= steps)
    {
      return fail("\"" + file + "\" has " + std::to_string(steps) + " volumes in its 4th " +
        "dimension; VolumeIndex " + std::to_string(this->VolumeIndex) + " is not one of them");
    }
    for (std::int64_t c5 = 0; c5 < n5; ++c5)
    {
      in.Volumes.push_back(volume(this->VolumeIndex, c5));
    }
  }
  in.Components = static_cast<int>(components);
  in.Scaled = nifti.HasScaling();
  in.OutputType = OutputType(h.DataType, in.Scaled);
  in.Name = this->ArrayName && *this->ArrayName ? this->ArrayName : vtkNIfTIFile::BaseName(file);
  if (in.Name.empty())
  {
    in.Name = "NIfTI";
  }

  // Everything that can go wrong is found here, not in RequestData (see
  // vtkNIfTIFile::VerifyData): the memory the whole image needs (the voxels
  // read and the output), the voxels being there.
  const double perVoxel =
    static_cast<double>(in.Volumes.size()) * vtkNIfTIFile::GetValueSize(h.DataType) +
    static_cast<double>(in.Components) * vtkDataArray::GetDataTypeSize(in.OutputType);
  if (!vtkSplineVizProgress::CheckOutputSize(
        static_cast<double>(nifti.GetNumberOfVoxels()), perVoxel, "the volume", &error))
  {
    return fail("\"" + file + "\": " + error);
  }
  if (!nifti.VerifyData(error))
  {
    return fail(error);
  }
  this->PlaceImage(outInfo);
  vtkDataObject::SetPointDataActiveScalarInfo(outInfo, in.OutputType, in.Components);
  return 1;
}

//------------------------------------------------------------------------------
int vtkNIfTIVolumeReader::RequestPiece(
  vtkInformation* outInfo, vtkImageData* output, const int ext[6])
{
  Internals& in = *this->Internal;
  vtkNIfTIImage& image = *this->Image;
  const int nz = image.Size[2];
  const vtkIdType n =
    vtkIdType(ext[1] - ext[0] + 1) * (ext[3] - ext[2] + 1) * (ext[5] - ext[4] + 1);
  std::string error;
  if (!vtkSplineVizProgress::CheckOutputSize(static_cast<double>(n) * in.Components,
        vtkDataArray::GetDataTypeSize(in.OutputType), "the volume", &error))
  {
    return this->Fail(outInfo, "\"" + std::string(this->FileName) + "\": " + error);
  }
  vtkNIfTIFile::Voxels raw;
  if (!image.ReadPiece(in.Volumes, ext, this->ReadProgress(0.6), raw, error))
  {
    return this->FailRead(outInfo, error);
  }
  vtkSmartPointer<vtkDataArray> array;
  array.TakeReference(vtkDataArray::CreateDataArray(in.OutputType));
  array->SetName(in.Name.c_str());
  array->SetNumberOfComponents(in.Components);
  array->SetNumberOfTuples(n);
  const double slope = image.File.GetSlope(), intercept = image.File.GetIntercept();
  WithElementType(raw.DataType,
    [&](auto v)
    {
      using S = decltype(v);
      void* target = array->GetVoidPointer(0);
      if (in.OutputType == VTK_DOUBLE && !std::is_same<S, double>::value)
      {
        Fill<S, double>(raw, static_cast<double*>(target), ext, image.Size[0], image.Place, nz,
          in.Scaled, slope, intercept);
      }
      else if (in.OutputType == VTK_FLOAT && !std::is_same<S, float>::value)
      {
        Fill<S, float>(raw, static_cast<float*>(target), ext, image.Size[0], image.Place, nz,
          in.Scaled, slope, intercept);
      }
      else
      {
        Fill<S, S>(raw, static_cast<S*>(target), ext, image.Size[0], image.Place, nz, in.Scaled,
          slope, intercept);
      }
    });
  this->UpdateProgress(0.9);
  if (this->CheckAbort())
  {
    output->Initialize();
    return 1;
  }
  output->GetPointData()->SetScalars(array);
  this->FinishPiece(output, ext);
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkNIfTIVolumeReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FourthDimension: " << this->FourthDimension << "\n";
  os << indent << "VolumeIndex: " << this->VolumeIndex << "\n";
  os << indent << "VolumeRange: " << this->VolumeRange[0] << " " << this->VolumeRange[1] << "\n";
  os << indent << "ArrayName: " << (this->ArrayName ? this->ArrayName : "(none)") << "\n";
}
