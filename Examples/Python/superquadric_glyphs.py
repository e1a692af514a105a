# SPDX-License-Identifier: BSD-3-Clause
"""Superquadric tensor glyphs of a real diffusion MRI scan, in VTK and ParaView.

    source build/splineviz-env.sh
    pvpython Examples/Python/superquadric_glyphs.py [OUTPUT_DIR]

1. Fits diffusion tensors to DIPY's small real scan (small_64D: 10 x 10 x 10
   voxels of 2 mm, 64 gradient directions) with DIPY's TensorModel. DIPY
   stores symmetric tensors as the lower triangle, XX XY YY XZ YZ ZZ: the
   glyphs are told so with the tensor layout (VTK's own order is
   XX YY ZZ XY YZ XZ; a wrong order gives wrong glyphs without any error).
2. VTK: vtkSuperquadricGlyphMapper draws one ray-cast superquadric glyph per
   voxel (Kindlmann's shapes, gamma = 0, 3, 20 as in Hlawitschka et al.'s
   figure 4), colored by the principal direction times FA, hiding voxels
   with FA < 0.15; only the raw tensors are uploaded, so the three pictures
   are three uniform changes.
3. ParaView (when the SplineViz plugin is found through SPLINEVIZ_PLUGIN, as
   set by splineviz-env.sh): the same volume through "Tensor Analysis" (FA,
   eigenvalues, ...) and shown with the "Superquadric Glyphs" representation,
   colored by mean diffusivity.

Writes superquadric-glyphs-*.png to OUTPUT_DIR (default: the current folder).
Needs DIPY and NiBabel (Debian: python3-dipy, installed by scripts/setup.sh).
"""
import os
import sys

import numpy as np

from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import (
    vtkActor,
    vtkRenderer,
    vtkRenderWindow,
    vtkWindowToImageFilter,
)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (OpenGL render window)

import splineviz

out_dir = sys.argv[1] if len(sys.argv) > 1 else "."
os.makedirs(out_dir, exist_ok=True)


def dti_volume():
    """DIPY's small_64D scan with tensors fitted by DIPY, as vtkImageData."""
    import nibabel as nib
    from dipy.core.gradients import gradient_table
    from dipy.data import get_fnames
    from dipy.io.gradients import read_bvals_bvecs
    from dipy.reconst.dti import TensorModel, lower_triangular

    dwi, bval, bvec = get_fnames("small_64D")
    image = nib.load(dwi)
    data = np.asarray(image.dataobj, dtype=np.float64)
    bvals, bvecs = read_bvals_bvecs(bval, bvec)
    fit = TensorModel(gradient_table(bvals, bvecs)).fit(data)
    lower = lower_triangular(fit.quadratic_form)  # XX XY YY XZ YZ ZZ, mm^2/s
    nx, ny, nz = lower.shape[:3]
    volume = vtkImageData()
    volume.SetDimensions(nx, ny, nz)
    volume.SetSpacing(*[float(s) for s in image.header.get_zooms()[:3]])
    # VTK image data is x-fastest: Fortran order of the (x, y, z) arrays
    tensors = numpy_to_vtk(lower.reshape(-1, 6, order="F").copy(), deep=1)
    tensors.SetName("DTI")
    volume.GetPointData().AddArray(tensors)
    fa = numpy_to_vtk(np.nan_to_num(fit.fa).ravel(order="F").copy(), deep=1)
    fa.SetName("DIPY FA")
    volume.GetPointData().AddArray(fa)
    return volume


def save(window, name):
    window.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    grab.Update()
    writer = vtkPNGWriter()
    path = os.path.join(out_dir, name)
    writer.SetFileName(path)
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()
    print("wrote", path)


volume = dti_volume()

# -- VTK: the mapper on the image data --------------------------------------
mapper = splineviz.vtkSuperquadricGlyphMapper()
mapper.SetInputData(volume)
mapper.SetTensorArray("DTI")
mapper.SetTensorLayout(2)  # vtkSplineVizTensorMath::SYMMETRIC_LOWER (NIfTI, DIPY)
mapper.SetScaleMode(mapper.SCALE_NORMALIZED)  # every glyph 2 mm long: shape only
mapper.SetScaleFactor(0.95)
mapper.SetAnisotropyThreshold(0.15)
mapper.SetGlyphColorMode(mapper.COLOR_BY_EIGENVECTOR)
actor = vtkActor()
actor.SetMapper(mapper)
actor.GetProperty().SetSpecular(0.3)
actor.GetProperty().SetSpecularPower(25)
renderer = vtkRenderer()
renderer.AddActor(actor)
renderer.SetBackground(0.08, 0.08, 0.1)
window = vtkRenderWindow()
window.SetOffScreenRendering(1)
window.SetSize(900, 700)
window.AddRenderer(renderer)
camera = renderer.GetActiveCamera()
camera.SetFocalPoint(9, 9, 9)
camera.SetPosition(30, -28, 34)
camera.SetViewUp(0, 0, 1)
renderer.ResetCamera()
camera.Zoom(1.05)
for gamma in (0.0, 3.0, 20.0):
    mapper.SetGamma(gamma)
    save(window, "superquadric-glyphs-vtk-gamma%d.png" % gamma)
print("%d glyphs, %d bytes per glyph on the GPU, tensors uploaded %d time(s)"
      % (mapper.GetNumberOfGlyphs(), mapper.GetGPUBytesPerGlyph(), mapper.GetUploadCount()))

# -- ParaView: Tensor Analysis + the "Superquadric Glyphs" representation ----
plugin = os.environ.get("SPLINEVIZ_PLUGIN")
if not plugin or not os.path.exists(plugin):
    print("SPLINEVIZ_PLUGIN not set: skipping the ParaView part")
    sys.exit(0)

from paraview import simple  # noqa: E402
from splineviz.plugin import load_plugin  # noqa: E402

load_plugin(globals(), plugin)  # unless ParaView loaded it at start-up
source = simple.TrivialProducer()
source.GetClientSideObject().SetOutput(volume)
analysis = simple.TensorAnalysis(Input=source)
analysis.Tensors = ["POINTS", "DTI"]
analysis.TensorLayout = 2  # NIfTI / DIPY order
view = simple.CreateRenderView()
view.ViewSize = [900, 700]
view.OrientationAxesVisibility = 0
display = simple.Show(analysis, view)
display.SetRepresentationType("Superquadric Glyphs")
display.SuperquadricTensors = "DTI"
display.SuperquadricTensorLayout = 2
display.SuperquadricScaleMode = 1  # Normalized
display.SuperquadricScaleFactor = 0.95
display.SuperquadricAnisotropyThreshold = 0.15
display.SuperquadricColorMode = 1  # the Coloring array through its color map
simple.ColorBy(display, ("POINTS", "MeanDiffusivity"))
display.RescaleTransferFunctionToDataRange(True)
view.CameraFocalPoint = [9, 9, 9]
view.CameraPosition = [30, -28, 34]
view.CameraViewUp = [0, 0, 1]
simple.ResetCamera(view)
path = os.path.join(out_dir, "superquadric-glyphs-paraview.png")
simple.SaveScreenshot(path, view, ImageResolution=[900, 700])
print("wrote", path)
# Release the ParaView view here rather than at the interpreter's exit: when
# this script ran inside another one (demo.py run by a test), pvpython
# crashed at exit (SIGSEGV in Xlib's error handler while the view's window
# was made current during ParaView's teardown).
simple.Delete(view)
del view, display
