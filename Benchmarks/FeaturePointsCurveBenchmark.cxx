// Feature curves (vtkFeatureCurveExtraction after the default detector, both at their defaults)
// against the exact curves of the generated parts (vtkFeatureModelSource, output port 1):
// - precision: the share of the polylines' length (sampled every s / 4) within 2 s of a true
//   curve; recall: the share of the true curves' length within 2 s of a polyline; F1;
// - polylines per true curve: the polylines that reach the scored region over the true curves
//   that do (a curve broken into pieces, and a false piece, count against it);
// - mean distance from the polylines to the true curves, over the samples within 2 s, in s;
// - the detector's crease points (FeatureType convex or concave) in the scored region: their
//   median distance to the true curves, and that of the same points moved by CreaseOffset onto
//   the line their voters agree on, in s.
// s is the clean cloud's mean spacing. The paper's models and the ribs are pieces cut from larger
// sheets (Model III's cylinder a tube): their cut edges are borders of the cloud, not features,
// so the region within 5 s of a cut is not scored (as in FeaturePointsQualityBenchmark).
// With --check, figures are compared with floors (a little beyond the worst measured at --scale 0.1
// and 0.3 when they were set): every part at sigma = 0.5 s and clean, and the clean parts with
// features denser and the plate 1 s thick held to the targets; the program fails when quality is
// lost.
#include "FeaturePointsBenchmarkFigures.h"
#include "FeaturePointsBenchmarkLines.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkPointData.h"
#include "vtkCreaseVotingFeatures.h"
#include "vtkFeatureCurveExtraction.h"
#include "vtkFeatureModelSource.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStaticPointLocator.h"
#include "vtkXMLPolyDataReader.h"
#include "vtkXMLPolyDataWriter.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>
#include <sys/stat.h>
#include <vector>

