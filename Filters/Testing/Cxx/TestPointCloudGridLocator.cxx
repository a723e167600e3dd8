// vtkPointCloudGridLocator against a brute-force search (which it must match exactly, ties broken
// by the smaller id) and against vtkStaticPointLocator (same distances), on a random volume, a
// thin sheet, a tight cluster with far outliers (robust box), an integer lattice (every distance
// ties many times), a cloud with stacked duplicates and one with NaN points; queries at the points
// themselves, between them and outside the box. Each with the grid and with the k-d tree
// (SetSearchStructure()), which must give the same answers. Then the degenerate data sets: empty,
// one point, all points non-finite. Then the batched FindNearestNeighbors(),
// GenerateRepresentation(), and clusters far apart (where AUTO picks the tree).
#include "vtkCellArray.h"
#include "vtkIdList.h"
#include "vtkIntArray.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointCloudGridLocator.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStaticPointLocator.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <random>
#include <string>
#include <utility>
#include <numeric>
#include <vector>

namespace
{
int Failures = 0;

void Check(bool ok, const std::string& what)
{
  if (!ok)
  {
    std::printf("FAILED: %s\n", what.c_str());
    ++Failures;
  }
}

vtkSmartPointer<vtkPolyData> Cloud(const std::string& kind, int n, unsigned seed)
{
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  for (int i = 0; i < n; ++i)
  {
    double x[3] = { u(rng), u(rng), u(rng) };
    if (kind == "sheet")
    {
      x[2] *= 0.001;
    }
    else if (kind == "cluster")
    {
      const double scale = i < 4 ? 1e5 : 0.01;
      for (double& c : x)
      {
        c *= scale;
      }
    }
    else if (kind == "lattice")
    {
      x[0] = i % 12;
      x[1] = (i / 12) % 12;
      x[2] = i / 144;
    }
    else if (kind == "nan" && i % 37 == 5)
    {
      x[i % 3] = i % 2 ? std::nan("") : HUGE_VAL;
    }
    points->InsertNextPoint(x);
  }
  if (kind == "duplicates")
  {
    for (int i = 0; i < n / 4; ++i)
    {
      points->InsertNextPoint(points->GetPoint(i % 50)); // stacks of up to 6 copies
    }
  }
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(points);
  return data;
}

bool Finite(const double x[3])
{
  return std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]);
}

// All finite points by (squared distance to x, id), leaving `skip` out.
std::vector<std::pair<double, vtkIdType>> BruteForce(
  vtkPoints* points, const double x[3], vtkIdType skip = -1)
{
  std::vector<std::pair<double, vtkIdType>> all;
  double y[3];
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    points->GetPoint(i, y);
    if (i != skip && Finite(y))
    {
      const double dx = x[0] - y[0], dy = x[1] - y[1], dz = x[2] - y[2];
      all.emplace_back(dx * dx + dy * dy + dz * dz, i);
    }
  }
  std::sort(all.begin(), all.end());
  return all;
}

std::vector<vtkIdType> IdsOf(vtkIdList* list)
{
  return std::vector<vtkIdType>(list->GetPointer(0), list->GetPointer(0) + list->GetNumberOfIds());
}

