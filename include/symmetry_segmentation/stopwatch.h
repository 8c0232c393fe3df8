#pragma once
#include <chrono>

namespace symmetry_segmentation {

/// Wall-clock milliseconds since construction or the last lap().
class Stopwatch {
 public:
  double elapsedMs() const {
    return std::chrono::duration<double, std::milli>(Clock::now() - start_).count();
  }
  double lap() {
    const double ms = elapsedMs();
    start_ = Clock::now();
    return ms;
  }

 private:
  using Clock = std::chrono::steady_clock;
  Clock::time_point start_ = Clock::now();
};

}  // namespace symmetry_segmentation
