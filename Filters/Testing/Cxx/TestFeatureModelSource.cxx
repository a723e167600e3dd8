// vtkFeatureModelSource: the ground truth agrees with the geometry, the sampling and the noise are
// what the parameters say, and a seed gives the same cloud every time.
#include "FeaturePointsTestRun.h"
#include "vtkFeatureModelSource.h"
#include "vtkFieldData.h"

#include <algorithm>
#include <array>
#include <cfloat>
#include <functional>
#include <set>
#include <string>

namespace
{
vtkSmartPointer<vtkPolyData> Generate(int model, vtkIdType n, double density, double noise,
  unsigned seed = 1, double separation = 5.0)
{
  vtkNew<vtkFeatureModelSource> source;
  source->SetModel(model);
  source->SetNumberOfPoints(n);
  source->SetFeatureDensityFactor(density);
  source->SetNoiseFactor(noise);
  source->SetSeed(seed);
  source->SetFeatureSeparation(separation);
  source->Update();
  return source->GetOutput();
}
double Field(vtkPolyData* p, const char* name)
{
  return p->GetFieldData()->GetArray(name)->GetComponent(0, 0);
}

// Distance from p to the segment a-b.
double SegmentDistance(const double p[3], const double a[3], const double b[3])
{
  double ab[3], ap[3];
  for (int k = 0; k < 3; ++k)
  {
    ab[k] = b[k] - a[k];
    ap[k] = p[k] - a[k];
  }
  const double t = std::min(1.0,
    std::max(0.0, (ap[0] * ab[0] + ap[1] * ab[1] + ap[2] * ab[2]) / (ab[0] * ab[0] + ab[1] * ab[1] + ab[2] * ab[2])));
  return std::sqrt(std::pow(ap[0] - t * ab[0], 2) + std::pow(ap[1] - t * ab[1], 2) + std::pow(ap[2] - t * ab[2], 2));
}

// The blob's radius in the unit direction u, for the model's size: the formula of the class
// documentation, 0.5 Size (1 + 0.15 (sin^2 phi cos 2 theta + 0.7 sin 2 phi sin theta + 0.6 P3)).
double BlobRadius(const double u[3], double size)
{
  const double x = u[0], y = u[1], z = u[2];
  return 0.5 * size * (1.0 + 0.15 * ((x * x - y * y) + 0.7 * 2.0 * y * z + 0.6 * 0.5 * (5.0 * z * z * z - 3.0 * z)));
}

// The L profile of the bracket in the (x, z) plane, in Size units (class documentation): bottom,
// free end 0.18 thick, top rising at 20 degrees for 0.4, flat top 0.3 wide, upright 0.3 x 0.6.
void BracketProfile(double x[7], double z[7])
{
  const double zc = -0.12 + 0.4 * std::tan(20.0 * M_PI / 180.0);
  const double px[7] = { -0.5, 0.5, 0.5, 0.1, -0.2, -0.2, -0.5 };
  const double pz[7] = { -0.3, -0.3, -0.12, zc, zc, 0.3, 0.3 };
  std::copy(px, px + 7, x);
  std::copy(pz, pz + 7, z);
}

// Positives expected: within 2 s of L units of feature curves lie about 2 (2 s) L of area, within
// the band B = DenseBandWidth nominal spacings about 2 B L, sampled FeatureDensityFactor times
// denser than the rest of the area A (the corners' overlaps neglected). A border has the surface
// on one side only: it counts as half its length.
double ExpectedPositiveFraction(double area, double length, double s, vtkIdType n, double factor)
{
  const double band = 5.0 * std::sqrt(area / static_cast<double>(n));
  const double positive = 4.0 * s * length, banded = std::min(area, 2.0 * band * length);
  return factor * positive / (factor * banded + area - banded);
}

// The length L = F x that PARALLEL_CREASES and THIN_PLATE are built with (class documentation), x
// being the nominal spacing sqrt(area / n) of the model so built, whose area is a0 + a1 L: the
// ribs' model has a0 = Size^2 and a1 = 6 Size (six walls L high), the plate a0 = 1.2 Size^2 and
// a1 = 3.2 Size (its rim, L high). Solved here from that promise alone.
double SeparationLength(double a0, double a1, vtkIdType n, double factor)
{
  const double b = a1 * factor, count = static_cast<double>(n);
  return factor * (b + std::sqrt(b * b + 4.0 * count * a0)) / (2.0 * count);
}

// The ground truth of a model recomputed here from its documented geometry, at a clean point p:
// the distance to the surface, delta (to the nearest feature curve), and the FeatureType a
// positive has there, given the corners' radius 2 s.
struct Truth
{
  double Surface, Delta;
  int Type;
};
using TruthFunction = std::function<Truth(const double p[3], double radius)>;

// A clean cloud (NoiseFactor 0) against its ground truth: every point on the surface (within
// 1e-9 Size), its FeatureDistance the recomputed delta, GroundTruth delta <= 2 s and FeatureType
// the recomputed type on the positives, 0 elsewhere.
void CheckClean(const std::string& name, vtkPolyData* cloud, const TruthFunction& truth,
  int& failures)
{
  vtkDataArray* d = cloud->GetPointData()->GetArray("FeatureDistance");
  vtkDataArray* labels = cloud->GetPointData()->GetArray("GroundTruth");
  vtkDataArray* types = cloud->GetPointData()->GetArray("GroundTruthType");
  FP_CHECK(d && labels && types, "%s: arrays", name.c_str());
  if (!d || !labels || !types)
  {
    return;
  }
  const double twoS = 2.0 * Field(cloud, "CleanMeanSpacing"), tol = 1e-9 * 100.0; // Size 100
  double surface = 0.0, error = 0.0;
  long wrongLabel = 0, wrongType = 0;
  for (vtkIdType i = 0; i < cloud->GetNumberOfPoints(); ++i)
  {
    double p[3];
    cloud->GetPoint(i, p);
    const Truth t = truth(p, twoS);
    const bool positive = t.Delta <= twoS;
    surface = std::max(surface, t.Surface);
    error = std::max(error, std::abs(t.Delta - d->GetComponent(i, 0)));
    wrongLabel += (labels->GetComponent(i, 0) != 0) != positive;
    wrongType += types->GetComponent(i, 0) != (positive ? t.Type : 0);
  }
  std::printf("%s clean: surface error %.2e, distance error %.2e, %ld wrong labels, %ld wrong "
              "types\n", name.c_str(), surface, error, wrongLabel, wrongType);
  FP_CHECK(surface < tol && error < tol && wrongLabel == 0 && wrongType == 0,
    "%s: surface %g, distance %g, %ld wrong labels, %ld wrong types", name.c_str(), surface, error,
    wrongLabel, wrongType);
}

// The box of half-edges hx, hy, hz centred on the origin (BOX, THIN_PLATE): its edges are convex,
// its corners are where the three coordinates are on their faces.
TruthFunction BoxTruth(double hx, double hy, double hz)
{
  return [=](const double p[3], double radius) {
    const double half[3] = { hx, hy, hz };
    double g[3], face = DBL_MAX, outside = -DBL_MAX;
    for (int k = 0; k < 3; ++k)
    {
      g[k] = std::abs(p[k]) - half[k]; // <= 0 inside, 0 on the faces normal to axis k
      outside = std::max(outside, g[k]);
      face = std::min(face, std::abs(g[k]));
    }
    // The edges along axis k lie where the other two coordinates are on their faces.
    const double edge =
      std::min({ std::hypot(g[1], g[2]), std::hypot(g[0], g[2]), std::hypot(g[0], g[1]) });
    const double corner = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
    return Truth{ std::max(face, outside), edge,
      corner <= radius ? vtkFeatureModelSource::CORNER : vtkFeatureModelSource::CONVEX_CREASE };
  };
}

// PARALLEL_CREASES of rib pitch d: the profile z(x) with three ribs d wide and high, d apart,
// centred on x = 0; their feet are concave, their top edges convex.
TruthFunction RibsTruth(double size, double d)
{
  std::vector<std::array<double, 2>> profile{ { -0.5 * size, 0.0 } };
  for (int k = 0; k < 3; ++k)
  {
    const double left = (2 * k - 2.5) * d;
    profile.insert(profile.end(), { { left, 0.0 }, { left, d }, { left + d, d }, { left + d, 0.0 } });
  }
  profile.push_back({ 0.5 * size, 0.0 });
  return [=](const double p[3], double) {
    Truth t{ DBL_MAX, DBL_MAX, 0 };
    const double q[3] = { p[0], 0.0, p[2] };
    for (size_t k = 0; k + 1 < profile.size(); ++k)
    {
      const double a[3] = { profile[k][0], 0.0, profile[k][1] };
      const double b[3] = { profile[k + 1][0], 0.0, profile[k + 1][1] };
      t.Surface = std::min(t.Surface, SegmentDistance(q, a, b));
      const double crease = std::hypot(p[0] - a[0], p[2] - a[2]);
      if (k > 0 && crease < t.Delta)
      {
        t.Delta = crease;
        t.Type = a[2] > 0.0 ? vtkFeatureModelSource::CONVEX_CREASE
                            : vtkFeatureModelSource::CONCAVE_CREASE;
      }
    }
    t.Surface += std::max(0.0, std::abs(p[1]) - 0.5 * size);
    return t;
  };
}

// HALF_CYLINDER: radius 0.3 Size around z, y >= 0, |z| <= 0.5 Size; its borders, the half circles
// and the lines x = +-0.3 Size, y = 0, meet at four corners.
TruthFunction HalfCylinderTruth(double size)
{
  return [=](const double p[3], double radius) {
    const double r = 0.3 * size, h = 0.5 * size, rho = std::hypot(p[0], p[1]);
    const double surface =
      std::abs(rho - r) + std::max(0.0, -p[1]) + std::max(0.0, std::abs(p[2]) - h);
    const double delta = std::min({ std::hypot(rho - r, h - std::abs(p[2])),
      std::hypot(p[0] - r, p[1]), std::hypot(p[0] + r, p[1]) });
    const double corner = std::hypot(std::hypot(std::abs(p[0]) - r, p[1]), h - std::abs(p[2]));
    return Truth{ surface, delta,
      corner <= radius ? vtkFeatureModelSource::CORNER : vtkFeatureModelSource::BORDER };
  };
}

// PLATE_WITH_HOLE: the square |x|, |y| <= 0.5 Size in z = 0 less the disk of radius 0.2 Size; its
// borders, the square and the circle; corners, the square's.
TruthFunction PlateWithHoleTruth(double size)
{
  return [=](const double p[3], double radius) {
    const double h = 0.5 * size, r = 0.2 * size, rho = std::hypot(p[0], p[1]);
    const double surface = std::abs(p[2]) + std::max(0.0, std::abs(p[0]) - h) +
      std::max(0.0, std::abs(p[1]) - h) + std::max(0.0, r - rho);
    const double delta = std::min({ h - std::abs(p[0]), h - std::abs(p[1]), rho - r });
    const double corner = std::hypot(h - std::abs(p[0]), h - std::abs(p[1]));
    return Truth{ surface, delta,
      corner <= radius ? vtkFeatureModelSource::CORNER : vtkFeatureModelSource::BORDER };
  };
}

// FeatureDistance at the point nearest the position q, against the distance `expected` of q to
// the features: delta is 1-Lipschitz, so the two differ by at most the point's distance to q.
void CheckHandPicked(const std::string& name, vtkPolyData* cloud, const std::array<double, 3>& q,
  double expected, int& failures)
{
  vtkIdType nearest = 0;
  double best = DBL_MAX;
  for (vtkIdType i = 0; i < cloud->GetNumberOfPoints(); ++i)
  {
    double p[3];
    cloud->GetPoint(i, p);
    const double gap = std::hypot(std::hypot(p[0] - q[0], p[1] - q[1]), p[2] - q[2]);
    if (gap < best)
    {
      best = gap;
      nearest = i;
    }
  }
  const double delta = cloud->GetPointData()->GetArray("FeatureDistance")->GetComponent(nearest, 0);
  const double s = Field(cloud, "CleanMeanSpacing");
  std::printf("%s at (%g, %g, %g): FeatureDistance %.4f of the point %.4f away, %.4f expected\n",
    name.c_str(), q[0], q[1], q[2], delta, best, expected);
  FP_CHECK(best < 5.0 * s && std::abs(delta - expected) <= best + 1e-9,
    "%s at (%g, %g, %g): FeatureDistance %g of the point %g away, %g expected", name.c_str(), q[0],
    q[1], q[2], delta, best, expected);
}

// How many points of each FeatureType.
std::array<long, 5> TypeCounts(vtkPolyData* cloud)
{
  std::array<long, 5> counts{};
  vtkDataArray* types = cloud->GetPointData()->GetArray("GroundTruthType");
  for (vtkIdType i = 0; types && i < types->GetNumberOfTuples(); ++i)
  {
    const int t = static_cast<int>(types->GetComponent(i, 0));
    counts[std::min(4, std::max(0, t))]++;
  }
  return counts;
}
} // namespace

