#pragma once

// What every HIL run is checked for, whatever the bus: clean exits, no telemetry lost, the
// supervisor's transitions and their timing in periods.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "common/cli/exit_code.hpp"
#include "control/supervisor.hpp"
#include "model/current_schedule.hpp"
#include "tests/hil/child_process.hpp"
#include "tests/hil/hil_run.hpp"

namespace mrd::test {

using control::SupervisorState;
using control::Trigger;
using tools::TelemetryRow;

// A good period as far as the telemetry shows: a fresh sample and no overrun.
inline bool fresh(const TelemetryRow& r) { return r.sample == "fresh" && r.overruns == 0; }
// Force mode's good period: a fresh demand too.
inline bool fresh_with_demand(const TelemetryRow& r) { return fresh(r) && r.demand_check == "fresh"; }
// A period the supervisor counts towards stale_periods: no fresh sample (overruns aside).
inline bool no_sample(const TelemetryRow& r) { return r.sample != "fresh"; }

// The run was made, the plant exited with 0 and the controller with `controller_exit` (a run
// that ends in SAFE through a fault: cli::kEndedSafe), and the telemetry has rows (callers wrap
// it in ASSERT_NO_FATAL_FAILURE).
inline void expect_processes_ran(const HilResult& r, int controller_exit = cli::kOk) {
  ASSERT_TRUE(r.failure.empty()) << r.failure;
  EXPECT_EQ(r.controller_exit, controller_exit) << r.controller_output;
  EXPECT_EQ(r.plant_exit, 0) << r.plant_output;
  ASSERT_FALSE(r.telemetry.empty());
}

// Common to every run: both processes end cleanly, every telemetry record reaches the file,
// and the last cycle is the shutdown one, in SAFE at 0 A.
inline void expect_clean_run(const HilResult& r, double duration, double rate = 1000.0) {
  ASSERT_NO_FATAL_FAILURE(expect_processes_ran(r));
  const auto cycles = mrd::test::find_number(r.controller_output, R"(cycles (\d+),)");
  const auto offered = mrd::test::find_number(r.controller_output, R"((\d+) records offered)");
  const auto written = mrd::test::find_number(r.controller_output, R"((\d+) written)");
  const auto dropped = mrd::test::find_number(r.controller_output, R"((\d+) dropped)");
  ASSERT_TRUE(cycles && offered && written && dropped) << r.controller_output;
  EXPECT_EQ(*cycles, std::round(duration * rate));
  EXPECT_EQ(*offered, *cycles + 1) << "every cycle and the shutdown cycle offer a record";
  EXPECT_EQ(*dropped, 0.0);
  EXPECT_EQ(*written + *dropped, *offered);
  EXPECT_EQ(static_cast<double>(r.telemetry.size()), *written);
  EXPECT_EQ(r.telemetry.back().state, SupervisorState::kSafe);
  EXPECT_NE(r.controller_output.find("-> SAFE (shutdown): 1"), std::string::npos) << r.controller_output;
  EXPECT_EQ(r.telemetry.back().setpoint, 0.0);
}

// INIT -> RUN exactly when the run of good periods (`good`) reaches recovery_periods.
inline std::size_t expect_first_run(const HilResult& r, const mrd::control::SupervisorConfig& safety,
                                    bool (*good)(const TelemetryRow&) = fresh) {
  for (std::size_t i = 0; i < r.telemetry.size(); ++i) {
    if (r.telemetry[i].state == SupervisorState::kInit) continue;
    EXPECT_EQ(r.telemetry[i].state, SupervisorState::kRun);
    EXPECT_EQ(r.telemetry[i].trigger, Trigger::kGoodPeriods);
    EXPECT_EQ(run_length_before(r.telemetry, i, good), static_cast<std::size_t>(safety.recovery_periods));
    return i;
  }
  ADD_FAILURE() << "never left INIT";
  return 0;
}

// SAFE -> RUN after recovery_periods good periods. A good period also needs the previous
// period's setpoint write to have succeeded, which the telemetry does not show: the first
// period or two after a reconnect may have a fresh sample but the failed write of the period
// before.
inline void expect_recovery_length(const HilResult& r, std::size_t back, const mrd::control::SupervisorConfig& safety) {
  const std::size_t n = run_length_before(r.telemetry, back, fresh);
  const auto m = static_cast<std::size_t>(safety.recovery_periods);
  EXPECT_GE(n, m);
  EXPECT_LE(n, m + 2);
}

// The current command follows Table 4 in control: the scheduled current is
// model::CurrentSchedule's on the displacement the loop held, in every row in control. Returns
// how many rows were in control.
inline std::size_t expect_table4_followed(const HilResult& r) {
  model::CurrentSchedule schedule;
  std::size_t in_control = 0;
  std::size_t mismatches = 0;
  for (const auto& row : r.telemetry) {
    const double scheduled = schedule.update(row.displacement);
    if (!row.in_control()) continue;
    ++in_control;
    if (scheduled != row.scheduled_current) ++mismatches;
  }
  EXPECT_EQ(mismatches, 0u);
  return in_control;
}

// No SAFE before the shutdown cycle.
inline void expect_never_safe_before_shutdown(const HilResult& r) {
  for (std::size_t i = 0; i + 1 < r.telemetry.size(); ++i) {
    ASSERT_NE(r.telemetry[i].state, SupervisorState::kSafe) << "cycle " << r.telemetry[i].cycle << "\n" << transitions(r);
  }
}

// The first row in `state` at or after time t on the faults' clock, and its index.
inline std::size_t first_in(const HilResult& r, SupervisorState state, double t) {
  for (std::size_t i = 0; i < r.telemetry.size(); ++i) {
    if (r.fault_time(r.telemetry[i]) >= t && r.telemetry[i].state == state) return i;
  }
  return r.telemetry.size();
}

// Force mode's outer controller fell silent at fault time `start` (demand_stale): row `safe`, the
// first SAFE, is the supervisor's demand_stale trip. Counted in loop periods from the
// telemetry's cycle column (a late wake-up moves rows in time, not in count): exactly
// demand_stale_periods + 1 from the last fresh demand to SAFE (the supervisor trips at more
// than demand_stale_periods without one), each period between without a fresh demand and
// DEGRADED, and the last fresh demand within two periods of the fault's start. Returns the
// periods.
inline std::uint64_t expect_demand_stale_trip(const HilResult& r, std::size_t safe,
                                              const control::SupervisorConfig& safety, double start, double period) {
  EXPECT_EQ(r.telemetry[safe].trigger, Trigger::kDemandStale) << transitions(r);
  EXPECT_GE(r.fault_time(r.telemetry[safe]), start) << transitions(r);
  std::size_t last_fresh = safe;
  while (last_fresh > 0 && r.telemetry[last_fresh].demand_check != "fresh") --last_fresh;
  EXPECT_EQ(r.telemetry[last_fresh].demand_check, "fresh") << "no fresh demand before SAFE";
  const std::uint64_t periods = r.telemetry[safe].cycle - r.telemetry[last_fresh].cycle;
  // The supervisor trips when more than demand_stale_periods executed periods in a row brought
  // no fresh demand, and `cycle` counts executed periods: neither sooner nor later.
  EXPECT_EQ(periods, static_cast<std::uint64_t>(safety.demand_stale_periods + 1)) << transitions(r);
  for (std::size_t i = last_fresh + 1; i < safe; ++i) {
    EXPECT_EQ(r.telemetry[i].demand_check, "missing") << "cycle " << r.telemetry[i].cycle;
    EXPECT_EQ(r.telemetry[i].state, SupervisorState::kDegraded) << "cycle " << r.telemetry[i].cycle;
  }
  EXPECT_NEAR(r.fault_time(r.telemetry[last_fresh]), start, 2 * period) << transitions(r);
  return periods;
}

}  // namespace mrd::test
