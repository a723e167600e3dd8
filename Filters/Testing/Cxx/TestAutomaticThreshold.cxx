// The AUTOMATIC threshold on weighted scores equals the rule on the scores repeated by their
// weights, exactly (same double), on skewed score sets with a feature-like tail, odd and even
// totals, ties, and weights of 1 only; and it separates a clear tail from its background.
#include "FeaturePointsTestRun.h"
#include "vtkFeaturePointDetector.h"

#include <random>
#include <vector>

int TestAutomaticThreshold(int, char*[])
{
  int failures = 0;
  std::mt19937 rng(11);
  for (int trial = 0; trial < 40; ++trial)
  {
    const int n = 1 + static_cast<int>(rng() % 3000);
    const int maxWeight = trial % 4 == 0 ? 1 : 1 + static_cast<int>(rng() % 200);
    std::lognormal_distribution<double> background(0.0, 0.3);
    std::uniform_real_distribution<double> tail(3.0, 10.0);
    std::vector<double> scores(n);
    std::vector<int> weights(n);
    std::vector<double> repeated;
    for (int i = 0; i < n; ++i)
    {
      scores[i] = (rng() % 10 == 0) ? tail(rng) : background(rng);
      if (trial % 5 == 1)
      {
        scores[i] = std::round(scores[i] * 4.0) / 4.0; // many ties
      }
      weights[i] = 1 + static_cast<int>(rng() % maxWeight);
      repeated.insert(repeated.end(), weights[i], scores[i]);
    }
    const double weighted = vtkFeaturePointDetector::AutomaticThreshold(scores, weights, 5.0);
    const double plain = vtkFeaturePointDetector::AutomaticThreshold(repeated, 5.0);
    FP_CHECK(weighted == plain, "trial %d (n %d, %zu repeated): weighted %.17g, repeated %.17g",
      trial, n, repeated.size(), weighted, plain);
  }

  // Background near 1, a tail from 5 up: the threshold lies between them.
  std::vector<double> scores;
  std::vector<int> weights;
  std::normal_distribution<double> noise(1.0, 0.05);
  for (int i = 0; i < 5000; ++i)
  {
    scores.push_back(noise(rng));
    weights.push_back(8);
  }
  for (int i = 0; i < 500; ++i)
  {
    scores.push_back(5.0 + i * 0.01);
    weights.push_back(1);
  }
  const double t = vtkFeaturePointDetector::AutomaticThreshold(scores, weights, 5.0);
  std::printf("separated tail: threshold %.4f\n", t);
  FP_CHECK(t > 1.1 && t < 5.0, "threshold %g not between the background and the tail", t);
  return failures ? EXIT_FAILURE : EXIT_SUCCESS;
}
