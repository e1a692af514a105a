// SPDX-License-Identifier: BSD-3-Clause
#include "vtkTessellatedTubeMapper.h"

#include "vtkRayCastTubeMapper.h"
#include "vtkSplineTubeCore.h"
#include "vtkSplineTubeMath.h"
#include "vtkSplineVizGPUBuffer.h"
#include "vtkTessellatedTubeLevels.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkFloatArray.h"
#include "vtkGarbageCollector.h"
#include "vtkIdTypeArray.h"
#include "vtkSMPTools.h"
#include "vtkTypeUInt32Array.h"
#include "vtkUnsignedCharArray.h"
#include "vtkMath.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLCamera.h"
#include "vtkOpenGLHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkShader.h"
#include "vtkShaderProgram.h"

#include "vtkSplineVizShaderPrelude.h"
#include "vtkSplineTubeMathShared.h"
#include "vtkSplineTubeColor.h"
#include "vtkSplineTubeNodes.h"
#include "vtkTessellatedTubeCommon.h"
#include "vtkTessellatedTubeFS.h"
#include "vtkTessellatedTubeTCS.h"
#include "vtkTessellatedTubeTES.h"
#include "vtkTessellatedTubeThinFS.h"
#include "vtkTessellatedTubeThinVS.h"
#include "vtkTessellatedTubeVS.h"

#include <vtk_glew.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <map>
#include <sstream>
#include <vector>

vtkStandardNewMacro(vtkTessellatedTubeMapper);

namespace
{
std::string TubeMathSource()
{
  return vtkSplineVizShaderPrelude::Get() + vtkSplineTubeMathShared;
}

/// What the vertex and tessellation stages share: the tubes buffer, the
/// color spline, the tessellated tubes' common code.
std::string CommonSource()
{
  std::string common = vtkTessellatedTubeCommon;
  vtkShaderProgram::Substitute(common, "//SV::SplineTubeColor::Dec", vtkSplineTubeColor);
  return std::string(vtkSplineTubeNodes) + common;
}

/// The source with line numbers, for error messages.
std::string NumberedSource(const std::string& source)
{
  std::istringstream in(source);
  std::ostringstream out;
  std::string line;
  int number = 1;
  while (std::getline(in, line))
  {
    out << number++ << ": " << line << "\n";
  }
  return out.str();
}

/// Compile one stage; 0 and `error` set on failure.
GLuint CompileStage(GLenum type, const std::string& source, std::string& error)
{
  GLuint shader = glCreateShader(type);
  if (!shader)
  {
    error = "glCreateShader failed";
    return 0;
  }
  const char* text = source.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok)
  {
    GLint length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(static_cast<size_t>(std::max(length, 1)), '\0');
    glGetShaderInfoLog(shader, static_cast<GLsizei>(log.size()), nullptr, log.data());
    error = NumberedSource(source) + "\n" + log.data();
    glDeleteShader(shader);
    return 0;
  }
  return shader;
}
}

//------------------------------------------------------------------------------
vtkTessellatedTubeMapper::vtkTessellatedTubeMapper()
  : Levels(new vtkTessellatedTubeLevels)
  , InstancesBuffer(new vtkSplineVizGPUBuffer)
  , FramesBuffer(new vtkSplineVizGPUBuffer)
{
}

//------------------------------------------------------------------------------
vtkTessellatedTubeMapper::~vtkTessellatedTubeMapper() = default;

//------------------------------------------------------------------------------
void vtkTessellatedTubeMapper::ReportReferences(vtkGarbageCollector* collector)
{
  this->Superclass::ReportReferences(collector);
  vtkGarbageCollectorReport(collector, this->Fallback, "Fallback");
}

//------------------------------------------------------------------------------
bool vtkTessellatedTubeMapper::IsTessellationSupported(vtkRenderWindow* window)
{
  auto* glWindow = vtkOpenGLRenderWindow::SafeDownCast(window);
  if (!glWindow)
  {
    return false;
  }
  glWindow->MakeCurrent();
  if (!glWindow->IsCurrent())
  {
    return false;
  }
  return vtkSplineVizGPUBuffer::ContextSupports(4, "GL_ARB_tessellation_shader") &&
    glPatchParameteri != nullptr;
}

//------------------------------------------------------------------------------
size_t vtkTessellatedTubeMapper::GetGPUMemorySize()
{
  const size_t mesh =
    this->BaseMeshes ? this->Levels->GetMeshIndices().size() * sizeof(unsigned int) : 0;
  return this->GetTubeBuffersSize() + this->FramesBuffer->GetNumberOfBytes() +
    this->InstancesBuffer->GetNumberOfBytes() + mesh;
}

