# SPDX-License-Identifier: BSD-3-Clause
"""pvbatch: the SplineViz plugin's LR-spline proxies in a ParaView pipeline:
open a .lr file through the reader factory, probe it along a line, resample
it to an image, render the spline's surface and check the picture; a state
saved before the field became SetInputArrayToProcess (1-element ArrayName and
Vectors properties) still selects its field."""
import os
import sys

from paraview.simple import *  # noqa: F401,F403
from splineviz_testing import coverage, load_pre_rename_state, output_dir, white_view

import splineviz  # noqa: F401  (Python wrappers of the SplineViz classes)

plugin = sys.argv[1]
LoadPlugin(plugin, remote=False, ns=globals())

data = os.path.join(os.environ["SPLINEVIZ_SOURCE_DIR"], "Testing", "Data", "External")
path = os.path.join(data, "cube-3patch-refined.lr")

# The reader factory must know the extensions.
reader = OpenDataFile(path)  # noqa: F405
if reader is None or reader.GetXMLName() != "LRSplineReader":
    print("ERROR: .lr files are not opened by the LR-spline reader:", reader)
    sys.exit(1)
reader.PhysicalBounds = [0, 2, 0, 2, 0, 2]
reader.UpdatePipeline()
info = reader.GetDataInformation()
assert info.GetNumberOfCells() == 3 * 1240, info.GetNumberOfCells()
g2 = OpenDataFile(os.path.join(data, "tensor-product-volume.g2"))  # noqa: F405
if g2 is None or g2.GetXMLName() != "LRSplineReader":
    print("ERROR: .g2 files are not opened by the LR-spline reader")
    sys.exit(1)
g2.UpdatePipeline()
assert g2.GetDataInformation().GetNumberOfCells() == 6

# Probe along the diagonal: patch 0 is the identity map of the unit cube, so
# in the box [0,2]^3 the field at x is x / 2.
line = Line(Point1=[0, 0, 0], Point2=[2, 2, 2], Resolution=50)  # noqa: F405
probe = LRSplineProbe(Input=reader, Source=line, ComputeGradient=1)  # noqa: F405
probe.UpdatePipeline()
from paraview import servermanager  # noqa: E402

out = servermanager.Fetch(probe)
field = out.GetPointData().GetArray("Field")
mask = out.GetPointData().GetArray("vtkValidPointMask")
worst = 0.0
for i in range(out.GetNumberOfPoints()):
    x = out.GetPoint(i)
    v = field.GetTuple3(i)
    assert mask.GetTuple1(i) == 1
    worst = max(worst, max(abs(v[k] - x[k] / 2.0) for k in range(3)))
print("probe along the diagonal: max error", worst)
if worst > 1e-12:
    print("ERROR: the probed field is wrong")
    sys.exit(1)

image = LRSplineResampleToImage(Input=reader, SamplingDimensions=[16, 16, 16])  # noqa: F405
image.UpdatePipeline()
iinfo = image.GetDataInformation()
assert iinfo.GetNumberOfPoints() == 16 ** 3, iinfo.GetNumberOfPoints()
arr = iinfo.GetPointDataInformation().GetArrayInformation("Field")
rng = arr.GetComponentRange(0)
assert abs(rng[0]) < 1e-12 and abs(rng[1] - 1.0) < 1e-12, rng

# Streamlines through patch 1 (the field v = (-y, x, z) in the unit cube,
# placed in [0,2]^3 it is (-y, x, z)/2 in physical units per parameter).
block = ExtractBlock(Input=reader)  # noqa: F405
block.Selectors = ["/Root/Patch1"]
tracer = LRSplineStreamTracer(Input=block, SeedType="Line")  # noqa: F405
tracer.SeedType.Point1 = [0.4, 0.1, 0.1]
tracer.SeedType.Point2 = [1.8, 0.1, 0.3]
tracer.SeedType.Resolution = 9
tracer.IntegratorType = "RKF45"
tracer.StepMode = "Adaptive (embedded methods)"
tracer.MaximumError = 1e-8
tracer.UpdatePipeline()
lines = servermanager.Fetch(tracer)
print("stream tracer:", lines.GetNumberOfLines(), "lines,", lines.GetNumberOfPoints(), "points")
assert lines.GetNumberOfLines() >= 10, lines.GetNumberOfLines()
for name in ("Field", "Speed", "IntegrationTime"):
    assert lines.GetPointData().GetArray(name) is not None, name
for name in ("SeedIds", "ReasonForTermination"):
    assert lines.GetCellData().GetArray(name) is not None, name
# radius about the z axis (the corner of the box) is preserved
worst = 0.0
for c in range(lines.GetNumberOfLines()):
    cell = lines.GetCell(c)
    ids = [cell.GetPointId(k) for k in range(cell.GetNumberOfPoints() - 1)]
    r0 = sum(v * v for v in lines.GetPoint(ids[0])[:2]) ** 0.5
    for i in ids:
        p = lines.GetPoint(i)
        worst = max(worst, abs((p[0] ** 2 + p[1] ** 2) ** 0.5 - r0))
print("stream tracer: largest change of the radius", worst)
if worst > 1e-6:
    print("ERROR: the streamlines are not the exact circles")
    sys.exit(1)

view = white_view((400, 300))
display = Show(reader, view)  # noqa: F405
ColorBy(display, ("POINTS", "Field", "Magnitude"))  # noqa: F405
view.CameraPosition = [6, -5, 7]
view.CameraFocalPoint = [1, 1, 1]
view.CameraViewUp = [0, 0, 1]
ResetCamera(view)  # noqa: F405
Render(view)  # noqa: F405

fraction, _ = coverage(view, "TestPluginLRSpline.png", stride=7)
print("fraction of non-background pixels:", fraction)
if fraction < 0.1 or fraction > 0.9:
    print("ERROR: the LR spline did not render as a cube in the middle of the view")
    sys.exit(1)

# A state saved before this release holds the field as the 1-element ArrayName
# (probe, resample) and Vectors (tracer); the hidden deprecated properties of
# those names (kept for one release) pass it to the filters.
probe.ArrayName = "Field"
image.ArrayName = "Field"
tracer.Vectors = "Field"
loaded = load_pre_rename_state(
    {"SelectInputField": "ArrayName", "SelectInputVectors": "Vectors"},
    os.path.join(output_dir(), "TestPluginLRSpline-pre-rename.pvsm"))
for xml_name in ("LRSplineProbe", "LRSplineResampleToImage", "LRSplineStreamTracer"):
    proxies = loaded.get(xml_name, [])
    fields = [p.GetClientSideObject().GetArrayName() for p in proxies]
    print("old state:", xml_name, fields)
    if len(proxies) != 1 or fields != ["Field"]:
        print("ERROR: the old state's field of %s does not reach the filter: %s"
              % (xml_name, fields))
        sys.exit(1)
