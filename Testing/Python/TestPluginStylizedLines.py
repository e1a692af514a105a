# SPDX-License-Identifier: BSD-3-Clause
"""pvbatch: the "Stylized Lines" representation of the SplineViz plugin on a
ParaView pipeline (the synthetic fibers source), with the tube radius
properties it shares with the tube representations and its own properties.
Checks that the lines are drawn as tubes (coverage well above that of
1-pixel lines and within 10 % of the ray-cast tubes of the same radii, which
follow splines through the points instead of the straight segments; the
exact comparison with vtkTubeFilter is TestStylizedLineReference; the
picture against its baseline image), that every documented property reaches
both mappers, that the halo in the background color changes the picture and
a texture pattern does too, and that picking reports the polyline."""
import sys

from paraview.simple import *  # noqa: F401,F403

import splineviz  # noqa: F401  (Python wrappers of the SplineViz classes)
from splineviz_testing import compare_baseline, fibers_scene
from splineviz_testing import coverage as image_coverage

LoadPlugin(sys.argv[1], remote=False, ns=globals())
fibers, view, display = fibers_scene(globals(), baseline=True)


def coverage(name):
    return image_coverage(view, name)


def fail(message):
    print("ERROR: " + message)
    sys.exit(1)


display.SetRepresentationType("Surface")
lines = coverage("TestPluginStylizedLines-lines.png")[0]

display.SetRepresentationType("Ray-Cast Tubes")
display.TubeRadiusArray = "Radius"
reference = coverage("TestPluginStylizedLines-raycast.png")[0]

display.SetRepresentationType("Stylized Lines")
display.TubeRadiusArray = "Radius"
stylized, plainPixels = coverage("TestPluginStylizedLines.png")
# The radius properties are shared with the tube representations: set while
# "Stylized Lines" is shown, they reach its mappers (not only the tubes').
display.TubeRadiusArray = "None"
display.TubeRadius = 0.02
Render(view)  # noqa: F405
if display.GetClientSideObject().GetActiveRepresentation().GetActor().GetMapper().GetRadius() != 0.02:
    fail("Tube Radius does not reach the stylized line mapper")
display.TubeRadiusArray = "Radius"
display.TubeRadius = 0.01
print("coverage: lines %.4f, ray-cast tubes %.4f, stylized lines %.4f" % (lines, reference, stylized))
if stylized < 2.0 * lines or stylized < 0.1:
    fail("the stylized lines did not render")
if abs(stylized - reference) > 0.1 * reference:
    fail("the stylized lines and the ray-cast tubes cover different areas")
# The picture itself, against its baseline (Testing/Data/Baseline).
compare_baseline(view, "TestPluginStylizedLines.png")

sub = display.GetClientSideObject().GetActiveRepresentation()
mapper = sub.GetActor().GetMapper()
print("active representation", sub.GetClassName(), "mapper", mapper.GetClassName())
if not mapper.IsA("vtkStylizedLineMapper"):
    fail("the representation does not use the stylized line mapper")
print("GPU bytes per segment: %.1f" % (mapper.GetGPUMemorySize() / 3530.0))

# Every documented property reaches both mappers (ParaView name -> mapper getter).
settings = {
    "TubeRadiusScale": ("RadiusScale", 1.25),
    "HaloWidth": ("HaloWidth", 0.3),
    "HaloColorFromBackground": ("HaloColorFromBackground", 0),
    "HaloDepthOffset": ("HaloDepthOffset", 3.0),
    "LineTexturePattern": ("TexturePattern", 2),
    "TextureRepeat": ("TextureRepeat", 5.0),
    "TextureRepeatUnits": ("TextureRepeatUnits", 1),
    "TextureCircumferentialRepeat": ("TextureCircumferentialRepeat", 3),
    "OrientationArray": ("OrientationArray", "Scalar"),
    "NormalMapping": ("NormalMapping", 1),
    "DepthCorrection": ("DepthCorrection", 0),
    "ExactSilhouette": ("ExactSilhouette", 0),
    "FixUp": ("FixUp", 0),
    "FixUpEpsilon": ("FixUpEpsilon", 0.05),
    "FixUpSides": ("FixUpSides", 24),
    "LineCapping": ("Capping", 0),
    "Shadows": ("Shadows", 1),
}
for name, (getter, value) in settings.items():
    setattr(display, name, value)
display.HaloColor = [1.0, 0.0, 0.0]
Render(view)  # noqa: F405
lod = sub.GetActor().GetLODMapper()
for m in [mapper] + ([lod] if lod else []):
    for name, (getter, value) in settings.items():
        got = getattr(m, "Get" + getter)()
        if isinstance(got, bool):
            got = int(got)
        if got != value:
            fail("property %s not forwarded: %r instead of %r" % (name, got, value))
    if list(m.GetHaloColor()) != [1.0, 0.0, 0.0]:
        fail("HaloColor not forwarded: %r" % (m.GetHaloColor(),))
coverage("TestPluginStylizedLines-settings.png")

# Back to the defaults, then a halo (background color) and a pattern each
# change the picture (the halo only where lines cross).
for name, value in {
    "TubeRadiusScale": 1.0,
    "HaloWidth": 0.0,
    "HaloColorFromBackground": 1,
    "LineTexturePattern": 0,
    "OrientationArray": "None",
    "NormalMapping": 0,
    "DepthCorrection": 1,
    "ExactSilhouette": 1,
    "FixUp": 1,
    "LineCapping": 1,
    "Shadows": 0,
}.items():
    setattr(display, name, value)
base = coverage("TestPluginStylizedLines-defaults.png")[1]


def changed(pixels):
    return sum(1 for a, b in zip(pixels, base) if a != b) / float(len(base))


display.HaloWidth = 0.4
halo = changed(coverage("TestPluginStylizedLines-halo.png")[1])
display.HaloWidth = 0.0
display.LineTexturePattern = 1
stripes = changed(coverage("TestPluginStylizedLines-stripes.png")[1])
display.LineTexturePattern = 0
display.Shadows = 1
shadows = changed(coverage("TestPluginStylizedLines-shadows.png")[1])
display.Shadows = 0
print("changed pixels: halo %.4f, stripes %.4f, shadows %.4f" % (halo, stripes, shadows))
if halo < 0.002 or stripes < 0.02 or shadows < 0.005:
    fail("the halo, the stripes or the shadows did not change the picture")

# Picking: cells selected on the lines' pixels are polylines of the fibers.
Render(view)  # noqa: F405
hits = 0
for x in range(200, 400, 20):
    SetActiveSource(fibers)  # noqa: F405
    SelectSurfaceCells(Rectangle=[x, 220, x + 4, 230])  # noqa: F405
    extract = ExtractSelection(Input=fibers)  # noqa: F405
    picked = servermanager.Fetch(extract)  # noqa: F405
    cells = picked.GetNumberOfCells()
    if cells > 0 and any(picked.GetCellType(i) != 4 for i in range(cells)):
        fail("picked a cell that is not a polyline")
    hits += 1 if cells > 0 else 0
    Delete(extract)  # noqa: F405
    ClearSelection(fibers)  # noqa: F405
    SetActiveSource(fibers)  # noqa: F405
print("picked polylines at %d of 10 places" % hits)
if hits < 3:
    fail("the lines were not picked")
