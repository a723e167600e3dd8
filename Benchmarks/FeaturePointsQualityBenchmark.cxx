// Held-out quality with default parameters, for the project's default detector
// (vtkCreaseVotingFeatures, "Crease") beside the paper's method as published
// (vtkFeaturePointExtraction, "Huang2023"), each at its own defaults, no per-cloud tuning:
// - CAD-like parts (vtkFeatureModelSource: Models I-III, Box, Cylinder, Bracket) with features
//   sampled 3x denser and uniformly, sigma = 0.5 s: precision, recall, F1 (docs/evaluation.md).
// - Smooth shapes (Sphere, Blob, Torus, Ellipsoid) at sigma = 0, 0.25 s, 0.5 s: false detections
//   per 1000 points, at the scaled point counts and at 7,000 points.
// - PCEDNet's labelled clouds (coordinates only): MCC per cloud, median per folder and overall.
// - Invariance: Model I (denser and uniform) scaled by 1000, moved by 10^6 and shuffled: share of
//   points whose mask changes.
// - Non-uniform sampling: the parts thinned to a density falling from 1 to 0.2 across x: F1.
// - The parts at sigma = 0 and 0.25 s, and at 7,000 points with sigma = 0, 0.25 s, 0.5 s: F1.
// - Real-part situations: parallel creases 3, 5 and 8 s apart, thin plates 0.5, 1 and 3 s thick,
//   open surfaces (borders), the parts at 20,000 points, sigma = 0.25 s: F1 and the share of the
//   true corner and border points typed so; Box and Bracket at the configurations of sections 1
//   and 6: the share of their true corner points typed so.
// With --check, every figure is compared with a floor (a little below the figure measured when the
// floor was set) and the program fails when quality is lost.
#include "FeaturePointsBenchmarkFigures.h"

#include "vtkCreaseVotingFeatures.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFeatureModelSource.h"
#include "vtkFeaturePointEvaluation.h"
#include "vtkFeaturePointExtraction.h"
#include "vtkFieldData.h"
#include "vtkPLYReader.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <map>
#include <random>
#include <string>
#include <tuple>
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
    { "Crease", [] { return vtkSmartPointer<vtkCreaseVotingFeatures>::New(); } },
    { "Huang2023", [] { return vtkSmartPointer<vtkFeaturePointExtraction>::New(); } },
  };
}

// Measured on the five test clouds: 0.391 (band; the open sheets of default/ lose their
// unlabelled borders' points: TwoPlane90 0.613 without borders, 0.243 with) and 0.842 (thin).
constexpr double PcednetFloor = 0.32;
constexpr double PcednetThinFloor = 0.80;

// Floors of the default detector ("Crease") at --scale 0.3, set from the figures measured when
// this benchmark was written, a little below them.
// The paper's models and the parallel creases are square sheets cut from a larger surface (and
// Model III's cylinder a tube cut at z = +-0.25 Size): their outer edges are crops, not features
// of the ground truth, but borders of the cloud, which the default detector marks (FeatureType
// BORDER) by design. Points within CropMargin s of a crop are not scored: the field array
// "ScoredHalfSide" holds the half side of the scored square and the half height of the scored
// tube.
constexpr double CropMargin = 5.0;
void MarkCropMargin(vtkPolyData* cloud, int model, double size)
{
  if (model != vtkFeatureModelSource::MODEL_I && model != vtkFeatureModelSource::MODEL_II &&
    model != vtkFeatureModelSource::MODEL_III && model != vtkFeatureModelSource::PARALLEL_CREASES)
  {
    return;
  }
  const double s = cloud->GetFieldData()->GetArray("CleanMeanSpacing")->GetTuple1(0);
  vtkNew<vtkDoubleArray> half;
  half->SetName("ScoredHalfSide");
  half->InsertNextValue(0.5 * size - CropMargin * s);
  half->InsertNextValue(
    model == vtkFeatureModelSource::MODEL_III ? 0.25 * size - CropMargin * s : VTK_DOUBLE_MAX);
  cloud->GetFieldData()->AddArray(half);
}

