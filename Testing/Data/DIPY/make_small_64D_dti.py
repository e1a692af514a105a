"""Fits diffusion tensors to DIPY's small real DWI volume `small_64D` and
writes them as a VTK image (small_64D_dti.vti next to this script).

    pvpython Testing/Data/DIPY/make_small_64D_dti.py

Needs DIPY (Debian: python3-dipy, which also ships the data) and ParaView's
VTK. Run once; the output is kept in the repository (see PROVENANCE.md).
"""
import os

import numpy as np
import dipy
import dipy.reconst.dti as dti
from dipy.core.gradients import gradient_table
from dipy.data import get_fnames
from dipy.io.gradients import read_bvals_bvecs
import nibabel as nib

from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkStringArray
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkIOXML import vtkXMLImageDataWriter

fimg, fbval, fbvec = get_fnames("small_64D")
img = nib.load(fimg)
data = img.get_fdata()
bvals, bvecs = read_bvals_bvecs(fbval, fbvec)
gtab = gradient_table(bvals, bvecs)
fit = dti.TensorModel(gtab, fit_method="WLS").fit(data)

nx, ny, nz = data.shape[:3]
spacing = [float(s) for s in img.header.get_zooms()[:3]]


def flat(a):
    """(nx, ny, nz, ...) -> VTK point order (x fastest)."""
    a = np.asarray(a)
    return a.reshape((nx * ny * nz,) + a.shape[3:], order="F")


out = vtkImageData()
out.SetDimensions(nx, ny, nz)
out.SetSpacing(spacing)
out.SetOrigin(0.0, 0.0, 0.0)


def add(name, values, dtype=np.float32):
    arr = numpy_to_vtk(np.ascontiguousarray(flat(values), dtype=dtype), deep=1)
    arr.SetName(name)
    out.GetPointData().AddArray(arr)


# DIPY's lower-triangular order Dxx, Dxy, Dyy, Dxz, Dyz, Dzz (mm^2/s)
add("DTI", fit.lower_triangular())
add("FA_DIPY", fit.fa)
add("MD_DIPY", fit.md)
add("Evec1_DIPY", fit.evecs[..., :, 0])
add("S0", data[..., bvals < 50].mean(axis=-1))

affine = vtkDoubleArray()
affine.SetName("NIfTIAffine")
affine.SetNumberOfComponents(16)
affine.InsertNextTuple(img.affine.ravel().tolist())
out.GetFieldData().AddArray(affine)
note = vtkStringArray()
note.SetName("Provenance")
note.InsertNextValue(
    "DIPY %s small_64D (dipy/data/files/small_64D.nii, .bval, .bvec), tensors fitted "
    "with dipy.reconst.dti.TensorModel (WLS); layout XX XY YY XZ YZ ZZ; voxel axes, "
    "origin 0, spacing = voxel size (mm); scanner affine in NIfTIAffine" % dipy.__version__)
out.GetFieldData().AddArray(note)

path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "small_64D_dti.vti")
writer = vtkXMLImageDataWriter()
writer.SetFileName(path)
writer.SetInputData(out)
writer.SetDataModeToAppended()
writer.SetCompressorTypeToZLib()
writer.Write()
print("wrote", path, os.path.getsize(path), "bytes; FA range", float(fit.fa.min()),
      float(fit.fa.max()), "; voxels with FA >= 0.3:", int((fit.fa >= 0.3).sum()))
