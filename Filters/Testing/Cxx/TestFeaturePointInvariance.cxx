// F is dimensionless: the same cloud scaled by 1000, or moved by 10^6 along each axis, gives the
// same FeatureMask (double-precision coordinates); so does a cloud with denser features whose
// points are also shuffled. The default detector gives the same mask at scales far beyond
// float's range (10^-290 to 10^300).
#include "FeaturePointsTestRun.h"

#include "vtkCreaseVotingFeatures.h"
#include "vtkCurvatureDensityFeatures.h"
#include "vtkDataArray.h"
#include "vtkFeaturePointExtraction.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"
#include "vtkSmoothShrinkIndexFeatures.h"
#include "vtkSurfaceVariationFeatures.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numeric>
#include <random>
#include <vector>

namespace
{
// The cloud's points (double) times 2^power, exactly.
vtkSmartPointer<vtkPolyData> ScaledCopy(vtkPolyData* cloud, int power)
{
  vtkNew<vtkPoints> scaled;
  scaled->SetDataTypeToDouble();
  scaled->SetNumberOfPoints(cloud->GetNumberOfPoints());
  for (vtkIdType i = 0; i < scaled->GetNumberOfPoints(); ++i)
  {
    double p[3];
    cloud->GetPoint(i, p);
    scaled->SetPoint(i, std::ldexp(p[0], power), std::ldexp(p[1], power), std::ldexp(p[2], power));
  }
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(scaled);
  return data;
}
}

