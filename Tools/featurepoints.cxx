// featurepoints: feature points (sharp edges, creases, corners) of a point cloud file, from the
// shell. Reads PLY, VTP, VTU, legacy VTK, PTS, XYZ/TXT, CSV, PCD or LAS; runs the project's
// default detector (crease: two-plane crease fits and a neighbourhood vote), the paper's method
// (huang2023: Huang et al. 2023) or one of its baselines; writes the cloud with its scores and
// FeatureMask as VTP, VTK, PLY, CSV or PCD; optionally renders a picture offscreen.
// `featurepoints --help` lists every option.
//
// Exit codes: 0 success; 1 bad input or failure (one line naming the file and the problem);
// 2 bad usage. A failed run leaves no output file behind and the input is never overwritten.
#include "vtkActor.h"
#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkCreaseVotingFeatures.h"
#include "vtkCurvatureDensityFeatures.h"
#include "vtkDoubleArray.h"
#include "vtkErrorCode.h"
#include "vtkFeatureCurveExtraction.h"
#include "vtkFeaturePointExtraction.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkLogger.h"
#include "vtkLookupTable.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkOutputWindow.h"
#include "vtkPNGWriter.h"
#include "vtkPointCloudIO.h"
#include "vtkPointCloudPLYReader.h"
#include "vtkPointCloudReader.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSMPTools.h"
#include "vtkScalarBarActor.h"
#include "vtkSmoothShrinkIndexFeatures.h"
#include "vtkStaticPointLocator.h"
#include "vtkSurfaceVariationFeatures.h"
#include "vtkTextActor.h"
#include "vtkTextProperty.h"
#include "vtkUnsignedCharArray.h"
#include "vtkVersion.h"
#include "vtkWindowToImageFilter.h"
#include "vtksys/SystemTools.hxx"

#include "featurepointsLines.h"

#ifdef FEATUREPOINTS_HAVE_MPI
#include "vtkDistributedFeaturePoints.h"
#include "vtkMPI.h"
#include "vtkMPIController.h"
#include "vtkXMLPPolyDataWriter.h"
#include "vtkMultiProcessController.h"
#endif

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <iomanip>
#include <map>
#include <sstream>
#include <string>
#include <thread>
#include <unistd.h> // isatty, and _exit in the signal handler (async-signal-safe)
#include <numeric>
#include <vector>

#ifndef FEATUREPOINTS_VERSION
#define FEATUREPOINTS_VERSION "unknown"
#endif

