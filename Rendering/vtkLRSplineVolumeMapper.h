// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkLRSplineVolumeMapper
 * @brief   Direct volume rendering of LR-spline volumes on the GPU, exact to the spline: no
 * resampling.
 *
 * Implements Fuchs, Barrowclough, Hjelmervik and Dahl, "Direct interactive
 * visualization of locally refined spline volumes for scalar and vector
 * fields" (Computers & Graphics 2018), §3.2 and §4. A VTK volume mapper: use
 * it with a vtkVolume and a vtkVolumeProperty. Input: the output of
 * vtkLRSplineReader, vtkIFEMReader, vtkLRSplineImageFitter or
 * vtkLRSplineFitter (one VTK_BEZIER_HEXAHEDRON grid per patch; the first
 * patch containing a point wins), or anything vtkLRSplineField::Build
 * accepts. Curved and rational geometry maps are rendered in physical space
 * (the map inverted per sample, as vtkLRSplineGeometryMap does).
 *
 * - Once per data change (§3.2): the Bernstein coefficients of every element,
 *   the element boxes and the search structure (ElementLocator: k-d forest of
 *   ForestResolution^3 trees, k-d tree, or for dyadic knots octree or look-up
 *   texture) go to the GPU; GetGPUMemorySize() counts the bytes.
 * - Per ray (Algorithm 2): value and exact gradient at every sample; adaptive
 *   steps (Eq. 4; AdaptiveSteps, StepScale) or SampleDistance; the transfer
 *   function Supersampling times between samples (§4.1); exact
 *   EmptySpaceSkipping; UseJittering; MaximumStepsPerPass.
 * - Shade with the exact gradient (ShadingModel: VTK's or Fuchs'); blend
 *   modes composite, maximum and minimum intensity, isosurface (crossings
 *   refined by IsosurfaceBisections); VectorMode for vector fields; opaque
 *   geometry drawn before ends the rays; clipping planes.
 * - Trimming (§4.1): a closed surface on input port 1
 *   (SetTrimmingSurfaceConnection), or, with TrimByDataBoundary, the data
 *   boundary that a vtkLRSplineFitter spline carries.
 *
 * Bad input (no field, a surface spline, rational data in field mode, NaN
 * coefficients, degrees above 3, an empty transfer function) is an error
 * naming the problem; nothing is drawn. Limits: degrees up to 3; at most 16
 * patches; the whole spline on each rank (no ordered compositing of pieces).
 * Details: docs/components.md; measurements: docs/performance.md.
 *
 * @sa vtkLRSplineReader vtkLRSplineField vtkLRSplineElementLocator
 */
#ifndef vtkLRSplineVolumeMapper_h
#define vtkLRSplineVolumeMapper_h

#include "SplineVizRenderingModule.h" // for export macro
#include "vtkAbstractVolumeMapper.h"

#include <array>  // for std::array
#include <memory> // for std::unique_ptr
#include <string> // for std::string
#include <vector> // for std::vector

class vtkMatrix4x4;
class vtkOpenGLRenderWindow;
class vtkPolyData;
class vtkShaderProgram;
class vtkRenderer;
class vtkVolume;
class vtkVolumeProperty;
class vtkWindow;

