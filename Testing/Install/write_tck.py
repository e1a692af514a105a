# SPDX-License-Identifier: BSD-3-Clause
"""Writes a small MRtrix .tck file by hand (header, float32 triplets, a NaN
triplet after each streamline, an Inf triplet at the end), independently of
SplineViz's writer:  write_tck.py OUT.tck N  -> N streamlines, streamline i
(from 0) with i + 2 points."""
import math
import struct
import sys

path, count = sys.argv[1], int(sys.argv[2])
data = b""
for i in range(count):
    for j in range(i + 2):
        data += struct.pack("<3f", float(i), float(j), 0.5 * j)
    data += struct.pack("<3f", math.nan, math.nan, math.nan)
data += struct.pack("<3f", math.inf, math.inf, math.inf)
offset = 64
header = "mrtrix tracks\ncount: %d\ndatatype: Float32LE\nfile: . %d\nEND\n" % (count, offset)
assert len(header) <= offset
with open(path, "wb") as f:
    f.write(header.encode("ascii").ljust(offset, b"\0") + data)
