#include "model/velocity_filter.hpp"

#include <gtest/gtest.h>

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
