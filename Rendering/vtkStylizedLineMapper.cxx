#include "vtkStylizedLineMapper.h"

#include "vtkSplineTubeCore.h"
#include "vtkSplineTubeMath.h"
#include "vtkSplineVizGPUBuffer.h"
#include "vtkStylizedLineFixUp.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkFloatArray.h"
#include "vtkHardwareSelector.h"
#include "vtkIdTypeArray.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkRenderer.h"
#include "vtkSMPTools.h"
#include "vtkShader.h"
#include "vtkShaderProgram.h"
#include "vtkTexture.h"
#include "vtkTypeUInt32Array.h"

#include "vtkSplineTubeMathPrelude.h"
#include "vtkSplineTubeMathShared.h"
#include "vtkStylizedLineFS.h"
#include "vtkStylizedLineMathShared.h"
#include "vtkStylizedLineVS.h"

#include <vtk_glew.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

vtkStandardNewMacro(vtkStylizedLineMapper);

namespace
{
/// Largest depth-correction distance, in radii (the view ray 7 degrees from
/// the tangent; closer to the tangent the fix-up draws real geometry).
const double DepthCap = 8.0;

/// Draw kinds of the vertex stage (lineMode).
enum LineMode
{
  STRIPS = 0,
  FIXUP_CYLINDERS = 1,
  CAPS = 2,
  FIXUP_JOINTS = 3
};
}

//------------------------------------------------------------------------------
struct vtkStylizedLineMapper::vtkInternals
{
  vtkSplineVizGPUBuffer Nodes;                   // (x, y, z, radius)
  vtkSplineVizGPUBuffer Tangents;                // octahedral unit tangents
  vtkSplineVizGPUBuffer Colors;                  // RGBA8, with scalar coloring
  vtkSplineVizGPUBuffer TexCoords;               // (along, orientation), with a texture
  vtkSplineVizGPUBuffer Frames;                  // octahedral frame vectors, with a texture
  vtkSplineVizGPUBuffer TubeStarts;              // first vertex per polyline (+ the end)
  vtkSplineVizGPUBuffer Segments;                // fix-up: first vertex of each fixed segment
  vtkSplineVizGPUBuffer JointsBuffer;            // fix-up: vertices with a joint sphere
  vtkSmartPointer<vtkOpenGLBufferObject> Meshes; // cylinder, then cap index patterns
  size_t MeshBytes = 0;
  int MeshSides = 0;
  int Sides = 8; // for the current view

  vtkStylizedLineFixUp FixUp;
  std::vector<int> StripFirsts;
  std::vector<int> StripCounts;
  std::vector<std::uint32_t> FixedSegments;
  std::vector<std::uint32_t> Joints;
  std::vector<double> LastView;

  bool TextureData = false;  // the uploaded lines carry texture coordinates and frames
  bool ActorTexture = false; // the actor being rendered has a texture
  std::string ShaderKey;
};

//------------------------------------------------------------------------------
vtkStylizedLineMapper::vtkStylizedLineMapper()
  : Internals(new vtkInternals)
{
}

//------------------------------------------------------------------------------
vtkStylizedLineMapper::~vtkStylizedLineMapper()
{
  this->SetOrientationArray(nullptr);
}

//------------------------------------------------------------------------------
bool vtkStylizedLineMapper::NeedsTextureData() const
{
  return this->TexturePattern != NO_PATTERN || this->Internals->ActorTexture;
}

//------------------------------------------------------------------------------
void vtkStylizedLineMapper::ConfigureTubeCore(vtkSplineTubeCore* core)
{
  const bool texture = this->NeedsTextureData();
  // Frames only for the texture's circumferential coordinate.
  core->SetComputeFrames(texture);
  core->SetNodeScalarRole("orientation");
  core->SetNodeScalarArrayName(texture && this->OrientationArray && this->OrientationArray[0]
      ? this->OrientationArray
      : nullptr);
}

//------------------------------------------------------------------------------
void vtkStylizedLineMapper::AppendBuildSignature(std::ostream& signature)
{
  signature << "|stylized:" << this->NeedsTextureData() << '|'
            << (this->OrientationArray ? this->OrientationArray : "") << '|'
            << this->TextureRepeatUnits;
}

