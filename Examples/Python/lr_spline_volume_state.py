# SPDX-License-Identifier: BSD-3-Clause
"""ParaView demo state: an LR-spline vector field volume rendered as it is
(no resampling) with streamlines of the same field as tubes inside it.

    pvpython Examples/Python/lr_spline_volume_state.py [output.png]
    (or in the ParaView GUI: View > Python Shell > Run Script)

Reads the real LR-spline volume cube-3patch-refined.lr with the LR-Spline
Volume Reader, takes its patch 1 (the field v = (-y, x, z) on 1240 locally
refined elements) and shows its magnitude with the SplineViz "LR-Spline
Volume" representation (vtkLRSplineVolumeMapper ray casts the Bezier
elements; adaptive steps), trimmed by a sphere; streamlines of the same
patch, traced by the LR-Spline Stream Tracer, are "Ray-Cast Tubes" inside
the volume (the rays stop at the tubes). Without the plugin's
representations it falls back to LR-Spline Resample To Image + ParaView's
"Volume" and the Tube filter.
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

view = CreateRenderView()  # noqa: F405
view.ViewSize = [800, 600]
view.OrientationAxesVisibility = 0
view.UseColorPaletteForBackground = 0
view.Background = [1, 1, 1]

# The volume: |v| through a color map and an opacity ramp.
volume = Show(patch, view)  # noqa: F405
if "LR-Spline Volume" in volume.GetProperty("Representation").Available:
    volume.SetRepresentationType("LR-Spline Volume")
    # Only the inside of a sphere (any closed surface, e.g. an STL file).
    volume.TrimmingSurface = Sphere(Center=[0.5, 0.5, 0.5], Radius=0.5,  # noqa: F405
                                    ThetaResolution=64, PhiResolution=64)
else:
    Hide(patch, view)  # noqa: F405
    image = LRSplineResampleToImage(Input=patch, SamplingDimensions=[128, 128, 128])  # noqa: F405
    volume = Show(image, view)  # noqa: F405
    volume.SetRepresentationType("Volume")
ColorBy(volume, ("POINTS", "Field", "Magnitude"))  # noqa: F405
field = GetColorTransferFunction("Field")  # noqa: F405
field.ApplyPreset("Viridis (matplotlib)", True)
field.RescaleTransferFunction(0.0, 1.75)
opacity = GetOpacityTransferFunction("Field")  # noqa: F405
opacity.Points = [0.0, 0.0, 0.5, 0.0, 0.6, 0.0, 0.5, 0.0, 1.75, 0.6, 0.5, 0.0]
opacity.RescaleTransferFunction(0.0, 1.75)
volume.ScalarOpacityUnitDistance = 0.25

# Streamlines of the same field, as tubes.
tracer = LRSplineStreamTracer(Input=patch, SeedType="Line")  # noqa: F405
tracer.SeedType.Point1 = [0.2, 0.03, 0.04]
tracer.SeedType.Point2 = [0.95, 0.03, 0.22]
tracer.SeedType.Resolution = 15
tracer.IntegratorType = "RKF45"
tracer.StepMode = "Adaptive (embedded methods)"
tracer.MaximumError = 1e-7
tracer.MaximumIntegrationStep = 0.02
lines = Show(tracer, view)  # noqa: F405
if "Ray-Cast Tubes" in lines.GetProperty("Representation").Available:
    lines.SetRepresentationType("Ray-Cast Tubes")
    lines.TubeRadius = 0.009
    shown = lines
else:
    Hide(tracer, view)  # noqa: F405
    tubes = Tube(Input=tracer, Radius=0.009, NumberofSides=16)  # noqa: F405
    shown = Show(tubes, view)  # noqa: F405
shown.ColorArrayName = ["POINTS", ""]
shown.AmbientColor = shown.DiffuseColor = [0.85, 0.25, 0.2]

view.CameraPosition = [2.6, -1.5, 2.1]
view.CameraFocalPoint = [0.5, 0.5, 0.45]
view.CameraViewUp = [0, 0, 1]
view.CameraViewAngle = 24
Render(view)  # noqa: F405
if len(sys.argv) > 1:
    SaveScreenshot(sys.argv[1], view, ImageResolution=[800, 600])  # noqa: F405
    print("wrote", sys.argv[1])
