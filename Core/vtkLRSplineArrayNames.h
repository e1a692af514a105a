// SPDX-License-Identifier: BSD-3-Clause
/**
 * The names of the arrays that carry an LR spline through a VTK pipeline
 * (Fuchs et al. §3.2.3: the Bezier blocks of an LR spline, one Bezier
 * cell per element): written by the readers and fitters, read by the field,
 * the geometry map and the volume mapper. Users see these names in ParaView's
 * spreadsheet and in Python; the class comments of vtkLRSplineReader,
 * vtkLRSplineImageFitter, vtkLRSplineFitter and vtkIFEMReader say what each
 * holds.
 *
 * Header-only, private to the module.
 */
#ifndef vtkLRSplineArrayNames_h
#define vtkLRSplineArrayNames_h

namespace vtkLRSplineArrayNames
{
///@{
/// Point data of the Bezier grid.
constexpr const char* ParameterCoordinates = "LRParameterCoordinates";
constexpr const char* RationalWeights = "RationalWeights"; // VTK's own name
///@}

///@{
/// Cell data of the Bezier grid: one tuple per LR element.
constexpr const char* ParameterBox = "LRParameterBox";
constexpr const char* ElementId = "LRElementId";
constexpr const char* ElementMinSide = "LRElementMinSide";
///@}

///@{
/// Field data describing the patch.
constexpr const char* PatchIndex = "LRPatchIndex";
constexpr const char* ParametricDimension = "LRParametricDimension";
constexpr const char* Degrees = "LRDegrees";
constexpr const char* NumberOfBasisFunctions = "LRNumberOfBasisFunctions";
constexpr const char* NumberOfElements = "LRNumberOfElements";
constexpr const char* NumberOfMeshRectangles = "LRNumberOfMeshRectangles";
constexpr const char* RefinementLevels = "LRRefinementLevels";
constexpr const char* ParameterDomain = "LRParameterDomain";
constexpr const char* Mode = "LRMode"; // 1: geometry (points are control points), 0: field
constexpr const char* Rational = "LRRational";
constexpr const char* PhysicalTransform = "LRPhysicalTransform";
constexpr const char* SourceFormat = "LRSourceFormat";
///@}

///@{
/// Field data of IFEM results whose geometry and field bases differ.
constexpr const char* GeometryReferenceBasis = "LRGeometryReferenceBasis";
constexpr const char* GeometryDeviation = "LRGeometryDeviation";
///@}

///@{
/// Field data of a fit (vtkLRSplineImageFitter, vtkLRSplineFitter); the
/// per-element error is cell data.
constexpr const char* FitMaximumError = "LRFitMaximumError";
constexpr const char* FitRMSError = "LRFitRMSError";
constexpr const char* FitTolerance = "LRFitTolerance";
constexpr const char* FitToleranceMet = "LRFitToleranceMet";
constexpr const char* FitIterations = "LRFitIterations";
constexpr const char* FitRefinementLevels = "LRFitRefinementLevels";
constexpr const char* FitDataRange = "LRFitDataRange";
constexpr const char* FitHistory = "LRFitHistory";
constexpr const char* FitSeconds = "LRFitSeconds";
constexpr const char* FitDomain = "LRFitDomain";
constexpr const char* FitReusedPreviousMesh = "LRFitReusedPreviousMesh";
constexpr const char* FitDataPoints = "LRFitDataPoints";
constexpr const char* FitElementMaxError = "LRFitElementMaxError";
/// vtkLRSplineFitter with RemoveOutliers: the number of data points left out
/// (field data), and on its outlier output, each one's deviation from its
/// neighbours in units of max(local spread, tolerance) (point data).
constexpr const char* FitOutliers = "LRFitOutliers";
constexpr const char* FitOutlierDeviation = "LRFitOutlierDeviation";
///@}
}

#endif
