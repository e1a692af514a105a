# SPDX-License-Identifier: BSD-3-Clause
"""An independent reference for the spline tests: parsers of the LRSplines text,
GoTools g2 (classes 200, 700) and IFEM Lagrange patch formats, and a direct
evaluation of the splines they hold, written from the formats' definitions
(docs/spline-formats.md, docs/ifem.md) with numpy only. Nothing here calls
SplineViz.

An LR spline is evaluated as the sum over ALL its basis functions
    f(u) = sum_i gamma_i c_i prod_d B(T_i,d; u_d)
with B the Cox-de Boor B-spline of the function's local knot vector T_i,d;
a rational one (homogeneous coefficients, the last component the weight w)
as the quotient of the first components by the last; fields on a rational
basis as sum_i gamma_i B_i w_i f_i / sum_i gamma_i B_i w_i.
"""
import re

import numpy as np


class Patch:
    """Basis functions (local knot vectors per direction, gamma), their
    coefficients, and the element boxes (lower corner, upper corner)."""

    def __init__(self, pardim, knots, coefs, gamma, lo, hi, rational_flag=0, kind="lr"):
        self.kind = kind              # "lr" (LRSplines text) or "g2"
        self.pardim = pardim
        self.knots = knots            # list over directions of arrays (nb, order+1)
        self.coefs = np.asarray(coefs, dtype=float)  # (nb, dim)
        self.gamma = np.asarray(gamma, dtype=float)
        self.lo = np.asarray(lo, dtype=float)        # (ne, pardim)
        self.hi = np.asarray(hi, dtype=float)
        self.rational_flag = rational_flag

    @property
    def nb(self):
        return len(self.gamma)


def _numbers(text):
    return [float(t) for t in text.replace(",", " ").split()]


def parse_lr(text):
    """All patches of an LRSplines text ("# LRSPLINE SURFACE/VOLUME")."""
    lines = text.splitlines()
    patches = []
    i = 0
    while i < len(lines):
        line = lines[i].strip()
        m = re.match(r"#\s*LRSPLINE\s+(SURFACE|VOLUME)", line)
        if not m:
            i += 1
            continue
        pardim = 2 if m.group(1) == "SURFACE" else 3
        i += 1
        while lines[i].strip().startswith("#"):
            i += 1
        head = [int(v) for v in lines[i].split()]
        i += 1
        orders = head[:pardim]
        nb, nl, ne, dim, rat = head[pardim:pardim + 5]
        while lines[i].strip().startswith("#"):
            i += 1
        knots = [[] for _ in range(pardim)]
        coefs, gamma = [], []
        for _ in range(nb):
            line = lines[i]
            i += 1
            vectors = re.findall(r"\[([^\]]*)\]", line)
            for d in range(pardim):
                knots[d].append(_numbers(vectors[d]))
            rest = line[line.rindex("]") + 1:]
            g = re.search(r"\(([^)]*)\)", rest)
            gamma.append(float(g.group(1)))
            coefs.append(_numbers(rest[:g.start()]))
        while lines[i].strip().startswith("#"):
            i += 1
        i += nl
        while lines[i].strip().startswith("#"):
            i += 1
        lo, hi = [], []
        for _ in range(ne):
            corners = re.findall(r"\(([^)]*)\)", lines[i].split(":", 1)[1])
            lo.append(_numbers(corners[0]))
            hi.append(_numbers(corners[1]))
            i += 1
        patches.append(Patch(pardim, [np.array(k) for k in knots], coefs, gamma, lo, hi, rat))
    return patches


