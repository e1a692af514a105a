# SPDX-License-Identifier: BSD-3-Clause
"""ParaView's parallel pipeline with ray-cast tubes: the same scene rendered
by one pvbatch process and by two MPI ranks (each drawing half of the tubes,
IceT compositing their images by depth) must give the same picture. The
ray-cast tubes write their exact depth, so the composite is exact: any
depth error would show where tubes of different ranks cross. A third run
colors the tubes by rank to prove that both ranks drew; a fourth runs the
two ranks with the occlusion-culling pre-pass, which must not change the
composite either (each rank culls only against its own tubes, exactly). A
fifth pair draws with the automatic radius (Tube Radius 0): every rank must
take it from the bounds of the whole data set, so that two ranks draw the
serial picture.

    TestParallelRayCastTubes.sh PVBATCH MPIEXEC PVPYTHON OUTPUT_DIR
renders the four images (one rank, two ranks, two ranks colored by rank,
two ranks with occlusion culling)
and runs this script on them:
    pvpython TestParallelRayCastTubes.py OUTPUT_DIR
"""
import os
import sys

from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader

def read(path):
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    return vtk_to_numpy(reader.GetOutput().GetPointData().GetScalars())[:, :3].astype(int)


out_dir = sys.argv[1]
serial = os.path.join(out_dir, "TestParallelRayCastTubes-1rank.png")
parallel = os.path.join(out_dir, "TestParallelRayCastTubes-2ranks.png")
ranks = os.path.join(out_dir, "TestParallelRayCastTubes-2ranks-by-rank.png")
culled = os.path.join(out_dir, "TestParallelRayCastTubes-2ranks-culling.png")

a = read(serial)
b = read(parallel)
covered = int((a.min(axis=1) < 250).sum())
difference = abs(a - b).max(axis=1)
wrong = int((difference > 24).sum())
print("covered pixels %d, pixels differing by more than 24 levels: %d (largest %d)"
      % (covered, wrong, int(difference.max())))
if covered < 20000:
    print("ERROR: the tubes did not render")
    sys.exit(1)
if wrong > covered // 1000:
    print("ERROR: the two-rank composite differs from the serial image")
    sys.exit(1)
difference = abs(a - read(culled)).max(axis=1)
wrong = int((difference > 24).sum())
print("with occlusion culling: pixels differing by more than 24 levels: %d (largest %d)"
      % (wrong, int(difference.max())))
if wrong > covered // 1000:
    print("ERROR: the two-rank composite with occlusion culling differs from the serial image")
    sys.exit(1)

a_auto = read(os.path.join(out_dir, "TestParallelRayCastTubes-1rank-automatic.png"))
b_auto = read(os.path.join(out_dir, "TestParallelRayCastTubes-2ranks-automatic.png"))
covered_auto = int((a_auto.min(axis=1) < 250).sum())
difference = abs(a_auto - b_auto).max(axis=1)
wrong = int((difference > 24).sum())
print("automatic radius: covered pixels %d, pixels differing by more than 24 levels: %d"
      % (covered_auto, wrong))
if covered_auto < 5000 or wrong > covered_auto // 1000:
    print("ERROR: with the automatic radius the two-rank composite differs from the serial image")
    sys.exit(1)

# Both ranks drew: two distinct tube colors in the by-rank image.
c = read(ranks)
tube = c[c.min(axis=1) < 250]
reds = int(((tube[:, 0] > tube[:, 2] + 40)).sum())
blues = int(((tube[:, 2] > tube[:, 0] + 40)).sum())
print("by rank: %d reddish, %d bluish pixels" % (reds, blues))
if reds < covered // 10 or blues < covered // 10:
    print("ERROR: one rank drew (almost) nothing")
    sys.exit(1)
