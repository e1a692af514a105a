// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkTractogramReader
 * @brief   Reads tractograms (fibre tracts) in MRtrix .tck (with .tsf per-point scalars) and
 * TrackVis .trk format as vtkPolyData polylines in world RAS+ millimetres.
 *
 * One polyline per streamline (formats: vtkTractogramFormats) in world RAS+ mm,
 * where vtkNIfTITensorReader puts the image they were tracked in.
 * - **.tck**: points as stored (float32, either byte order; float64 read as
 *   double); the header's `key: value` lines as field data "MRtrixHeader".
 *   Companion **.tsf** files (AddScalarFileName()) become 1-component point
 *   arrays named after the file (`tracks_FA.tsf` next to `tracks.tck` -> "FA").
 * - **.trk** (versions 1 and 2, either byte order): points mapped from voxel mm
 *   to RAS+ mm as nibabel does (vtkTractogramFormats::TrkVoxmmToRAS); per-point
 *   scalars become point arrays, per-streamline properties cell arrays; the
 *   geometry is kept as "TrackVis..." field data.
 * Empty streamlines are dropped unless KeepEmptyStreamlines is on.
 *
 * **Pieces**: a piece reads only its share of the file. A .tck piece owns the
 * streamlines whose first point lies in its n-th of the triplets and reads
 * from the triplet before its range to the NaN that ends its last streamline
 * (the same for each .tsf); a .tck whose end marker is not its last triplet
 * is read whole. A .trk piece gets streamlines [N p / n, N (p + 1) / n),
 * skipping the records before it by their point counts. GetLastBytesRead()
 * tells how many data bytes a read took.
 *
 * **Subsets** at read time (like `tckedit -number`), the same streamlines for
 * any number of pieces: SubsetMode STRIDE keeps every SubsetStride-th
 * streamline; RANDOM_FRACTION keeps a streamline when a hash of SubsetSeed and
 * its key (its index in a .trk, its first triplet's in a .tck) is below
 * SubsetFraction.
 *
 * Reads go in 16 MiB chunks in parallel (vtkSMPTools) with progress and
 * abort. Bad input (wrong magic, a missing or misplaced end marker, damaged
 * triplets, .trk counts past the end of the file, a .tsf that does not match,
 * NaN points) fails RequestData with an error and an empty output; nothing is
 * allocated from a count before the file is known to hold it.
 */

#ifndef vtkTractogramReader_h
#define vtkTractogramReader_h

#include "SplineVizIOModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

#include <cstdint> // for std::uint64_t
#include <memory>  // for std::unique_ptr
#include <string>  // for std::string
#include <vector>  // for std::vector

class SPLINEVIZIO_EXPORT vtkTractogramReader : public vtkPolyDataAlgorithm
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

  enum SubsetModes
  {
    SUBSET_ALL = 0,            ///< every streamline
    SUBSET_STRIDE = 1,         ///< the streamlines 0, k, 2k, ... of the file (k = SubsetStride)
    SUBSET_RANDOM_FRACTION = 2 ///< a seeded random choice of about SubsetFraction of them
  };
  ///@{
  /// Which streamlines to read (like `tckedit -number`); the same set for any
  /// number of pieces. Default SUBSET_ALL.
  vtkSetClampMacro(SubsetMode, int, SUBSET_ALL, SUBSET_RANDOM_FRACTION);
  vtkGetMacro(SubsetMode, int);
  void SetSubsetModeToAll() { this->SetSubsetMode(SUBSET_ALL); }
  void SetSubsetModeToStride() { this->SetSubsetMode(SUBSET_STRIDE); }
  void SetSubsetModeToRandomFraction() { this->SetSubsetMode(SUBSET_RANDOM_FRACTION); }
  ///@}

  ///@{
  /// SUBSET_STRIDE keeps the streamlines whose index in the file is a multiple of this. Default 10.
  vtkSetClampMacro(SubsetStride, int, 1, VTK_INT_MAX);
  vtkGetMacro(SubsetStride, int);
  ///@}

  ///@{
  /// SUBSET_RANDOM_FRACTION keeps each streamline with this probability. Default 0.1.
  vtkSetClampMacro(SubsetFraction, double, 0.0, 1.0);
  vtkGetMacro(SubsetFraction, double);
  ///@}

  ///@{
  /// The seed of SUBSET_RANDOM_FRACTION (the same seed, the same streamlines). Default 0.
  vtkSetMacro(SubsetSeed, int);
  vtkGetMacro(SubsetSeed, int);
  ///@}

  /// Number of streamlines in the file (all pieces, empty ones included) after the last read;
  /// for a piece of a .tck file, the header's count (-1 if it has none).
  vtkGetMacro(NumberOfStreamlinesInFile, vtkIdType);

  /// The bytes of streamline data (headers excluded) the last read took from its files.
  vtkGetMacro(LastBytesRead, vtkTypeInt64);

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
  bool ProbeMRtrixEnd(const std::string& fileName, std::uint64_t offset, std::uint64_t dataBytes,
    int valueSize, bool swap, int tupleSize, std::uint64_t& end);
  bool ScanMRtrixRange(const std::string& fileName, std::uint64_t offset, int valueSize, bool swap,
    int tupleSize, std::uint64_t from, std::uint64_t to, bool stopAtFirst, std::uint64_t& found,
    double progressBegin, double progressEnd, std::string& error);
  bool ReadTCKPiece(const std::string& fileName, std::uint64_t offset, std::uint64_t end,
    Streamlines& lines, std::string& error);
  bool ReadTCKWhole(const std::string& fileName, std::uint64_t offset, std::uint64_t dataBytes,
    Streamlines& lines, std::string& error);
  void KeepPieceOfWhole(Streamlines& lines);
  bool ReadTSF(const std::string& name, const std::string& tckHeaderTimestamp, bool piece,
    Streamlines& lines, double progressBegin, double progressEnd, std::string& error);
  void AddTrkFieldData(Streamlines& lines);
  std::vector<vtkIdType> SelectStreamlines(const Streamlines& lines) const;
  // The output's float arrays of point or cell values, and their raw
  // pointers for the conversion loops.
  struct ValueArrays;
  // Streamline s of `lines` into the output from point o (cell i): false when
  // a .trk point is not finite, in the file or in RAS+.
  static void ConvertTCK(const Streamlines& lines, std::size_t s, vtkIdType o, float* pf,
    double* pd, const ValueArrays& point);
  static bool ConvertTRK(const Streamlines& lines, std::size_t s, vtkIdType o, vtkIdType i,
    float* pf, const ValueArrays& point, const ValueArrays& cell);

  char* FileName = nullptr;
  int FileFormat = AUTOMATIC;
  vtkTypeBool KeepEmptyStreamlines = 0;
  int SubsetMode = SUBSET_ALL;
  int SubsetStride = 10;
  double SubsetFraction = 0.1;
  int SubsetSeed = 0;
  vtkIdType NumberOfStreamlinesInFile = 0;
  vtkTypeInt64 LastBytesRead = 0;
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