//------------------------------------------------------------------------------
void vtkTessellatedTubeMapper::ReleaseTessellationStages()
{
  if (this->ControlShader)
  {
    glDeleteShader(this->ControlShader);
  }
  if (this->EvaluationShader)
  {
    glDeleteShader(this->EvaluationShader);
  }
  this->ControlShader = 0;
  this->EvaluationShader = 0;
  this->StagesVersion.clear();
}

//------------------------------------------------------------------------------
void vtkTessellatedTubeMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  auto* glWindow = vtkOpenGLRenderWindow::SafeDownCast(window);
  if (glWindow && glWindow->IsCurrent())
  {
    // Our raw GL objects (VTK's own are released below).
    this->ReleaseTessellationStages();
    if (this->PrimitivesQuery)
    {
      glDeleteQueries(1, &this->PrimitivesQuery);
    }
  }
  this->ControlShader = 0;
  this->EvaluationShader = 0;
  this->PrimitivesQuery = 0;
  this->StagesVersion.clear();
  this->StagesFailed = false;
  this->FramesBuffer->ReleaseGraphicsResources(window);
  this->InstancesBuffer->ReleaseGraphicsResources(window);
  this->Levels->Invalidate();
  if (this->BaseMeshes)
  {
    this->BaseMeshes->ReleaseGraphicsResources();
  }
  this->BaseMeshes = nullptr;
  if (this->Fallback)
  {
    this->Fallback->ReleaseGraphicsResources(window);
  }
  this->Superclass::ReleaseGraphicsResources(window);
}

//------------------------------------------------------------------------------
void vtkTessellatedTubeMapper::RenderPiece(vtkRenderer* ren, vtkActor* act)
{
  if (!IsTessellationSupported(ren->GetRenderWindow()))
  {
    if (!this->FallbackWarned)
    {
      vtkWarningMacro(<< "This OpenGL context has no tessellation shaders (OpenGL 4.0 or "
                         "GL_ARB_tessellation_shader); drawing the tubes with "
                         "vtkRayCastTubeMapper instead.");
      this->FallbackWarned = true;
    }
    if (!this->Fallback)
    {
      this->Fallback = vtkSmartPointer<vtkRayCastTubeMapper>::New();
    }
    // Same input, coloring, clipping planes and radii.
    this->Fallback->ShallowCopy(this);
    this->Fallback->SetInputConnection(this->GetInputConnection(0, 0));
    this->Fallback->SetRadius(this->Radius);
    this->Fallback->SetRadiusArray(this->RadiusArray);
    this->Fallback->SetRadiusScale(this->RadiusScale);
    this->UsingFallback = true;
    this->Fallback->Render(ren, act);
    return;
  }
  this->UsingFallback = false;
  this->Superclass::RenderPiece(ren, act);
}

//------------------------------------------------------------------------------
void vtkTessellatedTubeMapper::UploadTubes(vtkOpenGLRenderWindow* window)
{
  if (!this->UploadTubeBuffers(window))
  {
    return;
  }
  // Orthogonal vectors (rotation-minimizing frames): octahedral, 2 x int16
  // per node, made piece by piece.
  vtkSplineTubeCore* core = this->Core;
  if (!this->FramesBuffer->UploadInPieces(window, static_cast<size_t>(core->GetNumberOfNodes()), 2,
        VTK_TYPE_INT16, GL_RG16I,
        [&](size_t first, size_t count, void* destination)
        {
          core->FillFrames(static_cast<vtkIdType>(first), static_cast<vtkIdType>(count),
            static_cast<short*>(destination));
        }))
  {
    vtkErrorMacro(<< "Could not upload the orthogonal vectors to the GPU: "
                  << this->FramesBuffer->GetLastUploadError());
    this->UploadFailed = true;
    return;
  }
  this->Levels->SetCore(core);
}

