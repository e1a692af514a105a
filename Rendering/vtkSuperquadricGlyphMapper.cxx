#include "vtkSuperquadricGlyphMapper.h"

#include "vtkSplineVizTensorMath.h"
#include "vtkSuperquadricGlyphPreparer.h"

#include "vtkAlgorithmOutput.h"
#include "vtkCallbackCommand.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataSet.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkHardwareSelector.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkMath.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOutputWindow.h"
#include "vtkOpenGLActor.h"
#include "vtkOpenGLCamera.h"
#include "vtkOpenGLHelper.h"
#include "vtkOpenGLIndexBufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLRenderer.h"
#include "vtkOpenGLVertexBufferObject.h"
#include "vtkOpenGLVertexBufferObjectGroup.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkScalarsToColors.h"
#include "vtkShaderProgram.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include "vtkSuperquadricGlyphFS.h"
#include "vtkSuperquadricGlyphGS.h"
#include "vtkSuperquadricGlyphShared.h"
#include "vtkSuperquadricGlyphVS.h"
#include "vtkTensorMathShared.h"

#include "vtk_glew.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkSuperquadricGlyphMapper);

namespace
{
namespace TM = vtkSplineVizTensorMath;
}

//------------------------------------------------------------------------------
class vtkSuperquadricGlyphMapper::Internals
{
public:
  vtkNew<vtkSuperquadricGlyphPreparer> Preparer;
  vtkNew<vtkCallbackCommand> Forwarder;
  std::string ColorKey;
  bool HaveColors = false;
  bool ShaderHaveColors = false;
  const void* UploadedTensors = nullptr;
  vtkMTimeType UploadedTensorsTime = 0;
  int BytesPerGlyph = 0;
  bool TooLarge = false; // the glyphs did not fit on the GPU: draw nothing
};

namespace
{
// Re-emits the preparer's (and its executive's) errors and warnings from the
// mapper: to the mapper's observers if it has any, else to the output window.
void ForwardEvent(vtkObject*, unsigned long event, void* clientData, void* callData)
{
  auto* mapper = static_cast<vtkSuperquadricGlyphMapper*>(clientData);
  if (mapper->HasObserver(event))
  {
    mapper->InvokeEvent(event, callData);
  }
  else if (event == vtkCommand::ErrorEvent)
  {
    vtkOutputWindowDisplayErrorText(static_cast<const char*>(callData));
  }
  else
  {
    vtkOutputWindowDisplayWarningText(static_cast<const char*>(callData));
  }
}
}

//------------------------------------------------------------------------------
vtkSuperquadricGlyphMapper::vtkSuperquadricGlyphMapper()
  : Internal(new Internals)
{
  // colors are per glyph, never interpolated through a texture
  this->InterpolateScalarsBeforeMapping = 0;
  this->Internal->Forwarder->SetClientData(this);
  this->Internal->Forwarder->SetCallback(ForwardEvent);
  this->Internal->Preparer->AddObserver(vtkCommand::ErrorEvent, this->Internal->Forwarder);
  this->Internal->Preparer->AddObserver(vtkCommand::WarningEvent, this->Internal->Forwarder);
  this->Internal->Preparer->GetExecutive()->AddObserver(
    vtkCommand::ErrorEvent, this->Internal->Forwarder);
}

//------------------------------------------------------------------------------
vtkSuperquadricGlyphMapper::~vtkSuperquadricGlyphMapper()
{
  this->SetTensorArrayName(nullptr);
  this->SetMaskArrayName(nullptr);
}

//------------------------------------------------------------------------------
void vtkSuperquadricGlyphMapper::SetInputData(vtkDataObject* input)
{
  this->SetInputDataObject(0, input);
}

//------------------------------------------------------------------------------
void vtkSuperquadricGlyphMapper::SetInputConnection(int port, vtkAlgorithmOutput* input)
{
  vtkSuperquadricGlyphPreparer* prep = this->Internal->Preparer;
  if (input && input->GetProducer() == prep)
  {
    this->Superclass::SetInputConnection(port, input);
    return;
  }
  prep->SetInputConnection(0, input);
  this->Superclass::SetInputConnection(port, input ? prep->GetOutputPort() : nullptr);
}

