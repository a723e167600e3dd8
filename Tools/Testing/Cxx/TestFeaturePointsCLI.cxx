// The featurepoints command, run as a user runs it (a child process), checked against the
// library called from C++:
//
//   TestFeaturePointsCLI PROGRAM FOLDER               results, formats, every bad input
//   TestFeaturePointsCLI PROGRAM FOLDER BASELINE.png  --screenshot against a baseline picture
//                                                     (needs a display: run under xvfb-run)
//
// Every bad input must give its exit code (1 bad input or failure, 2 bad usage), a one-line
// message naming the file and the problem, and leave no output file (nor a temporary one).
#include "FeaturePointsTestFiles.h"
#include "LASTestFile.h"

#include "vtkCreaseVotingFeatures.h"
#include "vtkFeatureModelSource.h"
#include "vtkFeaturePointExtraction.h"
#include "vtkIdTypeArray.h"
#include "vtkImageData.h"
#include "vtkImageDifference.h"
#include "vtkNew.h"
#include "vtkPNGReader.h"
#include "vtkPointCloudIO.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSurfaceVariationFeatures.h"
#include "vtkUnsignedCharArray.h"

#include <dirent.h>
#include <fcntl.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

extern char** environ;

namespace
{
using namespace fptest;
std::string Program, Folder;

struct Run
{
  int Code = -1;
  std::string Out, Err;
};

// Runs the program with these arguments; stdout and stderr are captured (not a terminal, so
// progress comes as plain lines).
Run Execute(const std::vector<std::string>& arguments)
{
  std::vector<std::string> all = { Program };
  all.insert(all.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (std::string& a : all)
  {
    argv.push_back(&a[0]);
  }
  argv.push_back(nullptr);
  const std::string out = Folder + "/stdout.txt", err = Folder + "/stderr.txt";
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, 2, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  Run run;
  pid_t pid = 0;
  if (posix_spawn(&pid, Program.c_str(), &actions, nullptr, argv.data(), environ) == 0)
  {
    int status = 0;
    ::waitpid(pid, &status, 0);
    run.Code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  }
  posix_spawn_file_actions_destroy(&actions);
  run.Out = Slurp(out);
  run.Err = Slurp(err);
  ::unlink(out.c_str());
  ::unlink(err.c_str());
  return run;
}

std::string Path(const std::string& name)
{
  return Folder + "/" + name;
}

// A bad run: its code, its message (one "featurepoints: ..." line holding `expected`), no output.
void ExpectFailure(const std::string& what, const std::vector<std::string>& arguments, int code,
  const std::string& expected, const std::string& output)
{
  const std::set<std::string> before = Entries(Folder);
  const Run run = Execute(arguments);
  Check(run.Code == code,
    what + ": exit code " + std::to_string(run.Code) + ", expected " + std::to_string(code));
  Check(run.Err.find("featurepoints: " ) != std::string::npos && run.Err.find(expected) != std::string::npos,
    what + ": stderr lacks '" + expected + "': " + run.Err);
  // The message is the last "featurepoints:" line before the usage hint, and it is one line.
  Check(run.Err.find("ERROR: In") == std::string::npos && run.Err.find("vtkExecutive") == std::string::npos,
    what + ": VTK's raw error text leaked: " + run.Err);
  Check(output.empty() || !Exists(output), what + ": output file left behind: " + output);
  std::set<std::string> after = Entries(Folder);
  Check(after == before, what + ": files created by a failed run");
}

vtkSmartPointer<vtkPolyData> ModelCloud(int model, vtkIdType n)
{
  vtkNew<vtkFeatureModelSource> source;
  source->SetModel(model);
  source->SetNumberOfPoints(n);
  source->Update();
  auto cloud = vtkSmartPointer<vtkPolyData>::New();
  cloud->SetPoints(source->GetOutput()->GetPoints());
  return cloud;
}

vtkUnsignedCharArray* MaskOf(vtkPointSet* data)
{
  return data ? vtkUnsignedCharArray::SafeDownCast(data->GetPointData()->GetArray("FeatureMask"))
              : nullptr;
}

// The FeatureType counts of a file written by the CLI: index 0 none, 1 convex, 2 concave, 3 corner,
// 4 border (vtkCreaseVotingFeatures::FeatureTypes); all -1 when the file has no such array.
std::vector<long> TypeCounts(const std::string& file)
{
  std::string error;
  vtkSmartPointer<vtkPointSet> data = vtkPointCloudIO::Read(file, error);
  auto* types = data
    ? vtkUnsignedCharArray::SafeDownCast(data->GetPointData()->GetArray("FeatureType"))
    : nullptr;
  std::vector<long> counts(5, types ? 0 : -1);
  for (vtkIdType i = 0; types && i < types->GetNumberOfTuples(); ++i)
  {
    const unsigned char t = types->GetValue(i);
    if (t < 5)
    {
      ++counts[t];
    }
  }
  return counts;
}

// The counts of the summary's "types" line (convex, concave, corner, border at indices 1-4); empty
// when there is no such line.
std::vector<long> SummaryTypeCounts(const std::string& out)
{
  const size_t at = out.find("\ntypes       ");
  long convex = 0, concave = 0, corner = 0, border = 0;
  if (at == std::string::npos ||
    std::sscanf(out.c_str() + at + 1, "types       convex %ld, concave %ld, corner %ld, border %ld",
      &convex, &concave, &corner, &border) != 4)
  {
    return {};
  }
  return { 0, convex, concave, corner, border };
}

// The summary's "features" count; -1 when there is no such line.
long SummaryFeatures(const std::string& out)
{
  const size_t at = out.find("\nfeatures    ");
  long features = -1;
  if (at == std::string::npos ||
    std::sscanf(out.c_str() + at + 1, "features    %ld", &features) != 1)
  {
    return -1;
  }
  return features;
}

// The CLI's mask read from `output` equals the filter's mask on the same file's cloud, which has
// more than `minimum` feature points.
void CheckSameMask(const std::string& what, vtkFeaturePointDetector* filter,
  const std::string& input, const std::string& output, long minimum = 50)
{
  std::string error;
  vtkSmartPointer<vtkPointSet> cloud = vtkPointCloudIO::Read(input, error);
  vtkSmartPointer<vtkPointSet> result = vtkPointCloudIO::Read(output, error);
  if (!cloud || !result)
  {
    Check(false, what + ": cannot read back: " + error);
    return;
  }
  filter->SetInputData(cloud);
  filter->Update();
  vtkUnsignedCharArray* expected = MaskOf(filter->GetOutput());
  vtkDataArray* got = result->GetPointData()->GetArray("FeatureMask");
  Check(got && got->GetNumberOfTuples() == expected->GetNumberOfTuples(),
    what + ": FeatureMask with one value per point");
  long differences = 0, features = 0;
  for (vtkIdType i = 0; got && i < expected->GetNumberOfTuples() && i < got->GetNumberOfTuples(); ++i)
  {
    differences += expected->GetValue(i) != got->GetComponent(i, 0);
    features += expected->GetValue(i);
  }
  Check(differences == 0, what + ": " + std::to_string(differences) + " mask differences");
  Check(features > minimum, what + ": the cloud has more than " + std::to_string(minimum) +
      " feature points (" + std::to_string(features) + ")");
  std::printf("%s: %ld feature points of %lld, same mask as the library\n", what.c_str(), features,
    static_cast<long long>(expected->GetNumberOfTuples()));
}

int Screenshot(const std::string& baseline)
{
  std::string error;
  const std::string input = Path("screenshot_input.ply");
  const std::string output = Path("screenshot_output.vtp");
  const std::string picture = Path("TestFeaturePointsCLIScreenshot.png");
  Check(vtkPointCloudIO::Write(ModelCloud(vtkFeatureModelSource::MODEL_I, 30000), input, error),
    "write the input: " + error);
  // The baseline shows the paper's method (huang2023, the default before crease): pinned.
  const Run run = Execute(
    { input, output, "--method", "huang2023", "--screenshot", picture, "--size", "640x480" });
  Check(run.Code == 0, "--screenshot run: exit code " + std::to_string(run.Code) + ": " + run.Err);
  Check(Exists(picture), "--screenshot wrote no picture");
  if (!Exists(baseline))
  {
    std::printf("FAILED: no baseline %s; the picture is %s\n", baseline.c_str(), picture.c_str());
    return EXIT_FAILURE;
  }
  vtkNew<vtkPNGReader> test, valid;
  test->SetFileName(picture.c_str());
  valid->SetFileName(baseline.c_str());
  vtkNew<vtkImageDifference> difference;
  difference->SetInputConnection(test->GetOutputPort());
  difference->SetImageConnection(valid->GetOutputPort());
  difference->Update();
  const double error2 = difference->GetThresholdedError();
  int dims[3];
  test->GetOutput()->GetDimensions(dims);
  std::printf("screenshot %dx%d, thresholded error %.3f against %s\n", dims[0], dims[1], error2,
    baseline.c_str());
  Check(dims[0] == 640 && dims[1] == 480, "picture size 640x480");
  Check(error2 <= 10.0, "picture differs from the baseline (thresholded error " +
      std::to_string(error2) + " > 10); the picture is " + picture);
  std::printf("%d failure(s)\n", Failures);
  return Failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
} // namespace

int main(int argc, char* argv[])
{
  if (argc < 3)
  {
    std::printf("usage: TestFeaturePointsCLI PROGRAM FOLDER [BASELINE.png]\n");
    return EXIT_FAILURE;
  }
  Program = argv[1];
  Folder = argv[2];
  ::mkdir(Folder.c_str(), 0755);
  if (argc > 3)
  {
    return Screenshot(argv[3]);
  }
  std::string error;

  // --help lists every option with its default; --version names the program.
  {
    const Run help = Execute({ "--help" });
    Check(help.Code == 0, "--help exit code");
    for (const char* option : { "--method", "--features-only", "--screenshot", "--size",
           "--threads", "--quiet", "--version", "--alpha", "--normal-k", "--ssi-k", "--density-k",
           "--center-k", "--ssi-center", "--gaussian-radius", "--voxel-filter", "--voxel-size",
           "--density-contrast", "--voxel-rule", "--threshold", "--threshold-sigmas", "--k",
           "--crease-k", "--band-width", "--min-angle", "--grow-threshold", "--thin\n",
           "--no-borders\n", "--single-scale\n", "[off]; crease", "FeatureType", "crease",
           "huang2023", "ssi", "pca", "wang-yuan", "[0.75", "[15, 3 to 1000]", "[150, 8 to 1000]",
           "[automatic; crease: 0.5]", "(default: --method crease)", "--method NAME         "
           "the method (default crease)" })
    {
      Check(help.Out.find(option) != std::string::npos, std::string("--help lacks ") + option);
    }
    const Run version = Execute({ "--version" });
    Check(version.Code == 0 && version.Out.find("featurepoints ") == 0, "--version: " + version.Out);
  }

  // Same mask as the library, through several formats and methods.
  const std::string vtp = Path("model.vtp"), ply = Path("model.ply"), csv = Path("model.csv");
  vtkSmartPointer<vtkPolyData> cloud = ModelCloud(vtkFeatureModelSource::MODEL_I, 20000);
  Check(vtkPointCloudIO::Write(cloud, vtp, error), "write model.vtp: " + error);
  Check(vtkPointCloudIO::Write(cloud, ply, error), "write model.ply: " + error);
  Check(vtkPointCloudIO::Write(cloud, csv, error), "write model.csv: " + error);
  // The default method is crease (vtkCreaseVotingFeatures, absolute threshold 0.5 on CreaseVotes).
  {
    const Run run = Execute({ vtp, Path("default.vtp") });
    Check(run.Code == 0, "default method: exit code " + std::to_string(run.Code) + ": " + run.Err);
    Check(run.Out.find("method      crease, mean spacing") != std::string::npos &&
        run.Out.find("noise sigma") != std::string::npos &&
        run.Out.find("threshold   CreaseVotes > 0.5 (absolute)") != std::string::npos,
      "default method's summary names crease and its threshold: " + run.Out);
    vtkNew<vtkCreaseVotingFeatures> filter;
    CheckSameMask("vtp -> vtp, default method (crease)", filter, vtp, Path("default.vtp"));
  }
  {
    const Run run = Execute({ vtp, Path("crease.vtp"), "--method", "crease", "--crease-k", "40",
      "--normal-k", "12", "--band-width", "1.5", "--min-angle", "20", "--grow-threshold", "0.4" });
    Check(run.Code == 0, "--method crease with options: " + run.Err);
    vtkNew<vtkCreaseVotingFeatures> filter;
    filter->SetNumberOfNeighbors(40);
    filter->SetNormalNeighbors(12);
    filter->SetBandWidth(1.5);
    filter->SetMinimumAngle(20);
    filter->SetGrowThreshold(0.4);
    CheckSameMask("vtp -> vtp, --method crease --crease-k 40 --normal-k 12 --band-width 1.5 "
                  "--min-angle 20 --grow-threshold 0.4",
      filter, vtp, Path("crease.vtp"));
  }
  {
    // --threshold-sigmas switches crease to the automatic rule; --threshold sets its own.
    const Run run = Execute({ vtp, Path("crease-auto.vtp"), "--threshold-sigmas", "3" });
    Check(run.Code == 0 && run.Out.find("3 robust standard deviations") != std::string::npos,
      "crease --threshold-sigmas 3: " + run.Out + run.Err);
    vtkNew<vtkCreaseVotingFeatures> filter;
    filter->SetThresholdModeToAutomatic();
    filter->SetThresholdSigmas(3);
    CheckSameMask("vtp -> vtp, crease --threshold-sigmas 3", filter, vtp, Path("crease-auto.vtp"));
    const Run absolute = Execute({ vtp, Path("crease-abs.vtp"), "--threshold", "0.6" });
    Check(absolute.Code == 0, "crease --threshold 0.6: " + absolute.Err);
    vtkNew<vtkCreaseVotingFeatures> filter6;
    filter6->SetThreshold(0.6);
    CheckSameMask("vtp -> vtp, crease --threshold 0.6", filter6, vtp, Path("crease-abs.vtp"));
  }
  // Types: the summary counts the feature points of each FeatureType, as the written array does.
  std::vector<long> defaultTypes;
  long defaultFeatures = -1;
  {
    const Run run = Execute({ vtp, Path("types.vtp") });
    Check(run.Code == 0, "crease, types line: " + run.Err);
    defaultTypes = TypeCounts(Path("types.vtp"));
    defaultFeatures = SummaryFeatures(run.Out);
    const std::vector<long> line = SummaryTypeCounts(run.Out);
    Check(!line.empty(), "crease summary has a types line: " + run.Out);
    Check(defaultTypes[0] >= 0, "crease .vtp output has a FeatureType array");
    Check(line.size() == 5 && defaultTypes[0] >= 0 &&
        std::equal(line.begin() + 1, line.end(), defaultTypes.begin() + 1),
      "types line counts the output's FeatureType array: " + run.Out);
    Check(line.size() == 5 && line[1] + line[2] + line[3] + line[4] == defaultFeatures,
      "types line adds up to the feature points: " + run.Out);
    Check(run.Out.find("time (s)    read ") != std::string::npos &&
        run.Out.find("\nextract (s) ") != std::string::npos,
      "the time lines follow the types line: " + run.Out);
    std::printf("default crease: %ld feature points; types convex %ld, concave %ld, corner %ld, "
                "border %ld\n",
      defaultFeatures, defaultTypes[1], defaultTypes[2], defaultTypes[3], defaultTypes[4]);
  }
  // --thin: one point wide, fewer feature points than the default band, the library's mask.
  {
    const Run run = Execute({ vtp, Path("thin.vtp"), "--thin" });
    Check(run.Code == 0, "--thin: exit code " + std::to_string(run.Code) + ": " + run.Err);
    const long thin = SummaryFeatures(run.Out);
    Check(thin > 0 && defaultFeatures > 0 && thin < defaultFeatures,
      "--thin gives fewer feature points (" + std::to_string(thin) + ") than the default (" +
        std::to_string(defaultFeatures) + ")");
    const std::vector<long> types = TypeCounts(Path("thin.vtp"));
    Check(types[0] >= 0, "--thin: the .vtp output has a FeatureType array");
    const std::vector<long> line = SummaryTypeCounts(run.Out);
    Check(line.size() == 5 && std::equal(line.begin() + 1, line.end(), types.begin() + 1) &&
        line[1] + line[2] + line[3] + line[4] == thin,
      "--thin: types line counts the output's FeatureType array: " + run.Out);
    vtkNew<vtkCreaseVotingFeatures> filter;
    filter->ThinFeaturesOn();
    CheckSameMask("vtp -> vtp, --thin", filter, vtp, Path("thin.vtp"));
  }
  // --single-scale, and the three flags together: the library's masks. On a box, whose corners no
  // fit of the 150 nearest explains, the scale per point changes the votes.
  {
    const std::string box = Path("box.vtp");
    Check(vtkPointCloudIO::Write(ModelCloud(vtkFeatureModelSource::BOX, 20000), box, error),
      "write box.vtp: " + error);
    const Run run = Execute({ box, Path("single.vtp"), "--single-scale" });
    Check(run.Code == 0, "--single-scale: " + run.Err);
    vtkNew<vtkCreaseVotingFeatures> filter;
    filter->MultiScaleOff();
    CheckSameMask("vtp -> vtp, --single-scale", filter, box, Path("single.vtp"));
    // The votes are the single scale's, not the default's.
    vtkNew<vtkCreaseVotingFeatures> multi;
    multi->SetInputData(filter->GetInput());
    multi->Update();
    vtkSmartPointer<vtkPointSet> written = vtkPointCloudIO::Read(Path("single.vtp"), error);
    vtkDataArray* got = written ? written->GetPointData()->GetArray("CreaseVotes") : nullptr;
    vtkDataArray* single = filter->GetOutput()->GetPointData()->GetArray("CreaseVotes");
    vtkDataArray* scales = multi->GetOutput()->GetPointData()->GetArray("CreaseVotes");
    long fromSingle = -1, fromMulti = -1;
    if (got && single && scales && got->GetNumberOfTuples() == single->GetNumberOfTuples())
    {
      fromSingle = fromMulti = 0;
      for (vtkIdType i = 0; i < got->GetNumberOfTuples(); ++i)
      {
        fromSingle += got->GetComponent(i, 0) != single->GetComponent(i, 0);
        fromMulti += got->GetComponent(i, 0) != scales->GetComponent(i, 0);
      }
    }
    Check(fromSingle == 0 && fromMulti > 0,
      "--single-scale: CreaseVotes as the library's single scale (" + std::to_string(fromSingle) +
        " differences), not as its default multi-scale (" + std::to_string(fromMulti) +
        " differences)");
    const Run all = Execute({ vtp, Path("flags.vtp"), "--thin", "--no-borders", "--single-scale" });
    Check(all.Code == 0, "--thin --no-borders --single-scale: " + all.Err);
    vtkNew<vtkCreaseVotingFeatures> flags;
    flags->ThinFeaturesOn();
    flags->BordersOff();
    flags->MultiScaleOff();
    CheckSameMask("vtp -> vtp, --thin --no-borders --single-scale", flags, vtp, Path("flags.vtp"));
  }
  // --no-borders on an open sheet: border points by default, none with it.
  {
    const std::string plate = Path("plate.vtp");
    Check(vtkPointCloudIO::Write(ModelCloud(vtkFeatureModelSource::PLATE_WITH_HOLE, 20000), plate,
            error),
      "write plate.vtp: " + error);
    const Run run = Execute({ plate, Path("plate-borders.vtp") });
    Check(run.Code == 0, "open sheet, default: " + run.Err);
    const std::vector<long> with = TypeCounts(Path("plate-borders.vtp"));
    Check(with[4] > 0, "open sheet: border points by default (" + std::to_string(with[4]) + ")");
    const Run off = Execute({ plate, Path("plate-no-borders.vtp"), "--no-borders" });
    Check(off.Code == 0, "open sheet, --no-borders: " + off.Err);
    const std::vector<long> without = TypeCounts(Path("plate-no-borders.vtp"));
    Check(without[0] >= 0 && without[4] == 0,
      "--no-borders: no BORDER type on an open sheet (" + std::to_string(without[4]) + ")");
    const std::vector<long> line = SummaryTypeCounts(off.Out);
    Check(line.size() == 5 && line[4] == 0, "--no-borders: types line says border 0: " + off.Out);
    vtkNew<vtkCreaseVotingFeatures> filter;
    filter->BordersOff();
    // A flat sheet has no crease: without its borders it may have no feature point at all.
    CheckSameMask("open sheet, --no-borders", filter, plate, Path("plate-no-borders.vtp"), -1);
    std::printf("open sheet (plate with a hole): %ld border points by default, %ld with "
                "--no-borders\n",
      with[4], without[4]);
  }
  // The paper's method, named: it was the default before crease.
  {
    const Run run = Execute({ vtp, Path("out.vtp"), "--method", "huang2023" });
    Check(run.Code == 0, "vtp -> vtp: exit code " + std::to_string(run.Code) + ": " + run.Err);
    Check(run.Out.find("features") != std::string::npos &&
        run.Out.find("candidates") != std::string::npos && run.Out.find("time (s)") != std::string::npos &&
        run.Out.find("method      huang2023") != std::string::npos,
      "summary lines: " + run.Out);
    Check(run.Out.find("\ntypes ") == std::string::npos, "huang2023 has no types line: " + run.Out);
    vtkNew<vtkFeaturePointExtraction> filter;
    CheckSameMask("vtp -> vtp, --method huang2023", filter, vtp, Path("out.vtp"));
  }
  {
    const Run run =
      Execute({ ply, Path("out.csv"), "--method", "huang2023", "--threads", "1", "--quiet" });
    Check(run.Code == 0 && run.Out.empty() && run.Err.empty(),
      "ply -> csv --quiet: code " + std::to_string(run.Code) + ", output '" + run.Out + run.Err + "'");
    vtkNew<vtkFeaturePointExtraction> filter;
    CheckSameMask("ply -> csv, --method huang2023, 1 thread", filter, ply, Path("out.csv"));
  }
  {
    const Run run = Execute({ csv, Path("out.ply"), "--method", "huang2023", "--alpha", "0.9",
      "--voxel-filter", "off", "--threshold-sigmas", "4" });
    Check(run.Code == 0, "csv -> ply with options: " + run.Err);
    vtkNew<vtkFeaturePointExtraction> filter;
    filter->SetAlpha(0.9);
    filter->UseVoxelFilterOff();
    filter->SetThresholdSigmas(4);
    CheckSameMask("csv -> ply, --method huang2023 --alpha 0.9 --voxel-filter off "
                  "--threshold-sigmas 4",
      filter, csv, Path("out.ply"));
  }
  {
    const Run run = Execute({ vtp, Path("pca.vtk"), "--method", "pca", "--k", "20" });
    Check(run.Code == 0, "--method pca: " + run.Err);
    vtkNew<vtkSurfaceVariationFeatures> filter;
    filter->SetNumberOfNeighbors(20);
    CheckSameMask("vtp -> vtk, --method pca --k 20", filter, vtp, Path("pca.vtk"));
  }
  // PCD in and out, LAS in (lidar-size coordinates: offsets of 5e5 and 4e6, steps of 0.1 mm):
  // the same masks as the library on the same files.
  {
    const std::string pcd = Path("model.pcd");
    Check(vtkPointCloudIO::Write(cloud, pcd, error), "write model.pcd: " + error);
    const Run in = Execute({ pcd, Path("from-pcd.vtp") });
    Check(in.Code == 0 && in.Out.find(": 20000 points") != std::string::npos,
      "pcd -> vtp: exit code " + std::to_string(in.Code) + ": " + in.Out + in.Err);
    vtkNew<vtkCreaseVotingFeatures> filter;
    CheckSameMask("pcd -> vtp, default method", filter, pcd, Path("from-pcd.vtp"));
    const Run out = Execute({ vtp, Path("to-pcd.pcd") });
    Check(out.Code == 0, "vtp -> pcd: exit code " + std::to_string(out.Code) + ": " + out.Err);
    Check(Slurp(Path("to-pcd.pcd")).find("\nDATA binary\n") != std::string::npos &&
        Slurp(Path("to-pcd.pcd")).find(" FeatureMask") != std::string::npos,
      "vtp -> pcd: binary PCD with a FeatureMask field");
    CheckSameMask("vtp -> pcd, default method", filter, vtp, Path("to-pcd.pcd"));

    using namespace featurepoints::lastest;
    File las;
    las.Minor = 4;
    las.Format = 6;
    las.Scale[0] = las.Scale[1] = las.Scale[2] = 1e-4;
    las.Offset[0] = 500000;
    las.Offset[1] = 4000000;
    las.Offset[2] = 100;
    for (vtkIdType i = 0; i < cloud->GetNumberOfPoints(); ++i)
    {
      double x[3];
      cloud->GetPoint(i, x);
      las.Points.push_back({ static_cast<int32_t>(std::lround(x[0] * 1e4)),
        static_cast<int32_t>(std::lround(x[1] * 1e4)), static_cast<int32_t>(std::lround(x[2] * 1e4)),
        static_cast<uint16_t>(i % 60000), 1, 1, 2, 1e5 + i, 0, 0, 0, 0 });
    }
    const std::string lasPath = Path("model.las");
    Spit(lasPath, Bytes(las));
    const Run lidar = Execute({ lasPath, Path("from-las.vtp") });
    Check(lidar.Code == 0 && lidar.Out.find(": 20000 points") != std::string::npos,
      "las -> vtp: exit code " + std::to_string(lidar.Code) + ": " + lidar.Out + lidar.Err);
    CheckSameMask("las (coordinates near 4e6) -> vtp, default method", filter, lasPath,
      Path("from-las.vtp"));
    vtkSmartPointer<vtkPointSet> read = vtkPointCloudIO::Read(Path("from-las.vtp"), error);
    double first[3] = { 0, 0, 0 }, model[3];
    if (read && read->GetNumberOfPoints() > 0)
    {
      read->GetPoint(0, first);
    }
    cloud->GetPoint(0, model);
    Check(read && read->GetPointData()->GetArray("Intensity") &&
        read->GetPointData()->GetArray("GpsTime") &&
        std::fabs(first[1] - (4000000 + std::lround(model[1] * 1e4) * 1e-4)) < 1e-6,
      "las -> vtp: Intensity, GpsTime and the double coordinates kept");
  }

  // --features-only: the feature points, their ids in the input (default method, as default.vtp).
  {
    const Run run = Execute({ vtp, Path("features.vtp"), "--features-only" });
    Check(run.Code == 0, "--features-only: " + run.Err);
    vtkSmartPointer<vtkPointSet> all = vtkPointCloudIO::Read(Path("default.vtp"), error);
    vtkSmartPointer<vtkPointSet> only = vtkPointCloudIO::Read(Path("features.vtp"), error);
    auto* ids = only ? vtkIdTypeArray::SafeDownCast(
                         only->GetPointData()->GetArray("vtkOriginalPointIds"))
                     : nullptr;
    vtkUnsignedCharArray* mask = MaskOf(all);
    long selected = 0;
    for (vtkIdType i = 0; mask && i < mask->GetNumberOfTuples(); ++i)
    {
      selected += mask->GetValue(i);
    }
    bool consistent = ids && only->GetNumberOfPoints() == selected;
    for (vtkIdType j = 0; consistent && j < only->GetNumberOfPoints(); ++j)
    {
      const vtkIdType i = ids->GetValue(j);
      double a[3], b[3];
      all->GetPoint(i, a);
      only->GetPoint(j, b);
      consistent = mask->GetValue(i) == 1 && a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
    }
    Check(consistent && selected > 0,
      "--features-only: the feature points, each with its id in the input");
  }

  // Bad usage: exit code 2.
  ExpectFailure("no arguments", {}, 2, "INPUT and OUTPUT files are needed", "");
  ExpectFailure("unknown option", { vtp, Path("o1.vtp"), "--bogus" }, 2,
    "unknown option '--bogus'", Path("o1.vtp"));
  ExpectFailure("out-of-range parameter",
    { vtp, Path("o2.vtp"), "--method", "huang2023", "--alpha", "1.5" }, 2,
    "--alpha 1.5 is out of range", Path("o2.vtp"));
  ExpectFailure("non-numeric parameter", { vtp, Path("o3.vtp"), "--normal-k", "ten" }, 2,
    "--normal-k takes a number", Path("o3.vtp"));
  ExpectFailure("picture size without a picture", { vtp, Path("o3.vtp"), "--size", "640x480" }, 2,
    "--size sets the size of the picture: it needs --screenshot FILE.png", Path("o3.vtp"));
  ExpectFailure("number beyond a double", { vtp, Path("o3.vtp"), "--threshold", "1e309" }, 2,
    "--threshold takes a finite number within a double's range and precision", Path("o3.vtp"));
  ExpectFailure("fractional count", { vtp, Path("o4.vtp"), "--method", "huang2023", "--ssi-k", "2.5" }, 2,
    "--ssi-k 2.5 is out of range: a whole number", Path("o4.vtp"));
  ExpectFailure("option of another method", { vtp, Path("o5.vtp"), "--method", "pca", "--alpha", "1" },
    2, "option --alpha does not apply to --method pca", Path("o5.vtp"));
  ExpectFailure("option of the paper's method, default method", { vtp, Path("o5.vtp"), "--alpha", "1" },
    2, "option --alpha does not apply to --method crease", Path("o5.vtp"));
  ExpectFailure("crease option, another method",
    { vtp, Path("o5.vtp"), "--method", "huang2023", "--band-width", "1" }, 2,
    "option --band-width does not apply to --method huang2023", Path("o5.vtp"));
  ExpectFailure("crease flag, another method",
    { vtp, Path("o5.vtp"), "--thin", "--method", "huang2023" }, 2,
    "option --thin does not apply to --method huang2023", Path("o5.vtp"));
  ExpectFailure("crease flag, another method (before it)",
    { vtp, Path("o5.vtp"), "--method", "pca", "--no-borders" }, 2,
    "option --no-borders does not apply to --method pca", Path("o5.vtp"));
  ExpectFailure("crease flag, another method (--single-scale)",
    { vtp, Path("o5.vtp"), "--method", "ssi", "--single-scale" }, 2,
    "option --single-scale does not apply to --method ssi", Path("o5.vtp"));
  ExpectFailure("flag with a value", { vtp, Path("o5.vtp"), "--thin=1" }, 2,
    "option --thin takes no value", Path("o5.vtp"));
  ExpectFailure("absolute and automatic threshold",
    { vtp, Path("o5.vtp"), "--threshold", "0.5", "--threshold-sigmas", "3" }, 2,
    "options --threshold and --threshold-sigmas exclude each other", Path("o5.vtp"));
  ExpectFailure("unknown method", { vtp, Path("o6.vtp"), "--method", "magic" }, 2,
    "unknown method 'magic'", Path("o6.vtp"));
  ExpectFailure("unknown input extension", { Path("model.foo"), Path("o7.vtp") }, 2,
    "model.foo: cannot tell the input format from the extension '.foo'", Path("o7.vtp"));
  ExpectFailure("unknown output extension", { vtp, Path("o8.obj") }, 2,
    "o8.obj: cannot tell the output format from the extension '.obj'", Path("o8.obj"));
  {
    const std::string before = Slurp(vtp);
    ExpectFailure("output is the input", { vtp, Folder + "/./model.vtp" }, 2,
      "is the input file; the input is never overwritten", "");
    Check(Slurp(vtp) == before, "the input is unchanged");
  }
  // The curves and the output named by two spellings of one file that does not exist yet.
  ExpectFailure("curves over the output", { vtp, Path("o15.vtp"), "--lines", Folder + "/./o15.vtp" },
    2, "the curves cannot replace the input, the output or the picture", Path("o15.vtp"));

  // Bad input or failure: exit code 1.
  ExpectFailure("missing file", { Path("missing.ply"), Path("o9.vtp") }, 1,
    "missing.ply: No such file or directory", Path("o9.vtp"));
  std::ofstream(Path("empty.xyz")).close();
  ExpectFailure("empty file", { Path("empty.xyz"), Path("o10.vtp") }, 1,
    "empty.xyz: the file is empty", Path("o10.vtp"));
  {
    const std::string whole = Slurp(ply);
    std::ofstream(Path("truncated.ply"), std::ios::binary) << whole.substr(0, whole.size() / 2);
    ExpectFailure("truncated binary PLY", { Path("truncated.ply"), Path("o11.vtp") }, 1,
      "truncated.ply: the file ends in vertex", Path("o11.vtp"));
  }
  std::ofstream(Path("word.xyz")) << "0 0 0\n1 0 0\n0 abc 1\n";
  ExpectFailure("non-numeric field", { Path("word.xyz"), Path("o12.vtp") }, 1,
    "word.xyz:3: field 2 ('abc') is not a number", Path("o12.vtp"));
  std::ofstream(Path("nan.csv")) << "x,y,z\n0,0,0\n1,nan,0\n";
  ExpectFailure("NaN in a text file", { Path("nan.csv"), Path("o13.vtp") }, 1,
    "nan.csv:3: field 2 ('nan') is not a finite number", Path("o13.vtp"));
  {
    vtkSmartPointer<vtkPolyData> bad = ModelCloud(vtkFeatureModelSource::MODEL_I, 1000);
    bad->GetPoints()->SetPoint(417, 0.0, std::nan(""), 1.0);
    Check(vtkPointCloudIO::Write(bad, Path("nan.vtp"), error), "write nan.vtp: " + error);
    ExpectFailure("NaN in a binary file", { Path("nan.vtp"), Path("o14.ply") }, 1,
      "nan.vtp: point 417 (counting from 0) has a non-finite coordinate", Path("o14.ply"));
  }
  ExpectFailure("unwritable output path", { vtp, Path("no-such-folder/out.vtp") }, 1,
    "no-such-folder/out.vtp: cannot create a file in", "");
  ExpectFailure("output names a folder", { vtp, Path("sub.vtp/") }, 2,
    "cannot tell the output format", "");

  std::printf("%d failure(s)\n", Failures);
  return Failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
