/**
 * @class   vtkSplineTubeCore
 * @brief   CPU preparation of spline tubes: node data, frames and the segment table.
 *
 * The shared "tube core" of the tube mappers (Salm, "Interactive Rendering of
 * Spline Tubes", §3 'Commonalities and terminology'). From the polylines of
 * one or more vtkPolyData it builds, once per data change:
 *
 * - per node (a point of a polyline, after merging repeated points):
 *   position, tangent, radius and its derivative, color (RGBA in [0, 1]) and
 *   its derivative — the values and derivatives of cubic Hermite splines
 *   through the nodes, with the nodes at successive integer values of the
 *   curve parameter (Salm's equidistant-node assumption);
 * - per node, a unit vector orthogonal to the tangent ("orthogonal vector" of
 *   Salm §3.1) propagated along each tube as a **rotation-minimizing frame**;
 * - a segment table (segment i spans nodes first[i] and first[i] + 1, flags for
 *   the first and last segment of a tube, the polyline's cell id and block),
 *   so that one instanced draw renders every segment of every tube without
 *   dummy segments (Salm Fig. 3, the "tubes buffer").
 *
 * Tangents are Catmull-Rom tangents (central differences of the neighbouring
 * nodes, m_i = (p_{i+1} - p_{i-1}) / 2) inside a tube and second-order one-sided
 * differences at its ends (m_0 = (-3 p_0 + 4 p_1 - p_2) / 2), so that the
 * spline is C1, interpolates every node and reproduces straight lines and
 * parabolas exactly. Radii and colors use the same differences. A tube of two
 * nodes is a straight segment with constant-speed parametrisation.
 *
 * Frames are propagated by the double-reflection method (Wang, Jüttler, Zheng
 * and Liu, ACM TOG 2008) along the cubic position spline, with sub-steps where
 * the tangent turns by more than MaximumFrameStepAngle between samples (Salm
 * inserts sub-steps where successive tangents turn by nearly 90 degrees; the
 * double reflection needs them to stay rotation-minimizing at any curvature).
 *
 * Per data change Build() also cuts every tube into **chunks**, runs of at
 * most ChunkSegments consecutive segments, each with a bounding sphere of
 * everything drawn for it (the segments' Bezier control points padded by
 * their radii): the units of the renderers' per-view work (frustum and
 * occlusion culling, vtkSplineTubeVisibility; level of detail).
 *
 * The split of each cubic segment into C1-continuous quadratic sub-segments
 * and their oriented bounding boxes (Salm §3.2 'Rendering') are in
 * vtkSplineTubeMath.h, shared with the shaders; see SplitSegment().
 *
 * Bad input is reported, never rendered as garbage: polylines with a NaN or
 * infinite coordinate, or a NaN, infinite, zero or negative radius, are
 * skipped with a warning naming the cell and point; repeated consecutive
 * points are merged (one warning with the count); polylines with fewer than
 * two distinct points are skipped (one warning with the count). A missing,
 * non-numeric or multi-component radius array is an error (AddPolyData()
 * returns false and adds nothing).
 *
 * An optional one-component point array (NodeScalarArrayName, e.g. the
 * stylized lines' orientation angles) is carried to the nodes the same way
 * (NodeScalars); polylines with a NaN or infinite value in it are skipped with
 * a warning, and a missing, non-numeric or multi-component array is an error.
 */

#ifndef vtkSplineTubeCore_h
#define vtkSplineTubeCore_h

#include "SplineVizModule.h" // for export macro
#include "vtkNew.h"          // for vtkNew
#include "vtkObject.h"

class vtkFloatArray;
class vtkIdTypeArray;
class vtkPolyData;
class vtkTypeUInt32Array;
class vtkUnsignedCharArray;

