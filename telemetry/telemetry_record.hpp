#pragma once

#include <cstdint>

#include "hal/clock.hpp"

namespace mrd::telemetry {

// One cycle as the telemetry writer sees it. SI units; the CSV names its own.
struct TelemetryRecord {
  std::uint64_t cycle = 0;
  hal::Timestamp time{};           // the cycle's release time
  double displacement = 0.0;       // held value the law used [m]
  double measured_current = 0.0;   // [A], NaN when the driver reports none
  double scheduled_current = 0.0;  // Table 4 [A]
  double law_current = 0.0;        // what the control law asked for [A]; NaN when not in control
  double setpoint = 0.0;           // what was written to the driver [A]
  double target_B = 0.0;           // what the schedule intends [T]; NaN when not in control
  double B = 0.0;                  // observer [T]
  double velocity = 0.0;           // observer [m/s]
  double force = 0.0;              // observer [N]
  std::uint32_t overruns = 0;      // periods missed before this cycle
  std::uint8_t sample = 0;         // SampleCheck
  std::uint8_t state = 0;          // SupervisorState
  std::uint8_t trigger = 0;        // Trigger of this cycle's transition (0: none)
  bool enable = false;
  bool latched = false;            // SAFE holds until an operator clears it
  std::uint64_t recoveries = 0;    // the observer's J-A recoveries since start
  // Force mode (NaN, fresh and false in table4 mode):
  double demand = 0.0;             // the demand the law used (the last good one) [N]
  double yield_force = 0.0;        // Eq. 12 at the law's target_B [N]; NaN when not in control
  std::uint8_t demand_check = 0;   // SampleCheck of this period's demand
  bool clipped = false;            // the demand pushed with the motion or lay beyond the range
  bool reached = false;            // the inverse's J-A search met its tolerance
  double force_scale = 0.0;        // the model's yield force scale (1 without a load cell)
  std::uint32_t load_cell_frozen = 0;  // periods the load cell was stale or bad so far (saturates)
  bool force_scale_at_bound = false;   // the scale reached a bound this period (journaled)
};

}  // namespace mrd::telemetry
