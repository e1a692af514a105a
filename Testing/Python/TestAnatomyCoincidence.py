# SPDX-License-Identifier: BSD-3-Clause
"""Anatomy under streamlines: a T1-like volume and a tractogram written by
nibabel in the same world space coincide in SplineViz, in the data and on
the screen, under affines that rotate and flip.

For each affine (identity; 30 degrees about z with x flipped; oblique with y
and z flipped and anisotropic voxels), nibabel writes
- a T1-like volume: background 100, one marked voxel 1000 (not at a corner),
- a .tck whose one streamline passes straight through the marked voxel's
  centre in RAS+ mm (computed with nibabel's affine only).
SplineViz reads the volume with vtkNIfTIVolumeReader and the streamline with
vtkTractogramReader. Checks:
- data: the volume probed (vtkProbeFilter, nearest voxel within half a
  voxel) at the streamline's middle point gives 1000; at its ends, two voxels
  away, 100;
- screen: the volume's marked voxel drawn by VTK's image slice (vtkImageSlice
  with vtkImageSliceMapper, which places the voxels with the image's
  origin, spacing and direction) and the streamline drawn by the ray-cast
  tubes, looking down the streamline: the tube's pixels (a thin tube, its
  axis seen end-on) lie inside the bright voxel's pixels.
Negative controls: the same volume read with the pixdim affine
(AffineSource PIXDIM: no rotation or offset) misses the streamline (probe
value not 1000); the tube moved by one voxel misses the bright voxel on the
screen.
"""
import os
import sys

import numpy as np

try:
    import nibabel as nib
    from nibabel.streamlines import Tractogram
except ImportError as error:
    print("nibabel not available, skipped:", error)
    sys.exit(125)

from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkFiltersCore import vtkProbeFilter
from vtkmodules.vtkRenderingCore import (vtkActor, vtkImageSlice, vtkImageSliceMapper,
                                         vtkRenderWindow, vtkRenderer, vtkWindowToImageFilter)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the OpenGL factory)

import splineviz
from splineviz_testing import Checker, output_dir

checker = Checker()
check = checker.check


def rotation(axis, degrees):
    a = np.radians(degrees)
    c, s = np.cos(a), np.sin(a)
    axis = np.asarray(axis, float) / np.linalg.norm(axis)
    x, y, z = axis
    return np.array([[c + x * x * (1 - c), x * y * (1 - c) - z * s, x * z * (1 - c) + y * s],
                     [y * x * (1 - c) + z * s, c + y * y * (1 - c), y * z * (1 - c) - x * s],
                     [z * x * (1 - c) - y * s, z * y * (1 - c) + x * s, c + z * z * (1 - c)]])


def affine(linear, offset):
    a = np.eye(4)
    a[:3, :3] = linear
    a[:3, 3] = offset
    return a


shape = (12, 10, 8)
marked = (7, 4, 3)
cases = {
    "identity": affine(np.diag([2.0, 2.0, 2.0]), [-12, -10, -8]),
    "rotated-flipped": affine(rotation([0, 0, 1], 30) @ np.diag([-2.0, 2.0, 2.0]), [20, -15, 5]),
    "oblique-flipped": affine(rotation([1, 2, 0.5], 25) @ np.diag([1.5, -2.5, -3.0]), [-5, 30, 12]),
}
out = output_dir()


def probe(image, points):
    pd = vtkPolyData()
    p = vtkPoints()
    for x in points:
        p.InsertNextPoint(*x)
    pd.SetPoints(p)
    f = vtkProbeFilter()
    f.SetInputData(pd)
    f.SetSourceData(image)
    f.Update()
    values = vtk_to_numpy(f.GetOutput().GetPointData().GetArray("T1"))
    valid = vtk_to_numpy(f.GetOutput().GetPointData().GetArray("vtkValidPointMask"))
    return values, valid


