# SPDX-License-Identifier: BSD-3-Clause
"""vtkIFEMReader and vtkLRSplineReader against an independent evaluation.

Every IFEM result file of Testing/Data/External/ifem (LR volumes and surfaces
on mixed bases, g2 tensor patches, a moving-mesh time series, a rational LR
shell, a rational g2 annulus, a Lagrange patch) is read at every level; at
random parameter points of random elements, VTK's own interpolation of the
output's Bezier (or Lagrange) cells -- vtkCell::EvaluateLocation, the
geometry and the point data weighted by its interpolation functions, rational
weights included -- must agree with ifem_reference.py, which reads the same
HDF5 datasets with h5py and sums every basis function of the file's patch text
(Cox-de Boor on each function's local knots, times gamma), to 1e-12 of the
values' magnitude. Element values (knotspan) must equal the file's. The same
for cube-2patch.lr, surface-refined.lr and GoTools' LR formats 293 / 793
(written by ifem_reference.gotools_lr from the LRSplines text of real patches). Negative controls: a
coefficient perturbed by 1e-9 of the magnitude, in the geometry and in a
field, must be detected; the rational shell read as polynomial is refused and
its points lie on the cylinder only when read as rational.
"""
import glob
import os
import sys
import time

import h5py
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import ifem_reference as R  # noqa: E402

from splineviz import vtkIFEMReader, vtkLRSplineReader  # noqa: E402
from vtkmodules.vtkCommonCore import reference  # noqa: E402
from vtkmodules.vtkCommonDataModel import vtkMultiBlockDataSet  # noqa: E402