// The mask and the FeatureDistance of the scored points (see MarkCropMargin).
void ScoredArrays(vtkPolyData* cloud, vtkDataArray* mask, vtkDataArray* distance,
  vtkSmartPointer<vtkDataArray>& scoredMask, vtkSmartPointer<vtkDataArray>& scoredDistance)
{
  scoredMask = mask;
  scoredDistance = distance;
  auto half = vtkDoubleArray::SafeDownCast(cloud->GetFieldData()->GetArray("ScoredHalfSide"));
  if (!half)
  {
    return;
  }
  const double h = half->GetValue(0), z = half->GetValue(1);
  scoredMask = vtkSmartPointer<vtkDataArray>::Take(mask->NewInstance());
  scoredDistance = vtkSmartPointer<vtkDataArray>::Take(distance->NewInstance());
  for (vtkIdType i = 0; i < cloud->GetNumberOfPoints(); ++i)
  {
    double x[3];
    cloud->GetPoint(i, x);
    if (std::abs(x[0]) <= h && std::abs(x[1]) <= h && std::abs(x[2]) <= z)
    {
      scoredMask->InsertNextTuple1(mask->GetTuple1(i));
      scoredDistance->InsertNextTuple1(distance->GetTuple1(i));
    }
  }
}

vtkSmartPointer<vtkPolyData> Model(int model, double scale, double density, double noise)
{
  vtkNew<vtkFeatureModelSource> source;
  source->SetModel(model);
  // Rounded, not truncated: 7000 / 220000 * 220000 is 6999.999... in floating point.
  source->SetNumberOfPoints(static_cast<vtkIdType>(std::llround(
    scale * static_cast<double>(vtkFeatureModelSource::GetDefaultNumberOfPoints(model)))));
  source->SetFeatureDensityFactor(density);
  source->SetNoiseFactor(noise);
  source->Update();
  vtkSmartPointer<vtkPolyData> cloud = source->GetOutput();
  MarkCropMargin(cloud, model, source->GetSize());
  return cloud;
}

// Non-uniform sampling: each point kept with a probability falling linearly from 1 at the
// smallest x to keep at the largest, with its point data (FeatureDistance).
vtkSmartPointer<vtkPolyData> ThinAlongX(vtkPolyData* cloud, double keep, unsigned seed)
{
  double bounds[6];
  cloud->GetBounds(bounds);
  const double width = bounds[1] > bounds[0] ? bounds[1] - bounds[0] : 1.0;
  std::mt19937 random(seed);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  auto thinned = vtkSmartPointer<vtkPolyData>::New();
  thinned->GetPointData()->CopyAllocate(cloud->GetPointData());
  for (vtkIdType i = 0; i < cloud->GetNumberOfPoints(); ++i)
  {
    double x[3];
    cloud->GetPoint(i, x);
    const double t = (x[0] - bounds[0]) / width;
    // The generator's raw output, so that the result is the same with every standard library.
    const double u = static_cast<double>(random()) / 4294967296.0;
    if (u < 1.0 - (1.0 - keep) * t)
    {
      thinned->GetPointData()->CopyData(cloud->GetPointData(), i, points->InsertNextPoint(x));
    }
  }
  thinned->SetPoints(points);
  thinned->GetFieldData()->ShallowCopy(cloud->GetFieldData());
  return thinned;
}

vtkDataArray* Mask(vtkFeaturePointDetector* filter, vtkPolyData* input)
{
  filter->SetInputData(input);
  filter->Update();
  return filter->GetOutput()->GetPointData()->GetArray("FeatureMask");
}

// Runs one method on a synthetic cloud, prints " P / R / F1 |" (after the method's name when
// `named`) and returns F1; s is the clean mean spacing of docs/evaluation.md's bands.
double PrintScores(const Method& method, vtkPolyData* cloud, double s, bool named)
{
  auto filter = method.Make();
  vtkNew<vtkFeaturePointEvaluation> evaluation;
  vtkSmartPointer<vtkDataArray> mask, distance;
  ScoredArrays(
    cloud, Mask(filter, cloud), cloud->GetPointData()->GetArray("FeatureDistance"), mask, distance);
  evaluation->EvaluateDistances(mask, distance, s);
  std::printf(" %s%s%.3f / %.3f / %.3f |", named ? method.Name : "", named ? " " : "",
    evaluation->GetPrecision(), evaluation->GetRecall(), evaluation->GetF1());
  return evaluation->GetF1();
}

