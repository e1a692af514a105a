# SPDX-License-Identifier: BSD-3-Clause
"""pvbatch: the "Superquadric Glyphs" representation of the SplineViz plugin
on a tensor volume (vtkImageData from a Programmable Source, DIPY-ordered
tensors): a glyph at EVERY voxel (not only the surface, which is what
vtkGeometryRepresentation's geometry filter would keep; the picture against
its baseline image), the properties reach the mapper, changing gamma
re-renders without uploading the tensors again, coloring by an array
works, and a multiblock of two volumes gets the glyphs of both."""
import builtins
import sys

from paraview.simple import *  # noqa: F401,F403

import splineviz  # noqa: F401  (Python wrappers of the SplineViz classes)
from splineviz_testing import compare_baseline, coverage as image_coverage, white_view

LoadPlugin(sys.argv[1], remote=False, ns=globals())

SCRIPT = """
import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk
n = 6
out = self.GetOutput()
out.SetDimensions(n, n, n)
out.SetOrigin(-2.5, -2.5, -2.5)
x, y, z = np.meshgrid(*(np.arange(n) - 2.5,) * 3, indexing="ij")
x, y, z = (a.ravel(order="F") for a in (x, y, z))
# principal direction: circles around the z axis; FA grows with the radius
r = np.sqrt(x * x + y * y) + 1e-9
e1 = np.stack([-y / r, x / r, np.zeros_like(r)], 1)
e3 = np.tile([0.0, 0.0, 1.0], (len(r), 1))
e2 = np.cross(e3, e1)
l1 = np.full(len(r), 1.0)
l2 = 0.3 + 0.5 * np.exp(-r)
l3 = np.where(z > 0, 0.2, l2 * 0.95)
T = (l1[:, None, None] * e1[:, :, None] * e1[:, None, :] +
     l2[:, None, None] * e2[:, :, None] * e2[:, None, :] +
     l3[:, None, None] * e3[:, :, None] * e3[:, None, :])
lower = np.stack([T[:, 0, 0], T[:, 1, 0], T[:, 1, 1], T[:, 2, 0], T[:, 2, 1], T[:, 2, 2]], 1)
t = numpy_to_vtk(lower.copy(), deep=1)
t.SetName("DTI")
out.GetPointData().AddArray(t)
radius = numpy_to_vtk(r.copy(), deep=1)
radius.SetName("Radius")
out.GetPointData().AddArray(radius)
"""
INFO = """
self.GetExecutive().GetOutputInformation(0).Set(
    self.GetExecutive().WHOLE_EXTENT(), 0, 5, 0, 5, 0, 5)
"""

tensor_volume = ProgrammableSource(OutputDataSetType="vtkImageData", Script=SCRIPT,  # noqa: F405
                            ScriptRequestInformation=INFO)
view = white_view((500, 400), baseline=True)
display = Show(tensor_volume, view)  # noqa: F405
if display.GetXMLName() != "UniformGridRepresentation":
    print("ERROR: unexpected representation", display.GetXMLName())
    sys.exit(1)
display.SetRepresentationType("Superquadric Glyphs")
display.SuperquadricTensors = "DTI"
display.SuperquadricTensorLayout = 2  # NIfTI / DIPY order
display.SuperquadricScaleFactor = 0.45
display.SuperquadricGamma = 3.0
view.CameraPosition = [9, -13, 8]
view.CameraFocalPoint = [0, 0, 0]
view.CameraViewUp = [0, 0, 1]
ResetCamera(view)  # noqa: F405


def coverage(name):
    return image_coverage(view, name, stride=2)


cov3, img3 = coverage("TestPluginSuperquadricGlyphs.png")
sub = display.GetClientSideObject().GetActiveRepresentation()
if sub.GetClassName() != "vtkSuperquadricGlyphRepresentation":
    print("ERROR: active representation is", sub.GetClassName())
    sys.exit(1)
