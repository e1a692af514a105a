// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkNIfTIVolumeReader
 * @brief   Reads a scalar or vector volume (a T1, FA, a label map, FSL's V1) from a
 * NIfTI-1/2 file into vtkImageData placed in world RAS+ mm, exactly as vtkNIfTITensorReader
 * places its tensors.
 *
 * The file is read by SplineViz's NIfTI layer (vtkNIfTIFile: NIfTI-1 and -2,
 * either byte order, .nii, .nii.gz and .hdr/.img pairs; every header field
 * validated before use). **Geometry** (vtkNIfTIReaderBase): the affine chosen
 * by AffineSource (sform, else qform, else pixdim), its rotation as the
 * image's direction matrix, the slices reversed when the affine flips: the
 * placement of the tensor reader, so a volume and tensors of the same grid
 * coincide point by point. Field data: "NIfTIAffine", "NIfTISlicesReversed".
 *
 * **Values**: the voxels' own type (uint8 ... uint64, float32, float64) when
 * the file has no scaling, so label volumes stay integers; when it scales
 * (scl_slope finite, not 0, and not slope 1 with intercept 0) value =
 * scl_slope x + scl_inter as float, or double for float64 and 32/64-bit
 * integer voxels. complex64/128 voxels become 2 components (real,
 * imaginary), RGB24 and RGBA32 3 and 4 unsigned char components (never scaled).
 *
 * **Dimensions 4 to 7**: the 5th (NIfTI's vector dimension) always gives
 * components. The 4th (with the rarely used 6th and 7th, flattened) gives
 * components too under FourthDimension AUTOMATIC when the 5th is 1 and it
 * holds at most 4 volumes (e.g. FSL's V1, X x Y x Z x 3), and always under
 * COMPONENTS (e.g. 64 diffusion-weighted volumes as 64 components); otherwise
 * (AUTOMATIC with more volumes, or VOLUMES) VolumeIndex chooses one volume
 * (a time point of fMRI), GetVolumeRange() giving the valid indices.
 * Components are in the file's order (4th dimension fastest); at most 65536.
 *
 * Piece requests: the reader produces the requested sub-extent and reads only
 * its slices (a .nii.gz is decompressed to its end, to check its integrity).
 * Bad input (no file, not NIfTI, a header field out of range, a truncated or
 * damaged file, a VolumeIndex beyond the file's volumes, a missing qform or
 * sform asked for, a singular affine, sizes beyond this machine's memory) is
 * an error (RequestInformation/RequestData return 0) with an empty output;
 * vtkNIfTIFile lists every check.
 */

#ifndef vtkNIfTIVolumeReader_h
#define vtkNIfTIVolumeReader_h

#include "SplineVizIOModule.h" // for export macro
#include "vtkNIfTIReaderBase.h"

#include <memory> // for std::unique_ptr

class SPLINEVIZIO_EXPORT vtkNIfTIVolumeReader : public vtkNIfTIReaderBase
{
public:
  static vtkNIfTIVolumeReader* New();
  vtkTypeMacro(vtkNIfTIVolumeReader, vtkNIfTIReaderBase);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum FourthDimensionModes
  {
    FOURTH_DIMENSION_AUTOMATIC = 0,  ///< components when the 5th is 1 and at most 4 volumes
    FOURTH_DIMENSION_COMPONENTS = 1, ///< every volume a component
    FOURTH_DIMENSION_VOLUMES = 2     ///< one volume, chosen by VolumeIndex
  };
  ///@{
  /// What the 4th dimension (and the 6th and 7th) becomes. Default FOURTH_DIMENSION_AUTOMATIC.
  vtkSetClampMacro(FourthDimension, int, FOURTH_DIMENSION_AUTOMATIC, FOURTH_DIMENSION_VOLUMES);
  vtkGetMacro(FourthDimension, int);
  void SetFourthDimensionToAutomatic() { this->SetFourthDimension(FOURTH_DIMENSION_AUTOMATIC); }
  void SetFourthDimensionToComponents() { this->SetFourthDimension(FOURTH_DIMENSION_COMPONENTS); }
  void SetFourthDimensionToVolumes() { this->SetFourthDimension(FOURTH_DIMENSION_VOLUMES); }
  ///@}

  ///@{
  /// The volume read when the 4th dimension selects volumes. Default 0.
  vtkSetClampMacro(VolumeIndex, int, 0, VTK_INT_MAX);
  vtkGetMacro(VolumeIndex, int);
  ///@}

  /// The valid VolumeIndex values, [0, volumes - 1] ([0, 0] when there is nothing to choose;
  /// after UpdateInformation()).
  vtkGetVector2Macro(VolumeRange, int);

  ///@{
  /// Name of the output point array; empty (the default): the file's name without extension.
  vtkSetStringMacro(ArrayName);
  vtkGetStringMacro(ArrayName);
  ///@}

  /// Does the file start with a NIfTI-1/2 header (the reader reports what is wrong with it)?
  static int CanReadFile(const char* fileName);

protected:
  vtkNIfTIVolumeReader();
  ~vtkNIfTIVolumeReader() override;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestPiece(vtkInformation* outInfo, vtkImageData* output, const int ext[6]) override;

  int FourthDimension = FOURTH_DIMENSION_AUTOMATIC;
  int VolumeIndex = 0;
  int VolumeRange[2] = { 0, 0 };
  char* ArrayName = nullptr;

private:
  vtkNIfTIVolumeReader(const vtkNIfTIVolumeReader&) = delete;
  void operator=(const vtkNIfTIVolumeReader&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
