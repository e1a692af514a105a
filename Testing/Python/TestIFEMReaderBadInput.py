# SPDX-License-Identifier: BSD-3-Clause
"""vtkIFEMReader on bad input: each case must fail with a clear message (naming
the dataset where there is one) and an empty output, never crash, hang or
allocate what the file cannot hold. The files are made here with h5py from a
small valid one (a g2 volume patch with a field and element values), which
must read, as the control."""
import os
import sys
import time

import h5py
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from splineviz import vtkIFEMReader  # noqa: E402
from splineviz_testing import Observed, output_dir  # noqa: E402

OUT = output_dir()
from splineviz_testing import Checker  # noqa: E402

checker = Checker()

G2 = """700 1 0 0
3 0
2 2
0 0 1 1
2 2
0 0 1 1
3 2
0 0 0.5 1 1
""" + "\n".join("%g %g %g" % (i, j, 2 * k) for k in (0, 0.5, 1) for j in (0, 1) for i in (0, 1))
LR_SURFACE = """# LRSPLINE SURFACE
#\tp1\tp2\tNbasis\tNline\tNel\tdim\trat
\t2\t2\t4\t4\t1\t2\t0
# Basis functions:
0: [0 0 1 ] x [0 0 1 ] 0 0 (1)
1: [0 1 1 ] x [0 0 1 ] 1 0 (1)
2: [0 0 1 ] x [0 1 1 ] 0 1 (1)
3: [0 1 1 ] x [0 1 1 ] 1 1 (1)
# Mesh lines:
0 x [0, 1] (2)
1 x [0, 1] (2)
[0, 1] x 0 (2)
[0, 1] x 1 (2)
# Elements:
0 [2] : (0, 0) x (1, 1)    {0, 1, 2, 3}
"""


fail = checker.fail


def chars(text):
    return np.frombuffer(text.encode(), dtype=np.int8)


def write(name, build):
    path = os.path.join(OUT, "TestIFEMReaderBadInput-%s.hdf5" % name)
    with h5py.File(path, "w") as f:
        build(f)
    return path


def valid(f, text=G2, nodes=12, elements=2):
    f["0/Sim-1/basis/1"] = chars(text)
    f["0/Sim-1/fields/u/1"] = np.arange(3.0 * nodes)
    f["0/Sim-1/knotspan/err/1"] = np.arange(1.0 * elements)
    f["0/timeinfo/level"] = np.array([0.0])


def read(path, **settings):
    reader = vtkIFEMReader()
    reader.SetFileName(path)
    for key, value in settings.items():
        getattr(reader, "Set" + key)(value)
    seen = Observed(reader)
    start = time.time()
    reader.Update()
    seconds = time.time() - start
    message = reader.GetLastErrorMessage()
    if isinstance(message, bytes):
        message = message.decode("utf-8", "replace")
    return reader.GetOutput(), message, seen, seconds


def expect_error(label, path, words, **settings):
    out, message, seen, seconds = read(path, **settings)
    print("%s: %s (%.3f s)" % (label, message, seconds))
    if out.GetNumberOfBlocks() != 0:
        fail("%s: the output is not empty" % label)
    if not seen.errors:
        fail("%s: no error was reported" % label)
    for w in words:
        if w not in message:
            fail("%s: the message lacks %r" % (label, w))
    if seconds > 2.0:
        fail("%s: took %.1f s" % (label, seconds))


def expect_ok(label, path, **settings):
    out, message, seen, _ = read(path, **settings)
    if out.GetNumberOfBlocks() == 0 or message or seen.errors:
        fail("%s: the valid file does not read: %s" % (label, message))
    return out, seen


# The control: valid files read.
expect_ok("valid g2 volume", write("valid", valid))
expect_ok("valid LR surface", write("valid-lr", lambda f: valid(f, LR_SURFACE, 4, 1)))

# Files and layouts.
expect_error("missing file", os.path.join(OUT, "does-not-exist.hdf5"), ["cannot open"])
text = os.path.join(OUT, "TestIFEMReaderBadInput-text.hdf5")
with open(text, "w") as out:
    out.write(G2)
expect_error("not HDF5", text, ["not an HDF5 file"])
expect_error("not IFEM's layout", write("layout", lambda f: f.create_group("results")),
             ["\"results\"", "not an output level"])
expect_error("a level missing", write("gap", lambda f: (valid(f), f.create_group("2"))),
             ["level 1 is missing"])
expect_error("no basis", write("nobasis", lambda f: f.create_dataset("0/Sim-1/fields/u/1",
                                                                     data=np.zeros(3))),
             ["no basis group"])
