# Filters/: VTK filters and sources of the SplineViz module, and the plain C++
# numerical code they share (included from cmake/module/CMakeLists.txt).
list(APPEND splineviz_classes
  "${SPLINEVIZ_FOLDER}/vtkSyntheticFibersSource")
