# SPDX-License-Identifier: BSD-3-Clause
"""vtkStreamlineSelection's label-image regions against a numpy reference.

Label volumes written by nibabel around DIPY's real cb_2 bundle under
affines that rotate and flip (sform and qform) or shear and flip (sform
only), read by vtkNIfTIVolumeReader (which places them in RAS+ mm with
reversed slices and a direction matrix). For random label sets and roles
(INCLUDE, EXCLUDE, ENDPOINT either / both ends, AND / OR, with a sphere),
the selected streamlines must be those of the reference, which works from
nibabel's affine alone: each segment is taken to voxel coordinates with the
inverse affine, and tested against every voxel of the set (the cube of side 1
around its index) by the separating-axis theorem; end points by their
nearest voxel. Cell-data labels of a vtkImageData are tested the same way
against world boxes. Negative controls: the reference with the flip left out
of the affine, and one sampling only the vertices, disagree. Bad input: an
empty label set, a missing or three-component array, no image, a singular
placement (spacing 0), a label array that does not match the extent.
"""
import os
import sys

import numpy as np

try:
    import nibabel as nib
    from dipy.data import get_fnames
except ImportError as error:
    print("nibabel or DIPY not available (python3-nibabel, python3-dipy), skipped:", error)
    sys.exit(125)

from vtkmodules.util.numpy_support import numpy_to_vtk, numpy_to_vtkIdTypeArray, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkIdList, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkImageData, vtkPolyData

import splineviz
from splineviz_testing import output_dir

out_dir = output_dir()
from splineviz_testing import Checker, Observed  # noqa: E402

checker = Checker()
rng = np.random.default_rng(4242)
S = splineviz.vtkStreamlineSelection


check = checker.check


cb = np.load(os.path.join(os.path.dirname(get_fnames("small_64D")[0]), "cb_2.npz"))
ends = np.asarray(cb["offsets"], dtype=np.int64)
starts = np.r_[0, ends[:-1]]
points32 = np.asarray(cb["points"], dtype=np.float32)
streamlines = [points32[s:e].astype(np.float64) for s, e in zip(starts, ends)]
N = len(streamlines)

pd = vtkPolyData()
vp = vtkPoints()
vp.SetData(numpy_to_vtk(points32, deep=True))
pd.SetPoints(vp)
cells = vtkCellArray()
cells.SetData(numpy_to_vtkIdTypeArray(np.r_[0, ends], deep=True),
              numpy_to_vtkIdTypeArray(np.arange(len(points32), dtype=np.int64), deep=True))
pd.SetLines(cells)
index_array = numpy_to_vtk(np.arange(N, dtype=np.int32), deep=True)
index_array.SetName("StreamlineIndex")
pd.GetCellData().AddArray(index_array)

A_SEG = np.concatenate([s[:-1] for s in streamlines])
B_SEG = np.concatenate([s[1:] for s in streamlines])
OWNER = np.concatenate([np.full(len(s) - 1, i) for i, s in enumerate(streamlines)])
FIRST = np.array([s[0] for s in streamlines])
LAST = np.array([s[-1] for s in streamlines])


# --- the reference ---------------------------------------------------------------
def segment_box_sat(a, b, lo, hi):
    """Separating-axis test of segments [a, b] against the box [lo, hi]."""
    c = 0.5 * (lo + hi)
    h = 0.5 * (hi - lo)
    m = 0.5 * (a + b) - c
    w = 0.5 * (b - a)
    overlap = np.all(np.abs(m) <= h + np.abs(w), axis=1)
    for i in range(3):
        axis = np.zeros(3)
        axis[i] = 1.0
        n = np.cross(axis, w)
        overlap &= np.abs(np.einsum("ij,ij->i", m, n)) <= np.abs(n) @ h
    return overlap


def to_voxels(p, affine):
    inv = np.linalg.inv(affine)
    return p @ inv[:3, :3].T + inv[:3, 3]


