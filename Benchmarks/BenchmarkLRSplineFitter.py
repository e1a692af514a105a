# SPDX-License-Identifier: BSD-3-Clause
"""LR splines for unstructured simulation data, side by side with ParaView's
way, in one run. A program, not a timed test.

    source build/splineviz-env.sh
    pvpython Benchmarks/BenchmarkLRSplineFitter.py [--quick] [TOLERANCE]

Data (each fitted by vtkLRSplineFitter with its defaults, to TOLERANCE,
default 0.02 of the range):
- OpenFOAM's porous angled duct (scripts/openfoam-case.sh; 22,000
  hexahedra), p and |U| at the cell centres;
- two synthetic unstructured meshes: a grid on [0,1]^3 clipped by a sphere
  into tetrahedra (vtkClipDataSet), with the smooth field plus a narrow
  Gaussian bump of the fitter's tests at its points: about 10^5 and 10^6
  points (--quick: 10^4 and 10^5).

For each: the fit's time, elements, coefficients, maximum and RMS error at
the data, and bytes: the input (the data's points and values as float32,
16 bytes a point, and the mesh's VTK memory) against the .lr file; then
ParaView's Resample To Image (vtkResampleToImage) at 128^3 and 256^3, and
the smallest of 32, 48, 64, 96, 128, 192, 256, 384 whose maximum error at
the data points away from the boundary (the image mixes in zeros outside
the mesh there) is at most the spline's: bytes as float32 and the ratio;
and both compressed with zlib (level 6, as VTK's XML writers compress),
the fair comparison for files on disk: an image is mostly zeros where the
mesh does not fill its box.
Rendering, 800 x 600 offscreen, each in a fresh render window: the first
frame (shader compilation and upload included) and the median of 5 frames
while rotating, for the spline (vtkLRSplineVolumeMapper trimmed by the
fitter's boundary surface), the 128^3 image (vtkSmartVolumeMapper, as
ParaView's Resample To Image + Volume), and the mesh itself
(vtkProjectedTetrahedraMapper, ParaView's default Volume representation of
an unstructured grid; --quick skips it above 10^5 points).
"""
import os
import runpy
import statistics
import subprocess
import sys
import time
import zlib

import numpy as np

import splineviz
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkDataObject, vtkImageData, vtkPiecewiseFunction, vtkSphere
from vtkmodules.vtkFiltersCore import vtkCellCenters
from vtkmodules.vtkFiltersGeneral import vtkClipDataSet, vtkDataSetTriangleFilter
from vtkmodules.vtkIOGeometry import vtkOpenFOAMReader
from vtkmodules.vtkRenderingCore import (vtkColorTransferFunction, vtkRenderer, vtkRenderWindow,
                                         vtkVolume, vtkVolumeProperty)
from vtkmodules.vtkRenderingVolume import vtkProjectedTetrahedraMapper
from vtkmodules.vtkRenderingVolumeOpenGL2 import vtkSmartVolumeMapper
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401

HERE = os.path.dirname(os.path.abspath(__file__))
# The example's resampling error (one place for ParaView's way of the comparison).
EXAMPLE = runpy.run_path(os.path.join(HERE, "..", "Examples", "Python", "lr_spline_fit_openfoam.py"),
                         run_name="lr_spline_fit_openfoam")
RESOLUTIONS = (32, 48, 64, 96, 128, 192, 256, 384)


def bump(x):
    """The fitter tests' field: smooth plus a Gaussian bump of width 0.05."""
    c = np.array([0.6, 0.4, 0.5])
    return (np.sin(2 * x[:, 0]) + x[:, 1] * x[:, 2] +
            np.exp(-((x - c) ** 2).sum(axis=1) / (2 * 0.05 ** 2)))


def synthetic_mesh(points):
    """A tetrahedral mesh of about `points` points: a grid on [0,1]^3 clipped
    by the sphere of radius 0.5 about its centre, the bump field at the points."""
    n = int(round((points / (np.pi / 6)) ** (1 / 3)))
    grid = vtkImageData()
    grid.SetDimensions(n, n, n)
    grid.SetSpacing(1 / (n - 1), 1 / (n - 1), 1 / (n - 1))
    x = np.stack(np.meshgrid(*(np.linspace(0, 1, n),) * 3, indexing="ij"), -1)
    x = x.transpose(2, 1, 0, 3).reshape(-1, 3)  # VTK order: x fastest
    values = numpy_to_vtk(bump(x), deep=1)
    values.SetName("f")
    grid.GetPointData().SetScalars(values)
    sphere = vtkSphere()
    sphere.SetCenter(0.5, 0.5, 0.5)
    sphere.SetRadius(0.5)
    clip = vtkClipDataSet()
    clip.SetInputData(grid)
    clip.SetClipFunction(sphere)
    clip.InsideOutOn()
    tets = vtkDataSetTriangleFilter()
    tets.SetInputConnection(clip.GetOutputPort())
    tets.Update()
    mesh = tets.GetOutput()
    return mesh, vtk_to_numpy(mesh.GetPoints().GetData()).astype(float), \
        vtk_to_numpy(mesh.GetPointData().GetArray("f")).astype(float)


