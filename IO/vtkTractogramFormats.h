// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkTractogramFormats
 * @brief   The MRtrix (.tck, .tsf) and TrackVis (.trk) tractogram formats: headers, byte
 * order, and the TrackVis voxel-mm to RAS+ mm map; shared by vtkTractogramReader and
 * vtkTractogramWriter.
 *
 * Plain C++ (not a vtkObject, not wrapped). What the formats are:
 *
 * - **.tck** (MRtrix3 "Tracks file format"): a text header, first line
 *   `mrtrix tracks`, then `key: value` lines up to `END`; `datatype` gives
 *   the value type and byte order (Float32LE, Float32BE; Float64LE/BE are
 *   accepted too), `file: . OFFSET` where the binary data start. The data are
 *   (x, y, z) triplets in world ("scanner", RAS+ mm) coordinates; a triplet of
 *   NaNs ends each streamline and a triplet of infinities ends the file.
 * - **.tsf** (MRtrix3 "Track scalar file"): the same header with the first
 *   line `mrtrix track scalars`; one value per streamline point, a NaN after
 *   each streamline, an infinity at the end; its `timestamp` matches the
 *   tractogram's.
 * - **.trk** (TrackVis, versions 1 and 2): a 1000-byte binary header (its
 *   last int, hdr_size, is 1000 in the file's byte order, which tells the
 *   order), then per streamline an int32 point count m, m records of
 *   (x, y, z, scalars...) float32 and the streamline's properties (float32).
 *   Points are in "voxel mm" (voxel index times voxel size, with (0, 0, 0) at
 *   the corner of the first voxel); version 2 adds vox_to_ras, the voxel to
 *   RAS+ mm matrix ([3][3] == 0: not recorded, identity assumed, as in
 *   nibabel); voxel_order names the direction of the stored voxel axes (empty:
 *   "LPS", TrackVis's default). Scalar and property names are 20 bytes each;
 *   "name\0N" says that the name covers N values (nibabel's convention).
 */

#ifndef vtkTractogramFormats_h
#define vtkTractogramFormats_h

#include "SplineVizIOModule.h" // for export macro

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

class SPLINEVIZIO_EXPORT vtkTractogramFormats
{
public:
  enum Format
  {
    UNKNOWN = 0,
    TCK = 1,
    TRK = 2
  };

  /// TCK or TRK from the first bytes of the file, else from its extension; UNKNOWN otherwise.
  static int DetectFormat(const std::string& fileName);
  /// TCK (.tck), TRK (.trk) or UNKNOWN, case-insensitive.
  static int FormatFromExtension(const std::string& fileName);

  static bool HostIsLittleEndian();
  /// Reverses the bytes of `count` elements of `size` bytes each, in place.
  static void SwapBytes(void* data, std::size_t size, std::size_t count);

  /// A parsed MRtrix header (.tck or .tsf).
  struct MRtrixHeader
  {
    std::string Magic;
    /// Every key: value line except datatype, file, count (in file order).
    std::vector<std::pair<std::string, std::string>> Fields;
    std::string DataType = "Float32LE";
    bool BigEndian = false;
    int ValueSize = 4; ///< 4 (float32) or 8 (float64)
    std::uint64_t DataOffset = 0;
    long long Count = -1; ///< the "count" field, -1 when absent
    std::string Timestamp;
  };

  /**
   * Reads the header of an MRtrix file whose first line must be `magic`.
   * False with a message on error (no such file, wrong magic, no END, a data
   * type other than Float32/Float64 LE/BE, a missing or multi-file `file`
   * entry, an offset outside the file).
   */
  static bool ReadMRtrixHeader(
    const std::string& fileName, const char* magic, MRtrixHeader& header, std::string& error);

  /**
   * The text of an MRtrix header: `magic`, the fields, count (10 digits, so
   * that it can be rewritten in place), datatype Float32LE, `file: . OFFSET`
   * with the offset of the data that follow it, END.
   */
  static std::string MakeMRtrixHeader(const char* magic,
    const std::vector<std::pair<std::string, std::string>>& fields, long long count);

  enum
  {
    TRK_HEADER_SIZE = 1000,
    TRK_MAX_NAMES = 10,
    TRK_NAME_LENGTH = 20
  };

  /// A parsed TrackVis header (host byte order).
  struct TrkHeader
  {
    short Dimensions[3] = { 1, 1, 1 };
    float VoxelSize[3] = { 1, 1, 1 };
    float Origin[3] = { 0, 0, 0 };
    short NumberOfScalars = 0;
    short NumberOfProperties = 0;
    /// Decoded names with their numbers of values (they cover the first
    /// values; any rest is named "scalars" / "properties", as nibabel does).
    std::vector<std::pair<std::string, int>> Scalars, Properties;
    double VoxelToRAS[4][4] = { { 1, 0, 0, 0 }, { 0, 1, 0, 0 }, { 0, 0, 1, 0 }, { 0, 0, 0, 1 } };
    bool VoxelToRASRecorded = true;
    std::string VoxelOrder = "RAS";
    int NumberOfStreamlines = 0; ///< 0: not recorded (read up to the end)
    int Version = 2;
    bool Swapped = false; ///< the file's byte order is not the host's
  };

  /// Decodes the 1000 header bytes. False with a message (wrong magic, hdr_size, version, counts).
  static bool ParseTrkHeader(const unsigned char* bytes, TrkHeader& header, std::string& error);
  /// Encodes a version-2 little-endian header (the names from Scalars and Properties).
  static bool EncodeTrkHeader(const TrkHeader& header, unsigned char* bytes, std::string& error);

  /**
   * The map from a .trk file's voxel-mm coordinates to RAS+ mm (4x4,
   * row-major), as nibabel applies it: divide by the voxel size, shift by
   * half a voxel to voxel centres, flip / swap axes from voxel_order to the
   * orientation of vox_to_ras, apply vox_to_ras. False when vox_to_ras or the
   * voxel order do not name three distinct axes.
   */
  static bool TrkVoxmmToRAS(const TrkHeader& header, double m[4][4], std::string& error);

  /// The axis codes ("RAS", "LPS", ...) of the columns of a 3x3 (in a 4x4) matrix; "" if
  /// degenerate.
  static std::string AxisCodes(const double m[4][4]);

  /// Inverts a 4x4 affine; false when singular.
  static bool InvertAffine(const double m[4][4], double inverse[4][4]);
};

#endif
