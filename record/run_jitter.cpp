#include "record/run_jitter.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

namespace mrd::record {

TimeJitter measure_jitter(const std::vector<double>& time) {
  TimeJitter j;
  const std::size_t n = time.size();
  if (n < 3) return j;
  std::vector<double> wander(n - 2);
  for (std::size_t i = 1; i + 1 < n; ++i) wander[i - 1] = std::fabs(time[i] - 0.5 * (time[i - 1] + time[i + 1]));
  const auto p90 = wander.begin() + static_cast<std::ptrdiff_t>((wander.size() * 9) / 10);
  std::nth_element(wander.begin(), p90, wander.end());
  j.wander = *p90;
  // Distinct steps, told apart above the doubles' own rounding of the times.
  std::vector<double> steps(n - 1);
  for (std::size_t i = 1; i < n; ++i) steps[i - 1] = time[i] - time[i - 1];
  std::ranges::sort(steps);
  const double noise = 64.0 * std::numeric_limits<double>::epsilon() *
                       std::max(std::fabs(time.front()), std::fabs(time.back()));
  double least = std::numeric_limits<double>::infinity();
  for (std::size_t i = 1; i < steps.size(); ++i)
    if (const double d = steps[i] - steps[i - 1]; d > noise) least = std::min(least, d);
  j.resolution = std::isfinite(least) ? least : 0.0;
  return j;
}

GapFilledRun resample_on_even_grid(const RecordedRun& run, const TimeJitter& jitter) {
  GapFilledRun out;
  const std::size_t n = run.size();
  const double period = 1.0 / run.sample_rate;
  const double gap_step = 1.5 * period + 2.0 * jitter.wander;
  const auto grid_size = static_cast<std::size_t>(std::floor((run.time.back() - run.time.front()) / period)) + 1;
  RecordedRun& g = out.run;
  g = run;
  g.time.resize(grid_size);
  const auto from = run.channels();
  const auto to = g.channels();
  for (std::size_t c = 0; c < from.size(); ++c)
    if (!from[c]->empty()) to[c]->assign(grid_size, 0.0);
  out.filled.assign(grid_size, 0);
  out.timing = RunTiming::kResampled;
  out.gap_step = 1.5 * period;  // on the grid
  std::size_t i = 1;  // run.time[i - 1] <= t < run.time[i], or i = n - 1 at the end
  for (std::size_t k = 0; k < grid_size; ++k) {
    const double t = run.time.front() + static_cast<double>(k) * period;
    while (i + 1 < n && run.time[i] <= t) ++i;
    const double step = run.time[i] - run.time[i - 1];
    const double w = std::clamp((t - run.time[i - 1]) / step, 0.0, 1.0);
    g.time[k] = t;
    for (std::size_t c = 0; c < from.size(); ++c)
      if (!from[c]->empty()) (*to[c])[k] = (*from[c])[i - 1] + w * ((*from[c])[i] - (*from[c])[i - 1]);
    if (step <= gap_step || w == 0.0 || w == 1.0) continue;
    out.filled[k] = 1;
    if (out.gaps.empty() || out.gaps.back().second + 1 != k) out.gaps.emplace_back(k, k);
    else out.gaps.back().second = k;
  }
  for (RecordedRun::SetAsideRow& row : g.set_aside_rows) {
    const double t = row.next_sample < n ? run.time[row.next_sample] : run.time.back() + period;
    row.next_sample = std::min(grid_size, static_cast<std::size_t>(std::ceil((t - run.time.front()) / period)));
  }
  char note[160];
  std::snprintf(note, sizeof note,
                "timestamps wander %.3g periods about an even grid (the time column resolves %.3g of one): "
                "every channel resampled onto it",
                jitter.wander / period, jitter.resolution / period);
  g.notes.emplace_back(note);
  return out;
}

GapFilledRun keep_recorded_times(const RecordedRun& run, const TimeJitter& jitter) {
  const double period = 1.0 / run.sample_rate;
  GapFilledRun out = fill_steps_longer_than(run, 1.5 * period + 2.0 * jitter.wander);
  out.timing = RunTiming::kRecorded;
  char note[200];
  std::snprintf(note, sizeof note,
                "timestamps wander %.3g periods about an even grid (the time column resolves %.3g of one): "
                "each sample kept at its recorded time, %zu logging gaps filled",
                jitter.wander / period, jitter.resolution / period, out.gaps.size());
  out.run.notes.emplace_back(note);
  return out;
}

}  // namespace mrd::record