void CompareQueries(const std::string& kind, int structure)
{
  vtkSmartPointer<vtkPolyData> data = Cloud(kind, 1500, 11);
  vtkPoints* points = data->GetPoints();
  const vtkIdType n = points->GetNumberOfPoints();
  vtkNew<vtkPointCloudGridLocator> grid;
  grid->SetDataSet(data);
  grid->SetSearchStructure(structure);
  grid->BuildLocator();
  const std::string name =
    kind + (structure == vtkPointCloudGridLocator::KD_TREE ? " (tree)" : " (grid)");
  Check(grid->GetUsesTree() == (structure == vtkPointCloudGridLocator::KD_TREE),
    name + ": the structure asked for");
  // The static locator is given the finite points only (a NaN has no bucket there).
  vtkNew<vtkPoints> finite;
  std::vector<vtkIdType> finiteId;
  for (vtkIdType i = 0; i < n; ++i)
  {
    if (Finite(points->GetPoint(i)))
    {
      finite->InsertNextPoint(points->GetPoint(i));
      finiteId.push_back(i);
    }
  }
  vtkNew<vtkPolyData> finiteData;
  finiteData->SetPoints(finite);
  vtkNew<vtkStaticPointLocator> reference;
  reference->SetDataSet(finiteData);
  reference->BuildLocator();
  Check(grid->GetNumberOfGridPoints() == static_cast<vtkIdType>(finiteId.size()),
    name + ": number of grid points");

  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  std::uniform_int_distribution<vtkIdType> pick(0, n - 1);
  long mismatches = 0, distanceMismatches = 0, queries = 0;
  vtkNew<vtkIdList> a, b;
  for (int q = 0; q < 300; ++q)
  {
    double x[3];
    if (q % 3 == 0)
    {
      points->GetPoint(pick(rng), x); // at a point (ties with its copies)
    }
    else
    {
      const double scale = kind == "lattice" ? 8.0 : (kind == "cluster" ? 0.02 : 1.0);
      for (double& c : x)
      {
        c = scale * u(rng) + (kind == "lattice" ? 5.5 : 0.0);
      }
      if (q % 3 == 2 && kind == "lattice")
      {
        // Half-integer positions: many points at exactly the same distance.
        for (double& c : x)
        {
          c = std::round(c) + 0.5;
        }
      }
    }
    if (!Finite(x))
    {
      continue;
    }
    ++queries;
    const auto expected = BruteForce(points, x);
    // FindClosestPoint: the nearest, the smaller id among ties.
    mismatches += grid->FindClosestPoint(x) == expected.front().second ? 0 : 1;
    // FindClosestNPoints: exactly the brute force's first N, in its order.
    for (int N : { 1, 6, 25 })
    {
      grid->FindClosestNPoints(N, x, a);
      reference->FindClosestNPoints(N, x, b);
      std::vector<vtkIdType> ids = IdsOf(a);
      mismatches += static_cast<int>(ids.size()) == N ? 0 : 1;
      for (int j = 0; j < N && j < static_cast<int>(ids.size()); ++j)
      {
        mismatches += ids[j] == expected[j].second ? 0 : 1;
        // The static locator: the same distance at each rank.
        const vtkIdType other = finiteId[b->GetId(j)];
        const double d2 = vtkMath::Distance2BetweenPoints(x, points->GetPoint(other));
        distanceMismatches += d2 == expected[j].first ? 0 : 1;
      }
    }
    // FindPointsWithinRadius: every point within R, nearest first; the static locator's set. R
    // lies halfway between the 13th distance and the next larger one, where rounding cannot move
    // a point across.
    size_t inside = std::min<size_t>(12, expected.size() - 2);
    while (inside + 2 < expected.size() && expected[inside + 1].first == expected[inside].first)
    {
      ++inside;
    }
    const double R =
      0.5 * (std::sqrt(expected[inside].first) + std::sqrt(expected[inside + 1].first));
    grid->FindPointsWithinRadius(R, x, a);
    reference->FindPointsWithinRadius(R, x, b);
    std::vector<vtkIdType> within, staticWithin;
    for (const auto& e : expected)
    {
      if (e.first <= R * R)
      {
        within.push_back(e.second);
      }
    }
    mismatches += IdsOf(a) == within ? 0 : 1;
    for (vtkIdType j = 0; j < b->GetNumberOfIds(); ++j)
    {
      staticWithin.push_back(finiteId[b->GetId(j)]);
    }
    std::sort(within.begin(), within.end());
    std::sort(staticWithin.begin(), staticWithin.end());
    distanceMismatches += within == staticWithin ? 0 : 1;
    // FindClosestPointWithinRadius: the nearest inside the radius, none outside.
    double dist2 = 0.0;
    mismatches += grid->FindClosestPointWithinRadius(R, x, dist2) == expected.front().second &&
        dist2 == expected.front().first
      ? 0
      : 1;
    const double shorter = 0.5 * std::sqrt(expected.front().first);
    mismatches += expected.front().first > 0.0 &&
        grid->FindClosestPointWithinRadius(shorter, x, dist2) != -1
      ? 1
      : 0;
  }
  // Non-finite positions find nothing.
  const double nowhere[3] = { std::nan(""), 0.0, 0.0 };
  grid->FindClosestNPoints(3, nowhere, a);
  mismatches += grid->FindClosestPoint(nowhere) == -1 && a->GetNumberOfIds() == 0 ? 0 : 1;
  std::printf("%-10s %ld queries: %ld mismatches with the brute force, %ld distance mismatches "
              "with vtkStaticPointLocator\n",
    name.c_str(), queries, mismatches, distanceMismatches);
  Check(queries > 250 && mismatches == 0 && distanceMismatches == 0, name + ": queries");
}