//------------------------------------------------------------------------------
vtkIdType vtkStylizedLineMapper::GetNumberOfFixedUpSegments()
{
  return static_cast<vtkIdType>(this->Internals->FixedSegments.size());
}

//------------------------------------------------------------------------------
vtkIdType vtkStylizedLineMapper::GetNumberOfFixUpBatches()
{
  return this->Internals->FixUp.GetNumberOfBatches();
}

//------------------------------------------------------------------------------
size_t vtkStylizedLineMapper::GetGPUMemorySize()
{
  vtkInternals& in = *this->Internals;
  return in.Nodes.GetNumberOfBytes() + in.Tangents.GetNumberOfBytes() +
    in.Colors.GetNumberOfBytes() + in.TexCoords.GetNumberOfBytes() + in.Frames.GetNumberOfBytes() +
    in.TubeStarts.GetNumberOfBytes() + in.Segments.GetNumberOfBytes() +
    in.JointsBuffer.GetNumberOfBytes() + this->TubesBuffer->GetNumberOfBytes() + in.MeshBytes;
}

//------------------------------------------------------------------------------
void vtkStylizedLineMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  vtkInternals& in = *this->Internals;
  for (vtkSplineVizGPUBuffer* buffer : { &in.Nodes, &in.Tangents, &in.Colors, &in.TexCoords,
         &in.Frames, &in.TubeStarts, &in.Segments, &in.JointsBuffer })
  {
    buffer->ReleaseGraphicsResources(window);
  }
  if (in.Meshes)
  {
    in.Meshes->ReleaseGraphicsResources();
  }
  in.Meshes = nullptr;
  in.MeshBytes = 0;
  in.MeshSides = 0;
  in.LastView.clear();
  this->Superclass::ReleaseGraphicsResources(window);
}

//------------------------------------------------------------------------------
void vtkStylizedLineMapper::ComputeBounds()
{
  this->Superclass::ComputeBounds();
  // The halo widens the lines.
  if (vtkMath::AreBoundsInitialized(this->Bounds) && this->HaloWidth > 0.0)
  {
    const double pad = this->HaloWidth * this->Core->GetMaximumRadius();
    for (int c = 0; c < 3; ++c)
    {
      this->Bounds[2 * c] -= pad;
      this->Bounds[2 * c + 1] += pad;
    }
  }
}

//------------------------------------------------------------------------------
void vtkStylizedLineMapper::RenderPiece(vtkRenderer* ren, vtkActor* act)
{
  this->Internals->ActorTexture = act->GetTexture() != nullptr;
  this->Superclass::RenderPiece(ren, act);
}