int TestFeatureModelSource(int, char*[])
{
  using namespace fptest;
  int failures = 0;
  const double size = 100.0, h = 50.0;

  // Model I without noise: every point on the profile z(x), and its distance to the nearest of
  // the three creases (x = -15, 0, 15 at the profile's corners) recomputed here.
  auto clean = Generate(vtkFeatureModelSource::MODEL_I, 20000, 3.0, 0.0);
  const double a = 0.15 * size, depth = a * std::tan(30.0 * M_PI / 180.0);
  vtkDataArray* delta = clean->GetPointData()->GetArray("FeatureDistance");
  vtkDataArray* truth = clean->GetPointData()->GetArray("GroundTruth");
  vtkDataArray* type = clean->GetPointData()->GetArray("GroundTruthType");
  const double s = Field(clean, "CleanMeanSpacing");
  FP_CHECK(clean->GetNumberOfPoints() == 20000 && delta && truth && type, "output shape");
  FP_CHECK(s > 0.0 && Field(clean, "NoiseSigma") == 0.0, "s %g", s);
  double worstSurface = 0.0, worstDelta = 0.0;
  long wrongLabel = 0, wrongType = 0;
  for (vtkIdType i = 0; delta && truth && type && i < clean->GetNumberOfPoints(); ++i)
  {
    double p[3];
    clean->GetPoint(i, p);
    const double z = std::abs(p[0]) < a ? -depth * (1.0 - std::abs(p[0]) / a) : 0.0;
    worstSurface = std::max(worstSurface, std::abs(p[2] - z));
    // The shoulders are convex, the valley floor concave; no corner (the sheet's edges are not
    // features).
    const double corners[3][2] = { { -a, 0.0 }, { 0.0, -depth }, { a, 0.0 } };
    double d = VTK_DOUBLE_MAX;
    int nearest = 0;
    for (int k = 0; k < 3; ++k)
    {
      const double dk = std::hypot(p[0] - corners[k][0], p[2] - corners[k][1]);
      nearest = dk < d ? k : nearest;
      d = std::min(d, dk);
    }
    const int expectedType = d > 2.0 * s ? 0
      : nearest == 1                     ? vtkFeatureModelSource::CONCAVE_CREASE
                                         : vtkFeatureModelSource::CONVEX_CREASE;
    worstDelta = std::max(worstDelta, std::abs(d - delta->GetComponent(i, 0)));
    wrongLabel += (truth->GetComponent(i, 0) != 0) != (d <= 2.0 * s);
    wrongType += type->GetComponent(i, 0) != expectedType;
    FP_CHECK(std::abs(p[1]) <= h + 1e-9 && std::abs(p[0]) <= h + 1e-9, "point %lld outside the sheet", (long long)i);
  }
  std::printf("Model I clean: s %.4f, surface error %.2e, distance error %.2e, %ld wrong labels, "
              "%ld wrong types\n", s, worstSurface, worstDelta, wrongLabel, wrongType);
  FP_CHECK(worstSurface < 1e-9, "a point is off the surface by %g", worstSurface);
  FP_CHECK(worstDelta < 1e-9, "FeatureDistance off by %g", worstDelta);
  FP_CHECK(wrongLabel == 0, "%ld ground-truth labels disagree with delta <= 2 s", wrongLabel);
  FP_CHECK(wrongType == 0, "%ld FeatureType values disagree with the nearest crease", wrongType);

  // Denser band: the points within the band are 3x as dense as the rest, by area. Compare the
  // density in the band's core (delta < 0.5 band) with the flat parts far from any crease.
  {
    const double nominal = std::sqrt(size * size / 20000.0 * (1.0 + 2 * a * (1.0 / std::cos(30.0 * M_PI / 180.0) - 1.0) / size));
    const double core = 2.0 * nominal; // well inside the 5-spacing band
    long inCore = 0, inFar = 0;
    for (vtkIdType i = 0; i < clean->GetNumberOfPoints(); ++i)
    {
      double p[3];
      clean->GetPoint(i, p);
      inCore += p[0] > a && p[0] - a < core; // the flat side of the crease at x = a
      inFar += p[0] > 30.0 && p[0] < 40.0;
    }
    // Areas: the core strip on the flat side of the x = a crease is core wide, the far strip 10.
    const double ratio = (inCore / core) / (inFar / 10.0);
    std::printf("density ratio band/far: %.2f (FeatureDensityFactor 3)\n", ratio);
    FP_CHECK(ratio > 2.4 && ratio < 3.6, "density ratio %.2f, expected about 3", ratio);
  }

  // Noise: on the flat far parts, z has the standard deviation NoiseFactor * s.
  auto noisy = Generate(vtkFeatureModelSource::MODEL_I, 20000, 3.0, 0.5);
  {
    double sum2 = 0.0;
    long count = 0;
    for (vtkIdType i = 0; i < noisy->GetNumberOfPoints(); ++i)
    {
      double p[3];
      noisy->GetPoint(i, p);
      if (std::abs(p[0]) > 25.0 && std::abs(p[0]) < 45.0)
      {
        sum2 += p[2] * p[2];
        ++count;
      }
    }
    const double sigma = std::sqrt(sum2 / count);
    const double expected = Field(noisy, "NoiseSigma");
    std::printf("noise: measured sigma %.4f, NoiseSigma %.4f = 0.5 s (s %.4f)\n", sigma, expected,
      Field(noisy, "CleanMeanSpacing"));
    FP_CHECK(std::abs(expected - 0.5 * Field(noisy, "CleanMeanSpacing")) < 1e-12, "NoiseSigma");
    FP_CHECK(std::abs(sigma / expected - 1.0) < 0.05, "sigma %.4f vs %.4f", sigma, expected);
  }

  // Same seed, same cloud; another seed, another cloud.
  auto again = Generate(vtkFeatureModelSource::MODEL_I, 20000, 3.0, 0.5);
  auto other = Generate(vtkFeatureModelSource::MODEL_I, 20000, 3.0, 0.5, 2);
  long same = 0, differ = 0;
  for (vtkIdType i = 0; i < noisy->GetNumberOfPoints(); ++i)
  {
    double p[3], q[3], r[3];
    noisy->GetPoint(i, p);
    again->GetPoint(i, q);
    other->GetPoint(i, r);
    same += p[0] == q[0] && p[1] == q[1] && p[2] == q[2];
    differ += p[0] != r[0];
  }
  FP_CHECK(same == 20000 && differ > 19000, "seed: %ld identical, %ld differ", same, differ);

  // Model II and III: every positive point lies near a crease of the geometry; Model III's delta
  // is the distance to the circle of radius 25 in z = 0.
  auto m3 = Generate(vtkFeatureModelSource::MODEL_III, 20000, 1.0, 0.0);
  double worst3 = 0.0;
  for (vtkIdType i = 0; i < m3->GetNumberOfPoints(); ++i)
  {
    double p[3];
    m3->GetPoint(i, p);
    const double d = std::hypot(std::hypot(p[0], p[1]) - 25.0, p[2]);
    worst3 = std::max(worst3, std::abs(d - m3->GetPointData()->GetArray("FeatureDistance")->GetComponent(i, 0)));
  }
  FP_CHECK(worst3 < 1e-9, "Model III distance off by %g", worst3);
  auto m2 = Generate(vtkFeatureModelSource::MODEL_II, 20000, 3.0, 0.5);
  const long positives2 = CountSet(vtkUnsignedCharArray::SafeDownCast(m2->GetPointData()->GetArray("GroundTruth")));
  std::printf("Model II: %ld positives of 20000; Model III distance error %.2e\n", positives2, worst3);
  FP_CHECK(positives2 > 1000 && positives2 < 10000, "Model II positives %ld", positives2);

  // The sphere has no feature: no positive, finite distances.
  auto sphere = Generate(vtkFeatureModelSource::SPHERE, 5000, 3.0, 0.5);
  const long positivesS = CountSet(vtkUnsignedCharArray::SafeDownCast(sphere->GetPointData()->GetArray("GroundTruth")));
  FP_CHECK(positivesS == 0, "sphere: %ld positives", positivesS);
  FP_CHECK(std::isfinite(sphere->GetPointData()->GetArray("FeatureDistance")->GetComponent(0, 0)), "sphere distance");

  // The closed parts the defaults were not tuned on, and the blob, as a benchmark makes them (the
  // model's own count, features 3x denser, sigma = 0.5 s): count, names, finite non-negative
  // distances (VTK_FLOAT_MAX on the blob), labels = delta <= 2 s, and a plausible share of
  // positives against the feature length (in Size units, borders counted half) and area (in
  // Size^2). The models of close and bordered features likewise, but sampled uniformly: the
  // estimate's denser bands would overlap between creases a few spacings apart. Their rib pitch
  // and plate thickness follow from FeatureSeparation 5 at 100,000 points.
  struct Part
  {
    int Model;
    const char* Name;
    vtkIdType Count;
    double Length, Area, Density;
  };
  const double rib = SeparationLength(1.0, 6.0, 100000, 5.0);
  const double plate = SeparationLength(1.2, 3.2, 100000, 5.0);
  double bx[7], bz[7], perimeter = 0.0, profileArea = 0.0;
  BracketProfile(bx, bz);
  for (int k = 0; k < 7; ++k)
  {
    const int l = (k + 1) % 7;
    perimeter += std::hypot(bx[l] - bx[k], bz[l] - bz[k]);
    profileArea += 0.5 * (bx[k] * bz[l] - bx[l] * bz[k]);
  }
  const Part parts[] = {
    { vtkFeatureModelSource::BOX, "Box", 100000, 4.0 * (1.0 + 0.7 + 0.5),
      2.0 * (0.7 + 0.5 + 0.35), 3.0 },
    { vtkFeatureModelSource::CYLINDER, "Cylinder", 80000, 2.0 * 2.0 * M_PI * 0.3,
      2.0 * M_PI * 0.3 * 0.6 + 2.0 * M_PI * 0.09, 3.0 },
    { vtkFeatureModelSource::BRACKET, "Bracket", 120000, 7 * 0.5 + 2.0 * perimeter,
      0.5 * perimeter + 2.0 * profileArea, 3.0 },
    { vtkFeatureModelSource::BLOB, "Blob", 100000, 0.0, 0.0, 3.0 },
    { vtkFeatureModelSource::PARALLEL_CREASES, "Parallel creases", 100000, 12.0, 1.0 + 6.0 * rib,
      1.0 },
    { vtkFeatureModelSource::THIN_PLATE, "Thin plate", 100000, 4.0 * (1.0 + 0.6 + plate),
      1.2 + 3.2 * plate, 1.0 },
    { vtkFeatureModelSource::HALF_CYLINDER, "Half cylinder", 100000, 0.5 * (2.0 + 2.0 * M_PI * 0.3),
      M_PI * 0.3, 1.0 },
    { vtkFeatureModelSource::PLATE_WITH_HOLE, "Plate with hole", 100000,
      0.5 * (4.0 + 2.0 * M_PI * 0.2), 1.0 - M_PI * 0.04, 1.0 },
    { vtkFeatureModelSource::TORUS, "Torus", 100000, 0.0, 0.0, 3.0 },
    { vtkFeatureModelSource::ELLIPSOID, "Ellipsoid", 100000, 0.0, 0.0, 3.0 },
  };
  for (const Part& part : parts)
  {
    vtkNew<vtkFeatureModelSource> source;
    source->SetModel(part.Model);
    source->SetFeatureDensityFactor(part.Density);
    source->Update();
    vtkPolyData* out = source->GetOutput();
    const vtkIdType n = out->GetNumberOfPoints();
    vtkDataArray* dist = out->GetPointData()->GetArray("FeatureDistance");
    auto* labels = vtkUnsignedCharArray::SafeDownCast(out->GetPointData()->GetArray("GroundTruth"));
    const double sp = Field(out, "CleanMeanSpacing");
    FP_CHECK(source->GetModel() == part.Model && n == part.Count &&
        vtkFeatureModelSource::GetDefaultNumberOfPoints(part.Model) == part.Count &&
        std::string(vtkFeatureModelSource::GetModelName(part.Model)) == part.Name && dist && labels &&
        out->GetNumberOfVerts() == n,
      "%s: %lld points", part.Name, (long long)n);
    if (!dist || !labels)
    {
      continue;
    }
    long bad = 0, wrong = 0;
    for (vtkIdType i = 0; i < n; ++i)
    {
      const double d = dist->GetComponent(i, 0);
      bad += part.Length > 0.0 ? !(std::isfinite(d) && d >= 0.0 && d < size) : d != VTK_FLOAT_MAX;
      wrong += (labels->GetValue(i) != 0) != (d <= 2.0 * sp);
    }
    const long positives = CountSet(labels);
    const double fraction = positives / static_cast<double>(n);
    const double expected = part.Length > 0.0
      ? ExpectedPositiveFraction(part.Area * size * size, part.Length * size, sp, n, part.Density)
      : 0.0;
    std::printf("%s: %lld points, s %.4f, NoiseSigma %.4f, %ld positives (%.2f%%, about %.2f%% "
                "expected), %ld bad distances, %ld wrong labels\n",
      part.Name, (long long)n, sp, Field(out, "NoiseSigma"), positives, 100.0 * fraction,
      100.0 * expected, bad, wrong);
    FP_CHECK(bad == 0 && wrong == 0, "%s: %ld bad distances, %ld wrong labels", part.Name, bad, wrong);
    FP_CHECK(sp > 0.0 && std::abs(Field(out, "NoiseSigma") - 0.5 * sp) < 1e-12, "%s: s %g", part.Name, sp);
    if (part.Length > 0.0)
    {
      FP_CHECK(fraction > 0.75 * expected && fraction < 1.25 * expected,
        "%s: %.2f%% positives, about %.2f%% expected", part.Name, 100.0 * fraction, 100.0 * expected);
    }
    else
    {
      FP_CHECK(positives == 0, "%s: %ld positives", part.Name, positives);
    }
  }

  // Without noise, every point of the parts lies on the surface (within 1e-9 Size) and its
  // FeatureDistance is the distance to the nearest feature curve, recomputed here.
  const double tol = 1e-9 * size;
  CheckClean("Box", Generate(vtkFeatureModelSource::BOX, 20000, 3.0, 0.0),
    BoxTruth(0.5 * size, 0.35 * size, 0.25 * size), failures);
  {
    // Uniform sampling (factor 1): the caps hold R / (2 H + R) = 1/3 of the area.
    auto cylinder = Generate(vtkFeatureModelSource::CYLINDER, 30000, 1.0, 0.0);
    vtkDataArray* d = cylinder->GetPointData()->GetArray("FeatureDistance");
    const double R = 0.3 * size, H = 0.3 * size;
    double surface = 0.0, error = 0.0;
    long onCaps = 0;
    for (vtkIdType i = 0; i < cylinder->GetNumberOfPoints(); ++i)
    {
      double p[3];
      cylinder->GetPoint(i, p);
      const double rho = std::hypot(p[0], p[1]);
      const double side = std::abs(rho - R) + std::max(0.0, std::abs(p[2]) - H);
      const double cap = std::abs(std::abs(p[2]) - H) + std::max(0.0, rho - R);
      surface = std::max(surface, std::min(side, cap));
      onCaps += cap < side;
      error = std::max(error, std::abs(std::hypot(rho - R, std::abs(p[2]) - H) - d->GetComponent(i, 0)));
    }
    const double capShare = onCaps / 30000.0;
    std::printf("Cylinder clean: surface error %.2e, distance error %.2e, caps' share %.4f (1/3)\n", surface, error, capShare);
    FP_CHECK(surface < tol && error < tol, "cylinder: surface %g, distance %g", surface, error);
    FP_CHECK(std::abs(capShare - 1.0 / 3.0) < 0.011, "cylinder: caps hold %.4f of the points", capShare); // 4 sd
  }
  {
    auto bracket = Generate(vtkFeatureModelSource::BRACKET, 20000, 3.0, 0.0);
    vtkDataArray* d = bracket->GetPointData()->GetArray("FeatureDistance");
    double x[7], z[7];
    BracketProfile(x, z);
    const double w = 0.25 * size;
    double surface = 0.0, error = 0.0;
    for (vtkIdType i = 0; i < bracket->GetNumberOfPoints(); ++i)
    {
      double p[3];
      bracket->GetPoint(i, p);
      double side = VTK_DOUBLE_MAX, edge = VTK_DOUBLE_MAX;
      bool inside = false;
      for (int k = 0; k < 7; ++k)
      {
        const int l = (k + 1) % 7;
        const double a[3] = { x[k] * size, -w, z[k] * size }, b[3] = { x[l] * size, -w, z[l] * size };
        const double a2[3] = { a[0], w, a[2] }, b2[3] = { b[0], w, b[2] };
        // The side face over the profile's edge k: the 2D distance, within the extrusion.
        const double q[3] = { p[0], -w, p[2] };
        side = std::min(side, SegmentDistance(q, a, b) + std::max(0.0, std::abs(p[1]) - w));
        edge = std::min({ edge, SegmentDistance(p, a, a2), SegmentDistance(p, a, b), SegmentDistance(p, a2, b2) });
        // Crossing test of (x, z) against the profile.
        if ((a[2] > p[2]) != (b[2] > p[2]) && p[0] < a[0] + (p[2] - a[2]) * (b[0] - a[0]) / (b[2] - a[2]))
        {
          inside = !inside;
        }
      }
      const double cap = inside ? std::abs(std::abs(p[1]) - w) : VTK_DOUBLE_MAX;
      surface = std::max(surface, std::min(side, cap));
      error = std::max(error, std::abs(edge - d->GetComponent(i, 0)));
    }
    std::printf("Bracket clean: surface error %.2e, distance error %.2e\n", surface, error);
    FP_CHECK(surface < tol && error < tol, "bracket: surface %g, distance %g", surface, error);
    auto again2 = Generate(vtkFeatureModelSource::BRACKET, 20000, 3.0, 0.0);
    long sameB = 0;
    for (vtkIdType i = 0; i < bracket->GetNumberOfPoints(); ++i)
    {
      double p[3], q[3];
      bracket->GetPoint(i, p);
      again2->GetPoint(i, q);
      sameB += p[0] == q[0] && p[1] == q[1] && p[2] == q[2];
    }
    FP_CHECK(sameB == 20000, "bracket: %ld of 20000 points repeat", sameB);

    // Uniform sampling (factor 1) by area over the side faces and the end caps (made of
    // rectangles and of the triangle under the sloped top, x > 0.1 and z > -0.12 Size).
    auto uniform = Generate(vtkFeatureModelSource::BRACKET, 40000, 1.0, 0.0);
    long onCaps = 0, inTriangle = 0;
    for (vtkIdType i = 0; i < uniform->GetNumberOfPoints(); ++i)
    {
      double p[3];
      uniform->GetPoint(i, p);
      const bool cap = std::abs(std::abs(p[1]) - w) < tol;
      onCaps += cap;
      inTriangle += cap && p[0] > 0.1 * size && p[2] > -0.12 * size;
    }
    const double triangle = 0.5 * 0.4 * 0.4 * std::tan(20.0 * M_PI / 180.0);
    const double all = 0.5 * perimeter + 2.0 * profileArea;
    const double capShare = onCaps / 40000.0, triangleShare = inTriangle / 40000.0;
    std::printf("Bracket uniform: caps hold %.4f of the points (%.4f of the area), the triangles "
                "%.4f (%.4f)\n", capShare, 2.0 * profileArea / all, triangleShare, 2.0 * triangle / all);
    FP_CHECK(std::abs(capShare - 2.0 * profileArea / all) < 0.01, "bracket: caps' share %.4f", capShare); // 4 sd
    FP_CHECK(std::abs(triangleShare - 2.0 * triangle / all) < 0.004, "bracket: triangles' share %.4f", triangleShare); // 5 sd
  }
  {
    // The blob: on the surface r(u), and sampled by area, not by solid angle: the part where
    // |x| > |y| (half of the directions, the larger radii of the sin^2 phi cos 2 theta term)
    // holds its share of the area, here integrated from the parametrization's finite-difference
    // tangents (midpoint rule; the part's boundaries, theta = pi/4 + k pi/2, on cell boundaries).
    auto blob = Generate(vtkFeatureModelSource::BLOB, 100000, 3.0, 0.0);
    double surface = 0.0;
    long inPart = 0;
    for (vtkIdType i = 0; i < blob->GetNumberOfPoints(); ++i)
    {
      double p[3];
      blob->GetPoint(i, p);
      const double r = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
      const double u[3] = { p[0] / r, p[1] / r, p[2] / r };
      surface = std::max(surface, std::abs(r - BlobRadius(u, size)));
      inPart += std::abs(u[0]) > std::abs(u[1]);
    }
    auto point = [size](double phi, double theta, double q[3]) {
      const double u[3] = { std::sin(phi) * std::cos(theta), std::sin(phi) * std::sin(theta), std::cos(phi) };
      const double r = BlobRadius(u, size);
      for (int k = 0; k < 3; ++k)
      {
        q[k] = r * u[k];
      }
    };
    const int nPhi = 300, nTheta = 600;
    const double dPhi = M_PI / nPhi, dTheta = 2.0 * M_PI / nTheta, e = 1e-6;
    double total = 0.0, part = 0.0;
    for (int i = 0; i < nPhi; ++i)
    {
      for (int j = 0; j < nTheta; ++j)
      {
        const double phi = (i + 0.5) * dPhi, theta = (j + 0.5) * dTheta;
        double a[3], b[3], c[3], f[3];
        point(phi + e, theta, a);
        point(phi - e, theta, b);
        point(phi, theta + e, c);
        point(phi, theta - e, f);
        const double tp[3] = { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
        const double tt[3] = { c[0] - f[0], c[1] - f[1], c[2] - f[2] };
        const double dA = std::sqrt(std::pow(tp[1] * tt[2] - tp[2] * tt[1], 2) +
                            std::pow(tp[2] * tt[0] - tp[0] * tt[2], 2) + std::pow(tp[0] * tt[1] - tp[1] * tt[0], 2)) /
          (4.0 * e * e) * dPhi * dTheta;
        total += dA;
        part += std::abs(std::cos(theta)) > std::abs(std::sin(theta)) ? dA : 0.0;
      }
    }
    const double share = inPart / 100000.0, expectedShare = part / total;
    std::printf("Blob clean: surface error %.2e, |x| > |y| holds %.4f of the points, %.4f of the "
                "area (0.5 of the directions)\n", surface, share, expectedShare);
    FP_CHECK(surface < tol, "blob: surface error %g", surface);
    FP_CHECK(std::abs(share - expectedShare) < 0.0065, "blob: |x| > |y| %.4f vs area %.4f", share, expectedShare); // 4 sd
  }

  {
    // The torus (major radius R = 0.35 Size, tube radius r = 0.1 Size): on its surface, and
    // sampled by area: the outer half of the tube (rho > R, angles v in (-pi/2, pi/2) around it)
    // holds (pi + 2 r / R) / (2 pi) = 0.5909 of the area, where a sampling uniform in v would
    // give 0.5.
    auto torus = Generate(vtkFeatureModelSource::TORUS, 100000, 3.0, 0.0);
    const double R = 0.35 * size, r = 0.1 * size;
    double surface = 0.0;
    long outer = 0;
    for (vtkIdType i = 0; i < torus->GetNumberOfPoints(); ++i)
    {
      double p[3];
      torus->GetPoint(i, p);
      const double rho = std::hypot(p[0], p[1]);
      surface = std::max(surface, std::abs(std::hypot(rho - R, p[2]) - r));
      outer += rho > R;
    }
    const double share = outer / 100000.0, expectedShare = (M_PI + 2.0 * r / R) / (2.0 * M_PI);
    std::printf("Torus clean: surface error %.2e, the outer half holds %.4f of the points, %.4f of "
                "the area\n", surface, share, expectedShare);
    FP_CHECK(surface < tol, "torus: surface error %g", surface);
    FP_CHECK(std::abs(share - expectedShare) < 0.0065, "torus: outer half %.4f vs area %.4f", share, expectedShare); // 4 sd
  }
  {
    // The ellipsoid (semi-axes a, b, c = 0.5, 0.3, 0.15 Size): on its surface, and sampled by
    // area: the caps |x| > a / 2 hold their share of the area, integrated here from the
    // parametrization (a sin phi cos theta, b sin phi sin theta, c cos phi) and its exact
    // tangents (midpoint rule).
    auto ellipsoid = Generate(vtkFeatureModelSource::ELLIPSOID, 100000, 3.0, 0.0);
    const double a = 0.5 * size, b = 0.3 * size, c = 0.15 * size;
    double surface = 0.0;
    long inCaps = 0;
    for (vtkIdType i = 0; i < ellipsoid->GetNumberOfPoints(); ++i)
    {
      double p[3];
      ellipsoid->GetPoint(i, p);
      const double level = std::sqrt(
        p[0] * p[0] / (a * a) + p[1] * p[1] / (b * b) + p[2] * p[2] / (c * c));
      surface = std::max(surface, std::abs(level - 1.0) * c); // within c |level - 1| of it
      inCaps += std::abs(p[0]) > 0.5 * a;
    }
    const int nPhi = 600, nTheta = 1200;
    const double dPhi = M_PI / nPhi, dTheta = 2.0 * M_PI / nTheta;
    double total = 0.0, caps = 0.0;
    for (int i = 0; i < nPhi; ++i)
    {
      for (int j = 0; j < nTheta; ++j)
      {
        const double phi = (i + 0.5) * dPhi, theta = (j + 0.5) * dTheta;
        const double tp[3] = { a * std::cos(phi) * std::cos(theta), b * std::cos(phi) * std::sin(theta),
          -c * std::sin(phi) };
        const double tt[3] = { -a * std::sin(phi) * std::sin(theta), b * std::sin(phi) * std::cos(theta),
          0.0 };
        const double dA = std::sqrt(std::pow(tp[1] * tt[2] - tp[2] * tt[1], 2) +
                            std::pow(tp[2] * tt[0] - tp[0] * tt[2], 2) + std::pow(tp[0] * tt[1] - tp[1] * tt[0], 2)) *
          dPhi * dTheta;
        total += dA;
        caps += std::abs(std::sin(phi) * std::cos(theta)) > 0.5 ? dA : 0.0;
      }
    }
    const double share = inCaps / 100000.0, expectedShare = caps / total;
    std::printf("Ellipsoid clean: surface error %.2e, |x| > a / 2 holds %.4f of the points, %.4f of "
                "the area\n", surface, share, expectedShare);
    FP_CHECK(surface < tol, "ellipsoid: surface error %g", surface);
    FP_CHECK(std::abs(share - expectedShare) < 0.0065, "ellipsoid: caps %.4f vs area %.4f", share, expectedShare); // 4 sd
  }

  // The models of close and bordered features without noise: on their surfaces, the ground truth
  // exact, and the distance right at a few hand-picked positions (in Size units).
  using Position = std::array<double, 3>;
  {
    const double d = SeparationLength(1.0, 6.0, 20000, 5.0) * size;
    auto ribs = Generate(vtkFeatureModelSource::PARALLEL_CREASES, 20000, 3.0, 0.0);
    CheckClean("Parallel creases", ribs, RibsTruth(size, d), failures);
    // The middle rib's top centre and the middle of the gap beside it, half a pitch from two
    // creases; the flat sheet 0.4 Size out, beyond the last rib's foot at 2.5 pitches.
    CheckHandPicked("Parallel creases", ribs, Position{ 0.0, 0.0, d }, 0.5 * d, failures);
    CheckHandPicked("Parallel creases", ribs, Position{ -d, 0.0, 0.0 }, 0.5 * d, failures);
    CheckHandPicked("Parallel creases", ribs, Position{ 0.4 * size, 0.0, 0.0 },
      0.4 * size - 2.5 * d, failures);

    const double t = SeparationLength(1.2, 3.2, 20000, 5.0) * size;
    auto plate = Generate(vtkFeatureModelSource::THIN_PLATE, 20000, 3.0, 0.0);
    CheckClean("Thin plate", plate, BoxTruth(0.5 * size, 0.3 * size, 0.5 * t), failures);
    CheckHandPicked("Thin plate", plate, Position{ 0.0, 0.0, 0.5 * t }, 0.3 * size, failures);
    CheckHandPicked("Thin plate", plate, Position{ 0.45 * size, 0.2 * size, 0.5 * t }, 0.05 * size,
      failures);

    // The arch's top is sqrt(2) R from both straight borders, 0.5 Size from the half circles.
    const double r = 0.3 * size;
    auto half = Generate(vtkFeatureModelSource::HALF_CYLINDER, 20000, 3.0, 0.0);
    CheckClean("Half cylinder", half, HalfCylinderTruth(size), failures);
    CheckHandPicked("Half cylinder", half, Position{ 0.0, r, 0.0 }, std::sqrt(2.0) * r, failures);
    CheckHandPicked("Half cylinder", half,
      Position{ r * std::cos(M_PI / 6), r * std::sin(M_PI / 6), 0.45 * size }, 0.05 * size,
      failures);

    auto holed = Generate(vtkFeatureModelSource::PLATE_WITH_HOLE, 20000, 3.0, 0.0);
    CheckClean("Plate with hole", holed, PlateWithHoleTruth(size), failures);
    CheckHandPicked("Plate with hole", holed, Position{ 0.35 * size, 0.0, 0.0 }, 0.15 * size,
      failures);
    CheckHandPicked("Plate with hole", holed, Position{ 0.45 * size, 0.45 * size, 0.0 },
      0.05 * size, failures);
    CheckHandPicked("Plate with hole", holed, Position{ 0.0, -0.25 * size, 0.0 }, 0.05 * size,
      failures);
  }

  // FeatureSeparation sets the distance of neighbouring creases in nominal spacings of the cloud
  // as built. The ribs' walls are the only points strictly between z = 0 and the ribs' height d,
  // at the six x of the walls: the creases lie at their feet and tops, each d from the next.
  for (const double separation : { 2.0, 5.0, 8.0 })
  {
    auto ribs = Generate(vtkFeatureModelSource::PARALLEL_CREASES, 20000, 3.0, 0.0, 1, separation);
    double d = 0.0;
    for (vtkIdType i = 0; i < ribs->GetNumberOfPoints(); ++i)
    {
      d = std::max(d, ribs->GetPoint(i)[2]);
    }
    std::set<double> walls;
    for (vtkIdType i = 0; i < ribs->GetNumberOfPoints(); ++i)
    {
      const double* p = ribs->GetPoint(i);
      if (p[2] > 0.0 && p[2] < d)
      {
        walls.insert(p[0]);
      }
    }
    double worstGap = 0.0;
    for (auto w = walls.begin(); w != walls.end() && std::next(w) != walls.end(); ++w)
    {
      worstGap = std::max(worstGap, std::abs(*std::next(w) - *w - d));
    }
    const double nominal = std::sqrt((size * size + 6.0 * d * size) / 20000.0);
    std::printf("Parallel creases, FeatureSeparation %g: creases %.4f apart, %.6f nominal "
                "spacings; %zu walls, their gaps off by %.2e\n",
      separation, d, d / nominal, walls.size(), worstGap);
    FP_CHECK(walls.size() == 6 && worstGap < 1e-9 * size, "%zu walls, gaps off by %g", walls.size(),
      worstGap);
    FP_CHECK(std::abs(d / nominal - separation) < 1e-9, "creases %g spacings apart, %g asked",
      d / nominal, separation);
    FP_CHECK(std::abs(d - SeparationLength(1.0, 6.0, 20000, separation) * size) < 1e-9 * size,
      "rib pitch %g", d);
  }
  {
    // Too wide ribs are reduced to fit the middle 0.8 Size: a pitch of 0.8 / 5 Size.
    vtkNew<vtkFeatureModelSource> source;
    source->SetModelToParallelCreases();
    source->SetNumberOfPoints(5000);
    source->SetNoiseFactor(0.0);
    source->SetFeatureSeparation(1000.0);
    source->GlobalWarningDisplayOff();
    source->Update();
    source->GlobalWarningDisplayOn();
    double top = 0.0;
    for (vtkIdType i = 0; i < source->GetOutput()->GetNumberOfPoints(); ++i)
    {
      top = std::max(top, source->GetOutput()->GetPoint(i)[2]);
    }
    FP_CHECK(std::abs(top - 0.16 * size) < 1e-9 * size, "capped ribs %g high", top);
  }
  // The thin plate's thickness: the z extent of the clean cloud, in nominal spacings; and its
  // ground truth, the two edges of each rim face within a few spacings.
  for (const double separation : { 0.5, 1.0, 3.0 })
  {
    auto plate = Generate(vtkFeatureModelSource::THIN_PLATE, 20000, 3.0, 0.0, 1, separation);
    double bounds[6];
    plate->GetBounds(bounds);
    const double t = bounds[5] - bounds[4];
    const double nominal = std::sqrt((1.2 * size * size + 3.2 * size * t) / 20000.0);
    std::printf("Thin plate, FeatureSeparation %g: %.4f thick, %.6f nominal spacings\n", separation,
      t, t / nominal);
    FP_CHECK(std::abs(t / nominal - separation) < 1e-9, "plate %g spacings thick, %g asked",
      t / nominal, separation);
    const double expected = SeparationLength(1.2, 3.2, 20000, separation) * size;
    char name[64];
    std::snprintf(name, sizeof(name), "Thin plate %g spacings thick", separation);
    CheckClean(name, plate,
      BoxTruth(0.5 * size, 0.3 * size, 0.5 * expected), failures);
  }

  // FeatureType by model, summed over three seeds (a corner where two borders meet at 90 degrees
  // holds about one positive per cloud): each model has the types of its features and no other;
  // borders only on the open models; FeatureType set exactly on the positives.
  struct Types
  {
    int Model;
    unsigned Present; // bit t: some point has the FeatureType t
  };
  const unsigned convex = 1u << vtkFeatureModelSource::CONVEX_CREASE,
                 concave = 1u << vtkFeatureModelSource::CONCAVE_CREASE,
                 corner = 1u << vtkFeatureModelSource::CORNER,
                 border = 1u << vtkFeatureModelSource::BORDER;
  const Types types[] = {
    { vtkFeatureModelSource::MODEL_I, convex | concave },
    { vtkFeatureModelSource::MODEL_II, convex | concave },
    { vtkFeatureModelSource::MODEL_III, convex },
    { vtkFeatureModelSource::SPHERE, 0u },
    { vtkFeatureModelSource::BOX, convex | corner },
    { vtkFeatureModelSource::CYLINDER, convex },
    { vtkFeatureModelSource::BRACKET, convex | concave | corner },
    { vtkFeatureModelSource::BLOB, 0u },
    { vtkFeatureModelSource::PARALLEL_CREASES, convex | concave },
    { vtkFeatureModelSource::THIN_PLATE, convex | corner },
    { vtkFeatureModelSource::HALF_CYLINDER, border | corner },
    { vtkFeatureModelSource::PLATE_WITH_HOLE, border | corner },
    { vtkFeatureModelSource::TORUS, 0u },
    { vtkFeatureModelSource::ELLIPSOID, 0u },
  };
  for (const Types& expected : types)
  {
    std::array<long, 5> counts{};
    long mismatched = 0;
    for (unsigned seed = 1; seed <= 3; ++seed)
    {
      auto cloud = Generate(expected.Model, 20000, 3.0, 0.5, seed);
      const std::array<long, 5> c = TypeCounts(cloud);
      for (int t = 0; t < 5; ++t)
      {
        counts[t] += c[t];
      }
      vtkDataArray* labels = cloud->GetPointData()->GetArray("GroundTruth");
      vtkDataArray* type = cloud->GetPointData()->GetArray("GroundTruthType");
      for (vtkIdType i = 0; type && i < cloud->GetNumberOfPoints(); ++i)
      {
        mismatched += (type->GetComponent(i, 0) != 0) != (labels->GetComponent(i, 0) != 0);
      }
    }
    unsigned present = 0;
    for (int t = 1; t < 5; ++t)
    {
      present |= counts[t] > 0 ? 1u << t : 0u;
    }
    std::printf("%-16s FeatureType: %ld none, %ld convex, %ld concave, %ld corner, %ld border\n",
      vtkFeatureModelSource::GetModelName(expected.Model), counts[0], counts[1], counts[2],
      counts[3], counts[4]);
    FP_CHECK(present == expected.Present && mismatched == 0,
      "%s: FeatureType present 0x%x, 0x%x expected; %ld points typed but not positive or back",
      vtkFeatureModelSource::GetModelName(expected.Model), present, expected.Present, mismatched);
  }
  return failures ? EXIT_FAILURE : EXIT_SUCCESS;
}
