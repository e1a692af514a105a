// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLRSplineVolumeMapper.h"

#include "vtkLRSplineField.h"
#include "vtkLRSplineVolumePreparer.h"
#include "vtkLRSplineVolumeShaderBuilder.h"
#include "vtkSplineVizGPUBuffer.h"

#include "vtkAlgorithmOutput.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkColorTransferFunction.h"
#include "vtkCommand.h"
#include "vtkContourValues.h"
#include "vtkDataArray.h"
#include "vtkDataObject.h"
#include "vtkExecutive.h"
#include "vtkInformation.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMath.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLCamera.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPlane.h"
#include "vtkPlaneCollection.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkTimeStamp.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <vtk_glew.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <vector>

vtkStandardNewMacro(vtkLRSplineVolumeMapper);

namespace
{
// Binds the positions of `buffer` (attribute vertexMC, 3 floats) to
// `program` in `array` (created on first use) unless `bound`, the program it
// was last bound to, is that program already.
void BindPositions(vtkSmartPointer<vtkOpenGLVertexArrayObject>& array, vtkShaderProgram*& bound,
  vtkShaderProgram* program, vtkOpenGLBufferObject* buffer)
{
  if (!array)
  {
    array = vtkSmartPointer<vtkOpenGLVertexArrayObject>::New();
  }
  if (bound != program)
  {
    array->ShaderProgramChanged();
    array->Bind();
    array->AddAttributeArray(
      program, buffer, "vertexMC", 0, 3 * sizeof(float), VTK_FLOAT, 3, false);
    bound = program;
  }
}

// Draws the back faces of the proxy box (`array`, 36 vertices) with the
// fragments blended premultiplied (else written as they are: the sample
// counts) and the depth test left to the rays (the opaque depth texture):
// every pixel the volume may cover runs its ray once, also with the camera
// inside the box; the isosurfaces (writeDepth) write their depth. The
// state is restored after.
void DrawProxyBox(
  vtkOpenGLState* state, vtkOpenGLVertexArrayObject* array, bool blend, bool writeDepth)
{
  vtkOpenGLState::ScopedglEnableDisable savedCull(state, GL_CULL_FACE);
  vtkOpenGLState::ScopedglEnableDisable savedBlend(state, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable savedDepthTest(state, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglDepthMask savedDepthMask(state);
  vtkOpenGLState::ScopedglDepthFunc savedDepthFunc(state);
  vtkOpenGLState::ScopedglBlendFuncSeparate savedBlendFunc(state);
  state->vtkglEnable(GL_CULL_FACE);
  state->vtkglCullFace(GL_FRONT);
  if (blend)
  {
    state->vtkglEnable(GL_BLEND);
    state->vtkglBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  }
  else
  {
    state->vtkglDisable(GL_BLEND);
  }
  state->vtkglEnable(GL_DEPTH_TEST);
  state->vtkglDepthFunc(GL_ALWAYS);
  state->vtkglDepthMask(writeDepth ? GL_TRUE : GL_FALSE);
  array->Bind();
  glDrawArrays(GL_TRIANGLES, 0, 36);
  array->Release();
  state->vtkglCullFace(GL_BACK);
}

// The limits the shaders are compiled for.
constexpr int MaximumIsoValues = vtkLRSplineVolumeShaderBuilder::MaximumIsoValues;
constexpr int MaximumClipPlanes = vtkLRSplineVolumeShaderBuilder::MaximumClipPlanes;
constexpr int MaximumLights = vtkLRSplineVolumeShaderBuilder::MaximumLights;
constexpr int TransferFunctionSize = 1024;

// Set a GLSL mat4 from a row-major vtkMatrix4x4 (vtkShaderProgram uploads
// the elements as they are, i.e. expects the transpose).
void SetMatrix(vtkShaderProgram* program, const char* name, vtkMatrix4x4* m)
{
  float columnMajor[16];
  for (int r = 0; r < 4; ++r)
  {
    for (int c = 0; c < 4; ++c)
    {
      columnMajor[4 * c + r] = static_cast<float>(m->GetElement(r, c));
    }
  }
  program->SetUniformMatrix4x4(name, columnMajor);
}

// The lights (VTK's volume mappers sum them): every switched-on light,
// directional (toward the light from its focal point; direction and
// intensity times color), at most MaximumLights; none: a headlight.
std::vector<std::array<float, 6>> CollectLights(vtkRenderer* ren)
{
  std::vector<std::array<float, 6>> lightList;
  vtkLightCollection* lights = ren->GetLights();
  lights->InitTraversal();
  for (vtkLight* l = lights->GetNextItem(); l && static_cast<int>(lightList.size()) < MaximumLights;
       l = lights->GetNextItem())
  {
    if (!l->GetSwitch() || !(l->GetIntensity() > 0))
    {
      continue;
    }
    double p[3], f[3], toLight[3];
    l->GetTransformedPosition(p);
    l->GetTransformedFocalPoint(f);
    vtkMath::Subtract(p, f, toLight);
    if (vtkMath::Normalize(toLight) == 0.0)
    {
      continue;
    }
    const double* c = l->GetDiffuseColor();
    const double i = l->GetIntensity();
    lightList.push_back({ static_cast<float>(toLight[0]), static_cast<float>(toLight[1]),
      static_cast<float>(toLight[2]), static_cast<float>(c[0] * i), static_cast<float>(c[1] * i),
      static_cast<float>(c[2] * i) });
  }
  if (lightList.empty())
  {
    double toLight[3];
    vtkMath::Subtract(
      ren->GetActiveCamera()->GetPosition(), ren->GetActiveCamera()->GetFocalPoint(), toLight);
    vtkMath::Normalize(toLight);
    lightList.push_back({ static_cast<float>(toLight[0]), static_cast<float>(toLight[1]),
      static_cast<float>(toLight[2]), 1.0f, 1.0f, 1.0f });
  }
  return lightList;
}
}

//------------------------------------------------------------------------------
struct vtkLRSplineVolumeMapper::vtkInternals
{
  // CPU side: the spline as flat arrays, rebuilt when the input or the
  // search settings change (Valid: those and the mapper's options are fine).
  vtkNew<vtkLRSplineVolumePreparer> Preparer;
  bool Valid = false;
  std::string Error;
  std::string ReportedError;
  std::string FailedShader;
  bool Quiet = false; // UpdateSpline() from GetBounds(): no error report
  // The shaders' sources for the current options.
  vtkNew<vtkLRSplineVolumeShaderBuilder> Shaders;

  // GPU side.
  vtkOpenGLRenderWindow* Window = nullptr;
  vtkTimeStamp UploadTime;
  vtkSplineVizGPUBuffer HeadsBuffer, NodeWordsBuffer, NodeSplitsBuffer, OctreeBuffer, BoxesBuffer,
    OffsetsBuffer, CoefficientsBuffer;
  vtkSmartPointer<vtkTextureObject> TransferTexture;
  std::string TransferKey;
  double TransferRange[2] = { 0, 1 };
  vtkSmartPointer<vtkTextureObject> DepthTexture;
  vtkSmartPointer<vtkTextureObject> DepthColor;
  vtkSmartPointer<vtkOpenGLFramebufferObject> DepthFramebuffer;
  bool DepthCopyWarned = false;
  vtkSmartPointer<vtkTextureObject> TrimTextures[2];
  vtkSmartPointer<vtkOpenGLFramebufferObject> TrimFramebuffers[2];
  vtkSmartPointer<vtkOpenGLBufferObject> CubeBuffer;
  vtkSmartPointer<vtkOpenGLVertexArrayObject> CubeArray;
  vtkShaderProgram* CubeArrayProgram = nullptr;
  vtkSmartPointer<vtkOpenGLBufferObject> TrimBuffer;
  vtkSmartPointer<vtkOpenGLVertexArrayObject> TrimArray;
  vtkShaderProgram* TrimArrayProgram = nullptr;
  vtkIdType TrimVertices = 0;
  std::string TrimKey;
  double CubeBox[6] = { 0, 0, 0, 0, 0, 0 };
  // Continuation passes: final color and depth, two sets of ray state
  // (accumulated color, ray, extra), their framebuffers, the final draw.
  vtkSmartPointer<vtkTextureObject> PassFinal[2];
  vtkSmartPointer<vtkTextureObject> PassState[2][3];
  vtkSmartPointer<vtkOpenGLFramebufferObject> PassFramebuffers[2];
  vtkSmartPointer<vtkOpenGLVertexArrayObject> CompositeArray;
  vtkShaderProgram* CompositeArrayProgram = nullptr;
  int Passes = 1;

  bool Fail(const std::string& message)
  {
    this->Valid = false;
    this->Error = message;
    return false;
  }

  void ReleaseGPU(vtkWindow* window)
  {
    for (vtkSplineVizGPUBuffer* b :
      { &this->HeadsBuffer, &this->NodeWordsBuffer, &this->NodeSplitsBuffer, &this->OctreeBuffer,
        &this->BoxesBuffer, &this->OffsetsBuffer, &this->CoefficientsBuffer })
    {
      b->ReleaseGraphicsResources(window);
    }
    for (vtkTextureObject* t : { this->TransferTexture.Get(), this->DepthTexture.Get(),
           this->DepthColor.Get(), this->TrimTextures[0].Get(), this->TrimTextures[1].Get(),
           this->PassFinal[0].Get(), this->PassFinal[1].Get(), this->PassState[0][0].Get(),
           this->PassState[0][1].Get(), this->PassState[0][2].Get(), this->PassState[1][0].Get(),
           this->PassState[1][1].Get(), this->PassState[1][2].Get() })
    {
      if (t)
      {
        t->ReleaseGraphicsResources(window);
      }
    }
    for (vtkOpenGLFramebufferObject* f : { this->DepthFramebuffer.Get(),
           this->TrimFramebuffers[0].Get(), this->TrimFramebuffers[1].Get(),
           this->PassFramebuffers[0].Get(), this->PassFramebuffers[1].Get() })
    {
      if (f)
      {
        f->ReleaseGraphicsResources(window);
      }
    }
    for (vtkOpenGLBufferObject* b : { this->CubeBuffer.Get(), this->TrimBuffer.Get() })
    {
      if (b)
      {
        b->ReleaseGraphicsResources();
      }
    }
    for (vtkOpenGLVertexArrayObject* a :
      { this->CubeArray.Get(), this->TrimArray.Get(), this->CompositeArray.Get() })
    {
      if (a)
      {
        a->ReleaseGraphicsResources();
      }
    }
    this->TransferTexture = nullptr;
    this->DepthTexture = nullptr;
    this->DepthColor = nullptr;
    this->DepthFramebuffer = nullptr;
    this->TrimTextures[0] = this->TrimTextures[1] = nullptr;
    this->TrimFramebuffers[0] = this->TrimFramebuffers[1] = nullptr;
    this->CubeBuffer = nullptr;
    this->CubeArray = nullptr;
    this->CubeArrayProgram = nullptr;
    this->TrimBuffer = nullptr;
    this->TrimArray = nullptr;
    this->TrimArrayProgram = nullptr;
    for (int k = 0; k < 2; ++k)
    {
      this->PassFinal[k] = nullptr;
      this->PassFramebuffers[k] = nullptr;
      for (auto& t : this->PassState[k])
      {
        t = nullptr;
      }
    }
    this->CompositeArray = nullptr;
    this->CompositeArrayProgram = nullptr;
    this->TransferKey.clear();
    this->TrimKey.clear();
    this->UploadTime = vtkTimeStamp();
    this->Window = nullptr;
  }
};

//------------------------------------------------------------------------------
vtkLRSplineVolumeMapper::vtkLRSplineVolumeMapper()
  : Internals(new vtkInternals)
{
  this->SetNumberOfInputPorts(2);
}

//------------------------------------------------------------------------------
vtkLRSplineVolumeMapper::~vtkLRSplineVolumeMapper()
{
  this->SetFieldArray(nullptr);
}

//------------------------------------------------------------------------------
int vtkLRSplineVolumeMapper::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == 0)
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataObject");
    return 1;
  }
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  return 1;
}

