# SPDX-License-Identifier: BSD-3-Clause
# Rendering/: mappers, their shared CPU-side preparation and their shaders
# (included from cmake/module/CMakeLists.txt).
list(APPEND splineviz_classes
  "${SPLINEVIZ_FOLDER}/vtkSplineTubeCore")
list(APPEND splineviz_classes
  "${SPLINEVIZ_FOLDER}/vtkSplineTubeMapper"
  "${SPLINEVIZ_FOLDER}/vtkRayCastTubeMapper"
  "${SPLINEVIZ_FOLDER}/vtkTessellatedTubeMapper")
# Depth cues for all of them (and any opaque geometry): screen-space ambient
# occlusion and depth-dependent halos from the depth buffer.
list(APPEND splineviz_classes
  "${SPLINEVIZ_FOLDER}/vtkLineAmbientOcclusionPass")
list(APPEND splineviz_shaders
  "${SPLINEVIZ_FOLDER}/glsl/vtkLineAmbientOcclusionCommon.glsl"
  "${SPLINEVIZ_FOLDER}/glsl/vtkLineAmbientOcclusionFS.glsl"
  "${SPLINEVIZ_FOLDER}/glsl/vtkLineAmbientOcclusionTilesVS.glsl")
list(APPEND splineviz_private_classes
  "${SPLINEVIZ_FOLDER}/vtkSplineVizGPUBuffer"
  "${SPLINEVIZ_FOLDER}/vtkSplineTubeVisibility"
  "${SPLINEVIZ_FOLDER}/vtkTessellatedTubeLevels")
# Stylized lines (Stoll et al.): the mapper, its CPU fix-up and the math
# shared by both and the shaders (vtkStylizedLineMath.h compiles
# glsl/vtkStylizedLineMathShared.glsl as C++).
list(APPEND splineviz_classes
  "${SPLINEVIZ_FOLDER}/vtkStylizedLineMapper")
list(APPEND splineviz_private_classes
  "${SPLINEVIZ_FOLDER}/vtkStylizedLineFixUp")
list(APPEND splineviz_private_headers
  "${SPLINEVIZ_FOLDER}/vtkStylizedLineMath.h")
list(APPEND splineviz_shaders
  "${SPLINEVIZ_FOLDER}/glsl/vtkStylizedLineMathShared.glsl"
  "${SPLINEVIZ_FOLDER}/glsl/vtkStylizedLineVS.glsl"
  "${SPLINEVIZ_FOLDER}/glsl/vtkStylizedLineFS.glsl")
list(APPEND splineviz_private_headers
  "${SPLINEVIZ_FOLDER}/vtkSplineTubeMath.h"
  "${SPLINEVIZ_FOLDER}/vtkSplineVizShaderPrelude.h")
list(APPEND splineviz_shaders
  "${SPLINEVIZ_FOLDER}/glsl/vtkSplineTubeMathShared.glsl"
  "${SPLINEVIZ_FOLDER}/glsl/vtkSplineTubeNodes.glsl"
  "${SPLINEVIZ_FOLDER}/glsl/vtkSplineTubeColor.glsl"
  "${SPLINEVIZ_FOLDER}/glsl/vtkRayCastTubeVS.glsl"
  "${SPLINEVIZ_FOLDER}/glsl/vtkRayCastTubeGS.glsl"
  "${SPLINEVIZ_FOLDER}/glsl/vtkRayCastTubeFS.glsl"
  "${SPLINEVIZ_FOLDER}/glsl/vtkTessellatedTubeCommon.glsl"
  "${SPLINEVIZ_FOLDER}/glsl/vtkTessellatedTubeVS.glsl"
  "${SPLINEVIZ_FOLDER}/glsl/vtkTessellatedTubeTCS.glsl"
  "${SPLINEVIZ_FOLDER}/glsl/vtkTessellatedTubeTES.glsl"
  "${SPLINEVIZ_FOLDER}/glsl/vtkTessellatedTubeThinFS.glsl"
  "${SPLINEVIZ_FOLDER}/glsl/vtkTessellatedTubeThinVS.glsl"
  "${SPLINEVIZ_FOLDER}/glsl/vtkTessellatedTubeFS.glsl")

# Superquadric tensor glyphs: the glyph math shared with the shaders
# (vtkSuperquadricGlyphMath.h compiles glsl/vtkSuperquadricGlyphShared.glsl as C++).
list(APPEND splineviz_private_headers
  "${SPLINEVIZ_FOLDER}/vtkSuperquadricGlyphMath.h")
list(APPEND splineviz_shaders
  "${SPLINEVIZ_FOLDER}/glsl/vtkSuperquadricGlyphShared.glsl")
# The superquadric tensor glyph mapper (Hlawitschka et al., Kindlmann 2004)
# and its shaders.
list(APPEND splineviz_classes
  "${SPLINEVIZ_FOLDER}/vtkSuperquadricGlyphMapper")
list(APPEND splineviz_private_classes
  "${SPLINEVIZ_FOLDER}/vtkSuperquadricGlyphPreparer")
list(APPEND splineviz_shaders
  "${SPLINEVIZ_FOLDER}/glsl/vtkSuperquadricGlyphVS.glsl"
  "${SPLINEVIZ_FOLDER}/glsl/vtkSuperquadricGlyphGS.glsl"
  "${SPLINEVIZ_FOLDER}/glsl/vtkSuperquadricGlyphFS.glsl")

# LR-spline direct volume rendering (Fuchs et al. §4): the mapper and its
# shaders; the element search and Bezier evaluation shared by the fragment
# stage and the CPU check (vtkLRSplineVolumeMath.h compiles
# glsl/vtkLRSplineVolumeShared.glsl as C++).
list(APPEND splineviz_classes
  "${SPLINEVIZ_FOLDER}/vtkLRSplineVolumeMapper")
# Its shader sources for a set of options, without OpenGL (as VTK's
# vtkVolumeShaderComposer for the GPU ray caster).
list(APPEND splineviz_private_classes
  "${SPLINEVIZ_FOLDER}/vtkLRSplineVolumeShaderBuilder")
# The spline as the flat arrays the mapper uploads, and the empty-space
# skipping flags, without OpenGL.
list(APPEND splineviz_private_classes
  "${SPLINEVIZ_FOLDER}/vtkLRSplineVolumePreparer")
list(APPEND splineviz_private_headers
  "${SPLINEVIZ_FOLDER}/vtkLRSplineVolumeMath.h")
list(APPEND splineviz_shaders
  "${SPLINEVIZ_FOLDER}/glsl/vtkLRSplineVolumeShared.glsl"
  "${SPLINEVIZ_FOLDER}/glsl/vtkLRSplineVolumeVS.glsl"
  "${SPLINEVIZ_FOLDER}/glsl/vtkLRSplineVolumeFS.glsl"
  "${SPLINEVIZ_FOLDER}/glsl/vtkLRSplineVolumeTrimFS.glsl"
  "${SPLINEVIZ_FOLDER}/glsl/vtkLRSplineVolumeCompositeFS.glsl")