expect_error("patch numbers with a gap",
             write("patchgap", lambda f: (valid(f), f.create_dataset("0/Sim-1/basis/3",
                                                                     data=chars(G2)))),
             ["no patch 2"])

# Patch texts.
expect_error("unknown patch text", write("unknown", lambda f: valid(f, "hello world")),
             ["/0/Sim-1/basis/1", "unknown patch text"])
expect_error("patch text of numbers",
             write("floattext", lambda f: (f.create_dataset("0/Sim-1/basis/1", data=np.zeros(8)),
                                           f.create_dataset("0/timeinfo/level", data=[0.0]))),
             ["/0/Sim-1/basis/1", "is not text"])
expect_error("a curve", write("curve", lambda f: valid(f, "100 1 0 0\n2 0\n2 2\n0 0 1 1\n0 0\n1 1\n")),
             ["class 100", "curve"])
expect_error("NaN coefficient", write("nan", lambda f: valid(f, G2.replace("\n1 1 2", "\nnan 1 2"))),
             ["/0/Sim-1/basis/1", "not a finite number"])
expect_error("truncated patch", write("truncated", lambda f: valid(f, G2[:-20])),
             ["/0/Sim-1/basis/1", "truncated"])
expect_error("absurd basis function count",
             write("absurdlr", lambda f: valid(f, LR_SURFACE.replace("\t4\t4\t1\t2", "\t99999999\t4\t1\t2"), 4, 1)),
             ["/0/Sim-1/basis/1"])
RATIONAL = (LR_SURFACE.replace("\t1\t2\t0\n", "\t1\t3\t0\n")
            .replace("] 0 0 (1)", "] 0 0 1 (1)").replace("] 1 0 (1)", "] 1 0 1 (1)")
            .replace("] 0 1 (1)", "] 0 1 1 (1)").replace("] 1 1 (1)", "] 1 1 -1 (1)"))
expect_ok("valid rational LR surface",
          write("rational", lambda f: valid(f, RATIONAL.replace("1 1 -1 (1)", "1 1 2 (1)"), 4, 1)))
expect_error("negative rational weight", write("weight", lambda f: valid(f, RATIONAL, 4, 1)),
             ["weight", "positive"])
expect_error("absurd Lagrange counts",
             write("lagrange", lambda f: valid(f, "# LAGRANGIAN nodes=1000000000 elements=5 type=hexahedron\n0 0 0\n")),
             ["more than the text can hold"])
expect_error("unknown Lagrange type",
             write("lagrangetype", lambda f: valid(f, "# LAGRANGIAN nodes=4 elements=1 type=tetrahedron\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n0 1 2 3\n")),
             ["unknown Lagrange element type"])

# Fields and element values.
expect_error("field size mismatch",
             write("fieldsize", lambda f: (valid(f), f.__delitem__("0/Sim-1/fields/u/1"),
                                           f.create_dataset("0/Sim-1/fields/u/1", data=np.zeros(13)))),
             ["field \"u\"", "13 values", "not a positive multiple of the 12"])
expect_error("element value size mismatch",
             write("knotspansize", lambda f: (valid(f), f.__delitem__("0/Sim-1/knotspan/err/1"),
                                              f.create_dataset("0/Sim-1/knotspan/err/1", data=np.zeros(3)))),
             ["element field \"err\"", "2 elements"])
expect_error("field of strings",
             write("fieldtype", lambda f: (valid(f), f.__delitem__("0/Sim-1/fields/u/1"),
                                           f.create_dataset("0/Sim-1/fields/u/1", data=np.array([b"ab"] * 36)))),
             ["does not hold numbers"])


def absurd(f):
    # 10^11 doubles announced (800 GB), nothing stored: chunked, never written.
    valid(f)
    del f["0/Sim-1/fields/u/1"]
    f.create_dataset("0/Sim-1/fields/u/1", shape=(10 ** 11,), dtype="f8", chunks=(4096,))


path = write("absurd", absurd)
print("absurd size: the file has %d bytes" % os.path.getsize(path))
expect_error("absurd dataset size", path, ["/0/Sim-1/fields/u/1", "refused before allocating"])

# A NaN in field values is data (simulations write NaN for undefined values): read, warned.
out, seen = expect_ok("NaN field value",
                      write("nanfield", lambda f: (valid(f), f.__delitem__("0/Sim-1/fields/u/1"),
                                                   f.create_dataset("0/Sim-1/fields/u/1",
                                                                    data=np.r_[np.nan, np.arange(35.0)]))))
if not seen.warnings:
    fail("a NaN field value is not warned about")
print("NaN field value: read, %d warning(s)" % len(seen.warnings))

checker.finish()
