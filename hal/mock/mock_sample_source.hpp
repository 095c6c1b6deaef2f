#pragma once

#include <cstdint>
#include <optional>

#include "hal/clock.hpp"
#include "hal/mock/fault_script.hpp"
#include "hal/sample_source.hpp"

namespace mrd::hal::mock {

// The script's faults one channel answers to, each as the FaultKind that triggers it on that
// channel; a fault with no kind never happens to it. What each does: FaultKind's comments.
struct SampleFaults {
  std::optional<FaultKind> missing;           // no sample
  std::optional<FaultKind> dropped;           // every parameter-th sample lost; the next shows a gap
  std::optional<FaultKind> stale;             // the previous sample again
  std::optional<FaultKind> not_finite;        // value NaN, flagged valid
  std::optional<FaultKind> out_of_range;      // value = parameter, flagged valid
  std::optional<FaultKind> jump;              // value += parameter on every other sample
  std::optional<FaultKind> future_timestamp;  // stamped parameter [s] ahead of the clock
  std::optional<FaultKind> old_timestamp;     // stamped parameter [s] behind the clock
  std::optional<FaultKind> corrupted;         // flagged corrupted, not valid
  std::optional<FaultKind> frozen;            // new samples that keep the value from before
};

// The LVDT's: every sample fault the script knows.
inline constexpr SampleFaults kLvdtFaults{
    .missing = FaultKind::kSensorTimeout,
    .dropped = FaultKind::kDroppedSample,
    .stale = FaultKind::kStaleValue,
    .not_finite = FaultKind::kNotANumber,
    .out_of_range = FaultKind::kOutOfRange,
    .jump = FaultKind::kDisplacementJump,
    .future_timestamp = FaultKind::kFutureTimestamp,
    .old_timestamp = FaultKind::kOldTimestamp,
    .corrupted = FaultKind::kCorruptedFrame,
    .frozen = FaultKind::kFrozenValue,
};
// The force demand's: missing, stale, not finite, out of range.
inline constexpr SampleFaults kDemandFaults{
    .missing = FaultKind::kDemandMissing,
    .stale = FaultKind::kDemandStale,
    .not_finite = FaultKind::kDemandNotFinite,
    .out_of_range = FaultKind::kDemandOutOfRange,
};

// One channel's sensor as the test or the simulated rig sets it (set_value, SI): one new sample
// per call, stamped with the clock, with the script's faults for this channel on top; or none
// while silenced (set_silent), or an unusable one while set_faulty. The plant lives elsewhere:
// hal knows no physics. Allocation-free.
class MockSampleSource final : public SampleSource {
 public:
  MockSampleSource(const Clock& clock, const FaultScript& script, const SampleFaults& faults)
      : clock_(clock), script_(script), faults_(faults) {}

  void set_value(double si) { value_ = si; }
  void set_silent(bool silent) { silent_ = silent; }
  void set_faulty(bool faulty) { faulty_ = faulty; }
  [[nodiscard]] std::optional<Sample> latest() override;

  [[nodiscard]] std::uint64_t samples_dropped() const { return dropped_; }

 private:
  [[nodiscard]] const ScriptedFault* active(const std::optional<FaultKind>& kind, Timestamp now) const {
    return kind ? script_.active(*kind, now) : nullptr;
  }
  bool drop_this_sample(Timestamp now);

  const Clock& clock_;
  const FaultScript& script_;
  SampleFaults faults_;
  double value_ = 0.0;
  bool silent_ = false;
  bool faulty_ = false;
  std::optional<Sample> last_;
  std::optional<double> frozen_;  // the value a frozen sensor keeps
  std::uint32_t sequence_ = 0;
  std::uint64_t dropped_ = 0;
  std::uint64_t drop_phase_ = 0;
  bool gap_pending_ = false;
  bool jump_off_ = false;  // the jump fault: this sample goes without the offset
};

}  // namespace mrd::hal::mock
