# SPDX-License-Identifier: BSD-3-Clause
"""pvbatch: the SplineViz plugin's "Tensor Line Tracer" proxy on the real
DIPY tensors (read through ParaView's reader factory): voxel seeding and a
point-cloud seed source, documented properties reaching the filter, and the
lines shown with the "Ray-Cast Tubes" representation (radius from FA, direct
RGB direction colors); the picture must be covered by tubes. A state saved
before the mask became SetInputArrayToProcess (a 1-element MaskArray) still
selects its mask. The Mask Array's "None" entry is no mask (the plugin's
vtkPVTensorLineTracer clears the selection), in new and old states alike;
a mask array the input does not have is the filter's error; the picture is
compared with its baseline image."""
import os
import sys

from paraview.simple import *  # noqa: F401,F403
from splineviz_testing import (Observed, compare_baseline, coverage, load_pre_rename_state,
                               output_dir, white_view)
from paraview import servermanager

import splineviz  # noqa: F401  (Python wrappers of the SplineViz classes)

LoadPlugin(sys.argv[1], remote=False, ns=globals())
path = os.path.join(os.environ["SPLINEVIZ_SOURCE_DIR"], "Testing", "Data", "DIPY",
                    "small_64D_dti.vti")
dti = OpenDataFile(path)  # noqa: F405

tracer = TensorLineTracer(Input=dti)  # noqa: F405
tracer.Tensors = ["POINTS", "DTI"]
tracer.TensorLayout = "XX XY YY XZ YZ ZZ (NIfTI, DIPY)"
tracer.Seeding = "Voxels above the seed FA threshold"
tracer.SeedFAThreshold = 0.3
tracer.StoppingFAThreshold = 0.15
tracer.MinimumLength = 4.0
tracer.UpdatePipeline()
lines = servermanager.Fetch(tracer)
server = tracer.GetClientSideObject()
print("voxel seeding: %d seeds, %d lines, %d points" % (server.GetNumberOfSeeds(),
                                                       lines.GetNumberOfLines(),
                                                       lines.GetNumberOfPoints()))
if server.GetTensorLayout() != 2 or server.GetNumberOfSeeds() != 595:
    print("ERROR: properties not forwarded or wrong seeds:", server.GetTensorLayout(),
          server.GetNumberOfSeeds())
    sys.exit(1)
if lines.GetNumberOfLines() < 300:
    print("ERROR: too few lines")
    sys.exit(1)
for name in ("FractionalAnisotropy", "Tensors", "PrincipalDirection", "DirectionColors",
             "ArcLength"):
    if lines.GetPointData().GetArray(name) is None:
        print("ERROR: missing point array", name)
        sys.exit(1)

# Seeds from a point cloud in the middle of the volume.
cloud = TensorLineTracer(Input=dti, SeedType="Point Cloud")  # noqa: F405
cloud.Tensors = ["POINTS", "DTI"]
cloud.TensorLayout = "XX XY YY XZ YZ ZZ (NIfTI, DIPY)"
cloud.Seeding = "Seed source"
cloud.SeedType.Center = [9, 9, 9]
cloud.SeedType.Radius = 4
cloud.SeedType.NumberOfPoints = 50
cloud.IntegratorType = "Runge-Kutta 2 (midpoint)"
cloud.Interpolation = "Log-Euclidean"
cloud.UpdatePipeline()
cloud_lines = servermanager.Fetch(cloud)
print("point cloud: %d lines" % cloud_lines.GetNumberOfLines())
if not 10 <= cloud_lines.GetNumberOfLines() <= 50:
    print("ERROR: unexpected number of lines from the point cloud")
    sys.exit(1)

view = white_view((500, 400), baseline=True)
display = Show(tracer, view)  # noqa: F405
display.SetRepresentationType("Ray-Cast Tubes")
display.TubeRadiusArray = "FractionalAnisotropy"
display.TubeRadiusScale = 0.15
ColorBy(display, ("POINTS", "DirectionColors"))  # noqa: F405
display.MapScalars = 0
view.CameraPosition = [40, -30, 40]
view.CameraFocalPoint = [9, 9, 9]
view.CameraViewUp = [0, 0, 1]
ResetCamera(view)  # noqa: F405
cover, pixels = coverage(view, "TestPluginTensorLines.png")
colored = sum(1 for p in pixels if max(p) - min(p) > 60) / float(len(pixels))
print("coverage %.3f, strongly colored %.3f" % (cover, colored))
sub = display.GetClientSideObject().GetActiveRepresentation()
if not sub.GetActor().GetMapper().IsA("vtkRayCastTubeMapper"):
    print("ERROR: not drawn with the ray-cast tube mapper")
    sys.exit(1)
