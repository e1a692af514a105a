# SPDX-License-Identifier: BSD-3-Clause
"""ParaView demo state: streamlines traced on an LR-spline vector field and
shown as tubes.

    pvpython Examples/Python/lr_spline_streamlines_state.py [output.png]
    (or in the ParaView GUI: View > Python Shell > Run Script)

Reads the real LR-spline volume cube-3patch-refined.lr with the LR-Spline
Volume Reader, takes its patch 1 (the field v = (-y, x, z)), traces
streamlines with the LR-Spline Stream Tracer (RKF45, adaptive) from a line of
seeds and shows them as SplineViz "Ray-Cast Tubes" (radius from Speed) when
that representation is available, otherwise with ParaView's Tube filter,
together with the spline's LR mesh.
"""
import os
import sys

from paraview.simple import *  # noqa: F401,F403

try:
    # Loads SplineVizPlugin unless ParaView did at start-up (PV_PLUGIN_PATH).
    from splineviz.plugin import load_plugin

    load_plugin(globals())
except (ImportError, RuntimeError) as error:
    print("SplineViz plugin not loaded (%s): ParaView's own filters only" % error)

here = os.path.dirname(os.path.abspath(__file__))
data = os.path.join(here, "..", "..", "Testing", "Data", "External", "cube-3patch-refined.lr")
reader = OpenDataFile(data)  # noqa: F405  (the LR-Spline Volume Reader)
patch = ExtractBlock(Input=reader)  # noqa: F405
patch.Selectors = ["/Root/Patch1"]

tracer = LRSplineStreamTracer(Input=patch, SeedType="Line")  # noqa: F405
tracer.SeedType.Point1 = [0.2, 0.03, 0.04]
tracer.SeedType.Point2 = [0.95, 0.03, 0.22]
tracer.SeedType.Resolution = 15
tracer.IntegratorType = "RKF45"
tracer.StepMode = "Adaptive (embedded methods)"
tracer.MaximumError = 1e-7
tracer.MaximumIntegrationStep = 0.02

view = CreateRenderView()  # noqa: F405
view.ViewSize = [800, 600]
view.OrientationAxesVisibility = 0
mesh = Show(patch, view)  # noqa: F405
mesh.SetRepresentationType("Wireframe")
mesh.Opacity = 0.2
mesh.ColorArrayName = [None, ""]

lines = Show(tracer, view)  # noqa: F405
available = lines.GetProperty("Representation").Available if hasattr(
    lines.GetProperty("Representation"), "Available") else []
if "Ray-Cast Tubes" in available:
    lines.SetRepresentationType("Ray-Cast Tubes")
    lines.TubeRadiusArray = "Speed"
    lines.TubeRadiusScale = 0.01
    shown = lines
else:
    Hide(tracer, view)  # noqa: F405
    tubes = Tube(Input=tracer)  # noqa: F405
    tubes.Scalars = ["POINTS", "Speed"]
    tubes.VaryRadius = "By Scalar"
    tubes.Radius = 0.006
    tubes.RadiusFactor = 2.5
    tubes.NumberofSides = 16
    shown = Show(tubes, view)  # noqa: F405
ColorBy(shown, ("POINTS", "Speed"))  # noqa: F405
shown.RescaleTransferFunctionToDataRange(True)

view.CameraPosition = [2.4, -1.6, 1.9]
view.CameraFocalPoint = [0.45, 0.45, 0.4]
view.CameraViewUp = [0, 0, 1]
ResetCamera(view)  # noqa: F405
Render(view)  # noqa: F405
if len(sys.argv) > 1:
    SaveScreenshot(sys.argv[1], view, ImageResolution=[800, 600])  # noqa: F405
    print("wrote", sys.argv[1])
