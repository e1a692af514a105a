// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkSplineTubeMapper
 * @brief   Base class of the SplineViz spline-tube mappers.
 *
 * What the line mappers (vtkRayCastTubeMapper, Salm §3.2,
 * vtkTessellatedTubeMapper, Salm §3.1, and vtkStylizedLineMapper) share:
 *
 * - input: vtkPolyData or a composite data set of vtkPolyData, as ParaView
 *   gives it; every polyline (VTK_LINE and VTK_POLY_LINE cells) of every
 *   block becomes a tube, all drawn together;
 * - radius: a constant Radius (world units; by default a fraction of the
 *   data's diagonal), or the per-point RadiusArray times RadiusScale; never
 *   narrower than MinimumPixelWidth pixels on screen;
 * - color: the actor's property, or scalars mapped through the mapper's usual
 *   settings (ScalarVisibility, ScalarMode, SelectColorArray, lookup table,
 *   ScalarRange, ColorMode, as vtkPolyDataMapper), interpolated along the
 *   tubes by the color spline;
 * - the per-data preparation by vtkSplineTubeCore, redone only when the
 *   input, the radius settings or the coloring change; bounds that include
 *   the radii;
 * - the tubes buffer on the GPU (Salm §3, Fig. 3), buffer textures read with
 *   texelFetch (glsl/vtkSplineTubeNodes.glsl): per node position and radius
 *   (the position alone when every node has the same radius, then a uniform)
 *   and the tube with its end flags; per tube the cell and block ids for
 *   picking; with scalar coloring, per node the color. 20 bytes per node (16
 *   with one radius), 4 more with colors, uploaded in pieces from the input
 *   (no copy kept on the CPU side); derivatives are computed from the
 *   neighbours where they are used;
 * - per frame, only the chunks in the frustum and not hidden behind what is
 *   drawn (OcclusionCulling), and while the camera moves a subset of the
 *   lines sized to the frame budget (InteractiveSubset); VisibilityArray,
 *   DirectionColoring, EndpointMarkers and a slab crop;
 * - the fragment-shader code for the color spline and for hardware picking.
 *
 * Subclasses upload what their shaders need (UploadTubes(), usually through
 * UploadTubeBuffers()) and draw (RenderPieceDraw()).
 */
#ifndef vtkSplineTubeMapper_h
#define vtkSplineTubeMapper_h

#include "SplineVizRenderingModule.h" // for export macro
#include "vtkNew.h"                   // for vtkNew
#include "vtkPlane.h"                 // for vtkNew<vtkPlane>
#include "vtkSmartPointer.h"          // for the endpoint markers
#include "vtkWeakPointer.h"           // for LevelOfDetailOf
#include "vtkOpenGLPolyDataMapper.h"

#include <chrono>     // for std::chrono::steady_clock
#include <cstdint>    // for std::uint32_t
#include <functional> // for std::function
#include <iosfwd>     // for std::ostream
#include <map>        // for std::map
#include <memory>     // for std::unique_ptr
#include <string>     // for std::string
#include <utility>    // for std::pair
#include <vector>     // for std::vector

class vtkMatrix4x4;
class vtkOpenGLSphereMapper;
class vtkPlane;
class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkSplineTubeCore;
class vtkSplineTubeVisibility;
class vtkSplineVizGPUBuffer;

class SPLINEVIZRENDERING_EXPORT vtkSplineTubeMapper : public vtkOpenGLPolyDataMapper
{
public:
  vtkTypeMacro(vtkSplineTubeMapper, vtkOpenGLPolyDataMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Constant tube radius in world units, used when no RadiusArray is set.
   * 0 (the default): automatic, AutomaticRadiusFactor times the diagonal of
   * AutomaticRadiusBounds (by default the input's bounds); see
   * ComputeAutomaticRadius(). GetEffectiveRadius() is the radius used by the
   * last build of the tubes.
   */
  vtkSetClampMacro(Radius, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(Radius, double);
  double GetEffectiveRadius() const { return this->EffectiveRadius; }
  ///@}

  ///@{
  /**
   * The bounds the automatic radius (Radius 0) is taken from. Invalid bounds
   * (the default, minimum above maximum): the input's own bounds. ParaView's
   * representations set the bounds of the whole data set here, so that every
   * rank of a parallel server draws its piece with the same radius.
   */
  vtkSetVector6Macro(AutomaticRadiusBounds, double);
  vtkGetVector6Macro(AutomaticRadiusBounds, double);
  ///@}

  /**
   * The automatic radius for data within `bounds`: AutomaticRadiusFactor
   * times the bounds' diagonal (0.01 for empty or single-point bounds).
   * Measured on tractograms in mm: DIPY's cb_2 bundle (160 mm diagonal)
   * gets 0.4 mm, a whole brain (260 mm) 0.65 mm, tubes 3-5 pixels wide when
   * the data fills a 1200x768 view; a unit cube's lines get 0.0043.
   */
  static double ComputeAutomaticRadius(const double bounds[6]);
  static constexpr double AutomaticRadiusFactor = 0.0025;

  ///@{
  /**
   * The narrowest a tube is drawn, in pixels across (default 1): a tube
   * thinner than that on the screen is drawn with the radius that makes it
   * this wide at its depth, so that thin and far tubes stay visible as
   * lines, as VTK's lines do, instead of breaking up into dots (a pixel is
   * lit only where a ray hits the tube). The depth is that of the widened
   * tube (within half a pixel's size of the exact one). 0: the exact radius
   * at any size.
   */
  vtkSetClampMacro(MinimumPixelWidth, double, 0.0, 64.0);
  vtkGetMacro(MinimumPixelWidth, double);
  ///@}

  ///@{
  /**
   * Name of a one-component point array with the radius at each point, in
   * world units (times RadiusScale). nullptr or "" (default): the constant
   * Radius. Points with a zero, negative or NaN radius make their polyline
   * skipped with a warning; a missing array is an error (nothing is drawn
   * for that block).
   */
  vtkSetStringMacro(RadiusArray);
  vtkGetStringMacro(RadiusArray);
  ///@}

  ///@{
  /**
   * Name of a one-component cell array that says which polylines to draw
   * (a streamline selection, e.g. vtkStreamlineSelection's "Selected"
   * array): a polyline whose value is 0 or NaN is left out, any other value
   * draws it. nullptr or "" (default): all are drawn. When only this
   * array's values change (the points, lines and coloring arrays are the
   * same arrays as before), the next frame draws the new selection without
   * building or uploading the tubes again: the hidden lines' chunks are
   * dropped from the per-view work. A block without the array is drawn
   * whole, with an error. The bounds and the automatic radius stay those of
   * all lines, so that the view does not jump when the selection changes.
   */
  vtkSetStringMacro(VisibilityArray);
  vtkGetStringMacro(VisibilityArray);
  /// Lines the last render could draw (all tubes without VisibilityArray).
  vtkIdType GetNumberOfVisibleLines() const { return this->NumberOfVisibleLines; }
  ///@}

  ///@{
  /**
   * Color by direction (default off): every fragment gets the color of the
   * direction of the spline's tangent at its curve parameter, RGB = the
   * absolute x, y and z components of the unit tangent in data coordinates
   * (red left-right, green front-back, blue up-down for a tractogram in RAS+
   * mm: the convention of every tractography viewer), opaque. No array is
   * needed; scalar coloring is then ignored. The ray-cast tubes evaluate the
   * tangent at the hit point; the tessellated tubes and stylized lines
   * interpolate the signed tangent between their vertices and normalize it
   * per fragment.
   */
  vtkSetMacro(DirectionColoring, bool);
  vtkGetMacro(DirectionColoring, bool);
  vtkBooleanMacro(DirectionColoring, bool);
  ///@}

  ///@{
  /**
   * Endpoint markers: a sphere at both ends of every drawn polyline, of
   * EndpointMarkerScale times the line's radius at that end (Radius, or
   * RadiusArray times RadiusScale), in EndpointMarkerColor, lit like
   * surfaces and with exact depth (VTK's impostor spheres,
   * vtkOpenGLSphereMapper), so a tractogram's terminations show as
   * tractography viewers show them. Lines hidden by VisibilityArray get
   * none; the slab crop and clipping planes cut them as they cut the lines.
   * Default off; scale 1.5; color yellow (1, 0.85, 0).
   */
  vtkSetMacro(EndpointMarkers, bool);
  vtkGetMacro(EndpointMarkers, bool);
  vtkBooleanMacro(EndpointMarkers, bool);
  vtkSetClampMacro(EndpointMarkerScale, double, 0.0, 100.0);
  vtkGetMacro(EndpointMarkerScale, double);
  vtkSetVector3Macro(EndpointMarkerColor, double);
  vtkGetVector3Macro(EndpointMarkerColor, double);
  /// The markers drawn in the last frame (2 per visible line, 0 when off).
  vtkIdType GetNumberOfEndpointMarkers() const { return this->NumberOfEndpointMarkers; }
  ///@}

  ///@{
  /**
   * Slab crop: with SlabThickness > 0, only the parts of the lines within
   * SlabThickness / 2 of the plane through SlabOrigin with normal SlabNormal
   * (data coordinates) are drawn, per fragment and exactly, as mrview draws
   * streamlines around the slice shown under them. 0 (default): no crop. The
   * slab is two of the mapper's clipping planes (so at most 4 others may be
   * set); they are added while the slab is on.
   */
  vtkSetVector3Macro(SlabOrigin, double);
  vtkGetVector3Macro(SlabOrigin, double);
  vtkSetVector3Macro(SlabNormal, double);
  vtkGetVector3Macro(SlabNormal, double);
  vtkSetClampMacro(SlabThickness, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(SlabThickness, double);
  ///@}

  ///@{
  /**
   * Factor applied to the values of RadiusArray. Default 1.
   */
  vtkSetClampMacro(RadiusScale, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(RadiusScale, double);
  ///@}

  ///@{
  /**
   * Name of an integer cell array of original cell ids: when a block has it,
   * picking reports its value for the picked polyline instead of the
   * polyline's index (ParaView's geometry representations pass
   * "vtkOriginalCellIds" through vtkPVDataRepresentation::SetArrayIdNames).
   * nullptr (default): the index.
   */
  vtkSetStringMacro(CellIdArray);
  vtkGetStringMacro(CellIdArray);
  ///@}

  ///@{
  /// Deprecated: use SetCellIdArray / GetCellIdArray; kept for one release.
  void SetCellIdArrayName(const char* name) { this->SetCellIdArray(name); }
  char* GetCellIdArrayName() { return this->GetCellIdArray(); }
  ///@}

  ///@{
  /**
   * Occlusion culling (default on): per frame the chunks of the lines
   * (vtkSplineTubeCore) are drawn front to back in groups, and a chunk whose
   * bounding sphere lies behind what is already drawn over its whole screen
   * rectangle (a depth pyramid read back between the groups) is not drawn at
   * all (vtkSplineTubeVisibility). Exact: the picture is the one drawn
   * without it. Used for opaque lines in single-sampled framebuffers (a
   * multisampled depth buffer cannot be read back); frustum culling of
   * chunks is always on.
   */
  vtkSetMacro(OcclusionCulling, bool);
  vtkGetMacro(OcclusionCulling, bool);
  vtkBooleanMacro(OcclusionCulling, bool);
  ///@}

  ///@{
  /**
   * Interaction budget (default on): while the camera moves (the render
   * window's desired update rate at least InteractiveUpdateRate, default 1,
   * as VTK's interactors set it during interaction), draw a stable,
   * spatially even subset of the lines sized so that the mapper's frame fits
   * InteractiveFrameTime (seconds; 0, the default: the actor's allocated
   * render time, 1 / desired update rate for a single actor); all lines when
   * the camera stops. The subset is a fraction of the lines (at least
   * MinimumLineFraction) by a fixed hash of their index (nested: a larger
   * fraction adds lines), so nothing is uploaded again; its size follows a
   * cost model (per-view work fixed, drawing proportional to the lines) fitted
   * to the frames measured. ForceInteractive draws the subset always (see
   * also SetLevelOfDetailOf()).
   */
  vtkSetMacro(InteractiveSubset, bool);
  vtkGetMacro(InteractiveSubset, bool);
  vtkBooleanMacro(InteractiveSubset, bool);
  vtkSetClampMacro(InteractiveUpdateRate, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(InteractiveUpdateRate, double);
  vtkSetClampMacro(InteractiveFrameTime, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(InteractiveFrameTime, double);
  /// The smallest subset: 0.05 % of the lines (500 of a million).
  static constexpr double MinimumLineFraction = 0.0005;
  vtkSetMacro(ForceInteractive, bool);
  vtkGetMacro(ForceInteractive, bool);
  vtkBooleanMacro(ForceInteractive, bool);
  ///@}

  ///@{
  /**
   * Make this mapper the level-of-detail stand-in of `full` (what ParaView's
   * representations draw while the camera moves): it keeps no data of its
   * own. Render() draws `full` as an interactive frame (ForceInteractive,
   * with this mapper's InteractiveFrameTime), sharing its tube core and GPU
   * buffers, and GetBounds() returns full's: no second copy of the data and
   * no second upload at the first camera move. nullptr (the default): an
   * ordinary mapper. `full` is not kept alive by this mapper.
   */
  void SetLevelOfDetailOf(vtkSplineTubeMapper* full);
  vtkSplineTubeMapper* GetLevelOfDetailOf();
  ///@}

  ///@{
  /**
   * What the last render drew: the fraction of the lines (1 at rest), the
   * chunks in the view frustum, the chunks drawn and those dropped as hidden,
   * the depth pyramids read back, the time the render took (seconds, to
   * the end of the GPU's work) and the part of it spent in per-view CPU work
   * (classification, projection, culling tests, the stylized fix-up).
   */
  double GetLastLineFraction() const { return this->LastLineFraction; }
  vtkIdType GetLastNumberOfChunksInFrustum() const;
  vtkIdType GetLastNumberOfChunksDrawn() const;
  vtkIdType GetLastNumberOfChunksHidden() const;
  int GetLastNumberOfDepthPyramids() const { return this->LastNumberOfDepthPyramids; }
  double GetLastDrawTime() const { return this->LastDrawTime; }
  double GetLastPerViewTime() const { return this->LastFixedTime; }
  ///@}

  /**
   * For tests only: a window depth added to the chunks' nearest depths in the
   * occlusion test. 0 (default) is exact; a positive value hides visible
   * chunks (the negative control of the tests that compare culling on and off).
   */
  void SetOcclusionCullingDepthBias(double bias);

  /**
   * The tube data built from the last rendered input (nodes, frames, segments).
   */
  vtkSplineTubeCore* GetTubeCore();

  /**
   * Build the tube data for the current input now (normally done on the
   * first render). Returns the number of segments.
   */
  vtkIdType UpdateTubes();

  /**
   * Bytes of tube data the mapper holds on the GPU (0 before the first render).
   */
  virtual size_t GetGPUMemorySize() { return 0; }

  /**
   * Bounds of the tubes, including their radii.
   */
  double* GetBounds() override;
  void GetBounds(double bounds[6]) override { this->vtkMapper::GetBounds(bounds); }

  void Render(vtkRenderer* ren, vtkActor* act) override;
  void ReleaseGraphicsResources(vtkWindow* window) override;

  /**
   * Scalars are mapped per point (or per cell) to colors, then interpolated;
   * no texture-map coloring.
   */
  int CanUseTextureMapForColoring(vtkDataObject*) override { return 0; }

protected:
  vtkSplineTubeMapper();
  ~vtkSplineTubeMapper() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  vtkExecutive* CreateDefaultExecutive() override;
  void ComputeBounds() override;

  /// The composite-aware render entry: (re)builds the tube data, then draws.
  void RenderPiece(vtkRenderer* ren, vtkActor* act) override;

  /// Upload the tube data to the GPU (called after the core was rebuilt).
  virtual void UploadTubes(vtkOpenGLRenderWindow* window) = 0;

  /**
   * Give the visibility its chunks (called after UploadTubes()): the core's
   * chunks by default; a subclass with chunks of its own sets those.
   */
  virtual void SetVisibilityChunks();

  /**
   * Draw the chunks visible in this view (see OcclusionCulling and
   * InteractiveSubset): `draw` is called for each group of chunks (ids of the
   * visibility's chunks, front to back, never empty), with the depth pyramid
   * of what the earlier groups drew read back in between. The subclass' GL
   * state (program, buffers) must survive the read-backs (they only bind the
   * read framebuffer).
   */
  void DrawVisibleChunks(vtkRenderer* ren, vtkActor* act,
    const std::function<void(const std::vector<std::uint32_t>& chunks)>& draw);

  /**
   * Per tube, whether VisibilityArray selects it (1) or not (0); nullptr
   * when every tube is drawn. Changed at GetLineMaskTime().
   */
  const unsigned char* GetLineMask() const
  {
    return this->LineMask.empty() ? nullptr : this->LineMask.data();
  }
  vtkMTimeType GetLineMaskTime() const { return this->LineMaskTime.GetMTime(); }

  /// Whether this render draws the interaction subset (set by RenderPiece()).
  bool IsInteractiveRender() const { return this->InteractiveRender; }

  ///@{
  /**
   * The tubes buffer shared by the tube mappers (see the class comment).
   * UploadTubeBuffers() uploads it from the core (positions relative to
   * Shift, with UploadNodes()); ActivateTubeBuffers() binds it to the
   * uniforms tubeNodes, tubeNodeInfo, tubeTubes and tubeColors (those the
   * program uses) and sets tubeConstantRadius;
   * GetTubeBuffersSize() counts its bytes.
   */
  bool UploadTubeBuffers(vtkOpenGLRenderWindow* window);
  void ActivateTubeBuffers(vtkShaderProgram* program);
  void DeactivateTubeBuffers();
  size_t GetTubeBuffersSize();
  ///@}

  /**
   * Upload the nodes' positions (relative to Shift) and radii from the core
   * to `buffer`, piece by piece: when every node has the same radius
   * (vtkSplineTubeCore::GetConstantRadius()) and the context reads RGB32F
   * buffer textures, the positions alone (12 bytes per node) and
   * NodesConstantRadius is that radius; otherwise position and radius
   * (RGBA32F, 16 bytes) and NodesConstantRadius is -1. The shaders read a
   * node through one function that takes the radius from the uniform
   * `<prefix>ConstantRadius` when it is not negative (SetNodesUniforms()).
   */
  bool UploadNodes(vtkOpenGLRenderWindow* window, vtkSplineVizGPUBuffer& buffer);
  /// Set `<prefix>ConstantRadius` of `program` (e.g. prefix "tube": tubeConstantRadius).
  void SetNodesUniforms(vtkShaderProgram* program, const char* prefix);
  float NodesConstantRadius = -1.0f;

  /**
   * Shader declarations of the tubes buffer (needs the spline-tube math
   * before them): glsl/vtkSplineTubeNodes.glsl, e.g. tubeSegmentModel().
   */
  static std::string GetTubeNodesDeclarations();

  /**
   * Shader declarations of the color spline (needs the tubes buffer's before
   * them): glsl/vtkSplineTubeColor.glsl, its function
   * `vec4 tubeColorSpline(int node, float t)`.
   */
  static std::string GetTubeColorDeclarations();

  /**
   * Shader declaration of `vec4 tubeDirectionColor(vec3 derivative)`, the
   * direction color (see DirectionColoring) of a tangent of any length.
   */
  static std::string GetTubeDirectionColorDeclarations();

  /**
   * What the shaders color by: 0 the actor's color, 1 the color spline of
   * mapped scalars, 2 the direction (the uniform tubeHaveColors).
   */
  int GetTubeColorMode() const { return this->DirectionColoring ? 2 : (this->HaveColors ? 1 : 0); }

  /**
   * Fragment-shader code declaring `vec4 tubeColor`, the color spline of node
   * `nodeExpression` (and the next node) at the curve parameter `tExpression`.
   */
  static std::string GetTubeColorImplementation(
    const char* nodeExpression, const char* tExpression);

  /**
   * Replace the picking tags of a fragment shader for the current selection
   * pass: the cell is the polyline of tube `tubeExpression` (an int
   * expression), the composite index its block's flat index (a non-composite
   * input keeps VTK's per-mapper index); tubes have no points to pick.
   */
  void ReplaceShaderTubePicking(std::string& FSSource, const char* tubeExpression);

  /**
   * With scalar coloring, the fragment color is the color spline's value
   * `tubeColor` (declared by the subclass' shader code, see
   * GetTubeColorImplementation()); otherwise the actor's color as usual.
   */
  void ReplaceShaderColor(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override;
  bool GetNeedToRebuildShaders(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;

  /**
   * The subclass' shaders, then every stage rewritten to read each array of
   * GetPagedBuffers() from its pages (vtkSplineVizGPUBuffer::ApplyPaging():
   * arrays over the GPU's buffer-texture limit are split in pages).
   */
  void BuildShaders(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override;

  /// A GPU array the shaders read per node and the uniform it is bound to.
  using PagedBuffer = std::pair<const char*, vtkSplineVizGPUBuffer*>;
  /**
   * The arrays that may exceed one buffer texture and are split into pages
   * (vtkSplineVizGPUBuffer::SetPageable(), before every upload): the base's
   * tubeNodes, tubeNodeInfo and tubeColors; subclasses add theirs. Their
   * shaders are rewritten to match (BuildShaders()).
   */
  virtual void GetPagedBuffers(std::vector<PagedBuffer>& buffers);
  /// The page layouts of GetPagedBuffers(): shaders made for one key fit data with the same.
  std::string GetPagingKey();
  /// Rewrite one shader stage to read every array of GetPagedBuffers() from its pages.
  void ApplyPaging(std::string& source);

  /// Binds the tubes buffer (ActivateTubeBuffers()).
  void SetMapperShaderParameters(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;
  /**
   * The camera uniforms every tube shader uses: tubeMCVC (uploaded positions
   * to view coordinates, see ComputeTubeMatrices()), tubeRadiusScale,
   * VCDCMatrix and, when the program clips, tubeVCMC.
   */
  void SetCameraShaderParameters(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;

  /**
   * Per-fragment clipping by the mapper's clipping planes (data
   * coordinates): with planes, declares the uniforms at //VTK::Clip::Dec
   * and replaces `implementationTag` with a test of the view-coordinate
   * point `vertexVC` (the ray-cast hit, or the interpolated surface point).
   */
  void ReplaceShaderTubeClip(std::string& FSSource, const char* implementationTag);

  /**
   * With the environment variable SPLINEVIZ_DUMP_SHADERS set, print the
   * final sources of a program, stage by stage (name, source), for
   * debugging shader replacements.
   */
  static void DumpShaderSources(const std::vector<std::pair<std::string, std::string>>& stages);
  /// The shaders wrote the final cell and block ids: nothing to convert.
  void ProcessSelectorPixelBuffers(
    vtkHardwareSelector* sel, std::vector<unsigned int>& pixeloffsets, vtkProp* prop) override;

  /// True when the data on the GPU is older than the core.
  bool NeedToUploadTubes() const { return this->UploadTime < this->CoreBuildTime; }

  /**
   * Set by UploadTubes() (and UploadTubeBuffers()) when the data could not be
   * put on the GPU (too large for its limits, out of memory): then nothing is
   * drawn until the data changes. Reset before every upload.
   */
  bool UploadFailed = false;

  /// Rebuild the core if the input, settings or coloring changed. Returns
  /// true when it was rebuilt.
  bool UpdateTubeCore();

  /**
   * Subclasses set the core's own options (frames, node scalars) here; called
   * by UpdateTubeCore() before the input is added. What it depends on must be
   * in AppendBuildSignature().
   */
  virtual void ConfigureTubeCore(vtkSplineTubeCore*) {}

  /**
   * Subclasses append the settings their tube data depends on (beyond the
   * radius and coloring settings): a change rebuilds the core.
   */
  virtual void AppendBuildSignature(std::ostream&) {}

  ///@{
  /**
   * For shaders that write gl_FragDepth: mark the end of that code with
   * GetFragDepthWrittenMarker(), then, after VTK's replacements, call
   * UseWrittenFragDepth(): from the marker on, render-pass code that reads
   * the fragment's depth (depth peeling, the shadow-map baker) reads the
   * written depth (gl_FragDepth; -vertexVC.z for 1/gl_FragCoord.w, the eye
   * distance of a perspective camera) instead of the rasterized one. It also
   * widens the tolerance of VTK's dual depth peeling to
   * WrittenFragDepthTolerance: an interpolated depth is the same in every
   * stage of the peeling, a depth the shader computes is not (see there).
   */
  static const char* GetFragDepthWrittenMarker();
  static void UseWrittenFragDepth(std::string& FSSource);
  /**
   * Window depths within this distance are the same layer for the depth
   * peeling of shaders that write their depth. VTK's dual depth peeling
   * compares a fragment's depth with the layers found by the previous stage,
   * which ran a different program (depth initialisation, then peeling): the
   * same arithmetic, compiled with different surroundings, is fused and
   * rounded differently. Measured with Mesa 25's llvmpipe on the tessellated
   * thin tubes (a ray-cylinder intersection per fragment): up to 2-5e-7,
   * above VTK's 1e-7, which lost pixels of the front layer.
   */
  static constexpr double WrittenFragDepthTolerance = 2e-6;
  ///@}

  // The buffer objects are ours: the superclass' VBO/IBO path is not used.
  bool GetNeedToRebuildBufferObjects(vtkRenderer*, vtkActor*) override { return false; }
  void BuildBufferObjects(vtkRenderer*, vtkActor*) override {}

  /**
   * For the current camera and actor: the matrix from uploaded positions
   * (model coordinates relative to `Shift`, the centre of the tubes, so that
   * float precision is spent near the data) to view coordinates, the matrix
   * from view to data coordinates (where clipping planes are given), and
   * the scale of radii from model to view coordinates; column-major.
   */
  void ComputeTubeMatrices(
    vtkRenderer* ren, vtkActor* act, float modelView[16], float viewModel[16], float& radiusScale);
  /// The same for another camera (its world-to-view matrix); viewModel may be nullptr.
  void ComputeTubeMatrices(vtkMatrix4x4* worldToView, vtkActor* act, float modelView[16],
    float viewModel[16], float& radiusScale);

  /**
   * The camera's view-to-display matrix (the projection, stored transposed
   * as VTK's shaders expect it in VCDCMatrix); owned by the camera.
   */
  static vtkMatrix4x4* GetViewToDisplayMatrix(vtkRenderer* ren);

  /**
   * Pixels per view unit of the renderer's camera (at unit distance for a
   * perspective camera), the larger of the two axes.
   */
  static double GetPixelScale(vtkRenderer* ren);

  double Radius = 0.0;
  double AutomaticRadiusBounds[6] = { 1.0, -1.0, 1.0, -1.0, 1.0, -1.0 };
  double EffectiveRadius = 0.0;
  double MinimumPixelWidth = 1.0;
  char* RadiusArray = nullptr;
  char* VisibilityArray = nullptr;
  bool DirectionColoring = false;
  double SlabOrigin[3] = { 0.0, 0.0, 0.0 };
  double SlabNormal[3] = { 0.0, 0.0, 1.0 };
  double SlabThickness = 0.0;
  double RadiusScale = 1.0;
  char* CellIdArray = nullptr;
  bool OcclusionCulling = true;
  bool InteractiveSubset = true;
  double InteractiveUpdateRate = 1.0;
  bool ForceInteractive = false;
  vtkWeakPointer<vtkSplineTubeMapper> LevelOfDetailOf;
  double InteractiveFrameTime = 0.0;

  std::unique_ptr<vtkSplineTubeVisibility> Visibility;

  vtkNew<vtkSplineTubeCore> Core;
  vtkNew<vtkPolyData> EmptyInput; ///< stands in for CurrentInput in superclass code
  double Shift[3] = { 0.0, 0.0, 0.0 };
  vtkIdType MaximumCellId = 0; ///< largest polyline cell id drawn (for picking)
  vtkTimeStamp CoreBuildTime;
  vtkTimeStamp UploadTime;
  vtkTimeStamp BoundsTime; ///< when CoreBounds were computed from the core
  double CoreBounds[6] = { 1.0, -1.0, 1.0, -1.0, 1.0, -1.0 };
  bool HaveColors = false;       ///< the tubes carry per-node colors (scalar coloring)
  bool InputIsComposite = false; ///< block ids are flat indices of a composite input
  int ShaderVariant = -1;        ///< colors and composite input the shaders were made for
  /// Per program: the page layouts of GetPagedBuffers() its shaders were made for.
  std::map<const vtkOpenGLHelper*, std::string> ProgramPaging;

  std::unique_ptr<vtkSplineVizGPUBuffer> NodesBuffer;
  std::unique_ptr<vtkSplineVizGPUBuffer> NodeInfoBuffer;
  std::unique_ptr<vtkSplineVizGPUBuffer> TubesBuffer;
  std::unique_ptr<vtkSplineVizGPUBuffer> ColorsBuffer;

private:
  vtkSplineTubeMapper(const vtkSplineTubeMapper&) = delete;
  void operator=(const vtkSplineTubeMapper&) = delete;

  /// Everything the tube data depends on besides the input's contents.
  std::string BuildSignature();
  /**
   * What of the input's contents the tube data depends on: per block its
   * points, lines, radius and coloring arrays (by identity and modification
   * time) and its original cell ids (by value). Equal keys: the built tubes
   * still hold, whatever else changed (e.g. the VisibilityArray's values).
   */
  std::string InputContentKey(vtkDataObject* input);
  /// Read VisibilityArray into LineMask when the input or the tubes changed.
  void UpdateLineMask();
  /// Add, move or remove the slab's two clipping planes (see SlabThickness).
  void UpdateSlabPlanes();
  vtkNew<vtkPlane> SlabPlanes[2];
  bool SlabPlanesAdded = false;
  /// Read the renderer's part of the depth buffer into DepthImage and build the pyramid.
  bool ReadDepthPyramid(vtkRenderer* ren);

  bool InteractiveRender = false;
  bool LastRenderInteractive = false;
  double InteractiveFraction = 1.0;  ///< the subset's fraction for the next interactive frame
  double LastFixedTime = 0.0;        ///< seconds of per-view work in the last render
  double LastProportionalTime = 0.0; ///< seconds of drawing per unit of line fraction
  std::chrono::steady_clock::time_point RenderStart;
  /// The fraction for the next interactive frame (see InteractiveSubset).
  double NextFraction(double fraction, double budget) const;
  double LastLineFraction = 1.0;
  double LastDrawTime = 0.0;
  int LastNumberOfDepthPyramids = 0;
  std::vector<float> DepthImage;
  struct PyramidHolder;
  std::unique_ptr<PyramidHolder> Pyramid;
  std::string LastSignature;
  std::string LastContentKey;
  vtkMTimeType LastInputMTime = 0;
  std::vector<unsigned char> LineMask;
  vtkTimeStamp LineMaskTime;
  std::string LastMaskSignature;
  vtkIdType NumberOfVisibleLines = 0;

  /// The endpoint markers' spheres for the current lines and visibility.
  void UpdateEndpointMarkers();
  /// Draw them (not while picking: the lines' cell ids are the picked ones).
  void RenderEndpointMarkers(vtkRenderer* ren, vtkActor* act);
  bool EndpointMarkers = false;
  double EndpointMarkerScale = 1.5;
  double EndpointMarkerColor[3] = { 1.0, 0.85, 0.0 };
  vtkIdType NumberOfEndpointMarkers = 0;
  vtkSmartPointer<vtkPolyData> Markers;
  vtkSmartPointer<vtkOpenGLSphereMapper> MarkerMapper;
  std::string LastMarkerSignature;
  vtkDataObject* LastInput = nullptr;
};

#endif
