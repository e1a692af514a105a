// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkLRSplineFitCore
 * @brief   The fitting idea shared by the LR-spline fitters: an LR spline refined where the data
 * is not met, sparse least squares on its basis, and the fitters' output.
 *
 * Plain C++ (not a vtkObject), used by vtkLRSplineImageFitter (voxels) and
 * vtkLRSplineFitter (scattered points). What depends on where the data sits
 * (how the normal equations are summed, how the error at the data is
 * evaluated) stays in the fitters; this class holds the rest:
 *
 * - the LR spline being refined (Builder) and where its splits may go
 *   (Options: halvings, optionally rounded to a grid, no part below a
 *   minimum), and the side of the initial elements (InitialSide);
 * - ComputeSupports(): the basis functions on every element and the elements
 *   in every function's support (CSR arrays);
 * - BuildPattern(): the sparsity pattern of the normal matrix (functions
 *   overlap when they share an element), whose entries the fitter fills;
 * - AddElementSmoothing(): the thin-plate energy of the functions on an
 *   element, in the element's own coordinates (the fitters' smoothing term);
 * - Regularize() and Solve(): the regularized normal equations
 *   (A + D) c = b + D c_prev, D pulling functions with little data towards
 *   the previous fit, solved by conjugate gradients with a Jacobi
 *   preconditioner from c_prev until the error left in the data values (its
 *   energy norm estimated from the last 10 steps, Strakos and Tichy 2002)
 *   is below a target;
 * - Refine(): structured mesh refinement (Johannessen, Kvamsdal and Dokken
 *   2014) of, on every element whose error exceeds the tolerance, the basis
 *   function of smallest support that can still be split (every function on
 *   it when the element itself cannot be split);
 * - Levels(): halvings of the initial elements reached;
 * - BuildBlock() and WritePatches(): the output block (the format of
 *   vtkLRSplineReader, see vtkLRSplineBezierGrid) with the fit's cell and
 *   field data, and the LRSplines text file (.lr).
 */

#ifndef vtkLRSplineFitCore_h
#define vtkLRSplineFitCore_h

#include "SplineVizFiltersModule.h" // for export macro
#include "vtkLRSplineBuilder.h"
#include "vtkSmartPointer.h"

#include <string>
#include <vector>

class vtkLRSplineBezierVolume;
class vtkUnstructuredGrid;

class SPLINEVIZFILTERS_EXPORT vtkLRSplineFitCore
{
public:
  vtkLRSplineBuilder Builder;
  vtkLRSplineBuilder::RefineOptions Options;
  double InitialSide[3] = { 1, 1, 1 };
  /// Smallest cell of ComputeSupports()' registration grid (parameter units).
  double MinimumCell = 1.0;

  /// CSR: the functions on each element, the elements of each function's support.
  std::vector<vtkIdType> SupportOffsets, SupportIds;
  std::vector<vtkIdType> FunctionElementOffsets, FunctionElements;

  /// The normal matrix: rows (one per function), columns and entries (filled by the fitter).
  std::vector<vtkIdType> RowOffsets;
  std::vector<int> Columns;
  std::vector<double> Entries;

  /// Compute the support lists of the builder's current patch.
  void ComputeSupports();

  /**
   * The sparsity pattern (RowOffsets, Columns; Entries sized and zeroed).
   * `sorted`: the columns of each row in increasing order (else in the order
   * the supports list them). Needs ComputeSupports().
   */
  void BuildPattern(bool sorted);

  /**
   * The diagonal weights D (delta) of the pull towards the previous fit:
   * delta_i = A_ii (1e-12 + regularization * max(0, 1 - weight_i / littleData)),
   * 1 where A_ii = 0 (no data: the previous coefficient is kept). `diagonal`
   * holds A_ii on input and A_ii + delta_i on output.
   */
  static void Regularize(const std::vector<double>& weight, double regularization,
    double littleData, std::vector<double>& diagonal, std::vector<double>& delta);

