// Spencer et al. (1997) modified Bouc-Wen model with the published parameters of Dyke's damper.
#include "model/spencer_bouc_wen.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

namespace {

using mrd::model::SpencerBoucWen;
using mrd::model::SpencerBoucWenParams;

constexpr double kT = 1.0 / 3004.8;  // the rate of Dyke's recording

TEST(SpencerBoucWen, PublishedParametersInSi) {
  const auto p = SpencerBoucWenParams::dyke_prototype();
  EXPECT_DOUBLE_EQ(p.c0a, 2100.0);    // 21 N s/cm
  EXPECT_DOUBLE_EQ(p.c0b, 350.0);     // 3.5 N s/(cm V)
  EXPECT_DOUBLE_EQ(p.k0, 4690.0);     // 46.9 N/cm
  EXPECT_DOUBLE_EQ(p.c1a, 28300.0);   // 283 N s/cm
  EXPECT_DOUBLE_EQ(p.c1b, 295.0);     // 2.95 N s/(cm V)
  EXPECT_DOUBLE_EQ(p.k1, 500.0);      // 5 N/cm
  EXPECT_DOUBLE_EQ(p.x0, 0.143);      // 14.3 cm
  EXPECT_DOUBLE_EQ(p.alpha_a, 14000.0);
  EXPECT_DOUBLE_EQ(p.alpha_b, 69500.0);
  EXPECT_DOUBLE_EQ(p.gamma, 3.63e6);  // 363 cm^-2
  EXPECT_DOUBLE_EQ(p.beta, 3.63e6);
  EXPECT_EQ(p.A, 301.0);
  EXPECT_EQ(p.eta, 190.0);
  EXPECT_TRUE(validate(p).ok()) << validate(p).to_string();
}

// By hand: at rest (x = y = 0, z = 0, y' = 0) only the accumulator acts, F = k1 (0 - x0).
TEST(SpencerBoucWen, AtRestTheForceIsTheAccumulatorPreload) {
  SpencerBoucWen m(SpencerBoucWenParams::dyke_prototype(), kT);
  for (int k = 0; k < 100; ++k) EXPECT_NEAR(m.step({.displacement = 0.0, .velocity = 0.0, .command_voltage = 2.25}), -500.0 * 0.143, 1e-9);
}

TEST(SpencerBoucWen, VoltageFilterHasTimeConstantOneOverEta) {
  SpencerBoucWen m(SpencerBoucWenParams::dyke_prototype(), 1e-4);
  const int n = static_cast<int>(std::lround(1.0 / 190.0 / 1e-4));  // 53 steps ~ 1/eta
  for (int k = 0; k < n; ++k) m.step({.displacement = 0.0, .velocity = 0.0, .command_voltage = 2.0});
  EXPECT_NEAR(m.state().u, 2.0 * (1.0 - std::exp(-190.0 * n * 1e-4)), 1e-9);
}

struct SineResult {
  double peak = 0.0;        // max |F| over the last two cycles [N]
  double dissipated = 0.0;  // closed integral of F dx over them [J]
  double closure = 0.0;     // max |F(t) - F(t - period)| over the last cycle [N]
};

// Spencer's test: 2.5 Hz sine of 1.5 cm amplitude at a constant voltage.
SineResult run_sine(double voltage) {
  SpencerBoucWen m(SpencerBoucWenParams::dyke_prototype(), kT);
  const double w = 2.0 * std::numbers::pi * 2.5;
  const int per_cycle = static_cast<int>(std::lround(1.0 / 2.5 / kT));
  std::vector<double> force;
  SineResult r;
  for (int k = 0; k < 4 * per_cycle; ++k) {
    const double t = k * kT;
    const double v = 0.015 * w * std::cos(w * t);
    force.push_back(m.step({.displacement = 0.015 * std::sin(w * t), .velocity = v, .command_voltage = voltage}));
    if (k >= 2 * per_cycle) {
      r.peak = std::max(r.peak, std::fabs(force.back()));
      r.dissipated += force.back() * v * kT;
    }
    if (k >= 3 * per_cycle) r.closure = std::max(r.closure, std::fabs(force.back() - force[k - per_cycle]));
  }
  return r;
}

TEST(SpencerBoucWen, LoopClosesDissipatesAndVoltageRaisesTheForce) {
  const SineResult off = run_sine(0.0);
  const SineResult on = run_sine(2.25);
  // About 0.6 kN and 1.7 kN: the scale of Spencer's Fig. 8 for this damper.
  EXPECT_GT(off.peak, 400.0);
  EXPECT_LT(off.peak, 900.0);
  EXPECT_GT(on.peak, 2.2 * off.peak);
  EXPECT_LT(on.peak, 2500.0);
  EXPECT_GT(off.dissipated, 0.0);
  EXPECT_GT(on.dissipated, 2.5 * off.dissipated);
  // The sample rate is not a whole number of samples per cycle, so the loops agree only to
  // within one sample's change of force.
  EXPECT_LT(off.closure, 5.0);
  EXPECT_LT(on.closure, 15.0);
}

TEST(SpencerBoucWen, ForceStaysBoundedUnderRandomMotionAndTelegraphVoltage) {
  SpencerBoucWen m(SpencerBoucWenParams::dyke_prototype(), kT);
  std::mt19937_64 rng(11);
  std::normal_distribution<double> accel(0.0, 30.0);
  std::uniform_real_distribution<double> flip(0.0, 1.0);
  double x = 0.0, v = 0.0, voltage = 0.0, peak = 0.0;
  for (int k = 0; k < 30000; ++k) {
    v = 0.98 * v + accel(rng) * kT;  // a random velocity of about 0.1 m/s RMS
    x = 0.999 * x + v * kT;
    if (flip(rng) < kT / 0.02) voltage = voltage > 0.0 ? 0.0 : 2.25;  // 20 ms mean dwell
    const double f = m.step({.displacement = x, .velocity = v, .command_voltage = voltage});
    ASSERT_TRUE(std::isfinite(f)) << k;
    peak = std::max(peak, std::fabs(f));
  }
  EXPECT_LT(peak, 5000.0);
  EXPECT_LE(std::fabs(m.state().z), std::sqrt(301.0 / 7.26e6) * (1.0 + 1e-12));
}

TEST(SpencerBoucWen, ValidateRejectsAnUnboundedBoucWen) {
  auto p = SpencerBoucWenParams::dyke_prototype();
  p.gamma = -p.beta;
  const auto report = validate(p);
  ASSERT_FALSE(report.ok());
  EXPECT_EQ(report.issues().front().field, "gamma");
}

}  // namespace
