# SPDX-License-Identifier: BSD-3-Clause
"""Shared by the Python and plugin tests: the checks and their report
(Checker), the synthetic-fibers scene the plugin tests draw, and measures of
how much of a rendered image is drawn."""
import os
import sys

import numpy as np


class Checker:
    """The checks of a test. check() prints one line per check, "ok: " or
    "ERROR: " (what ctest's FAIL_REGULAR_EXPRESSION looks for) and what was
    checked, and keeps the failures; finish() ends a failed test with their
    list and exit status 1 (a passed test goes on)."""

    def __init__(self):
        self.failures = []

    def check(self, condition, what):
        """Report `what` as passed when `condition` is true, else as failed.
        Returns the condition as a bool."""
        condition = bool(condition)
        print(("ok: " if condition else "ERROR: ") + what)
        if not condition:
            self.failures.append(what)
        return condition

    def fail(self, what):
        """Report `what` as failed."""
        self.check(False, what)

    def finish(self):
        """Exit with status 1 after listing the failures, if any."""
        if self.failures:
            print("ERROR: %d check(s) failed:\n  " % len(self.failures) + "\n  ".join(self.failures))
            sys.stdout.flush()
            sys.exit(1)


class Observed:
    """Collects an algorithm's errors and warnings (its executive's errors
    too), so that expected ones are not printed as failures."""

    def __init__(self, algorithm):
        from vtkmodules.util.vtkConstants import VTK_STRING

        self.errors = []
        self.warnings = []
        self.messages = []  # the errors' texts
        self.warning_messages = []  # the warnings' texts
        self.all_messages = []  # the errors' and warnings' texts, as they came
        self._error.__func__.CallDataType = VTK_STRING
        self._warning.__func__.CallDataType = VTK_STRING
        algorithm.AddObserver("ErrorEvent", self._error)
        algorithm.AddObserver("WarningEvent", self._warning)
        algorithm.GetExecutive().AddObserver("ErrorEvent", self._error)

    def _error(self, caller, event, message=None):
        self.errors.append(event)
        if message:
            self.messages.append(message)
            self.all_messages.append(message)

    def _warning(self, caller, event, message=None):
        self.warnings.append(event)
        if message:
            self.warning_messages.append(message)
            self.all_messages.append(message)


def set_translation(display, translation):
    """Sets a display's translation (the actor's position): the property's
    Python name is Position up to ParaView 5.11 and Translation (its label)
    from 5.12 on."""
    name = "Translation" if "Translation" in display.ListProperties() else "Position"
    setattr(display, name, list(translation))


def load_pre_rename_state(renames, path):
    """Saves the session's state to `path` rewritten as a state saved before
    the filters' field and mask became SetInputArrayToProcess properties
    (`renames`: new XML property name -> old one; the old properties held the
    array name alone), loads it, and returns the proxies it made (the
    "sources" group) by XML name. Remove with the deprecated names."""
    import xml.etree.ElementTree as ET

    from paraview import simple

    def ids():
        return set(p.GetGlobalIDAsString() for p in simple.GetSources().values())

    before = ids()
    simple.SaveState(path)
    tree = ET.parse(path)
    for prop in tree.iter("Property"):
        old = renames.get(prop.get("name"))
        if old is None:
            continue
        name = [e.get("value") for e in prop.findall("Element") if e.get("index") == "4"]
        for child in list(prop):
            prop.remove(child)
        prop.set("name", old)
        prop.set("id", prop.get("id").rsplit(".", 1)[0] + "." + old)
        prop.set("number_of_elements", "1")
        ET.SubElement(prop, "Element", index="0", value=name[0] if name else "")
    tree.write(path)
    simple.LoadState(path)
    loaded = {}
    for proxy in simple.GetSources().values():
        if proxy.GetGlobalIDAsString() not in before:
            loaded.setdefault(proxy.GetXMLName(), []).append(proxy)
    return loaded


