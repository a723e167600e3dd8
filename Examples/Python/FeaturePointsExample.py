"""Feature points of a point cloud from Python: read, detect, numpy, write, render to a PNG.

    PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 \
        Examples/Python/FeaturePointsExample.py CLOUD PREFIX

Writes PREFIX.vtp (the cloud with its scores and FeatureMask) and PREFIX.png (the points, feature
points in red, the others in blue). Debian's VTK renders through X: run it under xvfb-run -a
where there is no display. README.md shows this script from its first import on.
"""
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import (vtkActor, vtkPolyDataMapper, vtkRenderWindow,
                                         vtkRenderer, vtkWindowToImageFilter)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the OpenGL render window)
from featurepoints import vtkCreaseVotingFeatures, vtkPointCloudReader, vtkPointCloudWriter

reader = vtkPointCloudReader()  # the format from the extension
reader.SetFileName(sys.argv[1])
features = vtkCreaseVotingFeatures()  # the default detector, default parameters
features.SetInputConnection(reader.GetOutputPort())
features.Update()
if reader.GetErrorCode():
    sys.exit(reader.GetErrorMessage())

arrays = features.GetOutput().GetPointData()
mask = vtk_to_numpy(arrays.GetArray("FeatureMask"))
votes = vtk_to_numpy(arrays.GetArray("CreaseVotes"))
types = vtk_to_numpy(arrays.GetArray("FeatureType"))
print("%d feature points of %d; mean vote %.3f, %.3f on convex creases"
      % (mask.sum(), mask.size, votes.mean(), votes[types == 1].mean()))
print("convex %d, concave %d, corner %d, border %d"
      % tuple(np.count_nonzero(types == t) for t in (1, 2, 3, 4)))

writer = vtkPointCloudWriter()  # every array; never a partial file
writer.SetFileName(sys.argv[2] + ".vtp")
writer.SetInputConnection(features.GetOutputPort())
if not writer.Write():
    sys.exit(writer.GetErrorMessage())

mapper = vtkPolyDataMapper()  # feature points red, the others blue
mapper.SetInputConnection(features.GetOutputPort())
mapper.SetScalarModeToUsePointFieldData()
mapper.SelectColorArray("FeatureMask")
mapper.SetColorModeToMapScalars()  # uint8 values are colours by default
mapper.SetScalarRange(0, 1)
mapper.CreateDefaultLookupTable()
mapper.GetLookupTable().SetHueRange(0.667, 0.0)
actor = vtkActor()
actor.SetMapper(mapper)
actor.GetProperty().SetPointSize(3)
actor.GetProperty().LightingOff()  # flat colours: the normals would shade the points
renderer = vtkRenderer()
renderer.AddActor(actor)
renderer.SetBackground(1, 1, 1)
renderer.GetActiveCamera().Elevation(30)
renderer.GetActiveCamera().Azimuth(30)
renderer.ResetCamera()
window = vtkRenderWindow()
window.SetOffScreenRendering(1)
window.SetSize(800, 600)
window.AddRenderer(renderer)
window.Render()
image = vtkWindowToImageFilter()
image.SetInput(window)
png = vtkPNGWriter()
png.SetFileName(sys.argv[2] + ".png")
png.SetInputConnection(image.GetOutputPort())
png.Write()