namespace
{
using namespace fpbench;
bool verbose = false;
std::string cacheDir; // --cache: the detector's outputs, kept between runs

// The scored region: all but the 5 s next to the cut edges of the sheets and Model III's tube.
struct Region
{
  double HalfSide = VTK_DOUBLE_MAX;
  double HalfHeight = VTK_DOUBLE_MAX;
  bool Contains(const double x[3]) const
  {
    return std::abs(x[0]) <= this->HalfSide && std::abs(x[1]) <= this->HalfSide &&
      std::abs(x[2]) <= this->HalfHeight;
  }
};

Region ScoredRegion(int model, double size, double s)
{
  Region r;
  if (model == vtkFeatureModelSource::MODEL_I || model == vtkFeatureModelSource::MODEL_II ||
    model == vtkFeatureModelSource::MODEL_III || model == vtkFeatureModelSource::PARALLEL_CREASES)
  {
    r.HalfSide = 0.5 * size - 5.0 * s;
  }
  if (model == vtkFeatureModelSource::MODEL_III)
  {
    r.HalfHeight = 0.25 * size - 5.0 * s;
  }
  return r;
}

struct Scores
{
  double Precision = 0, Recall = 0, F1 = 0, PerCurve = 0, MeanDistance = 0;
  int Polylines = 0, TrueCurves = 0;
  // The crease points' median distance to the true curves, as found and moved by CreaseOffset
  // (in s; negative: no crease point, or no offsets in a cached output).
  double PointDistance = -1, MovedDistance = -1;
};

// The median distance of the crease points of `features` in the region to the true curves, as
// they are and moved by their CreaseOffset (the true curves sampled every s / 16: within s / 32).
void CreasePointDistances(vtkPolyData* features, vtkPolyData* truth, const Region& region,
  double s, Scores& r)
{
  vtkDataArray* types = features->GetPointData()->GetArray("FeatureType");
  vtkDataArray* mask = features->GetPointData()->GetArray("FeatureMask");
  vtkDataArray* offsets = features->GetPointData()->GetArray("CreaseOffset");
  if (!types || !mask || !offsets || offsets->GetNumberOfComponents() != 3)
  {
    return;
  }
  std::vector<std::array<double, 3>> t;
  std::vector<int> owner;
  SampleLines(truth, s / 16.0, t, owner);
  const NearestSample toTruth(t);
  std::vector<double> found, moved;
  for (vtkIdType i = 0; i < features->GetNumberOfPoints(); ++i)
  {
    const double type = types->GetTuple1(i);
    if (mask->GetTuple1(i) == 0.0 || (type != vtkCreaseVotingFeatures::CONVEX &&
                                        type != vtkCreaseVotingFeatures::CONCAVE))
    {
      continue;
    }
    std::array<double, 3> x, v;
    features->GetPoint(i, x.data());
    if (!region.Contains(x.data()))
    {
      continue;
    }
    offsets->GetTuple(i, v.data());
    found.push_back(toTruth.Distance(x) / s);
    for (int c = 0; c < 3; ++c)
    {
      x[c] += v[c];
    }
    moved.push_back(toTruth.Distance(x) / s);
  }
  if (found.empty())
  {
    return;
  }
  const size_t middle = found.size() / 2;
  std::nth_element(found.begin(), found.begin() + middle, found.end());
  std::nth_element(moved.begin(), moved.begin() + middle, moved.end());
  r.PointDistance = found[middle];
  r.MovedDistance = moved[middle];
}

Scores Evaluate(vtkPolyData* found, vtkPolyData* truth, const Region& region, double s)
{
  const double step = 0.25 * s;
  std::vector<std::array<double, 3>> f, t;
  std::vector<int> fOwner, tOwner;
  SampleLines(found, step, f, fOwner);
  SampleLines(truth, step, t, tOwner);
  const NearestSample toTruth(t), toFound(f);
  Scores r;
  std::vector<unsigned char> polylineIn(found->GetNumberOfCells(), 0), curveIn(truth->GetNumberOfCells(), 0);
  double scored = 0, near = 0, distance = 0;
  for (size_t k = 0; k < f.size(); ++k)
  {
    if (!region.Contains(f[k].data()))
    {
      continue;
    }
    polylineIn[fOwner[k]] = 1;
    ++scored;
    const double d = toTruth.Distance(f[k]);
    if (d <= 2.0 * s)
    {
      ++near;
      distance += d;
    }
  }
  r.Precision = scored ? near / scored : 0.0;
  r.MeanDistance = near ? distance / near / s : 0.0;
  double trueScored = 0, trueNear = 0;
  for (size_t k = 0; k < t.size(); ++k)
  {
    if (!region.Contains(t[k].data()))
    {
      continue;
    }
    curveIn[tOwner[k]] = 1;
    ++trueScored;
    trueNear += toFound.Distance(t[k]) <= 2.0 * s;
  }
  r.Recall = trueScored ? trueNear / trueScored : 0.0;
  r.F1 = r.Precision + r.Recall > 0 ? 2 * r.Precision * r.Recall / (r.Precision + r.Recall) : 0.0;
  if (verbose)
  {
    // Each polyline in the scored region: its ends, its length and its samples' mean distance.
    std::vector<double> length(polylineIn.size(), 0.0), sum(polylineIn.size(), 0.0);
    std::vector<int> count(polylineIn.size(), 0);
    for (size_t k = 0; k < f.size(); ++k)
    {
      sum[fOwner[k]] += toTruth.Distance(f[k]) / s;
      ++count[fOwner[k]];
    }
    // Each true curve: the mean offset of the polylines' samples near it (a bias across a
    // straight curve) against their mean distance (bias and scatter together).
    std::vector<std::array<double, 3>> offset(curveIn.size(), { 0.0, 0.0, 0.0 });
    std::vector<double> offsetDistance(curveIn.size(), 0.0);
    std::vector<int> offsetCount(curveIn.size(), 0);
    for (size_t k = 0; k < f.size(); ++k)
    {
      const vtkIdType j = toTruth.Closest(f[k]);
      if (!region.Contains(f[k].data()) || j < 0)
      {
        continue;
      }
      const double d = std::sqrt(vtkMath::Distance2BetweenPoints(f[k].data(), t[j].data()));
      if (d > 2.0 * s)
      {
        continue;
      }
      const int c = tOwner[j];
      for (int i = 0; i < 3; ++i)
      {
        offset[c][i] += (f[k][i] - t[j][i]) / s;
      }
      offsetDistance[c] += d / s;
      ++offsetCount[c];
    }
    for (size_t c = 0; c < curveIn.size(); ++c)
    {
      if (offsetCount[c])
      {
        const double m = offsetCount[c];
        std::printf("    true curve %zu: mean offset (%.2f %.2f %.2f) s, |mean offset| %.2f s, "
                    "mean distance %.2f s\n",
          c, offset[c][0] / m, offset[c][1] / m, offset[c][2] / m,
          std::sqrt(offset[c][0] * offset[c][0] + offset[c][1] * offset[c][1] +
            offset[c][2] * offset[c][2]) / m,
          offsetDistance[c] / m);
      }
    }
    for (vtkIdType c = 0; c < found->GetNumberOfCells(); ++c)
    {
      if (!polylineIn[c])
      {
        continue;
      }
      vtkNew<vtkIdList> ids;
      found->GetCellPoints(c, ids);
      double a[3], b[3];
      found->GetPoint(ids->GetId(0), a);
      found->GetPoint(ids->GetId(ids->GetNumberOfIds() - 1), b);
      std::printf("    line %lld: %lld vertices, (%.2f %.2f %.2f) - (%.2f %.2f %.2f), mean "
                  "distance %.2f s\n",
        static_cast<long long>(c), static_cast<long long>(ids->GetNumberOfIds()), a[0], a[1], a[2],
        b[0], b[1], b[2], count[c] ? sum[c] / count[c] : 0.0);
    }
  }
  r.Polylines = static_cast<int>(std::count(polylineIn.begin(), polylineIn.end(), 1));
  r.TrueCurves = static_cast<int>(std::count(curveIn.begin(), curveIn.end(), 1));
  r.PerCurve = r.TrueCurves ? static_cast<double>(r.Polylines) / r.TrueCurves : 0.0;
  return r;
}

struct Case
{
  int Model;
  vtkIdType Points;
  double Density, Noise, Separation;
};

// Runs one case, prints its row and returns its scores.
Scores Run(const Case& c, double& seconds)
{
  vtkNew<vtkFeatureModelSource> source;
  source->SetModel(c.Model);
  source->SetNumberOfPoints(c.Points);
  source->SetFeatureDensityFactor(c.Density);
  source->SetNoiseFactor(c.Noise);
  source->SetFeatureSeparation(c.Separation);
  source->Update();
  vtkPolyData* cloud = source->GetOutput();
  const double s = cloud->GetFieldData()->GetArray("CleanMeanSpacing")->GetTuple1(0);
  // The detector's output, from the cache when it holds this case.
  vtkSmartPointer<vtkPolyData> features;
  const std::string cached = cacheDir.empty()
    ? std::string()
    : cacheDir + "/curves-" + std::to_string(c.Model) + "-" + std::to_string(c.Points) + "-" +
      std::to_string(c.Density) + "-" + std::to_string(c.Noise) + "-" +
      std::to_string(c.Separation) + ".vtp";
  if (!cached.empty())
  {
    if (FILE* f = std::fopen(cached.c_str(), "rb"))
    {
      std::fclose(f);
      vtkNew<vtkXMLPolyDataReader> reader;
      reader->SetFileName(cached.c_str());
      reader->Update();
      features = reader->GetOutput();
    }
  }
  if (!features || features->GetNumberOfPoints() != cloud->GetNumberOfPoints())
  {
    vtkNew<vtkCreaseVotingFeatures> detector;
    detector->SetInputData(cloud);
    detector->CreaseOffsetsOn(); // read by CreasePointDistances only
    detector->Update();
    features = detector->GetOutput();
    if (!cached.empty())
    {
      vtkNew<vtkXMLPolyDataWriter> writer;
      writer->SetFileName(cached.c_str());
      writer->SetInputData(features);
      writer->SetDataModeToBinary();
      writer->Write();
    }
  }
  vtkNew<vtkFeatureCurveExtraction> curves;
  curves->SetInputData(features);
  const auto start = std::chrono::steady_clock::now();
  curves->Update();
  seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const Region region = ScoredRegion(c.Model, source->GetSize(), s);
  Scores r = Evaluate(curves->GetCurves(), source->GetFeatureCurves(), region, s);
  CreasePointDistances(features, source->GetFeatureCurves(), region, s, r);
  return r;
}

void PrintRow(const std::string& name, const Case& c, const Scores& r, double seconds)
{
  char points[32] = "    -     -";
  if (r.PointDistance >= 0.0)
  {
    std::snprintf(points, sizeof(points), "%5.2f %5.2f", r.PointDistance, r.MovedDistance);
  }
  std::printf(
    "%-24s %-8s %5.2f %7lld | %5.3f %5.3f %5.3f | %3d / %3d = %4.2f | %5.2f | %5.2f | %s\n",
    name.c_str(), c.Density > 1.0 ? "denser" : "uniform", c.Noise,
    static_cast<long long>(c.Points), r.Precision, r.Recall, r.F1, r.Polylines, r.TrueCurves,
    r.PerCurve, r.MeanDistance, seconds, points);
}

// The rows besides sigma = 0.5 s that meet the targets: the clean parts with features denser, the
// plate 1 s thick and the parallel creases 8 s apart (F1 0.995 and 0.997, one polyline per crease
// at --scale 0.1 and 0.3; 1.25 and 1.50 when the traces ran through the unvoted points between
// the creases). The clean uniform parts have floors of their own; the other real-part rows are
// printed only.
bool HeldToTargets(const Case& c)
{
  if (c.Noise == 0.0)
  {
    return c.Density > 1.0;
  }
  return (c.Model == vtkFeatureModelSource::THIN_PLATE && c.Separation == 0.5) ||
    (c.Model == vtkFeatureModelSource::PARALLEL_CREASES && c.Separation == 4.0);
}

void Header()
{
  std::printf("%-24s %-8s %5s %7s | %5s %5s %5s | %-15s | %5s | %5s | %5s %5s\n", "case",
    "features", "sigma", "points", "P", "R", "F1", "lines / true", "dist", "s", "pts", "moved");
}

} // namespace

