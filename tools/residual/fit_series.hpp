#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "record/recorded_run.hpp"
#include "record/run_gaps.hpp"
#include "tools/residual/fit_loss.hpp"
#include "tools/residual/screening.hpp"

namespace mrd::tools {

// What a sample is for: the fits use kFitting samples, the validation error the kValidation ones
// held out; kExcluded are those the screening set aside (no fit and no error counts them).
enum class SampleRole : std::uint8_t { kFitting, kValidation, kExcluded };

// One or more recorded runs as the residual analysis sees them: SI channels at one rate, the
// coil current in amperes, a velocity for every sample, and which samples validate.
struct FitSeries {
  double sample_period = 0.0;  // [s], the shortest of the runs
  std::vector<double> run_periods;  // [s], each run's own
  std::vector<double> displacement;  // [m]
  std::vector<double> velocity;      // [m/s]: recorded, or zero_phase_velocity
  std::vector<double> current;       // [A]
  std::vector<double> force;         // [N], measured
  std::vector<double> temperature;   // [degC], empty when no run recorded it
  std::vector<double> time;          // [s], each run's own clock (gap samples at the nominal period)
  // What the fits on this series minimise, and residual_rms reports. Only the searches' series
  // carry a robust loss (--robust-fit): what the reports quote is an RMS.
  FitLoss loss;
  // The first sample of each run: the model starts again from a demagnetised core there.
  std::vector<std::size_t> run_starts;
  std::vector<std::string> run_names;  // one per run start, for the reports
  // One per run start: how its samples sit in time (record::RunTiming). A run taken unevenly is
  // kept at its recorded times (make_fit_series), and the model steps each sample by its own
  // interval, `time` [i] - `time` [i - 1]; empty: every run even.
  std::vector<record::RunTiming> run_timing;
  std::vector<SampleRole> role;  // one per sample
  // 1 for a sample within the settling span after a step of the coil current (empty: none). A
  // transient there is the model's question (a coil lag, eddy currents) that the effect search
  // answers, not a logger's fault: the robust loss's trigger does not count it (robust_weights.hpp).
  std::vector<std::uint8_t> after_switch;
  bool screened = false;  // whether the screening ran (gaps are set aside either way)
  // What the screening set aside, per run (in the runs' order; without screening, only runs
  // with logging gaps).
  std::vector<std::pair<std::string, Screening>> screenings;
  [[nodiscard]] std::size_t excluded_samples() const {
    std::size_t n = 0;
    for (const auto& [run, s] : screenings) n += s.excluded_samples;
    return n;
  }
  std::vector<std::string> notes;  // how the series was made, for the reports

  [[nodiscard]] std::size_t size() const { return displacement.size(); }
  [[nodiscard]] record::RunTiming timing_of_run(std::size_t run) const {
    return run < run_timing.size() ? run_timing[run] : record::RunTiming::kEven;
  }
  [[nodiscard]] bool settles_after_switch(std::size_t i) const { return i < after_switch.size() && after_switch[i] != 0; }
};

struct FitSeriesOptions {
  std::optional<double> amps_per_volt;  // for runs that logged the driver's command voltage
  // [Hz] of zero_phase_velocity, for runs without velocity; <= 0: five times the frequency below
  // which 99 % of the displacement's power lies, within [2 Hz, 0.2 x the sample rate].
  double velocity_cutoff = 0.0;
  // Each run is cut into this many equal blocks, half of which validate, drawn at random with a
  // fixed seed: alternate blocks would lock onto the phase of a periodic motion whenever a
  // period spans an even number of them (a fit would then see only some phases).
  int blocks = 24;
  // Screening before the fit (screening.hpp): spans no damper produced are set aside.
  bool screen = true;
  // The model state's settling after each logging gap of 10 samples and 10 ms or more
  // (settling_spans) is set aside, screened or not; with `settle_start`, also at each run's start: for a core that had a history before
  // the record began (the model starts it demagnetised). Off by default: on a run that did
  // start demagnetised the first ascent is information (the fastest, least-field samples of a
  // sine started at its zero crossing).
  bool settle_start = false;
  // A step of the coil current within one sample of more than `switch_step` of the run's current
  // range starts a span of `switch_settling` [s] that the robust loss's trigger leaves out
  // (FitSeries::after_switch). A coil lag of up to 50 ms settles to 13 % in 0.1 s.
  double switch_step = 0.1;
  double switch_settling = 0.1;  // [s]
  ScreeningOptions screening;
};

// Throws InputError when a run has no force, a voltage run comes without a gain, or the runs
// differ in rate by more than 1 %.
FitSeries make_fit_series(const std::vector<record::RecordedRun>& runs, const FitSeriesOptions& options);

// Every `factor`-th sample (the middle one of each block of `factor`), or fewer for a run that
// would fall below `min_rate` [Hz]; run boundaries and the validation blocks are kept. Picked,
// not averaged: the force is a nonlinear function of the current's history (J-A, Eq. 13), so the
// force averaged over a block is not the force of the averaged current, which costs a fit on a
// switched current more than the samples left out do.
FitSeries decimate(const FitSeries& series, std::size_t factor, double min_rate);

// At most `max_samples` of the series: the opening of every run, in equal shares (a run shorter
// than its share whole, its rest to the others), each from the run's own start. Where a global
// search that integrates J-A explores before a local one refines on the whole series: a J-A
// pass costs per unit of the current's travel, so only fewer samples make it cheaper, and only
// a run's opening starts from the state the whole series' does (a window from its middle would
// start demagnetised where the core had a history, and J-A remembers it for cycles). The series
// itself when it is no longer than `max_samples`.
FitSeries run_openings(const FitSeries& series, std::size_t max_samples);

// The series without its excluded samples, and `per_sample` (one value per sample of `series`)
// cut the same way: what the residual's structure is analysed on.
FitSeries without_excluded(const FitSeries& series, const std::vector<double>& per_sample,
                           std::vector<double>& kept_values);

// Whether the coil current moves over the series by more than 5 % of its largest |value|: what
// decides whether a run can show the magnetics at all.
bool current_varies(const FitSeries& series);

// The rows in [begin, end) where the coil current steps by more than `threshold` from the row
// before (from no current at `begin`): what the switch settling and the switch timing start from.
std::vector<std::size_t> current_step_rows(const FitSeries& s, std::size_t begin, std::size_t end, double threshold);

// A time for every sample on one axis for plots: each run's own clock from 0, the next run
// starting a sample period after the one before ends (so a 22.4 s run at 200 Hz spans 22.4 s).
std::vector<double> series_time(const FitSeries& s);

// The factor that brings the series to at most `max_samples`.
std::size_t decimation_factor(const FitSeries& series, std::size_t max_samples);

}  // namespace mrd::tools
