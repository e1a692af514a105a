// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkLRSplineReader
 * @brief   Reads LR-spline volumes and surfaces (.lr, LRSplines text format, several patches) and
 * GoTools g2 spline patches (.g2: classes 200, 700, 293, 793) as exact Bezier cells.
 *
 * The data side of Fuchs et al., "Direct interactive visualization of locally
 * refined spline volumes" (§3): every LR element becomes one
 * VTK_BEZIER_HEXAHEDRON (volumes) or VTK_BEZIER_QUADRILATERAL (surfaces) whose
 * control points carry the element's Bernstein coefficients (the exact change
 * of basis of §3.2.3, computed once, in parallel). VTK interpolates point data
 * of Bezier cells with the same Bernstein basis, so the grid IS the spline:
 * ParaView shows it natively and every VTK filter can use it;
 * vtkLRSplineProbeFilter, vtkLRSplineResampleToImage and
 * vtkLRSplineStreamTracer evaluate it fast and exactly with a k-d forest.
 *
 * Output: a vtkMultiBlockDataSet, one block per patch ("Patch 0", ...), each a
 * vtkUnstructuredGrid written by vtkLRSplineBezierGrid (see there for the
 * cell, point and field data; the coefficients in an array named
 * OutputFieldName).
 *
 * Field mode (default): control points at the equally spaced points of each
 * element's parameter box (the Bezier form of the identity), optionally
 * mapped affinely so that the patches' parameter domains fill
 * PhysicalBounds. Geometry mode: the coefficients ARE the control points (an
 * IFEM-style geometry shows its real shape; 2 or 3 components). Rational
 * patches (g2 patches flagged rational; LRSplines text by RationalMode)
 * become rational Bezier cells in geometry mode and are an error in field
 * mode (a rational map is not the field mode's affine placement).
 *
 * Shared control points with equal coefficients are merged (MergePoints).
 * Piece p of n gets the elements [p N / n, (p + 1) N / n) of every patch.
 * Progress per patch, abort between patches (empty output).
 * ReadFromInputString reads the text from memory (the fuzz target). Bad
 * input (truncated files, wrong counts, unknown headers, non-finite numbers,
 * inconsistent meshes) gives an error naming the file and the line and an
 * empty output; RequestData returns 0.
 */

#ifndef vtkLRSplineReader_h
#define vtkLRSplineReader_h

#include "SplineVizIOModule.h" // for export macro
#include "vtkMultiBlockDataSetAlgorithm.h"

#include <string> // for std::string

class SPLINEVIZIO_EXPORT vtkLRSplineReader : public vtkMultiBlockDataSetAlgorithm
{
public:
  static vtkLRSplineReader* New();
  vtkTypeMacro(vtkLRSplineReader, vtkMultiBlockDataSetAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The file to read (.lr or .g2).
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  ///@{
  /**
   * Read from InputString instead of FileName (as vtkDataReader's
   * ReadFromInputString): the whole text of a .lr or .g2 file held in memory
   * (it may contain any bytes). Default off.
   */
  vtkSetMacro(ReadFromInputString, vtkTypeBool);
  vtkGetMacro(ReadFromInputString, vtkTypeBool);
  vtkBooleanMacro(ReadFromInputString, vtkTypeBool);
  void SetInputString(const std::string& text);
  void SetInputString(const char* text, std::size_t length);
  const std::string& GetInputString() const { return this->InputString; }
  ///@}

  enum FileFormats
  {
    AUTOMATIC = 0, ///< from the content ('#' first: LRSplines, a number: g2)
    LRSPLINES = 1,
    G2 = 2
  };
  ///@{
  /// Format of the file. Default AUTOMATIC.
  vtkSetClampMacro(FileFormat, int, AUTOMATIC, G2);
  vtkGetMacro(FileFormat, int);
  ///@}

  ///@{
  /**
   * Geometry mode: the coefficients are the control points (needs 2 or 3
   * components). Default off (field mode).
   */
  vtkSetMacro(GeometryMode, vtkTypeBool);
  vtkGetMacro(GeometryMode, vtkTypeBool);
  vtkBooleanMacro(GeometryMode, vtkTypeBool);
  ///@}

  ///@{
  /**
   * Field mode: the physical box (xmin, xmax, ymin, ymax, zmin, zmax) the
   * parameter domain is mapped to. An empty box (a min > its max, the
   * default) keeps parameter coordinates.
   */
  vtkSetVector6Macro(PhysicalBounds, double);
  vtkGetVector6Macro(PhysicalBounds, double);
  ///@}

  ///@{
  /**
   * How LRSplines text patches are told rational (see
   * vtkLRSplinePatch::RationalModes): Automatic (default; in geometry mode,
   * rat = 1 or more components than parametric directions), Polynomial or
   * Rational. g2 patches follow their own flag.
   */
  vtkSetClampMacro(RationalMode, int, 0, 2);
  vtkGetMacro(RationalMode, int);
  void SetRationalModeToAutomatic() { this->SetRationalMode(0); }
  void SetRationalModeToPolynomial() { this->SetRationalMode(1); }
  void SetRationalModeToRational() { this->SetRationalMode(2); }
  ///@}

  ///@{
  /**
   * Name of the output's point-data array of coefficients (the name the
   * fitters' OutputFieldName sets too). Default "Field".
   */
  vtkSetStringMacro(OutputFieldName);
  vtkGetStringMacro(OutputFieldName);
  ///@}

  ///@{
  /// Deprecated: use SetOutputFieldName / GetOutputFieldName; kept for one release.
  void SetFieldName(const char* name) { this->SetOutputFieldName(name); }
  char* GetFieldName() { return this->GetOutputFieldName(); }
  ///@}

  ///@{
  /// Merge coincident control points with equal coefficients. Default on.
  vtkSetMacro(MergePoints, vtkTypeBool);
  vtkGetMacro(MergePoints, vtkTypeBool);
  vtkBooleanMacro(MergePoints, vtkTypeBool);
  ///@}

  /// Can this reader read the file (by its content)?
  static int CanReadFile(const char* fileName);

  /// The message of the last error (empty when the last read succeeded).
  const char* GetLastErrorMessage() const { return this->LastError.c_str(); }

protected:
  vtkLRSplineReader();
  ~vtkLRSplineReader() override;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  char* FileName = nullptr;
  vtkTypeBool ReadFromInputString = 0;
  std::string InputString;
  int FileFormat = AUTOMATIC;
  vtkTypeBool GeometryMode = 0;
  double PhysicalBounds[6] = { 0, -1, 0, -1, 0, -1 };
  char* OutputFieldName = nullptr;
  vtkTypeBool MergePoints = 1;
  int RationalMode = 0;
  std::string LastError;

private:
  vtkLRSplineReader(const vtkLRSplineReader&) = delete;
  void operator=(const vtkLRSplineReader&) = delete;
};

#endif
