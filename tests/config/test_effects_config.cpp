// [damper.effects.*] in the TOML config: read, validated, written back, and run by the observer.
#include "config/effects_config.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "config/config_loader.hpp"
#include "tests/config/config_errors.hpp"
#include "control/control_law.hpp"

namespace {

using mrd::config::LoadedConfig;
using mrd::config::load_config_text;

using mrd::test::has_error;

TEST(EffectsConfig, TheDefaultConfigHasEveryEffectOff) {
  const LoadedConfig c = mrd::config::load_default_config();
  ASSERT_TRUE(c.ok()) << c.report();
  EXPECT_FALSE(c.config.law.damper.effects.any_enabled());
}

TEST(EffectsConfig, EnabledEffectsReachTheObserverOfTheControlLaw) {
  const LoadedConfig c = load_config_text(R"(
[damper.effects.gas_spring]
enabled = true
preload = 1500.0
stiffness = 30000
[damper.effects.coil_lag]
enabled = true
time_constant = 0.02
[damper.effects.thermal_drift]
enabled = true
yield_law = "exponential"
)",
                                          "effects.toml");
  ASSERT_TRUE(c.ok()) << c.report();
  const auto& effects = c.config.law.damper.effects;
  EXPECT_TRUE(effects.get<mrd::model::GasSpringEffect>().enabled);
  EXPECT_EQ(effects.get<mrd::model::GasSpringEffect>().stiffness, 30000.0);
  EXPECT_EQ(effects.get<mrd::model::ThermalDriftEffect>().yield_law, mrd::model::TemperatureLaw::kExponential);
  EXPECT_FALSE(effects.get<mrd::model::PreyieldHysteresisEffect>().enabled);

  // The control law built from this config runs them: at rest with no current the force is the
  // gas spring's preload, and the coil current lags the command.
  mrd::control::ControlLaw law(c.config.law);
  mrd::control::ControlLaw base(mrd::control::ControlLawConfig{});
  const mrd::model::Measurement at_rest{.displacement = 0.0, .velocity = 0.0, .coil_current = 1.0};
  const double force = law.observe(at_rest).estimate.force;
  EXPECT_NEAR(force - base.observe(at_rest).estimate.force, 1500.0, 1e-6 * 1500.0);
  EXPECT_TRUE(law.observer().effects().active());
  EXPECT_NEAR(law.observer().effects().coil_current(), -std::expm1(-1e-3 / 0.02), 1e-12);
}

TEST(EffectsConfig, WrittenTablesLoadBackToTheSameEffects) {
  mrd::model::EffectSet e;
  e.get<mrd::model::CoilLagEffect>() = {true, 1.0 / 190.0};
  e.get<mrd::model::PreyieldHysteresisEffect>().enabled = true;
  e.get<mrd::model::PreyieldHysteresisEffect>().A = 301.0;
  e.get<mrd::model::PreyieldHysteresisEffect>().beta = 3.63e6;
  e.get<mrd::model::PreyieldHysteresisEffect>().gamma = -1e5;
  e.get<mrd::model::PreyieldHysteresisEffect>().max_substeps = 200;
  e.get<mrd::model::GasSpringEffect>() = {true, -71.5, 500.0};
  e.get<mrd::model::ThermalDriftEffect>().enabled = true;
  e.get<mrd::model::ThermalDriftEffect>().viscosity_law = mrd::model::TemperatureLaw::kLinear;
  e.get<mrd::model::ThermalDriftEffect>().heat_capacity = 1234.5;
  e.get<mrd::model::SensorDelayEffect>() = {true, 3.3e-3};
  e.get<mrd::model::StrokeEndAirEffect>() = {true, 0.012, 0.75, 2e-3, 5e-5};
  const std::string text = mrd::config::effects_toml(e);
  const LoadedConfig c = load_config_text(text, "written.toml");
  ASSERT_TRUE(c.ok()) << c.report() << text;
  EXPECT_EQ(mrd::config::effects_toml(c.config.law.damper.effects), text);
  EXPECT_EQ(c.config.law.damper.effects.get<mrd::model::SensorDelayEffect>().delay, 3.3e-3);  // shortest round trip
  EXPECT_NE(text.find("[damper.effects.coil_lag]\nenabled = true\n"), std::string::npos) << text;
}

TEST(EffectsConfig, BadValuesAreReportedWithTheirLineAndKey) {
  const LoadedConfig c = load_config_text(R"([damper.effects.coil_lag]
time_constant = -0.001
[damper.effects.thermal_drift]
yield_law = "cubic"
[damper.effects.stroke_end_air]
depht = 0.5
[damper.effects.preyield_hysteresis]
gamma = 1e7
)",
                                          "bad.toml");
  EXPECT_FALSE(c.ok());
  EXPECT_TRUE(has_error(c, "bad.toml:2: damper.effects.coil_lag.time_constant: must lie in [0, 10], got -0.001"))
      << c.report();
  EXPECT_TRUE(has_error(c, "bad.toml:4: damper.effects.thermal_drift.yield_law: must be one of linear, "
                           "exponential, got \"cubic\""))
      << c.report();
  EXPECT_TRUE(has_error(c, "bad.toml:6: damper.effects.stroke_end_air.depht: unknown key (did you mean \"depth\"?)"))
      << c.report();
  EXPECT_TRUE(has_error(c, "bad.toml:8: damper.effects.preyield_hysteresis.gamma: must lie in (-beta, beta] for a "
                           "bounded z"))
      << c.report();
}

}  // namespace
