// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNIfTIFile.h"

#include "vtkSplineVizProgress.h"

#include "vtkAlgorithm.h"
#include "vtkByteSwap.h"
#include "vtkDoubleArray.h"
#include "vtkEndian.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtk_zlib.h"

#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
#include <memory>
#include <new>

namespace
{
constexpr std::size_t NIfTI1HeaderSize = 348;
constexpr std::size_t NIfTI2HeaderSize = 540;
constexpr std::uint64_t ChunkBytes = 16ull << 20; // between progress reports
// deflate cannot expand its input by more than about 1032:1 (RFC 1951: a
// 258-byte match costs at least 2 bits); plus gzip header slack.
constexpr std::uint64_t MaxDeflateRatio = 1032;
constexpr std::uint64_t DeflateSlack = 1 << 16;

#ifdef VTK_WORDS_BIGENDIAN
constexpr bool HostLittleEndian = false;
#else
constexpr bool HostLittleEndian = true;
#endif

// A number as "%g" prints it (1e+30, 352, nan), for messages.
std::string Number(double v)
{
  char text[32];
  std::snprintf(text, sizeof(text), "%g", v);
  return text;
}

std::string Lower(std::string s)
{
  std::transform(s.begin(), s.end(), s.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

bool EndsWith(const std::string& lowerName, const char* ext)
{
  const std::size_t n = std::strlen(ext);
  return lowerName.size() > n && lowerName.compare(lowerName.size() - n, n, ext) == 0;
}

bool FileExists(const std::string& name)
{
  std::ifstream in(name, std::ios::in | std::ios::binary);
  return static_cast<bool>(in);
}

std::uint64_t FileSize(const std::string& name)
{
  std::ifstream in(name, std::ios::in | std::ios::binary | std::ios::ate);
  const std::streamoff s = in ? static_cast<std::streamoff>(in.tellg()) : std::streamoff(-1);
  return s < 0 ? 0ull : static_cast<std::uint64_t>(s);
}

bool IsGzip(const std::string& name)
{
  std::ifstream in(name, std::ios::in | std::ios::binary);
  unsigned char b[2] = { 0, 0 };
  in.read(reinterpret_cast<char*>(b), 2);
  return in.gcount() == 2 && b[0] == 0x1f && b[1] == 0x8b;
}

// `name` with its .hdr / .img (optionally .gz) extension replaced by `to`
// ("hdr" or "img", in the case of the original), the first variant (with or
// without .gz) that exists; empty when none does.
std::string Partner(const std::string& name, const char* from, const char* to)
{
  const std::string lower = Lower(name);
  std::size_t stem = std::string::npos;
  const std::string dotFrom = std::string(".") + from;
  if (EndsWith(lower, (dotFrom + ".gz").c_str()))
  {
    stem = name.size() - 7;
  }
  else if (EndsWith(lower, dotFrom.c_str()))
  {
    stem = name.size() - 4;
  }
  std::string base;
  bool upper = false;
  if (stem != std::string::npos)
  {
    base = name.substr(0, stem);
    upper = std::isupper(static_cast<unsigned char>(name[stem + 1])) != 0;
  }
  else
  {
    // not a .hdr / .img name (e.g. a .nii with the pair magic): the stem
    base = name;
    for (const char* ext : { ".nii.gz", ".nii" })
    {
      if (EndsWith(lower, ext))
      {
        base = name.substr(0, name.size() - std::strlen(ext));
        break;
      }
    }
  }
  std::string ext = std::string(".") + to;
  if (upper)
  {
    std::transform(ext.begin(), ext.end(), ext.begin(),
      [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  }
  const bool gz = EndsWith(lower, ".gz");
  const std::string first = base + ext + (gz ? (upper ? ".GZ" : ".gz") : "");
  const std::string second = base + ext + (gz ? "" : (upper ? ".GZ" : ".gz"));
  if (FileExists(first))
  {
    return first;
  }
  return FileExists(second) ? second : std::string();
}

// Fields of a header in the file's byte order.
struct FieldReader
{
  const unsigned char* Bytes;
  bool Swap;
  template <typename T>
  T Get(std::size_t offset) const
  {
    T v;
    std::memcpy(&v, this->Bytes + offset, sizeof(T));
    if (this->Swap && sizeof(T) > 1)
    {
      vtkByteSwap::SwapVoidRange(&v, 1, sizeof(T));
    }
    return v;
  }
};

std::int32_t Swapped32(std::int32_t v)
{
  vtkByteSwap::SwapVoidRange(&v, 1, 4);
  return v;
}

// gzip decompression of a file, read forwards (several members allowed).
class GzipReader
{
public:
  GzipReader() = default;
  ~GzipReader()
  {
    if (this->Initialized)
    {
      inflateEnd(&this->Stream);
    }
  }
  GzipReader(const GzipReader&) = delete;
  GzipReader& operator=(const GzipReader&) = delete;

  bool Open(const std::string& name, std::string& error)
  {
    this->In.open(name, std::ios::in | std::ios::binary);
    if (!this->In)
    {
      error = "cannot open it (it does not exist or is not readable)";
      return false;
    }
    std::memset(&this->Stream, 0, sizeof(this->Stream));
    if (inflateInit2(&this->Stream, 15 + 16) != Z_OK) // gzip only
    {
      error = "cannot initialise zlib";
      return false;
    }
    this->Initialized = true;
    return true;
  }

  /// Decompresses the next `n` bytes to `target` (nullptr: discarded). The
  /// number produced (fewer at the end of the stream); false with a message
  /// when the stream is damaged or cut short.
  bool Read(unsigned char* target, std::uint64_t n, std::uint64_t& produced, std::string& error)
  {
    produced = 0;
    while (produced < n && !this->End)
    {
      if (this->Stream.avail_in == 0 && !this->Refill())
      {
        error = "the gzip stream is cut short (a truncated .gz file)";
        return false;
      }
      const std::uint64_t want = n - produced;
      const std::uint64_t room = target ? std::min<std::uint64_t>(want, 1u << 30)
                                        : std::min<std::uint64_t>(want, BufferSize);
      this->Stream.next_out = target ? target + produced : this->Scratch;
      this->Stream.avail_out = static_cast<uInt>(room);
      const int status = inflate(&this->Stream, Z_NO_FLUSH);
      produced += room - this->Stream.avail_out;
      this->Position += room - this->Stream.avail_out;
      if (status == Z_STREAM_END)
      {
        if (!this->NextMember())
        {
          this->End = true;
        }
      }
      else if (status == Z_BUF_ERROR)
      {
        if (this->Stream.avail_in == 0 && !this->Refill())
        {
          error = "the gzip stream is cut short (a truncated .gz file)";
          return false;
        }
      }
      else if (status != Z_OK)
      {
        error = std::string("the gzip stream is damaged (") +
          (this->Stream.msg ? this->Stream.msg : "zlib error " + std::to_string(status)) + ")";
        return false;
      }
    }
    return true;
  }

  bool AtEnd() const { return this->End; }
  std::uint64_t GetPosition() const { return this->Position; }

private:
  // More compressed input; false at the end of the file.
  bool Refill()
  {
    if (this->FileEnd)
    {
      return false;
    }
    const std::size_t keep = this->Stream.avail_in;
    if (keep > 0)
    {
      std::memmove(this->Input, this->Stream.next_in, keep);
    }
    this->In.read(
      reinterpret_cast<char*>(this->Input + keep), static_cast<std::streamsize>(BufferSize - keep));
    const std::size_t got = static_cast<std::size_t>(this->In.gcount());
    if (got == 0)
    {
      this->FileEnd = true;
    }
    this->Stream.next_in = this->Input;
    this->Stream.avail_in = static_cast<uInt>(keep + got);
    return got > 0;
  }

  // After a member's end: another member follows (true, zlib reset), or not
  // (anything else after the stream is ignored, as by gzip -d's padding rule).
  bool NextMember()
  {
    while (this->Stream.avail_in < 2 && this->Refill())
    {
    }
    if (this->Stream.avail_in >= 2 && this->Stream.next_in[0] == 0x1f &&
      this->Stream.next_in[1] == 0x8b)
    {
      inflateReset(&this->Stream);
      return true;
    }
    return false;
  }

  std::ifstream In;
  z_stream Stream;
  bool Initialized = false;
  bool FileEnd = false;
  bool End = false;
  std::uint64_t Position = 0;
  static constexpr std::size_t BufferSize = 1 << 16;
  std::vector<unsigned char> InputBuffer = std::vector<unsigned char>(BufferSize);
  std::vector<unsigned char> ScratchBuffer = std::vector<unsigned char>(BufferSize);
  unsigned char* Input = InputBuffer.data();
  unsigned char* Scratch = ScratchBuffer.data();
};

// Up to `n` first bytes of a file (decompressed when gzip) into `out`.
bool ReadPrefix(
  const std::string& name, std::size_t n, std::vector<unsigned char>& out, std::string& error)
{
  out.assign(n, 0);
  if (IsGzip(name))
  {
    GzipReader gz;
    std::uint64_t got = 0;
    if (!gz.Open(name, error))
    {
      return false;
    }
    std::string readError;
    const bool ok = gz.Read(out.data(), n, got, readError);
    out.resize(static_cast<std::size_t>(got));
    if (!ok && got < NIfTI1HeaderSize)
    {
      error = readError;
      return false;
    }
    return true;
  }
  std::ifstream in(name, std::ios::in | std::ios::binary);
  if (!in)
  {
    error = "cannot open it (it does not exist or is not readable)";
    return false;
  }
  in.read(reinterpret_cast<char*>(out.data()), static_cast<std::streamsize>(n));
  out.resize(static_cast<std::size_t>(in.gcount()));
  return true;
}

// The file the header is in: name.hdr(.gz) for name.img(.gz), else the name itself.
std::string HeaderFileOf(const std::string& name)
{
  const std::string lower = Lower(name);
  if (EndsWith(lower, ".img") || EndsWith(lower, ".img.gz"))
  {
    return Partner(name, "img", "hdr");
  }
  return name;
}

// Decodes the fields of a NIfTI-1 header (sizeof_hdr 348).
bool DecodeNIfTI1(
  const unsigned char* bytes, const FieldReader& f, vtkNIfTIFile::Header& h, std::string& error)
{
  const unsigned char* m = bytes + 344;
  if (!(m[0] == 'n' && (m[1] == '+' || m[1] == 'i') && m[2] == '1' && m[3] == '\0'))
  {
    error = "no NIfTI-1 magic (\"n+1\" or \"ni1\"): an Analyze 7.5 header or a damaged "
            "NIfTI-1 header, not read";
    return false;
  }
  h.Version = 1;
  h.SingleFile = m[1] == '+';
  for (int i = 0; i < 8; ++i)
  {
    h.Dim[i] = f.Get<std::int16_t>(40 + 2 * i);
    h.PixDim[i] = f.Get<float>(76 + 4 * i);
  }
  h.IntentCode = f.Get<std::int16_t>(68);
  h.DataType = f.Get<std::int16_t>(70);
  h.BitPix = f.Get<std::int16_t>(72);
  const double offset = f.Get<float>(108);
  if (!(offset >= 0.0 && offset <= 9007199254740992.0 && std::floor(offset) == offset))
  {
    error = "vox_offset (" + Number(offset) + ") is not a whole number of bytes >= 0";
    return false;
  }
  h.VoxOffset = static_cast<std::int64_t>(offset);
  h.SclSlope = f.Get<float>(112);
  h.SclInter = f.Get<float>(116);
  h.XYZTUnits = bytes[123];
  h.QFormCode = f.Get<std::int16_t>(252);
  h.SFormCode = f.Get<std::int16_t>(254);
  for (int i = 0; i < 3; ++i)
  {
    h.Quatern[i] = f.Get<float>(256 + 4 * i);
    h.QOffset[i] = f.Get<float>(268 + 4 * i);
    for (int j = 0; j < 4; ++j)
    {
      h.SRow[i][j] = f.Get<float>(280 + 16 * i + 4 * j);
    }
  }
  return true;
}

// Decodes the fields of a NIfTI-2 header (sizeof_hdr 540).
bool DecodeNIfTI2(const unsigned char* bytes, std::size_t size, const FieldReader& f,
  vtkNIfTIFile::Header& h, std::string& error)
{
  if (size < NIfTI2HeaderSize)
  {
    error = "a NIfTI-2 header cut short (" + std::to_string(size) + " of 540 bytes)";
    return false;
  }
  const unsigned char* m = bytes + 4;
  if (!(m[0] == 'n' && (m[1] == '+' || m[1] == 'i') && m[2] == '2' && m[3] == '\0'))
  {
    error = "no NIfTI-2 magic (\"n+2\" or \"ni2\")";
    return false;
  }
  if (!(m[4] == '\r' && m[5] == '\n' && m[6] == '\032' && m[7] == '\n'))
  {
    error = "the NIfTI-2 magic is damaged (the file went through a text-mode "
            "newline conversion)";
    return false;
  }
  h.Version = 2;
  h.SingleFile = m[1] == '+';
  h.DataType = f.Get<std::int16_t>(12);
  h.BitPix = f.Get<std::int16_t>(14);
  for (int i = 0; i < 8; ++i)
  {
    h.Dim[i] = f.Get<std::int64_t>(16 + 8 * i);
    h.PixDim[i] = f.Get<double>(104 + 8 * i);
  }
  h.VoxOffset = f.Get<std::int64_t>(168);
  if (h.VoxOffset < 0)
  {
    error = "vox_offset (" + std::to_string(h.VoxOffset) + ") is negative";
    return false;
  }
  h.SclSlope = f.Get<double>(176);
  h.SclInter = f.Get<double>(184);
  h.QFormCode = f.Get<std::int32_t>(344);
  h.SFormCode = f.Get<std::int32_t>(348);
  for (int i = 0; i < 3; ++i)
  {
    h.Quatern[i] = f.Get<double>(352 + 8 * i);
    h.QOffset[i] = f.Get<double>(376 + 8 * i);
    for (int j = 0; j < 4; ++j)
    {
      h.SRow[i][j] = f.Get<double>(400 + 32 * i + 8 * j);
    }
  }
  h.XYZTUnits = f.Get<std::int32_t>(500);
  h.IntentCode = f.Get<std::int32_t>(504);
  return true;
}

// Checks the decoded fields every reader relies on (see the class comment).
bool CheckFields(vtkNIfTIFile::Header& h, std::string& error)
{
  // Dimensions: dim[0] of them, each at least 1; x, y, z within int extents.
  if (h.Dim[0] < 1 || h.Dim[0] > 7)
  {
    error = "dim[0] (the number of dimensions) is " + std::to_string(h.Dim[0]) + ", not 1 to 7";
    return false;
  }
  for (int i = 1; i < 8; ++i)
  {
    if (i > h.Dim[0])
    {
      h.Dim[i] = 1;
    }
    else if (h.Dim[i] < 1)
    {
      error = "dim[" + std::to_string(i) + "] is " + std::to_string(h.Dim[i]) +
        (h.Dim[i] == 0 ? " (an empty image)" : "");
      return false;
    }
    else if (i <= 3 && h.Dim[i] > std::numeric_limits<std::int32_t>::max())
    {
      error = "dim[" + std::to_string(i) + "] is " + std::to_string(h.Dim[i]) +
        ", more than VTK's image extents can hold";
      return false;
    }
  }

  // The datatype, its size, and the product of the dimensions in bytes.
  const int valueSize = vtkNIfTIFile::GetValueSize(h.DataType);
  if (valueSize == 0)
  {
    const char* name = vtkNIfTIFile::GetDataTypeName(h.DataType);
    error = name ? std::string("voxels of datatype ") + name + " (" + std::to_string(h.DataType) +
        ") are not read"
                 : "unknown datatype code " + std::to_string(h.DataType);
    return false;
  }
  if (h.BitPix != 8 * valueSize)
  {
    error = "bitpix (" + std::to_string(h.BitPix) + ") does not match datatype " +
      vtkNIfTIFile::GetDataTypeName(h.DataType) + " (" + std::to_string(8 * valueSize) +
      " bits per voxel)";
    return false;
  }
  const std::uint64_t limit = (std::uint64_t(1) << 62) / static_cast<std::uint64_t>(valueSize);
  std::uint64_t count = 1;
  for (int i = 1; i < 8; ++i)
  {
    const std::uint64_t d = static_cast<std::uint64_t>(h.Dim[i]);
    if (count > limit / d)
    {
      error = "the dimensions announce more than 2^62 bytes of voxels";
      return false;
    }
    count *= d;
  }
  const std::int64_t headerSize = h.Version == 1 ? 348 : 540;
  if (h.SingleFile && h.VoxOffset < headerSize)
  {
    error = "vox_offset (" + std::to_string(h.VoxOffset) + ") lies inside the " +
      std::to_string(headerSize) + "-byte header";
    return false;
  }
  if (h.VoxOffset > (std::int64_t(1) << 62))
  {
    error = "vox_offset (" + std::to_string(h.VoxOffset) + ") is beyond any file";
    return false;
  }
  if (std::isfinite(h.SclSlope) && h.SclSlope != 0.0 && !std::isfinite(h.SclInter))
  {
    error = "scl_slope is " + Number(h.SclSlope) + " but scl_inter is not finite";
    return false;
  }
  return true;
}

template <typename T>
double Element(const unsigned char* bytes, std::int64_t index)
{
  T v;
  std::memcpy(&v, bytes + static_cast<std::size_t>(index) * sizeof(T), sizeof(T));
  return static_cast<double>(v);
}
}

//------------------------------------------------------------------------------
int vtkNIfTIFile::GetValueSize(int dataType)
{
  switch (dataType)
  {
    case UINT8:
    case INT8:
      return 1;
    case INT16:
    case UINT16:
      return 2;
    case RGB24:
      return 3;
    case INT32:
    case UINT32:
    case FLOAT32:
    case RGBA32:
      return 4;
    case INT64:
    case UINT64:
    case FLOAT64:
    case COMPLEX64:
      return 8;
    case COMPLEX128:
      return 16;
    default:
      return 0;
  }
}

int vtkNIfTIFile::GetElementsPerVoxel(int dataType)
{
  switch (dataType)
  {
    case COMPLEX64:
    case COMPLEX128:
      return 2;
    case RGB24:
      return 3;
    case RGBA32:
      return 4;
    default:
      return 1;
  }
}

bool vtkNIfTIFile::IsFloatingPoint(int dataType)
{
  return dataType == FLOAT32 || dataType == FLOAT64 || dataType == COMPLEX64 ||
    dataType == COMPLEX128;
}

const char* vtkNIfTIFile::GetDataTypeName(int dataType)
{
  switch (dataType)
  {
    case 1:
      return "binary";
    case UINT8:
      return "uint8";
    case INT16:
      return "int16";
    case INT32:
      return "int32";
    case FLOAT32:
      return "float32";
    case COMPLEX64:
      return "complex64";
    case FLOAT64:
      return "float64";
    case RGB24:
      return "RGB24";
    case INT8:
      return "int8";
    case UINT16:
      return "uint16";
    case UINT32:
      return "uint32";
    case INT64:
      return "int64";
    case UINT64:
      return "uint64";
    case FLOAT128:
      return "float128";
    case COMPLEX128:
      return "complex128";
    case COMPLEX256:
      return "complex256";
    case RGBA32:
      return "RGBA32";
    default:
      return nullptr;
  }
}

//------------------------------------------------------------------------------
bool vtkNIfTIFile::ParseHeader(
  const unsigned char* bytes, std::size_t size, Header& h, std::string& error)
{
  h = Header();
  if (size < NIfTI1HeaderSize)
  {
    error = "not a NIfTI file: " + std::to_string(size) +
      " bytes, shorter than a NIfTI-1 header (348 bytes)";
    return false;
  }
  std::int32_t sizeofHdr;
  std::memcpy(&sizeofHdr, bytes, 4);
  if (sizeofHdr == 348 || sizeofHdr == 540)
  {
    h.Swapped = false;
  }
  else if (Swapped32(sizeofHdr) == 348 || Swapped32(sizeofHdr) == 540)
  {
    h.Swapped = true;
    sizeofHdr = Swapped32(sizeofHdr);
  }
  else
  {
    error = "not a NIfTI file (sizeof_hdr is " + std::to_string(sizeofHdr) + ", not 348 or 540)";
    return false;
  }
  const FieldReader f{ bytes, h.Swapped };
  if (!(sizeofHdr == 348 ? DecodeNIfTI1(bytes, f, h, error)
                         : DecodeNIfTI2(bytes, size, f, h, error)))
  {
    return false;
  }
  return CheckFields(h, error);
}

//------------------------------------------------------------------------------
bool vtkNIfTIFile::LooksLikeNIfTI(const std::string& fileName)
{
  const std::string header = HeaderFileOf(fileName);
  if (header.empty())
  {
    return false;
  }
  std::vector<unsigned char> bytes;
  std::string error;
  if (!ReadPrefix(header, NIfTI2HeaderSize, bytes, error) || bytes.size() < NIfTI1HeaderSize)
  {
    return false;
  }
  std::int32_t s;
  std::memcpy(&s, bytes.data(), 4);
  if (s != 348 && s != 540)
  {
    s = Swapped32(s);
  }
  const unsigned char* m = s == 348 ? bytes.data() + 344 : bytes.data() + 4;
  return (s == 348 || (s == 540 && bytes.size() >= NIfTI2HeaderSize)) && m[0] == 'n' &&
    (m[1] == '+' || m[1] == 'i') && m[2] == (s == 348 ? '1' : '2') && m[3] == '\0';
}

std::string vtkNIfTIFile::BaseName(const std::string& fileName)
{
  const auto slash = fileName.find_last_of("/\\");
  const std::string name = slash == std::string::npos ? fileName : fileName.substr(slash + 1);
  const std::string lower = Lower(name);
  for (const char* ext : { ".nii.gz", ".nii", ".img.gz", ".img", ".hdr.gz", ".hdr" })
  {
    if (EndsWith(lower, ext))
    {
      return name.substr(0, name.size() - std::strlen(ext));
    }
  }
  return name;
}

//------------------------------------------------------------------------------
bool vtkNIfTIFile::Open(const std::string& fileName, std::string& error)
{
  this->Hdr = Header();
  this->Verified = false;
  this->HeaderFile = HeaderFileOf(fileName);
  this->ImageFile.clear();
  if (this->HeaderFile.empty())
  {
    error = "\"" + fileName + "\": its header file (.hdr) is missing";
    return false;
  }
  std::vector<unsigned char> bytes;
  if (!ReadPrefix(this->HeaderFile, NIfTI2HeaderSize, bytes, error))
  {
    error = "\"" + fileName + "\": " + error;
    return false;
  }
  if (!ParseHeader(bytes.data(), bytes.size(), this->Hdr, error))
  {
    error = "\"" + fileName + "\": " + error;
    return false;
  }
  const Header& h = this->Hdr;
  if (h.SingleFile)
  {
    this->ImageFile = this->HeaderFile;
  }
  else
  {
    const std::string lower = Lower(fileName);
    this->ImageFile = (EndsWith(lower, ".img") || EndsWith(lower, ".img.gz"))
      ? fileName
      : Partner(this->HeaderFile, "hdr", "img");
    if (this->ImageFile.empty())
    {
      error = "\"" + fileName + "\": the header is of a .hdr/.img pair, but its .img file " +
        "is missing";
      return false;
    }
  }
  // The voxels the header announces must be in the file.
  this->ImageCompressed = IsGzip(this->ImageFile);
  this->ImageFileSize = FileSize(this->ImageFile);
  const std::uint64_t needed = static_cast<std::uint64_t>(h.VoxOffset) +
    static_cast<std::uint64_t>(this->GetNumberOfVoxels()) *
      static_cast<std::uint64_t>(this->GetNumberOfVolumes()) *
      static_cast<std::uint64_t>(GetValueSize(h.DataType));
  if (!this->ImageCompressed && needed > this->ImageFileSize)
  {
    error = "\"" + fileName + "\" is truncated: its header announces voxels up to byte " +
      std::to_string(needed) + ", the file has " + std::to_string(this->ImageFileSize) + " bytes";
    return false;
  }
  const std::uint64_t most = this->ImageFileSize >
      (std::numeric_limits<std::uint64_t>::max() - DeflateSlack) / MaxDeflateRatio
    ? std::numeric_limits<std::uint64_t>::max()
    : this->ImageFileSize * MaxDeflateRatio + DeflateSlack;
  if (this->ImageCompressed && needed > most)
  {
    error = "\"" + fileName +
      "\" cannot hold the voxels its header announces: " + std::to_string(needed) +
      " bytes, but a gzip file of " + std::to_string(this->ImageFileSize) +
      " bytes decompresses to at most about " + std::to_string(most) +
      " (a truncated file or a damaged header)";
    return false;
  }
  return true;
}

bool vtkNIfTIFile::VerifyData(std::string& error)
{
  if (!this->ImageCompressed)
  {
    this->Verified = true; // Open() compared the file's size with the header
    return true;
  }
  const std::string identity = this->ImageFile + "\n" + std::to_string(this->ImageFileSize) + "\n" +
    std::to_string(vtksys::SystemTools::ModifiedTime(this->ImageFile));
  if (identity == this->VerifiedIdentity)
  {
    this->Verified = true;
    return true;
  }
  const std::uint64_t needed = static_cast<std::uint64_t>(this->Hdr.VoxOffset) +
    static_cast<std::uint64_t>(this->GetNumberOfVoxels()) *
      static_cast<std::uint64_t>(this->GetNumberOfVolumes()) *
      static_cast<std::uint64_t>(GetValueSize(this->Hdr.DataType));
  GzipReader gz;
  if (!gz.Open(this->ImageFile, error))
  {
    error = "\"" + this->ImageFile + "\": " + error;
    return false;
  }
  while (!gz.AtEnd())
  {
    std::uint64_t produced = 0;
    if (!gz.Read(nullptr, ChunkBytes, produced, error))
    {
      error = "\"" + this->ImageFile + "\": " + error;
      return false;
    }
  }
  if (gz.GetPosition() < needed)
  {
    error = "\"" + this->ImageFile + "\" is truncated: it decompresses to " +
      std::to_string(gz.GetPosition()) + " bytes, its header announces voxels up to byte " +
      std::to_string(needed);
    return false;
  }
  this->VerifiedIdentity = identity;
  this->Verified = true;
  return true;
}

std::int64_t vtkNIfTIFile::GetNumberOfVoxels() const
{
  return this->Hdr.Dim[1] * this->Hdr.Dim[2] * this->Hdr.Dim[3];
}

std::int64_t vtkNIfTIFile::GetNumberOfVolumes() const
{
  return this->Hdr.Dim[4] * this->Hdr.Dim[5] * this->Hdr.Dim[6] * this->Hdr.Dim[7];
}

bool vtkNIfTIFile::HasScaling() const
{
  const double s = this->Hdr.SclSlope;
  return std::isfinite(s) && s != 0.0 && !(s == 1.0 && this->Hdr.SclInter == 0.0) &&
    GetElementsPerVoxel(this->Hdr.DataType) <= 2; // never for RGB(A)
}

//------------------------------------------------------------------------------
bool vtkNIfTIFile::ComputeAffine(int source, double a[4][4], std::string& error) const
{
  const Header& h = this->Hdr;
  int use = source;
  if (use == AFFINE_AUTOMATIC)
  {
    use = h.SFormCode > 0 ? AFFINE_SFORM : (h.QFormCode > 0 ? AFFINE_QFORM : AFFINE_PIXDIM);
  }
  for (int i = 0; i < 4; ++i)
  {
    for (int j = 0; j < 4; ++j)
    {
      a[i][j] = i == j && i == 3 ? 1.0 : 0.0;
    }
  }
  if (use == AFFINE_SFORM)
  {
    if (h.SFormCode <= 0)
    {
      error = "it has no sform (sform_code " + std::to_string(h.SFormCode) + ")";
      return false;
    }
    for (int i = 0; i < 3; ++i)
    {
      for (int j = 0; j < 4; ++j)
      {
        a[i][j] = h.SRow[i][j];
      }
    }
  }
  else if (use == AFFINE_QFORM)
  {
    if (h.QFormCode <= 0)
    {
      error = "it has no qform (qform_code " + std::to_string(h.QFormCode) + ")";
      return false;
    }
    const double b = h.Quatern[0], c = h.Quatern[1], d = h.Quatern[2];
    const double norm2 = b * b + c * c + d * d;
    if (!std::isfinite(norm2) || norm2 > 1.0 + 1e-6)
    {
      error = "the qform quaternion (quatern_b, _c, _d) is not finite or longer than 1";
      return false;
    }
    const double aa = std::sqrt(std::max(0.0, 1.0 - norm2));
    const double r[3][3] = { { aa * aa + b * b - c * c - d * d, 2 * (b * c - aa * d),
                               2 * (b * d + aa * c) },
      { 2 * (b * c + aa * d), aa * aa + c * c - b * b - d * d, 2 * (c * d - aa * b) },
      { 2 * (b * d - aa * c), 2 * (c * d + aa * b), aa * aa + d * d - c * c - b * b } };
    const double qfac = h.PixDim[0] < 0 ? -1.0 : 1.0;
    const double s[3] = { h.PixDim[1], h.PixDim[2], qfac * h.PixDim[3] };
    for (int i = 0; i < 3; ++i)
    {
      for (int j = 0; j < 3; ++j)
      {
        a[i][j] = r[i][j] * s[j];
      }
      a[i][3] = h.QOffset[i];
    }
  }
  else
  {
    for (int i = 0; i < 3; ++i)
    {
      const double p = std::abs(h.PixDim[i + 1]);
      a[i][i] = p > 0 ? p : 1.0; // NaN and 0: 1
    }
  }
  const int units = h.XYZTUnits & 0x07;
  const double toMM = units == 1 ? 1000.0 : (units == 3 ? 1e-3 : 1.0);
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 4; ++j)
    {
      a[i][j] *= toMM;
      if (!std::isfinite(a[i][j]))
      {
        error = "the voxel to world transform has a non-finite value";
        return false;
      }
    }
  }
  // Singular, or so nearly that its inverse is meaningless.
  double norms = 1.0;
  for (int j = 0; j < 3; ++j)
  {
    norms *= std::sqrt(a[0][j] * a[0][j] + a[1][j] * a[1][j] + a[2][j] * a[2][j]);
  }
  const double det = a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
    a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
    a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
  if (!(norms > 0.0) || !std::isfinite(norms) || !std::isfinite(det) ||
    !(std::abs(det) > 1e-9 * norms))
  {
    error = "the voxel to world transform is singular (or nearly so)";
    return false;
  }
  return true;
}

void vtkNIfTIFile::ComputePlacement(const double affine[4][4], int nz, Placement& p)
{
  double a[4][4];
  std::memcpy(a, affine, sizeof(a));
  const double det = a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
    a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
    a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
  p.Flip = det < 0;
  if (p.Flip)
  {
    for (int i = 0; i < 3; ++i)
    {
      a[i][3] += a[i][2] * (nz - 1);
      a[i][2] = -a[i][2];
    }
  }
  for (int j = 0; j < 3; ++j)
  {
    const double s = std::sqrt(a[0][j] * a[0][j] + a[1][j] * a[1][j] + a[2][j] * a[2][j]);
    p.Spacing[j] = s;
    for (int i = 0; i < 3; ++i)
    {
      p.Direction[3 * i + j] = a[i][j] / s;
    }
  }
  for (int i = 0; i < 3; ++i)
  {
    p.Origin[i] = a[i][3];
  }
  p.Shear = 0.0;
  for (int u = 0; u < 3; ++u)
  {
    for (int v = u + 1; v < 3; ++v)
    {
      double dot = 0.0;
      for (int i = 0; i < 3; ++i)
      {
        dot += p.Direction[3 * i + u] * p.Direction[3 * i + v];
      }
      p.Shear = std::max(p.Shear, std::abs(dot));
    }
  }
}

//------------------------------------------------------------------------------
void vtkNIfTIFile::SetOutputInformation(
  vtkInformation* outInfo, const int size[3], const Placement& p)
{
  const int whole[6] = { 0, size[0] - 1, 0, size[1] - 1, 0, size[2] - 1 };
  outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), whole, 6);
  outInfo->Set(vtkDataObject::ORIGIN(), p.Origin, 3);
  outInfo->Set(vtkDataObject::SPACING(), p.Spacing, 3);
  outInfo->Set(vtkDataObject::DIRECTION(), p.Direction, 9);
  outInfo->Set(vtkAlgorithm::CAN_PRODUCE_SUB_EXTENT(), 1);
}

