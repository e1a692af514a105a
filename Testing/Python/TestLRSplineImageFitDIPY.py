# SPDX-License-Identifier: BSD-3-Clause
"""vtkLRSplineImageFitter on the real MR scans that python3-dipy ships, checked
against independent code.

aniso_vox.nii.gz (a brain, 58 x 58 x 24 voxels of 4 x 4 x 5 mm) fitted to 2 %
of its range, S0_10slices.nii.gz (128 x 128 x 10 voxels of 2 x 2 x 53 mm) to
5 %, both read by VTK's vtkNIFTIImageReader:
- the voxel values VTK reads are nibabel's (an independent NIfTI reader);
- the fitted spline, evaluated at every voxel (vtkLRSplineProbeFilter on the
  fitter's output), is within the tolerance of nibabel's values everywhere,
  with the maximum and RMS errors the fitter reports; negative control: the
  initial spline (no refinement) is not;
- VTK's own vtkProbeFilter, which interpolates the output's Bezier
  hexahedra with VTK's Bernstein basis (no SplineViz code), gives the same
  values at random voxels;
- the output is the reader's format: one block of VTK_BEZIER_HEXAHEDRON
  cells, degrees 2 2 2, the physical transform of the image (spacing,
  origin).
Prints elements, basis functions, errors and times.
"""
import os
import sys
import time

import numpy as np

try:
    import nibabel as nib
    import dipy.data
except ImportError as error:
    print("nibabel or DIPY not available (python3-nibabel, python3-dipy), skipped:", error)
    sys.exit(125)

from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import VTK_BEZIER_HEXAHEDRON, vtkPolyData, vtkStaticCellLocator
from vtkmodules.vtkFiltersCore import vtkProbeFilter
from vtkmodules.vtkIOImage import vtkNIFTIImageReader

import splineviz
from splineviz_testing import Observed

from splineviz_testing import Checker  # noqa: E402

checker = Checker()


check = checker.check


def fit(name, tolerance, levels=10):
    path = os.path.join(os.path.dirname(dipy.data.__file__), "files", name)
    reader = vtkNIFTIImageReader()
    reader.SetFileName(path)
    reader.Update()
    fitter = splineviz.vtkLRSplineImageFitter()
    fitter.SetInputConnection(reader.GetOutputPort())
    fitter.SetTolerance(tolerance)  # relative to the data range (the default mode)
    fitter.SetMaximumRefinementLevels(levels)
    observed = Observed(fitter)
    start = time.perf_counter()
    fitter.Update()
    seconds = time.perf_counter() - start
    return path, reader, fitter, seconds, observed


def voxel_errors(reader, spline, reference):
    """|spline - reference| at every voxel, the spline probed by SplineViz's probe filter."""
    probe = splineviz.vtkLRSplineProbeFilter()
    probe.SetInputConnection(reader.GetOutputPort())
    probe.SetSourceData(spline)
    probe.Update()
    out = probe.GetOutput()
    name = spline.GetBlock(0).GetPointData().GetScalars().GetName()
    nx, ny, nz = out.GetDimensions()
    values = vtk_to_numpy(out.GetPointData().GetArray(name)).reshape(nz, ny, nx).transpose(2, 1, 0)
    mask = vtk_to_numpy(out.GetPointData().GetArray("vtkValidPointMask"))
    return np.abs(values - reference), values, bool(mask.all())


