// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkRayCastTubeMapper
 * @brief   Renders polylines as exact, smooth spline tubes by GPU ray casting.
 *
 * Implements the ray-casting approach of Salm, "Interactive Rendering of
 * Spline Tubes", §3.2. Each polyline becomes a sphere-swept tube whose
 * centre, radius and color follow cubic Hermite splines through the points
 * (vtkSplineTubeCore); each cubic segment is approximated by SubSegments C1
 * quadratic sub-segments (vtkSplineTubeMath.h). Per sub-segment a rectangle
 * in the image plane bounds its projection; per fragment the view ray is
 * intersected with the spheres swept along the sub-segment: the roots of
 * polyB (degree 4, Salm eq. 6), then the minima of the entry distance (eq. 4),
 * each refined by RootIterations bisection steps (RootSamples brackets them).
 * The nearest hit gives the exact depth (gl_FragDepth: tubes intersect each
 * other and other geometry correctly, and parallel compositing is exact),
 * the normal, the color from the color spline, and rounded caps at the tube
 * ends. Lighting, scalar colors, opacity, clipping planes, depth peeling and
 * hardware picking (cell = the polyline, block index) go through VTK's usual
 * shader machinery.
 *
 * StraightTolerance (default 0.02): segments straight to within 2 % of their
 * radius and a quarter pixel are intersected with the round cone on their
 * chord in closed form; 0 finds the roots everywhere, as Salm does. Culling
 * and the interactive subset: see vtkSplineTubeMapper. On the GPU, uploaded
 * once per data change: the line mappers' node buffers (20 bytes per node,
 * 16 when all radii are equal, 4 more with scalar colors) and per tube its
 * cell and block ids (GetGPUMemorySize()). Translucent, every tube is one
 * layer, its nearest wall.
 *
 * Limits: no point picking (cell and block picking work); a non-uniform actor
 * scale is treated as the uniform scale with the same volume change. Why a
 * rectangle rather than the paper's box: docs/components.md; costs:
 * docs/performance.md.
 *
 * @sa vtkTessellatedTubeMapper vtkSplineTubeCore
 */
#ifndef vtkRayCastTubeMapper_h
#define vtkRayCastTubeMapper_h

#include "SplineVizRenderingModule.h" // for export macro
#include "vtkSplineTubeMapper.h"

#include <cstdint> // for std::uint32_t
#include <memory>  // for std::unique_ptr
#include <vector>  // for std::vector

class SPLINEVIZRENDERING_EXPORT vtkRayCastTubeMapper : public vtkSplineTubeMapper
{
public:
  static vtkRayCastTubeMapper* New();
  vtkTypeMacro(vtkRayCastTubeMapper, vtkSplineTubeMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Number of quadratic sub-segments per cubic segment (Salm uses 2, more
   * follow the cubic more closely). Even, from 2 to 16; odd values are
   * rounded up. Default 2.
   */
  void SetSubSegments(int n);
  vtkGetMacro(SubSegments, int);
  ///@}

  ///@{
  /**
   * Bisection steps per root in the fragment shader (Salm uses 10). Default 10.
   */
  vtkSetClampMacro(RootIterations, int, 1, 40);
  vtkGetMacro(RootIterations, int);
  ///@}

  ///@{
  /**
   * Samples of the entry-distance slope per real interval used to bracket
   * its minima before bisection (at least 2). Default 3 (enough to separate
   * the two minima of a sharp bend, see TestRayCastTubeIntersection).
   */
  vtkSetClampMacro(RootSamples, int, 2, 64);
  vtkGetMacro(RootSamples, int);
  ///@}

  ///@{
  /**
   * Segments and quadratic sub-segments that are straight to within this
   * fraction of their smallest radius (and a quarter pixel) are intersected
   * with the round cone on their chord in closed form instead of by root
   * finding (see the class comment); 0 always finds the roots, as Salm does.
   * Default 0.02.
   */
  vtkSetClampMacro(StraightTolerance, double, 0.0, 1.0);
  vtkGetMacro(StraightTolerance, double);
  ///@}

  ///@{
  /**
   * On (default): per view, the chunks whose segments are all straight there
   * (StraightTolerance and a quarter pixel, decided on the CPU with a
   * margin, so that the vertex stage decides the same) are drawn by a second
   * program whose fragment stage has no root finding; the rest by the full
   * one. The picture is the same; on a software rasterizer (llvmpipe) the
   * root-finding code alone, even where no fragment runs it, makes the
   * fragment stage a fifth slower (docs/performance.md). Off: one program.
   */
  vtkSetMacro(StraightChunkProgram, bool);
  vtkGetMacro(StraightChunkProgram, bool);
  vtkBooleanMacro(StraightChunkProgram, bool);
  ///@}

  /**
   * For tests only: the factor of the thresholds of that per-view choice;
   * 0.9 (default) leaves a margin for the vertex stage's float arithmetic. A
   * large factor sends curved chunks to the straight program (a negative
   * control: their picture changes).
   */
  vtkSetMacro(StraightChunkMargin, double);

  ///@{
  /// Chunks the last frame drew with the straight program and with the full one.
  vtkIdType GetLastNumberOfStraightChunks() const { return this->LastStraightChunks; }
  vtkIdType GetLastNumberOfRootFindingChunks() const { return this->LastRootFindingChunks; }
  ///@}

  size_t GetGPUMemorySize() override;
  void ReleaseGraphicsResources(vtkWindow* window) override;

protected:
  vtkRayCastTubeMapper();
  ~vtkRayCastTubeMapper() override;

  void UploadTubes(vtkOpenGLRenderWindow* window) override;
  void RenderPieceDraw(vtkRenderer* ren, vtkActor* act) override;

  void GetShaderTemplate(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override;
  void ReplaceShaderValues(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override;
  void ReplaceShaderClip(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override;
  void SetMapperShaderParameters(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;
  void SetCameraShaderParameters(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;

  int SubSegments = 2;
  int RootIterations = 10;
  int RootSamples = 3;
  double StraightTolerance = 0.02;

private:
  vtkRayCastTubeMapper(const vtkRayCastTubeMapper&) = delete;
  void operator=(const vtkRayCastTubeMapper&) = delete;

  /// The chunks of the group being drawn (first node, count).
  std::unique_ptr<vtkSplineVizGPUBuffer> ChunkList;
  /// Set while the straight program (no root finding) is built.
  bool BuildingStraightProgram = false;
  bool StraightChunkProgram = true;
  double StraightChunkMargin = 0.9;
  vtkIdType LastStraightChunks = 0;
  vtkIdType LastRootFindingChunks = 0;
  /// Draw `chunks` (upload their list) with `helper`'s program, built first.
  void DrawChunkList(vtkRenderer* ren, vtkActor* act, vtkOpenGLHelper& helper, bool straight,
    const std::vector<std::uint32_t>& chunks);
  /// Chunks per draw call (bounds the memory a software rasterizer's geometry stage takes).
  static constexpr size_t DrawChunks = 16384;
};

#endif
