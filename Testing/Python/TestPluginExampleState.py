# SPDX-License-Identifier: BSD-3-Clause
"""pvbatch: run one of the ParaView state examples (Examples/Python/*_state.py)
the way the README tells users to: with build/splineviz-env.sh's
PV_PLUGIN_PATH, so ParaView loads the plugin at start-up and the example's
splineviz.plugin.load_plugin must not load it a second time. The example must
use the SplineViz representations (not its fallback) and draw its picture.

    pvbatch TestPluginExampleState.py <example name without .py>
"""
import os
import runpy
import sys

from paraview.simple import *  # noqa: F401,F403
from splineviz.plugin import is_loaded
from splineviz_testing import drawn_fraction

name = sys.argv[1]
source = os.environ["SPLINEVIZ_SOURCE_DIR"]
out = os.environ.get("SPLINEVIZ_TEST_OUTPUT", ".")
os.makedirs(out, exist_ok=True)
if not is_loaded():
    print("ERROR: SplineVizPlugin was not loaded at start-up from PV_PLUGIN_PATH=%s"
          % os.environ.get("PV_PLUGIN_PATH"))
    sys.exit(1)

png = os.path.join(out, "TestExampleState-%s.png" % name)
if os.path.exists(png):
    os.remove(png)
sys.argv = [name + ".py", png]
state = runpy.run_path(os.path.join(source, "Examples", "Python", name + ".py"),
                       run_name="__main__")

expected = {"lines": "Ray-Cast Tubes"}
if name == "tractography_state":
    expected = {"lines": "Stylized Lines", "fa": "Slice"}
if name == "tensor_lines_state":
    expected["glyph_display"] = "Superquadric Glyphs"
if name == "lr_spline_volume_state":
    expected["volume"] = "LR-Spline Volume"
for display, representation in expected.items():
    used = state[display].Representation
    print("%s: %s" % (display, used))
    if used != representation:
        print("ERROR: %s shows '%s', expected the plugin's '%s'" % (display, used, representation))
        sys.exit(1)

if name == "tractography_state":
    # The depth cues come from the line depth-cue view (ambient occlusion and
    # depth-dependent halos).
    view = state["view"]
    print("view: %s, ambient occlusion %d, depth halos %d"
          % (view.GetXMLName(), view.AmbientOcclusion, view.DepthHalos))
    if view.GetXMLName() != "RenderViewWithLineDepthCues" or not view.AmbientOcclusion \
            or not view.DepthHalos:
        print("ERROR: the tractography example does not show its depth cues")
        sys.exit(1)

drawn = drawn_fraction(png)
print("fraction of the picture that is not background: %.3f" % drawn)
if drawn < 0.05:
    print("ERROR: the example drew (almost) nothing")
    sys.exit(1)
