// The paper's comparison, reproduced in one run (docs/benchmarks.md):
// - Table 1: Models I-III (vtkFeatureModelSource, feature bands sampled denser, sigma = 0.5 s),
//   each method with default parameters: points, Pr, Pt (the paper's), precision, recall, F1,
//   MCC (docs/evaluation.md) and seconds.
// - Table 2: the proposed method with and without the voxel step, on the same models sampled with
//   denser features and uniformly: seconds (median of --repeat runs), F1, Pr, Pt, time saved.
// - The labelled PCEDNet clouds (coordinates only given to the detectors): precision, recall and
//   MCC per model, medians per folder and over all models.
// Prints text tables and writes every row to a CSV file.
#include "FeaturePointsBenchmarkFigures.h"

#include "vtkCreaseVotingFeatures.h"
#include "vtkCurvatureDensityFeatures.h"
#include "vtkFeatureModelSource.h"
#include "vtkFeaturePointEvaluation.h"
#include "vtkFeaturePointExtraction.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkPLYReader.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkSmoothShrinkIndexFeatures.h"
#include "vtkSurfaceVariationFeatures.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

namespace
{
using namespace fpbench;
struct Method
{
  const char* Name;
  std::function<vtkSmartPointer<vtkFeaturePointDetector>()> Make;
};

std::vector<Method> Methods()
{
  return {
    { "PCA", [] { return vtkSmartPointer<vtkSurfaceVariationFeatures>::New(); } },
    { "SSI", [] { return vtkSmartPointer<vtkSmoothShrinkIndexFeatures>::New(); } },
    { "Wang&Yuan", [] { return vtkSmartPointer<vtkCurvatureDensityFeatures>::New(); } },
    { "Ours", [] { return vtkSmartPointer<vtkFeaturePointExtraction>::New(); } },
    { "Crease", [] { return vtkSmartPointer<vtkCreaseVotingFeatures>::New(); } },
  };
}

struct Row
{
  std::string Section, Dataset, Method;
  long long Points = 0, Detections = 0, Positives = 0;
  double Pr = 0, Pt = -1, Precision = 0, Recall = 0, F1 = 0, MCC = 0, Seconds = 0;
  double OracleF1 = -1;
};

// The best F1 any threshold on the method's score could give on this cloud, chosen with the ground
// truth: an oracle, shown beside the default figures to separate the score from the threshold rule.
double OracleF1(vtkDataArray* score, vtkDataArray* delta, double s)
{
  const vtkIdType n = score->GetNumberOfTuples();
  std::vector<std::pair<double, vtkIdType>> order(static_cast<size_t>(n));
  long long positives = 0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    order[i] = { -score->GetComponent(i, 0), i };
    positives += delta->GetComponent(i, 0) <= 2.0 * s;
  }
  std::sort(order.begin(), order.end());
  double best = 0.0;
  long long detections = 0, correct = 0, found = 0;
  for (size_t r = 0; r < order.size(); ++r)
  {
    const double d = delta->GetComponent(order[r].second, 0);
    ++detections;
    correct += d <= 4.0 * s;
    found += d <= 2.0 * s;
    // Only between distinct scores can a threshold separate points.
    if (r + 1 < order.size() && order[r + 1].first == order[r].first)
    {
      continue;
    }
    const double p = double(correct) / double(detections);
    const double q = positives ? double(found) / double(positives) : 0.0;
    if (p + q > 0.0)
    {
      best = std::max(best, 2.0 * p * q / (p + q));
    }
  }
  return best;
}

struct Options
{
  double Scale = 1.0;
  int Repeat = 3;
  int Threads = 0;
  int PcednetMax = -1;
  std::string Pcednet;
  std::string Csv = "paper_tables.csv";
  bool PcednetGiven = false;
};

