// SPDX-License-Identifier: BSD-3-Clause
// The deprecated names of the array and field properties (kept for one
// release) still work, so that they cannot break silently while they exist:
// for every renamed property a value set through the old name is read through
// the new one and the reverse, the old setter marks the object modified and
// nullptr clears the value through either name. The filters' old ArrayName /
// MaskArrayName select input array 0 (1 for the mask) on the right port as
// point data, and the LR-spline filters evaluate the field the old name
// selects (a name no patch has is reported). Remove this test with the
// deprecated names.
#include "vtkLRSplineFitter.h"
#include "vtkLRSplineImageFitter.h"
#include "vtkLRSplineProbeFilter.h"
#include "vtkLRSplineReader.h"
#include "vtkLRSplineResampleToImage.h"
#include "vtkLRSplineStreamTracer.h"
#include "vtkLRSplineVolumeMapper.h"
#include "vtkRayCastTubeMapper.h"
#include "vtkSplineTubeCore.h"
#include "vtkStylizedLineMapper.h"
#include "vtkSuperquadricGlyphMapper.h"
#include "vtkTensorLineTracer.h"
#include "vtkTessellatedTubeMapper.h"

#include "SplineVizTestUtilities.h"

#include "vtkCommand.h"
#include "vtkDataObject.h"
#include "vtkDataSet.h"
#include "vtkExecutive.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkTestErrorObserver.h"

#include <functional>
#include <string>

