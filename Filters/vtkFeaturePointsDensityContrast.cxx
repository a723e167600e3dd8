#include "vtkFeaturePointsDensityContrast.h"

#include "vtkFeaturePointsLocalPCA.h"
#include "vtkFeaturePointsStatistics.h"
#include "vtkObject.h"
#include "vtkPointCloudNeighborhoods.h"
#include "vtkPoints.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <utility>
#include <vector>

namespace
{
constexpr int KeyBits = 21;
constexpr int64_t KeyRange = int64_t(1) << KeyBits; // voxel indices per axis: [0, 2^21)

inline uint64_t PackKey(int64_t i, int64_t j, int64_t k)
{
  return static_cast<uint64_t>(i) | (static_cast<uint64_t>(j) << KeyBits) |
    (static_cast<uint64_t>(k) << (2 * KeyBits));
}

inline void UnpackKey(uint64_t key, int64_t ijk[3])
{
  const uint64_t mask = static_cast<uint64_t>(KeyRange - 1);
  ijk[0] = static_cast<int64_t>(key & mask);
  ijk[1] = static_cast<int64_t>((key >> KeyBits) & mask);
  ijk[2] = static_cast<int64_t>((key >> (2 * KeyBits)) & mask);
}

// The occupied voxels, sorted by key (k, then j, then i), with their point counts. The voxels of
// a row (fixed j and k) are contiguous in that order, so a neighbour lookup finds the row and
// searches its few voxels: 9 row lookups per 26-neighbourhood, each into a small table read in
// sequence by consecutive voxels. Rows are indexed by a dense (j, k) table when it is not much
// larger than the number of voxels (a surface: about a sixth of it), else by a hash table of the
// occupied rows (a box stretched by outliers).
struct SparseGrid
{
  std::vector<uint64_t> Keys;
  std::vector<int32_t> Counts;

  int64_t J0 = 0, K0 = 0, NJ = 0, NK = 0;
  std::vector<int32_t> RowStart; // dense: first voxel of row (j - J0) + NJ (k - K0), then the end
  std::vector<uint64_t> RowKeys; // sparse: open-addressing table, row key + 1 (0 marks empty)
  std::vector<int32_t> RowBegin, RowEnd;
  uint64_t Mask = 0;

  static uint64_t Mix(uint64_t key)
  {
    key ^= key >> 33;
    key *= 0xff51afd7ed558ccdULL;
    key ^= key >> 33;
    return key;
  }
  static uint64_t RowKey(uint64_t voxelKey) { return voxelKey >> KeyBits; }

  void BuildRows()
  {
    const size_t nv = this->Keys.size();
    int64_t lo[3] = { KeyRange, KeyRange, KeyRange }, hi[3] = { -1, -1, -1 };
    for (uint64_t key : this->Keys)
    {
      int64_t ijk[3];
      UnpackKey(key, ijk);
      for (int c = 1; c < 3; ++c)
      {
        lo[c] = std::min(lo[c], ijk[c]);
        hi[c] = std::max(hi[c], ijk[c]);
      }
    }
    this->RowStart.clear();
    this->RowKeys.clear();
    if (nv == 0)
    {
      return;
    }
    this->J0 = lo[1];
    this->K0 = lo[2];
    this->NJ = hi[1] - lo[1] + 1;
    this->NK = hi[2] - lo[2] + 1;
    if (static_cast<double>(this->NJ) * static_cast<double>(this->NK) <= 4.0 * nv + 1024.0)
    {
      // Keys are sorted, so rows come in increasing dense index.
      const size_t rows = static_cast<size_t>(this->NJ * this->NK);
      this->RowStart.assign(rows + 1, 0);
      size_t row = 0;
      for (size_t v = 0; v < nv; ++v)
      {
        int64_t ijk[3];
        UnpackKey(this->Keys[v], ijk);
        const size_t r = static_cast<size_t>((ijk[2] - this->K0) * this->NJ + (ijk[1] - this->J0));
        while (row <= r)
        {
          this->RowStart[row++] = static_cast<int32_t>(v);
        }
      }
      while (row <= rows)
      {
        this->RowStart[row++] = static_cast<int32_t>(nv);
      }
      return;
    }
    size_t size = 16;
    while (size < 2 * nv)
    {
      size *= 2;
    }
    this->Mask = size - 1;
    this->RowKeys.assign(size, 0);
    this->RowBegin.assign(size, 0);
    this->RowEnd.assign(size, 0);
    for (size_t v = 0; v < nv;)
    {
      const uint64_t row = RowKey(this->Keys[v]);
      size_t e = v + 1;
      while (e < nv && RowKey(this->Keys[e]) == row)
      {
        ++e;
      }
      uint64_t slot = Mix(row) & this->Mask;
      while (this->RowKeys[slot] != 0)
      {
        slot = (slot + 1) & this->Mask;
      }
      this->RowKeys[slot] = row + 1;
      this->RowBegin[slot] = static_cast<int32_t>(v);
      this->RowEnd[slot] = static_cast<int32_t>(e);
      v = e;
    }
  }

