// The table behind langevin_tabulated(), computed by the compiler: Chebyshev interpolation of
// the exact L and L' in long double, converted to monomials in t = |x| - centre and rounded to
// double. constinit makes a table that cannot be computed at compile time a build error, so no
// start-up code runs and nothing depends on static initialisation order.
#include "model/compile_time_fit.hpp"
#include "model/langevin.hpp"

namespace mrd::model {
namespace {

using compile_time::Real;
constexpr int kNodes = LangevinTable::kCoefficients;

// L(x) for x >= 0. Below 1/2 by Lambert's continued fraction L(x) = x/(3 + x^2/(5 + ...)),
// which has no cancellation near 0; above it coth(x) - 1/x with t = e^-2x.
constexpr Real exact_value(Real x) {
  if (x < 0.5L) {
    Real tail = 0.0L;
    for (int k = 40; k >= 2; --k) tail = x * x / (2 * k + 1 + tail);  // x^2/(5 + x^2/(7 + ...))
    return x / (3.0L + tail);
  }
  const Real t = compile_time::exp(-2.0L * x);
  return (1.0L + t) / (1.0L - t) - 1.0L / x;
}

// L'(x) for x >= 0. Below 1/2 from L' = 1 - L^2 - 2L/x (coth' = 1 - coth^2), above it
// 1/x^2 - 1/sinh^2 x.
constexpr Real exact_derivative(Real x) {
  if (x == 0.0L) return 1.0L / 3.0L;
  if (x < 0.5L) {
    const Real L = exact_value(x);
    return 1.0L - L * L - 2.0L * L / x;
  }
  const Real t = compile_time::exp(-2.0L * x);
  return 1.0L / (x * x) - 4.0L * t / ((1.0L - t) * (1.0L - t));
}

constexpr LangevinTable make_table() {
  LangevinTable table{};
  const Real half = 0.5L * kLangevinTableStep;
  for (std::size_t i = 0; i < table.intervals.size(); ++i) {
    const Real centre = static_cast<Real>(i) * kLangevinTableStep;
    // The first interval straddles 0, so L is fitted as the odd function and L' as the even one.
    const auto value = compile_time::chebyshev_fit<kNodes>(
        [](Real x) { return x < 0.0L ? -exact_value(-x) : exact_value(x); }, centre, half);
    const auto derivative = compile_time::chebyshev_fit<kNodes>(
        [](Real x) { return exact_derivative(x < 0.0L ? -x : x); }, centre, half);
    // There the even terms of L and the odd terms of L' vanish in exact arithmetic; they are
    // made exactly 0, so that L(0) = 0.
    const bool at_origin = i == 0;
    for (int k = 0; k < kNodes; ++k) {
      table.intervals[i].coefficients[2 * k] = at_origin && k % 2 == 0 ? 0.0 : value[k];
      table.intervals[i].coefficients[2 * k + 1] = at_origin && k % 2 == 1 ? 0.0 : derivative[k];
    }
  }
  return table;
}

}  // namespace

constinit const LangevinTable kLangevinTable = make_table();

}  // namespace mrd::model