//------------------------------------------------------------------------------
void vtkLRSplineVolumeMapper::SetBlendMode(int mode)
{
  if (mode != COMPOSITE_BLEND && mode != MAXIMUM_INTENSITY_BLEND &&
    mode != MINIMUM_INTENSITY_BLEND && mode != ISOSURFACE_BLEND)
  {
    vtkErrorMacro(<< "Unsupported blend mode " << mode
                  << " (composite 0, maximum intensity 1, minimum intensity 2, isosurface 5).");
    return;
  }
  if (this->BlendMode != mode)
  {
    this->BlendMode = mode;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkLRSplineVolumeMapper::SetTrimmingSurfaceConnection(vtkAlgorithmOutput* output)
{
  this->SetInputConnection(1, output);
}

void vtkLRSplineVolumeMapper::SetTrimmingSurfaceData(vtkPolyData* surface)
{
  this->SetInputDataInternal(1, surface);
}

vtkPolyData* vtkLRSplineVolumeMapper::GetTrimmingSurface()
{
  if (this->GetNumberOfInputConnections(1) > 0)
  {
    this->GetInputAlgorithm(1, 0)->Update(this->GetInputConnection(1, 0)->GetIndex());
  }
  if (auto* surface = vtkPolyData::SafeDownCast(this->GetInputDataObject(1, 0)))
  {
    return surface;
  }
  return this->TrimByDataBoundary
    ? vtkLRSplineField::GetTrimmingSurface(this->GetInputDataObject(0, 0))
    : nullptr;
}

//------------------------------------------------------------------------------
vtkIdType vtkLRSplineVolumeMapper::GetNumberOfElements()
{
  return this->Internals->Valid ? this->Internals->Preparer->GetNumberOfElements() : 0;
}

vtkIdType vtkLRSplineVolumeMapper::GetNumberOfSkippedElements()
{
  return this->Internals->Valid ? this->Internals->Preparer->GetNumberOfSkippedElements() : 0;
}

const char* vtkLRSplineVolumeMapper::GetLastErrorMessage()
{
  return this->Internals->Error.c_str();
}

//------------------------------------------------------------------------------
size_t vtkLRSplineVolumeMapper::GetGPUMemorySize()
{
  vtkInternals& in = *this->Internals;
  if (in.UploadTime.GetMTime() > 0)
  {
    return in.HeadsBuffer.GetNumberOfBytes() + in.NodeWordsBuffer.GetNumberOfBytes() +
      in.NodeSplitsBuffer.GetNumberOfBytes() + in.OctreeBuffer.GetNumberOfBytes() +
      in.BoxesBuffer.GetNumberOfBytes() + in.OffsetsBuffer.GetNumberOfBytes() +
      in.CoefficientsBuffer.GetNumberOfBytes();
  }
  if (!in.Valid)
  {
    return 0;
  }
  // Not uploaded yet: what the upload will hold.
  return in.Preparer->GetNumberOfBytes();
}

//------------------------------------------------------------------------------
bool vtkLRSplineVolumeMapper::UpdateSpline()
{
  vtkInternals& in = *this->Internals;
  if (this->GetNumberOfInputConnections(0) > 0)
  {
    this->GetInputAlgorithm(0, 0)->Update(this->GetInputConnection(0, 0)->GetIndex());
  }
  vtkDataObject* input = this->GetInputDataObject(0, 0);
  auto done = [&](bool ok)
  {
    if (!ok && !in.Quiet)
    {
      this->ReportError();
    }
    return ok;
  };
  vtkLRSplineVolumePreparer* preparer = in.Preparer;
  if (!input)
  {
    preparer->Reset();
    return done(in.Fail("no input: connect the output of vtkLRSplineReader (or a "
                        "vtkLRSplineImageFitter) to the mapper"));
  }
  // The field built, checked (its Requirements) and flattened into the
  // arrays to upload, once per input and search settings.
  const vtkMTimeType built = preparer->GetBuildTime();
  if (!preparer->Update(input, this->FieldArray, this->ElementLocator, this->ForestResolution))
  {
    return done(in.Fail(preparer->GetErrorMessage()));
  }
  const int nc = preparer->GetNumberOfComponents();
  if (this->VectorMode == COMPONENT && this->VectorComponent >= nc)
  {
    return done(in.Fail("VectorComponent " + std::to_string(this->VectorComponent) +
      " does not exist: the field has " + std::to_string(nc) + " components"));
  }
  if (!in.Valid || preparer->GetBuildTime() != built)
  {
    in.Valid = true;
    in.Error.clear();
    in.ReportedError.clear();
  }
  return done(true);
}

//------------------------------------------------------------------------------
double* vtkLRSplineVolumeMapper::GetBounds()
{
  // Quietly: views ask for bounds before the input is ready (the error, if
  // it persists, is reported by the render).
  this->Internals->Quiet = true;
  this->UpdateSpline();
  this->Internals->Quiet = false;
  if (this->Internals->Valid)
  {
    const double* bounds = this->Internals->Preparer->GetBounds();
    std::copy(bounds, bounds + 6, this->Bounds);
  }
  else
  {
    vtkMath::UninitializeBounds(this->Bounds);
  }
  return this->Bounds;
}

//------------------------------------------------------------------------------
std::string vtkLRSplineVolumeMapper::GetVertexShaderSource()
{
  return this->Internals->Shaders->GetVertexShaderSource();
}

std::string vtkLRSplineVolumeMapper::GetFragmentShaderSource()
{
  return this->Internals->Shaders->GetFragmentShaderTemplate();
}

//------------------------------------------------------------------------------
void vtkLRSplineVolumeMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Internals->ReleaseGPU(window);
}

//------------------------------------------------------------------------------
bool vtkLRSplineVolumeMapper::UploadSpline(vtkOpenGLRenderWindow* window)
{
  vtkInternals& in = *this->Internals;
  const vtkLRSplineVolumePreparer* prep = in.Preparer;
  // The spline's data on the GPU, once per change (a failure builds it again).
  if (in.UploadTime.GetMTime() < prep->GetBuildTime())
  {
    const auto& heads = prep->GetHeads();
    const auto& words = prep->GetNodeWords();
    const auto& splits = prep->GetNodeSplits();
    const auto& octree = prep->GetOctree();
    const auto& boxes = prep->GetBoxes();
    const auto& offsets = prep->GetOffsets();
    const auto& coefficients = prep->GetCoefficients();
    // One message for the whole spline before any upload (the buffers would
    // each refuse their own part).
    const std::size_t maxTexels = vtkSplineVizGPUBuffer::GetMaximumNumberOfTexels(window);
    const std::size_t largest = std::max(
      { coefficients.size(), boxes.size() / 4, words.size(), heads.size(), octree.size() });
    if (largest > maxTexels)
    {
      in.Fail("the spline needs a buffer texture of " + std::to_string(largest) +
        " texels; this OpenGL allows " + std::to_string(maxTexels));
      in.Preparer->Reset();
      return false;
    }
    bool ok =
      in.HeadsBuffer.Upload(window, heads.data(), heads.size(), 1, VTK_UNSIGNED_INT, GL_R32UI) &&
      in.NodeWordsBuffer.Upload(
        window, words.data(), words.size(), 1, VTK_UNSIGNED_INT, GL_R32UI) &&
      in.NodeSplitsBuffer.Upload(window, splits.data(), splits.size(), 1, VTK_FLOAT, GL_R32F) &&
      in.OctreeBuffer.Upload(window, octree.data(), octree.size(), 1, VTK_UNSIGNED_INT, GL_R32UI) &&
      in.BoxesBuffer.Upload(window, boxes.data(), boxes.size() / 4, 4, VTK_FLOAT, GL_RGBA32F) &&
      in.OffsetsBuffer.Upload(
        window, offsets.data(), offsets.size(), 1, VTK_UNSIGNED_INT, GL_R32UI) &&
      in.CoefficientsBuffer.Upload(
        window, coefficients.data(), coefficients.size(), 1, VTK_FLOAT, GL_R32F);
    if (!ok)
    {
      in.Fail("the spline's data could not be uploaded to the GPU: " +
        vtkSplineVizGPUBuffer::FirstUploadError(
          { &in.HeadsBuffer, &in.NodeWordsBuffer, &in.NodeSplitsBuffer, &in.OctreeBuffer,
            &in.BoxesBuffer, &in.OffsetsBuffer, &in.CoefficientsBuffer }));
      in.Preparer->Reset();
      return false;
    }
    in.UploadTime.Modified();
  }

  return true;
}

//------------------------------------------------------------------------------
bool vtkLRSplineVolumeMapper::UpdateTransferFunction(
  vtkOpenGLRenderWindow* window, vtkVolumeProperty* property)
{
  vtkInternals& in = *this->Internals;
  // The transfer function as a texture over the union of its ranges. (The
  // property's getters create default functions and switch the channels:
  // only the one in use is asked for.)
  const bool rgbColor = property->GetColorChannels(0) == 3;
  vtkColorTransferFunction* color = rgbColor ? property->GetRGBTransferFunction(0) : nullptr;
  vtkPiecewiseFunction* gray = rgbColor ? nullptr : property->GetGrayTransferFunction(0);
  vtkPiecewiseFunction* opacity = property->GetScalarOpacity(0);
  if (!opacity || opacity->GetSize() == 0 || (rgbColor && (!color || color->GetSize() == 0)) ||
    (!rgbColor && (!gray || gray->GetSize() == 0)))
  {
    in.Error = "the volume property's transfer function is empty (no scalar opacity or color "
               "points): nothing to render";
    return false;
  }
  {
    std::ostringstream key;
    key << color << ' ' << (color ? color->GetMTime() : 0) << ' ' << gray << ' '
        << (gray ? gray->GetMTime() : 0) << ' ' << opacity << ' ' << opacity->GetMTime();
    if (key.str() != in.TransferKey || !in.TransferTexture)
    {
      double range[2];
      opacity->GetRange(range);
      double colorRange[2];
      if (color)
      {
        color->GetRange(colorRange);
      }
      else
      {
        gray->GetRange(colorRange);
      }
      range[0] = std::min(range[0], colorRange[0]);
      range[1] = std::max(range[1], colorRange[1]);
      if (!(range[1] > range[0]))
      {
        range[1] = range[0] + 1.0;
      }
      std::vector<float> table(4 * TransferFunctionSize);
      for (int i = 0; i < TransferFunctionSize; ++i)
      {
        const double v = range[0] + (range[1] - range[0]) * i / (TransferFunctionSize - 1);
        double rgb[3] = { 1, 1, 1 };
        if (color)
        {
          color->GetColor(v, rgb);
        }
        else
        {
          rgb[0] = rgb[1] = rgb[2] = gray->GetValue(v);
        }
        table[4 * i] = static_cast<float>(rgb[0]);
        table[4 * i + 1] = static_cast<float>(rgb[1]);
        table[4 * i + 2] = static_cast<float>(rgb[2]);
        table[4 * i + 3] = static_cast<float>(vtkMath::ClampValue(opacity->GetValue(v), 0.0, 1.0));
      }
      if (!in.TransferTexture)
      {
        in.TransferTexture = vtkSmartPointer<vtkTextureObject>::New();
        in.TransferTexture->SetContext(window);
        in.TransferTexture->SetWrapS(vtkTextureObject::ClampToEdge);
        in.TransferTexture->SetWrapT(vtkTextureObject::ClampToEdge);
        in.TransferTexture->SetMinificationFilter(vtkTextureObject::Linear);
        in.TransferTexture->SetMagnificationFilter(vtkTextureObject::Linear);
      }
      in.TransferTexture->SetInternalFormat(GL_RGBA32F);
      in.TransferTexture->SetFormat(GL_RGBA);
      in.TransferTexture->SetDataType(GL_FLOAT);
      in.TransferTexture->Create2DFromRaw(TransferFunctionSize, 1, 4, VTK_FLOAT, table.data());
      in.TransferRange[0] = range[0];
      in.TransferRange[1] = range[1];
      in.TransferKey = key.str();
    }
  }

  return true;
}

//------------------------------------------------------------------------------
bool vtkLRSplineVolumeMapper::CollectIsoValues(
  vtkVolumeProperty* property, std::vector<float>& isoValues)
{
  vtkInternals& in = *this->Internals;
  // Iso values.
  isoValues.clear();
  if (this->BlendMode == ISOSURFACE_BLEND)
  {
    vtkContourValues* contours = property->GetIsoSurfaceValues();
    const int n = contours ? contours->GetNumberOfContours() : 0;
    if (n == 0)
    {
      in.Error = "isosurface blend mode without iso values (vtkVolumeProperty::"
                 "GetIsoSurfaceValues()->SetValue(0, value)): nothing to render";
      return false;
    }
    if (n > MaximumIsoValues)
    {
      vtkWarningMacro(<< n << " iso values: only the first " << MaximumIsoValues
                      << " are rendered.");
    }
    for (int i = 0; i < std::min(n, MaximumIsoValues); ++i)
    {
      isoValues.push_back(static_cast<float>(contours->GetValue(i)));
    }
  }

  return true;
}

//------------------------------------------------------------------------------
bool vtkLRSplineVolumeMapper::UpdateEmptySpaceSkipping(
  vtkOpenGLRenderWindow* window, vtkVolumeProperty* property, const std::vector<float>& isoValues)
{
  vtkInternals& in = *this->Internals;
  vtkLRSplineVolumePreparer* prep = in.Preparer;
  vtkPiecewiseFunction* opacity = property->GetScalarOpacity(0);
  // Empty-space skipping: flag the elements whose coefficient range (which
  // bounds their values) maps to zero opacity (composite) or holds no iso
  // value (isosurfaces); the rays jump over them. Recomputed when the
  // spline, the transfer function, the iso values, the blend or vector mode
  // change.
  std::ostringstream key;
  key << prep->GetBuildTime() << ' ' << in.TransferKey << ' ' << this->BlendMode << ' '
      << this->VectorMode << ' ' << this->VectorComponent << ' ' << this->EmptySpaceSkipping;
  for (float v : isoValues)
  {
    key << ' ' << v;
  }
  if (key.str() == prep->GetSkipKey())
  {
    return true;
  }
  const int component = this->VectorMode == MAGNITUDE ? -1 : this->VectorComponent;
  const bool skipping = this->EmptySpaceSkipping &&
    (this->BlendMode == COMPOSITE_BLEND || this->BlendMode == ISOSURFACE_BLEND);
  if (!skipping)
  {
    prep->UpdateSkipFlags(component, [](double, double) { return false; });
  }
  else if (this->BlendMode == COMPOSITE_BLEND)
  {
    // Values are looked up in a linearly filtered table: widen by a texel.
    const double t0 = in.TransferRange[0], t1 = in.TransferRange[1];
    const double texel = (t1 - t0) / (TransferFunctionSize - 1);
    prep->UpdateSkipFlags(component,
      [&](double lo, double hi)
      {
        const double a = std::max(lo - texel, t0);
        const double b = std::min(hi + texel, t1);
        // Outside the table's range the end values hold (clamping).
        double maxOpacity = opacity->GetValue(std::min(std::max(a, t0), t1));
        maxOpacity = std::max(maxOpacity, opacity->GetValue(std::max(std::min(b, t1), t0)));
        double node[4];
        for (int i = 0; i < opacity->GetSize(); ++i)
        {
          opacity->GetNodeValue(i, node);
          if (node[0] > a && node[0] < b)
          {
            maxOpacity = std::max(maxOpacity, node[1]);
          }
        }
        return a <= b && maxOpacity <= 0.0;
      });
  }
  else
  {
    // Isosurfaces: only the elements whose range holds an iso value.
    std::vector<std::array<double, 2>> visible;
    for (float v : isoValues)
    {
      visible.push_back({ v, v });
    }
    prep->UpdateSkipFlags(component, visible);
  }
  if (in.UploadTime.GetMTime() > 0)
  {
    const auto& boxes = prep->GetBoxes();
    if (!in.BoxesBuffer.Upload(window, boxes.data(), boxes.size() / 4, 4, VTK_FLOAT, GL_RGBA32F))
    {
      in.Error = "the spline's element boxes could not be uploaded to the GPU: " +
        in.BoxesBuffer.GetLastUploadError();
      return false;
    }
  }
  prep->SetSkipKey(key.str());
  return true;
}

//------------------------------------------------------------------------------
bool vtkLRSplineVolumeMapper::RenderTrimmingDepths(
  vtkShaderProgram* program, vtkMatrix4x4* dataToClip, const int viewport[4])
{
  vtkInternals& in = *this->Internals;
  vtkOpenGLRenderWindow* window = in.Window;
  vtkOpenGLState* state = window->GetState();
  vtkPolyData* surface = this->GetTrimmingSurface();
  std::ostringstream key;
  key << surface << ' ' << (surface ? surface->GetMTime() : 0);
  if (key.str() != in.TrimKey)
  {
    std::vector<float> tri;
    if (surface && surface->GetPolys())
    {
      vtkPoints* points = surface->GetPoints();
      vtkCellArray* polys = surface->GetPolys();
      const vtkIdType* ids;
      vtkIdType n;
      for (polys->InitTraversal(); polys->GetNextCell(n, ids);)
      {
        for (vtkIdType k = 1; k + 1 < n; ++k) // a fan (convex polygons)
        {
          for (vtkIdType v : { ids[0], ids[k], ids[k + 1] })
          {
            double x[3];
            points->GetPoint(v, x);
            tri.insert(tri.end(),
              { static_cast<float>(x[0]), static_cast<float>(x[1]), static_cast<float>(x[2]) });
          }
        }
      }
    }
    if (tri.empty())
    {
      in.Error = "the trimming surface has no polygons: nothing to render (remove it to "
                 "render the whole volume)";
      return false;
    }
    if (!in.TrimBuffer)
    {
      in.TrimBuffer = vtkSmartPointer<vtkOpenGLBufferObject>::New();
    }
    in.TrimBuffer->Upload(tri, vtkOpenGLBufferObject::ArrayBuffer);
    in.TrimVertices = static_cast<vtkIdType>(tri.size() / 3);
    in.TrimArrayProgram = nullptr;
    in.TrimKey = key.str();
  }
  const std::string vs = in.Shaders->GetVertexShaderSource();
  const std::string fs = in.Shaders->GetTrimmingFragmentShaderSource();
  vtkShaderProgram* trimProgram =
    window->GetShaderCache()->ReadyShaderProgram(vs.c_str(), fs.c_str(), "");
  if (!trimProgram)
  {
    in.Error = "the trimming shader did not compile or link";
    return false;
  }
  BindPositions(in.TrimArray, in.TrimArrayProgram, trimProgram, in.TrimBuffer);
  SetMatrix(trimProgram, "lrMCDCMatrix", dataToClip);
  for (int pass = 0; pass < 2; ++pass)
  {
    vtkSmartPointer<vtkTextureObject>& texture = in.TrimTextures[pass];
    vtkSmartPointer<vtkOpenGLFramebufferObject>& fbo = in.TrimFramebuffers[pass];
    if (!texture || static_cast<int>(texture->GetWidth()) != viewport[2] ||
      static_cast<int>(texture->GetHeight()) != viewport[3])
    {
      if (texture)
      {
        texture->ReleaseGraphicsResources(window);
      }
      texture = vtkSmartPointer<vtkTextureObject>::New();
      texture->SetContext(window);
      texture->SetMinificationFilter(vtkTextureObject::Nearest);
      texture->SetMagnificationFilter(vtkTextureObject::Nearest);
      texture->AllocateDepth(viewport[2], viewport[3], vtkTextureObject::Float32);
      fbo = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
      fbo->SetContext(window);
      fbo->SaveCurrentBindingsAndBuffers();
      fbo->Bind();
      fbo->AddDepthAttachment(texture);
      fbo->RestorePreviousBindingsAndBuffers();
    }
    fbo->SaveCurrentBindingsAndBuffers();
    fbo->Bind();
    fbo->DeactivateDrawBuffers();
    fbo->DeactivateReadBuffer();
    {
      vtkOpenGLState::ScopedglViewport savedViewport(state);
      vtkOpenGLState::ScopedglScissor savedScissor(state);
      vtkOpenGLState::ScopedglColorMask savedColorMask(state);
      vtkOpenGLState::ScopedglDepthMask savedDepthMask(state);
      vtkOpenGLState::ScopedglDepthFunc savedDepthFunc(state);
      vtkOpenGLState::ScopedglEnableDisable savedDepthTest(state, GL_DEPTH_TEST);
      vtkOpenGLState::ScopedglEnableDisable savedCull(state, GL_CULL_FACE);
      vtkOpenGLState::ScopedglEnableDisable savedBlend(state, GL_BLEND);
      state->vtkglViewport(0, 0, viewport[2], viewport[3]);
      state->vtkglScissor(0, 0, viewport[2], viewport[3]);
      state->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
      state->vtkglDepthMask(GL_TRUE);
      state->vtkglEnable(GL_DEPTH_TEST);
      state->vtkglDisable(GL_BLEND);
      // Front faces and back faces both: the orientation of the surface's
      // polygons is not trusted; the nearest and farthest hits are kept.
      state->vtkglDisable(GL_CULL_FACE);
      state->vtkglClearDepth(pass == 0 ? 1.0 : 0.0);
      state->vtkglClear(GL_DEPTH_BUFFER_BIT);
      state->vtkglDepthFunc(pass == 0 ? GL_LESS : GL_GREATER);
      in.TrimArray->Bind();
      glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(in.TrimVertices));
      in.TrimArray->Release();
      state->vtkglClearDepth(1.0);
    }
    fbo->RestorePreviousBindingsAndBuffers();
  }
  // The ray caster's program again.
  window->GetShaderCache()->ReadyShaderProgram(program, nullptr);
  return true;
}

