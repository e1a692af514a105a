// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkSplineTubeVisibility
 * @brief   Per-view visibility of a line renderer's chunks: frustum culling,
 * front-to-back groups, occlusion culling against a depth pyramid, and a
 * stable subset of the lines while the camera moves.
 *
 * Plain C++ (not a vtkObject), used by vtkSplineTubeMapper for the three line
 * renderers. A chunk is a run of consecutive segments of one line (see
 * vtkSplineTubeCore) with a bounding sphere that contains every fragment the
 * renderer draws for it. Per frame:
 *
 * 1. BeginFrame(): the chunks of the lines in the subset (Rank(line) <
 *    fraction; nested subsets, spatially even in expectation) and not
 *    hidden by the line mask (SetLineMask(), a selection) that meet the
 *    view frustum are projected to conservative pixel rectangles and nearest
 *    window depths, ordered front to back and split into groups: first the
 *    chunks that were visible in the last frame (a hint only: correctness never
 *    depends on it), then the rest in groups of doubling size (hierarchical
 *    occlusion culling in the spirit of Greene et al. 1993 and of the
 *    two-phase culling of current game engines).
 * 2. For each group, CullGroup() drops the chunks whose nearest depth lies
 *    behind the depth pyramid (tiles of maxima) of what is already drawn over
 *    their rectangle; the renderer draws the rest.
 * 3. EndFrame() keeps, for the next frame, the drawn chunks that are not
 *    hidden in the finished depth buffer.
 *
 * The test is conservative (a chunk is dropped only when every pixel it could
 * touch already holds something nearer), so the picture is exactly the one
 * drawn without culling, whatever the groups. The rectangles are widened by
 * a pixel and the spheres by a pixel's size at their far side, for renderers
 * that keep sub-pixel lines at least a pixel wide.
 */
#ifndef vtkSplineTubeVisibility_h
#define vtkSplineTubeVisibility_h

#include "SplineVizRenderingModule.h" // for export macro
#include "vtkType.h"

#include <cstdint>
#include <vector>

class SPLINEVIZRENDERING_EXPORT vtkSplineTubeVisibility
{
public:
  /// What the projection of the chunks depends on.
  struct View
  {
    double ModelView[16];  ///< column-major: chunk (sphere) coordinates to view coordinates
    double Projection[16]; ///< column-major: view to clip coordinates
    int Width = 1;         ///< viewport, pixels
    int Height = 1;
  };

  /// Maxima of a depth image over square tiles of 1, 2, 4, ... pixels.
  class SPLINEVIZRENDERING_EXPORT DepthPyramid
  {
  public:
    /// From a window-depth image (row 0 at the bottom, as glReadPixels gives it).
    void Build(const float* depth, int width, int height);
    /// Largest depth over the pixels [x0, x1] x [y0, y1] (clamped to the image), or
    /// more (a tile containing them).
    float MaximumOver(int x0, int y0, int x1, int y1) const;
    int GetWidth() const { return this->Width; }
    int GetHeight() const { return this->Height; }

  private:
    int Width = 0;
    int Height = 0;
    std::vector<std::vector<float>> Levels;
    std::vector<int> LevelWidths;
    std::vector<int> LevelHeights;
  };

  /**
   * Per data: `count` chunks, their spheres (x, y, z, radius per chunk, in the
   * coordinates View::ModelView starts from) and their lines; optionally the
   * smaller spheres of their parts (segments), chunk c's in
   * [partFirsts[c], partFirsts[c + 1]) of `parts`, encoded relative to the
   * chunk's sphere by EncodePart(): a chunk is hidden when its sphere or all
   * its parts' spheres are. The arrays must live until the next SetChunks().
   */
  void SetChunks(const float* spheres, const std::uint32_t* lines, vtkIdType count,
    const std::uint32_t* parts = nullptr, const std::uint32_t* partFirsts = nullptr);

  ///@{
  /**
   * A part's sphere (center, radius) relative to its chunk's sphere, in 32
   * bits (8 per coordinate): DecodePart() gives a sphere that contains the
   * part's (the center rounded, the radius rounded up and widened by the
   * rounding of the center).
   */
  static std::uint32_t EncodePart(const float chunk[4], const double part[4]);
  static void DecodePart(const float chunk[4], std::uint32_t code, float part[4]);
  ///@}

  /**
   * A sphere that contains `count` spheres (x, y, z, radius; float rounding
   * included): the culling tests a group of parts with it first.
   */
  static void EnclosingSphere(const float (*spheres)[4], std::uint32_t count, float out[4]);

