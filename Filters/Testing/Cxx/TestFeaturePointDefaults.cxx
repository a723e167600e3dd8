// The defaults users see outside C++ against the library's own: every default_values and range of
// the ParaView server-manager XML, and every default and range that `featurepoints --help`
// prints, compared with the getters (and the clamp ranges) of default-constructed filters.
//
//   TestFeaturePointDefaults FeaturePoints.xml [FEATUREPOINTS_EXECUTABLE]
//
// The XML is read from the source tree; the CLI part runs only when the executable is given (the
// ParaView plugin build has no CLI). A property or option this test does not know fails the test,
// so that a new one is added here with its getter.
#include "vtkCreaseVotingFeatures.h"
#include "vtkCurvatureDensityFeatures.h"
#include "vtkFeatureCurveExtraction.h"
#include "vtkFeatureModelSource.h"
#include "vtkFeaturePointExtraction.h"
#include "vtkSmartPointer.h"
#include "vtkSmoothShrinkIndexFeatures.h"
#include "vtkSurfaceVariationFeatures.h"
#include "vtkVoxelDensityContrastFilter.h"
#include "vtkXMLDataElement.h"
#include "vtkXMLUtilities.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <map>
#include <memory>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace
{
int Failures = 0;

void Fail(const std::string& what)
{
  std::printf("FAIL: %s\n", what.c_str());
  ++Failures;
}

bool Same(double a, double b)
{
  return a == b || std::fabs(a - b) <= 1e-9 * std::max(std::fabs(a), std::fabs(b));
}

std::string Text(double v)
{
  std::ostringstream s;
  s << v;
  return s.str();
}

// ---------------------------------------------------------------------------------------------
// The properties of the XML: for each setter a proxy calls, the getter that returns its current
// value and, for clamped setters, the clamp range.

struct Property
{
  const char* Class; // the class that declares the setter (subclasses inherit it)
  const char* Command;
  std::function<std::vector<double>(vtkObject*)> Value;
  std::function<double(vtkObject*)> Min = nullptr, Max = nullptr;
};

#define FP_VALUE(cls, name)                                                                        \
  [](vtkObject* o) { return std::vector<double>{ double(cls::SafeDownCast(o)->Get##name()) }; }
#define FP_CLAMPED(cls, name)                                                                      \
  Property                                                                                         \
  {                                                                                                \
    #cls, "Set" #name, FP_VALUE(cls, name),                                                        \
      [](vtkObject* o) { return double(cls::SafeDownCast(o)->Get##name##MinValue()); },            \
      [](vtkObject* o) { return double(cls::SafeDownCast(o)->Get##name##MaxValue()); }             \
  }
#define FP_PLAIN(cls, name)                                                                        \
  Property { #cls, "Set" #name, FP_VALUE(cls, name) }

const std::vector<Property>& Properties()
{
  static const std::vector<Property> properties = {
    FP_CLAMPED(vtkFeaturePointDetector, ThresholdMode),
    FP_PLAIN(vtkFeaturePointDetector, Threshold),
    FP_CLAMPED(vtkFeaturePointDetector, ThresholdSigmas),
    FP_PLAIN(vtkFeaturePointDetector, OutputFeaturesOnly),
    FP_CLAMPED(vtkCreaseVotingFeatures, NumberOfNeighbors),
    FP_CLAMPED(vtkCreaseVotingFeatures, NormalNeighbors),
    FP_CLAMPED(vtkCreaseVotingFeatures, BandWidth),
    FP_CLAMPED(vtkCreaseVotingFeatures, MinimumAngle),
    FP_CLAMPED(vtkCreaseVotingFeatures, GrowThreshold),
    FP_PLAIN(vtkCreaseVotingFeatures, ThinFeatures),
    FP_PLAIN(vtkCreaseVotingFeatures, CreaseOffsets),
    FP_PLAIN(vtkCreaseVotingFeatures, MergeCopies),
    FP_PLAIN(vtkCreaseVotingFeatures, RemoveOutliers),
    FP_PLAIN(vtkCreaseVotingFeatures, Borders),
    FP_PLAIN(vtkCreaseVotingFeatures, MultiScale),
    FP_CLAMPED(vtkFeaturePointExtraction, Alpha),
    FP_CLAMPED(vtkFeaturePointExtraction, NormalNeighbors),
    FP_CLAMPED(vtkFeaturePointExtraction, SSINeighbors),
    FP_CLAMPED(vtkFeaturePointExtraction, DensityNeighbors),
    FP_CLAMPED(vtkFeaturePointExtraction, CenterNeighbors),
    FP_CLAMPED(vtkFeaturePointExtraction, SSICenter),
    FP_CLAMPED(vtkFeaturePointExtraction, GaussianRadiusFactor),
    FP_PLAIN(vtkFeaturePointExtraction, UseVoxelFilter),
    FP_CLAMPED(vtkFeaturePointExtraction, VoxelSizeFactor),
    FP_CLAMPED(vtkFeaturePointExtraction, DensityContrast),
    FP_CLAMPED(vtkFeaturePointExtraction, VoxelContrastRule),
    FP_CLAMPED(vtkSurfaceVariationFeatures, NumberOfNeighbors),
    FP_CLAMPED(vtkCurvatureDensityFeatures, NumberOfNeighbors),
    FP_CLAMPED(vtkCurvatureDensityFeatures, CurvatureWeight),
    FP_CLAMPED(vtkCurvatureDensityFeatures, NormalAngleWeight),
    FP_CLAMPED(vtkCurvatureDensityFeatures, DensityWeight),
    FP_CLAMPED(vtkFeatureModelSource, Model),
    FP_CLAMPED(vtkFeatureModelSource, NumberOfPoints),
    FP_CLAMPED(vtkFeatureModelSource, FeatureDensityFactor),
    FP_CLAMPED(vtkFeatureModelSource, DenseBandWidth),
    FP_CLAMPED(vtkFeatureModelSource, NoiseFactor),
    FP_CLAMPED(vtkFeatureModelSource, Size),
    FP_PLAIN(vtkFeatureModelSource, Seed),
    FP_CLAMPED(vtkFeatureModelSource, ValleySlope),
    FP_CLAMPED(vtkFeatureModelSource, FeatureSeparation),
    FP_CLAMPED(vtkFeatureModelSource, OutputPointsPrecision),
    FP_CLAMPED(vtkFeatureCurveExtraction, FitRadius),
    FP_CLAMPED(vtkFeatureCurveExtraction, StepLength),
    FP_CLAMPED(vtkFeatureCurveExtraction, JoinDistance),
    FP_CLAMPED(vtkFeatureCurveExtraction, MinimumLength),
    Property{ "vtkFeatureModelSource", "SetCenter",
      [](vtkObject* o) {
        const double* c = vtkFeatureModelSource::SafeDownCast(o)->GetCenter();
        return std::vector<double>{ c[0], c[1], c[2] };
      } },
  };
  return properties;
}

const Property* FindProperty(vtkObject* object, const std::string& command)
{
  for (const Property& p : Properties())
  {
    if (command == p.Command && object->IsA(p.Class))
    {
      return &p;
    }
  }
  return nullptr;
}

vtkSmartPointer<vtkObject> MakeObject(const std::string& className)
{
  if (className == "vtkCreaseVotingFeatures")
  {
    return vtkSmartPointer<vtkCreaseVotingFeatures>::New();
  }
  if (className == "vtkFeaturePointExtraction")
  {
    return vtkSmartPointer<vtkFeaturePointExtraction>::New();
  }
  if (className == "vtkSmoothShrinkIndexFeatures")
  {
    return vtkSmartPointer<vtkSmoothShrinkIndexFeatures>::New();
  }
  if (className == "vtkSurfaceVariationFeatures")
  {
    return vtkSmartPointer<vtkSurfaceVariationFeatures>::New();
  }
  if (className == "vtkCurvatureDensityFeatures")
  {
    return vtkSmartPointer<vtkCurvatureDensityFeatures>::New();
  }
  if (className == "vtkFeatureModelSource")
  {
    return vtkSmartPointer<vtkFeatureModelSource>::New();
  }
  if (className == "vtkFeatureCurveExtraction")
  {
    return vtkSmartPointer<vtkFeatureCurveExtraction>::New();
  }
  return nullptr;
}

std::vector<double> Numbers(const char* text)
{
  std::vector<double> values;
  std::istringstream s(text ? text : "");
  double v;
  while (s >> v)
  {
    values.push_back(v);
  }
  return values;
}

// Checks one property element of a proxy; returns whether it had a default to check.
bool CheckProperty(vtkObject* object, const std::string& proxy, vtkXMLDataElement* property)
{
  const char* command = property->GetAttribute("command");
  const char* defaults = property->GetAttribute("default_values");
  const std::string tag = property->GetName();
  if (tag == "InputProperty" || !command || !defaults)
  {
    return false;
  }
  const std::string where = proxy + "." + (property->GetAttribute("name") ? property->GetAttribute("name") : "?");
  const Property* p = FindProperty(object, command);
  if (!p)
  {
    Fail(where + ": no getter known for " + command + " (add it to this test)");
    return false;
  }
  const std::vector<double> expected = p->Value(object);
  const std::vector<double> given = Numbers(defaults);
  bool same = given.size() == expected.size();
  for (size_t i = 0; same && i < given.size(); ++i)
  {
    same = Same(given[i], expected[i]);
  }
  std::string library;
  for (double v : expected)
  {
    library += (library.empty() ? "" : " ") + Text(v);
  }
  if (!same)
  {
    Fail(where + ": default_values \"" + defaults + "\", the filter's default " + library);
  }
  else
  {
    std::printf("  %-48s %s\n", where.c_str(), defaults);
  }
  // The documentation's own "Default X" (or "On (default)" / "Off (default)"), where it says one.
  for (int d = 0; d < property->GetNumberOfNestedElements(); ++d)
  {
    vtkXMLDataElement* doc = property->GetNestedElement(d);
    if (std::string(doc->GetName()) != "Documentation" || !doc->GetCharacterData())
    {
      continue;
    }
    const std::string text = doc->GetCharacterData();
    std::smatch match;
    static const std::regex number("Default (-?[0-9][0-9.e+-]*[0-9]|-?[0-9])");
    static const std::regex flag("(On|Off) \\(default");
    if (std::regex_search(text, match, number) && expected.size() == 1 &&
      !Same(std::atof(match[1].str().c_str()), expected[0]))
    {
      Fail(where + ": its documentation says 'Default " + match[1].str() +
        "', the filter's default is " + library);
    }
    else if (std::regex_search(text, match, flag) && expected.size() == 1 &&
      (match[1].str() == "On") != (expected[0] != 0))
    {
      Fail(where + ": its documentation says '" + match[1].str() + " (default)', the filter's default is " +
        library);
    }
  }
  // Domains: a range must be the setter's clamp range where the setter clamps; an enumeration
  // or a boolean must hold the default.
  for (int d = 0; d < property->GetNumberOfNestedElements(); ++d)
  {
    vtkXMLDataElement* domain = property->GetNestedElement(d);
    const std::string kind = domain->GetName();
    if (kind == "IntRangeDomain" || kind == "DoubleRangeDomain")
    {
      for (const char* bound : { "min", "max" })
      {
        const char* value = domain->GetAttribute(bound);
        const auto& getter = std::string(bound) == "min" ? p->Min : p->Max;
        if (!value || !getter)
        {
          continue;
        }
        const double clamp = getter(object);
        const double xml = std::atof(value);
        // ParaView's panels take -1e+30 for "no bound" on an unclamped double.
        if (!Same(xml, clamp))
        {
          Fail(where + ": range " + bound + " " + value + ", the setter clamps at " + Text(clamp));
        }
      }
    }
    else if (kind == "EnumerationDomain")
    {
      bool found = false;
      for (int e = 0; e < domain->GetNumberOfNestedElements(); ++e)
      {
        const char* value = domain->GetNestedElement(e)->GetAttribute("value");
        found = found || (value && !expected.empty() && Same(std::atof(value), expected[0]));
        if (value && p->Min && p->Max &&
          (std::atof(value) < p->Min(object) || std::atof(value) > p->Max(object)))
        {
          Fail(where + ": enumeration value " + value + " outside the setter's range");
        }
      }
      if (!found)
      {
        Fail(where + ": the default " + library + " is not one of the enumeration's values");
      }
    }
    else if (kind == "BooleanDomain")
    {
      if (expected.size() != 1 || (expected[0] != 0 && expected[0] != 1))
      {
        Fail(where + ": a boolean whose default is " + library);
      }
    }
  }
  return true;
}

int CheckXML(const char* file)
{
  vtkXMLDataElement* root = vtkXMLUtilities::ReadElementFromFile(file);
  if (!root)
  {
    Fail(std::string("cannot read ") + file);
    return 0;
  }
  std::unique_ptr<vtkXMLDataElement, void (*)(vtkXMLDataElement*)> owner(
    root, [](vtkXMLDataElement* e) { e->Delete(); });
  int proxies = 0, checked = 0;
  for (int g = 0; g < root->GetNumberOfNestedElements(); ++g)
  {
    vtkXMLDataElement* group = root->GetNestedElement(g);
    for (int x = 0; x < group->GetNumberOfNestedElements(); ++x)
    {
      vtkXMLDataElement* proxy = group->GetNestedElement(x);
      const char* className = proxy->GetAttribute("class");
      const char* name = proxy->GetAttribute("name");
      if (!className || !name)
      {
        continue;
      }
      vtkSmartPointer<vtkObject> object = MakeObject(className);
      vtkXMLDataElement* hints = proxy->FindNestedElementWithName("Hints");
      if (!object && hints && hints->FindNestedElementWithName("ReaderFactory"))
      {
        // A reader of the IO module (not linked here): it may have file names only, no defaults.
        for (int p = 0; p < proxy->GetNumberOfNestedElements(); ++p)
        {
          vtkXMLDataElement* property = proxy->GetNestedElement(p);
          const std::string kind = property->GetName();
          if (kind.find("Property") != std::string::npos &&
            (kind != "StringVectorProperty" || property->GetAttribute("default_values")))
          {
            Fail(std::string("reader proxy ") + name + ": property " +
              (property->GetAttribute("name") ? property->GetAttribute("name") : "?") +
              " is not a file name; this test cannot check its default");
          }
        }
        std::printf("XML: reader proxy %s (%s): file name only\n", name, className);
        continue;
      }
      if (!object)
      {
        Fail(std::string("proxy ") + name + ": class " + className + " unknown to this test");
        continue;
      }
      ++proxies;
      for (int p = 0; p < proxy->GetNumberOfNestedElements(); ++p)
      {
        checked += CheckProperty(object, name, proxy->GetNestedElement(p)) ? 1 : 0;
      }
    }
  }
  std::printf("XML: %d proxies, %d defaults checked\n", proxies, checked);
  if (proxies < 6 || checked < 50)
  {
    Fail("fewer proxies or defaults than the XML holds (6 proxies, 50 or more defaults)");
  }
  return checked;
}

// ---------------------------------------------------------------------------------------------
// featurepoints --help: each method option ends with "[DEFAULT, MIN to MAX; METHOD: VALUE]",
// then the methods it applies to.

struct Expected
{
  std::set<std::string> Methods; // the methods it applies to
  // The default the help must print for one method's default-constructed filter.
  std::function<std::string(vtkFeaturePointDetector*)> Default;
  // The range, from one of those filters' clamps; null for keywords, flags and unclamped values.
  std::function<std::pair<double, double>(vtkFeaturePointDetector*)> Range = nullptr;
};

vtkFeaturePointExtraction* Extraction(vtkFeaturePointDetector* f)
{
  return vtkFeaturePointExtraction::SafeDownCast(f);
}
vtkCreaseVotingFeatures* Crease(vtkFeaturePointDetector* f)
{
  return vtkCreaseVotingFeatures::SafeDownCast(f);
}
vtkSurfaceVariationFeatures* Variation(vtkFeaturePointDetector* f)
{
  return vtkSurfaceVariationFeatures::SafeDownCast(f);
}
vtkCurvatureDensityFeatures* CurvatureDensity(vtkFeaturePointDetector* f)
{
  return vtkCurvatureDensityFeatures::SafeDownCast(f);
}

#define FP_NUMBER(expr) [](vtkFeaturePointDetector* f) { return Text(double(expr)); }
#define FP_RANGE(object, name)                                                                     \
  [](vtkFeaturePointDetector* f) {                                                                 \
    return std::make_pair(double(object->Get##name##MinValue()), double(object->Get##name##MaxValue())); \
  }

const std::map<std::string, Expected>& CLIOptions()
{
  const std::set<std::string> all = { "crease", "huang2023", "ssi", "pca", "wang-yuan" };
  const std::set<std::string> ours = { "huang2023", "ssi" };
  static const std::map<std::string, Expected> options = {
    { "threshold-sigmas",
      { all, FP_NUMBER(f->GetThresholdSigmas()), FP_RANGE(f, ThresholdSigmas) } },
    { "threshold",
      { all, [](vtkFeaturePointDetector* f) {
          return f->GetThresholdMode() == vtkFeaturePointDetector::ABSOLUTE
            ? Text(f->GetThreshold())
            : std::string("automatic");
        } } },
    { "alpha", { ours, FP_NUMBER(Extraction(f)->GetAlpha()), FP_RANGE(Extraction(f), Alpha) } },
    { "normal-k",
      { { "huang2023", "ssi", "crease" },
        [](vtkFeaturePointDetector* f) {
          return Text(Extraction(f) ? Extraction(f)->GetNormalNeighbors()
                                    : Crease(f)->GetNormalNeighbors());
        },
        [](vtkFeaturePointDetector* f) {
          return Extraction(f) ? std::make_pair(double(Extraction(f)->GetNormalNeighborsMinValue()),
                                   double(Extraction(f)->GetNormalNeighborsMaxValue()))
                               : std::make_pair(double(Crease(f)->GetNormalNeighborsMinValue()),
                                   double(Crease(f)->GetNormalNeighborsMaxValue()));
        } } },
    { "ssi-k",
      { ours, FP_NUMBER(Extraction(f)->GetSSINeighbors()), FP_RANGE(Extraction(f), SSINeighbors) } },
    { "density-k",
      { ours, FP_NUMBER(Extraction(f)->GetDensityNeighbors()),
        FP_RANGE(Extraction(f), DensityNeighbors) } },
    { "center-k",
      { ours, FP_NUMBER(Extraction(f)->GetCenterNeighbors()),
        FP_RANGE(Extraction(f), CenterNeighbors) } },
    { "ssi-center",
      { ours, [](vtkFeaturePointDetector* f) {
          return std::string(
            Extraction(f)->GetSSICenter() == vtkFeaturePointExtraction::POINT ? "point" : "mean");
        } } },
    { "gaussian-radius",
      { ours, FP_NUMBER(Extraction(f)->GetGaussianRadiusFactor()),
        FP_RANGE(Extraction(f), GaussianRadiusFactor) } },
    { "voxel-filter",
      { ours, [](vtkFeaturePointDetector* f) {
          return std::string(Extraction(f)->GetUseVoxelFilter() ? "on" : "off");
        } } },
    { "voxel-size",
      { ours, FP_NUMBER(Extraction(f)->GetVoxelSizeFactor()),
        FP_RANGE(Extraction(f), VoxelSizeFactor) } },
    { "density-contrast",
      { ours, FP_NUMBER(Extraction(f)->GetDensityContrast()),
        FP_RANGE(Extraction(f), DensityContrast) } },
    { "voxel-rule",
      { ours, [](vtkFeaturePointDetector* f) {
          return std::string(Extraction(f)->GetVoxelContrastRule() ==
                vtkVoxelDensityContrastFilter::VOXEL_COUNTS
              ? "counts"
              : "spacing");
        } } },
    { "k",
      { { "pca", "wang-yuan" },
        [](vtkFeaturePointDetector* f) {
          return Text(Variation(f) ? Variation(f)->GetNumberOfNeighbors()
                                   : CurvatureDensity(f)->GetNumberOfNeighbors());
        },
        [](vtkFeaturePointDetector* f) {
          return Variation(f) ? std::make_pair(double(Variation(f)->GetNumberOfNeighborsMinValue()),
                                  double(Variation(f)->GetNumberOfNeighborsMaxValue()))
                              : std::make_pair(
                                  double(CurvatureDensity(f)->GetNumberOfNeighborsMinValue()),
                                  double(CurvatureDensity(f)->GetNumberOfNeighborsMaxValue()));
        } } },
    { "curvature-weight",
      { { "wang-yuan" }, FP_NUMBER(CurvatureDensity(f)->GetCurvatureWeight()),
        FP_RANGE(CurvatureDensity(f), CurvatureWeight) } },
    { "normal-angle-weight",
      { { "wang-yuan" }, FP_NUMBER(CurvatureDensity(f)->GetNormalAngleWeight()),
        FP_RANGE(CurvatureDensity(f), NormalAngleWeight) } },
    { "density-weight",
      { { "wang-yuan" }, FP_NUMBER(CurvatureDensity(f)->GetDensityWeight()),
        FP_RANGE(CurvatureDensity(f), DensityWeight) } },
    { "crease-k",
      { { "crease" }, FP_NUMBER(Crease(f)->GetNumberOfNeighbors()),
        FP_RANGE(Crease(f), NumberOfNeighbors) } },
    { "band-width",
      { { "crease" }, FP_NUMBER(Crease(f)->GetBandWidth()), FP_RANGE(Crease(f), BandWidth) } },
    { "min-angle",
      { { "crease" }, FP_NUMBER(Crease(f)->GetMinimumAngle()),
        FP_RANGE(Crease(f), MinimumAngle) } },
    { "grow-threshold",
      { { "crease" }, FP_NUMBER(Crease(f)->GetGrowThreshold()),
        FP_RANGE(Crease(f), GrowThreshold) } },
    // Flags: "[on]" when the filter already behaves as the flag asks, else "[off]".
    { "thin",
      { { "crease" }, [](vtkFeaturePointDetector* f) {
          return std::string(Crease(f)->GetThinFeatures() ? "on" : "off");
        } } },
    { "no-borders",
      { { "crease" }, [](vtkFeaturePointDetector* f) {
          return std::string(Crease(f)->GetBorders() ? "off" : "on");
        } } },
    { "single-scale",
      { { "crease" }, [](vtkFeaturePointDetector* f) {
          return std::string(Crease(f)->GetMultiScale() ? "off" : "on");
        } } },
    { "keep-copies",
      { { "crease" }, [](vtkFeaturePointDetector* f) {
          return std::string(Crease(f)->GetMergeCopies() ? "off" : "on");
        } } },
    { "keep-outliers",
      { { "crease" }, [](vtkFeaturePointDetector* f) {
          return std::string(Crease(f)->GetRemoveOutliers() ? "off" : "on");
        } } },
    { "crease-offsets",
      { { "crease" }, [](vtkFeaturePointDetector* f) {
          return std::string(Crease(f)->GetCreaseOffsets() ? "on" : "off");
        } } },
  };
  return options;
}

vtkSmartPointer<vtkFeaturePointDetector> MakeMethod(const std::string& method)
{
  const std::map<std::string, std::string> classes = { { "crease", "vtkCreaseVotingFeatures" },
    { "huang2023", "vtkFeaturePointExtraction" }, { "ssi", "vtkSmoothShrinkIndexFeatures" },
    { "pca", "vtkSurfaceVariationFeatures" }, { "wang-yuan", "vtkCurvatureDensityFeatures" } };
  const auto c = classes.find(method);
  return c == classes.end() ? nullptr
                            : vtkFeaturePointDetector::SafeDownCast(MakeObject(c->second));
}

std::string Trim(const std::string& s)
{
  const size_t b = s.find_first_not_of(" ,;");
  const size_t e = s.find_last_not_of(" ,;");
  return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}

std::vector<std::string> Split(const std::string& s, char separator)
{
  std::vector<std::string> parts;
  std::istringstream in(s);
  std::string part;
  while (std::getline(in, part, separator))
  {
    parts.push_back(Trim(part));
  }
  return parts;
}

// The help text of one option ("--name ARG" line and its indented continuation) -> the
// checks of its bracket.
void CheckOption(const std::string& name, const std::string& text)
{
  const auto found = CLIOptions().find(name);
  if (found == CLIOptions().end())
  {
    Fail("--" + name + ": an option this test does not know (add it with its getter)");
    return;
  }
  const Expected& expected = found->second;
  const size_t open = text.rfind('['), close = text.rfind(']');
  if (open == std::string::npos || close == std::string::npos || close < open)
  {
    Fail("--" + name + ": no [default] in its help");
    return;
  }
  // The methods it applies to: after "]; ", or all when nothing follows.
  std::set<std::string> methods;
  for (const std::string& m : Split(text.substr(close + 1), ','))
  {
    if (!m.empty())
    {
      methods.insert(m);
    }
  }
  if (methods.empty())
  {
    methods = CLIOptions().at("threshold-sigmas").Methods;
  }
  if (methods != expected.Methods)
  {
    Fail("--" + name + ": the help lists other methods than the library's options apply to");
  }
  // "DEFAULT[, MIN to MAX]" then "; METHOD: VALUE" for the methods that differ.
  const std::vector<std::string> parts = Split(text.substr(open + 1, close - open - 1), ';');
  std::map<std::string, std::string> shown;
  const std::vector<std::string> head = Split(parts[0], ',');
  for (const std::string& m : methods)
  {
    shown[m] = head[0];
  }
  for (size_t i = 1; i < parts.size(); ++i)
  {
    const size_t colon = parts[i].find(':');
    if (colon == std::string::npos)
    {
      Fail("--" + name + ": cannot read '" + parts[i] + "'");
      continue;
    }
    for (const std::string& m : Split(parts[i].substr(0, colon), ','))
    {
      shown[m] = Trim(parts[i].substr(colon + 1));
    }
  }
  for (const std::string& m : expected.Methods)
  {
    vtkSmartPointer<vtkFeaturePointDetector> filter = MakeMethod(m);
    const std::string library = expected.Default(filter);
    const std::string help = shown[m];
    char* end = nullptr;
    const double number = std::strtod(help.c_str(), &end);
    const bool numeric = !help.empty() && end && *end == '\0';
    if (numeric ? !Same(number, std::atof(library.c_str())) : help != library)
    {
      Fail("--" + name + " for " + m + ": the help says " + help + ", the filter's default is " +
        library);
    }
    if (expected.Range && head.size() > 1)
    {
      const std::pair<double, double> clamp = expected.Range(filter);
      const size_t to = head[1].find(" to ");
      const double low = std::atof(head[1].substr(0, to).c_str());
      const std::string highText = to == std::string::npos ? "" : Trim(head[1].substr(to + 4));
      const double high = highText == "any" ? clamp.second : std::atof(highText.c_str());
      if (to == std::string::npos || !Same(low, clamp.first) || !Same(high, clamp.second) ||
        (highText == "any" && clamp.second < VTK_DOUBLE_MAX))
      {
        Fail("--" + name + " for " + m + ": the help's range " + head[1] + ", the setter clamps to " +
          Text(clamp.first) + " to " + Text(clamp.second));
      }
    }
    else if (expected.Range)
    {
      Fail("--" + name + ": no range in its help");
    }
  }
  std::printf("  --%-22s %s\n", name.c_str(), text.substr(open, close - open + 1).c_str());
}

int CheckCLI(const char* executable)
{
  const std::string command = std::string("\"") + executable + "\" --help";
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe)
  {
    Fail("cannot run " + command);
    return 0;
  }
  std::string output;
  char buffer[4096];
  size_t got;
  while ((got = std::fread(buffer, 1, sizeof(buffer), pipe)) > 0)
  {
    output.append(buffer, got);
  }
  if (pclose(pipe) != 0)
  {
    Fail(command + " did not exit with 0");
  }
  const size_t section = output.find("Method options");
  if (section == std::string::npos)
  {
    Fail("no 'Method options' section in the help");
    return 0;
  }
  // Each option: a line "  --name ARG", then lines indented further, up to a blank line or the
  // next option.
  std::istringstream lines(output.substr(section));
  std::string line, name, text;
  std::set<std::string> seen;
  auto finish = [&]() {
    if (!name.empty())
    {
      CheckOption(name, text);
      seen.insert(name);
    }
    name.clear();
    text.clear();
  };
  std::getline(lines, line); // the section's title
  while (std::getline(lines, line))
  {
    if (line.compare(0, 4, "  --") == 0)
    {
      finish();
      const size_t end = line.find(' ', 4);
      name = line.substr(4, end == std::string::npos ? std::string::npos : end - 4);
    }
    else if (line.empty() || line[0] != ' ')
    {
      finish();
      break;
    }
    else
    {
      text += " " + line.substr(line.find_first_not_of(' '));
    }
  }
  finish();
  for (const auto& option : CLIOptions())
  {
    if (!seen.count(option.first))
    {
      Fail("--" + option.first + " is missing from the help");
    }
  }
  std::printf("CLI: %zu method options checked\n", seen.size());
  return static_cast<int>(seen.size());
}
}

int TestFeaturePointDefaults(int argc, char* argv[])
{
  if (argc < 2)
  {
    std::printf("usage: TestFeaturePointDefaults FeaturePoints.xml [featurepoints]\n");
    return EXIT_FAILURE;
  }
  std::printf("ParaView XML %s: default_values against the filters' getters\n", argv[1]);
  CheckXML(argv[1]);
  if (argc > 2)
  {
    std::printf("%s --help: defaults and ranges against the filters' getters\n", argv[2]);
    CheckCLI(argv[2]);
  }
  if (Failures)
  {
    std::printf("%d disagreement(s)\n", Failures);
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
