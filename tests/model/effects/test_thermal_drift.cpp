// ThermalDrift: the lumped temperature and the viscosity and yield factors.
#include "model/effects/thermal_drift.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace {

using mrd::model::TemperatureLaw;
using mrd::model::ThermalDrift;
using mrd::model::ThermalDriftParams;

ThermalDriftParams thermal_on() {
  ThermalDriftParams p;
  p.enabled = true;
  p.heat_capacity = 1000.0;        // J/K
  p.cooling_time_constant = 100.0;  // s
  return p;
}

TEST(ThermalDrift, HeatsTowardsTheBalanceOfPowerAndCoolingExactly) {
  const auto p = thermal_on();
  const double T = 1e-2;
  ThermalDrift d(p, T);
  const double power = 50.0;  // W: settles at 20 + 50 * 100 / 1000 = 25 degC
  for (int k = 0; k < 10000; ++k) d.heat(power);
  const double expected = 25.0 - 5.0 * std::exp(-10000 * T / p.cooling_time_constant);
  EXPECT_NEAR(d.temperature(), expected, 1e-9);
  // Early on, the rise is P / C per second (cooling has not started).
  ThermalDrift early(p, T);
  early.heat(power);
  EXPECT_NEAR(early.temperature() - 20.0, power / p.heat_capacity * T, 1e-6);
}

// Steps of their own length (samples taken unevenly) land on the same exact curve in time.
TEST(ThermalDrift, StepsOfTheirOwnLengthHeatOnTheClock) {
  const auto p = thermal_on();
  ThermalDrift d(p, 1e-2);
  const double power = 50.0;
  double t = 0.0;
  for (int k = 0; k < 3000; ++k) {
    const double dt = k % 3 == 0 ? 0.5 : 0.02;  // [s]
    d.set_step(dt);
    d.heat(power);
    t += dt;
    ASSERT_NEAR(d.temperature(), 25.0 - 5.0 * std::exp(-t / p.cooling_time_constant), 1e-9) << k;
  }
}

TEST(ThermalDrift, FactorsFallWhenHeatingAndRecoverWhenCooling) {
  const auto p = thermal_on();
  ThermalDrift d(p, 1e-2);
  EXPECT_EQ(d.viscosity_factor(), 1.0);
  EXPECT_EQ(d.yield_factor(), 1.0);
  for (int k = 0; k < 20000; ++k) d.heat(200.0);  // 200 s at 200 W
  const double hot = d.temperature();
  EXPECT_GT(hot, 30.0);
  EXPECT_NEAR(d.viscosity_factor(), std::exp(-p.viscosity_coefficient * (hot - 20.0)), 1e-12);
  EXPECT_NEAR(d.yield_factor(), 1.0 - p.yield_coefficient * (hot - 20.0), 1e-12);
  EXPECT_LT(d.viscosity_factor(), d.yield_factor());  // viscosity is the more sensitive
  for (int k = 0; k < 200000; ++k) d.heat(0.0);  // 2000 s = 20 tau_th without power
  EXPECT_NEAR(d.temperature(), 20.0, 1e-6);
  EXPECT_NEAR(d.viscosity_factor(), 1.0, 1e-6);
  EXPECT_NEAR(d.yield_factor(), 1.0, 1e-6);
}

TEST(ThermalDrift, LinearLawStopsAtTheFloor) {
  auto p = thermal_on();
  p.viscosity_law = TemperatureLaw::kLinear;
  p.viscosity_coefficient = 0.05;
  ThermalDrift d(p, 1.0);
  d.set_measured_temperature(60.0);  // 1 - 0.05 * 40 = -1: floored
  EXPECT_EQ(d.viscosity_factor(), p.min_factor);
}

TEST(ThermalDrift, AMeasuredTemperatureReplacesTheModelUntilNaN) {
  ThermalDrift d(thermal_on(), 1e-2);
  d.set_measured_temperature(45.0);
  d.heat(1e6);
  EXPECT_EQ(d.temperature(), 45.0);
  EXPECT_NEAR(d.yield_factor(), 1.0 - 0.004 * 25.0, 1e-12);
  d.set_measured_temperature(std::numeric_limits<double>::infinity());  // a broken reading
  EXPECT_EQ(d.temperature(), 45.0);
  d.set_measured_temperature(std::numeric_limits<double>::quiet_NaN());
  EXPECT_GT(d.temperature(), 20.0);  // the lumped state heated meanwhile
  EXPECT_LT(d.temperature(), 45.0);
}

TEST(ThermalDrift, ValidateRejectsNonPhysicalValues) {
  EXPECT_TRUE(validate(ThermalDriftParams{}).ok());
  auto p = ThermalDriftParams{};
  p.heat_capacity = 0.0;
  p.yield_coefficient = -0.01;
  const auto report = validate(p);
  ASSERT_EQ(report.issues().size(), 2u);
  EXPECT_EQ(report.issues()[0].field, "heat_capacity");
  EXPECT_EQ(report.issues()[1].field, "yield_coefficient");
}

}  // namespace
