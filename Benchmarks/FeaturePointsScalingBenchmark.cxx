// Speed and memory at every size (docs/benchmarks.md), measured against VTK's own point filters in the same
// process, on the same clouds:
// - for each size (default 100K, 1M, 10M points of Model I, features sampled 3x denser): the
//   proposed method's time per stage, points per second, peak memory beyond the input, and the
//   ratio of its time to vtkPCANormalEstimation's and vtkPCACurvatureEstimation's (k = 15);
// - the same figures for the default detector, vtkCreaseVotingFeatures (the CLI's --method crease);
// - the voxel step with and without, on denser-feature and uniform clouds;
// - the k nearest of every point (k = 15 and 150) with the project's grid against VTK's
//   vtkStaticPointLocator, through the same batched, threaded query (vtkPointCloudNeighborhoods);
// - the output with 1 thread against the output with all threads (bit-identical or not).
//
//   FeaturePointsScalingBenchmark [--sizes 100000,1000000,10000000] [--threads N] [--repeat R]
//
// Peak memory is the process's high-water mark (VmHWM, reset before each run through
// /proc/self/clear_refs) minus its resident size before the run, the input already built.
#include "vtkCreaseVotingFeatures.h"
#include "vtkFeatureModelSource.h"
#include "vtkFeaturePointExtraction.h"
#include "vtkFloatArray.h"
#include "vtkMath.h"
#include "vtkPCACurvatureEstimation.h"
#include "vtkPCANormalEstimation.h"
#include "vtkPointCloudNeighborhoods.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkStaticPointLocator.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

