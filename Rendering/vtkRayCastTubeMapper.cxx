#include "vtkRayCastTubeMapper.h"

#include "vtkSplineTubeCore.h"
#include "vtkSplineVizGPUBuffer.h"

#include "vtkActor.h"
#include "vtkFloatArray.h"
#include "vtkHardwareSelector.h"
#include "vtkIdTypeArray.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkOpenGLCamera.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkRenderer.h"
#include "vtkShader.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkTypeUInt32Array.h"
#include "vtkUnsignedCharArray.h"

#include "vtkRayCastTubeCullFS.h"
#include "vtkRayCastTubeCullVS.h"
#include "vtkRayCastTubeFS.h"
#include "vtkRayCastTubeGS.h"
#include "vtkRayCastTubeVS.h"
#include "vtkSplineTubeMathPrelude.h"
#include "vtkSplineTubeMathShared.h"

#include <vtk_glew.h>

#include <algorithm>
#include <cmath>
#include <vector>

vtkStandardNewMacro(vtkRayCastTubeMapper);

namespace
{
std::string TubeMathSource()
{
  return std::string(vtkSplineTubeMathPrelude) + vtkSplineTubeMathShared;
}
}

//------------------------------------------------------------------------------
vtkRayCastTubeMapper::vtkRayCastTubeMapper()
{
  // Sphere-swept tubes need no cross-section frames.
  this->Core->ComputeFramesOff();
}

//------------------------------------------------------------------------------
vtkRayCastTubeMapper::~vtkRayCastTubeMapper() = default;

