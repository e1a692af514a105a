# SPDX-License-Identifier: BSD-3-Clause
"""pvbatch: the plugin's neuroimaging readers and writer in ParaView, as a user
gets them. DIPY fits its real small_64D scan (an oblique, permuted affine);
nibabel saves the tensors (5D NIfTI) and DIPY's FA. Then, in ParaView:

- File > Open of the .nii.gz picks "NIfTI Diffusion Tensors" (listed by the
  reader factory), with the FA as a companion volume; the image keeps the
  scan's affine as its direction matrix; the reader factory offers both
  NIfTI readers for the tensor file and only "NIfTI Volume" for the FA,
  which File > Open reads onto the tensors' points with the same values;
- "Tensor Analysis" on it gives DIPY's FA (the rotated tensors keep their
  invariants), "Superquadric Glyphs" draw it (the whole volume and a slice
  from Extract Subset), "Tensor Line Tracer" traces it: at every seed the
  principal direction is DIPY's eigenvector rotated into the world frame;
- Save Data writes the fibres as .tck (+ .tsf) and .trk (the writer factory
  lists "Tractogram"), nibabel reads them back as the tracer's points, and
  File > Open of the .tck / .trk picks the tractogram reader, drawn as
  "Ray-Cast Tubes".
"""
import os
import sys

try:
    import nibabel as nib
    from dipy.core.gradients import gradient_table
    from dipy.data import get_fnames
    from dipy.io.gradients import read_bvals_bvecs
    from dipy.reconst.dti import TensorModel, lower_triangular
except ImportError as error:
    print("nibabel or DIPY not available, skipped:", error)
    sys.exit(125)

import numpy as np
from paraview import servermanager
from paraview.simple import *  # noqa: F401,F403
from vtkmodules.util.numpy_support import vtk_to_numpy

import splineviz  # noqa: F401  (Python wrappers of the SplineViz classes)
from splineviz_testing import coverage, output_dir, white_view

LoadPlugin(sys.argv[1], remote=False, ns=globals())
out = output_dir()
from splineviz_testing import Checker  # noqa: E402

checker = Checker()


check = checker.check


# DIPY's fit of a real scan, saved by nibabel.
dwi, bval, bvec = get_fnames("small_64D")
scan = nib.load(dwi)
bvals, bvecs = read_bvals_bvecs(bval, bvec)
fit = TensorModel(gradient_table(bvals, bvecs)).fit(np.asarray(scan.dataobj, dtype=np.float64))
nii = os.path.join(out, "TestPluginNeuroimaging-dti.nii.gz")
fa_file = os.path.join(out, "TestPluginNeuroimaging-FA.nii.gz")
nib.save(nib.Nifti1Image(lower_triangular(fit.quadratic_form)[:, :, :, None, :].astype(np.float32),
                         scan.affine), nii)
fa_dipy = np.nan_to_num(fit.fa).astype(np.float32)
nib.save(nib.Nifti1Image(fa_dipy, scan.affine), fa_file)
u, _, vt = np.linalg.svd(scan.affine[:3, :3])
rotation = u @ vt  # voxel frame -> world

factory = servermanager.vtkSMProxyManager.GetProxyManager().GetReaderFactory()
types = factory.GetSupportedFileTypes(servermanager.ActiveConnection.Session)
check("NIfTI Diffusion Tensors (*.nii *.nii.gz *.hdr *.hdr.gz *.img *.img.gz)" in types,
      "File > Open lists NIfTI Diffusion Tensors")
check("Tractograms (MRtrix .tck, TrackVis .trk) (*.tck *.trk)" in types, "File > Open lists tractograms")
check("NIfTI Volume (*.nii *.nii.gz *.hdr *.hdr.gz *.img *.img.gz)" in types,
      "File > Open lists NIfTI Volume")
session = servermanager.ActiveConnection.Session