void vtkNIfTIFile::SetEmptyOutputInformation(vtkInformation* outInfo)
{
  if (vtkDataObject* output = outInfo->Get(vtkDataObject::DATA_OBJECT()))
  {
    output->Initialize();
  }
  const int empty[6] = { 0, -1, 0, -1, 0, -1 };
  outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), empty, 6);
}

bool vtkNIfTIFile::ClampExtent(int e[6], const int size[3])
{
  for (int i = 0; i < 3; ++i)
  {
    e[2 * i] = std::max(e[2 * i], 0);
    e[2 * i + 1] = std::min(e[2 * i + 1], size[i] - 1);
    if (e[2 * i] > e[2 * i + 1])
    {
      return false;
    }
  }
  return true;
}

void vtkNIfTIFile::SetOutputGeometry(vtkImageData* output, const int extent[6], const Placement& p)
{
  output->SetExtent(const_cast<int*>(extent));
  output->SetOrigin(p.Origin);
  output->SetSpacing(p.Spacing);
  output->SetDirectionMatrix(p.Direction);
}

void vtkNIfTIFile::AddFieldData(vtkFieldData* fieldData, const double a[4][4], bool flip)
{
  vtkNew<vtkDoubleArray> affine;
  affine->SetName("NIfTIAffine");
  affine->SetNumberOfComponents(16);
  affine->SetNumberOfTuples(1);
  affine->SetTuple(0, &a[0][0]);
  fieldData->AddArray(affine);
  vtkNew<vtkIntArray> reversed;
  reversed->SetName("NIfTISlicesReversed");
  reversed->InsertNextValue(flip ? 1 : 0);
  fieldData->AddArray(reversed);
}

