# SPDX-License-Identifier: BSD-3-Clause
"""vtkStreamlineSelection against a brute-force numpy reference.

DIPY's real cb_2 bundle (116 streamlines, float32, mm) with random spheres,
axis-aligned and oriented boxes (AddSphere, AddBox, AddOrientedBox, and the
same shapes as vtkSphere / vtkBox implicit functions under a linear
Transform): the selected streamline sets must be identical to the
reference's for INCLUDE, EXCLUDE and ENDPOINT (either end, both ends) roles,
combined with AND and OR. The reference is written here independently: a
segment touches a sphere when its closest point to the centre is within the
radius, and a box when no separating axis exists (the separating-axis
theorem for a segment and a box, not the filter's slab clipping). A general
implicit function (vtkCylinder, sampled along segments) selects a subset of
the exact set and misses only streamlines that come within one sampling step
of the surface; a half-space (vtkPlane) is exact. A segment that crosses a
sphere with no vertex inside must be selected, and a point-sampling
reference must miss it and disagree on cb_2 (negative controls, as is a
reference given a shifted centre). The output keeps the point and cell data
of the selected streamlines; MARK_STREAMLINES gives the "Selected" array
instead; composite input is processed leaf by leaf; abort gives an empty
output. Bad input (radius <= 0 or NaN, min > max, a singular box map, a null
function) fails with a clear error; no regions selects everything with a
warning.
"""
import os
import sys

import numpy as np

try:
    from dipy.data import get_fnames
except ImportError as error:
    print("DIPY not available (python3-dipy), skipped:", error)
    sys.exit(125)

from vtkmodules.util.numpy_support import numpy_to_vtk, numpy_to_vtkIdTypeArray, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkCommand, vtkPoints
from vtkmodules.vtkCommonDataModel import (vtkBox, vtkCellArray, vtkCylinder, vtkMultiBlockDataSet,
                                           vtkPlane, vtkPolyData, vtkSphere)
from vtkmodules.vtkCommonMath import vtkMatrix4x4
from vtkmodules.vtkCommonTransforms import vtkTransform

import splineviz

from splineviz_testing import Checker, Observed  # noqa: E402

checker = Checker()
rng = np.random.default_rng(2929)
S = splineviz.vtkStreamlineSelection


check = checker.check


def polydata(streamlines):
    """Polylines from a list of (n, 3) arrays, with a point and a cell array."""
    points = np.concatenate(streamlines).astype(np.float32)
    offsets = np.r_[0, np.cumsum([len(s) for s in streamlines])].astype(np.int64)
    pd = vtkPolyData()
    vp = vtkPoints()
    vp.SetData(numpy_to_vtk(points, deep=True))
    pd.SetPoints(vp)
    cells = vtkCellArray()
    cells.SetData(numpy_to_vtkIdTypeArray(offsets, deep=True),
                  numpy_to_vtkIdTypeArray(np.arange(len(points), dtype=np.int64), deep=True))
    pd.SetLines(cells)
    pid = numpy_to_vtk(np.arange(len(points), dtype=np.float64), deep=True)
    pid.SetName("PointIndex")
    pd.GetPointData().AddArray(pid)
    cid = numpy_to_vtk(np.arange(len(streamlines), dtype=np.int32), deep=True)
    cid.SetName("StreamlineIndex")
    pd.GetCellData().AddArray(cid)
    return pd


cb = np.load(os.path.join(os.path.dirname(get_fnames("small_64D")[0]), "cb_2.npz"))
ends = np.asarray(cb["offsets"], dtype=np.int64)
starts = np.r_[0, ends[:-1]]
streamlines = [np.asarray(cb["points"][s:e], dtype=np.float64) for s, e in zip(starts, ends)]
cb2 = polydata(streamlines)
print("cb_2: %d streamlines, %d points" % (len(streamlines), cb2.GetNumberOfPoints()))


