#pragma once

#include <string>
#include <vector>

#include "tools/residual/fit_series.hpp"

namespace mrd::tools {

// Where a force residual lives. Each "share" compares the residual's energy in a part of the
// run with that part's share of the samples: 1 means spread evenly, 3 means three times as
// concentrated there as an even spread would be.
struct ResidualStructure {
  double rms = 0.0;          // [N]
  double noise_floor = 0.0;  // white-noise RMS from the sample-to-sample differences [N]
  double stroke_end_share = 0.0;     // |x| beyond 80 % of the stroke
  double low_velocity_share = 0.0;   // |v| below 10 % of the speed
  double after_step_share = 0.0;     // within 5 % of a current change's span of time after it
  double drift_ratio = 0.0;          // RMS of the last tenth over that of the first
  double displacement_correlation = 0.0;  // with x
  double velocity_correlation = 0.0;      // with v
  // Of the run whose residual spectrum is most concentrated, each run at its own sample period:
  double peak_frequency = 0.0;       // strongest line of the spectrum, DC excluded [Hz]
  double peak_power_share = 0.0;     // its power (+-2 bins) over the total (DC excluded)
  double motion_frequency = 0.0;     // strongest line of that run's displacement [Hz]
};

ResidualStructure analyse_residual(const FitSeries& series, const std::vector<double>& residual);

// One paragraph for the reports: the RMS against the noise floor, then each feature above its
// threshold (docs/CLOSING-THE-LOOP.md); "white, at the noise floor" when nothing stands out.
std::string describe(const ResidualStructure& s);

// The q-quantile (0..1) of |v|; 0 for an empty sequence.
double percentile_abs(const std::vector<double>& v, double q);

// The white-noise RMS of a sequence: 1.4826 MAD of its first differences / sqrt(2). Smooth
// model error hardly moves from one sample to the next; steps are outliers the median ignores.
double noise_floor(const std::vector<double>& residual);

}  // namespace mrd::tools
