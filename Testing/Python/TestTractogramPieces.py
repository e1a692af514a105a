# SPDX-License-Identifier: BSD-3-Clause
"""vtkTractogramReader's piece requests and read-time subsets against nibabel.

Files written by nibabel (.tck, .trk with per-point scalars and per-streamline
properties) or byte by byte here (big-endian and float64 .tck, .tck with
empty streamlines, .tsf companions), with streamlines of 1 to 150 points so
that piece boundaries fall inside streamlines. Each file is read in 1, 2, 3
and 7 pieces; the pieces' streamlines, concatenated in piece order, must be
the file's as nibabel reads it: the same points and arrays exactly, in
order, each once. Each piece must read about 1/n of the data
(GetLastBytesRead). Tiny files (fewer streamlines than pieces) and files
without streamlines too. Negative controls: the comparison rejects a wrong
split (a piece read with another number of pieces, a shifted range).

Subsets: every k-th streamline is exactly nibabel's [::k] for any number of
pieces; a seeded random fraction is the same set for any number of pieces,
of a size within 4 standard deviations of the fraction, another seed
another set.

Progress rises to 1 in piece reads; an abort leaves an empty output.

Bad input: a damaged triplet or an end marker inside the data, a truncated
file, a .trk record count running past the end, a .tsf that does not match:
the pieces that meet the damage fail with a message and an empty output,
quickly; the others are unaffected.
"""
import os
import sys
import time

import numpy as np

try:
    import nibabel as nib
    from nibabel.streamlines import Tractogram
except ImportError as error:
    print("nibabel not available (python3-nibabel), skipped:", error)
    sys.exit(125)

from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkCommand

import splineviz
from splineviz_testing import output_dir

out = output_dir()
from splineviz_testing import Checker, Observed  # noqa: E402

checker = Checker()
PIECES = (1, 2, 3, 7)


check = checker.check


class Piece:
    """One piece read: its streamlines (list of (n, 3) arrays), point and cell arrays."""

    def __init__(self, path, piece, pieces, tsf=(), keep_empty=False, subset=None):
        reader = splineviz.vtkTractogramReader()
        self.errors = Observed(reader)
        reader.SetFileName(path)
        for t in tsf:
            reader.AddScalarFileName(t)
        reader.SetKeepEmptyStreamlines(keep_empty)
        if subset:
            mode, value, seed = subset
            if mode == "stride":
                reader.SetSubsetModeToStride()
                reader.SetSubsetStride(value)
            else:
                reader.SetSubsetModeToRandomFraction()
                reader.SetSubsetFraction(value)
                reader.SetSubsetSeed(seed)
        start = time.time()
        self.ok = reader.UpdatePiece(piece, pieces, 0)
        self.seconds = time.time() - start
        self.bytes = reader.GetLastBytesRead()
        self.in_file = reader.GetNumberOfStreamlinesInFile()
        self.message = reader.GetLastErrorMessage()
        polydata = reader.GetOutput()
        self.cells = polydata.GetNumberOfCells()
        self.lines, self.point_arrays, self.cell_arrays = [], {}, {}
        if polydata.GetNumberOfCells() == 0:
            return
        offsets = vtk_to_numpy(polydata.GetLines().GetOffsetsArray())
        conn = vtk_to_numpy(polydata.GetLines().GetConnectivityArray())
        pts = vtk_to_numpy(polydata.GetPoints().GetData())
        self.lines = [pts[conn[a:b]] for a, b in zip(offsets[:-1], offsets[1:])]
        pd, cd = polydata.GetPointData(), polydata.GetCellData()
        for i in range(pd.GetNumberOfArrays()):
            a = vtk_to_numpy(pd.GetArray(i))
            self.point_arrays[pd.GetArrayName(i)] = [a[conn[x:y]] for x, y in
                                                     zip(offsets[:-1], offsets[1:])]
        for i in range(cd.GetNumberOfArrays()):
            self.cell_arrays[cd.GetArrayName(i)] = list(vtk_to_numpy(cd.GetArray(i)))


