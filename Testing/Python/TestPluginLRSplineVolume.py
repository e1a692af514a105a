# SPDX-License-Identifier: BSD-3-Clause
"""pvbatch: the "LR-Spline Volume" representation of the SplineViz plugin on the
real 3-patch LR-spline file, read by the plugin's reader.

The independent check: the pictures ParaView renders (composite, maximum
intensity, isosurface, a vector component, shading, a moved and scaled
actor, hidden patches, a trimming sphere) are rendered a second time in
plain VTK by vtkLRSplineVolumeMapper from the file read by vtkLRSplineReader, with the
transfer functions rebuilt from the values ParaView shows (the lookup
table's RGBPoints, the opacity function's Points, the unit distance, the iso
values) and ParaView's camera and lights; each pair must agree to an RMS
of at most 1 (0-255 scale). Negative controls: references with a wrong field
(a component instead of the magnitude), a wrong unit distance or the
untrimmed volume are far from ParaView's pictures, so the comparison can
fail. Also: the pictures are non-trivial and differ between the blend
modes, nothing is drawn outside the trimming sphere's silhouette (the
untrimmed volume is), the trimming surface follows its source, the camera
reset frames the spline (bounds), every property reaches the mapper or the
volume property, interactive (LOD) renders draw the outline, selections do
not crash, a data set that is no LR spline gives a clear error and nothing
drawn.

    pvbatch TestPluginLRSplineVolume.py PLUGIN
    mpiexec -np 2 pvbatch TestPluginLRSplineVolume.py parallel
        (plugin on PV_PLUGIN_PATH: the pictures of two ranks composited by
        IceT against the same plain-VTK references)
"""
import os
import sys

import numpy as np
from paraview.simple import *  # noqa: F401,F403

import splineviz
from splineviz_testing import compare_baseline, output_dir, png_rgb, set_translation, white_view

PARALLEL = len(sys.argv) > 1 and sys.argv[1] == "parallel"
if PARALLEL:
    from splineviz.plugin import load_plugin

    load_plugin(globals())
else:
    LoadPlugin(sys.argv[1], remote=False, ns=globals())  # noqa: F405

from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402
from vtkmodules.vtkCommonCore import vtkLogger  # noqa: E402
from vtkmodules.vtkCommonDataModel import vtkMultiBlockDataSet, vtkPiecewiseFunction  # noqa: E402
from vtkmodules.vtkFiltersSources import vtkSphereSource  # noqa: E402
from vtkmodules.vtkIOImage import vtkPNGWriter  # noqa: E402
from vtkmodules.vtkRenderingCore import (  # noqa: E402
    vtkColorTransferFunction,
    vtkLight,
    vtkRenderer,
    vtkRenderWindow,
    vtkVolume,
    vtkVolumeProperty,
    vtkWindowToImageFilter,
)

PATH = os.path.join(os.environ["SPLINEVIZ_SOURCE_DIR"], "Testing", "Data", "External",
                    "cube-3patch-refined.lr")
SIZE = [256, 200]
TOLERANCE = 1.0  # RMS, 0-255 scale
TAG = "TestPluginLRSplineVolume" + ("-2ranks" if PARALLEL else "")
SPHERE = dict(Center=[0.5, 0.45, 0.5], Radius=0.38, ThetaResolution=48, PhiResolution=48)
from splineviz_testing import Checker  # noqa: E402

checker = Checker()


fail = checker.fail


def rms(a, b):
    return float(np.sqrt(((a.astype(float) - b.astype(float)) ** 2).mean()))


def changed(a, b):
    """Fraction of the pixels that differ by more than 10 in some channel."""
    return float((np.abs(a - b).max(axis=2) > 10).mean())


def drawn(rgb):
    """Pixels that differ from the white background."""
    return np.abs(rgb - 255).max(axis=2) > 2


