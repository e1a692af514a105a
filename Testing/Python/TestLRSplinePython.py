# SPDX-License-Identifier: BSD-3-Clause
"""The LR-spline classes from Python (`splineviz`): read the real file, probe
it, resample it, and check the values against the identity map that the
first patch of cube-3patch-refined.lr represents."""
import os
import random
import sys

from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData

import splineviz

data = os.path.join(os.environ["SPLINEVIZ_SOURCE_DIR"], "Testing", "Data", "External")
reader = splineviz.vtkLRSplineReader()
reader.SetFileName(os.path.join(data, "cube-3patch-refined.lr"))
reader.SetOutputFieldName("position")
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

# Streamlines through patch 1 (v = (-y, x, z)): circles about the z axis,
# z growing like e^t.
import math  # noqa: E402

from vtkmodules.vtkFiltersSources import vtkLineSource  # noqa: E402

seeds = vtkLineSource()
seeds.SetPoint1(0.3, 0.05, 0.1)
seeds.SetPoint2(0.9, 0.05, 0.1)
seeds.SetResolution(5)
seeds.SetOutputPointsPrecision(1)  # double
tracer = splineviz.vtkLRSplineStreamTracer()
tracer.SetInputData(mb.GetBlock(1))
tracer.SetSourceConnection(seeds.GetOutputPort())
tracer.SetIntegratorType(splineviz.vtkLRSplineStreamTracer.RUNGE_KUTTA4)
tracer.SetStepMode(splineviz.vtkLRSplineStreamTracer.FIXED_TIME)
tracer.SetIntegrationStep(0.01)
tracer.SetIntegrationDirection(splineviz.vtkLRSplineStreamTracer.FORWARD)
tracer.Update()
lines = tracer.GetOutput()
assert lines.GetNumberOfLines() == 6, lines.GetNumberOfLines()
t = lines.GetPointData().GetArray("IntegrationTime")
worst = 0.0
for c in range(lines.GetNumberOfLines()):
    cell = lines.GetCell(c)
    x0 = lines.GetPoint(cell.GetPointId(0))
    for k in range(cell.GetNumberOfPoints() - 1):
        i = cell.GetPointId(k)
        ti = t.GetValue(i)
        ca, sa = math.cos(ti), math.sin(ti)
        exact = (ca * x0[0] - sa * x0[1], sa * x0[0] + ca * x0[1], x0[2] * math.exp(ti))
        p = lines.GetPoint(i)
        worst = max(worst, max(abs(p[j] - exact[j]) for j in range(3)))
print("stream tracer vs exact solution: max error", worst)
if worst > 1e-8:
    print("ERROR: the streamlines are wrong")
    sys.exit(1)
print("LR-spline tracer from Python OK")
