// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkNIfTIReaderBase
 * @brief   What the NIfTI readers share: the file, the choice of its voxel to world
 * transform, the image placement in world RAS+ mm, piece reading and error reporting.
 *
 * An abstract vtkImageAlgorithm; vtkNIfTITensorReader and
 * vtkNIfTIVolumeReader derive from it. The file (.nii, .nii.gz, .hdr/.img)
 * is read by vtkNIfTIFile, which checks every header field first.
 *
 * **Geometry**: the affine A chosen by AffineSource (sform, else qform, else
 * pixdim; mm) becomes the image's origin, spacing and direction matrix, the
 * slices stored in reverse order when det A < 0, so that GetPoint() is where A
 * puts each voxel (no resampling). A sheared affine gives a warning (the
 * direction matrix is then not orthonormal). Every output gets the field data
 * "NIfTIAffine" (A, 16 values, row-major) and "NIfTISlicesReversed" (0 or 1).
 *
 * **Pieces**: the readers produce the requested sub-extent, reading only its
 * slices. **Errors**: a failure empties the output (and its whole extent),
 * is reported with vtkErrorMacro and kept for GetLastErrorMessage().
 */

#ifndef vtkNIfTIReaderBase_h
#define vtkNIfTIReaderBase_h

#include "SplineVizIOModule.h" // for export macro
#include "vtkImageAlgorithm.h"

#include <functional> // for std::function
#include <memory>     // for std::unique_ptr
#include <string>     // for std::string

struct vtkNIfTIImage;

class SPLINEVIZIO_EXPORT vtkNIfTIReaderBase : public vtkImageAlgorithm
{
public:
  vtkTypeMacro(vtkNIfTIReaderBase, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The NIfTI file (.nii, .nii.gz, or either file of a .hdr/.img pair).
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
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

  /// The message of the last error (empty when the last read succeeded).
  const char* GetLastErrorMessage() const { return this->LastError.c_str(); }

  /// The voxel to world affine used by the last read (row-major 4x4, NIfTI voxel indices).
  vtkGetVectorMacro(Affine, double, 16);

protected:
  vtkNIfTIReaderBase();
  ~vtkNIfTIReaderBase() override;

  ///@{
  /**
   * Steps of a subclass's RequestInformation. OpenFile clears the last
   * error and opens FileName; ComputeAffine computes the affine chosen by
   * AffineSource; both return false after Fail(). PlaceImage places the
   * image (warning about shear), publishes Affine and sets the output
   * information of the whole image.
   */
  bool OpenFile(vtkInformation* outInfo);
  bool ComputeAffine(vtkInformation* outInfo);
  void PlaceImage(vtkInformation* outInfo);
  ///@}

  /**
   * Empties the output, then (unless RequestInformation failed) has
   * RequestPiece() produce the update extent clamped to the image (an
   * update extent outside the image: an empty output).
   */
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  /// Produces the piece `extent` (within the image, not empty) of the (empty) output.
  virtual int RequestPiece(vtkInformation* outInfo, vtkImageData* output, const int extent[6]) = 0;

  ///@{
  /**
   * Steps of a subclass's RequestPiece. ReadProgress is the progress
   * callback of a read that takes the share [0, share] of the work and
   * stops when the user aborts. FailRead reports a failed read (an abort:
   * an empty output, 1; an error: Fail()). FinishPiece gives the output its
   * geometry and field data.
   */
  std::function<bool(double)> ReadProgress(double share);
  int FailRead(vtkInformation* outInfo, const std::string& error);
  void FinishPiece(vtkImageData* output, const int extent[6]);
  ///@}

  /// Reports an error: an empty output of an empty whole extent, the message kept and
  /// reported with vtkErrorMacro. Returns 0 (for RequestInformation / RequestData to return).
  int Fail(vtkInformation* outInfo, const std::string& message);

  char* FileName = nullptr;
  int AffineSource = AFFINE_AUTOMATIC;
  std::string LastError;
  double Affine[16] = { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 };
  std::unique_ptr<vtkNIfTIImage> Image; // the open file and its placement

private:
  vtkNIfTIReaderBase(const vtkNIfTIReaderBase&) = delete;
  void operator=(const vtkNIfTIReaderBase&) = delete;
};

#endif
