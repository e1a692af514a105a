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
 * **Occlusion culling** (OcclusionCulling, off by default: measured slower
 * on llvmpipe, see below). On a software rasterizer such as Mesa llvmpipe a
 * fragment stage that writes gl_FragDepth gets no early depth test, so every
 * fragment of every overlapping rectangle runs the intersection. With
 * culling on, a depth pre-pass first draws, into a depth texture of the
 * mapper's own the size of the viewport, one quad per segment that lies
 * inside the tube (a band around the segment's chord, narrower than the tube
 * by the chord's distance from the sub-segments, see svInnerBandHalfWidth;
 * facing the eye and moved toward it), with a fragment stage that writes
 * nothing, so that the rasterizer's own early depth test applies. The
 * ray-cast pass then starts every fragment with an explicit depth test: its
 * rectangle lies in front of its whole sub-segment, so when the pre-pass
 * depth at the pixel is nearer, something inside a tube, hence a tube's
 * surface, hides the sub-segment there and the fragment is discarded before
 * the intersection. The result is exactly that of the ray caster without
 * culling (only fragments that would lose the depth test are dropped;
 * TestRayCastTubeCulling compares both pixel for pixel, with depth peeling
 * and picking too). The pre-pass is skipped (and the tubes drawn as without
 * it) for translucent tubes (they do not hide each other), with clipping
 * planes (a clipped tube hides nothing) and for segments whose tube may
 * contain the ray origin (their band is left out). GetLastRenderCulled()
 * says whether the last render used it.
 *
 * Measured with Benchmarks/SplineVizTubeBenchmark (camera far, orbit, all
 * renderers in one run; Mesa llvmpipe on 2 cores shared with other jobs,
 * load average about 8.5, so wall times are 2-3x the process CPU times and
 * only the ratios of one run mean something). Median frame in ms, wall
 * (process CPU), and first frame in s:
 *
 * | data, viewport           | culling on        | culling off       | vtkTubeFilter (12 sides) |
 * |--------------------------|-------------------|-------------------|--------------------------|
 * | Fibers2, 800x600         | 1374 (628), 1.8   | 1328 (647), 1.5   | 2086 (710), 3.6          |
 * | Fibers2, 1200x768        | 3404 (872), 4.1   | 2776 (760), 2.4   | 2692 (708), 8.0          |
 * | long curves, 800x600     | 2791 (632), 2.4   | 2232 (561), 2.4   | 2744 (764), 8.7          |
 * | long curves, 1200x768    | 3084 (742), 3.1   | 2224 (778), 2.7   | 2169 (922), 5.5          |
 * | 1 M segments, 800x600    | 8023 (3359), 10.0 | 6782 (3061), 7.1  | 9051 (4391), 23.6        |
 * | 1 M segments, 1200x768   | 8955 (4329), 10.0 | 6534 (3492), 6.4  | 10051 (4997), 25.6       |
 *
 * ("long curves": 1,701 curves x 68 points, segments about 25 radii long.)
 * Re-measured on the idle machine (two runs, culling off, frame ratio to
 * the tube filter's and first frame shorter by): Fibers2 0.93 and 2.9-3.3x
 * at 800x600, 1.01-1.12 and 2.6-2.7x at 1200x768; long curves 0.81-0.87
 * and 3.6-3.8x, 0.84-0.90 and 2.7-4.0x; 1 M segments 0.66-0.70 and
 * 4.5-6.1x, 0.72-0.79 and 5.2-5.3x. With the rectangles from the geometry
 * stage (one run, 60 frames): Fibers2 0.80 and 5.1x at 800x600, 0.97 and
 * 4.4x at 1200x768; long curves 0.80 and 5.4x, 0.81 and 5.0x; 1 M segments
 * 0.50 and 10.0x, 0.57 and 9.8x. With the color spline read from one texel
 * per node (glsl/vtkSplineTubeColor.glsl) and every renderer run with the
 * same allocator (the benchmark's --allocator steady): Fibers2 0.90 and
 * 4.5x, 0.97 and 3.8x; long curves 0.79 and 4.5x, 0.93 and 4.5x; 1 M
 * segments 0.45 and 11.5x, 0.55 and 9.8x. Where that Fibers2 frame goes at
 * 1200x768: 77 % of the CPU samples in the fragment stage; with every
 * fragment through the closed form for cones it would take 165 ms, with
 * every fragment through the root finding 570-630 ms, in full 340 ms; 3 or
 * 4 sub-segments per segment (more of them straight) make it 1.3-2.2x
 * longer (more rectangles, more overlapping fragments). The refinement
 * steps are not where the root finding's time goes: 4, 10 and 20 bisection
 * steps per root took 296, 309 and 359 ms for that frame (one run), and
 * the Illinois method (regula falsi, superlinear on a bracket; at 10 steps
 * the normal from the hit's curve parameter within 2e-6 of the converged
 * one, against 2.4e-3 by bisection) took 368 ms at 10 steps and 348 ms at
 * 6 (a division and more selects per step; it needs 5 steps for the roots
 * of polyB' and 10 for those of polyB not to miss rays entering the tube
 * by 0.02-0.9 radii, TestRayCastTubeIntersection). So bisection stays; the
 * per-fragment set-up and the fixed bracketing structure are the cost. The
 * latest run (frame ratio to the tube filter's, first frame shorter by):
 * Fibers2 0.78 and 5.3x at 800x600, 0.97 and 4.3x at 1200x768 (0.89 and
 * 0.98 in two more runs); long curves 0.80 and 5.4x, 0.80 and 4.7x; 1 M
 * segments 0.45 and 10.6x, 0.50 and 10.9x. First frames measured after
 * another renderer has drawn in the process: the first draw with geometry
 * pays llvmpipe's one-time costs (about 0.35 s; Fibers2 at 1200x768 drawn
 * first took 0.73 s, 2.5x shorter than the tube filter's).
 * With the camera among the Fibers2 tubes (800x600, another run) culling on
 * took 2286 (1099) ms, off 2038 (939) ms, and root finding everywhere
 * (StraightTolerance 0, as before) 4077 (1970) ms. The pre-pass costs a
 * second vertex pass over all segments, a second shader and a depth texture
 * per frame, and saves little; presumably because llvmpipe shades fragments
 * in groups and can skip the intersection only when every fragment of a
 * group is culled, which is rare where tubes are a few pixels wide and the
 * bundle has gaps (not verified inside llvmpipe). The closed form for
 * straight segments, not the culling, is what brought the frame near the
 * tube filter's (the issue measured 0.56x the tube filter's speed on
 * Fibers2 at 1200x768 before it).
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
#include "vtkNew.h"          // for vtkNew
#include "vtkSmartPointer.h" // for vtkSmartPointer
#include "vtkSplineTubeMapper.h"

class vtkOpenGLBufferObject;
class vtkOpenGLFramebufferObject;
class vtkOpenGLVertexArrayObject;
class vtkShaderProgram;
class vtkTextureObject;

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

  ///@{
  /**
   * Cull hidden fragments before the intersection with a depth pre-pass of
   * bands inside the tubes (see the class comment). Exact, but measured
   * slower on llvmpipe at the views benchmarked, so off by default.
   */
  vtkSetMacro(OcclusionCulling, bool);
  vtkGetMacro(OcclusionCulling, bool);
  vtkBooleanMacro(OcclusionCulling, bool);
  ///@}

  /**
   * True when the last render drew the culling pre-pass.
   */
  vtkGetMacro(LastRenderCulled, bool);

  ///@{
  /**
   * For tests only: scale of the culling bands' half-width. 1 (the default)
   * is the proved bound (svInnerBandHalfWidth); larger values let the bands
   * stick out of the tubes, so that visible fragments are culled and the
   * picture is wrong. TestRayCastTubeCulling uses this as a negative control
   * (a comparison of culling on and off must notice it). Do not change.
   */
  vtkSetClampMacro(CullingBandScale, double, 0.0, 4.0);
  vtkGetMacro(CullingBandScale, double);
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
  bool GetNeedToRebuildShaders(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;

  int SubSegments = 2;
  int RootIterations = 10;
  int RootSamples = 3;
  double StraightTolerance = 0.02;
  bool OcclusionCulling = false;
  bool LastRenderCulled = false;
  double CullingBandScale = 1.0;

private:
  vtkRayCastTubeMapper(const vtkRayCastTubeMapper&) = delete;
  void operator=(const vtkRayCastTubeMapper&) = delete;

  /// Draw `quads` quads of 4 vertices (gl_VertexID = 4 * quad + corner) with
  /// the shared index pattern (QuadIndices bound by the caller).
  static void DrawQuads(vtkIdType quads);
  /// The index pattern of QuadsPerDraw quads (196 kB), uploaded on first use
  /// by the culling pre-pass (the ray-cast pass draws points); false when
  /// it could not be uploaded.
  bool UploadQuadIndices();
  /// The culling pre-pass into CullDepth; false when it could not be drawn.
  bool RenderCullingPass(vtkRenderer* ren, vtkActor* act);

  static constexpr int QuadsPerDraw = 16384; ///< 65536 vertices: 16-bit indices
  vtkNew<vtkOpenGLBufferObject> QuadIndices;
  bool QuadIndicesUploaded = false;

  // Occlusion culling: the pre-pass program, its framebuffer and depth
  // texture (the viewport's size), and whether this draw uses it.
  vtkShaderProgram* CullProgram = nullptr; ///< owned by the window's shader cache
  vtkNew<vtkOpenGLVertexArrayObject> CullVAO;
  vtkSmartPointer<vtkOpenGLFramebufferObject> CullFramebuffer;
  vtkSmartPointer<vtkTextureObject> CullDepth;
  int CullSize[2] = { 0, 0 };
  int CullOrigin[2] = { 0, 0 };
  bool CullThisDraw = false;
  bool CullShaders = false; ///< the ray-cast program was made with the culling test
  bool CullFailed = false;  ///< reported once; culling stays off for this context
};

#endif
