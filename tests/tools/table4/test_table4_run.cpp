#include "tools/table4/table4_run.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace {

using mrd::tools::run_table4;
using mrd::tools::Table4RunOptions;

// The compensation figure in docs/MODEL.md: a Table 4 run at 0.5 Hz, +-40 mm, 1 kHz.
TEST(Table4Run, CompensationLowersBTrackingError) {
  Table4RunOptions options;
  options.controller.compensate_hysteresis = false;
  const auto off = run_table4(options);
  options.controller.compensate_hysteresis = true;
  const auto on = run_table4(options);
  EXPECT_GT(off.B_tracking.rms, 0.10);
  EXPECT_LT(on.B_tracking.rms, 0.75 * off.B_tracking.rms);
  EXPECT_LT(on.B_tracking.max, 0.65 * off.B_tracking.max);
}

TEST(Table4Run, BipolarDriverRemovesNearlyAllTrackingError) {
  Table4RunOptions options;
  options.controller.compensate_hysteresis = false;
  const auto off = run_table4(options);
  options.controller.compensate_hysteresis = true;
  options.controller.limits.min_current = -1.5;
  const auto on = run_table4(options);
  EXPECT_LT(on.B_tracking.rms, 0.25 * off.B_tracking.rms);  // what is left is the slew limit
}

// The real-time default evaluates the Langevin function from a table (docs/MODEL.md). Over a
// whole compensated Table 4 run, plant and controller, it must change B by far less than the
// integrator's 5e-7 T.
TEST(Table4Run, TabulatedLangevinLeavesTheRunUnchanged) {
  Table4RunOptions options;
  const auto tabulated = run_table4(options);
  options.plant.integration.langevin = mrd::model::LangevinEvaluation::kExact;
  options.controller.damper.integration.langevin = mrd::model::LangevinEvaluation::kExact;
  const auto exact = run_table4(options);
  ASSERT_EQ(tabulated.trace.size(), exact.trace.size());
  double max_B_difference = 0.0;
  for (std::size_t i = 0; i < exact.trace.size(); ++i) {
    max_B_difference =
        std::max(max_B_difference, std::fabs(tabulated.trace[i].B - exact.trace[i].B));
  }
  EXPECT_LT(max_B_difference, 1e-11);  // [T]
  std::printf("Table 4 run, tabulated vs exact Langevin: max |dB| = %.2g T\n", max_B_difference);
}

TEST(Table4Run, ObserverForceErrorIsSmallAgainstThePlant) {
  const auto on = run_table4(Table4RunOptions{});
  EXPECT_GT(on.peak_force, 40e3);  // a 50 kN class damper
  EXPECT_LT(on.observer_force.rms, 0.03 * on.peak_force);
}

}  // namespace
