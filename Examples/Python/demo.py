# SPDX-License-Identifier: BSD-3-Clause
"""SplineViz demonstration: renders the built-in synthetic data sets with the
SplineViz renderers to PNG files.

    pvpython Examples/Python/demo.py OUTPUT_DIR

(scripts/demo.sh sets up, builds and runs this under an X display.)
"""
import os
import runpy
import sys

from vtkmodules.vtkFiltersCore import vtkTubeFilter
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import (
    vtkActor,
    vtkPolyDataMapper,
    vtkRenderer,
    vtkRenderWindow,
    vtkWindowToImageFilter,
)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (OpenGL render window)
import vtkmodules.vtkRenderingFreeType  # noqa: F401

import splineviz

out_dir = sys.argv[1] if len(sys.argv) > 1 else "."
os.makedirs(out_dir, exist_ok=True)


def save(window, name):
    window.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    grab.Update()
    writer = vtkPNGWriter()
    path = os.path.join(out_dir, name)
    writer.SetFileName(path)
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()
    print("wrote", path)


# --- Spline tubes (Salm) -----------------------------------------------------
# The built-in data set: smooth random fibers the size of Salm's "Fibers"
# (241 tubes, 3,530 segments), radius and color from point arrays.
fibers = splineviz.vtkSyntheticFibersSource()
fibers.SetPresetToFibers()
fibers.Update()


DARK = (0.08, 0.08, 0.1)


def render(actors, name, position, focal, view_up=(0, 1, 0), size=(800, 600),
           background=(1, 1, 1), samples=None, reset_camera=True):
    """Render `actors` off screen, the camera at `position` looking at
    `focal`, and save the picture as `name`. reset_camera: fit the view to
    the actors (keeping the direction), else only the clipping range;
    samples: multisampling (None: VTK's default)."""
    renderer = vtkRenderer()
    for actor in actors:
        renderer.AddActor(actor)
    renderer.SetBackground(*background)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(*position)
    camera.SetFocalPoint(*focal)
    camera.SetViewUp(*view_up)
    if reset_camera:
        renderer.ResetCamera()
    else:
        renderer.ResetCameraClippingRange()
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    if samples is not None:
        window.SetMultiSamples(samples)
    window.SetSize(*size)
    window.AddRenderer(renderer)
    save(window, name)


def fiber_view(actor, name, camera_position=(0.25, 0.35, 1.9), focal=(0, 0, 0), size=(800, 600),
               samples=0):
    """The fibers from a fixed camera on a dark background."""
    render([actor], name, camera_position, focal, size=size, background=DARK, samples=samples,
           reset_camera=False)


# Ray-cast spline tubes: exact sphere-swept surfaces, per-point radius
# (world units) and scalar colors following cubic splines, rounded caps.
raycast = splineviz.vtkRayCastTubeMapper()
raycast.SetInputConnection(fibers.GetOutputPort())
raycast.SetRadiusArray("Radius")
raycast.SetScalarRange(0, 1)
raycast_actor = vtkActor()
raycast_actor.SetMapper(raycast)
raycast_actor.GetProperty().SetSpecular(0.4)
raycast_actor.GetProperty().SetSpecularPower(40)
fiber_view(raycast_actor, "fibers-raycast-tubes.png")
# ... and a close-up among the tubes (the surfaces stay smooth and exact).
fiber_view(raycast_actor, "fibers-raycast-tubes-closeup.png", camera_position=(0.08, 0.05, 0.32),
           focal=(0.0, 0.0, 0.0))

# Tessellated spline tubes (Salm section 3.1): a base mesh bent along the same
# splines, refined by the GPU's tessellation unit towards the silhouettes,
# flat end caps; 8x multisampling. The close-up in wireframe shows the
# refinement (silhouettes and cap rims finest, back patches culled).
tessellated = splineviz.vtkTessellatedTubeMapper()
tessellated.SetInputConnection(fibers.GetOutputPort())
tessellated.SetRadiusArray("Radius")
tessellated.SetScalarRange(0, 1)
tessellated_actor = vtkActor()
tessellated_actor.SetMapper(tessellated)
tessellated_actor.GetProperty().SetSpecular(0.4)
tessellated_actor.GetProperty().SetSpecularPower(40)


