// Private header of FeaturePoints::Filters (not installed): the robust statistics the detectors,
// the voxel pre-filter and the neighbourhood engine share. docs/design.md ("Threshold") says how
// the detectors use them.
#ifndef vtkFeaturePointsStatistics_h
#define vtkFeaturePointsStatistics_h

#include <algorithm>
#include <cstddef>
#include <vector>

namespace featurepoints
{
/**
 * The factor that turns a median absolute deviation into the standard deviation of a normal
 * distribution (1 / Phi^-1(3/4)): s = MADToSigma * MAD.
 */
constexpr double MADToSigma = 1.4826;

/**
 * The value of rank `rank` (0-based) of `values`, which are reordered (std::nth_element). The
 * caller makes sure that rank < values.size().
 */
template <typename T>
T ValueOfRank(std::vector<T>& values, std::size_t rank)
{
  auto at = values.begin() + rank;
  std::nth_element(values.begin(), at, values.end());
  return *at;
}

/**
 * The upper median: the value of rank n / 2 (for an even count, the larger of the two middle
 * values), or `empty` when there is no value. `values` are reordered.
 */
template <typename T>
T UpperMedian(std::vector<T>& values, T empty = T(0))
{
  return values.empty() ? empty : ValueOfRank(values, values.size() / 2);
}

/**
 * The median: the middle value, or the mean of the two middle values for an even count. `values`
 * (not empty) are reordered.
 */
inline double Median(std::vector<double>& values)
{
  const std::size_t n = values.size();
  auto mid = values.begin() + n / 2;
  std::nth_element(values.begin(), mid, values.end());
  double m = *mid;
  if (n % 2 == 0)
  {
    m = 0.5 * (m + *std::max_element(values.begin(), mid));
  }
  return m;
}

/**
 * The values of ranks n / 200 and n - 1 - n / 200 (the 0.5 % and 99.5 % quantiles) of `values`
 * (not empty), which are reordered: the central 99 % of a coordinate, which a few far outliers
 * do not stretch.
 */
template <typename T>
void CentralRange(std::vector<T>& values, T& low, T& high)
{
  const std::size_t n = values.size();
  low = ValueOfRank(values, n / 200);
  high = ValueOfRank(values, n - 1 - n / 200);
}

/**
 * The mean of the values that are at most `factor` times their upper median, summed in the
 * given order (so that the result does not depend on a thread count): a mean spacing from
 * nearest-neighbour distances that one far point does not set. `values` must be positive; 0 when
 * there is none.
 */
inline double MeanWithoutOutliers(const std::vector<double>& values, double factor)
{
  if (values.empty())
  {
    return 0.0;
  }
  std::vector<double> sorted(values);
  const double limit = factor * UpperMedian(sorted);
  double sum = 0.0;
  std::size_t count = 0;
  for (double v : values)
  {
    if (v <= limit)
    {
      sum += v;
      ++count;
    }
  }
  return count > 0 ? sum / static_cast<double>(count) : 0.0;
}
} // namespace featurepoints

#endif