for name, a in cases.items():
    data = np.full(shape, 100, np.int16)
    data[marked] = 1000
    img = nib.Nifti1Image(data, a)
    img.set_sform(a, code=1)
    img.set_qform(a, code=1)
    nii = os.path.join(out, "TestAnatomyCoincidence-%s.nii" % name)
    nib.save(img, nii)
    # The streamline: along the voxel's third axis through its centre, from
    # two voxels before to two voxels after (world mm, by nibabel's affine).
    ijk = np.array(marked, float)
    ends = [ijk - [0, 0, 2], ijk, ijk + [0, 0, 2]]
    world = nib.affines.apply_affine(a, np.array(ends))
    line = np.linspace(world[0], world[2], 21).astype(np.float32)
    tck = os.path.join(out, "TestAnatomyCoincidence-%s.tck" % name)
    nib.streamlines.save(Tractogram([line], affine_to_rasmm=np.eye(4)), tck)

    reader = splineviz.vtkNIfTIVolumeReader()
    reader.SetFileName(nii)
    reader.Update()
    image = reader.GetOutput()
    image.GetPointData().GetScalars().SetName("T1")
    lines = splineviz.vtkTractogramReader()
    lines.SetFileName(tck)
    lines.Update()
    streamline = vtk_to_numpy(lines.GetOutput().GetPoints().GetData()).astype(float)

    values, valid = probe(image, [streamline[10], streamline[0], streamline[-1]])
    check(valid.all() and values[0] == 1000 and values[1] == 100 and values[2] == 100,
          "%s: probed along the streamline: middle %s, ends %s, %s (want 1000, 100, 100)"
          % (name, values[0], values[1], values[2]))

    # Negative control: the pixdim affine puts the voxel elsewhere.
    control = splineviz.vtkNIfTIVolumeReader()
    control.SetFileName(nii)
    control.SetAffineSource(control.AFFINE_PIXDIM)
    control.Update()
    control_image = control.GetOutput()
    control_image.GetPointData().GetScalars().SetName("T1")
    values, valid = probe(control_image, [streamline[10]])
    if name != "identity":
        check(not (valid[0] and values[0] == 1000),
              "%s: control, the pixdim placement misses the voxel (value %s, valid %d)"
              % (name, values[0], valid[0]))

    # Screen: looking down the streamline at the voxel's slice.
    ren = vtkRenderer()
    ren.SetBackground(0, 0, 0)
    mapper = vtkImageSliceMapper()
    mapper.SetInputData(image)
    mapper.SetOrientationToZ()
    # The marked voxel's slice in VTK's index order (slices may be stored reversed).
    dims = image.GetDimensions()
    brightest = int(np.argmax(vtk_to_numpy(image.GetPointData().GetScalars())))
    mapper.SetSliceNumber(brightest // (dims[0] * dims[1]))
    slice_actor = vtkImageSlice()
    slice_actor.SetMapper(mapper)
    slice_actor.GetProperty().SetColorWindow(900)
    slice_actor.GetProperty().SetColorLevel(550)
    slice_actor.GetProperty().SetInterpolationTypeToNearest()
    ren.AddViewProp(slice_actor)
    tube_mapper = splineviz.vtkRayCastTubeMapper()
    tube_mapper.SetInputConnection(lines.GetOutputPort())
    tube_mapper.SetRadius(0.3)
    tube_mapper.SetMinimumPixelWidth(0)
    tube_actor = vtkActor()
    tube_actor.SetMapper(tube_mapper)
    tube_actor.GetProperty().SetColor(1.0, 0.0, 0.0)
    tube_actor.GetProperty().SetAmbient(1.0)
    tube_actor.GetProperty().SetDiffuse(0.0)
    ren.AddActor(tube_actor)
    win = vtkRenderWindow()
    win.SetOffScreenRendering(1)
    win.SetMultiSamples(0)
    win.SetSize(300, 300)
    win.AddRenderer(ren)
    cam = ren.GetActiveCamera()
    direction = world[2] - world[0]
    direction /= np.linalg.norm(direction)
    cam.SetFocalPoint(*world[1])
    cam.SetPosition(*(world[1] - 60.0 * direction))
    up = np.cross(direction, [0.3, 0.5, 0.8])
    cam.SetViewUp(*up)
    cam.ParallelProjectionOn()
    cam.SetParallelScale(8.0)
    ren.ResetCameraClippingRange()
    win.Render()
    w2i = vtkWindowToImageFilter()
    w2i.SetInput(win)
    w2i.Update()
    rgb = vtk_to_numpy(w2i.GetOutput().GetPointData().GetScalars())[:, :3].reshape(300, 300, 3)
    tube = (rgb[:, :, 0] > 200) & (rgb[:, :, 1] < 60) & (rgb[:, :, 2] < 60)
    # Without the tube: the slice alone, to find the bright voxel's pixels.
    tube_actor.VisibilityOff()
    win.Render()
    w2i.Modified()
    w2i.Update()
    alone = vtk_to_numpy(w2i.GetOutput().GetPointData().GetScalars())[:, :3].reshape(300, 300, 3)
    bright = alone.min(axis=2) > 200
    from vtkmodules.vtkIOImage import vtkPNGWriter
    writer = vtkPNGWriter()
    writer.SetFileName(os.path.join(out, "TestAnatomyCoincidence-%s.png" % name))
    tube_actor.VisibilityOn()
    win.Render()
    w2i.Modified()
    writer.SetInputConnection(w2i.GetOutputPort())
    writer.Write()
    check(tube.sum() > 20 and bright.sum() > 200,
          "%s: the tube covers %d pixels, the bright voxel %d" % (name, tube.sum(), bright.sum()))
    inside = (tube & bright).sum() / max(tube.sum(), 1)
    check(inside == 1.0, "%s: %.1f %% of the tube's pixels lie on the marked voxel"
          % (name, 100 * inside))
    # Negative control: the tube moved by one voxel along the voxel's first axis.
    tube_actor.SetPosition(*a[:3, 0])
    win.Render()
    w2i.Modified()
    w2i.Update()
    moved = vtk_to_numpy(w2i.GetOutput().GetPointData().GetScalars())[:, :3].reshape(300, 300, 3)
    moved_tube = (moved[:, :, 0] > 200) & (moved[:, :, 1] < 60) & (moved[:, :, 2] < 60)
    moved_inside = (moved_tube & bright).sum() / max(moved_tube.sum(), 1)
    check(moved_tube.sum() > 20 and moved_inside == 0.0,
          "%s: control, moved a voxel: %.1f %% of the tube's pixels on the marked voxel"
          % (name, 100 * moved_inside))

checker.finish()
