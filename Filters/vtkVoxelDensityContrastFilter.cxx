#include "vtkVoxelDensityContrastFilter.h"

#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkObjectFactory.h"
#include "vtkFeaturePointsLocalPCA.h"
#include "vtkPointCloudNeighborhoods.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkVoxelDensityContrastFilter);

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
} // namespace

vtkVoxelDensityContrastFilter::vtkVoxelDensityContrastFilter() = default;
vtkVoxelDensityContrastFilter::~vtkVoxelDensityContrastFilter() = default;

vtkIdType vtkVoxelDensityContrastFilter::MarkCandidates(vtkPoints* points,
  const unsigned char* valid, double spacing, const double* nearest, unsigned char* candidate,
  int32_t* voxelCount)
{
  this->VoxelSize = 0.0;
  this->NumberOfOccupiedVoxels = 0;
  this->NumberOfContrastVoxels = 0;
  this->NumberOfCandidates = 0;
  this->NumberOfClampedPoints = 0;
  this->ReferenceLevel = 0.0;
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
  auto isValid = [valid](vtkIdType i) { return !valid || valid[i]; };

  // Eq. 10-11: bounding box of the valid points (in blocks of points, in parallel; min and max do
  // not depend on the order).
  constexpr vtkIdType Block = 65536;
  const vtkIdType nBlocks = (n + Block - 1) / Block;
  std::vector<std::array<double, 6>> blockBox(nBlocks);
  std::vector<vtkIdType> blockValid(nBlocks + 1, 0);
  const featurepoints::PointReader reader(points);
  vtkSMPTools::For(0, nBlocks, [&](vtkIdType first, vtkIdType last) {
    double y[3];
    for (vtkIdType blk = first; blk < last; ++blk)
    {
      std::array<double, 6> box = { VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX,
        -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
      vtkIdType count = 0;
      for (vtkIdType i = blk * Block; i < std::min(n, (blk + 1) * Block); ++i)
      {
        if (isValid(i))
        {
          reader.Get(i, y);
          ++count;
          for (int c = 0; c < 3; ++c)
          {
            box[c] = std::min(box[c], y[c]);
            box[3 + c] = std::max(box[3 + c], y[c]);
          }
        }
      }
      blockBox[blk] = box;
      blockValid[blk + 1] = count;
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
    blockValid[blk + 1] += blockValid[blk]; // first entry of each block in `keyed` below
  }
  const vtkIdType nValid = blockValid[nBlocks];
  double x[3];
  bool fits = true;
  for (int c = 0; c < 3; ++c)
  {
    fits = fits && (hi[c] - lo[c]) / a < static_cast<double>(KeyRange - 1);
  }
  double origin[3] = { lo[0], lo[1], lo[2] };
  if (!fits)
  {
    // An outlier stretches the box beyond 2^21 voxels: centre the grid on the median point.
    std::vector<double> coord;
    coord.reserve(nValid);
    for (int c = 0; c < 3; ++c)
    {
      coord.clear();
      for (vtkIdType i = 0; i < n; ++i)
      {
        if (isValid(i))
        {
          coord.push_back(points->GetPoint(i)[c]);
        }
      }
      auto mid = coord.begin() + coord.size() / 2;
      std::nth_element(coord.begin(), mid, coord.end());
      origin[c] = *mid - static_cast<double>(KeyRange / 2) * a;
    }
  }

  // Voxel key of each valid point, sorted (key, point id).
  std::vector<std::pair<uint64_t, int32_t>> keyed(nValid);
  std::vector<vtkIdType> blockClamped(nBlocks, 0);
  vtkSMPTools::For(0, nBlocks, [&](vtkIdType first, vtkIdType last) {
    double y[3];
    for (vtkIdType blk = first; blk < last; ++blk)
    {
      vtkIdType e = blockValid[blk];
      for (vtkIdType i = blk * Block; i < std::min(n, (blk + 1) * Block); ++i)
      {
        if (!isValid(i))
        {
          continue;
        }
        reader.Get(i, y);
        int64_t ijk[3];
        bool wasClamped = false;
        for (int c = 0; c < 3; ++c)
        {
          const double f = std::floor((y[c] - origin[c]) / a);
          const double g = std::min(std::max(f, 0.0), static_cast<double>(KeyRange - 1));
          wasClamped = wasClamped || g != f;
          ijk[c] = static_cast<int64_t>(g);
        }
        blockClamped[blk] += wasClamped ? 1 : 0;
        keyed[e++] = { PackKey(ijk[0], ijk[1], ijk[2]), static_cast<int32_t>(i) };
      }
    }
  });
  const vtkIdType clamped = std::accumulate(blockClamped.begin(), blockClamped.end(), vtkIdType(0));
  this->NumberOfClampedPoints = clamped;
  vtkSMPTools::Sort(keyed.begin(), keyed.end());

  // Occupied voxels and their counts.
  SparseGrid grid;
  std::vector<vtkIdType> start; // first entry of each voxel in `keyed`
  for (size_t e = 0; e < keyed.size(); ++e)
  {
    if (e == 0 || keyed[e].first != keyed[e - 1].first)
    {
      grid.Keys.push_back(keyed[e].first);
      grid.Counts.push_back(0);
      start.push_back(static_cast<vtkIdType>(e));
    }
    ++grid.Counts.back();
  }
  start.push_back(static_cast<vtkIdType>(keyed.size()));
  grid.BuildRows();
  const vtkIdType nVoxels = static_cast<vtkIdType>(grid.Keys.size());
  this->NumberOfOccupiedVoxels = nVoxels;

  // The compared quantity per voxel: its count (paper) or its block's areal density 1/h^2.
  const bool block = this->ContrastRule == BLOCK_SPACING && nearest;
  std::vector<double> spacingSum(nVoxels, 0.0);
  if (block)
  {
    vtkSMPTools::For(0, nVoxels, [&](vtkIdType begin, vtkIdType end) {
      for (vtkIdType v = begin; v < end; ++v)
      {
        double sum = 0.0;
        for (vtkIdType e = start[v]; e < start[v + 1]; ++e)
        {
          sum += nearest[keyed[e].second];
        }
        spacingSum[v] = sum;
      }
    });
  }
  std::vector<double> level(nVoxels);
  std::vector<double> blockCount(nVoxels);
  if (!block)
  {
    for (vtkIdType v = 0; v < nVoxels; ++v)
    {
      level[v] = grid.Counts[v];
    }
  }
  else
  {
    // Two passes of a 3x3x3 box sum: a 5x5x5 block with tent weights, so that each density rests
    // on enough nearest distances (a few dozen on a surface) to be measured, not guessed.
    std::vector<double> count(nVoxels);
    for (vtkIdType v = 0; v < nVoxels; ++v)
    {
      count[v] = grid.Counts[v];
    }
    for (int pass = 0; pass < 2; ++pass)
    {
      std::vector<double> nextSum(nVoxels), nextCount(nVoxels);
      vtkSMPTools::For(0, nVoxels, [&](vtkIdType begin, vtkIdType end) {
        SparseGrid::Sweep neighbors(grid);
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
      blockCount[v] = count[v];
      const double h = spacingSum[v] / count[v];
      level[v] = h > 0.0 ? 1.0 / (h * h) : VTK_DOUBLE_MAX;
    }
  }

  // Contrast voxels. VOXEL_COUNTS (Filter_Algorithm): N(i) against each occupied neighbour.
  // BLOCK_SPACING: the block density against the cloud's typical block density, by a margin of
  // epsilon and of ContrastSigmas robust deviations of the block densities (the spread that random
  // sampling alone gives blocks of this size).
  const double eps = this->DensityContrast;
  double reference = 0.0;
  double spread = 0.0;
  double minimumCount = 0.0;
  if (block)
  {
    std::vector<double> sorted(level);
    auto mid = sorted.begin() + sorted.size() / 2;
    std::nth_element(sorted.begin(), mid, sorted.end());
    reference = *mid;
    // The spread from the blocks below the median only: denser regions, a minority, sit above it
    // and would widen a two-sided estimate.
    std::vector<double> below;
    for (double x : level)
    {
      if (x <= reference)
      {
        below.push_back(reference - x);
      }
    }
    auto low = below.begin() + below.size() / 2;
    std::nth_element(below.begin(), low, below.end());
    spread = 1.4826 * *low;
    // A block with few points (the rim of a surface, a stray cluster) measures no density.
    sorted = blockCount;
    mid = sorted.begin() + sorted.size() / 2;
    std::nth_element(sorted.begin(), mid, sorted.end());
    minimumCount = 0.5 * *mid;
  }
  const double cutoff =
    std::max((1.0 + eps) * reference, reference + this->ContrastSigmas * spread);
  this->ReferenceLevel = reference;
  std::vector<unsigned char> contrast(nVoxels, 0);
  vtkSMPTools::For(0, nVoxels, [&](vtkIdType begin, vtkIdType end) {
    SparseGrid::Sweep neighbors(grid);
    for (vtkIdType v = begin; v < end; ++v)
    {
      bool found = false;
      if (block)
      {
        found = blockCount[v] >= minimumCount && level[v] > cutoff;
      }
      else
      {
        neighbors(v, [&](vtkIdType w) {
          found = found || (level[v] - level[w]) / level[w] > eps;
        });
      }
      contrast[v] = found ? 1 : 0;
    }
  });
  // Too few contrast voxels to be more than the clumping of random sampling: no contrast at all.
  const vtkIdType found = std::count(contrast.begin(), contrast.end(), 1);
  if (static_cast<double>(found) < this->MinimumContrastFraction * static_cast<double>(nVoxels))
  {
    std::fill(contrast.begin(), contrast.end(), 0);
  }
  else if (block)
  {
    // Hysteresis: a denser region is contiguous, so the blocks connected to a contrast voxel
    // through blocks denser than the median by half the margin are part of it too. This keeps the
    // edges and the thinner stretches of a denser band that the strict margin misses.
    const double weak = reference + 0.5 * (cutoff - reference);
    std::vector<vtkIdType> front;
    for (vtkIdType v = 0; v < nVoxels; ++v)
    {
      if (contrast[v])
      {
        front.push_back(v);
      }
    }
    while (!front.empty())
    {
      const vtkIdType v = front.back();
      front.pop_back();
      grid.ForEachNeighbor(v, [&](vtkIdType w) {
        if (!contrast[w] && blockCount[w] >= minimumCount && level[w] > weak)
        {
          contrast[w] = 1;
          front.push_back(w);
        }
      });
    }
  }
  // Kept: the contrast voxels and their occupied neighbours. The relation is symmetric, so
  // whichever side is the minority looks at its neighbours: the contrast voxels mark theirs
  // (BLOCK_SPACING, where they are few), or every other voxel looks for one among its own
  // (VOXEL_COUNTS, where nearly every voxel shows contrast).
  std::vector<unsigned char> keep(contrast);
  const vtkIdType contrastVoxels = std::count(contrast.begin(), contrast.end(), 1);
  if (2 * contrastVoxels < nVoxels)
  {
    for (vtkIdType v = 0; v < nVoxels; ++v)
    {
      if (contrast[v])
      {
        grid.ForEachNeighbor(v, [&](vtkIdType w) { keep[w] = 1; });
      }
    }
  }
  else
  {
    vtkSMPTools::For(0, nVoxels, [&](vtkIdType begin, vtkIdType end) {
      SparseGrid::Sweep neighbors(grid);
      for (vtkIdType v = begin; v < end; ++v)
      {
        if (!contrast[v])
        {
          bool found = false;
          neighbors(v, [&](vtkIdType w) { found = found || contrast[w] != 0; });
          keep[v] = found ? 1 : 0;
        }
      }
    });
  }

  vtkIdType nContrast = 0, nCandidates = 0;
  for (vtkIdType v = 0; v < nVoxels; ++v)
  {
    nContrast += contrast[v];
    for (vtkIdType e = start[v]; e < start[v + 1]; ++e)
    {
      const int32_t id = keyed[e].second;
      candidate[id] = keep[v];
      nCandidates += keep[v];
      if (voxelCount)
      {
        voxelCount[id] = grid.Counts[v];
      }
    }
  }
  this->NumberOfContrastVoxels = nContrast;
  this->NumberOfCandidates = nCandidates;
  if (clamped > 0)
  {
    vtkWarningMacro(<< clamped << " point(s) lie more than 2^20 voxels (" << (KeyRange / 2) * a
                    << " units) from the cloud's median point and were clamped to the voxel grid's "
                       "border: outliers stretch the bounding box.");
  }
  return nCandidates;
}

bool vtkVoxelDensityContrastFilter::SampleShowsContrast(vtkPointCloudNeighborhoods* neighborhoods)
{
  if (this->ContrastRule != BLOCK_SPACING || !neighborhoods)
  {
    return true;
  }
  vtkPoints* points = neighborhoods->GetPoints();
  const unsigned char* valid = neighborhoods->GetValidMask();
  const vtkIdType n = neighborhoods->GetNumberOfPoints();
  const vtkIdType m = neighborhoods->GetNumberOfValidPoints();
  const double* b = neighborhoods->GetBounds();
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
      sampled[i] = featurepoints::InSampledRegion(x, origin, side, SampleModulus) ? 1 : 0;
    }
  });
  std::vector<vtkIdType> ids;
  for (vtkIdType i = 0; i < n; ++i)
  {
    if (sampled[i])
    {
      ids.push_back(i);
    }
  }
  if (static_cast<vtkIdType>(ids.size()) < MinimumSample)
  {
    return true;
  }
  // Kept by `neighborhoods`: the full test's 1-nearest pass will not search these points again.
  std::vector<double> found;
  neighborhoods->FindNearestDistances(ids, found);
  // The sample's mean spacing, as vtkPointCloudNeighborhoods measures the cloud's: coincident
  // points and isolated outliers (over 10 times the median) left out.
  std::vector<double> positive;
  for (double v : found)
  {
    if (v > 0.0)
    {
      positive.push_back(v);
    }
  }
  if (positive.empty())
  {
    return true;
  }
  auto mid = positive.begin() + positive.size() / 2;
  std::nth_element(positive.begin(), mid, positive.end());
  const double limit = 10.0 * *mid;
  double sum = 0.0;
  vtkIdType count = 0;
  for (double v : found)
  {
    if (v > 0.0 && v <= limit)
    {
      sum += v;
      ++count;
    }
  }
  std::vector<double> nearest(n, 0.0);
  for (size_t r = 0; r < ids.size(); ++r)
  {
    nearest[ids[r]] = found[r];
  }
  std::vector<unsigned char> candidate(n, 0);
  this->MarkCandidates(points, sampled.data(), sum / count, nearest.data(), candidate.data());
  return this->NumberOfContrastVoxels > 0;
}

int vtkVoxelDensityContrastFilter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet");
  return 1;
}

int vtkVoxelDensityContrastFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPointSet* input = vtkPointSet::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  if (!input || !output)
  {
    return 0;
  }
  const vtkIdType n = input->GetNumberOfPoints();
  vtkNew<vtkUnsignedCharArray> candidate;
  candidate->SetName("Candidate");
  candidate->SetNumberOfValues(n);
  vtkNew<vtkIntArray> counts;
  counts->SetName("VoxelPointCount");
  counts->SetNumberOfValues(n);
  std::fill_n(candidate->GetPointer(0), n, 0);
  std::fill_n(counts->GetPointer(0), n, 0);

  if (n > 0)
  {
    vtkNew<vtkPointCloudNeighborhoods> neighborhoods;
    if (!neighborhoods->Build(input->GetPoints()))
    {
      vtkErrorMacro(<< "Cannot voxelize the input: " << neighborhoods->GetErrorText() << ".");
    }
    else
    {
      if (neighborhoods->GetFirstInvalidPoint() >= 0)
      {
        vtkWarningMacro(<< n - neighborhoods->GetNumberOfValidPoints()
                        << " point(s) have NaN or infinite coordinates (the first is point "
                        << neighborhoods->GetFirstInvalidPoint() << "); they are never candidates.");
      }
      const double mean = neighborhoods->ComputeMeanSpacing();
      const double d = this->Spacing > 0.0 ? this->Spacing : mean;
      if (d > 0.0)
      {
        this->MarkCandidates(input->GetPoints(), neighborhoods->GetValidMask(), d,
          neighborhoods->GetNearestDistances().data(), candidate->GetPointer(0),
          counts->GetPointer(0));
      }
      else
      {
        vtkWarningMacro("All points coincide: the point spacing is 0 and no voxel grid can be built.");
      }
    }
  }

  output->SetPoints(input->GetPoints());
  output->GetPointData()->PassData(input->GetPointData());
  output->SetVerts(vtkPointCloudNeighborhoods::MakeVertexCells(n));
  output->GetPointData()->AddArray(candidate);
  output->GetPointData()->AddArray(counts);
  return 1;
}

void vtkVoxelDensityContrastFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "VoxelSizeFactor: " << this->VoxelSizeFactor << "\n";
  os << indent << "Spacing: " << this->Spacing << "\n";
  os << indent << "DensityContrast: " << this->DensityContrast << "\n";
  os << indent << "ContrastSigmas: " << this->ContrastSigmas << "\n";
  os << indent << "ContrastRule: " << this->ContrastRule << "\n";
  os << indent << "MinimumContrastFraction: " << this->MinimumContrastFraction << "\n";
}

vtkIdType vtkVoxelDensityContrastFilter::MarkCandidates(vtkPoints* points,
  vtkUnsignedCharArray* valid, double spacing, vtkDoubleArray* nearest,
  vtkUnsignedCharArray* candidate, vtkIntArray* voxelCount)
{
  const vtkIdType n = points ? points->GetNumberOfPoints() : 0;
  if (!candidate || (valid && valid->GetNumberOfValues() != n) ||
    (nearest && nearest->GetNumberOfValues() != n))
  {
    vtkErrorMacro(<< "MarkCandidates: valid and nearest need one value per point (" << n
                  << "), and candidate an array to fill");
    return -1;
  }
  candidate->SetNumberOfComponents(1);
  candidate->SetNumberOfValues(n);
  if (voxelCount)
  {
    voxelCount->SetNumberOfComponents(1);
    voxelCount->SetNumberOfValues(n);
  }
  return this->MarkCandidates(points, valid ? valid->GetPointer(0) : nullptr, spacing,
    nearest ? nearest->GetPointer(0) : nullptr, candidate->GetPointer(0),
    voxelCount ? voxelCount->GetPointer(0) : nullptr);
}
