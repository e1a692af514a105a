# SPDX-License-Identifier: BSD-3-Clause
"""The `splineviz` Python package: every public class imports and works in an
ordinary VTK pipeline."""
import sys

import splineviz
from splineviz import vtkSplineTubeCore, vtkSyntheticFibersSource
from vtkmodules.vtkCommonDataModel import vtkDataObject

expected = {
    "vtkSplineTubeCore",
    "vtkSyntheticFibersSource",
    "vtkSplineTubeMapper",
    "vtkRayCastTubeMapper",
    "vtkTessellatedTubeMapper",
    "vtkTensorAnalysisFilter",
    "vtkSuperquadricGlyphMapper",
}
abstract = {"vtkSplineTubeMapper", "vtkNIfTIReaderBase", "vtkLRSplineFitterBase"}
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
core.SetRadiusArray("Radius")
assert core.AddPolyData(out, None, 0)
core.Build()
assert core.GetNumberOfSegments() == 3530, core.GetNumberOfSegments()
assert core.GetNumberOfNodes() == 3771, core.GetNumberOfNodes()
assert core.GetNumberOfChunks() == core.GetTubeFirstChunks().GetValue(241)
xyzr = [0.0] * 4
core.GetNode(5, xyzr)
assert xyzr[3] > 0.0, xyzr
# The deprecated property names (kept for one release; TestSplineVizDeprecatedNames
# checks them in C++) are wrapped too and forward to the new names.
renamed = [
    ("vtkLRSplineReader", "FieldName", "OutputFieldName"),
    ("vtkLRSplineImageFitter", "FieldName", "OutputFieldName"),
    ("vtkLRSplineFitter", "FieldName", "OutputFieldName"),
    ("vtkLRSplineVolumeMapper", "FieldArrayName", "FieldArray"),
    ("vtkSplineTubeCore", "RadiusArrayName", "RadiusArray"),
    ("vtkSplineTubeCore", "NodeScalarArrayName", "NodeScalarArray"),
    ("vtkSplineTubeCore", "CellIdArrayName", "CellIdArray"),
    ("vtkRayCastTubeMapper", "CellIdArrayName", "CellIdArray"),
    ("vtkTessellatedTubeMapper", "CellIdArrayName", "CellIdArray"),
    ("vtkStylizedLineMapper", "CellIdArrayName", "CellIdArray"),
    ("vtkSuperquadricGlyphMapper", "TensorArrayName", "TensorArray"),
    ("vtkSuperquadricGlyphMapper", "MaskArrayName", "MaskArray"),
]
for name, old, new in renamed:
    obj = getattr(splineviz, name)()
    getattr(obj, "Set" + old)("a")
    if getattr(obj, "Get" + new)() != "a":
        print("ERROR: %s.Set%s does not set %s" % (name, old, new))
        sys.exit(1)
    getattr(obj, "Set" + new)("b")
    if getattr(obj, "Get" + old)() != "b":
        print("ERROR: %s.Get%s does not read %s" % (name, old, new))
        sys.exit(1)
# The filters' old ArrayName / MaskArrayName select an input array (index, port).
for name, old, idx, port in [("vtkLRSplineProbeFilter", "ArrayName", 0, 1),
                             ("vtkLRSplineResampleToImage", "ArrayName", 0, 0),
                             ("vtkLRSplineStreamTracer", "ArrayName", 0, 0),
                             ("vtkTensorLineTracer", "MaskArrayName", 1, 0)]:
    obj = getattr(splineviz, name)()
    getattr(obj, "Set" + old)("a")
    info = obj.GetInputArrayInformation(idx)
    if info.Get(vtkDataObject.FIELD_NAME()) != "a" or info.Get(obj.INPUT_PORT()) != port:
        print("ERROR: %s.Set%s does not select input array %d on port %d" % (name, old, idx, port))
        sys.exit(1)
    obj.SetInputArrayToProcess(idx, port, 0, vtkDataObject.FIELD_ASSOCIATION_POINTS, "b")
    if getattr(obj, "Get" + old)() != "b":
        print("ERROR: %s.Get%s does not read input array %d" % (name, old, idx))
        sys.exit(1)

print("splineviz package OK:", ", ".join(splineviz.__all__))
