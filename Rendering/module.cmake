# Rendering/: mappers, their shared CPU-side preparation and their shaders
# (included from cmake/module/CMakeLists.txt).
list(APPEND splineviz_classes
  "${SPLINEVIZ_FOLDER}/vtkSplineTubeCore")