//------------------------------------------------------------------------------
void vtkNIfTIImage::ComputePlacement()
{
  for (int i = 0; i < 3; ++i)
  {
    this->Size[i] = this->File.GetSize(i);
  }
  vtkNIfTIFile::ComputePlacement(this->A, this->Size[2], this->Place);
}

void vtkNIfTIImage::FileSlices(const int extent[6], int& k0, int& k1) const
{
  k0 = std::min(this->FileSlice(extent[4]), this->FileSlice(extent[5]));
  k1 = std::max(this->FileSlice(extent[4]), this->FileSlice(extent[5]));
}

bool vtkNIfTIImage::ReadPiece(const std::vector<std::int64_t>& volumes, const int extent[6],
  std::function<bool(double)> progress, vtkNIfTIFile::Voxels& voxels, std::string& error)
{
  int k0, k1;
  this->FileSlices(extent, k0, k1);
  this->File.Progress = std::move(progress);
  const bool read = this->File.ReadSlices(volumes, k0, k1, voxels, error);
  this->File.Progress = nullptr;
  return read;
}

//------------------------------------------------------------------------------
double vtkNIfTIFile::Voxels::Value(std::int64_t index) const
{
  const unsigned char* b = this->Bytes.data();
  switch (this->DataType)
  {
    case UINT8:
    case RGB24:
    case RGBA32:
      return Element<std::uint8_t>(b, index);
    case INT8:
      return Element<std::int8_t>(b, index);
    case INT16:
      return Element<std::int16_t>(b, index);
    case UINT16:
      return Element<std::uint16_t>(b, index);
    case INT32:
      return Element<std::int32_t>(b, index);
    case UINT32:
      return Element<std::uint32_t>(b, index);
    case INT64:
      return Element<std::int64_t>(b, index);
    case UINT64:
      return Element<std::uint64_t>(b, index);
    case FLOAT32:
    case COMPLEX64:
      return Element<float>(b, index);
    case FLOAT64:
    case COMPLEX128:
      return Element<double>(b, index);
    default:
      return 0.0;
  }
}

