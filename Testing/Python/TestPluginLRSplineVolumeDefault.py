# SPDX-License-Identifier: BSD-3-Clause
"""pvbatch: the first picture of a new user. cube-3patch-refined.lr opened
with defaults and shown as "LR-Spline Volume" must be coloured like
ParaView's own "Volume" representation colours a new data set: the first
field through ParaView's default color map and opacity ramp over its range.

Checks: the default picture is drawn and coloured (saturated pixels of many
hues, not a grey fog); it equals, to an RMS of 1/255, the picture with the
field chosen explicitly (ColorBy Field, Magnitude) and ParaView's default
transfer functions rescaled to its range -- the colouring ParaView would
give; negative control: the same picture with a grey color map fails the
colour check, so the check tells grey from coloured."""
import os
import sys

import numpy as np

from paraview.simple import *  # noqa: F401,F403
from splineviz_testing import output_dir, png_rgb, white_view

plugin = sys.argv[1]
LoadPlugin(plugin, remote=False, ns=globals())
path = os.path.join(os.environ["SPLINEVIZ_SOURCE_DIR"], "Testing", "Data", "External",
                    "cube-3patch-refined.lr")
from splineviz_testing import Checker  # noqa: E402

checker = Checker()


fail = checker.fail


def picture(view, name):
    png = os.path.join(output_dir(), "TestPluginLRSplineVolumeDefault-%s.png" % name)
    SaveScreenshot(png, view, ImageResolution=[400, 320])  # noqa: F405
    return png, png_rgb(png)


def colour_measures(rgb):
    """Drawn fraction, saturated fraction of the drawn pixels, hues seen (of 12)."""
    px = rgb.reshape(-1, 3).astype(float)
    drawn = np.abs(px - 255).max(axis=1) > 2
    spread = px.max(axis=1) - px.min(axis=1)
    saturated = drawn & (spread > 30)
    hues = set()
    for r, g, b in px[saturated][::7]:
        mx, mn = max(r, g, b), min(r, g, b)
        h = (0 if mx == mn else (60 * ((g - b) / (mx - mn)) % 360 if mx == r else
                                 60 * ((b - r) / (mx - mn)) + 120 if mx == g else
                                 60 * ((r - g) / (mx - mn)) + 240))
        hues.add(int(h // 30))
    return drawn.mean(), saturated.sum() / max(drawn.sum(), 1), len(hues)


def coloured(label, rgb):
    d, s, h = colour_measures(rgb)
    print("%s: %.3f of the view drawn, %.3f of it saturated, %d hue sectors" % (label, d, s, h))
    return d > 0.1 and s > 0.3 and h >= 2  # a colour map: more than one hue


reader = OpenDataFile(path)  # noqa: F405
view = white_view((400, 320))
view.UseFXAA = 0
display = Show(reader, view)  # noqa: F405
display.SetRepresentationType("LR-Spline Volume")
Render(view)  # noqa: F405
png, default = picture(view, "default")
if not coloured("defaults", default):
    fail("the default LR-Spline Volume picture is not coloured (%s)" % png)

# What ParaView gives when the field is chosen: its default color and opacity
# maps rescaled to the field's range.
ColorBy(display, ("POINTS", "Field", "Magnitude"))  # noqa: F405
lut = GetColorTransferFunction("Field")  # noqa: F405
lut.Discretize = 0  # the mapper samples continuous transfer functions
display.RescaleTransferFunctionToDataRange(False, True)
Render(view)  # noqa: F405
png2, explicit = picture(view, "explicit")
rms = float(np.sqrt(((default.astype(float) - explicit.astype(float)) ** 2).mean()))
print("default against ParaView's colouring of the first field: RMS %.3f / 255" % rms)
if rms > 1.0:
    fail("the default picture differs from ParaView's colouring of the first field (RMS %.2f)"
         % rms)

# Negative control: a grey map is not taken for a coloured picture.
lut.ApplyPreset("Grayscale", True)
Render(view)  # noqa: F405
png3, grey = picture(view, "grey")
if coloured("grey color map (negative control)", grey):
    fail("the colour check takes a grey picture for a coloured one")

checker.finish()