// The batched query: row r holds the k nearest *other* points of ids[r], as the brute force.
void CompareBatched(const std::string& kind, int structure)
{
  vtkSmartPointer<vtkPolyData> data = Cloud(kind, 1200, 13);
  vtkPoints* points = data->GetPoints();
  const vtkIdType n = points->GetNumberOfPoints();
  vtkNew<vtkPointCloudGridLocator> grid;
  grid->SetDataSet(data);
  grid->SetSearchStructure(structure);
  grid->BuildLocator();
  const std::string name =
    kind + (structure == vtkPointCloudGridLocator::KD_TREE ? " (tree)" : " (grid)");
  long mismatches = 0;
  // Every point (a cell's queries answered together for k > 8), every third (the slots marked in
  // an array over the grid), and every 40th (fewer than a sixteenth of the points: the listed rows
  // sorted).
  for (int stride : { 1, 3, 40 })
  {
    std::vector<vtkIdType> ids;
    for (vtkIdType i = n - 1; i >= 0; i -= stride)
    {
      ids.push_back(i); // descending
    }
    ids.push_back(ids.front()); // one id twice
    ids.push_back(ids[1]);      // and another, after it
    for (int k : { 1, 5, 12, 40, 150 })
    {
      std::vector<int32_t> table;
      std::vector<double> nearest;
      grid->FindNearestNeighbors(k, ids, table, &nearest);
      mismatches += table.size() == ids.size() * k && nearest.size() == ids.size() ? 0 : 1;
      for (size_t r = 0; r < ids.size() && table.size() == ids.size() * k; ++r)
      {
        double x[3];
        points->GetPoint(ids[r], x);
        const bool valid = Finite(x);
        const auto expected = valid ? BruteForce(points, x, ids[r]) : decltype(BruteForce(points, x)){};
        for (int j = 0; j < k; ++j)
        {
          const vtkIdType want = j < static_cast<int>(expected.size()) ? expected[j].second : -1;
          mismatches += table[r * k + j] == want ? 0 : 1;
        }
        const double wantNearest = expected.empty() ? 0.0 : std::sqrt(expected.front().first);
        mismatches += nearest[r] == wantNearest ? 0 : 1;
      }
    }
    // distinct: the nearest point at a nonzero distance.
    std::vector<int32_t> table;
    std::vector<double> nearest;
    grid->FindNearestNeighbors(1, ids, table, &nearest, true);
    for (size_t r = 0; r < ids.size(); ++r)
    {
      double x[3];
      points->GetPoint(ids[r], x);
      vtkIdType want = -1;
      double wantDistance = 0.0;
      if (Finite(x))
      {
        for (const auto& e : BruteForce(points, x, ids[r]))
        {
          if (e.first > 0.0)
          {
            want = e.second;
            wantDistance = std::sqrt(e.first);
            break;
          }
        }
      }
      mismatches += table[r] == want && nearest[r] == wantDistance ? 0 : 1;
    }
    // The wrapped counterpart gives the same table.
    vtkNew<vtkIdList> idList;
    for (vtkIdType id : ids)
    {
      idList->InsertNextId(id);
    }
    vtkNew<vtkIntArray> wrapped;
    std::vector<int32_t> direct;
    grid->FindNearestNeighbors(7, ids, direct);
    mismatches += grid->FindNearestNeighbors(7, idList, wrapped) &&
        wrapped->GetNumberOfComponents() == 7 &&
        std::equal(direct.begin(), direct.end(), wrapped->GetPointer(0))
      ? 0
      : 1;
  }
  std::printf("batched %-17s: %ld mismatches with the brute force\n", name.c_str(), mismatches);
  Check(mismatches == 0, name + ": batched");
}

