// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLineAmbientOcclusionPass.h"

#include "vtkLineAmbientOcclusionCommon.h"
#include "vtkLineAmbientOcclusionFS.h"
#include "vtkLineAmbientOcclusionTilesVS.h"

#include "vtkCamera.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderUtilities.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkSmartPointer.h"
#include "vtk_glew.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

vtkStandardNewMacro(vtkLineAmbientOcclusionPass);

struct vtkLineAmbientOcclusionPass::vtkInternals
{
  // The delegate's picture.
  vtkSmartPointer<vtkTextureObject> Color;
  vtkSmartPointer<vtkTextureObject> Depth;
  vtkSmartPointer<vtkOpenGLFramebufferObject> Framebuffer;
  // Drawn by the offscreen stages (through StageFramebuffer): the view point
  // of every pixel (RGBA32F), and, with halos only, per block its nearest and
  // farthest view z and the nearest view z within the halo's reach (RG32F).
  vtkSmartPointer<vtkTextureObject> Positions;
  vtkSmartPointer<vtkTextureObject> Blocks;
  vtkSmartPointer<vtkTextureObject> BlockReach;
  vtkSmartPointer<vtkOpenGLFramebufferObject> StageFramebuffer;
  /// The full-screen stages' programs (the halo stage has its own vertex
  /// shader and no quad).
  std::unique_ptr<vtkOpenGLQuadHelper> Quads[StageHalos];
  /// The halo stage's program (the window's shader cache owns it).
  vtkShaderProgram* HaloProgram = nullptr;
  vtkNew<vtkOpenGLVertexArrayObject> TileArray;
  int BlockSize = 4;
  int BlockCount[2] = { 0, 0 };
  /// The halo stage's tiles: 2 x 2 blocks.
  int TileCount[2] = { 0, 0 };

  static vtkSmartPointer<vtkTextureObject> NewTexture(vtkOpenGLRenderWindow* window)
  {
    auto texture = vtkSmartPointer<vtkTextureObject>::New();
    texture->SetContext(window);
    texture->SetWrapS(vtkTextureObject::ClampToEdge);
    texture->SetWrapT(vtkTextureObject::ClampToEdge);
    return texture;
  }

  void Allocate(vtkOpenGLRenderWindow* window, int w, int h)
  {
    if (!this->Color)
    {
      this->Color = NewTexture(window);
      this->Color->Create2D(w, h, 4, VTK_UNSIGNED_CHAR, false);
      this->Depth = NewTexture(window);
      this->Depth->AllocateDepth(w, h, vtkTextureObject::Float32);
      this->Framebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
      this->Framebuffer->SetContext(window);
      this->Positions = NewTexture(window);
      this->Positions->Create2D(w, h, 4, VTK_FLOAT, false);
      this->StageFramebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
      this->StageFramebuffer->SetContext(window);
    }
    this->Color->Resize(w, h);
    this->Depth->Resize(w, h);
    this->Positions->Resize(w, h);
  }

  /// Blocks of `size` pixels for a w x h window.
  void AllocateBlocks(vtkOpenGLRenderWindow* window, int w, int h, int size)
  {
    this->BlockSize = size;
    this->BlockCount[0] = (w + size - 1) / size;
    this->BlockCount[1] = (h + size - 1) / size;
    this->TileCount[0] = (this->BlockCount[0] + 1) / 2;
    this->TileCount[1] = (this->BlockCount[1] + 1) / 2;
    for (vtkSmartPointer<vtkTextureObject>* texture : { &this->Blocks, &this->BlockReach })
    {
      if (!*texture)
      {
        *texture = NewTexture(window);
        (*texture)->Create2D(this->BlockCount[0], this->BlockCount[1], 2, VTK_FLOAT, false);
      }
      (*texture)->Resize(this->BlockCount[0], this->BlockCount[1]);
    }
  }

