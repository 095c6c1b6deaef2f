#pragma once

#include <cmath>
#include <cstdlib>
#include <vector>

#include "record/recorded_run.hpp"

namespace mrd::fuzz {

// What every run a reader accepts must satisfy; a violation aborts, which libFuzzer reports
// as a crash with the input that caused it.
inline void check_run(const record::RecordedRun& run) {
  const auto column_ok = [&](const std::vector<double>& column, bool required) {
    if (column.empty()) return !required || run.time.empty();
    if (column.size() != run.time.size()) return false;
    for (const double v : column) {
      if (!std::isfinite(v)) return false;
    }
    return true;
  };
  if (!column_ok(run.time, true) || !column_ok(run.displacement, true) || !column_ok(run.coil, true) ||
      !column_ok(run.force, false) || !column_ok(run.velocity, false) || !column_ok(run.B, false) ||
      !column_ok(run.temperature, false)) {
    std::abort();
  }
  for (std::size_t i = 1; i < run.time.size(); ++i) {
    if (!(run.time[i] > run.time[i - 1])) std::abort();
  }
}

}  // namespace mrd::fuzz
