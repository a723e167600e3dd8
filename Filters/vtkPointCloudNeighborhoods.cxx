#include "vtkPointCloudNeighborhoods.h"

#include "vtkAlgorithm.h"
#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkFeaturePointsLocalPCA.h"
#include "vtkFeaturePointsStatistics.h"
#include "vtkFeaturePointsVertexCells.h"
#include "vtkTypeInt32Array.h"
#include "vtkTypeInt64Array.h"
#include "vtkIdList.h"
#include "vtkIntArray.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPThreadLocalObject.h"
#include "vtkSMPTools.h"
#include "vtkStaticPointLocator.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

vtkStandardNewMacro(vtkPointCloudNeighborhoods);

struct vtkPointCloudNeighborhoods::SearchGrid
{
  double Origin[3] = { 0, 0, 0 };
  double Spacing = 1.0; // side of a cell
  int Dims[3] = { 1, 1, 1 };
  std::vector<int32_t> CellStart;   // first slot of each cell, then the number of slots
  std::vector<int32_t> SortedIds;   // point id of each slot, cell by cell, ascending in a cell
  std::vector<double> SortedPoints; // coordinates of each slot
  std::vector<int32_t> SlotOf;      // slot of each point, -1 for invalid points

  // Coincident points (BuildSites(), only when some points coincide): the distinct positions of
  // each cell ("sites"), each with its points, so that a query reads a stack of copies once
  // rather than once per copy.
  bool HasDuplicates = false;
  std::vector<int32_t> SiteStart;   // first site of each cell, then the number of sites
  std::vector<double> SitePoints;   // coordinates of each site
  std::vector<int32_t> MemberStart; // first member of each site, then the number of members
  std::vector<int32_t> Members;     // slots of the points of each site, ascending

  vtkIdType Index(int i, int j, int k) const
  {
    return i + this->Dims[0] * (j + static_cast<vtkIdType>(this->Dims[1]) * k);
  }
  // Squared distance from x to the box of cell (i, j, k); border cells are open on their outer side.
  double BoxDistance2(int i, int j, int k, const double x[3]) const
  {
    const int c[3] = { i, j, k };
    double d2 = 0.0;
    for (int a = 0; a < 3; ++a)
    {
      const double gap = this->AxisGap(a, c[a], x[a]);
      d2 += gap * gap;
    }
    return d2;
  }
  // Distance from coordinate xa to the slab of cells c along axis a.
  double AxisGap(int a, int c, double xa) const
  {
    const double lo = this->Origin[a] + c * this->Spacing;
    return c > 0 && xa < lo
      ? lo - xa
      : (c < this->Dims[a] - 1 && xa > lo + this->Spacing ? xa - lo - this->Spacing : 0.0);
  }
  // The cells at Chebyshev distance `ring` from cell c: whole rows on the block's faces, the two
  // end cells of the rows inside it.
  template <typename F>
  void ForEachCellOfRing(const int c[3], int ring, F&& f) const
  {
    const int lo[3] = { std::max(c[0] - ring, 0), std::max(c[1] - ring, 0),
      std::max(c[2] - ring, 0) };
    const int hi[3] = { std::min(c[0] + ring, this->Dims[0] - 1),
      std::min(c[1] + ring, this->Dims[1] - 1), std::min(c[2] + ring, this->Dims[2] - 1) };
    for (int k = lo[2]; k <= hi[2]; ++k)
    {
      const bool kFace = k == c[2] - ring || k == c[2] + ring;
      for (int j = lo[1]; j <= hi[1]; ++j)
      {
        if (kFace || j == c[1] - ring || j == c[1] + ring)
        {
          for (int i = lo[0]; i <= hi[0]; ++i)
          {
            f(i, j, k);
          }
        }
        else
        {
          if (c[0] - ring >= 0)
          {
            f(c[0] - ring, j, k);
          }
          if (c[0] + ring < this->Dims[0])
          {
            f(c[0] + ring, j, k);
          }
        }
      }
    }
  }
  // Distance from x to the cells outside the block of rings 0..ring around cell c (any point not
  // yet seen lies there); `everything` tells that the block covers the whole grid.
  double RingGap(const int c[3], int ring, const double x[3], bool& everything) const
  {
    everything = true;
    double gap = VTK_DOUBLE_MAX;
    for (int a = 0; a < 3; ++a)
    {
      if (c[a] - ring > 0)
      {
        gap = std::min(gap, x[a] - (this->Origin[a] + (c[a] - ring) * this->Spacing));
        everything = false;
      }
      if (c[a] + ring < this->Dims[a] - 1)
      {
        gap = std::min(gap, this->Origin[a] + (c[a] + ring + 1) * this->Spacing - x[a]);
        everything = false;
      }
    }
    return gap;
  }
  // The cell of x, clamped to the grid: points beyond the robust box sit in its border cells.
  void CellOf(const double x[3], int c[3]) const
  {
    for (int a = 0; a < 3; ++a)
    {
      const double f = std::floor((x[a] - this->Origin[a]) / this->Spacing);
      c[a] = f < 0.0 ? 0 : (f >= this->Dims[a] - 1 ? this->Dims[a] - 1 : static_cast<int>(f));
    }
  }
};

namespace
{
// One k-nearest query per listed point; row r of the table gets the k nearest *other* valid points
// of ids[r], nearest first. The query asks for k + 1 points because the point itself comes back
// among them (first, unless duplicates tie with it at distance 0).
struct NearestNeighborsWorker
{
  vtkPoints* Points;
  vtkStaticPointLocator* Locator;
  const vtkIdType* LocatorToPoint; // null: locator ids are point ids
  const unsigned char* Valid;
  const vtkIdType* Ids;
  int K;
  int32_t* Table;
  double* Nearest;
  vtkSMPThreadLocalObject<vtkIdList> Result;

  void Initialize() { this->Result.Local()->Allocate(this->K + 1); }

