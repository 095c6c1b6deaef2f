// Force mode's load-cell feedback through the whole loop on the mock HAL: the correction moves
// the model's yield force scale while the law drives the coil, telemetry carries it, a silent
// or faulty load cell freezes it (counted, not a fault), and the bound is flagged once.
// Convergence and the time constant against an independent plant are ForceScaleCorrection.*.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "model/observer.hpp"
#include "tests/firmware/loop_fixture.hpp"
#include "tests/support/drifted_plant.hpp"

namespace {

using namespace mrd::test::reaction_terms;
using mrd::test::force_law;
using mrd::test::force_law_with_load_cell;

TEST(ForceModeLoadCell, WithoutALoadCellTheScaleStaysOne) {
  LoopRig rig({}, {}, nullptr, force_law());
  rig.set_load_cell_gain(0.5);  // read by nothing: the law has no correction
  ASSERT_GT(rig.run_until(kRun), 0);
  for (int i = 0; i < 3000; ++i) {
    rig.step();
    ASSERT_EQ(rig.loop().last().force_scale, 1.0);
  }
  EXPECT_EQ(rig.loop().law().force_scale_correction(), nullptr);
}

// The load cell measures an independent damper whose yield stress is 0.85 of the model's
// (tests/support/drifted_plant.hpp), driven by the current the loop commands on the LVDT's
// motion: the force at the start of each period from the setpoint held over the last one.
class DriftedRig {
 public:
  explicit DriftedRig(double factor, double tau = 1.0)
      : rig_({}, {}, nullptr, force_law_with_load_cell(tau)), plant_(mrd::test::drifted_plant(factor, 1e-3)) {
    rig_.set_load_cell_by_hand();
  }
  void step() {
    const double t = static_cast<double>(rig_.cycle()) * 1e-3;
    plant_force_ = plant_.step({.displacement = LoopRig::displacement_at(t),
                                .velocity = LoopRig::velocity_at(t),
                                .coil_current = rig_.hal().driver.last_setpoint()})
                       .force;
    rig_.hal().load_cell.set_value(plant_force_);
    rig_.step();
  }
  LoopRig& rig() { return rig_; }
  [[nodiscard]] double plant_force() const { return plant_force_; }

 private:
  LoopRig rig_;
  mrd::model::Observer plant_;
  double plant_force_ = 0.0;
};

TEST(ForceModeLoadCell, ADamperGivingLessThanTheModelLowersTheScaleToItsYieldRatio) {
  DriftedRig drifted(0.85);
  int to_run = 0;
  while (drifted.rig().loop().state() != kRun && to_run++ < 1000) drifted.step();
  ASSERT_EQ(drifted.rig().loop().state(), kRun);
  double error_sq = 0.0, force_sq = 0.0;
  int compared = 0;
  for (int i = 0; i < 20000; ++i) {  // 20 s, 10 periods of the sine, 20 time constants
    drifted.step();
    const auto& r = drifted.rig().loop().last();
    ASSERT_EQ(r.state, static_cast<std::uint8_t>(kRun));
    ASSERT_GE(r.force_scale, 0.7);
    ASSERT_LE(r.force_scale, 1.3);
    if (i >= 16000 && std::fabs(drifted.plant_force()) > 10e3) {
      // The plant's force at this period's start against the observer's estimate this period.
      error_sq += (r.force - drifted.plant_force()) * (r.force - drifted.plant_force());
      force_sq += drifted.plant_force() * drifted.plant_force();
      ++compared;
    }
  }
  std::printf("load cell on a 0.85 plant through the loop: scale %.4f, observer vs plant %.2f %% RMS\n",
              drifted.rig().loop().last().force_scale, 100.0 * std::sqrt(error_sq / force_sq));
  // Gated samples near the reversals and the observer's tracked velocity keep it off by a little.
  EXPECT_NEAR(drifted.rig().loop().last().force_scale, 0.85, 0.02);
  ASSERT_GT(compared, 1000);
  EXPECT_LT(std::sqrt(error_sq / force_sq), 0.03) << "the corrected observer agrees with the plant";
  EXPECT_EQ(drifted.rig().loop().last().load_cell_frozen, 0u);
}

TEST(ForceModeLoadCell, ASilentOrFaultyLoadCellFreezesTheScaleAndIsCountedNotAFault) {
  DriftedRig drifted(0.85);
  LoopRig& rig = drifted.rig();
  for (int i = 0; i < 3000; ++i) drifted.step();
  ASSERT_EQ(rig.loop().state(), kRun);
  const double moved = rig.loop().last().force_scale;
  ASSERT_LT(moved, 0.95);
  rig.hal().load_cell.set_silent(true);
  for (int i = 0; i < 1000; ++i) {
    drifted.step();
    ASSERT_EQ(rig.loop().last().force_scale, moved);
    ASSERT_EQ(rig.loop().state(), kRun);
  }
  // The first max_age (5) silent periods are not stale yet.
  EXPECT_EQ(rig.loop().last().load_cell_frozen, 995u);
  rig.hal().load_cell.set_silent(false);
  rig.hal().load_cell.set_faulty(true);
  for (int i = 0; i < 1000; ++i) {
    drifted.step();
    ASSERT_EQ(rig.loop().last().force_scale, moved);
    ASSERT_EQ(rig.loop().state(), kRun);
  }
  EXPECT_EQ(rig.loop().last().load_cell_frozen, 1995u);
  rig.hal().load_cell.set_faulty(false);
  for (int i = 0; i < 2000; ++i) drifted.step();
  EXPECT_LT(rig.loop().last().force_scale, moved) << "fresh samples move it on toward 0.85";
}

TEST(ForceModeLoadCell, OutsideControlTheScaleDoesNotMove) {
  // A silent outer controller takes the loop to SAFE; the load cell keeps reading, the scale holds.
  LoopRig safe_rig(script_of(FaultKind::kDemandMissing), {}, nullptr, force_law_with_load_cell(1.0));
  safe_rig.set_load_cell_gain(0.5);
  safe_rig.run_to(kFaultStart + 10);  // SAFE from the 6th silent period on
  ASSERT_EQ(safe_rig.loop().state(), kSafe);
  const double held = safe_rig.loop().last().force_scale;
  for (int i = 0; i < 30; ++i) {
    safe_rig.step();
    ASSERT_EQ(safe_rig.loop().state(), kSafe);
    ASSERT_EQ(safe_rig.loop().last().force_scale, held);
  }
}

TEST(ForceModeLoadCell, TheScaleStopsAtItsBoundAndSaysSoOnce) {
  LoopRig rig({}, {}, nullptr, force_law_with_load_cell(0.2));
  rig.set_load_cell_gain(0.5);
  ASSERT_GT(rig.run_until(kRun), 0);
  int flagged = 0;
  for (int i = 0; i < 10000; ++i) {
    rig.step();
    const auto& r = rig.loop().last();
    ASSERT_GE(r.force_scale, 0.7);
    flagged += r.force_scale_at_bound ? 1 : 0;
  }
  EXPECT_DOUBLE_EQ(rig.loop().last().force_scale, 0.7);
  EXPECT_EQ(flagged, 1);
}

TEST(ForceModeLoadCell, ALoadCellLawWithoutALoadCellSourceIsRefusedAtConstruction) {
  mrd::hal::mock::MockHal hal;
  EXPECT_THROW(mrd::firmware::ControlLoop(force_law_with_load_cell(), {},
                                          mrd::firmware::HalDevices{hal.lvdt, hal.driver, hal.lines, &hal.demand}),
               std::invalid_argument);
}

}  // namespace
