// The wrapped counterparts of the k-nearest queries on std::vector tables
// (vtkPointCloudNeighborhoods, vtkPointCloudGridLocator): the ids of a vtkIdList in, the table
// and the nearest distances out in VTK arrays. Private to FeaturePoints::Filters (not installed).
#ifndef vtkFeaturePointsTables_h
#define vtkFeaturePointsTables_h

#include "vtkDoubleArray.h"
#include "vtkIdList.h"
#include "vtkIntArray.h"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace featurepoints
{
/** The ids of `list` (none for nullptr). */
inline std::vector<vtkIdType> IdsOf(vtkIdList* list)
{
  std::vector<vtkIdType> ids;
  if (list)
  {
    ids.assign(list->GetPointer(0), list->GetPointer(0) + list->GetNumberOfIds());
  }
  return ids;
}

/**
 * Runs `query(rows, table, nearest)` (nearest: nullptr when `nearestDistances` is) on the ids of
 * `ids` and copies its k-column table into `table` (k components, a tuple per id) and its
 * distances into `nearestDistances`. False, with the arrays untouched, for k < 1, no table or a
 * failed query.
 */
template <typename Query>
bool FindNearestNeighborsInArrays(
  int k, vtkIdList* ids, vtkIntArray* table, vtkDoubleArray* nearestDistances, Query&& query)
{
  if (!table || k < 1)
  {
    return false;
  }
  const std::vector<vtkIdType> rows = IdsOf(ids);
  std::vector<int32_t> entries;
  std::vector<double> nearest;
  if (!query(rows, entries, nearestDistances ? &nearest : nullptr))
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
} // namespace featurepoints

#endif