mapper = sub.GetActor().GetMapper()
print("glyphs:", mapper.GetNumberOfGlyphs(), "coverage: %.3f" % cov3)
if mapper.GetNumberOfGlyphs() != 216:
    print("ERROR: expected a glyph at each of the 216 voxels, got", mapper.GetNumberOfGlyphs())
    sys.exit(1)
if cov3 < 0.1:
    print("ERROR: the glyphs did not render")
    sys.exit(1)
# The picture itself, against its baseline (Testing/Data/Baseline).
compare_baseline(view, "TestPluginSuperquadricGlyphs.png")
checks = [(mapper.GetTensorArray(), "DTI"), (mapper.GetTensorLayout(), 2),
          (round(mapper.GetScaleFactor(), 6), 0.45), (mapper.GetGamma(), 3.0)]
for got, expected in checks:
    if got != expected:
        print("ERROR: property did not reach the mapper:", got, "!=", expected)
        sys.exit(1)

# The bounds reported to the view include the glyphs (not only the points).
bounds = view.GetRenderer().ComputeVisiblePropBounds()
if not (bounds[0] < -2.6 and bounds[1] > 2.6):
    print("ERROR: view bounds do not include the glyphs:", bounds)
    sys.exit(1)

# Gamma: a different picture, no new upload.
uploads = mapper.GetUploadCount()
display.SuperquadricGamma = 0.0
cov0, img0 = coverage("TestPluginSuperquadricGlyphs-gamma0.png")
changed = builtins.sum(1 for a, b in zip(img0, img3) if a != b)
print("gamma 0: coverage %.3f, %d pixels changed, uploads %d -> %d"
      % (cov0, changed, uploads, mapper.GetUploadCount()))
if mapper.GetUploadCount() != uploads:
    print("ERROR: changing gamma uploaded the tensors again")
    sys.exit(1)
if changed < 500 or not cov0 < cov3:
    print("ERROR: gamma had no visible effect")
    sys.exit(1)

# Coloring by an array through the color map.
display.SuperquadricColorMode = 1
ColorBy(display, ("POINTS", "Radius"))  # noqa: F405
display.RescaleTransferFunctionToDataRange(True)
covc, imgc = coverage("TestPluginSuperquadricGlyphs-colored.png")
colors = set(p for p in imgc if p != (255.0, 255.0, 255.0))
print("colored by Radius: %d distinct colors" % len(colors))
if len(colors) < 50:
    print("ERROR: coloring by the Radius array failed")
    sys.exit(1)

# FA threshold hides the nearly isotropic glyphs.
display.SuperquadricAnisotropyThreshold = 0.62
covt, _ = coverage("TestPluginSuperquadricGlyphs-threshold.png")
print("FA threshold 0.62: coverage %.3f" % covt)
if not (0.0 < covt < 0.9 * covc):
    print("ERROR: the FA threshold did not hide glyphs")
    sys.exit(1)

# A multiblock of two volumes: glyphs of both.
second_volume = ProgrammableSource(OutputDataSetType="vtkImageData", Script=SCRIPT,  # noqa: F405
                             ScriptRequestInformation=INFO)
shifted = Transform(Input=second_volume)  # noqa: F405
shifted.Transform.Translate = [7, 0, 0]
group = GroupDatasets(Input=[tensor_volume, shifted])  # noqa: F405
Hide(tensor_volume, view)  # noqa: F405
gd = Show(group, view)  # noqa: F405
gd.SetRepresentationType("Superquadric Glyphs")
gd.SuperquadricTensors = "DTI"
gd.SuperquadricTensorLayout = 2
gd.SuperquadricScaleFactor = 0.45
ResetCamera(view)  # noqa: F405
covg, _ = coverage("TestPluginSuperquadricGlyphs-multiblock.png")
gmapper = gd.GetClientSideObject().GetActiveRepresentation().GetActor().GetMapper()
print("multiblock: %d glyphs, coverage %.3f" % (gmapper.GetNumberOfGlyphs(), covg))
if gmapper.GetNumberOfGlyphs() != 432 or covg < 0.05:
    print("ERROR: expected the glyphs of both blocks")
    sys.exit(1)
print("Superquadric Glyphs representation OK")