# --- the reference ------------------------------------------------------------
def segments(lines):
    a = np.concatenate([s[:-1] for s in lines])
    b = np.concatenate([s[1:] for s in lines])
    owner = np.concatenate([np.full(len(s) - 1, i) for i, s in enumerate(lines)])
    return a, b, owner


SEG = segments(streamlines)


def per_streamline(hit, owner, count):
    out = np.zeros(count, dtype=bool)
    np.logical_or.at(out, owner, hit)
    return out


def segment_sphere(a, b, centre, radius):
    """Distance from centre to each segment <= radius."""
    d = b - a
    t = np.einsum("ij,ij->i", centre - a, d) / np.einsum("ij,ij->i", d, d)
    t = np.clip(np.nan_to_num(t), 0.0, 1.0)
    closest = a + t[:, None] * d
    return np.linalg.norm(closest - centre, axis=1) <= radius


def segment_box_sat(a, b, lo, hi):
    """Separating-axis test of segments [a, b] against the box [lo, hi] (touching counts)."""
    c = 0.5 * (lo + hi)
    h = 0.5 * (hi - lo)
    m = 0.5 * (a + b) - c
    w = 0.5 * (b - a)
    eps = 1e-12 * (1.0 + np.abs(c).max() + h.max())
    overlap = np.all(np.abs(m) <= h + np.abs(w) + eps, axis=1)
    for i in range(3):
        axis = np.zeros(3)
        axis[i] = 1.0
        n = np.cross(axis, w)  # e_i x w
        overlap &= np.abs(np.einsum("ij,ij->i", m, n)) <= np.abs(n) @ h + eps
    return overlap


def in_sphere(p, centre, radius):
    return np.linalg.norm(p - centre, axis=1) <= radius


def in_box(p, lo, hi):
    return np.all((p >= lo) & (p <= hi), axis=1)


class RefRegion:
    """A region as the reference sees it: world -> local affine (or none) and a shape."""

    def __init__(self, kind, role, centre=None, radius=None, lo=None, hi=None, to_local=None):
        self.kind, self.role = kind, role
        self.centre, self.radius, self.lo, self.hi = centre, radius, lo, hi
        self.to_local = to_local  # 4x4 world -> local

    def local(self, p):
        if self.to_local is None:
            return p
        return p @ self.to_local[:3, :3].T + self.to_local[:3, 3]

    def touches(self, lines, seg):
        a, b, owner = seg
        a, b = self.local(a), self.local(b)
        if self.kind == "sphere":
            hit = segment_sphere(a, b, self.centre, self.radius)
        else:
            hit = segment_box_sat(a, b, self.lo, self.hi)
        return per_streamline(hit, owner, len(lines))

    def contains(self, p):
        p = self.local(p)
        if self.kind == "sphere":
            return in_sphere(p, self.centre, self.radius)
        return in_box(p, self.lo, self.hi)

    def ends(self, lines, both):
        first = self.contains(np.array([s[0] for s in lines]))
        last = self.contains(np.array([s[-1] for s in lines]))
        return (first & last) if both else (first | last)


def reference(lines, seg, regions, combine_and, both):
    keep = np.ones(len(lines), dtype=bool)
    includes = []
    for r in regions:
        if r.role == S.EXCLUDE:
            keep &= ~r.touches(lines, seg)
        elif r.role == S.INCLUDE:
            includes.append(r.touches(lines, seg))
        else:
            includes.append(r.ends(lines, both))
    if includes:
        stack = np.array(includes)
        keep &= stack.all(axis=0) if combine_and else stack.any(axis=0)
    return keep


# --- random regions -------------------------------------------------------------
ALL_POINTS = np.concatenate(streamlines)


def random_rotation():
    q, r = np.linalg.qr(rng.normal(size=(3, 3)))
    q = q @ np.diag(np.sign(np.diag(r)))
    if np.linalg.det(q) < 0:
        q[:, 0] = -q[:, 0]
    return q


