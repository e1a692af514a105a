# SPDX-License-Identifier: BSD-3-Clause
"""pvbatch: real tractograms opened with the defaults show lines, not dots.

DIPY's real cb_2 bundle (Testing/Data/DIPY/cb_2.vtp), written as a .tck by
nibabel and opened by file name, and the tensor lines traced from DIPY's real
tensors, are drawn with each SplineViz line representation ("Ray-Cast
Tubes", "Tessellated Tubes", "Stylized Lines") with every property at its
default, and with ParaView's own "Wireframe" (VTK's plain lines) as the
reference, the data filling the view; then with a hundredth of the
automatic radius (for cb_2 0.004 mm, below the old default of 0.01 mm that
showed dots). Checks:
- coverage: at least 97 % of the reference lines' pixels where a line is
  alone (in the dense parts tubes overlap whatever their width) have a drawn
  pixel of the representation within one pixel, at both radii;
- the default radius is automatic (Tube Radius 0) and gives tubes, not lines,
  when the data fills the view: around the lone lines at least 1.5 drawn
  pixels per line pixel; the thin tubes about a pixel wide (at most 1.6);
- negative control: with Minimum Pixel Width 0 (the exact radius at any
  size) the thin ray-cast tubes cover less than 80 % of the lines (the dots
  the defaults used to show).
"""
import os
import sys

import numpy as np

try:
    import nibabel as nib
except ImportError as error:
    print("nibabel not available, skipped:", error)
    sys.exit(125)

from paraview.simple import *  # noqa: F401,F403
from paraview import servermanager
from splineviz_testing import output_dir, png_rgb, white_view

LoadPlugin(sys.argv[1], remote=False, ns=globals())
source_dir = os.environ["SPLINEVIZ_SOURCE_DIR"]
out = output_dir()
from splineviz_testing import Checker  # noqa: E402

checker = Checker()


check = checker.check


def write_cb2_tck():
    """cb_2 as nibabel writes a .tck (points in RAS+ mm)."""
    from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
    from vtkmodules.util.numpy_support import vtk_to_numpy

    reader = vtkXMLPolyDataReader()
    reader.SetFileName(os.path.join(source_dir, "Testing", "Data", "DIPY", "cb_2.vtp"))
    reader.Update()
    polydata = reader.GetOutput()
    points = vtk_to_numpy(polydata.GetPoints().GetData()).astype(np.float32)
    lines = polydata.GetLines()
    offsets = vtk_to_numpy(lines.GetOffsetsArray())
    ids = vtk_to_numpy(lines.GetConnectivityArray())
    streamlines = [points[ids[offsets[i]:offsets[i + 1]]] for i in range(len(offsets) - 1)]
    tractogram = nib.streamlines.Tractogram(streamlines, affine_to_rasmm=np.eye(4))
    path = os.path.join(out, "TestPluginFirstPicture-cb_2.tck")
    nib.streamlines.save(tractogram, path)
    return path, len(streamlines)


def mask(view, name):
    """Drawn pixels (differing from the white background) of a screenshot."""
    png = os.path.join(out, name)
    SaveScreenshot(png, view, ImageResolution=list(view.ViewSize))  # noqa: F405
    rgb = png_rgb(png)
    return np.abs(rgb - 255).max(axis=2) > 30


def dilate(m):
    """3x3 dilation of a boolean image."""
    d = m.copy()
    d[1:, :] |= m[:-1, :]
    d[:-1, :] |= m[1:, :]
    e = d.copy()
    e[:, 1:] |= d[:, :-1]
    e[:, :-1] |= d[:, 1:]
    return e


def window_sum(m, radius=2):
    """Per pixel, the number of set pixels of `m` in its (2 radius + 1)^2 window."""
    p = np.pad(m.astype(np.int32), radius)
    c = np.cumsum(np.cumsum(p, axis=0), axis=1)
    c = np.pad(c, ((1, 0), (1, 0)))
    k = 2 * radius + 1
    return c[k:, k:] - c[:-k, k:] - c[k:, :-k] + c[:-k, :-k]


def isolated(lines):
    """The line pixels where a single line passes (at most 7 line pixels in
    their 5x5 window): where dots instead of a line would show (in the dense
    parts the tubes overlap whatever their width)."""
    return lines & (window_sum(lines) <= 7)


