// Helpers shared by the tests: run the filter on a cloud and fetch its arrays.
#ifndef FeaturePointsTestRun_h
#define FeaturePointsTestRun_h

#include "FeaturePointsTestClouds.h"
#include "vtkFeaturePointExtraction.h"
#include "vtkFloatArray.h"

#include <cmath>

namespace fptest
{
inline vtkUnsignedCharArray* Mask(vtkPolyData* out)
{
  return vtkUnsignedCharArray::SafeDownCast(out->GetPointData()->GetArray("FeatureMask"));
}
inline vtkFloatArray* Floats(vtkPolyData* out, const char* name)
{
  return vtkFloatArray::SafeDownCast(out->GetPointData()->GetArray(name));
}

// Every value of every float array of the output is finite.
inline bool AllFinite(vtkPolyData* out)
{
  // Every floating-point array of the output's point data, and at least one such array.
  int arrays = 0;
  vtkPointData* pd = out->GetPointData();
  for (int a = 0; a < pd->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = pd->GetArray(a);
    if (!array || (array->GetDataType() != VTK_FLOAT && array->GetDataType() != VTK_DOUBLE))
    {
      continue;
    }
    ++arrays;
    for (vtkIdType i = 0; i < array->GetNumberOfValues(); ++i)
    {
      if (!std::isfinite(array->GetVariantValue(i).ToDouble()))
      {
        return false;
      }
    }
  }
  return arrays > 0;
}

inline long CountSet(vtkUnsignedCharArray* a)
{
  long n = 0;
  for (vtkIdType i = 0; a && i < a->GetNumberOfValues(); ++i)
  {
    n += a->GetValue(i) != 0;
  }
  return n;
}
} // namespace fptest

#endif