//------------------------------------------------------------------------------
bool vtkTessellatedTubeMapper::UploadBaseMeshes()
{
  if (!this->Levels->BuildMeshes(this->BaseRings, this->BaseSides) && this->BaseMeshes)
  {
    return true;
  }
  if (!this->BaseMeshes)
  {
    this->BaseMeshes = vtkSmartPointer<vtkOpenGLBufferObject>::New();
    this->BaseMeshes->SetType(vtkOpenGLBufferObject::ElementArrayBuffer);
  }
  if (!this->BaseMeshes->Upload(
        this->Levels->GetMeshIndices(), vtkOpenGLBufferObject::ElementArrayBuffer))
  {
    vtkErrorMacro(<< "Could not upload the base meshes.");
    this->BaseMeshes = nullptr;
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkTessellatedTubeMapper::ClassifyView(vtkRenderer* ren, vtkActor* act)
{
  vtkTessellatedTubeLevels::View view;
  float viewModel[16];
  float radiusScale = 1.0f;
  this->ComputeTubeMatrices(ren, act, view.ModelView, viewModel, radiusScale);
  view.RadiusScale = radiusScale;
  vtkMatrix4x4* vcdc = GetViewToDisplayMatrix(ren); // holds the projection's transpose
  for (int r = 0; r < 4; ++r)
  {
    for (int c = 0; c < 4; ++c)
    {
      view.Proj[r][c] = vcdc->GetElement(c, r);
    }
  }
  ren->GetTiledSize(&view.Width, &view.Height);
  view.Parallel = ren->GetActiveCamera()->GetParallelProjection() != 0;
  vtkTessellatedTubeLevels::Settings settings;
  settings.LevelOfDetail = this->LevelOfDetail;
  settings.Capping = this->Capping;
  settings.MaxEdgeLength = this->MaxEdgeLength;
  settings.MaxSilhouetteEdgeLength = this->MaxSilhouetteEdgeLength;
  settings.MaxTessellationLevel = this->MaxTessellationLevel;
  settings.BaseRings = this->BaseRings;
  settings.BaseSides = this->BaseSides;
  this->Levels->ClassifyView(view, settings);
}

//------------------------------------------------------------------------------
std::string vtkTessellatedTubeMapper::GetLevelOfDetailSummary()
{
  return this->Levels->GetSummary();
}

//------------------------------------------------------------------------------
std::string vtkTessellatedTubeMapper::GetTessellationControlShaderSource()
{
  std::string source = vtkTessellatedTubeTCS;
  vtkShaderProgram::Substitute(source, "//SV::SplineTubeMath::Dec", TubeMathSource());
  vtkShaderProgram::Substitute(source, "//SV::TessellatedTubeCommon::Dec", CommonSource());
  return source;
}

//------------------------------------------------------------------------------
std::string vtkTessellatedTubeMapper::GetTessellationEvaluationShaderSource()
{
  std::string source = vtkTessellatedTubeTES;
  vtkShaderProgram::Substitute(source, "//SV::SplineTubeMath::Dec", TubeMathSource());
  vtkShaderProgram::Substitute(source, "//SV::TessellatedTubeCommon::Dec", CommonSource());
  return source;
}

//------------------------------------------------------------------------------
void vtkTessellatedTubeMapper::GetPagedBuffers(std::vector<PagedBuffer>& buffers)
{
  this->Superclass::GetPagedBuffers(buffers);
  buffers.emplace_back("tubeFrames", this->FramesBuffer.get());
  // Per frame, uploaded before the program is chosen (DrawChunks()).
  buffers.emplace_back("tubeInstances", this->InstancesBuffer.get());
}

//------------------------------------------------------------------------------
bool vtkTessellatedTubeMapper::LinkTessellationStages(
  vtkShaderProgram* program, vtkOpenGLRenderWindow*)
{
  const GLuint handle = static_cast<GLuint>(program->GetHandle());
  GLint attached = 0;
  glGetProgramiv(handle, GL_ATTACHED_SHADERS, &attached);
  std::vector<GLuint> shaders(static_cast<size_t>(std::max(attached, 1)));
  GLsizei count = 0;
  glGetAttachedShaders(handle, static_cast<GLsizei>(shaders.size()), &count, shaders.data());
  for (GLsizei i = 0; i < count; ++i)
  {
    GLint type = 0;
    glGetShaderiv(shaders[i], GL_SHADER_TYPE, &type);
    if (type == GL_TESS_EVALUATION_SHADER)
    {
      return true; // linked with them already (a program shared through VTK's cache)
    }
  }

  // The stages read the per-node arrays from as many pages as the data needs
  // (vtkSplineVizGPUBuffer::ApplyPaging()): compiled again when that changes.
  const std::string paging = this->GetPagingKey();
  if ((this->ControlShader || this->EvaluationShader) && paging != this->StagesPaging)
  {
    this->ReleaseTessellationStages();
  }
  if (!this->ControlShader || !this->EvaluationShader)
  {
    GLint major = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    this->StagesVersion = major >= 4
      ? "#version 400 core\n"
      : "#version 150\n#extension GL_ARB_tessellation_shader : require\n";
    std::string error;
    std::string control = this->StagesVersion + this->GetTessellationControlShaderSource();
    std::string evaluation = this->StagesVersion + this->GetTessellationEvaluationShaderSource();
    this->ApplyPaging(control);
    this->ApplyPaging(evaluation);
    this->StagesPaging = paging;
    this->ControlShader = CompileStage(GL_TESS_CONTROL_SHADER, control, error);
    if (!this->ControlShader)
    {
      vtkErrorMacro(<< "The tessellation control stage did not compile:\n" << error);
      return false;
    }
    this->EvaluationShader = CompileStage(GL_TESS_EVALUATION_SHADER, evaluation, error);
    if (!this->EvaluationShader)
    {
      vtkErrorMacro(<< "The tessellation evaluation stage did not compile:\n" << error);
      this->ReleaseTessellationStages();
      return false;
    }
  }

  glAttachShader(handle, this->ControlShader);
  glAttachShader(handle, this->EvaluationShader);
  glLinkProgram(handle);
  GLint linked = 0;
  glGetProgramiv(handle, GL_LINK_STATUS, &linked);
  if (!linked)
  {
    GLint length = 0;
    glGetProgramiv(handle, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(static_cast<size_t>(std::max(length, 1)), '\0');
    glGetProgramInfoLog(handle, static_cast<GLsizei>(log.size()), nullptr, log.data());
    vtkErrorMacro(<< "Linking the tessellation stages failed: " << log.data());
    glDetachShader(handle, this->ControlShader);
    glDetachShader(handle, this->EvaluationShader);
    return false;
  }
  // The program is bound (VTK's shader cache bound it); make the new
  // executable current explicitly.
  glUseProgram(handle);
  return true;
}

//------------------------------------------------------------------------------
void vtkTessellatedTubeMapper::UpdateShaders(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  // As vtkOpenGLPolyDataMapper::UpdateShaders, with the tessellation stages
  // linked in right after VTK's shader cache compiled and linked the
  // program: its uniform locations are looked up only afterwards.
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  cellBO.VAO->Bind();
  this->LastBoundBO = &cellBO;

  vtkShaderProgram* program = nullptr;
  if (this->GetNeedToRebuildShaders(cellBO, ren, act))
  {
    std::map<vtkShader::Type, vtkShader*> shaders;
    vtkNew<vtkShader> vs;
    vs->SetType(vtkShader::Vertex);
    vtkNew<vtkShader> gs;
    gs->SetType(vtkShader::Geometry);
    vtkNew<vtkShader> fs;
    fs->SetType(vtkShader::Fragment);
    shaders[vtkShader::Vertex] = vs;
    shaders[vtkShader::Geometry] = gs;
    shaders[vtkShader::Fragment] = fs;
    this->BuildShaders(shaders, ren, act);
    program = window->GetShaderCache()->ReadyShaderProgram(shaders);
    if (this->BuildingThinProgram)
    {
      // thin-tube draws: no tessellation stages
    }
    else if (program && !this->StagesFailed && !this->LinkTessellationStages(program, window))
    {
      this->StagesFailed = true; // reported; do not retry every frame
    }
    if (this->StagesFailed && !this->BuildingThinProgram)
    {
      program = nullptr;
    }
    if (program != cellBO.Program || (program && program->GetMTime() > cellBO.AttributeUpdateTime))
    {
      cellBO.Program = program;
      cellBO.VAO->ReleaseGraphicsResources();
    }
    cellBO.ShaderSourceTime.Modified();
  }
  else if (cellBO.Program)
  {
    program = window->GetShaderCache()->ReadyShaderProgram(cellBO.Program);
    // A program VTK had to compile again lost our stages: link them again.
    if (program && !this->BuildingThinProgram && !this->LinkTessellationStages(program, window))
    {
      this->StagesFailed = true;
      program = nullptr;
    }
    if (!program)
    {
      cellBO.Program = nullptr;
    }
    else if (program->GetMTime() > cellBO.AttributeUpdateTime)
    {
      cellBO.VAO->ReleaseGraphicsResources();
    }
  }

  if (cellBO.Program)
  {
    this->SetCustomUniforms(cellBO, act);
    this->SetMapperShaderParameters(cellBO, ren, act);
    this->SetPropertyShaderParameters(cellBO, ren, act);
    this->SetCameraShaderParameters(cellBO, ren, act);
    this->SetLightingShaderParameters(cellBO, ren, act);
    this->InvokeEvent(vtkCommand::UpdateShaderEvent, cellBO.Program);
  }
}

//------------------------------------------------------------------------------
void vtkTessellatedTubeMapper::GetShaderTemplate(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act)
{
  this->Superclass::GetShaderTemplate(shaders, ren, act);
  shaders[vtkShader::Vertex]->SetSource(
    this->BuildingThinProgram ? vtkTessellatedTubeThinVS : vtkTessellatedTubeVS);
  shaders[vtkShader::Geometry]->SetSource("");
}

//------------------------------------------------------------------------------
void vtkTessellatedTubeMapper::ReplaceShaderValues(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act)
{
  std::string VSSource = shaders[vtkShader::Vertex]->GetSource();
  std::string FSSource = shaders[vtkShader::Fragment]->GetSource();
  const std::string math = TubeMathSource();

  vtkShaderProgram::Substitute(VSSource, "//SV::SplineTubeMath::Dec", math);
  vtkShaderProgram::Substitute(VSSource, "//SV::TessellatedTubeCommon::Dec", CommonSource());
  // VTK's shader cache identifies programs by their vertex, geometry and
  // fragment sources: make the tessellation stages part of the key.
  if (!this->BuildingThinProgram)
  {
    const size_t stagesKey = std::hash<std::string>()(
      this->GetTessellationControlShaderSource() + this->GetTessellationEvaluationShaderSource());
    VSSource += "\n// tessellation stages " + std::to_string(stagesKey) + "\n";
  }

  std::string declarations =
    this->BuildingThinProgram ? vtkTessellatedTubeThinFS : vtkTessellatedTubeFS;
  vtkShaderProgram::Substitute(declarations, "//SV::SplineTubeMath::Dec", math);
  const int colorMode = this->GetTubeColorMode();
  if (colorMode == 2)
  {
    // Per fragment, the position spline's tangent at the curve parameter of
    // the fragment: the axis point nearest to it (the tube is swept by a
    // sphere), two Newton steps from the interpolated parameter of the run
    // (tubeTVSOutput, from its first node), which is off by up to a
    // fraction of the ring spacing in bends.
    declarations += "uniform mat4 tubeMCVC;\n" + GetTubeNodesDeclarations() +
      GetTubeDirectionColorDeclarations() +
      "vec4 tubeDirectionAt(ivec4 info, float tRun, vec3 pointVC)\n"
      "{\n"
      "  int k = clamp(int(floor(tRun)), 0, max(info.w >> 4, 1) - 1);\n"
      "  int node = info.x + k;\n"
      "  vec4 p0 = tubeNodeModel(node);\n"
      "  vec4 m0 = tubeNodeDerivativeModel(node);\n"
      "  vec4 p1 = tubeNodeModel(node + 1);\n"
      "  vec4 m1 = tubeNodeDerivativeModel(node + 1);\n"
      "  vec3 x = (inverse(tubeMCVC) * vec4(pointVC, 1.0)).xyz;\n"
      "  float t = clamp(tRun - float(k), 0.0, 1.0);\n"
      "  for (int i = 0; i < 2; ++i)\n"
      "  {\n"
      "    vec3 e = svHermite(p0, m0, p1, m1, t).xyz - x;\n"
      "    vec3 d = svHermiteDerivative(p0, m0, p1, m1, t).xyz;\n"
      "    vec3 dd = svHermiteSecondDerivative(p0, m0, p1, m1, t).xyz;\n"
      "    float h = dot(d, d) + dot(e, dd);\n"
      "    t = clamp(t - (h > 0.0 ? dot(e, d) / h : 0.0), 0.0, 1.0);\n"
      "  }\n"
      "  return tubeDirectionColor(svHermiteDerivative(p0, m0, p1, m1, t).xyz);\n"
      "}\n";
  }
  vtkShaderProgram::Substitute(FSSource, "//VTK::Normal::Dec", declarations);
  vtkShaderProgram::Substitute(FSSource, "//VTK::PositionVC::Dec", "in vec4 vertexVCVSOutput;");
  std::string position = "  vec4 vertexVC = vertexVCVSOutput;\n";
  if (colorMode == 1)
  {
    // The color spline, evaluated per vertex by the evaluation stage.
    position += "  vec4 tubeColor = tubeColorVSOutput;\n";
  }
  else if (colorMode == 2)
  {
    position +=
      "  vec4 tubeColor = tubeDirectionAt(tubeInfoVSOutput, tubeTVSOutput, vertexVC.xyz);\n";
  }
  vtkShaderProgram::Substitute(FSSource, "//VTK::PositionVC::Impl", position);
  if (this->BuildingThinProgram)
  {
    // Thin walls: the front surface along the ray from the ribbon (depth and
    // normal); caps as drawn. The vertex stage turns the caps' normals to the
    // eye (their walls show only front faces): no gl_FrontFacing flip.
    vtkShaderProgram::Substitute(FSSource, "//VTK::Depth::Impl",
      std::string("  vec3 tubeThinNormal = tubeNormalVCVSOutput.xyz;\n"
                  "  if (tubeAxisVCVSOutput.w > 0.0)\n"
                  "  {\n"
                  "    vec3 tubeHitVC;\n"
                  "    if (!tubeThinSurface(vertexVC.xyz, tubeHitVC, tubeThinNormal))\n"
                  "    {\n"
                  "      discard;\n"
                  "    }\n"
                  "    vertexVC = vec4(tubeHitVC, 1.0);\n"
                  "    vec4 tubeHitDC = VCDCMatrix * vertexVC;\n"
                  "    gl_FragDepth = 0.5 * (gl_DepthRange.diff * (tubeHitDC.z / tubeHitDC.w) +\n"
                  "      gl_DepthRange.near + gl_DepthRange.far);\n"
                  "  }\n"
                  "  else\n"
                  "  {\n"
                  "    gl_FragDepth = gl_FragCoord.z;\n"
                  "  }\n") +
        GetFragDepthWrittenMarker());
    vtkShaderProgram::Substitute(
      FSSource, "//VTK::Normal::Impl", "  vec3 normalVCVSOutput = normalize(tubeThinNormal);\n");
  }
  else
  {
    // The start caps are wound clockwise (seen from outside): flip their
    // sense of gl_FrontFacing.
    vtkShaderProgram::Substitute(FSSource, "//VTK::Normal::Impl",
      "  vec3 normalVCVSOutput = normalize(tubeNormalVCVSOutput);\n"
      "  if (gl_FrontFacing != (((tubeInfoVSOutput.w >> 2) & 3) != 1))\n"
      "  {\n"
      "    normalVCVSOutput = -normalVCVSOutput;\n"
      "  }\n");
  }

  // Picking: the cell is the polyline, the composite index its block.
  this->ReplaceShaderTubePicking(FSSource, "tubeInfoVSOutput.z");

  shaders[vtkShader::Vertex]->SetSource(VSSource);
  shaders[vtkShader::Fragment]->SetSource(FSSource);

  this->Superclass::ReplaceShaderValues(shaders, ren, act);
  if (this->BuildingThinProgram)
  {
    // Render passes (depth peeling) compare gl_FragCoord.z with their depth
    // textures; for thin walls the depth is the one written above.
    FSSource = shaders[vtkShader::Fragment]->GetSource();
    UseWrittenFragDepth(FSSource);
    shaders[vtkShader::Fragment]->SetSource(FSSource);
  }

  DumpShaderSources(
    { { this->BuildingThinProgram ? "ThinVS" : "VS", shaders[vtkShader::Vertex]->GetSource() },
      { "TCS", this->GetTessellationControlShaderSource() },
      { "TES", this->GetTessellationEvaluationShaderSource() },
      { "FS", shaders[vtkShader::Fragment]->GetSource() } });
}

//------------------------------------------------------------------------------
void vtkTessellatedTubeMapper::ReplaceShaderClip(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer*, vtkActor*)
{
  // Clip per fragment.
  std::string FSSource = shaders[vtkShader::Fragment]->GetSource();
  this->ReplaceShaderTubeClip(FSSource, "//VTK::Clip::Impl");
  shaders[vtkShader::Fragment]->SetSource(FSSource);
}

//------------------------------------------------------------------------------
void vtkTessellatedTubeMapper::SetMapperShaderParameters(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  this->Superclass::SetMapperShaderParameters(cellBO, ren, act);
  vtkShaderProgram* program = cellBO.Program;
  program->SetUniformf("tubeMaxEdgeLength", static_cast<float>(this->MaxEdgeLength));
  program->SetUniformf(
    "tubeSilhouetteEdgeLength", static_cast<float>(this->MaxSilhouetteEdgeLength));
  program->SetUniformf("tubeMaxLevel", static_cast<float>(this->MaxTessellationLevel));
  program->SetUniformf(
    "tubeMaxSilhouetteLevel", static_cast<float>(this->MaxSilhouetteTessellationLevel));
  program->SetUniformi("tubeCaps", this->Capping ? 1 : 0);
  program->SetUniformi("tubeHaveColors", this->GetTubeColorMode());
  program->SetUniformf("tubeSideLength", static_cast<float>(2.0 * this->MaxSilhouetteEdgeLength));
  this->FramesBuffer->Activate(program, "tubeFrames");
  this->InstancesBuffer->Activate(program, "tubeInstances");
}

//------------------------------------------------------------------------------
void vtkTessellatedTubeMapper::SetCameraShaderParameters(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  this->Superclass::SetCameraShaderParameters(cellBO, ren, act);
  vtkShaderProgram* program = cellBO.Program;
  vtkMatrix4x4* vcdc = GetViewToDisplayMatrix(ren);

  int width = 1;
  int height = 1;
  ren->GetTiledSize(&width, &height);
  const float viewport[2] = { static_cast<float>(std::max(width, 1)),
    static_cast<float>(std::max(height, 1)) };
  program->SetUniform2f("tubeViewport", viewport);

  // Frustum planes in view coordinates from the rows of the projection P
  // (vcdc holds P transposed): row3 +- row0, row3 +- row1, row3 +- row2.
  float planes[6][4];
  auto P = [vcdc](int r, int c) { return vcdc->GetElement(c, r); };
  for (int k = 0; k < 3; ++k)
  {
    for (int side = 0; side < 2; ++side)
    {
      const double sign = side == 0 ? 1.0 : -1.0;
      double p[4];
      for (int c = 0; c < 4; ++c)
      {
        p[c] = P(3, c) + sign * P(k, c);
      }
      const double len = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
      for (int c = 0; c < 4; ++c)
      {
        planes[2 * k + side][c] = static_cast<float>(len > 0.0 ? p[c] / len : 0.0);
      }
    }
  }
  program->SetUniform4fv("tubeFrustum", 6, planes);
}

//------------------------------------------------------------------------------
void vtkTessellatedTubeMapper::RenderPieceDraw(vtkRenderer* ren, vtkActor* act)
{
  this->NumberOfPrimitivesGenerated = 0;
  this->Levels->ResetSummary();
  if (this->Core->GetNumberOfSegments() == 0 || this->GetTubeBuffersSize() == 0 ||
    !this->UploadBaseMeshes())
  {
    return;
  }
  this->ClassifyView(ren, act);

  // The walls are wound counter-clockwise seen from outside: the rasterizer
  // culls their back faces (the control stage culled most back patches
  // already). The start caps are wound the other way: no culling for caps
  // (the control stage culls caps turned away).
  auto* window = static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow());
  vtkOpenGLState* state = window->GetState();
  vtkOpenGLState::ScopedglEnableDisable cull(state, GL_CULL_FACE);
  GLint cullMode = GL_BACK;
  state->vtkglGetIntegerv(GL_CULL_FACE_MODE, &cullMode);
  state->vtkglCullFace(GL_BACK);
  // The wireframe representation shows the tessellation (VTK 9.2 does not
  // track the polygon mode: restore the default).
  const bool wireframe = act->GetProperty()->GetRepresentation() == VTK_WIREFRAME;
  if (wireframe)
  {
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  }
  if (this->CountPrimitives)
  {
    if (!this->PrimitivesQuery)
    {
      glGenQueries(1, &this->PrimitivesQuery);
    }
    glBeginQuery(GL_PRIMITIVES_GENERATED, this->PrimitivesQuery);
  }

  this->DrawVisibleChunks(ren, act,
    [&](const std::vector<std::uint32_t>& chunks) { this->DrawChunks(ren, act, chunks); });

  if (this->CountPrimitives)
  {
    glEndQuery(GL_PRIMITIVES_GENERATED);
    GLuint64 count = 0;
    glGetQueryObjectui64v(this->PrimitivesQuery, GL_QUERY_RESULT, &count);
    this->NumberOfPrimitivesGenerated = static_cast<vtkTypeUInt64>(count);
  }
  if (wireframe)
  {
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  }
  state->vtkglCullFace(static_cast<unsigned int>(cullMode));
  this->DeactivateTubeBuffers();
  this->FramesBuffer->Deactivate();
  this->InstancesBuffer->Deactivate();
}

//------------------------------------------------------------------------------
void vtkTessellatedTubeMapper::DrawChunks(
  vtkRenderer* ren, vtkActor* act, const std::vector<std::uint32_t>& chunks)
{
  vtkTessellatedTubeLevels& levels = *this->Levels;
  levels.BuildDraws(chunks);
  const std::vector<vtkTessellatedTubeLevels::Draw>& draws = levels.GetDraws();
  if (draws.empty())
  {
    return;
  }
  auto* window = static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow());
  if (!this->InstancesBuffer->Upload(window, levels.GetInstances().data(),
        levels.GetInstances().size(), 1, VTK_TYPE_UINT32, GL_R32UI))
  {
    vtkErrorMacro(<< "Could not upload the instance list: "
                  << this->InstancesBuffer->GetLastUploadError());
    return;
  }
  const bool haveThin = std::any_of(
    draws.begin(), draws.end(), [](const vtkTessellatedTubeLevels::Draw& d) { return d.Thin; });
  const bool havePatches = std::any_of(
    draws.begin(), draws.end(), [](const vtkTessellatedTubeLevels::Draw& d) { return !d.Thin; });
  vtkOpenGLState* state = window->GetState();

  // Patches through the tessellation stages.
  vtkOpenGLHelper& helper = this->Primitives[PrimitiveTris];
  if (havePatches)
  {
    this->UpdateShaders(helper, ren, act);
  }
  if (havePatches && helper.Program)
  {
    vtkShaderProgram* program = helper.Program;
    // UpdateShaders() may have released the VAO after binding it (new
    // program); the draw has no attributes but core profiles need a VAO.
    helper.VAO->Bind();
    this->BaseMeshes->Bind();
    glPatchParameteri(GL_PATCH_VERTICES, 4);
    for (const auto& draw : draws)
    {
      if (draw.Thin)
      {
        continue;
      }
      const vtkTessellatedTubeLevels::MeshRange& mesh =
        draw.Caps ? levels.GetCapMesh(draw.Sides) : levels.GetWallMesh(draw.Rings, draw.Sides);
      if (draw.Caps)
      {
        state->vtkglDisable(GL_CULL_FACE);
      }
      else
      {
        state->vtkglEnable(GL_CULL_FACE);
      }
      program->SetUniformi("tubeRings", draw.Rings);
      program->SetUniformi("tubeSides", draw.Sides);
      program->SetUniformi("tubeListOffset", static_cast<int>(draw.Offset));
      program->SetUniformi("tubeChunks", draw.Chunks ? 1 : 0);
      glDrawElementsInstanced(GL_PATCHES, static_cast<GLsizei>(mesh.Count), GL_UNSIGNED_INT,
        reinterpret_cast<const void*>(mesh.Offset * sizeof(unsigned int)),
        static_cast<GLsizei>(draw.Count));
    }
    this->BaseMeshes->Release();
  }

  // Thin tubes: triangles from the vertex stage alone (a second program).
  vtkOpenGLHelper& thinHelper = this->Primitives[PrimitiveTriStrips];
  if (haveThin)
  {
    this->BuildingThinProgram = true;
    this->UpdateShaders(thinHelper, ren, act);
    this->BuildingThinProgram = false;
  }
  if (haveThin && thinHelper.Program)
  {
    vtkShaderProgram* program = thinHelper.Program;
    thinHelper.VAO->Bind();
    this->BaseMeshes->Bind();
    state->vtkglEnable(GL_CULL_FACE);
    for (const auto& draw : draws)
    {
      if (!draw.Thin)
      {
        continue;
      }
      program->SetUniformi("tubeListOffset", static_cast<int>(draw.Offset));
      program->SetUniformi("tubeCapDraw", draw.Caps ? 1 : 0);
      if (draw.Caps)
      {
        // (the start caps are wound the other way: no culling, as for the
        // caps' patches)
        const vtkTessellatedTubeLevels::MeshRange& mesh = levels.GetThinCapMesh();
        state->vtkglDisable(GL_CULL_FACE);
        glDrawElementsInstanced(GL_TRIANGLES, static_cast<GLsizei>(mesh.Count), GL_UNSIGNED_INT,
          reinterpret_cast<const void*>(mesh.Offset * sizeof(unsigned int)),
          static_cast<GLsizei>(draw.Count));
        state->vtkglEnable(GL_CULL_FACE);
        continue;
      }
      const size_t rows = static_cast<size_t>(draw.Rings - 1);
      program->SetUniformi("tubeRings", draw.Rings);
      glDrawElementsInstanced(GL_TRIANGLES,
        static_cast<GLsizei>(6 * rows * (vtkTessellatedTubeLevels::ThinRibbonSides - 1)),
        GL_UNSIGNED_INT,
        reinterpret_cast<const void*>(levels.GetThinMesh().Offset * sizeof(unsigned int)),
        static_cast<GLsizei>(draw.Count));
    }
    this->BaseMeshes->Release();
  }
}

//------------------------------------------------------------------------------
void vtkTessellatedTubeMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "MaxEdgeLength: " << this->MaxEdgeLength << "\n";
  os << indent << "MaxSilhouetteEdgeLength: " << this->MaxSilhouetteEdgeLength << "\n";
  os << indent << "MaxTessellationLevel: " << this->MaxTessellationLevel << "\n";
  os << indent << "MaxSilhouetteTessellationLevel: " << this->MaxSilhouetteTessellationLevel
     << "\n";
  os << indent << "BaseRings: " << this->BaseRings << "\n";
  os << indent << "BaseSides: " << this->BaseSides << "\n";
  os << indent << "LevelOfDetail: " << (this->LevelOfDetail ? "On" : "Off") << "\n";
  os << indent << "Capping: " << (this->Capping ? "On" : "Off") << "\n";
  os << indent << "CountPrimitives: " << (this->CountPrimitives ? "On" : "Off") << "\n";
  os << indent << "UsingFallback: " << (this->UsingFallback ? "yes" : "no") << "\n";
}
