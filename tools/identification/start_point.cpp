#include "tools/identification/start_point.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "model/langevin.hpp"
#include "model/physical_constants.hpp"
#include "tools/identification/bh_objective.hpp"

namespace mrd::tools {

namespace {

using model::kMu0;

// One monotone branch of a loop, sorted by H for interpolation.
struct Branch {
  std::vector<double> H, M;

  [[nodiscard]] double at(double h) const {
    const auto it = std::lower_bound(H.begin(), H.end(), h);
    if (it == H.begin()) return M.front();
    if (it == H.end()) return M.back();
    const auto i = static_cast<std::size_t>(it - H.begin());
    const double t = (h - H[i - 1]) / (H[i] - H[i - 1]);
    return M[i - 1] + t * (M[i] - M[i - 1]);
  }
};

// Splits a loop into its falling and rising branches (by the sign of dH).
void split_branches(const BHLoop& loop, Branch& falling, Branch& rising) {
  for (std::size_t i = 1; i < loop.H.size(); ++i) {
    const double dH = loop.H[i] - loop.H[i - 1];
    if (dH == 0.0) continue;
    Branch& b = dH < 0.0 ? falling : rising;
    b.H.push_back(loop.H[i]);
    b.M.push_back(loop.B[i] / kMu0 - loop.H[i]);
  }
  for (Branch* b : {&falling, &rising}) {
    std::vector<std::size_t> order(b->H.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t l, std::size_t r) { return b->H[l] < b->H[r]; });
    Branch sorted;
    for (const auto i : order) {
      if (!sorted.H.empty() && b->H[i] == sorted.H.back()) continue;
      sorted.H.push_back(b->H[i]);
      sorted.M.push_back(b->M[i]);
    }
    *b = std::move(sorted);
  }
}

// Field where the branch crosses M = -H (B = 0).
double zero_B_crossing(const Branch& b) {
  for (std::size_t i = 1; i < b.H.size(); ++i) {
    const double B0 = b.M[i - 1] + b.H[i - 1];
    const double B1 = b.M[i] + b.H[i];
    if ((B0 <= 0.0) != (B1 <= 0.0)) return b.H[i - 1] - B0 * (b.H[i] - b.H[i - 1]) / (B1 - B0);
  }
  return 0.0;
}

double inverse_langevin(double y) {  // L(x) = y for 0 < y < 1, by bisection
  double lo = 0.0, hi = 1.0 / (1.0 - y) + 1.0;
  for (int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (lo + hi);
    (model::langevin(mid).value < y ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

const BHLoop& largest_loop(const BHCurve& curve) {
  const BHLoop* largest = &curve.loops.front();
  double widest = 0.0;
  for (const auto& loop : curve.loops) {
    const double span = *std::max_element(loop.H.begin(), loop.H.end()) -
                        *std::min_element(loop.H.begin(), loop.H.end());
    if (span > widest) {
      widest = span;
      largest = &loop;
    }
  }
  return *largest;
}

}  // namespace

LoopFeatures measure_largest_loop(const BHCurve& curve) {
  Branch falling, rising;
  split_branches(largest_loop(curve), falling, rising);
  if (falling.H.size() < 2 || rising.H.size() < 2) {
    throw record::InputError(curve.source + ": the largest loop has no falling and rising branches");
  }
  LoopFeatures f;
  f.H_tip = 0.5 * (falling.H.back() - rising.H.front());
  f.M_tip = 0.5 * (falling.M.back() - rising.M.front());
  f.coercive_field = 0.5 * (std::fabs(zero_B_crossing(falling)) + std::fabs(zero_B_crossing(rising)));
  f.remanence = 0.5 * (falling.at(0.0) - rising.at(0.0));
  // Mid-line slope through the origin, over the inner tenth of the field range.
  const double h = 0.1 * f.H_tip;
  const double mid_plus = 0.5 * (falling.at(h) + rising.at(h));
  const double mid_minus = 0.5 * (falling.at(-h) + rising.at(-h));
  f.chi_origin = (mid_plus - mid_minus) / (2.0 * h);
  // Falling branch just below the tip: the last tenth of its points.
  const std::size_t n = falling.H.size();
  const std::size_t i0 = n - 1 - std::max<std::size_t>(1, n / 10);
  f.chi_reversal = (falling.M[n - 1] - falling.M[i0]) / (falling.H[n - 1] - falling.H[i0]);
  return f;
}

Point estimate_start_point(const BHCurve& curve) {
  const LoopFeatures f = measure_largest_loop(curve);
  const double chi0 = std::max(f.chi_origin, 1e-6);
  const double M_m = std::max(f.M_tip, 1e-6);

  // Anhysteretic from the mid-line: for each trial Ms, a and alpha follow from the slope at
  // the origin and the tip (see header); keep the Ms whose curve fits the mid-line best.
  Branch falling, rising;
  split_branches(largest_loop(curve), falling, rising);
  double best_error = std::numeric_limits<double>::infinity();
  model::JilesAthertonParams best{M_m * 1.2, f.H_tip, 0.0, std::max(f.coercive_field, 1e-3), 0.5};
  for (double ratio = 1.02; ratio < 4.0; ratio *= 1.03) {
    const double Ms = M_m * ratio;
    const double x_m = inverse_langevin(M_m / Ms);
    const double a = (f.H_tip - M_m / chi0) / (x_m - 3.0 * M_m / Ms);
    if (!(a > 0.0)) continue;
    // A floor on alpha (mean-field gain 0.05): a start of exactly 0 would pin the +-100%
    // search box to alpha = 0.
    const double alpha = std::max(0.05 * 3.0 * a / Ms, (3.0 * a - Ms / chi0) / Ms);
    model::JilesAthertonParams p{Ms, a, alpha, 1.0, 0.0};
    model::JilesAtherton ja(p, {1.0, 1.0});
    double error = 0.0;
    for (int i = -10; i <= 10; ++i) {
      const double H = f.H_tip * i / 10.0;
      const double mid = 0.5 * (falling.at(H) + rising.at(H));
      const double e = ja.anhysteretic_magnetisation(H) - mid;
      error += e * e;
    }
    if (error < best_error) {
      best_error = error;
      best.Ms = Ms;
      best.a = a;
      best.alpha = alpha;
    }
  }
  // c: reversible slope after the tip over the anhysteretic slope at the tip.
  {
    model::JilesAtherton ja(best, {1.0, 1.0});
    const double dH = 1e-3 * f.H_tip;
    const double chi_an_tip = (ja.anhysteretic_magnetisation(f.H_tip + dH) -
                               ja.anhysteretic_magnetisation(f.H_tip - dH)) / (2.0 * dH);
    best.c = chi_an_tip > 0.0 ? std::clamp(f.chi_reversal / chi_an_tip, 0.05, 0.95) : 0.5;
  }
  best.k = std::max(f.coercive_field, 1e-6 * f.H_tip);
  return to_point(best);
}

std::array<bool, kParameterCount> on_estimated_face(const Point& x, const Bounds& bounds,
                                                    const Point& start) {
  std::array<bool, kParameterCount> hit{};
  for (int j = 0; j < kParameterCount; ++j) {
    const double margin = 0.01 * (bounds.upper[j] - bounds.lower[j]);
    const bool physical_floor = bounds.lower[j] <= 1e-2 * start[j] * 1.000001;
    const bool physical_ceiling = j == 4 && bounds.upper[j] >= 1.0 - 1e-6;
    hit[static_cast<std::size_t>(j)] = (x[j] <= bounds.lower[j] + margin && !physical_floor) ||
                                       (x[j] >= bounds.upper[j] - margin && !physical_ceiling);
  }
  return hit;
}

Bounds bounds_around(const Point& start, double fraction) {
  Bounds b{start * (1.0 - fraction), start * (1.0 + fraction)};
  // Ms, a, k: a floor at 1% of the start. Below it a and k make the sub-steps (and the cost
  // of one evaluation) 100x finer while describing no material the loop could come from.
  for (const int j : {0, 1, 3}) b.lower[j] = std::max(b.lower[j], 1e-2 * start[j]);
  b.lower[2] = std::max(b.lower[2], 0.0);
  b.lower[4] = std::max(b.lower[4], 0.0);
  b.upper[4] = std::min(b.upper[4], 1.0 - 1e-9);
  return b;
}

}  // namespace mrd::tools
