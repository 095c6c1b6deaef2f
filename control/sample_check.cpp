#include "control/sample_check.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace mrd::control {

std::string_view to_string(SampleCheck c) {
  switch (c) {
    case SampleCheck::kFresh: return "fresh";
    case SampleCheck::kMissing: return "missing";
    case SampleCheck::kStale: return "stale";
    case SampleCheck::kCorrupted: return "corrupted";
    case SampleCheck::kNotFinite: return "not_finite";
    case SampleCheck::kOutOfRange: return "out_of_range";
    case SampleCheck::kFrozen: return "frozen";
    case SampleCheck::kJump: return "jump";
    case SampleCheck::kFromFuture: return "from_future";
  }
  return "unknown";
}

SampleCheck SampleChecker::check(const std::optional<hal::Sample>& sample, hal::Timestamp now) {
  if (!sample) return SampleCheck::kMissing;
  const bool repeated = last_sequence_ && *last_sequence_ == sample->sequence;
  last_sequence_ = sample->sequence;
  if (repeated || now - sample->timestamp > limits_.max_age) return SampleCheck::kStale;
  // A sample stamped after the cycle's release time (the bus thread got it meanwhile) is new;
  // beyond the allowed age it is a clock that cannot be trusted, and with it the velocity.
  if (sample->timestamp - now > limits_.max_age) return SampleCheck::kFromFuture;
  if (!sample->usable()) return SampleCheck::kCorrupted;
  if (!std::isfinite(sample->value)) return SampleCheck::kNotFinite;
  if (sample->value < limits_.min || sample->value > limits_.max) return SampleCheck::kOutOfRange;
  if (jumps(*sample)) return SampleCheck::kJump;
  if (limits_.frozen_periods > 0) {
    // Capped: a sensor frozen for weeks must not count its way back to fresh.
    repeats_ = has_value_ && sample->value == held_ ? std::min(repeats_ + 1, limits_.frozen_periods + 1) : 0;
    if (repeats_ > limits_.frozen_periods) return SampleCheck::kFrozen;
  }
  held_interval_ = has_value_ ? sample->timestamp - held_at_ : hal::Timestamp{};
  held_at_ = sample->timestamp;
  held_ = sample->value;
  has_value_ = true;
  return SampleCheck::kFresh;
}

bool SampleChecker::jumps(const hal::Sample& s) {
  const std::optional<hal::Sample> before = previous_;
  previous_ = s;
  if (limits_.max_speed <= 0.0 || !before) return false;
  using Seconds = std::chrono::duration<double>;
  // At least one microsecond: two samples with one timestamp may still differ by noise.
  const double dt = std::max(Seconds(s.timestamp - before->timestamp).count(), 1e-6);
  return std::fabs(s.value - before->value) > limits_.max_speed * dt;
}

model::SampleTiming SampleChecker::timing(SampleCheck check, hal::Timestamp now) const {
  using Seconds = std::chrono::duration<double>;
  return {.fresh = check == SampleCheck::kFresh,
          .interval = Seconds(held_interval_).count(),
          .age = Seconds(now - held_at_).count()};
}

}  // namespace mrd::control
