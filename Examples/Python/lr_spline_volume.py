# SPDX-License-Identifier: BSD-3-Clause
"""Direct volume rendering of an LR spline (Fuchs et al. §4) with
vtkLRSplineVolumeMapper: no resampling, the spline is evaluated exactly on the
GPU at every sample.

    pvpython Examples/Python/lr_spline_volume.py [OUTPUT_DIR]

Reads the real LR-spline volume cube-3patch-refined.lr (lrsplines-python's
test file) and takes its patch 1, the vector field v = (-y, x, z):
 - lr-spline-volume-streamlines.png: |v| volume rendered (composite, shaded
   with the exact gradient) with streamlines traced on the same spline
   (vtkLRSplineStreamTracer) drawn inside it as opaque ray-cast tubes: the
   rays end at the tubes' depth;
 - lr-spline-volume-isosurfaces.png: the isosurfaces |v| = 0.75 and 1.25
   (the outer one translucent), found between samples and refined by
   bisection on the exact spline, lit by its exact normal, with a clipping
   plane through the box.
"""
import os
import sys
import time

from vtkmodules.vtkCommonCore import vtkLookupTable
from vtkmodules.vtkCommonDataModel import vtkMultiBlockDataSet, vtkPiecewiseFunction, vtkPlane
from vtkmodules.vtkFiltersSources import vtkLineSource
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import (
    vtkActor,
    vtkColorTransferFunction,
    vtkRenderer,
    vtkRenderWindow,
    vtkVolume,
    vtkVolumeProperty,
    vtkWindowToImageFilter,
)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (OpenGL render window)

import splineviz

out = sys.argv[1] if len(sys.argv) > 1 else "."
os.makedirs(out, exist_ok=True)
here = os.path.dirname(os.path.abspath(__file__))
data = os.path.join(here, "..", "..", "Testing", "Data", "External", "cube-3patch-refined.lr")

reader = splineviz.vtkLRSplineReader()
reader.SetFileName(data)
reader.SetOutputFieldName("velocity")
reader.Update()
patch = vtkMultiBlockDataSet()  # patch 1 alone: v = (-y, x, z)
patch.SetBlock(0, reader.GetOutput().GetBlock(1))


def save(window, name):
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    writer = vtkPNGWriter()
    writer.SetFileName(os.path.join(out, name))
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()
    print("wrote", os.path.join(out, name))


def window_with(*props, size=(800, 600), background=(0.08, 0.09, 0.12)):
    renderer = vtkRenderer()
    renderer.SetBackground(*background)
    for prop in props:
        if isinstance(prop, vtkVolume):
            renderer.AddVolume(prop)
        else:
            renderer.AddActor(prop)
    window = vtkRenderWindow()
    window.SetSize(*size)
    window.SetMultiSamples(0)
    window.SetOffScreenRendering(1)
    window.AddRenderer(renderer)
    camera = renderer.GetActiveCamera()
    camera.SetFocalPoint(0.5, 0.5, 0.5)
    camera.SetPosition(2.5, 1.9, 2.1)
    camera.SetViewUp(0, 0, 1)
    renderer.ResetCamera()
    camera.Zoom(1.15)
    return window


# 1. |v| as a volume, streamlines inside as ray-cast tubes.
mapper = splineviz.vtkLRSplineVolumeMapper()
mapper.SetInputDataObject(patch)  # magnitude of the vectors by default
color = vtkColorTransferFunction()
color.AddRGBPoint(0.0, 0.23, 0.30, 0.75)
color.AddRGBPoint(0.9, 0.87, 0.87, 0.87)
color.AddRGBPoint(1.73, 0.71, 0.02, 0.15)
opacity = vtkPiecewiseFunction()
opacity.AddPoint(0.0, 0.0)
opacity.AddPoint(0.6, 0.02)
opacity.AddPoint(1.2, 0.15)
opacity.AddPoint(1.73, 0.6)
prop = vtkVolumeProperty()
prop.SetColor(color)
prop.SetScalarOpacity(opacity)
prop.SetScalarOpacityUnitDistance(0.25)
prop.ShadeOn()
prop.SetAmbient(0.35)
prop.SetDiffuse(0.7)
prop.SetSpecular(0.25)
volume = vtkVolume()
volume.SetMapper(mapper)
volume.SetProperty(prop)

seeds = vtkLineSource()
seeds.SetPoint1(0.25, 0.02, 0.05)
seeds.SetPoint2(0.95, 0.02, 0.05)
seeds.SetResolution(9)
tracer = splineviz.vtkLRSplineStreamTracer()
tracer.SetInputDataObject(patch)
tracer.SetSourceConnection(seeds.GetOutputPort())
tracer.SetIntegrationDirection(splineviz.vtkLRSplineStreamTracer.FORWARD)
tracer.SetMaximumIntegrationStep(0.02)
tubes = splineviz.vtkRayCastTubeMapper()
tubes.SetInputConnection(tracer.GetOutputPort())
tubes.SetRadius(0.012)
tubes.SetScalarModeToUsePointFieldData()
tubes.SelectColorArray("IntegrationTime")
tubes.SetScalarRange(0.0, 1.2)
lut = vtkLookupTable()
lut.SetHueRange(0.15, 0.0)
lut.SetSaturationRange(0.2, 0.9)
lut.Build()
tubes.SetLookupTable(lut)
tube_actor = vtkActor()
tube_actor.SetMapper(tubes)

window = window_with(volume, tube_actor)
start = time.perf_counter()
window.Render()
first = time.perf_counter() - start
start = time.perf_counter()
window.Render()
frame = time.perf_counter() - start
print("patch 1: %d elements, %.2f MB of spline data on the GPU; first frame %.2f s, "
      "next frame %.2f s (llvmpipe)" % (mapper.GetNumberOfElements(),
                                        mapper.GetGPUMemorySize() / 1e6, first, frame))
save(window, "lr-spline-volume-streamlines.png")

# 2. Isosurfaces on the exact spline, the outer one opened by a clipping plane.
iso_mapper = splineviz.vtkLRSplineVolumeMapper()
iso_mapper.SetInputDataObject(patch)
iso_mapper.SetBlendModeToIsoSurface()
plane = vtkPlane()
plane.SetOrigin(0.5, 0.5, 0.82)
plane.SetNormal(0.0, 0.0, -1.0)
iso_mapper.AddClippingPlane(plane)
iso_color = vtkColorTransferFunction()
iso_color.AddRGBPoint(0.75, 0.95, 0.65, 0.2)
iso_color.AddRGBPoint(1.25, 0.3, 0.55, 0.95)
iso_opacity = vtkPiecewiseFunction()
iso_opacity.AddPoint(0.75, 1.0)
iso_opacity.AddPoint(1.25, 0.45)
iso_prop = vtkVolumeProperty()
iso_prop.SetColor(iso_color)
iso_prop.SetScalarOpacity(iso_opacity)
iso_prop.ShadeOn()
iso_prop.SetSpecular(0.4)
iso_prop.SetSpecularPower(30)
iso_prop.GetIsoSurfaceValues().SetValue(0, 0.75)
iso_prop.GetIsoSurfaceValues().SetValue(1, 1.25)
iso_volume = vtkVolume()
iso_volume.SetMapper(iso_mapper)
iso_volume.SetProperty(iso_prop)
window = window_with(iso_volume)
window.Render()
save(window, "lr-spline-volume-isosurfaces.png")