def output_dir():
    """Where the tests write their images (ctest: build/Testing/Temporary)."""
    out = os.environ.get("SPLINEVIZ_TEST_OUTPUT", ".")
    os.makedirs(out, exist_ok=True)
    return out


def fibers_scene(ns, size=(600, 450), baseline=False):
    """SyntheticFibers (Preset Fibers) shown on white (a white_view(), with
    `baseline` as there), colored by its Scalar array, seen from a fixed
    camera. `ns`: the namespace LoadPlugin gave the plugin's functions to
    (the test's globals()). Returns (source, view, display)."""
    from paraview import simple

    fibers = ns["SyntheticFibers"](Preset=1)
    view = white_view(size, baseline)
    display = simple.Show(fibers, view)
    simple.ColorBy(display, ("POINTS", "Scalar"))
    simple.ResetCamera(view)
    view.CameraPosition = [0.3, 0.2, 2.2]
    view.CameraFocalPoint = [0, 0, 0]
    return fibers, view, display


def white_view(size=(500, 420), baseline=False):
    """A ParaView render view of the given size on white, without orientation
    axes (what coverage() measures against). `baseline`: single-sampled and
    without FXAA (ParaView's default is on), as the pictures compare_baseline()
    compares are."""
    from paraview import simple

    view = simple.CreateRenderView()
    view.ViewSize = list(size)
    view.UseColorPaletteForBackground = 0
    view.Background = [1, 1, 1]
    view.OrientationAxesVisibility = 0
    if baseline:
        view.MultiSamples = 0
        view.UseFXAA = 0
    return view


# The largest image error vtkTesting may find against a baseline. Its error
# (vtkImageDifference) sums, over the pixels, by how much each channel
# differs by more than 105 from the best match among the pixel's 3x3
# neighbours, in units of a whole pixel wrong (3 x 255): 0.01 fails a picture
# with a single pixel channel 8 levels beyond that tolerance. The pictures are
# rendered the same way each time, so an unchanged one has error 0; the
# fibers' ray-cast tubes 10 % thicker reach 0.034, the tensor lines' 0.18,
# another color map hundreds. Tighter than the C++ image tests' 0.05, which
# the 10 % thicker fibers pass.
BASELINE_THRESHOLD = 0.01


def compare_baseline(view, name, threshold=BASELINE_THRESHOLD):
    """VTK's image regression test of the screenshot `name` in output_dir()
    (as coverage() writes it) against Testing/Data/Baseline/`name`, done as
    the C++ image tests do it (vtkTesting: alternate baselines name_1.png,
    ...; a failed comparison leaves the test and difference images in
    output_dir()). `view` must be single-sampled without FXAA, as
    white_view() and fibers_scene() make it with baseline=True. Returns whether it passed; a
    failure prints an "ERROR: " line (the test fails)."""
    from vtkmodules.vtkTestingRendering import vtkTesting

    if view.MultiSamples != 0 or view.UseFXAA != 0:
        print("ERROR: %s: the baselines are single-sampled without FXAA" % name)
        return False
    baseline = os.path.join(os.environ["SPLINEVIZ_SOURCE_DIR"], "Testing", "Data", "Baseline",
                            name)
    testing = vtkTesting()
    for argument in ("-V", baseline, "-T", output_dir()):
        testing.AddArgument(argument)
    passed = testing.RegressionTest(os.path.join(output_dir(), name), threshold) == 1
    # vtkTesting's measurements end without a newline: start a line of our own
    # (ctest looks for "ERROR: " at the start of one).
    if passed:
        print("\nok: %s matches its baseline (threshold %g)" % (name, threshold))
    else:
        print("\nERROR: %s differs from its baseline %s (threshold %g; the test and difference "
              "images are in %s)" % (name, baseline, threshold, output_dir()))
    sys.stdout.flush()
    return passed


