# SPDX-License-Identifier: BSD-3-Clause
"""pvbatch: IFEM results in ParaView ("IFEM HDF5 Results").

- The reader factory opens IFEM .hdf5 files with the IFEM reader and does
  not claim an HDF5 file of another layout.
- Time: a state (pipeline, view, animation) steps through the 11 levels of
  Cyl2D-VMSFSI-weak.hdf5; every step shows the level whose time IFEM wrote
  (h5py reads the same timeinfo), the fields and the moving mesh change from
  step to step, and after saving and loading the state the same times and
  data come back.
- Pictures: the moving-mesh flow (g2 surfaces, colored by u_x), the LR
  surface Square-LR (Bezier quadrilaterals colored by the Poisson solution)
  and the rational NURBS shell are drawn coloured (many distinct colours,
  covering the view) and their images written for inspection.
"""
import os
import sys

import h5py
import numpy as np

from paraview.simple import *  # noqa: F401,F403
from paraview import servermanager  # noqa: E402
from splineviz_testing import output_dir, white_view
from vtkmodules.vtkCommonDataModel import vtkMultiBlockDataSet

plugin = sys.argv[1]
LoadPlugin(plugin, remote=False, ns=globals())

data = os.path.join(os.environ["SPLINEVIZ_SOURCE_DIR"], "Testing", "Data", "External", "ifem")
out_dir = output_dir()
from splineviz_testing import Checker  # noqa: E402

checker = Checker()


fail = checker.fail


def leaves(obj):
    """The patch grids of the reader's output (basis blocks of patch blocks)."""
    grids = []
    for b in range(obj.GetNumberOfBlocks()):
        basis = obj.GetBlock(b)
        for p in range(basis.GetNumberOfBlocks()):
            grids.append((obj.GetMetaData(b).Get(vtkMultiBlockDataSet.NAME()), basis.GetBlock(p)))
    return grids


def field_number(grid, name):
    a = grid.GetFieldData().GetAbstractArray(name)
    return a.GetValue(0) if a is not None else None


