# SPDX-License-Identifier: BSD-3-Clause
"""pvbatch: the plugin's Tensor Analysis filter on a DIPY-ordered tensor
volume (made by a Programmable Source), checked against numpy's eigvalsh;
a wrong layout choice changes the results; a 3-component array is refused."""
import sys

import numpy as np
from paraview import servermanager
from paraview.simple import *  # noqa: F401,F403
from vtkmodules.util.numpy_support import vtk_to_numpy

LoadPlugin(sys.argv[1], remote=False, ns=globals())

source = ProgrammableSource()  # noqa: F405
source.OutputDataSetType = "vtkImageData"
source.Script = """
import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk
rng = np.random.default_rng(3)
n = 5 * 4 * 3
out = self.GetOutput()
out.SetDimensions(5, 4, 3)
a = rng.normal(size=(n, 3, 3))
t = a @ a.transpose(0, 2, 1)          # symmetric positive definite
lower = np.stack([t[:, 0, 0], t[:, 1, 0], t[:, 1, 1], t[:, 2, 0], t[:, 2, 1], t[:, 2, 2]], 1)
arr = numpy_to_vtk(lower.copy(), deep=1)
arr.SetName("DTI")
out.GetPointData().AddArray(arr)
# the same tensors in FSL dtifit's documented order Dxx Dxy Dxz Dyy Dyz Dzz
upper = np.stack([t[:, 0, 0], t[:, 0, 1], t[:, 0, 2], t[:, 1, 1], t[:, 1, 2], t[:, 2, 2]], 1)
arr = numpy_to_vtk(upper.copy(), deep=1)
arr.SetName("FSL")
out.GetPointData().AddArray(arr)
"""
source.ScriptRequestInformation = """
self.GetExecutive().GetOutputInformation(0).Set(
    self.GetExecutive().WHOLE_EXTENT(), 0, 4, 0, 3, 0, 2)
"""

analysis = TensorAnalysis(Input=source)  # noqa: F405
analysis.Tensors = ["POINTS", "DTI"]
analysis.TensorLayout = 2  # NIfTI / DIPY order
analysis.ComputeAllEigenvectors = 1
analysis.UpdatePipeline()
data = servermanager.Fetch(analysis)
pd = data.GetPointData()
for name in ("Eigenvalues", "Eigenvector1", "Eigenvector2", "Eigenvector3",
             "FractionalAnisotropy", "MeanDiffusivity", "LinearAnisotropy",
             "PlanarAnisotropy", "SphericalAnisotropy"):
    if pd.GetArray(name) is None:
        print("ERROR: missing output array", name)
        sys.exit(1)

lower = vtk_to_numpy(pd.GetArray("DTI"))
t = np.zeros((lower.shape[0], 3, 3))
for k, (i, j) in enumerate([(0, 0), (1, 0), (1, 1), (2, 0), (2, 1), (2, 2)]):
    t[:, i, j] = lower[:, k]
    t[:, j, i] = lower[:, k]
ref = np.linalg.eigvalsh(t)[:, ::-1]
got = vtk_to_numpy(pd.GetArray("Eigenvalues"))
err = np.abs(got - ref).max() / np.abs(ref).max()
print("eigenvalues vs numpy: max relative error", err)
if err > 1e-12:
    print("ERROR: eigenvalues differ from numpy")
    sys.exit(1)
l1, l2, l3 = ref[:, 0], ref[:, 1], ref[:, 2]
md = ref.mean(1)
fa = np.sqrt(1.5 * ((ref - md[:, None]) ** 2).sum(1) / (ref ** 2).sum(1))
s = l1 + l2 + l3
checks = {
    "FractionalAnisotropy": fa,
    "MeanDiffusivity": md,
    "LinearAnisotropy": (l1 - l2) / s,
    "PlanarAnisotropy": 2 * (l2 - l3) / s,
    "SphericalAnisotropy": 3 * l3 / s,
}
for name, expected in checks.items():
    e = np.abs(vtk_to_numpy(pd.GetArray(name)) - expected).max()
    if e > 1e-12:
        print("ERROR:", name, "differs from numpy by", e)
        sys.exit(1)
# T e1 = l1 e1
e1 = vtk_to_numpy(pd.GetArray("Eigenvector1"))
res = np.abs(np.einsum("nij,nj->ni", t, e1) - l1[:, None] * e1).max()
if res > 1e-12 * np.abs(ref).max():
    print("ERROR: Eigenvector1 residual", res)
    sys.exit(1)

# The VTK order on DIPY data gives other eigenvalues.
analysis.TensorLayout = 1
analysis.UpdatePipeline()
wrong = vtk_to_numpy(servermanager.Fetch(analysis).GetPointData().GetArray("Eigenvalues"))
if np.abs(wrong - ref).max() < 1e-3:
    print("ERROR: the layout property has no effect")
    sys.exit(1)

# The menus name the layouts after the tools that write them: NIfTI's
# SYMMATRIX and DIPY the lower triangle, FSL's dtifit the upper one; the same
# labels in the Tensor Analysis, Tensor Line Tracer and glyph menus.
def layout_entries(proxy, name):
    domain = proxy.GetProperty(name).SMProperty.GetDomain("enum")
    return {domain.GetEntryValue(i): domain.GetEntryText(i) for i in range(domain.GetNumberOfEntries())}


expected_entries = {1: "XX YY ZZ XY YZ XZ (VTK, ParaView)", 2: "XX XY YY XZ YZ ZZ (NIfTI, DIPY)",
                    3: "XX XY XZ YY YZ ZZ (FSL, MFEM)"}
tracer = TensorLineTracer(Input=analysis)  # noqa: F405
glyphs = Show(analysis)  # noqa: F405
for proxy, name in ((analysis, "TensorLayout"), (tracer, "TensorLayout"),
                    (glyphs, "SuperquadricTensorLayout")):
    entries = layout_entries(proxy, name)
    if entries != expected_entries:
        print("ERROR: %s layout menu %s, expected %s" % (name, entries, expected_entries))
        sys.exit(1)

# The same tensors written in FSL's order, read with the FSL entry, give the
# same eigenvalues; read as NIfTI/DIPY order they do not.
analysis.Tensors = ["POINTS", "FSL"]
analysis.TensorLayout = "XX XY XZ YY YZ ZZ (FSL, MFEM)"
analysis.UpdatePipeline()
fsl = vtk_to_numpy(servermanager.Fetch(analysis).GetPointData().GetArray("Eigenvalues"))
err = np.abs(fsl - ref).max() / np.abs(ref).max()
print("FSL order with the FSL layout: max relative eigenvalue error", err)
if err > 1e-12:
    print("ERROR: FSL-ordered tensors read with the FSL layout differ")
    sys.exit(1)
analysis.TensorLayout = "XX XY YY XZ YZ ZZ (NIfTI, DIPY)"
analysis.UpdatePipeline()
wrong = vtk_to_numpy(servermanager.Fetch(analysis).GetPointData().GetArray("Eigenvalues"))
if np.abs(wrong - ref).max() < 1e-3:
    print("ERROR: FSL-ordered tensors read as NIfTI order give the right eigenvalues")
    sys.exit(1)
print("Tensor Analysis OK")
