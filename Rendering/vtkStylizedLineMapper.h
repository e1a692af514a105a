// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkStylizedLineMapper
 * @brief   Renders polylines as stylized line primitives: lit generalized cylinders splatted as
 * silhouette quads, with halos, textures, orientation, depth correction and a CPU fix-up.
 *
 * Implements Stoll, Gumhold and Seidel, "Visualization with stylized line
 * primitives" (IEEE Visualization 2005). Every polyline of the input
 * (vtkPolyData or a composite of them, as for vtkSplineTubeMapper) is drawn
 * as a generalized cylinder around the polyline (straight between its
 * points, §3) with radius, color, texture coordinate and orientation per point.
 *
 * - Silhouette quads (§4.1): one triangle strip per polyline, extruded in
 *   the vertex stage (Eq. 3-7 with ExactSilhouette, else Eq. 8) from at most
 *   36 bytes per vertex on the GPU (GetGPUMemorySize()).
 * - Shading (§4.2): the normal of Eq. 10, VTK's lighting, scalar colors,
 *   clipping planes, depth peeling (one layer per line when translucent),
 *   hardware picking (cell = the polyline, block index).
 * - Halos (§4.2): HaloWidth (radii), HaloColor or the background,
 *   HaloDepthOffset; DepthDependentHalo (Everts et al. 2009).
 * - Textures (§4.2, §6, Figs. 10-13): TexturePattern (stripes, arrows,
 *   dashes) or the actor's vtkTexture, TextureRepeat, OrientationArray,
 *   NormalMapping.
 * - Depth correction (§4.3, Eq. 11-12; DepthCorrection, on): the depth of
 *   the cylinder surface, so lines cross each other and other geometry.
 * - Hybrid fix-up (§4.3-4.4; FixUp, on): where a tangent nearly points at the
 *   viewer (FixUpEpsilon), batches of segments are drawn as real cylinders
 *   (vtkStylizedLineFixUp); flat caps close the line ends (Capping).
 * - Shadows (§4.2): a shadow map of its own (Shadows, ShadowMapResolution),
 *   or VTK's vtkShadowMapPass for shadows on other geometry too.
 *
 * Limits: lines are straight between their points (resample coarse ones,
 * e.g. with vtkSplineFilter); the corrected depth is that of infinite
 * cylinders, approximate at sharp joints; no point picking (cell and block
 * picking work); a non-uniform actor scale is treated as the uniform scale
 * with the same volume change. Design: docs/components.md, "Stylized lines".
 *
 * @sa vtkSplineTubeMapper vtkSplineTubeCore vtkStylizedLineFixUp vtkRayCastTubeMapper
 */
#ifndef vtkStylizedLineMapper_h
#define vtkStylizedLineMapper_h

#include "SplineVizRenderingModule.h" // for export macro
#include "vtkSplineTubeMapper.h"

#include <iosfwd> // for std::ostream
#include <memory> // for std::unique_ptr
#include <string> // for std::string

