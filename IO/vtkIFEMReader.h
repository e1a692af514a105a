// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkIFEMReader
 * @brief   Reads IFEM's HDF5 simulation results (isogeometric and Lagrange patches, fields,
 * element values, time steps) as exact Bezier cells in physical space.
 *
 * IFEM (SINTEF's isogeometric FEM library) writes one HDF5 group per output
 * level ("timeinfo/level" holds the time), in it one group per basis
 * "<Sim>-<b>" with the patch text (basis/<patch>: LRSplines text, GoTools g2
 * or "# LAGRANGIAN"), nodal fields (fields/<name>/<patch>) and element values
 * (knotspan/<name>/<patch>); a basis is written again only when it changes.
 * The layout and every convention below are in docs/ifem.md.
 *
 * Output per time step: a vtkMultiBlockDataSet with one block per basis,
 * holding one vtkUnstructuredGrid per patch ("Patch 1", ...), made by
 * vtkIFEMBlockBuilder: spline patches as VTK_BEZIER_HEXAHEDRON /
 * VTK_BEZIER_QUADRILATERAL cells whose control points are the geometry's
 * Bezier coefficients (rational bases with VTK's RationalWeights) and whose
 * point data are the fields' Bezier coefficients, so VTK's interpolation is
 * the simulation's geometry and field exactly; Lagrange patches as Lagrange
 * cells; element values as cell data. Field data: the LR keys of
 * vtkLRSplineBezierGrid (geometry mode) and "IFEMBasis", "IFEMPatch",
 * "IFEMLevel", "IFEMBasisLevel", "IFEMTime", "IFEMSpatialDimension"; for the
 * further bases of a mixed method "LRGeometryDeviation", the exact distance
 * of their geometry from "<Sim>-1"'s (warned about above 1e-9 of the size).
 *
 * Time steps: the times of "timeinfo" when every level has an increasing one,
 * else the level numbers; bases and fields are carried forward from the last
 * level that wrote them. Fields of a group without a basis of its own are
 * attached to the one basis their sizes fit. Settings: the bases, nodal and
 * element fields to read (selections by the names in the file),
 * RationalMode (vtkLRSplinePatch::RationalModes), MergePoints. Pieces split
 * every spline patch's elements. Bad input (missing groups, size mismatches,
 * unknown patch text, absurd sizes) is an error naming the dataset, with an
 * empty output, before anything is allocated for it.
 */

#ifndef vtkIFEMReader_h
#define vtkIFEMReader_h

#include "SplineVizIOModule.h" // for export macro
#include "vtkMultiBlockDataSetAlgorithm.h"

#include <memory> // for std::unique_ptr
#include <string> // for std::string

class vtkDataArraySelection;

class SPLINEVIZIO_EXPORT vtkIFEMReader : public vtkMultiBlockDataSetAlgorithm
{
public:
  static vtkIFEMReader* New();
  vtkTypeMacro(vtkIFEMReader, vtkMultiBlockDataSetAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The IFEM result file (.hdf5).
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  ///@{
  /**
   * Read the HDF5 file held in InputString (any bytes) instead of FileName
   * (for the fuzz target and files in memory). Default off.
   */
  vtkSetMacro(ReadFromInputString, vtkTypeBool);
  vtkGetMacro(ReadFromInputString, vtkTypeBool);
  vtkBooleanMacro(ReadFromInputString, vtkTypeBool);
  void SetInputString(const char* data, std::size_t length);
  ///@}

  ///@{
  /**
   * How LRSplines text patches are told rational (vtkLRSplinePatch::RationalModes):
   * 0 Automatic (default: the header's rat = 1, or more components than
   * parametric directions, SISO's rule), 1 Polynomial, 2 Rational. g2
   * patches follow their own flag.
   */
  vtkSetClampMacro(RationalMode, int, 0, 2);
  vtkGetMacro(RationalMode, int);
  void SetRationalModeToAutomatic() { this->SetRationalMode(0); }
  void SetRationalModeToPolynomial() { this->SetRationalMode(1); }
  void SetRationalModeToRational() { this->SetRationalMode(2); }
  ///@}

  ///@{
  /// Merge control points that neighbouring elements share. Default on.
  vtkSetMacro(MergePoints, vtkTypeBool);
  vtkGetMacro(MergePoints, vtkTypeBool);
  vtkBooleanMacro(MergePoints, vtkTypeBool);
  ///@}

  ///@{
  /// The nodal fields to read (names as written in the file; all by default).
  vtkDataArraySelection* GetPointDataArraySelection() { return this->PointSelection; }
  int GetNumberOfPointArrays();
  const char* GetPointArrayName(int index);
  int GetPointArrayStatus(const char* name);
  void SetPointArrayStatus(const char* name, int status);
  ///@}

  ///@{
  /// The element fields (knotspan) to read.
  vtkDataArraySelection* GetCellDataArraySelection() { return this->CellSelection; }
  int GetNumberOfCellArrays();
  const char* GetCellArrayName(int index);
  int GetCellArrayStatus(const char* name);
  void SetCellArrayStatus(const char* name, int status);
  ///@}

  ///@{
  /// The bases to read ("<Sim>-<b>"; all by default).
  vtkDataArraySelection* GetBasisSelection() { return this->BasisSelection; }
  int GetNumberOfBasisArrays();
  const char* GetBasisArrayName(int index);
  int GetBasisArrayStatus(const char* name);
  void SetBasisArrayStatus(const char* name, int status);
  ///@}

  /// The time steps found by the last RequestInformation.
  int GetNumberOfTimeSteps();
  double GetTimeStep(int index);

  /// Does the file hold IFEM's layout (HDF5, levels 0, 1, ..., a basis at level 0)?
  static int CanReadFile(const char* fileName);

  /// The message of the last error (empty when the last read succeeded).
  const char* GetLastErrorMessage() const { return this->LastError.c_str(); }

  vtkMTimeType GetMTime() override;

protected:
  vtkIFEMReader();
  ~vtkIFEMReader() override;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  char* FileName = nullptr;
  vtkTypeBool ReadFromInputString = 0;
  std::string InputString;
  int RationalMode = 0;
  vtkTypeBool MergePoints = 1;
  vtkDataArraySelection* PointSelection;
  vtkDataArraySelection* CellSelection;
  vtkDataArraySelection* BasisSelection;
  std::string LastError;

private:
  vtkIFEMReader(const vtkIFEMReader&) = delete;
  void operator=(const vtkIFEMReader&) = delete;

  struct vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
  bool UpdateLayout(std::string* error);
  int Fail(const std::string& message);
};

#endif
