/**
 * @class   vtkLRSplineBezierGrid
 * @brief   The VTK form of one LR-spline patch: a vtkUnstructuredGrid of VTK_BEZIER_HEXAHEDRON
 * cells with the patch's cell and field data (the output format of vtkLRSplineReader).
 *
 * Plain C++ (not a vtkObject), the one place that writes this format; used by
 * vtkLRSplineReader (patches read from files) and vtkLRSplineImageFitter
 * (patches fitted to images), so that everything downstream (probe,
 * resampling, stream tracer, the volume mapper, ParaView) sees one format.
 *
 * Every LR element (or those of a piece [FirstElement, LastElement)) becomes
 * one Bezier hexahedron whose control points carry the element's exact
 * Bernstein coefficients (vtkLRSplinePatch::ExtractBezier, Fuchs et al.
 * §3.2.3). The grid has
 * - cells: degrees (p, q, r), at least 1 (a piecewise constant direction is
 *   written as linear);
 * - cell data: "HigherOrderDegrees" (set as the degrees array),
 *   "LRParameterBox", "LRElementId" (index of the element in its patch),
 *   "LRElementMinSide" (shortest side, in the units of the points);
 * - point data: the coefficients in an array named FieldName (the active
 *   vectors with 3 components, the active scalars with 1); in geometry mode
 *   also "LRParameterCoordinates";
 * - field data: "LRPatchIndex", "LRDegrees", "LRNumberOfBasisFunctions",
 *   "LRNumberOfElements", "LRNumberOfMeshRectangles", "LRRefinementLevels"
 *   (per direction, log2 of largest over smallest element side),
 *   "LRParameterDomain", "LRMode" (0 field, 1 geometry),
 *   "LRPhysicalTransform" (field mode: scale xyz, offset xyz with
 *   x = offset + scale * u) and "LRSourceFormat".
 *
 * Field mode places the control points at the equally spaced points of each
 * element's parameter box mapped by x = Offset + Scale * u (the Bezier form
 * of that affine map). Geometry mode uses the coefficients as control points
 * (2 or 3 components). MergePoints merges coincident control points with
 * equal coefficients.
 */

#ifndef vtkLRSplineBezierGrid_h
#define vtkLRSplineBezierGrid_h

#include "SplineVizModule.h" // for export macro
#include "vtkSmartPointer.h"
#include "vtkType.h"

#include <string>

class vtkLRSplineBezierVolume;
class vtkLRSplinePatch;
class vtkUnstructuredGrid;

class SPLINEVIZ_EXPORT vtkLRSplineBezierGrid
{
public:
  struct Options
  {
    /// Written as "LRPatchIndex".
    int PatchIndex = 0;
    /// The elements [FirstElement, LastElement) (a piece); LastElement < 0: all.
    vtkIdType FirstElement = 0;
    vtkIdType LastElement = -1;
    /// Coefficients are the control points (2 or 3 components).
    bool GeometryMode = false;
    bool MergePoints = true;
    /// Field mode: x = Offset + Scale * u per axis.
    double Scale[3] = { 1, 1, 1 };
    double Offset[3] = { 0, 0, 0 };
    /// Name of the point-data array of coefficients.
    std::string FieldName = "Field";
    /// Written as "LRSourceFormat" (e.g. "LRSplines text").
    std::string SourceFormat;
  };

  /**
   * Extract the Bezier form of the patch (its piece) and build the grid.
   * Null with a message in `error` when the patch is invalid (or geometry mode
   * does not fit its dimension); `warning` receives the partition-of-unity
   * note of ExtractBezier, if any.
   */
  static vtkSmartPointer<vtkUnstructuredGrid> Build(const vtkLRSplinePatch& patch,
    const Options& options, std::string* error, std::string* warning = nullptr);

  /**
   * The same from a Bezier form already extracted from `patch` for the
   * elements [FirstElement, LastElement) (it is elevated to at least linear
   * in place). The patch gives the metadata.
   */
  static vtkSmartPointer<vtkUnstructuredGrid> Build(const vtkLRSplinePatch& patch,
    vtkLRSplineBezierVolume& volume, const Options& options, std::string* error);
};

#endif
// VTK-HeaderTest-Exclude: vtkLRSplineBezierGrid.h