# --- ParaView ---------------------------------------------------------------
reader = OpenDataFile(PATH)  # noqa: F405
# Single-sampled without FXAA (FXAA runs after IceT compositing only: it
# would differ from one rank), as the baseline picture is.
view = white_view(SIZE, baseline=True)
display = Show(reader, view)  # noqa: F405
if display.GetXMLName() != "UnstructuredGridRepresentation":
    fail("the reader's output is shown by %s" % display.GetXMLName())
if "LR-Spline Volume" not in display.GetProperty("Representation").Available:
    fail("'LR-Spline Volume' is not among the representation types")
display.SetRepresentationType("LR-Spline Volume")
ColorBy(display, ("POINTS", "Field", "Magnitude"))  # noqa: F405
lut = GetColorTransferFunction("Field")  # noqa: F405
lut.ApplyPreset("Viridis (matplotlib)", True)
lut.Discretize = 0  # the reference rebuilds the continuous function from RGBPoints
lut.RescaleTransferFunction(0.0, 2.45)
pwf = GetOpacityTransferFunction("Field")  # noqa: F405
pwf.Points = [0.0, 0.0, 0.5, 0.0, 0.9, 0.02, 0.5, 0.0, 1.6, 0.35, 0.5, 0.0, 2.45, 0.9, 0.5, 0.0]
pwf.RescaleTransferFunction(0.0, 2.45)
ResetCamera(view)  # noqa: F405
Render(view)  # noqa: F405
UNIT_DISTANCE = display.ScalarOpacityUnitDistance  # ParaView's default: a cell's size

subrep = display.GetClientSideObject().GetActiveRepresentation()
if subrep.GetClassName() != "vtkLRSplineVolumeRepresentation":
    fail("the active representation is %s" % subrep.GetClassName())
actor = subrep.GetActor()
mapper = actor.GetMapper()
if mapper is None or not mapper.IsA("vtkLRSplineVolumeMapper"):
    fail("the representation does not render with vtkLRSplineVolumeMapper")

# The camera reset frames the spline: the bounds reach the view.
focal = np.array(view.CameraFocalPoint)
if np.abs(focal - 0.5).max() > 1e-6:
    fail("the camera reset does not look at the spline's centre: %s" % focal)
reset_png = os.path.join(output_dir(), TAG + "-reset.png")
SaveScreenshot(reset_png, view, ImageResolution=SIZE)  # noqa: F405
reset = drawn(png_rgb(reset_png))
border = np.concatenate([reset[0], reset[-1], reset[:, 0], reset[:, -1]])
print("after the camera reset: %.3f of the picture drawn, %d border pixels" % (
    reset.mean(), border.sum()))
if reset.mean() < 0.15 or border.any():
    fail("the camera reset does not frame the volume (bounds wrong?)")

# A fixed oblique camera for the comparisons.
view.CameraPosition = [2.3, 1.7, 3.1]
view.CameraFocalPoint = [0.5, 0.5, 0.5]
view.CameraViewUp = [0, 1, 0]
view.CameraViewAngle = 30
Render(view)  # noqa: F405
if mapper.GetLastErrorMessage():
    fail("mapper error: %s" % mapper.GetLastErrorMessage())


def paraview_image(name):
    png = os.path.join(output_dir(), "%s-%s.png" % (TAG, name))
    SaveScreenshot(png, view, ImageResolution=SIZE)  # noqa: F405
    if mapper.GetLastErrorMessage():
        fail("%s: mapper error: %s" % (name, mapper.GetLastErrorMessage()))
    return png_rgb(png)


# --- plain VTK: the same scene without ParaView --------------------------------
vtk_reader = splineviz.vtkLRSplineReader()
vtk_reader.SetFileName(PATH)
vtk_reader.Update()


def reference_window():
    """One window for all the plain-VTK pictures (shaders compiled once)."""
    ren = vtkRenderer()
    ren.SetBackground(1, 1, 1)
    ren.AutomaticLightCreationOff()
    win = vtkRenderWindow()
    win.SetOffScreenRendering(1)
    win.SetMultiSamples(0)
    win.SetSize(SIZE)
    win.AddRenderer(ren)
    return {"renderer": ren, "window": win, "mapper": splineviz.vtkLRSplineVolumeMapper()}


