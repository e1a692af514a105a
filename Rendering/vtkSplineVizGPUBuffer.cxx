#include "vtkSplineVizGPUBuffer.h"

#include "vtkDataArray.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkType.h"

#include <vtk_glew.h>

//------------------------------------------------------------------------------
vtkSplineVizGPUBuffer::vtkSplineVizGPUBuffer() = default;

//------------------------------------------------------------------------------
vtkSplineVizGPUBuffer::~vtkSplineVizGPUBuffer() = default;

//------------------------------------------------------------------------------
bool vtkSplineVizGPUBuffer::Upload(vtkOpenGLRenderWindow* window, const void* data, size_t texels,
  int components, int vtkType, unsigned int glInternalFormat)
{
  const size_t bytes = texels * components * vtkDataArray::GetDataTypeSize(vtkType);
  if (!this->Buffer)
  {
    this->Buffer = vtkSmartPointer<vtkOpenGLBufferObject>::New();
    this->Buffer->SetType(vtkOpenGLBufferObject::TextureBuffer);
  }
  // A zero-sized buffer texture is not allowed: keep one dummy texel.
  const unsigned char zeros[16] = { 0 };
  const void* source = texels > 0 ? data : zeros;
  const size_t uploadBytes = texels > 0 ? bytes : sizeof(zeros);
  if (!this->Buffer->Upload(static_cast<const unsigned char*>(source), uploadBytes,
        vtkOpenGLBufferObject::TextureBuffer))
  {
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
  this->Bytes = 0;
  this->Texels = 0;
}
