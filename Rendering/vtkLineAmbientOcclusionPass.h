// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkLineAmbientOcclusionPass
 * @brief   Screen-space ambient occlusion and depth-dependent halos for dense
 * lines and tubes, from the depth buffer alone.
 *
 * A render pass that draws its delegate (e.g. a vtkRenderStepsPass) into an
 * offscreen color and depth buffer, then darkens each pixel by its ambient
 * occlusion and, optionally, draws depth-dependent halos. Only the depth
 * buffer is read, so it works for any opaque geometry that writes its depth:
 * the three line mappers and ordinary polygons.
 *
 * - Ambient occlusion (in the spirit of Eichelbaum et al., "LineAO", 2013):
 *   the view point and normal of each pixel are rebuilt from the depth;
 *   Samples points on each of Levels disks (the largest of Radius, each half
 *   the next) occlude it by max(0, n.(Q-P)/|Q-P| - Bias)/(1 - Bias), weighted
 *   by max(0, 1 - |Q-P|^2/R^2); the color is multiplied by
 *   clamp(1 - Strength o, 0, 1). An isolated tube does not occlude itself.
 * - Depth-dependent halos (Everts et al., "Depth-dependent halos", 2009;
 *   DepthHalos): a pixel lies in the halo of a nearer pixel at screen
 *   distance s when s < HaloWidth clamp((gap - HaloDepthOffset) /
 *   HaloDepthRange, 0, 1), in HaloColor or the background. A line gets no
 *   halo from itself while HaloDepthOffset exceeds its radius.
 * - LengthUnits: Radius, HaloDepthOffset and HaloDepthRange in pixels (the
 *   default) or world units; HaloWidth always in pixels.
 *
 * Usage: pass->SetDelegatePass(renderSteps); renderer->SetPass(pass).
 * Limits: translucent geometry is darkened with what lies behind it; the
 * buffers are single-sampled (no multisampling); hardware picking bypasses
 * the pass. Its stages and costs: docs/line-rendering.md, "Depth cues".
 *
 * @sa vtkSSAOPass vtkStylizedLineMapper vtkRayCastTubeMapper vtkTessellatedTubeMapper
 */
#ifndef vtkLineAmbientOcclusionPass_h
#define vtkLineAmbientOcclusionPass_h

#include "SplineVizRenderingModule.h" // for export macro
#include "vtkImageProcessingPass.h"

#include <memory> // for std::unique_ptr

class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkTextureObject;

class SPLINEVIZRENDERING_EXPORT vtkLineAmbientOcclusionPass : public vtkImageProcessingPass
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
  /// For tests: the halo stage on every tile, every pixel taking its samples
  /// until full coverage (the search without bounds). Set before the first
  /// render.
  bool HaloFullSearch = false;

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
    StagePositions = 0,  ///< every pixel's view point (offscreen)
    StageBlocks = 1,     ///< per block, its nearest and farthest depth (offscreen, halos only)
    StageBlockReach = 2, ///< per block, the nearest depth within reach (offscreen, halos only)
    StageCopy = 3,       ///< the delegate's color and depth
    StageOcclusion = 4,  ///< the occlusion factor, over geometry only
    StageHalos = 5       ///< the halos, on the tiles that can hold one
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