REFERENCE = reference_window()


def view_lights():
    """ParaView's lights (its light kit and headlight), switched on."""
    ren = view.GetClientSideObject().GetRenderer()
    lights = ren.GetLights()
    lights.InitTraversal()
    found = []
    light = lights.GetNextItem()
    while light is not None:
        if light.GetSwitch():
            found.append(light)
        light = lights.GetNextItem()
    return found


def vtk_image(name, blend=0, component=-1, iso=(), shade=False, unit=None, blocks=None,
              sphere=None, position=(0, 0, 0), scale=(1, 1, 1)):
    """The picture vtkLRSplineVolumeMapper renders on its own with ParaView's
    camera, lights, and transfer functions rebuilt from the values
    ParaView shows."""
    data = vtk_reader.GetOutput()
    if blocks is not None:
        subset = vtkMultiBlockDataSet()
        for i, b in enumerate(blocks):
            subset.SetBlock(i, data.GetBlock(b))
        data = subset
    m = REFERENCE["mapper"]  # builds its GPU data again only when the data changes
    m.SetInputDataObject(data)
    m.SetFieldArray("Field")
    if component >= 0:
        m.SetVectorModeToComponent()
        m.SetVectorComponent(component)
    else:
        m.SetVectorModeToMagnitude()
    m.SetBlendMode(blend)
    m.SetTrimmingSurfaceConnection(None)
    if sphere is not None:
        source = vtkSphereSource()
        source.SetCenter(sphere["Center"])
        source.SetRadius(sphere["Radius"])
        source.SetThetaResolution(sphere["ThetaResolution"])
        source.SetPhiResolution(sphere["PhiResolution"])
        m.SetTrimmingSurfaceConnection(source.GetOutputPort())
    ctf = vtkColorTransferFunction()
    # ParaView's enumeration has vtkColorTransferFunction's values (RGB 0 ... Step 5).
    ctf.SetColorSpace(lut.SMProxy.GetProperty("ColorSpace").GetElement(0))
    points = list(lut.RGBPoints)
    for i in range(0, len(points), 4):
        ctf.AddRGBPoint(*points[i:i + 4])
    otf = vtkPiecewiseFunction()
    points = list(pwf.Points)
    for i in range(0, len(points), 4):
        otf.AddPoint(*points[i:i + 4])
    prop = vtkVolumeProperty()
    prop.SetColor(ctf)
    prop.SetScalarOpacity(otf)
    prop.SetScalarOpacityUnitDistance(unit if unit else display.ScalarOpacityUnitDistance)
    prop.SetShade(1 if shade else 0)
    prop.SetAmbient(display.Ambient)
    prop.SetDiffuse(display.Diffuse)
    prop.SetSpecular(display.Specular)
    prop.SetSpecularPower(display.SpecularPower)
    for i, value in enumerate(iso):
        prop.GetIsoSurfaceValues().SetValue(i, value)
    volume = vtkVolume()
    volume.SetMapper(m)
    volume.SetProperty(prop)
    volume.SetPosition(position)
    volume.SetScale(scale)
    ren = REFERENCE["renderer"]
    ren.RemoveAllViewProps()
    ren.AddVolume(volume)
    ren.RemoveAllLights()
    for pv_light in view_lights():  # the mapper sums all lights
        light = vtkLight()
        light.SetLightType(pv_light.GetLightType())
        light.SetPosition(pv_light.GetPosition())
        light.SetFocalPoint(pv_light.GetFocalPoint())
        light.SetIntensity(pv_light.GetIntensity())
        light.SetDiffuseColor(pv_light.GetDiffuseColor())
        light.SetSpecularColor(pv_light.GetSpecularColor())
        light.SetPositional(pv_light.GetPositional())
        ren.AddLight(light)
    cam = ren.GetActiveCamera()
    cam.SetPosition(view.CameraPosition)
    cam.SetFocalPoint(view.CameraFocalPoint)
    cam.SetViewUp(view.CameraViewUp)
    cam.SetViewAngle(view.CameraViewAngle)
    ren.ResetCameraClippingRange()
    win = REFERENCE["window"]
    win.Render()
    if m.GetLastErrorMessage():
        fail("reference %s: mapper error: %s" % (name, m.GetLastErrorMessage()))
    grab = vtkWindowToImageFilter()
    grab.SetInput(win)
    grab.ReadFrontBufferOff()
    grab.Update()
    writer = vtkPNGWriter()
    writer.SetFileName(os.path.join(output_dir(), "%s-%s-vtk.png" % (TAG, name)))
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()
    rgb = vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars())[:, :3].astype(int)
    ren.RemoveAllViewProps()
    return rgb.reshape(SIZE[1], SIZE[0], 3)