void Degenerate(int structure)
{
  vtkNew<vtkIdList> result;
  const double x[3] = { 0.1, 0.2, 0.3 };
  std::vector<int32_t> table;
  std::vector<double> nearest;
  // Empty: nothing found, no error.
  {
    vtkNew<vtkPolyData> empty;
    vtkNew<vtkPoints> none;
    empty->SetPoints(none);
    vtkNew<vtkPointCloudGridLocator> grid;
    grid->SetSearchStructure(structure);
    grid->SetDataSet(empty);
    grid->BuildLocator();
    grid->FindClosestNPoints(4, x, result);
    grid->FindNearestNeighbors(3, std::vector<vtkIdType>{ 0, 5 }, table, &nearest);
    Check(grid->FindClosestPoint(x) == -1 && result->GetNumberOfIds() == 0 &&
        table == std::vector<int32_t>(6, -1) && nearest == std::vector<double>(2, 0.0) &&
        grid->GetNumberOfGridPoints() == 0,
      "empty data set");
  }
  // One point: it is everyone's nearest, and has no other.
  {
    vtkNew<vtkPolyData> one;
    vtkNew<vtkPoints> single;
    single->InsertNextPoint(5.0, -2.0, 1.0);
    one->SetPoints(single);
    vtkNew<vtkPointCloudGridLocator> grid;
    grid->SetSearchStructure(structure);
    grid->SetDataSet(one);
    grid->FindClosestNPoints(4, x, result); // builds on first use
    double dist2 = 0.0;
    grid->FindNearestNeighbors(2, std::vector<vtkIdType>{ 0 }, table, &nearest);
    Check(grid->FindClosestPoint(x) == 0 && result->GetNumberOfIds() == 1 &&
        result->GetId(0) == 0 && grid->FindClosestPointWithinRadius(1.0, x, dist2) == -1 &&
        grid->FindClosestPointWithinRadius(10.0, x, dist2) == 0 &&
        dist2 == vtkMath::Distance2BetweenPoints(x, single->GetPoint(0)) &&
        table == std::vector<int32_t>(2, -1) && nearest[0] == 0.0,
      "one-point data set");
  }
  // Only non-finite points: an empty grid.
  {
    vtkNew<vtkPolyData> bad;
    vtkNew<vtkPoints> nans;
    nans->InsertNextPoint(std::nan(""), 0.0, 0.0);
    nans->InsertNextPoint(0.0, HUGE_VAL, 0.0);
    bad->SetPoints(nans);
    vtkNew<vtkPointCloudGridLocator> grid;
    grid->SetSearchStructure(structure);
    grid->SetDataSet(bad);
    grid->BuildLocator();
    grid->FindPointsWithinRadius(1e300, x, result);
    Check(grid->FindClosestPoint(x) == -1 && result->GetNumberOfIds() == 0 &&
        grid->GetNumberOfGridPoints() == 0,
      "non-finite data set");
  }
  // Distances near the smallest normal double (a cloud spanning 1e-300 to 1e300, scaled
  // down): the buckets' scale (candidates over the largest squared distance) overflows; the k
  // nearest (more than the heap's 8) are still the nearest, in distance order.
  {
    vtkNew<vtkPolyData> tiny;
    vtkNew<vtkPoints> close;
    close->SetDataTypeToDouble();
    close->InsertNextPoint(0.0, 0.0, 0.0);
    const double r0 = 2.3e-154; // r0^2 = 5.3e-308, (1.5 r0)^2 = 1.2e-307
    for (int i = 1; i <= 30; ++i)
    {
      const double r = r0 * (1.0 + i / 60.0), a = 0.7 * i;
      close->InsertNextPoint(r * std::cos(a), r * std::sin(a), 0.0);
    }
    close->InsertNextPoint(1.0, 0.0, 0.0);
    tiny->SetPoints(close);
    vtkNew<vtkPointCloudGridLocator> grid;
    grid->SetSearchStructure(structure);
    grid->SetDataSet(tiny);
    grid->BuildLocator();
    grid->FindNearestNeighbors(20, std::vector<vtkIdType>{ 0 }, table, &nearest);
    bool ordered = table.size() == 20;
    for (int j = 0; j < 20 && ordered; ++j)
    {
      ordered = table[j] == j + 1;
    }
    Check(ordered, "squared distances near the smallest double");
  }
}