namespace
{
constexpr int ExitSuccess = 0;
constexpr int ExitFailure = 1;
constexpr int ExitUsage = 2;

// The length, in the input's units, of one unit of the frame the method ran in (1 unless
// ScaledFrame scaled the cloud).
double LengthUnit = 1.0;

using Clock = std::chrono::steady_clock;
double Seconds(Clock::time_point since)
{
  return std::chrono::duration<double>(Clock::now() - since).count();
}

// ---------------------------------------------------------------------------------------------
// Methods and their options

// The method run when --method is not given.
constexpr const char* DefaultMethod = "crease";

struct Method
{
  const char* Name;
  const char* Description;
  std::function<vtkSmartPointer<vtkFeaturePointDetector>()> Create;
  // Optional, for the summary: what the method adds to its "method" line (after the mean
  // spacing), and the score above which points grown from the feature points join them after
  // the threshold (hysteresis; NaN when the run grew nothing).
  std::function<std::string(vtkFeaturePointDetector*)> Details = nullptr;
  std::function<double(vtkFeaturePointDetector*)> GrowThreshold = nullptr;
  // Whether the output's FeatureType array holds vtkCreaseVotingFeatures::FeatureTypes: the
  // summary then counts the feature points of each type.
  bool FeatureTypes = false;
};

vtkCreaseVotingFeatures* Crease(vtkFeaturePointDetector* f)
{
  return vtkCreaseVotingFeatures::SafeDownCast(f);
}

const std::vector<Method>& Methods()
{
  static const std::vector<Method> methods = {
    { "crease",
      "the default: two-plane crease fits and a neighbourhood vote; score CreaseVotes, the "
      "fraction of the neighbourhood whose fitted crease line passes near the point; a feature "
      "point has a majority (> 0.5), then the features grow through points above "
      "--grow-threshold plus the cloud's median vote, and the points no fit explains "
      "(details finer than the smallest scale, corners) and open borders join them; array "
      "FeatureType: 1 convex crease, 2 concave crease, 3 corner, 4 border, 0 no feature",
      [] { return vtkSmartPointer<vtkCreaseVotingFeatures>::New(); },
      [](vtkFeaturePointDetector* f) {
        std::ostringstream s;
        s << ", noise sigma " << std::setprecision(6) << Crease(f)->GetNoiseSigma() * LengthUnit;
        return s.str();
      },
      [](vtkFeaturePointDetector* f) {
        // The filter grows the features only when GrowThreshold plus the median vote is below
        // the threshold used.
        return Crease(f)->GetGrowThresholdUsed() < f->GetThresholdUsed()
          ? Crease(f)->GetGrowThresholdUsed()
          : std::nan("");
      },
      true },
    { "huang2023",
      "the proposed method: SSI and PDI mixed into F, voxel density pre-filter (Huang, Chen, "
      "Zhang, Lu 2023)",
      [] { return vtkSmartPointer<vtkFeaturePointExtraction>::New(); } },
    { "ssi", "baseline: Smooth Shrink Index alone (Nie 2016), score F = SSI / spacing",
      [] { return vtkSmartPointer<vtkSmoothShrinkIndexFeatures>::New(); } },
    { "pca", "baseline: PCA surface variation lambda0 / (lambda0 + lambda1 + lambda2)",
      [] { return vtkSmartPointer<vtkSurfaceVariationFeatures>::New(); } },
    { "wang-yuan", "baseline: curvature, normal angle and density (Wang & Yuan, as the paper "
                   "describes it)",
      [] { return vtkSmartPointer<vtkCurvatureDensityFeatures>::New(); } },
  };
  return methods;
}

const Method* FindMethod(const std::string& name)
{
  for (const Method& m : Methods())
  {
    if (name == m.Name)
    {
      return &m;
    }
  }
  return nullptr;
}

// A numeric or keyword option of a filter, or a flag. `Methods` lists the methods it applies to
// (empty: all). A flag takes no value: given, it calls Apply(filter, 1); its Default is 1 when the
// filter already behaves so without it (printed "on", else "off").
struct FilterOption
{
  const char* Name;
  const char* Metavar;
  std::vector<std::string> Methods;
  double Min, Max;
  bool Integer;
  std::map<std::string, int> Keywords; // for keyword options: word -> value
  std::function<void(vtkFeaturePointDetector*, double)> Apply;
  std::function<double(vtkFeaturePointDetector*)> Default; // NaN: no number ("automatic")
  const char* Help;
  bool Flag = false;
};

vtkFeaturePointExtraction* Extraction(vtkFeaturePointDetector* f)
{
  return vtkFeaturePointExtraction::SafeDownCast(f);
}
vtkSurfaceVariationFeatures* Variation(vtkFeaturePointDetector* f)
{
  return vtkSurfaceVariationFeatures::SafeDownCast(f);
}
vtkCurvatureDensityFeatures* CurvatureDensity(vtkFeaturePointDetector* f)
{
  return vtkCurvatureDensityFeatures::SafeDownCast(f);
}

const std::vector<FilterOption>& FilterOptions()
{
  const std::vector<std::string> ours = { "huang2023", "ssi" };
  static const std::vector<FilterOption> options = {
    { "threshold-sigmas", "Z", {}, 0.0, 1000.0, false, {},
      [](vtkFeaturePointDetector* f, double v) {
        f->SetThresholdModeToAutomatic(); // crease thresholds its votes absolutely by default
        f->SetThresholdSigmas(v);
      },
      [](vtkFeaturePointDetector* f) { return f->GetThresholdSigmas(); },
      "automatic threshold: median score + Z robust standard deviations (the default rule of "
      "every method but crease)" },
    { "threshold", "VALUE", {}, -1e300, 1e300, false, {},
      [](vtkFeaturePointDetector* f, double v) {
        f->SetThresholdModeToAbsolute();
        f->SetThreshold(v);
      },
      [](vtkFeaturePointDetector* f) {
        return f->GetThresholdMode() == vtkFeaturePointDetector::ABSOLUTE ? f->GetThreshold()
                                                                          : std::nan("");
      },
      "absolute threshold on the method's score instead of the automatic one" },
    { "alpha", "A", ours, 0.0, 1.0, false, {},
      [](vtkFeaturePointDetector* f, double v) { Extraction(f)->SetAlpha(v); },
      [](vtkFeaturePointDetector* f) { return Extraction(f)->GetAlpha(); },
      "alpha of Eq. 1, weight of the SSI term against the density term" },
    { "normal-k", "K", { "huang2023", "ssi", "crease" }, 3, 1000, true, {},
      [](vtkFeaturePointDetector* f, double v) {
        if (Extraction(f))
        {
          Extraction(f)->SetNormalNeighbors(int(v));
        }
        else
        {
          Crease(f)->SetNormalNeighbors(int(v));
        }
      },
      [](vtkFeaturePointDetector* f) {
        return double(Extraction(f) ? Extraction(f)->GetNormalNeighbors()
                                    : Crease(f)->GetNormalNeighbors());
      },
      "neighbours of the PCA normal (Eq. 3; crease: the normals that seed its two-plane "
      "split)" },
    { "ssi-k", "K", ours, 1, 1000, true, {},
      [](vtkFeaturePointDetector* f, double v) { Extraction(f)->SetSSINeighbors(int(v)); },
      [](vtkFeaturePointDetector* f) { return double(Extraction(f)->GetSSINeighbors()); },
      "neighbours of the SSI's weighted centroid (Eq. 4)" },
    { "density-k", "K", ours, 1, 1000, true, {},
      [](vtkFeaturePointDetector* f, double v) { Extraction(f)->SetDensityNeighbors(int(v)); },
      [](vtkFeaturePointDetector* f) { return double(Extraction(f)->GetDensityNeighbors()); },
      "neighbours of the mean distance and density index (Eqs. 7, 9)" },
    { "center-k", "K", ours, 0, 1000, true, {},
      [](vtkFeaturePointDetector* f, double v) { Extraction(f)->SetCenterNeighbors(int(v)); },
      [](vtkFeaturePointDetector* f) { return double(Extraction(f)->GetCenterNeighbors()); },
      "neighbours of the density-weighted centre (Eq. 6)" },
    { "ssi-center", "mean|point", ours, 0, 1, true,
      { { "point", vtkFeaturePointExtraction::POINT },
        { "mean", vtkFeaturePointExtraction::DENSITY_WEIGHTED_MEAN } },
      [](vtkFeaturePointDetector* f, double v) { Extraction(f)->SetSSICenter(int(v)); },
      [](vtkFeaturePointDetector* f) { return double(Extraction(f)->GetSSICenter()); },
      "SSI measured from the density-weighted mean (Eq. 6) or the point (Eq. 2)" },
    { "gaussian-radius", "R", ours, 0.01, 1000.0, false, {},
      [](vtkFeaturePointDetector* f, double v) { Extraction(f)->SetGaussianRadiusFactor(v); },
      [](vtkFeaturePointDetector* f) { return Extraction(f)->GetGaussianRadiusFactor(); },
      "r of Eq. 5, in mean spacings" },
    { "voxel-filter", "on|off", ours, 0, 1, true, { { "on", 1 }, { "off", 0 } },
      [](vtkFeaturePointDetector* f, double v) { Extraction(f)->SetUseVoxelFilter(v != 0); },
      [](vtkFeaturePointDetector* f) { return double(Extraction(f)->GetUseVoxelFilter()); },
      "score only the voxel pre-filter's candidates (Section 3.2)" },
    { "voxel-size", "BETA", ours, 0.1, 1000.0, false, {},
      [](vtkFeaturePointDetector* f, double v) { Extraction(f)->SetVoxelSizeFactor(v); },
      [](vtkFeaturePointDetector* f) { return Extraction(f)->GetVoxelSizeFactor(); },
      "beta of Eq. 11: voxel side in mean spacings" },
    { "density-contrast", "EPS", ours, 0.0, 1e300, false, {},
      [](vtkFeaturePointDetector* f, double v) { Extraction(f)->SetDensityContrast(v); },
      [](vtkFeaturePointDetector* f) { return Extraction(f)->GetDensityContrast(); },
      "epsilon of the voxel pre-filter: relative density excess of a candidate voxel" },
    { "voxel-rule", "spacing|counts", ours, 0, 1, true,
      { { "counts", 0 }, { "spacing", 1 } },
      [](vtkFeaturePointDetector* f, double v) { Extraction(f)->SetVoxelContrastRule(int(v)); },
      [](vtkFeaturePointDetector* f) { return double(Extraction(f)->GetVoxelContrastRule()); },
      "what the pre-filter compares: block spacing, or the paper's voxel counts" },
    { "k", "K", { "pca", "wang-yuan" }, 3, 1000, true, {},
      [](vtkFeaturePointDetector* f, double v) {
        if (Variation(f))
        {
          Variation(f)->SetNumberOfNeighbors(int(v));
        }
        else
        {
          CurvatureDensity(f)->SetNumberOfNeighbors(int(v));
        }
      },
      [](vtkFeaturePointDetector* f) {
        return double(Variation(f) ? Variation(f)->GetNumberOfNeighbors()
                                   : CurvatureDensity(f)->GetNumberOfNeighbors());
      },
      "neighbours of the baseline's local analysis" },
    { "curvature-weight", "W", { "wang-yuan" }, 0.0, 1000.0, false, {},
      [](vtkFeaturePointDetector* f, double v) { CurvatureDensity(f)->SetCurvatureWeight(v); },
      [](vtkFeaturePointDetector* f) { return CurvatureDensity(f)->GetCurvatureWeight(); },
      "weight of the curvature indicator" },
    { "normal-angle-weight", "W", { "wang-yuan" }, 0.0, 1000.0, false, {},
      [](vtkFeaturePointDetector* f, double v) { CurvatureDensity(f)->SetNormalAngleWeight(v); },
      [](vtkFeaturePointDetector* f) { return CurvatureDensity(f)->GetNormalAngleWeight(); },
      "weight of the normal angle indicator" },
    { "density-weight", "W", { "wang-yuan" }, 0.0, 1000.0, false, {},
      [](vtkFeaturePointDetector* f, double v) { CurvatureDensity(f)->SetDensityWeight(v); },
      [](vtkFeaturePointDetector* f) { return CurvatureDensity(f)->GetDensityWeight(); },
      "weight of the density indicator" },
    { "crease-k", "K", { "crease" }, 8, 1000, true, {},
      [](vtkFeaturePointDetector* f, double v) { Crease(f)->SetNumberOfNeighbors(int(v)); },
      [](vtkFeaturePointDetector* f) { return double(Crease(f)->GetNumberOfNeighbors()); },
      "neighbours of each two-plane fit and of each vote" },
    { "band-width", "D", { "crease" }, 0.01, 1000.0, false, {},
      [](vtkFeaturePointDetector* f, double v) { Crease(f)->SetBandWidth(v); },
      [](vtkFeaturePointDetector* f) { return Crease(f)->GetBandWidth(); },
      "how far from a fitted crease line a point still counts as on it, in mean spacings "
      "(widened by twice the noise, in quadrature)" },
    { "min-angle", "DEGREES", { "crease" }, 0.0, 90.0, false, {},
      [](vtkFeaturePointDetector* f, double v) { Crease(f)->SetMinimumAngle(v); },
      [](vtkFeaturePointDetector* f) { return Crease(f)->GetMinimumAngle(); },
      "smallest bend that counts as a crease: a fit whose two planes meet at a smaller angle "
      "casts no vote" },
    { "grow-threshold", "V", { "crease" }, 0.0, 1.0, false, {},
      [](vtkFeaturePointDetector* f, double v) { Crease(f)->SetGrowThreshold(v); },
      [](vtkFeaturePointDetector* f) { return Crease(f)->GetGrowThreshold(); },
      "hysteresis: a point with more than V of the votes joins the feature points it is "
      "connected to through such points (off at or above the threshold)" },
    { "thin", "", { "crease" }, 0, 1, true, { { "off", 0 }, { "on", 1 } },
      [](vtkFeaturePointDetector* f, double) { Crease(f)->ThinFeaturesOn(); },
      [](vtkFeaturePointDetector* f) { return double(Crease(f)->GetThinFeatures()); },
      "one point wide: only the points within half a spacing of each crease (widened by the "
      "noise), across each border the outermost row (without it, a band about twice "
      "--band-width spacings wide)",
      true },
    { "no-borders", "", { "crease" }, 0, 1, true, { { "off", 0 }, { "on", 1 } },
      [](vtkFeaturePointDetector* f, double) { Crease(f)->BordersOff(); },
      [](vtkFeaturePointDetector* f) { return double(!Crease(f)->GetBorders()); },
      "open borders (a scan's edge, a hole, the edge of a sheet, the rim of a thin wall) are not "
      "feature points (without it they are, of type border)", true },
    { "single-scale", "", { "crease" }, 0, 1, true, { { "off", 0 }, { "on", 1 } },
      [](vtkFeaturePointDetector* f, double) { Crease(f)->MultiScaleOff(); },
      [](vtkFeaturePointDetector* f) { return double(!Crease(f)->GetMultiScale()); },
      "every fit and vote uses --crease-k neighbours (without it, where the hinge does not "
      "explain a point's neighbourhood, that point's neighbourhood is halved, down to 20 points)",
      true },
    { "keep-copies", "", { "crease" }, 0, 1, true, { { "off", 0 }, { "on", 1 } },
      [](vtkFeaturePointDetector* f, double) { Crease(f)->MergeCopiesOff(); },
      [](vtkFeaturePointDetector* f) { return double(!Crease(f)->GetMergeCopies()); },
      "score copies as separate points (without it, where at least 1 % of the points lie within "
      "1 % of a point's distance to its 8th nearest of another point, the detector scores the "
      "distinct positions and each copy takes its position's results; mpiexec runs always keep "
      "them)",
      true },
    { "keep-outliers", "", { "crease" }, 0, 1, true, { { "off", 0 }, { "on", 1 } },
      [](vtkFeaturePointDetector* f, double) { Crease(f)->RemoveOutliersOff(); },
      [](vtkFeaturePointDetector* f) { return double(!Crease(f)->GetRemoveOutliers()); },
      "score every point (without it, a point more than 12 standard errors off the plane of "
      "its 15 nearest or of its nearest point's, or isolated with no surface holding it, is an "
      "outlier: left out, 0 in every array)",
      true },
    { "crease-offsets", "", { "crease" }, 0, 1, true, { { "off", 0 }, { "on", 1 } },
      [](vtkFeaturePointDetector* f, double) { Crease(f)->CreaseOffsetsOn(); },
      [](vtkFeaturePointDetector* f) { return double(Crease(f)->GetCreaseOffsets()); },
      "adds the array CreaseOffset: from each point to the crease line that the lines voting for "
      "it agree on (the point plus it lies on the crease; 0 where no line votes); --lines turns "
      "it on for the curves' vertices",
      true },
  };
  return options;
}

const FilterOption* FindFilterOption(const std::string& name)
{
  for (const FilterOption& o : FilterOptions())
  {
    if (name == o.Name)
    {
      return &o;
    }
  }
  return nullptr;
}

std::string FormatNumber(double v)
{
  std::ostringstream s;
  s << v;
  return s.str();
}

// The option's default for one method, from a filter made for the purpose, so that the help
// never disagrees with the library.
std::string DefaultText(const FilterOption& o, const Method& method)
{
  const double v = o.Default ? o.Default(method.Create()) : std::nan("");
  if (std::isnan(v))
  {
    return "automatic";
  }
  for (const auto& keyword : o.Keywords)
  {
    if (keyword.second == static_cast<int>(v))
    {
      return keyword.first;
    }
  }
  return FormatNumber(v);
}

// The option's default over the methods it applies to: the value most of them share, and
// "; METHOD: VALUE" for the others, if any (e.g. "automatic" and "; crease: 0.5").
std::pair<std::string, std::string> DefaultText(const FilterOption& o)
{
  std::vector<std::pair<std::string, std::vector<std::string>>> groups; // value, its methods
  for (const Method& m : Methods())
  {
    if (!o.Methods.empty() && std::find(o.Methods.begin(), o.Methods.end(), m.Name) == o.Methods.end())
    {
      continue;
    }
    const std::string text = DefaultText(o, m);
    auto group = std::find_if(groups.begin(), groups.end(),
      [&](const std::pair<std::string, std::vector<std::string>>& g) { return g.first == text; });
    if (group == groups.end())
    {
      groups.emplace_back(text, std::vector<std::string>());
      group = groups.end() - 1;
    }
    group->second.emplace_back(m.Name);
  }
  if (groups.empty())
  {
    return {};
  }
  const auto most = std::max_element(groups.begin(), groups.end(),
    [](const std::pair<std::string, std::vector<std::string>>& a,
      const std::pair<std::string, std::vector<std::string>>& b) {
      return a.second.size() < b.second.size();
    });
  std::string others;
  for (auto g = groups.begin(); g != groups.end(); ++g)
  {
    if (g == most)
    {
      continue;
    }
    std::string methods;
    for (const std::string& m : g->second)
    {
      methods += (methods.empty() ? "" : ", ") + m;
    }
    others += "; " + methods + ": " + g->first;
  }
  return { most->first, others };
}

// Prints `text` wrapped to 78 columns, every line indented by `indent` spaces.
void PrintWrapped(const std::string& text, int indent)
{
  std::istringstream words(text);
  std::string word, line;
  while (words >> word)
  {
    if (!line.empty() && indent + line.size() + 1 + word.size() > 78)
    {
      std::printf("%*s%s\n", indent, "", line.c_str());
      line.clear();
    }
    line += (line.empty() ? "" : " ") + word;
  }
  if (!line.empty())
  {
    std::printf("%*s%s\n", indent, "", line.c_str());
  }
}

void PrintHelp()
{
  std::printf(
    "Usage: featurepoints INPUT OUTPUT [options]   (default: --method %s)\n"
    "\n"
    "Finds the feature points (sharp edges, creases, corners) of a point cloud and writes the\n"
    "cloud with its scores and a FeatureMask array (1 for a feature point). The default method,\n"
    "%s, is built to work with its default parameters on any cloud; --method huang2023 runs\n"
    "the paper's method (Huang, Chen, Zhang, Lu 2023).\n"
    "\n"
    "INPUT   %s (PLY: ASCII or binary, any vertex\n"
    "        properties, faces ignored; CSV/XYZ/TXT: with or without a header line; PCD: ascii,\n"
    "        binary or binary_compressed, every field, NaN points skipped; LAS 1.0-1.4: point\n"
    "        formats 0-10, uncompressed: LAZ is not supported in this build, it has no LASzip)\n"
    "OUTPUT  %s (VTP/VTK: every array; PLY: coordinates and every\n"
    "        numeric array as vertex properties; CSV: a header line, then one line per point;\n"
    "        PCD: binary, every numeric array as a field); under mpiexec -n N also .pvtp:\n"
    "        each process writes its piece (OUTPUT_<rank>.vtp beside it, points in input\n"
    "        order, their input ids in GlobalPointIds)\n"
    "\n"
    "General options:\n"
    "  --method NAME         the method (default %s):\n",
    DefaultMethod, DefaultMethod, vtkPointCloudIO::GetReadableExtensions().c_str(),
    vtkPointCloudIO::GetWritableExtensions().c_str(), DefaultMethod);
  for (const Method& m : Methods())
  {
    std::printf("      %s\n", m.Name);
    PrintWrapped(m.Description, 10);
  }
  std::printf(
    "  --features-only       write only the feature points, with their ids in the input\n"
    "                        (array vtkOriginalPointIds)\n"
    "  --screenshot FILE.png render the result offscreen: points coloured by the score, feature\n"
    "                        points in red (Debian's VTK needs an X display: use xvfb-run -a)\n"
    "  --lines FILE          also find the feature curves (polylines through the feature\n"
    "                        points) and write them: .vtp, .vtk (cell arrays CurveId,\n"
    "                        FeatureType, CreaseAngle, Length; point array Tangent), .csv (one\n"
    "                        line per vertex: x, y, z, CurveId, Tangent) or .obj (l lines);\n"
    "                        the output gets CurveId, --screenshot draws the curves\n"
    "  --size WxH            picture size (default 1200x900; each side 16 to 8192, at most\n"
    "                        16.8 megapixels, as 4096x4096)\n"
    "  --threads N           number of threads (default: all cores)\n"
    "  --quiet               print nothing but errors\n"
    "  --help                this text\n"
    "  --version             the program's and VTK's versions\n"
    "\n"
    "Method options (default in brackets; the methods an option applies to after it):\n");
  for (const FilterOption& o : FilterOptions())
  {
    std::string methods;
    for (const std::string& m : o.Methods)
    {
      methods += (methods.empty() ? "" : ", ") + m;
    }
    std::string range;
    if (o.Keywords.empty() && o.Name != std::string("threshold"))
    {
      range = ", " + FormatNumber(o.Min) + " to " + (o.Max > 1e299 ? "any" : FormatNumber(o.Max));
    }
    if (o.Flag)
    {
      std::printf("  --%s\n", o.Name);
    }
    else
    {
      std::printf("  --%s %s\n", o.Name, o.Metavar);
    }
    const auto defaults = DefaultText(o);
    PrintWrapped(std::string(o.Help) + " [" + defaults.first + range + defaults.second + "]" +
        (methods.empty() ? "" : "; " + methods),
      8);
  }
  std::printf("\n"
              "Exit status: 0 success, 1 bad input or failure, 2 bad usage. A failed run leaves\n"
              "no output file behind; the input is never overwritten.\n");
}

// ---------------------------------------------------------------------------------------------
// Messages and progress

bool Quiet = false;
// Set when every non-finite coordinate the method sees comes from the scaled frame (see
// ScaledFrame): the method's warning about NaN or infinite coordinates is then replaced by the
// program's own, which says why.
bool FrameOverflowOnly = false;

// Under mpiexec with more than one process: the processes (nullptr otherwise), and this one's rank.
#ifdef FEATUREPOINTS_HAVE_MPI
vtkMPIController* Processes = nullptr;
#endif
int Rank = 0;

[[noreturn]] void Fail(int code, const std::string& message)
{
  std::fprintf(stderr, "featurepoints: %s\n", vtkPointCloudIO::OneLine(message).c_str());
  if (code == ExitUsage)
  {
    std::fprintf(stderr, "Try 'featurepoints --help'.\n");
  }
#ifdef FEATUREPOINTS_HAVE_MPI
  if (Processes)
  {
    // The other processes wait for this one: end them all, with this exit code.
    std::fflush(stderr);
    MPI_Abort(MPI_COMM_WORLD, code);
  }
#endif
  std::exit(code);
}

// The exit code once the summary has reached standard output: a write that failed (a full
// device, a closed descriptor) fails the run, as the output's would.
int FinishStandardOutput(int code, const std::string& output)
{
  errno = 0;
  const bool flushed = std::fflush(stdout) == 0;
  const int error = errno;
  if (flushed && !std::ferror(stdout))
  {
    return code;
  }
  std::fprintf(stderr,
    "featurepoints: standard output: cannot write the summary (%s); %s was written\n",
    !flushed && error ? std::strerror(error) : "write error",
    vtkPointCloudIO::OneLine(output).c_str());
  return code == ExitSuccess ? ExitFailure : code;
}

// The number of processes mpiexec started (Open MPI, MPICH/Hydra, PMIx), or 1.
int LaunchedProcesses()
{
  for (const char* name : { "OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE", "MPI_LOCALNRANKS" })
  {
    if (const char* value = std::getenv(name))
    {
      return std::max(1, std::atoi(value));
    }
  }
  return 1;
}

// VTK's warnings as one line each (errors are reported by the program itself).
class OneLineOutputWindow : public vtkOutputWindow
{
public:
  static OneLineOutputWindow* New();
  vtkTypeMacro(OneLineOutputWindow, vtkOutputWindow);
  void DisplayText(const char* text) override
  {
    if (!Quiet)
    {
      std::fprintf(stderr, "featurepoints: %s\n", vtkPointCloudIO::MessageText(text).c_str());
    }
  }
  void DisplayErrorText(const char* text) override
  {
    std::fprintf(stderr, "featurepoints: error: %s\n", vtkPointCloudIO::MessageText(text).c_str());
  }
  void DisplayWarningText(const char* text) override
  {
    if (FrameOverflowOnly && std::strstr(text, "have NaN or infinite coordinates"))
    {
      return; // reported by the program (the far points of a scaled frame)
    }
    if (!Quiet)
    {
      std::fprintf(
        stderr, "featurepoints: warning: %s\n", vtkPointCloudIO::MessageText(text).c_str());
    }
  }
  void DisplayGenericWarningText(const char* text) override { this->DisplayWarningText(text); }
  void DisplayDebugText(const char*) override {}
};
vtkStandardNewMacro(OneLineOutputWindow);

// A progress bar on a terminal (after the first half second), one line per stage otherwise.
class Progress : public vtkCommand
{
public:
  static Progress* New() { return new Progress; }
  void Stage(const std::string& name)
  {
    this->Finish();
    this->Name = name;
    this->Start = Clock::now();
    this->Fraction = 0.0;
    if (!Quiet && !this->Terminal)
    {
      std::fprintf(stderr, "featurepoints: %s...\n", name.c_str());
    }
  }
  void Finish()
  {
    if (this->Drawn)
    {
      std::fprintf(stderr, "\r%*s\r", 79, "");
      this->Drawn = false;
    }
  }
  void Execute(vtkObject*, unsigned long, void* callData) override
  {
    this->Fraction = *static_cast<double*>(callData);
    if (Quiet || !this->Terminal || Seconds(this->RunStart) < 0.5 ||
      std::chrono::duration<double>(Clock::now() - this->LastDraw).count() < 0.1)
    {
      return;
    }
    this->LastDraw = Clock::now();
    constexpr int width = 40;
    const int filled = static_cast<int>(std::clamp(this->Fraction, 0.0, 1.0) * width);
    std::fprintf(stderr, "\r%-14.14s [%s%s] %3d%% %6.1f s", this->Name.c_str(),
      std::string(filled, '#').c_str(), std::string(width - filled, '.').c_str(),
      static_cast<int>(100 * std::clamp(this->Fraction, 0.0, 1.0)), Seconds(this->RunStart));
    std::fflush(stderr);
    this->Drawn = true;
  }
  bool Terminal = isatty(STDERR_FILENO) != 0;
  Clock::time_point RunStart = Clock::now();

private:
  std::string Name;
  Clock::time_point Start = Clock::now();
  Clock::time_point LastDraw = Clock::now();
  double Fraction = 0.0;
  bool Drawn = false;
};

// ---------------------------------------------------------------------------------------------
// Screenshot

// Removes the run's temporary files (the output, the curves and the picture being written: see
// vtkPointCloudIO::CreateTemporaryFile), on failure and on the signals that end the program.
void RemoveTemporaries(int signal)
{
  vtkPointCloudIO::RemoveTemporaryFileInProgress();
  if (signal)
  {
    ::_exit(128 + signal);
  }
}

// Whether this VTK renders through X and no X display is set: rendering would abort the program.
bool NeedsMissingDisplay()
{
  vtkNew<vtkRenderWindow> probe;
  const std::string kind = probe->GetClassName();
  const char* display = std::getenv("DISPLAY");
  return kind.find("XOpenGL") != std::string::npos && (!display || !*display);
}

// Looks at the cloud from its thinnest side, tilted so that relief shows: the camera's direction
// mixes the principal axes of the points (most of the smallest, some of the others), its up
// vector is the longest axis. A sheet is seen from above, a box at three-quarters.
void AimCamera(vtkPolyData* cloud, vtkCamera* camera)
{
  const vtkIdType n = cloud->GetNumberOfPoints();
  const vtkIdType stride = std::max<vtkIdType>(1, n / 100000);
  double mean[3] = { 0, 0, 0 }, x[3];
  vtkIdType count = 0;
  for (vtkIdType i = 0; i < n; i += stride, ++count)
  {
    cloud->GetPoint(i, x);
    for (int c = 0; c < 3; ++c)
    {
      mean[c] += x[c];
    }
  }
  for (int c = 0; c < 3 && count > 0; ++c)
  {
    mean[c] /= count;
  }
  double covariance[3][3] = { { 0, 0, 0 }, { 0, 0, 0 }, { 0, 0, 0 } };
  for (vtkIdType i = 0; i < n; i += stride)
  {
    cloud->GetPoint(i, x);
    for (int a = 0; a < 3; ++a)
    {
      for (int b = 0; b < 3; ++b)
      {
        covariance[a][b] += (x[a] - mean[a]) * (x[b] - mean[b]);
      }
    }
  }
  double* rows[3] = { covariance[0], covariance[1], covariance[2] };
  double values[3], vectorStore[3][3];
  double* vectors[3] = { vectorStore[0], vectorStore[1], vectorStore[2] };
  if (count < 3 || !vtkMath::Jacobi(rows, values, vectors)) // eigenvalues in decreasing order
  {
    return;
  }
  double direction[3], up[3];
  for (int c = 0; c < 3; ++c)
  {
    // Columns of `vectors` are the eigenvectors: 0 longest, 2 thinnest.
    direction[c] = vectors[c][2] + 0.55 * vectors[c][1] - 0.45 * vectors[c][0];
    up[c] = vectors[c][0];
  }
  vtkMath::Normalize(direction);
  camera->SetFocalPoint(mean);
  camera->SetPosition(mean[0] + direction[0], mean[1] + direction[1], mean[2] + direction[2]);
  camera->SetViewUp(up);
  camera->OrthogonalizeViewUp();
}

// Renders the result: points coloured by the score on a blue-to-green scale up to the threshold,
// feature points in red and larger, camera fitted to the cloud.
bool RenderPicture(vtkPolyData* result, const char* scoreName, double threshold,
  const std::string& captionText, int width, int height, const std::string& file,
  std::string& error, vtkPolyData* curves = nullptr)
{
  auto* mask = vtkUnsignedCharArray::SafeDownCast(result->GetPointData()->GetArray("FeatureMask"));
  vtkNew<vtkPoints> featurePoints;
  featurePoints->SetDataType(result->GetPoints()->GetDataType());
  for (vtkIdType i = 0; mask && i < result->GetNumberOfPoints(); ++i)
  {
    if (mask->GetValue(i))
    {
      featurePoints->InsertNextPoint(result->GetPoint(i));
    }
  }
  vtkNew<vtkPolyData> features;
  features->SetPoints(featurePoints);
  vtkNew<vtkCellArray> verts;
  for (vtkIdType i = 0; i < featurePoints->GetNumberOfPoints(); ++i)
  {
    verts->InsertNextCell(1, &i);
  }
  features->SetVerts(verts);

  const double pointSize = result->GetNumberOfPoints() > 200000 ? 1.5 : 2.5;
  vtkNew<vtkLookupTable> lut;
  lut->SetHueRange(0.667, 0.333);
  lut->Build();
  vtkNew<vtkPolyDataMapper> cloudMapper;
  cloudMapper->SetInputData(result);
  cloudMapper->SetScalarModeToUsePointFieldData();
  cloudMapper->SelectColorArray(scoreName);
  cloudMapper->SetLookupTable(lut);
  cloudMapper->SetScalarRange(0.0, threshold > 0.0 ? threshold : 1.0);
  vtkNew<vtkActor> cloudActor;
  cloudActor->SetMapper(cloudMapper);
  cloudActor->GetProperty()->SetPointSize(pointSize);
  cloudActor->GetProperty()->LightingOff(); // flat colours: a cloud's normals would shade it
  vtkNew<vtkPolyDataMapper> featureMapper;
  featureMapper->SetInputData(features);
  featureMapper->ScalarVisibilityOff();
  vtkNew<vtkActor> featureActor;
  featureActor->SetMapper(featureMapper);
  featureActor->GetProperty()->SetColor(0.9, 0.05, 0.05);
  featureActor->GetProperty()->SetPointSize(pointSize + 1.5);
  featureActor->GetProperty()->LightingOff();
  vtkNew<vtkScalarBarActor> bar;
  bar->SetLookupTable(lut);
  bar->SetTitle(scoreName);
  bar->SetNumberOfLabels(3);
  bar->SetWidth(0.08);
  bar->SetHeight(0.5);
  bar->SetPosition(0.88, 0.25);
  bar->UnconstrainedFontSizeOn();
  for (vtkTextProperty* text : { bar->GetTitleTextProperty(), bar->GetLabelTextProperty() })
  {
    text->SetColor(0.1, 0.1, 0.1);
    text->ShadowOff();
    text->ItalicOff();
    text->BoldOff();
    text->SetFontSize(std::max(10, height / 45));
  }
  vtkNew<vtkTextActor> caption;
  caption->SetInput(captionText.c_str());
  caption->GetTextProperty()->SetColor(0.1, 0.1, 0.1);
  caption->GetTextProperty()->SetFontSize(std::max(10, height / 45));
  caption->SetDisplayPosition(10, 10);

  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(cloudActor);
  renderer->AddActor(featureActor);
  // The feature curves (--lines), drawn over the points.
  vtkNew<vtkPolyDataMapper> curveMapper;
  vtkNew<vtkActor> curveActor;
  if (curves)
  {
    curveMapper->SetInputData(curves);
    curveMapper->ScalarVisibilityOff();
    curveMapper->SetResolveCoincidentTopologyToPolygonOffset();
    curveActor->SetMapper(curveMapper);
    curveActor->GetProperty()->SetColor(0.0, 0.0, 0.0);
    curveActor->GetProperty()->SetLineWidth(3.0);
    curveActor->GetProperty()->LightingOff();
    renderer->AddActor(curveActor);
  }
  renderer->AddActor2D(bar);
  renderer->AddActor2D(caption);
  renderer->SetBackground(1.0, 1.0, 1.0);
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(width, height);
  window->AddRenderer(renderer);
  AimCamera(result, renderer->GetActiveCamera());
  renderer->ResetCamera();
  window->Render();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  vtkNew<vtkPNGWriter> png;
  png->SetInputConnection(grab->GetOutputPort());
  png->SetFileName(file.c_str());
  png->Write();
  if (png->GetErrorCode() != 0)
  {
    error = "cannot write the picture";
    return false;
  }
  return true;
}

// ---------------------------------------------------------------------------------------------
// Command line

// The largest picture --size accepts, in pixels.
constexpr long long MaxPicturePixels = 4096LL * 4096LL;

struct Settings
{
  std::string Input, Output, Screenshot;
  std::string Lines; // --lines: the feature curves' file
  std::string MethodName = DefaultMethod;
  std::vector<std::pair<const FilterOption*, double>> FilterValues;
  bool FeaturesOnly = false;
  int Width = 1200, Height = 900;
  bool SizeGiven = false; // --size: only with --screenshot
  int Threads = 0;
};

// `text` as a finite double, blanks around it allowed (strtod skips the leading ones only);
// `outOfRange`, when given, tells a number beyond a double's range or precision (1e309, 5e-324,
// inf) from no number at all.
bool ParseNumber(const std::string& text, double& value, bool* outOfRange = nullptr)
{
  const size_t first = text.find_first_not_of(" \t");
  const size_t last = text.find_last_not_of(" \t");
  const std::string trimmed = first == std::string::npos ? "" : text.substr(first, last - first + 1);
  char* end = nullptr;
  errno = 0;
  value = std::strtod(trimmed.c_str(), &end);
  const bool whole = !trimmed.empty() && end == trimmed.c_str() + trimmed.size();
  if (outOfRange)
  {
    *outOfRange = whole && (errno == ERANGE || !std::isfinite(value)) && !std::isnan(value);
  }
  return whole && errno == 0 && std::isfinite(value);
}

// The command line as it is read: the arguments, the position, and the option at that position
// ("--name" or "--name=value").
struct CommandLine
{
  int Argc;
  char** Argv;
  int Index = 1;
  std::string Name, Value;
  bool HasValue = false;

