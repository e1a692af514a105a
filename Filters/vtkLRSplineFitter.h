/**
 * @class   vtkLRSplineFitter
 * @brief   Fits an LR-spline volume to the point or cell data of any data set (scattered points,
 * unstructured meshes, images) by LR-MBA and/or least squares with local refinement until a
 * tolerance is met at every data point.
 *
 * Fuchs et al. render LR volumes that approximate simulation data on
 * unstructured meshes, trimmed by the mesh's boundary. This filter makes such
 * volumes from any vtkDataSet, or the leaves of a composite data set, whose
 * points are fitted together as one point cloud. Cell data is taken at the
 * cells' parametric centres (vtkCellCenters). A vector array is fitted as the
 * magnitude (VectorMode MAGNITUDE, default) or all its components as one
 * multi-component spline (COMPONENTS; the error at a point is then the length
 * of the error vector).
 *
 * Domain: the data's bounding box, each side widened by Margin times its
 * length; x = offset + scale * u maps the parameters u in [0, m_d]
 * (InitialNumberOfElements) to it, so that splits are exact halvings.
 * Method (the iteration of GoTools' LRVolApprox; Skytt, Barrowclough and
 * Dokken 2015 for LR-MBA): start from a tensor-product spline of tri-degree
 * Degree, coefficients the data mean, and repeat
 * 1. update the coefficients with the data (Method):
 *    - MBA: multilevel B-spline approximation on the LR basis, run twice:
 *      every point p proposes phi_i = w_i r_p / sum_j w_j^2 for the functions
 *      on its element (w_i = gamma_i B_i(x_p), r_p the residual) and each
 *      coefficient moves by sum_p w_i^2 phi_i / sum_p w_i^2 (local, cheap,
 *      not a projection: it approaches the data level by level);
 *    - LEAST_SQUARES: minimize sum_p (s(x_p) - f_p)^2 + sum_i delta_i
 *      (c_i - c_i^prev)^2, delta pulling functions that see little data
 *      (sum_p w_i < 1) towards the previous fit (Regularization), by
 *      conjugate gradients (vtkLRSplineFitCore, shared with
 *      vtkLRSplineImageFitter); reproduces a spline of the space exactly;
 *    - HYBRID: least squares, then the two MBA sweeps on its residual;
 * 2. the error at every point, per element (vtkSMPTools);
 * 3. stop when the maximum (ToleranceType MAXIMUM) or RMS (RMS) error is at
 *    most the tolerance (ABSOLUTE or RELATIVE to the data range); otherwise
 *    refine every element whose largest (or RMS) error exceeds it
 *    (vtkLRSplineFitCore::Refine, halvings) and holding at least
 *    MinimumPointsPerElement points, up to MaximumRefinementLevels halvings
 *    of the initial elements and MaximumNumberOfElements.
 * The final errors are those of the output's Bezier form.
 *
 * Output port 0: a vtkMultiBlockDataSet with one block in the format of
 * vtkLRSplineReader and vtkLRSplineImageFitter (the same cell and field data
 * "LRFit..."), which the volume mapper, probe and stream tracer take. Output
 * port 1: the data's boundary surface (vtkDataSetSurfaceFilter of every leaf,
 * triangulated; empty for point clouds), for the volume mapper's trimming
 * input. With FileName set the spline is also written as a .lr file whose
 * parameters are u (read it back with PhysicalBounds = the fitted domain,
 * field data "LRFitDomain").
 *
 * Every piece fits all the data and outputs its share of the elements.
 * Refused before allocating: no points, no or a missing array, NaN or
 * infinite values or coordinates, all points on a plane or line (no volume),
 * Tolerance <= 0, degrees outside 1..5, MaximumRefinementLevels outside
 * 0..30, a MaximumNumberOfElements whose spline would not fit in memory.
 */

#ifndef vtkLRSplineFitter_h
#define vtkLRSplineFitter_h