// The outline: 8 corners, 12 edges, a box that holds the points.
void Representation()
{
  vtkSmartPointer<vtkPolyData> data = Cloud("volume", 500, 3);
  vtkNew<vtkPointCloudGridLocator> grid;
  grid->SetDataSet(data);
  vtkNew<vtkPolyData> outline;
  grid->GenerateRepresentation(0, outline);
  double box[6], points[6];
  outline->GetBounds(box);
  data->GetBounds(points);
  bool holds = true;
  for (int a = 0; a < 3; ++a)
  {
    holds = holds && box[2 * a] <= points[2 * a] && box[2 * a + 1] >= points[2 * a + 1];
  }
  int divisions[3];
  grid->GetDivisions(divisions);
  const double cells = static_cast<double>(divisions[0]) * divisions[1] * divisions[2];
  std::printf("outline: %lld points, %lld lines, %d x %d x %d cells for 500 points\n",
    static_cast<long long>(outline->GetNumberOfPoints()),
    static_cast<long long>(outline->GetNumberOfLines()), divisions[0], divisions[1], divisions[2]);
  // About two cells per point (at most two, and not far fewer).
  Check(outline->GetNumberOfPoints() == 8 && outline->GetNumberOfLines() == 12 && holds &&
      cells <= 1000.0 && cells >= 500.0,
    "representation");
}
} // namespace

// A dense cube and 3 % of the points spread a million times further: the grid's box is the cube's
// (its cells resolve the cube; the bounds would put it in one cell), and the nearest points are
// still exact.
void SpreadOutliers()
{
  std::mt19937 random(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0), far(-1e6, 1e6);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (int i = 0; i < 20000; ++i)
  {
    points->InsertNextPoint(unit(random), unit(random), unit(random));
  }
  for (int i = 0; i < 600; ++i)
  {
    points->InsertNextPoint(far(random), far(random), far(random));
  }
  vtkNew<vtkPolyData> data;
  data->SetPoints(points);
  vtkNew<vtkPointCloudGridLocator> grid;
  grid->SetDataSet(data);
  grid->BuildLocator();
  vtkNew<vtkPolyData> outline;
  grid->GenerateRepresentation(0, outline);
  double box[6];
  outline->GetBounds(box);
  vtkNew<vtkStaticPointLocator> reference;
  reference->SetDataSet(data);
  reference->BuildLocator();
  vtkNew<vtkIdList> expected, found;
  bool same = true;
  for (vtkIdType q = 0; q < 20600; q += 1000)
  {
    reference->FindClosestNPoints(10, points->GetPoint(q), expected);
    grid->FindClosestNPoints(10, points->GetPoint(q), found);
    same = same && IdsOf(expected) == IdsOf(found);
  }
  std::printf("spread outliers: box %g wide\n", box[1] - box[0]);
  Check(box[1] - box[0] < 10.0 && same, "spread outliers: the cube's box, exact nearest points");
}

// Three dense clusters (cube surfaces of 4,000 points each) a million times their size apart:
// each falls into a handful of the grid's cells, so AUTO answers with the k-d tree, and the
// answers are the brute force's (the 40 nearest of every 97th point, and a few far queries).
void FarClusters()
{
  std::mt19937 random(9);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  const double offsets[3][3] = { { 0, 0, 0 }, { 1e6, 0, 0 }, { 3e5, 7e5, -2e5 } };
  for (const auto& offset : offsets)
  {
    for (int i = 0; i < 4000; ++i)
    {
      double x[3] = { unit(random), unit(random), unit(random) };
      x[i % 3] = (i / 3) % 2; // on a face of the unit cube
      points->InsertNextPoint(x[0] + offset[0], x[1] + offset[1], x[2] + offset[2]);
    }
  }
  vtkNew<vtkPolyData> data;
  data->SetPoints(points);
  vtkNew<vtkPointCloudGridLocator> grid;
  grid->SetDataSet(data);
  grid->BuildLocator();
  const bool tree = grid->GetUsesTree();
  std::vector<vtkIdType> ids;
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); i += 97)
  {
    ids.push_back(i);
  }
  std::vector<int32_t> table;
  grid->FindNearestNeighbors(40, ids, table);
  long mismatches = 0;
  for (size_t r = 0; r < ids.size(); ++r)
  {
    const auto expected = BruteForce(points, points->GetPoint(ids[r]), ids[r]);
    for (int j = 0; j < 40; ++j)
    {
      mismatches += table[r * 40 + j] == expected[j].second ? 0 : 1;
    }
  }
  vtkNew<vtkIdList> found;
  for (const double* x : { offsets[1], offsets[2] })
  {
    const double far[3] = { x[0] + 5e5, x[1] - 3e5, x[2] + 11.0 };
    const auto expected = BruteForce(points, far);
    grid->FindClosestNPoints(30, far, found);
    for (int j = 0; j < 30; ++j)
    {
      mismatches += found->GetNumberOfIds() == 30 && found->GetId(j) == expected[j].second ? 0 : 1;
    }
  }
  std::printf("far clusters: cell occupancy %.0f, %s, %ld mismatches with the brute force\n",
    grid->GetCellOccupancy(), tree ? "k-d tree" : "grid", mismatches);
  Check(tree && mismatches == 0, "far clusters: the k-d tree, exact nearest points");
}

