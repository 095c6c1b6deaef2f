#pragma once

#include <functional>
#include <string>

#include <vector>

#include "tests/hil/child_process.hpp"

#include "tools/hil/telemetry_csv.hpp"
#include "record/recorded_run.hpp"

namespace mrd::test {

// One hardware-in-the-loop run: mrd-plant and mrd-controller as two processes on a bus.
struct HilScenario {
  std::string name;                 // files go to <temp>/mrd_hil_<name>/
  std::string controller_toml;      // the controller's config (its buses, safety, ...)
  std::string plant_toml;           // [profile], [faults.*], ... (plant.controller_config and
                                    // plant.log are set by the run)
  double controller_duration = 4.0;  // [s]
  bool ephemeral_port = true;       // Modbus TCP: the plant picks a port, the controller is told
  // Called while the controller runs (e.g. to watch GPIO lines); its text lands in `observed`.
  std::function<std::string(ChildProcess&)> while_running;
  // >= 0: the controller starts first and the plant this long after it [s] (Modbus TCP, on a
  // port the run picks); < 0: the plant first, the controller once it serves.
  double plant_delay = -1.0;
};

struct HilResult {
  int controller_exit = -1;
  int plant_exit = -1;
  std::string controller_output;
  std::string plant_output;
  std::vector<tools::TelemetryRow> telemetry;
  record::RecordedRun plant_log;
  double controller_t0 = 0.0;  // CLOCK_MONOTONIC of the telemetry's time 0 [s]
  double offset = 0.0;  // plant log time of the telemetry's time 0 [s]
  double fault_origin = 0.0;  // plant log time of the faults' time 0 (the first command) [s]
  std::string observed;  // what while_running reported
  std::string failure;  // why the run could not be made ("" when it was)

  // The plant's time of a telemetry row, and its time on the faults' clock.
  [[nodiscard]] double plant_time(const tools::TelemetryRow& r) const { return r.time + offset; }
  [[nodiscard]] double fault_time(const tools::TelemetryRow& r) const { return plant_time(r) - fault_origin; }
};

// Starts the plant, waits until it serves, runs the controller for its duration, stops the
// plant, and reads both files. Bounded waits throughout.
HilResult run_hil(const HilScenario& scenario);

// Every state change, for failure messages.
std::string transitions(const HilResult& r);

// What a failed expectation on a run prints: the supervisor's transitions, the sample checks
// where they change, and both processes' output (SCOPED_TRACE(diagnosis(r)) in each test).
std::string diagnosis(const HilResult& r);

// Consecutive rows ending at `index` (inclusive, going back) for which `pred` holds.
template <typename Pred>
std::size_t run_length_before(const std::vector<tools::TelemetryRow>& rows, std::size_t index, Pred pred) {
  std::size_t n = 0;
  for (std::size_t i = index + 1; i-- > 0 && pred(rows[i]);) ++n;
  return n;
}

}  // namespace mrd::test
