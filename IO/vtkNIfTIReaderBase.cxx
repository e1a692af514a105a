// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNIfTIReaderBase.h"

#include "vtkNIfTIFile.h"

#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkStreamingDemandDrivenPipeline.h"

//------------------------------------------------------------------------------
vtkNIfTIReaderBase::vtkNIfTIReaderBase()
  : Image(new vtkNIfTIImage)
{
  this->SetNumberOfInputPorts(0);
}

vtkNIfTIReaderBase::~vtkNIfTIReaderBase()
{
  this->SetFileName(nullptr);
}

//------------------------------------------------------------------------------
int vtkNIfTIReaderBase::Fail(vtkInformation* outInfo, const std::string& message)
{
  vtkNIfTIFile::SetEmptyOutputInformation(outInfo);
  this->LastError = message;
  vtkErrorMacro(<< message);
  return 0;
}

bool vtkNIfTIReaderBase::OpenFile(vtkInformation* outInfo)
{
  this->LastError.clear();
  if (!this->FileName || !*this->FileName)
  {
    return this->Fail(outInfo, "no file name was given");
  }
  std::string error;
  if (!this->Image->File.Open(this->FileName, error))
  {
    return this->Fail(outInfo, error);
  }
  return true;
}

bool vtkNIfTIReaderBase::ComputeAffine(vtkInformation* outInfo)
{
  std::string error;
  if (!this->Image->File.ComputeAffine(this->AffineSource, this->Image->A, error))
  {
    return this->Fail(outInfo, "\"" + std::string(this->FileName) + "\": " + error);
  }
  return true;
}

void vtkNIfTIReaderBase::PlaceImage(vtkInformation* outInfo)
{
  vtkNIfTIImage& image = *this->Image;
  image.ComputePlacement();
  if (image.Place.Shear > 1e-4)
  {
    vtkWarningMacro(<< this->FileName
                    << ": the voxel to world transform has shear; the image's direction "
                       "matrix is not orthonormal");
  }
  for (int i = 0; i < 4; ++i)
  {
    for (int j = 0; j < 4; ++j)
    {
      this->Affine[4 * i + j] = image.A[i][j];
    }
  }
  vtkNIfTIFile::SetOutputInformation(outInfo, image.Size, image.Place);
}

//------------------------------------------------------------------------------
int vtkNIfTIReaderBase::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkImageData* output = vtkImageData::GetData(outInfo);
  output->Initialize();
  if (!this->LastError.empty())
  {
    return this->Fail(outInfo, this->LastError); // RequestInformation failed
  }
  int extent[6];
  outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(), extent);
  if (!vtkNIfTIFile::ClampExtent(extent, this->Image->Size))
  {
    return 1; // an empty piece
  }
  return this->RequestPiece(outInfo, output, extent);
}

std::function<bool(double)> vtkNIfTIReaderBase::ReadProgress(double share)
{
  return [this, share](double f)
  {
    this->UpdateProgress(share * f);
    return !this->CheckAbort();
  };
}

int vtkNIfTIReaderBase::FailRead(vtkInformation* outInfo, const std::string& error)
{
  if (error == "aborted")
  {
    vtkImageData::GetData(outInfo)->Initialize();
    return 1;
  }
  return this->Fail(outInfo, error);
}

void vtkNIfTIReaderBase::FinishPiece(vtkImageData* output, const int extent[6])
{
  vtkNIfTIFile::SetOutputGeometry(output, extent, this->Image->Place);
  vtkNIfTIFile::AddFieldData(output->GetFieldData(), this->Image->A, this->Image->Place.Flip);
}

//------------------------------------------------------------------------------
void vtkNIfTIReaderBase::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "AffineSource: " << this->AffineSource << "\n";
}