//------------------------------------------------------------------------------
void vtkSuperquadricGlyphMapper::SetInputDataObject(int port, vtkDataObject* input)
{
  vtkSuperquadricGlyphPreparer* prep = this->Internal->Preparer;
  prep->SetInputDataObject(0, input);
  this->Superclass::SetInputConnection(port, input ? prep->GetOutputPort() : nullptr);
}

//------------------------------------------------------------------------------
void vtkSuperquadricGlyphMapper::UpdatePreparer()
{
  vtkSuperquadricGlyphPreparer* prep = this->Internal->Preparer;
  prep->SetTensorArrayName(this->TensorArrayName);
  prep->SetTensorLayout(this->TensorLayout);
  prep->SetMaskArrayName(this->MaskArrayName);
  prep->SetColorArraySelection(this->ScalarVisibility != 0, this->ScalarMode, this->ArrayAccessMode,
    this->ArrayId, this->ArrayName);
}

//------------------------------------------------------------------------------
double* vtkSuperquadricGlyphMapper::GetBounds()
{
  this->UpdatePreparer();
  return this->Superclass::GetBounds();
}

//------------------------------------------------------------------------------
void vtkSuperquadricGlyphMapper::ComputeBounds()
{
  vtkMath::UninitializeBounds(this->Bounds);
  vtkPolyData* glyphs = this->GetInput();
  if (!glyphs || glyphs->GetNumberOfPoints() == 0)
  {
    return;
  }
  glyphs->GetBounds(this->Bounds);
  vtkDataArray* stats = glyphs->GetFieldData()->GetArray("sqStatistics");
  const double pad = this->GetGlyphPadding(stats ? stats->GetTuple1(0) : 0.0);
  for (int c = 0; c < 3; ++c)
  {
    this->Bounds[2 * c] -= pad;
    this->Bounds[2 * c + 1] += pad;
  }
}

//------------------------------------------------------------------------------
double vtkSuperquadricGlyphMapper::GetGlyphPadding(double maxTensorNorm)
{
  // Half extent of a glyph's box along any axis a: sum_i s_i |e_i . a| <=
  // |s| (Cauchy-Schwarz, the e_i . a are a unit vector's coordinates), with
  // |s| <= scale |T|_F (|l| <= Frobenius norm), at most sqrt(3) times the
  // largest semi-axis, and the thickness floor adding at most a factor
  // sqrt(1 + 3 m^2).
  const double floorFactor = std::sqrt(1.0 + 3.0 * this->MinimumThickness * this->MinimumThickness);
  double pad = this->ScaleFactor * maxTensorNorm;
  if (this->ScaleMode == SCALE_NORMALIZED)
  {
    pad = std::sqrt(3.0) * this->ScaleFactor;
  }
  else if (this->ScaleMode == SCALE_CLAMPED)
  {
    pad = std::min(pad, std::sqrt(3.0) * this->MaximumScale);
  }
  return pad * floorFactor;
}