def compare(name, pv, **settings):
    """ParaView's picture against the plain-VTK one; returns the RMS."""
    reference = vtk_image(name, **settings)
    error = rms(pv, reference)
    print("%-22s ParaView vs plain VTK: RMS %.3f, max %d, drawn %.3f / %.3f" % (
        name, error, np.abs(pv - reference).max(), drawn(pv).mean(), drawn(reference).mean()))
    if error > TOLERANCE:
        fail("%s: ParaView's picture differs from the mapper's own (RMS %.3f > %.1f)" % (
            name, error, TOLERANCE))
    return error


def negative(name, pv, **settings):
    """A deliberately wrong reference must be far from ParaView's picture."""
    error = rms(pv, vtk_image(name, **settings))
    print("%-22s negative control: RMS %.3f (must exceed %.1f)" % (name, error, 5 * TOLERANCE))
    if error <= 5 * TOLERANCE:
        fail("negative control %s: the comparison cannot tell a wrong setting (RMS %.3f)" % (
            name, error))


# --- blend modes ----------------------------------------------------------------
# (Under MPI: composite, isosurface and trimming only, the rest is the same.)
SERIAL = not PARALLEL
composite = paraview_image("composite")
compare("composite", composite)
if SERIAL:
    # The picture itself, against its baseline (Testing/Data/Baseline).
    checker.check(compare_baseline(view, TAG + "-composite.png"),
                  "the composite picture matches its baseline")
    negative("wrong-field", composite, component=0)
    negative("wrong-unit-distance", composite, unit=4.0 * display.ScalarOpacityUnitDistance)
    display.BlendMode = "Maximum Intensity"
    mip = paraview_image("mip")
    compare("maximum-intensity", mip, blend=1)
display.BlendMode = "Isosurface"
display.IsosurfaceValues = [1.3]
iso = paraview_image("isosurface")
compare("isosurface", iso, blend=5, iso=[1.3])
if SERIAL:
    display.Shade = 1
    iso_shaded = paraview_image("isosurface-shaded")
    compare("isosurface-shaded", iso_shaded, blend=5, iso=[1.3], shade=True)
    display.Shade = 0
display.BlendMode = "Composite"

if SERIAL:
    pictures = {"composite": composite, "maximum intensity": mip, "isosurface": iso}
    for name, picture in pictures.items():
        print("%-18s drawn %.3f, mean color %s" % (
            name, drawn(picture).mean(), picture[drawn(picture)].mean(axis=0).round(1)))
        if drawn(picture).mean() < 0.15:
            fail("the %s picture is (nearly) empty" % name)
    names = list(pictures)
    for i in range(len(names)):
        for j in range(i + 1, len(names)):
            change = changed(pictures[names[i]], pictures[names[j]])
            print("%s vs %s: %.3f of the pixels differ" % (names[i], names[j], change))
            if change < 0.1:
                fail("the %s and %s pictures hardly differ" % (names[i], names[j]))

