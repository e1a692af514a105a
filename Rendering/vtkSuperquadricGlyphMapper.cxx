// SPDX-License-Identifier: BSD-3-Clause
#include "vtkSuperquadricGlyphMapper.h"

#include "vtkSplineVizGPUBuffer.h"
#include "vtkSplineVizTensorMath.h"
#include "vtkSuperquadricGlyphPreparer.h"

#include "vtkAlgorithmOutput.h"
#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkCompositeDataDisplayAttributes.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataSet.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkHardwareSelector.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkMath.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkObjectFactory.h"
#include "vtkOutputWindow.h"
#include "vtkPartitionedDataSet.h"
#include "vtkPartitionedDataSetCollection.h"
#include "vtkOpenGLActor.h"
#include "vtkOpenGLCamera.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkOpenGLHelper.h"
#include "vtkOpenGLIndexBufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLRenderer.h"
#include "vtkOpenGLVertexBufferObject.h"
#include "vtkOpenGLVertexBufferObjectGroup.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkScalarsToColors.h"
#include "vtkShaderProgram.h"
#include "vtkSmartPointer.h"
#include "vtkGarbageCollector.h"
#include "vtkTextureObject.h"
#include "vtkUnsignedCharArray.h"

#include "vtkSuperquadricGlyphFS.h"
#include "vtkSuperquadricGlyphGS.h"
#include "vtkSuperquadricGlyphShared.h"
#include "vtkSuperquadricGlyphVS.h"
#include "vtkSplineVizShaderPrelude.h"
#include "vtkTensorMathShared.h"

#include "vtk_glew.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkSuperquadricGlyphMapper);

namespace
{
namespace TM = vtkSplineVizTensorMath;
}

//------------------------------------------------------------------------------
class vtkSuperquadricGlyphMapper::Internals
{
public:
  // Owned, and reported to the garbage collector (ReportReferences): this
  // mapper's input is the preparer's output, so the two form a pipeline
  // cycle that only the collector can break.
  vtkSmartPointer<vtkSuperquadricGlyphPreparer> Preparer =
    vtkSmartPointer<vtkSuperquadricGlyphPreparer>::New();
  vtkNew<vtkCallbackCommand> Forwarder;
  std::string ColorKey;
  bool HaveColors = false;
  bool ShaderHaveColors = false;
  bool ShaderGeneralShapes = false;
  bool ShaderClip = false;
  // per-block attributes of composite inputs, uploaded per glyph
  vtkSmartPointer<vtkCompositeDataDisplayAttributes> BlockAttributes;
  vtkNew<vtkFloatArray> BlockColors;
  bool HaveBlockColors = false;
  bool ShaderHaveBlockColors = false;
  bool AnyTranslucentBlock = false;

  /// The block attributes of every leaf of a composite input, in the
  /// preparer's order: (r, g, b or -1 for none, opacity; 0 hidden), and the
  /// first concatenated point id of each leaf (one more entry). Returns false
  /// when there are no attributes or none applies; sets AnyTranslucentBlock.
  bool BlockColorsOfLeaves(
    std::vector<vtkIdType>& firstId, std::vector<std::array<float, 4>>& leafColor)
  {
    this->AnyTranslucentBlock = false;
    vtkCompositeDataSet* composite =
      vtkCompositeDataSet::SafeDownCast(this->Preparer->GetInputDataObject(0, 0));
    if (!this->BlockAttributes || !composite)
    {
      return false;
    }
    // the leaves' states, inherited from the nearest block that sets them
    // (as vtkCompositePolyDataMapper2 does: ParaView hides the root and
    // shows the selected blocks)
    std::vector<vtkDataSet*> leaves;
    std::vector<std::array<float, 4>> states;
    bool any = false;
    this->CollectBlockStates(composite, { -1.0f, -1.0f, -1.0f, 1.0f }, true, leaves, states, any);
    if (leaves != vtkCompositeDataSet::GetDataSets(composite))
    {
      // a composite type whose structure is not walked here: the leaves' own
      // attributes only
      const std::vector<vtkDataSet*> all = vtkCompositeDataSet::GetDataSets(composite);
      leaves.clear();
      states.clear();
      any = false;
      for (vtkDataSet* leaf : all)
      {
        this->CollectBlockStates(leaf, { -1.0f, -1.0f, -1.0f, 1.0f }, true, leaves, states, any);
      }
      if (leaves != all)
      {
        return false; // (empty leaves: no attributes)
      }
    }
    firstId.assign(leaves.size() + 1, 0);
    leafColor = states;
    for (size_t b = 0; b < leaves.size(); ++b)
    {
      firstId[b + 1] = firstId[b] + leaves[b]->GetNumberOfPoints();
      const float a = leafColor[b][3];
      this->AnyTranslucentBlock = this->AnyTranslucentBlock || (a > 0.0f && a < 1.0f);
    }
    return any;
  }

  /// Depth-first over multiblocks and partitioned collections: a node's
  /// color, opacity and visibility override the inherited ones; leaves (data
  /// sets) are appended with their state (opacity 0 when invisible).
  void CollectBlockStates(vtkDataObject* node, std::array<float, 4> state, bool visible,
    std::vector<vtkDataSet*>& leaves, std::vector<std::array<float, 4>>& states, bool& any)
  {
    if (!node)
    {
      return;
    }
    vtkCompositeDataDisplayAttributes* attributes = this->BlockAttributes;
    if (attributes->HasBlockColor(node))
    {
      double rgb[3];
      attributes->GetBlockColor(node, rgb);
      state = { static_cast<float>(rgb[0]), static_cast<float>(rgb[1]), static_cast<float>(rgb[2]),
        state[3] };
      any = true;
    }
    if (attributes->HasBlockOpacity(node))
    {
      state[3] =
        static_cast<float>(std::max(0.0, std::min(1.0, attributes->GetBlockOpacity(node))));
      any = true;
    }
    if (attributes->HasBlockVisibility(node))
    {
      visible = attributes->GetBlockVisibility(node);
      any = any || !visible;
    }
    if (auto* ds = vtkDataSet::SafeDownCast(node))
    {
      if (ds->GetNumberOfPoints() > 0 || ds->GetNumberOfCells() > 0)
      {
        leaves.push_back(ds);
        std::array<float, 4> leafState = state;
        if (!visible)
        {
          leafState[3] = 0.0f;
        }
        states.push_back(leafState);
      }
    }
    else if (auto* mb = vtkMultiBlockDataSet::SafeDownCast(node))
    {
      for (unsigned int i = 0; i < mb->GetNumberOfBlocks(); ++i)
      {
        this->CollectBlockStates(mb->GetBlock(i), state, visible, leaves, states, any);
      }
    }
    else if (auto* pdc = vtkPartitionedDataSetCollection::SafeDownCast(node))
    {
      for (unsigned int i = 0; i < pdc->GetNumberOfPartitionedDataSets(); ++i)
      {
        this->CollectBlockStates(
          pdc->GetPartitionedDataSet(i), state, visible, leaves, states, any);
      }
    }
    else if (auto* pds = vtkPartitionedDataSet::SafeDownCast(node))
    {
      for (unsigned int i = 0; i < pds->GetNumberOfPartitions(); ++i)
      {
        this->CollectBlockStates(pds->GetPartition(i), state, visible, leaves, states, any);
      }
    }
  }
  const void* UploadedTensors = nullptr;
  vtkMTimeType UploadedTensorsTime = 0;
  int BytesPerGlyph = 0;
  bool TooLarge = false; // the glyphs did not fit on the GPU: draw nothing

