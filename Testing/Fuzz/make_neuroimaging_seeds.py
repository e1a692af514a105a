# SPDX-License-Identifier: BSD-3-Clause
"""Writes the seeds and the hand-made regression inputs of the neuroimaging
fuzz targets (FuzzNIfTIReader, FuzzTractogramReader): small files written by
nibabel (the independent implementation) from DIPY's real data (its
small_64D scan, fitted by DIPY's TensorModel, its small_25 scan as shipped,
its cb_2 fibres), a few built byte by byte, each prefixed with the targets'
mode byte (see the comments at the top of the two targets). Deterministic:
running it again rewrites the same bytes.

    /usr/bin/python3 Testing/Fuzz/make_neuroimaging_seeds.py
"""
import gzip
import io
import os
import struct
import tempfile

import nibabel as nib
import numpy as np
from dipy.core.gradients import gradient_table
from dipy.data import get_fnames
from dipy.io.gradients import read_bvals_bvecs
from dipy.reconst.dti import TensorModel, lower_triangular
from nibabel.streamlines import Field, Tractogram

here = os.path.dirname(os.path.abspath(__file__))
tmp = tempfile.mkdtemp()
rng = np.random.default_rng(28)

# NIfTI target modes
NII, NII_GZ, RAW_GZ, PAIR = 0, 1, 2, 3
TENSOR, SUB_EXTENT, OPTION6, OPTION7 = 4, 0x20, 0x40, 0x80
# tractogram target modes
TCK, TRK, TCK_TSF, DETECT = 0, 1, 2, 3
FORCED, KEEP_EMPTY, PIECE = 4, 8, 16


def put(folder, name, mode, payload):
    os.makedirs(folder, exist_ok=True)
    data = bytes([mode]) + payload
    with open(os.path.join(folder, name), "wb") as f:
        f.write(data)
    print("%6d bytes  %s" % (len(data), os.path.relpath(os.path.join(folder, name), here)))


def nifti_bytes(img, name="x.nii"):
    path = os.path.join(tmp, name)
    nib.save(img, path)
    return open(path, "rb").read()


def rotation(angle_deg, axis):
    axis = np.asarray(axis, float) / np.linalg.norm(axis)
    k = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    a = np.radians(angle_deg)
    return np.eye(3) + np.sin(a) * k + (1 - np.cos(a)) * k @ k


def affine(angle, axis, zooms, offset, flip=False):
    a = np.eye(4)
    a[:3, :3] = rotation(angle, axis) @ np.diag(zooms) @ np.diag([-1 if flip else 1, 1, 1])
    a[:3, 3] = offset
    return a


corpus = os.path.join(here, "corpus", "nifti")
regressions = os.path.join(here, "regressions", "FuzzNIfTIReader")

# DIPY's small_64D scan fitted by DIPY: a 3 x 3 x 2 corner of the tensors.
dwi, bval, bvec = get_fnames("small_64D")
scan = nib.load(dwi)
bvals, bvecs = read_bvals_bvecs(bval, bvec)
data = np.asarray(scan.dataobj, dtype=np.float64)[3:6, 3:6, 4:6]
fit = TensorModel(gradient_table(bvals, bvecs)).fit(data)
q = fit.quadratic_form.astype(np.float32)
lower = lower_triangular(q)[:, :, :, None, :]
fsl = np.stack([q[..., i, j] for i, j in [(0, 0), (0, 1), (0, 2), (1, 1), (1, 2), (2, 2)]], -1)
tensor_nii = nifti_bytes(nib.Nifti1Image(lower, scan.affine))
put(corpus, "tensor-nii-dipy-5d", TENSOR | NII, tensor_nii)
put(corpus, "tensor-nii-dipy-5d-subextent", TENSOR | NII | SUB_EXTENT, tensor_nii)
put(corpus, "tensor-nii-dipy-5d-companions", TENSOR | NII | OPTION7, tensor_nii)
put(corpus, "tensor-niigz-dipy-4d-fsl", TENSOR | NII_GZ | OPTION6,
    nifti_bytes(nib.Nifti1Image(fsl, affine(30, [1, 1, 0.3], [2, 2.5, 3], [12, -40, 25], True))))
