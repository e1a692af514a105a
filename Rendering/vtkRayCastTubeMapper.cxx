#include "vtkRayCastTubeMapper.h"

#include "vtkSplineTubeCore.h"
#include "vtkSplineVizGPUBuffer.h"

#include "vtkActor.h"
#include "vtkFloatArray.h"
#include "vtkHardwareSelector.h"
#include "vtkIdTypeArray.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkOpenGLCamera.h"
#include "vtkOpenGLHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkRenderer.h"
#include "vtkShader.h"
#include "vtkShaderProgram.h"
#include "vtkTypeUInt32Array.h"
#include "vtkUnsignedCharArray.h"

#include "vtkRayCastTubeFS.h"
#include "vtkRayCastTubeVS.h"
#include "vtkSplineTubeMathPrelude.h"
#include "vtkSplineTubeMathShared.h"

#include <vtk_glew.h>

#include <algorithm>
#include <cmath>
#include <vector>

vtkStandardNewMacro(vtkRayCastTubeMapper);

namespace
{
// Marks the end of the code that wrote gl_FragDepth; see ReplaceShaderValues.
const char* const DepthWrittenMarker =
  "// SplineViz: gl_FragDepth is the tube's depth from here on\n";

std::string TubeMathSource()
{
  return std::string(vtkSplineTubeMathPrelude) + vtkSplineTubeMathShared;
}
}

//------------------------------------------------------------------------------
vtkRayCastTubeMapper::vtkRayCastTubeMapper()
  : Nodes(new vtkSplineVizGPUBuffer)
  , Segments(new vtkSplineVizGPUBuffer)
  , Tubes(new vtkSplineVizGPUBuffer)
  , Colors(new vtkSplineVizGPUBuffer)
  , ColorDerivatives(new vtkSplineVizGPUBuffer)
{
  // Sphere-swept tubes need no cross-section frames.
  this->Core->ComputeFramesOff();
}

//------------------------------------------------------------------------------
vtkRayCastTubeMapper::~vtkRayCastTubeMapper() = default;

