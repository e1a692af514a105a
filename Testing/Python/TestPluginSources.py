# SPDX-License-Identifier: BSD-3-Clause
"""pvbatch: load the SplineViz plugin and use its sources in a ParaView
pipeline, render and check the image shows them."""
import sys

from paraview.simple import *  # noqa: F401,F403
from splineviz_testing import coverage, white_view

plugin = sys.argv[1]
LoadPlugin(plugin, remote=False, ns=globals())

fibers = SyntheticFibers(Preset=1)  # noqa: F405
fibers.UpdatePipeline()
info = fibers.GetDataInformation()
assert info.GetNumberOfCells() == 241, info.GetNumberOfCells()
assert info.GetNumberOfPoints() == 3771, info.GetNumberOfPoints()

view = white_view((400, 300))
display = Show(fibers, view)  # noqa: F405
ColorBy(display, ("POINTS", "Scalar"))  # noqa: F405
ResetCamera(view)  # noqa: F405
Render(view)  # noqa: F405

fraction, _ = coverage(view, "TestPluginSources.png", stride=7)
print("fraction of non-background pixels:", fraction)
if fraction < 0.02:
    print("ERROR: the plugin's fibers did not render")
    sys.exit(1)