def run(name, tolerance):
    path, reader, fitter, seconds, observed = fit(name, tolerance)
    image = reader.GetOutput()
    nib_values = np.asarray(nib.load(path).dataobj, dtype=np.float64).squeeze()
    nx, ny, nz = image.GetDimensions()
    vtk_values = vtk_to_numpy(image.GetPointData().GetScalars()).reshape(nz, ny, nx).transpose(2, 1, 0)
    check(np.array_equal(vtk_values, nib_values), "%s: VTK's NIfTI reader gives nibabel's voxels" % name)

    tol = fitter.GetAbsoluteTolerance()
    value_range = nib_values.max() - nib_values.min()
    check(abs(tol - tolerance * value_range) <= 1e-12 * value_range,
          "%s: tolerance %.4g = %g of nibabel's range %g" % (name, tol, tolerance, value_range))
    output = fitter.GetOutput()
    errors, spline_values, inside = voxel_errors(reader, output, nib_values)
    print("%s: %d voxels -> %d elements, %d basis functions, %d levels, %d fits in %.2f s "
          "(wall; 2 shared cores); maximum error %.4g, RMS %.4g (tolerance %.4g)"
          % (name, image.GetNumberOfPoints(), fitter.GetNumberOfElements(),
             fitter.GetNumberOfBasisFunctions(), fitter.GetNumberOfRefinementLevels(),
             fitter.GetNumberOfIterations(), seconds, errors.max(), np.sqrt((errors ** 2).mean()), tol))
    check(inside, "%s: every voxel is inside the spline" % name)
    check(fitter.GetToleranceMet() and not observed.warnings and not observed.errors,
          "%s: the fitter met the tolerance" % name)
    check(errors.max() <= tol * (1 + 1e-9), "%s: every voxel within the tolerance (independent probe)" % name)
    check(abs(errors.max() - fitter.GetMaximumError()) <= 1e-9 * tol
          and abs(np.sqrt((errors ** 2).mean()) - fitter.GetRMSError()) <= 1e-9 * tol,
          "%s: the maximum and RMS errors are the fitter's" % name)

    grid = output.GetBlock(0)
    degrees = grid.GetCellData().GetArray("HigherOrderDegrees")
    transform = grid.GetFieldData().GetArray("LRPhysicalTransform")
    check(output.GetNumberOfBlocks() == 1 and grid.GetNumberOfCells() == fitter.GetNumberOfElements()
          and all(grid.GetCellType(c) == VTK_BEZIER_HEXAHEDRON for c in range(0, grid.GetNumberOfCells(), 97))
          and degrees.GetTuple3(0) == (2.0, 2.0, 2.0)
          and np.allclose(transform.GetTuple(0), image.GetSpacing() + image.GetOrigin(), rtol=0, atol=1e-12),
          "%s: the reader's format, placed by the image's spacing and origin" % name)

    # VTK's own interpolation of the Bezier hexahedra at random voxels (inside
    # the image: VTK's cell search can miss points on the grid's boundary).
    rng = np.random.default_rng(4)
    ijk = np.stack([rng.integers(1, n - 1, 200) for n in (nx, ny, nz)], axis=1)
    picks = ijk[:, 0] + nx * (ijk[:, 1] + ny * ijk[:, 2])
    points = vtkPoints()
    for p in picks:
        points.InsertNextPoint(image.GetPoint(int(p)))
    cloud = vtkPolyData()
    cloud.SetPoints(points)
    vtk_probe = vtkProbeFilter()
    vtk_probe.SetCellLocatorPrototype(vtkStaticCellLocator())  # (neighbouring cells share
    vtk_probe.SetInputData(cloud)                               # only equal control points)
    vtk_probe.SetSourceData(grid)
    vtk_probe.Update()
    name_array = grid.GetPointData().GetScalars().GetName()
    probed = vtk_to_numpy(vtk_probe.GetOutput().GetPointData().GetArray(name_array))
    valid = vtk_to_numpy(vtk_probe.GetOutput().GetPointData().GetArray("vtkValidPointMask"))
    ours = np.array([spline_values.transpose(2, 1, 0).ravel()[int(p)] for p in picks])
    agree = np.abs(probed - ours)[valid == 1]
    check(valid.sum() >= 198 and agree.max() <= 1e-6 * value_range,
          "%s: VTK's vtkProbeFilter on the Bezier cells agrees at %d random voxels (worst %.2g)"
          % (name, valid.sum(), agree.max()))

    # Negative control: the initial spline alone does not meet the tolerance.
    _, coarse_reader, coarse, _, coarse_observed = fit(name, tolerance, levels=0)
    coarse_errors, _, _ = voxel_errors(coarse_reader, coarse.GetOutput(), nib_values)
    check(not coarse.GetToleranceMet() and coarse_observed.warnings and coarse_errors.max() > 5 * tol,
          "%s: negative control: the initial spline misses by %.4g" % (name, coarse_errors.max()))


run("aniso_vox.nii.gz", 0.02)
run("S0_10slices.nii.gz", 0.05)
checker.finish()
