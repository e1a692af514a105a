// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkLRSplineVolumeShaderBuilder
 * @brief   The GLSL sources of vtkLRSplineVolumeMapper for a set of options (internal).
 *
 * The shader-text half of the LR-spline volume mapper, as
 * vtkVolumeShaderComposer is for VTK's GPU ray caster: no OpenGL, only
 * strings. Given what changes the shader text (the spline's common degrees,
 * components and patch count, curved geometry, the vector mode, blend mode,
 * shading and shading model, trimming, sample counting, multi-pass
 * continuation, supersampling and the number of lights), it returns the
 * vertex and fragment sources of the ray caster (Fuchs et al. §4), the
 * trimming depth pre-pass (§4.1) and the final draw of the multi-pass
 * continuation. The ray caster's shared GLSL (glsl/vtkLRSplineVolumeShared.glsl
 * and the SplineViz prelude) is substituted for its //SV:: placeholders and
 * the options become #define lines after //VTK::System::Dec; the //VTK::
 * placeholders left are the ones VTK's shader cache replaces (System,
 * Output). The array sizes the shaders are compiled for (patches, iso
 * values, clipping planes, lights) are the limits below; the mapper sets
 * uniforms within them.
 *
 * Internal to vtkLRSplineVolumeMapper (not wrapped); unit-tested by
 * TestLRSplineVolumeShaderBuilder.
 *
 * @sa vtkLRSplineVolumeMapper
 */
#ifndef vtkLRSplineVolumeShaderBuilder_h
#define vtkLRSplineVolumeShaderBuilder_h

#include "SplineVizRenderingModule.h" // for export macro
#include "vtkObject.h"

#include <string> // for std::string
#include <vector> // for std::vector

class SPLINEVIZRENDERING_EXPORT vtkLRSplineVolumeShaderBuilder : public vtkObject
{
public:
  static vtkLRSplineVolumeShaderBuilder* New();
  vtkTypeMacro(vtkLRSplineVolumeShaderBuilder, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The sizes of the shaders' uniform arrays: the most the mapper renders.
  static constexpr int MaximumPatches = 16;
  static constexpr int MaximumIsoValues = 8;
  static constexpr int MaximumClipPlanes = 6;
  static constexpr int MaximumLights = 8;
  ///@}

  ///@{
  /// The spline's common degrees (1 to 3 each; default 1, 1, 1).
  vtkSetVector3Macro(Degree, int);
  vtkGetVector3Macro(Degree, int);
  ///@}

  ///@{
  /// Components of the field (1 to 3; default 1).
  vtkSetClampMacro(NumberOfComponents, int, 1, 3);
  vtkGetMacro(NumberOfComponents, int);
  ///@}

  ///@{
  /**
   * vtkLRSplineVolumeMapper's VectorMode (-1 magnitude, default; 0 one
   * component) and VectorComponent: a vector field's magnitude or that
   * component (a scalar field is used as it is).
   */
  vtkSetClampMacro(VectorMode, int, -1, 0);
  vtkGetMacro(VectorMode, int);
  vtkSetClampMacro(VectorComponent, int, 0, 2);
  vtkGetMacro(VectorComponent, int);
  ///@}

  ///@{
  /// Number of patches (1 to MaximumPatches; default 1).
  vtkSetClampMacro(NumberOfPatches, int, 1, MaximumPatches);
  vtkGetMacro(NumberOfPatches, int);
  ///@}

  ///@{
  /// Some patch has a curved geometry map (default off).
  vtkSetMacro(Curved, bool);
  vtkGetMacro(Curved, bool);
  ///@}

  ///@{
  /// vtkLRSplineVolumeMapper::BlendModes (default 0, composite).
  vtkSetMacro(BlendMode, int);
  vtkGetMacro(BlendMode, int);
  ///@}

  ///@{
  /**
   * Shade with the exact gradient (the volume property's Shade; default
   * off; never while counting samples) and with Fuchs et al.'s diffuse
   * model instead of VTK's (default off).
   */
  vtkSetMacro(Shade, bool);
  vtkGetMacro(Shade, bool);
  vtkSetMacro(FuchsShading, bool);
  vtkGetMacro(FuchsShading, bool);
  ///@}

  ///@{
  /// Trim by the depths of a trimming surface (§4.1; default off).
  vtkSetMacro(Trim, bool);
  vtkGetMacro(Trim, bool);
  ///@}

  ///@{
  /// Write the number of spline evaluations instead of colors (default off).
  vtkSetMacro(CountSamples, bool);
  vtkGetMacro(CountSamples, bool);
  ///@}

  ///@{
  /// Continue the rays in passes (ray state in textures; default off).
  vtkSetMacro(MultiPass, bool);
  vtkGetMacro(MultiPass, bool);
  ///@}

  ///@{
  /// Transfer-function samples per step, composite blending only (default 4).
  vtkSetClampMacro(Supersampling, int, 1, 64);
  vtkGetMacro(Supersampling, int);
  ///@}

  ///@{
  /// Number of lights (1 to MaximumLights; default 1).
  vtkSetClampMacro(NumberOfLights, int, 1, MaximumLights);
  vtkGetMacro(NumberOfLights, int);
  ///@}

  /// The proxy box's vertex stage (used by all three programs).
  std::string GetVertexShaderSource();

  /**
   * The ray caster's fragment template: the shared GLSL substituted, the
   * options not yet (vtkLRSplineVolumeMapper::GetFragmentShaderSource()).
   */
  std::string GetFragmentShaderTemplate();

  /// `fragmentTemplate` with the options' #define lines: the source to compile.
  std::string BuildFragmentShaderSource(const std::string& fragmentTemplate);

  /// BuildFragmentShaderSource(GetFragmentShaderTemplate()).
  std::string GetFragmentShaderSource();

  /// The trimming surface's depth pre-pass.
  std::string GetTrimmingFragmentShaderSource();

  /// The final draw of the multi-pass continuation.
  std::string GetCompositeFragmentShaderSource();

  /**
   * The placeholders (//SV::Xxx::Yyy, //VTK::Xxx::Yyy) in `source` that VTK's
   * shader cache does not replace: empty for a complete source.
   */
  static std::vector<std::string> GetUnreplacedPlaceholders(const std::string& source);

protected:
  vtkLRSplineVolumeShaderBuilder() = default;
  ~vtkLRSplineVolumeShaderBuilder() override = default;

  int Degree[3] = { 1, 1, 1 };
  int NumberOfComponents = 1;
  int VectorMode = -1;
  int VectorComponent = 0;
  int NumberOfPatches = 1;
  bool Curved = false;
  int BlendMode = 0;
  bool Shade = false;
  bool FuchsShading = false;
  bool Trim = false;
  bool CountSamples = false;
  bool MultiPass = false;
  int Supersampling = 4;
  int NumberOfLights = 1;

private:
  vtkLRSplineVolumeShaderBuilder(const vtkLRSplineVolumeShaderBuilder&) = delete;
  void operator=(const vtkLRSplineVolumeShaderBuilder&) = delete;
};

#endif
