#pragma once

#include <algorithm>

namespace mrd::model {

// Limits a command to [lo, hi] and to a rate of change per sample: what a coil driver can do.
class SlewLimiter {
 public:
  SlewLimiter(double lo, double hi, double max_rate, double sample_period)
      : lo_(lo), hi_(hi), max_step_(max_rate * sample_period) {}

  // The reachable interval for the next sample.
  [[nodiscard]] double lowest_next() const { return std::max(lo_, value_ - max_step_); }
  [[nodiscard]] double highest_next() const { return std::min(hi_, value_ + max_step_); }

  double update(double request) {
    value_ = std::clamp(request, lowest_next(), highest_next());
    return value_;
  }
  [[nodiscard]] double value() const { return value_; }
  void reset(double value = 0.0) { value_ = std::clamp(value, lo_, hi_); }

 private:
  double lo_;
  double hi_;
  double max_step_;
  double value_ = 0.0;
};

}  // namespace mrd::model
