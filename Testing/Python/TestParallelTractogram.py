# SPDX-License-Identifier: BSD-3-Clause
"""The tractogram reader under MPI (TestParallelTractogram.sh runs it):

    pvpython TestParallelTractogram.py make OUTPUT_DIR
writes tracts.tck with nibabel: 600 smooth streamlines of 20 to 120 points
(0.6 mm steps) in a box of about 150 mm;
    pvpython TestParallelTractogram.py compare OUTPUT_DIR
checks what the scene runs wrote: with two ranks each rank held about half of
the streamlines and read about half of the data (LastBytesRead), the ranks'
streamlines add up to the file's; the composited image of two ranks equals
the single process's (all streamlines, and a random half: the subset does
not depend on the number of ranks). Negative control: the image of the
random half differs from the image of all streamlines by far more than the
tolerance. Bad input: with a NaN among the numbers in the second rank's
half, that rank reports the reader's error and holds nothing, the first
draws its half, and the run finishes.
"""
import glob
import json
import os
import sys

import numpy as np

out = sys.argv[2]
tck = os.path.join(out, "tracts.tck")
if sys.argv[1] == "make":
    import nibabel as nib
    from nibabel.streamlines import Tractogram
    rng = np.random.default_rng(4)
    lines = []
    for i in range(600):
        n = int(rng.integers(20, 120))
        start = rng.uniform(-30, 30, 3)
        direction = rng.normal(0, 1, 3)
        bend = rng.normal(0, 0.03, 3)
        tangents = direction / np.linalg.norm(direction) + np.cumsum(np.tile(bend, (n, 1)), axis=0)
        tangents /= np.linalg.norm(tangents, axis=1)[:, None]
        lines.append((start + 0.6 * np.cumsum(tangents, axis=0)).astype(np.float32))
    nib.streamlines.save(Tractogram(lines, affine_to_rasmm=np.eye(4)), tck)
    print("wrote %s: %d streamlines, %d points" % (tck, len(lines), sum(len(s) for s in lines)))
    # The same file damaged in the second rank's half: a NaN among the numbers
    # of a point at three quarters of the data.
    data = bytearray(open(tck, "rb").read())
    offset = nib.streamlines.TckFile._read_header(open(tck, "rb"))["_offset_data"]
    triplets = np.frombuffer(bytes(data[offset:]), "<f4").reshape(-1, 3)
    j = len(triplets) * 3 // 4
    j += int(np.argmax(np.isfinite(triplets[j:, 0])))
    data[offset + 12 * j:offset + 12 * j + 4] = np.float32(np.nan).tobytes()
    open(os.path.join(out, "tracts-damaged.tck"), "wb").write(data)
    sys.exit(0)

from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402
from vtkmodules.vtkIOImage import vtkPNGReader  # noqa: E402

from splineviz_testing import Checker  # noqa: E402

checker = Checker()


check = checker.check


def read(path):
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    return vtk_to_numpy(reader.GetOutput().GetPointData().GetScalars())[:, :3].astype(int)


def shares(label, subset):
    files = sorted(glob.glob(os.path.join(out, "shares-%s-%s-rank*.json" % (label, subset))))
    return [json.load(open(f)) for f in files]


import nibabel as nib  # noqa: E402

header = nib.streamlines.TckFile._read_header(open(tck, "rb"))
total = header["count"] if isinstance(header["count"], int) else int(header["count"])
data_bytes = os.path.getsize(tck) - header["_offset_data"]
serial, parallel = shares("1rank", "all"), shares("2ranks", "all")
print("one process: %s" % serial)
print("two ranks:   %s" % parallel)
print("file: %d streamlines, %d data bytes" % (total, data_bytes))
check(len(serial) == 1 and serial[0]["cells"] == total and serial[0]["bytes"] >= data_bytes,
      "one process holds every streamline and reads the whole data")
check(len(parallel) == 2 and sum(r["cells"] for r in parallel) == total and
      all(0.35 * total < r["cells"] < 0.65 * total for r in parallel),
      "two ranks: each holds about half of the streamlines, together all of them")
check(len(parallel) == 2 and all(r["bytes"] <= data_bytes / 2 + 3 * 12 * 121 + 64
                                 for r in parallel),
      "two ranks: each reads about half of the data (at most half plus its last streamline)")
half = shares("1rank", "half"), shares("2ranks", "half")
check(sum(r["cells"] for r in half[0]) == sum(r["cells"] for r in half[1]) and
      0.4 * total < sum(r["cells"] for r in half[0]) < 0.6 * total,
      "random half: the same number of streamlines with one and two ranks (%d)"
      % sum(r["cells"] for r in half[0]))

for subset in ("all", "half"):
    a = read(os.path.join(out, "1rank-%s.png" % subset))
    b = read(os.path.join(out, "2ranks-%s.png" % subset))
    covered = int((a.min(axis=1) < 250).sum())
    difference = abs(a - b).max(axis=1)
    wrong = int((difference > 24).sum())
    print("%s: covered pixels %d, pixels differing by more than 24 levels: %d (largest %d)"
          % (subset, covered, wrong, int(difference.max())))
    check(covered > 20000, "%s: the tubes rendered" % subset)
    check(wrong <= covered // 1000, "%s: the two-rank composite equals the single process's" % subset)
a = read(os.path.join(out, "1rank-all.png"))
b = read(os.path.join(out, "1rank-half.png"))
wrong = int((abs(a - b).max(axis=1) > 24).sum())
check(wrong > 10 * (int((a.min(axis=1) < 250).sum()) // 1000),
      "negative control: the random half's image differs from all streamlines' (%d pixels)" % wrong)

# A piece damaged on the second rank: that rank reports the reader's error
# and draws nothing, the first draws its half, and the run ends (no rank
# waits for the other forever).
damaged = shares("2ranks-damaged", "all")
log = open(os.path.join(out, "2ranks-damaged.log"), errors="replace").read()
status = open(os.path.join(out, "2ranks-damaged.status")).read().strip()
print("damaged piece: exit status %s, ranks %s" % (status, damaged))
check(status not in ("124", "137"), "damaged piece: the two ranks finish (exit status %s)" % status)
check(any("vtkTractogramReader" in line and "ERR" in line and "piece 1 of 2" in line
          and "pvbatch.1" in line for line in log.splitlines()),
      "damaged piece: the second rank reports the reader's error for its piece")
# (the damaged rank's reader fails, so the filter after it does not run there)
check(len(damaged) == 1 and damaged[0]["rank"] == 0 and
      0.35 * total < damaged[0]["cells"] < 0.65 * total,
      "damaged piece: the first rank holds its half, the damaged one no output")
picture = read(os.path.join(out, "2ranks-damaged-all.png"))
drawn_damaged = int((picture.min(axis=1) < 250).sum())
drawn_all = int((read(os.path.join(out, "2ranks-all.png")).min(axis=1) < 250).sum())
check(5000 < drawn_damaged < drawn_all,
      "damaged piece: the healthy half is drawn (%d pixels, all: %d)" % (drawn_damaged, drawn_all))

checker.finish()
print("parallel tractogram reading OK")
