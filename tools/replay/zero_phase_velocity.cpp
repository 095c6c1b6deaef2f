#include "tools/replay/zero_phase_velocity.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "tools/spectrum.hpp"

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

}  // namespace

std::vector<double> zero_phase_velocity(std::span<const double> displacement, double sample_rate,
                                        double cutoff) {
  std::vector<double> x(displacement.begin(), displacement.end());
  const std::size_t n = x.size();
  if (n < 2) return std::vector<double>(n, 0.0);
  // Above about 0.45 of the sample rate the low-pass would do nothing; plain differences then.
  if (cutoff > 0.0 && cutoff < 0.45 * sample_rate) {
    const Biquad filter = butterworth_low_pass(sample_rate, cutoff);
    filter.run(x);
    std::reverse(x.begin(), x.end());
    filter.run(x);
    std::reverse(x.begin(), x.end());
  }
  std::vector<double> v(n);
  v[0] = (x[1] - x[0]) * sample_rate;
  v[n - 1] = (x[n - 1] - x[n - 2]) * sample_rate;
  for (std::size_t i = 1; i + 1 < n; ++i) v[i] = 0.5 * (x[i + 1] - x[i - 1]) * sample_rate;
  return v;
}

double motion_velocity_cutoff(const std::vector<double>& displacement, double sample_rate) {
  const double f99 = frequency_below(displacement, 0, displacement.size(), 1.0 / sample_rate, 0.99);
  return std::clamp(5.0 * f99, 2.0, 0.2 * sample_rate);
}

}  // namespace mrd::tools