  void operator()(vtkIdType begin, vtkIdType end)
  {
    vtkIdList* result = this->Result.Local();
    double x[3], y[3];
    for (vtkIdType r = begin; r < end; ++r)
    {
      const vtkIdType id = this->Ids[r];
      int32_t* row = this->Table + r * this->K;
      int n = 0;
      double nearest = 0.0;
      if (this->Valid[id])
      {
        this->Points->GetPoint(id, x);
        this->Locator->FindClosestNPoints(this->K + 1, x, result);
        const vtkIdType found = result->GetNumberOfIds();
        bool selfSkipped = false;
        for (vtkIdType j = 0; j < found && n < this->K; ++j)
        {
          vtkIdType other = result->GetId(j);
          if (this->LocatorToPoint)
          {
            other = this->LocatorToPoint[other];
          }
          if (!selfSkipped && other == id)
          {
            selfSkipped = true;
            continue;
          }
          if (n == 0)
          {
            this->Points->GetPoint(other, y);
            nearest = std::sqrt(vtkMath::Distance2BetweenPoints(x, y));
          }
          row[n++] = static_cast<int32_t>(other);
        }
      }
      for (; n < this->K; ++n)
      {
        row[n] = -1;
      }
      if (this->Nearest)
      {
        this->Nearest[r] = nearest;
      }
    }
  }

  void Reduce() {}
};

// Exact k nearest neighbours on the module's own uniform grid (vtkPointCloudNeighborhoods::Grid):
// rings of cells around the query's cell, nearest first, until the k-th best distance is below
// the distance to the unsearched cells. Candidates are ordered by (distance, id), so ties are
// broken the same way whatever the scanning order, and each row depends on its point only.
struct GridNeighborsWorker
{
  const vtkPointCloudNeighborhoods::SearchGrid* Grid;
  const int32_t* Slots;     // the queries' slots, in grid order
  const vtkIdType* Rows;    // the table row of each of them
  int K;
  int32_t* Table;
  double* Nearest;
  bool Distinct; // K = 1 only: the nearest point at a nonzero distance

  struct Candidate
  {
    double D2;
    int32_t Id;
    bool operator<(const Candidate& o) const { return D2 < o.D2 || (D2 == o.D2 && Id < o.Id); }
  };
  vtkSMPThreadLocal<std::vector<Candidate>> Candidates;
  struct BucketScratch
  {
    std::vector<Candidate> Sorted;
    std::vector<int32_t> Start;
  };
  vtkSMPThreadLocal<BucketScratch> Buckets;

  void Initialize() {}

  // Sorts the candidates by (distance, id) and keeps the first `keep`: a bucket sort on the
  // squared distance (about one candidate per bucket, buckets in distance order, each bucket then
  // sorted exactly), which costs a few passes where nth_element and sort compare and mispredict
  // O(m log m) times. Buckets past the one that holds the keep-th candidate are never sorted.
  static void SortNearest(std::vector<Candidate>& candidates, size_t keep, BucketScratch& scratch)
  {
    const size_t m = candidates.size();
    if (m <= 16)
    {
      std::sort(candidates.begin(), candidates.end());
      candidates.resize(std::min(m, keep));
      return;
    }
    double largest = 0.0;
    for (const Candidate& c : candidates)
    {
      largest = std::max(largest, c.D2);
    }
    if (!std::isfinite(largest))
    {
      // Squared distances that overflow (coordinates beyond 1e154) have no bucket: plain sort.
      std::sort(candidates.begin(), candidates.end());
      candidates.resize(std::min(m, keep));
      return;
    }
    const int32_t buckets = static_cast<int32_t>(m);
    // Monotone in D2: a larger distance never lands in an earlier bucket.
    const double scale = largest > 0.0 ? (buckets - 0.5) / largest : 0.0;
    auto bucketOf = [scale, buckets](double d2) {
      return std::min(buckets - 1, static_cast<int32_t>(d2 * scale));
    };
    std::vector<int32_t>& start = scratch.Start;
    start.assign(static_cast<size_t>(buckets) + 1, 0);
    for (const Candidate& c : candidates)
    {
      ++start[bucketOf(c.D2) + 1];
    }
    for (int32_t b = 0; b < buckets; ++b)
    {
      start[b + 1] += start[b];
    }
    std::vector<Candidate>& sorted = scratch.Sorted;
    sorted.resize(m);
    {
      // Scatter, using start[b] as the next free slot of bucket b (restored below).
      for (const Candidate& c : candidates)
      {
        sorted[start[bucketOf(c.D2)]++] = c;
      }
      for (int32_t b = buckets; b > 0; --b)
      {
        start[b] = start[b - 1];
      }
      start[0] = 0;
    }
    size_t done = 0;
    for (int32_t b = 0; b < buckets && done < keep; ++b)
    {
      if (start[b + 1] - start[b] > 1)
      {
        std::sort(sorted.begin() + start[b], sorted.begin() + start[b + 1]);
      }
      done = static_cast<size_t>(start[b + 1]);
    }
    const size_t kept = std::min(m, keep);
    std::copy(sorted.begin(), sorted.begin() + kept, candidates.begin());
    candidates.resize(kept);
  }

