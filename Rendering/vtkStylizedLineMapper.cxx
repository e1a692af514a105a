// SPDX-License-Identifier: BSD-3-Clause
#include "vtkStylizedLineMapper.h"

#include "vtkSplineTubeCore.h"
#include "vtkSplineTubeVisibility.h"
#include "vtkSplineTubeMath.h"
#include "vtkSplineVizGPUBuffer.h"
#include "vtkStylizedLineFixUp.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkTextureObject.h"
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

#include <chrono>

#include "vtkSplineVizShaderPrelude.h"
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
  vtkSplineVizGPUBuffer CapsBuffer;              // the caps of a group: 2 x polyline + end
  vtkSmartPointer<vtkOpenGLBufferObject> Meshes; // cylinder, then cap index patterns
  size_t MeshBytes = 0;
  int MeshSides = 0;
  int Sides = 8; // for the current view

  vtkStylizedLineFixUp FixUp;
  std::vector<int> StripFirsts;
  std::vector<int> StripCounts;
  std::vector<std::uint32_t> Caps;
  double CullingWiden = -1.0; // the halo the visibility's chunks were made for
  std::vector<std::uint32_t> FixedSegments;
  std::vector<std::uint32_t> Joints;
  std::vector<double> LastView;

  // Whole polylines as strips (the shadow map's draw), per data.
  std::vector<int> WholeFirsts;
  std::vector<int> WholeCounts;

  // The shadow map.
  vtkSmartPointer<vtkOpenGLFramebufferObject> ShadowFramebuffer;
  vtkSmartPointer<vtkTextureObject> ShadowMap;
  vtkSmartPointer<vtkTextureObject> ShadowDummy; // for the sampler while the map is drawn
  int ShadowSize = 0;
  std::vector<double> LastShadowKey;
  double ShadowView[16];       // world to light view (row-major)
  double ShadowProjection[16]; // light view to clip (row-major)
  float ShadowBias = 0.0f;

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
  core->SetNodeScalarRole("orientation");
  // The fix-up's batches are what the visibility culls (SetVisibilityChunks()).
  core->ChunkTablesOff();
  core->SetNodeScalarArray(texture && this->OrientationArray && this->OrientationArray[0]
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
  const size_t shadow = in.ShadowMap ? 4 * static_cast<size_t>(in.ShadowSize) * in.ShadowSize : 0;
  return shadow + in.Nodes.GetNumberOfBytes() + in.Tangents.GetNumberOfBytes() +
    in.Colors.GetNumberOfBytes() + in.TexCoords.GetNumberOfBytes() + in.Frames.GetNumberOfBytes() +
    in.TubeStarts.GetNumberOfBytes() + in.Segments.GetNumberOfBytes() +
    in.JointsBuffer.GetNumberOfBytes() + this->TubesBuffer->GetNumberOfBytes() + in.MeshBytes;
}

