#pragma once

#include <cmath>

namespace mrd::model {

// Langevin function L(x) = coth(x) - 1/x and its derivative, the shape of Eq. 3.
// Near x = 0 both forms cancel catastrophically, so a Taylor series takes over below
// kSeriesLimit (truncation error < 1e-16 there). For large |x| one exp(-2|x|) underflows
// to 0 and the closed forms reduce to sign(x) - 1/x and 1/x^2, which stay finite.
struct LangevinValue {
  double value;       // L(x)
  double derivative;  // dL/dx
};

inline LangevinValue langevin(double x) {
  constexpr double kSeriesLimit = 0.05;
  const double ax = std::fabs(x);
  if (ax < kSeriesLimit) {
    const double x2 = x * x;
    // L(x) = x/3 - x^3/45 + 2x^5/945 - x^7/4725; L'(x) = 1/3 - x^2/15 + 2x^4/189 - x^6/675
    return {x * (1.0 / 3.0 + x2 * (-1.0 / 45.0 + x2 * (2.0 / 945.0 - x2 / 4725.0))),
            1.0 / 3.0 + x2 * (-1.0 / 15.0 + x2 * (2.0 / 189.0 - x2 / 675.0))};
  }
  // One exponential serves both: coth|x| = (1+t)/(1-t), 1/sinh^2|x| = 4t/(1-t)^2, t = e^{-2|x|}.
  // One division serves 1/|x| and 1/(1-t), the hot path's costliest operations after exp.
  const double t = std::exp(-2.0 * ax);
  const double one_minus_t = 1.0 - t;
  const double inv_product = 1.0 / (ax * one_minus_t);
  const double inv_x = one_minus_t * inv_product;
  const double inv_one_minus_t = ax * inv_product;
  const double value = (1.0 + t) * inv_one_minus_t - inv_x;
  const double derivative = inv_x * inv_x - 4.0 * t * inv_one_minus_t * inv_one_minus_t;
  return {x < 0.0 ? -value : value, derivative};
}

}  // namespace mrd::model
