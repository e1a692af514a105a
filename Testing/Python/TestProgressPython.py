# SPDX-License-Identifier: BSD-3-Clause
"""Progress, abort and a refused hostile size seen from Python, through the
example Examples/Python/progress_and_abort.py: the progress values increase
to 1 (at least 5 events), the cancelled run is empty, the 100000^3 request
fails with the memory message and the process goes on."""
import os
import runpy

source = os.environ["SPLINEVIZ_SOURCE_DIR"]
example = runpy.run_path(os.path.join(source, "Examples", "Python", "progress_and_abort.py"))
result = example["main"](os.path.join(source, "Testing", "Data", "External",
                                      "cube-3patch-refined.lr"))
from splineviz_testing import Checker  # noqa: E402

checker = Checker()
p = result["progress"]
checker.check(len(p) >= 5 and all(b >= a for a, b in zip(p, p[1:])) and p[-1] == 1.0,
              "progress increasing to 1 in >= 5 events: %s" % p)
checker.check(result["full"] == 96 ** 3, "full run: %d points" % result["full"])
checker.check(result["aborted"] == 0, "cancelled run: %d points, expected 0" % result["aborted"])
checker.check(not result["hostile_ok"] and "more than this machine's" in result["refusal"],
              "100000^3 refused as expected: %r" % result["refusal"])
checker.finish()
