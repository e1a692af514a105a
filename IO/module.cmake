# IO/: readers of the SplineViz module (included from cmake/module/CMakeLists.txt).
list(APPEND splineviz_classes
  "${SPLINEVIZ_FOLDER}/vtkLRSplineReader")
# Plain C++ parser of the LRSplines text and GoTools g2 formats.
list(APPEND splineviz_private_classes
  "${SPLINEVIZ_FOLDER}/vtkLRSplineParser")
