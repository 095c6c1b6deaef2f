#include "sim/current_profile.hpp"

#include <cmath>

namespace mrd::sim {

RandomTelegraph::RandomTelegraph(double low, double high, double mean_dwell, double sample_period,
                                 std::uint64_t seed)
    : low_(low), high_(high), switch_probability_(-std::expm1(-sample_period / mean_dwell)), rng_(seed) {}

double RandomTelegraph::step() {
  if (started_ && uniform_(rng_) < switch_probability_) high_now_ = !high_now_;
  started_ = true;
  return high_now_ ? high_ : low_;
}

}  // namespace mrd::sim
