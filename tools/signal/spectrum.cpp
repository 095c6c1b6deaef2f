#include "tools/signal/spectrum.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <unsupported/Eigen/FFT>

namespace mrd::tools {

std::vector<double> power_spectrum(const std::vector<double>& x, std::size_t from, std::size_t to,
                                   std::size_t& n) {
  n = 1;
  while (n * 2 <= std::min<std::size_t>(to - from, 1u << 18)) n *= 2;
  if (n < 64) return {};
  std::vector<double> window(n);
  double mean = 0.0;
  for (std::size_t i = 0; i < n; ++i) mean += x[from + i];
  mean /= static_cast<double>(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double hann = 0.5 - 0.5 * std::cos(2.0 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(n));
    window[i] = (x[from + i] - mean) * hann;
  }
  Eigen::FFT<double> fft;
  std::vector<std::complex<double>> spectrum;
  fft.fwd(spectrum, window);
  std::vector<double> power(n / 2, 0.0);
  for (std::size_t k = 1; k < n / 2; ++k) power[k] = std::norm(spectrum[k]);
  return power;
}

SpectralPeak spectral_peak(const std::vector<double>& x, std::size_t from, std::size_t to,
                           double sample_period) {
  std::size_t n = 0;
  const std::vector<double> power = power_spectrum(x, from, to, n);
  double total = 0.0;
  for (const double p : power) total += p;
  if (power.size() < 2 || total <= 0.0) return {};
  const std::size_t half = power.size();
  const auto best = static_cast<std::size_t>(std::max_element(power.begin() + 1, power.end()) - power.begin());
  double around = 0.0;
  for (std::size_t k = best > 3 ? best - 2 : 1; k <= std::min(best + 2, half - 1); ++k) around += power[k];
  return {static_cast<double>(best) / (static_cast<double>(n) * sample_period), around / total};
}

double frequency_below(const std::vector<double>& x, std::size_t from, std::size_t to, double sample_period,
                       double share) {
  std::size_t n = 0;
  const std::vector<double> power = power_spectrum(x, from, to, n);
  double total = 0.0;
  for (const double p : power) total += p;
  if (total <= 0.0) return 0.0;
  double sum = 0.0;
  for (std::size_t k = 1; k < power.size(); ++k) {
    sum += power[k];
    if (sum >= share * total) return static_cast<double>(k) / (static_cast<double>(n) * sample_period);
  }
  return 0.5 / sample_period;
}

}  // namespace mrd::tools
