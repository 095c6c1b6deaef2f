#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <optional>
#include <string_view>

#include "control/sample_check.hpp"
#include "hal/clock.hpp"
#include "common/single_writer_counter.hpp"
#include "common/validation_report.hpp"

namespace mrd::control {

// The supervisor's states. INIT and SAFE drive the same outputs (fail-safe current, enable as
// configured); RUN and DEGRADED let the control law drive the coil. Table: docs/FIRMWARE.md.
enum class SupervisorState : std::uint8_t { kInit, kRun, kDegraded, kSafe, kCount };

// Why a transition happened. The same trigger names the soft step (RUN -> DEGRADED) and the
// hard one (-> SAFE) of a problem that lasts; the counts tell them apart by (from, to).
enum class Trigger : std::uint8_t {
  kNone,
  kGoodPeriods,           // enough consecutive good periods: INIT/SAFE -> RUN, DEGRADED -> RUN
  kSampleMissing,         // no fresh sample this period (nothing new, repeated, or too old)
  kSensorStale,           // more than stale_periods periods without a fresh usable sample
  kSampleOutOfRange,      // outside [displacement_min, displacement_max]
  kSampleNotFinite,       // NaN or infinite
  kSampleCorrupted,       // checksum/decode failure or sensor fault flag
  kSampleFrozen,          // new samples repeating one value for more than frozen_periods
  kSampleJump,            // a sample further from the one before than max_speed allows
  kSampleFromFuture,      // a sample stamped ahead of the cycle by more than the allowed age
  kDriverFault,           // the driver fault line is set
  kFaultLineUnreadable,   // the driver fault line cannot be read
  kCurrentDisagreement,   // measured current differs from the setpoint by more than the tolerance
  kSetpointWriteFailed,   // the driver refused or could not take the setpoint
  kSetpointRefused,       // the device answered queued setpoints with a refusal
  kReadbackLost,          // the driver's measured current stopped arriving
  kLineWriteFailed,       // the enable or heartbeat line could not be written
  kDisableFailed,         // the enable line could not be set low while the driver must be off
  kObserverRecovery,      // the observer's J-A state went non-finite and was reset
  kCommandNotFinite,      // the control law produced a non-finite current
  kOverrun,               // the previous cycle overran its period
  kRepeatedOverruns,      // overrun_limit overruns without overrun_window clean periods between
  kShutdown,              // SIGTERM/SIGINT (SIGHUP re-checks the config): SAFE and stay there
  kOperatorClear,         // an operator cleared the latch (SAFE stays SAFE until good periods)
  // Force mode: the outer controller's demand, judged as the LVDT's samples are.
  kDemandMissing,         // no fresh demand this period (nothing new, repeated, or too old)
  kDemandStale,           // more than demand_stale_periods periods without a fresh usable demand
  kDemandOutOfRange,      // |demand| above [force] demand_range
  kDemandNotFinite,       // NaN or infinite
  kDemandCorrupted,       // checksum/decode failure
  kDemandFromFuture,      // stamped ahead of the cycle by more than the allowed age
  kLinkTimeout,           // INIT: the driver's link was still down link_timeout after start
  kBusStalled,            // a bus I/O thread stopped making progress: enable off, even in SAFE
  kCount
};

[[nodiscard]] std::string_view to_string(SupervisorState s);
[[nodiscard]] std::string_view to_string(Trigger t);

// Safety limits. Times are in control periods, so they scale with the rate.
struct SupervisorConfig {
  double displacement_min = -0.050;  // [m]
  double displacement_max = 0.050;   // [m]
  int stale_periods = 5;             // SAFE after more than this many periods without a fresh sample
  int bad_sample_periods = 3;        // SAFE after this many consecutive NaN/out-of-range/corrupted/frozen
  int frozen_periods = 0;            // a sample repeating its value exactly more than this often in a
                                     // row is frozen (0: no check; a rig at rest reads one value)
  double current_tolerance = 0.1;    // [A] |measured - setpoint| above this disagrees
  int current_disagreement_periods = 10;  // SAFE after this many consecutive disagreeing periods
  int write_failure_periods = 3;     // SAFE after this many consecutive failed setpoint writes, or
                                     // this many refused setpoints without one accepted between
  int readback_timeout_periods = 50; // SAFE when the measured current has not arrived for more than
                                     // this many periods (0: no readback expected) ...
  bool require_readback = false;     // ... counted from the start, not only once one has arrived
  int line_failure_periods = 3;      // SAFE after this many consecutive periods with a failed
                                     // enable or heartbeat write; latched when disabling fails
  int observer_recovery_periods = 3; // SAFE after observer recoveries in this many consecutive periods
  double max_speed = 2.0;            // [m/s] a displacement moving faster between two samples jumps (0: off)
  int driver_fault_limit = 3;        // SAFE latches (until an operator clears it) at this many
  int driver_fault_window = 60000;   // driver-side SAFE entries within this many periods
  int overrun_limit = 3;             // SAFE after this many overruns ...
  int overrun_window = 1000;         // ... with fewer than this many clean periods between two
  double fail_safe_current = 0.0;    // [A] in INIT and SAFE
  bool enable_in_safe = false;       // driver enable line in INIT and SAFE
  int recovery_periods = 200;        // M: good periods before INIT/SAFE -> RUN
  int degraded_clear_periods = 10;   // good periods before DEGRADED -> RUN
  double demand_range = 60e3;        // force mode: [N] a demand above this in magnitude is out of
                                     // range (the file's [force] demand_range)
  int demand_stale_periods = 5;      // force mode: SAFE after more than this many periods without a
                                     // fresh demand (the file's [force] demand_max_age)
  double link_timeout = 2.0;         // [s] INIT: SAFE when the driver's link is still down this long
                                     // after the first period (a device's boot time, not periods)

