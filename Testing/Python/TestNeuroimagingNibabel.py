# SPDX-License-Identifier: BSD-3-Clause
"""The neuroimaging readers and writer against an independent implementation,
nibabel (and DIPY for the tensors), on real data shipped by python3-dipy.

Tractograms: DIPY's cb_2 streamlines (116 real fibres) with per-point scalars
and per-streamline properties, written by nibabel as .tck and as .trk with a
voxel-to-RAS affine that rotates and flips (once with a voxel order that
agrees with it, once with one that does not, so nibabel reorients); a
big-endian .tck; a TrackVis version 1 file without scalars (built byte by
byte) read by nibabel; a .tck with an empty streamline. vtkTractogramReader
must give nibabel's points (float32: exactly for .tck, to 1e-4 mm after the
.trk voxel-mm map) and its scalars and properties exactly; files written by
vtkTractogramWriter must read back in nibabel as the input.

Tensors: DIPY fits its real small_101D scan (its affine is oblique, with a
flip); nibabel saves the tensors as 5D NIfTI (lower triangle, the NIfTI
standard) and 4D in FSL's documented order Dxx Dxy Dxz Dyy Dyz Dzz, also with
an affine that rotates by 30 degrees and flips, and with only a qform or
only an sform. vtkNIfTITensorReader must place every voxel where nibabel's
affine does and give R T R^T (R the rotation of the affine, T as nibabel reads
it) to 1e-6 relative; 5D and 4D files give identical tensors; negative
controls (FSL order read as NIfTI order, tensors left unrotated) must fail;
NIfTI-2, big-endian and .hdr/.img copies read identically; DIPY's FA as a
companion volume is copied exactly; 5 components are refused.
"""
import os
import struct
import sys
import warnings

import numpy as np

try:
    import nibabel as nib
    from nibabel.streamlines import Field, Tractogram
    from dipy.core.gradients import gradient_table
    from dipy.data import get_fnames
    from dipy.io.gradients import read_bvals_bvecs
    from dipy.reconst.dti import TensorModel, lower_triangular
except ImportError as error:
    print("nibabel or DIPY not available (python3-nibabel, python3-dipy), skipped:", error)
    sys.exit(125)

from vtkmodules.util.numpy_support import vtk_to_numpy

import splineviz

out = os.environ.get("SPLINEVIZ_TEST_OUTPUT", ".")
os.makedirs(out, exist_ok=True)
from splineviz_testing import Checker, Observed  # noqa: E402

checker = Checker()


check = checker.check


def read_tractogram(path, *tsf, keep_empty=False):
    reader = splineviz.vtkTractogramReader()
    errors = Observed(reader)
    reader.SetFileName(path)
    for t in tsf:
        reader.AddScalarFileName(t)
    reader.SetKeepEmptyStreamlines(keep_empty)
    reader.Update()
    return reader, reader.GetOutput(), errors


def lines_of(polydata):
    """The polylines of a vtkPolyData as a list of (n, 3) arrays, and their point ids."""
    offsets = vtk_to_numpy(polydata.GetLines().GetOffsetsArray())
    conn = vtk_to_numpy(polydata.GetLines().GetConnectivityArray())
    pts = vtk_to_numpy(polydata.GetPoints().GetData())
    ids = [conn[a:b] for a, b in zip(offsets[:-1], offsets[1:])]
    return [pts[i] for i in ids], ids


def max_difference(a, b):
    if len(a) != len(b) or any(len(x) != len(y) for x, y in zip(a, b)):
        return np.inf
    return max((np.abs(np.asarray(x, float) - np.asarray(y, float)).max() for x, y in zip(a, b)
                if len(x)), default=0.0)


# ---------------------------------------------------------------------------
# Tractograms: DIPY's cb_2 streamlines.
cb = np.load(os.path.join(os.path.dirname(get_fnames("small_64D")[0]), "cb_2.npz"))
ends = cb["offsets"]
starts = np.r_[0, ends[:-1]]
streamlines = [cb["points"][s:e].astype(np.float32) for s, e in zip(starts, ends)]
print("cb_2: %d streamlines, %d points" % (len(streamlines), sum(len(s) for s in streamlines)))
rng = np.random.default_rng(5)
per_point = {
    "fa": [rng.random((len(s), 1), dtype=np.float32) for s in streamlines],
    "colors": [rng.random((len(s), 3), dtype=np.float32) for s in streamlines],
}
per_line = {
    "length": np.array([[len(s)] for s in streamlines], np.float32),
    "bundle": rng.random((len(streamlines), 2), dtype=np.float32),
}
tractogram = Tractogram(streamlines, data_per_point=per_point, data_per_streamline=per_line,
                        affine_to_rasmm=np.eye(4))

