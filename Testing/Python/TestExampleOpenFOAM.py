# SPDX-License-Identifier: BSD-3-Clause
"""The OpenFOAM example (Examples/Python/lr_spline_fit_openfoam.py), VTK
without ParaView's server manager, on the real porous angled duct
(scripts/openfoam-case.sh, the case the plugin's OpenFOAM test caches) at a
5 % tolerance so that it stays short: it fits, writes its .lr files and
draws its two pictures. The trimmed one (trimmed by the boundary the fitted
spline carries, nothing connected) shows the duct: it draws at least 5 % of
the picture, no pixel where the untrimmed one (the spline's whole box)
draws none, and at least 20 % fewer pixels than the untrimmed one (negative
control: without trimming the box shows around the duct)."""
import os
import runpy
import sys

from splineviz_testing import drawn_mask, openfoam_case, output_dir, png_rgb

source = os.environ["SPLINEVIZ_SOURCE_DIR"]
foam = openfoam_case(source)
if foam is None:
    sys.exit(1)

out = os.path.join(output_dir(), "TestExampleOpenFOAM")
pictures = [os.path.join(out, "lr-spline-fit-openfoam%s.png" % s) for s in ("", "-untrimmed")]
for png in pictures:
    if os.path.exists(png):
        os.remove(png)
sys.argv = ["lr_spline_fit_openfoam.py", foam, out, "0.05"]
runpy.run_path(os.path.join(source, "Examples", "Python", "lr_spline_fit_openfoam.py"),
               run_name="__main__")

failures = []
for name in ("openfoam-p.lr", "openfoam-U.lr"):
    if not os.path.getsize(os.path.join(out, name)) > 0:
        failures.append("%s is empty" % name)
trimmed, untrimmed = (drawn_mask(png_rgb(png), tolerance=10) for png in pictures)
outside = int((trimmed & ~untrimmed).sum())
print("drawn: trimmed %.3f, untrimmed %.3f of the picture; trimmed pixels where the untrimmed "
      "picture has none: %d" % (trimmed.mean(), untrimmed.mean(), outside))
if trimmed.mean() < 0.05:
    failures.append("the trimmed picture is (almost) empty")
if outside > 0:
    failures.append("the trimmed picture draws where the spline's box does not")
if not trimmed.sum() < 0.8 * untrimmed.sum():
    failures.append("negative control: the untrimmed box should draw far more than the duct")
for failure in failures:
    print("ERROR:", failure)
sys.exit(1 if failures else 0)
