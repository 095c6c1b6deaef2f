#pragma once

#include <optional>
#include <string>

namespace mrd::tools {

// mrd-hil-report's job: a hardware-in-the-loop run in one page. Joins mrd-controller's
// telemetry with mrd-plant's log by time, prints the supervisor's transitions and the
// observer's force error against the plant's true force, and, with a plot folder, plots force
// against displacement (the paper's Fig. 14).
struct HilReportOptions {
  std::string telemetry_path;
  std::string plant_path;
  // CLOCK_MONOTONIC [s] of each file's time 0; without them, the files' time-origin lines.
  std::optional<double> controller_t0;
  std::optional<double> plant_t0;
  std::string plot_dir;  // empty: no plot; otherwise an existing, writable folder
};

// Prints the report on stdout; returns the exit code (mrd::cli: ok, bad input, I/O).
int print_hil_report(const HilReportOptions& options);

}  // namespace mrd::tools
