// Two noisy planes meeting along a crease (bent by 90 and by 30 degrees, sigma = 0.5 spacing):
// the feature points form a band along the crease, scored with the precision and recall of
// docs/evaluation.md.
// Floors sit a little below the figures measured when the test was written (in the comments).
#include "FeaturePointsTestRun.h"

int TestFeaturePointCreases(int, char*[])
{
  using namespace fptest;
  int failures = 0;
  struct Case
  {
    double Bend;
    double MinPrecision, MinRecall;
  };
  // Measured: 90 degrees P 0.77 R 0.97; 30 degrees P 0.68 R 0.15 (the paper's SSI is weak on
  // gentle creases under this much noise).
  const Case cases[] = { { 90.0, 0.70, 0.90 }, { 30.0, 0.55, 0.10 } };
  for (const Case& c : cases)
  {
    Cloud cloud = BentPlanes(30000, 21, c.Bend);
    vtkNew<vtkFeaturePointExtraction> filter;
    filter->SetInputData(cloud.Data);
    filter->Update();
    const Quality q = Evaluate(cloud, Mask(filter->GetOutput()));
    std::printf("bend %2.0f deg: %ld detections, %ld positives, precision %.3f recall %.3f F1 %.3f\n",
      c.Bend, q.Detections, q.Positives, q.Precision, q.Recall, q.F1);
    FP_CHECK(q.Precision >= c.MinPrecision, "bend %.0f: precision %.3f", c.Bend, q.Precision);
    FP_CHECK(q.Recall >= c.MinRecall, "bend %.0f: recall %.3f", c.Bend, q.Recall);
  }
  return failures ? EXIT_FAILURE : EXIT_SUCCESS;
}
