// Force mode through the whole loop on the mock HAL: the demand drives the coil through
// model::ForceInverse, the telemetry says what it did, and a missing, stale, non-finite or
// out-of-range demand gets the LVDT's treatment (DEGRADED, then SAFE after the documented
// periods), cycle by cycle. Table4 mode reads no demand: its outputs do not change.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include "tests/firmware/loop_fixture.hpp"

namespace {

using namespace mrd::test::reaction_terms;
using mrd::control::SampleCheck;
using mrd::test::force_law;

LoopRig force_rig(FaultScript script = {}) { return LoopRig(std::move(script), {}, nullptr, force_law()); }

TEST(ForceMode, TheObserverForceFollowsADissipativeDemand) {
  // The inverse and the observer share the model, so in RUN the force the observer estimates
  // the period after a command is the demand, but for what the slew limit and the zero-field
  // force leave out (near the reversals, where c v falls below the fluid's least force). A
  // bipolar driver: a unipolar one cannot clear the remanence (docs/FORCE-CONTROL.md, Limits).
  auto law = force_law();
  law.limits.min_current = -law.limits.max_current;
  LoopRig rig({}, {}, nullptr, law);
  ASSERT_GT(rig.run_until(kRun), 0);
  double demand_sq = 0.0;
  double error_sq = 0.0;
  int counted = 0;
  int clipped = 0;
  int reached = 0;
  double previous_demand = std::nan("");
  for (int i = 0; i < 4000; ++i) {  // two periods of the 0.5 Hz sine
    rig.step();
    const auto& r = rig.loop().last();
    ASSERT_EQ(r.state, static_cast<std::uint8_t>(kRun));
    ASSERT_EQ(r.demand_check, static_cast<std::uint8_t>(SampleCheck::kFresh));
    if (r.clipped) ++clipped;
    if (r.reached) ++reached;
    if (!r.clipped && std::isfinite(previous_demand) && std::fabs(previous_demand) > 5e3) {
      demand_sq += previous_demand * previous_demand;
      error_sq += (r.force - previous_demand) * (r.force - previous_demand);
      ++counted;
    }
    previous_demand = r.clipped ? std::nan("") : r.demand;
  }
  ASSERT_GT(counted, 3000);
  const double demand_rms = std::sqrt(demand_sq / counted);
  const double error_rms = std::sqrt(error_sq / counted);
  std::printf("force mode on the loop: demand RMS %.1f kN, error RMS %.1f N over %d periods, %d clipped, %d reached\n",
              demand_rms * 1e-3, error_rms, counted, clipped, reached);
  EXPECT_GT(demand_rms, 15e3);  // 250 kN s/m on up to 94 mm/s
  EXPECT_LT(error_rms, 0.02 * demand_rms) << "demand RMS " << demand_rms << " N";
  // Below the zero-field yield force (about 100 N, docs/FORCE-CONTROL.md) near each of the four
  // reversals: clipped there and nowhere else.
  EXPECT_GT(clipped, 0);
  EXPECT_LT(clipped, 400);
  EXPECT_GT(reached, 3900);
}

TEST(ForceMode, ADemandThatPushesWithTheMotionIsClippedToTheLeastCurrent) {
  LoopRig rig = force_rig();
  ASSERT_GT(rig.run_until(kRun), 0);
  rig.set_demand_damping(-LoopRig::kDemandDamping);
  for (int i = 0; i < 1000; ++i) rig.step();
  int clipped = 0;
  for (int i = 0; i < 500; ++i) {
    rig.step();
    clipped += rig.loop().last().clipped ? 1 : 0;
    // Slew-limited down to the driver's least current, then held there.
    EXPECT_EQ(rig.hal().driver.last_setpoint(), 0.0) << "cycle " << rig.cycle() - 1;
  }
  EXPECT_EQ(clipped, 500);
}

TEST(ForceMode, Table4ModeReadsNoDemandAndItsOutputsDoNotChange) {
  // The same run with and without every demand fault: the same setpoints, bit for bit.
  FaultScript faults = script_of(FaultKind::kDemandMissing);
  faults.add({FaultKind::kDemandNotFinite, cycle_time(1100, LoopRig::kPeriod), cycle_time(1200, LoopRig::kPeriod), 0.0});
  faults.add({FaultKind::kDemandOutOfRange, cycle_time(1300, LoopRig::kPeriod), cycle_time(1400, LoopRig::kPeriod), 1e9});
  LoopRig clean;
  LoopRig faulty(faults);
  for (int i = 0; i < 1600; ++i) {
    clean.step();
    faulty.step();
    ASSERT_EQ(clean.hal().driver.last_setpoint(), faulty.hal().driver.last_setpoint()) << "cycle " << i;
    ASSERT_TRUE(std::isnan(faulty.loop().last().demand));
  }
  EXPECT_EQ(faulty.loop().state(), kRun);
  EXPECT_EQ(faulty.loop().supervisor().transitions().into(kDegraded), 0u);
}

TEST(ForceMode, ForceModeWithoutADemandSourceIsRefusedAtConstruction) {
  mrd::hal::mock::MockHal hal;
  EXPECT_THROW(mrd::firmware::ControlLoop(force_law(), {}, {hal.lvdt, hal.driver, hal.lines}), std::invalid_argument);
}

TEST(ForceMode, ASilentOuterControllerKeepsInitAndIsNotAFault) {
  LoopRig rig = force_rig(FaultScript{{FaultKind::kDemandMissing, {}, cycle_time(3000, LoopRig::kPeriod), 0.0}});
  EXPECT_EQ(rig.run_until(kRun, 3000), -1);
  EXPECT_EQ(rig.loop().state(), kInit);
  EXPECT_EQ(rig.loop().supervisor().transitions().into(kSafe), 0u);
  // The first demand starts the count of good periods.
  EXPECT_EQ(rig.run_until(kRun), 3000 + kLimits.recovery_periods - 1);
}

// Missing and stale demands: DEGRADED in the period, SAFE in period Nd + 1 without a fresh one
// (Nd = [force] demand_max_age, 5), RUN M good periods after the fault ends.
class DemandSilence : public ::testing::TestWithParam<FaultKind> {};

TEST_P(DemandSilence, DegradesAtOnceAndIsSafeAfterDemandMaxAgePeriods) {
  LoopRig rig = force_rig(script_of(GetParam()));
  const Reaction r = react(rig);
  EXPECT_EQ(r.degraded, kFaultStart);
  EXPECT_EQ(r.safe, kFaultStart + kLimits.demand_stale_periods);
  expect_recovery(r);
  const auto& t = rig.loop().supervisor().transitions();
  EXPECT_EQ(t.get(kRun, kDegraded, Trigger::kDemandMissing), 1u);
  EXPECT_EQ(t.get(kDegraded, kSafe, Trigger::kDemandStale), 1u);
}

INSTANTIATE_TEST_SUITE_P(ForceMode, DemandSilence, ::testing::Values(FaultKind::kDemandMissing, FaultKind::kDemandStale),
                         [](const auto& p) { return std::string(to_string(p.param)); });

TEST(ForceMode, TheLawHoldsTheLastGoodDemandWhileDemandsAreMissing) {
  LoopRig rig = force_rig(FaultScript{{FaultKind::kDemandMissing, cycle_time(kFaultStart, LoopRig::kPeriod),
                                       cycle_time(kFaultStart + 3, LoopRig::kPeriod), 0.0}});
  rig.run_to(kFaultStart);
  const double last_good = rig.loop().last().demand;
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(rig.step(), kDegraded);
    EXPECT_EQ(rig.loop().last().demand, last_good);
    EXPECT_EQ(rig.loop().last().demand_check, static_cast<std::uint8_t>(SampleCheck::kMissing));
  }
  rig.step();
  EXPECT_NE(rig.loop().last().demand, last_good);
  EXPECT_EQ(rig.loop().state(), kDegraded) << "good again, DEGRADED until C good periods";
}

