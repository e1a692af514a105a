/**
 * @class   vtkNIfTITensorReader
 * @brief   Reads a diffusion tensor volume from a NIfTI-1/2 file (.nii, .nii.gz) into
 * vtkImageData with point tensors in world RAS+ mm, rotated with the image into the world frame.
 *
 * What DIPY (`TensorModel`, `save_nifti`), FSL (`dtifit --save_tensor`) and
 * other diffusion MRI tools write, read for the superquadric glyphs
 * (vtkSuperquadricGlyphMapper), vtkTensorAnalysisFilter and
 * vtkTensorLineTracer. The file is read by SplineViz's own NIfTI layer
 * (vtkNIfTIFile: NIfTI-1 and -2, either byte order, .nii, .nii.gz and
 * .hdr/.img pairs, every header field validated before it is used).
 *
 * **Components** (TensorLayout, the vtkSplineVizTensorMath layouts): 6
 * components of a symmetric tensor or 9 of a full one (row-major,
 * symmetrized), in the 5th dimension (X x Y x Z x 1 x 6, the NIfTI
 * standard's NIFTI_INTENT_SYMMATRIX layout, as DIPY writes) or in the 4th
 * (X x Y x Z x 6, as FSL writes). AUTOMATIC (the default) reads 5D files in
 * the NIfTI standard's lower-triangular order XX XY YY XZ YZ ZZ
 * (SYMMETRIC_NIFTI, DIPY's) and 4D files in FSL dtifit's upper-triangular
 * order XX XY XZ YY YZ ZZ (SYMMETRIC_FSL, also DIPY's `nifti_tensor=False`);
 * any other layout of 6 components can be chosen (a wrong choice gives
 * wrong tensors without an error: check the file's documentation). Other
 * component counts (e.g. 5) are an error. `scl_slope` / `scl_inter` are
 * applied when the slope is neither 0 nor NaN.
 *
 * **Geometry**: the voxel to world affine A is the sform when sform_code > 0,
 * else the qform (quaternion, qfac) when qform_code > 0, else pixdim scaling
 * (AffineSource chooses; nibabel's and MRtrix's precedence), in mm (the
 * spatial units of xyzt_units, metres or microns, are converted). The output
 * is a vtkImageData whose origin, spacing (the lengths of A's columns) and
 * **direction matrix** (the columns of A divided by them) place every voxel
 * centre exactly where A does, in RAS+ (x right, y anterior, z superior).
 * When det A < 0 (a flip, e.g. the usual LAS storage of FSL-style files) the
 * slices are stored in reverse order (VTK index k' = nz - 1 - k), so that the
 * direction matrix is a rotation (det +1), as VTK's own NIfTI reader does.
 * The direction matrix rather than resampling: resampling would interpolate
 * (blur) the tensors and change every value nibabel, DIPY or FSL would read
 * at a voxel. The SplineViz glyph mapper (point positions from GetPoint()),
 * the tensor line tracer (its image path honours the direction matrix) and
 * ParaView 5.11's Slice filter and Extract Subset (which keeps the matrix)
 * all place such images correctly; a filter that ignores the direction matrix
 * would show the image unrotated. A sheared affine (columns not orthogonal)
 * is kept as a non-orthogonal direction matrix, with a warning.
 *
 * **Tensors in the world frame**: the components refer to a frame given by
 * TensorFrame. VOXEL (default): the voxel axes i, j, k of the file, the frame
 * of FSL-convention b-vectors that DIPY fits in (and FSL when det A < 0);
 * FSL: FSL's b-vector convention, the voxel axes with x flipped when
 * det A > 0 (radiological storage; FSL's dtifit); WORLD: already in RAS+
 * world coordinates (MRtrix's `dwi2tensor`, whose gradients are in scanner
 * space). The output tensors are T' = R T R^T with R the rotation of A (the
 * orthogonal polar factor of its 3x3 part, the "finite strain" rotation for
 * sheared affines; FSL: R diag(-1, 1, 1) when det A > 0; WORLD: R = I), so
 * that glyphs and fibre tracking follow the anatomy. Units of the tensor
 * values are unchanged (DIPY and FSL write mm^2/s).
 *
 * **Output**: point data TensorArrayName ("Tensors", the active tensors) in
 * VTK's 6-component order XX YY ZZ XY YZ XZ (SYMMETRIC_VTK, the default
 * layout of the mappers and filters: no layout to choose downstream; float,
 * or double when the file holds float64); voxels with a NaN or infinite
 * component give NaN tensors (the mappers skip them). Field data:
 * "NIfTIAffine" (A as used, row-major 4x4, from the file's voxel indices),
 * "NIfTISlicesReversed" (1 when k' = nz - 1 - k).
 *
 * **Companion volumes** (AddCompanionFileName(): FA, a brain mask, a T1
 * registered to the diffusion space, FSL's V1): each becomes a point array
 * named after its file (`dti_FA.nii.gz` -> "dti_FA"), its first volume with
 * all its vector components. A companion with the same grid (dimensions and
 * affine within 1e-3 voxel) is copied voxel by voxel; another grid is
 * resampled at the output's points in world coordinates (trilinear for
 * floating-point data, nearest voxel for integer data such as masks; 0
 * outside), so a T1 on its own grid lines up too. Companion vectors are not
 * rotated.
 *
 * Piece requests: the reader produces the requested sub-extent
 * (CAN_PRODUCE_SUB_EXTENT), so ParaView's parallel pipeline splits the
 * volume; each piece reads only its slices (a .nii.gz is decompressed to its
 * end, to check its integrity). Bad input (no file, not NIfTI, a header
 * field out of range, a truncated or damaged file, complex or RGB voxels, a
 * volume without 6 or 9 components, a missing qform/sform asked for, a
 * singular affine, sizes beyond this machine's memory, unreadable
 * companions) is an error (vtkErrorMacro, RequestInformation/RequestData
 * return 0) with an empty output; vtkNIfTIFile lists every check.
 */

