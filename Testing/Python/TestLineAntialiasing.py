# SPDX-License-Identifier: BSD-3-Clause
"""Sub-pixel lines stay visible and are antialiased by the renderer's FXAA.

The fibres of vtkSyntheticFibersSource with a radius far below a pixel
(MinimumPixelWidth 1, the default: drawn one pixel wide) are drawn in black
on white by each line renderer, multisampling off, once without and once
with the renderer's FXAA (vtkRenderer::UseFXAA; ParaView's views have it on
by default). VTK's plain lines (vtkPolyDataMapper) are drawn the same way as
the reference. Checks, for each renderer:
- without FXAA, every drawn pixel is fully black or white (no antialiasing:
  the negative control), and the lines cover at least 90 % of the pixels
  VTK's lines cover;
- with FXAA, at least half of the drawn pixels are partly covered (grey:
  between 20 and 235), and 99 % of the pixels drawn without FXAA are still
  drawn (FXAA smooths the lines' edges, it does not erase them).
"""

import numpy as np
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the OpenGL factory)

import splineviz
from splineviz_testing import Checker, offscreen_window, output_dir, save_window

checker = Checker()
check = checker.check
out = output_dir()

W, H = 400, 400
source = splineviz.vtkSyntheticFibersSource()
source.Update()


def draw(mapper, fxaa, name):
    """The darkest channel of each pixel (0 black line, 255 white background)."""
    mapper.SetInputConnection(source.GetOutputPort())
    mapper.ScalarVisibilityOff()
    actor = vtkActor()
    actor.SetMapper(mapper)
    prop = actor.GetProperty()
    prop.SetColor(0, 0, 0)
    prop.SetAmbient(1.0)
    prop.SetDiffuse(0.0)
    prop.SetSpecular(0.0)
    window, renderer = offscreen_window(actor, (W, H))
    renderer.SetUseFXAA(fxaa)
    renderer.ResetCamera()
    window.Render()
    rgb = save_window(window, "%s/TestLineAntialiasing-%s.png" % (out, name))
    return rgb.min(axis=2).ravel()


lines = draw(vtkPolyDataMapper(), 0, "vtk-lines")
lines_drawn = lines < 255
check(np.count_nonzero(lines_drawn) > 2000, "VTK's lines draw %d pixels"
      % np.count_nonzero(lines_drawn))

for name in ("vtkRayCastTubeMapper", "vtkTessellatedTubeMapper", "vtkStylizedLineMapper"):
    def mapper():
        m = getattr(splineviz, name)()
        m.SetRadius(0.0005)  # a fifth of a pixel here
        return m

    plain = draw(mapper(), 0, name + "-plain")
    smooth = draw(mapper(), 1, name + "-fxaa")
    drawn = plain < 255
    grey = np.count_nonzero((plain > 20) & (plain < 235))
    check(grey == 0, "%s without FXAA: %d grey pixels (no antialiasing expected)" % (name, grey))
    covered = np.count_nonzero(drawn & lines_drawn) / np.count_nonzero(lines_drawn)
    check(covered >= 0.9, "%s without FXAA covers %.3f of VTK's lines' pixels" % (name, covered))
    smooth_drawn = smooth < 255
    partial = np.count_nonzero((smooth > 20) & (smooth < 235)) / max(1, np.count_nonzero(smooth_drawn))
    kept = np.count_nonzero(drawn & smooth_drawn) / max(1, np.count_nonzero(drawn))
    check(partial >= 0.5, "%s with FXAA: %.2f of the drawn pixels are grey" % (name, partial))
    check(kept >= 0.99, "%s with FXAA: %.4f of the lines' pixels still drawn" % (name, kept))

checker.finish()
