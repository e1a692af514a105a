# SPDX-License-Identifier: BSD-3-Clause
"""pvbatch: the "Tessellated Tubes" representation of the SplineViz plugin on
a ParaView pipeline (the synthetic fibers source), with a radius array,
scalar coloring and the tessellation properties. Checks that the tubes are
drawn (coverage well above that of 1-pixel lines and close to the ray-cast
tubes of the same radii; the picture against its baseline image), that
every documented property reaches both mappers, and that the refinement properties act (a GL_PRIMITIVES_GENERATED
count of the mapper: the base mesh alone generates fewer triangles)."""
import sys

from paraview.simple import *  # noqa: F401,F403

import splineviz  # noqa: F401  (Python wrappers of the SplineViz classes)
from splineviz_testing import compare_baseline, fibers_scene
from splineviz_testing import coverage as image_coverage

LoadPlugin(sys.argv[1], remote=False, ns=globals())
fibers, view, display = fibers_scene(globals(), baseline=True)


def coverage(name):
    return image_coverage(view, name)[0]


display.SetRepresentationType("Surface")
lines = coverage("TestPluginTessellatedTubes-lines.png")

display.SetRepresentationType("Ray-Cast Tubes")
display.TubeRadiusArray = "Radius"
rayCast = coverage("TestPluginTessellatedTubes-raycast.png")

display.SetRepresentationType("Tessellated Tubes")
display.TubeRadiusArray = "Radius"
display.TubeRadiusScale = 1.0
tubes = coverage("TestPluginTessellatedTubes.png")
print("coverage: lines %.4f, ray-cast tubes %.4f, tessellated tubes %.4f" % (lines, rayCast, tubes))
if tubes < 2.0 * lines or tubes < 0.1:
    print("ERROR: the tessellated tubes did not render")
    sys.exit(1)
# Same radii: nearly the same coverage (flat instead of round caps).
if abs(tubes - rayCast) > 0.05 * rayCast:
    print("ERROR: the tessellated and ray-cast tubes cover different areas")
    sys.exit(1)
# The picture itself, against its baseline (Testing/Data/Baseline).
compare_baseline(view, "TestPluginTessellatedTubes.png")

sub = display.GetClientSideObject().GetActiveRepresentation()
mapper = sub.GetActor().GetMapper()
print("active representation", sub.GetClassName(), "mapper", mapper.GetClassName())
if not mapper.IsA("vtkTessellatedTubeMapper"):
    print("ERROR: the representation does not use the tessellated tube mapper")
    sys.exit(1)
print("GPU bytes per segment: %.1f" % (mapper.GetGPUMemorySize() / 3530.0))

# Every documented property reaches both mappers.
settings = {
    "MaxEdgeLength": 12.0,
    "MaxSilhouetteEdgeLength": 3.0,
    "MaxTessellationLevel": 6,
    "MaxSilhouetteTessellationLevel": 9,
    "BaseRings": 12,
    "BaseSides": 6,
    "LevelOfDetail": 0,
    "Capping": 0,
}
for name, value in settings.items():
    setattr(display, name, value)
Render(view)  # noqa: F405
lod = sub.GetActor().GetLODMapper()
for m in [mapper] + ([lod] if lod else []):
    got = {name: getattr(m, "Get" + name)() for name in settings}
    got = {k: (int(v) if isinstance(v, bool) else v) for k, v in got.items()}
    if got != settings:
        print("ERROR: properties not forwarded:", got)
        sys.exit(1)

# The refinement acts: count the triangles with and without it.
mapper.CountPrimitivesOn()
Render(view)  # noqa: F405
refined = mapper.GetNumberOfPrimitivesGenerated()
display.MaxTessellationLevel = 1
display.MaxSilhouetteTessellationLevel = 1
Render(view)  # noqa: F405
base = mapper.GetNumberOfPrimitivesGenerated()
print("triangles: refined %d, base mesh %d" % (refined, base))
if not (base > 0 and refined > 1.2 * base):
    print("ERROR: the tessellation levels had no effect")
    sys.exit(1)

# A constant radius twice as large covers more.
display.TubeRadiusArray = "None"
display.TubeRadius = 0.02
display.LevelOfDetail = 1
display.Capping = 1
thick = coverage("TestPluginTessellatedTubes-constant.png")
print("coverage: constant radius 0.02: %.4f" % thick)
if thick <= tubes:
    print("ERROR: the constant radius was not applied")
    sys.exit(1)

# Level of detail: while the camera moves ParaView draws the LOD mapper,
# which has the full mapper draw a subset of its data: no second tube core,
# no second upload, and the picture still shows the tubes. (Before, the LOD
# mapper built and uploaded its own copy at the first camera move.)
view.LODThreshold = 0.0  # LOD for any data size
core_time = mapper.GetTubeCore().GetMTime()
view.CameraPosition = [1.02 * p for p in view.CameraPosition]
view.InteractiveRender()
lod = sub.GetActor().GetLODMapper()
moving = coverage("TestPluginTessellatedTubes-interactive.png")
print("interactive: LOD mapper %s of the full mapper, its core %d segments, its GPU bytes %d; "
      "the full mapper's core modified at %d (before %d), coverage %.4f"
      % ("stand-in" if lod.GetLevelOfDetailOf() == mapper else "NOT a stand-in",
         lod.GetTubeCore().GetNumberOfSegments(), lod.GetGPUMemorySize(),
         mapper.GetTubeCore().GetMTime(), core_time, moving))
if lod.GetLevelOfDetailOf() != mapper or lod.GetTubeCore().GetNumberOfSegments() != 0 or \
        lod.GetGPUMemorySize() != 0:
    print("ERROR: the LOD mapper holds data of its own")
    sys.exit(1)
if mapper.GetTubeCore().GetMTime() != core_time:
    print("ERROR: the interactive frame built the data again")
    sys.exit(1)
if moving < 0.5 * thick:
    print("ERROR: the interactive frame drew too little")
    sys.exit(1)
if list(lod.GetBounds()) != list(mapper.GetBounds()):
    print("ERROR: the LOD mapper's bounds %s differ from the data's %s"
          % (list(lod.GetBounds()), list(mapper.GetBounds())))
    sys.exit(1)
# Control: a change that rebuilds the data does change the core's time.
display.TubeRadius = 0.03
Render(view)  # noqa: F405
if mapper.GetTubeCore().GetMTime() == core_time:
    print("ERROR: control: a new radius did not rebuild the core (the check above sees nothing)")
    sys.exit(1)