//------------------------------------------------------------------------------
void vtkLRSplineVolumeMapper::CopyOpaqueDepth(const int viewport[4])
{
  // Copied as VTK's GPU ray caster does.
  vtkInternals& in = *this->Internals;
  vtkOpenGLRenderWindow* window = in.Window;
  vtkOpenGLState* state = window->GetState();
  if (!in.DepthTexture)
  {
    in.DepthTexture = vtkSmartPointer<vtkTextureObject>::New();
    in.DepthTexture->SetContext(window);
    in.DepthTexture->SetMinificationFilter(vtkTextureObject::Nearest);
    in.DepthTexture->SetMagnificationFilter(vtkTextureObject::Nearest);
    in.DepthTexture->SetWrapS(vtkTextureObject::ClampToEdge);
    in.DepthTexture->SetWrapT(vtkTextureObject::ClampToEdge);
    in.DepthColor = vtkSmartPointer<vtkTextureObject>::New();
    in.DepthColor->SetContext(window);
  }
  if (!in.DepthTexture->GetHandle() ||
    static_cast<int>(in.DepthTexture->GetWidth()) != viewport[2] ||
    static_cast<int>(in.DepthTexture->GetHeight()) != viewport[3])
  {
    in.DepthTexture->ReleaseGraphicsResources(window);
    in.DepthColor->ReleaseGraphicsResources(window);
    if (window->GetStencilCapable())
    {
      in.DepthTexture->AllocateDepthStencil(viewport[2], viewport[3]);
    }
    else
    {
      in.DepthTexture->AllocateDepth(viewport[2], viewport[3], vtkTextureObject::Fixed32);
    }
    in.DepthColor->Allocate2D(viewport[2], viewport[3], 4, VTK_UNSIGNED_CHAR);
    in.DepthFramebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
    in.DepthFramebuffer->SetContext(window);
    state->PushDrawFramebufferBinding();
    in.DepthFramebuffer->Bind(GL_DRAW_FRAMEBUFFER);
    in.DepthFramebuffer->AddDepthAttachment(in.DepthTexture);
    in.DepthFramebuffer->AddColorAttachment(0, in.DepthColor);
    state->PopDrawFramebufferBinding();
  }
  {
    state->PushDrawFramebufferBinding();
    in.DepthFramebuffer->Bind(GL_DRAW_FRAMEBUFFER);
    vtkOpenGLClearErrorMacro();
    state->vtkglBlitFramebuffer(viewport[0], viewport[1], viewport[0] + viewport[2],
      viewport[1] + viewport[3], 0, 0, viewport[2], viewport[3], GL_DEPTH_BUFFER_BIT, GL_NEAREST);
    if (glGetError() != GL_NO_ERROR)
    {
      // Incompatible depth formats: no opaque geometry is known.
      if (!in.DepthCopyWarned)
      {
        vtkWarningMacro(<< "Could not copy the depth buffer: the volume ignores the opaque "
                           "geometry of this render pass.");
        in.DepthCopyWarned = true;
      }
      vtkOpenGLState::ScopedglDepthMask mask(state);
      state->vtkglDepthMask(GL_TRUE);
      state->vtkglClearDepth(1.0);
      state->vtkglClear(GL_DEPTH_BUFFER_BIT);
    }
    state->PopDrawFramebufferBinding();
  }
}

