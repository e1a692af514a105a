# SPDX-License-Identifier: BSD-3-Clause
"""A real MR scan as an LR spline: DIPY's aniso_vox.nii.gz fitted by local refinement.

    source build/splineviz-env.sh
    pvpython Examples/Python/lr_spline_fit_image.py [OUTPUT_DIR] [TOLERANCE]

1. VTK's vtkNIFTIImageReader reads the scan that Debian's python3-dipy ships
   (dipy/data/files/aniso_vox.nii.gz: a brain, 58 x 58 x 24 voxels of
   4 x 4 x 5 mm, values 0 to 2149). The reader places it by its spacing (the
   scanner's oblique affine is its QFormMatrix, not applied).
2. vtkLRSplineImageFitter fits a quadratic LR spline to the voxel values by
   least squares, refining locally (structured mesh refinement of the basis
   functions on the elements that are off) until every voxel is within
   TOLERANCE (default 0.02, i.e. 2 % of the data range), as the LR splines
   that Fuchs et al. volume render are made.
3. It prints the maximum and RMS error over the voxels, the numbers of
   elements, basis functions and refinement levels, the time, and the size
   of the spline against the image's; it writes the spline as
   OUTPUT_DIR/aniso_vox.lr and reads it back with vtkLRSplineReader (placed
   by PhysicalBounds = the image's bounds) to show that it is the same
   spline.
4. OUTPUT_DIR/lr-spline-fit-aniso-vox.png: the middle slice of the scan, of
   the spline, of the error |spline - scan| (0 to the tolerance) and of the
   side of the element each voxel is in (VTK's own vtkProbeFilter on the
   Bezier cells): small elements where the scan varies.
5. OUTPUT_DIR/lr-spline-fit-aniso-vox-volume.png: the scan volume rendered
   the VTK way (vtkSmartVolumeMapper on the voxels, left) and the fitted
   spline volume rendered by vtkLRSplineVolumeMapper on the GPU from its
   Bezier coefficients, without resampling (right), with the same transfer
   function, shading and camera; it prints the mapper's GPU bytes against
   the image's.

The output of the fitter is what vtkLRSplineReader gives for an .lr file (one
block of Bezier hexahedra per patch), so everything that takes a spline
(probe, resampling, stream tracer, ParaView's LR-spline filters) takes it.
`fit_scan()` can be imported by other scripts.
"""
import os
import sys
import time

from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkLookupTable
from vtkmodules.vtkCommonDataModel import vtkImageData, vtkStaticCellLocator
from vtkmodules.vtkFiltersCore import vtkProbeFilter
from vtkmodules.vtkImagingCore import vtkExtractVOI, vtkImageMapToColors
from vtkmodules.vtkIOImage import vtkNIFTIImageReader, vtkPNGWriter
from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction
from vtkmodules.vtkRenderingCore import (
    vtkColorTransferFunction,
    vtkImageActor,
    vtkRenderer,
    vtkRenderWindow,
    vtkTextActor,
    vtkVolume,
    vtkVolumeProperty,
    vtkWindowToImageFilter,
)
from vtkmodules.vtkRenderingVolumeOpenGL2 import vtkSmartVolumeMapper
import vtkmodules.vtkRenderingFreeType  # noqa: F401  (text)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (OpenGL render window)

import splineviz


def scan_path(name="aniso_vox.nii.gz"):
    """The path of a scan that python3-dipy ships (None when DIPY is not installed)."""
    try:
        import dipy.data
    except ImportError:
        return None
    path = os.path.join(os.path.dirname(dipy.data.__file__), "files", name)
    return path if os.path.exists(path) else None


def fit_scan(path, tolerance=0.02, file_name=None):
    """Read a NIfTI scan and fit an LR spline to it; returns (reader, fitter, seconds)."""
    reader = vtkNIFTIImageReader()
    reader.SetFileName(path)
    reader.Update()
    fitter = splineviz.vtkLRSplineImageFitter()
    fitter.SetInputConnection(reader.GetOutputPort())
    fitter.SetDegree(2, 2, 2)                  # Fuchs' splines are quadratic
    fitter.SetToleranceModeToRelative()        # a fraction of the data range ...
    fitter.SetTolerance(tolerance)             # ... at every voxel
    fitter.SetOutputFieldName("intensity")
    if file_name:
        fitter.SetFileName(file_name)          # also write the .lr file
    start = time.perf_counter()
    fitter.Update()
    return reader, fitter, time.perf_counter() - start


