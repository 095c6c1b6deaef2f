#include "tools/residual/switch_timing.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <ranges>

#include "tools/residual/model_fit.hpp"

namespace mrd::tools {

namespace {

struct RunSpan {
  std::size_t from;
  std::size_t to;
};

RunSpan run_span(const FitSeries& s, std::size_t r) {
  return {s.run_starts[r], r + 1 < s.run_starts.size() ? s.run_starts[r + 1] : s.size()};
}

// One switch: its first row, the rows it spans, the current logged before it and after it, and
// the samples its phase shows in. A logger that sampled unevenly, put back on the even grid by
// interpolation, shows a switch as a ramp over the rows between the samples either side of it:
// those rows are one switch, whose phase is then counted in periods from the row before the first
// (0 .. rows), and each row takes the current its period held on average.
struct CurrentStep {
  std::size_t row;
  std::size_t rows = 1;
  double before;  // [A], 0 at a run's first row
  double after;   // [A]
  std::size_t window_end;
  double phase = 0.0;
  bool estimated = false;
};

// Up to this many rows of a ramp are one switch: a sample up to half a period early and the next
// up to half a period late have two of the grid's rows between them, three steps at most.
constexpr std::size_t kMaxRampRows = 3;

// Steps at consecutive rows, in one direction, read as one switch (see CurrentStep), on a run the
// reader resampled: on a run logged evenly a ramp is what the coil's current did (a driver's
// slew limit, an inductance) and each row keeps its own step.
std::vector<std::size_t> ramp_starts(const FitSeries& s, const std::vector<std::size_t>& rows) {
  const auto starts_a_run = [&s](std::size_t i) { return std::ranges::binary_search(s.run_starts, i); };
  const auto resampled = [&s](std::size_t i) {
    const auto run = static_cast<std::size_t>(std::ranges::upper_bound(s.run_starts, i) - s.run_starts.begin()) - 1;
    return run < s.run_resampled.size() && s.run_resampled[run] != 0;
  };
  std::vector<std::size_t> starts;
  for (std::size_t j = 0; j < rows.size(); ++j) {
    const std::size_t i = rows[j];
    const bool continues = j > 0 && i == rows[j - 1] + 1 && !starts_a_run(i) && !starts_a_run(rows[j - 1]) && resampled(i) &&
                           i - rows[starts.back()] < kMaxRampRows &&
                           (s.current[i] - s.current[i - 1]) * (s.current[i - 1] - s.current[i - 2]) > 0.0;
    if (!continues) starts.push_back(j);
  }
  return starts;
}

std::vector<CurrentStep> steps_of(const FitSeries& s, const SwitchTimingOptions& options) {
  const std::vector<std::size_t> rows = current_steps(s, options.step_share);
  const std::vector<std::size_t> starts = ramp_starts(s, rows);
  std::vector<CurrentStep> steps;
  steps.reserve(starts.size());
  std::size_t run = 0;
  for (std::size_t j = 0; j < starts.size(); ++j) {
    const std::size_t k = rows[starts[j]];
    const std::size_t last = rows[j + 1 < starts.size() ? starts[j + 1] - 1 : rows.size() - 1];
    while (run + 1 < s.run_starts.size() && s.run_starts[run + 1] <= k) ++run;
    const RunSpan span = run_span(s, run);
    const auto window = static_cast<std::size_t>(std::ceil(options.window / s.run_periods[run]));
    std::size_t end = std::min(span.to, last + std::max<std::size_t>(window, 1));
    if (j + 1 < starts.size()) end = std::min(end, rows[starts[j + 1]]);
    CurrentStep step{.row = k, .rows = last - k + 1, .before = k == span.from ? 0.0 : s.current[k - 1],
                     .after = s.current[last], .window_end = end};
    // A ramp starts at the phase that keeps the charge its rows logged.
    for (std::size_t i = k; i < last; ++i) step.phase += (s.current[i] - step.after) / (step.before - step.after);
    steps.push_back(step);
  }
  return steps;
}

// Each switch's rows given the current their periods held on average, at its phase (moved by
// `offset` when given, one per switch).
void write_phases(const std::vector<CurrentStep>& steps, FitSeries& s, const std::vector<double>* offset = nullptr) {
  for (std::size_t j = 0; j < steps.size(); ++j) {
    const auto span = static_cast<double>(steps[j].rows);
    const double phase = std::clamp(steps[j].phase + (offset != nullptr ? (*offset)[j] : 0.0), 0.0, span);
    for (std::size_t r = 0; r < steps[j].rows; ++r) {
      const double theta = std::clamp(phase - static_cast<double>(r), 0.0, 1.0);
      s.current[steps[j].row + r] = theta * steps[j].before + (1.0 - theta) * steps[j].after;
    }
  }
}

// One Gauss-Newton pass: each phase moved by the least-squares step along the force's change
// for a probe `offset` of it, over the kept samples of its window. One observer pass probes
// every step at once: the windows do not overlap, though a probe's effect runs on past its window
// through the lag and the core's memory into the next step's; the next pass corrects for what
// that mixed in.
void gauss_newton_pass(const model::DamperModel& model, FitSeries& s, std::vector<CurrentStep>& steps,
                       std::vector<double>& force) {
  std::vector<double> offset(steps.size());
  for (std::size_t j = 0; j < steps.size(); ++j)
    offset[j] = steps[j].phase < 0.5 * static_cast<double>(steps[j].rows) ? 0.25 : -0.25;
  write_phases(steps, s, &offset);
  std::vector<double> probed;
  predict_force(model, s, probed);
  for (std::size_t j = 0; j < steps.size(); ++j) {
    double along = 0.0;
    double norm = 0.0;
    for (std::size_t i = steps[j].row; i < steps[j].window_end; ++i) {
      if (s.role[i] == SampleRole::kExcluded) continue;
      const double slope = (probed[i] - force[i]) / offset[j];
      along += (s.force[i] - force[i]) * slope;
      norm += slope * slope;
    }
    if (!(norm > 0.0) || !std::isfinite(along)) continue;
    steps[j].phase = std::clamp(steps[j].phase + along / norm, 0.0, static_cast<double>(steps[j].rows));
    steps[j].estimated = true;
  }
  write_phases(steps, s);
  predict_force(model, s, force);
}

double median_of_estimated(const std::vector<CurrentStep>& steps) {
  std::vector<double> phases;
  for (const CurrentStep& step : steps)
    if (step.estimated && step.rows == 1) phases.push_back(step.phase);
  if (phases.empty()) return 0.0;
  const auto middle = phases.begin() + static_cast<std::ptrdiff_t>(phases.size() / 2);
  std::nth_element(phases.begin(), middle, phases.end());
  return *middle;
}

// The phases of `steps` estimated against `model` and written into `series`; `out` gets the
// counts and the median, and `force` the prediction with them.
void estimate_phases(const model::DamperModel& model, FitSeries& series, std::vector<CurrentStep>& steps,
                     const SwitchTimingOptions& options, std::vector<double>& force, SwitchTiming& out) {
  out.steps = steps.size();
  // A ramp's starting phase writes a step where the log had a ramp: the first pass's probes are
  // measured from that, not from the logged ramp.
  if (std::ranges::any_of(steps, [](const CurrentStep& step) { return step.rows > 1; })) {
    write_phases(steps, series);
    predict_force(model, series, force);
  }
  for (int pass = 0; pass < options.iterations; ++pass) gauss_newton_pass(model, series, steps, force);
  out.median_phase = median_of_estimated(steps);
  out.estimated = 0;
  for (CurrentStep& step : steps) {
    if (step.estimated) ++out.estimated;
    else if (step.rows == 1) step.phase = out.median_phase;  // a ramp keeps its logged charge, as a step
  }
  write_phases(steps, series);
  predict_force(model, series, force);
  out.rms_after = residual_rms(series, force).fitting;
}

}  // namespace

std::vector<std::size_t> current_steps(const FitSeries& s, double step_share) {
  std::vector<std::size_t> rows;
  for (std::size_t r = 0; r < s.run_starts.size(); ++r) {
    const RunSpan span = run_span(s, r);
    double low = std::numeric_limits<double>::infinity();
    double high = -low;
    for (std::size_t i = span.from; i < span.to; ++i) {
      if (s.role[i] == SampleRole::kExcluded || !std::isfinite(s.current[i])) continue;
      low = std::min(low, s.current[i]);
      high = std::max(high, s.current[i]);
    }
    // A run at one current has no step to time, its first row included: its coil was on before
    // the record began, and the model's start from no current is the settling's question.
    if (!(high > low)) continue;
    const std::vector<std::size_t> run_rows = current_step_rows(s, span.from, span.to, step_share * (high - low));
    rows.insert(rows.end(), run_rows.begin(), run_rows.end());
  }
  return rows;
}

SwitchTiming time_current_steps(const model::DamperModel& model, FitSeries& series,
                                const SwitchTimingOptions& options) {
  SwitchTiming out;
  std::vector<double> force;
  predict_force(model, series, force);
  out.rms_before = out.rms_after = residual_rms(series, force).fitting;
  std::vector<CurrentStep> steps = steps_of(series, options);
  if (steps.empty()) return out;
  const std::vector<double> logged = series.current;
  SwitchTiming timed = out;
  estimate_phases(model, series, steps, options, force, timed);
  const auto kept = static_cast<double>(std::ranges::count_if(series.role, [](SampleRole r) { return r != SampleRole::kExcluded; }));
  const double chance = static_cast<double>(timed.steps) / std::max(kept, 1.0);
  timed.applied = timed.rms_after * timed.rms_after < (1.0 - options.chance_multiple * chance) * out.rms_before * out.rms_before;
  if (!timed.applied) {
    timed.rms_after = out.rms_before;
    series.current = logged;
  }
  return timed;
}

}  // namespace mrd::tools
