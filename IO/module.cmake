# IO/: readers of the SplineViz module (included from cmake/module/CMakeLists.txt).
