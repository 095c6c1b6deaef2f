#include "model/saturating_shape.hpp"

#include <cmath>
#include <limits>
#include <numbers>

namespace mrd::model {

namespace {

// The knee's order m(q) past q = 1: 8 at q = 1, 128 at q = 2 (within 0.6 % of the corner min(x, 1)).
double knee_order(double q) { return 8.0 * std::exp2(4.0 * (q - 1.0)); }

// x / (1 + |x|^m)^(1/m), written in 1/x beyond 1 so that |x|^m cannot overflow.
double knee_of_order(double x, double m) {
  if (std::fabs(x) <= 1.0) return x / std::pow(1.0 + std::pow(std::fabs(x), m), 1.0 / m);
  return std::copysign(1.0 / std::pow(1.0 + std::pow(1.0 / std::fabs(x), m), 1.0 / m), x);
}

}  // namespace

double saturating_shape(double x, double q) {
  if (q > 1.0) return knee_of_order(x, knee_order(q));
  const double smooth = std::tanh(x);
  if (q == 0.0) return smooth;
  if (q < 0.0) {
    // atan scaled to slope 1 at 0: its tail approaches 1 as 1/x, far slower than tanh's.
    const double slow = (2.0 / std::numbers::pi) * std::atan(0.5 * std::numbers::pi * x);
    return smooth + (-q) * (slow - smooth);
  }
  // Order 8 by multiplications: the sign shape runs in the 10 kHz loop.
  double knee;
  if (std::fabs(x) <= 1.0) {
    const double x2 = x * x, x4 = x2 * x2;
    knee = x / std::pow(1.0 + x4 * x4, 0.125);
  } else {
    const double r = 1.0 / x, r2 = r * r, r4 = r2 * r2;
    knee = std::copysign(1.0 / std::pow(1.0 + r4 * r4, 0.125), x);
  }
  return smooth + q * (knee - smooth);
}

double saturating_shape_inverse(double y, double q) {
  if (!(y < 1.0)) return std::numeric_limits<double>::infinity();
  if (!(y > 0.0)) return 0.0;
  if (q == 0.0) return std::atanh(y);
  if (q == -1.0) return (2.0 / std::numbers::pi) * std::tan(0.5 * std::numbers::pi * y);
  if (q >= 1.0) {
    // y^m (1 + x^m) = x^m; 1 - y^m by expm1, which keeps its digits where y^m is near 1.
    const double m = knee_order(q);
    return y / std::pow(-std::expm1(m * std::log(y)), 1.0 / m);
  }
  // Every member lies at or below x (slope 1 at 0, concave for x > 0), so x >= y; double the
  // upper end until it holds the answer.
  double lo = y, hi = 2.0 * y + 1.0;
  for (int i = 0; i < 100 && saturating_shape(hi, q) < y; ++i) hi *= 2.0;
  for (int i = 0; i < 64 && hi - lo > 1e-15 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (saturating_shape(mid, q) < y ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace mrd::model
