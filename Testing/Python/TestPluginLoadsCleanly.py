# SPDX-License-Identifier: BSD-3-Clause
"""pvbatch: the SplineViz plugin loads and shows data of every kind without a
warning or an error (ctest fails on any WARN|/ERR| line), and its ParaView
XML is complete:

- each SplineViz representation type is offered exactly once for the data
  types it extends (a type registered twice for one representation is what
  makes ParaView warn "Replacing existing representation for key");
- every property marked panel_visibility="advanced" in Plugin/xml keeps that
  visibility where the representation exposes it to the user;
- every property a user sees has a non-empty <Documentation>.

    pvbatch TestPluginLoadsCleanly.py SplineVizPlugin.so
"""
import glob
import os
import sys
import xml.etree.ElementTree as ET

from paraview.simple import *  # noqa: F401,F403

failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
        print("ERROR: " + message)


xml_dir = os.path.join(os.environ["SPLINEVIZ_SOURCE_DIR"], "Plugin", "xml")
xml_files = sorted(glob.glob(os.path.join(xml_dir, "*.xml")))
check(len(xml_files) >= 5, "no plugin XML found in %s" % xml_dir)

# Static: documentation of every visible property; the advanced ones per proxy.
advanced = {}  # representation proxy name -> property names marked advanced
for path in xml_files:
    for proxy in ET.parse(path).getroot().iter():
        if not (proxy.tag.endswith("Proxy") and proxy.get("name") and proxy.tag != "Proxy"):
            continue
        for prop in proxy:
            if not prop.tag.endswith("Property") or prop.get("name") is None:
                continue
            if prop.get("panel_visibility") == "never" or prop.get("information_only") == "1":
                continue
            doc = prop.find("Documentation")
            check(doc is not None and (doc.text or "").strip(),
                  "%s: %s.%s has no documentation" % (os.path.basename(path), proxy.get("name"), prop.get("name")))
            if prop.get("panel_visibility") == "advanced" and proxy.tag == "RepresentationProxy":
                advanced.setdefault(proxy.get("name"), []).append(prop.get("name"))

tubes = ["Ray-Cast Tubes", "Tessellated Tubes", "Stylized Lines"]
cases = [
    ("polygonal data", Sphere(), tubes + ["Superquadric Glyphs"]),  # noqa: F405
    ("unstructured grid", Tetrahedralize(Input=Sphere()), tubes + ["Superquadric Glyphs", "LR-Spline Volume"]),  # noqa: F405
    ("image", Wavelet(), ["Superquadric Glyphs"]),  # noqa: F405
    ("structured grid", Transform(Input=Wavelet()), ["Superquadric Glyphs"]),  # noqa: F405
    ("multiblock", GroupDatasets(Input=[Wavelet(), Sphere()]), tubes + ["Superquadric Glyphs"]),  # noqa: F405
]
view = CreateRenderView()  # noqa: F405


def property_names(display):
    return set(display.ListProperties())


# What ParaView's own representations have (before the plugin is loaded).
own = {}
for name, source, _ in cases:
    display = Show(source, view)  # noqa: F405
    own[name] = property_names(display)
    Delete(display)  # noqa: F405
    del display

LoadPlugin(sys.argv[1], remote=False, ns=globals())  # noqa: F405

advanced_names = set(n for names in advanced.values() for n in names)
checked_advanced = set()
for name, source, offered in cases:
    display = Show(source, view)  # noqa: F405
    Render(view)  # noqa: F405
    available = list(display.GetProperty("Representation").Available)
    for kind in offered:
        check(available.count(kind) == 1,
              "%s (%s): '%s' offered %d times" % (name, display.GetXMLName(), kind, available.count(kind)))
    added = property_names(display) - own[name]
    check(added, "%s: the plugin added no properties to %s" % (name, display.GetXMLName()))
    for prop_name in sorted(added & advanced_names):
        checked_advanced.add(prop_name)
        visibility = display.SMProxy.GetProperty(prop_name).GetPanelVisibility()
        check(visibility == "advanced",
              "%s: %s is '%s', not advanced" % (display.GetXMLName(), prop_name, visibility))
    Hide(source, view)  # noqa: F405
check(len(checked_advanced) >= 20, "only %d advanced properties were found exposed" % len(checked_advanced))

if failures:
    sys.exit(1)
print("plugin loaded cleanly; %d advanced properties checked where exposed" % len(checked_advanced))
