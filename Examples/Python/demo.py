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