//------------------------------------------------------------------------------
void vtkStylizedLineMapper::UploadTubes(vtkOpenGLRenderWindow* window)
{
  vtkInternals& in = *this->Internals;
  vtkSplineTubeCore* core = this->Core;
  const vtkIdType numNodes = core->GetNumberOfNodes();
  const vtkIdType numTubes = core->GetNumberOfTubes();
  in.LastView.clear();
  in.FixedSegments.clear();
  if (numNodes >= (vtkIdType(1) << 30))
  {
    vtkErrorMacro(<< "Too many line vertices (" << numNodes << "); at most 2^30 are supported.");
    in.StripFirsts.clear();
    in.StripCounts.clear();
    return;
  }
  const float* P = core->GetNodePositions()->GetPointer(0);
  const float* R = core->GetNodeRadii()->GetPointer(0);
  const double shift[3] = { this->Shift[0], this->Shift[1], this->Shift[2] };
  // The fix-up's batches (per data); it owns the vertex tangents.
  in.FixUp.Build(core, this->Shift);
  const float* M = in.FixUp.GetTangents().data();

  // Positions (relative to the shift) and radii; unit tangents, octahedral.
  std::vector<float> nodes(static_cast<size_t>(4 * numNodes));
  std::vector<vtkTypeInt16> tangents(static_cast<size_t>(2 * numNodes));
  vtkSMPTools::For(0, numNodes,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        for (int c = 0; c < 3; ++c)
        {
          nodes[4 * i + c] = static_cast<float>(P[3 * i + c] - shift[c]);
        }
        nodes[4 * i + 3] = R[2 * i];
        const vtkSplineTubeMath::vec2 e = vtkSplineTubeMath::svOctEncode(
          vtkSplineTubeMath::vec3(M[3 * i], M[3 * i + 1], M[3 * i + 2]));
        tangents[2 * i] = static_cast<vtkTypeInt16>(std::lround(32767.0 * e.x));
        tangents[2 * i + 1] = static_cast<vtkTypeInt16>(std::lround(32767.0 * e.y));
      }
    });
  bool ok = in.Nodes.Upload(window, nodes.data(), numNodes, 4, VTK_FLOAT, GL_RGBA32F);
  ok = in.Tangents.Upload(window, tangents.data(), numNodes, 2, VTK_TYPE_INT16, GL_RG16I) && ok;

  // Polylines: first vertices (and the end), cell and block ids.
  std::vector<vtkTypeUInt32> starts(static_cast<size_t>(numTubes + 1));
  std::vector<vtkTypeInt32> tubes(static_cast<size_t>(2 * std::max<vtkIdType>(numTubes, 1)), 0);
  const vtkIdType* tubeFirst = core->GetTubeFirstNodes()->GetPointer(0);
  const vtkIdType* tubeNodes = core->GetTubeNumberOfNodes()->GetPointer(0);
  vtkIdType segment = 0;
  for (vtkIdType t = 0; t < numTubes; ++t)
  {
    starts[t] = static_cast<vtkTypeUInt32>(tubeFirst[t]);
    tubes[2 * t] = static_cast<vtkTypeInt32>(core->GetSegmentCellIds()->GetValue(segment));
    tubes[2 * t + 1] = static_cast<vtkTypeInt32>(core->GetSegmentBlockIds()->GetValue(segment));
    segment += tubeNodes[t] - 1;
  }
  starts[numTubes] = static_cast<vtkTypeUInt32>(numNodes);
  ok =
    in.TubeStarts.Upload(window, starts.data(), numTubes + 1, 1, VTK_TYPE_UINT32, GL_R32UI) && ok;
  ok = this->TubesBuffer->Upload(window, tubes.data(), numTubes, 2, VTK_TYPE_INT32, GL_RG32I) && ok;

  // Colors, with scalar coloring.
  if (this->HaveColors)
  {
    const float* C = core->GetNodeColors()->GetPointer(0);
    std::vector<unsigned char> colors(static_cast<size_t>(4 * numNodes));
    vtkSMPTools::For(0, 4 * numNodes,
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType i = begin; i < end; ++i)
        {
          colors[i] =
            static_cast<unsigned char>(std::lround(255.0f * std::min(1.0f, std::max(0.0f, C[i]))));
        }
      });
    ok = in.Colors.Upload(window, colors.data(), numNodes, 4, VTK_UNSIGNED_CHAR, GL_RGBA8) && ok;
  }
  else
  {
    in.Colors.ReleaseGraphicsResources(window);
  }

  // With a texture: the coordinate along each line (arc length, or its
  // integral over 1 / radius, along the straight segments), the orientation
  // angle, and the rotation-minimizing frame vectors.
  in.TextureData = core->GetNodeFrames()->GetNumberOfTuples() == numNodes && numNodes > 0;
  if (in.TextureData)
  {
    const float* F = core->GetNodeFrames()->GetPointer(0);
    vtkFloatArray* scalars = core->GetNodeScalars();
    const float* O =
      scalars->GetNumberOfTuples() == numNodes && numNodes > 0 ? scalars->GetPointer(0) : nullptr;
    const bool radii = this->TextureRepeatUnits == RADII;
    std::vector<float> coords(static_cast<size_t>(2 * numNodes));
    std::vector<vtkTypeInt16> frames(static_cast<size_t>(2 * numNodes));
    vtkSMPTools::For(0, numTubes,
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType t = begin; t < end; ++t)
        {
          double s = 0.0;
          for (vtkIdType k = 0; k < tubeNodes[t]; ++k)
          {
            const vtkIdType i = tubeFirst[t] + k;
            if (k > 0)
            {
              const double d =
                glm::distance(vtkSplineTubeMath::vec3(P[3 * i - 3], P[3 * i - 2], P[3 * i - 1]),
                  vtkSplineTubeMath::vec3(P[3 * i], P[3 * i + 1], P[3 * i + 2]));
              s += radii ? 0.5 * d * (1.0 / R[2 * i - 2] + 1.0 / R[2 * i]) : d;
            }
            coords[2 * i] = static_cast<float>(s);
            coords[2 * i + 1] = O ? O[i] : 0.0f;
            const vtkSplineTubeMath::vec2 e = vtkSplineTubeMath::svOctEncode(
              vtkSplineTubeMath::vec3(F[3 * i], F[3 * i + 1], F[3 * i + 2]));
            frames[2 * i] = static_cast<vtkTypeInt16>(std::lround(32767.0 * e.x));
            frames[2 * i + 1] = static_cast<vtkTypeInt16>(std::lround(32767.0 * e.y));
          }
        }
      });
    ok = in.TexCoords.Upload(window, coords.data(), numNodes, 2, VTK_FLOAT, GL_RG32F) && ok;
    ok = in.Frames.Upload(window, frames.data(), numNodes, 2, VTK_TYPE_INT16, GL_RG16I) && ok;
  }
  else
  {
    in.TexCoords.ReleaseGraphicsResources(window);
    in.Frames.ReleaseGraphicsResources(window);
  }
  if (!ok)
  {
    vtkErrorMacro(<< "Could not upload the lines to the GPU.");
  }
}