# .tck by nibabel (points only: nibabel's .tck has no scalars)
tck = os.path.join(out, "TestNeuroimagingNibabel-cb2.tck")
nib.streamlines.save(Tractogram(streamlines, affine_to_rasmm=np.eye(4)), tck)
reader, polydata, errors = read_tractogram(tck)
got, _ = lines_of(polydata)
ref = list(nib.streamlines.load(tck).streamlines)
check(max_difference(got, ref) == 0.0, ".tck written by nibabel: points equal nibabel's exactly")

# .trk by nibabel with a rotating, flipping affine (voxel order consistent or not)
c, s = np.cos(np.radians(20)), np.sin(np.radians(20))
rotation = np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]]) @ np.diag([-2.0, 2.0, 2.5])
vox_to_ras = np.eye(4)
vox_to_ras[:3, :3] = rotation
vox_to_ras[:3, 3] = [90, -126, -72]
for order in ("LAS", "RAS"):
    trk = os.path.join(out, "TestNeuroimagingNibabel-cb2-%s.trk" % order)
    header = {Field.VOXEL_TO_RASMM: vox_to_ras, Field.VOXEL_SIZES: np.array([2.0, 2.0, 2.5]),
              Field.DIMENSIONS: np.array([91, 109, 91]), Field.VOXEL_ORDER: order}
    nib.streamlines.save(tractogram, trk, header=header)
    loaded = nib.streamlines.load(trk)
    reader, polydata, errors = read_tractogram(trk)
    got, ids = lines_of(polydata)
    err = max_difference(got, list(loaded.streamlines))
    print("  .trk (voxel order %s): largest point difference to nibabel %.3g mm" % (order, err))
    check(err < 1e-4, ".trk by nibabel (voxel order %s): points equal nibabel's" % order)
    check(max_difference(got, streamlines) < 1e-4,
          ".trk (voxel order %s): points equal the input" % order)
    for name, values in per_point.items():
        array = vtk_to_numpy(polydata.GetPointData().GetArray(name)).reshape(-1, values[0].shape[1])
        check(max_difference([array[i] for i in ids],
                             list(loaded.tractogram.data_per_point[name])) == 0.0,
              ".trk (voxel order %s): point array %s equals nibabel's" % (order, name))
    for name, values in per_line.items():
        array = vtk_to_numpy(polydata.GetCellData().GetArray(name)).reshape(len(streamlines), -1)
        check(np.array_equal(array, loaded.tractogram.data_per_streamline[name]),
              ".trk (voxel order %s): cell array %s equals nibabel's" % (order, name))

# our writer -> nibabel: .trk with scalars and properties (header geometry kept), .tck
writer = splineviz.vtkTractogramWriter()
writer_errors = Observed(writer)
writer.SetInputData(polydata)  # the last .trk read
for name in per_point:
    writer.AddPointArrayName(name)
for name in per_line:
    writer.AddCellArrayName(name)
ours_trk = os.path.join(out, "TestNeuroimagingNibabel-ours.trk")
writer.SetFileName(ours_trk)
writer.Write()
check(writer.GetErrorCode() == 0 and not writer_errors.all_messages, "our .trk written")
loaded = nib.streamlines.load(ours_trk)
err = max_difference(list(loaded.streamlines), streamlines)
print("  our .trk read by nibabel: largest point difference %.3g mm" % err)
check(err < 1e-4, "our .trk read by nibabel: the input's points")
for name in per_point:
    check(max_difference(list(loaded.tractogram.data_per_point[name]), per_point[name]) == 0.0,
          "our .trk read by nibabel: point array " + name)
for name in per_line:
    check(np.array_equal(loaded.tractogram.data_per_streamline[name], per_line[name]),
          "our .trk read by nibabel: cell array " + name)
check(np.allclose(loaded.header[Field.VOXEL_TO_RASMM], vox_to_ras, atol=1e-6),
      "our .trk keeps the vox_to_ras it was read with")
