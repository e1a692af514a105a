// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLRSplineResampleToImage.h"

#include "vtkSplineVizPieces.h"
#include "vtkLRSplineField.h"
#include "vtkSplineVizInputArrays.h"
#include "vtkSplineVizProgress.h"

#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>

vtkStandardNewMacro(vtkLRSplineResampleToImage);

//------------------------------------------------------------------------------
vtkLRSplineResampleToImage::vtkLRSplineResampleToImage()
{
  // vtkImageAlgorithm selects the active scalars; nothing selected is the
  // active vectors, else scalars, here.
  vtkSplineVizInputArrays::SetName(this, 0, 0, nullptr);
}

vtkLRSplineResampleToImage::~vtkLRSplineResampleToImage() = default;

//------------------------------------------------------------------------------
void vtkLRSplineResampleToImage::SetArrayName(const char* name)
{
  vtkSplineVizInputArrays::SetName(this, 0, 0, name);
}

const char* vtkLRSplineResampleToImage::GetArrayName()
{
  return vtkSplineVizInputArrays::GetName(this, 0);
}

//------------------------------------------------------------------------------
int vtkLRSplineResampleToImage::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataObject");
  return 1;
}

//------------------------------------------------------------------------------
int vtkLRSplineResampleToImage::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  int extent[6];
  for (int d = 0; d < 3; ++d)
  {
    extent[2 * d] = 0;
    extent[2 * d + 1] = std::max(1, this->SamplingDimensions[d]) - 1;
  }
  outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  if (!this->UseInputBounds)
  {
    double origin[3], spacing[3];
    for (int d = 0; d < 3; ++d)
    {
      origin[d] = this->SamplingBounds[2 * d];
      spacing[d] = extent[2 * d + 1] > 0
        ? (this->SamplingBounds[2 * d + 1] - this->SamplingBounds[2 * d]) / extent[2 * d + 1]
        : 1.0;
    }
    outInfo->Set(vtkDataObject::ORIGIN(), origin, 3);
    outInfo->Set(vtkDataObject::SPACING(), spacing, 3);
  }
  outInfo->Set(CAN_PRODUCE_SUB_EXTENT(), 1);
  return 1;
}

//------------------------------------------------------------------------------
int vtkLRSplineResampleToImage::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  vtkSplineVizPieces::RequestWholeInput(inputVector[0]->GetInformationObject(0));
  return 1;
}

