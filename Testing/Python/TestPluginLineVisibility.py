# SPDX-License-Identifier: BSD-3-Clause
"""pvbatch: the line representations' Visibility Array.

SyntheticFibers with a cell array "Selected" made by ParaView's Calculator
(1 for the lines with TubeId above a threshold, else 0) is drawn by each line
representation ("Ray-Cast Tubes", "Tessellated Tubes", "Stylized Lines") with
Visibility Array = Selected, and compared with the same representation of
ParaView's Threshold of the selected lines (extracted as polylines): at most 0.05 % of
the drawn pixels may differ by more than 8/255 in a channel (the two place
the uploaded coordinates around different centres, so float rounding shades
a few hundred pixels by 1-6 levels and flips a few edge pixels; the Python
test TestLineVisibility, which keeps the centres equal, checks exact
equality).
Then the selection changes (the Calculator's function: the other lines) and
the image follows. Negative controls: Visibility Array None, and the old
selection's reference, differ in many pixels. Last, Direction Coloring
shows lines of each direction in its own channel.
"""
import sys

import numpy as np

from paraview.simple import *  # noqa: F401,F403
from splineviz_testing import output_dir, png_rgb, white_view

LoadPlugin(sys.argv[1], remote=False, ns=globals())
out = output_dir()
from splineviz_testing import Checker  # noqa: E402

checker = Checker()


check = checker.check


fibers = SyntheticFibers(Preset=1)
fibers.UpdatePipeline()
tubes = int(fibers.GetCellDataInformation().GetArray("TubeId").GetRange()[1]) + 1
half = tubes // 2
calc = Calculator(Input=fibers, AttributeType="Cell Data", ResultArrayName="Selected",
                  ResultArrayType="Unsigned Char")


def select_above(threshold):
    # 1 where TubeId > threshold, else 0.
    calc.Function = "(sign(TubeId - %g) + 1) / 2" % (threshold + 0.5)


def reference_source(lower, upper):
    threshold = Threshold(Input=fibers, Scalars=["CELLS", "TubeId"], LowerThreshold=lower,
                          UpperThreshold=upper)
    return ExtractSurface(Input=threshold)


def draw(source, representation, name, visibility=None):
    view = white_view((500, 400))
    view.CameraPosition = [0.3, 0.2, 2.2]
    view.CameraFocalPoint = [0, 0, 0]
    view.CameraViewUp = [0, 1, 0]
    display = Show(source, view)
    display.Representation = representation
    display.TubeRadius = 0.008
    ColorBy(display, None)
    display.AmbientColor = display.DiffuseColor = [0.8, 0.3, 0.2]
    if visibility:
        display.VisibilityArray = visibility
    png = "%s/TestPluginLineVisibility-%s.png" % (out, name)
    SaveScreenshot(png, view, ImageResolution=[500, 400])
    Delete(display)
    Delete(view)
    return png_rgb(png)


def differing(a, b):
    return int(np.count_nonzero(np.abs(a - b).max(axis=2) > 8))


for representation in ("Ray-Cast Tubes", "Tessellated Tubes", "Stylized Lines"):
    key = representation.split()[0].lower()
    select_above(half)
    upper = reference_source(half + 1, tubes)
    lower = reference_source(0, half)
    selected = draw(calc, representation, key + "-upper", "Selected")
    reference = draw(upper, representation, key + "-upper-reference")
    drawn = int(np.count_nonzero(np.any(reference != 255, axis=2)))
    diff = differing(selected, reference)
    check(drawn > 5000, "%s: the reference draws %d pixels" % (representation, drawn))
    check(diff <= 0.0005 * drawn, "%s: %d pixels differ from the selected lines alone"
          % (representation, diff))
    everything = draw(calc, representation, key + "-all")
    check(differing(everything, reference) > 0.1 * drawn,
          "%s: control, all lines differ in %d pixels"
          % (representation, differing(everything, reference)))
    # A new selection: the other half.
    calc.Function = "1 - (sign(TubeId - %g) + 1) / 2" % (half + 0.5)
    changed = draw(calc, representation, key + "-lower", "Selected")
    lower_reference = draw(lower, representation, key + "-lower-reference")
    diff = differing(changed, lower_reference)
    check(diff <= 0.0005 * drawn, "%s: after the change %d pixels differ from the new selection"
          % (representation, diff))
    check(differing(changed, reference) > 0.2 * drawn,
          "%s: control, the old selection differs in %d pixels"
          % (representation, differing(changed, reference)))

# Direction Coloring: the representation passes it on (the colors against the
# analytic tangent are checked by TestDirectionColoring): lines of every
# direction show in their dominant channel.
view = white_view((500, 400))
display = Show(fibers, view)
display.Representation = "Ray-Cast Tubes"
display.DirectionColoring = 1
ResetCamera(view)
png = "%s/TestPluginLineVisibility-direction.png" % out
SaveScreenshot(png, view, ImageResolution=[500, 400])
rgb = png_rgb(png).reshape(-1, 3)
drawn = rgb[np.any(rgb != 255, axis=1)]
dominant = [int(np.count_nonzero((drawn[:, c] > 1.6 * np.delete(drawn, c, axis=1).max(axis=1))))
            for c in range(3)]
