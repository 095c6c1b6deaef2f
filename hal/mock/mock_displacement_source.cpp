#include "hal/mock/mock_displacement_source.hpp"

#include <chrono>
#include <limits>

namespace mrd::hal::mock {

bool MockDisplacementSource::drop_this_sample(Timestamp now) {
  const ScriptedFault* f = script_.active(FaultKind::kDroppedSample, now);
  if (f == nullptr) return false;
  const auto period = f->parameter >= 1.0 ? static_cast<std::uint64_t>(f->parameter) : 1u;
  return ++drop_phase_ % period == 0;
}

std::optional<DisplacementSample> MockDisplacementSource::latest() {
  const Timestamp now = clock_.now();
  if (script_.is_active(FaultKind::kSensorTimeout, now)) return std::nullopt;
  if (drop_this_sample(now)) {
    ++sequence_;  // the sensor sent it; the bus lost it
    ++dropped_;
    gap_pending_ = true;
    return std::nullopt;
  }
  if (last_ && script_.is_active(FaultKind::kStaleValue, now)) return last_;

  DisplacementSample s{truth_, now, ++sequence_, kSampleValid};
  if (gap_pending_) s.flags |= kSampleSequenceGap;
  gap_pending_ = false;
  if (script_.is_active(FaultKind::kNotANumber, now)) {
    s.value = std::numeric_limits<double>::quiet_NaN();
  }
  if (const ScriptedFault* f = script_.active(FaultKind::kOutOfRange, now)) s.value = f->parameter;
  if (const ScriptedFault* f = script_.active(FaultKind::kDisplacementJump, now)) {
    if (!jump_off_) s.value += f->parameter;
    jump_off_ = !jump_off_;
  } else {
    jump_off_ = false;
  }
  if (const ScriptedFault* f = script_.active(FaultKind::kFutureTimestamp, now)) {
    s.timestamp += std::chrono::duration_cast<Timestamp>(std::chrono::duration<double>(f->parameter));
  }
  if (const ScriptedFault* f = script_.active(FaultKind::kOldTimestamp, now)) {
    s.timestamp -= std::chrono::duration_cast<Timestamp>(std::chrono::duration<double>(f->parameter));
  }
  if (script_.is_active(FaultKind::kCorruptedFrame, now)) s.flags = kSampleCorrupted;
  if (script_.is_active(FaultKind::kFrozenValue, now)) {
    if (!frozen_) frozen_ = last_ ? last_->value : s.value;
    s.value = *frozen_;
  } else {
    frozen_.reset();
  }
  last_ = s;
  return s;
}

}  // namespace mrd::hal::mock
