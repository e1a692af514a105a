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
#include <regex>
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
  this->ReleaseGraphicsResources(window);
  const size_t limit = GetMaximumNumberOfTexels(window);
  // Pages of a power of two of texels (the shaders split an index with a
  // shift and a mask), as large as one buffer texture may be.
  int shift = 0;
  while (shift < 62 && (size_t(2) << shift) <= limit)
  {
    ++shift;
  }
  const size_t pageTexels = texels > limit ? (size_t(1) << shift) : std::max<size_t>(texels, 1);
  const size_t pages = texels > limit ? (texels + pageTexels - 1) / pageTexels : 1;
  const size_t allowed = this->Pageable ? static_cast<size_t>(MaximumNumberOfPages) : 1;
  if (pages > allowed || texels > static_cast<size_t>(std::numeric_limits<int>::max()))
  {
    std::ostringstream msg;
    msg << "the data needs a GPU array of " << texels << " texels (" << texels * texelBytes
        << " bytes); this GPU allows at most " << limit
        << " texels per buffer (GL_MAX_TEXTURE_BUFFER_SIZE" << TestLimitNote() << ")";
    if (this->Pageable)
    {
      msg << " and SplineViz splits an array into at most " << MaximumNumberOfPages
          << " buffers of " << pageTexels << " texels, up to 2^31 texels in all";
    }
    msg << ": nothing is drawn";
    this->LastUploadError = msg.str();
    return false;
  }
  this->PageShift = texels > limit ? shift : 0;
  for (size_t page = 0; page < pages; ++page)
  {
    const size_t first = page * pageTexels;
    const size_t count = std::min(pageTexels, texels - std::min(texels, first));
    if (!this->UploadPage(window, first, count, components, vtkType, glInternalFormat, fill))
    {
      this->ReleaseGraphicsResources(window);
      return false;
    }
  }
  this->Bytes = texels * texelBytes;
  this->Texels = texels;
  return true;
}

//------------------------------------------------------------------------------
bool vtkSplineVizGPUBuffer::UploadPage(vtkOpenGLRenderWindow* window, size_t first, size_t count,
  int components, int vtkType, unsigned int glInternalFormat,
  const std::function<void(size_t first, size_t count, void* destination)>& fill)
{
  const size_t texelBytes =
    static_cast<size_t>(components) * static_cast<size_t>(vtkDataArray::GetDataTypeSize(vtkType));
  Page page;
  page.Buffer = vtkSmartPointer<vtkOpenGLBufferObject>::New();
  page.Buffer->SetType(vtkOpenGLBufferObject::TextureBuffer);
  // The buffer first (a zero-sized buffer texture is not allowed: one dummy
  // texel), then the data piece by piece.
  const size_t bytes = count * texelBytes;
  const size_t allocate = count > 0 ? bytes : 16;
  for (int i = 0; i < 64 && glGetError() != GL_NO_ERROR; ++i)
  {
    // errors of earlier calls are not this upload's
  }
  const unsigned char zeros[16] = { 0 };
  if (!page.Buffer->Upload(zeros, sizeof(zeros), vtkOpenGLBufferObject::TextureBuffer) ||
    !page.Buffer->Bind())
  {
    this->LastUploadError = "the GPU could not create a buffer: nothing is drawn";
    page.Buffer->ReleaseGraphicsResources();
    return false;
  }
  glBufferData(GL_TEXTURE_BUFFER, static_cast<GLsizeiptr>(allocate), count > 0 ? nullptr : zeros,
    GL_STATIC_DRAW);
  if (glGetError() == GL_OUT_OF_MEMORY)
  {
    this->LastUploadError = "the GPU could not allocate a buffer of " + std::to_string(allocate) +
      " bytes (GL_OUT_OF_MEMORY): nothing is drawn";
    page.Buffer->Release();
    page.Buffer->ReleaseGraphicsResources();
    return false;
  }
  if (count > 0)
  {
    const size_t perPiece = std::max<size_t>(1, PieceBytes / texelBytes);
    std::vector<unsigned char> staging(std::min(count, perPiece) * texelBytes);
    for (size_t done = 0; done < count; done += perPiece)
    {
      const size_t n = std::min(perPiece, count - done);
      fill(first + done, n, staging.data());
      glBufferSubData(GL_TEXTURE_BUFFER, static_cast<GLintptr>(done * texelBytes),
        static_cast<GLsizeiptr>(n * texelBytes), staging.data());
    }
  }
  page.Buffer->Release();
  if (glGetError() == GL_OUT_OF_MEMORY)
  {
    this->LastUploadError = "the GPU ran out of memory filling a buffer of " +
      std::to_string(allocate) + " bytes (GL_OUT_OF_MEMORY): nothing is drawn";
    page.Buffer->ReleaseGraphicsResources();
    return false;
  }
  page.Texture = vtkSmartPointer<vtkTextureObject>::New();
  page.Texture->SetContext(window);
  page.Texture->SetInternalFormat(glInternalFormat);
  const unsigned int texels = static_cast<unsigned int>(count > 0 ? count : 1);
  if (!page.Texture->CreateTextureBuffer(texels, components, vtkType, page.Buffer))
  {
    this->LastUploadError = "the GPU could not create a buffer texture of " +
      std::to_string(texels) + " texels: nothing is drawn";
    page.Texture->ReleaseGraphicsResources(window);
    page.Buffer->ReleaseGraphicsResources();
    return false;
  }
  this->Pages.push_back(page);
  return true;
}

