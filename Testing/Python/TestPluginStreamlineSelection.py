# SPDX-License-Identifier: BSD-3-Clause
"""pvbatch: the plugin's Select Streamlines filter on DIPY's real cb_2 bundle.

The default sphere (centre of the bounds, a tenth of the extent) selects
some but not all streamlines; a sphere set as its widget would, and a
rotated box (Position, Rotation, Scale as ParaView's box widget sets them),
select exactly the streamlines of a numpy reference (segment-to-centre
distance; the box by the separating-axis theorem in the frame of
T(position) Rz Rx Ry S applied to the unit cube). Negative controls: the
rotations in another order, and vertex sampling, disagree. Mark Streamlines
gives the "Selected" array; a radius of 0 fails with an error.
"""
import os
import sys

import numpy as np
from paraview import servermanager
from paraview.simple import *  # noqa: F401,F403
from vtkmodules.util.numpy_support import vtk_to_numpy

LoadPlugin(sys.argv[1], remote=False, ns=globals())

from splineviz_testing import Checker, Observed  # noqa: E402

checker = Checker()


check = checker.check


source_dir = os.environ.get("SPLINEVIZ_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
reader = XMLPolyDataReader(FileName=[os.path.join(source_dir, "Testing", "Data", "DIPY", "cb_2.vtp")])  # noqa: F405
reader.UpdatePipeline()
cb2 = servermanager.Fetch(reader)
points = vtk_to_numpy(cb2.GetPoints().GetData()).astype(np.float64)
offsets = vtk_to_numpy(cb2.GetLines().GetOffsetsArray())
lines = [points[offsets[i]:offsets[i + 1]] for i in range(len(offsets) - 1)]
N = len(lines)
A = np.concatenate([s[:-1] for s in lines])
B = np.concatenate([s[1:] for s in lines])
OWNER = np.concatenate([np.full(len(s) - 1, i) for i, s in enumerate(lines)])


def per_line(hit):
    out = np.zeros(N, dtype=bool)
    np.logical_or.at(out, OWNER, hit)
    return out


def sphere_reference(centre, radius):
    d = B - A
    t = np.clip(np.einsum("ij,ij->i", centre - A, d) / np.einsum("ij,ij->i", d, d), 0, 1)
    return per_line(np.linalg.norm(A + t[:, None] * d - centre, axis=1) <= radius)


def rot(axis, degrees):
    c, s = np.cos(np.radians(degrees)), np.sin(np.radians(degrees))
    i, j = [(1, 2), (2, 0), (0, 1)][axis]
    m = np.eye(3)
    m[i, i], m[i, j], m[j, i], m[j, j] = c, -s, s, c
    return m


def box_reference(position, rotation, scale, order=(2, 0, 1)):
    r = np.eye(3)
    for axis in order:
        r = r @ rot(axis, rotation[axis])
    to_world = np.eye(4)
    to_world[:3, :3] = r @ np.diag(scale)
    to_world[:3, 3] = position
    inv = np.linalg.inv(to_world)
    a = A @ inv[:3, :3].T + inv[:3, 3]
    b = B @ inv[:3, :3].T + inv[:3, 3]
    # Separating axes of a segment and the unit cube [0, 1]^3.
    c, h = np.full(3, 0.5), np.full(3, 0.5)
    m, w = 0.5 * (a + b) - c, 0.5 * (b - a)
    hit = np.all(np.abs(m) <= h + np.abs(w), axis=1)
    for i in range(3):
        e = np.zeros(3)
        e[i] = 1
        n = np.cross(e, w)
        hit &= np.abs(np.einsum("ij,ij->i", m, n)) <= np.abs(n) @ h
    return per_line(hit)


def selected(proxy):
    proxy.UpdatePipeline()
    out = servermanager.Fetch(proxy)
    pts = vtk_to_numpy(out.GetPoints().GetData()) if out.GetNumberOfPoints() else np.zeros((0, 3))
    offs = vtk_to_numpy(out.GetLines().GetOffsetsArray()) if out.GetNumberOfLines() else [0]
    # Identify each output streamline by its first point.
    firsts = {tuple(s[0]) : i for i, s in enumerate(lines)}
    got = np.zeros(N, dtype=bool)
    for k in range(len(offs) - 1):
        got[firsts[tuple(pts[offs[k]].astype(np.float64))]] = True
    return got


selection = SelectStreamlines(Input=reader)  # noqa: F405
b = cb2.GetBounds()
centre = np.array([(b[0] + b[1]) / 2, (b[2] + b[3]) / 2, (b[4] + b[5]) / 2])
radius = 0.1 * max(b[1] - b[0], b[3] - b[2], b[5] - b[4])
check(np.allclose(selection.SphereCenter, centre) and np.isclose(selection.SphereRadius, radius),
      "defaults: the sphere at the centre of the bounds, a tenth of the extent")
got = selected(selection)
expected = sphere_reference(centre, radius)
check(np.array_equal(got, expected),
      "default sphere: %d of %d streamlines, as the reference" % (got.sum(), N))

c = lines[40][9] + np.array([0.5, -0.3, 0.2])
selection.SphereCenter = list(c)
selection.SphereRadius = 4.0
got = selected(selection)
expected = sphere_reference(c, 4.0)
vertex = np.array([np.any(np.linalg.norm(s - c, axis=1) <= 4.0) for s in lines])
check(np.array_equal(got, expected) and 0 < got.sum() < N,
      "sphere moved as the widget would: %d streamlines, as the reference" % got.sum())

selection.SphereRole = "Exclude"
got = selected(selection)
check(np.array_equal(got, ~expected), "Exclude: the complement (%d)" % got.sum())

# A rotated box, with the sphere off.
selection.SphereRole = "Off"
selection.BoxRole = "Include"
position, rotation, scale = lines[40][9] - 6.0, [25.0, -40.0, 65.0], [15.0, 8.0, 12.0]
selection.BoxPosition = list(position)
selection.BoxRotation = rotation
selection.BoxLength = scale
got = selected(selection)
expected = box_reference(position, rotation, scale)
check(np.array_equal(got, expected) and 0 < got.sum() < N,
      "rotated box (Position, Rotation, Length): %d streamlines, as the reference" % got.sum())
check(not np.array_equal(box_reference(position, rotation, scale, order=(0, 1, 2)), expected),
      "negative control: the rotations applied in x, y, z order disagree")

# Sphere AND box; Mark Streamlines.
selection.SphereRole = "Include"
selection.OutputMode = "Mark Streamlines"
selection.UpdatePipeline()
out = servermanager.Fetch(selection)
marks = vtk_to_numpy(out.GetCellData().GetArray("Selected")).astype(bool)
both = sphere_reference(c, 4.0) & box_reference(position, rotation, scale)
check(out.GetNumberOfLines() == N and np.array_equal(marks, both) and 0 < both.sum(),
      "sphere AND box, Mark Streamlines: the Selected array as the reference (%d)" % both.sum())
selection.IncludeCombination = "OR"
selection.UpdatePipeline()
marks = vtk_to_numpy(servermanager.Fetch(selection).GetCellData().GetArray("Selected")).astype(bool)
either = sphere_reference(c, 4.0) | box_reference(position, rotation, scale)
check(np.array_equal(marks, either) and either.sum() > both.sum(), "OR (%d)" % either.sum())
check(not np.array_equal(vertex, sphere_reference(c, 4.0)),
      "negative control: vertex sampling misses streamlines that cross the sphere")

# Endpoint role, both ends, with a sphere large enough to hold some whole ends.
selection.BoxRole = "Off"
selection.SphereRole = "Endpoint"
selection.OutputMode = "Selected Streamlines"
end_centre = lines[50][0]
selection.SphereCenter = list(end_centre)
selection.SphereRadius = 30.0
for mode, both_ends in (("Either End", False), ("Both Ends", True)):
    selection.EndpointMode = mode
    got = selected(selection)
    first = np.array([np.linalg.norm(s[0] - end_centre) <= 30.0 for s in lines])
    last = np.array([np.linalg.norm(s[-1] - end_centre) <= 30.0 for s in lines])
    expected = (first & last) if both_ends else (first | last)
    touching = sphere_reference(end_centre, 30.0)
    check(np.array_equal(got, expected) and 0 < got.sum() < touching.sum(),
          "Endpoint, %s: %d streamlines (%d touch the sphere)" % (mode, got.sum(), touching.sum()))

# Bad input: radius 0 is an error (RequestData fails), the output empty.
errors = Observed(selection.GetClientSideObject())
selection.SphereRadius = 0.0
selection.UpdatePipeline()
out = servermanager.Fetch(selection)
check(any("radius <= 0" in m for m in errors.messages)
      and any("returned failure" in m for m in errors.messages) and out.GetNumberOfPoints() == 0,
      "radius 0: an error naming it, RequestData failed, an empty output")

checker.finish()
print("all passed")