  // The option's value: what follows '=', else the next argument.
  std::string TakeValue()
  {
    if (!this->HasValue)
    {
      if (this->Index + 1 >= this->Argc)
      {
        Fail(ExitUsage, "option --" + this->Name + " needs a value");
      }
      this->Value = this->Argv[++this->Index];
    }
    return this->Value;
  }

  // Refuses "--name=value" for an option that takes none.
  void NoValue() const
  {
    if (this->HasValue)
    {
      Fail(ExitUsage, "option --" + this->Name + " takes no value");
    }
  }
};

void PrintVersion()
{
  std::printf("featurepoints %s (VTK %s)\n", FEATUREPOINTS_VERSION, vtkVersion::GetVTKVersion());
}

std::string MethodNames()
{
  std::string names;
  for (const Method& m : Methods())
  {
    names += (names.empty() ? "" : ", ") + std::string(m.Name);
  }
  return names;
}

// --size WxH: a picture size within the limits (an offscreen picture takes about 64 bytes per
// pixel in all, colour, depth and copies: 8192x8192 would take over 4 GB and most of a minute).
void ReadPictureSize(const std::string& v, Settings& s)
{
  int w = 0, h = 0;
  char extra = 0;
  if (std::sscanf(v.c_str(), "%dx%d%c", &w, &h, &extra) != 2 || w < 16 || h < 16 || w > 8192 ||
    h > 8192)
  {
    Fail(ExitUsage,
      "--size takes WIDTHxHEIGHT in pixels, each from 16 to 8192 (at most 16.8 megapixels); got '" +
        v + "'");
  }
  if (static_cast<long long>(w) * h > MaxPicturePixels)
  {
    Fail(ExitUsage, "--size " + v + " is " + FormatNumber(std::round(w * (h / 1e5)) / 10) +
        " megapixels, about " + FormatNumber(std::ceil(64.0 * w * h / 1e8) / 10) +
        " GB to render: at most " + FormatNumber(std::round(MaxPicturePixels / 1e5) / 10) +
        " megapixels (e.g. 4096x4096)");
  }
  s.Width = w;
  s.Height = h;
  s.SizeGiven = true;
}

// The options that are not the methods': each reads what it needs from the command line into
// the settings (or prints and exits).
struct GeneralOption
{
  const char* Name;
  std::function<void(CommandLine&, Settings&)> Read;
};

const std::vector<GeneralOption>& GeneralOptions()
{
  static const std::vector<GeneralOption> options = {
    { "help",
      [](CommandLine&, Settings&) {
        PrintHelp();
        std::exit(ExitSuccess);
      } },
    { "version",
      [](CommandLine&, Settings&) {
        PrintVersion();
        std::exit(ExitSuccess);
      } },
    { "quiet",
      [](CommandLine& line, Settings&) {
        line.NoValue();
        Quiet = true;
      } },
    { "features-only",
      [](CommandLine& line, Settings& s) {
        line.NoValue();
        s.FeaturesOnly = true;
      } },
    { "method",
      [](CommandLine& line, Settings& s) {
        s.MethodName = line.TakeValue();
        if (!FindMethod(s.MethodName))
        {
          Fail(ExitUsage, "unknown method '" + s.MethodName + "' (methods: " + MethodNames() + ")");
        }
      } },
    { "screenshot",
      [](CommandLine& line, Settings& s) {
        s.Screenshot = line.TakeValue();
        if (vtkPointCloudIO::GetExtension(s.Screenshot) != "png")
        {
          Fail(ExitUsage,
            "--screenshot writes a PNG file: '" + s.Screenshot + "' does not end in .png");
        }
      } },
    { "lines",
      [](CommandLine& line, Settings& s) {
        s.Lines = line.TakeValue();
        if (!featurepoints::CanWriteLines(vtkPointCloudIO::GetExtension(s.Lines)))
        {
          Fail(ExitUsage, "--lines writes " + featurepoints::GetLinesExtensions() + ": '" +
              s.Lines + "' ends in none of them");
        }
      } },
    { "size", [](CommandLine& line, Settings& s) { ReadPictureSize(line.TakeValue(), s); } },
    { "threads",
      [](CommandLine& line, Settings& s) {
        const std::string v = line.TakeValue();
        double n = 0;
        if (!ParseNumber(v, n) || n < 1 || n > 4096 || n != std::floor(n))
        {
          Fail(ExitUsage, "--threads takes a whole number from 1 to 4096; got '" + v + "'");
        }
        s.Threads = static_cast<int>(n);
      } },
  };
  return options;
}

const GeneralOption* FindGeneralOption(const std::string& name)
{
  for (const GeneralOption& o : GeneralOptions())
  {
    if (name == o.Name)
    {
      return &o;
    }
  }
  return nullptr;
}

// A method option's value: a flag, a keyword, or a number within the option's range.
void ReadFilterOption(const FilterOption& o, CommandLine& line, Settings& s)
{
  if (o.Flag)
  {
    line.NoValue();
    s.FilterValues.emplace_back(&o, 1.0);
    return;
  }
  const std::string& name = line.Name;
  const std::string v = line.TakeValue();
  double number = 0.0;
  if (!o.Keywords.empty())
  {
    const auto k = o.Keywords.find(v);
    if (k == o.Keywords.end())
    {
      Fail(ExitUsage, "--" + name + " takes " + o.Metavar + "; got '" + v + "'");
    }
    number = k->second;
  }
  else if (bool outOfRange = false; !ParseNumber(v, number, &outOfRange))
  {
    Fail(ExitUsage,
      "--" + name +
        (outOfRange ? " takes a finite number within a double's range and precision (about "
                      "2.2e-308 to 1.8e308); got '"
                    : " takes a number; got '") +
        v + "'");
  }
  else if ((number < o.Min && o.Min > -1e299) || (number > o.Max && o.Max < 1e299) ||
    (o.Integer && number != std::floor(number)))
  {
    Fail(ExitUsage, "--" + name + " " + v + " is out of range: " +
        (o.Integer ? "a whole number" : "a number") + " from " + FormatNumber(o.Min) + " to " +
        (o.Max > 1e299 ? std::string("any") : FormatNumber(o.Max)));
  }
  s.FilterValues.emplace_back(&o, number);
}

// What the options decide together: the two files, one threshold rule, and options that apply
// to the method chosen.
void CheckSettings(Settings& s, const std::vector<std::string>& positional)
{
  if (positional.size() != 2)
  {
    Fail(ExitUsage, positional.size() < 2 ? "INPUT and OUTPUT files are needed"
                                          : "too many arguments: '" + positional[2] + "'");
  }
  s.Input = positional[0];
  s.Output = positional[1];
  // --threshold-sigmas asks for the automatic rule, --threshold for an absolute one.
  const auto isGiven = [&](const char* option) {
    return std::any_of(s.FilterValues.begin(), s.FilterValues.end(),
      [&](const std::pair<const FilterOption*, double>& v) {
        return v.first->Name == std::string(option);
      });
  };
  if (isGiven("threshold") && isGiven("threshold-sigmas"))
  {
    Fail(ExitUsage, "options --threshold and --threshold-sigmas exclude each other (absolute or "
                    "automatic threshold)");
  }
  for (const auto& value : s.FilterValues)
  {
    const auto& methods = value.first->Methods;
    if (!methods.empty() &&
      std::find(methods.begin(), methods.end(), s.MethodName) == methods.end())
    {
      Fail(ExitUsage, std::string("option --") + value.first->Name +
          " does not apply to --method " + s.MethodName);
    }
  }
}

// A hand parser rather than vtksys::CommandLineArguments: that one reports an unknown option
// only after the whole line is parsed (or stops parsing at the first one), has no "--" that ends
// the options, and prints its own messages, where this program names the first bad argument in
// one line of its own.
Settings ParseArguments(int argc, char* argv[])
{
  Settings s;
  std::vector<std::string> positional;
  CommandLine line{ argc, argv };
  for (; line.Index < argc; ++line.Index)
  {
    const std::string arg = argv[line.Index];
    if (arg == "--")
    {
      positional.insert(positional.end(), argv + line.Index + 1, argv + argc);
      break;
    }
    if (arg == "-h")
    {
      PrintHelp();
      std::exit(ExitSuccess);
    }
    if (arg.size() < 2 || arg.compare(0, 2, "--") != 0)
    {
      if (arg.size() > 1 && arg[0] == '-')
      {
        Fail(ExitUsage, "unknown option '" + arg + "'");
      }
      positional.push_back(arg);
      continue;
    }
    line.Name = arg.substr(2);
    line.Value.clear();
    const size_t equals = line.Name.find('=');
    line.HasValue = equals != std::string::npos;
    if (line.HasValue)
    {
      line.Value = line.Name.substr(equals + 1);
      line.Name.erase(equals);
    }
    if (const GeneralOption* o = FindGeneralOption(line.Name))
    {
      o->Read(line, s);
    }
    else if (const FilterOption* f = FindFilterOption(line.Name))
    {
      ReadFilterOption(*f, line, s);
    }
    else
    {
      Fail(ExitUsage, "unknown option '--" + line.Name + "'");
    }
  }
  CheckSettings(s, positional);
  return s;
}

// The input's point arrays that the method's own arrays of the same name replace in the output
// (the input's Normals, for instance): one line each, so that no column is lost without a word.
void WarnReplacedArrays(vtkPointSet* input, vtkPolyData* result)
{
  vtkPointData* in = input->GetPointData();
  vtkPointData* out = result->GetPointData();
  for (int a = 0; a < in->GetNumberOfArrays() && !Quiet; ++a)
  {
    vtkAbstractArray* array = in->GetAbstractArray(a);
    const char* name = array ? array->GetName() : nullptr;
    vtkAbstractArray* written = name ? out->GetAbstractArray(name) : nullptr;
    if (written && written != array)
    {
      std::fprintf(stderr,
        "featurepoints: note: the input's point array '%s' is replaced by the method's own\n", name);
    }
  }
}

// The points of a cloud that fall out of range in its scaled frame: finite in the input, infinite
// once scaled. A cloud that spans more than doubles can square (a part 1e-60 wide and a point at
// 1e260) has no scale for both.
struct FrameOverflow
{
  vtkIdType Count = 0;
  vtkIdType First = -1;
  vtkIdType NonFinite = 0; // points already NaN or infinite in the input
};

// The cloud with its coordinates multiplied by 2^exponent (double precision) and the same point
// data: what the method runs on when ScaledFrameExponent() is not 0. `overflow`: the points that
// become infinite in it, which the method then skips.
vtkSmartPointer<vtkPolyData> ScaledFrame(
  vtkPointSet* cloud, int exponent, FrameOverflow* overflow = nullptr)
{
  const vtkIdType n = cloud->GetNumberOfPoints();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(n);
  double x[3];
  for (vtkIdType i = 0; i < n; ++i)
  {
    cloud->GetPoint(i, x);
    const bool finite = std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]);
    for (double& c : x)
    {
      c = std::ldexp(c, exponent);
    }
    if (overflow && !finite)
    {
      ++overflow->NonFinite;
    }
    else if (overflow &&
      !(std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2])))
    {
      overflow->First = overflow->Count++ == 0 ? i : overflow->First;
    }
    points->SetPoint(i, x);
  }
  auto scaled = vtkSmartPointer<vtkPolyData>::New();
  scaled->SetPoints(points);
  scaled->GetPointData()->ShallowCopy(cloud->GetPointData());
  return scaled;
}

