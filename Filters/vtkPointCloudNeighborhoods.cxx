#include "vtkPointCloudNeighborhoods.h"

#include "vtkAbstractPointLocator.h"
#include "vtkAlgorithm.h"
#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkFeaturePointsLocalPCA.h"
#include "vtkFeaturePointsStatistics.h"
#include "vtkFeaturePointsTables.h"
#include "vtkFeaturePointsVertexCells.h"
#include "vtkTypeInt32Array.h"
#include "vtkTypeInt64Array.h"
#include "vtkIdList.h"
#include "vtkIntArray.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkPointCloudGridLocator.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPThreadLocalObject.h"
#include "vtkSMPTools.h"
#include "vtkStaticPointLocator.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <new>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <unistd.h>

vtkStandardNewMacro(vtkPointCloudNeighborhoods);

namespace
{
// One k-nearest query per listed point; row r of the table gets the k nearest *other* valid points
// of ids[r], nearest first. The query asks for k + 1 points because the point itself comes back
// among them (first, unless duplicates tie with it at distance 0).
struct NearestNeighborsWorker
{
  vtkPoints* Points;
  vtkAbstractPointLocator* Locator;
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
} // namespace

vtkPointCloudNeighborhoods::vtkPointCloudNeighborhoods()
  : Locator(vtkSmartPointer<vtkPointCloudGridLocator>::New())
{
}

vtkPointCloudNeighborhoods::~vtkPointCloudNeighborhoods()
{
  this->ReleaseLocator();
}

void vtkPointCloudNeighborhoods::SetLocator(vtkAbstractPointLocator* locator)
{
  if (locator == this->Locator.GetPointer() && locator)
  {
    return;
  }
  this->ReleaseLocator();
  this->Searchable = false;
  if (locator)
  {
    this->Locator = locator;
  }
  else
  {
    this->Locator = vtkSmartPointer<vtkPointCloudGridLocator>::New();
  }
  this->Modified();
}

vtkAbstractPointLocator* vtkPointCloudNeighborhoods::GetLocator() const
{
  return this->Locator;
}

void vtkPointCloudNeighborhoods::SetSearchMethod(int method)
{
  if (method == STATIC_POINT_LOCATOR)
  {
    if (!vtkStaticPointLocator::SafeDownCast(this->Locator))
    {
      this->SetLocator(vtkSmartPointer<vtkStaticPointLocator>::New());
    }
  }
  else if (method == GRID && !vtkPointCloudGridLocator::SafeDownCast(this->Locator))
  {
    this->SetLocator(vtkSmartPointer<vtkPointCloudGridLocator>::New());
  }
  else if (method != GRID)
  {
    vtkErrorMacro(<< "SearchMethod " << method << " is neither GRID (" << GRID
                  << ") nor STATIC_POINT_LOCATOR (" << STATIC_POINT_LOCATOR
                  << "); give SetLocator() any other locator. The locator is unchanged.");
  }
}

int vtkPointCloudNeighborhoods::GetSearchMethod() const
{
  if (vtkPointCloudGridLocator::SafeDownCast(this->Locator))
  {
    return GRID;
  }
  return vtkStaticPointLocator::SafeDownCast(this->Locator) ? STATIC_POINT_LOCATOR : OTHER_LOCATOR;
}

void vtkPointCloudNeighborhoods::ReleaseLocator()
{
  // The locator was built over this object's cloud: a locator kept by a filter between runs
  // should hold neither its search structure nor the cloud.
  if (this->Locator && this->LocatorData)
  {
    this->Locator->FreeSearchStructure();
    this->Locator->SetDataSet(nullptr);
  }
  this->GridLocator = nullptr;
  this->LocatorData = nullptr;
}

vtkPoints* vtkPointCloudNeighborhoods::GetPoints() const
{
  return this->Points;
}

std::string vtkPointCloudNeighborhoods::DescribeZeroSpacing(double spacing) const
{
  double bounds[6] = { 0.0, 0.0, 0.0, 0.0, 0.0, 0.0 };
  if (this->Points)
  {
    this->Points->GetBounds(bounds);
  }
  const double extent =
    std::max({ bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4] });
  if (extent > 0.0 && (!(extent * extent > 0.0) || !std::isfinite(spacing) || extent > 1e150))
  {
    std::ostringstream text;
    text << "The cloud spans " << extent
         << " units, where squares of distances underflow or overflow in double precision: "
            "scale its coordinates by a power of two that brings the extent near 1 (the "
            "featurepoints command does so itself)";
    return text.str();
  }
  return "All points coincide: the point spacing is 0";
}

