// control::ForceScaleCorrection against an independent generator: the "measured" force is a
// second observer whose fluid has drifted through model::ThermalDrift (tests/support/drifted_plant.hpp), the controller's observer
// is the base model with the correction's scale. Nothing here reuses the correction's formula.
#include "control/force_scale_correction.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "model/damper_model.hpp"
#include "model/observer.hpp"
#include "tests/support/drifted_plant.hpp"

namespace {

using mrd::control::ForceScaleCorrection;
using mrd::control::ForceScaleSettings;
using mrd::control::LoadCellObservation;
using mrd::control::LoadCellStatus;
using mrd::control::ScaleUpdate;
using mrd::model::DamperModel;
using mrd::model::Observer;

constexpr double kPeriod = 1e-3;       // [s]
constexpr double kForceRange = 45e3;   // [N], about the default damper's maximum yield force
Observer drifted_plant(double factor) { return mrd::test::drifted_plant(factor, kPeriod); }

// Both observers on the same motion and current; each period the correction sees the plant's
// force (with load-cell noise) against the controller's prediction, and the controller takes
// its scale. `speed` returns the velocity at time t, `current` the coil current.
struct Rig {
  explicit Rig(double plant_factor, ForceScaleSettings settings = {}, double noise_rms = 0.0)
      : plant(drifted_plant(plant_factor)),
        controller(DamperModel{}, {kPeriod}),
        correction(settings, kForceRange, kPeriod),
        noise(0.0, noise_rms) {}

  ScaleUpdate step(double velocity, double current, LoadCellStatus status = LoadCellStatus::kFresh) {
    x += velocity * kPeriod;
    const double measured = plant.step({.displacement = x, .velocity = velocity, .coil_current = current}).force +
                            (noise.stddev() > 0.0 ? noise(rng) : 0.0);
    const double predicted = controller.step({.displacement = x, .velocity = velocity, .coil_current = current}).force;
    const ScaleUpdate u = correction.update({.status = status,
                                             .measured = measured,
                                             .predicted = predicted,
                                             .viscous = controller.damper().force({.velocity = velocity, .yield_stress = 0.0}),
                                             .velocity = velocity});
    controller.set_yield_scale(correction.scale());
    return u;
  }

