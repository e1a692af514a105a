// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkSuperquadricGlyphPreparer
 * @brief   CPU data preparation of vtkSuperquadricGlyphMapper (internal).
 *
 * Turns any vtkDataSet, or the leaves of a composite data set, into one
 * compact vtkPolyData of glyph points (no cells) holding exactly what the
 * glyph shaders need (Hlawitschka et al.: only the raw tensors are uploaded):
 *
 * - points: float positions of the points whose tensor is drawable;
 * - point data `sqTensorDiag` (xx, yy, zz) and `sqTensorOff` (xy, yz, xz),
 *   float, read from the tensor array in its layout (vtkSplineVizTensorMath);
 * - point data `sqPointIds` (vtkIdType): the input point id of each glyph
 *   (for composite inputs the index in the concatenation of the leaves);
 * - when a color array is selected (SetColorArraySelection), that point
 *   array's kept tuples, as the active scalars;
 * - field data `sqStatistics` = (largest tensor Frobenius norm, NaN/inf
 *   tensors, zero tensors, masked points);
 * - the glyphs are sorted by the bricks of a uniform grid over their
 *   positions (about 8 glyphs per brick, at most 2^18 bricks): field data
 *   `sqBrickGrid` = (origin, spacing, dimensions) and `sqBrickOffsets`
 *   (vtkIdType, bricks + 1: the first glyph of every brick), for the
 *   mapper's occlusion culling.
 *
 * Points with a NaN/infinite or zero tensor, or a zero mask value, are left
 * out (one warning with the counts). A missing or mis-sized tensor array is
 * an error for its block. Multi-threaded with vtkSMPTools. Internal to
 * vtkSuperquadricGlyphMapper (not wrapped).
 */
#ifndef vtkSuperquadricGlyphPreparer_h
#define vtkSuperquadricGlyphPreparer_h

#include "SplineVizRenderingModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

#include <string> // for std::string

class vtkDataArray;
class vtkDataSet;

class SPLINEVIZRENDERING_EXPORT vtkSuperquadricGlyphPreparer : public vtkPolyDataAlgorithm
{
public:
  static vtkSuperquadricGlyphPreparer* New();
  vtkTypeMacro(vtkSuperquadricGlyphPreparer, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Tensor array (empty: active point tensors) and layout.
  void SetTensorArray(const char* name);
  vtkSetMacro(TensorLayout, int);
  vtkGetMacro(TensorLayout, int);

  /// Mask array (empty: none).
  void SetMaskArray(const char* name);

  /**
   * The point array to carry for coloring, selected as vtkMapper does
   * (vtkAbstractMapper::GetAbstractScalars); visible = false: none.
   */
  void SetColorArraySelection(
    bool visible, int scalarMode, int accessMode, int arrayId, const char* arrayName);

protected:
  vtkSuperquadricGlyphPreparer() = default;
  ~vtkSuperquadricGlyphPreparer() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  std::string TensorArray;
  int TensorLayout = 1;
  std::string MaskArray;
  bool ColorVisible = false;
  int ColorScalarMode = 0;
  int ColorAccessMode = 0;
  int ColorArrayId = -1;
  std::string ColorArrayName;

private:
  vtkSuperquadricGlyphPreparer(const vtkSuperquadricGlyphPreparer&) = delete;
  void operator=(const vtkSuperquadricGlyphPreparer&) = delete;

  /**
   * A leaf's point arrays: the tensors (TensorArray or the active ones)
   * and their layout, the mask (MaskArray) and the coloring scalars
   * (point scalars only); false after an error (`where` names the block).
   */
  bool FindLeafArrays(vtkDataSet* leaf, const std::string& where, vtkDataArray*& tensors,
    int& layout, vtkDataArray*& mask, vtkDataArray*& scalars);
};

#endif
