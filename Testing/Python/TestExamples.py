# SPDX-License-Identifier: BSD-3-Clause
"""The example scripts run and draw something (they are documentation: a
broken example is a bug)."""
import os
import runpy
import sys

from splineviz_testing import drawn_fraction, png_rgb

source = os.environ["SPLINEVIZ_SOURCE_DIR"]
out = os.environ.get("SPLINEVIZ_TEST_OUTPUT", ".")
os.makedirs(out, exist_ok=True)
png = os.path.join(out, "TestExamples-raycast_tubes.png")
sys.argv = ["raycast_tubes.py", png]
runpy.run_path(os.path.join(source, "Examples", "Python", "raycast_tubes.py"), run_name="__main__")
drawn = drawn_fraction(png, background=(255, 255, 255), tolerance=15)  # white background
print("fraction drawn:", drawn)
if drawn < 0.2:
    print("ERROR: the example drew (almost) nothing")
    sys.exit(1)

# superquadric_glyphs.py: DIPY's real scan as glyphs (VTK part; the ParaView
# part runs when SPLINEVIZ_PLUGIN is set). Needs DIPY.
try:
    import dipy  # noqa: F401
except ImportError:
    dipy = None
if dipy is None:
    print("DIPY not available: superquadric_glyphs.py skipped")
else:
    glyph_out = os.path.join(out, "TestExamples-superquadric")
    sys.argv = ["superquadric_glyphs.py", glyph_out]
    try:
        runpy.run_path(os.path.join(source, "Examples", "Python", "superquadric_glyphs.py"),
                       run_name="__main__")
    except SystemExit as stop:
        if stop.code not in (0, None):
            raise
    for gamma in (0, 3, 20):
        drawn = drawn_fraction(
            os.path.join(glyph_out, "superquadric-glyphs-vtk-gamma%d.png" % gamma),
            background=(0, 0, 0), tolerance=40)  # black background
        print("superquadric glyphs, gamma %d: fraction drawn %.3f" % (gamma, drawn))
        if drawn < 0.08:
            print("ERROR: the superquadric example drew (almost) nothing")
            sys.exit(1)

# neuroimaging_io.py: DIPY's real scan through NIfTI, glyphs, fibres, .tck back
# to nibabel (the example checks the round trip itself). Needs DIPY and nibabel.
try:
    import nibabel  # noqa: F401
except ImportError:
    nibabel = None
if dipy is None or nibabel is None:
    print("DIPY or nibabel not available: neuroimaging_io.py skipped")
else:
    neuro_out = os.path.join(out, "TestExamples-neuroimaging")
    sys.argv = ["neuroimaging_io.py", neuro_out]
    runpy.run_path(os.path.join(source, "Examples", "Python", "neuroimaging_io.py"),
                   run_name="__main__")
    drawn = drawn_fraction(os.path.join(neuro_out, "neuroimaging-dipy.png"),
                           background=(255, 255, 255), tolerance=15)
    print("neuroimaging example: fraction drawn %.3f" % drawn)
    if drawn < 0.15:
        print("ERROR: the neuroimaging example drew (almost) nothing")
        sys.exit(1)

# stylized_lines.py: Stoll's Fig. 11 encodings on streamlines VTK traces
# (VTK part; the ParaView part runs when SPLINEVIZ_PLUGIN is set).
lines_out = os.path.join(out, "TestExamples-stylized")
sys.argv = ["stylized_lines.py", lines_out]
runpy.run_path(os.path.join(source, "Examples", "Python", "stylized_lines.py"), run_name="__main__")
pictures = ["stylized-lines.png"]
if os.environ.get("SPLINEVIZ_PLUGIN"):
    pictures.append("stylized-lines-paraview.png")
for picture in pictures:
    drawn = drawn_fraction(os.path.join(lines_out, picture), tolerance=15)
    print("stylized lines example, %s: fraction drawn %.3f" % (picture, drawn))
    if drawn < 0.05:
        print("ERROR: the stylized lines example drew (almost) nothing in", picture)
        sys.exit(1)

