// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkSplineVizGPUBuffer
 * @brief   A GPU buffer read by shaders as a buffer texture (texelFetch).
 *
 * The SplineViz mappers keep their per-data arrays (the tubes buffer of Salm
 * §3, raw tensors) on the GPU in buffer objects bound as buffer textures
 * (samplerBuffer / usamplerBuffer / isamplerBuffer in GLSL). This helper owns
 * one vtkOpenGLBufferObject and the vtkTextureObject viewing it, uploads data
 * once per data change and counts the bytes it holds on the GPU.
 *
 * Pages: data with more texels than one buffer texture may hold
 * (GL_MAX_TEXTURE_BUFFER_SIZE: 2^27 on llvmpipe and on most GPUs, about a
 * million streamlines' nodes) is split into up to MaximumNumberOfPages
 * buffers of 2^GetPageShift() texels each, as MRtrix's viewer uploads its
 * tracks in pieces. The shaders then read the array through one function:
 * ApplyPaging() rewrites a stage's `uniform samplerBuffer name;` into one
 * sampler per page and its `texelFetch(name, i)` calls into `nameFetch(i)`,
 * which picks the page from the high bits of i. With one page (all data
 * that fits) the shader text is left as it is.
 *
 * Hostile sizes: an upload larger than the GPU allows (more texels than
 * MaximumNumberOfPages buffers hold, more bytes than a GLsizeiptr, or a
 * buffer the driver cannot allocate: GL_OUT_OF_MEMORY after glBufferData)
 * fails with an error that says what was asked and what the limit is, and
 * the buffer is released (IsValid() false), so that the mapper draws
 * nothing instead of stale or partial data. The environment variable
 * SPLINEVIZ_GPU_BUFFER_LIMIT (texels) lowers the limit, to test these paths
 * with small data. Upload() reports nothing itself: the mapper says so
 * with vtkErrorMacro, quoting the buffer's GetLastUploadError().
 *
 * Not wrapped (private to the module).
 */
#ifndef vtkSplineVizGPUBuffer_h
#define vtkSplineVizGPUBuffer_h

#include "vtkNew.h"
#include "vtkSmartPointer.h"

#include <cstddef>
#include <functional>
#include <initializer_list>
#include <string>
#include <vector>

class vtkOpenGLBufferObject;
class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkTextureObject;
class vtkWindow;

class vtkSplineVizGPUBuffer
{
public:
  vtkSplineVizGPUBuffer();
  ~vtkSplineVizGPUBuffer();

  /**
   * Upload `texels` texels of `components` components of VTK type `vtkType`
   * (VTK_FLOAT, VTK_UNSIGNED_INT, VTK_INT, VTK_UNSIGNED_CHAR...) and view them
   * with the GL internal format `glInternalFormat` (e.g. GL_RGBA32F,
   * GL_RG32UI, GL_RGBA8). Returns false (with a VTK error) on failure.
   */
  bool Upload(vtkOpenGLRenderWindow* window, const void* data, size_t texels, int components,
    int vtkType, unsigned int glInternalFormat);

  /**
   * The same, the data made piece by piece: `fill(first, count, destination)`
   * writes texels [first, first + count) to `destination`, a staging area of
   * at most PieceBytes, which is then copied into the buffer
   * (glBufferSubData). The whole data is never in memory twice on the CPU
   * side, and no single transfer exceeds PieceBytes (drivers refuse or stall
   * on very large ones).
   */
  bool UploadInPieces(vtkOpenGLRenderWindow* window, size_t texels, int components, int vtkType,
    unsigned int glInternalFormat,
    const std::function<void(size_t first, size_t count, void* destination)>& fill);
  static constexpr size_t PieceBytes = 32u << 20;

  /**
   * Bind the texture to a free texture unit and set `uniform` of `program` to
   * it; with several pages, page k > 0 is bound to `uniform` + "Page" + k
   * (the names ApplyPaging() declares).
   */
  void Activate(vtkShaderProgram* program, const char* uniform);
  void Deactivate();

  void ReleaseGraphicsResources(vtkWindow* window);

  /// True after a successful upload (false before, after a failed one and after release).
  bool IsValid() const { return !this->Pages.empty(); }

  /// The most buffers one array is split into (each takes a texture unit).
  static constexpr int MaximumNumberOfPages = 4;

  /**
   * Whether uploads may be split into pages (default off: an array over the
   * limit is refused). Only arrays that the shaders read through
   * ApplyPaging() may be paged.
   */
  void SetPageable(bool pageable) { this->Pageable = pageable; }
  bool GetPageable() const { return this->Pageable; }

  /// Buffers holding the last upload: 1 when it fit in one (0 before an upload).
  int GetNumberOfPages() const { return static_cast<int>(this->Pages.size()); }

  /// Texel i is texel (i & (2^shift - 1)) of page (i >> shift).
  int GetPageShift() const { return this->PageShift; }

  /**
   * Rewrite one shader stage's `source` to read the array bound to `uniform`
   * from this buffer's pages: its declaration `uniform <sampler> <uniform>;`
   * becomes one sampler per page and a function `<uniform>Fetch(int i)`
   * returning what texelFetch returns, and every `texelFetch(<uniform>,`
   * becomes `<uniform>Fetch(`. Nothing changes with one page or when the
   * stage does not declare `uniform`.
   */
  void ApplyPaging(std::string& source, const char* uniform) const;

  /// "pages/shift" of this buffer: shaders made for one layout fit another with the same key.
  std::string GetPagingKey() const;

  /**
   * The largest number of texels one buffer may hold in this context:
   * GL_MAX_TEXTURE_BUFFER_SIZE, or SPLINEVIZ_GPU_BUFFER_LIMIT when that is
   * set and smaller.
   */
  static size_t GetMaximumNumberOfTexels(vtkOpenGLRenderWindow* window);

  /**
   * `limit` lowered to SPLINEVIZ_GPU_BUFFER_LIMIT when that environment
   * variable holds a smaller number (the one place it is read; every mapper's
   * size limit goes through here, so tests can reach the refusal paths).
   */
  static size_t ApplyTestLimit(size_t limit);

  /// ", lowered by SPLINEVIZ_GPU_BUFFER_LIMIT" when that is set, else "" (for error messages).
  static const char* TestLimitNote();

  /**
   * True when the current OpenGL context is at least version `major`.0 or
   * lists `extension` (e.g. "GL_ARB_tessellation_shader"): the one place the
   * mappers ask what the context can do.
   */
  static bool ContextSupports(int major, const char* extension);

  /**
   * True when buffer textures may have the RGB32F format (three floats per
   * texel: OpenGL 4.0 or GL_ARB_texture_buffer_object_rgb32), so that
   * positions need not be padded to four floats.
   */
  static bool SupportsRGB32F() { return ContextSupports(4, "GL_ARB_texture_buffer_object_rgb32"); }

  /// Why this buffer's last Upload() failed, "" after a success (for the mapper's error message).
  const std::string& GetLastUploadError() const { return this->LastUploadError; }

  /**
   * The first non-empty GetLastUploadError() of `buffers`, listed in the order
   * they were uploaded, "" when none failed: the reason of a chain of uploads
   * (`ok = ok && b.Upload(...)`) that stops at its first failure.
   */
  static std::string FirstUploadError(std::initializer_list<const vtkSplineVizGPUBuffer*> buffers);

  /// Bytes held on the GPU (0 before the first upload).
  size_t GetNumberOfBytes() const { return this->Bytes; }
  size_t GetNumberOfTexels() const { return this->Texels; }

private:
  vtkSplineVizGPUBuffer(const vtkSplineVizGPUBuffer&) = delete;
  void operator=(const vtkSplineVizGPUBuffer&) = delete;

  /// One buffer object and the buffer texture that views it.
  struct Page
  {
    vtkSmartPointer<vtkOpenGLBufferObject> Buffer;
    vtkSmartPointer<vtkTextureObject> Texture;
  };

  /// Upload texels [first, first + count) of `fill` into a new page; false with LastUploadError.
  bool UploadPage(vtkOpenGLRenderWindow* window, size_t first, size_t count, int components,
    int vtkType, unsigned int glInternalFormat,
    const std::function<void(size_t first, size_t count, void* destination)>& fill);

  std::vector<Page> Pages;
  int PageShift = 0;
  bool Pageable = false;
  size_t Bytes = 0;
  size_t Texels = 0;
  std::string LastUploadError;
};

#endif
