// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkIFEMBlockBuilder
 * @brief   Turns one patch of an IFEM basis and the fields on it into a VTK block: exact Bezier
 * cells in physical space for spline patches, Lagrange cells for Lagrange patches.
 *
 * Plain C++ (not a vtkObject), used by vtkIFEMReader (see docs/ifem.md).
 *
 * Spline patches (LRSplines text, GoTools g2) are parsed by vtkLRSplineParser
 * and told rational by vtkLRSplinePatch::ApplyRationalMode (their
 * coefficients are control points). The geometry x(u) is the patch's own
 * coefficients (nsd = Dimension, less the weight when rational; 1 to 3 and at
 * least the parametric dimension); the fields' nodal values f_i are
 * coefficients on the same basis. Geometry, weight and fields are extracted
 * together, in one pass (vtkLRSplinePatch::ExtractBezier with the combined
 * coefficients (w_i x_i, w_i, w_i f_i) for a rational basis, whose fields are
 * sum_i R_i f_i with the rational basis R_i = gamma_i B_i w_i / W), and
 * written by vtkLRSplineBezierGrid in geometry mode: the points are the
 * geometry's Bezier coefficients, the fields Bezier point data, rational
 * bases get VTK's RationalWeights. So VTK's interpolation of the cells IS
 * the simulation's geometry and fields.
 *
 * Field names (ArraysFor): a name made of "a&&b&&c" parts (IFEM's merged
 * fields) gives one scalar array per part (the first part's words before a
 * space prefix the others, as SISO does); a 1-component field one scalar
 * array; a 2- or 3-component field its components "<name>_x", "_y", "_z" and
 * the vector "<name>" (3 components, zero-padded); more components
 * "<name>_0", "<name>_1", .... Scalars "<X>_x", "<X>_y" (and "<X>_z" in 3D)
 * of one block are also combined into the vector "<X>" when no array has
 * that name (SISO's recombination). Element values (knotspan) become cell
 * data with the same names.
 *
 * GeometryDeviation() compares two spline patches' geometries exactly: on
 * every overlap of their elements both maps are (rational) polynomials of
 * known degrees, compared at enough points per direction (the sum of the
 * degrees plus one) to decide their identity.
 */

#ifndef vtkIFEMBlockBuilder_h
#define vtkIFEMBlockBuilder_h

#include "SplineVizIOModule.h" // for export macro
#include "vtkIFEMLagrangePatch.h"
#include "vtkLRSplineBezierGrid.h"
#include "vtkLRSplinePatch.h"
#include "vtkSmartPointer.h"

#include <string>
#include <vector>

class vtkUnstructuredGrid;

class SPLINEVIZIO_EXPORT vtkIFEMBlockBuilder
{
public:
  /// A field as written: its name and its values (all components, interleaved).
  struct Values
  {
    std::string Name;
    std::vector<double> Data;
  };

  /// One patch of a basis: a spline or a Lagrange patch.
  struct Patch
  {
    bool IsLagrange = false;
    vtkLRSplinePatch Spline;
    vtkIFEMLagrangePatch Lagrange;
    /// Spatial dimension (coordinates of the geometry).
    int SpatialDimension = 3;
    std::string Format;
    int GetParametricDimension() const
    {
      return this->IsLagrange ? this->Lagrange.ParametricDimension
                              : this->Spline.ParametricDimension;
    }
    /// Nodes (Lagrange) or basis functions (splines).
    vtkIdType GetNumberOfNodes() const;
    vtkIdType GetNumberOfElements() const;
  };

  /**
   * Parse the text of one patch (one patch per dataset). `warning` receives
   * the note of an inferred rational patch.
   */
  static bool ParsePatch(const std::string& text, int rationalMode, Patch& patch,
    std::string* error, std::string* warning);

  struct Options
  {
    bool MergePoints = true;
    /// The elements [FirstElement, LastElement) (a piece); LastElement < 0: all.
    vtkIdType FirstElement = 0;
    vtkIdType LastElement = -1;
    int PatchIndex = 0;
  };

  /**
   * The block of `patch` with `fields` (nodal values: a positive multiple of
   * the number of nodes) as point data and `knotspans` (a positive multiple of
   * the number of elements) as cell data. Null with a message on a size
   * mismatch. Field values that are not finite (simulations write NaN for
   * undefined values) are kept, with a note in `warning`; geometry that is not
   * finite is refused by the parser.
   */
  static vtkSmartPointer<vtkUnstructuredGrid> Build(const Patch& patch,
    const std::vector<Values>& fields, const std::vector<Values>& knotspans, const Options& options,
    std::string* error, std::string* warning);

  /// The arrays (components relative to the field) of a field with `components` components.
  static std::vector<vtkLRSplineBezierGrid::Options::PointArray> ArraysFor(
    const std::string& name, int components);

  /**
   * Add the vectors "<X>" (3 components, zero-padded) of scalar arrays
   * "<X>_x", "<X>_y" (, "<X>_z" when present) where no array is named "<X>".
   */
  static void AddRecombinedVectors(std::vector<vtkLRSplineBezierGrid::Options::PointArray>& arrays);

  /**
   * The largest distance between the geometries of two spline patches over
   * their common parameter domain (exact, see the class documentation).
   * Infinity when their domains or spatial dimensions differ.
   */
  static bool GeometryDeviation(
    const Patch& a, const Patch& b, double& deviation, std::string* error);

private:
  static vtkSmartPointer<vtkUnstructuredGrid> BuildSpline(const Patch& patch,
    const std::vector<Values>& fields, const Options& options, std::string* error,
    std::string* warning);
  static vtkSmartPointer<vtkUnstructuredGrid> BuildLagrange(const Patch& patch,
    const std::vector<Values>& fields, const Options& options, std::string* error,
    std::string* warning);
  static bool AddCellValues(vtkUnstructuredGrid* grid, const std::vector<Values>& knotspans,
    vtkIdType numberOfElements, const std::vector<vtkIdType>& elementIds, std::string* error,
    std::string* warning);
};

#endif
// VTK-HeaderTest-Exclude: vtkIFEMBlockBuilder.h
