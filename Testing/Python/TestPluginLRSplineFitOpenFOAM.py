# SPDX-License-Identifier: BSD-3-Clause
"""pvbatch: a real simulation through the plugin. OpenFOAM's porous angled
duct (porousSimpleFoam, 22,000 hexahedra; run by scripts/openfoam-case.sh,
cached in the build tree) opened with ParaView's own OpenFOAM reader (cell
data), fitted by "LR-Spline Fit" to 5 % of the range of p and of |U|:
- the tolerance is met at every cell centre, by "LR-Spline Probe" on all
  22,000 centres and, independently of SplineViz, by a numpy sum over the
  basis functions of the written .lr file (ifem_reference) at 3,000 of them;
  negative control: the same numpy check against the field shifted by twice
  the tolerance fails;
- the fit passes the case's 20 time steps on to ParaView's animation;
- between the data, at 60,000 random points inside the mesh, the |U| spline
  stays within 0.5 ranges of the data's range; negative control: with
  Smoothing 0 it leaves the range by more than 10 ranges there;
- the p spline rendered by the "LR-Spline Volume" representation trimmed by
  the fitter's Boundary Surface port draws no pixel outside the silhouette
  of the mesh within the spline's domain (the box of the cell centres) and
  fills it; shown without a Trimming Surface it is trimmed the same way
  (the spline carries the boundary; pixel for pixel the same picture);
  negative control: Trim By Data Boundary off, it draws outside. Its colours
  match ParaView's own unlit surface of the mesh coloured by the cell values
  (median difference at most 8 of 255, 95th percentile 30); negative
  control: the first time step's fit differs (median above 8)."""
import os
import sys

import numpy as np

from paraview.simple import *  # noqa: F401,F403
from paraview import servermanager
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline
from vtkmodules.vtkFiltersCore import vtkProbeFilter

import ifem_reference as ref
from splineviz_testing import drawn_mask, openfoam_case, output_dir, png_rgb, white_view

plugin = sys.argv[1]
LoadPlugin(plugin, remote=False, ns=globals())
failures = []


def fail(message):
    print("ERROR:", message)
    failures.append(message)


source_dir = os.environ["SPLINEVIZ_SOURCE_DIR"]
foam = openfoam_case(source_dir)
if foam is None:
    fail("scripts/openfoam-case.sh failed")
    sys.exit(1)

reader = OpenFOAMReader(FileName=foam)  # noqa: F405
reader.MeshRegions = ["internalMesh"]
reader.CellArrays = ["p", "U"]
reader.Createcelltopointfiltereddata = 0
reader.UpdatePipelineInformation()
last = reader.TimestepValues[-1]
reader.UpdatePipeline(last)
mesh = servermanager.Fetch(reader).GetBlock(0)
print("%s at time %g: %d cells" % (foam, last, mesh.GetNumberOfCells()))
if mesh.GetNumberOfCells() != 22000:
    fail("expected the angled duct's 22,000 cells")

centres_filter = CellCenters(Input=reader)  # noqa: F405
centres_filter.UpdatePipeline(last)
centres = servermanager.Fetch(centres_filter)
centres = centres.GetBlock(0) if centres.IsA("vtkMultiBlockDataSet") else centres
x_centres = vtk_to_numpy(centres.GetPoints().GetData())


def values_of(dataset, name):
    v = vtk_to_numpy(dataset.GetCellData().GetArray(name) if dataset.GetCellData().GetArray(name)
                     else dataset.GetPointData().GetArray(name))
    return np.linalg.norm(v, axis=1) if v.ndim > 1 else v


def fit(array, smoothing=None, lr_file=None):
    f = LRSplineFit(Input=reader)  # noqa: F405
    f.Array = ["CELLS", array]
    f.Tolerance = 0.05
    if smoothing is not None:
        f.Smoothing = smoothing
    if lr_file:
        f.FileName = lr_file
    f.UpdatePipeline(last)
    block = servermanager.Fetch(f).GetBlock(0)
    fd = block.GetFieldData()
    report = {name: fd.GetArray("LRFit" + name).GetValue(0)
              for name in ("MaximumError", "Tolerance", "ToleranceMet", "Seconds")}
    report["Domain"] = [fd.GetArray("LRFitDomain").GetValue(i) for i in range(6)]
    report["Elements"] = block.GetNumberOfCells()
    return f, report


