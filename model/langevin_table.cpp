// The table behind langevin_tabulated(), computed by the compiler: Chebyshev interpolation of
// the exact L and L' in long double, converted to monomials in t = |x| - centre and rounded to
// double. constinit makes a table that cannot be computed at compile time a build error, so no
// start-up code runs and nothing depends on static initialisation order.
#include "model/langevin.hpp"

namespace mrd::model {
namespace {

using Real = long double;
constexpr int kNodes = LangevinTable::kCoefficients;
constexpr Real kPi = 3.141592653589793238462643383279502884L;
constexpr Real kLn2 = 0.693147180559945309417232121458176568L;

// e^-y for 0 <= y <= 41: y = n ln2 + r with r in [0, ln2), Taylor series for e^-r, then 2^-n.
constexpr Real exp_neg(Real y) {
  int n = 0;
  while (y >= kLn2 * (n + 1)) ++n;
  const Real r = y - kLn2 * n;
  Real term = 1.0L;
  Real sum = 1.0L;
  for (int k = 1; k < 30; ++k) {
    term *= -r / k;
    sum += term;
  }
  for (int i = 0; i < n; ++i) sum *= 0.5L;
  return sum;
}

// cos(x) for |x| <= pi by its Taylor series.
constexpr Real cosine(Real x) {
  Real term = 1.0L;
  Real sum = 1.0L;
  for (int k = 1; k < 30; ++k) {
    term *= -x * x / ((2 * k - 1) * (2 * k));
    sum += term;
  }
  return sum;
}

// L(x) for x >= 0. Below 1/2 by Lambert's continued fraction L(x) = x/(3 + x^2/(5 + x^2/(7 + ...))),
// which has no cancellation near 0; above it coth(x) - 1/x with t = e^-2x.
constexpr Real exact_value(Real x) {
  if (x < 0.5L) {
    Real tail = 0.0L;
    for (int k = 40; k >= 2; --k) tail = x * x / (2 * k + 1 + tail);  // x^2/(5 + x^2/(7 + ...))
    return x / (3.0L + tail);
  }
  const Real t = exp_neg(2.0L * x);
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
  const Real t = exp_neg(2.0L * x);
  return 1.0L / (x * x) - 4.0L * t / ((1.0L - t) * (1.0L - t));
}

// Monomial coefficients, in t in [-half, half], of the polynomial interpolating f at the
// Chebyshev nodes of [centre - half, centre + half].
template <typename F>
constexpr std::array<double, kNodes> chebyshev_fit(F f, Real centre, Real half) {
  std::array<Real, kNodes> u{};
  std::array<Real, kNodes> fu{};
  for (int k = 0; k < kNodes; ++k) {
    u[k] = cosine(kPi * (k + 0.5L) / kNodes);
    fu[k] = f(centre + half * u[k]);
  }
  // Chebyshev coefficients c_j = (2 - [j = 0]) / n * sum_k f(u_k) T_j(u_k).
  std::array<Real, kNodes> cheb{};
  for (int j = 0; j < kNodes; ++j) {
    Real sum = 0.0L;
    for (int k = 0; k < kNodes; ++k) {
      Real t_prev = 1.0L;
      Real t_j = j == 0 ? 1.0L : u[k];
      for (int m = 2; m <= j; ++m) {
        const Real next = 2.0L * u[k] * t_j - t_prev;
        t_prev = t_j;
        t_j = next;
      }
      sum += fu[k] * t_j;
    }
    cheb[j] = (j == 0 ? 1.0L : 2.0L) * sum / kNodes;
  }
  // sum c_j T_j(u) as monomials in u, with T_{j+1} = 2u T_j - T_{j-1}.
  std::array<Real, kNodes> mono{};
  std::array<Real, kNodes> t_prev{};  // T_0 = 1
  std::array<Real, kNodes> t_cur{};   // T_1 = u
  t_prev[0] = 1.0L;
  t_cur[1] = 1.0L;
  for (int k = 0; k < kNodes; ++k) mono[k] = cheb[0] * t_prev[k] + cheb[1] * t_cur[k];
  for (int j = 2; j < kNodes; ++j) {
    std::array<Real, kNodes> t_next{};
    for (int k = 0; k < kNodes; ++k) {
      t_next[k] = (k > 0 ? 2.0L * t_cur[k - 1] : 0.0L) - t_prev[k];
      mono[k] += cheb[j] * t_next[k];
    }
    t_prev = t_cur;
    t_cur = t_next;
  }
  // u = t / half.
  std::array<double, kNodes> coefficients{};
  Real scale = 1.0L;
  for (int k = 0; k < kNodes; ++k) {
    coefficients[k] = static_cast<double>(mono[k] / scale);
    scale *= half;
  }
  return coefficients;
}

constexpr LangevinTable make_table() {
  LangevinTable table{};
  const Real half = 0.5L * kLangevinTableStep;
  for (std::size_t i = 0; i < table.intervals.size(); ++i) {
    const Real centre = static_cast<Real>(i) * kLangevinTableStep;
    // The first interval straddles 0, so L is fitted as the odd function and L' as the even one.
    const auto value = chebyshev_fit(
        [](Real x) { return x < 0.0L ? -exact_value(-x) : exact_value(x); }, centre, half);
    const auto derivative = chebyshev_fit(
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