//------------------------------------------------------------------------------
void vtkLRSplineVolumeMapper::SetPatchUniforms(vtkShaderProgram* program)
{
  // Per patch: its parameter domain (curved: physical), the map to it, its
  // box, and where its search structure and elements start.
  const vtkLRSplineVolumePreparer* prep = this->Internals->Preparer;
  const std::vector<vtkLRSplineVolumePreparer::PatchInfo>& patches = prep->GetPatches();
  const int np = static_cast<int>(patches.size());
  std::vector<float> lo, hi, edge, offset, boxLoP, boxHiP;
  std::vector<int> blocks, starts, locators, curved;
  for (const vtkLRSplineVolumePreparer::PatchInfo& p : patches)
  {
    lo.insert(lo.end(), p.Lo, p.Lo + 3);
    hi.insert(hi.end(), p.Hi, p.Hi + 3);
    edge.insert(edge.end(), p.Edge, p.Edge + 3);
    offset.insert(offset.end(), p.Offset, p.Offset + 3);
    boxLoP.insert(boxLoP.end(), p.BoxLo, p.BoxLo + 3);
    boxHiP.insert(boxHiP.end(), p.BoxHi, p.BoxHi + 3);
    blocks.insert(blocks.end(), p.Blocks, p.Blocks + 3);
    starts.insert(starts.end(), p.Starts, p.Starts + 4);
    locators.push_back(p.Locator);
    curved.push_back(p.Curved);
  }
  auto set3f = [&](const char* name, std::vector<float>& v)
  { program->SetUniform3fv(name, np, reinterpret_cast<const float(*)[3]>(v.data())); };
  set3f("lrPatchLo", lo);
  set3f("lrPatchHi", hi);
  set3f("lrPatchEdge", edge);
  for (int p = 0; p < np; ++p)
  {
    // GLSL matrices are column-major: the transpose of the row-major array.
    float columns[9];
    for (int r = 0; r < 3; ++r)
    {
      for (int c = 0; c < 3; ++c)
      {
        columns[3 * c + r] = patches[p].Inverse[3 * r + c];
      }
    }
    program->SetUniformMatrix3x3(("lrPatchInverse[" + std::to_string(p) + "]").c_str(), columns);
  }
  set3f("lrPatchOffset", offset);
  set3f("lrPatchBoxLo", boxLoP);
  set3f("lrPatchBoxHi", boxHiP);
  program->SetUniform1iv("lrPatchBlocks", 3 * np, blocks.data());
  program->SetUniform1iv("lrPatchStarts", 4 * np, starts.data());
  program->SetUniform1iv("lrPatchLocator", np, locators.data());
  if (prep->GetCurved())
  {
    program->SetUniform1iv("lrPatchCurved", np, curved.data());
    program->SetUniformf("lrMinimumSide", static_cast<float>(prep->GetMinimumSide()));
  }
}