ours_tck = os.path.join(out, "TestNeuroimagingNibabel-ours.tck")
writer.RemoveAllPointArrayNames()
writer.AddPointArrayName("fa")
writer.SetFileName(ours_tck)
writer.Write()
check(writer.GetErrorCode() == 0, "our .tck written")
got_tck = list(nib.streamlines.load(ours_tck).streamlines)
check(max_difference(got_tck, got) == 0.0, "our .tck read by nibabel: the input's points exactly")
# the .tsf, parsed here independently: header, then one float32 per point, NaN per line, inf
tsf = splineviz.vtkTractogramWriter.ScalarFileName(ours_tck, "fa")
raw = open(tsf, "rb").read()
head = raw[:raw.index(b"\nEND\n") + 5].decode()
offset = int([l for l in head.splitlines() if l.startswith("file:")][0].split()[2])
values = np.frombuffer(raw[offset:], "<f4")
expected = np.concatenate([np.r_[v[:, 0], np.nan] for v in per_point["fa"]] + [[np.inf]])
check(head.startswith("mrtrix track scalars\n") and np.array_equal(values, expected, equal_nan=True),
      "our .tsf: one value per point, NaN after each streamline, inf at the end")
check([l for l in head.splitlines() if l.startswith("timestamp")] ==
      [l for l in open(ours_tck, "rb").read().split(b"\nEND\n")[0].decode().splitlines()
       if l.startswith("timestamp")], "our .tsf has the .tck's timestamp")
reader, back, errors = read_tractogram(ours_tck, tsf)
fa_back = vtk_to_numpy(back.GetPointData().GetArray("fa"))
check(np.array_equal(fa_back, np.concatenate(per_point["fa"])[:, 0]), "our .tck + .tsf read back")

def write_tck(path, lines, datatype="Float32LE"):
    """A .tck written here with numpy: the points, NaNs after each line, infs at the end."""
    data = np.concatenate([np.r_[s, [[np.nan] * 3]] for s in lines] + [[[np.inf] * 3]])
    text = "mrtrix tracks\ncount: %d\ndatatype: %s\nfile: . 80\nEND\n" % (len(lines), datatype)
    text = text + " " * (80 - len(text))  # the data start at byte 80
    open(path, "wb").write(text.encode() + data.astype(">f4" if datatype.endswith("BE") else "<f4").tobytes())


# big-endian .tck (nibabel reads it too)
big = os.path.join(out, "TestNeuroimagingNibabel-be.tck")
write_tck(big, streamlines[:20], "Float32BE")
reader, polydata, errors = read_tractogram(big)
got, _ = lines_of(polydata)
check(max_difference(got, list(nib.streamlines.load(big).streamlines)) == 0.0,
      "big-endian .tck: nibabel's points")

# an empty streamline: dropped as by nibabel, kept on request
empty = os.path.join(out, "TestNeuroimagingNibabel-empty.tck")
with_empty = streamlines[:3] + [np.zeros((0, 3), np.float32)] + streamlines[3:6]
write_tck(empty, with_empty)  # (nibabel's writer drops empty streamlines itself)
reader, polydata, errors = read_tractogram(empty)
got, _ = lines_of(polydata)
check(max_difference(got, list(nib.streamlines.load(empty).streamlines)) == 0.0 and len(got) == 6,
      ".tck with an empty streamline: dropped, like nibabel")
reader, polydata, errors = read_tractogram(empty, keep_empty=True)
got, _ = lines_of(polydata)
check(len(got) == 7 and len(got[3]) == 0 and reader.GetNumberOfStreamlinesInFile() == 7,
      ".tck with an empty streamline: kept as an empty polyline")

# TrackVis version 1 without scalars, byte by byte (empty voxel order: nibabel assumes LPS)
v1 = os.path.join(out, "TestNeuroimagingNibabel-v1.trk")
hdr = bytearray(1000)
hdr[0:6] = b"TRACK\0"
struct.pack_into("<3h", hdr, 6, 40, 50, 30)
struct.pack_into("<3f", hdr, 12, 2.0, 2.0, 3.0)
struct.pack_into("<i", hdr, 988, 20)
struct.pack_into("<i", hdr, 992, 1)
struct.pack_into("<i", hdr, 996, 1000)
records = b""
for line in streamlines[:20]:
    voxmm = np.abs(line) + 1.0  # inside the grid
    records += struct.pack("<i", len(line)) + voxmm.astype("<f4").tobytes()
open(v1, "wb").write(bytes(hdr) + records)
with warnings.catch_warnings():
    warnings.simplefilter("ignore")
    nib_v1 = list(nib.streamlines.load(v1).streamlines)
reader, polydata, errors = read_tractogram(v1)
got, _ = lines_of(polydata)
err = max_difference(got, nib_v1)
print("  TrackVis v1: largest point difference to nibabel %.3g mm" % err)
check(err < 1e-4 and polydata.GetPointData().GetNumberOfArrays() == 0,
      "TrackVis v1 without scalars: nibabel's points")

