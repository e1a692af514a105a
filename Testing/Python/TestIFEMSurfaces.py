# SPDX-License-Identifier: BSD-3-Clause
"""Probing and tracing IFEM surface results (LR and g2 surfaces) in physical space.

The real IFEM files of Testing/Data/External/ifem that hold surfaces are read
by vtkIFEMReader and probed with vtkLRSplineProbeFilter at x(u) of random
parameter points u, x computed by ifem_reference.py (numpy, the file's own
knots and coefficients, nothing from SplineViz). Checks:

- the probed fields equal the numpy evaluation at u (1e-10 of the field's
  magnitude), and the probed "LRParameterCoordinates" (the parameter map)
  equal u (1e-10): the inversion of the geometry map is exact. Planar curved
  multi-patch g2 (Cyl2D, 5 patches), rational planar g2 (Annulus), LR
  squares (Square-LR, Field2D-1PLR on two bases), and a rational LR shell
  curved in 3D (ScordelisPoint-NURBS);
- the shell probed at x(u) + d n (n the numpy normal): the foot is u again
  (1e-10) for d a fifth of SurfaceTolerance, outside for three times it;
  points beyond a boundary, in the cylinder's hole, beyond the outer box or
  off the plane are outside; with SurfaceTolerance 0 a point 1e-6 off the
  plane is outside and the plane's points inside;
- a streamline of Cyl2D's velocity u (level 10) at fixed time steps (RK4)
  equals a numpy RK4 streamline of the numpy-evaluated field with the same
  steps (numpy's own inversion, ifem_reference.SurfaceField), 1e-8, and goes
  around the cylinder into the outflow patch; negative control: the numpy
  field evaluated through the patches' corner (bilinear) maps instead of
  the geometry map misses the line by far more;
- a streamline on the shell stays on it (every point inside with
  SurfaceTolerance 0, x(u) of its foot within 1e-9 of the point) and its
  velocity is tangential (numpy normal);
- the 2-component field v(x) = x of surface-refined.lr (the LR surface's own
  coefficients, geometry mode) traced from x0 follows x0 e^t (1e-8);
- bad input: a surface without a field, a scalar field for the tracer, a NaN
  control point: an error and no output.
"""
import os
import re
import sys
import time

import h5py
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import ifem_reference as R  # noqa: E402
from splineviz_testing import Observed  # noqa: E402

from splineviz import (vtkIFEMReader, vtkLRSplineProbeFilter, vtkLRSplineReader,  # noqa: E402
                       vtkLRSplineStreamTracer)
from vtkmodules.vtkCommonCore import vtkPoints  # noqa: E402
from vtkmodules.vtkCommonDataModel import vtkDataObject, vtkMultiBlockDataSet  # noqa: E402
from vtkmodules.vtkCommonDataModel import vtkPolyData  # noqa: E402
from vtkmodules.vtkCommonDataModel import vtkUnstructuredGrid  # noqa: E402

