"""SplineViz demonstration: renders the built-in synthetic data sets with the
SplineViz renderers to PNG files.

    pvpython Examples/Python/demo.py OUTPUT_DIR

(scripts/demo.sh sets up, builds and runs this under an X display.)
"""
import os
import sys

from vtkmodules.vtkFiltersCore import vtkTubeFilter
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import (
    vtkActor,
    vtkPolyDataMapper,
    vtkRenderer,
    vtkRenderWindow,
    vtkWindowToImageFilter,
)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (OpenGL render window)
import vtkmodules.vtkRenderingFreeType  # noqa: F401

import splineviz

out_dir = sys.argv[1] if len(sys.argv) > 1 else "."
os.makedirs(out_dir, exist_ok=True)


def save(window, name):
    window.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    grab.Update()
    writer = vtkPNGWriter()
    path = os.path.join(out_dir, name)
    writer.SetFileName(path)
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()
    print("wrote", path)


fibers = splineviz.vtkSyntheticFibersSource()
fibers.SetPresetToFibers()
fibers.Update()

# The polylines as VTK's own tube filter draws them (the reference the
# SplineViz renderers are compared with).
tubes = vtkTubeFilter()
tubes.SetInputConnection(fibers.GetOutputPort())
tubes.SetRadius(0.006)
tubes.SetNumberOfSides(12)
mapper = vtkPolyDataMapper()
mapper.SetInputConnection(tubes.GetOutputPort())
mapper.SetScalarRange(0, 1)
actor = vtkActor()
actor.SetMapper(mapper)
renderer = vtkRenderer()
renderer.AddActor(actor)
renderer.SetBackground(0.1, 0.1, 0.12)
renderer.ResetCamera()
window = vtkRenderWindow()
window.SetOffScreenRendering(1)
window.SetSize(800, 600)
window.AddRenderer(renderer)
save(window, "fibers-vtk-tube-filter.png")

# --- LR-spline volumes (Fuchs et al.) --------------------------------------
# The real locally refined volume, read as exact Bezier hexahedra: its
# surface with the element edges, coloured by the element size (the local
# refinement, like the paper's Fig. 1), and the g2 tensor-product volume in
# geometry mode (its real shape).
from vtkmodules.vtkFiltersGeometry import vtkDataSetSurfaceFilter  # noqa: E402

data_dir = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "Testing",
                        "Data", "External")