def parse_g2(text):
    """All tensor-product patches (classes 200, 700) of a g2 text. Rational
    patches keep their homogeneous coefficients (rational_flag 1)."""
    tok = text.split()
    pos = 0
    patches = []
    while pos < len(tok):
        cls = int(tok[pos])
        ncolour = int(tok[pos + 3])
        pos += 4 + ncolour
        pardim = {200: 2, 700: 3}[cls]
        dim, rat = int(tok[pos]), int(tok[pos + 1])
        pos += 2
        n, order, gknots = [], [], []
        for _ in range(pardim):
            n.append(int(tok[pos]))
            order.append(int(tok[pos + 1]))
            pos += 2
            gknots.append(np.array([float(v) for v in tok[pos:pos + n[-1] + order[-1]]]))
            pos += n[-1] + order[-1]
        total = int(np.prod(n))
        width = dim + rat
        coefs = np.array([float(v) for v in tok[pos:pos + total * width]]).reshape(total, width)
        pos += total * width
        knots = [[] for _ in range(pardim)]
        for f in range(total):
            idx = []
            rest = f
            for d in range(pardim):
                idx.append(rest % n[d])
                rest //= n[d]
            for d in range(pardim):
                knots[d].append(gknots[d][idx[d]:idx[d] + order[d] + 1])
        breaks = [np.unique(k) for k in gknots]
        grids = np.meshgrid(*[np.arange(len(b) - 1) for b in breaks], indexing="ij")
        cells = np.stack([g.ravel(order="F") for g in grids], axis=1)
        lo = np.stack([breaks[d][cells[:, d]] for d in range(pardim)], axis=1)
        hi = np.stack([breaks[d][cells[:, d] + 1] for d in range(pardim)], axis=1)
        patches.append(Patch(pardim, [np.array(k) for k in knots], coefs, np.ones(total), lo, hi,
                             rat, "g2"))
    return patches


def parse_patch_text(text):
    text = text.lstrip()
    if text.startswith("#"):
        return parse_lr(text)
    return parse_g2(text)


def bsplines(T, x):
    """Values at x of the B-splines whose local knot vectors are the rows of
    T (Cox-de Boor on half-open intervals [t_j, t_j+1))."""
    p = T.shape[1] - 2
    N = ((T[:, :-1] <= x) & (x < T[:, 1:])).astype(float)
    for k in range(1, p + 1):
        for j in range(0, p - k + 1):
            d1 = T[:, j + k] - T[:, j]
            d2 = T[:, j + k + 1] - T[:, j + 1]
            a = np.where(d1 > 0, (x - T[:, j]) / np.where(d1 > 0, d1, 1.0) * N[:, j], 0.0)
            b = np.where(d2 > 0, (T[:, j + k + 1] - x) / np.where(d2 > 0, d2, 1.0) * N[:, j + 1],
                         0.0)
            N[:, j] = a + b
    return N[:, 0]


def basis(patch, u):
    """gamma_i prod_d B_i,d(u_d) for every basis function (u: pardim values)."""
    B = patch.gamma.copy()
    for d in range(patch.pardim):
        B *= bsplines(patch.knots[d], u[d])
    return B


def geometry(patch, u, rational, B=None):
    """The patch's map at u: its coefficients, homogeneous when rational.
    B: the basis values at u when already known."""
    B = basis(patch, u) if B is None else B
    h = B @ patch.coefs
    return h[:-1] / h[-1] if rational else h


def field(patch, u, values, rational, B=None):
    """A field (values: nb x components) on the patch's basis at u."""
    B = basis(patch, u) if B is None else B
    if rational:
        w = patch.coefs[:, -1]
        return (B * w) @ values / (B @ w)
    return B @ values


def component_names(name, nc):
    """The arrays the reader documents for a field (vtkIFEMBlockBuilder)."""
    if "&&" in name:
        parts = [p.strip() for p in name.split("&&")]
        if " " in parts[0]:
            prefix, parts[0] = parts[0].split(" ", 1)
            parts = [prefix + " " + p for p in parts]
        if len(parts) == nc:
            return parts
    if nc == 1:
        return [name]
    if nc <= 3:
        return [name + "_" + "xyz"[c] for c in range(nc)]
    return [name + "_%d" % c for c in range(nc)]