def msaa_view(actor, name, **kwargs):
    """fiber_view with 8x multisampling."""
    fiber_view(actor, name, samples=8, **kwargs)


msaa_view(tessellated_actor, "fibers-tessellated-tubes.png")
msaa_view(tessellated_actor, "fibers-tessellated-tubes-closeup.png", camera_position=(0.08, 0.05, 0.32),
          focal=(0.0, 0.0, 0.0))
wire_actor = vtkActor()
wire_actor.SetMapper(tessellated)
wire_actor.GetProperty().SetRepresentationToWireframe()
wire_actor.GetProperty().LightingOff()
wire_actor.GetProperty().SetColor(0.9, 0.9, 0.9)
tessellated.ScalarVisibilityOff()
fiber_view(wire_actor, "fibers-tessellated-tubes-closeup-wireframe.png",
           camera_position=(0.08, 0.05, 0.32), focal=(0.0, 0.0, 0.0))
tessellated.ScalarVisibilityOn()

# The same polylines as VTK's own tube filter draws them (12 sides, radius by
# the same array, straight segments): the way SplineViz is compared with.
fibers.GetOutput().GetPointData().SetActiveScalars("Radius")
tubes = vtkTubeFilter()
tubes.SetInputData(fibers.GetOutput())
tubes.SetNumberOfSides(12)
tubes.SetVaryRadiusToVaryRadiusByAbsoluteScalar()
tubes.Update()
fibers.GetOutput().GetPointData().SetActiveScalars("Scalar")
tube_data = tubes.GetOutput()
tube_data.GetPointData().SetActiveScalars("Scalar")
tube_mapper = vtkPolyDataMapper()
tube_mapper.SetInputData(tube_data)
tube_mapper.SetScalarRange(0, 1)
tube_actor = vtkActor()
tube_actor.SetMapper(tube_mapper)
tube_actor.GetProperty().SetSpecular(0.4)
tube_actor.GetProperty().SetSpecularPower(40)
fiber_view(tube_actor, "fibers-vtk-tube-filter-closeup.png", camera_position=(0.08, 0.05, 0.32),
           focal=(0.0, 0.0, 0.0))

# --- Stylized lines (Stoll et al.) -------------------------------------------
# The same fibers as lit generalized cylinders splatted as silhouette quads
# (one quad per segment, per-pixel normal and depth), with a halo in the
# background color that cuts the lines behind; then with stripes along the
# lines and their own shadows.
stylized = splineviz.vtkStylizedLineMapper()
stylized.SetInputConnection(fibers.GetOutputPort())
stylized.SetRadiusArray("Radius")
stylized.SetScalarRange(0, 1)
stylized.SetHaloWidth(0.4)
stylized_actor = vtkActor()
stylized_actor.SetMapper(stylized)
stylized_actor.GetProperty().SetSpecular(0.4)
stylized_actor.GetProperty().SetSpecularPower(40)
render([stylized_actor], "fibers-stylized-lines-halo.png", (0.25, 0.35, 1.9), (0, 0, 0),
       background=(1, 1, 1), samples=0, reset_camera=False)
textured = splineviz.vtkStylizedLineMapper()
textured.SetInputConnection(fibers.GetOutputPort())
textured.SetRadiusArray("Radius")
textured.SetScalarRange(0, 1)
textured.SetTexturePatternToStripes()
textured.SetShadows(True)
textured_actor = vtkActor()
textured_actor.SetMapper(textured)
textured_actor.GetProperty().SetSpecular(0.4)
textured_actor.GetProperty().SetSpecularPower(40)
fiber_view(textured_actor, "fibers-stylized-lines-closeup.png", camera_position=(0.08, 0.05, 0.32),
           focal=(0.0, 0.0, 0.0))
