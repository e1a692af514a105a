#include "vtkTessellatedTubeMapper.h"

#include "vtkRayCastTubeMapper.h"
#include "vtkSplineTubeCore.h"
#include "vtkSplineTubeMath.h"
#include "vtkSplineVizGPUBuffer.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkFloatArray.h"
#include "vtkGarbageCollector.h"
#include "vtkIdTypeArray.h"
#include "vtkSMPTools.h"
#include "vtkTypeUInt32Array.h"
#include "vtkUnsignedCharArray.h"
#include "vtkMath.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLCamera.h"
#include "vtkOpenGLHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkShader.h"
#include "vtkShaderProgram.h"

#include "vtkSplineTubeMathPrelude.h"
#include "vtkSplineTubeMathShared.h"
#include "vtkSplineTubeColor.h"
#include "vtkTessellatedTubeCommon.h"
#include "vtkTessellatedTubeFS.h"
#include "vtkTessellatedTubeTCS.h"
#include "vtkTessellatedTubeTES.h"
#include "vtkTessellatedTubeThinFS.h"
#include "vtkTessellatedTubeThinVS.h"
#include "vtkTessellatedTubeVS.h"

#include <vtk_glew.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <map>
#include <sstream>
#include <vector>

vtkStandardNewMacro(vtkTessellatedTubeMapper);

namespace
{
std::string TubeMathSource()
{
  return std::string(vtkSplineTubeMathPrelude) + vtkSplineTubeMathShared;
}

/// What the vertex and tessellation stages share, with the color spline.
std::string CommonSource()
{
  std::string common = vtkTessellatedTubeCommon;
  vtkShaderProgram::Substitute(common, "//VTK::SplineTubeColor::Dec", vtkSplineTubeColor);
  return common;
}

/// The source with line numbers, for error messages.
std::string NumberedSource(const std::string& source)
{
  std::istringstream in(source);
  std::ostringstream out;
  std::string line;
  int number = 1;
  while (std::getline(in, line))
  {
    out << number++ << ": " << line << "\n";
  }
  return out.str();
}

/// What the thin-tube levels depend on in a view (see ThinChunkLevels).
struct ThinView
{
  const float* ModelView = nullptr; // column-major, shifted model to view
  double Proj[4][4];
  double HalfViewport[2];
  double PixelScale;  // pixels per view unit at clip w = 1
  double RadiusScale; // model to view
  double Shift[3];
  double SideLength; // pixels per ring edge (2 MaxSilhouetteEdgeLength)
  double Edge;       // longest edge along the tube, pixels (4 MaxEdgeLength)
  double MaxLevel;   // MaxTessellationLevel
  bool Parallel;
};

/// A node in view coordinates: center, radius, derivatives, clip coordinates.
struct ViewNode
{
  double P[3];
  double R;
  double D[3];
  double DR;
  double Clip[4];
};

ViewNode ToView(const ThinView& v, const float* P, const float* M, const float* R, vtkIdType i)
{
  ViewNode n;
  const double x[3] = { P[3 * i] - v.Shift[0], P[3 * i + 1] - v.Shift[1],
    P[3 * i + 2] - v.Shift[2] };
  const float* mv = v.ModelView;
  for (int r = 0; r < 3; ++r)
  {
    n.P[r] = mv[r] * x[0] + mv[4 + r] * x[1] + mv[8 + r] * x[2] + mv[12 + r];
    n.D[r] = mv[r] * M[3 * i] + mv[4 + r] * M[3 * i + 1] + mv[8 + r] * M[3 * i + 2];
  }
  n.R = R[2 * i] * v.RadiusScale;
  n.DR = R[2 * i + 1] * v.RadiusScale;
  for (int r = 0; r < 4; ++r)
  {
    n.Clip[r] =
      v.Proj[r][0] * n.P[0] + v.Proj[r][1] * n.P[1] + v.Proj[r][2] * n.P[2] + v.Proj[r][3];
  }
  return n;
}

/// Intervals of the view-facing half ring at a node (the control stage's
/// tubeWallRingLevel, through the same shared functions).
double ThinRingLevel(const ThinView& v, const ViewNode& n)
{
  const vtkSplineTubeMath::vec3 d(n.D[0], n.D[1], n.D[2]);
  const vtkSplineTubeMath::vec3 toEye = v.Parallel
    ? vtkSplineTubeMath::vec3(0.0, 0.0, 1.0)
    : vtkSplineTubeMath::vec3(-n.P[0], -n.P[1], -n.P[2]);
  // (a degenerate direction counts as across the view: 3 intervals at least)
  const double least = glm::length(d) > 0.0 && glm::length(toEye) > 0.0
    ? vtkSplineTubeMath::svThinWallLeast(d, toEye)
    : 3.0;
  return vtkSplineTubeMath::svThinRingLevel(n.R, n.Clip[3], v.PixelScale, v.SideLength, 0.5, least);
}

/// Whether the cap of `kind` (1: start, 2: end) at a node is turned to the
/// eye, within a radius (the control stage's test for caps).
bool ThinCapVisible(const ThinView& v, const ViewNode& n, int kind)
{
  const double length = std::sqrt(n.D[0] * n.D[0] + n.D[1] * n.D[1] + n.D[2] * n.D[2]);
  if (length <= 0.0)
  {
    return true;
  }
  const double sign = kind == 1 ? -1.0 / length : 1.0 / length;
  const double facing =
    v.Parallel ? sign * n.D[2] : -sign * (n.D[0] * n.P[0] + n.D[1] * n.P[1] + n.D[2] * n.P[2]);
  return facing >= -n.R;
}

/// Pixel position of a node (false behind the eye).
bool ThinScreen(const ThinView& v, const ViewNode& n, double p[2])
{
  if (n.Clip[3] <= 0.0)
  {
    return false;
  }
  p[0] = n.Clip[0] / n.Clip[3] * v.HalfViewport[0];
  p[1] = n.Clip[1] / n.Clip[3] * v.HalfViewport[1];
  return true;
}

/// Rings along a thin run of `count` segments from node `first`: the level
/// the control stage's single-patch mode sets (tubeSinglePatch: edges at
/// most Edge pixels on screen, chords within half a pixel of the curve on
/// screen and within a tenth of the radius in space, 1.7 times that inside
/// runs, whose chords straddle the curve), and the intervals of its first
/// and last rings. The same bounds, through the same functions
/// (vtkSplineTubeMathShared.glsl's svThin...), computed once per view on the
/// CPU instead of per patch on the GPU.
void ThinChunkLevels(const ThinView& v, const float* P, const float* M, const float* R,
  vtkIdType first, vtkIdType count, double& along, double& ring0, double& ring1)
{
  const ViewNode a = ToView(v, P, M, R, first);
  const ViewNode b = ToView(v, P, M, R, first + count);
  ring0 = ThinRingLevel(v, a);
  ring1 = ThinRingLevel(v, b);
  using vtkSplineTubeMath::vec3;
  if (count == 1)
  {
    // The cubic's deviation from its chord (svThinSegmentSagitta).
    double pa[2];
    double pb[2];
    double screen = 1e30;
    if (ThinScreen(v, a, pa) && ThinScreen(v, b, pb))
    {
      screen = std::hypot(pa[0] - pb[0], pa[1] - pb[1]);
    }
    // The segment's middle (svHermite at t = 1/2, position and radius).
    using vtkSplineTubeMath::vec4;
    const vec4 p0(a.P[0], a.P[1], a.P[2], a.R);
    const vec4 m0(a.D[0], a.D[1], a.D[2], a.DR);
    const vec4 p1(b.P[0], b.P[1], b.P[2], b.R);
    const vec4 m1(b.D[0], b.D[1], b.D[2], b.DR);
    const vec4 middle = vtkSplineTubeMath::svHermite(p0, m0, p1, m1, 0.5);
    const double sagitta = vtkSplineTubeMath::svThinSegmentSagitta(m0, m1, 1.0);
    const double w =
      v.Proj[3][0] * middle.x + v.Proj[3][1] * middle.y + v.Proj[3][2] * middle.z + v.Proj[3][3];
    const double radius = std::min({ a.R, b.R, middle.w });
    const double sagittaLevel =
      vtkSplineTubeMath::svThinSagittaLevel(sagitta, w, radius, v.PixelScale);
    along =
      std::min(std::max(std::max(std::min(screen / v.Edge, v.MaxLevel), sagittaLevel), 1.0), 64.0);
    return;
  }
  double total = 0.0;
  double total3 = 0.0;
  double shortest = 1e30;
  double shortest3 = 1e30;
  vec3 previous(0.0);
  vec3 direction(0.0);
  double previousLength = 0.0;
  vec3 previous3(0.0);
  vec3 direction3(0.0);
  double previousLength3 = 0.0;
  for (vtkIdType k = 0; k <= count; ++k)
  {
    const ViewNode n = k == 0 ? a : (k == count ? b : ToView(v, P, M, R, first + k));
    double p2[2];
    if (!ThinScreen(v, n, p2))
    {
      along = 64.0;
      return;
    }
    const vec3 p(p2[0], p2[1], 0.0);
    const vec3 p3(n.P[0], n.P[1], n.P[2]);
    if (k > 0)
    {
      const vec3 d = p - previous;
      const double len = glm::length(d);
      total += len;
      const double curvature =
        k > 1 ? vtkSplineTubeMath::svThinChainCurvature(d, len, direction, previousLength) : 0.0;
      if (curvature > 0.0)
      {
        shortest =
          std::min(shortest, std::sqrt(8.0 * vtkSplineTubeMath::svThinSagittaPixels / curvature));
      }
      direction = d;
      previousLength = len;
      const vec3 d3 = p3 - previous3;
      const double len3 = glm::length(d3);
      total3 += len3;
      const double curvature3 = k > 1
        ? vtkSplineTubeMath::svThinChainCurvature(d3, len3, direction3, previousLength3)
        : 0.0;
      if (curvature3 > 0.0)
      {
        shortest3 = std::min(shortest3,
          std::sqrt(8.0 * vtkSplineTubeMath::svThinRunStraddle *
            vtkSplineTubeMath::svThinDepthSagitta * n.R / curvature3));
      }
      direction3 = d3;
      previousLength3 = len3;
    }
    previous = p;
    previous3 = p3;
  }
  along = std::min(
    std::max(std::ceil(std::max({ total / v.Edge, total / shortest, total3 / shortest3 })), 1.0),
    64.0);
}

/// Compile one stage; 0 and `error` set on failure.
GLuint CompileStage(GLenum type, const std::string& source, std::string& error)
{
  GLuint shader = glCreateShader(type);
  if (!shader)
  {
    error = "glCreateShader failed";
    return 0;
  }
  const char* text = source.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok)
  {
    GLint length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(static_cast<size_t>(std::max(length, 1)), '\0');
    glGetShaderInfoLog(shader, static_cast<GLsizei>(log.size()), nullptr, log.data());
    error = NumberedSource(source) + "\n" + log.data();
    glDeleteShader(shader);
    return 0;
  }
  return shader;
}
}

