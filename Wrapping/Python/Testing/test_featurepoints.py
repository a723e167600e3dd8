"""The Python package featurepoints against the C++ command-line tool, on the same files.

Run by CTest (FeaturePoints::PythonTests) as /usr/bin/python3 -m pytest with the build tree's
package on PYTHONPATH and, in the environment, FEATUREPOINTS_CLI (the featurepoints program;
the comparisons are skipped without it) and FEATUREPOINTS_DATA (Filters/Testing/Data/pcednet).
"""
import os
import re
import subprocess

import numpy as np
import pytest
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import (reference, vtkCommand, vtkDoubleArray, vtkIdList, vtkIntArray,
                                      vtkUnsignedCharArray)
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkCommonExecutionModel import vtkPolyDataAlgorithm
from vtkmodules.vtkIOCore import vtkWriter
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader

import featurepoints
from featurepoints import (vtkCreaseVotingFeatures, vtkFeatureCurveExtraction,
                           vtkFeaturePointEvaluation, vtkFeaturePointExtraction,
                           vtkPointCloudGridLocator, vtkPointCloudIO, vtkPointCloudNeighborhoods,
                           vtkPointCloudReader,
                           vtkPointCloudWriter, vtkVoxelDensityContrastFilter)

DATA = os.environ.get("FEATUREPOINTS_DATA", "")
CLI = os.environ.get("FEATUREPOINTS_CLI", "")
TWO_PLANES = os.path.join(DATA, "default", "TwoPlane90.ply")  # 6002 points, a 90-degree crease
FRACTAL = os.path.join(DATA, "default", "Frac2Guass3Noise.ply")  # 7212 points, noisy creases

needs_cli = pytest.mark.skipif(not os.path.isfile(CLI), reason="no featurepoints program")


def arrays(data):
    """The point arrays of a data set, as numpy arrays by name."""
    pd = data.GetPointData()
    return {pd.GetArrayName(i): vtk_to_numpy(pd.GetArray(i)) for i in range(pd.GetNumberOfArrays())
            if pd.GetArray(i) is not None}


def read(file_name):
    reader = vtkPointCloudReader()
    reader.SetFileName(file_name)
    reader.Update()
    assert reader.GetErrorCode() == 0, reader.GetErrorMessage()
    return reader