def readers_of(path):
    found = factory.GetReaders(path, session)
    return [found.GetString(i) for i in range(1, found.GetLength(), 3)]


check(readers_of(nii) == ["NIfTITensorReader", "NIfTIVolumeReader"],
      "a tensor file: both NIfTI readers offered (%s)" % readers_of(nii))
check(readers_of(fa_file) == ["NIfTIVolumeReader"],
      "a scalar volume: only NIfTI Volume offered (%s)" % readers_of(fa_file))

dti = OpenDataFile(nii)  # noqa: F405
check(dti is not None and dti.GetXMLName() == "NIfTITensorReader",
      "a .nii.gz opens with the NIfTI Diffusion Tensors reader")
dti.CompanionVolumes = [fa_file]
dti.UpdatePipeline()
image = servermanager.Fetch(dti)
direction = np.array([image.GetDirectionMatrix().GetElement(i, j) for i in range(3)
                      for j in range(3)]).reshape(3, 3)
check(image.GetNumberOfPoints() == 1000 and image.GetPointData().GetArray("Tensors") is not None
      and image.GetPointData().GetArray("TestPluginNeuroimaging-FA") is not None,
      "tensors and the FA companion on 1000 voxels")
check(np.abs(direction - np.eye(3)).max() > 0.1 and abs(np.linalg.det(direction) - 1) < 1e-6,
      "the scan's rotation is the image's direction matrix")

# DIPY's FA through File > Open: "NIfTI Volume", on the tensors' points, DIPY's values
fa_volume = OpenDataFile(fa_file)  # noqa: F405
check(fa_volume is not None and fa_volume.GetXMLName() == "NIfTIVolumeReader",
      "the FA .nii.gz opens with the NIfTI Volume reader")
fa_image = servermanager.Fetch(fa_volume)
same_points = fa_image.GetNumberOfPoints() == image.GetNumberOfPoints() and all(
    fa_image.GetPoint(i) == image.GetPoint(i) for i in range(image.GetNumberOfPoints()))
fa_values = vtk_to_numpy(fa_image.GetPointData().GetArray("TestPluginNeuroimaging-FA"))
check(same_points and np.array_equal(
    fa_values, vtk_to_numpy(image.GetPointData().GetArray("TestPluginNeuroimaging-FA"))),
      "NIfTI Volume: the tensors' points, the companion's values")

# NIfTI Volume's Volume Index on a 4D series: the range offered, the volume read
series = np.stack([fa_dipy * np.float32(t + 1) for t in range(5)], -1)
series_file = os.path.join(out, "TestPluginNeuroimaging-series.nii.gz")
nib.save(nib.Nifti1Image(series, scan.affine), series_file)
series_reader = NIfTIVolume(FileName=series_file)  # noqa: F405
series_reader.UpdatePipelineInformation()
series_reader.VolumeIndex = 3
series_reader.UpdatePipeline()
volume3 = vtk_to_numpy(servermanager.Fetch(series_reader).GetPointData().GetArray(0))
check(list(series_reader.GetPropertyValue("VolumeRangeInfo")) == [0, 4] and np.array_equal(volume3, fa_values * 4),
      "NIfTI Volume on 5 volumes: Volume Index 0..4 offered, volume 3 read")

analysis = TensorAnalysis(Input=dti)  # noqa: F405
analysis.Tensors = ["POINTS", "Tensors"]
analysis.UpdatePipeline()
result = servermanager.Fetch(analysis).GetPointData()
fa = vtk_to_numpy(result.GetArray("FractionalAnisotropy"))
fa_companion = vtk_to_numpy(result.GetArray("TestPluginNeuroimaging-FA"))
print("Tensor Analysis FA vs DIPY's: %.2g" % np.abs(fa - fa_companion).max())
check(np.abs(fa - fa_companion).max() < 1e-5, "Tensor Analysis on the reader: DIPY's FA")