void CheckFinite(const Row& r)
{
  for (double v : { r.Pr, r.Pt, r.Precision, r.Recall, r.F1, r.MCC, r.Seconds })
  {
    if (!std::isfinite(v))
    {
      std::fprintf(stderr, "error: non-finite figure for %s / %s\n", r.Dataset.c_str(), r.Method.c_str());
      ++Failures;
    }
  }
}

// Runs `filter` on `input` (timed), returns the mask's evaluation.
double Run(vtkFeaturePointDetector* filter, vtkPolyData* input)
{
  filter->SetInputData(input);
  filter->Modified();
  const auto t0 = std::chrono::steady_clock::now();
  filter->Update();
  const auto t1 = std::chrono::steady_clock::now();
  return std::chrono::duration<double>(t1 - t0).count();
}

// The figures of an evaluation as a table row (the caller names the row).
Row FromEvaluation(vtkFeaturePointEvaluation* evaluation, double seconds)
{
  Row r;
  r.Points = evaluation->GetNumberOfPoints();
  r.Detections = evaluation->GetDetections();
  r.Positives = evaluation->GetPositives();
  r.Pr = evaluation->GetPr();
  r.Pt = evaluation->GetPt();
  r.Precision = evaluation->GetPrecision();
  r.Recall = evaluation->GetRecall();
  r.F1 = evaluation->GetF1();
  r.MCC = evaluation->GetMCC();
  r.Seconds = seconds;
  return r;
}

Row EvaluateSynthetic(vtkFeaturePointDetector* filter, vtkPolyData* model, double seconds)
{
  vtkNew<vtkFeaturePointEvaluation> evaluation;
  const double s = model->GetFieldData()->GetArray("CleanMeanSpacing")->GetComponent(0, 0);
  if (!evaluation->EvaluateDistances(filter->GetOutput()->GetPointData()->GetArray("FeatureMask"),
        model->GetPointData()->GetArray("FeatureDistance"), s))
  {
    std::fprintf(stderr, "error: %s\n", evaluation->GetErrorText().c_str());
    ++Failures;
  }
  Row r = FromEvaluation(evaluation, seconds);
  r.OracleF1 = OracleF1(filter->GetOutput()->GetPointData()->GetArray(filter->GetScoreArrayName()),
    model->GetPointData()->GetArray("FeatureDistance"), s);
  return r;
}

vtkSmartPointer<vtkPolyData> MakeModel(int model, double density, double scale)
{
  vtkNew<vtkFeatureModelSource> source;
  source->SetModel(model);
  source->SetFeatureDensityFactor(density);
  source->SetNumberOfPoints(static_cast<vtkIdType>(
    std::llround(scale * double(vtkFeatureModelSource::GetDefaultNumberOfPoints(model)))));
  source->Update();
  return source->GetOutput();
}

// The detector sees the coordinates only.
vtkSmartPointer<vtkPolyData> PointsOnly(vtkPolyData* data)
{
  auto p = vtkSmartPointer<vtkPolyData>::New();
  p->SetPoints(data->GetPoints());
  return p;
}

std::string Percent(double v)
{
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%6.2f", 100.0 * v);
  return buffer;
}

void Usage(const char* program)
{
  std::printf(
    "usage: %s [--scale F] [--repeat N] [--threads N] [--pcednet DIR] [--pcednet-max N] [--csv FILE]\n"
    "  --scale F        fraction of the models' point counts (default 1: 170K, 220K, 130K)\n"
    "  --repeat N       runs per timing of Table 2, the median is reported (default 3)\n"
    "  --threads N      SMP threads (default: all cores)\n"
    "  --pcednet DIR    folder searched recursively for PCEDNet's labelled .ply files\n"
    "                   (default: %s; empty: skip)\n"
    "  --pcednet-max N  use at most N of those files (default: all)\n"
    "  --csv FILE       where to write every row (default paper_tables.csv)\n",
    program, FEATUREPOINTS_PCEDNET_DIR);
}
} // namespace

