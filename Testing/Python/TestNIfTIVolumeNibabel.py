# SPDX-License-Identifier: BSD-3-Clause
"""vtkNIfTIVolumeReader against nibabel, the independent implementation.

Files written by nibabel (random values, and DIPY's real aniso_vox brain, an
oblique flipped int16 scan, and its S0_10slices, a sheared uint16 one) under
affines that rotate and flip, given as sform and qform (qfac -1), sform only,
qform only; NIfTI-2, big-endian, .hdr/.img pairs, .nii.gz. For every point of
the reader's output, the voxel nibabel's affine puts there (inverse affine of
the point from GetPoint(), i.e. with the direction matrix) must be a whole
voxel index (to 1e-4 mm), every voxel must be hit once, and the value must be
nibabel's at that voxel: exactly for unscaled data (integer volumes stay
integers of the same type), to float32 rounding for scaled int16 (float),
exactly for scaled int32 (double). 4D: 3 volumes become 3 components, 7
volumes one volume chosen by VolumeIndex (or 7 components on request), a 5D
vector 3 components; RGB24 3 unsigned char components. The tensor reader puts
the same grid at the same points. A sub-extent gives the same values at the
same points. Negative controls: the pixdim affine of a rotated file, and the
values looked up at transposed indices, must fail the checks.
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

from vtkmodules.util.numpy_support import vtk_to_numpy

import splineviz
from splineviz_testing import output_dir

out = output_dir()
from splineviz_testing import Checker, Observed  # noqa: E402

checker = Checker()
rng = np.random.default_rng(29)


check = checker.check


def read(path, **options):
    reader = splineviz.vtkNIfTIVolumeReader()
    errors = Observed(reader)
    reader.SetFileName(path)
    for key, value in options.items():
        getattr(reader, "Set" + key)(value)
    reader.Update()
    return reader, reader.GetOutput(), errors


def rotation(angle_deg, axis):
    axis = np.asarray(axis, float) / np.linalg.norm(axis)
    k = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    a = np.radians(angle_deg)
    return np.eye(3) + np.sin(a) * k + (1 - np.cos(a)) * k @ k


def make_affine(angle, axis, zooms, offset, flip):
    a = np.eye(4)
    a[:3, :3] = rotation(angle, axis) @ np.diag(zooms) @ np.diag([-1.0 if flip else 1.0, 1, 1])
    a[:3, 3] = offset
    return a


def compare(image, affine, values, label, tolerance=0.0, lookup=None):
    """Positions against `affine` (nibabel's), values against `values` (x, y, z[, c]).
    Returns (position error in mm, every voxel once, largest value error)."""
    n = image.GetNumberOfPoints()
    points = np.array([image.GetPoint(i) for i in range(n)])
    ijk = nib.affines.apply_affine(np.linalg.inv(affine), points)
    index = np.round(ijk).astype(int)
    position = np.abs(nib.affines.apply_affine(affine, index) - points).max()
    shape = values.shape[:3]
    inside = ((index >= 0) & (index < np.array(shape))).all(1)
    once = inside.all() and len({tuple(x) for x in index}) == np.prod(shape) == n
    if not inside.all():
        return position, False, np.inf
    got = vtk_to_numpy(image.GetPointData().GetScalars()).reshape(n, -1).astype(np.float64)
    i, j, k = (index[:, 0], index[:, 1], index[:, 2]) if lookup is None else lookup(index)
    ref = values[i, j, k].reshape(n, -1).astype(np.float64)
    scale = np.maximum(np.abs(ref), 1.0) if tolerance > 0 else 1.0
    err = (np.abs(got - ref) / scale).max()
    print("  %s: positions within %.2g mm of nibabel's, every voxel once: %s, largest value "
          "error %.3g" % (label, position, once, err))
    return position, once, err


def save(img, name):
    path = os.path.join(out, "TestNIfTIVolumeNibabel-" + name)
    nib.save(img, path)
    return path


# Affines that rotate and flip, given every way a file can give them.
volume = rng.random((7, 6, 5)).astype(np.float32)
flipped = make_affine(35, [1, -2, 0.5], [1.5, 2.0, 2.5], [40, -60, 25], True)
plain = make_affine(-50, [0.3, 1, 1], [1.0, 1.2, 3.0], [-5, 7, 11], False)
cases = []
img = nib.Nifti1Image(volume, flipped)
cases.append(("sform and qform, rotation and flip", save(img, "both.nii"), flipped))
img = nib.Nifti1Image(volume, None)
img.set_qform(flipped, code=1)
img.set_sform(None, code=0)
check(img.get_qform(coded=True)[1] == 1 and img.header["pixdim"][0] == -1,
      "nibabel stores the flipped qform with qfac -1")
cases.append(("qform only, qfac -1", save(img, "qform.nii.gz"), flipped))
img = nib.Nifti1Image(volume, None)
img.set_sform(plain, code=2)
img.set_qform(None, code=0)
cases.append(("sform only, rotation without flip", save(img, "sform.nii"), plain))
cases.append(("NIfTI-2", save(nib.Nifti2Image(volume, flipped), "nifti2.nii"), flipped))
big = nib.Nifti1Image(volume, plain, header=nib.Nifti1Header(endianness=">"))
cases.append(("big-endian", save(big, "big.nii"), plain))
cases.append((".hdr/.img pair", save(nib.Nifti1Pair(volume, flipped), "pair.img"), flipped))
for label, path, affine in cases:
    reader, image, errors = read(path)
    position, once, err = compare(image, affine, volume, label)
    check(not errors.all_messages and position < 1e-4 and once and err == 0.0,
          "float32 volume, %s: nibabel's voxel at every point, value exact" % label)
    check(image.GetPointData().GetScalars().GetDataType() == 10,  # VTK_FLOAT
          "float32 volume, %s: float output" % label)

# Negative controls: the checks fail when the placement or the lookup is wrong.
reader, image, errors = read(cases[0][1], AffineSource=3)  # pixdim: no rotation
position, once, err = compare(image, flipped, volume, "negative control: pixdim affine")
check(position > 1.0 or not once, "negative control: a rotated file placed by pixdim fails")
reader, image, errors = read(cases[0][1])
position, once, err = compare(image, flipped, volume, "negative control: transposed lookup",
                              lookup=lambda index: (index[:, 0], index[:, 1], 4 - index[:, 2]))
check(err > 0.01, "negative control: values looked up at mirrored slices fail")

# Integer label volumes stay integers; scaling applied (float / double).
labels = rng.integers(0, 40, (6, 5, 4)).astype(np.int16)
path = save(nib.Nifti1Image(labels, flipped), "labels.nii.gz")
reader, image, errors = read(path)
scalars = image.GetPointData().GetScalars()
position, once, err = compare(image, flipped, np.asarray(nib.load(path).dataobj), "int16 labels")
check(scalars.GetDataType() == 4 and once and err == 0.0,  # VTK_SHORT
      "int16 labels without scaling: int16 output, nibabel's values exactly")
check(scalars.GetName() == "TestNIfTIVolumeNibabel-labels", "the array is named after the file")
for dtype, slope, inter, vtk_type, tolerance, label in (
        (np.int16, 2.5, -3.0, 10, 1e-7, "int16 scaled: float"),
        (np.int32, 0.001, 7.0, 11, 1e-15, "int32 scaled: double"),
        (np.uint8, 1.0, 0.0, 3, 0.0, "uint8 with slope 1, intercept 0: unscaled")):
    raw = rng.integers(0, 200, (4, 5, 3)).astype(dtype)
    img = nib.Nifti1Image(raw, plain)
    img.header.set_slope_inter(slope, inter)
    path = save(img, "scaled-%s.nii" % np.dtype(dtype).name)
    reader, image, errors = read(path)
    position, once, err = compare(image, plain, nib.load(path).get_fdata(), label, tolerance)
    check(image.GetPointData().GetScalars().GetDataType() == vtk_type and once and
          err <= tolerance, label + ", nibabel's get_fdata() values")

# 4D and 5D: components or volumes.
v1 = rng.standard_normal((5, 4, 3, 3)).astype(np.float32)
path = save(nib.Nifti1Image(v1, plain), "v1.nii.gz")
reader, image, errors = read(path)
position, once, err = compare(image, plain, v1, "X x Y x Z x 3")
check(image.GetPointData().GetScalars().GetNumberOfComponents() == 3 and once and err == 0.0,
      "a 4th dimension of 3: 3 components, nibabel's values")
series = rng.random((5, 4, 3, 7)).astype(np.float32)
path = save(nib.Nifti1Image(series, flipped), "series.nii")
reader, image, errors = read(path, VolumeIndex=4)
position, once, err = compare(image, flipped, series[..., 4], "X x Y x Z x 7, volume 4")
check(reader.GetVolumeRange() == (0, 6) and once and err == 0.0,
      "7 volumes: VolumeIndex 4 is nibabel's volume 4, VolumeRange 0..6")
reader, image, errors = read(path, FourthDimension=1)
position, once, err = compare(image, flipped, series, "X x Y x Z x 7 as components")
check(image.GetPointData().GetScalars().GetNumberOfComponents() == 7 and err == 0.0,
      "7 volumes as components on request")
reader, image, errors = read(path, VolumeIndex=7)
check(image.GetNumberOfPoints() == 0 and "VolumeIndex 7" in reader.GetLastErrorMessage(),
      "VolumeIndex beyond the volumes: a clear error, an empty output")
vector = rng.random((4, 4, 3, 1, 3)).astype(np.float32)
path = save(nib.Nifti1Image(vector, plain), "vector5d.nii")
reader, image, errors = read(path)
position, once, err = compare(image, plain, vector[:, :, :, 0, :], "X x Y x Z x 1 x 3")
check(image.GetPointData().GetScalars().GetNumberOfComponents() == 3 and err == 0.0,
      "a 5th dimension of 3: 3 components")
rgb = np.zeros((3, 4, 2), dtype=[("R", "u1"), ("G", "u1"), ("B", "u1")])
for c in "RGB":
    rgb[c] = rng.integers(0, 256, rgb.shape)
path = save(nib.Nifti1Image(rgb, plain), "rgb.nii")
reader, image, errors = read(path)
position, once, err = compare(image, plain, np.stack([rgb[c] for c in "RGB"], -1), "RGB24")
check(image.GetPointData().GetScalars().GetDataType() == 3 and err == 0.0,
      "RGB24: 3 unsigned char components")

# DIPY's real scans: an oblique flipped int16 brain, a sheared uint16 volume.
for name in ("aniso_vox.nii.gz", "S0_10slices.nii.gz"):
    path = os.path.join(os.path.dirname(get_fnames("small_64D")[0]), name)
    scan = nib.load(path)
    reader, image, errors = read(path)
    data = np.asarray(scan.dataobj)
    data = data.reshape(data.shape[:3] + (-1,))
    position, once, err = compare(image, scan.affine, data, "DIPY's " + name)
    check(position < 1e-4 and once and err == 0.0,
          "DIPY's %s (%s): nibabel's voxels and values" % (name, scan.get_data_dtype()))

# The tensor reader places the same grid at the same points.
tensors = rng.random((7, 6, 5, 1, 6)).astype(np.float32)
tensor_path = save(nib.Nifti1Image(tensors, flipped), "tensors.nii")
tensor_reader = splineviz.vtkNIfTITensorReader()
tensor_reader.SetFileName(tensor_path)
tensor_reader.Update()
reader, image, errors = read(cases[0][1])
t = tensor_reader.GetOutput()
same = t.GetNumberOfPoints() == image.GetNumberOfPoints() and max(
    np.abs(np.array(t.GetPoint(i)) - np.array(image.GetPoint(i))).max()
    for i in range(t.GetNumberOfPoints())) == 0.0
check(same and tensor_reader.GetAffine() == reader.GetAffine(),
      "the tensor reader and the volume reader put the same grid at the same points")

# A sub-extent: the same values at the same points.
reader = splineviz.vtkNIfTIVolumeReader()
reader.SetFileName(cases[1][1])
reader.UpdateExtent((1, 5, 2, 4, 1, 3))
part = reader.GetOutput()
position, once, err = compare(part, flipped, volume, "sub-extent")
check(part.GetNumberOfPoints() == 5 * 3 * 3 and position < 1e-4 and err == 0.0,
      "a sub-extent: nibabel's values at its points")

checker.finish()
print("vtkNIfTIVolumeReader agrees with nibabel")
