"""The example scripts run and draw something (they are documentation: a
broken example is a bug)."""
import os
import runpy
import sys

from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader

source = os.environ["SPLINEVIZ_SOURCE_DIR"]
out = os.environ.get("SPLINEVIZ_TEST_OUTPUT", ".")
os.makedirs(out, exist_ok=True)
png = os.path.join(out, "TestExamples-raycast_tubes.png")
sys.argv = ["raycast_tubes.py", png]
runpy.run_path(os.path.join(source, "Examples", "Python", "raycast_tubes.py"), run_name="__main__")
reader = vtkPNGReader()
reader.SetFileName(png)
reader.Update()
rgb = vtk_to_numpy(reader.GetOutput().GetPointData().GetScalars())[:, :3]
drawn = (rgb.min(axis=1) < 240).mean()
print("fraction drawn:", drawn)
if drawn < 0.2:
    print("ERROR: the example drew (almost) nothing")
    sys.exit(1)
