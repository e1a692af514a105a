# SPDX-License-Identifier: BSD-3-Clause
"""Virtual dissection of a real bundle with vtkStreamlineSelection.

    source build/splineviz-env.sh
    pvpython Examples/Python/streamline_selection.py [OUTPUT_DIR]

DIPY's cb_2 bundle (116 streamlines of a cingulum, RAS+ mm) is written as an
MRtrix .tck by nibabel and read by vtkTractogramReader. Two regions dissect
it: the streamlines must pass through a sphere (INCLUDE) and must not touch
an oriented box (EXCLUDE). With OutputMode MARK_STREAMLINES every streamline
stays, with the cell array "Selected" (0/1), drawn here in orange (selected)
and grey (not); the sphere is drawn translucent and the box as its edges:
streamline-selection.png.

Needs DIPY and NiBabel (Debian: python3-dipy, python3-nibabel).
"""
import os
import sys

import numpy as np
import nibabel as nib
from dipy.data import get_fnames

from vtkmodules.vtkCommonCore import vtkLookupTable
from vtkmodules.vtkCommonMath import vtkMatrix4x4
from vtkmodules.vtkFiltersSources import vtkCubeSource, vtkSphereSource
from vtkmodules.vtkFiltersCore import vtkFeatureEdges
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import (
    vtkActor,
    vtkPolyDataMapper,
    vtkRenderer,
    vtkRenderWindow,
    vtkWindowToImageFilter,
)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (OpenGL render window)

import splineviz

out_dir = sys.argv[1] if len(sys.argv) > 1 else "."
os.makedirs(out_dir, exist_ok=True)

# -- the bundle as a .tck ----------------------------------------------------------
cb = np.load(os.path.join(os.path.dirname(get_fnames("small_64D")[0]), "cb_2.npz"))
ends = cb["offsets"]
starts = np.r_[0, ends[:-1]]
streamlines = [cb["points"][s:e] for s, e in zip(starts, ends)]
tck = os.path.join(out_dir, "cb_2.tck")
nib.streamlines.save(nib.streamlines.Tractogram(streamlines, affine_to_rasmm=np.eye(4)), tck)
reader = splineviz.vtkTractogramReader()
reader.SetFileName(tck)

# -- the dissection ------------------------------------------------------------------
centre = [10.5, 15.0, 8.2]  # mm, in the middle of the bundle
radius = 5.0
box_bounds = [-10.0, 10.0, -2.5, 2.5, -10.0, 10.0]  # in the box's own frame
box_to_world = vtkMatrix4x4()  # a slab rotated 30 degrees about x, across the bundle
c, s = np.cos(np.radians(30)), np.sin(np.radians(30))
box_to_world.DeepCopy([1, 0, 0, 10.0,
                       0, c, -s, 38.0,
                       0, s, c, 10.0,
                       0, 0, 0, 1])
selection = splineviz.vtkStreamlineSelection()
selection.SetInputConnection(reader.GetOutputPort())
selection.AddSphere(centre, radius, selection.INCLUDE)
selection.AddOrientedBox(box_bounds, box_to_world, selection.EXCLUDE)
selection.SetOutputModeToMarkStreamlines()
selection.Update()
print("%d of %d streamlines selected" % (selection.GetNumberOfSelectedStreamlines(),
                                         len(streamlines)))

# -- the picture ----------------------------------------------------------------------
colors = vtkLookupTable()
colors.SetNumberOfTableValues(2)
colors.SetTableValue(0, 0.72, 0.72, 0.72, 1.0)  # not selected: grey
colors.SetTableValue(1, 0.95, 0.45, 0.05, 1.0)  # selected: orange
colors.SetTableRange(0, 1)
lines = vtkPolyDataMapper()
lines.SetInputConnection(selection.GetOutputPort())
lines.SetScalarModeToUseCellFieldData()
lines.SelectColorArray("Selected")
lines.SetColorModeToMapScalars()  # unsigned char 0/1: through the table, not as colours
lines.SetLookupTable(colors)
lines.SetScalarRange(0, 1)
line_actor = vtkActor()
line_actor.SetMapper(lines)
line_actor.GetProperty().SetLineWidth(2.0)
line_actor.GetProperty().SetRenderLinesAsTubes(True)

sphere = vtkSphereSource()
sphere.SetCenter(centre)
sphere.SetRadius(radius)
sphere.SetThetaResolution(48)
sphere.SetPhiResolution(24)
sphere_actor = vtkActor()
sphere_mapper = vtkPolyDataMapper()
sphere_mapper.SetInputConnection(sphere.GetOutputPort())
sphere_actor.SetMapper(sphere_mapper)
sphere_actor.GetProperty().SetColor(0.2, 0.6, 0.2)
sphere_actor.GetProperty().SetOpacity(0.35)

cube = vtkCubeSource()
cube.SetBounds(box_bounds)
edges = vtkFeatureEdges()
edges.SetInputConnection(cube.GetOutputPort())
box_mapper = vtkPolyDataMapper()
box_mapper.SetInputConnection(edges.GetOutputPort())
box_mapper.ScalarVisibilityOff()
box_actor = vtkActor()
box_actor.SetMapper(box_mapper)
box_actor.SetUserMatrix(box_to_world)
box_actor.GetProperty().SetColor(0.8, 0.1, 0.1)
box_actor.GetProperty().SetLineWidth(3)
box_actor.GetProperty().LightingOff()

renderer = vtkRenderer()
for actor in (line_actor, sphere_actor, box_actor):
    renderer.AddActor(actor)
renderer.SetBackground(1, 1, 1)
window = vtkRenderWindow()
window.SetOffScreenRendering(1)
window.SetSize(900, 600)
window.AddRenderer(renderer)
camera = renderer.GetActiveCamera()
camera.SetFocalPoint(15, 30, -5)
camera.SetPosition(230, 20, 40)  # from the right: the cingulum's arch in profile
camera.SetViewUp(0, 0, 1)
renderer.ResetCamera()
camera.Zoom(1.4)
window.Render()
grab = vtkWindowToImageFilter()
grab.SetInput(window)
grab.ReadFrontBufferOff()
grab.Update()
png = os.path.join(out_dir, "streamline-selection.png")
writer = vtkPNGWriter()
writer.SetFileName(png)
writer.SetInputConnection(grab.GetOutputPort())
writer.Write()
print("wrote", png)