# Superquadric Glyphs of the volume and of a slice
view = white_view((500, 420))
glyphs = Show(dti, view)  # noqa: F405
glyphs.SetRepresentationType("Superquadric Glyphs")
glyphs.SuperquadricTensors = "Tensors"
glyphs.SuperquadricScaleMode = "Normalized"  # every glyph 2 mm * 0.9 long (DTI in mm^2/s)
glyphs.SuperquadricScaleFactor = 0.9
glyphs.SuperquadricMaskArray = "TestPluginNeuroimaging-FA"
ResetCamera(view)  # noqa: F405
cover, _ = coverage(view, "TestPluginNeuroimaging-glyphs.png")
mapper = glyphs.GetClientSideObject().GetActiveRepresentation().GetActor().GetMapper()
print("glyphs: %d, coverage %.3f" % (mapper.GetNumberOfGlyphs(), cover))
check(mapper.IsA("vtkSuperquadricGlyphMapper") and mapper.GetNumberOfGlyphs() > 900 and cover > 0.1,
      "Superquadric Glyphs draw the reader's output")
Hide(dti, view)  # noqa: F405
middle = ExtractSubset(Input=dti)  # noqa: F405
middle.VOI = [0, 9, 0, 9, 5, 5]
slice_glyphs = Show(middle, view)  # noqa: F405
slice_glyphs.SetRepresentationType("Superquadric Glyphs")
slice_glyphs.SuperquadricTensors = "Tensors"
slice_glyphs.SuperquadricScaleMode = "Normalized"
slice_glyphs.SuperquadricScaleFactor = 0.9
ResetCamera(view)  # noqa: F405
cover, _ = coverage(view, "TestPluginNeuroimaging-slice-glyphs.png")
mapper = slice_glyphs.GetClientSideObject().GetActiveRepresentation().GetActor().GetMapper()
check(mapper.GetNumberOfGlyphs() >= 95 and cover > 0.05, "glyphs on a slice (Extract Subset)")
Hide(middle, view)  # noqa: F405

# Tensor Line Tracer on the reader: seeds follow DIPY's eigenvectors, rotated
tracer = TensorLineTracer(Input=dti)  # noqa: F405
tracer.Tensors = ["POINTS", "Tensors"]
tracer.Seeding = "Voxels above the seed FA threshold"
tracer.SeedFAThreshold = 0.3
tracer.StoppingFAThreshold = 0.15
tracer.MinimumLength = 4.0
tracer.UpdatePipeline()
lines = servermanager.Fetch(tracer)
print("fibres: %d lines, %d points" % (lines.GetNumberOfLines(), lines.GetNumberOfPoints()))
check(lines.GetNumberOfLines() > 300, "Tensor Line Tracer traces the reader's output")
arc = vtk_to_numpy(lines.GetPointData().GetArray("ArcLength"))
direction = vtk_to_numpy(lines.GetPointData().GetArray("PrincipalDirection"))
points = vtk_to_numpy(lines.GetPoints().GetData()).astype(np.float64)
seeds = np.where(arc == 0.0)[0]
ijk = np.round(nib.affines.apply_affine(np.linalg.inv(scan.affine), points[seeds])).astype(int)
e1 = fit.evecs[ijk[:, 0], ijk[:, 1], ijk[:, 2], :, 0] @ rotation.T  # DIPY's e1, in the world
agreement = np.abs(np.einsum("ij,ij->i", e1, direction[seeds])).min()
print("seeds: %d, smallest |e1 (DIPY, rotated) . direction| %.6f" % (len(seeds), agreement))
check(len(seeds) > 300 and agreement > 0.9999, "fibres start along DIPY's rotated eigenvectors")

# Save Data: .tck (+ .tsf) and .trk; nibabel reads them back
writers = servermanager.vtkSMProxyManager.GetProxyManager().GetWriterFactory()
check("Tractogram (MRtrix .tck, TrackVis .trk)" in writers.GetSupportedFileTypes(tracer.SMProxy),
      "Save Data lists the tractogram writer")
