# SPDX-License-Identifier: BSD-3-Clause
"""The slab crop (SlabOrigin, SlabNormal, SlabThickness) of the three line
renderers, checked through the depth buffer.

A synthetic tractogram (600 streamlines) is drawn by each renderer with a
perspective camera, once whole and once cropped to an oblique slab through its
centre, multisampling off. Every drawn pixel is taken back to world
coordinates from its depth (the inverse of the camera's projection, written
here with numpy). Checks:
- every pixel drawn with the crop lies in the slab (distance to the mid-plane
  at most half the thickness plus a thousandth of it, for depth precision);
- every pixel of the whole drawing whose surface point lies well inside the
  slab (a tube radius from its faces) is drawn with the crop too (at least
  99.5 %: the surface in front of it may have been cut away, the surface
  itself never is);
- negative control: at least 30 % of the whole drawing lies outside the slab;
- a zero normal is an error and draws the whole lines.
"""

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkFloatArray
from vtkmodules.vtkRenderingCore import vtkActor
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the OpenGL factory)

import splineviz
from splineviz_testing import Observed, offscreen_window, output_dir

from splineviz_testing import Checker  # noqa: E402

checker = Checker()


check = checker.check


W, H = 500, 400
source = splineviz.vtkSyntheticTractogramSource()
source.SetNumberOfStreamlines(600)
source.SetSeed(3)
source.Update()
bounds = np.array(source.GetOutput().GetBounds())
centre = 0.5 * (bounds[0::2] + bounds[1::2])
extent = float(np.linalg.norm(bounds[1::2] - bounds[0::2]))
normal = np.array([0.3, -0.25, 0.92])
normal /= np.linalg.norm(normal)
thickness = 0.12 * extent
radius = 0.002 * extent


def draw(cls, crop, normal_vector=normal):
    mapper = cls()
    mapper.SetInputConnection(source.GetOutputPort())
    mapper.SetRadius(radius)
    if crop:
        mapper.SetSlabOrigin(*centre)
        mapper.SetSlabNormal(*normal_vector)
        mapper.SetSlabThickness(thickness)
    actor = vtkActor()
    actor.SetMapper(mapper)
    win, ren = offscreen_window(actor, (W, H))
    cam = ren.GetActiveCamera()
    cam.SetFocalPoint(*centre)
    cam.SetPosition(*(centre + np.array([0.9, -1.3, 0.6]) * extent))
    cam.SetViewUp(0, 0, 1)
    ren.ResetCameraClippingRange(*bounds)
    observed = Observed(mapper)
    win.Render()
    z = vtkFloatArray()
    win.GetZbufferData(0, 0, W - 1, H - 1, z)
    depth = vtk_to_numpy(z).reshape(H, W)
    # World positions of the drawn pixels.
    m = cam.GetCompositeProjectionTransformMatrix(W / H, -1, 1)
    world_to_ndc = np.array([[m.GetElement(r, c) for c in range(4)] for r in range(4)])
    rows, cols = np.nonzero(depth < 1.0)
    ndc = np.stack([2.0 * (cols + 0.5) / W - 1.0, 2.0 * (rows + 0.5) / H - 1.0,
                    2.0 * depth[rows, cols] - 1.0, np.ones(len(rows))])
    p = np.linalg.solve(world_to_ndc, ndc)
    world = (p[:3] / p[3]).T
    distance = np.full((H, W), np.nan)
    distance[rows, cols] = (world - centre) @ normal
    return distance, observed


for name, cls in (("raycast", splineviz.vtkRayCastTubeMapper),
                  ("tessellated", splineviz.vtkTessellatedTubeMapper),
                  ("stylized", splineviz.vtkStylizedLineMapper)):
    whole, _ = draw(cls, False)
    cropped, _ = draw(cls, True)
    drawn_whole = ~np.isnan(whole)
    drawn_cropped = ~np.isnan(cropped)
    check(drawn_cropped.sum() > 2000, "%s: %d pixels drawn with the crop" % (name, drawn_cropped.sum()))
    outside = np.abs(cropped[drawn_cropped]) > 0.5 * thickness * 1.001
    check(outside.sum() == 0, "%s: %d cropped pixels outside the slab (largest distance %.4f of the "
          "half thickness)" % (name, outside.sum(), np.nanmax(np.abs(cropped)) / (0.5 * thickness)))
    inner = drawn_whole & (np.abs(np.nan_to_num(whole, nan=1e30)) < 0.5 * thickness - 2 * radius)
    kept = (inner & drawn_cropped).sum() / max(inner.sum(), 1)
    check(kept >= 0.995, "%s: %.2f %% of the whole drawing's pixels inside the slab are drawn"
          % (name, 100 * kept))
    control = (np.abs(whole[drawn_whole]) > 0.5 * thickness).mean()
    check(control > 0.3, "%s: control, %.0f %% of the whole drawing lies outside the slab"
          % (name, 100 * control))
    zero, observed = draw(cls, True, normal_vector=np.zeros(3))
    check(len(observed.errors) > 0 and (~np.isnan(zero)).sum() == drawn_whole.sum(),
          "%s: a zero normal is an error and draws the whole lines" % name)

checker.finish()
