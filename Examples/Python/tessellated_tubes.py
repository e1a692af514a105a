# SPDX-License-Identifier: BSD-3-Clause
"""Spline tubes drawn with the GPU's tessellation unit (SplineViz's
vtkTessellatedTubeMapper, Salm, "Interactive Rendering of Spline Tubes",
section 3.1), in an ordinary VTK pipeline from Python.

    pvpython Examples/Python/tessellated_tubes.py [--data fibers|fibers2] \\
        [--samples 8] [--no-lod] [--wireframe] [--output tubes.png]

(with the build tree's `splineviz` on PYTHONPATH: source build/splineviz-env.sh)

The polylines of the synthetic fibers source become tubes whose radius
follows the "Radius" point array and whose color follows the "Scalar" point
array, both along cubic splines through the points. The script prints how
many triangles the GPU generated and which base meshes the level of detail
chose, and writes a PNG.
"""
import argparse

from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import (
    vtkActor,
    vtkRenderer,
    vtkRenderWindow,
    vtkWindowToImageFilter,
)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (OpenGL render window)

import splineviz

parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
parser.add_argument("--data", choices=["fibers", "fibers2"], default="fibers")
parser.add_argument("--samples", type=int, default=8, help="multisamples (0: none)")
parser.add_argument("--no-lod", action="store_true", help="the paper's fixed 16 x 8 base mesh")
parser.add_argument("--wireframe", action="store_true", help="show the tessellated triangles")
parser.add_argument("--size", type=int, nargs=2, default=[800, 600])
parser.add_argument("--output", default="tessellated-tubes.png")
args = parser.parse_args()

fibers = splineviz.vtkSyntheticFibersSource()
if args.data == "fibers2":
    fibers.SetPresetToFibers2()
else:
    fibers.SetPresetToFibers()

mapper = splineviz.vtkTessellatedTubeMapper()
mapper.SetInputConnection(fibers.GetOutputPort())
mapper.SetRadiusArray("Radius")           # per-point radius, world units
mapper.SetScalarModeToUsePointFieldData()  # color by a point array ...
mapper.SelectColorArray("Scalar")          # ... through the lookup table
mapper.SetScalarRange(0, 1)
mapper.SetMaxEdgeLength(16)                # pixels (screen-space criterion)
mapper.SetMaxSilhouetteEdgeLength(4)       # pixels (silhouettes, cap rims)
mapper.SetMaxTessellationLevel(5)          # Salm's bounds
mapper.SetMaxSilhouetteTessellationLevel(7)
mapper.SetLevelOfDetail(not args.no_lod)
mapper.CountPrimitivesOn()                 # a query: only for reporting

actor = vtkActor()
actor.SetMapper(mapper)
actor.GetProperty().SetSpecular(0.4)
actor.GetProperty().SetSpecularPower(40)
if args.wireframe:
    actor.GetProperty().SetRepresentationToWireframe()

renderer = vtkRenderer()
renderer.AddActor(actor)
renderer.SetBackground(0.08, 0.08, 0.1)
renderer.ResetCamera()
renderer.GetActiveCamera().Zoom(1.3)
window = vtkRenderWindow()
window.SetOffScreenRendering(1)
window.SetMultiSamples(args.samples)
window.SetSize(*args.size)
window.AddRenderer(renderer)
window.Render()

if not splineviz.vtkTessellatedTubeMapper.IsTessellationSupported(window):
    print("no tessellation shaders in this OpenGL context: drawn by ray casting")
print("segments: %d" % mapper.GetTubeCore().GetNumberOfSegments())
print("triangles generated: %d" % mapper.GetNumberOfPrimitivesGenerated())
print("base meshes (rings x sides: segments): %s" % mapper.GetLevelOfDetailSummary())
print("GPU memory: %.1f bytes per segment"
      % (mapper.GetGPUMemorySize() / mapper.GetTubeCore().GetNumberOfSegments()))

grab = vtkWindowToImageFilter()
grab.SetInput(window)
grab.ReadFrontBufferOff()
writer = vtkPNGWriter()
writer.SetFileName(args.output)
writer.SetInputConnection(grab.GetOutputPort())
writer.Write()
print("wrote", args.output)
