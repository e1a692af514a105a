# SPDX-License-Identifier: BSD-3-Clause
"""Tie a line representation's slab crop to a ParaView Slice, as mrview crops
streamlines to a slab around the slice it shows under them.

    from paraview.simple import *
    from splineviz.slab import tie_slab_to_slice
    t1_slice = Slice(Input=t1)             # the anatomy, e.g. a T1 volume
    lines = Show(tractogram, view)
    lines.SetRepresentationType("Stylized Lines")
    tie_slab_to_slice(lines, t1_slice, thickness=5.0)
    t1_slice.SliceType.Origin = [0, 0, 12]  # the lines' slab moves with it

The representation's Slab Origin and Slab Normal follow the slice plane's
Origin and Normal from then on (ParaView property links, registered with the
proxy manager: they are saved in state files and listed under Tools > Manage
Links). Both must be in the same world coordinates, as SplineViz's NIfTI and
tractogram readers place them (RAS+ millimetres). The plane's Offset Values
and the slice's Transform are not followed.
"""

LINKED = (("Origin", "SlabOrigin"), ("Normal", "SlabNormal"))


def _link_names(name):
    return ["%s %s" % (name, slab) for _, slab in LINKED]


def tie_slab_to_slice(representation, slice_source, thickness=None, name=None):
    """Make ``representation`` (a "Ray-Cast Tubes", "Tessellated Tubes" or
    "Stylized Lines" display) crop its lines to the plane of ``slice_source``
    (a Slice filter whose Slice Type is a Plane), now and whenever the plane
    moves. ``thickness``: the Slab Thickness to set (left as it is when None;
    a thickness of 0 draws the whole lines). ``name``: the links' name
    prefix (default: derived from the two proxies). Returns the link names.
    Raises ValueError for a representation without a slab or a slice without
    a plane."""
    from paraview import servermanager

    for _, slab in LINKED:
        if representation.GetProperty(slab) is None:
            raise ValueError("the representation has no %s property: choose a SplineViz line "
                             "representation (Ray-Cast Tubes, Tessellated Tubes or Stylized "
                             "Lines)" % slab)
    plane = slice_source.GetProperty("SliceType")
    plane = plane.GetData() if plane is not None else None
    if plane is None or plane.GetProperty("Origin") is None or \
            plane.GetProperty("Normal") is None:
        raise ValueError("the slice has no plane (Slice Type must be Plane)")
    if thickness is not None:
        if not thickness >= 0:
            raise ValueError("the slab thickness must be 0 or more, not %r" % (thickness,))
        representation.SlabThickness = thickness
    if name is None:
        name = "SplineViz slab of %s to %s" % (
            representation.SMProxy.GetGlobalIDAsString(), slice_source.SMProxy.GetGlobalIDAsString())
    manager = servermanager.ProxyManager()
    names = _link_names(name)
    for (source, slab), link_name in zip(LINKED, names):
        # The slab takes the plane's value now; the link keeps it so.
        representation.SMProxy.GetProperty(slab).Copy(plane.SMProxy.GetProperty(source))
        link = servermanager.vtkSMPropertyLink()
        link.AddLinkedProperty(plane.SMProxy, source, servermanager.vtkSMLink.INPUT)
        link.AddLinkedProperty(representation.SMProxy, slab, servermanager.vtkSMLink.OUTPUT)
        manager.RegisterLink(link_name, link)
    representation.UpdateVTKObjects()
    return names


def untie_slab(names):
    """Remove the links ``tie_slab_to_slice`` returned; the slab keeps its
    current plane."""
    from paraview import servermanager

    manager = servermanager.ProxyManager()
    for link_name in names:
        manager.UnRegisterLink(link_name)
