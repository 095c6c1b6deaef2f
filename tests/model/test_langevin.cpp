#include "model/langevin.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using mrd::model::langevin;

// Reference in long double, far from the cancellation region.
long double reference_value(long double x) { return 1.0L / std::tanh(x) - 1.0L / x; }
long double reference_derivative(long double x) {
  const long double s = std::sinh(x);
  return 1.0L / (x * x) - 1.0L / (s * s);
}

TEST(Langevin, ZeroIsZeroWithSlopeOneThird) {
  EXPECT_EQ(langevin(0.0).value, 0.0);
  EXPECT_DOUBLE_EQ(langevin(0.0).derivative, 1.0 / 3.0);
}

TEST(Langevin, SeriesAndClosedFormAgreeAcrossTheSwitch) {
  for (const double x : {0.0499, 0.05, 0.0501, 0.1, 0.5, 1.0, 3.0}) {
    EXPECT_NEAR(langevin(x).value, static_cast<double>(reference_value(x)), 5e-14) << x;
    EXPECT_NEAR(langevin(x).derivative, static_cast<double>(reference_derivative(x)), 1e-12) << x;
  }
}

TEST(Langevin, IsOddWithEvenDerivative) {
  for (const double x : {1e-6, 0.01, 0.3, 2.0, 40.0}) {
    EXPECT_EQ(langevin(-x).value, -langevin(x).value);
    EXPECT_EQ(langevin(-x).derivative, langevin(x).derivative);
  }
}

TEST(Langevin, StaysFiniteAndBoundedForHugeArguments) {
  for (const double x : {30.0, 1e3, 1e8, 1e300}) {
    const auto L = langevin(x);
    ASSERT_TRUE(std::isfinite(L.value)) << x;
    ASSERT_TRUE(std::isfinite(L.derivative)) << x;
    EXPECT_LE(L.value, 1.0);
    EXPECT_NEAR(L.value, 1.0 - 1.0 / x, 1e-12);
    EXPECT_GE(L.derivative, 0.0);
  }
}

TEST(Langevin, IsMonotoneWithDerivativeBelowOneThird) {
  double previous = -1.0;
  for (double x = -50.0; x <= 50.0; x += 0.001) {
    const auto L = langevin(x);
    EXPECT_GT(L.value, previous);
    EXPECT_LE(L.derivative, 1.0 / 3.0 + 1e-15);
    previous = L.value;
  }
}

}  // namespace
