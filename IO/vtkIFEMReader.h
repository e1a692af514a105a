/**
 * @class   vtkIFEMReader
 * @brief   Reads IFEM's HDF5 simulation results (isogeometric and Lagrange patches, fields,
 * element values, time steps) as exact Bezier cells in physical space.
 *
 * IFEM (SINTEF's isogeometric FEM library) writes one HDF5 group per output
 * level (time step or adaptive step; "timeinfo/level" holds the time), in it
 * one group per basis "<Sim>-<b>" with the patch text (basis/<patch>:
 * LRSplines text, GoTools g2 or "# LAGRANGIAN"), nodal fields
 * (fields/<name>/<patch>, components interleaved) and element values
 * (knotspan/<name>/<patch>). A basis is written again only when it changes
 * (adaptive refinement, moving meshes); the reader carries every basis and
 * field forward from the last level that wrote it. The layout is in
 * docs/ifem.md.
 *
 * Output: per time step a vtkMultiBlockDataSet with one block per basis
 * (named like the basis), holding one block per patch ("Patch 1", ...): a
 * vtkUnstructuredGrid made by vtkIFEMBlockBuilder. Spline patches become
 * VTK_BEZIER_HEXAHEDRON / VTK_BEZIER_QUADRILATERAL cells whose control points
 * are the geometry's Bezier coefficients (rational bases with VTK's
 * RationalWeights) and whose point data are the fields' Bezier coefficients
 * on that basis, so VTK's interpolation of a cell is the simulation's
 * geometry and field, exactly; Lagrange patches become Lagrange cells. Field
 * names, split components and vectors follow vtkIFEMBlockBuilder::ArraysFor;
 * element values are cell data. Field data of each patch: the LR keys of
 * vtkLRSplineBezierGrid ("LRMode" 1, "LRParameterBox" per element, degrees,
 * "LRParametricDimension", "LRRational", point data
 * "LRParameterCoordinates") and "IFEMBasis", "IFEMPatch" (from 1),
 * "IFEMLevel", "IFEMBasisLevel" (the level that wrote the basis shown),
 * "IFEMTime", "IFEMSpatialDimension"; a basis "<Sim>-<b>" other than
 * "<Sim>-1" also "LRGeometryReferenceBasis" and "LRGeometryDeviation", the
 * exact largest distance between its geometry and that of "<Sim>-1" (mixed
 * methods write each basis with its own geometry coefficients; a deviation
 * above 1e-9 of the patch size is warned about, the fields being drawn on
 * their own basis' geometry).
 *
 * Time steps: the times of "timeinfo" when every level has one and they
 * increase, otherwise the level numbers. Fields of a group that has no basis
 * of its own (coupled simulators sharing a mesh) are attached to the one
 * basis whose patches all match their sizes; when none or several do, they
 * are skipped with a warning.
 *
 * Settings: the bases, nodal fields and element fields to read (array
 * selections, by the names written in the file), RationalMode (how
 * LRSplines text patches are told rational: see
 * vtkLRSplinePatch::RationalModes; Automatic is SISO's rule, dim > pardim),
 * MergePoints. Pieces split every spline patch's elements (each piece's
 * Bezier form is exact by itself). Bad input (missing groups, size
 * mismatches, unknown patch text, values that are not finite, absurd sizes)
 * is an error naming the dataset, with an empty output; nothing is allocated
 * for sizes the file cannot hold.
 */

#ifndef vtkIFEMReader_h
#define vtkIFEMReader_h

#include "SplineVizModule.h" // for export macro
#include "vtkMultiBlockDataSetAlgorithm.h"

#include <memory> // for std::unique_ptr
#include <string> // for std::string

class vtkDataArraySelection;

class SPLINEVIZ_EXPORT vtkIFEMReader : public vtkMultiBlockDataSetAlgorithm
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