def slice_picture(reader, fitter, png, size=260):
    """The middle slice: scan, spline, |spline - scan| and element side, side by side."""
    image = reader.GetOutput()
    nx, ny, nz = image.GetDimensions()
    k = nz // 2
    voi = vtkExtractVOI()
    voi.SetInputConnection(reader.GetOutputPort())
    voi.SetVOI(0, nx - 1, 0, ny - 1, k, k)
    voi.Update()
    spline = splineviz.vtkLRSplineProbeFilter()
    spline.SetInputConnection(voi.GetOutputPort())
    spline.SetSourceConnection(fitter.GetOutputPort())
    spline.Update()
    grid = fitter.GetOutput().GetBlock(0)
    sides = vtkProbeFilter()  # VTK's own search and Bezier cell inversion
    sides.SetCellLocatorPrototype(vtkStaticCellLocator())
    sides.SetInputConnection(voi.GetOutputPort())
    sides.SetSourceData(grid)
    sides.Update()
    name = grid.GetPointData().GetScalars().GetName()
    scan = vtk_to_numpy(voi.GetOutput().GetPointData().GetScalars()).astype(float)
    fitted = vtk_to_numpy(spline.GetOutput().GetPointData().GetArray(name))
    side = vtk_to_numpy(sides.GetOutput().GetPointData().GetArray("LRElementMinSide")) / image.GetSpacing()[0]
    low, high = image.GetScalarRange()
    tol = fitter.GetAbsoluteTolerance()
    window_level = (low, low + 0.5 * (high - low))  # the brightest tenth saturates
    panels = [("scan, slice %d" % k, scan, window_level, "grey"),
              ("LR spline", fitted, window_level, "grey"),
              ("error, 0 to %.0f (tolerance)" % tol, abs(fitted - scan), (0, tol), "hot"),
              ("element side: 0.5 (blue) to 8 voxels", side, (0.5, 8.0), "log")]
    window = vtkRenderWindow()
    window.SetOffScreenRendering(True)
    window.SetSize(size * len(panels), size + 30)
    window.SetMultiSamples(0)
    for i, (title, values, (vmin, vmax), kind) in enumerate(panels):
        plane = vtkImageData()
        plane.SetDimensions(nx, ny, 1)
        plane.SetSpacing(image.GetSpacing()[0], image.GetSpacing()[1], 1)
        plane.GetPointData().SetScalars(numpy_to_vtk(values.astype(float), deep=True))
        lut = vtkLookupTable()
        lut.SetRange(vmin, vmax)
        if kind == "grey":
            lut.SetSaturationRange(0, 0)
            lut.SetValueRange(0, 1)
        elif kind == "hot":
            lut.SetHueRange(0.0, 0.17)
            lut.SetValueRange(0.2, 1)
        else:
            lut.SetScaleToLog10()
            lut.SetHueRange(0.67, 0.0)
        lut.Build()
        colors = vtkImageMapToColors()
        colors.SetInputData(plane)
        colors.SetLookupTable(lut)
        actor = vtkImageActor()
        actor.GetMapper().SetInputConnection(colors.GetOutputPort())
        label = vtkTextActor()
        label.SetInput(title)
        label.GetTextProperty().SetFontSize(14)
        label.GetTextProperty().SetColor(0, 0, 0)
        label.SetPosition(6, size + 8)
        renderer = vtkRenderer()
        renderer.SetViewport(i / len(panels), 0, (i + 1) / len(panels), 1)
        renderer.SetBackground(1, 1, 1)
        renderer.AddActor(actor)
        renderer.AddActor2D(label)
        window.AddRenderer(renderer)
        renderer.ResetCamera()
        camera = renderer.GetActiveCamera()
        camera.ParallelProjectionOn()
        camera.SetParallelScale(0.5 * image.GetSpacing()[1] * ny * (size + 30) / size)
        camera.SetFocalPoint(*(0.5 * image.GetSpacing()[0] * (nx - 1),
                               0.5 * image.GetSpacing()[1] * (ny - 1) + 12, 0))
        camera.SetPosition(*(0.5 * image.GetSpacing()[0] * (nx - 1),
                             0.5 * image.GetSpacing()[1] * (ny - 1) + 12, 100))
        camera.SetViewUp(0, 1, 0)
        renderer.ResetCameraClippingRange()
    window.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    writer = vtkPNGWriter()
    writer.SetFileName(png)
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()
    return side


