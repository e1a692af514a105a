# SPDX-License-Identifier: BSD-3-Clause
"""Load the SplineViz ParaView plugin from a pvpython/pvbatch script, once.

    from paraview.simple import *
    from splineviz.plugin import load_plugin
    load_plugin(globals())

After ``source build/splineviz-env.sh`` ParaView already loads the plugin at
start-up (it is on ``PV_PLUGIN_PATH``); ParaView 5.11's ``LoadPlugin`` then
fails with the misleading "Plugin load failed: No plugin loaded yet." when it
is asked to load the same library again. ``load_plugin`` loads it only when
it is not loaded yet, so a script works the same with and without the
environment script.
"""
import os

PLUGIN_NAME = "SplineVizPlugin"


def plugin_file():
    """The plugin library: ``$SPLINEVIZ_PLUGIN``, else the build tree next to
    this package (``lib/paraview-5.11/plugins/SplineVizPlugin``), else the
    directories of ``$PV_PLUGIN_PATH``. None when there is none."""
    candidates = []
    if os.environ.get("SPLINEVIZ_PLUGIN"):
        candidates.append(os.environ["SPLINEVIZ_PLUGIN"])
    # <build>/lib/python3.X/site-packages/splineviz/plugin.py -> <build>/lib
    lib = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", ".."))
    if os.path.isdir(lib):
        for entry in sorted(os.listdir(lib)):
            if entry.startswith("paraview-"):
                candidates.append(
                    os.path.join(lib, entry, "plugins", PLUGIN_NAME, PLUGIN_NAME + ".so"))
    for directory in os.environ.get("PV_PLUGIN_PATH", "").split(os.pathsep):
        if directory:
            candidates.append(os.path.join(directory, PLUGIN_NAME + ".so"))
    for candidate in candidates:
        if os.path.isfile(candidate):
            return candidate
    return None


def is_loaded():
    """True when this process (the client, or pvbatch) has loaded the plugin."""
    from paraview.modules.vtkRemotingCore import vtkPVPluginTracker

    tracker = vtkPVPluginTracker.GetInstance()
    for i in range(tracker.GetNumberOfPlugins()):
        if tracker.GetPluginName(i) == PLUGIN_NAME and tracker.GetPluginLoaded(i):
            return True
    return False


def load_plugin(ns=None, filename=None):
    """Load the plugin unless it is loaded already; return its file name.

    ``ns``: the namespace that gets the plugin's sources, filters and readers
    as functions (pass ``globals()``, as for ``paraview.simple.LoadPlugin``);
    ``paraview.simple`` gets them as well.
    ``filename``: the library to load (default: ``plugin_file()``).
    Connected to a remote pvserver, the plugin is loaded there as well (it is
    required on client and server). Raises RuntimeError when the plugin cannot
    be found or loaded."""
    from paraview import servermanager, simple

    path = filename or plugin_file()
    if not is_loaded():
        if path is None:
            raise RuntimeError(
                "SplineVizPlugin not found: source build/splineviz-env.sh, or set "
                "SPLINEVIZ_PLUGIN to the path of SplineVizPlugin.so")
        simple.LoadPlugin(path, remote=False, ns=ns)
        if not is_loaded():
            raise RuntimeError("could not load the SplineViz plugin from %s" % path)
        # LoadPlugin gives the new functions to `ns` only; paraview.simple
        # gets them too, so that `simple.TensorAnalysis(...)` works as well.
        simple._add_functions(vars(simple))
    elif ns is not None:
        # Loaded at start-up: make sure the caller's namespace has the
        # plugin's functions even if it imported paraview.simple early.
        simple._add_functions(ns)
    connection = servermanager.ActiveConnection
    if path and connection is not None and connection.IsRemote():
        simple.LoadPlugin(path, remote=True, ns=ns)
    return path
