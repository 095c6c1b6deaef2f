#include "tools/residual/residual_structure.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "tools/signal/spectrum.hpp"
#include "tools/text_format.hpp"
#include "tools/signal/signal_scale.hpp"

namespace mrd::tools {

namespace {

// Energy share of the masked samples over their sample share; 0 when the mask is empty.
double concentration(const std::vector<double>& r, const std::vector<std::uint8_t>& mask) {
  double in = 0.0, all = 0.0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < r.size(); ++i) {
    all += r[i] * r[i];
    if (mask[i] != 0) {
      in += r[i] * r[i];
      ++count;
    }
  }
  if (count == 0 || count == r.size() || all <= 0.0) return 0.0;
  return (in / all) / (static_cast<double>(count) / static_cast<double>(r.size()));
}

double correlation(const std::vector<double>& a, const std::vector<double>& b) {
  const auto n = static_cast<double>(a.size());
  double ma = 0.0, mb = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    ma += a[i];
    mb += b[i];
  }
  ma /= n;
  mb /= n;
  double sab = 0.0, saa = 0.0, sbb = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    sab += (a[i] - ma) * (b[i] - mb);
    saa += (a[i] - ma) * (a[i] - ma);
    sbb += (b[i] - mb) * (b[i] - mb);
  }
  return saa > 0.0 && sbb > 0.0 ? sab / std::sqrt(saa * sbb) : 0.0;
}

}  // namespace

double percentile_abs(const std::vector<double>& v, double q) {
  std::vector<double> a(v.size());
  std::transform(v.begin(), v.end(), a.begin(), [](double x) { return std::fabs(x); });
  if (a.empty()) return 0.0;
  const auto k = static_cast<std::size_t>(q * static_cast<double>(a.size() - 1));
  std::nth_element(a.begin(), a.begin() + static_cast<std::ptrdiff_t>(k), a.end());
  return a[k];
}

double noise_floor(const std::vector<double>& r) {
  if (r.size() < 3) return 0.0;
  std::vector<double> d(r.size() - 1);
  for (std::size_t i = 1; i < r.size(); ++i) d[i - 1] = r[i] - r[i - 1];
  return mad_sigma(std::move(d)) / std::sqrt(2.0);
}