//------------------------------------------------------------------------------
bool vtkSuperquadricGlyphMapper::ComputeGlyphBounds(vtkDataObject* data, double bounds[6])
{
  vtkMath::UninitializeBounds(bounds);
  const std::vector<vtkDataSet*> leaves = vtkCompositeDataSet::GetDataSets(data);
  double maxNorm = 0.0;
  bool any = false;
  for (vtkDataSet* leaf : leaves)
  {
    vtkPointData* pd = leaf->GetPointData();
    vtkDataArray* tensors =
      this->TensorArrayName ? pd->GetArray(this->TensorArrayName) : pd->GetTensors();
    const int layout =
      tensors ? TM::ResolveLayout(this->TensorLayout, tensors->GetNumberOfComponents()) : -1;
    if (layout < 0 || leaf->GetNumberOfPoints() == 0)
    {
      continue;
    }
    vtkSMPThreadLocal<double> localMax;
    vtkSMPTools::For(0, tensors->GetNumberOfTuples(),
      [&](vtkIdType begin, vtkIdType end)
      {
        double& m = localMax.Local();
        for (vtkIdType i = begin; i < end; ++i)
        {
          double t[6];
          if (TM::ReadSymmetric(tensors, i, layout, t))
          {
            m = std::max(m,
              std::sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2] +
                2.0 * (t[3] * t[3] + t[4] * t[4] + t[5] * t[5])));
          }
        }
      });
    for (double m : localMax)
    {
      maxNorm = std::max(maxNorm, m);
    }
    double b[6];
    leaf->GetBounds(b);
    for (int c = 0; c < 3; ++c)
    {
      bounds[2 * c] = any ? std::min(bounds[2 * c], b[2 * c]) : b[2 * c];
      bounds[2 * c + 1] = any ? std::max(bounds[2 * c + 1], b[2 * c + 1]) : b[2 * c + 1];
    }
    any = true;
  }
  if (!any)
  {
    return false;
  }
  const double pad = this->GetGlyphPadding(maxNorm);
  for (int c = 0; c < 3; ++c)
  {
    bounds[2 * c] -= pad;
    bounds[2 * c + 1] += pad;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkSuperquadricGlyphMapper::RenderPiece(vtkRenderer* ren, vtkActor* actor)
{
  this->UpdatePreparer();
  this->Superclass::RenderPiece(ren, actor);
  vtkPolyData* glyphs = this->GetInput();
  vtkDataArray* stats = glyphs ? glyphs->GetFieldData()->GetArray("sqStatistics") : nullptr;
  this->NumberOfGlyphs = glyphs ? glyphs->GetNumberOfPoints() : 0;
  this->NumberOfInvalidTensors = stats ? static_cast<vtkIdType>(stats->GetTuple1(1)) : 0;
  this->NumberOfZeroTensors = stats ? static_cast<vtkIdType>(stats->GetTuple1(2)) : 0;
  this->NumberOfMaskedPoints = stats ? static_cast<vtkIdType>(stats->GetTuple1(3)) : 0;
}

//------------------------------------------------------------------------------
void vtkSuperquadricGlyphMapper::RenderPieceDraw(vtkRenderer* ren, vtkActor* actor)
{
  const int numVerts = this->VBOs->GetNumberOfTuples("vertexMC");
  if (numVerts > 0 && !this->Internal->TooLarge)
  {
    this->UpdateShaders(this->Primitives[PrimitiveTris], ren, actor);
    glDrawArrays(GL_POINTS, 0, static_cast<GLsizei>(numVerts));
  }
}

//------------------------------------------------------------------------------
std::string vtkSuperquadricGlyphMapper::GetColorKey()
{
  // What the per-glyph colors depend on (not every change of the mapper,
  // e.g. of Gamma, must recolor).
  vtkPolyData* glyphs = this->CurrentInput;
  vtkDataArray* scalars = glyphs ? glyphs->GetPointData()->GetScalars() : nullptr;
  std::ostringstream key;
  key << this->ScalarVisibility << "|" << this->ColorMode << "|" << this->ArrayComponent << "|"
      << this->UseLookupTableScalarRange << "|" << this->ScalarRange[0] << "|"
      << this->ScalarRange[1] << "|" << static_cast<void*>(this->LookupTable) << "|"
      << (this->LookupTable ? this->LookupTable->GetMTime() : 0) << "|"
      << static_cast<void*>(scalars) << "|" << (scalars ? scalars->GetMTime() : 0);
  return key.str();
}

//------------------------------------------------------------------------------
bool vtkSuperquadricGlyphMapper::GetNeedToRebuildBufferObjects(vtkRenderer*, vtkActor*)
{
  vtkPolyData* glyphs = this->CurrentInput;
  if (!glyphs)
  {
    return false;
  }
  vtkDataArray* diag = glyphs->GetPointData()->GetArray("sqTensorDiag");
  const Internals& in = *this->Internal;
  return in.UploadedTensors != diag || (diag && in.UploadedTensorsTime < diag->GetMTime()) ||
    in.ColorKey != this->GetColorKey();
}

//------------------------------------------------------------------------------
void vtkSuperquadricGlyphMapper::BuildBufferObjects(vtkRenderer* ren, vtkActor*)
{
  Internals& in = *this->Internal;
  vtkPolyData* poly = this->CurrentInput;
  vtkPointData* pd = poly->GetPointData();
  vtkDataArray* diag = pd->GetArray("sqTensorDiag");
  vtkDataArray* off = pd->GetArray("sqTensorOff");
  if (!diag || !off || !poly->GetPoints())
  {
    return;
  }

  // Per-glyph colors through the lookup table (point scalars only).
  in.HaveColors = false;
  if (pd->GetScalars() && this->ScalarVisibility)
  {
    // one color per glyph: never through a texture (ParaView turns
    // InterpolateScalarsBeforeMapping on)
    const int savedMode = this->ScalarMode;
    const vtkTypeBool savedInterpolate = this->InterpolateScalarsBeforeMapping;
    this->ScalarMode = VTK_SCALAR_MODE_USE_POINT_DATA;
    this->InterpolateScalarsBeforeMapping = 0;
    this->MapScalars(poly, 1.0);
    this->ScalarMode = savedMode;
    this->InterpolateScalarsBeforeMapping = savedInterpolate;
    in.HaveColors = this->Colors != nullptr &&
      this->Colors->GetNumberOfTuples() == poly->GetNumberOfPoints() &&
      this->Colors->GetNumberOfComponents() == 4;
  }

  // Hostile sizes: one draw call of GLsizei points, and the limit of
  // SPLINEVIZ_GPU_BUFFER_LIMIT (elements per GPU buffer, to test this path);
  // a buffer the driver cannot allocate (GL_OUT_OF_MEMORY) is caught below.
  // Either way nothing is drawn and the data is not retried until it changes.
  const vtkIdType numGlyphs = poly->GetNumberOfPoints();
  vtkIdType limit = VTK_INT_MAX;
  if (const char* forced = std::getenv("SPLINEVIZ_GPU_BUFFER_LIMIT"))
  {
    limit = std::min<vtkIdType>(limit, std::strtoll(forced, nullptr, 10));
  }
  in.TooLarge = numGlyphs > limit;
  if (in.TooLarge)
  {
    vtkErrorMacro(<< numGlyphs << " glyphs are more than one GPU draw can hold (at most " << limit
                  << (std::getenv("SPLINEVIZ_GPU_BUFFER_LIMIT")
                         ? ", lowered by SPLINEVIZ_GPU_BUFFER_LIMIT"
                         : "")
                  << "): nothing is drawn");
  }
  else
  {
    for (int i = 0; i < 64 && glGetError() != GL_NO_ERROR; ++i)
    {
      // errors of earlier calls are not this upload's
    }
    this->VBOs->CacheDataArray("vertexMC", poly->GetPoints()->GetData(), ren, VTK_FLOAT);
    this->VBOs->CacheDataArray("tensorDiagMC", diag, ren, VTK_FLOAT);
    this->VBOs->CacheDataArray("tensorOffMC", off, ren, VTK_FLOAT);
    this->VBOs->CacheDataArray(
      "glyphScalarColor", in.HaveColors ? this->Colors : nullptr, ren, VTK_UNSIGNED_CHAR);
    this->VBOs->BuildAllVBOs(ren);
    if (glGetError() == GL_OUT_OF_MEMORY)
    {
      in.TooLarge = true;
      vtkErrorMacro(<< "the GPU could not allocate the buffers of " << numGlyphs
                    << " glyphs (GL_OUT_OF_MEMORY): nothing is drawn");
    }
  }
  if (in.UploadedTensors != diag || in.UploadedTensorsTime < diag->GetMTime())
  {
    ++this->UploadCount;
    in.UploadedTensors = diag;
    in.UploadedTensorsTime = diag->GetMTime();
  }
  in.BytesPerGlyph = 0;
  for (const char* name : { "vertexMC", "tensorDiagMC", "tensorOffMC", "glyphScalarColor" })
  {
    vtkOpenGLVertexBufferObject* vbo = this->VBOs->GetVBO(name);
    if (vbo && vbo->GetNumberOfTuples() > 0)
    {
      in.BytesPerGlyph += static_cast<int>(vbo->GetStride());
    }
  }

  for (int i = PrimitiveStart; i < PrimitiveEnd; ++i)
  {
    this->Primitives[i].IBO->IndexCount = 0;
  }
  // Not drawn with it, but makes the superclass bind the attributes.
  this->Primitives[PrimitiveTris].IBO->IndexCount = static_cast<size_t>(poly->GetNumberOfPoints());
  in.ColorKey = this->GetColorKey();
  this->VBOBuildTime.Modified();
}

//------------------------------------------------------------------------------
int vtkSuperquadricGlyphMapper::GetGPUBytesPerGlyph()
{
  return this->Internal->BytesPerGlyph;
}

//------------------------------------------------------------------------------
vtkIdType vtkSuperquadricGlyphMapper::GetInputPointId(vtkIdType glyphIndex)
{
  vtkPolyData* glyphs = this->GetInput();
  vtkIdTypeArray* ids = glyphs
    ? vtkArrayDownCast<vtkIdTypeArray>(glyphs->GetPointData()->GetArray("sqPointIds"))
    : nullptr;
  return (ids && glyphIndex >= 0 && glyphIndex < ids->GetNumberOfTuples())
    ? ids->GetValue(glyphIndex)
    : -1;
}

//------------------------------------------------------------------------------
void vtkSuperquadricGlyphMapper::GetShaderTemplate(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer*, vtkActor*)
{
  shaders[vtkShader::Vertex]->SetSource(vtkSuperquadricGlyphVS);
  shaders[vtkShader::Geometry]->SetSource(vtkSuperquadricGlyphGS);
  shaders[vtkShader::Fragment]->SetSource(vtkSuperquadricGlyphFS);
}

//------------------------------------------------------------------------------
bool vtkSuperquadricGlyphMapper::GetNeedToRebuildShaders(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* actor)
{
  const bool colorsChanged = this->Internal->ShaderHaveColors != this->Internal->HaveColors;
  return this->Superclass::GetNeedToRebuildShaders(cellBO, ren, actor) || colorsChanged;
}

//------------------------------------------------------------------------------
void vtkSuperquadricGlyphMapper::ReplaceShaderValues(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* actor)
{
  std::string VSSource = shaders[vtkShader::Vertex]->GetSource();
  std::string GSSource = shaders[vtkShader::Geometry]->GetSource();
  std::string FSSource = shaders[vtkShader::Fragment]->GetSource();

  // The math shared with the CPU code.
  vtkShaderProgram::Substitute(VSSource, "//SQ::TensorMath::Dec", vtkTensorMathShared);
  vtkShaderProgram::Substitute(VSSource, "//SQ::GlyphMath::Dec", vtkSuperquadricGlyphShared);
  vtkShaderProgram::Substitute(FSSource, "//SQ::GlyphMath::Dec", vtkSuperquadricGlyphShared);

  // Scalar colors.
  this->Internal->ShaderHaveColors = this->Internal->HaveColors;
  if (this->Internal->HaveColors)
  {
    vtkShaderProgram::Substitute(VSSource, "//SQ::ScalarColor::Dec", "in vec4 glyphScalarColor;");
    vtkShaderProgram::Substitute(VSSource, "//SQ::ScalarColor::Impl",
      "  if (sqColorMode == 1)\n"
      "  {\n"
      "    glyphColorVSOut = glyphScalarColor;\n"
      "  }\n");
  }

  // Colors and material: as vtkOpenGLPolyDataMapper's, with the per-glyph
  // color (alpha >= 0) replacing the actor's color.
  std::string colorDec = "uniform float ambientIntensity;\n"
                         "uniform float diffuseIntensity;\n"
                         "uniform float opacityUniform;\n"
                         "uniform vec3 ambientColorUniform;\n"
                         "uniform vec3 diffuseColorUniform;\n";
  std::string colorImpl = "  vec3 ambientColor = ambientIntensity * ambientColorUniform;\n"
                          "  vec3 diffuseColor = diffuseIntensity * diffuseColorUniform;\n"
                          "  float opacity = opacityUniform;\n"
                          "  if (glyphColorGSOutput.a >= 0.0)\n"
                          "  {\n"
                          "    ambientColor = ambientIntensity * glyphColorGSOutput.rgb;\n"
                          "    diffuseColor = diffuseIntensity * glyphColorGSOutput.rgb;\n"
                          "    opacity = opacityUniform * glyphColorGSOutput.a;\n"
                          "  }\n";
  if (this->PrimitiveInfo[this->LastBoundBO].LastLightComplexity)
  {
    colorDec += "uniform float specularIntensity;\n"
                "uniform vec3 specularColorUniform;\n"
                "uniform float specularPowerUniform;\n";
    colorImpl += "  vec3 specularColor = specularIntensity * specularColorUniform;\n"
                 "  float specularPower = specularPowerUniform;\n";
  }
  vtkShaderProgram::Substitute(FSSource, "//VTK::Color::Dec", colorDec);
  vtkShaderProgram::Substitute(FSSource, "//VTK::Color::Impl", colorImpl);

  // Picking: point ids are glyph indices (mapped to input ids in
  // ProcessSelectorPixelBuffers); other passes write the mapper index.
  const int pass = this->LastSelectionState;
  if (pass >= vtkHardwareSelector::MIN_KNOWN_PASS)
  {
    if (pass == vtkHardwareSelector::POINT_ID_LOW24 ||
      pass == vtkHardwareSelector::POINT_ID_HIGH24 || pass == vtkHardwareSelector::CELL_ID_LOW24 ||
      pass == vtkHardwareSelector::CELL_ID_HIGH24)
    {
      const bool high =
        pass == vtkHardwareSelector::POINT_ID_HIGH24 || pass == vtkHardwareSelector::CELL_ID_HIGH24;
      vtkShaderProgram::Substitute(VSSource, "//VTK::Picking::Dec", "out int glyphIdVSOut;");
      vtkShaderProgram::Substitute(
        VSSource, "//VTK::Picking::Impl", "  glyphIdVSOut = gl_VertexID;");
      vtkShaderProgram::Substitute(
        GSSource, "//VTK::Picking::Dec", "in int glyphIdVSOut[];\nflat out int glyphIdGSOutput;");
      vtkShaderProgram::Substitute(
        GSSource, "//VTK::Picking::Impl", "  glyphIdGSOutput = glyphIdVSOut[0];");
      vtkShaderProgram::Substitute(FSSource, "//VTK::Picking::Dec", "flat in int glyphIdGSOutput;");
      vtkShaderProgram::Substitute(FSSource, "//VTK::Picking::Impl",
        high ? "  int idx = (glyphIdGSOutput >> 24) & 0xff;\n"
               "  gl_FragData[0] = vec4(float(idx) / 255.0, 0.0, 0.0, 1.0);\n"
             : "  int idx = glyphIdGSOutput;\n"
               "  gl_FragData[0] = vec4(float(idx % 256) / 255.0, float((idx / 256) % 256) / "
               "255.0, float((idx / 65536) % 256) / 255.0, 1.0);\n");
    }
    else
    {
      vtkShaderProgram::Substitute(FSSource, "//VTK::Picking::Dec", "uniform vec3 mapperIndex;");
      vtkShaderProgram::Substitute(
        FSSource, "//VTK::Picking::Impl", "  gl_FragData[0] = vec4(mapperIndex, 1.0);\n");
    }
  }
  // leave no VTK picking tags for the superclass
  vtkShaderProgram::Substitute(VSSource, "//VTK::Picking::Dec", "");
  vtkShaderProgram::Substitute(VSSource, "//VTK::Picking::Impl", "");
  vtkShaderProgram::Substitute(GSSource, "//VTK::Picking::Dec", "");
  vtkShaderProgram::Substitute(GSSource, "//VTK::Picking::Impl", "");
  vtkShaderProgram::Substitute(FSSource, "//VTK::Picking::Dec", "");
  vtkShaderProgram::Substitute(FSSource, "//VTK::Picking::Impl", "");

  shaders[vtkShader::Vertex]->SetSource(VSSource);
  shaders[vtkShader::Geometry]->SetSource(GSSource);
  shaders[vtkShader::Fragment]->SetSource(FSSource);

  // Lights, render passes (e.g. depth peeling), custom uniforms.
  this->Superclass::ReplaceShaderValues(shaders, ren, actor);
}

//------------------------------------------------------------------------------
void vtkSuperquadricGlyphMapper::SetMapperShaderParameters(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* actor)
{
  this->Superclass::SetMapperShaderParameters(cellBO, ren, actor);
  vtkShaderProgram* p = cellBO.Program;
  p->SetUniformf("sqGamma", static_cast<float>(this->Gamma));
  p->SetUniformf("sqScaleFactor", static_cast<float>(this->ScaleFactor));
  p->SetUniformf("sqMaximumScale", static_cast<float>(this->MaximumScale));
  p->SetUniformf("sqMinimumThickness", static_cast<float>(this->MinimumThickness));
  p->SetUniformf("sqMinimumRoundness", static_cast<float>(this->MinimumRoundness));
  p->SetUniformf("sqAnisotropyThreshold", static_cast<float>(this->AnisotropyThreshold));
  p->SetUniformf("sqMinimumEigenvalue",
    static_cast<float>(std::max(this->MinimumEigenvalue, -static_cast<double>(VTK_FLOAT_MAX))));
  p->SetUniformi("sqScaleMode", this->ScaleMode);
  p->SetUniformi("sqSignPolicy", this->NegativeEigenvaluePolicy);
  p->SetUniformi("sqColorMode", this->GlyphColorMode);
  p->SetUniformi("sqMaximumIterations", this->MaximumIterations);
}

//------------------------------------------------------------------------------
void vtkSuperquadricGlyphMapper::SetCameraShaderParameters(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* actor)
{
  vtkShaderProgram* program = cellBO.Program;
  vtkOpenGLCamera* cam = static_cast<vtkOpenGLCamera*>(ren->GetActiveCamera());
  vtkMatrix4x4* wcdc;
  vtkMatrix4x4* wcvc;
  vtkMatrix3x3* norms;
  vtkMatrix4x4* vcdc;
  cam->GetKeyMatrices(ren, wcvc, norms, vcdc, wcdc);
  program->SetUniformMatrix("VCDCMatrix", vcdc);

  // The key matrices are transposed for OpenGL; so is their product.
  vtkMatrix4x4* mcvc = wcvc;
  if (!actor->GetIsIdentity())
  {
    vtkMatrix4x4* mcwc;
    vtkMatrix3x3* anorms;
    static_cast<vtkOpenGLActor*>(actor)->GetKeyMatrices(mcwc, anorms);
    vtkMatrix4x4::Multiply4x4(mcwc, wcvc, this->TempMatrix4);
    mcvc = this->TempMatrix4;
  }
  program->SetUniformMatrix("MCVCMatrix", mcvc);
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      this->TempMatrix3->SetElement(i, j, mcvc->GetElement(i, j));
    }
  }
  program->SetUniformMatrix("glyphMCVC", this->TempMatrix3);
  program->SetUniformi("cameraParallel", cam->GetParallelProjection());
  program->SetUniformf("nearPlaneVC", static_cast<float>(-cam->GetClippingRange()[0]));
}