//------------------------------------------------------------------------------
// Level-of-detail data: per data change the chunks (runs of up to ChunkSize
// consecutive segments of one tube) with their bounding spheres; per view the
// bins and the instance list.
struct vtkTessellatedTubeMapper::vtkInternals
{
  static constexpr vtkIdType ChunkSize = 16;
  static constexpr unsigned char Culled = 255;
  static constexpr unsigned char WholeChunk = 254;   // one patch for the chunk
  static constexpr int SinglePatchSides = 8;         // ring edges made by the tessellator at most
  static constexpr double WholeChunkPixels = 1024.0; // 16-pixel edges at level 64
  static constexpr unsigned char ThinChunk = 253;    // a thin-tube draw (no tessellator)
  // Thin draws: chunks whose rings would need at most this many intervals
  // per half ring (tubes a few pixels wide).
  static constexpr int ThinMaxSides = 8;
  // Vertices per ring of thin draws: the two silhouette points and the point
  // nearest the eye (vtkTessellatedTubeThinVS.glsl's tubeRibbonSides).
  static constexpr int ThinRibbonSides = 3;
  static constexpr int ThinMirrorRing = 65; // vertex rings numbered from the run's end
  // Vertices of a thin run's cap polygon: the control stage's cap level
  // (svThinRingLevel of a whole turn, at least 8) is 8 wherever a tube's
  // rings are single patches (at most SinglePatchSides edges around).
  static constexpr int ThinCapSides = 8;

  std::vector<vtkIdType> TubeFirstSegment;  // tubes + 1
  std::vector<vtkIdType> TubeFirstChunk;    // tubes + 1
  std::vector<vtkIdType> ChunkFirstSegment; // chunks + 1
  std::vector<float> ChunkSphere;           // center (relative to Shift), radius
  std::vector<float> ChunkMaxLength;        // longest segment (control polygon)
  std::vector<float> ChunkMaxRadius;        // largest radius
  std::vector<float> ChunkLength;           // sum of the segments' control polygons

  std::vector<int> RingLadder; // vertex rings, finest first
  std::vector<int> SideLadder; // vertices per ring, finest first
  struct MeshRange
  {
    size_t Offset = 0; // in indices
    size_t Count = 0;
  };
  std::map<std::pair<int, int>, MeshRange> WallMeshes; // (rings, sides)
  std::map<int, MeshRange> CapMeshes;                  // sides
  // Thin-tube draws: rings along a run (the tessellation levels the control
  // stage would choose, rounded up to this ladder), ThinRibbonSides vertices
  // per ring.
  std::vector<int> ThinLadder;
  MeshRange ThinMesh;    // 64 rows of rings of ThinRibbonSides vertices
  MeshRange ThinCapMesh; // a fan of ThinCapSides vertices
  size_t MeshIndices = 0;
  int MeshBaseRings = 0;
  int MeshBaseSides = 0;

  struct Draw
  {
    int Rings;
    int Sides;
    bool Caps;
    bool Chunks;      // instances are (first segment, count) pairs
    bool Thin;        // a thin-tube draw: (first segment, count | L0 << 8 | L1 << 16)
    vtkIdType Offset; // in the instance list
    vtkIdType Count;
  };
  std::vector<unsigned char> ChunkRingBin;
  std::vector<vtkTypeUInt32> ChunkThinLevels; // thin draws: the rung of ThinLadder
  std::vector<unsigned char> ThinCaps; // per segment of thin runs: its caps turned to the eye
  std::vector<unsigned char> TubeSideBin;
  std::vector<vtkTypeUInt32> Instances;
  std::vector<Draw> Draws;
  vtkIdType CulledSegments = 0;
  std::vector<double> LastView; // what the current bins were made for
  vtkSplineVizGPUBuffer InstancesBuffer;
};

//------------------------------------------------------------------------------
vtkTessellatedTubeMapper::vtkTessellatedTubeMapper()
  : Internals(new vtkInternals)
  , FramesBuffer(new vtkSplineVizGPUBuffer)
{
}

//------------------------------------------------------------------------------
vtkTessellatedTubeMapper::~vtkTessellatedTubeMapper() = default;

//------------------------------------------------------------------------------
void vtkTessellatedTubeMapper::ReportReferences(vtkGarbageCollector* collector)
{
  this->Superclass::ReportReferences(collector);
  vtkGarbageCollectorReport(collector, this->Fallback, "Fallback");
}

//------------------------------------------------------------------------------
bool vtkTessellatedTubeMapper::IsTessellationSupported(vtkRenderWindow* window)
{
  auto* glWindow = vtkOpenGLRenderWindow::SafeDownCast(window);
  if (!glWindow)
  {
    return false;
  }
  glWindow->MakeCurrent();
  if (!glWindow->IsCurrent())
  {
    return false;
  }
  GLint major = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  bool supported = major >= 4;
  if (!supported)
  {
    GLint count = 0;
    glGetIntegerv(GL_NUM_EXTENSIONS, &count);
    for (GLint i = 0; i < count && !supported; ++i)
    {
      const char* name = reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, i));
      supported = name && std::strcmp(name, "GL_ARB_tessellation_shader") == 0;
    }
  }
  return supported && glPatchParameteri != nullptr;
}

//------------------------------------------------------------------------------
size_t vtkTessellatedTubeMapper::GetGPUMemorySize()
{
  const size_t mesh = this->BaseMeshes ? this->Internals->MeshIndices * sizeof(unsigned int) : 0;
  return this->GetTubeBuffersSize() + this->FramesBuffer->GetNumberOfBytes() +
    this->Internals->InstancesBuffer.GetNumberOfBytes() + mesh;
}

//------------------------------------------------------------------------------
void vtkTessellatedTubeMapper::ReleaseTessellationStages()
{
  if (this->ControlShader)
  {
    glDeleteShader(this->ControlShader);
  }
  if (this->EvaluationShader)
  {
    glDeleteShader(this->EvaluationShader);
  }
  this->ControlShader = 0;
  this->EvaluationShader = 0;
  this->StagesVersion.clear();
}

//------------------------------------------------------------------------------
void vtkTessellatedTubeMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  auto* glWindow = vtkOpenGLRenderWindow::SafeDownCast(window);
  if (glWindow && glWindow->IsCurrent())
  {
    // Our raw GL objects (VTK's own are released below).
    this->ReleaseTessellationStages();
    if (this->PrimitivesQuery)
    {
      glDeleteQueries(1, &this->PrimitivesQuery);
    }
  }
  this->ControlShader = 0;
  this->EvaluationShader = 0;
  this->PrimitivesQuery = 0;
  this->StagesVersion.clear();
  this->StagesFailed = false;
  this->FramesBuffer->ReleaseGraphicsResources(window);
  this->Internals->InstancesBuffer.ReleaseGraphicsResources(window);
  this->Internals->LastView.clear();
  if (this->BaseMeshes)
  {
    this->BaseMeshes->ReleaseGraphicsResources();
  }
  this->BaseMeshes = nullptr;
  this->Internals->MeshIndices = 0;
  if (this->Fallback)
  {
    this->Fallback->ReleaseGraphicsResources(window);
  }
  this->Superclass::ReleaseGraphicsResources(window);
}