//------------------------------------------------------------------------------
bool vtkStylizedLineMapper::BuildMeshes()
{
  vtkInternals& in = *this->Internals;
  if (in.Meshes && in.MeshSides == in.Sides)
  {
    return true;
  }
  // Cylinder between two rings (vertex = ring * sides + j), the cap fan
  // (vertex 0 the center, 1 + j the rim), then a square (the joints).
  const unsigned short n = static_cast<unsigned short>(in.Sides);
  std::vector<unsigned short> indices;
  indices.reserve(9 * n);
  for (unsigned short j = 0; j < n; ++j)
  {
    const unsigned short a = j;
    const unsigned short b = static_cast<unsigned short>((j + 1) % n);
    indices.insert(indices.end(),
      { a, b, static_cast<unsigned short>(n + a), static_cast<unsigned short>(n + a), b,
        static_cast<unsigned short>(n + b) });
  }
  for (unsigned short j = 0; j < n; ++j)
  {
    indices.insert(indices.end(),
      { 0, static_cast<unsigned short>(1 + j), static_cast<unsigned short>(1 + (j + 1) % n) });
  }
  indices.insert(indices.end(), { 0, 1, 2, 2, 1, 3 });
  if (!in.Meshes)
  {
    in.Meshes = vtkSmartPointer<vtkOpenGLBufferObject>::New();
    in.Meshes->SetType(vtkOpenGLBufferObject::ElementArrayBuffer);
  }
  if (!in.Meshes->Upload(indices, vtkOpenGLBufferObject::ElementArrayBuffer))
  {
    vtkErrorMacro(<< "Could not upload the fix-up meshes.");
    in.Meshes = nullptr;
    in.MeshBytes = 0;
    return false;
  }
  in.MeshSides = in.Sides;
  in.MeshBytes = indices.size() * sizeof(unsigned short);
  return true;
}

