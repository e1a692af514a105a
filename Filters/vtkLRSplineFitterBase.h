// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkLRSplineFitterBase
 * @brief   Abstract base of the LR-spline fitters: the settings, checks and results that
 * vtkLRSplineFitter (any data set) and vtkLRSplineImageFitter (images) share.
 *
 * Both fitters approximate sampled data by an LR-spline volume, the
 * representation Fuchs et al. render (LR splines, §3.1, output as the Bezier
 * blocks of §3.2.3 in vtkLRSplineReader's format). From a tensor-product
 * spline of degree Degree with InitialNumberOfElements elements per
 * direction they repeat: update the coefficients (regularized least squares,
 * Regularization pulling basis functions with little data towards the
 * previous fit); measure the error at the data; stop when it is within
 * Tolerance (ToleranceMode: ABSOLUTE_TOLERANCE in the data's units, or
 * RELATIVE_TOLERANCE, a fraction of the data range); else refine the
 * elements above it by structured mesh refinement (Johannessen, Kvamsdal and
 * Dokken 2014), up to MaximumRefinementLevels halvings and
 * MaximumNumberOfElements elements (then with a warning).
 *
 * The numerical core is vtkLRSplineFitCore. This class holds the rest the
 * two filters share: those settings with their defaults and checks (refused
 * at the update with an error: Tolerance not positive and finite, degrees
 * outside 1..5, InitialNumberOfElements below 1, MaximumRefinementLevels
 * outside 0..30, MaximumNumberOfElements below 1, Regularization not
 * finite); OutputFieldName and FileName; the array to fit (SetInputArrayToProcess,
 * default the active point scalars); the results of the last update
 * (GetMaximumError() ... GetFitTime(), and "LRFitSeconds" in the output's
 * field data); every piece fits all the data. Abstract: use a subclass.
 * Details: docs/lr-fitting.md and docs/components.md.
 */

#ifndef vtkLRSplineFitterBase_h
#define vtkLRSplineFitterBase_h

#include "SplineVizFiltersModule.h" // for export macro
#include "vtkMultiBlockDataSetAlgorithm.h"

#include <string> // for ResolveOutputFieldName

class vtkMultiBlockDataSet;

class SPLINEVIZFILTERS_EXPORT vtkLRSplineFitterBase : public vtkMultiBlockDataSetAlgorithm
{
public:
  vtkTypeMacro(vtkLRSplineFitterBase, vtkMultiBlockDataSetAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum ToleranceModes
  {
    ABSOLUTE_TOLERANCE = 0, ///< Tolerance in the data's units
    RELATIVE_TOLERANCE = 1  ///< Tolerance as a fraction of the data range (max - min)
  };

  ///@{
  /// Polynomial degree per direction, 1 to 5. Default 2 2 2 (Fuchs' splines are quadratic).
  vtkSetVector3Macro(Degree, int);
  vtkGetVector3Macro(Degree, int);
  ///@}

  ///@{
  /// Elements per direction of the initial tensor-product spline. Default 4 4 4.
  vtkSetVector3Macro(InitialNumberOfElements, int);
  vtkGetVector3Macro(InitialNumberOfElements, int);
  ///@}

  ///@{
  /**
   * The error allowed at the data: at every data point (voxel), or for the
   * RMS error with vtkLRSplineFitter's ToleranceType. Default 0.02 (relative:
   * 2 % of the data range).
   */
  vtkSetMacro(Tolerance, double);
  vtkGetMacro(Tolerance, double);
  ///@}

  ///@{
  /// How Tolerance is meant. Default RELATIVE_TOLERANCE.
  vtkSetClampMacro(ToleranceMode, int, ABSOLUTE_TOLERANCE, RELATIVE_TOLERANCE);
  vtkGetMacro(ToleranceMode, int);
  void SetToleranceModeToAbsolute() { this->SetToleranceMode(ABSOLUTE_TOLERANCE); }
  void SetToleranceModeToRelative() { this->SetToleranceMode(RELATIVE_TOLERANCE); }
  ///@}

  ///@{
  /**
   * Refinement stops (with a warning) when the spline (each patch, for a
   * composite of images) has this many elements; below 1 is refused.
   * Default 500000.
   */
  vtkSetMacro(MaximumNumberOfElements, vtkIdType);
  vtkGetMacro(MaximumNumberOfElements, vtkIdType);
  ///@}

  ///@{
  /// Most halvings of an initial element side, 0 to 30 (others are refused). Default 10.
  vtkSetMacro(MaximumRefinementLevels, int);
  vtkGetMacro(MaximumRefinementLevels, int);
  ///@}

  ///@{
  /**
   * Least squares: weight of the pull towards the previous fit for basis
   * functions with little data (less than one data point's weight, or less
   * than one voxel along some direction). Default 0.1 (stronger pulls
   * converge a little faster and bias the fit where data is sparse, as at
   * an image's faces, more).
   */
  vtkSetClampMacro(Regularization, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(Regularization, double);
  ///@}

  ///@{
  /**
   * Name of the output's point array of coefficients (as vtkLRSplineReader's
   * OutputFieldName); empty (default): the input array's name. The array to
   * fit is selected with SetInputArrayToProcess.
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
  /// If set, the fitted spline is also written to this .lr file.
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  ///@{
  /// Results of the last update (errors over all data points, counts over all patches).
  double GetMaximumError() const { return this->MaximumError; }
  double GetRMSError() const { return this->RMSError; }
  /// The tolerance in data units that was applied.
  double GetAbsoluteTolerance() const { return this->AbsoluteTolerance; }
  bool GetToleranceMet() const { return this->ToleranceMet; }
  vtkIdType GetNumberOfElements() const { return this->NumberOfElements; }
  vtkIdType GetNumberOfBasisFunctions() const { return this->NumberOfBasisFunctions; }
  /// Halvings of the initial element sides reached (largest over directions).
  int GetNumberOfRefinementLevels() const { return this->NumberOfRefinementLevels; }
  /// Fit-and-refine rounds (1: the initial spline was good enough).
  int GetNumberOfIterations() const { return this->NumberOfIterations; }
  /// Wall time of the fit in seconds.
  double GetFitTime() const { return this->FitTime; }
  ///@}

protected:
  vtkLRSplineFitterBase();
  ~vtkLRSplineFitterBase() override;

  // Every output port can handle piece requests; every piece fits all the data.
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override = 0;

  // Refuse bad shared settings (false with an error; see the class
  // documentation). Subclasses check theirs after these.
  virtual bool CheckSettings();
  // Zero the results and start the clock of FitTime (first thing in RequestData).
  virtual void ResetResults();
  // FitTime since ResetResults(), also as field data "LRFitSeconds" of the
  // output's first block (if any).
  void RecordFitTime(vtkMultiBlockDataSet* output);
  // The tolerance in data units for data in [range[0], range[1]] (at least
  // the rounding level of the values, for constant data).
  double ComputeAbsoluteTolerance(const double range[2]) const;
  // The output's array name: OutputFieldName, else the input array's, else "Field".
  std::string ResolveOutputFieldName(const char* arrayName) const;
  // The most fit-and-refine rounds of an update: 3 per refinement level
  // allowed, at most 64 (a safety bound; each round halves the marked intervals).
  int GetMaximumRounds() const;

  int Degree[3] = { 2, 2, 2 };
  int InitialNumberOfElements[3] = { 4, 4, 4 };
  double Tolerance = 0.02;
  int ToleranceMode = RELATIVE_TOLERANCE;
  vtkIdType MaximumNumberOfElements = 500000;
  int MaximumRefinementLevels = 10;
  double Regularization = 0.1;
  char* OutputFieldName = nullptr;
  char* FileName = nullptr;

  double MaximumError = 0.0;
  double RMSError = 0.0;
  double AbsoluteTolerance = 0.0;
  bool ToleranceMet = false;
  vtkIdType NumberOfElements = 0;
  vtkIdType NumberOfBasisFunctions = 0;
  int NumberOfRefinementLevels = 0;
  int NumberOfIterations = 0;
  double FitTime = 0.0;

private:
  double FitStart = 0.0; // steady clock, seconds

  vtkLRSplineFitterBase(const vtkLRSplineFitterBase&) = delete;
  void operator=(const vtkLRSplineFitterBase&) = delete;
};

#endif
