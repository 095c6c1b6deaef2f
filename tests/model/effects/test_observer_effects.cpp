// The observer with optional effects: off is the base model bit for bit; each one on changes
// the force the way its physics says.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>
#include <type_traits>

#include "model/effects/sensor_delay.hpp"
#include "model/observer.hpp"

namespace {

using mrd::model::DamperModel;
using mrd::model::EffectSet;
using mrd::model::Observer;
using mrd::model::CoilLagEffect;
using mrd::model::GasSpringEffect;
using mrd::model::PreyieldHysteresisEffect;
using mrd::model::SensorDelayEffect;
using mrd::model::StrokeEndAirEffect;
using mrd::model::ThermalDriftEffect;

constexpr double kT = 1e-3;

double x_at(int k) { return 0.040 * std::sin(2.0 * std::numbers::pi * 0.5 * k * kT); }
double v_at(int k) { return 0.040 * std::numbers::pi * std::cos(2.0 * std::numbers::pi * 0.5 * k * kT); }
double i_at(int k) { return 0.6 - 0.6 * std::cos(2.0 * std::numbers::pi * 0.5 * k * kT); }

DamperModel with(void (*enable)(EffectSet&)) {
  DamperModel m;
  enable(m.effects);
  return m;
}

// RMS of the force difference between two observers over two cycles with the true velocity.
double rms_force_change(const DamperModel& a, const DamperModel& b) {
  Observer oa(a), ob(b);
  double sum = 0.0;
  for (int k = 0; k < 4000; ++k) {
    const double d = oa.step({.displacement = x_at(k), .velocity = v_at(k), .coil_current = i_at(k)}).force - ob.step({.displacement = x_at(k), .velocity = v_at(k), .coil_current = i_at(k)}).force;
    sum += d * d;
  }
  return std::sqrt(sum / 4000);
}

TEST(ObserverEffects, AllOffIsTheBaseModelBitForBit) {
  DamperModel m;
  m.effects.get<CoilLagEffect>().time_constant = 0.5;  // parameters of disabled effects change nothing
  m.effects.get<GasSpringEffect>().preload = 1e4;
  Observer observer(m);
  mrd::model::JilesAtherton ja(m.jiles_atherton, m.circuit, m.integration);
  const mrd::model::YieldStress tau(m.fluid);
  const mrd::model::BinghamDamper bingham(m.geometry, m.fluid.viscosity);
  for (int k = 0; k < 3000; ++k) {
    const auto e = observer.step({.displacement = x_at(k), .velocity = v_at(k), .coil_current = i_at(k)});
    const double B = ja.apply_current(i_at(k));
    ASSERT_EQ(e.B, B);
    ASSERT_EQ(e.force, bingham.force({.velocity = v_at(k), .yield_stress = tau(B)}));
  }
  // Two copies of the same J-A would agree bit for bit through a clamp or a reset too.
  EXPECT_EQ(observer.magnetics().guard_events(), 0u);
  EXPECT_EQ(observer.magnetics().recoveries(), 0u);
}

// The force from a known B is the force of the step that computed that B, for the base model
// and with every effect after B on (the J-A state and the coil lag are left alone).
TEST(ObserverEffects, StepAtInductionGivesTheStepsForceForItsB) {
  for (const bool effects : {false, true}) {
    DamperModel m;
    if (effects) {
      m.effects.get<ThermalDriftEffect>().enabled = true;
      m.effects.get<PreyieldHysteresisEffect>().enabled = true;
      m.effects.get<GasSpringEffect>().enabled = true;
      m.effects.get<StrokeEndAirEffect>().enabled = true;
      m.effects.get<SensorDelayEffect>().enabled = true;
    }
    Observer full(m), at_B(m);
    for (int k = 0; k < 3000; ++k) {
      const auto e = full.step({.displacement = x_at(k), .velocity = v_at(k), .coil_current = i_at(k)});
      const auto f = at_B.step_at_induction({.displacement = x_at(k), .velocity = v_at(k)}, e.B);
      ASSERT_EQ(f.force, e.force) << "effects " << effects << ", step " << k;
      ASSERT_EQ(f.yield_stress, e.yield_stress);
    }
    EXPECT_EQ(at_B.magnetics().B(), 0.0) << "the J-A state is not touched";
  }
}

TEST(ObserverEffects, GasSpringAddsExactlyItsForce) {
  const auto m = with([](EffectSet& e) { e.get<GasSpringEffect>() = {true, 1500.0, 3e4}; });
  Observer base(DamperModel{}), sprung(m);
  for (int k = 0; k < 2000; ++k) {
    const double d = sprung.step({.displacement = x_at(k), .velocity = v_at(k), .coil_current = i_at(k)}).force - base.step({.displacement = x_at(k), .velocity = v_at(k), .coil_current = i_at(k)}).force;
    ASSERT_NEAR(d, 1500.0 + 3e4 * x_at(k), 1e-9) << k;
  }
}

TEST(ObserverEffects, CoilLagDelaysTheField) {
  const auto m = with([](EffectSet& e) { e.get<CoilLagEffect>() = {true, 20e-3}; });
  Observer lagged(m);
  Observer base{DamperModel{}};
  const auto step_b = base.step({.displacement = 0.0, .velocity = 0.1, .coil_current = 1.0});
  const auto step_l = lagged.step({.displacement = 0.0, .velocity = 0.1, .coil_current = 1.0});
  EXPECT_LT(step_l.B, 0.2 * step_b.B);  // after one period the current is 1 - exp(-1/20) = 5 %
  EXPECT_NEAR(lagged.effects().coil_current(), -std::expm1(-1.0 / 20.0), 1e-12);
  for (int k = 0; k < 200; ++k) lagged.step({.displacement = 0.0, .velocity = 0.1, .coil_current = 1.0});  // 10 tau later it has caught up
  EXPECT_NEAR(lagged.estimate().B, base.step({.displacement = 0.0, .velocity = 0.1, .coil_current = 1.0}).B, 1e-3);
}

// Samples taken unevenly (a USB logger's), each step given its own length: the lag's current
// and the pre-yield state are those of the continuous laws at the samples' true times, the lag's
// 1 - exp(-t/tau) and, for n = 2 from z = 0 at a constant v, z = z_max tanh(A v t / z_max).
TEST(ObserverEffects, StepsOfTheirOwnLengthKeepTheEffectsOnTheClock) {
  const double tau = 10e-3;
  const double v = 2e-3;  // [m/s]: 2 um a period, z covers its range in about 0.5 s
  const auto m = with([](EffectSet& e) {
    e.get<CoilLagEffect>() = {true, 10e-3};
    e.get<PreyieldHysteresisEffect>().enabled = true;
  });
  const auto p = m.effects.get<PreyieldHysteresisEffect>();
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> jitter(0.6 * kT, 1.4 * kT);
  std::vector<double> steps(600);
  for (double& dt : steps) dt = jitter(rng);

  Observer timed(m), counted(m);
  double t = 0.0;
  double worst_counted = 0.0;
  for (std::size_t k = 0; k < steps.size(); ++k) {
    t += steps[k];
    timed.step({.displacement = v * t, .velocity = v, .coil_current = 1.0, .step_duration = steps[k]});
    counted.step({.displacement = v * t, .velocity = v, .coil_current = 1.0});
    const double lag = -std::expm1(-t / tau);
    ASSERT_NEAR(timed.effects().coil_current(), lag, 1e-12) << k;
    const double z = timed.effects().element<PreyieldHysteresisEffect>().z();
    ASSERT_NEAR(z, p.z_max() * std::tanh(p.A * v * t / p.z_max()), 1e-4 * p.z_max()) << k;
    worst_counted = std::max(worst_counted, std::fabs(counted.effects().coil_current() - lag));
  }
  // Counted a period a sample, the same run's current is off by up to a few per cent.
  EXPECT_GT(worst_counted, 0.01);
  // Without a length the steps are the sample period again.
  const double before = timed.effects().coil_current();
  timed.step({.displacement = v * t, .velocity = v, .coil_current = 0.0});
  EXPECT_NEAR(timed.effects().coil_current(), before * std::exp(-kT / tau), 1e-12);
}

TEST(ObserverEffects, ThermalDriftLowersTheForceAsTheFluidHeats) {
  auto m = with([](EffectSet& e) {
    e.get<ThermalDriftEffect>().enabled = true;
    e.get<ThermalDriftEffect>().heat_capacity = 2000.0;  // small: it heats within the test
  });
  Observer hot(m), base{DamperModel{}};
  for (int k = 0; k < 4000; ++k) {
    hot.step({.displacement = x_at(k), .velocity = v_at(k), .coil_current = i_at(k)});
    base.step({.displacement = x_at(k), .velocity = v_at(k), .coil_current = i_at(k)});
  }
  EXPECT_GT(hot.effects().temperature(), 25.0);
  EXPECT_LT(std::fabs(hot.estimate().force), std::fabs(base.estimate().force));
  EXPECT_LT(hot.estimate().yield_stress, base.estimate().yield_stress);
  // A measured temperature at the reference gives the base model's yield stress back.
  hot.set_measured_temperature(20.0);
  const auto e = hot.step({.displacement = x_at(4000), .velocity = v_at(4000), .coil_current = i_at(4000)});
  EXPECT_NEAR(e.yield_stress, base.step({.displacement = x_at(4000), .velocity = v_at(4000), .coil_current = i_at(4000)}).yield_stress, 1e-6);
}

TEST(ObserverEffects, EachEffectChangesTheForce) {
  const DamperModel base;
  EXPECT_GT(rms_force_change(base, with([](EffectSet& e) { e.get<CoilLagEffect>().enabled = true; })), 100.0);
  EXPECT_GT(rms_force_change(base, with([](EffectSet& e) { e.get<PreyieldHysteresisEffect>().enabled = true; })), 100.0);
  EXPECT_GT(rms_force_change(base, with([](EffectSet& e) { e.get<ThermalDriftEffect>() = {.enabled = true, .heat_capacity = 500.0}; })), 100.0);
  EXPECT_GT(rms_force_change(base, with([](EffectSet& e) { e.get<StrokeEndAirEffect>().enabled = true; })), 100.0);
  EXPECT_GT(rms_force_change(base, with([](EffectSet& e) { e.get<GasSpringEffect>() = {true, 100.0, 0.0}; })), 99.0);
  EXPECT_GT(rms_force_change(base, with([](EffectSet& e) { e.get<SensorDelayEffect>() = {true, 5e-3}; })), 10.0);
}

// The observer fed by a late LVDT: with sensor_delay on it predicts the motion across the delay
// and its force is closer to the force of an observer that sees the true displacement.
TEST(ObserverEffects, SensorDelayCompensationBringsBackTheTrueForce) {
  const double delay = 8e-3;
  const auto compensating = with([](EffectSet& e) { e.get<SensorDelayEffect>() = {true, 8e-3}; });
  Observer truth{DamperModel{}}, naive{DamperModel{}}, predicted(compensating);
  mrd::model::SensorDelay lvdt({true, delay}, kT);
  double naive_sq = 0.0;
  double predicted_sq = 0.0;
  for (int k = 0; k < 6000; ++k) {
    const double late = lvdt.step(x_at(k));
    const double f = truth.step({.displacement = x_at(k), .coil_current = i_at(k)}).force;
    const double a = naive.step({.displacement = late, .coil_current = i_at(k)}).force - f;
    const double b = predicted.step({.displacement = late, .coil_current = i_at(k)}).force - f;
    if (k >= 2000) {
      naive_sq += a * a;
      predicted_sq += b * b;
    }
  }
  EXPECT_LT(predicted_sq, 0.25 * naive_sq);
}

TEST(ObserverEffects, ResetRestartsEveryEffect) {
  // Every effect of the list on (a new one is in by construction), the thermal drift fast.
  auto m = with([](EffectSet& e) {
    e.for_each([]<typename E>(typename E::Params& p) { p.enabled = true; });
    e.get<ThermalDriftEffect>().heat_capacity = 500.0;
    e.get<GasSpringEffect>().preload = 100.0;
  });
  Observer a(m), b(m);
  for (int k = 0; k < 3000; ++k) a.step({.displacement = x_at(k), .coil_current = i_at(k)});
  a.reset();
  for (int k = 0; k < 3000; ++k) ASSERT_EQ(a.step({.displacement = x_at(k), .coil_current = i_at(k)}).force, b.step({.displacement = x_at(k), .coil_current = i_at(k)}).force);
}

TEST(ObserverEffects, ValidateReportsEffectFieldsUnderTheirPath) {
  DamperModel m;
  m.effects.get<CoilLagEffect>().time_constant = -1.0;
  const auto report = validate(m);
  ASSERT_FALSE(report.ok());
  EXPECT_EQ(report.issues().front().field, "effects.coil_lag.time_constant");
}

}  // namespace

namespace {

// Every effect of AllEffects on alone, at its defaults: a new effect is walked by construction.
// Two are sized by their parameters and are zero at their defaults (the gas spring's preload
// and stiffness, learned_terms' terms): with them on, the observer gives the base model's force
// bit for bit.
TEST(ObserverEffects, EveryEffectOfTheListOnAloneAtItsDefaultsChangesTheForce) {
  const DamperModel base;
  std::size_t walked = 0;
  mrd::model::for_each_effect_type([&]<typename E>() {
    DamperModel on;
    on.effects.get<E>().enabled = true;
    const double change = rms_force_change(base, on);
    if constexpr (std::is_same_v<E, mrd::model::LearnedTermsEffect> || std::is_same_v<E, GasSpringEffect>) {
      EXPECT_EQ(change, 0.0) << E::kName;
    } else {
      EXPECT_GT(change, 1.0) << E::kName;
    }
    ++walked;
  });
  EXPECT_EQ(walked, mrd::model::effect_infos().size());
}

}  // namespace