//------------------------------------------------------------------------------
void vtkStylizedLineMapper::UpdateDraws(vtkRenderer* ren, vtkActor* act)
{
  vtkInternals& in = *this->Internals;
  float modelView[16];
  float viewModel[16];
  float radiusScale = 1.0f;
  this->ComputeTubeMatrices(ren, act, modelView, viewModel, radiusScale);
  const bool parallel = ren->GetActiveCamera()->GetParallelProjection() != 0;
  // Pixels per view unit (at distance 1 for a perspective camera).
  vtkMatrix4x4* vcdc = GetViewToDisplayMatrix(ren);
  int width = 1;
  int height = 1;
  ren->GetTiledSize(&width, &height);
  const double pixelsPerUnit =
    0.5 * std::max(vcdc->GetElement(0, 0) * width, vcdc->GetElement(1, 1) * height);
  std::vector<double> view(modelView, modelView + 16);
  view.insert(view.end(),
    { static_cast<double>(radiusScale), parallel ? 1.0 : 0.0, pixelsPerUnit,
      static_cast<double>(this->FixUpSides), this->FixUp ? 1.0 : 0.0, this->FixUpEpsilon,
      this->HaloWidth, static_cast<double>(this->UploadTime.GetMTime()) });
  if (view == in.LastView)
  {
    return;
  }
  vtkStylizedLineFixUp::View v;
  std::copy(modelView, modelView + 16, v.ModelView);
  v.RadiusScale = radiusScale;
  v.Parallel = parallel;
  v.Epsilon = this->FixUpEpsilon;
  v.JointRadius = 1.0 + this->HaloWidth;
  v.PixelsPerUnit = pixelsPerUnit;
  in.FixUp.Classify(v, this->FixUp, in.StripFirsts, in.StripCounts, in.FixedSegments, in.Joints);
  // Sides of about 3 pixels for the largest cap or cylinder on screen.
  const double sides = std::ceil(2.0 * vtkMath::Pi() * in.FixUp.GetMaximumScreenRadius() / 3.0);
  in.Sides = static_cast<int>(std::max(8.0, std::min<double>(this->FixUpSides, sides)));
  auto* window = static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow());
  if (!in.Segments.Upload(
        window, in.FixedSegments.data(), in.FixedSegments.size(), 1, VTK_TYPE_UINT32, GL_R32UI) ||
    !in.JointsBuffer.Upload(
      window, in.Joints.data(), in.Joints.size(), 1, VTK_TYPE_UINT32, GL_R32UI))
  {
    vtkErrorMacro(<< "Could not upload the fix-up's segment lists.");
    in.FixedSegments.clear();
    in.Joints.clear();
  }
  in.LastView = view;
}

//------------------------------------------------------------------------------
std::string vtkStylizedLineMapper::ShaderKey(vtkRenderer*, vtkActor*)
{
  std::ostringstream key;
  key << this->HaveColors << this->Internals->TextureData << this->Internals->ActorTexture
      << (this->DepthCorrection || this->HaloWidth > 0.0);
  return key.str();
}

//------------------------------------------------------------------------------
bool vtkStylizedLineMapper::GetNeedToRebuildShaders(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  const bool superclass = this->Superclass::GetNeedToRebuildShaders(cellBO, ren, act);
  const std::string key = this->ShaderKey(ren, act);
  if (key != this->Internals->ShaderKey)
  {
    this->Internals->ShaderKey = key;
    return true;
  }
  return superclass;
}

//------------------------------------------------------------------------------
void vtkStylizedLineMapper::GetShaderTemplate(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act)
{
  this->Superclass::GetShaderTemplate(shaders, ren, act);
  shaders[vtkShader::Vertex]->SetSource(vtkStylizedLineVS);
  shaders[vtkShader::Geometry]->SetSource("");
}