//------------------------------------------------------------------------------
void vtkStylizedLineMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  vtkInternals& in = *this->Internals;
  for (vtkSplineVizGPUBuffer* buffer : { &in.Nodes, &in.Tangents, &in.Colors, &in.TexCoords,
         &in.Frames, &in.TubeStarts, &in.Segments, &in.JointsBuffer, &in.CapsBuffer })
  {
    buffer->ReleaseGraphicsResources(window);
  }
  if (in.Meshes)
  {
    in.Meshes->ReleaseGraphicsResources();
  }
  in.Meshes = nullptr;
  if (in.ShadowMap)
  {
    in.ShadowMap->ReleaseGraphicsResources(window);
  }
  if (in.ShadowFramebuffer)
  {
    in.ShadowFramebuffer->ReleaseGraphicsResources(window);
  }
  if (in.ShadowDummy)
  {
    in.ShadowDummy->ReleaseGraphicsResources(window);
  }
  in.ShadowDummy = nullptr;
  in.ShadowMap = nullptr;
  in.ShadowFramebuffer = nullptr;
  in.ShadowSize = 0;
  in.LastShadowKey.clear();
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
    this->UploadFailed = true;
    in.StripFirsts.clear();
    in.StripCounts.clear();
    return;
  }
  // The fix-up's batches (per data).
  in.FixUp.Build(core, this->Shift);

  // Positions (relative to the shift) and radii (UploadNodes(): positions
  // alone for a constant radius); unit tangents, octahedral; filled piece by
  // piece from the input (no copy kept on the CPU side).
  const size_t nodes = static_cast<size_t>(numNodes);
  bool ok = this->UploadNodes(window, in.Nodes);
  ok = ok &&
    in.Tangents.UploadInPieces(window, nodes, 2, VTK_TYPE_INT16, GL_RG16I,
      [&](size_t first, size_t count, void* destination)
      {
        in.FixUp.FillTangents(static_cast<vtkIdType>(first), static_cast<vtkIdType>(count),
          static_cast<short*>(destination));
      });

  // Polylines: first vertices (and the end), cell and block ids.
  std::vector<vtkTypeUInt32> starts(static_cast<size_t>(numTubes + 1));
  std::vector<vtkTypeInt32> tubes(static_cast<size_t>(2 * std::max<vtkIdType>(numTubes, 1)), 0);
  in.WholeFirsts.resize(static_cast<size_t>(numTubes));
  in.WholeCounts.resize(static_cast<size_t>(numTubes));
  for (vtkIdType t = 0; t < numTubes; ++t)
  {
    starts[t] = static_cast<vtkTypeUInt32>(core->GetTubeFirstNode(t));
    tubes[2 * t] = static_cast<vtkTypeInt32>(core->GetTubeCellId(t));
    tubes[2 * t + 1] = static_cast<vtkTypeInt32>(core->GetTubeBlockId(t));
    in.WholeFirsts[t] = static_cast<int>(2 * core->GetTubeFirstNode(t));
    in.WholeCounts[t] = static_cast<int>(2 * core->GetTubeNumberOfNodes(t));
  }
  starts[numTubes] = static_cast<vtkTypeUInt32>(numNodes);
  in.LastShadowKey.clear();
  ok =
    ok && in.TubeStarts.Upload(window, starts.data(), numTubes + 1, 1, VTK_TYPE_UINT32, GL_R32UI);
  ok = ok && this->TubesBuffer->Upload(window, tubes.data(), numTubes, 2, VTK_TYPE_INT32, GL_RG32I);

  // Colors (RGBA8), with scalar coloring.
  if (this->HaveColors)
  {
    ok = ok &&
      in.Colors.UploadInPieces(window, nodes, 4, VTK_UNSIGNED_CHAR, GL_RGBA8,
        [&](size_t first, size_t count, void* destination)
        {
          core->FillColors(static_cast<vtkIdType>(first), static_cast<vtkIdType>(count),
            static_cast<unsigned int*>(destination));
        });
  }
  else
  {
    in.Colors.ReleaseGraphicsResources(window);
  }

  // With a texture: the coordinate along each line (arc length, or its
  // integral over 1 / radius, along the straight segments), the orientation
  // angle, and the rotation-minimizing frame vectors.
  in.TextureData = this->NeedsTextureData() && numNodes > 0;
  if (in.TextureData)
  {
    const bool radii = this->TextureRepeatUnits == RADII;
    ok = ok &&
      in.TexCoords.UploadInPieces(window, nodes, 2, VTK_FLOAT, GL_RG32F,
        [&](size_t first, size_t count, void* destination)
        {
          auto* coords = static_cast<float*>(destination);
          std::vector<float> orientation(count);
          core->FillScalars(
            static_cast<vtkIdType>(first), static_cast<vtkIdType>(count), orientation.data());
          const vtkIdType end = static_cast<vtkIdType>(first + count);
          std::vector<double> p;
          for (vtkIdType b = static_cast<vtkIdType>(first), t = core->GetTubeOfNode(b); b < end;
               ++t)
          {
            // The arc length from the tube's first node.
            const vtkIdType tubeFirst = core->GetTubeFirstNode(t);
            const vtkIdType stop = std::min(end, tubeFirst + core->GetTubeNumberOfNodes(t));
            p.resize(static_cast<size_t>(4 * (stop - tubeFirst)));
            core->GetTubeNodes(t, 0, stop - tubeFirst, p.data(), nullptr);
            double s = 0.0;
            for (vtkIdType k = 0; k < stop - tubeFirst; ++k)
            {
              if (k > 0)
              {
                const double d =
                  std::sqrt(vtkMath::Distance2BetweenPoints(&p[4 * k - 4], &p[4 * k]));
                s += radii ? 0.5 * d * (1.0 / p[4 * k - 1] + 1.0 / p[4 * k + 3]) : d;
              }
              const vtkIdType i = tubeFirst + k;
              if (i >= b)
              {
                coords[2 * (i - static_cast<vtkIdType>(first))] = static_cast<float>(s);
                coords[2 * (i - static_cast<vtkIdType>(first)) + 1] =
                  orientation[i - static_cast<vtkIdType>(first)];
              }
            }
            b = stop;
          }
        });
    ok = ok &&
      in.Frames.UploadInPieces(window, nodes, 2, VTK_TYPE_INT16, GL_RG16I,
        [&](size_t first, size_t count, void* destination)
        {
          core->FillFrames(static_cast<vtkIdType>(first), static_cast<vtkIdType>(count),
            static_cast<short*>(destination));
        });
  }
  else
  {
    in.TexCoords.ReleaseGraphicsResources(window);
    in.Frames.ReleaseGraphicsResources(window);
  }
  if (!ok)
  {
    vtkErrorMacro(<< "Could not upload the lines to the GPU: "
                  << vtkSplineVizGPUBuffer::FirstUploadError(
                       { &in.Nodes, &in.Tangents, &in.TubeStarts, this->TubesBuffer.get(),
                         &in.Colors, &in.TexCoords, &in.Frames }));
    this->UploadFailed = true;
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
void vtkStylizedLineMapper::SetVisibilityChunks()
{
  // The fix-up's batches, their spheres widened by the halo (and the caps
  // and fix-up geometry, within a radius).
  vtkInternals& in = *this->Internals;
  in.CullingWiden = 1.0 + std::max(0.0, this->HaloWidth);
  in.FixUp.SetCullingChunks(in.CullingWiden, *this->Visibility);
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
  const double pixelsPerUnit = GetPixelScale(ren);
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
  in.FixUp.BeginView(v, this->FixUp);
  // Sides of about 3 pixels for the largest cap or cylinder on screen.
  const double sides = std::ceil(2.0 * vtkMath::Pi() * in.FixUp.GetMaximumScreenRadius() / 3.0);
  in.Sides = static_cast<int>(std::max(8.0, std::min<double>(this->FixUpSides, sides)));
  in.LastView = view;
}

//------------------------------------------------------------------------------
void vtkStylizedLineMapper::GetShadowLightDirection(vtkRenderer* ren, double dir[3])
{
  // The first switched-on light that is not a headlight, else a virtual one
  // above and right of the camera.
  dir[0] = dir[1] = dir[2] = 0.0;
  vtkCamera* camera = ren->GetActiveCamera();
  bool found = false;
  vtkCollectionSimpleIterator it;
  vtkLightCollection* lights = ren->GetLights();
  lights->InitTraversal(it);
  while (vtkLight* light = lights->GetNextLight(it))
  {
    if (light->GetSwitch() && !light->LightTypeIsHeadlight())
    {
      const double* position = light->GetTransformedPosition();
      const double* focal = light->GetTransformedFocalPoint();
      for (int c = 0; c < 3; ++c)
      {
        dir[c] = focal[c] - position[c];
      }
      found = vtkMath::Norm(dir) > 0.0;
      if (found)
      {
        break;
      }
    }
  }
  if (!found)
  {
    double forward[3];
    double up[3];
    double right[3];
    camera->GetDirectionOfProjection(forward);
    camera->GetViewUp(up);
    vtkMath::Cross(forward, up, right);
    vtkMath::Normalize(right);
    vtkMath::Cross(right, forward, up);
    for (int c = 0; c < 3; ++c)
    {
      dir[c] = forward[c] - up[c] - 0.6 * right[c];
    }
  }
  vtkMath::Normalize(dir);
}

//------------------------------------------------------------------------------
double vtkStylizedLineMapper::SetUpShadowCamera(vtkActor* act, const double dir[3])
{
  // An orthographic light camera around the lines (world bounds).
  vtkInternals& in = *this->Internals;
  double bounds[6];
  act->GetBounds(bounds);
  if (!vtkMath::AreBoundsInitialized(bounds))
  {
    return 0.0;
  }
  double center[3];
  double radius = 0.0;
  for (int c = 0; c < 3; ++c)
  {
    center[c] = 0.5 * (bounds[2 * c] + bounds[2 * c + 1]);
    radius += 0.25 * (bounds[2 * c + 1] - bounds[2 * c]) * (bounds[2 * c + 1] - bounds[2 * c]);
  }
  radius = std::max(std::sqrt(radius), 1e-12);
  vtkNew<vtkCamera> light;
  light->SetFocalPoint(center);
  light->SetPosition(center[0] - 2.0 * radius * dir[0], center[1] - 2.0 * radius * dir[1],
    center[2] - 2.0 * radius * dir[2]);
  const vtkSplineTubeMath::vec3 up =
    vtkSplineTubeMath::svAnyOrthogonal(vtkSplineTubeMath::vec3(dir[0], dir[1], dir[2]));
  light->SetViewUp(up.x, up.y, up.z);
  light->ParallelProjectionOn();
  light->SetParallelScale(radius);
  light->SetClippingRange(radius, 3.0 * radius);
  vtkMatrix4x4* view = light->GetModelViewTransformMatrix();
  vtkMatrix4x4* projection = light->GetProjectionTransformMatrix(1.0, -1.0, 1.0);
  std::copy(&view->Element[0][0], &view->Element[0][0] + 16, in.ShadowView);
  std::copy(&projection->Element[0][0], &projection->Element[0][0] + 16, in.ShadowProjection);
  // Depth units per world unit: (far - near) = 2 radius maps to [0, 1].
  const double texel = 2.0 * radius / this->ShadowMapResolution;
  double actorScale = 1.0;
  if (!act->GetIsIdentity())
  {
    double a[3][3];
    for (int r = 0; r < 3; ++r)
    {
      for (int c = 0; c < 3; ++c)
      {
        a[r][c] = act->GetMatrix()->GetElement(r, c);
      }
    }
    actorScale = std::cbrt(std::abs(vtkMath::Determinant3x3(a)));
  }
  in.ShadowBias = static_cast<float>(
    (0.25 * this->Core->GetMaximumRadius() * actorScale + 2.0 * texel) / (2.0 * radius));
  return radius;
}

//------------------------------------------------------------------------------
bool vtkStylizedLineMapper::PrepareShadowFramebuffer(vtkOpenGLRenderWindow* window, int size)
{
  // Leaves the framebuffer bound (its previous bindings saved) when it succeeds.
  vtkInternals& in = *this->Internals;
  if (!in.ShadowFramebuffer)
  {
    in.ShadowFramebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
    in.ShadowFramebuffer->SetContext(window);
  }
  in.ShadowFramebuffer->SaveCurrentBindingsAndBuffers();
  in.ShadowFramebuffer->Bind();
  if (!in.ShadowMap || in.ShadowSize != size)
  {
    if (in.ShadowMap)
    {
      in.ShadowMap->ReleaseGraphicsResources(window);
    }
    in.ShadowMap = vtkSmartPointer<vtkTextureObject>::New();
    in.ShadowMap->SetContext(window);
    in.ShadowMap->SetDepthTextureCompare(true);
    in.ShadowMap->SetDepthTextureCompareFunction(vtkTextureObject::Lequal);
    in.ShadowMap->SetMinificationFilter(vtkTextureObject::Linear);
    in.ShadowMap->SetMagnificationFilter(vtkTextureObject::Linear);
    in.ShadowMap->SetWrapS(vtkTextureObject::ClampToEdge);
    in.ShadowMap->SetWrapT(vtkTextureObject::ClampToEdge);
    if (!in.ShadowMap->AllocateDepth(size, size, vtkTextureObject::Float32))
    {
      vtkErrorMacro(<< "Could not allocate a " << size << "^2 shadow map; shadows are off.");
      in.ShadowFramebuffer->RestorePreviousBindingsAndBuffers();
      in.ShadowMap = nullptr;
      in.ShadowSize = 0;
      return false;
    }
    in.ShadowFramebuffer->AddDepthAttachment(in.ShadowMap);
    in.ShadowSize = size;
  }
  in.ShadowFramebuffer->DeactivateDrawBuffers(); // depth only
  in.ShadowFramebuffer->DeactivateReadBuffer();
  const char* description = nullptr;
  if (!vtkOpenGLFramebufferObject::GetFrameBufferStatus(
        vtkOpenGLFramebufferObject::GetDrawMode(), description))
  {
    vtkErrorMacro(<< "The shadow map's framebuffer is incomplete (" << description
                  << "); shadows are off.");
    in.ShadowFramebuffer->RestorePreviousBindingsAndBuffers();
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkStylizedLineMapper::DrawShadowCasters(
  vtkOpenGLRenderWindow* window, vtkActor* act, vtkShaderProgram* program)
{
  // The lines seen from the light: their quads extrude toward it.
  vtkInternals& in = *this->Internals;
  vtkNew<vtkMatrix4x4> view;
  view->DeepCopy(in.ShadowView);
  float modelView[16];
  float radiusScale = 1.0f;
  this->ComputeTubeMatrices(view, act, modelView, nullptr, radiusScale);
  float clip[16];
  for (int r = 0; r < 4; ++r)
  {
    for (int c = 0; c < 4; ++c)
    {
      clip[4 * c + r] = static_cast<float>(in.ShadowProjection[4 * r + c]);
    }
  }
  program->SetUniformMatrix4x4("tubeMCVC", modelView);
  program->SetUniformf("tubeRadiusScale", radiusScale);
  program->SetUniformMatrix4x4("VCDCMatrix", clip);
  program->SetUniformi("cameraParallel", 1);
  program->SetUniformi("lineShadowPass", 1);
  program->SetUniformf("lineWiden", 1.0f);
  program->SetUniformi("lineHaloPass", 0);
  program->SetUniformi("lineMode", STRIPS);
  // Only the lines drawn cast shadows (see VisibilityArray).
  const unsigned char* mask = this->GetLineMask();
  std::vector<int> firsts;
  std::vector<int> counts;
  std::vector<std::uint32_t> caps;
  if (mask)
  {
    for (size_t t = 0; t < in.WholeFirsts.size(); ++t)
    {
      if (mask[t])
      {
        firsts.push_back(in.WholeFirsts[t]);
        counts.push_back(in.WholeCounts[t]);
        caps.push_back(static_cast<std::uint32_t>(2 * t));
        caps.push_back(static_cast<std::uint32_t>(2 * t + 1));
      }
    }
  }
  const std::vector<int>& drawFirsts = mask ? firsts : in.WholeFirsts;
  const std::vector<int>& drawCounts = mask ? counts : in.WholeCounts;
  if (!drawFirsts.empty())
  {
    glMultiDrawArrays(GL_TRIANGLE_STRIP, drawFirsts.data(), drawCounts.data(),
      static_cast<GLsizei>(drawFirsts.size()));
  }
  const bool capList = mask && !caps.empty() &&
    in.CapsBuffer.Upload(window, caps.data(), caps.size(), 1, VTK_TYPE_UINT32, GL_R32UI);
  if (capList)
  {
    in.CapsBuffer.Activate(program, "lineCaps");
  }
  if (this->Capping && (!mask || capList))
  {
    in.Meshes->Bind();
    program->SetUniformi("lineMode", CAPS);
    program->SetUniformi("lineCapList", capList ? 1 : 0);
    glDrawElementsInstanced(GL_TRIANGLES, 3 * in.MeshSides, GL_UNSIGNED_SHORT,
      reinterpret_cast<const void*>(6 * sizeof(unsigned short) * in.MeshSides),
      static_cast<GLsizei>(capList ? caps.size() : 2 * this->Core->GetNumberOfTubes()));
    in.Meshes->Release();
  }
}

//------------------------------------------------------------------------------
bool vtkStylizedLineMapper::UpdateShadowMap(
  vtkRenderer* ren, vtkActor* act, vtkOpenGLHelper& helper)
{
  vtkInternals& in = *this->Internals;
  auto* window = static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow());
  vtkShaderProgram* program = helper.Program;
  double dir[3];
  this->GetShadowLightDirection(ren, dir);
  const double radius = this->SetUpShadowCamera(act, dir);
  if (radius <= 0.0)
  {
    return false;
  }
  // Redraw the map only when what it shows changed.
  std::vector<double> key(in.ShadowView, in.ShadowView + 16);
  key.insert(key.end(),
    { radius, static_cast<double>(this->ShadowMapResolution),
      static_cast<double>(this->UploadTime.GetMTime()), static_cast<double>(act->GetMTime()),
      static_cast<double>(this->GetLineMaskTime()) });
  if (key == in.LastShadowKey && in.ShadowMap)
  {
    return true;
  }

  const int size = this->ShadowMapResolution;
  if (!this->PrepareShadowFramebuffer(window, size))
  {
    return false;
  }
  // The program's shadow sampler must not see the map being drawn: a
  // 1 x 1 stand-in of the same kind meanwhile.
  if (!in.ShadowDummy)
  {
    in.ShadowDummy = vtkSmartPointer<vtkTextureObject>::New();
    in.ShadowDummy->SetContext(window);
    in.ShadowDummy->SetDepthTextureCompare(true);
    in.ShadowDummy->AllocateDepth(1, 1, vtkTextureObject::Float32);
  }
  in.ShadowDummy->Activate();
  program->SetUniformi("lineShadowMap", in.ShadowDummy->GetTextureUnit());
  {
    vtkOpenGLState* state = window->GetState();
    vtkOpenGLState::ScopedglViewport viewport(state);
    vtkOpenGLState::ScopedglScissor scissor(state);
    vtkOpenGLState::ScopedglColorMask colorMask(state);
    vtkOpenGLState::ScopedglDepthMask depthMask(state);
    vtkOpenGLState::ScopedglEnableDisable depthTest(state, GL_DEPTH_TEST);
    state->vtkglViewport(0, 0, size, size);
    state->vtkglScissor(0, 0, size, size);
    state->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    state->vtkglDepthMask(GL_TRUE);
    state->vtkglEnable(GL_DEPTH_TEST);
    state->vtkglClearDepth(1.0);
    state->vtkglClear(GL_DEPTH_BUFFER_BIT);

    this->DrawShadowCasters(window, act, program);
  }
  in.ShadowFramebuffer->RestorePreviousBindingsAndBuffers();
  in.ShadowDummy->Deactivate();
  // Back to the camera.
  this->SetCameraShaderParameters(helper, ren, act);
  program->SetUniformf("lineWiden", static_cast<float>(1.0 + this->HaloWidth));
  program->SetUniformi("lineShadowPass", 0);
  in.LastShadowKey = key;
  return true;
}

//------------------------------------------------------------------------------
std::string vtkStylizedLineMapper::ShaderKey(vtkRenderer*, vtkActor*)
{
  std::ostringstream key;
  key << this->GetTubeColorMode() << this->Internals->TextureData << this->Internals->ActorTexture
      << (this->DepthCorrection || this->HaloWidth > 0.0) << this->Shadows;
  return key.str();
}

//------------------------------------------------------------------------------
void vtkStylizedLineMapper::GetPagedBuffers(std::vector<PagedBuffer>& buffers)
{
  this->Superclass::GetPagedBuffers(buffers);
  vtkInternals& in = *this->Internals;
  buffers.emplace_back("lineNodes", &in.Nodes);
  buffers.emplace_back("lineTangents", &in.Tangents);
  buffers.emplace_back("lineColors", &in.Colors);
  buffers.emplace_back("lineTexCoords", &in.TexCoords);
  buffers.emplace_back("lineFrames", &in.Frames);
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
  const std::string tubeMath = vtkSplineVizShaderPrelude::Get() + vtkSplineTubeMathShared;

  // What changes the code (the rest are uniforms).
  const bool writeDepth = this->DepthCorrection || this->HaloWidth > 0.0;
  const bool actorTexture = in.TextureData && in.ActorTexture;
  std::string defines;
  const int colorMode = this->GetTubeColorMode();
  if (colorMode == 1)
  {
    defines += "#define LINE_COLORS\n";
  }
  else if (colorMode == 2)
  {
    defines += "#define LINE_DIRECTION_COLORS\n";
  }
  if (in.TextureData)
  {
    defines += "#define LINE_TEXTURE\n";
  }
  if (actorTexture)
  {
    defines += "#define LINE_ACTOR_TEXTURE\n";
  }
  const bool selecting = this->LastSelectionState >= vtkHardwareSelector::MIN_KNOWN_PASS;
  if (selecting)
  {
    defines += "#define LINE_PICKING\n";
  }
  else if (this->Shadows)
  {
    defines += "#define LINE_SHADOWS\n";
  }

  vtkShaderProgram::Substitute(VSSource, "//VTK::System::Dec", "//VTK::System::Dec\n" + defines);
  vtkShaderProgram::Substitute(VSSource, "//SV::SplineTubeMath::Dec", tubeMath);
  vtkShaderProgram::Substitute(VSSource, "//SV::StylizedLineMath::Dec", vtkStylizedLineMathShared);

  vtkShaderProgram::Substitute(
    FSSource, "//VTK::System::Dec", "//VTK::System::Dec\n" + defines, false);
  std::string declarations = vtkStylizedLineFS;
  if (colorMode == 2)
  {
    declarations += GetTubeDirectionColorDeclarations();
  }
  vtkShaderProgram::Substitute(declarations, "//SV::SplineTubeMath::Dec", tubeMath);
  vtkShaderProgram::Substitute(
    declarations, "//SV::StylizedLineMath::Dec", vtkStylizedLineMathShared);
  // After the actor texture's sampler (declared by VTK at //VTK::TMap::Dec).
  vtkShaderProgram::Substitute(FSSource, "//VTK::TMap::Dec", "//VTK::TMap::Dec\n" + declarations);
  vtkShaderProgram::Substitute(FSSource, "//VTK::PositionVC::Dec", "in vec4 vertexVCVSOutput;");
  vtkShaderProgram::Substitute(
    FSSource, "//VTK::PositionVC::Impl", "  vec4 vertexVC = vertexVCVSOutput;\n");

  std::string depth = "  vec3 normalVCVSOutput;\n"
                      "  lineFragment(vertexVC, normalVCVSOutput);\n";
  if (colorMode == 1)
  {
    depth += "  vec4 tubeColor = lineColorVSOutput;\n";
  }
  else if (colorMode == 2)
  {
    depth += "  vec4 tubeColor = tubeDirectionColor(lineColorVSOutput.xyz);\n";
  }
  depth += "  //SV::TubeClip::Impl\n";
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
    FSSource, "//VTK::Color::Impl", "//VTK::Color::Impl\n  //SV::StylizedLine::Impl\n");
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
    style += "  specularColor *= lineHalo ? 0.0 : lineLit;\n";
  }
  vtkShaderProgram::Substitute(FSSource, "//SV::StylizedLine::Impl", style);
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
  this->ReplaceShaderTubeClip(FSSource, "//SV::TubeClip::Impl");
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
  this->SetNodesUniforms(program, "line");
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
  program->SetUniformi("lineSingleLayer", act->IsRenderingTranslucentPolygonalGeometry() ? 1 : 0);
  program->SetUniformf("lineHaloDepth", static_cast<float>(this->HaloDepthOffset));
  program->SetUniformf("lineHaloDepthRange",
    static_cast<float>(this->DepthDependentHalo ? this->HaloDepthRange : 0.0));
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
  using Clock = std::chrono::steady_clock;
  const auto viewStart = Clock::now();
  this->UpdateDraws(ren, act);
  this->LastFixUpTime = std::chrono::duration<double>(Clock::now() - viewStart).count();
  if (!this->BuildMeshes())
  {
    return;
  }
  if (in.CullingWiden != 1.0 + std::max(0.0, this->HaloWidth))
  {
    this->SetVisibilityChunks();
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
  const bool selecting = this->LastSelectionState >= vtkHardwareSelector::MIN_KNOWN_PASS;
  bool shadows = false;
  if (this->Shadows && !selecting)
  {
    vtkOpenGLState* shadowState =
      static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow())->GetState();
    vtkOpenGLState::ScopedglEnableDisable shadowCull(shadowState, GL_CULL_FACE);
    shadowState->vtkglDisable(GL_CULL_FACE);
    shadows = this->UpdateShadowMap(ren, act, helper);
  }
  if (shadows)
  {
    // View coordinates of this camera to shadow-map coordinates:
    // [0, 1]^3 from the light's clip space, through world coordinates.
    vtkInternals& sh = *this->Internals;
    vtkNew<vtkMatrix4x4> toMap;
    vtkNew<vtkMatrix4x4> light;
    light->DeepCopy(sh.ShadowProjection);
    vtkNew<vtkMatrix4x4> lightView;
    lightView->DeepCopy(sh.ShadowView);
    vtkMatrix4x4::Multiply4x4(light, lightView, light);
    vtkNew<vtkMatrix4x4> viewToWorld;
    viewToWorld->DeepCopy(ren->GetActiveCamera()->GetModelViewTransformMatrix());
    viewToWorld->Invert();
    vtkMatrix4x4::Multiply4x4(light, viewToWorld, light);
    vtkNew<vtkMatrix4x4> bias;
    for (int r = 0; r < 3; ++r)
    {
      bias->SetElement(r, r, 0.5);
      bias->SetElement(r, 3, 0.5);
    }
    vtkMatrix4x4::Multiply4x4(bias, light, toMap);
    float matrix[16];
    for (int r = 0; r < 4; ++r)
    {
      for (int c = 0; c < 4; ++c)
      {
        matrix[4 * c + r] = static_cast<float>(toMap->GetElement(r, c));
      }
    }
    program->SetUniformMatrix4x4("lineShadowMatrix", matrix);
    program->SetUniformf("lineShadowBias", sh.ShadowBias);
    program->SetUniformf("lineShadowTexel", 1.0f / static_cast<float>(sh.ShadowSize));
    program->SetUniformi("lineShadowPass", 0);
    sh.ShadowMap->Activate();
    program->SetUniformi("lineShadowMap", sh.ShadowMap->GetTextureUnit());
  }
  // Strips alternate their winding; the geometry is seen from both sides.
  vtkOpenGLState* state = static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow())->GetState();
  vtkOpenGLState::ScopedglEnableDisable cull(state, GL_CULL_FACE);
  state->vtkglDisable(GL_CULL_FACE);

  // Group by group (vtkSplineTubeVisibility): 1. the silhouette quads of
  // the visible batches, one multi-draw; 2. their polylines' caps, 3. the
  // fix-up's cylinders and joints of the batches fixed up; then the caps'
  // halos.
  auto* window = static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow());
  const GLsizei sides = static_cast<GLsizei>(in.MeshSides);
  const void* capOffset = reinterpret_cast<const void*>(6 * sizeof(unsigned short) * in.MeshSides);
  const size_t jointOffset = 9 * sizeof(unsigned short) * in.MeshSides;
  auto list = [&](vtkSplineVizGPUBuffer& buffer, const std::vector<std::uint32_t>& values,
                const char* uniform)
  {
    if (values.empty() ||
      !buffer.Upload(window, values.data(), values.size(), 1, VTK_TYPE_UINT32, GL_R32UI))
    {
      return false;
    }
    buffer.Activate(program, uniform);
    return true;
  };
  this->DrawVisibleChunks(ren, act,
    [&](const std::vector<std::uint32_t>& batches)
    {
      const auto drawsStart = Clock::now();
      in.FixUp.BuildDraws(
        batches, in.StripFirsts, in.StripCounts, in.Caps, in.FixedSegments, in.Joints);
      this->LastFixUpTime += std::chrono::duration<double>(Clock::now() - drawsStart).count();
      program->SetUniformi("lineMode", STRIPS);
      program->SetUniformi("lineHaloPass", 0);
      if (!in.StripFirsts.empty())
      {
        glMultiDrawArrays(GL_TRIANGLE_STRIP, in.StripFirsts.data(), in.StripCounts.data(),
          static_cast<GLsizei>(in.StripFirsts.size()));
      }
      const bool caps = this->Capping && list(in.CapsBuffer, in.Caps, "lineCaps");
      const bool fixed = list(in.Segments, in.FixedSegments, "lineSegments");
      const bool joints = list(in.JointsBuffer, in.Joints, "lineJoints");
      program->SetUniformi("lineCapList", 1);
      in.Meshes->Bind();
      for (int halo = 0; halo < (this->HaloWidth > 0.0 ? 2 : 1); ++halo)
      {
        program->SetUniformi("lineHaloPass", halo);
        if (caps)
        {
          program->SetUniformi("lineMode", CAPS);
          glDrawElementsInstanced(GL_TRIANGLES, 3 * sides, GL_UNSIGNED_SHORT, capOffset,
            static_cast<GLsizei>(in.Caps.size()));
        }
        // The fix-up's geometry has no halo: around a line seen down its
        // length a halo ring would cut the line's own parts further back
        // wherever they curve out of its profile (Stoll's halo is the
        // quads' band).
        if (fixed && halo == 0)
        {
          // The cylinders' back faces: hidden behind their front faces and,
          // at the open ends, behind the joint spheres or the end caps (a
          // sphere holds the end's disk). The vertex shader winds the walls
          // counterclockwise seen from outside, in view coordinates; culled
          // here, they cost no fragments (which get no early depth test).
          program->SetUniformi("lineMode", FIXUP_CYLINDERS);
          GLint cullMode = GL_BACK;
          state->vtkglGetIntegerv(GL_CULL_FACE_MODE, &cullMode);
          state->vtkglEnable(GL_CULL_FACE);
          state->vtkglCullFace(GL_BACK);
          glDrawElementsInstanced(GL_TRIANGLES, 6 * sides, GL_UNSIGNED_SHORT, nullptr,
            static_cast<GLsizei>(in.FixedSegments.size()));
          state->vtkglCullFace(static_cast<unsigned int>(cullMode));
          state->vtkglDisable(GL_CULL_FACE);
        }
        // Translucent, the joint spheres would be a second layer over the
        // cylinders they join (TestTubeTranslucency): left out.
        if (joints && halo == 0 && !act->IsRenderingTranslucentPolygonalGeometry())
        {
          program->SetUniformi("lineMode", FIXUP_JOINTS);
          glDrawElementsInstanced(GL_TRIANGLES, 6, GL_UNSIGNED_SHORT,
            reinterpret_cast<const void*>(jointOffset), static_cast<GLsizei>(in.Joints.size()));
        }
      }
      in.Meshes->Release();
    });
  if (shadows)
  {
    in.ShadowMap->Deactivate();
  }

  this->DeactivateTubeBuffers();
  for (vtkSplineVizGPUBuffer* buffer : { &in.Nodes, &in.Tangents, &in.Colors, &in.TexCoords,
         &in.Frames, &in.TubeStarts, &in.Segments, &in.JointsBuffer, &in.CapsBuffer })
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
  os << indent << "DepthDependentHalo: " << this->DepthDependentHalo << "\n";
  os << indent << "HaloDepthRange: " << this->HaloDepthRange << "\n";
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
