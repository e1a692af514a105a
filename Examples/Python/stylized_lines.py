# SPDX-License-Identifier: BSD-3-Clause
"""Stylized line primitives on streamlines (SplineViz's vtkStylizedLineMapper;
Stoll, Gumhold and Seidel, "Visualization with stylized line primitives",
section 6 and Fig. 11): the encodings of the paper, on streamlines that VTK's
vtkStreamTracer integrates through a swirling, expanding and contracting flow.

    pvpython Examples/Python/stylized_lines.py [output-directory]

(with the build tree's `splineviz` on PYTHONPATH: source build/splineviz-env.sh;
with SPLINEVIZ_PLUGIN or the plugin on PV_PLUGIN_PATH the ParaView part runs too)

- velocity magnitude -> color;
- integrated divergence -> radius: a stream tube's cross-section grows like
  exp(integral of div v dt), so the radius is r0 exp(0.5 integral div v dt)
  (the divergence is VTK's vtkGradientFilter's, interpolated onto the lines
  by the tracer, integrated over the tracer's IntegrationTime);
- integrated rotation about the flow direction (the tracer's "Rotation",
  with ComputeVorticity on) -> the orientation of a stripe texture: the
  stripes twist where the flow swirls (Fig. 11 right);
- a halo in the background color, so that lines in front cut the lines
  behind them.
Writes stylized-lines.png (VTK) and, with the plugin, stylized-lines-paraview.png.
"""
import os
import sys

import numpy as np
from vtkmodules.numpy_interface import dataset_adapter as dsa
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkLookupTable, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkImageData, vtkPolyData
from vtkmodules.vtkFiltersGeneral import vtkGradientFilter
from vtkmodules.vtkFiltersFlowPaths import vtkStreamTracer
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import (
    vtkActor,
    vtkRenderer,
    vtkRenderWindow,
    vtkWindowToImageFilter,
)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (OpenGL render window)

import splineviz

out = sys.argv[1] if len(sys.argv) > 1 else "."
os.makedirs(out, exist_ok=True)


def flow_field(n=48):
    """v = (a(z) x - w y, w x + a(z) y, 1 + 0.3 sin z) on [-2, 2]^2 x [0, 8]:
    a swirl of angular velocity w = 0.8 exp(-r^2) and a radial part
    a(z) = 0.5 sin(0.9 z) that makes the flow expand and contract
    (div v = 2 a(z) + 0.3 cos z)."""
    image = vtkImageData()
    image.SetDimensions(n, n, 2 * n)
    image.SetOrigin(-2.0, -2.0, 0.0)
    image.SetSpacing(4.0 / (n - 1), 4.0 / (n - 1), 8.0 / (2 * n - 1))
    x, y, z = np.meshgrid(np.linspace(-2, 2, n), np.linspace(-2, 2, n),
                          np.linspace(0, 8, 2 * n), indexing="ij")
    w = 0.8 * np.exp(-(x * x + y * y))
    a = 0.5 * np.sin(0.9 * z)
    v = np.stack([a * x - w * y, w * x + a * y, 1.0 + 0.3 * np.sin(z)], axis=-1)
    # VTK's point order: x fastest.
    v = v.transpose(2, 1, 0, 3).reshape(-1, 3)
    array = numpy_to_vtk(np.ascontiguousarray(v), deep=True)
    array.SetName("Velocity")
    image.GetPointData().SetVectors(array)
    return image


field = flow_field()
gradient = vtkGradientFilter()
gradient.SetInputData(field)
gradient.SetInputArrayToProcess(0, 0, 0, 0, "Velocity")
gradient.ComputeDivergenceOn()
gradient.SetDivergenceArrayName("Divergence")
gradient.ComputeGradientOff()
gradient.Update()

seeds = vtkPolyData()
points = vtkPoints()
for ring, radius in enumerate((0.35, 0.75, 1.15)):
    count = 8 + 6 * ring
    for k in range(count):
        angle = 2.0 * np.pi * (k + 0.5 * ring) / count
        points.InsertNextPoint(radius * np.cos(angle), radius * np.sin(angle), 0.1)
seeds.SetPoints(points)

tracer = vtkStreamTracer()
tracer.SetInputConnection(gradient.GetOutputPort())
tracer.SetSourceData(seeds)
tracer.SetInputArrayToProcess(0, 0, 0, 0, "Velocity")
tracer.SetIntegrationDirectionToForward()
tracer.SetIntegratorTypeToRungeKutta45()
tracer.SetMaximumPropagation(20.0)
tracer.SetInitialIntegrationStep(0.1)
tracer.SetComputeVorticity(True)  # gives "Rotation": integrated rotation about the flow direction
# One thread: the same streamlines on every run (VTK 9.2 traces seeds in
# parallel; once, in CI, the output's arrays did not match its lines).
tracer.SetForceSerialExecution(True)
tracer.Update()

# Integrated divergence -> radius, per streamline (trapezoidal rule over time).
lines = dsa.WrapDataObject(tracer.GetOutput())
div = np.asarray(lines.PointData["Divergence"])
time = np.asarray(lines.PointData["IntegrationTime"])
radius = np.zeros(len(time))
cells = tracer.GetOutput().GetLines()
if not (len(div) == len(time) == tracer.GetOutput().GetNumberOfPoints()
        and cells.GetNumberOfConnectivityIds() <= len(time)):
    raise RuntimeError("vtkStreamTracer's output is inconsistent: %d points, %d Divergence and "
                       "%d IntegrationTime values, %d line point ids"
                       % (tracer.GetOutput().GetNumberOfPoints(), len(div), len(time),
                          cells.GetNumberOfConnectivityIds()))