namespace
{
bool Same(const char* a, const char* b)
{
  return a && b && std::string(a) == b;
}

using Setter = std::function<void(const char*)>;
using Getter = std::function<const char*()>;

// Old name -> new name and back, Modified() from the old setter, nullptr
// clears through the old setter.
void CheckAlias(SplineVizTestStatus& status, const std::string& what, vtkObject* object,
  const Setter& setNew, const Getter& getNew, const Setter& setOld, const Getter& getOld)
{
  vtkMTimeType before = object->GetMTime();
  setOld("SetByOldName");
  SV_CHECK_MSG(status, Same(getNew(), "SetByOldName") && Same(getOld(), "SetByOldName"),
    what << ": set through the old name, the new name reads " << (getNew() ? getNew() : "(null)"));
  SV_CHECK_MSG(status, object->GetMTime() > before, what << ": the old setter does not Modified()");
  setNew("SetByNewName");
  SV_CHECK_MSG(status, Same(getOld(), "SetByNewName"),
    what << ": set through the new name, the old name reads " << (getOld() ? getOld() : "(null)"));
  before = object->GetMTime();
  setOld(nullptr);
  SV_CHECK_MSG(status, !getNew() && !getOld() && object->GetMTime() > before,
    what << ": nullptr through the old name does not clear the value");
}

// A string property renamed from Old to New (vtkSetStringMacro / vtkGetStringMacro).
#define SV_CHECK_STRING_ALIAS(status, object, New, Old)                                            \
  CheckAlias(                                                                                      \
    status, std::string((object)->GetClassName()) + "::" #Old " -> " #New, object,                 \
    [&](const char* v) { (object)->Set##New(v); },                                                 \
    [&]() -> const char* { return (object)->Get##New(); },                                         \
    [&](const char* v) { (object)->Set##Old(v); },                                                 \
    [&]() -> const char* { return (object)->Get##Old(); })

// The name selected as input array `idx` (what SetInputArrayToProcess sets).
const char* Selected(vtkAlgorithm* algorithm, int idx)
{
  vtkInformation* info = algorithm->GetInputArrayInformation(idx);
  return info->Has(vtkDataObject::FIELD_NAME()) ? info->Get(vtkDataObject::FIELD_NAME()) : nullptr;
}

// A filter's old ArrayName (or MaskArrayName) is input array `idx`, point
// data of input port `port`.
template <class Filter>
void CheckInputArrayAlias(SplineVizTestStatus& status, const std::string& what, Filter* filter,
  int idx, int port, const Setter& setOld, const Getter& getOld)
{
  CheckAlias(
    status, what, filter,
    [&](const char* v)
    { filter->SetInputArrayToProcess(idx, port, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, v); },
    [&]() { return Selected(filter, idx); }, setOld, getOld);
  setOld("Field");
  vtkInformation* info = filter->GetInputArrayInformation(idx);
  SV_CHECK_MSG(status,
    info->Get(vtkAlgorithm::INPUT_PORT()) == port &&
      info->Get(vtkAlgorithm::INPUT_CONNECTION()) == 0 &&
      info->Get(vtkDataObject::FIELD_ASSOCIATION()) == vtkDataObject::FIELD_ASSOCIATION_POINTS,
    what << ": the old setter selects input array " << idx << " elsewhere than point data of port "
         << port);
  setOld(nullptr);
}

// Run `algorithm` and return whether it reported an error containing `words`
// (any error when `words` is empty) - false when it ran without error.
bool Fails(vtkAlgorithm* algorithm, const std::string& words)
{
  vtkNew<vtkTest::ErrorObserver> observer;
  const unsigned long a = algorithm->AddObserver(vtkCommand::ErrorEvent, observer);
  const unsigned long e = algorithm->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, observer);
  algorithm->Modified();
  algorithm->Update();
  algorithm->RemoveObserver(a);
  algorithm->GetExecutive()->RemoveObserver(e);
  return observer->GetError() &&
    (words.empty() || observer->GetErrorMessage().find(words) != std::string::npos);
}
// `filter` with the field "velocity" selected through `setOld` outputs it;
// a name no patch has is reported.
void CheckEvaluates(
  SplineVizTestStatus& status, const std::string& what, vtkAlgorithm* filter, const Setter& setOld)
{
  setOld("velocity");
  const bool failed = Fails(filter, "");
  vtkDataSet* output = vtkDataSet::SafeDownCast(filter->GetOutputDataObject(0));
  SV_CHECK_MSG(status, !failed && output && output->GetPointData()->GetArray("velocity"),
    what << ": the named field is not evaluated");
  setOld("NoSuchField");
  SV_CHECK_MSG(status, Fails(filter, "NoSuchField"), what << ": a missing field is not reported");
}
}

int TestSplineVizDeprecatedNames(int, char*[])
{
  SplineVizTestStatus status;

  //--- The producers' output field: FieldName -> OutputFieldName.
  {
    vtkNew<vtkLRSplineReader> reader;
    SV_CHECK_STRING_ALIAS(status, reader.Get(), OutputFieldName, FieldName);
    vtkNew<vtkLRSplineImageFitter> imageFitter;
    SV_CHECK_STRING_ALIAS(status, imageFitter.Get(), OutputFieldName, FieldName);
    vtkNew<vtkLRSplineFitter> fitter;
    SV_CHECK_STRING_ALIAS(status, fitter.Get(), OutputFieldName, FieldName);
  }

  //--- The consumers' field: ArrayName -> input array 0 (the spline on port 1
  // of the probe, port 0 of the others).
  {
    vtkNew<vtkLRSplineProbeFilter> probe;
    CheckInputArrayAlias(
      status, "vtkLRSplineProbeFilter::ArrayName -> input array 0", probe.Get(), 0, 1,
      [&](const char* v) { probe->SetArrayName(v); }, [&]() { return probe->GetArrayName(); });
    vtkNew<vtkLRSplineResampleToImage> resample;
    CheckInputArrayAlias(
      status, "vtkLRSplineResampleToImage::ArrayName -> input array 0", resample.Get(), 0, 0,
      [&](const char* v) { resample->SetArrayName(v); },
      [&]() { return resample->GetArrayName(); });
    vtkNew<vtkLRSplineStreamTracer> tracer;
    CheckInputArrayAlias(
      status, "vtkLRSplineStreamTracer::ArrayName -> input array 0", tracer.Get(), 0, 0,
      [&](const char* v) { tracer->SetArrayName(v); }, [&]() { return tracer->GetArrayName(); });
    vtkNew<vtkTensorLineTracer> tensorLines;
    CheckInputArrayAlias(
      status, "vtkTensorLineTracer::MaskArrayName -> input array 1", tensorLines.Get(), 1, 0,
      [&](const char* v) { tensorLines->SetMaskArrayName(v); },
      [&]() { return tensorLines->GetMaskArrayName(); });
    // The tensors stay input array 0.
    vtkInformation* tensors = tensorLines->GetInputArrayInformation(0);
    SV_CHECK(status,
      !tensors->Has(vtkDataObject::FIELD_NAME()) &&
        tensors->Has(vtkDataObject::FIELD_ATTRIBUTE_TYPE()));
    vtkNew<vtkLRSplineVolumeMapper> volume;
    SV_CHECK_STRING_ALIAS(status, volume.Get(), FieldArray, FieldArrayName);
  }

  //--- The line renderers' arrays: ...ArrayName -> ...Array.
  {
    vtkNew<vtkSplineTubeCore> core;
    SV_CHECK_STRING_ALIAS(status, core.Get(), RadiusArray, RadiusArrayName);
    SV_CHECK_STRING_ALIAS(status, core.Get(), NodeScalarArray, NodeScalarArrayName);
    SV_CHECK_STRING_ALIAS(status, core.Get(), CellIdArray, CellIdArrayName);
    vtkNew<vtkRayCastTubeMapper> rayCast;
    SV_CHECK_STRING_ALIAS(status, rayCast.Get(), CellIdArray, CellIdArrayName);
    vtkNew<vtkTessellatedTubeMapper> tessellated;
    SV_CHECK_STRING_ALIAS(status, tessellated.Get(), CellIdArray, CellIdArrayName);
    vtkNew<vtkStylizedLineMapper> stylized;
    SV_CHECK_STRING_ALIAS(status, stylized.Get(), CellIdArray, CellIdArrayName);
    vtkNew<vtkSuperquadricGlyphMapper> glyphs;
    SV_CHECK_STRING_ALIAS(status, glyphs.Get(), TensorArray, TensorArrayName);
    SV_CHECK_STRING_ALIAS(status, glyphs.Get(), MaskArray, MaskArrayName);
  }

  //--- The old names reach the execution: the reader writes the field under
  // FieldName, and the filters evaluate the field their ArrayName names.
  {
    const std::string file = std::string(SPLINEVIZ_EXTERNAL_DATA_DIR) + "/cube-3patch-refined.lr";
    vtkNew<vtkLRSplineReader> reader;
    reader->SetFileName(file.c_str());
    reader->SetFieldName("velocity");
    reader->Update();
    vtkDataSet* patch = vtkDataSet::SafeDownCast(reader->GetOutput()->GetBlock(0));
    SV_CHECK_MSG(status, patch && patch->GetPointData()->GetArray("velocity"),
      "vtkLRSplineReader::SetFieldName does not name the output field");

    vtkNew<vtkPolyData> points;
    vtkNew<vtkPoints> pts;
    pts->InsertNextPoint(0.3, 0.4, 0.5);
    pts->InsertNextPoint(0.6, 0.5, 0.4);
    points->SetPoints(pts);

    vtkNew<vtkLRSplineProbeFilter> probe;
    probe->SetInputData(points);
    probe->SetSourceConnection(reader->GetOutputPort());
    CheckEvaluates(status, "vtkLRSplineProbeFilter::SetArrayName", probe,
      [&](const char* v) { probe->SetArrayName(v); });
    vtkNew<vtkLRSplineResampleToImage> resample;
    resample->SetInputConnection(reader->GetOutputPort());
    resample->SetSamplingDimensions(3, 3, 3);
    CheckEvaluates(status, "vtkLRSplineResampleToImage::SetArrayName", resample,
      [&](const char* v) { resample->SetArrayName(v); });
    vtkNew<vtkLRSplineStreamTracer> tracer;
    tracer->SetInputConnection(reader->GetOutputPort());
    tracer->SetSourceData(points);
    tracer->SetMaximumNumberOfSteps(10);
    CheckEvaluates(status, "vtkLRSplineStreamTracer::SetArrayName", tracer,
      [&](const char* v) { tracer->SetArrayName(v); });
  }
  return status.Result();
}
