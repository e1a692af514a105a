# SPDX-License-Identifier: BSD-3-Clause
"""Per-streamline visibility in the three line renderers (VisibilityArray).

For the ray-cast tubes, the tessellated tubes and the stylized lines, on a
synthetic tractogram of Fibers2 size (about 120k segments):

- a random selection drawn through VisibilityArray gives the same image, pixel
  for pixel (multisampling off), as the selected streamlines alone drawn by a
  second mapper (the reference: a polydata holding only those lines);
- changing the selection's values (the same points and lines) draws the new
  selection in the next frame without building the tubes again (the core is
  not rebuilt) and the image equals the new reference;
- negative controls: the image of all lines and the image of the complement
  selection differ from the reference in many pixels;
- a block without the array is an error and is drawn whole.

Two tiny anchor lines far outside the view are in both polydata, so that the
mappers place the uploaded coordinates around the same centre (float rounding
is then the same on both sides).
"""
import time

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkPoints, vtkUnsignedCharArray
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import vtkActor, vtkWindowToImageFilter
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the OpenGL factory)

import splineviz
from splineviz_testing import Observed, offscreen_window, output_dir

from splineviz_testing import Checker  # noqa: E402

checker = Checker()


check = checker.check


def make_tractogram():
    source = splineviz.vtkSyntheticTractogramSource()
    source.SetNumberOfStreamlines(1500)
    source.SetSeed(7)
    source.Update()
    data = source.GetOutput()
    points = vtk_to_numpy(data.GetPoints().GetData()).astype(np.float64)
    offsets = vtk_to_numpy(data.GetLines().GetOffsetsArray()).astype(np.int64)
    connectivity = vtk_to_numpy(data.GetLines().GetConnectivityArray()).astype(np.int64)
    lines = [connectivity[offsets[i]:offsets[i + 1]] for i in range(len(offsets) - 1)]
    return points, lines


def polydata(points, lines, anchors):
    """Polylines `lines` (index arrays into `points`) plus the two anchors."""
    pts = [points]
    cells = list(lines)
    base = len(points)
    for a in anchors:
        pts.append(a)
        cells.append(np.arange(base, base + len(a)))
        base += len(a)
    xyz = np.concatenate(pts)
    vpoints = vtkPoints()
    vpoints.SetData(numpy_to_vtk(np.ascontiguousarray(xyz), deep=True))
    array = vtkCellArray()
    for c in cells:
        array.InsertNextCell(len(c))
        for i in c:
            array.InsertCellPoint(int(i))
    pd = vtkPolyData()
    pd.SetPoints(vpoints)
    pd.SetLines(array)
    return pd


def render(mapper, camera_from, name):
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(0.8, 0.3, 0.2)
    win, ren = offscreen_window(actor, (600, 450))
    cam = ren.GetActiveCamera()
    cam.SetFocalPoint(*camera_from["focal"])
    cam.SetPosition(*camera_from["position"])
    cam.SetViewUp(0, 0, 1)
    ren.ResetCameraClippingRange(*camera_from["bounds"])
    return win, ren


def grab(win, name):
    win.Render()
    w2i = vtkWindowToImageFilter()
    w2i.SetInput(win)
    w2i.ReadFrontBufferOff()
    w2i.Update()
    writer = vtkPNGWriter()
    writer.SetFileName(output_dir() + "/" + name)
    writer.SetInputConnection(w2i.GetOutputPort())
    writer.Write()
    image = vtk_to_numpy(w2i.GetOutput().GetPointData().GetScalars())
    return image.reshape(450, 600, -1)[:, :, :3].astype(np.int32)


def differing(a, b):
    return int(np.count_nonzero(np.any(a != b, axis=2)))


points, lines = make_tractogram()
lo, hi = points.min(axis=0), points.max(axis=0)
centre = 0.5 * (lo + hi)
extent = float(np.linalg.norm(hi - lo))
# Anchors: tiny lines at the corners of a box around the data, outside the view.
anchors = [np.array([centre - 4 * extent, centre - 4 * extent + 1e-3]),
           np.array([centre + 4 * extent, centre + 4 * extent + 1e-3])]
camera = {"focal": centre, "position": centre + np.array([0.0, -1.6 * extent, 0.35 * extent]),
          "bounds": (lo[0], hi[0], lo[1], hi[1], lo[2], hi[2])}