class SPLINEVIZRENDERING_EXPORT vtkStylizedLineMapper : public vtkSplineTubeMapper
{
public:
  static vtkStylizedLineMapper* New();
  vtkTypeMacro(vtkStylizedLineMapper, vtkSplineTubeMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Width of the halo as a fraction of the line's radius (Stoll §4.2); 0
   * (default) turns it off.
   */
  vtkSetClampMacro(HaloWidth, double, 0.0, 10.0);
  vtkGetMacro(HaloWidth, double);
  ///@}

  ///@{
  /**
   * Color of the halo (RGB in [0, 1]), used when HaloColorFromBackground is
   * off. Default white.
   */
  vtkSetVector3Macro(HaloColor, double);
  vtkGetVector3Macro(HaloColor, double);
  ///@}

  ///@{
  /**
   * Draw the halo in the renderer's background color (default on), as Stoll
   * does; off: HaloColor.
   */
  vtkSetMacro(HaloColorFromBackground, bool);
  vtkGetMacro(HaloColorFromBackground, bool);
  vtkBooleanMacro(HaloColorFromBackground, bool);
  ///@}

  ///@{
  /**
   * How far behind its line the halo lies, in radii of the line: the halo
   * hides lines more than this far behind it, not nearer ones (so that
   * lines that touch do not cut each other). Default 2.
   */
  vtkSetClampMacro(HaloDepthOffset, double, 0.0, 1e6);
  vtkGetMacro(HaloDepthOffset, double);
  ///@}

  ///@{
  /**
   * Depth-dependent halos (Everts et al. 2009), default off: the halo's depth
   * behind its line grows across the halo, from HaloDepthOffset radii at the
   * line's edge to HaloDepthOffset + HaloDepthRange radii at its outer edge.
   * A line lying a gap g behind is then hidden over the fraction
   * clamp((g - HaloDepthOffset) / HaloDepthRange, 0, 1) of the halo's width:
   * lines of a tight bundle merge, lines far apart in depth get the whole
   * halo between them.
   */
  vtkSetMacro(DepthDependentHalo, bool);
  vtkGetMacro(DepthDependentHalo, bool);
  vtkBooleanMacro(DepthDependentHalo, bool);
  ///@}

  ///@{
  /**
   * Depth gap, in radii beyond HaloDepthOffset, at which a depth-dependent
   * halo reaches its full width. Default 10.
   */
  vtkSetClampMacro(HaloDepthRange, double, 0.0, 1e6);
  vtkGetMacro(HaloDepthRange, double);
  ///@}

  ///@{
  /**
   * Silhouette points of Eq. 6 (on, default: exact for the vertex's
   * infinite cylinder, also close to the line) or Eq. 8 (off: +-r times the
   * silhouette direction, cheaper, slightly wrong close up).
   */
  vtkSetMacro(ExactSilhouette, bool);
  vtkGetMacro(ExactSilhouette, bool);
  vtkBooleanMacro(ExactSilhouette, bool);
  ///@}

  ///@{
  /**
   * Per-fragment depth of the cylinder surface (Stoll §4.3). Default on;
   * off, the flat quads' depth is used (no gl_FragDepth written unless the
   * halo needs it: faster on software rasterizers, which then keep their
   * early depth test).
   */
  vtkSetMacro(DepthCorrection, bool);
  vtkGetMacro(DepthCorrection, bool);
  vtkBooleanMacro(DepthCorrection, bool);
  ///@}

  ///@{
  /**
   * The hybrid fix-up of Stoll §4.4 (see the class documentation). Default on.
   */
  vtkSetMacro(FixUp, bool);
  vtkGetMacro(FixUp, bool);
  vtkBooleanMacro(FixUp, bool);
  ///@}

  ///@{
  /**
   * The fix-up's threshold: a vertex is fixed up when the cosine between its
   * tangent and the view vector exceeds 1 - FixUpEpsilon. Default 0.025
   * (Stoll: 0.02-0.03, about 12-14 degrees).
   */
  vtkSetClampMacro(FixUpEpsilon, double, 0.0, 1.0);
  vtkGetMacro(FixUpEpsilon, double);
  ///@}

  ///@{
  /**
   * Largest number of sides of the cylinders the fix-up draws and of the end
   * caps: per view they get sides of about 3 pixels (at least 8) for the
   * largest of them on screen, at most this many. Default 64.
   */
  vtkSetClampMacro(FixUpSides, int, 3, 256);
  vtkGetMacro(FixUpSides, int);
  ///@}

  ///@{
  /**
   * Lines shadow each other (the mapper's own shadow map, see the class
   * documentation). Default off.
   */
  vtkSetMacro(Shadows, bool);
  vtkGetMacro(Shadows, bool);
  vtkBooleanMacro(Shadows, bool);
  ///@}

  ///@{
  /**
   * Size of the shadow map (texels per side). Default 1024.
   */
  vtkSetClampMacro(ShadowMapResolution, int, 64, 8192);
  vtkGetMacro(ShadowMapResolution, int);
  ///@}

  ///@{
  /**
   * Close the polylines with flat caps at their ends. Default on.
   */
  vtkSetMacro(Capping, bool);
  vtkGetMacro(Capping, bool);
  vtkBooleanMacro(Capping, bool);
  ///@}

  enum TexturePatterns
  {
    NO_PATTERN = 0, ///< plain lines
    STRIPES = 1,    ///< stripes along the line, TextureCircumferentialRepeat dark ones around it
    ARROWS = 2,     ///< arrow heads pointing along the line, TextureRepeat apart
    DASHES = 3      ///< dashed lines: gaps of half the TextureRepeat (not drawn)
  };

  ///@{
  /**
   * Built-in texture pattern (procedural and anti-aliased; none by default).
   * An actor texture (vtkActor::SetTexture) is used instead when the actor
   * has one, mapped with the same coordinates (u along, v around).
   */
  vtkSetClampMacro(TexturePattern, int, NO_PATTERN, DASHES);
  vtkGetMacro(TexturePattern, int);
  void SetTexturePatternToNone() { this->SetTexturePattern(NO_PATTERN); }
  void SetTexturePatternToStripes() { this->SetTexturePattern(STRIPES); }
  void SetTexturePatternToArrows() { this->SetTexturePattern(ARROWS); }
  void SetTexturePatternToDashes() { this->SetTexturePattern(DASHES); }
  ///@}

  enum TextureRepeatUnit
  {
    RADII = 0, ///< TextureRepeat in radii of the line (the coordinate is the integral of ds / r)
    WORLD = 1  ///< TextureRepeat in world units (arc length)
  };

  ///@{
  /**
   * Length along the line of one repeat of the texture (u from 0 to 1), in
   * TextureRepeatUnits. Default 8 (radii).
   */
  vtkSetClampMacro(TextureRepeat, double, 1e-12, VTK_DOUBLE_MAX);
  vtkGetMacro(TextureRepeat, double);
  ///@}

  ///@{
  /**
   * Units of TextureRepeat. Default RADII: the pattern scales with the line.
   */
  vtkSetClampMacro(TextureRepeatUnits, int, RADII, WORLD);
  vtkGetMacro(TextureRepeatUnits, int);
  void SetTextureRepeatUnitsToRadii() { this->SetTextureRepeatUnits(RADII); }
  void SetTextureRepeatUnitsToWorld() { this->SetTextureRepeatUnits(WORLD); }
  ///@}

  ///@{
  /**
   * Copies of the texture around the circumference (v from 0 to 1 this many
   * times per turn: stripes and arrows around the line). Default 2.
   */
  vtkSetClampMacro(TextureCircumferentialRepeat, int, 1, 64);
  vtkGetMacro(TextureCircumferentialRepeat, int);
  ///@}

  ///@{
  /**
   * Name of a one-component point array of angles (radians) that turn the
   * texture around the line (e.g. vtkStreamTracer's "Rotation", the
   * integrated rotation about the flow direction, Stoll Fig. 11). nullptr or
   * "" (default): none. A missing array is an error (nothing is drawn for
   * that block); polylines with NaN angles are skipped with a warning.
   */
  vtkSetStringMacro(OrientationArray);
  vtkGetStringMacro(OrientationArray);
  ///@}

  ///@{
  /**
   * Use the texture as a normal map (Stoll Fig. 13) instead of a color
   * modulation: the built-in patterns become grooves, an actor texture is
   * read as a tangent-space normal map (red around, green along the line,
   * blue outward). Default off.
   */
  vtkSetMacro(NormalMapping, bool);
  vtkGetMacro(NormalMapping, bool);
  vtkBooleanMacro(NormalMapping, bool);
  ///@}

  /**
   * Segments the last render drew as fix-up geometry instead of quads.
   */
  vtkIdType GetNumberOfFixedUpSegments();

  /**
   * Batches of the fix-up (built per data change).
   */
  vtkIdType GetNumberOfFixUpBatches();

  /**
   * Seconds the last render spent in the fix-up on the CPU (its per-view
   * classification and the draw lists of the visible batches), part of
   * GetLastPerViewTime().
   */
  double GetLastFixUpTime() const { return this->LastFixUpTime; }

  /**
   * Bytes of line data on the GPU: the vertex buffers, the polyline table,
   * the fix-up's segment list and the cap and cylinder index patterns.
   */
  size_t GetGPUMemorySize() override;

  void ReleaseGraphicsResources(vtkWindow* window) override;

protected:
  vtkStylizedLineMapper();
  ~vtkStylizedLineMapper() override;

  void ComputeBounds() override;
  void RenderPiece(vtkRenderer* ren, vtkActor* act) override;
  void UploadTubes(vtkOpenGLRenderWindow* window) override;
  void RenderPieceDraw(vtkRenderer* ren, vtkActor* act) override;
  /// The fix-up's batches are the chunks culled (widened by the halo).
  void SetVisibilityChunks() override;
  void ConfigureTubeCore(vtkSplineTubeCore* core) override;
  void AppendBuildSignature(std::ostream& signature) override;

  void GetShaderTemplate(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override;
  void ReplaceShaderValues(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override;
  void ReplaceShaderClip(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override;
  bool GetNeedToRebuildShaders(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;
  /// The base's per-node arrays and the lines' own (lineNodes, lineTangents...).
  void GetPagedBuffers(std::vector<PagedBuffer>& buffers) override;
  void SetMapperShaderParameters(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;
  void SetCameraShaderParameters(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;

  double HaloWidth = 0.0;
  double HaloColor[3] = { 1.0, 1.0, 1.0 };
  bool HaloColorFromBackground = true;
  double HaloDepthOffset = 2.0;
  bool DepthDependentHalo = false;
  double HaloDepthRange = 10.0;
  bool ExactSilhouette = true;
  bool DepthCorrection = true;
  bool FixUp = true;
  double FixUpEpsilon = 0.025;
  int FixUpSides = 64;
  double LastFixUpTime = 0.0;
  bool Capping = true;
  bool Shadows = false;
  int ShadowMapResolution = 1024;
  int TexturePattern = NO_PATTERN;
  double TextureRepeat = 8.0;
  int TextureRepeatUnits = RADII;
  int TextureCircumferentialRepeat = 2;
  char* OrientationArray = nullptr;
  bool NormalMapping = false;

private:
  vtkStylizedLineMapper(const vtkStylizedLineMapper&) = delete;
  void operator=(const vtkStylizedLineMapper&) = delete;

  /// Whether the lines carry texture coordinates and frames (a pattern or an
  /// actor texture).
  bool NeedsTextureData() const;
  /// The shader variant (what changes the code rather than a uniform).
  std::string ShaderKey(vtkRenderer* ren, vtkActor* act);
  /// Per view: the fix-up classification, the strip and cylinder draws.
  void UpdateDraws(vtkRenderer* ren, vtkActor* act);
  bool BuildMeshes();
  /// The shadow map for this frame (when Shadows is on); false without one.
  bool UpdateShadowMap(vtkRenderer* ren, vtkActor* act, vtkOpenGLHelper& helper);
  /// The light's direction (world, unit) the shadows are cast along.
  void GetShadowLightDirection(vtkRenderer* ren, double dir[3]);
  /// The orthographic light camera around the actor's bounds (ShadowView,
  /// ShadowProjection, ShadowBias); its half size, 0 without bounds.
  double SetUpShadowCamera(vtkActor* act, const double dir[3]);
  /// The depth map (size^2) and its framebuffer, bound; false (and unbound) if unusable.
  bool PrepareShadowFramebuffer(vtkOpenGLRenderWindow* window, int size);
  /// Draw the lines (the visible ones, their caps) from the light into the bound map.
  void DrawShadowCasters(vtkOpenGLRenderWindow* window, vtkActor* act, vtkShaderProgram* program);

  struct vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
