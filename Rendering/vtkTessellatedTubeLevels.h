// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkTessellatedTubeLevels
 * @brief   The level of detail of vtkTessellatedTubeMapper, on the CPU: base meshes, per-view
 * bins of the chunks and the instance lists of the draws.
 *
 * Plain C++ without OpenGL (the mapper uploads and draws what it makes), so
 * that the level-of-detail decisions can be tested directly. It works on the
 * chunks of a vtkSplineTubeCore (runs of consecutive segments with bounding
 * spheres):
 *
 * - BuildMeshes(): the ladders of base meshes (vertex rings along a segment
 *   halved from BaseRings down to 2, vertices per ring halved from BaseSides
 *   down to 4, and one patch around) and their quad-patch indices; the
 *   thin-tube ribbon mesh (three vertices per ring: the two silhouette points
 *   and the point nearest the eye, diagonals mirrored as the tessellator's) and
 *   the thin caps' fan.
 * - ClassifyView(): per view, for every chunk meeting the frustum its length
 *   on screen and the rings along it whose spacing stays below half
 *   MaxEdgeLength; per tube, from its widest chunk, the vertices per ring
 *   (steps of twice MaxSilhouetteEdgeLength around its circumference), so
 *   that the rings of neighbouring chunks always match.
 * - BuildDraws(): for a list of chunks (the visible ones of a group, see
 *   vtkSplineTubeVisibility), the bins and the instance list. A chunk of a
 *   thin tube at most WholeChunkPixels long on screen whose rings need at most
 *   ThinMaxSides intervals is a thin draw, its rings along the levels the
 *   control stage would choose (ThinChunkLevels: chords within a quarter pixel on
 *   screen and a tenth of the radius in space, through the shared
 *   svThin... functions of vtkSplineTubeMathShared.glsl) rounded up to the
 *   thin ladder; other chunks of thin tubes are one patch, longer ones a patch
 *   per segment; thick tubes are patches of their (rings, sides) bin. Caps
 *   are listed for the tubes' end segments (thin caps only when turned to
 *   the eye).
 *
 * Instance list entries: per wall patch its segment; per cap patch its
 * segment; per whole chunk (first segment, count); per thin run (first
 * segment, count | starts-and-ends-its-tube << 8); per thin cap (segment,
 * kind: 1 start, 2 end).
 */
#ifndef vtkTessellatedTubeLevels_h
#define vtkTessellatedTubeLevels_h

#include "SplineVizRenderingModule.h" // for export macro
#include "vtkType.h"

#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

class vtkSplineTubeCore;

class SPLINEVIZRENDERING_EXPORT vtkTessellatedTubeLevels
{
public:
  static constexpr unsigned char Culled = 255;
  static constexpr unsigned char WholeChunk = 254;   ///< one patch for the chunk
  static constexpr unsigned char ThinChunk = 253;    ///< a thin draw (no tessellator)
  static constexpr int SinglePatchSides = 8;         ///< ring edges made by the tessellator at most
  static constexpr double WholeChunkPixels = 1024.0; ///< 16-pixel edges at level 64
  /// Thin draws: chunks whose rings need at most this many intervals per half ring.
  static constexpr int ThinMaxSides = 8;
  /// Vertices per ring of thin draws (vtkTessellatedTubeThinVS.glsl's tubeRibbonSides).
  static constexpr int ThinRibbonSides = 3;
  /// Vertex rings of thin meshes numbered from the run's end start here.
  static constexpr int ThinMirrorRing = 65;
  /// Vertices of a thin run's cap polygon (the control stage's cap level).
  static constexpr int ThinCapSides = 8;

  /// The settings the levels follow (the mapper's).
  struct Settings
  {
    bool LevelOfDetail = true;
    bool Capping = true;
    double MaxEdgeLength = 16.0;
    double MaxSilhouetteEdgeLength = 2.0;
    int MaxTessellationLevel = 64;
    int BaseRings = 16;
    int BaseSides = 8;
  };

  /// The view: uploaded (shifted) model to view coordinates, projection, viewport.
  struct View
  {
    float ModelView[16]; ///< column-major
    double Proj[4][4];   ///< row-major
    int Width = 1;
    int Height = 1;
    double RadiusScale = 1.0;
    bool Parallel = false;
  };

  /// A range of the index list.
  struct MeshRange
  {
    size_t Offset = 0; ///< in indices
    size_t Count = 0;
  };

  /// One instanced draw.
  struct Draw
  {
    int Rings;
    int Sides;
    bool Caps;
    bool Chunks;      ///< instances are (first segment, count) pairs
    bool Thin;        ///< a thin draw: (first segment, count | tube ends << 8) pairs
    vtkIdType Offset; ///< in the instance list
    vtkIdType Count;
  };