  // The voxels [begin, end) of row (j, k); an empty range when it has none.
  void Row(int64_t j, int64_t k, int32_t& begin, int32_t& end) const
  {
    begin = end = 0;
    if (!this->RowStart.empty())
    {
      if (j >= this->J0 && j < this->J0 + this->NJ && k >= this->K0 && k < this->K0 + this->NK)
      {
        const size_t r = static_cast<size_t>((k - this->K0) * this->NJ + (j - this->J0));
        begin = this->RowStart[r];
        end = this->RowStart[r + 1];
      }
      return;
    }
    if (this->RowKeys.empty() || j < 0 || k < 0 || j >= KeyRange || k >= KeyRange)
    {
      return;
    }
    const uint64_t row = static_cast<uint64_t>(j) | (static_cast<uint64_t>(k) << KeyBits);
    for (uint64_t slot = Mix(row) & this->Mask;; slot = (slot + 1) & this->Mask)
    {
      const uint64_t stored = this->RowKeys[slot];
      if (stored == row + 1)
      {
        begin = this->RowBegin[slot];
        end = this->RowEnd[slot];
        return;
      }
      if (stored == 0)
      {
        return;
      }
    }
  }

  // Visits the 26-neighbourhoods of voxels taken in increasing order (a loop over a range of
  // voxels): the first key each of the 9 neighbouring rows needs only grows, so 9 cursors move
  // forward through the sorted keys, reading them in sequence, instead of searching each row.
  class Sweep
  {
  public:
    explicit Sweep(const SparseGrid& grid)
      : Grid(grid)
    {
      std::fill(this->Cursor, this->Cursor + 9, -1);
    }

    // Calls f(neighbourIndex) for each occupied voxel of the 26-neighbourhood of voxel v; v must
    // be larger than at the previous call.
    template <typename F>
    void operator()(vtkIdType v, F&& f)
    {
      const uint64_t* keys = this->Grid.Keys.data();
      const vtkIdType n = static_cast<vtkIdType>(this->Grid.Keys.size());
      int64_t ijk[3];
      UnpackKey(keys[v], ijk);
      const int64_t iLo = std::max<int64_t>(ijk[0] - 1, 0);
      const int64_t iHi = std::min<int64_t>(ijk[0] + 1, KeyRange - 1);
      int o = 0;
      for (int dk = -1; dk <= 1; ++dk)
      {
        for (int dj = -1; dj <= 1; ++dj, ++o)
        {
          const int64_t j = ijk[1] + dj, k = ijk[2] + dk;
          if (j < 0 || k < 0 || j >= KeyRange || k >= KeyRange)
          {
            continue;
          }
          const uint64_t first = PackKey(iLo, j, k), last = PackKey(iHi, j, k);
          vtkIdType& c = this->Cursor[o];
          if (c < 0 || (c + 8 < n && keys[c + 8] < first))
          {
            // First use, or a long way to go: search the rest of the keys.
            c = std::lower_bound(keys + std::max<vtkIdType>(c, 0), keys + n, first) - keys;
          }
          while (c < n && keys[c] < first)
          {
            ++c;
          }
          for (vtkIdType w = c; w < n && keys[w] <= last; ++w)
          {
            if (w != v)
            {
              f(w);
            }
          }
        }
      }
    }

  private:
    const SparseGrid& Grid;
    vtkIdType Cursor[9];
  };

