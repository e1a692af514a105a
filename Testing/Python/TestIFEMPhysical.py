# SPDX-License-Identifier: BSD-3-Clause
"""Probing and tracing IFEM results in physical space, on curved multi-patch geometry.

cube-2patch.lr (two LR patches, [-1, 0] x [0, 1]^2 and [0, 1]^3, the geometry
of IFEM-Poisson's cube-2patch.xinp) carries the analytic solution of that
Poisson problem, u = sin(pi x) sin(pi y) sin(pi z), and its flux q = -grad u,
projected onto each patch's basis by least squares (numpy, with
ifem_reference.py's independent evaluation of the LR basis) and written as an
IFEM HDF5 result with h5py. Two geometries: the cube as it is (affine) and the
cube bent by a smooth map of all control points (curved; the two patches
still meet exactly). vtkIFEMReader reads the file; vtkLRSplineProbeFilter and
vtkLRSplineStreamTracer work on it in physical space (inversion of the
geometry map). Checks:

- probing at x(u) of random parameter points u (x computed by numpy) equals
  the numpy evaluation of the field at u (1e-9: the inversion is exact) and
  the analytic u(x) (the projection's error: 5e-3 measured, 1e-2 allowed);
- points outside the geometry are masked out;
- a streamline of q seeded in one patch crosses into the other, stays within
  1e-3 of a numpy RK4 streamline of the analytic flux, and has no jump at the
  interface (consecutive points at most the step apart);
- negative control: probing the bent file at the unbent x misses the
  numpy values by far more than the tolerance.
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import ifem_poisson as poisson  # noqa: E402
import ifem_reference as R  # noqa: E402
from ifem_poisson import PI, analytic, bend, flux  # noqa: E402

from splineviz import vtkIFEMReader, vtkLRSplineProbeFilter, vtkLRSplineStreamTracer  # noqa: E402
from vtkmodules.vtkCommonCore import vtkPoints  # noqa: E402
from vtkmodules.vtkCommonDataModel import vtkDataObject, vtkPolyData  # noqa: E402

OUT = os.environ.get("SPLINEVIZ_TEST_OUTPUT", ".")
RNG = np.random.default_rng(27)
from splineviz_testing import Checker  # noqa: E402

checker = Checker()


fail = checker.fail


def probe(reader, X, name):
    pts = vtkPoints()
    pts.SetDataTypeToDouble()
    for x in X:
        pts.InsertNextPoint(*x)
    pd = vtkPolyData()
    pd.SetPoints(pts)
    f = vtkLRSplineProbeFilter()
    f.SetInputData(pd)
    f.SetSourceConnection(reader.GetOutputPort())
    f.SetInputArrayToProcess(0, 1, 0, vtkDataObject.FIELD_ASSOCIATION_POINTS, name)  # port 1
    f.Update()
    out = f.GetOutput()
    a = out.GetPointData().GetArray(name)
    m = out.GetPointData().GetArray("vtkValidPointMask")
    if a is None or m is None:
        fail("the probe gave no %s array (%s)" % (name, "mask" if a else "values"))
        return None, None
    v = np.array([a.GetTuple(i) for i in range(out.GetNumberOfPoints())])
    mask = np.array([m.GetTuple1(i) for i in range(out.GetNumberOfPoints())])
    return v, mask


def rk4_streamline(x0, h, steps):
    xs = [x0]
    x = x0.copy()
    inside = lambda y: -1 <= y[0] <= 1 and 0 <= y[1] <= 1 and 0 <= y[2] <= 1  # noqa: E731
    for _ in range(steps):
        k1 = flux(x)
        k2 = flux(x + 0.5 * h * k1)
        k3 = flux(x + 0.5 * h * k2)
        k4 = flux(x + h * k3)
        x = x + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
        if not inside(x):
            break
        xs.append(x.copy())
    return np.array(xs)


def check(curved):
    label = "bent" if curved else "affine"
    path = os.path.join(OUT, "TestIFEMPhysical-%s.hdf5" % label)
    patches = poisson.write(path, curved)
    reader = vtkIFEMReader()
    reader.SetFileName(path)
    reader.Update()

    # Probing at x(u) of random parameter points of both patches.
    X, ref_field, ref_flux, U = [], [], [], []
    for p in patches:
        for _ in range(150):
            u = RNG.uniform(0.0, 1.0, 3) * 0.999
            b = R.basis(p, u)
            U.append(u)
            X.append(R.geometry(p, u, False, b))
            val = R.field(p, u, p.values, False, b)
            ref_field.append(val[0])
            ref_flux.append(val[1:4])
    X = np.array(X)
    v, mask = probe(reader, X, "u")
    if v is None:
        return
    if mask.min() != 1:
        fail("%s: %d inside points were reported outside" % (label, int((mask == 0).sum())))
    spline_err = np.abs(v[:, 0] - np.array(ref_field)).max()
    analytic_err = np.abs(v[:, 0] - analytic(X)).max()
    q, _ = probe(reader, X, "q")
    flux_err = np.abs(q - np.array(ref_flux)).max() / PI
    print("%s: probe vs numpy spline %.2e (flux %.2e), vs analytic %.2e over %d points"
          % (label, spline_err, flux_err, analytic_err, len(X)))
    if not spline_err <= 1e-9 or not flux_err <= 1e-9:
        fail("%s: the probe differs from the spline by %.3g / %.3g" % (label, spline_err, flux_err))
    if not analytic_err <= 1e-2:
        fail("%s: the probe differs from the analytic solution by %.3g" % (label, analytic_err))

    # Outside points: pushed off the domain's faces (not the interface, whose
    # unbent x is 0) along the outward direction.
    flat = [R.parse_lr(t)[0] for t in poisson.patch_texts()]
    outside = []
    for p, pf in zip(patches, flat):
        while len(outside) < 20 * (1 + (p is patches[1])):
            u = RNG.uniform(0.05, 0.95, 3)
            d = RNG.integers(0, 3)
            u[d] = 0.0 if RNG.random() < 0.5 else 0.999999
            if abs(R.geometry(pf, u, False)[0]) < 1e-3:
                continue
            x = R.geometry(p, u, False)
            xin = R.geometry(p, np.where(np.arange(3) == d, 0.5, u), False)
            outside.append(x + 0.02 * (x - xin) / np.linalg.norm(x - xin))
    _, m = probe(reader, np.array(outside), "u")
    if m is not None and m.max() != 0:
        fail("%s: %d of %d outside points were reported inside"
             % (label, int(m.sum()), len(outside)))

    # A streamline of the flux from patch 2 into patch 1 (or back).
    seeds = vtkPolyData()
    sp = vtkPoints()
    sp.SetDataTypeToDouble()
    # In patch 1, where the flux runs toward x = 0 and on into patch 2.
    x0 = np.array([0.3, 0.4, 0.45]) if not curved else bend(np.array([[0.3, 0.4, 0.45]]))[0]
    sp.InsertNextPoint(*x0)
    seeds.SetPoints(sp)
    tracer = vtkLRSplineStreamTracer()
    tracer.SetInputConnection(reader.GetOutputPort())
    tracer.SetSourceData(seeds)
    tracer.SetInputArrayToProcess(0, 0, 0, vtkDataObject.FIELD_ASSOCIATION_POINTS, "q")
    tracer.SetIntegrationDirection(0)  # forward
    tracer.SetStepMode(0)  # fixed time steps
    tracer.SetIntegrationStep(0.002)
    tracer.SetMaximumNumberOfSteps(4000)
    tracer.Update()
    line = tracer.GetOutput()
    P = np.array([line.GetPoint(i) for i in range(line.GetNumberOfPoints())])
    if len(P) < 10:
        fail("%s: the streamline has %d points" % (label, len(P)))
        return
    sides = np.sign(P[:, 0] - (0 if not curved else 0.0))
    crossed = sides.min() < 0 < sides.max()
    speeds = np.linalg.norm(flux(P), axis=1)
    gaps = np.linalg.norm(np.diff(P, axis=0), axis=1)
    max_gap = gaps.max() / (0.002 * max(speeds.max(), 1e-12))
    print("%s: streamline of %d points, crosses the interface: %s, largest step / (h |q|) %.3f"
          % (label, len(P), crossed, max_gap))
    if not crossed:
        fail("%s: the streamline did not cross the patch interface" % label)
    if max_gap > 1.5:
        fail("%s: the streamline jumps (a step %.3g times h |q|)" % (label, max_gap))
    if not curved:
        ref = rk4_streamline(x0, 0.0005, 16000)
        # Distance of every traced point to the reference polyline's points.
        d = np.array([np.min(np.linalg.norm(ref - p, axis=1)) for p in P[::10]])
        print("%s: distance to the analytic streamline %.2e" % (label, d.max()))
        if not d.max() <= 2e-3:
            fail("%s: the streamline is %.3g from the analytic one" % (label, d.max()))
    return reader, U, np.array(ref_field)


check(False)
result = check(True)
# Negative control: the bent file probed at the unbent points x(u).
if result:
    reader, U, ref = result
    flat = [R.parse_lr(t)[0] for t in poisson.patch_texts()]
    Xflat = np.array([R.geometry(flat[i // 150], u, False) for i, u in enumerate(U)])
    w, m = probe(reader, Xflat, "u")
    err = np.abs(np.where(m == 1, w[:, 0], 1e3) - ref).max() if w is not None else 0
    print("negative control (unbent points): %.3g" % err)
    if not err > 1e-2:
        fail("the negative control did not fail")

checker.finish()
print("TestIFEMPhysical passed")
