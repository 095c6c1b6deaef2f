// The strategies' pieces: Dyke's switching rule, the static inverse against an anhysteretic
// curve and Eq. 11-13 computed here from the paper's formulas.
#include "tools/force_run/force_strategies.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "tools/force_run/force_run.hpp"

namespace {
namespace force_strategies_test {

using mrd::model::CompensatorLimits;
using mrd::model::DamperModel;
using mrd::model::Observer;
using mrd::tools::clipped_on_off_wants_maximum;

constexpr double kMu0 = 4e-7 * 3.14159265358979323846;

// (f_c - f) f > 0: more force wanted in the direction the damper already pushes.
TEST(ClippedOnOff, SwitchesOnOnlyWhenMoreDissipativeForceIsWanted) {
  EXPECT_TRUE(clipped_on_off_wants_maximum(10e3, 5e3));
  EXPECT_TRUE(clipped_on_off_wants_maximum(-10e3, -5e3));
  EXPECT_FALSE(clipped_on_off_wants_maximum(3e3, 5e3));    // already more than wanted
  EXPECT_FALSE(clipped_on_off_wants_maximum(-3e3, -5e3));
  EXPECT_FALSE(clipped_on_off_wants_maximum(10e3, -5e3));  // wanted against the present force
  EXPECT_FALSE(clipped_on_off_wants_maximum(-10e3, 5e3));
  EXPECT_FALSE(clipped_on_off_wants_maximum(10e3, 0.0));   // no force measured: the product is 0
}

TEST(ClippedOnOff, CommandsMaximumOrNoneThroughTheDriversSlew) {
  CompensatorLimits limits;
  limits.min_current = -1.5;
  const DamperModel m;
  const Observer observer(m);
  mrd::tools::ClippedOnOff law(limits, 1e-3);
  double i = 0.0;
  for (int k = 0; k < 20; ++k) i = law.command({.demand = {10e3, 0.1}, .measured_force = 5e3}, observer);
  EXPECT_NEAR(i, 1.5, 1e-12);  // 0.1 A a period at 100 A/s: there after 15 periods
  i = law.command({.demand = {1e3, 0.1}, .measured_force = 5e3}, observer);
  EXPECT_NEAR(i, 1.4, 1e-12);  // heading for none at the slew rate
  for (int k = 0; k < 20; ++k) i = law.command({.demand = {1e3, 0.1}, .measured_force = 5e3}, observer);
  EXPECT_NEAR(i, 0.0, 1e-12);  // and not below: "zero", not the driver's negative end
}

// The anhysteretic B of the default material at current I, by fixed-point iteration of
// M = Ms (coth(He / a) - a / He), He = H + alpha M (Eq. 3-4), with H = N I / Le (Eq. 9).
double anhysteretic_B(const DamperModel& m, double current) {
  const auto& p = m.jiles_atherton;
  const double H = m.circuit.turns * current / m.circuit.effective_length;
  double M = 0.0;
  for (int i = 0; i < 2000; ++i) {
    const double He = H + p.alpha * M;
    const double x = He / p.a;
    const double L = std::fabs(x) < 1e-4 ? x / 3.0 : 1.0 / std::tanh(x) - 1.0 / x;
    M = 0.5 * M + 0.5 * p.Ms * L;  // damped: alpha Ms / 3a = 0.22 converges either way
  }
  return kMu0 * (H + M);
}

TEST(InverseBingham, CurrentForInvertsTheAnhystereticCurve) {
  const DamperModel m;
  CompensatorLimits limits;
  limits.min_current = -1.5;
  const Observer observer(m);
  const mrd::tools::InverseBingham inverse(observer, limits);
  for (const double I : {0.05, 0.2, 0.5, 0.9, 1.2, 1.45}) {
    const double B = anhysteretic_B(m, I);
    EXPECT_NEAR(inverse.current_for(B), I, 2e-3) << I;   // the 257-point table's interpolation
    EXPECT_NEAR(inverse.current_for(-B), I, 2e-3) << I;  // the static inverse only knows |B|
  }
  EXPECT_DOUBLE_EQ(inverse.current_for(0.0), 0.0);
  EXPECT_DOUBLE_EQ(inverse.current_for(5.0), 1.5);  // beyond the curve: the maximum
}

// A demand made from Eq. 11-13 at a known current with these formulas, the default geometry
// and fluid (docs/MODEL.md), is answered with that current once the driver has slewed there.
TEST(InverseBingham, AnswersAForwardModelDemandWithItsCurrent) {
  const DamperModel m;
  CompensatorLimits limits;
  limits.min_current = -1.5;
  Observer observer(m);
  mrd::tools::InverseBingham law(observer, limits);
  const double I = 0.8, v = 0.05;
  const double B = anhysteretic_B(m, I);
  const double V = m.fluid.volume_fraction;
  const double tau = 146960.0 * std::pow(B, 0.5811) * std::pow(V, 1.706) * std::pow(1.5, 0.2) * std::pow(2.1, 0.8) +
                     1083.2 * V - 287.03;  // Eq. 13, rho in um, Ms in T
  const auto& g = m.geometry;
  const double c0 = 12.0 * m.fluid.viscosity * g.pole_length * g.piston_area * g.piston_area /
                    (3.14159265358979323846 * g.piston_diameter * std::pow(g.gap, 3));
  const double F = 3.0 * g.piston_area * g.pole_length / g.gap * tau * std::tanh(v / g.sign_velocity_scale) + c0 * v;
  double i = 0.0;
  for (int k = 0; k < 20; ++k) i = law.command({.demand = {F, v}}, observer);
  EXPECT_NEAR(i, I, 5e-3);
  // Pushing with the motion: the least force, no current.
  for (int k = 0; k < 20; ++k) i = law.command({.demand = {-F, v}}, observer);
  EXPECT_NEAR(i, 0.0, 1e-12);
}

TEST(ReachableForce, ProjectsOntoTheDampersRange) {
  const DamperModel m;
  const double tau_min = 146.0, tau_max = 40e3;
  const auto inside = mrd::tools::reachable_force(m, tau_min, tau_max, 20e3, 0.05);
  EXPECT_TRUE(inside.reachable);
  EXPECT_NEAR(inside.force, 20e3, 1e-6);
  const auto against = mrd::tools::reachable_force(m, tau_min, tau_max, -20e3, 0.05);
  EXPECT_FALSE(against.reachable);
  EXPECT_GT(against.force, 0.0);  // the least force still resists the motion
  const auto above = mrd::tools::reachable_force(m, tau_min, tau_max, 1e6, 0.05);
  EXPECT_FALSE(above.reachable);
  EXPECT_LT(above.force, 1e6);
}

}  // namespace force_strategies_test
}  // namespace
