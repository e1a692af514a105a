# SPDX-License-Identifier: BSD-3-Clause
"""Scene of TestParallelRayCastTubes (run by pvbatch, serially or under
mpiexec): the synthetic fibers, split into pieces across the ranks, drawn as
ray-cast tubes and composited by IceT; saves a screenshot.

    pvbatch ParallelRayCastTubesScene.py OUTPUT.png [by-rank | culling | automatic]

(culling: with the line renderers' occlusion culling; automatic: the
automatic radius, taken from the bounds of the whole data set on every
rank, instead of the radius array.)
"""
import sys

from paraview.simple import *  # noqa: F401,F403

from splineviz_testing import white_view

# The plugin is on PV_PLUGIN_PATH: every rank loads it at start-up.
fibers = SyntheticFibers(Preset=1)  # noqa: F405
if len(sys.argv) > 2 and sys.argv[2] == "automatic":
    # A line behind the camera, on the first piece only: it triples the
    # data's diagonal, so a rank taking the automatic radius from its own
    # piece would draw thinner tubes than the serial run.
    far = ProgrammableSource(OutputDataSetType="vtkPolyData")  # noqa: F405
    far.Script = """
from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline as sddp
piece = self.GetOutputInformation(0).Get(sddp.UPDATE_PIECE_NUMBER())
if piece == 0:
    from vtkmodules.vtkFiltersSources import vtkLineSource
    line = vtkLineSource()
    line.SetPoint1(0.3, 0.2, 3.0)
    line.SetPoint2(0.3, 0.2, 4.5)
    line.Update()
    self.GetOutput().ShallowCopy(line.GetOutput())
"""
    fibers = AppendDatasets(Input=[fibers, far])  # noqa: F405
    fibers = ExtractSurface(Input=fibers)  # noqa: F405
view = white_view((500, 400))
display = Show(fibers, view)  # noqa: F405
display.SetRepresentationType("Ray-Cast Tubes")
mode = sys.argv[2] if len(sys.argv) > 2 else ""
if mode != "automatic":
    display.TubeRadiusArray = "Radius"
culling = mode == "culling"
display.OcclusionCulling = 1 if culling else 0
if mode == "automatic":
    # One color: the appended line has no Scalar array, so the serial append
    # drops it while the second rank (without the line) keeps it.
    ColorBy(display, ("POINTS", None))  # noqa: F405
elif mode == "by-rank":
    ColorBy(display, ("POINTS", "vtkProcessId"))  # noqa: F405
else:
    ColorBy(display, ("POINTS", "Scalar"))  # noqa: F405
    GetColorTransferFunction("Scalar").RescaleTransferFunction(0.0, 1.0)  # noqa: F405
Render(view)  # noqa: F405
# The same camera whatever the number of ranks.
view.CameraPosition = [0.3, 0.2, 2.0]
view.CameraFocalPoint = [0, 0, 0]
view.CameraViewUp = [0, 1, 0]
view.CameraViewAngle = 30
Render(view)  # noqa: F405
SaveScreenshot(sys.argv[1], view, ImageResolution=[500, 400])  # noqa: F405
