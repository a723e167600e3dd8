#include "vtkDistributedFeaturePoints.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkFeaturePointDetector.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkMath.h"
#include "vtkMPI.h"
#include "vtkMPICommunicator.h"
#include "vtkMultiProcessController.h"
#include "vtkMultiProcessStream.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointCloudNeighborhoods.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <cstring>
#include <numeric>
#include <string>
#include <unordered_map>
#include <vector>

vtkStandardNewMacro(vtkDistributedFeaturePoints);
vtkCxxSetObjectMacro(vtkDistributedFeaturePoints, Detector, vtkFeaturePointDetector);
vtkCxxSetObjectMacro(vtkDistributedFeaturePoints, Controller, vtkMultiProcessController);

namespace
{
// The sample of the split: about this many points of the whole cloud.
constexpr long long SampleTarget = 100000;
// The spacing estimate's margin for the halo width a detector asks for.
constexpr double SpacingMargin = 1.25;
// Cells per axis of the grid whose cells' boxes, widened by their points' reach, make the halo.
constexpr int HaloCells = 8;
// Rows of the nearest-point searches done at a time.
constexpr size_t BlockSize = 65536;

// What a row of the cloud holds besides its global id: the coordinates' type and the point
// arrays (name, type, components), the same on every process.
struct Layout
{
  int PointType = VTK_FLOAT;
  std::vector<std::string> Names;
  std::vector<int> Types;
  std::vector<int> Components;

  size_t RowBytes() const
  {
    size_t bytes = sizeof(long long) +
      3 * static_cast<size_t>(vtkDataArray::GetDataTypeSize(this->PointType));
    for (size_t a = 0; a < this->Names.size(); ++a)
    {
      bytes += static_cast<size_t>(vtkDataArray::GetDataTypeSize(this->Types[a])) *
        this->Components[a];
    }
    return bytes;
  }

  void Save(vtkMultiProcessStream& s) const
  {
    s << this->PointType << static_cast<int>(this->Names.size());
    for (size_t a = 0; a < this->Names.size(); ++a)
    {
      s << this->Names[a] << this->Types[a] << this->Components[a];
    }
  }

  void Load(vtkMultiProcessStream& s)
  {
    int count = 0;
    s >> this->PointType >> count;
    this->Names.resize(count);
    this->Types.resize(count);
    this->Components.resize(count);
    for (int a = 0; a < count; ++a)
    {
      s >> this->Names[a] >> this->Types[a] >> this->Components[a];
    }
  }
};

// Points with their global ids and point arrays, as the layout says.
struct Rows
{
  std::vector<long long> Gid;
  vtkSmartPointer<vtkPoints> Points;
  std::vector<vtkSmartPointer<vtkDataArray>> Arrays;

  void Allocate(const Layout& layout, vtkIdType n)
  {
    this->Gid.assign(n, 0);
    this->Points = vtkSmartPointer<vtkPoints>::New();
    this->Points->SetDataType(layout.PointType);
    this->Points->SetNumberOfPoints(n);
    this->Arrays.clear();
    for (size_t a = 0; a < layout.Names.size(); ++a)
    {
      vtkSmartPointer<vtkDataArray> array =
        vtkSmartPointer<vtkDataArray>::Take(vtkDataArray::CreateDataArray(layout.Types[a]));
      array->SetName(layout.Names[a].c_str());
      array->SetNumberOfComponents(layout.Components[a]);
      array->SetNumberOfTuples(n);
      this->Arrays.push_back(array);
    }
  }

  vtkIdType Size() const { return static_cast<vtkIdType>(this->Gid.size()); }

  void Pack(vtkIdType i, unsigned char* out) const
  {
    std::memcpy(out, &this->Gid[i], sizeof(long long));
    out += sizeof(long long);
    vtkDataArray* p = this->Points->GetData();
    const size_t pb = 3 * static_cast<size_t>(p->GetDataTypeSize());
    std::memcpy(out, static_cast<unsigned char*>(p->GetVoidPointer(0)) + pb * i, pb);
    out += pb;
    for (const auto& a : this->Arrays)
    {
      const size_t b = static_cast<size_t>(a->GetDataTypeSize()) * a->GetNumberOfComponents();
      std::memcpy(out, static_cast<unsigned char*>(a->GetVoidPointer(0)) + b * i, b);
      out += b;
    }
  }

  void Unpack(vtkIdType i, const unsigned char* in)
  {
    std::memcpy(&this->Gid[i], in, sizeof(long long));
    in += sizeof(long long);
    vtkDataArray* p = this->Points->GetData();
    const size_t pb = 3 * static_cast<size_t>(p->GetDataTypeSize());
    std::memcpy(static_cast<unsigned char*>(p->GetVoidPointer(0)) + pb * i, in, pb);
    in += pb;
    for (const auto& a : this->Arrays)
    {
      const size_t b = static_cast<size_t>(a->GetDataTypeSize()) * a->GetNumberOfComponents();
      std::memcpy(static_cast<unsigned char*>(a->GetVoidPointer(0)) + b * i, in, b);
      in += b;
    }
  }

  // Copies of the rows `order` lists, in that order.
  Rows Select(const Layout& layout, const std::vector<vtkIdType>& order) const
  {
    Rows out;
    out.Allocate(layout, static_cast<vtkIdType>(order.size()));
    std::vector<unsigned char> row(layout.RowBytes());
    for (size_t j = 0; j < order.size(); ++j)
    {
      this->Pack(order[j], row.data());
      out.Unpack(static_cast<vtkIdType>(j), row.data());
    }
    return out;
  }

