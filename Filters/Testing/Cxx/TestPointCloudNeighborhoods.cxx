// The grid search of vtkPointCloudNeighborhoods against vtkStaticPointLocator, on clouds that
// stress a uniform grid: a noisy sheet, a sphere surface, a tight cluster beside a sparse halo,
// far outliers (robust box), an exactly flat plane and a line. Away from ties the two must return
// the same k nearest points in the same order; where distances tie (duplicates), the same
// distances.
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointCloudNeighborhoods.h"
#include "vtkPoints.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

namespace
{
int Failures = 0;

vtkSmartPointer<vtkPoints> Cloud(const std::string& kind, int n, unsigned seed)
{
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::normal_distribution<double> g(0.0, 1.0);
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  for (int i = 0; i < n; ++i)
  {
    double x[3] = { u(rng), u(rng), u(rng) };
    if (kind == "sheet")
    {
      x[2] = 0.01 * g(rng);
    }
    else if (kind == "sphere")
    {
      const double r = std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]) + 1e-12;
      for (double& c : x)
      {
        c /= r;
      }
    }
    else if (kind == "cluster")
    {
      const double scale = i % 10 == 0 ? 1.0 : 0.01; // 90 % in a tight cluster
      for (double& c : x)
      {
        c *= scale;
      }
    }
    else if (kind == "outliers" && i < 3)
    {
      x[0] = 1e6 * (i + 1);
    }
    else if (kind == "plane")
    {
      x[2] = 0.0;
    }
    else if (kind == "line")
    {
      x[1] = x[2] = 0.0;
    }
    points->InsertNextPoint(x);
  }
  if (kind == "duplicates")
  {
    for (int i = 0; i < n / 10; ++i)
    {
      points->InsertNextPoint(points->GetPoint(i));
    }
  }
  return points;
}

void Compare(const std::string& kind, int k)
{
  vtkSmartPointer<vtkPoints> points = Cloud(kind, 8000, 3);
  vtkNew<vtkPointCloudNeighborhoods> grid, locator;
  locator->SetSearchMethod(vtkPointCloudNeighborhoods::STATIC_POINT_LOCATOR);
  grid->Build(points);
  locator->Build(points);
  const std::vector<vtkIdType> ids = grid->GetValidIds();
  std::vector<int32_t> a, b;
  std::vector<double> da, db;
  grid->FindNearestNeighbors(k, ids, a, &da);
  locator->FindNearestNeighbors(k, ids, b, &db);
  long differentIds = 0, differentDistances = 0;
  for (size_t r = 0; r < ids.size(); ++r)
  {
    double x[3], y[3], z[3];
    points->GetPoint(ids[r], x);
    for (int j = 0; j < k; ++j)
    {
      const int32_t p = a[r * k + j], q = b[r * k + j];
      if (p == q)
      {
        continue;
      }
      ++differentIds;
      if (p < 0 || q < 0)
      {
        ++differentDistances;
        continue;
      }
      points->GetPoint(p, y);
      points->GetPoint(q, z);
      if (vtkMath::Distance2BetweenPoints(x, y) != vtkMath::Distance2BetweenPoints(x, z))
      {
        ++differentDistances;
      }
    }
  }
  const bool ties = kind == "duplicates"; // only there do distances tie
  const bool ok = differentDistances == 0 && (ties || differentIds == 0) &&
    grid->ComputeMeanSpacing() == locator->ComputeMeanSpacing();
  std::printf("%-10s k=%2d: %ld different ids (%s), %ld different distances, spacing %.6g %s\n",
    kind.c_str(), k, differentIds, ties ? "ties allowed" : "none allowed", differentDistances,
    grid->ComputeMeanSpacing(), ok ? "" : "FAILED");
  Failures += ok ? 0 : 1;
}
} // namespace

int TestPointCloudNeighborhoods(int, char*[])
{
  for (const char* kind :
    { "sheet", "sphere", "cluster", "outliers", "volume", "duplicates", "plane", "line" })
  {
    for (int k : { 1, 4, 8, 15, 50 })
    {
      Compare(kind, k);
    }
  }
  return Failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
