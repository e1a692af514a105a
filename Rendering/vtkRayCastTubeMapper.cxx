// SPDX-License-Identifier: BSD-3-Clause
#include "vtkRayCastTubeMapper.h"

#include "vtkSplineTubeCore.h"
#include "vtkSplineTubeVisibility.h"
#include "vtkSplineVizGPUBuffer.h"

#include "vtkActor.h"
#include "vtkFloatArray.h"
#include "vtkHardwareSelector.h"
#include "vtkIdTypeArray.h"
#include "vtkObjectFactory.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkOpenGLCamera.h"
#include "vtkOpenGLHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkRenderer.h"
#include "vtkShader.h"
#include "vtkShaderProgram.h"
#include "vtkTypeUInt32Array.h"
#include "vtkUnsignedCharArray.h"

#include "vtkRayCastTubeFS.h"
#include "vtkRayCastTubeGS.h"
#include "vtkRayCastTubeVS.h"
#include "vtkSplineVizShaderPrelude.h"
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
  return vtkSplineVizShaderPrelude::Get() + vtkSplineTubeMathShared;
}
}

//------------------------------------------------------------------------------
vtkRayCastTubeMapper::vtkRayCastTubeMapper()
  : ChunkList(new vtkSplineVizGPUBuffer)
{
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
  return this->GetTubeBuffersSize() + this->ChunkList->GetNumberOfBytes();
}

//------------------------------------------------------------------------------
void vtkRayCastTubeMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  this->ChunkList->ReleaseGraphicsResources(window);
  this->Superclass::ReleaseGraphicsResources(window);
}

