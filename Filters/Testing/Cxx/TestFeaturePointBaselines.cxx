// The paper's baselines: same output conventions as the proposed method, sensible detections on a
// 90-degree crease, and SSI alone is exactly the main filter with the three published settings.
#include "FeaturePointsTestRun.h"
#include "vtkCurvatureDensityFeatures.h"
#include "vtkSmoothShrinkIndexFeatures.h"
#include "vtkSurfaceVariationFeatures.h"

int TestFeaturePointBaselines(int, char*[])
{
  using namespace fptest;
  int failures = 0;
  Cloud cloud = BentPlanes(30000, 21, 90.0);
  const vtkIdType n = cloud.Data->GetNumberOfPoints();

  struct Case
  {
    vtkSmartPointer<vtkFeaturePointDetector> Filter;
    const char* Arrays[5];
    double MinPrecision, MinRecall;
  };
  // Measured when written: PCA P 0.72 R 0.68; Wang & Yuan P 0.87 R 0.96; SSI P 0.93 R 0.24.
  Case cases[] = {
    { vtkSmartPointer<vtkSurfaceVariationFeatures>::New(), { "Normals", "SurfaceVariation" }, 0.65, 0.6 },
    { vtkSmartPointer<vtkCurvatureDensityFeatures>::New(),
      { "Normals", "Curvature", "NormalAngle", "Density", "CurvatureDensity" }, 0.8, 0.9 },
    { vtkSmartPointer<vtkSmoothShrinkIndexFeatures>::New(), { "Normals", "SSI", "PDI", "F" }, 0.85, 0.15 },
  };
  for (Case& c : cases)
  {
    c.Filter->SetInputData(cloud.Data);
    c.Filter->Update();
    vtkPolyData* out = c.Filter->GetOutput();
    const char* name = c.Filter->GetClassName();
    FP_CHECK(out->GetNumberOfPoints() == n && out->GetNumberOfVerts() == n, "%s: output size", name);
    FP_CHECK(out->GetPointData()->GetScalars() &&
        std::string(out->GetPointData()->GetScalars()->GetName()) == c.Filter->GetScoreArrayName(),
      "%s: the score is not the active scalars", name);
    for (const char* array : c.Arrays)
    {
      if (!array)
      {
        break;
      }
      vtkFloatArray* a = Floats(out, array);
      bool finite = a != nullptr;
      for (vtkIdType i = 0; a && i < a->GetNumberOfValues(); ++i)
      {
        finite = finite && std::isfinite(a->GetValue(i));
      }
      FP_CHECK(finite, "%s: array %s missing or not finite", name, array);
    }
    const Quality q = Evaluate(cloud, Mask(out));
    std::printf("%-30s %5ld detections, precision %.3f recall %.3f F1 %.3f threshold %.4g\n", name,
      q.Detections, q.Precision, q.Recall, q.F1, c.Filter->GetThresholdUsed());
    FP_CHECK(q.Precision >= c.MinPrecision, "%s: precision %.3f", name, q.Precision);
    FP_CHECK(q.Recall >= c.MinRecall, "%s: recall %.3f", name, q.Recall);
    FP_CHECK(c.Filter->GetNumberOfFeaturePoints() == CountSet(Mask(out)), "%s: count", name);
  }

  // SSI alone == the main filter with alpha 1, no voxel step, Eq. 2's centre.
  vtkNew<vtkFeaturePointExtraction> main;
  main->SetInputData(cloud.Data);
  main->SetAlpha(1.0);
  main->UseVoxelFilterOff();
  main->SetSSICenterToPoint();
  main->Update();
  vtkFloatArray* a = Floats(main->GetOutput(), "F");
  vtkFloatArray* b = Floats(cases[2].Filter->GetOutput(), "F");
  long different = 0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    different += a->GetValue(i) != b->GetValue(i);
  }
  FP_CHECK(different == 0, "SSI baseline differs from the main filter on %ld points", different);

  // Bad input reaches the baselines' shared checks: 10 points give a warning and zero scores.
  vtkNew<vtkPolyData> few;
  vtkNew<vtkPoints> points;
  for (int i = 0; i < 10; ++i)
  {
    points->InsertNextPoint(i, i * i, 0.5 * i);
  }
  few->SetPoints(points);
  vtkNew<vtkSurfaceVariationFeatures> pca;
  pca->GlobalWarningDisplayOff();
  pca->SetInputData(few);
  pca->Update();
  FP_CHECK(pca->GetOutput()->GetNumberOfPoints() == 10 && pca->GetNumberOfFeaturePoints() == 0,
    "10 points: %lld features", (long long)pca->GetNumberOfFeaturePoints());
  return failures ? EXIT_FAILURE : EXIT_SUCCESS;
}