radius = 0.003 * extent
segments = sum(len(l) - 1 for l in lines)
print("streamlines:", len(lines), "segments:", segments)

rng = np.random.default_rng(11)
selections = [rng.random(len(lines)) < 0.3, rng.random(len(lines)) < 0.5]

full = polydata(points, lines, anchors)
selected = vtkUnsignedCharArray()
selected.SetName("Selected")
selected.SetNumberOfTuples(full.GetNumberOfCells())
full.GetCellData().AddArray(selected)


def set_selection(mask):
    values = np.concatenate([mask.astype(np.uint8), [1, 1]])  # anchors stay
    for i, v in enumerate(values):
        selected.SetValue(i, int(v))
    selected.Modified()


renderers = {"raycast": splineviz.vtkRayCastTubeMapper,
             "tessellated": splineviz.vtkTessellatedTubeMapper,
             "stylized": splineviz.vtkStylizedLineMapper}

for name, cls in renderers.items():
    mapper = cls()
    mapper.SetInputData(full)
    mapper.SetRadius(radius)
    mapper.SetVisibilityArray("Selected")
    set_selection(selections[0])
    win, ren = render(mapper, camera, name)
    for k, mask in enumerate(selections):
        if k > 0:
            set_selection(mask)
            full.Modified()  # as a filter's re-execution would
        core_time = mapper.GetTubeCore().GetMTime()
        start = time.perf_counter()
        win.Render()
        elapsed = time.perf_counter() - start
        image = grab(win, "TestLineVisibility-%s-%d.png" % (name, k))
        if k > 0:
            check(mapper.GetTubeCore().GetMTime() == core_time,
                  "%s: a new selection does not rebuild the tubes" % name)
        check(mapper.GetNumberOfVisibleLines() == int(mask.sum()) + 2,
              "%s: %d visible lines reported (expected %d)"
              % (name, mapper.GetNumberOfVisibleLines(), int(mask.sum()) + 2))
        start = time.perf_counter()
        win.Render()
        still = time.perf_counter() - start
        print("%s selection %d: frame %.3f s, the same frame again %.3f s" % (name, k, elapsed, still))

        # The reference: the selected lines alone.
        ref_mapper = cls()
        ref_mapper.SetInputData(polydata(points, [l for l, m in zip(lines, mask) if m], anchors))
        ref_mapper.SetRadius(radius)
        ref_win, _ = render(ref_mapper, camera, name)
        reference = grab(ref_win, "TestLineVisibility-%s-%d-reference.png" % (name, k))
        diff = differing(image, reference)
        drawn = int(np.count_nonzero(np.any(reference != 255, axis=2)))
        check(drawn > 20000, "%s: the reference draws %d pixels" % (name, drawn))
        check(diff == 0, "%s selection %d: %d pixels differ from the selected lines alone"
              % (name, k, diff))

        # Negative controls: the complement, and all lines.
        comp_mapper = cls()
        comp_mapper.SetInputData(polydata(points, [l for l, m in zip(lines, mask) if not m],
                                          anchors))
        comp_mapper.SetRadius(radius)
        comp_win, _ = render(comp_mapper, camera, name)
        complement = grab(comp_win, "TestLineVisibility-%s-%d-complement.png" % (name, k))
        check(differing(complement, reference) > drawn // 4,
              "%s: control, the complement differs in %d pixels"
              % (name, differing(complement, reference)))
        del comp_win, ref_win

    # All lines (the array unset) differ from the selection.
    mapper.SetVisibilityArray(None)
    everything = grab(win, "TestLineVisibility-%s-all.png" % name)
    check(differing(everything, image) > 5000,
          "%s: control, all lines differ from the selection in %d pixels"
          % (name, differing(everything, image)))
    check(mapper.GetNumberOfVisibleLines() == len(lines) + 2, "%s: all lines visible" % name)

    # A missing array: an error, and every line drawn.
    mapper.SetVisibilityArray("NoSuchArray")
    observed = Observed(mapper)
    missing = grab(win, "TestLineVisibility-%s-missing.png" % name)
    check(len(observed.errors) > 0, "%s: a missing visibility array is an error" % name)
    check(differing(missing, everything) == 0, "%s: ... and all lines are drawn" % name)
    del win

checker.finish()
