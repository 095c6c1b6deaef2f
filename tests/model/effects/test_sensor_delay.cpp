// SensorDelay: the plant's delay line and the observer's prediction across the delay.
#include "model/effects/sensor_delay.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace {

using mrd::model::predict_motion;
using mrd::model::SensorDelay;
using mrd::model::SensorDelayParams;

TEST(SensorDelay, WholePeriodsAreExact) {
  const double T = 1e-3;
  SensorDelay delay({true, 5e-3}, T);
  EXPECT_EQ(delay.delay_in_periods(), 5.0);
  for (int k = 0; k < 100; ++k) {
    const double x = std::sin(0.37 * k) + 0.01 * k;
    const double out = delay.step(x);
    const int j = std::max(k - 5, 0);  // before the line filled: the first value
    EXPECT_EQ(out, std::sin(0.37 * j) + 0.01 * j) << k;
  }
}

TEST(SensorDelay, FractionalDelayInterpolatesARampExactly) {
  const double T = 1e-3;
  SensorDelay delay({true, 2.5e-3}, T);  // 2.5 periods
  for (int k = 0; k < 50; ++k) {
    const double out = delay.step(3.0 * k * T);
    if (k >= 3) EXPECT_NEAR(out, 3.0 * (k * T - 2.5e-3), 1e-15) << k;
  }
}

TEST(SensorDelay, FractionalDelayOfASineIsWithinTheInterpolationError) {
  const double T = 1e-3;
  const double d = 3.3e-3;
  const double w = 2.0 * std::numbers::pi * 5.0;  // 5 Hz, 200 samples per cycle
  SensorDelay delay({true, d}, T);
  double max_error = 0.0;
  for (int k = 0; k < 1000; ++k) {
    const double out = delay.step(std::sin(w * k * T));
    if (k > 10) max_error = std::max(max_error, std::fabs(out - std::sin(w * (k * T - d))));
  }
  EXPECT_LT(max_error, w * w * T * T / 8.0 + 1e-12);  // linear interpolation bound
}

TEST(SensorDelay, ZeroDelayIsTheInput) {
  SensorDelay delay({true, 0.0}, 1e-3);
  EXPECT_EQ(delay.step(1.5), 1.5);
  EXPECT_EQ(delay.step(-2.5), -2.5);
}

TEST(SensorDelay, PredictionIsExactForConstantAcceleration) {
  // x(t) = 1 + 2 t + 3 t^2 measured d late.
  const double d = 4e-3;
  const double t = 0.7;
  const double tm = t - d;
  const auto now =
      predict_motion({.displacement = 1 + 2 * tm + 3 * tm * tm, .velocity = 2 + 6 * tm}, {.delay = d, .acceleration = 6.0});
  EXPECT_NEAR(now.displacement, 1 + 2 * t + 3 * t * t, 1e-14);
  EXPECT_NEAR(now.velocity, 2 + 6 * t, 1e-14);
}

TEST(SensorDelay, ValidateBoundsTheDelay) {
  EXPECT_TRUE(validate(SensorDelayParams{true, mrd::model::kMaxSensorDelay}).ok());
  EXPECT_FALSE(validate(SensorDelayParams{true, -1e-3}).ok());
  EXPECT_FALSE(validate(SensorDelayParams{true, 1.0}).ok());
}

}  // namespace