def openfoam_mesh(array):
    """The angled duct's internal mesh (last time) and its cell centres."""
    run = subprocess.run([os.path.join(HERE, "..", "scripts", "openfoam-case.sh")],
                         stdout=subprocess.PIPE, text=True, check=True)
    reader = vtkOpenFOAMReader()
    reader.SetFileName(run.stdout.strip().splitlines()[-1])
    reader.UpdateInformation()
    reader.EnableAllCellArrays()
    reader.CreateCellToPointOff()
    times = reader.GetTimeValues()
    reader.UpdateTimeStep(times.GetValue(times.GetNumberOfTuples() - 1))
    mesh = reader.GetOutput().GetBlock(0)
    centres = vtkCellCenters()
    centres.SetInputData(mesh)
    centres.Update()
    values = vtk_to_numpy(mesh.GetCellData().GetArray(array)).astype(float)
    if values.ndim > 1:
        values = np.linalg.norm(values, axis=1)
        magnitude = numpy_to_vtk(values, deep=1)
        magnitude.SetName("|U|")
        mesh.GetCellData().AddArray(magnitude)
        array = "|U|"
    return mesh, vtk_to_numpy(centres.GetOutput().GetPoints().GetData()).astype(float), \
        values, array


def fit(mesh, association, array, tolerance, lr_file):
    fitter = splineviz.vtkLRSplineFitter()
    fitter.SetInputData(mesh)
    fitter.SetInputArrayToProcess(0, 0, 0, association, array)
    fitter.SetTolerance(tolerance)
    fitter.SetFileName(lr_file)
    start = time.perf_counter()
    fitter.Update()
    return fitter, time.perf_counter() - start


def compressed_bytes(image, array):
    """The image's float32 values of `array`, compressed with zlib (level 6)."""
    values = vtk_to_numpy(image.GetPointData().GetArray(array)).astype(np.float32)
    return len(zlib.compress(values.tobytes(), 6))


def point_cloud(x):
    from vtkmodules.vtkCommonCore import vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkPolyData
    pd = vtkPolyData()
    points = vtkPoints()
    points.SetData(numpy_to_vtk(np.ascontiguousarray(x), deep=1))
    pd.SetPoints(points)
    return pd


def transfer_functions(low, high):
    prop = vtkVolumeProperty()
    color = vtkColorTransferFunction()
    opacity = vtkPiecewiseFunction()
    for fraction, rgb, alpha in ((0.0, (0.23, 0.30, 0.75), 0.1), (0.5, (0.87, 0.87, 0.87), 0.05),
                                 (1.0, (0.71, 0.02, 0.15), 0.4)):
        color.AddRGBPoint(low + fraction * (high - low), *rgb)
        opacity.AddPoint(low + fraction * (high - low), alpha)
    prop.SetColor(color)
    prop.SetScalarOpacity(opacity)
    prop.SetInterpolationTypeToLinear()
    return prop


def frames(mapper, prop, unit_distance, size=(800, 600)):
    """First frame in a fresh window, then the median of 5 rotated frames."""
    prop.SetScalarOpacityUnitDistance(unit_distance)
    volume = vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(prop)
    renderer = vtkRenderer()
    renderer.SetBackground(1, 1, 1)
    renderer.AddVolume(volume)
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetMultiSamples(0)
    window.SetSize(*size)
    window.AddRenderer(renderer)
    renderer.ResetCamera()
    renderer.GetActiveCamera().Elevation(25)
    renderer.GetActiveCamera().Azimuth(30)
    start = time.perf_counter()
    window.Render()
    first = time.perf_counter() - start
    times = []
    for _ in range(5):
        renderer.GetActiveCamera().Azimuth(7)
        start = time.perf_counter()
        window.Render()
        times.append(time.perf_counter() - start)
    window.Finalize()
    return first, statistics.median(times)


