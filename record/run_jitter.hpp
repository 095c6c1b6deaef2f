#pragma once

#include <vector>

#include "record/recorded_run.hpp"
#include "record/run_gaps.hpp"

namespace mrd::record {

// How far a run's timestamps wander about an even grid, against what the time column's own
// rounding explains. A sample's wander is measured from the midpoint of its neighbours, so a
// rate slightly off nominal or a gap elsewhere does not count: rounding to a resolution r moves
// it by at most r (the Dyke file: 3004.8 Hz written to 0.1 ms), a USB logger's jitter by up to
// twice its own amplitude.
struct TimeJitter {
  double wander = 0.0;      // [s], the 90th percentile of |t_i - (t_{i-1} + t_{i+1}) / 2|
  double resolution = 0.0;  // [s], the time column's quantum: the least difference of two steps
  // The samples were taken unevenly, not written rounded: more wander than the resolution
  // explains, and at least 1 % of a period (less costs nothing a fit could see).
  [[nodiscard]] bool uneven(double period) const {
    return wander > 0.01 * period && wander > 1.05 * resolution;
  }
};
[[nodiscard]] TimeJitter measure_jitter(const std::vector<double>& time);

// A run whose samples were taken unevenly, on the even grid t0 + k / sample_rate: every channel
// interpolated linearly between the recorded samples either side of each grid time. A step
// longer than 1.5 periods plus twice the wander is a logging gap: its grid samples are flagged
// `filled` and listed in `gaps`, as fill_gaps does (which calls this for such runs). The
// reader's set-aside rows point at the grid sample after their time.
[[nodiscard]] GapFilledRun resample_on_even_grid(const RecordedRun& run, const TimeJitter& jitter);

// The same run at its recorded times (RunTiming::kRecorded): only a step longer than 1.5
// periods plus twice the wander is a gap, filled at the nominal period and flagged, as
// fill_gaps does. For tools that step the model by each sample's own interval.
[[nodiscard]] GapFilledRun keep_recorded_times(const RecordedRun& run, const TimeJitter& jitter);

}  // namespace mrd::record