def covered(lines, drawn):
    """Fraction of the isolated line pixels with a drawn pixel within one
    pixel."""
    alone = isolated(lines)
    return float((alone & dilate(drawn)).sum()) / max(int(alone.sum()), 1)


def width_ratio(lines, drawn):
    """Drawn pixels per line pixel in the 5x5 windows of the isolated line
    pixels (about the tubes' width in pixels)."""
    near = window_sum(isolated(lines)) > 0
    return float((drawn & near).sum()) / max(int((lines & near).sum()), 1)


def examine(label, proxy):
    view = white_view((800, 500))
    display = Show(proxy, view)  # noqa: F405
    ColorBy(display, ("POINTS", None))  # noqa: F405
    display.AmbientColor = [0.1, 0.2, 0.6]
    display.DiffuseColor = [0.1, 0.2, 0.6]
    Render(view)  # noqa: F405
    ResetCamera(view)  # noqa: F405
    check(display.TubeRadius == 0.0, "%s: Tube Radius defaults to 0 (automatic)" % label)
    display.SetRepresentationType("Wireframe")
    lines = mask(view, "TestPluginFirstPicture-%s-lines.png" % label)
    # The defaults, then tubes of a hundredth of the automatic radius (cb_2:
    # 0.004 mm, below the old default radius of 0.01 mm that showed dots),
    # which must still show as lines.
    bounds = proxy.GetDataInformation().GetBounds()
    diagonal = np.linalg.norm(np.array(bounds[1::2]) - np.array(bounds[0::2]))
    for case, radius in (("default", 0.0), ("thin", 2.5e-5 * diagonal)):
        display.TubeRadius = radius
        for representation in ("Ray-Cast Tubes", "Tessellated Tubes", "Stylized Lines"):
            display.SetRepresentationType(representation)
            tag = representation.split()[0].lower()
            drawn = mask(view, "TestPluginFirstPicture-%s-%s-%s.png" % (label, case, tag))
            c = covered(lines, drawn)
            check(c >= 0.97, "%s, %s radius, %s: %.1f %% of the %d isolated line pixels covered "
                  "(>= 97 %%)" % (label, case, representation, 100 * c, isolated(lines).sum()))
            ratio = width_ratio(lines, drawn)
            if case == "default":
                check(ratio >= 1.5, "%s, %s radius, %s: %.2f drawn pixels per line pixel where "
                      "lines are alone (tubes wider than lines, >= 1.5)"
                      % (label, case, representation, ratio))
            else:
                check(ratio <= 1.6, "%s, %s radius, %s: %.2f drawn pixels per line pixel where "
                      "lines are alone (about one pixel wide, <= 1.6)"
                      % (label, case, representation, ratio))
    display.SetRepresentationType("Ray-Cast Tubes")
    display.MinimumPixelWidth = 0.0
    drawn = mask(view, "TestPluginFirstPicture-%s-thin-exact.png" % label)
    c = covered(lines, drawn)
    check(c < 0.8, "negative control: %s, thin ray-cast tubes at their exact size (Minimum "
          "Pixel Width 0) cover %.1f %% of the lone lines' pixels (< 80 %%)" % (label, 100 * c))
    display.MinimumPixelWidth = 1.0
    display.TubeRadius = 0.0
    Delete(view)  # noqa: F405


tck, count = write_cb2_tck()
cb2 = OpenDataFile(tck)  # noqa: F405
check(cb2 is not None and cb2.GetXMLName() == "TractogramReader",
      "File > Open of the .tck picks the tractogram reader")
cb2.UpdatePipeline()
check(servermanager.Fetch(cb2).GetNumberOfCells() == count,
      "the .tck holds cb_2's %d streamlines" % count)
examine("cb_2", cb2)

dti = OpenDataFile(os.path.join(source_dir, "Testing", "Data", "DIPY",  # noqa: F405
                                "small_64D_dti.vti"))
tracer = TensorLineTracer(Input=dti)  # noqa: F405
tracer.Tensors = ["POINTS", "DTI"]
tracer.TensorLayout = "XX XY YY XZ YZ ZZ (NIfTI, DIPY)"
tracer.UpdatePipeline()
examine("tensor-lines", tracer)

checker.finish()
print("all checks passed")