//------------------------------------------------------------------------------
void vtkLRSplineVolumeMapper::DrawSinglePass()
{
  // The back faces of the proxy box: every pixel the volume may cover runs
  // its ray once, also with the camera inside the box.
  vtkInternals& in = *this->Internals;
  DrawProxyBox(
    in.Window->GetState(), in.CubeArray, !this->CountSamples, this->BlendMode == ISOSURFACE_BLEND);
}

//------------------------------------------------------------------------------
void vtkLRSplineVolumeMapper::UpdateProxyBox(const double box[6])
{
  vtkInternals& in = *this->Internals;
  if (in.CubeBuffer && std::equal(box, box + 6, in.CubeBox))
  {
    return;
  }
  // Slightly larger than the box, so its faces never clip the volume.
  double pad[3];
  for (int d = 0; d < 3; ++d)
  {
    pad[d] = 1e-4 * (box[d + 3] - box[d]) + 1e-9;
  }
  std::vector<float> tri;
  const int faces[6][4] = { { 0, 2, 6, 4 }, { 1, 5, 7, 3 }, { 0, 4, 5, 1 }, { 2, 3, 7, 6 },
    { 0, 1, 3, 2 }, { 4, 6, 7, 5 } };
  auto corner = [&](int c, int d)
  {
    const bool high = (c >> d) & 1;
    return static_cast<float>(high ? box[d + 3] + pad[d] : box[d] - pad[d]);
  };
  for (const auto& f : faces)
  {
    for (int v : { 0, 1, 2, 0, 2, 3 })
    {
      for (int d = 0; d < 3; ++d)
      {
        tri.push_back(corner(f[v], d));
      }
    }
  }
  if (!in.CubeBuffer)
  {
    in.CubeBuffer = vtkSmartPointer<vtkOpenGLBufferObject>::New();
  }
  in.CubeBuffer->Upload(tri, vtkOpenGLBufferObject::ArrayBuffer);
  std::copy(box, box + 6, in.CubeBox);
  in.CubeArrayProgram = nullptr;
}

//------------------------------------------------------------------------------
void vtkLRSplineVolumeMapper::SetClippingPlaneUniforms(
  vtkShaderProgram* program, vtkMatrix4x4* dataToWorld)
{
  vtkPlaneCollection* planes = this->ClippingPlanes;
  const int n = planes ? std::min(planes->GetNumberOfItems(), MaximumClipPlanes) : 0;
  if (planes && planes->GetNumberOfItems() > MaximumClipPlanes)
  {
    vtkWarningMacro(<< "Only the first " << MaximumClipPlanes << " clipping planes are used.");
  }
  float equations[MaximumClipPlanes][4] = {};
  for (int i = 0; i < n; ++i)
  {
    vtkPlane* plane = planes->GetItem(i);
    double normal[3], origin[3];
    plane->GetNormal(normal);
    plane->GetOrigin(origin);
    // Kept: n . (x_world - o) >= 0 with x_world = A x + t.
    double d = -vtkMath::Dot(normal, origin);
    for (int r = 0; r < 3; ++r)
    {
      d += normal[r] * dataToWorld->GetElement(r, 3);
    }
    for (int c = 0; c < 3; ++c)
    {
      double v = 0.0;
      for (int r = 0; r < 3; ++r)
      {
        v += normal[r] * dataToWorld->GetElement(r, c);
      }
      equations[i][c] = static_cast<float>(v);
    }
    equations[i][3] = static_cast<float>(d);
  }
  program->SetUniformi("lrNumberOfClipPlanes", n);
  program->SetUniform4fv("lrClipPlanes", MaximumClipPlanes, equations);
}