//------------------------------------------------------------------------------
void vtkTessellatedTubeMapper::RenderPiece(vtkRenderer* ren, vtkActor* act)
{
  if (!IsTessellationSupported(ren->GetRenderWindow()))
  {
    if (!this->FallbackWarned)
    {
      vtkWarningMacro(<< "This OpenGL context has no tessellation shaders (OpenGL 4.0 or "
                         "GL_ARB_tessellation_shader); drawing the tubes with "
                         "vtkRayCastTubeMapper instead.");
      this->FallbackWarned = true;
    }
    if (!this->Fallback)
    {
      this->Fallback = vtkSmartPointer<vtkRayCastTubeMapper>::New();
    }
    // Same input, coloring, clipping planes and radii.
    this->Fallback->ShallowCopy(this);
    this->Fallback->SetInputConnection(this->GetInputConnection(0, 0));
    this->Fallback->SetRadius(this->Radius);
    this->Fallback->SetRadiusArray(this->RadiusArray);
    this->Fallback->SetRadiusScale(this->RadiusScale);
    this->UsingFallback = true;
    this->Fallback->Render(ren, act);
    return;
  }
  this->UsingFallback = false;
  this->Superclass::RenderPiece(ren, act);
}

//------------------------------------------------------------------------------
void vtkTessellatedTubeMapper::UploadTubes(vtkOpenGLRenderWindow* window)
{
  if (!this->UploadTubeBuffers(window))
  {
    return;
  }
  // Orthogonal vectors: octahedral encoding, 2 x int16 per node.
  vtkSplineTubeCore* core = this->Core;
  const vtkIdType numNodes = core->GetNumberOfNodes();
  const float* F = core->GetNodeFrames()->GetPointer(0);
  std::vector<vtkTypeInt16> frames(static_cast<size_t>(2 * numNodes));
  vtkSMPTools::For(0, numNodes,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        const vtkSplineTubeMath::vec2 e = vtkSplineTubeMath::svOctEncode(
          vtkSplineTubeMath::vec3(F[3 * i], F[3 * i + 1], F[3 * i + 2]));
        frames[2 * i] = static_cast<vtkTypeInt16>(std::lround(32767.0 * e.x));
        frames[2 * i + 1] = static_cast<vtkTypeInt16>(std::lround(32767.0 * e.y));
      }
    });
  if (!this->FramesBuffer->Upload(window, frames.data(), numNodes, 2, VTK_TYPE_INT16, GL_RG16I))
  {
    vtkErrorMacro(<< "Could not upload the orthogonal vectors to the GPU: "
                  << vtkSplineVizGPUBuffer::GetLastUploadError());
    this->UploadFailed = true;
    return;
  }
  this->BuildChunks();
}

//------------------------------------------------------------------------------
void vtkTessellatedTubeMapper::BuildChunks()
{
  vtkInternals& in = *this->Internals;
  vtkSplineTubeCore* core = this->Core;
  const vtkIdType numTubes = core->GetNumberOfTubes();
  in.TubeFirstSegment.assign(static_cast<size_t>(numTubes + 1), 0);
  in.TubeFirstChunk.assign(static_cast<size_t>(numTubes + 1), 0);
  for (vtkIdType t = 0; t < numTubes; ++t)
  {
    const vtkIdType segments = core->GetTubeNumberOfNodes()->GetValue(t) - 1;
    in.TubeFirstSegment[t + 1] = in.TubeFirstSegment[t] + segments;
    in.TubeFirstChunk[t + 1] =
      in.TubeFirstChunk[t] + (segments + vtkInternals::ChunkSize - 1) / vtkInternals::ChunkSize;
  }
  const vtkIdType numChunks = in.TubeFirstChunk[numTubes];
  in.ChunkFirstSegment.assign(static_cast<size_t>(numChunks + 1), 0);
  in.ChunkSphere.assign(static_cast<size_t>(4 * numChunks), 0.0f);
  in.ChunkMaxLength.assign(static_cast<size_t>(numChunks), 0.0f);
  in.ChunkMaxRadius.assign(static_cast<size_t>(numChunks), 0.0f);
  in.ChunkLength.assign(static_cast<size_t>(numChunks), 0.0f);
  in.ChunkRingBin.assign(static_cast<size_t>(numChunks), 0);
  in.ChunkThinLevels.assign(static_cast<size_t>(numChunks), 0);
  in.TubeSideBin.assign(static_cast<size_t>(numTubes), 0);
  in.LastView.clear();

  const float* P = core->GetNodePositions()->GetPointer(0);
  const float* M = core->GetNodeTangents()->GetPointer(0);
  const float* R = core->GetNodeRadii()->GetPointer(0);
  const vtkTypeUInt32* first = core->GetSegmentFirstNodes()->GetPointer(0);
  const double shift[3] = { this->Shift[0], this->Shift[1], this->Shift[2] };
  vtkSMPTools::For(0, numTubes,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType t = begin; t < end; ++t)
      {
        vtkIdType segment = in.TubeFirstSegment[t];
        const vtkIdType last = in.TubeFirstSegment[t + 1];
        for (vtkIdType c = in.TubeFirstChunk[t]; c < in.TubeFirstChunk[t + 1]; ++c)
        {
          in.ChunkFirstSegment[c] = segment;
          const vtkIdType stop = std::min(last, segment + vtkInternals::ChunkSize);
          double lo[3] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, VTK_DOUBLE_MAX };
          double hi[3] = { VTK_DOUBLE_MIN, VTK_DOUBLE_MIN, VTK_DOUBLE_MIN };
          double maxLength = 0.0;
          double totalLength = 0.0;
          double maxRadius = 0.0;
          for (; segment < stop; ++segment)
          {
            // The cubic Bezier control points of the position and radius
            // splines bound the segment (as in vtkSplineTubeCore::GetBounds).
            const vtkIdType i = first[segment];
            const vtkIdType j = i + 1;
            const double r =
              std::max({ static_cast<double>(R[2 * i]), static_cast<double>(R[2 * j]),
                R[2 * i] + R[2 * i + 1] / 3.0, R[2 * j] - R[2 * j + 1] / 3.0 });
            double control[4][3];
            for (int k = 0; k < 3; ++k)
            {
              control[0][k] = P[3 * i + k];
              control[1][k] = P[3 * i + k] + M[3 * i + k] / 3.0;
              control[2][k] = P[3 * j + k] - M[3 * j + k] / 3.0;
              control[3][k] = P[3 * j + k];
              for (int q = 0; q < 4; ++q)
              {
                lo[k] = std::min(lo[k], control[q][k] - r);
                hi[k] = std::max(hi[k], control[q][k] + r);
              }
            }
            double length = 0.0;
            for (int q = 0; q < 3; ++q)
            {
              length += std::sqrt(vtkMath::Distance2BetweenPoints(control[q], control[q + 1]));
            }
            maxLength = std::max(maxLength, length);
            totalLength += length;
            maxRadius = std::max(maxRadius, r);
          }
          double radius2 = 0.0;
          for (int k = 0; k < 3; ++k)
          {
            in.ChunkSphere[4 * c + k] = static_cast<float>(0.5 * (lo[k] + hi[k]) - shift[k]);
            radius2 += 0.25 * (hi[k] - lo[k]) * (hi[k] - lo[k]);
          }
          in.ChunkSphere[4 * c + 3] = static_cast<float>(std::sqrt(radius2));
          in.ChunkMaxLength[c] = static_cast<float>(maxLength);
          in.ChunkMaxRadius[c] = static_cast<float>(maxRadius);
          in.ChunkLength[c] = static_cast<float>(totalLength);
        }
      }
    });
  in.ChunkFirstSegment[numChunks] = core->GetNumberOfSegments();
}

