// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkTractogramWriter
 * @brief   Writes polylines (fibre tracts, e.g. from vtkTensorLineTracer) as an MRtrix .tck
 * tractogram (with .tsf per-point scalars) or a TrackVis .trk file.
 *
 * The input's lines (VTK_LINE and VTK_POLY_LINE cells of a vtkPolyData, or of
 * every polydata leaf of a composite data set, in order) are written as
 * streamlines, their points taken as world RAS+ millimetres (what
 * vtkTractogramReader and vtkNIfTITensorReader use; see
 * vtkTractogramFormats for the formats). Other cells are ignored with a
 * warning.
 *
 * - **.tck**: Float32LE triplets, a NaN triplet after each streamline, the
 *   `inf inf inf` end marker; the header has `count`, `datatype`, `file`, a
 *   `timestamp` and the "key: value" lines of the input's "MRtrixHeader"
 *   field data (as vtkTractogramReader keeps them), except those four. Each
 *   point array named by AddPointArrayName() (1 component) is written as a
 *   companion track scalar file `<name without .tck>.<array>.tsf` with the
 *   same timestamp (vtkTractogramReader names that array back).
 * - **.trk** (version 2, little-endian): points mapped from RAS+ mm to
 *   TrackVis voxel mm with the inverse of the map nibabel reads them with;
 *   the named point arrays become per-point scalars, the named cell arrays
 *   (AddCellArrayName()) per-streamline properties (at most 10 each, names
 *   of at most 20 bytes with the component count). The geometry (vox_to_ras,
 *   voxel size, dimensions, voxel order = the axis codes of vox_to_ras) is
 *   the input's "TrackVisVoxelToRAS", "TrackVisVoxelSize" and
 *   "TrackVisDimensions" field data when present and
 *   UseInputTrackVisGeometry is on (so a .trk read and written keeps its
 *   header), else VoxelToRAS, VoxelSize and Dimensions (default: identity,
 *   1 mm, 1 x 1 x 1, nibabel's defaults); SetGeometryFromImage() takes them
 *   from an image (e.g. the vtkNIfTITensorReader output the lines were
 *   traced in).
 *
 * Bad input is an error (vtkErrorMacro, the file is removed, GetErrorCode()
 * is set): no file name, an unknown extension without FileFormat, NaN or
 * infinite coordinates (a .tck cannot store them), a missing named array or
 * one with the wrong number of components, more than 10 named arrays or a
 * name too long for a .trk, a singular vox_to_ras, more than 2^31 - 1
 * streamlines or points per streamline for a .trk.
 */

#ifndef vtkTractogramWriter_h
#define vtkTractogramWriter_h

#include "SplineVizIOModule.h" // for export macro
#include "vtkWriter.h"

#include <memory> // for std::unique_ptr
#include <string> // for std::string

class vtkImageData;
class vtkPolyData;

class SPLINEVIZIO_EXPORT vtkTractogramWriter : public vtkWriter
{
public:
  static vtkTractogramWriter* New();
  vtkTypeMacro(vtkTractogramWriter, vtkWriter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The file to write (.tck or .trk).
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  enum FileFormats
  {
    AUTOMATIC = 0, ///< from the extension
    TCK = 1,
    TRK = 2
  };
  ///@{
  /// The format to write. Default AUTOMATIC (from the file name's extension).
  vtkSetClampMacro(FileFormat, int, AUTOMATIC, TRK);
  vtkGetMacro(FileFormat, int);
  void SetFileFormatToAutomatic() { this->SetFileFormat(AUTOMATIC); }
  void SetFileFormatToTCK() { this->SetFileFormat(TCK); }
  void SetFileFormatToTRK() { this->SetFileFormat(TRK); }
  ///@}

  ///@{
  /// Point arrays to write: .tsf files next to a .tck, per-point scalars of a .trk.
  void AddPointArrayName(const char* name);
  void RemoveAllPointArrayNames();
  int GetNumberOfPointArrayNames() const;
  const char* GetPointArrayName(int i) const;
  ///@}

  ///@{
  /// Cell arrays to write as per-streamline properties of a .trk (ignored for .tck).
  void AddCellArrayName(const char* name);
  void RemoveAllCellArrayNames();
  int GetNumberOfCellArrayNames() const;
  const char* GetCellArrayName(int i) const;
  ///@}

  ///@{
  /// .trk geometry: voxel to RAS+ mm matrix (row-major 4x4), voxel size, dimensions.
  vtkSetVectorMacro(VoxelToRAS, double, 16);
  vtkGetVectorMacro(VoxelToRAS, double, 16);
  vtkSetVector3Macro(VoxelSize, double);
  vtkGetVector3Macro(VoxelSize, double);
  vtkSetVector3Macro(Dimensions, int);
  vtkGetVector3Macro(Dimensions, int);
  ///@}

  /**
   * Sets VoxelToRAS, VoxelSize and Dimensions from an image (origin, spacing,
   * direction matrix, dimensions) and turns UseInputTrackVisGeometry off.
   */
  void SetGeometryFromImage(vtkImageData* image);

  ///@{
  /// Use the input's TrackVis geometry field data when it has it. Default on.
  vtkSetMacro(UseInputTrackVisGeometry, vtkTypeBool);
  vtkGetMacro(UseInputTrackVisGeometry, vtkTypeBool);
  vtkBooleanMacro(UseInputTrackVisGeometry, vtkTypeBool);
  ///@}

  /// The .tsf file a point array is written to next to a .tck file.
  static std::string ScalarFileName(const std::string& tckFileName, const std::string& arrayName);

  /// The message of the last error (empty when the last write succeeded).
  const char* GetLastErrorMessage() const { return this->LastError.c_str(); }

protected:
  vtkTractogramWriter();
  ~vtkTractogramWriter() override;

  void WriteData() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;

  struct Lines;
  bool WriteTCK(const Lines& lines, std::string& error);
  bool WriteTRK(const Lines& lines, std::string& error);

  char* FileName = nullptr;
  int FileFormat = AUTOMATIC;
  double VoxelToRAS[16] = { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 };
  double VoxelSize[3] = { 1, 1, 1 };
  int Dimensions[3] = { 1, 1, 1 };
  vtkTypeBool UseInputTrackVisGeometry = 1;
  std::string LastError;

private:
  vtkTractogramWriter(const vtkTractogramWriter&) = delete;
  void operator=(const vtkTractogramWriter&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
