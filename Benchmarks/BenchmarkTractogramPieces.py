# SPDX-License-Identifier: BSD-3-Clause
"""Peak memory of reading a tractogram in one pvbatch process and in MPI
ranks (each reading only its piece). Writes a synthetic .tck
(vtkSyntheticTractogramSource: dense bundles, 50-200 points, 1 mm steps) if
it is missing, then runs pvbatch on this script with 1 and with N ranks; each
rank reports its streamlines, the bytes its reader read and its peak RSS
(VmHWM, which unlike getrusage's maximum does not carry over a parent's
peak). A program, not a timed test.

    source build/splineviz-env.sh
    pvpython Benchmarks/BenchmarkTractogramPieces.py [STREAMLINES [RANKS [FILE]]]
    (defaults: 1000000, 2, /tmp/splineviz-pieces-STREAMLINES.tck)
"""
import json
import os
import subprocess
import sys
import tempfile

if len(sys.argv) > 1 and sys.argv[1] == "--rank":
    # run by pvbatch (every rank runs the Programmable Filter below)
    from paraview.simple import OpenDataFile, ProgrammableFilter
    tck, report = sys.argv[2], sys.argv[3]
    reader = OpenDataFile(tck)
    probe = ProgrammableFilter(Input=reader)
    probe.Script = """
import json
import splineviz
from vtkmodules.vtkParallelCore import vtkMultiProcessController
c = vtkMultiProcessController.GetGlobalController()
rank = c.GetLocalProcessId() if c else 0
source = self.GetInputAlgorithm(0, 0)
while not hasattr(source, "GetLastBytesRead"):
    source = source.GetInputAlgorithm(0, 0)
data = self.GetInput()
json.dump({"rank": rank, "streamlines": data.GetNumberOfCells(), "points": data.GetNumberOfPoints(),
           "bytes_read": source.GetLastBytesRead(),
           "peak_rss_mb": [int(l.split()[1]) for l in open("/proc/self/status")
                           if l.startswith("VmHWM")][0] / 1024.0},
          open(r"%s-%%d.json" %% rank, "w"))
""" % report
    probe.UpdatePipeline()  # (no sys.exit: pvbatch must finalize MPI)


def main():
    count = int(sys.argv[1]) if len(sys.argv) > 1 else 1000000
    ranks = int(sys.argv[2]) if len(sys.argv) > 2 else 2
    tck = sys.argv[3] if len(sys.argv) > 3 else "/tmp/splineviz-pieces-%d.tck" % count
    if not os.path.exists(tck):
        import splineviz
        source = splineviz.vtkSyntheticTractogramSource()
        source.SetNumberOfStreamlines(count)
        writer = splineviz.vtkTractogramWriter()
        writer.SetInputConnection(source.GetOutputPort())
        writer.SetFileName(tck)
        if not writer.Write():
            sys.exit("could not write " + tck)
    print("%s: %.0f MB" % (tck, os.path.getsize(tck) / 2.0 ** 20))
    # (without the MPI variables of this pvpython's own MPI start-up)
    env = {k: v for k, v in os.environ.items() if not k.startswith(("OMPI_", "PMIX_"))}
    env.update(OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    results = {}
    with tempfile.TemporaryDirectory() as folder:
        for n in (1, ranks):
            report = os.path.join(folder, "ranks%d" % n)
            command = ["pvbatch", "--force-offscreen-rendering", os.path.abspath(__file__), "--rank",
                       tck, report]
            if n > 1:
                command = ["mpiexec", "--oversubscribe", "-np", str(n)] + command
            subprocess.run(command, check=True, env=env, stdout=subprocess.DEVNULL)
            results[n] = [json.load(open("%s-%d.json" % (report, r))) for r in range(n)]
    single = results[1][0]["peak_rss_mb"]
    for n in (1, ranks):
        for r in results[n]:
            print("%d rank(s), rank %d: %9d streamlines %11d points, read %6.0f MB, peak RSS %6.0f MB"
                  " (%.2f of one process)" % (n, r["rank"], r["streamlines"], r["points"],
                                              r["bytes_read"] / 2.0 ** 20, r["peak_rss_mb"],
                                              r["peak_rss_mb"] / single))


if not (len(sys.argv) > 1 and sys.argv[1] == "--rank"):
    main()
