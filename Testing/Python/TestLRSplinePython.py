"""The LR-spline classes from Python (`splineviz`): read the real file, probe
it, resample it, and check the values against the identity map that the
first patch of cube-3patch-refined.lr represents."""
import os
import random
import sys

from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData

import splineviz

data = os.path.join(os.environ["SPLINEVIZ_SOURCE_DIR"], "..", "shared", "data", "external")
reader = splineviz.vtkLRSplineReader()
reader.SetFileName(os.path.join(data, "cube-3patch-refined.lr"))
reader.SetFieldName("position")
reader.Update()
mb = reader.GetOutput()
assert mb.GetNumberOfBlocks() == 3, mb.GetNumberOfBlocks()
patch = mb.GetBlock(0)
assert patch.GetNumberOfCells() == 1240
assert patch.GetFieldData().GetArray("LRNumberOfBasisFunctions").GetValue(0) == 1176

points = vtkPoints()
random.seed(1)
for _ in range(1000):
    points.InsertNextPoint(random.random(), random.random(), random.random())
cloud = vtkPolyData()
cloud.SetPoints(points)

probe = splineviz.vtkLRSplineProbeFilter()
probe.SetInputData(cloud)
probe.SetSourceConnection(reader.GetOutputPort())
probe.ComputeGradientOn()
probe.Update()
out = probe.GetOutput()
field = out.GetPointData().GetArray("position")
grad = out.GetPointData().GetArray("Gradient")
worst = 0.0
for i in range(out.GetNumberOfPoints()):
    x = out.GetPoint(i)
    v = field.GetTuple3(i)
    g = grad.GetTuple9(i)
    worst = max(worst, max(abs(v[k] - x[k]) for k in range(3)))
    worst = max(worst, abs(g[0] - 1.0), abs(g[4] - 1.0), abs(g[8] - 1.0), abs(g[1]))
print("identity map through the probe: max error", worst)
if worst > 1e-12:
    print("ERROR: probe values are wrong")
    sys.exit(1)

resample = splineviz.vtkLRSplineResampleToImage()
resample.SetInputConnection(reader.GetOutputPort())
resample.SetSamplingDimensions(5, 6, 7)
resample.Update()
img = resample.GetOutput()
assert img.GetNumberOfPoints() == 5 * 6 * 7
arr = img.GetPointData().GetArray("position")
for i in range(img.GetNumberOfPoints()):
    x = img.GetPoint(i)
    v = arr.GetTuple3(i)
    assert max(abs(v[k] - x[k]) for k in range(3)) < 1e-12, (x, v)
print("LR-spline Python OK")
