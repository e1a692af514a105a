"""pvbatch: load the SplineViz plugin and use its sources in a ParaView
pipeline, render and check the image shows them."""
import os
import sys

from paraview.simple import *  # noqa: F401,F403

plugin = sys.argv[1]
LoadPlugin(plugin, remote=False, ns=globals())

fibers = SyntheticFibers(Preset=1)  # noqa: F405
fibers.UpdatePipeline()
info = fibers.GetDataInformation()
assert info.GetNumberOfCells() == 241, info.GetNumberOfCells()
assert info.GetNumberOfPoints() == 3771, info.GetNumberOfPoints()

view = CreateRenderView()  # noqa: F405
view.ViewSize = [400, 300]
view.UseColorPaletteForBackground = 0
view.Background = [1, 1, 1]
view.OrientationAxesVisibility = 0
display = Show(fibers, view)  # noqa: F405
ColorBy(display, ("POINTS", "Scalar"))  # noqa: F405
ResetCamera(view)  # noqa: F405
Render(view)  # noqa: F405

out_dir = os.environ.get("SPLINEVIZ_TEST_OUTPUT", ".")
os.makedirs(out_dir, exist_ok=True)
png = os.path.join(out_dir, "TestPluginSources.png")
SaveScreenshot(png, view, ImageResolution=[400, 300])  # noqa: F405

from paraview.vtk.vtkIOImage import vtkPNGReader  # noqa: E402

reader = vtkPNGReader()
reader.SetFileName(png)
reader.Update()
img = reader.GetOutput()
scalars = img.GetPointData().GetScalars()
n = img.GetNumberOfPoints()
covered = sum(1 for i in range(0, n, 7) if scalars.GetTuple3(i) != (255.0, 255.0, 255.0))
fraction = covered / float(len(range(0, n, 7)))
print("fraction of non-background pixels:", fraction)
if fraction < 0.02:
    print("ERROR: the plugin's fibers did not render")
    sys.exit(1)