def random_region(role, kind):
    """(a function adding the region to a filter, the reference region)."""
    centre = ALL_POINTS[rng.integers(len(ALL_POINTS))] + rng.normal(scale=2.0, size=3)
    if kind in ("sphere", "vtkSphere"):
        radius = rng.uniform(1.0, 8.0)
        if kind == "sphere":
            return (lambda f: f.AddSphere(list(centre), radius, role),
                    RefRegion("sphere", role, centre=centre, radius=radius))
        # An ellipsoid: a vtkSphere under a scaling, rotating transform (world -> sphere frame).
        m = np.eye(4)
        m[:3, :3] = np.diag(rng.uniform(0.5, 1.5, 3)) @ random_rotation()
        m[:3, 3] = rng.normal(scale=3.0, size=3)
        local_centre = m[:3, :3] @ centre + m[:3, 3]
        fn = vtkSphere()
        fn.SetCenter(*local_centre)
        fn.SetRadius(radius)
        t = vtkTransform()
        t.SetMatrix(m.ravel())
        fn.SetTransform(t)
        return (lambda f: f.AddImplicitFunction(fn, role),
                RefRegion("sphere", role, centre=local_centre, radius=radius, to_local=m))
    half = rng.uniform(1.0, 8.0, 3)
    lo, hi = centre - half, centre + half
    if kind == "box":
        return (lambda f: f.AddBox(list(np.c_[lo, hi].ravel()), role),
                RefRegion("box", role, lo=lo, hi=hi))
    # Oriented: the box [-half, half] rotated, sheared a little, moved to centre.
    to_world = np.eye(4)
    to_world[:3, :3] = random_rotation() @ (np.eye(3) + rng.uniform(-0.3, 0.3, (3, 3)))
    to_world[:3, 3] = centre
    to_local = np.linalg.inv(to_world)
    if kind == "oriented":
        matrix = vtkMatrix4x4()
        matrix.DeepCopy(to_world.ravel())
        return (lambda f: f.AddOrientedBox(list(np.c_[-half, half].ravel()), matrix, role),
                RefRegion("box", role, lo=-half, hi=half, to_local=to_local))
    fn = vtkBox()
    fn.SetBounds(list(np.c_[-half, half].ravel()))
    t = vtkTransform()
    t.SetMatrix(to_local.ravel())
    fn.SetTransform(t)
    return (lambda f: f.AddImplicitFunction(fn, role),
            RefRegion("box", role, lo=-half, hi=half, to_local=to_local))


def run(data, adders, combine_and=True, both=False, mark=False):
    f = S()
    f.SetInputData(data)
    for add in adders:
        add(f)
    f.SetIncludeCombination(S.COMBINE_AND if combine_and else S.COMBINE_OR)
    f.SetEndpointMode(S.BOTH_ENDS if both else S.EITHER_END)
    f.SetOutputMode(S.MARK_STREAMLINES if mark else S.SELECTED_STREAMLINES)
    errors = Observed(f)
    f.Update()
    return f, errors


def selected_ids(out):
    return vtk_to_numpy(out.GetCellData().GetArray("StreamlineIndex"))


