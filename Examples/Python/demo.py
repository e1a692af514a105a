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

# -- Superquadric tensor glyphs (Hlawitschka et al.; Kindlmann 2004) ---------
# A synthetic tensor volume whose principal direction winds around the z axis
# and whose shape goes from linear (outside) through planar to nearly
# spherical (inside), drawn by vtkSuperquadricGlyphMapper at gamma 0, 3 and
# 20 (the same uploaded tensors, three uniform values), then DIPY's small
# real DTI scan when DIPY is available (see superquadric_glyphs.py).
import numpy as np  # noqa: E402
from vtkmodules.util.numpy_support import numpy_to_vtk  # noqa: E402
from vtkmodules.vtkCommonDataModel import vtkImageData  # noqa: E402

n = 8  # even: no point on the axis, where the winding direction is undefined
x, y, z = np.meshgrid(*(np.arange(n) - 0.5 * (n - 1),) * 3, indexing="ij")
x, y, z = (a.ravel(order="F") for a in (x, y, z))
r = np.sqrt(x * x + y * y) + 1e-9
e1 = np.stack([-y / r, x / r, 0.25 * np.ones_like(r)], 1)
e1 /= np.linalg.norm(e1, axis=1)[:, None]
e2 = np.cross(np.tile([0.0, 0.0, 1.0], (len(r), 1)), e1)
e2 /= np.linalg.norm(e2, axis=1)[:, None]
e3 = np.cross(e1, e2)
s = np.clip(r / r.max(), 0, 1)
l1 = np.ones_like(r)
l2 = 0.95 - 0.75 * s  # planar inside, linear outside
l3 = l2 * (0.9 - 0.75 * np.clip(np.abs(z) / z.max(), 0, 1))
T = sum(l[:, None, None] * e[:, :, None] * e[:, None, :] for l, e in ((l1, e1), (l2, e2), (l3, e3)))
six = np.stack([T[:, 0, 0], T[:, 1, 1], T[:, 2, 2], T[:, 0, 1], T[:, 1, 2], T[:, 0, 2]], 1)
field = vtkImageData()
field.SetDimensions(n, n, n)
tensor_array = numpy_to_vtk(six.copy(), deep=1)
tensor_array.SetName("T")
field.GetPointData().SetTensors(tensor_array)

glyph_window = vtkRenderWindow()
glyph_window.SetOffScreenRendering(1)
glyph_window.SetSize(1500, 520)
for v, gamma in enumerate((0.0, 3.0, 20.0)):
    glyph_mapper = splineviz.vtkSuperquadricGlyphMapper()
    glyph_mapper.SetInputData(field)
    glyph_mapper.SetGamma(gamma)
    glyph_mapper.SetScaleFactor(0.48)
    glyph_actor = vtkActor()
    glyph_actor.SetMapper(glyph_mapper)
    glyph_actor.GetProperty().SetSpecular(0.35)
    glyph_actor.GetProperty().SetSpecularPower(30)
    glyph_renderer = vtkRenderer()
    glyph_renderer.SetViewport(v / 3.0, 0.0, (v + 1) / 3.0, 1.0)
    glyph_renderer.SetBackground(0.1, 0.1, 0.12)
    glyph_renderer.AddActor(glyph_actor)
    glyph_window.AddRenderer(glyph_renderer)
    cam = glyph_renderer.GetActiveCamera()
    cam.SetPosition(9, -13, 9)
    cam.SetFocalPoint(0, 0, 0)
    cam.SetViewUp(0, 0, 1)
    glyph_renderer.ResetCamera()
    cam.Zoom(1.05)
save(glyph_window, "superquadric-glyphs-gamma-0-3-20.png")

try:
    import dipy  # noqa: F401
except ImportError:
    dipy = None
if dipy is not None:
    import runpy

    runpy.run_path(os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "superquadric_glyphs.py"), run_name="__main__")