  // A vtkPolyData of the rows (sharing their arrays), one vertex cell each unless `verts` is
  // false.
  vtkSmartPointer<vtkPolyData> ToPolyData(bool verts = true) const
  {
    auto poly = vtkSmartPointer<vtkPolyData>::New();
    poly->SetPoints(this->Points);
    for (const auto& a : this->Arrays)
    {
      poly->GetPointData()->AddArray(a);
    }
    if (verts)
    {
      poly->SetVerts(vtkPointCloudNeighborhoods::MakeVertexCells(this->Size()));
    }
    return poly;
  }
};

// The layout of a point set's arrays (vtkDataArray only; vtkGhostType left out).
Layout LayoutOf(vtkPointSet* data)
{
  Layout layout;
  layout.PointType = data->GetPoints() ? data->GetPoints()->GetDataType() : VTK_FLOAT;
  vtkPointData* pd = data->GetPointData();
  for (int a = 0; a < pd->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = pd->GetArray(a);
    if (!array || !array->GetName() ||
      std::strcmp(array->GetName(), vtkDataSetAttributes::GhostArrayName()) == 0)
    {
      continue;
    }
    layout.Names.emplace_back(array->GetName());
    layout.Types.push_back(array->GetDataType());
    layout.Components.push_back(array->GetNumberOfComponents());
  }
  return layout;
}

// The rows of a point set, their global ids from `firstGid` on, sharing its points and arrays
// (the rows are only read); false (and `error`) when it lacks an array of the layout.
bool RowsOf(
  vtkPointSet* data, const Layout& layout, long long firstGid, Rows& rows, std::string& error)
{
  const vtkIdType n = data->GetNumberOfPoints();
  rows.Allocate(layout, 0);
  rows.Gid.resize(n);
  if (n == 0)
  {
    return true;
  }
  std::iota(rows.Gid.begin(), rows.Gid.end(), firstGid);
  if (data->GetPoints()->GetDataType() == layout.PointType)
  {
    rows.Points = data->GetPoints();
  }
  else
  {
    rows.Points->GetData()->DeepCopy(data->GetPoints()->GetData()); // to the first piece's type
  }
  for (size_t a = 0; a < layout.Names.size(); ++a)
  {
    vtkDataArray* array = data->GetPointData()->GetArray(layout.Names[a].c_str());
    if (!array || array->GetDataType() != layout.Types[a] ||
      array->GetNumberOfComponents() != layout.Components[a] || array->GetNumberOfTuples() != n)
    {
      error = "point array " + layout.Names[a] + " differs from the first piece's";
      return false;
    }
    rows.Arrays[a] = array;
  }
  return true;
}

MPI_Comm CommOf(vtkMultiProcessController* controller)
{
  auto* communicator = vtkMPICommunicator::SafeDownCast(controller->GetCommunicator());
  return communicator ? *communicator->GetMPIComm()->GetHandle() : MPI_COMM_NULL;
}

// True on every process when `ok` holds on all of them (a collective: every process calls it).
bool AllAgree(MPI_Comm comm, bool ok)
{
  int mine = ok ? 1 : 0, all = 0;
  MPI_Allreduce(&mine, &all, 1, MPI_INT, MPI_MIN, comm);
  return all != 0;
}

// Each process sends rows[send[q]] to process q; returns what it receives, by source process.
// A collective: false on every process when any one's buffers would pass 2 GB (MPI's int
// counts), so that none waits in an exchange the others left.
bool Exchange(MPI_Comm comm, const Layout& layout, const Rows& rows,
  const std::vector<std::vector<vtkIdType>>& send, Rows& received)
{
  int nProcs = 0;
  MPI_Comm_size(comm, &nProcs);
  const size_t rowBytes = layout.RowBytes();
  std::vector<int> sendCounts(nProcs), sendOffsets(nProcs), recvCounts(nProcs), recvOffsets(nProcs);
  long long total = 0;
  bool fits = true;
  for (int q = 0; q < nProcs && fits; ++q)
  {
    const long long bytes = static_cast<long long>(send[q].size() * rowBytes);
    fits = bytes <= INT_MAX && total + bytes <= INT_MAX;
    sendCounts[q] = fits ? static_cast<int>(bytes) : 0;
    sendOffsets[q] = fits ? static_cast<int>(total) : 0;
    total += fits ? bytes : 0;
  }
  if (!AllAgree(comm, fits))
  {
    return false;
  }
  std::vector<unsigned char> out(std::max<long long>(total, 1));
  for (int q = 0; q < nProcs; ++q)
  {
    unsigned char* at = out.data() + sendOffsets[q];
    for (vtkIdType i : send[q])
    {
      rows.Pack(i, at);
      at += rowBytes;
    }
  }
  MPI_Alltoall(sendCounts.data(), 1, MPI_INT, recvCounts.data(), 1, MPI_INT, comm);
  long long totalIn = 0;
  for (int q = 0; q < nProcs && fits; ++q)
  {
    fits = totalIn + recvCounts[q] <= INT_MAX;
    recvOffsets[q] = fits ? static_cast<int>(totalIn) : 0;
    totalIn += fits ? recvCounts[q] : 0;
  }
  if (!AllAgree(comm, fits))
  {
    return false;
  }
  std::vector<unsigned char> in(std::max<long long>(totalIn, 1));
  MPI_Alltoallv(out.data(), sendCounts.data(), sendOffsets.data(), MPI_BYTE, in.data(),
    recvCounts.data(), recvOffsets.data(), MPI_BYTE, comm);
  const vtkIdType n = static_cast<vtkIdType>(totalIn / static_cast<long long>(rowBytes));
  received.Allocate(layout, n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    received.Unpack(i, in.data() + rowBytes * i);
  }
  return true;
}

// All rows on process 0, in global id order (the ids run from 0 to their count minus 1); `rows`
// is emptied once packed.
bool GatherInOrder(MPI_Comm comm, const Layout& layout, Rows& rows, Rows& all)
{
  int nProcs = 0, rank = 0;
  MPI_Comm_size(comm, &nProcs);
  MPI_Comm_rank(comm, &rank);
  const size_t rowBytes = layout.RowBytes();
  const long long bytes = static_cast<long long>(rows.Size()) * static_cast<long long>(rowBytes);
  int ok = bytes <= INT_MAX ? 1 : 0;
  std::vector<unsigned char> out(std::max<long long>(ok ? bytes : 1, 1));
  for (vtkIdType i = 0; i < rows.Size() && ok; ++i)
  {
    rows.Pack(i, out.data() + rowBytes * i);
  }
  rows = Rows();
  int count = ok ? static_cast<int>(bytes) : 0;
  std::vector<int> counts(nProcs), offsets(nProcs);
  MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, comm);
  long long total = 0;
  if (rank == 0)
  {
    for (int q = 0; q < nProcs; ++q)
    {
      offsets[q] = static_cast<int>(std::min<long long>(total, INT_MAX));
      total += counts[q];
    }
    ok = ok && total <= INT_MAX;
  }
  if (!AllAgree(comm, ok != 0))
  {
    return false;
  }
  std::vector<unsigned char> in(rank == 0 ? std::max<long long>(total, 1) : 1);
  MPI_Gatherv(out.data(), count, MPI_BYTE, in.data(), counts.data(), offsets.data(), MPI_BYTE, 0,
    comm);
  std::vector<unsigned char>().swap(out);
  if (rank != 0)
  {
    all.Allocate(layout, 0);
    return true;
  }
  // Each row straight to its place: its global id.
  const vtkIdType n = static_cast<vtkIdType>(total / static_cast<long long>(rowBytes));
  all.Allocate(layout, n);
  std::vector<unsigned char> placed(static_cast<size_t>(n), 0);
  for (vtkIdType i = 0; i < n; ++i)
  {
    long long gid = -1;
    std::memcpy(&gid, in.data() + rowBytes * i, sizeof(gid));
    if (gid < 0 || gid >= n || placed[gid])
    {
      return false; // not a numbering of the rows: never so for the pieces of one cloud
    }
    placed[gid] = 1;
    all.Unpack(static_cast<vtkIdType>(gid), in.data() + rowBytes * i);
  }
  return true;
}