//------------------------------------------------------------------------------
void vtkRayCastTubeMapper::SetSubSegments(int n)
{
  n = std::max(2, std::min(16, n + (n % 2)));
  if (n != this->SubSegments)
  {
    this->SubSegments = n;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
size_t vtkRayCastTubeMapper::GetGPUMemorySize()
{
  return this->GetTubeBuffersSize();
}

//------------------------------------------------------------------------------
void vtkRayCastTubeMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  this->QuadIndices->ReleaseGraphicsResources();
  this->QuadIndicesUploaded = false;
  this->CullVAO->ReleaseGraphicsResources();
  if (this->CullDepth)
  {
    this->CullDepth->ReleaseGraphicsResources(window);
  }
  if (this->CullFramebuffer)
  {
    this->CullFramebuffer->ReleaseGraphicsResources(window);
  }
  this->CullDepth = nullptr;
  this->CullFramebuffer = nullptr;
  this->CullProgram = nullptr; // released with the window's shader cache
  this->CullSize[0] = this->CullSize[1] = 0;
  this->CullFailed = false;
  this->Superclass::ReleaseGraphicsResources(window);
}

//------------------------------------------------------------------------------
void vtkRayCastTubeMapper::UploadTubes(vtkOpenGLRenderWindow* window)
{
  // The shared tubes buffer holds everything the ray caster reads.
  this->UploadTubeBuffers(window);
}

//------------------------------------------------------------------------------
bool vtkRayCastTubeMapper::UploadQuadIndices()
{
  if (this->QuadIndices->GetHandle() != 0 && this->QuadIndicesUploaded)
  {
    return true;
  }
  std::vector<unsigned short> indices(6 * QuadsPerDraw);
  for (int q = 0; q < QuadsPerDraw; ++q)
  {
    const unsigned short v = static_cast<unsigned short>(4 * q);
    const unsigned short pattern[6] = { v, static_cast<unsigned short>(v + 1),
      static_cast<unsigned short>(v + 2), static_cast<unsigned short>(v + 2),
      static_cast<unsigned short>(v + 1), static_cast<unsigned short>(v + 3) };
    std::copy(pattern, pattern + 6, &indices[6 * q]);
  }
  this->QuadIndicesUploaded =
    this->QuadIndices->Upload(indices, vtkOpenGLBufferObject::ElementArrayBuffer);
  return this->QuadIndicesUploaded;
}

//------------------------------------------------------------------------------
void vtkRayCastTubeMapper::GetShaderTemplate(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act)
{
  this->Superclass::GetShaderTemplate(shaders, ren, act);
  shaders[vtkShader::Vertex]->SetSource(vtkRayCastTubeVS);
  shaders[vtkShader::Geometry]->SetSource(vtkRayCastTubeGS);
}

//------------------------------------------------------------------------------
void vtkRayCastTubeMapper::ReplaceShaderValues(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act)
{
  std::string VSSource = shaders[vtkShader::Vertex]->GetSource();
  std::string FSSource = shaders[vtkShader::Fragment]->GetSource();
  const std::string math = TubeMathSource();

  vtkShaderProgram::Substitute(VSSource, "//VTK::SplineTubeMath::Dec", math);

  std::string declarations = vtkRayCastTubeFS;
  vtkShaderProgram::Substitute(declarations, "//VTK::SplineTubeMath::Dec", math);
  if (this->HaveColors)
  {
    declarations += GetTubeColorDeclarations();
  }
  if (this->CullThisDraw)
  {
    declarations += "uniform sampler2D tubeCullDepth;\n"
                    "uniform ivec2 tubeCullOrigin;\n";
  }
  vtkShaderProgram::Substitute(FSSource, "//VTK::Normal::Dec", declarations);
  // The proxy rectangle lies in the plane of the sub-segment's nearest depth,
  // so the exact depth written is never in front of the rasterized one: with
  // depth_greater a GPU may run the depth test before the shader. (llvmpipe
  // ignores it: Fibers2 frame times were the same within noise, 0.70 s with
  // and 0.81 s without.)
  vtkShaderProgram::Substitute(FSSource, "//VTK::System::Dec",
    "//VTK::System::Dec\n"
    "#ifdef GL_ARB_conservative_depth\n"
    "#extension GL_ARB_conservative_depth : enable\n"
    "layout(depth_greater) out float gl_FragDepth;\n"
    "#endif\n",
    false);
  vtkShaderProgram::Substitute(FSSource, "//VTK::PositionVC::Dec", "in vec4 vertexVCVSOutput;");
  vtkShaderProgram::Substitute(
    FSSource, "//VTK::PositionVC::Impl", "vec4 vertexVC = vertexVCVSOutput;\n");

  // The ray cast runs inside a branch: a software rasterizer runs the code
  // after a discard for the discarded fragments too (masked), but skips a
  // branch no fragment of its group takes.
  std::string depth = "  vec3 tubeHitVC;\n"
                      "  vec3 normalVCVSOutput;\n"
                      "  float tubeT;\n";
  if (this->CullThisDraw)
  {
    // Occlusion culling: the rectangle lies in front of its whole
    // sub-segment; behind the pre-pass depth something inside a tube (so a
    // tube's surface) is in front of it along this pixel's ray.
    depth += "  bool tubeHit = gl_FragCoord.z <= texelFetch(tubeCullDepth,\n"
             "    ivec2(gl_FragCoord.xy) - tubeCullOrigin, 0).r;\n";
  }
  else
  {
    depth += "  bool tubeHit = true;\n";
  }
  depth += "  if (tubeHit)\n"
           "  {\n"
           "    tubeHit = tubeRayCast(vertexVC.xyz, tubeHitVC, normalVCVSOutput, tubeT);\n"
           "  }\n";
  depth += ""
           "  if (!tubeHit)\n"
           "  {\n"
           "    discard;\n"
           "  }\n"
           "  if (tubeHit) // the rest of main(), closed at its end\n"
           "  {\n"
           "  vertexVC = vec4(tubeHitVC, 1.0);\n"
           "  //VTK::TubeClip::Impl\n"
           "  vec4 tubeHitDC = VCDCMatrix * vertexVC;\n"
           "  gl_FragDepth = 0.5 * (gl_DepthRange.diff * (tubeHitDC.z / tubeHitDC.w) +\n"
           "    gl_DepthRange.near + gl_DepthRange.far);\n";
  if (this->HaveColors)
  {
    depth += GetTubeColorImplementation("tubeInfoVSOutput.x", "tubeT");
  }
  depth += GetFragDepthWrittenMarker();
  vtkShaderProgram::Substitute(FSSource, "//VTK::Depth::Impl", depth);
  vtkShaderProgram::Substitute(
    FSSource, "//VTK::Coincident::Impl", "//VTK::Coincident::Impl\n  } // tubeHit\n");
  // The normal comes from the intersection.
  vtkShaderProgram::Substitute(FSSource, "//VTK::Normal::Impl", "");

  // Picking: the cell is the polyline, the composite index its block.
  this->ReplaceShaderTubePicking(FSSource, "tubeInfoVSOutput.z");

  shaders[vtkShader::Vertex]->SetSource(VSSource);
  shaders[vtkShader::Fragment]->SetSource(FSSource);

  this->Superclass::ReplaceShaderValues(shaders, ren, act);

  // Render passes (depth peeling) compare gl_FragCoord.z with their depth
  // textures; for ray-cast fragments the depth is the one written above.
  FSSource = shaders[vtkShader::Fragment]->GetSource();
  UseWrittenFragDepth(FSSource);
  shaders[vtkShader::Fragment]->SetSource(FSSource);
  DumpShaderSources({ { "VS", shaders[vtkShader::Vertex]->GetSource() },
    { "FS", shaders[vtkShader::Fragment]->GetSource() } });
}

//------------------------------------------------------------------------------
void vtkRayCastTubeMapper::ReplaceShaderClip(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer*, vtkActor*)
{
  // Clip the hit point (not the proxy rectangle).
  std::string FSSource = shaders[vtkShader::Fragment]->GetSource();
  this->ReplaceShaderTubeClip(FSSource, "//VTK::TubeClip::Impl");
  shaders[vtkShader::Fragment]->SetSource(FSSource);
}

//------------------------------------------------------------------------------
void vtkRayCastTubeMapper::SetMapperShaderParameters(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  this->Superclass::SetMapperShaderParameters(cellBO, ren, act);
  vtkShaderProgram* program = cellBO.Program;
  program->SetUniformi("subSegments", this->SubSegments);
  program->SetUniformi("rootIterations", this->RootIterations);
  program->SetUniformi("rootSamples", this->RootSamples);
  program->SetUniformf("tubeStraightTolerance", static_cast<float>(this->StraightTolerance));
  if (this->CullThisDraw && this->CullDepth)
  {
    this->CullDepth->Activate();
    program->SetUniformi("tubeCullDepth", this->CullDepth->GetTextureUnit());
    program->SetUniform2i("tubeCullOrigin", this->CullOrigin);
  }
}

//------------------------------------------------------------------------------
bool vtkRayCastTubeMapper::GetNeedToRebuildShaders(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  // The culling test is part of the fragment stage only when it is used.
  const bool superclass = this->Superclass::GetNeedToRebuildShaders(cellBO, ren, act);
  if (this->CullThisDraw != this->CullShaders)
  {
    this->CullShaders = this->CullThisDraw;
    return true;
  }
  return superclass;
}

//------------------------------------------------------------------------------
void vtkRayCastTubeMapper::SetCameraShaderParameters(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  this->Superclass::SetCameraShaderParameters(cellBO, ren, act);
  double range[2];
  ren->GetActiveCamera()->GetClippingRange(range);
  cellBO.Program->SetUniformf("tubeNearPlane", static_cast<float>(range[0]));
  // Pixels per view unit (at unit distance for perspective), for the
  // straightness tolerance.
  vtkMatrix4x4* vcdc = GetViewToDisplayMatrix(ren);
  int width = 1;
  int height = 1;
  ren->GetTiledSize(&width, &height);
  cellBO.Program->SetUniformf("tubePixelScale",
    static_cast<float>(0.5 *
      std::max(
        std::abs(vcdc->GetElement(0, 0)) * width, std::abs(vcdc->GetElement(1, 1)) * height)));
}

//------------------------------------------------------------------------------
void vtkRayCastTubeMapper::RenderPieceDraw(vtkRenderer* ren, vtkActor* act)
{
  const vtkIdType count = this->Core->GetNumberOfSegments() * this->SubSegments;
  this->LastRenderCulled = false;
  if (count == 0 || this->GetTubeBuffersSize() == 0)
  {
    return;
  }
  // Occlusion culling for opaque tubes without clipping planes (see the
  // class comment): the pre-pass first, before the ray-cast program is bound.
  this->CullThisDraw = this->OcclusionCulling && !this->CullFailed &&
    !act->IsRenderingTranslucentPolygonalGeometry() && this->GetNumberOfClippingPlanes() == 0;
  if (this->CullThisDraw)
  {
    this->CullThisDraw = this->RenderCullingPass(ren, act);
  }
  vtkOpenGLHelper& helper = this->Primitives[PrimitiveTris];
  this->UpdateShaders(helper, ren, act);

  if (!helper.Program)
  {
    return;
  }
  // UpdateShaders() may have released the VAO after binding it (new
  // program); the draw has no attributes but core profiles need a VAO bound.
  helper.VAO->Bind();
  // One rectangle (4-vertex strip) per sub-segment; either winding.
  vtkOpenGLState* state = static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow())->GetState();
  vtkOpenGLState::ScopedglEnableDisable cull(state, GL_CULL_FACE);
  state->vtkglDisable(GL_CULL_FACE);
  glDrawArrays(GL_POINTS, 0, static_cast<GLsizei>(count));

  this->DeactivateTubeBuffers();
  if (this->CullThisDraw && this->CullDepth)
  {
    this->CullDepth->Deactivate();
  }
  this->LastRenderCulled = this->CullThisDraw;
}