  // k = 1 (the spacing and the voxel densities ask it of every point): the best candidate is kept
  // in registers rather than in a heap, the cells of the first ring are pruned with per-axis gaps
  // computed once, and the search stops at the same ring as the general one, with the same result.
  // Distinct: the nearest point at a nonzero distance (copies of x are skipped).
  template <bool Distinct>
  Candidate NearestOne(const double* x, int32_t id) const
  {
    const auto& g = *this->Grid;
    Candidate best{ VTK_DOUBLE_MAX, -1 };
    auto scanCell = [&](vtkIdType cell) {
      if (g.HasDuplicates)
      {
        // A site's nearest candidate is its first point other than x.
        for (int32_t site = g.SiteStart[cell]; site < g.SiteStart[cell + 1]; ++site)
        {
          const double* y = g.SitePoints.data() + 3 * static_cast<size_t>(site);
          const double dx = x[0] - y[0], dy = x[1] - y[1], dz = x[2] - y[2];
          const double d2 = dx * dx + dy * dy + dz * dz;
          if (d2 <= best.D2 && (!Distinct || d2 > 0.0))
          {
            int32_t m = g.MemberStart[site];
            int32_t other = g.SortedIds[g.Members[m]];
            if (other == id)
            {
              if (++m == g.MemberStart[site + 1])
              {
                continue;
              }
              other = g.SortedIds[g.Members[m]];
            }
            if (d2 < best.D2 || other < best.Id)
            {
              best = Candidate{ d2, other };
            }
          }
        }
        return;
      }
      const int32_t last = g.CellStart[cell + 1];
      const double* y = g.SortedPoints.data() + 3 * static_cast<size_t>(g.CellStart[cell]);
      for (int32_t s = g.CellStart[cell]; s < last; ++s, y += 3)
      {
        const double dx = x[0] - y[0], dy = x[1] - y[1], dz = x[2] - y[2];
        const double d2 = dx * dx + dy * dy + dz * dz;
        if (d2 <= best.D2 && (!Distinct || d2 > 0.0))
        {
          const int32_t other = g.SortedIds[s];
          if (other != id && (d2 < best.D2 || other < best.Id))
          {
            best = Candidate{ d2, other };
          }
        }
      }
    };
    int c[3];
    g.CellOf(x, c);
    // Per axis, the squared gap from x to the cells c - 1, c, c + 1 (-1: outside the grid).
    double gap2[3][3];
    for (int a = 0; a < 3; ++a)
    {
      for (int d = 0; d < 3; ++d)
      {
        const int ca = c[a] + d - 1;
        const double gap = ca >= 0 && ca < g.Dims[a] ? g.AxisGap(a, ca, x[a]) : -1.0;
        gap2[a][d] = gap < 0.0 ? -1.0 : gap * gap;
      }
    }
    scanCell(g.Index(c[0], c[1], c[2]));
    // The general rule of the k-nearest search, ring by ring: stop when the best distance is
    // below the distance to the unsearched cells (or nothing is left).
    for (int ring = 0;; ++ring)
    {
      if (ring == 1)
      {
        for (int dk = 0; dk < 3; ++dk)
        {
          if (gap2[2][dk] < 0.0)
          {
            continue;
          }
          for (int dj = 0; dj < 3; ++dj)
          {
            if (gap2[1][dj] < 0.0)
            {
              continue;
            }
            for (int di = 0; di < 3; ++di)
            {
              if (gap2[0][di] < 0.0 || (di == 1 && dj == 1 && dk == 1))
              {
                continue;
              }
              // The sum in BoxDistance2's order, so that the same cells are pruned.
              if (best.Id >= 0 && gap2[0][di] + gap2[1][dj] + gap2[2][dk] > best.D2)
              {
                continue;
              }
              scanCell(g.Index(c[0] + di - 1, c[1] + dj - 1, c[2] + dk - 1));
            }
          }
        }
      }
      else if (ring > 1)
      {
        g.ForEachCellOfRing(c, ring, [&](int i, int j, int k) {
          if (best.Id < 0 || g.BoxDistance2(i, j, k, x) <= best.D2)
          {
            scanCell(g.Index(i, j, k));
          }
        });
      }
      bool everything;
      const double gap = g.RingGap(c, ring, x, everything);
      if (best.Id >= 0 ? (everything || (gap > 0.0 && best.D2 < gap * gap)) : everything)
      {
        return best;
      }
    }
  }

  void operator()(vtkIdType begin, vtkIdType end)
  {
    if (this->K == 1)
    {
      const auto& g = *this->Grid;
      for (vtkIdType o = begin; o < end; ++o)
      {
        const int32_t slot = this->Slots[o];
        const vtkIdType r = this->Rows[o];
        const double* x = g.SortedPoints.data() + 3 * static_cast<size_t>(slot);
        const Candidate best = this->Distinct ? this->NearestOne<true>(x, g.SortedIds[slot])
                                              : this->NearestOne<false>(x, g.SortedIds[slot]);
        this->Table[r] = best.Id;
        if (this->Nearest)
        {
          this->Nearest[r] = best.Id >= 0 ? std::sqrt(best.D2) : 0.0;
        }
      }
      return;
    }
    std::vector<Candidate>& candidates = this->Candidates.Local();
    BucketScratch& bucketScratch = this->Buckets.Local();
    const auto& g = *this->Grid;
    // Large k: the k-th squared distance of the previous query, a guess for this one (queries come
    // in grid order, so neighbouring queries follow each other). The result never depends on it.
    double hint = -1.0;
    for (vtkIdType o = begin; o < end; ++o)
    {
      // Queries in grid order read their coordinates in sequence, from the grid's own copy.
      const int32_t slot = this->Slots[o];
      const vtkIdType r = this->Rows[o];
      const int32_t id = g.SortedIds[slot];
      const double* x = g.SortedPoints.data() + 3 * static_cast<size_t>(slot);
      int32_t* row = this->Table + r * this->K;
      int n = 0;
      double nearest = 0.0;
      {
        candidates.clear();
        const bool useHeap = this->K <= 8;
        // Large k: once k candidates are known, nothing farther than the k-th can enter. Before
        // that, a guess from the previous query (1.2 times its k-th distance) keeps the far points
        // and cells out; when fewer than k points lie within it, the search starts again without.
        bool guessed = !useHeap && hint > 0.0;
        double bound = guessed ? 1.44 * hint : VTK_DOUBLE_MAX;
        int c[3];
        g.CellOf(x, c);
        for (int ring = 0;; ++ring)
        {
          auto scan = [&](int i, int j, int k) {
            // Skip a cell whose box lies farther than the k-th best distance so far: none of its
            // points can enter (the border cells reach to infinity, they hold the clamped points).
            const double limit = useHeap
              ? (static_cast<int>(candidates.size()) == this->K ? candidates.front().D2 : VTK_DOUBLE_MAX)
              : bound;
            if (limit < VTK_DOUBLE_MAX && g.BoxDistance2(i, j, k, x) > limit)
            {
              return;
            }
            const vtkIdType cell = g.Index(i, j, k);
            // Offers a candidate; false when it is not kept.
            auto offer = [&](const Candidate& cand) {
              if (!useHeap)
              {
                if (cand.D2 <= bound)
                {
                  candidates.push_back(cand);
                  return true;
                }
                return false;
              }
              if (static_cast<int>(candidates.size()) < this->K)
              {
                candidates.push_back(cand);
                std::push_heap(candidates.begin(), candidates.end());
                return true;
              }
              if (cand < candidates.front())
              {
                std::pop_heap(candidates.begin(), candidates.end());
                candidates.back() = cand;
                std::push_heap(candidates.begin(), candidates.end());
                return true;
              }
              return false;
            };
            if (g.HasDuplicates)
            {
              // The points of a site share their distance and come in ascending ids: at most K
              // of them can be among the K nearest, the first K other than the query, and once
              // one is not kept none of the next ones is.
              for (int32_t site = g.SiteStart[cell]; site < g.SiteStart[cell + 1]; ++site)
              {
                const double* y = g.SitePoints.data() + 3 * static_cast<size_t>(site);
                const double dx = x[0] - y[0], dy = x[1] - y[1], dz = x[2] - y[2];
                const double d2 = dx * dx + dy * dy + dz * dz;
                int kept = 0;
                for (int32_t m = g.MemberStart[site]; m < g.MemberStart[site + 1] && kept < this->K;
                     ++m)
                {
                  const int32_t other = g.SortedIds[g.Members[m]];
                  if (other == id)
                  {
                    continue;
                  }
                  if (!offer(Candidate{ d2, other }))
                  {
                    break;
                  }
                  ++kept;
                }
              }
              return;
            }
            for (int32_t s = g.CellStart[cell]; s < g.CellStart[cell + 1]; ++s)
            {
              const int32_t other = g.SortedIds[s];
              if (other == id)
              {
                continue;
              }
              const double* y = g.SortedPoints.data() + 3 * static_cast<size_t>(s);
              const double dx = x[0] - y[0], dy = x[1] - y[1], dz = x[2] - y[2];
              offer(Candidate{ dx * dx + dy * dy + dz * dz, other });
            }
          };
          g.ForEachCellOfRing(c, ring, scan);
          bool everything;
          const double gap = g.RingGap(c, ring, x, everything);
          // Small k: a bounded max-heap of the k best. Large k: the candidates nearer than the
          // k-th best so far are kept, and once per ring they are sorted (SortNearest) and cut
          // to k, which costs less than a heap.
          if (useHeap && static_cast<int>(candidates.size()) == this->K)
          {
            if (everything || (gap > 0.0 && candidates.front().D2 < gap * gap))
            {
              break;
            }
          }
          else if (!useHeap && static_cast<int>(candidates.size()) >= this->K)
          {
            SortNearest(candidates, static_cast<size_t>(this->K), bucketScratch);
            bound = candidates[this->K - 1].D2;
            if (everything || (gap > 0.0 && bound < gap * gap))
            {
              break;
            }
          }
          else if (guessed && (everything || (gap > 0.0 && bound < gap * gap)))
          {
            // Fewer than k points within the guess, and none left to find there: no guess.
            candidates.clear();
            bound = VTK_DOUBLE_MAX;
            guessed = false;
            ring = -1;
            continue;
          }
          else if (everything)
          {
            break;
          }
        }
        if (useHeap || static_cast<int>(candidates.size()) < this->K)
        {
          std::sort(candidates.begin(), candidates.end()); // (large k: sorted when trimmed)
        }
        if (!useHeap && static_cast<int>(candidates.size()) == this->K)
        {
          hint = candidates.back().D2;
        }
        for (const Candidate& cand : candidates)
        {
          row[n++] = cand.Id;
        }
        if (n > 0)
        {
          nearest = std::sqrt(candidates.front().D2);
        }
      }
      for (; n < this->K; ++n)
      {
        row[n] = -1;
      }
      if (this->Nearest)
      {
        this->Nearest[r] = nearest;
      }
    }
  }

