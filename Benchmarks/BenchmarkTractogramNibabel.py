# SPDX-License-Identifier: BSD-3-Clause
"""nibabel's load time for the files BenchmarkTractogramIO writes (run that with
--keep 1 first): the Python tool neuroimaging users read tractograms with,
for the README's comparison. Prints the median of 3 loads per file.

    build/bin/BenchmarkTractogramIO --keep 1
    python3 Benchmarks/BenchmarkTractogramNibabel.py [/tmp]
"""
import os
import sys
import time

import nibabel as nib

folder = sys.argv[1] if len(sys.argv) > 1 else "/tmp"
for name in ("BenchmarkTractogramIO.tck", "BenchmarkTractogramIO.trk"):
    path = os.path.join(folder, name)
    times = []
    for _ in range(3):
        t0 = time.perf_counter()
        tractogram = nib.streamlines.load(path)
        points = len(tractogram.streamlines.get_data())
        times.append(time.perf_counter() - t0)
    print("%-28s %9d points  nibabel %.3f s (median of 3)" % (name, points, sorted(times)[1]))