def domain(patch):
    """The parameter domain (lower corner, upper corner)."""
    return patch.lo.min(axis=0), patch.hi.max(axis=0)


def clamp(patch, u):
    """u kept in the domain, just below its upper ends (the B-splines here are
    half-open: at the upper end itself they vanish)."""
    lo, hi = domain(patch)
    return np.clip(u, lo, hi - 1e-13 * (hi - lo))


def tangents(patch, u, rational, h=1e-7):
    """d x / d u_d of the map by central differences (columns), clamped to
    the domain: enough for Newton's direction; the residual stays exact."""
    cols = []
    for d in range(patch.pardim):
        a, b = np.array(u, float), np.array(u, float)
        a[d] -= h
        b[d] += h
        a, b = clamp(patch, a), clamp(patch, b)
        cols.append((geometry(patch, b, rational) - geometry(patch, a, rational)) / (b[d] - a[d]))
    return np.stack(cols, axis=1)


def invert_surface(patch, x, rational, u0, tol=1e-14, iterations=50):
    """The parameter u of a surface patch whose x(u) is nearest x (Gauss-Newton
    on |x(u) - x|^2 with difference tangents, from u0, kept in the domain).
    Returns (u, distance), or (None, inf) when Newton does not converge."""
    lo, hi = domain(patch)
    u = np.array(u0, float)
    x = np.asarray(x, float)
    for _ in range(iterations):
        r = geometry(patch, u, rational)[:len(x)] - x
        J = tangents(patch, u, rational)[:len(x)]
        step = np.linalg.lstsq(J, r, rcond=None)[0]
        new = clamp(patch, u - step)
        moved = np.max(np.abs(new - u) / (hi - lo))
        u = new
        if moved < tol:
            return u, np.linalg.norm(geometry(patch, u, rational)[:len(x)] - x)
    return None, np.inf


class SurfaceField:
    """A field on the patches of a planar (nsd 2, or z = 0) surface result,
    evaluated at physical points by this module's own inversion: the patch
    whose sampled points lie nearest x is tried first."""

    def __init__(self, patches, values, rational, samples=21):
        self.patches, self.values, self.rational = patches, values, rational
        self.starts = []
        for p in patches:
            lo, hi = domain(p)
            g = np.linspace(0.0, 1.0, samples)
            U = np.array([clamp(p, [lo[0] + a * (hi[0] - lo[0]), lo[1] + b * (hi[1] - lo[1])])
                          for a in g for b in g])
            X = np.array([geometry(p, u, rational)[:2] for u in U])
            self.starts.append((U, X))

    def locate(self, x):
        """(patch index, u) of planar x, or (None, None) outside."""
        x = np.asarray(x, float)[:2]
        near = [np.min(np.linalg.norm(X - x, axis=1)) for _, X in self.starts]
        for k in np.argsort(near):
            U, X = self.starts[k]
            u0 = U[np.argmin(np.linalg.norm(X - x, axis=1))]
            u, dist = invert_surface(self.patches[k], x, self.rational, u0)
            if u is not None and dist < 1e-9:
                return k, u
        return None, None

    def __call__(self, x):
        k, u = self.locate(x)
        if k is None:
            return None
        return field(self.patches[k], u, self.values[k], self.rational)


def parse_lagrange(text):
    """IFEM's "# LAGRANGIAN nodes=N elements=M type=T": nodes (N, 3), elements (M, k)."""
    lines = text.strip().splitlines()
    head = dict(item.split("=") for item in lines[0].split()[2:])
    nn, ne = int(head["nodes"]), int(head["elements"])
    nodes = np.array([[float(v) for v in line.split()] for line in lines[1:1 + nn]])
    elements = np.array([[int(v) for v in line.split()] for line in lines[1 + nn:1 + nn + ne]])
    return head["type"], nodes, elements