def read_pieces(path, pieces, **kw):
    return [Piece(path, p, pieces, **kw) for p in range(pieces)]


def union(parts, what="lines", name=None):
    result = []
    for part in parts:
        result += getattr(part, what) if name is None else getattr(part, what).get(name, [])
    return result


def same(got, ref):
    """Exactly the same list of arrays: same number, same shapes, same values, same order."""
    return len(got) == len(ref) and all(
        np.shape(g) == np.shape(r) and np.array_equal(np.asarray(g, np.float64),
                                                      np.asarray(r, np.float64))
        for g, r in zip(got, ref))


def write_tck(path, lines, datatype="Float32LE", end=True):
    """A .tck written here with numpy: the points, NaNs after each line, infs at the end."""
    rows = [np.r_[np.asarray(s, np.float64).reshape(-1, 3), [[np.nan] * 3]] for s in lines]
    data = np.concatenate(rows + ([[[np.inf] * 3]] if end else [np.zeros((0, 3))]))
    text = "mrtrix tracks\ncount: %d\ndatatype: %s\nfile: . 96\nEND\n" % (len(lines), datatype)
    text = text + " " * (96 - len(text))  # the data start at byte 96
    dtype = ("<" if datatype.endswith("LE") else ">") + ("f8" if "64" in datatype else "f4")
    open(path, "wb").write(text.encode() + data.astype(dtype).tobytes())
    return 96


def write_tsf(path, values):
    """A .tsf: one value per point, NaN after each streamline, inf at the end."""
    data = np.concatenate([np.r_[v, np.nan] for v in values] + [[np.inf]]).astype("<f4")
    text = "mrtrix track scalars\ncount: %d\ndatatype: Float32LE\nfile: . 96\nEND\n" % len(values)
    open(path, "wb").write((text + " " * (96 - len(text))).encode() + data.tobytes())


rng = np.random.default_rng(26)


def random_streamlines(count, longest=150):
    lengths = rng.integers(1, longest, count)
    lengths[::17] = 1  # single points too
    return [(np.cumsum(rng.normal(0, 1, (n, 3)), axis=0) + 0.5 * i).astype(np.float32)
            for i, n in enumerate(lengths)]


def check_pieces(label, path, ref, data_bytes, longest_bytes, header_bytes=0, **kw):
    """The union of the pieces is `ref`, for every number of pieces; each reads about 1/n."""
    for n in PIECES:
        parts = read_pieces(path, n, **kw)
        ok = all(p.ok for p in parts) and not any(p.errors.all_messages for p in parts)
        check(ok and same(union(parts), ref["lines"]),
              "%s, %d piece(s): the pieces' streamlines are nibabel's, in order, each once "
              "(%d streamlines, per piece %s)" % (label, n, len(ref["lines"]),
                                                 [p.cells for p in parts]))
        for name, values in ref.get("point", {}).items():
            check(same(union(parts, "point_arrays", name), values),
                  "%s, %d piece(s): point array %s" % (label, n, name))
        for name, values in ref.get("cell", {}).items():
            check(same(union(parts, "cell_arrays", name), values),
                  "%s, %d piece(s): cell array %s" % (label, n, name))
        most = max(p.bytes for p in parts)
        total = sum(p.bytes for p in parts)
        # the share, plus the last streamline (found in growing blocks, then read) and probes
        bound = data_bytes / n + 4 * longest_bytes + header_bytes + 64
        print("  %s, %d piece(s): bytes read per piece %s of %d (bound %d)"
              % (label, n, [p.bytes for p in parts], data_bytes, bound))
        check(most <= bound and total >= data_bytes,
              "%s, %d piece(s): each piece reads about 1/%d of the data" % (label, n, n))
    return parts


