# SPDX-License-Identifier: BSD-3-Clause
"""Direction coloring (DirectionColoring) in the three line renderers against
the analytic curve.

A curl of known tangent: x(u) = (u, A sin(k u) cos(a), A sin(k u) sin(a)), a
sine of several periods in a plane tilted by `a` about the x axis (radius of
curvature at the peaks 16 pixels), sampled at 480 points (1.2 pixels apart,
as a whole-brain tractogram's 1 mm steps are when the brain fills the view),
drawn as a tube about 9 pixels wide with an orthographic camera
looking along the plane's normal, unlit (ambient 1, diffuse 0: the pixel is
the fragment's color). For every pixel drawn inside the tube (away from its
silhouette), the nearest point of the analytic curve to the pixel's centre
(in the plane) is the curve point the fragment belongs to (the tube is
swept by a sphere along the curve); its unit tangent's absolute components
are the expected RGB. Near the peaks the color changes by 16/255 per pixel
along the curve. Checks, at every pixel inside the tube: the 99th
percentile of the error at most 2/255; the largest at most 2/255 for the
ray-cast tubes (the tangent at the exact hit), 3/255 for the stylized lines
(which interpolate it between nodes) and 5/255 for the tessellated tubes
(which find the curve point from their polygonal mesh: off at a few pixels
in the sharpest bends); the spline through the samples is not the sine
exactly. Negative
controls: the colors of the polyline's chords, of
tangents a twentieth of a period further along, or with the channels
permuted, fail the same bound.
"""

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import vtkActor, vtkWindowToImageFilter
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the OpenGL factory)

import splineviz
from splineviz_testing import offscreen_window, output_dir

from splineviz_testing import Checker  # noqa: E402

checker = Checker()


check = checker.check


A, K, TILT = 0.35, 2.0 * np.pi / 1.5, np.radians(35.0)
LENGTH = 6.0
PLANE_Y = np.array([0.0, np.cos(TILT), np.sin(TILT)])  # the curve's second axis
NORMAL = np.array([0.0, -np.sin(TILT), np.cos(TILT)])
W, H = 640, 240
SCALE = 0.55 * LENGTH * H / W  # parallel scale: the curve fills the width


def curve(u):
    return np.outer(u, [1.0, 0.0, 0.0]) + np.outer(A * np.sin(K * u), PLANE_Y)


def tangent(u):
    t = np.outer(np.ones_like(u), [1.0, 0.0, 0.0]) + np.outer(A * K * np.cos(K * u), PLANE_Y)
    return t / np.linalg.norm(t, axis=1)[:, None]


def polyline():
    u = np.linspace(-LENGTH / 2, LENGTH / 2, 480)
    points = vtkPoints()
    points.SetData(numpy_to_vtk(curve(u), deep=True))
    lines = vtkCellArray()
    lines.InsertNextCell(len(u))
    for i in range(len(u)):
        lines.InsertCellPoint(i)
    pd = vtkPolyData()
    pd.SetPoints(points)
    pd.SetLines(lines)
    return pd


def render(cls, name):
    mapper = cls()
    mapper.SetInputData(polyline())
    pixel = 2.0 * SCALE / H
    mapper.SetRadius(4.5 * pixel)
    mapper.DirectionColoringOn()
    if hasattr(mapper, "SetHaloWidth"):
        mapper.SetHaloWidth(0.0)
    actor = vtkActor()
    actor.SetMapper(mapper)
    prop = actor.GetProperty()
    prop.SetAmbient(1.0)
    prop.SetDiffuse(0.0)
    prop.SetSpecular(0.0)
    win, ren = offscreen_window(actor, (W, H), background=(0, 0, 0))
    cam = ren.GetActiveCamera()
    cam.ParallelProjectionOn()
    cam.SetParallelScale(SCALE)
    cam.SetFocalPoint(0, 0, 0)
    cam.SetPosition(*(10.0 * NORMAL))
    cam.SetViewUp(*PLANE_Y)
    cam.SetClippingRange(1.0, 20.0)
    win.Render()
    w2i = vtkWindowToImageFilter()
    w2i.SetInput(win)
    w2i.Update()
    writer = vtkPNGWriter()
    writer.SetFileName("%s/TestDirectionColoring-%s.png" % (output_dir(), name))
    writer.SetInputConnection(w2i.GetOutputPort())
    writer.Write()
    rgb = vtk_to_numpy(w2i.GetOutput().GetPointData().GetScalars())[:, :3]
    return rgb.reshape(H, W, 3).astype(float)


