# SPDX-License-Identifier: BSD-3-Clause
"""A real CFD result as LR splines: OpenFOAM's porous angled duct fitted and volume rendered.

    source build/splineviz-env.sh
    CASE=$(scripts/openfoam-case.sh)          # runs the tutorial (about 15 s)
    pvpython Examples/Python/lr_spline_fit_openfoam.py $CASE [OUTPUT_DIR] [TOLERANCE]

1. VTK's vtkOpenFOAMReader (the reader ParaView uses) reads the last time
   step of the internal mesh (22,000 hexahedra of a bent duct with a porous
   block, from porousSimpleFoam): cell data p and U.
2. vtkLRSplineFitter fits quadratic LR splines to p and to |U| at the cell
   centres, refining locally until every centre is within TOLERANCE
   (default 0.01: 1 % of the data range), and U itself (3 components, 5 %)
   for streamlines. It prints the fit time, elements, coefficients, maximum
   and RMS error, the .lr file's bytes, and, for comparison, resampling the
   mesh to 128^3 and 256^3 images (vtkResampleToImage, ParaView's Resample To
   Image, of the cell data): bytes (float32) and the error of the trilinear
   image at the cell centres.
3. OUTPUT_DIR/lr-spline-fit-openfoam.png: p volume rendered from the spline
   by vtkLRSplineVolumeMapper, trimmed by the mesh's boundary surface (the
   fitter's second output), with streamlines traced on the U spline by
   vtkLRSplineStreamTracer; OUTPUT_DIR/lr-spline-fit-openfoam-untrimmed.png:
   the same without trimming (the spline's box shows outside the duct).
"""
import os
import sys
import time

import splineviz
from vtkmodules.vtkCommonDataModel import vtkDataObject
from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline
from vtkmodules.vtkFiltersCore import vtkCellCenters, vtkProbeFilter, vtkResampleToImage, vtkTubeFilter
from vtkmodules.vtkFiltersSources import vtkLineSource
from vtkmodules.vtkIOGeometry import vtkOpenFOAMReader
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import (vtkActor, vtkColorTransferFunction, vtkPolyDataMapper,
                                         vtkRenderer, vtkRenderWindow, vtkVolume,
                                         vtkVolumeProperty, vtkWindowToImageFilter)
from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401
import vtkmodules.vtkRenderingVolumeOpenGL2  # noqa: F401

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy


def read_case(foam):
    reader = vtkOpenFOAMReader()
    reader.SetFileName(foam)
    reader.UpdateInformation()
    reader.EnableAllCellArrays()
    # cell data only: the solution's values (the reader's point data would be
    # an interpolation to the points, with the walls' no-slip values)
    reader.CreateCellToPointOff()
    times = reader.GetTimeValues()
    last = times.GetValue(times.GetNumberOfTuples() - 1)
    reader.UpdateTimeStep(last)
    return reader, last


def fit(source, array, tolerance, vector_mode=0, file_name=None):
    fitter = splineviz.vtkLRSplineFitter()
    fitter.SetInputConnection(source.GetOutputPort())
    fitter.SetInputArrayToProcess(0, 0, 0, vtkDataObject.FIELD_ASSOCIATION_CELLS, array)
    fitter.SetVectorMode(vector_mode)
    fitter.SetTolerance(tolerance)
    if file_name:
        fitter.SetFileName(file_name)
    fitter.Update()
    return fitter


def resampled_error(mesh, centres, values, array, size):
    """Bytes (float32) and the largest and RMS error at the cell centres of
    the mesh resampled to a size^3 image and interpolated trilinearly; the
    largest error away from the boundary, how many centres that leaves out,
    and the image. (Benchmarks/BenchmarkLRSplineFitter.py uses it too.)"""
    resample = vtkResampleToImage()
    resample.SetInputDataObject(mesh)
    resample.SetSamplingDimensions(size, size, size)
    resample.Update()
    probe = vtkProbeFilter()
    probe.SetInputData(centres)
    probe.SetSourceData(resample.GetOutput())
    probe.Update()
    data = probe.GetOutput().GetPointData()
    probed = vtk_to_numpy(data.GetArray(array))
    if probed.ndim > 1:
        probed = np.linalg.norm(probed, axis=1)
    error = np.abs(probed - values)
    # centres whose 8 surrounding voxels all lie in the mesh (the others mix
    # in the zeros that resampling puts outside it)
    inside = vtk_to_numpy(data.GetArray("vtkValidPointMask")).astype(bool)
    mask = resample.GetOutput().GetPointData().GetArray("vtkValidPointMask")
    mask_probe = vtkProbeFilter()
    mask_probe.SetInputData(centres)
    valid = resample.GetOutput().NewInstance()
    valid.CopyStructure(resample.GetOutput())
    valid.GetPointData().SetScalars(mask)
    mask_probe.SetSourceData(valid)
    mask_probe.Update()
    interior = inside & (vtk_to_numpy(mask_probe.GetOutput().GetPointData().GetScalars()) > 0.999)
    return (4 * size ** 3, error.max(), np.sqrt((error ** 2).mean()), error[interior].max(),
            (~interior).sum(), resample.GetOutput())