check(min(dominant) > 200, "Direction Coloring: pixels dominated by red, green, blue: %s" % dominant)

# Slab crop: the representation passes it on (the crop itself is checked by
# TestSlabCrop): a thin slab draws a fraction of the lines' pixels.
display.DirectionColoring = 0
display.SlabOrigin = [0, 0, 0]
display.SlabNormal = [0, 0, 1]
png_whole = "%s/TestPluginLineVisibility-slab-whole.png" % out
SaveScreenshot(png_whole, view, ImageResolution=[500, 400])
display.SlabThickness = 0.1
png_slab = "%s/TestPluginLineVisibility-slab.png" % out
SaveScreenshot(png_slab, view, ImageResolution=[500, 400])
whole = int(np.count_nonzero(np.any(png_rgb(png_whole) != 255, axis=2)))
slab = int(np.count_nonzero(np.any(png_rgb(png_slab) != 255, axis=2)))
check(0 < slab < 0.5 * whole, "Slab Thickness 0.1: %d of %d pixels drawn" % (slab, whole))

# The slab tied to a Slice (splineviz.slab): the representation's slab follows
# the slice plane, and draws what the same slab set by hand draws; after
# untie_slab it stays where it was. Negative control: the slab at the old
# plane differs.
from splineviz.slab import tie_slab_to_slice, untie_slab  # noqa: E402

anatomy = Wavelet(WholeExtent=[-10, 10, -10, 10, -10, 10])
anatomy_slice = Slice(Input=anatomy)
anatomy_slice.SliceType = "Plane"
anatomy_slice.SliceType.Origin = [0, 0, 0]
anatomy_slice.SliceType.Normal = [0, 0, 1]
display.SlabThickness = 0.0
names = tie_slab_to_slice(display, anatomy_slice, thickness=0.1)
check(list(display.SlabOrigin) == [0, 0, 0] and list(display.SlabNormal) == [0, 0, 1]
      and display.SlabThickness == 0.1, "tied: the slab takes the slice's plane")
manager = servermanager.ProxyManager()
check(all(manager.GetRegisteredLink(n) is not None for n in names),
      "tied: the links are registered (%s)" % names)
anatomy_slice.SliceType.Origin = [0, 0, 0.15]
anatomy_slice.SliceType.Normal = [0, 0.6, 0.8]
check(np.allclose(display.SlabOrigin, [0, 0, 0.15]) and
      np.allclose(display.SlabNormal, [0, 0.6, 0.8]),
      "tied: the slab follows the moved slice (%s, %s)"
      % (list(display.SlabOrigin), list(display.SlabNormal)))
png_tied = "%s/TestPluginLineVisibility-slab-tied.png" % out
SaveScreenshot(png_tied, view, ImageResolution=[500, 400])
state = "%s/TestPluginLineVisibility-slab.pvsm" % out
SaveState(state)
with open(state) as f:
    saved = f.read()
check(all('name="%s"' % n in saved for n in names), "tied: the links are saved in the state")
untie_slab(names)
check(all(manager.GetRegisteredLink(n) is None for n in names), "untied: no links left")
anatomy_slice.SliceType.Origin = [0, 0, -0.3]
check(np.allclose(display.SlabOrigin, [0, 0, 0.15]), "untied: the slab stays (%s)"
      % list(display.SlabOrigin))
display.SlabOrigin = [0, 0, 0]
display.SlabNormal = [0, 0, 1]
png_old = "%s/TestPluginLineVisibility-slab-old.png" % out
SaveScreenshot(png_old, view, ImageResolution=[500, 400])
display.SlabOrigin = [0, 0, 0.15]
display.SlabNormal = [0, 0.6, 0.8]
png_hand = "%s/TestPluginLineVisibility-slab-hand.png" % out
SaveScreenshot(png_hand, view, ImageResolution=[500, 400])
tied = png_rgb(png_tied)
tied_drawn = int(np.count_nonzero(np.any(tied != 255, axis=2)))
check(tied_drawn > 200 and differing(tied, png_rgb(png_hand)) == 0,
      "tied slab: %d pixels drawn, %d differ from the slab set by hand"
      % (tied_drawn, differing(tied, png_rgb(png_hand))))
check(differing(tied, png_rgb(png_old)) > 100,
      "control: the slab at the old plane differs in %d pixels"
      % differing(tied, png_rgb(png_old)))
try:
    tie_slab_to_slice(display, anatomy)
    check(False, "a source without a plane is refused")
except ValueError as error:
    check("plane" in str(error), "a source without a plane: %s" % error)

checker.finish()
