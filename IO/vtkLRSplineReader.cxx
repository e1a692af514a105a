#include "vtkLRSplineReader.h"

#include "vtkLRSplineBezierVolume.h"
#include "vtkLRSplineParser.h"
#include "vtkLRSplinePatch.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkCompositeDataSet.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkHigherOrderHexahedron.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStringArray.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>
#include <unordered_map>

vtkStandardNewMacro(vtkLRSplineReader);

namespace
{
struct KeyHash
{
  std::size_t operator()(const std::array<double, 3>& k) const
  {
    std::size_t h = 0;
    for (double v : k)
    {
      std::uint64_t bits;
      const double z = v == 0.0 ? 0.0 : v; // -0 == 0
      std::memcpy(&bits, &z, sizeof(bits));
      h ^= std::hash<std::uint64_t>()(bits) + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
    }
    return h;
  }
};

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

template <typename ArrayT, typename T>
void AddFieldArray(vtkFieldData* fd, const char* name, std::initializer_list<T> values)
{
  vtkNew<ArrayT> a;
  a->SetName(name);
  a->SetNumberOfComponents(static_cast<int>(values.size()));
  a->SetNumberOfTuples(1);
  int c = 0;
  for (T v : values)
  {
    a->SetTypedComponent(0, c++, v);
  }
  fd->AddArray(a);
}
}

//------------------------------------------------------------------------------
vtkLRSplineReader::vtkLRSplineReader()
{
  this->SetNumberOfInputPorts(0);
  this->SetFieldName("Field");
}

