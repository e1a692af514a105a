"""Scene of TestParallelRayCastTubes (run by pvbatch, serially or under
mpiexec): the synthetic fibers, split into pieces across the ranks, drawn as
ray-cast tubes and composited by IceT; saves a screenshot.

    pvbatch ParallelRayCastTubesScene.py OUTPUT.png [by-rank | culling]

(culling: with the ray-cast tubes' occlusion-culling pre-pass.)
"""
import sys

from paraview.simple import *  # noqa: F401,F403

from splineviz_testing import white_view

# The plugin is on PV_PLUGIN_PATH: every rank loads it at start-up.
fibers = SyntheticFibers(Preset=1)  # noqa: F405
view = white_view((500, 400))
display = Show(fibers, view)  # noqa: F405
display.SetRepresentationType("Ray-Cast Tubes")
display.TubeRadiusArray = "Radius"
culling = len(sys.argv) > 2 and sys.argv[2] == "culling"
display.OcclusionCulling = 1 if culling else 0
if len(sys.argv) > 2 and not culling:
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