void Usage(const char* name)
{
  std::printf("usage: %s [--scale F] [--pcednet DIR] [--section N] [--check]\n"
              "  --scale F      fraction of the models' default point counts (default 0.3)\n"
              "  --pcednet DIR  folder searched recursively for PCEDNet's labelled .ply files\n"
              "                 (default: %s)\n"
              "  --section N    run only section N (1-7); may be repeated (default: all)\n"
              "  --check        compare the default detector's figures with their floors; exit 1\n"
              "                 when one is below (floors are set for --scale 0.3 and, for PCEDNet,\n"
              "                 the five clouds of Filters/Testing/Data/pcednet, as the CTest runs it)\n",
    name, FEATUREPOINTS_PCEDNET_DIR);
}
} // namespace

int main(int argc, char* argv[])
{
  double scale = 0.3;
  std::string pcednet = FEATUREPOINTS_PCEDNET_DIR;
  std::vector<int> sections;
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if (a == "--scale" && i + 1 < argc)
    {
      scale = std::atof(argv[++i]);
    }
    else if (a == "--pcednet" && i + 1 < argc)
    {
      pcednet = argv[++i];
    }
    else if (a == "--section" && i + 1 < argc)
    {
      const int section = std::atoi(argv[++i]);
      if (section < 1 || section > 7)
      {
        std::fprintf(stderr, "error: --section must be 1 to 7\n");
        return EXIT_FAILURE;
      }
      sections.push_back(section);
    }
    else if (a == "--check")
    {
      CheckFigures = true;
    }
    else
    {
      Usage(argv[0]);
      return a == "--help" || a == "-h" ? EXIT_SUCCESS : EXIT_FAILURE;
    }
  }
  if (!(scale > 0.0 && scale <= 10.0))
  {
    std::fprintf(stderr, "error: --scale must lie in (0, 10]\n");
    return EXIT_FAILURE;
  }
  const auto methods = Methods();
  auto wanted = [&](int section) {
    return sections.empty() ||
      std::find(sections.begin(), sections.end(), section) != sections.end();
  };
  std::printf("FeaturePoints: held-out quality with default parameters\n"
              "models at %.2f x their default point counts; Crease = vtkCreaseVotingFeatures "
              "(the default), Huang2023 = vtkFeaturePointExtraction (the paper)\n\n",
    scale);

  // Floors of the default detector's F1, denser then uniform.
  const std::map<int, std::pair<double, double>> f1Floors = {
    { vtkFeatureModelSource::MODEL_I, { 0.97, 0.96 } },
    { vtkFeatureModelSource::MODEL_II, { 0.95, 0.94 } },
    { vtkFeatureModelSource::MODEL_III, { 0.96, 0.96 } },
    { vtkFeatureModelSource::BOX, { 0.96, 0.95 } },
    { vtkFeatureModelSource::CYLINDER, { 0.95, 0.97 } },
    { vtkFeatureModelSource::BRACKET, { 0.96, 0.95 } },
  };

  // 1. CAD-like parts, sigma = 0.5 s.
  if (wanted(1))
  {
    std::printf("1. Parts, sigma = 0.5 s: precision / recall / F1 (target: F1 >= 0.90 each)\n");
    std::printf("%-10s %-8s %7s |", "model", "features", "points");
    for (const auto& m : methods)
    {
      std::printf(" %-22s|", m.Name);
    }
    std::printf("\n");
    std::vector<double> partF1;
    for (const auto& entry : f1Floors)
    {
      for (double density : { 3.0, 1.0 })
      {
        auto cloud = Model(entry.first, scale, density, 0.5);
        const double s = cloud->GetFieldData()->GetArray("CleanMeanSpacing")->GetTuple1(0);
        std::printf("%-10s %-8s %7lld |", vtkFeatureModelSource::GetModelName(entry.first),
          density > 1.0 ? "denser" : "uniform", static_cast<long long>(cloud->GetNumberOfPoints()));
        for (const auto& m : methods)
        {
          const double f1 = PrintScores(m, cloud, s, false);
          if (m.Name == methods[0].Name)
          {
            partF1.push_back(f1);
            Floor(std::string(vtkFeatureModelSource::GetModelName(entry.first)) +
                (density > 1.0 ? " denser F1" : " uniform F1"),
              f1, density > 1.0 ? entry.second.first : entry.second.second);
          }
        }
        std::printf("\n");
      }
    }
    std::printf("Crease: lowest F1 %.3f, median %.3f\n\n",
      *std::min_element(partF1.begin(), partF1.end()), Median(partF1));
  }

  // 2. Smooth shapes.
  if (wanted(2))
  {
    std::printf("2. Smooth shapes: false detections per 1000 points (target: <= 2)\n");
    std::printf("%-10s %-6s %7s |", "shape", "sigma", "points");
    for (const auto& m : methods)
    {
      std::printf(" %9s |", m.Name);
    }
    std::printf("\n");
    // The same shapes at the models' scaled point counts and at 7,000 points, the smallest size
    // the quality targets name: there a 150-point neighbourhood spans a third of the sphere's radius. Every
    // row is checked against the target.
    for (const bool small : { false, true })
    {
      for (int model : { vtkFeatureModelSource::SPHERE, vtkFeatureModelSource::BLOB,
             vtkFeatureModelSource::TORUS, vtkFeatureModelSource::ELLIPSOID })
      {
        for (double noise : { 0.0, 0.25, 0.5 })
        {
          const double fraction = small
            ? 7000.0 / static_cast<double>(vtkFeatureModelSource::GetDefaultNumberOfPoints(model))
            : scale;
          auto cloud = Model(model, fraction, 1.0, noise);
          std::printf("%-10s %-6.2f %7lld |", vtkFeatureModelSource::GetModelName(model), noise,
            static_cast<long long>(cloud->GetNumberOfPoints()));
          for (const auto& m : methods)
          {
            auto filter = m.Make();
            vtkDataArray* mask = Mask(filter, cloud);
            double detections = 0.0;
            for (vtkIdType i = 0; i < mask->GetNumberOfTuples(); ++i)
            {
              detections += mask->GetComponent(i, 0) != 0.0;
            }
            const double perThousand = 1000.0 * detections / cloud->GetNumberOfPoints();
            std::printf(" %9.2f |", perThousand);
            if (m.Name == methods[0].Name)
            {
              Ceiling(std::string(vtkFeatureModelSource::GetModelName(model)) + " false per 1000" +
                  (small ? " at 7000 points" : ""),
                perThousand, 2.0);
            }
          }
          std::printf("\n");
        }
      }
    }
    std::printf("\n");
  }

  // 3. PCEDNet.
  if (wanted(3))
  {
    std::vector<std::string> files;
    std::error_code error;
    if (std::filesystem::is_directory(pcednet, error))
    {
      for (const auto& entry : std::filesystem::recursive_directory_iterator(pcednet, error))
      {
        if (entry.is_regular_file() && entry.path().extension() == ".ply")
        {
          files.push_back(entry.path().string());
        }
      }
    }
    std::sort(files.begin(), files.end());
    std::printf("3. PCEDNet's labelled clouds under %s: MCC per cloud (target: median >= 0.75 "
                "with Thin)\n   Thin = the default detector with ThinFeatures on (--thin): "
                "PCEDNet labels the row of points nearest each edge\n",
      pcednet.c_str());
    std::vector<Method> pcednetMethods = methods;
    pcednetMethods.insert(pcednetMethods.begin() + 1, { "Thin", [] {
      auto thin = vtkSmartPointer<vtkCreaseVotingFeatures>::New();
      thin->ThinFeaturesOn();
      return vtkSmartPointer<vtkFeaturePointDetector>(thin);
    } });
    std::map<std::string, std::vector<double>> mcc; // method -> values
    // PCEDNet's folders (abc, abc_noise_0.04, default): method -> values, per folder and over the
    // ABC models with and without noise (the targets are medians over each of those sets).
    std::map<std::string, std::map<std::string, std::vector<double>>> groups;
    for (const auto& file : files)
    {
      vtkNew<vtkPLYReader> reader;
      reader->SetFileName(file.c_str());
      reader->Update();
      vtkPolyData* data = reader->GetOutput();
      auto labels = vtkFeaturePointEvaluation::LabelsFromColors(data->GetPointData()->GetScalars());
      if (!labels || data->GetNumberOfPoints() == 0)
      {
        std::fprintf(stderr, "error: %s: no points or no colour labels\n", file.c_str());
        ++Failures;
        continue;
      }
      vtkNew<vtkPolyData> coordinates; // the detectors get the coordinates only
      coordinates->SetPoints(data->GetPoints());
      std::printf("%-34s", std::filesystem::relative(file, pcednet).string().c_str());
      for (const auto& m : pcednetMethods)
      {
        auto filter = m.Make();
        vtkNew<vtkFeaturePointEvaluation> evaluation;
        evaluation->EvaluateLabels(Mask(filter, coordinates), labels);
        mcc[m.Name].push_back(evaluation->GetMCC());
        const std::string folder = std::filesystem::relative(file, pcednet).begin()->string();
        groups[folder][m.Name].push_back(evaluation->GetMCC());
        if (folder.rfind("abc", 0) == 0)
        {
          groups["abc*"][m.Name].push_back(evaluation->GetMCC());
        }
        std::printf(" %s %.3f", m.Name, evaluation->GetMCC());
      }
      std::printf("\n");
    }
    if (!files.empty())
    {
      std::printf("median MCC over %zu clouds:", files.size());
      for (const auto& m : pcednetMethods)
      {
        std::printf(" %s %.3f", m.Name, Median(mcc[m.Name]));
      }
      std::printf("\n");
      for (auto& group : groups)
      {
        if (group.second[methods[0].Name].size() == files.size())
        {
          continue; // one folder only: the line above
        }
        std::printf("median MCC over %s (%zu):", group.first.c_str(),
          group.second[methods[0].Name].size());
        for (const auto& m : pcednetMethods)
        {
          std::printf(" %s %.3f", m.Name, Median(group.second[m.Name]));
        }
        std::printf("\n");
      }
      // The floors are set for the five clouds of the project's test data (Filters/Testing/Data).
      Floor("PCEDNet median MCC", Median(mcc[methods[0].Name]), PcednetFloor);
      Floor("PCEDNet median MCC, thin", Median(mcc["Thin"]), PcednetThinFloor);
    }
    std::printf("\n");
  }

  // 4. Invariance.
  if (wanted(4))
  {
    std::printf("4. Invariance: Model I scaled by 1000, moved by 10^6 and shuffled\n");
    // Denser features exercise the voxel pre-filter and the threshold's background sample of the
    // paper's method; uniform sampling, its fallback to scoring every point.
    for (const double density : { 3.0, 1.0 })
    {
      auto cloud = Model(vtkFeatureModelSource::MODEL_I, scale, density, 0.5);
      const vtkIdType n = cloud->GetNumberOfPoints();
      std::vector<vtkIdType> order(static_cast<size_t>(n));
      for (vtkIdType i = 0; i < n; ++i)
      {
        order[i] = i;
      }
      std::mt19937 random(7);
      for (vtkIdType i = n - 1; i > 0; --i) // Fisher-Yates with the generator's raw output
      {
        std::swap(order[i], order[random() % static_cast<unsigned>(i + 1)]);
      }
      vtkNew<vtkPoints> moved;
      moved->SetDataTypeToDouble();
      moved->SetNumberOfPoints(n);
      for (vtkIdType i = 0; i < n; ++i)
      {
        double x[3];
        cloud->GetPoint(order[i], x);
        moved->SetPoint(i, 1000.0 * x[0] + 1e6, 1000.0 * x[1] - 1e6, 1000.0 * x[2] + 1e6);
      }
      vtkNew<vtkPolyData> transformed;
      transformed->SetPoints(moved);
      for (const auto& m : methods)
      {
        auto a = m.Make();
        auto b = m.Make();
        vtkDataArray* original = Mask(a, cloud);
        vtkDataArray* changed = Mask(b, transformed);
        vtkIdType differ = 0;
        for (vtkIdType i = 0; i < n; ++i)
        {
          differ += (original->GetComponent(order[i], 0) != 0.0) != (changed->GetComponent(i, 0) != 0.0);
        }
        const double share = 100.0 * differ / n;
        std::printf("%-10s %-8s %lld of %lld points change (%.3f%%)\n", m.Name,
          density > 1.0 ? "denser" : "uniform", static_cast<long long>(differ),
          static_cast<long long>(n), share);
        const std::string label = std::string(m.Name) + " mask change under scale/offset/shuffle (" +
          (density > 1.0 ? "denser" : "uniform") + "), %";
        Ceiling(label, share, 0.1);
      }
    }
  }

  // 5. Non-uniform sampling.
  if (wanted(5))
  {
    std::printf("\n5. Non-uniform sampling: the parts with uniform features, each point kept with a "
                "probability falling\n   linearly from 1 to 0.2 along x (sigma = 0.5 s of the full "
                "cloud; s, and the bands, as before thinning): P / R / F1\n");
    const std::map<int, double> thinFloors = {
      { vtkFeatureModelSource::MODEL_I, 0.98 },
      { vtkFeatureModelSource::MODEL_II, 0.96 },
      { vtkFeatureModelSource::MODEL_III, 0.97 }, // 0.977
      { vtkFeatureModelSource::BOX, 0.96 },
      { vtkFeatureModelSource::CYLINDER, 0.98 },
      { vtkFeatureModelSource::BRACKET, 0.95 },
    };
    for (const auto& entry : thinFloors)
    {
      auto full = Model(entry.first, scale, 1.0, 0.5);
      const double s = full->GetFieldData()->GetArray("CleanMeanSpacing")->GetTuple1(0);
      auto cloud = ThinAlongX(full, 0.2, 11);
      std::printf("%-10s %7lld of %7lld |", vtkFeatureModelSource::GetModelName(entry.first),
        static_cast<long long>(cloud->GetNumberOfPoints()),
        static_cast<long long>(full->GetNumberOfPoints()));
      for (const auto& m : methods)
      {
        const double f1 = PrintScores(m, cloud, s, true);
        if (m.Name == methods[0].Name)
        {
          Floor(std::string(vtkFeatureModelSource::GetModelName(entry.first)) + " thinned F1", f1,
            entry.second);
        }
      }
      std::printf("\n");
    }
  }
  // 6. Other noise levels and the smallest size.
  if (wanted(6))
  {
    std::printf("\n6. Parts at the other noise levels (sigma = 0 and 0.25 s) and at 7,000 points "
                "(sigma = 0, 0.25 s, 0.5 s):\n   precision / recall / F1 (target: F1 >= 0.90 each)\n");
    std::printf("%-10s %-8s %5s %7s |", "model", "features", "sigma", "points");
    for (const auto& m : methods)
    {
      std::printf(" %-22s|", m.Name);
    }
    std::printf("\n");
    // Floors of the default detector's F1 where the target is missed: a little below the figure
    // measured when the floor was set; elsewhere the target itself.
    // Key: model, features denser, sigma, at 7,000 points.
    const std::map<std::tuple<int, bool, double, bool>, double> sweepFloors = {
      { { vtkFeatureModelSource::MODEL_II, false, 0.5, true }, 0.87 }, // 0.889
    };
    std::vector<double> sweepF1;
    for (const bool small : { false, true })
    {
      for (const auto& entry : f1Floors)
      {
        for (double density : { 3.0, 1.0 })
        {
          for (double noise : { 0.0, 0.25, 0.5 })
          {
            if (!small && noise == 0.5)
            {
              continue; // section 1
            }
            const double defaultCount =
              static_cast<double>(vtkFeatureModelSource::GetDefaultNumberOfPoints(entry.first));
            const double fraction = small ? 7000.0 / defaultCount : scale;
            auto cloud = Model(entry.first, fraction, density, noise);
            const double s = cloud->GetFieldData()->GetArray("CleanMeanSpacing")->GetTuple1(0);
            std::printf("%-10s %-8s %5.2f %7lld |", vtkFeatureModelSource::GetModelName(entry.first),
              density > 1.0 ? "denser" : "uniform", noise,
              static_cast<long long>(cloud->GetNumberOfPoints()));
            for (const auto& m : methods)
            {
              const double f1 = PrintScores(m, cloud, s, false);
              if (m.Name == methods[0].Name)
              {
                sweepF1.push_back(f1);
                const auto floor = sweepFloors.find({ entry.first, density > 1.0, noise, small });
                Floor(std::string(vtkFeatureModelSource::GetModelName(entry.first)) +
                    (density > 1.0 ? " denser" : " uniform") + " sigma " +
                    std::to_string(noise).substr(0, 4) + (small ? " at 7000 points" : "") + " F1",
                  f1, floor != sweepFloors.end() ? floor->second : 0.90);
              }
            }
            std::printf("\n");
          }
        }
      }
    }
    std::printf("Crease: lowest F1 %.3f, median %.3f\n",
      *std::min_element(sweepF1.begin(), sweepF1.end()), Median(sweepF1));
  }

  // 7. Real-part situations.
  if (wanted(7))
  {
    std::printf("\n7. Real-part situations, sigma = 0.25 s, default detector: P / R / F1 and the share of "
                "the true\n   corner and border points typed so (target: F1 >= 0.90, typed >= 0.90)\n");
    std::printf("%-26s %7s | %-22s| %-7s | %-7s\n", "case", "points", "P / R / F1", "corner",
      "border");
    std::vector<double> caseF1;
    // Floors where the target is missed, a little below the figure measured when they were set;
    // elsewhere the target itself.
    const std::map<std::string, double> caseFloors = {
      { "Parallel creases 3 s apart F1", 0.88 }, // 0.909
      { "Parallel creases 5 s apart F1", 0.92 }, // 0.950
    };
    auto caseFloor = [&](const std::string& what) {
      const auto found = caseFloors.find(what);
      return found != caseFloors.end() ? found->second : 0.90;
    };
    auto runCase = [&](const std::string& name, vtkPolyData* cloud) {
      const double s = cloud->GetFieldData()->GetArray("CleanMeanSpacing")->GetTuple1(0);
      std::printf("%-26s %7lld |", name.c_str(), static_cast<long long>(cloud->GetNumberOfPoints()));
      auto filter = vtkSmartPointer<vtkCreaseVotingFeatures>::New();
      const double f1 = PrintScores({ "Crease", [&] { return filter; } }, cloud, s, false);
      caseF1.push_back(f1);
      Floor(name + " F1", f1, caseFloor(name + " F1"));
      vtkDataArray* truth = cloud->GetPointData()->GetArray("GroundTruthType");
      vtkDataArray* found = filter->GetOutput()->GetPointData()->GetArray("FeatureType");
      for (const int type : { vtkCreaseVotingFeatures::CORNER, vtkCreaseVotingFeatures::BORDER })
      {
        double total = 0.0, typed = 0.0;
        for (vtkIdType i = 0; i < cloud->GetNumberOfPoints(); ++i)
        {
          if (truth->GetTuple1(i) == type)
          {
            ++total;
            typed += found->GetTuple1(i) == type;
          }
        }
        if (total > 0.0)
        {
          std::printf(" %7.3f |", typed / total);
          const std::string what =
            name + (type == vtkCreaseVotingFeatures::CORNER ? " corners" : " borders") + " typed";
          Floor(what, typed / total, caseFloor(what));
        }
        else
        {
          std::printf(" %7s |", "-");
        }
      }
      std::printf("\n");
    };
    const vtkIdType caseCount = static_cast<vtkIdType>(std::llround(scale * 100000.0));
    auto makeCase = [&](int model, double separation, vtkIdType count) {
      vtkNew<vtkFeatureModelSource> source;
      source->SetModel(model);
      source->SetNumberOfPoints(count);
      source->SetFeatureDensityFactor(1.0);
      source->SetNoiseFactor(0.25);
      source->SetFeatureSeparation(separation);
      source->Update();
      vtkSmartPointer<vtkPolyData> cloud = source->GetOutput();
      MarkCropMargin(cloud, model, source->GetSize());
      return cloud;
    };
    // FeatureSeparation is in nominal spacings sqrt(area / points); the mean spacing s of a
    // Poisson sampling of a plane is half of that: x s apart is x / 2 nominal spacings.
    for (const double apart : { 3.0, 5.0, 8.0 })
    {
      runCase("Parallel creases " + std::to_string(int(apart)) + " s apart",
        makeCase(vtkFeatureModelSource::PARALLEL_CREASES, 0.5 * apart, caseCount));
    }
    for (const double thick : { 0.5, 1.0, 3.0 })
    {
      runCase("Thin plate " + std::to_string(thick).substr(0, 3) + " s thick",
        makeCase(vtkFeatureModelSource::THIN_PLATE, 0.5 * thick, caseCount));
    }
    runCase("Half cylinder (open)", makeCase(vtkFeatureModelSource::HALF_CYLINDER, 5.0, caseCount));
    runCase("Plate with hole (open)",
      makeCase(vtkFeatureModelSource::PLATE_WITH_HOLE, 5.0, caseCount));
    for (const auto& entry : f1Floors)
    {
      runCase(std::string(vtkFeatureModelSource::GetModelName(entry.first)) + " at 20,000",
        makeCase(entry.first, 5.0, 20000));
    }
    std::printf("Crease: lowest F1 %.3f, median %.3f\n",
      *std::min_element(caseF1.begin(), caseF1.end()), Median(caseF1));

    // The parts with corners at the configurations of sections 1 and 6: the share of their true
    // corner points typed CORNER, and of their true crease points typed CORNER (the corner zone
    // spilling along the creases).
    std::printf("\nCorner typing on the parts of sections 1 and 6: the share of the true corner "
                "points typed corner,\n   and of the true crease points typed corner\n");
    std::printf("%-10s %-8s %5s %7s | %-7s | %-7s\n", "model", "features", "sigma", "points",
      "corner", "crease");
    // Floors, a little below the figures measured when they were set (Box: 1.000 in every row).
    // Key: model, features denser, sigma, at 7,000 points.
    const std::map<std::tuple<int, bool, double, bool>, double> cornerFloors = {
      { { vtkFeatureModelSource::BRACKET, true, 0.0, false }, 0.90 },   // 0.936
      { { vtkFeatureModelSource::BRACKET, true, 0.25, false }, 0.85 },  // 0.897
      { { vtkFeatureModelSource::BRACKET, true, 0.5, false }, 0.82 },   // 0.872
      { { vtkFeatureModelSource::BRACKET, false, 0.5, false }, 0.83 },  // 0.884
      { { vtkFeatureModelSource::BRACKET, true, 0.25, true }, 0.78 },   // 0.830
      { { vtkFeatureModelSource::BRACKET, true, 0.5, true }, 0.75 },    // 0.809
      { { vtkFeatureModelSource::BRACKET, false, 0.25, true }, 0.70 },  // 0.725
      { { vtkFeatureModelSource::BRACKET, false, 0.5, true }, 0.75 },   // 0.800
    };
    for (const int model : { vtkFeatureModelSource::BOX, vtkFeatureModelSource::BRACKET })
    {
      for (const bool small : { false, true })
      {
        for (double density : { 3.0, 1.0 })
        {
          for (double noise : { 0.0, 0.25, 0.5 })
          {
            const double fraction = small
              ? 7000.0 / static_cast<double>(vtkFeatureModelSource::GetDefaultNumberOfPoints(model))
              : scale;
            auto cloud = Model(model, fraction, density, noise);
            auto filter = vtkSmartPointer<vtkCreaseVotingFeatures>::New();
            filter->SetInputData(cloud);
            filter->Update();
            vtkDataArray* truth = cloud->GetPointData()->GetArray("GroundTruthType");
            vtkDataArray* found = filter->GetOutput()->GetPointData()->GetArray("FeatureType");
            double corners = 0.0, cornersTyped = 0.0, creases = 0.0, creasesTyped = 0.0;
            for (vtkIdType i = 0; i < cloud->GetNumberOfPoints(); ++i)
            {
              const int t = static_cast<int>(truth->GetTuple1(i));
              const bool typed = found->GetTuple1(i) == vtkCreaseVotingFeatures::CORNER;
              if (t == vtkCreaseVotingFeatures::CORNER)
              {
                ++corners;
                cornersTyped += typed;
              }
              else if (t == vtkCreaseVotingFeatures::CONVEX ||
                t == vtkCreaseVotingFeatures::CONCAVE)
              {
                ++creases;
                creasesTyped += typed;
              }
            }
            const double share = corners > 0.0 ? cornersTyped / corners : 0.0;
            std::printf("%-10s %-8s %5.2f %7lld | %7.3f | %7.3f\n",
              vtkFeatureModelSource::GetModelName(model), density > 1.0 ? "denser" : "uniform",
              noise, static_cast<long long>(cloud->GetNumberOfPoints()), share,
              creases > 0.0 ? creasesTyped / creases : 0.0);
            const auto floor = cornerFloors.find({ model, density > 1.0, noise, small });
            Floor(std::string(vtkFeatureModelSource::GetModelName(model)) +
                (density > 1.0 ? " denser" : " uniform") + " sigma " +
                std::to_string(noise).substr(0, 4) + (small ? " at 7000 points" : "") +
                " corners typed",
              share, floor != cornerFloors.end() ? floor->second : 0.90);
          }
        }
      }
    }
  }
  if (CheckFigures)
  {
    std::printf("\n%s: %d figure(s) below their floor\n", Failures ? "FAILED" : "passed", Failures);
  }
  return Failures ? EXIT_FAILURE : EXIT_SUCCESS;
}
