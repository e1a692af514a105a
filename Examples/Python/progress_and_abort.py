# SPDX-License-Identifier: BSD-3-Clause
"""Progress, abort and hostile sizes from Python (README, "Reliability").

Reads a real LR-spline file, resamples it with a progress bar on the
terminal (vtkCommand.ProgressEvent), cancels a second run at 30 % (as a
Cancel button would, through AbortExecute), and shows that an absurd request
(100000^3 samples) is refused with an error instead of ending the process.

    pvpython Examples/Python/progress_and_abort.py [file.lr]

Returns (for the tests) a dict with the progress values, the number of
points of the full and the aborted run, and the refusal message.
"""
import os
import sys

from vtkmodules.util.misc import calldata_type
from vtkmodules.util.vtkConstants import VTK_STRING
from vtkmodules.vtkCommonCore import vtkCommand

import splineviz


def main(path):
    reader = splineviz.vtkLRSplineReader()
    reader.SetFileName(path)
    resample = splineviz.vtkLRSplineResampleToImage()
    resample.SetInputConnection(reader.GetOutputPort())
    resample.SetSamplingDimensions(96, 96, 96)

    # A progress bar: the filter reports progress between batches of samples.
    values = []

    def on_progress(caller, event):
        p = caller.GetProgress()
        values.append(p)
        bar = "#" * int(40 * p)
        sys.stdout.write("\rresampling [%-40s] %3d %%" % (bar, 100 * p))
        sys.stdout.flush()

    tag = resample.AddObserver(vtkCommand.ProgressEvent, on_progress)
    resample.Update()
    print()
    full = resample.GetOutput().GetNumberOfPoints()
    print("full run: %d samples, %d progress events" % (full, len(values)))

    # Cancel at 30 %: the run stops at the next batch and the output is empty.
    def cancel(caller, event):
        if caller.GetProgress() > 0.3:
            caller.AbortExecuteOn()

    resample.RemoveObserver(tag)
    tag = resample.AddObserver(vtkCommand.ProgressEvent, cancel)
    resample.Modified()
    resample.Update()
    aborted = resample.GetOutput().GetNumberOfPoints()
    print("cancelled run: %d samples" % aborted)
    resample.RemoveObserver(tag)
    resample.AbortExecuteOff()

    # An absurd request is refused before anything is allocated: an error
    # (here caught by observers, so nothing is printed), the update fails,
    # the output is empty and the process goes on.
    messages = []

    @calldata_type(VTK_STRING)
    def on_error(caller, event, message):
        messages.append(message)

    resample.AddObserver(vtkCommand.ErrorEvent, on_error)
    resample.GetExecutive().AddObserver(vtkCommand.ErrorEvent, on_error)
    resample.SetSamplingDimensions(100000, 100000, 100000)
    ok = resample.GetExecutive().Update()
    refusal = messages[0].strip().splitlines()[-1] if messages else ""
    print("100000^3 samples: update %s, %d points: %s"
          % ("failed" if not ok else "succeeded", resample.GetOutput().GetNumberOfPoints(), refusal))
    return {"progress": values, "full": full, "aborted": aborted, "hostile_ok": ok,
            "refusal": refusal}


if __name__ == "__main__":
    source = os.environ.get("SPLINEVIZ_SOURCE_DIR",
                            os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
    default = os.path.join(source, "Testing", "Data", "External", "cube-3patch-refined.lr")
    main(sys.argv[1] if len(sys.argv) > 1 else default)