def volume_picture(reader, fitter, png, size=(720, 380)):
    """The scan (vtkSmartVolumeMapper) and its spline (vtkLRSplineVolumeMapper) side by side.

    Returns the spline mapper (for its GPU bytes and element count)."""
    image = reader.GetOutput()
    low, high = image.GetScalarRange()
    prop = vtkVolumeProperty()
    color = vtkColorTransferFunction()
    opacity = vtkPiecewiseFunction()
    # background and noise transparent, tissue warm and faint, bright
    # structures (fluid, fat) opaque and pale
    for fraction, rgb, alpha in ((0.0, (0.0, 0.0, 0.0), 0.0),
                                 (0.10, (0.45, 0.15, 0.05), 0.0),
                                 (0.25, (0.95, 0.55, 0.30), 0.12),
                                 (0.45, (1.0, 0.85, 0.60), 0.45),
                                 (1.0, (1.0, 1.0, 0.95), 1.0)):
        value = low + fraction * (high - low)
        color.AddRGBPoint(value, *rgb)
        opacity.AddPoint(value, alpha)
    prop.SetColor(color)
    prop.SetScalarOpacity(opacity)
    prop.SetInterpolationTypeToLinear()
    prop.ShadeOn()
    prop.SetAmbient(0.3)
    prop.SetDiffuse(0.7)
    prop.SetSpecular(0.2)
    prop.SetScalarOpacityUnitDistance(4.0)   # one voxel side (mm)

    voxels = vtkSmartVolumeMapper()
    voxels.SetInputConnection(reader.GetOutputPort())
    voxels.SetRequestedRenderModeToGPU()
    spline = splineviz.vtkLRSplineVolumeMapper()
    spline.SetInputConnection(fitter.GetOutputPort())
    spline.SetFieldArray("intensity")

    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetMultiSamples(0)
    window.SetSize(*size)
    bounds = image.GetBounds()
    center = [0.5 * (bounds[2 * i] + bounds[2 * i + 1]) for i in range(3)]
    for i, (mapper, title) in enumerate(((voxels, "voxels: vtkSmartVolumeMapper"),
                                         (spline, "LR spline: vtkLRSplineVolumeMapper"))):
        volume = vtkVolume()
        volume.SetMapper(mapper)
        volume.SetProperty(prop)
        label = vtkTextActor()
        label.SetInput(title)
        label.GetTextProperty().SetFontSize(14)
        label.GetTextProperty().SetColor(1, 1, 1)
        label.SetPosition(8, 8)
        renderer = vtkRenderer()
        renderer.SetViewport(i / 2, 0, (i + 1) / 2, 1)
        renderer.SetBackground(0.1, 0.1, 0.12)
        renderer.AddVolume(volume)
        renderer.AddActor2D(label)
        window.AddRenderer(renderer)
        camera = renderer.GetActiveCamera()
        camera.SetFocalPoint(*center)
        camera.SetPosition(center[0] + 150, center[1] - 260, center[2] + 170)
        camera.SetViewUp(0, 0, 1)
        renderer.ResetCamera()
        camera.Dolly(1.6)
        renderer.ResetCameraClippingRange()
    window.Render()
    if spline.GetLastErrorMessage():
        raise RuntimeError("vtkLRSplineVolumeMapper: " + spline.GetLastErrorMessage())
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    writer = vtkPNGWriter()
    writer.SetFileName(png)
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()
    return spline