// Bad demand values: DEGRADED in the period, SAFE at the B-th in a row (safety.bad_sample_periods).
struct BadDemand {
  FaultKind kind;
  double parameter;
  Trigger trigger;
};

class BadDemandReaction : public ::testing::TestWithParam<BadDemand> {};

TEST_P(BadDemandReaction, DegradesAtOnceAndIsSafeAtTheBthBadDemand) {
  LoopRig rig = force_rig(script_of(GetParam().kind, GetParam().parameter));
  const Reaction r = react(rig);
  EXPECT_EQ(r.degraded, kFaultStart);
  EXPECT_EQ(r.safe, kFaultStart + kLimits.bad_sample_periods - 1);
  expect_recovery(r);
  const auto& t = rig.loop().supervisor().transitions();
  EXPECT_EQ(t.get(kRun, kDegraded, GetParam().trigger), 1u);
  EXPECT_EQ(t.get(kDegraded, kSafe, GetParam().trigger), 1u);
  EXPECT_TRUE(std::isfinite(rig.loop().last().demand)) << "a bad value is never used";
}

INSTANTIATE_TEST_SUITE_P(
    ForceMode, BadDemandReaction,
    ::testing::Values(BadDemand{FaultKind::kDemandNotFinite, 0.0, Trigger::kDemandNotFinite},
                      BadDemand{FaultKind::kDemandOutOfRange, 60001.0, Trigger::kDemandOutOfRange},
                      BadDemand{FaultKind::kDemandOutOfRange, -60001.0, Trigger::kDemandOutOfRange}),
    [](const auto& p) { return std::string(to_string(p.param.kind)) + std::to_string(p.index); });

TEST(ForceMode, ADemandJustInsideTheRangeIsFair) {
  LoopRig rig = force_rig(script_of(FaultKind::kDemandOutOfRange, 60000.0));
  const Reaction r = react(rig);
  EXPECT_EQ(r.degraded, -1);
  EXPECT_EQ(r.safe, -1);
}

}  // namespace
