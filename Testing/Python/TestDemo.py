# SPDX-License-Identifier: BSD-3-Clause
"""The README's main command renders Examples/Python/demo.py: run it into a
fresh directory and check every picture it promises is written and shows
something (not a blank or single-color image)."""
import os
import runpy
import shutil
import sys

from splineviz_testing import drawn_fraction

source = os.environ["SPLINEVIZ_SOURCE_DIR"]
out = os.path.join(os.environ.get("SPLINEVIZ_TEST_OUTPUT", "."), "TestDemo")
shutil.rmtree(out, ignore_errors=True)
os.makedirs(out)
sys.argv = ["demo.py", out]
runpy.run_path(os.path.join(source, "Examples", "Python", "demo.py"), run_name="__main__")

expected = [
    "fibers-raycast-tubes.png",
    "fibers-raycast-tubes-closeup.png",
    "fibers-tessellated-tubes.png",
    "fibers-tessellated-tubes-closeup.png",
    "fibers-tessellated-tubes-closeup-wireframe.png",
    "fibers-vtk-tube-filter-closeup.png",
    "fibers-stylized-lines-halo.png",
    "fibers-stylized-lines-closeup.png",
    "stylized-lines.png",
    "lr-spline-elements.png",
    "lr-spline-g2-geometry.png",
    "lr-spline-streamlines.png",
    "lr-spline-volume-streamlines.png",
    "lr-spline-volume-isosurfaces.png",
    "lr-spline-fit-aniso-vox-volume.png",
    "superquadric-glyphs-gamma-0-3-20.png",
    "tensor-lines-dipy.png",
]
failed = False
for name in expected:
    path = os.path.join(out, name)
    if not os.path.exists(path):
        print("ERROR: demo.py did not write", name)
        failed = True
        continue
    drawn = drawn_fraction(path)
    print("%s: %.3f of the picture drawn" % (name, drawn))
    if drawn < 0.03:
        print("ERROR: %s is (almost) blank" % name)
        failed = True
sys.exit(1 if failed else 0)