lr_file = os.path.join(data_dir, "cube-3patch-refined.lr")
if os.path.exists(lr_file):
    lr = splineviz.vtkLRSplineReader()
    lr.SetFileName(lr_file)
    lr.Update()
    patch = lr.GetOutput().GetBlock(0)
    surface = vtkDataSetSurfaceFilter()
    surface.SetInputData(patch)
    surface.SetNonlinearSubdivisionLevel(2)
    surface.Update()
    size_mapper = vtkPolyDataMapper()
    size_mapper.SetInputConnection(surface.GetOutputPort())
    size_mapper.SetScalarModeToUseCellFieldData()
    size_mapper.SelectColorArray("LRElementMinSide")
    size_mapper.SetScalarRange(patch.GetCellData().GetArray("LRElementMinSide").GetRange())
    size_actor = vtkActor()
    size_actor.SetMapper(size_mapper)
    edges = vtkDataSetSurfaceFilter()
    edges.SetInputData(patch)
    edges.SetNonlinearSubdivisionLevel(0)
    edge_mapper = vtkPolyDataMapper()
    edge_mapper.SetInputConnection(edges.GetOutputPort())
    edge_mapper.ScalarVisibilityOff()
    edge_actor = vtkActor()
    edge_actor.SetMapper(edge_mapper)
    edge_actor.GetProperty().SetRepresentationToWireframe()
    edge_actor.GetProperty().SetColor(0.05, 0.05, 0.05)
    renderer = vtkRenderer()
    renderer.AddActor(size_actor)
    renderer.AddActor(edge_actor)
    renderer.SetBackground(1, 1, 1)
    renderer.GetActiveCamera().SetPosition(2.6, -1.9, 2.4)
    renderer.GetActiveCamera().SetFocalPoint(0.5, 0.5, 0.5)
    renderer.GetActiveCamera().SetViewUp(0, 0, 1)
    renderer.ResetCamera()
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(800, 600)
    window.AddRenderer(renderer)
    save(window, "lr-spline-elements.png")

    g2 = splineviz.vtkLRSplineReader()
    g2.SetFileName(os.path.join(data_dir, "tensor-product-volume.g2"))
    g2.GeometryModeOn()
    g2.Update()
    shape = vtkDataSetSurfaceFilter()
    shape.SetInputData(g2.GetOutput().GetBlock(0))
    shape.SetNonlinearSubdivisionLevel(4)
    shape_mapper = vtkPolyDataMapper()
    shape_mapper.SetInputConnection(shape.GetOutputPort())
    shape_mapper.SetScalarModeToUsePointFieldData()
    shape_mapper.SelectColorArray("LRParameterCoordinates")
    shape_mapper.ColorByArrayComponent("LRParameterCoordinates", 1)
    shape_mapper.SetScalarRange(0, 1)
    shape_actor = vtkActor()
    shape_actor.SetMapper(shape_mapper)
    renderer = vtkRenderer()
    renderer.AddActor(shape_actor)
    renderer.SetBackground(1, 1, 1)
    renderer.GetActiveCamera().SetPosition(4, -6, 8)
    renderer.GetActiveCamera().SetFocalPoint(0, -1, 2.5)
    renderer.ResetCamera()
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(800, 600)
    window.AddRenderer(renderer)
    save(window, "lr-spline-g2-geometry.png")

    # Streamlines through the real spline: patch 1 of the file is the field
    # v = (-y, x, z) (helices about the z axis), traced on the exact spline
    # and drawn as tubes whose radius and colour follow the speed.
    # (vtkTubeFilter here; the SplineViz ray-cast tube mapper replaces it
    # where available.)
    from vtkmodules.vtkFiltersSources import vtkLineSource  # noqa: E402

    seeds = vtkLineSource()
    seeds.SetPoint1(0.2, 0.03, 0.04)
    seeds.SetPoint2(0.95, 0.03, 0.22)
    seeds.SetResolution(15)
    tracer = splineviz.vtkLRSplineStreamTracer()
    tracer.SetInputData(lr.GetOutput().GetBlock(1))
    tracer.SetSourceConnection(seeds.GetOutputPort())
    tracer.SetIntegratorType(splineviz.vtkLRSplineStreamTracer.RKF45)
    tracer.SetStepMode(splineviz.vtkLRSplineStreamTracer.ADAPTIVE)
    tracer.SetMaximumError(1e-7)
    tracer.SetMaximumIntegrationStep(0.02)
    tracer.Update()
    stream_tubes = vtkTubeFilter()
    stream_tubes.SetInputConnection(tracer.GetOutputPort())
    stream_tubes.SetInputArrayToProcess(0, 0, 0, 0, "Speed")
    stream_tubes.SetVaryRadiusToVaryRadiusByScalar()
    stream_tubes.SetRadius(0.006)
    stream_tubes.SetRadiusFactor(2.5)
    stream_tubes.SetNumberOfSides(16)
    stream_mapper = vtkPolyDataMapper()
    stream_mapper.SetInputConnection(stream_tubes.GetOutputPort())
    stream_mapper.SetScalarModeToUsePointFieldData()
    stream_mapper.SelectColorArray("Speed")
    stream_mapper.SetScalarRange(tracer.GetOutput().GetPointData().GetArray("Speed").GetRange())
    stream_actor = vtkActor()
    stream_actor.SetMapper(stream_mapper)
    renderer = vtkRenderer()
    renderer.AddActor(stream_actor)
    mesh1 = vtkDataSetSurfaceFilter()
    mesh1.SetInputData(lr.GetOutput().GetBlock(1))
    mesh1_mapper = vtkPolyDataMapper()
    mesh1_mapper.SetInputConnection(mesh1.GetOutputPort())
    mesh1_mapper.ScalarVisibilityOff()
    mesh1_actor = vtkActor()
    mesh1_actor.SetMapper(mesh1_mapper)
    mesh1_actor.GetProperty().SetRepresentationToWireframe()
    mesh1_actor.GetProperty().SetColor(0.3, 0.3, 0.3)
    mesh1_actor.GetProperty().SetOpacity(0.3)
    renderer.AddActor(mesh1_actor)  # the LR mesh of the spline
    renderer.SetBackground(1, 1, 1)
    renderer.GetActiveCamera().SetPosition(2.4, -1.6, 1.9)
    renderer.GetActiveCamera().SetFocalPoint(0.45, 0.45, 0.4)
    renderer.GetActiveCamera().SetViewUp(0, 0, 1)
    renderer.ResetCamera()
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(800, 600)
    window.AddRenderer(renderer)
    save(window, "lr-spline-streamlines.png")

# --- Fiber tracking: tensor lines (vtkTensorLineTracer) ----------------------
# DIPY's small real DTI scan (Testing/Data/DIPY/small_64D_dti.vti, tensors
# fitted by DIPY, lower-triangular layout): fibers traced from every voxel
# with FA >= 0.3, drawn as ray-cast spline tubes (radius from FA, RGB =
# |principal direction|), above the middle axial slice of the tensors drawn
# as superquadric glyphs when vtkSuperquadricGlyphMapper is part of this
# build, otherwise colored by the FA of vtkTensorAnalysisFilter.
from vtkmodules.vtkIOXML import vtkXMLImageDataReader  # noqa: E402
from vtkmodules.vtkImagingCore import vtkExtractVOI  # noqa: E402