namespace
{
double Seconds(const std::function<void()>& f)
{
  const auto t0 = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Median of `repeat` timings of f.
double MedianSeconds(int repeat, const std::function<void()>& f)
{
  std::vector<double> t;
  for (int r = 0; r < repeat; ++r)
  {
    t.push_back(Seconds(f));
  }
  std::sort(t.begin(), t.end());
  return t[t.size() / 2];
}

long StatusKiB(const char* key)
{
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
  {
    if (line.compare(0, std::strlen(key), key) == 0)
    {
      return std::atol(line.c_str() + std::strlen(key) + 1);
    }
  }
  return -1;
}

void ResetPeak()
{
  std::ofstream("/proc/self/clear_refs") << "5";
}

vtkSmartPointer<vtkPolyData> MakeCloud(vtkIdType n, double densityFactor)
{
  vtkNew<vtkFeatureModelSource> source;
  source->SetModel(vtkFeatureModelSource::MODEL_I);
  source->SetNumberOfPoints(n);
  source->SetFeatureDensityFactor(densityFactor);
  source->SetOutputPointsPrecision(vtkAlgorithm::SINGLE_PRECISION);
  source->Update();
  auto cloud = vtkSmartPointer<vtkPolyData>::New();
  cloud->SetPoints(source->GetOutput()->GetPoints()); // points only, as a scan would be
  return cloud;
}

struct Run
{
  double Seconds = 0.0;
  double PeakMiB = 0.0;
  std::vector<std::pair<std::string, double>> Stages;
  vtkIdType Candidates = 0, Features = 0;
  vtkSmartPointer<vtkPolyData> Output;
};

// Time, peak memory and stages of one run of `filter` on `cloud`.
Run RunDetector(vtkFeaturePointDetector* filter, vtkPolyData* cloud, bool keep = false)
{
  Run run;
  filter->SetInputData(cloud);
  ResetPeak();
  const long before = StatusKiB("VmRSS:");
  run.Seconds = Seconds([&] { filter->Update(); });
  run.PeakMiB = (StatusKiB("VmHWM:") - before) / 1024.0;
  for (int i = 0; i < filter->GetNumberOfStages(); ++i)
  {
    run.Stages.emplace_back(filter->GetStageName(i), filter->GetStageTime(i));
  }
  run.Features = filter->GetNumberOfFeaturePoints();
  if (keep)
  {
    run.Output = filter->GetOutput();
  }
  return run;
}

Run RunFilter(vtkPolyData* cloud, bool voxel, bool keep = false)
{
  vtkNew<vtkFeaturePointExtraction> filter;
  filter->SetUseVoxelFilter(voxel);
  Run run = RunDetector(filter, cloud, keep);
  run.Candidates = filter->GetNumberOfCandidates();
  return run;
}

std::string StageList(const Run& run)
{
  std::string stages;
  for (const auto& s : run.Stages)
  {
    char text[64];
    std::snprintf(
      text, sizeof(text), "%s%s %.3f", stages.empty() ? "" : ", ", s.first.c_str(), s.second);
    stages += text;
  }
  return stages;
}

template <typename FilterT>
double TimeVTK(vtkPolyData* cloud, int repeat)
{
  return MedianSeconds(repeat, [&] {
    vtkNew<FilterT> filter;
    filter->SetSampleSize(15);
    filter->SetInputData(cloud);
    filter->Update();
  });
}

// The k nearest of every point of the cloud, the locator built first (nullptr: the project's
// grid); the table in `table`, the median time of `repeat` runs returned.
double TimeNeighbours(vtkPolyData* cloud, int k, vtkAbstractPointLocator* locator, int repeat,
  std::vector<int32_t>& table)
{
  std::vector<vtkIdType> ids(static_cast<size_t>(cloud->GetNumberOfPoints()));
  std::iota(ids.begin(), ids.end(), vtkIdType(0));
  return MedianSeconds(repeat, [&] {
    vtkNew<vtkPointCloudNeighborhoods> neighbourhoods;
    if (locator)
    {
      neighbourhoods->SetLocator(locator);
    }
    neighbourhoods->Build(cloud->GetPoints());
    neighbourhoods->FindNearestNeighbors(k, ids, table);
  });
}

// The points whose k-th nearest lies at another distance in the two tables (ties may come in
// another order, the distances may not).
vtkIdType KthDistanceMismatches(
  vtkPoints* points, int k, const std::vector<int32_t>& a, const std::vector<int32_t>& b)
{
  vtkIdType mismatches = 0;
  double x[3], y[3], z[3];
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    const int32_t p = a[i * k + k - 1], q = b[i * k + k - 1];
    if (p < 0 || q < 0)
    {
      mismatches += (p < 0) != (q < 0);
      continue;
    }
    points->GetPoint(i, x);
    points->GetPoint(p, y);
    points->GetPoint(q, z);
    mismatches +=
      vtkMath::Distance2BetweenPoints(x, y) != vtkMath::Distance2BetweenPoints(x, z) ? 1 : 0;
  }
  return mismatches;
}

bool SameArrays(vtkPolyData* a, vtkPolyData* b)
{
  for (const char* name : { "Normals", "SSI", "PDI", "F", "Candidate", "FeatureMask" })
  {
    vtkDataArray* x = a->GetPointData()->GetArray(name);
    vtkDataArray* y = b->GetPointData()->GetArray(name);
    if (!x || !y || x->GetDataType() != y->GetDataType() ||
      x->GetNumberOfValues() != y->GetNumberOfValues() ||
      std::memcmp(x->GetVoidPointer(0), y->GetVoidPointer(0),
        x->GetNumberOfValues() * x->GetDataTypeSize()) != 0)
    {
      return false;
    }
  }
  return true;
}
} // namespace

