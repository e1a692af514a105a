# SPDX-License-Identifier: BSD-3-Clause
"""pvbatch: the SplineViz plugin's "LR-Spline Fit Image" in a ParaView pipeline:
fit ParaView's Wavelet (an analytic scalar image) to 2 % of its range, check
at every voxel with "LR-Spline Probe" that the tolerance holds, check the
fit's field data and that every property of the proxy is documented, write
the .lr file from the proxy and open it with the reader (Physical Bounds = the
image's bounds) as the same spline; a bad setting (a zero tolerance) fails
with the fitter's error; render the fitted spline's surface."""
import os
import sys

from paraview.simple import *  # noqa: F401,F403
from paraview import servermanager
from splineviz_testing import Observed, coverage, output_dir, white_view

plugin = sys.argv[1]
LoadPlugin(plugin, remote=False, ns=globals())

wavelet = Wavelet(WholeExtent=[-12, 12, -10, 10, -8, 8])  # noqa: F405
wavelet.UpdatePipeline()
low, high = wavelet.GetDataInformation().GetPointDataInformation().GetArrayInformation(
    "RTData").GetComponentRange(0)

lr_file = os.path.join(output_dir(), "TestPluginLRSplineFit.lr")
fit = LRSplineFitImage(Input=wavelet)  # noqa: F405
fit.Scalars = ["POINTS", "RTData"]
fit.Tolerance = 0.02
fit.ToleranceMode = "Relative to the data range"
fit.FileName = lr_file
fit.UpdatePipeline()
info = fit.GetDataInformation()
print("fit:", info.GetNumberOfCells(), "elements")
assert info.GetNumberOfCells() > 64, info.GetNumberOfCells()

spline = servermanager.Fetch(fit)
grid = spline.GetBlock(0)
fd = grid.GetFieldData()
tolerance = fd.GetArray("LRFitTolerance").GetValue(0)
met = fd.GetArray("LRFitToleranceMet").GetValue(0)
worst = fd.GetArray("LRFitMaximumError").GetValue(0)
history = fd.GetArray("LRFitHistory")
print("fit: tolerance %.4g, maximum error %.4g, RMS %.4g, %d fits, met %d"
      % (tolerance, worst, fd.GetArray("LRFitRMSError").GetValue(0), history.GetNumberOfTuples(), met))
if not met or abs(tolerance - 0.02 * (high - low)) > 1e-9 * (high - low) or worst > tolerance:
    print("ERROR: the fit did not meet 2 % of the range")
    sys.exit(1)
if grid.GetPointData().GetArray("RTData") is None:
    print("ERROR: the output's array is not named after the input's")
    sys.exit(1)

# Independently of the fitter: the spline at every voxel of the wavelet.
probe = LRSplineProbe(Input=fit, Source=wavelet)  # noqa: F405
probe.UpdatePipeline()
probed = servermanager.Fetch(probe)
values = probed.GetPointData().GetArray("RTData")
image = servermanager.Fetch(wavelet)
data = image.GetPointData().GetArray("RTData")
largest = max(abs(values.GetValue(i) - data.GetValue(i)) for i in range(image.GetNumberOfPoints()))
print("probe at the %d voxels: largest difference %.4g" % (image.GetNumberOfPoints(), largest))
if largest > tolerance * (1 + 1e-9):
    print("ERROR: the probed spline misses the tolerance")
    sys.exit(1)

# Every property is documented.
undocumented = [name for name in fit.ListProperties()
                if not fit.GetProperty(name).SMProperty.GetDocumentation()]
if undocumented:
    print("ERROR: undocumented properties:", undocumented)
    sys.exit(1)

# The .lr file the proxy wrote, opened with the reader, is the same spline.
reader = LRSplineVolumeReader(FileName=lr_file)  # noqa: F405
reader.PhysicalBounds = image.GetBounds()
reader.FieldName = "RTData"
probe_back = LRSplineProbe(Input=reader, Source=wavelet)  # noqa: F405
probe_back.UpdatePipeline()
back = servermanager.Fetch(probe_back).GetPointData().GetArray("RTData")
difference = max(abs(back.GetValue(i) - values.GetValue(i)) for i in range(image.GetNumberOfPoints()))
print("the .lr file read back differs by", difference)
if difference > 1e-9 * (high - low):
    print("ERROR: the written .lr file is not the fitted spline")
    sys.exit(1)

# A bad setting fails with the fitter's message.
bad = LRSplineFitImage(Input=wavelet, Tolerance=0.0)  # noqa: F405
observed = Observed(bad.GetClientSideObject())
bad.UpdatePipeline()
if bad.GetDataInformation().GetNumberOfCells() != 0 or not observed.errors:
    print("ERROR: a zero tolerance gave an output or no error")
    sys.exit(1)
print("zero tolerance: refused (%d error events)" % len(observed.errors))

view = white_view((400, 300))
display = Show(fit, view)  # noqa: F405
ColorBy(display, ("POINTS", "RTData"))  # noqa: F405
view.CameraPosition = [60, -50, 45]
view.CameraFocalPoint = [0, 0, 0]
view.CameraViewUp = [0, 0, 1]
ResetCamera(view)  # noqa: F405
Render(view)  # noqa: F405
fraction, _ = coverage(view, "TestPluginLRSplineFit.png", stride=7)
print("fraction of non-background pixels:", fraction)
if fraction < 0.1 or fraction > 0.9:
    print("ERROR: the fitted spline did not render in the middle of the view")
    sys.exit(1)