  void Release(vtkWindow* window)
  {
    for (auto& quad : this->Quads)
    {
      if (quad)
      {
        quad->ReleaseGraphicsResources(window);
        quad.reset();
      }
    }
    this->HaloProgram = nullptr;
    this->TileArray->ReleaseGraphicsResources();
    for (vtkOpenGLFramebufferObject* fbo : { this->Framebuffer, this->StageFramebuffer })
    {
      if (fbo)
      {
        fbo->ReleaseGraphicsResources(window);
      }
    }
    for (vtkTextureObject* texture :
      { this->Color, this->Depth, this->Positions, this->Blocks, this->BlockReach })
    {
      if (texture)
      {
        texture->ReleaseGraphicsResources(window);
      }
    }
    this->Color = nullptr;
    this->Depth = nullptr;
    this->Positions = nullptr;
    this->Blocks = nullptr;
    this->BlockReach = nullptr;
    this->Framebuffer = nullptr;
    this->StageFramebuffer = nullptr;
  }
};

//------------------------------------------------------------------------------
vtkLineAmbientOcclusionPass::vtkLineAmbientOcclusionPass()
  : Internals(new vtkInternals)
{
}

//------------------------------------------------------------------------------
vtkLineAmbientOcclusionPass::~vtkLineAmbientOcclusionPass() = default;

//------------------------------------------------------------------------------
void vtkLineAmbientOcclusionPass::ReleaseGraphicsResources(vtkWindow* w)
{
  this->Superclass::ReleaseGraphicsResources(w);
  this->Internals->Release(w);
}

//------------------------------------------------------------------------------
void vtkLineAmbientOcclusionPass::RenderOffscreen(
  const vtkRenderState* s, vtkOpenGLRenderWindow* window, int w, int h)
{
  vtkInternals& in = *this->Internals;
  in.Allocate(window, w, h);
  vtkOpenGLState* state = window->GetState();
  state->PushFramebufferBindings();
  in.Framebuffer->Bind();
  // The superclass keeps a depth attachment it finds: the delegate draws its
  // depth into the texture the composite reads.
  in.Framebuffer->AddDepthAttachment(in.Depth);
  this->Superclass::RenderDelegate(s, w, h, w, h, in.Framebuffer, in.Color);
  state->PopFramebufferBindings();
}