# ---------------------------------------------------------------------------
# .tck written by nibabel; float32 big-endian and float64 written here
lines = random_streamlines(300)
tck = os.path.join(out, "TestTractogramPieces.tck")
nib.streamlines.save(Tractogram(lines, affine_to_rasmm=np.eye(4)), tck)
ref = {"lines": list(nib.streamlines.load(tck).streamlines)}
header = nib.streamlines.TckFile._read_header(open(tck, "rb"))
offset = header["_offset_data"]
data_bytes = os.path.getsize(tck) - offset
longest = 12 * (max(len(s) for s in lines) + 1)
parts = check_pieces(".tck (nibabel)", tck, ref, data_bytes, longest)

# piece boundaries inside streamlines: the 7-piece split cuts streamlines
starts = np.cumsum([0] + [len(s) + 1 for s in lines])
end = starts[-1]
cuts = [end * p // 7 for p in range(1, 7)]
inside = sum(1 for c in cuts if c not in set(starts))
check(inside >= 5, ".tck: %d of the 6 boundaries of 7 pieces fall inside streamlines" % inside)

# negative controls: a wrong split is caught by the same comparison
wrong = read_pieces(tck, 2)[:1] + read_pieces(tck, 3)[1:]
check(not same(union(wrong), ref["lines"]),
      "negative control: pieces of 2 and 3 mixed are not the file's streamlines")
naive = [s for p in range(3) for i, s in enumerate(lines)
         if starts[i] < end * (p + 1) // 3 and starts[i + 1] > end * p // 3]
check(not same(naive, ref["lines"]),
      "negative control: a naive split (a streamline to every piece it touches) is rejected")

for datatype in ("Float32BE", "Float64LE", "Float64BE"):
    path = os.path.join(out, "TestTractogramPieces-%s.tck" % datatype)
    offset = write_tck(path, lines[:120], datatype)
    size = 8 if "64" in datatype else 4
    # nibabel reads float32 only: float64 files hold the float32 values written, exactly
    reference = {"lines": list(nib.streamlines.load(path).streamlines) if size == 4 else
                 [s.astype(np.float64) for s in lines[:120]]}
    check_pieces(".tck %s" % datatype, path, reference, os.path.getsize(path) - offset,
                 3 * size * 151)

# empty streamlines (kept or dropped), tiny and empty files
with_empty = lines[:5] + [np.zeros((0, 3), np.float32)] * 2 + lines[5:9] + [
    np.zeros((0, 3), np.float32)]
path = os.path.join(out, "TestTractogramPieces-empty-lines.tck")
offset = write_tck(path, with_empty)
check_pieces(".tck with empty streamlines", path,
             {"lines": list(nib.streamlines.load(path).streamlines)},
             os.path.getsize(path) - offset, longest)
check_pieces(".tck with empty streamlines kept", path, {"lines": with_empty},
             os.path.getsize(path) - offset, longest, keep_empty=True)
for count in (0, 1, 2):
    path = os.path.join(out, "TestTractogramPieces-%d.tck" % count)
    nib.streamlines.save(Tractogram(lines[:count], affine_to_rasmm=np.eye(4)), path)
    check_pieces(".tck with %d streamline(s)" % count, path,
                 {"lines": list(nib.streamlines.load(path).streamlines)},
                 os.path.getsize(path) - nib.streamlines.TckFile._read_header(
                     open(path, "rb"))["_offset_data"], longest)

# .tck + .tsf: the scalars follow the points of every piece
values = [rng.random(len(s)).astype(np.float32) for s in lines]
tsf = os.path.join(out, "TestTractogramPieces_fa.tsf")
write_tsf(tsf, values)
check_pieces(".tck + .tsf", tck, {"lines": ref["lines"], "point": {"fa": values}},
             data_bytes + os.path.getsize(tsf) - 96, longest + 4 * 151, tsf=[tsf])

# ---------------------------------------------------------------------------
# .trk written by nibabel with scalars and properties (an affine that rotates)
affine = np.array([[0, -1.5, 0, 90], [2, 0, 0, -120], [0, 0, 1.25, -60], [0, 0, 0, 1]])
per_point = {"fa": [rng.random((len(s), 1), dtype=np.float32) for s in lines],
             "rgb": [rng.random((len(s), 3), dtype=np.float32) for s in lines]}
per_line = {"length": np.array([[len(s)] for s in lines], np.float32),
            "pair": rng.random((len(lines), 2), dtype=np.float32)}
trk = os.path.join(out, "TestTractogramPieces.trk")
header = {nib.streamlines.Field.VOXEL_TO_RASMM: affine,
          nib.streamlines.Field.VOXEL_SIZES: np.array([1.5, 2, 1.25], np.float32),
          nib.streamlines.Field.DIMENSIONS: np.array([120, 130, 100], np.int16),
          nib.streamlines.Field.VOXEL_ORDER: b"PRS"}
nib.streamlines.save(Tractogram(lines, data_per_point=per_point, data_per_streamline=per_line,
                                affine_to_rasmm=np.eye(4)), trk, header=header)
loaded = nib.streamlines.load(trk)
whole = Piece(trk, 0, 1)
# the .trk points go through the voxel-mm map: nibabel's to 1e-4 mm, then pieces vs the whole read
err = max(np.abs(a - b).max() for a, b in zip(whole.lines, loaded.streamlines))
check(len(whole.lines) == len(lines) and err < 1e-4,
      ".trk (nibabel), one piece: nibabel's points (largest difference %.3g mm)" % err)
trk_ref = {"lines": whole.lines,
           "point": {"fa": [v[:, 0] for v in loaded.tractogram.data_per_point["fa"]],
                     "rgb": list(loaded.tractogram.data_per_point["rgb"])},
           "cell": {"length": list(loaded.tractogram.data_per_streamline["length"][:, 0]),
                    "pair": list(loaded.tractogram.data_per_streamline["pair"])}}
record = 4 * (3 + 4) * 151 + 4 * 3 + 4
check_pieces(".trk (nibabel, scalars, properties)", trk, trk_ref, os.path.getsize(trk) - 1000,
             record, header_bytes=4 * len(lines))
for count in (0, 2):
    path = os.path.join(out, "TestTractogramPieces-%d.trk" % count)
    nib.streamlines.save(Tractogram(lines[:count], affine_to_rasmm=np.eye(4)), path,
                         header=header)
    check_pieces(".trk with %d streamline(s)" % count, path, {"lines": Piece(path, 0, 1).lines},
                 os.path.getsize(path) - 1000, record, header_bytes=4 * count)
# n_count 0 (not recorded): the pieces count the records first
nocount = os.path.join(out, "TestTractogramPieces-nocount.trk")
raw = bytearray(open(trk, "rb").read())
raw[988:992] = np.int32(0).tobytes()
open(nocount, "wb").write(raw)
check_pieces(".trk without n_count", nocount, trk_ref, len(raw) - 1000, record,
             header_bytes=2 * 4 * len(lines))

# ---------------------------------------------------------------------------
# Subsets: the same streamlines whatever the number of pieces
many = random_streamlines(3000, longest=12)
sub_tck = os.path.join(out, "TestTractogramPieces-subset.tck")
sub_trk = os.path.join(out, "TestTractogramPieces-subset.trk")
nib.streamlines.save(Tractogram(many, affine_to_rasmm=np.eye(4)), sub_tck)
nib.streamlines.save(Tractogram(many, affine_to_rasmm=np.eye(4)), sub_trk, header=header)
for label, path in ((".tck", sub_tck), (".trk", sub_trk)):
    everything = (list(nib.streamlines.load(path).streamlines) if label == ".tck"
                  else Piece(path, 0, 1).lines)
    first = {tuple(np.round(s[0], 2)): i for i, s in enumerate(everything)}
    for k in (1, 3, 7):
        sets = [union(read_pieces(path, n, subset=("stride", k, 0))) for n in PIECES]
        check(all(same(s, everything[::k]) for s in sets),
              "%s every k-th streamline, k = %d: exactly the file's [::%d] for 1, 2, 3, 7 pieces (%s)"
              % (label, k, k, [len(s) for s in sets]))
    for fraction, seed in ((0.3, 1), (0.05, 2)):
        sets = [union(read_pieces(path, n, subset=("fraction", fraction, seed))) for n in PIECES]
        count = len(sets[0])
        sd = np.sqrt(len(many) * fraction * (1 - fraction))
        check(all(same(s, sets[0]) for s in sets[1:]),
              "%s random fraction %g (seed %d): the same %d streamlines for 1, 2, 3, 7 pieces"
              % (label, fraction, seed, count))
        check(abs(count - fraction * len(many)) < 4 * sd,
              "%s random fraction %g: %d of %d within 4 sd (%.1f) of %g"
              % (label, fraction, count, len(many), sd, fraction * len(many)))
        positions = [first.get(tuple(np.round(s[0], 2)), -1) for s in sets[0]]
        check(all(b > a for a, b in zip(positions, positions[1:])) and min(positions) >= 0 and
              same(sets[0], [everything[i] for i in positions]),
              "%s random fraction %g: streamlines of the file, in file order" % (label, fraction))
        other = union(read_pieces(path, 2, subset=("fraction", fraction, seed + 10)))
        check(not same(other, sets[0]), "negative control: another seed, another subset")
    check(len(union(read_pieces(path, 3, subset=("fraction", 0.0, 0)))) == 0 and
          same(union(read_pieces(path, 3, subset=("fraction", 1.0, 0))), everything),
          "%s random fraction 0 keeps nothing, 1 everything" % label)

# every k-th counts empty streamlines too (k-th of the file), whether they are kept or not
path = os.path.join(out, "TestTractogramPieces-empty-lines.tck")
for keep in (False, True):
    expected = [s for s in with_empty[::2] if keep or len(s)]
    sets = [union(read_pieces(path, n, keep_empty=keep, subset=("stride", 2, 0))) for n in PIECES]
    check(all(same(s, expected) for s in sets),
          ".tck with empty streamlines (%s), every 2nd: the file's [::2] for 1, 2, 3, 7 pieces"
          % ("kept" if keep else "dropped"))

# ---------------------------------------------------------------------------
# Progress and abort in the piece reads


def progress_run(path, piece, pieces, abort_at=None, **kw):
    reader = splineviz.vtkTractogramReader()
    errors = Observed(reader)
    reader.SetFileName(path)
    if kw.get("stride"):
        reader.SetSubsetModeToStride()
        reader.SetSubsetStride(3)
    seen = []

    def on_progress(caller, event):
        seen.append(caller.GetProgress())
        if abort_at is not None and caller.GetProgress() >= abort_at:
            caller.SetAbortExecute(1)

    reader.AddObserver(vtkCommand.ProgressEvent, on_progress)
    reader.UpdatePiece(piece, pieces, 0)
    return seen, reader.GetOutput().GetNumberOfCells(), errors.all_messages


for label, path, kw in ((".tck", sub_tck, {}), (".tck every 3rd", sub_tck, {"stride": True}),
                        (".trk", sub_trk, {})):
    full, cells, messages = progress_run(path, 1, 2, **kw)
    check(len(full) >= 4 and full == sorted(full) and full[-1] == 1.0 and cells > 0,
          "%s piece 1 of 2: progress rises to 1 (%d reports)" % (label, len(full)))
    # (the pipeline reports 0 before and 1 after the reader's own reports)
    seen, cells, messages = progress_run(path, 1, 2, abort_at=0.0, **kw)
    check(cells == 0 and not messages and len(seen) < len(full),
          "%s piece 1 of 2 aborted at its first report: empty output, no error, stops early (%d "
          "reports)" % (label, len(seen)))

# ---------------------------------------------------------------------------
# Bad input: the pieces that meet the damage fail quickly with a message, the others read


def damaged(name, data):
    path = os.path.join(out, "TestTractogramPieces-bad-" + name)
    open(path, "wb").write(data)
    return path


def check_bad(label, path, pieces, expect_failed, tsf=()):
    parts = read_pieces(path, pieces, tsf=tsf)
    failed = [i for i, p in enumerate(parts) if not p.ok]
    clear = all(p.errors.all_messages and p.message and p.cells == 0 for p in parts if not p.ok)
    print("  %s: failed pieces %s; %s" % (label, failed, [p.message for p in parts if not p.ok][0]))
    check(failed == expect_failed and clear and max(p.seconds for p in parts) < 5,
          "%s: pieces %s fail with a message and an empty output, quickly" % (label, expect_failed))


good = bytearray(open(tck, "rb").read())
offset = nib.streamlines.TckFile._read_header(open(tck, "rb"))["_offset_data"]
triplets = np.frombuffer(bytes(good[offset:]), "<f4").reshape(-1, 3)
tuples = len(triplets)
# a point (not a separator) at three quarters of the data: in piece 1 of 2, far from piece 0's end
j = tuples * 3 // 4 + int(np.argmax(np.isfinite(triplets[tuples * 3 // 4:, 0])))
mid = offset + 12 * j
bad = bytearray(good)
bad[mid:mid + 4] = np.float32(np.nan).tobytes()
check_bad(".tck with a NaN among numbers", damaged("mixed.tck", bad), 2, [1])
bad = bytearray(good)
bad[mid:mid + 12] = np.full(3, np.inf, np.float32).tobytes()
check_bad(".tck with an end marker inside the data", damaged("inner-end.tck", bad), 2, [1])
check_bad(".tck truncated (no end marker)", damaged("truncated.tck", good[:mid]), 3, [0, 1, 2])
check_bad(".tck truncated inside a triplet", damaged("truncated3.tck", good[:mid + 5]), 2, [0, 1])
bad = bytearray(open(tsf, "rb").read())
bad[96 + 4 * j:96 + 4 * (j + 1)] = np.float32(np.nan).tobytes()
check_bad(".tsf not matching in piece 1", tck, 2, [1], tsf=[damaged("fa.tsf", bad)])
check_bad(".tsf shorter than the tractogram", tck, 2, [0, 1],
          tsf=[damaged("short.tsf", open(tsf, "rb").read()[:-40])])
raw = bytearray(open(trk, "rb").read())
# the count of the streamline 200 (in the last third) runs past the end of the file
pos = 1000
for i in range(200):
    pos += 4 + 4 * 7 * int(np.frombuffer(raw[pos:pos + 4], "<i4")[0]) + 12
raw[pos:pos + 4] = np.int32(2 ** 30).tobytes()
check_bad(".trk with a point count past the end (streamline 200)", damaged("count.trk", raw), 3,
          [2])
raw[pos:pos + 4] = np.int32(-5).tobytes()
check_bad(".trk with a negative point count (streamline 200)", damaged("negative.trk", raw), 3,
          [2])
raw[pos:pos + 4] = open(trk, "rb").read()[pos:pos + 4]
raw[pos + 4:pos + 8] = np.float32(np.nan).tobytes()  # the first point of streamline 200
parts = read_pieces(damaged("nan.trk", raw), 3)
check([p.ok for p in parts] == [1, 1, 0] and "piece 2 of 3: streamline 200 has NaN" in parts[2].message,
      ".trk with a NaN point in streamline 200: piece 2 fails, naming the streamline by its index "
      "in the file")
check_bad(".trk truncated", damaged("truncated.trk", open(trk, "rb").read()[:-5000]), 3,
          [2])

checker.finish()
print("all checks passed")