def render(p_fit, u_fit, png, trimmed, size=(900, 420)):
    prop = vtkVolumeProperty()
    color = vtkColorTransferFunction()
    opacity = vtkPiecewiseFunction()
    low, high = p_fit.GetOutput().GetBlock(0).GetFieldData().GetArray("LRFitDataRange").GetTuple2(0)
    for fraction, rgb, alpha in ((0.0, (0.23, 0.30, 0.75), 0.15), (0.5, (0.87, 0.87, 0.87), 0.1),
                                 (1.0, (0.71, 0.02, 0.15), 0.3)):
        value = low + fraction * (high - low)
        color.AddRGBPoint(value, *rgb)
        opacity.AddPoint(value, alpha)
    prop.SetColor(color)
    prop.SetScalarOpacity(opacity)
    prop.SetInterpolationTypeToLinear()
    prop.SetScalarOpacityUnitDistance(0.004)
    mapper = splineviz.vtkLRSplineVolumeMapper()
    mapper.SetInputConnection(p_fit.GetOutputPort(0))
    mapper.SetFieldArray("p")
    # Trimmed by the mesh's boundary, which the fitted spline carries; the
    # untrimmed picture turns that off.
    mapper.SetTrimByDataBoundary(trimmed)
    volume = vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(prop)

    # Streamlines on the U spline from a line across the inlet (the duct's
    # first part runs along x at y in [0, 0.05]).
    bounds = p_fit.GetOutputDataObject(1).GetBounds()
    seeds = vtkLineSource()
    seeds.SetPoint1(bounds[0] + 0.02, 0.015, 0.0)
    seeds.SetPoint2(bounds[0] + 0.02, 0.035, 0.0)
    seeds.SetResolution(12)
    tracer = splineviz.vtkLRSplineStreamTracer()
    tracer.SetInputConnection(u_fit.GetOutputPort(0))
    tracer.SetSourceConnection(seeds.GetOutputPort())
    tracer.SetIntegrationDirectionToForward()
    tracer.SetMaximumPropagation(10 * (bounds[1] - bounds[0]))
    tracer.Update()
    tubes = vtkTubeFilter()
    tubes.SetInputConnection(tracer.GetOutputPort())
    tubes.SetRadius(0.004 * (bounds[1] - bounds[0]))
    tubes.SetNumberOfSides(8)
    tube_mapper = vtkPolyDataMapper()
    tube_mapper.SetInputConnection(tubes.GetOutputPort())
    tube_mapper.ScalarVisibilityOff()
    tube_actor = vtkActor()
    tube_actor.SetMapper(tube_mapper)
    tube_actor.GetProperty().SetColor(0.15, 0.15, 0.15)

    renderer = vtkRenderer()
    renderer.SetBackground(1, 1, 1)
    renderer.AddVolume(volume)
    renderer.AddActor(tube_actor)
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetMultiSamples(0)
    window.SetSize(*size)
    window.AddRenderer(renderer)
    center = [0.5 * (bounds[2 * i] + bounds[2 * i + 1]) for i in range(3)]
    camera = renderer.GetActiveCamera()
    camera.SetFocalPoint(*center)
    camera.SetPosition(center[0] + 0.1, center[1] - 0.35, center[2] + 0.6)
    camera.SetViewUp(0, 1, 0)
    renderer.ResetCamera()
    camera.Zoom(1.3)
    start = time.time()
    window.Render()
    first = time.time() - start
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.Update()
    writer = vtkPNGWriter()
    writer.SetFileName(png)
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()
    return first, tracer.GetOutput().GetNumberOfPoints()


def main():
    foam = sys.argv[1]
    out = sys.argv[2] if len(sys.argv) > 2 else "."
    tolerance = float(sys.argv[3]) if len(sys.argv) > 3 else 0.01
    os.makedirs(out, exist_ok=True)
    reader, last = read_case(foam)
    mesh = reader.GetOutput().GetBlock(0)
    print("OpenFOAM case %s, time %g: %d cells, %d points" % (foam, last, mesh.GetNumberOfCells(),
                                                           mesh.GetNumberOfPoints()))
    centres = vtkCellCenters()
    centres.SetInputData(mesh)
    centres.Update()
    fits = {}
    for name, array, mode in (("p", "p", 0), ("|U|", "U", 0)):
        lr_file = os.path.join(out, "openfoam-%s.lr" % array)
        f = fit(reader, array, tolerance, mode, lr_file)
        fits[name] = f
        values = vtk_to_numpy(mesh.GetCellData().GetArray(array))
        if values.ndim > 1:
            values = np.linalg.norm(values, axis=1)
        print("%s: %.2f s, %d elements, %d coefficients, %d levels, max error %.4g, RMS %.4g "
              "(tolerance %.4g = %g of the range %.4g), .lr %d bytes"
              % (name, f.GetFitTime(), f.GetNumberOfElements(), f.GetNumberOfBasisFunctions(),
                 f.GetNumberOfRefinementLevels(), f.GetMaximumError(), f.GetRMSError(),
                 f.GetAbsoluteTolerance(), tolerance, values.max() - values.min(),
                 os.path.getsize(lr_file)))
        for size in (128, 256):
            nbytes, worst, rms, interior, excluded, _ = resampled_error(
                mesh, centres.GetOutput(), values, array, size)
            print("   resampled to %d^3: %d bytes (%.1fx the .lr), max error %.4g, RMS %.4g; "
                  "max error %.4g without the %d centres next to the boundary"
                  % (size, nbytes, nbytes / os.path.getsize(lr_file), worst, rms, interior,
                     excluded))
    u_fit = fit(reader, "U", 0.05, 1)
    print("U (3 components, 5 %%): %.2f s, %d elements, max error %.4g"
          % (u_fit.GetFitTime(), u_fit.GetNumberOfElements(), u_fit.GetMaximumError()))
    for trimmed, suffix in ((True, ""), (False, "-untrimmed")):
        png = os.path.join(out, "lr-spline-fit-openfoam%s.png" % suffix)
        first, points = render(fits["p"], u_fit, png, trimmed)
        print("%s: first frame %.2f s, %d streamline points" % (png, first, points))


if __name__ == "__main__":
    main()
