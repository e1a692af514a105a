// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkTessellatedTubeMapper
 * @brief   Renders polylines as smooth spline tubes with the GPU tessellation unit.
 *
 * Salm, "Interactive Rendering of Spline Tubes", §3.1. Each polyline becomes a
 * tube whose axis, radius and color follow cubic Hermite splines through the
 * points (vtkSplineTubeCore): disks orthogonal to the axis, flat end caps.
 *
 * - Base mesh: a cylinder of quad patches per segment (BaseRings rings of
 *   BaseSides vertices), drawn instanced and bent along the position spline
 *   with the CPU's rotation-minimizing frames.
 * - Refinement (control stage): back patches and patches outside the frustum
 *   are culled; each edge gets the larger of a screen-space level (edges of
 *   MaxEdgeLength pixels, at most MaxTessellationLevel) and Salm's silhouette
 *   level (MaxSilhouetteEdgeLength, at most MaxSilhouetteTessellationLevel),
 *   from its two vertices only, so the tubes stay watertight.
 * - Evaluation stage: the refined vertices bent onto the tube, normals as in
 *   Salm Fig. 7; caps only at tube ends, their seams refined as silhouettes.
 * - Level of detail (LevelOfDetail, on by default; the paper's future work):
 *   per view (vtkTessellatedTubeLevels, in parallel with vtkSMPTools), the
 *   chunks of vtkSplineTubeCore (up to ChunkSegments segments) are culled and given the fewest
 * rings that keep chords within half MaxEdgeLength; tubes thin on screen are drawn as the
 * view-facing half of their wall, and short chunks of them without the tessellator
 *   (vtkTessellatedTubeThinVS.glsl: three vertices per ring, the fragment
 *   stage writing the exact depth and normal of the tube's front surface).
 *   TestTubeFidelity holds them to coverage IoU >= 0.98 and eye depth within
 *   a quarter radius on >= 98 % of the pixels. docs/design.md gives the measurements behind this.
 * - Fragment stage: VTK's lighting, opacity, clipping planes, depth peeling
 *   (one layer per tube, its front walls), cell and block picking; colors
 *   from the color spline per refined vertex; multisampling.
 *
 * GPU data (uploaded once per data change): vtkSplineTubeMapper's node
 * buffers plus the frames (4 bytes per node, octahedral); GetGPUMemorySize().
 *
 * VTK 9.2's vtkShader has no tessellation stages: the mapper compiles its
 * control and evaluation stages itself, attaches them to the program VTK
 * built and links again. Without tessellation (OpenGL < 4.0 and no
 * GL_ARB_tessellation_shader) it warns once and draws with a
 * vtkRayCastTubeMapper of the same settings.
 *
 * Limits: bulbs where the radius exceeds the curvature radius are not removed
 * (Salm Fig. 9); no point picking; a non-uniform actor scale is treated as
 * the uniform scale of the same volume change.
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
