// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkLineAmbientOcclusionPass
 * @brief   Screen-space ambient occlusion and depth-dependent halos for dense
 * lines and tubes, from the depth buffer alone.
 *
 * A render pass that draws its delegate (e.g. a vtkRenderStepsPass) into an
 * offscreen color and depth buffer and then darkens each pixel by its ambient
 * occlusion and, optionally, draws depth-dependent halos, in stages
 * (vtkLineAmbientOcclusionFS.glsl): every pixel's view point once into a
 * float texture; the picture copied; the occlusion factor multiplied in
 * where there is geometry only (a far-plane quad behind a GL_GREATER depth
 * test, so the early depth test skips the background); the halos drawn only
 * on tiles where some pixel lies more than HaloDepthOffset in front of
 * another within reach (vtkLineAmbientOcclusionTilesVS.glsl). Each stage has
 * its own program because on a CPU rasterizer (Mesa's llvmpipe) code behind
 * a branch or a uniform switch costs as if it ran; the skipped pixels are
 * exactly those whose result would be unchanged. docs/line-rendering.md has
 * the costs. Only the depth buffer is read for the geometry, so it works for any
 * opaque geometry that writes its depth: the three line mappers
 * (vtkRayCastTubeMapper with its exact per-fragment depth,
 * vtkTessellatedTubeMapper, vtkStylizedLineMapper) and ordinary polygons.
 *
 * - **Ambient occlusion** (in the spirit of Eichelbaum et al., "LineAO", 2013):
 *   at each pixel the view point and its normal are rebuilt from the depth
 *   buffer; for Levels radii (the largest Radius, each level half the next)
 *   Samples points of a disk around the pixel are read; a sample at Q
 *   occludes the point P by max(0, n.(Q-P)/|Q-P| - Bias)/(1 - Bias), weighted
 *   by max(0, 1 - |Q-P|^2/R^2) where R is the level's radius in view units at
 *   P's distance (occluders further away in depth than that do not count).
 *   The levels are averaged into an occlusion o in [0, 1] and the color is
 *   multiplied by clamp(1 - Strength o, 0, 1). A convex surface (an isolated
 *   tube) does not occlude itself; the background never occludes.
 * - **Depth-dependent halos** (Everts et al., "Depth-dependent halos", 2009),
 *   DepthHalos on: a pixel lies in the halo of a nearer pixel at screen
 *   distance s when s < HaloWidth clamp((gap - HaloDepthOffset) /
 *   HaloDepthRange, 0, 1), gap being its depth behind that pixel (the
 *   background is infinitely far). Lines of a tight bundle (small gaps) merge,
 *   lines far apart in depth are separated by the full halo. Halos are drawn
 *   in HaloColor or the renderer's background. A line's own pixels never get a
 *   halo from the line itself as long as HaloDepthOffset exceeds the line's
 *   radius (its depth varies by at most that much across it).
 * - **Units**: Radius, HaloDepthOffset and HaloDepthRange are pixels (default:
 *   a depth gap is converted into pixels at the nearer point's distance, so
 *   the look does not change with zoom) or world units (UNITS_WORLD, e.g.
 *   millimetres of a tractogram). HaloWidth is always in pixels.
 *
 * Usage: pass->SetDelegatePass(renderSteps); renderer->SetPass(pass).
 * Limits: translucent geometry is composited by the delegate and darkened
 * with what lies behind it; the offscreen buffers are single-sampled (no
 * multisampling inside the pass); hardware picking bypasses the pass.
 *
 * @sa vtkSSAOPass vtkStylizedLineMapper vtkRayCastTubeMapper vtkTessellatedTubeMapper
 */
#ifndef vtkLineAmbientOcclusionPass_h
#define vtkLineAmbientOcclusionPass_h

#include "SplineVizModule.h" // for export macro
#include "vtkImageProcessingPass.h"

#include <memory> // for std::unique_ptr

class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkTextureObject;

class SPLINEVIZ_EXPORT vtkLineAmbientOcclusionPass : public vtkImageProcessingPass
{
public:
  static vtkLineAmbientOcclusionPass* New();
  vtkTypeMacro(vtkLineAmbientOcclusionPass, vtkImageProcessingPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  void Render(const vtkRenderState* s) override;
  void ReleaseGraphicsResources(vtkWindow* w) override;

  enum Units
  {
    UNITS_PIXELS = 0, ///< lengths in pixels, depth gaps in pixels at the point's distance
    UNITS_WORLD = 1   ///< lengths and depth gaps in world units
  };

  ///@{
  /**
   * Darken by ambient occlusion. Default on.
   */
  vtkSetMacro(AmbientOcclusion, bool);
  vtkGetMacro(AmbientOcclusion, bool);
  vtkBooleanMacro(AmbientOcclusion, bool);
  ///@}

  ///@{
  /**
   * Units of Radius, HaloDepthOffset and HaloDepthRange. Default pixels.
   */
  vtkSetClampMacro(LengthUnits, int, UNITS_PIXELS, UNITS_WORLD);
  vtkGetMacro(LengthUnits, int);
  void SetLengthUnitsToPixels() { this->SetLengthUnits(UNITS_PIXELS); }
  void SetLengthUnitsToWorld() { this->SetLengthUnits(UNITS_WORLD); }
  ///@}

  ///@{
  /**
   * Radius of the largest sampling hemisphere. Default 32 (pixels); a few
   * line widths suits dense lines (LineAO scales it with the line width).
   */
  vtkSetClampMacro(Radius, double, 0.0, 1e30);
  vtkGetMacro(Radius, double);
  ///@}

  ///@{
  /**
   * Number of radii (each half the next). Default 3.
   */
  vtkSetClampMacro(Levels, int, 1, 6);
  vtkGetMacro(Levels, int);
  ///@}

  ///@{
  /**
   * Samples per level. Default 6.
   */
  vtkSetClampMacro(Samples, int, 1, 64);
  vtkGetMacro(Samples, int);
  ///@}

  ///@{
  /**
   * Darkening at full occlusion (the color is scaled by 1 - Strength x
   * occlusion, at least 0). Default 2 (an occluder covers at most about half
   * of a sampling disk).
   */
  vtkSetClampMacro(Strength, double, 0.0, 10.0);
  vtkGetMacro(Strength, double);
  ///@}

  ///@{
  /**
   * Cosine below which a sample above the tangent plane does not occlude
   * (hides the noise of normals rebuilt from depth). Default 0.1.
   */
  vtkSetClampMacro(Bias, double, 0.0, 0.9);
  vtkGetMacro(Bias, double);
  ///@}

  ///@{
  /**
   * Draw depth-dependent halos. Default off.
   */
  vtkSetMacro(DepthHalos, bool);
  vtkGetMacro(DepthHalos, bool);
  vtkBooleanMacro(DepthHalos, bool);
  ///@}

  ///@{
  /**
   * Full width of a halo, in pixels. Default 4.
   */
  vtkSetClampMacro(HaloWidth, double, 0.0, 64.0);
  vtkGetMacro(HaloWidth, double);
  ///@}

  ///@{
  /**
   * Depth gap below which there is no halo (LengthUnits). Default 4 (pixels);
   * keep it above the lines' radius.
   */
  vtkSetClampMacro(HaloDepthOffset, double, 0.0, 1e30);
  vtkGetMacro(HaloDepthOffset, double);
  ///@}

  ///@{
  /**
   * Depth gap (LengthUnits) beyond HaloDepthOffset over which the halo grows
   * to its full width; 0 gives full halos at once. Default 32 (pixels).
   */
  vtkSetClampMacro(HaloDepthRange, double, 0.0, 1e30);
  vtkGetMacro(HaloDepthRange, double);
  ///@}

  ///@{
  /**
   * Halo color (RGB in [0, 1]) when HaloColorFromBackground is off. Default
   * white.
   */
  vtkSetVector3Macro(HaloColor, double);
  vtkGetVector3Macro(HaloColor, double);
  ///@}

  ///@{
  /**
   * Draw halos in the renderer's background color. Default on.
   */
  vtkSetMacro(HaloColorFromBackground, bool);
  vtkGetMacro(HaloColorFromBackground, bool);
  vtkBooleanMacro(HaloColorFromBackground, bool);
  ///@}

protected:
  vtkLineAmbientOcclusionPass();
  ~vtkLineAmbientOcclusionPass() override;

  bool AmbientOcclusion = true;
  int LengthUnits = UNITS_PIXELS;
  double Radius = 32.0;
  int Levels = 3;
  int Samples = 6;
  double Strength = 2.0;
  double Bias = 0.1;
  bool DepthHalos = false;
  double HaloWidth = 4.0;
  double HaloDepthOffset = 4.0;
  double HaloDepthRange = 32.0;
  double HaloColor[3] = { 1.0, 1.0, 1.0 };
  bool HaloColorFromBackground = true;

private:
  vtkLineAmbientOcclusionPass(const vtkLineAmbientOcclusionPass&) = delete;
  void operator=(const vtkLineAmbientOcclusionPass&) = delete;

  /// The delegate's picture into the offscreen color and depth textures.
  void RenderOffscreen(const vtkRenderState* s, vtkOpenGLRenderWindow* window, int w, int h);
  /// One offscreen stage over `output` (reading `input`); false if it failed.
  bool RenderStageInto(const vtkRenderState* s, vtkOpenGLRenderWindow* window, int stage,
    vtkTextureObject* input, vtkTextureObject* output, int w, int h);
  /// The stages drawn into the bound framebuffer; false if one failed.
  bool RenderComposite(const vtkRenderState* s, vtkOpenGLRenderWindow* window, int w, int h);

  /// The stages of vtkLineAmbientOcclusionFS.glsl, one program each.
  enum Stage
  {
    StagePositions = 0, ///< every pixel's view point (offscreen)
    StageTiles = 1,     ///< per tile, its nearest and farthest depth (offscreen, halos only)
    StageCopy = 2,      ///< the delegate's color and depth
    StageOcclusion = 3, ///< the occlusion factor, over geometry only
    StageHalos = 4      ///< the halos, on the tiles that can hold one
  };
  /// The stage's program, built on first use and bound; null if it failed.
  vtkShaderProgram* ReadyStage(vtkOpenGLRenderWindow* window, int stage);
  /// The uniforms the stages read (view, window, settings).
  void SetUniforms(vtkShaderProgram* program, const vtkRenderState* s, int w, int h);
  /// How far from a pixel, in pixels, the halo stage reads.
  int HaloReach() const;

  struct vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
