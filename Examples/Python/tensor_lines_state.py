# SPDX-License-Identifier: BSD-3-Clause
"""ParaView demo state: fiber tracking on a real diffusion scan, the fibers
as tubes and the tensors as superquadric glyphs on a slice.

    source build/splineviz-env.sh
    pvpython Examples/Python/tensor_lines_state.py [output.png]
    (or in the ParaView GUI: View > Python Shell > Run Script)

Reads DIPY's small real DTI scan (Testing/Data/DIPY/small_64D_dti.vti,
tensors fitted by DIPY, lower-triangular layout; see its PROVENANCE.md),
traces fibers from every voxel with FA >= 0.3 with the Tensor Line Tracer
and shows them with the SplineViz "Ray-Cast Tubes" representation (radius
from the fractional anisotropy, the usual RGB direction colors), or with
ParaView's Tube filter when that representation is not available. The
middle axial slice of the tensors is shown with the "Superquadric Glyphs"
representation when the plugin has it (colored by the principal direction),
otherwise colored by the Tensor Analysis filter's fractional anisotropy.
"""
import os
import sys

from paraview.simple import *  # noqa: F401,F403

try:
    # Loads SplineVizPlugin unless ParaView did at start-up (PV_PLUGIN_PATH).
    from splineviz.plugin import load_plugin

    load_plugin(globals())
except (ImportError, RuntimeError) as error:
    print("SplineViz plugin not loaded (%s): ParaView's own filters only" % error)

here = os.path.dirname(os.path.abspath(__file__))
data = os.path.join(here, "..", "..", "Testing", "Data", "DIPY", "small_64D_dti.vti")
dti = OpenDataFile(data)  # noqa: F405

fibers = TensorLineTracer(Input=dti)  # noqa: F405
fibers.Tensors = ["POINTS", "DTI"]
fibers.TensorLayout = "XX XY YY XZ YZ ZZ (NIfTI, DIPY)"
fibers.Seeding = "Voxels above the seed FA threshold"
fibers.SeedFAThreshold = 0.3
fibers.StoppingFAThreshold = 0.15
fibers.MaximumAngle = 45.0
fibers.IntegrationStep = 0.25  # voxels: 0.5 mm
fibers.MinimumLength = 4.0  # mm

# The middle axial slice of the tensor volume.
tensor_slice = ExtractSubset(Input=dti)  # noqa: F405
tensor_slice.VOI = [0, 9, 0, 9, 4, 4]

view = CreateRenderView()  # noqa: F405
view.ViewSize = [900, 700]
view.OrientationAxesVisibility = 0
view.UseColorPaletteForBackground = 0
view.Background = [0.08, 0.08, 0.1]

lines = Show(fibers, view)  # noqa: F405
representations = lines.GetProperty("Representation").Available
if "Ray-Cast Tubes" in representations:
    lines.SetRepresentationType("Ray-Cast Tubes")
    lines.TubeRadiusArray = "FractionalAnisotropy"
    lines.TubeRadiusScale = 0.15
    shown = lines
    print("fibers: Ray-Cast Tubes")
else:
    Hide(fibers, view)  # noqa: F405
    tubes = Tube(Input=fibers)  # noqa: F405
    tubes.Scalars = ["POINTS", "FractionalAnisotropy"]
    tubes.VaryRadius = "By Scalar"
    tubes.Radius = 0.03
    tubes.RadiusFactor = 4.0
    tubes.NumberofSides = 12
    shown = Show(tubes, view)  # noqa: F405
    print("fibers: Tube filter (the Ray-Cast Tubes representation is not available)")
ColorBy(shown, ("POINTS", "DirectionColors"))  # noqa: F405
shown.MapScalars = 0  # RGB = |principal direction|

glyph_display = Show(tensor_slice, view)  # noqa: F405
if "Superquadric Glyphs" in glyph_display.GetProperty("Representation").Available:
    glyph_display.SetRepresentationType("Superquadric Glyphs")
    glyph_display.SuperquadricTensors = "DTI"
    glyph_display.SuperquadricTensorLayout = 2  # NIfTI / DIPY order
    glyph_display.SuperquadricScaleMode = 1  # Normalized: shape only
    glyph_display.SuperquadricScaleFactor = 0.95
    glyph_display.SuperquadricGamma = 3.0
    glyph_display.SuperquadricColorMode = 0  # principal direction x FA
    print("tensors: Superquadric Glyphs")
else:
    # Fallback: the slice colored by the tensor analysis (FA).
    Hide(tensor_slice, view)  # noqa: F405
    analysis = TensorAnalysis(Input=tensor_slice)  # noqa: F405
    analysis.Tensors = ["POINTS", "DTI"]
    analysis.TensorLayout = "XX XY YY XZ YZ ZZ (NIfTI, DIPY)"
    glyph_display = Show(analysis, view)  # noqa: F405
    glyph_display.SetRepresentationType("Surface")
    ColorBy(glyph_display, ("POINTS", "FractionalAnisotropy"))  # noqa: F405
    glyph_display.LookupTable = GetColorTransferFunction("FractionalAnisotropy")  # noqa: F405
    glyph_display.LookupTable.ApplyPreset("Grayscale", True)
    glyph_display.LookupTable.RescaleTransferFunction(0.0, 1.0)
    print("tensors: Tensor Analysis coloring (the Superquadric Glyphs representation is not "
          "available)")

view.CameraPosition = [40, -30, 40]
view.CameraFocalPoint = [9, 9, 9]
view.CameraViewUp = [0, 0, 1]
ResetCamera(view)  # noqa: F405
Render(view)  # noqa: F405
if len(sys.argv) > 1:
    SaveScreenshot(sys.argv[1], view, ImageResolution=[900, 700])  # noqa: F405
    print("wrote", sys.argv[1])