bool vtkNIfTIFile::ReadSlices(
  const std::vector<std::int64_t>& volumes, int k0, int k1, Voxels& v, std::string& error)
{
  v = Voxels();
  const Header& h = this->Hdr;
  const std::int64_t nv = this->GetNumberOfVolumes();
  if (k0 < 0 || k1 >= this->GetSize(2) || k0 > k1 || volumes.empty())
  {
    error = "no slices to read";
    return false;
  }
  for (std::int64_t m : volumes)
  {
    if (m < 0 || m >= nv)
    {
      error =
        "volume " + std::to_string(m) + " does not exist (the file has " + std::to_string(nv) + ")";
      return false;
    }
  }
  const std::uint64_t valueSize = static_cast<std::uint64_t>(GetValueSize(h.DataType));
  const std::uint64_t sliceVoxels = static_cast<std::uint64_t>(h.Dim[1] * h.Dim[2]);
  const std::uint64_t slabBytes = sliceVoxels * static_cast<std::uint64_t>(k1 - k0 + 1) * valueSize;
  const double total = static_cast<double>(slabBytes) * static_cast<double>(volumes.size());
  if (!vtkSplineVizProgress::CheckOutputSize(total, 1.0, "reading the voxels", &error) ||
    total > static_cast<double>(std::numeric_limits<std::size_t>::max() / 2))
  {
    if (error.empty())
    {
      error = "reading the voxels would take more memory than can be addressed";
    }
    return false;
  }
  try
  {
    v.Bytes.resize(static_cast<std::size_t>(total));
  }
  catch (const std::bad_alloc&)
  {
    error = "not enough memory for " + std::to_string(total) + " bytes of voxels";
    return false;
  }
  v.DataType = h.DataType;
  v.Elements = GetElementsPerVoxel(h.DataType);
  v.FirstSlice = k0;
  v.Slices = k1 - k0 + 1;
  v.SliceVoxels = static_cast<std::int64_t>(sliceVoxels);
  v.Volumes = volumes.size();
  std::vector<Range> ranges(volumes.size());
  const std::uint64_t volumeBytes = sliceVoxels * static_cast<std::uint64_t>(h.Dim[3]) * valueSize;
  for (std::size_t m = 0; m < volumes.size(); ++m)
  {
    ranges[m].Offset = static_cast<std::uint64_t>(h.VoxOffset) +
      static_cast<std::uint64_t>(volumes[m]) * volumeBytes +
      static_cast<std::uint64_t>(k0) * sliceVoxels * valueSize;
    ranges[m].Length = slabBytes;
    ranges[m].Target = v.Bytes.data() + m * slabBytes;
  }
  if (!this->ReadRanges(this->ImageFile, this->ImageCompressed, ranges, !this->Verified, error))
  {
    v = Voxels();
    if (error != "aborted")
    {
      error = "\"" + this->ImageFile + "\": " + error;
    }
    return false;
  }
  const std::size_t elementSize = static_cast<std::size_t>(valueSize) / v.Elements;
  if (h.Swapped && elementSize > 1)
  {
    vtkByteSwap::SwapVoidRange(v.Bytes.data(), v.Bytes.size() / elementSize, elementSize);
  }
  return true;
}