vtkLRSplineReader::~vtkLRSplineReader()
{
  this->SetFileName(nullptr);
  this->SetFieldName(nullptr);
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
    return head.find("LRSPLINE VOLUME") != std::string::npos ? 1 : 0;
  }
  if (format == vtkLRSplineParser::G2)
  {
    std::istringstream s(head);
    int cls = 0;
    s >> cls;
    return cls == 700 ? 1 : 0;
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

  const std::string formatName =
    format == vtkLRSplineParser::G2 ? "GoTools g2 class 700" : "LRSplines text";
  const char* fieldName = (this->FieldName && *this->FieldName) ? this->FieldName : "Field";
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
    const vtkIdType first = ne * piece / numPieces;
    const vtkIdType last = ne * (piece + 1) / numPieces;
    vtkLRSplineBezierVolume volume;
    std::string warning;
    if (!patch.ExtractBezier(volume, &error, &warning, first, last))
    {
      output->Initialize();
      return fail(where + "patch " + std::to_string(p) + ": " + error);
    }
    if (!warning.empty())
    {
      vtkWarningMacro(<< "\"" << inputName << "\": patch " << p << ": " << warning);
    }
    if (this->GeometryMode && patch.Dimension != 2 && patch.Dimension != 3)
    {
      output->Initialize();
      return fail(where + "patch " + std::to_string(p) +
        ": geometry mode needs coefficients "
        "with 2 or 3 components, this patch has " +
        std::to_string(patch.Dimension));
    }
    volume.ElevateToAtLeastLinear();
    const int* deg = volume.Degree;
    const int nc = volume.NumberOfComponents;
    const int per = volume.GetCoefficientsPerElement();
    const vtkIdType count = volume.GetNumberOfElements();

    double maxAbs = 0.0;
    for (double c : volume.Coefficients)
    {
      maxAbs = std::max(maxAbs, std::abs(c));
    }
    const double tol = 1e-10 * std::max(maxAbs, 1e-300);

    vtkNew<vtkUnstructuredGrid> grid;
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    points->Allocate(count * per);
    vtkNew<vtkDoubleArray> field;
    field->SetName(fieldName);
    field->SetNumberOfComponents(nc);
    field->Allocate(count * per * nc);
    vtkNew<vtkDoubleArray> paramCoords;
    paramCoords->SetName("LRParameterCoordinates");
    paramCoords->SetNumberOfComponents(3);

    vtkNew<vtkIdTypeArray> offsets, connectivity;
    offsets->SetNumberOfTuples(count + 1);
    connectivity->SetNumberOfTuples(count * per);
    std::unordered_map<std::array<double, 3>, std::vector<vtkIdType>, KeyHash> merge;
    if (this->MergePoints)
    {
      merge.reserve(static_cast<std::size_t>(count * per));
    }
    for (vtkIdType e = 0; e < count; ++e)
    {
      const double* box = volume.GetBox(e);
      const double* coeffs = volume.GetElementCoefficients(e);
      offsets->SetValue(e, e * per);
      for (int k = 0; k <= deg[2]; ++k)
      {
        for (int j = 0; j <= deg[1]; ++j)
        {
          for (int i = 0; i <= deg[0]; ++i)
          {
            const int ijk[3] = { i, j, k };
            std::array<double, 3> u;
            for (int d = 0; d < 3; ++d)
            {
              u[d] = ijk[d] == 0
                ? box[d]
                : (ijk[d] == deg[d]
                      ? box[d + 3]
                      : box[d] + (box[d + 3] - box[d]) * (static_cast<double>(ijk[d]) / deg[d]));
            }
            const double* c = coeffs + ((k * (deg[1] + 1) + j) * (deg[0] + 1) + i) * nc;
            vtkIdType id = -1;
            if (this->MergePoints)
            {
              auto it = merge.find(u);
              if (it != merge.end())
              {
                for (vtkIdType candidate : it->second)
                {
                  bool same = true;
                  for (int comp = 0; comp < nc && same; ++comp)
                  {
                    same = std::abs(field->GetValue(candidate * nc + comp) - c[comp]) <= tol;
                  }
                  if (same)
                  {
                    id = candidate;
                    break;
                  }
                }
              }
            }
            if (id < 0)
            {
              double x[3];
              if (this->GeometryMode)
              {
                x[0] = c[0];
                x[1] = c[1];
                x[2] = nc >= 3 ? c[2] : 0.0;
                paramCoords->InsertNextTuple(u.data());
              }
              else
              {
                for (int d = 0; d < 3; ++d)
                {
                  x[d] = offset[d] + scale[d] * u[d];
                }
              }
              id = points->InsertNextPoint(x);
              for (int comp = 0; comp < nc; ++comp)
              {
                field->InsertNextValue(c[comp]);
              }
              if (this->MergePoints)
              {
                merge[u].push_back(id);
              }
            }
            connectivity->SetValue(
              e * per + vtkHigherOrderHexahedron::PointIndexFromIJK(i, j, k, deg), id);
          }
        }
      }
    }
    offsets->SetValue(count, count * per);
    std::unordered_map<std::array<double, 3>, std::vector<vtkIdType>, KeyHash>().swap(merge);
    points->Squeeze();
    field->Squeeze();
    grid->SetPoints(points);
    vtkNew<vtkCellArray> cells;
    cells->SetData(offsets, connectivity);
    grid->SetCells(VTK_BEZIER_HEXAHEDRON, cells);

    vtkPointData* pd = grid->GetPointData();
    pd->AddArray(field);
    if (nc == 3)
    {
      pd->SetActiveVectors(fieldName);
    }
    else if (nc == 1)
    {
      pd->SetActiveScalars(fieldName);
    }
    if (this->GeometryMode)
    {
      pd->AddArray(paramCoords);
    }

    vtkCellData* cd = grid->GetCellData();
    vtkNew<vtkIntArray> degrees;
    degrees->SetName("HigherOrderDegrees");
    degrees->SetNumberOfComponents(3);
    degrees->SetNumberOfTuples(count);
    vtkNew<vtkDoubleArray> boxes;
    boxes->SetName("LRParameterBox");
    boxes->SetNumberOfComponents(6);
    boxes->SetNumberOfTuples(count);
    vtkNew<vtkIdTypeArray> elementIds;
    elementIds->SetName("LRElementId");
    elementIds->SetNumberOfTuples(count);
    vtkNew<vtkDoubleArray> minSide;
    minSide->SetName("LRElementMinSide");
    minSide->SetNumberOfTuples(count);
    for (vtkIdType e = 0; e < count; ++e)
    {
      const double* box = volume.GetBox(e);
      for (int d = 0; d < 3; ++d)
      {
        degrees->SetTypedComponent(e, d, deg[d]);
      }
      boxes->SetTypedTuple(e, box);
      elementIds->SetValue(e, first + e);
      double m = VTK_DOUBLE_MAX;
      for (int d = 0; d < 3; ++d)
      {
        m = std::min(m, (box[d + 3] - box[d]) * (this->GeometryMode ? 1.0 : scale[d]));
      }
      minSide->SetValue(e, m);
    }
    cd->AddArray(degrees);
    cd->SetHigherOrderDegrees(degrees);
    cd->AddArray(boxes);
    cd->AddArray(elementIds);
    cd->AddArray(minSide);

    // Metadata of the whole patch.
    double dom[6];
    patch.GetDomain(dom);
    int levels[3];
    for (int d = 0; d < 3; ++d)
    {
      double smallest = VTK_DOUBLE_MAX, largest = 0.0;
      for (vtkIdType e = 0; e < ne; ++e)
      {
        const double side = patch.ElementBoxes[6 * e + d + 3] - patch.ElementBoxes[6 * e + d];
        smallest = std::min(smallest, side);
        largest = std::max(largest, side);
      }
      levels[d] = static_cast<int>(std::lround(std::log2(largest / smallest)));
    }
    vtkFieldData* fd = grid->GetFieldData();
    AddFieldArray<vtkIntArray, int>(fd, "LRPatchIndex", { static_cast<int>(p) });
    AddFieldArray<vtkIntArray, int>(
      fd, "LRDegrees", { patch.Order[0] - 1, patch.Order[1] - 1, patch.Order[2] - 1 });
    AddFieldArray<vtkIdTypeArray, vtkIdType>(
      fd, "LRNumberOfBasisFunctions", { patch.GetNumberOfBasisFunctions() });
    AddFieldArray<vtkIdTypeArray, vtkIdType>(fd, "LRNumberOfElements", { ne });
    AddFieldArray<vtkIdTypeArray, vtkIdType>(
      fd, "LRNumberOfMeshRectangles", { static_cast<vtkIdType>(patch.MeshMultiplicities.size()) });
    AddFieldArray<vtkIntArray, int>(fd, "LRRefinementLevels", { levels[0], levels[1], levels[2] });
    AddFieldArray<vtkDoubleArray, double>(
      fd, "LRParameterDomain", { dom[0], dom[1], dom[2], dom[3], dom[4], dom[5] });
    AddFieldArray<vtkIntArray, int>(fd, "LRMode", { this->GeometryMode ? 1 : 0 });
    if (!this->GeometryMode)
    {
      AddFieldArray<vtkDoubleArray, double>(fd, "LRPhysicalTransform",
        { scale[0], scale[1], scale[2], offset[0], offset[1], offset[2] });
    }
    vtkNew<vtkStringArray> source;
    source->SetName("LRSourceFormat");
    source->InsertNextValue(formatName);
    fd->AddArray(source);

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
  os << indent << "FieldName: " << (this->FieldName ? this->FieldName : "(none)") << "\n";
  os << indent << "MergePoints: " << this->MergePoints << "\n";
}