int main(int argc, char* argv[])
{
  Options o;
  o.Pcednet = FEATUREPOINTS_PCEDNET_DIR;
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    const bool hasValue = i + 1 < argc;
    if (a == "--help" || a == "-h")
    {
      Usage(argv[0]);
      return 0;
    }
    else if (a == "--scale" && hasValue)
    {
      o.Scale = std::atof(argv[++i]);
    }
    else if (a == "--repeat" && hasValue)
    {
      o.Repeat = std::atoi(argv[++i]);
    }
    else if (a == "--threads" && hasValue)
    {
      o.Threads = std::atoi(argv[++i]);
    }
    else if (a == "--pcednet" && hasValue)
    {
      o.Pcednet = argv[++i];
      o.PcednetGiven = !o.Pcednet.empty();
    }
    else if (a == "--pcednet-max" && hasValue)
    {
      o.PcednetMax = std::atoi(argv[++i]);
    }
    else if (a == "--csv" && hasValue)
    {
      o.Csv = argv[++i];
    }
    else
    {
      std::fprintf(stderr, "error: unknown or incomplete option '%s'\n", a.c_str());
      Usage(argv[0]);
      return 2;
    }
  }
  if (!(o.Scale > 0.0 && o.Scale <= 10.0) || o.Repeat < 1 || o.Threads < 0)
  {
    std::fprintf(stderr, "error: --scale must lie in (0, 10], --repeat >= 1, --threads >= 0\n");
    return 2;
  }
  vtkSMPTools::Initialize(o.Threads);
  std::printf("FeaturePoints: the paper's comparison (Huang et al. 2023, Tables 1 and 2)\n");
  std::printf("SMP backend %s, %d thread(s); models at %.2f x the paper's point counts; noise "
              "sigma = 0.5 s.\n\n",
    vtkSMPTools::GetBackend(), vtkSMPTools::GetEstimatedNumberOfThreads(), o.Scale);
  std::vector<Row> rows;
  const int models[] = { vtkFeatureModelSource::MODEL_I, vtkFeatureModelSource::MODEL_II,
    vtkFeatureModelSource::MODEL_III };

  // Table 1.
  std::printf("Table 1: feature bands sampled 3x denser, default parameters for every method\n"
              "(oracle: the best F1 of any threshold on the method's score, picked with the ground "
              "truth; not a default figure)\n");
  std::printf("%-10s %-10s %8s %8s %7s %7s %6s %6s %6s %6s %8s %7s\n", "model", "method", "points",
    "detected", "Pr %", "Pt %", "prec", "recall", "F1", "MCC", "seconds", "oracle");
  for (int m : models)
  {
    auto model = MakeModel(m, 3.0, o.Scale);
    auto input = PointsOnly(model);
    for (const Method& method : Methods())
    {
      auto filter = method.Make();
      const double seconds = Run(filter, input);
      Row r = EvaluateSynthetic(filter, model, seconds);
      r.Section = "table1";
      r.Dataset = vtkFeatureModelSource::GetModelName(m);
      r.Method = method.Name;
      CheckFinite(r);
      rows.push_back(r);
      std::printf("%-10s %-10s %8lld %8lld %s %s %6.3f %6.3f %6.3f %6.3f %8.3f %7.3f\n",
        r.Dataset.c_str(), r.Method.c_str(), r.Points, r.Detections, Percent(r.Pr).c_str(),
        Percent(r.Pt).c_str(), r.Precision, r.Recall, r.F1, r.MCC, r.Seconds, r.OracleF1);
    }
  }

  // Table 2.
  std::printf("\nTable 2: the proposed method without and with the voxel step (median of %d "
              "runs)\n", o.Repeat);
  std::printf("%-10s %-8s | %8s %6s %7s %7s | %8s %6s %7s %7s | %6s %7s\n", "model", "features",
    "s (off)", "F1", "Pr %", "Pt %", "s (on)", "F1", "Pr %", "Pt %", "saved", "dF1");
  for (double density : { 3.0, 1.0 })
  {
    for (int m : models)
    {
      auto model = MakeModel(m, density, o.Scale);
      auto input = PointsOnly(model);
      Row result[2];
      for (int voxel = 0; voxel < 2; ++voxel)
      {
        vtkNew<vtkFeaturePointExtraction> filter;
        filter->SetUseVoxelFilter(voxel == 1);
        std::vector<double> times;
        for (int k = 0; k < o.Repeat; ++k)
        {
          times.push_back(Run(filter, input));
        }
        result[voxel] = EvaluateSynthetic(filter, model, Median(times));
        result[voxel].Section = "table2";
        result[voxel].Dataset = std::string(vtkFeatureModelSource::GetModelName(m)) +
          (density > 1.0 ? " (denser features)" : " (uniform)");
        result[voxel].Method = voxel ? "Ours, voxel step" : "Ours, no voxel step";
        CheckFinite(result[voxel]);
        rows.push_back(result[voxel]);
      }
      const double saved = 1.0 - result[1].Seconds / result[0].Seconds;
      std::printf("%-10s %-8s | %8.3f %6.3f %s %s | %8.3f %6.3f %s %s | %5.1f%% %+7.4f\n",
        vtkFeatureModelSource::GetModelName(m), density > 1.0 ? "denser" : "uniform",
        result[0].Seconds, result[0].F1, Percent(result[0].Pr).c_str(),
        Percent(result[0].Pt).c_str(), result[1].Seconds, result[1].F1,
        Percent(result[1].Pr).c_str(), Percent(result[1].Pt).c_str(), 100.0 * saved,
        result[1].F1 - result[0].F1);
    }
  }

  // PCEDNet's labelled clouds.
  std::vector<std::filesystem::path> files;
  std::error_code error;
  if (!o.Pcednet.empty() && std::filesystem::is_directory(o.Pcednet, error))
  {
    for (const auto& entry : std::filesystem::recursive_directory_iterator(o.Pcednet, error))
    {
      if (entry.is_regular_file() && entry.path().extension() == ".ply")
      {
        files.push_back(entry.path());
      }
    }
    std::sort(files.begin(), files.end());
    if (o.PcednetMax >= 0 && files.size() > static_cast<size_t>(o.PcednetMax))
    {
      files.resize(static_cast<size_t>(o.PcednetMax));
    }
  }
  if (files.empty())
  {
    std::printf("\nPCEDNet: no labelled .ply file under '%s'; skipped.\n", o.Pcednet.c_str());
    if (o.PcednetGiven)
    {
      std::fprintf(stderr, "error: --pcednet %s: no .ply file found\n", o.Pcednet.c_str());
      ++Failures;
    }
  }
  else
  {
    std::printf("\nPCEDNet labelled clouds (%zu files under %s): per-point labels, no tolerance\n",
      files.size(), o.Pcednet.c_str());
    std::printf("%-34s %-10s %7s %7s %6s %6s %6s %8s\n", "cloud", "method", "points", "sharp",
      "prec", "recall", "MCC", "seconds");
    // folder -> method -> MCC / precision / recall values.
    struct Values
    {
      std::vector<double> Precision, Recall, MCC;
    };
    std::vector<std::string> folders;
    std::vector<std::vector<Values>> perFolder;
    const auto methods = Methods();
    std::vector<Values> all(methods.size());
    for (const auto& file : files)
    {
      vtkNew<vtkPLYReader> reader;
      reader->SetFileName(file.string().c_str());
      reader->Update();
      vtkPolyData* cloud = reader->GetOutput();
      vtkDataArray* colors = cloud->GetPointData()->GetArray("RGBA");
      if (!colors)
      {
        colors = cloud->GetPointData()->GetArray("RGB");
      }
      auto labels = vtkFeaturePointEvaluation::LabelsFromColors(colors);
      if (cloud->GetNumberOfPoints() == 0 || !labels)
      {
        std::fprintf(stderr, "error: %s: no points or no colour labels (red, green, blue)\n",
          file.string().c_str());
        ++Failures;
        continue;
      }
      const std::string folder = file.parent_path().filename().string();
      const std::string name = folder + "/" + file.filename().string();
      auto f = std::find(folders.begin(), folders.end(), folder);
      if (f == folders.end())
      {
        folders.push_back(folder);
        perFolder.emplace_back(methods.size());
        f = folders.end() - 1;
      }
      auto& values = perFolder[static_cast<size_t>(f - folders.begin())];
      auto input = PointsOnly(cloud);
      for (size_t k = 0; k < methods.size(); ++k)
      {
        auto filter = methods[k].Make();
        const double seconds = Run(filter, input);
        vtkNew<vtkFeaturePointEvaluation> evaluation;
        if (!evaluation->EvaluateLabels(
              filter->GetOutput()->GetPointData()->GetArray("FeatureMask"), labels))
        {
          std::fprintf(stderr, "error: %s: %s\n", name.c_str(), evaluation->GetErrorText().c_str());
          ++Failures;
        }
        Row r = FromEvaluation(evaluation, seconds);
        r.Section = "pcednet";
        r.Dataset = name;
        r.Method = methods[k].Name;
        CheckFinite(r);
        rows.push_back(r);
        for (Values* v : { &values[k], &all[k] })
        {
          v->Precision.push_back(r.Precision);
          v->Recall.push_back(r.Recall);
          v->MCC.push_back(r.MCC);
        }
        std::printf("%-34s %-10s %7lld %7lld %6.3f %6.3f %6.3f %8.3f\n", name.c_str(),
          r.Method.c_str(), r.Points, r.Positives, r.Precision, r.Recall, r.MCC, r.Seconds);
      }
    }
    std::printf("\nPCEDNet medians (precision / recall / MCC)\n%-16s", "folder");
    for (const Method& m : methods)
    {
      std::printf(" %-22s", m.Name);
    }
    std::printf("\n");
    auto printMedians = [&](const std::string& label, const std::vector<Values>& v, size_t count) {
      std::printf("%-16s", (label + " (" + std::to_string(count) + ")").c_str());
      for (size_t k = 0; k < methods.size(); ++k)
      {
        std::printf(" %.3f / %.3f / %.3f  ", Median(v[k].Precision), Median(v[k].Recall),
          Median(v[k].MCC));
        Row r;
        r.Section = "pcednet-median";
        r.Dataset = label;
        r.Method = methods[k].Name;
        r.Points = static_cast<long long>(count);
        r.Precision = Median(v[k].Precision);
        r.Recall = Median(v[k].Recall);
        r.MCC = Median(v[k].MCC);
        rows.push_back(r);
      }
      std::printf("\n");
    };
    for (size_t i = 0; i < folders.size(); ++i)
    {
      printMedians(folders[i], perFolder[i], perFolder[i][0].MCC.size());
    }
    printMedians("all", all, all[0].MCC.size());
  }

  std::ofstream csv(o.Csv);
  csv << "section,dataset,method,points,detections,positives,Pr,Pt,precision,recall,F1,MCC,seconds,"
         "oracle_F1\n";
  for (const Row& r : rows)
  {
    csv << r.Section << ",\"" << r.Dataset << "\",\"" << r.Method << "\"," << r.Points << ","
        << r.Detections << "," << r.Positives << "," << r.Pr << "," << r.Pt << "," << r.Precision
        << "," << r.Recall << "," << r.F1 << "," << r.MCC << "," << r.Seconds << "," << r.OracleF1
        << "\n";
  }
  csv.close();
  if (!csv)
  {
    std::fprintf(stderr, "error: cannot write %s\n", o.Csv.c_str());
    return 1;
  }
  std::printf("\nCSV: %s (%zu rows)\n", o.Csv.c_str(), rows.size());
  return Failures ? 1 : 0;
}
