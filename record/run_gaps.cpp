#include "record/run_gaps.hpp"

#include <cmath>
#include <string>

#include "record/csv.hpp"
#include "record/run_jitter.hpp"

namespace mrd::record {

namespace {

// More filled samples than this many times the recorded ones: no gap, a timestamp far off.
constexpr double kMaxFilledShare = 4.0;

[[noreturn]] void throw_far_off(const RecordedRun& run, double missing) {
  throw InputError(run.name + ": the logging gaps would take " + std::to_string(static_cast<long long>(missing)) +
                   " filled samples, more than " + std::to_string(static_cast<int>(kMaxFilledShare)) +
                   " times the run's " + std::to_string(run.size()) +
                   ": a timestamp far off, or separate runs in one file (split it)");
}

}  // namespace

GapFilledRun fill_gaps(const RecordedRun& run, UnevenTimes uneven) {
  const std::size_t n = run.size();
  const double period = run.sample_rate > 0.0 ? 1.0 / run.sample_rate : 0.0;
  if (const TimeJitter jitter = measure_jitter(run.time); period > 0.0 && jitter.uneven(period)) {
    const double added = std::floor(run.duration() / period) + 1.0 - static_cast<double>(n);
    if (added > kMaxFilledShare * static_cast<double>(n)) throw_far_off(run, added);
    return uneven == UnevenTimes::kResample ? resample_on_even_grid(run, jitter) : keep_recorded_times(run, jitter);
  }
  std::size_t long_steps = 0;
  double missing_total = 0.0;
  for (std::size_t i = 1; i < n && period > 0.0; ++i) {
    const double dt = run.time[i] - run.time[i - 1];
    if (dt <= 1.5 * period) continue;
    ++long_steps;
    missing_total += dt / period;
  }
  if (long_steps == 0 || long_steps > std::max<std::size_t>(10, n / 100)) {
    GapFilledRun out{.run = run, .filled = std::vector<std::uint8_t>(n, 0), .gap_step = 1.5 * period};
    // Many long steps are a time column coarser than the period, not gaps.
    if (long_steps > 0)
      out.run.notes.push_back(std::to_string(long_steps) +
                              " time steps longer than 1.5 periods: too many to be logging gaps, left as they are");
    return out;
  }
  if (missing_total > kMaxFilledShare * static_cast<double>(n)) throw_far_off(run, missing_total);
  GapFilledRun out = fill_steps_longer_than(run, 1.5 * period);
  out.run.notes.push_back(std::to_string(out.gaps.size()) + " logging gaps filled with " +
                          std::to_string(out.run.size() - n) +
                          " samples at the nominal period (inputs bridged, not fitted)");
  return out;
}

GapFilledRun fill_steps_longer_than(const RecordedRun& run, double longest_step) {
  GapFilledRun out;
  const std::size_t n = run.size();
  const double period = 1.0 / run.sample_rate;
  out.gap_step = longest_step;
  out.run = run;
  RecordedRun& f = out.run;
  f.time.clear();
  for (std::vector<double>* c : f.channels()) c->clear();
  const auto from = run.channels();
  const auto to = f.channels();
  const auto append = [&](std::size_t i) {
    f.time.push_back(run.time[i]);
    for (std::size_t c = 0; c < from.size(); ++c)
      if (!from[c]->empty()) to[c]->push_back((*from[c])[i]);
    out.filled.push_back(0);
  };
  if (n > 0) append(0);
  for (std::size_t i = 1; i < n; ++i) {
    const double dt = run.time[i] - run.time[i - 1];
    if (dt > longest_step) {
      const auto missing = static_cast<std::size_t>(std::max(std::lround(dt / period), 1L)) - 1;
      const std::size_t first = f.size();
      for (std::size_t k = 1; k <= missing; ++k) {
        const double w = static_cast<double>(k) / static_cast<double>(missing + 1);
        f.time.push_back(run.time[i - 1] + w * dt);
        for (std::size_t c = 0; c < from.size(); ++c)
          if (!from[c]->empty()) to[c]->push_back((*from[c])[i - 1] + w * ((*from[c])[i] - (*from[c])[i - 1]));
        out.filled.push_back(1);
      }
      if (missing > 0) out.gaps.emplace_back(first, f.size() - 1);
    }
    append(i);
  }
  // The reader's set-aside rows point at samples of the filled run.
  for (RecordedRun::SetAsideRow& row : f.set_aside_rows) {
    std::size_t added = 0;
    for (const auto& [first, last] : out.gaps)
      if (first <= row.next_sample + added) added += last - first + 1;
    row.next_sample += added;
  }
  return out;
}

}  // namespace mrd::record
