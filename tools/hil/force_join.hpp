#pragma once

#include <cstddef>
#include <utility>
#include <vector>

#include "tools/hil/telemetry_csv.hpp"
#include "record/recorded_run.hpp"

namespace mrd::tools {

// The controller's telemetry joined with the plant's log by time: the controller's row at t
// meets the plant's sample at t + offset + lag, where `offset` is the difference of the two
// files' time origins (both on CLOCK_MONOTONIC) and `lag` the LVDT's transport delay, found as
// the shift within +-max_lag that best matches the two displacement records. A row whose plant
// time falls in a gap of the plant log (record::fill_gaps) is left out, not joined with a
// straight line across the gap.
struct ForceJoin {
  double offset = 0.0;      // [s]
  double lag = 0.0;         // [s]
  std::size_t rows = 0;     // rows in control (RUN or DEGRADED) that fall inside the plant log, not in its gaps
  double rms_error = 0.0;   // observer - true [N]
  double max_error = 0.0;   // max |observer - true| [N]
  double peak_force = 0.0;  // max |true force| over the joined rows [N]
  double displacement_rms = 0.0;  // controller - plant displacement after the lag [m]
  std::size_t in_plant_gaps = 0;  // rows in control left out: their plant time fell in a gap
  std::vector<std::pair<double, double>> plant_gaps;  // [s] each gap's logged samples either side
  // The joined samples, for plots: telemetry time, plant displacement, true force, observer force.
  std::vector<double> time;
  std::vector<double> displacement;
  std::vector<double> true_force;
  std::vector<double> observer_force;

  [[nodiscard]] double nrmse() const { return peak_force > 0.0 ? rms_error / peak_force : 0.0; }
};

// Throws InputError when the plant log has no force or nothing overlaps.
[[nodiscard]] ForceJoin join_force(const std::vector<TelemetryRow>& telemetry,
                                   const record::RecordedRun& plant, double offset, double max_lag = 0.02);

}  // namespace mrd::tools
