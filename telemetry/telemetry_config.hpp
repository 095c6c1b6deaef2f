#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "common/validation_report.hpp"

namespace mrd::telemetry {

struct TelemetryConfig {
  std::string path;          // CSV file; empty: no telemetry. Relative paths start in `directory`.
  // The only directory telemetry may write to: `path` must resolve (symbolic links followed)
  // to a file below it. "." is the working directory; the systemd unit starts in /var/log/mrd.
  std::string directory = ".";
  int decimation = 1;        // one record every N cycles
  int ring_size = 8192;      // records the ring holds between two writer passes
  double flush_period = 0.05;  // [s] how often the writer drains the ring
  // Each start writes its own file, numbered after the ones already there ("run.csv" becomes
  // run-0001.csv, run-0002.csv, ...), so a restart never truncates the last run's record.
  // false: `path` itself, truncated (mrd-controller --telemetry names an exact file).
  bool per_run = true;
  // The most a file may grow to [bytes]; the rest of the run is counted, not written. 0: no cap.
  std::int64_t max_bytes = 536870912;

  [[nodiscard]] bool enabled() const { return !path.empty(); }
  // `path` resolved against `directory`, what the writer opens.
  [[nodiscard]] std::string resolved_path() const;
  [[nodiscard]] ValidationReport validate() const;  // field paths relative to [telemetry]
};

}  // namespace mrd::telemetry
