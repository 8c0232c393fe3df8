#include "symmetry_segmentation/synthetic/random.h"

#include <cmath>

namespace symmetry_segmentation {
namespace synthetic {

Random::Random(uint64_t seed) : engine_(static_cast<std::mt19937::result_type>(seed ^ (seed >> 32))) {}

double Random::uniform() {
  // 27 + 26 bits from two 32-bit draws, offset by half a step so 0 and 1 never occur.
  const uint64_t a = engine_() >> 5;
  const uint64_t b = engine_() >> 6;
  return (static_cast<double>(a * 67108864ULL + b) + 0.5) / 9007199254740992.0;
}

double Random::uniform(double low, double high) { return low + (high - low) * uniform(); }

int Random::uniformInt(int low, int high) {
  const double span = static_cast<double>(high) - static_cast<double>(low) + 1.0;
  const int value = low + static_cast<int>(std::floor(uniform() * span));
  return value > high ? high : value;
}

double Random::normal(double mean, double sigma) {
  const double u1 = uniform();
  const double u2 = uniform();
  return mean + sigma * std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * M_PI * u2);
}

bool Random::chance(double probability) { return uniform() < probability; }

uint64_t deriveSeed(uint64_t master_seed, uint64_t stream) {
  uint64_t z = master_seed + 0x9E3779B97F4A7C15ULL * (stream + 1);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

}  // namespace synthetic
}  // namespace symmetry_segmentation