  void Reduce() {}
};
} // namespace

vtkPointCloudNeighborhoods::vtkPointCloudNeighborhoods() = default;
vtkPointCloudNeighborhoods::~vtkPointCloudNeighborhoods() = default;

vtkPoints* vtkPointCloudNeighborhoods::GetPoints() const
{
  return this->Points;
}

bool vtkPointCloudNeighborhoods::Build(vtkPoints* points)
{
  this->Points = points;
  this->Searchable = false;
  this->Grid.reset();
  this->Locator = nullptr;
  this->LocatorData = nullptr;
  this->LocatorToPoint.clear();
  this->Valid.clear();
  this->NearestDistances.clear();
  this->NearestKnown.clear();
  this->NumberOfPoints = points ? points->GetNumberOfPoints() : 0;
  this->NumberOfValidPoints = 0;
  this->FirstInvalidPoint = -1;
  this->NumberOfDuplicatePoints = 0;
  this->MeanSpacing = -1.0;
  this->ErrorText.clear();
  std::fill(this->Center, this->Center + 3, 0.0);
  std::fill(this->Bounds, this->Bounds + 6, 0.0);

  if (this->NumberOfPoints == 0)
  {
    this->ErrorText = "the input has no points";
    return false;
  }
  if (this->NumberOfPoints > std::numeric_limits<int32_t>::max())
  {
    this->ErrorText = "the input has more than 2^31 - 1 points";
    return false;
  }

  const vtkIdType n = this->NumberOfPoints;
  const featurepoints::PointReader reader(points);
  this->Valid.assign(n, 0);
  double lo[3] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, VTK_DOUBLE_MAX };
  double hi[3] = { -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
  double x[3];
  for (vtkIdType i = 0; i < n; ++i)
  {
    reader.Get(i, x);
    if (std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]))
    {
      this->Valid[i] = 1;
      ++this->NumberOfValidPoints;
      for (int c = 0; c < 3; ++c)
      {
        lo[c] = std::min(lo[c], x[c]);
        hi[c] = std::max(hi[c], x[c]);
      }
    }
    else if (this->FirstInvalidPoint < 0)
    {
      this->FirstInvalidPoint = i;
    }
  }
  if (this->NumberOfValidPoints == 0)
  {
    this->ErrorText = "no point has finite coordinates";
    return false;
  }
  for (int c = 0; c < 3; ++c)
  {
    this->Bounds[2 * c] = lo[c];
    this->Bounds[2 * c + 1] = hi[c];
    this->Center[c] = 0.5 * (lo[c] + hi[c]);
  }

  if (this->SearchMethod == GRID)
  {
    this->BuildGrid();
    this->Searchable = true;
    return true;
  }
  this->LocatorData = vtkSmartPointer<vtkPolyData>::New();
  if (this->NumberOfValidPoints == n)
  {
    this->LocatorData->SetPoints(points);
  }
  else
  {
    // Build the locator over the finite points only: a NaN coordinate has no bucket.
    vtkNew<vtkPoints> finite;
    finite->SetDataType(points->GetDataType());
    finite->SetNumberOfPoints(this->NumberOfValidPoints);
    this->LocatorToPoint.resize(this->NumberOfValidPoints);
    vtkIdType j = 0;
    for (vtkIdType i = 0; i < n; ++i)
    {
      if (this->Valid[i])
      {
        reader.Get(i, x);
        finite->SetPoint(j, x);
        this->LocatorToPoint[j++] = i;
      }
    }
    this->LocatorData->SetPoints(finite);
  }
  this->Locator = vtkSmartPointer<vtkStaticPointLocator>::New();
  this->Locator->SetDataSet(this->LocatorData);
  this->Locator->BuildLocator();
  this->Searchable = true;
  return true;
}

