# SPDX-License-Identifier: BSD-3-Clause
"""The tessellated tubes from Python: runs the example script
Examples/Python/tessellated_tubes.py (plain VTK pipeline with the `splineviz`
package) with and without the level of detail, and checks what it reports
and draws: triangles generated, the base meshes used, the GPU memory per
segment, and an image showing the tubes."""
import contextlib
import io
import os
import re
import runpy
import sys

source_dir = os.environ["SPLINEVIZ_SOURCE_DIR"]
out_dir = os.environ.get("SPLINEVIZ_TEST_OUTPUT", ".")
os.makedirs(out_dir, exist_ok=True)
script = os.path.join(source_dir, "Examples", "Python", "tessellated_tubes.py")


def run(*options):
    png = os.path.join(out_dir, "TestTessellatedTubesPython%s.png" % "".join(options))
    # Run the example in this interpreter (pvpython) as its own __main__.
    sys.argv = [script, "--size", "400", "300", "--output", png] + list(options)
    output = io.StringIO()
    with contextlib.redirect_stdout(output):
        runpy.run_path(script, run_name="__main__")
    result = type("Result", (), {"stdout": output.getvalue()})
    print(result.stdout)
    values = {}
    for key, pattern in (("segments", r"segments: (\d+)"), ("triangles", r"triangles generated: (\d+)"),
                         ("bytes", r"GPU memory: ([\d.]+) bytes")):
        match = re.search(pattern, result.stdout)
        if not match:
            print("ERROR: the example did not report", key)
            sys.exit(1)
        values[key] = float(match.group(1))
    values["lod"] = re.search(r"base meshes \(rings x sides: segments\): (.*)", result.stdout).group(1)

    from vtkmodules.vtkIOImage import vtkPNGReader

    reader = vtkPNGReader()
    reader.SetFileName(png)
    reader.Update()
    scalars = reader.GetOutput().GetPointData().GetScalars()
    background = scalars.GetTuple3(0)
    n = scalars.GetNumberOfTuples()
    covered = sum(1 for i in range(0, n, 5) if scalars.GetTuple3(i) != background)
    values["coverage"] = covered / float(len(range(0, n, 5)))
    return values


lod = run()
fixed = run("--no-lod")
print("level of detail:", lod)
print("fixed base mesh:", fixed)
for v in (lod, fixed):
    if v["segments"] != 3530 or v["triangles"] <= 0 or v["coverage"] < 0.1:
        print("ERROR: tubes missing", v)
        sys.exit(1)
    if v["bytes"] > 96:
        print("ERROR: more than Salm's 96 bytes per segment on the GPU", v["bytes"])
        sys.exit(1)
if "thin " not in lod["lod"] or "16 x 8" not in fixed["lod"]:
    print("ERROR: unexpected base meshes", lod["lod"], fixed["lod"])
    sys.exit(1)
if lod["triangles"] >= fixed["triangles"]:
    print("ERROR: the level of detail did not reduce the triangles")
    sys.exit(1)
if abs(lod["coverage"] - fixed["coverage"]) > 0.05 * fixed["coverage"]:
    print("ERROR: the level of detail changed the coverage by more than 5 %")
    sys.exit(1)
