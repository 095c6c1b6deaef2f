#include "hal/mock/mock_sample_source.hpp"

#include <chrono>
#include <limits>

namespace mrd::hal::mock {

namespace {

Timestamp seconds(double s) { return std::chrono::duration_cast<Timestamp>(std::chrono::duration<double>(s)); }

}  // namespace

bool MockSampleSource::drop_this_sample(Timestamp now) {
  const ScriptedFault* f = active(faults_.dropped, now);
  if (f == nullptr) return false;
  const auto period = f->parameter >= 1.0 ? static_cast<std::uint64_t>(f->parameter) : 1u;
  return ++drop_phase_ % period == 0;
}

std::optional<Sample> MockSampleSource::latest() {
  const Timestamp now = clock_.now();
  if (silent_ || active(faults_.missing, now) != nullptr) return std::nullopt;
  if (drop_this_sample(now)) {
    ++sequence_;  // the sensor sent it; the bus lost it
    ++dropped_;
    gap_pending_ = true;
    return std::nullopt;
  }
  if (last_ && active(faults_.stale, now) != nullptr) return last_;

  Sample s{value_, now, ++sequence_, kSampleValid};
  if (gap_pending_) s.flags |= kSampleSequenceGap;
  gap_pending_ = false;
  if (faulty_) s.flags |= kSampleSensorFault;
  if (active(faults_.not_finite, now) != nullptr) s.value = std::numeric_limits<double>::quiet_NaN();
  if (const ScriptedFault* f = active(faults_.out_of_range, now)) s.value = f->parameter;
  if (const ScriptedFault* f = active(faults_.jump, now)) {
    if (!jump_off_) s.value += f->parameter;
    jump_off_ = !jump_off_;
  } else {
    jump_off_ = false;
  }
  if (const ScriptedFault* f = active(faults_.future_timestamp, now)) s.timestamp += seconds(f->parameter);
  if (const ScriptedFault* f = active(faults_.old_timestamp, now)) s.timestamp -= seconds(f->parameter);
  if (active(faults_.corrupted, now) != nullptr) s.flags = kSampleCorrupted;
  if (active(faults_.frozen, now) != nullptr) {
    if (!frozen_) frozen_ = last_ ? last_->value : s.value;
    s.value = *frozen_;
  } else {
    frozen_.reset();
  }
  last_ = s;
  return s;
}

}  // namespace mrd::hal::mock