void vtkPointCloudNeighborhoods::BuildGrid()
{
  this->Grid.reset(new SearchGrid);
  SearchGrid& g = *this->Grid;
  const vtkIdType n = this->NumberOfPoints;
  const vtkIdType m = this->NumberOfValidPoints;
  const featurepoints::PointReader reader(this->Points);

  // The box: the bounds, or the central 99 % of the points widened by half its size when a few
  // far outliers stretch the bounds more than four times (they then share the border cells).
  double lo[3], hi[3];
  {
    const vtkIdType stride = std::max<vtkIdType>(1, m / 100000);
    std::vector<double> sample[3];
    double x[3];
    vtkIdType seen = 0;
    for (vtkIdType i = 0; i < n; ++i)
    {
      if (this->Valid[i] && (seen++ % stride) == 0)
      {
        reader.Get(i, x);
        for (int a = 0; a < 3; ++a)
        {
          sample[a].push_back(x[a]);
        }
      }
    }
    for (int a = 0; a < 3; ++a)
    {
      lo[a] = this->Bounds[2 * a];
      hi[a] = this->Bounds[2 * a + 1];
      std::vector<double>& v = sample[a];
      double rlo, rhi;
      featurepoints::CentralRange(v, rlo, rhi);
      const double robust = rhi - rlo;
      if (robust > 0.0 && hi[a] - lo[a] > 4.0 * robust)
      {
        lo[a] = std::max(lo[a], rlo - 0.5 * robust);
        hi[a] = std::min(hi[a], rhi + 0.5 * robust);
      }
    }
  }
  // Cell side: the smallest for which the grid has at most two cells per point.
  double extent[3], largest = 0.0;
  for (int a = 0; a < 3; ++a)
  {
    extent[a] = hi[a] - lo[a];
    largest = std::max(largest, extent[a]);
  }
  if (!(largest > 0.0))
  {
    largest = 1.0;
  }
  const double cells = 2.0 * static_cast<double>(m);
  auto count = [&](double h) {
    double product = 1.0;
    for (int a = 0; a < 3; ++a)
    {
      product *= std::max(1.0, std::ceil(extent[a] / h));
    }
    return product;
  };
  double small = largest * 1e-7, big = largest * 1.000001;
  for (int iteration = 0; iteration < 100 && big / small > 1.0001; ++iteration)
  {
    const double h = std::sqrt(small * big);
    (count(h) > cells ? small : big) = h;
  }
  g.Spacing = big;
  for (int a = 0; a < 3; ++a)
  {
    g.Origin[a] = lo[a];
    g.Dims[a] = static_cast<int>(std::max(1.0, std::ceil(extent[a] / g.Spacing)));
  }
  const vtkIdType numberOfCells = static_cast<vtkIdType>(g.Dims[0]) * g.Dims[1] * g.Dims[2];

  // Counting sort of the valid points by cell, ascending ids within a cell.
  std::vector<int64_t> cellOf(n, -1);
  g.CellStart.assign(numberOfCells + 1, 0);
  vtkSMPTools::For(0, n, [&](vtkIdType begin, vtkIdType end) {
    double x[3];
    int c[3];
    for (vtkIdType i = begin; i < end; ++i)
    {
      if (this->Valid[i])
      {
        reader.Get(i, x);
        g.CellOf(x, c);
        cellOf[i] = g.Index(c[0], c[1], c[2]);
      }
    }
  });
  for (vtkIdType i = 0; i < n; ++i)
  {
    if (cellOf[i] >= 0)
    {
      ++g.CellStart[cellOf[i] + 1];
    }
  }
  std::partial_sum(g.CellStart.begin(), g.CellStart.end(), g.CellStart.begin());
  g.SortedIds.resize(m);
  g.SortedPoints.resize(3 * static_cast<size_t>(m));
  std::vector<int32_t> next(g.CellStart.begin(), g.CellStart.end() - 1);
  g.SlotOf.assign(n, -1);
  for (vtkIdType i = 0; i < n; ++i)
  {
    if (cellOf[i] >= 0)
    {
      const int32_t slot = next[cellOf[i]]++;
      g.SlotOf[i] = slot;
      g.SortedIds[slot] = static_cast<int32_t>(i);
      reader.Get(i, g.SortedPoints.data() + 3 * static_cast<size_t>(slot));
    }
  }
  this->BuildSites();
}