bool vtkNIfTIFile::ReadRanges(const std::string& file, bool compressed, std::vector<Range>& ranges,
  bool toEnd, std::string& error)
{
  std::sort(ranges.begin(), ranges.end(),
    [](const Range& a, const Range& b) { return a.Offset < b.Offset; });
  std::uint64_t total = 0, done = 0;
  for (const Range& r : ranges)
  {
    total += r.Length;
  }
  auto report = [this, &done, total](std::uint64_t n)
  {
    done += n;
    return !this->Progress || this->Progress(total > 0 ? double(done) / double(total) : 1.0);
  };
  if (!compressed)
  {
    std::ifstream in(file, std::ios::in | std::ios::binary);
    for (const Range& r : ranges)
    {
      for (std::uint64_t at = 0; at < r.Length && in;)
      {
        const std::uint64_t n = std::min(ChunkBytes, r.Length - at);
        in.seekg(static_cast<std::streamoff>(r.Offset + at), std::ios::beg);
        in.read(reinterpret_cast<char*>(r.Target + at), static_cast<std::streamsize>(n));
        if (!in || static_cast<std::uint64_t>(in.gcount()) != n)
        {
          error = "cannot read its voxels (the file is truncated or unreadable)";
          return false;
        }
        at += n;
        if (!report(n))
        {
          error = "aborted";
          return false;
        }
      }
    }
    return true;
  }
  GzipReader gz;
  if (!gz.Open(file, error))
  {
    return false;
  }
  for (const Range& r : ranges)
  {
    std::uint64_t produced = 0;
    if (r.Offset > gz.GetPosition())
    {
      const std::uint64_t skip = r.Offset - gz.GetPosition();
      if (!gz.Read(nullptr, skip, produced, error))
      {
        return false;
      }
      if (produced < skip)
      {
        error = "the decompressed file ends at byte " + std::to_string(gz.GetPosition()) +
          ", before the voxels its header announces";
        return false;
      }
    }
    for (std::uint64_t at = 0; at < r.Length;)
    {
      const std::uint64_t n = std::min(ChunkBytes, r.Length - at);
      if (!gz.Read(r.Target + at, n, produced, error))
      {
        return false;
      }
      if (produced < n)
      {
        error = "the decompressed file ends at byte " + std::to_string(gz.GetPosition()) +
          ", before the voxels its header announces";
        return false;
      }
      at += n;
      if (!report(n))
      {
        error = "aborted";
        return false;
      }
    }
  }
  // The rest of the stream: damage and the checksum are found only at its end.
  while (toEnd && !gz.AtEnd())
  {
    std::uint64_t produced = 0;
    if (!gz.Read(nullptr, ChunkBytes, produced, error))
    {
      return false;
    }
    if (this->Progress && !this->Progress(1.0))
    {
      error = "aborted";
      return false;
    }
  }
  return true;
}
