#pragma once
// Seeded random numbers that are identical on every platform: std::mt19937 is fully specified
// by the standard, but std::*_distribution are not, so the distributions are written here.

#include <cstdint>
#include <random>

namespace symmetry_segmentation {
namespace synthetic {

class Random {
 public:
  explicit Random(uint64_t seed);

  /// Uniform in the open interval (0, 1) with 53 bits of resolution.
  double uniform();
  double uniform(double low, double high);
  /// Uniform integer in [low, high] (inclusive); low <= high.
  int uniformInt(int low, int high);
  /// Normal N(mean, sigma^2) by the Box-Muller transform (always consumes two uniforms).
  double normal(double mean, double sigma);
  bool chance(double probability);

 private:
  std::mt19937 engine_;
};

/// Independent seed for a sub-stream (layout, view i, fusion...) of a master seed (splitmix64).
uint64_t deriveSeed(uint64_t master_seed, uint64_t stream);

}  // namespace synthetic
}  // namespace symmetry_segmentation