def lagrange_1d(p, s):
    """The p+1 Lagrange polynomials on equally spaced nodes of [0, 1] at s."""
    nodes = np.linspace(0.0, 1.0, p + 1)
    out = np.ones(p + 1)
    for i in range(p + 1):
        for j in range(p + 1):
            if j != i:
                out[i] *= (s - nodes[j]) / (nodes[i] - nodes[j])
    return out


def lagrange_tensor(p, r, nodal, dim=3):
    """Tensor Lagrange interpolation in an element whose (p+1)^dim nodal
    values are numbered with the first direction fastest (IFEM's order)."""
    L = [lagrange_1d(p, r[d]) for d in range(dim)]
    if dim == 3:
        w = np.einsum("k,j,i->kji", L[2], L[1], L[0]).ravel()
    else:
        w = np.einsum("j,i->ji", L[1], L[0]).ravel()
    return w @ nodal


def gotools_lr(text, rational=False):
    """Class 293 / 793 text of the LRSplines text patch `text` (GoTools'
    LRSplineSurface / LRSplineVolume::write layout: see docs/spline-formats.md)."""
    lines = text.splitlines()
    patch = parse_lr(text)[0]
    pd = patch.pardim
    # Mesh rectangles of the LRSplines text (lines for surfaces).
    rects = []
    in_mesh = False
    for line in lines:
        if line.startswith("# Mesh"):
            in_mesh = True
            continue
        if line.startswith("# Elements"):
            break
        if in_mesh and line.strip():
            body, mult = line.rsplit("(", 1)
            mult = int(mult.strip(" )"))
            parts = body.split("x")
            lo, hi = [], []
            for part in parts:
                nums = _numbers(part.replace("[", " ").replace("]", " "))
                lo.append(nums[0])
                hi.append(nums[-1])
            rects.append((lo, hi, mult))
    knots = [np.unique(np.r_[patch.lo[:, d], patch.hi[:, d]]) for d in range(pd)]
    out = ["%d 1 0 0" % (293 if pd == 2 else 793), "%d 1e-12" % (1 if rational else 0)]
    for d in range(pd):
        out.append("%d %s" % (len(knots[d]), " ".join(repr(float(v)) for v in knots[d])))
    index = [{v: i for i, v in enumerate(k)} for k in knots]
    for d in range(pd):
        planes = []
        for pos, value in enumerate(knots[d]):
            mine = [(lo, hi, m) for lo, hi, m in rects if lo[d] == hi[d] == value]
            if pd == 2:
                o = 1 - d
                mult = np.zeros(len(knots[o]) - 1, dtype=int)
                for lo, hi, m in mine:
                    mult[index[o][lo[o]]:index[o][hi[o]]] = m
                runs = [(0, mult[0])] + [(j, mult[j]) for j in range(1, len(mult))
                                         if mult[j] != mult[j - 1]]
                planes.append("%d %s" % (len(runs), " ".join("%d %d" % r for r in runs)))
            else:
                a, b = (d + 1) % 3, (d + 2) % 3
                items = ["%d %d %d %d %d" % (index[a][lo[a]], index[b][lo[b]], index[a][hi[a]],
                                             index[b][hi[b]], m) for lo, hi, m in mine]
                planes.append("%d %s" % (len(items), " ".join(items)))
        out.append("%d\n%s" % (len(planes), "\n".join(planes)))
    out.append("%d" % patch.nb)
    dim = patch.coefs.shape[1] - (1 if rational else 0)
    for i in range(patch.nb):
        c = patch.coefs[i]
        weight = c[-1] if rational else 1.0
        cart = c[:dim] / weight
        out.append("%d %d\n%s %r %r" % (dim, 1 if rational else 0,
                                          " ".join(repr(float(v * patch.gamma[i])) for v in cart),
                                          float(patch.gamma[i]), float(weight)))
        for d in range(pd):
            kv = patch.knots[d][i]
            out.append("%d %s" % (len(kv), " ".join(str(index[d][v]) for v in kv)))
    return "\n".join(out) + "\n"
