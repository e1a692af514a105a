// SPDX-License-Identifier: BSD-3-Clause
#include "vtkSuperquadricGlyphRepresentation.h"

#include "vtkAlgorithmOutput.h"
#include "vtkCompositeDataDisplayAttributes.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataSet.h"
#include "vtkDemandDrivenPipeline.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPVLODActor.h"
#include "vtkPVRenderView.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkSuperquadricGlyphMapper.h"

#include <cstring>

namespace
{
//------------------------------------------------------------------------------
// Replaces vtkPVGeometryFilter in the representation's pipeline: every point
// of the input (not only the surface) with its point data, as vtkPolyData
// without cells; composite inputs give a flat vtkMultiBlockDataSet of those.
class vtkSuperquadricGlyphPointsFilter : public vtkAlgorithm
{
public:
  static vtkSuperquadricGlyphPointsFilter* New();
  vtkTypeMacro(vtkSuperquadricGlyphPointsFilter, vtkAlgorithm);

  vtkTypeBool ProcessRequest(
    vtkInformation* request, vtkInformationVector** in, vtkInformationVector* out) override
  {
    if (request->Has(vtkDemandDrivenPipeline::REQUEST_DATA_OBJECT()))
    {
      vtkDataObject* input = vtkDataObject::GetData(in[0], 0);
      vtkInformation* outInfo = out->GetInformationObject(0);
      vtkDataObject* output = outInfo->Get(vtkDataObject::DATA_OBJECT());
      // composite inputs keep their type and structure (so that ParaView's
      // block selectors for colors and visibility find their blocks)
      auto* composite = vtkCompositeDataSet::SafeDownCast(input);
      const bool ok = composite ? (output && output->IsA(input->GetClassName()))
                                : vtkPolyData::SafeDownCast(output) != nullptr;
      if (!ok)
      {
        vtkSmartPointer<vtkDataObject> created;
        if (composite)
        {
          created.TakeReference(composite->NewInstance());
        }
        else
        {
          created = vtkSmartPointer<vtkPolyData>::New();
        }
        outInfo->Set(vtkDataObject::DATA_OBJECT(), created);
      }
      return 1;
    }
    if (request->Has(vtkDemandDrivenPipeline::REQUEST_DATA()))
    {
      vtkDataObject* input = vtkDataObject::GetData(in[0], 0);
      vtkDataObject* output = vtkDataObject::GetData(out, 0);
      if (auto* ds = vtkDataSet::SafeDownCast(input))
      {
        Convert(ds, vtkPolyData::SafeDownCast(output));
        return 1;
      }
      auto* cd = vtkCompositeDataSet::SafeDownCast(input);
      auto* out = vtkCompositeDataSet::SafeDownCast(output);
      if (cd && out)
      {
        out->CopyStructure(cd);
        vtkSmartPointer<vtkCompositeDataIterator> it;
        it.TakeReference(cd->NewIterator());
        it->SkipEmptyNodesOn();
        for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
        {
          if (auto* leaf = vtkDataSet::SafeDownCast(it->GetCurrentDataObject()))
          {
            vtkNew<vtkPolyData> pd;
            Convert(leaf, pd);
            out->SetDataSet(it, pd);
          }
        }
        return 1;
      }
      // no or another input: empty output
      if (output)
      {
        output->Initialize();
      }
      return 1;
    }
    return this->Superclass::ProcessRequest(request, in, out);
  }

protected:
  vtkSuperquadricGlyphPointsFilter()
  {
    this->SetNumberOfInputPorts(1);
    this->SetNumberOfOutputPorts(1);
  }

  int FillInputPortInformation(int, vtkInformation* info) override
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataObject");
    return 1;
  }
  int FillOutputPortInformation(int, vtkInformation* info) override
  {
    info->Set(vtkDataObject::DATA_TYPE_NAME(), "vtkDataObject");
    return 1;
  }

  static void Convert(vtkDataSet* input, vtkPolyData* output)
  {
    if (!output)
    {
      return;
    }
    output->Initialize();
    if (auto* ps = vtkPointSet::SafeDownCast(input))
    {
      output->SetPoints(ps->GetPoints()); // shared, not copied
    }
    else
    {
      const vtkIdType n = input->GetNumberOfPoints();
      vtkNew<vtkPoints> points;
      points->SetDataTypeToDouble();
      points->SetNumberOfPoints(n);
      double* p = static_cast<double*>(points->GetVoidPointer(0));
      if (n > 0)
      {
        input->GetPoint(0, p); // builds any internal cache before the threads run
      }
      vtkSMPTools::For(0, n,
        [&](vtkIdType begin, vtkIdType end)
        {
          for (vtkIdType i = begin; i < end; ++i)
          {
            input->GetPoint(i, p + 3 * i);
          }
        });
      output->SetPoints(points);
    }
    output->GetPointData()->ShallowCopy(input->GetPointData());
    output->GetFieldData()->ShallowCopy(input->GetFieldData());
  }

private:
  vtkSuperquadricGlyphPointsFilter(const vtkSuperquadricGlyphPointsFilter&) = delete;
  void operator=(const vtkSuperquadricGlyphPointsFilter&) = delete;
};
vtkStandardNewMacro(vtkSuperquadricGlyphPointsFilter);

const char* ArrayOrNull(const char* name)
{
  return (name && name[0] != '\0' && std::strcmp(name, "None") != 0) ? name : nullptr;
}
}

vtkStandardNewMacro(vtkSuperquadricGlyphRepresentation);