# Stoll Fig. 11 on streamlines VTK traces: velocity to color, integrated
# divergence to radius, rotation to the stripes' orientation, a halo
# (Examples/Python/stylized_lines.py; with the plugin also in ParaView).
runpy.run_path(os.path.join(os.path.dirname(os.path.abspath(__file__)), "stylized_lines.py"),
               init_globals={"__doc__": None}, run_name="stylized_lines")

# --- LR-spline volumes (Fuchs et al.) --------------------------------------
# The real locally refined volume, read as exact Bezier hexahedra: its
# surface with the element edges, coloured by the element size (the local
# refinement, like the paper's Fig. 1), and the g2 tensor-product volume in
# geometry mode (its real shape).
from vtkmodules.vtkFiltersGeometry import vtkDataSetSurfaceFilter  # noqa: E402

data_dir = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "Testing",
                        "Data", "External")
lr_file = os.path.join(data_dir, "cube-3patch-refined.lr")
if os.path.exists(lr_file):
    lr = splineviz.vtkLRSplineReader()
    lr.SetFileName(lr_file)
    lr.Update()
    patch = lr.GetOutput().GetBlock(0)
    surface = vtkDataSetSurfaceFilter()
    surface.SetInputData(patch)
    surface.SetNonlinearSubdivisionLevel(2)
    surface.Update()
    size_mapper = vtkPolyDataMapper()
    size_mapper.SetInputConnection(surface.GetOutputPort())
    size_mapper.SetScalarModeToUseCellFieldData()
    size_mapper.SelectColorArray("LRElementMinSide")
    size_mapper.SetScalarRange(patch.GetCellData().GetArray("LRElementMinSide").GetRange())
    size_actor = vtkActor()
    size_actor.SetMapper(size_mapper)
    edges = vtkDataSetSurfaceFilter()
    edges.SetInputData(patch)
    edges.SetNonlinearSubdivisionLevel(0)
    edge_mapper = vtkPolyDataMapper()
    edge_mapper.SetInputConnection(edges.GetOutputPort())
    edge_mapper.ScalarVisibilityOff()
    edge_actor = vtkActor()
    edge_actor.SetMapper(edge_mapper)
    edge_actor.GetProperty().SetRepresentationToWireframe()
    edge_actor.GetProperty().SetColor(0.05, 0.05, 0.05)
    render([size_actor, edge_actor], "lr-spline-elements.png", (2.6, -1.9, 2.4), (0.5, 0.5, 0.5),
           view_up=(0, 0, 1))

    g2 = splineviz.vtkLRSplineReader()
    g2.SetFileName(os.path.join(data_dir, "tensor-product-volume.g2"))
    g2.GeometryModeOn()
    g2.Update()
    shape = vtkDataSetSurfaceFilter()
    shape.SetInputData(g2.GetOutput().GetBlock(0))
    shape.SetNonlinearSubdivisionLevel(4)
    shape_mapper = vtkPolyDataMapper()
    shape_mapper.SetInputConnection(shape.GetOutputPort())
    shape_mapper.SetScalarModeToUsePointFieldData()
    shape_mapper.SelectColorArray("LRParameterCoordinates")
    shape_mapper.ColorByArrayComponent("LRParameterCoordinates", 1)
    shape_mapper.SetScalarRange(0, 1)
    shape_actor = vtkActor()
    shape_actor.SetMapper(shape_mapper)
    render([shape_actor], "lr-spline-g2-geometry.png", (4, -6, 8), (0, -1, 2.5))

    # Streamlines through the real spline: patch 1 of the file is the field
    # v = (-y, x, z) (helices about the z axis), traced on the exact spline
    # and drawn as ray-cast tubes whose radius and colour follow the speed.
    from vtkmodules.vtkFiltersSources import vtkLineSource  # noqa: E402

    seeds = vtkLineSource()
    seeds.SetPoint1(0.2, 0.03, 0.04)
    seeds.SetPoint2(0.95, 0.03, 0.22)
    seeds.SetResolution(15)
    tracer = splineviz.vtkLRSplineStreamTracer()
    tracer.SetInputData(lr.GetOutput().GetBlock(1))
    tracer.SetSourceConnection(seeds.GetOutputPort())
    tracer.SetIntegratorType(splineviz.vtkLRSplineStreamTracer.RKF45)
    tracer.SetStepMode(splineviz.vtkLRSplineStreamTracer.ADAPTIVE)
    tracer.SetMaximumError(1e-7)
    tracer.SetMaximumIntegrationStep(0.02)
    tracer.Update()
    speed_range = tracer.GetOutput().GetPointData().GetArray("Speed").GetRange()
    stream_mapper = splineviz.vtkRayCastTubeMapper()
    stream_mapper.SetInputConnection(tracer.GetOutputPort())
    stream_mapper.SetRadiusArray("Speed")
    stream_mapper.SetRadiusScale(0.018 / speed_range[1])
    stream_mapper.SetScalarModeToUsePointFieldData()
    stream_mapper.SelectColorArray("Speed")
    stream_mapper.SetScalarRange(speed_range)
    stream_actor = vtkActor()
    stream_actor.SetMapper(stream_mapper)
    mesh1 = vtkDataSetSurfaceFilter()
    mesh1.SetInputData(lr.GetOutput().GetBlock(1))
    mesh1_mapper = vtkPolyDataMapper()
    mesh1_mapper.SetInputConnection(mesh1.GetOutputPort())
    mesh1_mapper.ScalarVisibilityOff()
    mesh1_actor = vtkActor()
    mesh1_actor.SetMapper(mesh1_mapper)
    mesh1_actor.GetProperty().SetRepresentationToWireframe()
    mesh1_actor.GetProperty().SetColor(0.3, 0.3, 0.3)
    mesh1_actor.GetProperty().SetOpacity(0.3)
    # the streamlines and the LR mesh of the spline
    render([stream_actor, mesh1_actor], "lr-spline-streamlines.png", (2.4, -1.6, 1.9),
           (0.45, 0.45, 0.4), view_up=(0, 0, 1))

