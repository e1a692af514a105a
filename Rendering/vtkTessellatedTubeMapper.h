// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkTessellatedTubeMapper
 * @brief   Renders polylines as smooth spline tubes with the GPU tessellation unit.
 *
 * Implements the tessellation-based approach of Salm, "Interactive Rendering
 * of Spline Tubes", §3.1. Each polyline becomes a tube whose axis, radius and
 * color follow cubic Hermite splines through the points (see
 * vtkSplineTubeCore); its cross-sections are disks orthogonal to the axis
 * (the disk model), closed by flat end caps.
 *
 * - **Base tessellation**: one cylinder mesh of quad patches, BaseRings vertex
 *   rings of BaseSides vertices plus the two cap centers, drawn instanced, one
 *   instance per segment of all tubes (a single draw call). The vertex stage
 *   reads the segment's nodes from the tubes buffer and bends the mesh along
 *   the position spline: the offset from the axis is built from the
 *   orthogonal vectors the CPU propagated along each tube (rotation-minimizing
 *   frames, vtkSplineTubeCore), interpolated, re-projected onto the
 *   cross-section plane and normalized, and scaled by the radius spline.
 * - **Level of detail** (LevelOfDetail, on by default; beyond the paper,
 *   which proposes it as future work): on llvmpipe and for large data the
 *   base geometry itself dominates the frame time (Salm §3.3 observes the
 *   same on a GPU). Per view, chunks of up to 16 consecutive segments are
 *   culled against the view frustum and given the fewest vertex rings (from
 *   BaseRings down to 2, halving the intervals) whose spacing stays below half
 *   MaxEdgeLength on screen. Per tube, from its widest visible part, the
 *   circumference in steps of twice MaxSilhouetteEdgeLength gives the
 *   vertices needed per ring: up to 8, the tube is thin and each ring is
 *   the view-facing half of the cross-section, turned to the eye per vertex
 *   by the evaluation stage (from one silhouette point, exact also in
 *   perspective, through the point nearest the eye to the other), so that
 *   thin tubes keep their outline and their depth: at least 3 intervals,
 *   more where the tube turns toward the eye (the depth error of a chord
 *   grows as 1 / sin of the angle between the tangent and the ray), the
 *   vertices between the silhouettes placed so that the chords straddle the
 *   circle (depth within 0.21 radii for 3 intervals); the level along
 *   keeps the chords within a quarter pixel of the curve on screen and within
 *   a tenth of the radius in space (from the curvature of the node chain or
 *   the segment's tangents; inside a run the vertices move out by half a
 *   chord's sagitta so that the chords straddle the curve, and 1.7 times
 *   longer chords keep the bound). A chunk of thin tube at most 1,024
 *   pixels long on screen is drawn **without the tessellator**: the CPU
 *   classification computes these levels for the whole chunk (the rings
 *   along, rounded up to a ladder of 20 values; the chunk is thin when its
 *   end rings need at most 8 intervals) and bins the chunks by them; one
 *   instanced draw per bin of an indexed triangle mesh of three vertices per
 *   ring, placed by the vertex stage (vtkTessellatedTubeThinVS.glsl): the
 *   two silhouette points of the ring (tubeViewFacingFrame, as the
 *   evaluation stage's half rings, so that neighbouring chunks and patches
 *   meet without cracks) and the point nearest the eye. The fragment stage
 *   (vtkTessellatedTubeThinFS.glsl) finds the tube's front surface along
 *   each pixel's ray from there, on the cylinder of the interpolated ring
 *   center, radius and tangent (svCylinderFrontDistance), and writes its
 *   depth and normal: exact for straight tubes, within the chords' sagitta
 *   elsewhere; fragments whose surface point lies beyond a tube's end are
 *   dropped for its cap. This replaced half rings of 3-5 intervals (the
 *   polygon carried the depth, within 0.21 radii for 3, more intervals
 *   where the tube turns toward the eye, whose chords straddled the circle):
 *   2-3 times the triangles and vertices, whose shading, set-up and binning
 *   on llvmpipe's application thread were the frame (a profile of the long
 *   curves at 800x600: 47 % of the samples on that thread, 23 % in the
 *   vertex shader and triangle set-up code), while llvmpipe's missing early
 *   depth test for a shader that writes gl_FragDepth costs little for
 *   tubes a few pixels wide (the same frames with and without such a write:
 *   79 and 86 ms). Two vertices per ring (the silhouettes only) would halve
 *   the triangles again (frame 0.22-0.30 of the tube filter's) but lose the
 *   half ellipse a ring turned to the eye shows beyond its silhouette points
 *   (21 pixels missing in TestTessellatedTubeReference's whole view, 8
 *   allowed). The control stage, the tessellator and its per-patch
 *   bookkeeping run on the application's thread too and cost more than the
 *   vertex shading (a profile of a Fibers2 frame: 65 % of the samples on
 *   that thread, the rasterizer threads half idle; without them 44 % and the
 *   rasterizer threads busy).
 *   The caps of thin chunks are drawn by the same program (tubeCapDraw): the
 *   disk's inscribed octagon (the control stage's level for such caps), two
 *   of its vertices the silhouette points where the wall's half rings end,
 *   listed per view only when turned to the eye (ThinCapVisible, the control
 *   stage's test), their normals turned to the eye by the vertex stage, so
 *   that the thin program's fragment stage needs no gl_FrontFacing flip. As
 *   patches they were the last tessellation draw of such views, and
 *   llvmpipe's evaluation stage grows its output buffer patch by patch (a
 *   realloc per patch, in a heap trimmed and mapped in again every frame).
 *   Longer chunks, and chunks whose rings need more intervals, are patches
 *   as before (a chunk one patch, or each segment one patch beyond 1,024
 *   pixels). Measured by
 *   TestTubeFidelity against vtkTubeFilter (64 sides) on DIPY's cb_2 bundle
 *   and synthetic curls at the whole view and zoomed 2x and 5x: coverage
 *   IoU 0.985-0.999 and eye depth within a quarter radius on 98.8-100 % of
 *   the shared pixels (96.9-100 % with the half rings' polygons; before thin
 *   tubes stayed tubes: IoU 0.92 and 30 % on cb_2's whole view).
 *   The price on llvmpipe (one idle run of SplineVizTubeBenchmark, camera
 *   far, 60 frames, see docs/performance.md): about one chord per segment on curved
 *   data; the frame 0.39 (800x600) and 0.43 (1200x768) times vtkTubeFilter's
 *   (12 sides) on Fibers2, 0.40 and 0.35 on the long smooth curves, 0.30 for
 *   1 M segments (with the half rings 0.45-0.51, 0.37-0.47, 0.53,
 *   0.47-0.50 and 0.40-0.47; identical runs differ by about 10 % on the
 *   test machine). The Fibers2 frames at 800x600 that
 *   used to vary from 0.15 to 0.35 s were the heap's: llvmpipe allocates each
 *   scene's bins (tens of MB per frame) in 64 kB blocks and frees them after
 *   the scene, and glibc returns the top of the heap to the system until the
 *   process first frees a large mapped block; the renderer that runs first
 *   in a fresh process then maps those pages in again every frame (the
 *   benchmark now runs every renderer with the same allocator, see its
 *   --allocator option). Before thin tubes stayed tubes: 0.34 on Fibers2
 *   (inexact) and 0.96 on the long curves;
 *   more than 8, the base mesh has at least half the needed vertices per ring
 *   (BaseSides halved down to 4) and Salm's refinement does the rest. The
 *   side count is chosen per tube so that the rings at the junctions always
 *   match (no cracks). One instanced draw per (rings, sides) bin reads its
 *   segments from an instance list; caps are drawn for the tubes' end
 *   segments only. The classification is O(chunks + segments) CPU work per
 *   view change (vtkSMPTools), skipped when the view did not change. With
 *   LevelOfDetail off, every segment is drawn with the full base mesh, as in
 *   the paper.
 * - **Refinement** (tessellation control stage): back-patch culling (a patch
 *   is dropped when all its vertex normals face away from the eye), frustum
 *   culling, then per edge the larger of a screen-space criterion (edges of
 *   at most MaxEdgeLength pixels, level at most MaxTessellationLevel) and the
 *   silhouette criterion (the edge's view-space length divided by the clip w
 *   of its midpoint, in pixels, weighted by its closeness to the silhouette:
 *   1 when its end normals face opposite ways, else the cube of how flat the
 *   angle between its normals and the rays to the eye is, for edges of at most
 *   MaxSilhouetteEdgeLength pixels, level at most
 *   MaxSilhouetteTessellationLevel; Salm's fix for notchy silhouettes). Inner
 *   levels are the maxima of the opposite outer levels. Levels depend only on
 *   the edge's two vertices, so patches sharing an edge (also across
 *   segments) agree and the tubes stay watertight.
 * - **Evaluation stage**: the refined vertices are bent onto the tube again;
 *   the wall normal is the offset vector projected onto the plane of the
 *   numerically determined surface tangent (Salm Fig. 7).
 * - **End caps** (Capping): flat disks at the ends of each tube, with the seam
 *   (the cap's rim) refined like a silhouette (Salm Fig. 11); caps between
 *   the segments of a tube are culled.
 * - **Fragment stage**: per-pixel normal, VTK's lighting, opacity, clipping
 *   planes, depth peeling and hardware picking (cell = the polyline,
 *   composite block index). The color spline of mapped scalars is evaluated
 *   per refined vertex by the evaluation stage and interpolated per pixel
 *   (Salm evaluates it per pixel; at the refined edge lengths the result is
 *   the same, and per pixel it cost a quarter of the frame on llvmpipe).
 * - Multisampling works when the render window has samples; the actor's
 *   wireframe representation shows the tessellated triangles.
 *
 * Data on the GPU (uploaded once per data change): the node buffers of
 * vtkSplineTubeMapper (per node 20 bytes, 16 when all radii are equal, 4
 * more with scalar coloring; per
 * tube 8 bytes) plus the orthogonal vectors, octahedral
 * encoded in 4 bytes per node (Salm's suggested compact format), and the base
 * meshes' index buffer (once; 3 KB of it for the thin-tube mesh, whose rows
 * alternate between the two ends of a run so that the first n rows are the
 * mesh of n rows). See GetGPUMemorySize().
 *
 * VTK 9.2's vtkShader has no tessellation stages: the mapper lets VTK build
 * and link the vertex and fragment stages (with all of VTK's shader
 * replacements), then compiles its control and evaluation stages with raw
 * OpenGL, attaches them to the same program and links it again before any
 * uniform is looked up. Without tessellation shaders (OpenGL < 4.0 and no
 * GL_ARB_tessellation_shader), the mapper warns once and draws the tubes
 * with a vtkRayCastTubeMapper with the same settings instead.
 *
 * Translucent, every tube is one layer, its front walls (back patches are
 * culled; TestTubeTranslucency).
 *
 * Limitations: bulbs (self-intersections of the disk model where the radius
 * is large compared to the curvature radius) are not removed (Salm Fig. 9);
 * point picking is not supported (cell and block picking are); non-uniform
 * actor scaling is treated as the uniform scale with the same volume change.
 *
 * @sa vtkRayCastTubeMapper vtkSplineTubeCore vtkSplineTubeMapper
 */
#ifndef vtkTessellatedTubeMapper_h
#define vtkTessellatedTubeMapper_h

#include "SplineVizRenderingModule.h" // for export macro
#include "vtkSmartPointer.h"          // for vtkSmartPointer
#include "vtkSplineTubeMapper.h"

#include <memory> // for std::unique_ptr
#include <string> // for std::string

class vtkOpenGLBufferObject;
class vtkRayCastTubeMapper;
class vtkRenderWindow;
class vtkSplineVizGPUBuffer;
class vtkTessellatedTubeLevels;

class SPLINEVIZRENDERING_EXPORT vtkTessellatedTubeMapper : public vtkSplineTubeMapper
{
public:
  static vtkTessellatedTubeMapper* New();
  vtkTypeMacro(vtkTessellatedTubeMapper, vtkSplineTubeMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Largest screen-space edge length (pixels) the refinement aims at
   * (Salm's first criterion). Default 16.
   */
  vtkSetClampMacro(MaxEdgeLength, double, 0.5, 1e6);
  vtkGetMacro(MaxEdgeLength, double);
  ///@}

  ///@{
  /**
   * Largest edge length (pixels) near the silhouettes and along the rims of
   * the caps (Salm's silhouette criterion and finer seams). Default 4.
   */
  vtkSetClampMacro(MaxSilhouetteEdgeLength, double, 0.5, 1e6);
  vtkGetMacro(MaxSilhouetteEdgeLength, double);
  ///@}

  ///@{
  /**
   * Upper bound of the tessellation level from the screen-space criterion.
   * 1 with MaxSilhouetteTessellationLevel 1 draws the base mesh only.
   * Default 5 (Salm). At most 64.
   */
  vtkSetClampMacro(MaxTessellationLevel, int, 1, 64);
  vtkGetMacro(MaxTessellationLevel, int);
  ///@}

  ///@{
  /**
   * Upper bound of the tessellation level from the silhouette criterion and
   * of the caps' seams. Default 7 (Salm). At most 64.
   */
  vtkSetClampMacro(MaxSilhouetteTessellationLevel, int, 1, 64);
  vtkGetMacro(MaxSilhouetteTessellationLevel, int);
  ///@}

  ///@{
  /**
   * Number of vertex rings of the base mesh along each segment (at least 2).
   * Default 16 (Salm).
   */
  vtkSetClampMacro(BaseRings, int, 2, 1024);
  vtkGetMacro(BaseRings, int);
  ///@}

  ///@{
  /**
   * Number of vertices per ring of the base mesh (at least 3). Default 8 (Salm).
   */
  vtkSetClampMacro(BaseSides, int, 3, 1024);
  vtkGetMacro(BaseSides, int);
  ///@}

  ///@{
  /**
   * Choose the base mesh per view (see the class comment). Default on.
   */
  vtkSetMacro(LevelOfDetail, bool);
  vtkGetMacro(LevelOfDetail, bool);
  vtkBooleanMacro(LevelOfDetail, bool);
  ///@}

  ///@{
  /**
   * Close the tubes with flat caps at their ends. Default on.
   */
  vtkSetMacro(Capping, bool);
  vtkGetMacro(Capping, bool);
  vtkBooleanMacro(Capping, bool);
  ///@}

  ///@{
  /**
   * Count the triangles the tessellation generates (a GL_PRIMITIVES_GENERATED
   * query around the draw; it waits for the draw to finish, so leave it off
   * for interactive rendering). Default off.
   */
  vtkSetMacro(CountPrimitives, bool);
  vtkGetMacro(CountPrimitives, bool);
  vtkBooleanMacro(CountPrimitives, bool);
  ///@}

  /**
   * Triangles generated by the last render (with CountPrimitives on; 0 otherwise).
   */
  vtkGetMacro(NumberOfPrimitivesGenerated, vtkTypeUInt64);

  /**
   * Whether the OpenGL context of `window` has tessellation shaders (makes
   * the context current). Without them the mapper draws with a
   * vtkRayCastTubeMapper.
   */
  static bool IsTessellationSupported(vtkRenderWindow* window);

  /**
   * True when the last render fell back to the ray-cast mapper.
   */
  vtkGetMacro(UsingFallback, bool);

  /**
   * Segments drawn by the last render with each number of vertex rings and
   * sides (level-of-detail statistics): a string "rings x sides: segments"
   * per bin ("chunks ..." and "thin ...": runs of segments as one patch or
   * one thin-tube draw, counted in runs; for thin-tube draws the sides are
   * the vertices per ring), and the number of segments culled on the CPU.
   */
  std::string GetLevelOfDetailSummary();

  /**
   * Bytes of tube data on the GPU: the tubes buffer, the orthogonal vectors,
   * the instance list and the base meshes.
   */
  size_t GetGPUMemorySize() override;

  void ReleaseGraphicsResources(vtkWindow* window) override;

protected:
  // The fallback ray caster shares this mapper's input: reported to the
  // garbage collector so that the pipeline cycle through it is collected.
  void ReportReferences(vtkGarbageCollector* collector) override;

  vtkTessellatedTubeMapper();
  ~vtkTessellatedTubeMapper() override;

  void RenderPiece(vtkRenderer* ren, vtkActor* act) override;
  void UploadTubes(vtkOpenGLRenderWindow* window) override;
  void RenderPieceDraw(vtkRenderer* ren, vtkActor* act) override;

  void UpdateShaders(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;
  /// The base's per-node arrays, tubeFrames and the per-frame tubeInstances.
  void GetPagedBuffers(std::vector<PagedBuffer>& buffers) override;
  void GetShaderTemplate(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override;
  void ReplaceShaderValues(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override;
  void ReplaceShaderClip(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override;
  void SetMapperShaderParameters(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;
  void SetCameraShaderParameters(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;

  ///@{
  /**
   * The GLSL of the tessellation stages (without the #version line), with
   * the shared math substituted. Tests override them to check that broken
   * shaders are caught.
   */
  virtual std::string GetTessellationControlShaderSource();
  virtual std::string GetTessellationEvaluationShaderSource();
  ///@}

  double MaxEdgeLength = 16.0;
  double MaxSilhouetteEdgeLength = 4.0;
  int MaxTessellationLevel = 5;
  int MaxSilhouetteTessellationLevel = 7;
  int BaseRings = 16;
  int BaseSides = 8;
  bool LevelOfDetail = true;
  bool Capping = true;
  bool CountPrimitives = false;
  vtkTypeUInt64 NumberOfPrimitivesGenerated = 0;
  bool UsingFallback = false;
  // Set while the program of the thin-tube draws (vertex and fragment stages
  // only) is built and its uniforms set.
  bool BuildingThinProgram = false;

private:
  vtkTessellatedTubeMapper(const vtkTessellatedTubeMapper&) = delete;
  void operator=(const vtkTessellatedTubeMapper&) = delete;

  /// Compile our stages (once per context), attach them to `program` and
  /// link it again, unless it already has them. False (with an error) on failure.
  bool LinkTessellationStages(vtkShaderProgram* program, vtkOpenGLRenderWindow* window);
  void ReleaseTessellationStages();
  /// The base meshes of every (rings, sides) level of detail, in one index buffer.
  bool UploadBaseMeshes();
  /// Classify the chunks for this view (vtkTessellatedTubeLevels::ClassifyView).
  void ClassifyView(vtkRenderer* ren, vtkActor* act);
  /// Draw the chunks of one visibility group: their bins, through both programs.
  void DrawChunks(vtkRenderer* ren, vtkActor* act, const std::vector<std::uint32_t>& chunks);

  std::unique_ptr<vtkTessellatedTubeLevels> Levels;
  std::unique_ptr<vtkSplineVizGPUBuffer> InstancesBuffer;
  std::unique_ptr<vtkSplineVizGPUBuffer> FramesBuffer;
  vtkSmartPointer<vtkOpenGLBufferObject> BaseMeshes;

  unsigned int ControlShader = 0;
  unsigned int EvaluationShader = 0;
  std::string StagesVersion; ///< #version line the stages were compiled with
  std::string StagesPaging;  ///< page layouts of the arrays the stages were compiled for
  bool StagesFailed = false;
  unsigned int PrimitivesQuery = 0;

  vtkSmartPointer<vtkRayCastTubeMapper> Fallback;
  bool FallbackWarned = false;
};

#endif