  // Occlusion culling: per brick its group of the current view, the draw
  // ranges of each group, the depth pyramid (level 0: a copy of the depth
  // buffer; levels 1, 2, 4, 6: maxima over 2^k x 2^k pixels).
  std::vector<unsigned char> BrickGroup;
  static constexpr int MaxGroups = 16;
  static constexpr int FrontSplits = 2; // parts of the front layer (ComputeGroups)
  std::vector<GLint> First[MaxGroups];
  std::vector<GLsizei> Count[MaxGroups];
  vtkIdType GroupGlyphs[MaxGroups] = {};
  int Pyramids = 0;
  vtkNew<vtkTextureObject> Depth;
  vtkNew<vtkTextureObject> Level[4]; // 2, 4, 16, 64 pixels
  vtkNew<vtkOpenGLFramebufferObject> LevelFBO;
  std::unique_ptr<vtkOpenGLQuadHelper> Reduce;

  /// Groups of the bricks for a camera at `eye` (model coordinates; for a
  /// parallel projection eye is the direction towards the camera and
  /// parallel is true): front (0), second (1) and deeper (2) layers, from
  /// the non-empty bricks between a brick and the camera side along the
  /// grid axes. Fills the draw ranges. Returns false for a single brick.
  bool ComputeGroups(vtkPolyData* glyphs, const double eye[3], bool parallel, int groups);

  /// Builds the depth pyramid of the viewport (x0, y0, w, h) of the current
  /// draw framebuffer.
  void BuildPyramid(vtkOpenGLRenderWindow* renWin, int x0, int y0, int w, int h);

  void ReleaseGraphicsResources(vtkWindow* win)
  {
    this->Depth->ReleaseGraphicsResources(win);
    for (auto& level : this->Level)
    {
      level->ReleaseGraphicsResources(win);
    }
    this->LevelFBO->ReleaseGraphicsResources(win);
    if (this->Reduce)
    {
      this->Reduce->ReleaseGraphicsResources(win);
      this->Reduce.reset();
    }
  }
};

namespace
{
// The reduction pass of the depth pyramid: each texel the maximum of a
// factor x factor block of the finer level (clamped at its edges).
const char* const PyramidReduceFS = R"(//VTK::System::Dec
in vec2 texCoord;
uniform sampler2D source;
uniform ivec2 sourceSize;
uniform int factor;
//VTK::Output::Dec
void main()
{
  ivec2 base = factor * ivec2(gl_FragCoord.xy);
  float m = 0.0;
  if (texCoord.x < -1.0)
  {
    m = 1.0; // never: keeps the quad's texture coordinate attribute in use
  }
  for (int j = 0; j < factor; ++j)
  {
    for (int i = 0; i < factor; ++i)
    {
      m = max(m, texelFetch(source, min(base + ivec2(i, j), sourceSize - 1), 0).r);
    }
  }
  gl_FragData[0] = vec4(m, 0.0, 0.0, 1.0);
}
)";
}

