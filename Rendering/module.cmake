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