//------------------------------------------------------------------------------
void vtkLRSplineVolumeMapper::SetShadingUniforms(vtkShaderProgram* program,
  vtkVolumeProperty* property, const std::vector<std::array<float, 6>>& lightList,
  const std::vector<float>& isoValues)
{
  vtkInternals& in = *this->Internals;
  const float range[2] = { static_cast<float>(in.TransferRange[0]),
    static_cast<float>(in.TransferRange[1]) };
  program->SetUniform2f("lrRange", range);
  program->SetUniformf("lrUnitDistance",
    static_cast<float>(std::max(property->GetScalarOpacityUnitDistance(0), 1e-12)));
  program->SetUniformf("lrAmbient", static_cast<float>(property->GetAmbient(0)));
  program->SetUniformf("lrDiffuse", static_cast<float>(property->GetDiffuse(0)));
  program->SetUniformf("lrSpecular", static_cast<float>(property->GetSpecular(0)));
  program->SetUniformf("lrSpecularPower", static_cast<float>(property->GetSpecularPower(0)));
  {
    std::vector<float> directions, colors;
    for (const auto& l : lightList)
    {
      directions.insert(directions.end(), l.begin(), l.begin() + 3);
      colors.insert(colors.end(), l.begin() + 3, l.end());
    }
    program->SetUniform3fv("lrLightDirections", static_cast<int>(lightList.size()),
      reinterpret_cast<const float(*)[3]>(directions.data()));
    program->SetUniform3fv("lrLightColors", static_cast<int>(lightList.size()),
      reinterpret_cast<const float(*)[3]>(colors.data()));
  }
  {
    float iso[MaximumIsoValues] = {};
    std::copy(isoValues.begin(), isoValues.end(), iso);
    program->SetUniform1fv("lrIsoValues", MaximumIsoValues, iso);
    program->SetUniformi("lrNumberOfIsoValues", static_cast<int>(isoValues.size()));
    program->SetUniformi("lrBisections", this->IsosurfaceBisections);
  }
}

//------------------------------------------------------------------------------
void vtkLRSplineVolumeMapper::ActivateTextures(vtkShaderProgram* program, bool trim)
{
  vtkInternals& in = *this->Internals;
  in.HeadsBuffer.Activate(program, "lrHeads");
  in.NodeWordsBuffer.Activate(program, "lrNodeWords");
  in.NodeSplitsBuffer.Activate(program, "lrNodeSplits");
  in.OctreeBuffer.Activate(program, "lrOctree");
  in.BoxesBuffer.Activate(program, "lrBoxes");
  in.OffsetsBuffer.Activate(program, "lrOffsets");
  in.CoefficientsBuffer.Activate(program, "lrCoefficients");
  in.TransferTexture->Activate();
  program->SetUniformi("lrTransfer", in.TransferTexture->GetTextureUnit());
  in.DepthTexture->Activate();
  program->SetUniformi("lrDepth", in.DepthTexture->GetTextureUnit());
  if (trim)
  {
    in.TrimTextures[0]->Activate();
    in.TrimTextures[1]->Activate();
    program->SetUniformi("lrTrimFront", in.TrimTextures[0]->GetTextureUnit());
    program->SetUniformi("lrTrimBack", in.TrimTextures[1]->GetTextureUnit());
  }
}

//------------------------------------------------------------------------------
void vtkLRSplineVolumeMapper::DeactivateTextures(bool trim)
{
  vtkInternals& in = *this->Internals;
  in.HeadsBuffer.Deactivate();
  in.NodeWordsBuffer.Deactivate();
  in.NodeSplitsBuffer.Deactivate();
  in.OctreeBuffer.Deactivate();
  in.BoxesBuffer.Deactivate();
  in.OffsetsBuffer.Deactivate();
  in.CoefficientsBuffer.Deactivate();
  in.TransferTexture->Deactivate();
  in.DepthTexture->Deactivate();
  if (trim)
  {
    in.TrimTextures[0]->Deactivate();
    in.TrimTextures[1]->Deactivate();
  }
}

//------------------------------------------------------------------------------
vtkShaderProgram* vtkLRSplineVolumeMapper::ReadyProgram(
  vtkOpenGLRenderWindow* window, bool shade, bool multiPass, int numberOfLights)
{
  // The options that change the shader text; the sources from the builder
  // (through the virtual hooks, which tests override).
  vtkInternals& in = *this->Internals;
  vtkLRSplineVolumeShaderBuilder* shaders = in.Shaders;
  const vtkLRSplineVolumePreparer* prep = in.Preparer;
  shaders->SetDegree(prep->GetDegree());
  shaders->SetNumberOfComponents(prep->GetNumberOfComponents());
  shaders->SetVectorMode(this->VectorMode);
  shaders->SetVectorComponent(this->VectorComponent);
  shaders->SetNumberOfPatches(prep->GetNumberOfPatches());
  shaders->SetCurved(prep->GetCurved());
  shaders->SetBlendMode(this->BlendMode);
  shaders->SetShade(shade);
  shaders->SetFuchsShading(this->ShadingModel == FUCHS);
  shaders->SetTrim(this->GetTrimmingSurface() != nullptr);
  shaders->SetCountSamples(this->CountSamples);
  shaders->SetMultiPass(multiPass);
  shaders->SetSupersampling(this->Supersampling);
  shaders->SetNumberOfLights(numberOfLights);
  const std::string fs = shaders->BuildFragmentShaderSource(this->GetFragmentShaderSource());
  const std::string vs = this->GetVertexShaderSource();
  // A source that failed once is not compiled again every frame.
  vtkShaderProgram* program = (vs + fs) == in.FailedShader
    ? nullptr
    : window->GetShaderCache()->ReadyShaderProgram(vs.c_str(), fs.c_str(), "");
  if (!program)
  {
    in.FailedShader = vs + fs;
    in.Error = "the volume shader did not compile or link (see the message above)";
  }
  return program;
}

//------------------------------------------------------------------------------
void vtkLRSplineVolumeMapper::SetTransformUniforms(vtkShaderProgram* program,
  vtkMatrix4x4* dataToWorld, vtkMatrix4x4* dataToClip, const int viewport[4], const double box[6])
{
  vtkNew<vtkMatrix4x4> clipToData;
  vtkMatrix4x4::Invert(dataToClip, clipToData);
  float a3[9], n3[9];
  vtkNew<vtkMatrix3x3> linear, normal;
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      linear->SetElement(r, c, dataToWorld->GetElement(r, c));
    }
  }
  vtkMatrix3x3::Invert(linear, normal);
  normal->Transpose();
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      // Column-major for GLSL.
      a3[3 * c + r] = static_cast<float>(linear->GetElement(r, c));
      n3[3 * c + r] = static_cast<float>(normal->GetElement(r, c));
    }
  }
  SetMatrix(program, "lrMCDCMatrix", dataToClip);
  SetMatrix(program, "lrDCMCMatrix", clipToData);
  program->SetUniformMatrix3x3("lrDataToWorld", a3);
  program->SetUniformMatrix3x3("lrNormalMatrix", n3);
  const float viewportF[4] = { static_cast<float>(viewport[0]), static_cast<float>(viewport[1]),
    static_cast<float>(viewport[2]), static_cast<float>(viewport[3]) };
  program->SetUniform4f("lrViewport", viewportF);
  const float boxLo[3] = { static_cast<float>(box[0]), static_cast<float>(box[1]),
    static_cast<float>(box[2]) };
  const float boxHi[3] = { static_cast<float>(box[3]), static_cast<float>(box[4]),
    static_cast<float>(box[5]) };
  program->SetUniform3f("lrBoxLo", boxLo);
  program->SetUniform3f("lrBoxHi", boxHi);
}

//------------------------------------------------------------------------------
int vtkLRSplineVolumeMapper::SetSamplingUniforms(
  vtkShaderProgram* program, vtkVolume* vol, bool multiPass, int stepsPerPass)
{
  double sampleDistance = 0.0;
  const int maxSteps = this->ComputeStepCount(vol, sampleDistance);
  program->SetUniformi("lrAdaptive", this->AdaptiveSteps ? 1 : 0);
  program->SetUniformf("lrStepScale", static_cast<float>(this->StepScale));
  program->SetUniformf("lrSampleDistance", static_cast<float>(sampleDistance));
  // Mesa's llvmpipe ends a fragment's loops after 65,535 iterations in all
  // (about 4,000 samples with the element look-up): say so, once per
  // setting, when fixed steps need more (adaptive estimates are the worst
  // case, finest everywhere, and rarely reached).
  if (!multiPass && !this->AdaptiveSteps && maxSteps > 4000 && maxSteps != this->WarnedSteps)
  {
    // checked once per setting, not every frame
    this->WarnedSteps = maxSteps;
    const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    if (renderer && std::string(renderer).find("llvmpipe") != std::string::npos)
    {
      vtkWarningMacro(<< "rays need up to " << maxSteps << " samples at SampleDistance "
                      << sampleDistance
                      << ", but Mesa's llvmpipe ends a fragment's loops after 65,535 "
                         "iterations (about 4,000 samples): long rays are cut short; use a "
                         "larger SampleDistance or adaptive steps");
    }
  }
  program->SetUniformi("lrMaxSteps", multiPass ? stepsPerPass : maxSteps);
  program->SetUniformf("lrJitter", this->UseJittering ? 1.0f : 0.0f);
  return maxSteps;
}

