# SPDX-License-Identifier: BSD-3-Clause
# Filters/: VTK filters and sources of the SplineViz module, and the plain C++
# numerical code they share (included from cmake/module/CMakeLists.txt).
list(APPEND splineviz_classes
  "${SPLINEVIZ_FOLDER}/vtkLRSplineFitterBase"
  "${SPLINEVIZ_FOLDER}/vtkLRSplineFitter"
  "${SPLINEVIZ_FOLDER}/vtkLRSplineImageFitter"
  "${SPLINEVIZ_FOLDER}/vtkLRSplineProbeFilter"
  "${SPLINEVIZ_FOLDER}/vtkLRSplineResampleToImage"
  "${SPLINEVIZ_FOLDER}/vtkLRSplineStreamTracer"
  "${SPLINEVIZ_FOLDER}/vtkStreamlineSelection"
  "${SPLINEVIZ_FOLDER}/vtkSyntheticFibersSource"
  "${SPLINEVIZ_FOLDER}/vtkSyntheticTractogramSource"
  "${SPLINEVIZ_FOLDER}/vtkTensorAnalysisFilter"
  "${SPLINEVIZ_FOLDER}/vtkTensorLineTracer")
# LR-spline volumes (Fuchs et al.): plain C++ shared by the filters, the
# reader and the renderers.
list(APPEND splineviz_private_classes
  "${SPLINEVIZ_FOLDER}/vtkLRSplineBezierGrid"
  "${SPLINEVIZ_FOLDER}/vtkLRSplineBezierVolume"
  "${SPLINEVIZ_FOLDER}/vtkLRSplineBuilder"
  "${SPLINEVIZ_FOLDER}/vtkLRSplineElementLocator"
  "${SPLINEVIZ_FOLDER}/vtkLRSplineEvaluator"
  "${SPLINEVIZ_FOLDER}/vtkLRSplineFitCore"
  "${SPLINEVIZ_FOLDER}/vtkLRSplineGeometryMap"
  "${SPLINEVIZ_FOLDER}/vtkLRSplineField"
  "${SPLINEVIZ_FOLDER}/vtkLRSplinePatch")
# Values that disagree with their neighbours (the fitter's RemoveOutliers).
list(APPEND splineviz_private_classes
  "${SPLINEVIZ_FOLDER}/vtkSplineVizLocalOutliers")
# Symmetric tensor math (layouts, eigen-decomposition, invariants, Kindlmann's
# glyph shape): plain C++ shared by the tensor filters and mappers; its core is
# glsl/vtkTensorMathShared.glsl, compiled as C++ and embedded in shaders.
list(APPEND splineviz_private_classes
  "${SPLINEVIZ_FOLDER}/vtkSplineVizTensorMath")
# All cores by default: the SMP backend the library's parallel loops run on.
list(APPEND splineviz_private_classes
  "${SPLINEVIZ_FOLDER}/vtkSplineVizThreads")
list(APPEND splineviz_shaders
  "${SPLINEVIZ_FOLDER}/glsl/vtkTensorMathShared.glsl")
# The shared GLSL/C++ subset: its C++ side (vtkSplineVizSharedGLSL.h) and the
# prelude every shader that embeds a *Shared.glsl file starts with.
list(APPEND splineviz_private_headers
  "${SPLINEVIZ_FOLDER}/vtkSplineVizSharedGLSL.h")
list(APPEND splineviz_shaders
  "${SPLINEVIZ_FOLDER}/glsl/vtkSplineVizPrelude.glsl"
  "${SPLINEVIZ_FOLDER}/glsl/vtkSplineVizCommonShared.glsl")
# The LR arrays' names; input arrays selected by name; progress, abort,
# output-size checks and requested pieces shared by the filters and readers.
list(APPEND splineviz_private_headers
  "${SPLINEVIZ_FOLDER}/vtkLRSplineArrayNames.h"
  "${SPLINEVIZ_FOLDER}/vtkSplineVizInputArrays.h"
  "${SPLINEVIZ_FOLDER}/vtkSplineVizPieces.h"
  "${SPLINEVIZ_FOLDER}/vtkSplineVizPolyLines.h"
  "${SPLINEVIZ_FOLDER}/vtkSplineVizProgress.h"
  "${SPLINEVIZ_FOLDER}/vtkSplineVizError.h"
  "${SPLINEVIZ_FOLDER}/vtkSplineVizSeeds.h"
  "${SPLINEVIZ_FOLDER}/vtkSplineVizTermination.h"
  "${SPLINEVIZ_FOLDER}/vtkSplineVizRandom.h")
# The explicit Runge-Kutta tableaux and step both tracers integrate with.
list(APPEND splineviz_private_headers
  "${SPLINEVIZ_FOLDER}/vtkSplineVizRungeKutta.h")
