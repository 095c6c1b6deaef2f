#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "control/supervisor.hpp"
#include "record/recorded_run.hpp"

namespace mrd::tools {

// One row of mrd-controller's telemetry CSV (firmware/csv_telemetry_writer), in SI units.
struct TelemetryRow {
  std::uint64_t cycle = 0;
  double time = 0.0;               // [s] from the first record
  double displacement = 0.0;       // [m]
  std::string sample;              // SampleCheck name
  double measured_current = 0.0;   // [A], NaN when none
  double scheduled_current = 0.0;  // [A]
  double law_current = 0.0;        // [A]
  double setpoint = 0.0;           // [A]
  double target_B = 0.0;           // [T]
  double B = 0.0;                  // [T]
  double velocity = 0.0;           // [m/s]
  double force = 0.0;              // observer [N]
  control::SupervisorState state = control::SupervisorState::kInit;
  control::Trigger trigger = control::Trigger::kNone;
  std::uint32_t overruns = 0;
  bool enable = false;
  bool latched = false;
  std::uint64_t recoveries = 0;  // the J-A observer's non-finite recoveries so far
  // Force mode's columns (zero and empty in a table4 file).
  double demand = 0.0;       // [N] the demand the law used
  double yield_force = 0.0;  // [N] Eq. 12's yield force at the law's target
  std::string demand_check;  // the demand's SampleCheck name
  bool clipped = false;      // the demand asked the damper to push: minimum force commanded
  bool reached = false;      // the inverse reached the demand within the period
  double force_scale = 0.0;  // the load-cell correction's scale on the model's yield force (1 without)
  std::uint32_t load_cell_frozen = 0;  // periods the load cell was stale or bad so far
  std::size_t line = 0;                // in the file

  [[nodiscard]] bool in_control() const {
    return state == control::SupervisorState::kRun || state == control::SupervisorState::kDegraded;
  }
};

// Records the file lacks between two kept rows: cycles skipped beyond the file's own step (its
// decimation; the ring dropped them, or a logger lost rows), or a time step over 1.5 record
// periods (the loop stalled, a logger's clock jumped).
struct TelemetryGap {
  std::size_t before = 0;     // index in rows of the last row before the gap
  double start = 0.0;         // [s] its time
  double end = 0.0;           // [s] the time of the first row after it
  std::uint64_t missing = 0;  // records missing by the cycle count
  [[nodiscard]] double duration() const { return end - start; }
};

// The controller's telemetry file: its rows, whether it has force mode's columns, and its
// time 0 on CLOCK_MONOTONIC when the file carries it (common/time_origin.hpp). Rows a logger
// spoiled are set aside as the run readers set them aside (record::RowScreen): a repeated row
// ("duplicate", the first kept), a time that repeats with other values or goes back, or a cycle
// that does not advance ("time_conflict"), an empty cell, or nan / inf where the writer never
// writes one ("non_finite").
struct TelemetryLog {
  std::vector<TelemetryRow> rows;
  bool force_mode = false;
  std::optional<double> time_origin;  // [s]
  double record_rate = 0.0;           // [Hz] records per second, gaps left out (record::nominal_sample_rate)
  std::vector<record::RecordedRun::SetAsideRow> set_aside_rows;
  std::vector<TelemetryGap> gaps;
};

// Reads the controller's telemetry CSV (table4 or force mode's header); throws InputError
// "file:line: column 'x': message" for a header it does not know, a ragged row, text where a
// number, count, flag or name belongs, and a file with no row left.
TelemetryLog parse_telemetry_csv(std::string_view text, const std::string& name);
TelemetryLog read_telemetry_csv(const std::string& path);

// The gaps between consecutive rows, by the rules of TelemetryGap.
[[nodiscard]] std::vector<TelemetryGap> find_gaps(const std::vector<TelemetryRow>& rows, double record_rate);
// "0.300 s from 1.200 s (lines 1203-1204): 299 records missing"
[[nodiscard]] std::string to_string(const TelemetryGap& g, const std::vector<TelemetryRow>& rows);

// A state change in the telemetry: the row where it took effect. After a gap with records missing
// that row is only the first one seen: the change took effect somewhere in the gap.
struct StateChange {
  std::uint64_t cycle = 0;
  double time = 0.0;
  control::SupervisorState from = control::SupervisorState::kInit;
  control::SupervisorState to = control::SupervisorState::kInit;
  control::Trigger trigger = control::Trigger::kNone;
  std::optional<TelemetryGap> within;  // the gap it fell in
};
[[nodiscard]] std::vector<StateChange> state_changes(const std::vector<TelemetryRow>& rows,
                                                     const std::vector<TelemetryGap>& gaps = {});
// "RUN -> SAFE (sensor_stale) at cycle 2345 (2.345 s)", or "... within a gap, after 2.100 s
// and by cycle 2345 (2.345 s)"
[[nodiscard]] std::string to_string(const StateChange& c);

}  // namespace mrd::tools
