"""Feature curves on a generated part, rendered offscreen: the picture of README.md's curves section.

Usage (Debian's /usr/bin/python3, PYTHONPATH holding the build's Python package, xvfb-run -a
without a display):

    /usr/bin/python3 Examples/Python/FeatureCurvesPicture.py OUT.png [MODEL [POINTS]]

MODEL is a vtkFeatureModelSource model name without spaces (default Bracket), POINTS its number
of points (default 36000); the noise is half the mean spacing. The cloud is drawn in grey, each
curve as a tube in its own colour.
"""
import sys

from featurepoints import (vtkCreaseVotingFeatures, vtkFeatureCurveExtraction,
                           vtkFeatureModelSource)
from vtkmodules.vtkCommonColor import vtkNamedColors
from vtkmodules.vtkCommonCore import vtkLookupTable
from vtkmodules.vtkFiltersCore import vtkMaskPoints, vtkTubeFilter
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import (vtkActor, vtkPolyDataMapper, vtkRenderWindow,
                                         vtkRenderer, vtkWindowToImageFilter)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the render window's implementation)

if len(sys.argv) < 2:
    sys.exit(__doc__)
model = sys.argv[2] if len(sys.argv) > 2 else "Bracket"
points = int(sys.argv[3]) if len(sys.argv) > 3 else 36000

source = vtkFeatureModelSource()
getattr(source, "SetModelTo" + model)()
source.SetNumberOfPoints(points)
source.SetNoiseFactor(0.5)
detector = vtkCreaseVotingFeatures()
detector.SetInputConnection(source.GetOutputPort())
detector.CreaseOffsetsOn()  # the crease vertices onto the moved crease points, as --lines does
curves = vtkFeatureCurveExtraction()
curves.SetInputConnection(detector.GetOutputPort())
curves.Update()
lines = curves.GetCurves()
print(f"{curves.GetNumberOfCurves()} curves, total length {curves.GetTotalLength():.1f}")

renderer = vtkRenderer()
renderer.SetBackground(1.0, 1.0, 1.0)
shown = vtkMaskPoints()  # every third point: the curves stay in view
shown.SetInputConnection(curves.GetOutputPort(0))
shown.SetOnRatio(3)
shown.GenerateVerticesOn()
shown.SingleVertexPerCellOn()
cloud = vtkPolyDataMapper()
cloud.SetInputConnection(shown.GetOutputPort())
cloud.ScalarVisibilityOff()
cloudActor = vtkActor()
cloudActor.SetMapper(cloud)
cloudActor.GetProperty().SetColor(0.72, 0.72, 0.72)
cloudActor.GetProperty().SetPointSize(1.5)
renderer.AddActor(cloudActor)

tubes = vtkTubeFilter()
tubes.SetInputData(lines)
tubes.SetRadius(0.6 * curves.GetMeanSpacing())
tubes.SetNumberOfSides(8)
names = ["crimson", "royal_blue", "forest_green", "dark_orange", "blue_violet", "steel_blue",
         "gold", "deep_pink", "sienna", "teal", "olive_drab", "navy"]
count = max(1, lines.GetNumberOfCells())
colours = vtkLookupTable()  # one colour per CurveId, the palette over again
colours.SetNumberOfTableValues(count)
colours.Build()
for k in range(count):
    colours.SetTableValue(k, *vtkNamedColors().GetColor3d(names[k % len(names)]), 1.0)
tubeMapper = vtkPolyDataMapper()
tubeMapper.SetInputConnection(tubes.GetOutputPort())
tubeMapper.SetScalarModeToUseCellFieldData()
tubeMapper.SelectColorArray("CurveId")
tubeMapper.SetLookupTable(colours)
tubeMapper.SetScalarRange(0, count - 1)
tubeActor = vtkActor()
tubeActor.SetMapper(tubeMapper)
renderer.AddActor(tubeActor)

window = vtkRenderWindow()
window.SetOffScreenRendering(1)
window.SetSize(720, 540)
window.AddRenderer(renderer)
renderer.ResetCamera()
renderer.GetActiveCamera().Azimuth(30.0)
renderer.GetActiveCamera().Elevation(25.0)
renderer.ResetCamera()
renderer.GetActiveCamera().Zoom(1.3)
window.Render()
image = vtkWindowToImageFilter()
image.SetInput(window)
writer = vtkPNGWriter()
writer.SetFileName(sys.argv[1])
writer.SetInputConnection(image.GetOutputPort())
writer.Write()
