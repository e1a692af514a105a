# SPDX-License-Identifier: BSD-3-Clause
"""Scene of TestParallelTractogram (run by pvbatch, serially or under
mpiexec): the test's .tck drawn as ray-cast tubes (all streamlines, then a
random half), composited by IceT; saves the screenshots, and each rank writes
its piece's cell count and the bytes its reader read (a Programmable Filter
runs on every rank and asks the rank's reader upstream).

    pvbatch TestParallelTractogramScene.py OUTPUT_DIR LABEL
"""
import os
import sys

from paraview.simple import *  # noqa: F401,F403

from splineviz_testing import white_view

out, label = sys.argv[1], sys.argv[2]
# LABEL ending in "-damaged": the file damaged in the second rank's half,
# all streamlines only.
damaged = label.endswith("-damaged")
reader = OpenDataFile(os.path.join(out, "tracts-damaged.tck" if damaged else "tracts.tck"))  # noqa: F405
shares = ProgrammableFilter(Input=reader)  # noqa: F405
SCRIPT = """
import json
import splineviz  # the reader's Python type (GetLastBytesRead)
from vtkmodules.vtkParallelCore import vtkMultiProcessController
controller = vtkMultiProcessController.GetGlobalController()
rank = controller.GetLocalProcessId() if controller else 0
source = self.GetInputAlgorithm(0, 0)
while not hasattr(source, "GetLastBytesRead"):  # past ParaView's post filter
    source = source.GetInputAlgorithm(0, 0)
data = self.GetInput()
with open(r"PREFIX-rank%d.json" % rank, "w") as f:
    json.dump({"rank": rank, "cells": data.GetNumberOfCells(), "points": data.GetNumberOfPoints(),
               "bytes": source.GetLastBytesRead()}, f)
self.GetOutput().ShallowCopy(data)
"""

view = white_view((500, 400))
for subset in ("all",) if damaged else ("all", "half"):
    if subset == "half":
        reader.SubsetMode = "Random Fraction"
        reader.SubsetFraction = 0.5
        reader.SubsetSeed = 3
    shares.Script = SCRIPT.replace("PREFIX", os.path.join(out, "shares-%s-%s" % (label, subset)))
    shares.UpdatePipeline()
    display = Show(reader, view)  # noqa: F405
    display.SetRepresentationType("Ray-Cast Tubes")
    display.TubeRadius = 0.6
    display.AmbientColor = display.DiffuseColor = [0.8, 0.35, 0.2]
    Render(view)  # noqa: F405
    # the same camera whatever the number of ranks (set after the first render's reset)
    view.CameraPosition = [180, -210, 155]
    view.CameraFocalPoint = [0, 0, 0]
    view.CameraViewUp = [0, 0, 1]
    view.CameraViewAngle = 30
    Render(view)  # noqa: F405
    SaveScreenshot(os.path.join(out, "%s-%s.png" % (label, subset)), view,  # noqa: F405
                   ImageResolution=[500, 400])
