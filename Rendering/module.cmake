# Rendering/: mappers, their shared CPU-side preparation and their shaders
# (included from cmake/module/CMakeLists.txt).
list(APPEND splineviz_classes
  "${SPLINEVIZ_FOLDER}/vtkSplineTubeCore")
list(APPEND splineviz_classes
  "${SPLINEVIZ_FOLDER}/vtkSplineTubeMapper"
  "${SPLINEVIZ_FOLDER}/vtkRayCastTubeMapper"
  "${SPLINEVIZ_FOLDER}/vtkTessellatedTubeMapper")
list(APPEND splineviz_private_classes
  "${SPLINEVIZ_FOLDER}/vtkSplineVizGPUBuffer")
list(APPEND splineviz_private_headers
  "${SPLINEVIZ_FOLDER}/vtkSplineTubeMath.h")
list(APPEND splineviz_shaders
  "${SPLINEVIZ_FOLDER}/glsl/vtkSplineTubeMathPrelude.glsl"
  "${SPLINEVIZ_FOLDER}/glsl/vtkSplineTubeMathShared.glsl"
  "${SPLINEVIZ_FOLDER}/glsl/vtkRayCastTubeVS.glsl"
  "${SPLINEVIZ_FOLDER}/glsl/vtkRayCastTubeFS.glsl"
  "${SPLINEVIZ_FOLDER}/glsl/vtkTessellatedTubeCommon.glsl"
  "${SPLINEVIZ_FOLDER}/glsl/vtkTessellatedTubeVS.glsl"
  "${SPLINEVIZ_FOLDER}/glsl/vtkTessellatedTubeTCS.glsl"
  "${SPLINEVIZ_FOLDER}/glsl/vtkTessellatedTubeTES.glsl"
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