// Back to the input's units after a run in a scaled frame: the output gets the input's points,
// and each array measured in lengths (the detector's GetLengthPower()) its values in the input's
// units, in double. The mean spacing field too.
void UnscaleResult(
  vtkPolyData* result, vtkPointSet* cloud, vtkFeaturePointDetector* detector, int exponent)
{
  result->SetPoints(cloud->GetPoints());
  detector->ScaleLengthArrays(result->GetPointData(), -exponent, cloud->GetPointData());
  if (auto* spacing = vtkDoubleArray::SafeDownCast(result->GetFieldData()->GetArray("MeanSpacing")))
  {
    spacing->SetValue(0, spacing->GetValue(0) * LengthUnit);
  }
}

// The first value of `array` that is NaN or infinite: its tuple i, component c and value v.
bool FirstNonFinite(vtkDataArray* array, vtkIdType& i, int& c, double& v)
{
  const int k = array->GetNumberOfComponents();
  for (i = 0; i < array->GetNumberOfTuples(); ++i)
  {
    for (c = 0; c < k; ++c)
    {
      v = array->GetComponent(i, c);
      if (!std::isfinite(v))
      {
        return true;
      }
    }
  }
  return false;
}

// The largest coordinate difference from point i of `result` to the nearest of its 8 nearest
// other positions (a distance within a factor sqrt(3)), over the cloud's bounding-box diagonal
// (-1 when unknown): tiny where the cloud's spacings shrink far below any
// measurement's precision (a fuzzer's geometric spacings, 1 down to 1e-300), where densities and
// curvatures leave the range of the output arrays; a far point gives an ordinary ratio.
double NearestOverDiagonal(vtkPolyData* result, vtkIdType i)
{
  if (i < 0 || i >= result->GetNumberOfPoints() || result->GetNumberOfPoints() < 2)
  {
    return -1.0;
  }
  const double diagonal = result->GetLength();
  if (!(diagonal > 0.0) || !std::isfinite(diagonal))
  {
    return -1.0;
  }
  vtkNew<vtkStaticPointLocator> locator;
  locator->SetDataSet(result);
  locator->BuildLocator();
  double x[3], y[3];
  result->GetPoint(i, x);
  vtkNew<vtkIdList> nearest;
  locator->FindClosestNPoints(8, x, nearest);
  double closest = -1.0;
  for (vtkIdType j = 0; j < nearest->GetNumberOfIds(); ++j)
  {
    result->GetPoint(nearest->GetId(j), y);
    if (x[0] == y[0] && x[1] == y[1] && x[2] == y[2])
    {
      continue; // the point itself, or a copy
    }
    // Component by component: a squared distance may underflow to 0 (which also leaves the
    // locator's order among such points arbitrary; any of them is as close).
    double d = 0.0;
    for (int c = 0; c < 3; ++c)
    {
      d = std::max(d, std::abs(x[c] - y[c]));
    }
    closest = closest < 0.0 ? d : std::min(closest, d);
  }
  return closest < 0.0 ? -1.0 : closest / diagonal;
}