qform_only = nib.Nifti1Image(lower, None)
qform_only.set_qform(scan.affine, code=1)
qform_only.set_sform(None, code=0)
put(corpus, "tensor-rawgz-dipy-5d-qform", TENSOR | RAW_GZ | 0x10,
    gzip.compress(nifti_bytes(qform_only), mtime=0))
full = np.concatenate([q.reshape(q.shape[:3] + (1, 9))], -1).astype(np.float64)
put(corpus, "tensor-nii2-9-float64", TENSOR | NII,
    nifti_bytes(nib.Nifti2Image(full, affine(-20, [0, 1, 1], [1.5, 1.5, 2], [0, 5, -3]))))

# Scalar and vector volumes.
vol = rng.random((4, 3, 3)).astype(np.float32)
put(corpus, "volume-nii-float32-rotated-flipped-sform", NII,
    nifti_bytes(nib.Nifti1Image(vol, affine(40, [0.2, 1, 0.5], [1, 2, 1.5], [3, -7, 11], True))))
labels = rng.integers(0, 5, (4, 4, 3)).astype(np.int16)
img = nib.Nifti1Image(labels, None)
img.set_qform(affine(15, [0, 0, 1], [1, 1, 2], [1, 2, 3], True), code=1)
img.set_sform(None, code=0)
put(corpus, "volume-niigz-int16-labels-qform-qfac", NII_GZ, nifti_bytes(img))
put(corpus, "volume-rawgz-dipy-small25", RAW_GZ, open(get_fnames("small_25")[0], "rb").read())
pair = nib.Nifti1Pair(rng.integers(0, 255, (3, 3, 2)).astype(np.uint8), affine(0, [0, 0, 1], [2, 2, 2], [0, 0, 0]))
nib.save(pair, os.path.join(tmp, "pair.img"))
pair_bytes = open(os.path.join(tmp, "pair.hdr"), "rb").read() + open(os.path.join(tmp, "pair.img"), "rb").read()
put(corpus, "volume-pair-uint8", PAIR, pair_bytes)
put(corpus, "volume-pair-uint8-opened-as-img", PAIR | OPTION7, pair_bytes)
big = nib.Nifti2Image(rng.random((3, 2, 2)), affine(10, [1, 0, 0], [1, 1, 1], [0, 0, 0]),
                      header=nib.Nifti2Header(endianness=">"))
put(corpus, "volume-nii2-bigendian-float64", NII, nifti_bytes(big))
four = nib.Nifti1Image(rng.integers(-100, 100, (3, 3, 2, 5)).astype(np.int16), np.eye(4))
four.header.set_slope_inter(2.0, -1.0)
put(corpus, "volume-nii-int16-4d-scaled-volume1", NII | OPTION7, nifti_bytes(four))
put(corpus, "volume-nii-int16-4d-scaled-components", NII | OPTION6, nifti_bytes(four))
rgb = np.zeros((2, 2, 2), dtype=[("R", "u1"), ("G", "u1"), ("B", "u1")])
rgb["R"], rgb["G"], rgb["B"] = 10, 200, 30
put(corpus, "volume-nii-rgb24", NII, nifti_bytes(nib.Nifti1Image(rgb, np.eye(4))))
put(corpus, "volume-nii-complex64-pixdim", NII | 0x18,
    nifti_bytes(nib.Nifti1Image((rng.random((2, 2, 2)) + 1j).astype(np.complex64), np.eye(4))))
members = nifti_bytes(nib.Nifti1Image(vol, np.eye(4)))
put(corpus, "volume-rawgz-two-gzip-members", RAW_GZ,
    gzip.compress(members[:400], mtime=0) + gzip.compress(members[400:], mtime=0))

# Regression inputs: the crash class of VTK 9.2's reader (an unknown datatype
# code: SIGSEGV in vtkNIFTIImageReader::RequestInformation; a 0 dimension:
# SIGSEGV in its RequestData; dim[5] = 0: SIGFPE), made from the
# nibabel-written tensor file, and hostile sizes.
def with_field(raw, offset, fmt, value):
    b = bytearray(raw)
    struct.pack_into(fmt, b, offset, value)
    return bytes(b)


for mode, label in ((TENSOR | NII, "tensor-nii"), (TENSOR | NII_GZ, "tensor-niigz"),
                    (NII, "volume-nii")):
    put(regressions, "vtk92-sigsegv-datatype-unknown-" + label, mode, with_field(tensor_nii, 70, "<h", -1))