def run_cli(tmp_path, cloud, *options):
    """The C++ program's output .vtp for the same input, read back."""
    output = str(tmp_path / "cli.vtp")
    done = subprocess.run([CLI, cloud, output, "--quiet"] + list(options),
                          capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    xml = vtkXMLPolyDataReader()
    xml.SetFileName(output)
    xml.Update()
    return xml.GetOutput()


def test_package_imports_beside_vtkmodules():
    # The classes are VTK classes: subclasses of vtkmodules' own, usable in their pipelines.
    assert issubclass(vtkCreaseVotingFeatures, vtkPolyDataAlgorithm)
    assert issubclass(vtkFeaturePointExtraction, vtkPolyDataAlgorithm)
    assert issubclass(vtkPointCloudReader, vtkPolyDataAlgorithm)
    assert issubclass(vtkPointCloudWriter, vtkWriter)
    for name in ["vtkCreaseVotingFeatures", "vtkFeaturePointExtraction", "vtkFeatureCurveExtraction",
                 "vtkFeatureModelSource", "vtkPointCloudReader", "vtkPointCloudWriter",
                 "vtkPointCloudIO", "vtkPointCloudNeighborhoods", "vtkFeaturePointEvaluation"]:
        assert name in featurepoints.__all__


def test_every_wrapped_method_is_callable_from_python():
    # No signature that Python cannot pass: a smart pointer or a bare pointer in or out.
    unusable = []
    for name in featurepoints.__all__:
        cls = getattr(featurepoints, name)
        for method in dir(cls):
            doc = getattr(getattr(cls, method), "__doc__", None) or ""
            for signature in re.findall(r"^(\w+\(.*?\)(?:\s*->\s*\S+)?)\s*$", doc.split("\nC++")[0],
                                        re.M | re.S):
                if re.search(r"vtkSmartPointer|->\s*Pointer\b|:\s*Pointer\b", signature):
                    unusable.append("%s.%s: %s" % (name, method, " ".join(signature.split())))
    assert not unusable, "\n".join(unusable)
    # The C++-only helpers are not wrapped; their wrapped counterparts are.
    assert not hasattr(vtkPointCloudIO, "Read")
    assert hasattr(vtkPointCloudIO, "ReadPolyData")


def test_reader_gives_every_vertex_property():
    cloud = read(TWO_PLANES).GetOutput()
    assert cloud.GetNumberOfPoints() == 6002
    assert cloud.GetNumberOfVerts() == 6002
    columns = arrays(cloud)
    assert columns["Normals"].shape == (6002, 3)
    assert columns["RGBA"].shape == (6002, 4)
    # PCEDNet's labels: the crease points are coloured (168, 0, 0), 36 of them in this cloud;
    # LabelsFromColors' wrapped counterpart reads them the same way.
    rgba = columns["RGBA"]
    assert np.count_nonzero((rgba[:, 0] == 168) & (rgba[:, 1] == 0) & (rgba[:, 2] == 0)) == 36
    labels = vtkUnsignedCharArray()
    assert vtkFeaturePointEvaluation.LabelsFromColors(cloud.GetPointData().GetArray("RGBA"), labels)
    assert labels.GetName() == "SharpLabel" and vtk_to_numpy(labels).sum() == 36
    grey = vtkDoubleArray()  # one component: no colours
    grey.SetNumberOfValues(3)
    assert not vtkFeaturePointEvaluation.LabelsFromColors(grey, labels)


@needs_cli
def test_crease_matches_the_program(tmp_path):
    reader = vtkPointCloudReader()
    reader.SetFileName(TWO_PLANES)
    crease = vtkCreaseVotingFeatures()
    crease.SetInputConnection(reader.GetOutputPort())
    crease.Update()
    ours = arrays(crease.GetOutput())
    theirs = arrays(run_cli(tmp_path, TWO_PLANES))
    for name in ["FeatureMask", "FeatureType", "CreaseVotes", "CreaseGain", "CreaseAngle", "Normals"]:
        assert name in ours, name
        assert np.array_equal(ours[name], theirs[name]), name
    mask = ours["FeatureMask"]
    # The program reports 559 feature points (88 convex, 58 corner, 413 border) on this cloud.
    assert mask.sum() == crease.GetNumberOfFeaturePoints() == 559
    assert np.count_nonzero(ours["FeatureType"] == 1) == 88
    assert np.all((ours["CreaseVotes"] > 0.5)[ours["FeatureType"] == 1])
    assert crease.GetMeanSpacing() == pytest.approx(0.00915593, rel=1e-5)


@needs_cli
def test_huang2023_matches_the_program(tmp_path):
    reader = vtkPointCloudReader()
    reader.SetFileName(FRACTAL)
    detector = vtkFeaturePointExtraction()
    detector.SetInputConnection(reader.GetOutputPort())
    detector.Update()
    ours = arrays(detector.GetOutput())
    theirs = arrays(run_cli(tmp_path, FRACTAL, "--method", "huang2023"))
    assert set(ours) == set(theirs)
    for name in ours:
        assert np.array_equal(ours[name], theirs[name]), name
    # The program reports 50 feature points of 7212, F above 0.931796.
    assert ours["FeatureMask"].sum() == 50
    assert detector.GetThresholdUsed() == pytest.approx(0.931796, rel=1e-5)
    assert np.all(ours["F"][ours["FeatureMask"] == 1] > detector.GetThresholdUsed())


@needs_cli
def test_curves_match_the_program(tmp_path):
    reader = read(TWO_PLANES)  # kept: VTK 9.1's pipeline does not keep its producer alive
    crease = vtkCreaseVotingFeatures()
    crease.SetInputConnection(reader.GetOutputPort())
    crease.CreaseOffsetsOn()  # as --lines does: the crease vertices onto the moved points
    curves = vtkFeatureCurveExtraction()
    curves.SetInputConnection(crease.GetOutputPort())
    curves.Update()
    lines = str(tmp_path / "lines.vtp")
    theirs = run_cli(tmp_path, TWO_PLANES, "--lines", lines)
    assert np.array_equal(arrays(curves.GetOutput())["CurveId"], arrays(theirs)["CurveId"])
    xml = vtkXMLPolyDataReader()
    xml.SetFileName(lines)
    xml.Update()
    ours, program = curves.GetOutput(1), xml.GetOutput()
    # The program reports 7 curves (the crease and the 6 border edges), 6.06359 long in all.
    assert curves.GetNumberOfCurves() == ours.GetNumberOfLines() == program.GetNumberOfLines() == 7
    assert curves.GetTotalLength() == pytest.approx(6.06359, rel=1e-4)
    assert np.array_equal(vtk_to_numpy(ours.GetPoints().GetData()),
                          vtk_to_numpy(program.GetPoints().GetData()))
    for name in ["CurveId", "FeatureType", "Length"]:
        assert np.array_equal(vtk_to_numpy(ours.GetCellData().GetArray(name)),
                              vtk_to_numpy(program.GetCellData().GetArray(name))), name


def test_reader_errors_are_one_line(tmp_path):
    errors = []

    def keep(caller, event):
        errors.append(caller.GetErrorMessage())

    bad = tmp_path / "bad.xyz"
    bad.write_text("0 0 0\n1 1 1\n2 two 2\n")
    cases = [(str(tmp_path / "missing.xyz"), "No such file or directory"),
             (str(bad), "bad.xyz:3:"),
             (str(tmp_path / "cloud.unknown"), "cannot tell the format from the extension")]
    (tmp_path / "cloud.unknown").write_text("0 0 0\n")
    for file_name, expected in cases:
        reader = vtkPointCloudReader()
        reader.AddObserver(vtkCommand.ErrorEvent, keep)
        reader.SetFileName(file_name)
        reader.Update()
        message = reader.GetErrorMessage()
        assert reader.GetErrorCode() != 0
        assert message.startswith(file_name) and expected in message and "\n" not in message
        assert reader.GetOutput().GetNumberOfPoints() == 0
        assert errors[-1] == message  # reported once, as that line
    assert len(errors) == len(cases)
    reader = vtkPointCloudReader()
    assert reader.CanReadFile("a.XYZ") == 1 and reader.CanReadFile("a.png") == 0


def test_writer_round_trip_and_no_partial_file(tmp_path):
    reader = read(TWO_PLANES)
    crease = vtkCreaseVotingFeatures()
    crease.SetInputConnection(reader.GetOutputPort())
    crease.Update()
    expected = arrays(crease.GetOutput())
    for extension in ["ply", "vtp", "csv", "vtk"]:
        target = str(tmp_path / ("features." + extension))
        writer = vtkPointCloudWriter()
        writer.SetFileName(target)
        writer.SetInputConnection(crease.GetOutputPort())
        assert writer.Write() == 1, writer.GetErrorMessage()
        back = arrays(read(target).GetOutput())
        assert np.array_equal(back["FeatureMask"], expected["FeatureMask"]), extension
        # Every file gives back the float scores exactly (.csv: as doubles of the same value).
        votes = back["CreaseVotes"].astype(expected["CreaseVotes"].dtype)
        assert np.array_equal(votes, expected["CreaseVotes"]), extension
    # A folder that does not exist, a format that cannot be written: an error, no file.
    writer = vtkPointCloudWriter()
    writer.SetInputConnection(crease.GetOutputPort())
    writer.AddObserver(vtkCommand.ErrorEvent, lambda caller, event: None)
    for target in [str(tmp_path / "no" / "such" / "folder.vtp"), str(tmp_path / "features.xyz")]:
        writer.SetFileName(target)
        assert writer.Write() == 0
        assert writer.GetErrorMessage().startswith(target)
        assert not os.path.exists(target)
    # Format overrides the extension.
    writer.SetFileName(str(tmp_path / "features.data"))
    writer.SetFormat("ply")
    assert writer.Write() == 1
    assert open(str(tmp_path / "features.data"), "rb").read(3) == b"ply"


def test_io_functions_from_python(tmp_path):
    # The wrapped counterparts of the C++-only helpers, and the error out-parameters.
    error = reference("")
    cloud = vtkPolyData()
    assert vtkPointCloudIO.ReadPolyData(TWO_PLANES, cloud, error)
    assert cloud.GetNumberOfPoints() == 6002 and str(error) == ""
    assert not vtkPointCloudIO.ReadPolyData(str(tmp_path / "none.ply"), cloud, error)
    assert str(error).startswith(str(tmp_path / "none.ply")) and cloud.GetNumberOfPoints() == 0
    cells = vtkCellArray()
    assert vtkPointCloudIO.MakeVertexCells(5, cells) and cells.GetNumberOfCells() == 5
    assert vtkPointCloudIO.GetExtension("a/b.PLY") == "ply"
    assert vtkPointCloudIO.CanRead("xyz") and not vtkPointCloudIO.CanWrite("xyz")
    target = str(tmp_path / "cloud.csv")
    vtkPointCloudIO.ReadPolyData(TWO_PLANES, cloud, error)
    assert vtkPointCloudIO.Write(cloud, target, error)
    assert os.path.getsize(target) > 6002 * 10


def test_grid_locator_from_python():
    # A VTK point locator: the queries of vtkAbstractPointLocator, the batched table and the
    # detectors' SetLocator().
    from vtkmodules.vtkCommonDataModel import vtkAbstractPointLocator, vtkStaticPointLocator
    cloud = read(FRACTAL).GetOutput()
    points = vtk_to_numpy(cloud.GetPoints().GetData()).astype(float)
    locator = vtkPointCloudGridLocator()
    assert isinstance(locator, vtkAbstractPointLocator)
    locator.SetDataSet(cloud)
    locator.BuildLocator()
    assert locator.GetNumberOfGridPoints() == 7212
    x = points[100] + 0.001
    distances = np.linalg.norm(points - x, axis=1)
    found = vtkIdList()
    locator.FindClosestNPoints(10, x, found)
    assert [found.GetId(j) for j in range(10)] == list(np.argsort(distances, kind="stable")[:10])
    assert locator.FindClosestPoint(x) == int(np.argmin(distances))
    radius = float(np.sort(distances)[20])
    locator.FindPointsWithinRadius(radius, x, found)
    assert sorted(found.GetId(j) for j in range(found.GetNumberOfIds())) == \
        sorted(np.nonzero(distances <= radius)[0])
    ids = vtkIdList()
    for i in range(0, 7212, 997):
        ids.InsertNextId(i)
    table = vtkIntArray()
    assert locator.FindNearestNeighbors(6, ids, table)
    rows = vtk_to_numpy(table)
    for r in range(ids.GetNumberOfIds()):
        d = np.linalg.norm(points - points[ids.GetId(r)], axis=1)
        d[ids.GetId(r)] = np.inf
        assert np.allclose(np.sort(d)[:6], d[rows[r]], rtol=1e-12, atol=0)
    # A detector with another locator finds the same feature points.
    masks = []
    for other in (None, vtkStaticPointLocator()):
        detector = vtkCreaseVotingFeatures()
        if other is not None:
            detector.SetLocator(other)
        assert detector.GetLocator() is not None
        detector.SetInputData(cloud)
        detector.Update()
        masks.append(vtk_to_numpy(detector.GetOutput().GetPointData().GetArray("FeatureMask")))
    assert masks[0].sum() > 100 and np.array_equal(masks[0], masks[1])


def test_neighborhoods_and_voxel_screen_from_python():
    # The wrapped counterparts of the C++-only table methods, against numpy and the filter.
    cloud = read(FRACTAL).GetOutput()
    points = vtk_to_numpy(cloud.GetPoints().GetData()).astype(float)
    neighborhoods = vtkPointCloudNeighborhoods()
    assert neighborhoods.Build(cloud.GetPoints())
    assert len(neighborhoods.GetCenter()) == 3 and len(neighborhoods.GetBounds()) == 6
    assert neighborhoods.GetBounds()[0] == pytest.approx(points[:, 0].min())
    valid = vtkUnsignedCharArray()
    neighborhoods.GetValidMask(valid)
    assert vtk_to_numpy(valid).sum() == 7212
    ids = vtkIdList()
    for i in range(0, 7212, 701):
        ids.InsertNextId(i)
    table, nearest = vtkIntArray(), vtkDoubleArray()
    assert neighborhoods.FindNearestNeighbors(8, ids, table, nearest)
    rows = vtk_to_numpy(table)
    assert rows.shape == (ids.GetNumberOfIds(), 8)
    for r in range(ids.GetNumberOfIds()):
        i = ids.GetId(r)
        distances = np.linalg.norm(points - points[i], axis=1)
        distances[i] = np.inf
        # Nearest first, the same distances as a brute-force search.
        assert np.allclose(np.sort(distances)[:8], distances[rows[r]], rtol=1e-12, atol=0)
        assert nearest.GetValue(r) == pytest.approx(distances.min(), rel=1e-12)
    spacing = neighborhoods.ComputeMeanSpacing()
    assert spacing == pytest.approx(0.00944515, rel=1e-5)  # the program's mean spacing
    cells = vtkCellArray()
    assert vtkPointCloudNeighborhoods.MakeVertexCells(7212, cells) and cells.GetNumberOfCells() == 7212
    # The mean spacing from a full table is the same as the one searched for.
    every = vtkIdList()
    for i in range(7212):
        every.InsertNextId(i)
    fresh = vtkPointCloudNeighborhoods()
    assert fresh.Build(cloud.GetPoints()) and fresh.FindNearestNeighbors(2, every, table)
    assert fresh.ComputeMeanSpacing(every, table) == spacing
    # A spatial order is a permutation of the points.
    order = vtkIntArray()
    reordered = vtkPointCloudNeighborhoods()
    assert reordered.Build(cloud.GetPoints()) and reordered.ReorderSpatially(order)
    assert np.array_equal(np.sort(vtk_to_numpy(order)), np.arange(7212))
    assert not np.array_equal(vtk_to_numpy(order), np.arange(7212))

    screen = vtkVoxelDensityContrastFilter()
    screen.SetInputData(cloud)
    screen.Update()
    expected = vtk_to_numpy(screen.GetOutput().GetPointData().GetArray("Candidate"))
    distances = vtkDoubleArray()
    for d in neighborhoods.GetNearestDistances():
        distances.InsertNextValue(d)
    candidate, counts = vtkUnsignedCharArray(), vtkIntArray()
    marked = vtkVoxelDensityContrastFilter().MarkCandidates(cloud.GetPoints(), valid, spacing,
                                                            distances, candidate, counts)
    assert marked == expected.sum() == np.count_nonzero(vtk_to_numpy(candidate))
    assert np.array_equal(vtk_to_numpy(candidate), expected)
    assert vtk_to_numpy(counts).min() >= 1
    short = vtkDoubleArray()
    short.SetNumberOfValues(3)
    checker = vtkVoxelDensityContrastFilter()
    checker.AddObserver(vtkCommand.ErrorEvent, lambda caller, event: None)
    assert checker.MarkCandidates(cloud.GetPoints(), valid, spacing, short, candidate) == -1


def test_smooth_models_torus_and_ellipsoid():
    # The two smooth shapes without features: their enum values, names, and clean points on the
    # exact surfaces (Size 100: torus radii 35 and 10, ellipsoid semi-axes 50, 30, 15).
    Source = featurepoints.vtkFeatureModelSource
    assert (Source.TORUS, Source.ELLIPSOID) == (12, 13)
    assert Source.GetModelName(Source.TORUS) == "Torus"
    assert Source.GetModelName(Source.ELLIPSOID) == "Ellipsoid"
    assert Source.GetDefaultNumberOfPoints(Source.TORUS) == 100000
    source = Source()
    source.SetNumberOfPoints(3000)
    source.SetNoiseFactor(0.0)
    source.SetModelToTorus()
    source.Update()
    p = vtk_to_numpy(source.GetOutput().GetPoints().GetData())
    assert np.abs(np.hypot(np.hypot(p[:, 0], p[:, 1]) - 35.0, p[:, 2]) - 10.0).max() < 1e-9
    assert vtk_to_numpy(source.GetOutput().GetPointData().GetArray("GroundTruth")).sum() == 0
    source.SetModelToEllipsoid()
    source.Update()
    p = vtk_to_numpy(source.GetOutput().GetPoints().GetData())
    level = (p[:, 0] / 50.0) ** 2 + (p[:, 1] / 30.0) ** 2 + (p[:, 2] / 15.0) ** 2
    assert np.abs(level - 1.0).max() < 1e-9 and p.shape == (3000, 3)
    assert source.GetFeatureCurves().GetNumberOfLines() == 0