def probe_points(f, points):
    """The fitted spline at `points` through "LR-Spline Probe" (NaN where
    it reports no value)."""
    pd = vtkPolyData()
    p = vtkPoints()
    p.SetData(numpy_to_vtk(np.ascontiguousarray(points), deep=1))
    pd.SetPoints(p)
    producer = PVTrivialProducer()  # noqa: F405
    producer.GetClientSideObject().SetOutput(pd)
    probe = LRSplineProbe(Input=f, Source=producer)  # noqa: F405
    probe.UpdatePipeline(last)
    out = servermanager.Fetch(probe)
    value = vtk_to_numpy(out.GetPointData().GetArray(0)).astype(float)
    Delete(probe)  # noqa: F405
    Delete(producer)  # noqa: F405
    return value


def lr_values(lr_file, domain, points):
    """Independent of SplineViz: the sum over all basis functions of the .lr
    file at the points, u = (x - lo) m / (hi - lo) (the fitter's map)."""
    with open(lr_file) as stream:
        patches = ref.parse_lr(stream.read())
    if len(patches) != 1:
        fail("%s holds %d patches, not 1" % (lr_file, len(patches)))
        return np.full(len(points), np.nan)
    patch = patches[0]
    lo_u, hi_u = ref.domain(patch)
    lo = np.array(domain[0::2])
    hi = np.array(domain[1::2])
    out = np.empty(len(points))
    for i, x in enumerate(points):
        u = lo_u + (x - lo) / (hi - lo) * (hi_u - lo_u)
        out[i] = ref.field(patch, ref.clamp(patch, u), patch.coefs, False)[0]
    return out


rng = np.random.default_rng(7)
sample = rng.choice(len(x_centres), 3000, replace=False)
for array in ("p", "U"):
    name = "|U|" if array == "U" else array
    data = values_of(mesh, array)
    lr_file = os.path.join(output_dir(), "TestPluginLRSplineFitOpenFOAM-%s.lr" % array)
    f, report = fit(array, lr_file=lr_file)
    tolerance = report["Tolerance"]
    print("%s: %d elements, max error %.4g, tolerance %.4g (5 %% of %.4g), met %d, %.2f s"
          % (name, report["Elements"], report["MaximumError"], tolerance,
             data.max() - data.min(), report["ToleranceMet"], report["Seconds"]))
    if not report["ToleranceMet"]:
        fail("%s: the tolerance is not met" % name)
    probed = probe_points(f, x_centres)
    worst = np.nanmax(np.abs(probed - data))
    print("   LR-Spline Probe at the %d centres: largest error %.4g, %d without a value"
          % (len(data), worst, np.isnan(probed).sum()))
    if np.isnan(probed).any() or worst > tolerance * (1 + 1e-9):
        fail("%s: the probe misses the tolerance at the cell centres" % name)
    independent = lr_values(lr_file, report["Domain"], x_centres[sample])
    worst = np.nanmax(np.abs(independent - data[sample]))
    if np.isnan(independent).any():
        fail("%s: no value from the .lr file" % name)
    shifted = np.abs(independent - (data[sample] + 2 * tolerance)).max()
    print("   numpy sum over the .lr file's basis at %d centres: largest error %.4g "
          "(negative control, the field shifted by twice the tolerance: %.4g)"
          % (len(sample), worst, shifted))
    if worst > tolerance * (1 + 1e-9):
        fail("%s: the .lr file misses the tolerance at the cell centres" % name)
    if shifted <= tolerance:
        fail("%s: negative control passed" % name)
    if array == "p":
        p_fit = f
    else:
        Delete(f)  # noqa: F405

