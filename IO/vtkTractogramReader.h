/**
 * @class   vtkTractogramReader
 * @brief   Reads tractograms (fibre tracts) in MRtrix .tck (with .tsf per-point scalars) and
 * TrackVis .trk format as vtkPolyData polylines in world RAS+ millimetres.
 *
 * The two file formats diffusion MRI tractography writes (MRtrix3
 * `tckgen`, DIPY, TrackVis / Diffusion Toolkit, nibabel): see
 * vtkTractogramFormats for what they contain. The output is one polyline per
 * streamline, its points in world ("scanner") coordinates, RAS+ (x to the
 * subject's right, y anterior, z superior), in mm, the point (0, 0, 0) of a
 * voxel grid at the centre of voxel (0, 0, 0) (nibabel's and MRtrix's
 * convention), so the lines lie where vtkNIfTITensorReader puts the image
 * they were tracked in; the tube mappers, the Superquadric Glyphs and every
 * VTK filter take them directly.
 *
 * - **.tck**: points as stored (float32, little- or big-endian as the header's
 *   `datatype` says; Float64 is accepted too and read as double). The
 *   header's `key: value` lines are kept as field data "MRtrixHeader"
 *   (a vtkStringArray of "key: value"), so that vtkTractogramWriter can write
 *   them back. Companion **.tsf** files (AddScalarFileName()) become
 *   1-component point arrays named after the file: `fibres.tsf` -> "fibres",
 *   and `tracks_FA.tsf` or `tracks.FA.tsf` next to `tracks.tck` -> "FA"; their
 *   streamlines must have the same numbers of points as the tractogram's
 *   (else an error), a differing `timestamp` gives a warning.
 * - **.trk** (versions 1 and 2, either byte order): points mapped from
 *   TrackVis "voxel mm" to RAS+ mm exactly as nibabel does
 *   (vtkTractogramFormats::TrkVoxmmToRAS; version 1 and an unrecorded
 *   vox_to_ras are taken as the identity, an empty voxel order as "LPS");
 *   the per-point scalars become point arrays and the per-streamline
 *   properties cell arrays, named as in the header ("name\0N" names an
 *   N-component array; values no name covers are "scalars" / "properties").
 *   The geometry is kept as field data "TrackVisVoxelToRAS" (16, row-major),
 *   "TrackVisVoxelSize", "TrackVisDimensions" and "TrackVisVoxelOrder" for
 *   the writer. Points are float32 (as stored), mapped in double precision.
 *
 * Empty streamlines (no points) are dropped unless KeepEmptyStreamlines is on
 * (then they are polylines without points, so that cell i is streamline i of
 * the file); nibabel drops them from .tck files too.
 *
 * Large files are read in chunks of 16 MiB with progress reports and parsed
 * in parallel (vtkSMPTools: the separators of a .tck are found by chunk, the
 * points of all streamlines converted and copied in parallel batches); the
 * reader honours AbortExecute between chunks and batches. Piece requests are
 * honoured: piece p of n gets the streamlines [p N / n, (p + 1) N / n) of the
 * N in the file.
 *
 * Bad input gives an error (vtkErrorMacro, RequestData returns 0) and an
 * empty output, never a partly filled one: no such file, wrong magic, no
 * END, an unsupported data type or multi-file .tck, a .tck without its
 * `inf inf inf` end marker or cut inside a triplet, triplets mixing NaN or
 * infinite values with numbers, a .trk whose header (hdr_size, version,
 * counts, voxel sizes, vox_to_ras) is invalid, whose streamlines run past the
 * end of the file or are fewer than n_count says, a negative point count,
 * NaN or infinite coordinates, a .tsf that does not match its tractogram.
 * Nothing is allocated from a count before the file is known to hold it.
 */

#ifndef vtkTractogramReader_h
#define vtkTractogramReader_h

#include "SplineVizModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

#include <memory> // for std::unique_ptr
#include <string> // for std::string

class SPLINEVIZ_EXPORT vtkTractogramReader : public vtkPolyDataAlgorithm
{
public:
  static vtkTractogramReader* New();
  vtkTypeMacro(vtkTractogramReader, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The file to read (.tck or .trk).
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  enum FileFormats
  {
    AUTOMATIC = 0, ///< from the first bytes ("mrtrix tracks", "TRACK"), else the extension
    TCK = 1,
    TRK = 2
  };
  ///@{
  /// The format of the file. Default AUTOMATIC.
  vtkSetClampMacro(FileFormat, int, AUTOMATIC, TRK);
  vtkGetMacro(FileFormat, int);
  void SetFileFormatToAutomatic() { this->SetFileFormat(AUTOMATIC); }
  void SetFileFormatToTCK() { this->SetFileFormat(TCK); }
  void SetFileFormatToTRK() { this->SetFileFormat(TRK); }
  ///@}

  ///@{
  /// MRtrix .tsf files of per-point scalars of a .tck tractogram (ignored for .trk).
  void AddScalarFileName(const char* fileName);
  void RemoveAllScalarFileNames();
  int GetNumberOfScalarFileNames() const;
  const char* GetScalarFileName(int i) const;
  ///@}

  ///@{
  /// Keep streamlines without points (as empty polylines). Default off.
  vtkSetMacro(KeepEmptyStreamlines, vtkTypeBool);
  vtkGetMacro(KeepEmptyStreamlines, vtkTypeBool);
  vtkBooleanMacro(KeepEmptyStreamlines, vtkTypeBool);
  ///@}

  /// Number of streamlines in the file (all pieces, empty ones included) after the last read.
  vtkGetMacro(NumberOfStreamlinesInFile, vtkIdType);

  /// Can this reader read the file (an MRtrix tracks or TrackVis header)?
  static int CanReadFile(const char* fileName);

  /// The message of the last error (empty when the last read succeeded).
  const char* GetLastErrorMessage() const { return this->LastError.c_str(); }

  /// The name of the point array a .tsf file becomes (see the class documentation).
  static std::string ScalarArrayName(
    const std::string& tsfFileName, const std::string& tckFileName);

protected:
  vtkTractogramReader();
  ~vtkTractogramReader() override;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  struct Streamlines;
  struct DataBuffer;
  bool ReadTCK(Streamlines& lines, std::string& error);
  bool ReadTRK(Streamlines& lines, std::string& error);
  bool ReadChunked(const std::string& fileName, unsigned long long offset, unsigned long long size,
    DataBuffer& buffer, double progressBegin, double progressEnd, std::string& error);

  char* FileName = nullptr;
  int FileFormat = AUTOMATIC;
  vtkTypeBool KeepEmptyStreamlines = 0;
  vtkIdType NumberOfStreamlinesInFile = 0;
  std::string LastError;
  int Piece = 0;
  int NumberOfPieces = 1;

private:
  vtkTractogramReader(const vtkTractogramReader&) = delete;
  void operator=(const vtkTractogramReader&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
