# SPDX-License-Identifier: BSD-3-Clause
"""pvbatch: the "Superquadric Glyphs" representation on an indefinite stress
field (VTK's vtkPointLoad, the Boussinesq solution, from a Programmable
Source): with Negative Eigenvalues "Schultz-Kindlmann" every tensor gets a
glyph (Skip keeps only the few definite ones), the quadratic-form coloring
shows both signs, changing gamma only changes uniforms; a multiblock of two
stress volumes takes the display's block colors and block visibility
(Block Colors, Block Selectors), which reach the mapper as composite display
attributes."""
import builtins
import sys

from paraview.simple import *  # noqa: F401,F403

import splineviz  # noqa: F401
from splineviz_testing import coverage as image_coverage, white_view

LoadPlugin(sys.argv[1], remote=False, ns=globals())

SCRIPT = """
from vtkmodules.vtkImagingHybrid import vtkPointLoad
load = vtkPointLoad()
load.SetLoadValue(100.0)
load.SetSampleDimensions(6, 6, 6)
load.SetModelBounds(-10, 10, -10, 10, -10, 10)
load.Update()
self.GetOutput().ShallowCopy(load.GetOutput())
"""
INFO = """
self.GetExecutive().GetOutputInformation(0).Set(
    self.GetExecutive().WHOLE_EXTENT(), 0, 5, 0, 5, 0, 5)
"""


def fail(message):
    print("ERROR:", message)
    sys.exit(1)


stress = ProgrammableSource(OutputDataSetType="vtkImageData", Script=SCRIPT,  # noqa: F405
                            ScriptRequestInformation=INFO)
view = white_view((500, 400))
display = Show(stress, view)  # noqa: F405
display.SetRepresentationType("Superquadric Glyphs")
display.SuperquadricScaleMode = 1  # normalized: every glyph of the same size
display.SuperquadricScaleFactor = 1.6
display.SuperquadricGamma = 3.0
view.CameraPosition = [30, -48, 36]
view.CameraFocalPoint = [0, 0, 0]
view.CameraViewUp = [0, 0, 1]
ResetCamera(view)  # noqa: F405
mapper = display.GetClientSideObject().GetActiveRepresentation().GetActor().GetMapper()

display.SuperquadricNegativeEigenvalues = 0  # Skip
cov_skip, _ = image_coverage(view, "TestPluginSuperquadricGlyphsStress-skip.png", stride=2)
skipped = mapper.GetNumberOfGlyphs()
display.SuperquadricNegativeEigenvalues = 2  # Schultz-Kindlmann
display.SuperquadricColorMode = 3  # quadratic form
cov_sk, img_sk = image_coverage(view, "TestPluginSuperquadricGlyphsStress.png", stride=2)
print("Skip: coverage %.3f; Schultz-Kindlmann: %d glyphs, coverage %.3f"
      % (cov_skip, mapper.GetNumberOfGlyphs(), cov_sk))
if mapper.GetNegativeEigenvaluePolicy() != 2 or mapper.GetGlyphColorMode() != 3:
    fail("the properties did not reach the mapper")
if mapper.GetNumberOfGlyphs() != 216 or skipped != 216:
    fail("every tensor is uploaded (the policy is applied on the GPU)")
if not cov_sk > 2.0 * cov_skip:
    fail("the Schultz-Kindlmann policy should draw the indefinite tensors Skip leaves out")
# both signs of the quadratic form (orange and blue, shaded)
warm = builtins.sum(1 for p in img_sk if p[0] > p[2] + 40)
cool = builtins.sum(1 for p in img_sk if p[2] > p[0] + 40)
print("quadratic form: %d warm, %d cool pixels" % (warm, cool))
if warm < 200 or cool < 200:
    fail("expected both signs of the quadratic form")

uploads = mapper.GetUploadCount()
display.SuperquadricGamma = 1.0
cov_g1, img_g1 = image_coverage(view, "TestPluginSuperquadricGlyphsStress-gamma1.png", stride=2)
changed = builtins.sum(1 for a, b in zip(img_g1, img_sk) if a != b)
if mapper.GetUploadCount() != uploads or changed < 200:
    fail("a gamma change must re-render without an upload (%d changed)" % changed)

# Block colors and visibility on a multiblock of two stress volumes.
second = ProgrammableSource(OutputDataSetType="vtkImageData", Script=SCRIPT,  # noqa: F405
                            ScriptRequestInformation=INFO)
shifted = Transform(Input=second)  # noqa: F405
shifted.Transform.Translate = [25, 0, 0]
group = GroupDatasets(Input=[stress, shifted])  # noqa: F405
Hide(stress, view)  # noqa: F405
gd = Show(group, view)  # noqa: F405
gd.SetRepresentationType("Superquadric Glyphs")
gd.SuperquadricNegativeEigenvalues = 2
gd.SuperquadricScaleMode = 1
gd.SuperquadricScaleFactor = 1.6
gd.SuperquadricColorMode = 2  # solid color: the block colors replace it
gd.AmbientColor = [1, 1, 1]
gd.DiffuseColor = [1, 1, 1]
ResetCamera(view)  # noqa: F405
# the blocks' selectors: GroupDatasets names them after its inputs
group.UpdatePipeline()
hierarchy = group.GetDataInformation().DataInformation.GetHierarchy()
selectors = ["/Root/" + hierarchy.GetNodeName(hierarchy.GetChild(0, i)) for i in range(2)]
print("blocks:", selectors)
gd.BlockColors = [selectors[0], "1", "0", "0", selectors[1], "0", "0", "1"]
cov_c, img_c = image_coverage(view, "TestPluginSuperquadricGlyphsStress-blocks.png", stride=2)
red = builtins.sum(1 for p in img_c if p[0] > 100 and p[1] < 60 and p[2] < 60)
blue = builtins.sum(1 for p in img_c if p[2] > 100 and p[0] < 60 and p[1] < 60)
gmapper = gd.GetClientSideObject().GetActiveRepresentation().GetActor().GetMapper()
print("blocks: %d glyphs, %d red and %d blue pixels" % (gmapper.GetNumberOfGlyphs(), red, blue))
if gmapper.GetCompositeDataDisplayAttributes() is None or red < 300 or blue < 300:
    fail("the block colors did not reach the glyphs")
gd.BlockSelectors = [selectors[0]]  # only the first block visible
cov_v, img_v = image_coverage(view, "TestPluginSuperquadricGlyphsStress-visibility.png", stride=2)
red_v = builtins.sum(1 for p in img_v if p[0] > 100 and p[1] < 60 and p[2] < 60)
blue_v = builtins.sum(1 for p in img_v if p[2] > 100 and p[0] < 60 and p[1] < 60)
print("visibility: %d red and %d blue pixels" % (red_v, blue_v))
if red_v < 300 or blue_v > 0:
    fail("the hidden block is drawn")
print("Superquadric Glyphs on a stress field OK")