dti_file = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "Testing",
                        "Data", "DIPY", "small_64D_dti.vti")
dti = vtkXMLImageDataReader()
dti.SetFileName(dti_file)
dti.Update()
tracer = splineviz.vtkTensorLineTracer()
tracer.SetInputConnection(dti.GetOutputPort())
tracer.SetInputArrayToProcess(0, 0, 0, 0, "DTI")
tracer.SetTensorLayout(2)  # DIPY: XX XY YY XZ YZ ZZ
tracer.SetSeedMode(splineviz.vtkTensorLineTracer.SEEDS_FROM_VOXELS)
tracer.SetSeedFAThreshold(0.3)
tracer.SetStoppingFAThreshold(0.15)
tracer.SetIntegrationStep(0.25)  # voxels
tracer.SetMinimumLength(4.0)  # mm
tracer.Update()
print("tensor lines: %d seeds, %d lines, %d points"
      % (tracer.GetNumberOfSeeds(), tracer.GetOutput().GetNumberOfLines(),
         tracer.GetOutput().GetNumberOfPoints()))
fiber_mapper = splineviz.vtkRayCastTubeMapper()
fiber_mapper.SetInputConnection(tracer.GetOutputPort())
fiber_mapper.SetRadiusArray("FractionalAnisotropy")
fiber_mapper.SetRadiusScale(0.15)
fiber_mapper.SetScalarModeToUsePointFieldData()
fiber_mapper.SelectColorArray("DirectionColors")
fiber_mapper.SetColorModeToDirectScalars()
fiber_actor = vtkActor()
fiber_actor.SetMapper(fiber_mapper)
fiber_actor.GetProperty().SetSpecular(0.3)
fiber_actor.GetProperty().SetSpecularPower(30)

middle = vtkExtractVOI()
middle.SetInputConnection(dti.GetOutputPort())
middle.SetVOI(0, 9, 0, 9, 4, 4)
middle.Update()
if hasattr(splineviz, "vtkSuperquadricGlyphMapper"):
    slice_mapper = splineviz.vtkSuperquadricGlyphMapper()
    slice_mapper.SetInputConnection(middle.GetOutputPort())
    slice_mapper.SetTensorArrayName("DTI")
    slice_mapper.SetTensorLayout(2)
    slice_mapper.SetScaleMode(slice_mapper.SCALE_NORMALIZED)
    slice_mapper.SetScaleFactor(0.95)
    slice_mapper.SetGamma(3.0)
    slice_mapper.SetGlyphColorMode(slice_mapper.COLOR_BY_EIGENVECTOR)
    print("tensor slice: superquadric glyphs")
else:
    slice_analysis = splineviz.vtkTensorAnalysisFilter()
    slice_analysis.SetInputConnection(middle.GetOutputPort())
    slice_analysis.SetInputArrayToProcess(0, 0, 0, 0, "DTI")
    slice_analysis.SetTensorLayout(2)
    slice_surface = vtkDataSetSurfaceFilter()
    slice_surface.SetInputConnection(slice_analysis.GetOutputPort())
    slice_mapper = vtkPolyDataMapper()
    slice_mapper.SetInputConnection(slice_surface.GetOutputPort())
    slice_mapper.SetScalarModeToUsePointFieldData()
    slice_mapper.SelectColorArray("FractionalAnisotropy")
    slice_mapper.SetScalarRange(0.0, 1.0)
    gray = slice_mapper.GetLookupTable()
    gray.SetSaturationRange(0, 0)
    gray.SetValueRange(0, 1)
    gray.SetHueRange(0, 0)
    print("tensor slice: FA of the tensor analysis (no superquadric glyph mapper in this build)")
slice_actor = vtkActor()
slice_actor.SetMapper(slice_mapper)
renderer = vtkRenderer()
renderer.AddActor(fiber_actor)
renderer.AddActor(slice_actor)
renderer.SetBackground(0.08, 0.08, 0.1)
renderer.GetActiveCamera().SetPosition(40, -30, 40)
renderer.GetActiveCamera().SetFocalPoint(9, 9, 9)
renderer.GetActiveCamera().SetViewUp(0, 0, 1)
renderer.ResetCamera()
window = vtkRenderWindow()
window.SetOffScreenRendering(1)
window.SetSize(900, 700)
window.AddRenderer(renderer)
save(window, "tensor-lines-dipy.png")