//------------------------------------------------------------------------------
void vtkSplineVizGPUBuffer::Activate(vtkShaderProgram* program, const char* uniform)
{
  for (size_t k = 0; k < this->Pages.size(); ++k)
  {
    vtkTextureObject* texture = this->Pages[k].Texture;
    texture->Activate();
    const std::string name = k == 0 ? std::string(uniform) : uniform + ("Page" + std::to_string(k));
    if (program->IsUniformUsed(name.c_str()))
    {
      program->SetUniformi(name.c_str(), texture->GetTextureUnit());
    }
  }
}

//------------------------------------------------------------------------------
void vtkSplineVizGPUBuffer::Deactivate()
{
  for (Page& page : this->Pages)
  {
    page.Texture->Deactivate();
  }
}

//------------------------------------------------------------------------------
void vtkSplineVizGPUBuffer::ReleaseGraphicsResources(vtkWindow* window)
{
  for (Page& page : this->Pages)
  {
    page.Texture->ReleaseGraphicsResources(window);
    page.Buffer->ReleaseGraphicsResources();
  }
  this->Pages.clear();
  this->PageShift = 0;
  this->Bytes = 0;
  this->Texels = 0;
}

//------------------------------------------------------------------------------
std::string vtkSplineVizGPUBuffer::GetPagingKey() const
{
  return std::to_string(this->Pages.size()) + "/" + std::to_string(this->PageShift);
}

//------------------------------------------------------------------------------
void vtkSplineVizGPUBuffer::ApplyPaging(std::string& source, const char* uniform) const
{
  if (this->Pages.size() < 2)
  {
    return;
  }
  const std::regex declaration(
    std::string("uniform\\s+([iu]?)samplerBuffer\\s+") + uniform + "\\s*;");
  std::smatch match;
  if (!std::regex_search(source, match, declaration))
  {
    return;
  }
  const std::string prefix = match[1].str();
  const std::string sampler = prefix + "samplerBuffer";
  const std::string value = prefix + "vec4";
  const std::string fetch = std::string(uniform) + "Fetch";
  std::ostringstream paged;
  paged << "uniform " << sampler << " " << uniform << ";\n";
  for (size_t k = 1; k < this->Pages.size(); ++k)
  {
    paged << "uniform " << sampler << " " << uniform << "Page" << k << ";\n";
  }
  paged << value << " " << fetch << "(int i)\n{\n"
        << "  int page = i >> " << this->PageShift << ";\n"
        << "  int texel = i & " << ((1 << this->PageShift) - 1) << ";\n";
  for (size_t k = 1; k < this->Pages.size(); ++k)
  {
    paged << "  if (page == " << k << ") return texelFetch(" << uniform << "Page" << k
          << ", texel);\n";
  }
  paged << "  return texelFetch(" << uniform << ", texel);\n}\n";
  std::string rewritten = source.substr(0, static_cast<size_t>(match.position(0)));
  std::string rest = match.suffix().str();
  // Every read after the declaration goes through the page function.
  const std::string call = std::string("texelFetch(") + uniform + ",";
  for (size_t at = rest.find(call); at != std::string::npos; at = rest.find(call, at))
  {
    rest.replace(at, call.size(), fetch + "(");
  }
  source = rewritten + paged.str() + rest;
}
