// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkSplineTubeCore
 * @brief   CPU side of the spline tubes: the tubes of polylines, their nodes' splines,
 * chunks for culling and the compact GPU layout, without copying the points.
 *
 * The shared "tube core" of the line mappers (Salm, "Interactive Rendering of
 * Spline Tubes", §3 'Commonalities and terminology'). From the polylines of
 * one or more vtkPolyData it makes, once per data change:
 *
 * - the tube table: per tube (a valid polyline) its first node, block and
 *   cell; a node is a point after repeated consecutive points are merged.
 *   Nodes are read from the inputs when needed (no copy of the points). Node
 *   derivatives (svNodeDerivative(): central differences inside, second-order
 *   one-sided at the ends) make the cubic Hermite splines C1 and reproduce
 *   lines and parabolas, the same on the CPU and in the shaders;
 * - chunks: runs of at most ChunkSegments segments with a bounding sphere of
 *   everything drawn for them and a sphere per segment, the units of the
 *   per-view work (vtkSplineTubeVisibility, levels of detail);
 * - the GPU layout, filled range by range for uploads in pieces: FillNodes()
 *   (position and radius, 16 bytes, or the position alone, 12 bytes, when
 *   every node has the same radius: GetConstantRadius()), FillNodeInfo()
 *   (tube and end flags, 4 bytes), FillColors() (RGBA8), FillFrames() (the
 *   rotation-minimizing frames of Salm §3.1, double reflection of Wang et al.
 *   2008, sub-stepped beyond MaximumFrameStepAngle; octahedral int16 x 2).
 *
 * Segment s (numbered tube by tube) runs from node GetSegmentFirstNode(s) to
 * the next.
 *
 * Bad input is reported, never drawn as garbage: polylines with a non-finite
 * coordinate, or a non-finite or non-positive radius (or node scalar), are
 * skipped with a warning naming the cell and point; repeated points are
 * merged (one warning); polylines with fewer than two distinct points are
 * skipped. A missing, non-numeric or multi-component radius (or node scalar)
 * array is an error (AddPolyData() returns false and adds nothing).
 */

#ifndef vtkSplineTubeCore_h
#define vtkSplineTubeCore_h

#include "SplineVizRenderingModule.h" // for export macro
#include "vtkNew.h"                   // for vtkNew
#include "vtkObject.h"

#include <functional> // for std::function
#include <memory>     // for std::unique_ptr

class vtkDataArray;
class vtkFloatArray;
class vtkIdTypeArray;
class vtkPolyData;
class vtkTypeUInt32Array;
class vtkUnsignedCharArray;

class SPLINEVIZRENDERING_EXPORT vtkSplineTubeCore : public vtkObject
{
public:
  static vtkSplineTubeCore* New();
  vtkTypeMacro(vtkSplineTubeCore, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Bits of the segment flags.
  enum SegmentFlagBits
  {
    TUBE_START = 1, ///< first segment of its tube: the start cap is drawn
    TUBE_END = 2    ///< last segment of its tube: the end cap is drawn
  };

  /// Bits of the node info words of FillNodes() (the rest: the tube).
  static constexpr unsigned int NODE_FIRST = 0x40000000u;
  static constexpr unsigned int NODE_LAST = 0x80000000u;
  static constexpr unsigned int NODE_TUBE_MASK = 0x3FFFFFFFu;

  /// The longest chunk, in segments.
  static constexpr int ChunkSegments = 8;

  ///@{
  /// Radius in world units used when no radius array is set. Default 0.01.
  vtkSetClampMacro(Radius, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(Radius, double);
  ///@}

  ///@{
  /**
   * Name of a one-component point array giving the radius in world units
   * (multiplied by RadiusScale). nullptr (default): the constant Radius.
   */
  vtkSetStringMacro(RadiusArray);
  vtkGetStringMacro(RadiusArray);
  ///@}

  ///@{
  /// Factor applied to the radius array's values. Default 1.
  vtkSetClampMacro(RadiusScale, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(RadiusScale, double);
  ///@}

  ///@{
  /**
   * Name of a one-component point array whose values the nodes carry
   * (GetNodeScalar()). nullptr (default): none.
   */
  vtkSetStringMacro(NodeScalarArray);
  vtkGetStringMacro(NodeScalarArray);
  ///@}

  ///@{
  /**
   * Name of an integer cell array of original cell ids (ParaView's
   * "vtkOriginalCellIds"): when a block has it, the tubes' cell ids (what
   * picking reports) are its values instead of the cell's index in the block.
   * nullptr (default): the index.
   */
  vtkSetStringMacro(CellIdArray);
  vtkGetStringMacro(CellIdArray);
  ///@}

  ///@{
  /**
   * Deprecated: use SetRadiusArray, SetNodeScalarArray, SetCellIdArray (and
   * their Get methods), the names the mappers use; kept for one release.
   */
  void SetRadiusArrayName(const char* name) { this->SetRadiusArray(name); }
  char* GetRadiusArrayName() { return this->GetRadiusArray(); }
  void SetNodeScalarArrayName(const char* name) { this->SetNodeScalarArray(name); }
  char* GetNodeScalarArrayName() { return this->GetNodeScalarArray(); }
  void SetCellIdArrayName(const char* name) { this->SetCellIdArray(name); }
  char* GetCellIdArrayName() { return this->GetCellIdArray(); }
  ///@}

  ///@{
  /// What the node scalars are, for messages ("The <role> array ..."). Default "node scalar".
  vtkSetStringMacro(NodeScalarRole);
  vtkGetStringMacro(NodeScalarRole);
  ///@}

  ///@{
  /**
   * Largest angle (radians) the tangent may turn between two steps of the
   * frame propagation (FillFrames()); longer turns are sub-divided. Default 0.1.
   */
  vtkSetClampMacro(MaximumFrameStepAngle, double, 1e-3, 1.5);
  vtkGetMacro(MaximumFrameStepAngle, double);
  ///@}

  ///@{
  /**
   * Whether Build() makes the chunk table (GetChunkSpheres() and the rest),
   * which the ray-cast and tessellated tubes cull and draw by. Off, Build()
   * computes the bounds only and the table is empty: the stylized lines cull
   * their own batches, and the table is 36 bytes per chunk and 4 per segment
   * (200 MB for a whole-brain tractogram of 25 M segments) plus the time to
   * make it. Default on.
   */
  vtkSetMacro(ChunkTables, bool);
  vtkGetMacro(ChunkTables, bool);
  vtkBooleanMacro(ChunkTables, bool);
  ///@}

  /// Forget all tubes and inputs (the settings are kept).
  void Initialize();

  /**
   * Add the polylines (VTK_LINE and VTK_POLY_LINE cells of the line array) of
   * `input` as tubes; the core keeps a reference to `input` (and `colors`).
   * `colors`, if given, holds one RGBA color (4 unsigned char components, as
   * made by vtkScalarsToColors::MapScalars) per point of `input`, or per cell
   * when `colorsPerCell` is true; without colors every node is white.
   * `blockId` is stored with every tube (the flat index of the block of a
   * composite data set). Returns false, with an error, when the input cannot
   * be used at all. Call Build() after the last AddPolyData().
   */
  bool AddPolyData(vtkPolyData* input, vtkUnsignedCharArray* colors, unsigned int blockId = 0,
    bool colorsPerCell = false);

  /// Make the chunks and the bounds (in parallel over tubes). Call once after the AddPolyData()s.
  void Build();

  ///@{
  /// Counts of what was built.
  vtkIdType GetNumberOfTubes() const;
  vtkIdType GetNumberOfNodes() const;
  vtkIdType GetNumberOfSegments() const;
  vtkIdType GetNumberOfChunks() const;
  ///@}

  ///@{
  /**
   * The tube table: first node, number of nodes, the polyline's cell id in
   * its input (or its original id, see CellIdArray) and block; the tube
   * of a node, the first segment of a tube.
   */
  vtkIdType GetTubeFirstNode(vtkIdType tube) const;
  vtkIdType GetTubeNumberOfNodes(vtkIdType tube) const;
  vtkIdType GetTubeCellId(vtkIdType tube) const;
  /// The polyline's index among the cells of its input (never the original id).
  vtkIdType GetTubeCellIndex(vtkIdType tube) const;
  unsigned int GetTubeBlockId(vtkIdType tube) const;
  vtkIdType GetTubeOfNode(vtkIdType node) const;
  vtkIdType GetTubeFirstSegment(vtkIdType tube) const
  {
    return this->GetTubeFirstNode(tube) - tube;
  }
  ///@}

  ///@{
  /**
   * A node's position and radius (x, y, z, r; the input's coordinates), their
   * derivatives along the tube (see the class comment), its color (RGBA in
   * [0, 1], white without colors) and scalar (0 without NodeScalarArray).
   */
  void GetNode(vtkIdType node, double xyzr[4]) const;
  /// Node k of a tube (0 its first): the same as GetNode() without finding the tube.
  void GetTubeNode(vtkIdType tube, vtkIdType k, double xyzr[4]) const;
  void GetNodeDerivative(vtkIdType node, double dxyzr[4]) const;
  void GetNodeColor(vtkIdType node, double rgba[4]) const;
  double GetNodeScalar(vtkIdType node) const;
  ///@}

  /**
   * Positions and radii (4 doubles each) and their derivatives of the `count`
   * nodes of tube `tube` from its node `first` (either output may be
   * nullptr): the fast way to read runs of nodes.
   */
  void GetTubeNodes(
    vtkIdType tube, vtkIdType first, vtkIdType count, double* xyzr, double* dxyzr) const;

  ///@{
  /// Segment s: its first node (the second is the next), its flags (SegmentFlagBits).
  vtkIdType GetSegmentFirstNode(vtkIdType segment) const;
  int GetSegmentFlags(vtkIdType segment) const;
  ///@}

  /**
   * Evaluate the cubic Hermite position spline of segment `segment` at
   * parameter t in [0, 1]: position, derivative, radius and radius derivative
   * (any output pointer may be nullptr).
   */
  void EvaluateSegment(vtkIdType segment, double t, double position[3], double derivative[3],
    double* radius, double* radiusDerivative) const;

  ///@{
  /**
   * The GPU layout of the nodes [first, first + count), in parallel:
   * FillNodes: `components` floats per node: 4 (position minus `shift`,
   * radius) or 3 (position minus `shift` only, for a constant radius);
   * FillNodeInfo: one word per node (its tube | NODE_FIRST | NODE_LAST, the
   * first and last node of the tube); FillColors: RGBA8 in one
   * word (red lowest); FillScalars: the node scalar; FillFrames: the unit
   * orthogonal vector of the rotation-minimizing frame, octahedral, 2 int16
   * (frames propagate along whole tubes: for a range cutting a tube, its
   * nodes before `first` are propagated but not written).
   */
  void FillNodes(
    vtkIdType first, vtkIdType count, const double shift[3], float* out, int components = 4) const;
  void FillNodeInfo(vtkIdType first, vtkIdType count, unsigned int* info) const;
  void FillColors(vtkIdType first, vtkIdType count, unsigned int* rgba) const;
  void FillScalars(vtkIdType first, vtkIdType count, float* scalars) const;
  void FillFrames(vtkIdType first, vtkIdType count, short* octahedral) const;
  ///@}

  /// The frames (unit orthogonal vectors, 3 doubles per node) of a tube, before encoding.
  void GetTubeFrames(vtkIdType tube, double* frames) const;

  ///@{
  /**
   * Chunk table (made by Build() when ChunkTables is on): per chunk its first segment (one more
   * tuple than chunks: the last is the number of segments), its tube, its
   * bounding sphere (x, y, z relative to GetCenter(), radius) and its sizes
   * (the length of its segments' Bezier control polygons, the longest such
   * polygon of one of its segments, its largest radius); per tube its first
   * chunk (one more tuple); per segment its sphere relative to its chunk's
   * (vtkSplineTubeVisibility::EncodePart); per chunk how straight its
   * segments are, for the ray-cast tubes' choice of a program per view: the
   * largest svSegmentStraightness() of its segments and the largest ratio of
   * it to the segment's smallest radius, then the same for the two quadratic
   * sub-segments of each segment (svSubSegmentStraightness(); ratios
   * VTK_FLOAT_MAX where a radius is not positive). Chunks of a tube are
   * consecutive.
   */
  vtkTypeUInt32Array* GetChunkFirstSegments() { return this->ChunkFirstSegments; }
  vtkTypeUInt32Array* GetChunkTubes() { return this->ChunkTubes; }
  vtkFloatArray* GetChunkSpheres() { return this->ChunkSpheres; }
  vtkFloatArray* GetChunkSizes() { return this->ChunkSizes; }
  vtkIdTypeArray* GetTubeFirstChunks() { return this->TubeFirstChunks; }
  vtkTypeUInt32Array* GetSegmentSpheres() { return this->SegmentSpheres; }
  vtkFloatArray* GetChunkStraightness() { return this->ChunkStraightness; }
  ///@}

  /**
   * The centre of the box of the tubes' nodes, known once AddPolyData() has
   * run: the origin of the chunk spheres and of the positions the mappers
   * upload (FillNodes() `shift`), so that floats keep their precision.
   */
  void GetCenter(double center[3]) const;

  /// True when colors were given for every piece added.
  bool HasColors() const { return this->ColorsGiven && !this->ColorsMissing; }

  /**
   * True when every node has the same radius: no piece took its radii from
   * RadiusArray and all pieces were added with the same Radius, which
   * `radius` receives. The GPU layout may then leave the radius out
   * (FillNodes() with 3 components): 4 bytes per node less.
   */
  bool GetConstantRadius(double& radius) const;

  /// True when the nodes carry scalars (NodeScalarArray was found).
  bool HasNodeScalars() const;

  /**
   * Bounds of the tubes' surfaces (the convex hulls of the cubic segments'
   * Bezier control points, padded by the largest radius of each segment),
   * made by Build(). Uninitialized bounds when there are no tubes.
   */
  void GetBounds(double bounds[6]) const;

  /// Largest radius over all nodes (0 without tubes).
  double GetMaximumRadius() const { return this->MaximumRadius; }

  /// Largest cell id of the tubes (what picking may report).
  vtkIdType GetMaximumCellId() const { return this->MaximumCellId; }

  ///@{
  /// What the last AddPolyData() calls skipped or merged (since Initialize()).
  vtkGetMacro(NumberOfSkippedLines, vtkIdType);
  vtkGetMacro(NumberOfMergedPoints, vtkIdType);
  ///@}

  /// Bytes the core holds (tube and chunk tables; not the inputs).
  size_t GetMemorySize() const;

protected:
  vtkSplineTubeCore();
  ~vtkSplineTubeCore() override;

  double Radius = 0.01;
  char* RadiusArray = nullptr;
  double RadiusScale = 1.0;
  char* NodeScalarArray = nullptr;
  char* NodeScalarRole = nullptr;
  char* CellIdArray = nullptr;
  double MaximumFrameStepAngle = 0.1;
  bool ChunkTables = true;

  vtkNew<vtkIdTypeArray> TubeFirstChunks;
  vtkNew<vtkTypeUInt32Array> ChunkFirstSegments;
  vtkNew<vtkTypeUInt32Array> ChunkTubes;
  vtkNew<vtkFloatArray> ChunkSpheres;
  vtkNew<vtkFloatArray> ChunkSizes;
  vtkNew<vtkTypeUInt32Array> SegmentSpheres;
  vtkNew<vtkFloatArray> ChunkStraightness;
  double Bounds[6] = { 1.0, -1.0, 1.0, -1.0, 1.0, -1.0 };
  double NodeBounds[6] = { 1.0, -1.0, 1.0, -1.0, 1.0, -1.0 }; ///< of the tubes' nodes

  bool ColorsGiven = false;
  bool ColorsMissing = false;
  double MaximumRadius = 0.0;
  vtkIdType MaximumCellId = 0;
  vtkIdType NumberOfSkippedLines = 0;
  vtkIdType NumberOfMergedPoints = 0;

private:
  vtkSplineTubeCore(const vtkSplineTubeCore&) = delete;
  void operator=(const vtkSplineTubeCore&) = delete;

  /// The named one-component numeric point array (nullptr without a name); false after an error.
  bool FindPointArray(vtkPolyData* input, const char* name, const char* what, vtkDataArray*& array);
  /// The input's original cell ids (CellIdArray: one integer component per cell), or nullptr.
  vtkDataArray* FindOriginalIds(vtkPolyData* input) const;
  /// The chunk table, the bounds and the centre.
  void BuildChunks();
  /// The bounds and the centre only (ChunkTables off); the chunk table emptied.
  void BuildBounds();
  /// The rotation-minimizing frames of tube t's first n nodes (at least 2), node by node.
  void PropagateFrames(vtkIdType t, vtkIdType n,
    const std::function<void(vtkIdType k, const double frame[3])>& write) const;

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
