// A noisy plane and a noisy sphere have no feature: with default parameters the filter marks
// (almost) none of their points (docs/evaluation.md: false detections per 1000 points).
#include "FeaturePointsTestRun.h"

int TestFeaturePointSmoothShapes(int, char*[])
{
  using namespace fptest;
  int failures = 0;
  struct Case
  {
    const char* Name;
    Cloud C;
  };
  Case cases[] = { { "noisy plane", NoisyPlane(20000, 11) }, { "noisy sphere", NoisySphere(20000, 12) },
    { "clean plane", NoisyPlane(20000, 13, 0.0) }, { "clean sphere", NoisySphere(20000, 14, 0.0) } };
  for (Case& c : cases)
  {
    vtkNew<vtkFeaturePointExtraction> filter;
    filter->SetInputData(c.C.Data);
    filter->Update();
    const long found = CountSet(Mask(filter->GetOutput()));
    const double perThousand = 1000.0 * found / c.C.Data->GetNumberOfPoints();
    std::printf("%-13s %ld feature points (%.2f per 1000), threshold %.4f\n", c.Name, found,
      perThousand, filter->GetThresholdUsed());
    FP_CHECK(perThousand <= 2.0, "%s: %.2f false feature points per 1000", c.Name, perThousand);
    FP_CHECK(AllFinite(filter->GetOutput()), "%s: non-finite output", c.Name);
  }
  return failures ? EXIT_FAILURE : EXIT_SUCCESS;
}
