// Private header of FeaturePoints::Filters and FeaturePoints::IO (not installed; each module adds
// this folder to its private include path): the vertex cells that make a cloud render as is.
#ifndef vtkFeaturePointsVertexCells_h
#define vtkFeaturePointsVertexCells_h

#include "vtkCellArray.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkTypeInt32Array.h"
#include "vtkTypeInt64Array.h"

#include <cstdint>
#include <limits>

namespace featurepoints
{
/**
 * One vertex cell per point, 0 to n-1, with 32-bit storage when n allows; nullptr when the memory
 * cannot be had.
 */
inline vtkSmartPointer<vtkCellArray> MakeVertexCells(vtkIdType n)
{
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  auto fill = [n, &cells](auto offsets, auto connectivity) {
    // SetNumberOfValues reports a failed allocation by leaving the size unchanged.
    offsets->SetNumberOfValues(n + 1);
    connectivity->SetNumberOfValues(n);
    if (offsets->GetNumberOfValues() != n + 1 || connectivity->GetNumberOfValues() != n)
    {
      return false;
    }
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
    return true;
  };
  const bool filled = n < std::numeric_limits<int32_t>::max()
    ? fill(vtkSmartPointer<vtkTypeInt32Array>::New(), vtkSmartPointer<vtkTypeInt32Array>::New())
    : fill(vtkSmartPointer<vtkTypeInt64Array>::New(), vtkSmartPointer<vtkTypeInt64Array>::New());
  return filled ? cells : nullptr;
}
} // namespace featurepoints

#endif