# Dense samples of the curve for the nearest-point search, in plane coordinates.
u_dense = np.linspace(-LENGTH / 2 - 0.2, LENGTH / 2 + 0.2, 200001)
plane_dense = np.stack([u_dense, A * np.sin(K * u_dense)], axis=1)
pixel = 2.0 * SCALE / H


def chord_direction(u):
    """The direction of the sampled polyline's segment holding u (what
    coloring each segment by its chord, without the spline, gives)."""
    samples = np.linspace(-LENGTH / 2, LENGTH / 2, 480)
    i = np.clip(np.searchsorted(samples, u) - 1, 0, len(samples) - 2)
    d = curve(samples[i + 1]) - curve(samples[i])
    return d / np.linalg.norm(d, axis=1)[:, None]


def expected_colors(rows, cols, shift=0.0, permute=False, chords=False):
    # Pixel centres in plane coordinates (x along the curve, y along PLANE_Y).
    x = (cols + 0.5 - W / 2) * pixel
    y = (rows + 0.5 - H / 2) * pixel
    # Nearest curve point: a coarse search on the dense samples, by column band.
    order = np.argsort(x)
    u_near = np.empty_like(x)
    step = u_dense[1] - u_dense[0]
    for i in order:
        lo = max(0, int((x[i] - 6 * pixel - u_dense[0]) / step))
        hi = min(len(u_dense), int((x[i] + 6 * pixel - u_dense[0]) / step) + 1)
        d = (plane_dense[lo:hi, 0] - x[i]) ** 2 + (plane_dense[lo:hi, 1] - y[i]) ** 2
        u_near[i] = u_dense[lo + int(np.argmin(d))]
    color = 255.0 * np.abs(chord_direction(u_near) if chords else tangent(u_near + shift))
    return color[:, [1, 2, 0]] if permute else color


renderers = {"raycast": splineviz.vtkRayCastTubeMapper,
             "tessellated": splineviz.vtkTessellatedTubeMapper,
             "stylized": splineviz.vtkStylizedLineMapper}
for name, cls in renderers.items():
    image = render(cls, name)
    drawn = image.max(axis=2) > 0
    # Inside the tube: the pixel and its 8 neighbours drawn (no silhouette pixel).
    inner = drawn.copy()
    for dy in (-1, 0, 1):
        for dx in (-1, 0, 1):
            inner &= np.roll(np.roll(drawn, dy, axis=0), dx, axis=1)
    rows, cols = np.nonzero(inner)
    check(len(rows) > 3000, "%s: %d pixels inside the tube" % (name, len(rows)))
    if len(rows) == 0:
        continue
    got = image[rows, cols]
    err = np.abs(got - expected_colors(rows, cols)).max(axis=1)
    p99, worst = np.percentile(err, 99), err.max()
    print("%s: error in 1/255, median %.2f, 99th percentile %.2f, largest %.2f; "
          "%d of %d pixels over 2/255" % (name, np.median(err), p99, worst,
                                          np.count_nonzero(err > 2.0), len(err)))
    # The ray cast evaluates the spline's tangent at the exact hit: within
    # 2/255 everywhere. The stylized lines interpolate it between nodes
    # (3/255); the tessellated tubes take the curve point nearest to the
    # fragment's point on their polygonal mesh (two Newton steps from the
    # parameter interpolated across it), which in the peaks' bends (radius
    # of curvature 16 px, tube 9 px wide) is off at a few pixels (4.4/255 at
    # 4 of 5,126 pixels): 5/255.
    limit = {"raycast": 2.0, "stylized": 3.0}.get(name, 5.0)
    check(p99 <= 2.0 and worst <= limit,
          "%s: direction colors within 2/255 (99 %%), %g/255 (all)" % (name, limit))
    period = 2.0 * np.pi / K
    for what, kwargs in (("shifted a twentieth of a period", {"shift": period / 20}),
                         ("the polyline's chords", {"chords": True}),
                         ("channels permuted", {"permute": True})):
        control = np.abs(got - expected_colors(rows, cols, **kwargs)).max(axis=1)
        check(np.percentile(control, 99) > 2.0,
              "%s: control (%s) fails the bound: 99th percentile %.1f/255"
              % (name, what, np.percentile(control, 99)))

checker.finish()
