#include "model/langevin.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>

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

namespace {

using mrd::model::langevin_tabulated;

// An independent reference in long double: the Maclaurin series L(x) = sum 2^2n B_2n x^(2n-1)
// / (2n)! below |x| = 1/4 (terms shrink by (x/pi)^2 < 0.007; 11 terms reach 1e-24), and the
// closed forms above it, where cancellation costs at most two of the 19 digits.
// 2^2n B_2n / (2n)! for n = 1..11, from B_2 = 1/6, B_4 = -1/30, ..., B_22 = 854513/138.
constexpr long double kSeries[] = {
    1.0L / 3,          -1.0L / 45,          2.0L / 945,          -1.0L / 4725,
    2.0L / 93555,      -1382.0L / 638512875, 4.0L / 18243225,    -3617.0L / 162820783125,
    87734.0L / 38979295480125, -349222.0L / 1531329465290625,
    1310724.0L / 57210374837081625};

long double series_value(long double x) {
  long double sum = 0.0L;
  for (int n = 10; n >= 0; --n) sum = sum * x * x + kSeries[n];
  return x * sum;
}
long double series_derivative(long double x) {
  long double sum = 0.0L;
  for (int n = 10; n >= 0; --n) sum = sum * x * x + (2 * n + 1) * kSeries[n];
  return sum;
}
long double accurate_value(long double x) {
  return std::fabs(x) < 0.25L ? series_value(x) : reference_value(x);
}
long double accurate_derivative(long double x) {
  return std::fabs(x) < 0.25L ? series_derivative(x) : reference_derivative(x);
}

TEST(LangevinReference, SeriesAndClosedFormsAgreeAtTheirSwitch) {
  for (const long double x : {0.2L, 0.25L, 0.3L}) {
    EXPECT_NEAR(static_cast<double>(series_value(x) - reference_value(x)), 0.0, 1e-17);
    EXPECT_NEAR(static_cast<double>(series_derivative(x) - reference_derivative(x)), 0.0, 1e-16);
  }
}

// The bound quoted in model/langevin.hpp and docs/MODEL.md, over a grid 100 times finer than
// the table's intervals, across the table's end, and into the asymptotic region.
TEST(LangevinTabulated, ErrorAgainstALongDoubleReferenceIsBounded) {
  double max_value_error = 0.0;
  double max_derivative_error = 0.0;
  for (int i = -260000; i <= 260000; ++i) {
    const double x = i * (1.0 / 10000.0) + 1e-7;  // off the interval centres and edges
    const auto L = langevin_tabulated(x);
    max_value_error = std::max(
        max_value_error, static_cast<double>(std::fabs(L.value - accurate_value(x))));
    max_derivative_error = std::max(
        max_derivative_error,
        static_cast<double>(std::fabs(L.derivative - accurate_derivative(x))));
  }
  EXPECT_LT(max_value_error, 1e-13);
  EXPECT_LT(max_derivative_error, 2e-13);
  std::printf("tabulated Langevin on |x| <= 26: max |L - ref| = %.2g, max |L' - ref| = %.2g\n",
              max_value_error, max_derivative_error);
}

TEST(LangevinTabulated, IsExactlyOddWithZeroAtZero) {
  EXPECT_EQ(langevin_tabulated(0.0).value, 0.0);
  EXPECT_NEAR(langevin_tabulated(0.0).derivative, 1.0 / 3.0, 2e-13);
  for (const double x : {1e-9, 0.01, 0.124, 0.125, 0.3, 2.0, 19.99, 20.0, 40.0}) {
    EXPECT_EQ(langevin_tabulated(-x).value, -langevin_tabulated(x).value);
    EXPECT_EQ(langevin_tabulated(-x).derivative, langevin_tabulated(x).derivative);
  }
}

TEST(LangevinTabulated, IsMonotoneAndFiniteEverywhere) {
  double previous = -1.0;
  for (double x = -50.0; x <= 50.0; x += 0.001) {
    const auto L = langevin_tabulated(x);
    EXPECT_GT(L.value, previous) << x;
    EXPECT_GT(L.derivative, 0.0) << x;
    EXPECT_LE(L.derivative, 1.0 / 3.0 + 1e-15) << x;
    previous = L.value;
  }
  for (const double x : {1e3, 1e300, std::numeric_limits<double>::infinity()}) {
    const auto L = langevin_tabulated(x);
    EXPECT_TRUE(std::isfinite(L.value) && std::isfinite(L.derivative)) << x;
    EXPECT_LE(L.value, 1.0);
  }
  EXPECT_TRUE(std::isnan(langevin_tabulated(std::nan("")).value));
}

}  // namespace

namespace {

using mrd::model::LangevinTableCursor;

// The cursor only remembers where it was; every answer must be langevin_tabulated()'s, bit for
// bit, whether x creeps (the J-A stages), jumps, leaves the table or is not a number.
TEST(LangevinTableCursor, AnswersExactlyAsTheStatelessFunction) {
  LangevinTableCursor cursor;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> creep(-0.01, 0.01);
  std::uniform_real_distribution<double> jump(-30.0, 30.0);
  double x = 0.0;
  for (int i = 0; i < 200000; ++i) {
    x = (i % 1000 == 0) ? jump(rng) : x + creep(rng);
    const auto a = cursor(x);
    const auto b = langevin_tabulated(x);
    ASSERT_EQ(a.value, b.value) << x;
    ASSERT_EQ(a.derivative, b.derivative) << x;
  }
  for (const double special : {0.0, -0.0, 0.125, -0.125, 20.125, -20.125, 1e300,
                               std::numeric_limits<double>::infinity()}) {
    EXPECT_EQ(cursor(special).value, langevin_tabulated(special).value) << special;
    EXPECT_EQ(cursor(special).derivative, langevin_tabulated(special).derivative) << special;
  }
  EXPECT_TRUE(std::isnan(cursor(std::nan("")).value));
  EXPECT_EQ(cursor(0.3).value, langevin_tabulated(0.3).value);  // and it recovers
}

}  // namespace
