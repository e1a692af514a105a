# SPDX-License-Identifier: BSD-3-Clause
"""pvbatch: SplineViz's filters and the LR-Spline Volume representation on an
IFEM result with curved two-patch geometry, in physical space.

The result: IFEM-Poisson's cube-2patch solution u and flux q on the two
patches of cube-2patch.lr bent by a smooth map (ifem_poisson.py), opened by
file name (OpenDataFile: the IFEM reader). Checks:
- LR-Spline Probe at points x(u) of random parameters of both patches gives
  the numpy evaluation of u at u (ifem_reference.py) to 1e-9;
- LR-Spline Stream Tracer of q from seeds in the patch x > 0 gives lines that
  cross into the other patch;
- the reader's output shown as "LR-Spline Volume" coloured by u, with the
  streamlines as a surface, draws a coloured picture (written for
  inspection).
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import ifem_poisson  # noqa: E402
import ifem_reference as R  # noqa: E402

from paraview.simple import *  # noqa: F401,F403,E402
from paraview import servermanager  # noqa: E402
from splineviz_testing import output_dir, white_view  # noqa: E402

plugin = sys.argv[1]
LoadPlugin(plugin, remote=False, ns=globals())  # noqa: F405
from splineviz_testing import Checker  # noqa: E402

checker = Checker()


fail = checker.fail


path = os.path.join(output_dir(), "TestPluginIFEMPhysical.hdf5")
patches = ifem_poisson.write(path, curved=True)
reader = OpenDataFile(path)  # noqa: F405
if reader is None or reader.GetXMLName() != "IFEMReader":
    fail("the result is not opened by the IFEM reader: %s" % reader)
    sys.exit(1)

# --- probe at known points ------------------------------------------------------------------
rng = np.random.default_rng(5)
X, ref = [], []
for p in patches:
    for _ in range(40):
        u = rng.uniform(0.0, 1.0, 3) * 0.999
        b = R.basis(p, u)
        X.append(R.geometry(p, u, False, b))
        ref.append(R.field(p, u, p.values, False, b)[0])
cloud = ProgrammableSource()  # noqa: F405
cloud.OutputDataSetType = "vtkPolyData"
cloud.Script = (
    "from vtkmodules.vtkCommonCore import vtkPoints\n"
    "pts = vtkPoints()\npts.SetDataTypeToDouble()\n"
    + "".join("pts.InsertNextPoint(%r, %r, %r)\n" % tuple(x) for x in X)
    + "self.GetPolyDataOutput().SetPoints(pts)\n")
probe = LRSplineProbe(Input=reader, Source=cloud)  # noqa: F405
probe.ArrayName = "u"
probe.UpdatePipeline()
out = servermanager.Fetch(probe)
values = out.GetPointData().GetArray("u")
mask = out.GetPointData().GetArray("vtkValidPointMask")
if values is None or mask is None or values.GetNumberOfTuples() != len(X):
    fail("the probe gave no values")
else:
    v = np.array([values.GetTuple1(i) for i in range(len(X))])
    m = np.array([mask.GetTuple1(i) for i in range(len(X))])
    err = np.abs(v - np.array(ref)).max()
    print("probe in physical space: %d of %d inside, largest error %.2e" % (m.sum(), len(X), err))
    if m.min() != 1 or not err <= 1e-9:
        fail("the probe differs from the numpy evaluation by %.3g (%d outside)"
             % (err, int((m == 0).sum())))

# --- streamlines across the patch interface ---------------------------------------------------
tracer = LRSplineStreamTracer(Input=reader, SeedType="Line")  # noqa: F405
tracer.Vectors = "q"
tracer.SeedType.Point1 = [0.25, 0.3, 0.45]
tracer.SeedType.Point2 = [0.3, 0.7, 0.55]
tracer.SeedType.Resolution = 5
tracer.UpdatePipeline()
lines = servermanager.Fetch(tracer)
P = np.array([lines.GetPoint(i) for i in range(lines.GetNumberOfPoints())])
crossing = 0
for c in range(lines.GetNumberOfCells()):
    ids = lines.GetCell(c).GetPointIds()
    xs = [P[ids.GetId(k), 0] for k in range(ids.GetNumberOfIds())]
    crossing += 1 if (min(xs) < -0.1 and max(xs) > 0.1) else 0
print("stream tracer: %d lines, %d cross the patch interface" % (lines.GetNumberOfCells(), crossing))
if lines.GetNumberOfCells() < 4 or crossing < 3:
    fail("the streamlines do not continue into the second patch")

# --- LR-Spline Volume with the streamlines -----------------------------------------------------
view = white_view((480, 320))
display = Show(reader, view)  # noqa: F405
display.SetRepresentationType("LR-Spline Volume")
ColorBy(display, ("POINTS", "u"))  # noqa: F405
lut = GetColorTransferFunction("u")  # noqa: F405
lut.ApplyPreset("Cool to Warm", True)
lut.RescaleTransferFunction(-1.0, 1.0)
pwf = GetOpacityTransferFunction("u")  # noqa: F405
pwf.Points = [-1.0, 0.8, 0.5, 0.0, -0.2, 0.0, 0.5, 0.0, 0.2, 0.0, 0.5, 0.0, 1.0, 0.8, 0.5, 0.0]
lines_display = Show(tracer, view)  # noqa: F405
ColorBy(lines_display, None)  # noqa: F405
lines_display.AmbientColor = lines_display.DiffuseColor = [0.1, 0.1, 0.1]
view.CameraPosition = [1.5, -2.6, 2.2]
view.CameraFocalPoint = [0.0, 0.5, 0.5]
view.CameraViewUp = [0, 0, 1]
ResetCamera(view)  # noqa: F405
Render(view)  # noqa: F405
mapper = display.GetClientSideObject().GetActiveRepresentation().GetActor().GetMapper()
if mapper is None or not mapper.IsA("vtkLRSplineVolumeMapper"):
    fail("the representation does not render with vtkLRSplineVolumeMapper")
png = os.path.join(output_dir(), "TestPluginIFEMPhysical.png")
SaveScreenshot(png, view, ImageResolution=[480, 320])  # noqa: F405
from vtkmodules.vtkIOImage import vtkPNGReader  # noqa: E402
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402

r = vtkPNGReader()
r.SetFileName(png)
r.Update()
img = vtk_to_numpy(r.GetOutput().GetPointData().GetScalars())[:, :3].astype(int)
red = ((img[:, 0] - img[:, 2]) > 60).mean()
blue = ((img[:, 2] - img[:, 0]) > 60).mean()
print("LR-Spline Volume: %.3f of the view reddish (u > 0), %.3f bluish (u < 0) (%s)"
      % (red, blue, png))
if red < 0.02 or blue < 0.02:
    fail("the volume is not drawn with both signs of u")

checker.finish()
print("TestPluginIFEMPhysical passed")
