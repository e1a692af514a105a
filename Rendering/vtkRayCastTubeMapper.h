// SPDX-License-Identifier: BSD-3-Clause
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
 * The proxy is a rectangle in the image plane per sub-segment, oriented
 * along its projection and bounding the spheres at its control points (its
 * convex hull; the oriented box clipped to the near plane when the camera is
 * among the tubes): set up once per sub-segment in the vertex stage (one
 * point each), emitted as a 4-vertex strip by the geometry stage. On a
 * software rasterizer it costs less than the paper's box (2 triangles
 * against up to 6); the measurements are in docs/performance.md.
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
 * Data on the GPU (uploaded once per data change): the line mappers' node
 * buffers (vtkSplineTubeMapper: 20 bytes per node, 16 when all radii are
 * equal, 4 more with scalar colors) and
 * per tube its cell and block ids. See GetGPUMemorySize().
 *
 * Translucent (actor opacity below 1, with VTK's depth peeling or its
 * order-independent translucency), every tube is one layer, its nearest
 * wall: each rectangle keeps only the hits between the planes normal to the
 * curve at its ends, so that neighbouring sub-segments, which share their
 * end spheres, never both draw a point (TestTubeTranslucency).
 *
 * Limitations: point picking is not
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
