// SPDX-License-Identifier: BSD-3-Clause
#include "vtkSplineVizGPUBuffer.h"

#include "vtkDataArray.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkType.h"

#include <vtk_glew.h>

#include <cstdlib>
#include <limits>
#include <algorithm>
#include <cstring>
#include <sstream>
#include <vector>
#include <string>

//------------------------------------------------------------------------------
std::string vtkSplineVizGPUBuffer::FirstUploadError(
  std::initializer_list<const vtkSplineVizGPUBuffer*> buffers)
{
  for (const vtkSplineVizGPUBuffer* buffer : buffers)
  {
    if (buffer && !buffer->LastUploadError.empty())
    {
      return buffer->LastUploadError;
    }
  }
  return std::string();
}

//------------------------------------------------------------------------------
vtkSplineVizGPUBuffer::vtkSplineVizGPUBuffer() = default;

//------------------------------------------------------------------------------
vtkSplineVizGPUBuffer::~vtkSplineVizGPUBuffer() = default;

//------------------------------------------------------------------------------
size_t vtkSplineVizGPUBuffer::GetMaximumNumberOfTexels(vtkOpenGLRenderWindow*)
{
  GLint glLimit = 0;
  glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &glLimit);
  return ApplyTestLimit(
    glLimit > 0 ? static_cast<size_t>(glLimit) : std::numeric_limits<size_t>::max());
}

//------------------------------------------------------------------------------
bool vtkSplineVizGPUBuffer::ContextSupports(int major, const char* extension)
{
  GLint contextMajor = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &contextMajor);
  if (contextMajor >= major)
  {
    return true;
  }
  GLint count = 0;
  glGetIntegerv(GL_NUM_EXTENSIONS, &count);
  for (GLint i = 0; i < count; ++i)
  {
    const char* name = reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, i));
    if (name && std::strcmp(name, extension) == 0)
    {
      return true;
    }
  }
  return false;
}

//------------------------------------------------------------------------------
size_t vtkSplineVizGPUBuffer::ApplyTestLimit(size_t limit)
{
  if (const char* forced = std::getenv("SPLINEVIZ_GPU_BUFFER_LIMIT"))
  {
    char* end = nullptr;
    const unsigned long long value = std::strtoull(forced, &end, 10);
    if (end != forced && value < limit)
    {
      limit = static_cast<size_t>(value);
    }
  }
  return limit;
}

//------------------------------------------------------------------------------
const char* vtkSplineVizGPUBuffer::TestLimitNote()
{
  return std::getenv("SPLINEVIZ_GPU_BUFFER_LIMIT") ? ", lowered by SPLINEVIZ_GPU_BUFFER_LIMIT" : "";
}

//------------------------------------------------------------------------------
bool vtkSplineVizGPUBuffer::Upload(vtkOpenGLRenderWindow* window, const void* data, size_t texels,
  int components, int vtkType, unsigned int glInternalFormat)
{
  const size_t texelBytes =
    static_cast<size_t>(components) * static_cast<size_t>(vtkDataArray::GetDataTypeSize(vtkType));
  return this->UploadInPieces(window, texels, components, vtkType, glInternalFormat,
    [&](size_t first, size_t count, void* destination)
    {
      std::memcpy(destination, static_cast<const unsigned char*>(data) + first * texelBytes,
        count * texelBytes);
    });
}

