# SPDX-License-Identifier: BSD-3-Clause
"""Diffusion MRI in and out: NIfTI tensors from DIPY, glyphs, fibres, .tck back to nibabel.

    source build/splineviz-env.sh
    pvpython Examples/Python/neuroimaging_io.py [OUTPUT_DIR]

1. DIPY fits diffusion tensors to its small real scan (small_64D, shipped by
   Debian's python3-dipy: 10 x 10 x 10 voxels of 2 mm, an oblique scanner
   affine) and saves them as NIfTI (5D, the NIfTI standard's lower-triangular
   order, as DIPY's own `dipy_fit_dti` does), with the FA beside them.
2. SplineViz's vtkNIfTITensorReader reads them: the image is placed by the
   file's affine (RAS+ mm, the rotation as the image's direction matrix) and
   the tensors are rotated into the same world frame; the FA comes along as a
   companion volume.
3. Superquadric glyphs on the middle slice (vtkExtractVOI), fibres traced by
   vtkTensorLineTracer from every voxel with FA >= 0.3, drawn as ray-cast
   tubes whose radius is the FA: neuroimaging-dipy.png.
4. vtkTractogramWriter writes the fibres as MRtrix .tck with the FA as a .tsf
   file; nibabel reads the .tck back and gets the same points.

Needs DIPY and NiBabel (Debian: python3-dipy, python3-nibabel; installed by
scripts/setup.sh). Writes its files to OUTPUT_DIR (default: the current folder).
"""
import os
import sys

import numpy as np
import nibabel as nib
from dipy.core.gradients import gradient_table
from dipy.data import get_fnames
from dipy.io.gradients import read_bvals_bvecs
from dipy.reconst.dti import TensorModel, lower_triangular

from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkImagingCore import vtkExtractVOI
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

# -- 1. DIPY: fit and save -----------------------------------------------------
dwi, bval, bvec = get_fnames("small_64D")
scan = nib.load(dwi)
bvals, bvecs = read_bvals_bvecs(bval, bvec)
fit = TensorModel(gradient_table(bvals, bvecs)).fit(np.asarray(scan.dataobj, dtype=np.float64))
tensors_file = os.path.join(out_dir, "small_64D_tensors.nii.gz")
fa_file = os.path.join(out_dir, "small_64D_FA.nii.gz")
# X x Y x Z x 1 x 6, XX XY YY XZ YZ ZZ (mm^2/s), in the voxel frame of the b-vectors
nib.save(nib.Nifti1Image(lower_triangular(fit.quadratic_form)[:, :, :, None, :].astype(np.float32),
                         scan.affine), tensors_file)
nib.save(nib.Nifti1Image(np.nan_to_num(fit.fa).astype(np.float32), scan.affine), fa_file)
print("DIPY wrote", tensors_file, "and", fa_file)

# -- 2. SplineViz: read them in world coordinates ---------------------------------
reader = splineviz.vtkNIfTITensorReader()
reader.SetFileName(tensors_file)  # 5D: read in NIfTI order (automatic); 4D FSL files too
reader.AddCompanionFileName(fa_file)  # -> point array "small_64D_FA"
reader.Update()
volume = reader.GetOutput()
print("read %d voxels; origin %s, spacing %s, rotation (direction matrix) applied"
      % (volume.GetNumberOfPoints(), np.round(volume.GetOrigin(), 2), volume.GetSpacing()))

# -- 3. glyphs on a slice, fibres as tubes -------------------------------------
middle = vtkExtractVOI()
middle.SetInputConnection(reader.GetOutputPort())
middle.SetVOI(0, 9, 0, 9, 5, 5)
glyphs = splineviz.vtkSuperquadricGlyphMapper()
glyphs.SetInputConnection(middle.GetOutputPort())
glyphs.SetTensorArray("Tensors")  # VTK order: the default layout, nothing to choose
glyphs.SetScaleMode(glyphs.SCALE_NORMALIZED)
glyphs.SetScaleFactor(0.9)
glyphs.SetGamma(3.0)
glyphs.SetGlyphColorMode(glyphs.COLOR_BY_EIGENVECTOR)
glyph_actor = vtkActor()
glyph_actor.SetMapper(glyphs)

tracer = splineviz.vtkTensorLineTracer()
tracer.SetInputConnection(reader.GetOutputPort())
tracer.SetInputArrayToProcess(0, 0, 0, 0, "Tensors")
tracer.SetSeedMode(tracer.SEEDS_FROM_VOXELS)
tracer.SetSeedFAThreshold(0.3)
tracer.SetStoppingFAThreshold(0.15)
tracer.SetMinimumLength(4.0)
tracer.Update()
fibres = tracer.GetOutput()
print("traced %d fibres, %d points" % (fibres.GetNumberOfLines(), fibres.GetNumberOfPoints()))
tubes = splineviz.vtkRayCastTubeMapper()
tubes.SetInputConnection(tracer.GetOutputPort())
tubes.SetRadiusArray("FractionalAnisotropy")
tubes.SetRadiusScale(0.25)
tubes.SetScalarModeToUsePointFieldData()
tubes.SelectColorArray("DirectionColors")
tubes.SetColorModeToDirectScalars()
tube_actor = vtkActor()
tube_actor.SetMapper(tubes)
tube_actor.GetProperty().SetSpecular(0.3)

renderer = vtkRenderer()
renderer.AddActor(glyph_actor)
renderer.AddActor(tube_actor)
renderer.SetBackground(1, 1, 1)
window = vtkRenderWindow()
window.SetOffScreenRendering(1)
window.SetSize(900, 700)
window.AddRenderer(renderer)
camera = renderer.GetActiveCamera()
center = np.array(volume.GetCenter())
camera.SetFocalPoint(*center)
camera.SetPosition(*(center + [-25, -45, 30]))
camera.SetViewUp(0, 0, 1)
renderer.ResetCamera()
camera.Zoom(1.3)
window.Render()
grab = vtkWindowToImageFilter()
grab.SetInput(window)
grab.ReadFrontBufferOff()
grab.Update()
png = os.path.join(out_dir, "neuroimaging-dipy.png")
writer = vtkPNGWriter()
writer.SetFileName(png)
writer.SetInputConnection(grab.GetOutputPort())
writer.Write()
print("wrote", png)

# -- 4. the fibres to MRtrix .tck (+ .tsf), read back by nibabel --------------------
tck = os.path.join(out_dir, "small_64D_fibres.tck")
tck_writer = splineviz.vtkTractogramWriter()
tck_writer.SetInputConnection(tracer.GetOutputPort())
tck_writer.SetFileName(tck)
tck_writer.AddPointArrayName("FractionalAnisotropy")  # -> small_64D_fibres.FractionalAnisotropy.tsf
tck_writer.Write()
back = nib.streamlines.load(tck)
points = vtk_to_numpy(fibres.GetPoints().GetData())
offsets = vtk_to_numpy(fibres.GetLines().GetOffsetsArray())
conn = vtk_to_numpy(fibres.GetLines().GetConnectivityArray())
difference = max(np.abs(s - points[conn[a:b]]).max()
                 for s, a, b in zip(back.streamlines, offsets[:-1], offsets[1:]))
print("nibabel read %d streamlines back from %s (largest difference %.3g mm)"
      % (len(back.streamlines), tck, difference))
if len(back.streamlines) != fibres.GetNumberOfLines() or difference > 1e-6:
    print("ERROR: the .tck does not hold the fibres")
    sys.exit(1)