tck = os.path.join(out, "TestPluginNeuroimaging-fibres.tck")
trk = os.path.join(out, "TestPluginNeuroimaging-fibres.trk")
SaveData(tck, proxy=tracer, PointArrays=["FractionalAnisotropy"])  # noqa: F405
SaveData(trk, proxy=tracer, PointArrays=["FractionalAnisotropy"], CellArrays=["Length"])  # noqa: F405
offsets = vtk_to_numpy(lines.GetLines().GetOffsetsArray())
conn = vtk_to_numpy(lines.GetLines().GetConnectivityArray())
fibres = [points[conn[a:b]] for a, b in zip(offsets[:-1], offsets[1:])]
for path, tolerance in ((tck, 1e-6), (trk, 1e-4)):
    loaded = nib.streamlines.load(path)
    err = max(np.abs(a - b).max() for a, b in zip(loaded.streamlines, fibres))
    check(len(loaded.streamlines) == len(fibres) and err < tolerance,
          "nibabel reads %s back as the tracer's fibres (%.2g mm)" % (os.path.basename(path), err))
fa_lines = vtk_to_numpy(lines.GetPointData().GetArray("FractionalAnisotropy"))
loaded = nib.streamlines.load(trk)
check(np.allclose(np.concatenate(list(loaded.tractogram.data_per_point["FractionalAnisotropy"]))[:, 0],
                  fa_lines[conn], atol=1e-7), "the .trk holds the FA per point")
check(os.path.exists(os.path.join(out, "TestPluginNeuroimaging-fibres.FractionalAnisotropy.tsf")),
      "the .tck has its .tsf")

# File > Open of the tractograms, drawn as ray-cast tubes
for path in (tck, trk):
    fibres_reader = OpenDataFile(path)  # noqa: F405
    check(fibres_reader is not None and fibres_reader.GetXMLName() == "TractogramReader",
          "%s opens with the tractogram reader" % os.path.basename(path))
if path == trk:
    tubes = Show(fibres_reader, view)  # noqa: F405
    tubes.SetRepresentationType("Ray-Cast Tubes")
    tubes.TubeRadiusArray = "FractionalAnisotropy"
    tubes.TubeRadiusScale = 0.3
    ColorBy(tubes, ("POINTS", "FractionalAnisotropy"))  # noqa: F405
    view.CameraPosition = [60, -40, 50]
    view.CameraFocalPoint = [10, 10, 10]
    view.CameraViewUp = [0, 0, 1]
    ResetCamera(view)  # noqa: F405
    cover, _ = coverage(view, "TestPluginNeuroimaging-tubes.png")
    mapper = tubes.GetClientSideObject().GetActiveRepresentation().GetActor().GetMapper()
    print("tubes: coverage %.3f" % cover)
    check(mapper.IsA("vtkRayCastTubeMapper") and cover > 0.1, "the .trk drawn as Ray-Cast Tubes")

# The subset properties: every 3rd streamline, a random half (a seed of its own)
subset = OpenDataFile(tck)  # noqa: F405
subset.SubsetMode = "Every k-th Streamline"
subset.SubsetStride = 3
subset.UpdatePipeline()
every3 = subset.GetDataInformation().GetNumberOfCells()
subset.SubsetMode = "Random Fraction"
subset.SubsetFraction = 0.5
subset.SubsetSeed = 7
subset.UpdatePipeline()
half = subset.GetDataInformation().GetNumberOfCells()
print("subsets: every 3rd %d, random half %d of %d" % (every3, half, len(fibres)))
check(every3 == (len(fibres) + 2) // 3 and 0.3 * len(fibres) < half < 0.7 * len(fibres),
      "Tractogram Reader subsets: every 3rd streamline, a random half")

checker.finish()
print("neuroimaging IO in ParaView OK")
