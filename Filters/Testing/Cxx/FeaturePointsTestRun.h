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
  for (const char* name : { "Normals", "SSI", "PDI", "F" })
  {
    vtkFloatArray* a = Floats(out, name);
    if (!a)
    {
      return false;
    }
    for (vtkIdType i = 0; i < a->GetNumberOfValues(); ++i)
    {
      if (!std::isfinite(a->GetValue(i)))
      {
        return false;
      }
    }
  }
  return true;
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
