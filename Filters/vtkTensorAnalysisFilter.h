// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkTensorAnalysisFilter
 * @brief   Eigenvalues, eigenvectors and anisotropy measures of a symmetric tensor field.
 *
 * For the tensor array selected with SetInputArrayToProcess(0, ...) (point or
 * cell data; by default the active point tensors), adds to the same
 * attribute data, tuple by tuple:
 *
 * | array                  | comps | contents                                      |
 * |------------------------|-------|-----------------------------------------------|
 * | `Eigenvalues`          | 3     | l1 >= l2 >= l3                                |
 * | `Eigenvector1`         | 3     | unit eigenvector of l1 (principal direction)  |
 * | `Eigenvector2`, `Eigenvector3` | 3 | only with ComputeAllEigenvectors on       |
 * | `FractionalAnisotropy` | 1     | FA in [0, 1]                                  |
 * | `MeanDiffusivity`      | 1     | (l1 + l2 + l3) / 3                            |
 * | `LinearAnisotropy`     | 1     | Westin cl = (l1 - l2) / S                     |
 * | `PlanarAnisotropy`     | 1     | Westin cp = 2 (l2 - l3) / S                   |
 * | `SphericalAnisotropy`  | 1     | Westin cs = 3 l3 / S                          |
 * | `Confidence`           | 1     | only for TEEM_7 input: the leading value      |
 * | `ShapeCoordinates`     | 2     | (u, v): the tensor's shape in the square of   |
 * |                        |       | Schultz and Kindlmann, any signs (see below)  |
 *
 * with S = l1 + l2 + l3 (the trace normalization Teem uses; all three are 0
 * when S <= 0, and they lie outside [0, 1] for indefinite tensors). These are
 * the quantities the superquadric glyphs are built from (Kindlmann 2004,
 * Hlawitschka et al. §2), for coloring and thresholding in ParaView; the math
 * is vtkSplineVizTensorMath, shared with vtkSuperquadricGlyphMapper.
 *
 * ShapeCoordinates (vtkSplineVizTensorMath::SchultzKindlmannSquare, the
 * paper's placement, the shared code of the Schultz-Kindlmann glyphs) is
 * defined for every sign pattern, unlike the Westin metrics: with the
 * eigenvalues divided by the largest |l_i|, u = (l2 + 1)/2 and v the position
 * along the smallest (positive-dominant tensors) or largest (negative-dominant
 * ones) eigenvalue; (1, 1) and (0, 0) are the positive and negative
 * isotropic tensors, u + v >= 1.5 the positive semi-definite ones,
 * u + v <= 0.5 the negative ones, (1/2, 1/2) diag(1, 0, -1). Coloring by it
 * (or thresholding u + v) separates tension, compression and shear in stress
 * fields.
 *
 * Component layouts (vtkSplineVizTensorMath::TensorLayout): 9-component
 * arrays are read as full 3x3 matrices (symmetrized) and 7-component arrays
 * as Teem/NRRD (confidence first); for 6-component arrays TensorLayout picks
 * the order: SYMMETRIC_VTK (XX YY ZZ XY YZ XZ, VTK and ParaView, the
 * default), SYMMETRIC_LOWER (XX XY YY XZ YZ ZZ, NIfTI and DIPY) or
 * SYMMETRIC_UPPER (XX XY XZ YY YZ ZZ, FSL dtifit and MFEM).
 *
 * Output arrays are double when the tensors are double, float otherwise.
 * Tuples with a NaN or infinite component give NaN in every output (one
 * warning with their count). A missing tensor array, or one whose number of
 * components does not fit the layout, is an error (RequestData returns 0).
 * Composite inputs are processed block by block; pieces pass through.
 * The work is multi-threaded with vtkSMPTools, in batches between which
 * progress is reported and abort honoured (an aborted run gives an empty
 * output).
 */
#ifndef vtkTensorAnalysisFilter_h
#define vtkTensorAnalysisFilter_h

#include "SplineVizModule.h" // for export macro
#include "vtkDataSetAlgorithm.h"

class SPLINEVIZ_EXPORT vtkTensorAnalysisFilter : public vtkDataSetAlgorithm
{
public:
  static vtkTensorAnalysisFilter* New();
  vtkTypeMacro(vtkTensorAnalysisFilter, vtkDataSetAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Order of the components of 6-component tensor arrays (a
   * vtkSplineVizTensorMath::TensorLayout value: SYMMETRIC_VTK = 1, the
   * default, SYMMETRIC_LOWER = 2, SYMMETRIC_UPPER = 3; FULL_9 = 0 and
   * TEEM_7 = 4 require 9- and 7-component arrays). 9- and 7-component arrays
   * are always read as FULL_9 and TEEM_7.
   */
  vtkSetClampMacro(TensorLayout, int, 0, 4);
  vtkGetMacro(TensorLayout, int);
  ///@}

  ///@{
  /**
   * Also output the medium and minor eigenvectors (Eigenvector2,
   * Eigenvector3). Default off.
   */
  vtkSetMacro(ComputeAllEigenvectors, bool);
  vtkGetMacro(ComputeAllEigenvectors, bool);
  vtkBooleanMacro(ComputeAllEigenvectors, bool);
  ///@}

  /// Number of tuples of the last execution that had a non-finite component.
  vtkGetMacro(NumberOfInvalidTensors, vtkIdType);

protected:
  vtkTensorAnalysisFilter();
  ~vtkTensorAnalysisFilter() override = default;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int TensorLayout = 1;
  bool ComputeAllEigenvectors = false;
  vtkIdType NumberOfInvalidTensors = 0;

private:
  vtkTensorAnalysisFilter(const vtkTensorAnalysisFilter&) = delete;
  void operator=(const vtkTensorAnalysisFilter&) = delete;
};

#endif