put(regressions, "vtk92-sigsegv-datatype-unknown-tensor-rawgz", TENSOR | RAW_GZ,
    gzip.compress(with_field(tensor_nii, 70, "<h", -1), mtime=0))
put(regressions, "vtk92-sigsegv-dim3-zero", TENSOR | NII, with_field(tensor_nii, 46, "<h", 0))
put(regressions, "vtk92-sigfpe-dim5-zero", TENSOR | NII, with_field(tensor_nii, 50, "<h", 0))
huge = with_field(with_field(with_field(tensor_nii, 42, "<h", 32767), 44, "<h", 32767), 46, "<h", 32767)
put(regressions, "hostile-dims-32767-cubed-nii", NII, huge)
put(regressions, "hostile-dims-32767-cubed-niigz", TENSOR | NII_GZ, huge)
v2 = nifti_bytes(nib.Nifti2Image(vol, np.eye(4)))
put(regressions, "hostile-nifti2-dim1-2e40", NII, with_field(v2, 24, "<q", 1 << 40))
put(regressions, "hostile-nifti2-vox-offset-2e62", NII, with_field(v2, 168, "<q", 1 << 62))
put(regressions, "hostile-nifti2-dims-product-overflow", NII,
    with_field(with_field(with_field(v2, 48, "<q", 1 << 40), 56, "<q", 1 << 40), 16, "<q", 5))
put(regressions, "hostile-components-dim4-32767", NII | OPTION6,
    with_field(with_field(nifti_bytes(four), 48, "<h", 32767), 50, "<h", 3))
put(regressions, "hostile-vox-offset-nan", NII, with_field(tensor_nii, 108, "<f", float("nan")))
gz = gzip.compress(tensor_nii, mtime=0)
put(regressions, "gzip-truncated", TENSOR | RAW_GZ, gz[:-100])
put(regressions, "gzip-bad-checksum", TENSOR | RAW_GZ, gz[:-8] + bytes([gz[-8] ^ 0xff]) + gz[-7:])
put(regressions, "gzip-damaged-deflate-data", RAW_GZ, gz[:60] + bytes(b ^ 0x55 for b in gz[60:90]) + gz[90:])
put(regressions, "pair-magic-single-file", PAIR, with_field(pair_bytes, 344, "4s", b"n+1\0"))
put(regressions, "analyze-no-magic", NII, with_field(tensor_nii, 344, "4s", b"\0\0\0\0"))

# Tractograms: DIPY's cb_2 fibres, written by nibabel.
cb = np.load(os.path.join(os.path.dirname(get_fnames("small_64D")[0]), "cb_2.npz"))
ends = cb["offsets"]
starts = np.r_[0, ends[:-1]]
lines = [cb["points"][s:e].astype(np.float32)[:12] for s, e in zip(starts, ends)][:4]
tck_corpus = os.path.join(here, "corpus", "tck")
trk_corpus = os.path.join(here, "corpus", "trk")
tract_regressions = os.path.join(here, "regressions", "FuzzTractogramReader")


def save_bytes(tractogram, name, **kwargs):
    path = os.path.join(tmp, name)
    nib.streamlines.save(tractogram, path, **kwargs)
    return open(path, "rb").read()


tck = save_bytes(Tractogram(lines, affine_to_rasmm=np.eye(4)), "cb2.tck")
put(tck_corpus, "tck-nibabel-cb2", TCK, tck)
put(tck_corpus, "tck-nibabel-cb2-piece", TCK | PIECE, tck)
put(tck_corpus, "detect-tck-nibabel-cb2", DETECT, tck)


def mrtrix(magic, values, datatype="Float32LE", extra="", count="4"):
    head = "%s\n%scount: %s\ndatatype: %s\n" % (magic, extra, count, datatype)
    offset = len(head) + len("file: . 0000\nEND\n")
    head += "file: . %04d\nEND\n" % offset
    fmt = {"Float32LE": "<f4", "Float32BE": ">f4", "Float64LE": "<f8"}[datatype]
    return head.encode() + np.asarray(values).astype(fmt).tobytes()


def tck_values(streamlines):
    return np.concatenate([np.r_[s, [[np.nan] * 3]] for s in streamlines] + [[[np.inf] * 3]]).ravel()


