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
  }
  return "unknown";
}

SampleCheck SampleChecker::check(const std::optional<hal::DisplacementSample>& sample,
                                 hal::Timestamp now) {
  if (!sample) return SampleCheck::kMissing;
  const bool repeated = last_sequence_ && *last_sequence_ == sample->sequence;
  last_sequence_ = sample->sequence;
  // A sample stamped after the cycle's release time (the bus thread got it meanwhile) is new.
  if (repeated || now - sample->timestamp > max_age_) return SampleCheck::kStale;
  if (!sample->usable()) return SampleCheck::kCorrupted;
  if (!std::isfinite(sample->value)) return SampleCheck::kNotFinite;
  if (sample->value < min_ || sample->value > max_) return SampleCheck::kOutOfRange;
  if (frozen_periods_ > 0) {
    // Capped: a sensor frozen for weeks must not count its way back to fresh.
    repeats_ = has_value_ && sample->value == held_ ? std::min(repeats_ + 1, frozen_periods_ + 1) : 0;
    if (repeats_ > frozen_periods_) return SampleCheck::kFrozen;
  }
  held_interval_ = has_value_ ? sample->timestamp - held_at_ : hal::Timestamp{};
  held_at_ = sample->timestamp;
  held_ = sample->value;
  has_value_ = true;
  return SampleCheck::kFresh;
}

model::SampleTiming SampleChecker::timing(SampleCheck check, hal::Timestamp now) const {
  using Seconds = std::chrono::duration<double>;
  return {check == SampleCheck::kFresh, Seconds(held_interval_).count(), Seconds(now - held_at_).count()};
}

}  // namespace mrd::control
