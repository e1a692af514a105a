# SPDX-License-Identifier: BSD-3-Clause
"""IFEM-Poisson's cube-2patch problem as an IFEM HDF5 result, for the tests.

cube-2patch.lr (two LR patches, [-1, 0] x [0, 1]^2 and [0, 1]^3: the geometry
of cube-2patch.xinp) carries the analytic solution u = sin(pi x) sin(pi y)
sin(pi z) and its flux q = -grad u, projected onto each patch's basis by
least squares (numpy, with ifem_reference.py's independent evaluation of the
LR basis), written with h5py in IFEM's layout. `curved`: every coefficient of
the geometry bent by a smooth map first (the patches still meet exactly).
"""
import os

import h5py
import numpy as np

import ifem_reference as R

PI = np.pi
SOURCE = os.environ.get("SPLINEVIZ_SOURCE_DIR",
                        os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
DATA = os.path.join(SOURCE, "Testing", "Data", "External")
_BASIS = {}


def analytic(x):
    return np.sin(PI * x[..., 0]) * np.sin(PI * x[..., 1]) * np.sin(PI * x[..., 2])


def flux(x):
    s = np.sin(PI * x)
    c = np.cos(PI * x)
    return -PI * np.stack([c[..., 0] * s[..., 1] * s[..., 2], s[..., 0] * c[..., 1] * s[..., 2],
                           s[..., 0] * s[..., 1] * c[..., 2]], axis=-1)


def bend(x):
    """A smooth, injective, non-affine map of the two cubes."""
    y = x.copy()
    y[..., 0] = x[..., 0] + 0.08 * np.sin(PI * x[..., 1]) * np.sin(PI * x[..., 2])
    y[..., 1] = x[..., 1] + 0.06 * np.sin(PI * x[..., 0]) + 0.04 * x[..., 2] ** 2
    y[..., 2] = x[..., 2] + 0.05 * np.sin(PI * x[..., 0]) * x[..., 1]
    return y


def lr_text_with(text, coefs):
    """The LRSplines text of one patch with new coefficients."""
    out, k = [], 0
    for line in text.splitlines():
        if ": [" in line and line.rstrip().endswith(")"):
            head = line[:line.rindex("]") + 1]
            gamma = line[line.rindex("("):]
            line = head + " " + " ".join(repr(float(c)) for c in coefs[k]) + " " + gamma
            k += 1
        out.append(line)
    assert k == len(coefs)
    return "\n".join(out) + "\n"


def patch_texts():
    text = open(os.path.join(DATA, "cube-2patch.lr")).read()
    return ["# LRSPLINE VOLUME" + p for p in text.split("# LRSPLINE VOLUME")[1:]]


def sample_points(patch, per):
    g = (np.arange(per) + 0.5) / per
    pts = []
    for lo, hi in zip(patch.lo, patch.hi):
        for a in g:
            for b in g:
                for c in g:
                    pts.append(lo + (hi - lo) * np.array([a, b, c]))
    return np.array(pts)


def project(patch, index):
    """Least-squares coefficients of u and q on the patch's basis (8 points
    per element; the basis matrix is kept for the other geometry)."""
    if index not in _BASIS:
        _BASIS[index] = np.array([R.basis(patch, u) for u in sample_points(patch, 2)])
    B = _BASIS[index]
    X = B @ patch.coefs
    rhs = np.column_stack([analytic(X), flux(X)])
    coef, *_ = np.linalg.lstsq(B, rhs, rcond=None)
    return coef


def write(path, curved):
    """Write the result; returns the patches (with .values: u, q per basis
    function) for independent evaluation."""
    texts = patch_texts()
    patches = [R.parse_lr(t)[0] for t in texts]
    if curved:
        for i, p in enumerate(patches):
            p.coefs = bend(p.coefs)
            texts[i] = lr_text_with(texts[i], p.coefs)
    with h5py.File(path, "w") as f:
        g = f.create_group("0/Poisson-1")
        for i, (text, patch) in enumerate(zip(texts, patches), start=1):
            g.create_dataset("basis/%d" % i, data=np.frombuffer(text.encode(), dtype=np.int8))
            c = project(patch, i)
            g.create_dataset("fields/u/%d" % i, data=c[:, 0].copy())
            g.create_dataset("fields/q/%d" % i, data=c[:, 1:4].reshape(-1).copy())
            patch.values = c
    return patches
