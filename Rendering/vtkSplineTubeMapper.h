/**
 * @class   vtkSplineTubeMapper
 * @brief   Base class of the SplineViz spline-tube mappers.
 *
 * What the tube mappers (vtkRayCastTubeMapper, Salm §3.2, and
 * vtkTessellatedTubeMapper, Salm §3.1) share:
 *
 * - input: vtkPolyData or a composite data set (e.g. a vtkMultiBlockDataSet)
 *   of vtkPolyData, as ParaView gives it; every polyline (VTK_LINE and
 *   VTK_POLY_LINE cells) of every block becomes a tube, and all tubes are drawn
 *   together (one buffer, one draw call);
 * - radius: a constant Radius (world units), or the per-point RadiusArray
 *   (world units) multiplied by RadiusScale;
 * - color: the actor's property, or scalars mapped through the mapper's usual
 *   settings (ScalarVisibility, ScalarMode, SelectColorArray, lookup table,
 *   ScalarRange, ColorMode: the same as vtkPolyDataMapper). Mapped colors are
 *   interpolated along the tubes by the color spline;
 * - the per-data preparation by vtkSplineTubeCore (nodes, tangents, frames,
 *   segment table), done only when the input, the radius settings or the
 *   coloring change; the per-frame work stays on the GPU;
 * - bounds that include the tubes' radii.
 *
 * - the tubes buffer on the GPU (Salm §3, Fig. 3), as buffer textures read by
 *   the shaders with texelFetch: per node the position and radius, the
 *   tangent and radius derivative (`tubeNodes`, 2 RGBA32F texels), per segment
 *   its first node, the TUBE_START/TUBE_END flags and its tube (`tubeSegments`,
 *   RG32UI), per tube the cell and block ids for picking (`tubeTubes`, RG32I)
 *   and, with scalar coloring, per node the color and its derivative (scaled
 *   by 127) as bytes in one texel (`tubeColors`, RG32UI; the color spline of
 *   glsl/vtkSplineTubeColor.glsl);
 * - the fragment-shader code for the color spline and for hardware picking
 *   (cell = polyline, composite index = block).
 *
 * Subclasses upload what their shaders need (UploadTubes(), usually through
 * UploadTubeBuffers()) and draw (RenderPieceDraw()).
 */
#ifndef vtkSplineTubeMapper_h
#define vtkSplineTubeMapper_h

#include "SplineVizModule.h" // for export macro
#include "vtkNew.h"          // for vtkNew
#include "vtkOpenGLPolyDataMapper.h"

#include <iosfwd>  // for std::ostream
#include <memory>  // for std::unique_ptr
#include <string>  // for std::string
#include <utility> // for std::pair
#include <vector>  // for std::vector

class vtkMatrix4x4;
class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkSplineTubeCore;
class vtkSplineVizGPUBuffer;

class SPLINEVIZ_EXPORT vtkSplineTubeMapper : public vtkOpenGLPolyDataMapper
{
public:
  vtkTypeMacro(vtkSplineTubeMapper, vtkOpenGLPolyDataMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Constant tube radius in world units, used when no RadiusArray is set.
   * Default 0.01.
   */
  vtkSetClampMacro(Radius, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(Radius, double);
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
  vtkSetStringMacro(CellIdArrayName);
  vtkGetStringMacro(CellIdArrayName);
  ///@}

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

  ///@{
  /**
   * The tubes buffer shared by the tube mappers (see the class comment).
   * UploadTubeBuffers() uploads it from the core (positions relative to
   * Shift); ActivateTubeBuffers() binds it to the uniforms tubeNodes,
   * tubeSegments, tubeTubes and tubeColors (those the program uses);
   * GetTubeBuffersSize() counts its bytes.
   */
  bool UploadTubeBuffers(vtkOpenGLRenderWindow* window);
  void ActivateTubeBuffers(vtkShaderProgram* program);
  void DeactivateTubeBuffers();
  size_t GetTubeBuffersSize();
  ///@}

  /**
   * Shader declarations of the color spline (with scalar coloring; needs the
   * spline-tube math before them): glsl/vtkSplineTubeColor.glsl, its
   * function `vec4 tubeColorSpline(int node, float t)`.
   */
  static std::string GetTubeColorDeclarations();

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
   * distance of a perspective camera) instead of the rasterized one.
   */
  static const char* GetFragDepthWrittenMarker();
  static void UseWrittenFragDepth(std::string& FSSource);
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

  double Radius = 0.01;
  char* RadiusArray = nullptr;
  double RadiusScale = 1.0;
  char* CellIdArrayName = nullptr;

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

  std::unique_ptr<vtkSplineVizGPUBuffer> NodesBuffer;
  std::unique_ptr<vtkSplineVizGPUBuffer> SegmentsBuffer;
  std::unique_ptr<vtkSplineVizGPUBuffer> TubesBuffer;
  std::unique_ptr<vtkSplineVizGPUBuffer> ColorsBuffer;

private:
  vtkSplineTubeMapper(const vtkSplineTubeMapper&) = delete;
  void operator=(const vtkSplineTubeMapper&) = delete;

  /// Everything the tube data depends on besides the input's contents.
  std::string BuildSignature();
  std::string LastSignature;
  vtkMTimeType LastInputMTime = 0;
  vtkDataObject* LastInput = nullptr;
};

#endif