  /**
   * Smoothing: add `smoothing` times the thin-plate energy of the functions
   * on element e to `local` (count x count, row-major, in the order of
   * SupportIds): local[a][b] += smoothing * integral over the element of
   * sum_{|alpha| = 2} (2 / alpha!) D^alpha B_a D^alpha B_b, the derivatives
   * taken in the element's own coordinates s in [0, 1]^3 (u = lo + s (hi - lo)),
   * so that the energy of a function does not depend on the element's size
   * or shape and the term fades as elements are refined (in the manner of
   * the smoothing term of GoTools' LRSurfApprox; Skytt, Barrowclough and
   * Dokken 2015). Exact (Gauss-Legendre on the Bezier form of each function,
   * one dimension at a time). `patch` is the builder's (GetPatch(), taken
   * once before threads call this). Needs ComputeSupports(). False with a message
   * when a function's knots do not cover the element.
   */
  bool AddElementSmoothing(const vtkLRSplinePatch& patch, vtkIdType e, double smoothing,
    double* local, std::string* error = nullptr) const;

  /**
   * Solve (A + D) x = rhs + D prior by preconditioned conjugate gradients
   * from x = prior (one component). `diagonal` is A_ii + delta_i. Stops when
   * the estimated error in the data values is below `target` or at the
   * rounding level. Returns the number of iterations.
   */
  int Solve(const std::vector<double>& rhs, const std::vector<double>& prior,
    const std::vector<double>& delta, const std::vector<double>& diagonal, double target,
    std::vector<double>& x) const;

  enum Outcome
  {
    REFINED,
    ELEMENT_LIMIT,
    NOTHING_REFINABLE,
    NO_PROGRESS,
    FAILED
  };

  /**
   * Refine where elementError (per element of the current patch) exceeds
   * `tolerance` (see the class documentation). Needs ComputeSupports().
   */
  Outcome Refine(const std::vector<double>& elementError, double tolerance,
    vtkIdType maximumElements, std::string* error);

  /**
   * Why a fit stopped refining, for its warning: `outcome` is ELEMENT_LIMIT,
   * NOTHING_REFINABLE or NO_PROGRESS (empty for the others);
   * `limits` says what stops the elements above the tolerance from being
   * split (the fitter's own settings, e.g. "MaximumRefinementLevels (8)").
   */
  static std::string StopReason(
    Outcome outcome, vtkIdType maximumElements, const std::string& limits);

  /// Halvings of the initial element sides reached (largest over directions).
  int Levels();

  /// What a fit reports in the output's field data.
  struct Report
  {
    double MaximumError = 0.0;
    double RMSError = 0.0;
    double Tolerance = 0.0;
    bool ToleranceMet = false;
    int Iterations = 0;
    int Levels = 0;
    double DataRange[2] = { 0, 0 };
    /// 5 values per iteration: elements, basis functions, maximum error, RMS error, solver
    /// iterations.
    std::vector<double> History;
  };

  /**
   * The output block of a fitted patch: the piece [piece/numPieces] of the
   * elements of `volume` (the patch's Bezier form) placed by x = offset +
   * scale * u, with cell data "LRFitElementMaxError" (elementError per
   * element) and field data "LRFitMaximumError", "LRFitRMSError",
   * "LRFitTolerance", "LRFitToleranceMet", "LRFitIterations",
   * "LRFitRefinementLevels", "LRFitDataRange", "LRFitHistory". Null with a
   * message on failure.
   */
  static vtkSmartPointer<vtkUnstructuredGrid> BuildBlock(const vtkLRSplinePatch& patch,
    const vtkLRSplineBezierVolume& volume, int patchIndex, int piece, int numPieces,
    const double scale[3], const double offset[3], const std::string& fieldName,
    const std::string& sourceFormat, const std::vector<double>& elementError, const Report& report,
    std::string* error);

  /// Write the patches to an LRSplines text file (.lr); false with a message on failure.
  static bool WritePatches(
    const char* fileName, const std::vector<vtkLRSplinePatch>& patches, std::string* error);

private:
  std::vector<std::vector<int>> Rows, ElementLists;
};

#endif
// VTK-HeaderTest-Exclude: vtkLRSplineFitCore.h
