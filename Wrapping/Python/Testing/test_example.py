"""Examples/Python/FeaturePointsExample.py (the README's Python script) and
Examples/Python/FeatureCurvesPicture.py (the README's picture of the curves) run and render.

Run by CTest (FeaturePoints::PythonExample) under xvfb-run where there is no display, with
FEATUREPOINTS_EXAMPLE and FEATUREPOINTS_CURVES_EXAMPLE (the scripts), FEATUREPOINTS_DATA and
FEATUREPOINTS_README in the environment.
"""
import os
import subprocess
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader

from featurepoints import vtkPointCloudReader

EXAMPLE = os.environ["FEATUREPOINTS_EXAMPLE"]
CLOUD = os.path.join(os.environ["FEATUREPOINTS_DATA"], "default", "TwoPlane90.ply")


def test_readme_shows_the_example():
    # The README's script is this file, word for word (from its first import on).
    readme = open(os.environ["FEATUREPOINTS_README"]).read()
    script = open(EXAMPLE).read()
    body = script[script.index("import sys"):]
    shown = body.strip() in readme
    assert shown, "README.md does not show %s as it is" % EXAMPLE


def test_example_reads_detects_writes_and_renders(tmp_path):
    prefix = str(tmp_path / "features")
    done = subprocess.run([sys.executable, EXAMPLE, CLOUD, prefix], capture_output=True,
                          text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    assert "559 feature points of 6002;" in done.stdout
    assert "convex 88, concave 0, corner 58, border 413" in done.stdout
    reader = vtkPointCloudReader()
    reader.SetFileName(prefix + ".vtp")
    reader.Update()
    assert vtk_to_numpy(reader.GetOutput().GetPointData().GetArray("FeatureMask")).sum() == 559
    png = vtkPNGReader()
    png.SetFileName(prefix + ".png")
    png.Update()
    image = png.GetOutput()
    assert image.GetDimensions()[:2] == (800, 600)
    rgb = vtk_to_numpy(image.GetPointData().GetScalars())[:, :3].astype(int)
    red = np.count_nonzero((rgb[:, 0] > 150) & (rgb[:, 1] < 80) & (rgb[:, 2] < 80))
    blue = np.count_nonzero((rgb[:, 2] > 150) & (rgb[:, 0] < 80) & (rgb[:, 1] < 80))
    # Feature points in red, the others in blue, on white: both are drawn, and far more blue.
    assert red > 200 and blue > 3 * red, (red, blue)


def test_curves_picture_renders_the_curves(tmp_path):
    # Examples/Python/FeatureCurvesPicture.py (the README's picture of the curves) on a small box.
    picture = str(tmp_path / "curves.png")
    done = subprocess.run([sys.executable, os.environ["FEATUREPOINTS_CURVES_EXAMPLE"], picture,
                           "Box", "10000"], capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    assert done.stdout.startswith("12 curves, total length "), done.stdout
    png = vtkPNGReader()
    png.SetFileName(picture)
    png.Update()
    image = png.GetOutput()
    assert image.GetDimensions()[:2] == (720, 540)
    rgb = vtk_to_numpy(image.GetPointData().GetScalars())[:, :3].astype(int)
    # The curves in colour over a grey cloud on white: many pixels far from any grey.
    coloured = np.count_nonzero(rgb.max(axis=1) - rgb.min(axis=1) > 80)
    assert coloured > 2000, coloured