#ifndef vtkNIfTITensorReader_h
#define vtkNIfTITensorReader_h

#include "SplineVizModule.h" // for export macro
#include "vtkImageAlgorithm.h"

#include <memory> // for std::unique_ptr
#include <string> // for std::string

class SPLINEVIZ_EXPORT vtkNIfTITensorReader : public vtkImageAlgorithm
{
public:
  static vtkNIfTITensorReader* New();
  vtkTypeMacro(vtkNIfTITensorReader, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The NIfTI file (.nii, .nii.gz, or either file of a .hdr/.img pair).
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

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

  enum AffineSources
  {
    AFFINE_AUTOMATIC = 0, ///< sform if sform_code > 0, else qform if qform_code > 0, else pixdim
    AFFINE_SFORM = 1,
    AFFINE_QFORM = 2,
    AFFINE_PIXDIM = 3 ///< voxel index times pixdim: no rotation, origin 0
  };
  ///@{
  /// Which of the file's transforms places the voxels. Default AFFINE_AUTOMATIC.
  vtkSetClampMacro(AffineSource, int, AFFINE_AUTOMATIC, AFFINE_PIXDIM);
  vtkGetMacro(AffineSource, int);
  void SetAffineSourceToAutomatic() { this->SetAffineSource(AFFINE_AUTOMATIC); }
  void SetAffineSourceToSForm() { this->SetAffineSource(AFFINE_SFORM); }
  void SetAffineSourceToQForm() { this->SetAffineSource(AFFINE_QFORM); }
  void SetAffineSourceToPixDim() { this->SetAffineSource(AFFINE_PIXDIM); }
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

  /// The message of the last error (empty when the last read succeeded).
  const char* GetLastErrorMessage() const { return this->LastError.c_str(); }

  /// The voxel to world affine used by the last read (row-major 4x4, NIfTI voxel indices).
  vtkGetVectorMacro(Affine, double, 16);

protected:
  vtkNIfTITensorReader();
  ~vtkNIfTITensorReader() override;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  char* FileName = nullptr;
  int TensorLayout = LAYOUT_AUTOMATIC;
  int TensorFrame = FRAME_VOXEL;
  int AffineSource = AFFINE_AUTOMATIC;
  char* TensorArrayName = nullptr;
  std::string LastError;
  double Affine[16] = { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 };

private:
  vtkNIfTITensorReader(const vtkNIfTITensorReader&) = delete;
  void operator=(const vtkNIfTITensorReader&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
