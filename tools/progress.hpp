#pragma once

#include <cstdint>
#include <limits>
#include <string_view>

namespace mrd::tools {

// Where a long job stands: what the compute code hands its progress sink. No I/O here; the sink
// decides whether and how to show it (tools/terminal_progress.hpp: a status line on a terminal).
struct ProgressReport {
  std::string_view stage;      // "base fit", "round", "search", ...
  int round = 0;               // 1-based; 0 where the stage has no rounds
  std::string_view candidate;  // the effect or algorithm just tried; may be empty
  std::int64_t done = 0;       // candidates tried, or evaluations spent, in this stage
  std::int64_t total = 0;      // of those; 0 when unknown
  double best_error = std::numeric_limits<double>::quiet_NaN();  // best so far, in `unit`
  std::string_view unit;       // "N RMS", "T RMSE"
};

// Receives reports from the job's worker threads, so an implementation serialises them itself.
class ProgressSink {
 public:
  virtual ~ProgressSink() = default;
  virtual void report(const ProgressReport& report) = 0;
};

}  // namespace mrd::tools