//------------------------------------------------------------------------------
void vtkLRSplineVolumeMapper::Render(vtkRenderer* ren, vtkVolume* vol)
{
  vtkInternals& in = *this->Internals;
  auto report = [this]() { this->ReportError(); };
  if (!this->UpdateSpline())
  {
    return;
  }
  vtkOpenGLRenderWindow* window = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  vtkVolumeProperty* property = vol->GetProperty();
  if (!window || !property)
  {
    return;
  }
  if (in.Window && in.Window != window)
  {
    in.ReleaseGPU(in.Window);
  }
  in.Window = window;
  vtkOpenGLClearErrorMacro();

  if (!this->UploadSpline(window) || !this->UpdateTransferFunction(window, property))
  {
    report();
    return;
  }
  std::vector<float> isoValues;
  if (!this->CollectIsoValues(property, isoValues) ||
    !this->UpdateEmptySpaceSkipping(window, property, isoValues))
  {
    report();
    return;
  }

  const std::vector<std::array<float, 6>> lightList = CollectLights(ren);

  // Continuation in passes when the rays may need more samples than a pass
  // runs (see MaximumStepsPerPass).
  int stepsPerPass = this->MaximumStepsPerPass;
  if (stepsPerPass <= 0)
  {
    stepsPerPass = in.Preparer->GetCurved() ? 400 : 2000;
  }
  double unusedDistance = 0.0;
  const bool multiPass =
    !this->CountSamples && this->ComputeStepCount(vol, unusedDistance) > stepsPerPass;

  // The program.
  const bool shade = property->GetShade(0) != 0 && !this->CountSamples;
  vtkShaderProgram* program =
    this->ReadyProgram(window, shade, multiPass, static_cast<int>(lightList.size()));
  if (!program)
  {
    report();
    return;
  }
  const bool trim = in.Shaders->GetTrim();

  // Matrices: data (the volume's model coordinates) to clip space.
  int viewport[4];
  ren->GetTiledSizeAndOrigin(&viewport[2], &viewport[3], &viewport[0], &viewport[1]);
  if (viewport[2] < 1 || viewport[3] < 1)
  {
    return;
  }
  vtkOpenGLCamera* camera = vtkOpenGLCamera::SafeDownCast(ren->GetActiveCamera());
  vtkMatrix4x4* wcvc;
  vtkMatrix3x3* norms;
  vtkMatrix4x4* vcdc;
  vtkMatrix4x4* wcdc;
  camera->GetKeyMatrices(ren, wcvc, norms, vcdc, wcdc);
  vtkNew<vtkMatrix4x4> worldToClip; // row-major (GetKeyMatrices gives them transposed)
  vtkMatrix4x4::Transpose(wcdc, worldToClip);
  vtkMatrix4x4* dataToWorld = vol->GetMatrix();
  vtkNew<vtkMatrix4x4> dataToClip;
  vtkMatrix4x4::Multiply4x4(worldToClip, dataToWorld, dataToClip);

  // The opaque geometry's depth (rays end there).
  this->CopyOpaqueDepth(viewport);

  // The proxy box (the union of the patches' boxes).
  const double* bounds = in.Preparer->GetBounds();
  double box[6] = { bounds[0], bounds[2], bounds[4], bounds[1], bounds[3], bounds[5] };
  this->UpdateProxyBox(box);

  // Trimming: the nearest front faces and the farthest back faces.
  if (trim && !this->RenderTrimmingDepths(program, dataToClip, viewport))
  {
    report();
    return;
  }

  // Uniforms.
  this->SetTransformUniforms(program, dataToWorld, dataToClip, viewport, box);
  this->SetPatchUniforms(program);
  this->SetClippingPlaneUniforms(program, dataToWorld);
  const int maxSteps = this->SetSamplingUniforms(program, vol, multiPass, stepsPerPass);
  this->SetShadingUniforms(program, property, lightList, isoValues);

  this->ActivateTextures(program, trim);

  // Draw the back faces of the proxy box: every pixel the volume may cover
  // runs its ray once, also with the camera inside the box.
  BindPositions(in.CubeArray, in.CubeArrayProgram, program, in.CubeBuffer);
  in.Passes = 1;
  if (multiPass && !this->DrawPasses(ren, program, dataToClip, viewport, stepsPerPass, maxSteps))
  {
    report();
  }
  else if (!multiPass)
  {
    this->DrawSinglePass();
  }

  this->DeactivateTextures(trim);
  vtkOpenGLCheckErrorMacro("failed after Render");
  // A good frame: a problem that comes back is reported again.
  in.Error.clear();
  in.ReportedError.clear();
}

//------------------------------------------------------------------------------
int vtkLRSplineVolumeMapper::GetNumberOfPasses()
{
  return this->Internals->Passes;
}

//------------------------------------------------------------------------------
int vtkLRSplineVolumeMapper::ComputeStepCount(vtkVolume* vol, double& sampleDistance)
{
  const vtkLRSplineVolumePreparer* prep = this->Internals->Preparer;
  const double* bounds = prep->GetBounds();
  const double box[6] = { bounds[0], bounds[2], bounds[4], bounds[1], bounds[3], bounds[5] };
  vtkMatrix4x4* dataToWorld = vol->GetMatrix();
  // The box's diagonal in world units.
  double diagonal = 0.0;
  for (int d = 0; d < 3; ++d)
  {
    double e[3] = { 0, 0, 0 };
    e[d] = box[d + 3] - box[d];
    double w[3];
    for (int r = 0; r < 3; ++r)
    {
      w[r] = dataToWorld->GetElement(r, 0) * e[0] + dataToWorld->GetElement(r, 1) * e[1] +
        dataToWorld->GetElement(r, 2) * e[2];
    }
    diagonal += vtkMath::Dot(w, w);
  }
  diagonal = std::sqrt(diagonal);
  sampleDistance = this->SampleDistance > 0 ? this->SampleDistance : diagonal / 100.0;
  if (this->MaximumNumberOfSteps > 0)
  {
    return this->MaximumNumberOfSteps;
  }
  // Automatic: the box's diagonal at the finest step, plus the gaps.
  double dataDiagonal = 0.0;
  for (int d = 0; d < 3; ++d)
  {
    dataDiagonal += (box[d + 3] - box[d]) * (box[d + 3] - box[d]);
  }
  dataDiagonal = std::sqrt(dataDiagonal);
  const int* degree = prep->GetDegree();
  const int maxDegree = std::max(degree[0], std::max(degree[1], degree[2]));
  const double steps = this->AdaptiveSteps
    ? dataDiagonal / (this->StepScale * prep->GetMinimumSide() / (1 << maxDegree))
    : diagonal / sampleDistance;
  return static_cast<int>(std::min(
    1.0e8, std::ceil(1.05 * steps) + 64.0 + 4.0 * static_cast<double>(prep->GetNumberOfPatches())));
}