# Time: the fit passes the reader's time steps on, so ParaView's animation
# scene steps through the fitted series.
fit_info = p_fit.GetClientSideObject().GetOutputInformation(0)
fit_times = list(fit_info.Get(vtkStreamingDemandDrivenPipeline.TIME_STEPS()) or [])
scene = GetAnimationScene()  # noqa: F405
scene.UpdateAnimationUsingDataTimeSteps()
scene_times = list(GetTimeKeeper().TimestepValues)  # noqa: F405
print("time steps: reader %d, fit %d, animation %d"
      % (len(reader.TimestepValues), len(fit_times), len(scene_times)))
if fit_times != list(reader.TimestepValues) or len(fit_times) < 2 or \
        not set(fit_times) <= set(scene_times):
    fail("the fit does not pass the case's time steps on to the animation")

# Between the data: random points inside the mesh (vtkProbeFilter's valid
# mask) and inside the fitted domain.
bounds = mesh.GetBounds()
points = rng.uniform(bounds[0::2], bounds[1::2], (200000, 3))
cloud = vtkPolyData()
cloud_points = vtkPoints()
cloud_points.SetData(numpy_to_vtk(points, deep=1))
cloud.SetPoints(cloud_points)
inside_probe = vtkProbeFilter()
inside_probe.SetInputData(cloud)
inside_probe.SetSourceData(mesh)
inside_probe.Update()
inside = vtk_to_numpy(inside_probe.GetOutput().GetPointData().GetArray(
    inside_probe.GetValidPointMaskArrayName())) > 0
lo, hi = x_centres.min(axis=0), x_centres.max(axis=0)
inside &= np.all((points >= lo) & (points <= hi), axis=1)
points = points[inside][:60000]
u_data = values_of(mesh, "U")
u_range = u_data.max() - u_data.min()
excursion = {}
for smoothing in (None, 0.0):
    f, report = fit("U", smoothing)
    values = probe_points(f, points)
    excursion[smoothing] = max(0.0, np.nanmax(values) - u_data.max(),
                               u_data.min() - np.nanmin(values)) / u_range
    print("|U|, Smoothing %s: %d elements; at %d points inside the mesh the spline is in "
          "[%.4g, %.4g] for data in [%.4g, %.4g]: %.3g ranges out"
          % ("default" if smoothing is None else smoothing, report["Elements"], len(points),
             np.nanmin(values), np.nanmax(values), u_data.min(), u_data.max(),
             excursion[smoothing]))
    Delete(f)  # noqa: F405
if excursion[None] > 0.5:
    fail("the |U| spline swings out of the data's range inside the mesh")
if excursion[0.0] <= 10:
    fail("negative control: without smoothing the |U| spline should swing")

# Trimmed rendering of p: nothing outside the mesh's silhouette.
view = white_view((420, 300))
view.ViewTime = last  # the view asks the pipeline for its own time
view.CameraPosition = [0.25, -0.3, 0.55]
view.CameraFocalPoint = [0.1, 0.06, 0.0]
view.CameraViewUp = [0, 1, 0]
view.CameraParallelProjection = 0


def picture_rgb(name):
    path = os.path.join(output_dir(), "TestPluginLRSplineFitOpenFOAM-%s.png" % name)
    SaveScreenshot(path, view, ImageResolution=list(view.ViewSize))  # noqa: F405
    return png_rgb(path).astype(float)


def picture(name):
    return drawn_mask(picture_rgb(name))


# The expected picture: the mesh where the spline is defined (the box of the
# cell centres, which leaves a rim of half a cell), drawn as a surface.
boundary = OutputPort(p_fit, 1)  # noqa: F405
domain = servermanager.Fetch(p_fit).GetBlock(0).GetFieldData().GetArray("LRFitDomain")
domain = [domain.GetValue(i) for i in range(6)]
inside_domain = Clip(Input=reader, ClipType="Box")  # noqa: F405
inside_domain.ClipType.Position = domain[0::2]
inside_domain.ClipType.Length = [domain[1] - domain[0], domain[3] - domain[2],
                                 domain[5] - domain[4]]