// The k-d split of the sample: node i splits on Axis at Value (below: Left, else Right), or is
// the leaf of process Rank.
struct SplitNode
{
  int Axis = 0;
  double Value = 0.0;
  int Left = -1;
  int Right = -1;
  int Rank = -1;
};

int BuildSplit(std::vector<SplitNode>& nodes, const std::vector<double>& sample,
  std::vector<vtkIdType>& ids, size_t lo, size_t hi, int firstRank, int ranks)
{
  const int node = static_cast<int>(nodes.size());
  nodes.emplace_back();
  if (ranks == 1)
  {
    nodes[node].Rank = firstRank;
    return node;
  }
  double boxLo[3] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, VTK_DOUBLE_MAX };
  double boxHi[3] = { -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
  for (size_t r = lo; r < hi; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      boxLo[c] = std::min(boxLo[c], sample[3 * ids[r] + c]);
      boxHi[c] = std::max(boxHi[c], sample[3 * ids[r] + c]);
    }
  }
  int axis = 0;
  for (int c = 1; c < 3; ++c)
  {
    if (boxHi[c] - boxLo[c] > boxHi[axis] - boxLo[axis])
    {
      axis = c;
    }
  }
  const int leftRanks = ranks / 2;
  // The left part gets leftRanks / ranks of the sample; ties by sample index keep it the same on
  // every process.
  const size_t mid = lo + (hi - lo) * static_cast<size_t>(leftRanks) / static_cast<size_t>(ranks);
  double value = 0.0;
  if (hi > lo)
  {
    auto less = [&](vtkIdType a, vtkIdType b) {
      const double xa = sample[3 * a + axis], xb = sample[3 * b + axis];
      return xa < xb || (xa == xb && a < b);
    };
    std::nth_element(ids.begin() + lo, ids.begin() + std::min(mid, hi - 1), ids.begin() + hi, less);
    value = sample[3 * ids[std::min(mid, hi - 1)] + axis];
  }
  nodes[node].Axis = axis;
  nodes[node].Value = value;
  // The sample below the value goes left (points equal to it go right, as in Owner()).
  std::vector<vtkIdType> below, above;
  for (size_t r = lo; r < hi; ++r)
  {
    (sample[3 * ids[r] + axis] < value ? below : above).push_back(ids[r]);
  }
  std::copy(below.begin(), below.end(), ids.begin() + lo);
  std::copy(above.begin(), above.end(), ids.begin() + lo + below.size());
  const size_t split = lo + below.size();
  const int left = BuildSplit(nodes, sample, ids, lo, split, firstRank, leftRanks);
  const int right =
    BuildSplit(nodes, sample, ids, split, hi, firstRank + leftRanks, ranks - leftRanks);
  nodes[node].Left = left;
  nodes[node].Right = right;
  return node;
}

int Owner(const std::vector<SplitNode>& nodes, const double x[3])
{
  int node = 0;
  while (nodes[node].Rank < 0)
  {
    node = x[nodes[node].Axis] < nodes[node].Value ? nodes[node].Left : nodes[node].Right;
  }
  return nodes[node].Rank;
}

// The box of process `rank` in the split: lo <= x < hi on each axis (infinite outside).
void LeafRegion(const std::vector<SplitNode>& nodes, int rank, double region[6])
{
  for (int c = 0; c < 3; ++c)
  {
    region[2 * c] = -VTK_DOUBLE_MAX;
    region[2 * c + 1] = VTK_DOUBLE_MAX;
  }
  // Processes [first, first + count) lie under a node; its left child has count / 2 of them.
  int node = 0, first = 0, count = 0;
  for (const SplitNode& n : nodes)
  {
    count += n.Rank >= 0 ? 1 : 0;
  }
  while (nodes[node].Rank < 0)
  {
    const int left = count / 2;
    const SplitNode& n = nodes[node];
    if (rank < first + left)
    {
      region[2 * n.Axis + 1] = std::min(region[2 * n.Axis + 1], n.Value);
      node = n.Left;
      count = left;
    }
    else
    {
      region[2 * n.Axis] = std::max(region[2 * n.Axis], n.Value);
      node = n.Right;
      first += left;
      count -= left;
    }
  }
}