// The first computed value that is NaN or infinite, as a message ("" when there is none): such a
// value is never written.
std::string FindNonFinite(vtkPolyData* result, vtkPointSet* cloud)
{
  vtkPointData* pd = result->GetPointData();
  for (int a = 0; a < pd->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = pd->GetArray(a);
    if (!array || (array->GetDataType() != VTK_FLOAT && array->GetDataType() != VTK_DOUBLE) ||
      cloud->GetPointData()->GetArray(array->GetName()) == array)
    {
      continue;
    }
    vtkIdType i = 0;
    int c = 0;
    double v = 0.0;
    if (FirstNonFinite(array, i, c, v))
    {
      double x[3] = { 0.0, 0.0, 0.0 };
      if (i < result->GetNumberOfPoints())
      {
        result->GetPoint(i, x);
      }
      std::ostringstream m;
      m << "the method computed " << v << " for array '" << array->GetName() << "' at point "
        << i << " (counting from 0) at (" << x[0] << ", " << x[1] << ", " << x[2]
        << "): the cloud's coordinates are beyond what it can compute with ";
      // Closer than a millionth of a float's precision across the cloud: no scan measures that.
      const double ratio = NearestOverDiagonal(result, i);
      if (ratio >= 0.0 && ratio < 1e-13)
      {
        m << "(its nearest other point lies " << ratio
          << " of the cloud's size away, far below any measurement's precision: merge such "
          << "points or drop them)";
      }
      else
      {
        m << "(a point far from the rest: remove it)";
      }
      return m.str();
    }
  }
  return "";
}

// A name with its folder resolved (links, ".", "..", relative to the working folder), for files
// that may not exist yet.
std::string ResolvedName(const std::string& name)
{
  const std::string full = vtksys::SystemTools::CollapseFullPath(name);
  return vtksys::SystemTools::GetRealPath(vtksys::SystemTools::GetFilenamePath(full)) + "/" +
    vtksys::SystemTools::GetFilenameName(full);
}

// Whether two names are the same file (links and other paths to it included), also where
// neither exists yet ("o.vtp" and "./o.vtp").
bool SameFile(const std::string& a, const std::string& b)
{
  return a == b || vtksys::SystemTools::SameFile(a, b) || ResolvedName(a) == ResolvedName(b);
}

// The filter's first error, as one line.
class ErrorFlag : public vtkCommand
{
public:
  static ErrorFlag* New() { return new ErrorFlag; }
  void Execute(vtkObject*, unsigned long, void* data) override
  {
    if (this->Message.empty())
    {
      this->Message = vtkPointCloudIO::MessageText(static_cast<const char*>(data));
    }
  }
  std::string Message;
};

// One run of the program once the command line is read: each stage is one member function, and
// Execute() calls them in order. A stage that fails ends the program with its one-line message.
class FeaturePointsRun
{
public:
  explicit FeaturePointsRun(const Settings& s)
    : S(s)
    , M(FindMethod(s.MethodName))
  {
  }

  int Execute()
  {
    if (Rank != 0)
    {
      // Another process of a distributed run: its share of the reading (a binary PLY file) and of
      // the work, nothing on the terminal or in the files (process 0 writes and reports).
      this->SetThreads();
      this->ReadCloud();
      this->Extract();
      this->WritePieces();
      return ExitSuccess;
    }
    this->CheckFiles();
    InstallSignalHandlers();
    this->SetThreads();
    this->ReadCloud();
    this->Extract();
    this->ExtractCurves();
    this->Render();
    if (!this->WritePieces())
    {
      this->WriteFiles();
    }
    if (!Quiet)
    {
      this->PrintSummary();
    }
    return ExitSuccess;
  }

private:
  // What the command line alone decides: formats, and files that must not be overwritten; then
  // what would fail after the work: unwritable targets, no display to render with.
  void CheckFiles() const
  {
    const Settings& s = this->S;
    const std::string inExt = vtkPointCloudIO::GetExtension(s.Input);
    const std::string outExt = vtkPointCloudIO::GetExtension(s.Output);
    if (!vtkPointCloudIO::CanRead(inExt))
    {
      Fail(ExitUsage, s.Input + ": cannot tell the input format from the extension " +
          (inExt.empty() ? std::string("(none)") : "'." + inExt + "'") +
          "; readable: " + vtkPointCloudIO::GetReadableExtensions());
    }
    if (outExt == "pvtp")
    {
      this->CheckPieces();
    }
    else if (!vtkPointCloudIO::CanWrite(outExt))
    {
      Fail(ExitUsage, s.Output + ": cannot tell the output format from the extension " +
          (outExt.empty() ? std::string("(none)") : "'." + outExt + "'") +
          "; writable: " + vtkPointCloudIO::GetWritableExtensions());
    }
    if (SameFile(s.Input, s.Output))
    {
      Fail(ExitUsage, s.Output + ": is the input file; the input is never overwritten");
    }
    if (!s.Screenshot.empty() &&
      (SameFile(s.Screenshot, s.Input) || SameFile(s.Screenshot, s.Output)))
    {
      Fail(ExitUsage, s.Screenshot + ": the picture cannot replace the input or the output");
    }
    if (s.SizeGiven && s.Screenshot.empty())
    {
      Fail(ExitUsage, "--size sets the size of the picture: it needs --screenshot FILE.png");
    }
    if (!s.Lines.empty() &&
      (SameFile(s.Lines, s.Input) || SameFile(s.Lines, s.Output) ||
        (!s.Screenshot.empty() && SameFile(s.Lines, s.Screenshot))))
    {
      Fail(ExitUsage, s.Lines + ": the curves cannot replace the input, the output or the picture");
    }
    std::string error;
    if (!vtkPointCloudIO::CanCreate(s.Output, error) ||
      (!s.Screenshot.empty() && !vtkPointCloudIO::CanCreate(s.Screenshot, error)) ||
      (!s.Lines.empty() && !vtkPointCloudIO::CanCreate(s.Lines, error)))
    {
      Fail(ExitFailure, error);
    }
    if (!s.Screenshot.empty() && NeedsMissingDisplay())
    {
      Fail(ExitFailure, s.Screenshot + ": cannot render: this VTK renders through X and no "
                                       "display is set (run under xvfb-run -a)");
    }
  }