put(tck_corpus, "tck-float32be", TCK, mrtrix("mrtrix tracks", tck_values(lines), "Float32BE"))
put(tck_corpus, "tck-float64le-forced", TCK | FORCED, mrtrix("mrtrix tracks", tck_values(lines), "Float64LE"))
with_empty = lines[:2] + [np.zeros((0, 3), np.float32)] + lines[2:]
put(tck_corpus, "tck-empty-streamline-kept", TCK | KEEP_EMPTY, mrtrix("mrtrix tracks", tck_values(with_empty)))
fa = [rng.random(len(s)).astype(np.float32) for s in lines]
tsf_values = np.concatenate([np.r_[v, np.nan] for v in fa] + [[np.inf]])
put(tck_corpus, "tck-tsf-fa", TCK_TSF,
    mrtrix("mrtrix tracks", tck_values(lines), extra="timestamp: 1\n") +
    mrtrix("mrtrix track scalars", tsf_values, extra="timestamp: 1\n"))

per_point = {"fa": [rng.random((len(s), 1), dtype=np.float32) for s in lines]}
per_line = {"length": np.array([[len(s)] for s in lines], np.float32)}
trk_header = {Field.VOXEL_TO_RASMM: affine(20, [0, 0, 1], [2, 2, 2.5], [90, -126, -72], True),
              Field.VOXEL_SIZES: np.array([2.0, 2.0, 2.5]), Field.DIMENSIONS: np.array([91, 109, 91]),
              Field.VOXEL_ORDER: "LAS"}
trk = save_bytes(Tractogram(lines, data_per_point=per_point, data_per_streamline=per_line,
                            affine_to_rasmm=np.eye(4)), "cb2.trk", header=trk_header)
put(trk_corpus, "trk-nibabel-cb2-scalars-properties", TRK, trk)
put(trk_corpus, "trk-nibabel-cb2-piece-forced", TRK | PIECE | FORCED, trk)
put(trk_corpus, "detect-trk-nibabel-cb2", DETECT, trk)


def trk_bytes(endian, version, count, streamlines):
    h = bytearray(1000)
    h[0:6] = b"TRACK\0"
    struct.pack_into(endian + "3h", h, 6, 40, 50, 30)
    struct.pack_into(endian + "3f", h, 12, 2.0, 2.0, 3.0)
    if version == 2:
        struct.pack_into(endian + "16f", h, 440, *np.diag([2.0, 2.0, 3.0, 1.0]).ravel())
        h[948:952] = b"RAS\0"
    struct.pack_into(endian + "3i", h, 988, count, version, 1000)
    body = b""
    for s in streamlines:
        body += struct.pack(endian + "i", len(s)) + (np.abs(s) + 1).astype(endian + "f4").tobytes()
    return bytes(h) + body


put(trk_corpus, "trk-v1-bytes", TRK, trk_bytes("<", 1, len(lines), lines))
put(trk_corpus, "trk-v2-bigendian-bytes", TRK, trk_bytes(">", 2, len(lines), lines))
put(trk_corpus, "trk-v2-count-unrecorded", TRK, trk_bytes("<", 2, 0, lines))

# Hostile sizes and damaged files for the tractogram reader.
put(tract_regressions, "trk-n-count-2e31", TRK, with_field(trk, 988, "<i", 2**31 - 1))
put(tract_regressions, "trk-first-point-count-2e31", TRK, with_field(trk, 1000, "<i", 2**31 - 1))
put(tract_regressions, "trk-n-scalars-32767", TRK, with_field(trk, 36, "<h", 32767))
put(tract_regressions, "trk-negative-point-count", TRK, with_field(trk, 1000, "<i", -5))
put(tract_regressions, "tck-offset-beyond-file", TCK, tck.replace(b"file: . ", b"file: . 9999999999", 1))
put(tract_regressions, "tck-count-huge", TCK, mrtrix("mrtrix tracks", tck_values(lines), count="99999999999"))
put(tract_regressions, "tck-truncated-in-triplet", TCK, tck[:-7])
put(tract_regressions, "tsf-does-not-match", TCK_TSF,
    mrtrix("mrtrix tracks", tck_values(lines)) + mrtrix("mrtrix track scalars", tsf_values[3:]))
