// Helpers of the benchmark programs that score polylines against polylines: points sampled along
// them, and the distance from a point to the nearest sample.
#ifndef FeaturePointsBenchmarkLines_h
#define FeaturePointsBenchmarkLines_h

#include "vtkCellArray.h"
#include "vtkIdList.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStaticPointLocator.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace fpbench
{
/** Points every `step` along each polyline of `lines`, with the index of their polyline. */
inline void SampleLines(vtkPolyData* lines, double step,
  std::vector<std::array<double, 3>>& samples, std::vector<int>& owner)
{
  vtkCellArray* cells = lines->GetLines();
  vtkNew<vtkIdList> ids;
  int cell = 0;
  for (cells->InitTraversal(); cells->GetNextCell(ids); ++cell)
  {
    for (vtkIdType k = 0; k + 1 < ids->GetNumberOfIds() || (k == 0 && ids->GetNumberOfIds() == 1);
         ++k)
    {
      double a[3], b[3];
      lines->GetPoint(ids->GetId(k), a);
      lines->GetPoint(ids->GetId(std::min(k + 1, ids->GetNumberOfIds() - 1)), b);
      const double length = std::sqrt(vtkMath::Distance2BetweenPoints(a, b));
      const int n = std::max(1, static_cast<int>(std::ceil(length / step)));
      for (int j = 0; j < n; ++j)
      {
        const double t = static_cast<double>(j) / n;
        samples.push_back({ a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]),
          a[2] + t * (b[2] - a[2]) });
        owner.push_back(cell);
      }
    }
    if (ids->GetNumberOfIds() > 0)
    {
      double x[3];
      lines->GetPoint(ids->GetId(ids->GetNumberOfIds() - 1), x);
      samples.push_back({ x[0], x[1], x[2] });
      owner.push_back(cell);
    }
  }
}

/** The nearest of a set of samples (VTK's static point locator over them). */
class NearestSample
{
public:
  explicit NearestSample(const std::vector<std::array<double, 3>>& samples)
  {
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    for (const auto& x : samples)
    {
      points->InsertNextPoint(x.data());
    }
    this->Data->SetPoints(points);
    this->Count = samples.size();
    if (this->Count)
    {
      this->Locator->SetDataSet(this->Data);
      this->Locator->BuildLocator();
    }
  }
  /** Distance from x to the nearest sample (VTK_DOUBLE_MAX when there is none). */
  double Distance(const std::array<double, 3>& x) const
  {
    if (!this->Count)
    {
      return VTK_DOUBLE_MAX;
    }
    double y[3];
    this->Data->GetPoint(this->Locator->FindClosestPoint(x.data()), y);
    return std::sqrt(vtkMath::Distance2BetweenPoints(x.data(), y));
  }
  /** Index of the nearest sample (-1 when there is none). */
  vtkIdType Closest(const std::array<double, 3>& x) const
  {
    return this->Count ? this->Locator->FindClosestPoint(x.data()) : -1;
  }

private:
  size_t Count = 0;
  vtkNew<vtkPolyData> Data;
  vtkNew<vtkStaticPointLocator> Locator;
};

/**
 * Polylines `found` against polylines `truth`, both sampled every s / 4: precision, the share of
 * the found samples within 2 s of a true one; recall, the share of the true samples within 2 s
 * of a found one.
 */
inline void ScoreLines(vtkPolyData* found, vtkPolyData* truth, double s, double& precision,
  double& recall)
{
  std::vector<std::array<double, 3>> f, t;
  std::vector<int> fOwner, tOwner;
  SampleLines(found, 0.25 * s, f, fOwner);
  SampleLines(truth, 0.25 * s, t, tOwner);
  const NearestSample toTruth(t), toFound(f);
  double near = 0.0;
  for (const auto& x : f)
  {
    near += toTruth.Distance(x) <= 2.0 * s;
  }
  precision = f.empty() ? 0.0 : near / f.size();
  near = 0.0;
  for (const auto& x : t)
  {
    near += toFound.Distance(x) <= 2.0 * s;
  }
  recall = t.empty() ? 0.0 : near / t.size();
}
} // namespace fpbench

#endif