  // OUT.pvtp (under mpiexec): every process writes its own points; the picture and the curves
  // need the whole cloud on one process.
  void CheckPieces() const
  {
    const Settings& s = this->S;
#ifdef FEATUREPOINTS_HAVE_MPI
    if (!Processes)
#endif
    {
      Fail(ExitUsage, s.Output + ": a parallel .pvtp output is written by several processes: run "
                                 "under mpiexec -n N (N > 1), or write a .vtp file");
    }
    if (!s.Screenshot.empty() || !s.Lines.empty())
    {
      Fail(ExitUsage, s.Output + ": --screenshot and --lines need the whole result on one "
                                 "process: not with a parallel .pvtp output");
    }
  }

  // OUT.pvtp: each process writes its piece of the result (its own points, in input order, with
  // their input indices in `GlobalPointIds`), process 0 the .pvtp file that lists the pieces.
  // False (nothing written) for any other output.
  bool WritePieces()
  {
#ifdef FEATUREPOINTS_HAVE_MPI
    const Settings& s = this->S;
    if (!Processes || vtkPointCloudIO::GetExtension(s.Output) != "pvtp")
    {
      return false;
    }
    this->Meter->Stage("writing");
    const auto start = Clock::now();
    vtkSmartPointer<vtkPolyData> written = this->Written();
    const int nProcs = Processes->GetNumberOfProcesses();
    vtkNew<vtkXMLPPolyDataWriter> writer;
    writer->SetController(Processes);
    writer->SetFileName(s.Output.c_str());
    writer->SetNumberOfPieces(nProcs);
    writer->SetStartPiece(Rank);
    writer->SetEndPiece(Rank);
    writer->SetDataModeToAppended();
    writer->EncodeAppendedDataOff(); // as vtkPointCloudIO writes a .vtp
    writer->SetCompressorTypeToLZ4();
    writer->SetInputData(vtkPointCloudIO::WithXMLNames(written, s.Output));
    vtkNew<ErrorFlag> writeError;
    writer->AddObserver(vtkCommand::ErrorEvent, writeError);
    const int ok = writer->Write() == 1 && writeError->Message.empty() ? 1 : 0;
    int allOk = 0;
    Processes->AllReduce(&ok, &allOk, 1, vtkCommunicator::MIN_OP);
    this->Meter->Finish();
    if (!ok)
    {
      Fail(ExitFailure, s.Output + ": cannot write this process's piece: " + writeError->Message);
    }
    if (!allOk && Rank == 0)
    {
      Fail(ExitFailure, s.Output + ": another process could not write its piece");
    }
    this->Times.emplace_back("write", Seconds(start));
    return true;
#else
    return false;
#endif
  }

  // Any signal that ends the program removes the temporary files first (SIGPIPE: a closed
  // terminal or pipe on stderr; SIGXCPU: the shell's CPU time limit). Past the shell's file size
  // limit a write fails (rather than a signal ending the program), and the writer says so.
  static void InstallSignalHandlers()
  {
    for (int signal :
      { SIGINT, SIGTERM, SIGHUP, SIGPIPE, SIGQUIT, SIGXCPU, SIGALRM, SIGUSR1, SIGUSR2 })
    {
      std::signal(signal, RemoveTemporaries);
    }
    std::signal(SIGXFSZ, SIG_IGN);
  }

  // More threads than cores only slows the run down (and TBB says so on the console).
  void SetThreads() const
  {
    const int cores = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
    if (this->S.Threads <= 0)
    {
      // Several processes on one machine share its cores (mpiexec says how many run here).
      const char* local = std::getenv("OMPI_COMM_WORLD_LOCAL_SIZE");
      const int here = local ? std::max(1, std::atoi(local)) : 1;
      if (here > 1)
      {
        vtkSMPTools::Initialize(std::max(1, cores / here));
      }
      return;
    }
    if (this->S.Threads > cores && !Quiet)
    {
      std::fprintf(stderr,
        "featurepoints: warning: --threads %d: this machine has %d core(s); using %d\n",
        this->S.Threads, cores, cores);
    }
    vtkSMPTools::Initialize(std::min(this->S.Threads, cores));
  }

  // Under mpiexec, a binary PLY file is read by every process, each its share of the vertex rows
  // (their byte range); true when that was done (its own piece is then this process's cloud).
  // Other files are read by process 0 alone (the other processes hold no point), as is a cloud
  // whose extent needs a scaled frame (its exponent is taken on the whole cloud).
  bool ReadPiece()
  {
#ifdef FEATUREPOINTS_HAVE_MPI
    const Settings& s = this->S;
    if (!Processes || vtkPointCloudIO::GetExtension(s.Input) != "ply")
    {
      return false;
    }
    vtkNew<vtkPointCloudPLYReader> reader;
    reader->SetFileName(s.Input.c_str());
    vtkNew<vtkCallbackCommand> keepError; // the reader's error is reported below, once
    reader->AddObserver(vtkCommand::ErrorEvent, keepError);
    reader->UpdatePiece(Rank, Processes->GetNumberOfProcesses(), 0);
    if (reader->GetErrorCode() != vtkErrorCode::NoError)
    {
      Fail(ExitFailure, reader->GetErrorMessage());
    }
    vtkPolyData* piece = reader->GetOutput();
    // Points of the pieces before this one: where this piece starts in the file.
    const int nProcs = Processes->GetNumberOfProcesses();
    long long count = piece->GetNumberOfPoints();
    std::vector<long long> counts(nProcs, 0);
    Processes->AllGather(&count, counts.data(), 1);
    const long long first = std::accumulate(counts.begin(), counts.begin() + Rank, 0LL);
    this->TotalPoints = static_cast<vtkIdType>(std::accumulate(counts.begin(), counts.end(), 0LL));
    this->FirstPoint = static_cast<vtkIdType>(first);
    double lo[3] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, VTK_DOUBLE_MAX };
    double hi[3] = { -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
    double x[3];
    for (vtkIdType i = 0; i < piece->GetNumberOfPoints(); ++i)
    {
      piece->GetPoint(i, x);
      for (int c = 0; c < 3; ++c)
      {
        lo[c] = std::min(lo[c], x[c]); // NaN never wins a comparison: the check below finds it
        hi[c] = std::max(hi[c], x[c]);
      }
    }
    double globalLo[3], globalHi[3];
    Processes->AllReduce(lo, globalLo, 3, vtkCommunicator::MIN_OP);
    Processes->AllReduce(hi, globalHi, 3, vtkCommunicator::MAX_OP);
    const double extent = std::max(
      { globalHi[0] - globalLo[0], globalHi[1] - globalLo[1], globalHi[2] - globalLo[2] });
    if (this->TotalPoints > 0 && extent > 0.0 &&
      (extent < std::ldexp(1.0, -64) || extent > std::ldexp(1.0, 64)))
    {
      return false; // a scaled frame, decided on the whole cloud
    }
    this->Cloud = piece;
    return true;
#else
    return false;
#endif
  }

  // The input cloud, which must hold points, all of them finite.
  void ReadCloud()
  {
    const Settings& s = this->S;
    this->Meter->Stage("reading");
    const auto start = Clock::now();
    if (this->ReadPiece())
    {
      this->ByPieces = true;
      this->Meter->Finish();
      this->Times.emplace_back("read", Seconds(start));
      if (this->TotalPoints == 0 && Rank == 0)
      {
        Fail(ExitFailure, s.Input + ": the file holds no point");
      }
      this->CheckFinite(this->FirstPoint);
      return;
    }
    if (Rank != 0)
    {
      auto empty = vtkSmartPointer<vtkPolyData>::New();
      empty->SetPoints(vtkNew<vtkPoints>());
      this->Cloud = empty;
      return;
    }
    this->Reader->SetFileName(s.Input.c_str());
    this->Reader->AddObserver(vtkCommand::ProgressEvent, this->Meter);
    vtkNew<vtkCallbackCommand> keepError; // the reader's error is reported below, once
    this->Reader->AddObserver(vtkCommand::ErrorEvent, keepError);
    this->Reader->Update();
    this->Meter->Finish();
    if (this->Reader->GetErrorCode() != vtkErrorCode::NoError)
    {
      Fail(ExitFailure, this->Reader->GetErrorMessage());
    }
    this->Cloud = this->Reader->GetOutput();
    this->Times.emplace_back("read", Seconds(start));
    this->TotalPoints = this->Cloud->GetNumberOfPoints();
    if (this->TotalPoints == 0)
    {
      Fail(ExitFailure, s.Input + ": the file holds no point");
    }
    this->TakeFilePoints();
    this->CheckFinite(0);
  }

  // A PCD file whose points with a NaN or infinite coordinate were skipped: the file's index (and
  // for ASCII data the line) of each point read, as the reader gives them in the cloud's field
  // data, taken out of it so that the output does not carry them.
  void TakeFilePoints()
  {
    if (vtkPointCloudIO::GetExtension(this->S.Input) != "pcd")
    {
      return;
    }
    vtkFieldData* fd = this->Cloud->GetFieldData();
    const vtkIdType n = this->Cloud->GetNumberOfPoints();
    auto take = [fd, n](const char* name) {
      vtkSmartPointer<vtkIdTypeArray> array = vtkIdTypeArray::SafeDownCast(fd->GetArray(name));
      fd->RemoveArray(name);
      return array && array->GetNumberOfValues() == n ? array : nullptr;
    };
    this->FilePointIds = take("FilePointIds");
    this->FileLines = take("FileLines");
  }

  // Point i of the cloud as a message names it: "FILE: point N (counting from 0)", with the
  // file's numbering where the reader skipped points before it ("FILE:LINE: point N ...").
  std::string InputPoint(vtkIdType i) const
  {
    const vtkIdType inFile = this->FilePointIds ? this->FilePointIds->GetValue(i) : -1;
    if (inFile < 0)
    {
      return this->S.Input + ": point " + std::to_string(this->FirstPoint + i) +
        " (counting from 0)";
    }
    const vtkIdType skipped = inFile - i;
    return this->S.Input +
      (this->FileLines ? ":" + std::to_string(this->FileLines->GetValue(i)) : std::string()) +
      ": point " + std::to_string(inFile) + " (counting from 0, as the file numbers its points; " +
      std::to_string(skipped) + " point" + (skipped == 1 ? "" : "s") +
      " with a NaN or infinite coordinate before it skipped)";
  }

