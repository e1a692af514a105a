# SPDX-License-Identifier: BSD-3-Clause
"""Client/server: pvpython connects to a pvserver of its own (started here on
a free port, without PV_PLUGIN_PATH), loads SplineVizPlugin on both sides
with splineviz.plugin.load_plugin, and renders the synthetic fibers with the
"Ray-Cast Tubes" representation on the server. Checks that the plugin is
loaded on the client, that the server offers the SplineViz representations,
and that the remotely rendered tubes cover much more of the image than
1-pixel lines, and that the "Render View (Line Depth Cues)" view draws its
halos there; then the real LR-spline file as "LR-Spline Volume" (the
spline stays on the server, which renders it), plain and trimmed by a
sphere.

    pvpython TestPluginClientServer.py <pvserver executable>
"""
import os
import socket
import subprocess
import sys
import time

from paraview.simple import *  # noqa: F401,F403
from splineviz_testing import coverage as image_coverage
from splineviz_testing import fibers_scene

pvserver = sys.argv[1]
out_dir = os.environ.get("SPLINEVIZ_TEST_OUTPUT", ".")
os.makedirs(out_dir, exist_ok=True)

with socket.socket() as s:
    s.bind(("localhost", 0))
    port = s.getsockname()[1]
env = dict(os.environ)
env.pop("PV_PLUGIN_PATH", None)  # the server must get the plugin from the client's request
log_path = os.path.join(out_dir, "TestPluginClientServer-pvserver.log")
log = open(log_path, "w")
server = subprocess.Popen([pvserver, "--server-port=%d" % port], stdout=log,
                          stderr=subprocess.STDOUT, env=env)
try:
    deadline = time.time() + 60
    while True:
        with open(log_path) as f:
            if "Accepting connection" in f.read():
                break
        if server.poll() is not None or time.time() > deadline:
            print("ERROR: pvserver did not start (see %s)" % log_path)
            sys.exit(1)
        time.sleep(0.2)

    Connect("localhost", port)  # noqa: F405
    from splineviz.plugin import is_loaded, load_plugin

    load_plugin(globals())
    if not is_loaded():
        print("ERROR: the plugin is not loaded on the client")
        sys.exit(1)

    fibers, view, display = fibers_scene(globals())
    available = display.GetProperty("Representation").Available
    for name in ("Ray-Cast Tubes", "Tessellated Tubes", "Superquadric Glyphs"):
        if name not in available:
            print("ERROR: the server does not offer the '%s' representation" % name)
            sys.exit(1)

    def coverage(name):
        return image_coverage(view, name)[0]

    display.SetRepresentationType("Surface")
    lines = coverage("TestPluginClientServer-lines.png")
    display.SetRepresentationType("Ray-Cast Tubes")
    display.TubeRadiusArray = "Radius"
    tubes = coverage("TestPluginClientServer.png")
    print("coverage: lines %.3f, ray-cast tubes on the server %.3f" % (lines, tubes))
    if tubes < 2.0 * lines or tubes < 0.1:
        print("ERROR: the ray-cast tubes were not rendered on the server")
        sys.exit(1)

    # "Render View (Line Depth Cues)": the pass runs where the server renders;
    # its halos cut the tubes behind (less of the image covered).
    cues = CreateView("RenderViewWithLineDepthCues")  # noqa: F405
    for name in ("ViewSize", "Background", "UseColorPaletteForBackground",
                 "OrientationAxesVisibility", "CameraPosition", "CameraFocalPoint",
                 "CameraViewUp"):
        setattr(cues, name, getattr(view, name))
    cue_display = Show(fibers, cues)  # noqa: F405
    cue_display.SetRepresentationType("Ray-Cast Tubes")
    cue_display.TubeRadiusArray = "Radius"
    cues.AmbientOcclusion = 0
    cues.UseLineDepthCues = 0
    without = image_coverage(cues, "TestPluginClientServer-cues-off.png")[0]
    cues.UseLineDepthCues = 1
    cues.DepthHalos = 1
    cues.HaloWidth = 6.0
    haloed = image_coverage(cues, "TestPluginClientServer-cues-halos.png")[0]
    print("coverage: line depth cues view %.3f, with halos %.3f" % (without, haloed))
    if without < 0.1 or not haloed < 0.95 * without:
        print("ERROR: the line depth cues view did not draw its halos on the server")
        sys.exit(1)
    Delete(cues)  # noqa: F405
    SetActiveView(view)  # noqa: F405

    # "LR-Spline Volume": the server reads the spline and renders it.
    path = os.path.join(os.environ["SPLINEVIZ_SOURCE_DIR"], "Testing", "Data", "External",
                        "cube-3patch-refined.lr")
    Hide(fibers, view)  # noqa: F405
    spline = OpenDataFile(path)  # noqa: F405
    volume = Show(spline, view)  # noqa: F405
    volume.SetRepresentationType("LR-Spline Volume")
    ColorBy(volume, ("POINTS", "Field", "Magnitude"))  # noqa: F405
    ResetCamera(view)  # noqa: F405
    whole = coverage("TestPluginClientServer-lr-spline-volume.png")
    volume.TrimmingSurface = Sphere(Center=[0.5, 0.5, 0.5], Radius=0.3)  # noqa: F405
    trimmed = coverage("TestPluginClientServer-lr-spline-volume-trimmed.png")
    print("coverage: LR-spline volume on the server %.3f, trimmed by a sphere %.3f" % (
        whole, trimmed))
    if whole < 0.2 or not 0.1 * whole < trimmed < 0.5 * whole:
        print("ERROR: the LR-spline volume was not rendered (or not trimmed) on the server")
        sys.exit(1)
    Disconnect()  # noqa: F405
finally:
    server.terminate()
    try:
        server.wait(timeout=30)
    except subprocess.TimeoutExpired:
        server.kill()
    log.close()
