#include "model/hysteresis_compensator.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "model/damper_model.hpp"

namespace {

using mrd::model::CompensatorLimits;
using mrd::model::HysteresisCompensator;
using mrd::model::JilesAtherton;
using mrd::model::TargetCurve;

JilesAtherton default_core() {
  const mrd::model::DamperModel m;
  return JilesAtherton(m.jiles_atherton, m.circuit, m.integration);
}

TEST(TargetCurve, AnhystereticTargetIsOddMonotoneAndAboveTheVirginCurve) {
  const JilesAtherton core = default_core();
  const TargetCurve anhysteretic(core, 1.5, TargetCurve::Kind::kAnhysteretic);
  const TargetCurve initial(core, 1.5, TargetCurve::Kind::kInitial);
  EXPECT_EQ(anhysteretic.B(0.0), 0.0);
  double previous = -1.0;
  for (double i = 0.0; i <= 1.5; i += 0.01) {
    EXPECT_GT(anhysteretic.B(i), previous);
    EXPECT_DOUBLE_EQ(anhysteretic.B(-i), -anhysteretic.B(i));
    EXPECT_GE(anhysteretic.B(i) + 1e-12, initial.B(i));
    previous = anhysteretic.B(i);
  }
}

TEST(HysteresisCompensator, ReachesAReachableTargetWithinTolerance) {
  JilesAtherton core = default_core();
  const TargetCurve target(core, 1.5);
  CompensatorLimits limits;
  limits.min_current = -1.5;  // bipolar driver, fast slew: every target is reachable
  limits.slew_rate = 1e4;
  HysteresisCompensator compensator(core, target, limits, 1e-3);
  for (const double scheduled : {0.2, 0.8, 1.2, 0.4, 0.0, 0.6}) {
    const double command = compensator.command(scheduled, core);
    const double B = core.apply_current(command);
    EXPECT_NEAR(B, target.B(scheduled), 2e-5) << scheduled;
    EXPECT_NEAR(compensator.target_B(), target.B(scheduled), 1e-15);
  }
  EXPECT_EQ(core.guard_events(), 0u);  // the target was reached by the equations, not a clamp
  EXPECT_EQ(core.recoveries(), 0u);
}

TEST(HysteresisCompensator, RespectsCurrentLimitsAndSlewRate) {
  JilesAtherton core = default_core();
  const TargetCurve target(core, 1.5);
  CompensatorLimits limits;  // 0..1.5 A, 100 A/s
  HysteresisCompensator compensator(core, target, limits, 1e-3);
  double previous = 0.0;
  for (int i = 0; i < 200; ++i) {
    const double scheduled = (i / 50) % 2 ? 0.0 : 1.2;
    const double command = compensator.command(scheduled, core);
    core.apply_current(command);
    EXPECT_GE(command, 0.0);
    EXPECT_LE(command, 1.5);
    EXPECT_LE(std::fabs(command - previous), 100.0 * 1e-3 + 1e-12);
    previous = command;
  }
}

TEST(HysteresisCompensator, CannotRemoveRemanenceWithAUnipolarDriver) {
  JilesAtherton core = default_core();
  const TargetCurve target(core, 1.5);
  HysteresisCompensator compensator(core, target, CompensatorLimits{}, 1e-3);
  for (int i = 0; i < 100; ++i) core.apply_current(compensator.command(1.2, core));
  double B = 0.0;
  for (int i = 0; i < 100; ++i) B = core.apply_current(compensator.command(0.0, core));
  EXPECT_EQ(compensator.last_command(), 0.0);
  EXPECT_GT(B, 0.1);  // the remanence stays; only a negative current could clear it
  EXPECT_EQ(core.guard_events(), 0u);
  EXPECT_EQ(core.recoveries(), 0u);
}

// current_for: the search alone, over an interval the caller gives (a coil lag's reachable
// currents). The forward J-A from the same state is the reference.
TEST(HysteresisCompensator, CurrentForFindsTheCurrentThatGivesTheTargetB) {
  JilesAtherton core = default_core();
  const TargetCurve target(core, 1.5);
  HysteresisCompensator compensator(core, target, CompensatorLimits{}, 1e-3);
  for (const double B : {0.5, 1.1, 0.3, 0.8, 0.05}) {
    const auto found = compensator.current_for(B, core, {-1.5, 1.5});
    EXPECT_TRUE(found.reached);
    EXPECT_LE(found.evaluations, 2 + CompensatorLimits{}.max_iterations);
    JilesAtherton forward = core;
    EXPECT_EQ(forward.apply_current(found.current), found.B);
    EXPECT_NEAR(core.apply_current(found.current), B, CompensatorLimits{}.tolerance) << B;
  }
}

TEST(HysteresisCompensator, CurrentForGivesTheNearerEndOfAnUnreachableTarget) {
  JilesAtherton core = default_core();
  const TargetCurve target(core, 1.5);
  HysteresisCompensator compensator(core, target, CompensatorLimits{}, 1e-3);
  const auto high = compensator.current_for(1.2, core, {0.0, 0.1});
  EXPECT_EQ(high.current, 0.1);
  EXPECT_FALSE(high.reached);
  EXPECT_EQ(high.evaluations, 2);
  for (int i = 0; i < 20; ++i) core.apply_current(0.1 * i);
  const auto low = compensator.current_for(0.0, core, {0.0, 1.5});  // the remanence stays
  EXPECT_EQ(low.current, 0.0);
  EXPECT_GT(low.B, 0.1);
  EXPECT_FALSE(low.reached);
  EXPECT_EQ(low.evaluations, 1);
}

// With a tolerance no trial meets, the search runs exactly its cap of iterations after the two
// ends, and more iterations never give a worse best.
TEST(HysteresisCompensator, CurrentForStopsAtTheIterationCapWithTheBestTrial) {
  const JilesAtherton core = default_core();
  const TargetCurve target(core, 1.5);
  double previous_error = 1.0;
  for (int cap = 0; cap <= 8; ++cap) {
    CompensatorLimits limits;
    limits.tolerance = 0.0;
    limits.max_iterations = cap;
    HysteresisCompensator compensator(core, target, limits, 1e-3);
    const auto found = compensator.current_for(0.7, core, {0.0, 1.5});
    EXPECT_EQ(found.evaluations, 2 + cap);
    EXPECT_FALSE(found.reached);
    const double error = std::fabs(found.B - 0.7);
    EXPECT_LE(error, previous_error) << cap;
    previous_error = error;
  }
  EXPECT_LT(previous_error, 1e-6);
}

}  // namespace