// 1 for the valid points whose reach (factor times the distance to their k-th nearest point, or
// to their nearest point at a nonzero distance if further), or whose box of half-width `width`,
// may leave `region`. Two bounds, each for a whole cell of a sparse grid of cells of side c (a
// sample's median k-th nearest distance):
// - a point's k nearest lie within the block of (2m + 1)^3 cells around its cell once the block
//   holds k + 1 points at two places at least, so within sqrt(3) (m + 1) c of it (a block of 27
//   cells mostly suffices, so this bound costs little);
// - in a cell that bound does not keep inside, one point y gets its exact k-th nearest distance
//   r(y), and each other point x the bound r(y) + |x - y|.
// At 10,000,000 points split in 2, the second bound leaves about 2 % of a process's points to the
// exact search where the first left up to a third.
std::vector<unsigned char> NearRegionBorder(vtkPointCloudNeighborhoods* neighborhoods,
  vtkPoints* points, const std::vector<vtkIdType>& valid, int k, double factor,
  const double region[6], double width)
{
  const vtkIdType n = points->GetNumberOfPoints();
  std::vector<unsigned char> near(n, 0);
  for (vtkIdType i : valid)
  {
    near[i] = 1;
  }
  if (static_cast<vtkIdType>(valid.size()) < 64 * static_cast<vtkIdType>(k + 1))
  {
    return near; // small piece: every point gets the exact reach
  }
  // The cell side from a sample's k-th nearest distances.
  std::vector<vtkIdType> sample;
  const size_t stride = std::max<size_t>(1, valid.size() / 1000);
  for (size_t r = 0; r < valid.size(); r += stride)
  {
    sample.push_back(valid[r]);
  }
  std::vector<int32_t> table;
  neighborhoods->FindNearestNeighbors(k, sample, table);
  std::vector<double> radii;
  double x[3], y[3];
  for (size_t r = 0; r < sample.size(); ++r)
  {
    const int32_t last = table[r * k + k - 1];
    if (last >= 0)
    {
      points->GetPoint(sample[r], x);
      points->GetPoint(last, y);
      radii.push_back(std::sqrt(vtkMath::Distance2BetweenPoints(x, y)));
    }
  }
  if (radii.empty())
  {
    return near;
  }
  std::nth_element(radii.begin(), radii.begin() + radii.size() / 2, radii.end());
  const double side = radii[radii.size() / 2];
  const double* b = neighborhoods->GetBounds();
  constexpr int64_t Range = int64_t(1) << 20;
  for (int c = 0; c < 3; ++c)
  {
    if (!(side > 0.0) || (b[2 * c + 1] - b[2 * c]) / side >= static_cast<double>(Range - 1))
    {
      return near;
    }
  }
  struct Cell
  {
    vtkIdType Count = 0;
    bool Interior = false; // every point's reach stays inside the region
    double Box[6] = { VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX,
      VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
    vtkIdType Representative = -1; // see below
    double Radius = 0.0;
  };
  auto keyOf = [&](const int64_t ijk[3]) { return (ijk[0] * Range + ijk[1]) * Range + ijk[2]; };
  std::unordered_map<int64_t, vtkIdType> index; // a cell's key to its place in `cells`
  std::vector<Cell> cells;
  std::vector<int64_t> keys;      // by cell
  std::vector<vtkIdType> cellOf(n, -1); // by point
  for (vtkIdType i : valid)
  {
    points->GetPoint(i, x);
    int64_t ijk[3];
    for (int c = 0; c < 3; ++c)
    {
      ijk[c] = static_cast<int64_t>(std::floor((x[c] - b[2 * c]) / side));
    }
    const int64_t key = keyOf(ijk);
    auto added = index.emplace(key, static_cast<vtkIdType>(cells.size()));
    if (added.second)
    {
      cells.emplace_back();
      keys.push_back(key);
    }
    cellOf[i] = added.first->second;
    Cell& cell = cells[cellOf[i]];
    ++cell.Count;
    for (int c = 0; c < 3; ++c)
    {
      cell.Box[2 * c] = std::min(cell.Box[2 * c], x[c]);
      cell.Box[2 * c + 1] = std::max(cell.Box[2 * c + 1], x[c]);
    }
  }
  constexpr int MaximumRings = 4;
  for (size_t e = 0; e < cells.size(); ++e)
  {
    const int64_t key = keys[e];
    const int64_t ijk[3] = { key / (Range * Range), (key / Range) % Range, key % Range };
    vtkIdType count = 0;
    double box[6] = { VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX,
      VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
    int rings = -1;
    for (int m = 0; m <= MaximumRings; ++m)
    {
      // The shell of the block at Chebyshev distance m.
      for (int64_t di = -m; di <= m; ++di)
      {
        for (int64_t dj = -m; dj <= m; ++dj)
        {
          for (int64_t dk = -m; dk <= m; ++dk)
          {
            if (std::max({ std::abs(di), std::abs(dj), std::abs(dk) }) != m)
            {
              continue;
            }
            const int64_t other[3] = { ijk[0] + di, ijk[1] + dj, ijk[2] + dk };
            if (other[0] < 0 || other[1] < 0 || other[2] < 0)
            {
              continue;
            }
            auto found = index.find(keyOf(other));
            if (found == index.end())
            {
              continue;
            }
            const Cell& near = cells[found->second];
            count += near.Count;
            for (int c = 0; c < 3; ++c)
            {
              box[2 * c] = std::min(box[2 * c], near.Box[2 * c]);
              box[2 * c + 1] = std::max(box[2 * c + 1], near.Box[2 * c + 1]);
            }
          }
        }
      }
      const bool twoPlaces = box[1] > box[0] || box[3] > box[2] || box[5] > box[4];
      if (count >= k + 1 && twoPlaces)
      {
        rings = m;
        break;
      }
    }
    if (rings < 0)
    {
      continue; // the exact reach decides
    }
    const double bound =
      std::max(factor * std::sqrt(3.0) * (rings + 1) * side * (1.0 + 1e-9), width);
    const double* own = cells[e].Box;
    bool inside = true;
    for (int c = 0; c < 3 && inside; ++c)
    {
      inside = own[2 * c] - bound > region[2 * c] && own[2 * c + 1] + bound < region[2 * c + 1];
    }
    cells[e].Interior = inside;
  }
  // In the other cells, one point's exact reach bounds the others': the distance to the k-th
  // nearest grows by at most the distance moved, r(x) <= r(y) + |x - y| (and where x's k nearest
  // coincide with it, y is a point at a nonzero distance from x within that bound).
  std::vector<vtkIdType> representatives;
  for (vtkIdType i : valid)
  {
    Cell& cell = cells[cellOf[i]];
    if (!cell.Interior && cell.Representative < 0)
    {
      cell.Representative = i;
      representatives.push_back(i);
    }
  }
  for (size_t start = 0; start < representatives.size(); start += BlockSize)
  {
    const std::vector<vtkIdType> block(representatives.begin() + start,
      representatives.begin() + std::min(representatives.size(), start + BlockSize));
    neighborhoods->FindNearestNeighbors(k, block, table);
    for (size_t r = 0; r < block.size(); ++r)
    {
      const int32_t last = table[r * k + k - 1];
      if (last >= 0)
      {
        points->GetPoint(block[r], x);
        points->GetPoint(last, y);
        cells[cellOf[block[r]]].Radius = std::sqrt(vtkMath::Distance2BetweenPoints(x, y));
      }
    }
  }
  for (vtkIdType i : valid)
  {
    const Cell& cell = cells[cellOf[i]];
    if (cell.Interior)
    {
      near[i] = 0;
      continue;
    }
    if (!(cell.Radius > 0.0))
    {
      continue; // the exact reach decides
    }
    points->GetPoint(i, x);
    points->GetPoint(cell.Representative, y);
    const double bound = std::max(
      factor * (cell.Radius + std::sqrt(vtkMath::Distance2BetweenPoints(x, y))) * (1.0 + 1e-9),
      width);
    bool inside = true;
    for (int c = 0; c < 3 && inside; ++c)
    {
      inside = x[c] - bound > region[2 * c] && x[c] + bound < region[2 * c + 1];
    }
    near[i] = inside ? 0 : 1;
  }
  return near;
}

bool Finite(const double x[3])
{
  return std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]);
}