# Direct volume rendering of the spline itself (Fuchs §4: exact evaluation on
# the GPU, no resampling): |v| of patch 1 with streamline tubes inside, and
# isosurfaces refined on the exact spline (Examples/Python/lr_spline_volume.py).
if hasattr(splineviz, "vtkLRSplineVolumeMapper"):
    runpy.run_path(os.path.join(os.path.dirname(os.path.abspath(__file__)), "lr_spline_volume.py"),
                   init_globals={"__doc__": None}, run_name="lr_spline_volume")

# A real MR scan as an LR spline, volume rendered: DIPY's aniso_vox.nii.gz
# fitted by vtkLRSplineImageFitter to 5 % of its range, next to the voxels
# drawn by vtkSmartVolumeMapper (Examples/Python/lr_spline_fit_image.py does
# the full fit to 2 % with its error report). Needs python3-dipy.
if hasattr(splineviz, "vtkLRSplineVolumeMapper") and hasattr(splineviz, "vtkLRSplineImageFitter"):
    fit_example = runpy.run_path(
        os.path.join(os.path.dirname(os.path.abspath(__file__)), "lr_spline_fit_image.py"),
        run_name="lr_spline_fit_image")
    scan = fit_example["scan_path"]()
    if scan is not None:
        scan_reader, scan_fitter, _ = fit_example["fit_scan"](scan, 0.05)
        path = os.path.join(out_dir, "lr-spline-fit-aniso-vox-volume.png")
        fit_example["volume_picture"](scan_reader, scan_fitter, path)
        print("wrote", path)

# -- Superquadric tensor glyphs (Hlawitschka et al.; Kindlmann 2004) ---------
# A synthetic tensor volume whose principal direction winds around the z axis
# and whose shape goes from linear (outside) through planar to nearly
# spherical (inside), drawn by vtkSuperquadricGlyphMapper at gamma 0, 3 and
# 20 (the same uploaded tensors, three uniform values), then DIPY's small
# real DTI scan when DIPY is available (see superquadric_glyphs.py).
import numpy as np  # noqa: E402
from vtkmodules.util.numpy_support import numpy_to_vtk  # noqa: E402
from vtkmodules.vtkCommonDataModel import vtkImageData  # noqa: E402

