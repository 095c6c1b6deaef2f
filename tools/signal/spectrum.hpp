#pragma once

#include <cstddef>
#include <vector>

// Spectra of recorded signals, for the host tools.
namespace mrd::tools {

// Power spectrum of the longest power-of-two stretch of x[from, to) (at most 2^18 samples),
// mean removed, Hann window: bins 0 .. n/2 - 1, bin k at k / (n T), bin 0 set to 0; `n` is the
// stretch's length. Empty when shorter than 64 samples.
std::vector<double> power_spectrum(const std::vector<double>& x, std::size_t from, std::size_t to,
                                   std::size_t& n);

struct SpectralPeak {
  double frequency = 0.0;  // [Hz]
  double share = 0.0;      // its power (+-2 bins) over the total, DC excluded
};
// The strongest line of x[from, to), DC excluded.
SpectralPeak spectral_peak(const std::vector<double>& x, std::size_t from, std::size_t to,
                           double sample_period);

// The frequency [Hz] below which `share` of the power of x[from, to) lies; 0 when too short.
double frequency_below(const std::vector<double>& x, std::size_t from, std::size_t to, double sample_period,
                       double share);

}  // namespace mrd::tools