SOURCE = os.environ.get("SPLINEVIZ_SOURCE_DIR",
                        os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
DATA = os.path.join(SOURCE, "Testing", "Data", "External")
OUT = os.environ.get("SPLINEVIZ_TEST_OUTPUT", ".")
RNG = np.random.default_rng(2027)
TOL = 1e-10
from splineviz_testing import Checker  # noqa: E402

checker = Checker()


fail = checker.fail


def ifem_path(name):
    return name if os.path.isabs(name) else os.path.join(DATA, "ifem", name)


def read(name, level):
    reader = vtkIFEMReader()
    reader.SetFileName(ifem_path(name))
    if name == BENT:
        reader.SetRationalModeToPolynomial()  # dim 3 > 2 is x, y, z, not a weight
    reader.UpdateInformation()
    reader.UpdateTimeStep(reader.GetTimeStep(level))
    data = vtkMultiBlockDataSet()
    data.ShallowCopy(reader.GetOutput())
    return data


def points(X):
    pts = vtkPoints()
    pts.SetDataTypeToDouble()
    for x in X:
        pts.InsertNextPoint(*(list(x) + [0.0] * (3 - len(x))))
    pd = vtkPolyData()
    pd.SetPoints(pts)
    return pd


def probe(source, X, name, tolerance=None):
    f = vtkLRSplineProbeFilter()
    f.SetInputData(points(X))
    f.SetSourceData(source)
    f.SetInputArrayToProcess(0, 1, 0, vtkDataObject.FIELD_ASSOCIATION_POINTS, name)  # port 1
    if tolerance is not None:
        f.SetSurfaceTolerance(tolerance)
    f.Update()
    out = f.GetOutput()
    a = out.GetPointData().GetArray(name)
    m = out.GetPointData().GetArray("vtkValidPointMask")
    if a is None or m is None:
        fail("probing %r gave no values" % name)
        return np.zeros((len(X), 1)), np.zeros(len(X))
    n = out.GetNumberOfPoints()
    return (np.array([a.GetTuple(i) for i in range(n)]),
            np.array([m.GetTuple1(i) for i in range(n)]))


def patches_of(f, level, basis):
    """The patches of the basis as of `level` (a basis is carried forward until rewritten)."""
    written = max(l for l in range(level + 1) if "%d/%s/basis" % (l, basis) in f)
    texts = f["%d/%s/basis" % (written, basis)]
    return [R.parse_patch_text(bytes(texts[k][()].astype(np.uint8)).decode())[0]
            for k in sorted(texts, key=int)]


def values_of(f, level, basis, name, patch_count, nb):
    return [f["%d/%s/fields/%s/%d" % (level, basis, name, k + 1)][()].reshape(nb[k], -1)
            for k in range(patch_count)]


def random_parameters(patch, n, margin=0.0):
    lo, hi = R.domain(patch)
    return lo + (hi - lo) * RNG.uniform(margin, 1.0 - margin, (n, patch.pardim))


def bent_square(path):
    """Square-LR's result with its geometry bent out of the plane: every
    control point (x, y) becomes (x, y, 0.3 sin(pi x) cos(pi y)), so the LR
    surface is a polynomial surface curved in 3D (dim 3) with the same field."""
    src = h5py.File(os.path.join(DATA, "ifem", "Square-LR.hdf5"), "r")
    text = bytes(src["0/Poisson-1/basis/1"][()].astype(np.uint8)).decode()
    lines, header = [], True
    for line in text.splitlines():
        if not line.startswith("#") and header and line.strip():
            v = line.split()
            v[5] = "3"  # p1 p2 Nbasis Nline Nel dim rat
            line, header = "\t" + "\t".join(v), False
        elif re.match(r"\s*\d+:\s*\[", line):  # a basis function: knots, coefficients, (gamma)
            head, rest = line[:line.rindex("]") + 1], line[line.rindex("]") + 1:]
            coords, gamma = rest[:rest.index("(")].split(), rest[rest.index("("):]
            x, y = float(coords[0]), float(coords[1])
            line = "%s %r %r %r %s" % (head, x, y, float(0.3 * np.sin(np.pi * x) * np.cos(np.pi * y)),
                                      gamma)
        lines.append(line)
    bent = "\n".join(lines) + "\n"
    with h5py.File(path, "w") as f:
        g = f.create_group("0/Poisson-1")
        g.create_dataset("basis/1", data=np.frombuffer(bent.encode(), dtype=np.int8))
        g.create_dataset("fields/u/1", data=src["0/Poisson-1/fields/u/1"][()])
    return path


BENT = bent_square(os.path.abspath(os.path.join(OUT, "TestIFEMSurfaces-bent-square.hdf5")))

# --- probing the real files --------------------------------------------------------------------
CASES = [
    # file, level, basis, rational, fields ({file field: arrays}), spatial dimension
    ("Cyl2D-VMSFSI-weak.hdf5", 10, "NavierStokes-1", False, ["u_x&&u_y&&p"], 2),
    ("Annulus.hdf5", 2, "Elasticity-1", True, ["displacement", "von Mises stress"], 2),
    ("Square-LR.hdf5", 0, "Poisson-1", False, ["u", "q_x", "q_y"], 2),
    ("Field2D-1PLR.hdf5", 0, "Stokes-1", False, ["u", "sigma_xy"], 2),
    ("Field2D-1PLR.hdf5", 0, "Stokes-2", False, ["p"], 2),
    ("ScordelisPoint-NURBS.hdf5", 2, "Elasticity-1", True, ["displacement"], 3),
    (BENT, 0, "Poisson-1", False, ["u"], 3),
]
worst = {"field": 0.0, "parameter": 0.0}
sources = {}
t0 = time.time()
for name, level, basis, rational, fields, nsd in CASES:
    f = h5py.File(ifem_path(name), "r")
    data = sources.setdefault((name, level), read(name, level))
    name = os.path.basename(name)
    patches = patches_of(f, level, basis)
    U, X, owner = [], [], []
    for k, p in enumerate(patches):
        for u in random_parameters(p, 40):
            U.append(u)
            X.append(R.geometry(p, u, rational)[:nsd])
            owner.append(k)
    U, X = np.array(U), np.array(X)
    # (The parameter map LRParameterCoordinates is polynomial: on a rational
    # basis its interpolation is not u, so rational patches are checked by
    # their fields only.)
    got, mask = probe(data, X, "LRParameterCoordinates")
    if mask.min() != 1:
        fail("%s: %d points of the surface reported outside" % (name, int((mask == 0).sum())))
    err_u = 0.0 if rational else np.abs(got[:, :2] - U).max()
    worst["parameter"] = max(worst["parameter"], err_u)
    for field in fields:
        nb = [p.nb for p in patches]
        vals = values_of(f, level, basis, field, len(patches), nb)
        ref = np.array([R.field(patches[k], u, vals[k], rational) for k, u in zip(owner, U)])
        scale = np.abs(np.concatenate(vals)).max()
        for c, array in enumerate(R.component_names(field, ref.shape[1])):
            v, m = probe(data, X, array)
            err = np.abs(v[:, 0] - ref[:, c]).max() / scale
            worst["field"] = max(worst["field"], err)
            if not err <= TOL or m.min() != 1:
                fail("%s %s: probe vs numpy %.3g of the magnitude" % (name, array, err))
    print("%s level %d %s: %d points, parameters within %s, fields within %.2e"
          % (name, level, basis, len(U), "(rational)" if rational else "%.2e" % err_u,
             worst["field"]))
    if not err_u <= TOL:
        fail("%s: the inversion misses the parameter by %.3g" % (name, err_u))
print("probing %d files: largest field error %.2e (relative), parameter error %.2e, %.2f s"
      % (len(CASES), worst["field"], worst["parameter"], time.time() - t0))

# --- points off the surface -----------------------------------------------------------------------
cyl = sources[("Cyl2D-VMSFSI-weak.hdf5", 10)]
outside = [[0, 0, 0], [0.3, 0.2, 0], [31, 0, 0], [-11, 1, 0], [5, 10.5, 0], [5, 3, 0.5],
           [5, 3, -0.5], [20, -5, 1.0]]
_, m = probe(cyl, outside, "u")
if m.max() != 0:
    fail("Cyl2D: %d of %d points off the surface reported inside" % (m.sum(), len(outside)))
_, m = probe(cyl, [[5, 3, 1e-6], [-5, -3, -1e-6], [5, 3, 0], [-5, -3, 0]], "u", tolerance=0.0)
if list(m) != [0, 0, 1, 1]:
    fail("Cyl2D, SurfaceTolerance 0: mask %s for 1e-6 off the plane and on it" % list(m))

def off_surface(label, data, patch, rational, values, array):
    """Points d n off the surface at x(u): the foot is u for d a fifth of the
    default SurfaceTolerance (the probed `array` equals numpy's at u, and for
    a polynomial patch the parameter map equals u), outside for three times
    it, and outside beyond the edge u_0 = lo."""
    U = random_parameters(patch, 60, 0.05)
    near, far, beyond, ref = [], [], [], []
    for u in U:
        x = R.geometry(patch, u, rational)
        T = R.tangents(patch, u, rational)
        n = np.cross(T[:, 0], T[:, 1])
        n /= np.linalg.norm(n)
        e = np.where((patch.lo <= u).all(axis=1) & (u < patch.hi).all(axis=1))[0][0]
        corners = np.array([R.geometry(patch, [a, b], rational)
                            for a in (patch.lo[e][0], patch.hi[e][0] - 1e-12)
                            for b in (patch.lo[e][1], patch.hi[e][1] - 1e-12)])
        size = np.linalg.norm(corners.max(axis=0) - corners.min(axis=0))
        sign = 1 if RNG.random() < 0.5 else -1
        near.append(x + sign * 0.2 * 0.01 * size * n)
        far.append(x + sign * 3.0 * 0.01 * size * n)
        ub = np.array([patch.lo[:, 0].min(), u[1]])
        tb = R.tangents(patch, ub, rational)[:, 0]
        beyond.append(R.geometry(patch, ub, rational) - 0.05 * size * tb / np.linalg.norm(tb))
        ref.append(R.field(patch, u, values, rational))
    ref = np.array(ref)
    v, m = probe(data, near, array)
    err = np.abs(v - ref).max() / np.abs(values).max()
    err_u = 0.0
    if not rational:
        got, _ = probe(data, near, "LRParameterCoordinates")
        err_u = np.abs(got[:, :2] - U).max()
    _, mf = probe(data, far, array)
    _, mb = probe(data, beyond, array)
    print("%s: points 0.2 %% of an element off: %d of %d on the surface, %r at the foot within "
          "%.2e, foot parameter within %s; 3 %% off: %d inside; beyond the edge: %d inside"
          % (label, m.sum(), len(U), array, err, "%.2e" % err_u if not rational else "(rational)",
             mf.sum(), mb.sum()))
    if m.min() != 1 or not err <= TOL or not err_u <= TOL:
        fail("%s: the closest-point projection misses the foot (%.3g, %.3g; %d outside)"
             % (label, err, err_u, int((m == 0).sum())))
    if mf.max() != 0 or mb.max() != 0:
        fail("%s: points off the surface or beyond its edge reported inside" % label)


f = h5py.File(os.path.join(DATA, "ifem", "ScordelisPoint-NURBS.hdf5"), "r")
shell = patches_of(f, 2, "Elasticity-1")[0]
shell_data = sources[("ScordelisPoint-NURBS.hdf5", 2)]
off_surface("shell (rational LR, 3D)", shell_data, shell, True,
            values_of(f, 2, "Elasticity-1", "displacement", 1, [shell.nb])[0], "displacement")
f = h5py.File(BENT, "r")
bent = patches_of(f, 0, "Poisson-1")[0]
off_surface("bent square (LR, 3D)", sources[(BENT, 0)], bent, False,
            values_of(f, 0, "Poisson-1", "u", 1, [bent.nb])[0], "u")


# --- a streamline on Cyl2D against numpy RK4 -------------------------------------------------------
def trace(source, seeds, array, h, steps, direction=0, tolerance=None):
    t = vtkLRSplineStreamTracer()
    t.SetInputData(source)
    t.SetSourceData(points(seeds))
    t.SetInputArrayToProcess(0, 0, 0, vtkDataObject.FIELD_ASSOCIATION_POINTS, array)
    t.SetIntegrationDirection(direction)
    t.SetStepModeToFixedTime()
    t.SetIntegrationStep(h)
    t.SetMaximumNumberOfSteps(steps)
    if tolerance is not None:
        t.SetSurfaceTolerance(tolerance)
    start = time.time()
    t.Update()
    out = t.GetOutput()
    P = np.array([out.GetPoint(i) for i in range(out.GetNumberOfPoints())])
    reasons = out.GetCellData().GetArray("ReasonForTermination")
    reason = [int(reasons.GetTuple1(i)) for i in range(out.GetNumberOfCells())] if reasons else []
    return P, out, reason, time.time() - start


def rk4(field, x0, h, steps):
    xs = [np.asarray(x0, float)]
    for _ in range(steps):
        x = xs[-1]
        k1 = field(x)
        k2 = None if k1 is None else field(x + 0.5 * h * k1[:2])
        k3 = None if k2 is None else field(x + 0.5 * h * k2[:2])
        k4 = None if k3 is None else field(x + h * k3[:2])
        if k4 is None:
            break
        xs.append(x + h / 6 * (k1[:2] + 2 * k2[:2] + 2 * k3[:2] + k4[:2]))
    return np.array(xs)


f = h5py.File(os.path.join(DATA, "ifem", "Cyl2D-VMSFSI-weak.hdf5"), "r")
cyl_patches = patches_of(f, 10, "NavierStokes-1")
cyl_values = [v[:, :2] for v in values_of(f, 10, "NavierStokes-1", "u_x&&u_y&&p", 5,
                                          [p.nb for p in cyl_patches])]
exact = R.SurfaceField(cyl_patches, cyl_values, False, samples=11)
seed, h, steps = np.array([-6.0, 0.35]), 0.15, 100
P, _, reason, seconds = trace(cyl, [seed], "u", h, steps)
start = time.time()
Q = rk4(exact, seed, h, steps)
numpy_seconds = time.time() - start
n = min(len(P), len(Q))
dist = np.linalg.norm(P[:n, :2] - Q[:n], axis=1).max() if n else np.inf
radius = np.linalg.norm(P[:, :2], axis=1)
around = P[:, 0].max() > 1.0 and radius.min() > 0.5 and np.abs(P[:, 2]).max() == 0
print("Cyl2D streamline: %d points (numpy %d) in %.3f s (numpy %.1f s), largest distance %.2e, "
      "nearest the cylinder's centre %.3f, x from %.2f to %.2f"
      % (len(P), len(Q), seconds, numpy_seconds, dist, radius.min(), P[:, 0].min(), P[:, 0].max()))
if len(P) != steps + 1 or len(Q) != steps + 1 or not dist <= 1e-8:
    fail("Cyl2D: the streamline differs from numpy's RK4 by %.3g (%d / %d points)"
         % (dist, len(P), len(Q)))
if not around:
    fail("Cyl2D: the streamline does not go around the cylinder")


class CornerMapField(R.SurfaceField):
    """Negative control: the geometry ignored, each patch taken as the bilinear
    map of its four corners."""

    def __init__(self, patches, values):
        super().__init__(patches, values, False, samples=2)
        self.corners = [X for _, X in self.starts]

    def locate(self, x):
        for k, p in enumerate(self.patches):
            lo, hi = R.domain(p)
            c = self.corners[k]  # (lo, lo), (lo, hi), (hi, lo), (hi, hi)
            s = np.array([0.5, 0.5])
            for _ in range(30):
                m = (c[0] * (1 - s[0]) * (1 - s[1]) + c[1] * (1 - s[0]) * s[1]
                     + c[2] * s[0] * (1 - s[1]) + c[3] * s[0] * s[1])
                J = np.stack([(c[2] - c[0]) * (1 - s[1]) + (c[3] - c[1]) * s[1],
                              (c[1] - c[0]) * (1 - s[0]) + (c[3] - c[2]) * s[0]], axis=1)
                s = np.clip(s - np.linalg.lstsq(J, m - x[:2], rcond=None)[0], -1, 2)
            if np.all(s >= 0) and np.all(s <= 1) and np.linalg.norm(m - x[:2]) < 1e-9:
                return k, lo + s * (hi - lo)
        return None, None


Qc = rk4(CornerMapField(cyl_patches, cyl_values), seed, h, 40)  # into the curved patches
nc = min(len(P), len(Qc))
control = np.linalg.norm(P[:nc, :2] - Qc[:nc], axis=1).max()
print("negative control (corner maps instead of the geometry): distance %.3g" % control)
if not control > 1e-3:
    fail("the negative control did not fail")

# --- a streamline on the curved shell ------------------------------------------------------------
disp = shell_data
lo, hi = R.domain(shell)
x0 = R.geometry(shell, lo + 0.5 * (hi - lo), True)
P, out, reason, seconds = trace(shell_data, [x0], "displacement", 2.0, 400, direction=2)
got, m = probe(shell_data, P, "LRParameterCoordinates", tolerance=0.0)
on = np.array([np.linalg.norm(R.geometry(shell, u[:2], True) - p) for u, p in zip(got, P)])
V = np.array([out.GetPointData().GetArray("displacement").GetTuple(i) for i in range(len(P))])
normal_part = 0.0
for u, v in zip(got, V):
    T = R.tangents(shell, u[:2], True)
    nn = np.cross(T[:, 0], T[:, 1])
    normal_part = max(normal_part, abs(v @ nn) / np.linalg.norm(nn) / max(np.linalg.norm(v), 1e-300))
print("shell streamline: %d points in %.3f s, reasons %s, %d on the surface (tolerance 0), "
      "largest |x(u) - x| %.2e, largest normal part of the velocity %.2e"
      % (len(P), seconds, reason, m.sum(), on.max(), normal_part))
if len(P) < 20 or m.min() != 1 or not on.max() <= 1e-9 or not normal_part <= 1e-6:
    fail("shell: the streamline leaves the surface or its velocity is not tangential")

# --- v(x) = x on the real LR surface (2 components) ------------------------------------------
lr = vtkLRSplineReader()
lr.SetFileName(os.path.join(DATA, "surface-refined.lr"))
lr.SetGeometryMode(True)
lr.Update()
x0 = np.array([0.2, 0.3, 0.0])
P, out, reason, seconds = trace(lr.GetOutput(), [x0], "Field", 0.01, 1000)
T = np.array([out.GetPointData().GetArray("IntegrationTime").GetTuple1(i) for i in range(len(P))])
err = np.abs(P[:-1] - np.outer(np.exp(T[:-1]), x0)).max()
print("surface-refined.lr, v = x: %d points, reasons %s, largest distance to x0 e^t %.2e, "
      "last point %r" % (len(P), reason, err, list(P[-1])))
if not err <= 1e-8 or reason != [1] or not abs(P[-1].max() - 1.0) <= 1e-8:
    fail("surface-refined.lr: the streamline of v = x leaves x0 e^t (%.3g) or the domain "
         "elsewhere (%s)" % (err, P[-1]))


# --- bad input -------------------------------------------------------------------------------------
def expect_error(label, algorithm, words):
    seen = Observed(algorithm)
    algorithm.Update()
    out = algorithm.GetOutput()
    text = " ".join(seen.messages)
    if not seen.errors or out.GetNumberOfPoints() != 0 or any(w not in text for w in words):
        fail("%s: expected an error naming %s and no output, got %r (%d points)"
             % (label, words, text[:300], out.GetNumberOfPoints()))
    else:
        print("%s: %s" % (label, seen.messages[0].strip().splitlines()[0][:160]))


square = sources[("Square-LR.hdf5", 0)]
grid = vtkUnstructuredGrid()
grid.DeepCopy(square.GetBlock(0).GetBlock(0))
for a in [grid.GetPointData().GetArrayName(i) for i in range(grid.GetPointData().GetNumberOfArrays())]:
    if a != "LRParameterCoordinates":
        grid.GetPointData().RemoveArray(a)
f = vtkLRSplineProbeFilter()
f.SetInputData(points([[0.5, 0.5, 0]]))
f.SetSourceData(grid)
expect_error("surface without a field (probe)", f, ["no point-data array"])
t = vtkLRSplineStreamTracer()
t.SetInputData(grid)
t.SetSourceData(points([[0.5, 0.5, 0]]))
expect_error("surface without a field (tracer)", t, ["no point-data array"])
t = vtkLRSplineStreamTracer()
t.SetInputData(cyl)
t.SetSourceData(points([[-6, 0.3, 0]]))
t.SetInputArrayToProcess(0, 0, 0, vtkDataObject.FIELD_ASSOCIATION_POINTS, "p")
expect_error("scalar field (tracer)", t, ["1 components", "2-component"])
bad = vtkUnstructuredGrid()
bad.DeepCopy(square.GetBlock(0).GetBlock(0))
bad.GetPoints().SetPoint(3, float("nan"), 0.2, 0.0)
f = vtkLRSplineProbeFilter()
f.SetInputData(points([[0.5, 0.5, 0]]))
f.SetSourceData(bad)
f.SetInputArrayToProcess(0, 1, 0, vtkDataObject.FIELD_ASSOCIATION_POINTS, "u")
expect_error("NaN control point (probe)", f, ["non-finite"])
t = vtkLRSplineStreamTracer()
t.SetInputData(bad)
t.SetSourceData(points([[0.5, 0.5, 0]]))
t.SetInputArrayToProcess(0, 0, 0, vtkDataObject.FIELD_ASSOCIATION_POINTS, "q")
expect_error("NaN control point (tracer)", t, ["non-finite"])

checker.finish()
print("TestIFEMSurfaces passed")