# --- 1. random regions on cb_2 ------------------------------------------------------
KINDS = ("sphere", "box", "oriented", "vtkSphere", "vtkBox")
ROLES = (S.INCLUDE, S.EXCLUDE, S.ENDPOINT)
mismatches = 0
trials = 0
nontrivial = 0
sampling_disagrees = 0
for trial in range(200):
    count = 1 + trial % 3
    regions = [random_region(ROLES[rng.integers(3)], KINDS[rng.integers(len(KINDS))])
               for _ in range(count)]
    combine_and = bool(rng.integers(2))
    both = bool(rng.integers(2))
    expected = reference(streamlines, SEG, [r for _, r in regions], combine_and, both)
    f, errors = run(cb2, [a for a, _ in regions], combine_and, both)
    got = np.zeros(len(streamlines), dtype=bool)
    got[selected_ids(f.GetOutput())] = True
    trials += 1
    if errors.errors or not np.array_equal(got, expected):
        mismatches += 1
        if mismatches <= 3:
            print("  trial %d: %d differ; errors %s" % (trial, np.sum(got != expected), errors.messages))
    if 0 < expected.sum() < len(streamlines):
        nontrivial += 1
    # Point sampling (vertices only) as a control: it must disagree somewhere.
    vertex_regions = [r for _, r in regions]
    vertex_keep = np.ones(len(streamlines), dtype=bool)
    inc = []
    for r in vertex_regions:
        inside = np.array([r.contains(s).any() for s in streamlines])
        if r.role == S.EXCLUDE:
            vertex_keep &= ~inside
        elif r.role == S.INCLUDE:
            inc.append(inside)
        else:
            inc.append(r.ends(streamlines, both))
    if inc:
        vertex_keep &= np.array(inc).all(axis=0) if combine_and else np.array(inc).any(axis=0)
    sampling_disagrees += int(not np.array_equal(vertex_keep, expected))
check(mismatches == 0, "cb_2, %d random region sets (spheres, boxes, oriented boxes, transformed "
      "vtkSphere / vtkBox; INCLUDE / EXCLUDE / ENDPOINT; AND / OR; either / both ends): "
      "identical streamline sets (%d differ)" % (trials, mismatches))