  // Every point of the cloud (the piece that starts at point `first` of the file) is finite.
  void CheckFinite(vtkIdType first) const
  {
    const vtkIdType n = this->Cloud->GetNumberOfPoints();
    for (vtkIdType i = 0; i < n; ++i)
    {
      double x[3];
      this->Cloud->GetPoint(i, x);
      if (!std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2]))
      {
        std::ostringstream m;
        m << this->S.Input << ": point " << first + i
          << " (counting from 0) has a non-finite coordinate (" << x[0] << ", " << x[1] << ", "
          << x[2] << ")";
        Fail(ExitFailure, m.str());
      }
    }
  }

  // Every value of the input's floating-point arrays that the output carries (those the method
  // does not replace with its own, as it does the Normals) is finite: the output holds no NaN or
  // infinity (the text formats' reader rejects such a value the same way).
  void CheckInputArrays() const
  {
    vtkPointData* pd = this->Cloud->GetPointData();
    for (int a = 0; a < pd->GetNumberOfArrays(); ++a)
    {
      vtkDataArray* array = pd->GetArray(a);
      if (!array || (array->GetDataType() != VTK_FLOAT && array->GetDataType() != VTK_DOUBLE) ||
        this->Replaced(array))
      {
        continue;
      }
      vtkIdType i = 0;
      int c = 0;
      double v = 0.0;
      if (FirstNonFinite(array, i, c, v))
      {
        std::ostringstream m;
        m << this->InputPoint(i) << ": point array '"
          << vtkPointCloudIO::MessageText(array->GetName() ? array->GetName() : "(no name)") << "'"
          << (array->GetNumberOfComponents() > 1 ? " component " + std::to_string(c)
                                                 : std::string())
          << " holds " << v << ", not a finite number";
        Fail(ExitFailure, m.str());
      }
    }
  }

  // Whether the method's output replaces the input's array with its own of the same name.
  bool Replaced(vtkDataArray* array) const
  {
    const char* name = array->GetName();
    if (!name)
    {
      return false;
    }
#ifdef FEATUREPOINTS_HAVE_MPI
    if (this->Driver)
    {
      // The result's arrays are copies: the driver knows which input arrays the method replaced.
      for (int a = 0; a < this->Driver->GetNumberOfReplacedArrays(); ++a)
      {
        if (std::strcmp(this->Driver->GetReplacedArray(a), name) == 0)
        {
          return true;
        }
      }
      return false;
    }
#endif
    vtkAbstractArray* written = this->Result->GetPointData()->GetAbstractArray(name);
    return written && written != array;
  }

  // The method with the options given, on the cloud (in a scaled frame when its extent would
  // overflow or underflow squared distances), its result in the input's units.
  void Extract()
  {
    const Settings& s = this->S;
    this->Filter = this->M->Create();
    for (const auto& value : s.FilterValues)
    {
      value.first->Apply(this->Filter, value.second);
    }
    if (!s.Lines.empty() && Crease(this->Filter) && !Crease(this->Filter)->GetCreaseOffsets())
    {
      // The curves place their vertices on the crease points moved by CreaseOffset (see
      // ExtractCurves, which drops the array again: it was not asked for).
      Crease(this->Filter)->CreaseOffsetsOn();
      this->OffsetsForCurves = true;
    }
    this->Filter->SetOutputFeaturesOnly(false); // the picture needs every point; see WriteFiles
    // Read by pieces: the whole cloud's extent needs no scaled frame (see ReadPiece).
    const int exponent = this->ByPieces ? 0 : vtkFeaturePointDetector::ScaledFrameExponent(this->Cloud);
    this->Exponent = exponent;
    if (exponent != 0)
    {
      LengthUnit = std::ldexp(1.0, -exponent);
      if (!Quiet)
      {
        double bounds[6];
        this->Cloud->GetPoints()->GetBounds(bounds);
        std::fprintf(stderr,
          "featurepoints: note: %s: the cloud spans %.3g units: the method runs on its "
          "coordinates scaled by 2^%d, where squares of distances neither overflow nor underflow "
          "(results in the input's units)\n",
          s.Input.c_str(),
          std::max({ bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4] }),
          exponent);
      }
      FrameOverflow overflow;
      this->Filter->SetInputData(ScaledFrame(this->Cloud, exponent, &overflow));
      FrameOverflowOnly = overflow.Count > 0 && overflow.NonFinite == 0;
      if (overflow.Count > 0 && !Quiet)
      {
        double x[3];
        this->Cloud->GetPoint(overflow.First, x);
        std::fprintf(stderr,
          "featurepoints: warning: %s: %lld point(s) lie too far from the rest of the cloud to "
          "share its scale (the first is point %lld, at %.3g %.3g %.3g): no power of two holds "
          "both within double precision; they are skipped: scores 0, never feature points\n",
          s.Input.c_str(), static_cast<long long>(overflow.Count),
          static_cast<long long>(overflow.First), x[0], x[1], x[2]);
      }
    }
    else
    {
      this->Filter->SetInputData(this->Cloud);
    }
    this->Filter->AddObserver(vtkCommand::ProgressEvent, this->Meter);
    vtkNew<ErrorFlag> filterError;
    this->Filter->AddObserver(vtkCommand::ErrorEvent, filterError);
    this->Meter->Stage("extracting");
    const auto start = Clock::now();
#ifdef FEATUREPOINTS_HAVE_MPI
    if (Processes)
    {
      // Each process holds its share of the file (binary PLY), or process 0 the whole cloud: the
      // driver splits it in space, each process scores its piece, and the result comes back to
      // process 0 in the input's order.
      this->Driver = vtkSmartPointer<vtkDistributedFeaturePoints>::New();
      this->Driver->SetController(Processes);
      this->Driver->SetDetector(this->Filter);
      this->Driver->SetInputData(this->Filter->GetInputDataObject(0, 0));
      // A .pvtp output: each process keeps its own points (in input order) and writes them.
      const bool pieces = vtkPointCloudIO::GetExtension(s.Output) == "pvtp";
      if (pieces && exponent != 0)
      {
        Fail(ExitFailure, s.Input + ": the cloud's extent needs a scaled frame, which a parallel "
                                    ".pvtp output does not take: write a .vtp file");
      }
      this->Driver->SetGatherOutput(!pieces);
      this->Driver->AddObserver(vtkCommand::ErrorEvent, filterError);
      this->Driver->Update();
      this->Meter->Finish();
      if (Rank != 0)
      {
        this->Result = this->Driver->GetOutput();
        this->CheckInputArrays();
        return;
      }
      this->Times.emplace_back("extract", Seconds(start));
      if (!filterError->Message.empty())
      {
        Fail(ExitFailure, s.Input + ": " + filterError->Message);
      }
      this->Result = this->Driver->GetOutput();
    }
    else
#endif
    {
      this->Filter->Update();
      this->Meter->Finish();
      this->Times.emplace_back("extract", Seconds(start));
      if (!filterError->Message.empty())
      {
        Fail(ExitFailure, s.Input + ": " + filterError->Message);
      }
      this->Result = this->Filter->GetOutput();
    }
    if (exponent != 0)
    {
      // The curves run in the scaled frame again (see ExtractCurves): they read the offsets as
      // the method gave them there.
      if (vtkDataArray* offsets = this->Result->GetPointData()->GetArray("CreaseOffset"))
      {
        this->FrameOffsets = vtk::TakeSmartPointer(offsets->NewInstance());
        this->FrameOffsets->DeepCopy(offsets);
      }
      UnscaleResult(this->Result, this->Cloud, this->Filter, exponent);
    }
    this->CheckInputArrays();
    const std::string nonFinite = FindNonFinite(this->Result, this->Cloud);
    if (!nonFinite.empty())
    {
      Fail(ExitFailure, s.Input + ": " + nonFinite);
    }
#ifdef FEATUREPOINTS_HAVE_MPI
    if (this->Driver)
    {
      // The result's arrays are copies: the driver knows which input arrays the method replaced.
      for (int a = 0; a < this->Driver->GetNumberOfReplacedArrays() && !Quiet; ++a)
      {
        std::fprintf(stderr,
          "featurepoints: note: the input's point array '%s' is replaced by the method's own\n",
          this->Driver->GetReplacedArray(a));
      }
    }
    else