#include "SplineVizModule.h" // for export macro
#include "vtkMultiBlockDataSetAlgorithm.h"

#include <string> // for std::string
#include <vector> // for std::vector

class vtkDataSet;
class vtkPolyData;

class SPLINEVIZ_EXPORT vtkLRSplineFitter : public vtkMultiBlockDataSetAlgorithm
{
public:
  static vtkLRSplineFitter* New();
  vtkTypeMacro(vtkLRSplineFitter, vtkMultiBlockDataSetAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Methods
  {
    MBA = 0,           ///< LR multilevel B-spline approximation, two sweeps per level
    LEAST_SQUARES = 1, ///< regularized least squares (conjugate gradients)
    HYBRID = 2         ///< least squares, then two MBA sweeps on its residual
  };
  enum ToleranceModes
  {
    ABSOLUTE_TOLERANCE = 0, ///< in the data's units
    RELATIVE_TOLERANCE = 1  ///< a fraction of the data range
  };
  enum ToleranceTypes
  {
    MAXIMUM_ERROR = 0, ///< every point within the tolerance
    RMS_ERROR = 1      ///< the root mean square error within the tolerance
  };
  enum VectorModes
  {
    MAGNITUDE = 0, ///< fit the length of a vector array
    COMPONENTS = 1 ///< fit every component (one spline with as many components)
  };

  ///@{
  /// Polynomial degree per direction, 1 to 5. Default 2 2 2.
  vtkSetVector3Macro(Degree, int);
  vtkGetVector3Macro(Degree, int);
  ///@}

  ///@{
  /// Elements per direction of the initial tensor-product spline. Default 4 4 4.
  vtkSetVector3Macro(InitialNumberOfElements, int);
  vtkGetVector3Macro(InitialNumberOfElements, int);
  ///@}

  ///@{
  /// How the coefficients are updated on every level. Default LEAST_SQUARES.
  vtkSetClampMacro(Method, int, MBA, HYBRID);
  vtkGetMacro(Method, int);
  void SetMethodToMBA() { this->SetMethod(MBA); }
  void SetMethodToLeastSquares() { this->SetMethod(LEAST_SQUARES); }
  void SetMethodToHybrid() { this->SetMethod(HYBRID); }
  ///@}

  ///@{
  /// The tolerance. Default 0.02 (relative: 2 % of the data range).
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
  /// Which error the tolerance bounds. Default MAXIMUM_ERROR.
  vtkSetClampMacro(ToleranceType, int, MAXIMUM_ERROR, RMS_ERROR);
  vtkGetMacro(ToleranceType, int);
  void SetToleranceTypeToMaximum() { this->SetToleranceType(MAXIMUM_ERROR); }
  void SetToleranceTypeToRMS() { this->SetToleranceType(RMS_ERROR); }
  ///@}

  ///@{
  /// Vector arrays: the magnitude or every component. Default MAGNITUDE.
  vtkSetClampMacro(VectorMode, int, MAGNITUDE, COMPONENTS);
  vtkGetMacro(VectorMode, int);
  void SetVectorModeToMagnitude() { this->SetVectorMode(MAGNITUDE); }
  void SetVectorModeToComponents() { this->SetVectorMode(COMPONENTS); }
  ///@}

  ///@{
  /// Most halvings of an initial element side, 0 to 30 (more is refused). Default 10.
  vtkSetMacro(MaximumRefinementLevels, int);
  vtkGetMacro(MaximumRefinementLevels, int);
  ///@}

  ///@{
  /// Refinement stops when the spline has this many elements. Default 500000.
  vtkSetMacro(MaximumNumberOfElements, vtkIdType);
  vtkGetMacro(MaximumNumberOfElements, vtkIdType);
  ///@}

  ///@{
  /**
   * An element is split only when it holds at least this many data points
   * (finer functions would have no data to determine them). Default 2.
   */
  vtkSetClampMacro(MinimumPointsPerElement, vtkIdType, 1, VTK_ID_MAX);
  vtkGetMacro(MinimumPointsPerElement, vtkIdType);
  ///@}

  ///@{
  /// Each side of the data's bounding box is widened by Margin times its length. Default 0.
  vtkSetClampMacro(Margin, double, 0.0, 10.0);
  vtkGetMacro(Margin, double);
  ///@}

  ///@{
  /// Least squares: pull of functions with little data towards the previous fit. Default 0.1.
  vtkSetClampMacro(Regularization, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(Regularization, double);
  ///@}

  ///@{
  /// Output port 1 gets the data's boundary surface (default on).
  vtkSetMacro(ExtractBoundary, vtkTypeBool);
  vtkGetMacro(ExtractBoundary, vtkTypeBool);
  vtkBooleanMacro(ExtractBoundary, vtkTypeBool);
  ///@}

  ///@{
  /// Name of the output's point array; empty (default): the input array's name.
  vtkSetStringMacro(FieldName);
  vtkGetStringMacro(FieldName);
  ///@}

  ///@{
  /// If set, the fitted spline is also written to this .lr file.
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  ///@{
  /// Results of the last update.
  double GetMaximumError() const { return this->MaximumError; }
  double GetRMSError() const { return this->RMSError; }
  double GetAbsoluteTolerance() const { return this->AbsoluteTolerance; }
  bool GetToleranceMet() const { return this->ToleranceMet; }
  vtkIdType GetNumberOfElements() const { return this->NumberOfElements; }
  vtkIdType GetNumberOfBasisFunctions() const { return this->NumberOfBasisFunctions; }
  vtkIdType GetNumberOfDataPoints() const { return this->NumberOfDataPoints; }
  int GetNumberOfRefinementLevels() const { return this->NumberOfRefinementLevels; }
  int GetNumberOfIterations() const { return this->NumberOfIterations; }
  double GetFitTime() const { return this->FitTime; }
  /// The fitted domain (xmin, xmax, ymin, ymax, zmin, zmax).
  const double* GetDomain() const { return this->Domain; }
  ///@}

protected:
  vtkLRSplineFitter();
  ~vtkLRSplineFitter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  // Refuse bad settings (false with an error).
  bool CheckSettings();
  // The positions (3 per point) and values (dim per point) of every leaf.
  bool GatherData(const std::vector<vtkDataSet*>& leaves, std::vector<double>& positions,
    std::vector<double>& values, int& dim, std::string& fieldName);
  // The boundary surface of the leaves (output port 1).
  bool BuildBoundary(const std::vector<vtkDataSet*>& leaves, vtkPolyData* boundary);

  int Degree[3] = { 2, 2, 2 };
  int InitialNumberOfElements[3] = { 4, 4, 4 };
  int Method = LEAST_SQUARES;
  double Tolerance = 0.02;
  int ToleranceMode = RELATIVE_TOLERANCE;
  int ToleranceType = MAXIMUM_ERROR;
  int VectorMode = MAGNITUDE;
  int MaximumRefinementLevels = 10;
  vtkIdType MaximumNumberOfElements = 500000;
  vtkIdType MinimumPointsPerElement = 2;
  double Margin = 0.0;
  double Regularization = 0.1;
  vtkTypeBool ExtractBoundary = 1;
  char* FieldName = nullptr;
  char* FileName = nullptr;

  double MaximumError = 0.0;
  double RMSError = 0.0;
  double AbsoluteTolerance = 0.0;
  bool ToleranceMet = false;
  vtkIdType NumberOfElements = 0;
  vtkIdType NumberOfBasisFunctions = 0;
  vtkIdType NumberOfDataPoints = 0;
  int NumberOfRefinementLevels = 0;
  int NumberOfIterations = 0;
  double FitTime = 0.0;
  double Domain[6] = { 0, 0, 0, 0, 0, 0 };

private:
  vtkLRSplineFitter(const vtkLRSplineFitter&) = delete;
  void operator=(const vtkLRSplineFitter&) = delete;
};

#endif