def touches_labels(affine, labels, label_set, vertices_only=False):
    """Per streamline: does it touch a voxel whose label is in label_set?"""
    a, b = to_voxels(A_SEG, affine), to_voxels(B_SEG, affine)
    voxels = np.argwhere(np.isin(labels, list(label_set)))
    hit = np.zeros(len(a), dtype=bool)
    for v in voxels:
        if vertices_only:
            hit |= np.all(np.abs(a - v) <= 0.5, axis=1) | np.all(np.abs(b - v) <= 0.5, axis=1)
        else:
            hit |= segment_box_sat(a, b, v - 0.5, v + 0.5)
    out = np.zeros(N, dtype=bool)
    np.logical_or.at(out, OWNER, hit)
    return out


def point_labels_in(p, affine, labels, label_set):
    v = np.floor(to_voxels(p, affine) + 0.5).astype(int)
    inside = np.all((v >= 0) & (v < np.array(labels.shape)), axis=1)
    result = np.zeros(len(p), dtype=bool)
    vi = v[inside]
    result[inside] = np.isin(labels[vi[:, 0], vi[:, 1], vi[:, 2]], list(label_set))
    return result


def ends_in(affine, labels, label_set, both):
    f = point_labels_in(FIRST, affine, labels, label_set)
    last = point_labels_in(LAST, affine, labels, label_set)
    return (f & last) if both else (f | last)


def segment_sphere(centre, radius):
    d = B_SEG - A_SEG
    t = np.clip(np.einsum("ij,ij->i", centre - A_SEG, d) / np.einsum("ij,ij->i", d, d), 0, 1)
    hit = np.linalg.norm(A_SEG + t[:, None] * d - centre, axis=1) <= radius
    out = np.zeros(N, dtype=bool)
    np.logical_or.at(out, OWNER, hit)
    return out


# --- the label volumes -----------------------------------------------------------
def rotation(angles):
    ax, ay, az = np.radians(angles)
    rx = np.array([[1, 0, 0], [0, np.cos(ax), -np.sin(ax)], [0, np.sin(ax), np.cos(ax)]])
    ry = np.array([[np.cos(ay), 0, np.sin(ay)], [0, 1, 0], [-np.sin(ay), 0, np.cos(ay)]])
    rz = np.array([[np.cos(az), -np.sin(az), 0], [np.sin(az), np.cos(az), 0], [0, 0, 1]])
    return rz @ ry @ rx


def make_volume(linear, name, sform_only):
    """A label volume around cb_2 with the voxel-to-world matrix `linear`; returns
    (path, the affine nibabel reads back, the labels in nibabel's index order)."""
    q = np.concatenate(streamlines) @ np.linalg.inv(linear).T
    qmin, qmax = q.min(axis=0) - 3, q.max(axis=0) + 3
    shape = tuple(int(x) for x in np.ceil(qmax - qmin) + 1)
    affine = np.eye(4)
    affine[:3, :3] = linear
    affine[:3, 3] = linear @ qmin
    labels = np.zeros(shape, dtype=np.int16)
    grid = np.stack(np.meshgrid(*[np.arange(n) for n in shape], indexing="ij"), axis=-1)
    # Balls of labels 1-6 of radius 1.5 voxels around points of the bundle, and scattered 7-9.
    all_points = np.concatenate(streamlines)
    for label in range(1, 7):
        centre = (all_points[rng.integers(len(all_points))] - affine[:3, 3]) @ np.linalg.inv(linear).T
        labels[np.linalg.norm(grid - centre, axis=-1) <= 1.5] = label
    flat = rng.integers(labels.size, size=40)
    labels.flat[flat] = rng.integers(7, 10, size=40)
    image = nib.Nifti1Image(labels, affine)
    if sform_only:
        image.set_qform(None, code=0)
        image.set_sform(affine, code=2)
    else:
        image.set_qform(affine, code=1)
        image.set_sform(affine, code=1)
    path = os.path.join(out_dir, "TestStreamlineSelectionLabels-%s.nii.gz" % name)
    nib.save(image, path)
    back = nib.load(path)
    return path, back.affine, np.asarray(back.dataobj)


flip = np.diag([-1.0, 1.0, 1.0])
volumes = [
    ("rotated-flipped", rotation((20, -35, 50)) @ np.diag([2.0, 2.5, 1.8]) @ flip, flip, False),
    ("sheared-flipped",
     (np.eye(3) + np.array([[0, 0.2, 0], [0, 0, -0.15], [0.1, 0, 0]])) @ rotation((-10, 15, 80))
     @ np.diag([1.6, 2.2, 2.0]) @ np.diag([1.0, 1.0, -1.0]), np.diag([1.0, 1.0, -1.0]), True),
]