def colours(image_path):
    from vtkmodules.vtkIOImage import vtkPNGReader
    from vtkmodules.util.numpy_support import vtk_to_numpy

    r = vtkPNGReader()
    r.SetFileName(image_path)
    r.Update()
    img = vtk_to_numpy(r.GetOutput().GetPointData().GetScalars())[:, :3].astype(int)
    drawn = np.any(img < 250, axis=1)
    saturated = (img.max(axis=1) - img.min(axis=1)) > 40
    distinct = len({tuple(c // 16) for c in img[drawn & saturated]})
    return drawn.mean(), (drawn & saturated).mean(), distinct


def picture(source, array, name, zoom=None):
    """Draw `source` coloured by `array` (zoom: focal point x, y and half height)."""
    view = white_view((500, 400))
    display = Show(source, view)  # noqa: F405
    ColorBy(display, ("POINTS", array))  # noqa: F405
    display.RescaleTransferFunctionToDataRange(False, True)
    Render(view)  # noqa: F405 (the first render resets the camera)
    if not zoom:
        view.ResetCamera()
    else:
        view.CameraParallelProjection = 1
        view.CameraFocalPoint = [zoom[0], zoom[1], 0]
        view.CameraPosition = [zoom[0], zoom[1], 50]
        view.CameraViewUp = [0, 1, 0]
        view.CameraParallelScale = zoom[2]
    Render(view)  # noqa: F405
    path = os.path.join(out_dir, "TestPluginIFEMReader-%s.png" % name)
    SaveScreenshot(path, view, ImageResolution=[500, 400])  # noqa: F405
    drawn, coloured, distinct = colours(path)
    print("%s: %.3f of the view drawn, %.3f coloured, %d distinct colours (%s)"
          % (name, drawn, coloured, distinct, path))
    if drawn < 0.1 or coloured < 0.08 or distinct < 20:
        fail("%s is not drawn coloured by %s" % (name, array))
    Delete(display)  # noqa: F405
    return view


# --- the reader factory --------------------------------------------------------------------
cyl = os.path.join(data, "Cyl2D-VMSFSI-weak.hdf5")
reader = OpenDataFile(cyl)  # noqa: F405
if reader is None or reader.GetXMLName() != "IFEMReader":
    fail("an IFEM .hdf5 file is not opened by the IFEM reader: %s" % reader)
    sys.exit(1)
other = os.path.join(out_dir, "TestPluginIFEMReader-not-ifem.h5")
with h5py.File(other, "w") as f:
    f.create_dataset("data", data=np.arange(10.0))
    f.create_group("0").create_dataset("x", data=np.zeros(3))
factory = servermanager.vtkSMProxyManager.GetProxyManager().GetReaderFactory()
session = servermanager.ActiveConnection.Session


def readers_for(path):
    names = factory.GetReaders(path, session)
    return [names.GetString(i) for i in range(1, names.GetLength(), 3)]


if "IFEMReader" in readers_for(other):
    fail("the IFEM reader claims an HDF5 file without IFEM's layout")
if "IFEMReader" not in readers_for(cyl):
    fail("the IFEM reader is not offered for an IFEM file")
print("a non-IFEM HDF5 file: IFEM reader not offered")

# --- time: a state that steps through the 11 levels ------------------------------------------
with h5py.File(cyl, "r") as f:
    file_times = [f["%d/timeinfo/level" % l][0] for l in range(11)]
times = list(reader.TimestepValues)
print("time steps:", times)
if len(times) != 11 or not np.allclose(times, file_times, rtol=0, atol=0):
    fail("the time steps %s are not the file's timeinfo %s" % (times, file_times))

view = white_view((500, 400))
display = Show(reader, view)  # noqa: F405
ColorBy(display, ("POINTS", "u_x"))  # noqa: F405
scene = GetAnimationScene()  # noqa: F405
scene.UpdateAnimationUsingDataTimeSteps()


def step_through(source, label):
    """Each animation time shows its level; returns per level (u_x range, bounds)."""
    seen = []
    for level, t in enumerate(times):
        scene.AnimationTime = t
        Render(view)  # noqa: F405
        output = source.GetClientSideObject().GetOutputDataObject(0)
        grids = leaves(output)
        levels = {field_number(g, "IFEMLevel") for _, g in grids}
        stamps = {field_number(g, "IFEMTime") for _, g in grids}
        if levels != {level} or stamps != {t} or len(grids) != 5:
            fail("%s: time %g shows levels %s, times %s, %d patches" % (label, t, levels, stamps,
                                                                         len(grids)))
        ux = np.concatenate([[g.GetPointData().GetArray("u_x").GetValue(i)
                              for i in range(g.GetNumberOfPoints())] for _, g in grids])
        xy = np.concatenate([[g.GetPoint(i)[:2] for i in range(g.GetNumberOfPoints())]
                             for _, g in grids])
        seen.append((ux, xy))
    return seen


first = step_through(reader, "the pipeline")
changes = [(np.max(np.abs(first[i + 1][0] - first[i][0])), np.max(np.abs(first[i + 1][1] -
                                                                          first[i][1])))
           for i in range(10)]
print("per step, largest change of u_x and of the control points:",
      ["%.2g/%.2g" % c for c in changes])
if min(c[0] for c in changes) <= 0 or max(c[1] for c in changes) <= 0:
    fail("the fields or the moving mesh do not change between levels")
scene.AnimationTime = times[0]
SaveScreenshot(os.path.join(out_dir, "TestPluginIFEMReader-Cyl2D-first.png"), view)  # noqa: F405
scene.AnimationTime = times[-1]
SaveScreenshot(os.path.join(out_dir, "TestPluginIFEMReader-Cyl2D-last.png"), view)  # noqa: F405

state = os.path.join(out_dir, "TestPluginIFEMReader.pvsm")
SaveState(state)  # noqa: F405
ResetSession()  # noqa: F405
LoadState(state)  # noqa: F405
reader = FindSource(os.path.basename(cyl))  # noqa: F405
if reader is None:
    reader = list(GetSources().values())[0]  # noqa: F405
view = GetActiveViewOrCreate("RenderView")  # noqa: F405
scene = GetAnimationScene()  # noqa: F405
scene.UpdateAnimationUsingDataTimeSteps()
if list(reader.TimestepValues) != times:
    fail("the loaded state has other time steps: %s" % list(reader.TimestepValues))
again = step_through(reader, "the loaded state")
for level in range(11):
    if not (np.array_equal(again[level][0], first[level][0]) and
            np.array_equal(again[level][1], first[level][1])):
        fail("level %d differs after loading the state" % level)
print("state saved, loaded and stepped through: same times and data")

# --- pictures -------------------------------------------------------------------------------
scene.AnimationTime = times[-1]
# The speed about the cylinder ("u": the vector of u_x, u_y split from u_x&&u_y&&p).
picture(reader, "u", "Cyl2D-speed", zoom=(0, 0, 1.5))
square = IFEMHDF5Results(FileName=os.path.join(data, "Square-LR.hdf5"))  # noqa: F405
picture(square, "u", "Square-LR-u")
shell = IFEMHDF5Results(FileName=os.path.join(data, "ScordelisPoint-NURBS.hdf5"))  # noqa: F405
picture(shell, "displacement_z", "Scordelis-shell")

checker.finish()
