#include "tools/residual/fit_series.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <numeric>
#include <random>
#include <span>

#include "record/csv.hpp"
#include "record/run_gaps.hpp"
#include "tools/signal/zero_phase_velocity.hpp"
#include "tools/signal/signal_scale.hpp"

namespace mrd::tools {

namespace {

void check_run(const record::RecordedRun& run, const FitSeriesOptions& options) {
  if (!run.has_force())
    throw record::InputError(run.name + ": the run has no force column; a residual needs the measured force");
  if (run.size() < 16 || !(run.sample_rate > 0.0))
    throw record::InputError(run.name + ": too short for a residual analysis (at least 16 samples)");
  record::check_sample_rate(run);
  if (run.coil_signal == record::CoilSignal::kCommandVoltage && !options.amps_per_volt)
    throw record::InputError(run.name +
                     ": the run logged the driver's command voltage, not the coil current: "
                     "give the driver gain (--amps-per-volt)");
}

// Sample i of `from`, every channel, at the end of `to`.
void append_sample(FitSeries& to, const FitSeries& from, std::size_t i) {
  to.displacement.push_back(from.displacement[i]);
  to.velocity.push_back(from.velocity[i]);
  to.current.push_back(from.current[i]);
  to.force.push_back(from.force[i]);
  if (!from.temperature.empty()) to.temperature.push_back(from.temperature[i]);
  if (!from.time.empty()) to.time.push_back(from.time[i]);
  to.role.push_back(from.role[i]);
  if (!from.after_switch.empty()) to.after_switch.push_back(from.after_switch[i]);
}

// The filled samples of each gap, with `margin_s` on either side, set aside as kGap spans
// (whether or not the rest was screened).
void set_aside_gaps(const record::GapFilledRun& filled, double margin_s, Screening& screening) {
  if (filled.gaps.empty()) return;
  std::vector<ScreenedSpan> gaps;
  for (const auto& [first, last] : filled.gaps) gaps.push_back({first, last, 0.0, 0.0, "time", ScreenReason::kGap});
  set_aside(screening, filled.run, std::move(gaps), margin_s);
}

// FitSeries::after_switch: the settling span after every step of the coil current. The model
// starts each run from a demagnetised core at 0 A, so a run that begins energised begins with a
// step from 0 A (the range counts 0 A for that reason).
void mark_switch_settling(FitSeries& s, const FitSeriesOptions& options) {
  s.after_switch.assign(s.size(), 0);
  for (std::size_t run = 0; run < s.run_starts.size(); ++run) {
    const std::size_t begin = s.run_starts[run];
    const std::size_t end = run + 1 < s.run_starts.size() ? s.run_starts[run + 1] : s.size();
    const auto [lo, hi] = std::minmax_element(s.current.begin() + static_cast<std::ptrdiff_t>(begin),
                                              s.current.begin() + static_cast<std::ptrdiff_t>(end));
    const double step = options.switch_step * (std::max(*hi, 0.0) - std::min(*lo, 0.0));
    if (!(step > 0.0)) continue;
    std::size_t marked_to = begin;  // marks [.., marked_to) are set
    for (const std::size_t i : current_step_rows(s, begin, end, step)) {
      std::size_t j = std::max(i, marked_to);
      for (; j < end && s.time[j] - s.time[i] < options.switch_settling; ++j) s.after_switch[j] = 1;
      marked_to = j;
    }
  }
}

// A run whose kept displacement spans less than this many times its noise has no motion to
// explain: every effect would fit the load cell's noise.
constexpr double kMotionOverNoise = 20.0;

void check_motion(const record::RecordedRun& run, const Screening& screening) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (std::size_t i = 0; i < run.size(); ++i) {
    if (!screening.excluded.empty() && screening.excluded[i]) continue;
    lo = std::min(lo, run.displacement[i]);
    hi = std::max(hi, run.displacement[i]);
  }
  if (!(hi > lo)) {
    if (!(hi >= lo)) return;  // nothing kept: the count of kept samples says so
    throw record::InputError(run.name + ": the displacement never moves on the kept samples: no damper "
                                         "motion to analyse (leave the run out)");
  }
  // A quantised LVDT's noise is at least its step.
  const double noise = std::max(sample_noise(run.displacement, screening.excluded), resolution(run.displacement));
  if (hi - lo >= kMotionOverNoise * noise) return;
  char text[200];
  std::snprintf(text, sizeof text,
                ": the displacement spans %.3g mm, within %g times its noise (%.3g mm): no damper motion "
                "to analyse (leave the run out)",
                (hi - lo) * 1e3, kMotionOverNoise, noise * 1e3);
  throw record::InputError(run.name + text);
}

// The fewest kept samples a fit takes: half of them validate, and the base fit alone moves
// about twenty coordinates.
constexpr std::size_t kMinFitSamples = 200;

void check_enough_kept(const FitSeries& s, const std::vector<record::RecordedRun>& runs) {
  const std::size_t kept = s.size() - s.excluded_samples();
  if (kept >= kMinFitSamples) return;
  std::string names;
  for (const auto& r : runs) names += (names.empty() ? "" : ", ") + r.name;
  std::map<std::string_view, std::size_t> by_reason;
  for (const auto& [run, screening] : s.screenings)
    for (const ScreenedSpan& span : screening.spans) by_reason[to_string(span.reason)] += span.last - span.first + 1;
  std::string why;
  for (const auto& [reason, count] : by_reason)
    why += (why.empty() ? "" : ", ") + std::string(reason) + " " + std::to_string(count);
  throw record::InputError(names + ": the screening left " + std::to_string(kept) + " of " +
                           std::to_string(s.size()) + " samples to fit; a fit needs at least " +
                           std::to_string(kMinFitSamples) + (why.empty() ? "" : " (set aside: " + why + ")"));
}

// The run's velocity: recorded, or zero_phase_velocity of its displacement (noted in `notes`).
std::vector<double> velocity_of(const record::RecordedRun& run, const record::GapFilledRun& gap_filled,
                                const Screening& screening, const FitSeriesOptions& options,
                                std::vector<std::string>& notes) {
  if (run.has_velocity()) return run.velocity;
  double cutoff = options.velocity_cutoff;
  if (cutoff <= 0.0) cutoff = motion_velocity_cutoff(run.displacement, run.sample_rate);
  // A span where the displacement was faulted is no motion either: it is bridged or split like a
  // gap (filtered through as recorded, it would bend the velocity for the filter's length on both
  // sides). A fault of the force alone leaves the motion measured.
  std::vector<std::uint8_t> unmeasured = gap_filled.filled;
  if (screening.excluded_samples > 0) {
    const std::vector<std::uint8_t> moved = faulted_samples(screening, unmeasured.size(), &FaultedInputs::displacement);
    for (std::size_t i = 0; i < unmeasured.size(); ++i) unmeasured[i] |= moved[i];
  }
  notes.push_back(run.name + ": velocity from the displacement, zero-phase low-pass at " + std::to_string(cutoff) +
                  " Hz" +
                  (gap_filled.gaps.empty() && screening.excluded_samples == 0
                       ? ""
                       : ", bridged across the logging gaps and the spans set aside (split where too long)"));
  if (gap_filled.timing != record::RunTiming::kRecorded)
    return zero_phase_velocity_by_stretch(run.displacement, run.time, run.sample_rate, cutoff, unmeasured);
  return zero_phase_velocity_at_times(run.displacement, run.time, run.sample_rate, cutoff, unmeasured);
}

}  // namespace