ROLES = (S.INCLUDE, S.EXCLUDE, S.ENDPOINT)
for name, linear, mirror, sform_only in volumes:
    path, affine, labels = make_volume(linear, name, sform_only)
    reader = splineviz.vtkNIfTIVolumeReader()
    reader.SetFileName(path)
    reader.SetArrayName("labels")
    reader_messages = Observed(reader)  # the sheared file's warning
    reader.Update()
    image = reader.GetOutput()
    check(np.linalg.det(affine[:3, :3]) < 0
          and vtk_to_numpy(image.GetFieldData().GetArray("NIfTISlicesReversed"))[0] == 1,
          "%s: det < 0, the reader reversed the slices" % name)
    mismatches, nontrivial, vertex_disagrees, flip_disagrees = 0, 0, 0, 0
    trials = 40
    for trial in range(trials):
        label_set = set(int(x) for x in rng.choice(np.arange(1, 10), size=rng.integers(1, 4),
                                                    replace=False))
        role = ROLES[trial % 3]
        both = bool(rng.integers(2))
        combine_and = bool(rng.integers(2))
        with_sphere = trial % 4 == 3
        f = S()
        f.SetInputData(pd)
        ids = vtkIdList()
        for label in sorted(label_set):
            ids.InsertNextId(label)
        f.AddLabelImage(image, "labels", ids, role)
        f.SetEndpointMode(S.BOTH_ENDS if both else S.EITHER_END)
        f.SetIncludeCombination(S.COMBINE_AND if combine_and else S.COMBINE_OR)
        if role == S.ENDPOINT:
            expected = ends_in(affine, labels, label_set, both)
        else:
            expected = touches_labels(affine, labels, label_set)
        unflipped = affine.copy()  # the flip undone (the volume mirrored about its first voxel)
        unflipped[:3, :3] = affine[:3, :3] @ mirror
        wrong = touches_labels(unflipped, labels, label_set) if role != S.ENDPOINT else \
            ends_in(unflipped, labels, label_set, both)
        vertex = touches_labels(affine, labels, label_set, vertices_only=True) \
            if role != S.ENDPOINT else expected
        if role == S.EXCLUDE:
            expected, wrong, vertex = ~expected, ~wrong, ~vertex
        if with_sphere:
            centre = streamlines[rng.integers(N)][rng.integers(18)]
            f.AddSphere(list(centre), 5.0, S.INCLUDE)
            sphere = segment_sphere(centre, 5.0)
            combine = (lambda x, y: x & y) if combine_and else (lambda x, y: x | y)
            if role == S.EXCLUDE:
                expected, wrong, vertex = (expected & sphere, wrong & sphere, vertex & sphere)
            else:
                expected, wrong, vertex = (combine(expected, sphere), combine(wrong, sphere),
                                           combine(vertex, sphere))
        errors = Observed(f)
        f.Update()
        got = np.zeros(N, dtype=bool)
        got[vtk_to_numpy(f.GetOutput().GetCellData().GetArray("StreamlineIndex"))] = True
        if errors.all_messages or not np.array_equal(got, expected):
            mismatches += 1
            if mismatches <= 3:
                print("  %s trial %d (labels %s role %d): %d differ %s" % (
                    name, trial, label_set, role, np.sum(got != expected), errors.all_messages))
        nontrivial += int(0 < expected.sum() < N)
        vertex_disagrees += int(not np.array_equal(vertex, expected))
        flip_disagrees += int(not np.array_equal(wrong, expected))
    check(mismatches == 0, "%s: %d random label sets and roles, identical streamline sets "
          "(%d differ)" % (name, trials, mismatches))
    check(nontrivial > trials // 3, "%s: %d trials select some but not all" % (name, nontrivial))
    check(vertex_disagrees > 0, "%s: negative control, vertex sampling disagrees in %d trials"
          % (name, vertex_disagrees))
    check(flip_disagrees > trials // 3, "%s: negative control, the affine without its flip "
          "disagrees in %d trials" % (name, flip_disagrees))

# --- cell-data labels ------------------------------------------------------------------
lo = np.concatenate(streamlines).min(axis=0) - 2
spacing = np.array([3.0, 4.0, 2.5])
cells_n = (np.ceil((np.concatenate(streamlines).max(axis=0) + 2 - lo) / spacing)).astype(int)
cell_labels = rng.integers(0, 40, size=tuple(cells_n[::-1])).astype(np.uint8)  # z, y, x
img = vtkImageData()
img.SetOrigin(*lo)
img.SetSpacing(*spacing)
img.SetDimensions(*(cells_n + 1))
arr = numpy_to_vtk(cell_labels.ravel(), deep=True)
arr.SetName("parcels")
img.GetCellData().AddArray(arr)
f = S()
f.SetInputData(pd)
ids = vtkIdList()
ids.InsertNextId(3)
f.AddLabelImage(img, "parcels", ids, S.INCLUDE)
f.Update()
got = np.zeros(N, dtype=bool)
got[vtk_to_numpy(f.GetOutput().GetCellData().GetArray("StreamlineIndex"))] = True
hit = np.zeros(len(A_SEG), dtype=bool)
for k, j, i in np.argwhere(cell_labels == 3):
    cell_lo = lo + spacing * np.array([i, j, k])
    hit |= segment_box_sat(A_SEG, B_SEG, cell_lo, cell_lo + spacing)
expected = np.zeros(N, dtype=bool)
np.logical_or.at(expected, OWNER, hit)
check(np.array_equal(got, expected) and 0 < expected.sum() < N,
      "cell-data labels: each cell its own box (%d selected)" % expected.sum())

# --- bad input ----------------------------------------------------------------------------
empty = vtkIdList()
one = vtkIdList()
one.InsertNextId(1)
vector_image = vtkImageData()
vector_image.DeepCopy(image)
vec = numpy_to_vtk(np.zeros((image.GetNumberOfPoints(), 3)), deep=True)
vec.SetName("labels")
vector_image.GetPointData().RemoveArray("labels")
vector_image.GetPointData().AddArray(vec)
# Image spaces that do not fit: a flat placement (spacing 0 along z), and a
# label array shorter than the image's extent.
flat_image = vtkImageData()
flat_image.DeepCopy(image)
flat_image.SetSpacing(image.GetSpacing()[0], image.GetSpacing()[1], 0.0)
short_image = vtkImageData()
short_image.DeepCopy(image)
short = numpy_to_vtk(np.ones(image.GetNumberOfPoints() - 7), deep=True)
short.SetName("labels")
short_image.GetPointData().RemoveArray("labels")
short_image.GetPointData().AddArray(short)
for what, add, phrase in (
        ("a singular placement", lambda f: f.AddLabelImage(flat_image, "labels", one, S.INCLUDE),
         "placement (spacing, direction) is singular"),
        ("an array shorter than the extent",
         lambda f: f.AddLabelImage(short_image, "labels", one, S.INCLUDE),
         "does not match its extent"),
        ("empty label set", lambda f: f.AddLabelImage(image, "labels", empty, S.INCLUDE), "empty"),
        ("no such array", lambda f: f.AddLabelImage(image, "nothing", one, S.INCLUDE),
         "no one-component point or cell array named 'nothing'"),
        ("three components", lambda f: f.AddLabelImage(vector_image, "labels", one, S.EXCLUDE),
         "no one-component"),
        ("no image", lambda f: f.AddLabelImage(None, "labels", one, S.ENDPOINT), "no image")):
    f = S()
    f.SetInputData(pd)
    add(f)
    errors = Observed(f)
    f.Update()
    check(any(phrase in e for e in errors.all_messages)
          and any("returned failure" in e for e in errors.all_messages)
          and f.GetOutput().GetNumberOfPoints() == 0,
          "bad input, %s: %s" % (what, errors.all_messages[:1]))
f = S()
f.AddSphere(0, 0, 0, 1, S.INCLUDE)
errors = Observed(f)
f.AddRegionLabel(0, 3)
check(any("not a label-image region" in e for e in errors.all_messages),
      "AddRegionLabel on a sphere: an error")

checker.finish()
print("all passed")
