// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLRSplineReader.h"

#include "vtkLRSplineBezierGrid.h"
#include "vtkLRSplineParser.h"
#include "vtkLRSplinePatch.h"

#include "vtkCompositeDataSet.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkObjectFactory.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

vtkStandardNewMacro(vtkLRSplineReader);

namespace
{
bool ReadWholeFile(const char* name, std::string& text, std::string& error)
{
  std::ifstream in(name, std::ios::in | std::ios::binary);
  if (!in)
  {
    error = "cannot open the file (it does not exist or is not readable)";
    return false;
  }
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  if (size < 0)
  {
    error = "cannot read the file (is it a directory?)";
    return false;
  }
  if (size > (std::streamoff(1) << 32))
  {
    error = "the file is larger than 4 GiB";
    return false;
  }
  in.seekg(0, std::ios::beg);
  text.resize(static_cast<std::size_t>(size));
  if (size > 0 && !in.read(&text[0], size))
  {
    error = "cannot read the file";
    return false;
  }
  return true;
}

}

//------------------------------------------------------------------------------
vtkLRSplineReader::vtkLRSplineReader()
{
  this->SetNumberOfInputPorts(0);
  this->SetOutputFieldName("Field");
}

vtkLRSplineReader::~vtkLRSplineReader()
{
  this->SetFileName(nullptr);
  this->SetOutputFieldName(nullptr);
}

//------------------------------------------------------------------------------
void vtkLRSplineReader::SetInputString(const std::string& text)
{
  if (text != this->InputString)
  {
    this->InputString = text;
    this->Modified();
  }
}

void vtkLRSplineReader::SetInputString(const char* text, std::size_t length)
{
  this->SetInputString(text ? std::string(text, length) : std::string());
}

//------------------------------------------------------------------------------
int vtkLRSplineReader::CanReadFile(const char* fileName)
{
  if (!fileName)
  {
    return 0;
  }
  std::ifstream in(fileName, std::ios::in | std::ios::binary);
  if (!in)
  {
    return 0;
  }
  std::string head(4096, '\0');
  in.read(&head[0], static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  const int format = vtkLRSplineParser::DetectFormat(head);
  if (format == vtkLRSplineParser::LRSPLINES)
  {
    return head.find("LRSPLINE VOLUME") != std::string::npos ||
        head.find("LRSPLINE SURFACE") != std::string::npos
      ? 1
      : 0;
  }
  if (format == vtkLRSplineParser::G2)
  {
    std::istringstream s(head);
    int cls = 0;
    s >> cls;
    return (cls == 200 || cls == 700 || cls == 293 || cls == 793) ? 1 : 0;
  }
  return 0;
}

//------------------------------------------------------------------------------
int vtkLRSplineReader::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  outInfo->Set(CAN_HANDLE_PIECE_REQUEST(), 1);
  return 1;
}