void vtkPointCloudNeighborhoods::BuildSites()
{
  SearchGrid& g = *this->Grid;
  const vtkIdType numberOfCells = static_cast<vtkIdType>(g.CellStart.size()) - 1;
  const double* p = g.SortedPoints.data();
  auto byPosition = [p](int32_t a, int32_t b) {
    const double* x = p + 3 * static_cast<size_t>(a);
    const double* y = p + 3 * static_cast<size_t>(b);
    return x[0] != y[0] ? x[0] < y[0] : x[1] != y[1] ? x[1] < y[1] : x[2] != y[2] ? x[2] < y[2] : a < b;
  };
  auto same = [p](int32_t a, int32_t b) {
    const double* x = p + 3 * static_cast<size_t>(a);
    const double* y = p + 3 * static_cast<size_t>(b);
    return x[0] == y[0] && x[1] == y[1] && x[2] == y[2];
  };
  // Whether any cell holds two points at one position (most clouds: none, and the grid stays as
  // it is); cells are checked in parallel, each on its own.
  std::vector<unsigned char> cellHasCopies(numberOfCells, 0);
  vtkSMPTools::For(0, numberOfCells, [&](vtkIdType begin, vtkIdType end) {
    std::vector<int32_t> slots;
    for (vtkIdType cell = begin; cell < end; ++cell)
    {
      const int32_t first = g.CellStart[cell], last = g.CellStart[cell + 1];
      if (last - first < 2)
      {
        continue;
      }
      slots.resize(last - first);
      std::iota(slots.begin(), slots.end(), first);
      std::sort(slots.begin(), slots.end(), byPosition);
      for (size_t s = 1; s < slots.size() && !cellHasCopies[cell]; ++s)
      {
        cellHasCopies[cell] = same(slots[s - 1], slots[s]) ? 1 : 0;
      }
    }
  });
  g.HasDuplicates = std::find(cellHasCopies.begin(), cellHasCopies.end(), 1) != cellHasCopies.end();
  if (!g.HasDuplicates)
  {
    return;
  }
  // The sites of each cell in the order of their first point, their points ascending.
  g.SiteStart.assign(numberOfCells + 1, 0);
  g.SitePoints.clear();
  g.MemberStart.assign(1, 0);
  g.Members.clear();
  g.Members.reserve(g.SortedIds.size());
  std::vector<int32_t> slots;
  std::vector<std::pair<int32_t, int32_t>> groups; // first slot, position in `slots`
  for (vtkIdType cell = 0; cell < numberOfCells; ++cell)
  {
    const int32_t first = g.CellStart[cell], last = g.CellStart[cell + 1];
    slots.resize(last - first);
    std::iota(slots.begin(), slots.end(), first);
    if (cellHasCopies[cell])
    {
      std::sort(slots.begin(), slots.end(), byPosition);
    }
    groups.clear();
    for (size_t s = 0; s < slots.size(); ++s)
    {
      if (s == 0 || !same(slots[s - 1], slots[s]))
      {
        groups.emplace_back(slots[s], static_cast<int32_t>(s));
      }
    }
    std::sort(groups.begin(), groups.end());
    for (const auto& group : groups)
    {
      const double* x = p + 3 * static_cast<size_t>(group.first);
      g.SitePoints.insert(g.SitePoints.end(), x, x + 3);
      for (size_t s = group.second; s < slots.size() && same(slots[s], group.first); ++s)
      {
        g.Members.push_back(slots[s]);
      }
      g.MemberStart.push_back(static_cast<int32_t>(g.Members.size()));
    }
    g.SiteStart[cell + 1] = g.SiteStart[cell] + static_cast<int32_t>(groups.size());
  }
}

std::vector<vtkIdType> vtkPointCloudNeighborhoods::GetValidIds() const
{
  std::vector<vtkIdType> ids;
  ids.reserve(this->NumberOfValidPoints);
  for (vtkIdType i = 0; i < this->NumberOfPoints; ++i)
  {
    if (this->Valid[i])
    {
      ids.push_back(i);
    }
  }
  return ids;
}

bool vtkPointCloudNeighborhoods::ReorderSpatially(std::vector<int32_t>& originalIds)
{
  if (!this->Searchable || !this->Grid || this->MeanSpacing >= 0.0 ||
    !this->NearestKnown.empty() || !this->NearestDistances.empty())
  {
    return false;
  }
  SearchGrid& g = *this->Grid;
  const vtkIdType n = this->NumberOfPoints;
  const vtkIdType m = this->NumberOfValidPoints;
  // New id i < m is slot i of the grid; the invalid points follow, with their own coordinates.
  originalIds.resize(n);
  std::copy(g.SortedIds.begin(), g.SortedIds.end(), originalIds.begin());
  g.SortedPoints.resize(3 * static_cast<size_t>(n));
  vtkIdType next = m;
  for (vtkIdType i = 0; i < n && next < n; ++i)
  {
    if (!this->Valid[i])
    {
      originalIds[next] = static_cast<int32_t>(i);
      this->Points->GetPoint(i, g.SortedPoints.data() + 3 * static_cast<size_t>(next));
      ++next;
    }
  }
  std::iota(g.SortedIds.begin(), g.SortedIds.end(), 0);
  std::iota(g.SlotOf.begin(), g.SlotOf.begin() + m, 0);
  std::fill(g.SlotOf.begin() + m, g.SlotOf.end(), -1);
  std::fill(this->Valid.begin(), this->Valid.begin() + m, 1);
  std::fill(this->Valid.begin() + m, this->Valid.end(), 0);
  this->FirstInvalidPoint = m < n ? m : -1;

  // The renumbered cloud reads the grid's coordinates in place (the array does not own them).
  vtkNew<vtkDoubleArray> coordinates;
  coordinates->SetNumberOfComponents(3);
  coordinates->SetArray(g.SortedPoints.data(), 3 * n, 1);
  this->Points = vtkSmartPointer<vtkPoints>::New();
  this->Points->SetData(coordinates);
  return true;
}

double vtkPointCloudNeighborhoods::ComputeMeanSpacing()
{
  if (this->MeanSpacing >= 0.0)
  {
    return this->MeanSpacing;
  }
  if (!this->Searchable)
  {
    return 0.0;
  }
  // The points whose nearest distance FindNearestDistances() has not found yet.
  std::vector<vtkIdType> ids;
  ids.reserve(this->NumberOfValidPoints);
  for (vtkIdType i = 0; i < this->NumberOfPoints; ++i)
  {
    if (this->Valid[i] && (this->NearestKnown.empty() || !this->NearestKnown[i]))
    {
      ids.push_back(i);
    }
  }
  std::vector<int32_t> table;
  std::vector<double> nearest;
  this->FindNearestNeighbors(1, ids, table, &nearest);
  if (this->NearestKnown.empty())
  {
    this->NearestDistances.assign(this->NumberOfPoints, 0.0);
  }
  for (size_t r = 0; r < ids.size(); ++r)
  {
    this->NearestDistances[ids[r]] = nearest[r];
  }
  return this->FinishMeanSpacing();
}

void vtkPointCloudNeighborhoods::FindNearestDistances(
  const std::vector<vtkIdType>& ids, std::vector<double>& distances)
{
  std::vector<int32_t> table;
  this->FindNearestNeighbors(1, ids, table, &distances);
  if (!this->Searchable || this->MeanSpacing >= 0.0)
  {
    return;
  }
  if (this->NearestKnown.empty())
  {
    this->NearestDistances.assign(this->NumberOfPoints, 0.0);
    this->NearestKnown.assign(this->NumberOfPoints, 0);
  }
  for (size_t r = 0; r < ids.size(); ++r)
  {
    this->NearestDistances[ids[r]] = distances[r];
    this->NearestKnown[ids[r]] = 1;
  }
}