# ---------------------------------------------------------------------------
# Tensors: DIPY fits its real small_101D scan.
dwi, bval, bvec = get_fnames("small_101D")
scan = nib.load(dwi)
bvals, bvecs = read_bvals_bvecs(bval, bvec)
fit = TensorModel(gradient_table(bvals, bvecs)).fit(np.asarray(scan.dataobj, dtype=np.float64))
q = fit.quadratic_form.astype(np.float32)  # (x, y, z, 3, 3), in the voxel frame
print("small_101D: %s voxels, affine\n%s" % (q.shape[:3], np.round(scan.affine, 4)))


def save_lower(path, affine, q, qform=True, sform=True):
    img = nib.Nifti1Image(lower_triangular(q)[:, :, :, None, :], affine)
    img.set_qform(affine if qform else None, code=1 if qform else 0)
    img.set_sform(affine if sform else None, code=1 if sform else 0)
    nib.save(img, path)
    check(np.allclose(nib.load(path).affine, affine, atol=1e-4), "nibabel wrote " + path)


def save_fsl(path, affine, q):
    order = [(0, 0), (0, 1), (0, 2), (1, 1), (1, 2), (2, 2)]  # FSL: Dxx Dxy Dxz Dyy Dyz Dzz
    nib.save(nib.Nifti1Image(np.stack([q[..., i, j] for i, j in order], -1), affine), path)


def read_tensors(path, layout=None, frame=None, companions=()):
    reader = splineviz.vtkNIfTITensorReader()
    errors = Observed(reader)
    reader.SetFileName(path)
    if layout is not None:
        reader.SetTensorLayout(layout)
    if frame is not None:
        reader.SetTensorFrame(frame)
    for c in companions:
        reader.AddCompanionFileName(c)
    reader.Update()
    return reader, reader.GetOutput(), errors


def compare(image, path, label):
    """Positions against nibabel's affine, tensors against R T R^T (T as nibabel reads the
    file, R the orthogonal polar factor of the affine). Returns the relative tensor error."""
    img = nib.load(path)
    affine = img.affine
    data = np.asarray(img.dataobj, dtype=np.float64).reshape(img.shape[:3] + (6,))
    if len(img.shape) == 5:
        t = np.zeros(img.shape[:3] + (3, 3))
        for k, (i, j) in enumerate([(0, 0), (1, 0), (1, 1), (2, 0), (2, 1), (2, 2)]):
            t[..., i, j] = t[..., j, i] = data[..., k]
    else:
        t = np.zeros(img.shape[:3] + (3, 3))
        for k, (i, j) in enumerate([(0, 0), (0, 1), (0, 2), (1, 1), (1, 2), (2, 2)]):
            t[..., i, j] = t[..., j, i] = data[..., k]
    u, _, vt = np.linalg.svd(affine[:3, :3])
    r = u @ vt
    world = np.einsum("ij,xyzjk,lk->xyzil", r, t, r)
    points = np.array([image.GetPoint(i) for i in range(image.GetNumberOfPoints())])
    ijk = nib.affines.apply_affine(np.linalg.inv(affine), points)
    index = np.round(ijk).astype(int)
    position = np.abs(ijk - index).max() * np.abs(affine[:3, :3]).max()
    covered = len({tuple(x) for x in index}) == np.prod(img.shape[:3])
    w = world[index[:, 0], index[:, 1], index[:, 2]]
    ref = np.stack([w[:, 0, 0], w[:, 1, 1], w[:, 2, 2], w[:, 0, 1], w[:, 1, 2], w[:, 0, 2]], 1)
    got = vtk_to_numpy(image.GetPointData().GetArray("Tensors")).astype(np.float64)
    scale = np.abs(ref).max(1)
    ok = scale > 0
    err = (np.abs(got - ref).max(1)[ok] / scale[ok]).max()
    zero = np.abs(got[~ok]).max() if (~ok).any() else 0.0
    print("  %s: voxel positions within %.2g mm of nibabel's, every voxel once: %s, "
          "largest relative tensor error %.3g" % (label, position, covered, err))
    return position, covered, err, zero


nii5 = os.path.join(out, "TestNeuroimagingNibabel-dti5d.nii.gz")
nii4 = os.path.join(out, "TestNeuroimagingNibabel-dti4d-fsl.nii.gz")
save_lower(nii5, scan.affine, q)
save_fsl(nii4, scan.affine, q)
reader, dti5, errors = read_tensors(nii5)
position, covered, err, zero = compare(dti5, nii5, "5D NIfTI, the scan's affine")
check(position < 1e-4 and covered and err < 1e-6 and zero == 0.0,
      "DIPY tensors, 5D (NIfTI order): placed and rotated as nibabel's affine says")