//------------------------------------------------------------------------------
int vtkLRSplineReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkMultiBlockDataSet* output = vtkMultiBlockDataSet::GetData(outInfo);
  this->LastError.clear();
  auto fail = [this](const std::string& msg)
  {
    this->LastError = msg;
    vtkErrorMacro(<< msg);
    return 0;
  };
  std::string text, error;
  const char* inputName = this->ReadFromInputString ? "the input string" : this->FileName;
  if (this->ReadFromInputString)
  {
    text = this->InputString;
  }
  else if (!this->FileName || !*this->FileName)
  {
    return fail("no file name was given");
  }
  const std::string where = std::string("cannot read \"") + inputName + "\": ";
  if (!this->ReadFromInputString && !ReadWholeFile(this->FileName, text, error))
  {
    return fail(where + error);
  }
  int format = this->FileFormat;
  if (format == AUTOMATIC)
  {
    format = vtkLRSplineParser::DetectFormat(text);
  }
  std::vector<vtkLRSplinePatch> patches;
  if (!vtkLRSplineParser::Parse(text, format, patches, &error))
  {
    return fail(where + error);
  }
  std::string().swap(text);
  for (std::size_t p = 0; p < patches.size(); ++p)
  {
    bool inferred = false;
    if (!patches[p].ApplyRationalMode(
          this->RationalMode, this->GeometryMode != 0, &inferred, &error))
    {
      return fail(where + "patch " + std::to_string(p) + ": " + error);
    }
    if (inferred)
    {
      vtkWarningMacro(<< "\"" << inputName << "\": patch " << p << " has " << patches[p].Dimension
                      << " components for " << patches[p].ParametricDimension
                      << " parametric directions: read as rational (the last component is the "
                         "weight); set RationalMode to Polynomial if it is not");
    }
    if (!patches[p].Validate(&error))
    {
      return fail(where + "patch " + std::to_string(p) + ": " + error);
    }
  }

  int piece = 0, numPieces = 1;
  if (outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER()))
  {
    piece = outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER());
    numPieces = outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES());
    numPieces = std::max(1, numPieces);
    piece = std::max(0, std::min(piece, numPieces - 1));
  }

  // One affine parameter -> physical map for all patches (field mode).
  double all[6] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX,
    -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
  for (const vtkLRSplinePatch& patch : patches)
  {
    double dom[6];
    patch.GetDomain(dom);
    for (int d = 0; d < 3; ++d)
    {
      all[d] = std::min(all[d], dom[d]);
      all[d + 3] = std::max(all[d + 3], dom[d + 3]);
    }
  }
  double scale[3] = { 1, 1, 1 }, offset[3] = { 0, 0, 0 };
  const bool mapped = !this->GeometryMode && this->PhysicalBounds[0] <= this->PhysicalBounds[1] &&
    this->PhysicalBounds[2] <= this->PhysicalBounds[3] &&
    this->PhysicalBounds[4] <= this->PhysicalBounds[5];
  if (mapped)
  {
    for (int d = 0; d < 3; ++d)
    {
      const double lo = this->PhysicalBounds[2 * d], hi = this->PhysicalBounds[2 * d + 1];
      if (!(hi > lo) || !std::isfinite(lo) || !std::isfinite(hi))
      {
        return fail("PhysicalBounds must have max > min in every direction");
      }
      scale[d] = (hi - lo) / (all[d + 3] - all[d]);
      offset[d] = lo - scale[d] * all[d];
    }
  }

  const std::string formatName = format == vtkLRSplineParser::G2 ? "GoTools g2" : "LRSplines text";
  vtkLRSplineBezierGrid::Options options;
  options.GeometryMode = this->GeometryMode != 0;
  options.MergePoints = this->MergePoints != 0;
  std::copy(scale, scale + 3, options.Scale);
  std::copy(offset, offset + 3, options.Offset);
  options.FieldName =
    (this->OutputFieldName && *this->OutputFieldName) ? this->OutputFieldName : "Field";
  options.SourceFormat = formatName;
  output->SetNumberOfBlocks(static_cast<unsigned int>(patches.size()));
  this->UpdateProgress(0.1);
  for (std::size_t p = 0; p < patches.size(); ++p)
  {
    // Progress per patch (the Bezier extraction of one patch is parallel);
    // abort between patches gives an empty output.
    if (this->CheckAbort())
    {
      output->Initialize();
      return 1;
    }
    if (p > 0)
    {
      this->UpdateProgress(0.1 + 0.9 * static_cast<double>(p) / patches.size());
    }
    const vtkLRSplinePatch& patch = patches[p];
    const vtkIdType ne = patch.GetNumberOfElements();
    options.PatchIndex = static_cast<int>(p);
    options.FirstElement = ne * piece / numPieces;
    options.LastElement = ne * (piece + 1) / numPieces;
    std::string warning;
    vtkSmartPointer<vtkUnstructuredGrid> grid =
      vtkLRSplineBezierGrid::Build(patch, options, &error, &warning);
    if (!warning.empty())
    {
      vtkWarningMacro(<< "\"" << inputName << "\": patch " << p << ": " << warning);
    }
    if (!grid)
    {
      output->Initialize();
      return fail(where + "patch " + std::to_string(p) + ": " + error);
    }
    output->SetBlock(static_cast<unsigned int>(p), grid);
    output->GetMetaData(static_cast<unsigned int>(p))
      ->Set(vtkCompositeDataSet::NAME(), ("Patch " + std::to_string(p)).c_str());
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkLRSplineReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "ReadFromInputString: " << this->ReadFromInputString << " ("
     << this->InputString.size() << " bytes)\n";
  os << indent << "FileFormat: " << this->FileFormat << "\n";
  os << indent << "GeometryMode: " << this->GeometryMode << "\n";
  os << indent << "PhysicalBounds: " << this->PhysicalBounds[0] << " " << this->PhysicalBounds[1]
     << " " << this->PhysicalBounds[2] << " " << this->PhysicalBounds[3] << " "
     << this->PhysicalBounds[4] << " " << this->PhysicalBounds[5] << "\n";
  os << indent << "OutputFieldName: " << (this->OutputFieldName ? this->OutputFieldName : "(none)")
     << "\n";
  os << indent << "MergePoints: " << this->MergePoints << "\n";
  os << indent << "RationalMode: " << this->RationalMode << "\n";
}