//------------------------------------------------------------------------------
void vtkStylizedLineMapper::ReplaceShaderValues(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act)
{
  vtkInternals& in = *this->Internals;
  std::string VSSource = shaders[vtkShader::Vertex]->GetSource();
  std::string FSSource = shaders[vtkShader::Fragment]->GetSource();
  const std::string tubeMath = std::string(vtkSplineTubeMathPrelude) + vtkSplineTubeMathShared;

  // What changes the code (the rest are uniforms).
  const bool writeDepth = this->DepthCorrection || this->HaloWidth > 0.0;
  const bool actorTexture = in.TextureData && in.ActorTexture;
  std::string defines;
  if (this->HaveColors)
  {
    defines += "#define LINE_COLORS\n";
  }
  if (in.TextureData)
  {
    defines += "#define LINE_TEXTURE\n";
  }
  if (actorTexture)
  {
    defines += "#define LINE_ACTOR_TEXTURE\n";
  }
  if (this->LastSelectionState >= vtkHardwareSelector::MIN_KNOWN_PASS)
  {
    defines += "#define LINE_PICKING\n";
  }

  vtkShaderProgram::Substitute(VSSource, "//VTK::System::Dec", "//VTK::System::Dec\n" + defines);
  vtkShaderProgram::Substitute(VSSource, "//VTK::SplineTubeMath::Dec", tubeMath);
  vtkShaderProgram::Substitute(VSSource, "//VTK::StylizedLineMath::Dec", vtkStylizedLineMathShared);

  vtkShaderProgram::Substitute(
    FSSource, "//VTK::System::Dec", "//VTK::System::Dec\n" + defines, false);
  std::string declarations = vtkStylizedLineFS;
  vtkShaderProgram::Substitute(declarations, "//VTK::SplineTubeMath::Dec", tubeMath);
  vtkShaderProgram::Substitute(
    declarations, "//VTK::StylizedLineMath::Dec", vtkStylizedLineMathShared);
  // After the actor texture's sampler (declared by VTK at //VTK::TMap::Dec).
  vtkShaderProgram::Substitute(FSSource, "//VTK::TMap::Dec", "//VTK::TMap::Dec\n" + declarations);
  vtkShaderProgram::Substitute(FSSource, "//VTK::PositionVC::Dec", "in vec4 vertexVCVSOutput;");
  vtkShaderProgram::Substitute(
    FSSource, "//VTK::PositionVC::Impl", "  vec4 vertexVC = vertexVCVSOutput;\n");

  std::string depth = "  vec3 normalVCVSOutput;\n"
                      "  lineFragment(vertexVC, normalVCVSOutput);\n";
  if (this->HaveColors)
  {
    depth += "  vec4 tubeColor = lineColorVSOutput;\n";
  }
  depth += "  //VTK::TubeClip::Impl\n";
  if (writeDepth)
  {
    depth += "  vec4 lineDC = VCDCMatrix * vertexVC;\n"
             "  gl_FragDepth = 0.5 * (gl_DepthRange.diff * (lineDC.z / lineDC.w) +\n"
             "    gl_DepthRange.near + gl_DepthRange.far);\n";
    depth += GetFragDepthWrittenMarker();
  }
  vtkShaderProgram::Substitute(FSSource, "//VTK::Depth::Impl", depth);
  // The colors are modulated after VTK computed them; the normal is ours.
  vtkShaderProgram::Substitute(
    FSSource, "//VTK::Color::Impl", "//VTK::Color::Impl\n  //VTK::StylizedLine::Impl\n");
  vtkShaderProgram::Substitute(FSSource, "//VTK::Normal::Impl", "");

  // Picking: the cell is the polyline, the composite index its block.
  this->ReplaceShaderTubePicking(FSSource, "lineInfoVSOutput.x");

  shaders[vtkShader::Vertex]->SetSource(VSSource);
  shaders[vtkShader::Fragment]->SetSource(FSSource);

  this->Superclass::ReplaceShaderValues(shaders, ren, act);

  FSSource = shaders[vtkShader::Fragment]->GetSource();
  std::string style = "  lineStyle(ambientColor, diffuseColor, opacity);\n";
  if (this->PrimitiveInfo[this->LastBoundBO].LastLightComplexity)
  {
    style += "  if (lineHalo)\n"
             "  {\n"
             "    specularColor = vec3(0.0);\n"
             "  }\n";
  }
  vtkShaderProgram::Substitute(FSSource, "//VTK::StylizedLine::Impl", style);
  if (writeDepth)
  {
    // Depth peeling and the shadow-map baker read the written depth.
    UseWrittenFragDepth(FSSource);
  }
  shaders[vtkShader::Fragment]->SetSource(FSSource);
  DumpShaderSources({ { "VS", shaders[vtkShader::Vertex]->GetSource() },
    { "FS", shaders[vtkShader::Fragment]->GetSource() } });
}