//------------------------------------------------------------------------------
void vtkRayCastTubeMapper::SetSubSegments(int n)
{
  n = std::max(2, std::min(16, n + (n % 2)));
  if (n != this->SubSegments)
  {
    this->SubSegments = n;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
size_t vtkRayCastTubeMapper::GetGPUMemorySize()
{
  return this->Nodes->GetNumberOfBytes() + this->Segments->GetNumberOfBytes() +
    this->Tubes->GetNumberOfBytes() + this->Colors->GetNumberOfBytes() +
    this->ColorDerivatives->GetNumberOfBytes();
}

//------------------------------------------------------------------------------
void vtkRayCastTubeMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  this->QuadIndices->ReleaseGraphicsResources();
  this->QuadIndicesUploaded = false;
  this->Nodes->ReleaseGraphicsResources(window);
  this->Segments->ReleaseGraphicsResources(window);
  this->Tubes->ReleaseGraphicsResources(window);
  this->Colors->ReleaseGraphicsResources(window);
  this->ColorDerivatives->ReleaseGraphicsResources(window);
  this->Superclass::ReleaseGraphicsResources(window);
}

//------------------------------------------------------------------------------
void vtkRayCastTubeMapper::UploadTubes(vtkOpenGLRenderWindow* window)
{
  if (this->QuadIndices->GetHandle() == 0 || !this->QuadIndicesUploaded)
  {
    std::vector<unsigned short> indices(6 * QuadsPerDraw);
    for (int q = 0; q < QuadsPerDraw; ++q)
    {
      const unsigned short v = static_cast<unsigned short>(4 * q);
      const unsigned short pattern[6] = { v, static_cast<unsigned short>(v + 1),
        static_cast<unsigned short>(v + 2), static_cast<unsigned short>(v + 2),
        static_cast<unsigned short>(v + 1), static_cast<unsigned short>(v + 3) };
      std::copy(pattern, pattern + 6, &indices[6 * q]);
    }
    this->QuadIndices->Upload(indices, vtkOpenGLBufferObject::ElementArrayBuffer);
    this->QuadIndicesUploaded = true;
  }
  vtkSplineTubeCore* core = this->Core;
  const vtkIdType numNodes = core->GetNumberOfNodes();
  const vtkIdType numSegments = core->GetNumberOfSegments();
  const vtkIdType numTubes = core->GetNumberOfTubes();
  if (numNodes >= (vtkIdType(1) << 30))
  {
    vtkErrorMacro(<< "Too many nodes (" << numNodes << "); at most 2^30 are supported.");
    return;
  }

  // Nodes: (x, y, z, r), (dx, dy, dz, dr), positions relative to Shift.
  std::vector<float> nodes(static_cast<size_t>(8 * numNodes));
  const float* P = core->GetNodePositions()->GetPointer(0);
  const float* M = core->GetNodeTangents()->GetPointer(0);
  const float* R = core->GetNodeRadii()->GetPointer(0);
  for (vtkIdType i = 0; i < numNodes; ++i)
  {
    float* n = &nodes[8 * i];
    for (int c = 0; c < 3; ++c)
    {
      n[c] = static_cast<float>(P[3 * i + c] - this->Shift[c]);
      n[4 + c] = M[3 * i + c];
    }
    n[3] = R[2 * i];
    n[7] = R[2 * i + 1];
  }
  this->Nodes->Upload(window, nodes.data(), 2 * numNodes, 4, VTK_FLOAT, GL_RGBA32F);

  // Segments: (first node | flags << 30, tube); tubes: (cell id, block id).
  std::vector<vtkTypeUInt32> segments(static_cast<size_t>(2 * numSegments));
  std::vector<vtkTypeInt32> tubes(static_cast<size_t>(2 * std::max<vtkIdType>(numTubes, 1)));
  const vtkTypeUInt32* first = core->GetSegmentFirstNodes()->GetPointer(0);
  const unsigned char* flags = core->GetSegmentFlags()->GetPointer(0);
  vtkIdType s = 0;
  for (vtkIdType t = 0; t < numTubes; ++t)
  {
    const vtkIdType n = core->GetTubeNumberOfNodes()->GetValue(t);
    tubes[2 * t] = static_cast<vtkTypeInt32>(core->GetSegmentCellIds()->GetValue(s));
    tubes[2 * t + 1] = static_cast<vtkTypeInt32>(core->GetSegmentBlockIds()->GetValue(s));
    for (vtkIdType k = 0; k + 1 < n; ++k, ++s)
    {
      segments[2 * s] = first[s] | (static_cast<vtkTypeUInt32>(flags[s]) << 30);
      segments[2 * s + 1] = static_cast<vtkTypeUInt32>(t);
    }
  }
  this->Segments->Upload(window, segments.data(), numSegments, 2, VTK_TYPE_UINT32, GL_RG32UI);
  this->Tubes->Upload(window, tubes.data(), numTubes, 2, VTK_TYPE_INT32, GL_RG32I);

  // Colors (RGBA8) and their derivatives (signed, scaled by 127, clamped to
  // [-1, 1]: a full color change per segment), only with scalar coloring.
  if (this->HaveColors)
  {
    std::vector<unsigned char> colors(static_cast<size_t>(4 * numNodes));
    std::vector<signed char> derivatives(static_cast<size_t>(4 * numNodes));
    const float* C = core->GetNodeColors()->GetPointer(0);
    const float* D = core->GetNodeColorDerivatives()->GetPointer(0);
    for (vtkIdType i = 0; i < 4 * numNodes; ++i)
    {
      colors[i] =
        static_cast<unsigned char>(std::lround(255.0f * std::min(1.0f, std::max(0.0f, C[i]))));
      derivatives[i] =
        static_cast<signed char>(std::lround(127.0f * std::min(1.0f, std::max(-1.0f, D[i]))));
    }
    this->Colors->Upload(window, colors.data(), numNodes, 4, VTK_UNSIGNED_CHAR, GL_RGBA8);
    this->ColorDerivatives->Upload(
      window, derivatives.data(), numNodes, 4, VTK_SIGNED_CHAR, GL_RGBA8I);
  }
  else
  {
    this->Colors->ReleaseGraphicsResources(window);
    this->ColorDerivatives->ReleaseGraphicsResources(window);
  }
}

//------------------------------------------------------------------------------
void vtkRayCastTubeMapper::GetShaderTemplate(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act)
{
  this->Superclass::GetShaderTemplate(shaders, ren, act);
  shaders[vtkShader::Vertex]->SetSource(vtkRayCastTubeVS);
  shaders[vtkShader::Geometry]->SetSource("");
}

//------------------------------------------------------------------------------
void vtkRayCastTubeMapper::ReplaceShaderValues(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act)
{
  std::string VSSource = shaders[vtkShader::Vertex]->GetSource();
  std::string FSSource = shaders[vtkShader::Fragment]->GetSource();
  const std::string math = TubeMathSource();

  vtkShaderProgram::Substitute(VSSource, "//VTK::SplineTubeMath::Dec", math);

  std::string declarations = vtkRayCastTubeFS;
  vtkShaderProgram::Substitute(declarations, "//VTK::SplineTubeMath::Dec", math);
  if (this->HaveColors)
  {
    declarations += "uniform samplerBuffer tubeColors;\n"
                    "uniform isamplerBuffer tubeColorDerivatives;\n";
  }
  vtkShaderProgram::Substitute(FSSource, "//VTK::Normal::Dec", declarations);
  vtkShaderProgram::Substitute(FSSource, "//VTK::PositionVC::Dec", "in vec4 vertexVCVSOutput;");
  vtkShaderProgram::Substitute(
    FSSource, "//VTK::PositionVC::Impl", "vec4 vertexVC = vertexVCVSOutput;\n");

  std::string depth = "  vec3 tubeHitVC;\n"
                      "  vec3 normalVCVSOutput;\n"
                      "  float tubeT;\n"
                      "  if (!tubeRayCast(vertexVC.xyz, tubeHitVC, normalVCVSOutput, tubeT))\n"
                      "  {\n"
                      "    discard;\n"
                      "  }\n"
                      "  vertexVC = vec4(tubeHitVC, 1.0);\n"
                      "  //VTK::TubeClip::Impl\n"
                      "  vec4 tubeHitDC = VCDCMatrix * vertexVC;\n"
                      "  gl_FragDepth = 0.5 * (gl_DepthRange.diff * (tubeHitDC.z / tubeHitDC.w) +\n"
                      "    gl_DepthRange.near + gl_DepthRange.far);\n";
  if (this->HaveColors)
  {
    depth +=
      "  int tubeNode = tubeInfoVSOutput.x;\n"
      "  vec4 tubeColor = clamp(svHermite(texelFetch(tubeColors, tubeNode),\n"
      "    vec4(texelFetch(tubeColorDerivatives, tubeNode)) / 127.0,\n"
      "    texelFetch(tubeColors, tubeNode + 1),\n"
      "    vec4(texelFetch(tubeColorDerivatives, tubeNode + 1)) / 127.0, tubeT), 0.0, 1.0);\n";
  }
  depth += DepthWrittenMarker;
  vtkShaderProgram::Substitute(FSSource, "//VTK::Depth::Impl", depth);
  // The normal comes from the intersection.
  vtkShaderProgram::Substitute(FSSource, "//VTK::Normal::Impl", "");

  // Picking: the cell is the polyline, the composite index its block.
  if (this->LastSelectionState >= vtkHardwareSelector::MIN_KNOWN_PASS)
  {
    const char* encode =
      "  gl_FragData[0] = vec4(float(idx % 256) / 255.0, float((idx / 256) % 256) / 255.0,\n"
      "    float((idx / 65536) % 256) / 255.0, 1.0);\n";
    switch (this->LastSelectionState)
    {
      case vtkHardwareSelector::CELL_ID_LOW24:
        vtkShaderProgram::Substitute(
          FSSource, "//VTK::Picking::Dec", "uniform isamplerBuffer tubeTubes;\n");
        vtkShaderProgram::Substitute(FSSource, "//VTK::Picking::Impl",
          std::string("  int idx = texelFetch(tubeTubes, tubeInfoVSOutput.z).x;\n") + encode);
        break;
      case vtkHardwareSelector::CELL_ID_HIGH24:
        vtkShaderProgram::Substitute(
          FSSource, "//VTK::Picking::Dec", "uniform isamplerBuffer tubeTubes;\n");
        vtkShaderProgram::Substitute(FSSource, "//VTK::Picking::Impl",
          std::string("  int idx = (texelFetch(tubeTubes, tubeInfoVSOutput.z).x >> 24) & 0xff;\n") +
            encode);
        break;
      case vtkHardwareSelector::COMPOSITE_INDEX_PASS:
        // The block's flat index (as vtkCompositePolyDataMapper2 reports it);
        // a non-composite input keeps VTK's per-mapper index.
        if (this->InputIsComposite)
        {
          vtkShaderProgram::Substitute(
            FSSource, "//VTK::Picking::Dec", "uniform isamplerBuffer tubeTubes;\n");
          vtkShaderProgram::Substitute(FSSource, "//VTK::Picking::Impl",
            std::string("  int idx = texelFetch(tubeTubes, tubeInfoVSOutput.z).y;\n") + encode);
        }
        break;
      case vtkHardwareSelector::POINT_ID_LOW24:
      case vtkHardwareSelector::POINT_ID_HIGH24:
        // Tubes have no points to pick.
        vtkShaderProgram::Substitute(FSSource, "//VTK::Picking::Impl", "  discard;\n");
        break;
      default:
        break; // actor and process passes: VTK's mapperIndex
    }
  }

  shaders[vtkShader::Vertex]->SetSource(VSSource);
  shaders[vtkShader::Fragment]->SetSource(FSSource);

  this->Superclass::ReplaceShaderValues(shaders, ren, act);

  // Render passes (depth peeling) compare gl_FragCoord.z with their depth
  // textures; for ray-cast fragments the depth is the one written above.
  FSSource = shaders[vtkShader::Fragment]->GetSource();
  const size_t marker = FSSource.find(DepthWrittenMarker);
  if (marker != std::string::npos)
  {
    std::string tail = FSSource.substr(marker);
    vtkShaderProgram::Substitute(tail, "gl_FragCoord.z", "gl_FragDepth", true);
    FSSource = FSSource.substr(0, marker) + tail;
    shaders[vtkShader::Fragment]->SetSource(FSSource);
  }
  if (getenv("SPLINEVIZ_DUMP_SHADERS"))
  {
    cout << "=== VS\n"
         << shaders[vtkShader::Vertex]->GetSource() << "\n=== GS\n"
         << shaders[vtkShader::Geometry]->GetSource() << "\n=== FS\n"
         << shaders[vtkShader::Fragment]->GetSource() << endl;
  }
}

//------------------------------------------------------------------------------
void vtkRayCastTubeMapper::ReplaceShaderColor(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act)
{
  if (!this->HaveColors)
  {
    this->Superclass::ReplaceShaderColor(shaders, ren, act);
    return;
  }
  // As VTK does for interpolated point colors, with the color spline's value.
  std::string FSSource = shaders[vtkShader::Fragment]->GetSource();
  std::string colorDec = "uniform float ambientIntensity;\n"
                         "uniform float diffuseIntensity;\n"
                         "uniform float opacityUniform;\n"
                         "uniform vec3 ambientColorUniform;\n"
                         "uniform vec3 diffuseColorUniform;\n";
  std::string colorImpl;
  if (this->PrimitiveInfo[this->LastBoundBO].LastLightComplexity)
  {
    colorDec += "uniform float specularIntensity;\n"
                "uniform vec3 specularColorUniform;\n"
                "uniform float specularPowerUniform;\n";
    colorImpl += "  vec3 specularColor = specularIntensity * specularColorUniform;\n"
                 "  float specularPower = specularPowerUniform;\n";
  }
  colorImpl += "  vec3 ambientColor = ambientIntensity * tubeColor.rgb;\n"
               "  vec3 diffuseColor = diffuseIntensity * tubeColor.rgb;\n"
               "  float opacity = opacityUniform * tubeColor.a;\n";
  vtkShaderProgram::Substitute(FSSource, "//VTK::Color::Dec", colorDec);
  vtkShaderProgram::Substitute(FSSource, "//VTK::Color::Impl", colorImpl);
  shaders[vtkShader::Fragment]->SetSource(FSSource);
}

//------------------------------------------------------------------------------
void vtkRayCastTubeMapper::ReplaceShaderClip(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer*, vtkActor*)
{
  // Clip the hit point (not the proxy box): planes are in data coordinates.
  std::string FSSource = shaders[vtkShader::Fragment]->GetSource();
  if (this->GetNumberOfClippingPlanes())
  {
    vtkShaderProgram::Substitute(FSSource, "//VTK::Clip::Dec",
      "uniform int numClipPlanes;\n"
      "uniform vec4 clipPlanes[6];\n"
      "uniform mat4 tubeVCMC;\n");
    vtkShaderProgram::Substitute(FSSource, "//VTK::TubeClip::Impl",
      "  vec4 tubeHitMC = tubeVCMC * vertexVC;\n"
      "  for (int planeNum = 0; planeNum < numClipPlanes; planeNum++)\n"
      "  {\n"
      "    if (dot(clipPlanes[planeNum], tubeHitMC) < 0.0) discard;\n"
      "  }\n");
  }
  shaders[vtkShader::Fragment]->SetSource(FSSource);
}

//------------------------------------------------------------------------------
bool vtkRayCastTubeMapper::GetNeedToRebuildShaders(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  // Shader variants depend on scalar coloring and composite input too.
  const int variant = (this->HaveColors ? 1 : 0) | (this->InputIsComposite ? 2 : 0);
  const bool superclass = this->Superclass::GetNeedToRebuildShaders(cellBO, ren, act);
  if (variant != this->ShaderVariant)
  {
    this->ShaderVariant = variant;
    return true;
  }
  return superclass;
}

//------------------------------------------------------------------------------
void vtkRayCastTubeMapper::SetMapperShaderParameters(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  this->Superclass::SetMapperShaderParameters(cellBO, ren, act);
  vtkShaderProgram* program = cellBO.Program;
  program->SetUniformi("subSegments", this->SubSegments);
  program->SetUniformi("rootIterations", this->RootIterations);
  program->SetUniformi("rootSamples", this->RootSamples);
  this->Nodes->Activate(program, "tubeNodes");
  this->Segments->Activate(program, "tubeSegments");
  if (program->IsUniformUsed("tubeTubes"))
  {
    this->Tubes->Activate(program, "tubeTubes");
  }
  if (this->HaveColors)
  {
    this->Colors->Activate(program, "tubeColors");
    this->ColorDerivatives->Activate(program, "tubeColorDerivatives");
  }
}

//------------------------------------------------------------------------------
void vtkRayCastTubeMapper::SetCameraShaderParameters(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  this->Superclass::SetCameraShaderParameters(cellBO, ren, act);
  vtkShaderProgram* program = cellBO.Program;
  float modelView[16];
  float viewModel[16];
  float radiusScale = 1.0f;
  this->ComputeTubeMatrices(ren, act, modelView, viewModel, radiusScale);
  program->SetUniformMatrix4x4("tubeMCVC", modelView);
  vtkMatrix4x4* wcdc;
  vtkMatrix4x4* wcvc;
  vtkMatrix3x3* normals;
  vtkMatrix4x4* vcdc;
  static_cast<vtkOpenGLCamera*>(ren->GetActiveCamera())
    ->GetKeyMatrices(ren, wcvc, normals, vcdc, wcdc);
  program->SetUniformMatrix("VCDCMatrix", vcdc);
  double range[2];
  ren->GetActiveCamera()->GetClippingRange(range);
  program->SetUniformf("tubeNearPlane", static_cast<float>(range[0]));
  program->SetUniformf("tubeRadiusScale", radiusScale);
  if (program->IsUniformUsed("tubeVCMC"))
  {
    program->SetUniformMatrix4x4("tubeVCMC", viewModel);
  }
}

//------------------------------------------------------------------------------
void vtkRayCastTubeMapper::RenderPieceDraw(vtkRenderer* ren, vtkActor* act)
{
  const vtkIdType count = this->Core->GetNumberOfSegments() * this->SubSegments;
  if (count == 0 || this->Nodes->GetNumberOfBytes() == 0)
  {
    return;
  }
  vtkOpenGLHelper& helper = this->Primitives[PrimitiveTris];
  this->UpdateShaders(helper, ren, act);

  if (!helper.Program)
  {
    return;
  }
  // UpdateShaders() may have released the VAO after binding it (new
  // program); the draw has no attributes but core profiles need a VAO bound.
  helper.VAO->Bind();
  // One rectangle (4-vertex strip) per sub-segment; either winding.
  vtkOpenGLState* state = static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow())->GetState();
  vtkOpenGLState::ScopedglEnableDisable cull(state, GL_CULL_FACE);
  state->vtkglDisable(GL_CULL_FACE);
  // Rectangles as indexed triangles: one small, shared index pattern for
  // QuadsPerDraw rectangles, drawn repeatedly with a base vertex (so that
  // every corner is shaded once, without per-rectangle index memory and
  // without the per-instance cost of instancing in software renderers).
  this->QuadIndices->Bind();
  const vtkIdType chunks = (count + QuadsPerDraw - 1) / QuadsPerDraw;
  std::vector<GLsizei> counts(static_cast<size_t>(chunks));
  std::vector<const void*> offsets(static_cast<size_t>(chunks), nullptr);
  std::vector<GLint> baseVertices(static_cast<size_t>(chunks));
  for (vtkIdType c = 0; c < chunks; ++c)
  {
    const vtkIdType quads = std::min<vtkIdType>(QuadsPerDraw, count - c * QuadsPerDraw);
    counts[c] = static_cast<GLsizei>(6 * quads);
    baseVertices[c] = static_cast<GLint>(4 * c * QuadsPerDraw);
  }
  glMultiDrawElementsBaseVertex(GL_TRIANGLES, counts.data(), GL_UNSIGNED_SHORT, offsets.data(),
    static_cast<GLsizei>(chunks), baseVertices.data());
  this->QuadIndices->Release();

  this->Nodes->Deactivate();
  this->Segments->Deactivate();
  this->Tubes->Deactivate();
  this->Colors->Deactivate();
  this->ColorDerivatives->Deactivate();
}

//------------------------------------------------------------------------------
void vtkRayCastTubeMapper::ProcessSelectorPixelBuffers(
  vtkHardwareSelector*, std::vector<unsigned int>&, vtkProp*)
{
  // The shader wrote the final cell and block ids; nothing to convert.
}

//------------------------------------------------------------------------------
void vtkRayCastTubeMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SubSegments: " << this->SubSegments << "\n";
  os << indent << "RootIterations: " << this->RootIterations << "\n";
  os << indent << "RootSamples: " << this->RootSamples << "\n";
}