int main(int argc, char* argv[])
{
  std::vector<vtkIdType> sizes = { 100000, 1000000, 10000000 };
  int threads = 0, repeat = 3;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (arg == "--sizes" && i + 1 < argc)
    {
      sizes.clear();
      std::stringstream list(argv[++i]);
      std::string item;
      while (std::getline(list, item, ','))
      {
        sizes.push_back(std::atoll(item.c_str()));
      }
    }
    else if (arg == "--threads" && i + 1 < argc)
    {
      threads = std::atoi(argv[++i]);
    }
    else if (arg == "--repeat" && i + 1 < argc)
    {
      repeat = std::max(1, std::atoi(argv[++i]));
    }
    else
    {
      std::printf("usage: FeaturePointsScalingBenchmark [--sizes N,N,...] [--threads N] "
                  "[--repeat R]\n");
      return arg == "--help" ? EXIT_SUCCESS : 2;
    }
  }
  if (threads > 0)
  {
    vtkSMPTools::Initialize(threads);
  }
  std::printf("SMP backend %s, %d threads; Model I, features 3x denser unless said; medians of %d "
              "back-to-back runs of the filter and of VTK's filters, ratios: medians of the "
              "back-to-back ratios\n\n",
    vtkSMPTools::GetBackend(), vtkSMPTools::GetEstimatedNumberOfThreads(), repeat);

  bool ok = true;
  std::printf("%10s %8s %9s %9s %8s %8s %9s %9s  %s\n", "points", "filter s", "Mpoint/s",
    "peak MiB", "B/point", "xPCANorm", "xPCACurv", "scored", "stages (s)");
  double firstPerPoint = 0.0;
  for (vtkIdType n : sizes)
  {
    vtkSmartPointer<vtkPolyData> cloud = MakeCloud(n, 3.0);
    // The filter and VTK's two filters run back to back `repeat` times; each figure is the median
    // of its runs and each ratio the median of the back-to-back ratios, so that a change in the
    // machine's load between runs does not show as a difference. Stages: the median run's.
    std::vector<Run> runs;
    std::vector<double> normalTimes, curvatureTimes, normalRatios, curvatureRatios;
    double peakMiB = 0.0;
    for (int r = 0; r < repeat; ++r)
    {
      runs.push_back(RunFilter(cloud, true));
      peakMiB = std::max(peakMiB, runs.back().PeakMiB);
      normalTimes.push_back(TimeVTK<vtkPCANormalEstimation>(cloud, 1));
      curvatureTimes.push_back(TimeVTK<vtkPCACurvatureEstimation>(cloud, 1));
      normalRatios.push_back(runs.back().Seconds / normalTimes.back());
      curvatureRatios.push_back(runs.back().Seconds / curvatureTimes.back());
    }
    std::sort(runs.begin(), runs.end(), [](const Run& a, const Run& b) { return a.Seconds < b.Seconds; });
    Run run = runs[runs.size() / 2];
    run.PeakMiB = peakMiB;
    auto median = [](std::vector<double>& v) {
      std::sort(v.begin(), v.end());
      return v[v.size() / 2];
    };
    const double normals = median(normalTimes);
    const double curvature = median(curvatureTimes);
    const double normalRatio = median(normalRatios);
    const double curvatureRatio = median(curvatureRatios);
    const std::string stages = StageList(run);
    const double perPoint = run.Seconds / n;
    firstPerPoint = firstPerPoint > 0 ? firstPerPoint : perPoint;
    std::printf("%10lld %8.3f %9.2f %9.1f %8.0f %8.2f %9.2f %9lld  %s\n",
      static_cast<long long>(n), run.Seconds, n / run.Seconds / 1e6, run.PeakMiB,
      run.PeakMiB * 1048576.0 / n, normalRatio, curvatureRatio,
      static_cast<long long>(run.Candidates), stages.c_str());
    std::printf("%10s vtkPCANormalEstimation %.3f s, vtkPCACurvatureEstimation %.3f s; time per "
                "point %.2fx the first size's\n",
      "", normals, curvature, perPoint / firstPerPoint);
    ok = ok && std::isfinite(run.Seconds) && run.Features > 0;
    // The default detector on the same cloud.
    vtkNew<vtkCreaseVotingFeatures> crease;
    const Run creaseRun = RunDetector(crease, cloud);
    std::printf("%10s crease (the default detector): %.3f s, %.2f Mpoint/s, peak %.1f MiB (%.0f "
                "B/point), %.2fx PCANormal, %lld features; %s\n",
      "", creaseRun.Seconds, n / creaseRun.Seconds / 1e6, creaseRun.PeakMiB,
      creaseRun.PeakMiB * 1048576.0 / n, creaseRun.Seconds / normals,
      static_cast<long long>(creaseRun.Features), StageList(creaseRun).c_str());
    ok = ok && std::isfinite(creaseRun.Seconds) && creaseRun.Features > 0;
  }

  // The voxel step: faster on denser features, no slower on uniform clouds.
  std::printf("\n%10s %-8s %10s %10s %8s %10s   (medians of at least 3 alternating runs; ratio: "
              "median of the pairs; 7 pairs up to 200K points)\n",
    "points", "cloud", "voxel s", "no voxel s", "ratio", "features");
  for (vtkIdType n : sizes)
  {
    if (n > 2000000)
    {
      continue; // the comparison needs several runs of each; 1M points show the trend
    }
    for (double factor : { 3.0, 1.0 })
    {
      vtkSmartPointer<vtkPolyData> cloud = MakeCloud(n, factor);
      // Runs with and without alternate, and the ratio is the median of the back-to-back pairs,
      // so that a change in the machine's load between them does not show as a difference.
      std::vector<double> with, without, ratio;
      // Small clouds run in a fraction of a second, where the machine's noise is largest: 7 pairs.
      const int pairs = std::max(repeat, n <= 200000 ? 7 : 3);
      for (int r = 0; r < pairs; ++r)
      {
        with.push_back(Seconds([&] { RunFilter(cloud, true); }));
        without.push_back(Seconds([&] { RunFilter(cloud, false); }));
        ratio.push_back(with.back() / without.back());
      }
      for (auto* v : { &with, &without, &ratio })
      {
        std::sort(v->begin(), v->end());
      }
      const size_t mid = with.size() / 2;
      std::printf("%10lld %-8s %10.3f %10.3f %8.3f %10lld\n", static_cast<long long>(n),
        factor > 1 ? "denser" : "uniform", with[mid], without[mid], ratio[mid],
        static_cast<long long>(RunFilter(cloud, true).Features));
    }
  }

  // The k nearest of every point: the project's grid and VTK's static point locator through the
  // same batched, threaded query; the same k-th distance for every point. At most 200,000 points
  // (VTK's locator takes about a minute per million points at k = 150).
  {
    const vtkIdType n = std::min<vtkIdType>(sizes.front(), 200000);
    vtkSmartPointer<vtkPolyData> cloud = MakeCloud(n, 3.0);
    std::printf("\n%10s %4s %10s %22s %8s %10s   (the %lld points' k nearest, build included; "
                "medians of %d runs, 1 of VTK's at k = 150)\n",
      "points", "k", "grid s", "vtkStaticPointLocator s", "ratio", "k-th differ",
      static_cast<long long>(n), repeat);
    for (int k : { 15, 150 })
    {
      std::vector<int32_t> ours, theirs;
      const double grid = TimeNeighbours(cloud, k, nullptr, repeat, ours);
      vtkNew<vtkStaticPointLocator> locator;
      // (At k = 150 VTK's locator takes many times the grid's: one run.)
      const double vtk = TimeNeighbours(cloud, k, locator, k > 15 ? 1 : repeat, theirs);
      const vtkIdType differ = KthDistanceMismatches(cloud->GetPoints(), k, ours, theirs);
      std::printf("%10lld %4d %10.3f %22.3f %8.2f %10lld\n", static_cast<long long>(n), k, grid,
        vtk, grid / vtk, static_cast<long long>(differ));
      ok = ok && differ == 0;
    }
  }

  // Bit-identical whatever the thread count.
  {
    const vtkIdType n = std::min<vtkIdType>(sizes.front(), 200000);
    vtkSmartPointer<vtkPolyData> cloud = MakeCloud(n, 3.0);
    const int all = vtkSMPTools::GetEstimatedNumberOfThreads();
    const Run many = RunFilter(cloud, true, true);
    vtkSMPTools::Initialize(1);
    const Run one = RunFilter(cloud, true, true);
    vtkSMPTools::Initialize(all);
    const bool same = SameArrays(many.Output, one.Output);
    std::printf("\n%lld points, %d threads vs 1 thread: Normals, SSI, PDI, F, Candidate, "
                "FeatureMask %s\n",
      static_cast<long long>(n), all, same ? "bit-identical" : "DIFFER");
    ok = ok && same;
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