//------------------------------------------------------------------------------
bool vtkTessellatedTubeMapper::BuildBaseMeshes()
{
  vtkInternals& in = *this->Internals;
  if (this->BaseMeshes && in.MeshBaseRings == this->BaseRings &&
    in.MeshBaseSides == this->BaseSides)
  {
    return true;
  }
  // The ladders: intervals along the segment halved down to 1; vertices per
  // ring halved down to 3.
  in.RingLadder.clear();
  for (int intervals = this->BaseRings - 1;; intervals = (intervals + 1) / 2)
  {
    in.RingLadder.push_back(intervals + 1);
    if (intervals == 1)
    {
      break;
    }
  }
  in.SideLadder.clear();
  for (int sides = this->BaseSides;; sides = (sides + 1) / 2)
  {
    in.SideLadder.push_back(sides);
    if ((sides + 1) / 2 < 4)
    {
      break;
    }
  }
  in.SideLadder.push_back(1); // one patch around the segment (thin tubes)

  // Quad patches (see vtkTessellatedTubeVS.glsl for the vertex numbering):
  // the walls of every (rings, sides), the caps of every sides (numbered as
  // a mesh of 2 rings: the first and the last ring of any segment).
  std::vector<unsigned int> indices;
  in.WallMeshes.clear();
  in.CapMeshes.clear();
  for (int sides : in.SideLadder)
  {
    const unsigned int perRing = static_cast<unsigned int>(sides + 1);
    for (int rings : in.RingLadder)
    {
      vtkInternals::MeshRange range;
      range.Offset = indices.size();
      for (int i = 0; i + 1 < rings; ++i)
      {
        for (int j = 0; j < sides; ++j)
        {
          const unsigned int a =
            static_cast<unsigned int>(i) * perRing + static_cast<unsigned int>(j);
          indices.insert(indices.end(), { a, a + 1, a + 1 + perRing, a + perRing });
        }
      }
      range.Count = indices.size() - range.Offset;
      in.WallMeshes[std::make_pair(rings, sides)] = range;
    }
    vtkInternals::MeshRange caps;
    caps.Offset = indices.size();
    const unsigned int startCenter = 2 * perRing;
    const unsigned int endCenter = startCenter + 1;
    for (int j = 0; j < sides; ++j)
    {
      const unsigned int a = static_cast<unsigned int>(j);
      indices.insert(indices.end(), { a, a + 1, startCenter, startCenter });
    }
    for (int j = 0; j < sides; ++j)
    {
      const unsigned int a = perRing + static_cast<unsigned int>(j);
      indices.insert(indices.end(), { a, a + 1, endCenter, endCenter });
    }
    caps.Count = indices.size() - caps.Offset;
    in.CapMeshes[sides] = caps;
  }
  // Thin-tube draws: triangles between consecutive rings of ThinRibbonSides
  // vertices (the silhouette points and the point nearest the eye, see
  // vtkTessellatedTubeThinVS.glsl), wound counter-clockwise seen from the
  // eye, the diagonals mirrored at the middle of the ring and of the run as
  // the tessellator's. One mesh serves every number n of rows: its rows
  // alternate between the run's start (row i: rings i, i + 1) and its end
  // (the mirror image, vertices numbered from the end ring: ThinMirrorRing +
  // rings before the end), so that the first n rows are the mesh of n rows.
  in.ThinLadder = { 1, 2, 3, 4, 5, 6, 7, 8, 10, 12, 14, 16, 20, 24, 28, 32, 40, 48, 56, 64 };
  in.ThinMesh.Offset = indices.size();
  {
    const int L = vtkInternals::ThinRibbonSides - 1;
    const auto perRing = static_cast<unsigned int>(vtkInternals::ThinRibbonSides);
    const unsigned int mirror = static_cast<unsigned int>(vtkInternals::ThinMirrorRing) * perRing;
    for (int row = 0; row < in.ThinLadder.back(); ++row)
    {
      const unsigned int i = static_cast<unsigned int>(row / 2);
      const bool fromEnd = (row & 1) != 0;
      for (int j = 0; j < L; ++j)
      {
        const unsigned int a = (fromEnd ? mirror : 0) + i * perRing + static_cast<unsigned int>(j);
        // Rows at the start: the diagonal from (j + 1, i) to (j, i + 1) on
        // the ring's second half; mirrored rows (reversed winding) likewise
        // in their numbering, which is the other diagonal in the run's.
        const bool other = 2 * j >= L;
        if (!fromEnd)
        {
          if (other)
          {
            indices.insert(
              indices.end(), { a, a + 1, a + perRing, a + 1, a + 1 + perRing, a + perRing });
          }
          else
          {
            indices.insert(
              indices.end(), { a, a + 1, a + 1 + perRing, a, a + 1 + perRing, a + perRing });
          }
        }
        else if (other)
        {
          indices.insert(
            indices.end(), { a, a + perRing, a + 1, a + 1, a + perRing, a + 1 + perRing });
        }
        else
        {
          indices.insert(
            indices.end(), { a, a + 1 + perRing, a + 1, a, a + perRing, a + 1 + perRing });
        }
      }
    }
  }
  in.ThinMesh.Count = indices.size() - in.ThinMesh.Offset;
  // Thin caps: the polygon as a fan from its vertex 0.
  in.ThinCapMesh.Offset = indices.size();
  for (unsigned int j = 1; j + 1 < static_cast<unsigned int>(vtkInternals::ThinCapSides); ++j)
  {
    indices.insert(indices.end(), { 0u, j, j + 1 });
  }
  in.ThinCapMesh.Count = indices.size() - in.ThinCapMesh.Offset;
  if (!this->BaseMeshes)
  {
    this->BaseMeshes = vtkSmartPointer<vtkOpenGLBufferObject>::New();
    this->BaseMeshes->SetType(vtkOpenGLBufferObject::ElementArrayBuffer);
  }
  if (!this->BaseMeshes->Upload(indices, vtkOpenGLBufferObject::ElementArrayBuffer))
  {
    vtkErrorMacro(<< "Could not upload the base meshes.");
    this->BaseMeshes = nullptr;
    return false;
  }
  in.MeshBaseRings = this->BaseRings;
  in.MeshBaseSides = this->BaseSides;
  in.MeshIndices = indices.size();
  in.LastView.clear();
  return true;
}