ResidualStructure analyse_residual(const FitSeries& s, const std::vector<double>& r) {
  ResidualStructure out;
  const std::size_t n = s.size();
  if (n < 16) return out;
  double sum = 0.0;
  for (const double v : r) sum += v * v;
  out.rms = std::sqrt(sum / static_cast<double>(n));
  out.noise_floor = noise_floor(r);

  const double stroke = percentile_abs(s.displacement, 0.999);
  const double speed = percentile_abs(s.velocity, 0.99);
  std::vector<std::uint8_t> mask(n);
  for (std::size_t i = 0; i < n; ++i) mask[i] = std::fabs(s.displacement[i]) > 0.8 * stroke;
  out.stroke_end_share = concentration(r, mask);
  for (std::size_t i = 0; i < n; ++i) mask[i] = std::fabs(s.velocity[i]) < 0.1 * speed;
  out.low_velocity_share = concentration(r, mask);

  // Samples shortly after a current change: within 5 % of the span, 20 ms or 5 samples.
  const auto [lo, hi] = std::minmax_element(s.current.begin(), s.current.end());
  const double span = *hi - *lo;
  const auto window = static_cast<std::size_t>(std::max(5.0, 0.02 / s.sample_period));
  std::fill(mask.begin(), mask.end(), 0);
  if (span > 0.0) {
    for (std::size_t i = 1; i < n; ++i) {
      if (std::fabs(s.current[i] - s.current[i - 1]) > 0.05 * span)
        std::fill(mask.begin() + static_cast<std::ptrdiff_t>(i),
                  mask.begin() + static_cast<std::ptrdiff_t>(std::min(n, i + window)), 1);
    }
  }
  out.after_step_share = concentration(r, mask);

  // Drift: the residual relative to the measured force's spread, first against last tenth
  // with the damper moving (a run that ends at rest would otherwise read as a drift).
  const std::size_t tenth = n / 10;
  const auto relative_rms = [&](std::size_t part) {
    double e = 0.0, f = 0.0, m = 0.0, moving = 0.0;
    const std::size_t from = part * tenth, to = from + tenth;
    for (std::size_t i = from; i < to; ++i) m += s.force[i];
    m /= static_cast<double>(tenth);
    for (std::size_t i = from; i < to; ++i) {
      e += r[i] * r[i];
      f += (s.force[i] - m) * (s.force[i] - m);
      moving += std::fabs(s.velocity[i]) > 0.1 * speed ? 1.0 : 0.0;
    }
    return moving > 0.3 * static_cast<double>(tenth) && f > 0.0 ? std::sqrt(e / f) : -1.0;
  };
  if (tenth > 0) {
    double first = -1.0, last = -1.0;
    for (std::size_t part = 0; part < 10 && first < 0.0; ++part) first = relative_rms(part);
    for (std::size_t part = 10; part-- > 0 && last < 0.0;) last = relative_rms(part);
    out.drift_ratio = first > 0.0 && last > 0.0 ? last / first : 0.0;
  }
  out.displacement_correlation = correlation(r, s.displacement);
  out.velocity_correlation = correlation(r, s.velocity);

  // Each run's spectrum at its own sample period (a frequency means nothing across runs at other
  // rates); the run whose residual is most periodic speaks for the series.
  for (std::size_t run = 0; run < std::max<std::size_t>(1, s.run_starts.size()); ++run) {
    const std::size_t from = s.run_starts.empty() ? 0 : s.run_starts[run];
    const std::size_t to = run + 1 < s.run_starts.size() ? s.run_starts[run + 1] : n;
    const SpectralPeak peak = spectral_peak(r, from, to, s.run_periods[run]);
    if (run > 0 && !(peak.share > out.peak_power_share)) continue;
    out.peak_frequency = peak.frequency;
    out.peak_power_share = peak.share;
    out.motion_frequency = spectral_peak(s.displacement, from, to, s.run_periods[run]).frequency;
  }
  return out;
}

std::string describe(const ResidualStructure& s) {
  std::string out = format("RMS %.4g N against a white-noise floor of %.4g N", s.rms, s.noise_floor);
  if (s.rms <= 1.25 * s.noise_floor) return out + ": white, at the noise floor; no structure left.";
  std::vector<std::string> parts;
  if (s.peak_power_share > 0.3) {
    std::string line = format("a periodic component at %.3g Hz carries %.0f%% of the residual power",
                              s.peak_frequency, 100.0 * s.peak_power_share);
    if (s.motion_frequency > 0.0)
      line += format(" (%.2f x the motion's %.3g Hz)", s.peak_frequency / s.motion_frequency, s.motion_frequency);
    parts.push_back(line);
  }
  if (s.stroke_end_share > 2.0)
    parts.push_back(format("error concentrates at the stroke ends (%.1f x an even spread)", s.stroke_end_share));
  if (s.low_velocity_share > 2.0)
    parts.push_back(format("error concentrates at low velocity (%.1f x)", s.low_velocity_share));
  if (s.after_step_share > 2.0)
    parts.push_back(format("error concentrates after current changes (%.1f x)", s.after_step_share));
  if (s.drift_ratio > 1.5 || (s.drift_ratio > 0.0 && s.drift_ratio < 1.0 / 1.5))
    parts.push_back(format("the error drifts over the run (last tenth %.2f x the first)", s.drift_ratio));
  if (std::fabs(s.displacement_correlation) > 0.3)
    parts.push_back(format("it follows the displacement (correlation %.2f)", s.displacement_correlation));
  if (std::fabs(s.velocity_correlation) > 0.3)
    parts.push_back(format("it follows the velocity (correlation %.2f)", s.velocity_correlation));
  if (parts.empty()) return out + "; spread evenly over stroke, velocity, current changes and time, with no dominant line.";
  out += "; ";
  for (std::size_t i = 0; i < parts.size(); ++i) out += (i > 0 ? "; " : "") + parts[i];
  return out + ".";
}

}  // namespace mrd::tools
