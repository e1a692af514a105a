"""Writes the seeds of the IFEM reader's fuzz target (corpus/ifem/) and the
GoTools LR seeds of the g2 parser's (corpus/g2/*-lr.g2): small HDF5 files with
IFEM's layout trimmed from the real files of Testing/Data/External/ifem (one
patch, one or two fields, the newest HDF5 format so that they are small), and
class 293 / 793 text written from the small LR seeds of corpus/lr.

    /usr/bin/python3 Testing/Fuzz/corpus/make_ifem_seeds.py
"""
import os
import sys

import h5py
import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
root = os.path.normpath(os.path.join(here, "..", "..", ".."))
sys.path.insert(0, os.path.join(root, "Testing", "Python"))
from ifem_reference import gotools_lr  # noqa: E402

data = os.path.join(root, "Testing", "Data", "External", "ifem")
out = os.path.join(here, "ifem")
os.makedirs(out, exist_ok=True)


def copy(src, dst, items, renumber=None):
    """Copy datasets (level, path) of src into a new small file dst."""
    with h5py.File(os.path.join(data, src), "r") as f, \
            h5py.File(os.path.join(out, dst), "w", libver="latest") as g:
        for path in items:
            target = renumber(path) if renumber else path
            g.create_dataset(target, data=f[path][()])
    print(dst, os.path.getsize(os.path.join(out, dst)), "bytes")


copy("Field3D-2PLR.hdf5", "g2-mixed-bases.hdf5",
     ["0/Stokes-1/basis/1", "0/Stokes-1/fields/u/1", "0/Stokes-2/basis/1", "0/Stokes-2/fields/v/1"])
copy("SmallBox.hdf5", "lagrange-two-levels.hdf5",
     ["0/Simra-1/basis/1", "0/Simra-1/fields/rho/1",
      "0/Simra-1/knotspan/Continuous global L2-projection eta^p/1", "1/Simra-1/fields/rho/1"])
copy("Cyl2D-VMSFSI-weak.hdf5", "moving-mesh-orphan.hdf5",
     ["0/NavierStokes-1/basis/1", "0/NavierStokes-1/fields/u_x&&u_y&&p/1", "0/SA-1/fields/nut/1",
      "0/timeinfo/level", "1/NavierStokes-1/basis/1", "1/NavierStokes-1/fields/u_x&&u_y&&p/1",
      "1/SA-1/fields/nut/1", "1/timeinfo/level"])
copy("Square-LR.hdf5", "lr-surface-knotspan.hdf5",
     ["0/Poisson-1/basis/1", "0/Poisson-1/fields/u/1",
      "0/Poisson-1/knotspan/a(u,u)^0.5/1"])
copy("Field2D-1PLR.hdf5", "lr-surface-mixed.hdf5",
     ["0/Stokes-2/basis/1", "0/Stokes-2/fields/p/1"])
copy("ScordelisPoint-NURBS.hdf5", "rational-lr-shell.hdf5",
     ["0/Elasticity-1/basis/1", "0/Elasticity-1/fields/displacement/1"])

# GoTools' LR formats for the g2 parser.
for name, rational in (("trilinear-one-element", False), ("quadratic-refined-scalar", False)):
    text = open(os.path.join(here, "lr", name + ".lr")).read()
    path = os.path.join(here, "g2", name + "-793.g2")
    with open(path, "w") as f:
        f.write(gotools_lr(text))
    print(os.path.basename(path), os.path.getsize(path), "bytes")
with h5py.File(os.path.join(data, "Field2D-1PLR.hdf5"), "r") as f:
    text = bytes(f["0/Stokes-2/basis/1"][()].astype(np.uint8)).decode()
path = os.path.join(here, "g2", "bicubic-surface-293.g2")
with open(path, "w") as f:
    f.write(gotools_lr(text))
print(os.path.basename(path), os.path.getsize(path), "bytes")