//------------------------------------------------------------------------------
vtkSuperquadricGlyphRepresentation::vtkSuperquadricGlyphRepresentation()
{
  this->GeometryFilter->Delete();
  this->GeometryFilter = vtkSuperquadricGlyphPointsFilter::New();
  this->Mapper->Delete();
  this->LODMapper->Delete();
  this->Mapper = vtkSuperquadricGlyphMapper::New();
  this->LODMapper = vtkSuperquadricGlyphMapper::New();
  this->SuppressLOD = true;
  // The superclass wires the geometry filter, its pipeline and the actor to
  // the mappers here.
  this->SetupDefaults();
}

//------------------------------------------------------------------------------
vtkSuperquadricGlyphRepresentation::~vtkSuperquadricGlyphRepresentation() = default;

//------------------------------------------------------------------------------
vtkSuperquadricGlyphMapper* vtkSuperquadricGlyphRepresentation::GetGlyphMapper()
{
  return vtkSuperquadricGlyphMapper::SafeDownCast(this->Mapper);
}

//------------------------------------------------------------------------------
int vtkSuperquadricGlyphRepresentation::ProcessViewRequest(
  vtkInformationRequestKey* request_type, vtkInformation* inInfo, vtkInformation* outInfo)
{
  // Block colors, opacities and visibilities: the superclass gives them only
  // to a vtkCompositePolyDataMapper2; decide before it resets its flags.
  vtkDataObject* delivered = nullptr;
  bool updateBlocks = false;
  if (request_type == vtkPVView::REQUEST_RENDER())
  {
    delivered = vtkPVView::GetDeliveredPiece(inInfo, this);
    updateBlocks =
      delivered && (this->BlockAttributeTime < delivered->GetMTime() || this->BlockAttrChanged);
  }
  if (!this->Superclass::ProcessViewRequest(request_type, inInfo, outInfo))
  {
    return 0;
  }
  if (updateBlocks)
  {
    vtkSuperquadricGlyphMapper* mapper = this->GetGlyphMapper();
    if (!mapper->GetCompositeDataDisplayAttributes())
    {
      vtkNew<vtkCompositeDataDisplayAttributes> attributes;
      mapper->SetCompositeDataDisplayAttributes(attributes);
    }
    this->PopulateBlockAttributes(mapper->GetCompositeDataDisplayAttributes(), delivered);
    mapper->GetCompositeDataDisplayAttributes()->Modified();
  }
  if (request_type == vtkPVView::REQUEST_UPDATE())
  {
    // Report the glyphs' bounds (points padded by the largest glyph) rather
    // than the points' bounds (the mapper's input is left alone: it is the
    // delivered data, set in REQUEST_RENDER).
    vtkDataObject* data = this->MultiBlockMaker->GetOutputDataObject(0);
    vtkSuperquadricGlyphMapper* mapper = this->GetGlyphMapper();
    double bounds[6];
    if (data && mapper && mapper->ComputeGlyphBounds(data, bounds))
    {
      vtkNew<vtkMatrix4x4> matrix;
      this->Actor->GetMatrix(matrix);
      vtkPVRenderView::SetGeometryBounds(inInfo, this, bounds, matrix);
    }
  }
  return 1;
}

//------------------------------------------------------------------------------
#define SV_FORWARD(method, type)                                                                   \
  void vtkSuperquadricGlyphRepresentation::method(type value)                                      \
  {                                                                                                \
    static_cast<vtkSuperquadricGlyphMapper*>(this->Mapper)->method(value);                         \
    static_cast<vtkSuperquadricGlyphMapper*>(this->LODMapper)->method(value);                      \
  }

SV_FORWARD(SetTensorLayout, int)
SV_FORWARD(SetGamma, double)
SV_FORWARD(SetMinimumRoundness, double)
SV_FORWARD(SetMaximumScale, double)
SV_FORWARD(SetMinimumThickness, double)
SV_FORWARD(SetAnisotropyThreshold, double)
SV_FORWARD(SetMinimumEigenvalue, double)
SV_FORWARD(SetNegativeEigenvaluePolicy, int)
SV_FORWARD(SetGlyphColorMode, int)
SV_FORWARD(SetMaximumIterations, int)
SV_FORWARD(SetCulling, int)
#undef SV_FORWARD

//------------------------------------------------------------------------------
void vtkSuperquadricGlyphRepresentation::SetGlyphScaleFactor(double value)
{
  static_cast<vtkSuperquadricGlyphMapper*>(this->Mapper)->SetScaleFactor(value);
  static_cast<vtkSuperquadricGlyphMapper*>(this->LODMapper)->SetScaleFactor(value);
}

//------------------------------------------------------------------------------
void vtkSuperquadricGlyphRepresentation::SetGlyphScaleMode(int mode)
{
  static_cast<vtkSuperquadricGlyphMapper*>(this->Mapper)->SetScaleMode(mode);
  static_cast<vtkSuperquadricGlyphMapper*>(this->LODMapper)->SetScaleMode(mode);
}

//------------------------------------------------------------------------------
void vtkSuperquadricGlyphRepresentation::SetTensorArray(const char* name)
{
  static_cast<vtkSuperquadricGlyphMapper*>(this->Mapper)->SetTensorArray(ArrayOrNull(name));
  static_cast<vtkSuperquadricGlyphMapper*>(this->LODMapper)->SetTensorArray(ArrayOrNull(name));
}

//------------------------------------------------------------------------------
void vtkSuperquadricGlyphRepresentation::SetMaskArray(const char* name)
{
  static_cast<vtkSuperquadricGlyphMapper*>(this->Mapper)->SetMaskArray(ArrayOrNull(name));
  static_cast<vtkSuperquadricGlyphMapper*>(this->LODMapper)->SetMaskArray(ArrayOrNull(name));
}

//------------------------------------------------------------------------------
void vtkSuperquadricGlyphRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
