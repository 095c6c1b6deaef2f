// control::ControlLaw driven as PX4's failsafe tests drive theirs: each period a position, a
// velocity and the coil current that flowed go in, the schedule's current, the command or the
// scale's update comes out. The figures are the paper's Table 4 levels, the driver's slew limit
// and Eq. 11-13 worked by hand for the default damper; the closed-loop checks use a second
// observer as the coil, not the law's own state.
#include "control/control_law.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/support/default_damper_figures.hpp"

namespace {
namespace control_law {  // its own names in the unity build

using mrd::control::ControlLaw;
using mrd::control::ControlLawConfig;
using mrd::control::ControlMode;
using mrd::control::LoadCellStatus;
using mrd::control::ScaleUpdate;
using mrd::model::Observer;

constexpr double kT = 1e-3;          // the default period [s]
constexpr double kSlewStep = 0.1;    // the default 100 A/s over one period [A]
constexpr double kMaxCurrent = 1.5;  // the default driver's [A]
constexpr double kC0 = mrd::test::kDefaultViscousCoefficient;
constexpr double kZeroFieldYieldForce = mrd::test::kDefaultZeroFieldYieldForce;

ControlLawConfig law_config(ControlMode mode, bool compensate = true) {
  ControlLawConfig c;
  c.mode = mode;
  c.compensate_hysteresis = compensate;
  return c;
}

ControlLawConfig with_load_cell() {
  ControlLawConfig c = law_config(ControlMode::kForce);
  c.has_load_cell = true;
  return c;
}

// The law in the loop: one call is one period. The coil is a second observer of the same
// damper that the commands drive; what flows is the last command (the loop's read-back).
struct Rig {
  explicit Rig(const ControlLawConfig& config) : law(config), coil(config.damper) {}

  // In control (the supervisor's RUN): observe, then command.
  ControlLaw::Command control(double x, double v, double demand = 0.0) {
    law.observe({.displacement = x, .velocity = v, .coil_current = flowing});
    const ControlLaw::Command c = law.command(demand);
    drive(x, v, c.current);
    return c;
  }
  // The supervisor drives `current` itself (INIT, SAFE).
  void held(double x, double v, double current) {
    law.observe({.displacement = x, .velocity = v, .coil_current = flowing});
    law.hold(current);
    drive(x, v, current);
  }
  void drive(double x, double v, double current) {
    flowing = current;
    coil_estimate = coil.step({.displacement = x, .velocity = v, .coil_current = current});
  }

