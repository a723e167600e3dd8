"""The plugin's Distributed Feature Points filter in pvbatch (run by RunDistributedPlugin.py).

  pvbatch TestDistributedPlugin.py --probe OUTPUT.txt
      writes the number of data partitions (MPI processes) of this pvbatch run.
  [mpiexec -n N] pvbatch [--mpi] TestDistributedPlugin.py PLUGIN METHOD HOW OUTPUT.txt
      METHOD: crease (the project's default detector) or huang2023 (the paper's method, voxel
      pre-filter on); HOW: plain (the detector's own filter) or driver (Distributed Feature
      Points, whole result gathered on the first process). Runs it on the plate with a hole of
      the plugin's Feature Model Source (20,000 points; a source that does not split its output:
      the first process holds the cloud) and writes, in input order, each point's FeatureMask and
      score (repr of the float) to OUTPUT.txt, after a first line with the partition count.
The script runs on the first process only (pvbatch's other processes serve the pipeline).
"""
import sys

from paraview import servermanager
from paraview.simple import LoadPlugin


def partitions():
    return servermanager.ActiveConnection.GetNumberOfDataPartitions()


def probe(output):
    with open(output, "w") as f:
        f.write("%d\n" % partitions())


def run(plugin, method, how, output):
    LoadPlugin(plugin, remote=False, ns=globals())

    source = FeatureModelSource()  # noqa: F821 (defined by LoadPlugin)
    source.Model = "Plate with hole (open borders)"
    source.NumberOfPoints = 20000
    score = {"crease": "CreaseVotes", "huang2023": "F"}[method]
    if how == "plain":
        if method == "crease":
            detector = CreaseFeaturePoints(Input=source)  # noqa: F821
        else:
            detector = FeaturePoints(Input=source)  # noqa: F821
    else:
        detector = DistributedFeaturePoints(Input=source)  # noqa: F821
        choices = detector.GetProperty("Detector").Available
        wanted = "CreaseVotingFeatures" if method == "crease" else "FeaturePointExtraction"
        label = {"CreaseVotingFeatures": "Crease Feature Points",
                 "FeaturePointExtraction": "Feature Points (Huang et al. 2023)"}[wanted]
        detector.Detector = label if label in choices else wanted
        detector.GatherOutput = 1
    detector.UpdatePipeline()
    result = servermanager.Fetch(detector)
    mask = result.GetPointData().GetArray("FeatureMask")
    values = result.GetPointData().GetArray(score)
    if mask is None or values is None:
        print("no FeatureMask or %s in the result of %s (%s)" % (score, method, how))
        return 1
    with open(output, "w") as f:
        f.write("%d\n" % partitions())
        for i in range(result.GetNumberOfPoints()):
            f.write("%d %r\n" % (mask.GetValue(i), values.GetValue(i)))
    print("%s (%s): %d points, %d feature points, %d partitions"
          % (method, how, result.GetNumberOfPoints(),
             sum(mask.GetValue(i) for i in range(result.GetNumberOfPoints())), partitions()))
    return 0


# The script ends normally on success: a sys.exit() in pvbatch --mpi leaves the first process
# without MPI_Finalize, and mpiexec then ends the others as an improper exit.
if sys.argv[1] == "--probe":
    probe(sys.argv[2])
elif run(*sys.argv[1:5]) != 0:
    sys.exit(1)
