// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkNIfTIFile
 * @brief   NIfTI-1 and NIfTI-2 files read by SplineViz's own code: the header parsed and
 * validated, the voxel to world affine and the image placement, and the voxel values of
 * chosen volumes and slices; shared by vtkNIfTITensorReader and vtkNIfTIVolumeReader.
 *
 * Plain C++ (not a vtkObject, not wrapped). NIfTI-1 (348-byte header) and
 * NIfTI-2 (540 bytes, 64-bit dimensions) in either byte order; single files
 * (magic "n+1" / "n+2") and .hdr/.img pairs ("ni1" / "ni2"), each part
 * optionally gzip-compressed (recognised by its first two bytes). Voxels are
 * stored x fastest, then y, z and the "volumes" of dimensions 4 to 7.
 *
 * Everything the readers use is checked before anything is allocated from
 * it, and a failure is a message, never a crash: the header size and magic
 * (Analyze 7.5 files are refused), the dimensions, the datatype and bitpix,
 * vox_offset, the scaling, that the file (or, compressed, its stream) holds
 * every voxel announced, that the values fit in memory, and the chosen
 * affine (finite, a valid quaternion, non-singular). A gzip part is
 * decompressed to its end whenever voxels are read, so a damaged stream or a
 * wrong checksum is an error. The full list: docs/reliability.md, "NIfTI".
 *
 * Geometry (ComputeAffine, ComputePlacement): the affine maps voxel indices
 * to world RAS+ mm: the sform when sform_code > 0, else the qform (with qfac)
 * when qform_code > 0, else pixdim scaling from the origin (the standard's
 * method 1); metres and microns converted to mm. The image gets origin,
 * spacing and a direction matrix; when det A < 0 the slices are stored in
 * reverse order so that the direction matrix is a rotation.
 *
 * Datatypes: (u)int8 to (u)int64, float32, float64, complex64, complex128 (2
 * values per voxel), RGB24, RGBA32. Not read: binary (1 bit), float128,
 * complex256.
 */

#ifndef vtkNIfTIFile_h
#define vtkNIfTIFile_h

#include "SplineVizIOModule.h" // for export macro

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

class vtkFieldData;
class vtkImageData;
class vtkInformation;

class SPLINEVIZIO_EXPORT vtkNIfTIFile
{
public:
  /// NIfTI datatype codes.
  enum DataTypes
  {
    UINT8 = 2,
    INT16 = 4,
    INT32 = 8,
    FLOAT32 = 16,
    COMPLEX64 = 32,
    FLOAT64 = 64,
    RGB24 = 128,
    INT8 = 256,
    UINT16 = 512,
    UINT32 = 768,
    INT64 = 1024,
    UINT64 = 1280,
    FLOAT128 = 1536,
    COMPLEX128 = 1792,
    COMPLEX256 = 2048,
    RGBA32 = 2304
  };

  /// The affine choices of the readers (their AffineSource property).
  enum AffineSources
  {
    AFFINE_AUTOMATIC = 0, ///< sform if sform_code > 0, else qform if qform_code > 0, else pixdim
    AFFINE_SFORM = 1,
    AFFINE_QFORM = 2,
    AFFINE_PIXDIM = 3
  };

  /// A decoded header, in host byte order, every NIfTI-1 field widened to its NIfTI-2 type.
  struct Header
  {
    int Version = 0;        ///< 1 or 2
    bool Swapped = false;   ///< the file's byte order is not the host's
    bool SingleFile = true; ///< "n+1" / "n+2"; false: "ni1" / "ni2" (a .hdr/.img pair)
    std::int64_t Dim[8] = { 0, 1, 1, 1, 1, 1, 1, 1 }; ///< Dim[i] = 1 for i > Dim[0]
    double PixDim[8] = { 0, 0, 0, 0, 0, 0, 0, 0 };
    int DataType = 0;
    int BitPix = 0;
    std::int64_t VoxOffset = 0;
    double SclSlope = 0.0, SclInter = 0.0;
    int XYZTUnits = 0;
    int IntentCode = 0;
    int QFormCode = 0, SFormCode = 0;
    double Quatern[3] = { 0, 0, 0 };
    double QOffset[3] = { 0, 0, 0 };
    double SRow[3][4] = { { 0, 0, 0, 0 }, { 0, 0, 0, 0 }, { 0, 0, 0, 0 } };
  };

