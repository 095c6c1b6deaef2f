// StrokeEndAir: the force collapse after reversals near the stroke ends (Section 4.3).
#include "model/effects/stroke_end_air.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

namespace {

using mrd::model::StrokeEndAir;
using mrd::model::StrokeEndAirParams;

StrokeEndAirParams stroke_end_on() {
  StrokeEndAirParams p;
  p.enabled = true;
  return p;  // threshold 30 mm, depth 0.9, length 5 mm
}

double sine(double amplitude, int k) { return amplitude * std::sin(2.0 * std::numbers::pi * 0.5 * k * 1e-3); }

TEST(StrokeEndAir, CollapsesAfterReversalsBeyondTheThresholdOnly) {
  StrokeEndAir air(stroke_end_on());
  double min_factor = 1.0;
  for (int k = 0; k < 4000; ++k) min_factor = std::min(min_factor, air.step(sine(0.040, k)));
  EXPECT_LT(min_factor, 0.12);  // just after the +-40 mm reversals

  StrokeEndAir inside(stroke_end_on());
  for (int k = 0; k < 4000; ++k) EXPECT_EQ(inside.step(sine(0.025, k)), 1.0) << k;
}

TEST(StrokeEndAir, RecoversWithTheTravelSinceTheReversal) {
  const auto p = stroke_end_on();
  StrokeEndAir air(p);
  // Up to +40 mm, then down in 0.1 mm steps.
  for (double x = 0.0; x <= 0.040 + 1e-12; x += 1e-4) air.step(x);
  for (double x = 0.040 - 1e-4; x > 0.0; x -= 1e-4) {
    const double f = air.step(x);
    const double s = 0.040 - x;
    if (s > p.reversal_travel + 1e-9) {
      EXPECT_TRUE(air.armed());
      EXPECT_NEAR(f, 1.0 - p.depth * std::exp(-s / p.length), 1e-9) << x;
    }
  }
  // The next reversal, at 0 mm, is inside the threshold: no collapse.
  air.step(1e-3);
  EXPECT_FALSE(air.armed());
  EXPECT_EQ(air.factor(), 1.0);
}

TEST(StrokeEndAir, LvdtNoiseDoesNotFakeReversalsMidStroke) {
  StrokeEndAir air(stroke_end_on());
  std::mt19937_64 rng(3);
  std::normal_distribution<double> noise(0.0, 5e-6);
  double smallest = 1.0;
  for (int k = 0; k < 6000; ++k) smallest = std::min(smallest, air.step(sine(0.040, k) + noise(rng)));
  EXPECT_EQ(air.reversals(), 6);  // +40, -40, ... mm: six in 6 s, none made up by the noise
  EXPECT_LT(smallest, 0.15);
}

TEST(StrokeEndAir, ValidateNamesTheBadField) {
  EXPECT_TRUE(validate(stroke_end_on()).ok());
  auto p = stroke_end_on();
  p.depth = 1.2;
  const auto report = validate(p);
  ASSERT_FALSE(report.ok());
  EXPECT_EQ(report.issues().front().field, "depth");
}

// The free recovery shape: no recovery over the dead travel, then a linear ramp that is whole
// `length` later (ramp share 1), or halfway between ramp and exponential (0.5).
TEST(StrokeEndAir, DeadTravelThenARampOrABlend) {
  for (const double share : {1.0, 0.5}) {
    auto p = stroke_end_on();
    p.dead_travel = 3e-3;
    p.ramp_share = share;
    StrokeEndAir air(p);
    for (double x = 0.0; x <= 0.040 + 1e-12; x += 1e-4) air.step(x);
    for (double x = 0.040 - 1e-4; x > 0.020; x -= 1e-4) {
      const double f = air.step(x);
      const double s = 0.040 - x;
      if (s < 2e-4) continue;  // before the reversal is confirmed
      const double u = std::max(s - 3e-3, 0.0) / 5e-3;
      const double shape = share * std::max(1.0 - u, 0.0) + (1.0 - share) * std::exp(-u);
      ASSERT_NEAR(f, 1.0 - 0.9 * shape, 1e-9) << "share " << share << " at s = " << s;
      if (s < 3e-3) ASSERT_NEAR(f, 0.1, 1e-9);
      if (share == 1.0 && s > 8.1e-3) ASSERT_EQ(f, 1.0);
    }
  }
}

}  // namespace