//------------------------------------------------------------------------------
bool vtkSplineVizGPUBuffer::UploadInPieces(vtkOpenGLRenderWindow* window, size_t texels,
  int components, int vtkType, unsigned int glInternalFormat,
  const std::function<void(size_t first, size_t count, void* destination)>& fill)
{
  const size_t texelBytes =
    static_cast<size_t>(components) * static_cast<size_t>(vtkDataArray::GetDataTypeSize(vtkType));
  this->LastUploadError.clear();
  const size_t limit = GetMaximumNumberOfTexels(window);
  if (texels > limit)
  {
    std::ostringstream msg;
    msg << "the data needs a GPU buffer of " << texels << " texels (" << texels * texelBytes
        << " bytes); this GPU allows at most " << limit
        << " texels per buffer (GL_MAX_TEXTURE_BUFFER_SIZE" << TestLimitNote()
        << "): nothing is drawn";
    this->LastUploadError = msg.str();
    this->ReleaseGraphicsResources(window);
    return false;
  }
  if (!this->Buffer)
  {
    this->Buffer = vtkSmartPointer<vtkOpenGLBufferObject>::New();
    this->Buffer->SetType(vtkOpenGLBufferObject::TextureBuffer);
  }
  // The buffer first (a zero-sized buffer texture is not allowed: one dummy
  // texel), then the data piece by piece.
  const size_t bytes = texels * texelBytes;
  const size_t allocate = texels > 0 ? bytes : 16;
  for (int i = 0; i < 64 && glGetError() != GL_NO_ERROR; ++i)
  {
    // errors of earlier calls are not this upload's
  }
  const unsigned char zeros[16] = { 0 };
  if (!this->Buffer->Upload(zeros, sizeof(zeros), vtkOpenGLBufferObject::TextureBuffer) ||
    !this->Buffer->Bind())
  {
    this->LastUploadError = "the GPU could not create a buffer: nothing is drawn";
    this->ReleaseGraphicsResources(window);
    return false;
  }
  glBufferData(GL_TEXTURE_BUFFER, static_cast<GLsizeiptr>(allocate), texels > 0 ? nullptr : zeros,
    GL_STATIC_DRAW);
  if (glGetError() == GL_OUT_OF_MEMORY)
  {
    this->LastUploadError = "the GPU could not allocate a buffer of " + std::to_string(allocate) +
      " bytes (GL_OUT_OF_MEMORY): nothing is drawn";
    this->Buffer->Release();
    this->ReleaseGraphicsResources(window);
    return false;
  }
  if (texels > 0)
  {
    const size_t perPiece = std::max<size_t>(1, PieceBytes / texelBytes);
    std::vector<unsigned char> staging(std::min(texels, perPiece) * texelBytes);
    for (size_t first = 0; first < texels; first += perPiece)
    {
      const size_t count = std::min(perPiece, texels - first);
      fill(first, count, staging.data());
      glBufferSubData(GL_TEXTURE_BUFFER, static_cast<GLintptr>(first * texelBytes),
        static_cast<GLsizeiptr>(count * texelBytes), staging.data());
    }
  }
  this->Buffer->Release();
  if (glGetError() == GL_OUT_OF_MEMORY)
  {
    this->LastUploadError = "the GPU ran out of memory filling a buffer of " +
      std::to_string(allocate) + " bytes (GL_OUT_OF_MEMORY): nothing is drawn";
    this->ReleaseGraphicsResources(window);
    return false;
  }
  if (this->Texture)
  {
    this->Texture->ReleaseGraphicsResources(window);
  }
  this->Texture = vtkSmartPointer<vtkTextureObject>::New();
  this->Texture->SetContext(window);
  this->Texture->SetInternalFormat(glInternalFormat);
  const unsigned int count = static_cast<unsigned int>(texels > 0 ? texels : 1);
  if (!this->Texture->CreateTextureBuffer(count, components, vtkType, this->Buffer))
  {
    this->LastUploadError = "the GPU could not create a buffer texture of " +
      std::to_string(count) + " texels: nothing is drawn";
    this->ReleaseGraphicsResources(window);
    return false;
  }
  this->Bytes = texels > 0 ? bytes : 0;
  this->Texels = texels;
  return true;
}

//------------------------------------------------------------------------------
void vtkSplineVizGPUBuffer::Activate(vtkShaderProgram* program, const char* uniform)
{
  if (!this->Texture)
  {
    return;
  }
  this->Texture->Activate();
  if (program->IsUniformUsed(uniform))
  {
    program->SetUniformi(uniform, this->Texture->GetTextureUnit());
  }
}

//------------------------------------------------------------------------------
void vtkSplineVizGPUBuffer::Deactivate()
{
  if (this->Texture)
  {
    this->Texture->Deactivate();
  }
}

//------------------------------------------------------------------------------
void vtkSplineVizGPUBuffer::ReleaseGraphicsResources(vtkWindow* window)
{
  if (this->Texture)
  {
    this->Texture->ReleaseGraphicsResources(window);
  }
  if (this->Buffer)
  {
    this->Buffer->ReleaseGraphicsResources();
  }
  this->Texture = nullptr;
  this->Bytes = 0;
  this->Texels = 0;
}