inside_domain.Exact = 1
inside_domain.Invert = 1
expected = ExtractSurface(Input=inside_domain)  # noqa: F405
expected.UpdatePipeline(last)
surface = Show(expected, view)  # noqa: F405
surface.SetRepresentationType("Surface")
surface.ColorArrayName = ["POINTS", ""]
view.ResetCamera()
Render(view)  # noqa: F405
silhouette = picture("boundary")
Hide(expected, view)  # noqa: F405
display = Show(p_fit, view)  # noqa: F405
display.SetRepresentationType("LR-Spline Volume")
ColorBy(display, ("POINTS", "p"))  # noqa: F405
# colours over the data's range, opaque everywhere (the default ramp leaves
# the low pressures transparent)
p_data = values_of(mesh, "p")
p_range = (float(p_data.min()), float(p_data.max()))
GetColorTransferFunction("p").RescaleTransferFunction(*p_range)  # noqa: F405
GetOpacityTransferFunction("p").Points = [p_range[0], 1, 0.5, 0,  # noqa: F405
                                          p_range[1], 1, 0.5, 0]
display.LRSplineScalarOpacityUnitDistance = 0.0005
# Trimmed by default: the spline carries the mesh's boundary.
automatic_rgb = picture_rgb("trimmed-automatic")
display.TrimByDataBoundary = 0
untrimmed = picture("untrimmed")
display.TrimByDataBoundary = 1
display.TrimmingSurface = boundary
trimmed_rgb = picture_rgb("trimmed")
trimmed = drawn_mask(trimmed_rgb)
automatic_differs = int((abs(automatic_rgb - trimmed_rgb).max(axis=2) > 0).sum())
print("automatic trimming: %d pixels differ from the Trimming Surface chosen by hand"
      % automatic_differs)
if automatic_differs:
    fail("the automatic trimming differs from the boundary chosen as Trimming Surface")
# Negative control for the colours: the first time step's fit.
view.ViewTime = reader.TimestepValues[0]
first_rgb = picture_rgb("trimmed-first-step")
view.ViewTime = last
# The reference colours: ParaView's own unlit surface of the mesh coloured by
# the cell values, with the same colour map.
Hide(p_fit, view)  # noqa: F405
surface = Show(expected, view)  # noqa: F405
ColorBy(surface, ("CELLS", "p"))  # noqa: F405
surface.Ambient = 1.0
surface.Diffuse = 0.0
reference_rgb = picture_rgb("reference")
outside = trimmed & ~silhouette
# The silhouette's interior: its pixels whose four neighbours are in it too
# (the outline's pixels are rasterized differently by the surface and the
# ray caster).
interior = silhouette.copy()
interior[1:-1, 1:-1] &= (silhouette[:-2, 1:-1] & silhouette[2:, 1:-1] &
                         silhouette[1:-1, :-2] & silhouette[1:-1, 2:])
interior[[0, -1], :] = False
interior[:, [0, -1]] = False
holes = interior & ~trimmed
print("silhouette %.3f of the view, trimmed %.3f, drawn outside %d px (untrimmed: %d px), "
      "holes in the silhouette's interior %d px of %d"
      % (silhouette.mean(), trimmed.mean(), outside.sum(), (untrimmed & ~silhouette).sum(),
         holes.sum(), interior.sum()))
if silhouette.mean() < 0.05:
    fail("the duct covers too little of the view")
if outside.any():
    fail("%d pixels drawn outside the mesh's silhouette" % outside.sum())
if (untrimmed & ~silhouette).sum() < 500:
    fail("negative control: the untrimmed volume should cover pixels outside the mesh")
if holes.sum() > 0.002 * interior.sum():
    fail("the trimmed volume leaves holes in the mesh's silhouette")
compare = interior & trimmed
colour = abs(trimmed_rgb - reference_rgb).max(axis=2)[compare]
colour_first = abs(first_rgb - reference_rgb).max(axis=2)[compare]
print("colours against the mesh's surface coloured by its cell values: median %.1f, "
      "95th percentile %.1f (of 255); the first time step's fit: %.1f, %.1f"
      % (np.median(colour), np.percentile(colour, 95), np.median(colour_first),
         np.percentile(colour_first, 95)))
if np.median(colour) > 8 or np.percentile(colour, 95) > 30:
    fail("the trimmed volume's colours are not the data's")
if np.median(colour_first) <= 8:
    fail("negative control: the first time step's fit has the last step's colours")
if failures:
    sys.exit(1)