//------------------------------------------------------------------------------
bool vtkTessellatedTubeMapper::UpdateDraws(vtkRenderer* ren, vtkActor* act)
{
  vtkInternals& in = *this->Internals;
  vtkSplineTubeCore* core = this->Core;
  const vtkIdType numTubes = core->GetNumberOfTubes();
  const vtkIdType numChunks = static_cast<vtkIdType>(in.ChunkMaxLength.size());

  float modelView[16];
  float viewModel[16];
  float radiusScale = 1.0f;
  this->ComputeTubeMatrices(ren, act, modelView, viewModel, radiusScale);
  vtkMatrix4x4* vcdc = GetViewToDisplayMatrix(ren);
  double proj[4][4]; // the projection P (vcdc holds its transpose)
  for (int r = 0; r < 4; ++r)
  {
    for (int c = 0; c < 4; ++c)
    {
      proj[r][c] = vcdc->GetElement(c, r);
    }
  }
  int width = 1;
  int height = 1;
  ren->GetTiledSize(&width, &height);

  // Skip the classification when nothing it depends on changed.
  std::vector<double> view(modelView, modelView + 16);
  view.insert(view.end(), &proj[0][0], &proj[0][0] + 16);
  view.insert(view.end(),
    { static_cast<double>(width), static_cast<double>(height), radiusScale,
      this->LevelOfDetail ? 1.0 : 0.0, this->Capping ? 1.0 : 0.0, this->MaxEdgeLength,
      this->MaxSilhouetteEdgeLength, static_cast<double>(this->BaseRings),
      static_cast<double>(this->BaseSides), static_cast<double>(numChunks),
      static_cast<double>(this->MaxTessellationLevel),
      static_cast<double>(this->UploadTime.GetMTime()) });
  if (view == in.LastView)
  {
    return !in.Draws.empty();
  }

  const int ringBins = static_cast<int>(in.RingLadder.size());
  const int sideBins = static_cast<int>(in.SideLadder.size());
  if (!this->LevelOfDetail)
  {
    std::fill(in.ChunkRingBin.begin(), in.ChunkRingBin.end(), 0);
    std::fill(in.TubeSideBin.begin(), in.TubeSideBin.end(), 0);
  }
  else
  {
    // Frustum planes (view coordinates, normalized): row3 +- row0, +- row1, +- row2.
    double planes[6][4];
    for (int k = 0; k < 3; ++k)
    {
      for (int side = 0; side < 2; ++side)
      {
        double* p = planes[2 * k + side];
        for (int c = 0; c < 4; ++c)
        {
          p[c] = proj[3][c] + (side == 0 ? 1.0 : -1.0) * proj[k][c];
        }
        const double len = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
        for (int c = 0; c < 4 && len > 0.0; ++c)
        {
          p[c] /= len;
        }
      }
    }
    const double pixelScale =
      0.5 * std::max(proj[0][0] * width, proj[1][1] * height); // pixels per unit at w = 1
    const double wSlope =
      std::sqrt(proj[3][0] * proj[3][0] + proj[3][1] * proj[3][1] + proj[3][2] * proj[3][2]);
    const double ringTarget = 0.5 * this->MaxEdgeLength;
    const double sideTarget = 2.0 * this->MaxSilhouetteEdgeLength;
    const double twoPi = 2.0 * vtkMath::Pi();
    ThinView thin;
    thin.ModelView = modelView;
    std::copy(&proj[0][0], &proj[0][0] + 16, &thin.Proj[0][0]);
    thin.HalfViewport[0] = 0.5 * width;
    thin.HalfViewport[1] = 0.5 * height;
    thin.PixelScale = pixelScale;
    thin.RadiusScale = radiusScale;
    std::copy(this->Shift, this->Shift + 3, thin.Shift);
    thin.SideLength = 2.0 * this->MaxSilhouetteEdgeLength;
    thin.Edge = vtkSplineTubeMath::svThinEdgeFactor * this->MaxEdgeLength;
    thin.MaxLevel = this->MaxTessellationLevel;
    thin.Parallel = ren->GetActiveCamera()->GetParallelProjection() != 0;
    const float* nodeP = core->GetNodePositions()->GetPointer(0);
    const float* nodeM = core->GetNodeTangents()->GetPointer(0);
    const float* nodeR = core->GetNodeRadii()->GetPointer(0);
    const vtkTypeUInt32* firstNodes = core->GetSegmentFirstNodes()->GetPointer(0);
    const unsigned char* segmentFlags = core->GetSegmentFlags()->GetPointer(0);
    in.ThinCaps.resize(static_cast<size_t>(core->GetNumberOfSegments()));
    const std::vector<int>& ladder = in.ThinLadder;
    vtkSMPTools::For(0, numTubes,
      [&](vtkIdType begin, vtkIdType end)
      {
        std::vector<double> chunkPixels;
        for (vtkIdType t = begin; t < end; ++t)
        {
          chunkPixels.clear();
          double widest = -1.0; // pixels; < 0: the tube is culled
          for (vtkIdType c = in.TubeFirstChunk[t]; c < in.TubeFirstChunk[t + 1]; ++c)
          {
            const float* sphere = &in.ChunkSphere[4 * c];
            double center[3];
            for (int r = 0; r < 3; ++r)
            {
              center[r] = modelView[r] * sphere[0] + modelView[4 + r] * sphere[1] +
                modelView[8 + r] * sphere[2] + modelView[12 + r];
            }
            const double radius = sphere[3] * radiusScale;
            bool outside = false;
            for (int k = 0; k < 6 && !outside; ++k)
            {
              outside = planes[k][0] * center[0] + planes[k][1] * center[1] +
                  planes[k][2] * center[2] + planes[k][3] <
                -radius;
            }
            if (outside)
            {
              in.ChunkRingBin[c] = vtkInternals::Culled;
              chunkPixels.push_back(-1.0);
              continue;
            }
            const double w = proj[3][0] * center[0] + proj[3][1] * center[1] +
              proj[3][2] * center[2] + proj[3][3] - wSlope * radius;
            int ringBin = 0;
            double radiusPixels = VTK_DOUBLE_MAX;
            double lengthPixels = VTK_DOUBLE_MAX;
            if (w > 1e-6 * (std::abs(proj[3][3]) + std::abs(center[2]) + radius))
            {
              const double scale = pixelScale * radiusScale / w;
              lengthPixels = in.ChunkLength[c] * scale;
              const double intervals = in.ChunkMaxLength[c] * scale / ringTarget;
              radiusPixels = in.ChunkMaxRadius[c] * scale;
              ringBin = ringBins - 1;
              while (ringBin > 0 && in.RingLadder[ringBin] - 1 < intervals)
              {
                --ringBin;
              }
            }
            in.ChunkRingBin[c] = static_cast<unsigned char>(ringBin);
            chunkPixels.push_back(lengthPixels);
            widest = std::max(widest, radiusPixels);
          }
          // Sides: one patch around when at most SinglePatchSides ring edges
          // are needed (the tessellator makes them), else the fewest base
          // vertices that the silhouette refinement can at least double to
          // the need.
          int sideBin = vtkInternals::Culled;
          if (widest >= 0.0)
          {
            const double sides = twoPi * widest / sideTarget;
            sideBin = sideBins - 1;
            if (sides > vtkInternals::SinglePatchSides)
            {
              sideBin = sideBins - 2;
              while (sideBin > 0 && in.SideLadder[sideBin] < 0.5 * sides)
              {
                --sideBin;
              }
            }
          }
          in.TubeSideBin[t] = static_cast<unsigned char>(sideBin);
          // Thin tubes: a chunk whose length on screen fits the largest
          // tessellation level with 4-pixel edges is drawn without the
          // tessellator (a thin-tube draw, its levels computed here) unless
          // its rings need more than ThinMaxSides intervals; then it becomes
          // one patch. Longer chunks: each segment is one patch (2 rings)
          // whose level along the control stage sets from the segment's
          // length and bending.
          if (sideBin == sideBins - 1)
          {
            for (vtkIdType c = in.TubeFirstChunk[t]; c < in.TubeFirstChunk[t + 1]; ++c)
            {
              const double pixels = chunkPixels[c - in.TubeFirstChunk[t]];
              if (pixels < 0.0)
              {
                continue;
              }
              const vtkIdType count = in.ChunkFirstSegment[c + 1] - in.ChunkFirstSegment[c];
              if (pixels <= vtkInternals::WholeChunkPixels)
              {
                double along = 1.0;
                double ring0 = 3.0;
                double ring1 = 3.0;
                ThinChunkLevels(thin, nodeP, nodeM, nodeR, firstNodes[in.ChunkFirstSegment[c]],
                  count, along, ring0, ring1);
                if (std::max(ring0, ring1) <= vtkInternals::ThinMaxSides)
                {
                  size_t rung = 0;
                  while (rung + 1 < ladder.size() && ladder[rung] < along)
                  {
                    ++rung;
                  }
                  in.ChunkRingBin[c] = vtkInternals::ThinChunk;
                  in.ChunkThinLevels[c] = static_cast<vtkTypeUInt32>(rung);
                  for (vtkIdType s = in.ChunkFirstSegment[c];
                       this->Capping && s < in.ChunkFirstSegment[c + 1]; ++s)
                  {
                    unsigned char visible = 0;
                    for (int kind = 1; kind <= 2; ++kind)
                    {
                      if ((segmentFlags[s] & kind) != 0 &&
                        ThinCapVisible(thin,
                          ToView(thin, nodeP, nodeM, nodeR, firstNodes[s] + (kind == 2 ? 1 : 0)),
                          kind))
                      {
                        visible |= static_cast<unsigned char>(kind);
                      }
                    }
                    in.ThinCaps[s] = visible;
                  }
                  continue;
                }
              }
              in.ChunkRingBin[c] = pixels <= vtkInternals::WholeChunkPixels && count > 1
                ? vtkInternals::WholeChunk
                : static_cast<unsigned char>(ringBins - 1);
            }
          }
        }
      });
  }

  // Bins: walls per (rings, sides), caps per sides, whole chunks (2 list
  // entries each); then the instance list.
  const int bins = ringBins * sideBins;
  const int chunkBin = bins + sideBins;
  const int thinBase = chunkBin + 1;
  const int thinBins = static_cast<int>(in.ThinLadder.size());
  const int thinCapBin = thinBase + thinBins; // (segment, kind) pairs
  auto thinBin = [&](vtkTypeUInt32 rung) { return thinBase + static_cast<int>(rung); };
  std::vector<vtkIdType> counts(static_cast<size_t>(thinCapBin + 1), 0);
  in.CulledSegments = 0;
  const unsigned char* flags = core->GetSegmentFlags()->GetPointer(0);
  for (vtkIdType t = 0; t < numTubes; ++t)
  {
    const int sideBin = in.TubeSideBin[t];
    for (vtkIdType c = in.TubeFirstChunk[t]; c < in.TubeFirstChunk[t + 1]; ++c)
    {
      const vtkIdType n = in.ChunkFirstSegment[c + 1] - in.ChunkFirstSegment[c];
      if (sideBin == vtkInternals::Culled || in.ChunkRingBin[c] == vtkInternals::Culled)
      {
        in.CulledSegments += n;
        continue;
      }
      if (in.ChunkRingBin[c] == vtkInternals::WholeChunk)
      {
        counts[chunkBin] += 2;
      }
      else if (in.ChunkRingBin[c] == vtkInternals::ThinChunk)
      {
        counts[thinBin(in.ChunkThinLevels[c])] += 2;
      }
      else
      {
        counts[in.ChunkRingBin[c] * sideBins + sideBin] += n;
      }
      if (this->Capping && in.ChunkRingBin[c] == vtkInternals::ThinChunk)
      {
        for (vtkIdType s = in.ChunkFirstSegment[c]; s < in.ChunkFirstSegment[c + 1]; ++s)
        {
          if (flags[s] != 0)
          {
            counts[thinCapBin] += 2 * ((in.ThinCaps[s] & 1) + (in.ThinCaps[s] >> 1));
          }
        }
      }
      else if (this->Capping)
      {
        for (vtkIdType s = in.ChunkFirstSegment[c]; s < in.ChunkFirstSegment[c + 1]; ++s)
        {
          counts[bins + sideBin] += flags[s] != 0 ? 1 : 0;
        }
      }
    }
  }
  std::vector<vtkIdType> offsets(counts.size() + 1, 0);
  for (size_t b = 0; b < counts.size(); ++b)
  {
    offsets[b + 1] = offsets[b] + counts[b];
  }
  in.Instances.resize(static_cast<size_t>(std::max<vtkIdType>(offsets.back(), 1)));
  std::vector<vtkIdType> cursor(offsets.begin(), offsets.end() - 1);
  for (vtkIdType t = 0; t < numTubes; ++t)
  {
    const int sideBin = in.TubeSideBin[t];
    if (sideBin == vtkInternals::Culled)
    {
      continue;
    }
    for (vtkIdType c = in.TubeFirstChunk[t]; c < in.TubeFirstChunk[t + 1]; ++c)
    {
      if (in.ChunkRingBin[c] == vtkInternals::Culled)
      {
        continue;
      }
      const bool thinChunk = in.ChunkRingBin[c] == vtkInternals::ThinChunk;
      if (thinChunk)
      {
        const vtkTypeUInt32 levels = in.ChunkThinLevels[c];
        vtkIdType& entry = cursor[thinBin(levels)];
        in.Instances[entry++] = static_cast<vtkTypeUInt32>(in.ChunkFirstSegment[c]);
        // (count | whether the run starts and ends its tube << 8)
        const vtkIdType last = in.ChunkFirstSegment[c + 1] - 1;
        in.Instances[entry++] =
          static_cast<vtkTypeUInt32>(in.ChunkFirstSegment[c + 1] - in.ChunkFirstSegment[c]) |
          (static_cast<vtkTypeUInt32>((flags[in.ChunkFirstSegment[c]] & 1) | (flags[last] & 2))
            << 8);
      }
      const bool whole = thinChunk || in.ChunkRingBin[c] == vtkInternals::WholeChunk;
      if (whole && !thinChunk)
      {
        vtkIdType& entry = cursor[chunkBin];
        in.Instances[entry++] = static_cast<vtkTypeUInt32>(in.ChunkFirstSegment[c]);
        in.Instances[entry++] =
          static_cast<vtkTypeUInt32>(in.ChunkFirstSegment[c + 1] - in.ChunkFirstSegment[c]);
      }
      vtkIdType& wall = cursor[whole ? 0 : in.ChunkRingBin[c] * sideBins + sideBin];
      for (vtkIdType s = in.ChunkFirstSegment[c]; s < in.ChunkFirstSegment[c + 1]; ++s)
      {
        if (!whole)
        {
          in.Instances[wall++] = static_cast<vtkTypeUInt32>(s);
        }
        if (this->Capping && flags[s] != 0 && thinChunk)
        {
          for (vtkTypeUInt32 kind = 1; kind <= 2; ++kind)
          {
            if ((in.ThinCaps[s] & kind) != 0)
            {
              in.Instances[cursor[thinCapBin]++] = static_cast<vtkTypeUInt32>(s);
              in.Instances[cursor[thinCapBin]++] = kind;
            }
          }
        }
        else if (this->Capping && flags[s] != 0)
        {
          in.Instances[cursor[bins + sideBin]++] = static_cast<vtkTypeUInt32>(s);
        }
      }
    }
  }
  in.Draws.clear();
  for (int b = 0; b <= chunkBin; ++b)
  {
    if (counts[b] == 0)
    {
      continue;
    }
    vtkInternals::Draw draw;
    draw.Thin = false;
    draw.Caps = b >= bins && b < chunkBin;
    draw.Chunks = b == chunkBin;
    draw.Rings = (draw.Caps || draw.Chunks) ? 2 : in.RingLadder[b / sideBins];
    draw.Sides = draw.Chunks ? 1 : in.SideLadder[draw.Caps ? b - bins : b % sideBins];
    draw.Offset = offsets[b];
    draw.Count = draw.Chunks ? counts[b] / 2 : counts[b];
    in.Draws.push_back(draw);
  }
  for (int b = thinBase; b < thinBase + thinBins; ++b)
  {
    if (counts[b] == 0)
    {
      continue;
    }
    vtkInternals::Draw draw;
    draw.Thin = true;
    draw.Caps = false;
    draw.Chunks = false;
    draw.Rings = in.ThinLadder[static_cast<size_t>(b - thinBase)] + 1;
    draw.Sides = vtkInternals::ThinRibbonSides;
    draw.Offset = offsets[b];
    draw.Count = counts[b] / 2;
    in.Draws.push_back(draw);
  }
  if (counts[thinCapBin] > 0)
  {
    vtkInternals::Draw draw;
    draw.Thin = true;
    draw.Caps = true;
    draw.Chunks = false;
    draw.Rings = 1;
    draw.Sides = vtkInternals::ThinCapSides;
    draw.Offset = offsets[thinCapBin];
    draw.Count = counts[thinCapBin] / 2;
    in.Draws.push_back(draw);
  }
  auto* window = static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow());
  if (!in.InstancesBuffer.Upload(window, in.Instances.data(), static_cast<size_t>(offsets.back()),
        1, VTK_TYPE_UINT32, GL_R32UI))
  {
    vtkErrorMacro(<< "Could not upload the instance list: "
                  << vtkSplineVizGPUBuffer::GetLastUploadError());
    in.Draws.clear();
  }
  in.LastView = view;
  return !in.Draws.empty();
}