//------------------------------------------------------------------------------
int vtkLRSplineResampleToImage::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkDataObject* source = vtkDataObject::GetData(inputVector[0], 0);
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkImageData* output = vtkImageData::GetData(outInfo);
  if (!source)
  {
    vtkErrorMacro(<< "no spline input: connect the output of vtkLRSplineReader");
    return 0;
  }
  for (int d = 0; d < 3; ++d)
  {
    if (this->SamplingDimensions[d] < 1)
    {
      vtkErrorMacro(<< "SamplingDimensions must be at least 1 in every direction");
      return 0;
    }
  }
  std::string error, fieldName;
  if (!vtkLRSplineField::SelectedFieldName(this, 0, 0, source, fieldName, &error))
  {
    vtkErrorMacro(<< error);
    return 0;
  }
  if (!vtkLRSplineField::BuildCached(this->Field, this->FieldKey, source, fieldName.c_str(),
        this->LocatorType, this->ForestResolution, false, &error))
  {
    vtkErrorMacro(<< "cannot evaluate the spline: " << error);
    return 0;
  }
  double bounds[6];
  if (this->UseInputBounds)
  {
    this->Field->GetBounds(bounds);
  }
  else
  {
    std::copy(this->SamplingBounds, this->SamplingBounds + 6, bounds);
    for (int d = 0; d < 3; ++d)
    {
      if (!(bounds[2 * d + 1] >= bounds[2 * d]))
      {
        vtkErrorMacro(<< "SamplingBounds must have max >= min in every direction");
        return 0;
      }
    }
  }
  const int* dims = this->SamplingDimensions;
  double origin[3], spacing[3];
  for (int d = 0; d < 3; ++d)
  {
    origin[d] = bounds[2 * d];
    spacing[d] = dims[d] > 1 ? (bounds[2 * d + 1] - bounds[2 * d]) / (dims[d] - 1) : 1.0;
    if (!(spacing[d] > 0))
    {
      spacing[d] = 1.0;
    }
  }
  int extent[6];
  if (outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT()))
  {
    // Within the whole extent of the current dimensions: a request left from
    // earlier, larger dimensions (e.g. a refused one) must not be used.
    outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(), extent);
    for (int d = 0; d < 3; ++d)
    {
      extent[2 * d] = std::max(extent[2 * d], 0);
      extent[2 * d + 1] = std::min(extent[2 * d + 1], dims[d] - 1);
    }
  }
  else
  {
    for (int d = 0; d < 3; ++d)
    {
      extent[2 * d] = 0;
      extent[2 * d + 1] = dims[d] - 1;
    }
  }
  // Absurd requests (e.g. 100000^3 samples) are refused before anything is
  // allocated: VTK's failed allocation would end the process.
  double samples = 1.0;
  for (int d = 0; d < 3; ++d)
  {
    samples *= std::max(0, extent[2 * d + 1] - extent[2 * d] + 1);
  }
  const int nc = this->Field->GetNumberOfComponents();
  const double bytesPerSample = 8.0 * nc * (this->ComputeGradient ? 4 : 1) + 1;
  if (!vtkSplineVizProgress::CheckOutputSize(
        samples, bytesPerSample, "the resampled image (SamplingDimensions)", &error))
  {
    vtkErrorMacro(<< error);
    return 0;
  }
  output->SetExtent(extent);
  output->SetOrigin(origin);
  output->SetSpacing(spacing);
  const vtkIdType n = output->GetNumberOfPoints();
  const int nx = extent[1] - extent[0] + 1, ny = extent[3] - extent[2] + 1;
  auto coordinate = [&](int d, int i)
  {
    // the last sample sits exactly on the upper bound
    return (dims[d] > 1 && i == dims[d] - 1) ? bounds[2 * d + 1] : origin[d] + i * spacing[d];
  };
  const vtkIdType inside = this->Field->EvaluateIntoPointData(
    output->GetPointData(), n,
    [&](vtkIdType id, double x[3])
    {
      const int i = extent[0] + static_cast<int>(id % nx);
      const int j = extent[2] + static_cast<int>((id / nx) % ny);
      const int k = extent[4] + static_cast<int>(id / (static_cast<vtkIdType>(nx) * ny));
      x[0] = coordinate(0, i);
      x[1] = coordinate(1, j);
      x[2] = coordinate(2, k);
    },
    this->ComputeGradient ? "Gradient" : nullptr, "vtkValidPointMask", this);
  if (inside < 0)
  {
    output->Initialize(); // aborted: a clean, empty output
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkLRSplineResampleToImage::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SamplingDimensions: " << this->SamplingDimensions[0] << " "
     << this->SamplingDimensions[1] << " " << this->SamplingDimensions[2] << "\n";
  os << indent << "UseInputBounds: " << this->UseInputBounds << "\n";
  os << indent << "SamplingBounds: " << this->SamplingBounds[0] << " " << this->SamplingBounds[1]
     << " " << this->SamplingBounds[2] << " " << this->SamplingBounds[3] << " "
     << this->SamplingBounds[4] << " " << this->SamplingBounds[5] << "\n";
  const char* field = vtkSplineVizInputArrays::GetName(this, 0);
  os << indent
     << "Field (input array 0): " << (field && *field ? field : "(active vectors, else scalars)")
     << "\n";
  os << indent << "ComputeGradient: " << this->ComputeGradient << "\n";
  os << indent << "LocatorType: " << this->LocatorType << "\n";
  os << indent << "ForestResolution: " << this->ForestResolution << "\n";
}
