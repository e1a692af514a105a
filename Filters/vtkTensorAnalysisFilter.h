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
 * | `ShapeCoordinates`     | 2     | (u, v) in Schultz and Kindlmann's square      |
 *
 * with S = l1 + l2 + l3 (Teem's trace normalization; 0 when S <= 0). These are
 * the quantities of the superquadric glyphs (Kindlmann 2004, Hlawitschka et
 * al. §2); the math is vtkSplineVizTensorMath. ShapeCoordinates (Schultz and
 * Kindlmann 2010, §4.2; SchultzKindlmannSquare) holds for every sign pattern:
 * (1, 1) and (0, 0) are the positive and negative isotropic tensors, u + v >=
 * 1.5 the positive semi-definite ones, u + v <= 0.5 the negative ones; it
 * separates tension, compression and shear in stress fields.
 *
 * TensorLayout orders 6-component arrays: SYMMETRIC_VTK (default),
 * SYMMETRIC_LOWER (NIfTI, DIPY) or SYMMETRIC_UPPER (FSL, MFEM); 9 components
 * are read as a full matrix (symmetrized), 7 as Teem/NRRD. Outputs are double
 * for double tensors, else float; non-finite tuples give NaN (one warning); a
 * missing or ill-sized array is an error. Composite inputs block by block,
 * pieces pass through; vtkSMPTools with progress and abort.
 */
#ifndef vtkTensorAnalysisFilter_h
#define vtkTensorAnalysisFilter_h

#include "SplineVizFiltersModule.h" // for export macro
#include "vtkDataSetAlgorithm.h"

class SPLINEVIZFILTERS_EXPORT vtkTensorAnalysisFilter : public vtkDataSetAlgorithm
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
