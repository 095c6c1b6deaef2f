#include "tools/residual/claim_evidence.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>

#include "tools/text_format.hpp"

namespace mrd::tools {

namespace {

// Continued fraction of the regularised incomplete beta I_x(a, b), by the modified Lentz method;
// converges fast for x < (a + 1) / (a + b + 2).
double beta_fraction(double a, double b, double x) {
  constexpr double kTiny = 1e-300;
  double c = 1.0;
  double d = 1.0 - (a + b) * x / (a + 1.0);
  d = 1.0 / (std::fabs(d) < kTiny ? kTiny : d);
  double f = d;
  for (int m = 1; m <= 500; ++m) {
    const double dm = m;
    for (const double coefficient : {dm * (b - dm) * x / ((a + 2 * dm - 1) * (a + 2 * dm)),
                                     -(a + dm) * (a + b + dm) * x / ((a + 2 * dm) * (a + 2 * dm + 1))}) {
      d = 1.0 + coefficient * d;
      c = 1.0 + coefficient / c;
      d = 1.0 / (std::fabs(d) < kTiny ? kTiny : d);
      c = std::fabs(c) < kTiny ? kTiny : c;
      f *= c * d;
    }
    if (std::fabs(c * d - 1.0) < 1e-15) break;
  }
  return f;
}

double incomplete_beta(double a, double b, double x) {
  if (x <= 0.0) return 0.0;
  if (x >= 1.0) return 1.0;
  const double front =
      std::exp(std::lgamma(a + b) - std::lgamma(a) - std::lgamma(b) + a * std::log(x) + b * std::log1p(-x));
  if (x < (a + 1.0) / (a + b + 2.0)) return front * beta_fraction(a, b, x) / a;
  return 1.0 - front * beta_fraction(b, a, 1.0 - x) / b;
}

// P(T <= t) for t >= 0.
double student_t_cdf(double t, double dof) { return 1.0 - 0.5 * incomplete_beta(dof / 2.0, 0.5, dof / (dof + t * t)); }

// A piece shorter than this holds too few samples for its mean square to mean much.
constexpr std::size_t kShortestPiece = 25;

}  // namespace

double student_t_quantile(double p, double dof) {
  double lo = 0.0;
  double hi = 1.0;
  while (student_t_cdf(hi, dof) < p && hi < 1e12) hi *= 2.0;
  for (int i = 0; i < 200 && hi - lo > 1e-12 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (student_t_cdf(mid, dof) < p ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

double normal_quantile(double p) {
  double lo = 0.0;
  double hi = 40.0;
  for (int i = 0; i < 200 && hi - lo > 1e-13; ++i) {
    const double mid = 0.5 * (lo + hi);
    (0.5 * std::erfc(-mid / std::numbers::sqrt2) < p ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

ValidationBlocks validation_blocks(const FitSeries& s, int pieces_per_block) {
  ValidationBlocks out;
  out.of_sample.assign(s.size(), -1);
  for (std::size_t r = 0; r < s.run_starts.size(); ++r) {
    const std::size_t begin = s.run_starts[r];
    const std::size_t end = r + 1 < s.run_starts.size() ? s.run_starts[r + 1] : s.size();
    // Stretches between fitting samples that hold a validation sample.
    struct Stretch {
      std::size_t first, last;  // [first, last)
    };
    std::vector<Stretch> stretches;
    std::size_t open = begin;
    bool holds_validation = false;
    for (std::size_t i = begin; i <= end; ++i) {
      const bool fitting = i == end || s.role[i] == SampleRole::kFitting;
      if (!fitting) {
        holds_validation = holds_validation || s.role[i] == SampleRole::kValidation;
        continue;
      }
      if (holds_validation) stretches.push_back({open, i});
      open = i + 1;
      holds_validation = false;
    }
    if (stretches.empty()) continue;
    std::size_t shortest = end - begin;
    for (const Stretch& st : stretches) shortest = std::min(shortest, st.last - st.first);
    const auto per_block = static_cast<std::size_t>(std::clamp<std::ptrdiff_t>(
        static_cast<std::ptrdiff_t>(shortest / kShortestPiece), 1, std::max(pieces_per_block, 1)));
    for (const Stretch& st : stretches) {
      const std::size_t length = st.last - st.first;
      // Whole blocks only (a stretch the screening lengthened is not one more), so no piece is
      // shorter than the shortest stretch's.
      const std::size_t pieces = std::max<std::size_t>(1, length / shortest) * per_block;
      for (std::size_t i = st.first; i < st.last; ++i) {
        if (s.role[i] != SampleRole::kValidation) continue;
        out.of_sample[i] = out.count + static_cast<int>(((i - st.first) * pieces) / length);
      }
      out.count += static_cast<int>(pieces);
    }
  }
  return out;
}

ClaimEvidence weigh_claim(const FitSeries& s, const ValidationBlocks& pieces, const std::vector<double>& simpler,
                          const std::vector<double>& richer, double noise_floor, int comparisons,
                          const ClaimCriterion& criterion) {
  ClaimEvidence e;
  e.noise_floor = noise_floor;
  // Pieces of another series (the fitting series' against the full one) weigh nothing.
  if (simpler.size() != s.size() || richer.size() != s.size() || pieces.of_sample.size() != s.size()) return e;
  const auto count = static_cast<std::size_t>(pieces.count);
  std::vector<double> simpler_loss(count, 0.0), richer_loss(count, 0.0), samples(count, 0.0);
  double change = 0.0;  // sum of d^2 [N^2]
  for (std::size_t i = 0; i < s.size(); ++i) {
    const int b = pieces.of_sample[i];
    if (b < 0) continue;
    const auto k = static_cast<std::size_t>(b);
    simpler_loss[k] += s.loss.rho(s.force[i] - simpler[i]);
    richer_loss[k] += s.loss.rho(s.force[i] - richer[i]);
    samples[k] += 1.0;
    change += (richer[i] - simpler[i]) * (richer[i] - simpler[i]);
  }
  // Per piece, the fall of the mean square; pieces the screening emptied carry nothing.
  std::vector<double> fall, weight;
  double total = 0.0, simpler_total = 0.0, fall_total = 0.0;
  for (std::size_t k = 0; k < count; ++k) {
    if (!(samples[k] > 0.0)) continue;
    fall.push_back((simpler_loss[k] - richer_loss[k]) / samples[k]);
    weight.push_back(samples[k]);
    total += samples[k];
    simpler_total += simpler_loss[k];
    fall_total += simpler_loss[k] - richer_loss[k];
  }
  e.pieces = static_cast<int>(fall.size());
  if (e.pieces < 2) return e;
  const double n = e.pieces;
  e.simpler_ms = simpler_total / total;
  e.reduction = fall_total / total;
  // The weighted mean's standard error (a ratio estimator's, over the pieces).
  double spread = 0.0;
  for (std::size_t k = 0; k < fall.size(); ++k)
    spread += weight[k] * weight[k] * (fall[k] - e.reduction) * (fall[k] - e.reduction);
  e.standard_error = std::sqrt(spread * n / (n - 1.0)) / total;
  const auto ratio = [](double x, double by) { return by > 0.0 ? x / by : (x > 0.0 ? 1e300 : 0.0); };
  e.t = ratio(e.reduction, e.standard_error);
  const double alpha = (1.0 - criterion.confidence) / std::max(comparisons, 1) / 2.0;
  e.t_required = student_t_quantile(1.0 - alpha, n - 1.0);
  // Without a noise floor (a record with no noise to read) there is no test against it.
  const bool noise_known = noise_floor > 0.0;
  e.z = noise_known ? ratio(fall_total, 2.0 * noise_floor * std::sqrt(change)) : 0.0;
  e.z_required = noise_known ? normal_quantile(1.0 - alpha) : std::numeric_limits<double>::infinity();
  const double noise_ms = noise_floor * noise_floor;
  e.required = std::max(criterion.excess_share * std::max(e.simpler_ms - noise_ms, 0.0), criterion.noise_share * noise_ms);
  return e;
}

double ClaimEvidence::margin() const {
  if (pieces < 2) return 0.0;
  const double significance = std::max(t / t_required, z / z_required);
  return std::min(significance, required > 0.0 ? reduction / required : significance);
}

std::string ClaimEvidence::describe() const {
  if (pieces < 2) return format("%d held-out pieces, too few to weigh", pieces);
  return format("validation mean square %+.4g N^2, needs a fall of %.4g N^2 (noise floor %.4g N); t = %.3g over %d "
                "pieces (needs %.3g) or z = %.3g against the noise (needs %.3g)",
                -reduction, required, noise_floor, t, pieces, t_required, z, z_required);
}

}  // namespace mrd::tools
