"""The FeaturePoints plugin in pvbatch, checked against the plain VTK build.

  pvbatch TestFeaturePointsPlugin.py PLUGIN REFERENCE BASELINE.png OUTPUT_FOLDER

Loads the plugin, checks the server-manager XML (menu category, documentation on every
property, input restricted to point sets), runs every detector on the synthetic cloud of
REFERENCE (written by the plain VTK build's test TestFeaturePointsReference) and compares the
arrays, the number of feature points and the feature point ids; writes a small grid as .xyz,
.pcd and .las, checks that File > Open offers the plugin's Point Cloud Reader for each (and picks
it for the .pcd) and that it reads their points and columns; shows the main filter (it must come up as points coloured by
F), saves a screenshot and compares it with BASELINE.png.
Exits 1 on any failed check.
"""
import os
import struct
import sys

from paraview import servermanager
from paraview.simple import (CreateRenderView, LoadPlugin, OpenDataFile, Render, ResetCamera,
                             SaveScreenshot, Wavelet, Show)

plugin, reference_file, baseline, folder = sys.argv[1:5]
failures = []


def check(ok, what):
    if not ok:
        failures.append(what)
        print("FAILED: " + what)


# The plugin's proxies (FeatureModelSource, FeaturePoints, ...) become functions of this module.
LoadPlugin(plugin, remote=False, ns=globals())

# The XML: every filter under "Point Cloud", every property documented, point sets only.
pxm = servermanager.ProxyManager()
proxies = {"CreaseVotingFeatures": "CreaseFeaturePoints",
           "FeaturePointExtraction": "FeaturePoints",
           "SmoothShrinkIndexFeatures": "SSIFeaturePoints",
           "SurfaceVariationFeatures": "PCAFeaturePoints",
           "CurvatureDensityFeatures": "WangYuanFeaturePoints"}
wavelet = Wavelet()
for group, name in [("filters", n) for n in proxies] + [("sources", "FeatureModelSource")]:
    proto = pxm.GetPrototypeProxy(group, name)
    check(proto is not None, "%s: no proxy" % name)
    if proto is None:
        continue
    menu = proto.GetHints().FindNestedElementByName("ShowInMenu") if proto.GetHints() else None
    check(menu is not None and menu.GetAttribute("category") == "Point Cloud",
          "%s: not in the Point Cloud menu" % name)
    it = proto.NewPropertyIterator()
    it.Begin()
    count = 0
    while not it.IsAtEnd():
        doc = it.GetProperty().GetDocumentation()
        check(doc is not None and len(doc.GetDescription().strip()) > 10,
              "%s.%s: no documentation" % (name, it.GetKey()))
        count += 1
        it.Next()
    print("%s: %d properties, all documented" % (name, count))
    if group == "filters":
        domain = proto.GetProperty("Input").GetDomain("input_type")
        check(domain.IsInDomain(wavelet.SMProxy, 0) == 0, "%s accepts an image" % name)

# The reader: File > Open of a .xyz file picks the plugin's Point Cloud Reader (the reader
# factory's choice by extension, as in the GUI), which reads every point and every column.
proto = pxm.GetPrototypeProxy("sources", "PointCloudReader")
check(proto is not None, "PointCloudReader: no proxy")
factory = servermanager.vtkSMProxyManager.GetProxyManager().GetReaderFactory()
factory.UpdateAvailableReaders()
rows = [(0.5 * i, 0.25 * j, 0.125 * i * j, 10 * i + j) for i in range(5) for j in range(4)]


# The same grid in three formats, written here: XYZ text, PCL's PCD (ascii) and LAS 1.2 (point
# format 0, coordinates near 10^6 stored as integers with a scale of 0.001 and an offset).
def write_pcd(path, rows):
    with open(path, "w") as f:
        f.write("# .PCD v0.7\nVERSION 0.7\nFIELDS x y z intensity\nSIZE 4 4 4 4\nTYPE F F F F\n"
                "COUNT 1 1 1 1\nWIDTH %d\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS %d\nDATA ascii\n"
                % (len(rows), len(rows)))
        for row in rows:
            f.write("%g %g %g %g\n" % row)