n = 8  # even: no point on the axis, where the winding direction is undefined
x, y, z = np.meshgrid(*(np.arange(n) - 0.5 * (n - 1),) * 3, indexing="ij")
x, y, z = (a.ravel(order="F") for a in (x, y, z))
r = np.sqrt(x * x + y * y) + 1e-9
e1 = np.stack([-y / r, x / r, 0.25 * np.ones_like(r)], 1)
e1 /= np.linalg.norm(e1, axis=1)[:, None]
e2 = np.cross(np.tile([0.0, 0.0, 1.0], (len(r), 1)), e1)
e2 /= np.linalg.norm(e2, axis=1)[:, None]
e3 = np.cross(e1, e2)
s = np.clip(r / r.max(), 0, 1)
l1 = np.ones_like(r)
l2 = 0.95 - 0.75 * s  # planar inside, linear outside
l3 = l2 * (0.9 - 0.75 * np.clip(np.abs(z) / z.max(), 0, 1))
T = sum(l[:, None, None] * e[:, :, None] * e[:, None, :] for l, e in ((l1, e1), (l2, e2), (l3, e3)))
six = np.stack([T[:, 0, 0], T[:, 1, 1], T[:, 2, 2], T[:, 0, 1], T[:, 1, 2], T[:, 0, 2]], 1)
field = vtkImageData()
field.SetDimensions(n, n, n)
tensor_array = numpy_to_vtk(six.copy(), deep=1)
tensor_array.SetName("T")
field.GetPointData().SetTensors(tensor_array)

glyph_window = vtkRenderWindow()
glyph_window.SetOffScreenRendering(1)
glyph_window.SetSize(1500, 520)
for v, gamma in enumerate((0.0, 3.0, 20.0)):
    glyph_mapper = splineviz.vtkSuperquadricGlyphMapper()
    glyph_mapper.SetInputData(field)
    glyph_mapper.SetGamma(gamma)
    glyph_mapper.SetScaleFactor(0.48)
    glyph_actor = vtkActor()
    glyph_actor.SetMapper(glyph_mapper)
    glyph_actor.GetProperty().SetSpecular(0.35)
    glyph_actor.GetProperty().SetSpecularPower(30)
    glyph_renderer = vtkRenderer()
    glyph_renderer.SetViewport(v / 3.0, 0.0, (v + 1) / 3.0, 1.0)
    glyph_renderer.SetBackground(0.1, 0.1, 0.12)
    glyph_renderer.AddActor(glyph_actor)
    glyph_window.AddRenderer(glyph_renderer)
    cam = glyph_renderer.GetActiveCamera()
    cam.SetPosition(9, -13, 9)
    cam.SetFocalPoint(0, 0, 0)
    cam.SetViewUp(0, 0, 1)
    glyph_renderer.ResetCamera()
    cam.Zoom(1.05)
save(glyph_window, "superquadric-glyphs-gamma-0-3-20.png")

try:
    import dipy  # noqa: F401
except ImportError:
    dipy = None
if dipy is not None:
    import runpy

    runpy.run_path(os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "superquadric_glyphs.py"), run_name="__main__")

# --- Fiber tracking: tensor lines (vtkTensorLineTracer) ----------------------
# DIPY's small real DTI scan (Testing/Data/DIPY/small_64D_dti.vti, tensors
# fitted by DIPY, lower-triangular layout): fibers traced from every voxel
# with FA >= 0.3, drawn as ray-cast spline tubes (radius from FA, RGB =
# |principal direction|), above the middle axial slice of the tensors drawn
# as superquadric glyphs when vtkSuperquadricGlyphMapper is part of this
# build, otherwise colored by the FA of vtkTensorAnalysisFilter.
from vtkmodules.vtkIOXML import vtkXMLImageDataReader  # noqa: E402
from vtkmodules.vtkImagingCore import vtkExtractVOI  # noqa: E402