if cover < 0.15 or colored < 0.05:
    print("ERROR: the tubes did not render with direction colors")
    sys.exit(1)
# The picture itself, against its baseline (Testing/Data/Baseline).
compare_baseline(view, "TestPluginTensorLines.png")

# A state saved before this release holds the mask as the 1-element MaskArray;
# the hidden deprecated property of that name (kept for one release) passes it
# to the filter.
cloud.MaskArray = "FA_DIPY"
cloud.UpdatePipeline()
if cloud.GetClientSideObject().GetMaskArrayName() != "FA_DIPY":
    print("ERROR: Mask Array does not reach the filter")
    sys.exit(1)
loaded = load_pre_rename_state({"SelectMaskArray": "MaskArray"},
                               os.path.join(output_dir(), "TestPluginTensorLines-pre-rename.pvsm"))
masks = [p.GetClientSideObject().GetMaskArrayName() for p in loaded.get("TensorLineTracer", [])]
print("old state: masks", masks)
# Its "None" (ParaView's entry for no array) is no mask: no selection reaches
# the VTK filter, which would report a mask array named "None".
if sorted(masks, key=str) != ["FA_DIPY", None]:
    print("ERROR: the old state's mask does not reach the filter:", masks)
    sys.exit(1)
for proxy in loaded.get("TensorLineTracer", []):
    observed = Observed(proxy.GetClientSideObject())
    proxy.UpdatePipeline()
    if observed.errors or proxy.GetDataInformation().GetNumberOfCells() == 0:
        print("ERROR: the old state's tracer failed:", observed.messages)
        sys.exit(1)

# "None", the Mask Array list's entry for no array (the default): the plugin's
# vtkPVTensorLineTracer clears the selection, the filter traces without a
# mask and reports nothing; any other missing name is the filter's error.
print("tracer class:", server.GetClassName())
if not server.IsA("vtkPVTensorLineTracer"):
    print("ERROR: the proxy does not make the plugin's vtkPVTensorLineTracer")
    sys.exit(1)
observed = Observed(server)
tracer.MaskArray = ["POINTS", "Missing"]
tracer.UpdatePipeline()
print("mask 'Missing':", observed.messages)
if server.GetMaskArrayName() != "Missing" or not any(
        "the mask array 'Missing' is not a point array" in m for m in observed.messages):
    print("ERROR: a missing mask array is not reported")
    sys.exit(1)
observed = Observed(server)
tracer.MaskArray = ["POINTS", "None"]
tracer.UpdatePipeline()
if server.GetMaskArrayName() is not None or observed.errors or observed.warnings:
    print("ERROR: the Mask Array's None is not no mask:", server.GetMaskArrayName(),
          observed.messages)
    sys.exit(1)
if server.GetNumberOfSeeds() != 595:
    print("ERROR: no mask, but %d seeds instead of 595" % server.GetNumberOfSeeds())
    sys.exit(1)
# The mask as a real array: fewer seeds (FA_DIPY >= 0.5 only where FA is
# high), so the mask acts and "None" above is not silently a mask.
tracer.MaskArray = ["POINTS", "FA_DIPY"]
tracer.UpdatePipeline()
masked_seeds = server.GetNumberOfSeeds()
print("seeds: no mask 595, FA_DIPY as the mask %d" % masked_seeds)
if server.GetMaskArrayName() != "FA_DIPY" or not 0 < masked_seeds < 595:
    print("ERROR: the mask array FA_DIPY does not act")
    sys.exit(1)
# A point array that is itself named "None" cannot be told from the entry:
# no mask, and a warning that says so.
renamed = Calculator(Input=dti, ResultArrayName="None", Function="FA_DIPY")  # noqa: F405
named = TensorLineTracer(Input=renamed)  # noqa: F405
named.Tensors = ["POINTS", "DTI"]
named.TensorLayout = "XX XY YY XZ YZ ZZ (NIfTI, DIPY)"
named.Seeding = "Voxels above the seed FA threshold"
named.MaskArray = ["POINTS", "None"]
named_server = named.GetClientSideObject()
observed = Observed(named_server)
named.UpdatePipeline()
print("an array named None: %d seeds, %d warnings" % (named_server.GetNumberOfSeeds(),
                                                      len(observed.warnings)))
if observed.errors or len(observed.warnings) != 1 or named_server.GetNumberOfSeeds() != 595:
    print("ERROR: an array named None is not 'no mask' with a warning")
    sys.exit(1)