  /**
   * The base meshes for BaseRings and BaseSides (quad patches, then the thin
   * ribbon and the thin cap fan, as triangles); false when they did not
   * change since the last call.
   */
  bool BuildMeshes(int baseRings, int baseSides);
  const std::vector<unsigned int>& GetMeshIndices() const { return this->MeshIndices; }
  const MeshRange& GetWallMesh(int rings, int sides) const
  {
    return this->WallMeshes.at(std::make_pair(rings, sides));
  }
  const MeshRange& GetCapMesh(int sides) const { return this->CapMeshes.at(sides); }
  const MeshRange& GetThinMesh() const { return this->ThinMesh; }
  const MeshRange& GetThinCapMesh() const { return this->ThinCapMesh; }

  /// Use the chunks of `core` (after every rebuild of the core).
  void SetCore(vtkSplineTubeCore* core);

  /**
   * Classify the chunks for a view (see the class comment); false (and
   * nothing done) when the view and settings are those of the last call.
   */
  bool ClassifyView(const View& view, const Settings& settings);

  /**
   * The draws of `chunks` (after ClassifyView()); GetDraws() and
   * GetInstances() hold them until the next call.
   */
  void BuildDraws(const std::vector<std::uint32_t>& chunks);
  const std::vector<Draw>& GetDraws() const { return this->Draws; }
  const std::vector<std::uint32_t>& GetInstances() const { return this->Instances; }

  /// Start a new frame's summary (GetSummary() sums BuildDraws() since).
  void ResetSummary();
  /// What the draws since ResetSummary() held, e.g. "thin 9 x 1: 12; culled: 3".
  std::string GetSummary() const;

  /// Forget the last view (the next ClassifyView() classifies).
  void Invalidate() { this->LastView.clear(); }

private:
  /// Where each kind of instance list goes in BuildDraws()'s bins.
  struct BinLayout
  {
    int SideBins = 0; ///< sides ladder size
    int Walls = 0;    ///< bins [0, Walls): walls per (rings, sides); then caps per sides
    int Chunks = 0;   ///< whole chunks (2 entries each)
    int ThinBase = 0; ///< thin runs per rung (2 entries each), ThinBins of them
    int ThinBins = 0;
    int ThinCaps = 0; ///< thin caps ((segment, kind) pairs)
  };
  BinLayout GetBinLayout() const;
  /// BuildDraws(), step by step: classify the chunks' tubes and thin runs,
  /// count the entries per bin, fill the instance list, make the draws.
  void ClassifyChunks(const std::vector<std::uint32_t>& chunks);
  std::vector<vtkIdType> CountInstances(
    const std::vector<std::uint32_t>& chunks, const BinLayout& layout);
  void FillInstances(const std::vector<std::uint32_t>& chunks, const BinLayout& layout,
    const std::vector<vtkIdType>& offsets);
  void AddDraws(const BinLayout& layout, const std::vector<vtkIdType>& counts,
    const std::vector<vtkIdType>& offsets);
  /// Whether a chunk is drawn in this view (its tube and itself not culled).
  bool IsDrawn(std::uint32_t chunk) const;
  /// A segment's ends: 1 when it starts its tube, 2 when it ends it.
  int SegmentEnds(vtkIdType segment, std::uint32_t tube) const;
  /// Of a thin chunk's segment with these ends, the caps turned to the eye (1 start, 2 end).
  int ThinCapsToDraw(std::uint32_t tube, int ends) const;
  void ClassifyThin(std::uint32_t chunk);
  /// A tube's chunks in this view: frustum, length on screen, rings; its sides.
  void ClassifyTube(vtkIdType tube);

  // Base meshes.
  std::vector<int> RingLadder; ///< vertex rings, finest first
  std::vector<int> SideLadder; ///< vertices per ring, finest first
  std::vector<int> ThinLadder; ///< rings along thin runs
  std::map<std::pair<int, int>, MeshRange> WallMeshes;
  std::map<int, MeshRange> CapMeshes;
  MeshRange ThinMesh;
  MeshRange ThinCapMesh;
  std::vector<unsigned int> MeshIndices;
  int MeshBaseRings = 0;
  int MeshBaseSides = 0;

  // Per data.
  vtkSplineTubeCore* Core = nullptr;

  // Per view.
  View CurrentView;
  Settings CurrentSettings;
  std::vector<double> LastView;
  std::vector<unsigned char> ChunkRingBin;
  std::vector<float> ChunkPixels; ///< length on screen (< 0: culled)
  std::vector<std::uint32_t> ChunkThinLevels;
  std::vector<unsigned char> TubeSideBin;
  std::vector<std::uint32_t> TubeStamp; ///< the view a tube was last classified in
  std::uint32_t ViewStamp = 0;
  double Planes[6][4] = {};            ///< frustum planes of the view, view coordinates
  ///@{
  /// Per tube: its start (end) cap turned to the eye, when the chunk that
  /// holds that end is thin (a thin draw); read only for those chunks.
  std::vector<unsigned char> ThinStartCaps;
  std::vector<unsigned char> ThinEndCaps;
  ///@}

  // Per draw list.
  std::vector<std::uint32_t> Instances;
  std::vector<Draw> Draws;
  std::map<std::string, vtkIdType> Summary;
  vtkIdType DrawnSegments = 0;
};

#endif
// VTK-HeaderTest-Exclude: vtkTessellatedTubeLevels.h