// An estimate of the cloud's mean spacing from a sample of a piece's own points: their distance to
// the nearest own point is at least their distance to the nearest point of the cloud, so this is
// an estimate from above (the processes take the largest).
double EstimateSpacing(vtkPointCloudNeighborhoods* neighborhoods, const std::vector<vtkIdType>& valid)
{
  std::vector<vtkIdType> sample;
  const size_t stride = std::max<size_t>(1, valid.size() / 4096);
  for (size_t r = 0; r < valid.size(); r += stride)
  {
    sample.push_back(valid[r]);
  }
  std::vector<int32_t> table;
  std::vector<double> distances;
  neighborhoods->FindNearestNeighbors(1, sample, table, &distances);
  std::vector<double> positive;
  for (double d : distances)
  {
    if (d > 0.0 && std::isfinite(d))
    {
      positive.push_back(d);
    }
  }
  if (positive.empty())
  {
    return 0.0;
  }
  // The mean without isolated points (over 10 times the median), as the detectors take it.
  std::vector<double> sorted(positive);
  std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
  const double limit = 10.0 * sorted[sorted.size() / 2];
  double sum = 0.0;
  size_t count = 0;
  for (double d : positive)
  {
    if (d <= limit)
    {
      sum += d;
      ++count;
    }
  }
  return sum / static_cast<double>(count);
}
// Every process's `local` values, concatenated in process order, on every process; `lengths` and
// `offsets` receive where each process's values lie.
std::vector<double> AllGatherValues(vtkMultiProcessController* controller,
  std::vector<double>& local, std::vector<vtkIdType>& lengths, std::vector<vtkIdType>& offsets)
{
  const int nProcs = controller->GetNumberOfProcesses();
  long long size = static_cast<long long>(local.size());
  std::vector<long long> sizes(nProcs, 0);
  controller->AllGather(&size, sizes.data(), 1);
  lengths.assign(nProcs, 0);
  offsets.assign(nProcs, 0);
  vtkIdType total = 0;
  for (int q = 0; q < nProcs; ++q)
  {
    lengths[q] = static_cast<vtkIdType>(sizes[q]);
    offsets[q] = total;
    total += lengths[q];
  }
  std::vector<double> all(std::max<vtkIdType>(total, 1));
  controller->AllGatherV(
    local.data(), all.data(), static_cast<vtkIdType>(local.size()), lengths.data(), offsets.data());
  all.resize(static_cast<size_t>(total));
  return all;
}

} // namespace

vtkDistributedFeaturePoints::vtkDistributedFeaturePoints()
{
  this->SetController(vtkMultiProcessController::GetGlobalController());
}

vtkDistributedFeaturePoints::~vtkDistributedFeaturePoints()
{
  this->SetDetector(nullptr);
  this->SetController(nullptr);
}

vtkMTimeType vtkDistributedFeaturePoints::GetMTime()
{
  vtkMTimeType t = this->Superclass::GetMTime();
  if (this->Detector)
  {
    t = std::max(t, this->Detector->GetMTime());
  }
  return t;
}

int vtkDistributedFeaturePoints::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet");
  return 1;
}

