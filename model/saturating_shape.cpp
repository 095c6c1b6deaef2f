#include "model/saturating_shape.hpp"

#include <cmath>
#include <limits>
#include <numbers>

namespace mrd::model {

double saturating_shape(double x, double q) {
  const double smooth = std::tanh(x);
  if (q == 0.0) return smooth;
  if (q < 0.0) {
    // atan scaled to slope 1 at 0: its tail approaches 1 as 1/x, far slower than tanh's.
    const double slow = (2.0 / std::numbers::pi) * std::atan(0.5 * std::numbers::pi * x);
    return smooth + (-q) * (slow - smooth);
  }
  // Linear, then flat within |x| ~ 1; written in 1/x beyond 1 so that x^8 cannot overflow.
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
  if (q == 1.0) {
    const double y2 = y * y, y4 = y2 * y2;
    return y / std::pow(1.0 - y4 * y4, 0.125);
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
