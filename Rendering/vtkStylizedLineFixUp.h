// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkStylizedLineFixUp
 * @brief   The CPU part of the hybrid rendering of stylized lines (Stoll et al. §4.4): batches
 * of segments, their per-view classification and the draw lists.
 *
 * Plain C++ (not a vtkObject), used by vtkStylizedLineMapper. It also owns the
 * vertex tangents of the lines (slPolylineTangent(): the bisectors of the
 * straight segments, the segments' directions at the ends), which the
 * mapper uploads, so that the shaders and the classification use the same.
 * Where a line's
 * tangent nearly points at the viewer, the silhouette quads of Stoll §4.1
 * degenerate and flip (§4.3); those places are drawn as real geometry
 * instead. Per data change, Build() cuts every polyline of a
 * vtkSplineTubeCore into batches: runs of at most MaximumBatchSegments
 * consecutive segments whose vertex tangents stay within MaximumBatchAngle
 * of the batch's first tangent (Stoll: 10-15 degrees), each with its tangent
 * cone and a bounding sphere. Per view (BeginView()), when a batch is first
 * drawn (BuildDraws(), for the batches of a visibility group, in parallel,
 * vtkSMPTools), it decides whether one of its vertices needs the
 * fix-up (slNeedsFixUp() of vtkStylizedLineMath.h, the same criterion the
 * tests use): a conservative cone test rejects most batches at once (the
 * smallest angle any of its vertices can make with its view ray, from the
 * angle between the sphere's direction and the cone's axis minus the cone's
 * and the sphere's angular radii, exceeds the threshold, and the eye is
 * further than the near-axis distance that this angle allows); the rest are
 * tested vertex by vertex. Then it writes the draw lists: the triangle
 * strips (two vertices per point) of the polyline pieces between fixed-up
 * batches, and the first points of the fixed-up segments.
 */
#ifndef vtkStylizedLineFixUp_h
#define vtkStylizedLineFixUp_h

#include "SplineVizRenderingModule.h" // for export macro
#include "vtkStylizedLineMath.h"      // for vec3
#include "vtkType.h"

#include <atomic>
#include <cstdint>
#include <vector>

class vtkSplineTubeCore;
class vtkSplineTubeVisibility;

class SPLINEVIZRENDERING_EXPORT vtkStylizedLineFixUp
{
public:
  /// Longest batch, in segments.
  static constexpr int MaximumBatchSegments = 8;
  /// Largest angle (radians) between a batch's vertex tangents and its first one (12 degrees).
  static constexpr double MaximumBatchAngle = 0.20943951023931953;

  /// What the classification depends on.
  struct View
  {
    double ModelView[16]; ///< column-major: uploaded (shifted) model coordinates to view
    double RadiusScale;   ///< model to view scale of radii
    bool Parallel;        ///< parallel projection
    double Epsilon;       ///< threshold of |t . u_hat| > 1 - Epsilon
    double JointRadius;   ///< joint spheres' radius in line radii (1 + halo width)
    double PixelsPerUnit; ///< pixels per view unit (perspective: at distance 1)
  };

  /**
   * Cut the polylines of `core` into batches. Positions are taken relative
   * to `shift` (the mapper's upload shift). Call again whenever the core is
   * rebuilt: Classify() reads the core's arrays.
   */
  void Build(vtkSplineTubeCore* core, const double shift[3]);

  /**
   * Start a view: the batches are classified when BuildDraws() first meets
   * them (when `enabled`; otherwise none is fixed up).
   */
  void BeginView(const View& view, bool enabled);

  /**
   * The draw lists of `batches` (ids ordered as the mapper draws them), after
   * classifying those not classified in this view: per strip its first vertex
   * (2 x first point) and its vertex count (2 x points) for the batches not
   * fixed up, consecutive batches of a polyline in one strip; the caps (2 x
   * polyline + end) of the polylines whose first or last batch is among them;
   * the first point of every fixed-up segment; and the joints: the points of
   * the fixed-up segments (each once) whose sphere of JointRadius line radii
   * stays behind the polyline's end caps (further than that from both ends).
   */
  void BuildDraws(const std::vector<std::uint32_t>& batches, std::vector<int>& stripFirsts,
    std::vector<int>& stripCounts, std::vector<std::uint32_t>& caps,
    std::vector<std::uint32_t>& segments, std::vector<std::uint32_t>& joints);

  /**
   * Hand the batches to `visibility` as its chunks (SetChunks()): spheres
   * (shifted model coordinates) that also hold `widen` times the largest
   * line radius around the vertices, the polyline of each, and the spheres
   * of their segments (parts, vtkSplineTubeVisibility::EncodePart()). The
   * arrays are the fix-up's own (the spheres' centers are the batches'), so
   * they live until the next Build() or SetCullingChunks(); nothing is
   * recomputed when `widen` is the last call's.
   */
  void SetCullingChunks(double widen, vtkSplineTubeVisibility& visibility);

  /// The unit tangent of a line vertex (the bisector; the segment's direction at the ends).
  void GetTangent(vtkIdType node, double tangent[3]) const;

  /// The tangents of the vertices [first, first + count), octahedral, 2 int16 each (in parallel).
  void FillTangents(vtkIdType first, vtkIdType count, short* octahedral) const;

  /**
   * The largest radius on screen, in pixels, of the polylines' ends (the
   * caps, in front of the eye) in this view and of the fixed-up segments'
   * points (in this view so far and the last); the mapper tessellates the
   * caps and cylinders from it.
   */
  double GetMaximumScreenRadius() const { return this->MaximumScreenRadius; }

  /// Per batch: 1 when it is fixed up in this view (if classified in it).
  const std::vector<unsigned char>& GetBatchFlags() const { return this->Flags; }

  /**
   * The reference classification: every vertex tested, no cone test
   * (for the tests; same output as GetBatchFlags()).
   */
  std::vector<unsigned char> ClassifyAllVertices(const View& view) const;

  vtkIdType GetNumberOfBatches() const { return static_cast<vtkIdType>(this->Batches.size()); }
  /// Batches tested vertex by vertex in this view (those the cone test kept).
  vtkIdType GetNumberOfCandidateBatches() const { return this->Candidates; }
  /// First point and segment count of batch b.
  vtkIdType GetBatchFirstNode(vtkIdType b) const { return this->Batches[b].FirstNode; }
  int GetBatchNumberOfSegments(vtkIdType b) const { return this->Batches[b].Segments; }

private:
  // Per batch; its bounding sphere and polyline are in Spheres and Tubes
  // (the visibility's chunk arrays, struct of arrays so that they are one
  // copy).
  struct Batch
  {
    std::uint32_t FirstNode;
    int Segments;
    float Axis[3];   ///< unit tangent of the first vertex
    float Cone;      ///< largest angle of a vertex tangent to Axis
    float Radius;    ///< radius of the sphere of the vertices (positions only)
    float MaxRadius; ///< largest line radius in the batch
  };
  bool TestVertices(vtkIdType b, const View& view) const;
  /// Nodes [k0, k1] of a tube (positions and radii, 4 each; may be nullptr) and their tangents.
  void Nodes(vtkIdType tube, vtkIdType k0, vtkIdType k1, double* xyzr,
    vtkStylizedLineMath::vec3* tangents) const;
  /// The cone test, then the vertices of the candidates.
  bool NeedsFixUp(vtkIdType b, const View& view, double thetaEps) const;
  /// Radius on screen (pixels) of point i in the current view (0 behind the eye).
  /// The radius in pixels of node k of tube t in the current view.
  double ScreenRadius(vtkIdType t, vtkIdType k) const;

  vtkSplineTubeCore* Core = nullptr;
  double Shift[3] = { 0.0, 0.0, 0.0 };
  std::vector<Batch> Batches;
  /// Per batch: center of the vertices' bounding sphere (shifted model coordinates) and
  /// the culling radius (Radius + CullingWiden x MaxRadius, rounded up).
  std::vector<float> Spheres;
  std::vector<std::uint32_t> Tubes;      ///< per batch: its polyline
  std::vector<std::uint32_t> Parts;      ///< per segment: its culling sphere, encoded
  std::vector<std::uint32_t> PartFirsts; ///< batches + 1: first part of each
  double CullingWiden = -1.0;            ///< what Spheres and Parts were made for
  std::vector<vtkIdType> TubeFirstBatch; ///< tubes + 1
  std::vector<unsigned char> Flags;
  std::vector<std::uint8_t> Stamps; ///< the view a batch was classified in (wraps)
  std::uint8_t ViewStamp = 0;
  View CurrentView{};
  bool Enabled = false;
  mutable std::atomic<vtkIdType> Candidates{ 0 };
  double MaximumScreenRadius = 0.0;
  double FixedScreenRadius = 0.0;
};

#endif
// VTK-HeaderTest-Exclude: vtkStylizedLineFixUp.h
