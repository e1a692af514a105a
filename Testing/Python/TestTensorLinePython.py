# SPDX-License-Identifier: BSD-3-Clause
"""pvpython: vtkTensorLineTracer from the `splineviz` package in a plain VTK
pipeline with numpy: the real DIPY tensors (SYMMETRIC_LOWER layout, voxel
seeding) against DIPY's own FA at the seeds, the stopping contract, and a
numpy-made circle field (T = a I + t t^T, t = (-y, x, 0)) whose lines must
stay on their circles."""
import os

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkImageData, vtkPolyData
from vtkmodules.vtkIOXML import vtkXMLImageDataReader

import splineviz

from splineviz_testing import Checker  # noqa: E402

checker = Checker()


check = checker.check


# Real data.
path = os.path.join(os.environ["SPLINEVIZ_SOURCE_DIR"], "Testing", "Data", "DIPY",
                    "small_64D_dti.vti")
reader = vtkXMLImageDataReader()
reader.SetFileName(path)
reader.Update()
img = reader.GetOutput()
tracer = splineviz.vtkTensorLineTracer()
tracer.SetInputConnection(reader.GetOutputPort())
tracer.SetInputArrayToProcess(0, 0, 0, 0, "DTI")  # point data
tracer.SetTensorLayout(2)  # DIPY: XX XY YY XZ YZ ZZ
tracer.SetSeedMode(splineviz.vtkTensorLineTracer.SEEDS_FROM_VOXELS)
tracer.SetSeedFAThreshold(0.3)
tracer.SetStoppingFAThreshold(0.15)
tracer.SetMaximumAngle(45.0)
tracer.SetIntegrationStep(0.25)
tracer.Update()
out = tracer.GetOutput()
fa = vtk_to_numpy(out.GetPointData().GetArray("FractionalAnisotropy"))
arc = vtk_to_numpy(out.GetPointData().GetArray("ArcLength"))
pts = vtk_to_numpy(out.GetPoints().GetData())
reasons = vtk_to_numpy(out.GetCellData().GetArray("ReasonForTermination"))
seed_ids = vtk_to_numpy(out.GetCellData().GetArray("SeedIds"))
fa_dipy = vtk_to_numpy(img.GetPointData().GetArray("FA_DIPY"))
print("DIPY: %d seeds, %d lines, %d points" % (tracer.GetNumberOfSeeds(), out.GetNumberOfLines(),
                                               out.GetNumberOfPoints()))
check(tracer.GetNumberOfSeeds() == int((fa_dipy >= 0.3).sum()), "seeds = voxels with FA >= 0.3")
check(reasons.shape == (out.GetNumberOfLines(), 2), "ReasonForTermination has 2 components")
check(np.all(np.diff(seed_ids) > 0), "lines in seed order")
check(fa.min() >= 0.15, "every point has FA >= the stopping threshold")
seeds = pts[arc == 0.0]
ijk = np.rint(seeds / 2.0).astype(int)  # spacing 2 mm, origin 0
ids = ijk[:, 0] + 10 * (ijk[:, 1] + 10 * ijk[:, 2])
check(np.abs(fa[arc == 0.0] - fa_dipy[ids]).max() < 1e-5, "FA at the seeds = DIPY's FA")
check(set(np.unique(reasons)) <= {1, 3, 4, 5, 6, 8, 9, 10, 11}, "known reason codes")

# A circle field made with numpy.
n = 41
grid = vtkImageData()
grid.SetDimensions(n, n, 3)
grid.SetOrigin(-2, -2, -0.1)
grid.SetSpacing(0.1, 0.1, 0.1)
k, j, i = np.meshgrid(np.arange(3), np.arange(n), np.arange(n), indexing="ij")
x = -2 + 0.1 * i.ravel()
y = -2 + 0.1 * j.ravel()
a = 0.1
t = np.stack([a + y * y, a + x * x, a + 0 * x, -x * y, 0 * x, 0 * x], 1)
arr = numpy_to_vtk(np.ascontiguousarray(t), deep=1)
arr.SetName("T")
grid.GetPointData().SetTensors(arr)
seed_points = vtkPoints()
for r in (0.6, 1.0, 1.4):
    seed_points.InsertNextPoint(r, 0.0, 0.0)
seed_set = vtkPolyData()
seed_set.SetPoints(seed_points)
circles = splineviz.vtkTensorLineTracer()
circles.SetInputData(grid)
circles.SetSourceData(seed_set)
circles.SetStoppingFAThreshold(0.0)
circles.SetIntegrationStepUnit(splineviz.vtkTensorLineTracer.LENGTH_UNIT)
circles.SetIntegrationStep(0.02)
circles.SetMaximumPropagation(2.0)
circles.Update()
c = circles.GetOutput()
check(c.GetNumberOfLines() == 3, "three circle lines")
cp = vtk_to_numpy(c.GetPoints().GetData())
cids = vtk_to_numpy(c.GetCellData().GetArray("SeedIds"))
offsets = vtk_to_numpy(c.GetLines().GetOffsetsArray())
worst = 0.0
for line, seed in enumerate(cids):
    p = cp[offsets[line]:offsets[line + 1]]
    r0 = (0.6, 1.0, 1.4)[seed]
    worst = max(worst, np.abs(np.hypot(p[:, 0], p[:, 1]) - r0).max())
print("circle field: largest radius error %.2e" % worst)
check(worst < 2e-3, "the lines stay on their circles")
checker.finish()
