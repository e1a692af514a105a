# SPDX-License-Identifier: BSD-3-Clause
"""The `splineviz` Python package: every public class imports and works in an
ordinary VTK pipeline."""
import sys

import splineviz
from splineviz import vtkSplineTubeCore, vtkSyntheticFibersSource

expected = {
    "vtkSplineTubeCore",
    "vtkSyntheticFibersSource",
    "vtkSplineTubeMapper",
    "vtkRayCastTubeMapper",
    "vtkTessellatedTubeMapper",
    "vtkTensorAnalysisFilter",
    "vtkSuperquadricGlyphMapper",
}
abstract = {"vtkSplineTubeMapper", "vtkNIfTIReaderBase"}
missing = expected - set(splineviz.__all__)
if missing:
    print("ERROR: classes missing from splineviz:", sorted(missing))
    sys.exit(1)
for name in splineviz.__all__:
    cls = getattr(splineviz, name)
    if name in abstract:
        continue
    obj = cls()  # every concrete exported class can be instantiated
    if not obj.IsA(name):
        print("ERROR:", name, "instantiates as", obj.GetClassName())
        sys.exit(1)

source = vtkSyntheticFibersSource()
source.SetPresetToFibers()
source.Update()
out = source.GetOutput()
assert out.GetNumberOfLines() == 241, out.GetNumberOfLines()
assert out.GetNumberOfPoints() - out.GetNumberOfLines() == 3530

core = vtkSplineTubeCore()
core.SetRadiusArrayName("Radius")
assert core.AddPolyData(out, None, 0)
core.Build()
assert core.GetNumberOfSegments() == 3530, core.GetNumberOfSegments()
assert core.GetNumberOfNodes() == 3771, core.GetNumberOfNodes()
assert core.GetNumberOfChunks() == core.GetTubeFirstChunks().GetValue(241)
xyzr = [0.0] * 4
core.GetNode(5, xyzr)
assert xyzr[3] > 0.0, xyzr
print("splineviz package OK:", ", ".join(splineviz.__all__))
