# SPDX-License-Identifier: BSD-3-Clause
"""pvbatch: the SplineViz plugin's "LR-Spline Fit" on an unstructured mesh in a
ParaView pipeline: ParaView's Wavelet clipped by a sphere (an unstructured
grid whose boundary is not its bounding box) is fitted to 2 % of its range;
"LR-Spline Probe" at every mesh point (independent of the fitter) finds the
tolerance met; every property of the proxy is documented; the second output
port is the mesh's boundary surface; the fitted volume rendered by the
"LR-Spline Volume" representation with that surface as Trimming Surface draws
no pixel outside the surface's own silhouette, while the untrimmed volume
(Trim By Data Boundary off, negative control) does, and leaves no holes in it;
shown without a Trimming Surface it draws the same pixels (the spline carries
its boundary) (a clipped mesh's non-conforming
faces once made some); Remove Outliers finds exactly five spiked values and
shows them on the third port; a bad setting fails with the fitter's error."""
import os
import sys

from paraview.simple import *  # noqa: F401,F403
from paraview import servermanager
from splineviz_testing import Observed, drawn_mask, output_dir, png_rgb, white_view

plugin = sys.argv[1]
LoadPlugin(plugin, remote=False, ns=globals())


def fail(message):
    print("ERROR:", message)
    sys.exit(1)


wavelet = Wavelet(WholeExtent=[-10, 10, -10, 10, -10, 10])  # noqa: F405
clip = Clip(Input=wavelet, ClipType="Sphere")  # noqa: F405
clip.ClipType.Center = [0, 0, 0]
clip.ClipType.Radius = 9.0
clip.Scalars = ["POINTS", "RTData"]
clip.Invert = 1
clip.UpdatePipeline()
mesh = servermanager.Fetch(clip)
print("mesh: %s, %d points, %d cells" % (mesh.GetClassName(), mesh.GetNumberOfPoints(),
                                          mesh.GetNumberOfCells()))
low, high = mesh.GetPointData().GetArray("RTData").GetRange()

fit = LRSplineFit(Input=clip)  # noqa: F405
fit.Array = ["POINTS", "RTData"]
fit.Tolerance = 0.02
fit.UpdatePipeline()
spline = servermanager.Fetch(fit)
grid = spline.GetBlock(0)
fd = grid.GetFieldData()
tolerance = fd.GetArray("LRFitTolerance").GetValue(0)
met = fd.GetArray("LRFitToleranceMet").GetValue(0)
print("fit: %d elements, tolerance %.4g, maximum error %.4g, met %d, %.2f s"
      % (grid.GetNumberOfCells(), tolerance, fd.GetArray("LRFitMaximumError").GetValue(0), met,
         fd.GetArray("LRFitSeconds").GetValue(0)))
if not met or abs(tolerance - 0.02 * (high - low)) > 1e-9 * (high - low):
    fail("the fit did not meet 2 % of the range")

# Independently of the fitter: the spline at every mesh point.
probe = LRSplineProbe(Input=fit, Source=clip)  # noqa: F405
probe.UpdatePipeline()
values = servermanager.Fetch(probe).GetPointData().GetArray("RTData")
data = mesh.GetPointData().GetArray("RTData")
largest = max(abs(values.GetValue(i) - data.GetValue(i)) for i in range(mesh.GetNumberOfPoints()))
print("probe at the %d mesh points: largest difference %.4g" % (mesh.GetNumberOfPoints(), largest))
if largest > tolerance * (1 + 1e-9):
    fail("the probed spline misses the tolerance")

undocumented = [name for name in fit.ListProperties()
                if not fit.GetProperty(name).SMProperty.GetDocumentation()]
if undocumented:
    fail("undocumented properties: %s" % undocumented)

boundary = OutputPort(fit, 1)  # noqa: F405
fit.UpdatePipeline()
boundary_info = fit.GetDataInformation(1)
print("boundary surface: %d cells" % boundary_info.GetNumberOfCells())
if boundary_info.GetNumberOfCells() < 100:
    fail("the second output port has no boundary surface")