//------------------------------------------------------------------------------
std::string vtkTessellatedTubeMapper::GetLevelOfDetailSummary()
{
  vtkInternals& in = *this->Internals;
  std::ostringstream s;
  for (const auto& draw : in.Draws)
  {
    s << (draw.Caps ? "caps " : "") << (draw.Chunks ? "chunks " : "") << (draw.Thin ? "thin " : "")
      << draw.Rings << " x " << draw.Sides << ": " << draw.Count << "; ";
  }
  s << "culled: " << in.CulledSegments;
  return s.str();
}

//------------------------------------------------------------------------------
std::string vtkTessellatedTubeMapper::GetTessellationControlShaderSource()
{
  std::string source = vtkTessellatedTubeTCS;
  vtkShaderProgram::Substitute(source, "//VTK::SplineTubeMath::Dec", TubeMathSource());
  vtkShaderProgram::Substitute(source, "//VTK::TessellatedTubeCommon::Dec", CommonSource());
  return source;
}

//------------------------------------------------------------------------------
std::string vtkTessellatedTubeMapper::GetTessellationEvaluationShaderSource()
{
  std::string source = vtkTessellatedTubeTES;
  vtkShaderProgram::Substitute(source, "//VTK::SplineTubeMath::Dec", TubeMathSource());
  vtkShaderProgram::Substitute(source, "//VTK::TessellatedTubeCommon::Dec", CommonSource());
  return source;
}

