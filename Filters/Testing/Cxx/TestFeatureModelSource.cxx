// vtkFeatureModelSource: the ground truth agrees with the geometry, the sampling and the noise are
// what the parameters say, and a seed gives the same cloud every time.
#include "FeaturePointsTestRun.h"
#include "vtkFeatureModelSource.h"
#include "vtkFieldData.h"

namespace
{
vtkSmartPointer<vtkPolyData> Generate(int model, vtkIdType n, double density, double noise,
  unsigned seed = 1)
{
  vtkNew<vtkFeatureModelSource> source;
  source->SetModel(model);
  source->SetNumberOfPoints(n);
  source->SetFeatureDensityFactor(density);
  source->SetNoiseFactor(noise);
  source->SetSeed(seed);
  source->Update();
  return source->GetOutput();
}
double Field(vtkPolyData* p, const char* name)
{
  return p->GetFieldData()->GetArray(name)->GetComponent(0, 0);
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
  const double s = Field(clean, "CleanMeanSpacing");
  FP_CHECK(clean->GetNumberOfPoints() == 20000 && delta && truth, "output shape");
  FP_CHECK(s > 0.0 && Field(clean, "NoiseSigma") == 0.0, "s %g", s);
  double worstSurface = 0.0, worstDelta = 0.0;
  long wrongLabel = 0;
  for (vtkIdType i = 0; delta && truth && i < clean->GetNumberOfPoints(); ++i)
  {
    double p[3];
    clean->GetPoint(i, p);
    const double z = std::abs(p[0]) < a ? -depth * (1.0 - std::abs(p[0]) / a) : 0.0;
    worstSurface = std::max(worstSurface, std::abs(p[2] - z));
    const double corners[3][2] = { { -a, 0.0 }, { 0.0, -depth }, { a, 0.0 } };
    double d = VTK_DOUBLE_MAX;
    for (const auto& c : corners)
    {
      d = std::min(d, std::hypot(p[0] - c[0], p[2] - c[1]));
    }
    worstDelta = std::max(worstDelta, std::abs(d - delta->GetComponent(i, 0)));
    wrongLabel += (truth->GetComponent(i, 0) != 0) != (d <= 2.0 * s);
    FP_CHECK(std::abs(p[1]) <= h + 1e-9 && std::abs(p[0]) <= h + 1e-9, "point %lld outside the sheet", (long long)i);
  }
  std::printf("Model I clean: s %.4f, surface error %.2e, distance error %.2e, %ld wrong labels\n",
    s, worstSurface, worstDelta, wrongLabel);
  FP_CHECK(worstSurface < 1e-9, "a point is off the surface by %g", worstSurface);
  FP_CHECK(worstDelta < 1e-9, "FeatureDistance off by %g", worstDelta);
  FP_CHECK(wrongLabel == 0, "%ld ground-truth labels disagree with delta <= 2 s", wrongLabel);

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
  return failures ? EXIT_FAILURE : EXIT_SUCCESS;
}
