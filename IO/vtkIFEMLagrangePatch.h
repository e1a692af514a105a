// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkIFEMLagrangePatch
 * @brief   An IFEM Lagrange patch ("# LAGRANGIAN" text of its HDF5 results) and its VTK grid
 * of Lagrange cells.
 *
 * Plain C++ (not a vtkObject), used by vtkIFEMReader. IFEM writes a
 * Lagrange patch (ASMbase::writeLagBasis) as
 *
 *   # LAGRANGIAN nodes=N elements=M type=T
 *   x y z                     (N lines, the nodes)
 *   n_0 n_1 ... n_k           (M lines, each element's nodes, 0-based)
 *
 * with T one of hexahedron, quad, triangle, line. The nodes of a hexahedron
 * or quadrilateral of degree p are the (p+1)^3 or (p+1)^2 points of a
 * tensor grid, numbered with the first direction fastest; they become
 * VTK_LAGRANGE_HEXAHEDRON / VTK_LAGRANGE_QUADRILATERAL cells (degree from the
 * node count, at most 10), triangles (3 nodes) VTK_TRIANGLE and lines
 * (2 or more nodes along the line) VTK_LAGRANGE_CURVE. Counts are checked
 * against the text's length before allocating; node indices, the node count
 * per element and finite coordinates are checked.
 */

#ifndef vtkIFEMLagrangePatch_h
#define vtkIFEMLagrangePatch_h

#include "SplineVizIOModule.h" // for export macro
#include "vtkSmartPointer.h"
#include "vtkType.h"

#include <string>
#include <vector>

class vtkUnstructuredGrid;

class SPLINEVIZIO_EXPORT vtkIFEMLagrangePatch
{
public:
  /// 3 coordinates per node.
  std::vector<double> Nodes;
  /// NodesPerElement node indices per element (IFEM's order).
  std::vector<vtkIdType> Elements;
  int NodesPerElement = 0;
  /// The VTK cell type and the degree per direction.
  int CellType = 0;
  int Degree = 1;
  int ParametricDimension = 3;
  std::string TypeName;

  vtkIdType GetNumberOfNodes() const { return static_cast<vtkIdType>(this->Nodes.size() / 3); }
  vtkIdType GetNumberOfElements() const
  {
    return this->NodesPerElement > 0
      ? static_cast<vtkIdType>(this->Elements.size() / this->NodesPerElement)
      : 0;
  }

  /// Parse the patch text. False with a message (naming the line) on error.
  bool Parse(const std::string& text, std::string* error);

  /**
   * The grid of the elements [first, last) with only the nodes they use;
   * `nodeIds` receives, per grid point, the node it is (to pick nodal field
   * values), `elementIds` per cell the element.
   */
  vtkSmartPointer<vtkUnstructuredGrid> BuildGrid(vtkIdType first, vtkIdType last,
    std::vector<vtkIdType>& nodeIds, std::vector<vtkIdType>& elementIds) const;
};

#endif
// VTK-HeaderTest-Exclude: vtkIFEMLagrangePatch.h