  // Calls f(neighbourIndex) for each occupied voxel of the 26-neighbourhood of voxel v, in any
  // order of v (the rows are looked up).
  template <typename F>
  void ForEachNeighbor(vtkIdType v, F&& f) const
  {
    int64_t ijk[3];
    UnpackKey(this->Keys[v], ijk);
    const int64_t iLo = std::max<int64_t>(ijk[0] - 1, 0);
    const int64_t iHi = std::min<int64_t>(ijk[0] + 1, KeyRange - 1);
    for (int dk = -1; dk <= 1; ++dk)
    {
      for (int dj = -1; dj <= 1; ++dj)
      {
        const int64_t j = ijk[1] + dj, k = ijk[2] + dk;
        int32_t begin, end;
        this->Row(j, k, begin, end);
        if (begin == end)
        {
          continue;
        }
        const uint64_t first = PackKey(iLo, j, k), last = PackKey(iHi, j, k);
        const uint64_t* keys = this->Keys.data();
        int32_t w = static_cast<int32_t>(std::lower_bound(keys + begin, keys + end, first) - keys);
        for (; w < end && keys[w] <= last; ++w)
        {
          if (w != v)
          {
            f(w);
          }
        }
      }
    }
  }
};

// One run of the test: the voxel grid of the valid points and what each stage computes on it.
// Each stage is one member function; DensityContrast::MarkCandidates calls them in order.
struct VoxelRun
{
  vtkPoints* Points;
  const unsigned char* Valid; // null: every point is valid
  vtkIdType N;
  double A; // the voxel side
  featurepoints::PointReader Reader;
  const featurepoints::DensityContrastProcesses* P = nullptr; // null: one process

  // The points in blocks of Block ids, so that the passes over them run in parallel and still
  // write in point order: BlockValid[b] valid points come before block b.
  static constexpr vtkIdType Block = 65536;
  vtkIdType NumberOfBlocks = 0;
  std::vector<vtkIdType> BlockValid;
  vtkIdType NumberOfValid = 0;
  double Origin[3] = { 0.0, 0.0, 0.0 };

  std::vector<std::pair<uint64_t, int32_t>> Keyed; // (voxel key, point id), sorted
  vtkIdType Clamped = 0;
  SparseGrid Grid;
  std::vector<vtkIdType> Start; // first entry of each voxel in Keyed, then the end
  vtkIdType NumberOfVoxels = 0;

  bool Block5 = false;              // BLOCK_SPACING with nearest distances
  std::vector<double> Level;        // the compared quantity per voxel
  std::vector<double> BlockCount;   // BLOCK_SPACING: points of each voxel's 5x5x5 block (tent weights)
  double Reference = 0.0;           // BLOCK_SPACING: the median block density
  double Spread = 0.0;              // BLOCK_SPACING: robust deviation of the blocks below it
  double MinimumCount = 0.0;        // BLOCK_SPACING: blocks with fewer points measure nothing
  double Cutoff = 0.0;              // BLOCK_SPACING: the density a contrast block exceeds
  std::vector<unsigned char> Contrast, Keep;
  // Distributed runs (all 1 in one process): the voxels that hold an own point; those the figures
  // of the whole cloud count, each voxel on exactly one process (the one that owns its point of
  // the smallest global id); and those within one voxel of an own point's, whose levels, contrast
  // and flood are exact in the piece (the halo holds 3 voxels around each own point's voxel).
  std::vector<unsigned char> HasOwn, Counted, Trusted;

  VoxelRun(vtkPoints* points, const unsigned char* valid, double a)
    : Points(points)
    , Valid(valid)
    , N(points->GetNumberOfPoints())
    , A(a)
    , Reader(points)
  {
  }

  bool IsValid(vtkIdType i) const { return !this->Valid || this->Valid[i]; }
  bool IsOwn(vtkIdType i) const { return !this->P || this->P->Owned[i]; }
  vtkIdType Sum(vtkIdType value) const { return this->P ? this->P->Sum(value) : value; }
  double UpperMedian(std::vector<double>& values) const
  {
    return this->P ? this->P->UpperMedian(values) : featurepoints::UpperMedian(values);
  }
  vtkIdType BlockEnd(vtkIdType blk) const { return std::min(this->N, (blk + 1) * Block); }

