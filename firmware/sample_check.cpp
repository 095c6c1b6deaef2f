#include "firmware/sample_check.hpp"

#include <cmath>

namespace mrd::firmware {

std::string_view to_string(SampleCheck c) {
  switch (c) {
    case SampleCheck::kFresh: return "fresh";
    case SampleCheck::kMissing: return "missing";
    case SampleCheck::kStale: return "stale";
    case SampleCheck::kCorrupted: return "corrupted";
    case SampleCheck::kNotFinite: return "not_finite";
    case SampleCheck::kOutOfRange: return "out_of_range";
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
  held_ = sample->value;
  has_value_ = true;
  return SampleCheck::kFresh;
}

}  // namespace mrd::firmware
