# SPDX-License-Identifier: BSD-3-Clause
"""Loading SplineViz runs VTK's parallel loops on all cores when the process
uses VTK's Sequential default (vtkSplineVizThreads): checked in fresh
processes, with negative controls (a backend the user chose is kept; one core
per MPI rank keeps Sequential) and against the same process without
SplineViz, which must stay Sequential (else the test proves nothing)."""
import os
import subprocess
import sys

CHILD = r"""
import sys
from vtkmodules.vtkCommonCore import vtkSMPTools
if sys.argv[1] == "splineviz":
    import splineviz  # loads the SplineViz library
    splineviz.vtkSyntheticFibersSource()
print("BACKEND", vtkSMPTools.GetBackend(), vtkSMPTools.GetEstimatedNumberOfThreads())
"""

cores = os.cpu_count() or 1
if cores < 2:
    print("one core: nothing to switch")
    sys.exit(125)


def run(load, **env):
    environment = dict(os.environ)
    # PV_PLUGIN_PATH: pvpython loads the plugins it names at start-up (the
    # SplineViz plugin would switch the "VTK alone" process too).
    for name in ("VTK_SMP_BACKEND_IN_USE", "VTK_SMP_MAX_THREADS",
                 "OMPI_COMM_WORLD_LOCAL_SIZE", "MPI_LOCALNRANKS", "PV_PLUGIN_PATH"):
        environment.pop(name, None)
    environment.update(env)
    python = os.environ.get("SPLINEVIZ_TEST_PYTHON", sys.executable)
    out = subprocess.run([python, "-c", CHILD, load], env=environment,
                         capture_output=True, text=True, timeout=120)
    for line in out.stdout.splitlines():
        if line.startswith("BACKEND"):
            _, backend, threads = line.split()
            return backend, int(threads)
    print("ERROR: no answer from the child:", out.stdout, out.stderr)
    sys.exit(1)


failures = []


def expect(what, got, backend, threads):
    print(f"{what}: {got[0]} with {got[1]} threads (expected {backend}, {threads})")
    if got != (backend, threads):
        failures.append(what)


plain = run("vtk")
print(f"VTK alone: {plain[0]} with {plain[1]} threads")
if plain[0] != "Sequential":
    print("this VTK does not default to Sequential: nothing to switch")
    sys.exit(125)
expect("SplineViz loaded", run("splineviz"), "STDThread", cores)
expect("VTK_SMP_BACKEND_IN_USE=Sequential kept", run("splineviz", VTK_SMP_BACKEND_IN_USE="Sequential"),
       "Sequential", 1)
expect("VTK_SMP_MAX_THREADS=1 keeps one thread", run("splineviz", VTK_SMP_MAX_THREADS="1"),
       "Sequential", 1)
expect("one core per MPI rank keeps Sequential",
       run("splineviz", OMPI_COMM_WORLD_LOCAL_SIZE=str(cores)), "Sequential", 1)
if cores >= 4:
    expect("two MPI ranks share the cores", run("splineviz", MPI_LOCALNRANKS="2"),
           "STDThread", cores // 2)
if failures:
    print("ERROR:", ", ".join(failures))
    sys.exit(1)