//------------------------------------------------------------------------------
void vtkRayCastTubeMapper::DrawQuads(vtkIdType quads)
{
  // Rectangles as indexed triangles: one small, shared index pattern for
  // QuadsPerDraw rectangles, drawn repeatedly with a base vertex (so that
  // every corner is shaded once, without per-rectangle index memory and
  // without the per-instance cost of instancing in software renderers).
  const vtkIdType chunks = (quads + QuadsPerDraw - 1) / QuadsPerDraw;
  std::vector<GLsizei> counts(static_cast<size_t>(chunks));
  std::vector<const void*> offsets(static_cast<size_t>(chunks), nullptr);
  std::vector<GLint> baseVertices(static_cast<size_t>(chunks));
  for (vtkIdType c = 0; c < chunks; ++c)
  {
    const vtkIdType n = std::min<vtkIdType>(QuadsPerDraw, quads - c * QuadsPerDraw);
    counts[c] = static_cast<GLsizei>(6 * n);
    baseVertices[c] = static_cast<GLint>(4 * c * QuadsPerDraw);
  }
  glMultiDrawElementsBaseVertex(GL_TRIANGLES, counts.data(), GL_UNSIGNED_SHORT, offsets.data(),
    static_cast<GLsizei>(chunks), baseVertices.data());
}