int TestFeaturePointInvariance(int, char*[])
{
  using namespace fptest;
  int failures = 0;
  Cloud cloud = BentPlanes(20000, 41, 60.0);
  auto run = [](vtkPolyData* data) {
    auto filter = vtkSmartPointer<vtkFeaturePointExtraction>::New();
    filter->SetInputData(data);
    filter->Update();
    return filter;
  };
  auto reference = run(cloud.Data);
  const long found = CountSet(Mask(reference->GetOutput()));
  FP_CHECK(found > 50, "only %ld feature points on the reference cloud", found);

  struct Transform
  {
    const char* Name;
    double Scale, Offset;
    int Type;
  };
  // The last case rounds the same cloud to single precision.
  for (const Transform& t : { Transform{ "scaled x1000", 1000.0, 0.0, VTK_DOUBLE },
         Transform{ "moved by 1e6", 1.0, 1e6, VTK_DOUBLE },
         Transform{ "scaled x0.001", 0.001, 0.0, VTK_DOUBLE },
         Transform{ "float points", 1.0, 0.0, VTK_FLOAT } })
  {
    vtkNew<vtkPoints> moved;
    moved->SetDataType(t.Type);
    moved->SetNumberOfPoints(cloud.Data->GetNumberOfPoints());
    double p[3];
    for (vtkIdType i = 0; i < moved->GetNumberOfPoints(); ++i)
    {
      cloud.Data->GetPoint(i, p);
      for (double& c : p)
      {
        c = c * t.Scale + t.Offset;
      }
      moved->SetPoint(i, p);
    }
    vtkNew<vtkPolyData> data;
    data->SetPoints(moved);
    auto result = run(data);
    long differ = 0;
    for (vtkIdType i = 0; i < moved->GetNumberOfPoints(); ++i)
    {
      differ +=
        Mask(result->GetOutput())->GetValue(i) != Mask(reference->GetOutput())->GetValue(i);
    }
    const double ratio = result->GetMeanSpacing() / reference->GetMeanSpacing();
    std::printf("%-14s %ld feature points, %ld mask differences, spacing ratio %.6f\n", t.Name,
      CountSet(Mask(result->GetOutput())), differ, ratio);
    FP_CHECK(differ == 0, "%s: %ld mask differences", t.Name, differ);
    FP_CHECK(std::abs(ratio / t.Scale - 1.0) < (t.Type == VTK_FLOAT ? 1e-4 : 1e-6),
      "%s: spacing ratio %g", t.Name, ratio);
    FP_CHECK(AllFinite(result->GetOutput()), "%s: non-finite output", t.Name);
  }

  // Features sampled 3x denser: the voxel pre-filter keeps a minority of candidates and the
  // AUTOMATIC threshold scores a sample of the other points, which must depend on where the
  // points are, not on their order. The cloud is shuffled, scaled and moved at once.
  Cloud denser = BentPlanes(40000, 43, 60.0, 0.5, 3.0);
  auto dense = run(denser.Data);
  const vtkIdType n = denser.Data->GetNumberOfPoints();
  const long candidates =
    CountSet(vtkUnsignedCharArray::SafeDownCast(dense->GetOutput()->GetPointData()->GetArray("Candidate")));
  FP_CHECK(candidates > 0 && candidates < n / 2, "denser cloud: %ld candidates of %lld", candidates,
    static_cast<long long>(n));
  std::vector<vtkIdType> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::mt19937 rng(5);
  std::shuffle(order.begin(), order.end(), rng);
  vtkNew<vtkPoints> shuffled;
  shuffled->SetDataTypeToDouble();
  shuffled->SetNumberOfPoints(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    double p[3];
    denser.Data->GetPoint(order[i], p);
    shuffled->SetPoint(i, 1000.0 * p[0] + 1e6, 1000.0 * p[1] - 1e6, 1000.0 * p[2] + 1e6);
  }
  vtkNew<vtkPolyData> shuffledData;
  shuffledData->SetPoints(shuffled);
  auto other = run(shuffledData);
  long differ = 0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    differ += Mask(other->GetOutput())->GetValue(i) != Mask(dense->GetOutput())->GetValue(order[i]);
  }
  std::printf("denser, shuffled, scaled and moved: %ld feature points, %ld candidates, %ld mask "
              "differences, threshold %.9g / %.9g\n",
    CountSet(Mask(other->GetOutput())), candidates, differ, other->GetThresholdUsed(),
    dense->GetThresholdUsed());
  FP_CHECK(CountSet(Mask(dense->GetOutput())) > 50, "denser cloud: only %ld feature points",
    CountSet(Mask(dense->GetOutput())));
  FP_CHECK(differ == 0, "denser cloud shuffled: %ld mask differences", differ);

  // The default detector at scales where squared lengths leave float's range (2^70, 2^140, 2^990
  // and their inverses, about 10^21 to 10^298 and 10^-289): exactly the same mask, offsets and
  // figures, scaled with the cloud (it runs scaled by a power of two to an extent near 1).
  auto crease = [](vtkPolyData* data) {
    auto filter = vtkSmartPointer<vtkCreaseVotingFeatures>::New();
    filter->CreaseOffsetsOn();
    filter->SetInputData(data);
    filter->Update();
    return filter;
  };
  auto creaseReference = crease(cloud.Data);
  vtkDataArray* referenceOffsets =
    creaseReference->GetOutput()->GetPointData()->GetArray("CreaseOffset");
  FP_CHECK(CountSet(Mask(creaseReference->GetOutput())) > 50, "crease: only %ld feature points",
    CountSet(Mask(creaseReference->GetOutput())));
  for (const int power : { 70, 140, 990, -70, -140, -960 })
  {
    vtkSmartPointer<vtkPolyData> data = ScaledCopy(cloud.Data, power);
    vtkPoints* scaled = data->GetPoints();
    auto result = crease(data);
    vtkPolyData* out = result->GetOutput();
    vtkDataArray* offsets = out->GetPointData()->GetArray("CreaseOffset");
    long maskDiffer = 0, offsetDiffer = 0;
    for (vtkIdType i = 0; i < scaled->GetNumberOfPoints(); ++i)
    {
      maskDiffer += Mask(out)->GetValue(i) != Mask(creaseReference->GetOutput())->GetValue(i);
      for (int c = 0; c < 3; ++c)
      {
        const double expected = referenceOffsets->GetComponent(i, c);
        const double got = std::ldexp(offsets->GetComponent(i, c), -power);
        offsetDiffer += got != expected;
      }
    }
    const double sigmaRatio =
      std::ldexp(result->GetNoiseSigma(), -power) / creaseReference->GetNoiseSigma();
    const double spacingRatio =
      std::ldexp(result->GetMeanSpacing(), -power) / creaseReference->GetMeanSpacing();
    std::printf("crease, scaled x2^%d: %ld feature points, %ld mask differences, %ld offsets off, "
                "noise ratio %.9f, spacing ratio %.9f\n",
      power, CountSet(Mask(out)), maskDiffer, offsetDiffer, sigmaRatio, spacingRatio);
    FP_CHECK(maskDiffer == 0, "crease scaled x2^%d: %ld mask differences", power, maskDiffer);
    FP_CHECK(offsetDiffer == 0, "crease scaled x2^%d: %ld offset components off", power,
      offsetDiffer);
    FP_CHECK(sigmaRatio == 1.0 && spacingRatio == 1.0,
      "crease scaled x2^%d: noise ratio %g, spacing ratio %g", power, sigmaRatio, spacingRatio);
    FP_CHECK(AllFinite(out), "crease scaled x2^%d: non-finite output", power);
  }
  // Every other method at the same scales: the same mask, and the arrays of a length unit (SSI,
  // PDI, Density) scaled with the cloud. Before they ran in a scaled frame, SSI (2^140), PDI and
  // Density (2^-140) held NaN, and at 2^990 / 2^-960 no method marked a point.
  struct Method
  {
    const char* Name;
    std::function<vtkSmartPointer<vtkFeaturePointDetector>()> Make;
    std::vector<std::pair<const char*, int>> Lengths; // array, power of the length unit
  };
  const Method methods[] = {
    { "huang2023", [] { return vtkSmartPointer<vtkFeaturePointDetector>(
                          vtkSmartPointer<vtkFeaturePointExtraction>::New()); },
      { { "SSI", 1 }, { "PDI", -1 } } },
    { "ssi", [] { return vtkSmartPointer<vtkFeaturePointDetector>(
                    vtkSmartPointer<vtkSmoothShrinkIndexFeatures>::New()); },
      { { "SSI", 1 } } },
    { "pca", [] { return vtkSmartPointer<vtkFeaturePointDetector>(
                    vtkSmartPointer<vtkSurfaceVariationFeatures>::New()); },
      {} },
    { "wang-yuan", [] { return vtkSmartPointer<vtkFeaturePointDetector>(
                          vtkSmartPointer<vtkCurvatureDensityFeatures>::New()); },
      { { "Density", -1 } } },
  };
  for (const Method& method : methods)
  {
    auto reference = method.Make();
    reference->SetInputData(cloud.Data);
    reference->Update();
    vtkPolyData* expected = reference->GetOutput();
    FP_CHECK(CountSet(Mask(expected)) > 10, "%s: only %ld feature points", method.Name,
      CountSet(Mask(expected)));
    for (const int power : { 140, 990, -140, -960 })
    {
      vtkSmartPointer<vtkPolyData> data = ScaledCopy(cloud.Data, power);
      vtkPoints* scaled = data->GetPoints();
      auto result = method.Make();
      result->SetInputData(data);
      result->Update();
      vtkPolyData* out = result->GetOutput();
      long maskDiffer = 0, valuesOff = 0;
      for (vtkIdType i = 0; i < scaled->GetNumberOfPoints(); ++i)
      {
        maskDiffer += Mask(out)->GetValue(i) != Mask(expected)->GetValue(i);
        for (const auto& length : method.Lengths)
        {
          vtkDataArray* a = out->GetPointData()->GetArray(length.first);
          vtkDataArray* b = expected->GetPointData()->GetArray(length.first);
          valuesOff += !a || !b ||
            std::ldexp(a->GetComponent(i, 0), -length.second * power) != b->GetComponent(i, 0);
        }
      }
      std::printf("%s, scaled x2^%d: %ld feature points, %ld mask differences, %ld length "
                  "values off\n",
        method.Name, power, CountSet(Mask(out)), maskDiffer, valuesOff);
      FP_CHECK(maskDiffer == 0, "%s scaled x2^%d: %ld mask differences", method.Name, power,
        maskDiffer);
      FP_CHECK(valuesOff == 0, "%s scaled x2^%d: %ld length values off", method.Name, power,
        valuesOff);
      FP_CHECK(AllFinite(out), "%s scaled x2^%d: non-finite output", method.Name, power);
    }
  }
  return failures ? EXIT_FAILURE : EXIT_SUCCESS;
}
