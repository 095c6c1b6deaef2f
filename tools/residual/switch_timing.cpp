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

// One step: its row, the current logged before it and after it, and the samples its phase shows in.
struct CurrentStep {
  std::size_t row;
  double before;  // [A], 0 at a run's first row
  double after;   // [A]
  std::size_t window_end;
  double phase = 0.0;
  bool estimated = false;
};

std::vector<CurrentStep> steps_of(const FitSeries& s, const SwitchTimingOptions& options) {
  const std::vector<std::size_t> rows = current_steps(s, options.step_share);
  std::vector<CurrentStep> steps;
  steps.reserve(rows.size());
  std::size_t run = 0;
  for (std::size_t j = 0; j < rows.size(); ++j) {
    const std::size_t k = rows[j];
    while (run + 1 < s.run_starts.size() && s.run_starts[run + 1] <= k) ++run;
    const RunSpan span = run_span(s, run);
    const auto window = static_cast<std::size_t>(std::ceil(options.window / s.run_periods[run]));
    std::size_t end = std::min(span.to, k + std::max<std::size_t>(window, 1));
    if (j + 1 < rows.size()) end = std::min(end, rows[j + 1]);
    steps.push_back({.row = k, .before = k == span.from ? 0.0 : s.current[k - 1], .after = s.current[k],
                     .window_end = end});
  }
  return steps;
}

// Each step's row given the current its period held on average, at its phase (moved by `offset`
// when given, one per step).
void write_phases(const std::vector<CurrentStep>& steps, FitSeries& s, const std::vector<double>* offset = nullptr) {
  for (std::size_t j = 0; j < steps.size(); ++j) {
    const double theta = std::clamp(steps[j].phase + (offset != nullptr ? (*offset)[j] : 0.0), 0.0, 1.0);
    s.current[steps[j].row] = theta * steps[j].before + (1.0 - theta) * steps[j].after;
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
  for (std::size_t j = 0; j < steps.size(); ++j) offset[j] = steps[j].phase < 0.5 ? 0.25 : -0.25;
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
    steps[j].phase = std::clamp(steps[j].phase + along / norm, 0.0, 1.0);
    steps[j].estimated = true;
  }
  write_phases(steps, s);
  predict_force(model, s, force);
}

double median_of_estimated(const std::vector<CurrentStep>& steps) {
  std::vector<double> phases;
  for (const CurrentStep& step : steps)
    if (step.estimated) phases.push_back(step.phase);
  if (phases.empty()) return 0.0;
  const auto middle = phases.begin() + static_cast<std::ptrdiff_t>(phases.size() / 2);
  std::nth_element(phases.begin(), middle, phases.end());
  return *middle;
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
  std::vector<CurrentStep> steps = steps_of(series, options);
  out.steps = steps.size();
  std::vector<double> force;
  predict_force(model, series, force);
  out.rms_before = out.rms_after = residual_rms(series, force).fitting;
  if (steps.empty()) return out;
  const std::vector<double> logged = series.current;
  for (int pass = 0; pass < options.iterations; ++pass) gauss_newton_pass(model, series, steps, force);
  out.median_phase = median_of_estimated(steps);
  for (CurrentStep& step : steps) {
    if (step.estimated) ++out.estimated;
    else step.phase = out.median_phase;
  }
  write_phases(steps, series);
  predict_force(model, series, force);
  const double rms = residual_rms(series, force).fitting;
  const auto kept = static_cast<double>(std::ranges::count_if(series.role, [](SampleRole r) { return r != SampleRole::kExcluded; }));
  const double chance = static_cast<double>(steps.size()) / std::max(kept, 1.0);
  out.applied = rms * rms < (1.0 - options.chance_multiple * chance) * out.rms_before * out.rms_before;
  if (out.applied) out.rms_after = rms;
  else series.current = logged;
  return out;
}

}  // namespace mrd::tools
