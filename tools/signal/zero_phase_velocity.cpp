#include "tools/signal/zero_phase_velocity.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <span>

#include "tools/signal/spectrum.hpp"

namespace mrd::tools {

namespace {

// Direct form II transposed biquad, started in steady state on the first input.
struct Biquad {
  double b0, b1, b2, a1, a2;

  void run(std::vector<double>& x) const {
    if (x.empty()) return;
    // Steady state for a constant input x0: y = x0 (unit DC gain).
    const double x0 = x.front();
    double z1 = x0 * (1.0 - b0);
    double z2 = x0 * (b2 - a2);
    for (double& v : x) {
      const double in = v;
      const double out = b0 * in + z1;
      z1 = b1 * in - a1 * out + z2;
      z2 = b2 * in - a2 * out;
      v = out;
    }
  }
};

// Butterworth low-pass by the bilinear transform with prewarping.
Biquad butterworth_low_pass(double sample_rate, double cutoff) {
  const double k = std::tan(std::numbers::pi * cutoff / sample_rate);
  const double q = std::numbers::sqrt2 / 2.0;
  const double norm = 1.0 / (1.0 + k / q + k * k);
  const double b0 = k * k * norm;
  return {b0, 2.0 * b0, b0, 2.0 * (k * k - 1.0) * norm, (1.0 - k / q + k * k) * norm};
}

// Value, slope and curvature (per sample and sample^2) at x[0] of the least-squares cubic through
// x[0..count): the record's state at its end, robust to the noise of single samples.
struct EndState {
  double value = 0.0, slope = 0.0, curvature = 0.0;
};

EndState end_state(std::span<const double> x, std::size_t count) {
  count = std::min(count, x.size());
  if (count < 4) return {x.empty() ? 0.0 : x[0], 0.0, 0.0};
  Eigen::Matrix4d normal = Eigen::Matrix4d::Zero();
  Eigen::Vector4d right = Eigen::Vector4d::Zero();
  const double scale = static_cast<double>(count);  // k / count keeps the normal matrix conditioned
  for (std::size_t i = 0; i < count; ++i) {
    const double k = static_cast<double>(i) / scale;
    const Eigen::Vector4d p(1.0, k, k * k, k * k * k);
    normal += p * p.transpose();
    right += p * x[i];
  }
  const Eigen::Vector4d c = normal.ldlt().solve(right);
  return {c(0), c(1) / scale, 2.0 * c(2) / (scale * scale)};
}

// `pad` samples before x[0], in time order: x reflected through x[0] (2 x0 - x_k keeps the
// value and the slope), its curvature restored (the reflection flips it) from the cubic through
// the first `fit` samples.
void pad_before(std::span<const double> x, std::size_t pad, std::size_t fit, std::vector<double>& out) {
  const std::size_t n = x.size();
  const double curvature = end_state(x, fit).curvature;
  const double width = 3.0 * static_cast<double>(std::max<std::size_t>(fit, 1));
  for (std::size_t k = pad; k >= 1; --k) {
    const double s = static_cast<double>(k);
    // The restored curvature fades out past the fitted span, where a parabola would run away.
    out.push_back(2.0 * x[0] - x[std::min(k, n - 1)] + curvature * s * s * std::exp(-(s * s) / (width * width)));
  }
}

// Samples a+1..b-1 by the quintic that meets each side's end_state (value, slope and curvature
// from `fit` samples): an interpolation between two measured motions, where each side's
// reflection would be an extrapolation from one.
void bridge_between(std::vector<double>& x, std::size_t a, std::size_t b, std::size_t fit) {
  const auto last = x.rend() - static_cast<std::ptrdiff_t>(a) - 1;
  const std::vector<double> before(last, last + static_cast<std::ptrdiff_t>(std::min(fit, a + 1)));
  const EndState left = end_state(before, fit);
  const EndState right = end_state(std::span<const double>(x).subspan(b), fit);
  const double length = static_cast<double>(b - a);
  const double p0 = left.value, m0 = -left.slope * length, c0 = left.curvature * length * length;
  const double p1 = right.value, m1 = right.slope * length, c1 = right.curvature * length * length;
  for (std::size_t k = a + 1; k < b; ++k) {
    const double s = static_cast<double>(k - a) / length, s2 = s * s, s3 = s2 * s, s4 = s3 * s, s5 = s4 * s;
    x[k] = (1.0 - 10.0 * s3 + 15.0 * s4 - 6.0 * s5) * p0 + (s - 6.0 * s3 + 8.0 * s4 - 3.0 * s5) * m0 +
           (0.5 * s2 - 1.5 * s3 + 1.5 * s4 - 0.5 * s5) * c0 + (0.5 * s3 - s4 + 0.5 * s5) * c1 +
           (-4.0 * s3 + 7.0 * s4 - 3.0 * s5) * m1 + (10.0 * s3 - 15.0 * s4 + 6.0 * s5) * p1;
  }
}

}  // namespace

std::vector<double> zero_phase_velocity(std::span<const double> displacement, double sample_rate,
                                        double cutoff) {
  const std::size_t n = displacement.size();
  if (n < 2) return std::vector<double>(n, 0.0);
  // Above about 0.45 of the sample rate the low-pass would do nothing; plain differences then.
  const bool filtered = cutoff > 0.0 && cutoff < 0.45 * sample_rate;
  // Each end padded (pad_before) so that the motion continues with its value, slope and
  // curvature: neither pass starts a transient on the record itself, the pads take it, over
  // three periods of the cutoff (the filter's response has died by a factor of about 1e-6).
  const std::size_t pad =
      filtered ? std::min(n - 1, static_cast<std::size_t>(std::ceil(3.0 * sample_rate / cutoff))) : 1;
  // The curvature from 0.7 periods of the cutoff, faded over three times that: the best of the
  // spans tried on sines at every phase (tests/tools/residual/test_fit_series.cpp).
  const auto fit = static_cast<std::size_t>(std::ceil(0.7 * sample_rate / std::max(cutoff, 1e-9)));
  std::vector<double> x;
  x.reserve(n + 2 * pad);
  pad_before(displacement, pad, fit, x);
  x.insert(x.end(), displacement.begin(), displacement.end());
  const std::vector<double> reversed(displacement.rbegin(), displacement.rend());
  std::vector<double> after;
  pad_before(reversed, pad, fit, after);
  x.insert(x.end(), after.rbegin(), after.rend());
  if (filtered) {
    const Biquad filter = butterworth_low_pass(sample_rate, cutoff);
    filter.run(x);
    std::reverse(x.begin(), x.end());
    filter.run(x);
    std::reverse(x.begin(), x.end());
  }
  // Central differences throughout: the pads give the ends their outer neighbours.
  std::vector<double> v(n);
  for (std::size_t i = 0; i < n; ++i) v[i] = 0.5 * (x[pad + i + 1] - x[pad + i - 1]) * sample_rate;
  return v;
}

std::vector<double> zero_phase_velocity_by_stretch(std::span<const double> displacement, std::span<const double> time,
                                                   double sample_rate, double cutoff,
                                                   const std::vector<std::uint8_t>& filled) {
  const std::size_t n = displacement.size();
  const double period = sample_rate / std::max(cutoff, 1e-9);  // of the cutoff, in samples
  // Each side's state from a quarter period of the cutoff: over longer spans the cubic's bias at
  // its end dominates (on sines beside a gap, with an LVDT's noise: velocity 1 % off the unbroken
  // run's from 0.7 periods, 0.1-0.6 % from a quarter).
  const auto fit = std::max<std::size_t>(8, static_cast<std::size_t>(std::ceil(std::min(0.25 * period, 1e6))));
  // Up to 1.5 periods of the cutoff (0.3 of the motion's with the automatic cutoff, where the
  // quintic's error is about 1e-3 of the motion) a gap with measured motion on both sides is
  // bridged and filtered through: a split puts two padded ends, each extrapolated from one side,
  // beside the gap.
  const auto longest_bridge = static_cast<std::size_t>(std::min(1.5 * period, 1e6));
  // A short gap that cannot be bridged (near an end or another gap; a lost row or two) is
  // filtered through on its recorded bridge: its chord is the motion to well within the filter's
  // resolution.
  const auto short_gap = static_cast<std::size_t>(std::min(0.1 * period, 1e6));
  const auto measured = [&](std::size_t from, std::size_t to) {
    return std::none_of(filled.begin() + static_cast<std::ptrdiff_t>(from), filled.begin() + static_cast<std::ptrdiff_t>(to),
                        [](std::uint8_t f) { return f != 0; });
  };
  std::vector<double> x(displacement.begin(), displacement.end());
  std::vector<std::uint8_t> split = filled;
  for (std::size_t i = 0; i < n;) {
    std::size_t j = i;
    while (j < n && filled[j]) ++j;
    const bool bridged =
        j > i && j - i <= longest_bridge && i >= fit && n - j >= fit && measured(i - fit, i) && measured(j, j + fit);
    if (bridged) bridge_between(x, i - 1, j, fit);
    if (bridged || (j > i && j - i <= short_gap))
      std::fill(split.begin() + static_cast<std::ptrdiff_t>(i), split.begin() + static_cast<std::ptrdiff_t>(j), 0);
    i = j > i ? j : i + 1;
  }
  std::vector<double> v(n, 0.0);
  for (std::size_t i = 0; i < n;) {
    if (split[i]) {
      // Across a gap, the bridge's slope.
      std::size_t b = i;
      while (b < n && split[b]) ++b;  // the first sample after it, or n at the record's end
      const std::size_t a = i > 0 ? i - 1 : i, end = std::min(b, n - 1);
      const double slope = time[end] > time[a] ? (x[end] - x[a]) / (time[end] - time[a]) : 0.0;
      for (; i < b; ++i) v[i] = slope;
      continue;
    }
    std::size_t j = i;
    while (j < n && !split[j]) ++j;
    const std::vector<double> part = zero_phase_velocity(std::span<const double>(x).subspan(i, j - i), sample_rate, cutoff);
    std::copy(part.begin(), part.end(), v.begin() + static_cast<std::ptrdiff_t>(i));
    i = j;
  }
  return v;
}

double motion_velocity_cutoff(const std::vector<double>& displacement, double sample_rate) {
  const double f99 = frequency_below(displacement, 0, displacement.size(), 1.0 / sample_rate, 0.99);
  return std::clamp(5.0 * f99, 2.0, 0.2 * sample_rate);
}

std::vector<double> zero_phase_velocity_at_times(std::span<const double> displacement, std::span<const double> time,
                                                 double sample_rate, double cutoff,
                                                 const std::vector<std::uint8_t>& filled) {
  const std::size_t n = displacement.size();
  if (n < 2) return std::vector<double>(n, 0.0);
  const double period = 1.0 / sample_rate;
  const double t0 = time.front();
  const auto grid_size = static_cast<std::size_t>(std::floor((time.back() - t0) / period)) + 2;
  std::vector<double> grid_time(grid_size), grid_x(grid_size);
  std::vector<std::uint8_t> grid_filled(grid_size, 0);
  std::size_t i = 1;  // time[i - 1] <= t < time[i], or i = n - 1 at the end
  for (std::size_t k = 0; k < grid_size; ++k) {
    const double t = t0 + static_cast<double>(k) * period;
    while (i + 1 < n && time[i] <= t) ++i;
    const double w = std::clamp((t - time[i - 1]) / (time[i] - time[i - 1]), 0.0, 1.0);
    grid_time[k] = t;
    grid_x[k] = displacement[i - 1] + w * (displacement[i] - displacement[i - 1]);
    if (!filled.empty()) grid_filled[k] = filled[i - 1] | filled[i];
  }
  const std::vector<double> grid_v = zero_phase_velocity_by_stretch(grid_x, grid_time, sample_rate, cutoff, grid_filled);
  std::vector<double> v(n);
  for (std::size_t j = 0; j < n; ++j) {
    const double at = std::max(0.0, (time[j] - t0) / period);
    const auto k = std::min(static_cast<std::size_t>(at), grid_size - 2);
    v[j] = grid_v[k] + (at - static_cast<double>(k)) * (grid_v[k + 1] - grid_v[k]);
  }
  return v;
}

}  // namespace mrd::tools