dti_file = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "Testing",
                        "Data", "DIPY", "small_64D_dti.vti")
dti = vtkXMLImageDataReader()
dti.SetFileName(dti_file)
dti.Update()
tracer = splineviz.vtkTensorLineTracer()
tracer.SetInputConnection(dti.GetOutputPort())
tracer.SetInputArrayToProcess(0, 0, 0, 0, "DTI")
tracer.SetTensorLayout(2)  # DIPY: XX XY YY XZ YZ ZZ
tracer.SetSeedMode(splineviz.vtkTensorLineTracer.SEEDS_FROM_VOXELS)
tracer.SetSeedFAThreshold(0.3)
tracer.SetStoppingFAThreshold(0.15)
tracer.SetIntegrationStep(0.25)  # voxels
tracer.SetMinimumLength(4.0)  # mm
tracer.Update()
print("tensor lines: %d seeds, %d lines, %d points"
      % (tracer.GetNumberOfSeeds(), tracer.GetOutput().GetNumberOfLines(),
         tracer.GetOutput().GetNumberOfPoints()))
fiber_mapper = splineviz.vtkRayCastTubeMapper()
fiber_mapper.SetInputConnection(tracer.GetOutputPort())
fiber_mapper.SetRadiusArray("FractionalAnisotropy")
fiber_mapper.SetRadiusScale(0.15)
fiber_mapper.SetScalarModeToUsePointFieldData()
fiber_mapper.SelectColorArray("DirectionColors")
fiber_mapper.SetColorModeToDirectScalars()
fiber_actor = vtkActor()
fiber_actor.SetMapper(fiber_mapper)
fiber_actor.GetProperty().SetSpecular(0.3)
fiber_actor.GetProperty().SetSpecularPower(30)

middle = vtkExtractVOI()
middle.SetInputConnection(dti.GetOutputPort())
middle.SetVOI(0, 9, 0, 9, 4, 4)
middle.Update()
if hasattr(splineviz, "vtkSuperquadricGlyphMapper"):
    slice_mapper = splineviz.vtkSuperquadricGlyphMapper()
    slice_mapper.SetInputConnection(middle.GetOutputPort())
    slice_mapper.SetTensorArray("DTI")
    slice_mapper.SetTensorLayout(2)
    slice_mapper.SetScaleMode(slice_mapper.SCALE_NORMALIZED)
    slice_mapper.SetScaleFactor(0.95)
    slice_mapper.SetGamma(3.0)
    slice_mapper.SetGlyphColorMode(slice_mapper.COLOR_BY_EIGENVECTOR)
    print("tensor slice: superquadric glyphs")
else:
    slice_analysis = splineviz.vtkTensorAnalysisFilter()
    slice_analysis.SetInputConnection(middle.GetOutputPort())
    slice_analysis.SetInputArrayToProcess(0, 0, 0, 0, "DTI")
    slice_analysis.SetTensorLayout(2)
    slice_surface = vtkDataSetSurfaceFilter()
    slice_surface.SetInputConnection(slice_analysis.GetOutputPort())
    slice_mapper = vtkPolyDataMapper()
    slice_mapper.SetInputConnection(slice_surface.GetOutputPort())
    slice_mapper.SetScalarModeToUsePointFieldData()
    slice_mapper.SelectColorArray("FractionalAnisotropy")
    slice_mapper.SetScalarRange(0.0, 1.0)
    gray = slice_mapper.GetLookupTable()
    gray.SetSaturationRange(0, 0)
    gray.SetValueRange(0, 1)
    gray.SetHueRange(0, 0)
    print("tensor slice: FA of the tensor analysis (no superquadric glyph mapper in this build)")
slice_actor = vtkActor()
slice_actor.SetMapper(slice_mapper)
render([fiber_actor, slice_actor], "tensor-lines-dipy.png", (40, -30, 40), (9, 9, 9),
       view_up=(0, 0, 1), size=(900, 700), background=DARK)
