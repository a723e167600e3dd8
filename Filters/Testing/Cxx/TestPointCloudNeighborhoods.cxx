// The grid search of vtkPointCloudNeighborhoods against vtkStaticPointLocator, on clouds that
// stress a uniform grid: a noisy sheet, a sphere surface, a tight cluster beside a sparse halo,
// far outliers (robust box), an exactly flat plane and a line. Away from ties the two must return
// the same k nearest points in the same order; where distances tie (duplicates), the same
// distances. Then ReorderSpatially(): a permutation of the cloud whose tables are the original
// tables renumbered, and in which a point's nearest neighbour is usually a few ids away.
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointCloudNeighborhoods.h"
#include "vtkPoints.h"

#include <cmath>
#include <cstdio>
#include <algorithm>
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

// ReorderSpatially: the renumbered cloud is a permutation of the input (invalid points last), its
// tables are the input's tables renumbered, and neighbours sit near each other in the numbering.
void Reordered(const std::string& kind, int k)
{
  vtkSmartPointer<vtkPoints> points = Cloud(kind == "invalid" ? "volume" : kind, 8000, 5);
  if (kind == "invalid")
  {
    for (vtkIdType i = 7; i < points->GetNumberOfPoints(); i += 50)
    {
      points->SetPoint(i, std::nan(""), 0.0, 0.0);
    }
  }
  const vtkIdType n = points->GetNumberOfPoints();
  vtkNew<vtkPointCloudNeighborhoods> plain, reordered;
  plain->Build(points);
  reordered->Build(points);
  std::vector<int32_t> original;
  bool ok = reordered->ReorderSpatially(original);
  const vtkIdType m = reordered->GetNumberOfValidPoints();
  vtkPoints* renumbered = reordered->GetPoints();
  ok = ok && static_cast<vtkIdType>(original.size()) == n && renumbered->GetNumberOfPoints() == n;
  std::vector<char> seen(n, 0);
  long misplaced = 0;
  for (vtkIdType i = 0; ok && i < n; ++i)
  {
    const int32_t o = original[i];
    if (o < 0 || o >= n || seen[o]++)
    {
      ok = false;
      break;
    }
    double x[3], y[3];
    points->GetPoint(o, x);
    renumbered->GetPoint(i, y);
    const bool valid = i < m;
    misplaced += valid != (plain->GetValidMask()[o] != 0) || valid != (reordered->GetValidMask()[i] != 0) ||
        (valid && (x[0] != y[0] || x[1] != y[1] || x[2] != y[2]))
      ? 1
      : 0;
  }
  // The k nearest of new point i, mapped back, are the k nearest of original[i] (same distances
  // where ids differ: ties).
  std::vector<vtkIdType> ids = reordered->GetValidIds();
  std::vector<vtkIdType> originalRows(ids.size());
  for (size_t r = 0; r < ids.size(); ++r)
  {
    originalRows[r] = original[ids[r]];
  }
  std::vector<int32_t> a, b;
  reordered->FindNearestNeighbors(k, ids, a);
  plain->FindNearestNeighbors(k, originalRows, b);
  long differentDistances = 0;
  std::vector<double> idGaps, randomGaps;
  for (size_t r = 0; ok && r < ids.size(); ++r)
  {
    double x[3], y[3], z[3];
    points->GetPoint(originalRows[r], x);
    for (int j = 0; j < k; ++j)
    {
      const int32_t p = a[r * k + j] < 0 ? -1 : original[a[r * k + j]], q = b[r * k + j];
      if (p != q && (p < 0 || q < 0))
      {
        ++differentDistances;
      }
      else if (p != q)
      {
        points->GetPoint(p, y);
        points->GetPoint(q, z);
        differentDistances +=
          vtkMath::Distance2BetweenPoints(x, y) != vtkMath::Distance2BetweenPoints(x, z) ? 1 : 0;
      }
    }
    idGaps.push_back(std::abs(static_cast<double>(a[r * k]) - static_cast<double>(ids[r])));
    randomGaps.push_back(
      std::abs(static_cast<double>(b[r * k]) - static_cast<double>(originalRows[r])));
  }
  auto median = [](std::vector<double>& v) {
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
  };
  const double idGap = median(idGaps), randomGap = median(randomGaps);
  const double s0 = plain->ComputeMeanSpacing(), s1 = reordered->ComputeMeanSpacing();
  // Coherent: the nearest point is usually a few cells away in the numbering, where the input's
  // random order puts it a quarter of the cloud away.
  ok = ok && misplaced == 0 && differentDistances == 0 && std::abs(s0 - s1) <= 1e-12 * s0 &&
    idGap < 0.01 * static_cast<double>(n) && randomGap > 0.2 * static_cast<double>(n);
  // Refused once a spacing is known (ids would change under it), and for the locator.
  std::vector<int32_t> again;
  vtkNew<vtkPointCloudNeighborhoods> locator;
  locator->SetSearchMethod(vtkPointCloudNeighborhoods::STATIC_POINT_LOCATOR);
  locator->Build(points);
  ok = ok && !reordered->ReorderSpatially(again) && !locator->ReorderSpatially(again);
  std::printf("reordered %-8s k=%2d: %ld misplaced, %ld different distances, median id gap to "
              "the nearest %.0f (input order %.0f) %s\n",
    kind.c_str(), k, misplaced, differentDistances, idGap, randomGap, ok ? "" : "FAILED");
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
  for (const char* kind : { "sheet", "outliers", "duplicates", "invalid" })
  {
    Reordered(kind, 15);
  }
  return Failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