double vtkPointCloudNeighborhoods::ComputeMeanSpacing(
  const std::vector<vtkIdType>& ids, const std::vector<int32_t>& table, int k)
{
  if (this->MeanSpacing >= 0.0)
  {
    return this->MeanSpacing;
  }
  if (!this->Searchable)
  {
    return 0.0;
  }
  this->NearestDistances.assign(this->NumberOfPoints, 0.0);
  vtkSMPTools::For(0, static_cast<vtkIdType>(ids.size()), [&](vtkIdType begin, vtkIdType end) {
    double x[3], y[3];
    for (vtkIdType r = begin; r < end; ++r)
    {
      const int32_t* row = table.data() + r * k;
      if (k > 0 && row[0] >= 0)
      {
        this->Points->GetPoint(ids[r], x);
        this->Points->GetPoint(row[0], y);
        this->NearestDistances[ids[r]] = std::sqrt(vtkMath::Distance2BetweenPoints(x, y));
      }
    }
  });
  return this->FinishMeanSpacing();
}

double vtkPointCloudNeighborhoods::FinishMeanSpacing()
{
  std::vector<double>& nearest = this->NearestDistances;
  // Points whose nearest point coincides with them: look further, for the nearest distinct point.
  std::vector<vtkIdType> stacked;
  for (vtkIdType i = 0; i < this->NumberOfPoints; ++i)
  {
    if (this->Valid[i] && nearest[i] == 0.0 && this->NumberOfValidPoints > 1)
    {
      stacked.push_back(i);
    }
  }
  this->NumberOfDuplicatePoints = static_cast<vtkIdType>(stacked.size());
  if (this->Grid && !stacked.empty())
  {
    // One query each for the nearest point at a nonzero distance: linear however many copies
    // a stack holds (the search below, for the locator, grows with them).
    std::vector<int32_t> table(stacked.size());
    std::vector<double> distinct(stacked.size());
    this->FindNearestNeighborsOnGrid(1, stacked, table, &distinct, nullptr, 0.0, 1.0, true);
    for (size_t r = 0; r < stacked.size(); ++r)
    {
      nearest[stacked[r]] = distinct[r];
    }
    stacked.clear();
  }
  for (int k = 8; !stacked.empty(); k *= 4)
  {
    const int kk = static_cast<int>(std::min<vtkIdType>(k, this->NumberOfValidPoints - 1));
    std::vector<int32_t> rows;
    this->FindNearestNeighbors(kk, stacked, rows);
    std::vector<vtkIdType> still;
    double x[3], y[3];
    for (size_t r = 0; r < stacked.size(); ++r)
    {
      this->Points->GetPoint(stacked[r], x);
      for (int j = 0; j < kk && rows[r * kk + j] >= 0; ++j)
      {
        this->Points->GetPoint(rows[r * kk + j], y);
        const double d = std::sqrt(vtkMath::Distance2BetweenPoints(x, y));
        if (d > 0.0)
        {
          nearest[stacked[r]] = d;
          break;
        }
      }
      if (nearest[stacked[r]] == 0.0 && kk < this->NumberOfValidPoints - 1)
      {
        still.push_back(stacked[r]);
      }
    }
    if (kk >= this->NumberOfValidPoints - 1)
    {
      break; // the rest coincide with every other point
    }
    stacked.swap(still);
  }

  // Mean of the nearest distances, ignoring isolated outliers (over 10 times the median), summed
  // in point order so that the value does not depend on the thread count.
  std::vector<double> positive;
  positive.reserve(this->NumberOfPoints);
  for (vtkIdType i = 0; i < this->NumberOfPoints; ++i)
  {
    if (this->Valid[i] && nearest[i] > 0.0)
    {
      positive.push_back(nearest[i]);
    }
  }
  this->MeanSpacing = featurepoints::MeanWithoutOutliers(positive, 10.0);
  return this->MeanSpacing;
}

bool vtkPointCloudNeighborhoods::FindNearestNeighbors(int k, const std::vector<vtkIdType>& ids,
  std::vector<int32_t>& table, std::vector<double>* nearestDistances, vtkAlgorithm* progressAlg,
  double progressStart, double progressEnd)
{
  const vtkIdType rows = static_cast<vtkIdType>(ids.size());
  table.resize(static_cast<size_t>(rows) * std::max(k, 0));
  if (nearestDistances)
  {
    nearestDistances->resize(rows);
  }
  if (k <= 0 || rows == 0 || !this->Searchable)
  {
    std::fill(table.begin(), table.end(), -1);
    return true;
  }
  if (this->SearchMethod == GRID)
  {
    return this->FindNearestNeighborsOnGrid(
      k, ids, table, nearestDistances, progressAlg, progressStart, progressEnd);
  }

  NearestNeighborsWorker worker{ this->Points, this->Locator,
    this->LocatorToPoint.empty() ? nullptr : this->LocatorToPoint.data(), this->Valid.data(),
    ids.data(), k, table.data(), nearestDistances ? nearestDistances->data() : nullptr, {} };

  // Batches let the main thread report progress and honour an abort request between them.
  const vtkIdType batch = std::max<vtkIdType>(20000, rows / 50);
  for (vtkIdType begin = 0; begin < rows; begin += batch)
  {
    const vtkIdType end = std::min(rows, begin + batch);
    vtkSMPTools::For(begin, end, worker);
    if (progressAlg)
    {
      progressAlg->UpdateProgress(progressStart +
        (progressEnd - progressStart) * static_cast<double>(end) / static_cast<double>(rows));
      if (progressAlg->GetAbortExecute())
      {
        return false;
      }
    }
  }
  return true;
}