  /**
   * Lines to leave out whatever the view: `mask[line]` 0 hides a line's
   * chunks (a streamline selection), nullptr (default) shows all. The array
   * must live until the next SetLineMask() or SetChunks().
   */
  void SetLineMask(const unsigned char* mask) { this->LineMask = mask; }

  /// Rank of a line in [0, 1): a hash of its index, so subsets are stable and nested.
  static double Rank(std::uint32_t line);

  /**
   * Start a frame: cull the chunks of the lines with Rank < `fraction` against
   * the frustum, order the rest front to back and split them into groups (the
   * chunks visible in the last frame first, when `useLastFrame`). With
   * `occlusion` false there is one group and CullGroup() drops nothing.
   */
  void BeginFrame(const View& view, double fraction, bool occlusion, bool useLastFrame);

  int GetNumberOfGroups() const { return static_cast<int>(this->GroupStarts.size()) - 1; }

  /**
   * The chunks of group `g` (front to back) that `pyramid` does not hide
   * (nullptr: all of them), appended to `chunks` after clearing it.
   */
  void CullGroup(int g, const DepthPyramid* pyramid, std::vector<std::uint32_t>& chunks);

  /**
   * End the frame: the drawn chunks that `pyramid` (the finished depth
   * buffer) does not hide are drawn first next time (nullptr: none is).
   */
  void EndFrame(const DepthPyramid* pyramid);

  ///@{
  /// What the last frame did: chunks in the frustum (and the subset), drawn, dropped as hidden.
  vtkIdType GetNumberOfChunksInFrustum() const
  {
    return static_cast<vtkIdType>(this->Order.size());
  }
  vtkIdType GetNumberOfChunksDrawn() const { return this->Drawn; }
  vtkIdType GetNumberOfChunksHidden() const { return this->Hidden; }
  ///@}

  /// The largest stretch of the frame's View::ModelView (set by BeginFrame()).
  double GetViewScale() const { return this->Scale; }

  /**
   * For tests only: window depth added to every chunk's nearest depth before
   * the occlusion test. 0 (default) is exact; a positive bias hides visible
   * chunks (a negative control for the tests that compare culling on and off).
   */
  void SetDepthBias(double bias) { this->DepthBias = bias; }

private:
  struct Projected
  {
    /// pixel rectangle (inclusive), clamped to the viewport (and to 65535)
    std::uint16_t X0, Y0, X1, Y1;
    float Depth; ///< nearest window depth (0: touches the eye plane)
  };
  bool Project(const float* sphere, const View& view, double pixelSlope[2], Projected& out) const;
  /// Chunk `chunk` with its projection `projected`: hidden by its sphere or by all its parts.
  bool IsHidden(std::uint32_t chunk, const Projected& projected, const DepthPyramid& pyramid) const;
  bool IsHidden(const Projected& projected, const DepthPyramid& pyramid) const;
  /// Parts tested together behind one enclosing sphere (IsHidden()).
  static constexpr std::uint32_t PartGroup = 4;

  const float* Spheres = nullptr;
  const std::uint32_t* Lines = nullptr;
  const std::uint32_t* Parts = nullptr;
  const std::uint32_t* PartFirsts = nullptr;
  const unsigned char* LineMask = nullptr;
  vtkIdType NumberOfChunks = 0;
  static constexpr int RankBuckets = 65536;
  std::vector<std::uint32_t> RankOrder;   ///< chunks by their line's rank
  std::vector<vtkIdType> RankBucketStart; ///< RankBuckets + 1 offsets into RankOrder
  std::vector<std::uint32_t> Order;       ///< chunks in the frustum, by group, front to back
  /// The projection of Order[i] at i (with occlusion only): the culling reads
  /// it in order, not scattered over the chunks (cache misses were most of its
  /// time); no per-chunk projection outlives BeginFrame().
  std::vector<Projected> OrderedProjection;
  std::vector<vtkIdType> GroupStarts;
  std::vector<unsigned char> Visible;        ///< per chunk: visible at the end of the last frame
  std::vector<std::uint32_t> DrawnPositions; ///< positions in Order of the drawn chunks
  vtkIdType Drawn = 0;
  vtkIdType Hidden = 0;
  bool Occlusion = false;
  double DepthBias = 0.0;
  double Scale = 1.0; ///< largest stretch of ModelView (sphere radii to view)
  View CurrentView;
  double PixelSlope[2] = { 0.0, 0.0 }; ///< pixel size per unit of distance (or per unit)
  double Planes[6][4] = {};            ///< frustum planes, view coordinates
};

#endif
// VTK-HeaderTest-Exclude: vtkSplineTubeVisibility.h
