// CoilLag: the first-order lag of the coil current behind the command.
#include "model/effects/coil_lag.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace {

using mrd::model::CoilLag;
using mrd::model::CoilLagParams;

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

TEST(CoilLag, ValidateRejectsNegativeTimeConstants) {
  EXPECT_TRUE(validate(CoilLagParams{}).ok());
  const auto report = validate(CoilLagParams{true, -1e-3});
  ASSERT_FALSE(report.ok());
  EXPECT_EQ(report.issues().front().field, "time_constant");
}

}  // namespace