//------------------------------------------------------------------------------
bool vtkLRSplineVolumeMapper::DrawPasses(vtkRenderer* ren, vtkShaderProgram* program,
  vtkMatrix4x4* dataToClip, const int viewport[4], int stepsPerPass, int totalSteps)
{
  vtkInternals& in = *this->Internals;
  vtkOpenGLRenderWindow* window = in.Window;
  vtkOpenGLState* state = window->GetState();
  const int w = viewport[2], h = viewport[3];
  // Viewport-sized float targets (re-made when the viewport changes).
  bool resized = false;
  auto target = [&](vtkSmartPointer<vtkTextureObject>& t, int components)
  {
    if (!t)
    {
      t = vtkSmartPointer<vtkTextureObject>::New();
      t->SetContext(window);
      t->SetMinificationFilter(vtkTextureObject::Nearest);
      t->SetMagnificationFilter(vtkTextureObject::Nearest);
      t->SetWrapS(vtkTextureObject::ClampToEdge);
      t->SetWrapT(vtkTextureObject::ClampToEdge);
    }
    if (!t->GetHandle() || static_cast<int>(t->GetWidth()) != w ||
      static_cast<int>(t->GetHeight()) != h)
    {
      t->ReleaseGraphicsResources(window);
      resized = true;
      return t->Allocate2D(w, h, components, VTK_FLOAT);
    }
    return true;
  };
  bool ok = target(in.PassFinal[0], 4) && target(in.PassFinal[1], 1);
  for (auto& set : in.PassState)
  {
    for (auto& t : set)
    {
      ok = ok && target(t, 4);
    }
  }
  if (!ok)
  {
    in.Error = "the textures of the multi-pass continuation (" + std::to_string(w) + " x " +
      std::to_string(h) + " pixels, 112 bytes each) could not be allocated";
    return false;
  }
  if (resized || !in.PassFramebuffers[0])
  {
    state->PushDrawFramebufferBinding();
    for (int k = 0; k < 2; ++k)
    {
      in.PassFramebuffers[k] = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
      in.PassFramebuffers[k]->SetContext(window);
      in.PassFramebuffers[k]->Bind(GL_DRAW_FRAMEBUFFER);
      in.PassFramebuffers[k]->AddColorAttachment(0, in.PassFinal[0]);
      in.PassFramebuffers[k]->AddColorAttachment(1, in.PassFinal[1]);
      for (int j = 0; j < 3; ++j)
      {
        in.PassFramebuffers[k]->AddColorAttachment(2 + j, in.PassState[k][j]);
      }
    }
    state->PopDrawFramebufferBinding();
  }

  // The passes: each resumes the rays the previous one left unfinished,
  // until a pass draws nothing (every ray ended).
  const float passViewport[4] = { 0.0f, 0.0f, static_cast<float>(w), static_cast<float>(h) };
  program->SetUniform4f("lrViewport", passViewport);
  GLuint query = 0;
  glGenQueries(1, &query);
  {
    vtkOpenGLState::ScopedglViewport savedViewport(state);
    vtkOpenGLState::ScopedglEnableDisable savedCull(state, GL_CULL_FACE);
    vtkOpenGLState::ScopedglEnableDisable savedBlend(state, GL_BLEND);
    vtkOpenGLState::ScopedglEnableDisable savedScissor(state, GL_SCISSOR_TEST);
    vtkOpenGLState::ScopedglEnableDisable savedDepthTest(state, GL_DEPTH_TEST);
    state->PushDrawFramebufferBinding();
    state->vtkglViewport(0, 0, w, h);
    state->vtkglDisable(GL_BLEND);
    state->vtkglDisable(GL_SCISSOR_TEST);
    state->vtkglDisable(GL_DEPTH_TEST);
    state->vtkglEnable(GL_CULL_FACE);
    state->vtkglCullFace(GL_FRONT);
    const GLfloat zero[4] = { 0, 0, 0, 0 };
    const GLfloat one[4] = { 1, 1, 1, 1 };
    // At most the passes the step count needs (plus the one that finds
    // nothing left).
    const int maxPasses = (totalSteps + stepsPerPass - 1) / stepsPerPass;
    int pass = 0;
    for (; pass < maxPasses; ++pass)
    {
      vtkOpenGLFramebufferObject* fbo = in.PassFramebuffers[pass % 2];
      fbo->Bind(GL_DRAW_FRAMEBUFFER);
      fbo->ActivateDrawBuffers(5);
      // (also directly: the state cache may skip a second framebuffer's)
      const GLenum buffers[5] = { GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2,
        GL_COLOR_ATTACHMENT3, GL_COLOR_ATTACHMENT4 };
      glDrawBuffers(5, buffers);
      // The state this pass writes starts inactive; the final targets are
      // cleared once.
      for (int b = pass == 0 ? 0 : 2; b < 5; ++b)
      {
        glClearBufferfv(GL_COLOR, b, b == 1 ? one : zero);
      }
      const vtkSmartPointer<vtkTextureObject>* read = in.PassState[(pass + 1) % 2];
      for (int j = 0; j < 3; ++j)
      {
        read[j]->Activate();
      }
      program->SetUniformi("lrPass", pass);
      // The last pass runs what is left of the samples per ray.
      program->SetUniformi("lrMaxSteps", std::min(stepsPerPass, totalSteps - pass * stepsPerPass));
      program->SetUniformi("lrLastPass", pass + 1 == maxPasses ? 1 : 0);
      program->SetUniformi("lrStateColor", read[0]->GetTextureUnit());
      program->SetUniformi("lrStateRay", read[1]->GetTextureUnit());
      program->SetUniformi("lrStateExtra", read[2]->GetTextureUnit());
      glBeginQuery(GL_ANY_SAMPLES_PASSED, query);
      in.CubeArray->Bind();
      glDrawArrays(GL_TRIANGLES, 0, 36);
      in.CubeArray->Release();
      glEndQuery(GL_ANY_SAMPLES_PASSED);
      for (int j = 0; j < 3; ++j)
      {
        read[j]->Deactivate();
      }
      GLuint drawn = 0;
      glGetQueryObjectuiv(query, GL_QUERY_RESULT, &drawn);
      if (!drawn)
      {
        break;
      }
    }
    in.Passes = std::min(pass + 1, maxPasses);
    state->PopDrawFramebufferBinding();
    state->vtkglCullFace(GL_BACK);
  }
  glDeleteQueries(1, &query);

  // The final colors (and isosurface depths) into the render target.
  const std::string vs = this->GetVertexShaderSource();
  const std::string fs = in.Shaders->GetCompositeFragmentShaderSource();
  vtkShaderProgram* composite =
    window->GetShaderCache()->ReadyShaderProgram(vs.c_str(), fs.c_str(), "");
  if (!composite)
  {
    in.Error = "the final shader of the multi-pass continuation did not compile";
    return false;
  }
  BindPositions(in.CompositeArray, in.CompositeArrayProgram, composite, in.CubeBuffer);
  SetMatrix(composite, "lrMCDCMatrix", dataToClip);
  const float viewportF[4] = { static_cast<float>(viewport[0]), static_cast<float>(viewport[1]),
    static_cast<float>(w), static_cast<float>(h) };
  composite->SetUniform4f("lrViewport", viewportF);
  composite->SetUniformi("lrWriteDepth", this->BlendMode == ISOSURFACE_BLEND ? 1 : 0);
  in.PassFinal[0]->Activate();
  in.PassFinal[1]->Activate();
  composite->SetUniformi("lrFinalColor", in.PassFinal[0]->GetTextureUnit());
  composite->SetUniformi("lrFinalDepth", in.PassFinal[1]->GetTextureUnit());
  DrawProxyBox(state, in.CompositeArray, true, this->BlendMode == ISOSURFACE_BLEND);
  in.PassFinal[0]->Deactivate();
  in.PassFinal[1]->Deactivate();
  (void)ren;
  // The main program is used again by the next frame: its uniforms are set
  // every frame.
  return true;
}

//------------------------------------------------------------------------------
void vtkLRSplineVolumeMapper::ReportError()
{
  vtkInternals& in = *this->Internals;
  if (!in.Error.empty() && in.Error != in.ReportedError)
  {
    vtkErrorMacro(<< in.Error);
    in.ReportedError = in.Error;
  }
}

//------------------------------------------------------------------------------
void vtkLRSplineVolumeMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  const char* blend = this->BlendMode == COMPOSITE_BLEND ? "Composite"
    : this->BlendMode == MAXIMUM_INTENSITY_BLEND         ? "MaximumIntensity"
    : this->BlendMode == MINIMUM_INTENSITY_BLEND         ? "MinimumIntensity"
                                                         : "IsoSurface";
  os << indent << "BlendMode: " << blend << "\n";
  os << indent << "FieldArray: " << (this->FieldArray ? this->FieldArray : "(auto)") << "\n";
  os << indent << "VectorMode: " << (this->VectorMode == MAGNITUDE ? "Magnitude" : "Component")
     << "\n";
  os << indent << "VectorComponent: " << this->VectorComponent << "\n";
  os << indent << "ElementLocator: " << vtkLRSplineElementLocator::GetTypeName(this->ElementLocator)
     << "\n";
  os << indent << "ForestResolution: " << this->ForestResolution << "\n";
  os << indent << "AdaptiveSteps: " << this->AdaptiveSteps << "\n";
  os << indent << "StepScale: " << this->StepScale << "\n";
  os << indent << "SampleDistance: " << this->SampleDistance << "\n";
  os << indent << "Supersampling: " << this->Supersampling << "\n";
  os << indent << "EmptySpaceSkipping: " << this->EmptySpaceSkipping << "\n";
  os << indent << "UseJittering: " << this->UseJittering << "\n";
  os << indent << "ShadingModel: " << (this->ShadingModel == FUCHS ? "Fuchs" : "Phong") << "\n";
  os << indent << "IsosurfaceBisections: " << this->IsosurfaceBisections << "\n";
  os << indent << "MaximumNumberOfSteps: " << this->MaximumNumberOfSteps << "\n";
  os << indent << "CountSamples: " << this->CountSamples << "\n";
  os << indent << "TrimByDataBoundary: " << this->TrimByDataBoundary << "\n";
  os << indent << "NumberOfElements: " << this->GetNumberOfElements() << "\n";
  os << indent << "LastErrorMessage: " << this->Internals->Error << "\n";
}
