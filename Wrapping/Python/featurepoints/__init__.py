"""FeaturePoints: feature points of noisy point clouds, as VTK pipeline algorithms.

The classes of the C++ modules FeaturePoints::Filters and FeaturePoints::IO, wrapped by VTK's
Python wrapper; they work with vtkmodules' own classes (vtkPolyData, vtkPolyDataMapper, ...)::

    from featurepoints import vtkPointCloudReader, vtkCreaseVotingFeatures

    reader = vtkPointCloudReader()
    reader.SetFileName("cloud.xyz")
    features = vtkCreaseVotingFeatures()
    features.SetInputConnection(reader.GetOutputPort())
    features.Update()

Readers and writers: vtkPointCloudReader and vtkPointCloudWriter pick the format by the file's
extension (vtkPointCloudIO); errors are VTK errors (vtkErrorMacro) and GetErrorMessage().
Keep a Python reference to every algorithm of a pipeline: in VTK 9.1 a consumer does not keep its
producer alive, so `f.SetInputConnection(vtkPointCloudReader().GetOutputPort())` crashes later.
"""

# The VTK modules these classes derive from and take as arguments: imported first, so that the
# wrapped base classes (vtkPolyDataAlgorithm, vtkWriter, ...) are registered before ours.
from vtkmodules import vtkCommonCore as _vtkCommonCore  # noqa: F401
from vtkmodules import vtkCommonDataModel as _vtkCommonDataModel  # noqa: F401
from vtkmodules import vtkCommonExecutionModel as _vtkCommonExecutionModel  # noqa: F401
from vtkmodules import vtkIOCore as _vtkIOCore  # noqa: F401

from .FeaturePointsFilters import *  # noqa: F401,F403
from .FeaturePointsIO import *  # noqa: F401,F403

__all__ = [name for name in dir() if name.startswith("vtk")]