  [[nodiscard]] ValidationReport validate() const;  // field paths relative to [safety]
};

// What the loop observed this period. Everything the supervisor judges arrives here.
struct SupervisorInputs {
  SampleCheck sample = SampleCheck::kFresh;
  SampleCheck demand = SampleCheck::kFresh;  // force mode's demand (DemandChecker); fresh otherwise
  std::optional<bool> driver_fault = false;  // nullopt: the line could not be read
  bool current_disagrees = false;            // judged by the loop, only when a reading exists
  bool setpoint_write_failed = false;        // the previous period's write
  bool link_down = false;                    // ... because it found no link (queued for when it
                                             // comes): in INIT a wait, else a failed write
  std::uint32_t setpoints_refused = 0;       // refusals the device reported since the previous period
  bool setpoint_accepted = false;            // and whether it accepted one meanwhile
  bool readback_lost = false;                // judged by the loop: no reading for too long
  bool line_write_failed = false;            // the previous period's enable or heartbeat write
  bool disable_failed = false;               // ... and it was the enable line going low
  bool observer_recovered = false;           // the observer reset its J-A state this period
  bool bus_stalled = false;                  // a bus I/O thread is hung: its setpoints go nowhere
  std::uint32_t overruns = 0;                // periods missed before this one
};

struct SupervisorDecision {
  SupervisorState state = SupervisorState::kInit;
  Trigger trigger = Trigger::kNone;  // of this period's transition, kNone without one
  bool in_control = false;           // RUN or DEGRADED: the control law drives the coil
  bool enable = false;               // driver enable line
  bool toggle_heartbeat = false;     // only while in control
  bool latched = false;              // SAFE holds until an operator clears it
};

// Transition counts by (from, to, trigger). Written by the loop thread only, read by any thread
// (SingleWriterCounter: no locks, no allocation).
class TransitionCounts {
 public:
  static constexpr std::size_t kStates = static_cast<std::size_t>(SupervisorState::kCount);
  static constexpr std::size_t kTriggers = static_cast<std::size_t>(Trigger::kCount);