FitSeries make_fit_series(const std::vector<record::RecordedRun>& runs, const FitSeriesOptions& options) {
  if (runs.empty()) throw record::InputError("no runs to analyse");
  const bool with_temperature =
      std::all_of(runs.begin(), runs.end(), [](const record::RecordedRun& r) { return r.has_temperature(); });
  FitSeries s;
  const int blocks = std::max(options.blocks, 2);
  for (const record::RecordedRun& recorded : runs) {
    check_run(recorded, options);
    // A logging gap becomes samples at the nominal period, bridged and never fitted: the model's
    // state runs through it. Samples taken unevenly stay at their times (the model steps each by
    // its own interval): put on a grid, a telegraph current's force would be interpolated across
    // its switches, an error no model on the grid can undo.
    const record::GapFilledRun gap_filled = record::fill_gaps(recorded, record::UnevenTimes::kKeep);
    const record::RecordedRun& even = gap_filled.run;
    // Screened: the faulted spans set aside, the model's inputs bridged across them.
    Screening screening;
    if (options.screen) {
      ScreeningOptions screening_options = options.screening;
      screening_options.gap_step = gap_filled.gap_step;
      screening = screen_run(even, screening_options);
    }
    record::RecordedRun bridged;
    const record::RecordedRun* source = &even;
    if (screening.excluded_samples > 0) {
      bridged = even;
      bridge_excluded_inputs(bridged, screening);
      source = &bridged;
    }
    const record::RecordedRun& run = *source;
    const double rate = run.sample_rate;
    s.sample_period = s.run_periods.empty() ? 1.0 / rate : std::min(s.sample_period, 1.0 / rate);
    s.run_periods.push_back(1.0 / rate);
    const double gain =
        run.coil_signal == record::CoilSignal::kCommandVoltage ? *options.amps_per_volt : 1.0;
    const std::vector<double> velocity = velocity_of(run, gap_filled, screening, options, s.notes);
    // After the velocity: the samples beside a gap are measurements, set aside but not bridged;
    // so are those the model's J-A state cannot yet follow.
    set_aside_gaps(gap_filled, options.screening.margin_s, screening);
    // On the bridged run: a spike the screening set aside must not stretch the extremes.
    set_aside(screening, even, settling_spans(run, gap_filled.gaps, options.settle_start), 0.0);
    check_motion(even, screening);
    s.run_starts.push_back(s.size());
    s.run_names.push_back(recorded.name);
    s.run_timing.push_back(gap_filled.timing);
    const std::size_t n = run.size();
    // Half the blocks validate: a fixed shuffle, the same for every run and every call.
    std::vector<SampleRole> held_out(static_cast<std::size_t>(blocks));
    for (std::size_t b = 0; b < held_out.size(); ++b)
      held_out[b] = b % 2 == 1 ? SampleRole::kValidation : SampleRole::kFitting;
    std::mt19937 shuffle_rng(20261121u + static_cast<unsigned>(s.run_starts.size()));
    for (std::size_t b = held_out.size() - 1; b > 0; --b)
      std::swap(held_out[b], held_out[shuffle_rng() % (b + 1)]);
    for (std::size_t i = 0; i < n; ++i) {
      s.displacement.push_back(run.displacement[i]);
      s.velocity.push_back(velocity[i]);
      s.current.push_back(run.coil[i] * gain);
      s.force.push_back(run.force[i]);
      if (with_temperature) s.temperature.push_back(run.temperature[i]);
      s.time.push_back(i < run.time.size() ? run.time[i] : static_cast<double>(i) / rate);
      const auto block = static_cast<int>((i * static_cast<std::size_t>(blocks)) / n);
      s.role.push_back(screening.excluded.empty() || !screening.excluded[i]
                           ? held_out[static_cast<std::size_t>(block)]
                           : SampleRole::kExcluded);
    }
    if (options.screen || !screening.spans.empty()) s.screenings.emplace_back(recorded.name, std::move(screening));
    s.screened = options.screen;
  }
  check_enough_kept(s, runs);
  mark_switch_settling(s, options);
  return s;
}

