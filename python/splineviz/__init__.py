# SPDX-License-Identifier: BSD-3-Clause
"""SplineViz for Python: spline tubes, superquadric tensor glyphs and
LR-spline volumes as ordinary VTK classes.

    from splineviz import vtkRayCastTubeMapper, vtkSyntheticFibersSource

Every public class of the C++ module is exported here; they mix freely with
``vtkmodules`` (or ``paraview.vtk``) pipelines. See README.md.
"""

from .SplineViz import *  # noqa: F401,F403

__all__ = [name for name in dir() if name.startswith("vtk")]