check(nontrivial > trials // 3, "the trials are not trivial: %d select some but not all" % nontrivial)
check(sampling_disagrees > 0, "negative control: vertex sampling disagrees with the exact "
      "reference in %d trials" % sampling_disagrees)

# The reference itself can fail: a sphere moved by 1.5 mm changes the set.
c0 = streamlines[10][9]
moved = reference(streamlines, SEG, [RefRegion("sphere", S.INCLUDE, centre=c0 + 1.5, radius=3.0)],
                  True, False)
f, _ = run(cb2, [lambda f: f.AddSphere(list(c0), 3.0, S.INCLUDE)])
got = np.zeros(len(streamlines), dtype=bool)
got[selected_ids(f.GetOutput())] = True
check(not np.array_equal(got, moved), "negative control: a reference with the centre moved "
      "1.5 mm disagrees")

# --- 2. a segment crossing a sphere with no vertex inside ------------------------------
crossing = [np.array([[-1.0, 0.5, 0.0], [1.0, 0.5, 0.0]]),  # passes 0.5 from the centre
            np.array([[-1.0, 0.7, 0.0], [1.0, 0.7, 0.0]]),  # passes 0.7 from it
            np.array([[0.0, 0.0, 0.3]])]                    # a single point inside
pd = polydata(crossing)
f, _ = run(pd, [lambda f: f.AddSphere(0, 0, 0, 0.6, S.INCLUDE)])
got = sorted(selected_ids(f.GetOutput()).tolist())
check(got == [0, 2], "a segment crossing a sphere with no vertex inside is selected, one passing "
      "outside is not, a one-point streamline inside is (got %s)" % got)
vertex = [bool(in_sphere(s, np.zeros(3), 0.6).any()) for s in crossing]
check(vertex == [False, False, True], "negative control: vertex sampling misses the crossing")
f, _ = run(pd, [lambda f: f.AddBox([-0.1, 0.1, 0.4, 0.6, -0.1, 0.1], S.INCLUDE)])
check(selected_ids(f.GetOutput()).tolist() == [0], "a segment crossing a box with no vertex "
      "inside is selected")

# --- 3. general implicit functions ------------------------------------------------------
plane = vtkPlane()
plane.SetOrigin(*streamlines[50][5])
plane.SetNormal(0.3, -0.8, 0.5)
normal = np.array(plane.GetNormal())
f, _ = run(cb2, [lambda f: f.AddImplicitFunction(plane, S.INCLUDE)])
expected = np.array([((s - streamlines[50][5]) @ normal <= 0).any() for s in streamlines])
got = np.zeros(len(streamlines), dtype=bool)
got[selected_ids(f.GetOutput())] = True
check(np.array_equal(got, expected) and 0 < got.sum() < len(got),
      "a half-space (vtkPlane, evaluated along segments) is exact (%d selected)" % got.sum())

cyl_centre = streamlines[30][8]
radius = 1.5
cylinder = vtkCylinder()  # infinite, along y; through cyl_centre
cylinder.SetCenter(*cyl_centre)
cylinder.SetRadius(radius)
step = 0.2
for name, step_value in (("explicit step 0.2 mm", step), ("automatic step", 0.0)):
    f = S()
    f.SetInputData(cb2)
    f.AddImplicitFunction(cylinder, S.INCLUDE)
    f.SetImplicitFunctionStep(step_value)
    f.Update()
    got = np.zeros(len(streamlines), dtype=bool)
    got[selected_ids(f.GetOutput())] = True
    used = step_value if step_value > 0 else 1e-3 * np.linalg.norm(np.ptp(ALL_POINTS, axis=0))
    # Exact: distance of each segment to the y axis through cyl_centre (2D segment-point distance).
    a, b, owner = SEG
    a2 = (a - cyl_centre)[:, [0, 2]]
    b2 = (b - cyl_centre)[:, [0, 2]]
    d = b2 - a2
    t = np.clip(np.nan_to_num(-np.einsum("ij,ij->i", a2, d) / np.einsum("ij,ij->i", d, d)), 0, 1)
    dist = np.linalg.norm(a2 + t[:, None] * d, axis=1)
    closest = np.full(len(streamlines), np.inf)
    np.minimum.at(closest, owner, dist)
    exact = closest <= radius
    missed = exact & ~got
    check(not (got & ~exact).any() and 0 < got.sum(),
          "vtkCylinder (%s): the sampled selection is within the exact one (%d of %d)"
          % (name, got.sum(), exact.sum()))
    # A sample falls within step / 2 of the closest point, where the distance
    # exceeds the closest one by at most (step / 2)^2 / (2 r) in the 2D cross-section.
    check(np.all(closest[missed] > radius - (used / 2) ** 2 / radius - 1e-9),
          "vtkCylinder (%s): only streamlines grazing within the step's reach are missed (%d)"
          % (name, missed.sum()))

# --- 4. output contents ------------------------------------------------------------------
centre = streamlines[20][3]
f, _ = run(cb2, [lambda f: f.AddSphere(list(centre), 4.0, S.INCLUDE)])
out = f.GetOutput()
ids = selected_ids(out)
expected_ids = np.flatnonzero(reference(streamlines, SEG, [RefRegion("sphere", S.INCLUDE,
                                                                     centre=centre, radius=4.0)],
                                        True, False))
check(np.array_equal(ids, expected_ids) and f.GetNumberOfSelectedStreamlines() == len(ids),
      "selected streamlines in input order, cell data kept, count reported (%d)" % len(ids))
point_index = vtk_to_numpy(out.GetPointData().GetArray("PointIndex")).astype(np.int64)
check(np.array_equal(point_index, np.concatenate([np.arange(starts[i], ends[i]) for i in ids])),
      "the points of the selected streamlines with their point data, in order")
check(np.array_equal(vtk_to_numpy(out.GetPoints().GetData()), cb["points"][point_index]),
      "point coordinates copied exactly (float32 kept)")
lines_out = vtk_to_numpy(out.GetLines().GetOffsetsArray())
check(np.array_equal(np.diff(lines_out), ends[ids] - starts[ids]), "one polyline per selection")

f, _ = run(cb2, [lambda f: f.AddSphere(list(centre), 4.0, S.INCLUDE)], mark=True)
out = f.GetOutput()
marks = vtk_to_numpy(out.GetCellData().GetArray("Selected"))
expected_marks = np.zeros(len(streamlines), dtype=np.uint8)
expected_marks[expected_ids] = 1
check(out.GetNumberOfLines() == len(streamlines) and np.array_equal(marks, expected_marks)
      and out.GetCellData().GetArray("StreamlineIndex") is not None
      and cb2.GetCellData().GetArray("Selected") is None,
      "MARK_STREAMLINES: every streamline, Selected = 0/1 as selected, input untouched")

# Composite input: every polydata leaf.
mb = vtkMultiBlockDataSet()
mb.SetBlock(0, cb2)
mb.SetBlock(1, polydata(crossing))
f = S()
f.SetInputData(mb)
f.AddSphere(list(centre), 4.0, S.INCLUDE)
f.AddSphere(0, 0, 0, 0.6, S.INCLUDE)
f.SetIncludeCombinationToOr()
f.Update()
out = f.GetOutput()
check(out.IsA("vtkMultiBlockDataSet")
      and np.array_equal(selected_ids(out.GetBlock(0)), expected_ids)
      and selected_ids(out.GetBlock(1)).tolist() == [0, 2]
      and f.GetNumberOfSelectedStreamlines() == len(expected_ids) + 2,
      "composite input: each leaf selected on its own")

# Abort: an observer aborts at the first progress report; the output is empty.
many = polydata([ALL_POINTS[i:i + 18] for i in range(0, len(ALL_POINTS) - 18)] * 40)
f = S()
f.SetInputData(many)
f.AddSphere(list(centre), 4.0, S.INCLUDE)
progress = []


def on_progress(caller, event):
    progress.append(caller.GetProgress())
    caller.SetAbortExecute(1)


f.AddObserver(vtkCommand.ProgressEvent, on_progress)
f.Update()
check(len(progress) >= 1 and f.GetOutput().GetNumberOfPoints() == 0,
      "abort at the first progress report: an empty output (%d reports)" % len(progress))

# --- 5. bad input ---------------------------------------------------------------------------
singular = vtkMatrix4x4()
singular.SetElement(2, 2, 0.0)
bad_cases = [
    ("radius 0", lambda f: f.AddSphere(list(centre), 0.0, S.INCLUDE), "radius"),
    ("radius -1", lambda f: f.AddSphere(list(centre), -1.0, S.EXCLUDE), "radius"),
    ("radius NaN", lambda f: f.AddSphere(list(centre), float("nan"), S.INCLUDE), "radius"),
    ("box min > max", lambda f: f.AddBox([0, 1, 5, 4, 0, 1], S.INCLUDE), "min > max"),
    ("singular box map", lambda f: f.AddOrientedBox([0, 1, 0, 1, 0, 1], singular, S.INCLUDE),
     "invertible"),
    ("null implicit function", lambda f: f.AddImplicitFunction(None, S.INCLUDE), "no function"),
]
zero_sphere = vtkSphere()
zero_sphere.SetRadius(0.0)
bad_cases.append(("vtkSphere radius 0", lambda f: f.AddImplicitFunction(zero_sphere, S.ENDPOINT),
                  "radius"))
for name, add, phrase in bad_cases:
    f = S()
    f.SetInputData(cb2)
    f.AddSphere(list(centre), 4.0, S.INCLUDE)  # a good region first
    add(f)
    errors = Observed(f)
    f.Update()
    check(any(phrase in e for e in errors.messages) and f.GetOutput().GetNumberOfPoints() == 0
          and any("returned failure" in e for e in errors.messages),
          "bad input, %s: error naming it (%s), RequestData failed, empty output"
          % (name, errors.messages[:1]))

f = S()
f.SetInputData(cb2)
errors = Observed(f)
f.Update()
check(not errors.errors and any("No regions" in w for w in errors.warning_messages)
      and f.GetOutput().GetNumberOfLines() == len(streamlines),
      "no regions: every streamline, with a warning")

checker.finish()
print("all passed")