//------------------------------------------------------------------------------
void vtkSuperquadricGlyphMapper::ProcessSelectorPixelBuffers(
  vtkHardwareSelector* sel, std::vector<unsigned int>& pixeloffsets, vtkProp*)
{
  const int pass = sel->GetCurrentPass();
  const bool pointPass =
    pass == vtkHardwareSelector::POINT_ID_LOW24 || pass == vtkHardwareSelector::POINT_ID_HIGH24;
  const bool cellPass =
    pass == vtkHardwareSelector::CELL_ID_LOW24 || pass == vtkHardwareSelector::CELL_ID_HIGH24;
  if (!this->PopulateSelectionSettings || !(pointPass || cellPass))
  {
    return;
  }
  const int lowPass =
    pointPass ? vtkHardwareSelector::POINT_ID_LOW24 : vtkHardwareSelector::CELL_ID_LOW24;
  const int highPass =
    pointPass ? vtkHardwareSelector::POINT_ID_HIGH24 : vtkHardwareSelector::CELL_ID_HIGH24;
  unsigned char* rawLow = sel->GetRawPixelBuffer(lowPass);
  unsigned char* rawHigh = sel->GetRawPixelBuffer(highPass);
  unsigned char* out = sel->GetPixelBuffer(pass);
  if (!rawLow || !out)
  {
    return;
  }
  const bool high = pass == highPass;
  if (high && !rawHigh)
  {
    return;
  }
  for (unsigned int pos : pixeloffsets)
  {
    vtkIdType glyph = 0;
    if (rawHigh)
    {
      glyph = rawHigh[pos];
    }
    glyph = (glyph << 8) | rawLow[pos + 2];
    glyph = (glyph << 8) | rawLow[pos + 1];
    glyph = (glyph << 8) | rawLow[pos];
    const vtkIdType id = std::max<vtkIdType>(this->GetInputPointId(glyph), 0);
    if (high)
    {
      out[pos] = static_cast<unsigned char>((id >> 24) & 0xff);
      out[pos + 1] = static_cast<unsigned char>((id >> 32) & 0xff);
      out[pos + 2] = static_cast<unsigned char>((id >> 40) & 0xff);
    }
    else
    {
      out[pos] = static_cast<unsigned char>(id & 0xff);
      out[pos + 1] = static_cast<unsigned char>((id >> 8) & 0xff);
      out[pos + 2] = static_cast<unsigned char>((id >> 16) & 0xff);
    }
  }
}