//------------------------------------------------------------------------------
void vtkStylizedLineMapper::ReplaceShaderClip(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer*, vtkActor*)
{
  // Clip the (corrected) surface point.
  std::string FSSource = shaders[vtkShader::Fragment]->GetSource();
  this->ReplaceShaderTubeClip(FSSource, "//VTK::TubeClip::Impl");
  shaders[vtkShader::Fragment]->SetSource(FSSource);
}

//------------------------------------------------------------------------------
void vtkStylizedLineMapper::SetMapperShaderParameters(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  this->Superclass::SetMapperShaderParameters(cellBO, ren, act);
  vtkInternals& in = *this->Internals;
  vtkShaderProgram* program = cellBO.Program;
  in.Nodes.Activate(program, "lineNodes");
  in.Tangents.Activate(program, "lineTangents");
  in.TubeStarts.Activate(program, "lineTubeStarts");
  in.Segments.Activate(program, "lineSegments");
  in.JointsBuffer.Activate(program, "lineJoints");
  if (this->HaveColors)
  {
    in.Colors.Activate(program, "lineColors");
  }
  if (in.TextureData)
  {
    in.TexCoords.Activate(program, "lineTexCoords");
    in.Frames.Activate(program, "lineFrames");
    program->SetUniformf("lineTextureRepeat", static_cast<float>(this->TextureRepeat));
    program->SetUniformf(
      "lineTextureAround", static_cast<float>(this->TextureCircumferentialRepeat));
    program->SetUniformi("linePattern", in.ActorTexture ? 0 : this->TexturePattern);
    program->SetUniformi("lineNormalMapping", this->NormalMapping ? 1 : 0);
  }
  program->SetUniformi("lineNumberOfTubes", static_cast<int>(this->Core->GetNumberOfTubes()));
  program->SetUniformi("lineExact", this->ExactSilhouette ? 1 : 0);
  program->SetUniformi("lineSides", in.MeshSides);
  program->SetUniformf("lineDepthCap", static_cast<float>(DepthCap));
  program->SetUniformf("lineWiden", static_cast<float>(1.0 + this->HaloWidth));
  program->SetUniformi("lineDepthCorrection", this->DepthCorrection ? 1 : 0);
  program->SetUniformf("lineHaloDepth", static_cast<float>(this->HaloDepthOffset));
  double* halo = this->HaloColorFromBackground ? ren->GetBackground() : this->HaloColor;
  const float haloColor[3] = { static_cast<float>(halo[0]), static_cast<float>(halo[1]),
    static_cast<float>(halo[2]) };
  program->SetUniform3f("lineHaloColor", haloColor);
}

//------------------------------------------------------------------------------
void vtkStylizedLineMapper::SetCameraShaderParameters(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  // tubeMCVC, tubeRadiusScale, VCDCMatrix (and tubeVCMC for clipping).
  this->Superclass::SetCameraShaderParameters(cellBO, ren, act);
}