bool vtkPointCloudNeighborhoods::Build(vtkPoints* points)
{
  this->Points = points;
  this->InputDataType = points ? points->GetDataType() : VTK_DOUBLE;
  this->Searchable = false;
  this->ReleaseLocator();
  this->LocatorToPoint.clear();
  this->Valid.clear();
  this->NearestDistances.clear();
  this->NearestKnown.clear();
  this->Unreached.clear();
  this->NumberOfPoints = points ? points->GetNumberOfPoints() : 0;
  this->NumberOfValidPoints = 0;
  this->FirstInvalidPoint = -1;
  this->NumberOfDuplicatePoints = 0;
  this->ExtraCopies.clear();
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

  this->LocatorData = vtkSmartPointer<vtkPolyData>::New();
  this->GridLocator = vtkPointCloudGridLocator::SafeDownCast(this->Locator);
  if (this->NumberOfValidPoints == n || this->GridLocator)
  {
    // (The grid leaves the non-finite points out itself, keeping the cloud's ids.)
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
  this->Locator->SetDataSet(this->LocatorData);
  this->Locator->BuildLocator();
  this->Searchable = true;
  return true;
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
  if (!this->Searchable || !this->GridLocator || this->MeanSpacing >= 0.0 ||
    !this->NearestKnown.empty() || !this->NearestDistances.empty())
  {
    return false;
  }
  vtkPoints* renumbered = this->GridLocator->ReorderSpatially(originalIds);
  if (!renumbered)
  {
    return false;
  }
  // The valid points come first, in the grid's order; the invalid ones follow.
  const vtkIdType n = this->NumberOfPoints;
  const vtkIdType m = this->NumberOfValidPoints;
  std::fill(this->Valid.begin(), this->Valid.begin() + m, 1);
  std::fill(this->Valid.begin() + m, this->Valid.end(), 0);
  this->FirstInvalidPoint = m < n ? m : -1;
  this->Points = renumbered;
  // The locator's data set is now the renumbered cloud.
  this->LocatorData = vtkPolyData::SafeDownCast(this->GridLocator->GetDataSet());
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
  this->NoteUnreached(ids, table.data(), 1);
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
  this->NoteUnreached(ids, table.data(), 1);
}

void vtkPointCloudNeighborhoods::NoteUnreached(
  const std::vector<vtkIdType>& ids, const int32_t* table, int k)
{
  // A point whose distance to every other one overflows (a point near 1e308) has no nearest
  // point: its distance stays 0, but it coincides with nothing.
  for (size_t r = 0; r < ids.size(); ++r)
  {
    if (k <= 0 || table[r * k] < 0)
    {
      this->Unreached.push_back(ids[r]);
    }
  }
  std::sort(this->Unreached.begin(), this->Unreached.end());
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
  this->NoteUnreached(ids, table.data(), k);
  return this->FinishMeanSpacing();
}

double vtkPointCloudNeighborhoods::FinishMeanSpacing()
{
  std::vector<double>& nearest = this->NearestDistances;
  // Points whose nearest point coincides with them: look further, for the nearest distinct point.
  std::vector<vtkIdType> stacked;
  for (vtkIdType i = 0; i < this->NumberOfPoints; ++i)
  {
    if (this->Valid[i] && nearest[i] == 0.0 && this->NumberOfValidPoints > 1 &&
      !std::binary_search(this->Unreached.begin(), this->Unreached.end(), i))
    {
      stacked.push_back(i);
    }
  }
  this->NumberOfDuplicatePoints = static_cast<vtkIdType>(stacked.size());
  // The copies of a position count once in the mean: a copy adds no spacing, and half the cloud
  // stacked at one position (a scanner's invalid returns at its origin) made that one distance
  // the median, and the mean spacing the distance from the stack to the rest. The stacked points
  // by position:
  std::vector<std::array<double, 3>> at(stacked.size());
  for (size_t r = 0; r < stacked.size(); ++r)
  {
    this->Points->GetPoint(stacked[r], at[r].data());
  }
  std::vector<size_t> order(stacked.size());
  std::iota(order.begin(), order.end(), size_t(0));
  std::sort(order.begin(), order.end(),
    [&at](size_t a, size_t b) { return at[a] < at[b] || (at[a] == at[b] && a < b); });
  this->ExtraCopies.clear();
  for (size_t o = 1; o < order.size(); ++o)
  {
    if (at[order[o]] == at[order[o - 1]])
    {
      this->ExtraCopies.push_back(stacked[order[o]]);
    }
  }
  std::sort(this->ExtraCopies.begin(), this->ExtraCopies.end());
  if (this->GridLocator && !stacked.empty())
  {
    // One query per position for the nearest point at a nonzero distance (the copies of a stack
    // share it): linear however many copies a stack holds, and as many walks through the grid as
    // there are stacks (100,000 points at two positions walked the whole grid 100,000 times).
    std::vector<vtkIdType> representatives;
    std::vector<size_t> group(stacked.size());
    for (size_t o = 0; o < order.size(); ++o)
    {
      if (o == 0 || at[order[o]] != at[order[o - 1]])
      {
        representatives.push_back(stacked[order[o]]);
      }
      group[order[o]] = representatives.size() - 1;
    }
    std::vector<int32_t> table(representatives.size());
    std::vector<double> distinct(representatives.size());
    this->GridLocator->FindNearestNeighbors(1, representatives, table, &distinct, true);
    for (size_t r = 0; r < stacked.size(); ++r)
    {
      nearest[stacked[r]] = distinct[group[r]];
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
    if (this->Valid[i] && nearest[i] > 0.0 &&
      !std::binary_search(this->ExtraCopies.begin(), this->ExtraCopies.end(), i))
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
  try
  {
    table.resize(static_cast<size_t>(rows) * std::max(k, 0));
    if (nearestDistances)
    {
      nearestDistances->resize(rows);
    }
  }
  catch (const std::exception&) // std::bad_alloc, std::length_error
  {
    vtkErrorMacro(<< "FindNearestNeighbors: not enough memory for a table of " << rows
                  << " rows of " << k << " neighbours.");
    table.clear();
    return false;
  }
  if (k <= 0 || rows == 0 || !this->Searchable)
  {
    std::fill(table.begin(), table.end(), -1);
    return true;
  }
  if (this->GridLocator)
  {
    return this->GridLocator->FindNearestNeighbors(
      k, ids, table, nearestDistances, false, progressAlg, progressStart, progressEnd);
  }

  NearestNeighborsWorker worker{ this->Points, this->Locator,
    this->LocatorToPoint.empty() ? nullptr : this->LocatorToPoint.data(), this->Valid.data(),
    ids.data(), k, table.data(), nearestDistances ? nearestDistances->data() : nullptr, {} };

  // Queries in parallel only where the locator's are known to be thread safe once built.
  const bool parallel = vtkStaticPointLocator::SafeDownCast(this->Locator) != nullptr;
  // Batches let the main thread report progress and honour an abort request between them.
  const vtkIdType batch = std::max<vtkIdType>(20000, rows / 50);
  for (vtkIdType begin = 0; begin < rows; begin += batch)
  {
    const vtkIdType end = std::min(rows, begin + batch);
    if (parallel)
    {
      vtkSMPTools::For(begin, end, worker);
    }
    else
    {
      worker.Initialize();
      worker(begin, end);
    }
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
  os << indent << "Locator: " << this->Locator->GetClassName() << "\n";
}

// The wrapped counterparts of the methods on std::vector tables and bare pointers (see the header):
// copies between VTK arrays and the C++ ones.
using featurepoints::IdsOf;

bool vtkPointCloudNeighborhoods::MakeVertexCells(vtkIdType n, vtkCellArray* cells)
{
  if (!cells || n < 0)
  {
    return false;
  }
  vtkSmartPointer<vtkCellArray> verts;
#if defined(_SC_PHYS_PAGES) && defined(_SC_PAGESIZE)
  // Beyond the machine's memory (two 64-bit arrays of n + 1 values): false without trying, since
  // a failed allocation inside VTK's arrays is reported differently by each VTK version (an
  // error, an exception, or an abort).
  const long pages = ::sysconf(_SC_PHYS_PAGES), pageSize = ::sysconf(_SC_PAGESIZE);
  if (pages > 0 && pageSize > 0 &&
    static_cast<double>(n + 1) * 16.0 > static_cast<double>(pages) * static_cast<double>(pageSize))
  {
    cells->Initialize();
    return false;
  }
#endif
  try
  {
    verts = MakeVertexCells(n);
  }
  catch (const std::bad_alloc&)
  {
    verts = nullptr; // not enough memory: false, as documented
  }
  catch (const std::length_error&)
  {
    verts = nullptr;
  }
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
  // Ids and entries must name points of the cloud (entries may be -1: no neighbour).
  const vtkIdType n = this->GetNumberOfPoints();
  for (size_t r = 0; r < rows.size(); ++r)
  {
    if (rows[r] < 0 || rows[r] >= n)
    {
      vtkErrorMacro(<< "ComputeMeanSpacing: id " << rows[r] << " (entry " << r
                    << " of the ids) is not a point of the cloud (0 to " << n - 1 << ")");
      return 0.0;
    }
  }
  for (size_t e = 0; e < entries.size(); ++e)
  {
    if (entries[e] < -1 || entries[e] >= n)
    {
      vtkErrorMacro(<< "ComputeMeanSpacing: table entry " << entries[e] << " (row " << e / k
                    << ", column " << e % k << ") is not a point of the cloud (0 to " << n - 1
                    << ", or -1)");
      return 0.0;
    }
  }
  return this->ComputeMeanSpacing(rows, entries, k);
}

bool vtkPointCloudNeighborhoods::FindNearestNeighbors(
  int k, vtkIdList* ids, vtkIntArray* table, vtkDoubleArray* nearestDistances)
{
  return featurepoints::FindNearestNeighborsInArrays(k, ids, table, nearestDistances,
    [&](const std::vector<vtkIdType>& rows, std::vector<int32_t>& entries,
      std::vector<double>* nearest) {
      return this->FindNearestNeighbors(k, rows, entries, nearest);
    });
}
