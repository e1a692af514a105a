// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkSuperquadricGlyphMapper
 * @brief   Ray-cast superquadric tensor glyphs on the GPU, one per point.
 *
 * Draws Kindlmann's superquadric tensor glyph (Kindlmann, "Superquadric
 * Tensor Glyphs", VisSym 2004) at every point of any vtkDataSet or of every
 * leaf of a composite data set, ray cast on the GPU after Hlawitschka,
 * Eichelbaum and Scheuermann, "Fast and memory efficient GPU-based rendering
 * of tensor data" (§3.1-3.6):
 *
 * - only the raw tensors are uploaded, once per data change: 36 bytes per
 *   glyph (+4 with scalar colors); NaN/infinite, zero and masked
 *   (MaskArray) tensors are left out, with one warning per data change;
 * - per frame on the GPU: eigen-decomposition (the code of
 *   vtkSplineVizTensorMath), Westin metrics, Kindlmann's shape from Gamma,
 *   a sprite of the glyph box's front faces and a ray cast of the implicit
 *   surface (at most MaximumIterations evaluations) with exact depth and
 *   analytic normal; changing Gamma, the scale, thresholds, sign policy or
 *   GlyphColorMode sets uniforms only (GetUploadCount());
 * - size: ScaleMode SCALE_BY_EIGENVALUES, SCALE_NORMALIZED or SCALE_CLAMPED
 *   (MaximumScale), times ScaleFactor; MinimumThickness, MinimumRoundness;
 * - colors: COLOR_BY_EIGENVECTOR (|e1| RGB x FA), COLOR_BY_SCALARS (the
 *   lookup table), COLOR_SOLID, COLOR_BY_QUADRATIC_FORM;
 * - indefinite tensors (NegativeEigenvaluePolicy SCHULTZ_KINDLMANN): the
 *   glyphs of Schultz and Kindlmann (IEEE TVCG 2010, §4.2-4.3), blended
 *   across a zero eigenvalue within ZeroEigenvalueBand;
 * - clipping planes (up to 6) cut the glyphs as solids; composite inputs
 *   take per-block colors, opacities and visibility;
 * - exact occlusion culling (Culling, on for opaque, non-multisampled
 *   rendering; NumberOfCullingGroups): the same image as without it.
 *
 * Picking: prop picking and point-id selection. Not supported: texture maps.
 * Bad input: a missing tensor array, or one whose components do not fit
 * TensorLayout, is an error for that block (nothing drawn for it). Design
 * and performance: docs/components.md, "Superquadric tensor glyphs", and
 * docs/performance.md.
 */
#ifndef vtkSuperquadricGlyphMapper_h
#define vtkSuperquadricGlyphMapper_h

#include "SplineVizRenderingModule.h" // for export macro
#include "vtkNew.h"                   // for vtkNew
#include "vtkOpenGLPolyDataMapper.h"

#include <memory> // for unique_ptr
#include <string> // for std::string

class vtkCompositeDataDisplayAttributes;
class vtkDataSet;
class vtkFloatArray;

