// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkNIfTITensorReader
 * @brief   Reads a diffusion tensor volume from a NIfTI-1/2 file into vtkImageData with point
 * tensors in world RAS+ mm, rotated with the image into the world frame.
 *
 * What DIPY, FSL (`dtifit --save_tensor`) and MRtrix write, for the
 * superquadric glyphs, vtkTensorAnalysisFilter and vtkTensorLineTracer. The
 * file (.nii, .nii.gz, .hdr/.img) is read by vtkNIfTIFile, which checks
 * every header field first. docs/nifti.md has the details.
 *
 * **Components** (TensorLayout): 6 (symmetric) or 9 (full, symmetrized) in
 * the 5th dimension (X x Y x Z x 1 x 6, NIFTI_INTENT_SYMMATRIX, DIPY) or the
 * 4th (X x Y x Z x 6, FSL). AUTOMATIC reads 5D files in the NIfTI order XX XY
 * YY XZ YZ ZZ and 4D files in FSL's XX XY XZ YY YZ ZZ; a wrong layout gives
 * wrong tensors without an error. scl_slope / scl_inter are applied.
 *
 * **Geometry** (vtkNIfTIReaderBase, shared with vtkNIfTIVolumeReader): the affine A chosen by
 * AffineSource (sform, else qform, else pixdim; mm) becomes origin, spacing
 * and the **direction matrix**, slices reversed when det A < 0, so that
 * GetPoint() is where A puts each voxel (no resampling: the tensors keep the
 * values nibabel reads). Sheared affines give a warning.
 *
 * **Frame** (TensorFrame): VOXEL (the file's voxel axes, DIPY), FSL (voxel
 * axes with x flipped when det A > 0) or WORLD (MRtrix). Output tensors are
 * T' = R T R^T, R the orthogonal polar factor of A (FSL: R diag(-1, 1, 1)
 * when det A > 0; WORLD: I), in VTK's order XX YY ZZ XY YZ XZ (float, double
 * for float64 files; NaN where a component is not finite). Field data:
 * "NIfTIAffine", "NIfTISlicesReversed".
 *
 * **Companion volumes** (FA, a mask, a T1, FSL's V1): point arrays named
 * after their files, the first volume with its vector components; copied on
 * the same grid, else resampled in world coordinates (trilinear, nearest
 * voxel for integer data, 0 outside); vectors are not rotated.
 *
 * Pieces read only their slices. Bad input (a header field out of range, a
 * truncated or damaged file, complex or RGB voxels, no 6 or 9 components, a
 * missing transform asked for, a singular affine, sizes beyond this
 * machine's memory, unreadable companions) is an error found in
 * RequestInformation where possible, with an empty output.
 */

#ifndef vtkNIfTITensorReader_h
#define vtkNIfTITensorReader_h

#include "SplineVizIOModule.h" // for export macro
#include "vtkNIfTIReaderBase.h"

#include <memory> // for std::unique_ptr
#include <string> // for std::string

class SPLINEVIZIO_EXPORT vtkNIfTITensorReader : public vtkNIfTIReaderBase
{
public:
  static vtkNIfTITensorReader* New();
  vtkTypeMacro(vtkNIfTITensorReader, vtkNIfTIReaderBase);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum
  {
    /// 5D: SYMMETRIC_NIFTI; 4D: SYMMETRIC_FSL; 9 components: FULL_9.
    LAYOUT_AUTOMATIC = -1
  };
  ///@{
  /**
   * Order of the tensor components in the file: LAYOUT_AUTOMATIC (-1, the
   * default) or a vtkSplineVizTensorMath::TensorLayout: FULL_9 (0),
   * SYMMETRIC_VTK (1), SYMMETRIC_LOWER = SYMMETRIC_NIFTI (2, NIfTI, DIPY),
   * SYMMETRIC_UPPER = SYMMETRIC_FSL (3, FSL dtifit, MFEM).
   */
  vtkSetClampMacro(TensorLayout, int, -1, 4);
  vtkGetMacro(TensorLayout, int);
  void SetTensorLayoutToAutomatic() { this->SetTensorLayout(LAYOUT_AUTOMATIC); }
  void SetTensorLayoutToNIfTI() { this->SetTensorLayout(2); }
  void SetTensorLayoutToFSL() { this->SetTensorLayout(3); }
  void SetTensorLayoutToVTK() { this->SetTensorLayout(1); }
  void SetTensorLayoutToFull9() { this->SetTensorLayout(0); }
  ///@}

  enum TensorFrames
  {
    FRAME_VOXEL = 0, ///< the file's voxel axes (DIPY; FSL when det A < 0)
    FRAME_FSL = 1,   ///< voxel axes, x flipped when det A > 0 (FSL's b-vector convention)
    FRAME_WORLD = 2  ///< already RAS+ world axes (MRtrix)
  };
  ///@{
  /// The frame the tensor components are given in. Default FRAME_VOXEL.
  vtkSetClampMacro(TensorFrame, int, FRAME_VOXEL, FRAME_WORLD);
  vtkGetMacro(TensorFrame, int);
  void SetTensorFrameToVoxel() { this->SetTensorFrame(FRAME_VOXEL); }
  void SetTensorFrameToFSL() { this->SetTensorFrame(FRAME_FSL); }
  void SetTensorFrameToWorld() { this->SetTensorFrame(FRAME_WORLD); }
  ///@}

  ///@{
  /// Name of the output tensor array. Default "Tensors".
  vtkSetStringMacro(TensorArrayName);
  vtkGetStringMacro(TensorArrayName);
  ///@}

  ///@{
  /// Companion volumes (FA, mask, T1, ...) read onto the tensor grid.
  void AddCompanionFileName(const char* fileName);
  void RemoveAllCompanionFileNames();
  int GetNumberOfCompanionFileNames() const;
  const char* GetCompanionFileName(int i) const;
  ///@}

  /// The point array a companion file becomes: its name without .nii / .nii.gz / .img / .hdr.
  static std::string CompanionArrayName(const std::string& fileName);

  /// Is this a valid NIfTI-1/2 file with 6 or 9 tensor components in its 4th or 5th dimension?
  static int CanReadFile(const char* fileName);

protected:
  vtkNIfTITensorReader();
  ~vtkNIfTITensorReader() override;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestPiece(vtkInformation* outInfo, vtkImageData* output, const int ext[6]) override;

  int TensorLayout = LAYOUT_AUTOMATIC;
  int TensorFrame = FRAME_VOXEL;
  char* TensorArrayName = nullptr;

private:
  vtkNIfTITensorReader(const vtkNIfTITensorReader&) = delete;
  void operator=(const vtkNIfTITensorReader&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