def main():
    out_dir = sys.argv[1] if len(sys.argv) > 1 else "."
    tolerance = float(sys.argv[2]) if len(sys.argv) > 2 else 0.02
    os.makedirs(out_dir, exist_ok=True)
    path = scan_path()
    if path is None:
        print("DIPY's aniso_vox.nii.gz is not installed (Debian: python3-dipy)")
        return 125
    lr_file = os.path.join(out_dir, "aniso_vox.lr")
    reader, fitter, seconds = fit_scan(path, tolerance, lr_file)
    image = reader.GetOutput()
    voxels = image.GetNumberOfPoints()
    low, high = image.GetScalarRange()
    print("scan: %s, %d x %d x %d voxels of %s mm, values %g to %g"
          % (os.path.basename(path), *image.GetDimensions(), image.GetSpacing(), low, high))
    print("fit to %.3g %% of the range (%.4g): maximum error %.4g, RMS %.4g, tolerance %s"
          % (100 * tolerance, fitter.GetAbsoluteTolerance(), fitter.GetMaximumError(),
             fitter.GetRMSError(), "met" if fitter.GetToleranceMet() else "NOT met"))
    print("%d elements, %d basis functions, %d refinement levels, %d fits, %.2f s"
          % (fitter.GetNumberOfElements(), fitter.GetNumberOfBasisFunctions(),
             fitter.GetNumberOfRefinementLevels(), fitter.GetNumberOfIterations(), seconds))
    history = fitter.GetOutput().GetBlock(0).GetFieldData().GetArray("LRFitHistory")
    for i in range(history.GetNumberOfTuples()):
        elements, functions, worst, rms, solver = history.GetTuple(i)
        print("  fit %d: %6d elements, %6d functions, maximum error %8.2f, RMS %7.2f, "
              "%d CG iterations" % (i + 1, elements, functions, worst, rms, solver))
    print("spline: %d coefficients for %d voxels (%.2f per voxel)"
          % (fitter.GetNumberOfBasisFunctions(), voxels,
             fitter.GetNumberOfBasisFunctions() / voxels))

    # The .lr file read back: the same spline where the image is.
    back = splineviz.vtkLRSplineReader()
    back.SetFileName(lr_file)
    back.SetPhysicalBounds(image.GetBounds())
    back.SetOutputFieldName("intensity")
    back.Update()
    probe_a = splineviz.vtkLRSplineProbeFilter()
    probe_a.SetInputConnection(reader.GetOutputPort())   # at the voxels
    probe_a.SetSourceConnection(fitter.GetOutputPort())
    probe_a.Update()
    probe_b = splineviz.vtkLRSplineProbeFilter()
    probe_b.SetInputConnection(reader.GetOutputPort())
    probe_b.SetSourceConnection(back.GetOutputPort())
    probe_b.Update()
    a = probe_a.GetOutput().GetPointData().GetArray("intensity")
    b = probe_b.GetOutput().GetPointData().GetArray("intensity")
    difference = max(abs(a.GetValue(i) - b.GetValue(i)) for i in range(voxels))
    print("wrote %s (%d bytes); read back it differs from the fit by %.3g at the voxels"
          % (lr_file, os.path.getsize(lr_file), difference))
    if difference > 1e-9 * (high - low):
        print("ERROR: the .lr file does not hold the fitted spline")
        return 1
    png = os.path.join(out_dir, "lr-spline-fit-aniso-vox.png")
    side = slice_picture(reader, fitter, png)
    print("wrote %s: element sides %.1f to %.1f voxels on the middle slice"
          % (png, side.min(), side.max()))
    png = os.path.join(out_dir, "lr-spline-fit-aniso-vox-volume.png")
    mapper = volume_picture(reader, fitter, png)
    print("wrote %s: the spline's %d elements take %d bytes on the GPU (the image's "
          "float voxels: %d bytes)" % (png, mapper.GetNumberOfElements(),
                                       mapper.GetGPUMemorySize(), 4 * voxels))
    return 0


if __name__ == "__main__":
    code = main()
    if code:
        sys.exit(code)
