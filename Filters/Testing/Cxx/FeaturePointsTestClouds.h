// Seeded synthetic clouds for the tests of FeaturePoints::Filters, with the clean distance of each
// point to the nearest feature curve (docs/evaluation.md's delta) and the quality figures of
// docs/evaluation.md. Header-only; test code, not part of the module's API.
#ifndef FeaturePointsTestClouds_h
#define FeaturePointsTestClouds_h

#include "vtkDoubleArray.h"
#include "vtkNew.h"
#include "vtkPointCloudNeighborhoods.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include <cmath>
#include <cstdio>
#include <functional>
#include <random>
#include <vector>

namespace fptest
{
struct Cloud
{
  vtkSmartPointer<vtkPolyData> Data;
  std::vector<double> Delta; // clean distance to the nearest feature curve (inf: no feature)
  double Spacing = 0.0;      // mean nearest-neighbour distance of the clean cloud
};

// Clean points from `sample(rng, p, delta)`, then Gaussian noise of noiseFactor * clean spacing.
inline Cloud MakeCloud(int n, unsigned seed, double noiseFactor,
  const std::function<void(std::mt19937&, double*, double&)>& sample)
{
  std::mt19937 rng(seed);
  Cloud cloud;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(n);
  cloud.Delta.resize(n);
  double p[3];
  for (int i = 0; i < n; ++i)
  {
    sample(rng, p, cloud.Delta[i]);
    points->SetPoint(i, p);
  }
  vtkNew<vtkPointCloudNeighborhoods> nb;
  nb->Build(points);
  cloud.Spacing = nb->ComputeMeanSpacing();
  std::normal_distribution<double> noise(0.0, noiseFactor * cloud.Spacing);
  for (int i = 0; i < n && noiseFactor > 0; ++i)
  {
    points->GetPoint(i, p);
    for (double& c : p)
    {
      c += noise(rng);
    }
    points->SetPoint(i, p);
  }
  cloud.Data = vtkSmartPointer<vtkPolyData>::New();
  cloud.Data->SetPoints(points);
  return cloud;
}

// A square plane of side 1 in z = 0: no feature.
inline Cloud NoisyPlane(int n, unsigned seed, double noiseFactor = 0.5)
{
  return MakeCloud(n, seed, noiseFactor, [](std::mt19937& rng, double* p, double& delta) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    p[0] = u(rng);
    p[1] = u(rng);
    p[2] = 0.0;
    delta = INFINITY;
  });
}

// A unit sphere: no feature.
inline Cloud NoisySphere(int n, unsigned seed, double noiseFactor = 0.5)
{
  return MakeCloud(n, seed, noiseFactor, [](std::mt19937& rng, double* p, double& delta) {
    std::normal_distribution<double> g(0.0, 1.0);
    double r = 0.0;
    do
    {
      p[0] = g(rng);
      p[1] = g(rng);
      p[2] = g(rng);
      r = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    } while (r < 1e-9);
    p[0] /= r;
    p[1] /= r;
    p[2] /= r;
    delta = INFINITY;
  });
}

// Two unit squares sharing the edge x = 0 (along y), the second one bent up by `bendDegrees` (the
// angle between the normals: 90 is a right-angle crease, 30 a gentle one). The points within
// `denseWidth` of the crease are sampled `denseFactor` times as densely (1: uniform sampling).
inline Cloud BentPlanes(int n, unsigned seed, double bendDegrees, double noiseFactor = 0.5,
  double denseFactor = 1.0, double denseWidth = 0.1)
{
  const double t = bendDegrees * M_PI / 180.0;
  // Rejection sampling of u in [-1, 1] with density denseFactor on |u| < denseWidth.
  return MakeCloud(n, seed, noiseFactor,
    [t, denseFactor, denseWidth](std::mt19937& rng, double* p, double& delta) {
      std::uniform_real_distribution<double> u01(0.0, 1.0);
      double u;
      for (;;)
      {
        u = 2.0 * u01(rng) - 1.0;
        const double accept = std::abs(u) < denseWidth ? 1.0 : 1.0 / denseFactor;
        if (u01(rng) < accept)
        {
          break;
        }
      }
      const double y = u01(rng);
      if (u < 0.0)
      {
        p[0] = u;
        p[1] = y;
        p[2] = 0.0;
      }
      else
      {
        p[0] = u * std::cos(t);
        p[1] = y;
        p[2] = u * std::sin(t);
      }
      delta = std::abs(u);
    });
}

// A thin bent plate: the 90-degree (or bendDegrees) bend of BentPlanes as a wall of the given
// thickness, both of its sides sampled (alternate points). Each side has its own crease line,
// thickness / 2 from the middle surface; delta is the distance to it along the side.
inline Cloud ThinBentPlate(int n, unsigned seed, double bendDegrees, double thickness)
{
  const double t = bendDegrees * M_PI / 180.0;
  int index = 0;
  return MakeCloud(n, seed, 0.5,
    [t, thickness, &index](std::mt19937& rng, double* p, double& delta) {
      std::uniform_real_distribution<double> u01(0.0, 1.0);
      const double h = (index++ % 2 ? 0.5 : -0.5) * thickness; // the side's offset
      const double corner = h * (std::cos(t) - 1.0) / std::sin(t); // its crease, in x
      const double u = 2.0 * u01(rng) - 1.0;
      const double y = u01(rng);
      if (u < 0.0)
      {
        p[0] = corner + u;
        p[1] = y;
        p[2] = h;
      }
      else
      {
        p[0] = corner + u * std::cos(t);
        p[1] = y;
        p[2] = h + u * std::sin(t);
      }
      delta = std::abs(u);
    });
}

struct Quality
{
  double Precision = 0, Recall = 0, F1 = 0;
  long Detections = 0, Positives = 0;
};

// docs/evaluation.md: positives delta <= 2s, correct detections delta <= 4s.
inline Quality Evaluate(const Cloud& cloud, vtkUnsignedCharArray* mask)
{
  Quality q;
  long correct = 0, found = 0;
  for (size_t i = 0; i < cloud.Delta.size(); ++i)
  {
    const bool detected = mask->GetValue(static_cast<vtkIdType>(i)) != 0;
    const bool positive = cloud.Delta[i] <= 2.0 * cloud.Spacing;
    q.Detections += detected;
    q.Positives += positive;
    correct += detected && cloud.Delta[i] <= 4.0 * cloud.Spacing;
    found += detected && positive;
  }
  q.Precision = q.Detections ? double(correct) / q.Detections : 0.0;
  q.Recall = q.Positives ? double(found) / q.Positives : 0.0;
  q.F1 = q.Precision + q.Recall > 0 ? 2 * q.Precision * q.Recall / (q.Precision + q.Recall) : 0.0;
  return q;
}

#define FP_CHECK(cond, ...)                                                                        \
  do                                                                                               \
  {                                                                                                \
    if (!(cond))                                                                                   \
    {                                                                                              \
      std::fprintf(stderr, "FAILED %s:%d: %s: ", __FILE__, __LINE__, #cond);                       \
      std::fprintf(stderr, __VA_ARGS__);                                                           \
      std::fprintf(stderr, "\n");                                                                  \
      ++failures;                                                                                  \
    }                                                                                              \
  } while (0)
} // namespace fptest

#endif
