// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkLRSplineBezierGrid
 * @brief   The VTK form of one LR-spline patch: a vtkUnstructuredGrid of VTK_BEZIER_HEXAHEDRON
 * (volumes) or VTK_BEZIER_QUADRILATERAL (surfaces) cells with the patch's cell and field data
 * (the output format of vtkLRSplineReader and vtkIFEMReader).
 *
 * Plain C++ (not a vtkObject), the one place that writes this format, used
 * by vtkLRSplineReader, vtkIFEMReader and vtkLRSplineImageFitter, so that
 * everything downstream (probe, resampling, stream tracer, volume mapper,
 * ParaView) sees one format. Every LR element (or those of a piece
 * [FirstElement, LastElement)) becomes one Bezier cell whose control points
 * carry the element's exact Bernstein coefficients
 * (vtkLRSplinePatch::ExtractBezier, Fuchs et al. §3.2.3). The grid has
 * - cells of degrees (p, q, r), at least 1 (a surface's third degree is 0);
 * - cell data "HigherOrderDegrees", "LRParameterBox" (6 values),
 *   "LRElementId" (the element's index in its patch), "LRElementMinSide"
 *   (its shortest parameter side, times the field-mode scale);
 * - point data: the coefficients in an array named FieldName (or the arrays
 *   of PointArrays); in geometry mode also "LRParameterCoordinates" (the
 *   parameter map's coefficients) and, when rational, "RationalWeights";
 * - field data "LRPatchIndex", "LRParametricDimension", "LRDegrees",
 *   "LRNumberOfBasisFunctions", "LRNumberOfElements",
 *   "LRNumberOfMeshRectangles", "LRRefinementLevels", "LRParameterDomain",
 *   "LRMode" (0 field, 1 geometry), "LRRational", "LRPhysicalTransform"
 *   (field mode: scale xyz, offset xyz, x = offset + scale * u) and
 *   "LRSourceFormat".
 *
 * Field mode places the control points at the equally spaced points of each
 * element's parameter box mapped by x = Offset + Scale * u. Geometry mode
 * takes them from the coefficients (PointComponents, or the first 2 or 3
 * components); rational coefficients must have been made rational Bezier
 * ones first (vtkLRSplineBezierVolume::Dehomogenize; WeightComponent).
 * MergePoints merges coincident control points with equal coefficients.
 */

#ifndef vtkLRSplineBezierGrid_h
#define vtkLRSplineBezierGrid_h

#include "SplineVizCoreModule.h" // for export macro
#include "vtkSmartPointer.h"
#include "vtkType.h"

#include <string>
#include <vector>

class vtkLRSplineBezierVolume;
class vtkLRSplinePatch;
class vtkUnstructuredGrid;

class SPLINEVIZCORE_EXPORT vtkLRSplineBezierGrid
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

    /// A point-data array made of chosen coefficient components.
    struct PointArray
    {
      std::string Name;
      /// The coefficient components, in order.
      std::vector<int> Components;
      /// Components of the array (more than Components: zeros); 0: as many.
      int NumberOfComponents = 0;
      /// Make it the active scalars (1) or vectors (3); 0: neither.
      int Active = 0;
    };
    /// The point arrays; empty: one array FieldName with every component.
    std::vector<PointArray> PointArrays;
    /// Geometry mode: the component of x, y and z (-1: 0). All -1: the first
    /// 2 or 3 components (then the patch must have 2 or 3).
    int PointComponents[3] = { -1, -1, -1 };
    /// Geometry mode, rational: the component holding the Bezier weight.
    int WeightComponent = -1;
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