# --- a trimming sphere: nothing outside its silhouette ------------------------------
sphere = Sphere(**SPHERE)  # noqa: F405
sphere_display = Show(sphere, view)  # noqa: F405
sphere_display.SetRepresentationType("Surface")
sphere_display.ColorArrayName = ["POINTS", ""]
sphere_display.AmbientColor = sphere_display.DiffuseColor = [0.2, 0.2, 0.2]
Hide(reader, view)  # noqa: F405
silhouette = drawn(paraview_image("sphere"))
Hide(sphere, view)  # noqa: F405
Show(reader, view)  # noqa: F405
display.TrimmingSurface = sphere
trimmed = paraview_image("trimmed")
# The trimming pre-pass rasterizes the same polygons as the sphere's own
# picture: not one pixel may lie outside that silhouette.
outside = drawn(trimmed) & ~silhouette
untrimmed_outside = drawn(composite) & ~silhouette
print("trimming sphere: silhouette %.3f, trimmed volume %.3f, drawn outside %d px "
      "(untrimmed: %d px)" % (silhouette.mean(), drawn(trimmed).mean(), outside.sum(),
                             untrimmed_outside.sum()))
if outside.any():
    fail("%d pixels drawn outside the trimming sphere's silhouette" % outside.sum())
if untrimmed_outside.sum() < 1000:
    fail("negative control: the untrimmed volume should cover pixels outside the sphere")
if drawn(trimmed).mean() < 0.5 * silhouette.mean():
    fail("the trimmed volume covers too little of the sphere's silhouette")
compare("trimmed", trimmed, sphere=SPHERE)
if SERIAL:
    negative("untrimmed", trimmed)
    # The trimming surface follows its source.
    sphere.Radius = 0.25
    smaller = paraview_image("trimmed-smaller")
    print("smaller sphere: drawn %.3f" % drawn(smaller).mean())
    if not drawn(smaller).mean() < 0.7 * drawn(trimmed).mean():
        fail("changing the trimming sphere's radius does not reach the mapper")
    compare("trimmed-smaller", smaller, sphere=dict(SPHERE, Radius=0.25))
    sphere.Radius = SPHERE["Radius"]
    display.TrimmingSurface = None
    again = paraview_image("untrimmed-again")
    if rms(again, composite) > TOLERANCE:
        fail("removing the trimming surface does not restore the whole volume")