class SPLINEVIZRENDERING_EXPORT vtkSuperquadricGlyphMapper : public vtkOpenGLPolyDataMapper
{
public:
  static vtkSuperquadricGlyphMapper* New();
  vtkTypeMacro(vtkSuperquadricGlyphMapper, vtkOpenGLPolyDataMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Scale modes: the semi-axes are ScaleFactor * l_i (SCALE_BY_EIGENVALUES),
   * ScaleFactor * l_i / l_1 (SCALE_NORMALIZED: the largest semi-axis is
   * ScaleFactor) or ScaleFactor * l_i uniformly shrunk to a largest semi-axis
   * of at most MaximumScale (SCALE_CLAMPED); every semi-axis is then at least
   * MinimumThickness times the largest (vtkTensorGlyph with a source of size
   * 2 gives the same sizes).
   */
  enum ScaleModes
  {
    SCALE_BY_EIGENVALUES = 0,
    SCALE_NORMALIZED = 1,
    SCALE_CLAMPED = 2
  };

  /// Negative-eigenvalue policies (vtkSplineVizTensorMath::SignPolicy).
  enum NegativeEigenvaluePolicies
  {
    SKIP_NEGATIVE = 0,
    ABSOLUTE_VALUES = 1,
    SCHULTZ_KINDLMANN = 2
  };

  /**
   * Color modes: COLOR_BY_EIGENVECTOR (|e1| as RGB times FA, the usual DTI
   * map), COLOR_BY_SCALARS (the mapper's point scalars through its lookup
   * table, as any vtkMapper; without scalars the actor's color),
   * COLOR_SOLID (the actor's property), COLOR_BY_QUADRATIC_FORM (the sign of
   * x^T T x on the surface, as Schultz and Kindlmann do). Lighting and
   * opacity come from the actor's property.
   */
  enum ColorModes
  {
    COLOR_BY_EIGENVECTOR = 0,
    COLOR_BY_SCALARS = 1,
    COLOR_SOLID = 2,
    COLOR_BY_QUADRATIC_FORM = 3
  };

  /**
   * The input: any vtkDataSet or composite data set with a point tensor array.
   */
  void SetInputData(vtkDataObject* input);

  ///@{
  /**
   * Inputs are routed through an internal preparation step
   * (vtkSuperquadricGlyphPreparer) that keeps the drawable points' positions
   * and tensors; GetInput() returns its output (a vtkPolyData of glyph points).
   */
  void SetInputConnection(int port, vtkAlgorithmOutput* input) override;
  void SetInputConnection(vtkAlgorithmOutput* input) override
  {
    this->SetInputConnection(0, input);
  }
  void SetInputDataObject(int port, vtkDataObject* input) override;
  void SetInputDataObject(vtkDataObject* input) override { this->SetInputDataObject(0, input); }
  ///@}

  /// Bounds of the glyphs (the points padded by the largest possible glyph).
  double* GetBounds() override;
  void GetBounds(double bounds[6]) override { this->Superclass::GetBounds(bounds); }

  ///@{
  /**
   * Name of the point tensor array; nullptr (default) uses the active point
   * tensors of each data set.
   */
  vtkSetStringMacro(TensorArray);
  vtkGetStringMacro(TensorArray);
  ///@}

  ///@{
  /**
   * Component order of 6-component tensor arrays, a
   * vtkSplineVizTensorMath::TensorLayout: SYMMETRIC_VTK (1, default: XX YY ZZ
   * XY YZ XZ), SYMMETRIC_LOWER (2: XX XY YY XZ YZ ZZ, NIfTI and DIPY) or
   * SYMMETRIC_UPPER (3: XX XY XZ YY YZ ZZ, FSL dtifit and MFEM). 9-component arrays are read
   * as row-major 3x3 matrices (symmetrized), 7-component arrays as Teem/NRRD
   * (confidence first, ignored); FULL_9 (0) and TEEM_7 (4) demand them.
   */
  vtkSetClampMacro(TensorLayout, int, 0, 4);
  vtkGetMacro(TensorLayout, int);
  ///@}

  ///@{
  /**
   * Optional point array: points where its (first component) value is 0 are
   * not drawn (and not uploaded). nullptr (default): no mask.
   */
  vtkSetStringMacro(MaskArray);
  vtkGetStringMacro(MaskArray);
  ///@}

  ///@{
  /**
   * Deprecated: use SetTensorArray, SetMaskArray (and their Get methods);
   * kept for one release.
   */
  void SetTensorArrayName(const char* name) { this->SetTensorArray(name); }
  char* GetTensorArrayName() { return this->GetTensorArray(); }
  void SetMaskArrayName(const char* name) { this->SetMaskArray(name); }
  char* GetMaskArrayName() { return this->GetMaskArray(); }
  ///@}

  ///@{
  /**
   * Kindlmann's sharpness gamma >= 0: 0 gives ellipsoids, large values boxes
   * and cylinders. Default 3 (Teem's default).
   */
  vtkSetClampMacro(Gamma, double, 0.0, 1000.0);
  vtkGetMacro(Gamma, double);
  ///@}

  ///@{
  /**
   * Lower bound of alpha and beta, in [0.05, 1]. Default 0.2 (the paper's
   * suggestion: exponents 2/alpha, 2/beta of at most 10).
   */
  vtkSetClampMacro(MinimumRoundness, double, 0.05, 1.0);
  vtkGetMacro(MinimumRoundness, double);
  ///@}

  ///@{
  /// Scale factor of the glyphs (see the class documentation). Default 1.
  vtkSetClampMacro(ScaleFactor, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(ScaleFactor, double);
  ///@}

  ///@{
  /// Scale mode (ScaleModes). Default SCALE_BY_EIGENVALUES.
  vtkSetClampMacro(ScaleMode, int, SCALE_BY_EIGENVALUES, SCALE_CLAMPED);
  vtkGetMacro(ScaleMode, int);
  ///@}

  ///@{
  /// Largest semi-axis in SCALE_CLAMPED mode. Default 1.
  vtkSetClampMacro(MaximumScale, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(MaximumScale, double);
  ///@}

  ///@{
  /**
   * Every semi-axis is at least this fraction of the largest one, in [0, 1]
   * (a zero eigenvalue would make a flat glyph). Default 0.05.
   */
  vtkSetClampMacro(MinimumThickness, double, 0.0, 1.0);
  vtkGetMacro(MinimumThickness, double);
  ///@}

  ///@{
  /**
   * Glyphs of tensors with a fractional anisotropy below this value are not
   * drawn (FA of the eigenvalues drawn, i.e. after the negative-eigenvalue
   * policy, so in [0, 1]). Default 0 (all).
   */
  vtkSetClampMacro(AnisotropyThreshold, double, 0.0, 1.0);
  vtkGetMacro(AnisotropyThreshold, double);
  ///@}

  ///@{
  /**
   * Glyphs whose smallest eigenvalue (after the negative-eigenvalue policy)
   * is below this value are not drawn. Default -VTK_DOUBLE_MAX (all).
   */
  vtkSetMacro(MinimumEigenvalue, double);
  vtkGetMacro(MinimumEigenvalue, double);
  ///@}

  ///@{
  /**
   * What to do with negative eigenvalues (NegativeEigenvaluePolicies):
   * SKIP_NEGATIVE (default, as Teem) does not draw tensors with a negative
   * eigenvalue; ABSOLUTE_VALUES draws the glyph of the absolute values;
   * SCHULTZ_KINDLMANN draws Schultz and Kindlmann's glyph of the signed
   * eigenvalues (see docs/components.md, "Superquadric tensor glyphs").
   */
  vtkSetClampMacro(NegativeEigenvaluePolicy, int, SKIP_NEGATIVE, SCHULTZ_KINDLMANN);
  vtkGetMacro(NegativeEigenvaluePolicy, int);
  void SetNegativeEigenvaluePolicyToSkipNegative()
  {
    this->SetNegativeEigenvaluePolicy(SKIP_NEGATIVE);
  }
  void SetNegativeEigenvaluePolicyToAbsoluteValues()
  {
    this->SetNegativeEigenvaluePolicy(ABSOLUTE_VALUES);
  }
  void SetNegativeEigenvaluePolicyToSchultzKindlmann()
  {
    this->SetNegativeEigenvaluePolicy(SCHULTZ_KINDLMANN);
  }
  ///@}

  ///@{
  /**
   * SCHULTZ_KINDLMANN only: width, relative to the largest |eigenvalue|, of
   * the band on the indefinite side of a zero eigenvalue in which the glyph
   * is blended with the definite side's glyph (see the class documentation),
   * in [0, 0.5]. Default 0.15. 0 gives the paper's glyphs exactly, which
   * change abruptly at the zero eigenvalue when MinimumThickness > 0.
   */
  vtkSetClampMacro(ZeroEigenvalueBand, double, 0.0, 0.5);
  vtkGetMacro(ZeroEigenvalueBand, double);
  ///@}

  ///@{
  /// Color mode (ColorModes). Default COLOR_BY_EIGENVECTOR.
  vtkSetClampMacro(GlyphColorMode, int, COLOR_BY_EIGENVECTOR, COLOR_BY_QUADRATIC_FORM);
  vtkGetMacro(GlyphColorMode, int);
  void SetGlyphColorModeToEigenvector() { this->SetGlyphColorMode(COLOR_BY_EIGENVECTOR); }
  void SetGlyphColorModeToScalars() { this->SetGlyphColorMode(COLOR_BY_SCALARS); }
  void SetGlyphColorModeToSolid() { this->SetGlyphColorMode(COLOR_SOLID); }
  void SetGlyphColorModeToQuadraticForm() { this->SetGlyphColorMode(COLOR_BY_QUADRATIC_FORM); }
  ///@}

  ///@{
  /**
   * Colors of COLOR_BY_QUADRATIC_FORM: each point x of a glyph's surface
   * (relative to its center) is drawn in PositiveFormColor where
   * x^T T x > 0 (e.g. tension of a stress tensor) and in NegativeFormColor
   * where x^T T x < 0 (compression), as Schultz and Kindlmann color their
   * glyphs (T and -T have the same Schultz-Kindlmann shape). Defaults
   * orange (0.9, 0.45, 0.2) and blue (0.2, 0.45, 0.9).
   */
  vtkSetVector3Macro(PositiveFormColor, double);
  vtkGetVector3Macro(PositiveFormColor, double);
  vtkSetVector3Macro(NegativeFormColor, double);
  vtkGetVector3Macro(NegativeFormColor, double);
  ///@}

  ///@{
  /**
   * Maximum number of evaluations of the superquadric function per ray, in
   * [1, 100]. Default 10 (the paper's maximum).
   */
  vtkSetClampMacro(MaximumIterations, int, 1, 100);
  vtkGetMacro(MaximumIterations, int);
  ///@}

  ///@{
  /**
   * Per-block display attributes of composite inputs, as for
   * vtkCompositePolyDataMapper2 (keyed by the leaf data sets of the input):
   * block visibility hides a block's glyphs, block opacity multiplies their
   * opacity (the mapper is then drawn as translucent), block color replaces
   * the actor's color where it is used (COLOR_SOLID, and COLOR_BY_SCALARS
   * without scalars). Changes re-upload the per-glyph colors (16 bytes per
   * glyph while attributes are set). nullptr (default): none.
   */
  void SetCompositeDataDisplayAttributes(vtkCompositeDataDisplayAttributes* attributes);
  vtkCompositeDataDisplayAttributes* GetCompositeDataDisplayAttributes();
  ///@}

  bool HasOpaqueGeometry() override;
  bool HasTranslucentPolygonalGeometry() override;

  ///@{
  /**
   * Occlusion culling (default on; see the class documentation): glyphs are
   * drawn brick by brick in visibility groups (NumberOfCullingGroups), each later group
   * tested against a depth pyramid of what is already drawn, whole glyphs in
   * the geometry stage and single fragments before the ray cast. Exact: the
   * image is the same with culling off. Used for opaque rendering without
   * multisampling; otherwise the glyphs are drawn in one pass.
   */
  vtkSetMacro(Culling, vtkTypeBool);
  vtkGetMacro(Culling, vtkTypeBool);
  vtkBooleanMacro(Culling, vtkTypeBool);
  ///@}

  ///@{
  /**
   * Number of visibility groups of the occlusion culling, clamped to
   * [1, 16]: the bricks of glyphs in front, behind them, ..., and all deeper
   * ones; a depth pyramid is built before each group but the first. Default
   * 12.
   */
  vtkSetClampMacro(NumberOfCullingGroups, int, 1, 16);
  vtkGetMacro(NumberOfCullingGroups, int);
  ///@}

  /**
   * Glyphs in culling group `group` in the last frame (all in group 0 when
   * culling was not used), and the number of depth pyramids built.
   */
  vtkIdType GetLastCullingGroupSize(int group);
  int GetLastNumberOfDepthPyramids();

  ///@{
  /**
   * For tests and benchmarks: count, with an OpenGL query, the sprite
   * triangles that the geometry stage emits (culled glyphs emit none). Off
   * by default (the query waits for the frame).
   */
  vtkSetMacro(CountSprites, bool);
  vtkGetMacro(CountSprites, bool);
  vtkGetMacro(LastSpriteTriangles, vtkIdType);
  ///@}

  ///@{
  /**
   * Statistics of the last data preparation: glyphs uploaded, points left
   * out for NaN/infinite tensors, for zero tensors, and by the mask.
   */
  vtkGetMacro(NumberOfGlyphs, vtkIdType);
  vtkGetMacro(NumberOfInvalidTensors, vtkIdType);
  vtkGetMacro(NumberOfZeroTensors, vtkIdType);
  vtkGetMacro(NumberOfMaskedPoints, vtkIdType);
  ///@}

  /**
   * Number of times the tensors were uploaded to the GPU (for tests and
   * benchmarks: parameter changes must not upload).
   */
  vtkGetMacro(UploadCount, int);

  /**
   * Bytes of GPU buffers per glyph of the last upload (positions, tensors
   * and, when used, scalar colors).
   */
  int GetGPUBytesPerGlyph();

  /**
   * Bounds that the glyphs of `data` (any data set or composite data set)
   * would have with the current settings, without changing the input: the
   * points' bounds padded by the largest glyph any tensor can give (from its
   * Frobenius norm). Returns false when no block has a usable tensor array.
   * (Used by the ParaView representation on the data server.)
   */
  bool ComputeGlyphBounds(vtkDataObject* data, double bounds[6]);

  /**
   * Padding of the points' bounds that contains every glyph whose tensor has
   * at most the given Frobenius norm, with the current scale settings.
   */
  double GetGlyphPadding(double maxTensorNorm);

  /// Maps the glyph index of a selection to the input point id.
  vtkIdType GetInputPointId(vtkIdType glyphIndex);

  void ReleaseGraphicsResources(vtkWindow*) override;

protected:
  vtkSuperquadricGlyphMapper();
  ~vtkSuperquadricGlyphMapper() override;
  void ReportReferences(vtkGarbageCollector* collector) override;

  void ComputeBounds() override;
  void UpdatePreparer();
  std::string GetColorKey();

  void RenderPiece(vtkRenderer* ren, vtkActor* act) override;
  void RenderPieceDraw(vtkRenderer* ren, vtkActor* act) override;
  bool UseCulling(vtkRenderer* ren, vtkActor* act);
  void DrawGlyphs(vtkRenderer* ren, vtkActor* act, int numVerts);

  void GetShaderTemplate(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override;
  void ReplaceShaderValues(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override;
  bool GetNeedToRebuildShaders(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;
  void SetMapperShaderParameters(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;
  void SetCameraShaderParameters(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;
  bool GetNeedToRebuildBufferObjects(vtkRenderer* ren, vtkActor* act) override;
  void BuildBufferObjects(vtkRenderer* ren, vtkActor* act) override;
  void ProcessSelectorPixelBuffers(
    vtkHardwareSelector* sel, std::vector<unsigned int>& pixeloffsets, vtkProp* prop) override;

  char* TensorArray = nullptr;
  int TensorLayout = 1;
  char* MaskArray = nullptr;
  double Gamma = 3.0;
  double MinimumRoundness = 0.2;
  double ScaleFactor = 1.0;
  int ScaleMode = SCALE_BY_EIGENVALUES;
  double MaximumScale = 1.0;
  double MinimumThickness = 0.05;
  double AnisotropyThreshold = 0.0;
  double MinimumEigenvalue = -VTK_DOUBLE_MAX;
  int NegativeEigenvaluePolicy = SKIP_NEGATIVE;
  double ZeroEigenvalueBand = 0.15;
  int GlyphColorMode = COLOR_BY_EIGENVECTOR;
  double PositiveFormColor[3] = { 0.9, 0.45, 0.2 };
  double NegativeFormColor[3] = { 0.2, 0.45, 0.9 };
  int MaximumIterations = 10;
  vtkTypeBool Culling = 1;
  int NumberOfCullingGroups = 12;
  bool CountSprites = false;
  vtkIdType LastSpriteTriangles = 0;

  vtkIdType NumberOfGlyphs = 0;
  vtkIdType NumberOfInvalidTensors = 0;
  vtkIdType NumberOfZeroTensors = 0;
  vtkIdType NumberOfMaskedPoints = 0;
  int UploadCount = 0;

  class Internals;
  std::unique_ptr<Internals> Internal;

private:
  vtkSuperquadricGlyphMapper(const vtkSuperquadricGlyphMapper&) = delete;
  void operator=(const vtkSuperquadricGlyphMapper&) = delete;
};

#endif
