// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkIFEMFile
 * @brief   Read access to IFEM's HDF5 result files: the layout of levels, bases, fields and
 * element values, and checked reads of their datasets.
 *
 * Plain C++ (not a vtkObject), used by vtkIFEMReader; the only SplineViz code
 * that calls the HDF5 C library. The layout (docs/ifem.md) is that of IFEM's
 * HDF5Writer:
 *
 *   /<level>/timeinfo/level                   the time of an output level
 *   /<level>/<Sim>-<b>/basis/<patch>          patch text (chars): LRSplines,
 *                                             GoTools g2 or "# LAGRANGIAN"
 *   /<level>/<Sim>-<b>/fields/<name>/<patch>  nodal values (float64,
 *                                             components interleaved)
 *   /<level>/<Sim>-<b>/knotspan/<name>/<patch> per-element values
 *
 * with levels 0, 1, ... and patches 1, 2, ...; the top level may also hold
 * "anasol" and "log", which are skipped. Scan() lists the layout without
 * reading data; ReadText() and ReadDoubles() read one dataset after checking
 * its type and its announced size against the file size and this machine's
 * memory (a dataset may not claim more than 64 times the file's bytes), so
 * that hostile files are refused before anything is allocated. Only hard
 * links are followed (an external link could name another file). HDF5's own
 * error printing is silenced while the file is read; failures come back as
 * messages.
 *
 * Open() reads a file by name, OpenImage() an HDF5 file held in memory (the
 * core driver with a file image; used by the fuzz target).
 */

#ifndef vtkIFEMFile_h
#define vtkIFEMFile_h

#include "SplineVizIOModule.h" // for export macro

#include <cstdint>
#include <map>
#include <string>
#include <vector>

class SPLINEVIZIO_EXPORT vtkIFEMFile
{
public:
  vtkIFEMFile() = default;
  ~vtkIFEMFile();
  vtkIFEMFile(const vtkIFEMFile&) = delete;
  vtkIFEMFile& operator=(const vtkIFEMFile&) = delete;

  /// One "<Sim>-<b>" group of one level.
  struct Group
  {
    /// The patches of basis/ (1 .. n), 0 when the level has no basis group.
    int NumberOfBasisPatches = 0;
    /// The names under fields/ and knotspan/.
    std::vector<std::string> Fields;
    std::vector<std::string> Knotspans;
    /// Other children (e.g. "Eigenmode"), reported by the reader.
    std::vector<std::string> Others;
  };
  /// One output level.
  struct Level
  {
    bool HasTime = false;
    double Time = 0.0;
    std::map<std::string, Group> Groups;
  };

  bool Open(const std::string& fileName, std::string* error);
  bool OpenImage(const std::string& bytes, std::string* error);
  void Close();
  bool IsOpen() const { return this->File >= 0; }

  /// The layout of every level (levels 0 .. n-1, all present).
  bool Scan(std::vector<Level>& levels, std::string* error);

  /// Does the link path exist (every part a hard link)?
  bool Exists(const std::string& path);

  /// The number of values of a dataset (checked like the reads).
  bool GetNumberOfValues(const std::string& path, uint64_t& count, std::string* error);

  /// A dataset of 1-byte integers (IFEM's patch text) as bytes.
  bool ReadText(const std::string& path, std::string& text, std::string* error);

  /// A dataset of integers or floating point numbers as doubles (any shape, flattened).
  bool ReadDoubles(const std::string& path, std::vector<double>& values, std::string* error);

  /**
   * Quick test for readers' CanReadFile: an HDF5 file whose top level holds
   * level groups (and possibly "anasol", "log"), level 0 a group with a
   * basis/ group.
   */
  static bool LooksLikeIFEM(const char* fileName);

  /// HDF5 files and objects open in this process (tests: 0 after every read).
  static long GetNumberOfOpenObjects();

private:
  bool ListChildren(const std::string& path, std::vector<std::string>& names,
    std::vector<bool>* isGroup, std::string* error);
  bool ScanGroup(const std::string& path, Group& group, std::string* error);
  /// An open dataset (Id, to be closed by the caller), its number of values and their type.
  struct Dataset
  {
    int64_t Id = -1;
    uint64_t Count = 0;
    int TypeClass = 0;
    std::size_t TypeSize = 0;
    bool IsSigned = false;
  };
  bool OpenDataset(const std::string& path, Dataset& dataset, std::string* error);

  int64_t File = -1;
  uint64_t FileBytes = 0;
};

#endif
// VTK-HeaderTest-Exclude: vtkIFEMFile.h
