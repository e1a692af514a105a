/**
 * @class   vtkRayCastTubeMapper
 * @brief   Renders polylines as exact, smooth spline tubes by GPU ray casting.
 *
 * Implements the ray-casting approach of Salm, "Interactive Rendering of
 * Spline Tubes", §3.2. Each polyline becomes a sphere-swept tube whose
 * centre, radius and color follow cubic Hermite splines through the points
 * (see vtkSplineTubeCore); each cubic segment is approximated by
 * SubSegments quadratic sub-segments (C1 continuous, see
 * vtkSplineTubeMath.h). Per sub-segment, a geometry shader rasterizes a tight
 * oriented bounding box; per fragment, the view ray is intersected with the
 * union of the spheres swept along the sub-segment in ray space: the real
 * intervals from the roots of polyB (degree 4, bracketed through its
 * derivatives, Salm eq. 6), then the minima of the entry distance f_t (eq. 4)
 * on each interval, each root refined by RootIterations bisection steps. The
 * nearest hit gives
 * - the exact depth (gl_FragDepth), so tubes intersect each other and any
 *   other geometry correctly, and parallel compositing (IceT) is exact;
 * - the normal, from the sphere centre to the hit point;
 * - the color, from the color spline at the hit's curve parameter;
 * - rounded caps at the tube ends (the end spheres).
 * Lighting, material, scalar coloring through lookup tables, opacity,
 * clipping planes, depth peeling passes and hardware picking (cell = the
 * polyline, composite block index) go through VTK's usual shader machinery.
 *
 * Proxy choice, measured on this machine (Mesa llvmpipe, 2 cores) with
 * Benchmarks/SplineVizTubeBenchmark: the paper's oriented box per
 * sub-segment, rasterized from a geometry shader emitting only the faces
 * turned to the eye, cost 2.4 times more per frame than a rectangle in the
 * image plane (4.2 s against 1.8 s for Fibers2 without any fragment work):
 * triangle setup and geometry-shader output dominate in a software
 * rasterizer, and the box needs up to 6 triangles against 2. So the proxy
 * is a rectangle oriented along the projected sub-segment, bounding the
 * projection of the spheres at its control points (the sub-segment's convex
 * hull; the oriented box clipped to the near plane when the camera is among
 * the tubes). The vertex stage sets it up once per sub-segment (one point
 * each) and a geometry stage emits its 4-vertex strip: built by the vertex
 * stage per corner (indexed triangles), the set-up ran four times per
 * sub-segment on the thread where llvmpipe shades vertices, 28 % of a
 * 1 M-segment frame; with the geometry stage that frame went from 1.43x to
 * 1.9-2.0x faster than vtkTubeFilter's at 800x600 and from 1.26x to
 * 1.5-1.8x at 1200x768 (Fibers2, whose frame is spent in the fragment
 * stage, unchanged within noise: 0.80-0.87 of the tube filter's frame at
 * 800x600, 0.97-1.03 at 1200x768). Instancing adds a per-instance cost (0.86 s against 0.72 s
 * for an earlier Fibers2 frame). (One rectangle per cubic segment for
 * segments small on screen, the fragment stage testing both sub-segments,
 * was measured too: no faster, since the per-fragment root finding, not the
 * rectangles, dominates; nor did rectangles cut short at the node spheres
 * the next proxy covers: llvmpipe shades fragments in 4 x 4 blocks, and
 * the blocks a rectangle of tubes 2-4 pixels wide touches barely change.)
 *
 * **Straight segments** (StraightTolerance, default 0.02): segments and
 * quadratic sub-segments whose spheres lie within 2 % of their smallest
 * radius and a quarter pixel of the round cone on their chord are
 * intersected with that cone in closed form (svIntersectRoundCone) instead of
 * by root finding; 0 finds the roots everywhere, as Salm does.
 *
 * **Culling**: only the chunks of segments in the view frustum and not
 * hidden behind tubes already drawn are drawn (OcclusionCulling,
 * vtkSplineTubeMapper); while the camera moves, a subset of the tubes that
 * fits the frame budget (InteractiveSubset).
 *
 * Data on the GPU (uploaded once per data change): per node the position,
 * radius, tangent and radius derivative (32 bytes) and, with scalar coloring,
 * the color and its derivative (8 bytes); per segment the first node and flags
 * (4 bytes) and the tube index (4 bytes); per tube its cell and block ids.
 * See GetGPUMemorySize().
 *
 * Limitations: translucent tubes show their nearest surface only (the far
 * wall of the same sub-segment is not drawn); point picking is not
 * supported (cell and block picking are); non-uniform actor scaling is
 * treated as the uniform scale with the same volume change.
 *
 * @sa vtkTessellatedTubeMapper vtkSplineTubeCore
 */
#ifndef vtkRayCastTubeMapper_h
#define vtkRayCastTubeMapper_h

#include "SplineVizModule.h" // for export macro
#include "vtkSplineTubeMapper.h"

#include <memory> // for std::unique_ptr

class SPLINEVIZ_EXPORT vtkRayCastTubeMapper : public vtkSplineTubeMapper
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
  /// Chunks per draw call (bounds the memory a software rasterizer's geometry stage takes).
  static constexpr size_t DrawChunks = 16384;
};

#endif
