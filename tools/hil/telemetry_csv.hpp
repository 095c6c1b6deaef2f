#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "control/supervisor.hpp"

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

  [[nodiscard]] bool in_control() const {
    return state == control::SupervisorState::kRun || state == control::SupervisorState::kDegraded;
  }
};

// Reads the controller's telemetry CSV; throws InputError "file:line: column 'x': message".
std::vector<TelemetryRow> parse_telemetry_csv(std::string_view text, const std::string& name);
std::vector<TelemetryRow> read_telemetry_csv(const std::string& path);

// A state change in the telemetry: the row where it took effect.
struct StateChange {
  std::uint64_t cycle = 0;
  double time = 0.0;
  control::SupervisorState from = control::SupervisorState::kInit;
  control::SupervisorState to = control::SupervisorState::kInit;
  control::Trigger trigger = control::Trigger::kNone;
};
[[nodiscard]] std::vector<StateChange> state_changes(const std::vector<TelemetryRow>& rows);
// "RUN -> SAFE (sensor_stale) at cycle 2345 (2.345 s)"
[[nodiscard]] std::string to_string(const StateChange& c);

}  // namespace mrd::tools
