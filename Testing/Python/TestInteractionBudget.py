# SPDX-License-Identifier: BSD-3-Clause
"""The interaction budget of the three line renderers (vtkSplineTubeMapper's
InteractiveSubset): a dense synthetic tractogram (4,000
streamlines, thin tubes so that the picture is not saturated) drawn still, then while "the camera moves" as VTK's
interactors signal it (the render window's desired update rate raised to 30),
with a frame budget of a third of the still frame, then still again:
- still frames draw every line (line fraction 1);
- interactive frames draw a subset (fraction below 0.8, at least the
  minimum) in less time than the still frame (median of three frames each),
  without building or uploading the tubes again (the tube core is not
  rebuilt);
- the subset is spread over the whole picture: of the 15 x 15 pixel blocks
  where the still frame draws at least half of the pixels, the subset leaves
  at most half as many as holes (drawing less than a fifth of the still
  frame's pixels there) as the negative control does: as many lines of a few
  bundles (the first along x), which must leave at least 2 % (5-36 %
  measured: fewer the larger the subset the budget allows);
- when the camera stops, the picture is the still picture again, pixel for
  pixel;
- negative control: with InteractiveSubset off the raised rate changes
  nothing (fraction 1, the still picture)."""
import os
import statistics

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkIdList
from vtkmodules.vtkRenderingCore import vtkActor, vtkWindowToImageFilter
from vtkmodules.vtkFiltersCore import vtkExtractCells
from vtkmodules.vtkFiltersGeometry import vtkGeometryFilter
from vtkmodules.vtkIOImage import vtkPNGWriter
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the OpenGL factory)

import splineviz
from splineviz_testing import Checker, offscreen_window, output_dir

checker = Checker()
check = checker.check
STILL, MOVING = 0.0001, 30.0
W, H = 600, 450

source = splineviz.vtkSyntheticTractogramSource()
source.SetNumberOfStreamlines(4000)
source.Update()
lines = source.GetOutput().GetNumberOfLines()
# Where each line starts along x (the few-bundles control takes the lowest).
polys = source.GetOutput()
starts = np.array([polys.GetPoint(polys.GetCell(i).GetPointId(0))[0] for i in range(lines)])
b = polys.GetBounds()
RADIUS = 2e-4 * np.linalg.norm([b[1] - b[0], b[3] - b[2], b[5] - b[4]])


def picture(win, name=None):
    """Renders; the RGB pixels (row 0 at the bottom), written to
    TestInteractionBudget-<name>.png in the test output when named."""
    win.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(win)
    grab.ReadFrontBufferOff()
    grab.Update()
    if name:
        writer = vtkPNGWriter()
        writer.SetFileName(os.path.join(output_dir(), "TestInteractionBudget-%s.png" % name))
        writer.SetInputConnection(grab.GetOutputPort())
        writer.Write()
    image = vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars())
    return image.reshape(H, W, -1)[:, :, :3].astype(np.int32)


def frames(win, mapper, count):
    """Renders `count` frames; the mapper's draw times and last fraction."""
    times = []
    for _ in range(count):
        win.Render()
        times.append(mapper.GetLastDrawTime())
    return statistics.median(times), mapper.GetLastLineFraction()


def all_lines_differ(win, mapper, rate, still):
    """Renders at the desired update `rate`: the pixels that differ from the
    `still` picture, or -1 when the frame did not draw every line."""
    win.SetDesiredUpdateRate(rate)
    image = picture(win)
    if mapper.GetLastLineFraction() != 1.0:
        return -1
    return int(np.any(image != still, axis=2).sum())


def drawn(image):
    return np.any(image != 255, axis=2)


def holes(full, part, size=15):
    """The share of the size x size pixel blocks where `full` draws at least
    half of the pixels in which `part` draws less than a fifth as many: the
    holes a subset of the lines leaves in the picture."""
    count = hole = 0
    for y in range(0, H - size + 1, size):
        for x in range(0, W - size + 1, size):
            block = (slice(y, y + size), slice(x, x + size))
            covered = drawn(full)[block].mean()
            if covered >= 0.5:
                count += 1
                hole += drawn(part)[block].mean() < 0.2 * covered
    return hole / max(count, 1)


