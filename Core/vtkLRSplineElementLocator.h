// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkLRSplineElementLocator
 * @brief   Finds the LR-spline element (axis-aligned box) containing a parameter point: k-d forest,
 * k-d tree, octree, lookup texture or linear search.
 *
 * Plain C++ (not a vtkObject). The element search of Fuchs et al., "Direct
 * interactive visualization of locally refined spline volumes", §3.2:
 *
 * - KD_FOREST (§3.2.1, Algorithm 1): the domain is divided into I x J x K
 *   regular blocks; each block holds a depth-balanced k-d tree over the
 *   elements that intersect it (splits chosen by counting the elements on
 *   either side of each candidate element boundary); a block meeting one
 *   element stores it directly. Works for any knot values.
 * - KD_TREE: one such tree over the whole domain (the forest with 1 block).
 * - OCTREE (§3.2.2): dyadic knots only (every element boundary at domain_min
 *   + k (domain_max - domain_min) / 2^l); regions are halved until each meets
 *   one element. Build() fails for other knots.
 * - TEXTURE: the lookup texture of §3.2 for dyadic knots (the forest whose
 *   blocks are the finest dyadic cells, O(1)); Build() fails for other knots
 *   or beyond 2048 cells per direction or 2^27 cells.
 * - LINEAR: a scan over all elements (the reference).
 *
 * All return the same element: elements are half-open boxes [lo, hi) except
 * at the domain's upper faces, which belong to the elements touching them.
 * Points outside the domain (or in a hole of an invalid mesh) give -1. The
 * structures are flat arrays that go to a GPU unchanged (GetHeads() and the
 * other accessors, whose comment gives the layout). Thread-safe for lookups
 * (const) after Build().
 */

#ifndef vtkLRSplineElementLocator_h
#define vtkLRSplineElementLocator_h

#include "SplineVizCoreModule.h" // for export macro
#include "vtkType.h"

#include <cstdint>
#include <string>
#include <vector>

class SPLINEVIZCORE_EXPORT vtkLRSplineElementLocator
{
public:
  enum LocatorType
  {
    LINEAR = 0,
    KD_TREE = 1,
    KD_FOREST = 2,
    OCTREE = 3,
    TEXTURE = 4
  };
  static const char* GetTypeName(int type);

  static constexpr std::uint32_t LeafBit = 0x80000000u;
  static constexpr std::uint32_t ElementMask = 0x7FFFFFFFu;
  static constexpr std::uint32_t NoElement = 0xFFFFFFFFu;
  static constexpr std::uint32_t ChildMask = 0x1FFFFFFFu;

  /**
   * Boxes that may overlap (default off): the bounding boxes of curved
   * elements in physical space. Then the k-d trees end in list leaves where
   * no split separates the boxes (a node word with direction bits 3 and the
   * count in bits 0-28, followed by that many leaf words), boxes are closed,
   * and FindCandidates() gives every box containing a point (FindElement()
   * the first). Only LINEAR, KD_TREE and KD_FOREST. Set before Build().
   */
  void SetAllowOverlap(bool overlap) { this->AllowOverlap = overlap; }
  bool GetAllowOverlap() const { return this->AllowOverlap; }

  /**
   * Build over n element boxes (6 doubles each: lo xyz, hi xyz; copied).
   * `blocks` is the forest resolution I, J, K (KD_FOREST only; null: 8^3).
   * Returns false with a message when the type is not applicable (OCTREE and
   * TEXTURE with non-dyadic knots) or the input is invalid.
   */
  bool Build(const double* boxes, vtkIdType n, int type, const int blocks[3], std::string* error);

  int GetType() const { return this->Type; }
  vtkIdType GetNumberOfElements() const { return static_cast<vtkIdType>(this->Boxes.size() / 6); }
  const double* GetDomain() const { return this->Domain; }
  const double* GetBox(vtkIdType e) const { return this->Boxes.data() + 6 * e; }

  /// Element containing p, or -1. `depth` (may be null) receives the number of inner tree nodes
  /// visited.
  vtkIdType FindElement(const double p[3], int* depth = nullptr) const;