SOURCE = os.environ.get("SPLINEVIZ_SOURCE_DIR",
                        os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
DATA = os.path.join(SOURCE, "Testing", "Data", "External")
OUT = os.environ.get("SPLINEVIZ_TEST_OUTPUT", ".")
TOL = 1e-12
RNG = np.random.default_rng(27)
from splineviz_testing import Checker  # noqa: E402

checker = Checker()
worst = {"geometry": 0.0, "field": 0.0}
counts = {"geometry": 0, "field": 0}


fail = checker.fail


def text_of(dataset):
    return bytes(dataset[()].astype(np.uint8)).decode()


def array_values(grid, name, association="point"):
    data = grid.GetPointData() if association == "point" else grid.GetCellData()
    a = data.GetArray(name)
    if a is None:
        return None
    n, c = a.GetNumberOfTuples(), a.GetNumberOfComponents()
    return np.array([a.GetTuple(i) for i in range(n)]).reshape(n, c)


def cells_by_box(grid, pardim):
    boxes = array_values(grid, "LRParameterBox", "cell")
    out = {}
    for c, b in enumerate(boxes):
        key = tuple(np.round(np.r_[b[:pardim], b[3:3 + pardim]], 12))
        out[key] = c
    return out


def vtk_evaluate(grid, cell_id, r):
    """Point and interpolation weights of VTK's cell at parametric r."""
    cell = grid.GetCell(cell_id)
    sub = reference(0)
    x = [0.0, 0.0, 0.0]
    w = [0.0] * cell.GetNumberOfPoints()
    cell.EvaluateLocation(sub, list(r), x, w)
    ids = [cell.GetPointId(k) for k in range(cell.GetNumberOfPoints())]
    return np.array(x), np.array(w), ids


def check(label, got, ref, scale, kind):
    err = np.max(np.abs(np.asarray(got) - np.asarray(ref))) / max(scale, 1e-300)
    worst[kind] = max(worst[kind], err)
    counts[kind] += 1
    if not err <= TOL:
        fail("%s: relative error %.3g (VTK %s, reference %s)" % (label, err, got, ref))
    return err


def compare_spline_block(label, grid, patch, rational, fields, knotspans, n_elem=12, n_pts=2,
                         negative=False, piece=False):
    """VTK's interpolation of the block against the reference evaluation
    (piece: the grid holds some of the elements; the others are skipped)."""
    pd = patch.pardim
    nsd = patch.coefs.shape[1] - (1 if rational else 0)
    lookup = cells_by_box(grid, pd)
    geo_scale = np.max(np.abs(patch.coefs[:, :nsd] / (patch.coefs[:, -1:] if rational else 1)))
    point_arrays = {n: array_values(grid, n) for n in
                    {c for f, v in fields.items() for c in R.component_names(f, v.shape[1])}}
    elements = RNG.choice(len(patch.lo), size=min(n_elem, len(patch.lo)), replace=False)
    detected = {"geometry": 0.0, "field": 0.0}
    for e in elements:
        key = tuple(np.round(np.r_[patch.lo[e], patch.hi[e]], 12))
        if key not in lookup:
            if not piece:
                fail("%s: element %d (box %s) has no cell" % (label, e, key))
            continue
        cell = lookup[key]
        for _ in range(n_pts):
            t = RNG.uniform(0.02, 0.98, pd)
            u = patch.lo[e] + t * (patch.hi[e] - patch.lo[e])
            x, w, ids = vtk_evaluate(grid, cell, np.r_[t, np.zeros(3 - pd)])
            B = R.basis(patch, u)
            ref = R.geometry(patch, u, rational, B)
            check(label + " geometry at u=%s" % u, x[:nsd], ref, geo_scale, "geometry")
            if negative:
                bumped = R.Patch(pd, patch.knots, patch.coefs.copy(), patch.gamma, patch.lo,
                                 patch.hi)
                i = int(np.argmax(B))
                bumped.coefs[i, 0] += 1e-9 * geo_scale
                detected["geometry"] = max(detected["geometry"], np.abs(
                    x[0] - R.geometry(bumped, u, rational, B)[0]) / geo_scale)
            for name, values in fields.items():
                nc = values.shape[1]
                ref_f = R.field(patch, u, values, rational, B)
                scale = max(np.max(np.abs(values)), 1e-300) if np.all(np.isfinite(values)) else 1
                for c, array in enumerate(R.component_names(name, nc)):
                    a = point_arrays.get(array)
                    if a is None:
                        fail("%s: no point array %r for field %r" % (label, array, name))
                        continue
                    got = w @ a[ids, 0]
                    if np.isfinite(ref_f[c]):
                        check("%s field %r at u=%s" % (label, array, u), got, ref_f[c], scale,
                              "field")
                if negative and np.all(np.isfinite(values)):
                    bumped = values.copy()
                    i = int(np.argmax(B))
                    bumped[i, 0] += 1e-9 * scale
                    a = point_arrays[R.component_names(name, nc)[0]]
                    detected["field"] = max(detected["field"], np.abs(
                        w @ a[ids, 0] - R.field(patch, u, bumped, rational, B)[0]) / scale)
    check_knotspans(label, grid, knotspans)
    if negative:
        for kind, value in detected.items():
            print("  negative control (%s coefficient + 1e-9): relative difference %.3g"
                  % (kind, value))
            if not value > 10 * TOL:
                fail("%s: a perturbed %s coefficient is not detected" % (label, kind))


def check_knotspans(label, grid, knotspans):
    ids = array_values(grid, "LRElementId", "cell")[:, 0].astype(int)
    for name, values in knotspans.items():
        nc = values.shape[1]
        for c, array in enumerate(R.component_names(name, nc)):
            a = array_values(grid, array, "cell")
            if a is None:
                a = array_values(grid, array + " (element)", "cell")
            if a is None:
                fail("%s: no cell array %r" % (label, array))
                continue
            ref = values[ids, c]
            same = (a[:, 0] == ref) | (np.isnan(a[:, 0]) & np.isnan(ref))
            if not np.all(same):
                fail("%s: element values %r differ from the file" % (label, array))


def is_rational(patch):
    """SISO's rule, stated independently: g2 says so; LR text when its header
    says so or when dim > pardim."""
    if patch.kind == "g2" or patch.rational_flag:
        return bool(patch.rational_flag)
    return patch.coefs.shape[1] > patch.pardim


def latest(f, level, path, lowest=0):
    for l in range(level, lowest - 1, -1):
        if "%d/%s" % (l, path) in f:
            return l
    return None


def ifem_file(path, negative=False):
    name = os.path.basename(path)
    f = h5py.File(path, "r")
    levels = sorted(int(k) for k in f.keys() if k.isdigit())
    groups = sorted({g for l in levels for g in f[str(l)] if g != "timeinfo"})
    bases = [g for g in groups if any("%d/%s/basis" % (l, g) in f for l in levels)]
    orphans = [g for g in groups if g not in bases]
    reader = vtkIFEMReader()
    reader.SetFileName(path)
    reader.UpdateInformation()
    if reader.GetNumberOfTimeSteps() != len(levels):
        fail("%s: %d time steps for %d levels" % (name, reader.GetNumberOfTimeSteps(),
                                                  len(levels)))
    shown = levels
    for level in shown:
        t0 = time.time()
        reader.UpdateTimeStep(reader.GetTimeStep(level))
        seconds = time.time() - t0
        out = reader.GetOutput()
        names = [out.GetMetaData(b).Get(vtkMultiBlockDataSet.NAME())
                 for b in range(out.GetNumberOfBlocks())]
        print("%s level %d: %s in %.3f s" % (name, level, names, seconds))
        for b, basis in enumerate(names):
            blocks = out.GetBlock(b)
            bl = latest(f, level, basis + "/basis")
            for p in range(1, blocks.GetNumberOfBlocks() + 1):
                grid = blocks.GetBlock(p - 1)
                text = text_of(f["%d/%s/basis/%d" % (bl, basis, p)])
                label = "%s level %d %s patch %d" % (name, level, basis, p)
                owners = [basis] + (orphans if len(bases) == 1 else [])
                fields, knotspans = {}, {}
                for kind, store in (("fields", fields), ("knotspan", knotspans)):
                    for owner in owners:
                        names_here = {n for l in range(level + 1) if "%d/%s/%s" % (l, owner, kind)
                                      in f for n in f["%d/%s/%s" % (l, owner, kind)]}
                        for fn in names_here:
                            fl = latest(f, level, "%s/%s/%s/%d" % (owner, kind, fn, p),
                                        bl if owner == basis else 0)
                            if fl is None:
                                continue
                            v = f["%d/%s/%s/%s/%d" % (fl, owner, kind, fn, p)][()].astype(float)
                            if v.size:
                                store[fn] = v
                if text.lstrip().startswith("# LAGRANGIAN"):
                    compare_lagrange(label, grid, text, fields, knotspans)
                    continue
                patch = R.parse_patch_text(text)[0]
                fields = {k: v.reshape(patch.nb, -1) for k, v in fields.items()}
                ne = len(patch.lo)
                knotspans = {k: v.reshape(ne, -1) for k, v in knotspans.items()}
                compare_spline_block(label, grid, patch, is_rational(patch), fields, knotspans,
                                     n_elem=6 if len(shown) > 3 else 10,
                                     negative=negative and b == 0 and p == 1 and level == 0)


def compare_lagrange(label, grid, text, fields, knotspans):
    kind, nodes, elements = R.parse_lagrange(text)
    npe = elements.shape[1]
    p = round(npe ** (1.0 / 3.0)) - 1
    ids = array_values(grid, "LRElementId", "cell")[:, 0].astype(int)
    fields = {k: v.reshape(len(nodes), -1) for k, v in fields.items()}
    scale = np.max(np.abs(nodes))
    for cell in RNG.choice(len(ids), size=min(12, len(ids)), replace=False):
        e = ids[cell]
        r = RNG.uniform(0.02, 0.98, 3)
        x, w, pts = vtk_evaluate(grid, cell, r)
        check(label + " Lagrange geometry", x, R.lagrange_tensor(p, r, nodes[elements[e]]), scale,
              "geometry")
        for name, values in fields.items():
            ref = R.lagrange_tensor(p, r, values[elements[e]])
            s = max(np.nanmax(np.abs(values)), 1e-300)
            for c, array in enumerate(R.component_names(name, values.shape[1])):
                a = array_values(grid, array)
                if np.isfinite(ref[c]):
                    check("%s field %r" % (label, array), w @ a[pts, 0], ref[c], s, "field")
    check_knotspans(label, grid, {k: v.reshape(len(elements), -1) for k, v in knotspans.items()})


def lr_reader(text=None, path=None, geometry=False, ext=".lr"):
    reader = vtkLRSplineReader()
    if path is None:
        path = os.path.join(OUT, "TestIFEMReader" + ext)
        with open(path, "w") as out:
            out.write(text)
    reader.SetFileName(path)
    reader.SetGeometryMode(geometry)
    reader.Update()
    if reader.GetOutput().GetNumberOfBlocks() == 0:
        fail("%s: %s" % (path, reader.GetLastErrorMessage()))
    return reader.GetOutput()


def field_mode_block(label, grid, patch):
    """Field mode: the parameter box in space, the coefficients as point data 'Field'."""
    pd = patch.pardim
    lookup = cells_by_box(grid, pd)
    a = array_values(grid, "Field")
    scale = np.max(np.abs(patch.coefs))
    for e in RNG.choice(len(patch.lo), size=min(20, len(patch.lo)), replace=False):
        cell = lookup[tuple(np.round(np.r_[patch.lo[e], patch.hi[e]], 12))]
        t = RNG.uniform(0.02, 0.98, pd)
        u = patch.lo[e] + t * (patch.hi[e] - patch.lo[e])
        x, w, ids = vtk_evaluate(grid, cell, np.r_[t, np.zeros(3 - pd)])
        check(label + " position", x[:pd], u, 1.0, "geometry")
        check(label + " field", w @ a[ids], R.field(patch, u, patch.coefs, False), scale, "field")


def lr_files():
    # cube-2patch.lr: both patches' geometry (geometry mode).
    text = open(os.path.join(DATA, "cube-2patch.lr")).read()
    out = lr_reader(path=os.path.join(DATA, "cube-2patch.lr"), geometry=True)
    for p, patch in enumerate(R.parse_lr(text)):
        compare_spline_block("cube-2patch.lr patch %d" % p, out.GetBlock(p), patch, False, {}, {},
                             n_elem=20)
    print("cube-2patch.lr: %d patches" % out.GetNumberOfBlocks())
    # An LR surface: field mode and geometry mode.
    text = open(os.path.join(DATA, "surface-refined.lr")).read()
    patch = R.parse_lr(text)[0]
    field_mode_block("surface-refined.lr", lr_reader(text).GetBlock(0), patch)
    compare_spline_block("surface-refined.lr geometry", lr_reader(text, geometry=True).GetBlock(0),
                         patch, False, {}, {}, n_elem=20)
    if lr_reader(text).GetBlock(0).GetCellType(0) != 77:
        fail("an LR surface is not read as Bezier quadrilaterals")
    # GoTools 293 (surface) and 793 (volume) from the same patches.
    field_mode_block("surface-refined as class 293", lr_reader(R.gotools_lr(text), ext=".g2")
                     .GetBlock(0), patch)
    cube = open(os.path.join(DATA, "cube-3patch-refined.lr")).read()
    first = cube[:cube.index("# LRSPLINE VOLUME", 10)]
    patch = R.parse_lr(first)[0]
    field_mode_block("cube-3patch-refined patch 0 as class 793",
                     lr_reader(R.gotools_lr(first), ext=".g2").GetBlock(0), patch)
    # A rational class 293: the NURBS shell's basis, with weights.
    f = h5py.File(os.path.join(DATA, "ifem", "ScordelisPoint-NURBS.hdf5"), "r")
    shell = text_of(f["1/Elasticity-1/basis/1"])
    patch = R.parse_lr(shell)[0]
    out = lr_reader(R.gotools_lr(shell, rational=True), geometry=True, ext=".g2")
    compare_spline_block("rational shell as class 293", out.GetBlock(0), patch, True, {}, {},
                         n_elem=20)


def rational_controls():
    """The shell's points lie on its cylinder (radius 25 about y) only when it
    is read as rational; as polynomial it has 4 coordinates: refused."""
    path = os.path.join(DATA, "ifem", "ScordelisPoint-NURBS.hdf5")
    reader = vtkIFEMReader()
    reader.SetFileName(path)
    reader.Update()
    grid = reader.GetOutput().GetBlock(0).GetBlock(0)
    radii = []
    for cell in range(0, grid.GetNumberOfCells(), 3):
        x, _, _ = vtk_evaluate(grid, cell, RNG.uniform(0, 1, 2).tolist() + [0])
        radii.append(np.hypot(x[0], x[2]))
    print("rational shell: radius about y from %.15f to %.15f" % (min(radii), max(radii)))
    if not np.allclose(radii, 25.0, rtol=1e-13, atol=0):
        fail("the rational shell is not on its cylinder")
    from vtkmodules.vtkCommonCore import vtkObject
    vtkObject.GlobalWarningDisplayOff()
    reader.SetRationalModeToPolynomial()
    reader.Update()
    vtkObject.GlobalWarningDisplayOn()
    message = reader.GetLastErrorMessage()
    print("read as polynomial: %s" % message)
    if reader.GetOutput().GetNumberOfBlocks() != 0 or "coordinates" not in message:
        fail("the rational shell read as polynomial is not refused")


def pieces():
    """Pieces split every patch's elements: together they are the whole, each exact."""
    path = os.path.join(DATA, "ifem", "Field3D-1PLR.hdf5")
    f = h5py.File(path, "r")
    patch = R.parse_patch_text(text_of(f["0/Stokes-1/basis/1"]))[0]
    u = f["0/Stokes-1/fields/u/1"][()].reshape(patch.nb, -1)
    seen = []
    for piece in range(3):
        reader = vtkIFEMReader()
        reader.SetFileName(path)
        reader.UpdatePiece(piece, 3, 0)
        grid = reader.GetOutput().GetBlock(0).GetBlock(0)
        seen += list(array_values(grid, "LRElementId", "cell")[:, 0].astype(int))
        compare_spline_block("Field3D-1PLR piece %d of 3" % piece, grid, patch, False, {"u": u}, {},
                             n_elem=27, n_pts=1, piece=True)
    print("pieces: elements %s" % sorted(seen))
    if sorted(seen) != list(range(len(patch.lo))):
        fail("the three pieces do not hold every element once")


def lagrange_quads():
    """A biquadratic Lagrange surface in 3D (IFEM's "quad" patches), made here."""
    path = os.path.join(OUT, "TestIFEMReader-lagrange-quad.hdf5")
    n = 5
    nodes = np.array([[i / 4 + 0.1 * np.sin(j), j / 4 + 0.05 * i * i, 0.3 * i * j]
                      for j in range(n) for i in range(n)])
    elements = [[(2 * ey + b) * n + 2 * ex + a for b in range(3) for a in range(3)]
                for ey in range(2) for ex in range(2)]
    text = "# LAGRANGIAN nodes=%d elements=4 type=quad\n" % len(nodes) + \
        "".join("%r %r %r\n" % tuple(float(v) for v in x) for x in nodes) + \
        "".join(" ".join(str(k) for k in e) + "\n" for e in elements)
    temperature = np.cos(nodes[:, 0] * 3) + nodes[:, 1] ** 2
    with h5py.File(path, "w") as out:
        out["0/Heat-1/basis/1"] = np.frombuffer(text.encode(), dtype=np.int8)
        out["0/Heat-1/fields/T/1"] = temperature
    reader = vtkIFEMReader()
    reader.SetFileName(path)
    reader.Update()
    grid = reader.GetOutput().GetBlock(0).GetBlock(0)
    ids = array_values(grid, "LRElementId", "cell")[:, 0].astype(int)
    T = array_values(grid, "T")
    for cell in range(grid.GetNumberOfCells()):
        for _ in range(3):
            r = RNG.uniform(0.02, 0.98, 2)
            x, w, pts = vtk_evaluate(grid, cell, np.r_[r, 0.0])
            e = np.array(elements[ids[cell]])
            check("Lagrange quad geometry", x, R.lagrange_tensor(2, r, nodes[e], 2), 1.0,
                  "geometry")
            check("Lagrange quad field", w @ T[pts, 0],
                  R.lagrange_tensor(2, r, temperature[e], 2), 2.0, "field")
    print("Lagrange quadrilaterals: %d cells of type %d" % (grid.GetNumberOfCells(),
                                                          grid.GetCellType(0)))


def main():
    for path in sorted(glob.glob(os.path.join(DATA, "ifem", "*.hdf5"))):
        ifem_file(path, negative=os.path.basename(path) == "Field3D-1PLR.hdf5")
    lr_files()
    rational_controls()
    pieces()
    lagrange_quads()
    print("largest relative errors: geometry %.3g over %d points, fields %.3g over %d values "
          "(tolerance %g)" % (worst["geometry"], counts["geometry"], worst["field"],
                              counts["field"], TOL))
    if counts["geometry"] < 1000 or counts["field"] < 5000:
        fail("too few comparisons: the test would not detect much")
    checker.finish()


if __name__ == "__main__":
    main()