class SPLINEVIZ_EXPORT vtkSplineTubeCore : public vtkObject
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

  ///@{
  /**
   * Radius in world units used when no radius array is set. Default 0.01.
   */
  vtkSetClampMacro(Radius, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(Radius, double);
  ///@}

  ///@{
  /**
   * Name of a one-component point array giving the radius in world units
   * (multiplied by RadiusScale). nullptr (default): the constant Radius.
   */
  vtkSetStringMacro(RadiusArrayName);
  vtkGetStringMacro(RadiusArrayName);
  ///@}

  ///@{
  /**
   * Factor applied to the radius array's values. Default 1.
   */
  vtkSetClampMacro(RadiusScale, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(RadiusScale, double);
  ///@}

  ///@{
  /**
   * Name of a one-component point array whose values are carried to the
   * nodes (GetNodeScalars()). nullptr (default): none.
   */
  vtkSetStringMacro(NodeScalarArrayName);
  vtkGetStringMacro(NodeScalarArrayName);
  ///@}

  ///@{
  /**
   * Name of an integer cell array of original cell ids (ParaView's
   * "vtkOriginalCellIds" of geometry filtered input): when a block has it,
   * the segments' cell ids (GetSegmentCellIds(), what picking reports) are
   * its values instead of the cell's index in the block. nullptr (default):
   * the index.
   */
  vtkSetStringMacro(CellIdArrayName);
  vtkGetStringMacro(CellIdArrayName);
  ///@}

  ///@{
  /**
   * What the node scalars are, for messages ("The <role> array ..."). Default
   * "node scalar".
   */
  vtkSetStringMacro(NodeScalarRole);
  vtkGetStringMacro(NodeScalarRole);
  ///@}

  ///@{
  /**
   * Largest angle (radians) the tangent may turn between two steps of the
   * frame propagation; longer turns are sub-divided. Default 0.1.
   */
  vtkSetClampMacro(MaximumFrameStepAngle, double, 1e-3, 1.5);
  vtkGetMacro(MaximumFrameStepAngle, double);
  ///@}

  ///@{
  /**
   * Whether Build() propagates the rotation-minimizing frames (needed by
   * the tessellated tubes; the ray-cast tubes, sphere-swept, do not use
   * them). Default on. Without frames, GetNodeFrames() is empty.
   */
  vtkSetMacro(ComputeFrames, bool);
  vtkGetMacro(ComputeFrames, bool);
  vtkBooleanMacro(ComputeFrames, bool);
  ///@}

  /// The longest chunk, in segments.
  static constexpr int ChunkSegments = 8;

  /**
   * Forget all tubes (the settings are kept).
   */
  void Initialize();

  /**
   * Append the polylines (VTK_LINE and VTK_POLY_LINE cells of the line array)
   * of `input` as tubes. `colors`, if given, holds one RGBA color (4 unsigned
   * char components, as made by vtkScalarsToColors::MapScalars) per point of
   * `input`, or per cell when `colorsPerCell` is true (then every node of a
   * polyline gets the polyline's color); without colors every node is white.
   * `blockId` is stored with every segment (the flat index of the block of a
   * composite data set).
   * Returns false, with an error, when the input cannot be used at all.
   * Call Build() after the last AddPolyData().
   */
  bool AddPolyData(vtkPolyData* input, vtkUnsignedCharArray* colors, unsigned int blockId = 0,
    bool colorsPerCell = false);

  /**
   * Compute tangents, derivatives and frames of everything added (in
   * parallel over tubes). Must be called once after the AddPolyData() calls.
   */
  void Build();

  ///@{
  /**
   * Counts of what was built.
   */
  vtkIdType GetNumberOfTubes() const;
  vtkIdType GetNumberOfNodes() const;
  vtkIdType GetNumberOfSegments() const;
  ///@}

  ///@{
  /**
   * Per-node data (one tuple per node; nodes of a tube are consecutive).
   * Positions (3), tangents (3, derivative with respect to the node parameter,
   * not normalized), radii (2: radius and its derivative), colors (4: RGBA in
   * [0, 1]), color derivatives (4), frames (3: unit vector orthogonal to the
   * tangent, rotation-minimizing along the tube).
   */
  vtkFloatArray* GetNodePositions() { return this->NodePositions; }
  vtkFloatArray* GetNodeTangents() { return this->NodeTangents; }
  vtkFloatArray* GetNodeRadii() { return this->NodeRadii; }
  vtkFloatArray* GetNodeColors() { return this->NodeColors; }
  vtkFloatArray* GetNodeColorDerivatives() { return this->NodeColorDerivatives; }
  vtkFloatArray* GetNodeFrames() { return this->NodeFrames; }
  /// The values of NodeScalarArrayName per node (empty without that array).
  vtkFloatArray* GetNodeScalars() { return this->NodeScalars; }
  ///@}

  ///@{
  /**
   * Segment table (one tuple per segment, ordered tube by tube): index of the
   * segment's first node (the second is that plus one), flags (SegmentFlagBits),
   * the cell id of the polyline in its input and the block id given to
   * AddPolyData().
   */
  vtkTypeUInt32Array* GetSegmentFirstNodes() { return this->SegmentFirstNodes; }
  vtkUnsignedCharArray* GetSegmentFlags() { return this->SegmentFlags; }
  vtkIdTypeArray* GetSegmentCellIds() { return this->SegmentCellIds; }
  vtkTypeUInt32Array* GetSegmentBlockIds() { return this->SegmentBlockIds; }
  ///@}

  ///@{
  /**
   * Tube table: first node and number of nodes of each tube.
   */
  vtkIdTypeArray* GetTubeFirstNodes() { return this->TubeFirstNodes; }
  vtkIdTypeArray* GetTubeNumberOfNodes() { return this->TubeNumberOfNodes; }
  ///@}

  ///@{
  /**
   * Chunk table (made by Build()): per chunk its first segment (one more
   * tuple than chunks: the last is the number of segments), its tube, its
   * bounding sphere (x, y, z relative to GetCenter(), radius) and its sizes
   * (the length of its segments' Bezier control polygons, the longest such
   * polygon of one of its segments, its largest radius). Chunks of a tube
   * are consecutive.
   */
  vtkIdType GetNumberOfChunks() const;
  vtkTypeUInt32Array* GetChunkFirstSegments() { return this->ChunkFirstSegments; }
  vtkTypeUInt32Array* GetChunkTubes() { return this->ChunkTubes; }
  vtkFloatArray* GetChunkSpheres() { return this->ChunkSpheres; }
  vtkFloatArray* GetChunkSizes() { return this->ChunkSizes; }
  /// Per segment its bounding sphere relative to its chunk's (vtkSplineTubeVisibility::EncodePart).
  vtkTypeUInt32Array* GetSegmentSpheres() { return this->SegmentSpheres; }
  vtkIdTypeArray* GetTubeFirstChunks() { return this->TubeFirstChunks; }
  ///@}

  /**
   * The centre of the tubes' bounds (made by Build(); the origin of the chunk
   * spheres, and of the positions the mappers upload).
   */
  void GetCenter(double center[3]) const;

  /**
   * True when colors were given for every piece added.
   */
  bool HasColors() const { return this->ColorsGiven && !this->ColorsMissing; }

  /**
   * Bounds of the tubes' surfaces (the convex hulls of the cubic segments'
   * Bezier control points, padded by the largest radius of each segment),
   * made by Build(). Uninitialized bounds when there are no tubes.
   */
  void GetBounds(double bounds[6]) const;

  /**
   * Largest radius over all nodes (0 without tubes).
   */
  double GetMaximumRadius() const { return this->MaximumRadius; }

  ///@{
  /**
   * What the last AddPolyData() calls skipped or merged (since Initialize()).
   */
  vtkGetMacro(NumberOfSkippedLines, vtkIdType);
  vtkGetMacro(NumberOfMergedPoints, vtkIdType);
  ///@}

  /**
   * Evaluate the cubic Hermite position spline of segment `segment` at
   * parameter t in [0, 1]: position, derivative, radius and radius derivative
   * (any output pointer may be nullptr).
   */
  void EvaluateSegment(vtkIdType segment, double t, double position[3], double derivative[3],
    double* radius, double* radiusDerivative);

protected:
  vtkSplineTubeCore();
  ~vtkSplineTubeCore() override;

  double Radius = 0.01;
  char* RadiusArrayName = nullptr;
  double RadiusScale = 1.0;
  char* NodeScalarArrayName = nullptr;
  char* NodeScalarRole = nullptr;
  char* CellIdArrayName = nullptr;
  double MaximumFrameStepAngle = 0.1;
  bool ComputeFrames = true;

  vtkNew<vtkFloatArray> NodePositions;
  vtkNew<vtkFloatArray> NodeTangents;
  vtkNew<vtkFloatArray> NodeRadii;
  vtkNew<vtkFloatArray> NodeColors;
  vtkNew<vtkFloatArray> NodeColorDerivatives;
  vtkNew<vtkFloatArray> NodeFrames;
  vtkNew<vtkFloatArray> NodeScalars;
  vtkNew<vtkTypeUInt32Array> SegmentFirstNodes;
  vtkNew<vtkUnsignedCharArray> SegmentFlags;
  vtkNew<vtkIdTypeArray> SegmentCellIds;
  vtkNew<vtkTypeUInt32Array> SegmentBlockIds;
  vtkNew<vtkIdTypeArray> TubeFirstNodes;
  vtkNew<vtkIdTypeArray> TubeNumberOfNodes;
  vtkNew<vtkIdTypeArray> TubeFirstChunks;
  vtkNew<vtkTypeUInt32Array> ChunkFirstSegments;
  vtkNew<vtkTypeUInt32Array> ChunkTubes;
  vtkNew<vtkFloatArray> ChunkSpheres;
  vtkNew<vtkFloatArray> ChunkSizes;
  vtkNew<vtkTypeUInt32Array> SegmentSpheres;
  double Bounds[6] = { 1.0, -1.0, 1.0, -1.0, 1.0, -1.0 };

  bool ColorsGiven = false;
  bool ColorsMissing = false;
  double MaximumRadius = 0.0;
  vtkIdType NumberOfSkippedLines = 0;
  vtkIdType NumberOfMergedPoints = 0;

private:
  vtkSplineTubeCore(const vtkSplineTubeCore&) = delete;
  void operator=(const vtkSplineTubeCore&) = delete;

  void PropagateFrames(vtkIdType tube);
  /// The chunk table, the bounds and the centre (after the tangents).
  void BuildChunks();
};

#endif
