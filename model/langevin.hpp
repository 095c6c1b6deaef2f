#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>

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

// The same function from a table of polynomials, for the real-time path: no exp and no
// division on |x| < kLangevinTableLimit. |x| is cut into intervals of width kLangevinTableStep
// centred on its multiples; on each, L and L' are degree-7 Chebyshev interpolants of the exact
// function (computed at compile time in long double, model/langevin_table.cpp), stored as
// monomials in t = |x| - centre. Max abs error: below 1e-13 in L and 2e-13 in L' (test
// LangevinTabulated.ErrorAgainstALongDoubleReferenceIsBounded, docs/MODEL.md). Beyond the table
// exp(-2|x|) < 4e-18, so L = sign(x) - 1/x and L' = 1/x^2 are exact in double.
struct LangevinTable {
  static constexpr int kCoefficients = 8;  // degree 7
  // Elements 2k and 2k + 1 are the coefficients of t^k in L and in L': as pairs, one packed
  // multiply and add evaluate both polynomials. Two cache lines per interval.
  struct alignas(64) Interval {
    std::array<double, 2 * kCoefficients> coefficients;
  };
  std::array<Interval, 81> intervals;  // centres 0, 0.25, ..., 20
};
inline constexpr double kLangevinTableStep = 0.25;
inline constexpr double kLangevinTableLimit = 20.125;  // the last interval's upper edge
extern const LangevinTable kLangevinTable;

namespace detail {

// The polynomials of `interval` at t = |x| - centre, |t| <= step/2, with the sign of x.
// L and L' side by side in an Eigen::Array2d (packed SIMD), by Estrin's scheme: three levels
// of multiply-add instead of Horner's chain of seven.
inline LangevinValue evaluate(const LangevinTable::Interval& interval, double t, double x) {
  using Pair = Eigen::Array2d;
  const auto c = [&interval](int k) {
    return Eigen::Map<const Pair, Eigen::Aligned16>(interval.coefficients.data() + 2 * k);
  };
  const double t2 = t * t;
  const double t4 = t2 * t2;
  const Pair p = ((c(0) + c(1) * t) + (c(2) + c(3) * t) * t2) +
                 ((c(4) + c(5) * t) + (c(6) + c(7) * t) * t2) * t4;
  return {std::copysign(p[0], x), p[1]};
}

inline LangevinValue asymptotic(double x) {  // |x| >= kLangevinTableLimit, or NaN
  const double inv_x = 1.0 / std::fabs(x);
  return {std::copysign(1.0 - inv_x, x), inv_x * inv_x};
}

// Index of the interval whose centre is nearest to ax, for 0 <= ax < kLangevinTableLimit.
// Adding 1.5 * 2^50 leaves a double whose last place is 2^-2 = kLangevinTableStep: the sum is ax
// rounded to the nearest centre, and its low mantissa bits count the steps. Both the index and
// t = ax - centre are exact, and it is shorter than a float-to-int conversion.
struct NearestInterval {
  std::size_t index;
  double centre;
};
inline NearestInterval nearest_interval(double ax) {
  constexpr double kRounder = 0x1.8p50;
  static_assert(kLangevinTableStep == 0x1p-2, "kRounder places the last bit at the step");
  const double rounded = ax + kRounder;
  // The min only matters if someone switched the FPU from rounding to nearest: the index then
  // still lands inside the table.
  const auto index = static_cast<std::size_t>(std::bit_cast<std::uint64_t>(rounded) & 0x7f);
  return {std::min(index, kLangevinTable.intervals.size() - 1), rounded - kRounder};
}

}  // namespace detail

inline LangevinValue langevin_tabulated(double x) {
  const double ax = std::fabs(x);
  if (!(ax < kLangevinTableLimit)) return detail::asymptotic(x);
  const auto [index, centre] = detail::nearest_interval(ax);
  return detail::evaluate(kLangevinTable.intervals[index], ax - centre, x);
}

// langevin_tabulated() for a caller whose x moves in small steps, such as the stages of one J-A
// integration: it first tries the interval of its previous call. The serial chain from x to L
// then holds one subtraction instead of the index arithmetic and the table load (about 15
// cycles); whether x is still inside is a well-predicted branch beside the chain, and a miss
// looks the interval up. Results are bit-identical to langevin_tabulated(): |t| < step/2
// means the remembered interval is the nearest one.
class LangevinTableCursor {
 public:
  LangevinValue operator()(double x) {
    const double ax = std::fabs(x);
    double t = ax - centre_;
    if (!(std::fabs(t) < 0.5 * kLangevinTableStep)) [[unlikely]] {
      if (!(ax < kLangevinTableLimit)) return detail::asymptotic(x);
      const auto [index, centre] = detail::nearest_interval(ax);
      interval_ = &kLangevinTable.intervals[index];
      centre_ = centre;
      t = ax - centre;
    }
    return detail::evaluate(*interval_, t, x);
  }

 private:
  const LangevinTable::Interval* interval_ = &kLangevinTable.intervals[0];
  double centre_ = 0.0;
};

}  // namespace mrd::model
