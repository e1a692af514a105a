# SPDX-License-Identifier: BSD-3-Clause
"""The tensor analysis on real diffusion MRI data against DIPY (an
independent implementation): DIPY fits tensors to its small_64D scan and
computes FA, MD and eigenvalues; vtkTensorAnalysisFilter reads DIPY's
lower-triangular tensors with the SYMMETRIC_LOWER layout and must give the
same values. Reading them in VTK order must not. Skipped without DIPY."""
import sys

import numpy as np

try:
    import nibabel as nib
    from dipy.core.gradients import gradient_table
    from dipy.data import get_fnames
    from dipy.io.gradients import read_bvals_bvecs
    from dipy.reconst.dti import TensorModel, lower_triangular
except ImportError as error:
    print("DIPY not available, skipped:", error)
    sys.exit(0)

from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkDataObject, vtkImageData

from splineviz import vtkTensorAnalysisFilter

dwi, bval, bvec = get_fnames("small_64D")
data = np.asarray(nib.load(dwi).dataobj, dtype=np.float64)
bvals, bvecs = read_bvals_bvecs(bval, bvec)
fit = TensorModel(gradient_table(bvals, bvecs)).fit(data)
lower = lower_triangular(fit.quadratic_form)
nx, ny, nz = lower.shape[:3]

image = vtkImageData()
image.SetDimensions(nx, ny, nz)
array = numpy_to_vtk(lower.reshape(-1, 6, order="F").copy(), deep=1)
array.SetName("DTI")
image.GetPointData().AddArray(array)


def analyse(layout):
    f = vtkTensorAnalysisFilter()
    f.SetInputData(image)
    f.SetInputArrayToProcess(0, 0, 0, vtkDataObject.FIELD_ASSOCIATION_POINTS, "DTI")
    f.SetTensorLayout(layout)
    f.Update()
    pd = f.GetOutput().GetPointData()
    return {name: vtk_to_numpy(pd.GetArray(name))
            for name in ("Eigenvalues", "FractionalAnisotropy", "MeanDiffusivity")}


ours = analyse(2)  # SYMMETRIC_LOWER
fa_ref = np.nan_to_num(fit.fa).ravel(order="F")
md_ref = fit.md.ravel(order="F")
ev_ref = fit.evals.reshape(-1, 3, order="F")  # DIPY sorts descending
scale = np.abs(ev_ref).max()
errors = {
    "FA": np.abs(ours["FractionalAnisotropy"] - fa_ref).max(),
    "MD": np.abs(ours["MeanDiffusivity"] - md_ref).max() / scale,
    "eigenvalues": np.abs(ours["Eigenvalues"] - ev_ref).max() / scale,
}
print("%d voxels, FA range %.3f..%.3f; max differences to DIPY:" % (len(fa_ref), fa_ref.min(),
      fa_ref.max()), errors)
for name, e in errors.items():
    if not e < 1e-10:
        print("ERROR:", name, "differs from DIPY by", e)
        sys.exit(1)
if fa_ref.max() < 0.3:
    print("ERROR: the scan should contain anisotropic voxels")
    sys.exit(1)
wrong = analyse(1)  # VTK order on DIPY data
if np.abs(wrong["FractionalAnisotropy"] - fa_ref).max() < 0.05:
    print("ERROR: the wrong layout gives DIPY's FA too")
    sys.exit(1)
print("tensor analysis agrees with DIPY")