# Trimmed rendering: nothing outside the boundary's silhouette.
view = white_view((360, 300))
view.CameraPosition = [40, -30, 25]
view.CameraFocalPoint = [0, 0, 0]
view.CameraViewUp = [0, 0, 1]
view.CameraParallelProjection = 0


def picture(name):
    path = os.path.join(output_dir(), "TestPluginLRSplineFitter-%s.png" % name)
    SaveScreenshot(path, view, ImageResolution=list(view.ViewSize))  # noqa: F405
    return png_rgb(path)


surface_display = Show(boundary, view)  # noqa: F405
surface_display.SetRepresentationType("Surface")
surface_display.ColorArrayName = ["POINTS", ""]
surface_display.AmbientColor = surface_display.DiffuseColor = [0.2, 0.2, 0.2]
view.CameraViewAngle = 30
Render(view)  # noqa: F405
silhouette = drawn_mask(picture("boundary"))
Hide(boundary, view)  # noqa: F405
display = Show(fit, view)  # noqa: F405
display.SetRepresentationType("LR-Spline Volume")
ColorBy(display, ("POINTS", "RTData"))  # noqa: F405
automatic = drawn_mask(picture("trimmed-automatic"))  # the spline carries its boundary
display.TrimByDataBoundary = 0
untrimmed = drawn_mask(picture("untrimmed"))
display.TrimByDataBoundary = 1
display.TrimmingSurface = boundary
trimmed = drawn_mask(picture("trimmed"))
print("automatic trimming: %d pixels differ from the boundary chosen as Trimming Surface"
      % (automatic != trimmed).sum())
if (automatic != trimmed).any():
    fail("the automatic trimming differs from the boundary chosen as Trimming Surface")
outside = trimmed & ~silhouette
untrimmed_outside = untrimmed & ~silhouette
print("silhouette %.3f, trimmed %.3f, drawn outside %d px (untrimmed: %d px)"
      % (silhouette.mean(), trimmed.mean(), outside.sum(), untrimmed_outside.sum()))
if outside.any():
    fail("%d pixels drawn outside the mesh's silhouette" % outside.sum())
if untrimmed_outside.sum() < 500:
    fail("negative control: the untrimmed volume should cover pixels outside the mesh")
if trimmed.mean() < 0.98 * silhouette.mean():
    fail("the trimmed volume leaves holes in the mesh's silhouette")

bad = LRSplineFit(Input=clip, Tolerance=0.0)  # noqa: F405
observed = Observed(bad.GetClientSideObject())
bad.UpdatePipeline()
if bad.GetDataInformation().GetNumberOfCells() != 0 or not observed.errors:
    fail("a zero tolerance gave an output or no error")
print("zero tolerance: refused (%d error events)" % len(observed.errors))

# Remove Outliers: five spiked mesh values come out on the third port, exactly.
# (The Programmable Filter's script runs in this interpreter: numpy's `clip`
# shadows the clip filter afterwards, so this comes last.)
spiky = ProgrammableFilter(Input=clip)  # noqa: F405
spiky.Script = """
out = self.GetOutput()
out.ShallowCopy(self.GetInput())
import vtk
values = vtk.vtkDoubleArray()
values.DeepCopy(out.GetPointData().GetArray("RTData"))
values.SetName("RTData")
for i in (11, 222, 1333, 2444, 3555):
    values.SetValue(i, values.GetValue(i) + 150.0)
out.GetPointData().AddArray(values)
"""
spiked = [11, 222, 1333, 2444, 3555]
robust = LRSplineFit(Input=spiky, RemoveOutliers=1)  # noqa: F405
robust.Array = ["POINTS", "RTData"]
robust.UpdatePipeline()
left = servermanager.Fetch(robust, idx=2)
found = sorted(mesh.FindPoint(left.GetPoint(i)) for i in range(left.GetNumberOfPoints()))
count = servermanager.Fetch(robust).GetBlock(0).GetFieldData().GetArray("LRFitOutliers")
print("Remove Outliers: %d points on the Outliers port %s (spiked %s), LRFitOutliers %d"
      % (left.GetNumberOfPoints(), found, spiked, count.GetValue(0)))
if found != spiked or count.GetValue(0) != len(spiked):
    fail("Remove Outliers did not find exactly the spiked values")