  ControlLaw law;
  Observer coil;
  mrd::model::ObserverEstimate coil_estimate;
  double flowing = 0.0;
};

// ---- table4 mode: the schedule --------------------------------------------------------------

TEST(ControlLaw, ObservesTheTable4LevelOfTheDisplacementsMagnitude) {
  // Mid-band |x| [m] and the paper's Table 4 current [A] there.
  const struct {
    double x, current;
  } table4[] = {{0.0025, 0.0}, {0.0075, 0.2}, {0.015, 0.4}, {0.025, 0.6}, {0.035, 0.8}, {0.045, 1.2}};
  for (const auto& row : table4) {
    for (const double sign : {1.0, -1.0}) {
      ControlLaw law(law_config(ControlMode::kTable4));
      const double scheduled =
          law.observe({.displacement = sign * row.x, .velocity = 0.0, .coil_current = 0.0}).scheduled_current;
      EXPECT_EQ(scheduled, row.current) << "x " << sign * row.x;
    }
  }
}

TEST(ControlLaw, TheScheduleFollowsTheStrokeEveryPeriod) {
  // One law along a stroke out to 45 mm and back: each period's observation carries the
  // level of that period's |x| (falling, once past the 0.2 mm band).
  ControlLaw law(law_config(ControlMode::kTable4));
  const struct {
    double x, current;
  } stroke[] = {{0.0, 0.0},  {0.006, 0.2},  {0.012, 0.4}, {-0.022, 0.6}, {0.033, 0.8}, {-0.045, 1.2},
                {0.036, 0.8}, {-0.026, 0.6}, {0.016, 0.4}, {0.008, 0.2},  {-0.001, 0.0}};
  for (const auto& p : stroke) {
    EXPECT_EQ(law.observe({.displacement = p.x, .velocity = 0.1, .coil_current = 0.0}).scheduled_current, p.current)
        << "x " << p.x;
  }
}

TEST(ControlLaw, UncompensatedCommandRampsAtTheSlewLimitToTheLevel) {
  Rig rig(law_config(ControlMode::kTable4, false));
  // 45 mm: 1.2 A, reached from 0 A in 12 periods of 0.1 A; then held there.
  for (int k = 1; k <= 20; ++k) {
    const ControlLaw::Command c = rig.control(0.045, 0.0);
    EXPECT_NEAR(c.current, std::fmin(k * kSlewStep, 1.2), 1e-12) << "period " << k;
  }
}

TEST(ControlLaw, Table4CommandCarriesNoDemandWhateverIsPassed) {
  for (const bool compensate : {false, true}) {
    Rig rig(law_config(ControlMode::kTable4, compensate));
    const ControlLaw::Command c = rig.control(0.045, 0.1, 5e3);
    EXPECT_TRUE(std::isnan(c.demand)) << compensate;
    EXPECT_TRUE(std::isnan(c.yield_force)) << compensate;
    EXPECT_FALSE(c.clipped) << compensate;
  }
}

TEST(ControlLaw, CompensatedCommandTakesTheCoilToTheScheduledInduction) {
  Rig compensated(law_config(ControlMode::kTable4, true));
  Rig plain(law_config(ControlMode::kTable4, false));
  ControlLaw::Command c;
  ControlLaw::Command p;
  for (int k = 0; k < 100; ++k) {
    c = compensated.control(0.045, 0.0);
    p = plain.control(0.045, 0.0);
  }
  // Both aim at the same B for the 1.2 A level; only the compensated one gets there: on the
  // ascending branch 1.2 A gives less than the anhysteretic target (docs/MODEL.md), so it
  // commands more, within the driver's range.
  EXPECT_EQ(c.target_B, p.target_B);
  EXPECT_GT(c.target_B, 0.5);
  EXPECT_GT(c.current, 1.2 + kSlewStep);
  EXPECT_LE(c.current, kMaxCurrent);
  EXPECT_NEAR(compensated.coil_estimate.B, c.target_B, 1e-5);  // the search's tolerance
  EXPECT_LT(plain.coil_estimate.B, p.target_B - 0.02);
}

// ---- force mode: the command from a demand --------------------------------------------------

TEST(ForceModeLaw, CommandsTheCurrentWhoseForceMeetsTheDemand) {
  Rig rig(law_config(ControlMode::kForce));
  const double v = 0.1;  // tanh(v / v_s) = tanh(100) = 1: the whole yield force acts
  const double demand = 20e3;
  ControlLaw::Command c;
  for (int k = 0; k < 100; ++k) c = rig.control(k * v * kT, v, demand);
  EXPECT_EQ(c.demand, demand);
  EXPECT_FALSE(c.clipped);
  EXPECT_TRUE(c.reached);
  // Eq. 12 by hand: the yield part is what the viscous part c0 v leaves of the demand.
  EXPECT_NEAR(c.yield_force, demand - kC0 * v, 0.01);
  EXPECT_NEAR(rig.coil_estimate.force, demand, 1.0);
}

TEST(ForceModeLaw, ADemandPushingWithTheMotionGetsTheLeastForce) {
  Rig rig(law_config(ControlMode::kForce));
  const double v = 0.1;
  ControlLaw::Command c;
  for (int k = 0; k < 100; ++k) c = rig.control(k * v * kT, v, -5e3);  // F v < 0: not dissipative
  EXPECT_TRUE(c.clipped);
  EXPECT_EQ(c.demand, -5e3);
  EXPECT_NEAR(c.yield_force, kZeroFieldYieldForce, 0.01);  // B = 0: the fluid's zero-field stress
  EXPECT_NEAR(rig.coil_estimate.force, kZeroFieldYieldForce + kC0 * v, 0.01);
}

TEST(ForceModeLaw, ADemandBeyondTheDampersRangeSaturatesTheDriver) {
  Rig rig(law_config(ControlMode::kForce));
  ControlLaw::Command c;
  for (int k = 0; k < 100; ++k) c = rig.control(k * 1e-4, 0.1, 1e6);
  EXPECT_TRUE(c.clipped);
  EXPECT_EQ(c.current, kMaxCurrent);
}

// ---- hold(): the supervisor's fail-safe current ---------------------------------------------

// In control at a high current, then SAFE holding the fail-safe current, then control again:
// the first command moves one slew step from the fail-safe current, not from the current the
// law commanded before SAFE.
void expect_resume_from_fail_safe(const ControlLawConfig& config, double fail_safe) {
  Rig rig(config);
  const double v = 0.1;
  double x = 0.045;
  const auto control = [&] { return rig.control(x += 1e-6, v, 1e6); };  // 45 mm (1.2 A), a demand past the range
  for (int k = 0; k < 49; ++k) control();
  ASSERT_GT(control().current, fail_safe + 3.0 * kSlewStep);
  for (int k = 0; k < 10; ++k) rig.held(x, v, fail_safe);
  EXPECT_NEAR(control().current, fail_safe + kSlewStep, 1e-12) << "fail-safe " << fail_safe;
}

TEST(ControlLaw, ResumesFromTheFailSafeCurrentItHeld) {
  for (const double fail_safe : {0.0, 0.3}) {
    expect_resume_from_fail_safe(law_config(ControlMode::kTable4, false), fail_safe);
    expect_resume_from_fail_safe(law_config(ControlMode::kTable4, true), fail_safe);
    expect_resume_from_fail_safe(law_config(ControlMode::kForce), fail_safe);
  }
}

TEST(ControlLaw, AHeldCurrentBeyondTheDriversRangeResumesFromItsEnd) {
  Rig rig(law_config(ControlMode::kTable4, false));
  rig.held(0.0, 0.0, 4.0);
  // |x| < 5 mm: the level is 0 A; from 1.5 A the ramp down starts.
  EXPECT_NEAR(rig.control(0.0, 0.0).current, kMaxCurrent - kSlewStep, 1e-12);
}

// ---- the force scale's correction (a load cell in force mode) -------------------------------

TEST(ForceScaleLaw, WithoutALoadCellTheScaleWaitsAtOne) {
  for (const ControlMode mode : {ControlMode::kTable4, ControlMode::kForce}) {
    ControlLaw law(law_config(mode));
    law.observe({.displacement = 0.02, .velocity = 0.1, .coil_current = 1.2});
    EXPECT_EQ(law.correct_force_scale(LoadCellStatus::kFresh, 1e3), ScaleUpdate::kWaiting);
    EXPECT_EQ(law.force_scale(), 1.0);
    EXPECT_EQ(law.force_scale_correction(), nullptr);
  }
}

// The load cell reads `measured(estimate)` in a period observed at (v, current).
template <typename Measured>
ScaleUpdate one_reading(ControlLaw& law, double v, double current, Measured measured) {
  const auto& o = law.observe({.displacement = 0.02, .velocity = v, .coil_current = current});
  return law.correct_force_scale(LoadCellStatus::kFresh, measured(o.estimate.force));
}

// A load cell 20 % below the model's yield part: c0 v + 0.8 (F - c0 v).
double low_yield(double v, double force) { return kC0 * v + 0.8 * (force - kC0 * v); }

TEST(ForceScaleLaw, AYieldingDamperMovesTheScaleOneFirstOrderStep) {
  ControlLaw law(with_load_cell());
  const double v = 0.1;
  EXPECT_EQ(one_reading(law, v, 1.2, [&](double f) { return low_yield(v, f); }), ScaleUpdate::kMoved);
  // One period of the 5 s first-order move toward 0.8: 1 - 0.2 (1 - exp(-1 ms / 5 s)).
  EXPECT_NEAR(law.force_scale(), 0.999960004, 1e-12);
  EXPECT_EQ(law.observer().yield_scale(), law.force_scale());
}

TEST(ForceScaleLaw, TheGateLetsOnlyAYieldingDamperThrough) {
  // Too slow: 5 mm/s is under the 10 mm/s gate however large the force.
  ControlLaw slow(with_load_cell());
  EXPECT_EQ(one_reading(slow, 0.005, 1.2, [](double f) { return 0.8 * f; }), ScaleUpdate::kGatedOut);
  // Fast with no field: the whole force (c0 v, about 8 kN) passes a 10 % gate of the range
  // (about 45 kN), but its yield part is the zero-field stress's 100 N, which does not.
  ControlLaw unfielded(with_load_cell());
  const double v = 0.15;
  EXPECT_EQ(one_reading(unfielded, v, 0.0, [&](double f) { return low_yield(v, f); }), ScaleUpdate::kGatedOut);
  // A measured yield part against the model's: a load cell wired backwards.
  ControlLaw reversed(with_load_cell());
  EXPECT_EQ(one_reading(reversed, 0.1, 1.2, [](double f) { return -f; }), ScaleUpdate::kGatedOut);
  for (const ControlLaw* law : {&slow, &unfielded, &reversed}) EXPECT_EQ(law->force_scale(), 1.0);
}

TEST(ForceScaleLaw, ASilentLoadCellGoesStaleAndFreezesTheScale) {
  ControlLaw law(with_load_cell());
  const double v = 0.1;
  for (int k = 0; k < 100; ++k) one_reading(law, v, 1.2, [&](double f) { return low_yield(v, f); });
  const double moved = law.force_scale();
  ASSERT_LT(moved, 1.0);
  // max_age_periods 5: five periods wait, the sixth is stale.
  for (int k = 0; k < 5; ++k) EXPECT_EQ(law.correct_force_scale(LoadCellStatus::kNone, 0.0), ScaleUpdate::kWaiting);
  EXPECT_EQ(law.correct_force_scale(LoadCellStatus::kNone, 0.0), ScaleUpdate::kStale);
  EXPECT_EQ(law.correct_force_scale(LoadCellStatus::kBad, 0.0), ScaleUpdate::kBad);
  EXPECT_EQ(law.force_scale(), moved);
}

}  // namespace control_law
}  // namespace
