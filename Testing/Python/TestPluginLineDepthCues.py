# SPDX-License-Identifier: BSD-3-Clause
"""pvbatch: the SplineViz plugin's "Render View (Line Depth Cues)" view
(vtkPVRenderViewWithLineDepthCues, with vtkLineAmbientOcclusionPass as its
image processing pass) on the synthetic fibers drawn as Ray-Cast Tubes,
against ParaView's plain render view of the same scene:
- cues off: the same image as the plain render view;
- cues on with Occlusion Strength 0 (negative control of the pass's own
  copy): the same image too;
- ambient occlusion on: no pixel brighter, a share of the tubes' pixels
  darker (the crevices between crossing tubes; 5 % of them in this sparse
  scene), the background untouched, and fewer darker with a smaller radius;
- halos on (occlusion off): pixels of farther tubes next to nearer ones take
  the background color (or, at a halo's soft edge, blend toward it), none
  gets darker;
Both views without FXAA: ParaView does not apply it on top of an image
processing pass.
The pass itself is checked against a quadrature of its estimator in
TestLineAmbientOcclusion."""
import sys

import numpy as np
from paraview.simple import *  # noqa: F401,F403

import splineviz  # noqa: F401  (Python wrappers of the SplineViz classes)
from splineviz_testing import Checker, fibers_scene, output_dir, png_rgb

LoadPlugin(sys.argv[1], remote=False, ns=globals())
checker = Checker()
check = checker.check

fibers, plain, display = fibers_scene(globals())
display.SetRepresentationType("Ray-Cast Tubes")

cues = CreateView("RenderViewWithLineDepthCues")
# ParaView applies FXAA only without an image processing pass (with IceT, as
# in pvbatch); compare both views without it.
plain.UseFXAA = 0
for name in ("ViewSize", "Background", "UseColorPaletteForBackground",
             "OrientationAxesVisibility", "UseFXAA"):
    setattr(cues, name, getattr(plain, name))
cue_display = Show(fibers, cues)
cue_display.SetRepresentationType("Ray-Cast Tubes")
ColorBy(cue_display, ("POINTS", "Scalar"))
for name in ("CameraPosition", "CameraFocalPoint", "CameraViewUp", "CameraViewAngle"):
    setattr(cues, name, getattr(plain, name))
Render(plain)
cues.CameraParallelScale = plain.CameraParallelScale


def image(view, name):
    png = output_dir() + "/" + name
    SaveScreenshot(png, view, ImageResolution=list(view.ViewSize))
    return png_rgb(png)


reference = image(plain, "TestPluginLineDepthCues-plain.png")
background = np.all(reference == 255, axis=2)
tubes = ~background
print("tube pixels: %d of %d" % (tubes.sum(), tubes.size))
check(tubes.mean() > 0.1, "the plain view drew the tubes (%.3f covered)" % tubes.mean())



def check_unchanged(name, what):
    """The view's image `name` is the plain view's, within 1/255."""
    diff = np.abs(image(cues, name) - reference).max()
    check(diff <= 1, "%s: the plain view's image (largest difference %d)" % (what, diff))


cues.UseLineDepthCues = 0
check_unchanged("TestPluginLineDepthCues-off.png", "cues off")
cues.UseLineDepthCues = 1
cues.OcclusionStrength = 0.0
check_unchanged("TestPluginLineDepthCues-strength0.png", "cues on, strength 0")

cues.OcclusionStrength = 2.0
cues.OcclusionRadius = 24.0
occluded = image(cues, "TestPluginLineDepthCues-occlusion.png")
change = reference.sum(axis=2) - occluded.sum(axis=2)  # > 0: darker
darker = (change > 9) & tubes
print("ambient occlusion: %.1f %% of the tube pixels darker by more than 3/255 per "
      "channel, mean darkening %.1f, largest brightening %d, background changed %d"
      % (100.0 * darker.sum() / tubes.sum(), change[tubes].mean() / 3.0,
         max(0, -change.min()), int(np.count_nonzero(change[background]))))
check(-change.min() <= 3, "ambient occlusion only darkens (brightening %d)" % -change.min())
check(darker.sum() > 0.02 * tubes.sum(),
      "ambient occlusion darkens the crevices (%d pixels)" % darker.sum())
check(np.count_nonzero(change[background]) == 0, "the background is not darkened")
# The properties reach the pass: a smaller radius darkens less.
cues.OcclusionRadius = 6.0
small = image(cues, "TestPluginLineDepthCues-occlusion-radius6.png")
darker_small = ((reference.sum(axis=2) - small.sum(axis=2)) > 9) & tubes
print("radius 6: %d pixels darker (radius 24: %d)" % (darker_small.sum(), darker.sum()))
check(darker_small.sum() < 0.8 * darker.sum(), "the occlusion radius reaches the pass")

cues.AmbientOcclusion = 0
cues.DepthHalos = 1
cues.HaloWidth = 6.0
haloed = image(cues, "TestPluginLineDepthCues-halos.png")
now_background = np.all(haloed == 255, axis=2) & tubes
# A halo's soft edge mixes the color with the (white) background: lighter
# in every channel, never darker.
darkened = (haloed < reference - 1).any(axis=2)
print("halos: %d tube pixels became background, %d partly; %d darkened"
      % (now_background.sum(), int(((haloed > reference + 1).any(axis=2) & ~now_background).sum()),
         darkened.sum()))
check(now_background.sum() > 0.02 * tubes.sum(),
      "halos cut the tubes behind (%d pixels)" % now_background.sum())
check(darkened.sum() == 0, "halos only blend toward the background (%d darkened)" % darkened.sum())
check(np.count_nonzero(np.any(haloed != 255, axis=2) & background) == 0,
      "halos never cover the background with anything else")
checker.finish()