for name, cls in (("raycast", splineviz.vtkRayCastTubeMapper),
                  ("tessellated", splineviz.vtkTessellatedTubeMapper),
                  ("stylized", splineviz.vtkStylizedLineMapper)):
    mapper = cls()
    mapper.SetInputConnection(source.GetOutputPort())
    mapper.SetRadius(RADIUS)  # thin: the picture is not saturated
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(0.8, 0.3, 0.2)
    win, ren = offscreen_window(actor, (W, H))
    ren.ResetCamera()
    ren.GetActiveCamera().Azimuth(30)
    ren.ResetCameraClippingRange()

    win.SetDesiredUpdateRate(STILL)
    win.Render()  # the first frame: build, upload, compile
    still_time, still_fraction = frames(win, mapper, 3)
    still = picture(win, "%s-still" % name)
    core_time = mapper.GetTubeCore().GetMTime()
    check(still_fraction == 1.0, "%s: still frames draw every line (fraction %g)"
          % (name, still_fraction))

    mapper.SetInteractiveFrameTime(still_time / 3.0)
    win.SetDesiredUpdateRate(MOVING)
    frames(win, mapper, 3)  # the subset adapts to the budget
    moving_time, _ = frames(win, mapper, 3)
    moving = picture(win, "%s-moving" % name)
    fraction = mapper.GetLastLineFraction()  # of the picture's frame
    print("%s: %d lines, still frame %.3f s; moving (budget %.3f s): %.3f s, line fraction %.3f"
          % (name, lines, still_time, still_time / 3.0, moving_time, fraction))
    check(0.0005 <= fraction < 0.8,  # vtkSplineTubeMapper::MinimumLineFraction
          "%s: moving frames draw a subset (fraction %.3f)" % (name, fraction))
    check(moving_time < still_time, "%s: moving frames are shorter (%.3f s against %.3f s)"
          % (name, moving_time, still_time))
    check(mapper.GetTubeCore().GetMTime() == core_time,
          "%s: the subset builds and uploads nothing again" % name)
    check(drawn(moving).sum() < drawn(still).sum(),
          "%s: the subset draws fewer pixels (%d against %d)"
          % (name, drawn(moving).sum(), drawn(still).sum()))

    differ = all_lines_differ(win, mapper, STILL, still)
    check(differ == 0, "%s: when the camera stops, every line again (%d pixels differ from the "
          "still picture)" % (name, differ))

    # Negative control: no subset without InteractiveSubset.
    mapper.InteractiveSubsetOff()
    differ = all_lines_differ(win, mapper, MOVING, still)
    check(differ == 0, "%s: control, InteractiveSubset off: every line at the raised rate (%d "
          "pixels differ)" % (name, differ))
    # Spread: the subset leaves no holes where the lines are, unlike as many
    # lines of a few bundles (negative control: those whose first points lie
    # lowest along x, the bundles' axis order).
    one_side = vtkIdList()
    for i in np.argsort(starts)[:max(1, int(round(fraction * lines)))]:
        one_side.InsertNextId(int(i))
    first = vtkExtractCells()
    first.SetInputConnection(source.GetOutputPort())
    first.SetCellList(one_side)
    geometry = vtkGeometryFilter()
    geometry.SetInputConnection(first.GetOutputPort())
    mapper.SetInputConnection(geometry.GetOutputPort())
    mapper.InteractiveSubsetOn()
    win.SetDesiredUpdateRate(STILL)
    bundles = picture(win, "%s-few-bundles" % name)
    mapper.SetInputConnection(source.GetOutputPort())
    subset_holes, control_holes = holes(still, moving), holes(still, bundles)
    check(control_holes >= 0.02 and subset_holes <= 0.5 * control_holes,
          "%s: the subset is spread over the picture: %.1f %% of the blocks are holes (%d lines "
          "of a few bundles, the control: %.1f %%)"
          % (name, 100 * subset_holes, one_side.GetNumberOfIds(), 100 * control_holes))
    del win, ren, actor, mapper

checker.finish()
print("all passed")
