#include "vtkPointCloudGridLocator.h"

#include "vtkAlgorithm.h"
#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkFeaturePointsLocalPCA.h"
#include "vtkFeaturePointsStatistics.h"
#include "vtkFeaturePointsTables.h"
#include "vtkIdList.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"

#include <nanoflann.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

vtkStandardNewMacro(vtkPointCloudGridLocator);

namespace
{
// AUTO's limit on CellOccupancy, where the grid's 15- and 150-nearest queries of every point
// together cost what the tree's do. Measured on two cube surfaces of 25,000 points each, further
// and further apart (the grid's time grows with the occupancy, the tree's does not): at 2,600
// the grid 0.29 + 0.38 s, the tree 0.07 + 0.61 s; at 25,000 the grid 2.26 + 1.44 s, the tree
// 0.08 + 0.64 s; an even cloud has 5 to 60 (the grid then 0.04 + 0.2 s, the tree 0.06 + 0.5 s).
constexpr double TreeOccupancy = 3000.0;

// The position a point's site is keyed by: its coordinates rounded down to multiples of 2^-540
// (about 2.8e-163). Two points with the same key differ by less than that in every coordinate,
// so their squared distance underflows to exactly 0: to every query they are as coincident as
// copies, and grouped as copies are (without it, points packed closer than that, as a cloud whose
// spacings shrink to 1e-300, tie at distance 0 with each other and every query reads them all).
// From 2^-488 on, every double already is such a multiple (its last bit is worth 2^-540 or
// more): the key is the coordinate itself.
// The absolute part of the tree's widened bound (see TreeNearest).
constexpr double TreeSlack = 64 * std::numeric_limits<double>::denorm_min();

double SiteKey(double x)
{
  constexpr double quantum = 0x1p-540;
  return std::fabs(x) < 0x1p-488 ? std::floor(x / quantum) * quantum : x;
}
}

struct vtkPointCloudGridLocator::SearchGrid
{
  double Origin[3] = { 0, 0, 0 };
  double Spacing = 1.0; // side of a cell
  int Dims[3] = { 1, 1, 1 };
  std::vector<int32_t> CellStart;   // first slot of each cell, then the number of slots
  std::vector<int32_t> SortedIds;   // point id of each slot, cell by cell, ascending in a cell
  // Coordinates of each slot: an array that ReorderSpatially() hands out as the renumbered
  // points (shared, so that they outlive the grid), and a pointer to its values.
  vtkSmartPointer<vtkDoubleArray> Coordinates;
  double* SortedPoints = nullptr;
  std::vector<int32_t> SlotOf;      // slot of each point, -1 for invalid points

  // Coincident points (BuildSites(), only when some points coincide): the distinct positions of
  // each cell ("sites"), each with its points, so that a query reads a stack of copies once
  // rather than once per copy.
  bool HasDuplicates = false;
  std::vector<int32_t> SiteStart;   // first site of each cell, then the number of sites
  std::vector<double> SitePoints;   // coordinates of each site
  std::vector<int32_t> MemberStart; // first member of each site, then the number of members
  std::vector<int32_t> Members;     // slots of the points of each site, ascending