def write_las(path, rows, offset=(500000.0, 4000000.0, 100.0), scale=0.001):
    records = b"".join(struct.pack("<iiiHBBbBH", *[int(round((row[c] - offset[c]) / scale)) for c in range(3)],
                                   int(row[3]), 0x09, 2, 0, 0, 0) for row in rows)
    lo = [min(r[c] for r in rows) for c in range(3)]
    hi = [max(r[c] for r in rows) for c in range(3)]
    header = struct.pack("<4sHHIHH8sBB32s32sHHHIIBHI5I3d3d6d", b"LASF", 0, 0, 0, 0, 0, b"\0" * 8, 1, 2,
                         b"FeaturePoints test", b"FeaturePoints test", 1, 2026, 227, 227, 0, 0, 20,
                         len(rows), len(rows), 0, 0, 0, 0, scale, scale, scale, *offset,
                         hi[0], lo[0], hi[1], lo[1], hi[2], lo[2])
    assert len(header) == 227
    with open(path, "wb") as f:
        f.write(header + records)


offset = (500000.0, 4000000.0, 100.0)
cases = []
cloud_file = os.path.join(folder, "TestFeaturePointsPlugin.xyz")
with open(cloud_file, "w") as f:
    f.write("# a 5 x 4 grid: x y z and one more column\n")
    for row in rows:
        f.write("%g %g %g %g\n" % row)
cases.append((cloud_file, rows, "Field 3"))
write_pcd(os.path.join(folder, "TestFeaturePointsPlugin.pcd"), rows)
cases.append((os.path.join(folder, "TestFeaturePointsPlugin.pcd"), rows, "intensity"))
las_rows = [(r[0] + offset[0], r[1] + offset[1], r[2] + offset[2], r[3]) for r in rows]
write_las(os.path.join(folder, "TestFeaturePointsPlugin.las"), las_rows, offset)
cases.append((os.path.join(folder, "TestFeaturePointsPlugin.las"), las_rows, "Intensity"))
for extension in ["pts", "txt", "csv", "pcd", "las"]:
    hint = proto.GetHints().FindNestedElementByName("ReaderFactory") if proto else None
    check(hint is not None and extension in hint.GetAttribute("extensions").split(),
          "PointCloudReader: .%s is not in its ReaderFactory extensions" % extension)
session = servermanager.ActiveConnection.Session
for path, expected, column_name in cases:
    # File > Open offers the plugin's reader for the file (ParaView lets the user choose when
    # several readers claim an extension, as its molecule reader does .xyz).
    try:  # the readers that claim the file's extension
        offered = factory.GetReaders(path, session)
    except (AttributeError, TypeError):
        offered = factory.GetPossibleReaders(path, session)
    names = [offered.GetString(i) for i in range(offered.GetNumberOfStrings())] if offered else []
    check("PointCloudReader" in names,
          "File > Open does not offer the Point Cloud Reader for %s (offers %s)"
          % (os.path.basename(path), names))
    reader = globals()["PointCloudReader"](FileName=path)
    cloud = servermanager.Fetch(reader)
    column = cloud.GetPointData().GetArray(column_name)
    points = [cloud.GetPoint(i) for i in range(cloud.GetNumberOfPoints())]
    check(cloud.GetNumberOfPoints() == len(expected) and cloud.GetNumberOfVerts() == len(expected),
          "PointCloudReader: %s: %d points and %d vertices, not %d"
          % (os.path.basename(path), cloud.GetNumberOfPoints(), cloud.GetNumberOfVerts(),
             len(expected)))
    check(len(points) == len(expected) and
          all(abs(p[c] - q[c]) < 1e-6 for p, q in zip(points, expected) for c in range(3)),
          "PointCloudReader: %s: the points differ from the file's" % os.path.basename(path))
    check(column is not None and [column.GetValue(i) for i in range(column.GetNumberOfTuples())]
          == [r[3] for r in expected],
          "PointCloudReader: %s: no point array '%s' with the file's values"
          % (os.path.basename(path), column_name))
    print("PointCloudReader: %s, %d points, arrays %s"
          % (os.path.basename(path), cloud.GetNumberOfPoints(),
             [cloud.GetPointData().GetArrayName(i)
              for i in range(cloud.GetPointData().GetNumberOfArrays())]))
# OpenDataFile asks the reader factory as File > Open does; no other reader claims .pcd.
try:
    opened = OpenDataFile(cases[1][0])
except RuntimeError as error:
    opened = None
    print("OpenDataFile: %s" % error)