  Observer plant;
  Observer controller;
  ForceScaleCorrection correction;
  std::mt19937_64 rng{7};
  std::normal_distribution<double> noise;
  double x = 0.0;
};

double sine_velocity(double t) { return 0.126 * std::sin(2.0 * 3.14159265358979 * 0.5 * t); }  // 40 mm at 0.5 Hz
double wandering_current(double t) { return 1.0 + 0.4 * std::sin(2.0 * 3.14159265358979 * 0.13 * t); }

TEST(ForceScaleCorrection, ConvergesToThePlantsYieldScaleOnASineWithNoise) {
  Rig rig(0.8, {}, 200.0);
  for (int i = 0; i < 60000; ++i) {  // 60 s, 12 time constants (but gated out near reversals)
    const double t = i * kPeriod;
    rig.step(sine_velocity(t), wandering_current(t));
  }
  EXPECT_NEAR(rig.correction.scale(), 0.8, 0.01);
  // The corrected prediction now agrees with the plant at a yielding point.
  const double v = 0.1;
  const double plant = rig.plant.step({.displacement = rig.x, .velocity = v, .coil_current = 1.0}).force;
  const double model = rig.controller.step({.displacement = rig.x, .velocity = v, .coil_current = 1.0}).force;
  EXPECT_NEAR(model / plant, 1.0, 0.015);
  EXPECT_GT(rig.correction.moves(), 30000u);
  EXPECT_FALSE(rig.correction.at_bound());
}

TEST(ForceScaleCorrection, ReachesSixtyThreePercentAfterOneTimeConstantGatedIn) {
  for (const double tau : {1.0, 5.0}) {
    ForceScaleSettings s;
    s.time_constant = tau;
    Rig rig(0.8, s);
    // A steady yielding point: every period passes the gate, the ratio is 0.8 each time.
    const double threshold = 1.0 - 0.632 * (1.0 - 0.8);
    int periods = 0;
    while (rig.correction.scale() > threshold && periods < 100000) {
      rig.step(0.1, 1.0);
      ++periods;
    }
    EXPECT_NEAR(periods * kPeriod, tau, 0.01 * tau) << "tau " << tau;
  }
}

// A load cell slower than the loop (one sample in 10 periods, 100 Hz under 1 kHz; max_age
// above its period) moves the scale on the same time scale: tau is seconds, not samples.
TEST(ForceScaleCorrection, TheTimeConstantIsInSecondsWhateverTheLoadCellsRate) {
  ForceScaleSettings s;
  s.time_constant = 1.0;
  s.max_age_periods = 12;
  Rig rig(0.8, s);
  const double threshold = 1.0 - 0.632 * (1.0 - 0.8);
  int periods = 0;
  while (rig.correction.scale() > threshold && periods < 100000) {
    rig.step(0.1, 1.0, periods % 10 == 9 ? LoadCellStatus::kFresh : LoadCellStatus::kNone);
    ++periods;
  }
  // Within one sample's spacing of tau (the scale moves in steps of 10 ms).
  EXPECT_NEAR(periods * kPeriod, 1.0, 0.011);
  EXPECT_EQ(rig.correction.stale_periods(), 0u) << "a sample every 10 periods is not stale at max_age 12";
}

// A plant whose ratio sits right at the bound, with noise: the scale leaves the bound and comes
// back many times, but its arrival is said once until it has come well inside again.
TEST(ForceScaleCorrection, NoiseAtTheBoundSaysTheArrivalOnce) {
  ForceScaleSettings s;
  s.time_constant = 0.2;
  Rig rig(0.7, s, 800.0);
  int reached = 0;
  int arrivals = 0;
  bool was_at_bound = false;
  for (int i = 0; i < 20000; ++i) {
    rig.step(0.1, 1.0);
    reached += rig.correction.reached_bound();
    arrivals += rig.correction.at_bound() && !was_at_bound;
    was_at_bound = rig.correction.at_bound();
  }
  EXPECT_GT(arrivals, 5) << "the noise should lift the scale off the bound now and then";
  EXPECT_EQ(reached, 1);
}

TEST(ForceScaleCorrection, NeverLeavesItsBoundsAndReportsReachingOne) {
  for (const double factor : {0.5, 1.6}) {
    ForceScaleSettings s;
    s.time_constant = 0.5;
    Rig rig(factor, s, 500.0);
    int reached = 0;
    for (int i = 0; i < 20000; ++i) {
      const double t = i * kPeriod;
      rig.step(sine_velocity(t), wandering_current(t));
      reached += rig.correction.reached_bound();
      ASSERT_GE(rig.correction.scale(), 0.7) << "factor " << factor << " period " << i;
      ASSERT_LE(rig.correction.scale(), 1.3) << "factor " << factor << " period " << i;
    }
    EXPECT_DOUBLE_EQ(rig.correction.scale(), factor < 1.0 ? 0.7 : 1.3);
    EXPECT_TRUE(rig.correction.at_bound());
    EXPECT_EQ(reached, 1) << "factor " << factor;
  }
}

TEST(ForceScaleCorrection, DoesNotMoveWhenGatedOut) {
  Rig slow(0.8);
  for (int i = 0; i < 5000; ++i) {
    // Below min_speed, in either direction, with a large yield force.
    EXPECT_EQ(slow.step(i % 2 == 0 ? 0.005 : -0.005, 1.5), ScaleUpdate::kGatedOut);
  }
  EXPECT_EQ(slow.correction.scale(), 1.0);
  Rig weak(0.8);
  for (int i = 0; i < 5000; ++i) {
    // Fast enough, but a virgin core at no current: the zero-field force, below the force gate.
    EXPECT_EQ(weak.step(0.02, 0.0), ScaleUpdate::kGatedOut);
  }
  EXPECT_EQ(weak.correction.scale(), 1.0);
  Rig viscous(0.8);
  for (int i = 0; i < 5000; ++i) {
    // Fast, at no current: the whole force (c0 v, about 8 kN) is above the force gate, the yield
    // part (the zero-field stress's) is not, and the ratio of yield parts would be noise.
    EXPECT_EQ(viscous.step(0.15, 0.0), ScaleUpdate::kGatedOut);
    ASSERT_GT(std::fabs(viscous.controller.estimate().force), 0.1 * kForceRange) << i;
  }
  EXPECT_EQ(viscous.correction.scale(), 1.0);
  EXPECT_EQ(slow.correction.moves() + weak.correction.moves() + viscous.correction.moves(), 0u);
}

TEST(ForceScaleCorrection, AYieldPartOfTheWrongSignIsGatedOut) {
  ForceScaleCorrection c({}, kForceRange, kPeriod);
  // A measured force whose yield part opposes the model's (a load cell wired backwards).
  EXPECT_EQ(c.update({.status = LoadCellStatus::kFresh, .measured = -20e3, .predicted = 20e3, .viscous = 1e3,
                      .velocity = 0.1}),
            ScaleUpdate::kGatedOut);
  EXPECT_EQ(c.scale(), 1.0);
}

TEST(ForceScaleCorrection, FreezesWhileStaleOrBadAndCountsIt) {
  ForceScaleSettings s;
  s.max_age_periods = 5;
  Rig rig(0.8, s);
  for (int i = 0; i < 2000; ++i) rig.step(0.1, 1.0);
  const double moved = rig.correction.scale();
  ASSERT_LT(moved, 0.99);
  for (int i = 0; i < 5; ++i) EXPECT_EQ(rig.step(0.1, 1.0, LoadCellStatus::kNone), ScaleUpdate::kWaiting);
  for (int i = 0; i < 3000; ++i) EXPECT_EQ(rig.step(0.1, 1.0, LoadCellStatus::kNone), ScaleUpdate::kStale);
  EXPECT_EQ(rig.correction.scale(), moved);
  EXPECT_EQ(rig.correction.stale_periods(), 3000u);
  for (int i = 0; i < 1000; ++i) EXPECT_EQ(rig.step(0.1, 1.0, LoadCellStatus::kBad), ScaleUpdate::kBad);
  EXPECT_EQ(rig.correction.scale(), moved);
  EXPECT_EQ(rig.correction.bad_samples(), 1000u);
  // A fresh sample whose value is not finite is a bad one too.
  EXPECT_EQ(rig.correction.update({.status = LoadCellStatus::kFresh,
                                   .measured = std::numeric_limits<double>::quiet_NaN(),
                                   .predicted = 20e3,
                                   .velocity = 0.1}),
            ScaleUpdate::kBad);
  EXPECT_EQ(rig.correction.scale(), moved);
  // Fresh again: it moves on.
  EXPECT_EQ(rig.step(0.1, 1.0), ScaleUpdate::kMoved);
  EXPECT_LT(rig.correction.scale(), moved);
}

TEST(ForceScaleCorrection, SettingsAreValidated) {
  EXPECT_TRUE(validate(ForceScaleSettings{}).ok());
  ForceScaleSettings s;
  s.time_constant = 0.0;
  s.max_correction = 1.0;
  s.max_age_periods = 0;
  const auto r = validate(s);
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.to_string().find("time_constant"), std::string::npos);
  EXPECT_NE(r.to_string().find("max_correction"), std::string::npos);
  EXPECT_NE(r.to_string().find("max_age_periods"), std::string::npos);
}

TEST(ForceScaleCorrection, NoCorrectionAtAllIsRefusedNotABoundReachedAtOnce) {
  ForceScaleSettings s;
  s.max_correction = 0.0;
  const auto r = validate(s);
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.to_string().find("max_correction"), std::string::npos) << r.to_string();
}

}  // namespace
