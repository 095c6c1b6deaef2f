#pragma once

// Compile-time tools for the real-time tables (model/langevin_table.cpp, model/mr_fluid.cpp):
// elementary functions in long double by their series, and Chebyshev interpolation. Everything
// is constexpr, so a table built with them is a constant of the binary: no start-up code.
#include <array>

namespace mrd::model::compile_time {

using Real = long double;
inline constexpr Real kPi = 3.141592653589793238462643383279502884L;
inline constexpr Real kLn2 = 0.693147180559945309417232121458176568L;

// e^y for |y| <= 1000: y = n ln2 + r with r in [0, ln2), Taylor series for e^r, then 2^n.
constexpr Real exp(Real y) {
  int n = static_cast<int>(y / kLn2);
  if (n * kLn2 > y) --n;
  const Real r = y - n * kLn2;
  Real term = 1.0L;
  Real sum = 1.0L;
  for (int k = 1; k < 30; ++k) {
    term *= r / k;
    sum += term;
  }
  for (; n > 0; --n) sum *= 2.0L;
  for (; n < 0; ++n) sum *= 0.5L;
  return sum;
}

// ln(x) for x > 0: x = 2^n f with f in [1, 2), ln f = 2 atanh((f - 1)/(f + 1)) by its series.
constexpr Real log(Real x) {
  int n = 0;
  for (; x >= 2.0L; ++n) x *= 0.5L;
  for (; x < 1.0L; --n) x *= 2.0L;
  const Real z = (x - 1.0L) / (x + 1.0L);  // <= 1/3
  Real power = z;
  Real sum = 0.0L;
  for (int k = 0; k < 40; ++k) {
    sum += power / (2 * k + 1);
    power *= z * z;
  }
  return n * kLn2 + 2.0L * sum;
}

// cos(x) for |x| <= pi by its Taylor series.
constexpr Real cos(Real x) {
  Real term = 1.0L;
  Real sum = 1.0L;
  for (int k = 1; k < 30; ++k) {
    term *= -x * x / ((2 * k - 1) * (2 * k));
    sum += term;
  }
  return sum;
}

// Monomial coefficients, in t = x - centre with |t| <= half, of the degree-(N - 1) polynomial
// that interpolates f at the Chebyshev nodes of [centre - half, centre + half], rounded to
// double. Interpolation at these nodes is within a factor of a few of the best polynomial.
template <int N, typename F>
constexpr std::array<double, N> chebyshev_fit(F f, Real centre, Real half) {
  std::array<Real, N> u{};
  std::array<Real, N> fu{};
  for (int k = 0; k < N; ++k) {
    u[k] = cos(kPi * (k + 0.5L) / N);
    fu[k] = f(centre + half * u[k]);
  }
  // Chebyshev coefficients c_j = (2 - [j = 0]) / N * sum_k f(u_k) T_j(u_k).
  std::array<Real, N> chebyshev{};
  for (int j = 0; j < N; ++j) {
    Real sum = 0.0L;
    for (int k = 0; k < N; ++k) {
      Real t_previous = 1.0L;
      Real t_j = j == 0 ? 1.0L : u[k];
      for (int m = 2; m <= j; ++m) {
        const Real next = 2.0L * u[k] * t_j - t_previous;
        t_previous = t_j;
        t_j = next;
      }
      sum += fu[k] * t_j;
    }
    chebyshev[j] = (j == 0 ? 1.0L : 2.0L) * sum / N;
  }
  // sum c_j T_j(u) as monomials in u, with T_{j+1} = 2u T_j - T_{j-1}.
  std::array<Real, N> monomial{};
  std::array<Real, N> t_previous{};  // T_0 = 1
  std::array<Real, N> t_current{};   // T_1 = u
  t_previous[0] = 1.0L;
  if constexpr (N > 1) t_current[1] = 1.0L;
  for (int k = 0; k < N; ++k) monomial[k] = chebyshev[0] * t_previous[k];
  if constexpr (N > 1) {
    for (int k = 0; k < N; ++k) monomial[k] += chebyshev[1] * t_current[k];
  }
  for (int j = 2; j < N; ++j) {
    std::array<Real, N> t_next{};
    for (int k = 0; k < N; ++k) {
      t_next[k] = (k > 0 ? 2.0L * t_current[k - 1] : 0.0L) - t_previous[k];
      monomial[k] += chebyshev[j] * t_next[k];
    }
    t_previous = t_current;
    t_current = t_next;
  }
  // u = t / half.
  std::array<double, N> coefficients{};
  Real scale = 1.0L;
  for (int k = 0; k < N; ++k) {
    coefficients[k] = static_cast<double>(monomial[k] / scale);
    scale *= half;
  }
  return coefficients;
}

}  // namespace mrd::model::compile_time