//------------------------------------------------------------------------------
bool vtkLineAmbientOcclusionPass::RenderStageInto(const vtkRenderState* s,
  vtkOpenGLRenderWindow* window, int stage, vtkTextureObject* input, vtkTextureObject* output,
  int w, int h)
{
  vtkInternals& in = *this->Internals;
  vtkShaderProgram* program = this->ReadyStage(window, stage);
  if (!program)
  {
    return false;
  }
  vtkOpenGLState* state = window->GetState();
  state->PushFramebufferBindings();
  in.StageFramebuffer->Bind();
  in.StageFramebuffer->AddColorAttachment(0, output);
  in.StageFramebuffer->ActivateDrawBuffer(0);
  vtkOpenGLState::ScopedglViewport viewport(state);
  vtkOpenGLState::ScopedglEnableDisable blend(state, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable depthTest(state, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglEnableDisable scissorTest(state, GL_SCISSOR_TEST);
  state->vtkglViewport(0, 0, output->GetWidth(), output->GetHeight());
  state->vtkglDisable(GL_BLEND);
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglDisable(GL_SCISSOR_TEST);
  input->Activate();
  this->SetUniforms(program, s, w, h);
  in.Quads[stage]->Render();
  input->Deactivate();
  state->PopFramebufferBindings();
  return true;
}

//------------------------------------------------------------------------------
vtkShaderProgram* vtkLineAmbientOcclusionPass::ReadyStage(vtkOpenGLRenderWindow* window, int stage)
{
  // The stage's fragment shader: the full-screen template calling its entry
  // point (built once per program).
  const bool fullSearch = this->HaloFullSearch;
  auto fragmentShader = [stage, fullSearch]()
  {
    static const char* const entryPoints[StageHalos + 1] = { "  lineAOPositionsMain();\n",
      "  lineAOBlocksMain();\n", "  lineAOBlockReachMain();\n", "  lineAOCopyMain();\n",
      "  lineAOOcclusionMain();\n", "  lineAOHaloMain();\n" };
    std::string fs = vtkOpenGLRenderUtilities::GetFullScreenQuadFragmentShaderTemplate();
    vtkShaderProgram::Substitute(fs, "//VTK::FSQ::Decl",
      std::string(stage == StageHalos ? "#define LINE_AO_TILES\n" : "") +
        (stage == StageHalos && fullSearch ? "#define LINE_AO_FULL_SEARCH\n" : "") +
        vtkLineAmbientOcclusionCommon + vtkLineAmbientOcclusionFS);
    vtkShaderProgram::Substitute(fs, "//VTK::FSQ::Impl", entryPoints[stage]);
    return fs;
  };
  vtkInternals& in = *this->Internals;
  vtkShaderProgram* program = nullptr;
  if (stage == StageHalos)
  {
    // Drawn tile by tile: its own vertex shader, the same fragment template.
    if (!in.HaloProgram)
    {
      std::string vs = vtkLineAmbientOcclusionTilesVS;
      vtkShaderProgram::Substitute(vs, "//SV::LineAmbientOcclusionCommon::Dec",
        std::string(fullSearch ? "#define LINE_AO_FULL_SEARCH\n" : "") +
          vtkLineAmbientOcclusionCommon);
      in.HaloProgram =
        window->GetShaderCache()->ReadyShaderProgram(vs.c_str(), fragmentShader().c_str(), "");
    }
    else
    {
      window->GetShaderCache()->ReadyShaderProgram(in.HaloProgram);
    }
    program = in.HaloProgram;
    if (program && program->GetCompiled())
    {
      in.TileArray->Bind();
    }
  }
  else
  {
    std::unique_ptr<vtkOpenGLQuadHelper>& quad = in.Quads[stage];
    if (!quad)
    {
      quad.reset(new vtkOpenGLQuadHelper(window, nullptr, fragmentShader().c_str(), ""));
    }
    else
    {
      window->GetShaderCache()->ReadyShaderProgram(quad->Program);
    }
    program = quad->Program;
  }
  if (!program || !program->GetCompiled())
  {
    vtkErrorMacro("Could not build the line ambient occlusion shader program.");
    return nullptr;
  }
  return program;
}

//------------------------------------------------------------------------------
void vtkLineAmbientOcclusionPass::SetUniforms(
  vtkShaderProgram* program, const vtkRenderState* s, int w, int h)
{
  vtkInternals& in = *this->Internals;
  vtkRenderer* ren = s->GetRenderer();
  // View to normalized device coordinates, as the delegate drew them.
  vtkMatrix4x4* projection =
    ren->GetActiveCamera()->GetProjectionTransformMatrix(ren->GetTiledAspectRatio(), -1, 1);
  vtkNew<vtkMatrix4x4> inverse;
  vtkMatrix4x4::Invert(projection, inverse);
  inverse->Transpose();
  const float clipW[2] = { static_cast<float>(projection->GetElement(3, 2)),
    static_cast<float>(projection->GetElement(3, 3)) };
  const double p11 = projection->GetElement(1, 1);

  // The textures the stage reads are the active ones.
  const std::pair<const char*, vtkTextureObject*> samplers[5] = { { "aoColor", in.Color },
    { "aoDepth", in.Depth }, { "aoPositions", in.Positions }, { "aoBlocks", in.Blocks },
    { "aoBlockReach", in.BlockReach } };
  for (const auto& sampler : samplers)
  {
    if (sampler.second && sampler.second->GetTextureUnit() >= 0)
    {
      program->SetUniformi(sampler.first, sampler.second->GetTextureUnit());
    }
  }
  program->SetUniformMatrix("aoInverseProjection", inverse);
  program->SetUniform2f("aoClipW", clipW);
  program->SetUniformf("aoPixelScale", static_cast<float>(2.0 / (p11 * h)));
  const float texel[2] = { 1.0f / static_cast<float>(w), 1.0f / static_cast<float>(h) };
  program->SetUniform2f("aoTexel", texel);
  const int size[2] = { w, h };
  program->SetUniform2i("aoSize", size);

  program->SetUniformi("aoWorldUnits", this->LengthUnits == UNITS_WORLD ? 1 : 0);
  program->SetUniformi("aoLevels", this->Levels);
  program->SetUniformi("aoSamples", this->Samples);
  program->SetUniformf("aoRadius", static_cast<float>(this->Radius));
  program->SetUniformf("aoStrength", static_cast<float>(this->Strength));
  program->SetUniformf("aoBias", static_cast<float>(this->Bias));
  program->SetUniformf("aoHaloWidth", static_cast<float>(this->HaloWidth));
  program->SetUniformf("aoHaloOffset", static_cast<float>(this->HaloDepthOffset));
  program->SetUniformf("aoHaloRange", static_cast<float>(this->HaloDepthRange));
  const double* halo = this->HaloColorFromBackground ? ren->GetBackground() : this->HaloColor;
  const float haloColor[3] = { static_cast<float>(halo[0]), static_cast<float>(halo[1]),
    static_cast<float>(halo[2]) };
  program->SetUniform3f("aoHaloColor", haloColor);
  program->SetUniformi("aoBlockSize", in.BlockSize);
  program->SetUniform2i("aoBlockCount", in.BlockCount);
  program->SetUniform2i("aoTileCount", in.TileCount);
}

//------------------------------------------------------------------------------
int vtkLineAmbientOcclusionPass::HaloReach() const
{
  // The halo's farthest sample lies HaloWidth pixels away, rounded to a pixel
  // (with a margin for the shader's rounding of its distance and direction).
  return static_cast<int>(std::floor(this->HaloWidth * (1.0 + 1.0e-5) + 0.5));
}

//------------------------------------------------------------------------------
bool vtkLineAmbientOcclusionPass::RenderComposite(
  const vtkRenderState* s, vtkOpenGLRenderWindow* window, int w, int h)
{
  vtkInternals& in = *this->Internals;
  const bool occlusion = this->AmbientOcclusion && this->Strength > 0.0;
  const bool halos = this->DepthHalos && this->HaloWidth > 0.0;
  vtkOpenGLState* state = window->GetState();
  vtkOpenGLState::ScopedglEnableDisable blend(state, GL_BLEND);
  vtkOpenGLState::ScopedglBlendFuncSeparate blendFunc(state);
  vtkOpenGLState::ScopedglEnableDisable depthTest(state, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglDepthFunc depthFunc(state);
  vtkOpenGLState::ScopedglDepthMask depthMask(state);
  in.Color->Activate();
  in.Depth->Activate();
  in.Positions->Activate();
  if (in.BlockReach)
  {
    in.BlockReach->Activate();
  }
  // Draws one stage with its program; false if the program failed.
  auto draw = [&](int stage)
  {
    vtkShaderProgram* program = this->ReadyStage(window, stage);
    if (program)
    {
      this->SetUniforms(program, s, w, h);
      if (stage == StageHalos)
      {
        glDrawArrays(GL_TRIANGLES, 0, 6 * in.TileCount[0] * in.TileCount[1]);
        in.TileArray->Release();
      }
      else
      {
        in.Quads[stage]->Render();
      }
    }
    return program != nullptr;
  };
  bool drawn = true;

  // 1. Color and depth replace what the framebuffer holds in the viewport.
  state->vtkglDisable(GL_BLEND);
  state->vtkglEnable(GL_DEPTH_TEST);
  state->vtkglDepthFunc(GL_ALWAYS);
  state->vtkglDepthMask(GL_TRUE);
  drawn = draw(StageCopy);

  // 2. The occlusion factor multiplies the color where there is geometry: the
  // quad lies on the far plane (depth range [1, 1]) and passes the depth test
  // only in front of what is nearer, so background pixels are never shaded.
  if (drawn && occlusion)
  {
    GLfloat range[2];
    glGetFloatv(GL_DEPTH_RANGE, range);
    glDepthRange(1.0, 1.0);
    state->vtkglDepthFunc(GL_GREATER);
    state->vtkglDepthMask(GL_FALSE);
    state->vtkglEnable(GL_BLEND);
    state->vtkglBlendFuncSeparate(GL_ZERO, GL_SRC_COLOR, GL_ZERO, GL_ONE);
    drawn = draw(StageOcclusion);
    glDepthRange(range[0], range[1]);
  }

  // 3. Halos, over geometry and background alike, blended by their coverage,
  // on the tiles that can hold one.
  if (drawn && halos)
  {
    state->vtkglDisable(GL_DEPTH_TEST);
    state->vtkglDepthMask(GL_FALSE);
    state->vtkglEnable(GL_BLEND);
    state->vtkglBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
    drawn = draw(StageHalos);
  }
  if (in.BlockReach)
  {
    in.BlockReach->Deactivate();
  }
  in.Positions->Deactivate();
  in.Depth->Deactivate();
  in.Color->Deactivate();
  return drawn;
}

//------------------------------------------------------------------------------
void vtkLineAmbientOcclusionPass::Render(const vtkRenderState* s)
{
  vtkOpenGLClearErrorMacro();
  this->NumberOfRenderedProps = 0;
  if (!this->DelegatePass)
  {
    vtkWarningMacro("No delegate pass: nothing is drawn.");
    return;
  }
  vtkRenderer* ren = s->GetRenderer();
  vtkOpenGLRenderWindow* window = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  const bool enabled = this->AmbientOcclusion || (this->DepthHalos && this->HaloWidth > 0.0);
  if (!window || ren->GetSelector() || !enabled)
  {
    // Picking draws ids, not colors: nothing to shade.
    this->DelegatePass->Render(s);
    this->NumberOfRenderedProps = this->DelegatePass->GetNumberOfRenderedProps();
    return;
  }

  int x = 0, y = 0, w = 0, h = 0;
  if (vtkFrameBufferObjectBase* fbo = s->GetFrameBuffer())
  {
    fbo->GetLastSize(w, h);
  }
  else
  {
    ren->GetTiledSizeAndOrigin(&w, &h, &x, &y);
  }
  if (w <= 0 || h <= 0)
  {
    return;
  }
  this->RenderOffscreen(s, window, w, h);
  vtkInternals& in = *this->Internals;
  bool ready = this->RenderStageInto(s, window, StagePositions, in.Depth, in.Positions, w, h);
  if (ready && this->DepthHalos && this->HaloWidth > 0.0)
  {
    // Blocks at least the halo's reach: the samples of a block's pixels read
    // only the 3 x 3 blocks around it.
    in.AllocateBlocks(window, w, h, std::max(4, this->HaloReach()));
    ready = this->RenderStageInto(s, window, StageBlocks, in.Positions, in.Blocks, w, h) &&
      this->RenderStageInto(s, window, StageBlockReach, in.Blocks, in.BlockReach, w, h);
  }

  vtkOpenGLState* state = window->GetState();
  vtkOpenGLState::ScopedglViewport viewport(state);
  vtkOpenGLState::ScopedglScissor scissor(state);
  state->vtkglViewport(x, y, w, h);
  state->vtkglScissor(x, y, w, h);
  if (ready)
  {
    this->RenderComposite(s, window, w, h);
  }
  vtkOpenGLCheckErrorMacro("failed after Render");
}

//------------------------------------------------------------------------------
void vtkLineAmbientOcclusionPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "AmbientOcclusion: " << this->AmbientOcclusion << "\n";
  os << indent << "LengthUnits: " << (this->LengthUnits == UNITS_WORLD ? "world" : "pixels")
     << "\n";
  os << indent << "Radius: " << this->Radius << "\n";
  os << indent << "Levels: " << this->Levels << "\n";
  os << indent << "Samples: " << this->Samples << "\n";
  os << indent << "Strength: " << this->Strength << "\n";
  os << indent << "Bias: " << this->Bias << "\n";
  os << indent << "DepthHalos: " << this->DepthHalos << "\n";
  os << indent << "HaloWidth: " << this->HaloWidth << "\n";
  os << indent << "HaloDepthOffset: " << this->HaloDepthOffset << "\n";
  os << indent << "HaloDepthRange: " << this->HaloDepthRange << "\n";
  os << indent << "HaloColor: " << this->HaloColor[0] << " " << this->HaloColor[1] << " "
     << this->HaloColor[2] << "\n";
  os << indent << "HaloColorFromBackground: " << this->HaloColorFromBackground << "\n";
}
