// Helpers of the benchmark programs: the median of a series, and the floors and ceilings that
// --check holds figures to.
#ifndef FeaturePointsBenchmarkFigures_h
#define FeaturePointsBenchmarkFigures_h

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

namespace fpbench
{
/** Whether figures are held to their floors and ceilings (--check), and how many are past them. */
inline bool CheckFigures = false;
inline int Failures = 0;

/** With CheckFigures, counts and prints a figure below its floor. */
inline void Floor(const std::string& what, double value, double floor)
{
  if (CheckFigures && !(value >= floor))
  {
    std::printf("  FAIL: %s = %.3f, below its floor %.3f\n", what.c_str(), value, floor);
    ++Failures;
  }
}

/** With CheckFigures, counts and prints a figure above its ceiling. */
inline void Ceiling(const std::string& what, double value, double ceiling)
{
  if (CheckFigures && !(value <= ceiling))
  {
    std::printf("  FAIL: %s = %.3f, above its ceiling %.3f\n", what.c_str(), value, ceiling);
    ++Failures;
  }
}

/** The median of a series (the mean of the two middle values for an even count; 0 if empty). */
inline double Median(std::vector<double> v)
{
  if (v.empty())
  {
    return 0.0;
  }
  std::sort(v.begin(), v.end());
  const size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}
} // namespace fpbench

#endif
