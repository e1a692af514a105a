# SPDX-License-Identifier: BSD-3-Clause
"""pvbatch: the "Ray-Cast Tubes" representation of the SplineViz plugin on a
ParaView pipeline (the synthetic fibers source), with a radius array,
scalar coloring and the ray-casting properties; checks that the tubes are
drawn (coverage well above that of 1-pixel lines, and the picture against
its baseline image) and that the properties reach the mapper; then the
endpoint markers (a property the tube representations share)."""
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
lines = coverage("TestPluginRayCastTubes-lines.png")

display.SetRepresentationType("Ray-Cast Tubes")
display.TubeRadiusArray = "Radius"
display.TubeRadiusScale = 1.0
display.SubSegments = 4
display.RootIterations = 12
display.StraightTolerance = 0.05
display.OcclusionCulling = 1
tubes = coverage("TestPluginRayCastTubes.png")
print("coverage: lines %.3f, ray-cast tubes %.3f" % (lines, tubes))
if tubes < 2.0 * lines or tubes < 0.1:
    print("ERROR: the ray-cast tubes did not render")
    sys.exit(1)
# The picture itself, against its baseline (Testing/Data/Baseline).
compare_baseline(view, "TestPluginRayCastTubes.png")

# The properties reached the mapper on the (local) server.
sub = display.GetClientSideObject().GetActiveRepresentation()
mapper = sub.GetActor().GetMapper()
print("active representation", sub.GetClassName(), "mapper", mapper.GetClassName())
if not mapper.IsA("vtkRayCastTubeMapper"):
    print("ERROR: the representation does not use the ray-cast tube mapper")
    sys.exit(1)
forwarded = (mapper.GetSubSegments(), mapper.GetRootIterations(), mapper.GetRadiusArray(),
             round(mapper.GetStraightTolerance(), 6), mapper.GetOcclusionCulling())
if forwarded != (4, 12, "Radius", 0.05, True):
    print("ERROR: properties not forwarded:", forwarded)
    sys.exit(1)
if mapper.GetLastNumberOfDepthPyramids() == 0:
    print("ERROR: occlusion culling was not used")
    sys.exit(1)
display.OcclusionCulling = 0
print("GPU bytes per segment: %.1f" % (mapper.GetGPUMemorySize() / 3530.0))

# A constant radius twice as large covers more.
display.TubeRadiusArray = "None"
display.TubeRadius = 0.02
thick = coverage("TestPluginRayCastTubes-constant.png")
print("coverage: constant radius 0.02: %.3f" % thick)
if thick <= tubes:
    print("ERROR: the constant radius was not applied")
    sys.exit(1)

# Endpoint markers: 2 per polyline, in their color, on both line mappers
# that share the property (the tessellated tubes get it too).
def marker_colored(name):
    pixels = image_coverage(view, name)[1]
    return sum(1 for r, g, b in pixels if r > 230 and 190 < g < 240 and b < 40)


before = marker_colored("TestPluginRayCastTubes-no-endpoints.png")
display.EndpointMarkers = 1
display.EndpointMarkerColor = [1.0, 0.85, 0.0]
yellow = marker_colored("TestPluginRayCastTubes-endpoints.png")
lines = fibers.GetDataInformation().GetNumberOfCells()
markers = mapper.GetNumberOfEndpointMarkers()
print("endpoint markers: %d for %d lines; sampled pixels of their color %d (without: %d)" % (
    markers, lines, yellow, before))
if markers != 2 * lines or yellow < before + 100:
    print("ERROR: the endpoint markers were not drawn")
    sys.exit(1)
display.SetRepresentationType("Tessellated Tubes")
Render(view)
tess = display.GetClientSideObject().GetActiveRepresentation().GetActor().GetMapper()
if not tess.GetEndpointMarkers() or tess.GetNumberOfEndpointMarkers() != 2 * lines:
    print("ERROR: the tessellated tubes did not get the endpoint markers")
    sys.exit(1)
