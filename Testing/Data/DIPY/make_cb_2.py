"""Writes DIPY's real fibre bundle `cb_2` (116 streamlines of a cingulum
bundle) as VTK polylines (cb_2.vtp next to this script), for the tube
fidelity test that C++ runs without numpy.

    pvpython Testing/Data/DIPY/make_cb_2.py

Needs DIPY (Debian: python3-dipy, which ships the data) and ParaView's VTK.
Run once; the output is kept in the repository (see PROVENANCE.md).
"""
import os

import numpy as np
from dipy.data import get_fnames

from vtkmodules.util.numpy_support import numpy_to_vtk, numpy_to_vtkIdTypeArray
from vtkmodules.vtkCommonCore import vtkPoints, vtkStringArray
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter

cb = np.load(os.path.join(os.path.dirname(get_fnames("small_64D")[0]), "cb_2.npz"))
points = np.ascontiguousarray(cb["points"], dtype=np.float32)
ends = np.asarray(cb["offsets"], dtype=np.int64)
starts = np.r_[0, ends[:-1]]

vtk_points = vtkPoints()
vtk_points.SetData(numpy_to_vtk(points, deep=True))
cells = vtkCellArray()
cells.SetData(numpy_to_vtkIdTypeArray(np.r_[0, ends], deep=True),
              numpy_to_vtkIdTypeArray(np.arange(len(points), dtype=np.int64), deep=True))
pd = vtkPolyData()
pd.SetPoints(vtk_points)
pd.SetLines(cells)
note = vtkStringArray()
note.SetName("Provenance")
note.InsertNextValue("DIPY cb_2.npz ('points', 'offsets'): %d streamlines, %d points, mm; "
                     "see Testing/Data/DIPY/PROVENANCE.md" % (len(ends), len(points)))
pd.GetFieldData().AddArray(note)
assert all(e > s + 1 for s, e in zip(starts, ends))

writer = vtkXMLPolyDataWriter()
writer.SetInputData(pd)
writer.SetDataModeToBinary()
writer.SetCompressorTypeToZLib()
writer.SetFileName(os.path.join(os.path.dirname(os.path.abspath(__file__)), "cb_2.vtp"))
writer.Write()
print("wrote %s: %d streamlines, %d points" % (writer.GetFileName(), len(ends), len(points)))
