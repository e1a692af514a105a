# SPDX-License-Identifier: BSD-3-Clause
"""pvbatch: LR-Spline Probe and LR-Spline Stream Tracer on an IFEM surface
result, the flow around a cylinder of Cyl2D-VMSFSI-weak.hdf5 (five curved g2
patches in the plane), opened by file name at its last time step.

Checks:
- LR-Spline Probe along a line across the channel (x = 3, y in [-8, 8])
  gives vtkValidPointMask 1 everywhere and the velocity u the probe filter
  gives for the same points outside ParaView (vtkLRSplineProbeFilter on
  the reader's output, 1e-12);
- LR-Spline Stream Tracer from a line of seeds upstream of the cylinder
  gives lines in the plane z = 0 that pass the cylinder (none enters it:
  r >= 0.49, its wall is a quadratic arc through r = 0.5) and reach x > 5;
- the result coloured by |u| with the streamlines draws both (written for
  docs/ifem.md: ifem-cyl2d-streamlines.png).
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from paraview.simple import *  # noqa: F401,F403,E402
from paraview import servermanager  # noqa: E402
from splineviz_testing import drawn_fraction, output_dir, png_rgb, white_view  # noqa: E402

plugin = sys.argv[1]
LoadPlugin(plugin, remote=False, ns=globals())  # noqa: F405
SOURCE = os.environ.get("SPLINEVIZ_SOURCE_DIR",
                        os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
path = os.path.join(SOURCE, "Testing", "Data", "External", "ifem", "Cyl2D-VMSFSI-weak.hdf5")
from splineviz_testing import Checker  # noqa: E402

checker = Checker()


fail = checker.fail


reader = OpenDataFile(path)  # noqa: F405
if reader is None or reader.GetXMLName() != "IFEMReader":
    fail("the result is not opened by the IFEM reader: %s" % reader)
    sys.exit(1)
scene = GetAnimationScene()  # noqa: F405
scene.UpdateAnimationUsingDataTimeSteps()
scene.AnimationTime = reader.TimestepValues[-1]

# --- probe along a line ---------------------------------------------------------------------------
line = Line(Point1=[3.0, -8.0, 0.0], Point2=[3.0, 8.0, 0.0], Resolution=40)  # noqa: F405
probe = LRSplineProbe(Input=reader, Source=line)  # noqa: F405
probe.ArrayName = "u"
probe.UpdatePipeline(reader.TimestepValues[-1])
out = servermanager.Fetch(probe)
mask = out.GetPointData().GetArray("vtkValidPointMask")
u = out.GetPointData().GetArray("u")
direct = None
if mask is None or u is None:
    fail("the probe gave no u or mask")
else:
    from splineviz import vtkLRSplineProbeFilter  # noqa: E402
    from vtkmodules.vtkCommonDataModel import vtkDataObject  # noqa: E402

    data = servermanager.Fetch(reader)
    f = vtkLRSplineProbeFilter()
    f.SetInputData(servermanager.Fetch(line))
    f.SetSourceData(data)
    f.SetInputArrayToProcess(0, 1, 0, vtkDataObject.FIELD_ASSOCIATION_POINTS, "u")
    f.Update()
    ref = f.GetOutput().GetPointData().GetArray("u")
    m = np.array([mask.GetTuple1(i) for i in range(mask.GetNumberOfTuples())])
    err = max(np.abs(np.array(u.GetTuple(i)) - np.array(ref.GetTuple(i))).max()
              for i in range(u.GetNumberOfTuples()))
    ux = np.array([u.GetTuple(i)[0] for i in range(u.GetNumberOfTuples())])
    print("LR-Spline Probe across the channel: %d of %d inside, u_x from %.3f to %.3f, "
          "against the filter outside ParaView %.1e" % (m.sum(), len(m), ux.min(), ux.max(), err))
    if m.min() != 1 or not err <= 1e-12 or not ux.max() > 0.1:
        fail("the probe across the channel is wrong (mask %d of %d, %.3g)"
             % (m.sum(), len(m), err))

# --- streamlines around the cylinder --------------------------------------------------------------
tracer = LRSplineStreamTracer(Input=reader, SeedType="Line")  # noqa: F405
tracer.Vectors = "u"
tracer.SeedType.Point1 = [-6.0, -2.0, 0.0]
tracer.SeedType.Point2 = [-6.0, 2.0, 0.0]
tracer.SeedType.Resolution = 14
tracer.IntegrationStep = 0.05
tracer.MaximumNumberOfSteps = 1000
tracer.UpdatePipeline(reader.TimestepValues[-1])
lines = servermanager.Fetch(tracer)
P = np.array([lines.GetPoint(i) for i in range(lines.GetNumberOfPoints())])
if len(P) == 0:
    fail("no streamlines")
    sys.exit(1)
r = np.linalg.norm(P[:, :2], axis=1)
print("LR-Spline Stream Tracer: %d lines, %d points, nearest the cylinder's centre %.3f, "
      "x up to %.2f, |z| up to %.1e" % (lines.GetNumberOfCells(), len(P), r.min(),
                                        P[:, 0].max(), np.abs(P[:, 2]).max()))
if lines.GetNumberOfCells() < 15 or r.min() < 0.49 or P[:, 0].max() < 5 or np.abs(P[:, 2]).max():
    fail("the streamlines do not pass the cylinder in the plane")

# --- the picture ----------------------------------------------------------------------------------
view = white_view((720, 400))
display = Show(reader, view)  # noqa: F405
ColorBy(display, ("POINTS", "u", "Magnitude"))  # noqa: F405
lut = GetColorTransferFunction("u")  # noqa: F405
lut.ApplyPreset("Cool to Warm", True)
lut.RescaleTransferFunction(0.0, 1.4)
display.SetScalarBarVisibility(view, True)
# The lines just above the plane (drawn over it, not half buried in it).
lifted = Transform(Input=tracer)  # noqa: F405
lifted.Transform.Translate = [0.0, 0.0, 0.05]
lines_display = Show(lifted, view)  # noqa: F405
ColorBy(lines_display, None)  # noqa: F405
lines_display.AmbientColor = lines_display.DiffuseColor = [0.05, 0.05, 0.05]
lines_display.LineWidth = 2.0
Render(view)  # noqa: F405
view.CameraPosition = [0.5, 0.0, 40.0]
view.CameraFocalPoint = [0.5, 0.0, 0.0]
view.CameraViewUp = [0, 1, 0]
view.CameraParallelProjection = 1
view.CameraParallelScale = 3.6
Render(view)  # noqa: F405
png = os.path.join(output_dir(), "TestPluginIFEMSurfaces.png")
SaveScreenshot(png, view, ImageResolution=[720, 400])  # noqa: F405
rgb = png_rgb(png).reshape(-1, 3)
dark = (rgb.max(axis=1) < 60).mean()
red = ((rgb[:, 0] - rgb[:, 2]) > 60).mean()
blue = ((rgb[:, 2] - rgb[:, 0]) > 60).mean()
drawn = drawn_fraction(png, background=(255, 255, 255), tolerance=10)
print("picture: %.3f dark (streamlines), %.3f red (fast, beside the cylinder), %.3f blue (slow, "
      "before and behind it), %.3f not white (%s)" % (dark, red, blue, drawn, png))
if dark < 0.01 or red < 0.01 or blue < 0.002 or drawn < 0.9:
    fail("the picture does not show the streamlines over the coloured flow")

checker.finish()
print("TestPluginIFEMSurfaces passed")