  // Eqs. 10-11: the grid starts at the bounding box's minimum corner (computed in blocks of
  // points, in parallel; min and max do not depend on the order), or is centred on the median
  // point when an outlier stretches the box beyond 2^21 voxels.
  void PlaceGrid()
  {
    this->NumberOfBlocks = (this->N + Block - 1) / Block;
    const vtkIdType nBlocks = this->NumberOfBlocks;
    std::vector<std::array<double, 6>> blockBox(nBlocks);
    this->BlockValid.assign(nBlocks + 1, 0);
    vtkSMPTools::For(0, nBlocks, [&](vtkIdType first, vtkIdType last) {
      double y[3];
      for (vtkIdType blk = first; blk < last; ++blk)
      {
        std::array<double, 6> box = { VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, VTK_DOUBLE_MAX,
          -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
        vtkIdType count = 0;
        for (vtkIdType i = blk * Block; i < this->BlockEnd(blk); ++i)
        {
          if (this->IsValid(i))
          {
            ++count;
          }
          if (this->IsValid(i) && this->IsOwn(i))
          {
            this->Reader.Get(i, y);
            for (int c = 0; c < 3; ++c)
            {
              box[c] = std::min(box[c], y[c]);
              box[3 + c] = std::max(box[3 + c], y[c]);
            }
          }
        }
        blockBox[blk] = box;
        this->BlockValid[blk + 1] = count;
      }
    });
    double lo[3] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, VTK_DOUBLE_MAX };
    double hi[3] = { -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
    for (vtkIdType blk = 0; blk < nBlocks; ++blk)
    {
      for (int c = 0; c < 3; ++c)
      {
        lo[c] = std::min(lo[c], blockBox[blk][c]);
        hi[c] = std::max(hi[c], blockBox[blk][3 + c]);
      }
      this->BlockValid[blk + 1] += this->BlockValid[blk];
    }
    if (this->P)
    {
      this->P->MinMax(lo, hi); // the whole cloud's box
    }
    this->NumberOfValid = this->BlockValid[nBlocks];
    bool fits = true;
    for (int c = 0; c < 3; ++c)
    {
      fits = fits && (hi[c] - lo[c]) / this->A < static_cast<double>(KeyRange - 1);
      this->Origin[c] = lo[c];
    }
    if (fits)
    {
      return;
    }
    std::vector<double> coord;
    coord.reserve(this->NumberOfValid);
    for (int c = 0; c < 3; ++c)
    {
      coord.clear();
      for (vtkIdType i = 0; i < this->N; ++i)
      {
        if (this->IsValid(i) && this->IsOwn(i))
        {
          coord.push_back(this->Points->GetPoint(i)[c]);
        }
      }
      this->Origin[c] = this->UpperMedian(coord) - static_cast<double>(KeyRange / 2) * this->A;
    }
  }

  // The voxel key of each valid point, sorted by (key, point id); points beyond the grid's
  // border are clamped to it and counted.
  void KeyPoints()
  {
    this->Keyed.resize(this->NumberOfValid);
    std::vector<vtkIdType> blockClamped(this->NumberOfBlocks, 0);
    vtkSMPTools::For(0, this->NumberOfBlocks, [&](vtkIdType first, vtkIdType last) {
      double y[3];
      for (vtkIdType blk = first; blk < last; ++blk)
      {
        vtkIdType e = this->BlockValid[blk];
        for (vtkIdType i = blk * Block; i < this->BlockEnd(blk); ++i)
        {
          if (!this->IsValid(i))
          {
            continue;
          }
          this->Reader.Get(i, y);
          int64_t ijk[3];
          bool wasClamped = false;
          for (int c = 0; c < 3; ++c)
          {
            const double f = std::floor((y[c] - this->Origin[c]) / this->A);
            const double g = std::min(std::max(f, 0.0), static_cast<double>(KeyRange - 1));
            wasClamped = wasClamped || g != f;
            ijk[c] = static_cast<int64_t>(g);
          }
          blockClamped[blk] += wasClamped && this->IsOwn(i) ? 1 : 0;
          this->Keyed[e++] = { PackKey(ijk[0], ijk[1], ijk[2]), static_cast<int32_t>(i) };
        }
      }
    });
    this->Clamped =
      this->Sum(std::accumulate(blockClamped.begin(), blockClamped.end(), vtkIdType(0)));
    vtkSMPTools::Sort(this->Keyed.begin(), this->Keyed.end());
  }

  // The occupied voxels, their point counts and their ranges in Keyed.
  void CollectVoxels()
  {
    for (size_t e = 0; e < this->Keyed.size(); ++e)
    {
      if (e == 0 || this->Keyed[e].first != this->Keyed[e - 1].first)
      {
        this->Grid.Keys.push_back(this->Keyed[e].first);
        this->Grid.Counts.push_back(0);
        this->Start.push_back(static_cast<vtkIdType>(e));
      }
      ++this->Grid.Counts.back();
    }
    this->Start.push_back(static_cast<vtkIdType>(this->Keyed.size()));
    this->Grid.BuildRows();
    this->NumberOfVoxels = static_cast<vtkIdType>(this->Grid.Keys.size());
    const vtkIdType nVoxels = this->NumberOfVoxels;
    this->HasOwn.assign(nVoxels, 1);
    this->Counted.assign(nVoxels, 1);
    this->Trusted.assign(nVoxels, 1);
    if (!this->P)
    {
      return;
    }
    for (vtkIdType v = 0; v < nVoxels; ++v)
    {
      bool own = false;
      int32_t first = -1;
      int32_t firstOrder = 0;
      for (vtkIdType e = this->Start[v]; e < this->Start[v + 1]; ++e)
      {
        const int32_t id = this->Keyed[e].second;
        own = own || this->IsOwn(id);
        const int32_t order = this->P->InputOrder ? this->P->InputOrder[id] : id;
        if (first < 0 || order < firstOrder)
        {
          first = id;
          firstOrder = order;
        }
      }
      this->HasOwn[v] = own ? 1 : 0;
      this->Counted[v] = this->IsOwn(first) ? 1 : 0;
    }
    std::fill(this->Trusted.begin(), this->Trusted.end(), 0);
    for (vtkIdType v = 0; v < nVoxels; ++v)
    {
      if (this->HasOwn[v])
      {
        this->Trusted[v] = 1;
        this->Grid.ForEachNeighbor(v, [&](vtkIdType w) { this->Trusted[w] = 1; });
      }
    }
  }

  // The values of the counted voxels (one process: every voxel).
  std::vector<double> CountedValues(const std::vector<double>& values) const
  {
    std::vector<double> kept;
    kept.reserve(values.size());
    for (size_t v = 0; v < values.size(); ++v)
    {
      if (this->Counted[v])
      {
        kept.push_back(values[v]);
      }
    }
    return kept;
  }

  // The compared quantity per voxel: its count (VOXEL_COUNTS) or its block's areal density 1/h^2
  // (BLOCK_SPACING), h the mean nearest distance over a 5x5x5 block: two passes of a 3x3x3 box
  // sum, so tent weights, and each density rests on enough nearest distances (a few dozen on a
  // surface) to be measured, not guessed.
  void MeasureLevels(const double* nearest)
  {
    const vtkIdType nVoxels = this->NumberOfVoxels;
    this->Level.assign(nVoxels, 0.0);
    this->BlockCount.assign(nVoxels, 0.0);
    if (!this->Block5)
    {
      for (vtkIdType v = 0; v < nVoxels; ++v)
      {
        this->Level[v] = this->Grid.Counts[v];
      }
      return;
    }
    // Each voxel's sum in ascending order of the values: a function of the voxel's points only,
    // whatever their numbering (a piece's renumbering differs from the whole cloud's).
    std::vector<double> spacingSum(nVoxels, 0.0);
    vtkSMPTools::For(0, nVoxels, [&](vtkIdType begin, vtkIdType end) {
      std::vector<double> values;
      for (vtkIdType v = begin; v < end; ++v)
      {
        values.clear();
        for (vtkIdType e = this->Start[v]; e < this->Start[v + 1]; ++e)
        {
          values.push_back(nearest[this->Keyed[e].second]);
        }
        std::sort(values.begin(), values.end());
        double sum = 0.0;
        for (double value : values)
        {
          sum += value;
        }
        spacingSum[v] = sum;
      }
    });
    std::vector<double> count(nVoxels);
    for (vtkIdType v = 0; v < nVoxels; ++v)
    {
      count[v] = this->Grid.Counts[v];
    }
    for (int pass = 0; pass < 2; ++pass)
    {
      std::vector<double> nextSum(nVoxels), nextCount(nVoxels);
      vtkSMPTools::For(0, nVoxels, [&](vtkIdType begin, vtkIdType end) {
        SparseGrid::Sweep neighbors(this->Grid);
        for (vtkIdType v = begin; v < end; ++v)
        {
          double sum = spacingSum[v];
          double c = count[v];
          neighbors(v, [&](vtkIdType w) {
            sum += spacingSum[w];
            c += count[w];
          });
          nextSum[v] = sum;
          nextCount[v] = c;
        }
      });
      spacingSum.swap(nextSum);
      count.swap(nextCount);
    }
    for (vtkIdType v = 0; v < nVoxels; ++v)
    {
      this->BlockCount[v] = count[v];
      const double h = spacingSum[v] / count[v];
      this->Level[v] = h > 0.0 ? 1.0 / (h * h) : VTK_DOUBLE_MAX;
    }
  }

  // BLOCK_SPACING: the cloud's typical block density (the median), the spread that random
  // sampling alone gives blocks of this size, and the cutoff a contrast block must exceed: the
  // median by the relative margin epsilon and by `sigmas` robust deviations.
  void EstimateReference(double epsilon, double sigmas)
  {
    if (this->Block5)
    {
      const std::vector<double> levels = this->CountedValues(this->Level);
      std::vector<double> sorted(levels);
      this->Reference = this->UpperMedian(sorted);
      // The spread from the blocks below the median only: denser regions, a minority, sit above
      // it and would widen a two-sided estimate.
      std::vector<double> below;
      for (double x : levels)
      {
        if (x <= this->Reference)
        {
          below.push_back(this->Reference - x);
        }
      }
      this->Spread = featurepoints::MADToSigma * this->UpperMedian(below);
      // A block with few points (the rim of a surface, a stray cluster) measures no density.
      sorted = this->CountedValues(this->BlockCount);
      this->MinimumCount = 0.5 * this->UpperMedian(sorted);
    }
    this->Cutoff =
      std::max((1.0 + epsilon) * this->Reference, this->Reference + sigmas * this->Spread);
  }

  // The contrast voxels. VOXEL_COUNTS (Filter_Algorithm): N(i) against each occupied neighbour.
  // BLOCK_SPACING: the block density against the cutoff. Too few contrast voxels to be more than
  // the clumping of random sampling count as none at all. Returns whether any remains.
  bool MarkContrastVoxels(double epsilon, double minimumFraction)
  {
    const vtkIdType nVoxels = this->NumberOfVoxels;
    this->Contrast.assign(nVoxels, 0);
    vtkSMPTools::For(0, nVoxels, [&](vtkIdType begin, vtkIdType end) {
      SparseGrid::Sweep neighbors(this->Grid);
      for (vtkIdType v = begin; v < end; ++v)
      {
        bool found = false;
        if (!this->Trusted[v])
        {
          // A piece's outer voxels: their levels are not the cloud's, and no own point needs them.
        }
        else if (this->Block5)
        {
          found = this->BlockCount[v] >= this->MinimumCount && this->Level[v] > this->Cutoff;
        }
        else
        {
          neighbors(v, [&](vtkIdType w) {
            found = found || (this->Level[v] - this->Level[w]) / this->Level[w] > epsilon;
          });
        }
        this->Contrast[v] = found ? 1 : 0;
      }
    });
    vtkIdType found = 0, counted = 0;
    for (vtkIdType v = 0; v < nVoxels; ++v)
    {
      found += this->Counted[v] & this->Contrast[v];
      counted += this->Counted[v];
    }
    found = this->Sum(found);
    counted = this->Sum(counted);
    if (static_cast<double>(found) < minimumFraction * static_cast<double>(counted))
    {
      std::fill(this->Contrast.begin(), this->Contrast.end(), 0);
      return false;
    }
    return true;
  }

  // BLOCK_SPACING hysteresis: a denser region is contiguous, so the blocks connected to a
  // contrast voxel through blocks denser than the median by half the margin are part of it too.
  // This keeps the edges and the thinner stretches of a denser band that the strict margin misses.
  void GrowContrast()
  {
    const double weak = this->Reference + 0.5 * (this->Cutoff - this->Reference);
    std::vector<vtkIdType> front;
    for (vtkIdType v = 0; v < this->NumberOfVoxels; ++v)
    {
      if (this->Contrast[v])
      {
        front.push_back(v);
      }
    }
    // Distributed runs: each process floods its trusted voxels; the voxels it reached go to
    // every process, which floods on from those it trusts, until no process reaches a new one.
    // A step of the flood from w to x is taken by a process that owns a point of x (x and w are
    // trusted there), so the processes together take every step one process takes.
    for (;;)
    {
      std::vector<uint64_t> reached;
      while (!front.empty())
      {
        const vtkIdType v = front.back();
        front.pop_back();
        this->Grid.ForEachNeighbor(v, [&](vtkIdType w) {
          if (!this->Contrast[w] && this->Trusted[w] &&
            this->BlockCount[w] >= this->MinimumCount && this->Level[w] > weak)
          {
            this->Contrast[w] = 1;
            front.push_back(w);
            reached.push_back(this->Grid.Keys[w]);
          }
        });
      }
      if (!this->P)
      {
        return;
      }
      this->P->AllGather(reached);
      if (reached.empty())
      {
        return;
      }
      const uint64_t* keys = this->Grid.Keys.data();
      for (uint64_t key : reached)
      {
        const uint64_t* at = std::lower_bound(keys, keys + this->NumberOfVoxels, key);
        const vtkIdType w = at - keys;
        if (w < this->NumberOfVoxels && *at == key && this->Trusted[w] && !this->Contrast[w])
        {
          this->Contrast[w] = 1;
          front.push_back(w);
        }
      }
    }
  }

  // Kept: the contrast voxels and their occupied neighbours. The relation is symmetric, so
  // whichever side is the minority looks at its neighbours: the contrast voxels mark theirs
  // (BLOCK_SPACING, where they are few), or every other voxel looks for one among its own
  // (VOXEL_COUNTS, where nearly every voxel shows contrast).
  void KeepNeighbors()
  {
    const vtkIdType nVoxels = this->NumberOfVoxels;
    this->Keep = this->Contrast;
    const vtkIdType contrastVoxels = std::count(this->Contrast.begin(), this->Contrast.end(), 1);
    if (2 * contrastVoxels < nVoxels)
    {
      for (vtkIdType v = 0; v < nVoxels; ++v)
      {
        if (this->Contrast[v])
        {
          this->Grid.ForEachNeighbor(v, [&](vtkIdType w) { this->Keep[w] = 1; });
        }
      }
      return;
    }
    vtkSMPTools::For(0, nVoxels, [&](vtkIdType begin, vtkIdType end) {
      SparseGrid::Sweep neighbors(this->Grid);
      for (vtkIdType v = begin; v < end; ++v)
      {
        if (!this->Contrast[v])
        {
          bool found = false;
          neighbors(v, [&](vtkIdType w) { found = found || this->Contrast[w] != 0; });
          this->Keep[v] = found ? 1 : 0;
        }
      }
    });
  }

  // The points of the kept voxels are the candidates; returns their number and the number of
  // contrast voxels.
  vtkIdType WriteCandidates(unsigned char* candidate, int32_t* voxelCount, vtkIdType& contrast) const
  {
    vtkIdType nCandidates = 0;
    contrast = 0;
    for (vtkIdType v = 0; v < this->NumberOfVoxels; ++v)
    {
      contrast += this->Counted[v] & this->Contrast[v];
      for (vtkIdType e = this->Start[v]; e < this->Start[v + 1]; ++e)
      {
        const int32_t id = this->Keyed[e].second;
        const unsigned char kept = this->IsOwn(id) ? this->Keep[v] : 0;
        candidate[id] = kept;
        nCandidates += kept;
        if (voxelCount)
        {
          voxelCount[id] = this->Grid.Counts[v];
        }
      }
    }
    return nCandidates;
  }
};

// The points of a spatial sample for the quick screen: whole cubic regions of side `side`, one in
// `modulus` (see featurepoints::InSampledRegion).
std::vector<unsigned char> SampleRegions(vtkPoints* points, const unsigned char* valid,
  vtkIdType n, const double origin[3], double side, uint64_t modulus)
{
  std::vector<unsigned char> sampled(n, 0);
  vtkSMPTools::For(0, n, [&](vtkIdType first, vtkIdType last) {
    double x[3];
    for (vtkIdType i = first; i < last; ++i)
    {
      if (!valid[i])
      {
        continue;
      }
      points->GetPoint(i, x);
      sampled[i] = featurepoints::InSampledRegion(x, origin, side, modulus) ? 1 : 0;
    }
  });
  return sampled;
}
} // namespace

namespace featurepoints
{
vtkIdType DensityContrast::MarkCandidates(vtkPoints* points, const unsigned char* valid,
  double spacing, const double* nearest, unsigned char* candidate, int32_t* voxelCount)
{
  this->VoxelSize = 0.0;
  this->NumberOfOccupiedVoxels = 0;
  this->NumberOfContrastVoxels = 0;
  this->NumberOfCandidates = 0;
  this->NumberOfClampedPoints = 0;
  this->ReferenceLevel = 0.0;
  this->RequiredHaloWidth = 0.0;
  const vtkIdType n = points ? points->GetNumberOfPoints() : 0;
  std::fill(candidate, candidate + n, 0);
  if (voxelCount)
  {
    std::fill(voxelCount, voxelCount + n, 0);
  }
  const double a = this->VoxelSizeFactor * spacing;
  if (n == 0 || !(a > 0.0) || !std::isfinite(a))
  {
    return 0;
  }
  this->VoxelSize = a;
  const DensityContrastProcesses* processes = this->Processes;
  if (processes)
  {
    this->RequiredHaloWidth = HaloWidthFor(a);
    if (this->RequiredHaloWidth > processes->HaloWidth)
    {
      return 0;
    }
  }

  VoxelRun run(points, valid, a);
  run.P = processes;
  run.PlaceGrid();
  run.KeyPoints();
  this->NumberOfClampedPoints = run.Clamped;
  if (processes && run.Clamped > 0)
  {
    // Voxels clamped to the grid's border hold points from anywhere: only the whole cloud holds
    // all of theirs.
    this->RequiredHaloWidth = VTK_DOUBLE_MAX;
    if (processes->HaloWidth < VTK_DOUBLE_MAX)
    {
      return 0;
    }
  }
  run.CollectVoxels();
  this->NumberOfOccupiedVoxels =
    run.Sum(std::accumulate(run.Counted.begin(), run.Counted.end(), vtkIdType(0)));
  run.Block5 = this->ContrastRule == BLOCK_SPACING && nearest;
  run.MeasureLevels(nearest);
  run.EstimateReference(this->DensityContrast, this->ContrastSigmas);
  this->ReferenceLevel = run.Reference;
  if (run.MarkContrastVoxels(this->DensityContrast, this->MinimumContrastFraction) && run.Block5)
  {
    run.GrowContrast();
  }
  run.KeepNeighbors();
  this->NumberOfCandidates =
    run.Sum(run.WriteCandidates(candidate, voxelCount, this->NumberOfContrastVoxels));
  this->NumberOfContrastVoxels = run.Sum(this->NumberOfContrastVoxels);
  if (run.Clamped > 0 && this->Reporter)
  {
    vtkWarningWithObjectMacro(this->Reporter,
      << run.Clamped << " point(s) lie more than 2^20 voxels (" << (KeyRange / 2) * a
      << " units) from the cloud's median point and were clamped to the voxel grid's "
         "border: outliers stretch the bounding box.");
  }
  return this->NumberOfCandidates;
}

bool DensityContrast::SampleShowsContrast(vtkPointCloudNeighborhoods* neighborhoods)
{
  if (this->ContrastRule != BLOCK_SPACING || !neighborhoods)
  {
    return true;
  }
  this->RequiredHaloWidth = 0.0;
  const DensityContrastProcesses* processes = this->Processes;
  vtkPoints* points = neighborhoods->GetPoints();
  const unsigned char* valid = neighborhoods->GetValidMask();
  const vtkIdType n = neighborhoods->GetNumberOfPoints();
  vtkIdType m = neighborhoods->GetNumberOfValidPoints();
  const double* b = neighborhoods->GetBounds();
  if (processes)
  {
    vtkIdType own = 0;
    for (vtkIdType i = 0; i < n; ++i)
    {
      own += valid[i] && processes->Owned[i] ? 1 : 0;
    }
    m = processes->Sum(own);
    b = processes->Bounds;
  }
  const double diagonal = std::sqrt((b[1] - b[0]) * (b[1] - b[0]) + (b[3] - b[2]) * (b[3] - b[2]) +
    (b[5] - b[4]) * (b[5] - b[4]));
  constexpr vtkIdType MinimumSample = 8192;
  constexpr uint64_t SampleModulus = 8;
  if (!points || m < SampleModulus * MinimumSample || !(diagonal > 0.0))
  {
    return true;
  }
  const double side = 20.0 * diagonal / std::sqrt(static_cast<double>(m));
  const double origin[3] = { b[0], b[2], b[4] };
  std::vector<unsigned char> sampled =
    SampleRegions(points, valid, n, origin, side, SampleModulus);
  std::vector<vtkIdType> ids;
  vtkIdType ownSampled = 0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    if (sampled[i])
    {
      ids.push_back(i);
      ownSampled += !processes || processes->Owned[i] ? 1 : 0;
    }
  }
  if ((processes ? processes->Sum(ownSampled) : ownSampled) < MinimumSample)
  {
    return true;
  }
  // Kept by `neighborhoods`: the full test's 1-nearest pass will not search these points again.
  std::vector<double> found;
  neighborhoods->FindNearestDistances(ids, found);
  // The sample's mean spacing, as vtkPointCloudNeighborhoods measures the cloud's: coincident
  // points and isolated outliers (over 10 times the median) left out.
  std::vector<double> positive;
  for (size_t r = 0; r < ids.size(); ++r)
  {
    if (found[r] > 0.0 && (!processes || processes->Owned[ids[r]]))
    {
      positive.push_back(found[r]);
    }
  }
  const double spacing = processes ? processes->MeanWithoutOutliers(positive)
                                   : MeanWithoutOutliers(positive, 10.0);
  if (!(spacing > 0.0))
  {
    return true;
  }
  std::vector<double> nearest(n, 0.0);
  for (size_t r = 0; r < ids.size(); ++r)
  {
    nearest[ids[r]] = found[r];
  }
  std::vector<unsigned char> candidate(n, 0);
  this->MarkCandidates(points, sampled.data(), spacing, nearest.data(), candidate.data());
  return this->NumberOfContrastVoxels > 0;
}
} // namespace featurepoints
