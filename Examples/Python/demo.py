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
