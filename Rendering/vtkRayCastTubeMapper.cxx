#include "vtkRayCastTubeMapper.h"

#include "vtkSplineTubeCore.h"
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
  std::string FSSource = shaders[vtkShader::Fragment]->GetSource();
  const std::string math = TubeMathSource();

  vtkShaderProgram::Substitute(VSSource, "//VTK::SplineTubeMath::Dec", math);

  std::string declarations = vtkRayCastTubeFS;
  vtkShaderProgram::Substitute(declarations, "//VTK::SplineTubeMath::Dec", math);
  if (this->HaveColors)
  {
    declarations += GetTubeColorDeclarations();
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
  if (this->Core->GetNumberOfSegments() == 0 || this->GetTubeBuffersSize() == 0)
  {
    return;
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

  // One point per sub-segment (gl_VertexID = SubSegments * segment + k):
  // the visible chunks' segment ranges, consecutive chunks merged.
  const vtkTypeUInt32* chunkFirst = this->Core->GetChunkFirstSegments()->GetPointer(0);
  const GLint sub = this->SubSegments;
  std::vector<GLint> firsts;
  std::vector<GLsizei> counts;
  this->DrawVisibleChunks(ren, act,
    [&](const std::vector<std::uint32_t>& chunks)
    {
      firsts.clear();
      counts.clear();
      for (std::uint32_t c : chunks)
      {
        const GLint first = static_cast<GLint>(chunkFirst[c]) * sub;
        const GLsizei count = static_cast<GLsizei>(chunkFirst[c + 1] - chunkFirst[c]) * sub;
        if (!firsts.empty() && firsts.back() + counts.back() == first)
        {
          counts.back() += count;
        }
        else
        {
          firsts.push_back(first);
          counts.push_back(count);
        }
      }
      glMultiDrawArrays(
        GL_POINTS, firsts.data(), counts.data(), static_cast<GLsizei>(firsts.size()));
    });
  this->DeactivateTubeBuffers();
}

//------------------------------------------------------------------------------
void vtkRayCastTubeMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SubSegments: " << this->SubSegments << "\n";
  os << indent << "RootIterations: " << this->RootIterations << "\n";
  os << indent << "RootSamples: " << this->RootSamples << "\n";
  os << indent << "StraightTolerance: " << this->StraightTolerance << "\n";
}
