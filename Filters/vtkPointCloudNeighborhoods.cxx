#include "vtkPointCloudNeighborhoods.h"

#include "vtkAlgorithm.h"
#include "vtkCellArray.h"
#include "vtkTypeInt32Array.h"
#include "vtkTypeInt64Array.h"
#include "vtkIdList.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPThreadLocalObject.h"
#include "vtkSMPTools.h"
#include "vtkStaticPointLocator.h"

#include <algorithm>
#include <cmath>
#include <limits>

vtkStandardNewMacro(vtkPointCloudNeighborhoods);

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
  this->Locator = nullptr;
  this->LocatorData = nullptr;
  this->LocatorToPoint.clear();
  this->Valid.clear();
  this->NearestDistances.clear();
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
  this->Valid.assign(n, 0);
  double lo[3] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, VTK_DOUBLE_MAX };
  double hi[3] = { -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
  double x[3];
  for (vtkIdType i = 0; i < n; ++i)
  {
    points->GetPoint(i, x);
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
        points->GetPoint(i, x);
        finite->SetPoint(j, x);
        this->LocatorToPoint[j++] = i;
      }
    }
    this->LocatorData->SetPoints(finite);
  }
  this->Locator = vtkSmartPointer<vtkStaticPointLocator>::New();
  this->Locator->SetDataSet(this->LocatorData);
  this->Locator->BuildLocator();
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

double vtkPointCloudNeighborhoods::ComputeMeanSpacing()
{
  if (this->MeanSpacing >= 0.0)
  {
    return this->MeanSpacing;
  }
  if (!this->Locator)
  {
    return 0.0;
  }
  const std::vector<vtkIdType> ids = this->GetValidIds();
  std::vector<int32_t> table;
  std::vector<double> nearest;
  this->FindNearestNeighbors(1, ids, table, &nearest);
  this->NearestDistances.assign(this->NumberOfPoints, 0.0);
  for (size_t r = 0; r < ids.size(); ++r)
  {
    this->NearestDistances[ids[r]] = nearest[r];
  }
  return this->FinishMeanSpacing();
}

double vtkPointCloudNeighborhoods::ComputeMeanSpacing(
  const std::vector<vtkIdType>& ids, const std::vector<int32_t>& table, int k)
{
  if (this->MeanSpacing >= 0.0)
  {
    return this->MeanSpacing;
  }
  if (!this->Locator)
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
  double limit = 0.0;
  if (!positive.empty())
  {
    auto mid = positive.begin() + positive.size() / 2;
    std::nth_element(positive.begin(), mid, positive.end());
    limit = 10.0 * *mid;
  }
  double sum = 0.0;
  vtkIdType count = 0;
  for (vtkIdType i = 0; i < this->NumberOfPoints; ++i)
  {
    if (this->Valid[i] && nearest[i] > 0.0 && nearest[i] <= limit)
    {
      sum += nearest[i];
      ++count;
    }
  }
  this->MeanSpacing = count > 0 ? sum / static_cast<double>(count) : 0.0;
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
  if (k <= 0 || rows == 0 || !this->Locator)
  {
    std::fill(table.begin(), table.end(), -1);
    return true;
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

vtkSmartPointer<vtkCellArray> vtkPointCloudNeighborhoods::MakeVertexCells(vtkIdType n)
{
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  auto fill = [n, &cells](auto offsets, auto connectivity) {
    offsets->SetNumberOfValues(n + 1);
    connectivity->SetNumberOfValues(n);
    vtkSMPTools::For(0, n + 1, [&](vtkIdType begin, vtkIdType end) {
      for (vtkIdType i = begin; i < end; ++i)
      {
        offsets->SetValue(i, i);
        if (i < n)
        {
          connectivity->SetValue(i, i);
        }
      }
    });
    cells->SetData(offsets, connectivity);
  };
  if (n < std::numeric_limits<int32_t>::max())
  {
    fill(vtkSmartPointer<vtkTypeInt32Array>::New(), vtkSmartPointer<vtkTypeInt32Array>::New());
  }
  else
  {
    fill(vtkSmartPointer<vtkTypeInt64Array>::New(), vtkSmartPointer<vtkTypeInt64Array>::New());
  }
  return cells;
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