#endif
    {
      WarnReplacedArrays(this->Cloud, this->Result);
    }
    this->Grown = this->M->GrowThreshold ? this->M->GrowThreshold(this->Filter) : std::nan("");
  }

  // --lines: the feature curves; the output gets CurveId.
  void ExtractCurves()
  {
    if (this->S.Lines.empty())
    {
      return;
    }
    this->Meter->Stage("curves");
    const auto start = Clock::now();
    if (this->Exponent == 0)
    {
      this->Curves->SetInputData(this->Result);
      this->Curves->Update();
      this->Result = this->Curves->GetOutput();
    }
    else
    {
      // A cloud the method ran on scaled (see ScaledFrameExponent): the curves too, on the result
      // scaled the same way (its mean spacing with it), then the curves back in the input's
      // units; the result gets their CurveId.
      vtkSmartPointer<vtkPolyData> scaled = ScaledFrame(this->Result, this->Exponent);
      scaled->GetFieldData()->ShallowCopy(this->Result->GetFieldData());
      // CreaseOffset as the method gave it in that frame (the result's is in the input's units).
      scaled->GetPointData()->RemoveArray("CreaseOffset");
      if (this->FrameOffsets)
      {
        scaled->GetPointData()->AddArray(this->FrameOffsets);
      }
      if (vtkDataArray* spacing = this->Result->GetFieldData()->GetArray("MeanSpacing"))
      {
        vtkSmartPointer<vtkDataArray> inFrame = vtk::TakeSmartPointer(spacing->NewInstance());
        inFrame->DeepCopy(spacing);
        inFrame->SetTuple1(0, std::ldexp(spacing->GetTuple1(0), this->Exponent));
        scaled->GetFieldData()->AddArray(inFrame);
      }
      this->Curves->SetInputData(scaled);
      this->Curves->Update();
      this->Result->GetPointData()->AddArray(
        this->Curves->GetOutput()->GetPointData()->GetArray("CurveId"));
      vtkPolyData* curves = this->Curves->GetCurves();
      double bounds[6];
      this->Cloud->GetBounds(bounds);
      vtkNew<vtkPoints> points;
      points->SetDataTypeToDouble();
      points->SetNumberOfPoints(curves->GetNumberOfPoints());
      double x[3];
      for (vtkIdType i = 0; i < curves->GetNumberOfPoints(); ++i)
      {
        curves->GetPoint(i, x);
        for (int c = 0; c < 3; ++c)
        {
          x[c] = std::ldexp(x[c], -this->Exponent);
          // A vertex that the smoothing put just beyond such a cloud: onto its bounds.
          if (!std::isfinite(x[c]))
          {
            x[c] = std::min(std::max(x[c], bounds[2 * c]), bounds[2 * c + 1]);
          }
        }
        points->SetPoint(i, x);
      }
      curves->SetPoints(points);
      if (vtkDataArray* length = curves->GetCellData()->GetArray("Length"))
      {
        for (vtkIdType c = 0; c < length->GetNumberOfTuples(); ++c)
        {
          const double value = std::ldexp(length->GetTuple1(c), -this->Exponent);
          // A length the input's units cannot hold (a cloud that spans about the largest
          // double): refused before anything is written, rather than written as infinite.
          if (!std::isfinite(value))
          {
            Fail(ExitFailure,
              this->S.Input + ": a feature curve is longer than the largest double in the "
                              "cloud's units (the cloud spans about 1.8e308 or more); scale "
                              "the cloud down to extract its curves");
          }
          length->SetTuple1(c, value);
        }
      }
    }
    if (this->OffsetsForCurves)
    {
      this->Result->GetPointData()->RemoveArray("CreaseOffset");
    }
    this->Meter->Finish();
    this->Times.emplace_back("curves", Seconds(start));
  }

  // --screenshot: the picture, into a temporary file that WriteFiles renames once the output is
  // written too.
  void Render()
  {
    const Settings& s = this->S;
    if (s.Screenshot.empty())
    {
      return;
    }
    this->Meter->Stage("rendering");
    const auto start = Clock::now();
    std::string error;
    this->PictureFile = vtkPointCloudIO::CreateTemporaryFile(
      vtkPointCloudIO::WriteTarget(s.Screenshot), error, true);
    if (this->PictureFile.empty())
    {
      Fail(ExitFailure, error);
    }
    std::ostringstream caption;
    caption << this->M->Name << ": " << this->Filter->GetNumberOfFeaturePoints()
            << " feature points (red) of " << this->TotalPoints << ", "
            << this->Filter->GetScoreArrayName() << " > " << std::setprecision(4)
            << this->Filter->GetThresholdUsed();
    if (!std::isnan(this->Grown))
    {
      caption << ", grown through > " << this->Grown;
    }
    if (!s.Lines.empty())
    {
      caption << "; " << this->Curves->GetNumberOfCurves() << " curves (black)";
    }
    if (!RenderPicture(this->Result, this->Filter->GetScoreArrayName(),
          this->Filter->GetThresholdUsed(), caption.str(), s.Width, s.Height,
          this->PictureFile, error, s.Lines.empty() ? nullptr : this->Curves->GetCurves()))
    {
      RemoveTemporaries(0);
      Fail(ExitFailure, s.Screenshot + ": " + error);
    }
    this->Times.emplace_back("render", Seconds(start));
  }

  // What is written: the result, or only its feature points (with their ids in the input).
  vtkSmartPointer<vtkPolyData> Written() const
  {
    if (!this->S.FeaturesOnly)
    {
      return this->Result;
    }
    auto written = vtkSmartPointer<vtkPolyData>::New();
    vtkFeaturePointDetector::SelectFeaturePoints(this->Result,
      vtkUnsignedCharArray::SafeDownCast(this->Result->GetPointData()->GetArray("FeatureMask")),
      written);
    return written;
  }

  // The output (only the feature points if asked, with their ids in the input), the curves, and
  // the picture renamed into place: a failure leaves none of them behind.
  void WriteFiles()
  {
    const Settings& s = this->S;
    vtkSmartPointer<vtkPolyData> written = this->Written();
    this->Meter->Stage("writing");
    const auto start = Clock::now();
    std::string error;
    // The curves first, into a temporary file beside their target, renamed only once the output
    // is written too: a failure of either leaves every file as it was.
    std::string linesFile;
    if (!s.Lines.empty())
    {
      const std::string target = vtkPointCloudIO::WriteTarget(s.Lines);
      linesFile = vtkPointCloudIO::CreateTemporaryFile(target, error, true);
      if (linesFile.empty() ||
        !featurepoints::WriteLines(this->Curves->GetCurves(), linesFile, error,
          vtkPointCloudIO::GetExtension(s.Lines)))
      {
        this->Meter->Finish();
        RemoveTemporaries(0);
        // The message names the file asked for, not the temporary one.
        for (size_t at = linesFile.empty() ? std::string::npos : error.find(linesFile);
             at != std::string::npos; at = error.find(linesFile, at + s.Lines.size()))
        {
          error.replace(at, linesFile.size(), s.Lines);
        }
        Fail(ExitFailure, error);
      }
    }
    if (!vtkPointCloudIO::Write(written, s.Output, error, "", this->Meter))
    {
      this->Meter->Finish();
      RemoveTemporaries(0);
      Fail(ExitFailure, error);
    }
    if (!linesFile.empty())
    {
      if (std::rename(linesFile.c_str(), vtkPointCloudIO::WriteTarget(s.Lines).c_str()) != 0)
      {
        const std::string reason = std::strerror(errno);
        this->Meter->Finish();
        RemoveTemporaries(0);
        // A failed run leaves no output behind.
        std::remove(vtkPointCloudIO::WriteTarget(s.Output).c_str());
        Fail(ExitFailure, s.Lines + ": cannot write: " + reason);
      }
      vtkPointCloudIO::ReleaseTemporaryFile(linesFile);
    }
    this->Meter->Finish();
    this->Times.emplace_back("write", Seconds(start));
    if (!this->PictureFile.empty() &&
      std::rename(this->PictureFile.c_str(), vtkPointCloudIO::WriteTarget(s.Screenshot).c_str()) !=
        0)
    {
      RemoveTemporaries(0);
      Fail(ExitFailure, s.Screenshot + ": cannot write: " + std::strerror(errno));
    }
    vtkPointCloudIO::ReleaseTemporaryFile(this->PictureFile);
  }

  // The counts of each FeatureType, when the method writes them ("" otherwise).
  std::string TypeCounts() const
  {
    auto* types = this->M->FeatureTypes
      ? vtkUnsignedCharArray::SafeDownCast(this->Result->GetPointData()->GetArray("FeatureType"))
      : nullptr;
    if (!types)
    {
      return "";
    }
    long long counts[5] = { 0, 0, 0, 0, 0 };
    for (vtkIdType i = 0; i < types->GetNumberOfTuples(); ++i)
    {
      const unsigned char t = types->GetValue(i);
      if (t < 5)
      {
        ++counts[t];
      }
    }
    char line[160];
    std::snprintf(line, sizeof(line), "convex %lld, concave %lld, corner %lld, border %lld",
      counts[vtkCreaseVotingFeatures::CONVEX], counts[vtkCreaseVotingFeatures::CONCAVE],
      counts[vtkCreaseVotingFeatures::CORNER], counts[vtkCreaseVotingFeatures::BORDER]);
    return line;
  }

  void PrintSummary() const
  {
    const Settings& s = this->S;
    vtkFeaturePointDetector* filter = this->Filter;
    const vtkIdType n = this->TotalPoints;
    const vtkIdType features = filter->GetNumberOfFeaturePoints();
    std::printf("input       %s: %lld points\n", s.Input.c_str(), static_cast<long long>(n));
    std::printf("method      %s, mean spacing %.6g%s\n", this->M->Name,
      filter->GetMeanSpacing() * LengthUnit,
      this->M->Details ? this->M->Details(filter).c_str() : "");
    if (filter->GetNumberOfCandidates() == 0)
    {
      std::printf("threshold   none: no point was scored\n");
    }
    else
    {
      std::printf("threshold   %s > %.6g (%s)%s\n", filter->GetScoreArrayName(),
        filter->GetThresholdUsed(),
        filter->GetThresholdMode() == vtkFeaturePointDetector::AUTOMATIC
          ? (FormatNumber(filter->GetThresholdSigmas()) + " robust standard deviations above the "
                                                          "median")
              .c_str()
          : "absolute",
        std::isnan(this->Grown) ? ""
                                : (", then grown along the features through " +
                                    std::string(filter->GetScoreArrayName()) + " > " +
                                    FormatNumber(this->Grown) +
                                    "; unexplained details and borders join")
                                    .c_str());
    }
    vtkCreaseVotingFeatures* crease = vtkCreaseVotingFeatures::SafeDownCast(filter);
    const vtkIdType outliers = crease ? crease->GetNumberOfOutliers() : 0;
    std::printf("candidates  %lld of %lld points scored%s\n",
      static_cast<long long>(filter->GetNumberOfCandidates()), static_cast<long long>(n),
      outliers > 0
        ? (" (" + std::to_string(outliers) + (outliers == 1 ? " outlier" : " outliers") +
            " left out: off their surface)")
            .c_str()
        : "");
    std::printf("features    %lld (%.2f %%)\n", static_cast<long long>(features),
      100.0 * features / std::max<vtkIdType>(n, 1));
    const std::string types = this->TypeCounts();
    if (!types.empty())
    {
      std::printf("types       %s\n", types.c_str());
    }
    std::printf(
      "output      %s%s\n", s.Output.c_str(), s.FeaturesOnly ? " (feature points only)" : "");
    if (!s.Lines.empty())
    {
      // The sum of finite lengths can pass the largest double (see ExtractCurves).
      const double total = std::ldexp(this->Curves->GetTotalLength(), -this->Exponent);
      char length[64];
      if (std::isfinite(total))
      {
        std::snprintf(length, sizeof(length), "%.6g", total);
      }
      else
      {
        std::snprintf(length, sizeof(length), "above 1.8e308");
      }
      std::printf("curves      %lld, total length %s (%s)\n",
        static_cast<long long>(this->Curves->GetNumberOfCurves()), length, s.Lines.c_str());
    }
    if (!s.Screenshot.empty())
    {
      std::printf("picture     %s (%dx%d)\n", s.Screenshot.c_str(), s.Width, s.Height);
    }
    std::printf("time (s)    ");
    for (size_t i = 0; i < this->Times.size(); ++i)
    {
      std::printf("%s%s %.3f", i ? ", " : "", this->Times[i].first.c_str(), this->Times[i].second);
    }
    std::printf("; total %.3f\n", Seconds(this->Meter->RunStart));
    std::string stages;
    for (int i = 0; i < filter->GetNumberOfStages(); ++i)
    {
      char line[96];
      std::snprintf(line, sizeof(line), "%s%s %.3f", i ? ", " : "", filter->GetStageName(i),
        filter->GetStageTime(i));
      stages += line;
    }
    std::printf("extract (s) %s\n", stages.c_str());
#ifdef FEATUREPOINTS_HAVE_MPI
    if (this->Driver)
    {
      std::printf("ranks       %d, the input read %s%s\n", this->Driver->GetNumberOfRanks(),
        this->ByPieces ? "by every rank (its share of the vertex rows)" : "by rank 0",
        this->Driver->GetDistributed()
          ? ""
          : " (run on rank 0 alone: this method with these options is not distributed yet, or the "
            "cloud is too small to split)");
      for (int r = 0; r < this->Driver->GetNumberOfRanks(); ++r)
      {
        std::printf("rank %-6d %lld own points, %lld halo points\n", r,
          static_cast<long long>(this->Driver->GetNumberOfOwnedPoints(r)),
          static_cast<long long>(this->Driver->GetNumberOfHaloPoints(r)));
      }
    }
#endif
  }

  const Settings& S;
  const Method* M;
  vtkNew<Progress> Meter; // progress on the terminal
  std::vector<std::pair<std::string, double>> Times;
  vtkNew<vtkPointCloudReader> Reader;
  vtkSmartPointer<vtkPointSet> Cloud; // under mpiexec: this process's piece
  vtkIdType TotalPoints = 0;          // the whole cloud's points
  vtkIdType FirstPoint = 0;           // where this process's piece starts in the file
  vtkSmartPointer<vtkIdTypeArray> FilePointIds; // see TakeFilePoints
  vtkSmartPointer<vtkIdTypeArray> FileLines;
  bool ByPieces = false;              // each process read its share of the file
  vtkSmartPointer<vtkFeaturePointDetector> Filter;
#ifdef FEATUREPOINTS_HAVE_MPI
  vtkSmartPointer<vtkDistributedFeaturePoints> Driver;
#endif
  vtkPolyData* Result = nullptr;
  int Exponent = 0; // the scaled frame's power of two (see ScaledFrameExponent), 0: none
  bool OffsetsForCurves = false; // CreaseOffset turned on for --lines only (see Extract)
  vtkSmartPointer<vtkDataArray> FrameOffsets; // CreaseOffset in the scaled frame (see Extract)
  double Grown = std::nan(""); // see Method::GrowThreshold
  vtkNew<vtkFeatureCurveExtraction> Curves;
  std::string PictureFile;
};
} // namespace

int main(int argc, char* argv[])
{
  // VTK's messages come through the output window, as one line each, and never through VTK's
  // logger (which prints them again, with a time stamp, on stderr).
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  vtkNew<OneLineOutputWindow> messages;
  vtkOutputWindow::SetInstance(messages);
#ifdef FEATUREPOINTS_HAVE_MPI
  // MPI only when mpiexec started several processes: a plain run neither needs nor starts it.
  vtkNew<vtkMPIController> processes;
  if (LaunchedProcesses() > 1)
  {
    processes->Initialize(&argc, &argv);
    if (processes->GetNumberOfProcesses() > 1)
    {
      Processes = processes;
      Rank = processes->GetLocalProcessId();
      vtkMultiProcessController::SetGlobalController(processes);
    }
  }
#endif
  const Settings s = ParseArguments(argc, argv);
  if (Rank != 0)
  {
    Quiet = true; // process 0 reports for all
  }
  try
  {
    FeaturePointsRun run(s);
    const int code = FinishStandardOutput(run.Execute(), s.Output);
#ifdef FEATUREPOINTS_HAVE_MPI
    if (Processes)
    {
      Processes->Finalize();
    }
#endif
    return code;
  }
  catch (const std::bad_alloc&)
  {
    RemoveTemporaries(0);
    Fail(ExitFailure, s.Input + ": not enough memory to process this cloud");
  }
  catch (const std::exception& e)
  {
    RemoveTemporaries(0);
    Fail(ExitFailure, s.Input + ": unexpected failure (" + e.what() + ")");
  }
}
