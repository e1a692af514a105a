# SPDX-License-Identifier: BSD-3-Clause
"""ParaView demo state: the tractography workflow on a real diffusion scan.
Fibers are traced, dissected with two regions, colored by direction and
drawn over an FA slice.

    source build/splineviz-env.sh
    pvpython Examples/Python/tractography_state.py [output.png]
    (or in the ParaView GUI: View > Python Shell > Run Script)

Steps:
1. Read DIPY's small real DTI scan (Testing/Data/DIPY/small_64D_dti.vti,
   tensors fitted by DIPY).
2. Trace fibers from every voxel with FA >= 0.25 (Tensor Line Tracer).
3. Dissect them with Select Streamlines, using two regions:
   - the fibers must pass through a sphere in the middle of the scan
     (Include);
   - they must not touch a box over its upper part (Exclude).
   Mark Streamlines keeps every fiber and adds the cell array "Selected".
4. Draw the fibers with the "Stylized Lines" representation:
   - Visibility Array "Selected" shows only the dissected fibers; change a
     region and the next frame shows the new selection;
   - Direction Coloring colors them RGB = |tangent| (red left-right, green
     front-back, blue up-down);
   - the view is a "Render View (Line Depth Cues)": ambient occlusion
     darkens the fibers where others lie close around them, and
     depth-dependent halos separate fibers that cross far apart in depth
     while a tight bundle stays one (they replace the stylized lines' own
     halos, whose Halo Width stays 0).
5. Draw the middle axial slice of the fractional anisotropy (Tensor
   Analysis) in grey underneath.
"""
import os
import sys

from paraview.simple import *  # noqa: F401,F403

# Loads SplineVizPlugin unless ParaView did at start-up (PV_PLUGIN_PATH).
from splineviz.plugin import load_plugin

load_plugin(globals())

here = os.path.dirname(os.path.abspath(__file__))
data = os.path.join(here, "..", "..", "Testing", "Data", "DIPY", "small_64D_dti.vti")
dti = OpenDataFile(data)  # noqa: F405
dti.UpdatePipeline()
bounds = dti.GetDataInformation().GetBounds()
center = [0.5 * (bounds[2 * k] + bounds[2 * k + 1]) for k in range(3)]
size = [bounds[2 * k + 1] - bounds[2 * k] for k in range(3)]

fibers = TensorLineTracer(Input=dti)  # noqa: F405
fibers.Tensors = ["POINTS", "DTI"]
fibers.TensorLayout = "XX XY YY XZ YZ ZZ (NIfTI, DIPY)"
fibers.Seeding = "Voxels above the seed FA threshold"
fibers.SeedFAThreshold = 0.25
fibers.StoppingFAThreshold = 0.15
fibers.MaximumAngle = 45.0
fibers.IntegrationStep = 0.25  # voxels
fibers.MinimumLength = 4.0  # mm

# Two regions: through a sphere in the middle, not into a box over the top.
dissection = SelectStreamlines(Input=fibers)  # noqa: F405
dissection.SphereRole = "Include"
dissection.SphereCenter = center
dissection.SphereRadius = 0.15 * max(size)
dissection.BoxRole = "Exclude"
dissection.BoxPosition = [bounds[0], bounds[2], center[2] + 0.3 * size[2]]
dissection.BoxLength = [size[0], size[1], 0.2 * size[2]]
dissection.OutputMode = "Mark Streamlines"

# FA of the tensors; its middle axial slice is drawn under the fibers.
analysis = TensorAnalysis(Input=dti)  # noqa: F405
analysis.Tensors = ["POINTS", "DTI"]
analysis.TensorLayout = "XX XY YY XZ YZ ZZ (NIfTI, DIPY)"

# A render view with line depth cues (vtkLineAmbientOcclusionPass).
view = CreateView("RenderViewWithLineDepthCues")  # noqa: F405
view.AmbientOcclusion = 1
view.DepthHalos = 1
view.ViewSize = [900, 700]
view.OrientationAxesVisibility = 0
view.UseColorPaletteForBackground = 0
view.Background = [1.0, 1.0, 1.0]

lines = Show(dissection, view)  # noqa: F405
lines.SetRepresentationType("Stylized Lines")
lines.DirectionColoring = 1
lines.VisibilityArray = "Selected"
lines.TubeRadius = 0.012 * max(size)

fa = Show(analysis, view)  # noqa: F405
fa.SetRepresentationType("Slice")
fa.SliceMode = "XY Plane"
ColorBy(fa, ("POINTS", "FractionalAnisotropy"))  # noqa: F405
fa_colors = GetColorTransferFunction("FractionalAnisotropy")  # noqa: F405
fa_colors.ApplyPreset("Grayscale", True)
fa_colors.RescaleTransferFunction(0.0, 1.0)
fa.SetScalarBarVisibility(view, False)

view.CameraFocalPoint = center
view.CameraPosition = [center[0] + 1.6 * size[0], center[1] - 2.2 * size[1],
                       center[2] + 1.8 * size[2]]
view.CameraViewUp = [0, 0, 1]
ResetCamera(view)  # noqa: F405
view.CameraPosition = [center[k] + 0.8 * (view.CameraPosition[k] - center[k]) for k in range(3)]
Render(view)  # noqa: F405
print("fibers traced: %d" % fibers.GetDataInformation().GetNumberOfCells())
if len(sys.argv) > 1:
    SaveScreenshot(sys.argv[1], view, ImageResolution=[900, 700])  # noqa: F405
    print("wrote", sys.argv[1])
