"""The FeaturePoints plugin in pvbatch, checked against the plain VTK build.

  pvbatch TestFeaturePointsPlugin.py PLUGIN REFERENCE BASELINE.png OUTPUT_FOLDER

Loads the plugin, checks the server-manager XML (menu category, documentation on every
property, input restricted to point sets), runs every detector on the synthetic cloud of
REFERENCE (written by the plain VTK build's test TestFeaturePointsReference) and compares the
arrays, the number of feature points and the feature point ids; opens a small .xyz file written
here through OpenDataFile (File > Open), which must pick the plugin's Point Cloud Reader, and
checks its points and columns; shows the main filter (it must come up as points coloured by
F), saves a screenshot and compares it with BASELINE.png.
Exits 1 on any failed check.
"""
import os
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
cloud_file = os.path.join(folder, "TestFeaturePointsPlugin.xyz")
rows = [(0.5 * i, 0.25 * j, 0.125 * i * j, 10 * i + j) for i in range(5) for j in range(4)]
with open(cloud_file, "w") as f:
    f.write("# a 5 x 4 grid: x y z and one more column\n")
    for row in rows:
        f.write("%g %g %g %g\n" % row)
for extension in ["pts", "txt", "csv", "pcd", "las"]:
    hint = proto.GetHints().FindNestedElementByName("ReaderFactory") if proto else None
    check(hint is not None and extension in hint.GetAttribute("extensions").split(),
          "PointCloudReader: .%s is not in its ReaderFactory extensions" % extension)
# OpenDataFile asks the reader factory, as File > Open does: it must choose the plugin's reader.
try:
    opened = OpenDataFile(cloud_file)
except RuntimeError as error:
    opened = None
    print("OpenDataFile: %s" % error)
check(opened is not None and opened.GetXMLName() == "PointCloudReader",
      "File > Open of a .xyz file (OpenDataFile) made %s, not a PointCloudReader"
      % (opened.GetXMLName() if opened is not None else "nothing"))
if opened is not None:
    cloud = servermanager.Fetch(opened)
    column = cloud.GetPointData().GetArray("Field 3")
    points = [cloud.GetPoint(i) for i in range(cloud.GetNumberOfPoints())]
    check(cloud.GetNumberOfPoints() == len(rows) and cloud.GetNumberOfVerts() == len(rows),
          "PointCloudReader: %d points and %d vertices, not %d"
          % (cloud.GetNumberOfPoints(), cloud.GetNumberOfVerts(), len(rows)))
    check(points == [r[:3] for r in rows], "PointCloudReader: the points differ from the file's")
    check(column is not None and [column.GetValue(i) for i in range(column.GetNumberOfTuples())]
          == [r[3] for r in rows], "PointCloudReader: column 4 is not the point array 'Field 3'")
    print("PointCloudReader: %s opened by File > Open, %d points, arrays %s"
          % (os.path.basename(cloud_file), cloud.GetNumberOfPoints(),
             [cloud.GetPointData().GetArrayName(i)
              for i in range(cloud.GetPointData().GetNumberOfArrays())]))
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