check(opened is not None and opened.GetXMLName() == "PointCloudReader",
      "File > Open of a .pcd file (OpenDataFile) made %s, not a PointCloudReader"
      % (opened.GetXMLName() if opened is not None else "nothing"))
missing = globals()["PointCloudReader"](FileName=os.path.join(folder, "missing.xyz"))
missing.UpdatePipeline()
check(servermanager.Fetch(missing).GetNumberOfPoints() == 0,
      "PointCloudReader: a missing file gives points")

# Results: the same as the plain VTK build's, for the same generated cloud.
reference = {}
settings = {}
with open(reference_file) as f:
    for line in f:
        if line.startswith("#") or not line.strip():
            continue
        fields = line.split()
        if fields[0] == "cloud":
            settings = dict(item.split("=") for item in fields[1:])
            continue
        reference[fields[0]] = (int(fields[1]), fields[2].split(","), [int(i) for i in fields[3:]])
source = globals()["FeatureModelSource"](Model=int(settings["model"]), NumberOfPoints=int(settings["points"]),
                            Seed=int(settings["seed"]))
for proxy_name, simple_name in proxies.items():
    expected_count, expected_arrays, expected_ids = reference[proxy_name]
    detector = globals()[simple_name](Input=source)
    data = servermanager.Fetch(detector)
    pd = data.GetPointData()
    arrays = sorted(pd.GetArrayName(i) for i in range(pd.GetNumberOfArrays()))
    mask = pd.GetArray("FeatureMask")
    ids = [i for i in range(data.GetNumberOfPoints()) if mask and mask.GetValue(i)]
    check(arrays == sorted(expected_arrays), "%s: arrays %s, plain VTK build %s"
          % (simple_name, arrays, sorted(expected_arrays)))
    check(len(ids) == expected_count, "%s: %d feature points, plain VTK build %d"
          % (simple_name, len(ids), expected_count))
    check(ids == expected_ids, "%s: %d feature point ids differ from the plain VTK build's"
          % (simple_name, len(set(ids) ^ set(expected_ids))))
    detector.UpdatePropertyInformation()
    check(detector.GetProperty("NumberOfFeaturePoints")[0] == expected_count,
          "%s: NumberOfFeaturePoints information property" % simple_name)
    print("%s: %d feature points of %d, arrays %s: same as the plain VTK build"
          % (simple_name, len(ids), data.GetNumberOfPoints(), ",".join(arrays)))

# Shown: points, coloured by F; then the picture against the baseline.
view = CreateRenderView()
view.OrientationAxesVisibility = 0
detector = globals()["FeaturePoints"](Input=source)
display = Show(detector, view)
check(display.Representation == "Points", "shown as %s, not Points" % display.Representation)
check(list(display.ColorArrayName) == ["POINTS", "F"],
      "coloured by %s, not F" % list(display.ColorArrayName))
view.CameraPosition = [60.0, -160.0, 140.0]
view.CameraFocalPoint = [0.0, 0.0, 0.0]
view.CameraViewUp = [0.0, 0.0, 1.0]
ResetCamera(view)
Render(view)
picture = os.path.join(folder, "TestFeaturePointsPlugin.png")
SaveScreenshot(picture, view, ImageResolution=[640, 480])
if not os.path.exists(baseline):
    check(False, "no baseline %s; the picture is %s" % (baseline, picture))
else:
    from vtkmodules.vtkImagingCore import vtkImageDifference
    from vtkmodules.vtkIOImage import vtkPNGReader
    test, valid = vtkPNGReader(), vtkPNGReader()
    test.SetFileName(picture)
    valid.SetFileName(baseline)
    difference = vtkImageDifference()
    difference.SetInputConnection(test.GetOutputPort())
    difference.SetImageConnection(valid.GetOutputPort())
    difference.Update()
    error = difference.GetThresholdedError()
    print("screenshot: thresholded error %.3f against %s" % (error, baseline))
    check(error <= 10.0, "screenshot differs from the baseline (%.3f > 10); see %s"
          % (error, picture))

print("%d failure(s)" % len(failures))
# Leave without ParaView's teardown: with Xvfb and Mesa it ends in a GLXBadContext X error after
# every check is done, and the X error handler turns the exit status into 1.
sys.stdout.flush()
os._exit(1 if failures else 0)