def coverage(view, name, stride=3, background=(255.0, 255.0, 255.0)):
    """Save a screenshot of `view` as `name` in output_dir() and return
    (fraction of the sampled pixels that differ from the background, the
    sampled pixels); every `stride`-th pixel is sampled."""
    from paraview import simple
    from paraview.vtk.vtkIOImage import vtkPNGReader

    png = os.path.join(output_dir(), name)
    simple.SaveScreenshot(png, view, ImageResolution=list(view.ViewSize))
    reader = vtkPNGReader()
    reader.SetFileName(png)
    reader.Update()
    scalars = reader.GetOutput().GetPointData().GetScalars()
    pixels = [scalars.GetTuple3(i) for i in range(0, scalars.GetNumberOfTuples(), stride)]
    hit = sum(1 for p in pixels if p != background)
    return hit / float(len(pixels)), pixels


def png_rgb(png):
    """The RGB pixels of the image file `png` as an int numpy array of shape
    (height, width, 3), the first row at the bottom (VTK's order)."""
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkIOImage import vtkPNGReader

    reader = vtkPNGReader()
    reader.SetFileName(png)
    reader.Update()
    width, height, _ = reader.GetOutput().GetDimensions()
    rgb = vtk_to_numpy(reader.GetOutput().GetPointData().GetScalars())[:, :3].astype(int)
    return rgb.reshape(height, width, 3)


def drawn_fraction(png, background=None, tolerance=30):
    """Fraction of the pixels of the image file `png` whose RGB differs from
    `background` (default: the first pixel) by more than `tolerance` in
    some channel."""
    rgb = png_rgb(png).reshape(-1, 3)
    reference = rgb[0] if background is None else background
    return float((abs(rgb - reference).max(axis=1) > tolerance).mean())


def drawn_mask(rgb, background=(255, 255, 255), tolerance=3):
    """Per pixel of `rgb` (as png_rgb returns it): whether it differs from
    `background` by more than `tolerance` in some channel."""
    return abs(rgb - np.asarray(background)).max(axis=2) > tolerance


def offscreen_window(actor, size, background=(1, 1, 1)):
    """A single-sampled offscreen render window of `size` (width, height)
    whose one renderer, with `background`, holds `actor`: the scene the VTK
    (not ParaView) image tests draw. Returns (window, renderer)."""
    from vtkmodules.vtkRenderingCore import vtkRenderWindow, vtkRenderer
    import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the OpenGL factory)

    ren = vtkRenderer()
    ren.SetBackground(*background)
    ren.AddActor(actor)
    win = vtkRenderWindow()
    win.SetOffScreenRendering(1)
    win.SetMultiSamples(0)
    win.SetSize(*size)
    win.AddRenderer(ren)
    return win, ren


def save_window(window, png):
    """Write what `window` shows (its back buffer, rendered already) to the
    PNG file `png` and return its RGB pixels as png_rgb() would read them
    back: an int numpy array (height, width, 3), the first row at the bottom."""
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkIOImage import vtkPNGWriter
    from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter

    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    grab.Update()
    writer = vtkPNGWriter()
    writer.SetInputConnection(grab.GetOutputPort())
    writer.SetFileName(png)
    writer.Write()
    image = grab.GetOutput()
    width, height, _ = image.GetDimensions()
    scalars = vtk_to_numpy(image.GetPointData().GetScalars())
    return scalars[:, :3].reshape(height, width, 3).astype(int)


def openfoam_case(source_dir):
    """The .foam file of OpenFOAM's porous angled duct, run once by
    scripts/openfoam-case.sh into the tests' output (SPLINEVIZ_NO_INSTALL: the
    tests do not install packages); None after printing why it failed."""
    import subprocess

    case_dir = os.path.join(output_dir(), "openfoam", "angledDuct")
    run = subprocess.run([os.path.join(source_dir, "scripts", "openfoam-case.sh"), case_dir],
                         env=dict(os.environ, SPLINEVIZ_NO_INSTALL="1"),
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if run.returncode != 0:
        print(run.stderr)
        print("ERROR: scripts/openfoam-case.sh failed")
        return None
    return run.stdout.strip().splitlines()[-1]
