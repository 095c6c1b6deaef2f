#include "tools/replay/replay.hpp"

#include <optional>

#include <algorithm>
#include <cmath>
#include <limits>

#include "record/csv.hpp"
#include "record/run_gaps.hpp"
#include "tools/signal/zero_phase_velocity.hpp"

namespace mrd::tools {

ForceError force_error(std::span<const double> measured, std::span<const double> predicted) {
  ForceError e;
  e.samples = std::min(measured.size(), predicted.size());
  if (e.samples == 0) return e;
  double sum = 0.0, sum_sq = 0.0;
  double lo = measured[0], hi = measured[0];
  for (std::size_t i = 0; i < e.samples; ++i) {
    const double r = measured[i] - predicted[i];
    sum += r;
    sum_sq += r * r;
    e.max = std::max(e.max, std::fabs(r));
    lo = std::min(lo, measured[i]);
    hi = std::max(hi, measured[i]);
  }
  const auto n = static_cast<double>(e.samples);
  e.rms = std::sqrt(sum_sq / n);
  e.mean = sum / n;
  e.measured_range = hi - lo;
  e.nrmse =
      e.measured_range > 0.0 ? e.rms / e.measured_range : std::numeric_limits<double>::quiet_NaN();
  return e;
}

namespace {

control::ControlLawConfig law_for(const record::RecordedRun& run, const ReplayOptions& options) {
  if (!(run.sample_rate > 0.0) || run.size() < 2) {
    throw record::InputError(run.name +
                     ": cannot replay: the run needs at least 2 samples at a known rate");
  }
  record::check_sample_rate(run);
  if (run.coil_signal == record::CoilSignal::kCommandVoltage && !options.amps_per_volt) {
    throw record::InputError(run.name +
                     ": the run logged the driver's command voltage, not the coil current: "
                     "give the driver gain (--amps-per-volt)");
  }
  if (options.amps_per_volt && !std::isfinite(*options.amps_per_volt)) {
    throw record::InputError("--amps-per-volt must be a finite number");
  }
  if (options.use_recorded_velocity && options.zero_phase_cutoff) {
    throw record::InputError("--recorded-velocity and --zero-phase-velocity exclude each other");
  }
  if (options.use_recorded_velocity && !run.has_velocity()) {
    throw record::InputError(run.name + ": --recorded-velocity, but the run has no velocity column");
  }
  control::ControlLawConfig law = options.law;
  law.observer.sample_period = 1.0 / run.sample_rate;
  const auto report = control::validate(law);
  if (!report.ok())
    throw record::InputError(run.name + ": cannot replay with this config:\n" + report.to_string());
  return law;
}

}  // namespace

ReplayResult replay(const record::RecordedRun& run, const ReplayOptions& options) {
  const control::ControlLawConfig config = law_for(run, options);
  const double gain = run.coil_signal == record::CoilSignal::kCommandVoltage ? *options.amps_per_volt : 1.0;
  // The force: the firmware's observer driven by the current the run recorded.
  model::Observer observer(config.damper, config.observer);
  // The command: the whole control law in its own closed loop on the run's displacement, the
  // driver delivering each command as the mock driver does (ControlLoop feeds the law the
  // current that flowed, which is then its last command).
  control::ControlLaw law(config);
  double flowing = 0.0;

  ReplayResult result;
  result.sample_period = config.observer.sample_period;
  result.sampling = record::summarize_sampling(run.time);
  ReplayTrace& t = result.trace;
  for (auto* v : {&t.coil_current, &t.velocity, &t.B, &t.predicted_force, &t.scheduled_current,
                  &t.command_current}) {
    v->resize(run.size());
  }
  // Logging gaps filled at the nominal period, so the loop's steps keep their length and its
  // state runs through a gap; only the recorded samples are traced and judged.
  const record::GapFilledRun gap_filled = record::fill_gaps(run);
  const record::RecordedRun& even = gap_filled.run;
  // The velocity a sensor would give: recorded, offline zero-phase, or none (the filter).
  std::vector<double> offline;
  if (options.zero_phase_cutoff) {
    const double cutoff = *options.zero_phase_cutoff > 0.0 ? *options.zero_phase_cutoff
                                                           : motion_velocity_cutoff(even.displacement, even.sample_rate);
    offline = zero_phase_velocity_by_stretch(even.displacement, even.time, even.sample_rate, cutoff, gap_filled.filled);
  }
  const std::vector<double>* sensor = options.use_recorded_velocity ? &even.velocity
                                      : options.zero_phase_cutoff   ? &offline
                                                                    : nullptr;
  for (std::size_t i = 0, k = 0; i < even.size(); ++i) {
    const double x = even.displacement[i];
    const double current = even.coil[i] * gain;
    std::optional<double> velocity;
    if (sensor != nullptr) velocity = (*sensor)[i];
    const model::ObserverEstimate estimate =
        observer.step({.displacement = x, .velocity = velocity, .coil_current = current});
    const double scheduled =
        law.observe({.displacement = x, .velocity = velocity, .coil_current = flowing}).scheduled_current;
    flowing = law.command().current;
    if (gap_filled.filled[i]) continue;
    t.coil_current[k] = current;
    t.velocity[k] = estimate.velocity;
    t.B[k] = estimate.B;
    t.predicted_force[k] = estimate.force;
    t.scheduled_current[k] = scheduled;
    t.command_current[k] = flowing;
    ++k;
  }
  if (run.has_force()) result.force = force_error(run.force, t.predicted_force);
  return result;
}

}  // namespace mrd::tools