  /**
   * Decodes and validates `size` header bytes (a NIfTI-1 header needs 348,
   * a NIfTI-2 header 540). False with a message when the bytes are not a
   * NIfTI header or a field is unusable (see the class comment).
   */
  static bool ParseHeader(
    const unsigned char* bytes, std::size_t size, Header& header, std::string& error);

  ///@{
  /// Properties of a datatype code (0 / nullptr for codes that are not read).
  static int GetValueSize(int dataType);        ///< bytes per voxel
  static int GetElementsPerVoxel(int dataType); ///< 2 complex, 3 RGB, 4 RGBA, else 1
  static bool IsFloatingPoint(int dataType);    ///< float32/64, complex
  static const char* GetDataTypeName(int dataType);
  ///@}

  /// True when the first bytes of the file (decompressed if gzip) are a NIfTI-1/2 header's.
  static bool LooksLikeNIfTI(const std::string& fileName);

  /// The file's name without its folder and .nii / .nii.gz / .hdr / .img (.gz) extension.
  static std::string BaseName(const std::string& fileName);

  /**
   * Opens `fileName` (.nii, .nii.gz, .hdr, .img, optionally .gz): reads and
   * validates the header, finds the image file of a pair and checks that the
   * voxels the header announces are there. False with a message otherwise.
   */
  bool Open(const std::string& fileName, std::string& error);

  const Header& GetHeader() const { return this->Hdr; }
  /// The file the voxels are in (the .img of a pair).
  const std::string& GetImageFileName() const { return this->ImageFile; }
  /// x, y, z size (i = 0, 1, 2).
  int GetSize(int i) const { return static_cast<int>(this->Hdr.Dim[i + 1]); }
  std::int64_t GetNumberOfVoxels() const;
  /// Volumes of dimensions 4 to 7 (flattened, the 4th fastest).
  std::int64_t GetNumberOfVolumes() const;

  ///@{
  /// scl_slope / scl_inter: applied (value = slope x + inter) when HasScaling().
  bool HasScaling() const;
  double GetSlope() const { return this->HasScaling() ? this->Hdr.SclSlope : 1.0; }
  double GetIntercept() const { return this->HasScaling() ? this->Hdr.SclInter : 0.0; }
  ///@}

  /**
   * The voxel index to world mm affine (row-major 4x4) chosen by `source`
   * (AffineSources). False with a message when that transform is missing,
   * not finite, has a quaternion of norm > 1 or is singular.
   */
  bool ComputeAffine(int source, double affine[4][4], std::string& error) const;

  /// Where the output image goes (see the class comment).
  struct Placement
  {
    double Origin[3] = { 0, 0, 0 };
    double Spacing[3] = { 1, 1, 1 };
    double Direction[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
    bool Flip = false;  ///< output slice k' is the file's slice nz - 1 - k'
    double Shear = 0.0; ///< largest |cosine| between two axes (0 for orthogonal axes)
  };
  static void ComputePlacement(const double affine[4][4], int nz, Placement& placement);

  /// The file's slice of output slice k'.
  static int FileSlice(const Placement& p, int nz, int k) { return p.Flip ? nz - 1 - k : k; }

  ///@{
  /**
   * VTK glue shared by the readers: the output information of a whole image
   * (extent, origin, spacing, direction, sub-extents allowed) or, after an
   * error, of an empty one (no stale data of an earlier read), the update
   * extent clamped to the image (false when empty), the geometry of an
   * output piece and the field data "NIfTIAffine" (16, row-major) and
   * "NIfTISlicesReversed" (0 or 1).
   */
  static void SetOutputInformation(
    vtkInformation* outInfo, const int size[3], const Placement& placement);
  static void SetEmptyOutputInformation(vtkInformation* outInfo);
  static bool ClampExtent(int extent[6], const int size[3]);
  static void SetOutputGeometry(
    vtkImageData* output, const int extent[6], const Placement& placement);
  static void AddFieldData(vtkFieldData* fieldData, const double affine[4][4], bool flip);
  ///@}

