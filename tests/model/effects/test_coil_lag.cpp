// CoilLag: the first-order lag of the coil current behind the command.
#include "model/effects/coil_lag.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace {

using mrd::model::CoilLag;
using mrd::model::CoilLagParams;
using mrd::model::CurrentRange;

TEST(CoilLag, StepResponseFollowsTheTimeConstantExactly) {
  const double T = 1e-3;
  const double tau = 1.0 / 190.0;  // Spencer's eta for Dyke's damper
  CoilLag lag({true, tau}, T);
  for (int k = 1; k <= 100; ++k) {
    const double i = lag.step(1.0);
    EXPECT_NEAR(i, 1.0 - std::exp(-k * T / tau), 1e-14) << k;
  }
}

TEST(CoilLag, ReachesSixtyThreePercentAfterOneTimeConstant) {
  const double T = 1e-4;
  CoilLag lag({true, 5e-3}, T);
  double i = 0.0;
  for (int k = 0; k < 50; ++k) i = lag.step(2.0);  // 50 periods = tau
  EXPECT_NEAR(i / 2.0, 1.0 - std::exp(-1.0), 1e-12);
}

TEST(CoilLag, StableWhenThePeriodIsLongerThanTheTimeConstant) {
  CoilLag lag({true, 1e-4}, 1e-2);  // T = 100 tau: explicit Euler would diverge
  EXPECT_NEAR(lag.step(1.0), 1.0, 1e-12);
  EXPECT_NEAR(lag.step(-1.0), -1.0, 1e-12);
}

TEST(CoilLag, ZeroTimeConstantIsNoLagAndABadCommandHoldsTheCurrent) {
  CoilLag none({true, 0.0}, 1e-3);
  EXPECT_EQ(none.step(0.7), 0.7);
  CoilLag lag({true, 5e-3}, 1e-3);
  const double i = lag.step(1.0);
  EXPECT_EQ(lag.step(std::numeric_limits<double>::quiet_NaN()), i);
}

// The inverse: the command held over one period that lands the lagged current on the target.
// The forward step() is the reference: from any current it reaches each target in one period.
TEST(CoilLag, CommandForBringsTheLaggedCurrentToTheTargetInOnePeriod) {
  const double T = 1e-3;
  CoilLag lag({true, 20e-3}, T);
  const CurrentRange wide{-100.0, 100.0};
  for (const double target : {1.0, 1.0, 0.3, 0.0, 1.2, -0.4, 0.6}) {
    EXPECT_NEAR(lag.step(lag.command_for(target, T, wide)), target, 1e-13) << target;
  }
  // Over another dt the command differs, and held for that dt it lands there too.
  const double held = lag.command_for(0.9, 2.0 * T, wide);
  lag.step(held);
  EXPECT_NEAR(lag.step(held), 0.9, 1e-13);
  // By hand: T = tau, from 0 to 1 A is 1 / (1 - 1/e).
  CoilLag one_tau({true, 1e-3}, T);
  EXPECT_NEAR(one_tau.command_for(1.0, T, wide), 1.0 / (1.0 - std::exp(-1.0)), 1e-14);
  CoilLag none({true, 0.0}, T);
  EXPECT_EQ(none.command_for(0.7, T, wide), 0.7);
}

// Bounded by the driver, a step of 0 -> 1 A through tau = 20 ms at T = 1 ms commands the
// driver's 1.5 A until 1.5 (1 - exp(-k T / tau)) can reach 1 A, which takes
// k = ceil(tau ln 3 / T) = 22 periods; the last command lands on 1 A exactly and holds it.
TEST(CoilLag, CommandForIsBoundedByTheDriverAndReachesTheTargetWhenItCan) {
  const double T = 1e-3;
  const double tau = 20e-3;
  CoilLag lag({true, tau}, T);
  const CurrentRange driver{0.0, 1.5};
  int periods = 0;
  while (lag.current() < 1.0 - 1e-12 && periods < 100) {
    const double command = lag.command_for(1.0, T, driver);
    EXPECT_GE(command, 0.0);
    EXPECT_LE(command, 1.5);
    EXPECT_NEAR(lag.reachable(T, driver).highest, lag.current() + (1.5 - lag.current()) * -std::expm1(-T / tau),
                1e-15);
    lag.step(command);
    ++periods;
  }
  EXPECT_EQ(periods, static_cast<int>(std::ceil(tau * std::log(3.0) / T)));
  EXPECT_NEAR(lag.current(), 1.0, 1e-13);
  EXPECT_NEAR(lag.step(lag.command_for(1.0, T, driver)), 1.0, 1e-13);
  EXPECT_EQ(lag.command_for(std::nan(""), T, driver), lag.current());  // a bad target holds
}

TEST(CoilLag, ValidateRejectsNegativeTimeConstants) {
  EXPECT_TRUE(validate(CoilLagParams{}).ok());
  const auto report = validate(CoilLagParams{true, -1e-3});
  ASSERT_FALSE(report.ok());
  EXPECT_EQ(report.issues().front().field, "time_constant");
}

}  // namespace