bool vtkPointCloudNeighborhoods::FindNearestNeighborsOnGrid(int k,
  const std::vector<vtkIdType>& ids, std::vector<int32_t>& table,
  std::vector<double>* nearestDistances, vtkAlgorithm* progressAlg, double progressStart,
  double progressEnd, bool distinct)
{
  const SearchGrid& g = *this->Grid;
  const vtkIdType rows = static_cast<vtkIdType>(ids.size());
  // The queries in grid order (by their slot), so that neighbouring queries read the same cells
  // and their coordinates in sequence. Rows of invalid points are filled here.
  const int32_t k32 = k;
  std::vector<vtkIdType> rowOfSlot(g.SortedIds.size(), -1);
  std::vector<std::pair<int32_t, vtkIdType>> repeated; // an id listed twice
  for (vtkIdType r = 0; r < rows; ++r)
  {
    const int32_t slot = g.SlotOf[ids[r]];
    if (slot < 0)
    {
      std::fill_n(table.data() + r * k32, k32, -1);
      if (nearestDistances)
      {
        (*nearestDistances)[r] = 0.0;
      }
    }
    else if (rowOfSlot[slot] >= 0)
    {
      repeated.emplace_back(slot, r);
    }
    else
    {
      rowOfSlot[slot] = r;
    }
  }
  std::vector<int32_t> slots;
  std::vector<vtkIdType> order;
  slots.reserve(rows);
  order.reserve(rows);
  for (size_t slot = 0; slot < rowOfSlot.size(); ++slot)
  {
    if (rowOfSlot[slot] >= 0)
    {
      slots.push_back(static_cast<int32_t>(slot));
      order.push_back(rowOfSlot[slot]);
    }
  }
  for (const auto& extra : repeated)
  {
    slots.push_back(extra.first);
    order.push_back(extra.second);
  }
  std::vector<vtkIdType>().swap(rowOfSlot);
  const vtkIdType queries = static_cast<vtkIdType>(slots.size());

  GridNeighborsWorker worker{ &g, slots.data(), order.data(), k, table.data(),
    nearestDistances ? nearestDistances->data() : nullptr, distinct && k == 1, {} };
  const vtkIdType batch = std::max<vtkIdType>(20000, queries / 50);
  for (vtkIdType begin = 0; begin < queries; begin += batch)
  {
    const vtkIdType end = std::min(queries, begin + batch);
    vtkSMPTools::For(begin, end, worker);
    if (progressAlg)
    {
      progressAlg->UpdateProgress(progressStart +
        (progressEnd - progressStart) * static_cast<double>(end) / static_cast<double>(queries));
      if (progressAlg->GetAbortExecute())
      {
        return false;
      }
    }
  }
  return true;
}

vtkSmartPointer<vtkCellArray> vtkPointCloudNeighborhoods::MakeVertexCells(vtkIdType n)
{
  return featurepoints::MakeVertexCells(n);
}

void vtkPointCloudNeighborhoods::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfPoints: " << this->NumberOfPoints << "\n";
  os << indent << "NumberOfValidPoints: " << this->NumberOfValidPoints << "\n";
  os << indent << "FirstInvalidPoint: " << this->FirstInvalidPoint << "\n";
  os << indent << "NumberOfDuplicatePoints: " << this->NumberOfDuplicatePoints << "\n";
  os << indent << "MeanSpacing: " << this->MeanSpacing << "\n";
}

// The wrapped counterparts of the methods on std::vector tables and bare pointers (see the header):
// copies between VTK arrays and the C++ ones.
namespace
{
std::vector<vtkIdType> IdsOf(vtkIdList* list)
{
  std::vector<vtkIdType> ids;
  if (list)
  {
    ids.assign(list->GetPointer(0), list->GetPointer(0) + list->GetNumberOfIds());
  }
  return ids;
}
} // namespace

bool vtkPointCloudNeighborhoods::MakeVertexCells(vtkIdType n, vtkCellArray* cells)
{
  if (!cells || n < 0)
  {
    return false;
  }
  vtkSmartPointer<vtkCellArray> verts = MakeVertexCells(n);
  if (!verts)
  {
    cells->Initialize();
    return false;
  }
  cells->ShallowCopy(verts);
  if (cells->GetNumberOfCells() != n)
  {
    cells->Initialize();
    return false;
  }
  return true;
}

void vtkPointCloudNeighborhoods::GetValidMask(vtkUnsignedCharArray* mask) const
{
  if (!mask)
  {
    return;
  }
  mask->SetNumberOfComponents(1);
  mask->SetNumberOfValues(static_cast<vtkIdType>(this->Valid.size()));
  std::copy(this->Valid.begin(), this->Valid.end(), mask->GetPointer(0));
}

bool vtkPointCloudNeighborhoods::ReorderSpatially(vtkIntArray* originalIds)
{
  std::vector<int32_t> ids;
  if (!originalIds || !this->ReorderSpatially(ids))
  {
    return false;
  }
  originalIds->SetNumberOfComponents(1);
  originalIds->SetNumberOfValues(static_cast<vtkIdType>(ids.size()));
  std::copy(ids.begin(), ids.end(), originalIds->GetPointer(0));
  return true;
}

double vtkPointCloudNeighborhoods::ComputeMeanSpacing(vtkIdList* ids, vtkIntArray* table)
{
  const std::vector<vtkIdType> rows = IdsOf(ids);
  const int k = table ? table->GetNumberOfComponents() : 0;
  if (k < 1 || table->GetNumberOfTuples() != static_cast<vtkIdType>(rows.size()))
  {
    vtkErrorMacro(<< "ComputeMeanSpacing: the table must have one tuple per id ("
                  << rows.size() << ")");
    return 0.0;
  }
  const int32_t* first = table->GetPointer(0);
  const std::vector<int32_t> entries(first, first + rows.size() * static_cast<size_t>(k));
  return this->ComputeMeanSpacing(rows, entries, k);
}

bool vtkPointCloudNeighborhoods::FindNearestNeighbors(
  int k, vtkIdList* ids, vtkIntArray* table, vtkDoubleArray* nearestDistances)
{
  if (!table || k < 1)
  {
    return false;
  }
  const std::vector<vtkIdType> rows = IdsOf(ids);
  std::vector<int32_t> entries;
  std::vector<double> nearest;
  if (!this->FindNearestNeighbors(k, rows, entries, nearestDistances ? &nearest : nullptr))
  {
    return false;
  }
  table->SetNumberOfComponents(k);
  table->SetNumberOfTuples(static_cast<vtkIdType>(rows.size()));
  std::copy(entries.begin(), entries.end(), table->GetPointer(0));
  if (nearestDistances)
  {
    nearestDistances->SetNumberOfComponents(1);
    nearestDistances->SetNumberOfValues(static_cast<vtkIdType>(nearest.size()));
    std::copy(nearest.begin(), nearest.end(), nearestDistances->GetPointer(0));
  }
  return true;
}