//------------------------------------------------------------------------------
bool vtkSuperquadricGlyphMapper::Internals::ComputeGroups(
  vtkPolyData* glyphs, const double eye[3], bool parallel, int groups)
{
  const int deepest = std::max(1, std::min(groups, MaxGroups)) - 1;
  vtkDataArray* gridArray = glyphs->GetFieldData()->GetArray("sqBrickGrid");
  vtkIdTypeArray* offsetArray =
    vtkArrayDownCast<vtkIdTypeArray>(glyphs->GetFieldData()->GetArray("sqBrickOffsets"));
  if (!gridArray || !offsetArray || gridArray->GetNumberOfTuples() != 9)
  {
    return false;
  }
  double origin[3], spacing[3];
  int dims[3];
  for (int c = 0; c < 3; ++c)
  {
    origin[c] = gridArray->GetTuple1(c);
    spacing[c] = gridArray->GetTuple1(3 + c);
    dims[c] = static_cast<int>(gridArray->GetTuple1(6 + c));
  }
  const vtkIdType bricks = static_cast<vtkIdType>(dims[0]) * dims[1] * dims[2];
  if (bricks <= 1 || offsetArray->GetNumberOfTuples() != bricks + 1)
  {
    return false;
  }
  const vtkIdType* offsets = offsetArray->GetPointer(0);
  this->BrickGroup.resize(bricks);
  unsigned char* group = this->BrickGroup.data();
  vtkSMPTools::For(0, bricks,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType b = begin; b < end; ++b)
      {
        if (offsets[b + 1] == offsets[b])
        {
          group[b] = 0;
          continue;
        }
        const int cell[3] = { static_cast<int>(b % dims[0]),
          static_cast<int>((b / dims[0]) % dims[1]),
          static_cast<int>(b / (static_cast<vtkIdType>(dims[0]) * dims[1])) };
        // towards the camera from the brick's center
        double dir[3];
        double length = 0.0;
        for (int c = 0; c < 3; ++c)
        {
          dir[c] = parallel ? eye[c] : eye[c] - (origin[c] + (cell[c] + 0.5) * spacing[c]);
          length = std::max(length, std::abs(dir[c]));
        }
        // The layer: along each grid axis that faces the camera, the number
        // of non-empty bricks between this one and the camera side (at most
        // 2, looking 8 bricks far); the smallest over the axes. (A ray
        // towards the camera would also count the brick's neighbours on the
        // same visible face.)
        int layer = deepest;
        for (int c = 0; c < 3 && layer > 0; ++c)
        {
          if (!(std::abs(dir[c]) > 0.05 * length))
          {
            continue;
          }
          const int step = dir[c] > 0 ? 1 : -1;
          // the camera's brick along this axis (perspective): no further
          int last = step > 0 ? dims[c] - 1 : 0;
          if (!parallel)
          {
            const int eyeCell = static_cast<int>(std::floor((eye[c] - origin[c]) / spacing[c]));
            last = step > 0 ? std::min(last, eyeCell) : std::max(last, eyeCell);
          }
          int found = 0;
          int k[3] = { cell[0], cell[1], cell[2] };
          for (int walked = 0; walked < 4 * deepest + 4 && found < layer; ++walked)
          {
            if (k[c] == last)
            {
              break;
            }
            k[c] += step;
            const vtkIdType n = k[0] + dims[0] * (k[1] + static_cast<vtkIdType>(dims[1]) * k[2]);
            found += offsets[n + 1] > offsets[n] ? 1 : 0;
            if (walked == 4 * deepest + 3)
            {
              found = deepest; // not resolved: behind
            }
          }
          layer = std::min(layer, found);
        }
        group[b] = static_cast<unsigned char>(layer);
      }
    });
  // The front layer is drawn in FrontSplits parts, nearest bricks first:
  // its glyphs' sprites overlap their neighbours', so later parts are culled
  // against earlier ones too. Deeper layers follow.
  const int splits = std::min(FrontSplits, deepest);
  if (splits > 1)
  {
    std::vector<std::pair<double, vtkIdType>> front;
    for (vtkIdType b = 0; b < bricks; ++b)
    {
      if (offsets[b + 1] > offsets[b] && group[b] == 0)
      {
        const double center[3] = { origin[0] + (b % dims[0] + 0.5) * spacing[0],
          origin[1] + ((b / dims[0]) % dims[1] + 0.5) * spacing[1],
          origin[2] + (b / (static_cast<vtkIdType>(dims[0]) * dims[1]) + 0.5) * spacing[2] };
        const double depth = parallel
          ? -(center[0] * eye[0] + center[1] * eye[1] + center[2] * eye[2])
          : (center[0] - eye[0]) * (center[0] - eye[0]) +
            (center[1] - eye[1]) * (center[1] - eye[1]) +
            (center[2] - eye[2]) * (center[2] - eye[2]);
        front.emplace_back(depth, b);
      }
    }
    std::sort(front.begin(), front.end());
    for (vtkIdType b = 0; b < bricks; ++b)
    {
      if (group[b] > 0)
      {
        group[b] = static_cast<unsigned char>(std::min(group[b] + splits - 1, deepest));
      }
    }
    for (size_t k = 0; k < front.size(); ++k)
    {
      group[front[k].second] = static_cast<unsigned char>((k * splits) / front.size());
    }
  }
  for (int g = 0; g < MaxGroups; ++g)
  {
    this->First[g].clear();
    this->Count[g].clear();
    this->GroupGlyphs[g] = 0;
  }
  for (vtkIdType b = 0; b < bricks; ++b)
  {
    const vtkIdType n = offsets[b + 1] - offsets[b];
    if (n == 0)
    {
      continue;
    }
    const int g = group[b];
    this->GroupGlyphs[g] += n;
    if (!this->First[g].empty() &&
      this->First[g].back() + this->Count[g].back() == static_cast<GLint>(offsets[b]))
    {
      this->Count[g].back() += static_cast<GLsizei>(n);
    }
    else
    {
      this->First[g].push_back(static_cast<GLint>(offsets[b]));
      this->Count[g].push_back(static_cast<GLsizei>(n));
    }
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkSuperquadricGlyphMapper::Internals::BuildPyramid(
  vtkOpenGLRenderWindow* renWin, int x0, int y0, int w, int h)
{
  vtkOpenGLState* ostate = renWin->GetState();
  // Level 0: the depth buffer of the current draw framebuffer.
  this->Depth->SetContext(renWin);
  if (!this->Depth->GetHandle() || static_cast<int>(this->Depth->GetWidth()) != w ||
    static_cast<int>(this->Depth->GetHeight()) != h)
  {
    this->Depth->AllocateDepth(w, h, vtkTextureObject::Float32);
  }
  unsigned int drawBinding = 0, drawBuffer = 0;
  ostate->GetCurrentDrawFramebufferState(drawBinding, drawBuffer);
  ostate->PushReadFramebufferBinding();
  ostate->vtkglBindFramebuffer(GL_READ_FRAMEBUFFER, drawBinding);
  this->Depth->CopyFromFrameBuffer(x0, y0, 0, 0, w, h);
  this->Depth->Deactivate();
  ostate->PopReadFramebufferBinding();

  // Levels 1, 2, 4, 6 (2, 4, 16, 64 pixels).
  if (!this->Reduce)
  {
    this->Reduce.reset(new vtkOpenGLQuadHelper(renWin, nullptr, PyramidReduceFS, ""));
  }
  else
  {
    renWin->GetShaderCache()->ReadyShaderProgram(this->Reduce->Program);
  }
  vtkShaderProgram* program = this->Reduce->Program;
  if (!program)
  {
    return;
  }
  vtkOpenGLState::ScopedglViewport savedViewport(ostate);
  vtkOpenGLState::ScopedglScissor savedScissor(ostate);
  vtkOpenGLState::ScopedglDepthMask savedDepthMask(ostate);
  vtkOpenGLState::ScopedglColorMask savedColorMask(ostate);
  vtkOpenGLState::ScopedglEnableDisable savedDepthTest(ostate, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglEnableDisable savedBlend(ostate, GL_BLEND);
  ostate->vtkglDisable(GL_DEPTH_TEST);
  ostate->vtkglDisable(GL_BLEND);
  ostate->vtkglDepthMask(GL_FALSE);
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  ostate->PushFramebufferBindings();
  this->LevelFBO->SetContext(renWin);
  vtkTextureObject* source = this->Depth;
  int sw = w, sh = h;
  const int factors[4] = { 2, 2, 4, 4 };
  for (int l = 0; l < 4; ++l)
  {
    vtkTextureObject* level = this->Level[l];
    const int factor = factors[l];
    const int dw = (sw + factor - 1) / factor, dh = (sh + factor - 1) / factor;
    level->SetContext(renWin);
    if (!level->GetHandle() || static_cast<int>(level->GetWidth()) != dw ||
      static_cast<int>(level->GetHeight()) != dh)
    {
      level->Allocate2D(dw, dh, 1, VTK_FLOAT);
    }
    this->LevelFBO->Bind();
    this->LevelFBO->AddColorAttachment(0, level);
    this->LevelFBO->ActivateDrawBuffer(0);
    ostate->vtkglViewport(0, 0, dw, dh);
    ostate->vtkglScissor(0, 0, dw, dh);
    source->Activate();
    program->SetUniformi("source", source->GetTextureUnit());
    const int size[2] = { sw, sh };
    program->SetUniform2i("sourceSize", size);
    program->SetUniformi("factor", factor);
    this->Reduce->Render();
    source->Deactivate();
    source = level;
    sw = dw;
    sh = dh;
  }
  this->LevelFBO->RemoveColorAttachment(0);
  ostate->PopFramebufferBindings();
  ++this->Pyramids;
}

namespace
{
// Re-emits the preparer's (and its executive's) errors and warnings from the
// mapper: to the mapper's observers if it has any, else to the output window.
void ForwardEvent(vtkObject*, unsigned long event, void* clientData, void* callData)
{
  auto* mapper = static_cast<vtkSuperquadricGlyphMapper*>(clientData);
  if (mapper->HasObserver(event))
  {
    mapper->InvokeEvent(event, callData);
  }
  else if (event == vtkCommand::ErrorEvent)
  {
    vtkOutputWindowDisplayErrorText(static_cast<const char*>(callData));
  }
  else
  {
    vtkOutputWindowDisplayWarningText(static_cast<const char*>(callData));
  }
}
}

//------------------------------------------------------------------------------
vtkSuperquadricGlyphMapper::vtkSuperquadricGlyphMapper()
  : Internal(new Internals)
{
  // colors are per glyph, never interpolated through a texture
  this->InterpolateScalarsBeforeMapping = 0;
  this->Internal->Forwarder->SetClientData(this);
  this->Internal->Forwarder->SetCallback(ForwardEvent);
  this->Internal->Preparer->AddObserver(vtkCommand::ErrorEvent, this->Internal->Forwarder);
  this->Internal->Preparer->AddObserver(vtkCommand::WarningEvent, this->Internal->Forwarder);
  this->Internal->Preparer->GetExecutive()->AddObserver(
    vtkCommand::ErrorEvent, this->Internal->Forwarder);
}

//------------------------------------------------------------------------------
vtkSuperquadricGlyphMapper::~vtkSuperquadricGlyphMapper()
{
  this->SetTensorArray(nullptr);
  this->SetMaskArray(nullptr);
}

//------------------------------------------------------------------------------
void vtkSuperquadricGlyphMapper::ReportReferences(vtkGarbageCollector* collector)
{
  this->Superclass::ReportReferences(collector);
  vtkGarbageCollectorReport(collector, this->Internal->Preparer, "Preparer");
}

//------------------------------------------------------------------------------
void vtkSuperquadricGlyphMapper::SetInputData(vtkDataObject* input)
{
  this->SetInputDataObject(0, input);
}

//------------------------------------------------------------------------------
void vtkSuperquadricGlyphMapper::SetInputConnection(int port, vtkAlgorithmOutput* input)
{
  vtkSuperquadricGlyphPreparer* prep = this->Internal->Preparer;
  if (input && input->GetProducer() == prep)
  {
    this->Superclass::SetInputConnection(port, input);
    return;
  }
  prep->SetInputConnection(0, input);
  this->Superclass::SetInputConnection(port, input ? prep->GetOutputPort() : nullptr);
}

//------------------------------------------------------------------------------
void vtkSuperquadricGlyphMapper::SetInputDataObject(int port, vtkDataObject* input)
{
  vtkSuperquadricGlyphPreparer* prep = this->Internal->Preparer;
  prep->SetInputDataObject(0, input);
  this->Superclass::SetInputConnection(port, input ? prep->GetOutputPort() : nullptr);
}

//------------------------------------------------------------------------------
void vtkSuperquadricGlyphMapper::UpdatePreparer()
{
  vtkSuperquadricGlyphPreparer* prep = this->Internal->Preparer;
  prep->SetTensorArray(this->TensorArray);
  prep->SetTensorLayout(this->TensorLayout);
  prep->SetMaskArray(this->MaskArray);
  prep->SetColorArraySelection(this->ScalarVisibility != 0, this->ScalarMode, this->ArrayAccessMode,
    this->ArrayId, this->ArrayName);
}

//------------------------------------------------------------------------------
double* vtkSuperquadricGlyphMapper::GetBounds()
{
  this->UpdatePreparer();
  return this->Superclass::GetBounds();
}

//------------------------------------------------------------------------------
void vtkSuperquadricGlyphMapper::ComputeBounds()
{
  vtkMath::UninitializeBounds(this->Bounds);
  vtkPolyData* glyphs = this->GetInput();
  if (!glyphs || glyphs->GetNumberOfPoints() == 0)
  {
    return;
  }
  glyphs->GetBounds(this->Bounds);
  vtkDataArray* stats = glyphs->GetFieldData()->GetArray("sqStatistics");
  const double pad = this->GetGlyphPadding(stats ? stats->GetTuple1(0) : 0.0);
  for (int c = 0; c < 3; ++c)
  {
    this->Bounds[2 * c] -= pad;
    this->Bounds[2 * c + 1] += pad;
  }
}

//------------------------------------------------------------------------------
double vtkSuperquadricGlyphMapper::GetGlyphPadding(double maxTensorNorm)
{
  // Half extent of a glyph's box along any axis a: sum_i s_i |e_i . a| <=
  // |s| (Cauchy-Schwarz, the e_i . a are a unit vector's coordinates), with
  // |s| <= scale |T|_F (|l| <= Frobenius norm), at most sqrt(3) times the
  // largest semi-axis, and the thickness floor adding at most a factor
  // sqrt(1 + 3 m^2).
  const double floorFactor = std::sqrt(1.0 + 3.0 * this->MinimumThickness * this->MinimumThickness);
  double pad = this->ScaleFactor * maxTensorNorm;
  if (this->ScaleMode == SCALE_NORMALIZED)
  {
    pad = std::sqrt(3.0) * this->ScaleFactor;
  }
  else if (this->ScaleMode == SCALE_CLAMPED)
  {
    pad = std::min(pad, std::sqrt(3.0) * this->MaximumScale);
  }
  return pad * floorFactor;
}

//------------------------------------------------------------------------------
bool vtkSuperquadricGlyphMapper::ComputeGlyphBounds(vtkDataObject* data, double bounds[6])
{
  vtkMath::UninitializeBounds(bounds);
  const std::vector<vtkDataSet*> leaves = vtkCompositeDataSet::GetDataSets(data);
  double maxNorm = 0.0;
  bool any = false;
  for (vtkDataSet* leaf : leaves)
  {
    vtkPointData* pd = leaf->GetPointData();
    vtkDataArray* tensors = this->TensorArray ? pd->GetArray(this->TensorArray) : pd->GetTensors();
    const int layout =
      tensors ? TM::ResolveLayout(this->TensorLayout, tensors->GetNumberOfComponents()) : -1;
    if (layout < 0 || leaf->GetNumberOfPoints() == 0)
    {
      continue;
    }
    vtkSMPThreadLocal<double> localMax;
    vtkSMPTools::For(0, tensors->GetNumberOfTuples(),
      [&](vtkIdType begin, vtkIdType end)
      {
        double& m = localMax.Local();
        for (vtkIdType i = begin; i < end; ++i)
        {
          double t[6];
          if (TM::ReadSymmetric(tensors, i, layout, t))
          {
            m = std::max(m,
              std::sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2] +
                2.0 * (t[3] * t[3] + t[4] * t[4] + t[5] * t[5])));
          }
        }
      });
    for (double m : localMax)
    {
      maxNorm = std::max(maxNorm, m);
    }
    double b[6];
    leaf->GetBounds(b);
    for (int c = 0; c < 3; ++c)
    {
      bounds[2 * c] = any ? std::min(bounds[2 * c], b[2 * c]) : b[2 * c];
      bounds[2 * c + 1] = any ? std::max(bounds[2 * c + 1], b[2 * c + 1]) : b[2 * c + 1];
    }
    any = true;
  }
  if (!any)
  {
    return false;
  }
  const double pad = this->GetGlyphPadding(maxNorm);
  for (int c = 0; c < 3; ++c)
  {
    bounds[2 * c] -= pad;
    bounds[2 * c + 1] += pad;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkSuperquadricGlyphMapper::RenderPiece(vtkRenderer* ren, vtkActor* actor)
{
  this->UpdatePreparer();
  this->Superclass::RenderPiece(ren, actor);
  vtkPolyData* glyphs = this->GetInput();
  vtkDataArray* stats = glyphs ? glyphs->GetFieldData()->GetArray("sqStatistics") : nullptr;
  this->NumberOfGlyphs = glyphs ? glyphs->GetNumberOfPoints() : 0;
  this->NumberOfInvalidTensors = stats ? static_cast<vtkIdType>(stats->GetTuple1(1)) : 0;
  this->NumberOfZeroTensors = stats ? static_cast<vtkIdType>(stats->GetTuple1(2)) : 0;
  this->NumberOfMaskedPoints = stats ? static_cast<vtkIdType>(stats->GetTuple1(3)) : 0;
}

//------------------------------------------------------------------------------
void vtkSuperquadricGlyphMapper::RenderPieceDraw(vtkRenderer* ren, vtkActor* actor)
{
  const int numVerts = this->VBOs->GetNumberOfTuples("vertexMC");
  if (numVerts > 0 && !this->Internal->TooLarge)
  {
    this->UpdateShaders(this->Primitives[PrimitiveTris], ren, actor);
    GLuint query = 0;
    if (this->CountSprites)
    {
      glGenQueries(1, &query);
      glBeginQuery(GL_PRIMITIVES_GENERATED, query);
    }
    this->DrawGlyphs(ren, actor, numVerts);
    if (this->CountSprites)
    {
      glEndQuery(GL_PRIMITIVES_GENERATED);
      GLuint primitives = 0;
      glGetQueryObjectuiv(query, GL_QUERY_RESULT, &primitives);
      glDeleteQueries(1, &query);
      this->LastSpriteTriangles = static_cast<vtkIdType>(primitives);
    }
  }
}

//------------------------------------------------------------------------------
bool vtkSuperquadricGlyphMapper::UseCulling(vtkRenderer*, vtkActor* actor)
{
  if (!this->Culling || actor->IsRenderingTranslucentPolygonalGeometry() ||
    actor->GetProperty()->GetOpacity() < 1.0)
  {
    return false;
  }
  GLint sampleBuffers = 0;
  glGetIntegerv(GL_SAMPLE_BUFFERS, &sampleBuffers);
  return sampleBuffers == 0; // a multisampled depth buffer cannot be copied
}

//------------------------------------------------------------------------------
void vtkSuperquadricGlyphMapper::DrawGlyphs(vtkRenderer* ren, vtkActor* actor, int numVerts)
{
  Internals& in = *this->Internal;
  vtkOpenGLHelper& cellBO = this->Primitives[PrimitiveTris];
  vtkShaderProgram* program = cellBO.Program;
  in.Pyramids = 0;
  for (vtkIdType& n : in.GroupGlyphs)
  {
    n = 0;
  }
  in.GroupGlyphs[0] = numVerts;

  // The camera in model coordinates.
  vtkCamera* camera = ren->GetActiveCamera();
  const bool parallel = camera->GetParallelProjection() != 0;
  double eye[4] = { 0, 0, 0, 1 };
  if (parallel)
  {
    camera->GetDirectionOfProjection(eye);
    eye[0] = -eye[0];
    eye[1] = -eye[1];
    eye[2] = -eye[2];
    eye[3] = 0.0;
  }
  else
  {
    camera->GetPosition(eye);
  }
  if (!actor->GetIsIdentity())
  {
    vtkNew<vtkMatrix4x4> inverse;
    vtkMatrix4x4::Invert(actor->GetMatrix(), inverse);
    inverse->MultiplyPoint(eye, eye);
    if (!parallel && eye[3] != 0.0)
    {
      eye[0] /= eye[3];
      eye[1] /= eye[3];
      eye[2] /= eye[3];
    }
  }
  if (!this->UseCulling(ren, actor) ||
    !in.ComputeGroups(this->CurrentInput, eye, parallel, this->NumberOfCullingGroups))
  {
    program->SetUniformi("sqCulling", 0);
    glDrawArrays(GL_POINTS, 0, static_cast<GLsizei>(numVerts));
    return;
  }

  vtkOpenGLRenderWindow* renWin = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  int w = 0, h = 0, x0 = 0, y0 = 0;
  ren->GetTiledSizeAndOrigin(&w, &h, &x0, &y0);
  bool culling = false;
  for (int g = 0; g < Internals::MaxGroups; ++g)
  {
    if (in.First[g].empty())
    {
      continue;
    }
    if (culling)
    {
      // everything drawn so far, as a depth pyramid
      in.BuildPyramid(renWin, x0, y0, w, h);
      renWin->GetShaderCache()->ReadyShaderProgram(program);
      cellBO.VAO->Bind();
      in.Depth->Activate();
      for (auto& level : in.Level)
      {
        level->Activate();
      }
      program->SetUniformi("sqCulling", 1);
      program->SetUniformi("sqPyramid0", in.Depth->GetTextureUnit());
      program->SetUniformi("sqPyramid1", in.Level[0]->GetTextureUnit());
      program->SetUniformi("sqPyramid2", in.Level[1]->GetTextureUnit());
      program->SetUniformi("sqPyramid4", in.Level[2]->GetTextureUnit());
      program->SetUniformi("sqPyramid6", in.Level[3]->GetTextureUnit());
      const int origin[2] = { x0, y0 };
      const int size[2] = { w, h };
      program->SetUniform2i("sqViewportOrigin", origin);
      program->SetUniform2i("sqViewportSize", size);
    }
    else
    {
      program->SetUniformi("sqCulling", 0);
    }
    glMultiDrawArrays(
      GL_POINTS, in.First[g].data(), in.Count[g].data(), static_cast<GLsizei>(in.First[g].size()));
    if (culling)
    {
      in.Depth->Deactivate();
      for (auto& level : in.Level)
      {
        level->Deactivate();
      }
    }
    culling = true;
  }
}

//------------------------------------------------------------------------------
vtkIdType vtkSuperquadricGlyphMapper::GetLastCullingGroupSize(int group)
{
  return group >= 0 && group < Internals::MaxGroups ? this->Internal->GroupGlyphs[group] : 0;
}

//------------------------------------------------------------------------------
int vtkSuperquadricGlyphMapper::GetLastNumberOfDepthPyramids()
{
  return this->Internal->Pyramids;
}

//------------------------------------------------------------------------------
std::string vtkSuperquadricGlyphMapper::GetColorKey()
{
  // What the per-glyph colors depend on (not every change of the mapper,
  // e.g. of Gamma, must recolor).
  vtkPolyData* glyphs = this->CurrentInput;
  vtkDataArray* scalars = glyphs ? glyphs->GetPointData()->GetScalars() : nullptr;
  std::ostringstream key;
  key << this->ScalarVisibility << "|" << this->ColorMode << "|" << this->ArrayComponent << "|"
      << this->UseLookupTableScalarRange << "|" << this->ScalarRange[0] << "|"
      << this->ScalarRange[1] << "|" << static_cast<void*>(this->LookupTable) << "|"
      << (this->LookupTable ? this->LookupTable->GetMTime() : 0) << "|"
      << static_cast<void*>(scalars) << "|" << (scalars ? scalars->GetMTime() : 0) << "|"
      << static_cast<void*>(this->Internal->BlockAttributes.Get()) << "|"
      << (this->Internal->BlockAttributes ? this->Internal->BlockAttributes->GetMTime() : 0);
  return key.str();
}

//------------------------------------------------------------------------------
bool vtkSuperquadricGlyphMapper::GetNeedToRebuildBufferObjects(vtkRenderer*, vtkActor*)
{
  vtkPolyData* glyphs = this->CurrentInput;
  if (!glyphs)
  {
    return false;
  }
  vtkDataArray* diag = glyphs->GetPointData()->GetArray("sqTensorDiag");
  const Internals& in = *this->Internal;
  return in.UploadedTensors != diag || (diag && in.UploadedTensorsTime < diag->GetMTime()) ||
    in.ColorKey != this->GetColorKey();
}

//------------------------------------------------------------------------------
void vtkSuperquadricGlyphMapper::BuildBufferObjects(vtkRenderer* ren, vtkActor*)
{
  Internals& in = *this->Internal;
  vtkPolyData* poly = this->CurrentInput;
  vtkPointData* pd = poly->GetPointData();
  vtkDataArray* diag = pd->GetArray("sqTensorDiag");
  vtkDataArray* off = pd->GetArray("sqTensorOff");
  if (!diag || !off || !poly->GetPoints())
  {
    return;
  }

  // Per-glyph colors through the lookup table (point scalars only).
  in.HaveColors = false;
  if (pd->GetScalars() && this->ScalarVisibility)
  {
    // one color per glyph: never through a texture (ParaView turns
    // InterpolateScalarsBeforeMapping on)
    const int savedMode = this->ScalarMode;
    const vtkTypeBool savedInterpolate = this->InterpolateScalarsBeforeMapping;
    this->ScalarMode = VTK_SCALAR_MODE_USE_POINT_DATA;
    this->InterpolateScalarsBeforeMapping = 0;
    this->MapScalars(poly, 1.0);
    this->ScalarMode = savedMode;
    this->InterpolateScalarsBeforeMapping = savedInterpolate;
    in.HaveColors = this->Colors != nullptr &&
      this->Colors->GetNumberOfTuples() == poly->GetNumberOfPoints() &&
      this->Colors->GetNumberOfComponents() == 4;
  }

  // Hostile sizes: one draw call of GLsizei points, and the limit of
  // SPLINEVIZ_GPU_BUFFER_LIMIT (elements per GPU buffer, to test this path);
  // a buffer the driver cannot allocate (GL_OUT_OF_MEMORY) is caught below.
  // Either way nothing is drawn and the data is not retried until it changes.
  const vtkIdType numGlyphs = poly->GetNumberOfPoints();
  const vtkIdType limit =
    static_cast<vtkIdType>(vtkSplineVizGPUBuffer::ApplyTestLimit(VTK_INT_MAX));
  in.TooLarge = numGlyphs > limit;
  in.HaveBlockColors = false;
  if (in.TooLarge)
  {
    vtkErrorMacro(<< numGlyphs << " glyphs are more than one GPU draw can hold (at most " << limit
                  << vtkSplineVizGPUBuffer::TestLimitNote() << "): nothing is drawn");
  }
  else
  {
    // Per-block attributes: (r, g, b or -1 for no color, opacity; 0 hidden).
    std::vector<vtkIdType> firstId;
    std::vector<std::array<float, 4>> leafColor;
    vtkIdTypeArray* pointIds = vtkArrayDownCast<vtkIdTypeArray>(pd->GetArray("sqPointIds"));
    if (in.BlockColorsOfLeaves(firstId, leafColor) && pointIds)
    {
      const vtkIdType n = poly->GetNumberOfPoints();
      in.BlockColors->SetNumberOfComponents(4);
      in.BlockColors->SetNumberOfTuples(n);
      float* out = in.BlockColors->GetPointer(0);
      const vtkIdType* ids = pointIds->GetPointer(0);
      vtkSMPTools::For(0, n,
        [&](vtkIdType begin, vtkIdType end)
        {
          for (vtkIdType i = begin; i < end; ++i)
          {
            const size_t b = static_cast<size_t>(
              std::upper_bound(firstId.begin(), firstId.end(), ids[i]) - firstId.begin() - 1);
            std::copy(leafColor[b].begin(), leafColor[b].end(), out + 4 * i);
          }
        });
      in.BlockColors->Modified();
      in.HaveBlockColors = true;
    }

    for (int i = 0; i < 64 && glGetError() != GL_NO_ERROR; ++i)
    {
      // errors of earlier calls are not this upload's
    }
    this->VBOs->CacheDataArray("vertexMC", poly->GetPoints()->GetData(), ren, VTK_FLOAT);
    this->VBOs->CacheDataArray(
      "glyphBlockColor", in.HaveBlockColors ? in.BlockColors.Get() : nullptr, ren, VTK_FLOAT);
    this->VBOs->CacheDataArray("tensorDiagMC", diag, ren, VTK_FLOAT);
    this->VBOs->CacheDataArray("tensorOffMC", off, ren, VTK_FLOAT);
    this->VBOs->CacheDataArray(
      "glyphScalarColor", in.HaveColors ? this->Colors : nullptr, ren, VTK_UNSIGNED_CHAR);
    this->VBOs->BuildAllVBOs(ren);
    if (glGetError() == GL_OUT_OF_MEMORY)
    {
      in.TooLarge = true;
      vtkErrorMacro(<< "the GPU could not allocate the buffers of " << numGlyphs
                    << " glyphs (GL_OUT_OF_MEMORY): nothing is drawn");
    }
  }
  if (in.UploadedTensors != diag || in.UploadedTensorsTime < diag->GetMTime())
  {
    ++this->UploadCount;
    in.UploadedTensors = diag;
    in.UploadedTensorsTime = diag->GetMTime();
  }
  in.BytesPerGlyph = 0;
  for (const char* name :
    { "vertexMC", "tensorDiagMC", "tensorOffMC", "glyphScalarColor", "glyphBlockColor" })
  {
    vtkOpenGLVertexBufferObject* vbo = this->VBOs->GetVBO(name);
    if (vbo && vbo->GetNumberOfTuples() > 0)
    {
      in.BytesPerGlyph += static_cast<int>(vbo->GetStride());
    }
  }

  for (int i = PrimitiveStart; i < PrimitiveEnd; ++i)
  {
    this->Primitives[i].IBO->IndexCount = 0;
  }
  // Not drawn with it, but makes the superclass bind the attributes.
  this->Primitives[PrimitiveTris].IBO->IndexCount = static_cast<size_t>(poly->GetNumberOfPoints());
  in.ColorKey = this->GetColorKey();
  this->VBOBuildTime.Modified();
}

//------------------------------------------------------------------------------
void vtkSuperquadricGlyphMapper::SetCompositeDataDisplayAttributes(
  vtkCompositeDataDisplayAttributes* attributes)
{
  if (this->Internal->BlockAttributes != attributes)
  {
    this->Internal->BlockAttributes = attributes;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkCompositeDataDisplayAttributes* vtkSuperquadricGlyphMapper::GetCompositeDataDisplayAttributes()
{
  return this->Internal->BlockAttributes;
}

//------------------------------------------------------------------------------
bool vtkSuperquadricGlyphMapper::HasOpaqueGeometry()
{
  // translucent blocks: everything is drawn in the translucent pass
  std::vector<vtkIdType> firstId;
  std::vector<std::array<float, 4>> leafColor;
  this->Internal->BlockColorsOfLeaves(firstId, leafColor);
  return this->Superclass::HasOpaqueGeometry() && !this->Internal->AnyTranslucentBlock;
}

//------------------------------------------------------------------------------
bool vtkSuperquadricGlyphMapper::HasTranslucentPolygonalGeometry()
{
  std::vector<vtkIdType> firstId;
  std::vector<std::array<float, 4>> leafColor;
  this->Internal->BlockColorsOfLeaves(firstId, leafColor);
  return this->Superclass::HasTranslucentPolygonalGeometry() || this->Internal->AnyTranslucentBlock;
}

//------------------------------------------------------------------------------
int vtkSuperquadricGlyphMapper::GetGPUBytesPerGlyph()
{
  return this->Internal->BytesPerGlyph;
}

//------------------------------------------------------------------------------
vtkIdType vtkSuperquadricGlyphMapper::GetInputPointId(vtkIdType glyphIndex)
{
  vtkPolyData* glyphs = this->GetInput();
  vtkIdTypeArray* ids = glyphs
    ? vtkArrayDownCast<vtkIdTypeArray>(glyphs->GetPointData()->GetArray("sqPointIds"))
    : nullptr;
  return (ids && glyphIndex >= 0 && glyphIndex < ids->GetNumberOfTuples())
    ? ids->GetValue(glyphIndex)
    : -1;
}

//------------------------------------------------------------------------------
void vtkSuperquadricGlyphMapper::GetShaderTemplate(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer*, vtkActor*)
{
  shaders[vtkShader::Vertex]->SetSource(vtkSuperquadricGlyphVS);
  shaders[vtkShader::Geometry]->SetSource(vtkSuperquadricGlyphGS);
  shaders[vtkShader::Fragment]->SetSource(vtkSuperquadricGlyphFS);
}

//------------------------------------------------------------------------------
bool vtkSuperquadricGlyphMapper::GetNeedToRebuildShaders(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* actor)
{
  const bool colorsChanged = this->Internal->ShaderHaveColors != this->Internal->HaveColors;
  const bool shapesChanged =
    this->Internal->ShaderGeneralShapes != (this->NegativeEigenvaluePolicy == SCHULTZ_KINDLMANN);
  const bool clipChanged = this->Internal->ShaderClip != (this->GetNumberOfClippingPlanes() > 0);
  const bool blocksChanged =
    this->Internal->ShaderHaveBlockColors != this->Internal->HaveBlockColors;
  return this->Superclass::GetNeedToRebuildShaders(cellBO, ren, actor) || colorsChanged ||
    shapesChanged || clipChanged || blocksChanged;
}

//------------------------------------------------------------------------------
void vtkSuperquadricGlyphMapper::ReplaceShaderValues(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* actor)
{
  std::string VSSource = shaders[vtkShader::Vertex]->GetSource();
  std::string GSSource = shaders[vtkShader::Geometry]->GetSource();
  std::string FSSource = shaders[vtkShader::Fragment]->GetSource();

  // The math shared with the CPU code, after the prelude of the shared subset.
  vtkShaderProgram::Substitute(VSSource, "//SV::Prelude::Dec", vtkSplineVizShaderPrelude::Get());
  vtkShaderProgram::Substitute(FSSource, "//SV::Prelude::Dec", vtkSplineVizShaderPrelude::Get());
  vtkShaderProgram::Substitute(VSSource, "//SV::TensorMath::Dec", vtkTensorMathShared);
  vtkShaderProgram::Substitute(VSSource, "//SV::GlyphMath::Dec", vtkSuperquadricGlyphShared);
  vtkShaderProgram::Substitute(FSSource, "//SV::GlyphMath::Dec", vtkSuperquadricGlyphShared);

  // The general ray caster, for the Schultz-Kindlmann shapes only.
  this->Internal->ShaderGeneralShapes = this->NegativeEigenvaluePolicy == SCHULTZ_KINDLMANN;
  for (std::string* source : { &VSSource, &GSSource, &FSSource })
  {
    vtkShaderProgram::Substitute(*source, "//SV::GeneralShapes::Dec",
      this->Internal->ShaderGeneralShapes ? "#define SQ_GENERAL_SHAPES" : "");
  }
  // Clipping planes: in the fragment stage, on the ray (not VTK's per-vertex
  // clip distances, which would cut the sprites); whole glyphs beyond a plane
  // in the geometry stage.
  this->Internal->ShaderClip = this->GetNumberOfClippingPlanes() > 0;
  for (std::string* source : { &GSSource, &FSSource })
  {
    vtkShaderProgram::Substitute(
      *source, "//SV::Clip::Dec", this->Internal->ShaderClip ? "#define SQ_CLIP" : "");
  }

  // Per-block colors, opacities, visibilities.
  this->Internal->ShaderHaveBlockColors = this->Internal->HaveBlockColors;
  if (this->Internal->HaveBlockColors)
  {
    vtkShaderProgram::Substitute(VSSource, "//SV::BlockColor::Dec", "in vec4 glyphBlockColor;");
    vtkShaderProgram::Substitute(VSSource, "//SV::BlockColor::Impl",
      "  if (glyphBlockColor.w <= 0.0)\n"
      "  {\n"
      "    glyphValidVSOut = 0; // a hidden block\n"
      "    return;\n"
      "  }\n"
      "  if (glyphColorVSOut.a < 0.0 && glyphBlockColor.x >= 0.0)\n"
      "  {\n"
      "    glyphColorVSOut = vec4(glyphBlockColor.rgb, 1.0); // instead of the actor's\n"
      "  }\n"
      "  glyphColorVSOut.a *= glyphBlockColor.w;\n");
  }

  // Scalar colors.
  this->Internal->ShaderHaveColors = this->Internal->HaveColors;
  if (this->Internal->HaveColors)
  {
    vtkShaderProgram::Substitute(VSSource, "//SV::ScalarColor::Dec", "in vec4 glyphScalarColor;");
    vtkShaderProgram::Substitute(VSSource, "//SV::ScalarColor::Impl",
      "  if (sqColorMode == 1)\n"
      "  {\n"
      "    glyphColorVSOut = glyphScalarColor;\n"
      "  }\n");
  }

  // Colors and material: as vtkOpenGLPolyDataMapper's, with the per-glyph
  // color (alpha >= 0) replacing the actor's color.
  std::string colorDec = "uniform float ambientIntensity;\n"
                         "uniform float diffuseIntensity;\n"
                         "uniform float opacityUniform;\n"
                         "uniform vec3 ambientColorUniform;\n"
                         "uniform vec3 diffuseColorUniform;\n";
  std::string colorImpl = "  vec3 ambientColor = ambientIntensity * ambientColorUniform;\n"
                          "  vec3 diffuseColor = diffuseIntensity * diffuseColorUniform;\n"
                          "  float opacity = opacityUniform;\n"
                          "  if (glyphColorFS.a >= 0.0)\n"
                          "  {\n"
                          "    ambientColor = ambientIntensity * glyphColorFS.rgb;\n"
                          "    diffuseColor = diffuseIntensity * glyphColorFS.rgb;\n"
                          "    opacity = opacityUniform * glyphColorFS.a;\n"
                          "  }\n"
                          "  else\n"
                          "  {\n"
                          "    opacity = opacityUniform * -glyphColorFS.a;\n"
                          "  }\n";
  if (this->PrimitiveInfo[this->LastBoundBO].LastLightComplexity)
  {
    colorDec += "uniform float specularIntensity;\n"
                "uniform vec3 specularColorUniform;\n"
                "uniform float specularPowerUniform;\n";
    colorImpl += "  vec3 specularColor = specularIntensity * specularColorUniform;\n"
                 "  float specularPower = specularPowerUniform;\n";
  }
  vtkShaderProgram::Substitute(FSSource, "//VTK::Color::Dec", colorDec);
  vtkShaderProgram::Substitute(FSSource, "//VTK::Color::Impl", colorImpl);

  // Picking: point ids are glyph indices (mapped to input ids in
  // ProcessSelectorPixelBuffers); other passes write the mapper index.
  const int pass = this->LastSelectionState;
  if (pass >= vtkHardwareSelector::MIN_KNOWN_PASS)
  {
    if (pass == vtkHardwareSelector::POINT_ID_LOW24 ||
      pass == vtkHardwareSelector::POINT_ID_HIGH24 || pass == vtkHardwareSelector::CELL_ID_LOW24 ||
      pass == vtkHardwareSelector::CELL_ID_HIGH24)
    {
      const bool high =
        pass == vtkHardwareSelector::POINT_ID_HIGH24 || pass == vtkHardwareSelector::CELL_ID_HIGH24;
      vtkShaderProgram::Substitute(VSSource, "//VTK::Picking::Dec", "out int glyphIdVSOut;");
      vtkShaderProgram::Substitute(
        VSSource, "//VTK::Picking::Impl", "  glyphIdVSOut = gl_VertexID;");
      vtkShaderProgram::Substitute(
        GSSource, "//VTK::Picking::Dec", "in int glyphIdVSOut[];\nflat out int glyphIdGSOutput;");
      vtkShaderProgram::Substitute(
        GSSource, "//VTK::Picking::Impl", "  glyphIdGSOutput = glyphIdVSOut[0];");
      vtkShaderProgram::Substitute(FSSource, "//VTK::Picking::Dec", "flat in int glyphIdGSOutput;");
      vtkShaderProgram::Substitute(FSSource, "//VTK::Picking::Impl",
        high ? "  int idx = (glyphIdGSOutput >> 24) & 0xff;\n"
               "  gl_FragData[0] = vec4(float(idx) / 255.0, 0.0, 0.0, 1.0);\n"
             : "  int idx = glyphIdGSOutput;\n"
               "  gl_FragData[0] = vec4(float(idx % 256) / 255.0, float((idx / 256) % 256) / "
               "255.0, float((idx / 65536) % 256) / 255.0, 1.0);\n");
    }
    else
    {
      vtkShaderProgram::Substitute(FSSource, "//VTK::Picking::Dec", "uniform vec3 mapperIndex;");
      vtkShaderProgram::Substitute(
        FSSource, "//VTK::Picking::Impl", "  gl_FragData[0] = vec4(mapperIndex, 1.0);\n");
    }
  }
  // leave no VTK picking tags for the superclass
  vtkShaderProgram::Substitute(VSSource, "//VTK::Picking::Dec", "");
  vtkShaderProgram::Substitute(VSSource, "//VTK::Picking::Impl", "");
  vtkShaderProgram::Substitute(GSSource, "//VTK::Picking::Dec", "");
  vtkShaderProgram::Substitute(GSSource, "//VTK::Picking::Impl", "");
  vtkShaderProgram::Substitute(FSSource, "//VTK::Picking::Dec", "");
  vtkShaderProgram::Substitute(FSSource, "//VTK::Picking::Impl", "");

  shaders[vtkShader::Vertex]->SetSource(VSSource);
  shaders[vtkShader::Geometry]->SetSource(GSSource);
  shaders[vtkShader::Fragment]->SetSource(FSSource);

  // Lights, render passes (e.g. depth peeling), custom uniforms.
  this->Superclass::ReplaceShaderValues(shaders, ren, actor);
}

//------------------------------------------------------------------------------
void vtkSuperquadricGlyphMapper::SetMapperShaderParameters(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* actor)
{
  this->Superclass::SetMapperShaderParameters(cellBO, ren, actor);
  vtkShaderProgram* p = cellBO.Program;
  p->SetUniformf("sqGamma", static_cast<float>(this->Gamma));
  p->SetUniformf("sqScaleFactor", static_cast<float>(this->ScaleFactor));
  p->SetUniformf("sqMaximumScale", static_cast<float>(this->MaximumScale));
  p->SetUniformf("sqMinimumThickness", static_cast<float>(this->MinimumThickness));
  p->SetUniformf("sqMinimumRoundness", static_cast<float>(this->MinimumRoundness));
  if (this->Internal->ShaderGeneralShapes)
  {
    p->SetUniformf("sqZeroEigenvalueBand", static_cast<float>(this->ZeroEigenvalueBand));
  }
  p->SetUniformf("sqAnisotropyThreshold", static_cast<float>(this->AnisotropyThreshold));
  p->SetUniformf("sqMinimumEigenvalue",
    static_cast<float>(std::max(this->MinimumEigenvalue, -static_cast<double>(VTK_FLOAT_MAX))));
  p->SetUniformi("sqScaleMode", this->ScaleMode);
  p->SetUniformi("sqSignPolicy", this->NegativeEigenvaluePolicy);
  p->SetUniformi("sqColorMode", this->GlyphColorMode);
  float positive[3], negative[3];
  for (int c = 0; c < 3; ++c)
  {
    positive[c] = static_cast<float>(this->PositiveFormColor[c]);
    negative[c] = static_cast<float>(this->NegativeFormColor[c]);
  }
  p->SetUniform3f("sqPositiveFormColor", positive);
  p->SetUniform3f("sqNegativeFormColor", negative);
  p->SetUniformi("sqMaximumIterations", this->MaximumIterations);
}

//------------------------------------------------------------------------------
void vtkSuperquadricGlyphMapper::SetCameraShaderParameters(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* actor)
{
  vtkShaderProgram* program = cellBO.Program;
  vtkOpenGLCamera* cam = static_cast<vtkOpenGLCamera*>(ren->GetActiveCamera());
  vtkMatrix4x4* wcdc;
  vtkMatrix4x4* wcvc;
  vtkMatrix3x3* norms;
  vtkMatrix4x4* vcdc;
  cam->GetKeyMatrices(ren, wcvc, norms, vcdc, wcdc);
  program->SetUniformMatrix("VCDCMatrix", vcdc);

  // The key matrices are transposed for OpenGL; so is their product.
  vtkMatrix4x4* mcvc = wcvc;
  if (!actor->GetIsIdentity())
  {
    vtkMatrix4x4* mcwc;
    vtkMatrix3x3* anorms;
    static_cast<vtkOpenGLActor*>(actor)->GetKeyMatrices(mcwc, anorms);
    vtkMatrix4x4::Multiply4x4(mcwc, wcvc, this->TempMatrix4);
    mcvc = this->TempMatrix4;
  }
  program->SetUniformMatrix("MCVCMatrix", mcvc);
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      this->TempMatrix3->SetElement(i, j, mcvc->GetElement(i, j));
    }
  }
  program->SetUniformMatrix("glyphMCVC", this->TempMatrix3);
  program->SetUniformi("cameraParallel", cam->GetParallelProjection());
  if (program->IsUniformUsed("glyphVCMC"))
  {
    // the clipping planes are in data coordinates (the transposed key
    // matrix's inverse is the transposed inverse)
    vtkNew<vtkMatrix4x4> vcmc;
    vtkMatrix4x4::Invert(mcvc, vcmc);
    program->SetUniformMatrix("glyphVCMC", vcmc);
  }
  program->SetUniformf("nearPlaneVC", static_cast<float>(-cam->GetClippingRange()[0]));
}

//------------------------------------------------------------------------------
void vtkSuperquadricGlyphMapper::ProcessSelectorPixelBuffers(
  vtkHardwareSelector* sel, std::vector<unsigned int>& pixeloffsets, vtkProp*)
{
  const int pass = sel->GetCurrentPass();
  const bool pointPass =
    pass == vtkHardwareSelector::POINT_ID_LOW24 || pass == vtkHardwareSelector::POINT_ID_HIGH24;
  const bool cellPass =
    pass == vtkHardwareSelector::CELL_ID_LOW24 || pass == vtkHardwareSelector::CELL_ID_HIGH24;
  if (!this->PopulateSelectionSettings || !(pointPass || cellPass))
  {
    return;
  }
  const int lowPass =
    pointPass ? vtkHardwareSelector::POINT_ID_LOW24 : vtkHardwareSelector::CELL_ID_LOW24;
  const int highPass =
    pointPass ? vtkHardwareSelector::POINT_ID_HIGH24 : vtkHardwareSelector::CELL_ID_HIGH24;
  unsigned char* rawLow = sel->GetRawPixelBuffer(lowPass);
  unsigned char* rawHigh = sel->GetRawPixelBuffer(highPass);
  unsigned char* out = sel->GetPixelBuffer(pass);
  if (!rawLow || !out)
  {
    return;
  }
  const bool high = pass == highPass;
  if (high && !rawHigh)
  {
    return;
  }
  for (unsigned int pos : pixeloffsets)
  {
    vtkIdType glyph = 0;
    if (rawHigh)
    {
      glyph = rawHigh[pos];
    }
    glyph = (glyph << 8) | rawLow[pos + 2];
    glyph = (glyph << 8) | rawLow[pos + 1];
    glyph = (glyph << 8) | rawLow[pos];
    const vtkIdType id = std::max<vtkIdType>(this->GetInputPointId(glyph), 0);
    if (high)
    {
      out[pos] = static_cast<unsigned char>((id >> 24) & 0xff);
      out[pos + 1] = static_cast<unsigned char>((id >> 32) & 0xff);
      out[pos + 2] = static_cast<unsigned char>((id >> 40) & 0xff);
    }
    else
    {
      out[pos] = static_cast<unsigned char>(id & 0xff);
      out[pos + 1] = static_cast<unsigned char>((id >> 8) & 0xff);
      out[pos + 2] = static_cast<unsigned char>((id >> 16) & 0xff);
    }
  }
}

//------------------------------------------------------------------------------
void vtkSuperquadricGlyphMapper::ReleaseGraphicsResources(vtkWindow* win)
{
  this->Superclass::ReleaseGraphicsResources(win);
  this->Internal->ReleaseGraphicsResources(win);
  this->Internal->UploadedTensors = nullptr;
  this->Internal->UploadedTensorsTime = 0;
  this->Internal->ColorKey.clear();
}

//------------------------------------------------------------------------------
void vtkSuperquadricGlyphMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "TensorArray: " << (this->TensorArray ? this->TensorArray : "(none)") << "\n";
  os << indent << "TensorLayout: " << this->TensorLayout << " ("
     << TM::GetLayoutName(this->TensorLayout) << ")\n";
  os << indent << "MaskArray: " << (this->MaskArray ? this->MaskArray : "(none)") << "\n";
  os << indent << "Gamma: " << this->Gamma << "\n";
  os << indent << "MinimumRoundness: " << this->MinimumRoundness << "\n";
  os << indent << "ScaleFactor: " << this->ScaleFactor << "\n";
  os << indent << "ScaleMode: " << this->ScaleMode << "\n";
  os << indent << "MaximumScale: " << this->MaximumScale << "\n";
  os << indent << "MinimumThickness: " << this->MinimumThickness << "\n";
  os << indent << "AnisotropyThreshold: " << this->AnisotropyThreshold << "\n";
  os << indent << "MinimumEigenvalue: " << this->MinimumEigenvalue << "\n";
  os << indent << "NegativeEigenvaluePolicy: " << this->NegativeEigenvaluePolicy << "\n";
  os << indent << "ZeroEigenvalueBand: " << this->ZeroEigenvalueBand << "\n";
  os << indent << "GlyphColorMode: " << this->GlyphColorMode << "\n";
  os << indent << "PositiveFormColor: " << this->PositiveFormColor[0] << " "
     << this->PositiveFormColor[1] << " " << this->PositiveFormColor[2] << "\n";
  os << indent << "NegativeFormColor: " << this->NegativeFormColor[0] << " "
     << this->NegativeFormColor[1] << " " << this->NegativeFormColor[2] << "\n";
  os << indent << "MaximumIterations: " << this->MaximumIterations << "\n";
  os << indent << "Culling: " << this->Culling << "\n";
  os << indent << "NumberOfCullingGroups: " << this->NumberOfCullingGroups << "\n";
  os << indent << "CountSprites: " << this->CountSprites << "\n";
  os << indent << "NumberOfGlyphs: " << this->NumberOfGlyphs << "\n";
  os << indent << "NumberOfInvalidTensors: " << this->NumberOfInvalidTensors << "\n";
  os << indent << "NumberOfZeroTensors: " << this->NumberOfZeroTensors << "\n";
  os << indent << "NumberOfMaskedPoints: " << this->NumberOfMaskedPoints << "\n";
  os << indent << "UploadCount: " << this->UploadCount << "\n";
}
