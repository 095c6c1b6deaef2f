// Every optional effect on: the observer's, the plant's and the control law's steps still make
// no heap allocation. Its own binary, so that the hook sees every allocation of the process.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "control/control_law.hpp"
#include "model/observer.hpp"
#include "sim/damper_plant.hpp"
#include "tests/support/allocation_counter.hpp"

namespace {

using mrd::test::start_counting_allocations;
using mrd::test::stop_counting_allocations;

constexpr int kSteps = 100000;

// Every effect of AllEffects switched on (a new effect is in by construction), some sized so that
// their costlier paths run.
mrd::model::DamperModel every_effect_on() {
  mrd::model::DamperModel m;
  auto& e = m.effects;
  e.for_each([]<typename E>(typename E::Params& p) { p.enabled = true; });
  e.get<mrd::model::PreyieldHysteresisEffect>().n = 1.7;  // the std::pow path as well
  e.get<mrd::model::GasSpringEffect>() = {true, 1500.0, 3e4};
  e.get<mrd::model::SensorDelayEffect>() = {true, 3.5e-3};
  e.get<mrd::model::LearnedTermsEffect>().coefficients.fill(1.0);
  return m;
}

TEST(RealTimeEffects, EveryEffectOfTheListIsOnInTheseTests) {
  const mrd::model::DamperModel m = every_effect_on();
  for (const mrd::model::EffectInfo& info : mrd::model::effect_infos()) EXPECT_TRUE(info.enabled(m.effects)) << info.name;
}

double x_at(int k) { return 0.045 * std::sin(2.0 * std::numbers::pi * 0.5 * k * 1e-3); }
double v_at(int k) { return 0.045 * std::numbers::pi * std::cos(2.0 * std::numbers::pi * 0.5 * k * 1e-3); }
double i_at(int k) { return 0.6 + 0.6 * std::sin(2.0 * std::numbers::pi * 0.7 * k * 1e-3); }

TEST(RealTimeEffects, ObserverStepsWithEveryEffectDoNotAllocate) {
  mrd::model::Observer filtered(every_effect_on());
  mrd::model::Observer sensed(every_effect_on());
  double sink = 0.0;
  start_counting_allocations();
  for (int k = 0; k < kSteps; ++k) {
    sink += filtered.step({.displacement = x_at(k), .coil_current = i_at(k)}).force;
    sink += sensed.step({.displacement = x_at(k), .velocity = v_at(k), .coil_current = i_at(k)}).force;
    if (k == kSteps / 2) sensed.set_measured_temperature(35.0);
  }
  EXPECT_EQ(stop_counting_allocations(), 0u);
  EXPECT_TRUE(std::isfinite(sink));
}

TEST(RealTimeEffects, PlantStepsWithEveryEffectDoNotAllocate) {
  mrd::sim::DamperPlant plant(
      every_effect_on(),
      mrd::sim::PlantSettings{.sample_period = 1e-3, .lvdt_noise_rms = 5e-6, .force_noise_rms = 20.0, .seed = 3});
  double sink = 0.0;
  start_counting_allocations();
  for (int k = 0; k < kSteps; ++k) sink += plant.step({.displacement = x_at(k), .velocity = v_at(k), .coil_current = i_at(k)}).measured_force;
  EXPECT_EQ(stop_counting_allocations(), 0u);
  EXPECT_TRUE(std::isfinite(sink));
}

TEST(RealTimeEffects, ControlLawStepWithEveryEffectDoesNotAllocate) {
  mrd::control::ControlLawConfig config;
  config.damper = every_effect_on();
  mrd::control::ControlLaw law(config);
  double coil = 0.0;
  start_counting_allocations();
  for (int k = 0; k < kSteps; ++k) {
    law.observe({.displacement = x_at(k), .coil_current = coil});
    coil = law.command().current;
  }
  EXPECT_EQ(stop_counting_allocations(), 0u);
  EXPECT_TRUE(std::isfinite(coil));
}

}  // namespace
