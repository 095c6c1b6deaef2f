#pragma once

#include <string>
#include <vector>

#include "tools/json.hpp"
#include "tools/plot/figure.hpp"
#include "tools/report/html_report.hpp"

// The force-fit part of a report, shared by mrd-replay and mrd-residual: measured against
// predicted force over time, displacement and velocity, and the residual's structure.
namespace mrd::tools {

struct ForceFitTraces {
  std::string name;                 // the run(s), for captions
  std::vector<double> time;         // [s]
  std::vector<double> displacement; // [m]
  std::vector<double> velocity;     // [m/s]
  std::vector<double> measured;     // [N]
  std::vector<double> predicted;    // [N]
  std::string predicted_label = "predicted";
  std::vector<double> baseline;     // optional second prediction [N] (e.g. the base model)
  std::string baseline_label;
  std::vector<double> reference;    // optional: a published model's prediction [N] (Spencer 1997 on Dyke's run)
  std::string reference_label;
  std::vector<bool> keep;           // optional: false where screening set a sample aside
  // Several runs analysed together: each one's first sample and name (empty: one run). `time`
  // then runs on from one run to the next, each span the run's own seconds.
  std::vector<std::size_t> run_starts;
  std::vector<std::string> run_names;
};

// One run's share of the figures, at its own sample step.
struct RunFitFigures {
  std::string name;
  std::size_t samples = 0;   // kept
  double fit_percent = 0.0;
  double nrmse = 0.0;        // rms_N over the range of its measured force (mrd-replay's nrmse)
  double rms_N = 0.0;
  double max_N = 0.0;
  double lag_step_s = 0.0;   // its own sample period
  double acf_outside = 0.0;  // fraction of lags 1..lags with |r| above its own 95 % bound
};

// How much of an input the residual still carries (MATLAB resid's cross-correlation test).
struct InputCorrelation {
  std::string input;         // "velocity", "displacement"
  double max_abs_r = 0.0;    // the largest |r(k)| over k = -lags..lags
  double at_lag_s = 0.0;     // its lag (> 0: the residual follows the input); in samples when the runs' rates differ
  double bound = 0.0;        // 95 % bound when input and residual are unrelated (Bartlett: both autocorrelations)
  double outside = 0.0;      // fraction of the lags with |r| above it
  std::vector<double> r;     // r(k) for k = -lags..lags (the report's plot)
};

struct ForceFitFigures {
  double fit_percent = 0.0;  // nrmse_fit_percent over the kept samples
  double nrmse = 0.0;        // rms_N over the range of the measured force (kept samples)
  double rms_N = 0.0;        // of measured - predicted over the kept samples
  double max_N = 0.0;
  double baseline_fit_percent = 0.0;  // NaN without a baseline
  double reference_fit_percent = 0.0; // of the published reference model; NaN without one
  double reference_rms_N = 0.0;
  std::size_t lags = 0;      // autocorrelation lags 1..lags
  double lag_step_s = 0.0;
  double acf_bound = 0.0;    // 95 % bound, 1.96/sqrt(N)
  double acf_outside = 0.0;  // fraction of lags 1..lags with |r| above it
  std::vector<InputCorrelation> inputs;  // the residual against the velocity and the displacement
  // With several runs: each run's figures; the autocorrelation above is then the runs' own,
  // averaged by their kept samples, at lags in samples (lag_step_s is 0 when their rates differ).
  std::vector<RunFitFigures> runs;
};
[[nodiscard]] ForceFitFigures force_fit_figures(const ForceFitTraces& t, std::size_t lags = 100);

// The figures as the tools' JSON "fit" object: fit_percent, nrmse, rms_N, max_N, baseline_fit_percent,
// acf_lags, acf_lag_step_s, acf_bound, acf_outside_fraction, input_xcorr (one object per input:
// input, max_abs_r, at_lag_s, bound, outside_fraction), and with a reference model reference_fit_percent
// and reference_rms_N. The report's cells name them "fit.*".
[[nodiscard]] Json force_fit_json(const ForceFitFigures& f);

// Where each run begins on a time axis, for a plot: a dotted line at each after the first,
// named while there are eight runs or fewer; none for one run.
[[nodiscard]] std::vector<plot::Marker> run_boundaries(const std::vector<double>& time,
                                                       const std::vector<std::size_t>& run_starts,
                                                       const std::vector<std::string>& run_names);

// The same boundaries for a time chart: where each run begins, named while there are eight or fewer.
[[nodiscard]] std::vector<TimeMarker> run_markers(const std::vector<double>& time, const std::vector<std::size_t>& run_starts,
                                                  const std::vector<std::string>& run_names);

// The per-run figures as text lines (none for one run), for the tools' summaries.
[[nodiscard]] std::string per_run_text(const ForceFitFigures& f);

// The plot "residual_autocorrelation": r(k) of `residual` for k = 0..lags as impulses, at lag
// k * lag_step on `lag_axis`, between the 95 % bounds +-1.96/sqrt(N).
void add_autocorrelation_plot(HtmlReport& report, const std::vector<double>& residual, std::size_t lags,
                              double lag_step, const plot::Axis& lag_axis, const std::string& caption);

// Writes the section (figures table and six plots) into the report.
ForceFitFigures add_force_fit(HtmlReport& report, const ForceFitTraces& t);

}  // namespace mrd::tools