def run(label, mesh, association, array, x, values, tolerance, render_mesh=True):
    out = os.environ.get("TMPDIR", "/tmp")
    lr_file = os.path.join(out, "splineviz-benchmark-%s.lr" % label.replace(" ", "-"))
    fitter, seconds = fit(mesh, association, array, tolerance, lr_file)
    lr_bytes = os.path.getsize(lr_file)
    input_bytes = 16 * len(values)
    print("\n== %s: %d data points (%s), values in [%.4g, %.4g]"
          % (label, len(values), "cell centres" if association else "mesh points",
             values.min(), values.max()))
    print("   LR fit: %.2f s, %d elements, %d coefficients, max error %.4g, RMS %.4g "
          "(tolerance %.4g, met %d)"
          % (seconds, fitter.GetNumberOfElements(), fitter.GetNumberOfBasisFunctions(),
             fitter.GetMaximumError(), fitter.GetRMSError(), fitter.GetAbsoluteTolerance(),
             fitter.GetToleranceMet()))
    print("   bytes: data %d (float32 points + values; the VTK mesh %d), .lr %d: "
          "compression %.2fx"
          % (input_bytes, mesh.GetActualMemorySize() * 1024, lr_bytes, input_bytes / lr_bytes))
    cloud = point_cloud(x)
    images = {}
    equal = None
    for size in RESOLUTIONS:
        start = time.perf_counter()
        _, worst, _, interior, _, image = EXAMPLE["resampled_error"](
            mesh, cloud, values, array, size)
        rs = time.perf_counter() - start
        if size in (128, 256) or (equal is None and interior <= fitter.GetMaximumError()):
            images[size] = image
        if size in (128, 256):
            print("   Resample To Image %d^3 (and probing it): %.2f s, %d bytes (%.1fx the .lr), "
                  "max error %.4g (%.4g away from the boundary)"
                  % (size, rs, 4 * size ** 3, 4 * size ** 3 / lr_bytes, worst, interior))
        if equal is None and interior <= fitter.GetMaximumError():
            equal = size
        if size >= 256 and equal is not None:
            break
    if equal:
        print("   equal maximum error (away from the boundary): %d^3, %d bytes, %.1fx the .lr"
              % (equal, 4 * equal ** 3, 4 * equal ** 3 / lr_bytes))
    else:
        print("   equal maximum error: not reached by %d^3 (%d bytes, %.1fx the .lr)"
              % (RESOLUTIONS[-1], 4 * RESOLUTIONS[-1] ** 3, 4 * RESOLUTIONS[-1] ** 3 / lr_bytes))
    with open(lr_file, "rb") as f:
        lr_zipped = len(zlib.compress(f.read(), 6))
    print("   compressed (zlib 6): .lr %d bytes; %s"
          % (lr_zipped, ", ".join("%d^3 %d bytes (%.1fx the .lr)" % (size, zipped, zipped / lr_zipped)
                                  for size, zipped in sorted(
                                      (size, compressed_bytes(image, array))
                                      for size, image in images.items()))))

    low, high = values.min(), values.max()
    diagonal = np.linalg.norm(np.ptp(x, axis=0))
    rows = []
    spline_mapper = splineviz.vtkLRSplineVolumeMapper()
    spline_mapper.SetInputConnection(fitter.GetOutputPort(0))
    spline_mapper.SetTrimmingSurfaceConnection(fitter.GetOutputPort(1))
    rows.append(("LR spline, trimmed", frames(spline_mapper, transfer_functions(low, high),
                                              diagonal / 50)))
    smart = vtkSmartVolumeMapper()
    smart.SetInputData(images[128])
    smart.SetScalarModeToUsePointFieldData()
    smart.SelectScalarArray(array)
    rows.append(("Resample To Image 128^3 + vtkSmartVolumeMapper",
                 frames(smart, transfer_functions(low, high), diagonal / 50)))
    if render_mesh:
        tets = vtkDataSetTriangleFilter()
        tets.SetInputData(mesh)
        tets.Update()
        projected = vtkProjectedTetrahedraMapper()
        projected.SetInputConnection(tets.GetOutputPort())
        projected.SetScalarMode(4 if association else 3)  # cell or point field data
        projected.SelectScalarArray(array)
        rows.append(("the mesh, vtkProjectedTetrahedraMapper",
                     frames(projected, transfer_functions(low, high), diagonal / 50)))
    base = rows[0][1]
    for name, (first, frame) in rows:
        print("   %-48s first frame %7.3f s (%.2fx the spline's), frame %7.3f s (%.2fx)"
              % (name, first, first / base[0], frame, frame / base[1]))


def main():
    args = [a for a in sys.argv[1:] if a != "--quick"]
    quick = "--quick" in sys.argv
    tolerance = float(args[0]) if args else 0.02
    for array in ("p", "U"):
        mesh, x, values, name = openfoam_mesh(array)
        run("OpenFOAM duct %s" % name, mesh, vtkDataObject.FIELD_ASSOCIATION_CELLS, name, x,
            values, tolerance)
    for points in ((10 ** 4, 10 ** 5) if quick else (10 ** 5, 10 ** 6)):
        mesh, x, values = synthetic_mesh(points)
        run("synthetic %d" % len(values), mesh, vtkDataObject.FIELD_ASSOCIATION_POINTS, "f", x,
            values, tolerance, render_mesh=not quick or points <= 10 ** 5)


if __name__ == "__main__":
    main()
