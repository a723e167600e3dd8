// Private header of FeaturePoints::Filters (not installed): the robust statistics the detectors,
// the voxel pre-filter and the neighbourhood engine share. docs/design.md ("Threshold") says how
// the detectors use them.
#ifndef vtkFeaturePointsStatistics_h
#define vtkFeaturePointsStatistics_h

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <utility>
#include <vector>

namespace featurepoints
{
/**
 * The factor that turns a median absolute deviation into the standard deviation of a normal
 * distribution (1 / Phi^-1(3/4)): s = MADToSigma * MAD.
 */
constexpr double MADToSigma = 1.4826;

/**
 * The name of the first of these (name, value) parameters whose value is NaN (VTK's clamping
 * setters let NaN through), or nullptr when each is a number.
 */
template <typename Iterator>
const char* FirstNaN(Iterator first, Iterator last)
{
  for (; first != last; ++first)
  {
    if (std::isnan(first->second))
    {
      return first->first;
    }
  }
  return nullptr;
}

inline const char* FirstNaN(std::initializer_list<std::pair<const char*, double>> parameters)
{
  return FirstNaN(parameters.begin(), parameters.end());
}

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
 * The value of rank floor(share n) of the n `values` (at most n - 1; share 1/2: the upper
 * median), or `empty` when there is no value. `values` are reordered.
 */
template <typename T>
T ValueOfShare(std::vector<T>& values, double share, T empty = T(0))
{
  if (values.empty())
  {
    return empty;
  }
  const std::size_t rank = std::min(values.size() - 1,
    static_cast<std::size_t>(std::max(0.0, share) * static_cast<double>(values.size())));
  return ValueOfRank(values, rank);
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
 * An exact sum of doubles: every finite value is added without rounding into a fixed-point integer
 * of 2112 bits (66 limbs of 32 bits, each held in an int64 so that 2^31 additions need no carry),
 * which covers every finite double. The sum therefore does not depend on the order of the
 * additions, nor on how the values are split between threads or processes: two partial sums merge
 * exactly (Merge, or a sum of the limbs element by element). Value() rounds the exact sum once.
 * Used where a result must be the same whatever the order of the points (the mean spacing of a
 * cloud split between processes, docs/design.md "Distributed runs").
 */
class ExactSum
{
public:
  static constexpr int NumberOfLimbs = 66;
  // A value m 2^e (m an integer of 53 bits, e >= -1074) lands at bit e + Bias of the integer.
  static constexpr int Bias = 1074;

  void Add(double v)
  {
    if (v == 0.0 || !std::isfinite(v))
    {
      return;
    }
    int e;
    const double f = std::frexp(std::abs(v), &e); // |v| = f 2^e, f in [0.5, 1)
    int64_t m = static_cast<int64_t>(std::ldexp(f, 53));
    int shift = e - 53 + Bias; // bit position of m's lowest bit
    if (shift < 0)             // subnormal: the bits below 2^-1074 are zero
    {
      m >>= -shift;
      shift = 0;
    }
    const int limb = shift / 32;
    const int offset = shift % 32;
    // m << offset spans at most 85 bits: three limbs.
    const uint64_t low = static_cast<uint64_t>(m) << offset;
    const uint64_t high = offset ? static_cast<uint64_t>(m) >> (64 - offset) : 0;
    const int64_t sign = v < 0.0 ? -1 : 1;
    this->Limbs[limb] += sign * static_cast<int64_t>(low & 0xffffffffu);
    this->Limbs[limb + 1] += sign * static_cast<int64_t>(low >> 32);
    if (limb + 2 < NumberOfLimbs)
    {
      this->Limbs[limb + 2] += sign * static_cast<int64_t>(high);
    }
    if (++this->Pending == (1 << 30))
    {
      this->Normalize();
    }
  }

  void Merge(const ExactSum& other)
  {
    this->Normalize();
    ExactSum o(other);
    o.Normalize();
    for (int i = 0; i < NumberOfLimbs; ++i)
    {
      this->Limbs[i] += o.Limbs[i];
    }
    this->Normalize();
  }

  // Carries: every limb but the last in [0, 2^32). The representation is then unique.
  void Normalize()
  {
    for (int i = 0; i + 1 < NumberOfLimbs; ++i)
    {
      const int64_t carry = this->Limbs[i] >> 32; // floor division by 2^32
      this->Limbs[i] -= carry * (int64_t(1) << 32);
      this->Limbs[i + 1] += carry;
    }
    this->Pending = 0;
  }

  /** The sum, rounded to a double; a function of the exact sum only. */
  double Value() const
  {
    ExactSum n(*this);
    n.Normalize();
    // From the most significant limb down: once the partial value exceeds 2^64 times the next
    // limb's weight, the rest cannot change it by more than the rounding already made.
    double sum = 0.0;
    for (int i = NumberOfLimbs - 1; i >= 0; --i)
    {
      if (n.Limbs[i] != 0)
      {
        sum += std::ldexp(static_cast<double>(n.Limbs[i]), 32 * i - Bias);
      }
    }
    return sum;
  }

  /** The limbs, for a reduction across processes (sum them element by element). */
  int64_t* GetLimbs() { return this->Limbs.data(); }

private:
  std::array<int64_t, NumberOfLimbs> Limbs{};
  int64_t Pending = 0;
};

/**
 * The mean of the values that are at most `factor` times their upper median, summed exactly
 * (ExactSum), so that the result depends neither on the order of the values nor on a thread or
 * process count: a mean spacing from nearest-neighbour distances that one far point does not set.
 * `values` must be positive; 0 when there is none.
 */
inline double MeanWithoutOutliers(const std::vector<double>& values, double factor)
{
  if (values.empty())
  {
    return 0.0;
  }
  std::vector<double> sorted(values);
  const double limit = factor * UpperMedian(sorted);
  ExactSum sum;
  std::size_t count = 0;
  for (double v : values)
  {
    if (v <= limit)
    {
      sum.Add(v);
      ++count;
    }
  }
  return count > 0 ? sum.Value() / static_cast<double>(count) : 0.0;
}
} // namespace featurepoints

#endif