std::vector<std::size_t> current_step_rows(const FitSeries& s, std::size_t begin, std::size_t end, double threshold) {
  std::vector<std::size_t> rows;
  for (std::size_t i = begin; i < end; ++i)
    if (std::fabs(s.current[i] - (i == begin ? 0.0 : s.current[i - 1])) > threshold) rows.push_back(i);
  return rows;
}

FitSeries without_excluded(const FitSeries& series, const std::vector<double>& per_sample,
                           std::vector<double>& kept_values) {
  FitSeries out;
  out.notes = series.notes;
  out.loss = series.loss;
  out.sample_period = series.sample_period;
  kept_values.clear();
  for (std::size_t r = 0; r < series.run_starts.size(); ++r) {
    const std::size_t end = r + 1 < series.run_starts.size() ? series.run_starts[r + 1] : series.size();
    out.run_starts.push_back(out.size());
    out.run_periods.push_back(series.run_periods[r]);
    if (r < series.run_names.size()) out.run_names.push_back(series.run_names[r]);
    if (r < series.run_timing.size()) out.run_timing.push_back(series.run_timing[r]);
    for (std::size_t i = series.run_starts[r]; i < end; ++i) {
      if (series.role[i] == SampleRole::kExcluded) continue;
      append_sample(out, series, i);
      kept_values.push_back(per_sample[i]);
    }
  }
  return out;
}