int vtkDistributedFeaturePoints::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPointSet* input = vtkPointSet::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  if (!input || !output)
  {
    return 0;
  }
  if (!this->Detector)
  {
    vtkErrorMacro("No detector: call SetDetector() first.");
    return 0;
  }
  vtkFeaturePointDetector* detector = this->Detector;
  vtkMultiProcessController* controller = this->Controller;
  const int nProcs = controller ? controller->GetNumberOfProcesses() : 1;
  const MPI_Comm comm = nProcs > 1 ? CommOf(controller) : MPI_COMM_NULL;
  this->OwnedCounts.assign(1, input->GetNumberOfPoints());
  this->HaloCounts.assign(1, 0);
  this->Distributed = false;
  this->ReplacedArrays.clear();
  const bool featuresOnly = detector->GetOutputFeaturesOnly();
  if (nProcs <= 1 || comm == MPI_COMM_NULL)
  {
    if (nProcs > 1)
    {
      vtkErrorMacro("The controller is not an MPI controller: cannot split the cloud.");
      return 0;
    }
    vtkMultiProcessController* saved = detector->GetController();
    if (saved)
    {
      saved->Register(this);
    }
    detector->SetController(nullptr);
    detector->SetInputData(input);
    detector->Update();
    detector->SetController(saved);
    if (saved)
    {
      saved->UnRegister(this);
    }
    output->ShallowCopy(detector->GetOutput());
    return 1;
  }
  const int rank = controller->GetLocalProcessId();

  // The cloud: the pieces in process order.
  long long localCount = input->GetNumberOfPoints();
  std::vector<long long> counts(nProcs, 0);
  controller->AllGather(&localCount, counts.data(), 1);
  std::vector<long long> firstGid(nProcs + 1, 0);
  for (int q = 0; q < nProcs; ++q)
  {
    firstGid[q + 1] = firstGid[q] + counts[q];
  }
  const long long total = firstGid[nProcs];
  int layoutRoot = 0;
  while (layoutRoot < nProcs - 1 && counts[layoutRoot] == 0)
  {
    ++layoutRoot;
  }
  Layout layout;
  {
    vtkMultiProcessStream stream;
    if (rank == layoutRoot)
    {
      LayoutOf(input).Save(stream);
    }
    controller->Broadcast(stream, layoutRoot);
    layout.Load(stream);
  }
  Rows mine;
  std::string error;
  int ok = RowsOf(input, layout, firstGid[rank], mine, error) ? 1 : 0;
  int allOk = 0;
  controller->AllReduce(&ok, &allOk, 1, vtkCommunicator::MIN_OP);
  if (!allOk)
  {
    vtkErrorMacro(<< "Cannot split the cloud: "
                  << (ok ? "another process's piece does not match" : error) << ".");
    return 0;
  }

  int k = 0, levels = 0;
  const bool supported = detector->GetHaloExtent(k, levels) && k > 0 && levels > 0;
  // Every piece needs enough points for its neighbourhoods (checked again after the split).
  bool split = supported && total >= 4LL * (k + 1) * nProcs;

  Rows own;
  std::vector<SplitNode> nodes;
  if (split)
  {
    // 1. The sample and the k-d split, the same on every process.
    const long long stride = std::max<long long>(1, total / SampleTarget);
    std::vector<double> local;
    double x[3];
    for (vtkIdType i = 0; i < mine.Size(); ++i)
    {
      if (mine.Gid[i] % stride == 0)
      {
        mine.Points->GetPoint(i, x);
        if (Finite(x))
        {
          local.insert(local.end(), x, x + 3);
        }
      }
    }
    std::vector<vtkIdType> lengths, offsets;
    std::vector<double> sample = AllGatherValues(controller, local, lengths, offsets);
    std::vector<vtkIdType> ids(sample.size() / 3);
    std::iota(ids.begin(), ids.end(), 0);
    BuildSplit(nodes, sample, ids, 0, ids.size(), 0, nProcs);

    // 2. Each point to the process of its box (non-finite points stay: they are never searched).
    std::vector<std::vector<vtkIdType>> send(nProcs);
    for (vtkIdType i = 0; i < mine.Size(); ++i)
    {
      mine.Points->GetPoint(i, x);
      send[Finite(x) ? Owner(nodes, x) : rank].push_back(i);
    }
    Rows received;
    if (!Exchange(comm, layout, mine, send, received))
    {
      vtkErrorMacro("Cannot split the cloud: a piece holds more than 2 GB.");
      return 0;
    }
    std::vector<vtkIdType> order(received.Size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(),
      [&](vtkIdType a, vtkIdType b) { return received.Gid[a] < received.Gid[b]; });
    own = received.Select(layout, order);
    mine = Rows();

    // Every piece must hold neighbourhoods of k points, or the cloud is not split.
    vtkIdType valid = 0;
    for (vtkIdType i = 0; i < own.Size(); ++i)
    {
      own.Points->GetPoint(i, x);
      valid += Finite(x) ? 1 : 0;
    }
    long long fewest = 0, enough = valid;
    controller->AllReduce(&enough, &fewest, 1, vtkCommunicator::MIN_OP);
    split = fewest >= 4LL * (k + 1);
    if (!split)
    {
      // Back to the input's pieces for the single-process run.
      std::vector<std::vector<vtkIdType>> home(nProcs);
      for (vtkIdType i = 0; i < own.Size(); ++i)
      {
        const int q = static_cast<int>(
          std::upper_bound(firstGid.begin(), firstGid.end(), own.Gid[i]) - firstGid.begin() - 1);
        home[q].push_back(i);
      }
      if (!Exchange(comm, layout, own, home, mine))
      {
        vtkErrorMacro("Cannot gather the cloud back: a piece holds more than 2 GB.");
        return 0;
      }
    }
  }

  if (!split)
  {
    // On process 0 alone, on the whole cloud in the input's order.
    Rows all;
    if (!GatherInOrder(comm, layout, mine, all))
    {
      vtkErrorMacro("Cannot gather the cloud on process 0: it holds more than 2 GB.");
      return 0;
    }
    this->OwnedCounts.assign(nProcs, 0);
    this->HaloCounts.assign(nProcs, 0);
    this->OwnedCounts[0] = total;
    int status = 1;
    if (rank == 0)
    {
      vtkMultiProcessController* saved = detector->GetController();
      if (saved)
      {
        saved->Register(this);
      }
      detector->SetController(nullptr);
      vtkSmartPointer<vtkPolyData> cloud = all.ToPolyData();
      detector->SetInputData(cloud);
      detector->Update();
      this->FindReplacedArrays(cloud, detector->GetOutput());
      detector->SetController(saved);
      if (saved)
      {
        saved->UnRegister(this);
      }
      output->ShallowCopy(detector->GetOutput());
    }
    controller->Broadcast(&status, 1, 0);
    return status;
  }
  this->Distributed = true;

  // The halo width the detector needs beyond its neighbourhoods (the paper's method's voxel
  // blocks, in units of the cloud's mean spacing): taken from an estimate of the spacing from
  // above, with a margin. A run that finds it too narrow says how wide it must be (the same on
  // every process), and the halo is built again.
  const double widthPerSpacing = detector->GetHaloWidthFor(1.0);
  double width = 0.0;
  Rows piece;
  vtkNew<vtkUnsignedCharArray> ghosts;
  vtkNew<vtkIdTypeArray> pieceGids;
  vtkSmartPointer<vtkPolyData> pieceData;
  vtkPolyData* result = nullptr;
  for (int attempt = 0;; ++attempt)
  {
    if (attempt > 0)
    {
      // The own rows again, from the piece: the detector ran without them.
      const vtkIdType n = pieceGids->GetNumberOfValues();
      piece.Gid.resize(n);
      std::vector<vtkIdType> ownRows;
      for (vtkIdType j = 0; j < n; ++j)
      {
        piece.Gid[j] = pieceGids->GetValue(j);
        if (ghosts->GetValue(j) == 0)
        {
          ownRows.push_back(j);
        }
      }
      own = piece.Select(layout, ownRows);
    }
    // 3. The reach of each own point, and the boxes of the halo.
    std::vector<double> boxes; // 6 per box: lo x, lo y, lo z, hi x, hi y, hi z
    {
      vtkNew<vtkPointCloudNeighborhoods> neighborhoods;
      neighborhoods->Build(own.Points);
      const std::vector<vtkIdType> valid = neighborhoods->GetValidIds();
      if (attempt == 0 && widthPerSpacing > 0.0)
      {
        double local = EstimateSpacing(neighborhoods, valid), largest = 0.0;
        controller->AllReduce(&local, &largest, 1, vtkCommunicator::MAX_OP);
        width = detector->GetHaloWidthFor(SpacingMargin * largest);
      }
      const double factor = std::ldexp(1.0, levels) - 1.0;
      double region[6];
      LeafRegion(nodes, rank, region);
      // Only the points whose reach may leave this process's region add to the halo: a cheap upper
      // bound of the reach rules out the others, and the rest get the exact one.
      const std::vector<unsigned char> nearBorder =
        NearRegionBorder(neighborhoods, own.Points, valid, k, factor, region, width);
      std::vector<vtkIdType> ids;
      for (vtkIdType i : valid)
      {
        if (nearBorder[i])
        {
          ids.push_back(i);
        }
      }
      std::vector<int32_t> table;
      const double* b = neighborhoods->GetBounds();
      double cell[3];
      for (int c = 0; c < 3; ++c)
      {
        cell[c] = std::max((b[2 * c + 1] - b[2 * c]) / HaloCells, 1e-300);
      }
      std::vector<double> cellBox(6 * HaloCells * HaloCells * HaloCells);
      for (size_t c = 0; c < cellBox.size(); c += 6)
      {
        std::fill_n(cellBox.begin() + c, 3, VTK_DOUBLE_MAX);
        std::fill_n(cellBox.begin() + c + 3, 3, -VTK_DOUBLE_MAX);
      }
      double x[3], y[3];
      for (size_t r = 0; r < ids.size(); ++r)
      {
        if (r % BlockSize == 0)
        {
          const std::vector<vtkIdType> block(
            ids.begin() + r, ids.begin() + std::min(ids.size(), r + BlockSize));
          neighborhoods->FindNearestNeighbors(k, block, table);
        }
        const vtkIdType i = ids[r];
        own.Points->GetPoint(i, x);
        // The distance to the k-th nearest own point, or, where the k nearest all coincide with
        // the point, to the nearest own point at a nonzero distance (the mean spacing needs it).
        // Unbounded when there is none.
        double radius = VTK_DOUBLE_MAX;
        const int32_t last = table[(r % BlockSize) * k + k - 1];
        if (last >= 0)
        {
          own.Points->GetPoint(last, y);
          radius = std::sqrt(vtkMath::Distance2BetweenPoints(x, y));
        }
        for (vtkIdType kk = 4 * static_cast<vtkIdType>(k); radius == 0.0; kk *= 4)
        {
          const vtkIdType n = static_cast<vtkIdType>(valid.size()) - 1;
          std::vector<int32_t> row;
          neighborhoods->FindNearestNeighbors(static_cast<int>(std::min(kk, n)), { i }, row);
          radius = VTK_DOUBLE_MAX;
          for (int32_t j : row)
          {
            own.Points->GetPoint(j, y);
            const double d = j >= 0 ? std::sqrt(vtkMath::Distance2BetweenPoints(x, y)) : 0.0;
            if (d > 0.0)
            {
              radius = d;
              break;
            }
          }
          if (radius == VTK_DOUBLE_MAX && kk < n)
          {
            radius = 0.0; // look further
          }
        }
        const double reach = radius == VTK_DOUBLE_MAX
          ? radius
          : std::max(factor * radius * (1.0 + 1e-12), width);
        int index = 0;
        for (int c = 2; c >= 0; --c)
        {
          const int j = std::min(HaloCells - 1,
            std::max(0, static_cast<int>(std::floor((x[c] - b[2 * c]) / cell[c]))));
          index = index * HaloCells + j;
        }
        double* box = cellBox.data() + 6 * index;
        for (int c = 0; c < 3; ++c)
        {
          box[c] = std::min(box[c], reach == VTK_DOUBLE_MAX ? -VTK_DOUBLE_MAX : x[c] - reach);
          box[3 + c] = std::max(box[3 + c], reach == VTK_DOUBLE_MAX ? VTK_DOUBLE_MAX : x[c] + reach);
        }
      }
      for (size_t c = 0; c < cellBox.size(); c += 6)
      {
        if (cellBox[c] <= cellBox[c + 3])
        {
          boxes.insert(boxes.end(), cellBox.begin() + c, cellBox.begin() + c + 6);
        }
      }
    }
    std::vector<vtkIdType> lengths, offsets;
    const std::vector<double> allBoxes = AllGatherValues(controller, boxes, lengths, offsets);

    // 4. The halo: each own point that falls in another process's boxes goes to it.
    std::vector<std::vector<vtkIdType>> send(nProcs);
    {
      double x[3];
      for (int q = 0; q < nProcs; ++q)
      {
        if (q == rank || lengths[q] == 0)
        {
          continue;
        }
        const double* qb = allBoxes.data() + offsets[q];
        const vtkIdType nb = lengths[q] / 6;
        double lo[3] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, VTK_DOUBLE_MAX };
        double hi[3] = { -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
        for (vtkIdType j = 0; j < nb; ++j)
        {
          for (int c = 0; c < 3; ++c)
          {
            lo[c] = std::min(lo[c], qb[6 * j + c]);
            hi[c] = std::max(hi[c], qb[6 * j + 3 + c]);
          }
        }
        auto inside = [](const double* p, const double* l, const double* h) {
          return p[0] >= l[0] && p[0] <= h[0] && p[1] >= l[1] && p[1] <= h[1] && p[2] >= l[2] &&
            p[2] <= h[2];
        };
        for (vtkIdType i = 0; i < own.Size(); ++i)
        {
          own.Points->GetPoint(i, x);
          if (!Finite(x) || !inside(x, lo, hi))
          {
            continue;
          }
          for (vtkIdType j = 0; j < nb; ++j)
          {
            if (inside(x, qb + 6 * j, qb + 6 * j + 3))
            {
              send[q].push_back(i);
              break;
            }
          }
        }
      }
    }
    Rows halo;
    if (!Exchange(comm, layout, own, send, halo))
    {
      vtkErrorMacro("Cannot build the halos: a piece holds more than 2 GB.");
      return 0;
    }
    long long figures[2] = { own.Size(), halo.Size() };
    std::vector<long long> allFigures(2 * nProcs);
    controller->AllGather(figures, allFigures.data(), 2);
    this->OwnedCounts.resize(nProcs);
    this->HaloCounts.resize(nProcs);
    for (int q = 0; q < nProcs; ++q)
    {
      this->OwnedCounts[q] = static_cast<vtkIdType>(allFigures[2 * q]);
      this->HaloCounts[q] = static_cast<vtkIdType>(allFigures[2 * q + 1]);
    }

    // 5. The piece: own points and halo in global id order, the halo flagged.
    piece = Rows();
    {
      const vtkIdType n = own.Size() + halo.Size();
      std::vector<std::pair<long long, vtkIdType>> order; // (gid, row; halo rows after own rows)
      order.reserve(n);
      for (vtkIdType i = 0; i < own.Size(); ++i)
      {
        order.emplace_back(own.Gid[i], i);
      }
      for (vtkIdType i = 0; i < halo.Size(); ++i)
      {
        order.emplace_back(halo.Gid[i], own.Size() + i);
      }
      std::sort(order.begin(), order.end());
      piece.Allocate(layout, n);
      ghosts->SetName(vtkDataSetAttributes::GhostArrayName());
      ghosts->SetNumberOfValues(n);
      pieceGids->SetName(vtkFeaturePointDetector::GetPieceGlobalIdsArrayName());
      pieceGids->SetNumberOfValues(n);
      std::vector<unsigned char> row(layout.RowBytes());
      for (vtkIdType j = 0; j < n; ++j)
      {
        const vtkIdType i = order[j].second;
        const bool isHalo = i >= own.Size();
        (isHalo ? halo : own).Pack(isHalo ? i - own.Size() : i, row.data());
        piece.Unpack(j, row.data());
        ghosts->SetValue(j, isHalo ? vtkDataSetAttributes::DUPLICATEPOINT : 0);
        pieceGids->SetValue(j, static_cast<vtkIdType>(order[j].first));
      }
    }
    halo = Rows();
    // The detector reads neither the own rows (the piece holds them), nor the piece's ids
    // (pieceGids holds them), nor vertex cells: none is kept while it runs.
    own = Rows();
    std::vector<long long>().swap(piece.Gid);
    pieceData = piece.ToPolyData(false);
    pieceData->GetPointData()->AddArray(ghosts);
    pieceData->GetPointData()->AddArray(pieceGids);

    // 6. The detector on the piece, its cloud-wide figures reduced over the processes.
    vtkMultiProcessController* saved = detector->GetController();
    if (saved)
    {
      saved->Register(this);
    }
    detector->SetController(controller);
    detector->SetOutputFeaturesOnly(false);
    detector->SetHaloWidth(width);
    detector->SetInputData(pieceData);
    detector->Update();
    detector->SetHaloWidth(0.0);
    detector->SetController(saved);
    detector->SetOutputFeaturesOnly(featuresOnly);
    if (saved)
    {
      saved->UnRegister(this);
    }
    result = detector->GetOutput();
    double required = detector->GetRequiredHaloWidth(), widest = 0.0;
    controller->AllReduce(&required, &widest, 1, vtkCommunicator::MAX_OP);
    if (!(widest > width))
    {
      break;
    }
    // At most three shortfalls: the quick screen's, the voxel filter's, clamped points'.
    if (attempt >= 3)
    {
      vtkErrorMacro(<< "The detector needs a halo of width " << widest << ", more than the "
                    << width << " it was given.");
      return 0;
    }
    width = widest; // the estimate fell short: the halo again, as wide as the run said
  }
  this->FindReplacedArrays(pieceData, result);

  // 7. The own points' results.
  vtkNew<vtkFieldData> fieldData;
  fieldData->ShallowCopy(result->GetFieldData());
  // The input's active normals, which a detector's output keeps active (its own replace them
  // under the same name) and the rows below do not carry.
  vtkDataArray* activeNormals = input ? input->GetPointData()->GetNormals() : nullptr;
  const std::string normalsName =
    activeNormals && activeNormals->GetName() ? activeNormals->GetName() : "";
  Layout outLayout;
  Rows ownResult;
  {
    vtkNew<vtkPolyData> resultNoGhosts;
    resultNoGhosts->SetPoints(result->GetPoints());
    resultNoGhosts->GetPointData()->ShallowCopy(result->GetPointData());
    resultNoGhosts->GetPointData()->RemoveArray(vtkDataSetAttributes::GhostArrayName());
    resultNoGhosts->GetPointData()->RemoveArray(
      vtkFeaturePointDetector::GetPieceGlobalIdsArrayName());
    outLayout = LayoutOf(resultNoGhosts);
    Rows resultRows;
    RowsOf(resultNoGhosts, outLayout, 0, resultRows, error);
    std::vector<vtkIdType> ownRows;
    for (vtkIdType j = 0; j < pieceGids->GetNumberOfValues(); ++j)
    {
      resultRows.Gid[j] = pieceGids->GetValue(j);
      if (ghosts->GetValue(j) == 0)
      {
        ownRows.push_back(j);
      }
    }
    ownResult = resultRows.Select(outLayout, ownRows);
  }
  // Neither the piece nor the detector's output is read again: released before the gather.
  detector->SetInputData(nullptr);
  result->ReleaseData();
  result = nullptr;
  pieceData = nullptr;
  piece = Rows();
  vtkSmartPointer<vtkPolyData> full;
  if (this->GatherOutput)
  {
    Rows all;
    if (!GatherInOrder(comm, outLayout, ownResult, all))
    {
      vtkErrorMacro("Cannot gather the result on process 0: it holds more than 2 GB.");
      return 0;
    }
    full = all.ToPolyData();
  }
  else
  {
    full = ownResult.ToPolyData();
    vtkNew<vtkIdTypeArray> gids;
    gids->SetName("GlobalPointIds");
    gids->SetNumberOfValues(ownResult.Size());
    for (vtkIdType i = 0; i < ownResult.Size(); ++i)
    {
      gids->SetValue(i, static_cast<vtkIdType>(ownResult.Gid[i]));
    }
    full->GetPointData()->AddArray(gids);
  }
  full->GetFieldData()->ShallowCopy(fieldData);
  if (const char* scalars = detector->GetScoreArrayName())
  {
    full->GetPointData()->SetActiveScalars(scalars);
  }
  if (!normalsName.empty() && full->GetPointData()->GetArray(normalsName.c_str()))
  {
    full->GetPointData()->SetActiveNormals(normalsName.c_str());
  }
  if (featuresOnly)
  {
    vtkFeaturePointDetector::SelectFeaturePoints(full,
      vtkUnsignedCharArray::SafeDownCast(full->GetPointData()->GetArray("FeatureMask")), output);
  }
  else
  {
    output->ShallowCopy(full);
  }
  return 1;
}

void vtkDistributedFeaturePoints::FindReplacedArrays(vtkPolyData* input, vtkPolyData* result)
{
  for (int a = 0; a < input->GetPointData()->GetNumberOfArrays(); ++a)
  {
    vtkAbstractArray* array = input->GetPointData()->GetAbstractArray(a);
    const char* name = array ? array->GetName() : nullptr;
    if (!name || std::strcmp(name, vtkDataSetAttributes::GhostArrayName()) == 0 ||
      std::strcmp(name, vtkFeaturePointDetector::GetPieceGlobalIdsArrayName()) == 0)
    {
      continue;
    }
    vtkAbstractArray* written = result->GetPointData()->GetAbstractArray(name);
    if (written && written != array)
    {
      this->ReplacedArrays.emplace_back(name);
    }
  }
}

void vtkDistributedFeaturePoints::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Detector: " << this->Detector << "\n";
  os << indent << "Controller: " << this->Controller << "\n";
  os << indent << "GatherOutput: " << this->GatherOutput << "\n";
}