  void count(SupervisorState from, SupervisorState to, Trigger why) {
    counts_[index(from, to, why)].add();
  }
  [[nodiscard]] std::uint64_t get(SupervisorState from, SupervisorState to, Trigger why) const {
    return counts_[index(from, to, why)].get();
  }
  [[nodiscard]] std::uint64_t total() const;
  // Every entry into `to` from another state, whatever the trigger (SAFE -> SAFE, a latch or
  // an operator's clear, is not an entry).
  [[nodiscard]] std::uint64_t into(SupervisorState to) const;

 private:
  static std::size_t index(SupervisorState from, SupervisorState to, Trigger why) {
    return (static_cast<std::size_t>(from) * kStates + static_cast<std::size_t>(to)) * kTriggers +
           static_cast<std::size_t>(why);
  }
  std::array<SingleWriterCounter, kStates * kStates * kTriggers> counts_{};
};

// The safety state machine: a pure function of (state, inputs, now). It reads no clock and does
// no I/O, so tests script hours of faults in milliseconds. Transitions and reaction times are
// tabulated in docs/FIRMWARE.md.
class Supervisor {
 public:
  explicit Supervisor(const SupervisorConfig& config);

  // The largest driver_fault_limit validate() accepts: the size of the latch's ring.
  static constexpr std::size_t kMaxDriverFaultLimit = 16;

  SupervisorDecision step(const SupervisorInputs& in, hal::Timestamp now);
  // This period's command cannot be written: SAFE now, with `why`, and the decision that holds.
  SupervisorDecision veto(Trigger why, hal::Timestamp now);
  // From the next step on: SAFE with kShutdown, and no recovery.
  void request_shutdown() { shutdown_ = true; }
  // An operator's clear: a latched SAFE may recover again after recovery_periods good periods.
  void clear_latch(hal::Timestamp now);

  [[nodiscard]] SupervisorState state() const { return state_; }
  [[nodiscard]] bool latched() const { return latched_; }
  [[nodiscard]] hal::Timestamp since() const { return since_; }  // time of the last transition
  [[nodiscard]] const TransitionCounts& transitions() const { return counts_; }
  [[nodiscard]] const SupervisorConfig& config() const { return config_; }

 private:
  void update_counters(const SupervisorInputs& in);
  [[nodiscard]] Trigger hard_trigger(const SupervisorInputs& in) const;
  [[nodiscard]] Trigger soft_trigger(const SupervisorInputs& in) const;
  void go(SupervisorState to, Trigger why, hal::Timestamp now, SupervisorDecision& d);
  void count_driver_fault();
  void fill(SupervisorDecision& d) const;

  SupervisorConfig config_;
  hal::Timestamp link_timeout_;
  SupervisorState state_ = SupervisorState::kInit;
  hal::Timestamp since_{};
  std::optional<hal::Timestamp> started_;  // the first step's time, the link timeout's origin
  bool shutdown_ = false;
  bool latched_ = false;
  bool bus_stalled_ = false;  // this period's: the enable line is the only way left to the coil

  // Consecutive-period counters.
  std::int64_t without_sample_ = 0;
  std::int64_t bad_samples_ = 0;
  std::int64_t without_demand_ = 0;
  std::int64_t bad_demands_ = 0;
  std::int64_t disagreeing_ = 0;
  std::int64_t failed_writes_ = 0;
  std::int64_t refused_ = 0;         // refused setpoints since the last accepted one
  std::int64_t failed_lines_ = 0;
  std::int64_t failed_disables_ = 0;
  std::int64_t recovering_ = 0;
  std::int64_t periods_ = 0;         // steps taken, the driver-fault window's clock
  // Periods of the last driver_fault_limit driver-side SAFE entries, a ring.
  std::array<std::int64_t, kMaxDriverFaultLimit> driver_faults_{};
  std::size_t driver_fault_count_ = 0;
  std::int64_t good_ = 0;
  std::int64_t overruns_ = 0;        // since the last overrun_window clean periods
  std::int64_t clean_periods_ = 0;   // since the last overrun

  TransitionCounts counts_;
};

}  // namespace mrd::control
