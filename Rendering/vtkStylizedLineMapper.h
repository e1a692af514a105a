// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkStylizedLineMapper
 * @brief   Renders polylines as stylized line primitives: lit generalized cylinders splatted as
 * silhouette quads, with halos, textures, orientation, depth correction and a CPU fix-up.
 *
 * Implements Stoll, Gumhold and Seidel, "Visualization with stylized line
 * primitives" (IEEE Visualization 2005). Every polyline of the input
 * (vtkPolyData or a composite data set of them, as for the tube mappers,
 * see vtkSplineTubeMapper) is drawn as a generalized cylinder with a
 * circular profile whose axis is the polyline (straight segments between its
 * points, §3) and whose radius, color, texture coordinate and orientation
 * are given per point.
 *
 * - **Per-vertex data, uploaded once per data change** (§3, §4.1): position
 *   and radius (16 bytes; 12, the position alone, when all radii are equal),
 *   unit tangent (octahedral, 4 bytes), with scalar
 *   coloring the color (RGBA8, 4 bytes), with a texture the texture
 *   coordinate along the line and the orientation angle (8 bytes) and a
 *   body-fixed frame vector (4 bytes), plus 12 bytes per polyline: at most
 *   36 bytes per vertex against Stoll's 110 per segment. The polyline scan,
 *   the validation, tangents, radii and colors come from the tube core
 *   (vtkSplineTubeCore), shared with the tube mappers. GetGPUMemorySize()
 *   counts the bytes.
 * - **Silhouette-quad splatting** (§4.1): the vertex stage computes the two
 *   silhouette points of each vertex from Eq. 3-7 (the exact extrusion with
 *   f_i, ExactSilhouette on) or Eq. 8 (off); each polyline is one triangle
 *   strip of two vertices per point, all polylines in one multi-draw, with
 *   no index or vertex attribute data (the stage reads its vertex from the
 *   buffers by gl_VertexID).
 * - **Fragment stage** (§4.2): the normal of Eq. 10 from the interpolated
 *   frame vectors, then VTK's lighting, material, opacity, scalar coloring,
 *   clipping planes (of the corrected surface point), depth peeling and
 *   hardware picking (cell = the polyline, composite index = its block).
 *   Translucent, each line is one layer: quad fragments beyond the plane of
 *   their polyline's end are left to its cap, and the fix-up's joint
 *   spheres are not drawn (TestTubeTranslucency).
 * - **Halo** (§4.2): HaloWidth (a fraction of the radius) widens every quad;
 *   the extra band is drawn in HaloColor (or the renderer's background) at a
 *   depth pushed back by HaloDepthOffset radii, so that it hides lines
 *   further behind and never its own line. The halo is defined in object
 *   space: it scales with the line. DepthDependentHalo tilts the halo away
 *   from the eye (Everts et al. 2009), so that its visible width follows the
 *   depth gap to the lines behind it. The caps have one too; the fix-up's
 *   geometry has none (around a line seen down its length a halo ring
 *   would cut the line's own parts further back).
 * - **Textures along the line** (§4.2, §6, Figs. 10-13): built-in stripes,
 *   arrows or dashes (procedural, anti-aliased), or the actor's vtkTexture,
 *   mapped with u along the line (TextureRepeat, in radii or world units)
 *   and v around the circumference, measured in a rotation-minimizing frame
 *   of the line (so the texture stays on the surface as the camera turns);
 *   the OrientationArray (radians) turns it around the line (Stoll Fig. 11).
 *   With NormalMapping the texture perturbs the normal instead of the color
 *   (the patterns as bumps, an actor texture as a tangent-space normal map,
 *   Fig. 13).
 * - **Depth correction** (§4.3, Eq. 11-12; DepthCorrection on by default):
 *   each fragment's depth is that of the cylinder surface in front of the
 *   quad, d = r / sin(alpha) along the view ray, weighted by the normal's
 *   component toward the eye; lines cross each other and other geometry
 *   plausibly. It is exact for an infinite cylinder seen orthographically;
 *   it stays approximate at the joints of strongly bent lines and where the
 *   tangent turns toward the viewer (where the fix-up takes over).
 * - **Hybrid fix-up** (§4.3-4.4, FixUp on by default): where the tangent
 *   nearly points at the viewer (|t . u| > 1 - FixUpEpsilon, default 0.025
 *   after Stoll's 0.02-0.03) or the eye is at the line, the quads flip and
 *   leave holes. Per view change the CPU tests precomputed batches of up to
 *   16 consecutive segments whose tangents differ by at most 12 degrees
 *   (Stoll: 10-15 degrees) in parallel (vtkSMPTools; a batch is skipped by
 *   one cone test unless the view can meet its tangents), and the batches
 *   with a problem vertex are drawn as real geometry instead of quads:
 *   cylinders per segment, generated on the GPU from the
 *   same vertex buffers (only the list of segments is uploaded, a few bytes
 *   per fixed segment). This is Stoll's method 1 (tessellated geometry, exact
 *   depth) without its alpha blending: the quad strips are split at the
 *   batch boundaries, so nothing is drawn twice and the shading of both
 *   parts is the same fragment code. Method 2 (four quads per segment bent
 *   towards the viewer) was not used: looking along a segment it covers at
 *   most the half of the profile disk facing the eye and its depth is not
 *   continuous (Stoll §4.4). Line ends are closed by flat caps (drawn for the
 *   polylines' ends turned to the eye). See vtkStylizedLineFixUp.
 * - **Shadows** (§4.2), two ways. With Shadows on, the mapper keeps a shadow
 *   map of its own (Stoll's method: the lines rendered from the light, their
 *   quads extruded toward the light, into a ShadowMapResolution^2 depth
 *   texture, redrawn only when the light, the camera of a camera light or
 *   the data change), so that lines shadow each other wherever the mapper
 *   is used, ParaView included: the light is the renderer's first switched-on
 *   light that is not a headlight (a light of ParaView's light kit), else a
 *   virtual light above and right of the camera; it is treated as
 *   directional (an orthographic shadow camera around the lines); in shadow
 *   the diffuse and specular light is dimmed to 40 % (3x3 percentage-closer
 *   filtering). Or, for shadows on other geometry too, the mapper renders
 *   into VTK's vtkShadowMapBakerPass / vtkShadowMapPass like polygonal
 *   geometry: seen from the light its quads extrude toward the light, the
 *   lit pass looks its fragments up at their corrected surface points.
 *
 * Limits: the lines are straight between their points (resample coarse
 * polylines, e.g. with vtkSplineFilter); the depth of the quads is the
 * infinite cylinders' (not the joints'); point picking is not supported
 * (cell and block picking are); a non-uniform actor scale is treated as the
 * uniform scale with the same volume change.
 *
 * @sa vtkSplineTubeMapper vtkSplineTubeCore vtkStylizedLineFixUp vtkRayCastTubeMapper
 */
#ifndef vtkStylizedLineMapper_h
#define vtkStylizedLineMapper_h

#include "SplineVizModule.h" // for export macro
#include "vtkSplineTubeMapper.h"

#include <iosfwd> // for std::ostream
#include <memory> // for std::unique_ptr
#include <string> // for std::string

class SPLINEVIZ_EXPORT vtkStylizedLineMapper : public vtkSplineTubeMapper
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
