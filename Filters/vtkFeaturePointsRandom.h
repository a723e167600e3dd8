// Private header of FeaturePoints::Filters (not installed): the random numbers of the clouds the
// module generates (vtkFeatureModelSource, vtkMeshFeatureSampler).
#ifndef vtkFeaturePointsRandom_h
#define vtkFeaturePointsRandom_h

#include <cmath>
#include <random>

namespace featurepoints
{
/**
 * Random numbers defined bit for bit by the standard (mt19937_64) and by this header (the
 * conversions; the standard distributions are not), so that a seed gives the same cloud with
 * every standard library.
 */
struct Random
{
  std::mt19937_64 Engine;
  explicit Random(unsigned int seed)
    : Engine(seed)
  {
  }
  // Uniform in [0, 1): the top 53 bits of the engine's output.
  double Uniform() { return static_cast<double>(this->Engine() >> 11) * (1.0 / 9007199254740992.0); }
  // Standard normal, Box-Muller; 1 - u keeps the logarithm finite.
  double Gaussian()
  {
    const double u = 1.0 - this->Uniform();
    const double v = this->Uniform();
    return std::sqrt(-2.0 * std::log(u)) * std::cos(2.0 * 3.14159265358979323846 * v);
  }
};
} // namespace featurepoints

#endif
