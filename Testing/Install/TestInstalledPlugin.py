# SPDX-License-Identifier: BSD-3-Clause
"""pvbatch with the installed SplineViz (TestInstall.sh plugin).

    pvbatch TestInstalledPlugin.py PREFIX FILE.tck COUNT startup|by-path

startup: ParaView was started with PV_PLUGIN_CONFIG_FILE naming the
installed SplineViz.plugins.xml; its plugin manager must have located the
plugin next to that file (inside PREFIX) and loaded it at start-up.
by-path: nothing set; splineviz.plugin.load_plugin() finds the installed
plugin next to the installed package and loads it.
Either way the plugin's TractogramReader must read COUNT streamlines from
FILE.tck, and `splineviz` must be the installed package.
"""
import os
import sys

from paraview import servermanager
from paraview.simple import *  # noqa: F401,F403

prefix, tck, count, mode = os.path.realpath(sys.argv[1]), sys.argv[2], int(sys.argv[3]), sys.argv[4]


def check(condition, message):
    if not condition:
        print("ERROR: " + message)
        sys.exit(1)


def inside_prefix(path):
    return path is not None and os.path.realpath(path).startswith(prefix + os.sep)


import splineviz  # noqa: E402
import splineviz.plugin  # noqa: E402

check(inside_prefix(splineviz.__file__), "splineviz imported from %s, not from %s" % (splineviz.__file__, prefix))
check(inside_prefix(splineviz.plugin.plugin_file()),
      "splineviz.plugin finds %s, not the installed plugin" % splineviz.plugin.plugin_file())

info = servermanager.vtkSMProxyManager.GetProxyManager().GetPluginManager().GetLocalInformation()
listed = {info.GetPluginName(i): info.GetPluginFileName(i) for i in range(info.GetNumberOfPlugins())}
if mode == "startup":
    check("SplineVizPlugin" in listed, "the plugin manager does not list SplineVizPlugin: %s" % sorted(listed))
    check(inside_prefix(listed["SplineVizPlugin"]),
          "SplineVizPlugin listed at %r, not in %s" % (listed["SplineVizPlugin"], prefix))
    check(splineviz.plugin.is_loaded(), "the plugin named by PV_PLUGIN_CONFIG_FILE was not loaded at start-up")
else:
    check(not splineviz.plugin.is_loaded(), "the plugin is loaded though nothing asked for it")

path = splineviz.plugin.load_plugin(globals())
check(inside_prefix(path), "loaded %s, not the installed plugin" % path)
reader = OpenDataFile(tck)  # noqa: F405 (File > Open: the plugin's reader factory)
check(reader is not None and reader.GetXMLName() == "TractogramReader",
      "File > Open does not use the plugin's reader for .tck")
reader.UpdatePipeline()
lines = reader.GetDataInformation().GetNumberOfCells()
check(lines == count, "the installed plugin read %d streamlines, not %d" % (lines, count))
print("%s: installed plugin %s read %d streamlines; splineviz from %s" % (mode, path, lines, splineviz.__file__))
