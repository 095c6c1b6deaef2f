#pragma once

#include <cstdint>
#include <random>

namespace mrd::sim {

// A random telegraph command like Dyke's: two levels, switching after dwell times drawn from
// an exponential distribution of mean `mean_dwell` (each period switches with probability
// 1 - exp(-T / mean_dwell)). Deterministic for a seed; starts at `low`.
class RandomTelegraph {
 public:
  RandomTelegraph(double low, double high, double mean_dwell, double sample_period, std::uint64_t seed);

  double step();  // the level held over the next period

 private:
  double low_;
  double high_;
  double switch_probability_;
  bool high_now_ = false;
  bool started_ = false;
  std::mt19937_64 rng_;
  std::uniform_real_distribution<double> uniform_{0.0, 1.0};
};

}  // namespace mrd::sim