class SPLINEVIZRENDERING_EXPORT vtkLRSplineVolumeMapper : public vtkAbstractVolumeMapper
{
public:
  static vtkLRSplineVolumeMapper* New();
  vtkTypeMacro(vtkLRSplineVolumeMapper, vtkAbstractVolumeMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The blend modes (the values of vtkVolumeMapper's).
  enum BlendModes
  {
    COMPOSITE_BLEND = 0,
    MAXIMUM_INTENSITY_BLEND = 1,
    MINIMUM_INTENSITY_BLEND = 2,
    ISOSURFACE_BLEND = 5
  };

  ///@{
  /**
   * Blend mode. Default COMPOSITE_BLEND.
   */
  void SetBlendMode(int mode);
  vtkGetMacro(BlendMode, int);
  void SetBlendModeToComposite() { this->SetBlendMode(COMPOSITE_BLEND); }
  void SetBlendModeToMaximumIntensity() { this->SetBlendMode(MAXIMUM_INTENSITY_BLEND); }
  void SetBlendModeToMinimumIntensity() { this->SetBlendMode(MINIMUM_INTENSITY_BLEND); }
  void SetBlendModeToIsoSurface() { this->SetBlendMode(ISOSURFACE_BLEND); }
  ///@}

  ///@{
  /**
   * Name of the point-data array of coefficients to render (the reader's and
   * the fitters' OutputFieldName, "Field" by default). nullptr or ""
   * (default): the active vectors, else the active scalars, else the first
   * array.
   */
  vtkSetStringMacro(FieldArray);
  vtkGetStringMacro(FieldArray);
  ///@}

  ///@{
  /// Deprecated: use SetFieldArray / GetFieldArray; kept for one release.
  void SetFieldArrayName(const char* name) { this->SetFieldArray(name); }
  char* GetFieldArrayName() { return this->GetFieldArray(); }
  ///@}

  enum VectorModes
  {
    MAGNITUDE = -1, ///< the length of the vector field
    COMPONENT = 0   ///< one component (VectorComponent)
  };

  ///@{
  /**
   * For fields with several components: their MAGNITUDE (default) or one
   * COMPONENT (VectorComponent). A scalar field is rendered as it is.
   */
  vtkSetClampMacro(VectorMode, int, MAGNITUDE, COMPONENT);
  vtkGetMacro(VectorMode, int);
  void SetVectorModeToMagnitude() { this->SetVectorMode(MAGNITUDE); }
  void SetVectorModeToComponent() { this->SetVectorMode(COMPONENT); }
  vtkSetClampMacro(VectorComponent, int, 0, 2);
  vtkGetMacro(VectorComponent, int);
  ///@}

  enum Locators
  {
    KD_FOREST = 2, ///< vtkLRSplineElementLocator::KD_FOREST (default)
    KD_TREE = 1,
    OCTREE = 3, ///< dyadic knots only
    TEXTURE = 4 ///< dyadic knots only
  };

  ///@{
  /**
   * Element search structure on the GPU (the values of
   * vtkLRSplineElementLocator::LocatorType). Default KD_FOREST.
   */
  vtkSetClampMacro(ElementLocator, int, KD_TREE, TEXTURE);
  vtkGetMacro(ElementLocator, int);
  void SetElementLocatorToKdForest() { this->SetElementLocator(KD_FOREST); }
  void SetElementLocatorToKdTree() { this->SetElementLocator(KD_TREE); }
  void SetElementLocatorToOctree() { this->SetElementLocator(OCTREE); }
  void SetElementLocatorToTexture() { this->SetElementLocator(TEXTURE); }
  ///@}

  ///@{
  /**
   * Trees per direction of the k-d forest (0, default: automatic, about
   * 2 x the cube root of the element count, at most 64).
   */
  vtkSetClampMacro(ForestResolution, int, 0, 512);
  vtkGetMacro(ForestResolution, int);
  ///@}

  ///@{
  /**
   * Adaptive steps (Eq. 4: the current element's shortest side / 2^degree,
   * times StepScale; default on) or fixed steps of SampleDistance.
   */
  vtkSetMacro(AdaptiveSteps, bool);
  vtkGetMacro(AdaptiveSteps, bool);
  vtkBooleanMacro(AdaptiveSteps, bool);
  vtkSetClampMacro(StepScale, double, 1e-3, 100.0);
  vtkGetMacro(StepScale, double);
  ///@}

  ///@{
  /**
   * Fixed step in world units (AdaptiveSteps off). 0 (default): a hundredth of
   * the diagonal of the patches' box.
   */
  vtkSetClampMacro(SampleDistance, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(SampleDistance, double);
  ///@}

  ///@{
  /**
   * Empty-space skipping (default on): rays jump over the elements whose
   * Bezier coefficients (which bound the element's values: convex hull
   * property) map to zero opacity, or, for isosurfaces, hold no iso value.
   * Exact: skipped elements add nothing.
   */
  vtkSetMacro(EmptySpaceSkipping, bool);
  vtkGetMacro(EmptySpaceSkipping, bool);
  vtkBooleanMacro(EmptySpaceSkipping, bool);
  ///@}

  /// Elements skipped in the last render (empty-space skipping).
  vtkIdType GetNumberOfSkippedElements();

  ///@{
  /**
   * Transfer-function samples per spline step (§4.1). Default 4; 1 turns the
   * supersampling off.
   */
  vtkSetClampMacro(Supersampling, int, 1, 64);
  vtkGetMacro(Supersampling, int);
  ///@}

  ///@{
  /**
   * Start each ray at a random point of its first step (VTK's jittering,
   * against wood-grain). Default off.
   */
  vtkSetMacro(UseJittering, bool);
  vtkGetMacro(UseJittering, bool);
  vtkBooleanMacro(UseJittering, bool);
  ///@}

  enum ShadingModels
  {
    PHONG = 0, ///< VTK's ambient, diffuse and specular (the volume property's)
    FUCHS = 1  ///< Fuchs et al.'s diffuse model max(0.4, |l . n|)
  };

  ///@{
  /**
   * Shading model when the volume property's Shade is on. Default PHONG.
   */
  vtkSetClampMacro(ShadingModel, int, PHONG, FUCHS);
  vtkGetMacro(ShadingModel, int);
  void SetShadingModelToPhong() { this->SetShadingModel(PHONG); }
  void SetShadingModelToFuchs() { this->SetShadingModel(FUCHS); }
  ///@}

  ///@{
  /**
   * Bisection steps refining an isosurface crossing on the exact spline.
   * Default 16.
   */
  vtkSetClampMacro(IsosurfaceBisections, int, 1, 40);
  vtkGetMacro(IsosurfaceBisections, int);
  ///@}

  ///@{
  /**
   * Largest number of samples per ray. 0 (default): automatic, enough for a
   * ray across the whole box at the finest step (adaptive: the smallest
   * element's step times StepScale; fixed: SampleDistance), so that the step
   * count cuts no ray short; a positive value caps the work per pixel (rays
   * stop there). Rays longer than MaximumStepsPerPass samples continue in
   * further passes (Mesa's llvmpipe ends a fragment's loops after 65,535
   * iterations in all, about 4,000 samples per pass).
   */
  vtkSetClampMacro(MaximumNumberOfSteps, int, 0, VTK_INT_MAX);
  vtkGetMacro(MaximumNumberOfSteps, int);
  ///@}

  ///@{
  /**
   * Samples per ray and rendering pass. Rays that need more (the number of
   * samples of MaximumNumberOfSteps, or its automatic estimate) are
   * continued in further passes: the ray state (position, previous sample,
   * accumulated color and opacity) is kept in viewport-sized float textures
   * (7 x 16 bytes per pixel while passes are needed) and each pass resumes
   * the unfinished rays, until none is left; then the final colors are drawn.
   * So every step setting renders completely, also where a shader's loops
   * are capped (Mesa's llvmpipe: 65,535 iterations per invocation). 0
   * (default): automatic, 2000 samples (400 on curved geometry, whose
   * samples run Newton's method). Not used with CountSamples.
   */
  vtkSetClampMacro(MaximumStepsPerPass, int, 0, VTK_INT_MAX);
  vtkGetMacro(MaximumStepsPerPass, int);
  /// Rendering passes of the last frame (1 without continuation).
  int GetNumberOfPasses();
  ///@}

  ///@{
  /**
   * The trimming surface (input port 1, optional): a closed vtkPolyData of
   * polygons in the volume's data coordinates. Without one, the input's
   * vtkLRSplineField::TRIMMING_SURFACE (the fitted data's boundary) if it
   * has one (TrimByDataBoundary).
   */
  void SetTrimmingSurfaceConnection(vtkAlgorithmOutput* output);
  void SetTrimmingSurfaceData(vtkPolyData* surface);
  ///@}

  ///@{
  /**
   * Trim by the input's vtkLRSplineField::TRIMMING_SURFACE (the boundary of
   * the data vtkLRSplineFitter fitted) when port 1 has no surface. Default on;
   * off shows the whole fitted box.
   */
  vtkSetMacro(TrimByDataBoundary, bool);
  vtkGetMacro(TrimByDataBoundary, bool);
  vtkBooleanMacro(TrimByDataBoundary, bool);
  ///@}

  /**
   * The surface the next render trims by (port 1's, brought up to date, else
   * the input's TRIMMING_SURFACE with TrimByDataBoundary); null: none.
   */
  vtkPolyData* GetTrimmingSurface();

  /**
   * Debugging and tests: instead of colors, write the number of spline
   * evaluations of each pixel's ray as a 24-bit integer in RGB (R lowest).
   */
  vtkSetMacro(CountSamples, bool);
  vtkGetMacro(CountSamples, bool);
  vtkBooleanMacro(CountSamples, bool);

  /**
   * Bytes of spline data on the GPU: coefficients, element boxes and
   * coefficient offsets, search structures (not the transfer function and
   * depth textures, which depend on the window).
   */
  size_t GetGPUMemorySize();

  /**
   * Build the GPU-side data for the current input now (also done by the first
   * render): false when the input cannot be rendered (GetLastErrorMessage()
   * says why).
   */
  bool UpdateSpline();

  /// Number of elements of all patches (after UpdateSpline()).
  vtkIdType GetNumberOfElements();

  /// The message of the last failure (empty when the last render worked).
  const char* GetLastErrorMessage();

  void Render(vtkRenderer* ren, vtkVolume* vol) override;
  void ReleaseGraphicsResources(vtkWindow* window) override;
  double* GetBounds() override;
  void GetBounds(double bounds[6]) override { this->vtkAbstractVolumeMapper::GetBounds(bounds); }

protected:
  vtkLRSplineVolumeMapper();
  ~vtkLRSplineVolumeMapper() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;

  /**
   * The ray caster's sources from vtkLRSplineVolumeShaderBuilder: the vertex
   * stage, and the fragment template (with the shared evaluation code) that
   * the builder completes with the options of each frame. Tests override
   * them to check that broken shaders are caught.
   */
  virtual std::string GetVertexShaderSource();
  virtual std::string GetFragmentShaderSource();

  int BlendMode = COMPOSITE_BLEND;
  char* FieldArray = nullptr;
  int VectorMode = MAGNITUDE;
  int VectorComponent = 0;
  int ElementLocator = KD_FOREST;
  int ForestResolution = 0;
  bool AdaptiveSteps = true;
  double StepScale = 1.0;
  double SampleDistance = 0.0;
  int Supersampling = 4;
  bool EmptySpaceSkipping = true;
  bool UseJittering = false;
  int ShadingModel = PHONG;
  int IsosurfaceBisections = 16;
  int MaximumNumberOfSteps = 0;
  int MaximumStepsPerPass = 0;
  bool CountSamples = false;
  bool TrimByDataBoundary = true;
  int WarnedSteps = 0; // the step count last checked against llvmpipe's loop limit

private:
  vtkLRSplineVolumeMapper(const vtkLRSplineVolumeMapper&) = delete;
  void operator=(const vtkLRSplineVolumeMapper&) = delete;

  // vtkErrorMacro for the current error unless it was reported already.
  void ReportError();

  // The steps of Render(), each false with the error set when it fails:
  // the spline's arrays to the GPU (once per change); the transfer function
  // as a texture; the iso values (isosurface blending); the empty-space
  // skipping flags of the elements (per transfer function and blend mode).
  bool UploadSpline(vtkOpenGLRenderWindow* window);
  bool UpdateTransferFunction(vtkOpenGLRenderWindow* window, vtkVolumeProperty* property);
  bool CollectIsoValues(vtkVolumeProperty* property, std::vector<float>& isoValues);
  bool UpdateEmptySpaceSkipping(vtkOpenGLRenderWindow* window, vtkVolumeProperty* property,
    const std::vector<float>& isoValues);
  // The depth of the opaque geometry drawn so far into a texture.
  void CopyOpaqueDepth(const int viewport[4]);
  // The uniforms of the patches.
  void SetPatchUniforms(vtkShaderProgram* program);
  // The trimming surface's nearest front and farthest back depths (§4.1);
  // `program` is made current again.
  bool RenderTrimmingDepths(
    vtkShaderProgram* program, vtkMatrix4x4* dataToClip, const int viewport[4]);

  // Samples per ray (MaximumNumberOfSteps or the automatic estimate) and the
  // fixed step (world units) for the volume's placement.
  int ComputeStepCount(vtkVolume* vol, double& sampleDistance);

  // The ray caster's program for this frame: the options that change the
  // shader text (spline, blend mode, shading, trimming, passes,
  // supersampling, lights) into the shader builder, its source compiled;
  // null (error set) when it does not compile or link.
  vtkShaderProgram* ReadyProgram(
    vtkOpenGLRenderWindow* window, bool shade, bool multiPass, int numberOfLights);
  // The matrices (data to clip space and back, data to world, normals), the
  // viewport and the proxy box.
  void SetTransformUniforms(vtkShaderProgram* program, vtkMatrix4x4* dataToWorld,
    vtkMatrix4x4* dataToClip, const int viewport[4], const double box[6]);
  // The step settings and the samples per pass; returns the samples per ray.
  int SetSamplingUniforms(
    vtkShaderProgram* program, vtkVolume* vol, bool multiPass, int stepsPerPass);
  // The proxy box's triangles (the box, padded, data coordinates), when it changed.
  void UpdateProxyBox(const double box[6]);
  // ClippingPlanes (at most 6) as plane equations in data coordinates.
  void SetClippingPlaneUniforms(vtkShaderProgram* program, vtkMatrix4x4* dataToWorld);
  // The transfer range, the property's shading, the lights (direction and
  // color each) and the iso values.
  void SetShadingUniforms(vtkShaderProgram* program, vtkVolumeProperty* property,
    const std::vector<std::array<float, 6>>& lightList, const std::vector<float>& isoValues);
  // The spline's buffers, the transfer function, the depth and (trim) the
  // trimming depths bound to their samplers; and unbound.
  void ActivateTextures(vtkShaderProgram* program, bool trim);
  void DeactivateTextures(bool trim);

  // The rays in one pass into the current draw framebuffer.
  void DrawSinglePass();
  // The rays in passes (continuation, see MaximumStepsPerPass; at most
  // totalSteps samples per ray) into the current draw framebuffer; false
  // (error set) when a GPU resource failed.
  bool DrawPasses(vtkRenderer* ren, vtkShaderProgram* program, vtkMatrix4x4* dataToClip,
    const int viewport[4], int stepsPerPass, int totalSteps);

  struct vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