# lr_spline_volume.py: direct volume rendering of a real LR spline (volume
# with streamline tubes inside; isosurfaces).
volume_out = os.path.join(out, "TestExamples-lr-spline-volume")
sys.argv = ["lr_spline_volume.py", volume_out]
runpy.run_path(os.path.join(source, "Examples", "Python", "lr_spline_volume.py"),
               run_name="__main__")
for picture in ["lr-spline-volume-streamlines.png", "lr-spline-volume-isosurfaces.png"]:
    drawn = drawn_fraction(os.path.join(volume_out, picture), background=(20, 23, 31),
                           tolerance=6)
    print("LR-spline volume example, %s: fraction drawn %.3f" % (picture, drawn))
    if drawn < 0.1:
        print("ERROR: the LR-spline volume example drew (almost) nothing in", picture)
        sys.exit(1)

# lr_spline_fit_image.py: DIPY's real scan fitted by an LR spline (to 10 % of
# the range here, to keep the suite short; 2 % by default), written as .lr
# and read back (the example checks that itself). Needs DIPY.
if dipy is None:
    print("DIPY not available: lr_spline_fit_image.py skipped")
else:
    fit_out = os.path.join(out, "TestExamples-lr-fit")
    sys.argv = ["lr_spline_fit_image.py", fit_out, "0.1"]
    try:
        runpy.run_path(os.path.join(source, "Examples", "Python", "lr_spline_fit_image.py"),
                       run_name="__main__")
    except SystemExit as stop:
        if stop.code not in (0, None):
            print("ERROR: lr_spline_fit_image.py failed with", stop.code)
            sys.exit(1)
    if not os.path.getsize(os.path.join(fit_out, "aniso_vox.lr")):
        print("ERROR: the fitting example wrote no .lr file")
        sys.exit(1)
    drawn = drawn_fraction(os.path.join(fit_out, "lr-spline-fit-aniso-vox.png"),
                           background=(255, 255, 255), tolerance=15)
    print("fitting example: fraction drawn %.3f" % drawn)
    if drawn < 0.6:
        print("ERROR: the fitting example's slices are (almost) blank")
        sys.exit(1)
    # the two halves: the voxels (vtkSmartVolumeMapper) and the spline
    # (vtkLRSplineVolumeMapper) must both show the brain, about as large
    rgb = png_rgb(os.path.join(fit_out, "lr-spline-fit-aniso-vox-volume.png"))
    rgb = rgb[: rgb.shape[0] * 85 // 100]   # above the labels
    half = rgb.shape[1] // 2
    drawn = [float((abs(part.reshape(-1, 3).astype(int) - (26, 26, 31)).max(axis=1) > 12).mean())
             for part in (rgb[:, :half], rgb[:, half:])]
    print("fitting example, volume rendering: fraction drawn %.3f (voxels), %.3f (spline)"
          % tuple(drawn))
    if min(drawn) < 0.15 or not 0.75 < drawn[1] / drawn[0] < 1.33:
        print("ERROR: the fitted spline's volume rendering is blank or unlike the scan's")
        sys.exit(1)

# streamline_selection.py: DIPY's cb_2 dissected by a sphere and a box; the
# picture shows selected (orange) and other (grey) streamlines. Needs DIPY.
if dipy is None or nibabel is None:
    print("DIPY or NiBabel not available: streamline_selection.py skipped")
else:
    selection_out = os.path.join(out, "TestExamples-selection")
    sys.argv = ["streamline_selection.py", selection_out]
    runpy.run_path(os.path.join(source, "Examples", "Python", "streamline_selection.py"),
                   run_name="__main__")
    rgb = png_rgb(os.path.join(selection_out, "streamline-selection.png")).reshape(-1, 3).astype(int)
    orange = int((abs(rgb - (242, 115, 13)).max(axis=1) < 60).sum())
    grey = int(((abs(rgb - rgb.mean(axis=1, keepdims=True)).max(axis=1) < 12)
                & (rgb.mean(axis=1) < 215) & (rgb.mean(axis=1) > 60)).sum())
    print("selection example: %d orange, %d grey pixels" % (orange, grey))
    if orange < 500 or grey < 2000:
        print("ERROR: the selection example does not show selected and other streamlines")
        sys.exit(1)