  /// Voxel values read by ReadSlices(), in host byte order.
  struct Voxels
  {
    std::vector<unsigned char> Bytes;
    int DataType = 0;
    int Elements = 1;   ///< values per voxel (2 complex, 3 RGB, 4 RGBA)
    int FirstSlice = 0; ///< the file slice of the buffer's first slice
    int Slices = 0;
    std::int64_t SliceVoxels = 0; ///< nx ny
    std::size_t Volumes = 0;

    /// Element `e` of voxel (i, j, file slice k) of the `m`-th volume read, as double.
    double Get(std::size_t m, int i, int j, int k, int e, int nx) const
    {
      const std::int64_t voxel =
        (static_cast<std::int64_t>(m) * this->Slices + (k - this->FirstSlice)) * this->SliceVoxels +
        static_cast<std::int64_t>(j) * nx + i;
      return this->Value(voxel * this->Elements + e);
    }
    /// Element number `index` of the buffer as double.
    double Value(std::int64_t index) const;
  };

  /**
   * Reads the file slices [k0, k1] of the given volumes (indices into the
   * flattened dimensions 4 to 7) into `voxels`: for each volume in the given
   * order, its slices, x fastest. Refuses reads that would not fit in this
   * machine's memory before allocating. A gzip part is decompressed to its
   * end (integrity) unless VerifyData() did that already. Progress (if set) is called with the
   * share done and may return false to abort: ReadSlices then returns false with the error
   * "aborted".
   */
  bool ReadSlices(
    const std::vector<std::int64_t>& volumes, int k0, int k1, Voxels& voxels, std::string& error);

  /**
   * Checks that every voxel the header announces can be read: a gzip part
   * is decompressed to its end (damage, a wrong checksum, a stream shorter
   * than the voxels), once per version of the file (its name, size and
   * modification time; later calls return at once, and ReadSlices() then
   * stops decompressing after the last voxel it needs). An uncompressed file
   * was checked by Open(). Lets a reader find every problem of a file in
   * RequestInformation (where ParaView copes with a failure: an image reader
   * failing in RequestData leaves a ParaView 5.11 client waiting for the
   * server's data forever).
   */
  bool VerifyData(std::string& error);

  /// Called while reading voxels (0..1); return false to abort.
  std::function<bool(double)> Progress;

  /// Where in the uncompressed stream, how much, and where it goes.
  struct Range
  {
    std::uint64_t Offset = 0;
    std::uint64_t Length = 0;
    unsigned char* Target = nullptr;
  };

private:
  bool ReadRanges(const std::string& file, bool compressed, std::vector<Range>& ranges, bool toEnd,
    std::string& error);

  Header Hdr;
  std::string HeaderFile, ImageFile;
  bool ImageCompressed = false;
  std::uint64_t ImageFileSize = 0;
  bool Verified = false;        // VerifyData() passed for the open file
  std::string VerifiedIdentity; // the file version it passed for
};

/**
 * An open file placed as an output image: what the NIfTI readers
 * (vtkNIfTIReaderBase) keep from RequestInformation to RequestData.
 */
struct SPLINEVIZIO_EXPORT vtkNIfTIImage
{
  vtkNIfTIFile File;
  double A[4][4] = { { 1, 0, 0, 0 }, { 0, 1, 0, 0 }, { 0, 0, 1, 0 }, { 0, 0, 0, 1 } };
  int Size[3] = { 0, 0, 0 };
  vtkNIfTIFile::Placement Place;

  /// Size and Place from the open file and A.
  void ComputePlacement();
  /// The file slice of output slice k.
  int FileSlice(int k) const { return vtkNIfTIFile::FileSlice(this->Place, this->Size[2], k); }
  /// The file slices [k0, k1] holding the output extent's slices.
  void FileSlices(const int extent[6], int& k0, int& k1) const;
  /// Reads the given volumes' file slices of the output extent (vtkNIfTIFile::ReadSlices),
  /// calling `progress` meanwhile.
  bool ReadPiece(const std::vector<std::int64_t>& volumes, const int extent[6],
    std::function<bool(double)> progress, vtkNIfTIFile::Voxels& voxels, std::string& error);
};

#endif
// VTK-HeaderTest-Exclude: vtkNIfTIFile.h