  /// Every element whose box contains p (sorted within a leaf; see SetAllowOverlap).
  void FindCandidates(const double p[3], std::vector<vtkIdType>& out) const;

  /// True when element e contains p (half-open, closed at the domain's upper faces).
  bool Contains(vtkIdType e, const double p[3]) const;

  /**
   * All elements whose box meets the OPEN box (lo, hi), sorted, without
   * duplicates. For KD_TREE and KD_FOREST a tree traversal, otherwise a scan.
   */
  void FindElementsIntersecting(const double box[6], std::vector<vtkIdType>& out) const;

  ///@{
  /**
   * The flat arrays, uploadable to a GPU unchanged (Algorithm 1's layout):
   * - Heads: uint32 per block (i fastest, then j, then k). Bit 31 set: a leaf,
   *   bits 0-30 the element (0x7FFFFFFF: no element); otherwise the index of
   *   the block tree's root node.
   * - NodeWords: uint32 per node. Bit 31 set: a leaf, bits 0-30 the element.
   *   Otherwise bits 29-30 the split direction (0, 1, 2) and bits 0-28 the
   *   index of the LEFT child (points with p[dir] < split); the right child
   *   is the next node (index + 1).
   * - NodeSplits: double per node (the split value; GetNodeSplitsFloat()
   *   gives a float copy for a RG32F texture buffer).
   * - BlockEdges[d]: I+1 (J+1, K+1) block boundaries; the block of p is found
   *   exactly against these values.
   * - OctreeNodes: uint32 per node; bit 31 set: leaf (element in bits 0-30),
   *   else the index of the first of 8 children (child = x>=mid | y>=mid<<1 |
   *   z>=mid<<2, mid the midpoint of the node's region).
   */
  const int* GetNumberOfBlocks() const { return this->Blocks; }
  const std::vector<double>& GetBlockEdges(int d) const { return this->Edges[d]; }
  const std::vector<std::uint32_t>& GetHeads() const { return this->Heads; }
  const std::vector<std::uint32_t>& GetNodeWords() const { return this->NodeWords; }
  const std::vector<double>& GetNodeSplits() const { return this->NodeSplits; }
  std::vector<float> GetNodeSplitsFloat() const;
  const std::vector<std::uint32_t>& GetOctreeNodes() const { return this->OctreeNodes; }
  ///@}

  /// Depth statistics over blocks (forest/tree/texture: tree depth per block,
  /// 0 for a direct leaf; octree: leaf depths), as in the paper's tables.
  struct Statistics
  {
    int MinDepth = 0;
    int MaxDepth = 0;
    double MeanDepth = 0.0;
    double VarianceDepth = 0.0;
    vtkIdType NumberOfNodes = 0;
    vtkIdType NumberOfBlocks = 0;
    vtkIdType NumberOfLeafBlocks = 0; ///< blocks that store their element directly
    std::size_t MemoryBytes = 0;      ///< size of the flat arrays
  };
  const Statistics& GetStatistics() const { return this->Stats; }

  /**
   * Finest dyadic level per direction of the element boundaries relative to
   * the domain (every boundary at lo + k (hi - lo) / 2^level); false when some
   * boundary is not dyadic up to level 30.
   */
  static bool ComputeDyadicLevels(
    const double* boxes, vtkIdType n, const double domain[6], int levels[3]);

private:
  bool BuildForest(const int blocks[3], std::string* error);
  bool BuildOctree(std::string* error);
  vtkIdType BlockIndex(int d, double x) const;

  int Type = LINEAR;
  bool AllowOverlap = false;
  std::vector<double> Boxes;
  double Domain[6] = { 0, 0, 0, 0, 0, 0 };
  int Blocks[3] = { 0, 0, 0 };
  double InvBlockWidth[3] = { 0, 0, 0 };
  std::vector<double> Edges[3];
  std::vector<std::uint32_t> Heads;
  std::vector<std::uint32_t> NodeWords;
  std::vector<double> NodeSplits;
  std::vector<std::uint32_t> OctreeNodes;
  Statistics Stats;
};

#endif
// VTK-HeaderTest-Exclude: vtkLRSplineElementLocator.h
