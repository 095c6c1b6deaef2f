// PreyieldHysteresis: Bouc-Wen's z and the force-velocity loop it opens near v = 0.
#include "model/effects/preyield_hysteresis.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

namespace {

using mrd::model::PreyieldHysteresis;
using mrd::model::PreyieldHysteresisParams;

// Spencer's A = 301, gamma = beta = 363 cm^-2 (Dyke's damper) in SI: a stiff Bouc-Wen element,
// z_max = 6.4 mm reached within about 20 um of travel.
PreyieldHysteresisParams spencer_like() {
  PreyieldHysteresisParams p;
  p.enabled = true;
  p.A = 301.0;
  p.beta = 3.63e6;
  p.gamma = 3.63e6;
  p.n = 2.0;
  p.stiffness = 14000.0;  // alpha_a, 140 N/cm
  return p;
}

TEST(PreyieldHysteresis, ZMaxIsTheBoundOfTheClosedForm) {
  EXPECT_NEAR(PreyieldHysteresisParams{}.z_max(), 1e-3, 1e-15);
  EXPECT_NEAR(spencer_like().z_max(), std::sqrt(301.0 / 7.26e6), 1e-15);
}

// For n = 2 and z from 0 with v > 0, dz/dx = A - (beta + gamma) z^2 has the solution
// z = z_max tanh(A x / z_max). Large steps (many sub-steps) must land on it.
TEST(PreyieldHysteresis, MatchesTheClosedFormForNEqualsTwoAtAStiffSamplePeriod) {
  const auto p = spencer_like();
  const double T = 1.0 / 3004.8;  // Dyke's sample rate
  const double v = 0.05;          // 5 cm/s: 17 um per period, most of the transition
  PreyieldHysteresis h(p, T);
  const double zm = p.z_max();
  for (int k = 1; k <= 20; ++k) {
    const double z = h.step(v);
    const double exact = zm * std::tanh(p.A * v * T * k / zm);
    EXPECT_NEAR(z, exact, 1e-4 * zm) << k;  // RK4 at |lambda h| <= 0.5: about 2e-5 z_max
  }
}

TEST(PreyieldHysteresis, ZStaysBoundedForAnyVelocitySequence) {
  for (const double n : {1.0, 1.5, 2.0, 3.0}) {
    auto p = spencer_like();
    p.n = n;
    p.gamma = 0.3 * p.beta;
    PreyieldHysteresis h(p, 1e-3);
    std::mt19937_64 rng(7);
    std::normal_distribution<double> v(0.0, 0.05);
    double max_z = 0.0;
    for (int k = 0; k < 20000; ++k) max_z = std::max(max_z, std::fabs(h.step(v(rng))));
    EXPECT_LE(max_z, p.z_max() * (1.0 + 1e-12)) << n;
    EXPECT_GT(max_z, 0.9 * p.z_max()) << n;
  }
}

// The loop in force-displacement: the closed integral of alpha z dx is dissipated energy (> 0),
// and after the first cycle the loop closes.
TEST(PreyieldHysteresis, LoopAreaIsPositiveAndTheLoopCloses) {
  auto p = PreyieldHysteresisParams{};
  p.enabled = true;
  p.stiffness = 1e6;  // 1 kN at z_max = 1 mm
  const double T = 1e-3;
  const double amplitude = 5e-3;
  const double f = 1.0;
  PreyieldHysteresis h(p, T);
  const int per_cycle = 1000;
  double area = 0.0;
  double z_end_1 = 0.0;
  double z_end_2 = 0.0;
  for (int k = 0; k < 3 * per_cycle; ++k) {
    const double t = k * T;
    const double v = amplitude * 2.0 * std::numbers::pi * f * std::cos(2.0 * std::numbers::pi * f * t);
    const double z = h.step(v);
    if (k >= 2 * per_cycle) area += p.stiffness * z * v * T;
    if (k == 2 * per_cycle - 1) z_end_1 = z;
    if (k == 3 * per_cycle - 1) z_end_2 = z;
  }
  EXPECT_GT(area, 0.0);
  // Bounded by a rectangle of height 2 alpha z_max over the stroke.
  EXPECT_LT(area, 2.0 * p.stiffness * p.z_max() * 2.0 * amplitude);
  EXPECT_NEAR(z_end_1, z_end_2, 1e-9);
}

// Force-velocity: at the same small velocity the force differs just after a reversal (z still
// on its way) from the force in steady motion: the loop opens near v = 0.
TEST(PreyieldHysteresis, ForceLagsTheVelocityAfterAReversal) {
  PreyieldHysteresisParams p;
  p.enabled = true;
  PreyieldHysteresis h(p, 1e-3);
  const double yield_force = 1000.0;
  const mrd::model::FluidForceParts at_20_mm_s{
      .yield_force = yield_force, .sign_term = std::tanh(0.02 / 1e-3), .viscous_force = 0.0, .velocity = 0.02};
  for (int k = 0; k < 1000; ++k) h.step(-0.05);  // long travel down: z = -z_max
  h.step(0.02);                                   // reversed: 20 um up
  const double just_reversed = h.fluid_force(at_20_mm_s);
  for (int k = 0; k < 1000; ++k) h.step(0.02);
  const double steady = h.fluid_force(at_20_mm_s);
  EXPECT_NEAR(steady, yield_force, 1.0);
  EXPECT_LT(just_reversed, 0.6 * steady);  // half of the yield force still points down
}

TEST(PreyieldHysteresis, ValidateNamesTheBadField) {
  EXPECT_TRUE(validate(PreyieldHysteresisParams{}).ok());
  auto p = PreyieldHysteresisParams{};
  p.gamma = 2.0 * p.beta;
  auto report = validate(p);
  ASSERT_FALSE(report.ok());
  EXPECT_EQ(report.issues().front().field, "gamma");
  p = {};
  p.yield_fraction = 1.5;
  report = validate(p);
  ASSERT_FALSE(report.ok());
  EXPECT_EQ(report.issues().front().field, "yield_fraction");
}

}  // namespace