//------------------------------------------------------------------------------
void vtkRayCastTubeMapper::UploadTubes(vtkOpenGLRenderWindow* window)
{
  // The shared tubes buffer holds everything the ray caster reads.
  this->UploadTubeBuffers(window);
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
  std::string GSSource = shaders[vtkShader::Geometry]->GetSource();
  std::string FSSource = shaders[vtkShader::Fragment]->GetSource();
  const std::string math = TubeMathSource();

  // The vertex stage reads the tubes buffer and, with scalar coloring, makes
  // the color spline's ends, passed flat to the fragments.
  vtkShaderProgram::Substitute(VSSource, "//SV::SplineTubeMath::Dec",
    math + GetTubeNodesDeclarations() + GetTubeColorDeclarations());
  std::string declarations = vtkRayCastTubeFS;
  if (this->BuildingStraightProgram)
  {
    // The chunks every segment of which is straight: no root finding.
    declarations = "#define SV_STRAIGHT_CHUNKS\n" + declarations;
  }
  vtkShaderProgram::Substitute(declarations, "//SV::SplineTubeMath::Dec", math);
  const int colorMode = this->GetTubeColorMode();
  if (colorMode == 2)
  {
    declarations += GetTubeDirectionColorDeclarations();
  }
  if (colorMode != 0)
  {
    vtkShaderProgram::Substitute(GSSource, "//SV::TubeColor::GSDec",
      "flat out vec4 tubeC0GSOutput;\n"
      "flat out vec4 tubeD0GSOutput;\n"
      "flat out vec4 tubeC1GSOutput;\n"
      "flat out vec4 tubeD1GSOutput;\n");
    vtkShaderProgram::Substitute(GSSource, "//SV::TubeColor::GSImpl",
      "tubeC0GSOutput = tubeRect[0].c0;\n"
      "    tubeD0GSOutput = tubeRect[0].d0;\n"
      "    tubeC1GSOutput = tubeRect[0].c1;\n"
      "    tubeD1GSOutput = tubeRect[0].d1;\n");
    declarations += "flat in vec4 tubeC0VSOutput;\n"
                    "flat in vec4 tubeD0VSOutput;\n"
                    "flat in vec4 tubeC1VSOutput;\n"
                    "flat in vec4 tubeD1VSOutput;\n";
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
  std::string depth =
    "  vec3 tubeHitVC;\n"
    "  vec3 normalVCVSOutput;\n"
    "  float tubeT;\n"
    "  bool tubeHit = tubeRayCast(vertexVC.xyz, tubeHitVC, normalVCVSOutput, tubeT);\n"
    "  if (!tubeHit)\n"
    "  {\n"
    "    discard;\n"
    "  }\n"
    "  if (tubeHit) // the rest of main(), closed at its end\n"
    "  {\n"
    "  vertexVC = vec4(tubeHitVC, 1.0);\n"
    "  //SV::TubeClip::Impl\n"
    "  vec4 tubeHitDC = VCDCMatrix * vertexVC;\n"
    "  gl_FragDepth = 0.5 * (gl_DepthRange.diff * (tubeHitDC.z / tubeHitDC.w) +\n"
    "    gl_DepthRange.near + gl_DepthRange.far);\n";
  if (colorMode == 1)
  {
    depth += "  vec4 tubeColor = clamp(svHermite(tubeC0VSOutput, tubeD0VSOutput, tubeC1VSOutput,\n"
             "    tubeD1VSOutput, tubeT), 0.0, 1.0);\n";
  }
  else if (colorMode == 2)
  {
    // The ends carry the position spline: its tangent at the hit.
    depth += "  vec4 tubeColor = tubeDirectionColor(svHermiteDerivative(tubeC0VSOutput,\n"
             "    tubeD0VSOutput, tubeC1VSOutput, tubeD1VSOutput, tubeT).xyz);\n";
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
  shaders[vtkShader::Geometry]->SetSource(GSSource);
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
  this->ReplaceShaderTubeClip(FSSource, "//SV::TubeClip::Impl");
  shaders[vtkShader::Fragment]->SetSource(FSSource);
}

//------------------------------------------------------------------------------
void vtkRayCastTubeMapper::SetMapperShaderParameters(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  this->Superclass::SetMapperShaderParameters(cellBO, ren, act);
  vtkShaderProgram* program = cellBO.Program;
  program->SetUniformi("subSegments", this->SubSegments);
  program->SetUniformi("tubeChunkSegments", vtkSplineTubeCore::ChunkSegments);
  program->SetUniformi("tubeHaveColors", this->GetTubeColorMode());
  program->SetUniformi("rootIterations", this->RootIterations);
  program->SetUniformi("rootSamples", this->RootSamples);
  program->SetUniformf("tubeStraightTolerance", static_cast<float>(this->StraightTolerance));
  program->SetUniformi("tubeSingleLayer", act->IsRenderingTranslucentPolygonalGeometry() ? 1 : 0);
}

//------------------------------------------------------------------------------
void vtkRayCastTubeMapper::SetCameraShaderParameters(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  this->Superclass::SetCameraShaderParameters(cellBO, ren, act);
  double range[2];
  ren->GetActiveCamera()->GetClippingRange(range);
  cellBO.Program->SetUniformf("tubeNearPlane", static_cast<float>(range[0]));
  // For the straightness tolerance.
  cellBO.Program->SetUniformf("tubePixelScale", static_cast<float>(GetPixelScale(ren)));
}

//------------------------------------------------------------------------------
void vtkRayCastTubeMapper::RenderPieceDraw(vtkRenderer* ren, vtkActor* act)
{
  this->LastStraightChunks = 0;
  this->LastRootFindingChunks = 0;
  if (this->Core->GetNumberOfSegments() == 0 || this->GetTubeBuffersSize() == 0)
  {
    return;
  }
  vtkOpenGLState* state = static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow())->GetState();
  vtkOpenGLState::ScopedglEnableDisable cull(state, GL_CULL_FACE);
  state->vtkglDisable(GL_CULL_FACE);

  // Which chunks the vertex stage will draw without root finding in this
  // view: those whose every segment is straight there (mode 2: straight to
  // within StraightTolerance of its smallest radius and a quarter pixel, not
  // near the eye), or, with two sub-segments, whose every sub-segment is
  // (mode 1 or better). Decided conservatively, from the chunk's largest
  // straightness (model units, times the view's largest stretch), its
  // smallest pixel (at its sphere's nearest depth) and a margin for the
  // vertex stage's float arithmetic.
  float modelView[16];
  float radiusScale = 1.0f;
  this->ComputeTubeMatrices(ren, act, modelView, nullptr, radiusScale);
  double clipping[2];
  ren->GetActiveCamera()->GetClippingRange(clipping);
  const bool parallel = ren->GetActiveCamera()->GetParallelProjection() != 0;
  const double pixelScale = std::max(GetPixelScale(ren), 1e-300);
  const float* spheres = this->Core->GetChunkSpheres()->GetPointer(0);
  const float* straightness = this->Core->GetChunkStraightness()->GetPointer(0);
  const double margin = this->StraightChunkMargin;
  auto isStraight = [&](std::uint32_t c, double scale)
  {
    const float* s = spheres + 4 * c;
    const double zNear = modelView[2] * s[0] + modelView[6] * s[1] + modelView[10] * s[2] +
      modelView[14] + scale * s[3];
    if (!parallel && zNear >= -clipping[0] * (1.0 + 1e-3))
    {
      return false; // near the eye: root finding
    }
    const double pixel = parallel ? 1.0 / pixelScale : -zNear / pixelScale;
    const double maxError = margin * 0.25 * pixel;
    const double maxRatio = margin * this->StraightTolerance * radiusScale;
    const float* e = straightness + 4 * c;
    return (e[0] * scale <= maxError && e[1] * scale <= maxRatio) ||
      (this->SubSegments == 2 && e[2] * scale <= maxError && e[3] * scale <= maxRatio);
  };

  std::vector<std::uint32_t> straightChunks;
  std::vector<std::uint32_t> otherChunks;
  this->DrawVisibleChunks(ren, act,
    [&](const std::vector<std::uint32_t>& chunks)
    {
      const bool split = this->StraightChunkProgram && this->StraightTolerance > 0.0;
      const double scale = this->Visibility->GetViewScale();
      straightChunks.clear();
      otherChunks.clear();
      for (std::uint32_t c : chunks)
      {
        (split && isStraight(c, scale) ? straightChunks : otherChunks).push_back(c);
      }
      this->DrawChunkList(ren, act, this->Primitives[PrimitiveTriStrips], true, straightChunks);
      this->DrawChunkList(ren, act, this->Primitives[PrimitiveTris], false, otherChunks);
    });
  this->ChunkList->Deactivate();
  this->DeactivateTubeBuffers();
}

//------------------------------------------------------------------------------
void vtkRayCastTubeMapper::DrawChunkList(vtkRenderer* ren, vtkActor* act, vtkOpenGLHelper& helper,
  bool straight, const std::vector<std::uint32_t>& chunks)
{
  if (chunks.empty())
  {
    return;
  }
  this->BuildingStraightProgram = straight;
  this->UpdateShaders(helper, ren, act);
  this->BuildingStraightProgram = false;
  if (!helper.Program)
  {
    return;
  }
  // UpdateShaders() may have released the VAO after binding it (new
  // program); the draw has no attributes but core profiles need a VAO bound.
  helper.VAO->Bind();
  (straight ? this->LastStraightChunks : this->LastRootFindingChunks) +=
    static_cast<vtkIdType>(chunks.size());

  // One point per sub-segment of the chunks: their list (first segment,
  // count) read by the vertex stage; one rectangle (4-vertex strip) per
  // sub-segment, either winding.
  const vtkTypeUInt32* chunkFirst = this->Core->GetChunkFirstSegments()->GetPointer(0);
  const vtkTypeUInt32* chunkTube = this->Core->GetChunkTubes()->GetPointer(0);
  auto* window = static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow());
  std::vector<vtkTypeUInt32> list(2 * chunks.size());
  for (size_t i = 0; i < chunks.size(); ++i)
  {
    list[2 * i] = chunkFirst[chunks[i]] + chunkTube[chunks[i]]; // its first node
    list[2 * i + 1] = chunkFirst[chunks[i] + 1] - chunkFirst[chunks[i]];
  }
  if (!this->ChunkList->Upload(window, list.data(), chunks.size(), 2, VTK_TYPE_UINT32, GL_RG32UI))
  {
    vtkErrorMacro(<< "Could not upload the chunk list: " << this->ChunkList->GetLastUploadError());
    return;
  }
  this->ChunkList->Activate(helper.Program, "tubeChunkList");
  // In draws of at most DrawChunks chunks, each flushed: a software
  // rasterizer (Mesa llvmpipe) bins a frame's primitives until a flush,
  // about 2 kB per chunk; without flushes a million chunks take gigabytes.
  const GLint perChunk = vtkSplineTubeCore::ChunkSegments * this->SubSegments;
  for (size_t first = 0; first < chunks.size(); first += DrawChunks)
  {
    const size_t count = std::min<size_t>(DrawChunks, chunks.size() - first);
    glDrawArrays(
      GL_POINTS, static_cast<GLint>(first) * perChunk, static_cast<GLsizei>(count) * perChunk);
    if (first + count < chunks.size())
    {
      glFinish();
    }
  }
}

//------------------------------------------------------------------------------
void vtkRayCastTubeMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SubSegments: " << this->SubSegments << "\n";
  os << indent << "RootIterations: " << this->RootIterations << "\n";
  os << indent << "RootSamples: " << this->RootSamples << "\n";
  os << indent << "StraightTolerance: " << this->StraightTolerance << "\n";
  os << indent << "StraightChunkProgram: " << (this->StraightChunkProgram ? "On" : "Off") << "\n";
  os << indent << "StraightChunkMargin: " << this->StraightChunkMargin << "\n";
}
