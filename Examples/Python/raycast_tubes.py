# SPDX-License-Identifier: BSD-3-Clause
"""Ray-cast spline tubes in an ordinary VTK pipeline (pvpython or any Python
with ParaView's vtkmodules):

    source build/splineviz-env.sh
    pvpython Examples/Python/raycast_tubes.py [out.png]

Polylines (here from the built-in synthetic fibers; any vtkPolyData with
lines works, e.g. streamlines) are drawn as smooth tubes whose radius follows
a point array in world units and whose color follows a scalar through a
lookup table, next to an opaque sphere that they cut exactly (exact depth).
Without an output file name the window is interactive.
"""
import sys

from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkRenderingCore import (
    vtkActor,
    vtkColorTransferFunction,
    vtkPolyDataMapper,
    vtkRenderer,
    vtkRenderWindow,
    vtkRenderWindowInteractor,
    vtkWindowToImageFilter,
)
from vtkmodules.vtkIOImage import vtkPNGWriter
import vtkmodules.vtkInteractionStyle  # noqa: F401
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401

from splineviz import vtkRayCastTubeMapper, vtkSyntheticFibersSource

fibers = vtkSyntheticFibersSource()
fibers.SetPresetToFibers()  # 241 tubes, 3,530 segments, arrays "Radius" and "Scalar"

colors = vtkColorTransferFunction()
colors.AddRGBPoint(0.0, 0.23, 0.30, 0.75)
colors.AddRGBPoint(0.5, 0.86, 0.86, 0.86)
colors.AddRGBPoint(1.0, 0.71, 0.02, 0.15)

tubes = vtkRayCastTubeMapper()
tubes.SetInputConnection(fibers.GetOutputPort())
tubes.SetRadiusArray("Radius")  # world units; or tubes.SetRadius(0.01)
tubes.SetRadiusScale(1.0)
tubes.SetSubSegments(2)  # quadratic pieces per cubic segment (Salm: 2)
tubes.SetRootIterations(10)  # bisection steps per root (Salm: 10)
tubes.SetLookupTable(colors)
tubes.SetScalarRange(0.0, 1.0)  # colors from the active scalars ("Scalar")

actor = vtkActor()
actor.SetMapper(tubes)
actor.GetProperty().SetSpecular(0.5)
actor.GetProperty().SetSpecularPower(40)

sphere = vtkSphereSource()
sphere.SetRadius(0.2)
sphere.SetThetaResolution(64)
sphere.SetPhiResolution(64)
sphere_mapper = vtkPolyDataMapper()
sphere_mapper.SetInputConnection(sphere.GetOutputPort())
sphere_actor = vtkActor()
sphere_actor.SetMapper(sphere_mapper)

renderer = vtkRenderer()
renderer.AddActor(actor)
renderer.AddActor(sphere_actor)
renderer.SetBackground(1, 1, 1)
renderer.GetActiveCamera().SetPosition(0.3, 0.4, 1.8)
renderer.ResetCameraClippingRange()
window = vtkRenderWindow()
window.SetSize(900, 700)
window.AddRenderer(renderer)

if len(sys.argv) > 1:
    window.SetOffScreenRendering(1)
    window.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    writer = vtkPNGWriter()
    writer.SetFileName(sys.argv[1])
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()
    print("GPU memory: %.1f bytes per segment" % (tubes.GetGPUMemorySize() / 3530.0))
else:
    interactor = vtkRenderWindowInteractor()
    interactor.SetRenderWindow(window)
    window.Render()
    interactor.Start()
