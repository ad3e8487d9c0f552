"""Opens a crashsim XDMF description in ParaView (pvpython), goes to the last
state, colours the deformed mesh by von Mises stress and saves a PNG.

    xvfb-run -a pvpython paraview_render.py RUN.xdmf OUT.png

Prints what ParaView read (time steps, point and cell arrays, bounds) and the
share of the picture the model covers, for the test to check."""
import sys

from paraview.simple import (ColorBy, GetActiveViewOrCreate, SaveScreenshot,
                             Show, XDMFReader)
from vtkmodules.vtkIOImage import vtkPNGReader

xdmf, png = sys.argv[1], sys.argv[2]
src = XDMFReader(FileNames=[xdmf])
src.UpdatePipelineInformation()
times = list(src.TimestepValues)
last = times[-1]
src.UpdatePipeline(last)
info = src.GetDataInformation()
print("timesteps", len(times), "last", last)
print("points", info.GetNumberOfPoints(), "cells", info.GetNumberOfCells())
print("point_arrays", ",".join(sorted(src.PointData.keys())))
print("cell_arrays", ",".join(sorted(src.CellData.keys())))
print("bounds", " ".join(f"{b:.6g}" for b in info.GetBounds()))
vm = src.CellData["von_mises"].GetRange()
print("von_mises_range", f"{vm[0]:.6g}", f"{vm[1]:.6g}")

view = GetActiveViewOrCreate("RenderView")
view.ViewSize = [800, 600]
view.ViewTime = last
view.OrientationAxesVisibility = 0
view.Background = [1.0, 1.0, 1.0]
try:  # ParaView >= 5.10 takes the background from the colour palette unless told
    view.UseColorPaletteForBackground = 0
except AttributeError:
    pass
shown = Show(src, view)
ColorBy(shown, ("CELLS", "von_mises"))
shown.RescaleTransferFunctionToDataRange(True)
shown.SetScalarBarVisibility(view, True)
view.CameraPosition = [1.0, -1.5, 1.2]
view.CameraFocalPoint = [0.0, 0.0, 0.0]
view.CameraViewUp = [0.0, 0.0, 1.0]
view.ResetCamera()
SaveScreenshot(png, view, ImageResolution=[800, 600])

# Share of pixels that are not the white background.
reader = vtkPNGReader()
reader.SetFileName(png)
reader.Update()
img = reader.GetOutput()
scalars = img.GetPointData().GetScalars()
n = img.GetNumberOfPoints()
comps = scalars.GetNumberOfComponents()
covered = 0
for i in range(n):
    rgb = [scalars.GetComponent(i, c) for c in range(min(3, comps))]
    if min(rgb) < 245:
        covered += 1
print("covered", f"{covered / n:.4f}")