// Spacings shrinking geometrically from 1 to 1e-300 (a cloud found by fuzzing): about half of
// the points lie within 1e-162 of each other, where squared distances underflow to 0. They form
// one site (one position to every query), so that the queries do not read them all (before,
// 20,000 points took seconds and 200,000 minutes: a speed that docs/design.md measures, not this
// test). What this checks is that the grouping keeps the answers: the nearest points are the
// brute force's wherever the k-th squared distance is a normal number, and below that, where the
// grid's distances and the brute force's may differ by a subnormal, the k-th distance found is
// the brute force's within 1e-300.
void ShrinkingSpacings(int structure)
{
  const int n = 3000, k = 15;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (int i = 0; i < n; ++i)
  {
    const double e = std::exp(-700.0 * i / (n - 1));
    points->InsertNextPoint(e, e * std::fmod(i * 0.6180339887, 1.0), e * std::fmod(i * 0.4142135623, 1.0));
  }
  vtkNew<vtkPolyData> data;
  data->SetPoints(points);
  vtkNew<vtkPointCloudGridLocator> grid;
  grid->SetSearchStructure(structure);
  grid->SetDataSet(data);
  grid->BuildLocator();
  std::vector<vtkIdType> ids(n);
  std::iota(ids.begin(), ids.end(), 0);
  std::vector<int32_t> table;
  grid->FindNearestNeighbors(k, ids, table);
  long mismatches = 0, exact = 0;
  double worst = 0.0;
  for (int r = 0; r < n; ++r)
  {
    double x[3], y[3];
    points->GetPoint(r, x);
    const auto expected = BruteForce(points, x, r);
    if (expected[k - 1].first >= std::numeric_limits<double>::min())
    {
      ++exact;
      for (int j = 0; j < k; ++j)
      {
        mismatches += table[r * k + j] == expected[j].second ? 0 : 1;
      }
      continue;
    }
    points->GetPoint(table[r * k + k - 1], y);
    const double d2 = vtkMath::Distance2BetweenPoints(x, y);
    worst = std::max(worst, std::fabs(d2 - expected[k - 1].first));
  }
  std::printf("shrinking spacings (%s): %ld of %ld rows with normal distances differ from the "
              "brute force, the others' k-th distance within %g\n",
    structure == vtkPointCloudGridLocator::GRID ? "grid" : "k-d tree", mismatches, exact, worst);
  Check(mismatches == 0 && exact > n / 3 && worst <= 1e-300, "shrinking spacings");
}

int TestPointCloudGridLocator(int, char*[])
{
  for (int structure : { vtkPointCloudGridLocator::GRID, vtkPointCloudGridLocator::KD_TREE })
  {
    for (const char* kind : { "volume", "sheet", "cluster", "lattice", "duplicates", "nan" })
    {
      CompareQueries(kind, structure);
      CompareBatched(kind, structure);
    }
    Degenerate(structure);
    ShrinkingSpacings(structure);
  }
  Representation();
  SpreadOutliers();
  FarClusters();
  return Failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