std::size_t decimation_factor(const FitSeries& series, std::size_t max_samples) {
  return std::max<std::size_t>(1, (series.size() + max_samples - 1) / std::max<std::size_t>(max_samples, 1));
}

FitSeries decimate(const FitSeries& series, std::size_t wanted, double min_rate) {
  if (wanted <= 1) return series;
  FitSeries out;
  out.notes = series.notes;
  out.loss = series.loss;
  std::vector<std::size_t> ends(series.run_starts.begin() + 1, series.run_starts.end());
  ends.push_back(series.size());
  for (std::size_t r = 0; r < ends.size(); ++r) {
    const double rate = 1.0 / series.run_periods[r];
    const std::size_t factor = std::clamp<std::size_t>(
        wanted, 1, static_cast<std::size_t>(std::max(1.0, std::floor(rate / min_rate))));
    out.run_periods.push_back(series.run_periods[r] * static_cast<double>(factor));
    out.sample_period = r == 0 ? out.run_periods[0] : std::min(out.sample_period, out.run_periods[r]);
    out.run_starts.push_back(out.size());
    if (r < series.run_names.size()) out.run_names.push_back(series.run_names[r]);
    if (r < series.run_timing.size()) out.run_timing.push_back(series.run_timing[r]);
    for (std::size_t from = series.run_starts[r]; from < ends[r]; from += factor) {
      const std::size_t to = std::min(from + factor, ends[r]);
      const std::size_t mid = from + (to - from) / 2;
      append_sample(out, series, mid);
    }
  }
  return out;
}

FitSeries run_openings(const FitSeries& series, std::size_t max_samples) {
  if (series.size() <= max_samples) return series;
  const std::size_t runs = series.run_starts.size();
  const auto end_of = [&](std::size_t r) { return r + 1 < runs ? series.run_starts[r + 1] : series.size(); };
  // Equal shares; a run shorter than its share is taken whole and leaves the rest to the others.
  std::vector<std::size_t> order(runs), take(runs);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::ranges::sort(order, {}, [&](std::size_t r) { return end_of(r) - series.run_starts[r]; });
  std::size_t left = max_samples;
  for (std::size_t k = 0; k < runs; ++k) {
    const std::size_t r = order[k];
    take[r] = std::min(end_of(r) - series.run_starts[r], left / (runs - k));
    left -= take[r];
  }
  FitSeries out;
  out.notes = series.notes;
  out.loss = series.loss;
  for (std::size_t r = 0; r < runs; ++r) {
    if (take[r] == 0) continue;
    out.sample_period = out.run_starts.empty() ? series.run_periods[r] : std::min(out.sample_period, series.run_periods[r]);
    out.run_starts.push_back(out.size());
    out.run_periods.push_back(series.run_periods[r]);
    if (r < series.run_names.size()) out.run_names.push_back(series.run_names[r]);
    if (r < series.run_timing.size()) out.run_timing.push_back(series.run_timing[r]);
    for (std::size_t i = series.run_starts[r]; i < series.run_starts[r] + take[r]; ++i) append_sample(out, series, i);
  }
  return out;
}

bool current_varies(const FitSeries& s) { return varies(s.current); }

std::vector<double> series_time(const FitSeries& s) {
  std::vector<double> out(s.size());
  double offset = 0.0;
  for (std::size_t r = 0; r < s.run_starts.size(); ++r) {
    const std::size_t from = s.run_starts[r];
    const std::size_t to = r + 1 < s.run_starts.size() ? s.run_starts[r + 1] : s.size();
    const double period = r < s.run_periods.size() ? s.run_periods[r] : s.sample_period;
    const bool timed = s.time.size() == s.size();
    for (std::size_t i = from; i < to; ++i)
      out[i] = offset + (timed ? s.time[i] - s.time[from] : static_cast<double>(i - from) * period);
    if (to > from) offset = out[to - 1] + period;
  }
  return out;
}

}  // namespace mrd::tools
