#pragma once

#include <cstdint>
#include <initializer_list>
#include <string_view>
#include <vector>

#include "hal/clock.hpp"
#include "common/validation_report.hpp"

namespace mrd::hal::mock {

enum class FaultKind : std::uint8_t {
  kSensorTimeout,      // no sample at all
  kStaleValue,         // the previous sample again: same value, timestamp and sequence
  kFrozenValue,        // new samples (sequence, timestamp) that keep the last value before the fault
  kNotANumber,         // value NaN, flagged valid (the sensor does not know)
  kOutOfRange,         // value = parameter [m], flagged valid
  kCorruptedFrame,     // flagged corrupted (bad checksum/decode), not valid
  kDroppedSample,      // every parameter-th sample is lost (1 = all); the next one shows a gap
  kDriverFault,        // the driver fault line reads set
  kFaultLineUnreadable,  // the driver fault line cannot be read
  kCurrentBias,        // measured current = setpoint + parameter [A]
  kDriverWriteFails,   // write_setpoint() fails with an I/O error
  kReadbackSilent,     // the driver stops reporting its measured current
  kSetpointRefused,    // write_setpoint() queues, and the device refuses each write
  kEnableWriteFails,   // set_enable() fails with an I/O error
  kHeartbeatWriteFails,  // the heartbeat write fails with an I/O error
  kDisplacementJump,   // value += parameter [m] on every other sample from the first, flagged
                       // valid: a sensor jumping back and forth (one sample long: a spike)
  kFutureTimestamp,    // the sample's timestamp is parameter [s] ahead of the clock
  // The force demand (force mode), as the LVDT's faults above:
  kDemandMissing,      // no demand at all
  kDemandStale,        // the previous demand again: same value, timestamp and sequence
  kDemandNotFinite,    // value NaN, flagged valid
  kDemandOutOfRange,   // value = parameter [N], flagged valid
  kOldTimestamp,       // a new sample (sequence number) stamped parameter [s] before the clock:
                       // a bus that delivers late
  kCount
};
[[nodiscard]] std::string_view to_string(FaultKind k);

// Active for start <= now < end, on the injected clock.
struct ScriptedFault {
  FaultKind kind = FaultKind::kSensorTimeout;
  Timestamp start{};
  Timestamp end{};
  double parameter = 0.0;
};

// The time of control cycle `cycle` at a fixed period: scripts written in cycles read well.
[[nodiscard]] constexpr Timestamp cycle_time(std::int64_t cycle, Timestamp period) {
  return cycle * period;
}

// A fixed list of faults, built before the run. Queries walk the list without allocating.
class FaultScript {
 public:
  FaultScript() = default;
  FaultScript(std::initializer_list<ScriptedFault> faults) : faults_(faults) {}

  FaultScript& add(const ScriptedFault& f) {
    faults_.push_back(f);
    return *this;
  }
  // The first matching fault active at `now`, or nullptr.
  [[nodiscard]] const ScriptedFault* active(FaultKind kind, Timestamp now) const;
  [[nodiscard]] bool is_active(FaultKind kind, Timestamp now) const {
    return active(kind, now) != nullptr;
  }
  [[nodiscard]] const std::vector<ScriptedFault>& faults() const { return faults_; }
  [[nodiscard]] ValidationReport validate() const;  // fields "faults[i].end" etc.

 private:
  std::vector<ScriptedFault> faults_;
};

}  // namespace mrd::hal::mock
