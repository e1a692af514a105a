# SPDX-License-Identifier: BSD-3-Clause
"""SplineViz for Python: spline tubes, superquadric tensor glyphs and
LR-spline volumes as ordinary VTK classes.

    from splineviz import vtkRayCastTubeMapper, vtkSyntheticFibersSource

Every public class of the C++ modules is exported here, from the wrapped
modules ``splineviz.SplineVizFilters``, ``splineviz.SplineVizIO`` and
``splineviz.SplineVizRendering`` (SplineViz::Filters, ::IO and ::Rendering;
SplineViz::Core has no wrapped classes); they mix freely with ``vtkmodules``
(or ``paraview.vtk``) pipelines. See README.md.
"""

from .SplineVizFilters import *  # noqa: F401,F403
from .SplineVizIO import *  # noqa: F401,F403
from .SplineVizRendering import *  # noqa: F401,F403

__all__ = [name for name in dir() if name.startswith("vtk")]