//------------------------------------------------------------------------------
void vtkStylizedLineMapper::RenderPieceDraw(vtkRenderer* ren, vtkActor* act)
{
  vtkInternals& in = *this->Internals;
  const vtkIdType numTubes = this->Core->GetNumberOfTubes();
  if (numTubes == 0 || in.Nodes.GetNumberOfBytes() == 0)
  {
    return;
  }
  this->UpdateDraws(ren, act);
  if (!this->BuildMeshes())
  {
    return;
  }

  vtkOpenGLHelper& helper = this->Primitives[PrimitiveTris];
  this->UpdateShaders(helper, ren, act);
  if (!helper.Program)
  {
    return;
  }
  vtkShaderProgram* program = helper.Program;
  // UpdateShaders() may have released the VAO after binding it (new
  // program); the draws have no attributes but core profiles need a VAO.
  helper.VAO->Bind();
  // Strips alternate their winding; the geometry is seen from both sides.
  vtkOpenGLState* state = static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow())->GetState();
  vtkOpenGLState::ScopedglEnableDisable cull(state, GL_CULL_FACE);
  state->vtkglDisable(GL_CULL_FACE);

  // 1. The silhouette quads of every polyline piece, one multi-draw.
  program->SetUniformi("lineMode", STRIPS);
  program->SetUniformi("lineHaloPass", 0);
  if (!in.StripFirsts.empty())
  {
    glMultiDrawArrays(GL_TRIANGLE_STRIP, in.StripFirsts.data(), in.StripCounts.data(),
      static_cast<GLsizei>(in.StripFirsts.size()));
  }
  // 2. Caps, 3. the fix-up's cylinders and joints; then the caps' halos.
  in.Meshes->Bind();
  const GLsizei sides = static_cast<GLsizei>(in.MeshSides);
  const void* capOffset = reinterpret_cast<const void*>(6 * sizeof(unsigned short) * in.MeshSides);
  const size_t jointOffset = 9 * sizeof(unsigned short) * in.MeshSides;
  const GLsizei fixed = static_cast<GLsizei>(in.FixedSegments.size());
  for (int halo = 0; halo < (this->HaloWidth > 0.0 ? 2 : 1); ++halo)
  {
    program->SetUniformi("lineHaloPass", halo);
    if (this->Capping)
    {
      program->SetUniformi("lineMode", CAPS);
      glDrawElementsInstanced(
        GL_TRIANGLES, 3 * sides, GL_UNSIGNED_SHORT, capOffset, static_cast<GLsizei>(2 * numTubes));
    }
    // The fix-up's geometry has no halo: around a line seen down its length
    // a halo ring would cut the line's own parts further back wherever they
    // curve out of its profile (Stoll's halo is the quads' band).
    if (fixed > 0 && halo == 0)
    {
      program->SetUniformi("lineMode", FIXUP_CYLINDERS);
      glDrawElementsInstanced(GL_TRIANGLES, 6 * sides, GL_UNSIGNED_SHORT, nullptr, fixed);
    }
    if (!in.Joints.empty() && halo == 0)
    {
      program->SetUniformi("lineMode", FIXUP_JOINTS);
      glDrawElementsInstanced(GL_TRIANGLES, 6, GL_UNSIGNED_SHORT,
        reinterpret_cast<const void*>(jointOffset), static_cast<GLsizei>(in.Joints.size()));
    }
  }
  in.Meshes->Release();

  this->DeactivateTubeBuffers();
  for (vtkSplineVizGPUBuffer* buffer : { &in.Nodes, &in.Tangents, &in.Colors, &in.TexCoords,
         &in.Frames, &in.TubeStarts, &in.Segments, &in.JointsBuffer })
  {
    buffer->Deactivate();
  }
}

//------------------------------------------------------------------------------
void vtkStylizedLineMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "HaloWidth: " << this->HaloWidth << "\n";
  os << indent << "HaloColor: " << this->HaloColor[0] << " " << this->HaloColor[1] << " "
     << this->HaloColor[2] << "\n";
  os << indent << "HaloColorFromBackground: " << this->HaloColorFromBackground << "\n";
  os << indent << "HaloDepthOffset: " << this->HaloDepthOffset << "\n";
  os << indent << "ExactSilhouette: " << this->ExactSilhouette << "\n";
  os << indent << "DepthCorrection: " << this->DepthCorrection << "\n";
  os << indent << "FixUp: " << this->FixUp << "\n";
  os << indent << "FixUpEpsilon: " << this->FixUpEpsilon << "\n";
  os << indent << "FixUpSides: " << this->FixUpSides << "\n";
  os << indent << "Capping: " << this->Capping << "\n";
  os << indent << "TexturePattern: " << this->TexturePattern << "\n";
  os << indent << "TextureRepeat: " << this->TextureRepeat << "\n";
  os << indent << "TextureRepeatUnits: " << (this->TextureRepeatUnits == RADII ? "RADII" : "WORLD")
     << "\n";
  os << indent << "TextureCircumferentialRepeat: " << this->TextureCircumferentialRepeat << "\n";
  os << indent
     << "OrientationArray: " << (this->OrientationArray ? this->OrientationArray : "(none)")
     << "\n";
  os << indent << "NormalMapping: " << this->NormalMapping << "\n";
}