reader, dti4, errors = read_tensors(nii4)
check(np.array_equal(vtk_to_numpy(dti4.GetPointData().GetArray("Tensors")),
                     vtk_to_numpy(dti5.GetPointData().GetArray("Tensors"))),
      "the same tensors in FSL's order (4D, automatic layout) read identically")
reader, dti4x, errors = read_tensors(nii4, layout=3)
check(np.array_equal(vtk_to_numpy(dti4x.GetPointData().GetArray("Tensors")),
                     vtk_to_numpy(dti5.GetPointData().GetArray("Tensors"))),
      "FSL order with the FSL layout chosen: identical")
reader, wrong, errors = read_tensors(nii4, layout=2)
check(compare(wrong, nii4, "negative control: FSL file read in NIfTI order")[2] > 1e-2,
      "negative control: the FSL file read in NIfTI order differs")
reader, wrong, errors = read_tensors(nii5, frame=2)
check(compare(wrong, nii5, "negative control: tensors not rotated")[2] > 1e-2,
      "negative control: tensors taken as world-frame (not rotated) differ")

# the same tensors as NIfTI-2, big-endian NIfTI-1 and a .hdr/.img pair (nibabel): identical
reference = vtk_to_numpy(dti5.GetPointData().GetArray("Tensors"))
for label, img, name in (
        ("NIfTI-2", nib.Nifti2Image(lower_triangular(q)[:, :, :, None, :], scan.affine), "dti5d-nifti2.nii"),
        ("big-endian", nib.Nifti1Image(lower_triangular(q)[:, :, :, None, :], scan.affine,
                                       header=nib.Nifti1Header(endianness=">")), "dti5d-big.nii"),
        (".hdr/.img pair", nib.Nifti1Pair(lower_triangular(q)[:, :, :, None, :], scan.affine),
         "dti5d-pair.img")):
    path = os.path.join(out, "TestNeuroimagingNibabel-" + name)
    nib.save(img, path)
    reader, image, errors = read_tensors(path)
    got = image.GetPointData().GetArray("Tensors")
    check(got is not None and np.array_equal(vtk_to_numpy(got), reference),
          "DIPY tensors as %s: the same tensors as from the .nii.gz" % label)

# an affine with a 30 degree rotation and a flip; qform only; sform only
axis = np.array([1.0, 1.0, 0.3]) / np.linalg.norm([1.0, 1.0, 0.3])
k = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
rot = np.eye(3) + np.sin(np.radians(30)) * k + (1 - np.cos(np.radians(30))) * k @ k
oblique = np.eye(4)
oblique[:3, :3] = rot @ np.diag([-2.0, 2.5, 3.0])
oblique[:3, 3] = [12.0, -40.0, 25.0]
for label, kwargs in (("rotation and flip, qform and sform", {}),
                      ("rotation and flip, qform only", {"sform": False}),
                      ("rotation and flip, sform only", {"qform": False})):
    path = os.path.join(out, "TestNeuroimagingNibabel-%s.nii.gz"
                        % label.split(", ")[1].replace(" ", "-"))
    save_lower(path, oblique, q, **kwargs)
    reader, image, errors = read_tensors(path)
    position, covered, err, zero = compare(image, path, label)
    check(position < 1e-4 and covered and err < 1e-6, "DIPY tensors, " + label)

# DIPY's FA as a companion volume: copied exactly; 5 components: refused
fa_path = os.path.join(out, "TestNeuroimagingNibabel-FA.nii.gz")
fa = np.nan_to_num(fit.fa).astype(np.float32)
nib.save(nib.Nifti1Image(fa, scan.affine), fa_path)
reader, image, errors = read_tensors(nii5, companions=[fa_path])
got_fa = vtk_to_numpy(image.GetPointData().GetArray("TestNeuroimagingNibabel-FA"))
points = np.array([image.GetPoint(i) for i in range(image.GetNumberOfPoints())])
index = np.round(nib.affines.apply_affine(np.linalg.inv(scan.affine), points)).astype(int)
check(np.array_equal(got_fa, fa[index[:, 0], index[:, 1], index[:, 2]]),
      "DIPY's FA as a companion volume: copied voxel by voxel")
five = os.path.join(out, "TestNeuroimagingNibabel-five.nii.gz")
nib.save(nib.Nifti1Image(rng.random((4, 5, 6, 5)).astype(np.float32), scan.affine), five)
reader, image, errors = read_tensors(five)
check(image.GetNumberOfPoints() == 0 and "6 (symmetric) or 9" in reader.GetLastErrorMessage(),
      "5 components: a clear error, an empty output")
print("error message:", reader.GetLastErrorMessage())

checker.finish()
print("neuroimaging IO agrees with nibabel")