  // Where the cells are too uneven for the grid (see BuildTree()): a k-d tree over the slots,
  // which then answers every query (nullptr: the grid does).
  struct SlotTree;
  std::shared_ptr<SlotTree> Tree;

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
  double AxisGap(int a, int c, double xa) const { return this->AxisGap(a, c, xa, xa); }
  // Distance from the interval [lo, hi] to the slab of cells c along axis a.
  double AxisGap(int a, int c, double lo, double hi) const
  {
    const double from = this->Origin[a] + c * this->Spacing;
    return c > 0 && hi < from
      ? from - hi
      : (c < this->Dims[a] - 1 && lo > from + this->Spacing ? lo - from - this->Spacing : 0.0);
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

struct vtkPointCloudGridLocator::SearchGrid::SlotTree
{
  // The slots' coordinates as nanoflann reads them: through the grid, whose coordinate array
  // ReorderSpatially() may move. Where some points coincide, the tree holds the sites instead
  // (one entry per position), so that a stack of copies is offered once, as the grid reads it.
  struct Slots
  {
    const SearchGrid* Grid;
    size_t kdtree_get_point_count() const
    {
      return this->Grid->HasDuplicates ? this->Grid->SitePoints.size() / 3
                                       : this->Grid->SortedIds.size();
    }
    double kdtree_get_pt(uint32_t entry, size_t a) const
    {
      return this->Grid->HasDuplicates ? this->Grid->SitePoints[3 * static_cast<size_t>(entry) + a]
                                       : this->Grid->SortedPoints[3 * static_cast<size_t>(entry) + a];
    }
    template <class Box>
    bool kdtree_get_bbox(Box&) const
    {
      return false;
    }
  };
  using Index =
    nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, Slots>, Slots, 3, uint32_t>;
  Slots Cloud;
  Index Tree;
  explicit SlotTree(const SearchGrid* grid)
    : Cloud{ grid }
    , Tree(3, this->Cloud, nanoflann::KDTreeSingleIndexAdaptorParams(16))
  {
  }
};

namespace
{

// Exact nearest points on the grid: rings of cells around the query's cell, nearest first, until
// the k-th best distance is below the distance to the unsearched cells. Candidates are ordered by
// (distance, id), so ties are broken the same way whatever the scanning order, and each answer
// depends on its query only.
struct GridQuery
{
  const vtkPointCloudGridLocator::SearchGrid* Grid;
  int K;

  struct Candidate
  {
    double D2;
    int32_t Id;
    // Left unset: the large-k scans size their buffer, then write every entry.
    Candidate() {} // NOLINT(modernize-use-equals-default)
    Candidate(double d2, int32_t id)
      : D2(d2)
      , Id(id)
    {
    }
    bool operator<(const Candidate& o) const { return D2 < o.D2 || (D2 == o.D2 && Id < o.Id); }
  };
  struct BucketScratch
  {
    std::vector<Candidate> Sorted;
    std::vector<int32_t> Bucket;
    std::vector<int32_t> Start;
  };

  // Sorts the candidates by (distance, id) and keeps the first `keep`: a bucket sort on the
  // squared distance (about one candidate per bucket, buckets in distance order, each bucket then
  // sorted exactly), which costs a few passes where nth_element and sort compare and mispredict
  // O(m log m) times. Only the buckets up to the one that holds the keep-th candidate are filled
  // and sorted; the rest share one overflow bucket that is never read. `largest`: an upper bound
  // of the squared distances when the caller knows one (the bound it kept them within), else
  // negative (then a pass finds the largest).
  static void SortNearest(
    std::vector<Candidate>& candidates, size_t keep, BucketScratch& scratch, double largest = -1.0)
  {
    const size_t m = candidates.size();
    if (m <= 16 || keep == 0)
    {
      std::sort(candidates.begin(), candidates.end());
      candidates.resize(std::min(m, keep));
      return;
    }
    if (!(largest >= 0.0) || !(largest < VTK_DOUBLE_MAX))
    {
      largest = 0.0;
      for (const Candidate& c : candidates)
      {
        largest = std::max(largest, c.D2);
      }
    }
    const int32_t buckets = static_cast<int32_t>(m);
    // Monotone in D2: a larger distance never lands in an earlier bucket.
    const double scale = largest > 0.0 ? (buckets - 0.5) / largest : 0.0;
    if (!std::isfinite(largest) || !std::isfinite(scale))
    {
      // Squared distances that overflow (coordinates beyond 1e154), or so small that the scale
      // does (subnormal, 0 x inf would be NaN), have no bucket: plain sort.
      std::sort(candidates.begin(), candidates.end());
      candidates.resize(std::min(m, keep));
      return;
    }
    std::vector<int32_t>& bucket = scratch.Bucket;
    std::vector<int32_t>& start = scratch.Start;
    bucket.resize(m);
    start.assign(static_cast<size_t>(buckets) + 2, 0);
    for (size_t i = 0; i < m; ++i)
    {
      const int32_t b = std::min(buckets - 1, static_cast<int32_t>(candidates[i].D2 * scale));
      bucket[i] = b;
      ++start[b + 1];
    }
    // Start of each bucket up to `last`, the one that holds the keep-th candidate; bucket
    // last + 1 takes every later candidate.
    const size_t kept = std::min(m, keep);
    int32_t last = buckets - 1;
    for (int32_t b = 0; b < buckets; ++b)
    {
      start[b + 1] += start[b];
      if (static_cast<size_t>(start[b + 1]) >= kept)
      {
        last = b;
        break;
      }
    }
    const int32_t overflow = last + 1;
    std::vector<Candidate>& sorted = scratch.Sorted;
    sorted.resize(m);
    // Scatter, start[b] moving on to the end of bucket b (the start of bucket b + 1).
    for (size_t i = 0; i < m; ++i)
    {
      sorted[start[std::min(bucket[i], overflow)]++] = candidates[i];
    }
    for (int32_t b = 0, from = 0; b <= last; from = start[b], ++b)
    {
      const int32_t to = start[b];
      if (to - from > 1)
      {
        InsertionSort(sorted.data() + from, sorted.data() + to);
      }
    }
    std::copy(sorted.begin(), sorted.begin() + kept, candidates.begin());
    candidates.resize(kept);
  }

  // Sorts [first, last) by (distance, id): a bucket holds a few candidates, where std::sort's
  // set-up costs more than the sort.
  static void InsertionSort(Candidate* first, Candidate* last)
  {
    if (last - first > 16)
    {
      std::sort(first, last);
      return;
    }
    for (Candidate* i = first + 1; i < last; ++i)
    {
      const Candidate c = *i;
      Candidate* j = i;
      for (; j > first && c < *(j - 1); --j)
      {
        *j = *(j - 1);
      }
      *j = c;
    }
  }

  // The tree's queries (Grid->Tree set), with the grid's answers: nanoflann offers the slots
  // and these sets keep the best by (distance, id), the distance computed as the grid computes
  // it. The bound they give nanoflann is widened by a relative 1e-9 so that points at exactly
  // the k-th distance are offered too (nanoflann takes only those strictly nearer), and by 64
  // of the smallest subnormals where the relative part underflows (a k-th distance of 0 or
  // subnormal). Not by the smallest normal double: with a k-th distance of 0, that let in every
  // node within 1.5e-154 of the query, a whole cloud's worth where its spacings shrink to 1e-300.
  struct TreeNearest
  {
    const vtkPointCloudGridLocator::SearchGrid& G;
    const double* X;
    int32_t Skip;  // the query's own id (-1: none)
    bool Distinct; // copies of x skipped
    size_t K;
    std::vector<Candidate>& Heap; // a max-heap of the K best so far

    bool full() const { return this->Heap.size() == this->K; }
    double worstDist() const
    {
      if (!this->full())
      {
        return std::numeric_limits<double>::infinity();
      }
      const double w = this->Heap.front().D2;
      return w + w * 1e-9 + TreeSlack;
    }
    bool addPoint(double, uint32_t entry)
    {
      if (!this->G.HasDuplicates)
      {
        this->Offer(this->G.SortedPoints + 3 * static_cast<size_t>(entry), this->G.SortedIds[entry]);
        return true;
      }
      // A site: its points share their distance and come in ascending ids, so once one is not
      // kept none of the next ones is (as the grid's scan of a site).
      const double* y = this->G.SitePoints.data() + 3 * static_cast<size_t>(entry);
      for (int32_t m = this->G.MemberStart[entry]; m < this->G.MemberStart[entry + 1]; ++m)
      {
        if (!this->Offer(y, this->G.SortedIds[this->G.Members[m]]))
        {
          break;
        }
      }
      return true;
    }
    // Offers point `id` at y; false when neither it nor a point of larger id at y can be kept.
    bool Offer(const double* y, int32_t id)
    {
      const double dx = this->X[0] - y[0], dy = this->X[1] - y[1], dz = this->X[2] - y[2];
      const Candidate c{ dx * dx + dy * dy + dz * dz, id };
      if (c.Id == this->Skip)
      {
        return true;
      }
      if (this->Distinct && c.D2 == 0.0)
      {
        return false;
      }
      if (this->Heap.size() < this->K)
      {
        this->Heap.push_back(c);
        std::push_heap(this->Heap.begin(), this->Heap.end());
      }
      else if (c < this->Heap.front())
      {
        std::pop_heap(this->Heap.begin(), this->Heap.end());
        this->Heap.back() = c;
        std::push_heap(this->Heap.begin(), this->Heap.end());
      }
      else
      {
        return false;
      }
      return true;
    }
  };
  struct TreeWithin
  {
    const vtkPointCloudGridLocator::SearchGrid& G;
    const double* X;
    double R2;
    std::vector<Candidate>& Found;

    bool full() const { return true; }
    double worstDist() const { return this->R2 + this->R2 * 1e-9 + TreeSlack; }
    bool addPoint(double, uint32_t entry)
    {
      const bool site = this->G.HasDuplicates;
      const double* y = (site ? this->G.SitePoints.data() : this->G.SortedPoints) +
        3 * static_cast<size_t>(entry);
      const double dx = this->X[0] - y[0], dy = this->X[1] - y[1], dz = this->X[2] - y[2];
      const double d2 = dx * dx + dy * dy + dz * dz;
      if (d2 > this->R2)
      {
        return true;
      }
      if (!site)
      {
        this->Found.push_back(Candidate{ d2, this->G.SortedIds[entry] });
        return true;
      }
      for (int32_t m = this->G.MemberStart[entry]; m < this->G.MemberStart[entry + 1]; ++m)
      {
        this->Found.push_back(Candidate{ d2, this->G.SortedIds[this->G.Members[m]] });
      }
      return true;
    }
  };
  // The K nearest of x (other than `skip`) from the tree, nearest first.
  void TreeSearch(const double* x, int32_t skip, bool distinct, size_t k,
    std::vector<Candidate>& candidates) const
  {
    candidates.clear();
    TreeNearest set{ *this->Grid, x, skip, distinct, k, candidates };
    this->Grid->Tree->Tree.findNeighbors(set, x, nanoflann::SearchParams());
    std::sort_heap(candidates.begin(), candidates.end());
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
    if (g.Tree)
    {
      thread_local std::vector<Candidate> found;
      this->TreeSearch(x, id, Distinct, 1, found);
      return found.empty() ? best : found.front();
    }
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
      const double* y = g.SortedPoints + 3 * static_cast<size_t>(g.CellStart[cell]);
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

  // Large k: the points of slots [first, last) other than point `id` within `bound` of x, as
  // candidates from out[kept] on (room for last - first of them); returns the new count. Every
  // point is written, and kept (the count moves on) when it is within the bound: no branch on the
  // bound, which a cell's points pass or fail unpredictably.
  size_t KeepWithin(const double* x, int32_t id, double bound, int32_t first, int32_t last,
    Candidate* out, size_t kept) const
  {
    const auto& g = *this->Grid;
    const double* y = g.SortedPoints + 3 * static_cast<size_t>(first);
    for (int32_t s = first; s < last; ++s, y += 3)
    {
      const int32_t other = g.SortedIds[s];
      const double dx = x[0] - y[0], dy = x[1] - y[1], dz = x[2] - y[2];
      const double d2 = dx * dx + dy * dy + dz * dz;
      out[kept] = Candidate{ d2, other };
      kept += static_cast<size_t>((d2 <= bound) & (other != id));
    }
    return kept;
  }

  // The K nearest points of x other than point `id` (-1: none skipped) into `row`, -1 past the
  // last one found; returns the distance to the nearest (0 when none). `hint`: see operator().
  double NearestK(const double* x, int32_t id, int32_t* row, double& hint,
    std::vector<Candidate>& candidates, BucketScratch& bucketScratch) const
  {
    const auto& g = *this->Grid;
    int n = 0;
    double nearest = 0.0;
    if (g.Tree)
    {
      this->TreeSearch(x, id, false, static_cast<size_t>(this->K), candidates);
      for (const Candidate& cand : candidates)
      {
        row[n++] = cand.Id;
      }
      nearest = n > 0 ? std::sqrt(candidates.front().D2) : 0.0;
    }
    else
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
          const int32_t first = g.CellStart[cell], last = g.CellStart[cell + 1];
          if (!useHeap)
          {
            const size_t base = candidates.size();
            candidates.resize(base + static_cast<size_t>(last - first));
            candidates.resize(
              this->KeepWithin(x, id, bound, first, last, candidates.data(), base));
            return;
          }
          for (int32_t s = first; s < last; ++s)
          {
            const int32_t other = g.SortedIds[s];
            if (other == id)
            {
              continue;
            }
            const double* y = g.SortedPoints + 3 * static_cast<size_t>(s);
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
          SortNearest(candidates, static_cast<size_t>(this->K), bucketScratch, bound);
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
    return nearest;
  }

  // The slots of the cells that may hold a point within sqrt(bound) of some point of the box
  // [lo, hi]: per row of cells, the run of cells whose box lies within that distance of the box
  // (the distance to a row's cells falls then rises along it: the run is contiguous). Border
  // cells are open on their outer side, as in BoxDistance2().
  void SlotsNear(const double lo[3], const double hi[3], double bound,
    std::vector<std::pair<int32_t, int32_t>>& ranges) const
  {
    const auto& g = *this->Grid;
    ranges.clear();
    // A little beyond the bound: a rounding in the boxes' or the cells' coordinates (a point
    // that the cell index puts in a cell whose box, as computed, misses it by an ulp) must not
    // leave out a point within it.
    const double reach = std::sqrt(bound) * (1.0 + 1e-9) + 1e-9 * g.Spacing;
    bound = reach * reach;
    const double from[3] = { lo[0] - reach, lo[1] - reach, lo[2] - reach };
    const double to[3] = { hi[0] + reach, hi[1] + reach, hi[2] + reach };
    int first[3], last[3];
    g.CellOf(from, first);
    g.CellOf(to, last);
    // Squared gap along axis a between the box and the cells' slab c.
    auto gap2 = [&](int a, int c) {
      const double d = g.AxisGap(a, c, lo[a], hi[a]);
      return d * d;
    };
    for (int k = first[2]; k <= last[2]; ++k)
    {
      const double gz = gap2(2, k);
      if (gz > bound)
      {
        continue;
      }
      for (int j = first[1]; j <= last[1]; ++j)
      {
        const double left = bound - gz - gap2(1, j);
        if (left < 0.0)
        {
          continue;
        }
        int i0 = first[0], i1 = last[0];
        while (i0 <= i1 && gap2(0, i0) > left)
        {
          ++i0;
        }
        while (i1 >= i0 && gap2(0, i1) > left)
        {
          --i1;
        }
        if (i0 <= i1)
        {
          const int32_t begin = g.CellStart[g.Index(i0, j, k)];
          const int32_t end = g.CellStart[g.Index(i1, j, k) + 1];
          if (begin < end)
          {
            ranges.emplace_back(begin, end);
          }
        }
      }
    }
  }

  // The K nearest of x (other than point id) among the slots of `ranges`, when at least K of
  // them lie within sqrt(bound) and every point within that distance of x lies in the ranges:
  // then no other point can be nearer than the K-th, and the answer is NearestK()'s (the same
  // squared distances, the same order by (distance, id)). Returns false, writing nothing,
  // when fewer than K lie within it.
  bool NearestKInRanges(const double* x, int32_t id, double bound,
    const std::vector<std::pair<int32_t, int32_t>>& ranges, int32_t* row, double& nearest,
    double& kth, std::vector<Candidate>& candidates, BucketScratch& bucketScratch) const
  {
    const auto& g = *this->Grid;
    size_t total = 0;
    for (const auto& range : ranges)
    {
      total += static_cast<size_t>(range.second - range.first);
    }
    if (candidates.size() < total)
    {
      candidates.resize(total);
    }
    size_t kept = 0;
    for (const auto& range : ranges)
    {
      kept = this->KeepWithin(x, id, bound, range.first, range.second, candidates.data(), kept);
    }
    if (kept < static_cast<size_t>(this->K))
    {
      return false;
    }
    candidates.resize(kept);
    SortNearest(candidates, static_cast<size_t>(this->K), bucketScratch, bound);
    for (int n = 0; n < this->K; ++n)
    {
      row[n] = candidates[n].Id;
    }
    nearest = std::sqrt(candidates.front().D2);
    kth = candidates[this->K - 1].D2;
    return true;
  }
};

// The batched query: one row per listed point of the grid, the queries taken in grid order (by
// slot), so that consecutive queries read the same cells and their coordinates in sequence.
struct GridNeighborsWorker
{
  GridQuery Query;
  const int32_t* Slots;  // the queries' slots, in grid order
  const vtkIdType* Rows; // the table row of each of them
  int32_t* Table;
  double* Nearest;
  bool Distinct; // K = 1 only: the nearest point at a nonzero distance
  vtkSMPThreadLocal<std::vector<GridQuery::Candidate>> Candidates;
  vtkSMPThreadLocal<GridQuery::BucketScratch> Buckets;
  vtkSMPThreadLocal<std::vector<std::pair<int32_t, int32_t>>> Ranges;

  void Initialize() {}

  void operator()(vtkIdType begin, vtkIdType end)
  {
    if (this->Query.K == 1)
    {
      const auto& g = *this->Query.Grid;
      for (vtkIdType o = begin; o < end; ++o)
      {
        const int32_t slot = this->Slots[o];
        const vtkIdType r = this->Rows[o];
        const double* x = g.SortedPoints + 3 * static_cast<size_t>(slot);
        const GridQuery::Candidate best = this->Distinct
          ? this->Query.NearestOne<true>(x, g.SortedIds[slot])
          : this->Query.NearestOne<false>(x, g.SortedIds[slot]);
        this->Table[r] = best.Id;
        if (this->Nearest)
        {
          this->Nearest[r] = best.Id >= 0 ? std::sqrt(best.D2) : 0.0;
        }
      }
      return;
    }
    std::vector<GridQuery::Candidate>& candidates = this->Candidates.Local();
    GridQuery::BucketScratch& bucketScratch = this->Buckets.Local();
    const auto& g = *this->Query.Grid;
    // Large k: the k-th squared distance of the previous query, a guess for this one (queries come
    // in grid order, so neighbouring queries follow each other). The result never depends on it.
    double hint = -1.0;
    if (this->Query.K > 8 && !g.Tree && !g.HasDuplicates)
    {
      this->ByCell(begin, end, hint, candidates, bucketScratch);
      return;
    }
    for (vtkIdType o = begin; o < end; ++o)
    {
      // Queries in grid order read their coordinates in sequence, from the grid's own copy.
      const int32_t slot = this->Slots[o];
      const vtkIdType r = this->Rows[o];
      const double nearest = this->Query.NearestK(g.SortedPoints + 3 * static_cast<size_t>(slot),
        g.SortedIds[slot], this->Table + r * this->Query.K, hint, candidates, bucketScratch);
      if (this->Nearest)
      {
        this->Nearest[r] = nearest;
      }
    }
  }

  void Reduce() {}

  // Large k, the grid's queries a cell at a time: the cells near the cell's queries are found
  // once for all of them (GridQuery::SlotsNear()) within 1.2 times the previous query's k-th
  // distance, and each query compares the points of those cells. A query with fewer than k
  // points within that distance is answered by NearestK(). The rows are NearestK()'s.
  void ByCell(vtkIdType begin, vtkIdType end, double& hint,
    std::vector<GridQuery::Candidate>& candidates, GridQuery::BucketScratch& bucketScratch)
  {
    const auto& g = *this->Query.Grid;
    std::vector<std::pair<int32_t, int32_t>>& ranges = this->Ranges.Local();
    for (vtkIdType o = begin; o < end;)
    {
      // The run of queries in the cell of the first.
      const double* first = g.SortedPoints + 3 * static_cast<size_t>(this->Slots[o]);
      int c[3];
      g.CellOf(first, c);
      const vtkIdType cell = g.Index(c[0], c[1], c[2]);
      vtkIdType last = o + 1;
      while (last < end && this->Slots[last] >= g.CellStart[cell] &&
        this->Slots[last] < g.CellStart[cell + 1])
      {
        ++last;
      }
      double lo[3] = { first[0], first[1], first[2] };
      double hi[3] = { first[0], first[1], first[2] };
      for (vtkIdType q = o + 1; q < last; ++q)
      {
        const double* x = g.SortedPoints + 3 * static_cast<size_t>(this->Slots[q]);
        for (int a = 0; a < 3; ++a)
        {
          lo[a] = std::min(lo[a], x[a]);
          hi[a] = std::max(hi[a], x[a]);
        }
      }
      // Only where the distance reaches past a cell: within a crowded cell (a dense spot of an
      // uneven cloud) one query's rings read fewer cells than the cell's neighbours all around.
      const double bound = 1.44 * hint;
      const bool together = hint > 0.0 && bound >= g.Spacing * g.Spacing;
      if (together)
      {
        this->Query.SlotsNear(lo, hi, bound, ranges);
      }
      for (; o < last; ++o)
      {
        const int32_t slot = this->Slots[o];
        const vtkIdType r = this->Rows[o];
        const double* x = g.SortedPoints + 3 * static_cast<size_t>(slot);
        int32_t* row = this->Table + r * this->Query.K;
        double nearest = 0.0, kth = 0.0;
        if (together &&
          this->Query.NearestKInRanges(x, g.SortedIds[slot], bound, ranges, row, nearest, kth,
            candidates, bucketScratch))
        {
          hint = kth;
        }
        else
        {
          nearest =
            this->Query.NearestK(x, g.SortedIds[slot], row, hint, candidates, bucketScratch);
        }
        if (this->Nearest)
        {
          this->Nearest[r] = nearest;
        }
      }
    }
  }
};
} // namespace

void vtkPointCloudGridLocator::BuildGrid(vtkPoints* points,
  const std::vector<unsigned char>& valid, const double bounds[6], vtkIdType m)
{
  this->Grid.reset(new SearchGrid);
  SearchGrid& g = *this->Grid;
  const vtkIdType n = points->GetNumberOfPoints();
  const featurepoints::PointReader reader(points);

  // The box: the bounds, or the central 99 % of the points widened by half its size when a few
  // far outliers stretch the bounds more than four times (they then share the border cells).
  // Where more outliers than that stretch it (a few per cent of the points spread far around a
  // dense part), the dense part falls into a few cells, and every query there compares most of
  // its points: the central 95 % and 80 % are tried too, and the box whose cells a query reads
  // least (the sum over cells of the squared number of points, on a sample) wins.
  double lo[3], hi[3];
  const double cells = 2.0 * static_cast<double>(m);
  // Cell side for a box: the smallest for which the grid has at most two cells per point.
  auto sideOf = [&](const double* blo, const double* bhi) {
    double extent[3], largest = 0.0;
    for (int a = 0; a < 3; ++a)
    {
      extent[a] = bhi[a] - blo[a];
      largest = std::max(largest, extent[a]);
    }
    if (!(largest > 0.0))
    {
      largest = 1.0;
    }
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
    return big;
  };
  {
    const vtkIdType stride = std::max<vtkIdType>(1, m / 100000);
    std::vector<double> sample[3];
    double x[3];
    vtkIdType seen = 0;
    for (vtkIdType i = 0; i < n; ++i)
    {
      if (valid[i] && (seen++ % stride) == 0)
      {
        reader.Get(i, x);
        for (int a = 0; a < 3; ++a)
        {
          sample[a].push_back(x[a]);
        }
      }
    }
    const std::vector<double> points[3] = { sample[0], sample[1], sample[2] };
    // The central part of the sample between ranks `cut` and size - 1 - cut on each axis, widened
    // by half its size where the bounds are more than four times as wide.
    auto central = [&](size_t cut, double* blo, double* bhi) {
      for (int a = 0; a < 3; ++a)
      {
        blo[a] = bounds[2 * a];
        bhi[a] = bounds[2 * a + 1];
        std::vector<double>& v = sample[a];
        if (v.empty())
        {
          continue;
        }
        const double rlo = featurepoints::ValueOfRank(v, std::min(cut, v.size() - 1));
        const double rhi = featurepoints::ValueOfRank(v, v.size() - 1 - std::min(cut, v.size() - 1));
        const double robust = rhi - rlo;
        if (robust > 0.0 && bhi[a] - blo[a] > 4.0 * robust)
        {
          blo[a] = std::max(blo[a], rlo - 0.5 * robust);
          bhi[a] = std::min(bhi[a], rhi + 0.5 * robust);
        }
      }
    };
    // The sample's pairs within cells of a box, its points beyond it clamped to its border cells.
    auto costOf = [&](const double* blo, const double* bhi) {
      const double h = sideOf(blo, bhi);
      int dims[3];
      for (int a = 0; a < 3; ++a)
      {
        dims[a] = static_cast<int>(std::max(1.0, std::ceil((bhi[a] - blo[a]) / h)));
      }
      std::vector<int64_t> index(points[0].size());
      for (size_t i = 0; i < index.size(); ++i)
      {
        int64_t c = 0;
        for (int a = 2; a >= 0; --a)
        {
          const double f = std::floor((points[a][i] - blo[a]) / h);
          const int64_t k = f < 0.0 ? 0 : (f >= dims[a] - 1 ? dims[a] - 1 : static_cast<int64_t>(f));
          c = c * dims[a] + k;
        }
        index[i] = c;
      }
      std::sort(index.begin(), index.end());
      double cost = 0.0;
      for (size_t i = 0; i < index.size();)
      {
        size_t j = i;
        while (j < index.size() && index[j] == index[i])
        {
          ++j;
        }
        cost += static_cast<double>(j - i) * static_cast<double>(j - i);
        i = j;
      }
      return cost;
    };
    const size_t size = points[0].size();
    central(size / 200, lo, hi);
    // Only where the central 80 % is less than a quarter of the box on some axis, and the
    // sample's queries compare more than 64 points of their own cell on average (a regular
    // cloud: a few).
    double narrow[2][3];
    central(size / 10, narrow[0], narrow[1]);
    bool compare = false;
    for (int a = 0; a < 3; ++a)
    {
      compare = compare || narrow[1][a] - narrow[0][a] < 0.25 * (hi[a] - lo[a]);
    }
    double best = size && compare ? costOf(lo, hi) : 0.0;
    for (int candidate = 0; candidate < 2; ++candidate)
    {
      if (!(best > 64.0 * static_cast<double>(size)))
      {
        break;
      }
      // The central 95 %, then the central 80 % (computed above).
      double clo[3], chi[3];
      if (candidate == 0)
      {
        central(size / 40, clo, chi);
      }
      else
      {
        std::copy(narrow[0], narrow[0] + 3, clo);
        std::copy(narrow[1], narrow[1] + 3, chi);
      }
      const double cost = costOf(clo, chi);
      if (cost < 0.5 * best)
      {
        best = cost;
        std::copy(clo, clo + 3, lo);
        std::copy(chi, chi + 3, hi);
      }
    }
  }
  double extent[3];
  for (int a = 0; a < 3; ++a)
  {
    extent[a] = hi[a] - lo[a];
  }
  g.Spacing = sideOf(lo, hi);
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
      if (valid[i])
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
  g.Coordinates = vtkSmartPointer<vtkDoubleArray>::New();
  g.Coordinates->SetNumberOfComponents(3);
  g.Coordinates->SetNumberOfTuples(m);
  g.SortedPoints = g.Coordinates->GetPointer(0);
  std::vector<int32_t> next(g.CellStart.begin(), g.CellStart.end() - 1);
  g.SlotOf.assign(n, -1);
  for (vtkIdType i = 0; i < n; ++i)
  {
    if (cellOf[i] >= 0)
    {
      const int32_t slot = next[cellOf[i]]++;
      g.SlotOf[i] = slot;
      g.SortedIds[slot] = static_cast<int32_t>(i);
      reader.Get(i, g.SortedPoints + 3 * static_cast<size_t>(slot));
    }
  }
  this->BuildSites();
  this->BuildTree();
}

void vtkPointCloudGridLocator::BuildTree()
{
  SearchGrid& g = *this->Grid;
  // The mean number of positions in a query's own cell (each position weighted by its cell's
  // count): a few on any cloud whose points spread over the box, thousands where clusters lie
  // far apart relative to their size, each then in a handful of cells, which every query there
  // reads whole (the time grows with the square of the points).
  const vtkIdType numberOfCells = static_cast<vtkIdType>(g.CellStart.size()) - 1;
  const std::vector<int32_t>& start = g.HasDuplicates ? g.SiteStart : g.CellStart;
  double pairs = 0.0;
  for (vtkIdType cell = 0; cell < numberOfCells; ++cell)
  {
    const double count = static_cast<double>(start[cell + 1] - start[cell]);
    pairs += count * count;
  }
  const double positions = static_cast<double>(start[numberOfCells]);
  this->CellOccupancy = positions > 0.0 ? pairs / positions : 0.0;
  const bool tree = this->SearchStructure == KD_TREE ||
    (this->SearchStructure == AUTO && this->CellOccupancy > TreeOccupancy);
  if (tree && !g.SortedIds.empty())
  {
    g.Tree = std::make_shared<SearchGrid::SlotTree>(&g);
  }
}

void vtkPointCloudGridLocator::BuildSites()
{
  SearchGrid& g = *this->Grid;
  const vtkIdType numberOfCells = static_cast<vtkIdType>(g.CellStart.size()) - 1;
  const double* p = g.SortedPoints;
  // Slots by their sites' keys (SiteKey()), then ascending.
  auto byPosition = [p](int32_t a, int32_t b) {
    const double* x = p + 3 * static_cast<size_t>(a);
    const double* y = p + 3 * static_cast<size_t>(b);
    for (int c = 0; c < 3; ++c)
    {
      const double kx = SiteKey(x[c]), ky = SiteKey(y[c]);
      if (kx != ky)
      {
        return kx < ky;
      }
    }
    return a < b;
  };
  auto same = [p](int32_t a, int32_t b) {
    const double* x = p + 3 * static_cast<size_t>(a);
    const double* y = p + 3 * static_cast<size_t>(b);
    return SiteKey(x[0]) == SiteKey(y[0]) && SiteKey(x[1]) == SiteKey(y[1]) &&
      SiteKey(x[2]) == SiteKey(y[2]);
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

bool vtkPointCloudGridLocator::FindNearestNeighbors(int k, const std::vector<vtkIdType>& ids,
  std::vector<int32_t>& table, std::vector<double>* nearestDistances, bool distinct,
  vtkAlgorithm* progressAlg, double progressStart, double progressEnd)
{
  const vtkIdType rows = static_cast<vtkIdType>(ids.size());
  table.resize(static_cast<size_t>(rows) * std::max(k, 0));
  if (nearestDistances)
  {
    nearestDistances->resize(rows);
  }
  if (k <= 0)
  {
    return true;
  }
  this->BuildLocator();
  if (!this->Grid)
  {
    std::fill(table.begin(), table.end(), -1);
    if (nearestDistances)
    {
      std::fill(nearestDistances->begin(), nearestDistances->end(), 0.0);
    }
    return true;
  }
  const SearchGrid& g = *this->Grid;
  // The queries in grid order (by their slot), so that neighbouring queries read the same cells
  // and their coordinates in sequence. Rows of invalid points are filled here.
  // The queries' order: their slots ascending (the first row of each), then the rows of an id
  // listed again, in row order. A call for most of the grid marks the slots in an array of one
  // entry per point; a call for a block of rows sorts its (slot, row) pairs, so that it costs in
  // the block's size, not in the cloud's.
  const int32_t k32 = k;
  const vtkIdType n = static_cast<vtkIdType>(g.SlotOf.size());
  auto slotOfRow = [&](vtkIdType r) -> int32_t {
    const int32_t slot = ids[r] >= 0 && ids[r] < n ? g.SlotOf[ids[r]] : -1;
    if (slot < 0)
    {
      std::fill_n(table.data() + r * k32, k32, -1);
      if (nearestDistances)
      {
        (*nearestDistances)[r] = 0.0;
      }
    }
    return slot;
  };
  std::vector<int32_t> slots;
  std::vector<vtkIdType> order;
  std::vector<std::pair<int32_t, vtkIdType>> repeated; // an id listed again: (slot, row)
  slots.reserve(rows);
  order.reserve(rows);
  if (rows >= static_cast<vtkIdType>(g.SortedIds.size()) / 16)
  {
    std::vector<vtkIdType> rowOfSlot(g.SortedIds.size(), -1);
    for (vtkIdType r = 0; r < rows; ++r)
    {
      const int32_t slot = slotOfRow(r);
      if (slot >= 0)
      {
        if (rowOfSlot[slot] >= 0)
        {
          repeated.emplace_back(slot, r);
        }
        else
        {
          rowOfSlot[slot] = r;
        }
      }
    }
    for (size_t slot = 0; slot < rowOfSlot.size(); ++slot)
    {
      if (rowOfSlot[slot] >= 0)
      {
        slots.push_back(static_cast<int32_t>(slot));
        order.push_back(rowOfSlot[slot]);
      }
    }
  }
  else
  {
    std::vector<std::pair<int32_t, vtkIdType>> listed; // (slot, row)
    listed.reserve(static_cast<size_t>(rows));
    for (vtkIdType r = 0; r < rows; ++r)
    {
      const int32_t slot = slotOfRow(r);
      if (slot >= 0)
      {
        listed.emplace_back(slot, r);
      }
    }
    std::sort(listed.begin(), listed.end());
    for (size_t q = 0; q < listed.size(); ++q)
    {
      if (q > 0 && listed[q].first == listed[q - 1].first)
      {
        repeated.push_back(listed[q]);
      }
      else
      {
        slots.push_back(listed[q].first);
        order.push_back(listed[q].second);
      }
    }
    std::sort(repeated.begin(), repeated.end(),
      [](const std::pair<int32_t, vtkIdType>& a, const std::pair<int32_t, vtkIdType>& b) {
        return a.second < b.second;
      });
  }
  for (const auto& extra : repeated)
  {
    slots.push_back(extra.first);
    order.push_back(extra.second);
  }
  const vtkIdType queries = static_cast<vtkIdType>(slots.size());

  GridNeighborsWorker worker{ { &g, k }, slots.data(), order.data(), table.data(),
    nearestDistances ? nearestDistances->data() : nullptr, distinct && k == 1, {}, {}, {} };
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

vtkPointCloudGridLocator::vtkPointCloudGridLocator() = default;
vtkPointCloudGridLocator::~vtkPointCloudGridLocator() = default;

void vtkPointCloudGridLocator::FreeSearchStructure()
{
  this->Grid.reset();
  this->CellOccupancy = 0.0;
  this->NumberOfBuckets = 0;
}

void vtkPointCloudGridLocator::BuildLocator()
{
  if (this->Grid && this->BuildTime > this->MTime && this->DataSet &&
    this->BuildTime > this->DataSet->GetMTime())
  {
    return;
  }
  this->FreeSearchStructure();
  std::fill(this->Bounds, this->Bounds + 6, 0.0);
  if (!this->DataSet)
  {
    vtkErrorMacro(<< "No data set to build the grid over.");
    return;
  }
  const vtkIdType n = this->DataSet->GetNumberOfPoints();
  if (n > std::numeric_limits<int32_t>::max())
  {
    vtkErrorMacro(<< "The data set has " << n << " points, more than the 2^31 - 1 this grid holds.");
    return;
  }
  // The points as a vtkPoints (a data set that is not a vtkPointSet gives a copy).
  vtkSmartPointer<vtkPoints> points;
  if (auto* pointSet = vtkPointSet::SafeDownCast(this->DataSet))
  {
    points = pointSet->GetPoints();
  }
  if (!points)
  {
    points = vtkSmartPointer<vtkPoints>::New();
    points->SetDataTypeToDouble();
    points->SetNumberOfPoints(n);
    for (vtkIdType i = 0; i < n; ++i)
    {
      points->SetPoint(i, this->DataSet->GetPoint(i));
    }
  }

  // The finite points and their bounds: a NaN coordinate has no cell.
  const featurepoints::PointReader reader(points);
  std::vector<unsigned char> valid(n, 0);
  vtkIdType m = 0;
  double bounds[6] = { VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX,
    VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
  double x[3];
  for (vtkIdType i = 0; i < n; ++i)
  {
    reader.Get(i, x);
    if (std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]))
    {
      valid[i] = 1;
      ++m;
      for (int a = 0; a < 3; ++a)
      {
        bounds[2 * a] = std::min(bounds[2 * a], x[a]);
        bounds[2 * a + 1] = std::max(bounds[2 * a + 1], x[a]);
      }
    }
  }
  if (m == 0)
  {
    // No finite point: one empty cell, so that every query finds nothing.
    this->Grid.reset(new SearchGrid);
    this->Grid->CellStart.assign(2, 0);
    this->Grid->SlotOf.assign(n, -1);
    this->Grid->Coordinates = vtkSmartPointer<vtkDoubleArray>::New();
    this->Grid->Coordinates->SetNumberOfComponents(3);
  }
  else
  {
    std::copy(bounds, bounds + 6, this->Bounds);
    this->BuildGrid(points, valid, bounds, m);
  }
  const SearchGrid& g = *this->Grid;
  this->NumberOfBuckets = static_cast<vtkIdType>(g.Dims[0]) * g.Dims[1] * g.Dims[2];
  this->BuildTime.Modified();
}

namespace
{
bool IsFinite(const double x[3])
{
  return std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]);
}
} // namespace

vtkIdType vtkPointCloudGridLocator::FindClosestPoint(const double x[3])
{
  this->BuildLocator();
  if (!this->Grid || !IsFinite(x))
  {
    return -1;
  }
  return GridQuery{ this->Grid.get(), 1 }.NearestOne<false>(x, -1).Id;
}

vtkIdType vtkPointCloudGridLocator::FindClosestPointWithinRadius(
  double radius, const double x[3], double& dist2)
{
  this->BuildLocator();
  dist2 = -1.0;
  if (!this->Grid || !IsFinite(x))
  {
    return -1;
  }
  const GridQuery::Candidate best = GridQuery{ this->Grid.get(), 1 }.NearestOne<false>(x, -1);
  if (best.Id < 0 || best.D2 > radius * radius)
  {
    return -1;
  }
  dist2 = best.D2;
  return best.Id;
}

void vtkPointCloudGridLocator::FindClosestNPoints(int N, const double x[3], vtkIdList* result)
{
  result->Reset();
  this->BuildLocator();
  if (!this->Grid || !IsFinite(x) || N <= 0)
  {
    return;
  }
  const GridQuery query{ this->Grid.get(), N };
  std::vector<int32_t> row(N);
  std::vector<GridQuery::Candidate> candidates;
  GridQuery::BucketScratch scratch;
  double hint = -1.0;
  query.NearestK(x, -1, row.data(), hint, candidates, scratch);
  for (int j = 0; j < N && row[j] >= 0; ++j)
  {
    result->InsertNextId(row[j]);
  }
}

void vtkPointCloudGridLocator::FindPointsWithinRadius(double R, const double x[3], vtkIdList* result)
{
  result->Reset();
  this->BuildLocator();
  if (!this->Grid || !IsFinite(x) || !(R >= 0.0))
  {
    return;
  }
  const SearchGrid& g = *this->Grid;
  const double r2 = R * R;
  std::vector<GridQuery::Candidate> found;
  int c[3];
  g.CellOf(x, c);
  if (g.Tree)
  {
    GridQuery::TreeWithin within{ g, x, r2, found };
    g.Tree->Tree.findNeighbors(within, x, nanoflann::SearchParams());
  }
  for (int ring = 0; !g.Tree; ++ring)
  {
    g.ForEachCellOfRing(c, ring, [&](int i, int j, int k) {
      if (g.BoxDistance2(i, j, k, x) > r2)
      {
        return;
      }
      const vtkIdType cell = g.Index(i, j, k);
      const double* y = g.SortedPoints + 3 * static_cast<size_t>(g.CellStart[cell]);
      for (int32_t s = g.CellStart[cell]; s < g.CellStart[cell + 1]; ++s, y += 3)
      {
        const double dx = x[0] - y[0], dy = x[1] - y[1], dz = x[2] - y[2];
        const double d2 = dx * dx + dy * dy + dz * dz;
        if (d2 <= r2)
        {
          found.push_back(GridQuery::Candidate{ d2, g.SortedIds[s] });
        }
      }
    });
    // Done when the unsearched cells all lie beyond R.
    bool everything;
    const double gap = g.RingGap(c, ring, x, everything);
    if (everything || (gap > 0.0 && gap > R))
    {
      break;
    }
  }
  std::sort(found.begin(), found.end());
  result->SetNumberOfIds(static_cast<vtkIdType>(found.size()));
  for (size_t j = 0; j < found.size(); ++j)
  {
    result->SetId(static_cast<vtkIdType>(j), found[j].Id);
  }
}

void vtkPointCloudGridLocator::GenerateRepresentation(int, vtkPolyData* pd)
{
  if (!pd)
  {
    return;
  }
  this->BuildLocator();
  vtkNew<vtkPoints> corners;
  corners->SetDataTypeToDouble();
  vtkNew<vtkCellArray> lines;
  if (this->Grid && this->Grid->SortedIds.size() > 0)
  {
    const SearchGrid& g = *this->Grid;
    for (int corner = 0; corner < 8; ++corner)
    {
      double x[3];
      for (int a = 0; a < 3; ++a)
      {
        x[a] = g.Origin[a] + ((corner >> a) & 1) * g.Dims[a] * g.Spacing;
      }
      corners->InsertNextPoint(x);
    }
    // The 12 edges: corners that differ along one axis.
    for (int corner = 0; corner < 8; ++corner)
    {
      for (int a = 0; a < 3; ++a)
      {
        if (!((corner >> a) & 1))
        {
          const vtkIdType edge[2] = { corner, corner | (1 << a) };
          lines->InsertNextCell(2, edge);
        }
      }
    }
  }
  pd->Initialize();
  pd->SetPoints(corners);
  pd->SetLines(lines);
}

void vtkPointCloudGridLocator::GetDivisions(int divisions[3]) const
{
  for (int a = 0; a < 3; ++a)
  {
    divisions[a] = this->Grid ? this->Grid->Dims[a] : 0;
  }
}

double vtkPointCloudGridLocator::GetCellSize() const
{
  return this->Grid ? this->Grid->Spacing : 0.0;
}

void vtkPointCloudGridLocator::GetOrigin(double origin[3]) const
{
  for (int a = 0; a < 3; ++a)
  {
    origin[a] = this->Grid ? this->Grid->Origin[a] : 0.0;
  }
}

vtkIdType vtkPointCloudGridLocator::GetNumberOfGridPoints() const
{
  return this->Grid ? static_cast<vtkIdType>(this->Grid->SortedIds.size()) : 0;
}

vtkPoints* vtkPointCloudGridLocator::ReorderSpatially(std::vector<int32_t>& originalIds)
{
  if (!this->Grid || !this->DataSet)
  {
    return nullptr;
  }
  SearchGrid& g = *this->Grid;
  const vtkIdType n = static_cast<vtkIdType>(g.SlotOf.size());
  const vtkIdType m = static_cast<vtkIdType>(g.SortedIds.size());
  // New id i < m is slot i of the grid; the points left out follow, with their own coordinates.
  originalIds.resize(n);
  std::copy(g.SortedIds.begin(), g.SortedIds.end(), originalIds.begin());
  if (n > m)
  {
    // Room for the points left out (SetNumberOfTuples() would not keep the values).
    vtkNew<vtkDoubleArray> longer;
    longer->SetNumberOfComponents(3);
    longer->SetNumberOfTuples(n);
    std::copy(g.SortedPoints, g.SortedPoints + 3 * static_cast<size_t>(m), longer->GetPointer(0));
    g.Coordinates = longer;
    g.SortedPoints = g.Coordinates->GetPointer(0);
  }
  vtkIdType next = m;
  for (vtkIdType i = 0; i < n && next < n; ++i)
  {
    if (g.SlotOf[i] < 0)
    {
      originalIds[next] = static_cast<int32_t>(i);
      this->DataSet->GetPoint(i, g.SortedPoints + 3 * static_cast<size_t>(next));
      ++next;
    }
  }
  std::iota(g.SortedIds.begin(), g.SortedIds.end(), 0);
  std::iota(g.SlotOf.begin(), g.SlotOf.begin() + m, 0);
  std::fill(g.SlotOf.begin() + m, g.SlotOf.end(), -1);

  // The renumbered points read the grid's coordinates in place; they become the data set, and the
  // grid stays built over them.
  vtkNew<vtkPoints> renumbered;
  renumbered->SetData(g.Coordinates);
  vtkNew<vtkPolyData> data;
  data->SetPoints(renumbered);
  this->SetDataSet(data);
  this->BuildTime.Modified();
  return renumbered;
}

void vtkPointCloudGridLocator::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  int divisions[3];
  this->GetDivisions(divisions);
  os << indent << "Divisions: (" << divisions[0] << ", " << divisions[1] << ", " << divisions[2]
     << ")\n";
  os << indent << "CellSize: " << this->GetCellSize() << "\n";
  os << indent << "NumberOfGridPoints: " << this->GetNumberOfGridPoints() << "\n";
  os << indent << "SearchStructure: " << this->SearchStructure << "\n";
  os << indent << "CellOccupancy: " << this->CellOccupancy << "\n";
  os << indent << "UsesTree: " << (this->GetUsesTree() ? "yes" : "no") << "\n";
}

bool vtkPointCloudGridLocator::GetUsesTree() const
{
  return this->Grid && this->Grid->Tree;
}

// The wrapped counterparts of the methods on std::vector tables (see the header).
bool vtkPointCloudGridLocator::FindNearestNeighbors(
  int k, vtkIdList* ids, vtkIntArray* table, vtkDoubleArray* nearestDistances)
{
  return featurepoints::FindNearestNeighborsInArrays(k, ids, table, nearestDistances,
    [&](const std::vector<vtkIdType>& rows, std::vector<int32_t>& entries,
      std::vector<double>* nearest) { return this->FindNearestNeighbors(k, rows, entries, nearest); });
}

vtkPoints* vtkPointCloudGridLocator::ReorderSpatially(vtkIntArray* originalIds)
{
  std::vector<int32_t> ids;
  vtkPoints* points = originalIds ? this->ReorderSpatially(ids) : nullptr;
  if (points)
  {
    originalIds->SetNumberOfComponents(1);
    originalIds->SetNumberOfValues(static_cast<vtkIdType>(ids.size()));
    std::copy(ids.begin(), ids.end(), originalIds->GetPointer(0));
  }
  return points;
}