cells.InitTraversal()
from vtkmodules.vtkCommonCore import vtkIdList  # noqa: E402

ids = vtkIdList()
while cells.GetNextCell(ids):
    idx = np.array([ids.GetId(i) for i in range(ids.GetNumberOfIds())])
    integral = np.concatenate([[0.0], np.cumsum(0.5 * (div[idx[1:]] + div[idx[:-1]]) * np.diff(time[idx]))])
    radius[idx] = 0.035 * np.exp(0.5 * integral)
radius_array = vtkDoubleArray()
radius_array.SetName("Radius")
for r in radius:
    radius_array.InsertNextValue(float(r))
tracer.GetOutput().GetPointData().AddArray(radius_array)
speed = np.linalg.norm(np.asarray(lines.PointData["Velocity"]), axis=1)
print("%d streamlines, %d points; speed %.2f .. %.2f, radius %.3f .. %.3f, rotation %.2f .. %.2f rad"
      % (tracer.GetOutput().GetNumberOfLines(), len(time), speed.min(), speed.max(),
         radius.min(), radius.max(), np.min(lines.PointData["Rotation"]),
         np.max(lines.PointData["Rotation"])))

# Velocity magnitude -> color: purple to red to yellow (Stoll Fig. 11).
lut = vtkLookupTable()
lut.SetNumberOfTableValues(256)
for i in range(256):
    s = i / 255.0
    lut.SetTableValue(i, min(1.0, 0.45 + 1.1 * s), max(0.0, 1.6 * s - 0.6), max(0.0, 0.55 - 1.2 * s), 1.0)
lut.SetVectorModeToMagnitude()
lut.Build()


def lines_actor(textured):
    mapper = splineviz.vtkStylizedLineMapper()
    mapper.SetInputConnection(tracer.GetOutputPort())
    mapper.SetRadiusArray("Radius")
    mapper.SetScalarModeToUsePointFieldData()
    mapper.SelectColorArray("Velocity")
    mapper.SetLookupTable(lut)
    mapper.SetScalarRange(float(speed.min()), float(speed.max()))
    mapper.SetHaloWidth(0.35)  # in the background color
    if textured:
        mapper.SetTexturePatternToStripes()
        mapper.SetTextureCircumferentialRepeat(2)
        mapper.SetOrientationArray("Rotation")
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetSpecular(0.35)
    actor.GetProperty().SetSpecularPower(30)
    return actor, mapper


window = vtkRenderWindow()
window.SetSize(1200, 600)
window.SetOffScreenRendering(1)
for v, textured in enumerate((False, True)):
    actor, mapper = lines_actor(textured)
    renderer = vtkRenderer()
    renderer.SetViewport(0.5 * v, 0.0, 0.5 * v + 0.5, 1.0)
    renderer.SetBackground(0.96, 0.96, 0.94)
    renderer.AddActor(actor)
    window.AddRenderer(renderer)
    camera = renderer.GetActiveCamera()
    camera.SetFocalPoint(0.0, 0.0, 4.0)
    camera.SetPosition(7.0, -9.0, 7.5)
    camera.SetViewUp(0.0, 0.0, 1.0)
    renderer.ResetCamera()
    camera.Zoom(1.1)
window.Render()
print("GPU bytes per segment: %.1f" % (mapper.GetGPUMemorySize()
                                        / max(1, mapper.GetTubeCore().GetNumberOfSegments())))
grab = vtkWindowToImageFilter()
grab.SetInput(window)
grab.Update()
writer = vtkPNGWriter()
writer.SetFileName(os.path.join(out, "stylized-lines.png"))
writer.SetInputConnection(grab.GetOutputPort())
writer.Write()
print("wrote", os.path.join(out, "stylized-lines.png"))

# The same in ParaView: the "Stylized Lines" representation.
plugin = os.environ.get("SPLINEVIZ_PLUGIN")
try:
    from paraview import simple
except ImportError:
    simple = None
if simple is not None and (plugin or os.environ.get("PV_PLUGIN_PATH")):
    from splineviz.plugin import load_plugin

    load_plugin(globals(), plugin)
    # The streamlines as a user would have them: a file ParaView opens.
    from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter

    vtp = os.path.join(out, "stylized-lines-streamlines.vtp")
    save = vtkXMLPolyDataWriter()
    save.SetFileName(vtp)
    save.SetInputConnection(tracer.GetOutputPort())
    save.Write()
    streamlines = simple.XMLPolyDataReader(FileName=[vtp])
    view = simple.CreateRenderView()
    view.ViewSize = [800, 600]
    view.OrientationAxesVisibility = 0
    display = simple.Show(streamlines, view)
    display.SetRepresentationType("Stylized Lines")
    simple.ColorBy(display, ("POINTS", "Velocity", "Magnitude"))
    display.TubeRadiusArray = "Radius"
    display.HaloWidth = 0.35
    display.LineTexturePattern = "Stripes"
    display.OrientationArray = "Rotation"
    view.CameraFocalPoint = [0.0, 0.0, 4.0]
    view.CameraPosition = [7.0, -9.0, 7.5]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    simple.ResetCamera(view)
    png = os.path.join(out, "stylized-lines-paraview.png")
    simple.SaveScreenshot(png, view, ImageResolution=[800, 600])
    print("wrote", png)
    # Release the view here, not at the interpreter's exit (as
    # superquadric_glyphs.py does: inside another script, pvpython crashed at
    # exit while ParaView's teardown made the view's window current).
    simple.Delete(display)
    simple.Delete(view)
    simple.Delete(streamlines)
    del view, display, streamlines