//------------------------------------------------------------------------------
void vtkSuperquadricGlyphMapper::ReleaseGraphicsResources(vtkWindow* win)
{
  this->Superclass::ReleaseGraphicsResources(win);
  this->Internal->UploadedTensors = nullptr;
  this->Internal->UploadedTensorsTime = 0;
  this->Internal->ColorKey.clear();
}

//------------------------------------------------------------------------------
void vtkSuperquadricGlyphMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "TensorArrayName: " << (this->TensorArrayName ? this->TensorArrayName : "(none)")
     << "\n";
  os << indent << "TensorLayout: " << this->TensorLayout << " ("
     << TM::GetLayoutName(this->TensorLayout) << ")\n";
  os << indent << "MaskArrayName: " << (this->MaskArrayName ? this->MaskArrayName : "(none)")
     << "\n";
  os << indent << "Gamma: " << this->Gamma << "\n";
  os << indent << "MinimumRoundness: " << this->MinimumRoundness << "\n";
  os << indent << "ScaleFactor: " << this->ScaleFactor << "\n";
  os << indent << "ScaleMode: " << this->ScaleMode << "\n";
  os << indent << "MaximumScale: " << this->MaximumScale << "\n";
  os << indent << "MinimumThickness: " << this->MinimumThickness << "\n";
  os << indent << "AnisotropyThreshold: " << this->AnisotropyThreshold << "\n";
  os << indent << "MinimumEigenvalue: " << this->MinimumEigenvalue << "\n";
  os << indent << "NegativeEigenvaluePolicy: " << this->NegativeEigenvaluePolicy << "\n";
  os << indent << "GlyphColorMode: " << this->GlyphColorMode << "\n";
  os << indent << "MaximumIterations: " << this->MaximumIterations << "\n";
  os << indent << "NumberOfGlyphs: " << this->NumberOfGlyphs << "\n";
  os << indent << "NumberOfInvalidTensors: " << this->NumberOfInvalidTensors << "\n";
  os << indent << "NumberOfZeroTensors: " << this->NumberOfZeroTensors << "\n";
  os << indent << "NumberOfMaskedPoints: " << this->NumberOfMaskedPoints << "\n";
  os << indent << "UploadCount: " << this->UploadCount << "\n";
}