int main(int argc, char* argv[])
{
  double scale = 0.3;
  vtkIdType large = 200000;
  std::string only;
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if (a == "--scale" && i + 1 < argc)
    {
      scale = std::atof(argv[++i]);
    }
    else if (a == "--check")
    {
      CheckFigures = true;
    }
    else if (a == "--verbose")
    {
      verbose = true;
    }
    else if (a == "--points" && i + 1 < argc)
    {
      large = std::atoll(argv[++i]);
    }
    else if (a == "--cache" && i + 1 < argc)
    {
      cacheDir = argv[++i];
    }
    else if (a == "--only" && i + 1 < argc)
    {
      only = argv[++i];
    }
    else
    {
      std::printf("usage: %s [--scale F] [--points N] [--check] [--verbose] [--only NAME] "
                  "[--cache DIR]\n"
                  "  --scale F    fraction of the models' default point counts (default 0.3)\n"
                  "  --points N   the section of large parts at sigma 0.5 s: N points (default\n"
                  "               200000; 0 leaves it out)\n"
                  "  --check      compare the figures with their floors (set at --scale 0.1 and 0.3)\n"
                  "  --verbose    list each polyline of the scored region, and per true curve the\n"
                  "               polylines' mean offset from it (a bias) and mean distance\n"
                  "  --only NAME  run the cases whose name contains NAME\n"
                  "  --cache DIR  keep the detector's outputs in DIR (an existing folder) and read\n"
                  "               them back in later runs: for work on the curve filter alone\n",
        argv[0]);
      return a == "--help" || a == "-h" ? EXIT_SUCCESS : EXIT_FAILURE;
    }
  }
  if (!(scale > 0.0 && scale <= 10.0))
  {
    std::fprintf(stderr, "error: --scale must lie in (0, 10]\n");
    return EXIT_FAILURE;
  }
  if (large < 0 || large > 100000000)
  {
    std::fprintf(stderr, "error: --points must lie in [0, 100000000]\n");
    return EXIT_FAILURE;
  }
  struct stat folder;
  if (!cacheDir.empty() && (::stat(cacheDir.c_str(), &folder) != 0 || !S_ISDIR(folder.st_mode)))
  {
    std::fprintf(stderr, "error: --cache %s: no such folder\n", cacheDir.c_str());
    return EXIT_FAILURE;
  }
  std::printf("FeaturePoints: feature curves against the exact curves, default parameters\n"
              "P, R, F1 within 2 s; lines / true: polylines per true curve; dist: mean distance "
              "polyline -> true curve (samples within 2 s), in s; s: seconds of the curve filter;\n"
              "pts, moved: median distance of the crease points to the true curves, and of the same "
              "points moved by CreaseOffset, in s\n"
              "targets: F1 >= 0.95, lines / true <= 1.2, dist <= 0.5 at sigma 0.5 s\n\n");
  const int parts[] = { vtkFeatureModelSource::MODEL_I, vtkFeatureModelSource::MODEL_II,
    vtkFeatureModelSource::MODEL_III, vtkFeatureModelSource::BOX, vtkFeatureModelSource::CYLINDER,
    vtkFeatureModelSource::BRACKET };
  std::vector<double> f1s, perCurve, distances;
  auto scaled = [&](int model, double fraction) {
    return static_cast<vtkIdType>(std::llround(
      fraction * static_cast<double>(vtkFeatureModelSource::GetDefaultNumberOfPoints(model))));
  };
  auto runSection = [&](const std::vector<std::pair<std::string, Case>>& cases) {
    Header();
    for (const auto& entry : cases)
    {
      if (!only.empty() && entry.first.find(only) == std::string::npos)
      {
        continue;
      }
      double seconds = 0.0;
      const Scores r = Run(entry.second, seconds);
      PrintRow(entry.first, entry.second, r, seconds);
      f1s.push_back(r.F1);
      perCurve.push_back(r.PerCurve);
      const std::string row = entry.first + (entry.second.Density > 1.0 ? " denser " : " uniform ") +
        std::to_string(entry.second.Points) + " sigma " + std::to_string(entry.second.Noise);
      // Every part has crease points: a missing figure fails (as infinity), unless the outputs
      // come from a cache, which may have been written without the offsets.
      const double moved = r.MovedDistance >= 0.0 || !cacheDir.empty()
        ? r.MovedDistance
        : std::numeric_limits<double>::infinity();
      if (entry.second.Noise == 0.5)
      {
        distances.push_back(r.MeanDistance);
        // The parts at sigma = 0.5 s: floors a little beyond the worst row measured at --scale
        // 0.1 and 0.3 and at 200,000 points (F1 0.963, 1.67 lines per true curve, 0.52 s). At
        // 200,000 points every part meets the target (1.2 lines per true curve): Model II with
        // uniform features has 8 polylines for its 7 curves (one link along the crop edge); its
        // ninth, one of the 15 degree creases broken where the detector misses 20 s of it, went
        // when the bridge's bend test measured on the wider section too (0.181 against 3 errors,
        // 0.186, on the narrow one). Below 200,000 points the worst is one piece more than Model
        // I's three curves (1.33, at --scale 0.1).
        Floor(row + " F1", r.F1, 0.94);
        Ceiling(row + " lines per true curve", r.PerCurve, entry.second.Points > 100000 ? 1.2 : 1.8);
        Ceiling(row + " mean distance (s)", r.MeanDistance, 0.56);
        // The crease points moved onto their voters' line: at most 0.23 s from the true curves
        // (median) at --scale 0.1 and 0.3 and 200,000 points, where they lie 1.24-1.39 s away.
        Ceiling(row + " crease points moved (s)", moved, 0.3);
      }
      else if (HeldToTargets(entry.second))
      {
        // Rows that meet the targets at --scale 0.1 and 0.3 (worst: F1 0.977, 1.08 lines per
        // true curve) are held to them.
        Floor(row + " F1", r.F1, 0.95);
        Ceiling(row + " lines per true curve", r.PerCurve, 1.2);
      }
      else if (entry.second.Model == vtkFeatureModelSource::PARALLEL_CREASES &&
        entry.second.Separation == 2.5)
      {
        // Creases 5 s apart, their bands one strip, traced on the points moved onto their
        // voters' lines, each trace on its own line where they lie side by side: F1 0.861 and
        // 0.863 at --scale 0.1 and 0.3 (0.771 and 0.791 with every trace on the strip's middle,
        // 0.402 and 0.422 traced on the ridges of the score).
        Floor(row + " F1", r.F1, 0.80);
      }
      else if (entry.second.Model == vtkFeatureModelSource::PARALLEL_CREASES &&
        entry.second.Separation == 1.5)
      {
        // Creases 3 s apart: F1 0.548 and 0.614 at --scale 0.1 and 0.3 (0.485 and 0.505 before
        // the lines side by side were traced apart).
        Floor(row + " F1", r.F1, 0.50);
      }
      else if (entry.second.Model == vtkFeatureModelSource::THIN_PLATE &&
        entry.second.Separation == 1.5)
      {
        // The plate 3 s thick, each rim face's two edges traced apart: F1 0.823 and 0.848 at
        // --scale 0.1 and 0.3 (0.752 and 0.747 with one polyline between them).
        Floor(row + " F1", r.F1, 0.77);
      }
      else if (entry.second.Noise == 0.0)
      {
        // The clean uniform parts: the detector's false points beside the creases still break
        // some curves (worst at --scale 0.1 and 0.3: F1 0.968, 1.71 lines per true curve on Model
        // II, and Model III's one circle in 2 pieces at 13,000 points).
        Floor(row + " F1", r.F1, 0.95);
        Ceiling(row + " lines per true curve", r.PerCurve, 2.0);
      }
      if (entry.second.Noise == 0.0)
      {
        // Clean, moved: at most 0.04 s at --scale 0.1 and 0.3, where they lie 0.97-1.21 s away.
        Ceiling(row + " crease points moved (s)", moved, 0.08);
      }
    }
  };

  std::printf("1. Parts at %.2f x their default point counts, sigma = 0.5 s and clean\n", scale);
  std::vector<std::pair<std::string, Case>> cases;
  for (int model : parts)
  {
    for (double noise : { 0.5, 0.0 })
    {
      for (double density : { 3.0, 1.0 })
      {
        cases.push_back({ vtkFeatureModelSource::GetModelName(model),
          { model, scaled(model, scale), density, noise, 5.0 } });
      }
    }
  }
  runSection(cases);

  std::printf("\n2. Parts at 7,000 points, sigma = 0.5 s\n");
  cases.clear();
  for (int model : parts)
  {
    for (double density : { 3.0, 1.0 })
    {
      cases.push_back(
        { vtkFeatureModelSource::GetModelName(model), { model, 7000, density, 0.5, 5.0 } });
    }
  }
  runSection(cases);

  if (large > 0)
  {
    std::printf("\n3. Parts at %lld points, sigma = 0.5 s\n", static_cast<long long>(large));
    cases.clear();
    for (int model : parts)
    {
      for (double density : { 3.0, 1.0 })
      {
        cases.push_back(
          { vtkFeatureModelSource::GetModelName(model), { model, large, density, 0.5, 5.0 } });
      }
    }
    runSection(cases);
  }

  std::printf("\n4. Real-part situations, uniform, sigma = 0.25 s\n");
  cases.clear();
  const vtkIdType count = static_cast<vtkIdType>(std::llround(scale * 100000.0));
  for (const double apart : { 3.0, 5.0, 8.0 })
  {
    cases.push_back({ "Parallel creases " + std::to_string(int(apart)) + " s",
      { vtkFeatureModelSource::PARALLEL_CREASES, count, 1.0, 0.25, 0.5 * apart } });
  }
  for (const double thick : { 1.0, 3.0 })
  {
    cases.push_back({ "Thin plate " + std::to_string(int(thick)) + " s",
      { vtkFeatureModelSource::THIN_PLATE, count, 1.0, 0.25, 0.5 * thick } });
  }
  cases.push_back({ "Half cylinder", { vtkFeatureModelSource::HALF_CYLINDER, count, 1.0, 0.25, 5.0 } });
  cases.push_back(
    { "Plate with hole", { vtkFeatureModelSource::PLATE_WITH_HOLE, count, 1.0, 0.25, 5.0 } });
  runSection(cases);

  if (f1s.empty())
  {
    return Failures ? EXIT_FAILURE : EXIT_SUCCESS;
  }
  std::printf("\nall rows: F1 lowest %.3f, median %.3f; lines / true highest %.2f, median %.2f",
    *std::min_element(f1s.begin(), f1s.end()), Median(f1s),
    *std::max_element(perCurve.begin(), perCurve.end()), Median(perCurve));
  if (!distances.empty()) // none when --only picks no row at sigma 0.5 s
  {
    std::printf("; dist at sigma 0.5 s highest %.2f, median %.2f",
      *std::max_element(distances.begin(), distances.end()), Median(distances));
  }
  std::printf("\n");
  if (CheckFigures)
  {
    std::printf("\n%s: %d figure(s) past their floor\n", Failures ? "FAILED" : "passed", Failures);
  }
  return Failures ? EXIT_FAILURE : EXIT_SUCCESS;
}