//------------------------------------------------------------------------------
bool vtkTessellatedTubeMapper::LinkTessellationStages(
  vtkShaderProgram* program, vtkOpenGLRenderWindow*)
{
  const GLuint handle = static_cast<GLuint>(program->GetHandle());
  GLint attached = 0;
  glGetProgramiv(handle, GL_ATTACHED_SHADERS, &attached);
  std::vector<GLuint> shaders(static_cast<size_t>(std::max(attached, 1)));
  GLsizei count = 0;
  glGetAttachedShaders(handle, static_cast<GLsizei>(shaders.size()), &count, shaders.data());
  for (GLsizei i = 0; i < count; ++i)
  {
    GLint type = 0;
    glGetShaderiv(shaders[i], GL_SHADER_TYPE, &type);
    if (type == GL_TESS_EVALUATION_SHADER)
    {
      return true; // linked with them already (a program shared through VTK's cache)
    }
  }

  if (!this->ControlShader || !this->EvaluationShader)
  {
    GLint major = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    this->StagesVersion = major >= 4
      ? "#version 400 core\n"
      : "#version 150\n#extension GL_ARB_tessellation_shader : require\n";
    std::string error;
    const std::string control = this->StagesVersion + this->GetTessellationControlShaderSource();
    this->ControlShader = CompileStage(GL_TESS_CONTROL_SHADER, control, error);
    if (!this->ControlShader)
    {
      vtkErrorMacro(<< "The tessellation control stage did not compile:\n" << error);
      return false;
    }
    const std::string evaluation =
      this->StagesVersion + this->GetTessellationEvaluationShaderSource();
    this->EvaluationShader = CompileStage(GL_TESS_EVALUATION_SHADER, evaluation, error);
    if (!this->EvaluationShader)
    {
      vtkErrorMacro(<< "The tessellation evaluation stage did not compile:\n" << error);
      this->ReleaseTessellationStages();
      return false;
    }
  }

  glAttachShader(handle, this->ControlShader);
  glAttachShader(handle, this->EvaluationShader);
  glLinkProgram(handle);
  GLint linked = 0;
  glGetProgramiv(handle, GL_LINK_STATUS, &linked);
  if (!linked)
  {
    GLint length = 0;
    glGetProgramiv(handle, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(static_cast<size_t>(std::max(length, 1)), '\0');
    glGetProgramInfoLog(handle, static_cast<GLsizei>(log.size()), nullptr, log.data());
    vtkErrorMacro(<< "Linking the tessellation stages failed: " << log.data());
    glDetachShader(handle, this->ControlShader);
    glDetachShader(handle, this->EvaluationShader);
    return false;
  }
  // The program is bound (VTK's shader cache bound it); make the new
  // executable current explicitly.
  glUseProgram(handle);
  return true;
}

//------------------------------------------------------------------------------
void vtkTessellatedTubeMapper::UpdateShaders(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  // As vtkOpenGLPolyDataMapper::UpdateShaders, with the tessellation stages
  // linked in right after VTK's shader cache compiled and linked the
  // program: its uniform locations are looked up only afterwards.
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  cellBO.VAO->Bind();
  this->LastBoundBO = &cellBO;

  vtkShaderProgram* program = nullptr;
  if (this->GetNeedToRebuildShaders(cellBO, ren, act))
  {
    std::map<vtkShader::Type, vtkShader*> shaders;
    vtkNew<vtkShader> vs;
    vs->SetType(vtkShader::Vertex);
    vtkNew<vtkShader> gs;
    gs->SetType(vtkShader::Geometry);
    vtkNew<vtkShader> fs;
    fs->SetType(vtkShader::Fragment);
    shaders[vtkShader::Vertex] = vs;
    shaders[vtkShader::Geometry] = gs;
    shaders[vtkShader::Fragment] = fs;
    this->BuildShaders(shaders, ren, act);
    program = window->GetShaderCache()->ReadyShaderProgram(shaders);
    if (this->BuildingThinProgram)
    {
      // thin-tube draws: no tessellation stages
    }
    else if (program && !this->StagesFailed && !this->LinkTessellationStages(program, window))
    {
      this->StagesFailed = true; // reported; do not retry every frame
    }
    if (this->StagesFailed && !this->BuildingThinProgram)
    {
      program = nullptr;
    }
    if (program != cellBO.Program || (program && program->GetMTime() > cellBO.AttributeUpdateTime))
    {
      cellBO.Program = program;
      cellBO.VAO->ReleaseGraphicsResources();
    }
    cellBO.ShaderSourceTime.Modified();
  }
  else if (cellBO.Program)
  {
    program = window->GetShaderCache()->ReadyShaderProgram(cellBO.Program);
    // A program VTK had to compile again lost our stages: link them again.
    if (program && !this->BuildingThinProgram && !this->LinkTessellationStages(program, window))
    {
      this->StagesFailed = true;
      program = nullptr;
    }
    if (!program)
    {
      cellBO.Program = nullptr;
    }
    else if (program->GetMTime() > cellBO.AttributeUpdateTime)
    {
      cellBO.VAO->ReleaseGraphicsResources();
    }
  }

  if (cellBO.Program)
  {
    this->SetCustomUniforms(cellBO, act);
    this->SetMapperShaderParameters(cellBO, ren, act);
    this->SetPropertyShaderParameters(cellBO, ren, act);
    this->SetCameraShaderParameters(cellBO, ren, act);
    this->SetLightingShaderParameters(cellBO, ren, act);
    this->InvokeEvent(vtkCommand::UpdateShaderEvent, cellBO.Program);
  }
}

//------------------------------------------------------------------------------
void vtkTessellatedTubeMapper::GetShaderTemplate(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act)
{
  this->Superclass::GetShaderTemplate(shaders, ren, act);
  shaders[vtkShader::Vertex]->SetSource(
    this->BuildingThinProgram ? vtkTessellatedTubeThinVS : vtkTessellatedTubeVS);
  shaders[vtkShader::Geometry]->SetSource("");
}

//------------------------------------------------------------------------------
void vtkTessellatedTubeMapper::ReplaceShaderValues(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act)
{
  std::string VSSource = shaders[vtkShader::Vertex]->GetSource();
  std::string FSSource = shaders[vtkShader::Fragment]->GetSource();
  const std::string math = TubeMathSource();

  vtkShaderProgram::Substitute(VSSource, "//VTK::SplineTubeMath::Dec", math);
  vtkShaderProgram::Substitute(VSSource, "//VTK::TessellatedTubeCommon::Dec", CommonSource());
  // VTK's shader cache identifies programs by their vertex, geometry and
  // fragment sources: make the tessellation stages part of the key.
  if (!this->BuildingThinProgram)
  {
    const size_t stagesKey = std::hash<std::string>()(
      this->GetTessellationControlShaderSource() + this->GetTessellationEvaluationShaderSource());
    VSSource += "\n// tessellation stages " + std::to_string(stagesKey) + "\n";
  }

  std::string declarations =
    this->BuildingThinProgram ? vtkTessellatedTubeThinFS : vtkTessellatedTubeFS;
  vtkShaderProgram::Substitute(declarations, "//VTK::SplineTubeMath::Dec", math);
  vtkShaderProgram::Substitute(FSSource, "//VTK::Normal::Dec", declarations);
  vtkShaderProgram::Substitute(FSSource, "//VTK::PositionVC::Dec", "in vec4 vertexVCVSOutput;");
  std::string position = "  vec4 vertexVC = vertexVCVSOutput;\n";
  if (this->HaveColors)
  {
    // The color spline, evaluated per vertex by the evaluation stage.
    position += "  vec4 tubeColor = tubeColorVSOutput;\n";
  }
  vtkShaderProgram::Substitute(FSSource, "//VTK::PositionVC::Impl", position);
  if (this->BuildingThinProgram)
  {
    // Thin walls: the front surface along the ray from the ribbon (depth and
    // normal); caps as drawn. The vertex stage turns the caps' normals to the
    // eye (their walls show only front faces): no gl_FrontFacing flip.
    vtkShaderProgram::Substitute(FSSource, "//VTK::Depth::Impl",
      std::string("  vec3 tubeThinNormal = tubeNormalVCVSOutput.xyz;\n"
                  "  if (tubeAxisVCVSOutput.w > 0.0)\n"
                  "  {\n"
                  "    vec3 tubeHitVC;\n"
                  "    if (!tubeThinSurface(vertexVC.xyz, tubeHitVC, tubeThinNormal))\n"
                  "    {\n"
                  "      discard;\n"
                  "    }\n"
                  "    vertexVC = vec4(tubeHitVC, 1.0);\n"
                  "    vec4 tubeHitDC = VCDCMatrix * vertexVC;\n"
                  "    gl_FragDepth = 0.5 * (gl_DepthRange.diff * (tubeHitDC.z / tubeHitDC.w) +\n"
                  "      gl_DepthRange.near + gl_DepthRange.far);\n"
                  "  }\n"
                  "  else\n"
                  "  {\n"
                  "    gl_FragDepth = gl_FragCoord.z;\n"
                  "  }\n") +
        GetFragDepthWrittenMarker());
    vtkShaderProgram::Substitute(
      FSSource, "//VTK::Normal::Impl", "  vec3 normalVCVSOutput = normalize(tubeThinNormal);\n");
  }
  else
  {
    // The start caps are wound clockwise (seen from outside): flip their
    // sense of gl_FrontFacing.
    vtkShaderProgram::Substitute(FSSource, "//VTK::Normal::Impl",
      "  vec3 normalVCVSOutput = normalize(tubeNormalVCVSOutput);\n"
      "  if (gl_FrontFacing != (((tubeInfoVSOutput.w >> 2) & 3) != 1))\n"
      "  {\n"
      "    normalVCVSOutput = -normalVCVSOutput;\n"
      "  }\n");
  }

  // Picking: the cell is the polyline, the composite index its block.
  this->ReplaceShaderTubePicking(FSSource, "tubeInfoVSOutput.z");

  shaders[vtkShader::Vertex]->SetSource(VSSource);
  shaders[vtkShader::Fragment]->SetSource(FSSource);

  this->Superclass::ReplaceShaderValues(shaders, ren, act);
  if (this->BuildingThinProgram)
  {
    // Render passes (depth peeling) compare gl_FragCoord.z with their depth
    // textures; for thin walls the depth is the one written above.
    FSSource = shaders[vtkShader::Fragment]->GetSource();
    UseWrittenFragDepth(FSSource);
    shaders[vtkShader::Fragment]->SetSource(FSSource);
  }

  DumpShaderSources(
    { { this->BuildingThinProgram ? "ThinVS" : "VS", shaders[vtkShader::Vertex]->GetSource() },
      { "TCS", this->GetTessellationControlShaderSource() },
      { "TES", this->GetTessellationEvaluationShaderSource() },
      { "FS", shaders[vtkShader::Fragment]->GetSource() } });
}

//------------------------------------------------------------------------------
void vtkTessellatedTubeMapper::ReplaceShaderClip(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer*, vtkActor*)
{
  // Clip per fragment.
  std::string FSSource = shaders[vtkShader::Fragment]->GetSource();
  this->ReplaceShaderTubeClip(FSSource, "//VTK::Clip::Impl");
  shaders[vtkShader::Fragment]->SetSource(FSSource);
}

//------------------------------------------------------------------------------
void vtkTessellatedTubeMapper::SetMapperShaderParameters(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  this->Superclass::SetMapperShaderParameters(cellBO, ren, act);
  vtkShaderProgram* program = cellBO.Program;
  program->SetUniformf("tubeMaxEdgeLength", static_cast<float>(this->MaxEdgeLength));
  program->SetUniformf(
    "tubeSilhouetteEdgeLength", static_cast<float>(this->MaxSilhouetteEdgeLength));
  program->SetUniformf("tubeMaxLevel", static_cast<float>(this->MaxTessellationLevel));
  program->SetUniformf(
    "tubeMaxSilhouetteLevel", static_cast<float>(this->MaxSilhouetteTessellationLevel));
  program->SetUniformi("tubeCaps", this->Capping ? 1 : 0);
  program->SetUniformi("tubeHaveColors", this->HaveColors ? 1 : 0);
  program->SetUniformf("tubeSideLength", static_cast<float>(2.0 * this->MaxSilhouetteEdgeLength));
  this->FramesBuffer->Activate(program, "tubeFrames");
  this->Internals->InstancesBuffer.Activate(program, "tubeInstances");
}

//------------------------------------------------------------------------------
void vtkTessellatedTubeMapper::SetCameraShaderParameters(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  this->Superclass::SetCameraShaderParameters(cellBO, ren, act);
  vtkShaderProgram* program = cellBO.Program;
  vtkMatrix4x4* vcdc = GetViewToDisplayMatrix(ren);

  int width = 1;
  int height = 1;
  ren->GetTiledSize(&width, &height);
  const float viewport[2] = { static_cast<float>(std::max(width, 1)),
    static_cast<float>(std::max(height, 1)) };
  program->SetUniform2f("tubeViewport", viewport);

  // Frustum planes in view coordinates from the rows of the projection P
  // (vcdc holds P transposed): row3 +- row0, row3 +- row1, row3 +- row2.
  float planes[6][4];
  auto P = [vcdc](int r, int c) { return vcdc->GetElement(c, r); };
  for (int k = 0; k < 3; ++k)
  {
    for (int side = 0; side < 2; ++side)
    {
      const double sign = side == 0 ? 1.0 : -1.0;
      double p[4];
      for (int c = 0; c < 4; ++c)
      {
        p[c] = P(3, c) + sign * P(k, c);
      }
      const double len = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
      for (int c = 0; c < 4; ++c)
      {
        planes[2 * k + side][c] = static_cast<float>(len > 0.0 ? p[c] / len : 0.0);
      }
    }
  }
  program->SetUniform4fv("tubeFrustum", 6, planes);
}

//------------------------------------------------------------------------------
void vtkTessellatedTubeMapper::RenderPieceDraw(vtkRenderer* ren, vtkActor* act)
{
  this->NumberOfPrimitivesGenerated = 0;
  vtkInternals& in = *this->Internals;
  if (this->Core->GetNumberOfSegments() == 0 || this->GetTubeBuffersSize() == 0)
  {
    return;
  }
  auto* window = static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow());
  if (!this->BuildBaseMeshes() || !this->UpdateDraws(ren, act))
  {
    return;
  }
  const bool haveThin = std::any_of(
    in.Draws.begin(), in.Draws.end(), [](const vtkInternals::Draw& d) { return d.Thin; });
  const bool havePatches = std::any_of(
    in.Draws.begin(), in.Draws.end(), [](const vtkInternals::Draw& d) { return !d.Thin; });

  // The walls are wound counter-clockwise seen from outside: the rasterizer
  // culls their back faces (the control stage culled most back patches
  // already). The start caps are wound the other way: no culling for caps
  // (the control stage culls caps turned away).
  vtkOpenGLState* state = window->GetState();
  vtkOpenGLState::ScopedglEnableDisable cull(state, GL_CULL_FACE);
  GLint cullMode = GL_BACK;
  state->vtkglGetIntegerv(GL_CULL_FACE_MODE, &cullMode);
  state->vtkglCullFace(GL_BACK);
  // The wireframe representation shows the tessellation (VTK 9.2 does not
  // track the polygon mode: restore the default).
  const bool wireframe = act->GetProperty()->GetRepresentation() == VTK_WIREFRAME;
  if (wireframe)
  {
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  }
  if (this->CountPrimitives)
  {
    if (!this->PrimitivesQuery)
    {
      glGenQueries(1, &this->PrimitivesQuery);
    }
    glBeginQuery(GL_PRIMITIVES_GENERATED, this->PrimitivesQuery);
  }

  // Patches through the tessellation stages.
  vtkOpenGLHelper& helper = this->Primitives[PrimitiveTris];
  if (havePatches)
  {
    this->UpdateShaders(helper, ren, act);
  }
  if (havePatches && helper.Program)
  {
    vtkShaderProgram* program = helper.Program;
    // UpdateShaders() may have released the VAO after binding it (new
    // program); the draw has no attributes but core profiles need a VAO.
    helper.VAO->Bind();
    this->BaseMeshes->Bind();
    glPatchParameteri(GL_PATCH_VERTICES, 4);
    for (const auto& draw : in.Draws)
    {
      if (draw.Thin)
      {
        continue;
      }
      const vtkInternals::MeshRange& mesh = draw.Caps
        ? in.CapMeshes[draw.Sides]
        : in.WallMeshes[std::make_pair(draw.Rings, draw.Sides)];
      if (draw.Caps)
      {
        state->vtkglDisable(GL_CULL_FACE);
      }
      else
      {
        state->vtkglEnable(GL_CULL_FACE);
      }
      program->SetUniformi("tubeRings", draw.Rings);
      program->SetUniformi("tubeSides", draw.Sides);
      program->SetUniformi("tubeListOffset", static_cast<int>(draw.Offset));
      program->SetUniformi("tubeChunks", draw.Chunks ? 1 : 0);
      glDrawElementsInstanced(GL_PATCHES, static_cast<GLsizei>(mesh.Count), GL_UNSIGNED_INT,
        reinterpret_cast<const void*>(mesh.Offset * sizeof(unsigned int)),
        static_cast<GLsizei>(draw.Count));
    }
    this->BaseMeshes->Release();
  }

  // Thin tubes: triangles from the vertex stage alone (a second program).
  vtkOpenGLHelper& thinHelper = this->Primitives[PrimitiveTriStrips];
  if (haveThin)
  {
    this->BuildingThinProgram = true;
    this->UpdateShaders(thinHelper, ren, act);
    this->BuildingThinProgram = false;
  }
  if (haveThin && thinHelper.Program)
  {
    vtkShaderProgram* program = thinHelper.Program;
    thinHelper.VAO->Bind();
    this->BaseMeshes->Bind();
    state->vtkglEnable(GL_CULL_FACE);
    for (const auto& draw : in.Draws)
    {
      if (!draw.Thin)
      {
        continue;
      }
      program->SetUniformi("tubeListOffset", static_cast<int>(draw.Offset));
      program->SetUniformi("tubeCapDraw", draw.Caps ? 1 : 0);
      if (draw.Caps)
      {
        // (the start caps are wound the other way: no culling, as for the
        // caps' patches)
        state->vtkglDisable(GL_CULL_FACE);
        glDrawElementsInstanced(GL_TRIANGLES, static_cast<GLsizei>(in.ThinCapMesh.Count),
          GL_UNSIGNED_INT,
          reinterpret_cast<const void*>(in.ThinCapMesh.Offset * sizeof(unsigned int)),
          static_cast<GLsizei>(draw.Count));
        state->vtkglEnable(GL_CULL_FACE);
        continue;
      }
      const size_t rows = static_cast<size_t>(draw.Rings - 1);
      program->SetUniformi("tubeRings", draw.Rings);
      glDrawElementsInstanced(GL_TRIANGLES,
        static_cast<GLsizei>(6 * rows * (vtkInternals::ThinRibbonSides - 1)), GL_UNSIGNED_INT,
        reinterpret_cast<const void*>(in.ThinMesh.Offset * sizeof(unsigned int)),
        static_cast<GLsizei>(draw.Count));
    }
    this->BaseMeshes->Release();
  }

  if (this->CountPrimitives)
  {
    glEndQuery(GL_PRIMITIVES_GENERATED);
    GLuint64 count = 0;
    glGetQueryObjectui64v(this->PrimitivesQuery, GL_QUERY_RESULT, &count);
    this->NumberOfPrimitivesGenerated = static_cast<vtkTypeUInt64>(count);
  }
  if (wireframe)
  {
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  }
  state->vtkglCullFace(static_cast<unsigned int>(cullMode));
  this->DeactivateTubeBuffers();
  this->FramesBuffer->Deactivate();
  in.InstancesBuffer.Deactivate();
}

//------------------------------------------------------------------------------
void vtkTessellatedTubeMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "MaxEdgeLength: " << this->MaxEdgeLength << "\n";
  os << indent << "MaxSilhouetteEdgeLength: " << this->MaxSilhouetteEdgeLength << "\n";
  os << indent << "MaxTessellationLevel: " << this->MaxTessellationLevel << "\n";
  os << indent << "MaxSilhouetteTessellationLevel: " << this->MaxSilhouetteTessellationLevel
     << "\n";
  os << indent << "BaseRings: " << this->BaseRings << "\n";
  os << indent << "BaseSides: " << this->BaseSides << "\n";
  os << indent << "LevelOfDetail: " << (this->LevelOfDetail ? "On" : "Off") << "\n";
  os << indent << "Capping: " << (this->Capping ? "On" : "Off") << "\n";
  os << indent << "CountPrimitives: " << (this->CountPrimitives ? "On" : "Off") << "\n";
  os << indent << "UsingFallback: " << (this->UsingFallback ? "yes" : "no") << "\n";
}
