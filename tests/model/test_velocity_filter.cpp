#include "model/velocity_filter.hpp"

#include "model/observer.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

namespace {

using mrd::model::VelocityFilter;

TEST(VelocityFilter, TracksARampWithoutLag) {
  VelocityFilter f(1e-3, 20.0);
  double v = 0.0;
  for (int i = 0; i < 2000; ++i) v = f.update(0.05 * i * 1e-3);
  EXPECT_NEAR(v, 0.05, 1e-9);
}

// A bus polled on its own clock delivers samples 0.6 or 1.2 ms apart to a 1 ms loop.
TEST(VelocityFilter, TracksARampSampledAtUnevenIntervalsAtTheirOwnIntervals) {
  VelocityFilter own(1e-3, 20.0), fixed(1e-3, 20.0);
  double t = 0.0, v_own = 0.0, v_fixed = 0.0, fixed_lo = 1.0, fixed_hi = -1.0;
  for (int i = 0; i < 3000; ++i) {
    const double interval = i % 2 == 0 ? 0.6e-3 : 1.2e-3;
    t += interval;
    v_own = own.update(0.05 * t, interval);
    v_fixed = fixed.update(0.05 * t);
    if (i > 2000) {
      fixed_lo = std::min(fixed_lo, v_fixed);
      fixed_hi = std::max(fixed_hi, v_fixed);
    }
  }
  EXPECT_NEAR(v_own, 0.05, 1e-9);
  EXPECT_NEAR(own.velocity_after(0.5e-3), 0.05, 1e-9);  // no acceleration on a ramp
  // The loop period's gains take the 0.9 ms mean interval for 1 ms: 10 % slow, and wavering.
  EXPECT_NEAR(0.5 * (fixed_lo + fixed_hi), 0.045, 0.001);
  EXPECT_GT(fixed_hi - fixed_lo, 1e-4);
}

TEST(VelocityFilter, CarriesTheVelocityForwardAtTheTrackedAcceleration) {
  VelocityFilter f(1e-3, 20.0);
  for (int i = 0; i < 3000; ++i) {
    const double t = i * 1e-3;
    f.update(0.5 * 2.0 * t * t);  // 2 m/s^2 from rest
  }
  EXPECT_NEAR(f.acceleration(), 2.0, 1e-6);
  EXPECT_NEAR(f.velocity_after(1e-3) - f.velocity(), 2e-3, 1e-8);
}

TEST(VelocityFilter, IgnoresANonPositiveIntervalOnceItIsPrimed) {
  VelocityFilter f(1e-3, 20.0);
  f.update(0.0, 0.0);  // a first sample primes the tracker whatever its interval
  const double v = f.update(1e-4, 1e-3);
  EXPECT_GT(v, 0.0);
  EXPECT_EQ(f.update(5.0, 0.0), v);
  EXPECT_EQ(f.update(5.0, -1e-3), v);
}

// The observer on bus samples: each new sample tracked at its interval, the velocity carried
// to the step by the sample's age at the tracked acceleration, never more than two periods.
TEST(ObserverSampleTiming, CarriesTheVelocityByTheSampleAgeUpToTwoPeriods) {
  const double T = 1e-3, a = 2.0;
  mrd::model::Observer o(mrd::model::DamperModel{}, {T, 20.0});
  // The step's velocity on a sample held from an earlier period, `age` old.
  const auto held = [&o](double x, double age) {
    return o.step({.displacement = x, .timing = mrd::model::SampleTiming{.fresh = false, .age = age}}).velocity;
  };
  EXPECT_EQ(held(0.0, 1e6), 0.0);  // no sample yet: nothing to carry
  double x = 0.0;
  for (int i = 0; i < 3000; ++i) {
    const double t = i * T;
    x = 0.5 * a * t * t;
    o.step({.displacement = x, .timing = mrd::model::SampleTiming{.fresh = true, .interval = T, .age = 0.0}});
  }
  const double tracked = o.estimate().velocity;
  EXPECT_NEAR(tracked, a * 2999 * T, 1e-6);
  EXPECT_NEAR(held(x, 0.5 * T), tracked + a * 0.5 * T, 1e-6);
  EXPECT_NEAR(held(x, 10.0 * T), tracked + a * 2.0 * T, 1e-6);
  EXPECT_NEAR(held(x, -T), tracked, 1e-6);  // stamped after the step
}

TEST(VelocityFilter, TracksThePapersSineWithSmallErrorUnderLvdtNoise) {
  const double A = 0.04, w = 2.0 * std::numbers::pi * 0.5, T = 1e-3;
  VelocityFilter f(T, 20.0);
  std::mt19937 rng(3);
  std::normal_distribution<double> noise(0.0, 5e-6);
  double sum_sq = 0.0;
  int n = 0;
  for (int i = 0; i < 6000; ++i) {
    const double t = i * T;
    const double v = f.update(A * std::sin(w * t) + noise(rng));
    if (t > 2.0) {
      sum_sq += std::pow(v - A * w * std::cos(w * t), 2);
      ++n;
    }
  }
  EXPECT_LT(std::sqrt(sum_sq / n), 1e-3);  // < 1 mm/s RMS against 126 mm/s peak
}

}  // namespace
