# SPDX-License-Identifier: BSD-3-Clause
"""Progress, abort and a refused hostile size seen from Python, through the
example Examples/Python/progress_and_abort.py: the progress values increase
to 1 (at least 5 events), the cancelled run is empty, the 100000^3 request
fails with the memory message and the process goes on."""
import os
import runpy
import sys

source = os.environ["SPLINEVIZ_SOURCE_DIR"]
example = runpy.run_path(os.path.join(source, "Examples", "Python", "progress_and_abort.py"))
result = example["main"](os.path.join(source, "Testing", "Data", "External",
                                      "cube-3patch-refined.lr"))
failures = []
p = result["progress"]
if len(p) < 5 or any(b < a for a, b in zip(p, p[1:])) or p[-1] != 1.0:
    failures.append("progress not increasing to 1 in >= 5 events: %s" % p)
if result["full"] != 96 ** 3:
    failures.append("full run: %d points" % result["full"])
if result["aborted"] != 0:
    failures.append("cancelled run: %d points, expected 0" % result["aborted"])
if result["hostile_ok"] or "more than this machine's" not in result["refusal"]:
    failures.append("100000^3 not refused as expected: %r" % result["refusal"])
for f in failures:
    print("ERROR: " + f)
sys.exit(1 if failures else 0)
