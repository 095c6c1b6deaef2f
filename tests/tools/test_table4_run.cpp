#include "tools/table4_run.hpp"

#include <gtest/gtest.h>

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

TEST(Table4Run, ObserverForceErrorIsSmallAgainstThePlant) {
  const auto on = run_table4(Table4RunOptions{});
  EXPECT_GT(on.peak_force, 40e3);  // a 50 kN class damper
  EXPECT_LT(on.observer_force.rms, 0.03 * on.peak_force);
}

}  // namespace