//------------------------------------------------------------------------------
bool vtkRayCastTubeMapper::RenderCullingPass(vtkRenderer* ren, vtkActor* act)
{
  auto* window = static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow());
  vtkOpenGLState* state = window->GetState();
  int viewport[4] = { 0, 0, 0, 0 };
  state->vtkglGetIntegerv(GL_VIEWPORT, viewport);
  const int width = viewport[2];
  const int height = viewport[3];
  if (width <= 0 || height <= 0)
  {
    return false;
  }
  if (!this->UploadQuadIndices()) // (only this pass draws quads)
  {
    vtkErrorMacro(<< "Could not upload the occlusion-culling pre-pass' indices; drawing "
                     "without it.");
    this->CullFailed = true;
    return false;
  }

  // The program (vertex stage: the bands; fragment stage: nothing).
  vtkOpenGLShaderCache* cache = window->GetShaderCache();
  vtkShaderProgram* program = nullptr;
  if (this->CullProgram)
  {
    program = cache->ReadyShaderProgram(this->CullProgram);
  }
  else
  {
    std::string vs = vtkRayCastTubeCullVS;
    vtkShaderProgram::Substitute(vs, "//VTK::SplineTubeMath::Dec", TubeMathSource());
    program = cache->ReadyShaderProgram(vs.c_str(), vtkRayCastTubeCullFS, "");
  }
  this->CullProgram = program;
  if (!program)
  {
    vtkErrorMacro(<< "The occlusion-culling pre-pass did not compile; drawing without it.");
    this->CullFailed = true;
    return false;
  }

  // Its framebuffer: a depth texture the size of the viewport.
  if (!this->CullFramebuffer)
  {
    this->CullFramebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
    this->CullFramebuffer->SetContext(window);
  }
  this->CullFramebuffer->SaveCurrentBindingsAndBuffers();
  this->CullFramebuffer->Bind();
  if (!this->CullDepth || this->CullSize[0] != width || this->CullSize[1] != height)
  {
    if (this->CullDepth)
    {
      this->CullFramebuffer->RemoveDepthAttachment();
      this->CullDepth->ReleaseGraphicsResources(window);
    }
    this->CullDepth = vtkSmartPointer<vtkTextureObject>::New();
    this->CullDepth->SetContext(window);
    this->CullDepth->SetMinificationFilter(vtkTextureObject::Nearest);
    this->CullDepth->SetMagnificationFilter(vtkTextureObject::Nearest);
    this->CullDepth->SetWrapS(vtkTextureObject::ClampToEdge);
    this->CullDepth->SetWrapT(vtkTextureObject::ClampToEdge);
    if (!this->CullDepth->AllocateDepth(width, height, vtkTextureObject::Float32))
    {
      this->CullFramebuffer->RestorePreviousBindingsAndBuffers();
      this->CullDepth = nullptr;
      this->CullSize[0] = this->CullSize[1] = 0;
      vtkErrorMacro(<< "Could not allocate the " << width << " x " << height
                    << " depth texture of the occlusion culling; drawing without it.");
      this->CullFailed = true;
      return false;
    }
    this->CullFramebuffer->AddDepthAttachment(this->CullDepth);
    this->CullSize[0] = width;
    this->CullSize[1] = height;
  }
  this->CullFramebuffer->DeactivateDrawBuffers(); // depth only
  this->CullFramebuffer->DeactivateReadBuffer();
  const char* description = nullptr;
  if (!vtkOpenGLFramebufferObject::GetFrameBufferStatus(
        vtkOpenGLFramebufferObject::GetDrawMode(), description))
  {
    this->CullFramebuffer->RestorePreviousBindingsAndBuffers();
    vtkErrorMacro(<< "The occlusion culling's framebuffer is incomplete (" << description
                  << "); drawing without it.");
    this->CullFailed = true;
    return false;
  }
  {
    vtkOpenGLState::ScopedglViewport savedViewport(state);
    vtkOpenGLState::ScopedglScissor savedScissor(state);
    vtkOpenGLState::ScopedglDepthMask savedDepthMask(state);
    vtkOpenGLState::ScopedglDepthFunc savedDepthFunc(state);
    vtkOpenGLState::ScopedglEnableDisable savedDepthTest(state, GL_DEPTH_TEST);
    vtkOpenGLState::ScopedglEnableDisable savedCullFace(state, GL_CULL_FACE);
    vtkOpenGLState::ScopedglEnableDisable savedBlend(state, GL_BLEND);
    state->vtkglViewport(0, 0, width, height);
    state->vtkglScissor(0, 0, width, height);
    state->vtkglDepthMask(GL_TRUE);
    state->vtkglEnable(GL_DEPTH_TEST);
    state->vtkglDepthFunc(GL_LESS);
    state->vtkglDisable(GL_CULL_FACE);
    state->vtkglDisable(GL_BLEND);
    state->vtkglClearDepth(1.0);
    state->vtkglClear(GL_DEPTH_BUFFER_BIT);

    float modelView[16];
    float radiusScale = 1.0f;
    this->ComputeTubeMatrices(ren, act, modelView, nullptr, radiusScale);
    program->SetUniformMatrix4x4("tubeMCVC", modelView);
    program->SetUniformf("tubeRadiusScale", radiusScale);
    program->SetUniformMatrix("VCDCMatrix", GetViewToDisplayMatrix(ren));
    program->SetUniformi("cameraParallel", ren->GetActiveCamera()->GetParallelProjection());
    program->SetUniformi("subSegments", this->SubSegments);
    program->SetUniformf("tubeBandScale", static_cast<float>(this->CullingBandScale));
    this->NodesBuffer->Activate(program, "tubeNodes");
    this->SegmentsBuffer->Activate(program, "tubeSegments");
    this->CullVAO->Bind();
    this->QuadIndices->Bind();
    DrawQuads(this->Core->GetNumberOfSegments());
    this->QuadIndices->Release();
    this->CullVAO->Release();
    this->NodesBuffer->Deactivate();
    this->SegmentsBuffer->Deactivate();
  }
  this->CullFramebuffer->RestorePreviousBindingsAndBuffers();
  this->CullOrigin[0] = viewport[0];
  this->CullOrigin[1] = viewport[1];
  return true;
}

//------------------------------------------------------------------------------
void vtkRayCastTubeMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SubSegments: " << this->SubSegments << "\n";
  os << indent << "RootIterations: " << this->RootIterations << "\n";
  os << indent << "RootSamples: " << this->RootSamples << "\n";
  os << indent << "StraightTolerance: " << this->StraightTolerance << "\n";
  os << indent << "OcclusionCulling: " << (this->OcclusionCulling ? "On" : "Off") << "\n";
  os << indent << "LastRenderCulled: " << (this->LastRenderCulled ? "yes" : "no") << "\n";
  os << indent << "CullingBandScale: " << this->CullingBandScale << "\n";
}
