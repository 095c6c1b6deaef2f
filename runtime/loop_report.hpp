#pragma once

#include <string>

#include "runtime/latency_histogram.hpp"
#include "runtime/loop_statistics.hpp"

namespace mrd::runtime {

// The statistics printout (at exit and on SIGUSR1). Runs on a non-real-time thread.
// "wake-up latency [us]: p50 4.1  p99 12.3  p99.9 30.2  max 41.0  (n = 60000)"
[[nodiscard]] std::string format_percentiles(const char* name, const LatencyHistogram& h);
// Counts in decade-ish bins (<1, 1-2, 2-5, 5-10, ... us), for the bench's histogram table.
[[nodiscard]] std::string format_histogram(const char* name, const LatencyHistogram& h);
[[nodiscard]] std::string format_loop_statistics(const LoopStatistics& stats);

}  // namespace mrd::runtime
