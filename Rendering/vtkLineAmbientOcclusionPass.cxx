// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLineAmbientOcclusionPass.h"

#include "vtkLineAmbientOcclusionFS.h"

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
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkSmartPointer.h"
#include "vtk_glew.h"

#include <string>

vtkStandardNewMacro(vtkLineAmbientOcclusionPass);

struct vtkLineAmbientOcclusionPass::vtkInternals
{
  vtkSmartPointer<vtkTextureObject> Color;
  vtkSmartPointer<vtkTextureObject> Depth;
  vtkSmartPointer<vtkOpenGLFramebufferObject> Framebuffer;
  std::unique_ptr<vtkOpenGLQuadHelper> Quad;

  void Allocate(vtkOpenGLRenderWindow* window, int w, int h)
  {
    if (!this->Color)
    {
      this->Color = vtkSmartPointer<vtkTextureObject>::New();
      this->Color->SetContext(window);
      this->Color->SetWrapS(vtkTextureObject::ClampToEdge);
      this->Color->SetWrapT(vtkTextureObject::ClampToEdge);
      this->Color->Create2D(w, h, 4, VTK_UNSIGNED_CHAR, false);
      this->Depth = vtkSmartPointer<vtkTextureObject>::New();
      this->Depth->SetContext(window);
      this->Depth->SetWrapS(vtkTextureObject::ClampToEdge);
      this->Depth->SetWrapT(vtkTextureObject::ClampToEdge);
      this->Depth->AllocateDepth(w, h, vtkTextureObject::Float32);
      this->Framebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
      this->Framebuffer->SetContext(window);
    }
    this->Color->Resize(w, h);
    this->Depth->Resize(w, h);
  }

  void Release(vtkWindow* window)
  {
    if (this->Quad)
    {
      this->Quad->ReleaseGraphicsResources(window);
      this->Quad.reset();
    }
    if (this->Framebuffer)
    {
      this->Framebuffer->ReleaseGraphicsResources(window);
    }
    if (this->Color)
    {
      this->Color->ReleaseGraphicsResources(window);
      this->Depth->ReleaseGraphicsResources(window);
    }
    this->Color = nullptr;
    this->Depth = nullptr;
    this->Framebuffer = nullptr;
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
bool vtkLineAmbientOcclusionPass::RenderComposite(
  const vtkRenderState* s, vtkOpenGLRenderWindow* window, int w, int h)
{
  vtkInternals& in = *this->Internals;
  if (!in.Quad)
  {
    std::string fs = vtkOpenGLRenderUtilities::GetFullScreenQuadFragmentShaderTemplate();
    vtkShaderProgram::Substitute(fs, "//VTK::FSQ::Decl", vtkLineAmbientOcclusionFS);
    vtkShaderProgram::Substitute(fs, "//VTK::FSQ::Impl", "  lineAOMain();\n");
    in.Quad.reset(new vtkOpenGLQuadHelper(window, nullptr, fs.c_str(), ""));
  }
  else
  {
    window->GetShaderCache()->ReadyShaderProgram(in.Quad->Program);
  }
  vtkShaderProgram* program = in.Quad->Program;
  if (!program || !program->GetCompiled())
  {
    vtkErrorMacro("Could not build the line ambient occlusion shader program.");
    return false;
  }

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

  in.Color->Activate();
  in.Depth->Activate();
  program->SetUniformi("aoColor", in.Color->GetTextureUnit());
  program->SetUniformi("aoDepth", in.Depth->GetTextureUnit());
  program->SetUniformMatrix("aoInverseProjection", inverse);
  program->SetUniform2f("aoClipW", clipW);
  program->SetUniformf("aoPixelScale", static_cast<float>(2.0 / (p11 * h)));
  const float texel[2] = { 1.0f / static_cast<float>(w), 1.0f / static_cast<float>(h) };
  program->SetUniform2f("aoTexel", texel);
  const int size[2] = { w, h };
  program->SetUniform2i("aoSize", size);

  program->SetUniformi("aoWorldUnits", this->LengthUnits == UNITS_WORLD ? 1 : 0);
  program->SetUniformi("aoEnabled", this->AmbientOcclusion ? 1 : 0);
  program->SetUniformi("aoLevels", this->Levels);
  program->SetUniformi("aoSamples", this->Samples);
  program->SetUniformf("aoRadius", static_cast<float>(this->Radius));
  program->SetUniformf("aoStrength", static_cast<float>(this->Strength));
  program->SetUniformf("aoBias", static_cast<float>(this->Bias));
  program->SetUniformi("aoHalo", this->DepthHalos ? 1 : 0);
  program->SetUniformf("aoHaloWidth", static_cast<float>(this->HaloWidth));
  program->SetUniformf("aoHaloOffset", static_cast<float>(this->HaloDepthOffset));
  program->SetUniformf("aoHaloRange", static_cast<float>(this->HaloDepthRange));
  const double* halo = this->HaloColorFromBackground ? ren->GetBackground() : this->HaloColor;
  const float haloColor[3] = { static_cast<float>(halo[0]), static_cast<float>(halo[1]),
    static_cast<float>(halo[2]) };
  program->SetUniform3f("aoHaloColor", haloColor);

  // Color and depth replace what the framebuffer holds in the viewport.
  vtkOpenGLState* state = window->GetState();
  vtkOpenGLState::ScopedglEnableDisable blend(state, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable depthTest(state, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglDepthFunc depthFunc(state);
  vtkOpenGLState::ScopedglDepthMask depthMask(state);
  state->vtkglDisable(GL_BLEND);
  state->vtkglEnable(GL_DEPTH_TEST);
  state->vtkglDepthFunc(GL_ALWAYS);
  state->vtkglDepthMask(GL_TRUE);
  in.Quad->Render();
  in.Depth->Deactivate();
  in.Color->Deactivate();
  return true;
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

  vtkOpenGLState* state = window->GetState();
  vtkOpenGLState::ScopedglViewport viewport(state);
  vtkOpenGLState::ScopedglScissor scissor(state);
  state->vtkglViewport(x, y, w, h);
  state->vtkglScissor(x, y, w, h);
  this->RenderComposite(s, window, w, h);
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
