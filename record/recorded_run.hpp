#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace mrd::record {

// What the run's coil channel holds.
enum class CoilSignal : std::uint8_t {
  kCurrent,         // the coil current [A] (measured, commanded, or a constant the test held)
  kCommandVoltage,  // the driver's command voltage [V]; replay needs the driver gain [A/V]
};
[[nodiscard]] std::string_view to_string(CoilSignal s);

// One recorded damper run in SI units, whatever file it came from: the readers convert at the
// edge. Time, displacement and the coil channel are always there; the other channels are empty
// vectors when the run did not record them, otherwise as long as `time`.
struct RecordedRun {
  std::string name;          // the file, for messages, plots and reports
  double sample_rate = 0.0;  // nominal [Hz]: nominal_sample_rate(time)
  CoilSignal coil_signal = CoilSignal::kCurrent;
  std::string coil_source;  // where the coil channel came from: "current_A", "--current 0.5 A", ...

  std::vector<double> time;          // [s], strictly increasing, as recorded (not shifted to 0)
  std::vector<double> displacement;  // [m]
  std::vector<double> coil;          // [A], or [V] for kCommandVoltage
  std::vector<double> force;         // [N], the measured damper force
  std::vector<double> velocity;      // [m/s], as recorded (often differenced from displacement)
  std::vector<double> B;             // [T]
  // Degrees Celsius, not kelvin: MR fluid data sheets and viscosity-temperature laws are
  // written in Celsius, and a thermal drift is a difference, which is the same in both.
  std::vector<double> temperature;
  // CLOCK_MONOTONIC [s] of time 0 when the file says (mrd-plant's log, the controller's
  // telemetry: common/time_origin.hpp), to join it with another log of the same host.
  std::optional<double> time_origin;

  // Rows the reader set aside rather than refuse the file for: a repeated row ("duplicate", one
  // kept), a time that repeats with other values or goes back ("time_conflict"), an empty, nan
  // or inf cell ("non_finite"). The screening reports them with its own spans.
  struct SetAsideRow {
    std::string_view reason;
    std::size_t line = 0;          // in the file
    std::size_t next_sample = 0;   // the sample it came before (size() when after the last)
    std::string column;            // the cell's column; empty for a whole-row reason
  };
  std::vector<SetAsideRow> set_aside_rows;

  // What the reader did that the user must know (ignored columns, dropped CAN frames), one
  // line each; reports print them.
  std::vector<std::string> notes;

  // Every per-sample channel beside time (empty where not recorded), for code that treats them
  // alike: filling a gap, dropping a row.
  [[nodiscard]] std::array<std::vector<double>*, 6> channels() {
    return {&displacement, &coil, &force, &velocity, &B, &temperature};
  }
  [[nodiscard]] std::array<const std::vector<double>*, 6> channels() const {
    return {&displacement, &coil, &force, &velocity, &B, &temperature};
  }

  [[nodiscard]] std::size_t size() const { return time.size(); }
  [[nodiscard]] double duration() const {
    return time.size() > 1 ? time.back() - time.front() : 0.0;
  }
  [[nodiscard]] bool has_force() const { return !force.empty(); }
  [[nodiscard]] bool has_velocity() const { return !velocity.empty(); }
  [[nodiscard]] bool has_B() const { return !B.empty(); }
  [[nodiscard]] bool has_temperature() const { return !temperature.empty(); }
};

// How evenly a run is sampled. Periods are time differences between consecutive samples.
struct SamplingSummary {
  double nominal_period = 0.0;  // [s], 1 / sample_rate
  double min_period = 0.0;      // [s]
  double max_period = 0.0;      // [s]
  std::size_t gaps = 0;         // periods longer than 1.5 nominal periods (lost samples)
};
[[nodiscard]] SamplingSummary summarize_sampling(const std::vector<double>& time);

// The nominal rate: the mean of the steps no longer than 1.5 times the median one. The mean, not
// the median: a time column rounded to 0.1 ms (the Dyke file, 3004.8 Hz) has steps of 0.3 and
// 0.4 ms but its mean step is exact; without the long steps: a logging gap is missing samples,
// not a slower logger. Those steps are left out only while they are rare (1 %, or 10): a time
// column coarser than the period alternates short and long steps, and then the span gives the
// rate. 0 for fewer than two samples.
[[nodiscard]] double nominal_sample_rate(const std::vector<double>& time);

// Damper rigs log between a few Hz and some tens of kHz; a rate outside [1 Hz, 1 MHz] is a
// time column in other units or a broken clock, and every time constant fitted on it would be
// nonsense.
inline constexpr double kMinSampleRate = 1.0;  // [Hz]
inline constexpr double kMaxSampleRate = 1e6;  // [Hz]
// Throws InputError naming the run when its nominal rate lies outside those bounds.
void check_sample_rate(const RecordedRun& run);

}  // namespace mrd::record