def serial_checks():
    """What runs once, in one process (the rest also runs under MPI)."""
    # --- a vector component, shading, hidden patches -------------------------------------
    ColorBy(display, ("POINTS", "Field", "Y"))  # noqa: F405
    lut.Discretize = 0
    Render(view)  # noqa: F405
    if mapper.GetVectorMode() != mapper.COMPONENT or mapper.GetVectorComponent() != 1:
        fail("the color map's component does not reach the mapper")
    component = paraview_image("component-y")
    compare("component-y", component, component=1)
    ColorBy(display, ("POINTS", "Field", "Magnitude"))  # noqa: F405
    Render(view)  # noqa: F405
    if mapper.GetVectorMode() != mapper.MAGNITUDE:
        fail("the color map's magnitude mode does not reach the mapper")

    display.Shade = 1
    display.Specular = 0.4
    display.Diffuse = 0.8
    display.Ambient = 0.1
    shaded = paraview_image("composite-shaded")
    compare("composite-shaded", shaded, shade=True)
    if rms(shaded, composite) < 2.0:
        fail("Shade does not change the picture")
    display.Shade = 0
    display.Specular = 0.0
    display.Diffuse = 1.0
    display.Ambient = 0.0

    # The actor's transform.
    set_translation(display, [0.15, -0.1, 0.0])
    display.Scale = [1.0, 0.8, 1.2]
    moved = paraview_image("transformed")
    compare("transformed", moved, position=(0.15, -0.1, 0.0), scale=(1.0, 0.8, 1.2))
    if changed(moved, composite) < 0.1:
        fail("Position and Scale do not move the volume")
    set_translation(display, [0.0, 0.0, 0.0])
    display.Scale = [1.0, 1.0, 1.0]

    # Patch 0 holds (x, y, z), patch 1 (-y, x, z): the same magnitude, other components.
    ColorBy(display, ("POINTS", "Field", "X"))  # noqa: F405
    lut.Discretize = 0
    all_patches = paraview_image("component-x")
    display.BlockSelectors = ["/Root/Patch1", "/Root/Patch2"]
    hidden = paraview_image("component-x-patches-1-2")
    compare("component-x-patches-1-2", hidden, component=0, blocks=[1, 2])
    print("hiding patch 0: %.3f of the pixels change" % changed(hidden, all_patches))
    if changed(hidden, all_patches) < 0.1:
        fail("hiding a patch does not change the picture")
    display.BlockSelectors = ["/"]
    ColorBy(display, ("POINTS", "Field", "Magnitude"))  # noqa: F405

    # A cell array cannot be rendered (the field is the points' Bezier
    # coefficients): a warning, and the spline's default field.
    vtkLogger.SetStderrVerbosity(vtkLogger.VERBOSITY_ERROR)  # the expected warning only
    ColorBy(display, ("CELLS", "LRElementMinSide"))  # noqa: F405
    cell_colored = paraview_image("cell-array")
    vtkLogger.SetStderrVerbosity(vtkLogger.VERBOSITY_INFO)
    print("colored by a cell array: field %r, drawn %.3f" % (
        mapper.GetFieldArray(), drawn(cell_colored).mean()))
    if mapper.GetFieldArray() is not None or drawn(cell_colored).mean() < 0.15:
        fail("coloring by a cell array does not fall back to the spline's field")
    # No color array at all: the default field through ParaView's default maps over its
    # range (TestPluginLRSplineVolumeDefault compares that picture with ParaView's colouring).
    ColorBy(display, None)  # noqa: F405
    uncolored = paraview_image("no-color-array")
    shown = uncolored[drawn(uncolored)]
    print("no color array: field %r, drawn %.3f, mean color %s, darkest %d" % (
        mapper.GetFieldArray(), drawn(uncolored).mean(), shown.mean(axis=0).round(1),
        shown.min()))
    if drawn(uncolored).mean() < 0.15 or shown.min() < 60:
        fail("without a color array the volume is not drawn as a translucent volume")
    ColorBy(display, ("POINTS", "Field", "Magnitude"))  # noqa: F405
    lut.Discretize = 0
    after = paraview_image("colored-again")
    if rms(after, composite) > TOLERANCE:
        fail("coloring by Field again does not restore ParaView's color map and opacity")

    # --- every property reaches the mapper or the volume property -------------------------
    settings = {
        "ElementLocator": ("ElementLocator", 1),
        "ForestResolution": ("ForestResolution", 5),
        "AdaptiveSteps": ("AdaptiveSteps", 0),
        "StepScale": ("StepScale", 0.5),
        "SampleDistance": ("SampleDistance", 0.01),
        "Supersampling": ("Supersampling", 2),
        "UseJittering": ("UseJittering", 1),
        "ShadingModel": ("ShadingModel", 1),
        "IsosurfaceBisections": ("IsosurfaceBisections", 20),
        "MaximumNumberOfSteps": ("MaximumNumberOfSteps", 4000),
    }
    for name, (_, value) in settings.items():
        setattr(display, name, value)
    display.BlendMode = "Minimum Intensity"
    display.LRSplineScalarOpacityUnitDistance = 0.2
    Render(view)  # noqa: F405
    for name, (getter, value) in settings.items():
        got = getattr(mapper, "Get" + getter)()
        if isinstance(got, bool):
            got = int(got)
        if got != value:
            fail("property %s not forwarded: %r instead of %r" % (name, got, value))
    if mapper.GetBlendMode() != 2:
        fail("BlendMode not forwarded: %r" % mapper.GetBlendMode())
    if abs(actor.GetProperty().GetScalarOpacityUnitDistance() - 0.2) > 1e-12:
        fail("the scalar opacity unit distance does not reach the volume property")
    minip = paraview_image("minip-fixed-steps")
    if mapper.GetLastErrorMessage() or drawn(minip).mean() < 0.15:
        fail("minimum intensity with fixed steps, k-d tree, jittering did not render")
    for name, value in {"ElementLocator": 2, "ForestResolution": 0, "AdaptiveSteps": 1,
                        "StepScale": 1.0, "SampleDistance": 0.0, "Supersampling": 4,
                        "UseJittering": 0, "ShadingModel": 0, "IsosurfaceBisections": 16,
                        "MaximumNumberOfSteps": 8192}.items():
        setattr(display, name, value)
    display.BlendMode = "Composite"
    display.LRSplineScalarOpacityUnitDistance = UNIT_DISTANCE
    Render(view)  # noqa: F405

    # --- interactive renders: the outline; selection does not crash ------------------------
    view.LODThreshold = 0.0
    reader.SMProxy.MarkModified(reader.SMProxy)  # the view decides about LOD when it updates
    view.SMProxy.InteractiveRender()
    grab = vtkWindowToImageFilter()
    grab.SetInput(view.GetRenderWindow())
    grab.ShouldRerenderOff()  # the interactive picture, not a new still render
    grab.ReadFrontBufferOn()
    grab.Update()
    writer = vtkPNGWriter()
    writer.SetFileName(os.path.join(output_dir(), TAG + "-interactive-outline.png"))
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()
    lod = vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars())[:, :3].astype(int)
    lod_drawn = float((np.abs(lod - 255).max(axis=1) > 2).mean())
    print("interactive render: LOD enabled %d, %.4f of the picture drawn" % (
        actor.GetEnableLOD(), lod_drawn))
    if not actor.GetEnableLOD() or not 0.002 < lod_drawn < 0.05:
        fail("interactive renders do not draw the outline of the patches' box")
    view.LODThreshold = 1e9
    Render(view)  # noqa: F405
    SetActiveSource(reader)  # noqa: F405
    SelectSurfaceCells(Rectangle=[80, 60, 180, 140])  # noqa: F405
    Render(view)  # noqa: F405
    ClearSelection(reader)  # noqa: F405
    print("a selection over the volume did not crash")

    # --- bad input: a data set that is no LR spline ---------------------------------------
    vtkLogger.SetStderrVerbosity(vtkLogger.VERBOSITY_OFF)  # the expected error only
    wavelet = Tetrahedralize(Input=Wavelet(WholeExtent=[0, 4, 0, 4, 0, 4]))  # noqa: F405
    Hide(reader, view)  # noqa: F405
    bad = Show(wavelet, view)  # noqa: F405
    bad.SetRepresentationType("LR-Spline Volume")
    ColorBy(bad, ("POINTS", "RTData"))  # noqa: F405
    Render(view)  # noqa: F405
    bad_mapper = bad.GetClientSideObject().GetActiveRepresentation().GetActor().GetMapper()
    message = bad_mapper.GetLastErrorMessage() if bad_mapper else ""
    png = os.path.join(output_dir(), TAG + "-not-a-spline.png")
    SaveScreenshot(png, view, ImageResolution=SIZE)  # noqa: F405
    vtkLogger.SetStderrVerbosity(vtkLogger.VERBOSITY_INFO)
    print("not a spline: error '%s', drawn %.4f" % (message, drawn(png_rgb(png)).mean()))
    if not message or drawn(png_rgb(png)).any():
        fail("a data set that is no LR spline does not give a clear error and an empty picture")


if PARALLEL:
    from paraview import servermanager  # noqa: E402

    ranks = servermanager.ActiveConnection.GetNumberOfDataPartitions()
    print("ranks: %d" % ranks)
    if ranks < 2:
        fail("the parallel test runs on %d rank(s)" % ranks)
else:
    serial_checks()
checker.finish()
print("all checks passed")
